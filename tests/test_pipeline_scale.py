"""Properties of the render pipeline at scale and at the edges of the float range.

- Homogeneous invariance: scaling one vertex's (x, y, z, w) by a positive factor moves it
  along its own ray and must change nothing on screen, even when w drops below 1e-300 (a
  fixed eye-plane margin used to drop such a vertex and report a near-plane crossing).
- Coordinates near the float maximum: the same frame as at ordinary scale, and no
  RuntimeWarning (the clipper used to overflow into a silent empty frame).
- The vectorised clipper equals a per-triangle scalar Sutherland-Hodgman.
- The one-pass z-buffer equals a sequential one, ties and all, with and without the test.
- planned == force="all" on scenes with extreme w and crossings.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from conftest import examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import teachraster as tr
from teachraster.pipeline.clipping import CLIPPED, DEFAULT_GUARD, clip_triangles
from teachraster.pipeline.zbuffer import passed_on_arrival, resolve

W, H = 20, 16
SETTINGS = settings(
    max_examples=examples(60), deadline=None, suppress_health_check=[HealthCheck.too_slow]
)


def _strict(fn, *args, **kwargs):
    """Call ``fn`` with every warning an error (no RuntimeWarning may escape)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return fn(*args, **kwargs)


# Coordinates 0 or of magnitude in [1e-3, 1e3], so that scaling by 2**±1000 stays normal
# (exact): the property is then equality, not closeness.
coord = st.one_of(
    st.just(0.0),
    st.floats(1e-3, 1e3).flatmap(lambda m: st.sampled_from([m, -m])),
)
vertex = st.tuples(coord, coord, coord, st.floats(1e-3, 1e3)).map(list)
crossing = st.tuples(coord, coord, coord, coord).map(list)
triangle = st.one_of(
    st.lists(vertex, min_size=3, max_size=3),  # in front of the eye (w > 0)
    st.lists(crossing, min_size=3, max_size=3),  # any w: near/far crossings, behind the eye
)


def _same_frame(a, b):
    """Same pixels and plan; depth equal up to the rounding of a clipped vertex (the same
    point on its ray, reached from a different scale). A pixel may change hands only
    between two triangles at the same depth there (an exact tie, such as a duplicate
    triangle, that this rounding can break either way)."""
    # 1e-9: a vertex at infinity (w = 0) is cut at the guard band, a million pixels away,
    # where the depth plane is good to ~1e-11 only.
    np.testing.assert_array_equal(a.coverage, b.coverage)
    np.testing.assert_allclose(a.depth, b.depth, rtol=0, atol=1e-9)
    swapped = a.triangle_id != b.triangle_id
    assert (np.abs(a.depth - b.depth)[swapped] <= 1e-9).all()
    for name in ("clipping", "culling", "depth_test"):
        ea, eb = a.plan[name], b.plan[name]
        assert (ea.ran, ea.count, ea.why) == (eb.ran, eb.count, eb.why)
        # Culling's total counts the pieces clipping made; a polygon that degenerates to a
        # ray through the eye may fan into a different number of zero-area pieces (a new
        # corner lands on the origin, or a rounding away from it), which draw nothing.
        assert name == "culling" or ea.total == eb.total


@SETTINGS
@given(
    tris=st.lists(triangle, min_size=1, max_size=3),
    which=st.tuples(st.integers(0, 2), st.integers(0, 2)),
    power=st.integers(-1000, 1000),
    cull=st.sampled_from([None, "back"]),
)
def test_scaling_one_vertex_changes_nothing(tris, which, power, cull):
    """One vertex times 2**power (w down to ~1e-304 or up to ~1e304): the same pixels,
    depths and plan, and no warning."""
    clip = np.array(tris, dtype=np.float64)
    t, v = which[0] % len(clip), which[1]
    scaled = clip.copy()
    scaled[t, v] *= 2.0**power
    base = _strict(tr.render, clip, W, H, cull=cull)
    _same_frame(base, _strict(tr.render, scaled, W, H, cull=cull))


