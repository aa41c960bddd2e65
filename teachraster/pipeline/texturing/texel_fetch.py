"""Reading texels: argument checks for textures and coordinates, wrapping, one-level lookups.

The shared ground of :mod:`.texture` (the public ``sample``), :mod:`.mip_pyramid` and
:mod:`.texture_filters`: every texture and every ``uv`` array is checked here, and the two
filters *within one level* (``nearest``, GL's ``NEAREST``; ``bilinear``, GL's ``LINEAR``) are
written once here, so the mipmapped filters reuse exactly the same texel arithmetic.

>>> level = np.array([[0.0, 1.0], [2.0, 3.0]])
>>> lookup(level, np.array([0.5]), np.array([0.25]), "bilinear", "repeat")
array([[0.5]])
"""

from __future__ import annotations

import numpy as np

from ...core.validate import as_int, as_real

#: The filters within one level, and what lies outside [0, 1].
LEVEL_FILTERS = ("nearest", "bilinear")
WRAPS = ("repeat", "clamp")


def as_texture(texture, name: str = "texture") -> np.ndarray:
    """``texture`` as a finite float64 array (H, W) or (H, W, C), or a ValueError naming it."""
    try:
        tex = as_real(name, texture)
    except TypeError as exc:  # strings, complex, ragged...: a texture is an array of numbers
        raise ValueError(
            f"{name} must be a numeric array of shape (H, W) or (H, W, C): {exc}"
        ) from None
    if tex.ndim not in (2, 3) or min(tex.shape) < 1:
        raise ValueError(f"{name} must have shape (H, W) or (H, W, C), got {tex.shape}")
    if not np.isfinite(tex).all():
        raise ValueError(f"{name} contains NaN or infinity")
    return tex


def as_uv(name: str, uv, allow_inf: bool = False) -> np.ndarray:
    """``uv`` as a float64 array (..., 2); NaN is allowed (it marks "no sample")."""
    arr = as_real(name, uv)
    if arr.ndim < 1 or arr.shape[-1] != 2:
        raise ValueError(f"{name} must have shape (..., 2): (u, v) pairs, got {arr.shape}")
    if not allow_inf and np.isinf(arr).any():
        # NaN means "uncovered" and is allowed; infinity has no texel at all.
        raise ValueError(f"{name} contains infinity (NaN is allowed and marks no sample)")
    return arr


def texture_size(shape, name: str = "shape") -> tuple[int, int]:
    """``(H, W)`` from a texture shape ``(H, W)`` or ``(H, W, C)``, or a ValueError naming it."""
    try:
        dims = tuple(as_int(name, s) for s in shape)  # 2.7 is no size (int() would floor it)
    except (TypeError, ValueError):
        raise ValueError(
            f"{name} must be a texture shape (H, W) or (H, W, C), got {shape!r}"
        ) from None
    if len(dims) not in (2, 3) or min(dims) < 1:
        raise ValueError(f"{name} must be a texture shape (H, W) or (H, W, C), got {shape!r}")
    return dims[0], dims[1]


def wrap_index(index: np.ndarray, size, wrap: str) -> np.ndarray:
    """Integer texel indices for float indices (already floored), tiled or clamped; ``size``
    a number or one per index."""
    if wrap == "repeat":
        index = np.mod(index, size)  # floor-mod: -1 -> size - 1, like GL_REPEAT
    else:
        index = np.clip(index, 0, size - 1)
    return index.astype(np.intp)


def lookup(level: np.ndarray, u: np.ndarray, v: np.ndarray, filter: str, wrap: str) -> np.ndarray:
    """Filter one texture level at finite coordinates ``u``, ``v`` (n,): an (n, C) array.

    ``nearest`` takes the texel whose square contains (u, v); ``bilinear`` is GL's
    ``LINEAR``: texel centres on integers after ``x = u W - 1/2``, the four neighbours blended
    by the fractional parts (convention in :mod:`teachraster.pipeline.texture`).
    """
    h, w = level.shape[:2]
    # Texels as rows of an (H*W, C) table fetched by one flat index (np.take): a little faster
    # than fancy-indexing [row, col], and it treats (H, W) and (H, W, C) textures alike.
    return filtered(level.reshape(h * w, -1), 0, h, w, u, v, filter, wrap)


