"""2×2 quads, helper pixels and derivatives in ``render``, against an independent reference.

The reference evaluates an attribute at any window point by solving for the point's
*clip-space* barycentrics b (Σ b_i (x_i − x_ndc w_i) = 0, Σ b_i (y_i − y_ndc w_i) = 0,
Σ b_i = 1): the exact perspective mapping, with no λ/w formula from the package. Its
w = Σ b_i w_i is ≤ 0 beyond the triangle's horizon.
"""

from __future__ import annotations

import numpy as np
import pytest

import teachraster as tr
from teachraster.pipeline.mesh import Mesh
from teachraster.pipeline.quad_derivatives import may_minify
from teachraster.pipeline.scenes import Scene, get_scene

W, H = 24, 18


def ref_eval(clip, attrs, x, y, width=W, height=H):
    """Attribute (k,) and w at window point (x, y) on the plane of clip triangle (3, 4)."""
    xn, yn = 2 * x / width - 1, 1 - 2 * y / height
    a = np.array(
        [clip[:, 0] - xn * clip[:, 3], clip[:, 1] - yn * clip[:, 3], np.ones(3)], dtype=float
    )
    b = np.linalg.solve(a, [0.0, 0.0, 1.0])
    return b @ attrs, b @ clip[:, 3]


def ref_derivatives(clip, attrs, row, col, mode="coarse", width=W, height=H):
    """The CONVENTIONS rule at one pixel: quad differences, away from lanes beyond the horizon."""
    qr, qc = row - row % 2, col - col % 2
    lane = {}
    for dr in (0, 1):
        for dc in (0, 1):
            lane[dr, dc] = ref_eval(clip, attrs, qc + dc + 0.5, qr + dr + 0.5, width, height)
    own_r, own_c = (row % 2, col % 2) if mode == "fine" else (0, 0)

    def diff(pairs):
        for p, q in pairs:
            if lane[p][1] > 0 and lane[q][1] > 0:
                return lane[q][0] - lane[p][0]
        return None

    ddx = diff([((own_r, 0), (own_r, 1)), ((1 - own_r, 0), (1 - own_r, 1))])
    ddy = diff([((0, own_c), (1, own_c)), ((0, 1 - own_c), (1, 1 - own_c))])
    return ddx, ddy


def ref_exact(clip, attrs, row, col, width=W, height=H, h=1e-5):
    """Central differences of the exact mapping at the pixel centre (the last resort)."""
    x, y = col + 0.5, row + 0.5

    def f(px, py):
        return ref_eval(clip, attrs, px, py, width, height)[0]

    return (f(x + h, y) - f(x - h, y)) / (2 * h), (f(x, y + h) - f(x, y - h)) / (2 * h)


def random_tri(rng, near=1.0, far=6.0):
    """A perspective clip-space triangle mostly on screen: w in [near, far], z inside."""
    w = rng.uniform(near, far, 3)
    ndc = rng.uniform(-1.1, 1.1, (3, 2))
    z = rng.uniform(-0.9, 0.9, 3) * w
    return np.column_stack([ndc * w[:, None], z, w])


@pytest.mark.parametrize("mode", ["coarse", "fine"])
def test_derivatives_match_the_exact_mapping(rng, mode):
    checked = exacts = 0
    for _ in range(25):
        clip = random_tri(rng)
        attrs = rng.uniform(-2, 2, (3, 3))
        frame = tr.render(clip[None], W, H, attrs=attrs[None], derivatives=mode)
        assert frame.ddx.shape == frame.ddy.shape == (H, W, 3)
        cov = frame.coverage
        assert np.isnan(frame.ddx[~cov]).all() and np.isnan(frame.ddy[~cov]).all()
        assert np.isfinite(frame.ddx[cov]).all() and np.isfinite(frame.ddy[cov]).all()
        for r, c in zip(*np.nonzero(cov)):
            ddx, ddy = ref_derivatives(clip, attrs, r, c, mode)
            ex, ey = ref_exact(clip, attrs, r, c)
            scale = 1 + np.abs(attrs).max()
            for got, want, exact in ((frame.ddx, ddx, ex), (frame.ddy, ddy, ey)):
                if want is None:  # both rows (columns) reach beyond the horizon
                    np.testing.assert_allclose(got[r, c], exact, rtol=1e-5, atol=1e-6 * scale)
                    exacts += 1
                else:
                    np.testing.assert_allclose(got[r, c], want, rtol=1e-9, atol=1e-9 * scale)
            checked += 1
    assert checked > 500 and exacts > 0


def test_coarse_is_one_pair_per_quad_fine_differs_per_row():
    clip = np.array([[[-1, -1, 0, 1], [3, -1, 0, 4], [-1, 3, 0, 2]]], float)
    uv = np.array([[[0, 0], [1, 0], [0, 1]]], float)
    coarse = tr.render(clip, 8, 8, attrs=uv, derivatives=True)
    fine = tr.render(clip, 8, 8, attrs=uv, derivatives="fine")
    full = coarse.coverage
    for r in range(0, 8, 2):
        for c in range(0, 8, 2):
            if full[r : r + 2, c : c + 2].all():
                block = coarse.ddx[r : r + 2, c : c + 2].reshape(4, 2)
                assert (block == block[0]).all()
                assert not np.array_equal(fine.ddx[r, c], fine.ddx[r + 1, c])  # perspective
    np.testing.assert_array_equal(coarse.ddx[0::2, 0::2], fine.ddx[0::2, 0::2])