@SETTINGS
@given(
    tris=st.lists(triangle, min_size=1, max_size=3),
    powers=st.lists(st.integers(-690, 690), min_size=3, max_size=3),
)
def test_vertices_scaled_apart_beyond_the_float_range(tris, powers):
    """Each vertex of every triangle times its own 2**power: vertices of one triangle then
    differ in scale by up to 2**1400 (w = 1e-250 beside 1e121 used to underflow the
    clipper's t and throw a crossing a million pixels off). Still the same frame."""
    clip = np.array(tris, dtype=np.float64)
    scaled = np.ldexp(clip, np.array(powers)[None, :, None])
    _same_frame(_strict(tr.render, clip, W, H), _strict(tr.render, scaled, W, H))


def test_vertices_further_apart_than_the_float_range_are_refused():
    """Scales 2**-600 and 2**1000 in one triangle: bringing it within range would make the
    small vertex vanish into the eye point, so render says so, naming ``clip``."""
    tri = np.ldexp(np.array([[[0.0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]]]),
                   np.array([0, -600, 1000])[None, :, None])  # fmt: skip
    with pytest.raises(ValueError, match="clip: the vertices of triangle 0 differ in scale"):
        tr.render(tri, W, H)


def test_vertices_thirty_orders_of_magnitude_apart_regression():
    """The case the fuzz found: w of -3e-239, 7e-251 and 3e121 in one triangle."""
    clip = np.array([[
        [9.9033305487542443e-240, 3.7861975860844152e-239, 1.8682019477760810e-240,
         -3.0000097655875113e-239],
        [7.8445586502810075e-251, -8.9277495702353799e-251, 4.6134264688193533e-251,
         7.4152857272025200e-251],
        [-3.0181198373034394e121, -7.5347012463339710e120, 2.5818282775837835e121,
         2.6556187424717737e121],
    ]])  # fmt: skip
    moderate = np.ldexp(clip, -np.frexp(np.abs(clip[0, :, 3]))[1][None, :, None])
    for bits in (8, 5, 0):
        frame = _strict(tr.render, clip, 16, 12, subpixel_bits=bits)
        assert frame.coverage.sum() > 0
        _same_frame(frame, _strict(tr.render, moderate, 16, 12, subpixel_bits=bits))


@SETTINGS
@given(w0=st.floats(1e-307, 1e-300), factor=st.floats(1e-3, 1e3))
def test_a_vertex_next_to_the_eye_is_not_a_crossing(w0, factor):
    """A vertex at (0, 0, 0, w) with w < 1e-300 is in front of the eye: nothing is clipped,
    the plan says so, and any positive factor gives the same frame."""
    tri = np.array([[[0, 0, 0, w0], [1, 0, 0.5, 1], [0, 1, 0.5, 1]]])
    frame = _strict(tr.render, tri, W, H)
    assert frame.plan["clipping"].count == 0 and not frame.plan["clipping"].ran
    assert "nothing to clip" in frame.plan["clipping"].why
    other = tri.copy()
    other[0, 0] *= factor
    _same_frame(frame, _strict(tr.render, other, W, H))


@SETTINGS
@given(tris=st.lists(triangle, min_size=1, max_size=3), attrs=st.floats(-1.0, 1.0))
def test_coordinates_near_the_float_maximum(tris, attrs):
    """Every triangle scaled so its largest |coordinate| is about 1e307 or more: the same
    frame as at ordinary scale, no warning; attributes near the float maximum stay finite
    and within their vertex range."""
    clip = np.array(tris, dtype=np.float64)
    peak = np.abs(clip).max()
    if peak == 0:
        return
    power = 1023 - int(np.frexp(peak)[1])  # the largest power of two that keeps it finite
    huge = np.ldexp(clip, power)
    assert np.isfinite(huge).all() and np.abs(huge).max() > 4e307
    _same_frame(_strict(tr.render, clip, W, H), _strict(tr.render, huge, W, H))
    big = np.full((len(clip), 3, 1), 1.7e308)
    big[:, 1] = -1.7e308
    big[:, 2] = attrs * 1.7e308
    frame = _strict(tr.render, huge, W, H, attrs=big)
    values = frame.attrs[frame.coverage]
    assert np.isfinite(values).all() and (np.abs(values) <= 1.7e308).all()


