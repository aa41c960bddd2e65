"""Watertightness: meshes sharing edges cover every pixel centre inside exactly once.

Fans around a shared vertex and grids of triangles are rasterised triangle by triangle and the
coverages summed. Inside the mesh the sum must be exactly 1 (no cracks, no double hits); it must
never exceed 1 anywhere. Vertex orders are shuffled per triangle, so both windings occur.
"""

from fractions import Fraction

import numpy as np
import pytest
from conftest import METHODS, cases, edge_exact, examples, snapped_vertices
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr


def accumulate(tris, width, height, method, rng=None, bits=8):
    """Sum of the coverages of ``tris`` (shuffling each triangle's vertex order with ``rng``)."""
    counts = np.zeros((height, width), dtype=np.int64)
    for xy in tris:
        xy = np.asarray(xy, dtype=float)
        if rng is not None:
            xy = xy[rng.permutation(3)]
        fill = tr.rasterize(tr.Triangle(xy), width, height, method=method, subpixel_bits=bits)
        counts += fill.coverage
    return counts


def fan(centre, rim, closed=True):
    """Triangles (centre, rim[k], rim[k + 1]) around a shared vertex."""
    n = len(rim) if closed else len(rim) - 1
    return [np.array([centre, rim[k], rim[(k + 1) % len(rim)]], dtype=float) for k in range(n)]


def convex_hull(points):
    """Exact convex hull (monotone chain) of Fraction points, counter-clockwise in y-up terms."""
    pts = sorted(set(points))

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and edge_exact(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]

    return half(pts) + half(reversed(pts))


def strictly_inside_hull(points, width, height, bits=8):
    """(height, width) bool: pixel centres strictly inside the convex hull of snapped ``points``."""
    snapped = snapped_vertices(points, bits)
    hull = convex_hull(snapped)
    inside = np.zeros((height, width), dtype=bool)
    half = Fraction(1, 2)
    for i in range(height):
        for j in range(width):
            p = (j + half, i + half)
            inside[i, j] = all(
                edge_exact(hull[k], hull[(k + 1) % len(hull)], p) > 0 for k in range(len(hull))
            )
    return inside


def assert_watertight(counts, interior):
    assert counts.max() <= 1, f"pixels covered twice: {np.argwhere(counts > 1)[:8].tolist()}"
    holes = np.argwhere(interior & (counts != 1))
    assert holes.size == 0, f"interior pixels not covered: {holes[:8].tolist()}"


# Integer directions in angular order: every spoke from a pixel centre passes through centres.
LATTICE_DIRECTIONS = [
    (1, 0), (2, 1), (1, 1), (1, 2), (0, 1), (-1, 2), (-1, 1), (-2, 1),
    (-1, 0), (-2, -1), (-1, -1), (-1, -2), (0, -1), (1, -2), (1, -1), (2, -1),
]  # fmt: skip


@pytest.mark.parametrize("method", METHODS)
def test_fan_on_pixel_centre_with_spokes_through_centres_covers_image_once(method):
    """16 spokes from the centre (8.5, 8.5) along lattice directions; the rim is far outside."""
    c = np.array([8.5, 8.5])
    rim = [c + 30 * np.array(d) for d in LATTICE_DIRECTIONS]
    counts = accumulate(fan(c, rim), 17, 17, method, np.random.default_rng(1))
    np.testing.assert_array_equal(counts, np.ones((17, 17), dtype=int))


