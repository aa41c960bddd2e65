"""Draw lines with a real GPU rasteriser (OpenGL through Mesa's llvmpipe) to check
:func:`teachraster.rasterize_line` against.

``gl_lines`` takes end points in *window* pixels (y down, as the core), draws them as
``GL_LINES``, ``GL_LINE_STRIP`` or ``GL_LINE_LOOP`` into a float32 target with additive
blending, and returns how many fragments landed on each pixel (so a pixel lit twice by a
polyline shows as 2). The vertex shader emits ``(2x/W - 1, 2y/H - 1)``: that is clip y
negated, as :mod:`teachraster.study.opengl` does, so GL's window y equals ours and its rows
are read back unflipped; for power-of-two sizes and points on the 1/256 grid the float32
viewport transform is exact.

What llvmpipe does (Mesa ``src/gallium/drivers/llvmpipe/lp_setup_line.c``): it does not walk
diamonds. It draws every one-pixel line as a parallelogram one pixel thick along the minor
axis, filled under the triangle top-left rule, and decides the two end pixels with float32
tests of where the end points lie in their pixel ("diamond exit" approximated). That equals
GL's rule except at three kinds of place, which :func:`llvmpipe_deviation` names:

(a) ``"endpoint_on_diamond"``: an end point exactly on a diamond's boundary (the float tests
    use ``<`` where the perturbed rule would need the ε-ordering);
(b) ``"y_major_up_on_centre_row"``: y-major lines running up (y decreasing) whose start lies
    exactly on a pixel-centre row: llvmpipe drops the first pixel;
(c) ``"half_way_centre"``: a pixel centre within 1/512 px of the half-way line of a line
    whose end llvmpipe moved (to the diamond it keeps), decided by the float32 parallelogram.

Attributes along a line (:func:`gl_line_attribute`) are a fourth shortcut: GL's t is the
projection of the pixel centre onto the segment, ``(p - pa)·(pb - pa) / |pb - pa|²``;
llvmpipe sets up its planes along the major axis only, ``t = (x - xa) / (xb - xa)`` for an
x-major line, so its values step evenly per column and ignore the minor offset (the 1/w rule
on top is the same). ``tests/test_lines_gl.py`` checks both statements.
"""

from __future__ import annotations

import numpy as np

from ..core.validate import as_float, as_size, check_choice
from .opengl import gl_context

MODES = ("lines", "line_strip", "line_loop")

#: Compiled programs, per (context, shaders): llvmpipe JIT-compiles each program, so it is
#: compiled once per process, not once per line.
_PROGRAMS: dict = {}


def _program(ctx, vs: str, fs: str):
    key = (id(ctx), vs, fs)
    if key not in _PROGRAMS:
        _PROGRAMS[key] = ctx.program(vertex_shader=vs, fragment_shader=fs)
    return _PROGRAMS[key]


#: Deviation (c): centres this close (px) to the half-way line between two pixels.
HALF_WAY_BAND = 1 / 512

_VS = """#version 330
uniform vec2 size;
in vec2 in_xy;
void main() {
    // window (x, y-down) -> clip with y negated: GL's window y is then our y (module doc)
    gl_Position = vec4(in_xy.x * 2.0 / size.x - 1.0, in_xy.y * 2.0 / size.y - 1.0, 0.0, 1.0);
}
"""
_FS = """#version 330
layout(location = 0) out vec4 o_count;
void main() { o_count = vec4(1.0, 0.0, 0.0, 1.0); }
"""


def gl_lines(points, width: int, height: int, *, mode: str = "lines", line_width: float = 1):
    """Fragments per pixel when OpenGL draws ``points`` (N, 2, window px) as lines.

    Parameters
    ----------
    points : (N, 2) array-like
        Window positions (x right, y down, px). ``"lines"`` pairs them (N even).
    width, height : int
        Image size (powers of two keep the float32 viewport transform exact).
    mode : {"lines", "line_strip", "line_loop"}
        ``GL_LINES``, ``GL_LINE_STRIP`` or ``GL_LINE_LOOP``.
    line_width : float
        ``glLineWidth`` (aliased); llvmpipe draws wider lines as rectangles.

    Returns
    -------
    (height, width) int64
        How many fragments GL produced at each pixel (row 0 at the top).
    """
    import moderngl

    width, height = as_size("width", width), as_size("height", height)
    check_choice("mode", mode, MODES)
    line_width = as_float("line_width", line_width)
    pts = np.asarray(points, dtype=np.float64)
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise ValueError(f"points must have shape (N, 2), got {pts.shape}")
    ctx, _ = gl_context()
    prog = _program(ctx, _VS, _FS)
    prog["size"].value = (float(width), float(height))
    buf = ctx.buffer(pts.astype("f4").tobytes())
    vao = ctx.vertex_array(prog, [(buf, "2f", "in_xy")])
    target = ctx.renderbuffer((width, height), 4, dtype="f4")
    fbo = ctx.framebuffer([target])
    try:
        fbo.use()
        ctx.enable_only(moderngl.BLEND)
        ctx.blend_func = moderngl.ONE, moderngl.ONE
        ctx.blend_equation = moderngl.FUNC_ADD
        ctx.line_width = line_width
        fbo.clear(0.0, 0.0, 0.0, 0.0)
        prim = {"lines": moderngl.LINES, "line_strip": moderngl.LINE_STRIP,
                "line_loop": moderngl.LINE_LOOP}[mode]  # fmt: skip
        vao.render(prim, vertices=len(pts))
        out = np.empty((height, width, 4), dtype="f4")
        fbo.read_into(out, components=4, dtype="f4")
    finally:
        ctx.line_width = 1.0
        ctx.blend_func = moderngl.SRC_ALPHA, moderngl.ONE_MINUS_SRC_ALPHA
        ctx.enable_only(moderngl.NOTHING)
        for obj in (vao, buf, fbo, target):
            obj.release()
    return out[..., 0].astype(np.int64)


