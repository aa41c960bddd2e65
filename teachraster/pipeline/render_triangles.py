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
6. perspective-correct interpolation of the attributes, at the visible pixels only;
7. on request, their screen-space derivatives from 2×2 quads with helper pixels
   (:mod:`teachraster.pipeline.quad_derivatives`), for texture filtering.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..core.fill import CULL
from ..core.interpolation import MODES
from ..core.snapping import SUBPIXEL_BITS, check_bits
from ..core.validate import as_finite, as_size, check_choice
from .depth import DEPTH_FORMATS
from .quad_derivatives import QuadTrace, as_derivative_mode, derivatives_stage
from .render_plan import Plan, parse_force
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
    quads : QuadTrace or None
        The 2×2 quads and helper pixels evaluated for derivatives, when they were.
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
    quads: QuadTrace | None = None


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
    ddx, ddy : (H, W, k) float64 or None
        Screen-space derivatives of the attributes from 2×2 quads (``derivatives=``): per
        pixel step right and per pixel step down; NaN where uncovered. None when not computed.
    """

    triangle_id: np.ndarray
    attrs: np.ndarray
    depth: np.ndarray
    plan: Plan
    trace: RenderTrace | None = None
    ddx: np.ndarray | None = None
    ddy: np.ndarray | None = None

    @property
    def coverage(self) -> np.ndarray:
        """(H, W) bool: pixels some triangle wrote."""
        return self.triangle_id >= 0


def _check_clip(clip, attrs):
    if np.size(clip) == 0:  # an empty scene, however it is spelt ([] or (0, 3, 4))
        clip = np.zeros((0, 3, 4))
    clip = as_finite("clip", clip, (None, 3, 4))
    n = len(clip)
    if attrs is None:
        return clip, np.zeros((n, 3, 0))
    arr = np.asarray(attrs, dtype=np.float64)
    if arr.ndim == 2:
        arr = arr[:, :, None]
    arr = as_finite("attrs", arr, (n, 3, None))
    return clip, arr


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
    derivatives=False,
    derivatives_where=None,
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
    derivatives : bool or {"coarse", "fine"}
        Also compute ``frame.ddx``, ``frame.ddy`` from 2×2 quads: ``True`` or ``"coarse"``
        (one pair per quad, as llvmpipe) or ``"fine"`` (per row / column); see
        :mod:`teachraster.pipeline.quad_derivatives`.
    derivatives_where : (N,) bool array-like, optional
        Only the pixels of these input triangles get derivatives (NaN elsewhere); how
        ``render(scene, ...)`` limits them to the triangles a texture filter minifies.

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
    clip, attrs = _check_clip(clip, attrs)
    width, height = as_size("width", width), as_size("height", height)
    check_choice("cull", cull, CULL)
    check_choice("depth_format", depth_format, DEPTH_FORMATS)
    check_choice("interpolation", interpolation, MODES)
    subpixel_bits = check_bits(subpixel_bits)
    forced = parse_force(force)
    mode = as_derivative_mode(derivatives)
    where = _check_where(derivatives_where, len(clip))

    clipped, clipping = clip_stage(clip, attrs, width, height, subpixel_bits, forced)
    window = viewport_stage(clipped, width, height)
    culled, culling = cull_stage(window, cull, subpixel_bits)
    frags = fill_stage(window, width, height, subpixel_bits, culled)
    visible, depth_testing = depth_stage(
        frags, window, width, height, depth_test, depth_format, forced
    )
    values, (perspective, attributes) = interpolate_stage(
        frags, visible, clipped, interpolation, forced
    )

    ddx, ddy, quads, derivs = derivatives_stage(
        frags, visible, clipped, (width, height), mode,
        None if where is None else where[clipped.parent], interpolation, forced, trace,
    )  # fmt: skip

    plan = Plan((clipping, culling, depth_testing, perspective, attributes, derivs))
    record = _record(clipped, window, culled, frags, visible, quads) if trace else None
    frame = _frame(visible, values, clipped, frags, width, height, plan, record)
    if ddx is None:
        return frame
    return replace(frame, ddx=_image(visible, ddx, width, height),
                   ddy=_image(visible, ddy, width, height))  # fmt: skip


def _check_where(where, n):
    if where is None:
        return None
    arr = np.asarray(where)
    if arr.shape != (n,) or arr.dtype != bool:
        raise ValueError(f"derivatives_where must be a bool array of shape ({n},), got {arr!r}")
    return arr


def _image(visible, values, width, height) -> np.ndarray:
    """(H, W, k) image of per-visible-pixel values, NaN elsewhere."""
    out = np.full((width * height, values.shape[1]), np.nan)
    out[visible.pixels] = values
    return out.reshape(height, width, values.shape[1])


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


def _record(clipped, window, culled, frags, visible, quads=None) -> RenderTrace:
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
        quads=quads,
    )
