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

from ...core.interpolation import huge_exponents, weights_per_row


@dataclass(frozen=True)
class ShadeTables:
    """Per triangle, what evaluating its attributes and depth at a point needs.

    Every table is (c, M), one contiguous row per number, so a gather of n triangles
    (``np.take(table, tri, axis=1)``) gives (c, n) rows that the arithmetic runs along.

    Attributes
    ----------
    edges : (3, 4, M) float64
        For weight k, the opposite edge a → b (a = vertex k+1, b = vertex k+2): a.x, a.y,
        dx, dy, in pixels (the barycentric source vertices).
    area : (M,) float64
        E(v1, v2, v3) of those vertices.
    w : (M, 3) float64
        Clip w per vertex; ``ratio`` (3, M) min(w) / w_i, the perspective weights' factors.
    perspective : (M,) bool
        Whether a triangle's attributes are divided by w.
    values : (3, k, M)
        The attributes of each vertex; ``value_lo``, ``value_hi`` (k, M) their range.
    value_scale : (k, M) int or None
        Powers of two that bring values near the float maximum down (``values`` is stored
        scaled by them, and sums scaled back, so extrapolation gives ±inf only where the
        true value overflows; :func:`~teachraster.core.interpolation.huge_exponents`);
        None when every value is ordinary.
    depth : (3, 1, M)
        Window depth of each vertex; ``depth_lo``, ``depth_hi`` (1, M) its range.
    """

    edges: np.ndarray
    area: np.ndarray
    w: np.ndarray
    ratio: np.ndarray
    perspective: np.ndarray
    values: np.ndarray
    value_lo: np.ndarray
    value_hi: np.ndarray
    value_scale: np.ndarray | None
    depth: np.ndarray
    depth_lo: np.ndarray
    depth_hi: np.ndarray


def shade_tables(source, window, w, attrs, perspective) -> ShadeTables:
    """The :class:`ShadeTables` of a batch.

    ``source`` is :func:`~teachraster.pipeline.batched_fill.weight_source`'s answer (the
    vertices and areas barycentrics come from), ``window`` (M, 3, 3), ``w`` (M, 3) clip w,
    ``attrs`` (M, 3, k), ``perspective`` (M,) bool.
    """
    src, src_area, _, _ = source
    edges = np.empty((3, 4, len(src)))
    for k in range(3):
        a, b = src[:, (k + 1) % 3], src[:, (k + 2) % 3]
        edges[k] = a[:, 0], a[:, 1], b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
    values = np.ascontiguousarray(np.transpose(attrs, (1, 2, 0)))  # (3, k, M)
    lo, hi = values.min(axis=0), values.max(axis=0)
    scale = huge_exponents(attrs).T  # (k, M)
    if scale.any():
        values = np.ldexp(values, -scale)
    depth = np.ascontiguousarray(np.transpose(window[:, :, 2:3], (1, 2, 0)))
    return ShadeTables(
        edges, src_area.astype(np.float64), w, np.ascontiguousarray((w.min(axis=1)[:, None] / w).T),
        np.asarray(perspective, dtype=bool), values, lo, hi, scale if scale.any() else None,
        depth, depth.min(axis=0), depth.max(axis=0),
    )  # fmt: skip


def barycentrics_at(tables: ShadeTables, tri: np.ndarray, x, y) -> np.ndarray:
    """Barycentrics (3, n) of triangles ``tri`` at points (x, y) in pixels, any point.

    Weight k (from 0: λ1, λ2, λ3) is E(a, b, p) / E(v1, v2, v3), a → b the edge opposite its
    vertex (indices k+1, k+2 mod 3): the same vertices and areas the batched
    fill uses, evaluated directly at the point (negative outside: extrapolation).
    """
    lam = np.empty((3, len(tri)))
    area = np.take(tables.area, tri)
    for k in range(3):
        ax, ay, dx, dy = np.take(tables.edges[k], tri, axis=1)
        e = y - ay
        e *= dx
        d = x - ax
        d *= dy
        e -= d
        np.divide(e, area, out=lam[k])
    return lam


#: Pixels shaded per block: a block's dozen temporaries stay in the CPU cache, which makes
#: the same arithmetic on a frame's worth of pixels ~1.5x faster than in one pass.
BLOCK = 16384


