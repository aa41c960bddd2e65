"""``gl_texture_lod_subprocess``: lesson 09's GPU check in a process of its own.

The comparison with llvmpipe needs OpenGL and is skipped without it; what happens without
OpenGL (no moderngl, or a child that dies) is tested everywhere, with a stand-in ``moderngl``
module put first on the child's path.
"""

from __future__ import annotations

import ast
import os
from pathlib import Path

import numpy as np
import pytest

import teachraster as tr
from teachraster.study import opengl_texture
from teachraster.study.opengl import gl_texture_lod_subprocess

pytestmark = pytest.mark.gl

W, H = 48, 32
CLIP = np.array(
    [
        [[-1, -1, 0.5, 1], [1, -1, 0.5, 1], [-1, 1, 0.5, 4]],
        [[1, -1, 0.5, 1], [1, 1, 0.5, 4], [-1, 1, 0.5, 4]],
    ],
    dtype=float,
)
UV = np.array([[[0, 0], [4, 0], [0, 4]], [[4, 0], [4, 4], [0, 4]]], dtype=float)
LEVELS = tr.mipmap(tr.checkerboard(4, 16))


def _fake_moderngl(tmp_path, monkeypatch, body: str) -> None:
    """Make the child import ``body`` as moderngl (the child inherits PYTHONPATH)."""
    (tmp_path / "moderngl.py").write_text(body)
    path = os.environ.get("PYTHONPATH")
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(filter(None, [str(tmp_path), path])))


def test_without_moderngl_the_answer_says_why(tmp_path, monkeypatch):
    _fake_moderngl(tmp_path, monkeypatch, "raise ImportError('no module named moderngl')\n")
    ok, why, frame = gl_texture_lod_subprocess(CLIP, UV, W, H, LEVELS)
    assert ok is False and frame is None
    assert "moderngl is not installed" in why


def test_a_child_that_dies_is_reported_not_raised(tmp_path, monkeypatch):
    _fake_moderngl(tmp_path, monkeypatch, "import os\nos._exit(3)\n")
    ok, why, frame = gl_texture_lod_subprocess(CLIP, UV, W, H, LEVELS)
    assert ok is False and frame is None
    assert "exit code 3" in why


def test_inputs_are_checked_before_the_child_starts():
    with pytest.raises(ValueError, match="uv"):
        gl_texture_lod_subprocess(CLIP, np.zeros((2, 3, 3)), W, H, LEVELS)
    with pytest.raises(ValueError, match="filter"):
        gl_texture_lod_subprocess(CLIP, UV, W, H, LEVELS, filter="anisotropic")
    with pytest.raises(ValueError, match="width"):
        gl_texture_lod_subprocess(CLIP, UV, 0, H, LEVELS)


def test_the_child_script_imports_only_numpy_and_moderngl():
    """What makes it start fast: no ``import teachraster`` (nor a relative import) in it."""
    tree = ast.parse(Path(opengl_texture.__file__).read_text())
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            assert node.level == 0, "a relative import fails when the file runs as a script"
            names.add(node.module.split(".")[0])
    assert names <= {"__future__", "sys", "numpy", "moderngl"}, names


def test_the_same_frame_as_in_process():
    from teachraster.study.opengl import gl_available, gl_texture_lod

    ok, why = gl_available()
    if not ok:
        if os.environ.get("TEACHRASTER_REQUIRE_GL"):
            raise RuntimeError(f"TEACHRASTER_REQUIRE_GL is set but no OpenGL context: {why}")
        pytest.skip(f"no OpenGL context can be created here: {why}")
    for filter in ("nearest_mipmap_nearest", "trilinear"):
        ok, renderer, apart = gl_texture_lod_subprocess(CLIP, UV, W, H, LEVELS, filter=filter)
        assert ok and renderer == why
        here = gl_texture_lod(CLIP, UV, W, H, LEVELS, filter=filter)
        for field in ("triangle_id", "lod", "level", "color"):
            np.testing.assert_array_equal(getattr(apart, field), getattr(here, field))
        assert (apart.triangle_id >= 0).mean() > 0.3 and np.nanmax(apart.lod) > 3  # a trapezoid


def test_no_notebook_starts_multiprocessing():
    """A ``multiprocessing`` child (spawn or forkserver) starts a resource-tracker process that
    outlives it; IPython's kernel then waits about two seconds for it at every shut-down or
    restart (lesson 09 once took 2.2 s longer that way). A plain ``subprocess``, as
    :func:`gl_texture_lod_subprocess` uses, leaves nothing behind."""
    import nbformat

    folder = Path(__file__).resolve().parent.parent / "notebooks"
    for path in sorted(folder.glob("**/*.ipynb")):
        source = "\n".join(c.source for c in nbformat.read(path, as_version=4).cells)
        for word in ("multiprocessing", "ProcessPoolExecutor"):
            assert word not in source, f"{path.name} uses {word}"
