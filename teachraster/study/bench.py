"""Accuracy vs time: what each cheaper or costlier way of rasterising gets wrong, and costs.

Run ``python -m teachraster.study.bench [--quick] [--out DIR] [--repeat N]``. On fixed, seeded
scenes it measures every variant's error against a ground truth computed independently of
the rasteriser, and its time (the median of ``--repeat`` runs after two warm-ups, with
``time.perf_counter``; the variants of a group are timed round-robin, so a busy machine
slows them alike). It prints a table, writes ``bench.csv`` (one row per variant) and
the plots ``pareto.png`` and ``subdivision.png`` into DIR (default ``bench-out/``).

Groups
------
interpolation
    ``tr.rasterize`` of a steeply receding textured floor (two triangles) with affine,
    perspective-correct and subdivided (N = 2 ... 32) interpolation. Error: absolute error of
    the texture coordinates, in texels of a 256-texel texture, against a ray-plane
    intersection per pixel centre in 3D (float64), which never uses screen-space
    barycentrics.
edge functions
    :func:`teachraster.study.precision.coverage` in five arithmetics, evaluated directly or
    incrementally. Error: pixels whose coverage differs from the exact rational coverage of
    the triangle snapped to 1/256 px (CONVENTIONS' reference), on random triangles and on a
    jittered watertight mesh placed at 0, 1e5 and 1e6 px from the origin; also gaps and
    double hits on the mesh, and differences from the exact *unsnapped* geometry.

    Far from the origin the image is a window of pixels at the mesh's integer offset
    (``origin=`` of :mod:`teachraster.study.precision`) and every arithmetic is given the
    *absolute* coordinates, as a rasteriser without a window-relative set-up would see
    them. The integer arithmetics are unaffected (subtracting whole pixels is exact, so
    they equal ``tr.rasterize`` on window-relative positions); float32 rounds each vertex to
    1/128 px at 1e5 and 1/16 px at 1e6, and that, not cracking, is its main failure: a
    shared vertex rounds the same way in both triangles and an exact tie rounds to an
    exact 0, so the direct float32 mesh stays almost watertight while its edges move. Cracks
    come from float32 *stepping*, whose rounding errors accumulate along long rows.
fill
    Span tables vs half-planes, with and without the trace, at two image sizes. Error:
    pixels differing from the exact coverage (all variants are exact: this group shows what
    the algorithm and the trace cost, not what they buy in accuracy).
depth
    ``tr.render`` with each ``depth_format`` storing either the window depth (the hyperbola
    ``z' = n + f - fn/z`` rescaled to [0, 1]) or a depth linear in view distance, on pairs of
    nearly coplanar overlapping triangles at distances 1 to 500. Error: depth-order
    inversions, pixels whose visible triangle differs from the true nearest one.

:func:`run` returns the rows, :func:`pareto_front` picks the variants no other beats on both
time and error, and :func:`pareto_figure` draws the trade-off (matplotlib is imported only
there, so the package stays numpy-only).
"""

from __future__ import annotations

import argparse
import csv
import math
import statistics
import sys
import time
from collections.abc import Callable, Iterable
from fractions import Fraction
from pathlib import Path

import numpy as np

from ..core.fill import rasterize
from ..core.snapping import check_bits
from ..core.triangle import Triangle
from ..core.validate import as_int, as_size
from ..pipeline.camera import perspective
from ..pipeline.depth import linear_depth
from ..pipeline.render_scenes import render
from . import precision

GROUPS = ("interpolation", "edge functions", "fill", "depth")

#: Texture size that converts texture coordinates to texels.
TEXELS = 256
SUBDIVISIONS = (2, 4, 8, 16, 32)
EDGE_VARIANTS = tuple(
    (arith, ev) for arith in precision.ARITHMETICS for ev in precision.EVALUATIONS
)
#: Offsets (px) at which the jittered mesh is rasterised, through an image window there.
MESH_OFFSETS = (0, 100_000, 1_000_000)
DEPTH_FORMATS = ("float64", "float32", "unorm24", "unorm16")
DEPTH_MAPPINGS = ("window", "linear")
#: View distances of the depth pairs, and the gap between the two triangles of a pair.
DEPTH_DISTANCES = (1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0)
DEPTH_GAP = 0.01
NEAR, FAR = 0.1, 1000.0

