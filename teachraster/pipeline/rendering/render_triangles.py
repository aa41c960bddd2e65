"""``render``: clip, cull, fill, depth-test and interpolate a list of clip-space triangles.

The pipeline, in order, one function of :mod:`teachraster.pipeline.stages` per stage (each
simulated only where the scene needs it, see :mod:`teachraster.pipeline.render_plan`):

1. homogeneous clipping against near and far (:mod:`teachraster.pipeline.clipping`);
2. the viewport transform to window coordinates (:mod:`teachraster.pipeline.viewport`);
3. back- or front-face culling, if asked;
4. filling every triangle at once (:mod:`teachraster.pipeline.batched_fill`, identical pixels to
   :func:`teachraster.rasterize`);
5. the z-buffer (Ritschel, *Interpolation and z-buffering*): a fragment is kept when its
   stored depth is strictly smaller than the buffer's, so ties keep the earlier triangle;
   without the depth test later triangles overwrite earlier ones
   (:mod:`teachraster.pipeline.zbuffer`); before it, Hi-Z drops the blocks of raster
   lines that a triangle covering their whole 8×8 tile hides, so their depth is never
   interpolated (:mod:`teachraster.pipeline.hiz_tiles`); with ``trace=True``, what early-z
   and Hi-Z would save a GPU drawing in order (:mod:`teachraster.pipeline.hierarchical_z`);
6. perspective-correct interpolation of the attributes, at the visible pixels only;
7. on request, their screen-space derivatives from 2×2 quads with helper pixels
   (:mod:`teachraster.pipeline.quad_derivatives`), for texture filtering.
"""

from __future__ import annotations

import copy
import dataclasses
from dataclasses import dataclass, field, replace

import numpy as np

from ...core.sample_patterns import as_samples, is_single
from ...core.snapping import SUBPIXEL_BITS
from ...core.validate import as_bool, as_real
from ..antialiasing.multisampling import multisample_stage
from ..blending.colour_blending import blend_stage, check_blend, replaced_colour
from ..planning.inputs import check_render
from ..planning.overrides import SINGLE_SAMPLE_RULES, rule
from ..planning.render_plan import Plan, depth_test_effect, hi_z_effect
from ..texturing.quad_derivatives import QuadTrace, as_derivative_mode, derivatives_stage
from ..visibility.hierarchical_z import HiZResult, replay_stage
from ..visibility.hiz_tiles import HiZCut, HiZTiles
from ..visibility.zbuffer import passed_on_arrival
from .stages import (
    clip_stage,
    cull_stage,
    depth_stage,
    fill_stage,
    fragment_values,
    interpolate_stage,
    viewport_stage,
)

#: The readers of a traced frame behind :meth:`Frame.history` and :meth:`Frame.overlay`:
#: the debugging stage (:mod:`teachraster.pipeline.debugging`) sits above this one, since it
#: reads frames, and registers its functions here when imported (``import teachraster``
#: imports every stage).
FRAME_DEBUGGERS: dict = {}


@dataclass(frozen=True)
class DebugInputs:
    """What frame debugging (:mod:`teachraster.pipeline.debugging`) keeps from a traced
    render beyond the fragment arrays.

    Attributes
    ----------
    inputs : RenderInputs
        The checked arguments (size, depth test and format, snapping, culling).
    clipped : ClipResult
        The triangles after clipping (``parent`` maps them to the input).
    offsets : (S, 2) float64 or None
        Sample offsets as tested (MSAA), None for one sample at the centre.
    centroid : bool
    fragments : Fragments or None
        The single-sample fill's fragments (None with MSAA).
    pixel : (m,) int64 or None
        Their flat pixel indices (the depth stage's, kept rather than recomputed).
    writes : (M,) bool or None
        Per triangle after clipping, its depth mask (``depth_write``); None: all write.
    blend : BlendState or None
        The colour buffer's state (blend mode, clear colour, format), None without one.
    cache : dict
        What the overlays computed once for this frame (filled on first use).
    """

    inputs: object
    clipped: object
    offsets: np.ndarray | None
    centroid: bool
    fragments: object
    pixel: np.ndarray | None = None
    writes: np.ndarray | None = None
    blend: object = None
    cache: dict = field(default_factory=dict, compare=False, repr=False)


