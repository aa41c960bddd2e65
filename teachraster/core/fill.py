"""``rasterize``: fill one triangle by span tables or half-planes, then interpolate."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from . import half_planes, span_tables, tiles
from .barycentrics import barycentric_pixels
from .bbox import BBox, pixel_bbox
from .edges import culled as culled_by
from .edges import setup_edges
from .interpolation import FILL_MODES, MODES, blend, interpolate, subdivided
from .snapping import SUBPIXEL_BITS, check_bits
from .trace import FillTrace
from .triangle import Triangle
from .validate import as_bool, as_int, as_size, check_choice, check_pixels

METHODS = {"halfplane": half_planes.fill, "span": span_tables.fill, "tiled": tiles.fill}
CULL = (None, "back", "front")


@dataclass(frozen=True)
class Fill:
    """The result of :func:`rasterize`.

    Attributes
    ----------
    coverage : (height, width) bool
        Pixels whose centres the triangle covers.
    attrs : mapping of name to (height, width) or (height, width, k) float64
        Interpolated attributes, NaN outside coverage.
    depth : (height, width) float64 or None
        Window depth (affine in screen space), NaN outside; None when no z was given.
    trace : FillTrace or None
        Every step, when ``trace=True``.
    """

    coverage: np.ndarray
    attrs: Mapping[str, np.ndarray]
    depth: np.ndarray | None
    trace: FillTrace | None = None


def rasterize(
    tri: Triangle,
    width: int,
    height: int,
    *,
    method: str = "halfplane",
    interpolation: str = "perspective",
    subdivision: int = 8,
    trace: bool = False,
    subpixel_bits: int | None = SUBPIXEL_BITS,
    cull: str | None = None,
    block_sizes=tiles.BLOCK_SIZES,
    max_pixels: int | None = None,
) -> Fill:
    """Fill a triangle into a ``height`` × ``width`` image and interpolate its attributes.

    Parameters
    ----------
    tri : Triangle
        Screen-space triangle (see ``CONVENTIONS``: x right, y down, pixel centres at
        ``(j + 0.5, i + 0.5)``).
    width, height : int
        Image size in pixels.
    method : {"halfplane", "span", "tiled"}
        Half-plane edge tests over the bounding box, span tables (split at u4, fill
        raster lines), or hierarchical blocks (accept or reject whole blocks by their
        corners, test pixels only in partial blocks of the smallest size). All three cover
        exactly the same pixels.
    interpolation : {"perspective", "affine", "subdivided"}
        Perspective-correct (f/w over 1/w), plain screen-space interpolation, or
        perspective-correct only at every ``subdivision``-th pixel of each span and at
        its ends with affine steps in between (the classic software-renderer trade-off).
    subdivision : int
        Pixels between exact evaluations for ``"subdivided"`` (1 = exact).
    trace : bool
        Record every step (see :class:`~teachraster.core.trace.FillTrace`). Never changes
        the pixels.
    subpixel_bits : int or None
        Vertices are snapped to ``1 / 2**subpixel_bits`` px before coverage is decided
        (8, as in Direct3D). None keeps raw floats, to show what precision does.
    cull : {None, "back", "front"}
        Drop back-facing (clockwise on screen) or front-facing triangles.
    block_sizes : sequence of int
        Block sizes of ``method="tiled"``, largest first, each dividing the one before
        (llvmpipe's 64, 16, 4 by default). Checked for every method.
    max_pixels : int, optional
        Largest ``width * height`` allowed (default 2**28 = 16384²): a larger image raises
        a ValueError saying what it would cost, before anything is allocated.

    Examples
    --------
    >>> import teachraster as tr
    >>> tri = tr.Triangle([[0, 0], [4, 0], [0, 4]], attrs={"u": [0.0, 1.0, 0.0]})
    >>> fill = tr.rasterize(tri, 4, 4)
    >>> fill.coverage.astype(int)
    array([[1, 1, 1, 0],
           [1, 1, 0, 0],
           [1, 0, 0, 0],
           [0, 0, 0, 0]])
    >>> float(fill.attrs["u"][0, 1])     # at the centre (1.5, 0.5): u = x / 4
    0.375
    """
    if not isinstance(tri, Triangle):
        raise TypeError(f"tri must be a teachraster.Triangle, got {type(tri).__name__}")
    width, height = as_size("width", width), as_size("height", height)
    channels = sum(f.size // 3 for f in tri.attrs.values())
    check_pixels(width, height, max_pixels, 9 + 8 * channels)  # coverage, depth, attributes
    check_choice("method", method, tuple(METHODS))
    check_choice("interpolation", interpolation, FILL_MODES)
    subdivision = as_int("subdivision", subdivision, minimum=1)
    check_choice("cull", cull, CULL)
    trace = as_bool("trace", trace)
    subpixel_bits = check_bits(subpixel_bits)
    block_sizes = tiles.check_block_sizes(block_sizes)

    setup = setup_edges(tri.xy, subpixel_bits)
    box = pixel_bbox(setup, width, height)
    culled = bool(culled_by(setup.original_area2, cull))
    if culled:
        local, algo_trace = np.zeros(box.shape, dtype=bool), None
    else:
        extra = {"block_sizes": block_sizes, "image": (height, width)} if method == "tiled" else {}
        local, algo_trace = METHODS[method](setup, box, trace, **extra)
    if setup.area2 == 0:  # zero area covers nothing (exact arithmetic already ensures it)
        local[:] = False

    coverage = np.zeros((height, width), dtype=bool)
    coverage[box.row0 : box.row1, box.col0 : box.col1] = local
    rows, cols = np.nonzero(coverage)  # row-major, the order of every per-pixel array
    lam = barycentric_pixels(setup, rows, cols)

    # All attributes travel as one (3, K) block, so the per-pixel work (weights, blend,
    # scatter) runs once per fill rather than once per attribute.
    packed, layout = _pack(tri.attrs)
    modes = MODES if trace else (interpolation,)
    values = {mode: interpolate(lam, packed, tri.w, mode) for mode in modes if mode in MODES}
    if interpolation == "subdivided":
        # A step beyond the widest span anchors only the span ends, like any larger step;
        # capping it keeps every index sum in int64.
        step = min(subdivision, width + 1)
        values["subdivided"] = subdivided(lam, rows, packed, tri.w, step)
    depth_values = None if tri.z is None else blend(lam, tri.z)

    image = np.full((height, width, packed.shape[1]), np.nan)
    image[coverage] = values[interpolation]
    attrs = _unpack(image, layout)
    depth = None
    if depth_values is not None:
        depth = np.full((height, width), np.nan)
        depth[coverage] = depth_values
    fill_trace = None
    if trace:
        fill_trace = _record(
            tri, setup, box, method, interpolation, subpixel_bits, (width, height),
            culled, local, algo_trace, lam,
            {mode: _unpack(v, layout) for mode, v in values.items()}, depth_values,
            subdivision if interpolation == "subdivided" else None,
        )  # fmt: skip
    return Fill(coverage=coverage, attrs=attrs, depth=depth, trace=fill_trace)


def _pack(attrs: Mapping[str, np.ndarray]):
    """Stack (3,) and (3, k) attributes into one (3, K) block, remembering the layout."""
    layout, blocks, start = {}, [], 0
    for name, f in attrs.items():
        block = f.reshape(3, -1)
        layout[name] = start if f.ndim == 1 else slice(start, start + block.shape[1])
        blocks.append(block)
        start += block.shape[1]
    packed = np.concatenate(blocks, axis=1) if blocks else np.zeros((3, 0))
    return packed, layout


def _unpack(block: np.ndarray, layout) -> dict[str, np.ndarray]:
    """Views of each attribute in a (..., K) block: (...,) for scalars, (..., k) otherwise."""
    return {name: block[..., where] for name, where in layout.items()}


def _record(tri, setup, box: BBox, method, interpolation, bits, size, culled, local,
            algo_trace, lam, values, depth_values, subdivision) -> FillTrace:  # fmt: skip
    """The FillTrace of one fill: the data only; the trace numbers the steps and writes
    every caption itself."""
    width, height = size
    px = 1.0 / float(setup.unit)
    snapped = setup.p[np.argsort(setup.perm)].astype(np.float64) * px
    area = float(setup.original_area2) * px * px / 2

    return FillTrace(
        method=method,
        interpolation=interpolation,
        subpixel_bits=bits,
        width=width,
        height=height,
        xy=tri.xy,
        snapped=snapped,
        signed_area=area,
        front_facing=area < 0,
        culled=culled,
        edges=setup.edges,
        top_left=setup.top_left,
        bbox=box,
        covered=local,
        pixel_barycentric=lam,
        pixel_affine=values["affine"],
        pixel_perspective=values["perspective"],
        pixel_depth=depth_values,
        span=algo_trace if method == "span" else None,
        halfplane=algo_trace if method == "halfplane" else None,
        blocks=algo_trace if method == "tiled" else None,
        subdivision=subdivision,
        pixel_subdivided=values.get("subdivided"),
    )
