"""An nbgrader course directory of the exercises: ``teachraster nbgrader DIR``.

nbgrader (https://nbgrader.readthedocs.io) expects the teacher versions under
``source/<assignment>/`` and its settings in ``nbgrader_config.py`` at the course's root. Each
exercise notebook is one assignment named after it (``01_coverage``), released with the
conventions it refers to. Its check cells are nbgrader's autograded test cells (one point
each): they call ``report.assert_passed()``, so a failing check scores 0 and its feedback
carries the checker's explanation.

Standard library only: laying out the files needs neither nbgrader nor numpy.
"""

from __future__ import annotations

from pathlib import Path

#: The settings the round trip of the suite (tests/test_nbgrader.py) runs with.
CONFIG = '''"""nbgrader settings of the teachraster exercises (written by ``teachraster nbgrader``).

    cd THIS_DIRECTORY
    nbgrader generate_assignment 01_coverage    # release/01_coverage/: the student version
    teachraster nbgrader . --check-submissions  # submissions nbgrader would score 0 silently
    nbgrader autograde 01_coverage              # grades submitted/<student>/01_coverage/
    nbgrader generate_feedback 01_coverage      # feedback/<student>/01_coverage/*.html
    nbgrader export                             # grades.csv
"""

import os

c = get_config()  # noqa: F821 (nbgrader defines it)

# Every check gives a student's code 10 s of CPU time in all, a case 2 s of it (an endless
# loop is stopped after 2 s of CPU). The check cells are locked, so their budget cannot be
# raised there: to raise every check's budget for the whole class (a slow grading machine,
# a course that welcomes slow but correct code), set the seconds here. The kernels nbgrader
# starts inherit this environment variable.
os.environ.setdefault("TEACHRASTER_CHECK_BUDGET", "10")

c.CourseDirectory.course_id = "teachraster"
# The stub nbgrader writes for a solution (its default for Python, named here because
# `teachraster student-version` writes the same one).
c.ClearSolutions.code_stub = {"python": "# YOUR CODE HERE\\nraise NotImplementedError()"}
# Each check stops a student's endless loop within its own budget of CPU time; on a busy
# machine the wall-clock time is longer (up to 20 times a case's limit). This only bounds a
# cell that hangs outside a check (nbgrader's default is 30 s per cell).
c.Execute.timeout = 600
'''


def assignment_name(notebook: Path) -> str:
    """The assignment of an exercise notebook: its name without ``.ipynb``."""
    return Path(notebook).stem


def layout(notebooks: dict[str, bytes], conventions: bytes) -> dict[str, bytes]:
    """The files of the course directory, by relative name, from the teacher notebooks.

    ``notebooks`` maps each notebook's file name to its content.
    """
    files = {"nbgrader_config.py": CONFIG.encode()}
    for name, data in notebooks.items():
        folder = f"source/{assignment_name(Path(name))}"
        files[f"{folder}/{name}"] = data
        files[f"{folder}/CONVENTIONS.md"] = conventions
    return files