def square_rim(c, half):
    """Rim on the square of half-size ``2 * half`` around c, one vertex per lattice direction.

    Each rim vertex is c + m * d for an integer m, so every spoke passes through pixel centres
    (when c is a pixel centre) and the fan's union is exactly the square.
    """
    return [
        c + (2 * half // max(abs(dx), abs(dy))) * np.array([dx, dy])
        for dx, dy in LATTICE_DIRECTIONS
    ]


@pytest.mark.parametrize("method", METHODS)
def test_small_fan_on_centre_inside_image(method):
    """A fan whose rim vertices are also pixel centres, fully inside the image."""
    c = np.array([7.5, 6.5])
    rim = square_rim(c, 2)
    counts = accumulate(fan(c, rim), 16, 14, method, np.random.default_rng(2))
    assert_watertight(counts, strictly_inside_hull(rim, 16, 14))
    assert counts[6, 7] == 1  # the shared vertex's own pixel belongs to exactly one triangle
    outside = np.ones((14, 16), dtype=bool)
    outside[6 - 4 : 6 + 5, 7 - 4 : 7 + 5] = False  # the closed square |x - 7.5|, |y - 6.5| <= 4
    assert counts[outside].sum() == 0
    assert counts.sum() == 64  # 8 x 8 centres: each square edge through centres, top-left rule


def random_convex_fan(rng, kind, width, height):
    """A closed fan: shared vertex inside a convex rim of points snapped to the sub-pixel grid."""
    n = int(rng.integers(3, 12))
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    angles += np.linspace(0, 0.3, n)  # keep a minimum gap
    angles = angles[angles < 2 * np.pi]
    radius = rng.uniform(2, 12)
    centre = rng.uniform([2, 2], [width - 2, height - 2])
    rim = centre + radius * np.stack([np.cos(angles), np.sin(angles)], axis=1)
    rim = np.round(rim * 256) / 256
    if kind == "centre":  # shared vertex exactly on a pixel centre
        shared = np.floor(centre) + 0.5
    elif kind == "subpixel":
        shared = np.round((centre + rng.uniform(-1, 1, 2)) * 256) / 256
    else:
        shared = centre + rng.uniform(-1, 1, 2)
    return shared, rim


def fan_is_valid(shared, rim) -> bool:
    """Every fan triangle has the same (nonzero) orientation on the snapped grid."""
    signs = set()
    for tri in fan(shared, rim):
        a, b, c = snapped_vertices(tri)
        signs.add(np.sign(edge_exact(a, b, c)))
    return len(rim) >= 3 and signs in ({1}, {-1})


@pytest.mark.parametrize("kind", ["centre", "subpixel", "float"])
@pytest.mark.parametrize("method", METHODS)
def test_random_convex_fans(kind, method):
    """Seeded random convex fans: interior pixels exactly once, nothing twice, nothing outside."""
    rng = np.random.default_rng(["centre", "subpixel", "float"].index(kind) + 10)
    checked = 0
    while checked < cases(25):
        shared, rim = random_convex_fan(rng, kind, 20, 18)
        if not fan_is_valid(shared, rim):
            continue
        counts = accumulate(fan(shared, rim), 20, 18, method, rng)
        assert_watertight(counts, strictly_inside_hull(rim, 20, 18))
        checked += 1


def grid_triangles(xs, ys, alternate=True):
    """Split each cell of the vertex grid (xs[j], ys[i]) into two triangles along a diagonal."""
    tris = []
    for i in range(xs.shape[0] - 1):
        for j in range(xs.shape[1] - 1):
            p00 = (xs[i, j], ys[i, j])
            p01 = (xs[i, j + 1], ys[i, j + 1])
            p10 = (xs[i + 1, j], ys[i + 1, j])
            p11 = (xs[i + 1, j + 1], ys[i + 1, j + 1])
            if alternate and (i + j) % 2:
                tris += [[p00, p01, p10], [p01, p11, p10]]  # diagonal p01-p10
            else:
                tris += [[p00, p01, p11], [p00, p11, p10]]  # diagonal p00-p11
    return tris


def regular_grid(x0, y0, step, width, height):
    nx = int(np.ceil((width - x0 + 2 * step) / step)) + 1
    ny = int(np.ceil((height - y0 + 2 * step) / step)) + 1
    gx = x0 - step + step * np.arange(nx)
    gy = y0 - step + step * np.arange(ny)
    return np.meshgrid(gx, gy)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize(
    ("x0", "y0", "step"),
    [(0.0, 0.0, 2.0), (0.5, 0.5, 3.0), (0.25, 0.75, 2.5), (0.1, 0.3, 1.7), (0.5, 0.0, 1.0)],
    ids=["corners", "centres", "quarter", "float", "unit"],
)
@pytest.mark.parametrize("alternate", [False, True], ids=["same-diagonal", "alternating"])
def test_regular_grid_covers_every_pixel_once(x0, y0, step, alternate, method):
    """A regular grid split by diagonals (many through pixel centres) covers each pixel once."""
    xs, ys = regular_grid(x0, y0, step, 20, 16)
    tris = grid_triangles(xs, ys, alternate)
    counts = accumulate(tris, 20, 16, method, np.random.default_rng(3))
    np.testing.assert_array_equal(counts, np.ones((16, 20), dtype=int))


@pytest.mark.parametrize("bits", [0, 2, 4, 16])
def test_grid_watertight_at_other_precisions(bits):
    """Watertightness holds on any sub-pixel grid, not just 1/256."""
    xs, ys = regular_grid(0.3, 0.1, 2.2, 15, 12)
    for method in METHODS:
        counts = accumulate(grid_triangles(xs, ys), 15, 12, method, np.random.default_rng(4), bits)
        np.testing.assert_array_equal(counts, np.ones((12, 15), dtype=int))


def jittered_grid(rng, step, width, height, grid):
    """Regular grid with each vertex moved by up to step/4 (keeps every cell convex)."""
    xs, ys = regular_grid(0.0, 0.0, step, width, height)
    jitter = rng.uniform(-step / 4, step / 4, size=(2, *xs.shape))
    xs, ys = xs + jitter[0], ys + jitter[1]
    if grid == "subpixel":
        return np.round(xs * 256) / 256, np.round(ys * 256) / 256
    if grid == "centre":
        return np.floor(xs) + 0.5, np.floor(ys) + 0.5
    return xs, ys


def mesh_is_valid(tris) -> bool:
    signs = {np.sign(edge_exact(*snapped_vertices(t))) for t in tris}
    return signs in ({1}, {-1})


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("grid", ["subpixel", "centre", "float"])
def test_jittered_grid_covers_every_pixel_once(grid, method):
    """Jittered vertex grids (on the 1/256 grid, on pixel centres, raw floats): exactly once."""
    rng = np.random.default_rng(["subpixel", "centre", "float"].index(grid) + 20)
    checked = 0
    while checked < 4:
        xs, ys = jittered_grid(rng, 4.0 if grid == "centre" else 3.0, 18, 15, grid)
        tris = grid_triangles(xs, ys, alternate=bool(checked % 2))
        if not mesh_is_valid(tris):
            continue
        counts = accumulate(tris, 18, 15, method, rng)
        np.testing.assert_array_equal(counts, np.ones((15, 18), dtype=int))
        checked += 1


@settings(max_examples=examples(25), deadline=None)
@given(st.integers(0, 2**32 - 1), st.sampled_from(["subpixel", "centre"]))
def test_hypothesis_jittered_grid_mixing_methods(seed, grid):
    """A jittered mesh filled with span and half-plane alternately is still watertight."""
    rng = np.random.default_rng(seed)
    xs, ys = jittered_grid(rng, 4.0, 12, 10, grid)
    tris = grid_triangles(xs, ys)
    if not mesh_is_valid(tris):
        return
    counts = np.zeros((10, 12), dtype=int)
    for k, xy in enumerate(tris):
        xy = np.asarray(xy)[rng.permutation(3)]
        counts += tr.rasterize(tr.Triangle(xy), 12, 10, method=METHODS[k % 2]).coverage
    np.testing.assert_array_equal(counts, np.ones((10, 12), dtype=int))


@settings(max_examples=examples(40), deadline=None)
@given(st.tuples(st.integers(-2, 18), st.integers(-2, 16)), st.integers(1, 4))
def test_hypothesis_lattice_fan_shared_vertex_on_any_centre(cell, half):
    """The lattice fan around any pixel centre (spokes through centres) is watertight."""
    c = np.array(cell, dtype=float) + 0.5
    rim = square_rim(c, half)
    for method in METHODS:
        counts = accumulate(fan(c, rim), 17, 15, method)
        assert_watertight(counts, strictly_inside_hull(rim, 17, 15))
