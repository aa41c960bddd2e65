"""Mipmaps: a texture's pyramid of ever smaller, pre-averaged copies (Williams 1983).

A pixel far down a receding floor covers many texels; sampling one of them (``nearest``) or
four (``bilinear``) aliases -- the moiré of lesson 04. The cure GPUs use is to average *before*
sampling: level 0 is the texture, level ``l + 1`` halves each side of level ``l`` (GL's floor
rule ``max(1, floor(size / 2))``, so non-power-of-two sizes work) with a box filter, down to
1 × 1 (Fatahalian, CMU 15-462 *Texture*).

The box filter is exact area averaging: texel ``c`` of the smaller level covers
``[c / W', (c + 1) / W']`` in ``u`` and is the mean of the larger level over that interval, each
larger texel weighted by how much of it lies inside. For even sizes this is the plain mean of
2 × 2 texels; for odd ones a texel straddles two parents and is shared between them.

>>> levels = mipmap(np.arange(16.0).reshape(4, 4))
>>> [lv.shape for lv in levels]
[(4, 4), (2, 2), (1, 1)]
>>> levels[1]
array([[ 2.5,  4.5],
       [10.5, 12.5]])
"""

from __future__ import annotations

import numpy as np

from .texel_fetch import as_texture


def level_sizes(height: int, width: int) -> list[tuple[int, int]]:
    """``(H, W)`` of every level under GL's floor rule, level 0 first, down to 1 × 1.

    >>> level_sizes(5, 3)
    [(5, 3), (2, 1), (1, 1)]
    """
    sizes = [(height, width)]
    while sizes[-1] != (1, 1):
        h, w = sizes[-1]
        sizes.append((max(1, h // 2), max(1, w // 2)))
    return sizes


def _box_taps(n_in: int, n_out: int) -> tuple[np.ndarray, np.ndarray]:
    """Indices and weights (n_out, 3) of the area-weighted box filter from n_in to n_out texels.

    Output texel c spans [c, c + 1) * n_in / n_out in input texels: at most 3 of them when
    n_out = floor(n_in / 2) (the span is under 3 texels and starts on a multiple of its
    length), each weighted by its overlap, the weights summing to 1.
    """
    scale = n_in / n_out
    lo = np.arange(n_out) * scale
    first = np.floor(lo).astype(np.intp)
    idx = first[:, None] + np.arange(3)
    # Overlap of [lo, lo + scale) with input texel [i, i + 1), exact in rationals up to
    # rounding; computed from integer bounds times n_out to stay exact in float64.
    start = np.maximum(idx * n_out, (np.arange(n_out) * n_in)[:, None])
    stop = np.minimum((idx + 1) * n_out, (np.arange(n_out) * n_in + n_in)[:, None])
    weight = np.maximum(stop - start, 0) / n_in
    return np.minimum(idx, n_in - 1), weight


def _shrink(level: np.ndarray, axis: int, n_out: int) -> np.ndarray:
    n_in = level.shape[axis]
    if n_in == n_out:
        return level
    idx, weight = _box_taps(n_in, n_out)
    shape = [1] * level.ndim
    shape[axis] = n_out
    out = 0.0
    for t in range(3):
        out = out + np.take(level, idx[:, t], axis=axis) * weight[:, t].reshape(shape)
    return out


def mipmap(texture) -> list[np.ndarray]:
    """The mip pyramid of ``texture``: a list of float64 arrays, level 0 (a copy) first.

    Parameters
    ----------
    texture : (H, W) or (H, W, C) array-like
        Finite texel values.

    Returns
    -------
    list of (H_l, W_l) or (H_l, W_l, C) float64 arrays
        ``floor(log2(max(H, W))) + 1`` levels, sizes from :func:`level_sizes`, the last 1 × 1;
        each level the area average of the one before (see the module docstring).

    Examples
    --------
    >>> [lv.shape for lv in mipmap(np.zeros((6, 3, 2)))]
    [(6, 3, 2), (3, 1, 2), (1, 1, 2)]
    >>> float(mipmap(np.arange(3.0)[None, :])[-1][0, 0])   # three texels averaged
    1.0
    """
    tex = as_texture(texture)
    levels = [tex.copy()]
    for h, w in level_sizes(*tex.shape[:2])[1:]:
        levels.append(_shrink(_shrink(levels[-1], 0, h), 1, w))
    return levels


def is_pyramid(value) -> bool:
    """True for a list or tuple of arrays (what :func:`mipmap` returns), not a nested list."""
    return (
        isinstance(value, list | tuple)
        and len(value) > 0
        and all(isinstance(lv, np.ndarray) for lv in value)
    )


def as_pyramid(texture_or_pyramid, name: str = "texture") -> list[np.ndarray]:
    """A checked pyramid: the given one, or :func:`mipmap` of a single texture.

    A given pyramid may stop before 1 × 1 (GL's ``TEXTURE_MAX_LEVEL``), but its sizes must
    follow :func:`level_sizes` and its channels agree, or a ValueError names ``name``.
    """
    if not is_pyramid(texture_or_pyramid):
        return mipmap(as_texture(texture_or_pyramid, name))
    levels = [as_texture(lv, f"{name}[{i}]") for i, lv in enumerate(texture_or_pyramid)]
    want = level_sizes(*levels[0].shape[:2])
    for i, lv in enumerate(levels):
        if i >= len(want) or lv.shape[:2] != want[i] or lv.shape[2:] != levels[0].shape[2:]:
            expect = want[i] + levels[0].shape[2:] if i < len(want) else "no level"
            raise ValueError(
                f"{name}[{i}] must have shape {expect} (GL's floor rule from level 0 "
                f"{levels[0].shape}), got {lv.shape}"
            )
    return levels
