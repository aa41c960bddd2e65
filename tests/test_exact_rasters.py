"""Small rasters worked out by hand, written as literal 0/1 arrays.

Each expected array below was derived on paper from CONVENTIONS.md (pixel centres at
``(j + 0.5, i + 0.5)``, y down, top-left rule); the comments give the reasoning. Every case is
checked with both fill methods and all six vertex orders (both windings).
"""

import numpy as np
import pytest
from conftest import METHODS, PERMUTATIONS, reference_coverage

import teachraster as tr

# A square [0.25, 4.75]^2 (corners off the pixel grid, on the 1/256 grid) holds the 5 x 5
# pixel centres 0.5 .. 4.5. Its diagonal y = x runs through the 5 centres (k + 0.5, k + 0.5).
# Upper-right triangle (interior y < x): the diagonal is its *left* edge (it goes up when the
# triangle is walked with positive area) -> the 5 diagonal centres are its: 10 + 5 = 15.
# Lower-left triangle (interior y > x): the diagonal is its right edge -> excluded: 10.
SQUARE_UPPER = [[0.25, 0.25], [4.75, 0.25], [4.75, 4.75]]
SQUARE_LOWER = [[0.25, 0.25], [4.75, 4.75], [0.25, 4.75]]
SQUARE_UPPER_COVERAGE = [
    [1, 1, 1, 1, 1, 0],
    [0, 1, 1, 1, 1, 0],
    [0, 0, 1, 1, 1, 0],
    [0, 0, 0, 1, 1, 0],
    [0, 0, 0, 0, 1, 0],
    [0, 0, 0, 0, 0, 0],
]
SQUARE_LOWER_COVERAGE = [
    [0, 0, 0, 0, 0, 0],
    [1, 0, 0, 0, 0, 0],
    [1, 1, 0, 0, 0, 0],
    [1, 1, 1, 0, 0, 0],
    [1, 1, 1, 1, 0, 0],
    [0, 0, 0, 0, 0, 0],
]

# Square [0.5, 4.5]^2 with *every* edge through pixel centres: 4 x 4 centres 0.5 .. 3.5 plus
# the centres on its boundary. Split along the anti-diagonal x + y = 5 (centres with i + j = 4).
# Triangle A: top edge y = 0.5 (top: included), left edge x = 0.5 (left: included), diagonal on
# its lower right (excluded). Centres with i, j >= 0 and i + j < 4: 4 + 3 + 2 + 1 = 10.
EDGE_A = [[0.5, 0.5], [4.5, 0.5], [0.5, 4.5]]
EDGE_A_COVERAGE = [
    [1, 1, 1, 1, 0, 0],
    [1, 1, 1, 0, 0, 0],
    [1, 1, 0, 0, 0, 0],
    [1, 0, 0, 0, 0, 0],
    [0, 0, 0, 0, 0, 0],
    [0, 0, 0, 0, 0, 0],
]
# Triangle B: right edge x = 4.5 and bottom edge y = 4.5 excluded (no column 4, no row 4);
# the diagonal is its left edge: included. Centres with i, j <= 3 and i + j >= 4: 1 + 2 + 3 = 6.
EDGE_B = [[4.5, 0.5], [4.5, 4.5], [0.5, 4.5]]
EDGE_B_COVERAGE = [
    [0, 0, 0, 0, 0, 0],
    [0, 0, 0, 1, 0, 0],
    [0, 0, 1, 1, 0, 0],
    [0, 1, 1, 1, 0, 0],
    [0, 0, 0, 0, 0, 0],
    [0, 0, 0, 0, 0, 0],
]

# Direct3D-style right triangle on pixel corners: (0,0), (4,0), (0,4) in a 4 x 4 image. The
# hypotenuse x + y = 4 runs through the centres with i + j = 3; it is a right (bottom-right)
# edge, so those centres are excluded: 3 + 2 + 1 = 6 pixels.
CORNER_TRI = [[0, 0], [4, 0], [0, 4]]
CORNER_TRI_COVERAGE = [
    [1, 1, 1, 0],
    [1, 1, 0, 0],
    [1, 0, 0, 0],
    [0, 0, 0, 0],
]

