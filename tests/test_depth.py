"""Depth mappings, depth-buffer formats, resolution and z-fighting (Ritschel, *Interpolation and z-buffering*)."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from conftest import examples
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr
from teachraster.pipeline.depth import (
    DEPTH_FORMATS,
    depth_resolution,
    fights,
    linear_depth,
    quantize,
    seed_depth,
    window_depth,
)
from teachraster.pipeline.viewport import to_window

UNORM = {"unorm24": 24, "unorm16": 16}

planes = st.tuples(st.floats(1e-3, 10.0), st.floats(1.01, 1e5)).map(
    lambda nf: (nf[0], nf[0] * nf[1])
)  # (near, far) with far > near


def gl_frustum(l, r, b, t, n, f) -> np.ndarray:
    """The glFrustum matrix (OpenGL 2.1 reference page), written out independently."""
    return np.array(
        [
            [2 * n / (r - l), 0, (r + l) / (r - l), 0],
            [0, 2 * n / (t - b), (t + b) / (t - b), 0],
            [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)],
            [0, 0, -1, 0],
        ]
    )


# -- mappings ---------------------------------------------------------------------------------
@settings(max_examples=examples(200), deadline=None)
@given(nf=planes)
def test_window_depth_endpoints_exact(nf):
    near, far = nf
    assert window_depth(near, near, far) == 0.0
    assert window_depth(far, near, far) == 1.0


@settings(max_examples=examples(100), deadline=None)
@given(nf=planes, seed=st.integers(0, 2**32 - 1))
def test_window_depth_monotonic_even_in_floating_point(nf, seed):
    near, far = nf
    rng = np.random.default_rng(seed)
    z = np.sort(np.concatenate([rng.uniform(near, far, 500), near * (1 + np.arange(20) * 1e-15)]))
    d = window_depth(z, near, far)
    assert (np.diff(d) >= 0).all()  # rounding never reverses depth order
    assert ((d >= 0) & (d <= 1)).all()
    spread = np.geomspace(near, far, 50)  # well-separated distances: strictly increasing
    assert (np.diff(window_depth(spread, near, far)) > 0).all()


@pytest.mark.parametrize("near, far", [(0.1, 1000.0), (0.5, 2.0), (1.0, 100.0), (0.01, 50.0)])
def test_window_depth_matches_opengl_projection(rng, near, far):
    """Project through rows 3 and 4 of glFrustum, divide by w, apply the viewport's z/2 + 1/2."""
    proj = gl_frustum(-0.7, 0.4, -0.3, 0.5, near, far)
    z = np.concatenate([[near, far], rng.uniform(near, far, 1000), np.geomspace(near, far, 100)])
    eye = np.stack([rng.uniform(-5, 5, z.size), rng.uniform(-5, 5, z.size), -z, np.ones_like(z)])
    clip = (proj @ eye).T  # the camera looks down -z: a point at distance z has z_eye = -z
    np.testing.assert_allclose(clip[:, 3], z)  # clip w is the view distance
    want = (clip[:, 2] / clip[:, 3]) / 2 + 0.5
    np.testing.assert_allclose(window_depth(z, near, far), want, rtol=1e-12, atol=1e-12)
    # ... and the package's own viewport transform (CONVENTIONS) agrees.
    np.testing.assert_allclose(window_depth(z, near, far), to_window(clip, 4, 4)[:, 2], atol=1e-12)


def test_window_depth_outside_the_frustum_and_nan():
    near, far = 0.5, 10.0
    assert window_depth(0.25, near, far) < 0  # in front of the near plane: clipped away
    assert window_depth(20.0, near, far) > 1
    assert window_depth(np.inf, near, far) == pytest.approx(far / (far - near))
    assert np.isnan(window_depth([np.nan, 1.0], near, far)).tolist() == [True, False]