@dataclass(frozen=True)
class RenderTrace:
    """What each stage of :func:`render` did (plain arrays, nothing per pixel in Python).

    Attributes
    ----------
    clip_status : (N,) int8
        Per input triangle: 0 untouched by clipping, 1 clipped, 2 dropped.
    clip_polygons : tuple of (n, 4) arrays
        The polygon each clipped triangle became, in clip space.
    window : (M, 3, 3) float64
        Window (x, y, z) of every triangle after clipping; ``parent`` (M,) its input index.
    parent : (M,) int
    culled : (M,) bool
        Triangles removed by culling.
    fragment_triangle, fragment_row, fragment_col : (m,) int
        Every fragment in drawing order (input triangle index, pixel).
    fragment_depth : (m,) float64
        Its depth as the buffer stores it (after ``depth_format`` quantisation).
    fragment_passed : (m,) bool
        Whether it passed the depth test when it arrived (always True without the test).
    fragment_sample : (m,) int64 or None
        Multisampled renders: the sample each fragment entry was tested at (entries grouped
        by sample, drawing order inside each), or -1 for a pixel decided whole (one triangle at every sample, no per-sample test; its depth is
        NaN here, the per-sample depths are in ``Frame.sample_depth``).
    quads : QuadTrace or None
        The 2×2 quads and helper pixels evaluated for derivatives, when they were.
    hiz : HiZResult or None
        Early-z and Hi-Z of a GPU drawing in this order, per block and fragment (None
        without the depth test).
    hiz_tiles : HiZTiles or None
        The renderer's own Hi-Z: tile bounds and, per fragment, whether it was rejected
        (None without the depth test).
    debug : DebugInputs or None
        What :meth:`Frame.history` and :meth:`Frame.overlay` need beyond the fragments
        (the checked inputs, the clipped triangles, the fill's fragments); references
        only, nothing is copied.
    """

    clip_status: np.ndarray
    clip_polygons: tuple[np.ndarray, ...]
    window: np.ndarray
    parent: np.ndarray
    culled: np.ndarray
    fragment_triangle: np.ndarray
    fragment_row: np.ndarray
    fragment_col: np.ndarray
    fragment_depth: np.ndarray
    fragment_passed: np.ndarray
    fragment_sample: np.ndarray | None = None
    quads: QuadTrace | None = None
    hiz: HiZResult | None = None
    hiz_tiles: HiZTiles | None = None
    debug: DebugInputs | None = None


class _OnFirstUse:
    """A :class:`Frame` field that may be given as a zero-argument callable, called (once)
    when the field is first read: the large per-sample arrays of a multisampled frame
    (S ids, depths and attribute vectors per pixel) are only built if someone reads them.

    A data descriptor as a dataclass default: the dataclass's ``__init__`` stores through
    ``__set__``, and the class-level read (``instance is None``) gives the default, None.
    """

    def __set_name__(self, owner, name):
        self.key = "_" + name

    def __get__(self, instance, owner=None):
        if instance is None:
            return None
        value = instance.__dict__[self.key]
        if callable(value):
            value = value()
            instance.__dict__[self.key] = value
        return value

    def __set__(self, instance, value):
        instance.__dict__[self.key] = value


