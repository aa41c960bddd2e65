"""Slips in the helper ``edge_function`` that ``covers`` calls, and a side test of one edge only,
as images the ``covers`` and ``fill`` checks can name (r420 H1, H5).

Each is the exercise's own algorithm (orient by E(v1, v2, v3), zero area covers nothing, every
edge's side test with the top-left rule on E == 0) run with the wrong edge function, or with
one edge's test alone: an unsigned E (``abs``) covers every centre off the edges' lines; E with
p measured from b in x and from a in y shifts each sloped edge's line. The words point to the
helper's own check, which names the slip with numbers (issue 30: "never misdiagnose").
"""

from __future__ import annotations

import numpy as np

from .cases import CoverageCase


def _signed(a, b, p):
    return (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - a[0])


def _mixed(a, b, p):
    return (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - b[0])


def _per_length(a, b, p):
    """E / |b − a|: a signed distance, NaN (0/0) on a zero-length edge (r428 H5)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return _signed(a, b, p) / np.hypot(*(np.asarray(b) - np.asarray(a)))


#: The wrong edge functions, by kind: (a, b, points (..., 2)) -> E.
EDGE_FUNCTIONS = {
    "unsigned edge function": lambda a, b, p: np.abs(_signed(a, b, p)),
    "edge function from two anchors": _mixed,
    "NaN on a zero-length edge": _per_length,
}

HELPER_CHECK = 'show(ex.check("edge_function", edge_function)) names it with numbers'
WORDS = {
    "unsigned edge function": "your edge function returns |E| (abs): it is never negative, so "
    "every centre passes every edge's side test, inside the triangle or not, and only the "
    "centres on an edge's line that the tie test refuses are left out. E must keep its sign, "
    f"which tells the side of a→b that p lies on: {HELPER_CHECK}",
    "edge function from two anchors": "your edge function measures p from b in x "
    "(p[0] − b[0]) but from a in y (p[1] − a[1]): that adds (b.x − a.x)·(b.y − a.y) to E and "
    "moves each sloped edge's line. Take both differences from the same vertex: "
    f"{HELPER_CHECK}",
    "NaN on a zero-length edge": "your edge function gives NaN on a zero-length edge (0/0: a "
    "division by the edge's length?): NaN fails every comparison, so neither the zero-area "
    "test nor a side test refuses it, and a triangle collapsed to a point (or to a segment) "
    "covers pixels around it. Keep E undivided, (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − "
    f"a.x): {HELPER_CHECK}",
    "one edge only": "you test one edge only (v1→v2, after orienting): a centre is covered "
    "only when it is inside all three edges, so test each of v1→v2, v2→v3 and v3→v1 and "
    "return True only after all three pass",
}


def _top_left(a, b) -> bool:
    return bool(b[1] < a[1] or (b[1] == a[1] and b[0] > a[0]))


def image(case: CoverageCase, xy, kind: str) -> np.ndarray:
    """(h, w): the exercise's algorithm on triangle ``xy`` with slip ``kind`` (a key of
    :data:`EDGE_FUNCTIONS`, or "one edge only")."""
    w, h = case.size
    rows, cols = np.indices((h, w))
    points = np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], axis=-1)
    ef = EDGE_FUNCTIONS.get(kind, _signed)
    v = [np.asarray(q, dtype=float) for q in xy]
    area = float(ef(v[0], v[1], v[2][None])[0])
    if area < 0:
        v = [v[0], v[2], v[1]]
    one = kind == "one edge only"  # the reviewer's one-edge covers tests no area either
    inside = np.full((h, w), bool(area != 0) or one)
    for k in range(1 if one else 3):
        a, b = v[k], v[(k + 1) % 3]
        e = ef(a, b, points)
        # refused where E < 0, or E == 0 off a top or left edge: NaN passes both (r428 H5)
        inside &= ~((e < 0) | ((e == 0) & (not _top_left(a, b))))
    return inside


def images(case: CoverageCase, kind: str) -> np.ndarray:
    """(n, h, w): :func:`image` of every triangle of the case."""
    return np.array([image(case, xy, kind) for xy in case.triangles])


#: r438 H1: the third barycentric taken as the remainder (Scratchapixel's w = 1 − u − v).
REMAINDER = (
    "your third barycentric is the remainder 1 − λ1 − λ2: in floating point that is not "
    "exactly its own edge's E / E(v1, v2, v3), so on that edge it comes out a rounding error "
    "(±1e-16) instead of 0, and the tie rule never sees the edge: its centres go by the "
    "rounding. Compute each λ from its own edge function (λ3 = E(v1, v2, p) / E(v1, v2, v3)), "
    "or test the edge functions' signs before dividing"
)


def remainder_image(case: CoverageCase, xy, k: int) -> np.ndarray:
    """(h, w): the exercise's algorithm with barycentrics E / E(v1, v2, v3) of the oriented
    triangle, the one of edge ``k`` (v1→v2, v2→v3, v3→v1 for k = 0, 1, 2) taken as 1 − the
    other two; the tie rule on λ == 0."""
    w, h = case.size
    rows, cols = np.indices((h, w))
    points = np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], axis=-1)
    v = [np.asarray(q, dtype=float) for q in xy]
    area = float(_signed(v[0], v[1], v[2][None])[0])
    if area == 0:
        return np.zeros((h, w), dtype=bool)
    if area < 0:
        v, area = [v[0], v[2], v[1]], -area
    edges = [(v[i], v[(i + 1) % 3]) for i in range(3)]
    lam = [_signed(a, b, points) / area for a, b in edges]
    lam[k] = 1 - lam[(k + 1) % 3] - lam[(k + 2) % 3]
    inside = np.ones((h, w), dtype=bool)
    for (a, b), q in zip(edges, lam):
        inside &= ~((q < 0) | ((q == 0) & (not _top_left(a, b))))
    return inside