#: What the ``error`` column means, per group (the y axis of the Pareto plot).
ERROR_MEASURE = {
    "interpolation": "max |uv error| (texels)",
    "edge functions": "pixels wrong vs exact 1/256 coverage",
    "fill": "pixels wrong vs exact coverage",
    "depth": "depth-order inversions (pixels)",
}
#: Extra columns printed in the table, per group (all of them go to the CSV).
TABLE_COLUMNS = {
    "interpolation": ("mean_abs_texels", "divides_per_pixel"),
    "edge functions": ("gaps", "double_hits", "wrong_px_unsnapped_geometry"),
    "fill": (),
    "depth": ("first_inverted_z",),
}
COMMON_COLUMNS = (
    "group",
    "variant",
    "time_median_s",
    "time_ratio_to_baseline",
    "baseline",
    "error",
    "error_measure",
)


# -- sizes ------------------------------------------------------------------------------------
def sizes(quick: bool = False) -> dict:
    """Image sizes of each group (smaller with ``quick``, same variants and scenes)."""
    if quick:
        return {"interp": 256, "edges": 256, "mesh": 512, "fill": (256, 512), "depth": 128}
    return {"interp": 512, "edges": 512, "mesh": 2048, "fill": (512, 1024), "depth": 512}


def variant_names(quick: bool = False) -> dict[str, list[str]]:
    """The variants of each group, in the order :func:`run` measures them."""
    small, large = sizes(quick)["fill"]
    fill = [
        f"{method}{'+trace' if traced else ''} {n}²"
        for n in (small, large)
        for method in ("halfplane", "span")
        for traced in (False, True)
    ]
    return {
        "interpolation": ["affine", "perspective"] + [f"subdivided N={n}" for n in SUBDIVISIONS],
        "edge functions": [f"{a} {e}" for a, e in EDGE_VARIANTS],
        "fill": fill,
        "depth": [f"{m} {f}" for m in DEPTH_MAPPINGS for f in DEPTH_FORMATS],
    }


# -- timing and progress ----------------------------------------------------------------------
def time_interleaved(fns: list[Callable[[], object]], repeat: int) -> list[float]:
    """Median wall time of each ``fn()``, measured round-robin: one call of each per round.

    Other work on the machine (another process, a CPU-frequency change) then slows every
    variant alike instead of whichever happened to be measured at that moment, so the
    ratios between variants stay fair on a busy machine. Two untimed warm-up rounds come
    first.
    """
    repeat = as_size("repeat", repeat)
    for _ in range(2):
        for fn in fns:
            fn()
    times = [[] for _ in fns]
    for _ in range(max(1, repeat)):
        for fn, record in zip(fns, times):
            t0 = time.perf_counter()
            fn()
            record.append(time.perf_counter() - t0)
    return [statistics.median(t) for t in times]


def _time_rows(rows: list[dict], fns: list, repeat: int, progress: Progress, baseline: str):
    """Time a group's variants together (:func:`time_interleaved`), then add the ratios."""
    for row, t in zip(rows, time_interleaved(fns, repeat)):
        row["time_median_s"] = t
    progress.step(f"{rows[0]['group']}: timing")
    return _ratios(rows, baseline)


