"""Lines against a real GPU rasteriser: GL_LINES / GL_LINE_STRIP / GL_LINE_LOOP through Mesa's
llvmpipe (moderngl + EGL), pixel by pixel. Skipped, with the reason, without OpenGL.

What these tests found (Mesa 22.3, ``lp_setup_line.c``): llvmpipe follows GL's diamond-exit
rule for one-pixel lines everywhere except at three kinds of place, each tested below as such
(``llvmpipe_deviation`` names them): end points exactly on a diamond boundary, the first pixel
of y-major lines running up from a pixel-centre row, and centres within 1/512 px of the
half-way line. Wide lines: llvmpipe fills GL's aliased parallelogram (offset along the minor
axis), not the rectangle of our CONVENTIONS; away from the ends the parallelogram agrees with
llvmpipe exactly, and the rectangle differs.
"""

from __future__ import annotations

import collections

import numpy as np
import pytest
from gl_required import require_gl

require_gl()

import teachraster as tr
from teachraster.core.lines import wide_line_triangles
from teachraster.study.opengl_lines import gl_lines, llvmpipe_deviation

pytestmark = pytest.mark.gl

W, H = 64, 32  # powers of two: the float32 viewport transform is exact on the 1/256 grid


def _ours(p0, p1):
    return tr.rasterize_line(p0, p1, W, H).coverage.astype(int)


def _random_lines(seed, grid, n):
    rng = np.random.default_rng(seed)
    return [rng.integers(0, [W * grid, H * grid], (2, 2)) / grid for _ in range(n)]


@pytest.mark.parametrize("grid", [256, 4, 2])
def test_gl_lines_match_the_diamond_rule_except_the_named_deviations(grid):
    """Every pixel agrees, or the disagreement is one of llvmpipe's three shortcuts."""
    seen = collections.Counter()
    for p in _random_lines(grid, grid, 150):
        gl = gl_lines(p, W, H)
        ours = _ours(p[0], p[1])
        for r, c in np.argwhere(gl != ours):
            why = llvmpipe_deviation(p[0], p[1], r, c)
            assert why is not None, f"unexplained difference on {p.tolist()} at ({r}, {c})"
            seen[why] += 1
    if grid == 256:  # generic lines: the end tests almost never meet a boundary exactly
        assert sum(seen.values()) <= 10, seen


def test_generic_lines_agree_pixel_for_pixel():
    """Off the boundaries (end points not on a diamond edge, no half-way ties) no pixel differs."""
    agree = 0
    for p in _random_lines(7, 256, 100):
        gl, ours = gl_lines(p, W, H), _ours(p[0], p[1])
        explained = all(llvmpipe_deviation(p[0], p[1], r, c) for r, c in np.argwhere(gl != ours))
        assert explained
        agree += bool((gl == ours).all())
    assert agree >= 95


def test_deviation_a_endpoint_on_a_diamond_boundary():
    p = np.array([[1.64453125, 27.14453125], [60.44921875, 4.65234375]])
    gl, ours = gl_lines(p, W, H), _ours(p[0], p[1])
    assert ours[27, 1] == 1 and gl[27, 1] == 0  # GL's ε says the start pixel is exited
    assert llvmpipe_deviation(p[0], p[1], 27, 1) == "endpoint_on_diamond"


def test_deviation_b_y_major_up_from_a_centre_row_drops_the_first_pixel():
    p = np.array([[10.25, 20.5], [12.625, 5.3125]])  # y-major, running up, start on row 20's centre
    gl, ours = gl_lines(p, W, H), _ours(p[0], p[1])
    assert ours[20, 10] == 1 and gl[20, 10] == 0
    assert (gl != ours).sum() == 1
    assert llvmpipe_deviation(p[0], p[1], 20, 10) == "y_major_up_on_centre_row"


def test_deviation_c_centres_near_the_half_way_line():
    p = np.array([[31.53125, 1.09765625], [41.6953125, 31.58203125]])
    gl, ours = gl_lines(p, W, H), _ours(p[0], p[1])
    diff = np.argwhere(gl != ours)
    assert len(diff) > 0
    assert {llvmpipe_deviation(p[0], p[1], r, c) for r, c in diff} == {"half_way_centre"}


def test_line_strip_and_loop_light_shared_vertices_once_as_ours():
    pts = np.array([(3.25, 4.5), (40.125, 9.75), (50.5, 28.25), (10.0625, 20.375)])
    strip = sum(_ours(a, b) for a, b in zip(pts[:-1], pts[1:]))
    assert (gl_lines(pts, W, H, mode="line_strip") == strip).all()
    loop = sum(_ours(a, b) for a, b in zip(pts, np.roll(pts, -1, axis=0)))
    gl_loop = gl_lines(pts, W, H, mode="line_loop")
    assert (gl_loop == loop).all() and gl_loop.max() == 1


