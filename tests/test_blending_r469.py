"""Review r469 (lesson 12b): lesson 11's glass pixel is its §7 (S9), the |WBOIT − truth| panel
greys the pixels outside the overlap (S4), llvmpipe's reverse-subtract codes explained by its
8-bit source (S5), the explorer's ends (S7), density (S8) and the advanced blend equations
(M2). The under blend (M1) was taken out again: its factor pair (ONE_MINUS_DST_ALPHA, ONE) is
exercise 9.3's answer (test_exercises_09.test_lesson_12_prints_no_atop)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from notebook_runs import executed, lesson, streams

pytestmark = [pytest.mark.filterwarnings("ignore::DeprecationWarning"), pytest.mark.notebook]
NB = Path(__file__).resolve().parents[1] / "notebooks" / "12b_blending.ipynb"


def _flat(cid: str) -> str:
    cells = json.loads(NB.read_text())["cells"]
    return " ".join("".join(next(c for c in cells if c.get("id") == cid)["source"]).split())


def test_text_items_r469():
    # S9: lesson 11's §6 is "A NaN in the frame"; the glass pixel is §7
    assert "(lesson 11 §7 follows the same at one pixel, in its history)" in _flat("35d05472")
    # S4: outside the overlap grey, so the black stripes are the only black
    assert "np.ma.masked_where(~two" in _flat("oit_fig")
    assert "(grey: one layer or none)" in _flat("oit_figmd")
    # S8: cell 46 in two paragraphs; cell 51's opener says what the table is
    cells = json.loads(NB.read_text())["cells"]
    srgbgl = "".join(next(c for c in cells if c.get("id") == "srgbglmd")["source"])
    assert "several steps.\n\nWhose errors" in srgbgl
    assert "The two sRGB boxes give four settings; the cell prints one pixel" in _flat("tryit")
    # S5: the clause in the table
    assert "llvmpipe rounds the source to 8 bits first: alpha 0.5 to 128/255" in _flat("blendrules")
    # M2
    assert "`KHR_blend_equation_advanced`, core in OpenGL ES 3.2" in _flat("blendclamp")


def test_llvmpipe_codes_from_an_8bit_source():
    """S5: llvmpipe's [0, 0, 127, 63] is §1's reverse subtract from the source rounded to 8
    bits (alpha 128/255), exactly."""
    ns = lesson("12b_blending")
    if not ns.ok:
        pytest.skip("no OpenGL context")
    stored = np.asarray(ns.gl_clamp["FUNC_REVERSE_SUBTRACT"][0]).astype(int)
    assert ns.rounded_first.tolist() == stored.tolist()
    assert (
        "from the source rounded to 8 bits first (alpha 128/255):\n  codes [0, 0, 127, 63]"
        in streams(executed("12b_blending").notebook())
    )


def test_explorer_ends_disabled():
    """S7: "earlier" is disabled at the top of the list, "later" at the bottom."""
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(white=True, backend="image")
    assert ex.earlier.disabled and not ex.later.disabled
    ex.select.value = len(ex.order) - 1
    assert ex.later.disabled and not ex.earlier.disabled
    ex.sort.click()
    assert ex.select.value == 0 and ex.earlier.disabled


def test_crossing_question_on_the_figure():
    """r437's second lift: a prediction acted on a figure before "sort wrong here": drag the
    marker along row 24 to the column where the two crossing triangles' depth order swaps; the
    swap is where the sort's wrong pixels begin in that row, and the figure waits for Check."""
    ns = lesson("12b_blending")
    assert "answer=(swap_col, row_q + 0.5)," in _flat("q_cross") and "tolerance=2," in _flat(
        "q_cross"
    )
    row = ns.wrong_order[ns.row_q]
    assert int(np.flatnonzero(row)[0]) == ns.swap_col  # the sort goes wrong right of the swap
    assert abs(ns.swap_col - 2) > 2  # the marker starts off the answer
    assert "q_cross.hold()" in _flat("645e8987")
    assert "no correct order" in _flat("sortfails") and "Column" not in _flat("sortfails")
