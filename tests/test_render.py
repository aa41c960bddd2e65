"""``tr.render``: the clip-space scene pipeline against the single-triangle rasteriser.

References here are built from ``tr.rasterize`` (one triangle at a time, window coordinates
from ``tr.to_window``), from CONVENTIONS.md, or from plain Python loops (the z-buffer), never
from the pipeline's own batch code. The scene convenience ``tr.render(scene, camera, W, H)``
and bad-input handling are tested at the end.
"""

from __future__ import annotations

import numpy as np
import pytest

import teachraster as tr
from teachraster.pipeline.depth import quantize
from teachraster.pipeline.scenes import SCENES, get_scene
from teachraster.pipeline.texture import texel_error

W, H = 24, 18


# -- helpers (also imported by the other scene-pipeline test files) ----------------------------
def clip_from_window(xy, z=0.5, w=1.0, width=W, height=H) -> np.ndarray:
    """Clip coordinates (..., 4) whose window position is ``xy`` (..., 2), depth ``z``, w ``w``."""
    xy = np.asarray(xy, dtype=np.float64)
    z = np.broadcast_to(np.asarray(z, dtype=np.float64), xy.shape[:-1])
    w = np.broadcast_to(np.asarray(w, dtype=np.float64), xy.shape[:-1])
    x = (2 * xy[..., 0] / width - 1) * w
    y = (1 - 2 * xy[..., 1] / height) * w
    return np.stack([x, y, (2 * z - 1) * w, w], axis=-1)


def random_clip(rng, n, *, equal_w=False, cross=False, spread=1.3) -> np.ndarray:
    """``n`` random clip-space triangles (n, 3, 4), overlapping on screen.

    ``cross=True`` lets vertices leave -w <= z <= w (near/far crossings) and puts some behind
    the eye (w < 0); otherwise every vertex is strictly inside and nothing is clipped.
    """
    w = rng.uniform(0.3, 3.0, (n, 3))
    if equal_w:
        w[:] = w[:, :1]
    ndc = rng.uniform(-spread, spread, (n, 3, 2))
    zn = rng.uniform(-0.95, 0.95, (n, 3))
    if cross:
        zn = rng.uniform(-1.8, 1.8, (n, 3))
        w = np.where(rng.random((n, 3)) < 0.15, -w, w)
    return np.concatenate([ndc * w[..., None], (zn * w)[..., None], w[..., None]], axis=-1)


def reference_fill(clip_tri, attrs_tri, width=W, height=H, **kwargs):
    """``tr.rasterize`` of one unclipped clip-space triangle: window xy and z, clip w."""
    win = tr.to_window(clip_tri, width, height)
    attrs = {} if attrs_tri is None else {"a": np.asarray(attrs_tri, dtype=np.float64)}
    tri = tr.Triangle(win[:, :2], w=clip_tri[:, 3], z=win[:, 2], attrs=attrs)
    return tr.rasterize(tri, width, height, **kwargs)


def sequential_zbuffer(trace, width, height, depth_test=True):
    """Replay the trace's fragments one by one through a plain z-buffer.

    Returns (owner (H, W) of input-triangle ids, passed list of bools), with CONVENTIONS'
    rule: a fragment passes when strictly nearer than the stored depth (or always, without
    the depth test).
    """
    buffer = {}
    owner = np.full(width * height, -1, dtype=np.int64)
    passed = []
    for t, r, c, d in zip(
        trace.fragment_triangle.tolist(),
        trace.fragment_row.tolist(),
        trace.fragment_col.tolist(),
        trace.fragment_depth.tolist(),
    ):
        p = r * width + c
        ok = (not depth_test) or d < buffer.get(p, float("inf"))
        if ok:
            buffer[p] = d
            owner[p] = t
        passed.append(ok)
    return owner.reshape(height, width), passed


def assert_uncovered_is_nan(frame):
    """triangle_id -1 exactly where depth and every attribute are NaN."""
    out = frame.triangle_id < 0
    assert (frame.triangle_id >= -1).all()
    np.testing.assert_array_equal(np.isnan(frame.depth), out)
    if frame.attrs.shape[-1]:
        np.testing.assert_array_equal(np.isnan(frame.attrs).all(axis=-1), out)
        assert np.isfinite(frame.attrs[~out]).all()


