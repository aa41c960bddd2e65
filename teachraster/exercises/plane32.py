"""E computed in float32 as the plane A·x + B·y + C, for the ``covers`` and ``fill`` checks to
name (r438 H6; exercise 06 names the same form, r432 MN1).

Near the origin, E in float32 from differences, (b − a)·(p − a), is exact for small triangles:
the differences and their products fit 24 bits. In the plane form the terms A·x and
C = a.x·b.y − a.y·b.x are products of whole coordinates (24 bits and more already at 30 px on
the 1/256 grid), far larger than E, and E is what is left when they cancel: a centre on an edge
comes out a rounding error off it, and the tie rule never sees it. Two ways of writing C are
tried; the winding is decided as the student's helper decides it, from differences in float32.
"""

from __future__ import annotations

import numpy as np

from .cases import CoverageCase


def _difference32(a, b, p):
    return (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - a[0])


def _plane32(a, b, p, form: str):
    big_a, big_b = a[1] - b[1], b[0] - a[0]
    if form == "cross":
        c = a[0] * b[1] - a[1] * b[0]
    else:  # expanded: (b.y − a.y)·a.x − (b.x − a.x)·a.y
        c = (b[1] - a[1]) * a[0] - (b[0] - a[0]) * a[1]
    return big_a * p[..., 0] + big_b * p[..., 1] + c


FORMS = ("cross", "expanded")


def image(case: CoverageCase, xy, form: str) -> np.ndarray:
    """(h, w): the rule with E = A·x + B·y + C in float32 (C written as ``form``)."""
    w, h = case.size
    f = np.float32
    rows, cols = np.indices((h, w))
    points = np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], -1).astype(f)
    v = [np.asarray(q, dtype=float).astype(f) for q in xy]
    with np.errstate(over="ignore", invalid="ignore"):
        area = _difference32(v[0], v[1], v[2][None])[0]
        if area == 0:
            return np.zeros((h, w), dtype=bool)
        if area < 0:
            v = [v[0], v[2], v[1]]
        inside = np.ones((h, w), dtype=bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = _plane32(a, b, points, form)
            owns = bool(b[1] < a[1] or (b[1] == a[1] and b[0] > a[0]))
            inside &= (e >= 0) if owns else (e > 0)
    return inside


def fits(case: CoverageCase, expected, got, masks) -> bool | None:
    """Does one form of C give the student's every image of this case (and change it)?"""
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return None
    for form in FORMS:
        images = np.array([image(case, xy, form) for xy in case.triangles]) & masks
        if not np.array_equal(images, expected) and np.array_equal(images, got):
            return True
    return False


WORDS = (
    "you computed E in float32 as the plane A·x + B·y + C: A·x and C (a.x·b.y − a.y·b.x) are "
    "products of whole coordinates on the 1/256-px grid, which need more than float32's 24 "
    "bits already a few dozen px from the origin, and E is what is left when they cancel: a "
    "centre on an edge comes out a rounding error off it, so the tie rule never sees it (and "
    "one near an edge may land on the wrong side). Compute E in float64 (plain Python floats or "
    "np.float64), or from the differences (b − a)·(p − a)"
)
