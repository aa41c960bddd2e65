"""Antialiasing ground truth: the exact area of a triangle inside each pixel, and what samples buy.

A box-filtered (ideally antialiased) image shows at each pixel the fraction of the pixel
square the triangle covers. :func:`pixel_area` computes it by clipping the triangle against
each pixel square (Sutherland–Hodgman: the polygon cut by the four sides in turn) and taking
the shoelace area of what is left, in float64 or, with ``exact=True``, in rational arithmetic
(:class:`fractions.Fraction`), which is exact for any input. The triangle is the one the
rasteriser fills: snapped to the sub-pixel grid (``subpixel_bits``, default 8).

:func:`sample_error_study` measures, for 1, 2, 4, 8 and 16 samples and each pattern kind, how
far the coverage fraction ``fill.coverage_fraction`` of ``tr.rasterize`` is from that area,
and what each costs in time (median of repeated fills). :func:`temporal_history` is temporal
antialiasing's accumulation: one jittered sample per pixel and frame, blended into a history
(reprojected, and optionally clamped to the new frame's neighbourhood).

>>> area = pixel_area([[0, 0], [2, 0], [0, 2]], 2, 2)
>>> area.tolist()                      # the diagonal halves pixels (0, 1) and (1, 0)
[[1.0, 0.5], [0.5, 0.0]]
>>> float(area.sum())                  # the triangle's area, 2 px²
2.0
"""

from __future__ import annotations

import statistics
import time
from fractions import Fraction

import numpy as np

from ..core.fill import rasterize
from ..core.sample_patterns import sample_pattern
from ..core.snapping import SUBPIXEL_BITS, check_bits, snap
from ..core.triangle import Triangle
from ..core.validate import as_bool, as_finite, as_size

#: The exponent k of error ∝ S^k for stratified (jittered) samples in a pixel crossed by an
#: edge: Mitchell (*Consequences of stratified sampling in graphics*, SIGGRAPH 1996) shows
#: that their variance falls like S^-3/2 (lesson 08 §7 draws it against the study).
STRATIFIED_ERROR_EXPONENT = -0.75


def _clip(poly: list, axis: int, bound, keep_below: bool) -> list:
    """Sutherland–Hodgman: the part of polygon ``poly`` with ``p[axis] <= bound`` (or >=)."""
    out = []
    n = len(poly)
    for k in range(n):
        a, b = poly[k], poly[(k + 1) % n]
        da, db = a[axis] - bound, b[axis] - bound
        a_in = da <= 0 if keep_below else da >= 0
        b_in = db <= 0 if keep_below else db >= 0
        if a_in:
            out.append(a)
        if a_in != b_in:  # the side crosses the line: add the crossing point
            t = da / (da - db)
            out.append(tuple(a[i] + t * (b[i] - a[i]) for i in range(2)))
    return out


def _area(poly: list):
    """Unsigned shoelace area of a polygon (0 for fewer than three corners)."""
    if len(poly) < 3:
        return 0
    s = 0
    for k in range(len(poly)):
        (x0, y0), (x1, y1) = poly[k], poly[(k + 1) % len(poly)]
        s += x0 * y1 - x1 * y0
    return abs(s) / 2


def pixel_area(xy, width: int, height: int, *, subpixel_bits=SUBPIXEL_BITS, exact=False):
    """(height, width) float64: the area of the triangle inside each pixel square, px².

    Parameters
    ----------
    xy : (3, 2) array-like
        Screen-space vertices (CONVENTIONS: x right, y down); snapped to ``subpixel_bits``
        first (None keeps them as they are), so this is the triangle the rasteriser fills.
    width, height : int
        Image size.
    exact : bool
        Clip in rational arithmetic (exact), instead of float64 (error ~1e-16 px²).
    """
    v = as_finite("xy", xy, (3, 2))
    width, height = as_size("width", width), as_size("height", height)
    exact = as_bool("exact", exact)
    v = snap(v, check_bits(subpixel_bits))
    num = Fraction if exact else float
    tri = [tuple(num(float(c)) for c in p) for p in v]
    out = np.zeros((height, width))
    c0, c1 = max(int(np.floor(v[:, 0].min())), 0), min(int(np.ceil(v[:, 0].max())), width)
    r0, r1 = max(int(np.floor(v[:, 1].min())), 0), min(int(np.ceil(v[:, 1].max())), height)
    for j in range(c0, c1):  # one vertical strip per column, then its pixels row by row
        strip = _clip(_clip(tri, 0, num(j), False), 0, num(j + 1), True)
        if len(strip) < 3:
            continue
        for i in range(r0, r1):
            cell = _clip(_clip(strip, 1, num(i), False), 1, num(i + 1), True)
            out[i, j] = float(_area(cell))
    return out


