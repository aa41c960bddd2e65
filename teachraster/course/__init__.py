"""Where the course is: the lesson notebooks and the exercise notebooks, as files.

A wheel carries them as package data (``teachraster/course/notebooks/``, written by the build:
see ``setup.py``), with the exercises already in their student version (the teacher versions,
with solutions, never travel in the wheel: they are in the repository), and ``CONVENTIONS.md``. In a checkout of the
repository (an editable install) they are read from ``notebooks/`` itself, where the exercises
are the teacher versions; :func:`teachraster.exercises.student_version.student_notebook` turns
either into the student version (it leaves a student version unchanged).

Writing them into a directory without losing anything is :mod:`teachraster.course.install`;
the nbgrader course directory of the exercises is :mod:`teachraster.course.nbgrader_layout`.

Standard library only: ``teachraster lessons`` needs no numpy to copy files.
"""

from __future__ import annotations

from pathlib import Path

#: Inside an installed wheel.
PACKAGED = Path(__file__).resolve().parent / "notebooks"
#: In a checkout of the repository: teachraster/course -> the repository's notebooks/.
CHECKOUT = Path(__file__).resolve().parents[2] / "notebooks"
#: The conventions the exercises refer to: in the wheel beside the notebooks, else the checkout's.
CONVENTIONS = "CONVENTIONS.md"


def notebooks_dir() -> Path:
    """The directory holding the lessons (and ``exercises/``): packaged, else the checkout's.

    Raises ``FileNotFoundError`` when neither exists (an installation without its data).
    """
    for path in (PACKAGED, CHECKOUT):
        if any(path.glob("*.ipynb")):
            return path
    raise FileNotFoundError(
        f"no lesson notebooks in {PACKAGED} or {CHECKOUT}: reinstall teachraster from a wheel "
        "or a checkout of its repository"
    )


def lessons() -> list[Path]:
    """The lesson notebooks, in course order (00_..., 01_..., ...)."""
    return sorted(notebooks_dir().glob("*.ipynb"))


def exercises() -> list[Path]:
    """The exercise notebooks, in course order (teacher versions in a checkout)."""
    return sorted((notebooks_dir() / "exercises").glob("*.ipynb"))


def conventions() -> Path:
    """``CONVENTIONS.md``, the rules the exercises refer to (packaged, else the checkout's).

    Raises ``FileNotFoundError`` when it is missing.
    """
    for path in (PACKAGED / CONVENTIONS, CHECKOUT.parent / CONVENTIONS):
        if path.is_file():
            return path
    raise FileNotFoundError(f"no {CONVENTIONS} in {PACKAGED} or {CHECKOUT.parent}")
