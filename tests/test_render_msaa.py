"""Multisampled ``tr.render``: per-sample coverage and depth, shading per pixel, the resolve.

References: ``tr.rasterize(..., samples=S)`` per triangle (itself checked exactly in
tests/test_multisample.py) with an independent per-sample z-buffer written here; the plan's
key property (planned == forced) on random and built-in scenes.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import cases
from test_plan import random_scene
from test_render import H, W, clip_from_window, random_clip

import teachraster as tr
from teachraster.pipeline.multisampling import _owners, owners
from teachraster.pipeline.render_plan import FORCEABLE
from teachraster.pipeline.scenes import SCENES, get_scene

FIELDS = ("triangle_id", "sample_triangle_id")
VALUES = ("attrs", "depth", "sample_depth", "sample_attrs")


def assert_same(a, b, msg=""):
    for name in FIELDS:
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=f"{msg} {name}")
    for name in VALUES:
        np.testing.assert_allclose(getattr(a, name), getattr(b, name), rtol=0, atol=1e-12,
                                   err_msg=f"{msg} {name}")  # fmt: skip


def reference_samples(clip, width, height, samples=4, depth_test=True):
    """Per-sample ids and depths by filling each triangle alone and a z-buffer per sample."""
    ids = np.full((height, width, len(tr.sample_pattern(samples))), -1)
    depth = np.full(ids.shape, np.inf)
    win = tr.to_window(clip, width, height)
    for t, v in enumerate(win):
        fill = tr.rasterize(tr.Triangle(v[:, :2], z=v[:, 2]), width, height, samples=samples)
        cov = fill.sample_coverage
        if depth_test:
            cov = cov & (fill.sample_depth < depth)
        ids[cov], depth[cov] = t, fill.sample_depth[cov]
    return ids


# -- planned == forced ------------------------------------------------------------------------
@pytest.mark.parametrize("samples", [4, 2, 8, 16, "jittered"])
def test_planned_equals_forced_random_scenes(rng, samples):
    if samples == "jittered":
        samples = tr.sample_pattern(9, "jittered", seed=4)
    per_sample = 0
    for index in range(cases(40)):
        clip, attrs, kw = random_scene(rng, index)
        planned = tr.render(clip, W, H, attrs=attrs, samples=samples, **kw)
        msg = f"scene {index}: clip={clip.tolist()}, kwargs={kw}"
        for force in ("all", *FORCEABLE):
            forced = tr.render(clip, W, H, attrs=attrs, samples=samples, force=force, **kw)
            assert_same(planned, forced, f"{msg} force={force}")
        effect = planned.plan["multisampling"]
        assert effect.total == int(planned.coverage.sum())
        per_sample += effect.count < effect.total
    assert per_sample > cases(40) / 4  # whole pixels are skipped in most scenes


@pytest.mark.parametrize("name", list(SCENES))
def test_planned_equals_forced_builtin_scenes(name):
    scene = get_scene(name)
    planned = tr.render(scene, None, 64, 48, samples=4)
    forced = tr.render(scene, None, 64, 48, samples=4, force="multisampling")
    assert_same(planned, forced, name)
    np.testing.assert_allclose(planned.image, forced.image, rtol=0, atol=1e-12)
    everything = tr.render(scene, None, 64, 48, samples=4, force="all")
    np.testing.assert_array_equal(planned.sample_triangle_id, everything.sample_triangle_id)
    assert forced.plan["multisampling"].count == forced.plan["multisampling"].total


# -- per-sample coverage and depth ------------------------------------------------------------
def test_per_sample_ids_match_rasterize_painter(rng):
    for _ in range(20):
        clip = random_clip(rng, int(rng.integers(1, 8)), equal_w=True)
        for samples in (2, 4, 8, 16):
            frame = tr.render(clip, W, H, samples=samples, depth_test=False)
            want = reference_samples(clip, W, H, samples, depth_test=False)
            np.testing.assert_array_equal(frame.sample_triangle_id, want)


def test_per_sample_depth_test_layers(rng):
    """Constant-depth triangles: the per-sample z-buffer has no near-ties to round."""
    for _ in range(20):
        n = int(rng.integers(2, 8))
        xy = rng.uniform(-4, [W + 4, H + 4], (n, 3, 2))
        z = rng.permutation(np.linspace(0.1, 0.9, n))
        clip = clip_from_window(xy, z[:, None])
        frame = tr.render(clip, W, H, samples=4)
        np.testing.assert_array_equal(frame.sample_triangle_id, reference_samples(clip, W, H))
        hit = frame.sample_triangle_id >= 0
        np.testing.assert_allclose(frame.sample_depth[hit], z[frame.sample_triangle_id[hit]])
        assert np.isnan(frame.sample_depth[~hit]).all()


def test_sample_depth_is_the_plane_at_the_sample(rng):
    clip = random_clip(rng, 6)
    frame = tr.render(clip, W, H, samples=4, depth_test=False)
    win = tr.to_window(clip, W, H)
    p = tr.sample_pattern(4)
    for i, j, s in zip(*np.nonzero(frame.sample_triangle_id >= 0)):
        v = win[frame.sample_triangle_id[i, j, s]]
        lam = tr.barycentric(v[:, :2], [j + p[s, 0], i + p[s, 1]])
        assert frame.sample_depth[i, j, s] == pytest.approx(lam @ v[:, 2], abs=1e-9)


# -- per pixel: owner, attributes, resolve ----------------------------------------------------
def test_owner_most_samples_ties_earlier():
    assert owners(np.array([[0, 1, 1, -1]]))[0].tolist() == [1]
    assert owners(np.array([[1, 0, 0, 1]]))[0].tolist() == [0]  # tie: the earlier
    assert owners(np.array([[-1, -1, -1, -1]]))[0].tolist() == [-1]
    # two triangles sharing the diagonal of a 2x2 image
    clip = clip_from_window([[[0, 0], [2, 0], [0, 2]], [[2, 0], [2, 2], [0, 2]]], 0.5, 1.0, 2, 2)
    frame = tr.render(clip, 2, 2, attrs=np.array([[1.0] * 3, [2.0] * 3]), samples=4)
    ids = frame.sample_triangle_id
    assert ((ids >= 0).sum(axis=2) == 4).all()  # watertight per sample
    for i in range(2):
        for j in range(2):
            counts = np.bincount(ids[i, j], minlength=2)
            assert frame.triangle_id[i, j] == int(np.argmax(counts))
            assert frame.attrs[i, j, 0] == 1.0 + frame.triangle_id[i, j]


def test_pair_owners_decide_like_sample_owners(rng):
    """``_owners`` (per (pixel, triangle) pair and its sample mask, as the renderer keeps
    them) picks the owner ``owners`` picks from the samples, and the piece at its lowest
    sample when clipping split the input triangle."""
    for _ in range(300):
        n_s = int(rng.choice([2, 4, 8, 16]))
        parent = np.sort(rng.integers(0, 4, 7))  # clipping keeps pieces in input order
        sub = rng.integers(-1, 7, (int(rng.integers(1, 6)), n_s))
        sub[:, 0] = np.maximum(sub[:, 0], 0)  # every pixel shows something
        pixel, tri = np.nonzero((sub[:, :, None] == np.arange(7)).any(axis=1))
        bits = ((sub[pixel] == tri[:, None]) << np.arange(n_s)).sum(axis=1)
        pixels, own = _owners(pixel, parent[tri], bits)
        want, first = owners(np.where(sub >= 0, parent[np.maximum(sub, 0)], -1))
        np.testing.assert_array_equal(pixels, np.arange(len(sub)))
        np.testing.assert_array_equal(parent[tri[own]], want)
        np.testing.assert_array_equal(tri[own], sub[np.arange(len(sub)), first])


def test_attributes_once_per_pixel_at_the_centre(rng):
    clip = random_clip(rng, 6, equal_w=True)
    attrs = rng.uniform(0, 1, (6, 3, 2))
    frame = tr.render(clip, W, H, attrs=attrs, samples=4)
    win = tr.to_window(clip, W, H)
    ids = frame.sample_triangle_id
    for i, j in zip(*np.nonzero(frame.coverage)):
        for s in range(4):
            t = ids[i, j, s]
            if t < 0:
                assert np.isnan(frame.sample_attrs[i, j, s]).all()
                continue
            lam = tr.barycentric(win[t, :, :2], [j + 0.5, i + 0.5])  # may extrapolate
            np.testing.assert_allclose(frame.sample_attrs[i, j, s], lam @ attrs[t], atol=1e-9)
        t = frame.triangle_id[i, j]
        lam = tr.barycentric(win[t, :, :2], [j + 0.5, i + 0.5])
        np.testing.assert_allclose(frame.attrs[i, j], lam @ attrs[t], atol=1e-9)


@pytest.mark.parametrize("samples", [4, 2, 8])
def test_centroid_moves_uncovered_centres_like_rasterize(rng, samples):
    """``centroid=True``: a pixel whose centre its triangle does not cover takes the
    attributes at the covered sample nearest the centre (values in range), as
    ``rasterize(..., centroid=True)`` does; covered centres keep their values."""
    moved = 0
    for index in range(30):
        xy = rng.integers(-3, [W + 3, H + 3], (3, 2)).astype(np.float64)  # snapping is exact
        w = rng.uniform(0.5, 3.0, 3) if index % 2 else np.ones(3)
        attrs = rng.uniform(-1, 1, (1, 3, 2))
        clip = clip_from_window(xy[None], rng.uniform(0.1, 0.9, 3), w)
        frame = tr.render(clip, W, H, attrs=attrs, samples=samples, centroid=True)
        plain = tr.render(clip, W, H, attrs=attrs, samples=samples)
        tri = tr.Triangle(tr.to_window(clip, W, H)[0, :, :2], attrs={"a": attrs[0]}, w=w)
        fill = tr.rasterize(tri, W, H, samples=samples, centroid=True)
        centre = tr.rasterize(tri, W, H).coverage
        np.testing.assert_array_equal(frame.coverage, fill.coverage)
        np.testing.assert_allclose(frame.attrs[frame.coverage], fill.attrs["a"][fill.coverage],
                                   rtol=0, atol=1e-9)  # fmt: skip
        np.testing.assert_array_equal(frame.attrs[centre], plain.attrs[centre])
        off = frame.coverage & ~centre
        moved += off.sum()
        lo, hi = attrs[0].min(axis=0) - 1e-12, attrs[0].max(axis=0) + 1e-12
        assert ((frame.attrs[off] >= lo) & (frame.attrs[off] <= hi)).all()
        assert_same(frame, tr.render(clip, W, H, attrs=attrs, samples=samples, centroid=True,
                                     force="all"))  # fmt: skip
    assert moved > 50


def test_centroid_planned_equals_forced(rng):
    for index in range(30):
        clip, attrs, kw = random_scene(rng, index)
        planned = tr.render(clip, W, H, attrs=attrs, samples=4, centroid=True, **kw)
        for force in ("all", "multisampling", "attributes"):
            forced = tr.render(clip, W, H, attrs=attrs, samples=4, centroid=True, force=force,
                               **kw)  # fmt: skip
            assert_same(planned, forced, f"scene {index} force={force}")


def test_centroid_is_checked_and_ignored_with_one_sample():
    clip = clip_from_window([[[0, 0], [4, 0], [0, 4]]], 0.5, 1.0, 4, 4)
    with pytest.raises(TypeError, match="centroid"):
        tr.render(clip, 4, 4, samples=4, centroid="yes")
    one = tr.render(clip, 4, 4, attrs=np.ones((1, 3)), centroid=True)
    np.testing.assert_array_equal(one.attrs, tr.render(clip, 4, 4, attrs=np.ones((1, 3))).attrs)


def test_resolve_and_single_sample_frames():
    clip = clip_from_window([[[0, 0], [4, 0], [0, 4]]], 0.5, 1.0, 4, 4)
    frame = tr.render(clip, 4, 4, attrs=np.ones((1, 3, 3)), samples=4)
    fraction = frame.coverage_fraction
    red = frame.resolve(frame.sample_attrs * [1, 0, 0], background=[0, 0, 1.0])
    np.testing.assert_allclose(red[..., 0], fraction)
    np.testing.assert_allclose(red[..., 2], 1 - fraction)
    assert set(np.unique(fraction)) <= {0, 0.25, 0.5, 0.75, 1.0}
    one = tr.render(clip, 4, 4, attrs=np.ones((1, 3)))
    np.testing.assert_array_equal(one.resolve(np.ones((4, 4)), 0.0), one.coverage.astype(float))
    np.testing.assert_array_equal(one.coverage_fraction, one.coverage.astype(float))
    with pytest.raises(ValueError, match="values"):
        frame.resolve(np.ones((4, 4)))


def test_scene_image_is_the_resolve():
    scene = get_scene("single_triangle")
    frame = tr.render(scene, None, 40, 30, samples=4)
    one = tr.render(scene, None, 40, 30)
    full = frame.coverage_fraction == 1
    assert full.any() and (frame.coverage_fraction[frame.coverage] < 1).any()
    # partly covered pixels blend the triangle with the white background: never darker
    edge = frame.coverage & ~full
    assert np.isfinite(frame.image[frame.coverage]).all()
    assert np.isnan(frame.image[~frame.coverage]).all()
    lum = frame.image.mean(axis=2)
    inside = one.image.mean(axis=2)
    assert (lum[edge] >= np.nanmin(inside) - 1e-12).all()


@pytest.mark.parametrize("samples", [3, 0, [[0.5, 1.5]], True])
def test_bad_samples_in_render(samples):
    clip = clip_from_window([[[0, 0], [4, 0], [0, 4]]], 0.5, 1.0, 4, 4)
    with pytest.raises((ValueError, TypeError), match="samples"):
        tr.render(clip, 4, 4, samples=samples)


def test_trace_records_the_per_sample_tests(rng):
    clip = random_clip(rng, 6)
    frame = tr.render(clip, W, H, samples=4, trace=True)
    plain = tr.render(clip, W, H, samples=4)
    np.testing.assert_array_equal(frame.sample_triangle_id, plain.sample_triangle_id)
    t = frame.trace
    per_sample = t.fragment_sample >= 0
    # at each sample the last entry that passed the test (drawing order) is what is shown
    last = {}
    for k in np.flatnonzero(per_sample & t.fragment_passed):
        last[t.fragment_row[k], t.fragment_col[k], t.fragment_sample[k]] = t.fragment_triangle[k]
    assert len(last) > 20
    for (i, j, s), tri in last.items():
        assert frame.sample_triangle_id[i, j, s] == tri
    whole = ~per_sample
    ids = frame.sample_triangle_id[t.fragment_row[whole], t.fragment_col[whole]]
    assert (ids == t.fragment_triangle[whole][:, None]).all()  # one triangle at every sample
    assert whole.sum() == frame.plan["multisampling"].total - frame.plan["multisampling"].count


@pytest.mark.parametrize(
    "clip",
    [np.zeros((0, 3, 4)), np.array([[[0, 0, 0, -1], [1, 0, 0, -1], [0, 1, 0, -1]]], float),
     np.array([[[0, 0, 0, 1], [0.5, 0.5, 0, 1], [1, 1, 0, 1]]], float)],
    ids=["empty", "behind the eye", "zero area"],
)  # fmt: skip
def test_nothing_to_draw(clip):
    frame = tr.render(clip, 8, 6, samples=4, attrs=np.ones((len(clip), 3)), trace=True)
    assert (frame.sample_triangle_id == -1).all() and (frame.triangle_id == -1).all()
    assert np.isnan(frame.sample_depth).all() and np.isnan(frame.attrs).all()
    assert frame.plan["multisampling"].total == 0
    np.testing.assert_array_equal(frame.resolve(np.zeros((6, 8, 4)), 0.5), 0.5)
