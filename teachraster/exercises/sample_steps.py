"""A point moved off the centre, or a relative tolerance on the edge function's two products:
found from the rule's images, for :mod:`.coverage_checks` to name (r428 WP1, WP2, M1).

- A step off the centre (``p[0] + 1e-7``): the rule run at every centre moved by δ along a
  direction (δ on a ladder 1e-9 … 1e-4 px). On a non-horizontal edge a step to the right
  decides an exact tie as the top-left rule does; only a centre *near* a long steep edge
  (|dy| · δ > |E| = 2^-16 px²) shows it (:func:`stepped`).
- A relative tolerance (``math.isclose(p1, p2)``, default ``rel_tol`` 1e-9): E taken as 0 where
  |E| ≤ r · max(|p1|, |p2|), p1 = (b.x − a.x)(p.y − a.y) and p2 = (b.y − a.y)(p.x − a.x) on the
  oriented edges; only a centre near an edge whose products are large (10^5 px²) shows it
  (:func:`relative_tolerance`).

The case :func:`.near_ties.long_near_tie_case` holds centres that tell these apart from each
other and from an absolute tolerance.
"""

from __future__ import annotations

import numpy as np

from . import coverage as cov
from .cases import CoverageCase

#: The steps tried, px, smallest first: the least that gives the image is quoted ("or more").
STEPS = (1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4)
#: Along an axis first, then diagonally.
DIRECTIONS = ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1))


def _points(case: CoverageCase) -> np.ndarray:
    w, h = case.size
    rows, cols = np.indices((h, w))
    return np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], axis=-1)


def _top_left(a, b) -> bool:
    return bool(b[1] < a[1] or (b[1] == a[1] and b[0] > a[0]))


def _oriented(xy) -> list[np.ndarray]:
    v = [np.asarray(q, dtype=float) for q in xy]
    return [v[0], v[2], v[1]] if cov.area2(np.asarray(xy, dtype=float)) < 0 else v


def _products(a, b, p):
    return (b[0] - a[0]) * (p[..., 1] - a[1]), (b[1] - a[1]) * (p[..., 0] - a[0])


