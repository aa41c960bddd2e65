"""Submissions nbgrader would grade 0 without a word: found before grading.

nbgrader finds a student's answers and its own check cells by their cell metadata
(``metadata.nbgrader.grade_id``). An editor that strips cell metadata (some do on save), or a
student who deletes a check cell, leaves nbgrader nothing to grade: ``nbgrader autograde``
scores those checks 0 and says nothing. :func:`problems` compares each submitted notebook
(``submitted/<student>/<assignment>/<notebook>``) with its source (``source/<assignment>/``):
every check cell and every solution cell of the source must be there, with its metadata.
``teachraster nbgrader DIR --check-submissions`` prints what it finds.

It also flags a cell that changes the checker (r14 09-3). A student's cells run in the grading
kernel before the locked checks, so one line, ``Report.assert_passed = lambda self: None``,
makes every later check pass whatever the answer. :func:`checker_changes` reads the code of
each cell that is not one of the source's own cells and flags, by their text (``ast``), an
assignment to or a ``setattr`` on a checker name (``Report``, ``ex``, ``teachraster``,
``tries`` ...), a reset of exercise 11's counts, and an import of the checker's machinery
(``teachraster.exercises.report``, ``.tries``, ``.checks`` ...). It reads what is written,
not what runs: code built at run time (``exec`` of a text, ``getattr`` with a computed name)
passes unseen (docs/grading.md says so).

Standard library only.
"""

from __future__ import annotations

import ast
import json
from pathlib import Path

#: Names whose attributes a solution has no reason to set: the checker and its modules.
CHECKER_NAMES = frozenset({"teachraster", "exercises", "ex", "Report", "Failure", "tries",
                           "checks", "report", "running", "package_answers"})  # fmt: skip
#: The checker's machinery: a solution imports none of it (``ex.check`` and the package's
#: functions are imported by the notebooks' locked cells).
MACHINERY = frozenset({"report", "tries", "checks", "running", "package_answers", "interrupt",
                       "alarm", "value_checks", "diagnosis", "output"})  # fmt: skip
_RESETS = frozenset({"clear", "pop", "popitem", "update", "setdefault", "__setitem__"})


def _dotted(node) -> list[str]:
    """The names of an attribute chain (``a.b[0].c`` -> a, b, c); [] for anything else."""
    out = []
    while isinstance(node, ast.Attribute | ast.Subscript | ast.Call):
        if isinstance(node, ast.Attribute):
            out.append(node.attr)
        node = node.func if isinstance(node, ast.Call) else node.value
    return [node.id, *reversed(out)] if isinstance(node, ast.Name) else []


def _flagged(node) -> bool:
    """Does this statement or call change the checker (see the module's note)?"""
    if isinstance(node, ast.Assign | ast.AugAssign | ast.AnnAssign | ast.Delete):
        targets = node.targets if isinstance(node, ast.Assign | ast.Delete) else [node.target]
        return any(isinstance(t, ast.Attribute | ast.Subscript)
                   and CHECKER_NAMES & set(_dotted(t)) for t in targets)  # fmt: skip
    if isinstance(node, ast.Call):
        called = _dotted(node.func)
        if called[-1:] in (["setattr"], ["delattr"], ["__setattr__"]) and node.args:
            return bool(CHECKER_NAMES & set(_dotted(node.args[0])) or called[-1] != "setattr")
        return bool(called[-1:] and called[-1] in _RESETS
                    and {"tries", "_FAILED", "_WRONG"} & set(called))  # fmt: skip
    if isinstance(node, ast.ImportFrom) and node.module:
        parts = node.module.split(".")
        named = {a.name for a in node.names}
        return parts[:2] == ["teachraster", "exercises"] and bool(
            MACHINERY & set(parts[2:3]) or (len(parts) == 2 and MACHINERY & named)
        )
    if isinstance(node, ast.Import):
        return any(a.name.split(".")[:2] == ["teachraster", "exercises"]
                   and MACHINERY & set(a.name.split(".")[2:3]) for a in node.names)  # fmt: skip
    return False


def checker_changes(source: str) -> list[str]:
    """The lines of one cell's code that change the checker (the module's note)."""
    lines = source.splitlines()
    code = "\n".join("" if ln.lstrip()[:1] in ("%", "!") else ln for ln in lines)  # magics
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return []
    found = sorted({n.lineno for n in ast.walk(tree) if _flagged(n)})
    return [lines[k - 1].strip() for k in found]


def _cell_text(cell: dict) -> str:
    text = cell.get("source", "")
    return "".join(text) if isinstance(text, list) else str(text)


def _graded_cells(nb: dict) -> dict[str, str]:
    """grade_id -> "check cell" or "solution cell", for the cells nbgrader grades by id."""
    out = {}
    for cell in nb.get("cells", []):
        meta = (cell.get("metadata") or {}).get("nbgrader") or {}
        if not isinstance(meta, dict) or not isinstance(meta.get("grade_id"), str):
            continue
        if meta.get("grade"):
            out[meta["grade_id"]] = "check cell"
        elif meta.get("solution"):
            out[meta["grade_id"]] = "solution cell"
    return out


def _read(path: Path) -> dict | None:
    try:
        nb = json.loads(path.read_bytes().decode("utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return None
    return nb if isinstance(nb, dict) and isinstance(nb.get("cells"), list) else None


def problems(root: Path) -> list[str]:
    """What nbgrader would silently score 0 in ``root``'s submissions, one line each."""
    root = Path(root)
    out = []
    for source in sorted((root / "source").glob("*/*.ipynb")):
        assignment = source.parent.name
        wanted = _graded_cells(_read(source) or {})
        for student in sorted(p for p in (root / "submitted").glob("*") if p.is_dir()):
            folder = student / assignment
            if not folder.is_dir():
                continue  # no submission for this assignment: nbgrader says so itself
            where = f"submitted/{student.name}/{assignment}/{source.name}"
            nb = _read(folder / source.name)
            if nb is None:
                why = "missing" if not (folder / source.name).exists() else "not a notebook"
                out.append(f"{where}: {why}: every check of it scores 0")
                continue
            have = _graded_cells(nb)
            for grade_id, kind in wanted.items():
                if have.get(grade_id) != kind:
                    out.append(
                        f"{where}: the {kind} {grade_id!r} is gone (deleted, or its cell "
                        "metadata stripped by an editor): nbgrader scores it 0 without a word"
                    )
            out += _changes(where, nb, _read(source) or {})
    return out


def _changes(where: str, nb: dict, source: dict) -> list[str]:
    """A line for each cell of ``nb`` that changes the checker (r14 09-3); the source's own
    cells, as shipped, are not read."""
    shipped = {_cell_text(c) for c in source.get("cells", []) if c.get("cell_type") == "code"}
    out = []
    for cell in nb.get("cells", []):
        text = _cell_text(cell)
        if cell.get("cell_type") != "code" or text in shipped:
            continue
        for line in checker_changes(text):
            out.append(
                f"{where}: a cell changes the checker ({line[:80]!r}): a student's cell runs "
                "in the grading kernel, so code that rebinds the checker (Report.assert_passed, "
                "ex.check) or resets its counts can make later checks pass whatever the "
                "answer. Read the cell, and re-check that student's functions by hand"
            )
    return out
