"""Lesson 03, review r380: each test fails on the lesson before the fix.

FIG1: the standards table was 1214 px wide in a 932-px cell at 1366 px (JupyterLab, file
browser open): two tables now, the standards and the two implementations, with the long names
in notes (measured 2026-12-07 with Chromium and JupyterLab at 1366 × 900: both 907 px in the
932-px cell). S1: the view's bar (0.191, over the whole triangle) and the printed largest rise
at the pixel centres (0.166) are both printed and told apart. S2: q_sheet's figure draws the
covered centres filled. S3: section 4's cancellation chain told once, section 2's "same
rounding in each range" once. S4: no aside on a variant no student proposed.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from notebook_runs import executed, lesson, streams

ROOT = Path(__file__).resolve().parent.parent
NAME = "03_barycentric_and_plane_equations"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _cells() -> dict:
    return {c["id"]: "".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]}


def _flat(text: str) -> str:
    """The words of a cell, its Python string pieces joined."""
    return " ".join(re.sub(r'"\s*f?r?"', "", text).split())


def test_fig1_the_rules_fit_a_laptop_column():
    table = _cells()["c03-rules-table"]
    heads = [line for line in table.splitlines() if line.startswith("| rule |")]
    assert len(heads) == 2 and all(line.count(" | ") <= 3 for line in heads)
    rows = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    spans = [span for line in rows for span in re.findall(r"`([^`]+)`", line)]
    # what made the table 1214 px wide: a 46-character name in the llvmpipe column
    assert max(map(len, spans)) <= len('interpolation="perspective"')
    assert "test_attributes_follow_the_unsnapped_vertices" not in " ".join(rows)
    assert "`test_attributes_follow_the_unsnapped_vertices`" in table  # in its note
    assert "`VK_EXT_sample_locations`" in table and "`SUBPIXEL_BITS`" in table


@pytest.mark.notebook
def test_s1_the_bar_and_the_centres_measured_apart():
    import teachraster as tr

    ns = lesson(NAME)
    assert round(float(np.nanmax(ns.sheet_gap)), 3) == 0.166
    assert round(float(ns.whole_gap.max()), 3) == 0.191 > round(float(np.nanmax(ns.sheet_gap)), 3)
    assert round(float(-ns.whole_gap.min()), 3) == 0.143
    assert np.allclose(ns.whole_at, [7.1667, 10.1042], atol=1e-4)  # the view's (7.17, 10.1)
    # the view's own search (explore_attributes.js, largestGap) finds the same point
    from explorables_node import call_js

    parts = ("raster_rules", "view3d", "explore_attributes")
    (js,) = call_js(parts, [("largestGap", [ns.xy.tolist(), [1.0, 1.0, ns.w_far], ns.f.tolist()])])
    assert js["gap"] == pytest.approx(ns.whole_gap.max(), abs=1e-12)
    assert np.allclose(js["p"], ns.whole_at, atol=1e-12)
    assert np.allclose(tr.perspective_weights(ns.lam_grid, [1.0, 1.0, 8.0]).sum(axis=1), 1.0)
    printed = streams(executed(NAME).notebook())
    assert "over the whole triangle (the view's bar): largest rise 0.191 at (7.17, 10.10)" in (
        printed
    )
    assert "largest rise 0.166, deepest sink 0.117" in printed
    held = _flat(_cells()["c18c-surfaces-held"])
    assert "larger of the two gaps" not in held
    assert "It reads {whole_gap.max():.3f}, not the {np.nanmax(sheet_gap):.3f}" in held
    assert "measured over different points" in held


def test_s2_the_question_draws_which_centres_are_covered():
    ask = _cells()["q-sheet"]
    assert "centres=False" in ask
    assert "plot_pixel_centres(ax, W, H, sheet_covered)" in ask
    assert "Only covered centres (filled " in ask


def test_s3_each_explanation_told_once():
    cells = _cells()
    far = _flat(cells["recentre_predict"].split("explain=")[1])
    for chain in ("cancel to D", "half float64's gap", "far_D_error", "far_A_error"):
        assert chain not in far, chain
    assert "the text under the figure follows the digits" in far
    assert "catastrophic" in cells["recentre_held"]  # the one telling
    drift = _flat(cells["drift_md"])
    assert "float32's step is the same for every value" not in drift
    assert "the same amount, in the same direction" not in drift
    assert "give about a fifth of it back" in drift  # what only the printout shows stays
    assert "float32's step is fixed" in _flat(cells["f9acb59d"])  # the explanation keeps it


def test_s4_no_aside_on_a_variant_nobody_proposed():
    md = " ".join(_cells()["ff0e2ce7"].split())
    assert "third column" not in md and "$w_k (x_k, y_k, 1)$" in md
