"""Mipmaps, the level of detail and the mipmapped / anisotropic filters, against references.

The references here are written from the GL rules in CONVENTIONS.md and the
``texture_filters`` docstring, scalar by scalar in plain Python floats: they share no code
with the package.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import examples
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr
from teachraster.pipeline.mip_pyramid import level_sizes
from teachraster.pipeline.texture import TEXTURE_FILTERS
from teachraster.pipeline.texture_filters import MIPMAP_FILTERS, levels_read, nearest_level


# -- references -------------------------------------------------------------------------------
def ref_shrink_axis(a: np.ndarray, axis: int, n_out: int) -> np.ndarray:
    """Exact area average: repeat each texel n_out times, average blocks of n_in."""
    n_in = a.shape[axis]
    if n_in == n_out:
        return a
    fine = np.repeat(a, n_out, axis=axis)
    shape = list(fine.shape)
    shape[axis : axis + 1] = [n_out, n_in]
    return fine.reshape(shape).mean(axis=axis + 1)


def ref_texel(level, r, c, wrap):
    h, w = level.shape[:2]
    if wrap == "repeat":
        r, c = r % h, c % w
    else:
        r, c = min(max(r, 0), h - 1), min(max(c, 0), w - 1)
    return level[r, c]


def ref_lookup(level, u, v, within, wrap):
    h, w = level.shape[:2]
    if within == "nearest":
        return ref_texel(level, math.floor(v * h), math.floor(u * w), wrap)
    x, y = u * w - 0.5, v * h - 0.5
    i, j = math.floor(y), math.floor(x)
    a, b = x - j, y - i
    return (
        (1 - a) * (1 - b) * ref_texel(level, i, j, wrap)
        + a * (1 - b) * ref_texel(level, i, j + 1, wrap)
        + (1 - a) * b * ref_texel(level, i + 1, j, wrap)
        + a * b * ref_texel(level, i + 1, j + 1, wrap)
    )


def ref_mip(levels, u, v, lam, filter, wrap="repeat"):
    """One sample of a mipmapped filter, following the GL specification's wording."""
    q = len(levels) - 1
    within = "bilinear" if filter in ("linear_mipmap_nearest", "trilinear") else "nearest"
    if lam <= 0:  # magnification: level 0
        return ref_lookup(levels[0], u, v, within, wrap)
    if filter.endswith("mipmap_nearest"):
        d = 0 if lam <= 0.5 else math.ceil(lam + 0.5) - 1
        return ref_lookup(levels[min(d, q)], u, v, within, wrap)
    if lam >= q:
        return ref_lookup(levels[q], u, v, within, wrap)
    d1 = math.floor(lam)
    t = lam - d1
    lo = ref_lookup(levels[d1], u, v, within, wrap)
    hi = ref_lookup(levels[d1 + 1], u, v, within, wrap)
    return (1 - t) * lo + t * hi


def ref_lambda(dx, dy, h, w):
    jac = np.array([[dx[0] * w, dy[0] * w], [dx[1] * h, dy[1] * h]])
    return math.log2(max(np.linalg.norm(jac[:, 0]), np.linalg.norm(jac[:, 1])))


def ref_aniso(levels, u, v, dx, dy, max_aniso, wrap="repeat"):
    h, w = levels[0].shape[:2]
    px = math.hypot(dx[0] * w, dx[1] * h)
    py = math.hypot(dy[0] * w, dy[1] * h)
    pmax, pmin = max(px, py), min(px, py)
    if pmax <= 1:  # magnified: level 0
        return ref_lookup(levels[0], u, v, "bilinear", wrap)
    n = min(math.ceil(pmax / pmin), max_aniso)
    lam = math.log2(pmax / n)
    du, dv = (dx if px >= py else dy)[:2]
    total = 0.0
    for i in range(1, n + 1):
        s = i / (n + 1) - 0.5
        total = total + ref_mip(levels, u + s * du, v + s * dv, lam, "trilinear", wrap)
    return total / n


