"""Hard cases of multisampling: watertight per sample, slivers between centres, samples on edges.

The top-left rule must hold at every sample as it does at centres: a mesh covers each sample
exactly once, whatever the triangulation, and a sample exactly on a shared edge belongs to
exactly one of the two triangles.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from conftest import METHODS, PERMUTATIONS

import teachraster as tr
from teachraster.pipeline.viewport import to_window

PATTERNS = {
    "standard4": tr.sample_pattern(4),
    "standard16": tr.sample_pattern(16),
    "grid9": tr.sample_pattern(9, "grid"),
    "random8": tr.sample_pattern(8, "random", seed=2),
}


def coverage_count(tris, width, height, samples, method="halfplane"):
    """Per-sample count of triangles covering each sample, (H, W, S)."""
    total = 0
    for xy in tris:
        total = total + tr.rasterize(tr.Triangle(xy), width, height, samples=samples,
                                     method=method).sample_coverage.astype(int)  # fmt: skip
    return total


def convex_polygon(rng, centre, n, radius, snap_to):
    """A convex polygon (counter-clockwise in y-down numbers) on the 1/snap_to grid: the
    convex hull (monotone chain, collinear points dropped) of random points."""
    pts = centre + rng.uniform(-radius, radius, (n, 2))
    pts = np.unique(np.round(pts * snap_to) / snap_to, axis=0)
    pts = sorted(map(tuple, pts))

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    hull = []
    for part in (pts, pts[::-1]):
        chain = []
        for p in part:
            while len(chain) >= 2 and cross(chain[-2], chain[-1], p) <= 0:
                chain.pop()
            chain.append(p)
        hull += chain[:-1]
    return np.array(hull)


@pytest.mark.parametrize("pattern", list(PATTERNS))
@pytest.mark.parametrize("snap_to", [2, 256])  # half-integers (ties everywhere), 1/256 px
def test_fans_watertight_and_triangulation_free(rng, pattern, snap_to):
    """Fan from an inner point vs fan from a corner of the same convex polygon: every sample
    covered at most once by either, and the same samples covered by both."""
    samples = PATTERNS[pattern]
    for _ in range(6):
        poly = convex_polygon(rng, np.array([8.0, 7.0]), int(rng.integers(6, 14)), 7.5, snap_to)
        assert len(poly) >= 3
        centre = poly.mean(axis=0)  # strictly inside a convex polygon (any float will do)
        n = len(poly)
        spokes = [np.array([centre, poly[k], poly[(k + 1) % n]]) for k in range(n)]
        corner = [np.array([poly[0], poly[k], poly[k + 1]]) for k in range(1, n - 1)]
        method = METHODS[len(poly) % 2]
        a = coverage_count(spokes, 16, 14, samples, method)
        b = coverage_count(corner, 16, 14, samples, method)
        assert a.max() <= 1 and b.max() <= 1
        np.testing.assert_array_equal(a, b)
        assert a.sum() > 0


@pytest.mark.parametrize("pattern", list(PATTERNS))
def test_jittered_grid_covers_its_rectangle_once(rng, pattern):
    samples = PATTERNS[pattern]
    nx, ny, cell = 4, 3, 4.0
    x = np.arange(nx + 1) * cell + 0.5
    y = np.arange(ny + 1) * cell + 0.25
    gx, gy = np.meshgrid(x, y)
    inner = (slice(1, -1), slice(1, -1))
    gx[inner] += np.round(rng.uniform(-1.5, 1.5, gx[inner].shape) * 256) / 256
    gy[inner] += np.round(rng.uniform(-1.5, 1.5, gy[inner].shape) * 256) / 256
    tris = []
    for i, j in itertools.product(range(ny), range(nx)):
        q = np.array([[gx[i, j], gy[i, j]], [gx[i, j + 1], gy[i, j + 1]],
                      [gx[i + 1, j + 1], gy[i + 1, j + 1]], [gx[i + 1, j], gy[i + 1, j]]])  # fmt: skip
        tris += [q[[0, 1, 2]], q[[0, 2, 3]]] if (i + j) % 2 else [q[[0, 1, 3]], q[[1, 2, 3]]]
    W, H = 18, 14
    count = coverage_count(tris, W, H, samples)
    rect = [[x[0], y[0]], [x[-1], y[0]], [x[-1], y[-1]], [x[0], y[-1]]]
    rect = np.array(rect)
    want = coverage_count([rect[[0, 1, 2]], rect[[0, 2, 3]]], W, H, samples)
    np.testing.assert_array_equal(count, want)
    assert want.max() == 1
    # the same mesh through tr.render: every sample of the rectangle shows one triangle
    clip = np.concatenate([(np.array(tris) / [W, H] * 2 - 1) * [1, -1],
                           np.zeros((len(tris), 3, 1)), np.ones((len(tris), 3, 1))], -1)  # fmt: skip
    np.testing.assert_allclose(to_window(clip, W, H)[..., :2], np.array(tris), atol=1e-12)
    frame = tr.render(clip, W, H, samples=samples, depth_test=False)
    np.testing.assert_array_equal(frame.sample_triangle_id >= 0, want == 1)


def test_sliver_between_centres_appears_only_with_samples():
    """A thin strip from y = 0.1 to 0.2 covers no pixel centre (y = 0.5) but the 4-sample
    pattern's first sample (y = 0.125) in every column."""
    tri = tr.Triangle([[-1, 0.1], [20, 0.1], [-1, 0.2]], attrs={"u": [0.0, 1.0, 0.0]})
    assert not tr.rasterize(tri, 16, 2).coverage.any()  # it vanishes at one sample
    fill = tr.rasterize(tri, 16, 2, samples=4)
    covered = fill.sample_coverage
    assert covered[0, :, 0].sum() > 10 and not covered[..., 1:].any() and not covered[1].any()
    np.testing.assert_array_equal(fill.coverage_fraction[0], covered[0, :, 0] / 4)
    assert np.isfinite(fill.attrs["u"][fill.coverage]).all()
    centroid = tr.rasterize(tri, 16, 2, samples=4, centroid=True)
    u = centroid.attrs["u"][centroid.coverage]
    assert ((u >= 0) & (u <= 1)).all()


