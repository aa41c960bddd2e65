"""Blend clip-space triangles with a real GPU (OpenGL through Mesa's llvmpipe) to check
``render(..., blend=...)`` against.

:func:`gl_blend` draws the triangles one by one in submission order with the same blend state
(``glBlendFunc`` pair, ``glDepthMask`` per triangle, ``GL_LESS`` on a float32 depth buffer,
clear colour) into an ``RGBA32F`` colour buffer, into an ``SRGB8_ALPHA8`` one with
``GL_FRAMEBUFFER_SRGB`` on (then GL converts the stored colour to linear before blending and
back after, rounding to 8 bits at every step), or into an ``RGBA8`` (UNORM) one, which
clamps (lesson 12b measures it), optionally with 4-sample MSAA resolved by a blit; with any
``glBlendEquation`` operator. As in :mod:`teachraster.study.opengl`, clip y is negated in the
vertex shader so GL's rows are ours, read back unflipped.
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import BLEND_MODES
from .opengl import gl_context

_PROGRAMS: dict = {}
_GL_SRGB8_ALPHA8 = 0x8C43
_GL_FRAMEBUFFER_SRGB = 0x8DB9

_VS = """#version 330
in vec4 in_pos;
in vec4 in_col;
smooth out vec4 colour;
void main() {
    gl_Position = vec4(in_pos.x, -in_pos.y, in_pos.z, in_pos.w);
    colour = in_col;
}
"""
_FS = """#version 330
smooth in vec4 colour;
layout(location = 0) out vec4 o_colour;
void main() { o_colour = colour; }
"""


def gl_blend(clip, width, height, attrs, *, blend="over", depth_write=True, depth_test=True,
             clear_color=(0.0, 0.0, 0.0, 0.0), srgb=False, unorm8=False, samples=0,
             equation="FUNC_ADD") -> np.ndarray:  # fmt: skip
    """The colour buffer after GL blends ``attrs`` (N, 3, 4) RGBA of triangles ``clip``.

    Parameters
    ----------
    clip : (N, 3, 4) clip-space vertices; attrs : (N, 3, 4) RGBA per vertex.
    blend : a mode of ``render`` ("over", "premultiplied", "additive", "multiply"), a
        ``glBlendFunc`` pair, or None: ``GL_BLEND`` disabled (the fragment colour replaces).
    depth_write : bool or (N,) bools, ``glDepthMask`` per triangle.
    srgb : bool, an ``SRGB8_ALPHA8`` target with ``GL_FRAMEBUFFER_SRGB`` (else ``RGBA32F``).
    unorm8 : bool, an ``RGBA8`` target (8-bit unsigned normalized, no sRGB) instead.
    samples : int, 0 or 4: multisampled, resolved by ``glBlitFramebuffer``.
    equation : ``glBlendEquation``'s operator, "FUNC_ADD" (the default), "FUNC_SUBTRACT",
        "FUNC_REVERSE_SUBTRACT", "MIN" or "MAX".

    Returns
    -------
    (height, width, 4) float64 (RGBA32F) or uint8 (the codes stored: sRGB-encoded, or
    RGBA8's), row 0 on top.
    """
    import moderngl

    clip = np.asarray(clip, dtype=np.float64)
    attrs = np.asarray(attrs, dtype=np.float64)
    n = len(clip)
    writes = np.broadcast_to(np.asarray(depth_write, dtype=bool), (n,))
    ctx, gl = gl_context()
    if id(ctx) not in _PROGRAMS:  # llvmpipe JIT-compiles a program: once per process
        _PROGRAMS[id(ctx)] = ctx.program(vertex_shader=_VS, fragment_shader=_FS)
    prog = _PROGRAMS[id(ctx)]
    pos = ctx.buffer(clip.astype("f4").tobytes())
    col = ctx.buffer(attrs.astype("f4").tobytes())
    vao = ctx.vertex_array(prog, [(pos, "4f", "in_pos"), (col, "4f", "in_col")])
    if srgb and unorm8:
        raise ValueError("srgb and unorm8: one colour target, pick one")
    eight = srgb or unorm8  # the codes of an 8-bit target, read back as they are stored
    fmt = {"internal_format": _GL_SRGB8_ALPHA8} if srgb else {}
    fmt["dtype"] = "f1" if eight else "f4"
    target = ctx.texture((width, height), 4, samples=samples, **fmt)
    fbo = ctx.framebuffer([target])
    objects, depth_rb = [vao, pos, col, fbo, target], None
    try:
        fbo.use()
        depth_rb = gl.float_depth_buffer(width, height, samples) if depth_test else None
        flags = (moderngl.BLEND if blend is not None else 0) | (
            moderngl.DEPTH_TEST if depth_test else 0
        )
        ctx.enable_only(flags)
        if srgb:
            ctx.enable_direct(_GL_FRAMEBUFFER_SRGB)
        ctx.depth_func = "<"
        if blend is not None:
            src, dst = blend if isinstance(blend, tuple) else BLEND_MODES[blend]
            ctx.blend_func = getattr(moderngl, src), getattr(moderngl, dst)
            ctx.blend_equation = getattr(moderngl, equation)
        fbo.depth_mask = True
        fbo.clear(*clear_color, depth=1.0)
        for i in range(n):  # submission order, each with its own depth mask
            fbo.depth_mask = bool(writes[i])
            vao.render(moderngl.TRIANGLES, vertices=3, first=3 * i)
        fbo.depth_mask = True
        return _read(ctx, fbo, (width, height), srgb, eight, samples, objects)
    finally:
        if srgb:
            ctx.disable_direct(_GL_FRAMEBUFFER_SRGB)
        ctx.enable_only(moderngl.NOTHING)
        if depth_rb is not None:
            gl.delete(depth_rb)
        for obj in reversed(objects):
            obj.release()


def _read(ctx, fbo, size, srgb, eight, samples, objects) -> np.ndarray:
    """Read the colour target back (resolving MSAA by a blit into a one-sample copy)."""
    dtype, kind = ("f1", np.uint8) if eight else ("f4", np.float32)
    if samples:
        fmt = {"internal_format": _GL_SRGB8_ALPHA8} if srgb else {}
        single = ctx.texture(size, 4, dtype=dtype, **fmt)
        out_fbo = ctx.framebuffer([single])
        objects += [out_fbo, single]
        ctx.copy_framebuffer(out_fbo, fbo)
        fbo = out_fbo
    out = np.empty((size[1], size[0], 4), dtype=kind)
    fbo.read_into(out, components=4, dtype=dtype)
    return out if eight else out.astype(np.float64)
