"""Render clip-space triangles with a real GPU rasteriser (OpenGL) to check teachraster against.

This optional module draws the same clip-space triangles as :func:`teachraster.pipeline.render_triangles.render` with
OpenGL, through `moderngl <https://moderngl.readthedocs.io>`_ and a headless EGL context (on
machines without a GPU that is Mesa's llvmpipe, a software rasteriser that, like Direct3D and
teachraster, snaps vertices to 1/256 px). It reads back float32 render targets: the triangle id
(``gl_PrimitiveID``), every attribute interpolated both as a GLSL ``smooth`` (perspective-correct)
and a ``noperspective`` (affine) varying, and the window depth ``gl_FragCoord.z``.
:func:`gl_texture_lod` draws textured triangles and reads back GLSL
``textureQueryLod(...)`` (GL's λ from its own 2×2 quads) and the colour a mipmapped filter
returns, to check quads, derivatives and the choice of mip level (lesson 09).

The core package never imports this module, and importing it does not need moderngl: it is
imported inside the functions, so :func:`gl_available` can report why OpenGL is missing.

How the conventions are met
---------------------------
- **Rows and the fill rule.** GL's window has y up, row 0 at the bottom, and a top-left fill
  rule in those coordinates. Flipping the read-back image to put row 0 at the top would turn
  it into a *bottom*-left rule. Instead the vertex shader negates clip y and the rows are read
  back unflipped: GL's window y is then exactly teachraster's y-down ``y_win``, GL row r is our
  row r, and GL's top-left rule is ours.
- **Winding.** After negating y, GL's signed area in its window coordinates equals
  teachraster's ``E(v0, v1, v2)``, which is negative for our front faces (counter-clockwise on
  screen). GL calls a positive area counter-clockwise, so ``glFrontFace(GL_CW)`` makes GL's
  front faces ours, and ``cull="back"`` drops exactly what the conventions call back-facing.
- **Depth.** A 32-bit float depth buffer (``GL_DEPTH_COMPONENT32F``), ``GL_LESS`` (strictly
  nearer wins, ties keep the earlier triangle) and primitive order without the test. The
  depth range is set to [0, 1/2] and ``2 * gl_FragCoord.z`` is reported: halving is exact in
  floating point, so nothing changes except that a fragment on the far plane (depth 1) still
  passes against the cleared value 1.0, as it does in teachraster where an empty pixel has no
  depth at all.

- **Multisampling.** :func:`gl_render_samples` draws into a 4-sample float texture and reads
  every sample back with ``texelFetch`` on a ``sampler2DMS``; ``gl_SampleMaskIn`` gives GL's
  own coverage mask per fragment. llvmpipe's positions (``glGetMultisamplefv``) are the
  Direct3D standard pattern, and with y negated they are our y-down offsets unchanged.

Examples
--------
Where OpenGL is available, GL covers exactly the pixels the core rasteriser does:

>>> import numpy as np
>>> import teachraster as tr
>>> clip = np.array([[[-1, 1, 0, 1], [1, 1, 0, 1], [-1, -1, 0, 1]]], dtype=float)
>>> ours = tr.rasterize(tr.Triangle([[0, 0], [4, 0], [0, 4]]), 4, 4).coverage
>>> ours.astype(int)          # the hypotenuse is a right edge: its centres are not covered
array([[1, 1, 1, 0],
       [1, 1, 0, 0],
       [1, 0, 0, 0],
       [0, 0, 0, 0]])
>>> ok, why = gl_available()
>>> not ok or bool((gl_render(clip, 4, 4).coverage == ours).all())
True
"""

from __future__ import annotations

import ctypes
import ctypes.util
from dataclasses import dataclass

import numpy as np

from ..core.validate import as_size
from .opengl_texture import GL_MIN_FILTERS, create_context, draw_texture_lod

__all__ = [
    "GLFrame",
    "GLRenderer",
    "GLSampleFrame",
    "GLTextureFrame",
    "gl_available",
    "gl_render",
    "gl_render_samples",
    "gl_sample_positions",
    "gl_texture_lod",
    "gl_texture_lod_subprocess",
]

#: Attribute components carried by one varying (a vec4).
_CHUNK = 4
#: vec4 attribute chunks per draw pass: 1 target (id, depth) + 2 per chunk <= 8 colour targets.
_CHUNKS_PER_PASS = 3
#: Triangle ids travel as float32, exact up to 2**24.
_MAX_TRIANGLES = 2**24

# OpenGL enums used through ctypes (moderngl has no 32-bit float depth buffer).
_GL_RENDERBUFFER = 0x8D41
_GL_FRAMEBUFFER = 0x8D40
_GL_DEPTH_ATTACHMENT = 0x8D00
_GL_DEPTH_COMPONENT32F = 0x8CAC
_GL_FRAMEBUFFER_COMPLETE = 0x8CD5
_GL_SAMPLE_POSITION = 0x8E50

# Cached per process: creating an EGL context costs tens of milliseconds.
_STATE: dict = {"status": None, "ctx": None, "gl": None, "programs": {}}


