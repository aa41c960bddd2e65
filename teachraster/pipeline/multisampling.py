"""Multisampled rendering: coverage and depth per sample, shading once per pixel and triangle.

What a GPU does with MSAA, and what ``tr.render(..., samples=S)`` simulates:

1. **coverage per sample**: every sample of every pixel is tested against every triangle
   exactly like a pixel centre (:mod:`teachraster.core.multisample`); here the span tables
   of :mod:`teachraster.pipeline.batched_fill` run once per sample, one raster line per
   sample row, giving per (triangle, pixel row) one column interval per sample;
2. **depth per sample**: each covered sample gets the triangle's depth at the sample point
   and is z-tested on its own (the buffer holds S depths per pixel);
3. **shading once per pixel and triangle**: the attributes of a triangle are evaluated once
   per pixel it covers, at the pixel centre (extrapolated when the centre lies outside),
   and written to every sample it wins;
4. **resolve**: the pixel's colour is the mean over its S samples, uncovered samples counting
   as the background (:meth:`~teachraster.pipeline.render_triangles.Frame.resolve`).

*Simulate only what the scene calls for*: in a pixel covered wholly by one triangle and
touched by no other, every sample has the same triangle, so no per-sample test is needed:
the intersection of a line's S sample intervals is such "full" pixels, and only the rest
(partly covered, or reached by two or more triangles) is expanded to samples. The
``multisampling`` effect of the plan says for how many pixels that ran; ``force`` expands
every pixel, with the same frame (tests/test_render_msaa.py).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core.edges import setup_edges
from ..core.interpolation import blend_each, weights_per_row
from ..core.multisample import offsets_in_units
from .batched_fill import flat_ranges, line_bounds, weight_source
from .depth import quantize
from .render_plan import (
    attributes_effect,
    depth_test_effect,
    multisampling_effect,
    perspective_effect,
)
from .zbuffer import resolve


@dataclass(frozen=True)
class SampleFragments:
    """Per-sample coverage of a batch, as whole pixels where possible.

    Attributes
    ----------
    full_pixel, full_tri : (f,) int64
        (pixel, triangle) pairs where the triangle covers every sample of the pixel (flat
        pixel index, triangle index after clipping), in drawing order.
    tri, pixel, sample : (m,) int64
        Every covered sample of the other (pixel, triangle) pairs.
    n_fragments : int
        (pixel, triangle) pairs covering at least one sample.
    """

    full_pixel: np.ndarray
    full_tri: np.ndarray
    tri: np.ndarray
    pixel: np.ndarray
    sample: np.ndarray
    n_fragments: int


def _sample_lines(setup, live, units, width, height):
    """Raster lines (owner, row) and each sample's column interval lo..hi (L, S)."""
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
    lo = np.empty((len(rows), len(units)), dtype=np.int64)
    hi = np.empty_like(lo)
    for s, (ox, oy) in enumerate(units.tolist()):
        y = rows * unit + oy
        if not setup.exact:
            y = y.astype(np.float64)
        l_s, h_s, ok = line_bounds(setup, owner, y, ox, width)
        ok &= (y >= ymin[owner]) & (y <= ymax[owner])  # the sample row crosses the triangle
        lo[:, s], hi[:, s] = l_s, np.where(ok, h_s, l_s - 1)
    return owner, rows, lo, hi


