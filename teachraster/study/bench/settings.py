"""What the study measures: groups, variants, sizes and the columns of its table."""

from __future__ import annotations

from .. import precision

GROUPS = ("interpolation", "edge functions", "fill", "depth")

#: Texture size that converts texture coordinates to texels.
TEXELS = 256
#: Roll of the study's floor camera about its view axis, in degrees: depth changes along
#: every raster line (level, each line would have one depth).
FLOOR_ROLL = 25.0
SUBDIVISIONS = (2, 4, 8, 16, 32)
EDGE_VARIANTS = tuple(
    (arith, ev) for arith in precision.ARITHMETICS for ev in precision.EVALUATIONS
)
#: Offsets (px) at which the jittered mesh is rasterised, through an image window there.
MESH_OFFSETS = (0, 100_000, 1_000_000)
DEPTH_FORMATS = ("float64", "float32", "unorm24", "unorm16")
DEPTH_MAPPINGS = ("window", "linear")
#: The depth variants, (mapping, format): every format for both mappings, and reverse-Z
#: (``reversed_depth``, the test reversed: greater wins) in float32, the format it is for, and
#: in unorm24, where a unorm's even steps make reversing change nothing (lesson 05b §4): a row
#: that shows it (review r243 FIG2: the chart read as if reverse-Z helped unorm24 too).
DEPTH_VARIANTS = tuple((m, f) for m in DEPTH_MAPPINGS for f in DEPTH_FORMATS) + (
    ("reversed", "float32"),
    ("reversed", "unorm24"),
)
#: View distances of the depth pairs, and the gap between the two triangles of a pair.
DEPTH_DISTANCES = (1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0)
DEPTH_GAP = 0.01
#: View distances of the slanted pairs (a camera-facing triangle pierced by a slanted one),
#: out to near the far plane, where window depth has the least resolution.
SLANTED_DISTANCES = (1.0, 5.0, 20.0, 50.0, 100.0, 200.0, 400.0, 700.0, 900.0)
#: How far a slanted triangle's depth runs either side of its pair's distance (a fraction).
SLANT = 0.4
NEAR, FAR = 0.1, 1000.0

#: What the ``error`` column means, per group (the y axis of the Pareto plot).
ERROR_MEASURE = {
    "interpolation": "max |uv error| (texels)",
    "edge functions": "pixels wrong vs exact 1/256 coverage",
    "fill": "pixels wrong vs exact 1/256 coverage",
    "depth": "depth-order inversions (pixels)",
}
#: Extra columns printed in the table, per group (all of them go to the CSV).
TABLE_COLUMNS = {
    "interpolation": ("mean_abs_texels", "error_px", "mean_error_px", "divides_per_pixel"),
    "edge functions": ("gaps", "double_hits", "wrong_px_unsnapped_geometry"),
    "fill": ("coverage_median_s",),
    "depth": ("facing_wrong", "slanted_wrong", "first_inverted_z"),
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
        "depth": [f"{m} {f}" for m, f in DEPTH_VARIANTS],
    }
