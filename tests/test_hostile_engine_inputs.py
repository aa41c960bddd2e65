"""Engine inputs a hostile (or unlucky) user tries: each is answered, fast, with a named error
or the true value, never a hang, a raw numpy error, a warning or silent garbage.

These are the engine items of the "course a teacher can trust" review: anisotropic filtering
with an unbounded probe count, derivatives and coordinates near the float maximum, booleans
and strings where numbers belong, a silent downgrade of trilinear under MSAA, the resolve's
arguments, sample offsets a hair below 1, and blocks far larger than the image.
"""

from __future__ import annotations

import math
import tracemalloc
import warnings

import numpy as np
import pytest

import teachraster as tr
from teachraster.pipeline.texture_filters import MAX_ANISOTROPY

TEX = tr.checkerboard(4, 16)
UV = [[0.3, 0.4], [0.71, 0.2]]


@pytest.fixture(autouse=True)
def _warnings_are_errors():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


@pytest.mark.parametrize("cap", [math.inf, 1e5, 17, 10**9])
def test_max_anisotropy_is_clamped_to_16(cap):
    ddx, ddy = [[1e-4, 0.0]] * 2, [[0.0, 50.0]] * 2  # a needle: far more than 16 probes
    got = tr.sample(TEX, UV, "anisotropic", ddx=ddx, ddy=ddy, max_anisotropy=cap)
    want = tr.sample(TEX, UV, "anisotropic", ddx=ddx, ddy=ddy, max_anisotropy=MAX_ANISOTROPY)
    assert MAX_ANISOTROPY == 16
    np.testing.assert_array_equal(got, want)


@pytest.mark.parametrize("filter", ["trilinear", "nearest_mipmap_nearest", "anisotropic"])
@pytest.mark.parametrize("d", [1e308, 1.7e308, np.inf, -np.inf])
def test_huge_and_infinite_derivatives_read_the_smallest_level(filter, d):
    ddx, ddy = [[d, 0.0]] * 2, [[0.0, d]] * 2
    got = tr.sample(TEX, UV, filter, ddx=ddx, ddy=ddy)
    smallest = tr.mipmap(TEX)[-1]  # a 1 x 1 level: its one texel everywhere
    np.testing.assert_allclose(got, np.broadcast_to(smallest[0, 0], got.shape), rtol=1e-12)
    assert not np.signbit(got).any()


@pytest.mark.parametrize("scale", [1e200, 1e-200, 1e300, 1e-300, 2.0**-1070])
def test_mip_level_has_no_overflow_or_underflow(scale):
    lam = tr.mip_level([[scale, 0.0]], [[0.0, scale / 2]], (8, 8))
    assert lam[0] == pytest.approx(math.log2(scale) + 3, abs=1e-9)


def test_mip_level_in_the_ordinary_range_is_the_gl_formula_bit_for_bit():
    rng = np.random.default_rng(5)
    dx, dy = rng.normal(size=(500, 2)) / 40, rng.normal(size=(500, 2)) / 40
    sx = (dx[:, 0] * 64) ** 2 + (dx[:, 1] * 32) ** 2
    sy = (dy[:, 0] * 64) ** 2 + (dy[:, 1] * 32) ** 2
    np.testing.assert_array_equal(tr.mip_level(dx, dy, (32, 64)), 0.5 * np.log2(np.maximum(sx, sy)))


@pytest.mark.parametrize("filter", ["nearest", "bilinear"])
@pytest.mark.parametrize("u", [1.7e308, -1.7e308, 2.0**60 + 0.25, 1e300])
def test_huge_coordinates_repeat_and_clamp(filter, u):
    rep = tr.sample(TEX, [[u, 0.4]], filter)
    np.testing.assert_array_equal(rep, tr.sample(TEX, [[math.fmod(u, 1.0) % 1.0, 0.4]], filter))
    clamp = tr.sample(TEX, [[u, 0.4]], filter, wrap="clamp")
    border = 1.0 if u > 0 else 0.0
    np.testing.assert_array_equal(clamp, tr.sample(TEX, [[border, 0.4]], filter, wrap="clamp"))


