"""Who owns each pixel of a 2-D mesh, by OpenGL (Mesa's llvmpipe): lesson 07's check on a GPU.

Lesson 07 draws its meshes in window coordinates (pixels, y down) with
:func:`teachraster.rasterize`; :func:`gl_owners` draws the same triangles with OpenGL and
reads back two things:

- the **owner** of each pixel: ``gl_PrimitiveID`` of the fragment that wrote it, depth test
  off (:func:`~teachraster.study.opengl.gl_render`'s ``triangle_id``);
- the **fragments** each pixel received: the stencil buffer incremented on every fragment
  (:func:`~teachraster.study.opengl_counters.gl_counters`' overdraw). The owner alone is the
  last writer, which hides a pixel drawn twice; the count does not.

The triangles go to GL as clip coordinates with w = 1, the inverse of the conventions'
viewport transform (:func:`window_to_clip`). GL computes the window position back in float32:
a vertex on the 1/256-px grid lands within about 1e-5 px of it, far inside the half step
(1/512 px) that would snap it elsewhere, so GL snaps and fills the vertices we do.

Like :mod:`.opengl`, this module needs ``moderngl`` only when it draws:
:func:`~teachraster.study.opengl.gl_available` says whether it can.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.validate import as_size

__all__ = ["GLOwners", "gl_owners", "window_to_clip"]


@dataclass(frozen=True)
class GLOwners:
    """What OpenGL drew of a mesh.

    Attributes
    ----------
    owner : (H, W) int64
        Index of the triangle that wrote the pixel, -1 where none did (depth test off: the
        last triangle drawn that covers it).
    fragments : (H, W) int64
        How many fragments reached the pixel, over all the triangles: 1 everywhere a mesh
        covers, never 2 if GL draws no centre twice.
    """

    owner: np.ndarray
    fragments: np.ndarray


def window_to_clip(xy, width: int, height: int) -> np.ndarray:
    """Clip coordinates (N, 3, 4), w = 1 and z = 0, of window-space triangles ``xy`` (N, 3, 2)
    in an image ``width`` × ``height``: ``x = 2 x_win / width − 1``, ``y = 1 − 2 y_win /
    height`` (CONVENTIONS.md, the viewport transform inverted).

    >>> window_to_clip([[[0, 0], [4, 0], [0, 4]]], 4, 4).tolist()
    [[[-1.0, 1.0, 0.0, 1.0], [1.0, 1.0, 0.0, 1.0], [-1.0, -1.0, 0.0, 1.0]]]
    """
    width, height = as_size("width", width), as_size("height", height)
    xy = np.asarray(xy, dtype=np.float64)
    if xy.ndim != 3 or xy.shape[1:] != (3, 2):
        raise ValueError(f"xy must be (N, 3, 2) window-space triangles, got shape {xy.shape}")
    x = 2 * xy[..., 0] / width - 1
    y = 1 - 2 * xy[..., 1] / height
    return np.stack([x, y, np.zeros_like(x), np.ones_like(x)], axis=-1)


def gl_owners(xy, width: int, height: int) -> GLOwners:
    """Draw window-space triangles ``xy`` (N, 3, 2) with OpenGL, depth test off, in order:
    each pixel's owner and the fragments it received (see the module docstring).

    Raises ``RuntimeError`` where no OpenGL context can be created
    (:func:`~teachraster.study.opengl.gl_available` says why).
    """
    from .opengl import gl_render
    from .opengl_counters import gl_counters

    clip = window_to_clip(xy, width, height)
    owner = gl_render(clip, width, height, depth_test=False).triangle_id
    fragments = gl_counters(clip, width, height, depth_test=False).overdraw
    return GLOwners(np.asarray(owner, dtype=np.int64), np.asarray(fragments, dtype=np.int64))
