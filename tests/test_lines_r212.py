"""Review r212 of lesson 12a (lines): a fresh read's nine items, as fixed.

12a-1: the Markdown under q_tie no longer says which half of the shift decides its tie; the
held, folded cell of the ties prints it (the ε² flipped moves nothing, the ε moves the four).
12a-2: the tie table's Vulkan column is computed from the specification's sentence in exact
fractions, not by teachraster's rule relabelled. 12a-3, 12a-4: q_moved names every column
that changed (column 8 newly lit) and points at no hidden figure as if it were shown.
12a-5: the step captions say where the line is read, on the column's centre line x = j + ½,
not "at the centre". 12a-6: Vulkan's non-strict default line is a parallelogram in the
one-pixel table. 12a-7: the DDA comment says what the loop keeps. 12a-8: the attributes along
a line are §6, in the plan. 12a-9: the explorer's key no longer says "outlined".
"""

from __future__ import annotations

import json
import re
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from explorables_node import call_js
from notebook_runs import lesson

import teachraster as tr

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "12a_lines.ipynb"
LINES = ("raster_rules", "explore_lines")


def _cells() -> list[dict]:
    return json.loads(NOTEBOOK.read_text())["cells"]


def _source(cell_id: str) -> str:
    return "".join(next(c for c in _cells() if c.get("id") == cell_id)["source"])


def _flat(cell_id: str) -> str:
    return " ".join(_source(cell_id).split())


@pytest.fixture(scope="module")
def ns():
    return lesson("12a_lines")


def _vulkan_lit():
    """The lesson's own vulkan_lit, run outside the notebook."""
    body = _source("b9bb4840").split("VK_EPS = ")[1].split("\n\n\ndef vulkan_rows")[0]
    scope = {"Fraction": Fraction}
    exec("VK_EPS = " + body, scope)
    return scope["vulkan_lit"]


# -- 12a-5: where the caption reads the line -----------------------------------------------
def test_trace_captions_read_the_line_on_the_column_centre_line():
    x_major = tr.rasterize_line((0.5, 0.5), (8.5, 4.5), 10, 6, trace=True).trace
    assert x_major.caption(3).startswith(
        "column 1: at x = 1.5, the column's centre, the line is at y = 1; pixel (row 1, col 1)"
    )
    y_major = tr.rasterize_line((0.5, 0.5), (4.5, 8.5), 6, 10, trace=True).trace
    assert y_major.caption(3).startswith(
        "row 1: at y = 1.5, the row's centre, the line is at x = 1;"
    )
    dda = tr.rasterize_line((0.5, 0.5), (8.5, 4.5), 10, 6, rule="dda", trace=True).trace
    assert dda.caption(3).startswith("column 1, float32 sum: y = ")
    for trace in (x_major, y_major, dda):
        assert not any("line at the centre" in trace.caption(k) for k in range(len(trace)))


def test_explorer_captions_read_the_line_where_the_trace_does():
    walks = call_js(LINES, [("diamondSteps", [[0.5, 0.5], [8.5, 4.5], 10, 6]),
                            ("diamondSteps", [[0.5, 0.5], [4.5, 8.5], 6, 10])])  # fmt: skip
    x_cap, y_cap = call_js(LINES, [("stepCaption", [walks[0], 1]), ("stepCaption", [walks[1], 1])])
    assert x_cap.startswith("column 1: at x = 1.5, the column's centre, the line is at y = 1. ")
    assert y_cap.startswith("row 1: at y = 1.5, the row's centre, the line is at x = 1. ")
    assert "at the centre." not in x_cap + y_cap


# -- 12a-1, 12a-9: what stands on screen around q_tie and the explorer --------------------------
def test_nothing_visible_under_q_tie_says_which_half_of_the_shift_decides():
    text = _flat("diamondfig")
    assert "shift by ε decides" not in text and "alike" not in text
    assert "ties, four of them" in text
    # the folded, held ties cell prints it, and the table's text points at that print
    cell = _source("b9bb4840")
    assert cell.startswith("q_tie.hold()") and "flipping the ε² moves" in cell
    assert "flips the sign of each on §1's line" in _flat("tiestable")


@pytest.mark.notebook
def test_the_shift_by_epsilon_decides_every_sloped_tie(ns):
    assert ns.moved_by == {(1, -1): 0, (-1, 1): len(ns.tie_xy)} == {(1, -1): 0, (-1, 1): 4}


def test_explorer_key_says_what_it_draws_darker():
    key = _flat("diamondexpmd").split("Try:")[0]
    assert "outlined" not in key and "the walk tests" not in key
    assert "faintly and, darker, those of the pixels the line passes through or touches" in key
    assert len(key.split()) < 90


