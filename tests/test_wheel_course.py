"""The course travels with the package (issue 10): build the wheel, install it into a fresh
virtual environment, run ``teachraster lessons`` there and execute lesson 00 from the copy.

Slow (about a minute: a wheel build, a venv, a notebook): marked ``slow``; deselect it with
``-m "not slow"`` while iterating. It needs no network beyond the configured package indexes:
the build backend (setuptools) comes from them, and the new environment reuses this one's
installed dependencies (numpy, matplotlib, ipykernel, ...) through a ``.pth`` file, while
teachraster itself comes only from the wheel.
"""

from __future__ import annotations

import json
import os
import shlex
import site
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
import run_once

ROOT = Path(__file__).resolve().parent.parent
LESSONS = sorted(p.name for p in (ROOT / "notebooks").glob("*.ipynb"))
EXERCISES = sorted(p.name for p in (ROOT / "notebooks" / "exercises").glob("*.ipynb"))

pytestmark = pytest.mark.slow


def _run(cmd, **kwargs):
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # nothing from the tree
    env["MPLBACKEND"] = "Agg"
    # the kernel "python3" as this environment's ipykernel declares it ("python": the
    # interpreter that starts it, here the wheel's venv), never a spec in the user's data dir
    # (~/.local/share/jupyter/kernels/python3, left by `ipykernel install --user` for another
    # venv, ran lesson 00 in that venv: seen on a shared machine); the wheel's venv has none
    env["JUPYTER_PATH"] = str(Path(sys.prefix) / "share" / "jupyter")
    return subprocess.run(cmd, capture_output=True, text=True, env=env, **kwargs)


def _build_wheel(out: Path) -> None:
    build = _run([sys.executable, "-m", "pip", "wheel", str(ROOT), "--no-deps", "-w", str(out)])
    if build.returncode and "setuptools" in build.stderr and "No matching" in build.stderr:
        pytest.skip("no setuptools>=77 to build with (no package index reachable)")
    assert build.returncode == 0, build.stderr[-3000:]


@pytest.fixture(scope="module")
def wheel() -> Path:
    """The wheel, built once per run (whichever worker asks first)."""
    (path,) = run_once.shared_folder("wheel", _build_wheel).glob("teachraster-*.whl")
    return path


def test_the_wheel_holds_the_lessons_and_only_student_exercises(wheel):
    with zipfile.ZipFile(wheel) as zf:
        names = set(zf.namelist())
        course = "teachraster/course/notebooks/"
        assert {course + name for name in LESSONS} <= names
        assert "teachraster/cli/templates/offline_lesson.html.j2" in names  # teachraster html
        assert {course + "exercises/" + name for name in EXERCISES} <= names
        for name in EXERCISES:
            text = zf.read(course + "exercises/" + name).decode()
            assert "BEGIN SOLUTION" not in text and "raise NotImplementedError()" in text


def test_installed_wheel_copies_the_course_and_lesson_00_runs(wheel, tmp_path):
    venv = tmp_path / "venv"
    assert _run([sys.executable, "-m", "venv", "--without-pip", str(venv)]).returncode == 0
    python = venv / "bin" / "python"
    install = _run(
        [sys.executable, "-m", "pip", "--python", str(python), "install", "--no-deps", str(wheel)]
    )
    assert install.returncode == 0, install.stderr[-3000:]
    # the dependencies of this environment, without its (editable) teachraster: a path added
    # by a .pth file is not a site directory, so the editable install's own .pth is not run
    (new_site,) = (venv / "lib").glob("python3*/site-packages")
    (new_site / "deps.pth").write_text("\n".join(site.getsitepackages()) + "\n")

    course = tmp_path / "my course"
    copy = _run([str(venv / "bin" / "teachraster"), "lessons", str(course)], cwd=tmp_path)
    assert copy.returncode == 0, copy.stderr
    assert f"jupyter lab {shlex.quote(str(course))}" in copy.stdout  # shell-quoted (issue 17)
    assert (course / "CONVENTIONS.md").is_file()
    assert sorted(p.name for p in course.glob("*.ipynb")) == LESSONS
    assert sorted(p.name for p in (course / "exercises").glob("*.ipynb")) == EXERCISES

    lesson = course / LESSONS[0]
    nb = json.loads(lesson.read_text())
    probe = "import teachraster\nprint('TEACHRASTER', teachraster.__file__)"
    nb["cells"].insert(
        0,
        {
            "cell_type": "code",
            "metadata": {},
            "source": probe,
            "outputs": [],
            "execution_count": None,
        },
    )
    lesson.write_text(json.dumps(nb))
    script = (
        "import sys, nbformat\n"
        "from nbclient import NotebookClient\n"
        "nb = nbformat.read(sys.argv[1], as_version=4)\n"
        "NotebookClient(nb, timeout=300, kernel_name='python3',\n"
        "               resources={'metadata': {'path': sys.argv[2]}}).execute()\n"
        "print(nb.cells[0].outputs[0]['text'])\n"
    )
    run = _run([str(python), "-c", script, str(lesson), str(course)], cwd=course)
    assert run.returncode == 0, run.stderr[-3000:]
    assert f"TEACHRASTER {new_site}" in run.stdout, run.stdout  # the wheel's copy, not the tree's
