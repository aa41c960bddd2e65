"""nbgrader grades the exercises for real (issue 17): the whole pipeline, in a temporary course.

``teachraster nbgrader DIR`` lays out the course; then nbgrader's own steps run there:
``generate_assignment`` of every exercise notebook, ``autograde`` of two submissions per
assignment — the teacher version (full marks) and the release unchanged (0) —,
``generate_feedback`` and ``export``, whose ``grades.csv`` is checked, and the gradebook's
score of every graded cell (each check cell its own points in the teacher's, 0 in the
release's). Every ``notebooks/exercises/*.ipynb`` takes part, whatever its exercises: the
points are found from the nbgrader metadata.

A third submission, the release with its first exercise solved (that exercise's points), was
folded into those two (CI time: it was a third of the notebooks autograded). A notebook runs top
to bottom, so in that submission the first exercise's check cells ran after the same cells as in
the teacher's (the release is the teacher's notebook with its solutions stubbed, and no solution
comes before the first), and every later check ran its own stub as in the release's: each cell's
score is the teacher's or the release's, both checked here cell by cell.

The steps run through nbgrader's Python API (``NbGraderAPI``, the one its formgrader calls) in
the test's process, with the course's ``nbgrader_config.py``: the commands did the same, each in
a fresh Python that spent 1 to 2 s of CPU starting (four commands per course; this file took
98 s of CPU with them, 91 s without, back to back on a 2-core machine, 2026-12-06). Each
submission is still executed in a fresh kernel of its own, as ``nbgrader autograde`` does.

nbgrader is a test dependency (``teachraster[test]``). Where it is missing the round trip skips,
saying so, unless TEACHRASTER_REQUIRE_NBGRADER is set (CI sets it): then it fails.
"""

from __future__ import annotations

import contextlib
import csv
import functools
import importlib.util
import json
import os
import re
import shutil
import sys
import warnings
from pathlib import Path

import nbformat
import pytest
import run_once
from test_packaging import _graded_figures, _graded_streams, _streams

from teachraster.cli import main
from teachraster.exercises.student_version import student_text

pytestmark = pytest.mark.nbgrader

ROOT = Path(__file__).resolve().parent.parent
EXERCISES = sorted((ROOT / "notebooks" / "exercises").glob("*.ipynb"))
#: This environment's bin first (the venv's bin may not be on PATH): the kernels' tools.
BIN = str(Path(sys.executable).parent)
HAVE_NBGRADER = importlib.util.find_spec("nbgrader") is not None
REQUIRED = bool(os.environ.get("TEACHRASTER_REQUIRE_NBGRADER"))
STUDENTS = ("teacher", "untouched")


def _require_nbgrader() -> None:
    if not HAVE_NBGRADER:
        if REQUIRED:
            raise RuntimeError("TEACHRASTER_REQUIRE_NBGRADER is set but nbgrader is missing")
        pytest.skip("nbgrader is not installed (pip install 'teachraster[test]')")


@contextlib.contextmanager
def _course_environment(root: Path):
    """The environment the nbgrader commands had (and the kernels inherit), put back after:
    the course's ``nbgrader_config.py`` sets a variable with ``os.environ.setdefault``."""
    saved = dict(os.environ)
    os.environ["PATH"] = os.pathsep.join([BIN, os.environ.get("PATH", "")])
    os.environ["MPLBACKEND"] = "Agg"
    os.environ["JUPYTER_CONFIG_DIR"] = str(root / ".jupyter")  # no user or site settings
    try:
        yield
    finally:
        os.environ.clear()
        os.environ.update(saved)


@contextlib.contextmanager
def _gradebook_without_fsync():
    """SQLite connections opened meanwhile (nbgrader's gradebook, ``gradebook.db`` in the
    course) do not wait for the disk at each commit (``PRAGMA synchronous=OFF``): a round
    trip commits some 770 times, each an fsync of a file that lives only as long as the run.
    What is written, read and graded is the same; only a power cut could lose it."""
    from sqlalchemy import event
    from sqlalchemy.engine import Engine

    def no_fsync(connection, _record) -> None:
        connection.execute("PRAGMA synchronous=OFF")

    event.listen(Engine, "connect", no_fsync)
    try:
        yield
    finally:
        event.remove(Engine, "connect", no_fsync)


