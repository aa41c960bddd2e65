"""The cells of an nbgrader notebook as the tests read them: by ``grade_id``, and flattened
(whitespace folded), so a rewrap of a cell's text does not break a check on its words."""

from __future__ import annotations

import json
from pathlib import Path


def graded_cell(notebook: Path, grade_id: str) -> str:
    """The source of the cell of ``notebook`` whose nbgrader ``grade_id`` is ``grade_id``."""
    cells = json.loads(Path(notebook).read_text(encoding="utf-8"))["cells"]
    for cell in cells:
        if cell["metadata"].get("nbgrader", {}).get("grade_id") == grade_id:
            return "".join(cell["source"])
    raise KeyError(f"{Path(notebook).name} has no cell with grade_id {grade_id!r}")


def flat(text: str) -> str:
    """``text`` with every run of whitespace one space."""
    return " ".join(text.split())