@dataclass(frozen=True)
class Frame:
    """The result of :func:`render`.

    Attributes
    ----------
    triangle_id : (H, W) int64
        Index of the input triangle that wrote each pixel (the last fragment that passed
        the depth test there), -1 where none did.
    attrs : (H, W, k) float64
        Perspective-correct attributes, NaN where uncovered.
    depth : (H, W) float64
        Window depth as stored in the depth buffer: only depth that was written, so NaN
        where uncovered and where only triangles with ``depth_write=False`` passed. With
        ``depth_test=False`` every fragment passes and writes (GL's ``GL_ALWAYS``, not
        ``glDisable(GL_DEPTH_TEST)``, which writes no depth): the last fragment's depth.
    plan : Plan
        Which effects were simulated, for how much, and why.
    trace : RenderTrace or None
        Every stage's record, when ``trace=True``.
    sample_triangle_id : (H, W, S) int64 or None
        With ``samples`` other than 1: the input triangle each sample shows, -1 none.
        ``triangle_id``, ``depth`` and ``attrs`` then describe the triangle owning most of
        the pixel's samples (ties: the earlier), evaluated once for the pixel (``depth``: of
        the samples holding a written depth, which differ with ``depth_write=False``).
    sample_depth : (H, W, S) float64 or None
        The depth buffer, one depth per sample, NaN where no depth was written.
    sample_attrs : (H, W, S, k) float64 or None
        The attributes each sample holds: those of its triangle, evaluated once per pixel
        (at the centre, extrapolated when outside), NaN where uncovered.

        The three per-sample arrays are kept compressed, as GPUs keep a multisampled
        surface: one triangle (depth plane, attribute value) per pixel decided whole, and
        single samples only where the per-sample test ran. Each array is expanded on
        first read (then kept), so a render that only needs the per-pixel results, or
        only the ids, never builds the others.
    samples : (S, 2) float64 or None
        The sample offsets inside the pixel as tested, in px.
    ddx, ddy : (H, W, k) float64 or None
        Screen-space derivatives of the attributes from 2×2 quads (``derivatives=``): per
        pixel step right and per pixel step down; NaN where uncovered. None when not computed.
    color, sample_color : (H, W, 4), (H, W, S, 4) float64 or None
        The colour buffer when ``attrs`` are RGBA (k = 4), resolved under MSAA, and with
        samples per sample: starting at ``clear_color``, each fragment that passes the depth
        test is blended in submission order (``blend=`` a mode) or, with ``blend=None``
        (blending disabled, as in GL), written over what is there
        (:mod:`teachraster.pipeline.blending`). None without RGBA attributes. Without
        blending they are built on first read.
    """

    triangle_id: np.ndarray
    attrs: np.ndarray
    depth: np.ndarray
    plan: Plan
    trace: RenderTrace | None = None
    sample_triangle_id: np.ndarray | None = _OnFirstUse()
    sample_depth: np.ndarray | None = _OnFirstUse()
    sample_attrs: np.ndarray | None = _OnFirstUse()
    samples: np.ndarray | None = None
    ddx: np.ndarray | None = None
    ddy: np.ndarray | None = None
    color: np.ndarray | None = _OnFirstUse()
    sample_color: np.ndarray | None = _OnFirstUse()

    @property
    def coverage(self) -> np.ndarray:
        """(H, W) bool: pixels some triangle wrote."""
        return self.triangle_id >= 0

    @property
    def coverage_fraction(self) -> np.ndarray:
        """(H, W) float64: fraction of each pixel's samples some triangle covers."""
        if self.sample_triangle_id is None:
            return self.coverage.astype(np.float64)
        return (self.sample_triangle_id >= 0).mean(axis=2)

    def resolve(self, values, background=0.0) -> np.ndarray:
        """The MSAA resolve: the mean of per-sample ``values`` over all S samples of a pixel.

        Uncovered samples count as ``background`` (a scalar or a (c,) colour).

        Parameters
        ----------
        values : (H, W, S) or (H, W, S, c) array-like
            One value per sample, e.g. ``frame.sample_attrs`` or a colour shaded from it.
            A single-sample frame takes (H, W) or (H, W, c) values instead.
        background : float or (c,) array-like

        Examples
        --------
        >>> clip = [[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]]
        >>> frame = render(clip, 2, 2, attrs=[[1.0, 1.0, 1.0]], samples=4)
        >>> frame.resolve(frame.sample_attrs, background=0.0)[..., 0]
        array([[0.5, 0. ],
               [1. , 0.5]])
        """
        ids = self.sample_triangle_id
        values = as_real("values", values)  # strings, complex, ragged: a named error
        if ids is None:
            ids = self.triangle_id[..., None]
            if values.shape[:2] != ids.shape[:2]:
                raise ValueError(
                    f"values must have shape {ids.shape[:2]} (+ channels) for a one-sample "
                    f"frame, got {values.shape}"
                )
            values = values[:, :, None]
        if values.shape[:3] != ids.shape or values.ndim > 4:
            raise ValueError(
                f"values must have shape {ids.shape} or {ids.shape + ('c',)}, got {values.shape}"
            )
        bg = as_real("background", background)
        if bg.shape not in ((), values.shape[3:]):
            raise ValueError(
                f"background must be a number or have shape {values.shape[3:]} (one value per "
                f"channel of values), got {bg.shape}"
            )
        covered = (ids >= 0).reshape(*ids.shape, *([1] * (values.ndim - 3)))
        bg = np.broadcast_to(bg, values.shape[3:])
        picked = np.where(covered, values, bg)
        with np.errstate(over="ignore", invalid="ignore"):
            out = picked.mean(axis=2)
        # Values near ±1.8e308: the sum overflows although the mean does not. Average those
        # pixels scaled by 2**-5 (exact for normal numbers; S <= 32), then scale back.
        bad = ~np.isfinite(out) & np.isfinite(picked).all(axis=2)
        if bad.any():
            out[bad] = (picked[bad] * 2.0**-5).mean(axis=1) * 2.0**5
        return out

    def history(self, row: int, col: int):
        """Every triangle on the way to pixel (``row``, ``col``), in submission order, with
        the first test that stopped it: a ``PixelHistory`` (needs ``trace=True``; see
        :mod:`teachraster.pipeline.debugging.frame_history`)."""
        return FRAME_DEBUGGERS["history"](self, row, col)

    def overlay(self, kind: str) -> np.ndarray:
        """(H, W) debug view: "overdraw", "depth_complexity", "quad_overshading",
        "triangle_size", "hi_z" or "nan" (needs ``trace=True`` except "nan"; see
        :mod:`teachraster.pipeline.debugging.overlays`)."""
        return FRAME_DEBUGGERS["overlay"](self, kind)


