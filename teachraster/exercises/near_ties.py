"""Coverage cases with a centre as close to an edge as the 1/256-px grid allows (r420 W1, W2).

On the 1/256 grid, E(a, b, p) at a pixel centre is a whole multiple of 2^-16 px²: a centre off
an edge has |E| ≥ 2^-16. A tolerance in the edge test (``abs(E) < 1e-4``, or ``1e-9 · area``)
takes such a centre for one on the edge, and the tie rule decides it the other way. Each case
here puts one centre at E = s · 2^-16 (s = ±1, ±2, ±4) from edge a→b of a triangle, strictly
inside the other two edges, on the side where the tie rule gives the other answer: inside a
right edge (the rule covers it, a tolerance leaves it out) or just outside a left one (the
rule leaves it out, a tolerance covers it). A *large* case puts the third vertex thousands of
px away, so that E(v1, v2, v3) ≥ 2 · 10^4 px² and a relative tolerance of 1e-9 · area flips the
centre too.

Every case is drawn so that float32 arithmetic gives the rule's answer at every centre of its
window (the products of the edge function anchored at either end are checked), so a float32
answer passes these cases and a tolerance is the only cause of a failure here
(:func:`float32_safe`).
"""

from __future__ import annotations

import math

import numpy as np

from .cases import WINDOW, CoverageCase

#: How the label of a near-tie case begins (:func:`float32_safe` reads it).
NEAR_TIE = "near tie"
UNIT = 256  # the grid: 1/256 px
#: The smallest E(v1, v2, v3) of a large case, px²: 1e-9 of it is 2e-5 px² > 2^-16.
LARGE_AREA = 2e4


def float32_safe(case: CoverageCase) -> bool:
    """A near-tie case: float32 gives the rule's answer at each of its centres (checked when
    it was drawn), so a wrong centre there is no float32 rounding."""
    return case.label.startswith(NEAR_TIE)


