"""Meshes, model transforms, primitives (winding!) and the OBJ reader."""

from __future__ import annotations

import io
from collections import Counter

import numpy as np
import pytest

from teachraster.pipeline.camera import Camera
from teachraster.pipeline.mesh import (
    Mesh,
    cube_mesh,
    fan_mesh,
    grid_mesh,
    plane_mesh,
    rotate,
    scale,
    translate,
    uv_sphere_mesh,
)
from teachraster.pipeline.obj import ObjError, read_obj
from teachraster.pipeline.viewport import to_window


def face_normals(mesh: Mesh) -> np.ndarray:
    c = mesh.corner_positions()
    return np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])


def signed_volume(mesh: Mesh) -> float:
    """Divergence theorem: positive for a closed mesh whose faces are wound outwards."""
    c = mesh.corner_positions()
    return float(np.einsum("ij,ij->i", c[:, 0], np.cross(c[:, 1], c[:, 2])).sum() / 6)


def welded_edges(mesh: Mesh) -> Counter:
    """Directed edges between *positions* (duplicated seam vertices welded together)."""
    _, ids = np.unique(mesh.positions, axis=0, return_inverse=True)
    t = ids.reshape(-1)[mesh.triangles]
    return Counter((int(t[f, k]), int(t[f, (k + 1) % 3])) for f in range(len(t)) for k in range(3))


def window_E(mesh: Mesh, cam: Camera, width=64, height=48) -> np.ndarray:
    """E(v0, v1, v2) of every triangle in y-down window coordinates."""
    xy = to_window(cam.clip(mesh.corner_positions(), width / height), width, height)[..., :2]
    (x0, y0), (x1, y1), (x2, y2) = xy[:, 0].T, xy[:, 1].T, xy[:, 2].T
    return (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)


# -- Mesh -------------------------------------------------------------------------------------
def test_mesh_copies_and_freezes():
    pos = np.zeros((3, 3))
    m = Mesh(pos, [[0, 1, 2]], {"s": [1, 2, 3]})
    pos[0, 0] = 9
    assert m.positions[0, 0] == 0
    assert m.triangles.dtype == np.int64 and m.positions.dtype == np.float64
    for arr in (m.positions, m.triangles, m.attrs["s"]):
        with pytest.raises(ValueError):
            arr[0] = 1
    assert "V=3, T=1" in repr(m)


@pytest.mark.parametrize(
    "args, error, pattern",
    [
        ((np.zeros((3, 2)), [[0, 1, 2]]), ValueError, "positions"),
        (([[0, 0, np.nan]] * 3, [[0, 1, 2]]), ValueError, "positions"),
        ((np.zeros((3, 3)), [[0, 1, 3]]), ValueError, r"triangles\[0, 2\] = 3"),
        ((np.zeros((3, 3)), [[0, -1, 2]]), ValueError, "triangles"),
        ((np.zeros((3, 3)), [0, 1, 2]), ValueError, r"triangles must have shape \(T, 3\)"),
        ((np.zeros((3, 3)), [[0, 1, 2.5]]), TypeError, "triangles"),
        ((np.zeros((3, 3)), [[0, 1, 2]], {"uv": np.zeros((2, 2))}), ValueError, r"attrs\['uv'\]"),
        ((np.zeros((3, 3)), [[0, 1, 2]], {"c": [0, np.inf, 0]}), ValueError, r"attrs\['c'\]"),
        ((np.zeros((3, 3)), [[0, 1, 2]], {1: [0, 0, 0]}), TypeError, "names"),
    ],
)
def test_mesh_errors_name_the_field(args, error, pattern):
    with pytest.raises(error, match=pattern):
        Mesh(*args)


def test_integral_float_indices_and_empty_mesh():
    assert Mesh(np.zeros((3, 3)), np.array([[0.0, 1.0, 2.0]])).triangles.dtype == np.int64
    empty = Mesh(np.zeros((0, 3)), [])
    assert empty.triangles.shape == (0, 3) and empty.corner_positions().shape == (0, 3, 3)


def test_corner_shapes():
    m = fan_mesh(5)
    m = Mesh(m.positions, m.triangles, {**m.attrs, "s": np.arange(6.0)})
    assert m.corner("s").shape == (5, 3)
    assert m.corner("color").shape == (5, 3, 3)
    assert np.array_equal(m.corner("s"), m.triangles)  # s is the vertex index
    assert np.array_equal(m.corner_positions()[:, 0], np.zeros((5, 3)))
    with pytest.raises(KeyError, match="normal"):
        Mesh(m.positions, m.triangles).corner("normal")


