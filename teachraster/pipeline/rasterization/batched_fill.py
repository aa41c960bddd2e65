"""Many triangles at once: span tables vectorised across triangles and raster lines.

A scene of thousands of small triangles would spend its time in Python if each were
filled by its own call. Here every (triangle, raster line) pair is one entry of flat
arrays: the span of each line comes from the same exact :func:`edge_bounds` as the
span-table fill, so the pixels are identical to filling each triangle with
:func:`teachraster.rasterize`, and the work is proportional to lines + fragments rather
than to bounding-box area.

The fragments are generated once, as (triangle, row, column); what is *evaluated* at them
(barycentrics, a plane such as depth) is computed on demand and only where it is needed,
so a z-buffer can decide visibility before any attribute is touched.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ...core.bbox import centre_ranges
from ...core.edges import facing, setup_edges
from ...core.snapping import SUBPIXEL_BITS, check_bits
from ...core.span_tables import edge_bounds
from ...core.validate import as_bool, as_finite, as_size, check_pixels, short_repr


@dataclass(frozen=True)
class Fragments:
    """Pixel centres covered by a batch of triangles, in triangle order (drawing order).

    Attributes
    ----------
    tri : (m,) int64
        Index of the triangle (in the batch) that covers the pixel.
    row, col : (m,) int64
        The pixel.
    facing : (n,) int8
        Per triangle: +1 clockwise on screen (back-facing), -1 counter-clockwise
        (front-facing), 0 zero area.
    vertices : (n, 3, 2) float64
        The positions, in pixels, the weights are set up from (snapped, or the caller's
        unsnapped ones with ``snapped_weights=False``), in the caller's vertex order.
    area2 : (n,) float64
        E(v1, v2, v3) of ``vertices`` (twice the signed area, px²).

    ``lam`` (m, 3), the screen-space barycentrics of every fragment, is computed on first
    use; :meth:`weights` and :meth:`weights_at` evaluate them for a subset or at any
    point (a sample position, a helper pixel), :meth:`plane` interpolates per-vertex
    values affinely at every fragment.
    """

    tri: np.ndarray
    row: np.ndarray
    col: np.ndarray
    facing: np.ndarray
    vertices: np.ndarray
    area2: np.ndarray

    @cached_property
    def lam(self) -> np.ndarray:
        """(m, 3) barycentrics of vertices 0, 1, 2 at every fragment's pixel centre."""
        return self.weights()

    def weights(self, index=None) -> np.ndarray:
        """(len(index), 3) barycentrics at the centres of fragments ``index`` (all if None)."""
        if index is None:
            return self.weights_at(self.tri, self.col + 0.5, self.row + 0.5)
        return self.weights_at(self.tri[index], self.col[index] + 0.5, self.row[index] + 0.5)

    def weights_at(self, tri: np.ndarray, x: np.ndarray, y: np.ndarray, scale=None) -> np.ndarray:
        """(len(tri), 3) barycentrics of triangles ``tri`` at points (x, y) in pixels.

        Weight k (from 0: λ1, λ2, λ3) is E(a, b, p) / E(v1, v2, v3), a → b the edge opposite
        its vertex in walking order (vertex indices k+1, k+2 mod 3), for either winding;
        points outside the triangle get negative weights (extrapolation). With ``scale``
        (n, 3), weight k is E(a, b, p) * scale[tri, k] instead (per-triangle factors
        folded into the one pass, such as the perspective weights' 1/w, see
        :func:`teachraster.core.interpolation.normalised_weights`). The result is the
        transpose of a (3, len(tri)) array, so each weight's column is contiguous.
        """
        lam = np.empty((3, len(tri)))
        area = self.area2[tri] if scale is None else None
        for k, (ax, ay, dx, dy) in enumerate(self._edges):
            # E(a, b, p) = (b - a).x (p.y - a.y) - (b - a).y (p.x - a.x), for edge a = v_k+1,
            # b = v_k+2; one gather per per-triangle number (contiguous, cheap).
            e = y - ay[tri]
            e *= dx[tri]
            d = x - ax[tri]
            d *= dy[tri]
            e -= d
            if scale is None:
                np.divide(e, area, out=lam[k])
            else:
                np.multiply(e, np.ascontiguousarray(scale[:, k])[tri], out=lam[k])
        return lam.T

    @cached_property
    def _edges(self) -> tuple[tuple[np.ndarray, ...], ...]:
        """Per vertex k, the opposite edge a → b as contiguous (n,) arrays: a.x, a.y, dx, dy."""
        v = self.vertices
        out = []
        for k in range(3):
            a, b = v[:, (k + 1) % 3], v[:, (k + 2) % 3]
            out.append(tuple(np.ascontiguousarray(c) for c in (a[:, 0], a[:, 1], *(b - a).T)))
        return tuple(out)

    def plane(self, values: np.ndarray) -> np.ndarray:
        """(m,) per-vertex ``values`` (n, 3) interpolated affinely at every fragment.

        The plane ``f = f0 + A (x - x0) + B (y - y0)`` of each triangle is set up once
        (Fatahalian's matrix M, CMU 15-462 *Texture*) and moved to the pixel grid, ``f = C +
        A col + B row`` with ``C = f0 + A (0.5 - x0) + B (0.5 - y0)`` (as llvmpipe's set-up
        moves its planes to the origin: three gathers and two multiply-adds per fragment),
        then clamped to the vertex values' range (rounding cannot leave it, so depth stays
        in [0, 1]). Cheaper than barycentrics when only one quantity, such as depth, is
        needed.
        """
        v, f = self.vertices, np.asarray(values, dtype=np.float64)
        e1, e2 = v[:, 1] - v[:, 0], v[:, 2] - v[:, 0]
        d1, d2 = f[:, 1] - f[:, 0], f[:, 2] - f[:, 0]
        with np.errstate(divide="ignore", invalid="ignore"):  # zero area: no fragments
            A = (d1 * e2[:, 1] - d2 * e1[:, 1]) / self.area2
            B = (d2 * e1[:, 0] - d1 * e2[:, 0]) / self.area2
            C = f[:, 0] + A * (0.5 - v[:, 0, 0]) + B * (0.5 - v[:, 0, 1])
        t = self.tri
        out = A[t] * self.col
        out += B[t] * self.row
        out += C[t]
        # (np.minimum of the columns: a reduction over an axis of three is slow in numpy)
        np.maximum(out, np.minimum(np.minimum(f[:, 0], f[:, 1]), f[:, 2])[t], out=out)
        np.minimum(out, np.maximum(np.maximum(f[:, 0], f[:, 1]), f[:, 2])[t], out=out)
        return out