def _egcd(x: int, y: int) -> tuple[int, int, int]:
    """(g, m, n) with m·x + n·y = g = gcd(x, y)."""
    if y == 0:
        return (x, 1, 0) if x >= 0 else (-x, -1, 0)
    g, m, n = _egcd(y, x % y)
    return g, n, m - (x // y) * n


def _units_e(a, b, p) -> int:
    """E(a, b, p) in units of 2^-16 px², exactly (a, b, p in units of 1/256 px)."""
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def _float32_signs_agree(xy: np.ndarray, points: np.ndarray) -> bool:
    """At every point, each edge's E computed in float32 (inputs cast, anchored at either end
    of the edge) has the exact E's sign (0 included), and so has E(v1, v2, v3)."""
    f = np.float32
    v32, p32 = xy.astype(f), points.astype(f)
    for k in range(3):
        a, b = xy[k], xy[(k + 1) % 3]
        exact = np.sign(
            (b[0] - a[0]) * (points[:, 1] - a[1]) - (b[1] - a[1]) * (points[:, 0] - a[0])
        )
        for anchor in (v32[k], v32[(k + 1) % 3]):
            d = v32[(k + 1) % 3] - v32[k]
            e32 = d[0] * (p32[:, 1] - anchor[1]) - d[1] * (p32[:, 0] - anchor[0])
            if not np.array_equal(np.sign(e32), exact):
                return False
    return True


def _edge(rng, s: int, large: bool):
    """(a, b, c) in units: edge a→b with c, a pixel centre, at E(a, b, c) = s (2^-16 px²),
    b below a where s > 0 (a right edge of a triangle on its positive side), above it where
    s < 0 (a left edge); None where this draw does not fit the window."""
    c = (rng.integers(3, WINDOW - 3, 2) * UNIT + UNIT // 2).astype(int)
    ux = int(rng.integers(-500, 501))
    uy = int(rng.integers(300, 800)) * (1 if s > 0 else -1)
    if math.gcd(ux, uy) != 1:
        return None
    _, m, n = _egcd(uy, ux)  # m·uy + n·ux = 1, so d0 = (m, -n) has d0 × u = 1
    d0 = np.array([s * m, -s * n])
    u = np.array([ux, uy])
    lam = rng.uniform(2.0, 3.0) if large else rng.uniform(1.4, 2.2)
    t = round(lam - float(d0 @ u) / float(u @ u))
    d = d0 + t * u
    a = c - u
    b = a + d
    if (d[1] > 0) != (s > 0) or not all(UNIT // 4 <= q <= (WINDOW - 0.25) * UNIT for q in (*a, *b)):
        return None
    return a, b, c


def near_tie_triangle(rng, s: int, large: bool = False) -> np.ndarray | None:
    """A triangle (3 × 2, px, clockwise on screen as a, b, v) whose centre c lies at
    E(a, b, c) = s · 2^-16 px², strictly inside the other two edges, float32-safe
    (:func:`_float32_signs_agree`); None where this draw fails (draw again)."""
    edge = _edge(rng, s, large)
    if edge is None:
        return None
    a, b, c = edge
    d = b - a
    normal = np.array([-d[1], d[0]]) / np.hypot(*d)  # towards E > 0
    height = rng.uniform(6000, 9000) if large else rng.uniform(2.5, 5.0)
    v = np.rint((a + b) / 2 + normal * height * UNIT).astype(int)
    area = _units_e(a, b, v)
    if _units_e(b, v, c) <= 0 or _units_e(v, a, c) <= 0 or area <= 0:
        return None
    if large and area / UNIT**2 < LARGE_AREA:
        return None
    if not large and not all(UNIT // 4 <= q <= (WINDOW - 0.25) * UNIT for q in v):
        return None
    xy = np.array([a, b, v], dtype=float) / UNIT
    rows, cols = np.indices((WINDOW, WINDOW))
    centres = np.stack([cols.ravel() + 0.5, rows.ravel() + 0.5], axis=-1)
    return xy if _float32_signs_agree(xy, centres) else None


def near_tie_cases(rng, word: str, signs=(1, -1, 2, -4), large=(1, -1)) -> list[CoverageCase]:
    """One small case for each of ``signs`` and one large one for each of ``large``, both
    windings alternating, on a :data:`~.cases.WINDOW`-px window at the origin; labels begin
    with :data:`NEAR_TIE` and ``word`` ("" for the fixed cases, "drawn for this check")."""
    out = []
    for n, (s, big) in enumerate([(s, False) for s in signs] + [(s, True) for s in large]):
        xy = None
        while xy is None:
            xy = near_tie_triangle(rng, s, big)
        if n % 2:  # the other winding: v1, v3, v2
            xy = xy[[0, 2, 1]]
        xy = np.roll(xy, int(rng.integers(0, 3)), axis=0)
        what = "a large triangle, " if big else ""
        times = "" if abs(s) == 1 else f"{abs(s)} · "
        label = (f"{NEAR_TIE}{word} {n + 1}: {what}a centre {times}2^-16 px² "
                 f"{'inside' if s > 0 else 'outside'} an edge (as near as the 1/256 grid "
                 "allows)")  # fmt: skip
        out.append(CoverageCase(label, xy[None], (0, 0), (WINDOW, WINDOW)))
    return out


# -- r428 WP1, WP2: near ties beside long edges ---------------------------------------------------
#: How the label of the long near-tie case begins (not :data:`NEAR_TIE`: float32 may fail it).
LONG_NEAR_TIES = "long near ties"
#: The long edges' shapes, (|u.x| range, |u.y| range) in px, u half the edge (the centre in the
#: middle), and the third vertex's distance from it, px: *steep* (|dy| ≈ 1000 px, |dx| < 1 px,
#: products below 2^24 · 2^-16 px², so float32 holds them exactly), *diagonal* (|dx| < |dy|,
#: products ≈ 10^5 px²), *shallow* (|dy| ≤ 12 px, products ≥ 10^5 px²), *sliver* (a diagonal
#: edge of a triangle 2-4 px tall: products ≈ 10^5 px², area ≈ 10^3 px²).
LONG_SHAPES = {"steep": ((1 / UNIT, 24 / UNIT), (400, 500), (4000, 6000)),
               "diagonal": ((250, 350), (400, 500), (1500, 2000)),
               "shallow": ((10500, 12000), (3.0, 4.0), (1500, 2000)),
               "sliver": ((250, 350), (400, 500), (2.0, 4.0))}  # fmt: skip


def _long_edge(rng, s: int, shape: str, c: np.ndarray, sx: int):
    """(a, b) in units: a→b with E(a, b, c) = s (2^-16 px²), c in its middle, b below a where
    s > 0 (a right edge), above it where s < 0 (a left edge); None where this draw fails."""
    (x0, x1), (y0, y1), _ = LONG_SHAPES[shape]
    ux = int(rng.uniform(x0, x1) * UNIT) * sx
    uy = int(rng.uniform(y0, y1) * UNIT) * (1 if s > 0 else -1)
    if math.gcd(ux, uy) != 1:
        return None
    _, m, n = _egcd(uy, ux)  # m·uy + n·ux = 1, so d0 = (m, -n) has d0 × u = 1
    d0 = np.array([s * m, -s * n])
    u = np.array([ux, uy])
    d = d0 + round(2.0 - float(d0 @ u) / float(u @ u)) * u
    a = c - u
    return (a, a + d) if (d[1] > 0) == (s > 0) else None


def _long_triangle(rng, s: int, shape: str, c: np.ndarray, sx: int) -> np.ndarray | None:
    """A triangle (px) whose centre c lies at E(a, b, c) = s · 2^-16 px² beside its long edge
    a→b (running sx in x), strictly inside the other two; or None."""
    edge = _long_edge(rng, s, shape, c, sx)
    if edge is None:
        return None
    a, b = edge
    d = b - a
    normal = np.array([-d[1], d[0]]) / np.hypot(*d)  # towards E > 0
    v = np.rint((a + b) / 2 + normal * rng.uniform(*LONG_SHAPES[shape][2]) * UNIT).astype(int)
    if _units_e(b, v, c) <= 0 or _units_e(v, a, c) <= 0 or _units_e(a, b, v) <= 0:
        return None
    return np.array([a, b, v], dtype=float) / UNIT


def long_near_tie_case(rng) -> CoverageCase:
    """r428 WP1, WP2: five triangles (not a mesh) on a :data:`~.cases.WINDOW`-px window at the
    origin, each with one centre 2^-16 px² from an edge: inside a steep long right edge,
    outside a diagonal long left edge, inside a shallow long right edge, inside a sliver's
    long right edge, and inside a short right edge of a large triangle (:func:`near_tie_triangle`).
    A step off the centre (to the right: steep, diagonal, sliver), a relative tolerance on the
    products (``math.isclose``: diagonal, shallow, sliver), one on the area (all but the
    sliver) and an absolute one (all) each flip a different set, so the set the student gets
    wrong tells them apart (:mod:`.sample_steps`); the diagonal and shallow edges run the same
    way in x, so no step along y flips both. float32 may fail the long ones (products of 10^5
    px²), never the steep one or the short one."""
    tris, used = [], set()
    sx = int(rng.choice((1, -1)))
    for s, shape in ((1, "steep"), (-1, "diagonal"), (1, "shallow"), (1, "sliver")):
        xy = None
        while xy is None:
            c = rng.integers(2, WINDOW - 2, 2)
            if (int(c[0]), int(c[1])) in used:
                continue
            sign = sx if shape != "steep" else int(rng.choice((1, -1)))
            xy = _long_triangle(rng, s, shape, c * UNIT + UNIT // 2, sign)
        used.add((int(c[0]), int(c[1])))
        tris.append(xy if len(tris) % 2 == 0 else xy[[0, 2, 1]])
    short = None
    while short is None:
        short = near_tie_triangle(rng, 1, large=True)
    tris.append(np.roll(short, 1, axis=0))
    label = (f"{LONG_NEAR_TIES}: five triangles, each with a centre 2^-16 px² from an edge "
             "(as near as the 1/256 grid allows), four beside long edges (steep, diagonal, "
             "shallow, a sliver's) and one beside a short edge of a large triangle")  # fmt: skip
    return CoverageCase(label, np.array(tris), (0, 0), (WINDOW, WINDOW))


#: How the label of the float32-winding sliver begins (r438 WP1).
SLIVER32 = "a sliver whose area float32 cannot hold"
#: Its vertices (found by a seeded search): E(v1, v2, v3) = 0.043 px², products of 10^6 px²;
#: in float32 E(v1, v2, v3) comes out 0. Centre (2.5, 5.5), v3, is covered by the rule.
SLIVER32_XY = ((1570.3046875, -1967.69140625), (-932.390625, 1182.125), (2.5, 5.5))


def sliver32_case() -> CoverageCase:
    """r438 WP1: a sliver 4,000 px long whose E(v1, v2, v3) = 0.043 px² float32 rounds to 0
    (its products, ~10^6 px², keep 24 bits): a winding or zero-area test in float32 drops it,
    though the rule covers its vertex v3 at a centre. Every edge test in float64 is exact."""
    label = f"{SLIVER32}: 4,000 px long, E(v1, v2, v3) = 0.043 px², its products 10^6 px²"
    return CoverageCase(label, np.array([SLIVER32_XY]), (0, 0), (WINDOW, WINDOW))


def winding32_images(case: CoverageCase, expected: np.ndarray) -> np.ndarray:
    """The rule's images where the winding is decided by E(v1, v2, v3) in float32: a triangle
    whose float32 E is 0 or of the other sign covers nothing (its interior turned to E < 0)."""
    out = expected.copy()
    for k, xy in enumerate(case.triangles):
        v = np.asarray(xy, dtype=np.float32)
        e32 = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
        a, b, c = np.asarray(xy, dtype=float)
        e = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        if e32 == 0 or np.sign(e32) != np.sign(e):
            out[k] = False
    return out
