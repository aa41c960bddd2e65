"""Per-sample coverage of a whole batch of triangles, whole pixels kept whole.

The span tables of :mod:`teachraster.pipeline.batched_fill` run once per sample, one raster
line per sample row: per (triangle, pixel row) each sample s gets a column interval
``lo[s] <= j <= hi[s]``, decided exactly like a pixel centre (snapped edge functions, the
top-left rule, :func:`teachraster.core.span_tables.edge_bounds`). On the snapped grid the S
passes share everything but the sample's own offset: the per-line numbers of each edge are
gathered once, and each sample costs one floor division per edge.

From the S intervals of a line: columns in all of them (their intersection) are *full*
pixels, where the triangle covers every sample; the rest of their union is *partial*, kept
as one (pixel, triangle) pair with a bit mask of the samples it covers. Nothing is expanded
to single samples here; :mod:`teachraster.pipeline.multisampling` does that only where a
pixel's samples can differ.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.edges import passes
from .batched_fill import flat_ranges, line_bounds

#: Raster lines per block in the per-sample span pass (see :func:`sample_fragments`).
BLOCK = 16384


@dataclass(frozen=True)
class SampleFragments:
    """Per-sample coverage of a batch: whole pixels, and the others with their sample masks.

    Attributes
    ----------
    full_pixel, full_tri : (f,) int64
        (pixel, triangle) pairs where the triangle covers every sample of the pixel (flat
        pixel index, triangle index after clipping), in drawing order.
    part_pixel, part_tri : (p,) int64
        The (pixel, triangle) pairs covering some samples but not all (left parts of the
        lines, then right parts; nothing downstream depends on their order).
    part_mask : (p,) int64
        Their covered samples, bit s for sample s (never 0).
    n_samples : int
        S.
    """

    full_pixel: np.ndarray
    full_tri: np.ndarray
    part_pixel: np.ndarray
    part_tri: np.ndarray
    part_mask: np.ndarray
    n_samples: int

    @property
    def n_fragments(self) -> int:
        """(pixel, triangle) pairs covering at least one sample."""
        return len(self.full_pixel) + len(self.part_pixel)

    def part_samples(self, index=None) -> tuple[np.ndarray, np.ndarray]:
        """Partial pairs ``index`` (all if None) expanded: (pair, sample) per covered sample,
        pairs in the given order and samples ascending within each."""
        mask = self.part_mask if index is None else self.part_mask[index]
        bits = (mask[:, None] >> np.arange(self.n_samples)) & 1
        pair, sample = np.nonzero(bits)
        if index is not None:
            pair = np.asarray(index)[pair]
        return pair, sample


def _lines(setup, live, height):
    """Raster lines (owner, row): every pixel row whose square meets a triangle's y-range."""
    p, unit = setup.p, setup.unit
    ymin, ymax = p[:, :, 1].min(axis=1), p[:, :, 1].max(axis=1)
    # pixel rows whose square [i, i + 1) meets the y-range: every sample row lies in one
    if setup.exact:
        r0, r1 = ymin // unit, ymax // unit + 1
    else:
        r0, r1 = np.floor(ymin / unit), np.floor(ymax / unit) + 1
    r0 = np.clip(r0, 0, height).astype(np.int64)
    r1 = np.clip(r1, 0, height).astype(np.int64)
    r1 = np.where(live, np.maximum(r1, r0), r0)
    owner, rows = flat_ranges(r0, r1)
    return owner, rows, ymin[owner], ymax[owner]


