"""Degenerate and extreme triangles: no exception, no warning, no NaN, the right pixel count.

Every test here runs with warnings turned into errors and numpy floating-point errors raised
(divide, overflow and invalid operations; ``np.errstate``), so a silent divide-by-zero or
overflow fails the test.
"""

import warnings

import numpy as np
import pytest
from conftest import METHODS, MODES, examples, explain, reference_coverage
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr


@pytest.fixture(autouse=True)
def strict_numerics():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # Underflow is IEEE's normal gradual loss (numpy ignores it by default); the rest raise.
        with np.errstate(divide="raise", over="raise", invalid="raise", under="ignore"):
            yield


def fill_all(xy, width=10, height=10, bits=8, w=(1.0, 2.0, 4.0)):
    """Rasterise with every method, mode and trace setting; check sanity; return coverages."""
    tri = tr.Triangle(xy, w=w, z=[0.0, 0.5, 1.0], attrs={"u": [1.0, 2.0, 3.0], "rgb": np.eye(3)})
    out = []
    for method in METHODS:
        for mode in MODES:
            for trace in (False, True):
                fill = tr.rasterize(
                    tri, width, height, method=method, interpolation=mode, trace=trace,
                    subpixel_bits=bits,
                )  # fmt: skip
                cov = fill.coverage
                for arr in (fill.attrs["u"], fill.attrs["rgb"], fill.depth):
                    assert np.isfinite(arr[cov]).all(), "NaN/inf inside coverage"
                    assert np.isnan(arr[~cov]).all(), "a value outside coverage"
                out.append(cov)
    for cov in out[1:]:
        np.testing.assert_array_equal(cov, out[0])
    return out[0]


ZERO_AREA = {
    "collinear": [[0, 0], [4, 4], [8, 8]],
    "collinear-through-centres": [[0.5, 0.5], [2.5, 2.5], [5.5, 5.5]],
    "collinear-middle-vertex-last": [[1.5, 0.5], [7.5, 6.5], [4.5, 3.5]],
    "two-coincident": [[1.2, 3.4], [1.2, 3.4], [7.9, 8.1]],
    "two-coincident-on-centre": [[2.5, 2.5], [6.5, 2.5], [2.5, 2.5]],
    "all-equal": [[3.3, 3.3]] * 3,
    "all-equal-on-centre": [[4.5, 4.5]] * 3,
    "flat-horizontal-on-centre-row": [[0.5, 2.5], [6.5, 2.5], [3.5, 2.5]],
    "flat-horizontal": [[0.1, 2.7], [9.9, 2.7], [4.4, 2.7]],
    "flat-vertical-on-centre-column": [[3.5, 0.5], [3.5, 9.5], [3.5, 4.5]],
    "flat-vertical": [[3.1, 0.1], [3.1, 9.9], [3.1, 5.0]],
    "collinear-after-snapping": [[0, 0], [4, 4 + 1e-4], [8, 8]],
    "collinear-huge": [[-1e5, -1e5], [0, 0], [1e5, 1e5]],
}


@pytest.mark.parametrize("name", ZERO_AREA)
def test_zero_area_covers_nothing(name):
    """A zero-area triangle (after snapping) covers no pixel, in every mode, with no warning."""
    xy = np.array(ZERO_AREA[name], dtype=float)
    for perm in ([0, 1, 2], [2, 1, 0], [1, 2, 0]):
        assert fill_all(xy[perm]).sum() == 0


@pytest.mark.parametrize("name", ZERO_AREA)
def test_zero_area_unsnapped_does_not_crash(name):
    """With subpixel_bits=None (raw floats) degenerate input is handled without error."""
    cov = fill_all(np.array(ZERO_AREA[name], dtype=float), bits=None)
    if name != "collinear-after-snapping":  # only this one has a (tiny) nonzero float area
        assert cov.sum() == 0


@pytest.mark.parametrize("name", ZERO_AREA)
def test_zero_area_trace_is_sane(name):
    """Tracing a zero-area triangle works; its winding step says it is degenerate."""
    for method in METHODS:
        fill = tr.rasterize(tr.Triangle(ZERO_AREA[name]), 10, 10, method=method, trace=True)
        t = fill.trace
        assert t.signed_area == 0.0
        assert "zero area" in t.step(1).caption
        assert not fill.coverage.any() and not t.coverage_at(len(t) - 1).any()
        assert (t.filled_at == -1).all()
        assert all(s.caption for s in t)


