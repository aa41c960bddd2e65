"""Multisampled rendering: coverage and depth per sample, shading once per pixel and triangle.

What a GPU does with MSAA, and what ``tr.render(..., samples=S)`` simulates:

1. **coverage per sample**: every sample of every pixel is tested against every triangle
   exactly like a pixel centre (:mod:`teachraster.core.multisample`); here the span tables
   of :mod:`teachraster.pipeline.batched_fill` run once per sample, one raster line per
   sample row, giving per (triangle, pixel row) one column interval per sample
   (:mod:`teachraster.pipeline.sample_coverage`);
2. **depth per sample**: each covered sample gets the triangle's depth at the sample point
   and is z-tested on its own (the buffer holds S depths per pixel);
3. **shading once per pixel and triangle**: the attributes of a triangle are evaluated once
   per pixel it covers, at the pixel centre (extrapolated when the centre lies outside),
   and written to every sample it wins (:mod:`teachraster.pipeline.sample_shading`);
4. **resolve**: the pixel's colour is the mean over its S samples, uncovered samples counting
   as the background (:meth:`~teachraster.pipeline.render_triangles.Frame.resolve`).

*Simulate only what the scene calls for*: in a pixel covered wholly by one triangle and
touched by no other, every sample has the same triangle, so no per-sample test is needed:
the intersection of a line's S sample intervals is such "full" pixels, and only the rest
(partly covered, or where another triangle might be in front in part of the pixel) is
expanded to samples. A full triangle whose depth is surely below every other's over the
pixel (first by the triangles' own depth ranges, then by the planes over the pixel square)
also takes the whole pixel.
Where samples are tested one by one, a triangle surely behind another at a sample is
dropped there, and a sample left with one triangle needs no depth at all. The
``multisampling`` effect of the plan says for how many pixels per-sample work ran;
``force`` expands every pixel, with the same frame (tests/test_render_msaa.py).

Like a GPU's compressed multisample surface, the frame keeps one triangle (and one
attribute value) per pixel decided whole and single samples only where they were tested:
:class:`SampleIds`, :class:`SampleDepths` and :class:`SampleAttributes` expand to the
(H, W, S) arrays when ``frame.sample_*`` is first read.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cache

import numpy as np

from ...core.edges import setup_edges
from ...core.multisample import offsets_in_units
from ..planning.render_plan import (
    attributes_effect,
    depth_test_effect,
    multisampling_effect,
    perspective_effect,
)
from ..rasterization.batched_fill import weight_source
from ..rasterization.sample_coverage import centre_covered, sample_fragments
from ..visibility.depth import quantize
from ..visibility.zbuffer import last_written, passed_on_arrival, resolve, surely_in_front
from .sample_shading import BLOCK, shade, shade_tables


def depth_planes(source, window) -> np.ndarray:
    """Per triangle (M, 7): origin x, y (source units), z there, dz/dx, dz/dy, min z, max z.

    Window depth is affine in screen space: one plane per triangle, evaluated relative to
    its vertex 0 (no large absolute products), from the same vertices as the barycentrics.
    """
    src, area, unit, _ = source
    z = window[:, :, 2]
    gx, gy = np.zeros(len(z)), np.zeros(len(z))
    for k in range(3):
        a, b = src[:, (k + 1) % 3], src[:, (k + 2) % 3]
        gx -= (b[:, 1] - a[:, 1]) * z[:, k]
        gy += (b[:, 0] - a[:, 0]) * z[:, k]
    with np.errstate(divide="ignore", invalid="ignore"):  # zero area: never covers anything
        gx, gy = gx / area, gy / area
    return np.stack([src[:, 0, 0], src[:, 0, 1], z[:, 0], gx, gy, z.min(1), z.max(1)], axis=1)


def plane_depth(planes, unit, tri, x, y) -> np.ndarray:
    """Depth of triangles ``tri`` (n,) at points (x, y) px, clamped to the vertices' range.

    ``x`` and ``y`` are (n,) or (n, S) (all S samples of one pixel: one gather per pixel,
    the same operations per sample, so the same bits as point by point).
    """
    c = np.take(planes.T, tri, axis=1)  # (7, n): one gather, each row contiguous
    if np.ndim(x) == 2:
        c = c[:, :, None]
    d = x * unit
    d -= c[0]
    d *= c[3]
    e = y * unit
    e -= c[1]
    e *= c[4]
    d += e
    d += c[2]  # z0 + gx (x - x0) + gy (y - y0), in this order everywhere
    np.maximum(d, c[5], out=d)
    np.minimum(d, c[6], out=d)
    return d


def whole_pixels(frags, planes, unit, size, depth_test, depth_format):
    """Pixels where one triangle shows at every sample without a per-sample test.

    A pixel qualifies when a triangle covers all its samples and either no other triangle
    reaches the pixel, or (depth test off, no partial coverage) it is the last drawn, or
    (depth test on) its stored depth at every sample is surely below every other
    triangle's there, partly covering ones included (:func:`_nearest_whole`).

    Returns the winner per pixel (-1: decide sample by sample) and whether 2+ triangles
    reach each pixel (n_pix,) bool.
    """
    width, height = size
    n_pix = width * height
    if depth_test:
        return _nearest_whole(frags, planes, unit, width, n_pix, depth_format)
    f_pix, f_tri = frags.full_pixel, frags.full_tri
    count = np.bincount(f_pix, minlength=n_pix)
    partial = np.bincount(frags.part_pixel, minlength=n_pix) > 0
    reached = (count + partial) > 1
    winner = np.full(n_pix, -1, dtype=np.int64)
    f_count, f_partial = count[f_pix], partial[f_pix]
    one = ~f_partial & (f_count == 1)
    winner[f_pix[one]] = f_tri[one]
    # without the depth test the last one drawn (highest index) wins at every sample
    many = np.flatnonzero(~f_partial & (f_count > 1))
    last = np.full(n_pix, -1, dtype=np.int64)
    np.maximum.at(last, f_pix[many], many)
    done = np.flatnonzero(last >= 0)
    winner[done] = f_tri[last[done]]
    return winner, reached


def _nearest_whole(frags, planes, unit, width, n_pix, depth_format):
    """With the depth test: per pixel, the full triangle surely nearest at every sample
    (-1: decide sample by sample), and whether another triangle reaches it (bool, valid
    where some triangle covers every sample).

    "Surely" first by each triangle's own depth range (the plane is clamped to its
    vertices' depths, so no sample of it lies outside them: one gather per fragment); the
    candidate is the full triangle with the smallest upper end (ties: the earlier), and it
    wins when that is below every other triangle's lower end there. Where that does not
    settle it, by the planes' ranges over the pixel square (:func:`_depth_range`). Both
    bounds are quantised like the stored depth, so every sample's test would agree.
    """
    f_pix, f_tri = frags.full_pixel, frags.full_tri
    if len(f_pix) == 0:  # no triangle covers every sample of any pixel
        return np.full(n_pix, -1, dtype=np.int64), np.zeros(n_pix, dtype=bool)
    m = len(planes)
    z_lo, z_hi = quantize(planes[:, 5], depth_format), quantize(planes[:, 6], depth_format)
    order = np.lexsort((np.arange(m), z_hi))  # by upper end, then drawing order
    rank = np.empty(m, dtype=np.int64)
    rank[order] = np.arange(m)
    best = np.full(n_pix, m, dtype=np.int64)
    np.minimum.at(best, f_pix, rank[f_tri])
    cand = np.r_[order, -1][best]  # -1: no triangle covers every sample
    rest = np.full(n_pix, np.inf)
    np.minimum.at(rest, f_pix, np.where(f_tri == cand[f_pix], np.inf, z_lo[f_tri]))
    np.minimum.at(rest, frags.part_pixel, z_lo[frags.part_tri])
    winner = np.where(surely_in_front(np.r_[z_hi, np.inf][cand], rest), cand, -1)  # -1: inf
    shared = rest < np.inf  # another triangle reaches the pixel (where one covers it all)
    # where the triangles' own depth ranges overlap: the planes over the pixel square
    left = (cand >= 0) & (winner < 0)
    sel, p_sel = np.flatnonzero(left[f_pix]), np.flatnonzero(left[frags.part_pixel])
    if len(sel):
        full = f_pix[sel], f_tri[sel]
        part = frags.part_pixel[p_sel], frags.part_tri[p_sel]
        still = np.flatnonzero(left)  # these pixels, numbered 0.. for small work arrays
        number = np.empty(len(left), dtype=np.int64)  # read only at these pixels
        number[still] = np.arange(len(still))
        full, part = (number[full[0]], full[1]), (number[part[0]], part[1])
        # a whole winner c needs every partial o with z_hi[o] >= (o's lower end over the
        # square) > (c's upper end) >= z_lo[c]: pixels where a partial triangle's range
        # lies below every full one's cannot be decided whole, and are left out here
        f_min, p_min = np.full(len(still), np.inf), np.full(len(still), np.inf)
        np.minimum.at(f_min, full[0], z_lo[full[1]])
        np.minimum.at(p_min, part[0], z_hi[part[1]])
        hope = p_min > f_min
        full = tuple(a[hope[full[0]]] for a in full)
        part = tuple(a[hope[part[0]]] for a in part)
        lo, hi = _depth_range(planes, unit, still[full[0]], full[1], width, depth_format)
        p_lo, _ = _depth_range(planes, unit, still[part[0]], part[1], width, depth_format)
        decided = np.full(len(still), -1, dtype=np.int64)
        _nearest(full, (lo, hi), part[0], p_lo, decided)
        winner[still] = decided
    return winner, shared


def _depth_range(planes, unit, pix, tri, width, depth_format):
    """Lower and upper bound of each plane's stored depth over its pixel square."""
    row, col = np.divmod(pix, width)
    c = planes[tri]
    tx, ty = c[:, 3] * ((col + 0.5) * unit - c[:, 0]), c[:, 4] * ((row + 0.5) * unit - c[:, 1])
    centre = c[:, 2] + tx + ty
    reach = 0.5 * unit * (np.abs(c[:, 3]) + np.abs(c[:, 4]))
    margin = 1e-12 * (1.0 + np.abs(tx) + np.abs(ty) + reach)
    lo = quantize(np.clip(centre - reach - margin, c[:, 5], c[:, 6]) - margin, depth_format)
    hi = quantize(np.clip(centre + reach + margin, c[:, 5], c[:, 6]) + margin, depth_format)
    return lo, hi


