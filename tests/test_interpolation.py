"""Interpolation: barycentrics, affine vs perspective-correct, depth, plane equations (the plane-equation post, Ritschel, Fatahalian).

Reference values are computed here from exact Fraction barycentrics of the snapped triangle and
the formulas in CONVENTIONS.md, independently of the package's own arithmetic.
"""

from fractions import Fraction

import numpy as np
import pytest
from conftest import (
    METHODS,
    MODES,
    centres,
    exact_barycentric,
    examples,
    random_triangles,
    subpixel_coords,
    triangles,
)
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr

W, H = 14, 12


def seeded_cases(seed, n, kinds=("float", "subpixel", "centre", "tie")):
    """(xy, w, z, u, rgb) for n seeded random triangles of each kind that cover something."""
    rng = np.random.default_rng(seed)
    for kind in kinds:
        for xy in random_triangles(rng, kind, n, W, H):
            w = rng.uniform(0.1, 20.0, 3)
            z = rng.uniform(0.0, 1.0, 3)
            u = rng.uniform(-5.0, 5.0, 3)
            rgb = rng.uniform(0.0, 1.0, (3, 4))
            yield xy, w, z, u, rgb


def exact_lambdas(xy, coverage) -> np.ndarray:
    """(n, 3) float barycentrics of the covered pixel centres, rounded once from exact values."""
    _, _, x, y = centres(coverage)
    return np.array(
        [[float(v) for v in exact_barycentric(xy, (px, py))] for px, py in zip(x, y)]
    ).reshape(-1, 3)


def scale(values) -> float:
    return float(np.max(np.abs(values))) or 1.0


# -- affine vs perspective --------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_equal_w_makes_perspective_identical_to_affine(method):
    """With the same w at all three vertices, perspective-correct == affine, bit for bit."""
    for xy, w, _, u, rgb in seeded_cases(1, 40):
        for wc in (1.0, w[0]):
            tri = tr.Triangle(xy, w=[wc] * 3, attrs={"u": u, "rgb": rgb})
            p = tr.rasterize(tri, W, H, method=method, interpolation="perspective")
            a = tr.rasterize(tri, W, H, method=method, interpolation="affine")
            for name in ("u", "rgb"):
                np.testing.assert_array_equal(p.attrs[name], a.attrs[name])


def test_affine_matches_the_independent_formula():
    """Affine: f = sum(lambda_i f_i), lambda from exact Fractions, within 1e-12 of max |f|."""
    for xy, w, _, u, rgb in seeded_cases(2, 40):
        tri = tr.Triangle(xy, w=w, attrs={"u": u, "rgb": rgb})
        fill = tr.rasterize(tri, W, H, interpolation="affine")
        lam = exact_lambdas(xy, fill.coverage)
        np.testing.assert_allclose(
            fill.attrs["u"][fill.coverage], lam @ u, rtol=0, atol=1e-12 * scale(u)
        )
        np.testing.assert_allclose(
            fill.attrs["rgb"][fill.coverage], lam @ rgb, rtol=0, atol=1e-12 * scale(rgb)
        )


@pytest.mark.parametrize("method", METHODS)
def test_perspective_matches_the_independent_formula(method):
    """Perspective: f = sum(lambda_i f_i / w_i) / sum(lambda_i / w_i), within 1e-12 relative."""
    for xy, w, _, u, rgb in seeded_cases(3, 40):
        tri = tr.Triangle(xy, w=w, attrs={"u": u, "rgb": rgb})
        fill = tr.rasterize(tri, W, H, method=method, interpolation="perspective")
        lam = exact_lambdas(xy, fill.coverage)
        q = lam / w
        want_u = (q @ u) / q.sum(axis=1)
        want_rgb = (q @ rgb) / q.sum(axis=1, keepdims=True)
        np.testing.assert_allclose(
            fill.attrs["u"][fill.coverage], want_u, rtol=1e-12, atol=1e-12 * scale(u)
        )
        np.testing.assert_allclose(
            fill.attrs["rgb"][fill.coverage], want_rgb, rtol=1e-12, atol=1e-12 * scale(rgb)
        )