def test_bilinear_of_texels_near_the_float_maximum():
    tex = np.array([[1e308, -1e308], [-1.7e308, 1.7e308]])
    centres = [[0.25, 0.25], [0.75, 0.25], [0.25, 0.75], [0.75, 0.75]]
    np.testing.assert_array_equal(tr.sample(tex, centres, "bilinear"), tex.ravel())
    mid = tr.sample(tex, [[0.5, 0.25]], "bilinear")
    assert mid[0] == 0.0


@pytest.mark.parametrize(
    "kwargs",
    [
        {"lod": "1"},
        {"lod": True},
        {"lod": np.True_},
        {"lod": [1 + 2j, 0]},
        {"ddx": [["1", "0"]] * 2, "ddy": [[0, 1]] * 2},
        {"ddx": [[True, False]] * 2, "ddy": [[0, 1]] * 2},
        {"ddx": [[0, 1]] * 2, "ddy": [[0, "1"]] * 2},
    ],
)
def test_lod_and_derivatives_must_be_numbers(kwargs):
    name = "ddy" if "ddy" in kwargs and np.asarray(kwargs["ddy"]).dtype.kind == "U" else None
    name = name or next(iter(kwargs))
    with pytest.raises(TypeError, match=name):
        tr.sample(TEX, UV, "trilinear", **kwargs)


def test_mip_level_refuses_booleans():
    with pytest.raises(TypeError, match="ddx"):
        tr.mip_level([[True, False]], [[0.0, 1.0]], (8, 8))


def test_numpy_booleans_are_flags_everywhere():
    clip = [[[-1, -1, 0, 1], [1, -1, 0, 2], [-1, 1, 0, 1]]]
    uv = [[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]]
    a = tr.render(clip, 8, 8, attrs=uv, derivatives=np.True_)
    b = tr.render(clip, 8, 8, attrs=uv, derivatives=True)
    np.testing.assert_array_equal(a.ddx, b.ddx)
    c = tr.render(clip, 8, 8, attrs=uv, derivatives=np.False_)
    assert c.ddx is None or np.isnan(c.ddx).all()
    d = tr.render(clip, 8, 8, attrs=uv, samples=4, centroid=np.True_)
    assert d.sample_triangle_id is not None


def test_trilinear_under_msaa_is_never_a_silent_downgrade():
    scene = tr.get_scene("textured_floor")
    msaa = tr.render(scene, None, 96, 72, samples=4, texture_filter="trilinear")
    effect = msaa.plan["derivatives"]
    assert effect.ran and "samples=4" in effect.why and "quad" in effect.why
    bilinear = tr.render(scene, None, 96, 72, samples=4, texture_filter="bilinear")
    assert np.nanmax(np.abs(msaa.image - bilinear.image)) > 0.1  # mip levels are used
    # Where one triangle covers every sample of a pixel, the pixel shades exactly as in the
    # one-sample render: same quad, same triangle, same differences.
    single = tr.render(scene, None, 96, 72, texture_filter="trilinear")
    ids = msaa.sample_triangle_id
    whole = (ids == ids[..., :1]).all(axis=-1) & (ids[..., 0] >= 0)
    np.testing.assert_allclose(msaa.image[whole], single.image[whole], rtol=0, atol=1e-12)


def test_msaa_derivatives_match_the_one_sample_quads():
    from teachraster.pipeline.rendering.msaa_derivatives import sample_derivatives

    scene = tr.get_scene("textured_floor")
    single = tr.render(scene, None, 64, 48, texture_filter="trilinear")
    msaa = tr.render(scene, None, 64, 48, samples=4)
    clip = scene.camera.clip(scene.mesh.corner_positions(), 64 / 48)
    ddx, ddy, _ = sample_derivatives(
        msaa.sample_triangle_id, clip, scene.mesh.corner("uv"), 8, True
    )
    ids = msaa.sample_triangle_id
    whole = (ids == ids[..., :1]).all(axis=-1) & (ids[..., 0] >= 0)
    uv = single.layout["uv"]
    np.testing.assert_allclose(ddx[whole][:, 0], single.ddx[whole][:, uv], atol=1e-15)
    np.testing.assert_allclose(ddy[whole][:, 0], single.ddy[whole][:, uv], atol=1e-15)
    assert np.isnan(ddx[ids < 0]).all()


