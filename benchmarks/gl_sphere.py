"""Time Mesa's llvmpipe (OpenGL through moderngl + EGL) on the sphere scene, for comparison.

Run from anywhere (the repository root is put on ``sys.path``)::

    python benchmarks/gl_sphere.py             # 1024×1024, ~20,000-triangle UV sphere
    python benchmarks/gl_sphere.py --repeat 21 --size 512

:func:`time_gl` is what the scene benchmark imports; run standalone, this builds its own UV
sphere in numpy (a perspective camera looking at a unit sphere that fills the image, one
texture-coordinate attribute ``uv``, depth test on) and prints the medians.

Three figures, each a median of ``repeat`` timed calls after one warm-up call (the EGL context
and the compiled shader programs are created once per process and never timed):

- ``upload_draw_read``: everything :func:`teachraster.study.opengl.gl_render` does per frame: create
  the vertex buffers, vertex arrays and float32 render targets, draw, read every target back
  into numpy and release the GL objects;
- ``draw_read``: the scene already uploaded (:class:`teachraster.study.opengl.GLRenderer` kept): clear,
  draw, read back and build the :class:`~teachraster.study.opengl.GLFrame` (float64, NaN masking);
- ``draw_read_raw``: the same without the conversion: clear, draw and read the float32 targets
  (id/depth, ``smooth`` and ``noperspective``) into numpy. This is what a GPU-resident scene
  costs per frame, read-back included.

Importing this module only defines functions (and puts the repository root on ``sys.path``).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path
from typing import NamedTuple

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from teachraster.study.opengl import GLRenderer, gl_available, gl_render  # noqa: E402


class GLTiming(NamedTuple):
    """Median seconds per frame (see the module docstring)."""

    upload_draw_read: float
    draw_read: float
    draw_read_raw: float


def _median_time(fn, repeat: int) -> float:
    fn()  # warm-up: first use compiles shaders / faults in pages; not what we compare
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def time_gl(clip, width: int, height: int, attrs=None, repeat: int = 7) -> GLTiming:
    """Median llvmpipe time per frame, with and without uploading the scene, read-back included.

    Parameters
    ----------
    clip : (N, 3, 4) array-like
        Clip-space triangles, as for :func:`teachraster.pipeline.render_triangles.render`.
    width, height : int
        Image size.
    attrs : (N, 3) or (N, 3, k) array-like, optional
        Per-vertex attributes (interpolated and read back both as smooth and noperspective).
    repeat : int
        Timed calls per figure (after one warm-up call).

    Returns
    -------
    GLTiming
        ``upload_draw_read``, ``draw_read`` and ``draw_read_raw`` medians in seconds.

    Raises
    ------
    RuntimeError
        When no OpenGL context can be created (the message says why).
    """
    ok, why = gl_available()
    if not ok:
        raise RuntimeError(f"OpenGL is not available: {why}")
    full = _median_time(
        lambda: gl_render(clip, width, height, attrs=attrs, depth_test=True), repeat
    )
    with GLRenderer(clip, width, height, attrs=attrs, depth_test=True) as gl:
        draw_read = _median_time(gl.render, repeat)
        raw = _median_time(gl.render_raw, repeat)
    return GLTiming(upload_draw_read=full, draw_read=draw_read, draw_read_raw=raw)


def uv_sphere(n_lat: int = 100, n_lon: int = 101) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A unit UV sphere: positions (V, 3), texture coordinates (V, 2), triangles (T, 3).

    The seam column is duplicated (u = 0 and u = 1) and the pole rows are degenerate quads
    split as usual, so there are ``2 * n_lat * n_lon`` triangles, a few of zero area at the
    poles (exactly what a UV sphere from a modelling tool looks like).
    """
    theta = np.linspace(0, np.pi, n_lat + 1)  # from the north pole down
    phi = np.linspace(0, 2 * np.pi, n_lon + 1)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    pos = np.stack([np.sin(t) * np.cos(p), np.cos(t), np.sin(t) * np.sin(p)], -1).reshape(-1, 3)
    uv = np.stack([p / (2 * np.pi), 1 - t / np.pi], -1).reshape(-1, 2)
    idx = np.arange((n_lat + 1) * (n_lon + 1)).reshape(n_lat + 1, n_lon + 1)
    a, b = idx[:-1, :-1].ravel(), idx[:-1, 1:].ravel()
    c, d = idx[1:, :-1].ravel(), idx[1:, 1:].ravel()
    tris = np.concatenate([np.stack([a, c, b], -1), np.stack([b, c, d], -1)])
    return pos, uv, tris


def sphere_scene(distance: float = 2.6, fill: float = 0.98, near: float = 0.5, far: float = 10.0):
    """Clip-space triangles (T, 3, 4) and uv (T, 3, 2) of a unit sphere filling the image.

    A look-at camera on the +z axis ``distance`` from the centre; the vertical field of view
    is chosen so the sphere's silhouette spans ``fill`` of the image height.
    """
    pos, uv, tris = uv_sphere()
    view = pos - np.array([0.0, 0.0, distance])  # camera at (0, 0, d) looking down -z
    half = np.arcsin(1 / distance) / fill  # silhouette half-angle, widened a little
    f = 1 / np.tan(half)
    x, y, z = view[:, 0], view[:, 1], view[:, 2]
    clip = np.stack(
        [
            f * x,
            f * y,
            (far + near) / (near - far) * z + 2 * far * near / (near - far),
            -z,
        ],
        -1,
    )
    return clip[tris], uv[tris]


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=1024, help="image width = height")
    parser.add_argument("--repeat", type=int, default=11, help="timed calls per figure")
    args = parser.parse_args(argv)
    ok, why = gl_available()
    if not ok:
        print(f"skipped: {why}")
        return 0
    clip, uv = sphere_scene()
    frame = gl_render(clip, args.size, args.size, attrs=uv)
    covered = frame.coverage.mean()
    print(
        f"renderer: {why}\nscene: UV sphere, {len(clip)} triangles, {args.size}×{args.size}, "
        f"uv attribute, depth test on; {covered:.1%} of the pixels covered"
    )
    timing = time_gl(clip, args.size, args.size, attrs=uv, repeat=args.repeat)
    print(f"llvmpipe upload + draw + read-back: {timing.upload_draw_read * 1e3:8.1f} ms (median)")
    print(f"llvmpipe draw + read-back (GLFrame): {timing.draw_read * 1e3:7.1f} ms (median)")
    print(f"llvmpipe draw + raw float32 read:   {timing.draw_read_raw * 1e3:8.1f} ms (median)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