def test_helpers_are_never_written_and_change_nothing(rng):
    clip = np.stack([random_tri(rng) for _ in range(6)])
    attrs = rng.uniform(0, 1, (6, 3, 2))
    a = tr.render(clip, W, H, attrs=attrs)
    b = tr.render(clip, W, H, attrs=attrs, derivatives=True, trace=True)
    np.testing.assert_array_equal(a.triangle_id, b.triangle_id)
    np.testing.assert_array_equal(a.attrs, b.attrs)
    np.testing.assert_array_equal(a.depth, b.depth)
    assert a.ddx is None and b.plan["derivatives"].ran and not a.plan["derivatives"].ran


def test_each_triangle_uses_its_own_helpers():
    # Two triangles share the diagonal of the frame but map uv discontinuously (0..1 on the
    # left triangle, 10..11 on the right): a quad on the diagonal must not mix them.
    clip = np.array(
        [
            [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]],
            [[1, -1, 0, 1], [1, 1, 0, 1], [-1, 1, 0, 1]],
        ],
        float,
    )
    uv = np.array([[[0, 0], [1, 0], [0, 1]], [[11, 10], [11, 11], [10, 11]]], float)
    frame = tr.render(clip, 8, 8, attrs=uv, derivatives=True, trace=True)
    np.testing.assert_allclose(frame.ddx[frame.coverage], np.broadcast_to([1 / 8, 0], (64, 2)))
    np.testing.assert_allclose(frame.ddy[frame.coverage], np.broadcast_to([0, -1 / 8], (64, 2)))
    quads = frame.trace.quads
    straddling = len(quads.row) - len(set(zip(quads.row.tolist(), quads.col.tolist())))
    assert straddling == 4  # the quads on the diagonal are evaluated once per triangle


def test_trace_records_quads_helpers_and_shaded_values(rng):
    clip = np.stack([random_tri(rng) for _ in range(4)])
    attrs = rng.uniform(0, 1, (4, 3, 2))
    frame = tr.render(clip, W, H, attrs=attrs, derivatives=True, trace=True)
    q = frame.trace.quads
    shown = np.zeros((H + 1, W + 1), dtype=int)
    for i in range(len(q.row)):
        for lane, (dc, dr) in enumerate([(0, 0), (1, 0), (0, 1), (1, 1)]):
            r, c = q.row[i] + dr, q.col[i] + dc
            if q.shaded[i, lane]:
                assert frame.triangle_id[r, c] == q.triangle[i]
                np.testing.assert_allclose(q.values[i, lane], frame.attrs[r, c], atol=1e-9)
                shown[r, c] += 1
            elif r < H and c < W:
                assert frame.triangle_id[r, c] != q.triangle[i]
    assert (shown[:H, :W] == frame.coverage).all()  # each visible pixel in exactly one pair
    assert q.helpers == 4 * len(q.row) - frame.coverage.sum()
    eff = frame.plan["derivatives"]
    assert eff.count == frame.coverage.sum() and f"{q.helpers:,} helper" in eff.why


def test_helpers_beyond_the_horizon_are_avoided():
    # Vertex 2 sits almost on the triangle's horizon (w = 1e9): lanes one pixel beyond it
    # extrapolate to 1/w < 0. Their differences come from lanes in front of the horizon.
    w = np.array([1.0, 1.0, 1e9])
    ndc = np.array([[-0.9, -0.9], [0.9, -0.9], [0.05, 1 - 10 / 18]])  # vertex 2 at y = 5.0
    clip = np.column_stack([ndc * w[:, None], np.zeros(3), w])
    uv = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 1.0]])
    frame = tr.render(clip[None], W, H, attrs=uv[None], derivatives=True, trace=True)
    q = frame.trace.quads
    assert (q.inv_w <= 0).any() and q.fallback.any()
    cov = frame.coverage
    assert np.isfinite(frame.ddx[cov]).all() and np.isfinite(frame.ddy[cov]).all()
    assert "beyond the horizon" in frame.plan["derivatives"].why
    for r, c in zip(*np.nonzero(cov)):
        ddx, ddy = ref_derivatives(clip, uv, r, c)
        if ddx is not None:
            np.testing.assert_allclose(frame.ddx[r, c], ddx, rtol=1e-6, atol=1e-9)
        if ddy is not None:
            np.testing.assert_allclose(frame.ddy[r, c], ddy, rtol=1e-6, atol=1e-9)


def test_affine_interpolation_has_constant_derivatives(rng):
    clip = random_tri(rng)[None]
    attrs = rng.uniform(0, 1, (1, 3, 2))
    frame = tr.render(clip, W, H, attrs=attrs, derivatives="fine", interpolation="affine")
    d = frame.ddx[frame.coverage]
    np.testing.assert_allclose(d, np.broadcast_to(d[0], d.shape), atol=1e-12)