# -- mipmap -----------------------------------------------------------------------------------
@pytest.mark.parametrize("shape", [(8, 8), (16, 4, 3), (1, 32), (5, 7), (6, 3, 2), (13, 1), (1, 1)])
def test_mipmap_is_the_exact_area_average_level_by_level(rng, shape):
    tex = rng.uniform(0, 1, size=shape)
    levels = tr.mipmap(tex)
    h, w = shape[:2]
    assert len(levels) == math.floor(math.log2(max(h, w))) + 1
    assert levels[-1].shape[:2] == (1, 1)
    assert levels[0] is not tex and np.array_equal(levels[0], tex)
    for prev, lv in zip(levels, levels[1:]):
        # GL's floor rule for the size
        assert lv.shape == (max(1, prev.shape[0] // 2), max(1, prev.shape[1] // 2)) + shape[2:]
        ref = ref_shrink_axis(ref_shrink_axis(prev, 0, lv.shape[0]), 1, lv.shape[1])
        np.testing.assert_allclose(lv, ref, rtol=0, atol=1e-14)


def test_power_of_two_levels_are_2x2_means_and_keep_the_mean(rng):
    tex = rng.uniform(0, 1, size=(32, 64, 3))
    levels = tr.mipmap(tex)
    for prev, lv in zip(levels, levels[1:]):
        h, w = lv.shape[:2]
        hh, ww = prev.shape[0] // h, prev.shape[1] // w
        ref = prev.reshape(h, hh, w, ww, 3).mean(axis=(1, 3))
        np.testing.assert_allclose(lv, ref, atol=1e-15)
    np.testing.assert_allclose(levels[-1][0, 0], tex.mean(axis=(0, 1)), atol=1e-14)


def test_level_sizes_follow_the_floor_rule():
    assert level_sizes(1, 1) == [(1, 1)]
    assert level_sizes(7, 2) == [(7, 2), (3, 1), (1, 1)]
    assert [s for s, _ in level_sizes(100, 1)] == [100, 50, 25, 12, 6, 3, 1]


# -- level of detail --------------------------------------------------------------------------
@settings(max_examples=examples(60), deadline=None)
@given(
    d=st.lists(st.floats(-2, 2, allow_nan=False, allow_subnormal=False), min_size=4, max_size=4),
    h=st.integers(1, 512),
    w=st.integers(1, 512),
)
def test_mip_level_is_the_gl_formula(d, h, w):
    dx, dy = np.array(d[:2]), np.array(d[2:])
    if max(abs(x) for x in d) < 1e-6:
        return
    got = tr.mip_level(dx, dy, (h, w, 3))
    assert got == pytest.approx(ref_lambda(dx, dy, h, w), abs=1e-12)


@pytest.mark.parametrize("angle", [0.0, 0.3, 1.0, 2.5])
@pytest.mark.parametrize("scale", [0.25, 1.0, 3.0, 100.0])
def test_a_rotated_uniform_scale_has_lambda_log2_scale(angle, scale):
    # uv = R(angle) * scale * (x, y) / 64 on a 64 x 64 texture: scale texels per pixel.
    c, s = math.cos(angle), math.sin(angle)
    dx = np.array([c, s]) * scale / 64
    dy = np.array([-s, c]) * scale / 64
    assert tr.mip_level(dx, dy, (64, 64)) == pytest.approx(math.log2(scale), abs=1e-12)


def test_mip_level_keeps_extra_channels_nan_and_zero():
    dx = np.array([[0.5, 0.0, 9.0], [np.nan, 0.0, 0.0], [0.0, 0.0, 0.0]])
    dy = np.zeros((3, 3))
    got = tr.mip_level(dx, dy, (4, 4))
    assert got[0] == 1.0 and np.isnan(got[1]) and got[2] == -np.inf


def test_nearest_level_is_gls_rule():
    lam = np.linspace(-2, 12, 2801)
    got = nearest_level(lam, 9)
    for lv, g in zip(lam, got):
        want = 0 if lv <= 0.5 else math.ceil(lv + 0.5) - 1
        assert g == min(max(want, 0), 9)


# -- mipmapped filters ------------------------------------------------------------------------
MIP = [f for f in MIPMAP_FILTERS if f != "anisotropic"]


@pytest.mark.parametrize("wrap", ["repeat", "clamp"])
@pytest.mark.parametrize("filter", MIP)
@pytest.mark.parametrize("shape", [(16, 16, 3), (12, 5)])
def test_mipmapped_filters_match_the_scalar_reference(rng, filter, wrap, shape):
    tex = rng.uniform(0, 1, size=shape)
    levels = tr.mipmap(tex)
    uv = rng.uniform(-0.5, 1.5, size=(300, 2))
    lam = rng.uniform(-2, 6, size=300)
    lam[:40] = np.round(lam[:40] * 2) / 2  # exactly on the ½ boundaries too
    got = tr.sample(tex, uv, filter, wrap, lod=lam)
    want = np.array([ref_mip(levels, u, v, lv, filter, wrap) for (u, v), lv in zip(uv, lam)])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)


@pytest.mark.parametrize("filter", MIP)
def test_lod_from_derivatives_equals_lod_given(rng, filter):
    tex = rng.uniform(0, 1, size=(32, 16, 3))
    uv = rng.uniform(0, 1, size=(50, 2))
    dx, dy = rng.normal(0, 0.1, size=(2, 50, 4))
    lam = tr.mip_level(dx, dy, tex.shape)
    np.testing.assert_array_equal(
        tr.sample(tex, uv, filter, ddx=dx, ddy=dy), tr.sample(tex, uv, filter, lod=lam)
    )


def test_magnified_trilinear_is_bilinear_and_huge_lod_is_the_mean(rng):
    tex = rng.uniform(0, 1, size=(16, 16, 3))
    uv = rng.uniform(0, 1, size=(100, 2))
    np.testing.assert_array_equal(
        tr.sample(tex, uv, "trilinear", lod=-1.0), tr.sample(tex, uv, "bilinear")
    )
    np.testing.assert_allclose(
        tr.sample(tex, uv, "trilinear", lod=50.0), np.broadcast_to(tex.mean((0, 1)), (100, 3))
    )


def test_a_pyramid_can_be_given_and_may_stop_early(rng):
    tex = rng.uniform(0, 1, size=(8, 8))
    levels = tr.mipmap(tex)
    uv = rng.uniform(0, 1, size=(40, 2))
    for f in TEXTURE_FILTERS[:-1]:
        kw = {} if f in ("nearest", "bilinear") else {"lod": 1.7}
        np.testing.assert_array_equal(tr.sample(levels, uv, f, **kw), tr.sample(tex, uv, f, **kw))
    # two levels only (GL_TEXTURE_MAX_LEVEL = 1): lod 5 clamps to level 1
    np.testing.assert_array_equal(
        tr.sample(levels[:2], uv, "trilinear", lod=5.0),
        tr.sample(levels, uv, "trilinear", lod=1.0),
    )


@settings(max_examples=examples(40), deadline=None)
@given(value=st.floats(-5, 5), lam=st.floats(-3, 10), filter=st.sampled_from(MIP))
def test_constant_textures_stay_constant(value, lam, filter):
    tex = np.full((6, 10), value)
    got = tr.sample(tex, [[0.3, 0.9], [-4.2, 7.1]], filter, lod=lam)
    np.testing.assert_allclose(got, value, atol=1e-12 * max(1, abs(value)))


def test_nan_uv_or_nan_lod_gives_nan(rng):
    tex = rng.uniform(0, 1, size=(8, 8, 3))
    uv = np.array([[0.5, 0.5], [np.nan, 0.5], [0.5, 0.5]])
    got = tr.sample(tex, uv, "trilinear", lod=np.array([1.0, 1.0, np.nan]))
    assert np.isfinite(got[0]).all() and np.isnan(got[1:]).all()


def read_level(levels, uv, within, level):
    """``within`` filtering of pyramid level ``level`` (n,) at ``uv`` (n, 2), via an integer
    λ (GL's nearest level of an integer λ is that level)."""
    f = "nearest_mipmap_nearest" if within == "nearest" else "linear_mipmap_nearest"
    return tr.sample(levels, uv, f, lod=np.asarray(level, dtype=float))


@pytest.mark.parametrize("filter", TEXTURE_FILTERS)
def test_levels_read_are_what_the_sampler_reads(rng, filter):
    """Per filter, the levels, weights and probes ``levels_read`` reports (what the
    FilterExplorer's level panel shows) rebuild the sampler's value exactly: level 0 for
    the unmipmapped filters, GL's nearest level, ⌊λ⌋ and ⌊λ⌋ + 1 blended by λ − ⌊λ⌋, and for
    anisotropic N probes at λ' = log2(P_max / N), finer than the pixel's λ."""
    tex = rng.uniform(0, 1, size=(32, 32, 3))
    levels = tr.mipmap(tex)
    n = 200
    uv = rng.uniform(0, 1, size=(n, 2))
    dx = rng.normal(0, 0.08, size=(n, 2))
    dy = rng.normal(0, 0.08, size=(n, 2)) * rng.uniform(0.05, 1, size=(n, 1))
    dx[:10] /= 100  # magnified footprints
    dx[-1] = np.nan  # an uncovered pixel
    read = levels_read(filter, dx, dy, tex.shape)
    assert np.isnan(read.first[-1]) and np.isnan(read.weight[-1])
    dx, dy, uv, n = dx[:-1], dy[:-1], uv[:-1], n - 1
    first, second, t = read.first[:-1], read.second[:-1], read.weight[:-1]
    lam = tr.mip_level(dx, dy, tex.shape)
    within = "bilinear" if filter in ("bilinear", "linear_mipmap_nearest", "trilinear",
                                      "anisotropic") else "nearest"  # fmt: skip
    if filter != "anisotropic":
        got = tr.sample(levels, uv, filter, ddx=dx, ddy=dy) if filter in MIPMAP_FILTERS else (
            tr.sample(tex, uv, filter))  # fmt: skip
        lo, hi = read_level(levels, uv, within, first), read_level(levels, uv, within, second)
        np.testing.assert_allclose(got, (1 - t[:, None]) * lo + t[:, None] * hi, atol=1e-12)
        assert (read.probes == 1).all()
        if filter in ("nearest", "bilinear"):
            assert (first == 0).all() and (t == 0).all()
        elif filter.endswith("mipmap_nearest"):
            assert (t == 0).all() and len(set(first.tolist())) >= 3
        else:  # blended where λ lies strictly between two levels of the pyramid
            between = (lam > 0) & (lam < len(levels) - 1) & (lam != np.floor(lam))
            assert (t[between] > 0).all() and (second[between] == first[between] + 1).all()
            np.testing.assert_array_equal(first[lam >= 0], np.floor(np.minimum(lam, 5))[lam >= 0])
        return
    px, py = np.hypot(dx[:, 0] * 32, dx[:, 1] * 32), np.hypot(dy[:, 0] * 32, dy[:, 1] * 32)
    pmax, pmin = np.maximum(px, py), np.minimum(px, py)
    probes = np.where(pmax <= 1, 1, np.minimum(np.ceil(pmax / pmin), 16)).astype(int)
    np.testing.assert_array_equal(read.probes[:-1], probes)
    np.testing.assert_allclose(read.lod[:-1], np.log2(pmax / probes), atol=1e-12)
    assert (probes > 1).sum() > 50 and (read.lod[:-1] < lam)[probes > 1].all()  # finer
    major = np.where((px >= py)[:, None], dx, dy)
    total = 0.0
    for i in range(1, probes.max() + 1):
        on = probes >= i
        at = uv + np.where(on, i / (probes + 1) - 0.5, 0)[:, None] * major
        value = (1 - t[:, None]) * read_level(levels, at, within, first) + t[:, None] * (
            read_level(levels, at, within, second))  # fmt: skip
        total = total + np.where(on[:, None], value, 0.0)
    got = tr.sample(tex, uv, "anisotropic", ddx=dx, ddy=dy)
    np.testing.assert_allclose(got, total / probes[:, None], atol=1e-12)


# -- anisotropic ------------------------------------------------------------------------------
@pytest.mark.parametrize("max_aniso", [1, 2, 4, 16])
def test_anisotropic_matches_the_ext_spec_reference(rng, max_aniso):
    tex = rng.uniform(0, 1, size=(32, 32, 3))
    levels = tr.mipmap(tex)
    uv = rng.uniform(0, 1, size=(120, 2))
    dx = rng.normal(0, 0.05, size=(120, 2))
    dx[:10] /= 100  # some magnified footprints too
    dy = rng.normal(0, 0.05, size=(120, 2)) * rng.uniform(0.01, 1, size=(120, 1))
    got = tr.sample(tex, uv, "anisotropic", ddx=dx, ddy=dy, max_anisotropy=max_aniso)
    want = np.array([ref_aniso(levels, u, v, a, b, max_aniso) for (u, v), a, b in zip(uv, dx, dy)])
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)