def test_subpixel_triangle_around_a_centre_covers_one_pixel():
    """A triangle 0.03 px wide that contains the centre (2.5, 2.5) covers exactly that pixel."""
    # snapped: x, y in {637, 645} / 256 = {2.488, 2.520}; hypotenuse x + y = 5.008 > 5.
    cov = fill_all([[2.49, 2.49], [2.52, 2.49], [2.49, 2.52]])
    expected = np.zeros((10, 10), dtype=bool)
    expected[2, 2] = True
    np.testing.assert_array_equal(cov, expected)


def test_subpixel_triangle_missing_all_centres_covers_nothing():
    """A tiny triangle between pixel centres covers nothing (and interpolates nothing)."""
    assert fill_all([[2.6, 2.6], [2.9, 2.6], [2.6, 2.9]]).sum() == 0


def test_subpixel_triangle_smaller_than_the_snapping_grid_vanishes():
    """All three vertices snap to the same 1/256 point: nothing, and no division by zero."""
    assert fill_all([[2.5001, 2.5001], [2.5003, 2.5], [2.5, 2.5003]]).sum() == 0


@pytest.mark.parametrize(
    "xy",
    [
        [[0.3, 0.5], [60.7, 1.5], [60.7, 1.52]],
        [[0.5, 0.5], [63.5, 9.5], [63.4, 9.5]],  # thin sliver starting on a pixel centre
        [[0.0, 0.0], [64.0, 10.0], [64.0, 10.0 + 1 / 256]],  # one sub-pixel step wide
        [[5.1, -40.0], [5.2, 50.0], [5.15, 50.0]],  # vertical sliver through the image
    ],
)
def test_slivers_match_the_exact_reference(xy):
    """Long thin triangles: exactly the reference pixels, finite attributes, no warnings."""
    cov = fill_all(xy, 64, 12)
    want = reference_coverage(xy, 64, 12)
    assert np.array_equal(cov, want), explain(xy, cov, want)


def test_sliver_along_pixel_centres_takes_the_centres_of_its_left_edge():
    """A sliver whose long left edge runs through a column of pixel centres covers that column.

    Its top vertex (3.5, 0.5) is a pixel centre on the left edge and on the long right edge
    (not top-left), so row 0 is excluded; rows 1..9 keep column 3.
    """
    xy = [[3.5, 0.5], [3.5 + 1 / 256, 9.9], [3.5, 9.9]]
    cov = fill_all(xy)
    expected = np.zeros((10, 10), dtype=bool)
    expected[1:, 3] = True
    np.testing.assert_array_equal(cov, expected)


@settings(max_examples=examples(60), deadline=None)
@given(
    st.lists(st.tuples(st.floats(1, 8), st.floats(1, 8)), min_size=3, max_size=3),
    st.integers(-6, 6),
    st.integers(-6, 6),
)
def test_translation_by_whole_pixels_shifts_coverage(xy, dx, dy):
    """Moving a triangle by whole pixels moves its coverage by the same number of pixels."""
    xy = np.array(xy)
    size = 24
    base = tr.rasterize(tr.Triangle(xy + 8), size, size).coverage
    moved = tr.rasterize(tr.Triangle(xy + 8 + [dx, dy]), size, size).coverage
    np.testing.assert_array_equal(np.roll(base, (dy, dx), axis=(0, 1)), moved)


BIG_DIAGONAL_UPPER = [[-1e5 + 0.5, -1e5 + 0.5], [1e5 + 0.5, 1e5 + 0.5], [1e5 + 0.5, -1e5 + 0.5]]
BIG_DIAGONAL_LOWER = [[-1e5 + 0.5, -1e5 + 0.5], [1e5 + 0.5, 1e5 + 0.5], [-1e5 + 0.5, 1e5 + 0.5]]


@pytest.mark.parametrize("method", METHODS)
def test_far_vertices_edge_through_centres(method):
    """Vertices at ~1e5 px, shared edge y = x through the centres (k + .5, k + .5).

    The upper-right triangle has the diagonal as its left edge, so it takes the diagonal
    centres (j >= i); the lower-left one takes j < i. Together: every pixel exactly once.
    """
    upper = tr.rasterize(tr.Triangle(BIG_DIAGONAL_UPPER), 9, 9, method=method).coverage
    lower = tr.rasterize(tr.Triangle(BIG_DIAGONAL_LOWER), 9, 9, method=method).coverage
    i, j = np.indices((9, 9))
    np.testing.assert_array_equal(upper, j >= i)
    np.testing.assert_array_equal(lower, j < i)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("shift", [1, 3, 5])
