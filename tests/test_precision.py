"""teachraster.study.precision: the edge-function arithmetics of the accuracy-vs-time study."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import KINDS, random_triangles, raster, reference_coverage

import teachraster as tr
from teachraster.study import precision
from teachraster.study.bench import exact_coverage, jittered_mesh

SIZE = 24


def _triangles(rng, n_per_kind=6):
    return np.concatenate([random_triangles(rng, k, n_per_kind, SIZE, SIZE) for k in KINDS])


def test_fixed8_direct_and_incremental_equal_rasterize(rng):
    for xy in _triangles(rng):
        want = raster(xy, SIZE, SIZE)
        for ev in precision.EVALUATIONS:
            got = precision.coverage(xy, SIZE, SIZE, "fixed8", ev)
            assert (got == want).all(), (ev, xy.tolist())


def test_fixed8_matches_the_exact_rational_reference(rng):
    for xy in random_triangles(rng, "tie", 20, 8, 8):
        assert (precision.coverage(xy, 8, 8) == reference_coverage(xy, 8, 8)).all()


def test_fixed4_equals_rasterize_with_4_bits(rng):
    for xy in _triangles(rng):
        want = raster(xy, SIZE, SIZE, subpixel_bits=4)
        for ev in precision.EVALUATIONS:
            assert (precision.coverage(xy, SIZE, SIZE, "fixed4", ev) == want).all()


def test_unsnapped_equals_rasterize_without_snapping(rng):
    for xy in _triangles(rng, 3):
        want = raster(xy, SIZE, SIZE, subpixel_bits=None)
        assert (precision.coverage(xy, SIZE, SIZE, "unsnapped") == want).all()


def test_float64_equals_fixed8_for_small_coordinates(rng):
    # Snapped small coordinates need few bits: every product and difference is exact.
    for xy in _triangles(rng):
        want = precision.coverage(xy, SIZE, SIZE, "fixed8")
        for ev in precision.EVALUATIONS:
            assert (precision.coverage(xy, SIZE, SIZE, "float64", ev) == want).all()


def test_exact_arithmetics_ignore_the_window_origin(rng):
    offset = np.array([100_000, 300_000])
    for xy in _triangles(rng, 2):
        for arith in ("fixed8", "fixed4"):
            near = precision.coverage(xy, SIZE, SIZE, arith)
            far = precision.coverage(xy + offset, SIZE, SIZE, arith, origin=tuple(offset))
            assert (near == far).all()


def test_far_from_origin_float32_goes_wrong_where_fixed8_stays_exact():
    # At 1e6 px float32 keeps 1/16 px: the vertices move, so coverage differs from the exact
    # 1/256 reference, while fixed8 stays exact and the mesh stays covered exactly once.
    size, off = 256, 1_000_000
    mesh = jittered_mesh(size, cells=4) + off
    wrong = 0
    for xy in mesh:
        ref = exact_coverage(xy, size, size, 8, origin=(off, off))
        assert (precision.coverage(xy, size, size, "fixed8", origin=(off, off)) == ref).all()
        wrong += (precision.coverage(xy, size, size, "float32", origin=(off, off)) != ref).sum()
    assert wrong > 0
    counts = precision.mesh_coverage_counts(mesh, size, size, "fixed8", origin=(off, off))
    assert (counts[1:-1, 1:-1] == 1).all() and counts.max() == 1


def test_float32_stepping_cracks_a_mesh_that_fixed8_covers_exactly_once():
    # Gaps and double hits need a rounding error larger than a centre's distance to an edge:
    # long rows of incremental float32 stepping produce them; fixed8 never does.
    size = 2048
    mesh = jittered_mesh(size, cells=4, seed=3)
    exact = precision.mesh_coverage_counts(mesh, size, size, "fixed8", "incremental")
    assert exact.max() == 1 and (exact[1:-1, 1:-1] == 1).all()
    f32 = precision.mesh_coverage_counts(mesh, size, size, "float32", "incremental")
    gaps = ((exact == 1) & (f32 == 0)).sum()
    assert gaps + (f32 > 1).sum() > 0


def test_incremental_float32_drifts_over_thousands_of_pixels():
    # E reaches ~1.6e5 px² with 1/256-px steps: more bits than float32's 24, so every
    # addition rounds, and the roundings pile up along the row.
    xy = [[0.3, 0.1], [4000.7, 37.3], [10.2, 39.9]]
    width, height = 4000, 40
    exact = precision.edge_values(xy, width, height, "float64", "direct")  # exact here
    stepped = precision.edge_values(xy, width, height, "float32", "incremental")
    drift = np.abs(stepped - exact).max(axis=(0, 1))  # per column: steps taken
    assert drift[-500:].max() > 20 * drift[:20].max() > 0
    assert drift[-500:].max() > 1.0  # px²: several pixel-widths of edge displacement
    # Direct float32 rounds once per pixel and does not accumulate; float64 stepping is exact.
    direct = precision.edge_values(xy, width, height, "float32", "direct")
    assert np.abs(direct - exact).max() < 0.05
    f64 = precision.edge_values(xy, width, height, "float64", "incremental")
    assert np.abs(f64 - exact).max() < 1e-6
    # ... and the drift decides pixels: wrong ones appear only far along the row.
    wrong = precision.coverage(xy, width, height, "float32", "incremental") != raster(
        xy, width, height
    )
    assert wrong.any() and np.nonzero(wrong)[1].min() > 1000


def test_edge_values_are_positive_inside():
    xy = [[0.5, 0.5], [9.2, 1.3], [2.1, 7.7]]
    cov = precision.coverage(xy, 10, 10)
    e = precision.edge_values(xy, 10, 10)
    assert (e[:, cov] >= 0).all()


def test_mesh_counts_of_a_split_square():
    square = [[[0, 0], [8, 0], [0, 8]], [[8, 0], [8, 8], [0, 8]]]
    for arith in precision.ARITHMETICS:
        counts = precision.mesh_coverage_counts(square, 8, 8, arith)
        assert (counts == 1).all(), arith


def test_zero_area_covers_nothing():
    for arith in precision.ARITHMETICS:
        assert not precision.coverage([[1, 1], [5, 5], [3, 3]], 8, 8, arith).any()


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"arithmetic": "float16"}, "arithmetic"),
        ({"evaluation": "sideways"}, "evaluation"),
        ({"origin": (0.5, 0)}, "origin"),
    ],
)
def test_bad_arguments(kwargs, match):
    with pytest.raises(ValueError, match=match):
        precision.coverage([[0, 0], [4, 0], [0, 4]], 4, 4, **kwargs)


def test_core_is_unchanged_by_importing_precision():
    # precision is a study module: the default path stays tr.rasterize's own.
    fill = tr.rasterize(tr.Triangle([[0, 0], [4, 0], [0, 4]]), 4, 4)
    assert int(fill.coverage.sum()) == 6


def _gpu_edge_values(xy, width, height):
    """E of each oriented edge at every pixel centre, exact integers on a GPU's grid (256 units
    a pixel): computed here apart from the package, to check what wrong_regions reads."""
    p = np.rint(np.asarray(xy, float) * 256).astype(np.int64)
    (ax, ay), (bx, by), (cx, cy) = p
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0:
        p = p[[0, 2, 1]]
    jj, ii = np.meshgrid(256 * np.arange(width) + 128, 256 * np.arange(height) + 128)
    return np.array([(b[0] - a[0]) * (ii - a[1]) - (b[1] - a[1]) * (jj - a[0])
                     for a, b in zip(p, np.roll(p, -1, axis=0))])  # fmt: skip


def test_wrong_regions_of_lesson_10s_int32_walk():
    """Review r247 C1 (lesson 10): the wrong regions' sides follow the triangle's edges, lines
    parallel to an edge where its value passes a multiple of 2**31, and the bounding box; only
    a handful lie on 4x4 block boundaries. Each side is checked here on exact integers."""
    from teachraster.core import fixed_point

    xy = [[3.2, 6.4], [312.6, 18.8], [62.8, 312.6]]
    narrow = fixed_point.narrow_fill(tr.Triangle(xy), 320, 320, int_bits=32,
                                     block_sizes=(16, 4), centre_bit=False)  # fmt: skip
    found = precision.wrong_regions(xy, narrow)
    wrong = narrow.wrong
    assert found.wrong == int(wrong.sum()) > 0
    assert found.wrongly_in == int((narrow.coverage & ~narrow.exact).sum())
    e = _gpu_edge_values(xy, 320, 320)
    total, wrap_checked = 0, 0
    for axis in (0, 1):
        n = wrong.shape[axis] - 1
        a, b = np.arange(n), np.arange(1, n + 1)
        side = wrong.take(a, axis=axis) != wrong.take(b, axis=axis)
        total += int(side.sum())
        ea, eb = e.take(a, axis=axis + 1), e.take(b, axis=axis + 1)
        # floor division by 2**31 changes between the two centres, other than at 0 alone
        band_a, band_b = ea // 2**31, eb // 2**31
        crossed = (band_a != band_b) & ~(np.minimum(band_a, band_b) == -1) | (
            np.abs(band_a - band_b) > 1)  # fmt: skip
        wrap_checked += int((side & crossed.any(axis=0)).sum())
    assert sum(found.sides.values()) == total
    assert found.sides["other"] == 0 and found.sides["block"] < 0.02 * total
    # every side counted as a wrap line does cross a nonzero multiple of 2**31 (some sides on
    # one also cross an edge or lie on the box, and count there first)
    assert found.sides["wrap"] <= wrap_checked and found.sides["wrap"] > 0.4 * total
    assert found.sides["box"] > 0 and found.near < 0.05 * found.wrong


def test_wrong_regions_within_the_budget_are_empty():
    from teachraster.core import fixed_point

    xy = [[2.2, 3.1], [25.6, 8.3], [9.4, 27.7]]
    narrow = fixed_point.narrow_fill(tr.Triangle(xy), 32, 32, int_bits=32, block_sizes=(16, 4),
                                     centre_bit=False)  # fmt: skip
    found = precision.wrong_regions(xy, narrow)
    assert found.wrong == found.near == 0 and not any(found.sides.values())