def test_sharp_turn_lights_a_pixel_twice_in_gl_too():
    pts = np.array([(0.5, 0.5), (4.0, 2.0), (0.5, 1.5)])  # the turn is on a diamond corner
    gl = gl_lines(pts, W, H, mode="line_strip")
    ours = sum(_ours(a, b) for a, b in zip(pts[:-1], pts[1:]))
    assert ours.max() == 2
    # (4, 2) lies on diamond boundaries: deviation (a) may move single pixels, not the point
    assert gl.max() == 2


def test_bresenham_differs_where_the_diamond_rule_and_gl_agree():
    p = np.array([[0.5, 0.5], [4.5, 2.5]])
    gl = gl_lines(p, W, H)
    bres = tr.rasterize_line(p[0], p[1], W, H, rule="bresenham").coverage
    assert (gl == _ours(p[0], p[1])).all()
    assert gl[1, 1] == 1 and bres[0, 1] and not bres[1, 1]


@pytest.mark.parametrize("line_width", [2, 3, 5])
def test_wide_lines_are_gls_parallelogram_in_llvmpipe(line_width):
    """Away from the two ends, llvmpipe's wide line is GL's minor-axis parallelogram pixel for
    pixel; our rectangle (CONVENTIONS) is a different shape and differs there."""
    rect_differs = 0
    for p in _random_lines(line_width, 256, 30):
        gl = gl_lines(p, W, H, line_width=line_width)
        para = np.zeros((H, W), int)
        for tri in wide_line_triangles(p[0], p[1], line_width, shape="gl"):
            para += tr.rasterize(tr.Triangle(tri), W, H).coverage
        x_major = abs(p[1, 0] - p[0, 0]) >= abs(p[1, 1] - p[0, 1])
        axis = 0 if x_major else 1
        lo, hi = sorted(p[:, axis])
        centres = np.arange(W if x_major else H) + 0.5
        inner = (centres > lo + 1) & (centres < hi - 1)
        mask = np.broadcast_to(inner[None, :] if x_major else inner[:, None], (H, W))
        assert (gl == para)[mask].all(), p.tolist()
        rect = tr.rasterize_line(p[0], p[1], W, H, line_width=line_width).coverage
        rect_differs += bool((gl != rect)[mask].any())
    assert rect_differs > 0


@pytest.mark.parametrize(
    "name", [n for n in __import__("teachraster.study.hardcases", fromlist=["x"]).LINE_CASES
             if n != "line_very_long"],
)  # fmt: skip
def test_line_hard_cases_in_llvmpipe(name):
    """Each segment of each line case: llvmpipe's pixels, up to the named deviations."""
    from teachraster.study.hardcases import get_line_case

    case = get_line_case(name)
    width, height = case.size
    for (p0, p1), fill in zip(case.segments, case.run().fills):
        gl = gl_lines(np.array([p0, p1]), 64, 64)
        assert not gl[height:].any() and not gl[:, width:].any()
        ours = fill.coverage.astype(int)
        for r, c in np.argwhere(gl[:height, :width] != ours):
            assert llvmpipe_deviation(p0, p1, r, c), (name, p0.tolist(), p1.tolist(), r, c)


def test_line_attributes_llvmpipe_uses_the_major_axis_not_the_projection():
    """GL's t projects the centre onto the segment (ours); llvmpipe's planes run along the
    major axis only. With that t the 1/w rule agrees with llvmpipe to float32 accuracy."""
    from teachraster.core.lines import line_parameter
    from teachraster.study.opengl_lines import gl_line_attribute

    rng = np.random.default_rng(21)
    projection_differs = 0
    for _ in range(20):
        p = rng.integers(0, [W * 256, H * 256], (2, 2)) / 256
        w = 2.0 ** rng.integers(0, 3, 2)
        gl = gl_line_attribute(p[0], p[1], W, H, w=w, f=(0.0, 1.0))
        ours = tr.rasterize_line(p[0], p[1], W, H, attrs={"f": [0.0, 1.0]}, w=w).attrs["f"]
        rows, cols = np.nonzero(~np.isnan(gl) & ~np.isnan(ours))
        d = p[1] - p[0]
        axis = 0 if abs(d[0]) >= abs(d[1]) else 1
        centre = (cols, rows)[axis] + 0.5
        t_major = (centre - p[0, axis]) / d[axis]
        inner = (t_major > 0) & (t_major < 1) & (line_parameter(p[0], p[1], rows, cols) > 0)
        inner &= line_parameter(p[0], p[1], rows, cols) < 1
        q = np.stack([(1 - t_major) / w[0], t_major / w[1]], axis=1)
        major_value = q[:, 1] / q.sum(axis=1)
        np.testing.assert_allclose(gl[rows, cols][inner], major_value[inner], atol=2e-6)
        projection_differs += bool((np.abs(ours[rows, cols] - gl[rows, cols])[inner] > 1e-4).any())
    assert projection_differs > 10
