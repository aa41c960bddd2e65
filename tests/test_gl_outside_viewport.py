"""Vertices outside the viewport: where llvmpipe and teachraster part, and why.

llvmpipe clips triangles against the viewport in x and y (Mesa's draw module, set up in
``llvmpipe_create_context`` with "clipping - enabled, with no guardband"). The new vertices
are computed in float32 and snapped again, so a clipped edge moves by up to about 1/512 px, and
a pixel centre lying *exactly* on such an edge may be decided the other way. teachraster clips
only against the near and far planes and rasterises the rest of the triangle as it is (an
unlimited guard band, as Direct3D's rules and hardware guard bands do): clipping never changes
which centres are covered. So the two agree on every centre that is not exactly on an edge,
and agree everywhere when all vertices are inside the viewport.
"""

from __future__ import annotations

import numpy as np
import pytest
from gl_required import require_gl

require_gl()

import teachraster as tr  # noqa: E402
from teachraster.study.opengl import gl_render  # noqa: E402

pytestmark = pytest.mark.gl

W, H = 64, 32


def clip_space(win: np.ndarray) -> np.ndarray:
    """Window positions (y down) to clip space with w = 1 (exact: quarter pixels)."""
    clip = np.zeros((1, 3, 4))
    clip[0, :, 0] = win[:, 0] / W * 2 - 1
    clip[0, :, 1] = 1 - win[:, 1] / H * 2
    clip[0, :, 2] = 0.5
    clip[0, :, 3] = 1.0
    return clip


def differing(win: np.ndarray) -> np.ndarray:
    ours = tr.render(clip_space(win), W, H).coverage
    gl = gl_render(clip_space(win), W, H, depth_test=False).triangle_id >= 0
    return np.argwhere(ours != gl)


def on_an_edge(win: np.ndarray, rows_cols: np.ndarray) -> np.ndarray:
    """Whether each pixel centre lies exactly on one of the triangle's edge lines."""
    p = rows_cols[:, ::-1] + 0.5
    hits = np.zeros(len(p), dtype=bool)
    for a, b in ((0, 1), (1, 2), (2, 0)):
        hits |= tr.edge_function(win[a], win[b], p) == 0  # exact on the quarter-pixel grid
    return hits


def random_windows(rng, n, inside: bool):
    for _ in range(n):
        lo_x, hi_x = (0, 4 * W - 1) if inside else (-160, 4 * W + 160)
        lo_y, hi_y = (0, 4 * H - 1) if inside else (-120, 4 * H + 120)
        win = np.column_stack([rng.integers(lo_x, hi_x, 3), rng.integers(lo_y, hi_y, 3)]) / 4.0
        yield np.round(win * 2) / 2 + 0.5  # on half pixels: many centres exactly on edges


def test_vertices_inside_the_viewport_agree_everywhere():
    rng = np.random.default_rng(7)
    for win in random_windows(rng, 80, inside=True):
        if (win[:, 0] < W).all() and (win[:, 1] < H).all():
            assert len(differing(win)) == 0, win.tolist()


def test_outside_the_viewport_only_centres_exactly_on_an_edge_differ():
    rng = np.random.default_rng(1)
    seen = 0
    for win in random_windows(rng, 150, inside=False):
        d = differing(win)
        assert on_an_edge(win, d).all(), (win.tolist(), d.tolist())
        seen += len(d)
    assert seen > 0  # the case exists: llvmpipe's viewport clipping does move edges
