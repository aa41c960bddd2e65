"""Exercise 1's slips in the point ``covers`` tests and in its three edge tests (r453).

- A point off the pixel centres (``coverage_checks.sample_point_case``, a case, built
  where the other cases are: the checker's reference functions live there): capstone 12's MSAA scene asks
  ``covers`` at each sample position, so a ``covers`` that tests the centre of p's pixel
  (``floor(p) + 0.5``, or lesson 02's ``biased_coverage`` wrapped at ``floor(p)``) must fail
  exercise 1 already, named (r453 WP1).
- p − (½, ½) tested instead of p (r453 H3), the mirror of ``PAST_P``.
- A tie test parenthesised as ``(e < 0 or e == 0) and not tl`` (a top or left edge then
  refuses nothing), and the third edge listed as v1→v3 (r453 H1, H2).
- The vertices held in float32 (``np.asarray(xy, np.float32)``), the edge functions then in
  float64 (r453 M2: told "the plane A·x + B·y + C").
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..core.edges import edge_function, top_left_edges
from . import coverage as cov
from .cases import CoverageCase

#: Direct3D's standard 4× pattern, sample 0: (−2/16, −6/16) from the centre, i.e.
#: (0.375, 0.125) from the pixel's corner, on the 1/16 grid (exact on the 1/256 one).
SAMPLE = (0.375, 0.125)
SAMPLE_LABEL = "points off the pixel centres"


def _centre_of_pixel(case: CoverageCase) -> CoverageCase:
    """The case asked at the centres of the pixels its points lie in (floor(p) + 0.5)."""
    return replace(case, origin=tuple(np.floor(np.add(case.origin, 0.5)).tolist()))


def pixel_centre_images(case: CoverageCase) -> np.ndarray:
    """(n, h, w): the rule at the centre of the pixel each asked point p lies in."""
    return cov.rule_images(_centre_of_pixel(case))


PIXEL_CENTRE = (
    "you tested the centre of p's pixel (floor(p) + 0.5), not p: covers is asked about the "
    "point p itself, and capstone 12's MSAA scene asks it at each sample position, off the "
    "centre (lesson 02's `biased_coverage`, which samples centres only, wrapped at floor(p) "
    "does this too). Test p as given"
)

BEFORE_P = (
    "you tested p − (0.5, 0.5), not p: p is already the point to test (a pixel's centre "
    "(j + 0.5, i + 0.5), or in the MSAA scene a sample's position), so taking half a pixel off "
    "moves it to the pixel's corner (j, i) (the centre turned back into a pixel's index?)"
)


def describe_pixel_centre(case, xy, e, g, i, j):
    """Pixel (i, j)'s point p and its pixel's centre: the two verdicts (None where the
    student's answer is not the centre's)."""
    p = np.array([case.origin[0] + j + 0.5, case.origin[1] + i + 0.5])
    c = np.floor(p) + 0.5
    if bool(cov.covered(xy, c)[0]) != g[i, j]:
        return None
    rule = "covers it" if e[i, j] else "leaves it uncovered"
    yours = "your function covered it" if g[i, j] else "your function left it uncovered"
    where = cov.where_point(xy, p), cov.where_point(xy, c)
    ties = cov.ties_of(*where)
    return (f"the point p = {cov.point(p)} lies {where[0]}, so the rule {rule}; its pixel's "
            f"centre {cov.point(c)} lies {where[1]}, and {yours}", ties)  # fmt: skip


# -- the three edge tests written with a slip --------------------------------------------------
PRECEDENCE = (
    "you never refuse a centre outside a top or left edge: the test reads like "
    "`(e < 0 or e == 0) and not top_left`, so on a top or left edge nothing is refused, not "
    "even E < 0. Refuse E < 0 on every edge, and E == 0 on the others: "
    "`e < 0 or (e == 0 and not top_left)`"
)
THIRD_EDGE = (
    "you test the edge v1→v3 instead of v3→v1 (the edge list `(v1, v2), (v2, v3), (v1, v3)`?): "
    "run the other way, its E has the other sign, so you keep what lies outside that edge and "
    "refuse its inside. The three edges go round the triangle: v1→v2, v2→v3, v3→v1"
)


def _points(case: CoverageCase) -> np.ndarray:
    w, h = case.size
    rows, cols = np.indices((h, w))
    return np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], axis=-1)


def slip_image(case: CoverageCase, xy, slip: str) -> np.ndarray:
    """(h, w): the coverage of the oriented triangle ``xy`` with ``slip``: "precedence" (a top
    or left edge refuses nothing), "third edge" (v1→v3 tested for v3→v1), or "float32
    vertices" (the vertices rounded to float32, the tests exact)."""
    v = np.asarray(xy, dtype=float)
    points = _points(case)
    if slip == "float32 vertices":  # the area of float32 vertices in float32, E in float64
        v = v.astype(np.float32)
        d1, d2 = v[1] - v[0], v[2] - v[0]
        area = float(d1[0] * d2[1] - d1[1] * d2[0])  # float32 products, as numpy computes them
        v = v.astype(float)
    else:
        area = float(edge_function(v[0], v[1], v[2]))
    if area == 0:
        return np.zeros(points.shape[:2], dtype=bool)
    if area < 0:
        v = v[[0, 2, 1]]
    edges = [(v[0], v[1]), (v[1], v[2]), (v[0], v[2]) if slip == "third edge" else (v[2], v[0])]
    inside = np.ones(points.shape[:2], dtype=bool)
    for a, b in edges:
        e = edge_function(a, b, points)
        owns = bool(top_left_edges(a, b))
        if slip == "precedence":
            inside &= owns | (e > 0)
        else:
            inside &= (e > 0) | ((e == 0) & owns)
    return inside


def slip_images(case: CoverageCase, slip: str) -> np.ndarray:
    """(n, h, w): :func:`slip_image` of every triangle of the case."""
    return np.array([slip_image(case, xy, slip) for xy in case.triangles])


def float32_vertex_words(args, expected, got) -> str:
    """r453 M2: the vertices in float32, with the spacing float32 has where they lie."""
    (case,) = args
    far = float(np.abs(case.triangles).max())
    step = float(np.spacing(np.float32(far)))
    return (f"your vertices are held in float32 (np.asarray(xy, np.float32)?): about {far:.6g} "
            f"px from the origin float32 numbers are {cov.fmt(step)} px apart, so vertices on "
            "the 1/256-px grid move before any test, and centres near an edge change side. "
            "Keep the vertices (and the edge functions) in float64: plain Python floats or "
            "np.float64")  # fmt: skip