def sample_fragments(setup, live, units, width: int, height: int, force: bool) -> SampleFragments:
    """Per-sample coverage of a batch of triangles, whole pixels kept whole.

    ``setup`` is the batch's edge set-up (window positions), ``live`` (M,) the triangles to
    draw, ``units`` (S, 2) the sample offsets on the internal grid. The columns where every
    sample's interval overlaps are *full* pixels; the rest of the union is expanded to
    samples. With ``force`` no pixel is taken as full.
    """
    owner, rows, lo, hi = _sample_lines(setup, live, units, width, height)
    covered = hi >= lo
    union_lo = np.where(covered, lo, width).min(axis=1, initial=width)
    union_hi = np.where(covered, hi, -1).max(axis=1, initial=-1)
    if force:
        full_lo, full_hi = np.zeros(len(rows), np.int64), np.full(len(rows), -1, np.int64)
    else:  # columns where every sample is covered: the intersection of the intervals
        full_lo, full_hi = lo.max(axis=1), hi.min(axis=1)
    has_full = full_hi >= full_lo
    f_line, f_col = flat_ranges(full_lo, np.where(has_full, full_hi + 1, full_lo))
    # the rest of the union: left of the full part, and right of it
    left_stop = np.where(has_full, full_lo, union_hi + 1)
    right_lo = np.where(has_full, full_hi + 1, 0)
    right_stop = np.where(has_full, union_hi + 1, 0)
    l_line, l_col = flat_ranges(union_lo, np.maximum(left_stop, union_lo))
    r_line, r_col = flat_ranges(right_lo, np.maximum(right_stop, right_lo))
    p_line, p_col = np.concatenate([l_line, r_line]), np.concatenate([l_col, r_col])
    mask = (lo[p_line] <= p_col[:, None]) & (p_col[:, None] <= hi[p_line])
    e_frag, e_sample = np.nonzero(mask)  # the union may have gaps: empty rows drop out
    tri, pix = owner[p_line[e_frag]], rows[p_line[e_frag]] * width + p_col[e_frag]
    return SampleFragments(
        full_pixel=rows[f_line] * width + f_col,
        full_tri=owner[f_line],
        tri=tri,
        pixel=pix,
        sample=e_sample.astype(np.int64),
        n_fragments=len(f_line) + int(mask.any(axis=1).sum()),
    )


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
    (depth test on) its depth over the whole pixel square lies strictly below every other
    triangle's there, partly covering ones included (bounded by the plane's slope, after
    quantisation: every sample's test would agree). Returns the winner per pixel (-1: decide
    sample by sample).
    """
    width, height = size
    n_pix = width * height
    f_pix, f_tri = frags.full_pixel, frags.full_tri
    count = np.bincount(f_pix, minlength=n_pix)
    partial = np.bincount(frags.pixel, minlength=n_pix) > 0
    winner = np.full(n_pix, -1, dtype=np.int64)
    one = ~partial[f_pix] & (count[f_pix] == 1)
    winner[f_pix[one]] = f_tri[one]
    if not depth_test:  # the last one drawn (highest index) wins at every sample
        many = np.flatnonzero(~partial[f_pix] & (count[f_pix] > 1))
        last = np.full(n_pix, -1, dtype=np.int64)
        np.maximum.at(last, f_pix[many], many)
        done = np.flatnonzero(last >= 0)
        winner[done] = f_tri[last[done]]
        return winner
    contested = np.flatnonzero(partial[f_pix] | (count[f_pix] > 1))
    if len(contested):  # per-pixel reductions by ufunc.at: no sort by pixel needed
        hidden = np.flatnonzero(count[frags.pixel] > 0)  # partial entries beside a full one
        _nearest_everywhere(planes, unit, (f_pix[contested], f_tri[contested]),
                            (frags.pixel[hidden], frags.tri[hidden]), width, depth_format,
                            winner)  # fmt: skip
    return winner


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


def _nearest_everywhere(planes, unit, full, partial, width, depth_format, winner):
    """Set ``winner`` where one whole triangle is nearer than all others over the pixel.

    ``full`` = (pixels, triangles) of fragments covering every sample of contested pixels,
    in drawing order; ``partial`` = the same for entries covering only some samples there.
    Each plane's range over the pixel square is its centre value ± half the slopes; a margin
    covers the rounding of the per-sample evaluation; quantising both ends keeps the order
    every sample's test would see. The candidate is the first full fragment (drawing order)
    with the smallest upper end; it wins when that is below every other's lower end.
    """
    n_pix = len(winner)
    pix, tri = full
    lo, hi = _depth_range(planes, unit, pix, tri, width, depth_format)
    best = np.full(n_pix, np.inf)
    np.minimum.at(best, pix, hi)
    index = np.arange(len(pix))
    first = np.full(n_pix, len(pix), dtype=np.int64)
    np.minimum.at(first, pix, np.where(hi == best[pix], index, len(pix)))
    rest = np.full(n_pix, np.inf)
    np.minimum.at(rest, pix, np.where(first[pix] == index, np.inf, lo))
    if len(partial[0]):
        p_lo, _ = _depth_range(planes, unit, *partial, width, depth_format)
        np.minimum.at(rest, partial[0], p_lo)
    done = np.flatnonzero(best < rest)  # inf < inf is False for pixels not in this set
    winner[done] = tri[first[done]]


def barycentrics_at(source, tri: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Barycentrics (n, 3) of triangles ``tri`` at points (x, y) in pixels, any point.

    ``source`` is :func:`~teachraster.pipeline.batched_fill.weight_source`'s answer: the
    same vertices and areas the batched fill uses, evaluated directly at the point.
    """
    src, src_area, src_unit, _ = source
    px, py = x * src_unit, y * src_unit
    lam = np.empty((len(tri), 3))
    area = src_area[tri].astype(np.float64)
    v = src[tri]  # one gather of the three vertices
    for k in range(3):
        a, b = v[:, (k + 1) % 3], v[:, (k + 2) % 3]
        dx, dy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
        lam[:, k] = (dx * (py - a[:, 1]) - dy * (px - a[:, 0])) / area
    return lam