# -- the vectorised clipper against a scalar one ---------------------------------------------
def scalar_clip(tri: np.ndarray, guard: float) -> list[np.ndarray]:
    """Sutherland-Hodgman one vertex at a time (near, far, the guard band, the eye), with
    the clipper's documented rules: step from the endpoint nearer the plane, put the new
    vertex exactly on it, drop corners with w <= 0 at the end."""
    planes = [
        (lambda v: v[2] + v[3], lambda v: (v[0], v[1], -v[3], v[3])),
        (lambda v: v[3] - v[2], lambda v: (v[0], v[1], v[3], v[3])),
        (lambda v: guard * v[3] - v[0], lambda v: (guard * v[3], v[1], v[2], v[3])),
        (lambda v: guard * v[3] + v[0], lambda v: (-guard * v[3], v[1], v[2], v[3])),
        (lambda v: guard * v[3] - v[1], lambda v: (v[0], guard * v[3], v[2], v[3])),
        (lambda v: guard * v[3] + v[1], lambda v: (v[0], -guard * v[3], v[2], v[3])),
    ]
    poly = [np.asarray(v, dtype=np.float64) for v in tri]
    for dist, onto in planes:
        out = []
        for i in range(len(poly)):
            a, b = poly[i], poly[(i + 1) % len(poly)]
            da, db = dist(a), dist(b)
            if da >= 0:
                out.append(a)
            if (da >= 0) != (db >= 0):
                if abs(da) > abs(db):
                    a, b, da, db = b, a, db, da
                with np.errstate(all="ignore"):  # the clipper's form, t's as the fallback
                    v = a + da * ((b - a) / (da - db))
                v = np.where(np.isfinite(v), v, a + da / (da - db) * (b - a))
                out.append(np.array(onto(v)))
        poly = out
    return [v for v in poly if v[3] > 0]


@SETTINGS
@given(tris=st.lists(st.lists(crossing, min_size=3, max_size=3), min_size=1, max_size=12))
def test_vectorised_clipper_equals_scalar_sutherland_hodgman(tris):
    """Polygon by polygon, the batch clipper gives a scalar clipper's corners exactly and
    fans each into len - 2 triangles in input order."""
    clip = np.array(tris, dtype=np.float64)
    res = _strict(clip_triangles, clip, np.zeros((len(clip), 3, 0)))
    assert len(res.polygons) == (res.status == CLIPPED).sum()
    for t, poly in zip(np.flatnonzero(res.status == CLIPPED), res.polygons):
        want = np.array(scalar_clip(clip[t], DEFAULT_GUARD)).reshape(-1, 4)
        assert poly.shape == want.shape
        np.testing.assert_array_equal(poly, want)
        assert (res.parent == t).sum() == max(len(poly) - 2, 0)
    assert (np.diff(res.parent) >= 0).all()


def test_clipping_one_triangle_or_many_is_the_same(rng):
    """A batch is clipped row by row: each triangle alone gives the same pieces."""
    from test_render import random_clip

    clip = random_clip(rng, 200, cross=True)
    attrs = rng.normal(size=(200, 3, 2))
    res = clip_triangles(clip, attrs)
    for t in range(0, 200, 7):
        alone = clip_triangles(clip[t : t + 1], attrs[t : t + 1])
        np.testing.assert_array_equal(alone.clip, res.clip[res.parent == t])
        np.testing.assert_array_equal(alone.attrs, res.attrs[res.parent == t])


# -- the one-pass z-buffer --------------------------------------------------------------------
def sequential(pixel, depth, depth_test):
    winner, best, passed = {}, {}, []
    for i, (p, d) in enumerate(zip(pixel.tolist(), depth.tolist())):
        ok = (not depth_test) or d < best.get(p, np.inf)
        passed.append(ok)
        if ok:
            winner[p], best[p] = i, d
    return winner, passed


