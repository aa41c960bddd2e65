"""Homogeneous clipping: triangles are cut in clip space, never mirrored or dropped whole.

The reference for what a partly hidden triangle should cover is computed here from the
geometry alone: the part of the 3D triangle with -w <= z <= w is a convex polygon whose
corners are the triangle's vertices inside that slab and the points where its edges cross
z = -w or z = w (plus a dense barycentric sampling of the inside, for good measure). Its
screen image is the convex hull of their projections. Every covered pixel centre must lie
within 1 px of that hull, and every pixel centre more than 1 px inside it must be covered.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_render import H, W, clip_from_window, random_clip, reference_fill

import teachraster as tr
from teachraster.pipeline.camera import perspective
from teachraster.pipeline.clipping import CLIPPED, DROPPED, INSIDE, W_MIN, clip_triangles
from teachraster.pipeline.scenes import get_scene

NEAR, FAR = 0.1, 20.0
PROJ = perspective(70.0, W / H, NEAR, FAR)


# -- the geometric reference -----------------------------------------------------------------
def in_slab_points(tri: np.ndarray, samples: int = 40) -> np.ndarray:
    """Clip-space points (n, 4) of the triangle with -w <= z <= w: corners and samples."""
    pts = []
    for k in range(3):
        a, b = tri[k], tri[(k + 1) % 3]
        pts.append(a)
        for sign in (1.0, -1.0):  # near plane z + w = 0, far plane w - z = 0
            da, db = sign * a[2] + a[3], sign * b[2] + b[3]
            if (da < 0) != (db < 0):
                pts.append(a + da / (da - db) * (b - a))
    i, j = np.mgrid[0 : samples + 1, 0 : samples + 1]
    keep = i + j <= samples
    lam = np.stack([i[keep], j[keep], samples - i[keep] - j[keep]], 1) / samples
    pts.extend(lam @ tri)
    pts = np.array(pts)
    tol = 1e-9 * np.abs(pts[:, 3:]).max()
    ok = (pts[:, 2] + pts[:, 3] >= -tol) & (pts[:, 3] - pts[:, 2] >= -tol)
    return pts[ok]


def convex_hull(points: np.ndarray) -> np.ndarray:
    """Counter-clockwise (in y-up terms: positive cross products) hull, Andrew's monotone chain."""
    pts = sorted(set(map(tuple, points.tolist())))
    if len(pts) <= 2:
        return np.array(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def hull_signed_distance(hull: np.ndarray, p: np.ndarray) -> np.ndarray:
    """Signed distance of points p (n, 2) to the convex hull: negative inside, positive out.

    Inside: minus the distance to the nearest edge line. Outside: distance to the polygon.
    """
    a, b = hull, np.roll(hull, -1, axis=0)
    d = b - a
    length = np.hypot(d[:, 0], d[:, 1])
    rel = p[:, None, :] - a[None]
    # distance to each edge's line; positive on the outside (hull is counter-clockwise)
    line = -(d[None, :, 0] * rel[..., 1] - d[None, :, 1] * rel[..., 0]) / length
    inside = (line <= 0).all(axis=1)
    t = np.clip((rel * d[None]).sum(-1) / length**2, 0, 1)
    seg = np.hypot(*(rel - t[..., None] * d[None]).transpose(2, 0, 1)).min(axis=1)
    return np.where(inside, line.max(axis=1), seg)


def check_against_hull(clip_tri: np.ndarray, coverage: np.ndarray, width=W, height=H):
    """Coverage within 1 px of the in-slab part's screen image, and covering its interior."""
    pts = in_slab_points(clip_tri)
    rows, cols = np.mgrid[0:height, 0:width]
    centres = np.stack([cols.ravel() + 0.5, rows.ravel() + 0.5], 1)
    if len(pts) == 0:
        assert not coverage.any()
        return
    xy = tr.to_window(pts, width, height)[:, :2]
    xy[:, 1] *= -1  # y up, so the hull is counter-clockwise in the usual sense
    hull = convex_hull(xy)
    if len(hull) < 3:
        assert not coverage.any()
        return
    flip = centres * [1, -1]
    dist = hull_signed_distance(hull, flip).reshape(height, width)
    msg = f"clip={clip_tri.tolist()}"
    bad_out = coverage & (dist > 1.0)
    assert not bad_out.any(), f"{msg}: covered but outside the visible part {np.argwhere(bad_out)}"
    missed = ~coverage & (dist < -1.0)
    assert not missed.any(), f"{msg}: visible part not covered at {np.argwhere(missed)}"


def perspective_triangles(rng, n, behind: int) -> np.ndarray:
    """``n`` view-space triangles through PROJ with exactly ``behind`` vertices behind the
    near plane (some of them behind the eye, w < 0), returned in clip space (n, 3, 4)."""
    out = []
    while len(out) < n:
        p = np.column_stack([rng.uniform(-4, 4, (3, 2)), rng.uniform(-6, 3, 3), np.ones(3)])
        c = p @ PROJ.T
        if (c[:, 3] < NEAR).sum() == behind and (c[:, 3] <= 0).any() == (behind > 0):
            out.append(c)
    return np.array(out)


# -- wholly in front ---------------------------------------------------------------------------
def test_wholly_inside_triangles_are_untouched(rng):
    """Inside triangles come out of the clipper bit-identical, with force=True as well."""
    clip = random_clip(rng, 50)
    attrs = rng.uniform(0, 1, (50, 3, 2))
    for force in (False, True):
        res = clip_triangles(clip, attrs, force=force)
        assert (res.status == INSIDE).all()
        np.testing.assert_array_equal(res.clip, clip)
        np.testing.assert_array_equal(res.attrs, attrs)
        np.testing.assert_array_equal(res.parent, np.arange(50))
        assert res.polygons == ()


# -- near plane: cut, never mirrored ---------------------------------------------------------
@pytest.mark.parametrize("behind", [1, 2])
def test_near_plane_cut_matches_the_visible_part(rng, behind):
    """One or two vertices behind the near plane (some behind the eye): the render covers
    the screen image of the in-front part, to within 1 px, and nothing else."""
    covered_some = 0
    mirrored_would_differ = 0
    for clip_tri in perspective_triangles(rng, 60, behind):
        frame = tr.render(clip_tri[None], W, H)
        check_against_hull(clip_tri, frame.coverage)
        covered_some += frame.coverage.any()
        # what dividing by a negative w would have drawn, for contrast
        naive = tr.to_window(clip_tri, W, H)[:, :2]
        if np.abs(naive).max() < 1e5:
            mirrored = tr.rasterize(tr.Triangle(naive), W, H).coverage
            mirrored_would_differ += (mirrored != frame.coverage).sum() > 3
    assert covered_some > 20
    assert mirrored_would_differ > 5  # the hull test would catch a mirrored triangle


def test_behind_camera_scene_is_cut_not_mirrored():
    """The built-in behind_camera scene: coverage follows the in-front part's projection."""
    scene = get_scene("behind_camera")
    clip = scene.clip(W / H)
    assert (clip[..., 3] < 0).any()
    frame = tr.render(clip, W, H, trace=True)
    assert frame.coverage.sum() > 20
    check_against_hull(clip[0], frame.coverage)
    assert frame.trace.clip_status.tolist() == [CLIPPED]
    assert frame.plan["clipping"].ran and frame.plan["clipping"].count == 1


def test_far_plane_cut_matches_the_visible_part(rng):
    """Triangles reaching beyond the far plane are cut there, not dropped or stretched."""
    n = 0
    while n < 40:
        p = np.column_stack([rng.uniform(-30, 30, (3, 2)), rng.uniform(-35, -5, 3), np.ones(3)])
        c = p @ PROJ.T
        beyond = (c[:, 2] > c[:, 3]).sum()
        if beyond not in (1, 2):
            continue
        n += 1
        frame = tr.render(c[None], W, H)
        check_against_hull(c, frame.coverage)
        assert np.nanmax(frame.depth, initial=0) <= 1.0


@pytest.mark.parametrize("bits", [8, None])
def test_random_crossings_cover_the_visible_part(rng, bits):
    """Hand-made clip coordinates crossing near, far, or the eye plane in any way."""
    for clip_tri in random_clip(rng, 150, cross=True):
        frame = tr.render(clip_tri[None], W, H, subpixel_bits=bits)
        check_against_hull(clip_tri, frame.coverage)


def test_wholly_hidden_triangles_are_dropped():
    """All behind the eye, all in front of near, or all beyond far: dropped, empty frame."""
    base = clip_from_window([[2, 2], [20, 3], [4, 15]], 0.5, 2.0)
    behind_eye = base * [1, 1, 1, -1]  # w < 0 at every vertex (and z > -w there)
    before_near = base.copy()
    before_near[:, 2] = -1.5 * base[:, 3]
    beyond_far = base.copy()
    beyond_far[:, 2] = 1.5 * base[:, 3]
    clip = np.stack([behind_eye, before_near, beyond_far])
    frame = tr.render(clip, W, H, trace=True)
    assert (frame.triangle_id == -1).all()
    assert frame.trace.clip_status.tolist() == [DROPPED] * 3
    assert "dropped" in frame.plan["clipping"].why
    # next to a visible triangle, the dropped ones leave it alone
    both = tr.render(np.concatenate([clip, base[None]]), W, H)
    np.testing.assert_array_equal(
        both.triangle_id, np.where(tr.render(base[None], W, H).coverage, 3, -1)
    )


# -- attributes of the new vertices --------------------------------------------------------------
def test_new_vertices_interpolate_linear_attributes_exactly(rng):
    """A linear function of clip position f = A·(x, y, z, w), given at the vertices, still
    equals A·v at every vertex the clipper creates; new vertices lie on the plane cut."""
    clip = random_clip(rng, 300, cross=True)
    A = rng.normal(size=(4, 3))
    res = clip_triangles(clip, clip @ A)
    assert (res.status == CLIPPED).sum() > 50 and (res.status == DROPPED).sum() > 10
    scale = np.abs(clip).max() * np.abs(A).sum(axis=0)
    np.testing.assert_allclose(res.attrs, res.clip @ A, rtol=0, atol=1e-12 * scale.max())
    v = res.clip.reshape(-1, 4)
    tol = 1e-12 * np.abs(clip).max()
    assert (v[:, 2] + v[:, 3] >= -tol).all() and (v[:, 3] - v[:, 2] >= -tol).all()
    assert (v[:, 3] > 0).all() and (v[:, 3] >= W_MIN - tol).all()  # never at or behind the eye
    # every output vertex is on the parent triangle's plane in clip space (a convex combo)
    for t, piece in zip(res.parent, res.clip):
        lam, *_ = np.linalg.lstsq(clip[t].T, piece.T, rcond=None)
        assert (lam >= -1e-9).all() and np.allclose(lam.sum(axis=0), 1.0)
    for polygon in res.polygons:
        assert 3 <= len(polygon) <= 6  # cut by near, far and the eye plane: at most 6 corners


@pytest.mark.parametrize("bits", [None, 8])
def test_clip_position_as_attribute_reproduces_each_pixel(rng, bits):
    """Feed each vertex's clip position as its attribute: perspective-correct interpolation
    must give back, at every covered pixel, a clip point whose projection is that pixel
    centre and whose depth is the stored depth, with w > 0 (nothing mirrored)."""
    tol = 1e-7 if bits is None else 1.5 / 2**bits  # in pixels (snapping moves the vertices)
    for clip_tri in perspective_triangles(rng, 40, 1 + int(rng.integers(0, 2))):
        frame = tr.render(clip_tri[None], W, H, attrs=clip_tri[None], subpixel_bits=bits)
        rows, cols = np.nonzero(frame.coverage)
        if len(rows) == 0:
            continue
        c = frame.attrs[rows, cols]
        assert (c[:, 3] >= NEAR * (1 - 1e-9)).all()
        win = tr.to_window(c, W, H)
        np.testing.assert_allclose(win[:, 0], cols + 0.5, atol=tol)
        np.testing.assert_allclose(win[:, 1], rows + 0.5, atol=tol)
        if bits is None:
            np.testing.assert_allclose(win[:, 2], frame.depth[rows, cols], atol=1e-9)


# -- the eye plane and the guard band ----------------------------------------------------------
def test_vertex_on_the_eye_plane_is_finite():
    """A vertex with w = 0 (and z = 0, inside -w <= z <= w): no error, no inf or NaN."""
    cases = [
        [[0, 0, 0, 0], [1, -1, 0.5, 1], [-1, -1, 0.5, 1]],
        [[5, 3, 0, 0], [1, -1, 0.5, 1], [-1, -0.5, 0.5, 1]],  # a direction at infinity
        [[0, 0, 0, 0], [0, 0, 0, 0], [1, 1, 0.2, 1]],
        [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]],
    ]
    for case in cases:
        clip = np.array([case], dtype=float)
        attrs = np.array([[[1.0, 0], [0, 1], [0, 0]]])
        frame = tr.render(clip, W, H, attrs=attrs, trace=True)
        cov = frame.coverage
        assert np.isfinite(frame.depth[cov]).all() and np.isfinite(frame.attrs[cov]).all()
        assert np.isfinite(frame.trace.window).all()
        assert ((frame.attrs[cov] >= 0) & (frame.attrs[cov] <= 1)).all()
        assert ((frame.depth[cov] >= 0) & (frame.depth[cov] <= 1)).all()
    # a vertex at the eye projects onto its neighbours (a ray through the eye is a point):
    # nothing to draw; a direction at infinity (w = 0, x != 0) spreads far across the image
    assert not tr.render(np.array([cases[0]], dtype=float), W, H).coverage.any()
    assert tr.render(np.array([cases[1]], dtype=float), W, H).coverage.sum() > 20