def test_isotropic_footprints_make_anisotropic_trilinear(rng):
    tex = rng.uniform(0, 1, size=(16, 16))
    uv = rng.uniform(0, 1, size=(60, 2))
    scale = rng.uniform(0.01, 0.5, size=(60, 1))
    dx, dy = scale * np.array([1.0, 0.0]), scale * np.array([0.0, 1.0])
    np.testing.assert_allclose(
        tr.sample(tex, uv, "anisotropic", ddx=dx, ddy=dy),
        tr.sample(tex, uv, "trilinear", ddx=dx, ddy=dy),
        atol=1e-14,
    )


def test_anisotropic_keeps_stripes_along_the_footprint_trilinear_greys_them():
    # Horizontal stripes one texel tall; a footprint 8 texels long along u (the stripes) and
    # 1 texel across them. The true footprint average at a row centre is that row's value:
    # anisotropic keeps it (8 probes at level 0), trilinear blurs to level 3: grey.
    tex = np.repeat(np.array([[0.0], [1.0]] * 32), 64, axis=1)  # 64 x 64, rows 0 1 0 1 ...
    uv = np.array([[0.5, 4.5 / 64], [0.5, 5.5 / 64]])
    dx, dy = np.array([[8 / 64, 0.0]] * 2), np.array([[0.0, 1 / 64]] * 2)
    aniso = tr.sample(tex, uv, "anisotropic", ddx=dx, ddy=dy, max_anisotropy=8)
    np.testing.assert_allclose(aniso, [0.0, 1.0], atol=1e-12)
    tri = tr.sample(tex, uv, "trilinear", ddx=dx, ddy=dy)
    np.testing.assert_allclose(tri, [0.5, 0.5], atol=1e-12)
    # capped at 2 probes, the probes sit at level log2(8 / 2) = 2: grey again
    capped = tr.sample(tex, uv, "anisotropic", ddx=dx, ddy=dy, max_anisotropy=2)
    np.testing.assert_allclose(capped, [0.5, 0.5], atol=1e-12)