@settings(max_examples=examples(200), deadline=None)
@given(nf=planes, t=st.floats(0, 1))
def test_seed_depth_is_the_seed_formula(nf, t):
    near, far = nf
    z = near + t * (far - near)
    got = seed_depth(z, near, far)
    assert got == pytest.approx(near + far - far * near / z, rel=1e-12, abs=1e-12 * far)
    # The seed's z' and GL's window depth are the same hyperbola, rescaled.
    assert window_depth(z, near, far) == pytest.approx(
        (got - near) / (far - near), rel=1e-9, abs=1e-12
    )


@pytest.mark.parametrize("near, far", [(0.1, 1000.0), (0.5, 2.0), (1.0, 100.0), (3.0, 7.0)])
def test_seed_depth_maps_near_to_near_far_to_far_monotonically(near, far):
    assert seed_depth(near, near, far) == near
    assert seed_depth(far, near, far) == far
    z = np.linspace(near, far, 10001)
    assert (np.diff(seed_depth(z, near, far)) >= 0).all()


def test_linear_depth():
    np.testing.assert_array_equal(linear_depth([2.0, 3.0, 6.0], 2.0, 6.0), [0.0, 0.25, 1.0])
    np.testing.assert_array_equal(linear_depth([0.0, 5.0], -5.0, 5.0), [0.5, 1.0])  # ortho
    z = np.linspace(0.1, 1000, 1001)
    np.testing.assert_allclose(np.diff(linear_depth(z, 0.1, 1000.0)), 1 / 1000, rtol=1e-9)


# -- quantize ---------------------------------------------------------------------------------
depths = st.lists(st.floats(0, 1), min_size=1, max_size=50).map(np.array)


@settings(max_examples=examples(200), deadline=None)
@given(d=depths, fmt=st.sampled_from(DEPTH_FORMATS))
def test_quantize_is_idempotent(d, fmt):
    q = quantize(d, fmt)
    assert q.dtype == np.float64 and q.shape == d.shape
    np.testing.assert_array_equal(quantize(q, fmt), q)


@pytest.mark.parametrize("fmt, bits", UNORM.items())
def test_quantize_exact_on_representable_unorm_values(rng, fmt, bits):
    scale = 2**bits - 1
    k = np.concatenate([[0, 1, scale - 1, scale], rng.integers(0, scale + 1, 10000)])
    values = k / scale
    np.testing.assert_array_equal(quantize(values, fmt), values)
    np.testing.assert_array_equal(quantize(values, fmt) * scale, k)  # integers read back


def test_quantize_exact_on_float32_values(rng):
    values = rng.uniform(0, 1, 10000).astype(np.float32).astype(np.float64)
    np.testing.assert_array_equal(quantize(values, "float32"), values)
    d = rng.uniform(0, 1, 10000)
    np.testing.assert_array_equal(quantize(d, "float32"), d.astype(np.float32))
    np.testing.assert_array_equal(quantize(d, "float64"), d)


@pytest.mark.parametrize("fmt, bits", UNORM.items())
def test_quantize_unorm_error_at_most_half_a_step(rng, fmt, bits):
    step = 1 / (2**bits - 1)
    d = np.concatenate([rng.uniform(0, 1, 100000), np.linspace(0, 1, 1001)])
    err = np.abs(quantize(d, fmt) - d)
    assert err.max() <= step / 2 * (1 + 1e-9)
    assert err.max() > step / 2 * 0.99  # and really quantises (the bound is attained)


@pytest.mark.parametrize("fmt, bits", UNORM.items())
def test_quantize_unorm_rounds_to_nearest_integer_exactly(rng, fmt, bits):
    """Independent check in exact rational arithmetic (ties are measure-zero for random d)."""
    scale = 2**bits - 1
    for d in rng.uniform(0, 1, 300):
        k = round(Fraction(float(d)) * scale)
        assert quantize(d, fmt) == k / scale


