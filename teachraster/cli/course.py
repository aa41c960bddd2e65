"""``teachraster lessons`` and ``teachraster student-version``: the course as files to open.

``teachraster lessons [DIR]`` copies the lesson notebooks into DIR and the student versions of
the exercise notebooks into DIR/exercises/, then says how to open them. It never overwrites a
file (a student's work) unless ``--force`` is given.

``teachraster student-version [NOTEBOOK ...] -o DIR`` writes the student version of exercise
notebooks (default: the course's): every region between ``### BEGIN SOLUTION`` and
``### END SOLUTION`` replaced by nbgrader's stub ``raise NotImplementedError()``.

>>> import argparse
>>> sub = argparse.ArgumentParser().add_subparsers(dest="command")
>>> add_parsers(sub)
>>> sub.choices["lessons"].parse_args([]).directory
PosixPath('teachraster-course')
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

DEFAULT_DIR = Path("teachraster-course")


def add_parsers(subparsers) -> None:
    """Add the ``lessons`` and ``student-version`` subcommands to ``subparsers``."""
    p = subparsers.add_parser(
        "lessons",
        help="copy the lessons and exercises (student version) into a directory",
        description="Copy the lesson notebooks into DIR and the student versions of the "
        "exercise notebooks into DIR/exercises/, and say how to open them.",
    )
    p.add_argument(
        "directory",
        metavar="DIR",
        nargs="?",
        type=Path,
        default=DEFAULT_DIR,
        help=f"where to put the course (default: ./{DEFAULT_DIR})",
    )
    p.add_argument("--force", action="store_true", help="overwrite notebooks already in DIR")
    p.set_defaults(parser=p)

    p = subparsers.add_parser(
        "student-version",
        help="write the student version of exercise notebooks (solutions -> stubs)",
        description="Replace each region between '### BEGIN SOLUTION' and '### END SOLUTION' "
        "by 'raise NotImplementedError()' (as nbgrader does) and clear outputs.",
    )
    p.add_argument(
        "notebooks",
        metavar="NOTEBOOK",
        nargs="*",
        type=Path,
        help="teacher versions (default: the course's exercise notebooks)",
    )
    p.add_argument("-o", "--output", type=Path, required=True, help="output directory")
    p.add_argument("--force", action="store_true", help="overwrite notebooks already there")
    p.set_defaults(parser=p)


def _targets(sources: list[Path], directory: Path, force: bool, parser) -> list[Path]:
    targets = [directory / s.name for s in sources]
    existing = [t for t in targets if t.exists()]
    if existing and not force:
        parser.error(
            f"{existing[0]} already exists (and {len(existing) - 1} more): it may hold your "
            "work; choose another directory or pass --force to overwrite"
        )
    directory.mkdir(parents=True, exist_ok=True)
    return targets


def _student_versions(sources: list[Path], directory: Path, force: bool, parser) -> list[Path]:
    from ..exercises.student_version import write_student_version

    targets = _targets(sources, directory, force, parser)
    return [write_student_version(s, t) for s, t in zip(sources, targets)]


def cmd_lessons(args, parser) -> int:
    """Copy the lessons into DIR and the student exercises into DIR/exercises/."""
    from .. import course

    lessons, exercises = course.lessons(), course.exercises()
    targets = _targets(lessons, args.directory, args.force, parser)
    _targets(exercises, args.directory / "exercises", args.force, parser)  # check all first
    for src, dst in zip(lessons, targets):
        shutil.copyfile(src, dst)
    done = _student_versions(exercises, args.directory / "exercises", True, parser)
    where = args.directory
    print(
        f"copied {len(lessons)} lessons into {where}/ and {len(done)} exercises into "
        f"{where / 'exercises'}/"
    )
    print("open them with JupyterLab (pip install 'teachraster[lab]' if it is missing):")
    print(f"    jupyter lab {where}")
    print(
        f"start with {targets[0].name}; write each exercise's function where it says "
        "'YOUR CODE HERE' and run the check cell below it"
    )
    return 0


def cmd_student_version(args, parser) -> int:
    """Write the student versions of the given (or the course's) exercise notebooks."""
    from .. import course

    sources = args.notebooks or course.exercises()
    missing = [s for s in sources if not s.is_file()]
    if missing:
        parser.error(f"argument NOTEBOOK: no such file: {missing[0]}")
    for path in _student_versions(sources, args.output, args.force, parser):
        print(f"wrote {path}", file=sys.stdout)
    return 0


COMMANDS = {"lessons": cmd_lessons, "student-version": cmd_student_version}
