"""Numerical fuzz: extreme w ratios, near-plane crossings and every sub-pixel precision.

Every pixel whose centre is covered must get a finite attribute within the range of the vertex
values (its attribute is a convex combination of them, CONVENTIONS "Interpolation"), with no
RuntimeWarning, for ``tr.rasterize`` and ``tr.render`` alike. The cases that first showed NaN
(w ratios of 1e4 and more with a covered centre just outside the unsnapped triangle) are kept
as explicit regressions below.
"""

import warnings

import numpy as np
import pytest
from conftest import examples
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr
from teachraster.core.interpolation import (
    blend,
    blend_each,
    convex_weights,
    normalised_weights,
    perspective_weights,
    weights_per_row,
)

SIZE = 16
BITS = st.sampled_from([None, *range(17)])
# w from 1e-6 to 1e6 (ratios up to 1e12), often at the extremes where the failures were.
LOG_W = st.one_of(st.sampled_from([-6.0, -4.0, 0.0, 4.0, 6.0]), st.floats(-6.0, 6.0))
COORD = st.floats(-4.0, SIZE + 4.0)
VALUE = st.floats(-1e3, 1e3)
# For render: also ratios of 1e300 (subnormal weight totals). Wider spreads within one
# triangle are refused with a ValueError naming clip (tests/test_pipeline_scale.py).
LOG_W_ANY = st.one_of(LOG_W, st.sampled_from([-150.0, 150.0]), st.floats(-150.0, 150.0))


def strict(call):
    """``call()`` with every warning turned into an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return call()


def assert_within(values, lo, hi, where):
    """values (n, k) finite and within [lo, hi] (per row or broadcast), exactly (the clamp)."""
    assert np.isfinite(values).all(), f"non-finite inside coverage: {where}"
    assert (values >= lo).all() and (values <= hi).all(), f"outside the vertex range: {where}"


# -- rasterize ---------------------------------------------------------------------------------
@settings(max_examples=examples(150), deadline=None)
@given(
    xy=st.lists(st.tuples(COORD, COORD), min_size=3, max_size=3),
    log_w=st.lists(LOG_W, min_size=3, max_size=3),
    u=st.lists(st.tuples(VALUE, VALUE), min_size=3, max_size=3),
    bits=BITS,
    method=st.sampled_from(["halfplane", "span"]),
    mode=st.sampled_from(["perspective", "affine", "subdivided"]),
)
def test_rasterize_covered_centres_get_convex_values(xy, log_w, u, bits, method, mode):
    """Finite attributes within the vertex range at every covered centre, NaN elsewhere."""
    u = np.array(u)
    tri = tr.Triangle(xy, w=10.0 ** np.array(log_w), attrs={"u": u})
    fill = strict(
        lambda: tr.rasterize(
            tri, SIZE, SIZE, method=method, interpolation=mode, subpixel_bits=bits, subdivision=3
        )
    )
    got = fill.attrs["u"]
    assert np.isnan(got[~fill.coverage]).all()
    assert_within(got[fill.coverage], u.min(axis=0), u.max(axis=0), (xy, log_w, bits))


# -- render --------------------------------------------------------------------------------------
def clip_triangle(ndc_xy, ndc_z, w):
    """(3, 4) clip-space vertices from NDC positions and w (negative w: behind the eye)."""
    w = np.asarray(w, dtype=np.float64)
    xy = np.asarray(ndc_xy, dtype=np.float64) * np.abs(w)[:, None]
    return np.column_stack([xy, np.asarray(ndc_z) * np.abs(w), w])


# Window positions, half of them a hair from a pixel centre: snapping then moves an edge across
# the centre, which is covered although it lies just outside the unsnapped triangle.
NEAR_CENTRE = st.builds(
    lambda j, d: j + 0.5 + d, st.integers(-2, SIZE + 1), st.floats(-0.004, 0.004)
)
WIN = st.one_of(st.floats(-4.0, SIZE + 4.0), NEAR_CENTRE)
NDC = WIN.map(lambda x: 2 * x / SIZE - 1)  # x and y alike (the y flip changes nothing here)
NDC_Z = st.floats(-2.0, 2.0)  # beyond ±1: the vertex is cut by the near or far plane


@settings(max_examples=examples(150), deadline=None)
@given(
    tris=st.lists(
        st.tuples(
            st.lists(st.tuples(NDC, NDC), min_size=3, max_size=3),
            st.lists(NDC_Z, min_size=3, max_size=3),
            st.lists(LOG_W_ANY, min_size=3, max_size=3),
            st.lists(st.booleans(), min_size=3, max_size=3),  # behind the eye (w < 0)
            st.lists(st.tuples(VALUE, VALUE), min_size=3, max_size=3),
        ),
        min_size=1,
        max_size=3,
    ),
    bits=BITS,
    depth_test=st.booleans(),
    interpolation=st.sampled_from(["perspective", "affine"]),
)
def test_render_covered_pixels_get_convex_values(tris, bits, depth_test, interpolation):
    """After clipping (near-plane crossings, w < 0) and with w ratios up to 1e12: every covered
    pixel's attributes lie within its input triangle's vertex range and depth within [0, 1]."""
    clip, attrs = [], []
    for ndc_xy, ndc_z, log_w, behind, values in tris:
        w = 10.0 ** np.array(log_w) * np.where(behind, -1.0, 1.0)
        clip.append(clip_triangle(ndc_xy, ndc_z, w))
        attrs.append(values)
    clip, attrs = np.array(clip), np.array(attrs)
    frame = strict(
        lambda: tr.render(
            clip, SIZE, SIZE, attrs=attrs, subpixel_bits=bits, depth_test=depth_test,
            interpolation=interpolation,
        )
    )  # fmt: skip
    check_frame(frame, attrs, (clip.tolist(), bits))


def check_frame(frame, attrs, where):
    """Covered pixels: finite attributes within their triangle's range, depth in [0, 1]."""
    ids = frame.triangle_id
    covered = ids >= 0
    assert np.isnan(frame.attrs[~covered]).all() and np.isnan(frame.depth[~covered]).all()
    t = ids[covered]
    assert_within(frame.attrs[covered], attrs[t].min(axis=1), attrs[t].max(axis=1), where)
    assert_within(frame.depth[covered], 0.0, 1.0, where)