def test_quantize_nan_clamp_copy_and_errors():
    for fmt in DEPTH_FORMATS:
        q = quantize([np.nan, 0.5], fmt)
        assert np.isnan(q[0]) and not np.isnan(q[1])
    np.testing.assert_array_equal(quantize([-0.2, 1.3], "unorm16"), [0.0, 1.0])  # unorm clamps
    d = np.array([0.25, 0.5])
    q = quantize(d, "float64")
    q[0] = 9.0
    assert d[0] == 0.25  # a new array, never a view of the input
    assert quantize(0.5, "float32").shape == ()
    for bad in ("unorm8", "float16", None, "UNORM16"):
        with pytest.raises(ValueError, match="depth_format"):
            quantize([0.5], bad)


# -- resolution -------------------------------------------------------------------------------
@pytest.mark.parametrize("fmt", ["unorm24", "unorm16"])
def test_resolution_grows_as_z_squared_for_unorm(fmt):
    near, far = 0.1, 1000.0
    z = np.geomspace(1.0, 400.0, 30)
    ratio = depth_resolution(2 * z, near, far, fmt) / depth_resolution(z, near, far, fmt)
    np.testing.assert_allclose(ratio, 4.0, rtol=1e-12)


def test_resolution_grows_roughly_as_z_squared_for_float32():
    near, far = 0.1, 1000.0
    z = np.geomspace(1.0, 400.0, 30)
    res = depth_resolution(z, near, far, "float32")
    assert (np.diff(res) > 0).all()
    ratio = depth_resolution(2 * z, near, far, "float32") / res
    assert ((ratio >= 2) & (ratio <= 8)).all()  # z**2 times float32's power-of-two steps
    # Far away float32 stores depth near 1 with step 2**-24, like unorm24 (2**24 - 1 steps).
    np.testing.assert_allclose(res[-1], depth_resolution(400.0, near, far, "unorm24"), rtol=1e-6)


def test_float32_resolution_at_the_far_plane_is_the_step_below_one():
    """Depth 1 has no float32 neighbour inside [0, 1] above it: the step is 2**-24, as unorm24's.

    A gap of 0.9 at the far plane (below the 2**-23 step's 1.19) never fights, as `fights` says.
    """
    near, far = 0.1, 1000.0
    res = depth_resolution([far, far - 1e-4], near, far, "float32")
    np.testing.assert_allclose(res, depth_resolution(far, near, far, "unorm24"), rtol=1e-6)
    z = np.linspace(far - 1.0, far, 2001)
    assert not fights(z - 0.9, z, near, far, "float32").any()
    assert fights(z - res[0] / 4, z, near, far, "float32").mean() > 0.5


def test_resolution_counts_the_distinct_stored_values():
    """About (interval length) / resolution distinct depths are stored across a short interval."""
    near, far = 0.1, 1000.0
    for fmt in ("unorm16", "unorm24", "float32"):
        for z0 in (2.0, 30.0, 500.0):
            res = float(depth_resolution(z0, near, far, fmt))
            if 40 * res > 0.05 * z0:
                continue  # the resolution would change too much across the interval
            z = np.linspace(z0 - 20 * res, z0 + 20 * res, 20001)
            distinct = np.unique(quantize(window_depth(z, near, far), fmt)).size
            assert 38 <= distinct <= 42, (fmt, z0, distinct)


@pytest.mark.parametrize("fmt, bits", UNORM.items())
def test_linear_mapping_has_constant_resolution(fmt, bits):
    near, far = 0.1, 1000.0
    res = depth_resolution(np.linspace(near, far, 100), near, far, fmt, mapping="linear")
    np.testing.assert_allclose(res, (far - near) / (2**bits - 1), rtol=1e-12)
    assert np.ptp(res) == 0.0


# -- fighting ---------------------------------------------------------------------------------
def test_half_a_unit_fights_far_away_but_not_close_up():
    near, far = 0.1, 1000.0
    assert fights(500.0, 500.5, near, far, "unorm16")
    assert not fights(2.0, 2.5, near, far, "unorm16")
    # More bits, or a linear depth, separate them at 500 too.
    assert not fights(500.0, 500.5, near, far, "unorm16", mapping="linear")
    assert not fights(500.0, 500.5, near, far, "float64")


