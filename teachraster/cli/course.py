"""``teachraster lessons``, ``student-version`` and ``nbgrader``: the course as files.

``teachraster lessons [DIR]`` copies the lesson notebooks into DIR, the student versions of the
exercise notebooks into DIR/exercises/ and ``CONVENTIONS.md`` into DIR, then says how to open
them. It adds what is missing and never loses a student's work: after an upgrade, a notebook
the student never edited (its cells as an earlier version shipped them, as recorded in
``DIR/.teachraster-course.json``: :mod:`teachraster.course.manifest`) is refreshed to the new
version; a notebook that differs is kept, unless ``--force``, which replaces it and keeps the
old file beside it (``name.2026-11-26T10-00.ipynb``). See :mod:`teachraster.course.install`.

``teachraster student-version [NOTEBOOK ...] -o DIR`` writes the student version of exercise
notebooks (default: the course's), as nbgrader releases them
(:mod:`teachraster.exercises.student_version`). A malformed marker stops it before anything is
written, with the notebook, the cell and the line.

``teachraster nbgrader DIR [NOTEBOOK ...]`` lays out an nbgrader course directory: the teacher
versions under ``source/<assignment>/`` and ``nbgrader_config.py``
(:mod:`teachraster.course.nbgrader_layout`). ``teachraster nbgrader DIR --check-submissions``
lists the submissions nbgrader would score 0 without a word (:mod:`teachraster.course.submissions`).

>>> import argparse
>>> sub = argparse.ArgumentParser().add_subparsers(dest="command")
>>> add_parsers(sub)
>>> sub.choices["lessons"].parse_args([]).directory
PosixPath('teachraster-course')
"""

from __future__ import annotations

import os
import shlex
from pathlib import Path

from ..course import manifest
from ..course.install import CourseError, Outcome, atomic_write, install

DEFAULT_DIR = Path("teachraster-course")
#: Where ``teachraster nbgrader --force`` keeps replaced files: outside source/, so that an
#: old teacher version is never released to students.
NBGRADER_BACKUPS = "backups"


def add_parsers(subparsers) -> None:
    """Add the ``lessons``, ``student-version`` and ``nbgrader`` subcommands."""
    p = subparsers.add_parser(
        "lessons",
        help="copy the lessons and exercises (student version) into a directory",
        description="Copy the lesson notebooks into DIR, the student versions of the exercise "
        "notebooks into DIR/exercises/ and CONVENTIONS.md into DIR, and say how to open them. "
        "Missing files are added; a notebook that differs from the shipped one is kept.",
    )
    p.add_argument(
        "directory",
        metavar="DIR",
        nargs="?",
        type=Path,
        default=DEFAULT_DIR,
        help=f"where to put the course (default: ./{DEFAULT_DIR})",
    )
    _add_force(p, "replace notebooks that differ from the shipped ones (the old file is kept)")

    p = subparsers.add_parser(
        "student-version",
        help="write the student version of exercise notebooks (solutions -> stubs)",
        description="Replace each region between '### BEGIN SOLUTION' and '### END SOLUTION' "
        "by nbgrader's stub 'raise NotImplementedError()', remove hidden tests and clear "
        "outputs, as 'nbgrader generate_assignment' does.",
    )
    _add_notebooks(p, "teacher versions (default: the course's exercise notebooks)")
    p.add_argument("-o", "--output", type=Path, required=True, help="output directory")
    _add_force(p, "replace notebooks already there (the old file is kept)")

    p = subparsers.add_parser(
        "nbgrader",
        help="lay out an nbgrader course directory of the exercises",
        description="Write DIR/source/<assignment>/<notebook> for each exercise notebook "
        "(teacher versions) and DIR/nbgrader_config.py; then grade with nbgrader in DIR.",
    )
    p.add_argument("directory", metavar="DIR", type=Path, help="the course directory")
    _add_notebooks(p, "teacher versions (default: the course's exercise notebooks)")
    _add_force(p, f"replace files that differ (old ones kept under DIR/{NBGRADER_BACKUPS}/)")
    p.add_argument(
        "--check-submissions",
        action="store_true",
        help="write nothing: list the submissions in DIR/submitted/ that nbgrader would score "
        "0 without a word (a check or solution cell deleted, or its metadata stripped), and "
        "cells whose code changes the checker (Report.assert_passed = ...)",
    )


