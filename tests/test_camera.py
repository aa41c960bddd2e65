"""Camera: look-at, OpenGL perspective and orthographic matrices, and validation."""

from __future__ import annotations

import numpy as np
import pytest

from teachraster.pipeline.camera import Camera, look_at, orthographic, perspective
from teachraster.pipeline.viewport import to_window

CAMERAS = [
    Camera(eye=(0, 0, 5), target=(0, 0, 0)),
    Camera(eye=(3, 2, -4), target=(0.5, -1, 2), fov_y=35, near=0.5, far=50),
    Camera(eye=(1, 7, 1), target=(0, 0, 0), up=(0, 0, -1), fov_y=120),
    Camera(eye=(2, 1, 3), target=(-1, 0, 0), projection="orthographic", ortho_height=4.0),
    Camera(eye=(0, 0, 1), target=(0, 0, -1), projection="orthographic", near=-2, far=2),
]


def view_dir(cam: Camera) -> np.ndarray:
    d = np.subtract(cam.target, cam.eye)
    return d / np.linalg.norm(d)


@pytest.mark.parametrize("cam", CAMERAS)
def test_look_at_is_a_rigid_motion_to_minus_z(cam):
    v = cam.view_matrix()
    r = v[:3, :3]
    assert np.allclose(r @ r.T, np.eye(3)) and np.isclose(np.linalg.det(r), 1.0)
    assert np.allclose(v @ [*cam.eye, 1], [0, 0, 0, 1])
    dist = np.linalg.norm(np.subtract(cam.target, cam.eye))
    assert np.allclose(v @ [*cam.target, 1], [0, 0, -dist, 1])
    # up stays up: its image has a positive view-space y and no x
    up = r @ np.array(cam.up, dtype=float)
    assert up[1] > 0 and abs(up[0]) < 1e-12


@pytest.mark.parametrize("cam", CAMERAS)
@pytest.mark.parametrize("size", [(64, 48), (100, 100), (30, 90)])
def test_point_on_view_axis_maps_to_image_centre(cam, size):
    width, height = size
    for t in (0.3, 0.5, 0.9):
        depth = cam.near + t * (cam.far - cam.near)
        p = np.add(cam.eye, depth * view_dir(cam))
        win = to_window(cam.clip(p, width / height), width, height)
        assert np.allclose(win[:2], [width / 2, height / 2], atol=1e-9)
        assert 0 < win[2] < 1


@pytest.mark.parametrize("cam", CAMERAS)
def test_near_plane_is_depth_0_and_far_plane_depth_1(cam):
    d = view_dir(cam)
    pts = np.array([np.add(cam.eye, cam.near * d), np.add(cam.eye, cam.far * d)])
    win = to_window(cam.clip(pts, 1.5), 60, 40)
    assert np.allclose(win[:, 2], [0.0, 1.0], atol=1e-9)


def test_depth_grows_with_distance():
    cam = CAMERAS[1]
    d = view_dir(cam)
    depths = np.linspace(cam.near, cam.far, 50)
    z = to_window(cam.clip(np.add(cam.eye, depths[:, None] * d), 1.0), 10, 10)[:, 2]
    assert np.all(np.diff(z) > 0)


@pytest.mark.parametrize("cam", [c for c in CAMERAS if c.projection == "perspective"])
def test_perspective_w_is_view_depth(cam, rng):
    pts = rng.uniform(-10, 10, size=(200, 3))
    view = pts @ cam.view_matrix()[:3, :3].T + cam.view_matrix()[:3, 3]
    clip = cam.clip(pts, 4 / 3)
    assert np.allclose(clip[:, 3], -view[:, 2])
    behind = clip[:, 3] < 0  # no divide happened: points behind the eye keep w < 0
    assert behind.any() and (~behind).any()


@pytest.mark.parametrize("cam", [c for c in CAMERAS if c.projection == "orthographic"])
def test_orthographic_keeps_w_1(cam, rng):
    clip = cam.clip(rng.uniform(-10, 10, size=(5, 7, 3)), 2.0)
    assert clip.shape == (5, 7, 4)
    assert np.all(clip[..., 3] == 1.0)


