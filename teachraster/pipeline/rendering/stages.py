"""The stages of :func:`~teachraster.pipeline.render_triangles.render`, in pipeline order.

Lesson 05 follows a triangle from clip space to a pixel; each step of that journey is one
function here, and ``render`` is just these calls in a row::

    clip_stage        (N, 3, 4) clip, (N, 3, k) attrs -> ClipResult, Effect
    viewport_stage    ClipResult -> (M, 3, 3) window x, y, z
    cull_stage        window     -> (M,) bool culled, Effect
    fill_stage        window     -> Fragments: (triangle, row, col) of every covered centre
    depth_stage       Fragments  -> Visibility: stored depth per fragment, winner per pixel, Effect
    interpolate_stage Visibility -> (v, k) attributes at the v visible pixels, two Effects

What crosses each boundary, for code that extends a stage (tiles, multisampling, texture
derivatives):

- :class:`~teachraster.pipeline.clipping.ClipResult`: ``clip`` (M, 3, 4), ``attrs``
  (M, 3, k), ``parent`` (M,) input index, ``status`` (N,), the cut ``polygons``;
- :class:`~teachraster.pipeline.batched_fill.Fragments`: ``tri``, ``row``, ``col`` (m,) are
  generated once; nothing is evaluated at them until asked: ``weights(index)`` /
  ``weights_at(tri, x, y)`` give barycentrics at fragments or at any point (sample
  positions, helper pixels), ``plane(values)`` an affine per-vertex quantity (depth);
- :class:`Visibility`: ``depth`` and ``pixel`` (m,) per fragment, ``pixels`` (v,) covered
  flat pixel indices and ``winner`` (v,) the fragment each shows; ``passed`` on demand.

Every stage receives and returns plain numpy arrays and small frozen dataclasses (the trace
contract); the words that explain a stage's decision live in
:mod:`teachraster.pipeline.render_plan`, the stage only hands over the counts. A stage simulates
an effect only where the scene needs it (the plan), unless ``forced`` names it; the planned
and the forced render give the same frame (tests/test_plan.py).

Conventions shared by all stages: triangles are indexed 0..M-1 *after* clipping
(``ClipResult.parent`` maps them to the input); fragments are indexed 0..m-1 in drawing order
(by triangle, then raster line, then column); pixels are flat indices ``row * width + col``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ...core.edges import culled as culled_by
from ...core.edges import setup_edges
from ...core.interpolation import blend_each, convex_weights, normalised_weights, weights_per_row
from ..geometry.clipping import CLIPPED, DROPPED, INSIDE, ClipResult, classify, clip_triangles
from ..geometry.viewport import to_window
from ..planning.overrides import rule
from ..planning.render_plan import (
    Effect,
    attributes_effect,
    clipping_effect,
    culling_effect,
    depth_test_effect,
    perspective_effect,
)
from ..rasterization.batched_fill import Fragments, rasterize_batch
from ..rasterization.rule_coverage import fill_by_rule
from ..visibility.depth import quantize
from ..visibility.rule_depth import passed_by_rule
from ..visibility.zbuffer import last_written, passed_on_arrival, resolve


def guard_band(width: int, height: int, bits: int | None) -> float:
    """NDC guard band G: window |x|, |y| <= (G + 1) * size / 2 stay just inside the range
    where the fixed-point edge functions are exact (|x| < 2**(29 - bits) px)."""
    limit_px = 2.0 ** (29 - (bits if bits is not None else 8))
    guard = 2 * 0.999 * limit_px / max(width, height) - 1.0
    if guard < 1.0:
        raise ValueError(
            f"subpixel_bits: a {width}x{height} image does not fit the exact fixed-point "
            f"range with {bits} sub-pixel bits; use fewer bits"
        )
    return guard


def guard_band_reach(width: int, height: int, bits: int | None) -> tuple[float, float]:
    """The guard band of :func:`guard_band` and its reach in window pixels, from one formula.

    A vertex is inside the band when ``|x|, |y| <= G * w`` (inclusive, as
    :func:`~teachraster.pipeline.geometry.clipping.classify` tests it); after the divide and
    the viewport, ``x_win = (x / w + 1) * size / 2``, so inside the band
    ``|x_win|, |y_win| <= (G + 1) * size / 2``. Both numbers are returned together so that a
    text quoting them cannot round one and not the other.

    Returns
    -------
    guard : float
        G, in NDC units; it depends on the image size (a smaller image, a larger G).
    reach_px : float
        ``(G + 1) * max(width, height) / 2``: 0.999 of the exact range, 2**(29 - bits) px.

    >>> guard_band_reach(16, 16, 8)
    (261880.856, 2095054.848)
    """
    guard = guard_band(width, height, bits)
    return guard, (guard + 1.0) * max(width, height) / 2


def clip_stage(
    clip: np.ndarray, attrs: np.ndarray, width: int, height: int, bits: int | None, forced
) -> tuple[ClipResult, Effect]:
    """1. Clip (N, 3, 4) triangles and their (N, 3, k) attributes against near and far.

    Only triangles a plane cuts go through the clipper (all of them if "clipping" is in
    ``forced``); the guard band sized to the image keeps window coordinates exact.
    Returns the :class:`~teachraster.pipeline.clipping.ClipResult` (M output triangles)
    and the "clipping" effect.
    """
    force = "clipping" in forced
    clipped = clip_triangles(clip, attrs, guard=guard_band(width, height, bits), force=force)
    cut = clipped.status == CLIPPED
    # Which cuts were the near/far planes, and which only the guard band far off screen.
    n_guard = int((classify(clip[cut], None) == INSIDE).sum()) if cut.any() else 0
    n_drop = int((clipped.status == DROPPED).sum())
    effect = clipping_effect(len(clip), int(cut.sum()) - n_guard, n_guard, n_drop, force)
    return clipped, effect


def viewport_stage(clipped: ClipResult, width: int, height: int) -> np.ndarray:
    """2. The divide by w and the viewport transform: (M, 3, 3) window (x, y, z).

    Safe because clipping left every w > 0. Always runs, so it has no plan entry.
    """
    return to_window(clipped.clip, width, height)


def cull_stage(window: np.ndarray, cull: str | None, bits: int | None) -> tuple[np.ndarray, Effect]:
    """3. Back- or front-face culling by screen winding: (M,) bool culled, and its effect.

    Facing is decided on the snapped triangle, the one that is actually filled (the same
    test as :func:`teachraster.rasterize`, :func:`teachraster.core.edges.culled`).
    """
    area2 = setup_edges(window[:, :, :2], bits).original_area2
    culled = np.asarray(culled_by(area2, cull)).reshape(len(window))
    return culled, culling_effect(cull, int(culled.sum()), len(window))


def fill_stage(
    window: np.ndarray, width: int, height: int, bits: int | None, culled: np.ndarray, spans=None,
    coverage=None,
) -> Fragments:  # fmt: skip
    """4. Every covered pixel centre of every triangle not culled, in drawing order.

    Coverage is decided on the snapped grid (identical to :func:`teachraster.rasterize`);
    the barycentrics ``Fragments.lam`` come from the unsnapped positions, as llvmpipe sets up
    attributes (so the new vertices clipping creates interpolate exactly; Direct3D sets them
    up from the snapped positions, D3D11.3 §3.2.4 and §15.16.2). Filling always
    runs, so it has no plan entry. ``spans`` (Hi-Z, :mod:`teachraster.pipeline.hiz_tiles`)
    drops hidden blocks of raster lines before they become fragments. ``coverage``, a
    caller's rule (:mod:`teachraster.pipeline.planning.overrides`), decides instead, centre
    by centre (:func:`~teachraster.pipeline.rasterization.rule_coverage.fill_by_rule`).
    """
    if coverage is not None:
        return fill_by_rule(window[:, :, :2], width, height, bits, culled, coverage)
    return rasterize_batch(
        window[:, :, :2], width, height, subpixel_bits=bits, skip=culled, snapped_weights=False,
        spans=spans,
    )  # fmt: skip


@dataclass(frozen=True)
class Visibility:
    """What the depth stage hands on: which fragment each pixel shows.

    Attributes
    ----------
    depth : (m,) float64
        Every fragment's depth as the buffer stores it (after ``depth_format``).
    pixel : (m,) int64
        Every fragment's flat pixel index ``row * width + col``.
    depth_test : bool
        Whether the test was on (without it, later fragments overwrite earlier ones).
    pixels : (v,) int64
        Flat indices of the covered pixels, ascending.
    winner : (v,) int64
        The fragment each covered pixel shows: the last that passed the depth test (its
        colour and id are the ones kept).
    contested : int
        Pixels that 2+ fragments reach (depth complexity above one), as the resolve counted.
    writes : (m,) bool or None
        Each fragment's depth mask (``depth_write``); None: every fragment writes depth.
    stored : (v,) int64 or None
        With ``writes``: the fragment whose depth the buffer keeps at each covered pixel
        (the last that passed and wrote), -1 where none wrote; None: the winner's.

    ``passed`` (m,) bool, whether each fragment passed the depth test when it arrived
    (always True without the test), is computed on first use (for the trace).
    """

    depth: np.ndarray
    pixel: np.ndarray
    depth_test: bool
    pixels: np.ndarray
    winner: np.ndarray
    contested: int = 0
    writes: np.ndarray | None = None
    stored: np.ndarray | None = None

    @cached_property
    def passed(self) -> np.ndarray:
        return passed_on_arrival(self.pixel, self.depth, self.writes, self.depth_test)

    @property
    def buffer_depth(self) -> np.ndarray:
        """(v,) the depth buffer at the covered pixels: only depth that was written (NaN
        where no fragment that passed there wrote depth)."""
        if self.stored is None:
            return self.depth[self.winner]
        return np.where(self.stored >= 0, self.depth[self.stored], np.nan)


def depth_stage(
    frags: Fragments,
    window: np.ndarray,
    width: int,
    height: int,
    depth_test: bool,
    depth_format: str,
    forced,
    writes=None,
    depth_rule=None,
) -> tuple[Visibility, Effect]:
    """5. The z-buffer (Ritschel, *Interpolation and z-buffering*): who is visible where.

    Depth is affine in screen space, so it comes from each triangle's depth plane, one
    multiply-add per fragment (no barycentrics). With the test a fragment is kept when its
    stored depth is strictly smaller than the buffer's, so ties keep the earlier triangle;
    without it later triangles overwrite earlier ones. The plan counts the pixels that
    fragments of 2+ triangles reach (where the test decides anything); "depth_test" in
    ``forced`` reports every fragment as tested (the one-pass resolve does the same work
    either way; meaningless, and not reported, with the test off).

    ``writes`` (M,) bool, per triangle, is its depth mask (``depth_write``; None: all
    write): a triangle that does not write is tested but leaves the buffer as it was, so
    the pixel shows the last fragment that passed and the buffer keeps the last written
    depth (the test then runs in drawing order, :func:`passed_on_arrival`). ``depth_rule``,
    a caller's rule (:mod:`teachraster.pipeline.planning.overrides`), decides instead which
    of each pixel's fragments pass
    (:func:`~teachraster.pipeline.visibility.rule_depth.passed_by_rule`).
    """
    depth = frags.plane(window[:, :, 2])  # a fresh array: float64 needs no copy
    if depth_format != "float64":
        depth = quantize(depth, depth_format)
    pixel = frags.row * width + frags.col
    force = "depth_test" in forced and depth_test
    if writes is None and (depth_rule is None or not depth_test):
        winner, tested = resolve(pixel, depth, width * height, depth_test)
        pixels = np.flatnonzero(winner >= 0)
        effect = depth_test_effect(depth_test, force, tested, len(pixels))
        return Visibility(depth, pixel, depth_test, pixels, winner[pixels], tested), effect
    mask = np.ones(len(frags.tri), dtype=bool) if writes is None else writes[frags.tri]
    if depth_test and depth_rule is not None:
        passed = passed_by_rule(pixel, depth, mask, depth_rule)
    else:
        passed = passed_on_arrival(pixel, depth, mask, depth_test)
    winner, stored = last_written(pixel, passed, mask, width * height)
    tested = int((np.bincount(pixel, minlength=width * height) > 1).sum())
    pixels = np.flatnonzero(winner >= 0)
    effect = depth_test_effect(depth_test, force, tested, len(pixels))
    visible = Visibility(depth, pixel, depth_test, pixels, winner[pixels], tested, mask,
                         stored[pixels])  # fmt: skip
    visible.__dict__["passed"] = passed  # computed already (a cached_property's slot)
    return visible, effect


def interpolate_stage(
    frags: Fragments, visible: Visibility, clipped: ClipResult, interpolation: str, forced,
    overrides=None,
) -> tuple[np.ndarray, tuple[Effect, Effect]]:  # fmt: skip
    """6. Attributes at the visible pixels: (v, k) values, and the perspective and
    attributes effects.

    Perspective-correct (f/w over 1/w, Ek, *Triangles and Perspective Correct
    Interpolation*, eq. 19) only for triangles whose three w differ, where affine
    interpolation would be wrong; at visible pixels only, unless forced. ``overrides``
    (:mod:`teachraster.pipeline.planning.overrides`) may replace the weights and the
    perspective weights (:func:`_weights_by_rule`).
    """
    w, attrs = clipped.clip[:, :, 3], clipped.attrs
    k = attrs.shape[2]
    unequal = ~np.all(w == w[:, :1], axis=1)
    if interpolation == "affine":
        unequal[:] = False
    every = "attributes" in forced
    shade = np.arange(len(frags.tri)) if every else visible.winner
    divide_all = "perspective" in forced and interpolation == "perspective"
    values = _interpolate(frags, shade, w, attrs, unequal, divide_all, overrides)
    if every:
        values = values[visible.winner]
    # Count the triangles whose visible (or, forced, all) fragments were really divided.
    shaded_tris = np.flatnonzero(np.bincount(frags.tri[shade], minlength=len(w)))
    n_persp = len(shaded_tris) if divide_all else int(unequal[shaded_tris].sum())
    m = len(clipped.clip)
    perspective = perspective_effect(k, len(shaded_tris), n_persp, m, interpolation, divide_all)
    n_frags, n_visible = len(frags.tri), len(visible.pixels)
    attributes = attributes_effect(k, len(shade), n_frags, n_visible, every)
    return values, (perspective, attributes)


def _interpolate(frags, shade, w, attrs, unequal, force_perspective, overrides=None):
    """Attributes (len(shade), k) at fragments ``shade``, perspective-correct where needed.

    Each row's value depends on its fragment alone (not on the others evaluated with it),
    so the colour stage, the attributes and the pixel history get the same bits for the
    same fragment whichever set they ask for."""
    k = attrs.shape[2]
    if k == 0 or len(shade) == 0:
        return np.zeros((len(shade), k))
    tri = frags.tri[shade]
    x, y = frags.col[shade] + 0.5, frags.row[shade] + 0.5
    persp = np.ones(len(tri), dtype=bool) if force_perspective else unequal[tri]
    if rule(overrides, "weights") or rule(overrides, "perspective"):
        weights = _weights_by_rule(frags, tri, x, y, w, persp, overrides)
        return blend_each(weights, attrs, index=tri)
    # Weights from the unsnapped set-up can be slightly negative at a covered centre that
    # snapping brought inside an edge: made convex, so every value stays within range.
    if persp.all():  # the common case: 1/w folded into the barycentric pass
        weights = _perspective_weights(frags, tri, x, y, w)
    else:
        weights = convex_weights(frags.weights_at(tri, x, y))
        if persp.any():
            weights[persp] = _perspective_weights(frags, tri[persp], x[persp], y[persp], w)
    return blend_each(weights, attrs, index=tri)


def fragment_values(frags, index, clipped: ClipResult, interpolation: str, forced,
                    overrides=None) -> np.ndarray:  # fmt: skip
    """Attributes (n, k) at fragments ``index``, exactly as :func:`interpolate_stage`
    evaluates them (the same bits): for the colour of every fragment that reaches the
    colour buffer, and for the pixel history."""
    w = clipped.clip[:, :, 3]
    unequal = ~np.all(w == w[:, :1], axis=1)
    if interpolation == "affine":
        unequal[:] = False
    divide_all = "perspective" in forced and interpolation == "perspective"
    return _interpolate(frags, np.asarray(index), w, clipped.attrs, unequal, divide_all,
                        overrides)  # fmt: skip


def _perspective_weights(frags, tri, x, y, w):
    """Perspective-correct convex weights at covered centres, in one barycentric pass.

    Each triangle's ``(min(w) / w_i) / area`` is folded into its edge functions, so no
    per-pixel ``λ = E / area`` divide is needed (:func:`normalised_weights` says why the
    result equals :func:`weights_per_row` of the convex λ); the rare rows that fails
    (underflow, a degenerate set-up) are redone by :func:`weights_per_row` itself.
    """
    with np.errstate(divide="ignore", over="ignore", invalid="ignore", under="ignore"):
        smallest = np.minimum(np.minimum(w[:, 0], w[:, 1]), w[:, 2])  # not min(axis=1): slow
        scale = (smallest[:, None] / w) / frags.area2[:, None]
    weights, bad = normalised_weights(frags.weights_at(tri, x, y, scale=scale))
    if bad.any():
        redo = tri[bad]
        weights[bad] = weights_per_row(frags.weights_at(redo, x[bad], y[bad]), w[redo])
    return weights


def _weights_by_rule(frags, tri, x, y, w, persp, overrides) -> np.ndarray:
    """The weights of the vertex values (n, 3) with a caller's rules, row by row.

    ``weights(xy, p)`` gives the barycentrics at (x, y) from the positions the package sets
    its weights up from (else the package's); they are made convex as the package makes its
    own (:func:`convex_weights`: only rows with a negative weight change, a centre snapping
    brought inside an edge). ``perspective(lam, w)`` then gives the weights of the values
    wherever the package would divide by w (``persp``; else the package's
    :func:`weights_per_row`); elsewhere the barycentrics are the weights.
    """
    own_weights, own_perspective = rule(overrides, "weights"), rule(overrides, "perspective")
    if own_weights is None:
        lam = frags.weights_at(tri, x, y)
    else:
        xy = frags.vertices
        lam = np.array([_three("weights", own_weights(xy[t].copy(), np.array([px, py])))
                        for t, px, py in zip(tri.tolist(), x.tolist(), y.tolist())])  # fmt: skip
        lam = lam.reshape(len(tri), 3)
    lam = convex_weights(lam)
    out = lam.copy()
    rows = np.flatnonzero(persp)
    if own_perspective is None:
        if len(rows):
            out[rows] = weights_per_row(lam[rows], w[tri[rows]])
        return out
    for i in rows.tolist():
        out[i] = _three("perspective", own_perspective(lam[i].copy(), w[tri[i]].copy()))
    return out


def _three(name: str, value) -> np.ndarray:
    """A rule's answer as three float64 weights (ValueError naming the rule otherwise)."""
    arr = np.asarray(value, dtype=np.float64)
    if arr.shape != (3,):
        raise ValueError(f"the {name} rule must return 3 weights, got shape {arr.shape}")
    return arr