def test_far_triangle_moved_by_whole_pixels_moves_coverage(method, shift):
    """A huge triangle (vertices ~1e5) moved right by whole pixels: coverage moves with it."""
    xy = np.array([[-1e5 + 0.3, -1e5 + 0.7], [1e5 + 0.9, 1e5 + 0.2], [1e5, -3e5]])
    size = 12
    base = tr.rasterize(tr.Triangle(xy), size, size, method=method).coverage
    assert 0 < base.sum() < size * size  # an edge crosses the image
    np.testing.assert_array_equal(base, reference_coverage(xy, size, size))
    moved = tr.rasterize(tr.Triangle(xy + [shift, 0]), size, size, method=method).coverage
    np.testing.assert_array_equal(moved[:, shift:], base[:, :-shift])


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("offset", [1, 3, -7, 50_000, -50_000])
def test_far_triangle_slid_along_its_own_edge_is_unchanged(method, offset):
    """Sliding the 1e5-px diagonal triangle by (k, k) whole pixels along its edge y = x keeps
    exactly the same pixels (the diagonal centres stay on its left edge: j >= i)."""
    moved = np.array(BIG_DIAGONAL_UPPER) + offset
    cov = tr.rasterize(tr.Triangle(moved), 12, 12, method=method).coverage
    i, j = np.indices((12, 12))
    np.testing.assert_array_equal(cov, j >= i)


@pytest.mark.parametrize(
    "xy",
    [
        [[-1e5, -1e5], [1e5, 0.3], [0.7, 1e5]],
        [[-1e5, 3.2], [1e5, 6.7], [-1e5, 3.9]],  # a long sliver crossing the image
        [[2.0e6, 0.25], [-2.0e6, 7.75], [3.0, -2.0e6]],  # close to the int64 limit (2**21 px)
        [[-2.09e6, -2.09e6], [2.09e6, 5.5], [5.5, 2.09e6]],
        [[1e5 + 0.5, 3.5], [-1e5 + 0.5, 3.5], [0.5, 1e5]],  # top edge on a row of centres
    ],
)
def test_huge_coordinates_partially_covering_the_image(xy):
    """Coordinates ~1e5 .. 2e6 px: exactly the reference pixels, finite attributes."""
    cov = fill_all(xy, 12, 12)
    want = reference_coverage(xy, 12, 12)
    assert np.array_equal(cov, want), explain(xy, cov, want)


def test_huge_triangle_covers_the_whole_image():
    """A triangle much bigger than the image covers every pixel; attributes stay finite."""
    cov = fill_all([[-1e5, -1e5], [3e5, -1e5], [-1e5, 3e5]], 32, 24)
    assert cov.all()


def test_coordinates_beyond_the_exact_range_raise_valueerror_naming_xy():
    """1e9 px cannot be snapped to 1/256 in int64 exactly: ValueError mentioning xy."""
    tri = tr.Triangle([[1e9, 0], [0, 1e9], [0, 0]])
    for method in METHODS:
        with pytest.raises(ValueError, match="xy"):
            tr.rasterize(tri, 8, 8, method=method)
    with pytest.raises(ValueError, match="xy"):
        tr.rasterize(tr.Triangle([[3e6, 0], [0, 1], [0, 0]]), 8, 8)  # just past 2**21 px
    with pytest.raises(ValueError, match="xy"):
        tr.rasterize(tri, 8, 8, subpixel_bits=0)


def test_huge_coordinates_unsnapped_do_not_crash():
    """With subpixel_bits=None there is no int64 limit: 1e9 px rasterises without error."""
    cov = fill_all([[-1e9, -1e9], [1e9, -1e9], [0.0, 1e9]], 8, 8, bits=None)
    assert cov.all()


@settings(max_examples=examples(100), deadline=None)
@given(
    st.lists(st.tuples(st.floats(-1e6, 1e6), st.floats(-1e6, 1e6)), min_size=3, max_size=3).map(
        np.array
    )
)
def test_hypothesis_large_random_triangles_match_reference(xy):
    """Random triangles with coordinates up to 1e6 px agree with the exact reference."""
    want = reference_coverage(xy, 8, 8)
    for method in METHODS:
        got = tr.rasterize(tr.Triangle(xy), 8, 8, method=method).coverage
        assert np.array_equal(got, want), explain(xy, got, want)


@settings(max_examples=examples(80), deadline=None)
@given(
    st.lists(st.tuples(st.floats(-20, 30), st.floats(-20, 30)), min_size=3, max_size=3).map(
        np.array
    ),
    st.one_of(st.none(), st.integers(0, 16)),
)
def test_hypothesis_any_precision_no_warnings_no_nan(xy, bits):
    """Any triangle at any precision (including raw floats): no warning, finite attributes."""
    fill_all(xy, 10, 10, bits=bits)