def _cut_by_hand(tri: np.ndarray, limit: float) -> np.ndarray:
    """The triangle ∩ {x <= limit·w} as fan triangles, for the one vertex beyond it."""
    out = [k for k in range(3) if tri[k, 0] > limit * tri[k, 3]]
    assert len(out) == 1
    k = out[0]
    a, far, b = tri[(k + 1) % 3], tri[k], tri[(k + 2) % 3]  # a -> far -> b in winding order

    def cut(p, q):
        dp, dq = limit * p[3] - p[0], limit * q[3] - q[0]
        return p + dp / (dp - dq) * (q - p)

    pa, pb = cut(a, far), cut(far, b)
    return np.array([[a, pa, pb], [a, pb, b]])


@pytest.mark.parametrize("bits", [8, None])
@pytest.mark.parametrize("w_far", [1.0, 3.0])
def test_huge_guard_band_triangle(bits, w_far):
    """A vertex at x = 1e9·w renders its visible part like the same triangle cut by hand at
    x = 4·w (outside the image): coverage equal except at centres within 1e-3 px of an
    original edge, attributes (linear in clip space) equal, no error."""
    tri = np.array([[-0.5, -0.5, 0.1, 1.0], [1e9 * w_far, 0.1 * w_far, 0.3 * w_far, w_far],
                    [-0.4, 0.6, -0.2, 1.5]])  # fmt: skip
    A = np.array([[1.0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 0, 1]]).T  # attrs x, y, w
    frame = tr.render(tri[None], W, H, attrs=(tri @ A)[None], subpixel_bits=bits)
    pieces = _cut_by_hand(tri, 4.0)
    ref = tr.render(pieces, W, H, attrs=pieces @ A, subpixel_bits=bits)
    assert frame.coverage.sum() > 0.2 * W * H
    # centres within 1e-3 px of the two long edges (near vertex -> the far vertex on screen)
    win = tr.to_window(tri, W, H)[:, :2]
    rows, cols = np.mgrid[0:H, 0:W]
    p = np.stack([cols + 0.5, rows + 0.5], -1)
    near_edge = np.zeros((H, W), dtype=bool)
    for k in (0, 2):
        d = (win[1] - win[k]) / np.hypot(*(win[1] - win[k]))
        rel = p - win[k]
        near_edge |= np.abs(rel[..., 0] * d[1] - rel[..., 1] * d[0]) < 1e-3
    same = frame.coverage == ref.coverage
    assert (same | near_edge).all()
    both = frame.coverage & ref.coverage
    tol = 1e-9 if bits is None else 0.05
    np.testing.assert_allclose(frame.attrs[both], ref.attrs[both], rtol=tol, atol=tol)


