"""Triangle meshes, model transforms and primitive builders.

A :class:`Mesh` is indexed, as on a GPU: shared vertex positions, triangles as triples of
indices, and per-vertex attributes. Where a vertex needs different attributes on
different faces (a cube's corners, a sphere's texture seam) it is simply duplicated.

Winding: every closed mesh here has its outward faces counter-clockwise when seen from
outside (OpenGL's default front face). Seen through a camera, front faces then have a
negative ``E(v1, v2, v3)`` in y-down window coordinates (see CONVENTIONS).

>>> m = cube_mesh()
>>> m.positions.shape, m.triangles.shape, m.corner("uv").shape
((24, 3), (12, 3), (12, 3, 2))
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from ...core.validate import as_finite, as_float, as_int, check_shape


def _integral(arr: np.ndarray) -> bool:
    """Whether float ``arr`` holds whole numbers that int64 can take without overflow."""
    return bool(np.all(np.isfinite(arr)) and np.all(arr == np.round(arr))) and bool(
        np.all(np.abs(arr) < 2**62)
    )


def _as_indices(value, n_vertices: int) -> np.ndarray:
    try:
        arr = np.asarray(value)
        if arr.size == 0:
            arr = arr.reshape(0, 3).astype(np.int64)
        if arr.dtype.kind == "f" and _integral(arr):
            arr = arr.astype(np.int64)  # integral floats (e.g. from np.loadtxt) are fine
    except (TypeError, ValueError) as exc:
        raise TypeError(f"triangles must be an integer array: {exc}") from None
    if arr.dtype.kind not in "iu":
        raise TypeError(f"triangles must hold integer vertex indices, got dtype {arr.dtype}")
    if arr.ndim != 2 or arr.shape[1] != 3:
        raise ValueError(f"triangles must have shape (T, 3), got {arr.shape}")
    arr = arr.astype(np.int64)
    bad = (arr < 0) | (arr >= n_vertices)
    if bad.any():
        t, k = np.argwhere(bad)[0]
        raise ValueError(
            f"triangles[{t}, {k}] = {arr[t, k]} is not a vertex index: "
            f"there are {n_vertices} positions (valid 0..{n_vertices - 1})"
        )
    return arr


@dataclass(frozen=True, eq=False)
class Mesh:
    """An indexed triangle mesh.

    Parameters
    ----------
    positions : (V, 3) array-like
        Vertex positions (model or world space).
    triangles : (T, 3) integer array-like
        Indices into ``positions``; counter-clockwise = front-facing (OpenGL).
    attrs : mapping of str to (V,) or (V, k) array-like
        Per-vertex attributes, e.g. ``"uv"`` (V, 2), ``"color"`` (V, 3), ``"normal"`` (V, 3).

    All arrays are copied and made read-only. Equality is identity (arrays have no single
    truth value).
    """

    positions: np.ndarray
    triangles: np.ndarray
    attrs: Mapping[str, np.ndarray] = field(default_factory=dict)

    def __post_init__(self) -> None:
        pos = as_finite("positions", self.positions, (None, 3))
        tris = _as_indices(self.triangles, len(pos))
        if not isinstance(self.attrs, Mapping):
            raise TypeError(f"attrs must be a mapping of name to values, got {type(self.attrs)}")
        clean = {}
        for name, values in self.attrs.items():
            if not isinstance(name, str):
                raise TypeError(f"attrs: names must be strings, got {name!r}")
            arr = as_finite(f"attrs[{name!r}]", values, None)
            shape = (len(pos),) if arr.ndim == 1 else (len(pos), None)
            check_shape(f"attrs[{name!r}]", arr.shape, shape)
            clean[name] = arr
        for arr in (pos, tris, *clean.values()):
            arr.flags.writeable = False
        object.__setattr__(self, "positions", pos)
        object.__setattr__(self, "triangles", tris)
        object.__setattr__(self, "attrs", clean)

    def __repr__(self) -> str:
        attrs = ", ".join(f"{k}{v.shape[1:] or ''}" for k, v in self.attrs.items())
        return f"Mesh(V={len(self.positions)}, T={len(self.triangles)}, attrs=[{attrs}])"

    def corner(self, name: str) -> np.ndarray:
        """Per-triangle corner values of attribute ``name``: (T, 3) or (T, 3, k)."""
        if name not in self.attrs:
            raise KeyError(f"mesh has no attribute {name!r}; it has {sorted(self.attrs)}")
        return self.attrs[name][self.triangles]

    def corner_positions(self) -> np.ndarray:
        """Per-triangle corner positions, (T, 3, 3)."""
        return self.positions[self.triangles]

    def transformed(self, matrix) -> Mesh:
        """This mesh moved by an affine model matrix (4, 4).

        Positions are transformed as points; a ``"normal"`` attribute by the inverse
        transpose (so it stays perpendicular to the surface under non-uniform scaling)
        and renormalised. Other attributes are copied. As in OpenGL, a mirroring matrix
        (negative determinant) reverses the winding; the triangle order is left alone.

        >>> plane_mesh(2, 1).transformed(scale((1, 1, 3))).attrs["normal"][0]
        array([0., 1., 0.])
        """
        m = as_finite("matrix", matrix, (4, 4))
        if not np.array_equal(m[3], [0, 0, 0, 1]):
            # Projections belong to the camera (clip space keeps w); a model transform
            # that divided here would lose the w that clipping and interpolation need.
            raise ValueError(f"matrix must be affine (last row 0 0 0 1), got {m[3].tolist()}")
        attrs = dict(self.attrs)
        if "normal" in attrs:
            if abs(np.linalg.det(m[:3, :3])) < 1e-300:
                raise ValueError("matrix is singular: normals cannot be transformed")
            n = attrs["normal"] @ np.linalg.inv(m[:3, :3])  # == (inv(A).T @ n.T).T
            length = np.linalg.norm(n, axis=-1, keepdims=True)
            attrs["normal"] = np.divide(n, length, out=np.zeros_like(n), where=length > 0)
        pos = self.positions @ m[:3, :3].T + m[:3, 3]
        return Mesh(pos, self.triangles, attrs)

    @classmethod
    def merge(cls, *meshes: Mesh) -> Mesh:
        """One mesh holding all triangles of ``meshes``, in order.

        Only attributes present in every mesh (with the same width k) are kept.

        >>> Mesh.merge(fan_mesh(3), cube_mesh()).triangles.shape
        (15, 3)
        """
        if not meshes:
            raise ValueError("merge needs at least one mesh")
        for m in meshes:
            if not isinstance(m, Mesh):
                raise TypeError(f"merge takes Mesh objects, got {type(m)}")
        names = [n for n in meshes[0].attrs if all(n in m.attrs for m in meshes)]
        for n in names:
            widths = {m.attrs[n].shape[1:] for m in meshes}
            if len(widths) > 1:
                raise ValueError(f"attrs[{n!r}] has different shapes per vertex: {widths}")
        offsets = np.cumsum([0] + [len(m.positions) for m in meshes[:-1]])
        return cls(
            np.concatenate([m.positions for m in meshes]),
            np.concatenate([m.triangles + o for m, o in zip(meshes, offsets)]),
            {n: np.concatenate([m.attrs[n] for m in meshes]) for n in names},
        )


# -- model transforms -------------------------------------------------------------------------
def translate(x: float, y: float, z: float) -> np.ndarray:
    """Translation matrix (4, 4).

    >>> translate(1, 2, 3) @ [0, 0, 0, 1]
    array([1., 2., 3., 1.])
    """
    m = np.eye(4)
    m[:3, 3] = [as_float("x", x), as_float("y", y), as_float("z", z)]
    return m


def scale(s) -> np.ndarray:
    """Scaling matrix (4, 4): ``s`` is one factor or three (x, y, z).

    >>> np.diag(scale((1, 2, 3)))
    array([1., 2., 3., 1.])
    """
    s = np.atleast_1d(as_finite("s", s, (None,) if np.ndim(s) else ()))
    if s.shape not in ((1,), (3,)):
        raise ValueError(f"s must be one factor or three, got {s.shape[0]}")
    return np.diag([*np.broadcast_to(s, (3,)), 1.0])


def rotate(axis, degrees: float) -> np.ndarray:
    """Rotation matrix (4, 4) by ``degrees`` about ``axis`` ("x", "y", "z" or a 3-vector).

    Right-handed: counter-clockwise when seen from the tip of the axis looking back.

    >>> rotate("z", 90) @ [1, 0, 0, 1]
    array([0., 1., 0., 1.])
    """
    if isinstance(axis, str):
        named = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1)}
        if axis.lower() not in named:
            raise ValueError(f"axis must be 'x', 'y', 'z' or a 3-vector, got {axis!r}")
        axis = named[axis.lower()]
    a = as_finite("axis", axis, (3,))
    length = np.linalg.norm(a)
    if length == 0:
        raise ValueError("axis must not be the zero vector")
    x, y, z = a / length
    degrees = as_float("degrees", degrees)
    if degrees % 90 == 0:
        # Quarter turns exactly: cos(90°) in floating point is 6e-17, not 0, which would
        # leave a floor that is not quite flat.
        c, s = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(degrees // 90) % 4]
    else:
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])  # cross-product matrix
    m = np.eye(4)
    m[:3, :3] = c * np.eye(3) + s * k + (1 - c) * np.outer([x, y, z], [x, y, z])  # Rodrigues
    return m


# -- primitives -------------------------------------------------------------------------------


def _positive(name: str, value) -> float:
    v = as_float(name, value, finite=False)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"{name} must be a finite number > 0, got {value!r}")
    return v


def _quads(nx: int, ny: int) -> np.ndarray:
    """Two triangles per cell of an (ny+1) x (nx+1) vertex lattice, row-major.

    Cell corners a (i, j), b (i, j+1), c (i+1, j+1), d (i+1, j) give (a, b, c), (a, c, d):
    counter-clockwise when the lattice's first axis (j) x second axis (i) is the normal.
    """
    i, j = np.meshgrid(np.arange(ny), np.arange(nx), indexing="ij")
    a = (i * (nx + 1) + j).ravel()
    b, c, d = a + 1, a + nx + 2, a + nx + 1
    return np.stack([np.stack([a, b, c], -1), np.stack([a, c, d], -1)], 1).reshape(-1, 3)


def grid_mesh(nx: int, ny: int, size: float = 2.0) -> Mesh:
    """An ``nx`` x ``ny`` grid of quads (2 triangles each) in the z = 0 plane, facing +z.

    Spans ``[-size/2, size/2]`` in x and y; watertight (neighbouring cells share vertices).
    uv runs 0..1 along +x (u) and -y (v): texture row 0 (v = 0) is at the top, so a texture
    appears upright (the convention of :mod:`teachraster.pipeline.texture`).

    >>> grid_mesh(3, 2).triangles.shape
    (12, 3)
    """
    nx, ny, size = as_int("nx", nx, minimum=1), as_int("ny", ny, minimum=1), _positive("size", size)
    u, v = np.meshgrid(np.linspace(0, 1, nx + 1), np.linspace(0, 1, ny + 1))
    u, v = u.ravel(), v.ravel()
    pos = np.stack([(u - 0.5) * size, (v - 0.5) * size, np.zeros_like(u)], -1)
    attrs = {
        "uv": np.stack([u, 1 - v], -1),  # texture row 0 (v = 0) at the top (+y)
        "color": np.stack([u, v, np.full_like(u, 0.5)], -1),
        "normal": np.tile([0.0, 0.0, 1.0], (len(u), 1)),
    }
    return Mesh(pos, _quads(nx, ny), attrs)


def plane_mesh(size: float = 2.0, n: int = 1) -> Mesh:
    """A square floor in the y = 0 plane, ``n`` x ``n`` quads, facing up (+y).

    Spans ``[-size/2, size/2]`` in x and z; uv runs 0..1 along +x (u) and +z (v), so a
    viewer standing at +z sees the texture upright, its top row (v = 0) farthest away.

    >>> plane_mesh(2, 1).corner_positions()[0]
    array([[-1.,  0.,  1.],
           [ 1.,  0.,  1.],
           [ 1.,  0., -1.]])
    """
    grid = grid_mesh(n, n, size)
    # Tip the xy grid back onto the floor: +y becomes -z, the normal +z becomes +y.
    return grid.transformed(rotate("x", -90))


def cube_mesh(size: float = 1.0) -> Mesh:
    """An axis-aligned cube of edge ``size`` centred at the origin: 24 vertices, 12 triangles.

    Each face has its own 4 vertices, so uv (0..1 per face, upright on the side faces),
    normal and colour can differ from face to face. Colours (Okabe and Ito's colour-blind-safe
    set, as in every figure of the course): +x vermillion, -x sky blue, +y bluish green,
    -y reddish purple, +z blue, -z yellow.
    """
    h = _positive("size", size) / 2
    normals = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    hexes = ["D55E00", "56B4E9", "009E73", "CC79A7", "0072B2", "F0E442"]
    colors = np.array([[int(h[i : i + 2], 16) / 255 for i in (0, 2, 4)] for h in hexes])
    corners = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]])  # counter-clockwise in (u, v)
    pos, uv, nrm, col = [], [], [], []
    for n, c in zip(normals, colors):
        # Pick u so that v = n x u is "up" on the side faces; then u x v = n, and corners
        # that run counter-clockwise in (u, v) run counter-clockwise seen from outside.
        u = np.cross([0, 1, 0], n) if n[1] == 0 else np.array([1, 0, 0])
        v = np.cross(n, u)
        pos.append(h * (n + corners[:, :1] * u + corners[:, 1:] * v))
        uv.append(np.stack([corners[:, 0] + 1, 1 - corners[:, 1]], -1) / 2)  # v down
        nrm.append(np.tile(n, (4, 1)))
        col.append(np.tile(c, (4, 1)))
    tris = np.array([[0, 1, 2], [0, 2, 3]])
    tris = np.concatenate([tris + 4 * f for f in range(6)])
    attrs = {"uv": np.concatenate(uv), "normal": np.concatenate(nrm)}
    attrs["color"] = np.concatenate(col).astype(np.float64)
    return Mesh(np.concatenate(pos), tris, attrs)


def uv_sphere_mesh(radius: float = 1.0, n_lat: int = 16, n_lon: int = 32) -> Mesh:
    """A latitude-longitude sphere: ``2 n_lat n_lon - 2 n_lon`` triangles.

    Rings run from the north pole (+y, v = 0, the texture's top row) to the south pole
    (v = 1); u = longitude /
    360°, growing counter-clockwise seen from +y. The seam column (u = 0 and u = 1) and
    the pole vertices are duplicated so each can carry its own uv; their positions are
    exactly equal, so the surface stays watertight. Near the poles each band is one
    triangle per longitude step, not a quad with a degenerate half.

    >>> uv_sphere_mesh(1, 4, 6).triangles.shape
    (36, 3)
    """
    r = _positive("radius", radius)
    n_lat, n_lon = as_int("n_lat", n_lat, minimum=2), as_int("n_lon", n_lon, minimum=3)
    i, j = np.meshgrid(np.arange(n_lat + 1), np.arange(n_lon + 1), indexing="ij")
    theta = np.pi * i / n_lat  # polar angle from +y
    phi = 2 * np.pi * (j % n_lon) / n_lon  # j % n_lon: the seam repeats column 0 exactly
    sin_t = np.where((i == 0) | (i == n_lat), 0.0, np.sin(theta))  # exact poles
    cos_t = np.where(i == 0, 1.0, np.where(i == n_lat, -1.0, np.cos(theta)))
    normal = np.stack([sin_t * np.sin(phi), cos_t, sin_t * np.cos(phi)], -1).reshape(-1, 3)
    u = j / n_lon
    u = np.where((i == 0) | (i == n_lat), (j + 0.5) / n_lon, u)  # pole: middle of its wedge
    uv = np.stack([u, i / n_lat], -1).reshape(-1, 2)
    row = n_lon + 1
    tris = []
    for band in range(n_lat):
        a = band * row + np.arange(n_lon)  # (band, j)
        b, c, d = a + row, a + row + 1, a + 1  # (band+1, j), (band+1, j+1), (band, j+1)
        # Longitude grows counter-clockwise seen from +y, so from outside the order
        # top-left a, bottom-left b, bottom-right c, top-right d is counter-clockwise.
        # A pole band has one triangle per wedge, using pole vertex j (at u of its middle).
        if band == 0:
            tris.append(np.stack([a, b, c], -1))  # a is the north pole
        elif band == n_lat - 1:
            tris.append(np.stack([a, b, d], -1))  # b is the south pole
        else:
            tris += [np.stack([a, b, c], -1), np.stack([a, c, d], -1)]
    tris = np.concatenate(tris)
    # The last pole vertex of each pole row is never used (a pole has one vertex per
    # wedge, not per meridian): keep only used vertices, renumbered in order.
    used = np.unique(tris)
    new_index = np.full(len(normal), -1)
    new_index[used] = np.arange(len(used))
    normal, uv = normal[used], uv[used]
    attrs = {"uv": uv, "normal": normal, "color": 0.5 + 0.5 * normal}
    return Mesh(r * normal, new_index[tris], attrs)


def fan_mesh(n: int = 12, radius: float = 1.0) -> Mesh:
    """``n`` triangles around a shared centre vertex in the z = 0 plane, facing +z.

    Vertex 0 is the centre; rim vertex k is at angle 360° k / n. Neighbours share rim
    vertices, so the fan is watertight.

    >>> fan_mesh(4).triangles.tolist()
    [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    """
    n, r = as_int("n", n, minimum=3), _positive("radius", radius)
    a = 2 * np.pi * np.arange(n) / n
    xy = np.concatenate([[[0.0, 0.0]], np.stack([np.cos(a), np.sin(a)], -1)])
    pos = np.concatenate([r * xy, np.zeros((n + 1, 1))], axis=1)
    k = np.arange(1, n + 1)
    tris = np.stack([np.zeros(n, dtype=np.int64), k, k % n + 1], -1)
    hue = np.concatenate([[0.0], a]) / (2 * np.pi)
    # A simple colour wheel with a white centre, so interpolation shows up clearly.
    color = 0.5 + 0.5 * np.cos(2 * np.pi * (hue[:, None] - [0, 1 / 3, 2 / 3]))
    color[0] = 1.0
    attrs = {
        "uv": 0.5 + [0.5, -0.5] * xy,
        "color": color,
        "normal": np.tile([0.0, 0, 1], (n + 1, 1)),
    }
    return Mesh(pos, tris, attrs)