def line_samples(setup, lines, units, width: int):
    """Each sample's column interval lo..hi (S, L) on ``lines`` (owner, row, ymin, ymax).

    ``hi < lo`` where the sample row misses the triangle (one row per sample, contiguous).
    Identical to running :func:`~teachraster.pipeline.batched_fill.line_bounds` once per
    sample (which the unsnapped, float path does); on the exact grid the S passes share
    their gathers.
    """
    owner, rows, ymin, ymax = lines
    lo = np.empty((len(units), len(rows)), dtype=np.int64)
    hi = np.empty_like(lo)
    if not setup.exact:
        for s, (ox, oy) in enumerate(units.tolist()):
            y = (rows * setup.unit + oy).astype(np.float64)
            l_s, h_s, ok = line_bounds(setup, owner, y, ox, width)
            ok &= (y >= ymin) & (y <= ymax)  # the sample row crosses the triangle
            lo[s], hi[s] = l_s, np.where(ok, h_s, l_s - 1)
        return lo, hi
    lo[:], hi[:] = 0, width - 1
    ok = np.ones(lo.shape, dtype=bool)
    for s, (_, oy) in enumerate(units.tolist()):  # the sample row crosses the triangle
        y = rows * setup.unit + oy
        ok[s] = (y >= ymin) & (y <= ymax)
    for k in range(3):
        _edge_samples(setup, k, owner, rows, units, (lo, hi, ok))
    np.putmask(hi, ~ok, lo - 1)
    return lo, hi


def _edge_samples(setup, k, owner, rows, units, out):
    """Narrow every sample's interval (lo, hi, ok: (S, L), in place) by oriented edge k.

    The exact branch of :func:`~teachraster.core.span_tables.edge_bounds`, with the
    per-line numbers computed once for all samples: on the row of sample s,
    E = dx (y_s - a.y) - dy (X - a.x) with y_s = row * unit + oy_s, and the test E >= bias
    (0 on a top-left edge, else 1: E > 0 on integers) gives, with one floor division
    q = (K - bias) // |dy| of K = dx (y_s - a.y), X - a.x <= q for an edge going down
    (an upper bound) and X - a.x >= -q for one going up (a lower bound).
    """
    lo, hi, ok = out
    p, unit = setup.p, setup.unit
    shift = int(unit).bit_length() - 1
    a, b = p[:, k], p[:, (k + 1) % 3]
    ax, ay = np.take(a[:, 0], owner), np.take(a[:, 1], owner)
    dx, dy = np.take(b[:, 0] - a[:, 0], owner), np.take(b[:, 1] - a[:, 1], owner)
    down, up, flat = dy > 0, dy < 0, dy == 0
    size = np.abs(dy)
    size[flat] = 1
    base = rows * unit - ay
    base *= dx
    base -= np.take(np.where(setup.top_left[:, k], 0, 1), owner)  # K - bias, without dx oy_s
    sign = np.where(up, -1, 1)
    # the column bound: floor((a.x + q - ox) / unit) going down, ceil((a.x - q - ox) / unit)
    # going up, both one arithmetic shift of a.x +- q - ox (+ unit - 1 for the ceiling)
    corner = ax + np.where(up, unit - 1, 0)
    any_flat = flat.any()
    for s, (ox, oy) in enumerate(units.tolist()):
        e = dx * oy
        e += base  # K - bias on the sample's row
        if any_flat:  # a horizontal edge keeps or drops its whole row
            ok[s] &= ~flat | (e >= 0)
        e //= size
        e *= sign
        e += corner
        e -= ox
        e >>= shift
        np.minimum(hi[s], e, out=hi[s], where=down)
        np.maximum(lo[s], e, out=lo[s], where=up)


def sample_fragments(setup, live, units, width: int, height: int, force: bool) -> SampleFragments:
    """Per-sample coverage of a batch of triangles, whole pixels kept whole.

    ``setup`` is the batch's edge set-up (window positions), ``live`` (M,) the triangles to
    draw, ``units`` (S, 2) the sample offsets on the internal grid. The columns where every
    sample's interval overlaps are *full* pixels; the rest of the union is kept with its
    sample masks. With ``force`` no pixel is taken as full. Lines are handled in blocks of
    :data:`BLOCK` (the work arrays stay in cache); full pixels stay in drawing order.
    """
    lines = _lines(setup, live, height)
    parts = []
    for a in range(0, max(len(lines[0]), 1), BLOCK):  # blocks: the work stays in cache
        block = tuple(x[a : a + BLOCK] for x in lines)
        lo, hi = line_samples(setup, block, units, width)
        parts.append(_line_fragments(block[0], block[1], lo, hi, width, force))
    return SampleFragments(*(np.concatenate(field) for field in zip(*parts)), len(units))


