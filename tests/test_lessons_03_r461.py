"""Lesson 03, review r461: each test fails on the lesson before the fix.

S1: the contour label 0.8 of section 1's λ1 map sat in the narrow corner at v1 (its line runs
2.1 px inside the triangle) and touched the edge v3v1; the 0.8 line is now unlabelled, and the
text says so. S2: the text above the 3-D view said the perspective-correct f (blue) and the
affine plane (orange) coincide at the start, where the view draws one sheet, in blue only.
S3: "each term is off by up to half of it" (float64's gap near 10^13) is no bound: the products
inside a term round too, and at the table's 10^4 and 10^5 px offsets a term of D is off by
more than half its gap.
"""

from __future__ import annotations

import json
import re
from fractions import Fraction
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
NAME = "03_barycentric_and_plane_equations"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _sources() -> list[str]:
    return ["".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]]


def _flat(text: str) -> str:
    """The words of a cell, its Python string pieces joined."""
    return " ".join(re.sub(r'"\s*f?r?"', "", text).split())


def test_s1_the_label_in_the_narrow_corner_is_left_off():
    cell = next(t for t in _sources() if "lam1_art = plot_barycentric(" in t)
    assert "contour_levels = [0.2, 0.4, 0.6, 0.8]" in cell  # four lines drawn
    assert "labelled = contour_levels[:-1]" in cell and "levels=labelled" in cell
    assert "levels=contour_levels, fmt=" not in cell
    text = _flat(
        next(t for t in _sources() if t.startswith("q_weights.hold()") and "contours_md" in t)
    )
    assert "the last unlabelled in the narrow corner at $\\mathbf{v}_1$" in text
    # why: the λ1 = 0.8 line runs (1 - 0.8) |v2 - v3| inside the triangle, 2.1 px
    xy = np.array([[2.0, 1.0], [13.0, 5.0], [5.0, 12.0]])
    assert round(0.2 * float(np.hypot(*(xy[1] - xy[2]))), 1) == 2.1


def test_s2_one_sheet_at_the_start():
    text = " ".join(next(t for t in _sources() if t.startswith("The same in 3-D")).split())
    assert "(blue) and the affine plane (orange) are one and the same plane" not in text
    assert "one and the same plane, the plane of sections 2 and 3, drawn once, in blue" in text
    assert "The affine plane (orange) comes apart from it once $w_3$ moves" in text


def test_s3_a_term_of_d_is_not_bounded_by_its_last_rounding():
    cells = _sources()
    setup = next(t for t in cells if t.startswith("local = np.array("))
    assert "local = np.array([[0.5, 0.5], [13.25, 3.5], [4.75, 11.5]])" in setup
    assert "fvals = np.array([0.1, 7.3, -2.9])" in setup
    assert "offsets = [0, 100, 1_000, 10_000, 100_000, 1_000_000]" in setup
    local = np.array([[0.5, 0.5], [13.25, 3.5], [4.75, 11.5]])
    fvals = np.array([0.1, 7.3, -2.9])
    worst = 0.0
    for off in (10_000, 100_000):
        (x1, y1), (x2, y2), (x3, y3) = local + off
        f1, f2, f3 = fvals
        got = [x1 * (y2 * f3 - y3 * f2), x2 * (y3 * f1 - y1 * f3), x3 * (y1 * f2 - y2 * f1)]
        q = [Fraction(v) for v in (x1, y1, x2, y2, x3, y3, f1, f2, f3)]
        exact = [
            q[0] * (q[3] * q[8] - q[5] * q[7]),
            q[2] * (q[5] * q[6] - q[1] * q[8]),
            q[4] * (q[1] * q[7] - q[3] * q[6]),
        ]
        for g, e in zip(got, exact):
            worst = max(worst, abs(float(Fraction(g) - e)) / (np.spacing(abs(g)) / 2))
    assert worst > 2  # more than half a gap: the old bound was wrong
    held = _flat(next(t for t in cells if t.startswith("q_far.hold()") and "Markdown(" in t))
    assert "so each term is off by up to half of it" not in held
    assert "Rounding each term to float64 costs up to half of it" in held
    assert "the products inside a term add roundings of their own" in held