def level_table(levels) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Every level's texels in one (T, C) table, and each level's offset, height and width.

    So a mipmapped filter reads all its pixels' levels in one pass of :func:`filtered`, each
    pixel with its own level's offset and size, instead of one pass per level.
    """
    flat = [lv.reshape(lv.shape[0] * lv.shape[1], -1) for lv in levels]
    sizes = np.array([len(f) for f in flat])
    offset = np.concatenate([[0], np.cumsum(sizes)[:-1]])
    height = np.array([lv.shape[0] for lv in levels])
    width = np.array([lv.shape[1] for lv in levels])
    return np.concatenate(flat), offset, height, width


def filtered(table, offset, h, w, u, v, filter: str, wrap: str) -> np.ndarray:
    """:func:`lookup` on texels stored from ``offset`` of ``table`` as an ``h`` × ``w`` level;
    ``offset``, ``h``, ``w`` are numbers or per-sample arrays (see :func:`level_table`)."""

    def fetch(row, col):
        return np.take(table, offset + row * w + col, axis=0)

    u, v = reduce_coordinates(u, wrap), reduce_coordinates(v, wrap)
    if filter == "nearest":
        # The texel whose square [c/W, (c+1)/W) contains u: floor(u * W), then wrap the index.
        return fetch(wrap_index(np.floor(v * h), h, wrap), wrap_index(np.floor(u * w), w, wrap))
    # Written as a + t (b - a), recentred like interpolation.blend, so a constant texture
    # stays exactly constant and t = 0 returns a exactly.
    x0, y0, fx, fy = bilinear_corner(u, v, h, w)
    fx, fy = fx[:, None], fy[:, None]
    c0, c1 = wrap_index(x0, w, wrap), wrap_index(x0 + 1, w, wrap)
    r0, r1 = wrap_index(y0, h, wrap), wrap_index(y0 + 1, h, wrap)
    t00, t01 = fetch(r0, c0), fetch(r0, c1)
    t10, t11 = fetch(r1, c0), fetch(r1, c1)
    with np.errstate(over="ignore", invalid="ignore"):
        out = _bilinear_blend(t00, t01, t10, t11, fx, fy)
    bad = ~np.isfinite(out).all(axis=1)
    if bad.any():
        # Texels near ±1.8e308: a difference such as 1e308 - (-1e308) overflows although the
        # blend (a convex combination) does not. Blend those samples scaled down by 2**-4
        # (exact), then scale back: inf only where the true value overflows (it cannot).
        s = 2.0**-4
        tb = [t[bad] * s for t in (t00, t01, t10, t11)]
        out[bad] = _bilinear_blend(*tb, fx[bad], fy[bad]) / s
    return out


def bilinear_corner(u, v, h, w):
    """The 2 × 2 texels ``LINEAR`` reads at ``u``, ``v`` of an ``h`` × ``w`` level: the column
    and row of the first (not yet wrapped: the others are the next column and row), and the
    blend weights of the second column and row.

    Texel centres lie on integers after ``x = u W - 1/2`` (GL's ``LINEAR``), so the texels read are columns ``⌊x⌋`` and ``⌊x⌋ + 1``, blended by ``x - ⌊x⌋``; rows alike.

    >>> bilinear_corner(np.array([0.5]), np.array([0.3]), 4, 4)
    (array([1.]), array([0.]), array([0.5]), array([0.7]))
    """
    x, y = u * w - 0.5, v * h - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    return x0, y0, x - x0, y - y0


def _bilinear_blend(t00, t01, t10, t11, fx, fy):
    top = t00 + fx * (t01 - t00)
    return top + fy * (t10 + fx * (t11 - t10) - top)


#: Beyond this magnitude a coordinate has no fractional texel left (u W is an integer) and
#: u W may even overflow: such coordinates are reduced first, exactly.
HUGE_COORDINATE = 2.0**40


def reduce_coordinates(u: np.ndarray, wrap: str) -> np.ndarray:
    """``u`` with huge values brought into range without changing the texel they pick.

    ``repeat`` tiles with period 1, so ``u mod 1`` (exact in floating point) reads the same
    texels; ``clamp`` reads the border texel for anything beyond [0, 1], so such ``u`` are
    clamped to [-1, 2]. Ordinary coordinates are returned untouched (the same bits as
    before), so only values that would otherwise overflow ``u W`` change.

    >>> reduce_coordinates(np.array([0.25, 1.7e308, -3e300]), "repeat")
    array([0.25, 0.  , 0.  ])
    >>> reduce_coordinates(np.array([0.25, 1.7e308, -3e300]), "clamp")
    array([ 0.25,  2.  , -1.  ])
    """
    huge = np.abs(u) > HUGE_COORDINATE
    if not huge.any():
        return u
    u = np.array(u, dtype=np.float64)
    u[huge] = np.mod(u[huge], 1.0) if wrap == "repeat" else np.clip(u[huge], -1.0, 2.0)
    return u