@dataclass(frozen=True)
class GLFrame:
    """What OpenGL drew, read back from float32 render targets (row 0 at the top).

    Attributes
    ----------
    triangle_id : (height, width) int64
        Index of the triangle that wrote the pixel (``gl_PrimitiveID``), -1 where none did.
    smooth : (height, width, k) float64
        Attributes interpolated as GLSL ``smooth`` varyings (perspective-correct), NaN where
        uncovered. ``k`` is 0 when no attributes were given.
    noperspective : (height, width, k) float64
        The same attributes as ``noperspective`` varyings (affine in screen space).
    depth : (height, width) float64
        Window depth ``gl_FragCoord.z`` in [0, 1] of the fragment that wrote the pixel,
        NaN where uncovered.
    coverage : (height, width) bool
        ``triangle_id >= 0``.
    depth_buffer : (height, width) float64 or None
        The depth buffer itself (``glReadPixels`` of ``GL_DEPTH_COMPONENT``), NaN where
        nothing was written: with ``depth_write`` off for some triangles it differs from
        ``depth``. None when the depth test was off.
    """

    triangle_id: np.ndarray
    smooth: np.ndarray
    noperspective: np.ndarray
    depth: np.ndarray
    coverage: np.ndarray
    depth_buffer: np.ndarray | None = None


def gl_available() -> tuple[bool, str]:
    """Whether an OpenGL 3.3 context can be created here, and the renderer or the reason not.

    Tries to import moderngl and create a standalone (headless) EGL context. The answer and
    the context are cached for the life of the process.

    Returns
    -------
    (True, renderer) or (False, reason)
        ``renderer`` is ``GL_RENDERER``, e.g. ``"llvmpipe (LLVM 15.0.6, 256 bits)"``.

    Examples
    --------
    >>> ok, text = gl_available()
    >>> isinstance(ok, bool) and isinstance(text, str)
    True
    """
    if _STATE["status"] is None:
        _STATE["status"] = _create_context()
    return _STATE["status"]


def _create_context() -> tuple[bool, str]:
    ctx, why = create_context()
    if ctx is None:
        return False, why
    try:
        gl = RawGL()
    except OSError as exc:
        ctx.release()
        return False, f"OpenGL context created but raw GL entry points not found: {exc}"
    _STATE["ctx"], _STATE["gl"] = ctx, gl
    return True, str(ctx.info["GL_RENDERER"])


def gl_context():
    """The cached headless context and the raw GL calls, for the other cross-check modules
    (:mod:`.opengl_lines`, :mod:`.opengl_blend`); RuntimeError when there is no OpenGL."""
    return _context()


def _context():
    ok, why = gl_available()
    if not ok:
        raise RuntimeError(f"OpenGL is not available: {why}")
    return _STATE["ctx"], _STATE["gl"]


def egl_function(symbol: str, restype, *argtypes):
    """A GL entry point that moderngl does not offer, looked up through ``eglGetProcAddress``
    (the one lookup every llvmpipe cross-check uses)."""
    if "egl" not in _STATE:
        egl = ctypes.CDLL(ctypes.util.find_library("EGL") or "libEGL.so.1")
        egl.eglGetProcAddress.restype = ctypes.c_void_p
        egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
        _STATE["egl"] = egl
    ptr = _STATE["egl"].eglGetProcAddress(symbol.encode())
    if not ptr:
        raise OSError(f"eglGetProcAddress({symbol!r}) returned NULL")
    return ctypes.CFUNCTYPE(restype, *argtypes)(ptr)


