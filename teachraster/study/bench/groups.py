"""The four groups of the study: each variant's error against its ground truth, and its time."""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from types import SimpleNamespace

import numpy as np

from ...core.fill import rasterize
from ...core.triangle import Triangle
from ...core.validate import as_int, as_size
from ...pipeline.geometry.camera import perspective
from ...pipeline.rendering.render_scenes import render
from ...pipeline.visibility.depth import linear_depth, reversed_depth
from ...pipeline.visibility.zbuffer import passes_depth_test
from .. import precision
from .ground_truth import exact_coverage, screen_offset_px, uv_ground_truth
from .settings import (
    DEPTH_DISTANCES,
    DEPTH_GAP,
    DEPTH_VARIANTS,
    EDGE_VARIANTS,
    FAR,
    FLOOR_ROLL,
    MESH_OFFSETS,
    NEAR,
    SLANT,
    SLANTED_DISTANCES,
    SUBDIVISIONS,
    TEXELS,
)
from .timing import Progress, time_rows


# -- interpolation ----------------------------------------------------------------------------
def floor_quad(size: int, roll: float = FLOOR_ROLL):
    """A floor receding from 0.6 to 60 units, as two window-space triangles with w and uv.

    A pinhole camera of focal length ``size / 2`` px, 1 unit above the floor and rolled by
    ``roll`` degrees about its view axis. Without the roll every raster line of a level
    floor has one depth, so perspective is affine along each span and subdivided
    interpolation is exact (why Doom, whose camera only turned, drew floors row by row with
    one depth per row); the roll makes w change along the rows, the general case for a
    polygon of any orientation (Quake's spans, which divide every 8 or 16 pixels). A
    camera-space point (X, Y, Z) lands at ``(c + f X / Z, c + f Y / Z)`` (y down) with
    w = Z. Positions are put on the 1/256 px grid, so the rasteriser's snapped triangle *is*
    the geometry and the only error left is interpolation's. u runs 0..1 across, v 0..1
    from near to far.

    Returns
    -------
    xy (2, 3, 2), w (2, 3), uv (2, 3, 2)
    """
    size = as_size("size", size)
    f = c = size / 2
    corners = np.array([[-4.0, 0.6], [4.0, 0.6], [4.0, 60.0], [-4.0, 60.0]])  # (X, Z)
    uv = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    a = math.radians(roll)
    X = corners[:, 0] * math.cos(a) - 1.0 * math.sin(a)  # the floor is 1 unit below (y down)
    Y = corners[:, 0] * math.sin(a) + 1.0 * math.cos(a)
    w = corners[:, 1]
    xy = np.column_stack([c + f * X / w, c + f * Y / w])
    xy = np.rint(xy * 256) / 256
    tris = np.array([[0, 1, 2], [0, 2, 3]])
    return xy[tris], w[tris], uv[tris]


