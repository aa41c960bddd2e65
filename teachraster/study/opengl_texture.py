"""OpenGL's λ for textured triangles, with nothing but numpy and moderngl: also a script.

This is the drawing half of :func:`teachraster.study.opengl.gl_texture_lod` (which validates
the inputs and shapes the result). It imports nothing from teachraster, so it can also run as
a script in a fresh Python process: :func:`teachraster.study.opengl.gl_texture_lod_subprocess`
does that for lesson 09, so that the GPU driver's memory is given back when the cell ends and
the child process starts in a tenth of a second instead of importing the whole package.

Run as a script, it reads ``sys.argv[1]`` (an ``.npz`` file: ``clip``, ``uv``, ``width``,
``height``, ``filter`` and ``level_0``, ``level_1``, …), creates a headless context and writes
``sys.argv[2]`` (an ``.npz`` file: ``ok``, ``why`` and, when ``ok``, the two render targets
``lod_target`` and ``color_target``). Both files hold plain arrays (no pickles).

Conventions as in :mod:`teachraster.study.opengl`: the vertex shader negates clip y, so GL's
window rows and 2×2 quads are teachraster's, and its (s, t) are our (u, v).
"""

from __future__ import annotations

import sys

import numpy as np

#: Minifying filters GL can be asked for, by teachraster's names.
GL_MIN_FILTERS = {
    "nearest_mipmap_nearest": "NEAREST_MIPMAP_NEAREST",
    "linear_mipmap_nearest": "LINEAR_MIPMAP_NEAREST",
    "nearest_mipmap_linear": "NEAREST_MIPMAP_LINEAR",
    "trilinear": "LINEAR_MIPMAP_LINEAR",
}

_LOD_VS = """#version 400
in vec4 in_pos;
in vec2 in_uv;
smooth out vec2 uv;
void main() {
    gl_Position = vec4(in_pos.x, -in_pos.y, in_pos.z, in_pos.w);  // y negated, as above
    uv = in_uv;
}
"""

_LOD_FS = """#version 400
uniform sampler2D tex;
smooth in vec2 uv;
layout(location = 0) out vec4 o_lod;
layout(location = 1) out vec4 o_color;
void main() {
    vec2 q = textureQueryLod(tex, uv);  // x: the level(s) accessed, y: the computed lambda
    o_lod = vec4(float(gl_PrimitiveID), q.x, q.y, 1.0);
    o_color = texture(tex, uv);
}
"""


def create_context():
    """A headless OpenGL 3.3 context through EGL, or why there is none.

    Returns
    -------
    (context, "") or (None, reason)
        ``context`` is a ``moderngl.Context``; ``reason`` says what to install.
    """
    try:
        import moderngl
    except ImportError as exc:
        return None, f"moderngl is not installed ({exc}); pip install moderngl"
    try:
        return moderngl.create_standalone_context(backend="egl", require=330), ""
    except Exception as exc:  # glcontext raises plain Exceptions for missing EGL/drivers
        return None, (
            f"no OpenGL 3.3 context through headless EGL: {exc} (on Debian: apt-get install "
            "libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri libgbm1)"
        )


def draw_texture_lod(ctx, programs: dict, clip, uv, width, height, levels, filter):
    """Draw textured triangles and read back GL's λ and sampled colour (checked inputs).

    Parameters
    ----------
    ctx : moderngl.Context
    programs : dict
        A cache of compiled programs (the shader is compiled once per context).
    clip : (N, 3, 4) float array
        Clip-space vertices.
    uv : (N, 3, 2) float array
        Texture coordinates per vertex.
    width, height : int
        Image size.
    levels : list of (h, w, C) float arrays, C <= 4
        The full pyramid, level 0 first.
    filter : str
        A key of :data:`GL_MIN_FILTERS`.

    Returns
    -------
    lod_target, color_target : (height, width, 4) float32 arrays
        ``(gl_PrimitiveID, textureQueryLod.x, textureQueryLod.y, 1)`` (-1 where nothing was
        drawn) and ``texture(tex, uv)``; row 0 at the top.
    """
    import moderngl

    if "lod" not in programs:
        programs["lod"] = ctx.program(vertex_shader=_LOD_VS, fragment_shader=_LOD_FS)
    prog = programs["lod"]
    res = []
    try:
        h0, w0, comps = levels[0].shape
        tex = ctx.texture((w0, h0), comps, levels[0].astype("f4").tobytes(), dtype="f4")
        res.append(tex)
        tex.build_mipmaps()  # allocates every level; overwritten with ours below
        for i, lv in enumerate(levels[1:], start=1):
            tex.write(np.ascontiguousarray(lv, dtype="f4").tobytes(), level=i)
        tex.filter = (getattr(moderngl, GL_MIN_FILTERS[filter]), moderngl.NEAREST)
        tex.repeat_x = tex.repeat_y = True
        pos = ctx.buffer(np.asarray(clip, dtype="f4").tobytes())
        tc = ctx.buffer(np.asarray(uv, dtype="f4").tobytes())
        res += [pos, tc]
        vao = ctx.vertex_array(prog, [(pos, "4f", "in_pos"), (tc, "2f", "in_uv")])
        res.append(vao)
        targets = [ctx.renderbuffer((width, height), 4, dtype="f4") for _ in range(2)]
        res += targets
        fbo = ctx.framebuffer(targets)
        res.append(fbo)
        fbo.use()
        ctx.enable_only(moderngl.NOTHING)
        fbo.clear(-1.0, -1.0, -1.0, -1.0)
        tex.use(0)
        prog["tex"].value = 0
        vao.render(moderngl.TRIANGLES, vertices=3 * len(clip))
        out = []
        for attachment in range(2):
            buf = np.empty((height, width, 4), dtype="f4")
            fbo.read_into(buf, components=4, attachment=attachment, dtype="f4")  # no flip
            out.append(buf)
    finally:
        for obj in reversed(res):
            obj.release()
    return out[0], out[1]


def main(argv: list[str]) -> int:
    """The script: inputs from ``argv[1]``, results to ``argv[2]`` (see the module docstring)."""
    with np.load(argv[1], allow_pickle=False) as data:
        clip, uv = data["clip"], data["uv"]
        width, height, filter = int(data["width"]), int(data["height"]), str(data["filter"])
        levels = [data[f"level_{i}"] for i in range(sum(k.startswith("level_") for k in data))]
    ctx, why = create_context()
    if ctx is None:
        np.savez(argv[2], ok=False, why=why)
        return 0
    try:
        lod, color = draw_texture_lod(ctx, {}, clip, uv, width, height, levels, filter)
        np.savez(argv[2], ok=True, why=str(ctx.info["GL_RENDERER"]), lod_target=lod,
                 color_target=color)  # fmt: skip
    finally:
        ctx.release()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
