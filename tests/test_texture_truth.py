"""Ground truth for texture filtering: the exact perspective map and footprint averages."""

from __future__ import annotations

import numpy as np
import pytest

import teachraster as tr
from teachraster.study.texture_truth import (
    exact_uv,
    filter_study,
    footprint_average,
    gaussian_average,
    texel_reads,
)


def test_exact_uv_agrees_with_render_at_pixel_centres(rng):
    for _ in range(10):
        w = rng.uniform(1, 5, 3)
        clip = np.column_stack([rng.uniform(-1, 1, (3, 2)) * w[:, None], np.zeros(3), w])[None]
        uv = rng.uniform(-1, 2, (1, 3, 2))
        frame = tr.render(clip, 20, 16, attrs=uv)
        r, c = np.nonzero(frame.coverage)
        got, wp = exact_uv(np.repeat(clip, len(r), 0), np.repeat(uv, len(r), 0), c + 0.5,
                           r + 0.5, 20, 16)  # fmt: skip
        np.testing.assert_allclose(got, frame.attrs[r, c], atol=1e-9)
        assert (wp > 0).all()


def full_screen_quad(u_scale=1.0, w=(1.0, 1.0, 1.0, 1.0)):
    """Two triangles covering the whole image, uv 0..u_scale, per-corner w."""
    w = np.asarray(w)
    corners = np.array([[-1, 1], [1, 1], [1, -1], [-1, -1]], float)  # tl, tr, br, bl
    uvs = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float) * u_scale
    idx = [[0, 3, 1], [1, 3, 2]]
    clip = np.array([[[*corners[i] * w[i], 0, w[i]] for i in t] for t in idx])
    return clip, uvs[idx]


def test_footprint_of_an_axis_aligned_pixel_is_its_texel_block(rng):
    # 8 x 8 pixels over a 32 x 32 texture: each pixel covers exactly 4 x 4 texels, and the
    # 16 x 16 jittered strata put 16 points in every texel: the mean is exact.
    tex = rng.uniform(0, 1, (32, 32, 3))
    clip, uv = full_screen_quad()
    frame = tr.render(clip, 8, 8, attrs=uv)
    truth = footprint_average(clip, uv, tex, frame.triangle_id, samples=16)
    np.testing.assert_allclose(truth, tr.mipmap(tex)[2], atol=1e-12)


def test_constant_texture_and_uncovered_pixels():
    clip, uv = full_screen_quad(u_scale=7.0, w=(1, 1, 4, 4))
    ids = tr.render(clip, 10, 6, attrs=uv).triangle_id
    ids[0, 0] = -1
    truth = footprint_average(clip, uv, np.full((5, 3), 0.25), ids, samples=4)
    assert np.isnan(truth[0, 0]) and np.allclose(truth[ids >= 0], 0.25)


def test_gaussian_average_is_a_weighted_mean_about_the_pixel_centre(rng):
    """Review r257 C1: the second reference. A constant texture stays constant (the weights
    are normalised, points beyond the horizon dropped); on an axis-aligned texture of 4 x 4
    texels a pixel, the Gaussian of σ = 0.5 px reaches into the neighbours: it is smoother
    than the box, and its mean over the image is the texture's."""
    clip, uv = full_screen_quad(u_scale=7.0, w=(1, 1, 4, 4))
    ids = tr.render(clip, 10, 6, attrs=uv).triangle_id
    ids[0, 0] = -1
    flat = gaussian_average(clip, uv, np.full((5, 3), 0.25), ids, samples=6)
    assert np.isnan(flat[0, 0]) and np.allclose(flat[ids >= 0], 0.25)
    tex = rng.uniform(0, 1, (32, 32))
    clip, uv = full_screen_quad()
    ids = tr.render(clip, 8, 8, attrs=uv).triangle_id
    box = footprint_average(clip, uv, tex, ids, samples=16)
    smooth = gaussian_average(clip, uv, tex, ids, samples=24)
    assert smooth.std() < 0.8 * box.std()
    assert abs(smooth.mean() - tex.mean()) < 0.02


def test_texel_reads_and_the_study_rows():
    scene = tr.get_scene("textured_floor")
    frame = tr.render(scene, width=64, height=48, texture_filter="trilinear")
    cov = frame.coverage
    d = (frame.ddx[cov], frame.ddy[cov], scene.texture.shape)
    assert texel_reads("nearest", *d) == 1
    assert texel_reads("linear_mipmap_nearest", *d) == 4
    assert 1 < texel_reads("nearest_mipmap_linear", *d) <= 2
    assert 4 < texel_reads("trilinear", *d) <= 8
    assert texel_reads("anisotropic", *d) > texel_reads("trilinear", *d)
    rows = filter_study(scene, 96, 72, samples=12, repeat=1)
    by = {r["filter"]: r for r in rows}
    assert set(by) == set(tr.TEXTURE_FILTERS)  # every filter, nearest_mipmap_linear too
    # minified pixels: mipmaps beat no mipmaps, anisotropy beats trilinear
    assert by["trilinear"]["error_minified"] < by["bilinear"]["error_minified"]
    assert by["anisotropic"]["error_minified"] < by["trilinear"]["error_minified"]
    assert all(r["time_median_s"] > 0 for r in rows)
    # the Gaussian reference too (review r257 C1): mipmaps still beat no mipmaps against it
    assert by["trilinear"]["error_minified_gaussian"] < by["bilinear"]["error_minified_gaussian"]