def _line_fragments(owner, rows, lo, hi, width: int, force: bool):
    """:func:`sample_fragments` of some lines: full (pixel, triangle), then partial
    (pixel, triangle, sample mask)."""
    covered = hi >= lo
    union_lo = np.where(covered, lo, width).min(axis=0, initial=width)
    union_hi = np.where(covered, hi, -1).max(axis=0, initial=-1)
    if force:
        full_lo, full_hi = np.zeros(len(rows), np.int64), np.full(len(rows), -1, np.int64)
    else:  # columns where every sample is covered: the intersection of the intervals
        full_lo, full_hi = lo.max(axis=0), hi.min(axis=0)
    has_full = full_hi >= full_lo
    start = rows * width  # flat pixel index of column 0 of each line
    full_tri, full_pixel = _runs(start + full_lo, start + np.where(has_full, full_hi + 1, 0), owner)
    # the rest of the union: left of the full part, and right of it
    left_stop = np.where(has_full, full_lo, union_hi + 1)
    right_lo = np.where(has_full, full_hi + 1, 0)
    right_stop = np.where(has_full, union_hi + 1, 0)
    line = np.arange(len(rows))
    l_line, l_col = _runs(union_lo, np.maximum(left_stop, union_lo), line)
    r_line, r_col = _runs(right_lo, np.maximum(right_stop, right_lo), line)
    p_line, p_col = np.concatenate([l_line, r_line]), np.concatenate([l_col, r_col])
    inside = np.take(lo, p_line, axis=1) <= p_col  # (S, p): each sample's interval
    inside &= p_col <= np.take(hi, p_line, axis=1)
    mask = _bits(inside)
    keep = np.flatnonzero(mask)  # the union may have gaps: those columns drop out
    p_line, p_col = p_line[keep], p_col[keep]
    return (full_pixel, full_tri, np.take(start, p_line) + p_col, np.take(owner, p_line),
            mask[keep])  # fmt: skip


def _runs(starts, stops, tags):
    """The integer runs [starts[i], stops[i]) flattened: (tags[i] per value, value)."""
    counts = np.maximum(stops - starts, 0)
    first = np.cumsum(counts) - counts  # where each run begins in the flat arrays
    values = np.arange(int(counts.sum()), dtype=np.int64)
    values += np.repeat(starts - first, counts)
    return np.repeat(tags, counts), values


def _bits(inside: np.ndarray) -> np.ndarray:
    """(S, p) bool to (p,) int64 masks, bit s set where row s is True (S <= 16).

    >>> _bits(np.array([[True, False], [True, True]])).tolist()
    [3, 2]
    """
    mask = inside[0].astype(np.uint16)  # narrow while building: less memory to stream
    for s in range(1, len(inside)):
        mask |= inside[s].astype(np.uint16) << np.uint16(s)
    return mask.astype(np.int64)


def centre_covered(setup, tri: np.ndarray, pixel: np.ndarray, width: int) -> np.ndarray:
    """(n,) bool: does triangle ``tri[i]`` cover the centre of flat pixel ``pixel[i]``?

    The exact centre test of the 1-sample fill (snapped edge functions, the top-left
    rule), for centroid sampling: a covered centre is where attributes are evaluated.
    """
    row, col = np.divmod(pixel, width)
    x, y = col * setup.unit + setup.half, row * setup.unit + setup.half
    covered = np.ones(len(tri), dtype=bool)
    for k in range(3):
        a, b = setup.p[tri, k], setup.p[tri, (k + 1) % 3]
        e = (b[:, 0] - a[:, 0]) * (y - a[:, 1]) - (b[:, 1] - a[:, 1]) * (x - a[:, 0])
        covered &= passes(e, setup.top_left[tri, k])
    return covered