def flat_ranges(starts: np.ndarray, stops: np.ndarray):
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
    spans=None,
    max_pixels: int | None = None,
) -> Fragments:
    """Fragments of triangles ``xy`` (n, 3, 2) in window pixels; ``skip`` (n,) bool drops some.

    Coverage is always decided on the snapped grid. ``snapped_weights=False`` computes the
    barycentrics from the unsnapped positions instead, as OpenGL implementations such as
    llvmpipe do for attribute set-up (a triangle whose unsnapped area has a different sign
    or is zero keeps its snapped weights, which always exist where it covers a pixel).

    ``spans``, optional, sees the raster lines before they become fragments: called as
    ``spans(lines, counts)`` with ``lines`` a :class:`Fragments` whose ``tri``, ``row``,
    ``col`` are each line's triangle, row and first column and ``counts`` (L,) its pixels,
    it returns pieces of them in drawing order (``.tri``, ``.row``, ``.col``, ``.counts``);
    how :mod:`teachraster.pipeline.hiz_tiles` drops hidden blocks before they exist.

    Arguments are checked as :func:`teachraster.rasterize` checks them (errors name the
    argument; ``max_pixels`` bounds ``width * height``, 2**28 by default: a triangle
    covering the image makes one fragment per pixel).

    Two triangles splitting a 2×2 square: the shared diagonal's centres go to the triangle
    for which it is a top-left edge, so each pixel is covered exactly once.

    >>> f = rasterize_batch(np.array([[[0, 0], [2, 0], [0, 2]], [[2, 0], [2, 2], [0, 2]]]), 2, 2)
    >>> f.tri.tolist(), f.row.tolist(), f.col.tolist()
    ([0, 1, 1, 1], [0, 0, 1, 1], [0, 1, 0, 1])
    """
    xy, width, height, subpixel_bits, skip, snapped_weights = _checked(
        xy, width, height, subpixel_bits, skip, snapped_weights, max_pixels
    )
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
    owner, rows = flat_ranges(r0, r1)
    y = rows * unit + half
    if not exact:
        y = y.astype(np.float64)

    lo, hi, ok = line_bounds(setup, owner, y, half, width)
    counts = np.where(ok, np.maximum(hi - lo + 1, 0), 0)  # pixels on each line's span
    src, src_area, _, _ = weight_source(xy, setup, snapped_weights)
    fac, src_area = facing(area2), src_area.astype(np.float64)
    if spans is not None:  # the caller cuts spans before they become fragments (Hi-Z)
        cut = spans(Fragments(owner, rows, lo, fac, src, src_area), counts)
        owner, rows, lo, counts = cut.tri, cut.row, cut.col, cut.counts
    # One fragment per covered centre, generated once: column = lo + position in the span.
    first = np.cumsum(counts) - counts  # where each line's span starts in the flat arrays
    cols = np.arange(first[-1] + counts[-1] if len(counts) else 0)
    cols += np.repeat(lo - first, counts)
    tri = np.repeat(owner, counts)
    rows = np.repeat(rows, counts)
    return Fragments(tri, rows, cols, fac, src, src_area)