def render(
    clip,
    width: int,
    height: int,
    *,
    attrs=None,
    depth_test: bool = True,
    cull: str | None = None,
    depth_format: str = "float64",
    interpolation: str = "perspective",
    force=None,
    trace: bool = False,
    subpixel_bits: int | None = SUBPIXEL_BITS,
    max_pixels: int | None = None,
    samples=1,
    centroid: bool = False,
    derivatives=False,
    derivatives_where=None,
    blend=None,
    depth_write=True,
    clear_color=(0.0, 0.0, 0.0, 0.0),
    color_format: str = "float64",
    overrides=None,
) -> Frame:
    """Render clip-space triangles into a ``height`` × ``width`` frame (bad arguments raise
    a ValueError or TypeError naming them, see :mod:`teachraster.pipeline.inputs`).

    Parameters
    ----------
    clip : (N, 3, 4) array-like
        Clip-space vertices (x, y, z, w) of N triangles, e.g. ``projection @ view @ p``.
    width, height : int
        Frame size in pixels.
    attrs : (N, 3) or (N, 3, k) array-like, optional
        Per-vertex attributes, interpolated perspective-correctly.
    depth_test : bool
        On: nearer wins, ties keep the earlier. Off: later wins and writes depth (``GL_ALWAYS``).
    cull : {None, "back", "front"}
        Remove back-facing (clockwise on screen) or front-facing triangles.
    depth_format : {"float64", "float32", "unorm24", "unorm16"}
        What the depth buffer stores; fewer bits show z-fighting.
    interpolation : {"perspective", "affine"}
        GLSL ``smooth`` (perspective-correct, the default) or ``noperspective``.
    force, trace : None, "all" or names from ``render_plan.FORCEABLE``; bool
        Run these effects everywhere (even where they change nothing); record every stage.
    subpixel_bits, max_pixels : int or None, int (optional)
        Snapping as in :func:`teachraster.rasterize`; the largest ``width * height`` (2**28).
    samples, centroid : int or (S, 2) array-like, bool
        Multisampling (MSAA): 1, 2, 4, 8, 16 (standard patterns) or offsets in [0, 1)².
        Coverage and the depth test per sample, attributes once per pixel and triangle
        (:class:`Frame`), at the centre or (``centroid``) the covered sample nearest it.
    derivatives : bool or {"coarse", "fine"}
        ``frame.ddx``, ``frame.ddy`` from 2×2 quads: ``True``/``"coarse"`` (one pair per
        quad, as llvmpipe) or ``"fine"``; see :mod:`teachraster.pipeline.quad_derivatives`.
    derivatives_where : (N,) bool array-like, optional
        Only the pixels of these input triangles get derivatives (NaN elsewhere).
    blend, depth_write, clear_color : None or "over", "premultiplied", "additive", "multiply"
        (or a glBlendFunc pair), bool or (N,) bools, (4,): with RGBA ``attrs`` the colour
        buffer ``frame.color`` starts at ``clear_color`` and every fragment that passes is
        blended in submission order, or with ``blend=None`` (blending disabled) written over
        it. ``depth_write`` (``glDepthMask``, per triangle, with or without blending): a
        triangle that does not write depth is still tested, and leaves the depth buffer
        (``frame.depth``, Hi-Z, the history) as it was.
    color_format : {"float64", "srgb8"}
        What the colour buffer stores: float64 as computed, or GL's ``SRGB8_ALPHA8`` with
        ``GL_FRAMEBUFFER_SRGB`` (clamped and rounded to 8 bits after every layer;
        :mod:`teachraster.pipeline.blending`).
    overrides : StageOverrides or dict, optional
        Rules replacing the package's own, element by element: :mod:`.overrides`.

    Examples
    --------
    >>> clip = [[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]]
    >>> frame = render(clip, 4, 4)
    >>> frame.triangle_id        # centres on the diagonal: a right edge, so not covered
    array([[-1, -1, -1, -1],
           [ 0, -1, -1, -1],
           [ 0,  0, -1, -1],
           [ 0,  0,  0, -1]])
    """
    a = check_render(clip, width, height, attrs=attrs, depth_test=depth_test, cull=cull,
                     depth_format=depth_format, interpolation=interpolation, force=force,
                     trace=trace, subpixel_bits=subpixel_bits, max_pixels=max_pixels,
                     overrides=overrides)  # fmt: skip
    clip, attrs, width, height, subpixel_bits = a.clip, a.attrs, a.width, a.height, a.subpixel_bits
    forced, own_blend = a.forced, rule(a.overrides, "blend")
    offsets, centroid = _check_samples(samples, centroid, a.overrides)
    mode, where = _check_derivatives(derivatives, derivatives_where, len(clip), offsets)
    blending = check_blend(blend, depth_write, clear_color, attrs, color_format, own_blend)
    clipped, clipping = clip_stage(clip, attrs, width, height, subpixel_bits, forced)
    window = viewport_stage(clipped, width, height)
    culled, culling = cull_stage(window, cull, subpixel_bits)
    writes = blending.depth_write[clipped.parent]
    writes = None if writes.all() else writes  # None: every triangle writes depth
    if offsets is not None:  # MSAA: coverage, depth test and resolve per sample
        return _render_multisampled(clipped, window, culled, (clipping, culling), offsets, a,
                                    centroid, (blending, writes))  # fmt: skip
    derivatives = (mode, None if where is None else where[clipped.parent])
    return _render_single(clipped, window, culled, (clipping, culling), a, derivatives,
                          (blending, writes))  # fmt: skip