def test_fights_follows_the_resolution(rng):
    near, far = 0.1, 1000.0
    for fmt in ("unorm16", "unorm24", "float32"):
        z = rng.uniform(1.0, 900.0, 2000)
        res = depth_resolution(z, near, far, fmt)
        assert not fights(z, z + 3 * res, near, far, fmt).any()  # always a step apart
        assert fights(z, z + res / 20, near, far, fmt).mean() > 0.85  # mostly the same step


def test_fights_ties_nan_and_broadcasting():
    near, far = 0.1, 1000.0
    got = fights([[500.0], [2.0]], [500.0, 500.5, np.nan], near, far, "unorm16")
    assert got.shape == (2, 3) and got.dtype == bool
    assert got.tolist() == [[False, True, False], [False, False, False]]


# -- validation -------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: window_depth(1.0, 0.0, 10.0), "near"),
        (lambda: window_depth(1.0, -1.0, 10.0), "near"),
        (lambda: window_depth(1.0, 1.0, 1.0), "far"),
        (lambda: window_depth(1.0, np.nan, 10.0), "near"),
        (lambda: window_depth(1.0, 1.0, np.inf), "far"),
        (lambda: window_depth(1.0, "a", 10.0), "near"),
        (lambda: window_depth([1.0, -2.0], 0.5, 10.0), "z_view"),
        (lambda: window_depth(0.0, 0.5, 10.0), "z_view"),
        (lambda: seed_depth(-1.0, 0.5, 10.0), "z"),
        (lambda: linear_depth(1.0, 5.0, 2.0), "far"),
        (lambda: depth_resolution(1.0, 0.5, 10.0, "unorm12"), "depth_format"),
        (lambda: depth_resolution(1.0, 0.5, 10.0, "unorm16", mapping="log"), "mapping"),
        (lambda: depth_resolution(1.0, 0.0, 10.0, "unorm16"), "near"),
        (lambda: fights(1.0, 2.0, 0.5, 10.0, "half"), "depth_format"),
        (lambda: fights(np.ones(3), np.ones(2), 0.5, 10.0, "unorm16"), "z_a and z_b"),
        (lambda: fights(-1.0, 2.0, 0.5, 10.0, "unorm16"), "z_a"),
    ],
)
def test_validation_names_the_argument(call, match):
    with pytest.raises((ValueError, TypeError), match=match):
        call()


def test_linear_mapping_allows_an_orthographic_near_plane():
    assert linear_depth(0.0, 0.0, 10.0) == 0.0
    assert depth_resolution(-1.0, -2.0, 10.0, "unorm16", mapping="linear") > 0
    assert not fights(-1.0, 1.0, -2.0, 10.0, "unorm16", mapping="linear")


# -- reverse-Z and depth bias (lesson 05b) -----------------------------------------------------
def test_reversed_depth_is_one_minus_window_depth_without_the_cancellation():
    from teachraster.pipeline.depth import reversed_depth

    z = np.geomspace(0.1, 1000.0, 50)
    rev = reversed_depth(z, 0.1, 1000.0)
    assert np.allclose(rev, 1 - tr.window_depth(z, 0.1, 1000.0), atol=1e-12)
    assert rev[0] == 1.0 and rev[-1] == 0.0 and (np.diff(rev) < 0).all()
    # far away the small value keeps its relative precision, which 1 - d loses
    exact = (0.1 / 900.0 - 0.1 / 1000.0) / (1 - 0.1 / 1000.0)
    assert abs(reversed_depth(900.0, 0.1, 1000.0) - exact) < 1e-16 * exact * 10


def test_reversed_float32_resolves_what_window_float32_cannot():
    near, far, z = 0.1, 1000.0, np.array([100.0, 300.0, 900.0])
    win = tr.depth_resolution(z, near, far, "float32")
    rev = tr.depth_resolution(z, near, far, "float32", mapping="reversed")
    assert (rev < win / 100).all()
    # nearly proportional to z (float32's relative step), not z**2
    assert 2 < rev[1] / rev[0] < 4.5 and 8 < win[1] / win[0] < 10
    a, b = z[1:], z[1:] + 0.005
    assert tr.fights(a, b, near, far, "float32").all()
    assert not tr.fights(a, b, near, far, "float32", mapping="reversed").any()
    # unorm has an even step: reversing it gains nothing
    assert np.allclose(
        tr.depth_resolution(z, near, far, "unorm24", mapping="reversed"),
        tr.depth_resolution(z, near, far, "unorm24"),
    )