class RawGL:
    """The few GL calls moderngl does not offer (through :func:`egl_function`).

    moderngl's depth buffers are 24-bit fixed point; the depth test must run on float32 like
    the depth we compare against, so we attach a ``GL_DEPTH_COMPONENT32F`` renderbuffer
    ourselves, and set the depth range (see the module docstring).
    """

    def __init__(self) -> None:
        u, i, d = ctypes.c_uint, ctypes.c_int, ctypes.c_double
        self.gen_renderbuffers = egl_function("glGenRenderbuffers", None, i, ctypes.POINTER(u))
        self.delete_renderbuffers = egl_function(
            "glDeleteRenderbuffers", None, i, ctypes.POINTER(u)
        )
        self.bind_renderbuffer = egl_function("glBindRenderbuffer", None, u, u)
        self.renderbuffer_storage_multisample = egl_function(
            "glRenderbufferStorageMultisample", None, u, i, u, i, i
        )
        self.framebuffer_renderbuffer = egl_function("glFramebufferRenderbuffer", None, u, u, u, u)
        self.check_framebuffer_status = egl_function("glCheckFramebufferStatus", u, u)
        self.depth_range = egl_function("glDepthRange", None, d, d)
        self.get_multisample = egl_function(
            "glGetMultisamplefv", None, u, u, ctypes.POINTER(ctypes.c_float)
        )
        self.depth_mask = egl_function("glDepthMask", None, ctypes.c_ubyte)
        self.read_pixels = egl_function("glReadPixels", None, i, i, i, i, u, u, ctypes.c_void_p)

    def renderbuffer(self, internal_format: int, attachment: int, width: int, height: int,
                     samples: int = 0) -> int:  # fmt: skip
        """Attach a new renderbuffer (``samples`` per pixel; 0 = single-sampled, which
        ``glRenderbufferStorageMultisample`` takes as ``glRenderbufferStorage``) to the bound
        framebuffer; return its name."""
        name = ctypes.c_uint(0)
        self.gen_renderbuffers(1, ctypes.byref(name))
        self.bind_renderbuffer(_GL_RENDERBUFFER, name)
        self.renderbuffer_storage_multisample(
            _GL_RENDERBUFFER, samples, internal_format, width, height
        )
        self.bind_renderbuffer(_GL_RENDERBUFFER, 0)
        self.framebuffer_renderbuffer(_GL_FRAMEBUFFER, attachment, _GL_RENDERBUFFER, name.value)
        status = self.check_framebuffer_status(_GL_FRAMEBUFFER)
        if status != _GL_FRAMEBUFFER_COMPLETE:
            self.delete(name.value)
            raise RuntimeError(
                f"framebuffer with renderbuffer {internal_format:#x} incomplete: {status:#x}"
            )
        return name.value

    def float_depth_buffer(self, width: int, height: int, samples: int = 0) -> int:
        """Attach a new float32 depth renderbuffer to the bound framebuffer; its name."""
        return self.renderbuffer(_GL_DEPTH_COMPONENT32F, _GL_DEPTH_ATTACHMENT, width, height,
                                 samples)  # fmt: skip

    def delete(self, renderbuffer: int) -> None:
        name = ctypes.c_uint(renderbuffer)
        self.delete_renderbuffers(1, ctypes.byref(name))


def _shaders(n_chunks: int) -> tuple[str, str]:
    """GLSL 3.30 sources for a pass carrying ``n_chunks`` vec4 attribute chunks."""
    chunks = range(n_chunks)
    vs = ["#version 330", "in vec4 in_pos;"]
    vs += [f"in vec4 in_a{c};\nsmooth out vec4 s{c};\nnoperspective out vec4 n{c};" for c in chunks]
    vs += [
        "void main() {",
        # y negated: GL's bottom-up window rows become our top-down rows, unflipped, so its
        # top-left rule is ours (module docstring). GL clips this in homogeneous space itself.
        "    gl_Position = vec4(in_pos.x, -in_pos.y, in_pos.z, in_pos.w);",
        *[f"    s{c} = in_a{c};\n    n{c} = in_a{c};" for c in chunks],
        "}",
    ]
    fs = ["#version 330"]
    fs += [f"smooth in vec4 s{c};\nnoperspective in vec4 n{c};" for c in chunks]
    fs += ["layout(location = 0) out vec4 o_id_depth;"]
    fs += [
        f"layout(location = {1 + 2 * c}) out vec4 o_s{c};\n"
        f"layout(location = {2 + 2 * c}) out vec4 o_n{c};"
        for c in chunks
    ]
    fs += [
        "uniform int id_base;",  # the first triangle of the draw (one draw per depth mask)
        "void main() {",
        # The depth range is [0, 1/2] (module docstring); doubling is exact.
        "    o_id_depth = vec4(float(gl_PrimitiveID + id_base), 2.0 * gl_FragCoord.z, 0.0, 1.0);",
        *[f"    o_s{c} = s{c};\n    o_n{c} = n{c};" for c in chunks],
        "}",
    ]
    return "\n".join(vs) + "\n", "\n".join(fs) + "\n"


def _program(ctx, n_chunks: int):
    programs = _STATE["programs"]
    if n_chunks not in programs:
        vs, fs = _shaders(n_chunks)
        programs[n_chunks] = ctx.program(vertex_shader=vs, fragment_shader=fs)
    return programs[n_chunks]


def _check_inputs(clip, width, height, attrs, cull):
    width, height = as_size("width", width), as_size("height", height)
    clip = np.asarray(clip, dtype=np.float64)
    if clip.ndim != 3 or clip.shape[1:] != (3, 4):
        raise ValueError(f"clip must have shape (N, 3, 4), got {clip.shape}")
    if not np.isfinite(clip).all():
        raise ValueError("clip contains NaN or infinity")
    if len(clip) > _MAX_TRIANGLES:
        raise ValueError(f"at most {_MAX_TRIANGLES} triangles (ids are exact float32 values)")
    n = len(clip)
    if attrs is None:
        attrs = np.zeros((n, 3, 0))
    attrs = np.asarray(attrs, dtype=np.float64)
    if attrs.ndim == 2:
        attrs = attrs[..., None]
    if attrs.ndim != 3 or attrs.shape[:2] != (n, 3):
        raise ValueError(
            f"attrs must have shape (N, 3) or (N, 3, k) with N = {n}, got {attrs.shape}"
        )
    if cull not in (None, "back", "front"):
        raise ValueError(f"cull must be None, 'back' or 'front'; got {cull!r}")
    return clip, int(width), int(height), attrs


