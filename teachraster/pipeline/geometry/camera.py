"""Cameras: a look-at view matrix and OpenGL's perspective and orthographic projections.

Everything follows OpenGL (right-handed): the camera sits at the origin of view space and
looks down its -z axis, x to the right and y up. The projection maps view space to *clip
space* (x, y, z, w); the divide by w and the viewport transform (:func:`to_window`) come
later, after clipping against the near plane. For the perspective matrix ``w = -z_view``,
the distance in front of the camera, which is the w that perspective-correct
interpolation divides by.

>>> cam = Camera(eye=(0, 0, 5), target=(0, 0, 0))
>>> cam.clip([0, 0, 0], aspect=1.0)          # on the view axis, 5 units in front
array([0.  , 0.  , 4.8..., 5.  ])
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...core.validate import as_finite, as_float, as_real

PROJECTIONS = ("perspective", "orthographic")


def _unit(name: str, v: np.ndarray) -> np.ndarray:
    n = float(np.linalg.norm(v))
    if n == 0 or not math.isfinite(n):
        raise ValueError(f"{name} has no direction (length {n})")
    return v / n


def look_at(eye, target, up=(0, 1, 0)) -> np.ndarray:
    """View matrix (4, 4) of a camera at ``eye`` looking at ``target`` (gluLookAt).

    The camera looks down its -z axis; ``up`` fixes the roll (it need not be
    perpendicular to the view direction, only not parallel to it).

    >>> look_at((0, 0, 5), (0, 0, 0)) @ [0, 0, 0, 1]    # 5 units down -z
    array([ 0.,  0., -5.,  1.])
    """
    eye = as_finite("eye", eye, (3,))
    target = as_finite("target", target, (3,))
    up = as_finite("up", up, (3,))
    f = _unit("target - eye", target - eye)
    s = np.cross(f, up)
    if np.linalg.norm(s) <= 1e-12 * np.linalg.norm(up):
        raise ValueError(f"up {up.tolist()} is parallel to the view direction {f.tolist()}")
    s = _unit("side", s)
    u = np.cross(s, f)  # already unit: s and f are orthonormal
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye  # rotate, after moving the eye to the origin
    return m


def perspective(fov_y: float, aspect: float, near: float, far: float) -> np.ndarray:
    """OpenGL's perspective matrix (gluPerspective); ``fov_y`` in degrees.

    Clip w is ``-z_view``: the view-space depth, positive in front of the camera. NDC z
    runs from -1 at the near plane to +1 at the far plane.

    >>> p = perspective(90, 1.0, 1.0, 3.0)
    >>> p @ [0, 0, -1, 1], p @ [0, 0, -3, 1]        # near -> z/w = -1, far -> +1
    (array([ 0.,  0., -1.,  1.]), array([0., 0., 3., 3.]))
    """
    fov_y, aspect = as_float("fov_y", fov_y), as_float("aspect", aspect)
    near, far = as_float("near", near), as_float("far", far)
    if not 0 < fov_y < 180:
        raise ValueError(f"fov_y must be between 0 and 180 degrees, got {fov_y}")
    if aspect <= 0:
        raise ValueError(f"aspect must be > 0 (width / height), got {aspect}")
    if near == far:
        raise ValueError(f"near and far must differ, got {near} for both")
    half = math.tan(math.radians(fov_y) / 2)
    if half == 0:  # a subnormal angle: tan underflows to 0 and the focal length is infinite
        raise ValueError(f"fov_y is too small to make a projection, got {fov_y}")
    f = 1.0 / half
    m = np.zeros((4, 4))
    m[0, 0] = f / aspect
    m[1, 1] = f
    m[2, 2] = (far + near) / (near - far)
    m[2, 3] = 2 * far * near / (near - far)
    m[3, 2] = -1.0
    return m


def orthographic(left: float, right: float, bottom: float, top: float, near: float, far: float):
    """OpenGL's orthographic matrix (glOrtho), (4, 4); w stays 1.

    >>> orthographic(-2, 2, -1, 1, 0, 10) @ [2, 1, -10, 1]
    array([1., 1., 1., 1.])
    """
    names = ("left", "right", "bottom", "top", "near", "far")
    values = (left, right, bottom, top, near, far)
    left, right, bottom, top, near, far = (as_float(n, v) for n, v in zip(names, values))
    for a, b, lo, hi in ((left, right, "left", "right"), (bottom, top, "bottom", "top"),
                         (near, far, "near", "far")):  # fmt: skip
        if a == b:
            raise ValueError(f"{lo} and {hi} must differ, got {a} for both")
    m = np.eye(4)
    m[0, 0] = 2 / (right - left)
    m[1, 1] = 2 / (top - bottom)
    m[2, 2] = -2 / (far - near)
    m[0, 3] = -(right + left) / (right - left)
    m[1, 3] = -(top + bottom) / (top - bottom)
    m[2, 3] = -(far + near) / (far - near)
    return m


@dataclass(frozen=True)
class Camera:
    """A look-at camera with a perspective or orthographic projection.

    Parameters
    ----------
    eye, target : 3 floats
        Camera position and the point it looks at.
    up : 3 floats
        Which way is up on screen (not parallel to ``target - eye``).
    fov_y : float
        Vertical field of view in degrees, in (0, 180) (perspective only).
    near, far : float
        Clip planes, distances along the view direction; ``0 < near < far`` for a
        perspective camera (``near`` may be <= 0 for an orthographic one).
    projection : {"perspective", "orthographic"}
    ortho_height : float
        Visible height in world units of an orthographic camera (> 0).

    Every impossible value raises ``ValueError`` naming the field.
    """

    eye: tuple[float, float, float]
    target: tuple[float, float, float]
    up: tuple[float, float, float] = (0.0, 1.0, 0.0)
    fov_y: float = 60.0
    near: float = 0.1
    far: float = 100.0
    projection: str = "perspective"
    ortho_height: float = 2.0

    def __post_init__(self) -> None:
        def bad(field: str, why: str):
            return ValueError(f"impossible camera: {field} {why}")

        for name in ("eye", "target", "up"):
            try:
                v = as_finite(name, getattr(self, name), (3,))
            except (TypeError, ValueError) as exc:
                raise ValueError(f"impossible camera: {exc}") from None
            # Tuples of floats keep the dataclass hashable and its repr readable.
            object.__setattr__(self, name, tuple(float(x) for x in v))
        for name in ("fov_y", "near", "far", "ortho_height"):
            value = getattr(self, name)
            try:
                value = float(value)
            except (TypeError, ValueError):
                raise bad(name, f"must be a number, got {value!r}") from None
            if not math.isfinite(value):
                raise bad(name, f"must be finite, got {value}")
            object.__setattr__(self, name, value)
        if self.projection not in PROJECTIONS:
            raise bad("projection", f"must be one of {PROJECTIONS}, got {self.projection!r}")
        if not 0 < self.fov_y < 180:
            raise bad("fov_y", f"must be in (0, 180) degrees, got {self.fov_y}")
        if self.projection == "perspective" and self.near <= 0:
            # The perspective divide needs the near plane strictly in front of the eye.
            raise bad("near", f"must be > 0 for a perspective camera, got {self.near}")
        if self.far <= self.near:
            raise bad("far", f"must be greater than near ({self.near}), got {self.far}")
        if self.ortho_height <= 0:
            raise bad("ortho_height", f"must be > 0, got {self.ortho_height}")
        eye, target, up = (np.array(v) for v in (self.eye, self.target, self.up))
        if np.array_equal(eye, target):
            raise bad("target", f"equals eye {self.eye}: no view direction")
        if not np.any(up):
            raise bad("up", "is the zero vector")
        f = (target - eye) / np.linalg.norm(target - eye)
        if np.linalg.norm(np.cross(f, up / np.linalg.norm(up))) <= 1e-12:
            raise bad("up", f"{self.up} is parallel to the view direction {f.tolist()}")

    def view_matrix(self) -> np.ndarray:
        """World to view space, (4, 4): see :func:`look_at`."""
        return look_at(self.eye, self.target, self.up)

    def projection_matrix(self, aspect: float) -> np.ndarray:
        """View to clip space, (4, 4), for an image of ``aspect`` = width / height."""
        aspect = as_float("aspect", aspect, finite=False)
        if not (math.isfinite(aspect) and aspect > 0):
            raise ValueError(f"aspect must be a finite number > 0 (width / height), got {aspect}")
        if self.projection == "perspective":
            return perspective(self.fov_y, aspect, self.near, self.far)
        h = self.ortho_height / 2
        return orthographic(-h * aspect, h * aspect, -h, h, self.near, self.far)

    def matrix(self, aspect: float) -> np.ndarray:
        """World to clip space, (4, 4): projection @ view."""
        return self.projection_matrix(aspect) @ self.view_matrix()

    def clip(self, points, aspect: float) -> np.ndarray:
        """Clip-space coordinates (..., 4) of world points (..., 3), *before* any divide.

        Dividing here would be wrong for points behind the camera (w <= 0): clipping
        against the near plane has to happen first, in homogeneous coordinates.
        """
        p = as_real("points", points)
        if p.shape[-1:] != (3,):
            raise ValueError(f"points must have shape (..., 3), got {p.shape}")
        m = self.matrix(aspect)
        return p @ m[:, :3].T + m[:, 3]
