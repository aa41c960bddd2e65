"""Multisampling: coverage at S sample points per pixel, attributes once per pixel.

Each sample is decided exactly like a pixel centre (CONVENTIONS, *Multisampling*): the same
snapped edge functions and the same top-left rule of :mod:`teachraster.core.edges`, only
evaluated at ``(j + ox_s, i + oy_s)`` instead of ``(j + 1/2, i + 1/2)``. The fill of one
sample is therefore the ordinary fill (span tables, one raster line per row of that sample,
or half-planes) run on :meth:`EdgeSetup.at_sample`, and both algorithms agree per sample
because they agree at any tested point.

Exactness: sample offsets are placed on the internal grid (``1 / 2**(bits + 1)`` px, half
the vertex grid), as GPUs place samples on a fixed sub-pixel grid. The standard patterns are
multiples of 1/16 px, so with 3 or more sub-pixel bits they land exactly where they are
given, and every edge value at a sample is an exact int64.

Where the attributes of a pixel are evaluated (its *evaluation point*):

- MSAA (default): at the pixel centre, even when the centre is outside the triangle: the
  attribute plane is then *extrapolated* (as GPUs do), and values may leave the vertex range;
- ``centroid=True``: at the covered sample nearest the centre when the centre is not covered
  (ties: lower sample index), so values stay in range;
- the centroid sample is also used where the extrapolated 1/w at the centre would be <= 0
  (the perspective divide has no meaning there).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .bbox import BBox, pixel_bbox
from .edges import EdgeSetup, passes
from .interpolation import blend, interpolate


@dataclass(frozen=True)
class SampleTrace:
    """The per-sample tests of a multisampled fill (``trace=True`` with ``samples``).

    Attributes
    ----------
    offsets : (S, 2) float64
        Sample offsets inside the pixel as tested (on the internal grid), in px.
    boxes : tuple of S BBox
        The pixels whose sample s lies in the triangle's bounding box.
    tests : tuple of S HalfPlaneTrace or SpanTrace
        The fill algorithm's own record for each sample (bbox-local, like the centre's).
    coverage : (H, W, S) bool
        Per-sample coverage (``fill.sample_coverage``).
    eval_rows, eval_cols : (n,) int64
        The pixels whose fragment runs (any sample covered), row-major.
    eval_sample : (n,) int8
        Where each pixel's attributes were evaluated: -1 the centre, else the sample index
        (centroid). -2 marks supersampling (every covered sample).
    eval_xy : (n, 2) float64
        That point in pixels (the centre for supersampled pixels).
    vertices : (3, 2) int64 or float64
        The oriented vertices in internal units (for :meth:`edge_values`).
    top_left : (3,) bool
        The top-left flag of each oriented edge.
    unit : int or float
        Internal units per pixel.
    """

    offsets: np.ndarray
    boxes: tuple[BBox, ...]
    tests: tuple
    coverage: np.ndarray
    eval_rows: np.ndarray
    eval_cols: np.ndarray
    eval_sample: np.ndarray
    eval_xy: np.ndarray
    vertices: np.ndarray
    top_left: np.ndarray
    unit: int | float

    @property
    def n_samples(self) -> int:
        return len(self.offsets)

    def edge_values(self, row: int, col: int) -> np.ndarray:
        """(S, 3) edge values E_k (px², oriented edges, test order) at each sample of a pixel."""
        pts = _points(self.unit, self.offsets * self.unit, row, col)
        return _edge_values(self.vertices, pts).astype(np.float64) / float(self.unit) ** 2

    def passed(self, row: int, col: int) -> np.ndarray:
        """(S, 3) bool: each edge's tie-aware test at each sample of a pixel."""
        pts = _points(self.unit, self.offsets * self.unit, row, col)
        e = _edge_values(self.vertices, pts)
        return passes(e, self.top_left)


def _points(unit, offsets_units, row, col) -> np.ndarray:
    """Sample positions of one pixel in units (S, 2), exact integers on the snapped grid."""
    base = np.array([col, row]) * unit
    pts = base + offsets_units
    if isinstance(unit, int):
        pts = np.rint(pts).astype(np.int64)
    return pts


def offsets_in_units(offsets: np.ndarray, setup: EdgeSetup) -> np.ndarray:
    """Sample offsets on the internal grid: int64 units when snapped, else float px.

    Rounding is half to even, like vertex snapping; an offset that rounds up to the next
    pixel (0.9999999 px -> 512/512) is kept on the pixel's last grid line instead, since
    every offset lies in [0, 1): a sample is never tested outside its own pixel.

    >>> from teachraster.core.edges import setup_edges
    >>> setup = setup_edges(np.array([[0.0, 0], [4, 0], [0, 4]]), 8)
    >>> offsets_in_units(np.array([[0.375, 0.125]]), setup)     # 512 units per pixel
    array([[192,  64]])
    """
    if not setup.exact:
        return np.asarray(offsets, dtype=np.float64)
    units = np.rint(np.asarray(offsets, dtype=np.float64) * setup.unit)
    return np.minimum(units, setup.unit - 1).astype(np.int64)


