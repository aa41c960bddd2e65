"""Multisampling in ``tr.rasterize``: sample patterns, per-sample coverage, attributes per pixel.

Coverage per sample is checked against an exact rational reference written from CONVENTIONS
(*Multisampling*: sample s of pixel (i, j) at (j + ox_s, i + oy_s), decided like a centre) and
against the centre fill of the translated triangle; attributes against the exact plane.
"""

from __future__ import annotations

import itertools
from fractions import Fraction

import numpy as np
import pytest
from conftest import (
    KINDS,
    METHODS,
    PERMUTATIONS,
    edge_exact,
    exact_barycentric,
    random_triangles,
    snapped_vertices,
    top_left,
)

import teachraster as tr
from teachraster.core.sample_patterns import as_samples

STANDARD = (2, 4, 8, 16)


def reference_samples(xy, width, height, offsets, bits=8) -> np.ndarray:
    """(H, W, S) coverage of the snapped triangle at every sample, in exact Fractions."""
    v = snapped_vertices(xy, bits)
    out = np.zeros((height, width, len(offsets)), dtype=bool)
    area2 = edge_exact(v[0], v[1], v[2])
    if area2 == 0:
        return out
    if area2 < 0:
        v = [v[0], v[2], v[1]]
    edges = [(v[k], v[(k + 1) % 3]) for k in range(3)]
    tl = [top_left(a, b) for a, b in edges]
    ys = [p[1] for p in v]
    for s, (ox, oy) in enumerate(offsets):
        ox, oy = Fraction(float(ox)), Fraction(float(oy))
        for i in range(height):
            py = i + oy
            if not min(ys) <= py <= max(ys):
                continue
            for j in range(width):
                p = (j + ox, py)
                e = [edge_exact(a, b, p) for a, b in edges]
                out[i, j, s] = all(ek > 0 or (ek == 0 and t) for ek, t in zip(e, tl))
    return out


# -- sample patterns ------------------------------------------------------------------------------
def test_standard_patterns():
    assert tr.sample_pattern(1).tolist() == [[0.5, 0.5]]
    assert tr.sample_pattern(4).tolist() == [
        [0.375, 0.125], [0.875, 0.375], [0.125, 0.625], [0.625, 0.875]
    ]  # fmt: skip
    for n in STANDARD:
        p = tr.sample_pattern(n)
        assert p.shape == (n, 2) and ((p >= 0) & (p < 1)).all()
        assert len({tuple(q) for q in p.tolist()}) == n  # distinct
        assert (p * 16 == np.round(p * 16)).all()  # Direct3D's 1/16 px grid
        # rotated: no two samples share a column or a row (n <= 16 on a 16-wide grid)
        assert len(set(p[:, 0])) == n and len(set(p[:, 1])) == n


def test_grid_jittered_random():
    g = tr.sample_pattern(9, "grid")
    assert np.allclose(sorted(set(g[:, 0])), [1 / 6, 1 / 2, 5 / 6])
    for kind in ("jittered", "random"):
        a, b = tr.sample_pattern(16, kind, seed=3), tr.sample_pattern(16, kind, seed=3)
        assert np.array_equal(a, b) and not np.array_equal(a, tr.sample_pattern(16, kind, 4))
        assert ((a >= 0) & (a < 1)).all() and (a * 256 == np.round(a * 256)).all()
    j = tr.sample_pattern(16, "jittered", seed=1)
    cells = np.floor(j * 4).astype(int)  # one point per cell, in row-major cell order
    assert cells.tolist() == [[c, r] for r in range(4) for c in range(4)]
    assert tr.sample_pattern(5, "random").shape == (5, 2)


@pytest.mark.parametrize(
    "args, name",
    [((3,), "n"), ((0,), "n"), ((8, "grid"), "n"), ((2, "jittered"), "n"), ((4, "hex"), "kind"),
     ((4, "random", -1), "seed")],
)  # fmt: skip
def test_pattern_errors_name_the_argument(args, name):
    with pytest.raises(ValueError, match=name):
        tr.sample_pattern(*args)


@pytest.mark.parametrize(
    "samples", [3, 0, -4, 32, [[0.5, 1.0]], [[0.5, -0.1]], [0.5, 0.5], [[np.nan, 0.5]], []]
)
def test_bad_samples(samples):
    tri = tr.Triangle([[0, 0], [4, 0], [0, 4]])
    with pytest.raises(ValueError, match="samples"):
        tr.rasterize(tri, 4, 4, samples=samples)