@pytest.mark.parametrize("ratio", [1e4, 1e6, 1e9, 1e12])
@pytest.mark.parametrize("bits", [None, 0, 4, 8, 16])
def test_thin_triangles_with_extreme_w_ratios_stay_finite(rng, ratio, bits):
    """The failure of issue 9: thin triangles (many centres pulled inside an edge by snapping)
    whose far vertex has w ``ratio`` times the others'. Before the fix the perspective weights
    summed to <= 0 and the log-domain fallback took the log of a negative number."""
    n, size = 40, 32
    centre = rng.integers(0, size, (n, 3, 2)) + 0.5  # vertices a hair from pixel centres
    win = centre + rng.uniform(-1, 1, (n, 3, 2)) / 2.0 ** (1 if bits is None else bits + 1)
    win[:, 2] = win[:, 1] + rng.uniform(-0.6, 0.6, (n, 2))  # thin: two vertices close
    ndc = 2 * win / size - 1
    w = np.ones((n, 3))
    w[np.arange(n), rng.integers(0, 3, n)] = ratio
    w *= 10.0 ** rng.uniform(-3, 3, (n, 1))
    clip = np.concatenate([ndc * w[..., None], np.zeros((n, 3, 1)), w[..., None]], axis=-1)
    attrs = rng.uniform(-1, 1, (n, 3, 2))
    for k in range(n):  # one at a time: every triangle's covered pixels are visible
        frame = strict(lambda k=k: tr.render(clip[k : k + 1], size, size, attrs=attrs[k : k + 1],
                                             subpixel_bits=bits))  # fmt: skip
        check_frame(frame, attrs[k : k + 1], (clip[k].tolist(), bits))


