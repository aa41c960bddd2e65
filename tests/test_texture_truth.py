"""Ground truth for texture filtering: the exact perspective map and footprint averages."""

from __future__ import annotations

import numpy as np
import pytest

import teachraster as tr
from teachraster.study.texture_truth import (
    exact_uv,
    filter_study,
    footprint_average,
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


def test_texel_reads_and_the_study_rows():
    scene = tr.get_scene("textured_floor")
    frame = tr.render(scene, width=64, height=48, texture_filter="trilinear")
    cov = frame.coverage
    d = (frame.ddx[cov], frame.ddy[cov], scene.texture.shape)
    assert texel_reads("nearest", *d) == 1
    assert texel_reads("linear_mipmap_nearest", *d) == 4
    assert 4 < texel_reads("trilinear", *d) <= 8
    assert texel_reads("anisotropic", *d) > texel_reads("trilinear", *d)
    rows = filter_study(scene, 96, 72, samples=12, repeat=1)
    by = {r["filter"]: r for r in rows}
    assert set(by) >= {"nearest", "bilinear", "trilinear", "anisotropic"}
    # minified pixels: mipmaps beat no mipmaps, anisotropy beats trilinear
    assert by["trilinear"]["error_minified"] < by["bilinear"]["error_minified"]
    assert by["anisotropic"]["error_minified"] < by["trilinear"]["error_minified"]
    assert all(r["time_median_s"] > 0 for r in rows)


@pytest.mark.parametrize("samples", [1, 3])
def test_truth_is_repeatable(samples):
    clip, uv = full_screen_quad(u_scale=3.0, w=(1, 1, 3, 3))
    ids = tr.render(clip, 6, 6, attrs=uv).triangle_id
    tex = tr.checkerboard(4, 16)
    a = footprint_average(clip, uv, tex, ids, samples=samples, seed=5)
    b = footprint_average(clip, uv, tex, ids, samples=samples, seed=5)
    np.testing.assert_array_equal(a, b)