def unsnapped_values(clip_tri, attrs_tri, rows, cols, interpolation, width=W, height=H):
    """Attributes (n, k) and depth (n,) at pixel centres from the *unsnapped* window triangle.

    Barycentrics λ_k = E(v_k+1, v_k+2, p) / E(v0, v1, v2) of the float window positions (what
    GPUs use for attribute set-up), then Σ λ f (affine) or Σ λ f / w / Σ λ / w (perspective),
    clamped to the vertex values' range. For the attributes λ is first made convex (negative
    weights, at covered centres that snapping brought inside an edge, clamped to 0 and the row
    renormalised: a covered centre gets a convex combination); depth extrapolates as llvmpipe's
    plane equation does, clamped to the vertex depths.
    """
    win = tr.to_window(clip_tri, width, height)
    v = win[:, :2]
    p = np.stack([cols + 0.5, rows + 0.5], 1)

    def edge(a, b):
        return (b[0] - a[0]) * (p[:, 1] - a[1]) - (b[1] - a[1]) * (p[:, 0] - a[0])

    area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
    lam = np.stack([edge(v[1], v[2]), edge(v[2], v[0]), edge(v[0], v[1])], 1) / area
    mu = np.maximum(lam, 0)
    mu = mu / mu.sum(axis=1, keepdims=True)
    if interpolation == "perspective":
        mu = mu / clip_tri[:, 3]
        mu = mu / mu.sum(axis=1, keepdims=True)
    a = np.asarray(attrs_tri, dtype=np.float64)
    values = np.clip(mu @ a, a.min(axis=0), a.max(axis=0))
    depth = np.clip(lam @ win[:, 2], win[:, 2].min(), win[:, 2].max())
    return values, depth


# -- one triangle: as tr.rasterize ---------------------------------------------------------------
@pytest.mark.parametrize("bits", [8, None])
@pytest.mark.parametrize("interpolation", ["perspective", "affine"])
def test_single_triangle_as_rasterize(rng, interpolation, bits):
    """Coverage identical to tr.rasterize (window xy and z from to_window, w = clip w); attrs
    (perspective or affine) and depth within 1e-12 of the same interpolation with weights
    from the unsnapped window positions (GPU attribute set-up, commit 7f805fb) -- which,
    with subpixel_bits=None, is exactly tr.rasterize's own result."""
    differs = 0.0
    for _ in range(150):
        clip = random_clip(rng, 1)
        attrs = rng.uniform(-2, 2, (1, 3, 2))
        frame = tr.render(clip, W, H, attrs=attrs, interpolation=interpolation, subpixel_bits=bits)
        fill = reference_fill(clip[0], attrs[0], interpolation=interpolation, subpixel_bits=bits)
        msg = f"clip={clip.tolist()}, subpixel_bits={bits}"
        np.testing.assert_array_equal(frame.triangle_id == 0, fill.coverage, err_msg=msg)
        np.testing.assert_array_equal(frame.triangle_id[~fill.coverage], -1)
        assert_uncovered_is_nan(frame)
        rows, cols = np.nonzero(fill.coverage)
        values, depth = unsnapped_values(clip[0], attrs[0], rows, cols, interpolation)
        np.testing.assert_allclose(frame.attrs[rows, cols], values, rtol=0, atol=1e-12, err_msg=msg)
        np.testing.assert_allclose(frame.depth[rows, cols], depth, rtol=0, atol=1e-12, err_msg=msg)
        if bits is None:
            np.testing.assert_allclose(frame.attrs, fill.attrs["a"], rtol=0, atol=1e-12)
            np.testing.assert_allclose(frame.depth, fill.depth, rtol=0, atol=1e-12)
        if len(rows):
            other = "affine" if interpolation == "perspective" else "perspective"
            alt, _ = unsnapped_values(clip[0], attrs[0], rows, cols, other)
            differs = max(differs, float(np.abs(alt - frame.attrs[rows, cols]).max()))
    assert differs > 1e-2  # the two modes really differ on these triangles: the test can tell


def test_single_triangle_span_and_halfplane_and_no_snapping(rng):
    """The same holds with subpixel_bits=4 and None (the batch honours the precision)."""
    for bits in (4, None):
        for _ in range(40):
            clip = random_clip(rng, 1)
            frame = tr.render(clip, W, H, subpixel_bits=bits)
            fill = reference_fill(clip[0], None, subpixel_bits=bits, method="span")
            np.testing.assert_array_equal(frame.triangle_id == 0, fill.coverage)