def test_issue_case_weights_sum_to_nothing():
    """The regression in its smallest form: λ with a small negative weight at the vertex whose
    w is 1e-4 of the others' gave Σ λ_i min(w)/w_i < 0; the weights are now convex."""
    lam = np.array([[-1e-3, 0.5, 0.501]])
    w = np.array([[1.0, 1e4, 1e4]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mu = weights_per_row(lam, w)
    assert np.isfinite(mu).all() and (mu >= 0).all()
    assert mu.sum() == pytest.approx(1.0, abs=1e-15)
    np.testing.assert_array_equal(mu[:, 0], 0.0)


def test_subnormal_weight_totals_stay_finite():
    """w from 3.7e-22 to 3.6e289 (a ratio beyond the float range): the perspective terms of
    some covered centres sum to a subnormal total, whose reciprocal overflows; the weights are
    divided by the total itself, and rows whose every term underflowed are redone in logs."""
    clip = np.array([[
        [4.8422206510653815e-22, -9.9469583337623692e-23, 7.7460915712799127e-23,
         3.7060558637015205e-22],
        [-9.2623485211795792e286, 4.5143651238154359e286, 5.8879057147264721e286,
         1.0866849519673419e287],
        [2.5479094722906058e289, 3.2495904121176647e289, 3.1005333821363250e289,
         3.6283158776430638e289],
    ]])  # fmt: skip
    attrs = np.array([[[-0.30186167875298198, 8.7599214511715161e299],
                       [2.3855243875653766e299, 0.99077434092284267],
                       [-0.63063034057752110, 5.7588632804911315e307]]])  # fmt: skip
    frame = strict(lambda: tr.render(clip, 16, 12, attrs=attrs, subpixel_bits=1))
    assert (frame.triangle_id >= 0).any()
    check_frame(frame, attrs, "subnormal totals")


def test_normalised_weights_divide_by_subnormal_totals():
    q = np.array([[1e-310, 2e-310, 0.0], [-1.0, 0.0, 0.0], [np.inf, 1.0, 0.0]])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mu, bad = normalised_weights(q)
    np.testing.assert_allclose(mu[0], [1 / 3, 2 / 3, 0.0], rtol=1e-3)  # subnormal precision
    assert bad.tolist() == [False, True, True]


# -- the interpolation functions themselves --------------------------------------------------------
@settings(max_examples=examples(200), deadline=None)
@given(
    lam=st.lists(st.floats(-1e3, 1e3), min_size=3, max_size=3),
    log_w=st.lists(st.floats(-300.0, 300.0), min_size=3, max_size=3),
    values=st.lists(st.floats(-1e300, 1e300), min_size=3, max_size=3),
)
def test_weights_are_convex_for_any_input(lam, log_w, values):
    """Whatever λ (negative, not summing to 1) and w (ratios to 1e600), the default weights
    are >= 0 and sum to 1, and the blend lies within the vertex values, without a warning."""
    lam, w, f = np.array([lam]), 10.0 ** np.array([log_w]), np.array(values)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mu = weights_per_row(lam, w)
        out = blend_each(mu, f[None, :, None])[0, 0]
    assert np.isfinite(mu).all() and (mu >= 0).all() and (mu <= 1).all()
    assert mu.sum() == pytest.approx(1.0, abs=1e-12)
    assert f.min() <= out <= f.max()


def test_convex_weights_keep_good_rows_bit_for_bit_and_settle_degenerate_ones():
    """Non-negative rows are untouched (vertices and edges stay exact); +inf takes the row;
    all-non-positive rows become equal weights."""
    good = np.array([[1.0, 0.0, 0.0], [0.2, 0.3, 0.5], [0.0, 0.25, 0.75]])
    assert convex_weights(good) is good
    odd = np.array([[np.inf, 1.0, -np.inf], [-1.0, 0.0, -2.0], [np.inf, np.inf, 0.0]])
    np.testing.assert_array_equal(
        convex_weights(odd), [[1.0, 0.0, 0.0], [1 / 3, 1 / 3, 1 / 3], [0.5, 0.5, 0.0]]
    )


def test_extrapolate_keeps_the_unclamped_interpolation():
    """``extrapolate=True`` (MSAA centres, helper pixels outside the triangle) uses the weights
    as given: the affine and perspective formulas continue beyond the edges, unclamped."""
    lam = np.array([[-0.5, 0.75, 0.75]])
    f = np.array([0.0, 1.0, 2.0])
    np.testing.assert_allclose(blend(lam, f, extrapolate=True), [2.25])
    np.testing.assert_allclose(blend(convex_weights(lam), f), [1.5])
    w = np.array([1.0, 2.0, 2.0])
    mu = perspective_weights(lam, w, extrapolate=True)
    np.testing.assert_allclose(mu, [[-0.5 / 0.25, 0.375 / 0.25, 0.375 / 0.25]])
    assert (perspective_weights(lam, w) >= 0).all()


# -- values near the float maximum where the answer may leave the vertex range ------------------
HUGE = st.sampled_from([1.7e308, -1.7e308, 1e300, -1e-300, 0.0, 1.0])


@settings(max_examples=examples(60), deadline=None)
@given(
    xy=st.lists(st.tuples(COORD, COORD), min_size=3, max_size=3),
    values=st.lists(st.tuples(HUGE, HUGE), min_size=3, max_size=3),
    log_w=st.lists(LOG_W, min_size=3, max_size=3),
    samples=st.sampled_from([4, 16]),
    per_sample=st.booleans(),
)
def test_huge_values_extrapolate_and_average_without_warnings(xy, values, log_w, samples,
                                                              per_sample):  # fmt: skip
    """MSAA centres outside the triangle extrapolate, supersampling averages samples: with
    vertex values near ±1.7e308 neither may warn or produce NaN (two huge terms used to give
    inf - inf); the average of covered samples stays within the vertex range."""
    values = np.array(values)
    tri = tr.Triangle(np.array(xy), w=10.0 ** np.array(log_w), attrs={"f": values})
    fill = strict(lambda: tr.rasterize(tri, SIZE, SIZE, samples=samples, per_sample=per_sample))
    got = fill.attrs["f"][fill.coverage]
    assert not np.isnan(got).any()
    if per_sample:
        assert_within(got, values.min(axis=0), values.max(axis=0), (xy, values.tolist()))


@settings(max_examples=examples(40), deadline=None)
@given(
    tris=st.lists(
        st.tuples(st.lists(st.tuples(NDC, NDC), min_size=3, max_size=3),
                  st.lists(LOG_W, min_size=3, max_size=3),
                  st.lists(st.tuples(HUGE, HUGE), min_size=3, max_size=3)),
        min_size=1, max_size=3,
    ),
    samples=st.sampled_from([1, 4]),
)  # fmt: skip
def test_huge_values_in_render_derivatives_and_msaa(tris, samples):
    """Quad derivatives (helper pixels extrapolate, differences of huge values) and MSAA
    centres with vertex values near the float maximum: no warning, no NaN where covered."""
    clip = np.array([clip_triangle(p, [0.5] * 3, 10.0 ** np.array(w)) for p, w, _ in tris])
    attrs = np.array([v for _, _, v in tris])
    deriv = samples == 1
    frame = strict(lambda: tr.render(clip, SIZE, SIZE, attrs=attrs, samples=samples,
                                     derivatives=deriv))  # fmt: skip
    covered = frame.triangle_id >= 0
    assert not np.isnan(frame.attrs[covered]).any()
    if deriv:
        assert not np.isnan(frame.ddx[covered]).any() and not np.isnan(frame.ddy[covered]).any()


@pytest.mark.parametrize("extrapolate", [False, True])
@pytest.mark.parametrize("lam", [[0.0, 0.5, 0.5], [0.0, 0.0, 1.0], [0.2, 0.3, 0.5]])
def test_one_point_gets_the_weights_of_its_row_even_where_every_term_underflows(lam, extrapolate):
    """r421: one point's λ (shape (3,)) at w = (1e-310, 1e300, 1e300), where every term
    λ_i min(w)/w_i underflows, raised a raw TypeError (a 0-d total indexed per row); it gets
    what the same λ as a row of a (1, 3) array gets, and so does a (1, 1, 3) grid."""
    w = np.array([1e-310, 1e300, 1e300])
    row = perspective_weights(np.array([lam]), w, extrapolate=extrapolate)[0]
    assert np.isfinite(row).all() and row.sum() == pytest.approx(1.0)
    one = perspective_weights(np.array(lam), w, extrapolate=extrapolate)
    grid = perspective_weights(np.array([[lam]]), w, extrapolate=extrapolate)
    assert one.shape == (3,) and grid.shape == (1, 1, 3)
    np.testing.assert_array_equal(one, row)
    np.testing.assert_array_equal(grid[0, 0], row)
