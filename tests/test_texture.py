"""Textures: checkerboard, nearest / bilinear sampling, wrapping, NaN, texel error."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import examples
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr
from teachraster.pipeline.texture import FILTERS, WRAPS, checkerboard, sample, texel_error


def centres(h: int, w: int) -> np.ndarray:
    """(h, w, 2) uv of every texel centre, ((c + 0.5)/W, (r + 0.5)/H)."""
    r, c = np.mgrid[0:h, 0:w]
    return np.stack([(c + 0.5) / w, (r + 0.5) / h], axis=-1)


@pytest.fixture
def tex(rng):
    return rng.uniform(0, 1, size=(5, 7, 3))


# -- checkerboard -----------------------------------------------------------------------------
def test_checkerboard_default_shape_and_colours():
    board = checkerboard()
    light, dark = np.array((0.92, 0.92, 0.92)), np.array((0.15, 0.2, 0.35))
    assert board.shape == (64, 64, 3) and board.dtype == np.float64
    assert ((board >= 0) & (board <= 1)).all()
    np.testing.assert_array_equal(board[0, 0], light)  # colors[0] is the top-left square
    np.testing.assert_array_equal(board[0, 8], dark)  # 64 / 8 = 8 texels per square
    np.testing.assert_array_equal(board[8, 0], dark)
    np.testing.assert_array_equal(board[8, 8], light)
    np.testing.assert_array_equal(board[7, 7], light)
    is_light = (board == light).all(axis=-1)
    assert ((board == dark).all(axis=-1) | is_light).all()  # only the two colours
    assert is_light.sum() == 64 * 64 // 2


@pytest.mark.parametrize("checks, texels", [(1, 1), (3, 10), (7, 7), (8, 64), (5, 64)])
def test_checkerboard_squares_alternate(checks, texels):
    board = checkerboard(checks=checks, texels=texels, colors=([1.0], [0.0]))[..., 0]
    assert board.shape == (texels, texels)
    # Walking along a row or column, the colour changes exactly checks - 1 times.
    assert (np.diff(board[0]) != 0).sum() == checks - 1
    assert (np.diff(board[:, -1]) != 0).sum() == checks - 1
    # Each square is uniform: the board is an outer "xor" of one row and one column.
    row, col = board[0], board[:, 0]
    np.testing.assert_array_equal(board, (row[None, :] == col[:, None]).astype(float))


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"checks": 0}, "checks"),
        ({"checks": 9, "texels": 8}, "checks"),
        ({"checks": 2.0}, "checks"),
        ({"texels": 0}, "texels"),
        ({"colors": ((1, 1, 1),)}, "colors"),
        ({"colors": ((1, 1, 1), (0, 0, 2))}, "colors"),
        ({"colors": "ab"}, "colors"),
    ],
)
def test_checkerboard_validation(kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        checkerboard(**kwargs)


# -- nearest ----------------------------------------------------------------------------------
@pytest.mark.parametrize("wrap", WRAPS)
def test_nearest_at_centres_returns_texels_exactly(tex, wrap):
    np.testing.assert_array_equal(sample(tex, centres(5, 7), wrap=wrap), tex)
    np.testing.assert_array_equal(sample(tex[..., 1], centres(5, 7), wrap=wrap), tex[..., 1])


def test_nearest_matches_square_containment(rng, tex):
    """Independent reference: the texel whose square [c/W, (c+1)/W) holds u (and likewise v)."""
    uv = rng.uniform(0, 1, size=(500, 2))
    got = sample(tex, uv)
    for (u, v), value in zip(uv, got):
        c = next(c for c in range(7) if c / 7 <= u < (c + 1) / 7)
        r = next(r for r in range(5) if r / 5 <= v < (r + 1) / 5)
        np.testing.assert_array_equal(value, tex[r, c])


# -- bilinear ---------------------------------------------------------------------------------
@pytest.mark.parametrize("wrap", WRAPS)
def test_bilinear_at_centres_equals_nearest(rng, tex, wrap):
    # Power-of-two sizes: texel centres are exact binary fractions, so equality is exact.
    tex8 = rng.uniform(0, 1, size=(4, 8, 2))
    uv = centres(4, 8)
    np.testing.assert_array_equal(
        sample(tex8, uv, "bilinear", wrap), sample(tex8, uv, "nearest", wrap)
    )
    # Other sizes: (c + 0.5)/W * W - 0.5 may miss c by an ulp, so equal to rounding.
    uv = centres(5, 7)
    np.testing.assert_allclose(sample(tex, uv, "bilinear", wrap), tex, rtol=0, atol=1e-14)


def test_bilinear_halfway_is_the_mean(tex):
    h, w = 5, 7
    r, c = np.mgrid[0 : h - 1, 0 : w - 1]
    across = np.stack([(c + 1.0) / w, (r + 0.5) / h], axis=-1)  # between (r, c) and (r, c+1)
    down = np.stack([(c + 0.5) / w, (r + 1.0) / h], axis=-1)  # between (r, c) and (r+1, c)
    corner = np.stack([(c + 1.0) / w, (r + 1.0) / h], axis=-1)  # among the four
    a, b, d, e = tex[:-1, :-1], tex[:-1, 1:], tex[1:, :-1], tex[1:, 1:]
    for wrap in WRAPS:
        np.testing.assert_allclose(sample(tex, across, "bilinear", wrap), (a + b) / 2, atol=1e-14)
        np.testing.assert_allclose(sample(tex, down, "bilinear", wrap), (a + d) / 2, atol=1e-14)
        np.testing.assert_allclose(
            sample(tex, corner, "bilinear", wrap), (a + b + d + e) / 4, atol=1e-14
        )


def test_bilinear_reproduces_a_linear_ramp(rng):
    """Bilinear filtering is exact on functions linear in the texel index (between centres)."""
    h, w = 6, 9
    r, c = np.mgrid[0:h, 0:w]
    ramp = 2.0 * c - 3.0 * r + 1.0
    u = rng.uniform(0.5 / w, 1 - 0.5 / w, 400)
    v = rng.uniform(0.5 / h, 1 - 0.5 / h, 400)
    got = sample(ramp, np.stack([u, v], axis=-1), "bilinear", "clamp")
    np.testing.assert_allclose(got, 2.0 * (u * w - 0.5) - 3.0 * (v * h - 0.5) + 1.0, atol=1e-12)


def test_bilinear_border_repeat_blends_opposite_edge_clamp_does_not():
    tex = np.array([[0.0, 10.0, 20.0, 30.0]])
    uv = [[0.0, 0.5], [1.0, 0.5]]  # on the left and right image borders
    np.testing.assert_array_equal(sample(tex, uv, "bilinear", "repeat"), [15.0, 15.0])
    np.testing.assert_array_equal(sample(tex, uv, "bilinear", "clamp"), [0.0, 30.0])


# -- wrapping ---------------------------------------------------------------------------------
@pytest.mark.parametrize("filter", FILTERS)
def test_repeat_wraps_by_whole_periods(rng, filter):
    tex = rng.uniform(0, 1, size=(4, 8, 3))
    uv = rng.integers(0, 1024, size=(300, 2)) / 1024  # binary fractions: uv + k is exact
    base = sample(tex, uv, filter)
    for shift in ([1, 0], [0, 1], [-1, 0], [3, -2], [-7, 5]):
        np.testing.assert_array_equal(sample(tex, uv + shift, filter), base)


def test_clamp_clamps():
    tex = np.arange(12.0).reshape(3, 4)
    # 0.625 and 0.5 are the centres of column 2 and row 1, so bilinear blends nothing there.
    uv = [[-0.3, 0.5], [1.7, 0.5], [0.625, -5.0], [0.625, 9.0], [-1.0, -1.0], [2.0, 2.0]]
    want = [tex[1, 0], tex[1, 3], tex[0, 2], tex[2, 2], tex[0, 0], tex[2, 3]]
    for filter in FILTERS:
        np.testing.assert_array_equal(sample(tex, uv, filter, "clamp"), want)
    # Repeat, by contrast, wraps u = 1.7 around to 0.7: column 2.
    assert sample(tex, [[1.7, 0.5]], "nearest", "repeat")[0] == tex[1, 2]
    assert sample(tex, [[1.625, 0.5]], "bilinear", "repeat")[0] == tex[1, 2]


# -- NaN, constants, shapes -------------------------------------------------------------------
@pytest.mark.parametrize("filter", FILTERS)
@pytest.mark.parametrize("wrap", WRAPS)
def test_nan_propagates(tex, filter, wrap):
    uv = np.full((3, 4, 2), 0.4)
    uv[0, 0] = np.nan
    uv[1, 2, 0] = np.nan  # only u missing
    uv[2, 3, 1] = np.nan  # only v missing
    got = sample(tex, uv, filter, wrap)
    assert got.shape == (3, 4, 3)
    missing = np.zeros((3, 4), dtype=bool)
    missing[0, 0] = missing[1, 2] = missing[2, 3] = True
    assert np.isnan(got[missing]).all()
    assert np.isfinite(got[~missing]).all()
    assert np.isnan(sample(tex, np.full((2, 2), np.nan), filter, wrap)).all()


@settings(max_examples=examples(60), deadline=None)
@given(
    uv=st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50)), min_size=1, max_size=20).map(
        np.array
    ),
    filter=st.sampled_from(FILTERS),
    wrap=st.sampled_from(WRAPS),
)
def test_constant_texture_samples_constant(uv, filter, wrap):
    colour = np.array([0.1, 0.37, 0.9])
    tex = np.broadcast_to(colour, (3, 5, 3))
    got = sample(tex, uv, filter, wrap)
    np.testing.assert_array_equal(got, np.broadcast_to(colour, got.shape))  # exactly


def test_shapes(tex):
    uv = np.zeros((4, 6, 2))
    assert sample(tex, uv).shape == (4, 6, 3)
    assert sample(tex[..., 0], uv).shape == (4, 6)
    assert sample(tex, [0.5, 0.5]).shape == (3,)
    assert sample(tex, np.zeros((0, 2))).shape == (0, 3)
    assert sample(np.ones((1, 1)), uv, "bilinear").shape == (4, 6)  # a single texel works


@pytest.mark.parametrize(
    "args, kwargs, match",
    [
        ((np.zeros(4), [[0.5, 0.5]]), {}, "texture"),
        ((np.zeros((2, 2, 2, 2)), [[0.5, 0.5]]), {}, "texture"),
        ((np.zeros((0, 2)), [[0.5, 0.5]]), {}, "texture"),
        ((np.full((2, 2), np.nan), [[0.5, 0.5]]), {}, "texture"),
        ((np.zeros((2, 2)), [[0.5, 0.5, 0.5]]), {}, "uv"),
        ((np.zeros((2, 2)), [[np.inf, 0.5]]), {}, "uv"),
        ((np.zeros((2, 2)), "uv"), {}, "uv"),
        ((np.zeros((2, 2)), [[0.5, 0.5]]), {"filter": "bicubic"}, "filter"),
        ((np.zeros((2, 2)), [[0.5, 0.5]]), {"wrap": "mirror"}, "wrap"),
    ],
)
def test_sample_validation(args, kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        sample(*args, **kwargs)


# -- texel error ------------------------------------------------------------------------------
def test_texel_error_measures_in_texels():
    # u differs by 1/4 of a 4-wide texture: 1 texel; v by 1/8 of an 8-high texture: 1 texel;
    # the third pair is 1 texel across and 3 down.
    a = np.array([[0.5, 0.5], [0.5, 0.5], [0.25, 0.25], [np.nan, 0.0]])
    b = np.array([[0.75, 0.5], [0.5, 0.625], [0.5, 0.625], [0.0, 0.0]])
    got = texel_error(a, b, (8, 4))
    np.testing.assert_allclose(got[:3], [1.0, 1.0, np.sqrt(10.0)], rtol=1e-15)
    assert np.isnan(got[3])
    assert texel_error(a, b, (8, 4, 3)).shape == (4,)  # a texture.shape with channels works
    np.testing.assert_array_equal(texel_error(a[:3], a[:3], (8, 4)), 0.0)
    assert texel_error(np.zeros((2, 3, 2)), [0.5, 0.0], (2, 2)).shape == (2, 3)  # broadcasts


@pytest.mark.parametrize(
    "args, match",
    [
        (([[0, 0]], [[0, 0, 0]], (2, 2)), "uv_b"),
        (([0], [[0, 0]], (2, 2)), "uv_a"),
        ((np.zeros((3, 2)), np.zeros((2, 2)), (2, 2)), "broadcast"),
        (([[0, 0]], [[0, 0]], (2,)), "shape"),
        (([[0, 0]], [[0, 0]], (0, 2)), "shape"),
        (([[0, 0]], [[0, 0]], 4), "shape"),
    ],
)
def test_texel_error_validation(args, match):
    with pytest.raises(ValueError, match=match):
        texel_error(*args)


def test_affine_warp_is_visible_in_texels():
    """A floor receding in depth: affine uv lands texels away from perspective-correct uv."""
    tex = checkerboard()
    tri = tr.Triangle(
        [[2, 30], [30, 30], [16, 2]], w=[1.0, 1.0, 8.0], attrs={"uv": [[0, 1], [1, 1], [0.5, 0]]}
    )
    persp = tr.rasterize(tri, 32, 32, interpolation="perspective").attrs["uv"]
    affine = tr.rasterize(tri, 32, 32, interpolation="affine").attrs["uv"]
    err = texel_error(persp, affine, tex.shape)
    covered = ~np.isnan(persp[..., 0])
    assert np.isnan(err[~covered]).all()
    assert np.nanmax(err) > 5  # many texels off: the well-known warp
    differs = (sample(tex, persp) != sample(tex, affine)).any(axis=-1)
    assert differs[covered].any()