def test_attrs_n3_same_as_n31(rng):
    """attrs of shape (N, 3) give the same single channel as (N, 3, 1)."""
    clip = random_clip(rng, 6)
    a = rng.uniform(0, 1, (6, 3))
    f2 = tr.render(clip, W, H, attrs=a)
    f3 = tr.render(clip, W, H, attrs=a[:, :, None])
    assert f2.attrs.shape == f3.attrs.shape == (H, W, 1)
    np.testing.assert_array_equal(f2.attrs, f3.attrs)
    np.testing.assert_array_equal(f2.triangle_id, f3.triangle_id)


def test_no_attrs_gives_zero_channels():
    """Without attrs, attrs is (H, W, 0); triangle_id is int and -1 outside."""
    frame = tr.render(clip_from_window([[[2, 2], [20, 3], [5, 15]]]), W, H)
    assert frame.attrs.shape == (H, W, 0)
    assert frame.triangle_id.dtype.kind == "i"
    assert (frame.triangle_id == -1).any() and (frame.triangle_id == 0).any()
    np.testing.assert_array_equal(frame.coverage, frame.triangle_id >= 0)


def test_depth_is_window_depth():
    """Constant NDC z = 0.3 gives window depth 0.65 (z/2 + 1/2) at every covered pixel."""
    clip = np.array([[[-1, -1, 0.3, 1], [1, -1, 0.3, 1], [-1, 1, 0.3, 1]]]) * 2.0  # w = 2
    frame = tr.render(clip, W, H)
    d = frame.depth[frame.coverage]
    assert d.size > 0
    np.testing.assert_allclose(d, 0.65, rtol=0, atol=1e-15)


def test_clip_positions_follow_the_viewport_transform():
    """A clip triangle lands on the pixels of its window-space image (y down, row 0 on top)."""
    xy = np.array([[1.0, 1.0], [9.0, 1.0], [1.0, 5.0]])
    frame = tr.render(clip_from_window(xy[None], w=2.5), W, H)
    want = tr.rasterize(tr.Triangle(xy), W, H).coverage
    np.testing.assert_array_equal(frame.coverage, want)
    assert frame.coverage[1, 1] and not frame.coverage[H - 2, 1]


# -- the z-buffer ------------------------------------------------------------------------------
SQUARE = np.array([[[2, 2], [20, 2], [2, 16]], [[20, 2], [20, 16], [2, 16]]], dtype=float)
BIG = np.array([[-5, -5], [60, -5], [-5, 60]], dtype=float)


def two_layers(z_first, z_second):
    """Two full-screen triangles at constant window depths, drawn first then second."""
    return np.stack([clip_from_window(BIG, z_first), clip_from_window(BIG, z_second, w=2.0)])


@pytest.mark.parametrize("fmt", tr.DEPTH_FORMATS)
def test_nearer_wins_in_either_order(fmt):
    """Strictly smaller depth wins whichever triangle is drawn first."""
    for a, b, want in ((0.3, 0.7, 0), (0.7, 0.3, 1)):
        frame = tr.render(two_layers(a, b), W, H, depth_format=fmt)
        assert (frame.triangle_id == want).all()
        np.testing.assert_allclose(frame.depth, min(a, b), atol=2e-5)


def test_exact_ties_keep_the_earlier_triangle():
    """Equal depth: the first drawn keeps the pixel (strictly-smaller test)."""
    frame = tr.render(two_layers(0.5, 0.5), W, H)
    assert (frame.triangle_id == 0).all()
    three = np.concatenate([two_layers(0.6, 0.4), two_layers(0.4, 0.9)])  # ids 0..3
    frame = tr.render(three, W, H)
    assert (frame.triangle_id == 1).all()  # 1 and 2 tie at 0.4; 1 came first


def test_depth_test_off_later_overwrites():
    """depth_test=False: the last triangle drawn wins, even when it is farther."""
    frame = tr.render(two_layers(0.2, 0.9), W, H, depth_test=False)
    assert (frame.triangle_id == 1).all()
    np.testing.assert_allclose(frame.depth, 0.9)
    assert not frame.plan["depth_test"].ran


