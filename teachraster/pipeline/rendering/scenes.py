"""Built-in teaching scenes: each a mesh, a camera looking at it, and how to shade it.

Texture coordinates follow :mod:`teachraster.pipeline.texture`: ``v = 0`` is the top row of the
texture, so a texture appears upright on a surface whose ``v`` grows downwards.

>>> scene = get_scene("cube")
>>> scene.clip(aspect=4 / 3).shape, scene.uses
((12, 3, 4), ('color',))
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ...core.validate import short_repr
from ..geometry.camera import Camera
from ..geometry.mesh import (
    Mesh,
    cube_mesh,
    fan_mesh,
    grid_mesh,
    plane_mesh,
    rotate,
    translate,
    uv_sphere_mesh,
)

SHADINGS = {"color": ("color",), "texture": ("uv",), "flat": ()}


def _local_checkerboard(checks: int = 8, texels: int = 64) -> np.ndarray:
    """(texels, texels, 3) board of ``checks`` x ``checks`` squares, like texture.checkerboard."""
    square = np.arange(texels) * checks // texels
    parity = (square[:, None] + square[None, :]) % 2
    return np.array([[0.92, 0.92, 0.92], [0.15, 0.2, 0.35]])[parity]


try:  # the texture module's checkerboard, where it exists (it is written separately)
    from ..texturing.texture import checkerboard
except ImportError:
    checkerboard = _local_checkerboard


@dataclass(frozen=True, eq=False)
class Scene:
    """A mesh, a camera and a shading mode.

    Parameters
    ----------
    name : str
    description : str
        One line: what the scene teaches.
    mesh : Mesh
    camera : Camera
    texture : (H, W, 3) array in [0, 1], optional
        Needed by ``shading="texture"``.
    shading : {"color", "texture", "flat"}
        ``"color"`` interpolates the ``"color"`` attribute, ``"texture"`` samples the
        texture at the interpolated ``"uv"``, ``"flat"`` uses no attribute (colour by
        triangle id).
    """

    name: str
    description: str
    mesh: Mesh
    camera: Camera
    texture: np.ndarray | None = None
    shading: str = "color"

    def __post_init__(self) -> None:
        if self.shading not in SHADINGS:
            raise ValueError(f"shading must be one of {tuple(SHADINGS)}, got {self.shading!r}")
        missing = [a for a in self.uses if a not in self.mesh.attrs]
        if missing:
            raise ValueError(f"shading {self.shading!r} needs mesh attrs {missing}")
        if self.shading == "texture" and self.texture is None:
            raise ValueError("texture: shading 'texture' needs a texture")
        if self.texture is not None:
            tex = np.array(self.texture, dtype=np.float64)
            if tex.ndim != 3 or tex.shape[2] != 3 or 0 in tex.shape:
                raise ValueError(f"texture must have shape (H, W, 3), got {tex.shape}")
            if not (np.isfinite(tex).all() and tex.min() >= 0 and tex.max() <= 1):
                raise ValueError("texture values must be finite and in [0, 1]")
            tex.flags.writeable = False
            object.__setattr__(self, "texture", tex)

    @property
    def uses(self) -> tuple[str, ...]:
        """The mesh attributes the shading needs: ``("color",)``, ``("uv",)`` or ``()``."""
        return SHADINGS[self.shading]

    def clip(self, aspect: float) -> np.ndarray:
        """Clip-space corners (T, 3, 4) of every triangle, for an image of ``aspect``."""
        return self.camera.clip(self.mesh.corner_positions(), aspect)


def _facing(distance: float = 3.0, **kw) -> Camera:
    """A camera on +z looking at the origin: the z = 0 plane faces it."""
    return Camera(eye=(0, 0, distance), target=(0, 0, 0), **kw)


def _rgb_triangle(positions, uv) -> Mesh:
    """A one-triangle mesh with red, green and blue corners and texture coordinates ``uv``."""
    return Mesh(positions, [[0, 1, 2]], {"color": np.eye(3), "uv": uv})


def single_triangle() -> Scene:
    """One front-facing triangle with red, green and blue corners."""
    return Scene(
        "single_triangle",
        "one triangle: coverage, edge functions and barycentric colour interpolation",
        _rgb_triangle(
            [[-1.0, -0.8, 0], [1.0, -0.6, 0], [-0.1, 0.9, 0]], [[0, 1], [1, 1], [0.5, 0]]
        ),
        _facing(),
    )


def textured_floor() -> Scene:
    """Two big triangles of checkerboard floor running from the viewer to the horizon."""
    # A 40 x 40 floor whose near edge (z = 0) is below the bottom of the view and whose far
    # edge is 41 units away: two triangles with very different w, the classic demo of the
    # warp that affine (screen-space) texture interpolation produces.
    mesh = plane_mesh(40.0, 1).transformed(translate(0, 0, -20))
    cam = Camera(eye=(0, 1, 1), target=(0, 0.5, -4), near=0.1, far=100.0)
    return Scene(
        "textured_floor",
        "a textured floor receding to the horizon: affine vs perspective-correct uv",
        mesh,
        cam,
        texture=checkerboard(checks=16, texels=128),
        shading="texture",
    )


def intersecting_triangles() -> Scene:
    """Two triangles that pierce each other along a segment at x = 0."""
    # A lies in the plane z = x/2 and B in z = -x/2: each is in front on one side of x = 0,
    # so neither can be drawn first; only a per-pixel depth test gets both halves right.
    mesh = Mesh(
        [
            [-1.0, -0.6, -0.5],
            [1.0, -0.6, 0.5],
            [0.0, 0.8, 0.0],
            [-1.0, -0.4, 0.5],
            [1.0, -0.4, -0.5],
            [0.0, 1.0, 0.0],
        ],
        [[0, 1, 2], [3, 4, 5]],
        {"color": [[0.9, 0.2, 0.2]] * 3 + [[0.2, 0.3, 0.9]] * 3},
    )
    return Scene(
        "intersecting_triangles",
        "two triangles that pierce each other: the z-buffer resolves depth per pixel",
        mesh,
        _facing(),
    )


def cyclic_overlap() -> Scene:
    """Three long triangles, each over the next and under the previous (a cycle)."""
    # Stick 0 runs along y = -0.4 from its wide end at x = -1.6 (z = +0.3, near) to its tip
    # at x = +1.9 (z = -0.3, far); sticks 1 and 2 are it turned by 120° and 240° about the
    # view axis. The three lines cross at x = ±0.69 along each stick, so each stick passes
    # right through the other two, its ends well beyond them (review r38: crossings that
    # read at a glance, not slivers at the ends). Stick k+1 crosses stick k where k is far
    # and k+1 is near, so the "in front of" relation is a cycle and no painter's order
    # exists, although no two triangles intersect.
    base = np.array([[-1.6, -0.7, 0.3], [1.9, -0.4, -0.3], [-1.6, -0.1, 0.3]])
    colors = np.array([[0.9, 0.3, 0.2], [0.2, 0.7, 0.3], [0.2, 0.4, 0.9]])
    pos = np.concatenate([base @ rotate("z", 120 * k)[:3, :3].T for k in range(3)])
    mesh = Mesh(
        pos,
        np.arange(9).reshape(3, 3),
        {"color": np.repeat(colors, 3, axis=0)},
    )
    return Scene(
        "cyclic_overlap",
        "three triangles in cyclic overlap: no painter's order exists, the z-buffer works",
        mesh,
        _facing(3.6),
    )


def cube() -> Scene:
    """A unit cube seen from above a corner: three faces front-facing, three back-facing."""
    return Scene(
        "cube",
        "a cube: back-face culling by screen winding and depth testing of a closed mesh",
        cube_mesh(1.0),
        Camera(eye=(1.6, 1.3, 2.2), target=(0, 0, 0)),
    )


def uv_sphere(n_lat: int = 16, n_lon: int = 32) -> Scene:
    """A checkerboard-textured latitude-longitude sphere."""
    return Scene(
        "uv_sphere",
        "a textured sphere: many small triangles, poles and a texture seam",
        uv_sphere_mesh(1.0, n_lat, n_lon),
        Camera(eye=(0, 0.8, 3), target=(0, 0, 0)),
        texture=checkerboard(checks=8, texels=64),
        shading="texture",
    )


def fan(n: int = 12) -> Scene:
    """A triangle fan facing the camera: watertight, every pixel filled exactly once."""
    return Scene(
        "fan",
        "a triangle fan: shared edges are filled exactly once (the top-left rule)",
        fan_mesh(n, 1.0),
        _facing(),
    )


def grid(n: int = 8) -> Scene:
    """An n x n grid of quads facing the camera: watertight, flat shaded by triangle id."""
    return Scene(
        "grid",
        "a grid of triangles: shared edges and vertices are filled exactly once",
        grid_mesh(n, n, 2.0),
        _facing(),
        shading="flat",
    )


def behind_camera() -> Scene:
    """A floor triangle with one vertex behind the camera (clip w < 0 there)."""
    # Projecting the vertex behind the eye without clipping first would mirror it to the
    # other side of the image; clipping against the near plane in clip space avoids that.
    mesh = _rgb_triangle(
        [[-1.5, -0.5, -1.0], [0.0, -0.5, 4.0], [1.5, -0.5, -1.0]], [[0, 0], [0.5, 1], [1, 0]]
    )
    return Scene(
        "behind_camera",
        "a triangle partly behind the camera: near-plane clipping in homogeneous space",
        mesh,
        _facing(2.0),
    )


SCENES: dict[str, Callable[[], Scene]] = {
    "single_triangle": single_triangle,
    "textured_floor": textured_floor,
    "intersecting_triangles": intersecting_triangles,
    "cyclic_overlap": cyclic_overlap,
    "cube": cube,
    "uv_sphere": uv_sphere,
    "fan": fan,
    "grid": grid,
    "behind_camera": behind_camera,
}


def get_scene(name: str) -> Scene:
    """Build the built-in scene called ``name`` (see ``SCENES``)."""
    if not isinstance(name, str) or name not in SCENES:
        raise ValueError(f"name: unknown scene {short_repr(name)}; choose from {', '.join(SCENES)}")
    return SCENES[name]()