def _grade_course(root: Path, submit) -> None:
    """``nbgrader generate_assignment "*"``, then ``submit()`` (which fills ``submitted/``),
    ``autograde "*"``, ``generate_feedback`` of the students the tests read and ``export``, in
    this process (nbgrader's API, with the course's config file and no other: the commands ran
    with an empty JUPYTER_CONFIG_DIR)."""
    from nbgrader.api import Gradebook
    from nbgrader.apps import NbGraderAPI
    from nbgrader.coursedir import CourseDirectory
    from nbgrader.plugins import CsvExportPlugin
    from sqlalchemy.exc import SAWarning
    from traitlets.config.loader import PyFileConfigLoader

    def check(name: str, result: dict) -> None:
        log, error = result.get("log", ""), result.get("error", "")[-4000:]
        assert result["success"], f"nbgrader {name}:\n{log}\n{error}"

    with _course_environment(root), warnings.catch_warnings(), _gradebook_without_fsync():
        # nbgrader's gradebook warns of its own session use (SQLAlchemy's "not in session"):
        # the commands printed the same to a stderr no test read
        warnings.simplefilter("ignore", SAWarning)
        config = PyFileConfigLoader("nbgrader_config.py", path=str(root)).load_config()
        config.CourseDirectory.root = str(root)
        api = NbGraderAPI(coursedir=CourseDirectory(config=config), config=config)
        check("generate_assignment", api.generate_assignment("*"))  # all left in source/
        submit()
        check("autograde", api.autograde("*", "*"))
        # feedback for the two students the tests read (a glob over student ids; CI time)
        check("generate_feedback", api.generate_feedback("*", "[tu]*"))
        with Gradebook(api.coursedir.db_url, api.coursedir.course_id) as gradebook:
            CsvExportPlugin(config=config, to=str(root / "grades.csv")).export(gradebook)


def _text(cell: dict) -> str:
    return "".join(cell["source"])


def _grading(cell: dict) -> dict:
    return cell.get("metadata", {}).get("nbgrader", {})


def first_exercise(nb: dict) -> tuple[int, int]:
    """(index of the first solution cell, points of the graded cells checking it).

    Its checks are the graded cells after it, up to the next solution cell.
    """
    cells = nb["cells"]
    first = next(i for i, c in enumerate(cells) if _grading(c).get("solution"))
    points = 0
    for cell in cells[first + 1 :]:
        if _grading(cell).get("solution"):
            break
        if _grading(cell).get("grade"):
            points += _grading(cell)["points"]
    return first, points


def total_points(nb: dict) -> int:
    return sum(_grading(c)["points"] for c in nb["cells"] if _grading(c).get("grade"))


def _submit(root: Path, student: str, assignment: str, name: str, nb: dict) -> None:
    folder = root / "submitted" / student / assignment
    folder.mkdir(parents=True)
    (folder / name).write_text(json.dumps(nb))


def _round_trip(folder: Path, exercises: tuple[Path, ...]) -> None:
    root = folder / "course"
    assert main(["nbgrader", str(root)]) == 0
    for source in (root / "source").iterdir():  # this part's assignments only
        if source.name not in {p.stem for p in exercises}:
            shutil.rmtree(source)

    def submit() -> None:
        for path in exercises:
            teacher = json.loads(path.read_text())
            release = json.loads((root / "release" / path.stem / path.name).read_text())
            for student, nb in zip(STUDENTS, (teacher, release)):
                _submit(root, student, path.stem, path.name, nb)

    _grade_course(root, submit)