def test_z_fighting_appears_with_unorm16_not_float64():
    """Two nearly coplanar tilted planes 2e-6 apart: float64 and float32 always see the nearer
    (drawn second); a 16-bit buffer stores equal depths at most pixels, ties go to the
    earlier, farther one, and the winner alternates in stripes (z-fighting)."""
    xy = np.array([[-2, -2], [60, -2], [-2, 60]], dtype=float)  # covers the whole image
    z = np.array([0.40, 0.41, 0.43])
    clip = np.stack([clip_from_window(xy, z), clip_from_window(xy, z - 2e-6)])
    for fmt in ("float64", "float32", "unorm24"):
        assert (tr.render(clip, W, H, depth_format=fmt).triangle_id == 1).all(), fmt
    ids = tr.render(clip, W, H, depth_format="unorm16").triangle_id
    assert (ids >= 0).all()
    assert (ids == 0).sum() > 0.3 * ids.size and (ids == 1).sum() > 0  # both show: a fight
    switches = (np.diff(ids, axis=1) != 0).sum()
    assert switches >= 3  # not a clean split but stripes


@pytest.mark.parametrize("fmt", tr.DEPTH_FORMATS)
def test_stored_depth_is_quantised(rng, fmt):
    """frame.depth is what the buffer stores: quantize(window depth, depth_format)."""
    clip = random_clip(rng, 5)
    exact = tr.render(clip, W, H, depth_format="float64", depth_test=False)
    frame = tr.render(clip, W, H, depth_format=fmt, depth_test=False)
    np.testing.assert_array_equal(frame.triangle_id, exact.triangle_id)
    np.testing.assert_array_equal(frame.depth, quantize(exact.depth, fmt))


@pytest.mark.parametrize("bits", [8, None])
@pytest.mark.parametrize("depth_test", [True, False])
@pytest.mark.parametrize("fmt", ["float64", "unorm16"])
def test_trace_matches_a_sequential_zbuffer(rng, depth_test, fmt, bits):
    """Replaying the traced fragments in drawing order through a Python z-buffer gives the
    same pass/fail per fragment and the same final triangle ids; each triangle's fragments
    are exactly tr.rasterize's coverage (and, unsnapped, its quantised window depth)."""
    for scene in range(40):
        n = int(rng.integers(1, 9))
        clip = random_clip(rng, n, spread=0.9)
        if scene % 4 == 0:  # exact ties: a repeated triangle
            clip = np.concatenate([clip, clip[:1]])
        frame = tr.render(
            clip, W, H, trace=True, depth_test=depth_test, depth_format=fmt, subpixel_bits=bits
        )
        t = frame.trace
        assert (np.diff(t.fragment_triangle) >= 0).all()  # drawing order = input order
        owner, passed = sequential_zbuffer(t, W, H, depth_test)
        np.testing.assert_array_equal(t.fragment_passed, passed)
        np.testing.assert_array_equal(frame.triangle_id, owner)
        for k in range(len(clip)):
            fill = reference_fill(clip[k], None, subpixel_bits=bits)
            mine = t.fragment_triangle == k
            got = np.zeros((H, W), dtype=bool)
            got[t.fragment_row[mine], t.fragment_col[mine]] = True
            assert mine.sum() == got.sum()
            np.testing.assert_array_equal(got, fill.coverage)
            if bits is not None:
                continue  # depth: see test_single_triangle_equals_rasterize
            np.testing.assert_allclose(
                t.fragment_depth[mine],
                quantize(fill.depth[t.fragment_row[mine], t.fragment_col[mine]], fmt),
                rtol=0,
                atol=1e-12,
            )
        assert (t.clip_status == 0).all() and not t.culled.any()


def test_trace_does_not_change_pixels(rng):
    """render(trace=True) gives the same ids, attrs and depth as trace=False."""
    for _ in range(20):
        clip = random_clip(rng, 6, cross=True)
        attrs = rng.uniform(0, 1, (6, 3, 2))
        for kw in ({}, {"cull": "back"}, {"depth_test": False}, {"depth_format": "unorm16"}):
            a = tr.render(clip, W, H, attrs=attrs, **kw)
            b = tr.render(clip, W, H, attrs=attrs, trace=True, **kw)
            assert a.trace is None and b.trace is not None
            np.testing.assert_array_equal(a.triangle_id, b.triangle_id)
            np.testing.assert_array_equal(a.attrs, b.attrs)
            np.testing.assert_array_equal(a.depth, b.depth)


