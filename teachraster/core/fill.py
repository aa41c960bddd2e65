"""``rasterize``: fill one triangle by span tables or half-planes, then interpolate."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from . import half_planes, span_tables, tiles
from .barycentrics import barycentric_pixels
from .bbox import BBox, pixel_bbox
from .block_shading import cell_size, shade_blocks
from .edges import culled as culled_by
from .edges import setup_edges
from .interpolation import FILL_MODES, MODES, blend, interpolate, subdivided
from .multisample import MultiFill, fill_samples
from .sample_patterns import as_samples, is_single
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
        Multisampled: evaluated where the attributes are.
    trace : FillTrace or None
        Every step, when ``trace=True``.
    sample_coverage : (height, width, S) bool or None
        Coverage of every sample (``samples`` other than 1); ``coverage`` is their "any".
    sample_attrs : mapping of name to (height, width, S) or (height, width, S, k), or None
        Attributes at every covered sample (``per_sample=True``), NaN elsewhere.
    sample_depth : (height, width, S) float64 or None
        Window depth at every covered sample (multisampled with z), NaN elsewhere.
    samples : (S, 2) float64 or None
        The sample offsets inside the pixel as tested (on the internal grid), in px.
    """

    coverage: np.ndarray
    attrs: Mapping[str, np.ndarray]
    depth: np.ndarray | None
    trace: FillTrace | None = None
    sample_coverage: np.ndarray | None = None
    sample_attrs: Mapping[str, np.ndarray] | None = None
    sample_depth: np.ndarray | None = None
    samples: np.ndarray | None = None

    @property
    def coverage_fraction(self) -> np.ndarray:
        """(height, width) float64: the fraction of each pixel's samples covered (0 or 1
        without multisampling)."""
        if self.sample_coverage is None:
            return self.coverage.astype(np.float64)
        return self.sample_coverage.mean(axis=2)


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
    samples=1,
    centroid: bool = False,
    per_sample: bool = False,
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
        Half-plane tests over the bounding box, span tables (split at u4, fill raster
        lines) or hierarchical tiles (``block_sizes``). All cover exactly the same pixels.
    interpolation : {"perspective", "affine", "subdivided"}
        Perspective-correct (f/w over 1/w), plain screen-space, or perspective-correct at
        every ``subdivision``-th pixel of each span and its ends, affine in between.
    subdivision : int
        Pixels between exact evaluations for ``"subdivided"`` (1 = exact).
    trace : bool
        Record every step (:class:`~teachraster.core.trace.FillTrace`); never changes pixels.
    subpixel_bits : int or None
        Vertices are snapped to ``1 / 2**subpixel_bits`` px before coverage is decided
        (8, as in Direct3D). None keeps raw floats, to show what precision does.
    cull : {None, "back", "front"}
        Drop back-facing (clockwise on screen) or front-facing triangles.
    block_sizes : sequence of int
        Tiles: block sizes, largest first, each dividing the one before (64, 16, 4). Cells
        the walk leaves whole are shaded as blocks (:mod:`.block_shading`), same values.
    max_pixels : int, optional
        Largest ``width * height`` (default 2**28): larger raises before allocating.
    samples : int or (S, 2) array-like
        1 (centres), 2, 4, 8, 16 (standard patterns, :func:`~teachraster.sample_pattern`)
        or offsets in [0, 1)²: coverage per sample (``fill.sample_coverage``).
    centroid : bool
        Multisampled: attributes at the covered sample nearest an uncovered centre.
    per_sample : bool
        Supersampling: attributes per covered sample (``fill.sample_attrs``), their mean.

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
    width, height, subdivision, trace, subpixel_bits, block_sizes = _check_args(
        tri, width, height, method, interpolation, subdivision, cull, trace, subpixel_bits,
        max_pixels, block_sizes,
    )  # fmt: skip
    offsets = _check_samples(samples, method, interpolation, centroid, per_sample)
    setup = setup_edges(tri.xy, subpixel_bits)
    box, culled = pixel_bbox(setup, width, height), bool(culled_by(setup.original_area2, cull))
    coverage, local, algo_trace = _fill_centres(setup, box, method, culled, trace, width,
                                                height, block_sizes)  # fmt: skip
    packed, layout = _pack(tri.attrs)  # one (3, K) block: per-pixel work once per fill
    # With samples, they decide coverage; the centres still drive the trace.
    multi = None if offsets is None else fill_samples(
        setup, offsets, (width, height), METHODS[method], coverage, packed, tri,
        (interpolation, centroid, per_sample, trace, culled))  # fmt: skip
    if method == "tiled" and not trace and multi is None and interpolation in MODES:
        return _shade_whole_blocks(tri, setup, coverage, (packed, layout), interpolation,
                                   block_sizes)  # fmt: skip
    lam, values, depth_values = _interpolate_centres(tri, setup, coverage, packed, interpolation,
                                                     subdivision, trace)  # fmt: skip
    fill_trace = None
    if trace:
        fill_trace = _record(
            tri, setup, box, method, interpolation, subpixel_bits, (width, height),
            culled, local, algo_trace, lam,
            {mode: _unpack(v, layout) for mode, v in values.items()}, depth_values,
            subdivision if interpolation == "subdivided" else None,
            None if multi is None else multi.trace,
        )  # fmt: skip
    if multi is not None:
        return _multi_result(multi, layout, fill_trace)
    return _centre_fill(coverage, values[interpolation], depth_values, layout, fill_trace)