@pytest.fixture(scope="module")
def msaa_frame():
    return tr.render([[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]], 4, 4, samples=4)


@pytest.mark.parametrize(
    "values, error",
    [
        ("x", TypeError),
        (np.ones((4, 4, 4)) * 1j, TypeError),
        (None, TypeError),
        ([[1, 2]], ValueError),
        (np.ones(3), ValueError),
        (np.ones((4, 4, 4, 2, 2)), ValueError),
        ([[[["a"]]]], TypeError),
    ],
)
def test_resolve_names_bad_values(msaa_frame, values, error):
    with pytest.raises(error, match="values"):
        msaa_frame.resolve(values)


@pytest.mark.parametrize("background", ["white", 1j, [1.0, 2.0], [[0.0]]])
def test_resolve_names_a_bad_background(msaa_frame, background):
    with pytest.raises((TypeError, ValueError), match="background"):
        msaa_frame.resolve(np.ones((4, 4, 4, 3)), background=background)


def test_resolve_means_near_the_float_maximum(msaa_frame):
    got = msaa_frame.resolve(np.full((4, 4, 4), 1.7e308), background=1.7e308)
    np.testing.assert_array_equal(got, np.full((4, 4), 1.7e308))


def test_resolve_of_a_one_sample_frame_checks_its_shape():
    frame = tr.render([[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]], 4, 4)
    with pytest.raises(ValueError, match="values"):
        frame.resolve(np.ones(3))
    assert frame.resolve(np.ones((4, 4))).shape == (4, 4)


@pytest.mark.parametrize(
    "samples", [[[0.5 + 1j, 0.5]], [["0.5", 0.5]], [[True, False]], [[b"1", 0.5]]]
)
def test_sample_offsets_must_be_real_numbers(samples):
    clip = [[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]]
    with pytest.raises(TypeError, match="samples"):
        tr.render(clip, 4, 4, samples=samples)


def test_an_offset_just_below_one_stays_inside_its_pixel():
    # A square from x = 1 to x = 3 (two triangles): its left edge is a left edge, so a sample
    # exactly at x = 1.0 would be covered. The offset 0.9999999 of pixel column 0 lies at
    # x = 0.9999999 < 1, outside: column 0 must stay empty.
    x0, x1 = 1 / 2 - 1, 3 / 2 - 1  # window x = 1 and 3 on a 4-px-wide image
    a, b, c, d = [x0, -1, 0, 1], [x1, -1, 0, 1], [x1, 1, 0, 1], [x0, 1, 0, 1]
    frame = tr.render([[a, b, c], [a, c, d]], 4, 4, samples=[[0.9999999, 0.5]])
    assert (frame.sample_triangle_id[:, 0, 0] == -1).all()
    assert (frame.sample_triangle_id[:, 1, 0] >= 0).all()
    exact_one = tr.render([[a, b, c], [a, c, d]], 4, 4, samples=[[0.0, 0.5]])
    assert (exact_one.sample_triangle_id[:, 1, 0] >= 0).all()


@pytest.mark.parametrize("sizes", [(10**4,), (10**5,), (10007,), (10**4, 1), (2**20, 2**10, 1)])
def test_blocks_far_larger_than_the_image_cost_what_the_image_costs(sizes):
    tri = tr.Triangle([[1.2, 1.1], [7.3, 2.2], [3.4, 7.5]], w=[1, 2, 3], attrs={"u": [0, 1, 2]})
    ref = tr.rasterize(tri, 8, 8)
    tracemalloc.start()
    try:
        got = tr.rasterize(tri, 8, 8, method="tiled", block_sizes=sizes, trace=True)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 8 * 2**20, f"{peak / 2**20:.1f} MiB for an 8 x 8 image"
    np.testing.assert_array_equal(got.coverage, ref.coverage)
    np.testing.assert_array_equal(got.attrs["u"], ref.attrs["u"])
