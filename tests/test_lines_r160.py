"""Review r160 of lesson 12a (lines): the tie rule named after the rule that decided it.

12a-1: on a horizontal line along a row boundary the DiamondExplorer and the trace's captions
said "GL's perturbation … decided it" while lighting the upper row, and the lesson's own tie
table says GL lights the lower one. The −(ε, ε²) here is applied with y down, as Vulkan's
Bresenham rule applies it; GL applies it with y up. The captions now name the y-down rule and
say where GL decides otherwise; these tests hold the page, the trace and GL's mirrored rule
to one another.
"""

from __future__ import annotations

import numpy as np
from explorables_node import call_js

import teachraster as tr
from teachraster.core.line_rules import gl_decides_otherwise

LINES = ("raster_rules", "explore_lines")
FLAT = ((0.3, 1.0), (8.3, 1.0))  # the reviewer's drag: horizontal, on the row boundary y = 1
SLOPED = ((0.5, 0.5), (8.5, 4.5))  # the lesson's tie line: GL and the y-down rule agree


def _gl(a, b, width, height):
    # GL's rule: the same −(ε, ε²) applied in GL's window (y up), y_GL = height − y, mirrored back
    mirrored = tr.rasterize_line((a[0], height - a[1]), (b[0], height - b[1]), width, height)
    return mirrored.coverage[::-1]


def test_gl_decides_otherwise_exactly_on_horizontal_lines_on_a_row_boundary():
    """The predicate the captions use is GL's mirrored rule: where it is False, GL lights
    the same pixels; where it is True and the line lights anything, GL lights others."""
    rng = np.random.default_rng(160)
    width, height = 12, 10
    ends = list(rng.integers(0, 24, (600, 2, 2)) / 2.0) + list(rng.integers(0, 48, (300, 2, 2)) / 4)
    for y in range(height + 1):  # horizontals on every row boundary, and one off it
        ends += [np.array([[0.5, y], [9.25, y]]), np.array([[0.5, y + 0.25], [9.25, y + 0.25]])]
    told = 0
    for a, b in ends:
        ours = tr.rasterize_line(a, b, width, height).coverage
        differ = bool((ours != _gl(a, b, width, height)).any())
        if gl_decides_otherwise(a, b):
            told += 1
            assert differ or not ours.any(), (a.tolist(), b.tolist())
        else:
            assert not differ, (a.tolist(), b.tolist())
    assert told >= 11


def test_trace_caption_names_the_y_down_rule_and_gl_lighting_the_row_below():
    (a, b), (w, h) = FLAT, (10, 6)
    line = tr.rasterize_line(a, b, w, h, trace=True)
    caption = line.trace.caption(3)  # column 1
    assert "pixel (row 0, col 1)" in caption and "Vulkan's Bresenham rule" in caption
    assert (
        "with y down" in caption and "GL moves them with y up and lights the pixel below" in caption
    )
    assert "GL's perturbation" not in caption
    # the caption's claim: the row below is GL's, in every column the line lights
    rows_ours = sorted(set(np.argwhere(line.coverage)[:, 0].tolist()))
    rows_gl = sorted(set(np.argwhere(_gl(a, b, w, h))[:, 0].tolist()))
    assert rows_ours == [0] and rows_gl == [1]
    sloped = tr.rasterize_line(*SLOPED, 10, 6, trace=True).trace.caption(3)
    assert "GL, moving them with y up, decides it the same way" in sloped


def test_explorer_caption_agrees_with_the_trace_and_the_tie_table():
    """The page's step captions say what the trace says, on the row-boundary line and on the
    sloped one; the pixel the page lights is the tie table's teachraster (y-down) row, and
    the pixel below it is the table's GL row (cell "tiestable": upper row and lower row)."""
    walks = call_js(LINES, [("diamondSteps", [list(FLAT[0]), list(FLAT[1]), 10, 6]),
                            ("diamondSteps", [list(SLOPED[0]), list(SLOPED[1]), 10, 6])])  # fmt: skip
    flat_caps = call_js(
        LINES, [("stepCaption", [walks[0], k]) for k in range(len(walks[0]["steps"]))]
    )
    told = call_js(LINES, [("glDecidesOtherwise", [walks[0]]), ("glDecidesOtherwise", [walks[1]])])
    assert told == [gl_decides_otherwise(*FLAT), gl_decides_otherwise(*SLOPED)] == [True, False]
    gl = _gl(*FLAT, 10, 6)
    for k, step in enumerate(walks[0]["steps"]):
        lit = [c for c in step["cands"] if c["state"] == 1]
        if not lit:
            continue
        (c,) = lit
        assert c["tie"] and c["row"] == 0  # the upper row, a tie
        assert gl[c["row"] + 1, c["col"]] and not gl[c["row"], c["col"]]  # GL: the pixel below
        assert (
            "Vulkan's Bresenham rule" in flat_caps[k] and "lights the pixel below" in flat_caps[k]
        )
        assert "GL's perturbation" not in flat_caps[k]
    sloped_caps = call_js(LINES, [("stepCaption", [walks[1], 1])])
    assert "decides it the same way" in sloped_caps[0]


