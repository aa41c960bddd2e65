"""Review r186 of lesson 12a (lines): presentation, two omissions, and one prediction.

12a-10: the lesson's own checking code (the tie rows, llvmpipe's allowance, the clipping
sample) is folded, its point in its output. 12a-9: the explorer's instructions, §2's error
term and the wide-line table are cut to their concepts; the spec editions' notes stand in one
folded Sources block. 12a-6: the strict (rectangular) 1 px line is drawn beside the diamond
rule, 1 or 2 pixels a column against one, counted. 12a-7: brightness against slope, a 45°
line's ink per unit length 1/√2 of a horizontal one's. 12a-8: Xiaolin Wu's weights printed
beside the exact areas. 12a-5: q_bres asks for the mechanism. 12a-1, 11, 12, 13: the caps
figure's own key, Ek's equation, "its answers are Vulkan's", the farthest clipping change.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from notebook_runs import executed, lesson

pytestmark = [pytest.mark.filterwarnings("ignore::DeprecationWarning"), pytest.mark.notebook]

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "12a_lines.ipynb"


def _cells() -> list[dict]:
    return json.loads(NOTEBOOK.read_text())["cells"]


def _cell(cell_id: str) -> dict:
    return next(c for c in _cells() if c.get("id") == cell_id)


def _source(cell_id: str) -> str:
    return "".join(_cell(cell_id)["source"])


def _flat(cell_id: str) -> str:
    return " ".join(_source(cell_id).split())


def _printed(cell_id: str) -> str:
    cell = next(c for c in executed("12a_lines").notebook().cells if c.get("id") == cell_id)
    return "".join(o.get("text", "") for o in cell.outputs if o.get("output_type") == "stream")


@pytest.fixture(scope="module")
def ns():
    return lesson("12a_lines")


def test_checking_code_is_folded():
    """12a-10: the cells whose point is their output show it, not 40-60 lines of harness."""
    for cell_id in ("b9bb4840", "fc2a3156", "clipcell", "bresquote"):
        meta = _cell(cell_id)["metadata"]
        assert meta["jupyter"]["source_hidden"] is True and meta["tags"] == ["hide-input"]


def test_prose_cut_to_its_concepts():
    """12a-9: the explorer's key is short; §2's opening holds the error term, not the
    player's key (held with the player now); the wide-line table has no PDF's layout."""
    opening = _source("diamondexpmd").split("Try:")[0]
    assert len(opening.split()) < 90 and "compare the lit" in _source("diamondexpmd")
    assert "player" not in _source("f01a3333") and len(_source("f01a3333").split()) < 200
    assert "**The player above**" in _source("bresquote")
    wide = _source("widetbl")
    assert "May 5, 2022" not in wide and "PDF" not in wide and "14.5.2.1" not in wide
    assert "`LineRasterizationMode`" in wide and "1.0 px quadrilaterals" in wide
    sources = _flat("sources")
    assert _cells()[-1].get("id") == "sources" and sources.endswith("</details>")
    for note in ("May 5, 2022", "GL 1.1's §3.4.2", "point_line_tri_clip", "eq. 9 and eq. 19"):
        assert note in sources, note
    assert "point_line_tri_clip" not in _source("clipmd")


def test_strict_line_lights_one_or_two_pixels_a_column(ns):
    """12a-6: the 1 px rectangle (Vulkan's strictLines, RECTANGULAR mode) beside the diamond
    rule on one line of slope 2/3, every centre at least 0.08 px from its outline: the
    diamond rule lights one pixel in each of 13 columns, the rectangle 1 or 2 (17 pixels)."""
    assert ns.k_margin >= 0.08 and str(ns.k_slope) == "2/3"
    assert ns.per_col["diamond"] == [1] * 13
    assert set(ns.per_col["strict"]) == {1, 2} and sum(ns.per_col["strict"]) == 17
    assert not (ns.k_diamond & ~ns.k_strict).any()  # the rectangle holds every diamond pixel
    printed = _printed("strictcell")
    assert "diamond exit      13 pixels: 1 1 1 1 1 1 1 1 1 1 1 1 1" in printed
    assert "strict rectangle  17 pixels: 1 1 2 1 1 2 1 1 2 1 1 2 1" in printed
    text = _flat("strictmd")
    assert "`strictLines`" in text and "lights 1 or 2 pixels there" in text
    assert round(np.hypot(1, 2 / 3), 3) == 1.202 and "1.202 px tall" in printed


def test_brightness_against_slope(ns):
    """12a-7: one pixel a column gives a 45° line 1/√2 of a horizontal line's ink per unit
    length; the smooth line's area is its length at every slope; the strict rectangle lights
    1 or 2 a column at 45° as the line moves by 0.45 px (0.707 or 1.414 per unit length)."""
    ink = ns.ink
    assert ink["horizontal"] == pytest.approx((1, 1, 1))
    assert ink["45°, through the centres"] == pytest.approx((2**-0.5, 2**-0.5, 1))
    assert ink["45°, 0.45 px lower"] == pytest.approx((2**-0.5, 2**0.5, 1))
    assert ns.dim == pytest.approx(2**-0.5)
    printed = _printed("strictcell")
    assert "diamond exit, 45° against horizontal: 0.707 = 1/√2" in printed
    assert "length 10.733 px, area 10.733 px²; the aliased line lights 10" in printed
    assert "length × cos θ = 9.6 px" in printed
    assert round(float(ns.smooth.sum()), 3) == 10.733 and int(ns.one_px.sum()) == 10
    text = _flat("strictmd")
    assert "$1/\\sqrt2$ of a horizontal line's ink" in text and "10.733 px²" in text
    assert "lights 10 pixels" in text
    assert "$1/\\sqrt2$ of a horizontal line's ink" in _flat("db845d96")


def test_wu_weights_beside_the_exact_areas(ns):
    """12a-8: "an approximation of that area" as numbers: in the question's column Wu's two
    weights (0.380, 0.620) sum to 1, the exact areas (0.439, 0.679) to √(1 + m²) = 1.118.
    Printed only in the cell q_smooth holds."""
    assert ns.wu_weights == pytest.approx((0.38, 0.62))
    assert ns.sm_column == pytest.approx(np.hypot(1, 0.5))
    assert abs(ns.wu_weights[0] - ns.sm_area) > 0.03  # outside q_smooth's tolerance: no cue
    printed = _printed("smoothcell")
    assert "Wu's weights there: 0.380 and 0.620" in printed and "1.118 = √(1 + m²)" in printed
    assert _source("smoothcell").startswith("q_smooth.hold()")
    assert "prints Wu's two weights" in _flat("smoothmd")


def test_bresenham_question_is_not_answered_before_its_check(ns):
    """12a-5: nothing a student can read before Check says where or how the two rules part:
    the player's cell comment no longer does, and the 'reduces to Bresenham' text is held."""
    from test_predictions_r147 import seen_before_check

    seen = seen_before_check("12a_lines", "q_bres = Predict(", "q_bres")
    for told in ("Bresenham stays", "GL's ε steps", "keeps the row", "keeps the upper",
                 "2 pixels differ: [(2, 6), (3, 6)]"):  # fmt: skip
        assert told not in seen, told
    assert _source("bresquote").startswith("q_bres.hold()")


def test_minor_items(ns):
    """12a-1: the caps figure has its own key (the four fills and the caps) and dashed cap
    outlines. 12a-11: Ek's t is his eq. 9 solved for t, eq. 19 being 1/z linear in q.
    12a-12: "its answers are Vulkan's". 12a-13: the clipping cell prints its change farthest
    from the clipped end, 19 px away: "not only beside the clipped end"."""
    whole = _source("joinsfig").split("# the whole polyline")[1]
    for label in ("a segment's rectangle", "both rectangles", "added by the bevel",
                  "added by the miter only", "added by the caps", "the join's and caps' outlines"):  # fmt: skip
        assert f'label="{label}' in whole, label
    assert 'ls="--"' in whole.split("for cap in")[1]
    persp = _source("persp")
    assert "Ek's eq. 9, t (z1 - q (z1 - z0)) = q z0, solved for t" in persp
    assert "eq. 19 solved" not in persp and "(its eq. 9 solved for $t$)" in _flat("perspmd")
    table = _flat("tiestable")
    assert "so its answers are Vulkan's" in table and "its column is" not in table
    assert ns.farthest[4] == pytest.approx(18.956, abs=1e-3)
    assert "pixels [(5, 18), (6, 18)], 19.0 px from the new end" in _printed("clipcell")
    assert "not only beside the clipped end" in _flat("clipmd")
    assert "prints the change farthest from its clipped end" in _flat("clipmd")


def test_12a_r191_the_tie_is_broken_the_other_way_on_this_line_only():
    """Review r191 12a F: Bresenham breaks the midpoint tie the other way from the diamond rule
    on §2's line, not on every line (in 4 of 8 octants the two agree); and nothing visible
    under q_bres says the two part on this line, or that the printout reaches column 11."""
    import json
    import re
    from pathlib import Path

    path = Path(__file__).resolve().parent.parent / "notebooks" / "12a_lines.ipynb"
    cells = ["".join(c["source"]) for c in json.loads(path.read_text())["cells"]]
    flat = re.sub(r"\s+", " ", "\n".join(cells))
    assert "(a tie, which it breaks the other way)" not in flat
    assert "which on §2's line it breaks the other way" in flat
    assert "light differently on this line" not in flat
    assert "the error terms printed above go on to column" not in flat
