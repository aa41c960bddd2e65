"""``render``: clip, cull, fill, depth-test and interpolate a list of clip-space triangles.

The pipeline, in order (each stage simulated only where the scene needs it, see
:mod:`teachraster.pipeline.render_plan`):

1. homogeneous clipping against near and far (:mod:`teachraster.pipeline.clipping`);
2. the viewport transform to window coordinates (:mod:`teachraster.pipeline.viewport`);
3. back- or front-face culling, if asked;
4. filling every triangle at once (:mod:`teachraster.pipeline.batched_fill`, identical pixels to
   :func:`teachraster.rasterize`);
5. the z-buffer (Ritschel, *Interpolation and z-buffering*): a fragment is kept when its stored depth is strictly smaller
   than the buffer's, so ties keep the earlier triangle; without the depth test later
   triangles overwrite earlier ones;
6. perspective-correct interpolation of the attributes, at the visible pixels only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.interpolation import blend_each, convex_weights, weights_per_row
from ..core.snapping import SUBPIXEL_BITS
from .batched_fill import rasterize_batch, snapped_area2
from .clipping import CLIPPED, DROPPED, INSIDE, classify, clip_triangles
from .depth import quantize
from .inputs import check_render
from .render_plan import Effect, Plan
from .viewport import to_window


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


def _guard(width: int, height: int, bits: int | None) -> float:
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
    n_in, k = len(clip), attrs.shape[2]
    effects = []

    # 1. clipping, only for triangles a plane cuts
    clipped = clip_triangles(
        clip, attrs, guard=_guard(width, height, subpixel_bits), force="clipping" in forced
    )
    n_cut = int((clipped.status == CLIPPED).sum())
    n_drop = int((clipped.status == DROPPED).sum())
    # Which cuts were the near/far planes, and which only the guard band far off screen.
    n_guard = int(((clipped.status == CLIPPED) & (classify(clip, None) == INSIDE)).sum())
    n_depth = n_cut - n_guard
    why = (
        f"{n_depth} triangle(s) cross the near or far plane and were cut in clip space"
        if n_depth
        else "no triangle crosses the near or far plane: nothing to clip"
    )
    if n_guard:
        why += (
            f"; {n_guard} reach far beyond the image and were trimmed at the guard band "
            "(invisible parts only)"
        )
    if n_drop:
        why += f"; {n_drop} lie wholly outside and were dropped"
    if "clipping" in forced:
        why = "every triangle sent through the clipper; " + why
    effects.append(
        Effect("clipping", bool(n_cut) or "clipping" in forced, n_cut, n_in, "triangles", why,
               "clipping" in forced)
    )  # fmt: skip

    # 2. viewport transform (safe: clipping left w > 0)
    window = to_window(clipped.clip, width, height)
    w = clipped.clip[:, :, 3]
    m_tris = len(window)

    # 3. culling by screen winding (front-facing = counter-clockwise on screen)
    # Facing is decided on the snapped triangle, the one that is actually filled.
    signed = snapped_area2(window[:, :, :2], subpixel_bits)
    culled = np.zeros(m_tris, dtype=bool)
    if cull == "back":
        culled = signed > 0
    elif cull == "front":
        culled = signed < 0
    effects.append(
        Effect(
            "culling", cull is not None, int(culled.sum()), m_tris, "triangles",
            f"cull={cull!r} asked: {int(culled.sum())} {cull}-facing triangle(s) removed"
            if cull else "not asked (cull=None): both windings are drawn",
        )
    )  # fmt: skip

    # 4. fill every triangle at once
    # Coverage on the snapped grid; weights from the unsnapped positions, as GPUs set up
    # attributes (so the new vertices clipping creates interpolate exactly).
    frags = rasterize_batch(window[:, :, :2], width, height, subpixel_bits=subpixel_bits,
                            skip=culled, snapped_weights=False)  # fmt: skip
    depth = blend_each(frags.lam, window[frags.tri, :, 2:3])[:, 0]
    depth = quantize(depth, depth_format)
    pixel = frags.row * width + frags.col

    # 5. visibility (forcing the test means nothing when it is switched off)
    force_test = "depth_test" in forced and depth_test
    winner, passed, tested = _resolve(pixel, frags.tri, depth, width * height, depth_test,
                                      force_test, trace)  # fmt: skip
    covered = int((winner >= 0).sum())
    if not depth_test:
        why = "off (depth_test=False): later triangles overwrite earlier ones"
        tested = 0
    elif force_test:
        why = "every fragment depth-tested against the buffer"
    else:
        why = (
            f"fragments of 2+ triangles land on {tested:,} pixel(s): tested there; "
            f"the other {covered - tested:,} covered pixel(s) hold a single fragment"
        )
    effects.append(
        Effect("depth_test", depth_test and (tested > 0 or force_test), tested, covered,
               "pixels", why, force_test)
    )  # fmt: skip

    # 6. attributes, perspective-correct, at visible pixels only (or every fragment if forced)
    unequal = ~np.all(w == w[:, :1], axis=1)
    if interpolation == "affine":
        unequal[:] = False
    where = np.flatnonzero(winner >= 0)
    shade = np.arange(len(frags.tri)) if "attributes" in forced else winner[where]
    divide_all = "perspective" in forced and interpolation == "perspective"
    values = _interpolate(frags, shade, w, clipped.attrs, unequal, divide_all)
    if "attributes" in forced:
        values = values[winner[where]]
    # Count the triangles whose visible (or, forced, all) fragments were really divided.
    shaded_tris = np.unique(frags.tri[shade])
    n_persp = len(shaded_tris) if divide_all else int(unequal[shaded_tris].sum())
    if k == 0:
        why = "no attributes given: nothing to interpolate"
    elif len(shaded_tris) == 0:
        why = "no triangle is visible: nothing to interpolate"
    elif interpolation == "affine":
        why = "interpolation='affine' asked: screen-space values, no divide by w"
        n_persp = 0
    elif divide_all:
        why = "divide by w at every pixel, even where all three w are equal"
    elif n_persp:
        why = (
            f"w differs across the vertices of {n_persp} of the {len(shaded_tris)} visible "
            "triangle(s): f/w over 1/w there; equal w makes affine interpolation exact elsewhere"
        )
    else:
        why = "every triangle has equal w at its vertices: affine interpolation is exact"
    effects.append(
        Effect("perspective", k > 0 and n_persp > 0, n_persp if k else 0, m_tris, "triangles",
               why, divide_all)
    )  # fmt: skip
    n_shaded = len(shade) if k else 0
    effects.append(
        Effect(
            "attributes", k > 0, n_shaded, len(frags.tri), "fragments",
            (f"{k} channel(s) at every fragment, hidden ones included" if "attributes" in forced
             else f"{k} channel(s) at the {covered:,} visible pixel(s) only, not at hidden "
             "fragments") if k else "no attributes given",
            "attributes" in forced,
        )
    )  # fmt: skip

    triangle_id = np.full(width * height, -1, dtype=np.int64)
    triangle_id[where] = clipped.parent[frags.tri[winner[where]]]
    out_depth = np.full(width * height, np.nan)
    out_depth[where] = depth[winner[where]]
    out_attrs = np.full((width * height, k), np.nan)
    out_attrs[where] = values
    record = None
    if trace:
        record = RenderTrace(
            clip_status=clipped.status,
            clip_polygons=clipped.polygons,
            window=window,
            parent=clipped.parent,
            culled=culled,
            fragment_triangle=clipped.parent[frags.tri],
            fragment_row=frags.row,
            fragment_col=frags.col,
            fragment_depth=depth,
            fragment_passed=passed,
        )
    return Frame(
        triangle_id=triangle_id.reshape(height, width),
        attrs=out_attrs.reshape(height, width, k),
        depth=out_depth.reshape(height, width),
        plan=Plan(tuple(effects)),
        trace=record,
    )


def _interpolate(frags, shade, w, attrs, unequal, force_perspective):
    """Attributes (len(shade), k) at fragments ``shade``, perspective-correct where needed."""
    k = attrs.shape[2]
    if k == 0 or len(shade) == 0:
        return np.zeros((len(shade), k))
    tri = frags.tri[shade]
    # Weights from the unsnapped set-up can be slightly negative at a covered centre that
    # snapping brought inside an edge: made convex, so the value stays within range.
    weights = convex_weights(frags.lam[shade])
    persp = np.ones(len(tri), dtype=bool) if force_perspective else unequal[tri]
    if persp.any():  # f/w and 1/w are affine in screen space (Ek, *Triangles and Perspective Correct Interpolation*, eq. 19)
        weights[persp] = weights_per_row(weights[persp], w[tri[persp]])
    return blend_each(weights, attrs[tri])


def _resolve(pixel, tri, depth, n_pixels, depth_test, force_test, trace):
    """The z-buffer: winning fragment per pixel (-1 none), pass flags, pixels tested.

    Fragments arrive in drawing order. A pixel reached by one fragment needs no test; where
    several arrive, the nearest wins (strictly smaller depth, so ties keep the earlier).
    """
    count = np.bincount(pixel, minlength=n_pixels)
    multi = count[pixel] > 1
    tested = int((count > 1).sum())
    winner = np.full(n_pixels, -1, dtype=np.int64)
    single = np.flatnonzero(~multi)
    winner[pixel[single]] = single
    passed = np.ones(len(pixel), dtype=bool)
    idx = np.arange(len(pixel)) if force_test else np.flatnonzero(multi)
    if len(idx) == 0:
        return winner, passed, tested
    # Group the contested fragments by pixel, keeping drawing order within each pixel.
    order = idx[np.argsort(pixel[idx], kind="stable")]
    pix = pixel[order]
    starts = np.flatnonzero(np.r_[True, pix[1:] != pix[:-1]])
    rank = np.arange(len(order)) - np.repeat(starts, np.diff(np.r_[starts, len(order)]))
    if not depth_test:  # painter's order: the last fragment drawn wins
        last = np.r_[starts[1:], len(order)] - 1
        winner[pix[last]] = order[last]
        return winner, passed, tested
    # One layer at a time: layer r holds the r-th fragment of every contested pixel, so
    # each layer touches a pixel at most once and the buffer update is a plain scatter.
    buffer = np.full(n_pixels, np.inf)
    for r in range(int(rank.max()) + 1):
        layer = order[rank == r]
        p = pixel[layer]
        ok = depth[layer] < buffer[p]
        passed[layer] = ok
        buffer[p[ok]] = depth[layer[ok]]
        winner[p[ok]] = layer[ok]
    return winner, passed, tested