# -- bad input --------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "args, kwargs, match",
    [
        ((np.zeros(4), [[0.5, 0.5]]), {"filter": "trilinear", "lod": 0.0}, "texture"),
        ((np.zeros((2, 2, 2, 2)), [[0.5, 0.5]]), {"filter": "trilinear", "lod": 0.0}, "texture"),
        (([["a", "b"], ["c", "d"]], [[0.5, 0.5]]), {}, "texture"),
        (({"x": 1}, [[0.5, 0.5]]), {}, "texture"),
        ((np.full((2, 2), np.nan), [[0.5, 0.5]]), {"filter": "trilinear", "lod": 0.0}, "texture"),
        ((np.zeros((4, 4)), [[0.5, 0.5]]), {"filter": "bicubic"}, "filter"),
        ((np.zeros((4, 4)), [[0.5, 0.5]]), {"filter": "trilinear"}, "lod"),
        ((np.zeros((4, 4)), [[0.5, 0.5]]), {"filter": "anisotropic", "lod": 1.0}, "ddx"),
        ((np.zeros((4, 4)), [[0.5, 0.5]]), {"filter": "nearest", "lod": 1.0}, "lod"),
        (
            (np.zeros((4, 4)), [[0.5, 0.5]]),
            {"filter": "anisotropic", "ddx": [[1, 0]], "ddy": [[0, 1]], "max_anisotropy": 0},
            "max_anisotropy",
        ),
        (
            (np.zeros((4, 4)), [[0.5, 0.5]]),
            {"filter": "anisotropic", "ddx": [[1, 0]], "ddy": [[0, 1]], "max_anisotropy": -2},
            "max_anisotropy",
        ),
        (
            (np.zeros((4, 4)), [[0.5, 0.5]]),
            {"filter": "trilinear", "ddx": [[1, 0]], "ddy": [[0, 1]], "max_anisotropy": "x"},
            "max_anisotropy",
        ),
        (
            (np.zeros((4, 4)), [[0.5, 0.5]]),
            {"filter": "trilinear", "ddx": [[1]], "ddy": [[1]]},
            "ddx",
        ),
        (([np.zeros((4, 4)), np.zeros((3, 2))], [[0.5, 0.5]]), {}, r"texture\[1\]"),
        (([np.zeros((4, 4)), np.full((2, 2), np.nan)], [[0.5, 0.5]]), {}, r"texture\[1\]"),
    ],
)
def test_bad_input_is_a_value_error_naming_the_argument(args, kwargs, match):
    with pytest.raises(ValueError, match=match):
        tr.sample(*args, **kwargs)


