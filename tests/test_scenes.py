"""Built-in scenes: they build, and each really shows what it claims to teach."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import teachraster as tr
from teachraster.pipeline.camera import Camera
from teachraster.pipeline.mesh import Mesh, fan_mesh
from teachraster.pipeline.scenes import (
    SCENES,
    Scene,
    behind_camera,
    cyclic_overlap,
    fan,
    get_scene,
    grid,
    intersecting_triangles,
    textured_floor,
    uv_sphere,
)
from teachraster.pipeline.viewport import to_window

W, H = 96, 72


def window(scene: Scene, width=W, height=H) -> np.ndarray:
    """(T, 3, 3) window coordinates; only for scenes with every w > 0."""
    clip = scene.clip(width / height)
    assert np.all(clip[..., 3] > 0)
    return to_window(clip, width, height)


def pixel_centres(width=W, height=H) -> np.ndarray:
    rows, cols = np.mgrid[0:height, 0:width]
    return np.stack([cols + 0.5, rows + 0.5], -1)


@pytest.mark.parametrize("name", list(SCENES))
def test_every_scene_builds(name):
    scene = get_scene(name)
    assert scene.name == name
    assert scene.description and "\n" not in scene.description
    t = len(scene.mesh.triangles)
    for aspect in (1.0, 4 / 3, 0.5):
        clip = scene.clip(aspect)
        assert clip.shape == (t, 3, 4) and np.isfinite(clip).all()
    assert all(a in scene.mesh.attrs for a in scene.uses)
    assert scene.uses == {"color": ("color",), "texture": ("uv",), "flat": ()}[scene.shading]
    if scene.shading == "texture":
        tex = scene.texture
        assert tex.ndim == 3 and tex.shape[2] == 3 and 0 <= tex.min() and tex.max() <= 1


def test_get_scene_unknown_lists_names():
    with pytest.raises(ValueError, match="choose from single_triangle, textured_floor"):
        get_scene("teapot")


def test_scene_validation():
    mesh, cam = fan_mesh(4), Camera(eye=(0, 0, 3), target=(0, 0, 0))
    with pytest.raises(ValueError, match="shading"):
        Scene("x", "x", mesh, cam, shading="phong")
    with pytest.raises(ValueError, match="texture"):
        Scene("x", "x", mesh, cam, shading="texture")
    with pytest.raises(ValueError, match="texture"):
        Scene("x", "x", mesh, cam, texture=np.full((4, 4, 3), 2.0))
    with pytest.raises(ValueError, match="needs mesh attrs"):
        Scene("x", "x", Mesh(mesh.positions, mesh.triangles), cam)
    assert Scene("x", "x", Mesh(mesh.positions, mesh.triangles), cam, shading="flat").uses == ()


@pytest.mark.parametrize(
    "name", ["single_triangle", "intersecting_triangles", "cyclic_overlap", "fan", "grid"]
)
def test_flat_scenes_face_the_camera(name):
    """Counter-clockwise on screen (front-facing) = negative E in y-down window numbers."""
    xy = window(get_scene(name))[..., :2]
    (x0, y0), (x1, y1), (x2, y2) = xy[:, 0].T, xy[:, 1].T, xy[:, 2].T
    assert np.all((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0) < 0)


def test_behind_camera_has_one_vertex_with_negative_w():
    scene = behind_camera()
    w = scene.clip(W / H)[0, :, 3]
    assert (w < 0).sum() == 1
    assert np.all(w[w >= 0] > scene.camera.near)


def test_intersecting_triangles_pierce_each_other():
    win = window(intersecting_triangles())
    a, b = win
    z_a, z_b = a[:, 2], b[:, 2]
    assert z_a.min() < z_b.max() and z_b.min() < z_a.max()  # depth ranges overlap
    # ... and it is not just the ranges: where both cover the screen, each is in front
    # somewhere, so the nearer triangle changes from pixel to pixel
    p = pixel_centres()
    la, lb = tr.barycentric(a[:, :2], p), tr.barycentric(b[:, :2], p)
    both = (la > 0).all(-1) & (lb > 0).all(-1)
    diff = (la @ z_a - lb @ z_b)[both]
    assert (diff < 0).sum() > 20 and (diff > 0).sum() > 20


def test_cyclic_overlap_has_no_painters_order():
    win = window(cyclic_overlap())
    p = pixel_centres()
    lam = [tr.barycentric(t[:, :2], p) for t in win]
    inside = [(l > 1e-9).all(-1) for l in lam]
    depth = [l @ t[:, 2] for l, t in zip(lam, win)]
    front = set()  # (i, j): triangle i is in front of j where they overlap
    for i, j in itertools.combinations(range(3), 2):
        both = inside[i] & inside[j]
        assert both.sum() >= 5, "every pair overlaps on screen"
        d = depth[i][both] - depth[j][both]
        assert np.all(d < 0) or np.all(d > 0), "consistent in-front relation (no piercing)"
        front.add((i, j) if d[0] < 0 else (j, i))
    assert front in ({(0, 1), (1, 2), (2, 0)}, {(1, 0), (2, 1), (0, 2)})  # a cycle
    for order in itertools.permutations(range(3)):  # painter: draw far to near
        drawn_later = {(order[k], order[m]) for k in range(3) for m in range(k)}
        assert not front <= drawn_later, f"painter order {order} would be right"


def coverage_counts(scene: Scene) -> np.ndarray:
    counts = np.zeros((H, W), dtype=int)
    for t in window(scene):
        counts += tr.rasterize(tr.Triangle(t[:, :2]), W, H).coverage
    return counts


def strictly_inside(poly: np.ndarray, points: np.ndarray, margin: float = 0.01) -> np.ndarray:
    """Points farther than ``margin`` px inside the convex polygon ``poly`` (n, 2)."""
    ok = np.ones(points.shape[:-1], dtype=bool)
    orient = None
    for a, b in zip(poly, np.roll(poly, -1, axis=0)):
        e = (b[0] - a[0]) * (points[..., 1] - a[1]) - (b[1] - a[1]) * (points[..., 0] - a[0])
        e = e / np.hypot(*(b - a))
        orient = orient or np.sign(e.max() + e.min())
        ok &= orient * e > margin
    return ok


@pytest.mark.parametrize("scene, outline", [(fan(12), "fan"), (grid(8), "grid"), (fan(5), "fan")])
def test_fan_and_grid_are_watertight_on_screen(scene, outline):
    counts = coverage_counts(scene)
    assert counts.max() == 1, "a pixel covered twice: shared edges must be filled once"
    pos = scene.mesh.positions
    if outline == "fan":
        corners = pos[1:]  # the rim, in order
    else:
        n = round(np.sqrt(len(pos))) - 1
        corners = pos[[0, n, (n + 1) ** 2 - 1, n * (n + 1)]]
    poly = to_window(scene.camera.clip(corners, W / H), W, H)[:, :2]
    inside = strictly_inside(poly, pixel_centres())
    assert inside.sum() > 500
    assert np.all(counts[inside] == 1), "a hole inside the mesh"


@pytest.mark.parametrize("n_lat, n_lon", [(16, 32), (5, 7), (2, 3)])
def test_uv_sphere_triangle_count(n_lat, n_lon):
    assert len(uv_sphere(n_lat, n_lon).mesh.triangles) == 2 * n_lat * n_lon - 2 * n_lon


def test_textured_floor_recedes_to_the_horizon():
    scene = textured_floor()
    for width, height in ((W, H), (256, 256), (320, 180)):
        # the horizon is where directions parallel to the floor go: the point at infinity
        # (0, 0, -1, 0) in homogeneous world coordinates
        horizon = to_window(scene.camera.matrix(width / height) @ [0, 0, -1, 0], width, height)
        win = to_window(scene.clip(width / height), width, height)
        y = win[..., 1]
        far = win[..., 2] > 0.99
        assert far.any() and (~far).any()
        assert np.all(y[far] > horizon[1])  # the floor stays below the horizon...
        assert np.all(y[far] - horizon[1] < 0.05 * height)  # ...and its far end nearly reaches it
        assert y.max() > height  # its near end runs out of the bottom of the image
    w = scene.clip(1.0)[..., 3]
    assert w.max() / w.min() > 20  # very different w: where affine uv visibly warps


def test_local_checkerboard_fallback_matches_the_texture_module():
    from teachraster.pipeline import scenes
    from teachraster.pipeline.texture import checkerboard

    for checks, texels in ((8, 64), (16, 128), (3, 10)):
        want = checkerboard(checks=checks, texels=texels)
        assert np.array_equal(scenes._local_checkerboard(checks, texels), want)