def _add_notebooks(p, help: str) -> None:
    p.add_argument("notebooks", metavar="NOTEBOOK", nargs="*", type=Path, help=help)


def _add_force(p, help: str) -> None:
    p.add_argument("--force", action="store_true", help=help)
    p.set_defaults(parser=p)


def _sources(notebooks: list[Path], parser) -> list[Path]:
    """The given notebooks (checked: files, distinct names) or the course's exercises."""
    from .. import course

    sources = notebooks or course.exercises()
    for s in sources:
        if not s.is_file():
            why = "is a directory" if s.is_dir() else "no such file"
            parser.error(f"argument NOTEBOOK: {why}: {s}")
    names = [s.name for s in sources]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        parser.error(
            f"argument NOTEBOOK: two inputs would both be written as {twice[0]}: "
            + ", ".join(str(s) for s in sources if s.name == twice[0])
        )
    return sources


def _refuse_own_inputs(directory: Path, names: list[str], sources: list[Path]) -> None:
    """A target that is one of the inputs would be overwritten by its own output: refuse."""
    inputs = {s.resolve() for s in sources}
    for name in names:
        if (directory / name).resolve() in inputs:
            raise CourseError(f"{directory / name} is an input: it would be written onto itself")


def _say(outcome: Outcome, directory: Path) -> None:
    def names(paths):
        return ", ".join(os.path.relpath(p, directory.resolve()) for p in paths)

    if outcome.added:
        print(f"added {len(outcome.added)} files: {names(outcome.added)}")
    if outcome.unchanged:
        print(f"{len(outcome.unchanged)} already there, unchanged")
    if outcome.refreshed:
        print(
            f"refreshed {len(outcome.refreshed)} file(s) you had not edited to this version: "
            f"{names(outcome.refreshed)}"
        )
    for path, old in outcome.replaced:
        print(f"replaced {path}; the old file is kept as {old}")
    if outcome.kept:
        print(
            f"kept {len(outcome.kept)} file(s) that differ from the shipped ones (your work?): "
            f"{names(outcome.kept)}\n    --force replaces them and keeps each old file"
        )


def cmd_lessons(args, parser) -> int:
    """Copy the lessons, the student exercises and CONVENTIONS.md into DIR."""
    from .. import course
    from ..exercises.student_version import student_text

    lessons, exercises = course.lessons(), course.exercises()
    files = {p.name: p.read_bytes() for p in lessons}
    files.update({f"exercises/{p.name}": student_text(p).encode() for p in exercises})
    files[course.CONVENTIONS] = course.conventions().read_bytes()
    _refuse_own_inputs(args.directory, list(files), [*lessons, *exercises])
    recorded = manifest.read(args.directory)
    outcome = install(args.directory, files, force=args.force, shipped=recorded)
    _record(args.directory, files, recorded, outcome)
    _say(outcome, args.directory)
    where = args.directory
    print(f"the course is in {where}: {len(lessons)} lessons, {len(exercises)} exercises")
    print("open it with JupyterLab (pip install 'teachraster[lab]' if it is missing):")
    print(f"    jupyter lab {shlex.quote(str(where))}")
    print(
        f"start with {lessons[0].name}; write each exercise's function where it says "
        "'YOUR CODE HERE' and run the check cell below it"
    )
    return 0


def _record(directory: Path, files: dict, recorded: dict, outcome: Outcome) -> None:
    """Write the manifest: what this version shipped, except for the files the student edited
    (kept: they still come from the version recorded before, or from none)."""
    root = Path(os.path.abspath(directory))
    kept = {p.relative_to(root.resolve()).as_posix() for p in outcome.kept}
    shipped = {n: manifest.fingerprint(n, data) for n, data in files.items() if n not in kept}
    shipped.update({n: recorded[n] for n in kept if n in recorded})
    atomic_write(root / manifest.NAME, manifest.text(shipped, _version()))


def _version() -> str:
    try:
        from importlib.metadata import version

        return version("teachraster")
    except Exception:  # noqa: BLE001 - a checkout without metadata
        return "unknown"