def test_transformed_moves_points_and_normals(rng):
    m = uv_sphere_mesh(1.0, 6, 8)
    mat = translate(1, 2, 3) @ rotate((1, 2, 0.5), 33) @ scale((1, 4, 0.5))
    t = m.transformed(mat)
    assert np.allclose(t.positions, m.positions @ mat[:3, :3].T + mat[:3, 3])
    assert np.array_equal(t.attrs["uv"], m.attrs["uv"])
    n = t.attrs["normal"]
    assert np.allclose(np.linalg.norm(n, axis=1), 1)
    # the inverse transpose keeps normals perpendicular to the stretched surface: a tangent
    # t of the sphere (t . n = 0) becomes A t, and (A t) . (A^-T n) = t . n = 0
    tangent = np.cross(m.attrs["normal"], rng.normal(size=(len(n), 3)))
    assert np.allclose(np.einsum("vj,vj->v", tangent @ mat[:3, :3].T, n), 0, atol=1e-12)
    flat = cube_mesh().transformed(mat)
    fn = face_normals(flat)
    fn /= np.linalg.norm(fn, axis=1, keepdims=True)
    assert np.allclose(flat.corner("normal"), fn[:, None, :])


def test_transformed_rejects_projective_and_singular():
    p = np.eye(4)
    p[3, 2] = -1
    with pytest.raises(ValueError, match="affine"):
        cube_mesh().transformed(p)
    with pytest.raises(ValueError, match="singular"):
        cube_mesh().transformed(scale((1, 0, 1)))
    no_normals = Mesh(cube_mesh().positions, cube_mesh().triangles)
    assert np.all(no_normals.transformed(scale(0)).positions == 0)


def test_merge():
    a, b = fan_mesh(3), cube_mesh()
    b = Mesh(b.positions, b.triangles, {"uv": b.attrs["uv"], "only_b": np.zeros(24)})
    m = Mesh.merge(a, b)
    assert sorted(m.attrs) == ["uv"]
    assert len(m.positions) == 4 + 24
    assert np.array_equal(m.triangles[:3], a.triangles)
    assert np.array_equal(m.triangles[3:], b.triangles + 4)
    assert np.array_equal(m.corner_positions()[3:], b.corner_positions())
    with pytest.raises(ValueError, match="at least one"):
        Mesh.merge()
    bad = Mesh(a.positions, a.triangles, {"uv": np.zeros((4, 3))})
    with pytest.raises(ValueError, match="uv"):
        Mesh.merge(a, bad)


# -- transforms -------------------------------------------------------------------------------
def test_transforms():
    assert np.array_equal(translate(1, 2, 3)[:3, 3], [1, 2, 3])
    assert np.array_equal(np.diag(scale(2)), [2, 2, 2, 1])
    assert np.allclose(rotate("x", 90) @ [0, 1, 0, 1], [0, 0, 1, 1])
    assert np.allclose(rotate("y", 90) @ [0, 0, 1, 1], [1, 0, 0, 1])
    assert np.array_equal(rotate("z", 90) @ [1, 0, 0, 1], [0, 1, 0, 1])  # exact quarter turn
    assert np.allclose(rotate((0, 0, 5), 30), rotate("z", 30))
    r = rotate((1, -2, 3), 77)[:3, :3]
    assert np.allclose(r @ r.T, np.eye(3)) and np.isclose(np.linalg.det(r), 1)
    assert np.allclose(r @ np.array([1, -2, 3]), [1, -2, 3])  # the axis is fixed
    for bad, pattern in [(lambda: rotate("w", 1), "axis"), (lambda: rotate((0, 0, 0), 1), "zero")]:
        with pytest.raises(ValueError, match=pattern):
            bad()
    with pytest.raises(ValueError, match="one factor or three"):
        scale((1, 2))


# -- primitives -------------------------------------------------------------------------------
@pytest.mark.parametrize("n_lat, n_lon", [(2, 3), (3, 4), (16, 32), (7, 5)])
def test_uv_sphere_counts_and_closure(n_lat, n_lon):
    m = uv_sphere_mesh(2.5, n_lat, n_lon)
    assert len(m.triangles) == 2 * n_lat * n_lon - 2 * n_lon
    assert len(m.positions) == (n_lat - 1) * (n_lon + 1) + 2 * n_lon  # seam and poles split
    assert np.array_equal(np.unique(m.triangles), np.arange(len(m.positions)))  # all used
    assert np.allclose(np.linalg.norm(m.positions, axis=1), 2.5)
    assert np.all(np.linalg.norm(face_normals(m), axis=1) > 1e-9)  # no degenerate triangle
    edges = welded_edges(m)
    # closed and consistently wound: every directed edge appears once, its reverse once
    assert all(c == 1 and edges[(b, a)] == 1 for (a, b), c in edges.items())
    assert signed_volume(m) > 0
    uv = m.attrs["uv"]
    assert uv.min() >= 0 and uv.max() <= 1
    north = m.positions[:, 1] == 2.5
    assert np.all(uv[north, 1] == 0)  # the north pole is the top row of the texture


