"""Vertices outside the viewport: where llvmpipe and teachraster part, and why.

llvmpipe clips triangles against the viewport in x and y (Mesa's draw module, set up in
``llvmpipe_create_context`` with "clipping - enabled, with no guardband"). The new vertices
are computed in float32 and snapped again, so a clipped edge moves by up to about 1/512 px, and
a pixel centre or sample lying on such an edge, or within a snapping step of it, may be
decided the other way: with vertices on half pixels that is exactly on an edge; with
vertices anywhere on the 1/256 grid, or off it, samples up to 0.0015 px inside an edge were
seen to differ. teachraster clips only against the near and far planes and rasterises the
rest of the triangle as it is (a guard band far outside the image, as Direct3D's rules and hardware
guard bands do): clipping never changes which centres are covered. So the two agree on every
centre and sample farther than 1/256 px from an edge, and agree everywhere when all vertices
are inside the viewport.
"""

from __future__ import annotations

import numpy as np
import pytest
from gl_required import require_gl

require_gl()

import teachraster as tr  # noqa: E402
from teachraster.study.opengl import gl_render, gl_render_samples  # noqa: E402

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


def edge_distance(win: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Distance (px) of each point (x, y) from the nearest of the triangle's edge lines."""
    d = np.full(len(points), np.inf)
    for a, b in ((0, 1), (1, 2), (2, 0)):
        length = float(np.hypot(*(win[b] - win[a])))
        d = np.minimum(d, np.abs(tr.edge_function(win[a], win[b], points)) / length)
    return d


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


def test_outside_the_viewport_centres_and_samples_differ_only_within_a_snapping_step():
    """Vertices anywhere (on the 1/256 grid, or off it), pixel centres and the 4 standard
    samples: every difference lies within 1/256 px of an edge line, and some do not lie
    exactly on one (the note used to say "only exactly on an edge")."""
    rng = np.random.default_rng(5)
    pattern = tr.sample_pattern(4)
    near = []
    for k in range(120):
        lo, hi = (-40, -30), (W + 40, H + 30)
        win = np.column_stack([rng.uniform(lo[0], hi[0], 3), rng.uniform(lo[1], hi[1], 3)])
        if k % 2:
            win = np.round(win * 256) / 256
        clip = clip_space(win)
        ours = tr.render(clip, W, H, samples=4, depth_test=False).sample_triangle_id >= 0
        gl = gl_render_samples(clip, W, H, samples=4, depth_test=False).sample_triangle_id >= 0
        r, c, s = np.nonzero(ours != gl)
        near += edge_distance(win, np.c_[c + pattern[s, 0], r + pattern[s, 1]]).tolist()
        r, c = differing(win).T
        near += edge_distance(win, np.c_[c + 0.5, r + 0.5]).tolist()
    near = np.array(near)
    assert len(near) > 0 and (near <= 1 / 256).all(), near.max()
    assert (near > 0).any()  # not only exactly on an edge