def cmd_student_version(args, parser) -> int:
    """Write the student versions of the given (or the course's) exercise notebooks."""
    from ..exercises.student_version import student_text

    sources = _sources(args.notebooks, parser)
    files = {s.name: student_text(s).encode() for s in sources}  # every marker checked first
    _refuse_own_inputs(args.output, list(files), sources)
    there = [args.output / n for n, data in files.items() if _differs(args.output / n, data)]
    if there and not args.force:
        parser.error(
            f"{there[0]} already exists (and {len(there) - 1} more): it may hold work; choose "
            "another directory or pass --force (the old files are kept beside them)"
        )
    outcome = install(args.output, files, force=args.force)
    for path in outcome.added + [p for p, _ in outcome.replaced] + outcome.unchanged:
        print(f"wrote {path}")
    _say(Outcome(replaced=outcome.replaced), args.output)
    return 0


def _differs(path: Path, data: bytes) -> bool:
    return path.is_file() and not path.is_symlink() and path.read_bytes() != data


def cmd_check_submissions(args, parser) -> int:
    """List what nbgrader would silently score 0 in DIR's submissions; 1 when there is any."""
    from ..course.submissions import problems

    if not (args.directory / "source").is_dir():
        parser.error(f"{args.directory} holds no source/: not an nbgrader course directory")
    found = problems(args.directory)
    for line in found:
        print(line)
    if found:
        print(
            f"{len(found)} problem(s). A missing cell: nbgrader would score its check 0 "
            "without saying so; ask for the notebook again, or restore its cells from "
            "release/ (nbgrader's own cells, metadata included), before `nbgrader autograde`. "
            "A cell that changes the checker: its checks may pass whatever the answer; read "
            "it before trusting the grade"
        )
        return 1
    print("every submitted notebook holds its check and solution cells, metadata included, "
          "and no cell that changes the checker in plain code")  # fmt: skip
    return 0


def cmd_nbgrader(args, parser) -> int:
    """Lay out DIR as an nbgrader course of the (given or the course's) exercise notebooks."""
    if args.check_submissions:
        return cmd_check_submissions(args, parser)
    from .. import course
    from ..course.nbgrader_layout import assignment_name, layout
    from ..exercises.student_version import read_notebook, student_notebook

    sources = _sources(args.notebooks, parser)
    for s in sources:
        if s.suffix != ".ipynb":  # nbgrader would skip it: say so rather than grade nothing
            parser.error(f"argument NOTEBOOK: {s} is not named *.ipynb, so nbgrader skips it")
        nb = read_notebook(s)
        student_notebook(nb, str(s))  # malformed markers stop here, before any write
        if "BEGIN SOLUTION" not in "".join("".join(c.get("source", "")) for c in nb["cells"]):
            raise CourseError(
                f"{s} holds no solution (no '### BEGIN SOLUTION'): it is a student version. "
                "The teacher versions are in the repository's notebooks/exercises/ (a git "
                "checkout, or pip install -e); pass them as NOTEBOOK arguments"
            )
    conventions = course.conventions().read_bytes()
    files = layout({s.name: s.read_bytes() for s in sources}, conventions)
    _refuse_own_inputs(args.directory, list(files), sources)
    outcome = install(args.directory, files, force=args.force, backups=Path(NBGRADER_BACKUPS))
    _say(outcome, args.directory)
    where = shlex.quote(str(args.directory))
    print(f"an nbgrader course of {len(sources)} assignments is in {args.directory}; grade with:")
    print(f"    cd {where}")
    for s in sources[:1]:
        name = shlex.quote(assignment_name(s))
        print(f"    nbgrader generate_assignment {name}   # and so on for each")
    print("    # collect the submissions, then, before grading, list those nbgrader would score 0")
    print(f"    teachraster nbgrader {where} --check-submissions")
    print("    nbgrader autograde ASSIGNMENT && nbgrader generate_feedback ASSIGNMENT")
    print("    nbgrader export    # grades.csv")
    return 0


COMMANDS = {
    "lessons": cmd_lessons,
    "student-version": cmd_student_version,
    "nbgrader": cmd_nbgrader,
}
