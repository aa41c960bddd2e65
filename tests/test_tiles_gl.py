"""The tiled fill against a real GPU rasteriser: Mesa llvmpipe (moderngl + EGL), which walks
64/16/4 blocks itself. Skipped, with the reason, where no OpenGL context can be made."""

from __future__ import annotations

import numpy as np
import pytest
from gl_required import require_gl

require_gl()

import teachraster as tr
from teachraster.study.opengl import gl_render

pytestmark = pytest.mark.gl

W, H = 160, 96  # several 64-blocks, clipped at the right and bottom borders


def clip_from_window(xy):
    """Clip-space vertices (w = 1) landing exactly on window ``xy`` (on the 1/256 grid)."""
    xy = np.asarray(xy, float)
    ndc = np.stack([xy[:, 0] * 2 / W - 1, 1 - xy[:, 1] * 2 / H, np.zeros(3)], axis=-1)
    return np.concatenate([ndc, np.ones((3, 1))], axis=-1)


@pytest.mark.parametrize("kind", ["subpixel", "tie", "small"])
def test_tiled_coverage_equals_llvmpipe(kind):
    """Vertices inside the image on the 1/256 grid (no clipping in GL): identical pixels."""
    rng = np.random.default_rng(["subpixel", "tie", "small"].index(kind) + 1300)
    checked = 0
    for _ in range(60):
        if kind == "subpixel":
            xy = rng.integers(0, [W * 256, H * 256], size=(3, 2)) / 256
        elif kind == "tie":
            xy = rng.integers(0, [2 * W, 2 * H], size=(3, 2)) / 2
        else:  # triangles a few pixels across: partial blocks everywhere
            xy = rng.integers(0, [W * 256, H * 256], size=(1, 2)) / 256
            xy = np.clip(xy + rng.integers(-1024, 1024, size=(3, 2)) / 256, 0, [W, H])
        gl = gl_render(clip_from_window(xy)[None], W, H)
        for sizes in [(64, 16, 4), (16, 4, 1)]:
            ours = tr.rasterize(tr.Triangle(xy), W, H, method="tiled", block_sizes=sizes)
            diff = np.argwhere(gl.coverage != ours.coverage)
            assert not len(diff), f"xy={xy.tolist()} sizes={sizes}: differs at {diff[:5].tolist()}"
        checked += int(gl.coverage.any())
    assert checked > 40
