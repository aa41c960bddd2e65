"""A real GPU's own counters for the frame-debugging overlays: stencil counts and occlusion
queries from OpenGL (Mesa's llvmpipe through moderngl, headless EGL).

A GPU counts overdraw with its stencil buffer: every fragment that reaches the stencil
stage increments the pixel's (sample's) stencil value. :func:`gl_counters` draws the same
clip-space triangles as :func:`teachraster.pipeline.render_triangles.render` twice:

1. **overdraw**: depth test off, stencil test always passing, ``glStencilOp(KEEP, INCR,
   INCR)``: the stencil counts every covered sample (``frame.overlay("overdraw")``);
2. **depth complexity**: depth test on (``GL_LESS``, float32 depth, as
   :mod:`teachraster.study.opengl` sets it up), ``glStencilOp(KEEP, KEEP, INCR)``: the
   stencil counts the samples that passed the depth test when they arrived, the triangles
   drawn one by one in submission order (``frame.overlay("depth_complexity")``); each draw
   is wrapped in an occlusion query (``GL_SAMPLES_PASSED``), the samples each triangle got
   through the depth test.

The stencil is read back sample by sample without stencil texturing: eight full-screen
passes, one per stencil bit (``glStencilFunc(GL_EQUAL, 2**b, 2**b)``), each adding 2**b
into a float colour target by additive blending, then ``texelFetch`` of every sample.
Conventions as in :mod:`teachraster.study.opengl`: clip y negated (GL's rows and top-left
rule are ours, unflipped), ``glFrontFace(GL_CW)``, depth range [0, 1/2].

The context is the one :func:`teachraster.study.opengl.gl_available` creates (moderngl's
current context); the few GL calls moderngl lacks (stencil state, a float32 depth with an
8-bit stencil) are looked up through ``eglGetProcAddress``.
"""

from __future__ import annotations

import ctypes
import ctypes.util
from dataclasses import dataclass

import numpy as np

from ..core.validate import as_size
from .opengl import (
    FULL_SCREEN_CORNERS,
    FULL_SCREEN_VS,
    SAMPLE_FETCH_FS,
    RawGL,
    egl_function,
    gl_available,
)

__all__ = ["GLCounters", "gl_counters"]

_GL = {
    "RENDERBUFFER": 0x8D41,
    "FRAMEBUFFER": 0x8D40,
    "DEPTH_STENCIL_ATTACHMENT": 0x821A,
    "DEPTH32F_STENCIL8": 0x8CAD,
    "FRAMEBUFFER_COMPLETE": 0x8CD5,
    "STENCIL_TEST": 0x0B90,
    "ALWAYS": 0x0207,
    "EQUAL": 0x0202,
    "KEEP": 0x1E00,
    "INCR": 0x1E02,
    "STENCIL_BUFFER_BIT": 0x0400,
    "DEPTH_BUFFER_BIT": 0x0100,
}
_STATE: dict = {}


@dataclass(frozen=True)
class GLCounters:
    """What OpenGL counted for a scene.

    Attributes
    ----------
    overdraw : (H, W) int64
        Stencil incremented on every fragment, depth test off: covered samples per pixel,
        summed over the pixel's samples.
    depth_complexity : (H, W) int64
        Stencil incremented on depth pass, triangles drawn in submission order.
    samples_passed : (N,) int64
        ``GL_SAMPLES_PASSED`` of each triangle's draw (depth test on).
    """

    overdraw: np.ndarray
    depth_complexity: np.ndarray
    samples_passed: np.ndarray