@pytest.mark.parametrize(
    "bad", [np.zeros(3), np.zeros((2, 2, 2, 2)), [["a"]], np.full((2, 2), np.nan)]
)
def test_mipmap_refuses_bad_textures(bad):
    with pytest.raises(ValueError, match="texture"):
        tr.mipmap(bad)


def test_mip_level_refuses_bad_shapes():
    with pytest.raises(ValueError, match="texture_shape"):
        tr.mip_level([0.1, 0.1], [0.1, 0.1], (4,))
    with pytest.raises(ValueError, match="ddx"):
        tr.mip_level([0.1], [0.1], (4, 4))


def test_probe_count_ignores_rounding_on_a_face_on_square():
    """Review r92 09-2: a face-on square's footprints are square only to ~15 digits
    (P_max / P_min = 1 + 8e-15 on half its pixels); the ceiling must give 1 probe there, so
    that anisotropic equals trilinear, while a ratio of exactly 2 (and a millionth over 1)
    still gives 2."""
    from teachraster.pipeline.texturing.texture_filters import anisotropic_probes
    from teachraster.widgets.textured import CORNER_UV, TRIANGLES, plane_clip

    camera = tr.Camera(eye=(0.0, 0.0, 0.0), target=(0.0, 0.0, -1.0), fov_y=60.0)
    uv = np.broadcast_to(CORNER_UV[TRIANGLES] * 6, (2, 3, 2))
    frame = tr.render(plane_clip(0.0, camera, 4 / 3), 160, 120, attrs=uv, derivatives=True)
    cov = frame.coverage
    dx, dy = frame.ddx[..., :2][cov], frame.ddy[..., :2][cov]
    n, lam, _ = anisotropic_probes(dx, dy, 64, 64, 16)
    px, py = np.hypot(*(dx * 64).T), np.hypot(*(dy * 64).T)
    assert (np.maximum(px, py) / np.minimum(px, py) > 1).any()  # the rounding is there
    assert (n == 1).all() and (lam > 0).all()  # minified, yet one probe at every pixel
    tex = np.random.default_rng(3).uniform(size=(64, 64))
    np.testing.assert_array_equal(
        tr.sample(tex, frame.attrs[cov], "anisotropic", ddx=dx, ddy=dy),
        tr.sample(tex, frame.attrs[cov], "trilinear", ddx=dx, ddy=dy),
    )
    two = anisotropic_probes(
        np.array([[4 / 64, 0.0], [4 / 64, 0.0]]),
        np.array([[0.0, 2 / 64], [0.0, 4 / 64 / (1 + 1e-6)]]),
        64,
        64,
        16,
    )
    assert two[0].tolist() == [2, 2]  # exactly 2, and 1 + 1e-6