def _nearest(full, bounds, part_pixel, part_lo, winner):
    """Set ``winner`` where one whole triangle is surely nearer than all others in the pixel.

    ``full`` = (pixels, triangles) of fragments covering every sample of contested pixels,
    in drawing order, with lower and upper bounds ``bounds`` of their stored depths there;
    ``part_lo`` the lower bounds of the fragments covering only some samples (at
    ``part_pixel``). The candidate is the first full fragment (drawing order) with the
    smallest upper bound; it wins when that is below every other's lower bound.
    """
    n_pix = len(winner)
    pix, tri = full
    lo, hi = bounds
    best = np.full(n_pix, np.inf)
    np.minimum.at(best, pix, hi)
    index = np.arange(len(pix))
    first = np.full(n_pix, len(pix), dtype=np.int64)
    np.minimum.at(first, pix, np.where(hi == best[pix], index, len(pix)))
    rest = np.full(n_pix, np.inf)
    np.minimum.at(rest, pix, np.where(first[pix] == index, np.inf, lo))
    if len(part_pixel):
        np.minimum.at(rest, part_pixel, part_lo)
    done = np.flatnonzero(surely_in_front(best, rest))  # never for inf: not in this set
    winner[done] = tri[first[done]]


def owners(parents: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per pixel, the input triangle owning most samples (ties: the earlier) and a sample of it.

    ``parents`` (n, S) holds the input triangle id of each sample (-1 none). Returns the owner
    (n,) (-1 where no sample is covered) and the first sample (n,) it owns.

    >>> owners(np.array([[3, 1, 1, 3], [2, -1, -1, -1], [-1, -1, -1, -1]]))
    (array([ 1,  2, -1]), array([1, 0, 0]))
    """
    count = np.zeros(parents.shape, dtype=np.int64)  # samples of the same triangle
    for t in range(parents.shape[1]):
        count += parents == parents[:, t : t + 1]
    count[parents < 0] = 0
    best = count.max(axis=1, initial=0)
    big = np.iinfo(np.int64).max
    candidate = (count == best[:, None]) & (parents >= 0)
    owner = np.where(candidate, parents, big).min(axis=1, initial=big)
    owner = np.where(best > 0, owner, -1)
    first = np.argmax(parents == owner[:, None], axis=1)
    return owner, first


@dataclass(frozen=True)
class SampleIds:
    """The triangle each sample shows (H, W, S), built on first read
    (``Frame.sample_triangle_id``).

    Like a GPU's compressed multisample surface, the frame keeps one triangle per pixel
    decided whole (``winner`` (P,), -1 elsewhere) and the per-sample test's answers only at
    the samples it decided (``slots``: flat pixel * S + sample, ascending; ``tri``).
    ``parent`` maps triangles after clipping to input ids (None: the same ids).
    """

    shape: tuple
    winner: np.ndarray
    slots: np.ndarray
    tri: np.ndarray
    parent: np.ndarray | None = None

    def __call__(self) -> np.ndarray:
        out = np.repeat(self.winner, self.shape[-1])
        out[self.slots] = self.tri
        if self.parent is not None:  # -1 stays -1: index -1 reads the appended -1
            out = np.r_[self.parent, -1][out]
        return out.reshape(self.shape)


@dataclass(frozen=True)
class SampleDepths:
    """The per-sample depth buffer (H, W, S), filled on first use (``Frame.sample_depth``).

    At the samples the per-sample test decided (``slots``: flat pixel * S + sample) and at
    every sample of the pixels decided whole (``whole_pixel``, ``whole_tri``), the depth of
    the sample's triangle (``tri``) at the sample, evaluated and quantised exactly as the
    test does.
    """

    shape: tuple
    slots: np.ndarray
    tri: np.ndarray
    whole_pixel: np.ndarray
    whole_tri: np.ndarray
    planes: np.ndarray
    unit: float
    offsets: np.ndarray
    depth_format: str

    def __call__(self) -> np.ndarray:
        height, width, n_s = self.shape
        out = np.full((height * width, n_s), np.nan)
        pixel, sample = np.divmod(self.slots, n_s)
        args = (self.planes, self.unit, self.offsets, width, self.depth_format)
        out.reshape(-1)[self.slots] = _entry_depths(*args, self.tri, pixel, sample)
        ox, oy = self.offsets[:, 0], self.offsets[:, 1]
        for a in range(0, len(self.whole_pixel), BLOCK):  # blocks: temporaries stay in cache
            b = slice(a, a + BLOCK)
            wr, wc = np.divmod(self.whole_pixel[b], width)
            d = plane_depth(self.planes, self.unit, self.whole_tri[b], wc[:, None] + ox,
                            wr[:, None] + oy)  # fmt: skip
            if self.depth_format != "float64":  # float64 stores the value as it is
                d = quantize(d, self.depth_format)
            out[self.whole_pixel[b]] = d
        return out.reshape(self.shape)


@dataclass(frozen=True)
class SampleAttributes:
    """The attributes every sample holds (H, W, S, k), filled on first use
    (``Frame.sample_attrs``): one value per whole pixel for all its samples
    (``whole_pixel``, ``whole_values`` (k, n)), and at the other covered samples
    (``pixel``, ``sample``) the value of their (pixel, triangle) pair, ``values[:, pair]``."""

    shape: tuple
    whole_pixel: np.ndarray
    whole_values: np.ndarray
    pixel: np.ndarray
    sample: np.ndarray
    values: np.ndarray
    pair: np.ndarray

    def __call__(self) -> np.ndarray:
        height, width, n_s, k = self.shape
        one = np.full((height * width, 1, k), np.nan)  # one value per pixel, then S copies
        for j in range(k):
            one[self.whole_pixel, 0, j] = self.whole_values[j]
        out = np.repeat(one, n_s, axis=1)
        out[self.pixel, self.sample] = self.values.T[self.pair]
        return out.reshape(self.shape)


@dataclass(frozen=True)
class MultiFrame:
    """Per-sample and per-pixel results of a multisampled render (flat pixel arrays)."""

    sample_tri: SampleIds  # called: (H, W, S) triangle after clipping, -1 none
    sample_depth: SampleDepths  # called: (H, W, S)
    sample_attrs: SampleAttributes  # called: (H, W, S, k)
    owner: np.ndarray  # (P,) triangle after clipping owning most samples, -1 none
    attrs: np.ndarray  # (k, P): one contiguous row per channel
    depth: np.ndarray  # (P,)
    offsets: np.ndarray  # (S, 2) px as tested
    record: dict  # the per-sample depth-test entries and the whole pixels, for the trace
    passed: tuple | None = None  # blending: (slot, colour) of every sample that passed


def _sample_entries(frags, winner, n_s, n_tri):
    """Every covered sample of the pixels not decided whole: (triangle, pixel, sample,
    pair) by pixel, then drawing order (triangle index), then sample, so at each sample
    the entries arrive in drawing order, as the z-buffer needs; and the (pixel, triangle)
    pairs they come from, (triangle, pixel, sample mask) in that order (``pair`` indexes
    them)."""
    rest = np.flatnonzero(winner[frags.full_pixel] < 0)  # full fragments count S times
    part = np.flatnonzero(winner[frags.part_pixel] < 0)
    tri = np.concatenate([frags.full_tri[rest], frags.part_tri[part]])
    pixel = np.concatenate([frags.full_pixel[rest], frags.part_pixel[part]])
    mask = np.concatenate([np.full(len(rest), (1 << n_s) - 1), frags.part_mask[part]])
    order = np.argsort(pixel * n_tri + tri)
    tri, pixel, mask = tri[order], pixel[order], mask[order]
    covered = (mask[:, None] & (1 << np.arange(n_s))) != 0  # (pairs, S) row-major
    pair, sample = np.divmod(np.flatnonzero(covered), n_s)
    return (tri[pair], pixel[pair], sample, pair), (tri, pixel, mask)


@dataclass(frozen=True)
class SampleTests:
    """Every covered sample's depth test, in drawing order (kept when the frame blends or
    some triangle does not write depth: then no pixel is decided whole, and the colour
    stage reads these very decisions).

    ``slot`` (e,) flat pixel * S + sample of each entry (by pixel, then drawing order, then
    sample), ``pair`` (e,) its (pixel, triangle) pair, ``passed`` (e,) bool whether it
    passed on arrival, ``stored`` the entries whose depth the buffer keeps in the end (the
    last that passed and wrote, one per sample that holds a depth).
    """

    slot: np.ndarray
    pair: np.ndarray
    passed: np.ndarray
    stored: np.ndarray


def visibility(frags, planes, unit, offsets, size, options, forced, colour=(None, False)):
    """The depth buffer per sample: its triangles (:class:`SampleIds`) and depths
    (:class:`SampleDepths`), the whole pixels (flat index, triangle), the (pixel, triangle)
    pair that won each decided sample (an index into the pairs (triangle, pixel, sample
    mask) of the pixels decided sample by sample), the number of samples where 2+ triangles met, and
    the trace record.

    ``options`` is ``(depth_test, depth_format, trace)``: with ``trace`` every entry's
    depth and test is computed (and recorded); without, a sample only one triangle still
    reaches is decided without evaluating a depth (:func:`_decide_samples`). ``colour`` =
    (the triangles' depth masks (M,) or None for all writing, whether every sample's test
    is kept, :class:`SampleTests`, for blending): with either no pixel is decided whole and
    the last fragment that passed shows, the last that wrote keeps its depth. The last
    value returned is the :class:`SampleTests` (None when not kept).
    """
    depth_test, depth_format, trace = options
    force_test, force_ms = forced
    writes, keep = colour
    expand = writes is not None or keep  # every sample's test, in drawing order
    width, height = size
    n_s, n_pix = len(offsets), width * height
    if force_ms or expand:
        winner, reached = np.full(n_pix, -1, np.int64), None
    else:
        winner, reached = whole_pixels(frags, planes, unit, size, depth_test, depth_format)
    (tri, pixel, sample, pair), pairs = _sample_entries(frags, winner, n_s, len(planes))
    # the z-buffer over these pixels' samples only: pixels numbered 0.. in order
    p_pixel = pairs[1]  # the pairs' pixels, ascending
    new_pixel = np.r_[True, p_pixel[1:] != p_pixel[:-1]] if len(p_pixel) else p_pixel > 0
    still = p_pixel[new_pixel]
    cell = (np.cumsum(new_pixel) - 1)[pair] * n_s + sample
    entries = (tri, pixel, sample, cell, len(still) * n_s)
    every = (depth_test, depth_format, trace or force_test or expand)  # every entry tested
    writes = None if writes is None else writes[tri]
    won, met, depth, tests = _decide_samples(entries, planes, unit, offsets, width, every,
                                             (writes, expand))  # fmt: skip
    cells = np.flatnonzero(won >= 0)
    slots = still[cells // n_s] * n_s + cells % n_s  # flat pixel * S + sample, ascending
    won = won[cells]
    # whole pixels: their one triangle at every sample, no per-sample test (-1 elsewhere)
    sample_tri = SampleIds((height, width, n_s), winner, slots, tri[won])
    wp = np.flatnonzero(winner >= 0)
    if len(wp):  # a pixel decided whole that 2+ triangles reach: the test settled all of it
        met += n_s * int(np.count_nonzero(reached[wp]))
    depth_slots, depth_tri = slots, tri[won]
    if tests is not None:  # the buffer keeps the last written depth, not the last passed
        passed, stored = tests
        tests = SampleTests(pixel * n_s + sample, pair, passed, stored[stored >= 0])
        depth_slots, depth_tri = tests.slot[tests.stored], tri[tests.stored]
    depths = SampleDepths((height, width, n_s), depth_slots, depth_tri, wp, winner[wp], planes,
                          unit, offsets, depth_format)  # fmt: skip
    record = None
    if trace:
        record = {"tri": tri, "pixel": pixel, "sample": sample, "depth": depth,
                  "n_tri": len(planes), "depth_test": depth_test, "whole_pixel": wp,
                  "whole_tri": winner[wp]}  # fmt: skip
    return sample_tri, depths, (wp, winner[wp]), (pair[won], pairs), met, record, tests


def _entry_depths(planes, unit, offsets, width, depth_format, tri, pixel, sample):
    """The stored depth of triangles ``tri`` at samples ``sample`` of pixels ``pixel``."""
    row, col = np.divmod(pixel, width)
    x, y = col + offsets[sample, 0], row + offsets[sample, 1]
    depth = plane_depth(planes, unit, tri, x, y)
    if depth_format != "float64":  # float64 stores the value as it is
        depth = quantize(depth, depth_format)
    return depth


def _decide_samples(entries, planes, unit, offsets, width, options, colour=(None, False)):
    """The winning entry of every sample cell (-1: none), the cells 2+ entries reach,
    (with ``every``) every entry's stored depth (else None), and with ``colour`` = (depth
    masks per entry or None, keep) where either is given: every entry's test on arrival
    and per cell the entry whose depth the buffer keeps (``(passed, stored)``, else None;
    the winner is then the last entry that passed).

    ``entries`` = (tri, pixel, sample, cell, n_cells), drawing order within each cell. The
    rule is :func:`~teachraster.pipeline.zbuffer.resolve`'s. Without ``every`` it runs only
    where it can matter: with the depth test, an entry whose triangle's lowest stored depth
    lies above the highest of another entry's triangle in the same cell loses there for
    sure (the planes are clamped to their vertices' depths), and a cell left with one entry
    is that entry's, with no depth evaluated at all.
    """
    tri, pixel, sample, cell, n_cells = entries
    depth_test, depth_format, every = options
    args = (planes, unit, offsets, width, depth_format)
    writes, keep = colour
    if every:  # every entry tested (the trace records each test)
        depth = _entry_depths(*args, tri, pixel, sample)
        if writes is None and not keep:
            won, met = resolve(cell, depth, n_cells, depth_test)
            return won, met, depth, None
        met = int(np.count_nonzero(np.bincount(cell, minlength=n_cells) > 1))
        passed = passed_on_arrival(cell, depth, writes, depth_test)
        won, stored = last_written(cell, passed, writes, n_cells)
        return won, met, depth, (passed, stored)
    met = int(np.count_nonzero(np.bincount(cell, minlength=n_cells) > 1))
    keep = np.arange(len(cell))
    if depth_test:
        z_lo, z_hi = quantize(planes[:, 5], depth_format), quantize(planes[:, 6], depth_format)
        ceiling = np.full(n_cells, np.inf)
        np.minimum.at(ceiling, cell, z_hi[tri])
        keep = np.flatnonzero(~surely_in_front(ceiling[cell], z_lo[tri]))
    count = np.bincount(cell[keep], minlength=n_cells)
    won = np.full(n_cells, -1, dtype=np.int64)
    alone = count[cell[keep]] == 1
    won[cell[keep[alone]]] = keep[alone]
    test = keep[~alone]  # cells where 2+ entries may still win: the z-buffer decides
    depth = _entry_depths(*args, tri[test], pixel[test], sample[test])
    best, _ = resolve(cell[test], depth, n_cells, depth_test)
    hit = np.flatnonzero(best >= 0)
    won[hit] = test[best[hit]]
    return won, met, None, None


def shade_pixels(sample_tri, whole, decided, tables, frags, parent, offsets, size, flags):
    """Attributes per sample (once per pixel and triangle, a :class:`SampleAttributes`) and
    the owners' per-pixel values (owner, (k, P) attributes, depth) and the evaluations.

    ``sample_tri`` is the frame's :class:`SampleIds`, ``decided`` = (the pair that won each
    decided sample, the pairs (triangle, pixel, sample mask)) from :func:`visibility`.
    ``flags`` = (force "multisampling", force "attributes", the edge set-up for centroid
    sampling or None).
    """
    force_ms, force_attrs, centroid = flags
    width, height = size
    n_s, n_pix = len(offsets), width * height
    k = tables.value_lo.shape[0]
    owner = np.full(n_pix, -1, dtype=np.int64)
    pix_attrs, pix_depth = np.full((k, n_pix), np.nan), np.full(n_pix, np.nan)
    # simple pixels: one evaluation serves all samples
    sp, st = whole
    at_centroid = None if centroid is None else (centre_covered(centroid, st, sp, width), None)
    whole_vals, dep = shade(tables, st, sp, None, offsets, width, at_centroid)
    owner[sp], pix_attrs[:, sp], pix_depth[sp] = st, whole_vals, dep
    # the other covered pixels: one evaluation per (pixel, triangle) that won a sample
    won_pair, (pair_tri, pair_pixel, pair_mask) = decided
    slots = sample_tri.slots  # ascending
    bits = np.bincount(won_pair, weights=1 << (slots % n_s), minlength=len(pair_tri))
    shown = np.flatnonzero(bits)  # (pixel, triangle) order
    bits = bits[shown].astype(np.int64)  # the samples each shown pair won
    number = np.empty(len(pair_tri), dtype=np.int64)
    number[shown] = np.arange(len(shown))
    inverse = number[won_pair]  # each decided sample's pair among the shown
    tri, pix = pair_tri[shown], pair_pixel[shown]
    # the samples each triangle covers there: what its one evaluation may use (the pair's
    # own coverage, so every consumer evaluating a pair gets the same value)
    covers = _pair_covers(pair_mask[shown], n_s)
    at_centroid = None
    if centroid is not None:  # the centre test, and the samples each triangle covers
        at_centroid = (centre_covered(centroid, tri, pix, width), covers)
    if force_ms:  # every sample evaluates its own triangle: the same values, S times the work
        if at_centroid is not None:
            at_centroid = (at_centroid[0][inverse], at_centroid[1][inverse])
        vals, dep = shade(tables, sample_tri.tri, slots // n_s, covers[inverse], offsets, width,
                          at_centroid)  # fmt: skip
        first = np.full(len(shown), len(slots), dtype=np.int64)
        np.minimum.at(first, inverse, np.arange(len(slots)))
        sample_attrs = (vals, np.arange(len(slots)))
        vals, dep = vals[:, first], dep[first]
    else:
        vals, dep = shade(tables, tri, pix, covers, offsets, width, at_centroid)
        sample_attrs = (vals, inverse)
    sample_attrs = SampleAttributes((height, width, n_s, k), sp, whole_vals, slots // n_s,
                                    slots % n_s, *sample_attrs)  # fmt: skip
    if len(shown):
        others, own = _owners(pix, parent[tri], bits)
        owner[others] = tri[own]
        pix_attrs[:, others], pix_depth[others] = vals[:, own], dep[own]
    n_shaded = len(sp) + (len(slots) if force_ms else len(shown))
    if force_attrs:  # also every hidden (pixel, triangle): evaluated, then discarded
        m = len(tables.area)
        keys = np.unique(np.r_[frags.part_pixel * m + frags.part_tri,
                               frags.full_pixel * m + frags.full_tri])  # fmt: skip
        hidden_pix, hidden_tri = np.divmod(keys, m)
        won = sample_tri().reshape(n_pix, n_s)[hidden_pix] == hidden_tri[:, None]
        shade(tables, hidden_tri, hidden_pix, won, offsets, width)
        n_shaded += len(keys)
    return sample_attrs, owner, pix_attrs, pix_depth, n_shaded


def _pair_covers(pair_mask, n_s) -> np.ndarray:
    """(n, S) bool: the samples each (pixel, triangle) pair covers, from its bit mask."""
    return (pair_mask[:, None] & (1 << np.arange(n_s))) != 0


def passed_colours(tables, tests: SampleTests, pairs, offsets, width, centroid):
    """The colour stage's input under MSAA: every sample that passed the depth test (its
    slot, in drawing order within each) and the attributes of its (pixel, triangle) pair,
    evaluated once per pair exactly as the frame's ``sample_attrs`` (the same function on
    the same pair: the same bits). ``centroid`` is the edge set-up, or None."""
    pair_tri, pair_pixel, pair_mask = pairs
    used = np.flatnonzero(np.bincount(tests.pair[tests.passed], minlength=len(pair_tri)))
    tri, pix = pair_tri[used], pair_pixel[used]
    covers = _pair_covers(pair_mask[used], len(offsets))
    at_centroid = None
    if centroid is not None:
        at_centroid = (centre_covered(centroid, tri, pix, width), covers)
    values, _ = shade(tables, tri, pix, covers, offsets, width, at_centroid)
    number = np.empty(len(pair_tri), dtype=np.int64)
    number[used] = np.arange(len(used))
    entry = np.flatnonzero(tests.passed)
    return tests.slot[entry], values.T[number[tests.pair[entry]]]


def written_depth(tables, tests: SampleTests, pairs, parent, offsets, size, centroid):
    """Per pixel (P,), the depth the frame shows when some triangle does not write depth:
    of the triangles whose depth the pixel's samples keep, the one keeping most (ties: the
    earlier, as :func:`owners`), evaluated once for the pixel like the attributes; NaN
    where no sample holds a written depth."""
    pair_tri, pair_pixel, pair_mask = pairs
    n_s = len(offsets)
    width, height = size
    out = np.full(width * height, np.nan)
    kept = tests.pair[tests.stored]
    bits = np.bincount(kept, weights=1 << (tests.slot[tests.stored] % n_s),
                       minlength=len(pair_tri))  # fmt: skip
    held = np.flatnonzero(bits)  # (pixel, triangle) order
    if not len(held):
        return out
    pixels, own = _owners(pair_pixel[held], parent[pair_tri[held]], bits[held].astype(np.int64))
    pair = held[own]
    tri, pix = pair_tri[pair], pair_pixel[pair]
    covers = _pair_covers(pair_mask[pair], n_s)
    at_centroid = None
    if centroid is not None:
        at_centroid = (centre_covered(centroid, tri, pix, width), covers)
    _, out[pixels] = shade(tables, tri, pix, covers, offsets, width, at_centroid)
    return out


@cache
def _bit_tables() -> tuple[np.ndarray, np.ndarray]:
    """For every 16-bit sample mask: how many bits are set, and the lowest one (16 if none).

    >>> [table[[0, 1, 6, 8]].tolist() for table in _bit_tables()]
    [[0, 1, 2, 1], [16, 0, 1, 3]]
    """
    masks = np.arange(1 << 16)
    count = np.zeros(len(masks), dtype=np.int64)
    low = np.full(len(masks), 16, dtype=np.int64)
    for s in range(15, -1, -1):
        on = (masks >> s) & 1 == 1
        count += on
        low[on] = s
    return count, low


def _owners(pixel, parent, bits):
    """Per pixel, which (pixel, triangle) pair owns it: the input triangle (``parent``)
    showing at most of its samples (ties: the earlier), and of its pieces after clipping
    the one at its lowest sample, as :func:`owners` decides.

    ``pixel``, ``parent`` and ``bits`` (the samples each pair shows) are per pair, sorted by
    pixel and then triangle (so pieces of one input triangle are neighbours). Returns the
    pixels (ascending) and the owning pair of each.
    """
    count, low = _bit_tables()  # samples shown, and the lowest of them
    count, low = count[bits], low[bits]
    # (pixel, input triangle) groups: samples shown, and the pair at the lowest one
    starts = np.flatnonzero(np.r_[True, (pixel[1:] != pixel[:-1]) | (parent[1:] != parent[:-1])])
    size = np.diff(np.r_[starts, len(bits)])
    total = np.add.reduceat(count, starts)
    lowest = np.minimum.reduceat(low, starts)
    index = np.arange(len(bits))
    at = np.minimum.reduceat(np.where(low == np.repeat(lowest, size), index, len(bits)), starts)
    # per pixel, the group showing most samples; groups are in input-triangle order
    g_pixel = pixel[starts]
    firsts = np.flatnonzero(np.r_[True, g_pixel[1:] != g_pixel[:-1]])
    most = np.maximum.reduceat(total, firsts)
    group = np.arange(len(starts))
    best = np.where(total == np.repeat(most, np.diff(np.r_[firsts, len(starts)])), group,
                    len(starts))  # fmt: skip
    return g_pixel[firsts], at[np.minimum.reduceat(best, firsts)]


def _perspective_rows(w, interpolation: str, forced):
    """(M,) bool: the triangles shaded perspective-correctly (w unequal, or all when the
    plan forces "perspective"), none for affine interpolation; and whether it was forced."""
    divide_all = "perspective" in forced and interpolation == "perspective"
    perspective = np.ones(len(w), bool) if divide_all else ~np.all(w == w[:, :1], axis=1)
    if interpolation == "affine":
        perspective = np.zeros(len(w), bool)
    return perspective, divide_all


def pair_attributes(clipped, window, setup, options, tri, pixel, covers, width):
    """Attributes (n, k) of triangles ``tri`` shaded once for ``pixel`` exactly as the
    multisampled render shades a (pixel, triangle) pair; for frame debugging, which asks
    for the pairs the render did not keep (fragments hidden later at every sample).

    ``options`` = (interpolation, forced, offsets in px (S, 2), centroid); ``covers`` (n, S)
    bool: the samples each triangle covers in its pixel (where it would have shown).
    """
    interpolation, forced, px, centroid = options
    w = clipped.clip[:, :, 3]
    source = weight_source(window[:, :, :2], setup, snapped_weights=False)
    tables = shade_tables(
        source, window, w, clipped.attrs, _perspective_rows(w, interpolation, forced)[0]
    )
    at_centroid = (centre_covered(setup, tri, pixel, width), covers) if centroid else None
    values, _ = shade(tables, tri, pixel, covers, px, width, at_centroid)
    return values.T


def multisample_stage(clipped, window, culled, size, bits, offsets, options, forced,
                      colour=(None, False)):  # fmt: skip
    """Fill, depth-test and shade a multisampled frame: a :class:`MultiFrame` and its effects.

    ``options`` is ``(depth_test, depth_format, interpolation, trace, centroid)``;
    ``forced`` the plan's forced effects ("multisampling" expands every pixel to samples);
    ``colour`` = (depth masks per triangle or None for all writing, blending): with
    blending every sample that passed and its colour are handed on (``MultiFrame.passed``).
    """
    depth_test, depth_format, interpolation, trace, centroid = options
    width, height = size
    xy = window[:, :, :2]
    setup = setup_edges(xy, bits)
    live = (np.asarray(setup.original_area2) != 0) & ~culled
    units = offsets_in_units(offsets, setup)
    px = units.astype(np.float64) / float(setup.unit)
    force_ms = "multisampling" in forced
    frags = sample_fragments(setup, live, units, width, height, force_ms)
    source = weight_source(xy, setup, snapped_weights=False)
    planes = depth_planes(source, window)
    force_test = "depth_test" in forced and depth_test
    writes, blending = colour
    sample_tri, depths, whole, decided, contested, record, tests = visibility(
        frags,
        planes,
        source[2],
        px,
        size,
        (depth_test, depth_format, trace),
        (force_test, force_ms),
        colour,
    )
    w = clipped.clip[:, :, 3]
    perspective, divide_all = _perspective_rows(w, interpolation, forced)
    tables = shade_tables(source, window, w, clipped.attrs, perspective)
    sample_attrs, owner, attrs, depth, n_shaded = shade_pixels(
        sample_tri,
        whole,
        decided,
        tables,
        frags,
        clipped.parent,
        px,
        size,
        (force_ms, "attributes" in forced, setup if centroid else None),
    )
    at = setup if centroid else None
    if writes is not None:  # the depth a pixel shows is one that was written
        depth = written_depth(tables, tests, decided[1], clipped.parent, px, size, at)
    passed = passed_colours(tables, tests, decided[1], px, width, at) if blending else None
    if depth_format != "float64":  # float64 stores the value as it is
        depth = quantize(depth, depth_format)
    n_covered = int((owner >= 0).sum())
    n_samples = len(px) * len(whole[0]) + len(decided[0])
    n_per_sample = n_covered - len(whole[0])
    k = clipped.attrs.shape[2]
    shown = np.zeros(len(w), dtype=bool)  # the triangles some sample shows
    shown[whole[1]] = True
    shown[sample_tri.tri] = True
    n_persp = int(perspective[shown].sum())
    depth_effect = depth_test_effect(depth_test, force_test, contested, n_samples)
    why = depth_effect.why.replace("pixel(s)", "sample(s)").replace(
        "every fragment", "every sample"
    )
    effects = (
        replace(depth_effect, unit="samples", why=why),
        multisampling_effect(len(px), n_per_sample, n_covered, force_ms),
        perspective_effect(k, int(shown.sum()), n_persp, len(w), interpolation, divide_all),
        attributes_effect(k, n_shaded, frags.n_fragments, n_covered, "attributes" in forced),
    )
    multi = MultiFrame(sample_tri, depths, sample_attrs, owner, attrs, depth, px, record, passed)
    return multi, effects