def test_reversed_fights_uses_greater_is_nearer():
    # two well separated surfaces never "fight", whichever mapping stores them
    assert not tr.fights([1.0], [2.0], 0.1, 10.0, "float32", mapping="reversed").any()


def test_depth_bias_and_slope():
    from teachraster.pipeline.depth import depth_bias, max_depth_slope, offset_clip_depth

    assert np.isclose(depth_bias(0.3, "unorm24", units=2.0), 2 / (2**24 - 1))
    assert depth_bias(0.5, "float32", units=1.0) == np.spacing(np.float32(0.5))
    assert depth_bias(0.5, "float32", units=-1.0) == -np.spacing(np.float32(0.5))
    assert depth_bias(0.5, "unorm16") == 0.0  # GL's initial units: no offset
    assert np.isclose(depth_bias(0.5, "float64", units=0.0, slope=0.02, slope_factor=1.5), 0.03)
    tri = np.array([[[0, 0, 0.5], [8, 0, 0.5], [0, 4, 0.9]], [[0, 0, 0], [1, 1, 0], [2, 2, 0]]])
    slopes = max_depth_slope(tri)
    assert np.isclose(slopes[0], 0.1) and np.isnan(slopes[1])
    clip = np.array([[[0.0, 0.0, 0.2, 1.0], [0.5, 0.0, -0.4, 2.0], [0.0, 0.5, 0.1, 3.0]]])
    moved = offset_clip_depth(clip, -0.01)
    before = clip[..., 2] / clip[..., 3] / 2 + 0.5
    after = moved[..., 2] / moved[..., 3] / 2 + 0.5
    assert np.allclose(after - before, -0.01) and np.array_equal(
        moved[..., [0, 1, 3]], clip[..., [0, 1, 3]]
    )
    with pytest.raises(ValueError, match="depth_format"):
        depth_bias(0.5, "unorm8")
    with pytest.raises(ValueError, match="clip"):
        offset_clip_depth(np.zeros((3, 4)), 0.1)


def test_decal_with_depth_bias_wins_the_depth_test():
    from teachraster.pipeline.depth import depth_bias, offset_clip_depth

    # A wall and a decal on it (the same plane), the decal drawn second: without a bias
    # the tie keeps the wall. The offset is ADDED to the depth (GL 4.6 §14.6.5, Direct3D's
    # DepthBias), so under "less" the decal needs glPolygonOffset(0, -1): then it wins every
    # pixel; the wrong sign, +1 on the decal, pushes it behind and it loses every pixel.
    wall = np.array([[[-1, -1, 0.3, 1], [3, -1, 0.3, 1], [-1, 3, 0.3, 1]]], dtype=float)
    decal = wall.copy()
    plain = tr.render(np.concatenate([wall, decal]), 8, 8, depth_format="unorm16")
    assert (plain.triangle_id == 0).all()
    for units, winner in ((-1.0, 1), (1.0, 0)):
        bias = depth_bias(0.65, "unorm16", units=units)
        assert np.sign(bias) == np.sign(units)  # the APIs' sign: o = units * r, added
        biased = tr.render(np.concatenate([wall, offset_clip_depth(decal, bias)]), 8, 8,
                           depth_format="unorm16")  # fmt: skip
        assert (biased.triangle_id == winner).all(), units
    # the same cure the other way round: +1 on the wall, drawn first, and the decal unbiased
    pushed = offset_clip_depth(wall, depth_bias(0.65, "unorm16", units=1.0))
    assert (tr.render(np.concatenate([pushed, decal]), 8, 8, depth_format="unorm16").triangle_id
            == 1).all()  # fmt: skip
