"""Span tables, half-planes and the exact Fraction reference cover exactly the same pixels."""

import warnings

import numpy as np
import pytest
from conftest import (
    KINDS,
    METHODS,
    PERMUTATIONS,
    any_triangle,
    cases,
    examples,
    explain,
    float_coords,
    random_triangles,
    raster,
    reference_coverage,
    subpixel_coords,
    tie_coords,
    triangles,
)
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr

W, H = 13, 11  # not square, so a swapped row/column shows up


@pytest.mark.parametrize("kind", KINDS)
def test_bulk_random_triangles_match_reference(kind):
    """1000 seeded random triangles per kind: span == half-plane == exact reference."""
    rng = np.random.default_rng(
        ["float", "centre", "subpixel", "tie", "outside", "huge"].index(kind)
    )
    for xy in random_triangles(rng, kind, cases(1000), W, H):
        want = reference_coverage(xy, W, H)
        for method in METHODS:
            got = raster(xy, W, H, method=method)
            assert np.array_equal(got, want), f"{method}: " + explain(xy, got, want)


@pytest.mark.parametrize("kind", ["float", "centre", "tie", "outside"])
def test_every_vertex_order_gives_the_same_coverage(kind):
    """All six vertex orders (three per winding) fill identical pixels, in both methods."""
    rng = np.random.default_rng(100 + KINDS.index(kind))
    for xy in random_triangles(rng, kind, 60, W, H):
        want = reference_coverage(xy, W, H)
        for perm in PERMUTATIONS:
            for method in METHODS:
                got = raster(xy[list(perm)], W, H, method=method)
                assert np.array_equal(got, want), f"{method} {perm}: " + explain(xy, got, want)


@pytest.mark.parametrize("bits", [0, 1, 4, 12, 16])
def test_other_subpixel_precisions_match_reference(bits):
    """With 0..16 sub-pixel bits both methods still follow the exact rule on that grid."""
    rng = np.random.default_rng(200 + bits)
    for kind in ("float", "tie", "outside"):
        for xy in random_triangles(rng, kind, 100, W, H):
            want = reference_coverage(xy, W, H, bits=bits)
            for method in METHODS:
                got = raster(xy, W, H, method=method, subpixel_bits=bits)
                assert np.array_equal(got, want), f"{method}: " + explain(xy, got, want)


def test_snapping_is_round_half_to_even():
    """0.5/256 px rounds to 0 and 1.5/256 to 2/256: coverage follows the even neighbour."""
    # A right triangle whose left edge sits at x = 0.5 +- half a sub-pixel step. Round half to
    # even puts x = 0.5 + 0.5/256 at 0.5 (128 is even): the centre column 0 is on the left edge
    # and covered. x = 0.5 + 1.5/256 rounds to 0.5 + 2/256: column 0 is outside.
    step = 1 / 256
    on = raster([[0.5 + step / 2, 0.1], [3.9, 0.1], [0.5 + step / 2, 3.9]], 4, 4)
    off = raster([[0.5 + 1.5 * step, 0.1], [3.9, 0.1], [0.5 + 1.5 * step, 3.9]], 4, 4)
    assert on[:, 0].any()
    assert not off[:, 0].any()
    np.testing.assert_array_equal(
        tr.snap([[0.5 + step / 2, 0.5 + 1.5 * step]]), [[0.5, 0.5 + 2 * step]]
    )


def test_many_ties_on_small_grid_exhaustive_sample():
    """Triangles with vertices on a 0.5 px lattice (edges through centres and corners)."""
    rng = np.random.default_rng(7)
    pts = rng.integers(0, 13, size=(800, 3, 2)) / 2.0
    for xy in pts:
        want = reference_coverage(xy, 6, 6)
        for method in METHODS:
            got = raster(xy, 6, 6, method=method)
            assert np.array_equal(got, want), f"{method}: " + explain(xy, got, want)


def test_triangle_larger_than_image_covers_it_all():
    """A triangle enclosing the image covers every pixel, in both methods."""
    xy = [[-50.3, -40.1], [200.7, -30.2], [-20.9, 180.4]]
    for method in METHODS:
        assert raster(xy, W, H, method=method).all()


def test_triangle_outside_image_covers_nothing():
    """A triangle entirely outside the image (any side) covers nothing and does not fail."""
    for dx, dy in [(-20, 0), (20, 0), (0, -20), (0, 20)]:
        xy = np.array([[1.2, 1.3], [8.7, 2.1], [4.4, 9.9]]) + [dx, dy]
        for method in METHODS:
            assert not raster(xy, W, H, method=method).any()


@settings(max_examples=examples(300), deadline=None)
@given(any_triangle)
def test_hypothesis_span_equals_halfplane_equals_reference(xy):
    """Hypothesis (shrinks to a minimal counter-example): span == half-plane == reference."""
    want = reference_coverage(xy, W, H)
    for method in METHODS:
        got = raster(xy, W, H, method=method)
        assert np.array_equal(got, want), f"{method}: " + explain(xy, got, want)


@settings(max_examples=examples(150), deadline=None)
@given(triangles(tie_coords(5)), st.sampled_from(PERMUTATIONS))
def test_hypothesis_ties_any_vertex_order(xy, perm):
    """On the half-pixel lattice every vertex order fills the reference pixels."""
    want = reference_coverage(xy, 5, 5)
    for method in METHODS:
        got = raster(xy[list(perm)], 5, 5, method=method)
        assert np.array_equal(got, want), f"{method} {perm}: " + explain(xy, got, want)


@settings(max_examples=examples(100), deadline=None)
@given(triangles(subpixel_coords(-40, 50)))
def test_hypothesis_partly_outside_subpixel_grid(xy):
    """Vertices on the 1/256 grid far beyond the image: clipping to the image is exact."""
    want = reference_coverage(xy, W, H)
    for method in METHODS:
        got = raster(xy, W, H, method=method)
        assert np.array_equal(got, want), f"{method}: " + explain(xy, got, want)


@settings(max_examples=examples(100), deadline=None)
@given(triangles(float_coords(-5.0, 20.0)))
def test_hypothesis_unsnapped_methods_agree(xy):
    """With subpixel_bits=None (raw floats) the two methods still agree with each other."""
    span = raster(xy, W, H, method="span", subpixel_bits=None)
    half = raster(xy, W, H, method="halfplane", subpixel_bits=None)
    assert np.array_equal(span, half), explain(xy, span, half)


def test_unsnapped_methods_agree_even_for_astronomically_far_vertices():
    """With raw floats the span ends are found by bisection on E itself (the same operations
    the half-plane test evaluates), so the methods agree, without warnings, at any scale."""
    rng = np.random.default_rng(2026)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for _ in range(600):
            xy = rng.uniform(-1, 1, (3, 2)) * 10.0 ** rng.integers(0, 150)
            xy[rng.integers(0, 3)] = rng.uniform(0, 8, 2)  # keep one vertex near the image
            tri = tr.Triangle(xy)
            half = tr.rasterize(tri, 8, 8, subpixel_bits=None).coverage
            span = tr.rasterize(tri, 8, 8, subpixel_bits=None, method="span").coverage
            assert np.array_equal(half, span), xy.tolist()
