"""Reviews r217 (lesson 12b, blending) and r218 (lesson 12a, lines): the small items, as fixed.

r218 12a-1: q_tie's explanation names the cell that prints the tie by what it does (the next
cell is Markdown). 12a-2: p1's pixel is "left unlit", as the player draws it (white), not
"dark". 12a-3: §4's lead-in asks what q_wide asks, a count per hundred, not a difference.
r217 12b-1, 12b-2 are checked in test_lines_lesson (the core Vulkan wording, "None of them
reorders"). 12b-3: the cell after the OIT figure measures, it asks nothing. 12b-4: §7's two
sRGB boxes in a table, in the order the cell prints them. 12b-5: engines sort objects and
draw a closed transparent mesh back faces first, with sources.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

_NOTEBOOKS = Path(__file__).resolve().parents[1] / "notebooks"


def _cells(name: str) -> dict[str, str]:
    cells = json.loads((_NOTEBOOKS / f"{name}.ipynb").read_text())["cells"]
    return {c.get("id"): "".join(c["source"]) for c in cells}


def _flat(text: str) -> str:
    return " ".join(text.split())


def test_r218_12a_the_tie_cell_named_by_what_it_does():
    cells = _cells("12a_lines")
    ids = list(cells)
    explain = _flat(cells["27754070"].split("explain=")[1])
    assert "The next cell prints it" not in explain
    assert "The cell after the figure's description prints and draws it" in explain
    # the cell after the question describes the figure; the one after it prints and draws
    after = ids[ids.index("27754070") + 1 :]
    assert after[:2] == ["diamondfig", "9d36d56c"]
    assert cells["diamondfig"].startswith("Below, the line of the last question")
    assert "print(" in cells["9d36d56c"] and "plt.show()" in cells["9d36d56c"]


def test_r218_12a_p1_pixel_left_unlit_and_wide_question_asks_per_hundred():
    cells = _cells("12a_lines")
    assert "dark in both" not in cells["bresquote"]
    assert "(p1's pixel is left unlit in both)" in _flat(cells["bresquote"])
    lead_in = _flat(next(s for s in cells.values() if s.startswith("## 4. Wide lines")))
    assert "How many more pixels" not in lead_in
    assert lead_in.endswith("For every hundred pixels one lights, how many does the other light?")
    asked = cells["wideq"].split("q_wide = Predict(")[1].split("answer=")[0]
    # q_wide asks the same: a count per hundred (its prompt, split over string literals)
    assert "For every 100 pixels" in asked and "how many does the rectangle light?" in asked


def test_r217_12b_measures_table_and_object_sorting():
    cells = _cells("12b_blending")
    assert "the cell after the figure measures where WBOIT is right" in _flat(cells["oit_figmd"])
    assert " asks " not in _flat(cells["oit_figmd"])
    # item 4: one table row per printed way, in the printed order, and the three bullets
    tryit = cells["tryit"]
    rows = [line for line in tryit.splitlines() if line.startswith("| ") and "---" not in line]
    assert rows[0].startswith("| ticked | what it models in GL | what you see |")
    assert [r.split("|")[1].strip() for r in rows[1:]] == [
        "neither",
        '"sRGB framebuffer"',
        "both",
        '"colours sRGB-encoded (decode)"',
    ]
    printed = cells["7a2f48dd"].split("srgb_ways = {")[1].split("}")[0]
    order = re.findall(r"\((True|False), (True|False)\)", printed)
    assert order == [("False", "False"), ("True", "False"), ("True", "True"), ("False", "True")]
    bullets = [line for line in tryit.splitlines() if line.startswith("- **")]
    assert len(bullets) == 4  # review r263 M3: the blend state's bullet first
    assert bullets[0].startswith('- **"blend"** and **"alpha"**')
    # item 5: objects, two passes, back faces first, with the sources quoted
    text = _flat(cells["sortfails"])
    assert text.startswith("Engines sort whole **objects**, not triangles")
    assert "its back faces first (front faces culled), then its front faces (back faces" in text
    assert '"transparent objects, which need to be sorted from back to front before being' in text
    assert "SIGGRAPH 2000 course notes, §12.3 *Sorting*" in text
    assert (
        '`TWO_PASSES_TWO_SIDES` transparency mode draws "first with back faces only, then' in text
    )
