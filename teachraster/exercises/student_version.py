"""Student versions of exercise notebooks: solutions replaced by stubs, exactly as nbgrader does.

The teacher version holds each solution between ``### BEGIN SOLUTION`` and ``### END SOLUTION``
(nbgrader's markers, each on a line of its own). The student version is what nbgrader's
``generate_assignment`` releases: every solution region replaced by the stub, indented like
the marker (in a markdown cell, ``YOUR ANSWER HERE``)::

    # YOUR CODE HERE
    raise NotImplementedError()

a solution cell without markers replaced whole by the stub, hidden tests (``### BEGIN HIDDEN
TESTS`` ... ``### END HIDDEN TESTS``) and mark schemes removed, outputs cleared, and the cells
nbgrader locks made read-only. The check cells stay: :func:`teachraster.exercises.check` reports
a stub as "not implemented yet".

nbgrader silently accepts markers it cannot pair (an END before any BEGIN) or finds anywhere in
a line (``x = 1  # BEGIN SOLUTION``); here every such marker is an error naming the notebook,
the cell and the line, so that no answer leaks into a student version through a typo: a second
BEGIN before END, END before BEGIN, BEGIN without END, a marker sharing its line with code or
text, a marker spelt another way (``### begin solution``, ``### BEGIN_SOLUTION``), a region in
a cell that nbgrader metadata marks as no solution cell.

Standard library only (json, re): the build (setup.py) loads this file directly to put student
versions into the wheel, before teachraster or numpy can be imported.

>>> cell = {"cell_type": "code", "source": "def f(x):\\n    ### BEGIN SOLUTION\\n    return x\\n"
...         "    ### END SOLUTION\\n", "outputs": [], "execution_count": 3, "metadata": {}}
>>> print(student_notebook({"cells": [cell]})["cells"][0]["source"])
def f(x):
    # YOUR CODE HERE
    raise NotImplementedError()
<BLANKLINE>
"""

from __future__ import annotations

import copy
import difflib
import json
import os
import re
import tempfile
from pathlib import Path

BEGIN, END = "BEGIN SOLUTION", "END SOLUTION"
#: The nbgrader metadata schema nbgrader accepts.
SCHEMA = 3
STUB = ("# YOUR CODE HERE", "raise NotImplementedError()")
TEXT_STUB = ("YOUR ANSWER HERE",)
#: The regions nbgrader clears, with what replaces them (None: removed).
REGIONS = {"SOLUTION": STUB, "HIDDEN TESTS": None, "MARK SCHEME": None}
#: A well-formed marker: alone on its line, after an optional comment mark (nbgrader's docs
#: write ``=== BEGIN MARK SCHEME ===`` in markdown).
_MARKER = re.compile(
    r"^[ \t]*(?:#+|=+)?[ \t]*(BEGIN|END) (SOLUTION|HIDDEN TESTS|MARK SCHEME)[ \t]*=*[ \t]*\r?$"
)
#: Anything that looks like a marker, in any spelling (case, '_' or '-' for the space).
_LOOKALIKE = re.compile(
    r"\b(begin|end)[\s_-]*(solutions?|hidden[\s_-]*tests?|mark[\s_-]*schemes?)", re.IGNORECASE
)
#: A comment line of two or three words, the first like BEGIN or END: a candidate misspelt
#: marker ("### BEGIN SOLUTON", "### BEGN SOLUTION"), compared with the real ones.
_SHORT_COMMENT = re.compile(
    r"^[ \t]*(?:#+|=+)[ \t]*([A-Za-z]+)[ \t_-]+([A-Za-z]+(?:[ \t_-]+[A-Za-z]+)?)[ \t=]*\r?$"
)


class NotebookError(ValueError):
    """A notebook that cannot be turned into a student version; the message says where.

    ``line`` is the line of the cell (from 1) when the error is a marker's, else None.
    """

    def __init__(self, message: str, line: int | None = None):
        super().__init__(message)
        self.line = line


def _where(name: str, index: int, cell: dict, line: int | None = None) -> str:
    grade_id = (cell.get("metadata") or {}).get("nbgrader", {}).get("grade_id")
    place = f"{name}: cell {index}" + (f" ({grade_id})" if isinstance(grade_id, str) else "")
    return place + (f", line {line}" if line is not None else "")


def _misspelt(line: str) -> bool:
    """A comment line spelt nearly like a marker: a pair of them would hide an answer."""
    match = _SHORT_COMMENT.match(line)
    if not match:
        return False
    first, rest = match.group(1).upper(), " ".join(re.split(r"[ \t_-]+", match.group(2).upper()))

    def like(a: str, b: str) -> bool:  # one or two letters off, same first letter, same words
        same_shape = a[0] == b[0] and a.count(" ") == b.count(" ")
        return same_shape and difflib.SequenceMatcher(None, a, b).ratio() >= 0.75

    return any(like(first, k) for k in ("BEGIN", "END")) and any(like(rest, r) for r in REGIONS)