def _edge_values(p: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """E_k at points ``pts`` (n, 2) for oriented vertices ``p``: (n, 3), exact in int64."""
    out = np.empty((len(pts), 3), dtype=np.result_type(p, pts))
    for k in range(3):
        a, b = p[k], p[(k + 1) % 3]
        out[:, k] = (b[0] - a[0]) * (pts[:, 1] - a[1]) - (b[1] - a[1]) * (pts[:, 0] - a[0])
    return out


def barycentric_points(setup: EdgeSetup, pts: np.ndarray) -> np.ndarray:
    """Barycentrics (n, 3) in the caller's vertex order at points ``pts`` (n, 2) in units.

    The same division as :func:`teachraster.core.barycentrics.barycentric_pixels`, at any
    point: negative weights outside the triangle (extrapolation).
    """
    e = _edge_values(setup.p, pts).astype(np.float64)
    lam = np.empty_like(e)
    area2 = float(setup.area2)
    for k in range(3):  # the weight of oriented vertex k is the edge opposite it
        lam[:, setup.perm[k]] = e[:, (k + 1) % 3] / area2
    return lam


def sample_fills(
    setup: EdgeSetup, offsets: np.ndarray, width: int, height: int, fill: Callable, record: bool
):
    """Per-sample coverage (H, W, S), each sample's bbox and the algorithm's traces.

    ``fill(setup, bbox, record)`` is the fill algorithm (span tables or half-planes): it runs
    once per sample on the setup moved to that sample.
    """
    units = offsets_in_units(offsets, setup)
    coverage = np.zeros((height, width, len(units)), dtype=bool)
    boxes, traces = [], []
    for s, (ox, oy) in enumerate(units.tolist()):
        at = setup.at_sample(ox, oy)
        box = pixel_bbox(at, width, height)
        local, trace = fill(at, box, record)
        if setup.area2 == 0:
            local[:] = False
        coverage[box.row0 : box.row1, box.col0 : box.col1, s] = local
        boxes.append(box)
        traces.append(trace)
    return coverage, tuple(boxes), tuple(traces), units


def evaluation_points(setup, units, sample_cov, centre_cov, rows, cols, centroid, w):
    """Where each fragment's attributes are evaluated: points (n, 2) in units, sample (n,).

    ``sample`` is -1 for the pixel centre, else the index of the centroid sample: the covered
    sample nearest the centre (squared distance in units, ties to the lower index), used when
    ``centroid`` is asked and the centre is not covered, and wherever the extrapolated 1/w
    at an uncovered centre would be <= 0.
    """
    unit, half = setup.unit, setup.half
    centre = np.stack([cols * unit + half, rows * unit + half], axis=1)
    if setup.exact:
        centre = centre.astype(np.int64)
    outside = ~centre_cov[rows, cols]
    if not centroid and outside.any() and not np.all(w == w[0]):
        lam = barycentric_points(setup, centre[outside])
        q = lam * (w.min() / w)
        bad = np.zeros(len(rows), dtype=bool)
        bad[np.flatnonzero(outside)[~(q.sum(axis=1) > 0)]] = True
        move = bad
    else:
        move = outside if centroid else np.zeros(len(rows), dtype=bool)
    which = np.full(len(rows), -1, dtype=np.int8)
    if move.any():
        d = (units - half).astype(np.float64)
        dist = d[:, 0] ** 2 + d[:, 1] ** 2  # (S,): the same for every pixel
        order = np.argsort(dist, kind="stable")  # nearest first, ties to the lower index
        cov = sample_cov[rows[move], cols[move]][:, order]
        which[move] = order[np.argmax(cov, axis=1)]  # first covered in that order
        pts = centre.copy()
        base = np.stack([cols[move], rows[move]], axis=1) * unit
        pts[move] = base + units[which[move]]
        return pts, which
    return centre, which


def extrapolate(lam: np.ndarray, values: np.ndarray, w: np.ndarray, mode: str) -> np.ndarray:
    """``Σ μ_i f_i`` without clamping, for evaluation points that may lie outside.

    μ is λ (affine) or (λ_i / w_i) / Σ λ_j / w_j (perspective): the planes of f/w and 1/w
    extended beyond the triangle, as a GPU evaluates them at an uncovered pixel centre.
    Callers make sure Σ λ_j / w_j > 0 (:func:`evaluation_points`).
    """
    if mode == "perspective" and not np.all(w == w[0]):
        q = lam * (w.min() / w)
        lam = q / q.sum(axis=1, keepdims=True)
    return blend(lam, values, extrapolate=True)


@dataclass(frozen=True)
class MultiFill:
    """Images of one multisampled fill (attributes as one packed (..., K) block)."""

    coverage: np.ndarray  # (H, W) any sample covered
    sample_coverage: np.ndarray  # (H, W, S)
    attrs: np.ndarray  # (H, W, K)
    depth: np.ndarray | None  # (H, W)
    sample_attrs: np.ndarray | None  # (H, W, S, K) with per_sample
    sample_depth: np.ndarray | None  # (H, W, S)
    offsets: np.ndarray  # (S, 2) px, as tested
    trace: SampleTrace | None


def fill_samples(setup, offsets, size, fill, centre_cov, packed, tri, options) -> MultiFill:
    """Coverage per sample, then attributes once per pixel (or per sample), for ``rasterize``.

    ``options`` is ``(interpolation, centroid, per_sample, record, culled)``.
    """
    interpolation, centroid, per_sample, record, culled = options
    width, height = size
    sample_cov, boxes, tests, units = sample_fills(setup, offsets, width, height, fill, record)
    if culled:
        sample_cov[:] = False
    coverage = sample_cov.any(axis=2)
    rows, cols = np.nonzero(coverage)
    n_s, k = len(units), packed.shape[1]
    base = np.stack([cols, rows], axis=1)[:, None, :] * setup.unit  # (n, 1, 2)
    si = np.nonzero(sample_cov[rows, cols])  # (fragment, sample) of every covered sample
    pts = (base + units[None, :, :])[si]
    lam_s = barycentric_points(setup, pts)
    sample_depth = None
    if tri.z is not None:
        sample_depth = np.full((height, width, n_s), np.nan)
        sample_depth[rows[si[0]], cols[si[0]], si[1]] = blend(lam_s, tri.z)
    attrs = np.full((height, width, k), np.nan)
    depth = None if tri.z is None else np.full((height, width), np.nan)
    sample_attrs = None
    if per_sample:  # supersampling: shade every covered sample, the pixel is their mean
        sample_attrs = np.full((height, width, n_s, k), np.nan)
        sample_attrs[rows[si[0]], cols[si[0]], si[1]] = interpolate(
            lam_s, packed, tri.w, interpolation
        )
        attrs[rows, cols] = covered_mean(sample_attrs[rows, cols])
        if depth is not None:
            depth[rows, cols] = covered_mean(sample_depth[rows, cols])
        which = np.full(len(rows), -2, dtype=np.int8)
        where = np.stack([cols + 0.5, rows + 0.5], axis=1).astype(np.float64)
    else:
        w = tri.w if interpolation == "perspective" else np.ones(3)
        pts, which = evaluation_points(
            setup, units, sample_cov, centre_cov, rows, cols, centroid, w
        )
        lam = barycentric_points(setup, pts)
        inside = centre_cov[rows, cols] | (which >= 0)
        attrs[rows[inside], cols[inside]] = interpolate(lam[inside], packed, tri.w, interpolation)
        out = ~inside
        attrs[rows[out], cols[out]] = extrapolate(lam[out], packed, tri.w, interpolation)
        if depth is not None:
            depth[rows[inside], cols[inside]] = blend(lam[inside], tri.z)
            depth[rows[out], cols[out]] = extrapolate(lam[out], tri.z, tri.w, "affine")
        where = pts.astype(np.float64) / float(setup.unit)
    px_offsets = units.astype(np.float64) / float(setup.unit)
    trace = None
    if record:
        trace = SampleTrace(
            offsets=px_offsets, boxes=boxes, tests=tests, coverage=sample_cov,
            eval_rows=rows, eval_cols=cols, eval_sample=which, eval_xy=where,
            vertices=setup.p, top_left=setup.top_left, unit=setup.unit,
        )  # fmt: skip
    return MultiFill(
        coverage=coverage, sample_coverage=sample_cov, attrs=attrs, depth=depth,
        sample_attrs=sample_attrs, sample_depth=sample_depth, offsets=px_offsets, trace=trace,
    )  # fmt: skip


def covered_mean(values: np.ndarray) -> np.ndarray:
    """Mean over axis 1 of the covered samples' values (NaN: uncovered), (n, S, ...) -> (n, ...).

    Each value is divided by its pixel's count before summing, so values near the float
    maximum average without overflow (``np.nanmean`` sums first); the mean is clamped to the
    samples' own range, which rounding could otherwise leave by an ulp. Every pixel passed
    has at least one covered sample.

    >>> covered_mean(np.array([[1.5e308, 1.7e308, np.nan]]))
    array([1.6e+308])
    """
    count = np.expand_dims((~np.isnan(values)).sum(axis=1), 1)
    mean = np.nansum(values / count, axis=1)
    return np.clip(mean, np.nanmin(values, axis=1), np.nanmax(values, axis=1))