@pytest.mark.parametrize("method", METHODS)
def test_samples_exactly_on_edges(method):
    """Edges through sample 0 of the 4-sample pattern (0.375, 0.125) of pixel (0, 0)."""
    s = 4

    def at(xy):
        return tr.rasterize(tr.Triangle(xy), 4, 4, samples=s, method=method).sample_coverage[
            0, 0, 0
        ]

    # horizontal edge y = 0.125: a top edge (interior below) covers it, a bottom one does not
    assert at([[-2, 0.125], [3, 0.125], [-2, 3]])
    assert not at([[-2, 0.125], [3, 0.125], [-2, -3]])
    # vertical edge x = 0.375: a left edge (interior right) covers it, a right one does not
    assert at([[0.375, -2], [0.375, 3], [3, 0.5]])
    assert not at([[0.375, -2], [0.375, 3], [-3, 0.5]])
    # a diagonal through the sample shared by two triangles: exactly one has it
    a = [[0.375 - 1, 0.125 - 1], [0.375 + 1, 0.125 + 1], [3, -3]]
    b = [[0.375 - 1, 0.125 - 1], [0.375 + 1, 0.125 + 1], [-3, 3]]
    assert at(a) != at(b)
    # a vertex on the sample: shared by a fan of four triangles around it, owned once
    v = [0.375, 0.125]
    fan = [[v, [2, -2], [2, 2]], [v, [2, 2], [-2, 2]], [v, [-2, 2], [-2, -2]],
           [v, [-2, -2], [2, -2]]]  # fmt: skip
    assert sum(bool(at(t)) for t in fan) == 1


def test_every_vertex_order_in_render(rng):
    xy = rng.uniform(0, 12, (4, 3, 2))
    z = rng.uniform(0.1, 0.9, (4, 3))
    base = None
    for perm in PERMUTATIONS:
        v = xy[:, list(perm)]
        clip = np.concatenate([(v / 12 * 2 - 1) * [1, -1], (2 * z[:, list(perm), None] - 1),
                               np.ones((4, 3, 1))], -1)  # fmt: skip
        frame = tr.render(clip, 12, 12, samples=4)
        if base is None:
            base = frame
        np.testing.assert_array_equal(frame.sample_triangle_id, base.sample_triangle_id)
        np.testing.assert_allclose(frame.sample_depth, base.sample_depth, atol=1e-12)