def test_perspective_reproduces_world_space_linear_attributes():
    """Project a 3-D triangle: perspective interpolation of world X equals the ray-plane hit.

    Screen positions are chosen on the 1/256 grid (so snapping changes nothing) with depths
    Z_i = w_i; world points are unprojected from them. An attribute linear in world space
    (here X and 2X - Y + 3Z) must come out exactly as at the point where the pixel's ray meets
    the triangle's plane; affine interpolation does not (the lecture's perspective error).
    """
    rng = np.random.default_rng(4)
    fx = fy = 10.0
    cx, cy = W / 2, H / 2
    for _ in range(30):
        xy = np.round(rng.uniform(-1, [W + 1, H + 1], (3, 2)) * 256) / 256
        Z = rng.uniform(1.0, 30.0, 3)
        P = np.stack([(xy[:, 0] - cx) * Z / fx, (xy[:, 1] - cy) * Z / fy, Z], axis=1)
        f = np.stack([P[:, 0], 2 * P[:, 0] - P[:, 1] + 3 * P[:, 2]], axis=1)
        tri = tr.Triangle(xy, w=Z, attrs={"f": f})
        fill = tr.rasterize(tri, W, H)
        _, _, x, y = centres(fill.coverage)
        d = np.stack([(x - cx) / fx, (y - cy) / fy, np.ones_like(x)], axis=1)
        n = np.cross(P[1] - P[0], P[2] - P[0])
        hit = d * ((n @ P[0]) / (d @ n))[:, None]
        want = np.stack([hit[:, 0], 2 * hit[:, 0] - hit[:, 1] + 3 * hit[:, 2]], axis=1)
        np.testing.assert_allclose(fill.attrs["f"][fill.coverage], want, rtol=1e-9, atol=1e-9)
        if not np.allclose(Z, Z[0]) and fill.coverage.sum() > 3:
            affine = tr.rasterize(tri, W, H, interpolation="affine").attrs["f"][fill.coverage]
            assert not np.allclose(affine, want, rtol=1e-6, atol=1e-6)


# -- barycentrics -----------------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_trace_barycentrics_sum_to_one_and_lie_in_unit_interval(method):
    """Inside coverage the barycentrics sum to 1 (1e-12) and lie in [0, 1]; NaN outside."""
    for xy, *_ in seeded_cases(5, 40):
        fill = tr.rasterize(tr.Triangle(xy), W, H, method=method, trace=True)
        lam = fill.trace.image(fill.trace.barycentric)
        inside = lam[fill.coverage]
        assert np.all(np.abs(inside.sum(axis=1) - 1) <= 1e-12)
        assert inside.min(initial=0) >= 0 and inside.max(initial=1) <= 1
        assert np.isnan(lam[~fill.coverage]).all()


def test_trace_barycentrics_match_exact_values():
    """Trace barycentrics equal the exact ones (vertex order as given) to 1e-15."""
    for xy, *_ in seeded_cases(6, 25):
        fill = tr.rasterize(tr.Triangle(xy), W, H, trace=True)
        lam = fill.trace.image(fill.trace.barycentric)[fill.coverage]
        np.testing.assert_allclose(lam, exact_lambdas(xy, fill.coverage), rtol=0, atol=1e-15)


def test_barycentric_reproduces_vertices():
    """tr.barycentric at the vertices gives the identity matrix; at the centroid, 1/3 each."""
    rng = np.random.default_rng(7)
    for _ in range(50):
        xy = rng.uniform(-100, 100, (3, 2))
        np.testing.assert_allclose(tr.barycentric(xy, xy), np.eye(3), atol=1e-12)
        np.testing.assert_allclose(tr.barycentric(xy, xy.mean(axis=0)), [1 / 3] * 3, atol=1e-12)