def _marker(line: str, number: int) -> tuple[str, str] | None:
    """``(BEGIN|END, region)`` for a marker line, None for other lines; malformed: raises."""
    match = _MARKER.match(line)
    if match:
        return match.group(1), match.group(2)
    if _LOOKALIKE.search(line) or _misspelt(line):
        raise NotebookError(
            "a marker must stand alone on its line, spelt '### BEGIN SOLUTION' (or END, "
            f"HIDDEN TESTS, MARK SCHEME): {line.strip()[:80]!r}",
            number,
        )
    return None


def strip_regions(source: str, cell_type: str = "code") -> tuple[str, set[str]]:
    """``source`` with its regions cleared as nbgrader clears them, and the kinds it had.

    Raises :class:`NotebookError` (with ``line`` set; the caller adds the place) at the first
    malformed or unpaired marker.
    """
    stub = STUB if cell_type == "code" else TEXT_STUB
    out, open_region, found, number = [], None, set(), 0
    for number, line in enumerate(source.split("\n"), start=1):
        marker = _marker(line, number)
        if marker is None:
            if open_region is None:
                out.append(line)
            continue
        kind, region = marker
        if kind == "BEGIN":
            if open_region is not None:
                raise NotebookError(f"a second BEGIN {region} before END {open_region}", number)
            open_region = region
            found.add(region)
            indent = line[: len(line) - len(line.lstrip())]
            if REGIONS[region] is not None:
                out.extend(indent + s for s in (stub if region == "SOLUTION" else REGIONS[region]))
        elif open_region != region:
            raise NotebookError(f"END {region} without a BEGIN {region} before it", number)
        else:
            open_region = None
    if open_region is not None:
        raise NotebookError(f"BEGIN {open_region} without an END {open_region}", number)
    return "\n".join(out), found


def strip_solutions(source: str) -> str:
    """``source`` (a code cell's) with every solution region replaced by the stub."""
    return strip_regions(source)[0]


def _cells(nb, name: str) -> list:
    if not isinstance(nb, dict) or not isinstance(nb.get("cells"), list):
        raise NotebookError(f"{name}: not a Jupyter notebook (a JSON object with a list 'cells')")
    if not isinstance(nb.get("nbformat", 4), int) or nb.get("nbformat", 4) < 4:
        raise NotebookError(
            f"{name}: not a notebook this can read: format {nb.get('nbformat')!r}, not 4"
        )
    for index, cell in enumerate(nb["cells"]):
        if not (isinstance(cell, dict) and isinstance(cell.get("cell_type"), str)):
            raise NotebookError(f"{name}: not a Jupyter notebook: cell {index} has no cell_type")
        source = cell.get("source", "")
        if isinstance(source, list) and all(isinstance(s, str) for s in source):
            source = ""
        if not isinstance(source, str) or not isinstance(cell.get("metadata", {}), dict):
            raise NotebookError(
                f"{name}: not a Jupyter notebook: cell {index} has a malformed source or metadata"
            )
    return nb["cells"]


def _stubbed(text: str, stub: str) -> bool:
    """Does ``text`` hold the stub already (a student version, to be left as it is)?"""
    lines = [line.strip() for line in text.split("\n")]
    first, *rest = stub.split("\n")
    return any(
        lines[i : i + len(rest) + 1] == [first, *rest]
        for i in range(len(lines))
        if lines[i] == first
    )


def _check_grading(grading: dict, cell: dict, where: str) -> None:
    """Refuse what nbgrader's metadata validator refuses (nbgrader/nbgraderformat/v3.py)."""
    missing = [key for key in ("grade", "solution", "locked") if key not in grading]
    if missing:
        raise NotebookError(f"{where}: nbgrader metadata without {', '.join(missing)}")
    if grading.get("schema_version") != SCHEMA:
        raise NotebookError(
            f"{where}: nbgrader metadata of schema version {grading.get('schema_version')!r}, "
            f"not {SCHEMA} (run 'nbgrader update' on the notebook)"
        )
    grade, solution, task = grading["grade"], grading["solution"], grading.get("task", False)
    if grade or solution or grading["locked"]:
        if not isinstance(grading.get("grade_id"), str) or not grading["grade_id"]:
            raise NotebookError(f"{where}: an nbgrader cell without a grade_id")
    if grade and "points" not in grading:
        raise NotebookError(f"{where}: a graded cell without points")
    markdown = cell.get("cell_type") == "markdown"
    if task and not markdown:
        raise NotebookError(f"{where}: a task cell must be markdown")
    if not task and markdown and grade != solution:
        raise NotebookError(
            f"{where}: a markdown cell graded by hand must be both a grade and a solution cell"
        )