def test_cube():
    m = cube_mesh(2.0)
    assert m.positions.shape == (24, 3) and m.triangles.shape == (12, 3)
    assert np.all(np.abs(m.positions) == 1)
    assert signed_volume(m) == pytest.approx(8.0)
    edges = welded_edges(m)
    assert all(c == 1 and edges[(b, a)] == 1 for (a, b), c in edges.items())
    # per-face attributes: 6 distinct normals and colours, uv covering the unit square
    assert len(np.unique(m.attrs["normal"], axis=0)) == 6
    assert len(np.unique(m.attrs["color"], axis=0)) == 6
    fn = face_normals(m)
    assert np.all(np.einsum("tj,tj->t", fn, m.corner("normal")[:, 0]) > 0)
    for f in range(6):
        assert sorted(map(tuple, m.attrs["uv"][4 * f : 4 * f + 4])) == [
            (0, 0),
            (0, 1),
            (1, 0),
            (1, 1),
        ]


@pytest.mark.parametrize(
    "mesh, normal",
    [
        (plane_mesh(3.0, 4), (0, 1, 0)),
        (grid_mesh(3, 5, 1.0), (0, 0, 1)),
        (fan_mesh(7, 2.0), (0, 0, 1)),
    ],
)
def test_open_primitives_face_their_normal(mesh, normal):
    fn = face_normals(mesh)
    assert np.all(fn @ normal > 0)
    assert np.allclose(fn / np.linalg.norm(fn, axis=1, keepdims=True), normal)
    assert np.allclose(mesh.attrs["normal"], normal)
    assert mesh.attrs["uv"].min() >= 0 and mesh.attrs["uv"].max() <= 1
    # watertight: interior edges are used once in each direction
    edges = welded_edges(mesh)
    assert all(c == 1 for c in edges.values())


def test_primitive_sizes():
    assert plane_mesh(3.0, 4).triangles.shape == (32, 3)
    assert np.array_equal(plane_mesh(3.0, 4).positions[:, 1], np.zeros(25))  # exactly flat
    g = grid_mesh(3, 5, 1.0)
    assert g.triangles.shape == (30, 3) and np.abs(g.positions).max() == 0.5
    f = fan_mesh(7, 2.0)
    assert f.triangles.shape == (7, 3) and np.all(f.triangles[:, 0] == 0)
    assert np.allclose(np.linalg.norm(f.positions[1:], axis=1), 2.0)
    for bad in (lambda: fan_mesh(2), lambda: grid_mesh(0, 1), lambda: uv_sphere_mesh(1, 1, 8)):
        with pytest.raises(ValueError):
            bad()
    with pytest.raises(ValueError, match="radius"):
        uv_sphere_mesh(-1.0)


CAMS = [
    Camera(eye=(2, 1.5, 3), target=(0, 0, 0)),
    Camera(eye=(-3, -2, 0.5), target=(0.1, 0, 0)),
    Camera(eye=(0.2, 4, 0.1), target=(0, 0, 0), fov_y=40),
    Camera(eye=(1, 1, -3), target=(0, 0, 0), projection="orthographic", ortho_height=3),
]


@pytest.mark.parametrize("cam", CAMS)
@pytest.mark.parametrize(
    "mesh", [cube_mesh(1.0), uv_sphere_mesh(0.8, 6, 10)], ids=["cube", "sphere"]
)
def test_winding_front_faces_have_negative_E_on_screen(cam, mesh):
    """CONVENTIONS: counter-clockwise on screen = front-facing = E < 0 in y-down numbers."""
    e = window_E(mesh, cam)
    centroid = mesh.corner_positions().mean(axis=1)
    fn = face_normals(mesh)
    if cam.projection == "perspective":
        to_eye = np.asarray(cam.eye) - centroid
    else:
        to_eye = np.broadcast_to(np.subtract(cam.eye, cam.target), centroid.shape)
    facing = np.einsum("tj,tj->t", fn, to_eye)
    clear = np.abs(facing) > 1e-6 * np.linalg.norm(fn, axis=1)  # skip edge-on faces
    assert clear.sum() >= len(e) // 2
    assert np.all(e[clear & (facing > 0)] < 0)
    assert np.all(e[clear & (facing < 0)] > 0)
    assert (facing > 0).any() and (facing < 0).any()


# -- OBJ --------------------------------------------------------------------------------------
SQUARE = """\
# a unit square as one quad
mtllib nothing.mtl
o square
v 0 0 0
v 1 0 0 1.0
v 1 1 0
v 0 1 0

vn 0 0 1
g front
usemtl none
s off
f 1 2 3 4
"""