@pytest.mark.parametrize("bits", [8, 12, 16])
def test_guard_band_stays_rasterisable_at_every_precision(bits):
    """The guard band must keep clipped window coordinates inside the exact fixed-point range
    for every allowed subpixel_bits. A 6000 x 1 image is rasterisable at 16 bits (|x| < 8192
    px), so a triangle with a vertex at x = 100·w must render its visible part, not raise."""
    width, height = 6000, 1
    clip = np.array([[[-0.5, -1.0, 0.0, 1.0], [100.0, 0.5, 0.0, 1.0], [-0.5, 1.0, 0.0, 1.0]]])
    frame = tr.render(clip, width, height, subpixel_bits=bits)
    # the only row's centres lie on y_ndc = 0: covered from x_ndc = -0.5 (window x 1500) to
    # x_ndc = 66.5, far beyond the right border
    cov = frame.coverage[0]
    assert cov[1500:].all() and not cov[:1500].any()


def test_clipped_pieces_keep_the_winding():
    """All pieces of one clipped triangle face the same way, so culling keeps or drops all."""
    rng = np.random.default_rng(7)
    clip = random_clip(rng, 200, cross=True)
    res = clip_triangles(clip, np.zeros((200, 3, 0)))
    win = tr.to_window(res.clip, W, H)
    (ax, ay), (bx, by), (cx, cy) = (win[:, k, :2].T for k in range(3))
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    for t in np.flatnonzero(res.status == CLIPPED):
        signs = set(np.sign(area[res.parent == t]).tolist()) - {0.0}
        assert len(signs) <= 1, f"clip={clip[t].tolist()}"
    for cull in ("back", "front"):
        frame = tr.render(clip, W, H, cull=cull, trace=True)
        t = frame.trace
        for parent in np.flatnonzero(t.clip_status == CLIPPED):
            flags = set(t.culled[t.parent == parent].tolist())
            assert len(flags) <= 1


