"""Many triangles at once: span tables vectorised across triangles and raster lines.

A scene of thousands of small triangles would spend its time in Python if each were
filled by its own call. Here every (triangle, raster line) pair is one entry of flat
arrays: the span of each line comes from the same exact :func:`edge_bounds` as the
span-table fill, so the pixels are identical to filling each triangle with
:func:`teachraster.rasterize`, and the work is proportional to lines + fragments rather
than to bounding-box area.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.bbox import centre_ranges
from ..core.edges import facing, setup_edges
from ..core.snapping import SUBPIXEL_BITS
from ..core.span_tables import edge_bounds


@dataclass(frozen=True)
class Fragments:
    """Pixel centres covered by a batch of triangles, in triangle order.

    Attributes
    ----------
    tri : (m,) int64
        Index of the triangle (in the batch) that covers the pixel.
    row, col : (m,) int64
        The pixel.
    lam : (m, 3) float64
        Screen-space barycentrics of the triangle's vertices 0, 1, 2 (their order as given).
    facing : (n,) int8
        Per triangle: +1 clockwise on screen (back-facing), -1 counter-clockwise
        (front-facing), 0 zero area.
    """

    tri: np.ndarray
    row: np.ndarray
    col: np.ndarray
    lam: np.ndarray
    facing: np.ndarray


def _ranges(starts: np.ndarray, stops: np.ndarray):
    """Flatten the integer ranges [starts[i], stops[i]): (owner index, value) arrays."""
    counts = np.maximum(stops - starts, 0)
    owner = np.repeat(np.arange(len(counts)), counts)
    first = np.cumsum(counts) - counts  # where each range begins in the flat arrays
    values = np.repeat(starts, counts) + (np.arange(counts.sum()) - np.repeat(first, counts))
    return owner, values


def snapped_area2(xy: np.ndarray, subpixel_bits: int | None = SUBPIXEL_BITS) -> np.ndarray:
    """Twice the signed area of each snapped triangle (n,), in internal units².

    Positive when clockwise on screen (back-facing), negative when front-facing.
    """
    return np.asarray(setup_edges(np.asarray(xy, dtype=np.float64), subpixel_bits).original_area2)


def rasterize_batch(
    xy: np.ndarray,
    width: int,
    height: int,
    *,
    subpixel_bits: int | None = SUBPIXEL_BITS,
    skip: np.ndarray | None = None,
    snapped_weights: bool = True,
) -> Fragments:
    """Fragments of triangles ``xy`` (n, 3, 2) in window pixels; ``skip`` (n,) bool drops some.

    Coverage is always decided on the snapped grid. ``snapped_weights=False`` computes the
    barycentrics from the unsnapped positions instead, as OpenGL implementations such as
    llvmpipe do for attribute set-up (a triangle whose unsnapped area has a different sign
    or is zero keeps its snapped weights, which always exist where it covers a pixel).

    Two triangles splitting a 2×2 square: the shared diagonal's centres go to the triangle
    for which it is a top-left edge, so each pixel is covered exactly once.

    >>> f = rasterize_batch(np.array([[[0, 0], [2, 0], [0, 2]], [[2, 0], [2, 2], [0, 2]]]), 2, 2)
    >>> f.tri.tolist(), f.row.tolist(), f.col.tolist()
    ([0, 1, 1, 1], [0, 0, 1, 1], [0, 1, 0, 1])
    """
    xy = np.asarray(xy, dtype=np.float64).reshape(-1, 3, 2)
    # The same set-up as tr.rasterize, once for the whole batch: snapping, orientation
    # (inside on the positive side of every edge) and the top-left classification.
    setup = setup_edges(xy, subpixel_bits)
    unit, half, exact = setup.unit, setup.half, setup.exact
    area2 = np.asarray(setup.original_area2)
    p = setup.p
    live = area2 != 0
    if skip is not None:
        live &= ~skip

    # Raster lines per triangle: centres within the y-range, clipped to the image.
    r0, r1 = centre_ranges(p[:, :, 1].min(axis=1), p[:, :, 1].max(axis=1), setup, height)
    r1 = np.where(live, r1, r0)
    owner, rows = _ranges(r0, r1)
    y = rows * unit + half
    if not exact:
        y = y.astype(np.float64)

    lo = np.zeros(len(rows), dtype=np.int64)
    hi = np.full(len(rows), width - 1, dtype=np.int64)
    ok = np.ones(len(rows), dtype=bool)
    for k in range(3):
        a, b = p[owner, k], p[owner, (k + 1) % 3]
        top_left = setup.top_left[owner, k]
        # Each edge bounds the lines its closed y-range contains (an active edge table).
        active = (y >= np.minimum(a[:, 1], b[:, 1])) & (y <= np.maximum(a[:, 1], b[:, 1]))
        if not exact:  # raw floats: all three tests on every line (see span_tables.fill)
            active[:] = True
        e_lo, e_hi, e_ok, _ = edge_bounds(
            a, b, top_left, y, unit, half, exact, first_col=0, last_col=width - 1
        )
        lo = np.where(active, np.maximum(lo, e_lo), lo)
        hi = np.where(active, np.minimum(hi, e_hi), hi)
        ok &= ~active | e_ok
    counts = np.where(ok, np.maximum(hi - lo + 1, 0), 0)  # pixels on each line's span
    within = np.arange(counts.sum()) - np.repeat(np.cumsum(counts) - counts, counts)
    tri = np.repeat(owner, counts)
    cols = np.repeat(lo, counts) + within
    line_rows, rows = rows, np.repeat(rows, counts)

    # Barycentrics from the exact edge functions, in the caller's vertex order: weight k is
    # E(v_k+1, v_k+2, p) / E(v0, v1, v2), which holds for either winding. Along a span E
    # changes by -dy per unit of x, so it is evaluated once at the span's start and then
    # stepped (*Triangle Rasterisation II - Interpolation*'s incremental form); on the snapped grid the steps are exact
    # integers, so this is the same value as evaluating E at every pixel.
    lam = np.empty((len(tri), 3))
    # The snapped vertices in the caller's order (the orientation swap is its own inverse).
    v = np.take_along_axis(p, setup.perm[:, :, None], axis=1)
    src, src_unit, src_half, src_area = v, unit, half, area2
    if not snapped_weights:
        raw = np.asarray(xy, dtype=np.float64)
        (px, py), (qx, qy), (rx, ry) = (raw[:, k].T for k in range(3))
        raw_area = (qx - px) * (ry - py) - (qy - py) * (rx - px)
        usable = np.sign(raw_area) == np.sign(area2)
        src = np.where(usable[:, None, None], raw, v / float(unit))
        src_area = np.where(usable, raw_area, area2 / float(unit) ** 2)
        src_unit, src_half = 1.0, 0.5
    start_x = lo * src_unit + src_half
    row_y = line_rows * src_unit + src_half
    area = np.repeat(src_area[owner], counts).astype(np.float64)
    for k in range(3):
        a, b = src[owner, (k + 1) % 3], src[owner, (k + 2) % 3]
        dx, dy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
        e_start = dx * (row_y - a[:, 1]) - dy * (start_x - a[:, 0])
        e = np.repeat(e_start, counts) - np.repeat(dy * src_unit, counts) * within
        np.divide(e, area, out=lam[:, k])
    return Fragments(tri=tri, row=rows, col=cols, lam=lam, facing=facing(area2))
