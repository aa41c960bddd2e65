"""Packaging, notebooks and CI wiring: the things that break without touching the core."""

import re
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from notebook_runs import NOTEBOOKS as NOTEBOOK_ROOT
from notebook_runs import executed

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK_DIR = ROOT / "notebooks"
LESSONS = sorted(NOTEBOOK_DIR.glob("*.ipynb"))
LESSON_IDS = [nb.name for nb in LESSONS]
#: Exercise notebooks (teacher versions, issue 10); their student versions are generated.
EXERCISES = sorted((NOTEBOOK_DIR / "exercises").glob("*.ipynb"))
#: Every committed notebook under notebooks/: lessons and exercises.
NOTEBOOKS = LESSONS + EXERCISES
NB_IDS = [str(nb.relative_to(NOTEBOOK_DIR)) for nb in NOTEBOOKS]
EX_IDS = [nb.name for nb in EXERCISES]


def test_core_import_does_not_pull_in_plotting_or_widgets():
    code = (
        "import sys, teachraster\n"
        "heavy = {'matplotlib', 'ipywidgets', 'ipympl'}\n"
        "print(sorted({m.split('.')[0] for m in sys.modules} & heavy))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT
    )
    assert out.stdout.strip() == "[]", f"import teachraster loaded {out.stdout.strip()}"


#: The lessons by number: issue 4's 00 tour and one per topic of the notes, lesson 05 split by
#: issue 10 into 05a (the z-buffer, clipping) and 05b (depth precision); 08 antialiasing
#: (issue 11), 09 texture filtering (issue 12), 10 tiles (issue 13), 11 frame debugging (issue 21),
#: 12 lines and blending (issue 22), split by issue 29 into 12a (lines) and 12b (blending).
CURRICULUM = [
    "00",
    "01",
    "02",
    "03",
    "04",
    "05a",
    "05b",
    "06",
    "07",
    "08",
    "09",
    "10",
    "11",
    "12a",
    "12b",
]


def test_every_lesson_of_the_curriculum_is_there():
    """Every lesson of CURRICULUM, and nothing else, is a notebook ``<number>_<topic>.ipynb``."""
    prefixes = sorted(name.split("_")[0] for name in LESSON_IDS)
    assert prefixes == CURRICULUM, LESSON_IDS


@pytest.mark.parametrize("path", NOTEBOOKS, ids=NB_IDS)
def test_notebook_is_committed_clean(path):
    nb = nbformat.read(path, as_version=4)
    nbformat.validate(nb)
    assert nb.metadata.get("kernelspec", {}).get("name") == "python3"
    dirty = [
        i
        for i, cell in enumerate(nb.cells)
        if cell.cell_type == "code" and (cell.outputs or cell.execution_count is not None)
    ]
    assert not dirty, (
        f"{path.name}: cells {dirty} have outputs or execution counts; clear them with "
        "`.venv/bin/jupyter nbconvert --clear-output --inplace notebooks/*.ipynb`"
    )


def execute(nb, cwd: Path, allow_errors: bool = False):
    """Run every cell of ``nb`` in a fresh python3 kernel; raise on the first failing cell
    (unless ``allow_errors``: then every cell runs and errors are outputs)."""
    from nbclient import NotebookClient

    client = NotebookClient(
        nb,
        timeout=300,
        kernel_name="python3",
        allow_errors=allow_errors,
        resources={"metadata": {"path": str(cwd)}},
    )
    client.execute()  # raises CellExecutionError, with the traceback, if any cell fails
    return nb


# exercise notebooks run in test_exercise_teacher_version_passes_and_draws_every_check
@pytest.mark.notebook
@pytest.mark.parametrize("path", LESSONS, ids=LESSON_IDS)
def test_notebook_runs_headless(path):
    # the run every test of this session shares (tests/notebook_runs.py), in the lesson's folder
    run = executed(path.relative_to(NOTEBOOK_ROOT).with_suffix("").as_posix())
    assert not run.error, f"{path.name} failed:\n{run.error}"


def _streams(nb) -> str:
    return "".join(
        out.get("text", "")
        for cell in nb.cells
        if cell.cell_type == "code"
        for out in cell.outputs
        if out.get("output_type") == "stream"
    )