# -- 12a-2: Vulkan's column ----------------------------------------------------------------
def test_vulkan_column_is_the_specification_sentence_not_teachraster():
    cell = _source("b9bb4840")
    vk = cell.split("def vulkan_lit")[1].split("\n\n\ndef d3d_tie_rows")[0]
    assert "rasterize_line" not in vk and "Fraction" in vk
    assert "steep_vk = [j for j in range(6) if vulkan_lit(" in cell
    # the sentence, in exact fractions, lights what teachraster lights on random lines,
    # ties galore on the half- and quarter-pixel grids
    vulkan_lit = _vulkan_lit()
    rng = np.random.default_rng(212)
    for n in range(90):
        grid = (256, 2, 4)[n % 3]
        a, b = rng.integers(0, [12 * grid, 8 * grid], (2, 2)) / grid
        if (a == b).all():
            continue
        ours = tr.rasterize_line(a, b, 12, 8).coverage
        theirs = np.array([[vulkan_lit(a, b, i, j) for j in range(12)] for i in range(8)])
        assert (ours == theirs).all(), (a.tolist(), b.tolist())
    assert "not teachraster's code, which applies the same rule" in _flat("cbafd253")


@pytest.mark.notebook
def test_vulkan_column_agrees_with_teachraster_by_computation(ns):
    for name, rows in ns.tie_rows.items():
        assert ns.vk_rows[name] == rows[0], name
    assert ns.steep_vk == ns.steep_cols[0] == [0]


# -- 12a-3, 12a-4: q_moved ---------------------------------------------------------------
@pytest.mark.notebook
def test_moved_line_explanation_names_every_column_that_changed(ns):
    assert ns.moved_cols == [1, 3, 5, 7] and ns.kept_cols == [0, 2, 4, 6]
    assert ns.newly_lit == [8] and not ns.old_cols[:, 8].any() and ns.new_cols[4, 8]
    changed = sorted(ns.moved_cols + ns.newly_lit)
    differ = np.flatnonzero((ns.old_cols != ns.new_cols).any(axis=0)).tolist()
    assert differ == changed  # nothing else changed
    code = _source("movedq01")
    assert "the others keep it" not in code and "keep it; column" in code
    stem = code.split("q_moved = PredictPixels(")[1].split("answer=")[0]
    assert "pixels of the figure above" not in stem
    assert '(the figure above shows them "\n    "once the tie question is checked)' in stem


# -- 12a-6, 12a-7, 12a-8 ---------------------------------------------------------------------
def test_vulkan_row_names_the_non_strict_parallelogram():
    row = next(r for r in _source("linetbl").splitlines() if r.startswith("| Vulkan"))
    assert "without `strictLines`, the default mode draws a parallelogram" in row
    assert "may follow the Bresenham rules instead" in row


@pytest.mark.notebook
def test_dda_comment_says_which_lines_it_keeps(ns):
    code = _source("dda_screen")
    assert "200 random x-major" not in code and "200 drawn,\n# the x-major ones kept" in code
    assert 0 < ns.n_x < 200


def test_attributes_along_a_line_are_a_section_of_the_plan():
    cells = _cells()
    heads = [
        "".join(c["source"]).split("\n")[0]
        for c in cells
        if c["cell_type"] == "markdown" and "".join(c["source"]).startswith("## ")
    ]
    assert heads[4:7] == ["## 5. What llvmpipe does, and what GL allows",
                          "## 6. Attributes along a line", "## Summary"]  # fmt: skip
    assert "6. **Attributes along a line**" in _source("ed50d3ee")
    ids = [c.get("id") for c in cells]
    assert ids.index("clipcell") < ids.index("perspmd") < ids.index("persp") < ids.index("db845d96")
    assert "Attributes along the line differ too" not in _source("2fbdab6a")
    assert "as if the parallelogram was decomposed into two triangles" in _flat("perspmd")
    assert not re.search(r"\(§6\)", _source("2fbdab6a"))


def test_gl_clipping_quotation_names_its_source():
    """The sentence quoted from GL's Primitive Clipping was added by
    ARB_pipeline_statistics_query (its "Modify Section 13.5, Primitive Clipping", written
    against GL 4.4; core in GL 4.6): checked against the extension's text in OpenGL-Registry."""
    text = _flat("clipmd")
    assert "since ARB_pipeline_statistics_query added a paragraph to *Primitive Clipping*" in text
    assert '"pass incoming primitives unchanged … as long as the results of rendering' in text
    assert "ARB_pipeline_statistics_query (written against GL 4.4, core in GL 4.6)" in _flat(
        "sources"
    )