@settings(max_examples=examples(200), deadline=None)
@given(
    frags=st.lists(
        st.tuples(st.integers(0, 5), st.sampled_from([0.0, 0.25, 0.5, 1.0])), max_size=40
    ),
    depth_test=st.booleans(),
)
def test_one_pass_zbuffer_equals_a_sequential_one(frags, depth_test):
    """Few pixels and few depths, so ties and deep stacks are common."""
    pixel = np.array([f[0] for f in frags], dtype=np.int64)
    depth = np.array([f[1] for f in frags], dtype=np.float64)
    winner, tested = resolve(pixel, depth, 6, depth_test)
    want, passed = sequential(pixel, depth, depth_test)
    assert {p: int(w) for p, w in enumerate(winner) if w >= 0} == want
    assert tested == int((np.bincount(pixel, minlength=6) > 1).sum())
    if depth_test:
        assert passed_on_arrival(pixel, depth).tolist() == passed


def test_zbuffer_cost_does_not_grow_with_depth_complexity():
    """The layers of a deep stack are resolved without a loop over them: 4096 fragments on
    one pixel give the same answer as the sequential test."""
    rng = np.random.default_rng(5)
    depth = rng.choice(np.linspace(0, 1, 50), 4096)
    pixel = np.zeros(4096, dtype=np.int64)
    winner, _ = resolve(pixel, depth, 1, True)
    want, passed = sequential(pixel, depth, True)
    assert winner[0] == want[0]
    assert passed_on_arrival(pixel, depth).tolist() == passed


# -- planned == force="all" at the extremes ------------------------------------------------
@SETTINGS
@given(
    tris=st.lists(triangle, min_size=1, max_size=4),
    tiny=st.integers(-1000, 0),
    depth_format=st.sampled_from(["float64", "unorm16"]),
    depth_test=st.booleans(),
)
def test_planned_equals_everything_on_at_the_extremes(tris, tiny, depth_format, depth_test):
    """Crossings, vertices next to the eye (w scaled by 2**-1000) and duplicate triangles:
    the planned render equals force='all'."""
    clip = np.array(tris, dtype=np.float64)
    clip[0, 0] *= 2.0**tiny
    clip = np.concatenate([clip, clip[:1]])  # a depth tie
    attrs = np.linspace(0, 1, len(clip) * 3 * 2).reshape(len(clip), 3, 2)
    kw = {"attrs": attrs, "depth_format": depth_format, "depth_test": depth_test}
    planned = _strict(tr.render, clip, W, H, **kw)
    forced = _strict(tr.render, clip, W, H, force="all", **kw)
    np.testing.assert_array_equal(planned.triangle_id, forced.triangle_id)
    np.testing.assert_array_equal(planned.depth, forced.depth)
    # Vertices thousands of pixels away make the barycentrics of a pixel accurate to ~1e-12
    # only; the forced divide by equal w renormalises them, the planned affine path does not.
    np.testing.assert_allclose(planned.attrs, forced.attrs, rtol=0, atol=1e-9)


@pytest.mark.parametrize("layers", [16, 4096])
def test_stacked_layers_render_like_the_nearest(layers):
    """Many layers stacked on one spot: every pixel shows the nearest layer (the earliest
    among equal depths), whatever the depth complexity."""
    rng = np.random.default_rng(layers)
    z = rng.choice(np.linspace(-0.9, 0.9, 7), layers)
    quad = np.array([[-1, -1], [1, -1], [1, 1]], dtype=float)
    clip = np.zeros((layers, 3, 4))
    clip[:, :, :2] = quad
    clip[:, :, 2] = z[:, None]
    clip[:, :, 3] = 1.0
    frame = tr.render(clip, 8, 8, trace=True)
    first_nearest = int(np.flatnonzero(z == z.min())[0])
    assert set(np.unique(frame.triangle_id[frame.coverage]).tolist()) == {first_nearest}
    passed = frame.trace.fragment_passed.reshape(layers, -1)
    running = np.minimum.accumulate(np.r_[np.inf, z[:-1]])
    np.testing.assert_array_equal(passed.all(axis=1), z < running)