def _figures(nb) -> int:
    return sum(
        "image/png" in out.get("data", {})
        for cell in nb.cells
        if cell.cell_type == "code"
        for out in cell.outputs
    )


def _solution_cells(nb) -> list[int]:
    return [i for i, c in enumerate(nb.cells) if "### BEGIN SOLUTION" in c.source]


def _graded(nb):
    """The graded check cells: one per exercise, one per scene of the capstone (issue 30)."""
    return [c for c in nb.cells if c.metadata.get("nbgrader", {}).get("grade")]


def _graded_streams(nb) -> str:
    return _streams(nbformat.v4.new_notebook(cells=_graded(nb)))


def _graded_figures(nb) -> int:
    return _figures(nbformat.v4.new_notebook(cells=_graded(nb)))


@pytest.mark.parametrize("path", EXERCISES, ids=EX_IDS)
def test_exercise_notebook_has_nbgrader_solutions_each_followed_by_a_check(path):
    nb = nbformat.read(path, as_version=4)
    solutions = _solution_cells(nb)
    assert solutions, f"{path.name} has no ### BEGIN SOLUTION region"
    for i in solutions:
        assert "### END SOLUTION" in nb.cells[i].source
        assert nb.cells[i].metadata["nbgrader"]["solution"] is True
        check = nb.cells[i + 1].source
        assert check.startswith(("report = ex.check(", "report = ex.capstone(")), (
            f"cell {i + 1} should check cell {i}"
        )
        assert nb.cells[i + 1].metadata["nbgrader"]["grade"] is True  # graded (issue 17)


@pytest.mark.notebook
@pytest.mark.parametrize("path", EXERCISES, ids=EX_IDS)
def test_exercise_teacher_version_passes_and_draws_every_check(path):
    run = executed(path.relative_to(NOTEBOOK_ROOT).with_suffix("").as_posix())
    assert not run.error, f"{path.name} failed:\n{run.error}"
    nb = run.notebook()
    n = len(_graded(nb))  # an ungraded cell may show a failing report (exercise 10's naive fill)
    text = _graded_streams(nb)
    assert text.count("cases pass") == n and " fail" not in text, text
    assert _graded_figures(nb) == n  # each check shows its report as a figure too


@pytest.mark.parametrize("path", EXERCISES, ids=EX_IDS)
def test_exercise_student_version_hides_the_solutions(path, tmp_path):
    """The student version has stubs where the solutions were. Run top to bottom it says "not
    implemented yet" at each check: nbgrader's round trip runs exactly this notebook (its
    release, checked equal to ``student-version``'s) as the untouched submission and checks
    that (tests/test_nbgrader.py), so it is not run a second time here."""
    from teachraster.cli import main

    assert main(["student-version", str(path), "-o", str(tmp_path)]) == 0
    student = nbformat.read(tmp_path / path.name, as_version=4)
    assert "### BEGIN SOLUTION" not in "".join(c.source for c in student.cells)
    assert "raise NotImplementedError()" in "".join(c.source for c in student.cells)


def quick_start_commands():
    """The shell commands in the fenced blocks of README's "Quick start" section."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    match = re.search(r"^## Quick start\n(.*?)(?=^## )", text, flags=re.M | re.S)
    assert match, 'README.md has no "## Quick start" section'
    blocks = re.findall(r"^```[a-z]*\n(.*?)^```$", match.group(1), flags=re.M | re.S)
    return [line.strip() for block in blocks for line in block.splitlines() if line.strip()]


def test_readme_quick_start_is_two_commands():
    assert quick_start_commands() == ["python3 dev.py lab", "python3 dev.py test"]


@pytest.mark.skipif(shutil.which("bash") is None, reason="needs bash")
def test_ci_runs_the_readme_test_command():
    out = subprocess.run(
        ["bash", str(ROOT / ".ci" / "run"), "--print-command"],
        capture_output=True,
        text=True,
        check=True,
        cwd=ROOT,
    )
    assert out.stdout.strip() == quick_start_commands()[1]