def _checked(xy, width, height, bits, skip, snapped_weights, max_pixels):
    """The arguments of :func:`rasterize_batch`, validated (errors name the argument)."""
    xy = as_finite("xy", xy, None)
    if xy.ndim not in (2, 3) or xy.shape[-2:] != (3, 2):
        raise ValueError(f"xy must have shape (n, 3, 2): three (x, y) per triangle, got {xy.shape}")
    xy = xy.reshape(-1, 3, 2)  # one triangle (3, 2) is a batch of one
    width, height = as_size("width", width), as_size("height", height)
    check_pixels(width, height, max_pixels, 24)  # a fragment: triangle, row, column
    if skip is not None:
        skip = np.asarray(skip)
        if skip.dtype != bool or skip.shape != (len(xy),):
            raise ValueError(
                f"skip must be a bool array of shape ({len(xy)},), got {short_repr(skip)}"
            )
    return (xy, width, height, check_bits(bits), skip,
            as_bool("snapped_weights", snapped_weights))  # fmt: skip


def line_bounds(setup, owner: np.ndarray, y: np.ndarray, half, width: int):
    """Column bounds of raster lines: lo, hi (int64) and ok (bool) per entry of ``owner``.

    ``setup`` is the batch's :func:`setup_edges`; line i belongs to triangle ``owner[i]`` and
    tests the points ``(j * unit + half, y[i])`` in internal units (``half`` the pixel
    centre's x offset, or a sample's, when multisampling). The span is ``lo <= j <= hi``
    where ``ok``. Lines outside a triangle's y-range are the caller's to drop.
    """
    p, unit, exact = setup.p, setup.unit, setup.exact
    lo = np.zeros(len(y), dtype=np.int64)
    hi = np.full(len(y), width - 1, dtype=np.int64)
    ok = np.ones(len(y), dtype=bool)
    # Every line applies all three edge tests: coverage is the intersection of the three
    # half-planes, so an edge whose y-range misses the line still bounds it correctly (on
    # the exact integer grid the answer is identical to an active edge table's).
    # Per-triangle numbers are gathered per line from contiguous 1-D arrays (indexing the
    # (n, 3, 2) block with two index arrays takes a slow path in numpy).
    corner = [[np.ascontiguousarray(p[:, k, c]) for c in (0, 1)] for k in range(3)]
    for k in range(3):
        # (L, 2) views of (2, L) arrays: each coordinate stays contiguous for edge_bounds.
        a = np.stack([corner[k][0][owner], corner[k][1][owner]]).T
        j = (k + 1) % 3
        b = np.stack([corner[j][0][owner], corner[j][1][owner]]).T
        top_left = np.ascontiguousarray(setup.top_left[:, k])[owner]
        e_lo, e_hi, e_ok, _ = edge_bounds(
            a, b, top_left, y, unit, half, exact,
            first_col=0, last_col=width - 1, crossings=False,
        )  # fmt: skip
        np.maximum(lo, e_lo, out=lo)
        np.minimum(hi, e_hi, out=hi)
        ok &= e_ok
    return lo, hi, ok


def weight_source(xy: np.ndarray, setup, snapped_weights: bool):
    """Vertices (n, 3, 2) px, area2 (n,) px², unit 1.0 and centre 0.5 for barycentrics.

    The snapped vertices in the caller's order (the orientation swap is its own inverse),
    or (``snapped_weights=False``) the unsnapped ones, as GPUs set up attributes; a triangle
    whose unsnapped area has another sign or is zero keeps its snapped weights.
    """
    p, unit, area2 = setup.p, setup.unit, np.asarray(setup.original_area2)
    snapped = np.take_along_axis(p, setup.perm[:, :, None], axis=1) / float(unit)
    src, src_area = snapped, area2 / float(unit) ** 2
    if not snapped_weights:
        (px, py), (qx, qy), (rx, ry) = (xy[:, k].T for k in range(3))
        raw_area = (qx - px) * (ry - py) - (qy - py) * (rx - px)
        usable = np.sign(raw_area) == np.sign(area2)
        src = np.where(usable[:, None, None], xy, snapped)
        src_area = np.where(usable, raw_area, src_area)
    return src, src_area.astype(np.float64), 1.0, 0.5