class _StencilGL(RawGL):
    """The raw GL entry points for stencil state, beside :class:`RawGL`'s renderbuffers."""

    def __init__(self) -> None:
        super().__init__()
        u, i, d = ctypes.c_uint, ctypes.c_int, ctypes.c_double
        self.enable = egl_function("glEnable", None, u)
        self.disable = egl_function("glDisable", None, u)
        self.stencil_func = egl_function("glStencilFunc", None, u, i, u)
        self.stencil_op = egl_function("glStencilOp", None, u, u, u)
        self.stencil_mask = egl_function("glStencilMask", None, u)
        self.clear_stencil = egl_function("glClearStencil", None, i)
        self.clear_depth = egl_function("glClearDepth", None, d)
        self.clear = egl_function("glClear", None, u)

    def depth_stencil(self, width: int, height: int, samples: int) -> int:
        """Attach a float32 depth + 8-bit stencil renderbuffer to the bound framebuffer."""
        return self.renderbuffer(_GL["DEPTH32F_STENCIL8"], _GL["DEPTH_STENCIL_ATTACHMENT"],
                                 width, height, samples)  # fmt: skip


_DRAW_VS = """#version 330
in vec4 in_pos;
void main() { gl_Position = vec4(in_pos.x, -in_pos.y, in_pos.z, in_pos.w); }
"""
_DRAW_FS = """#version 330
out vec4 o;
void main() { o = vec4(0.0); }
"""
_BIT_FS = """#version 330
uniform float weight;
out vec4 o;
void main() { o = vec4(weight, 0.0, 0.0, 1.0); }
"""


def _setup():
    """The shared context, the stencil entry points and the three programs (cached)."""
    ok, why = gl_available()
    if not ok:
        raise RuntimeError(f"OpenGL is not available: {why}")
    import moderngl

    ctx = moderngl.get_context()
    if _STATE.get("ctx") is not ctx:
        _STATE.clear()
        _STATE["ctx"], _STATE["gl"] = ctx, _StencilGL()
        _STATE["draw"] = ctx.program(vertex_shader=_DRAW_VS, fragment_shader=_DRAW_FS)
        _STATE["bit"] = ctx.program(vertex_shader=FULL_SCREEN_VS, fragment_shader=_BIT_FS)
        _STATE["fetch"] = ctx.program(vertex_shader=FULL_SCREEN_VS, fragment_shader=SAMPLE_FETCH_FS)
    return _STATE["ctx"], _STATE["gl"]


def gl_counters(clip, width: int, height: int, *, samples: int = 1, depth_test: bool = True,
                cull: str | None = None, depth_write=True) -> GLCounters:  # fmt: skip
    """Draw clip-space triangles (N, 3, 4) with OpenGL and read its stencil counts and
    occlusion queries (see the module docstring). ``samples``: 1 or an MSAA count;
    ``depth_write``: ``glDepthMask`` per triangle (a bool or (N,) bools) in the
    depth-complexity pass."""
    width, height = as_size("width", width), as_size("height", height)
    clip = np.asarray(clip, dtype=np.float64)
    if clip.ndim != 3 or clip.shape[1:] != (3, 4) or not np.isfinite(clip).all():
        raise ValueError(f"clip must be a finite (N, 3, 4) array, got shape {clip.shape}")
    if cull not in (None, "back", "front"):
        raise ValueError(f"cull must be None, 'back' or 'front'; got {cull!r}")
    ctx, gl = _setup()
    res, rb = [], None
    try:
        tex = ctx.texture((width, height), 4, dtype="f4", samples=0 if samples == 1 else samples)
        res.append(tex)
        fbo = ctx.framebuffer([tex])
        res.append(fbo)
        fbo.depth_mask = True  # moderngl masks depth writes of a colour-only framebuffer
        fbo.use()
        rb = gl.depth_stencil(width, height, 0 if samples == 1 else samples)
        pos = ctx.buffer(clip.astype("f4").tobytes())
        res.append(pos)
        vao = ctx.vertex_array(_STATE["draw"], [(pos, "4f", "in_pos")])
        res.append(vao)
        corners = ctx.buffer(FULL_SCREEN_CORNERS.tobytes())
        res.append(corners)
        quads = [
            ctx.vertex_array(_STATE[p], [(corners, "2f", "in_corner")]) for p in ("bit", "fetch")
        ]
        res += quads
        passes = {}
        writes = np.broadcast_to(np.asarray(depth_write, dtype=bool), (len(clip),))
        for name, test in (("overdraw", False), ("depth_complexity", depth_test)):
            passed = _draw(ctx, gl, vao, len(clip), test, cull,
                           None if name == "overdraw" else writes)  # fmt: skip
            passes[name] = _read_stencil(ctx, gl, fbo, tex, quads, (width, height), samples, res)
            if name == "depth_complexity":
                passes["samples_passed"] = passed
    finally:
        gl.disable(_GL["STENCIL_TEST"])
        if rb is not None:
            gl.delete(rb)
        for obj in reversed(res):
            obj.release()
    return GLCounters(passes["overdraw"], passes["depth_complexity"], passes["samples_passed"])