def _centre_fill(coverage, values, depth_values, layout, fill_trace) -> Fill:
    """The :class:`Fill` of per-pixel values (row-major, None: nothing was interpolated)."""
    attrs = {} if values is None else _unpack(_place(coverage, values), layout)
    depth = None if depth_values is None else _place(coverage, depth_values)
    return Fill(coverage=coverage, attrs=attrs, depth=depth, trace=fill_trace)


def _shade_whole_blocks(tri, setup, coverage, packing, interpolation, block_sizes):
    """The tiled fill's :class:`Fill`, the cells its walk left whole shaded as blocks (the
    same values, bit for bit: :mod:`.block_shading`)."""
    packed, layout = packing
    if packed.shape[1] == 0 and tri.z is None:  # coverage only: nothing to shade
        return _centre_fill(coverage, None, None, layout, None)
    image, depth = shade_blocks(tri, setup, coverage, packed, interpolation,
                                cell_size(block_sizes))  # fmt: skip
    return Fill(coverage=coverage, attrs=_unpack(image, layout), depth=depth)


def _interpolate_centres(tri, setup, coverage, packed, interpolation, subdivision, trace):
    """Barycentrics, the attribute values of every mode needed and the depth at the covered
    centres, in row-major order (the order of every per-pixel array).

    A trace records both affine and perspective-correct values, whatever mode was asked.
    """
    if packed.shape[1] == 0 and tri.z is None and not trace:
        # Nothing to interpolate and nothing to record: weights would be computed for no one
        # (a coverage-only fill then costs what its algorithm costs, nothing more).
        return None, {interpolation: None}, None
    rows, cols = np.nonzero(coverage)
    lam = barycentric_pixels(setup, rows, cols)
    width = coverage.shape[1]
    modes = MODES if trace else (interpolation,)
    values = {mode: interpolate(lam, packed, tri.w, mode) for mode in modes if mode in MODES}
    if interpolation == "subdivided":
        # A step beyond the widest span anchors only the span ends, like any larger step;
        # capping it keeps every index sum in int64.
        step = min(subdivision, width + 1)
        values["subdivided"] = subdivided(lam, rows, packed, tri.w, step)
    depth_values = None if tri.z is None else blend(lam, tri.z)
    return lam, values, depth_values


def _place(coverage: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Per-pixel ``values`` (n, ...) into an image (H, W, ...), NaN outside ``coverage``."""
    image = np.full((*coverage.shape, *values.shape[1:]), np.nan)
    image[coverage] = values
    return image


def _check_args(tri, width, height, method, interpolation, subdivision, cull, trace, bits,
                max_pixels, block_sizes):  # fmt: skip
    """Validated arguments of :func:`rasterize` (errors name the argument)."""
    if not isinstance(tri, Triangle):
        raise TypeError(f"tri must be a teachraster.Triangle, got {type(tri).__name__}")
    width, height = as_size("width", width), as_size("height", height)
    channels = sum(f.size // 3 for f in tri.attrs.values())
    check_pixels(width, height, max_pixels, 9 + 8 * channels)  # coverage, depth, attributes
    check_choice("method", method, tuple(METHODS))
    check_choice("interpolation", interpolation, FILL_MODES)
    subdivision = as_int("subdivision", subdivision, minimum=1)
    check_choice("cull", cull, CULL)
    return (width, height, subdivision, as_bool("trace", trace), check_bits(bits),
            tiles.check_block_sizes(block_sizes))  # fmt: skip


def _fill_centres(setup, box, method, culled, record, width, height, block_sizes):
    """Pixel-centre coverage (H, W), its bbox-local part and the algorithm's trace."""
    if culled:
        local, algo_trace = np.zeros(box.shape, dtype=bool), None
    else:
        extra = {"block_sizes": block_sizes, "image": (height, width)} if method == "tiled" else {}
        local, algo_trace = METHODS[method](setup, box, record, **extra)
    if setup.area2 == 0:  # zero area covers nothing (exact arithmetic already ensures it)
        local[:] = False
    coverage = np.zeros((height, width), dtype=bool)
    coverage[box.row0 : box.row1, box.col0 : box.col1] = local
    return coverage, local, algo_trace


def _check_samples(samples, method, interpolation, centroid, per_sample):
    """Validated multisampling options: the (S, 2) offsets, or None for one centre sample."""
    centroid = as_bool("centroid", centroid)
    per_sample = as_bool("per_sample", per_sample)
    if is_single(samples):  # one sample at the centre: centroid and per_sample change nothing
        return None
    offsets = as_samples(samples)
    if method not in ("halfplane", "span"):
        raise ValueError(f"samples: method={method!r} fills pixel centres only; use samples=1")
    if interpolation == "subdivided":
        raise ValueError(
            "interpolation: 'subdivided' steps along spans of pixel centres and is not "
            "defined with samples > 1; use 'perspective' or 'affine'"
        )
    return offsets


def _multi_result(multi: MultiFill, layout, fill_trace) -> Fill:
    """The :class:`Fill` of a multisampled rasterisation."""
    return Fill(
        coverage=multi.coverage,
        attrs=_unpack(multi.attrs, layout),
        depth=multi.depth,
        trace=fill_trace,
        sample_coverage=multi.sample_coverage,
        sample_attrs=None if multi.sample_attrs is None else _unpack(multi.sample_attrs, layout),
        sample_depth=multi.sample_depth,
        samples=multi.offsets,
    )


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
            algo_trace, lam, values, depth_values, subdivision, samples) -> FillTrace:  # fmt: skip
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
        samples=samples,
    )
