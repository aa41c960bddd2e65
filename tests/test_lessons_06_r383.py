"""Lesson 06, review r383: each test fails on the lesson before the fix.

FIG1: the standards table was 1063 px wide in a 932-px cell at 1366 px (JupyterLab, file
browser open), its "where" column cut: two tables now, the standards and the two
implementations, the sections in notes under each (measured 2026-12-07 with Chromium and
JupyterLab at 1366 × 900: 907 and 710 px in the 932-px cell; tested in test_lessons_b's
test_06_review_r276_precision_table). S1: no code cell's first line, which JupyterLab shows of
a folded cell, names a ``q_…`` question; the two widget cells are folded too. S3: the quotation
on stepping is said to be about colour. S4: OpenGL's 4-bit minimum named beside Vulkan's. S5:
the low-r cut is the printed one (r = 2), not "about 4" under a printed 3.08.
"""

from __future__ import annotations

import json
from pathlib import Path

from notebook_runs import lesson

ROOT = Path(__file__).resolve().parent.parent
NAME = "06_what_accuracy_costs"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _cells() -> list[dict]:
    return json.loads(NOTEBOOK.read_text())["cells"]


def test_s1_no_first_line_names_a_question():
    cells = _cells()
    for i, cell in enumerate(cells):
        if cell["cell_type"] != "code":
            continue
        first = "".join(cell["source"]).split("\n", 1)[0]
        assert "q_" not in first, (i, first)
    for cid in ("spanexplorer", "e9f2ae5f"):  # the span explorer, the divide-cost explorer
        (cell,) = [c for c in cells if c["id"] == cid]
        assert cell["metadata"]["jupyter"]["source_hidden"], cid
        assert "hide-input" in cell["metadata"]["tags"], cid
    held = [c for c in cells if "".join(c["source"]).split("\n", 1)[-1].startswith("q_")]
    assert len(held) >= 17


def test_s3_s4_s5_wording():
    ns = lesson(NAME)
    edge = " ".join(ns.EDGE_TEXT.split())
    # r500 S2: the seed is named for the fact (E stepped like any affine function); the
    # grids' sources stand once, in §6's standards table
    assert "*Triangle Rasterisation II - Interpolation*" in edge
    assert "like any affine function" in edge and "(Vulkan)" not in edge
    why = " ".join(ns.SPAN_WHY.split())
    assert "about 4" not in why
    assert f"cuts it nearly 4 times ({ns.cut_low:.2f} at $r = 2$" in why
    assert f"{ns.span_cut[10.0]:.2f} already at $r = 10$" in why
    assert 3.7 < ns.cut_low < 3.9 and 3.0 < ns.span_cut[10.0] < 3.2
