"""Build step that puts the course into the wheel (the rest of the metadata is in pyproject.toml).

The lessons (``notebooks/*.ipynb``) and the *student* versions of the exercise notebooks
(``notebooks/exercises/*.ipynb``, solutions replaced by stubs) are written into the built
package as ``teachraster/course/notebooks/``, so that ``pip install teachraster`` brings the
course and ``teachraster lessons`` can copy it. The notebooks stay in one place in git.
"""

import importlib.util
import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent


def _student_version_module():
    # Loaded from its file: the build must not import teachraster (nor numpy) to do this.
    path = ROOT / "teachraster" / "exercises" / "student_version.py"
    spec = importlib.util.spec_from_file_location("_teachraster_student_version", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class BuildPyWithCourse(build_py):
    """``build_py`` that also copies the course into ``teachraster/course/notebooks``."""

    def run(self):
        super().run()
        source = ROOT / "notebooks"
        if not source.is_dir():  # building from an sdist without notebooks: nothing to add
            return
        target = Path(self.build_lib) / "teachraster" / "course" / "notebooks"
        # A build directory left from an earlier build may hold lessons renamed since.
        shutil.rmtree(target, ignore_errors=True)
        (target / "exercises").mkdir(parents=True, exist_ok=True)
        for lesson in sorted(source.glob("*.ipynb")):
            shutil.copyfile(lesson, target / lesson.name)
        # the conventions the exercises refer to (teachraster lessons copies them too)
        if (ROOT / "CONVENTIONS.md").is_file():
            shutil.copyfile(ROOT / "CONVENTIONS.md", target / "CONVENTIONS.md")
        student = _student_version_module()
        for exercise in sorted((source / "exercises").glob("*.ipynb")):
            student.write_student_version(exercise, target / "exercises" / exercise.name)


setup(cmdclass={"build_py": BuildPyWithCourse})