def _render_single(clipped, window, culled, effects, a, derivatives, colour) -> Frame:
    """The one-sample rest of :func:`render`, after clipping, the viewport and culling
    (``a``: the checked arguments; ``derivatives``: the mode and the pieces that want them;
    ``colour``: the blend state and the depth masks)."""
    blending, writes = colour
    width, height, forced, interpolation = a.width, a.height, a.forced, a.interpolation
    # with Hi-Z: hidden blocks never become fragments (blending keeps them all, marked)
    frags, cut = _fill(window, culled, a, writes, blending.blending)
    visible, depth_testing = depth_stage(frags, window, width, height, a.depth_test,
                                         a.depth_format, forced, writes,
                                         rule(a.overrides, "depth"))  # fmt: skip
    values, (perspective, attributes) = interpolate_stage(
        frags, visible, clipped, interpolation, forced, a.overrides
    )
    ddx, ddy, quads, derivs = derivatives_stage(
        frags, visible, clipped, (width, height), *derivatives, interpolation, forced, a.trace,
    )  # fmt: skip
    effects = (*effects, depth_testing, perspective, attributes, derivs)
    plan = _plan(cut, frags, visible, effects, forced)
    record = a.trace and _record(clipped, window, culled, frags, visible, quads, cut, a,
                                 (writes, blending))  # fmt: skip
    frame = _frame(visible, values, clipped, frags, width, height, plan, record, ddx, ddy)
    if not blending.blending:
        return with_colour(frame, blending)
    # the colour of every fragment that passed, evaluated as the attributes are
    passed = np.flatnonzero(visible.passed)
    src = fragment_values(frags, passed, clipped, interpolation, forced, a.overrides)
    return with_colour(frame, blending, *blend_stage(visible.pixel[passed], src,
                                                     (height, width), 1, blending))  # fmt: skip


