"""The viewport transform: clip space to window (screen) space, as in CONVENTIONS.

``x_win = (x/w + 1) * width / 2``, ``y_win = (1 - y/w) * height / 2`` (y down, row 0 at
the top), ``z_win = (z/w) / 2 + 1/2`` (NDC z in [-1, 1] to depth [0, 1], smaller nearer).
"""

from __future__ import annotations

import numpy as np

from ...core.validate import as_real, as_size


def to_window(clip, width: int, height: int) -> np.ndarray:
    """Window coordinates (x, y, z) of clip-space points (..., 4).

    The divide by w is only meaningful after clipping against the near plane (w > 0): a
    point behind the eye (w < 0) comes out mirrored through it (lesson 05 shows what that
    would draw), and one on the eye plane (w = 0) has no image at all (a ValueError).

    >>> to_window([[0.0, 0.0, 0.0, 1.0], [-2.0, 2.0, 2.0, 2.0]], 640, 480)
    array([[320. , 240. ,   0.5],
           [  0. ,   0. ,   1. ]])
    """
    c = as_real("clip", clip)
    if c.ndim < 1 or c.shape[-1] != 4:
        raise ValueError(f"clip must have shape (..., 4): (x, y, z, w) points, got {c.shape}")
    width, height = as_size("width", width), as_size("height", height)
    w = c[..., 3]
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # refused below
        x = (c[..., 0] / w + 1.0) * (width / 2)
        y = (1.0 - c[..., 1] / w) * (height / 2)
        z = (c[..., 2] / w) * 0.5 + 0.5
        out = np.stack([x, y, z], axis=-1)
    if not np.isfinite(out).all():
        raise ValueError(
            "clip: a point is infinite, on the eye plane (w = 0) or so close to it that it "
            "projects beyond the float range; clip first (tr.clip_triangles)"
        )
    return out
