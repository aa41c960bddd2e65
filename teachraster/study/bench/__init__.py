"""Accuracy vs time: what each cheaper or costlier way of rasterising gets wrong, and costs.

Run ``python -m teachraster.study.bench [--quick] [--out DIR] [--repeat N] [--cpu]``. On fixed,
seeded scenes it measures every variant's error against a ground truth computed independently
of the rasteriser, and its time (the median of ``--repeat`` runs after two warm-ups, with
``time.perf_counter``, or this process's CPU time, ``time.process_time``, with ``--cpu`` or
``run(clock=...)``; the variants of a group are timed round-robin, so a busy machine slows
them alike). It prints a table, writes ``bench.csv`` (one row per variant) and
the plots ``pareto.png`` and ``subdivision.png`` into DIR (default ``bench-out/``).

Groups
------
interpolation
    ``tr.rasterize`` of a steeply receding textured floor (two triangles) with affine,
    perspective-correct and subdivided (N = 2 ... 32) interpolation. Error: absolute error of
    the texture coordinates, in texels of a 256-texel texture, against a ray-plane
    intersection per pixel centre in 3D (float64), which never uses screen-space
    barycentrics; and (``error_px``, ``mean_error_px``) how far on screen that error moves
    the texture, in pixels (:func:`floor_errors`).
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
    the algorithm and the trace cost, not what they buy in accuracy). The timed triangle has
    w and uv, so each fill also interpolates uv perspective-correctly at every pixel, the
    same work for both algorithms; ``coverage_median_s`` (and its min and max) times the
    same fill of the bare positions, in the same rounds: the coverage alone.
depth
    ``tr.render`` with each ``depth_format`` storing either the window depth (the hyperbola
    ``z' = n + f - fn/z`` rescaled to [0, 1]) or a depth linear in view distance, and
    reverse-Z (the reversed depth, the test reversed: :func:`greater_passes`) in float32 and
    in unorm24 (where it changes nothing), on pairs of
    nearly coplanar overlapping triangles at distances 1 to 500, and on crossing pairs (a
    camera-facing triangle pierced by a slanted one, :func:`slanted_pairs`) at distances 1 to
    900. Error: depth-order inversions, pixels whose visible triangle differs from the true
    nearest one, summed over both sets (``facing_wrong``, ``slanted_wrong``).

The study is a package: :mod:`.settings` (groups, variants, sizes), :mod:`.timing`,
:mod:`.ground_truth` (exact coverage, ray-traced texture coordinates), :mod:`.groups` (the four
groups), :mod:`.measure` (the whole run), :mod:`.report` (Pareto front, CSV, table, figures)
and :mod:`.command` (the command line).

:func:`run` returns the rows, :func:`pareto_front` picks the variants no other beats on both
time and error, and :func:`pareto_figure` draws the trade-off (matplotlib is imported only
there, so the package stays numpy-only).
"""

from .command import (
    main,
)
from .ground_truth import (
    exact_coverage,
    uv_ground_truth,
)
from .groups import (
    RCP_BITS,
    bench_depth,
    bench_edges,
    bench_fill,
    bench_interpolation,
    depth_clip,
    depth_pairs,
    fill_triangle,
    floor_errors,
    floor_quad,
    greater_passes,
    jittered_mesh,
    mesh_wrong_pixels,
    random_triangles,
    slanted_pairs,
)
from .measure import (
    run,
)
from .report import (
    FRONT_DEFINITION,
    PANELS,
    columns,
    format_table,
    pareto_figure,
    pareto_front,
    pareto_panel,
    plot,
    subdivision_figure,
    write_csv,
)
from .settings import (
    COMMON_COLUMNS,
    DEPTH_DISTANCES,
    DEPTH_FORMATS,
    DEPTH_GAP,
    DEPTH_MAPPINGS,
    DEPTH_VARIANTS,
    EDGE_VARIANTS,
    ERROR_MEASURE,
    FAR,
    FLOOR_ROLL,
    GROUPS,
    MESH_OFFSETS,
    NEAR,
    SUBDIVISIONS,
    TABLE_COLUMNS,
    TEXELS,
    sizes,
    variant_names,
)
from .timing import (
    Progress,
    time_interleaved,
    time_rows,
)
from .worst_pixel import (
    check_doubling_cut,
    steepest_piece,
)

__all__ = [
    "COMMON_COLUMNS",
    "DEPTH_DISTANCES",
    "DEPTH_FORMATS",
    "RCP_BITS",
    "DEPTH_GAP",
    "DEPTH_MAPPINGS",
    "DEPTH_VARIANTS",
    "EDGE_VARIANTS",
    "ERROR_MEASURE",
    "FAR",
    "FLOOR_ROLL",
    "GROUPS",
    "MESH_OFFSETS",
    "NEAR",
    "PANELS",
    "Progress",
    "SUBDIVISIONS",
    "TABLE_COLUMNS",
    "TEXELS",
    "bench_depth",
    "bench_edges",
    "bench_fill",
    "bench_interpolation",
    "columns",
    "depth_clip",
    "depth_pairs",
    "check_doubling_cut",
    "steepest_piece",
    "slanted_pairs",
    "exact_coverage",
    "fill_triangle",
    "floor_errors",
    "floor_quad",
    "greater_passes",
    "format_table",
    "jittered_mesh",
    "mesh_wrong_pixels",
    "main",
    "pareto_figure",
    "FRONT_DEFINITION",
    "pareto_front",
    "pareto_panel",
    "plot",
    "random_triangles",
    "run",
    "sizes",
    "subdivision_figure",
    "time_interleaved",
    "time_rows",
    "uv_ground_truth",
    "variant_names",
    "write_csv",
]
