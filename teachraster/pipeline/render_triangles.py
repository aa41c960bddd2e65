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
   (:mod:`teachraster.pipeline.zbuffer`);
6. perspective-correct interpolation of the attributes, at the visible pixels only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.sample_patterns import as_samples, is_single
from ..core.snapping import SUBPIXEL_BITS
from .inputs import check_render
from .multisampling import multisample_stage
from .render_plan import Plan
from .stages import (
    clip_stage,
    cull_stage,
    depth_stage,
    fill_stage,
    interpolate_stage,
    viewport_stage,
)
from .zbuffer import passed_on_arrival


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


@dataclass(frozen=True)
class Frame:
    """The result of :func:`render`.

    Attributes
    ----------
    triangle_id : (H, W) int64
        Index of the input triangle that wrote each pixel, -1 where none did.
    attrs : (H, W, k) float64
        Perspective-correct attributes, NaN where uncovered.
    depth : (H, W) float64
        Window depth as stored in the depth buffer, NaN where uncovered.
    plan : Plan
        Which effects were simulated, for how much, and why.
    trace : RenderTrace or None
        Every stage's record, when ``trace=True``.
    sample_triangle_id : (H, W, S) int64 or None
        With ``samples`` other than 1: the input triangle each sample shows, -1 none.
        ``triangle_id``, ``depth`` and ``attrs`` then describe the triangle owning most of
        the pixel's samples (ties: the earlier), evaluated once for the pixel.
    sample_depth : (H, W, S) float64 or None
        The depth buffer, one depth per sample, NaN where uncovered.
    sample_attrs : (H, W, S, k) float64 or None
        The attributes each sample holds: those of its triangle, evaluated once per pixel
        (at the centre, extrapolated when outside), NaN where uncovered.
    samples : (S, 2) float64 or None
        The sample offsets inside the pixel as tested, in px.
    """

    triangle_id: np.ndarray
    attrs: np.ndarray
    depth: np.ndarray
    plan: Plan
    trace: RenderTrace | None = None
    sample_triangle_id: np.ndarray | None = None
    sample_depth: np.ndarray | None = None
    sample_attrs: np.ndarray | None = None
    samples: np.ndarray | None = None

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
        if ids is None:
            ids = self.triangle_id[..., None]
            values = np.asarray(values, dtype=np.float64)[:, :, None]
        values = np.asarray(values, dtype=np.float64)
        if values.shape[:3] != ids.shape:
            raise ValueError(f"values must have shape {ids.shape} (+ channels), got {values.shape}")
        covered = (ids >= 0).reshape(*ids.shape, *([1] * (values.ndim - 3)))
        bg = np.broadcast_to(np.asarray(background, dtype=np.float64), values.shape[3:])
        return np.where(covered, values, bg).mean(axis=2)


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
) -> Frame:
    """Render clip-space triangles into a ``height`` × ``width`` frame.

    Parameters
    ----------
    clip : (N, 3, 4) array-like
        Clip-space vertices (x, y, z, w) of N triangles, e.g. ``projection @ view @ p``.
    width, height : int
        Frame size in pixels.
    attrs : (N, 3) or (N, 3, k) array-like, optional
        Per-vertex attributes, interpolated perspective-correctly.
    depth_test : bool
        z-buffer on (nearer wins, ties keep the earlier triangle) or off (later wins).
    cull : {None, "back", "front"}
        Remove back-facing (clockwise on screen) or front-facing triangles.
    depth_format : {"float64", "float32", "unorm24", "unorm16"}
        What the depth buffer stores; fewer bits show z-fighting.
    interpolation : {"perspective", "affine"}
        Perspective-correct attributes (GLSL ``smooth``, the default) or plain
        screen-space ones (``noperspective``), to show the difference.
    force : None, "all" or names from ``teachraster.pipeline.render_plan.FORCEABLE``
        Run these effects everywhere, even where the plan says they change nothing.
    trace : bool
        Record every stage (see :class:`RenderTrace`).
    subpixel_bits : int or None
        Snapping precision, as in :func:`teachraster.rasterize`.
    max_pixels : int, optional
        Largest ``width * height`` allowed (default 2**28 = 16384²): a larger frame raises
        a ValueError saying what it would cost, before anything is allocated.

    Raises
    ------
    ValueError, TypeError
        For a bad argument, naming it (see :mod:`teachraster.pipeline.inputs`).
    samples : int or (S, 2) array-like
        Multisampling (MSAA): 1, 2, 4, 8, 16 (standard patterns) or offsets in [0, 1)².
        Coverage and the depth test per sample, attributes once per pixel and triangle
        (see :class:`Frame` and :mod:`teachraster.pipeline.multisampling`).

    Examples
    --------
    >>> clip = [[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]]
    >>> frame = render(clip, 4, 4)
    >>> frame.triangle_id        # centres on the diagonal: a right edge, so not covered
    array([[-1, -1, -1, -1],
           [ 0, -1, -1, -1],
           [ 0,  0, -1, -1],
           [ 0,  0,  0, -1]])
    >>> print(frame.plan["clipping"].why)
    no triangle crosses the near or far plane: nothing to clip
    """
    a = check_render(clip, width, height, attrs=attrs, depth_test=depth_test, cull=cull,
                     depth_format=depth_format, interpolation=interpolation, force=force,
                     trace=trace, subpixel_bits=subpixel_bits, max_pixels=max_pixels)  # fmt: skip
    clip, attrs, width, height, subpixel_bits = a.clip, a.attrs, a.width, a.height, a.subpixel_bits
    depth_test, trace, forced = a.depth_test, a.trace, a.forced
    offsets = None if is_single(samples) else as_samples(samples)

    clipped, clipping = clip_stage(clip, attrs, width, height, subpixel_bits, forced)
    window = viewport_stage(clipped, width, height)
    culled, culling = cull_stage(window, cull, subpixel_bits)
    if offsets is not None:
        multi, effects = multisample_stage(
            clipped, window, culled, (width, height), subpixel_bits, offsets,
            (depth_test, depth_format, interpolation), forced,
        )  # fmt: skip
        return _multi_frame(multi, clipped, window, culled, (width, height),
                            Plan((clipping, culling, *effects)), trace)  # fmt: skip
    frags = fill_stage(window, width, height, subpixel_bits, culled)
    visible, depth_testing = depth_stage(
        frags, window, width, height, depth_test, depth_format, forced
    )
    values, (perspective, attributes) = interpolate_stage(
        frags, visible, clipped, interpolation, forced
    )

    plan = Plan((clipping, culling, depth_testing, perspective, attributes))
    record = _record(clipped, window, culled, frags, visible) if trace else None
    return _frame(visible, values, clipped, frags, width, height, plan, record)


