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
   (:mod:`teachraster.pipeline.zbuffer`); where fragments overlap, what early-z and Hi-Z
   would save a GPU drawing in order (:mod:`teachraster.pipeline.hierarchical_z`);
6. perspective-correct interpolation of the attributes, at the visible pixels only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.snapping import SUBPIXEL_BITS
from .hierarchical_z import HiZResult, hiz_stage
from .inputs import check_render
from .render_plan import Plan
from .stages import (
    clip_stage,
    cull_stage,
    depth_stage,
    fill_stage,
    interpolate_stage,
    viewport_stage,
)


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
    hiz : HiZResult or None
        Early-z and Hi-Z per block and fragment (None without the depth test).
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
    hiz: HiZResult | None = None


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
    """

    triangle_id: np.ndarray
    attrs: np.ndarray
    depth: np.ndarray
    plan: Plan
    trace: RenderTrace | None = None

    @property
    def coverage(self) -> np.ndarray:
        """(H, W) bool: pixels some triangle wrote."""
        return self.triangle_id >= 0


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

    clipped, clipping = clip_stage(clip, attrs, width, height, subpixel_bits, forced)
    window = viewport_stage(clipped, width, height)
    culled, culling = cull_stage(window, cull, subpixel_bits)
    frags = fill_stage(window, width, height, subpixel_bits, culled)
    visible, depth_testing = depth_stage(
        frags, window, width, height, depth_test, depth_format, forced
    )
    hiz, hi_z = hiz_stage(frags, window, visible, width, height, depth_format, forced)
    values, (perspective, attributes) = interpolate_stage(
        frags, visible, clipped, interpolation, forced
    )

    plan = Plan((clipping, culling, depth_testing, hi_z, perspective, attributes))
    record = _record(clipped, window, culled, frags, visible, hiz) if trace else None
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


def _record(clipped, window, culled, frags, visible, hiz=None) -> RenderTrace:
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
        hiz=hiz,
    )