def test_zbuffer_equals_nearest_of_rasterize(rng):
    """With float64 depth, every pixel shows the nearest triangle there (ties: earliest), as
    computed from per-triangle tr.rasterize depth images (unsnapped: same weights)."""
    for _ in range(30):
        clip = random_clip(rng, 7)
        frame = tr.render(clip, W, H, subpixel_bits=None)
        depths = np.stack([reference_fill(c, None, subpixel_bits=None).depth for c in clip])
        stack = np.where(np.isnan(depths), np.inf, depths)
        want = np.where(np.isfinite(stack).any(axis=0), np.argmin(stack, axis=0), -1)
        np.testing.assert_array_equal(frame.triangle_id, want)


# -- culling -------------------------------------------------------------------------------
CW = np.array([[2.0, 2.0], [20.0, 3.0], [4.0, 15.0]])  # E(v0, v1, v2) > 0: clockwise on screen


def test_cull_back_removes_clockwise_on_screen():
    """cull='back' drops a triangle with positive signed area in y-down window numbers,
    'front' keeps it; the reversed winding behaves the other way round."""
    assert tr.Triangle(CW).signed_area > 0
    cw, ccw = clip_from_window(CW[None]), clip_from_window(CW[None, [0, 2, 1]])
    assert not tr.render(cw, W, H, cull="back").coverage.any()
    assert tr.render(cw, W, H, cull="front").coverage.any()
    assert tr.render(ccw, W, H, cull="back").coverage.any()
    assert not tr.render(ccw, W, H, cull="front").coverage.any()
    assert tr.render(cw, W, H).coverage.any() and tr.render(ccw, W, H).coverage.any()


def test_culling_equals_rasterize_cull(rng):
    """With culling, each pixel's owner is computed from tr.rasterize(cull=...) fills."""
    for cull in ("back", "front"):
        for _ in range(30):
            clip = random_clip(rng, 6)
            frame = tr.render(clip, W, H, cull=cull, subpixel_bits=None)
            depths = []
            for c in clip:
                win = tr.to_window(c, W, H)
                tri = tr.Triangle(win[:, :2], z=win[:, 2])
                fill = tr.rasterize(tri, W, H, cull=cull, subpixel_bits=None)
                depths.append(np.where(fill.coverage, fill.depth, np.inf))
            depths = np.stack(depths)
            want = np.where(np.isfinite(depths).any(axis=0), np.argmin(depths, axis=0), -1)
            np.testing.assert_array_equal(frame.triangle_id, want, err_msg=cull)
            plan = frame.plan["culling"]
            assert plan.ran and plan.why


def test_cull_decides_on_the_snapped_triangle():
    """A sliver whose float winding is counter-clockwise but whose snapped (drawn) triangle is
    clockwise: render(cull=...) must agree with tr.rasterize(cull=...), which decides on the
    snapped triangle that is actually filled (a horizontal top edge through the centres)."""
    y0 = 0.5
    xy = np.array([[0.0, y0 - 0.45 / 256], [20.0, y0 + 0.45 / 256], [200.0, y0 + 0.6 / 256]])
    # float: counter-clockwise (front); snapped: (0, .5), (20, .5), (200, .5 + 1/256), clockwise
    assert tr.Triangle(xy).signed_area < 0
    snapped = tr.snap(xy)
    assert tr.Triangle(snapped).signed_area > 0
    plain = tr.rasterize(tr.Triangle(xy), W, H).coverage
    assert plain.sum() >= 10  # it covers the centres on its top edge
    clip = clip_from_window(xy[None])
    for cull in (None, "back", "front"):
        want = tr.rasterize(tr.Triangle(xy), W, H, cull=cull).coverage
        got = tr.render(clip, W, H, cull=cull).coverage
        # guard: the float round trip through clip space keeps the same snapped vertices
        np.testing.assert_array_equal(tr.snap(tr.to_window(clip[0], W, H)[:, :2]), snapped)
        np.testing.assert_array_equal(got, want, err_msg=f"cull={cull!r}")


# -- scenes: tr.render(scene, camera, W, H) ------------------------------------------------
SW, SH = 64, 48


