"""The painter's algorithm (Ritschel, *Interpolation and z-buffering*): sort triangles far to near, draw without a z-buffer.

It needs no depth buffer, but one depth per *triangle* cannot order triangles that
intersect or overlap cyclically, which is where the z-buffer's per-pixel test wins.
"""

from __future__ import annotations

import numpy as np

from ...core.validate import check_choice
from ..planning.inputs import check_attrs, check_clip
from .render_triangles import Frame
from .render_triangles import render as render_clip

KEYS = ("max", "mean", "min")


def painter_order(clip, key: str = "max") -> np.ndarray:
    """Drawing order, far to near, by each triangle's ``key`` window depth.

    Triangles with a vertex at or behind the eye (w <= 0) are sorted by their in-front
    vertices only (clipping handles the rest); ties keep the input order.

    >>> painter_order([[[0, 0, 0.5, 1]] * 3, [[0, 0, -0.5, 1]] * 3, [[0, 0, 0.9, 1]] * 3])
    array([2, 0, 1])
    """
    check_choice("key", key, KEYS)
    clip = check_clip(clip)
    if len(clip) == 0:
        return np.zeros(0, dtype=np.int64)
    front = clip[..., 3] > 0
    # Window depth z/w / 2 + 1/2 (the viewport's); a vertex a hair in front of the eye may
    # project to ±inf, which still sorts (no NaN: w > 0 and z finite).
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        z = np.where(front, clip[..., 2] / np.where(front, clip[..., 3], 1.0) * 0.5 + 0.5, np.nan)
    depth = {"max": np.nanmax, "mean": np.nanmean, "min": np.nanmin}[key](
        np.where(front.any(axis=1)[:, None], z, 0.0), axis=1
    )
    return np.argsort(-depth, kind="stable")


def painter(clip, width: int, height: int, *, attrs=None, key: str = "max", **kwargs) -> Frame:
    """Render with the painter's algorithm; ``triangle_id`` refers to the input order.

    Keyword arguments other than ``depth_test`` go to :func:`teachraster.pipeline.render_triangles.render`.
    """
    if "depth_test" in kwargs:
        raise TypeError("painter draws without a depth test; do not pass depth_test")
    clip = check_clip(clip)
    order = painter_order(clip, key)
    clip = clip[order]
    if attrs is not None:
        attrs = check_attrs(attrs, len(clip))[order]
    frame = render_clip(clip, width, height, attrs=attrs, depth_test=False, **kwargs)
    ids = frame.triangle_id  # input order: drawing-order ids mapped back
    if len(order):
        ids = np.where(ids >= 0, order[np.maximum(ids, 0)], -1)
    return Frame(ids, frame.attrs, frame.depth, frame.plan, frame.trace)
