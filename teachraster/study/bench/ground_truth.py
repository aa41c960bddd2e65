"""Ground truths computed independently of the rasteriser: exact coverage, ray-traced uv."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from ...core.snapping import check_bits
from ...core.validate import as_size

# -- exact coverage (the conventions' reference) ----------------------------------------------
#: Bound on the rounding error of a float64 orient2d, relative to |t1| + |t2|. Shewchuk's
#: bound is (3 + 16 eps) eps ~ 3.3e-16 (rounded differences included); 1e-15 is 3x that.
_ERRBOUND = 1e-15


def exact_coverage(xy, width: int, height: int, bits: int | None = 8, origin=(0, 0)):
    """Exact coverage by the top-left rule, in rational arithmetic, written from CONVENTIONS.

    Vertices are snapped to ``1 / 2**bits`` px (round half to even) as Fractions, or taken as
    the exact rationals the floats are (``bits=None``). Each pixel's edge functions are
    first evaluated in float64; where the result is farther from 0 than a proven bound on
    its rounding error its sign is certain, and only the remaining pixels (centres on or a
    hair from an edge) are decided with Fractions. This is independent of the package's
    rasteriser and of :mod:`teachraster.study.precision`.

    Returns
    -------
    (height, width) bool
        For the window of pixels ``origin + (j, i)``.
    """
    width, height = as_size("width", width), as_size("height", height)
    bits = check_bits(bits)
    ox, oy = (int(v) for v in origin)
    xy = np.asarray(xy, dtype=np.float64)
    if bits is None:
        v = [(Fraction(x), Fraction(y)) for x, y in xy.tolist()]
    else:
        s = 2**bits  # Python's round() of a Fraction rounds half to even
        v = [
            (Fraction(round(Fraction(x) * s), s), Fraction(round(Fraction(y) * s), s))
            for x, y in xy.tolist()
        ]

    def edge(a, b, p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    out = np.zeros((height, width), dtype=bool)
    area2 = edge(v[0], v[1], v[2])
    if area2 == 0:
        return out
    if area2 < 0:
        v = [v[0], v[2], v[1]]
    xs, ys = [p[0] for p in v], [p[1] for p in v]
    half = Fraction(1, 2)
    c0, c1 = max(math.ceil(min(xs) - half), ox), min(math.floor(max(xs) - half) + 1, ox + width)
    r0, r1 = max(math.ceil(min(ys) - half), oy), min(math.floor(max(ys) - half) + 1, oy + height)
    if c1 <= c0 or r1 <= r0:
        return out
    cols, rows = np.arange(c0, c1), np.arange(r0, r1)
    px, py = cols + 0.5, rows + 0.5  # exact in float64
    inside = np.ones((len(rows), len(cols)), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        # Snapped vertices and raw floats are exact float64 values, so only the arithmetic
        # below rounds, and the bound covers it.
        ax, ay, bx, by = float(a[0]), float(a[1]), float(b[0]), float(b[1])
        t1 = (bx - ax) * (py - ay)[:, None]
        t2 = ((by - ay) * (px - ax))[None, :]
        e = t1 - t2
        bound = _ERRBOUND * (np.abs(t1) + np.abs(t2))
        ok = e > bound
        unsure = inside & ~ok & (e >= -bound)
        for i, j in zip(*np.nonzero(unsure)):
            p = (Fraction(2 * int(cols[j]) + 1, 2), Fraction(2 * int(rows[i]) + 1, 2))
            ek = edge(a, b, p)
            ok[i, j] = ek > 0 or (ek == 0 and top_left)
        inside &= ok
    out[r0 - oy : r1 - oy, c0 - ox : c1 - ox] = inside
    return out


def screen_offset_px(xy, w, uv, rows, cols, error) -> np.ndarray:
    """How far on screen, in pixels, a texture-coordinate error moves the texture, per pixel.

    A pixel at (x, y) that shows the texture at ``uv + e`` instead of ``uv`` shows what
    belongs at the screen point p where the true (perspective-correct) texture coordinates
    are ``uv + e``: this returns ``|p − (x, y)|``, exactly (float64), not to first order. With
    the triangle's screen-space planes a·p of u/w, v/w and 1/w (lesson 04), p solves the two
    linear equations (a_u − u' a_q)·p = 0 and (a_v − v' a_q)·p = 0, (u', v') = uv + e: the
    plane's projective map, inverted (p may lie outside the triangle, on its plane).

    Parameters
    ----------
    xy (3, 2), w (3,), uv (3, 2)
        The triangle's window positions, clip w and texture coordinates.
    rows, cols : (P,) int
        The pixels (their centres are evaluated).
    error : (P, 2)
        Each pixel's error in the units of ``uv`` (texels and texel coordinates alike).

    Returns
    -------
    (P,) float64, pixels.

    >>> xy = np.array([[0.0, 0.0], [8.0, 0.0], [0.0, 8.0]])      # uv = xy / 8: 1/8 per px
    >>> screen_offset_px(xy, np.ones(3), xy / 8, np.array([1]), np.array([1]),
    ...                  np.array([[0.25, 0.0]]))                  # a quarter is 2 px
    array([2.])
    """
    xy, w, uv = (np.asarray(a, dtype=np.float64) for a in (xy, w, uv))
    plane = np.linalg.solve(np.column_stack([xy, np.ones(3)]), np.column_stack([uv / w[:, None],
                            1.0 / w]))  # fmt: skip  # (3, 3): u/w, v/w, 1/w = a x + b y + c
    x, y = np.asarray(cols) + 0.5, np.asarray(rows) + 0.5
    at = np.column_stack([x, y, np.ones(len(x))])
    values = at @ plane  # (P, 3)
    shown = values[:, :2] / values[:, 2:3] + np.asarray(error, dtype=np.float64)  # (P, 2)
    m = plane.T[None, :2, :] - shown[:, :, None] * plane[:, 2][None, None, :]  # (P, 2, 3)
    p = np.linalg.solve(m[:, :, :2], -m[:, :, 2:3])[:, :, 0]  # the screen point showing it
    return np.hypot(p[:, 0] - x, p[:, 1] - y)


def uv_ground_truth(xy, w, uv, size: int, rows, cols) -> np.ndarray:
    """Texture coordinates at pixel centres by ray-plane intersection in 3D (float64).

    Each window vertex (x, y) with depth w is lifted back to the 3D point
    ``((x - c) w / f, (y - c) w / f, w)`` of the pinhole camera of :func:`floor_quad`; the
    ray through the pixel centre meets the triangle's plane at Q, and uv is blended with
    Q's barycentric coordinates *in 3D* (ratios of sub-triangle areas). No screen-space
    barycentric or 1/w interpolation is involved.
    """
    f = c = size / 2
    P = np.column_stack([(xy[:, 0] - c) * w / f, (xy[:, 1] - c) * w / f, w])
    n = np.cross(P[1] - P[0], P[2] - P[0])
    d = np.column_stack([(cols + 0.5 - c) / f, (rows + 0.5 - c) / f, np.ones(len(rows))])
    t = (n @ P[0]) / (d @ n)
    Q = t[:, None] * d
    nn = n @ n
    bary = [np.cross(P[(i + 1) % 3] - Q, P[(i + 2) % 3] - Q) @ n / nn for i in range(3)]
    return sum(b[:, None] * uv[i] for i, b in enumerate(bary))