@pytest.mark.parametrize("bad", ["yes", 1, "Coarse", [True]])
def test_bad_derivatives_name_the_argument(bad):
    with pytest.raises(ValueError, match="derivatives"):
        tr.render(np.zeros((1, 3, 4)) + [0, 0, 0, 1], 4, 4, derivatives=bad)


def test_bad_derivatives_where_names_the_argument():
    clip = np.array([[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]], float)
    with pytest.raises(ValueError, match="derivatives_where"):
        tr.render(clip, 4, 4, derivatives=True, derivatives_where=[True, False])


# -- the plan: derivatives only where a mipmapped filter minifies -------------------------------
def magnified_scene():
    """A small textured square right in front of the camera: magnified everywhere."""
    mesh = Mesh(
        [[-1.0, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
        [[0, 1, 2], [0, 2, 3]],
        {"uv": [[0, 1], [1, 1], [1, 0], [0, 0]]},
    )
    cam = tr.Camera(eye=(0.3, 0.2, 2.5), target=(0, 0, 0))
    return Scene("square", "magnified", mesh, cam, texture=tr.checkerboard(2, 8), shading="texture")


@pytest.mark.parametrize("filter", ["trilinear", "nearest_mipmap_nearest", "anisotropic"])
def test_magnified_scene_skips_derivatives_with_the_same_image(filter):
    scene = magnified_scene()
    planned = tr.render(scene, width=64, height=48, texture_filter=filter)
    forced = tr.render(scene, width=64, height=48, texture_filter=filter, force="derivatives")
    eff = planned.plan["derivatives"]
    assert not eff.ran and eff.count == 0 and "magnified everywhere" in eff.why
    assert forced.plan["derivatives"].forced and forced.plan["derivatives"].count > 0
    lam = tr.mip_level(forced.ddx, forced.ddy, scene.texture.shape)
    assert np.nanmax(lam) <= 0
    np.testing.assert_array_equal(planned.image, forced.image)
    np.testing.assert_array_equal(planned.image, tr.render(scene, width=64, height=48,
                                                           texture_filter="bilinear"
                                                           if filter != "nearest_mipmap_nearest"
                                                           else "nearest").image)  # fmt: skip


@pytest.mark.parametrize("filter", ["trilinear", "linear_mipmap_nearest", "anisotropic"])
def test_floor_scene_needs_derivatives_and_planned_equals_forced(filter):
    scene = get_scene("textured_floor")
    planned = tr.render(scene, width=96, height=72, texture_filter=filter)
    forced = tr.render(scene, width=96, height=72, texture_filter=filter, force="all")
    assert planned.plan["derivatives"].ran
    assert "may be minified on 2 of 2" in planned.plan["derivatives"].why
    np.testing.assert_array_equal(planned.image, forced.image)
    # the scene's image is sample() of the clip render's derivatives
    clip = scene.clip(96 / 72)
    frame = tr.render(clip, 96, 72, attrs=scene.mesh.corner("uv"), derivatives=True)
    want = tr.sample(scene.texture, frame.attrs, filter, ddx=frame.ddx, ddy=frame.ddy)
    np.testing.assert_array_equal(planned.image, want)


def test_bilinear_scene_plan_says_no_mipmaps():
    frame = tr.render(get_scene("textured_floor"), width=32, height=24, texture_filter="bilinear")
    assert not frame.plan["derivatives"].ran and "uses no mipmaps" in frame.plan["derivatives"].why
    with pytest.raises(ValueError, match="texture_filter"):
        tr.render(get_scene("textured_floor"), width=8, height=8, texture_filter="cubic")


def test_may_minify_is_conservative(rng):
    """Where it says magnified, the forced quad derivatives never give λ > 0."""
    said_no = 0
    for _ in range(60):
        clip = random_tri(rng, near=0.5, far=3)[None]
        uv = rng.uniform(0, 1, (1, 3, 2)) * rng.choice([0.05, 0.3, 2.0])
        shape = (int(rng.integers(2, 40)),) * 2
        flag = may_minify(clip, uv, W, H, shape)[0]
        frame = tr.render(clip, W, H, attrs=uv, derivatives=True)
        lam = tr.mip_level(frame.ddx, frame.ddy, shape)
        if not flag:
            said_no += 1
            assert not (lam > 0).any()
    assert said_no > 5


def test_forcing_other_effects_leaves_derivatives_unchanged(rng):
    for _ in range(10):
        clip = np.stack([random_tri(rng) for _ in range(5)])
        attrs = rng.uniform(0, 1, (5, 3, 2))
        a = tr.render(clip, W, H, attrs=attrs, derivatives=True)
        b = tr.render(clip, W, H, attrs=attrs, derivatives=True, force="all")
        np.testing.assert_allclose(a.ddx, b.ddx, rtol=0, atol=1e-12)
        np.testing.assert_allclose(a.ddy, b.ddy, rtol=0, atol=1e-12)