def test_a_magnified_footprint_draws_the_2x2_texels_bilinear_reads():
    """r95 09-4: the footprint figure drew a magnified pixel's 0.54-texel ρ square as what
    trilinear reads; it reads the 2 × 2 texels of one bilinear read of level 0. The figure
    takes them from the sampler's own corner (``bilinear_corner``) and draws them dashed; a
    minified footprint keeps its square of side ρ."""
    import matplotlib

    matplotlib.use("agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    from teachraster.pipeline.texturing.texel_fetch import bilinear_corner
    from teachraster.plotting.footprint import footprint, plot_footprint, trilinear_reads

    uv, ddx, ddy = np.array([0.3, 0.6]), np.array([0.3 / 64, 0]), np.array([0, 0.5 / 64])
    fp = footprint(uv, ddx, ddy, (64, 64))
    assert fp.lam < 0 and fp.probes == 1
    x0, y0, _, _ = bilinear_corner(uv[:1], uv[1:], 64, 64)
    assert fp.bilinear.tolist() == [x0[0], y0[0]]
    # exactly the texels trilinear fetches (the texel centres of the 2 x 2 block), no other
    for dx in (-0.5, 0.5, 1.5, 2.5):
        for dy in (-0.5, 0.5, 1.5, 2.5):
            point = fp.bilinear + [dx, dy]
            inside = 0 < dx < 2 and 0 < dy < 2
            assert trilinear_reads(uv[None], ddx[None], ddy[None], (64, 64), point)[0] == inside
    fig, ax = plt.subplots()
    art = plot_footprint(ax, fp)
    square = art["square"]
    # review r336 S4: the one probe's dot, at the pixel's centre, over the ellipse and square
    np.testing.assert_allclose(art["dots"].get_xydata(), [[0.0, 0.0]])
    assert art["dots"].get_zorder() > max(art["ellipse"].get_zorder(), square.get_zorder())
    assert isinstance(square, Rectangle) and square.get_linestyle() == "--"
    assert (square.get_width(), square.get_height()) == (2.0, 2.0)
    np.testing.assert_allclose(square.get_xy(), fp.bilinear - fp.centre)
    lo, hi = sorted(ax.get_xlim()), sorted(ax.get_ylim())  # the whole block is in view
    assert lo[0] <= square.get_x() and square.get_x() + 2 <= lo[1]
    assert hi[0] <= square.get_y() and square.get_y() + 2 <= hi[1]
    minified = footprint(uv, 8 * ddx, 8 * ddy, (64, 64))
    assert minified.bilinear is None and minified.lam > 0
    square = plot_footprint(ax, minified)["square"]
    assert square.get_linestyle() == "-" and square.get_width() == pytest.approx(minified.rho)
    plt.close(fig)