@settings(max_examples=examples(100), deadline=None)
@given(
    st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50)), min_size=4, max_size=4).map(
        np.array
    )
)
def test_barycentric_is_the_ratio_of_areas(pts):
    """lambda_A(P) = area(P, B, C) / area(A, B, C) etc. (Ritschel, *Interpolation and z-buffering*), against exact Fractions."""
    xy, p = pts[:3], pts[3]
    a, b, c = [(Fraction(x), Fraction(y)) for x, y in xy]
    P = (Fraction(p[0]), Fraction(p[1]))

    def area(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    total = area(a, b, c)
    if abs(total) < 1e-3:
        return
    want = [area(P, b, c) / total, area(P, c, a) / total, area(P, a, b) / total]
    got = tr.barycentric(xy, p)
    # Each weight is a difference of products of coordinate differences (size ~ extent²)
    # over the doubled area: its rounding error grows with extent² / |area| (a sliver far
    # from P is ill-conditioned, whatever the formula), times the weights' own size.
    extent = float(np.ptp(pts, axis=0).max())
    cond = max(1.0, extent**2 / abs(float(total)))
    tol = 1e-14 * cond * (1 + max(abs(float(v)) for v in want))
    np.testing.assert_allclose(got, [float(v) for v in want], rtol=0, atol=tol)
    np.testing.assert_allclose(got.sum(), 1.0, atol=tol)


def test_barycentric_shapes_and_zero_area():
    """(..., 2) points give (..., 3) weights; a zero-area triangle raises ValueError naming xy."""
    xy = [[0, 0], [4, 0], [0, 4]]
    assert tr.barycentric(xy, np.zeros((5, 7, 2))).shape == (5, 7, 3)
    with pytest.raises(ValueError, match="xy"):
        tr.barycentric([[0, 0], [1, 1], [2, 2]], [[0.5, 0.5]])
    with pytest.raises(ValueError, match="points"):
        tr.barycentric(xy, [[1, 2, 3]])


# -- constant attributes, NaN outside, depth ----------------------------------------------------
CONSTANTS = [0.1, 1 / 3, -7.25e10, 1e-300, 0.0, 123456.789]


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("method", METHODS)
def test_constant_attributes_stay_exactly_constant(method, mode):
    """An attribute equal at all vertices comes out EXACTLY that value (==), scalar and vector."""
    vec = np.array(CONSTANTS)
    for xy, w, *_ in seeded_cases(8, 25):
        for c in CONSTANTS:
            tri = tr.Triangle(xy, w=w, attrs={"c": [c] * 3, "v": np.tile(vec, (3, 1))})
            fill = tr.rasterize(tri, W, H, method=method, interpolation=mode)
            assert (fill.attrs["c"][fill.coverage] == c).all()
            assert (fill.attrs["v"][fill.coverage] == vec).all()


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("method", METHODS)
def test_nan_exactly_outside_coverage(method, mode):
    """Attributes (H, W) / (H, W, k) and depth are NaN exactly where the pixel is not covered."""
    for xy, w, z, u, rgb in seeded_cases(9, 15):
        fill = tr.rasterize(
            tr.Triangle(xy, w=w, z=z, attrs={"u": u, "rgb": rgb}), W, H, method=method,
            interpolation=mode,
        )  # fmt: skip
        assert fill.attrs["u"].shape == (H, W) and fill.attrs["rgb"].shape == (H, W, 4)
        assert fill.attrs["u"].dtype == np.float64 and fill.depth.dtype == np.float64
        np.testing.assert_array_equal(np.isnan(fill.attrs["u"]), ~fill.coverage)
        np.testing.assert_array_equal(np.isnan(fill.attrs["rgb"]).all(axis=2), ~fill.coverage)
        assert not np.isnan(fill.attrs["rgb"][fill.coverage]).any()
        np.testing.assert_array_equal(np.isnan(fill.depth), ~fill.coverage)


def test_no_z_means_no_depth():
    """Without z, fill.depth is None; without attrs, fill.attrs is empty."""
    fill = tr.rasterize(tr.Triangle([[0, 0], [5, 0], [0, 5]]), 5, 5)
    assert fill.depth is None and dict(fill.attrs) == {}


@pytest.mark.parametrize("mode", MODES)
def test_depth_is_affine_even_with_perspective(mode):
    """Window depth is interpolated affinely whatever the attribute mode and w."""
    for xy, w, z, *_ in seeded_cases(10, 25):
        fill = tr.rasterize(tr.Triangle(xy, w=w, z=z), W, H, interpolation=mode)
        lam = exact_lambdas(xy, fill.coverage)
        np.testing.assert_allclose(fill.depth[fill.coverage], lam @ z, rtol=0, atol=1e-12)


@pytest.mark.parametrize("mode", MODES)
def test_depth_within_vertex_depth_range(mode):
    """Depth is a convex combination of the vertex depths: inside [min z, max z], in [0, 1]."""
    for xy, w, z, *_ in seeded_cases(11, 60, kinds=("centre", "tie", "float")):
        for zz in (z, [1.0, 0.0, 0.0], [0.0, 1.0, 1.0], [0.25, 0.75, 0.75]):
            fill = tr.rasterize(tr.Triangle(xy, w=w, z=zz), W, H, interpolation=mode)
            d = fill.depth[fill.coverage]
            assert d.size == 0 or (min(zz) <= d.min() and d.max() <= max(zz)), (
                f"xy={xy.tolist()}, z={list(zz)}: depth range [{d.min()!r}, {d.max()!r}]"
            )


@pytest.mark.parametrize("method", METHODS)
def test_depth_on_an_edge_between_two_zero_depth_vertices_is_not_negative(method):
    """Minimal repro: pixel (row 2, col 4) lies on the edge v1-v2 (both z = 0), lambda =
    (0, 2/11, 9/11). Its depth must be 0 (it may not be negative: window depth is in [0, 1])."""
    tri = tr.Triangle([[5.5, 4.5], [13.5, 2.5], [2.5, 2.5]], z=[1.0, 0.0, 0.0])
    fill = tr.rasterize(tri, 12, 12, method=method)
    assert fill.coverage[2, 4]
    assert fill.depth[2, 4] >= 0.0, f"depth {fill.depth[2, 4]!r} < 0"
    assert np.nanmin(fill.depth) >= 0.0


@pytest.mark.parametrize("mode", MODES)
def test_attributes_within_vertex_value_range(mode):
    """Interpolated attributes (both modes) never leave [min f_i, max f_i] (convex weights)."""
    for xy, w, _, u, _ in seeded_cases(12, 60, kinds=("centre", "tie")):
        for f in (u, [1.0, 0.0, 0.0], [-2.0, 3.0, 3.0]):
            fill = tr.rasterize(tr.Triangle(xy, w=w, attrs={"f": f}), W, H, interpolation=mode)
            v = fill.attrs["f"][fill.coverage]
            assert v.size == 0 or (min(f) <= v.min() and v.max() <= max(f)), (
                f"xy={xy.tolist()}, w={w.tolist()}, f={list(f)}: [{v.min()!r}, {v.max()!r}]"
            )


# -- plane equations (*Triangle Rasterisation II - Interpolation*) and the setup matrix (Fatahalian, CMU 15-462 *Texture*) --------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_plane_equation_agrees_with_affine_interpolation(method):
    """f = -(A x + B y + D) / C at pixel centres equals the affine fill (snapped vertices)."""
    for xy, _, _, u, rgb in seeded_cases(13, 25, kinds=("subpixel", "centre")):
        fill = tr.rasterize(
            tr.Triangle(xy, attrs={"u": u, "rgb": rgb}), W, H, method=method, interpolation="affine"
        )
        _, _, x, y = centres(fill.coverage)
        plane = tr.plane_equation(xy, u)
        np.testing.assert_allclose(plane(x, y), fill.attrs["u"][fill.coverage], atol=1e-10)
        plane_rgb = tr.plane_equation(xy, rgb)
        np.testing.assert_allclose(plane_rgb(x, y), fill.attrs["rgb"][fill.coverage], atol=1e-10)


def test_plane_equation_coefficients():
    """The post *Triangle Rasterisation II - Interpolation*: C is twice the signed area (shared by all attributes); dx = -A/C, dy = -B/C
    are the per-pixel and per-row steps."""
    rng = np.random.default_rng(14)
    for _ in range(50):
        xy = rng.uniform(-20, 20, (3, 2))
        f = rng.uniform(-3, 3, 3)
        plane = tr.plane_equation(xy, f)
        assert plane.C == pytest.approx(2 * tr.Triangle(xy).signed_area, rel=1e-12)
        assert tr.plane_equation(xy, rng.uniform(-3, 3, 3)).C == plane.C
        np.testing.assert_allclose(plane.dx, -plane.A / plane.C)
        np.testing.assert_allclose(plane.dy, -plane.B / plane.C)
        x, y = rng.uniform(-20, 20, 2)
        np.testing.assert_allclose(plane(x + 1, y) - plane(x, y), plane.dx, atol=1e-9)
        np.testing.assert_allclose(plane(x, y + 1) - plane(x, y), plane.dy, atol=1e-9)
        np.testing.assert_allclose(plane(xy[:, 0], xy[:, 1]), f, atol=1e-10)  # through the points


@pytest.mark.parametrize("k", [None, 3])
def test_stepped_plane_approximates_direct_evaluation(k):
    """stepped(): start exact, then add dy per row and dx per pixel (*Triangle Rasterisation II - Interpolation*'s inner loop);
    over a 64 x 48 grid the accumulated rounding stays tiny."""
    rng = np.random.default_rng(15)
    for _ in range(20):
        xy = rng.uniform(0, 64, (3, 2))
        f = rng.uniform(-1, 1, 3 if k is None else (3, k))
        plane = tr.plane_equation(xy, f)
        x0, y0 = 0.5, 0.5
        grid = plane.stepped(x0, y0, 64, 48)
        assert grid.shape == ((48, 64) if k is None else (48, 64, k))
        Y, X = np.mgrid[0:48, 0:64] + 0.5
        direct = plane(X, Y)
        np.testing.assert_array_equal(grid[0, 0], plane(x0, y0))  # exact start
        step = np.max(np.abs(plane.dx)) + np.max(np.abs(plane.dy)) + np.max(np.abs(f))
        np.testing.assert_allclose(grid, direct, rtol=0, atol=1e-10 * step * 112)


def test_setup_matrix_inverts_the_edge_matrix():
    """Fatahalian (CMU 15-462, *Texture*): M = inverse of [[b - a], [c - a]], so M @ [[b - a], [c - a]] = I."""
    rng = np.random.default_rng(16)
    for _ in range(50):
        xy = rng.uniform(-30, 30, (3, 2))
        M = tr.setup_matrix(xy)
        edges = np.stack([xy[1] - xy[0], xy[2] - xy[0]])
        np.testing.assert_allclose(M @ edges, np.eye(2), atol=1e-9)
    with pytest.raises(ValueError, match="xy"):
        tr.setup_matrix([[0, 0], [1, 1], [2, 2]])
    with pytest.raises(ValueError, match="xy"):
        tr.plane_equation([[0, 0], [1, 1], [2, 2]], [1, 2, 3])


def test_attribute_plane_agrees_with_plane_equation():
    """[A, B] = M [f_b - f_a, f_c - f_a] gives *Triangle Rasterisation II - Interpolation*'s gradient (dx, dy) and the same values;
    one M reused for several attributes gives the same planes as a fresh set-up."""
    rng = np.random.default_rng(17)
    for _ in range(50):
        xy = rng.uniform(-30, 30, (3, 2))
        M = tr.setup_matrix(xy)
        for f in (rng.uniform(-2, 2, 3), rng.uniform(-2, 2, (3, 4))):
            plane = tr.plane_equation(xy, f)
            ap = tr.attribute_plane(xy, f)
            reused = tr.attribute_plane(xy, f, M=M)
            np.testing.assert_allclose(ap.A, plane.dx, rtol=1e-9, atol=1e-12)
            np.testing.assert_allclose(ap.B, plane.dy, rtol=1e-9, atol=1e-12)
            np.testing.assert_array_equal(reused.A, ap.A)
            np.testing.assert_array_equal(reused.B, ap.B)
            # the lessons' names for Fatahalian's A, B (lesson 03 prints g_x beside dx)
            assert ap.g_x is ap.A and ap.g_y is ap.B
            pts = rng.uniform(-30, 30, (10, 2))
            np.testing.assert_allclose(
                ap(pts[:, 0], pts[:, 1]), plane(pts[:, 0], pts[:, 1]), atol=1e-9
            )
            assert ap.origin == (xy[0, 0], xy[0, 1])
            np.testing.assert_array_equal(ap(xy[0, 0], xy[0, 1]), f[0])  # exact at vertex a


def _exact_plane_value(xy, f, p) -> Fraction:
    a, b, c = [(Fraction(x), Fraction(y)) for x, y in xy]
    P = (Fraction(p[0]), Fraction(p[1]))

    def e(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    area = e(a, b, c)
    lam = (e(b, c, P) / area, e(c, a, P) / area, e(a, b, P) / area)
    return sum(l * Fraction(v) for l, v in zip(lam, f))


def test_recentred_plane_is_accurate_far_from_the_origin():
    """Fatahalian (CMU 15-462, *Texture*): "greater precision near the origin". At ~1e7 px the plane recentred at vertex a
    stays accurate (error < 1e-9) and is never worse than *Triangle Rasterisation II - Interpolation*'s absolute-coordinate plane,
    which loses digits to cancellation (compared against Fraction-exact values)."""
    rng = np.random.default_rng(18)
    worst_absolute = 0.0
    for _ in range(30):
        xy = 1e7 + rng.uniform(0, 10, (3, 2))
        f = rng.uniform(-1, 1, 3)
        absolute, recentred = tr.plane_equation(xy, f), tr.attribute_plane(xy, f)
        for p in xy.mean(axis=0) + rng.uniform(-1, 1, (5, 2)):
            exact = _exact_plane_value(xy, f, p)
            err_rec = abs(Fraction(float(recentred(*p))) - exact)
            err_abs = abs(Fraction(float(absolute(*p))) - exact)
            assert err_rec < Fraction(1, 10**9)
            assert err_rec <= err_abs
            worst_absolute = max(worst_absolute, float(err_abs))
    assert worst_absolute > 1e-7  # the lesson: the absolute form visibly loses precision


def test_planes_in_float32_as_a_gpus_set_up():
    """Review r226 F1: Direct3D sets up its interpolators in float32 (D3D11.3 §15.16.2); both
    forms take ``dtype=np.float32`` and compute and evaluate in it. Near the origin they agree
    with float64 to float32's precision; at 16 368 px (inside a 16 384-px target, positions on
    the 1/256-px grid) the absolute form misses by more than 1 and the recentred one does not
    notice the distance. float64 stays the default, bit for bit."""
    xy, f = np.array([[0.5, 0.5], [13.25, 3.5], [4.75, 11.5]]), np.array([0.1, 7.3, -2.9])
    pts = np.array([[3.5, 4.5], [8.5, 6.5]])
    for form in (tr.plane_equation, tr.attribute_plane):
        single = form(xy, f, dtype=np.float32)(*pts.T)
        assert single.dtype == np.float32
        np.testing.assert_allclose(single, form(xy, f)(*pts.T), atol=1e-5)
        assert form(xy, f, dtype=np.float64)(*pts.T).tolist() == form(xy, f)(*pts.T).tolist()
    far = xy + 16_368
    exact = [_exact_plane_value(far, f, p + 16_368) for p in pts]
    absolute = tr.plane_equation(far, f, dtype=np.float32)(*(pts + 16_368).T)
    recentred = tr.attribute_plane(far, f, dtype=np.float32)(*(pts + 16_368).T)
    assert max(abs(float(Fraction(float(v)) - e)) for v, e in zip(absolute, exact)) > 0.5
    assert max(abs(float(Fraction(float(v)) - e)) for v, e in zip(recentred, exact)) < 5e-6
    with pytest.raises(ValueError, match="dtype"):
        tr.plane_equation(xy, f, dtype=np.float16)


@settings(max_examples=examples(60), deadline=None)
@given(triangles(subpixel_coords(-1, 13)), st.sampled_from(MODES))
def test_hypothesis_constant_vector_attribute_is_exact(xy, mode):
    """Hypothesis: any triangle, any mode, constant (3, k) attributes stay exactly constant."""
    vec = np.array([0.3, -1.7, 1e20])
    fill = tr.rasterize(
        tr.Triangle(xy, w=[0.5, 3.0, 17.0], attrs={"v": np.tile(vec, (3, 1))}), W, H,
        interpolation=mode,
    )  # fmt: skip
    assert (fill.attrs["v"][fill.coverage] == vec).all()