#: The round trip in two courses, each half of the notebooks (alternate ones: about equal
#: work), so that two workers grade one each at the same time. Grading is one autograde
#: running 36 notebooks one after the other (~3 min); as one course, the second worker waited
#: for it on the lock with its core idle. Each test runs once per part, the parts' tests next
#: to each other (parametrised, not a module fixture), so the first two go to two workers.
PARTS = (tuple(EXERCISES[0::2]), tuple(EXERCISES[1::2]))
each_part = pytest.mark.parametrize("part", range(len(PARTS)), ids=["part-a", "part-b"])


@pytest.fixture
def course(part) -> Path:
    """A course directory of ``PARTS[part]`` after the whole nbgrader round trip (once per
    run, whichever worker asks first; the tests only read it)."""
    _require_nbgrader()  # skips, or fails where nbgrader is required
    build = functools.partial(_round_trip, exercises=PARTS[part])
    return run_once.shared_folder(f"nbgrader-course-{part}", build) / "course"


def test_the_parts_grade_every_exercise_notebook_once():
    assert sorted(p for part in PARTS for p in part) == EXERCISES and all(PARTS)


@each_part
def test_every_exercise_notebook_is_released_as_its_student_version(course, part):
    for path in PARTS[part]:
        release = json.loads((course / "release" / path.stem / path.name).read_text())
        ours = json.loads(student_text(path))
        assert [_text(c) for c in release["cells"]] == [_text(c) for c in ours["cells"]]
        assert "BEGIN SOLUTION" not in json.dumps(release)
        assert (course / "release" / path.stem / "CONVENTIONS.md").is_file()


@each_part
def test_grades_give_full_marks_zero_and_each_exercise_its_points(course, part):
    """grades.csv: the teacher's full marks, the release's 0; the gradebook: every graded cell
    scored on its own, its points in the teacher's and 0 in the release's (so the first
    exercise solved alone is worth its points: the submission that showed it was folded into
    these two, see the module's docstring)."""
    from nbgrader.api import Gradebook

    with open(course / "grades.csv", newline="") as f:
        rows = {(r["assignment"], r["student_id"]): r for r in csv.DictReader(f)}
    assert {a for a, _ in rows} == {p.stem for p in PARTS[part]}
    with Gradebook(f"sqlite:///{course / 'gradebook.db'}", "teachraster") as gradebook:
        for path in PARTS[part]:
            teacher = json.loads(path.read_text())
            full, (_, one) = total_points(teacher), first_exercise(teacher)
            assert full >= one > 0, path.name
            points = {_grading(c)["grade_id"]: _grading(c)["points"]
                      for c in teacher["cells"] if _grading(c).get("grade")}  # fmt: skip
            for student, score in {"teacher": full, "untouched": 0}.items():
                row = rows[(path.stem, student)]
                assert float(row["max_score"]) == full, (path.name, row)
                assert float(row["score"]) == score, (path.name, student, row)
                cells = gradebook.find_submission_notebook(path.stem, path.stem, student).grades
                scores = {g.name: (g.score, g.max_score) for g in cells}
                solved = student == "teacher"
                assert scores == {k: (p if solved else 0, p) for k, p in points.items()}, (
                    path.name, student, scores)  # fmt: skip


@each_part
def test_feedback_carries_the_checkers_explanation(course, part):
    for path in PARTS[part]:
        name = path.with_suffix(".html").name
        untouched = (course / "feedback" / "untouched" / path.stem / name).read_text()
        teacher = (course / "feedback" / "teacher" / path.stem / name).read_text()
        assert "not implemented yet" in untouched
        assert "cases pass" in teacher and "not implemented yet" not in teacher
        graded = sum(bool(_grading(c).get("grade")) for c in json.loads(path.read_text())["cells"])
        for student, failures in (("teacher", 0), ("untouched", graded)):
            nb = json.loads((course / "autograded" / student / path.stem / path.name).read_text())
            errors = [o for c in nb["cells"] for o in c.get("outputs", [])]
            errors = [o for o in errors if o["output_type"] == "error"]
            assert [e["ename"] for e in errors] == ["AssertionError"] * failures, path.name
            # the capstone's assertion names its scene only (r174 12-9: its report, printed
            # just above, was said twice)
            assert all(
                "not implemented yet" in e["evalue"]
                or "the report printed above says why" in e["evalue"]
                for e in errors
            )
        # the untouched submission is the student version run top to bottom (the only run of
        # it): each check says "not implemented yet" in its report and its figure, no traceback
        nb = nbformat.read(course / "autograded" / "untouched" / path.stem / path.name, 4)
        text = _graded_streams(nb)
        assert text.count("not implemented yet") == graded, (path.name, text)
        assert "Traceback" not in _streams(nb), path.name
        assert _graded_figures(nb) == graded, path.name