def span_divides(cov: np.ndarray, mode: str, n: int) -> int:
    """Perspective divides a scalar span loop performs: the cost numpy's timing hides.

    Per pixel for perspective, none for affine, and for subdivided one at every n-th pixel
    of each span and at its last pixel (see ``interpolation.subdivided``).
    """
    if mode == "affine":
        return 0
    lengths = cov.sum(axis=1)
    lengths = lengths[lengths > 0]
    if mode == "perspective":
        return int(lengths.sum())
    return int((-(-lengths // n) + ((lengths - 1) % n != 0)).sum())


def floor_errors(size: int, interpolation: str, subdivision: int = 16, fills=None):
    """The study's floor (:func:`floor_quad`) at ``size``² filled with ``interpolation``:
    per covered pixel, the error of u and v in texels (P, 2) and how far on screen it moves
    the texture, in pixels (P,) (:func:`~.ground_truth.screen_offset_px`); and the two
    triangles' coverages. ``fills`` are the two triangles' fills when already made.
    ``"perspective float32"`` interpolates perspective-correctly in float32 (:func:`_float32_fill`),
    ``"perspective float16"`` hands that result on in half precision (GLSL ES ``mediump``),
    ``"perspective rcp12"`` takes the reciprocal to 12 bits (SSE's ``rcpps``, :func:`rcp12`) and
    ``"perspective rcp12 newton"`` refines it by one Newton step.

    >>> texels, px, _ = floor_errors(64, "subdivided", 2)
    >>> texels.shape[1], bool(px.max() < 1 < texels.max())   # far on the texture, near on screen
    (2, True)
    """
    xy, w, uv = floor_quad(size)
    if fills is None and interpolation in FLOAT32_FILLS:
        handed, reciprocal = FLOAT32_FILLS[interpolation]
        fills = [_float32_fill(xy[t], w[t], uv[t], size, handed, reciprocal) for t in range(2)]
    if fills is None:
        fills = [rasterize(Triangle(xy[t], w=w[t], attrs={"uv": uv[t]}), size, size,
                           interpolation=interpolation, subdivision=subdivision)
                 for t in range(2)]  # fmt: skip
    texels, px, covs = [], [], []
    for t, fl in enumerate(fills):
        rows, cols = np.nonzero(fl.coverage)
        error = fl.attrs["uv"][rows, cols] - uv_ground_truth(xy[t], w[t], uv[t], size, rows, cols)
        texels.append(error * TEXELS)
        px.append(screen_offset_px(xy[t], w[t], uv[t], rows, cols, error))
        covs.append(fl.coverage)
    return np.concatenate(texels), np.concatenate(px), covs


#: Significand bits (the leading one counted) of :func:`rcp12`'s reciprocal
RCP_BITS = 12


def rcp12(q: np.ndarray) -> np.ndarray:
    """A stand-in for SSE's ``rcpps``: float32's 1/q with its significand rounded to
    :data:`RCP_BITS` bits, a relative error of at most 2^-12 (Intel documents ``rcpps``'s as
    under 1.5 · 2^-12, from a table, not this rounding).

    >>> float(abs(rcp12(np.float32([3.0]))[0] * 3 - 1)) <= 2.0**-12
    True
    """
    m, e = np.frexp(np.float32(1.0) / q)  # m in [0.5, 1): RCP_BITS bits kept
    return np.ldexp(np.round(m * 2.0**RCP_BITS) / 2.0**RCP_BITS, e).astype(np.float32)


def rcp12_newton(q: np.ndarray) -> np.ndarray:
    """:func:`rcp12` refined by one Newton step r (2 − q r) in float32 (2 multiplies and a
    subtraction): its relative error squared, down to float32's rounding."""
    r = rcp12(q)
    return (r * (np.float32(2.0) - q * r)).astype(np.float32)


def _exact_rcp(q: np.ndarray) -> np.ndarray:
    return np.float32(1.0) / q


#: The float32 fills :func:`floor_errors` makes: (the type u and v are handed on in, the
#: reciprocal of 1/w)
FLOAT32_FILLS = {
    "perspective float32": (np.float32, _exact_rcp),
    "perspective float16": (np.float16, _exact_rcp),
    "perspective rcp12": (np.float32, rcp12),
    "perspective rcp12 newton": (np.float32, rcp12_newton),
}


def _float32_fill(
    xy, w, uv, size: int, handed=np.float32, reciprocal=_exact_rcp
) -> SimpleNamespace:
    """One floor triangle filled perspective-correctly in float32, as a shader receives it:
    the screen-space planes of u/w, v/w and 1/w (set up in float64, stored in float32)
    evaluated at each covered pixel centre in float32, then u = (u/w) · (1 / (1/w)), the
    reciprocal and the products rounded to float32 too. ``handed=np.float16``: u and v then
    rounded to half precision, as a ``mediump`` varying (or SPIR-V ``RelaxedPrecision``) hands
    them to a shader that keeps them in 16 bits; the interpolation itself stays float32.
    ``reciprocal``: how 1/(1/w) is taken (:data:`FLOAT32_FILLS`). ``coverage`` and ``attrs["uv"]`` as a fill's (float64 values that float32 holds exactly;
    NaN outside)."""
    cov = rasterize(Triangle(xy), size, size).coverage
    rows, cols = np.nonzero(cov)
    planes = np.linalg.solve(np.column_stack([xy, np.ones(3)]),
                             np.column_stack([uv / w[:, None], 1.0 / w]))  # fmt: skip
    a, b, c = planes.astype(np.float32)  # each a row of (u/w, v/w, 1/w) coefficients
    x, y = (cols + 0.5).astype(np.float32), (rows + 0.5).astype(np.float32)
    q = x[:, None] * a + y[:, None] * b + c  # float32 throughout
    uv_at = np.full((size, size, 2), np.nan)
    uv_at[rows, cols] = (q[:, :2] * reciprocal(q[:, 2:])).astype(handed)
    return SimpleNamespace(coverage=cov, attrs={"uv": uv_at})


def bench_interpolation(
    cfg: dict, repeat: int, progress: Progress, clock: Callable[[], float] = time.perf_counter
) -> list[dict]:
    size = cfg["interp"]
    xy, w, uv = floor_quad(size)
    tris = [Triangle(xy[t], w=w[t], attrs={"uv": uv[t]}) for t in range(2)]
    modes = [("affine", "affine", 1), ("perspective", "perspective", 1)]
    modes += [(f"subdivided N={n}", "subdivided", n) for n in SUBDIVISIONS]
    rows_out, timers = [], []
    for name, mode, n in modes:

        def fill(mode=mode, n=n):
            return [rasterize(t, size, size, interpolation=mode, subdivision=n) for t in tris]

        texels, px, covs = floor_errors(size, mode, n, fills=fill())
        err = np.abs(texels).ravel()
        divides = sum(span_divides(cov, mode, n) for cov in covs)
        rows_out.append(
            {
                "group": "interpolation",
                "variant": name,
                "error": float(err.max()),
                "mean_abs_texels": float(err.mean()),
                # the same errors on screen: how far the texel shown belongs, in pixels
                "error_px": float(px.max()),
                "mean_error_px": float(px.mean()),
                "divides_per_pixel": divides / len(err) * 2,  # err holds u and v: 2 per pixel
            }
        )
        timers.append(fill)
        progress.step(f"interpolation: {name}")
    return time_rows(rows_out, timers, repeat, progress, "perspective", clock=clock)


# -- edge functions ---------------------------------------------------------------------------
def random_triangles(size: int, seed: int = 6) -> np.ndarray:
    """Fixed triangles near the origin: 12 with arbitrary float vertices, 12 on the half-pixel
    grid (edges through pixel centres and corners: ties everywhere)."""
    size, seed = as_size("size", size), as_int("seed", seed)
    rng = np.random.default_rng(seed)
    floats = rng.uniform(-0.1 * size, 1.1 * size, size=(12, 3, 2))
    ties = rng.integers(0, 2 * size, size=(12, 3, 2)) / 2.0
    return np.concatenate([floats, ties])


def triangulate_grid(g: np.ndarray) -> np.ndarray:
    """Two triangles per cell of a (k+1, k+1, 2) grid of points, the diagonals alternating
    like a checkerboard (so both diagonal directions, and every edge kind, occur)."""
    cells = g.shape[0] - 1
    tris = []
    for r in range(cells):
        for c in range(cells):
            a, b, cc, d = g[r, c], g[r, c + 1], g[r + 1, c + 1], g[r + 1, c]
            tris += [[a, b, cc], [a, cc, d]] if (r + c) % 2 else [[a, b, d], [b, cc, d]]
    return np.array(tris)


def jittered_mesh(size: int, cells: int = 4, seed: int = 3) -> np.ndarray:
    """A watertight mesh filling [1, size - 1]²: a grid of ``cells`` x ``cells`` quads with
    randomly moved inner vertices (border vertices slide along the border only), each quad
    split along alternating diagonals. Big triangles: long rows for stepping to drift on."""
    size, cells = as_size("size", size), as_size("cells", cells)
    seed = as_int("seed", seed)
    rng = np.random.default_rng(seed)
    step = (size - 2) / cells
    g = np.stack(np.meshgrid(np.arange(cells + 1), np.arange(cells + 1)), -1) * step
    jitter = rng.uniform(-0.35, 0.35, g.shape) * step
    jitter[[0, -1], :, 1] = 0  # top and bottom rows stay on their lines
    jitter[:, [0, -1], 0] = 0  # left and right columns too
    g = g + jitter + 1.0
    return triangulate_grid(g)


def mesh_wrong_pixels(
    size: int, offset: int, arithmetic: str, against: str | None = None
) -> np.ndarray:
    """Where the study's jittered mesh, placed ``offset`` px from the origin, is covered
    differently in ``arithmetic`` (direct evaluation) than in ``against``.

    Parameters
    ----------
    size : int
        The mesh's window, ``size`` x ``size`` px (the study's ``sizes()["mesh"]``).
    offset : int
        Its distance from the origin in x and in y, in px (one of ``MESH_OFFSETS``).
    arithmetic : str
        One of :func:`teachraster.study.precision.coverage`'s arithmetics.
    against : str or None
        Another arithmetic, or ``None`` for the exact coverage on the 1/256 px grid (the
        reference ``bench_edges`` counts the ``mesh_wrong_px_at_...`` columns against).

    Returns
    -------
    (size, size) int
        Per pixel, how many of the mesh's triangles decide its centre differently; the sum
        is the study's count (against the exact reference, its ``mesh_wrong_px_at_...``).
    """
    size, offset = as_size("size", size), as_int("offset", offset)
    out = np.zeros((size, size), dtype=np.int64)
    for t in jittered_mesh(size) + float(offset):
        got = precision.coverage(t, size, size, arithmetic, origin=(offset, offset))
        if against is None:
            ref = exact_coverage(t, size, size, 8, origin=(offset, offset))
        else:
            ref = precision.coverage(t, size, size, against, origin=(offset, offset))
        out += got != ref
    return out


def _scale_label(offset: int) -> str:
    return "0" if offset == 0 else f"1e{round(math.log10(offset))}"


def bench_edges(
    cfg: dict, repeat: int, progress: Progress, clock: Callable[[], float] = time.perf_counter
) -> list[dict]:
    size, msize = cfg["edges"], cfg["mesh"]
    tris = random_triangles(size)
    ref8 = [exact_coverage(t, size, size, 8) for t in tris]
    ref_raw = [exact_coverage(t, size, size, None) for t in tris]
    mesh = jittered_mesh(msize)
    meshes = {}
    for off in MESH_OFFSETS:
        # Absolute coordinates off + local ones: the image is the window at (off, off).
        placed = mesh + float(off)
        refs = [exact_coverage(t, msize, msize, 8, origin=(off, off)) for t in placed]
        counts = np.sum(refs, axis=0)
        assert counts.max() <= 1, "the reference mesh must be watertight"
        meshes[off] = (placed, refs, counts)
    rows_out, timers = [], []
    for arith, ev in EDGE_VARIANTS:

        def fill(arith=arith, ev=ev):
            return [precision.coverage(t, size, size, arith, ev) for t in tris]

        got = fill()
        row = {
            "group": "edge functions",
            "variant": f"{arith} {ev}",
            "wrong_px_random": int(sum((g != r).sum() for g, r in zip(got, ref8))),
            "wrong_px_unsnapped_geometry": int(sum((g != r).sum() for g, r in zip(got, ref_raw))),
        }
        total_wrong, gaps, double = row["wrong_px_random"], 0, 0
        for off, (placed, refs, want) in meshes.items():
            counts = np.zeros((msize, msize), dtype=np.int32)
            wrong = 0
            for t, ref in zip(placed, refs):
                cov = precision.coverage(t, msize, msize, arith, ev, origin=(off, off))
                wrong += int((cov != ref).sum())
                counts += cov
            label = _scale_label(off)
            row[f"mesh_wrong_px_at_{label}"] = wrong
            row[f"gaps_at_{label}"] = int(((want == 1) & (counts == 0)).sum())
            row[f"double_hits_at_{label}"] = int((counts > 1).sum())
            total_wrong += wrong
            gaps += row[f"gaps_at_{label}"]
            double += row[f"double_hits_at_{label}"]
        row.update(error=total_wrong, gaps=gaps, double_hits=double, cracks=gaps + double)
        rows_out.append(row)
        timers.append(fill)
        progress.step(f"edge functions: {arith} {ev}")
    return time_rows(rows_out, timers, repeat, progress, "fixed8 direct", clock=clock)


# -- fill algorithms --------------------------------------------------------------------------
def fill_triangle(size: int) -> Triangle:
    """About half the image, with w = 1, 2, 4 and uv: the work of a typical textured fill."""
    xy = np.array([[0.013, 0.021], [0.987, 0.063], [0.197, 0.979]]) * size
    return Triangle(xy, w=[1.0, 2.0, 4.0], attrs={"uv": [[0, 0], [1, 0], [0, 1]]})


def bench_fill(
    cfg: dict, repeat: int, progress: Progress, clock: Callable[[], float] = time.perf_counter
) -> list[dict]:
    """Each fill's time, and beside it (``coverage_*_s``) the same fill of the bare positions.

    The timed fill interpolates the triangle's uv perspective-correctly at every covered
    pixel, the same work for both algorithms and most of the time in numpy; the bare
    triangle (no w, no attributes) times the coverage alone, where the algorithms differ.
    """
    rows_out = []
    for size in cfg["fill"]:
        tri = fill_triangle(size)
        bare = Triangle(tri.xy)
        ref = exact_coverage(tri.xy, size, size, 8)
        block, timers, coverage_timers = [], [], []
        for method in ("halfplane", "span"):
            for traced in (False, True):
                name = f"{method}{'+trace' if traced else ''} {size}²"

                def fill(method=method, traced=traced, tri=tri, size=size):
                    return rasterize(tri, size, size, method=method, trace=traced)

                def cover(method=method, traced=traced, tri=bare, size=size):
                    return rasterize(tri, size, size, method=method, trace=traced)

                block.append(
                    {
                        "group": "fill",
                        "variant": name,
                        "error": int((fill().coverage != ref).sum()),
                        "pixels": int(ref.sum()),
                    }
                )
                timers.append(fill)
                coverage_timers.append(cover)
                progress.step(f"fill: {name}")
        rows_out += time_rows(block, timers, repeat, progress, f"halfplane {size}²",
                              also=("coverage", coverage_timers), clock=clock)  # fmt: skip
    return rows_out


# -- depth ------------------------------------------------------------------------------------
def depth_pairs(aspect: float = 1.0):
    """Pairs of camera-facing triangles, one pair per distance in :data:`DEPTH_DISTANCES`.

    Pair k sits in cell k of a 3 x 3 layout of the screen: a triangle at view distance
    ``z + DEPTH_GAP`` is drawn first, then one at ``z`` shifted a little sideways, so most
    of the two overlap. A depth buffer that cannot tell them apart stores a tie, and the
    tie keeps the earlier, *farther* triangle: an inversion. Facing the camera, each
    triangle has one view distance, so any depth mapping (linear too) is affine over it.

    Returns
    -------
    view (2K, 3, 3) view-space vertices, z_view (2K,) their distances.
    """
    shape = np.array([[-0.28, -0.25], [0.25, -0.3], [-0.05, 0.28]])  # NDC, about the cell
    view, z_view = [], []
    for k, z in enumerate(DEPTH_DISTANCES):
        for dz, shift in ((DEPTH_GAP, 0.0), (0.0, 0.06)):
            d = z + dz
            view.append(_in_cell(k, shape, shift, d, aspect))
            z_view.append(d)
    return np.array(view), np.array(z_view)


def slanted_pairs(aspect: float = 1.0):
    """Pairs that cross: a camera-facing triangle pierced by a slanted one.

    Pair k sits in cell k of a 3 x 3 layout, at view distance ``z`` = ``SLANTED_DISTANCES[k]``:
    first a triangle whose depth runs from ``z (1 - SLANT)`` on its left to ``z (1 + SLANT)``
    on its right, then a camera-facing one at ``z``. They intersect along a line; which one
    is in front changes there. Window depth (affine in screen space, lesson 05b) puts that
    line where it is; a depth *linear* in view distance, interpolated affinely over the
    slanted triangle, does not (it is affine in screen space only when the triangle faces
    the camera), at any number of bits.

    Returns
    -------
    view (2K, 3, 3) view-space vertices, z_view (2K,) the distance of each pair.
    """
    shape = np.array([[-0.28, -0.25], [0.28, -0.3], [-0.05, 0.28]])  # NDC, about the cell
    view, z_view = [], []
    for k, z in enumerate(SLANTED_DISTANCES):
        for slant, shift in ((SLANT, 0.0), (0.0, 0.05)):
            d = z * (1 + slant * shape[:, 0] / 0.28)
            view.append(_in_cell(k, shape, shift, d, aspect))
            z_view.append(z)
    return np.array(view), np.array(z_view)


def _in_cell(k: int, shape: np.ndarray, shift: float, d, aspect: float) -> np.ndarray:
    """(3, 3) view-space vertices that project to ``shape`` (NDC, about the cell's centre)
    moved ``shift`` to the right in cell k of a 3 x 3 layout of the screen, at view
    distance ``d`` (one for all three vertices, or one each)."""
    t = 1.0 / perspective(60.0, aspect, NEAR, FAR)[1, 1]  # tan(fov / 2)
    ndc = np.array([(k % 3 - 1) * 2 / 3, (1 - k // 3) * 2 / 3]) + shape + [shift, 0.0]
    d = np.broadcast_to(np.asarray(d, dtype=np.float64), (len(ndc),))
    return np.column_stack([ndc[:, 0] * d * t * aspect, ndc[:, 1] * d * t, -d])


def depth_clip(view: np.ndarray, mapping: str, aspect: float = 1.0) -> np.ndarray:
    """Clip coordinates storing the window depth, ``linear_depth`` of the view distance, or
    (``"reversed"``) reverse-Z's ``reversed_depth`` (near 1, far 0: draw it with
    :func:`greater_passes`)."""
    proj = perspective(60.0, aspect, NEAR, FAR)
    homo = np.concatenate([view, np.ones(view.shape[:2] + (1,))], axis=2)
    clip = homo @ proj.T
    mapped = {"linear": linear_depth, "reversed": reversed_depth}.get(mapping)
    if mapped is not None:
        # z_win = (z/w)/2 + 1/2 = d  <=>  z = w (2 d - 1); exact per vertex. The reversed depth
        # is affine on screen across any triangle (it is affine in 1/z, as window depth is),
        # linear depth only across camera-facing ones. Both keep the clip planes: the
        # reversed z is -z (far and near swap), computed from reversed_depth so that a far
        # depth keeps its float64 digits (what 1 - d would round away).
        w = clip[..., 3]
        clip[..., 2] = w * (2 * mapped(-view[..., 2], NEAR, FAR) - 1)
    return clip


def greater_passes(depths, writes) -> list[bool]:
    """Reverse-Z's depth test of one pixel, for ``tr.render(..., overrides={"depth": ...})``:
    the buffer cleared to 0 (the far plane), a fragment passes when its stored depth is
    strictly greater than the buffer's (``GL_GREATER``), so a tie keeps the earlier fragment,
    as the package's own strict test does.

    >>> greater_passes([0.2, 0.5, 0.5, 0.1], [True] * 4)
    [True, True, False, False]
    """
    stored, passed = 0.0, []
    for d, writes_depth in zip(depths, writes):
        # GL_GREATER is GL_LESS on negated depths: the package's one compare decides it
        passed.append(bool(passes_depth_test(-d, -stored)))
        if passed[-1] and writes_depth:
            stored = d
    return passed


def bench_depth(
    cfg: dict, repeat: int, progress: Progress, clock: Callable[[], float] = time.perf_counter
) -> list[dict]:
    size = cfg["depth"]
    view, z_view = depth_pairs()
    # Ground truth: the painter's algorithm with exact view distances, far to near, no
    # depth buffer at all (valid: the triangles face the camera and do not intersect).
    order = np.argsort(-z_view, kind="stable")
    painted = render(depth_clip(view[order], "window"), size, size, depth_test=False)
    truth = np.where(painted.triangle_id >= 0, order[painted.triangle_id], -1)
    pair_of = np.where(truth >= 0, truth // 2, -1)
    # Crossing pairs: window depth in float64 is exact to rounding (affine in screen space).
    slanted, _ = slanted_pairs()
    slanted_truth = render(depth_clip(slanted, "window"), size, size).triangle_id
    rows_out, timers = [], []
    for mapping, fmt in DEPTH_VARIANTS:
        clip = depth_clip(view, mapping)
        slanted_clip = depth_clip(slanted, mapping)
        test = {"overrides": {"depth": greater_passes}} if mapping == "reversed" else {}

        def draw(clip=clip, fmt=fmt, test=test):
            return render(clip, size, size, depth_format=fmt, **test)

        wrong = draw().triangle_id != truth
        crossing = render(slanted_clip, size, size, depth_format=fmt, **test).triangle_id
        slanted_wrong = int((crossing != slanted_truth).sum())
        bad_pairs = sorted(set(pair_of[wrong].tolist()) - {-1})
        first = DEPTH_DISTANCES[bad_pairs[0]] if bad_pairs else ""
        rows_out.append(
            {
                "group": "depth",
                "variant": f"{mapping} {fmt}",
                "error": int(wrong.sum()) + slanted_wrong,
                "facing_wrong": int(wrong.sum()),
                "slanted_wrong": slanted_wrong,
                "first_inverted_z": first,
                "inverted_pairs": len(bad_pairs),
            }
        )
        timers.append(draw)
        progress.step(f"depth: {mapping} {fmt}")
    return time_rows(rows_out, timers, repeat, progress, "window float64", clock=clock)