class Progress:
    """A one-line text progress bar on stderr (no dependency)."""

    def __init__(self, total: int, enabled: bool = True, width: int = 30):
        self.total, self.done, self.enabled, self.width = total, 0, enabled, width

    def step(self, label: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        filled = round(self.width * self.done / self.total)
        bar = "#" * filled + "-" * (self.width - filled)
        sys.stderr.write(f"\r[{bar}] {self.done:2d}/{self.total} {label[:40]:<40}")
        if self.done == self.total:
            sys.stderr.write("\n")
        sys.stderr.flush()


# -- exact coverage (the conventions' reference) ----------------------------------------------
#: Bound on the rounding error of a float64 orient2d, relative to |t1| + |t2|. Shewchuk's
#: bound is (3 + 16 eps) eps ~ 3.3e-16 (rounded differences included); 1e-15 is 3x that.
_ERRBOUND = 1e-15


def exact_coverage(xy, width: int, height: int, bits: int | None = 8, origin=(0, 0)):
    """Exact coverage by the top-left rule, in rational arithmetic, written from CONVENTIONS.

    Vertices are snapped to ``1 / 2**bits`` px (round half to even) as Fractions, or taken as
    the exact rationals the floats are (``bits=None``). Each pixel's edge functions are
    first evaluated in float64; where the result is farther from 0 than a proven bound on
    its rounding error its sign is certain, and only the remaining pixels (centres on or a
    hair from an edge) are decided with Fractions. This is independent of the package's
    rasteriser and of :mod:`teachraster.study.precision`.

    Returns
    -------
    (height, width) bool
        For the window of pixels ``origin + (j, i)``.
    """
    width, height = as_size("width", width), as_size("height", height)
    bits = check_bits(bits)
    ox, oy = (int(v) for v in origin)
    xy = np.asarray(xy, dtype=np.float64)
    if bits is None:
        v = [(Fraction(x), Fraction(y)) for x, y in xy.tolist()]
    else:
        s = 2**bits  # Python's round() of a Fraction rounds half to even
        v = [
            (Fraction(round(Fraction(x) * s), s), Fraction(round(Fraction(y) * s), s))
            for x, y in xy.tolist()
        ]

    def edge(a, b, p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    out = np.zeros((height, width), dtype=bool)
    area2 = edge(v[0], v[1], v[2])
    if area2 == 0:
        return out
    if area2 < 0:
        v = [v[0], v[2], v[1]]
    xs, ys = [p[0] for p in v], [p[1] for p in v]
    half = Fraction(1, 2)
    c0, c1 = max(math.ceil(min(xs) - half), ox), min(math.floor(max(xs) - half) + 1, ox + width)
    r0, r1 = max(math.ceil(min(ys) - half), oy), min(math.floor(max(ys) - half) + 1, oy + height)
    if c1 <= c0 or r1 <= r0:
        return out
    cols, rows = np.arange(c0, c1), np.arange(r0, r1)
    px, py = cols + 0.5, rows + 0.5  # exact in float64
    inside = np.ones((len(rows), len(cols)), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        # Snapped vertices and raw floats are exact float64 values, so only the arithmetic
        # below rounds, and the bound covers it.
        ax, ay, bx, by = float(a[0]), float(a[1]), float(b[0]), float(b[1])
        t1 = (bx - ax) * (py - ay)[:, None]
        t2 = ((by - ay) * (px - ax))[None, :]
        e = t1 - t2
        bound = _ERRBOUND * (np.abs(t1) + np.abs(t2))
        ok = e > bound
        unsure = inside & ~ok & (e >= -bound)
        for i, j in zip(*np.nonzero(unsure)):
            p = (Fraction(2 * int(cols[j]) + 1, 2), Fraction(2 * int(rows[i]) + 1, 2))
            ek = edge(a, b, p)
            ok[i, j] = ek > 0 or (ek == 0 and top_left)
        inside &= ok
    out[r0 - oy : r1 - oy, c0 - ox : c1 - ox] = inside
    return out


# -- interpolation ----------------------------------------------------------------------------
def floor_quad(size: int, roll: float = 25.0):
    """A floor receding from 0.6 to 60 units, as two window-space triangles with w and uv.

    A pinhole camera of focal length ``size / 2`` px, 1 unit above the floor and rolled by
    ``roll`` degrees about its view axis. Without the roll every raster line of a level
    floor has one depth, so perspective is affine along each span and subdivided
    interpolation would be exact (why Quake drew floors along lines of constant depth); the
    roll makes w change along the rows, the general case. A camera-space point (X, Y, Z)
    lands at ``(c + f X / Z, c + f Y / Z)`` (y down) with w = Z. Positions are put on the
    1/256 px grid, so the rasteriser's snapped triangle *is* the geometry and the only error
    left is interpolation's. u runs 0..1 across, v 0..1 from near to far.

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


def uv_ground_truth(xy, w, uv, size: int, rows, cols) -> np.ndarray:
    """Texture coordinates at pixel centres by ray-plane intersection in 3D (float64).

    Each window vertex (x, y) with depth w is lifted back to the 3D point
    ``((x - c) w / f, (y - c) w / f, w)`` of the pinhole camera of :func:`floor_quad`; the
    ray through the pixel centre meets the triangle's plane at Q, and uv is blended with
    Q's barycentric coordinates *in 3D* (ratios of sub-triangle areas). No screen-space
    barycentric or 1/w interpolation is involved.
    """
    f = c = size / 2
    P = np.column_stack([(xy[:, 0] - c) * w / f, (xy[:, 1] - c) * w / f, w])
    n = np.cross(P[1] - P[0], P[2] - P[0])
    d = np.column_stack([(cols + 0.5 - c) / f, (rows + 0.5 - c) / f, np.ones(len(rows))])
    t = (n @ P[0]) / (d @ n)
    Q = t[:, None] * d
    nn = n @ n
    bary = [np.cross(P[(i + 1) % 3] - Q, P[(i + 2) % 3] - Q) @ n / nn for i in range(3)]
    return sum(b[:, None] * uv[i] for i, b in enumerate(bary))


def _divides(cov: np.ndarray, mode: str, n: int) -> int:
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


def bench_interpolation(cfg: dict, repeat: int, progress: Progress) -> list[dict]:
    size = cfg["interp"]
    xy, w, uv = floor_quad(size)
    tris = [Triangle(xy[t], w=w[t], attrs={"uv": uv[t]}) for t in range(2)]
    truth = []
    for t in range(2):
        cov = rasterize(tris[t], size, size).coverage
        rows, cols = np.nonzero(cov)
        truth.append((cov, uv_ground_truth(xy[t], w[t], uv[t], size, rows, cols)))
    modes = [("affine", "affine", 1), ("perspective", "perspective", 1)]
    modes += [(f"subdivided N={n}", "subdivided", n) for n in SUBDIVISIONS]
    rows_out, timers = [], []
    for name, mode, n in modes:

        def fill(mode=mode, n=n):
            return [rasterize(t, size, size, interpolation=mode, subdivision=n) for t in tris]

        errs = []
        for fl, (cov, want) in zip(fill(), truth):
            errs.append(np.abs(fl.attrs["uv"][cov] - want).ravel() * TEXELS)
        err = np.concatenate(errs)
        divides = sum(_divides(cov, mode, n) for cov, _ in truth)
        rows_out.append(
            {
                "group": "interpolation",
                "variant": name,
                "error": float(err.max()),
                "mean_abs_texels": float(err.mean()),
                "divides_per_pixel": divides / len(err) * 2,  # err holds u and v: 2 per pixel
            }
        )
        timers.append(fill)
        progress.step(f"interpolation: {name}")
    return _time_rows(rows_out, timers, repeat, progress, "perspective")


# -- edge functions ---------------------------------------------------------------------------
def random_triangles(size: int, seed: int = 6) -> np.ndarray:
    """Fixed triangles near the origin: 12 with arbitrary float vertices, 12 on the half-pixel
    grid (edges through pixel centres and corners: ties everywhere)."""
    size, seed = as_size("size", size), as_int("seed", seed)
    rng = np.random.default_rng(seed)
    floats = rng.uniform(-0.1 * size, 1.1 * size, size=(12, 3, 2))
    ties = rng.integers(0, 2 * size, size=(12, 3, 2)) / 2.0
    return np.concatenate([floats, ties])


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
    tris = []
    for r in range(cells):
        for c in range(cells):
            a, b, cc, d = g[r, c], g[r, c + 1], g[r + 1, c + 1], g[r + 1, c]
            tris += [[a, b, cc], [a, cc, d]] if (r + c) % 2 else [[a, b, d], [b, cc, d]]
    return np.array(tris)


def _scale_label(offset: int) -> str:
    return "0" if offset == 0 else f"1e{round(math.log10(offset))}"


def bench_edges(cfg: dict, repeat: int, progress: Progress) -> list[dict]:
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
    return _time_rows(rows_out, timers, repeat, progress, "fixed8 direct")


# -- fill algorithms --------------------------------------------------------------------------
def fill_triangle(size: int) -> Triangle:
    """About half the image, with w = 1, 2, 4 and uv: the work of a typical textured fill."""
    xy = np.array([[0.013, 0.021], [0.987, 0.063], [0.197, 0.979]]) * size
    return Triangle(xy, w=[1.0, 2.0, 4.0], attrs={"uv": [[0, 0], [1, 0], [0, 1]]})


def bench_fill(cfg: dict, repeat: int, progress: Progress) -> list[dict]:
    rows_out = []
    for size in cfg["fill"]:
        tri = fill_triangle(size)
        ref = exact_coverage(tri.xy, size, size, 8)
        block, timers = [], []
        for method in ("halfplane", "span"):
            for traced in (False, True):
                name = f"{method}{'+trace' if traced else ''} {size}²"

                def fill(method=method, traced=traced, tri=tri, size=size):
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
                progress.step(f"fill: {name}")
        rows_out += _time_rows(block, timers, repeat, progress, f"halfplane {size}²")
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
    proj = perspective(60.0, aspect, NEAR, FAR)
    t = 1.0 / proj[1, 1]  # tan(fov / 2)
    shape = np.array([[-0.28, -0.25], [0.25, -0.3], [-0.05, 0.28]])  # NDC, about the cell
    view, z_view = [], []
    for k, z in enumerate(DEPTH_DISTANCES):
        centre = np.array([(k % 3 - 1) * 2 / 3, (1 - k // 3) * 2 / 3])
        for dz, shift in ((DEPTH_GAP, 0.0), (0.0, 0.06)):
            ndc = centre + shape + [shift, 0.0]
            d = z + dz
            pts = np.column_stack([ndc[:, 0] * d * t * aspect, ndc[:, 1] * d * t, -np.full(3, d)])
            view.append(pts)
            z_view.append(d)
    return np.array(view), np.array(z_view)


def depth_clip(view: np.ndarray, mapping: str, aspect: float = 1.0) -> np.ndarray:
    """Clip coordinates storing the window depth, or ``linear_depth`` of the view distance."""
    proj = perspective(60.0, aspect, NEAR, FAR)
    homo = np.concatenate([view, np.ones(view.shape[:2] + (1,))], axis=2)
    clip = homo @ proj.T
    if mapping == "linear":
        # z_win = (z/w)/2 + 1/2 = linear_depth  <=>  z = w (2 linear_depth - 1); exact per
        # vertex, and affine across these camera-facing triangles.
        w = clip[..., 3]
        clip[..., 2] = w * (2 * linear_depth(-view[..., 2], NEAR, FAR) - 1)
    return clip


def bench_depth(cfg: dict, repeat: int, progress: Progress) -> list[dict]:
    size = cfg["depth"]
    view, z_view = depth_pairs()
    # Ground truth: the painter's algorithm with exact view distances, far to near, no
    # depth buffer at all (valid: the triangles face the camera and do not intersect).
    order = np.argsort(-z_view, kind="stable")
    painted = render(depth_clip(view[order], "window"), size, size, depth_test=False)
    truth = np.where(painted.triangle_id >= 0, order[painted.triangle_id], -1)
    pair_of = np.where(truth >= 0, truth // 2, -1)
    rows_out, timers = [], []
    for mapping in DEPTH_MAPPINGS:
        clip = depth_clip(view, mapping)
        for fmt in DEPTH_FORMATS:

            def draw(clip=clip, fmt=fmt):
                return render(clip, size, size, depth_format=fmt)

            wrong = draw().triangle_id != truth
            bad_pairs = sorted(set(pair_of[wrong].tolist()) - {-1})
            first = DEPTH_DISTANCES[bad_pairs[0]] if bad_pairs else ""
            rows_out.append(
                {
                    "group": "depth",
                    "variant": f"{mapping} {fmt}",
                    "error": int(wrong.sum()),
                    "first_inverted_z": first,
                    "inverted_pairs": len(bad_pairs),
                }
            )
            timers.append(draw)
            progress.step(f"depth: {mapping} {fmt}")
    return _time_rows(rows_out, timers, repeat, progress, "window float64")


# -- the study --------------------------------------------------------------------------------
def _ratios(rows: list[dict], baseline: str) -> list[dict]:
    base = next(r["time_median_s"] for r in rows if r["variant"] == baseline)
    for r in rows:
        r["time_ratio_to_baseline"] = r["time_median_s"] / base
        r["baseline"] = baseline
        r["error_measure"] = ERROR_MEASURE[r["group"]]
    return rows


def run(quick: bool = False, *, repeat: int | None = None, progress: bool = False) -> list[dict]:
    """Measure every variant of every group; one dict per variant.

    Parameters
    ----------
    quick : bool
        Smaller images and meshes (same variants): a smoke run of a few seconds.
    repeat : int, optional
        Timed runs per variant (median taken); default 7, or 3 with ``quick``.
    progress : bool
        Draw a progress bar on stderr.

    Returns
    -------
    list of dict
        Keys :data:`COMMON_COLUMNS` plus each group's own measures.
    """
    cfg = sizes(quick)
    repeat = (3 if quick else 7) if repeat is None else int(repeat)
    names = variant_names(quick)
    # one step per variant (its error measured), one per timed block of variants
    steps = sum(len(v) for v in names.values()) + len(GROUPS) + 1  # fill: two sizes
    bar = Progress(steps, enabled=progress)
    rows = []
    for bench in (bench_interpolation, bench_edges, bench_fill, bench_depth):
        rows += bench(cfg, repeat, bar)
    return rows


def pareto_front(rows: Iterable[dict], x: str = "time_median_s", y: str = "error") -> list[dict]:
    """The rows no other row beats on both ``x`` and ``y`` (smaller is better), by ``x``.

    A row is dominated when another is at least as good on both and better on one. Of rows
    with identical (x, y) the first is kept.

    >>> rows = [{"t": 1, "e": 5}, {"t": 2, "e": 1}, {"t": 3, "e": 3}, {"t": 4, "e": 0}]
    >>> [r["t"] for r in pareto_front(rows, "t", "e")]
    [1, 2, 4]
    """
    front, best = [], math.inf
    for r in sorted(rows, key=lambda r: (r[x], r[y])):
        if r[y] < best:
            front.append(r)
            best = r[y]
    return front


def columns(rows: list[dict]) -> list[str]:
    """CSV columns: the common ones, then every group's own, in first-seen order."""
    cols = list(COMMON_COLUMNS)
    for r in rows:
        cols += [k for k in r if k not in cols]
    return cols


def write_csv(rows: list[dict], path) -> Path:
    path = Path(path)
    with path.open("w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=columns(rows), restval="")
        writer.writeheader()
        writer.writerows(rows)
    return path


def _fmt(v) -> str:
    if isinstance(v, float):
        return f"{v:.3g}"
    return str(v)


def format_table(rows: list[dict]) -> str:
    """A plain-text table, one block per group."""
    lines = []
    for group in GROUPS:
        block = [r for r in rows if r["group"] == group]
        if not block:
            continue
        extra = TABLE_COLUMNS[group]
        head = ["variant", "time (ms)", "x base", "error", *extra]
        body = [
            [
                r["variant"],
                f"{r['time_median_s'] * 1e3:.3g}",
                f"{r['time_ratio_to_baseline']:.2f}",
                _fmt(r["error"]),
                *(_fmt(r.get(c, "")) for c in extra),
            ]
            for r in block
        ]
        widths = [max(len(s) for s in col) for col in zip(head, *body)]
        lines.append(
            f"{group}: error = {ERROR_MEASURE[group]}; x base = time / {block[0]['baseline']}"
        )
        for cells in [head, *body]:
            lines.append(
                "  "
                + "  ".join(
                    c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(cells, widths))
                )
            )
        lines.append("")
    return "\n".join(lines)


# -- plots (matplotlib imported here only) ----------------------------------------------------
#: The panels of the Pareto figure: (group, title, x key, y key, x label, y label, log x).
PANELS = (
    (
        "interpolation",
        "interpolation: error vs numpy time",
        "time_ms",
        "error",
        "time per run (ms, median)",
        ERROR_MEASURE["interpolation"],
        True,
    ),
    (
        "interpolation",
        "interpolation: error vs divides (the classic cost)",
        "divides_per_pixel",
        "error",
        "perspective divides per pixel (what a scalar span loop pays)",
        ERROR_MEASURE["interpolation"],
        False,
    ),
    (
        "edge functions",
        "edge functions: coverage errors",
        "time_ms",
        "error",
        "time per run (ms, median)",
        ERROR_MEASURE["edge functions"],
        True,
    ),
    (
        "edge functions",
        "edge functions: cracks in a watertight mesh",
        "time_ms",
        "cracks",
        "time per run (ms, median)",
        "mesh gaps + double hits (pixels)",
        True,
    ),
    (
        "fill",
        "fill algorithms",
        "time_ms",
        "error",
        "time per run (ms, median)",
        ERROR_MEASURE["fill"],
        True,
    ),
    (
        "depth",
        "depth storage and mapping",
        "time_ms",
        "error",
        "time per render (ms, median)",
        ERROR_MEASURE["depth"],
        True,
    ),
)


def _place_labels(ax, pts, texts, fontsize=7.5):
    """Label points without overlaps: greedy, each label tries slots above and below.

    Positions are worked out in axes fractions (the axes' limits and scales must be final);
    a label moved away from its point gets a thin leader line.
    """
    to_axes = ax.transData + ax.transAxes.inverted()
    char_w, line_h = 0.0058 * fontsize / 7.5 * 1.6, 0.034 * fontsize / 7.5
    placed = []
    order = sorted(range(len(pts)), key=lambda i: (pts[i][0], pts[i][1]))
    for i in order:
        px, py = to_axes.transform(pts[i])
        w = char_w * len(texts[i])
        for k in (0, 1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6):
            x0, y0 = px + 0.012, py + 0.004 + k * line_h
            box = (x0, y0, x0 + w, y0 + line_h * 0.9)
            clash = any(
                box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3] for b in placed
            )
            if not clash:
                break
        placed.append(box)
        ax.annotate(
            texts[i],
            pts[i],
            xytext=(x0, y0),
            textcoords="axes fraction",
            fontsize=fontsize,
            va="bottom",
            arrowprops={"arrowstyle": "-", "lw": 0.5, "color": "gray"} if k else None,
        )


def pareto_panel(ax, block, title, xkey, ykey, xlabel, ylabel, xlog):
    """One panel of :func:`pareto_figure`: the variants of ``block`` (rows of one group),
    error ``ykey`` against cost ``xkey``, with the Pareto front; for lessons that lay out
    the panels themselves."""
    pts = [dict(r, time_ms=r["time_median_s"] * 1e3) for r in block]
    errors = np.array([float(p[ykey]) for p in pts])
    exact = errors == 0
    integral = bool(np.all(errors == np.round(errors)))
    if exact.all():
        # Nothing to trade: every variant is exact, only the time differs.
        floor, ylog = 0.0, False
    else:
        floor, ylog = (0.5 if integral else errors[~exact].min() / 4), True
    for p, e in zip(pts, errors):
        p["_x"], p["_y"] = float(p[xkey]), max(float(e), floor)
    front = pareto_front(pts, "_x", "_y")
    on_front = {id(p) for p in front}
    xs, ys = [p["_x"] for p in pts], [p["_y"] for p in pts]
    if xlog:
        from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

        ax.set_xscale("log")
        ax.set_xlim(min(xs) / 1.3, max(xs) * 2.6)  # room for labels on the right
        # Plain numbers at 1, 2, 5 x 10^k: easier to read off than 2 x 10^0.
        ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
        ax.xaxis.set_minor_formatter(NullFormatter())
    else:
        span = max(xs) - min(xs) or 1.0
        ax.set_xlim(min(xs) - 0.05 * span, max(xs) + 0.45 * span)
    if ylog:
        ax.set_yscale("log")
        ax.set_ylim(min(ys) / 3, max(ys) * 6)
    else:
        ax.set_ylim(-1, 1)
        ax.set_yticks([0], ["0 (exact)"])
    if len(front) > 1:
        fx, fy = [p["_x"] for p in front], [p["_y"] for p in front]
        right = ax.get_xlim()[1]
        # A step line: the least error reachable within each time (or cost) budget.
        ax.step(
            fx + [right],
            fy + [fy[-1]],
            where="post",
            color="tab:red",
            lw=1.4,
            alpha=0.6,
            label="Pareto front",
            zorder=1,
        )
        ax.legend(loc="upper right", fontsize=8)
    for p in pts:
        best = id(p) in on_front
        ax.scatter(
            p["_x"],
            p["_y"],
            s=40 if best else 26,
            zorder=3,
            marker="o" if best else "s",
            color="tab:red" if best else "tab:blue",
        )
    if ylog and exact.any():
        ax.axhline(floor, color="gray", ls="--", lw=0.8)
        ax.annotate(
            "0 (exact)",
            (0.005, floor),
            xycoords=("axes fraction", "data"),
            xytext=(0, -10),
            textcoords="offset points",
            fontsize=8,
            color="gray",
        )
    _place_labels(ax, [(p["_x"], p["_y"]) for p in pts], [p["variant"] for p in pts])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, which="major", alpha=0.3)
    note = " (all exact: only the time differs)" if exact.all() else ""
    ax.set_title(f"{title}{note}", fontsize=11)


def pareto_figure(rows: list[dict]):
    """Error against cost for every variant, one panel per measure, Pareto front drawn.

    Panels (:data:`PANELS`): interpolation error against time and against perspective
    divides per pixel; edge-function coverage errors and mesh cracks against time; fill
    and depth errors against time. Errors use a log axis; an error of exactly 0 is drawn on
    a dashed "0 (exact)" line below the smallest non-zero one. Red round markers are on the
    front (nothing is both faster and more accurate). Returns a
    ``matplotlib.figure.Figure`` (no pyplot state: safe in scripts and notebooks).
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(16, 15), layout="constrained")
    axes = fig.subplots(3, 2).ravel()
    for ax, (group, title, xkey, ykey, xlabel, ylabel, xlog) in zip(axes, PANELS):
        block = [r for r in rows if r["group"] == group and ykey in r]
        if not block:
            ax.set_visible(False)
            continue
        pareto_panel(ax, block, title, xkey, ykey, xlabel, ylabel, xlog)
    fig.suptitle(
        "Accuracy vs time: lower left is better; red = on the Pareto front "
        "(no variant is both cheaper and more accurate)",
        fontsize=13,
    )
    return fig


def subdivision_figure(rows: list[dict]):
    """Max and mean texel error of subdivided interpolation against N, with the two bounds."""
    from matplotlib.figure import Figure

    block = {r["variant"]: r for r in rows if r["group"] == "interpolation"}
    fig = Figure(figsize=(7, 4.5), layout="constrained")
    ax = fig.subplots()
    ns = [n for n in SUBDIVISIONS if f"subdivided N={n}" in block]
    for key, label, style in (("error", "max", "o-"), ("mean_abs_texels", "mean", "s--")):
        ax.plot(
            ns, [block[f"subdivided N={n}"][key] for n in ns], style, label=f"subdivided, {label}"
        )
        if "affine" in block:
            ax.axhline(block["affine"][key], color="tab:red", ls=":", lw=1)
            ax.annotate(
                f"affine, {label}",
                (ns[0], block["affine"][key]),
                fontsize=8,
                color="tab:red",
                xytext=(0, 3),
                textcoords="offset points",
            )
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("N: pixels between perspective-correct divides")
    ax.set_ylabel("|uv error| (texels of a 256-texel texture)")
    ax.set_title("Subdivided perspective: one divide every N pixels")
    ax.grid(True, which="both", alpha=0.25)
    ax.legend(fontsize=8)
    return fig


def plot(rows: list[dict], out_dir) -> list[Path]:
    """Write ``pareto.png`` and ``subdivision.png`` into ``out_dir``; return their paths."""
    out_dir = Path(out_dir)
    paths = [out_dir / "pareto.png", out_dir / "subdivision.png"]
    pareto_figure(rows).savefig(paths[0], dpi=110)
    subdivision_figure(rows).savefig(paths[1], dpi=110)
    return paths


# -- command line -----------------------------------------------------------------------------
def main(argv: list[str] | None = None) -> int:
    """``python -m teachraster.study.bench [--quick] [--out DIR] [--repeat N]``."""
    parser = argparse.ArgumentParser(
        prog="python -m teachraster.study.bench",
        description="Accuracy vs time of teachraster's cheaper and costlier variants.",
    )
    parser.add_argument("--quick", action="store_true", help="small scenes: a smoke run")
    parser.add_argument("--out", default="bench-out", help="output directory (bench-out/)")
    parser.add_argument("--repeat", type=int, default=None, help="timed runs per variant")
    parser.add_argument("--no-plots", action="store_true", help="write the CSV only")
    args = parser.parse_args(argv)
    if args.repeat is not None and args.repeat < 1:
        parser.error("--repeat must be >= 1")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = run(args.quick, repeat=args.repeat, progress=True)
    print(format_table(rows))
    written = [write_csv(rows, out / "bench.csv")]
    if not args.no_plots:
        written += plot(rows, out)
    print("wrote " + ", ".join(str(p) for p in written))
    return 0


if __name__ == "__main__":
    sys.exit(main())