# -- the grading convention, read from the notebooks (no nbgrader needed) ----------------------
LOCKED = {"grade": False, "locked": True, "schema_version": 3, "solution": False, "task": False}


#: A check of the capstone (issue 30): one scene rendered with the student's functions
#: (matched with its whitespace collapsed: ruff may wrap the call over several lines).
CAPSTONE_CHECK = re.compile(
    r'report = ex\.capstone\( ?"(\w+)", ((?:\w+=\w+, )*\w+=\w+),? ?\) show\(report\) '
    r"report\.assert_passed\(\)"
)


def _capstone_check(cell, fn=None) -> bool:
    """A graded capstone check cell (plugging in ``fn``, when given)."""
    match = CAPSTONE_CHECK.fullmatch(" ".join(_text(cell).split()).replace("( ", "("))
    if not match:
        return False
    args = [a.split("=") for a in match.group(2).split(", ")]
    meta = _grading(cell)
    return (all(k == v for k, v in args) and (fn is None or fn in dict(args))
            and meta["grade_id"] == f"capstone_{match.group(1)}_check" and meta["grade"]
            and meta["locked"] and not meta["solution"] and meta["points"] > 0)  # fmt: skip


@pytest.mark.parametrize("path", EXERCISES, ids=[p.name for p in EXERCISES])
def test_teacher_notebook_is_an_nbgrader_source(path):
    """Solution cells, graded check cells worth points right after them, the rest locked
    (the capstone: a solution cell's scenes right after it, and more scenes later)."""
    cells = json.loads(path.read_text())["cells"]
    ids = [_grading(c).get("grade_id") for c in cells]
    assert all(ids) and len(set(ids)) == len(ids), ids
    solutions = [i for i, c in enumerate(cells) if _grading(c).get("solution")]
    assert solutions
    checked = set()
    for i in solutions:
        fn = ids[i].removesuffix("_solution")
        assert ids[i] == f"{fn}_solution" and "### BEGIN SOLUTION" in _text(cells[i])
        assert _grading(cells[i]) == {
            "grade": False, "grade_id": ids[i], "locked": False, "schema_version": 3,
            "solution": True, "task": False,
        }  # fmt: skip
        check = cells[i + 1]
        checked |= {i, i + 1}
        if _capstone_check(check, fn):
            continue
        assert _text(check) == (
            f'report = ex.check("{fn}", {fn})\nshow(report)\nreport.assert_passed()'
        )
        meta = _grading(check)
        assert meta["grade"] and meta["locked"] and not meta["solution"] and meta["points"] > 0
        assert meta["grade_id"] == f"{fn}_check"
    checked |= {i for i, c in enumerate(cells) if _capstone_check(c)}
    for i, cell in enumerate(cells):
        if i not in checked:
            assert {k: v for k, v in _grading(cell).items() if k != "grade_id"} == LOCKED, i
    assert "nbgrader" not in "".join(_text(c) for c in cells if c["cell_type"] == "code")


@pytest.mark.parametrize("path", EXERCISES, ids=[p.name for p in EXERCISES])
def test_stubs_state_the_task_in_words_not_the_formula_to_type(path):
    """The markdown right above a solution states the task and the rule in words: no
    displayed formula (``$$``) for the student to copy into the stub (issue 20)."""
    cells = json.loads(path.read_text())["cells"]
    for i, cell in enumerate(cells):
        if _grading(cell).get("solution"):
            task = next(c for c in reversed(cells[:i]) if c["cell_type"] == "markdown")
            assert "$$" not in _text(task), (path.name, _text(task)[:200])