def test_bad_samples_types_and_options():
    tri = tr.Triangle([[0, 0], [4, 0], [0, 4]])
    for bad in (True, 4.0, "4"):
        with pytest.raises(TypeError, match="samples"):
            tr.rasterize(tri, 4, 4, samples=bad)
    with pytest.raises(TypeError, match="centroid"):
        tr.rasterize(tri, 4, 4, samples=4, centroid=1)
    with pytest.raises(TypeError, match="per_sample"):
        tr.rasterize(tri, 4, 4, samples=4, per_sample="yes")
    with pytest.raises(ValueError, match="interpolation"):
        tr.rasterize(tri, 4, 4, samples=4, interpolation="subdivided")
    assert as_samples(np.array([[0.25, 0.75]])).tolist() == [[0.25, 0.75]]


# -- coverage per sample --------------------------------------------------------------------------
@pytest.mark.parametrize("kind", KINDS)
def test_sample_coverage_exact_and_methods_agree(rng, kind):
    W, H = 12, 9
    for n, xy in itertools.product(STANDARD, random_triangles(rng, kind, 6, W, H)):
        offsets = tr.sample_pattern(n)
        want = reference_samples(xy, W, H, offsets)
        for method in METHODS:
            fill = tr.rasterize(tr.Triangle(xy), W, H, samples=n, method=method)
            assert np.array_equal(fill.sample_coverage, want), (kind, n, method, xy.tolist())
            assert np.array_equal(fill.coverage, want.any(axis=2))
            assert np.array_equal(fill.coverage_fraction, want.mean(axis=2))


def test_sample_is_the_centre_of_the_shifted_triangle(rng):
    """Sample s of triangle T == pixel centres of T moved by (1/2 - o_s): shifts on the grid."""
    W, H = 16, 12
    for xy in random_triangles(rng, "float", 20, W, H):
        for n in STANDARD:
            offsets = tr.sample_pattern(n)
            fill = tr.rasterize(tr.Triangle(xy), W, H, samples=n)
            for s, o in enumerate(offsets):
                moved = tr.rasterize(tr.Triangle(xy + (0.5 - o)), W, H).coverage
                assert np.array_equal(fill.sample_coverage[..., s], moved), (n, s, xy.tolist())


def test_every_vertex_order_and_custom_patterns(rng):
    W, H = 10, 10
    patterns = [tr.sample_pattern(9, "grid"), tr.sample_pattern(7, "random", seed=5),
                tr.sample_pattern(16, "jittered", seed=2), np.array([[0.5, 0.5]])]  # fmt: skip
    for xy in random_triangles(rng, "tie", 8, W, H):
        for offsets in patterns:
            # offsets as tested lie on the 1/512 px grid: compare with the reference there
            tested = np.rint(offsets * 512) / 512
            want = reference_samples(xy, W, H, tested)
            for perm, method in itertools.product(PERMUTATIONS, METHODS):
                fill = tr.rasterize(tr.Triangle(xy[list(perm)]), W, H, samples=offsets,
                                    method=method)  # fmt: skip
                assert np.array_equal(fill.sample_coverage, want), (perm, method, xy.tolist())
                assert np.array_equal(fill.samples, tested)


def test_centre_pattern_equals_single_sample(rng):
    for xy in random_triangles(rng, "tie", 20, 8, 8):
        one = tr.rasterize(tr.Triangle(xy), 8, 8)
        multi = tr.rasterize(tr.Triangle(xy), 8, 8, samples=[[0.5, 0.5]])
        assert np.array_equal(multi.sample_coverage[..., 0], one.coverage)


def test_raw_floats_and_culling():
    xy = np.array([[0.3, 0.2], [7.1, 1.3], [2.2, 6.9]])
    raw = tr.rasterize(tr.Triangle(xy), 8, 8, samples=4, subpixel_bits=None)
    span = tr.rasterize(tr.Triangle(xy), 8, 8, samples=4, subpixel_bits=None, method="span")
    assert np.array_equal(raw.sample_coverage, span.sample_coverage)
    p = tr.sample_pattern(4)
    for s in range(4):  # raw floats: tested where the pattern says, no grid
        x, y = np.meshgrid(np.arange(8) + p[s, 0], np.arange(8) + p[s, 1])
        e = [tr.edge_function(xy[k], xy[(k + 1) % 3], np.stack([x, y], -1)) for k in range(3)]
        assert np.array_equal(raw.sample_coverage[..., s], np.all(np.array(e) > 0, axis=0))
    culled = tr.rasterize(tr.Triangle(xy), 8, 8, samples=4, cull="back")  # clockwise on screen
    assert not culled.sample_coverage.any() and not culled.coverage.any()


# -- attributes -----------------------------------------------------------------------------------
def exact_value(xy, point, values, w=None):
    """The attribute plane at ``point`` (inside or out), exactly, perspective when w given."""
    lam = exact_barycentric(xy, point)
    if w is None:
        return float(sum(lv * Fraction(f) for lv, f in zip(lam, values)))
    q = [lv / Fraction(wi) for lv, wi in zip(lam, w)]
    return float(sum(qi * Fraction(f) for qi, f in zip(q, values)) / sum(q))