def with_colour(frame, state, color=None, sample_color=None, effect=None) -> Frame:
    """The frame with its colour buffer (the hook of :mod:`.blending`): the blended
    ``color`` and ``sample_color`` with the plan's "blending" ``effect``, or without
    blending (``color`` None) the colour each pixel (sample) shows over the clear colour,
    built on first read; the frame itself without RGBA attributes."""
    if not state.buffer:
        return frame
    # A shallow copy, not dataclasses.replace: replace would read (and so build) the lazy
    # per-sample arrays of a multisampled frame.
    out = copy.copy(frame)
    if color is None:
        written = _Written(out, state)
        color = written if frame.samples is None else _Written(out, state, resolve=True)
        sample_color = None if frame.samples is None else written
    else:
        object.__setattr__(out, "plan", Plan((*frame.plan.effects, effect)))
    object.__setattr__(out, "color", color)
    object.__setattr__(out, "sample_color", sample_color)
    return out


@dataclass(frozen=True, eq=False, repr=False)
class _Written:
    """The colour buffer without blending, built on first read (a callable the frame keeps,
    picklable): each pixel (sample) the colour of the fragment it shows, over the clear
    colour; ``resolve``: the mean of the samples."""

    frame: Frame
    state: object
    resolve: bool = False

    def __call__(self) -> np.ndarray:
        f = self.frame
        if self.resolve:
            return f.sample_color.mean(axis=2)
        if f.samples is None:
            return replaced_colour(f.triangle_id >= 0, f.attrs, self.state)
        return replaced_colour(f.sample_triangle_id >= 0, f.sample_attrs, self.state)


def _fill(window, culled, a, writes=None, keep_all=False):
    """The fill stage, with the Hi-Z hook when the depth test is on (nothing is hidden
    otherwise): hidden blocks never become fragments; a trace (and ``keep_all``, for
    blending) keeps them all, marked. ``a`` are the checked inputs, ``writes`` the
    triangles' depth masks (only writers hide anything). Returns the fragments and the
    hook (None without it)."""
    cut = None
    coverage = rule(a.overrides, "coverage")
    # Hi-Z drops blocks by the package's coverage and depth test: not when either is replaced
    if a.depth_test and coverage is None and rule(a.overrides, "depth") is None:
        image = (a.height, a.width)
        cut = HiZCut(window[:, :, 2], image, a.depth_format, "hi_z" in a.forced,
                     a.trace or keep_all, writes=writes)  # fmt: skip
    return fill_stage(window, a.width, a.height, a.subpixel_bits, culled, cut, coverage), cut


def _plan(cut, frags, visible, effects, forced) -> Plan:
    """The plan, with the "hi_z" effect after the depth test's."""
    clipping, culling, depth_testing, perspective, attributes, derivs = effects
    result = None if cut is None else cut.result
    hi_z, depth_testing, attributes = _hi_z_effects(
        result, len(frags.tri), (depth_testing, attributes), visible, forced
    )
    return Plan((clipping, culling, depth_testing, hi_z, perspective, attributes, derivs))


