"""Naive variants: what a straightforward rasteriser computes instead (numpy only).

Deliberately *not* what the core does, so lesson 07 can show naive and correct side by side.
"""

from __future__ import annotations

import numpy as np

from ...core.plane_equations import plane_equation
from ...core.validate import as_size


# -- naive helpers (numpy only; deliberately what the core does *not* do) -------------------
def naive_coverage(
    xy,
    width: int,
    height: int,
    *,
    rule: str = "inclusive",
    dtype=np.float64,
    orient: str = "unsnapped",
    absolute: bool = False,
    origin: tuple[int, int] = (0, 0),
) -> np.ndarray:
    """Coverage by raw floating-point edge functions: no snapping and (unless asked) no tie rule.

    Parameters
    ----------
    xy : (3, 2) array-like
        Vertices in pixels.
    width, height : int
        Size of the window of pixels tested.
    rule : {"inclusive", "strict", "top_left", "top_right", "bottom_left", "bottom_right"}
        A centre on an edge is inside (``E >= 0``: shared edges are drawn twice), outside
        (``E > 0``: shared edges are drawn by nobody), or decided by the top-left rule (the
        other three: the rule with the top or the left direction reversed, a typical mistake).
    dtype : numpy float type
        Arithmetic of the edge functions (float32 as on old GPUs and in shaders).
    orient : {"unsnapped", "none"}
        Orient by the sign of the float area, or assume clockwise-on-screen input (a
        counter-clockwise triangle then covers nothing).
    absolute : bool
        Evaluate ``E = A x + B y + C`` with absolute coordinates (*Triangle Rasterisation II - Interpolation*'s plane form),
        which cancels catastrophically far from the origin, instead of from differences.
    origin : (row, col)
        Pixel index of the window's top-left pixel (for triangles far from the origin).
    """
    v = np.asarray(xy, dtype=np.float64).astype(dtype)
    (ax, ay), (bx, by), (cx, cy) = v
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if orient == "unsnapped" and area < 0:
        v = v[[0, 2, 1]]
    rows = np.arange(origin[0], origin[0] + height)
    cols = np.arange(origin[1], origin[1] + width)
    py = (rows.astype(np.float64) + 0.5).astype(dtype)[:, None]
    px = (cols.astype(np.float64) + 0.5).astype(dtype)[None, :]
    inside = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        if absolute:
            A, B = a[1] - b[1], b[0] - a[0]
            C = a[0] * b[1] - a[1] * b[0]
            e = A * px + B * py + C
        else:
            e = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
        if rule == "inclusive":
            ok = e >= 0
        elif rule == "strict":
            ok = e > 0
        else:  # "top_left" (or, a mistake, the rule with a direction reversed)
            vertical, horizontal = rule.split("_")
            side = b[1] < a[1] if horizontal == "left" else b[1] > a[1]
            flat = b[1] == a[1] and (b[0] > a[0] if vertical == "top" else b[0] < a[0])
            ok = e >= 0 if side or flat else e > 0
        inside &= ok
    return inside


def naive_counts(triangles, width: int, height: int, **kwargs) -> np.ndarray:
    """Sum of :func:`naive_coverage` over triangles."""
    width, height = as_size("width", width), as_size("height", height)
    counts = np.zeros((height, width), dtype=np.int64)
    for xy in triangles:
        counts += naive_coverage(xy, width, height, **kwargs)
    return counts


