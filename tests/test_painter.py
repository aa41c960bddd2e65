"""The painter's algorithm: right when triangles are separated in depth, wrong on the two
scenes built to defeat it, where the z-buffer is right.

"Right" is decided independently: per pixel, the triangle whose ``tr.rasterize`` window
depth is smallest there (ties to the earliest), from one fill per triangle.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from test_render import H, W, clip_from_window, reference_fill

import teachraster as tr
from teachraster.pipeline.painters_algorithm import KEYS, painter, painter_order
from teachraster.pipeline.scenes import get_scene


def nearest_per_pixel(clip, width=W, height=H, bits=None):
    """(H, W) index of the nearest triangle at each pixel (-1 none), from per-triangle fills."""
    depth = np.stack(
        [reference_fill(c, None, width, height, subpixel_bits=bits).depth for c in clip]
    )
    depth = np.where(np.isnan(depth), np.inf, depth)
    return np.where(np.isfinite(depth).any(axis=0), np.argmin(depth, axis=0), -1)


def layered_scene(rng, n):
    """``n`` overlapping perspective triangles, each within its own disjoint depth band."""
    bands = rng.permutation(n)
    tris = []
    for b in bands:
        lo = 0.05 + 0.9 * b / n
        z = rng.uniform(lo, lo + 0.8 / n, 3)
        xy = rng.uniform(-4, W + 4, (3, 2))
        tris.append(clip_from_window(xy, z, rng.uniform(0.5, 3.0, 3)))
    return np.array(tris)


# -- painter_order -----------------------------------------------------------------------------
def test_order_far_to_near_by_key():
    """Sorted by decreasing max / mean / min window depth; ties keep the input order."""
    z = np.array([[0.5, 0.6, 0.1], [0.2, 0.9, 0.3], [0.55, 0.55, 0.55], [0.5, 0.6, 0.1]])
    clip = clip_from_window(np.zeros((4, 3, 2)), z, 2.0)
    np.testing.assert_array_equal(painter_order(clip, "max"), [1, 0, 3, 2])
    np.testing.assert_array_equal(painter_order(clip, "min"), [2, 1, 0, 3])
    np.testing.assert_array_equal(painter_order(clip, "mean"), [2, 1, 0, 3])
    np.testing.assert_array_equal(painter_order(clip), painter_order(clip, "max"))


def test_order_ignores_vertices_behind_the_eye():
    """A vertex with w <= 0 has no window depth: the others decide."""
    a = clip_from_window(np.zeros((3, 2)), [0.3, 0.3, 0.3])
    b = clip_from_window(np.zeros((3, 2)), [0.6, 0.6, 0.2])
    b[2] = [0.0, 0.0, 5.0, -1.0]  # behind the eye; its z/w would be -5
    np.testing.assert_array_equal(painter_order([a, b], "min"), [1, 0])
    assert np.isfinite(painter_order([a, b], "mean")).all()


def test_order_rejects_unknown_key():
    """key must be one of max/mean/min, named in the error."""
    with pytest.raises(ValueError, match="key"):
        painter_order(np.zeros((1, 3, 4)) + 1, "median")
    with pytest.raises(ValueError, match="key"):
        painter(clip_from_window(np.zeros((1, 3, 2))), W, H, key="median")


def test_painter_refuses_depth_test():
    """painter draws without a depth test; passing depth_test is a TypeError naming it."""
    with pytest.raises(TypeError, match="depth_test"):
        painter(clip_from_window(np.zeros((1, 3, 2))), W, H, depth_test=True)


# -- where it works --------------------------------------------------------------------------------
@pytest.mark.parametrize("key", KEYS)
def test_painter_equals_zbuffer_when_depths_are_separated(rng, key):
    """Triangles in disjoint depth bands: painter == z-buffer == nearest per pixel, with
    attributes and depth identical, triangle ids in input order."""
    for _ in range(30):
        n = int(rng.integers(2, 8))
        clip = layered_scene(rng, n)
        attrs = rng.uniform(0, 1, (n, 3, 2))
        z = tr.render(clip, W, H, attrs=attrs, subpixel_bits=None)
        p = painter(clip, W, H, attrs=attrs, key=key, subpixel_bits=None)
        np.testing.assert_array_equal(p.triangle_id, z.triangle_id)
        np.testing.assert_array_equal(z.triangle_id, nearest_per_pixel(clip))
        np.testing.assert_allclose(p.attrs, z.attrs, rtol=0, atol=1e-12)
        np.testing.assert_allclose(p.depth, z.depth, rtol=0, atol=1e-12)


def test_painter_ids_refer_to_input_order(rng):
    """Shuffling the input shuffles the ids with it: the same picture either way."""
    clip = layered_scene(rng, 6)
    perm = rng.permutation(6)
    a = painter(clip, W, H)
    b = painter(clip[perm], W, H)
    ids = np.where(b.triangle_id >= 0, perm[np.maximum(b.triangle_id, 0)], -1)
    np.testing.assert_array_equal(ids, a.triangle_id)
    assert len(np.unique(a.triangle_id)) > 3


# -- where it fails ------------------------------------------------------------------------------
@pytest.mark.parametrize("name", ["cyclic_overlap", "intersecting_triangles"])
@pytest.mark.parametrize("key", KEYS)
def test_painter_fails_where_the_zbuffer_succeeds(name, key):
    """On the scenes built to defeat it, the painter shows the wrong triangle at some pixels
    for every sort key, while the z-buffer shows the nearest one everywhere."""
    width, height = 96, 72
    clip = get_scene(name).clip(width / height)
    assert (clip[..., 3] > 0).all() and (np.abs(clip[..., 2]) < clip[..., 3]).all()
    truth = nearest_per_pixel(clip, width, height, bits=None)
    z = tr.render(clip, width, height, subpixel_bits=None)
    np.testing.assert_array_equal(z.triangle_id, truth)
    p = painter(clip, width, height, key=key, subpixel_bits=None)
    np.testing.assert_array_equal(p.coverage, z.coverage)
    wrong = p.triangle_id != truth
    assert wrong.sum() >= 20, f"{name}, key={key}: painter wrong at only {wrong.sum()} pixels"
    # and every drawing order of the triangles is wrong somewhere (no painter's order exists)
    for order in itertools.permutations(range(len(clip))):
        drawn = tr.render(clip[list(order)], width, height, depth_test=False, subpixel_bits=None)
        ids = np.where(drawn.triangle_id >= 0, np.array(order)[drawn.triangle_id], -1)
        assert (ids != truth).any(), f"order {order} would be right"