class GLRenderer:
    """One scene uploaded to OpenGL, ready to be drawn and read back as often as wanted.

    :func:`gl_render` is this in one call. Keeping the renderer lets a benchmark time the
    draw and read-back apart from the upload (buffers, vertex arrays, render targets).

    Parameters
    ----------
    clip, width, height, attrs, depth_test, cull, depth_write
        As in :func:`gl_render`.

    Examples
    --------
    >>> import numpy as np
    >>> clip = np.array([[[-1, 1, 0, 1], [1, 1, 0, 1], [-1, -1, 0, 1]]], dtype=float)
    >>> if gl_available()[0]:
    ...     with GLRenderer(clip, 4, 4) as gl:
    ...         frames = [gl.render() for _ in range(3)]   # upload once, draw three times
    ...     print([int(f.coverage.sum()) for f in frames])
    ... else:
    ...     print([6, 6, 6])
    [6, 6, 6]
    """

    def __init__(self, clip, width, height, *, attrs=None, depth_test=True, cull=None,
                 depth_write=True):  # fmt: skip
        clip, self.width, self.height, attrs = _check_inputs(clip, width, height, attrs, cull)
        self.ctx, self._gl = _context()
        self.depth_test, self.cull, self.k = bool(depth_test), cull, attrs.shape[2]
        self.depth_write = np.broadcast_to(np.asarray(depth_write, dtype=bool), (len(clip),))
        self._resources: list = []
        self._depth_rb: int | None = None
        try:
            self._upload(clip, attrs)
        except BaseException:
            self.release()
            raise

    def _upload(self, clip: np.ndarray, attrs: np.ndarray) -> None:
        ctx = self.ctx
        n = len(clip)
        pos = ctx.buffer(clip.astype("f4").tobytes())
        self._resources.append(pos)
        n_chunks = -(-self.k // _CHUNK)
        padded = np.zeros((n, 3, n_chunks * _CHUNK), dtype="f4")
        padded[..., : self.k] = attrs
        chunk_buffers = []
        for c in range(n_chunks):
            buf = ctx.buffer(np.ascontiguousarray(padded[..., c * 4 : c * 4 + 4]).tobytes())
            self._resources.append(buf)
            chunk_buffers.append(buf)
        # Passes of up to _CHUNKS_PER_PASS chunks; ids and depth come out of every pass alike.
        groups = [
            range(s, min(s + _CHUNKS_PER_PASS, n_chunks))
            for s in range(0, n_chunks, _CHUNKS_PER_PASS)
        ]
        self._passes = []
        for group in groups or [range(0)]:
            prog = _program(ctx, len(group))
            content = [(pos, "4f", "in_pos")]
            content += [(chunk_buffers[c], "4f", f"in_a{j}") for j, c in enumerate(group)]
            vao = ctx.vertex_array(prog, content)
            self._resources.append(vao)
            self._passes.append((vao, list(group)))
        size = (self.width, self.height)
        n_targets = 1 + 2 * max(len(g) for _, g in self._passes)
        targets = [ctx.renderbuffer(size, 4, dtype="f4") for _ in range(n_targets)]
        self._resources.extend(targets)
        self.fbo = ctx.framebuffer(targets)
        self._resources.append(self.fbo)
        self.fbo.use()
        self._depth_rb = self._gl.float_depth_buffer(self.width, self.height)
        self.fbo.depth_mask = True  # moderngl assumes no depth writes without its own buffer
        self._n_vertices = 3 * n

    def draw(self, vao) -> None:
        """Clear the targets and draw every triangle with one pass's vertex array."""
        import moderngl

        ctx = self.ctx
        self.fbo.use()
        self._gl.depth_range(0.0, 0.5)
        flags = moderngl.NOTHING
        if self.depth_test:
            flags |= moderngl.DEPTH_TEST
            ctx.depth_func = "<"  # strictly nearer wins; ties keep the earlier triangle
        if self.cull is not None:
            flags |= moderngl.CULL_FACE
            ctx.front_face = "cw"  # with y negated, GL's clockwise is our counter-clockwise
            ctx.cull_face = self.cull
        ctx.enable_only(flags)
        # -1 marks "no triangle" in the id target; the other targets are masked later.
        self.fbo.clear(-1.0, -1.0, -1.0, -1.0, depth=1.0)
        # one draw per run of triangles with the same depth mask (glDepthMask)
        mask = self.depth_write
        cuts = [0, *np.flatnonzero(mask[1:] != mask[:-1]) + 1, len(mask)]
        for a, b in zip(cuts[:-1], cuts[1:]):
            if b > a:
                self._gl.depth_mask(int(mask[a]))
                vao.program["id_base"] = int(a)
                vao.render(moderngl.TRIANGLES, vertices=3 * (b - a), first=3 * a)
        self._gl.depth_mask(1)

    def _read(self, attachment: int) -> np.ndarray:
        out = np.empty((self.height, self.width, 4), dtype="f4")
        self.fbo.read_into(out, components=4, attachment=attachment, dtype="f4")
        return out  # GL row 0 is our row 0: no flip (module docstring)

    def render_raw(self) -> list[list[np.ndarray]]:
        """Draw every pass and return its float32 targets as read, without any conversion.

        Returns
        -------
        list (one per pass) of lists of (height, width, 4) float32 arrays
            ``[id_depth, smooth_0, noperspective_0, smooth_1, ...]``: channel 0 of ``id_depth``
            is the triangle id (-1 where none), channel 1 the depth; each attribute pair holds
            four components of the pass's attribute chunks. Row 0 is the top.
        """
        out = []
        for vao, group in self._passes:
            self.draw(vao)
            out.append([self._read(i) for i in range(1 + 2 * len(group))])
        return out

    def render(self) -> GLFrame:
        """Draw all passes and read the targets back into a :class:`GLFrame`."""
        h, w = self.height, self.width
        smooth = np.empty((h, w, self.k))
        nopersp = np.empty((h, w, self.k))
        raw = self.render_raw()
        ids = raw[0][0][..., 0].astype(np.int64)  # ids and depth are the same in every pass
        depth = raw[0][0][..., 1].astype(np.float64)
        for (_, group), targets in zip(self._passes, raw):
            for j, c in enumerate(group):
                lo, hi = c * _CHUNK, min(c * _CHUNK + _CHUNK, self.k)
                smooth[..., lo:hi] = targets[1 + 2 * j][..., : hi - lo]
                nopersp[..., lo:hi] = targets[2 + 2 * j][..., : hi - lo]
        stored = self._depth_buffer() if self.depth_test else None
        coverage = ids >= 0  # the id target was cleared to -1
        # copyto with a broadcast mask: several times faster than boolean-index assignment
        uncovered = ~coverage
        np.copyto(depth, np.nan, where=uncovered)
        np.copyto(smooth, np.nan, where=uncovered[..., None])
        np.copyto(nopersp, np.nan, where=uncovered[..., None])
        return GLFrame(
            triangle_id=ids,
            smooth=smooth,
            noperspective=nopersp,
            depth=depth,
            coverage=coverage,
            depth_buffer=stored,
        )

    def _depth_buffer(self) -> np.ndarray:
        """The float32 depth buffer after the last draw, doubled (range [0, 1/2]), NaN where
        it still holds the cleared 1.0 (no written depth reaches 1/2 beyond the far plane)."""
        out = np.empty((self.height, self.width), dtype=np.float32)
        self.fbo.use()
        self._gl.read_pixels(0, 0, self.width, self.height, 0x1902, 0x1406,  # DEPTH, FLOAT
                             out.ctypes.data)  # fmt: skip
        depth = 2.0 * out.astype(np.float64)
        return np.where(out == 1.0, np.nan, depth)

    def release(self) -> None:
        """Free the GL objects of this scene (the cached context and programs stay)."""
        if self._depth_rb is not None:
            self._gl.delete(self._depth_rb)
            self._depth_rb = None
        for obj in reversed(self._resources):
            obj.release()
        self._resources.clear()

    def __enter__(self) -> GLRenderer:
        return self

    def __exit__(self, *exc) -> None:
        self.release()


def gl_render(clip, width: int, height: int, *, attrs=None, depth_test: bool = True,
              cull: str | None = None, depth_write=True) -> GLFrame:  # fmt: skip
    """Draw clip-space triangles with OpenGL and read back ids, attributes and depth.

    The vertices go straight to ``gl_Position`` (with y negated, see the module docstring),
    so GL clips in homogeneous space itself, exactly the input of :func:`teachraster.pipeline.render_triangles.render`.

    Parameters
    ----------
    clip : (N, 3, 4) array-like
        Clip-space vertices (x, y, z, w); sent to GL as float32.
    width, height : int
        Image size in pixels.
    attrs : (N, 3) or (N, 3, k) array-like, optional
        Per-vertex attributes, interpolated both as ``smooth`` and ``noperspective``
        varyings (float32). Any k: four components per varying, several passes when needed.
    depth_test : bool
        Nearer fragment wins (strictly smaller depth; ties keep the earlier triangle), with a
        float32 depth buffer. Without it later triangles overwrite earlier ones.
    cull : {None, "back", "front"}
        Drop triangles that are back-facing (clockwise on screen) or front-facing.
    depth_write : bool or (N,) bools
        ``glDepthMask`` per triangle (the triangles are drawn in runs of equal masks).

    Returns
    -------
    GLFrame

    Raises
    ------
    RuntimeError
        When no OpenGL context can be created (:func:`gl_available` says why).
    ValueError
        On malformed input.
    """
    with GLRenderer(clip, width, height, attrs=attrs, depth_test=depth_test, cull=cull,
                    depth_write=depth_write) as gl:  # fmt: skip
        return gl.render()


# -- multisampling -----------------------------------------------------------------------------
@dataclass(frozen=True)
class GLSampleFrame:
    """What OpenGL drew into a multisampled framebuffer, read back sample by sample.

    Attributes
    ----------
    sample_triangle_id : (height, width, S) int64
        Index of the triangle each sample shows (``gl_PrimitiveID`` of the fragment that
        wrote it), -1 where none did. Row 0 at the top, as everywhere.
    sample_mask : (height, width, S) bool
        Bit s of ``gl_SampleMaskIn[0]`` of the fragment that wrote sample s (False where
        none did): GL's own coverage mask for the fragment.
    positions : (S, 2) float64
        The sample positions GL reports (``glGetMultisamplefv(GL_SAMPLE_POSITION, s)``).
    sample_value : (height, width, S) float64 or None
        With ``attrs``: the value of the scalar varying each sample holds, evaluated once
        per fragment (no sample shading), at the centre or, ``centroid``, where the GL
        implementation puts the centroid; NaN where no fragment wrote the sample.
    """

    sample_triangle_id: np.ndarray
    sample_mask: np.ndarray
    positions: np.ndarray
    sample_value: np.ndarray | None = None


_MS_DRAW_FS = """#version 400
layout(location = 0) out vec4 o_id;
void main() {
    // the depth range is [0, 1/2] (module docstring); the id and this fragment's mask
    o_id = vec4(float(gl_PrimitiveID), float(gl_SampleMaskIn[0]), 0.0, 1.0);
}
"""
_MS_VALUE_VS = """#version 400
in vec4 in_pos;
in float in_a;
{q} out float value;
void main() {{
    gl_Position = vec4(in_pos.x, -in_pos.y, in_pos.z, in_pos.w);
    value = in_a;
}}
"""
_MS_VALUE_FS = """#version 400
{q} in float value;
layout(location = 0) out vec4 o_id;
void main() {{
    o_id = vec4(float(gl_PrimitiveID), float(gl_SampleMaskIn[0]), value, 1.0);
}}
"""
#: One triangle over the whole viewport (corners (-1, -1), (3, -1), (-1, 3) in clip space),
#: for the passes that read a multisampled target back pixel by pixel.
FULL_SCREEN_CORNERS = np.array([-1, -1, 3, -1, -1, 3], dtype="f4")
FULL_SCREEN_VS = """#version 330
in vec2 in_corner;
void main() { gl_Position = vec4(in_corner, 0.0, 1.0); }
"""
#: Sample ``sample_index`` of the multisampled texture ``samples``, at this fragment's pixel.
SAMPLE_FETCH_FS = """#version 330
uniform sampler2DMS samples;
uniform int sample_index;
out vec4 o;
void main() { o = texelFetch(samples, ivec2(gl_FragCoord.xy), sample_index); }
"""


def gl_sample_positions(samples: int = 4) -> np.ndarray:
    """(S, 2) sample positions of a ``samples``-sample float framebuffer, as GL reports them.

    GL gives them from the pixel's lower-left corner with y up; with clip y negated and no
    flip on read-back (module docstring) GL's rows are ours, so these are our y-down offsets.
    """
    ctx, gl = _context()
    tex = ctx.texture((4, 4), 4, dtype="f4", samples=samples)
    fbo = ctx.framebuffer([tex])
    try:
        fbo.use()
        out = np.empty((samples, 2))
        for s in range(samples):
            v = (ctypes.c_float * 2)()
            gl.get_multisample(_GL_SAMPLE_POSITION, s, v)
            out[s] = v[0], v[1]
        return out
    finally:
        fbo.release()
        tex.release()


def gl_render_samples(clip, width: int, height: int, *, samples: int = 4, depth_test: bool = True,
                      cull: str | None = None, attrs=None,
                      centroid: bool = False) -> GLSampleFrame:  # fmt: skip
    """Draw clip-space triangles into an S-sample framebuffer and read every sample back.

    The triangles are drawn as in :func:`gl_render` (clip y negated, float32 depth in
    [0, 1/2], ``GL_LESS``), into a multisampled float texture; a second pass reads sample s
    of every pixel with ``texelFetch`` on a ``sampler2DMS`` into a plain float target.
    ``attrs`` (N, 3): a scalar per vertex, a ``smooth`` varying (``centroid smooth`` with
    ``centroid``) whose value every sample keeps (``sample_value``).
    """
    import moderngl

    clip, width, height, values = _check_inputs(clip, width, height, attrs, cull)
    ctx, gl = _context()
    res, depth_rb = [], None
    try:
        tex = ctx.texture((width, height), 4, dtype="f4", samples=samples)
        res.append(tex)
        fbo = ctx.framebuffer([tex])
        res.append(fbo)
        fbo.use()
        depth_rb = gl.float_depth_buffer(width, height, samples)
        fbo.depth_mask = True
        if "ms_draw" not in _STATE["programs"]:
            vs, _ = _shaders(0)
            _STATE["programs"]["ms_draw"] = ctx.program(
                vertex_shader=vs, fragment_shader=_MS_DRAW_FS
            )
            _STATE["programs"]["ms_resolve"] = ctx.program(
                vertex_shader=FULL_SCREEN_VS, fragment_shader=SAMPLE_FETCH_FS
            )
        draw, read = _STATE["programs"]["ms_draw"], _STATE["programs"]["ms_resolve"]
        pos = ctx.buffer(clip.astype("f4").tobytes())
        res.append(pos)
        content = [(pos, "4f", "in_pos")]
        if attrs is not None:
            draw = _value_program(ctx, centroid)
            value_buffer = ctx.buffer(values[..., 0].astype("f4").tobytes())
            res.append(value_buffer)
            content.append((value_buffer, "1f", "in_a"))
        vao = ctx.vertex_array(draw, content)
        res.append(vao)
        gl.depth_range(0.0, 0.5)
        flags = moderngl.NOTHING
        if depth_test:
            flags |= moderngl.DEPTH_TEST
            ctx.depth_func = "<"
        if cull is not None:
            flags |= moderngl.CULL_FACE
            ctx.front_face, ctx.cull_face = "cw", cull
        ctx.enable_only(flags)
        fbo.clear(-1.0, 0.0, 0.0, 0.0, depth=1.0)
        if len(clip):
            vao.render(moderngl.TRIANGLES, vertices=3 * len(clip))
        positions = gl_sample_positions(samples)
        ids, masks, value = _read_samples(ctx, read, tex, (width, height), samples, res)
    finally:
        if depth_rb is not None:
            gl.delete(depth_rb)
        for obj in reversed(res):
            obj.release()
    bits = masks.astype(np.int64)
    mask = (bits[..., None] >> np.arange(samples)) & 1
    covered = ids >= 0
    return GLSampleFrame(
        sample_triangle_id=ids,
        sample_mask=np.stack([mask[..., s, s] for s in range(samples)], axis=-1).astype(bool)
        & covered,
        positions=positions,
        sample_value=None if attrs is None else np.where(covered, value, np.nan),
    )


def _value_program(ctx, centroid: bool):
    """The multisampled draw carrying one scalar varying (centroid-qualified or not)."""
    key = ("ms_value", bool(centroid))
    if key not in _STATE["programs"]:
        q = "centroid" if centroid else ""
        _STATE["programs"][key] = ctx.program(vertex_shader=_MS_VALUE_VS.format(q=q),
                                              fragment_shader=_MS_VALUE_FS.format(q=q))  # fmt: skip
    return _STATE["programs"][key]


def _read_samples(ctx, program, tex, size, samples, res):
    """(H, W, S) ids, masks and values: one full-screen pass per sample with ``texelFetch``."""
    import moderngl

    width, height = size
    corners = ctx.buffer(FULL_SCREEN_CORNERS.tobytes())
    res.append(corners)
    vao = ctx.vertex_array(program, [(corners, "2f", "in_corner")])
    res.append(vao)
    target = ctx.renderbuffer(size, 4, dtype="f4")
    res.append(target)
    out_fbo = ctx.framebuffer([target])
    res.append(out_fbo)
    out_fbo.use()
    ctx.enable_only(moderngl.NOTHING)
    tex.use(location=0)
    program["samples"] = 0
    ids = np.empty((height, width, samples), dtype=np.int64)
    masks = np.empty((height, width, samples))
    values = np.empty((height, width, samples))
    buf = np.empty((height, width, 4), dtype="f4")
    for s in range(samples):
        program["sample_index"] = s
        vao.render(moderngl.TRIANGLES, vertices=3)
        out_fbo.read_into(buf, components=4, dtype="f4")  # GL row 0 is ours: no flip
        ids[..., s] = buf[..., 0].astype(np.int64)
        masks[..., s] = buf[..., 1]
        values[..., s] = buf[..., 2]
    return ids, masks, values


# -- texture level of detail ------------------------------------------------------------------
@dataclass(frozen=True)
class GLTextureFrame:
    """What OpenGL computed for a textured draw (row 0 at the top).

    Attributes
    ----------
    triangle_id : (height, width) int64
        ``gl_PrimitiveID``, -1 where nothing was drawn.
    lod : (height, width) float64
        ``textureQueryLod(tex, uv).y``: GL's λ relative to the base level, NaN where uncovered.
    level : (height, width) float64
        ``textureQueryLod(tex, uv).x``: the (clamped) level GL would access.
    color : (height, width, 4) float64
        ``texture(tex, uv)`` with the asked minifying filter (RGBA; channels the texture did
        not have are GL's defaults).
    """

    triangle_id: np.ndarray
    lod: np.ndarray
    level: np.ndarray
    color: np.ndarray


def gl_texture_lod(
    clip, uv, width: int, height: int, levels, *, filter: str = "nearest_mipmap_nearest"
) -> GLTextureFrame:
    """Draw textured clip-space triangles with OpenGL and read back λ and the sampled colour.

    The mip levels are uploaded as given (``levels[0]`` first, our row 0 as GL's ``t = 0``
    so GL's (s, t) is teachraster's (u, v)), wrap ``REPEAT``, magnification ``NEAREST``. GL
    computes λ from its own 2×2 quads: with y negated its quads are aligned with ours, so this
    checks :func:`teachraster.render`'s derivatives and :func:`teachraster.mip_level`.

    Parameters
    ----------
    clip : (N, 3, 4) array-like
        Clip-space vertices, as in :func:`gl_render`.
    uv : (N, 3, 2) array-like
        Texture coordinates per vertex (a ``smooth`` varying).
    width, height : int
        Image size.
    levels : list of (h, w) or (h, w, C) arrays, C <= 4
        The full pyramid (e.g. ``tr.mipmap(texture)``), down to 1 × 1.
    filter : str
        One of ``nearest_mipmap_nearest``, ``linear_mipmap_nearest``,
        ``nearest_mipmap_linear``, ``trilinear``.
    """
    clip, uv, width, height, levels = _check_texture_inputs(clip, uv, width, height, levels, filter)
    ctx, _ = _context()
    lod, color = draw_texture_lod(ctx, _STATE["programs"], clip, uv, width, height, levels, filter)
    return _texture_frame(lod, color)


def gl_texture_lod_subprocess(
    clip, uv, width: int, height: int, levels, *, filter: str = "nearest_mipmap_nearest",
    timeout: float = 120.0,
) -> tuple[bool, str, GLTextureFrame | None]:  # fmt: skip
    """:func:`gl_texture_lod` in a fresh Python process, and whether OpenGL was there.

    For a notebook kernel that lives for a whole class: the GPU driver (llvmpipe maps hundreds
    of MiB) is loaded only in the child, and its memory is given back when the child exits.
    The child runs :mod:`.opengl_texture` as a script, which imports numpy and moderngl but not
    teachraster, so it starts in about a tenth of a second; it is a plain ``subprocess``, not
    ``multiprocessing``, whose resource-tracker process would outlive the call (and make
    IPython's kernel wait seconds for it at shut-down).

    Parameters
    ----------
    clip, uv, width, height, levels, filter
        As in :func:`gl_texture_lod` (checked here, before the child starts).
    timeout : float
        Seconds to wait for the child.

    Returns
    -------
    (True, renderer, frame) or (False, reason, None)
        ``renderer`` is ``GL_RENDERER``; ``reason`` says why there is no OpenGL (or how the
        child failed).
    """
    import subprocess
    import sys
    import tempfile
    from pathlib import Path

    from . import opengl_texture

    clip, uv, width, height, levels = _check_texture_inputs(clip, uv, width, height, levels, filter)
    arrays = {f"level_{i}": lv for i, lv in enumerate(levels)}
    with tempfile.TemporaryDirectory() as tmp:
        given, got = Path(tmp) / "in.npz", Path(tmp) / "out.npz"
        np.savez(given, clip=clip, uv=uv, width=width, height=height, filter=filter, **arrays)
        child = subprocess.run(
            [sys.executable, "-c", _RUN_SCRIPT, opengl_texture.__file__, str(given), str(got)],
            capture_output=True, text=True, timeout=timeout, check=False,
        )  # fmt: skip
        if child.returncode != 0 or not got.exists():
            last = (child.stderr.strip().splitlines() or ["no message"])[-1]
            return False, f"the OpenGL process failed (exit code {child.returncode}): {last}", None
        with np.load(got, allow_pickle=False) as out:
            if not bool(out["ok"]):
                return False, str(out["why"]), None
            return True, str(out["why"]), _texture_frame(out["lod_target"], out["color_target"])


# Runs a file as __main__ without putting its folder first on sys.path (where teachraster's own
# module names could shadow others), as ``python path`` would.
_RUN_SCRIPT = (
    "import runpy, sys; sys.argv = sys.argv[1:]; runpy.run_path(sys.argv[0], run_name='__main__')"
)


def _check_texture_inputs(clip, uv, width, height, levels, filter):
    clip, width, height, uv = _check_inputs(clip, width, height, uv, None)
    if uv.shape[2] != 2:
        raise ValueError(f"uv must have shape (N, 3, 2), got {uv.shape}")
    if filter not in GL_MIN_FILTERS:
        raise ValueError(f"filter must be one of {tuple(GL_MIN_FILTERS)}; got {filter!r}")
    levels = [np.asarray(lv, dtype=np.float64) for lv in levels]
    levels = [lv[..., None] if lv.ndim == 2 else lv for lv in levels]
    return clip, uv, width, height, levels


def _texture_frame(lod_target: np.ndarray, color_target: np.ndarray) -> GLTextureFrame:
    """The two read-back render targets as a frame: NaN where nothing was drawn."""
    out = lod_target.astype(np.float64)
    ids = out[..., 0].astype(np.int64)
    uncovered = ids < 0
    lod, level, color = out[..., 2], out[..., 1], color_target.astype(np.float64)
    for arr in (lod, level):
        arr[uncovered] = np.nan
    color[uncovered] = np.nan
    return GLTextureFrame(triangle_id=ids, lod=lod, level=level, color=color)