def shade(source, window, w, attrs, tri, pixel, won, offsets, width, perspective):
    """Attributes (n, k) and depth (n,) of ``tri`` evaluated once for ``pixel``.

    At the pixel centre, extrapolated on the triangle's planes when the centre lies
    outside (values may leave the vertex range; inside they are clamped to it, as at
    covered centres). Where the extrapolated 1/w would be <= 0, at the sample nearest the
    centre among ``won`` (n, S) bool, the samples the triangle shows in that pixel (ties:
    lower index). ``perspective`` (M,) bool: divide by w.
    """
    row, col = np.divmod(pixel, width)
    x, y = col + 0.5, row + 0.5
    lam = barycentrics_at(source, tri, x, y)
    wt = w[tri]
    persp = perspective[tri]
    q = lam * (wt.min(axis=1, keepdims=True) / wt)
    total = q[:, 0] + q[:, 1] + q[:, 2]
    inside = (lam[:, 0] >= 0) & (lam[:, 1] >= 0) & (lam[:, 2] >= 0)
    bad = persp & ~inside & ~(total > 0)
    if bad.any():  # the plane of 1/w crosses zero before the centre: use a covered sample
        d = offsets - 0.5
        order = np.argsort(d[:, 0] ** 2 + d[:, 1] ** 2, kind="stable")
        s = order[np.argmax(won[bad][:, order], axis=1)]
        x, y = x.astype(np.float64), y.astype(np.float64)
        x[bad], y[bad] = col[bad] + offsets[s, 0], row[bad] + offsets[s, 1]
        lam[bad] = barycentrics_at(source, tri[bad], x[bad], y[bad])
        q[bad] = lam[bad] * (wt[bad].min(axis=1, keepdims=True) / wt[bad])
        total[bad] = q[bad, 0] + q[bad, 1] + q[bad, 2]
        inside = (lam[:, 0] >= 0) & (lam[:, 1] >= 0) & (lam[:, 2] >= 0)
    with np.errstate(divide="ignore", invalid="ignore"):  # rows fixed just below
        weights = np.where(persp[:, None], q / total[:, None], lam)
    under = persp & ~(total > 0)  # every term underflowed: the log-domain fallback
    if under.any():
        weights[under] = weights_per_row(np.maximum(lam[under], 0), wt[under])
    values = _blend(weights, attrs[tri], inside)
    depth = _blend(lam, window[tri, :, 2:3], inside)[:, 0]
    return values, depth