def _frame(visible, values, clipped, frags, width, height, plan, record) -> Frame:
    """Scatter the visible pixels' triangle, depth and attributes into (H, W) images."""
    k = values.shape[1]
    triangle_id = np.full(width * height, -1, dtype=np.int64)
    triangle_id[visible.pixels] = clipped.parent[frags.tri[visible.winner]]
    depth = np.full(width * height, np.nan)
    depth[visible.pixels] = visible.depth[visible.winner]
    attrs = np.full((width * height, k), np.nan)
    attrs[visible.pixels] = values
    return Frame(
        triangle_id=triangle_id.reshape(height, width),
        attrs=attrs.reshape(height, width, k),
        depth=depth.reshape(height, width),
        plan=plan,
        trace=record,
    )


def _multi_frame(multi, clipped, window, culled, size, plan, trace) -> Frame:
    """The :class:`Frame` of a multisampled render (input triangle ids, (H, W, ...) images)."""
    width, height = size
    n_s, k = len(multi.offsets), clipped.attrs.shape[2]

    def ids(sub):  # input triangle ids (-1 stays -1; -1 also when nothing survived clipping)
        parent = np.r_[clipped.parent, -1]  # index -1 reads the appended -1
        return parent[sub]

    record = None
    if trace:  # the per-sample entries in drawing order, then the pixels decided whole
        r = multi.record
        tri = np.concatenate([r["tri"], r["whole_tri"]])
        row, col = np.divmod(np.concatenate([r["pixel"], r["whole_pixel"]]), width)
        record = RenderTrace(
            clipped.status, clipped.polygons, window, clipped.parent, culled,
            clipped.parent[tri], row, col,
            np.concatenate([r["depth"], np.full(len(r["whole_tri"]), np.nan)]),
            np.concatenate([
                passed_on_arrival(r["slot"], r["depth"]) if r["depth_test"]
                else np.ones(len(r["slot"]), dtype=bool),
                np.ones(len(r["whole_tri"]), dtype=bool),
            ]),
            np.concatenate([r["sample"], np.full(len(r["whole_tri"]), -1)]),
        )  # fmt: skip
    return Frame(
        triangle_id=ids(multi.owner).reshape(height, width),
        attrs=multi.attrs.reshape(height, width, k),
        depth=multi.depth.reshape(height, width),
        plan=plan,
        trace=record,
        sample_triangle_id=ids(multi.sample_tri).reshape(height, width, n_s),
        sample_depth=multi.sample_depth.reshape(height, width, n_s),
        sample_attrs=multi.sample_attrs.reshape(height, width, n_s, k),
        samples=multi.offsets,
    )


def _record(clipped, window, culled, frags, visible) -> RenderTrace:
    """The trace of every stage (plain arrays, see :class:`RenderTrace`)."""
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
        fragment_passed=visible.passed,
    )