@pytest.mark.parametrize("name", list(SCENES))
def test_scene_image_finite_where_covered_nan_elsewhere(name):
    """image is (H, W, 3), finite exactly on covered pixels; only scene.uses interpolated."""
    scene = get_scene(name)
    frame = tr.render(scene, None, SW, SH)
    assert isinstance(frame, tr.SceneFrame)
    assert frame.image.shape == (SH, SW, 3)
    cov = frame.triangle_id >= 0
    assert cov.any(), name
    assert np.isfinite(frame.image[cov]).all()
    assert np.isnan(frame.image[~cov]).all()
    assert sorted(frame.layout) == sorted(scene.uses)
    width = sum(frame.layout[n].stop - frame.layout[n].start for n in frame.layout)
    assert frame.attrs.shape == (SH, SW, width)
    assert_uncovered_is_nan(frame)
    skipped = set(scene.mesh.attrs) - set(scene.uses)
    why = frame.plan["attributes"].why
    assert all(s in why for s in skipped), why


@pytest.mark.parametrize("name", list(SCENES))
def test_scene_force_attributes_interpolates_all_with_identical_values(name):
    """force='attributes' interpolates every mesh attribute; the used ones are unchanged."""
    scene = get_scene(name)
    plain = tr.render(scene, None, SW, SH)
    every = tr.render(scene, None, SW, SH, force="attributes")
    assert sorted(every.layout) == sorted(scene.mesh.attrs)
    np.testing.assert_array_equal(plain.triangle_id, every.triangle_id)
    for used in scene.uses:
        np.testing.assert_array_equal(plain.attr(used), every.attr(used))
    np.testing.assert_array_equal(plain.image, every.image)
    with pytest.raises(KeyError):
        plain.attr("normal")


def test_scene_render_equals_clip_render():
    """render(scene) is render(scene.clip(aspect), attrs=used attributes)."""
    scene = get_scene("cube")
    frame = tr.render(scene, None, SW, SH)
    clip = scene.clip(SW / SH)
    attrs = scene.mesh.corner("color")
    direct = tr.render(clip, SW, SH, attrs=attrs)
    np.testing.assert_array_equal(frame.triangle_id, direct.triangle_id)
    np.testing.assert_array_equal(frame.attr("color"), direct.attrs)
    np.testing.assert_array_equal(frame.image, direct.attrs)


def test_scene_with_another_camera():
    """An explicit camera replaces the scene's own."""
    scene = get_scene("single_triangle")
    cam = tr.Camera(eye=(0, 0, 30), target=(0, 0, 0))  # far away: a small triangle
    near = tr.render(scene, None, SW, SH).coverage.sum()
    far = tr.render(scene, cam, SW, SH).coverage.sum()
    assert 0 < far < near / 10


def _floor_uv_by_ray_casting(scene, width, height):
    """Exact uv of the floor (y = 0 plane) under each pixel centre, by casting rays."""
    inv = np.linalg.inv(scene.camera.matrix(width / height))
    rows, cols = np.mgrid[0:height, 0:width]
    ndc = np.stack([2 * (cols + 0.5) / width - 1, 1 - 2 * (rows + 0.5) / height], -1)
    ends = []
    for z in (-1.0, 1.0):
        p = np.concatenate([ndc, np.full((height, width, 1), z), np.ones((height, width, 1))], -1)
        q = p @ inv.T
        ends.append(q[..., :3] / q[..., 3:])
    a, b = ends
    t = a[..., 1] / (a[..., 1] - b[..., 1])
    hit = a + t[..., None] * (b - a)
    # plane_mesh(40) moved to z in [-40, 0]: u runs along +x, v along +z (0 far away)
    return np.stack([(hit[..., 0] + 20) / 40, (hit[..., 2] + 40) / 40], -1)


def test_textured_floor_affine_warps_perspective_is_exact():
    """Perspective-correct uv equals ray-cast uv (unsnapped, to 1e-6 texel); affine uv is off
    by many texels far away; along the centre column perspective uv is monotone in depth."""
    scene = get_scene("textured_floor")
    width, height = 80, 60
    persp = tr.render(scene, None, width, height, subpixel_bits=None)
    affine = tr.render(scene, None, width, height, subpixel_bits=None, interpolation="affine")
    np.testing.assert_array_equal(persp.triangle_id, affine.triangle_id)
    cov = persp.coverage
    assert cov.sum() > 0.3 * cov.size
    shape = scene.texture.shape
    exact = _floor_uv_by_ray_casting(scene, width, height)
    err_p = texel_error(persp.attr("uv")[cov], exact[cov], shape)
    err_a = texel_error(affine.attr("uv")[cov], exact[cov], shape)
    assert err_p.max() < 1e-6
    assert err_a.max() > 10  # the classic warp, many texels
    both = texel_error(persp.attr("uv")[cov], affine.attr("uv")[cov], shape)
    assert both.max() > 10
    col = width // 2
    rows = np.flatnonzero(cov[:, col])
    order = np.argsort(persp.depth[rows, col])
    v = persp.attr("uv")[rows[order], col, 1]
    assert (np.diff(v) < 0).all()  # farther away: smaller v (v = 0 at the far edge)