# Apex exactly on the pixel centre (2.5, 0.5), base off-grid at y ~ 4.3. The apex lies on the
# left edge (top-left) and on the right edge (not top-left): a centre on a vertex is covered only
# if every edge through it allows it, so row 0 is empty. Row 1 (y = 1.5): span x in
# [1.89, 3.11] -> centre 2.5; rows 2 and 3: [1.29, 3.71] and [0.68, 4.32] -> 1.5 .. 3.5.
APEX_TRI = [[2.5, 0.5], [0.2, 4.3], [4.8, 4.3]]
APEX_COVERAGE = [
    [0, 0, 0, 0, 0, 0],
    [0, 0, 1, 0, 0, 0],
    [0, 1, 1, 1, 0, 0],
    [0, 1, 1, 1, 0, 0],
    [0, 0, 0, 0, 0, 0],
]
# A vertex on the centre (1.5, 1.5) where a top edge and a left edge meet: covered. The
# hypotenuse from (4.2, 1.5) to (1.5, 3.9) crosses row 1 at x = 4.2 and row 2 at x = 3.075.
CORNER_ON_CENTRE = [[1.5, 1.5], [4.2, 1.5], [1.5, 3.9]]
CORNER_ON_CENTRE_COVERAGE = [
    [0, 0, 0, 0, 0, 0],
    [0, 1, 1, 1, 0, 0],
    [0, 1, 1, 0, 0, 0],
    [0, 1, 0, 0, 0, 0],
    [0, 0, 0, 0, 0, 0],
]

CASES = {
    "square-upper-15": (SQUARE_UPPER, SQUARE_UPPER_COVERAGE),
    "square-lower-10": (SQUARE_LOWER, SQUARE_LOWER_COVERAGE),
    "edges-through-centres-A": (EDGE_A, EDGE_A_COVERAGE),
    "edges-through-centres-B": (EDGE_B, EDGE_B_COVERAGE),
    "d3d-corner-triangle": (CORNER_TRI, CORNER_TRI_COVERAGE),
    "apex-on-centre": (APEX_TRI, APEX_COVERAGE),
    "top-left-vertex-on-centre": (CORNER_ON_CENTRE, CORNER_ON_CENTRE_COVERAGE),
}


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("perm", PERMUTATIONS, ids=str)
@pytest.mark.parametrize("case", CASES)
def test_hand_worked_raster(case, perm, method):
    """The literal hand-derived array comes out, for both methods and every vertex order."""
    xy, expected = CASES[case]
    expected = np.array(expected, dtype=bool)
    h, w = expected.shape
    fill = tr.rasterize(tr.Triangle(np.array(xy, dtype=float)[list(perm)]), w, h, method=method)
    np.testing.assert_array_equal(fill.coverage.astype(int), expected.astype(int))


@pytest.mark.parametrize("case", CASES)
def test_hand_worked_raster_matches_reference(case):
    """The hand-derived arrays agree with the exact Fraction reference (checks the checker)."""
    xy, expected = CASES[case]
    expected = np.array(expected, dtype=bool)
    h, w = expected.shape
    np.testing.assert_array_equal(reference_coverage(xy, w, h), expected)


def test_hand_counts():
    """The pixel counts stated in the comments: 15 + 10, 10 + 6, 6, 7, 6."""
    counts = {k: int(np.sum(v[1])) for k, v in CASES.items()}
    assert counts == {
        "square-upper-15": 15,
        "square-lower-10": 10,
        "edges-through-centres-A": 10,
        "edges-through-centres-B": 6,
        "d3d-corner-triangle": 6,
        "apex-on-centre": 7,
        "top-left-vertex-on-centre": 6,
    }


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize(
    "pair", [(SQUARE_UPPER, SQUARE_LOWER), (EDGE_A, EDGE_B)], ids=["off-grid", "on-centres"]
)
def test_square_halves_are_disjoint_and_cover_the_square(pair, method):
    """Two triangles sharing a diagonal through pixel centres: disjoint, union = whole square."""
    first, second = (tr.rasterize(tr.Triangle(xy), 6, 6, method=method).coverage for xy in pair)
    assert not (first & second).any()
    union = np.zeros((6, 6), dtype=bool)
    lo, hi = (0, 5) if pair[0] is SQUARE_UPPER else (0, 4)
    union[lo:hi, lo:hi] = True
    np.testing.assert_array_equal(first | second, union)