def test_field_of_view_reaches_the_image_top_and_side():
    cam = Camera(eye=(0, 0, 0), target=(0, 0, -1), fov_y=90)
    w, h = 200, 100
    # at 45 degrees up the view ends: the top of the image; aspect 2 widens x
    win = to_window(cam.clip([[0, 3, -3], [6, 0, -3]], w / h), w, h)
    assert np.allclose(win[:, :2], [[100, 0], [200, 50]])


def test_orthographic_height_and_aspect():
    cam = Camera(eye=(0, 0, 5), target=(0, 0, 0), projection="orthographic", ortho_height=4)
    win = to_window(cam.clip([[-4, 2, 0], [4, -2, 1]], 2.0), 80, 40)
    assert np.allclose(win[:, :2], [[0, 0], [80, 40]])


def test_matrices_match_opengl_formulas():
    p = perspective(60, 1.5, 0.1, 100)
    f = 1 / np.tan(np.radians(30))
    assert np.allclose(np.diag(p), [f / 1.5, f, -100.1 / 99.9, 0])
    assert p[3, 2] == -1 and np.isclose(p[2, 3], -2 * 100 * 0.1 / 99.9)
    o = orthographic(-1, 3, -2, 2, 1, 5)
    assert np.allclose(o @ [-1, -2, -1, 1], [-1, -1, -1, 1])
    assert np.allclose(o @ [3, 2, -5, 1], [1, 1, 1, 1])
    assert np.allclose(look_at((0, 0, 0), (0, 0, -1)), np.eye(4))


def test_camera_is_frozen_and_hashable():
    cam = Camera(eye=[0, 0, 5], target=np.zeros(3))
    assert cam.eye == (0.0, 0.0, 5.0) and isinstance(cam.target, tuple)
    assert hash(cam) == hash(Camera(eye=(0, 0, 5), target=(0, 0, 0)))
    with pytest.raises(AttributeError):
        cam.near = 1.0


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"eye": (0, np.nan, 5)}, "eye"),
        ({"target": (0, 0, np.inf)}, "target"),
        ({"eye": (0, 0)}, "eye"),
        ({"up": ("a", 1, 0)}, "up"),
        ({"near": 0.0}, "near"),
        ({"near": -1.0}, "near"),
        ({"near": np.nan}, "near"),
        ({"far": 0.05}, "far"),
        ({"far": np.inf}, "far"),
        ({"near": 2.0, "far": 2.0}, "far"),
        ({"fov_y": 0.0}, "fov_y"),
        ({"fov_y": 180.0}, "fov_y"),
        ({"fov_y": "wide"}, "fov_y"),
        ({"eye": (1, 2, 3), "target": (1, 2, 3)}, "target"),
        ({"up": (0, 0, -2)}, "up"),
        ({"up": (0, 0, 0)}, "up"),
        ({"projection": "fisheye"}, "projection"),
        ({"projection": "orthographic", "ortho_height": 0}, "ortho_height"),
        ({"projection": "orthographic", "near": 3, "far": 1}, "far"),
    ],
)
def test_impossible_cameras_name_the_field(kwargs, field):
    args = {"eye": (0, 0, 5), "target": (0, 0, 0)} | kwargs
    with pytest.raises(ValueError, match=rf"impossible camera: .*\b{field}\b"):
        Camera(**args)


def test_orthographic_allows_near_at_or_behind_the_eye():
    cam = Camera(eye=(0, 0, 5), target=(0, 0, 0), projection="orthographic", near=-1, far=1)
    assert cam.near == -1


@pytest.mark.parametrize("aspect", [0, -1.0, np.nan, np.inf])
def test_bad_aspect(aspect):
    with pytest.raises(ValueError, match="aspect"):
        CAMERAS[0].clip([0, 0, 0], aspect)


def test_clip_needs_3d_points():
    with pytest.raises(ValueError, match=r"\(\.\.\., 3\)"):
        CAMERAS[0].clip([[0, 0, 0, 1]], 1.0)
