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