# -- the lesson's own numbers (the executed notebook) -----------------------------------------
import json  # noqa: E402
from pathlib import Path  # noqa: E402

import pytest  # noqa: E402
from notebook_runs import lesson  # noqa: E402

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "12a_lines.ipynb"


def _source(cell_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return "".join(next(c for c in cells if c.get("id") == cell_id)["source"])


@pytest.fixture(scope="module")
def ns():
    return lesson("12a_lines")


@pytest.mark.notebook
def test_tie_table_and_explorer_agree_on_the_row_boundary_line(ns):
    """The cell's horizontal line, (0.3, 1) -> (8.3, 1): the table says GL lower row, Vulkan,
    Direct3D and teachraster upper; the explorer's page lights the upper row and its caption
    says GL lights the pixel below."""
    ours, gl, d3d = ns.tie_rows["horizontal on y = 1"]
    assert (ours, gl, d3d, ns.vk_rows["horizontal on y = 1"]) == ([0], [1], [0], [0])
    a, b, _ = ns.tie_lines["horizontal on y = 1"]
    assert (a, b) == FLAT
    row = next(r for r in _source("tiestable").splitlines() if r.startswith("| horizontal"))
    # GL, Vulkan, Direct3D, llvmpipe (measured: r345 M1), teachraster
    assert [c.strip() for c in row.split("|")[2:-1]] == ["lower row", "upper row", "upper row",
                                                          "lower row", "upper row"]  # fmt: skip
    walk = call_js(LINES, [("diamondSteps", [list(a), list(b), 10, 6])])[0]
    caption = call_js(LINES, [("stepCaption", [walk, 1])])[0]  # column 1, the table's column
    lit = [c for c in walk["steps"][1]["cands"] if c["state"] == 1]
    assert [(c["row"], c["col"]) for c in lit] == [(ours[0], 1)] and gl[0] == ours[0] + 1
    assert (
        "(row 0, col 1)" in caption
        and "GL moves them with y up and lights the pixel below" in caption
    )


@pytest.mark.notebook
def test_vulkan_and_bresenham_quotes_and_section_numbers():
    """Vulkan's perturbation sentence and framebuffer origin quoted (Vulkan-Docs
    chapters/primsrast.adoc); GL 4.6 §14.5.1's "reduces to Bresenham's algorithm" quoted beside
    the printed difference; §14.5.2.1's heading text quoted as it stands in the core PDF of
    May 5, 2022 (checked with the PDF's text: "This subsection is only defined in the
    compatibility profile.")."""
    table = " ".join(_source("tiestable").split())
    assert "Obtain the perturbed endpoints $p_a'$ given by $(x_a, y_a) - (\\varepsilon," in table
    assert '"a fragment is located by its upper left corner"' in table
    quote = " ".join(_source("bresquote").split())
    assert "reduces to Bresenham's algorithm with one modification" in quote and "D = 0" in quote
    # review r186 12a-9: the PDF's layout is a source note, folded at the end, not in the table
    assert "May 5, 2022" not in _source("widetbl")
    wide = " ".join(_source("sources").split())
    assert '"This subsection is only defined in the compatibility profile"' in wide


@pytest.mark.notebook
def test_clipping_and_joins_numbers(ns):
    """Review r160 12a-3, 12a-5: the clipping paragraph's computed example and the joins
    figure's counts, as the cells print them."""
    assert ns.clipped_lines == ns.n_clip == 400 and max(ns.end_moves) <= 1 / 512
    assert (ns.lines_changed, ns.pixels_changed) == (4, 8)
    text = " ".join(_source("clipmd").split())
    assert "1/512 px" in text and "64 × 32" in text and "§13.7" in text
    assert int((ns.seg1 & ns.seg2).sum()) == 3 and int(ns.bevel.sum()) == 2
    assert int(ns.miter.sum()) == 4 and not (ns.bevel & ~ns.miter).any() and int(ns.caps.sum()) > 0