def _hi_z_effects(result, n_fragments, effects, visible, forced):
    """The "hi_z" effect; the depth test and attributes told of what Hi-Z dropped.

    The depth test then decides only among the fragments Hi-Z kept (a trace keeps every
    fragment, so its count is taken over the kept ones too); the attributes count all
    fragments, dropped ones included.
    """
    depth_testing, attributes = effects
    hi_z = hi_z_effect(result is not None, n_fragments, result)
    if result is None or not result.rejected:
        return hi_z, depth_testing, attributes
    contested = visible.contested
    if result.fragment_rejected is not None:  # the trace: nothing was dropped, count as if
        contested = int((np.bincount(visible.pixel[~result.fragment_rejected]) > 1).sum())
    force = "depth_test" in forced
    depth_testing = depth_test_effect(True, force, contested, len(visible.pixels))
    depth_testing = dataclasses.replace(
        depth_testing, why=depth_testing.why + f" (after Hi-Z dropped {result.rejected:,})"
    )
    if result.fragment_rejected is None:  # the trace's fragments are all of them already
        attributes = dataclasses.replace(attributes, total=result.fragments)
    elif "attributes" in forced and attributes.count:  # as without the trace: kept only
        attributes = dataclasses.replace(attributes, count=attributes.count - result.rejected)
    return hi_z, depth_testing, attributes


def _render_multisampled(clipped, window, culled, effects, offsets, a, centroid, colour) -> Frame:
    """The multisampled rest of :func:`render`, after clipping, the viewport and culling
    (``a``: the checked arguments; ``colour``: the blend state and the depth masks)."""
    blending, writes = colour
    size = (a.width, a.height)
    options = (a.depth_test, a.depth_format, a.interpolation, a.trace, centroid)
    multi, more = multisample_stage(
        clipped, window, culled, size, a.subpixel_bits, offsets, options, a.forced,
        (writes, blending.blending),
    )  # fmt: skip
    plan = Plan((*effects, *more))
    debug = None
    if a.trace:
        debug = DebugInputs(a, clipped, multi.offsets, centroid, None, writes=writes,
                            blend=blending if blending.buffer else None)  # fmt: skip
    frame = _multi_frame(multi, clipped, window, culled, size, plan, debug)
    if not blending.blending:
        return with_colour(frame, blending)
    slot, src = multi.passed  # every sample that passed, and its pair's colour
    blended = blend_stage(slot, src, (a.height, a.width), len(multi.offsets), blending)
    return with_colour(frame, blending, *blended)


def _check_samples(samples, centroid, overrides=None):
    """The sample offsets (S, 2), or None for one sample at the centre (``centroid``, a
    bool, then changes nothing), and ``centroid``; the one-sample rules of ``overrides``
    need one sample (ValueError)."""
    centroid = as_bool("centroid", centroid)
    offsets = None if is_single(samples) else as_samples(samples)
    single = [n for n in overrides.given if n in SINGLE_SAMPLE_RULES] if overrides else []
    if offsets is not None and single:
        raise ValueError(f"overrides: the {', '.join(single)} rule(s) replace one-sample stages; "
                         "render with samples=1 (under MSAA only blend and resolve apply)")  # fmt: skip
    return offsets, centroid


def _check_derivatives(derivatives, where, n, offsets):
    """The derivative mode (None: off) and the triangles that want derivatives (None: all)."""
    mode = as_derivative_mode(derivatives)
    if offsets is not None and mode is not None:
        raise ValueError("derivatives: quad derivatives are simulated with samples=1 only")
    return mode, _check_where(where, n)


def _check_where(where, n):
    if where is None:
        return None
    arr = np.asarray(where)
    if arr.shape != (n,) or arr.dtype != bool:
        raise ValueError(f"derivatives_where must be a bool array of shape ({n},), got {arr!r}")
    return arr


def _image(visible, values, width, height) -> np.ndarray:
    """(H, W, k) image of per-visible-pixel values, NaN elsewhere.

    Stored channel by channel ((k, H, W) seen through a transpose): scattering one
    contiguous plane per channel is about twice as fast as scattering k-wide rows.
    """
    k = values.shape[1]
    out = np.full((k, width * height), np.nan)
    for j in range(k):
        out[j, visible.pixels] = values[:, j]
    return out.reshape(k, height, width).transpose(1, 2, 0)