@pytest.mark.parametrize("how", ["text", "path", "str_path", "stringio", "bytesio"])
def test_read_obj_sources(how, tmp_path):
    path = tmp_path / "square.obj"
    path.write_text(SQUARE)
    source = {
        "text": SQUARE,
        "path": path,
        "str_path": str(path),
        "stringio": io.StringIO(SQUARE),
        "bytesio": io.BytesIO(SQUARE.encode()),
    }[how]
    m = read_obj(source)
    assert m.triangles.tolist() == [[0, 1, 2], [0, 2, 3]]
    assert np.array_equal(m.positions[2], [1, 1, 0])
    assert m.attrs == {}


def test_read_obj_face_forms_and_negative_indices():
    text = """
v 0 0 0
v 1 0 0
v 0 1 0
vn 0 0 1
f 1//1 2//1 3//1
v 5 5 5
v 6 5 5
v 5 6 5
f -3 -2 -1
f 4 -2 -1 # trailing comment
"""
    m = read_obj(text)
    assert m.triangles.tolist() == [[0, 1, 2], [3, 4, 5], [3, 4, 5]]
    assert len(m.positions) == 6


def test_read_obj_uv_splits_vertices_and_flips_v():
    text = """
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vt 0.25 0.5 0
vn 0 0 1
f 1/1/1 2/2/1 3/3/1
f 1/5/1 3/3/1 4/4/1
"""
    m = read_obj(text)
    # vertex 1 appears with two different texture coordinates: two output vertices
    assert len(m.positions) == 5
    assert m.triangles.tolist() == [[0, 1, 2], [3, 2, 4]]
    assert np.array_equal(m.positions[0], m.positions[3])
    assert np.allclose(m.corner("uv")[0], [[0, 1], [1, 1], [1, 0]])  # v = 1 - v_obj
    assert np.allclose(m.attrs["uv"][3], [0.25, 0.5])


def test_read_obj_pentagon_is_fanned():
    vs = "\n".join(f"v {np.cos(a):.6f} {np.sin(a):.6f} 0" for a in np.linspace(0, 5, 5))
    m = read_obj(vs + "\nvt 0 0\nvt 1 1\nf 1/1 2/2 3/1 4/2 5/1\n")
    assert m.triangles.shape == (3, 3)
    assert np.array_equal(m.triangles[:, 0], [0, 0, 0])
    assert m.attrs["uv"].shape == (5, 2)


def test_read_obj_empty_and_faceless():
    assert read_obj("# nothing\n").triangles.shape == (0, 3)
    assert read_obj("v 1 2 3\n").positions.shape == (1, 3)


def test_read_obj_cube_roundtrip_keeps_winding(tmp_path):
    cube = cube_mesh()
    lines = [f"v {x} {y} {z}" for x, y, z in cube.positions.tolist()]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in cube.triangles]
    m = read_obj("\n".join(lines) + "\n")
    assert np.array_equal(m.corner_positions(), cube.corner_positions())
    assert signed_volume(m) > 0


@pytest.mark.parametrize(
    "text, line, reason",
    [
        ("v 0 0 0\nv 1 x 0\n", 2, "bad number 'x'"),
        ("v 0 0\n", 1, "v needs 3 to 4 numbers, got 2"),
        ("v 0 0 0\nv 1 0 0\nv 0 nan 0\n", 3, "not finite"),
        ("\n\nvt 1 2 3 4\n", 3, "vt needs 1 to 3 numbers"),
        ("v 0 0 0\nv 1 0 0\n# c\nf 1 2\n", 4, "at least 3 vertices"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "vertex index 4 out of range"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "index 0"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n", 4, "out of range"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 a\n", 4, "bad vertex index 'a'"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3\n", 5, "mixes vertex forms"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n", 4, "texture coordinate index 1"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", 4, "normal index 1 out of range"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2/ 3/ \n", 4, None),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", 4, "bad face vertex"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf 1 2 3\n", 6, "line 5 had them"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\nf 1/1 2/1 3/1\n", 6, "line 5 had no"),
        ("v 0 0 0\nbogus 1 2\n", 2, "unknown statement 'bogus'"),
    ],
)
def test_read_obj_errors_give_line_and_reason(text, line, reason):
    with pytest.raises(ObjError) as info:
        read_obj(text)
    assert str(info.value).startswith(f"line {line}: ")
    assert info.value.line == line
    if reason is not None:
        assert reason in str(info.value)
    assert isinstance(info.value, ValueError)


def test_read_obj_bad_source():
    with pytest.raises(TypeError, match="source"):
        read_obj(42)
    with pytest.raises(FileNotFoundError):
        read_obj("no/such/file.obj")
