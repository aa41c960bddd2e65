"""Review r262 (lesson 12a, round 29): the line player draws the diamonds the explorer draws
(FIG1), llvmpipe's aliased width range, the multisampled-line table (M1), GL's width rounding
(M2) and CONVENTIONS saying what the tie table computes (C1)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from explorables_node import NODE, call_js

import teachraster as tr
from teachraster.plotting.lines import LineView

ROOT = Path(__file__).resolve().parents[1]
LINES = ("raster_rules", "explore_lines")
NB = ROOT / "notebooks" / "12a_lines.ipynb"

#: the lesson's lines (§1, §2's Bresenham line, a y-major one, a horizontal one on a row
#: boundary, one running up) and two off the grid
ENDS = [((0.5, 0.5), (8.5, 4.5), 10, 6), ((0.5, 0.5), (12.5, 5.5), 14, 7),
        ((0.5, 0.5), (4.5, 8.5), 6, 10), ((0.3, 1.0), (8.3, 1.0), 10, 6),
        ((0.5, 4.5), (8.5, 0.5), 10, 6), ((1.9, 1.05), (8.6, 4.4), 10, 6),
        ((7.3, 0.2), (1.1, 5.7), 10, 6)]  # fmt: skip


def _source(cid: str) -> str:
    cells = json.loads(NB.read_text())["cells"]
    return " ".join("".join(next(c for c in cells if c.get("id") == cid)["source"]).split())


@pytest.mark.skipif(NODE is None, reason="needs node")
def test_player_and_explorer_draw_the_same_diamonds():
    """FIG1: LineTrace.near keeps, step by step, the candidates the explorer's nearCandidates
    keeps (same pixels), so the player no longer outlines rows away from the line."""
    walks = call_js(LINES, [("diamondSteps", [list(a), list(b), w, h]) for a, b, w, h in ENDS])
    for (a, b, w, h), walk in zip(ENDS, walks, strict=True):
        kept = call_js(LINES, [("nearCandidates", [walk, s]) for s in walk["steps"]])
        js = {(int(c["row"]), int(c["col"])) for near in kept for c in near}
        trace = tr.rasterize_line(a, b, w, h, trace=True).trace
        s, near = trace.steps, trace.near()
        py = {(int(r), int(c)) for r, c in zip(s.rows[near], s.cols[near])}
        assert py == js, (a, b)


def test_player_at_step_6_outlines_no_diamond_rows_away():
    """FIG1: §2's line at step 6 (column 4, the line at y = 2.17 there) outlined rows 0-4 of
    column 4 thick, and dotted rows 2-3 of columns 0-3 where the line is at y 0.5-1.75."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    line = tr.rasterize_line((0.5, 0.5), (12.5, 5.5), 14, 7, trace=True)
    view = LineView.create(ax, line, 6)
    now = [p.vertices[:4].mean(axis=0) for p in view.diamonds["now"].get_paths()]
    rows_now = sorted(int(y) for _, y in now)
    assert rows_now and all(abs(r + 0.5 - 2.17) < 1.5 for r in rows_now) and len(rows_now) <= 2
    tested = [p.vertices[:4].mean(axis=0) for p in view.diamonds["tested"].get_paths()]
    for x, y in tested:  # a dotted diamond's pixel is crossed by the line in its column
        j = int(x)
        y_lo, y_hi = sorted(0.5 + (np.array([max(j, 0.5), j + 1]) - 0.5) * 5 / 12)
        assert int(y) < y_hi and y_lo < int(y) + 1
    plt.close(fig)


def test_multisampled_lines_and_width_rounding_stated():
    """M1: a table for lines on a multisampled framebuffer (GL §14.5.4, Vulkan, Direct3D,
    teachraster); M2: GL's aliased width rounded, clamped to ALIASED_LINE_WIDTH_RANGE."""
    msaa = _source("msaalines")
    for api in ("| GL |", "| Vulkan |", "| Direct3D 10/11/12 |", "| teachraster |"):
        assert api in msaa, api
    assert "§14.5.4 *Line Multisample Rasterization*" in msaa
    assert "glDisable(GL_MULTISAMPLE)" in msaa and "1.4 px" in msaa
    assert "(08_antialiasing.ipynb)" in msaa
    wide = _source("widetbl")
    assert "rounded to the nearest integer" in wide and "ALIASED_LINE_WIDTH_RANGE" in wide
    assert "§5's cell prints llvmpipe's range" in wide
    sources = _source("sources")
    assert "may be clipped" in sources and "decomposed into two triangles" in sources


def test_conventions_say_lines_are_vulkans_rule_not_direct3ds():
    """C1: CONVENTIONS (header and Lines) agreed with Direct3D where the tie table (cell 14)
    prints 'teachraster 1, Vulkan 1, GL 1, Direct3D 0'."""
    text = " ".join((ROOT / "CONVENTIONS.md").read_text().split())
    assert "(GL spec, Direct3D)" not in text
    assert "one-pixel lines follow Vulkan's Bresenham rule, not Direct3D's" in text
    assert "teachraster's lines are Vulkan's without a flip" in text
    assert "at an x-major tie with dy/dx > 0" in text
    # (a check of the team's shared copy outside the repository was here: a test reads only the
    # repository, since a read-only outside copy may lag behind it, as it did on 2026-12-06)