def _frame(visible, values, clipped, frags, width, height, plan, record, ddx=None,
           ddy=None) -> Frame:  # fmt: skip
    """Scatter the visible pixels' triangle, depth, attributes (and derivatives) into images."""
    triangle_id = np.full(width * height, -1, dtype=np.int64)
    triangle_id[visible.pixels] = clipped.parent[frags.tri[visible.winner]]
    depth = np.full(width * height, np.nan)
    depth[visible.pixels] = visible.buffer_depth  # only depth that was written
    return Frame(
        triangle_id=triangle_id.reshape(height, width),
        attrs=_image(visible, values, width, height),
        depth=depth.reshape(height, width),
        plan=plan,
        trace=record or None,
        ddx=None if ddx is None else _image(visible, ddx, width, height),
        ddy=None if ddy is None else _image(visible, ddy, width, height),
    )


def _multi_frame(multi, clipped, window, culled, size, plan, debug) -> Frame:
    """The :class:`Frame` of a multisampled render (input triangle ids, (H, W, ...) images)."""
    width, height = size
    k = clipped.attrs.shape[2]

    parent = clipped.parent  # input ids (None: nothing was clipped, the same ids)
    if np.array_equal(parent, np.arange(len(parent))):
        parent = None

    def ids(sub):  # input triangle ids (-1 stays -1; -1 also when nothing survived clipping)
        return sub if parent is None else np.r_[parent, -1][sub]

    record = None
    if debug is not None:  # the per-sample entries in drawing order, then the pixels decided whole
        r = dict(multi.record)
        slot = r["pixel"] * len(multi.offsets) + r["sample"]
        order = np.argsort(slot * r["n_tri"] + r["tri"])  # by sample, drawing order inside
        for name in ("tri", "pixel", "sample", "depth"):
            r[name] = r[name][order]
        r["writes"] = None if debug.writes is None else debug.writes[r["tri"]]
        r["slot"] = slot[order]
        tri = np.concatenate([r["tri"], r["whole_tri"]])
        row, col = np.divmod(np.concatenate([r["pixel"], r["whole_pixel"]]), width)
        record = RenderTrace(
            clipped.status, clipped.polygons, window, clipped.parent, culled,
            clipped.parent[tri], row, col,
            np.concatenate([r["depth"], np.full(len(r["whole_tri"]), np.nan)]),
            np.concatenate([
                passed_on_arrival(r["slot"], r["depth"], r["writes"], r["depth_test"]),
                np.ones(len(r["whole_tri"]), dtype=bool),
            ]),
            np.concatenate([r["sample"], np.full(len(r["whole_tri"]), -1)]),
            debug=debug,
        )  # fmt: skip
    return Frame(
        triangle_id=ids(multi.owner).reshape(height, width),
        attrs=multi.attrs.reshape(k, height, width).transpose(1, 2, 0),
        depth=multi.depth.reshape(height, width),
        plan=plan,
        trace=record,
        sample_triangle_id=replace(multi.sample_tri, parent=parent),  # built on first read
        sample_depth=multi.sample_depth,  # built on first read
        sample_attrs=multi.sample_attrs,
        samples=multi.offsets,
    )


def _record(clipped, window, culled, frags, visible, quads, cut, a, colour) -> RenderTrace:
    """The trace of every stage (plain arrays, see :class:`RenderTrace`), with the replay of
    a GPU's early-z and Hi-Z in drawing order; ``a`` are the checked inputs, ``colour`` the
    depth masks and the blend state."""
    writes, blending = colour
    width, height, depth_format = a.width, a.height, a.depth_format
    hiz = None  # with a replaced depth rule there is no package early-z to replay
    if rule(a.overrides, "depth") is None:
        hiz = replay_stage(frags, window, visible, width, height, depth_format)
    return RenderTrace(
        clip_status=clipped.status,
        clip_polygons=clipped.polygons,
        window=window,
        parent=clipped.parent,
        culled=culled,
        fragment_triangle=clipped.parent[frags.tri],
        fragment_row=frags.row,
        fragment_col=frags.col,
        fragment_depth=visible.depth,
        # the replay already ran the test in drawing order: the same answers, once
        fragment_passed=visible.passed if hiz is None else hiz.fragment_passed,
        quads=quads,
        hiz=hiz,
        hiz_tiles=None if cut is None else cut.result,
        debug=DebugInputs(a, clipped, None, False, frags, visible.pixel, writes,
                          blending if blending.buffer else None),
    )  # fmt: skip
