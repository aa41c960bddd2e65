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
- A tolerance on the distance to the edge's line (|E| / |b − a| < ε, r438 M1, M2), and a bias on
  the edges that do not own their ties (E − β ≥ 0 there, Direct3D's integer test with β taken
  as 1 px² or 1e-4 px², r438 M3): the same fit, relative to the edge's length or to 1
  (:func:`relative_tolerance` with ``length``, ``absolute``, ``one_sided``).

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
          length: bool = False, one_sided: bool = False, absolute: bool = False,
          per_area: bool = False):  # fmt: skip
    """(h, w) bool: the rule at each centre moved by ``step`` (px), with E taken as 0 where
    |E| ≤ ``rel`` · max(|p1|, |p2|) (anchored at each oriented edge's start), or where
    |E| ≤ ``rel`` · ``area`` if ``area`` is given, or |E| ≤ ``rel`` · |b − a| (a distance to
    the edge's line below ``rel`` px) if ``length``, or |E| ≤ ``rel`` (px²) if ``absolute``.
    ``one_sided`` (r438 M1, M3): no tie is made; a centre inside an edge that does not own its
    ties is covered only beyond the bound (a bias: E − β ≥ 0), one outside any edge never.
    ``per_area`` (r453 M1): |E| ≤ ``rel`` · |E(v1, v2, v3)|, a tolerance on λ = E / area."""
    points = _points(case) + np.asarray(step, dtype=float)
    if per_area:
        area = abs(cov.area2(np.asarray(xy, dtype=float)))
    if cov.area2(np.asarray(xy, dtype=float)) == 0:
        return np.zeros(points.shape[:2], dtype=bool)
    v = _oriented(xy)
    inside = np.ones(points.shape[:2], dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        p1, p2 = _products(a, b, points)
        e = p1 - p2
        bound = rel * _scale(a, b, p1, p2, area, length, absolute)
        if one_sided:
            inside &= (e >= 0) if _top_left(a, b) else (e > bound)
            continue
        tie = np.abs(e) <= bound if rel else e == 0
        inside &= np.where(tie, _top_left(a, b), e > 0)
    return inside


def _scale(a, b, p1, p2, area: float = 0.0, length: bool = False, absolute: bool = False):
    """What a tolerance is relative to: the triangle's area, the edge's length, 1 (an
    absolute one), or else the larger of the edge function's two products at each point."""
    if absolute:
        return 1.0
    if area:
        return area
    if length:
        return float(np.hypot(*(b - a)))
    return np.maximum(np.abs(p1), np.abs(p2))


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


def _ratios(xy, points, length: bool = False, absolute: bool = False,
            one_sided: bool = False, per_area: bool = False) -> np.ndarray:  # fmt: skip
    """(3, ...): at each point, |E| / max(|p1|, |p2|) for each oriented edge (|E| / |b − a|
    if ``length``, |E| if ``absolute``); ``one_sided``: inside the edges that do not own their
    ties only (elsewhere a bias changes nothing: inf)."""
    v = _oriented(xy)
    out = []
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        p1, p2 = _products(a, b, points)
        area = abs(cov.area2(np.asarray(xy, dtype=float))) if per_area else 0.0
        big = np.broadcast_to(_scale(a, b, p1, p2, area, length, absolute), p1.shape)
        ok = (big > 0) & ((p1 > p2) & (not _top_left(a, b)) if one_sided else True)
        with np.errstate(divide="ignore", invalid="ignore"):
            out.append(np.where(ok, np.abs(p1 - p2) / big, np.inf))
    return np.array(out)


def _ratio(xy, points, area: float = 0.0, length: bool = False) -> np.ndarray:
    """At each point, the least ratio of :func:`_ratios` (|E| / ``area`` where it is given)."""
    if area:
        return np.abs(np.array([p1 - p2 for p1, p2 in (_products(a, b, points) for a, b in
                                zip(_oriented(xy), np.roll(_oriented(xy), -1, axis=0)))])).min(
            axis=0) / area  # fmt: skip
    return _ratios(xy, points, length).min(axis=0)


#: The largest tolerance looked for, by what it is relative to: a fraction of the products
#: (isclose), a distance in px, px² (an absolute bias: one unit of an integer grid taken as 1).
CAPS = {"products": 1e-3, "length": 0.1, "absolute": 2.0, "per_area": 1e-3}


def relative_tolerance(case: CoverageCase, expected, got, masks, length=False,
                       one_sided=False, absolute=False, per_area=False) -> float | None:  # fmt: skip
    """The least r such that E within r · max(|p1|, |p2|) of 0 (r · |b − a| if ``length``: a
    distance to the edge's line below r px; r px² if ``absolute``) taken as 0 gives the
    student's every image of this case, if below :data:`CAPS` and it changes something, else
    None (``one_sided``: a bias on the edges that do not own their ties, see :func:`image`).
    A centre off two edges needs both taken as 0: the r tried run up from the least that
    explains every wrong centre through the ratios of the wrong centres' edges."""
    if not _shaped(got, expected) or np.array_equal(got, expected):
        return None
    cap = CAPS["absolute" if absolute else "length" if length else
               "per_area" if per_area else "products"]  # fmt: skip
    points = _points(case)
    ratios = [_ratios(xy, points, length, absolute, one_sided, per_area) for xy in case.triangles]
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
        above = float(np.nextafter(r, 1.0))
        images = [image(case, xy, rel=above, length=length, one_sided=one_sided,
                        absolute=absolute, per_area=per_area) for xy in case.triangles]  # fmt: skip
        if _same(case, got, images, masks):
            return above if not absolute else float(r)  # an absolute one: exact on the grid
    return None


def tolerance_range(case: CoverageCase, expected, got, masks, **form) -> tuple | None:
    """(lo, hi): the tolerances r of :func:`relative_tolerance`'s ``form`` that give the
    student's every image of this case (lo = 0 where it is the rule's), lo ≤ r < hi (hi: the least ratio above lo at which a
    centre the student has right would change), or None. One ε of the student's must lie in
    every failing case's range (r438: an ε fitted case by case took an area-relative
    tolerance for a distance one)."""
    if not _shaped(got, expected):
        return None
    same = np.array_equal(got, expected)  # a passing case: no tolerance may change it
    lo = 0.0 if same else relative_tolerance(case, expected, got, masks, **form)
    if lo is None:
        return None
    points = _points(case)
    keys = ("length", "absolute", "one_sided", "per_area")
    ratios = [_ratios(xy, points, *(bool(form.get(k)) for k in keys)) for xy in case.triangles]
    above = np.unique(np.concatenate([q.ravel() for q in ratios]))
    above = above[(above > lo) & np.isfinite(above)]
    first, last = 0, len(above)  # the first candidate whose image differs: a bisection
    while first < last:
        mid = (first + last) // 2
        r = float(np.nextafter(above[mid], 1.0))
        images = [image(case, xy, rel=r, **form) for xy in case.triangles]
        if _same(case, got, images, masks):
            first = mid + 1
        else:
            last = mid
    return lo, float(above[first]) if first < len(above) else np.inf


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


def distance_words(case: CoverageCase, r: float, one_sided: bool = False) -> str:
    """r438 M1, M2: a tolerance on the distance |E| / |b − a| to the edge's line (told float32,
    or a step off the centre, before)."""
    what = ("you leave out a centre inside an edge that does not own its ties unless it lies "
            f"more than ε ≥ {cov.fmt(r)} px from the edge's line, as if it lay on it" if one_sided
            else f"you take a centre within ε ≥ {cov.fmt(r)} px of an edge's line for one on it, "
            "so the tie rule decides it")  # fmt: skip
    return (
        f"a tolerance on the distance to the edge's line (|E| / |b − a| < ε): {what}, though "
        "it lies strictly inside. Beside a long edge a "
        "centre 2^-16 px² inside lies 2^-16 / |b − a| px from the line: 1.5e-8 px beside an "
        "edge 1000 px long, below any ε you might pick. On the 1/256 grid E is exact: compare "
        "E itself with 0 exactly (E == 0 is the only tie; no division, no ε)"
    )


def bias_words(case: CoverageCase, r: float) -> str:
    """r438 M3, H2: a bias (E − β ≥ 0, β > 0) on the edges that do not own their ties."""
    return (
        f"a bias on the edges that do not own their ties: you cover a centre inside such an "
        f"edge only where E ≥ β, β above {cov.fmt(r)} px² (Direct3D's integer test E + bias "
        "≥ 0 with a bias of −1, or int(E), taken over in px²?), so a centre strictly inside it "
        "by less is left out. Here E's unit is 2^-16 px² = 1.53e-05 px², not 1: for those "
        "edges test E > 0 exactly, for the top and left edges E ≥ 0"
    )


def area_words(case: CoverageCase, r: float) -> str:
    """r453 M1: a tolerance on λ = E / E(v1, v2, v3) (told a step off the centre before)."""
    return (
        "a tolerance in the edge test, relative to the triangle's area: you take a centre "
        "whose λ = E / E(v1, "
        f"v2, v3) (a barycentric) lies within ε of 0, ε above {cov.fmt(r)}, for one on the "
        "edge, so the tie rule decides it, though it lies strictly inside. Beside an edge of a "
        "large "
        "triangle a centre 2^-16 px² inside has λ = 2^-16 / E(v1, v2, v3): 1e-12 where the "
        "area is 10^7 px², below any ε you might pick. On the 1/256 grid E is exact: a centre "
        "off the edge has |E| ≥ 2^-16 px², so compare E (or λ) with 0 exactly, no ε"
    )