def _draw(ctx, gl, vao, n, depth_test, cull, writes):
    """Clear and draw the triangles with the stencil counting; the samples each passed.
    ``writes`` (N,) bool: one by one, each with its depth mask and occlusion query (None:
    all in one draw)."""
    import moderngl

    gl.depth_range(0.0, 0.5)
    flags = moderngl.DEPTH_TEST if depth_test else moderngl.NOTHING
    if cull is not None:
        flags |= moderngl.CULL_FACE
        ctx.front_face, ctx.cull_face = "cw", cull
    ctx.enable_only(flags)
    ctx.depth_func = "<"
    gl.stencil_mask(0xFF)
    gl.clear_stencil(0)
    gl.clear_depth(1.0)
    gl.clear(_GL["STENCIL_BUFFER_BIT"] | _GL["DEPTH_BUFFER_BIT"])
    gl.enable(_GL["STENCIL_TEST"])
    gl.stencil_func(_GL["ALWAYS"], 0, 0xFF)
    # depth fail keeps, depth pass (or no depth test at all) increments
    gl.stencil_op(_GL["KEEP"], _GL["KEEP"], _GL["INCR"])
    passed = np.zeros(n, dtype=np.int64)
    if writes is None:
        if n:
            vao.render(moderngl.TRIANGLES, vertices=3 * n)
        return passed
    query = ctx.query(samples=True)  # (moderngl frees queries with the context)
    for t in range(n):  # one draw per triangle, in submission order
        gl.depth_mask(int(writes[t]))
        with query:
            vao.render(moderngl.TRIANGLES, vertices=3, first=3 * t)
        passed[t] = query.samples
    gl.depth_mask(1)
    return passed


def _read_stencil(ctx, gl, fbo, tex, quads, size, samples, res):
    """(H, W) stencil summed over samples: one additive pass per stencil bit into the
    colour target, then every sample read back."""
    import moderngl

    width, height = size
    bit, fetch = quads
    fbo.use()
    fbo.clear(0.0, 0.0, 0.0, 0.0)
    ctx.enable_only(moderngl.BLEND)
    ctx.blend_func = moderngl.ONE, moderngl.ONE
    gl.stencil_op(_GL["KEEP"], _GL["KEEP"], _GL["KEEP"])
    for b in range(8):
        gl.stencil_func(_GL["EQUAL"], 1 << b, 1 << b)
        bit.program["weight"] = float(1 << b)
        bit.render(moderngl.TRIANGLES, vertices=3)
    gl.disable(_GL["STENCIL_TEST"])
    ctx.enable_only(moderngl.NOTHING)
    buf = np.empty((height, width, 4), dtype="f4")
    if samples == 1:
        fbo.read_into(buf, components=4, dtype="f4")  # GL row 0 is ours: no flip
        return buf[..., 0].astype(np.int64)
    target = ctx.renderbuffer(size, 4, dtype="f4")
    res.append(target)
    out = ctx.framebuffer([target])
    res.append(out)
    out.use()
    tex.use(location=0)
    fetch.program["samples"] = 0
    total = np.zeros((height, width), dtype=np.int64)
    for s in range(samples):
        fetch.program["sample_index"] = s
        fetch.render(moderngl.TRIANGLES, vertices=3)
        out.read_into(buf, components=4, dtype="f4")
        total += buf[..., 0].astype(np.int64)
    fbo.use()
    return total
