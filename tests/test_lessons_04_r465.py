"""Lesson 04, review r465: each test fails on the lesson before the fix.

S1: the floor heatmap's blue ring (its largest pixel) was in no key and no text; the text
under it now names it, and it lies on the diagonal. S2: the summary's typed 0.333 (the largest
|t - q| for r = 4) was checked by no test; it is now tied to section 1's closed form and print.
"""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from notebook_runs import lesson  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "04_perspective_correct_interpolation.ipynb"


def _cells() -> dict:
    return {c["id"]: "".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]}


def test_04_r465_s2_summary_peak_is_section_1s_closed_form():
    cells = _cells()
    # section 1's segment, as the check cell sets it up, and what that cell prints
    assert "x0, z0, x1, z1 = -1.0, 1.0, 2.0, 4.0" in cells["c03"]
    r = 4.0 / 1.0
    peak = (np.sqrt(r) - 1) ** 2 / (r - 1)
    assert "(np.sqrt(r) - 1) ** 2 / (r - 1):.3f" in cells["c03"]
    summary = " ".join(cells["c20"].split())
    assert f"{peak:.3f} for $r = {r:g}$, section 1)" in summary


def test_04_r465_s1_floor_ring_named_and_on_the_diagonal():
    text = " ".join(_cells()["floor_md"].split())
    assert "the blue ring marks the largest pixel, on it" in text
    ns = lesson("04_perspective_correct_interpolation")
    row, col = np.unravel_index(np.nanargmax(ns.texels), ns.texels.shape)
    (x0, y0), (x1, y1) = ns.diagonal
    centre = np.array([col + 0.5, row + 0.5])
    # distance of the ringed pixel's centre from the diagonal's line, in pixels
    d = abs((x1 - x0) * (y0 - centre[1]) - (x0 - centre[0]) * (y1 - y0)) / np.hypot(
        x1 - x0, y1 - y0
    )
    assert d < 1.5