def gl_version() -> str:
    """``GL_VERSION`` of the context (it names the Mesa release llvmpipe comes from)."""
    ctx, _ = gl_context()
    return str(ctx.info["GL_VERSION"])


def gl_line_width_range() -> tuple[float, float]:
    """``ALIASED_LINE_WIDTH_RANGE`` of the context: the widths ``glLineWidth`` may draw without
    multisampling (GL requires only 1; a driver whose range stops at 1 draws every line 1 px)."""
    ctx, _ = gl_context()
    low, high = ctx.info["GL_ALIASED_LINE_WIDTH_RANGE"]
    return float(low), float(high)


def _on_diamond_boundary(p) -> bool:
    """Whether window point ``p`` lies exactly on the boundary of some pixel's diamond."""
    fx, fy = p[0] - np.floor(p[0]), p[1] - np.floor(p[1])
    # |x - cx| + |y - cy| for the nearest centres: the boundary is where the sum is 1/2
    return any(abs(fx - cx) + abs(fy - cy) == 0.5 for cx in (-0.5, 0.5, 1.5)
               for cy in (-0.5, 0.5, 1.5))  # fmt: skip


def llvmpipe_deviation(p0, p1, row: int, col: int) -> str | None:
    """Which of llvmpipe's three known deviations from GL's rule explains a pixel where it and
    :func:`teachraster.rasterize_line` disagree on the line p0 → p1 (window px, on the 1/256
    grid), or None when none does (then it is a real difference to report).

    Returns ``"endpoint_on_diamond"``, ``"y_major_up_on_centre_row"`` or
    ``"half_way_centre"`` (module docstring), checked in that order.

    >>> llvmpipe_deviation((1.64453125, 27.14453125), (60.44921875, 4.65234375), 27, 1)
    'endpoint_on_diamond'
    """
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    if _on_diamond_boundary(p0) or _on_diamond_boundary(p1):
        return "endpoint_on_diamond"
    d = p1 - p0
    y_major = abs(d[1]) > abs(d[0])
    if y_major and d[1] < 0 and p0[1] % 1 == 0.5 and (row, col) == tuple(np.floor(p0[::-1])):
        return "y_major_up_on_centre_row"
    axis = 1 if y_major else 0  # the major axis: the pixel centre along it
    centre = (col if axis == 0 else row) + 0.5
    minor = p0[1 - axis] + (centre - p0[axis]) * d[1 - axis] / d[axis]
    if abs(minor - np.round(minor)) <= HALF_WAY_BAND:
        return "half_way_centre"
    return None


_VS_ATTR = """#version 330
uniform vec2 size;
in vec4 in_pos;
in float in_f;
smooth out float f;
void main() {
    // in_pos = (x_win, y_win, 0, w): clip coordinates (x_ndc w, y_ndc w, 0, w), y negated
    vec2 ndc = vec2(in_pos.x * 2.0 / size.x - 1.0, in_pos.y * 2.0 / size.y - 1.0);
    gl_Position = vec4(ndc * in_pos.w, 0.0, in_pos.w);
    f = in_f;
}
"""
_FS_ATTR = """#version 330
smooth in float f;
layout(location = 0) out vec4 o_value;
void main() { o_value = vec4(f, 1.0, 0.0, 1.0); }
"""


def gl_line_attribute(p0, p1, width: int, height: int, *, w=(1.0, 1.0), f=(0.0, 1.0)):
    """A ``smooth`` (perspective-correct) attribute along one GL line: (height, width) float64,
    NaN where GL produced no fragment. ``w`` is each end's clip w (the window positions stay
    ``p0``, ``p1``), ``f`` the attribute at each end."""
    import moderngl

    width, height = as_size("width", width), as_size("height", height)
    ctx, _ = gl_context()
    prog = _program(ctx, _VS_ATTR, _FS_ATTR)
    prog["size"].value = (float(width), float(height))
    verts = np.array([[*p0, 0.0, w[0], f[0]], [*p1, 0.0, w[1], f[1]]], dtype="f4")
    buf = ctx.buffer(verts.tobytes())
    vao = ctx.vertex_array(prog, [(buf, "4f 1f", "in_pos", "in_f")])
    target = ctx.renderbuffer((width, height), 4, dtype="f4")
    fbo = ctx.framebuffer([target])
    try:
        fbo.use()
        ctx.enable_only(moderngl.NOTHING)
        fbo.clear(0.0, 0.0, 0.0, 0.0)
        vao.render(moderngl.LINES, vertices=2)
        out = np.empty((height, width, 4), dtype="f4")
        fbo.read_into(out, components=4, dtype="f4")
    finally:
        for obj in (vao, buf, fbo, target):
            obj.release()
    return np.where(out[..., 1] > 0, out[..., 0].astype(np.float64), np.nan)