def test_clipping_leaves_unclipped_triangles_as_rasterize(rng):
    """In a scene where some triangles are clipped, the others draw exactly as tr.rasterize."""
    clip = np.concatenate([random_clip(rng, 4, spread=0.8), random_clip(rng, 4, cross=True)])
    frame = tr.render(clip, W, H, depth_test=False, trace=True)
    t = frame.trace
    for k in np.flatnonzero(t.clip_status == INSIDE):
        mine = t.fragment_triangle == k
        got = np.zeros((H, W), dtype=bool)
        got[t.fragment_row[mine], t.fragment_col[mine]] = True
        np.testing.assert_array_equal(got, reference_fill(clip[k], None).coverage)


@pytest.mark.parametrize("w0", [1e-13, 1e-30, 1e-200])
def test_a_vertex_a_hair_in_front_of_the_eye_is_kept(w0):
    """-w <= z <= w holds for a vertex at z = 0, w = 1e-13: the triangle is inside, not
    dropped (a fixed eye-plane margin like w >= 1e-12 would cut away its whole screen
    footprint), and it draws exactly what it draws at w = 1."""
    near_eye = tr.render([[[0, 0, 0, w0], [1, 0, 0, 1], [0, 1, 0, 1]]], 16, 16)
    plain = tr.render([[[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]]], 16, 16)
    np.testing.assert_array_equal(near_eye.triangle_id, plain.triangle_id)
    assert near_eye.plan["clipping"].count == 0