def test_textured_floor_default_snapping_still_close():
    """With the default 1/256 px snapping perspective uv stays within a texel of exact."""
    scene = get_scene("textured_floor")
    frame = tr.render(scene, None, 80, 60)
    exact = _floor_uv_by_ray_casting(scene, 80, 60)
    cov = frame.coverage
    assert texel_error(frame.attr("uv")[cov], exact[cov], scene.texture.shape).max() < 1.0


# -- bad input ---------------------------------------------------------------------------------
GOOD = np.array([[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]], dtype=float)


@pytest.mark.parametrize(
    "args, kwargs, error, match",
    [
        ((GOOD[0], 8, 8), {}, ValueError, "clip"),
        ((GOOD[:, :, :3], 8, 8), {}, ValueError, "clip"),
        ((np.where(np.eye(4, dtype=bool)[None, :3], np.nan, GOOD), 8, 8), {}, ValueError, "clip"),
        ((np.where(GOOD == 0, np.inf, GOOD), 8, 8), {}, ValueError, "clip"),
        ((np.full((1, 3, 4), "x"), 8, 8), {}, TypeError, "clip"),
        ((GOOD, 8, 8), {"attrs": np.zeros((2, 3))}, ValueError, "attrs"),
        ((GOOD, 8, 8), {"attrs": np.zeros((1, 2))}, ValueError, "attrs"),
        ((GOOD, 8, 8), {"attrs": [[0, 1, np.nan]]}, ValueError, "attrs"),
        ((GOOD, 0, 8), {}, ValueError, "width"),
        ((GOOD, 8, -1), {}, ValueError, "height"),
        ((GOOD, 8.0, 8), {}, TypeError, "width"),
        ((GOOD, 8, 8), {"cull": "backface"}, ValueError, "cull"),
        ((GOOD, 8, 8), {"depth_format": "unorm8"}, ValueError, "depth_format"),
        ((GOOD, 8, 8), {"interpolation": "smooth"}, ValueError, "interpolation"),
        ((GOOD, 8, 8), {"subpixel_bits": 40}, ValueError, "subpixel_bits"),
        ((GOOD, 8, 8), {"force": "zbuffer"}, ValueError, "force"),
        ((GOOD, 8, 8), {"force": ["clipping", "nope"]}, ValueError, "force"),
    ],
)
def test_render_rejects_bad_input_naming_the_argument(args, kwargs, error, match):
    """Each bad argument raises ValueError/TypeError whose message names it."""
    with pytest.raises(error, match=match):
        tr.render(*args, **kwargs)


def test_render_accepts_an_empty_scene():
    """No triangles: an empty frame, not an error."""
    frame = tr.render(np.zeros((0, 3, 4)), 5, 4)
    assert (frame.triangle_id == -1).all() and np.isnan(frame.depth).all()


def test_scene_render_rejects_bad_scene_and_camera():
    """render_scene names a wrong scene or camera type."""
    with pytest.raises(TypeError, match="scene"):
        tr.render_scene("cube", None, 8, 8)
    with pytest.raises(TypeError, match="camera"):
        tr.render(get_scene("cube"), "camera", 8, 8)


@pytest.mark.parametrize(
    "width, height, error, match",
    [
        (8, 0, ValueError, "height"),
        (0, 8, ValueError, "width"),
        (-4, 8, ValueError, "width"),
        ("8", 8, TypeError, "width"),
        (8, None, TypeError, "height"),
        (8, 6.0, TypeError, "height"),
    ],
)
def test_scene_render_bad_size_names_the_argument(width, height, error, match):
    """tr.render(scene, camera, width, height) checks the size like tr.render(clip, ...) does:
    the error is a ValueError/TypeError naming width or height (not a ZeroDivisionError from
    the aspect ratio)."""
    with pytest.raises(error, match=match):
        tr.render(get_scene("cube"), None, width, height)