def test_attributes_at_the_centre_extrapolate(rng):
    W, H = 10, 8
    for xy in random_triangles(rng, "float", 10, W, H):
        u = rng.uniform(-1, 1, 3)
        tri = tr.Triangle(xy, attrs={"u": u}, z=[0.2, 0.5, 0.9])
        fill = tr.rasterize(tri, W, H, samples=4, interpolation="affine")
        one = tr.rasterize(tri, W, H, interpolation="affine")
        both = fill.coverage & one.coverage  # covered centres: the ordinary, clamped value
        assert np.array_equal(fill.attrs["u"][both], one.attrs["u"][both])
        rows, cols = np.nonzero(fill.coverage & ~one.coverage)
        for i, j in zip(rows, cols):  # uncovered centres: the plane, extended
            want = exact_value(xy, (j + 0.5, i + 0.5), u)
            assert fill.attrs["u"][i, j] == pytest.approx(want, rel=1e-9, abs=1e-9)
        assert np.isnan(fill.attrs["u"][~fill.coverage]).all()
        assert np.isfinite(fill.depth[fill.coverage]).all()


def sliver():
    """Long and thin: most covered pixels have their centre outside, far from the edges."""
    return np.array([[0.1, 0.3], [15.9, 2.2], [0.2, 0.9]])


def test_extrapolation_leaves_the_range_and_centroid_stays_inside():
    tri = tr.Triangle(sliver(), attrs={"u": [0.0, 1.0, 0.0], "v": [0.0, 0.0, 1.0]})
    msaa = tr.rasterize(tri, 16, 4, samples=4)
    cen = tr.rasterize(tri, 16, 4, samples=4, centroid=True)
    assert np.array_equal(msaa.coverage, cen.coverage)
    v = msaa.attrs["v"][msaa.coverage]
    assert (v < 0).any() or (v > 1).any()  # the centres lie off the sliver: out of range
    for name in ("u", "v"):
        c = cen.attrs[name][cen.coverage]
        assert ((c >= 0) & (c <= 1)).all()
    trace = tr.rasterize(tri, 16, 4, samples=4, centroid=True, trace=True).trace.samples
    one = tr.rasterize(tri, 16, 4).coverage
    moved = trace.eval_sample >= 0
    assert np.array_equal(moved, ~one[trace.eval_rows, trace.eval_cols])
    p = tr.sample_pattern(4)
    for r, c, s, (x, y) in zip(trace.eval_rows[moved], trace.eval_cols[moved],
                               trace.eval_sample[moved], trace.eval_xy[moved]):  # fmt: skip
        assert cen.sample_coverage[r, c, s]
        assert (x, y) == (c + p[s, 0], r + p[s, 1])
        # nearest covered sample to the centre (standard 4: all equally far: lowest index)
        assert s == np.flatnonzero(cen.sample_coverage[r, c])[0]
        want = exact_value(sliver(), (x, y), [0.0, 1.0, 0.0])
        assert cen.attrs["u"][r, c] == pytest.approx(want, abs=1e-12)


def test_centroid_picks_the_nearest_covered_sample():
    offsets = np.array([[0.0, 0.0], [0.25, 0.5], [0.5, 0.75], [0.5, 0.25]])
    # A vertical strip covering x in (0.1, 0.4) of pixel 0: samples 1 (x=.25) only, not centre.
    tri = tr.Triangle([[0.1, -1], [0.4, -1], [0.1, 3]], attrs={"u": [0.0, 1.0, 2.0]})
    fill = tr.rasterize(tri, 1, 1, samples=offsets, centroid=True, trace=True)
    assert fill.sample_coverage[0, 0].tolist() == [False, True, False, False]
    assert fill.trace.samples.eval_sample.tolist() == [1]
    # ties: samples 2 and 3 are both 0.25 from the centre: the lower index wins
    tri = tr.Triangle([[0.45, -1], [0.55, -1], [0.45, 3]])
    fill = tr.rasterize(tri, 1, 1, samples=offsets, centroid=True, trace=True)
    assert fill.sample_coverage[0, 0].tolist() == [False, False, True, True]
    assert fill.trace.samples.eval_sample.tolist() == [-1]  # the centre itself is covered
    # the band y < 0.4 covers samples 0, 2 and 3, not the centre; 2 and 3 are equally near
    offsets = np.array([[0.0, 0.0], [0.25, 0.5], [0.75, 0.25], [0.25, 0.25]])
    tri = tr.Triangle([[-5, 0.4], [5, 0.4], [0, -10]])
    fill = tr.rasterize(tri, 1, 1, samples=offsets, centroid=True, trace=True)
    assert fill.sample_coverage[0, 0].tolist() == [True, False, True, True]
    assert fill.trace.samples.eval_sample.tolist() == [2]