def test_clip_polygon_steps_record_each_plane_and_end_at_clip_polygon():
    from teachraster.pipeline.clipping import PLANE_NAMES, clip_polygon, clip_polygon_steps

    rng = np.random.default_rng(7)
    for _ in range(50):
        tri = np.column_stack([rng.uniform(-2, 2, (3, 3)), rng.uniform(-1, 3, (3, 1))])
        attrs = rng.uniform(0, 1, (3, 2))
        steps = clip_polygon_steps(tri, attrs, guard=4.0)
        poly, pattrs = clip_polygon(tri, attrs, guard=4.0)
        assert [s.plane for s in steps] == list(PLANE_NAMES[: len(steps)])
        assert np.array_equal(steps[-1].polygon, poly) and np.array_equal(steps[-1].attrs, pattrs)
        before = tri
        for s in steps:
            assert len(s.distances) == len(before) and len(s.new) == len(s.polygon)
            # kept vertices are the inside ones of the polygon before, in order
            assert np.array_equal(s.polygon[~s.new], before[s.distances >= 0])
            before = s.polygon
        # every new vertex of the near step lies on z = -w
        near = steps[0]
        assert np.allclose(near.polygon[near.new, 2], -near.polygon[near.new, 3])


def test_plane_names_follow_the_planes_rows():
    """Review r59 (05a, guard band): PLANE_NAMES and the edge names had each guard pair's two
    sides swapped; row k of planes() is the plane named k."""
    from teachraster.pipeline.debugging.edge_names import PLANES
    from teachraster.pipeline.geometry.clipping import PLANE_NAMES, distances

    g = 10.0
    right, top = np.array([2 * g, 0.0, 0.0, 1.0]), np.array([0.0, 2 * g, 0.0, 1.0])
    assert np.argmin(distances(right, g)) == PLANE_NAMES.index("guard x <= g w")
    assert np.argmin(distances(top, g)) == PLANE_NAMES.index("guard y <= g w")
    assert PLANES[np.argmin(distances(right, g))] == "guard right"
    assert PLANES[np.argmin(distances(top, g))] == "guard top"
