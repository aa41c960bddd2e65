"""``render_scene``'s texturing and MSAA resolve with a caller's rules, pixel by pixel.

The package filters a whole image of texture coordinates at once
(:func:`teachraster.pipeline.texturing.texture.sample`) and resolves samples with
:meth:`Frame.resolve`. A caller's rules (:mod:`teachraster.pipeline.planning.overrides`:
a student's ``bilinear``, ``trilinear`` and ``resolve`` in the course's capstone) are asked
once per covered pixel instead, with the arguments the exercises use; the texture and the
pyramid they get are read-only (a rule that writes into them raises). The level of detail a
``trilinear`` rule gets is the package's λ (:func:`teachraster.mip_level` of the quad
derivatives), unclamped: keeping it within the pyramid is the filter's job.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..texturing.mip_pyramid import mipmap
from ..texturing.texture_filters import mip_level

#: The wrap mode of the scenes' textures (``sample``'s default).
WRAP = "repeat"


def texture_by_rule(texture, uv, texture_filter: str, ddx, ddy, rule: Callable) -> np.ndarray:
    """(..., C) the texture filtered by ``rule`` at every finite ``uv`` (..., 2), NaN elsewhere.

    ``texture_filter`` "bilinear": ``rule(texture, uv, wrap)``; "trilinear":
    ``rule(pyramid, uv, lod, wrap)`` with ``lod`` from ``ddx``, ``ddy`` (..., 2) (zero
    derivatives, a magnified pixel: λ = -inf).
    """
    tex = _read_only(np.asarray(texture, dtype=np.float64))
    uv = np.asarray(uv, dtype=np.float64)
    channels = tex.shape[2:] if tex.ndim == 3 else ()
    out = np.full(uv.shape[:-1] + channels, np.nan)
    covered = np.isfinite(uv).all(axis=-1)
    if texture_filter == "trilinear":
        pyramid = [_read_only(level) for level in mipmap(tex)]
        zero = np.zeros_like(uv)
        dx = zero if ddx is None else np.where(np.isnan(ddx), 0.0, ddx)
        dy = zero if ddy is None else np.where(np.isnan(ddy), 0.0, ddy)
        with np.errstate(divide="ignore"):
            lod = mip_level(dx, dy, tex.shape)
    for index in zip(*np.nonzero(covered)):
        point = uv[index].copy()
        if texture_filter == "trilinear":
            value = rule(pyramid, point, float(lod[index]), WRAP)
        else:
            value = rule(tex, point, WRAP)
        out[index] = _values("texture", value, channels)
    return out


def resolve_by_rule(colours, ids, background, rule: Callable) -> np.ndarray:
    """(H, W, 3): ``rule(colours (S, 3), ids (S,), background (3,))`` at every pixel some
    sample covers (``ids`` (H, W, S), -1 uncovered, whose colours are NaN), NaN elsewhere."""
    colours = np.asarray(colours, dtype=np.float64)
    ids = np.asarray(ids)
    bg = np.broadcast_to(np.asarray(background, dtype=np.float64), colours.shape[-1:])
    out = np.full(colours.shape[:2] + colours.shape[-1:], np.nan)
    for r, c in zip(*np.nonzero((ids >= 0).any(axis=2))):
        value = rule(colours[r, c].copy(), ids[r, c].copy(), bg.copy())
        out[r, c] = _values("resolve", value, colours.shape[-1:])
    return out


def _read_only(arr: np.ndarray) -> np.ndarray:
    view = arr.view()
    view.flags.writeable = False
    return view


def _values(name: str, value, channels: tuple) -> np.ndarray:
    arr = np.asarray(value, dtype=np.float64)
    if arr.shape != channels:
        raise ValueError(f"the {name} rule must return shape {channels}, got {arr.shape}")
    return arr