def naive_window(clip, width: int, height: int) -> np.ndarray:
    """Divide by w *before* clipping: a vertex behind the eye is mirrored, w = 0 gives inf/NaN."""
    width, height = as_size("width", width), as_size("height", height)
    c = np.asarray(clip, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        ndc = c[..., :3] / c[..., 3:4]
    x = (ndc[..., 0] + 1.0) * (width / 2)
    y = (1.0 - ndc[..., 1]) * (height / 2)
    return np.stack([x, y, ndc[..., 2] * 0.5 + 0.5], axis=-1)


def naive_stepped32(xy, f, x0: float, y0: float, ncols: int, nrows: int) -> np.ndarray:
    """The plane-equation post's (*Triangle Rasterisation II - Interpolation*) incremental stepping (start, then ``+= dx`` per pixel) in float32."""
    ncols, nrows = as_size("ncols", ncols), as_size("nrows", nrows)
    plane = plane_equation(xy, f)
    start = np.float32(plane(x0, y0))
    dx, dy = np.float32(plane.dx), np.float32(plane.dy)
    firsts = np.add.accumulate(np.r_[start, np.full(nrows - 1, dy, dtype=np.float32)])
    grid = np.empty((nrows, ncols), dtype=np.float32)
    grid[:, 0] = firsts
    grid[:, 1:] = dx
    return np.add.accumulate(grid, axis=1, dtype=np.float32).astype(np.float64)


def naive_affine(xy, f, width: int, height: int) -> np.ndarray:
    """Screen-space (affine) interpolation everywhere in the image, ignoring w."""
    width, height = as_size("width", width), as_size("height", height)
    v = np.asarray(xy, dtype=np.float64)
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    (ax, ay), (bx, by), (cx, cy) = v
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    l0 = ((cx - bx) * (ys - by) - (cy - by) * (xs - bx)) / area
    l1 = ((ax - cx) * (ys - cy) - (ay - cy) * (xs - cx)) / area
    l2 = 1.0 - l0 - l1
    f = np.asarray(f, dtype=np.float64)
    return l0 * f[0] + l1 * f[1] + l2 * f[2]


def naive_perspective32(lam: np.ndarray, w, f) -> np.ndarray:
    """Perspective-correct weights in float32, as a shader would: ``(λ/w) / Σ λ/w``."""
    lam32 = lam.astype(np.float32)
    with np.errstate(all="ignore"):
        q = lam32 / np.asarray(w, dtype=np.float64).astype(np.float32)
        q = q / q.sum(axis=1, keepdims=True)
    return (q.astype(np.float64) @ np.asarray(f, dtype=np.float64)).astype(np.float64)


#: Naive rules the lesson 07 picker applies to any screen-space case, each a way a
#: straightforward rasteriser goes wrong: name -> (what it does, in words; keyword arguments of
#: :func:`naive_coverage`; whether the vertices are first rounded to whole pixels).
NAIVE_RULES = {
    "E ≥ 0": ("raw floats, a centre exactly on an edge inside every triangle that shares the "
              "edge (no tie rule)", {"rule": "inclusive"}, False),
    "E > 0": ("raw floats, a centre exactly on an edge inside no triangle (no tie rule)",
              {"rule": "strict"}, False),
    "whole px": ("vertices rounded to whole pixels (no sub-pixel bits), then the top-left rule",
                 {"rule": "top_left"}, True),
    "one winding": ("no re-orientation: a triangle wound the other way round covers nothing "
                    "(top-left rule)", {"rule": "top_left", "orient": "none"}, False),
}  # fmt: skip


def naive_rule_masks(triangles, width: int, height: int, rule: str):
    """Each triangle's coverage under the naive ``rule`` of :data:`NAIVE_RULES`, and the
    triangles it filled (rounded to whole pixels for ``"whole px"``, else as given).

    >>> tris = [[[0.5, 0.5], [4.5, 0.5], [0.5, 4.5]]]   # edges through 13 centres
    >>> [int(naive_rule_masks(tris, 5, 5, r)[0][0].sum()) for r in ("E ≥ 0", "E > 0")]
    [15, 3]
    """
    if rule not in NAIVE_RULES:
        raise ValueError(f"rule must be one of {list(NAIVE_RULES)}, got {rule!r}")
    _, kwargs, rounded = NAIVE_RULES[rule]
    filled = np.rint(np.asarray(triangles, dtype=np.float64)) if rounded else triangles
    return [naive_coverage(xy, width, height, **kwargs) for xy in filled], filled