@pytest.mark.parametrize("method", METHODS)
def test_horizontal_edge_through_centres_top_in_bottom_out(method):
    """A rectangle row band y in [1.5, 3.5]: centres on the top edge in, on the bottom edge out."""
    # Two triangles forming the rectangle [0.2, 5.8] x [1.5, 3.5]; their diagonal is off-centre.
    upper = tr.rasterize(tr.Triangle([[0.2, 1.5], [5.8, 1.5], [5.8, 3.5]]), 6, 5, method=method)
    lower = tr.rasterize(tr.Triangle([[0.2, 1.5], [5.8, 3.5], [0.2, 3.5]]), 6, 5, method=method)
    both = upper.coverage.astype(int) + lower.coverage.astype(int)
    expected = np.zeros((5, 6), dtype=int)
    expected[1:3] = 1  # rows 1 (y = 1.5, top edge) and 2; not row 3 (y = 3.5, bottom edge)
    np.testing.assert_array_equal(both, expected)


@pytest.mark.parametrize("method", METHODS)
def test_vertical_edge_through_centres_left_in_right_out(method):
    """A column band x in [1.5, 3.5]: centres on the left edge in, on the right edge out."""
    left = tr.rasterize(tr.Triangle([[1.5, 0.2], [3.5, 0.2], [1.5, 4.8]]), 5, 5, method=method)
    right = tr.rasterize(tr.Triangle([[3.5, 0.2], [3.5, 4.8], [1.5, 4.8]]), 5, 5, method=method)
    both = left.coverage.astype(int) + right.coverage.astype(int)
    expected = np.zeros((5, 5), dtype=int)
    expected[:, 1:3] = 1  # columns 1 (x = 1.5, left edge) and 2; not column 3 (right edge)
    np.testing.assert_array_equal(both, expected)


@pytest.mark.parametrize("method", METHODS)
def test_both_windings_give_the_same_coverage(method):
    """Reversing the vertex order (the other winding) changes nothing about coverage."""
    for xy, _ in CASES.values():
        xy = np.array(xy, dtype=float)
        cw = tr.rasterize(tr.Triangle(xy), 6, 6, method=method).coverage
        ccw = tr.rasterize(tr.Triangle(xy[::-1]), 6, 6, method=method).coverage
        assert cw.any()
        np.testing.assert_array_equal(cw, ccw)


@pytest.mark.parametrize("method", METHODS)
def test_culling_back_drops_clockwise_on_screen_front_drops_the_other(method):
    """cull="back" drops positive signed area (clockwise on screen); "front" the negative one."""
    cw = tr.Triangle(EDGE_A)  # (0.5,0.5) -> (4.5,0.5) -> (0.5,4.5): clockwise on screen
    ccw = tr.Triangle(EDGE_A[::-1])
    assert cw.signed_area == 8.0 and not cw.front_facing
    assert ccw.signed_area == -8.0 and ccw.front_facing
    full = np.array(EDGE_A_COVERAGE, dtype=bool)

    def cover(tri, cull):
        return tr.rasterize(tri, 6, 6, method=method, cull=cull).coverage

    np.testing.assert_array_equal(cover(cw, None), full)
    np.testing.assert_array_equal(cover(ccw, None), full)
    assert not cover(cw, "back").any()
    np.testing.assert_array_equal(cover(cw, "front"), full)
    assert not cover(ccw, "front").any()
    np.testing.assert_array_equal(cover(ccw, "back"), full)


def test_culled_triangle_has_nan_attributes_everywhere():
    """A culled triangle writes nothing: its attributes and depth are NaN everywhere."""
    tri = tr.Triangle(EDGE_A, z=[0.1, 0.2, 0.3], attrs={"u": [1.0, 2.0, 3.0]})
    fill = tr.rasterize(tri, 6, 6, cull="back")
    assert not fill.coverage.any()
    assert np.isnan(fill.attrs["u"]).all() and np.isnan(fill.depth).all()


def test_image_size_is_height_by_width():
    """Arrays are indexed [row, col]: shape (height, width), row = y, col = x."""
    # A thin triangle in the last column of a 7-wide, 3-high image. Its hypotenuse from
    # (6.1, 0.1) to (6.9, 1.9) crosses y = 0.5 at x = 6.28 (centre 6.5 inside) and y = 1.5 at
    # x = 6.72 (centre 6.5 outside).
    fill = tr.rasterize(tr.Triangle([[6.1, 0.1], [6.9, 0.1], [6.9, 1.9]]), 7, 3)
    expected = np.zeros((3, 7), dtype=int)
    expected[0, 6] = 1
    np.testing.assert_array_equal(fill.coverage.astype(int), expected)
