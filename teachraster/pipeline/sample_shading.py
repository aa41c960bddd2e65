"""Shading a multisampled frame: attributes once per pixel and triangle, at the pixel centre.

MSAA evaluates a triangle's attributes once for each pixel it shows in, at the pixel centre,
and writes that one value to every sample it wins. The centre may lie outside the triangle:
the attribute planes are then *extrapolated* (values may leave the vertex range; inside the
triangle they are clamped to it, as at covered centres). Where the extrapolated 1/w would be
<= 0 the perspective divide means nothing, and the covered sample nearest the centre is used
instead (ties: the lower sample index).

Everything per triangle (edge vectors, areas, the ratios min(w) / w_i, vertex values and
their ranges) is laid out once as contiguous columns (:class:`ShadeTables`), so shading n
pixels is a few gathers and a few multiply-adds per pixel.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.interpolation import weights_per_row


def _columns(a: np.ndarray) -> tuple[np.ndarray, ...]:
    """The columns of (M, c) ``a`` as contiguous (M,) arrays."""
    return tuple(np.ascontiguousarray(a[:, c]) for c in range(a.shape[1]))


@dataclass(frozen=True)
class ShadeTables:
    """Per triangle, what evaluating its attributes and depth at a point needs.

    Attributes
    ----------
    edges : three tuples of (M,) arrays
        For weight k, the opposite edge a → b (a = vertex k+1, b = vertex k+2):
        a.x, a.y, dx, dy, in pixels (the barycentric source vertices).
    area : (M,) float64
        E(v0, v1, v2) of those vertices.
    w : (M, 3) float64
        Clip w per vertex; ``ratio`` (M, 3) min(w) / w_i, the perspective weights' factors.
    perspective : (M,) bool
        Whether a triangle's attributes are divided by w.
    vertex_values, value_lo, value_hi : (M, k) arrays
        The attribute of each vertex (a tuple of three), and their minimum and maximum.
    vertex_depth, depth_lo, depth_hi : the same for window depth, as (M, 1).
    """

    edges: tuple
    area: np.ndarray
    w: np.ndarray
    ratio: np.ndarray
    perspective: np.ndarray
    vertex_values: tuple
    value_lo: np.ndarray
    value_hi: np.ndarray
    vertex_depth: tuple
    depth_lo: np.ndarray
    depth_hi: np.ndarray


def shade_tables(source, window, w, attrs, perspective) -> ShadeTables:
    """The :class:`ShadeTables` of a batch.

    ``source`` is :func:`~teachraster.pipeline.batched_fill.weight_source`'s answer (the
    vertices and areas barycentrics come from), ``window`` (M, 3, 3), ``w`` (M, 3) clip w,
    ``attrs`` (M, 3, k), ``perspective`` (M,) bool.
    """
    src, src_area, _, _ = source
    edges = []
    for k in range(3):
        a, b = src[:, (k + 1) % 3], src[:, (k + 2) % 3]
        edges.append(
            _columns(np.stack([a[:, 0], a[:, 1], b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]], 1))
        )
    depth = window[:, :, 2:3]

    def spread(v):  # per-vertex values and their range
        return tuple(np.ascontiguousarray(v[:, i]) for i in range(3)), v.min(axis=1), v.max(axis=1)

    values, lo, hi = spread(attrs)
    z, z_lo, z_hi = spread(depth)
    return ShadeTables(
        tuple(edges), src_area.astype(np.float64), w, w.min(axis=1, keepdims=True) / w,
        np.asarray(perspective, dtype=bool), values, lo, hi, z, z_lo, z_hi,
    )  # fmt: skip


def barycentrics_at(tables: ShadeTables, tri: np.ndarray, x, y) -> np.ndarray:
    """Barycentrics (n, 3) of triangles ``tri`` at points (x, y) in pixels, any point.

    Weight k is E(v_k+1, v_k+2, p) / E(v0, v1, v2): the same vertices and areas the batched
    fill uses, evaluated directly at the point (negative outside: extrapolation).
    """
    lam = np.empty((len(tri), 3))
    area = np.take(tables.area, tri)
    for k, (ax, ay, dx, dy) in enumerate(tables.edges):
        e = y - np.take(ay, tri)
        e *= np.take(dx, tri)
        d = x - np.take(ax, tri)
        d *= np.take(dy, tri)
        e -= d
        np.divide(e, area, out=lam[:, k])
    return lam


def shade(tables: ShadeTables, tri, pixel, won, offsets, width):
    """Attributes (n, k) and depth (n,) of triangles ``tri`` evaluated once for ``pixel``.

    At the pixel centre, extrapolated on the triangle's planes when the centre lies
    outside (values may leave the vertex range; inside they are clamped to it). Where the
    extrapolated 1/w would be <= 0, at the sample nearest the centre among ``won`` (n, S)
    bool, the samples the triangle shows in that pixel (ties: lower index); ``won`` may be
    None when every triangle shows at all samples of its pixel.
    """
    row, col = np.divmod(pixel, width)
    x, y = col + 0.5, row + 0.5
    lam = barycentrics_at(tables, tri, x, y)
    persp = np.take(tables.perspective, tri)
    q = lam * np.take(tables.ratio, tri, axis=0)
    total = q[:, 0] + q[:, 1]
    total += q[:, 2]
    inside = lam[:, 0] >= 0
    inside &= lam[:, 1] >= 0
    inside &= lam[:, 2] >= 0
    bad = persp & ~inside & ~(total > 0)
    if bad.any():  # the plane of 1/w crosses zero before the centre: use a covered sample
        if won is None:
            won = np.ones((len(tri), len(offsets)), dtype=bool)
        d = offsets - 0.5
        order = np.argsort(d[:, 0] ** 2 + d[:, 1] ** 2, kind="stable")
        s = order[np.argmax(won[bad][:, order], axis=1)]
        x[bad], y[bad] = col[bad] + offsets[s, 0], row[bad] + offsets[s, 1]
        lam[bad] = barycentrics_at(tables, tri[bad], x[bad], y[bad])
        q[bad] = lam[bad] * tables.ratio[tri[bad]]
        total[bad] = q[bad, 0] + q[bad, 1] + q[bad, 2]
        inside = (lam[:, 0] >= 0) & (lam[:, 1] >= 0) & (lam[:, 2] >= 0)
    with np.errstate(divide="ignore", invalid="ignore"):  # rows fixed just below
        if persp.all():
            weights = np.divide(q, total[:, None], out=q)
        else:
            weights = np.where(persp[:, None], q / total[:, None], lam)
    under = persp & ~(total > 0)  # every term underflowed: the log-domain fallback
    if under.any():
        weights[under] = weights_per_row(np.maximum(lam[under], 0), tables.w[tri[under]])
    values = _blend(weights, tri, tables.vertex_values, tables.value_lo, tables.value_hi, inside)
    depth = _blend(lam, tri, tables.vertex_depth, tables.depth_lo, tables.depth_hi, inside)
    return values, depth[:, 0]


def _blend(weights, tri, vertex, lo, hi, clamp):
    """``Σ μ_i f_i`` per row (n, k); clamped to the vertex range where ``clamp``."""
    v0, v1, v2 = (np.take(v, tri, axis=0) for v in vertex)
    out = weights[:, 0:1] * v0
    out += weights[:, 1:2] * v1
    out += weights[:, 2:3] * v2
    if clamp.any():
        at = np.flatnonzero(clamp)
        c = out[at]
        np.maximum(c, lo[tri[at]], out=c)
        np.minimum(c, hi[tri[at]], out=c)
        out[at] = c
    return out