def _student_cell(cell: dict, name: str, index: int) -> None:
    source = cell.get("source", "")
    text = "".join(source) if isinstance(source, list) else source
    meta = cell.setdefault("metadata", {})
    grading = meta.get("nbgrader") if isinstance(meta.get("nbgrader"), dict) else {}
    if "nbgrader" in meta:
        if not isinstance(meta["nbgrader"], dict):
            raise NotebookError(f"{_where(name, index, cell)}: its nbgrader metadata is not a dict")
        _check_grading(grading, cell, _where(name, index, cell))
    try:
        text, found = strip_regions(text, cell["cell_type"])
    except NotebookError as exc:
        raise NotebookError(f"{_where(name, index, cell, exc.line)}: {exc}", exc.line) from None
    # as nbgrader: a region in a cell its metadata does not mark for it is an error
    for region, flag in (
        ("SOLUTION", "solution"),
        ("HIDDEN TESTS", "grade"),
        ("MARK SCHEME", "task"),
    ):
        if grading and region in found and not grading.get(flag):
            raise NotebookError(
                f"{_where(name, index, cell)}: a {region} region in a cell whose nbgrader "
                f"metadata does not say {flag!r}: true"
            )
    stub = "\n".join(STUB if cell["cell_type"] == "code" else TEXT_STUB)
    if grading.get("solution") and "SOLUTION" not in found and not _stubbed(text, stub):
        text = stub  # as nbgrader: a solution cell without markers is all solution
    if grading.get("solution") or found:
        cell.pop("attachments", None)  # a pasted picture of the answer goes with it
    cell["source"] = text
    if cell["cell_type"] == "code":
        cell["outputs"], cell["execution_count"] = [], None
    if grading.get("solution") or grading.get("grade") or grading.get("locked"):
        meta["deletable"] = False  # as nbgrader's LockCells: the graded cells stay
    if not grading.get("solution") and (grading.get("grade") or grading.get("locked")):
        meta["editable"] = False


def student_notebook(nb: dict, name: str = "notebook") -> dict:
    """A copy of notebook ``nb`` (as parsed JSON) as nbgrader would release it.

    ``name`` (the file, say) starts every error message. Raises :class:`NotebookError` for a
    malformed marker or a JSON value that is not a notebook.
    """
    nb = copy.deepcopy(nb)
    ids: dict[str, int] = {}
    for index, cell in enumerate(_cells(nb, name)):
        _student_cell(cell, name, index)
        grading = cell["metadata"].get("nbgrader") or {}
        if grading.get("grade") or grading.get("solution") or grading.get("locked"):
            grade_id = grading["grade_id"]
            if grade_id in ids:
                raise NotebookError(
                    f"{_where(name, index, cell)}: grade_id {grade_id!r} is also cell "
                    f"{ids[grade_id]}'s (nbgrader refuses a duplicate grade id)"
                )
            ids[grade_id] = index
    return nb


def read_notebook(path: Path) -> dict:
    """Notebook ``path`` as parsed JSON; :class:`NotebookError` (naming it) if it is none."""
    path = Path(path)
    try:
        nb = json.loads(path.read_bytes().decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise NotebookError(f"{path}: not a Jupyter notebook (not UTF-8 JSON: {exc})") from None
    _cells(nb, str(path))
    return nb


def notebook_text(nb: dict) -> str:
    """``nb`` as Jupyter saves it (one-space indent, UTF-8 kept, a final newline)."""
    return json.dumps(nb, indent=1, ensure_ascii=False) + "\n"


def student_text(src: Path) -> str:
    """The student version of notebook file ``src``, as the text of a notebook file."""
    return notebook_text(student_notebook(read_notebook(src), str(src)))


def write_student_version(src: Path, dst: Path) -> Path:
    """Write the student version of notebook ``src`` to ``dst`` (a file or a directory).

    The text goes to a temporary file renamed over ``dst``: an interrupted write leaves no
    truncated notebook. (The course commands add the checks against losing work.)
    """
    src, dst = Path(src), Path(dst)
    if dst.is_dir():
        dst = dst / src.name
    text = student_text(src)
    fd, tmp = tempfile.mkstemp(dir=dst.parent, prefix=f".{dst.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, dst)
    except BaseException:
        os.unlink(tmp)
        raise
    return dst