def image(case: CoverageCase, xy, step=(0.0, 0.0), rel: float = 0.0, area: float = 0.0,
          length: bool = False):  # fmt: skip
    """(h, w) bool: the rule at each centre moved by ``step`` (px), with E taken as 0 where
    |E| ≤ ``rel`` · max(|p1|, |p2|) (anchored at each oriented edge's start), or where
    |E| ≤ ``rel`` · ``area`` if ``area`` is given, or |E| ≤ ``rel`` · |b − a| (a distance to
    the edge's line below ``rel`` px) if ``length``."""
    points = _points(case) + np.asarray(step, dtype=float)
    if cov.area2(np.asarray(xy, dtype=float)) == 0:
        return np.zeros(points.shape[:2], dtype=bool)
    v = _oriented(xy)
    inside = np.ones(points.shape[:2], dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        p1, p2 = _products(a, b, points)
        e = p1 - p2
        bound = rel * (area if area else float(np.hypot(*(b - a))) if length
                       else np.maximum(np.abs(p1), np.abs(p2)))  # fmt: skip
        tie = np.abs(e) <= bound if rel else e == 0
        inside &= np.where(tie, _top_left(a, b), e > 0)
    return inside


def _same(case, got, images, masks) -> bool:
    return all(np.array_equal(g, im & m) for g, im, m in zip(got, images, masks))


def _shaped(got, expected) -> bool:
    return isinstance(got, np.ndarray) and got.shape == expected.shape


def stepped(case: CoverageCase, expected, got, masks) -> tuple[float, int, int] | None:
    """(δ, sx, sy): the least step of :data:`STEPS` along a direction that gives the student's
    every image of this case (within ``masks``, the pixels asked about), or None."""
    if not _shaped(got, expected) or np.array_equal(got, expected):
        return None
    for delta in STEPS:
        for sx, sy in DIRECTIONS:
            images = [image(case, xy, (sx * delta, sy * delta)) for xy in case.triangles]
            if _same(case, got, images, masks):
                return delta, sx, sy
    return None


def _ratios(xy, points, length: bool = False) -> np.ndarray:
    """(3, ...): at each point, |E| / max(|p1|, |p2|) for each oriented edge (|E| / |b − a|
    if ``length``)."""
    v = _oriented(xy)
    out = []
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        p1, p2 = _products(a, b, points)
        big = np.full(p1.shape, np.hypot(*(b - a))) if length else np.maximum(abs(p1), abs(p2))
        with np.errstate(divide="ignore", invalid="ignore"):
            out.append(np.where(big > 0, np.abs(p1 - p2) / big, np.inf))
    return np.array(out)


def _ratio(xy, points, area: float = 0.0, length: bool = False) -> np.ndarray:
    """At each point, the least ratio of :func:`_ratios` (|E| / ``area`` where it is given)."""
    if area:
        return np.abs(np.array([p1 - p2 for p1, p2 in (_products(a, b, points) for a, b in
                                zip(_oriented(xy), np.roll(_oriented(xy), -1, axis=0)))])).min(
            axis=0) / area  # fmt: skip
    return _ratios(xy, points, length).min(axis=0)


def relative_tolerance(case: CoverageCase, expected, got, masks, length=False) -> float | None:
    """The least r such that E within r · max(|p1|, |p2|) of 0 (r · |b − a| if ``length``: a
    distance to the edge's line below r px) taken as 0 gives the student's every image of
    this case, if below 1e-3 (0.1 px) and it changes something, else None. A centre off two
    edges needs both taken as 0: the r tried run up from the least that explains every wrong
    centre through the ratios of the wrong centres' edges."""
    if not _shaped(got, expected) or np.array_equal(got, expected):
        return None
    cap = 0.1 if length else 1e-3
    points = _points(case)
    ratios = [_ratios(xy, points, length) for xy in case.triangles]
    r0 = 0.0
    for q, g, e in zip(ratios, got, expected):
        if (g != e).any():
            r0 = max(r0, float(q.min(axis=0)[g != e].max()))
    if not r0 < cap:
        return None
    # the wrong centres' ratios on each edge: one of them is the student's least r
    tried = np.unique(
        np.concatenate([q[:, g != e].ravel() for q, g, e in zip(ratios, got, expected)])
    )
    for r in [r0, *tried[(tried > r0) & (tried < cap)][:40]][0 if r0 else 1 :]:
        r = float(np.nextafter(r, 1.0))
        images = [image(case, xy, rel=r, length=length) for xy in case.triangles]
        if _same(case, got, images, masks):
            return r
    return None


def power(x: float) -> str:
    """1e-07 as '1e-7'."""
    return f"{x:.0e}".replace("e-0", "e-").replace("e+0", "e")


def step_words(delta: float | None, sx: int, sy: int, fill: bool) -> str:
    """The words for a step of ``delta`` px (None: a tiny one, its size not told by the case)
    along (sx, sy)."""
    way = " and ".join(w for w in ({1: "right", -1: "left"}.get(sx), {1: "down", -1: "up"}.get(sy))
                       if w)  # fmt: skip
    d = "1e-6" if delta is None else power(delta)
    size = "" if delta is None else f" by {d} px or more"
    x, y = ("j + 0.5", "i + 0.5") if fill else ("p[0]", "p[1]")
    x += {1: f" + {d}", -1: f" − {d}", 0: ""}[sx]
    y += {1: f" + {d}", -1: f" − {d}", 0: ""}[sy]
    point = f"({x}, {y})"
    return (
        f"a sample moved off the centre{size}: your images are the rule's tested a tiny step "
        f"off each centre ({way}: {point} gives them): "
        "a centre off an edge by less than the step times the edge's slope lands on the other "
        "side, and one on an edge is decided by the step, not the tie rule (a step to the "
        "right mimics the top-left rule on every non-horizontal edge, but not near a long "
        "steep one). Test the centre itself: vertices and centres are on the 1/256-px grid, "
        "so E there is exact"
    )


def tolerance_words(case: CoverageCase, r: float) -> str:
    return (
        f"a relative tolerance (math.isclose) in the edge test: you take E for 0 where it is "
        f"within a fraction r ≥ {cov.fmt(r)} of the products (b.x − a.x)(p.y − a.y) and "
        "(b.y − a.y)(p.x − a.x) it is the difference of, so beside a long edge, whose products "
        "reach 10^5 px², a centre 2^-16 px² off the edge is decided by the tie rule, though it "
        "lies strictly on one side (math.isclose's default rel_tol is 1e-9; np.isclose's rtol "
        "is 1e-5). On the 1/256 grid E is exact: compare E with 0 exactly (p1 > p2, p1 == p2)"
    )