@pytest.mark.parametrize("samples", [1, 3])
def test_truth_is_repeatable(samples):
    clip, uv = full_screen_quad(u_scale=3.0, w=(1, 1, 3, 3))
    ids = tr.render(clip, 6, 6, attrs=uv).triangle_id
    tex = tr.checkerboard(4, 16)
    a = footprint_average(clip, uv, tex, ids, samples=samples, seed=5)
    b = footprint_average(clip, uv, tex, ids, samples=samples, seed=5)
    np.testing.assert_array_equal(a, b)


def footprint_average_by_solving(clip, uv, texture, triangle_id, *, samples=16, seed=0):
    """The first footprint_average, kept as a cross-check: one linear solve per point
    (:func:`exact_uv`), the texel read by the engine's own ``lookup``."""
    from teachraster.pipeline.texturing.texel_fetch import lookup

    tex = np.asarray(texture, dtype=np.float64)
    tex3 = tex.reshape(*tex.shape[:2], -1)
    clip, uv = np.asarray(clip, dtype=np.float64), np.asarray(uv, dtype=np.float64)
    height, width = triangle_id.shape
    rows, cols = np.nonzero(triangle_id >= 0)
    out = np.full((height, width, tex3.shape[2]), np.nan)
    rng = np.random.default_rng(seed)
    s = int(samples)
    grid = (np.arange(s) + 0.0) / s
    chunk = max(1, 100_000 // (s * s))
    for start in range(0, len(rows), chunk):
        r, c = rows[start : start + chunk], cols[start : start + chunk]
        n = len(r)
        jit = rng.uniform(0, 1 / s, size=(n, s, s, 2))
        x = (c[:, None, None] + grid[None, None, :] + jit[..., 0]).reshape(-1)
        y = (r[:, None, None] + grid[None, :, None] + jit[..., 1]).reshape(-1)
        tri = np.repeat(triangle_id[r, c], s * s)
        coords, w = exact_uv(clip[tri], uv[tri], x, y, width, height)
        ok = w > 0
        vals = lookup(tex3, coords[:, 0], coords[:, 1], "nearest", "repeat")
        vals[~ok] = 0.0
        count = ok.reshape(n, -1).sum(axis=1)
        total = vals.reshape(n, s * s, -1).sum(axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            out[r, c] = total / count[:, None]
    return out if tex.ndim == 3 else out[..., 0]


@pytest.mark.parametrize("trial", range(6))
def test_footprint_average_equals_one_solve_per_point(trial):
    # random triangles (some crossing w = 0: a horizon inside the image), random textures
    # of odd and power-of-two sizes, one or three channels, several sample counts
    rng = np.random.default_rng(100 + trial)
    n = int(rng.integers(1, 4))
    w = rng.uniform(-0.5 if trial % 2 else 0.3, 4.0, (n, 3))
    xy = rng.uniform(-1.5, 1.5, (n, 3, 2)) * np.abs(w)[..., None]
    clip = np.concatenate([xy, np.zeros((n, 3, 1)), w[..., None]], axis=2)
    uv = rng.uniform(-3, 3, (n, 3, 2))
    shape = [(16, 16, 3), (7, 5), (8, 13, 3)][trial % 3]
    tex = rng.uniform(0, 1, shape)
    ids = rng.integers(-1, n, (11, 14))
    samples = int(rng.integers(1, 7))
    new = footprint_average(clip, uv, tex, ids, samples=samples, seed=trial)
    old = footprint_average_by_solving(clip, uv, tex, ids, samples=samples, seed=trial)
    np.testing.assert_allclose(new, old, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(np.isnan(new), np.isnan(old))


def test_footprint_average_of_the_filter_explorers_floor_is_unchanged():
    from teachraster.pipeline.geometry.camera import Camera
    from teachraster.widgets.textured import CORNER_UV, TRIANGLES, plane_clip

    camera = Camera(eye=(0.0, 0.0, 0.0), target=(0.0, 0.0, -1.0), fov_y=60.0, near=0.05,
                    far=50.0)  # fmt: skip
    tex = tr.checkerboard(8, 64)
    uv = np.broadcast_to(CORNER_UV[TRIANGLES] * 8, (2, 3, 2))
    for tilt in (20.0, 85.0):
        clip = plane_clip(tilt, camera, 64 / 48)
        ids = tr.render(clip, 64, 48, attrs=uv).triangle_id
        new = footprint_average(clip, uv, tex, ids, samples=5)
        old = footprint_average_by_solving(clip, uv, tex, ids, samples=5)
        np.testing.assert_array_equal(new, old)