def test_negative_one_over_w_falls_back_to_the_centroid_sample():
    # 1/w is large at vertex 0 and tiny at 1 and 2: extended beyond the long edge v1-v2,
    # away from vertex 0, the plane of 1/w crosses zero before the pixel centres (y = 0.5).
    xy = np.array([[4.0, 0.1], [0.0, 0.45], [8.0, 0.45]])
    w = np.array([1.0, 1000.0, 1000.0])
    tri = tr.Triangle(xy, w=w, attrs={"u": [0.0, 1.0, 0.0]})
    lam = tr.barycentric(tr.snap(xy), [[4.5, 0.5]])[0]
    assert (lam / w).sum() <= 0  # the case exists at pixel (0, 4)
    fill = tr.rasterize(tri, 8, 1, samples=4, trace=True)
    trace = fill.trace.samples
    k = int(np.flatnonzero(trace.eval_cols == 4)[0])
    assert trace.eval_sample[k] >= 0
    u = fill.attrs["u"][fill.coverage]
    assert np.isfinite(u).all()


def test_perspective_extrapolation_matches_the_plane_of_f_over_w(rng):
    W, H = 10, 8
    for xy in random_triangles(rng, "subpixel", 10, W, H):
        w = rng.uniform(1, 3, 3)
        tri = tr.Triangle(xy, w=w, attrs={"u": [0.0, 1.0, 2.0]})
        fill = tr.rasterize(tri, W, H, samples=4, trace=True)
        t = fill.trace.samples
        for r, c, (x, y) in zip(t.eval_rows, t.eval_cols, t.eval_xy):
            want = exact_value(xy, (x, y), [0.0, 1.0, 2.0], w)
            assert fill.attrs["u"][r, c] == pytest.approx(want, rel=1e-9, abs=1e-9)


def test_per_sample_supersampling(rng):
    W, H = 8, 8
    for xy in random_triangles(rng, "float", 8, W, H):
        tri = tr.Triangle(xy, z=[0.1, 0.4, 0.8], attrs={"c": [[1, 0], [0, 1], [0.5, 0.5]]})
        fill = tr.rasterize(tri, W, H, samples=4, per_sample=True)
        sa = fill.sample_attrs["c"]
        assert sa.shape == (H, W, 4, 2)
        assert np.array_equal(np.isnan(sa[..., 0]), ~fill.sample_coverage)
        p = tr.sample_pattern(4)
        for i, j, s in zip(*np.nonzero(fill.sample_coverage)):
            want = exact_value(xy, (j + p[s, 0], i + p[s, 1]), [1, 0, 0.5], [1, 1, 1])
            assert sa[i, j, s, 0] == pytest.approx(want, abs=1e-12)
            assert 0 <= sa[i, j, s, 1] <= 1
        mean = np.nanmean(np.where(fill.sample_coverage[..., None], sa, np.nan)[fill.coverage], 1)
        assert np.allclose(fill.attrs["c"][fill.coverage], mean)
        assert np.allclose(fill.depth[fill.coverage],
                           np.nanmean(fill.sample_depth[fill.coverage], axis=1))  # fmt: skip


def test_sample_depth_and_trace_do_not_change_results(rng):
    for xy in random_triangles(rng, "float", 8, 8, 8):
        tri = tr.Triangle(xy, z=[0.1, 0.4, 0.8], attrs={"u": [0.0, 1.0, 0.0]})
        for method in METHODS:
            a = tr.rasterize(tri, 8, 8, samples=8, method=method)
            b = tr.rasterize(tri, 8, 8, samples=8, method=method, trace=True)
            assert np.array_equal(a.sample_coverage, b.sample_coverage)
            assert np.array_equal(a.attrs["u"], b.attrs["u"], equal_nan=True)
            assert np.array_equal(a.sample_depth, b.sample_depth, equal_nan=True)
            d = a.sample_depth[a.sample_coverage]
            assert ((d >= 0.1) & (d <= 0.8)).all()
            assert np.isnan(a.sample_depth[~a.sample_coverage]).all()
            t = b.trace.samples
            assert len(t.tests) == 8 and len(t.boxes) == 8
            for i, j in zip(*np.nonzero(a.coverage)):
                assert np.array_equal(t.passed(i, j).all(axis=1), a.sample_coverage[i, j])
                e = t.edge_values(i, j)
                assert np.array_equal(e > 0, t.passed(i, j) & (e != 0))