def coverage_error(xy, width: int, height: int, samples, **kwargs) -> np.ndarray:
    """(height, width): ``coverage_fraction`` of ``tr.rasterize`` minus the exact pixel area."""
    fill = rasterize(Triangle(xy), width, height, samples=samples, **kwargs)
    return fill.coverage_fraction - pixel_area(xy, width, height)


def study_triangles(size: int = 48, n: int = 12, seed: int = 11) -> np.ndarray:
    """Seeded triangles (n, 3, 2) for the study: random ones and thin, near-axis ones.

    Half are random inside the image; the others are long and thin, running nearly
    horizontal or nearly vertical (the edges where ordered and rotated grids differ).
    """
    rng = np.random.default_rng(seed)
    out = rng.uniform(1, size - 1, (n, 3, 2))
    for t in range(n // 2, n):
        a = rng.uniform(2, size / 4, 2)
        length, slope, width = size * 0.7, rng.uniform(-0.15, 0.15), rng.uniform(1.5, 5)
        tri = np.array([[0, 0], [length, slope * length], [0, width]])
        if t % 2:
            tri = tri[:, ::-1]
        out[t] = a + tri
    return out


def _study_patterns(kinds, counts, patterns):
    """(kind, samples, offsets) of every pattern :func:`sample_error_study` measures."""
    for kind in kinds:
        for n in counts:
            try:
                offsets = sample_pattern(n, kind) if n > 1 or kind != "standard" else 1
            except ValueError:
                continue  # this kind cannot make n samples (e.g. a grid of 2)
            yield kind, n, offsets
    if patterns is None:
        return
    if not isinstance(patterns, dict):
        raise TypeError(f"patterns must be a dict of name: offsets, got {type(patterns).__name__}")
    for name, offsets in patterns.items():
        offsets = as_finite("patterns", offsets, None)
        if offsets.ndim != 2 or offsets.shape[1] != 2 or len(offsets) < 1:
            raise ValueError(f"patterns[{name!r}] must be (S, 2) offsets, got {offsets.shape}")
        yield str(name), len(offsets), offsets


def sample_error_study(triangles=None, size: int = 48, counts=(1, 2, 4, 8, 16),
                       kinds=("standard", "grid", "jittered", "random"), repeat: int = 5,
                       patterns=None):  # fmt: skip
    """Error of the coverage fraction against the exact area, and the fill's time.

    For each pattern (kind, n) that exists: over all pixels where either is non-zero,
    the mean and max absolute error of ``coverage_fraction`` against :func:`pixel_area`,
    and the median time of one ``tr.rasterize`` of all the triangles (``repeat`` runs).
    ``patterns`` (a dict name: (S, 2) offsets in the pixel) adds patterns of one's own, each
    measured alike under its name (e.g. a standard pattern moved by a fraction of a pixel).

    Returns
    -------
    list of dict
        ``kind``, ``samples``, ``mean_error``, ``max_error``, ``time_s`` per pattern.
    """
    tris = study_triangles(size) if triangles is None else np.asarray(triangles, float)
    truth = [pixel_area(t, size, size) for t in tris]
    rows = []
    for kind, n, offsets in _study_patterns(kinds, counts, patterns):
        errors, times = [], []
        for t, want in zip(tris, truth):
            fill = rasterize(Triangle(t), size, size, samples=offsets)
            err = fill.coverage_fraction - want
            errors.append(np.abs(err[(want > 0) | (fill.coverage_fraction > 0)]))
        for _ in range(repeat):
            t0 = time.perf_counter()
            for t in tris:
                rasterize(Triangle(t), size, size, samples=offsets)
            times.append(time.perf_counter() - t0)
        e = np.concatenate(errors)
        rows.append({"kind": kind, "samples": n, "mean_error": float(e.mean()),
                     "max_error": float(e.max()), "time_s": statistics.median(times)})  # fmt: skip
    return rows


def _half_plane_area(nx, ny, c) -> np.ndarray:
    """Exact area of {(x, y) in the unit square : nx·x + ny·y <= c}, vectorised.

    Mirroring x (or y) makes both normal components non-negative; then the area is the
    distribution function of a·x + b·y for x, y uniform: a piecewise quadratic in c.
    """
    a, b = np.abs(nx), np.abs(ny)
    t = c - np.minimum(nx, 0.0) - np.minimum(ny, 0.0)
    ramp = lambda s: np.maximum(s, 0.0) ** 2  # noqa: E731
    area = (ramp(t) - ramp(t - a) - ramp(t - b) + ramp(t - a - b)) / (2 * a * b)
    return np.clip(area, 0.0, 1.0)


def edge_error_study(counts=(4, 16, 64, 256), edges: int = 4000, seed: int = 1,
                     standard=(2, 4, 8, 16)) -> list[dict]:  # fmt: skip
    """Mean |sampled − exact| coverage of one pixel crossed by a straight edge, per pattern.

    Each of ``edges`` random half-planes (a uniform angle, and an offset uniform over the
    lines that cross the pixel) cuts the unit pixel square; S samples estimate the area it
    covers. Kinds: ``"grid"`` (√S × √S ordered grid), ``"jittered"`` (one random sample in
    each grid cell, drawn anew for every edge: stratified sampling), ``"random"`` (S
    independent uniform samples), ``"grid, axis edges"`` (the ordered grid against
    horizontal edges only: its worst case), ``"standard, axis edges"`` (the standard
    pattern of each count in ``standard`` against the same horizontal edges: every sample on
    a row of its own, so its error falls like 1/S there; 1/(4S) where the rows are centred in
    their strips, 1/(2S) for the 16-sample pattern, whose rows start at the pixel's edge) and
    ``"standard"`` (those patterns against the random edges: the GPU's own patterns where an
    edge may run at any angle). Mitchell (*Consequences of stratified sampling in
    graphics*, SIGGRAPH 1996) shows that in pixels crossed by an edge stratified sampling's
    variance falls like S^-3/2, so its error like S^-3/4; independent samples fall like
    S^-1/2.

    Returns
    -------
    list of dict
        ``kind``, ``samples``, ``mean_error`` per kind and count.
    """
    rng = np.random.default_rng(seed)
    theta = rng.uniform(0.0, np.pi, edges)
    nx, ny = np.cos(theta), np.sin(theta)
    lo = np.minimum(nx, 0.0) + np.minimum(ny, 0.0)
    c = lo + rng.uniform(0.0, 1.0, edges) * (np.abs(nx) + np.abs(ny))
    area = _half_plane_area(nx, ny, c)
    level = rng.uniform(0.0, 1.0, edges)  # horizontal edges: y <= level
    rows = []
    for s in counts:
        n = int(round(np.sqrt(s)))
        if n * n != s:
            raise ValueError(f"counts must be perfect squares, got {s}")
        cell = np.stack(np.meshgrid(np.arange(n), np.arange(n)), -1).reshape(-1, 2) / n
        patterns = {
            "grid": np.broadcast_to(cell + 0.5 / n, (edges, s, 2)),
            "jittered": cell + rng.uniform(0.0, 1.0 / n, (edges, s, 2)),
            "random": rng.uniform(0.0, 1.0, (edges, s, 2)),
        }
        for kind, p in patterns.items():
            inside = (nx[:, None] * p[..., 0] + ny[:, None] * p[..., 1] <= c[:, None]).mean(1)
            rows.append({"kind": kind, "samples": s,
                         "mean_error": float(np.abs(inside - area).mean())})  # fmt: skip
        grid_y = cell[:, 1] + 0.5 / n
        inside = (grid_y[None, :] <= level[:, None]).mean(1)
        rows.append({"kind": "grid, axis edges", "samples": s,
                     "mean_error": float(np.abs(inside - level).mean())})  # fmt: skip
    for s in standard:  # fixed patterns: no draw from rng, the other kinds' edges unchanged
        p = sample_pattern(s)
        inside = (p[None, :, 1] <= level[:, None]).mean(1)
        rows.append({"kind": "standard, axis edges", "samples": int(s),
                     "mean_error": float(np.abs(inside - level).mean())})  # fmt: skip
        inside = (nx[:, None] * p[:, 0] + ny[:, None] * p[:, 1] <= c[:, None]).mean(1)
        rows.append({"kind": "standard", "samples": int(s),
                     "mean_error": float(np.abs(inside - area).mean())})  # fmt: skip
    return rows


def _moved(image: np.ndarray, dx: float, dy: float) -> np.ndarray:
    """``image`` (H, W, ...) resampled at (x − dx, y − dy), bilinear, its border repeated:
    what it showed moved by (dx, dy) pixels, as a TAA reprojection fetches its history."""
    h, w = image.shape[:2]
    ys, xs = np.clip(np.arange(h) - dy, 0, h - 1), np.clip(np.arange(w) - dx, 0, w - 1)
    y0, x0 = np.floor(ys).astype(int), np.floor(xs).astype(int)
    y1, x1 = np.minimum(y0 + 1, h - 1), np.minimum(x0 + 1, w - 1)
    extra = (1,) * (image.ndim - 2)  # colour channels, if any, share the weights
    fy, fx = (ys - y0).reshape(-1, 1, *extra), (xs - x0).reshape(1, -1, *extra)
    top = image[y0][:, x0] * (1 - fx) + image[y0][:, x1] * fx
    bottom = image[y1][:, x0] * (1 - fx) + image[y1][:, x1] * fx
    return top * (1 - fy) + bottom * fy


def _neighbourhood_range(frame: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The least and greatest value of ``frame`` (H, W, ...) in each pixel's 3 × 3
    neighbourhood (per channel, the border repeated): the box a TAA clamps its history to."""
    h, w = frame.shape[:2]
    padded = np.pad(frame, [(1, 1), (1, 1)] + [(0, 0)] * (frame.ndim - 2), mode="edge")
    around = np.stack([padded[dy : dy + h, dx : dx + w] for dy in range(3) for dx in range(3)])
    return around.min(axis=0), around.max(axis=0)


def temporal_history(frames, alpha: float = 0.1, motion=(0.0, 0.0), *,
                     clamp: bool = False) -> np.ndarray:  # fmt: skip
    """Temporal antialiasing's accumulation: an exponential history of jittered frames.

    Each frame is rendered with one sample per pixel, its position moved (jittered) from
    frame to frame; the history starts as the first frame and then blends each new one in
    with weight ``alpha``: ``h_t = (1 − alpha)·reproject(h_{t−1}) + alpha·frame_t``. A static
    view needs no reprojection; where the image moves by ``motion`` = (dx, dy) px per frame,
    the history is fetched where the content was (bilinear, as :func:`_moved`), which blurs
    it a little every frame. With ``clamp`` the fetched history is first clamped to the
    range of the new frame in the pixel's 3 × 3 neighbourhood (Karis, *High Quality Temporal
    Supersampling*, SIGGRAPH 2014): a stale value outside it cannot linger, nor can detail
    that the new frame's one sample per pixel missed. See also Yang, Liu and Salvi, *A
    Survey of Temporal Antialiasing Techniques* (Computer Graphics Forum, 2020).

    Parameters
    ----------
    frames : (T, H, W) or (T, H, W, C) array-like
        The jittered frames, in order.
    alpha : float
        The new frame's weight, in (0, 1]; 0.1 is a common choice.
    motion : (float, float)
        How far the image moves per frame, px (y down).
    clamp : bool
        Clamp the fetched history to the new frame's 3 × 3 neighbourhood range.

    Returns
    -------
    (T, H, W) or (T, H, W, C) ndarray
        The history after each frame.

    >>> temporal_history([[[0.0]], [[1.0]], [[1.0]]], alpha=0.5)[:, 0, 0].tolist()
    [0.0, 0.5, 0.75]
    >>> temporal_history([[[0.0]], [[1.0]], [[1.0]]], alpha=0.5, clamp=True)[:, 0, 0].tolist()
    [0.0, 1.0, 1.0]
    """
    frames = as_finite("frames", frames, None)
    if frames.ndim < 3:
        raise ValueError(f"frames must be (T, H, W) or (T, H, W, C), got shape {frames.shape}")
    alpha = float(alpha)
    if not 0.0 < alpha <= 1.0:
        raise ValueError(f"alpha must lie in (0, 1], got {alpha}")
    dx, dy = (float(v) for v in motion)
    out = np.empty_like(frames)
    out[0] = frames[0]
    for t in range(1, len(frames)):
        previous = out[t - 1] if dx == dy == 0.0 else _moved(out[t - 1], dx, dy)
        if clamp:
            previous = np.clip(previous, *_neighbourhood_range(frames[t]))
        out[t] = (1.0 - alpha) * previous + alpha * frames[t]
    return out


def ghost_sides(images, targets, motion, *, least: float = 1 / 16) -> dict:
    """Ghost pixels of a moving shape's history, counted by the side of the shape they lie on.

    A ghost pixel is one the reference ``targets`` leave empty (0) where ``images`` show more
    than ``least`` (for a 16-sample reference, its least step). Looking from it along the
    motion: with the shape ahead of it (and not behind), it lies **behind** the motion, where
    a trail is left; with the shape behind it, **ahead**. A trail lies behind only; a blur
    spreads to both sides, so the two counts tell a trail from a blur (lesson 08 §6).

    Parameters
    ----------
    images, targets : (T, H, W) array-like
        The history and the reference, frame by frame.
    motion : (float, float)
        The shape's motion per frame, px (y down); not zero.
    least : float
        The least value that counts as shown.

    Returns
    -------
    dict
        ``{"behind": n, "ahead": n, "beside": n}``, summed over the frames (``beside``: the
        shape neither ahead nor behind along the motion, or both).

    >>> target = np.zeros((1, 5, 1)); target[0, 2] = 1.0   # the shape in row 2, moving down
    >>> image = np.full((1, 5, 1), 0.5)
    >>> ghost_sides(image, target, (0.0, 0.25))
    {'behind': 2, 'ahead': 2, 'beside': 0}
    """
    return {side: int(mask.sum()) for side, mask in ghost_masks(images, targets, motion,
                                                                least=least).items()}  # fmt: skip


def ghost_masks(images, targets, motion, *, least: float = 1 / 16) -> dict:
    """The ghost pixels :func:`ghost_sides` counts, as (T, H, W) boolean masks by side.

    Returns ``{"behind": mask, "ahead": mask, "beside": mask}`` (the figures outline them:
    a ghost's value may be too faint to see in a colour map).
    """
    images, targets = as_finite("images", images, None), as_finite("targets", targets, None)
    if images.ndim != 3 or images.shape != targets.shape:
        raise ValueError(f"images and targets must be (T, H, W) alike, got {images.shape} "
                         f"and {targets.shape}")  # fmt: skip
    dx, dy = (float(v) for v in motion)
    if dx == dy == 0.0:
        raise ValueError("motion must not be zero: a still shape has no behind")
    ux, uy = np.array([dx, dy]) / np.hypot(dx, dy)
    ghost = (targets == 0) & (images > least)
    covered = targets > 0
    _, h, w = covered.shape
    rows, cols = np.mgrid[:h, :w]
    seen = {1: np.zeros_like(covered), -1: np.zeros_like(covered)}  # shape ahead, behind
    for step in range(1, h + w):  # one pixel at a time along the motion, both ways
        for sign, found in seen.items():
            r = np.rint(rows + sign * step * uy).astype(int)
            c = np.rint(cols + sign * step * ux).astype(int)
            inside = (r >= 0) & (r < h) & (c >= 0) & (c < w)
            found[:, inside] |= covered[:, r[inside], c[inside]]
    behind = ghost & seen[1] & ~seen[-1]
    ahead = ghost & seen[-1] & ~seen[1]
    return {"behind": behind, "ahead": ahead, "beside": ghost & ~behind & ~ahead}
