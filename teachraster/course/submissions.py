"""Submissions nbgrader would grade 0 without a word: found before grading.

nbgrader finds a student's answers and its own check cells by their cell metadata
(``metadata.nbgrader.grade_id``). An editor that strips cell metadata (some do on save), or a
student who deletes a check cell, leaves nbgrader nothing to grade: ``nbgrader autograde``
scores those checks 0 and says nothing. :func:`problems` compares each submitted notebook
(``submitted/<student>/<assignment>/<notebook>``) with its source (``source/<assignment>/``):
every check cell and every solution cell of the source must be there, with its metadata.
``teachraster nbgrader DIR --check-submissions`` prints what it finds.

Standard library only.
"""

from __future__ import annotations

import json
from pathlib import Path


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
    return out