def shade(tables: ShadeTables, tri, pixel, covers, offsets, width, centroid=None):
    """Attributes (k, n) and depth (n,) of triangles ``tri`` evaluated once for ``pixel``.

    At the pixel centre, extrapolated on the triangle's planes when the centre lies
    outside (values may leave the vertex range; inside they are clamped to it). Where the
    extrapolated 1/w would be <= 0, at the sample nearest the centre among ``covers`` (n, S)
    bool, the samples the triangle covers in that pixel (ties: lower index); ``covers`` may
    be None when every triangle covers all samples of its pixel. The value depends on the
    (pixel, triangle) pair alone, never on which samples it wins in the end, so the
    colour stage, the frame and the pixel history evaluate a pair alike. Runs in blocks of
    :data:`BLOCK` pixels (each row's values depend on that row alone).

    ``centroid`` = (centre covered (n,) bool, covered samples (n, S) bool or None for all):
    centroid sampling, where an uncovered centre moves to the covered sample nearest it
    (ties: lower index), and the values there are clamped to the vertex range.
    """
    values = np.empty((tables.value_lo.shape[0], len(tri)))
    depth = np.empty(len(tri))
    for a in range(0, len(tri), BLOCK):
        b = slice(a, a + BLOCK)
        part = None
        if centroid is not None:
            part = (centroid[0][b], None if centroid[1] is None else centroid[1][b])
        values[:, b], depth[b] = _shade_block(
            tables, tri[b], pixel[b], None if covers is None else covers[b], offsets, width, part
        )
    return values, depth


def _nearest_covered(offsets, covered):
    """Per row of ``covered`` (n, S) bool, the covered sample nearest the pixel centre
    (squared distance, ties to the lower index)."""
    d = offsets - 0.5
    order = np.argsort(d[:, 0] ** 2 + d[:, 1] ** 2, kind="stable")
    return order[np.argmax(covered[:, order], axis=1)]


def _shade_block(tables: ShadeTables, tri, pixel, covers, offsets, width, centroid):
    """:func:`shade` of one block."""
    row, col = np.divmod(pixel, width)
    x, y = col + 0.5, row + 0.5
    moved = None
    if centroid is not None:  # uncovered centres move to the nearest covered sample
        moved = ~centroid[0]
        if moved.any():
            cover = centroid[1]
            cover = np.ones((len(tri), len(offsets)), bool) if cover is None else cover
            s = _nearest_covered(offsets, cover[moved])
            x[moved], y[moved] = col[moved] + offsets[s, 0], row[moved] + offsets[s, 1]
    lam = barycentrics_at(tables, tri, x, y)
    persp = np.take(tables.perspective, tri)
    q = lam * np.take(tables.ratio, tri, axis=1)
    total = q[0] + q[1]
    total += q[2]
    inside = lam[0] >= 0
    inside &= lam[1] >= 0
    inside &= lam[2] >= 0
    bad = persp & ~inside & ~(total > 0)
    if moved is not None:  # already at a covered sample: clamped, like a covered centre
        bad &= ~moved
    if bad.any():  # the plane of 1/w crosses zero before the centre: use a covered sample
        if covers is None:
            covers = np.ones((len(tri), len(offsets)), dtype=bool)
        s = _nearest_covered(offsets, covers[bad])
        x[bad], y[bad] = col[bad] + offsets[s, 0], row[bad] + offsets[s, 1]
        lam[:, bad] = barycentrics_at(tables, tri[bad], x[bad], y[bad])
        q[:, bad] = lam[:, bad] * tables.ratio[:, tri[bad]]
        total[bad] = q[0, bad] + q[1, bad] + q[2, bad]
        inside = (lam[0] >= 0) & (lam[1] >= 0) & (lam[2] >= 0)
    if moved is not None:
        inside |= moved
    with np.errstate(divide="ignore", invalid="ignore"):  # rows fixed just below
        if persp.all():
            weights = np.divide(q, total, out=q)
        else:
            weights = np.where(persp, q / total, lam)
    under = persp & ~(total > 0)  # every term underflowed: the log-domain fallback
    if under.any():
        fallback = weights_per_row(np.maximum(lam[:, under], 0).T, tables.w[tri[under]])
        weights[:, under] = fallback.T
    values = _blend(weights, tri, tables.values, tables.value_scale, inside,
                    (tables.value_lo, tables.value_hi))  # fmt: skip
    depth = _blend(lam, tri, tables.depth, None, inside, (tables.depth_lo, tables.depth_hi))
    return values, depth[0]


def _blend(weights, tri, vertex, scale, clamp, bounds):
    """``Σ μ_i f_i`` (k, n) of weights (3, n) and per-vertex values ``vertex`` (3, k, M)
    (stored divided by ``2**scale`` where ``scale`` is not None); clamped to the vertex
    range ``bounds`` (lo, hi) where ``clamp``."""
    lo, hi = bounds
    with np.errstate(over="ignore", invalid="ignore"):  # near the float max: see ShadeTables
        out = weights[0] * np.take(vertex[0], tri, axis=1)
        out += weights[1] * np.take(vertex[1], tri, axis=1)
        out += weights[2] * np.take(vertex[2], tri, axis=1)
        if scale is not None:
            out = np.ldexp(out, np.take(scale, tri, axis=1))
    if clamp.all():
        np.maximum(out, np.take(lo, tri, axis=1), out=out)
        np.minimum(out, np.take(hi, tri, axis=1), out=out)
    elif clamp.any():
        c = np.maximum(out, np.take(lo, tri, axis=1))
        np.minimum(c, np.take(hi, tri, axis=1), out=c)
        np.copyto(out, c, where=clamp)
    return out
