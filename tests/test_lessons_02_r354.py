"""Lesson 02, review r354: the folded cells' first lines speak to the student (S1), the
printed lines fit a column (S6), and the bounding box's cost is stated with its numbers (M1)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

NOTEBOOK = Path(__file__).resolve().parent.parent / "notebooks" / "02_half_planes.ipynb"


def test_r354_folded_cells_open_with_the_question_not_a_build_note():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    folded = ["".join(c["source"]) for c in cells
              if c["metadata"].get("jupyter", {}).get("source_hidden")]  # fmt: skip
    assert len(folded) >= 5
    for text in folded:
        first = text.split("\n", 1)[0]
        assert "folded" not in first and "the next cell" not in first, first
        assert first.startswith(("# Question", "q_")), first
    held = next(t for t in folded if t.startswith("q_edge12.hold()"))
    assert "all three questions above" in held.split("\n", 1)[0]
    code = "\n".join(folded)
    assert "look-up" not in code and "works it out from the formula" not in code  # S7


def test_r354_the_outputs_fit_a_column_and_the_box_share_is_printed():
    from notebook_runs import executed

    cells = executed("02_half_planes").notebook().cells
    text = {c.get("id"): "".join(c.source) for c in cells}
    printed = {c.get("id"): "".join(o.text for o in c.get("outputs", [])
                                    if o.output_type == "stream") for c in cells}  # fmt: skip
    for cid in ("c10", "f444dd6b", "r231-30a"):  # cells 16, 26 and 37: 136-191 characters
        lines = printed[cid].splitlines()
        assert lines and max(map(len, lines)) <= 80, (cid, max(lines, key=len))
    # M1: "at most half its box ... 41% for ours, 7% for a sliver", printed by section 1's cell
    shares = re.findall(r"covers (\d+) of its (\d+) centres tested \((\d+)%\)", printed["c03"])
    (ours, sliver) = [(int(n), int(m), int(p)) for n, m, p in shares]
    assert ours == (70, 169, 41) and sliver[2] < 10 and 2 * max(ours[0], sliver[0]) <= ours[1]
    flat = " ".join(text["c09"].split())
    assert (
        "area is at most half its box's" in flat
        and f"{ours[2]}% for ours, {sliver[2]}% for a sliver" in flat
    )