def _blend(weights, values, clamp):
    """``Σ μ_i f_i`` per row, values (n, 3, k); clamped to the vertex range where ``clamp``."""
    v0, v1, v2 = values[:, 0], values[:, 1], values[:, 2]
    out = blend_each(weights, values, extrapolate=True)  # no inf - inf near the float max
    lo = np.minimum(np.minimum(v0, v1), v2)
    hi = np.maximum(np.maximum(v0, v1), v2)
    return np.where(clamp[:, None], np.minimum(np.maximum(out, lo), hi), out)


def _distinct(sub: np.ndarray, i: np.ndarray, s: np.ndarray):
    """One entry per distinct triangle of each row of ``sub`` (n, S).

    ``(i, s)`` enumerate the entries ``sub >= 0`` row-major. Returns ``first`` (positions in
    that enumeration of each row's first sample of a triangle) and ``inverse`` (for every
    entry, the index in ``first`` of its triangle's first sample).
    """
    lead = np.argmax(sub[:, :, None] == sub[:, None, :], axis=2)  # (n, S): first same sample
    slot = np.full(sub.shape, -1, dtype=np.int64)
    slot[i, s] = np.arange(len(i))
    is_first = lead[i, s] == s
    first = np.flatnonzero(is_first)
    number = np.full(len(i), -1, dtype=np.int64)
    number[first] = np.arange(len(first))
    inverse = number[slot[i, lead[i, s]]]
    return first, inverse


def owners(parents: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per pixel, the input triangle owning most samples (ties: the earlier) and a sample of it.

    ``parents`` (n, S) holds the input triangle id of each sample (-1 none). Returns the owner
    (n,) (-1 where no sample is covered) and the first sample (n,) it owns.

    >>> owners(np.array([[3, 1, 1, 3], [2, -1, -1, -1], [-1, -1, -1, -1]]))
    (array([ 1,  2, -1]), array([1, 0, 0]))
    """
    count = (parents[:, :, None] == parents[:, None, :]).sum(axis=2)
    count = np.where(parents >= 0, count, 0)
    best = count.max(axis=1, initial=0)
    big = np.iinfo(np.int64).max
    candidate = (count == best[:, None]) & (parents >= 0)
    owner = np.where(candidate, parents, big).min(axis=1, initial=big)
    owner = np.where(best > 0, owner, -1)
    first = np.argmax(parents == owner[:, None], axis=1)
    return owner, first


@dataclass(frozen=True)
class MultiFrame:
    """Per-sample and per-pixel results of a multisampled render (flat pixel arrays)."""

    sample_tri: np.ndarray  # (P, S) triangle after clipping, -1 none
    sample_depth: np.ndarray  # (P, S)
    sample_attrs: np.ndarray  # (P, S, k)
    owner: np.ndarray  # (P,) triangle after clipping owning most samples, -1 none
    attrs: np.ndarray  # (P, k)
    depth: np.ndarray  # (P,)
    offsets: np.ndarray  # (S, 2) px as tested
    record: dict  # the per-sample depth-test entries and the whole pixels, for the trace


def visibility(frags, planes, unit, offsets, size, options, forced):
    """The depth buffer per sample: (P, S) triangle and stored depth, the whole pixels
    (flat index, triangle) and the number of samples where 2+ triangles met."""
    depth_test, depth_format = options
    _, force_ms = forced  # the one-pass z-buffer does the same work forced or not
    width, height = size
    n_s, n_pix = len(offsets), width * height
    if force_ms:
        winner = np.full(n_pix, -1, np.int64)
    else:
        winner = whole_pixels(frags, planes, unit, size, depth_test, depth_format)
    # every covered sample of the other pixels (full fragments count S times)
    rest = np.flatnonzero(winner[frags.full_pixel] < 0)
    keep = np.flatnonzero(winner[frags.pixel] < 0)
    tri = np.concatenate([np.repeat(frags.full_tri[rest], n_s), frags.tri[keep]])
    pixel = np.concatenate([np.repeat(frags.full_pixel[rest], n_s), frags.pixel[keep]])
    sample = np.concatenate([np.tile(np.arange(n_s), len(rest)), frags.sample[keep]])
    # grouped by sample slot, drawing order (triangle index) inside each: the z-buffer's order
    order = np.argsort((pixel * n_s + sample) * len(planes) + tri)
    tri, pixel, sample = tri[order], pixel[order], sample[order]
    row, col = np.divmod(pixel, width)
    x, y = col + offsets[sample, 0], row + offsets[sample, 1]
    depth = quantize(plane_depth(planes, unit, tri, x, y), depth_format)
    slot = pixel * n_s + sample
    won, _ = resolve(slot, depth, n_pix * n_s, depth_test)
    sample_tri = np.full(n_pix * n_s, -1, dtype=np.int64)
    sample_depth = np.full(n_pix * n_s, np.nan)
    hit = np.flatnonzero(won >= 0)
    sample_tri[hit], sample_depth[hit] = tri[won[hit]], depth[won[hit]]
    # whole pixels: their one triangle at every sample, no per-sample test
    wp = np.flatnonzero(winner >= 0)
    wr, wc = np.divmod(wp, width)
    sample_tri = sample_tri.reshape(n_pix, n_s)
    sample_depth = sample_depth.reshape(n_pix, n_s)
    sample_tri[wp] = winner[wp][:, None]
    sample_depth[wp] = quantize(
        plane_depth(planes, unit, winner[wp], wc[:, None] + offsets[:, 0],
                    wr[:, None] + offsets[:, 1]), depth_format,
    )  # fmt: skip
    met = int(np.count_nonzero(np.bincount(slot) > 1))
    reached = np.bincount(frags.full_pixel, minlength=n_pix) + (
        np.bincount(frags.pixel, minlength=n_pix) > 0
    )  # a pixel decided whole that 2+ triangles reach: the test settled all its samples
    met += n_s * int(np.count_nonzero(reached[wp] > 1))
    record = {"tri": tri, "pixel": pixel, "sample": sample, "depth": depth, "slot": slot,
              "depth_test": depth_test, "whole_pixel": wp, "whole_tri": winner[wp]}  # fmt: skip
    return sample_tri, sample_depth, (wp, winner[wp]), met, record


def shade_pixels(sample_tri, whole, frags, source, window, clipped, offsets, size, flags):
    """Attributes per sample (once per pixel and triangle) and the owners' per-pixel values."""
    force_ms, force_attrs, perspective = flags
    width, _ = size
    n_pix, n_s = sample_tri.shape
    w, attrs, parent = clipped.clip[:, :, 3], clipped.attrs, clipped.parent
    k = attrs.shape[2]
    out_attrs = np.full((n_pix, n_s, k), np.nan)
    owner = np.full(n_pix, -1, dtype=np.int64)
    pix_attrs, pix_depth = np.full((n_pix, k), np.nan), np.full(n_pix, np.nan)
    args = (source, window, w, attrs)
    # simple pixels: one evaluation serves all samples
    sp, st = whole
    vals, dep = shade(*args, st, sp, np.ones((len(sp), n_s), bool), offsets, width, perspective)
    out_attrs[sp] = vals[:, None, :]
    owner[sp], pix_attrs[sp], pix_depth[sp] = st, vals, dep
    # the other covered pixels: one evaluation per (pixel, triangle) seen at a sample
    is_simple = np.zeros(n_pix, dtype=bool)
    is_simple[sp] = True
    others = np.flatnonzero((sample_tri >= 0).any(axis=1) & ~is_simple)
    sub = sample_tri[others]
    i, s = np.nonzero(sub >= 0)
    pix, tri = others[i], sub[i, s]
    if force_ms:  # every sample evaluates its own triangle: the same values, S times the work
        first, inverse = np.arange(len(pix)), np.arange(len(pix))
    else:
        first, inverse = _distinct(sub, i, s)
    won = sample_tri[pix[first]] == tri[first][:, None]
    vals, dep = shade(*args, tri[first], pix[first], won, offsets, width, perspective)
    out_attrs[pix, s] = vals[inverse]
    parents = np.where(sub >= 0, parent[np.maximum(sub, 0)], -1)
    _, own_sample = owners(parents)
    slot = np.full(sub.shape, -1, dtype=np.int64)
    slot[i, s] = np.arange(len(i))
    at = inverse[slot[np.arange(len(others)), own_sample]]
    owner[others] = sub[np.arange(len(others)), own_sample]
    pix_attrs[others], pix_depth[others] = vals[at], dep[at]
    n_shaded = len(sp) + len(first)
    if force_attrs:  # also every hidden (pixel, triangle): evaluated, then discarded
        keys = np.unique(
            np.r_[frags.pixel * len(w) + frags.tri, frags.full_pixel * len(w) + frags.full_tri]
        )
        hidden_pix, hidden_tri = np.divmod(keys, len(w))
        won = sample_tri[hidden_pix] == hidden_tri[:, None]
        shade(*args, hidden_tri, hidden_pix, won, offsets, width, perspective)
        n_shaded += len(keys)
    return out_attrs, owner, pix_attrs, pix_depth, n_shaded


def multisample_stage(clipped, window, culled, size, bits, offsets, options, forced):
    """Fill, depth-test and shade a multisampled frame: a :class:`MultiFrame` and its effects.

    ``options`` is ``(depth_test, depth_format, interpolation)``; ``forced`` the plan's
    forced effects ("multisampling" expands every pixel to samples).
    """
    depth_test, depth_format, interpolation = options
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
    sample_tri, sample_depth, whole, contested, record = visibility(
        frags, planes, source[2], px, size, (depth_test, depth_format), (force_test, force_ms)
    )
    w = clipped.clip[:, :, 3]
    unequal = ~np.all(w == w[:, :1], axis=1)
    divide_all = "perspective" in forced and interpolation == "perspective"
    perspective = np.ones(len(w), bool) if divide_all else unequal
    if interpolation == "affine":
        perspective = np.zeros(len(w), bool)
    flags = (force_ms, "attributes" in forced, perspective)
    sample_attrs, owner, attrs, depth, n_shaded = shade_pixels(
        sample_tri, whole, frags, source, window, clipped, px, size, flags
    )
    depth = quantize(depth, depth_format)
    n_covered = int((owner >= 0).sum())
    n_samples = int((sample_tri >= 0).sum())
    n_per_sample = n_covered - len(whole[0])
    k = clipped.attrs.shape[2]
    visible = np.unique(sample_tri[sample_tri >= 0])
    n_persp = int(perspective[visible].sum())
    depth_effect = depth_test_effect(depth_test, force_test, contested, n_samples)
    why = depth_effect.why.replace("pixel(s)", "sample(s)").replace(
        "every fragment", "every sample"
    )
    effects = (
        replace(depth_effect, unit="samples", why=why),
        multisampling_effect(len(px), n_per_sample, n_covered, force_ms),
        perspective_effect(k, len(visible), n_persp, len(w), interpolation, divide_all),
        attributes_effect(k, n_shaded, frags.n_fragments, n_covered, "attributes" in forced),
    )
    multi = MultiFrame(sample_tri, sample_depth, sample_attrs, owner, attrs, depth, px, record)
    return multi, effects
