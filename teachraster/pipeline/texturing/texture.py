"""Textures: a procedural checkerboard, and sampling (nearest, bilinear, mipmapped, anisotropic).

Ritschel (*Interpolation and z-buffering*) lists texture coordinates among the per-pixel values
a rasteriser interpolates; Ek (*Triangles and Perspective Correct Interpolation*) and
Fatahalian (CMU 15-462, *Texture*) explain why they must be interpolated perspective-correctly. Sampling a texture at
the interpolated coordinates is what makes the difference *visible*: with affine
interpolation a receding checkerboard bends (the classic warp), and :func:`texel_error` measures
the bend in texels.

Texture coordinate convention
-----------------------------
A texture is an array ``(H, W)`` or ``(H, W, C)`` indexed ``[row, col]``, like the image
(CONVENTIONS: row 0 is the top).

- ``u`` runs along the columns, left to right; ``v`` runs along the rows, top to bottom, so row 0
  is at ``v = 0``. Both span [0, 1] over the whole image.
- Texel ``(r, c)`` covers ``[c/W, (c+1)/W] x [r/H, (r+1)/H]`` and has its centre at
  ``((c + 0.5)/W, (r + 0.5)/H)`` -- the same "centres at +0.5" rule as pixels.
- ``nearest`` returns the texel whose square contains ``(u, v)``: column ``floor(u * W)``.
- ``bilinear`` is GL's ``GL_LINEAR``: ``x = u*W - 0.5`` (so texel centres land on integers),
  blend the four texels around ``(x, y)`` by the fractional parts.
- ``wrap="repeat"`` tiles the texture (GL ``GL_REPEAT``: ``u`` and ``u + 1`` sample the same);
  ``wrap="clamp"`` repeats the border texels outwards (GL ``GL_CLAMP_TO_EDGE``).

Where ``uv`` is NaN (pixels no triangle covers, see CONVENTIONS) the sample is NaN.

>>> tex = checkerboard(checks=2, texels=2)
>>> sample(tex, [[0.25, 0.25], [0.75, 0.25]])      # the centres of texels (0, 0) and (0, 1)
array([[0.92, 0.92, 0.92],
       [0.15, 0.2 , 0.35]])
"""

from __future__ import annotations

from numbers import Real

import numpy as np

from ...core.validate import as_int, as_real, check_choice
from .mip_pyramid import as_pyramid, is_pyramid
from .texel_fetch import LEVEL_FILTERS, WRAPS, as_texture, as_uv, lookup, texture_size
from .texture_filters import MIPMAP_FILTERS, mip_level, sample_anisotropic, sample_levels

#: The filters within one level (no mipmaps); the mipmapped ones are ``MIPMAP_FILTERS``.
FILTERS = LEVEL_FILTERS
#: Every filter ``sample`` knows.
TEXTURE_FILTERS = FILTERS + tuple(MIPMAP_FILTERS)


def checkerboard(
    checks: int = 8,
    texels: int = 64,
    colors=((0.92, 0.92, 0.92), (0.15, 0.2, 0.35)),
) -> np.ndarray:
    """A ``checks`` x ``checks`` checkerboard texture of ``texels`` x ``texels`` texels.

    The classic test texture for perspective: its straight lines show at a glance whether
    texture coordinates were interpolated perspective-correctly (Fatahalian, CMU 15-462 *Texture*).

    Parameters
    ----------
    checks : int
        Number of squares along each side (1 <= checks <= texels).
    texels : int
        Texture size in texels along each side.
    colors : (2, C) array-like
        The two colours, values in [0, 1]; ``colors[0]`` is the top-left square.

    Returns
    -------
    (texels, texels, C) float64
        Square ``(i, j)`` (``i`` down, ``j`` across) has colour ``colors[(i + j) % 2]``.

    Examples
    --------
    >>> checkerboard(checks=2, texels=4, colors=([1.0], [0.0]))[..., 0]
    array([[1., 1., 0., 0.],
           [1., 1., 0., 0.],
           [0., 0., 1., 1.],
           [0., 0., 1., 1.]])
    """
    texels = as_int("texels", texels, minimum=1)
    checks = as_int("checks", checks, minimum=1)
    if checks > texels:
        raise ValueError(
            f"checks must be <= texels (a square must be at least one texel wide), "
            f"got checks={checks}, texels={texels}"
        )
    cols = as_real("colors", colors)
    if cols.ndim != 2 or cols.shape[0] != 2 or cols.shape[1] < 1:
        raise ValueError(f"colors must have shape (2, C): two colours, got {cols.shape}")
    if not (np.isfinite(cols).all() and ((cols >= 0) & (cols <= 1)).all()):
        raise ValueError(f"colors must lie in [0, 1], got {cols.tolist()}")
    # Integer arithmetic decides each texel's square, so squares of unequal size (texels not a
    # multiple of checks) still tile exactly, with no rounding at square boundaries.
    square = np.arange(texels) * checks // texels
    parity = (square[:, None] + square[None, :]) % 2
    return cols[parity]


def sample(
    texture,
    uv,
    filter: str = "nearest",
    wrap: str = "repeat",
    *,
    lod=None,
    ddx=None,
    ddy=None,
    max_anisotropy=16,
) -> np.ndarray:
    """Sample a texture or its mip pyramid at texture coordinates ``uv``.

    Convention in the module docstring; the mipmapped filters in
    :mod:`teachraster.pipeline.texture_filters`.

    Parameters
    ----------
    texture : (H, W) or (H, W, C) array-like, or a pyramid (list of arrays, see ``mipmap``)
        Finite texel values (kept as they are: an 8-bit image is not rescaled). A single
        texture is turned into its pyramid when the filter uses mipmaps; a pyramid's level 0
        serves ``nearest`` and ``bilinear``.
    uv : (..., 2) array-like
        ``(u, v)`` per sample; NaN marks "no sample" (an uncovered pixel).
    filter : str
        ``"nearest"`` or ``"bilinear"`` (level 0 only), ``"nearest_mipmap_nearest"``,
        ``"linear_mipmap_nearest"``, ``"nearest_mipmap_linear"``, ``"trilinear"`` (these need
        ``lod``, or ``ddx`` and ``ddy``) or ``"anisotropic"`` (needs ``ddx`` and ``ddy``).
    wrap : {"repeat", "clamp"}
        What lies outside [0, 1]: the texture tiled, or its border texels stretched.
    lod : float or (...) array-like, optional
        The level of detail λ per sample (broadcast against ``uv``'s leading shape).
    ddx, ddy : (..., k) array-like, optional
        Screen-space derivatives of ``(u, v)`` (channels 0, 1), e.g. ``frame.ddx``; λ is
        :func:`~teachraster.pipeline.texture_filters.mip_level` of them.
    max_anisotropy : number >= 1
        Most probes ``anisotropic`` takes along the footprint's major axis (GL's
        ``TEXTURE_MAX_ANISOTROPY``); clamped to ``MAX_ANISOTROPY`` (16), as GL clamps it to
        the implementation's maximum (16 on llvmpipe), so ``inf`` means 16.

    Returns
    -------
    (..., C) float64, or (...) for an (H, W) texture
        NaN wherever ``u``, ``v`` (or the level of detail) is NaN.

    Examples
    --------
    >>> tex = np.array([[0.0, 1.0], [2.0, 3.0]])
    >>> sample(tex, [[0.25, 0.75], [1.25, 0.75]])         # texel (1, 0); repeat wraps u = 1.25
    array([2., 2.])
    >>> sample(tex, [[0.5, 0.25], [np.nan, np.nan]], filter="bilinear")   # between (0,0) and (0,1)
    array([0.5, nan])
    >>> sample(tex, [[-3.0, 0.25]], wrap="clamp")
    array([0.])
    >>> sample(tex, [[0.25, 0.25], [0.25, 0.25]], "trilinear", lod=[0.0, 1.0])   # level 1: mean
    array([0. , 1.5])
    """
    check_choice("filter", filter, TEXTURE_FILTERS)
    check_choice("wrap", wrap, WRAPS)
    if filter in FILTERS:
        levels = as_pyramid(texture) if is_pyramid(texture) else [as_texture(texture)]
    else:
        levels = as_pyramid(texture)
    uv = as_uv("uv", uv)
    lead, tail = uv.shape[:-1], levels[0].shape[2:]
    flat = uv.reshape(-1, 2)
    # Uncovered pixels carry NaN coordinates (CONVENTIONS); skip them instead of letting NaN
    # reach an integer index, and give them NaN colour so "nothing drawn" stays visible.
    ok = ~np.isnan(flat).any(axis=1)
    if filter in FILTERS:
        _check_unused(filter, lod=lod, ddx=ddx, ddy=ddy)
        values = lookup(levels[0], flat[ok, 0], flat[ok, 1], filter, wrap)
    else:
        values, ok = _sample_mipmapped(levels, flat, ok, lead, filter, wrap, lod, ddx, ddy,
                                       max_anisotropy)  # fmt: skip
    out = np.full((flat.shape[0], values.shape[1]), np.nan)
    out[ok] = values
    return out.reshape(lead + tail)


def _check_unused(filter, **given):
    extra = [name for name, value in given.items() if value is not None]
    if extra:
        raise ValueError(
            f"{extra[0]}: filter={filter!r} samples level 0 only and takes no {extra[0]}"
        )


def _sample_mipmapped(levels, flat, ok, lead, filter, wrap, lod, ddx, ddy, max_anisotropy):
    """Values at the samples ``ok`` where λ is also defined, and that narrowed mask."""
    if isinstance(max_anisotropy, bool) or not isinstance(max_anisotropy, Real | np.number):
        raise ValueError(f"max_anisotropy must be a number >= 1, got {max_anisotropy!r}")
    if not max_anisotropy >= 1:  # also refuses NaN
        raise ValueError(
            f"max_anisotropy must be a number >= 1 (GL's minimum), got {max_anisotropy!r}"
        )
    if filter == "anisotropic" and (lod is not None or ddx is None or ddy is None):
        raise ValueError("filter='anisotropic' needs ddx and ddy (the footprint), not lod")
    if lod is not None and (ddx is not None or ddy is not None):
        raise ValueError("lod: give either lod or ddx and ddy, not both")
    if lod is None and (ddx is None or ddy is None):
        raise ValueError(f"filter={filter!r} needs lod, or ddx and ddy to compute it from")
    n = flat.shape[0]
    if lod is not None:
        lam = _real_not_bool("lod", lod)
        try:
            lam = np.broadcast_to(lam, lead).reshape(n)
        except ValueError:
            raise ValueError(f"lod must be a number or an array of shape {lead}") from None
    else:
        dx = _derivatives("ddx", ddx, lead)
        dy = _derivatives("ddy", ddy, lead)
        lam = mip_level(dx, dy, levels[0].shape)
    ok = ok & ~np.isnan(lam)
    u, v = flat[ok, 0], flat[ok, 1]
    if filter == "anisotropic":
        return sample_anisotropic(levels, u, v, dx[ok], dy[ok], max_anisotropy, wrap), ok
    how, within = MIPMAP_FILTERS[filter]
    return sample_levels(levels, u, v, lam[ok], how, within, wrap), ok


def _real_not_bool(name, value) -> np.ndarray:
    """``value`` as float64 (NaN and inf pass); strings, complex and booleans refused.

    ``lod=True`` or ``lod="1"`` is a slip, never a level of detail (as in ``mip_level``).
    """
    arr = as_real(name, value)
    if np.asarray(value).dtype.kind == "b":
        raise TypeError(f"{name} must be numeric (real numbers), got {value!r}")
    return arr


def _derivatives(name, value, lead):
    arr = _real_not_bool(name, value)
    if arr.shape[:-1] != lead or arr.ndim < 1 or arr.shape[-1] < 2:
        raise ValueError(f"{name} must have shape {lead + ('k',)} with k >= 2, got {arr.shape}")
    return arr.reshape(-1, arr.shape[-1])[:, :2]


def texel_error(uv_a, uv_b, shape) -> np.ndarray:
    """Distance between two sets of texture coordinates, in texels.

    ``sqrt(((u_a - u_b) W)**2 + ((v_a - v_b) H)**2)``: how far apart on the texture two
    samples land -- e.g. affine vs perspective-correct coordinates of the same pixel. Above
    about 0.5 texel the difference can show up as a wrong texel under nearest filtering.

    Parameters
    ----------
    uv_a, uv_b : (..., 2) array-like
        Texture coordinates (broadcast against each other); NaN allowed.
    shape : tuple
        The texture's shape ``(H, W)`` or ``(H, W, C)``, e.g. ``texture.shape``.

    Returns
    -------
    (...) float64
        NaN where either input is NaN.

    Examples
    --------
    >>> texel_error([[0.5, 0.5], [0.0, 0.0]], [[0.75, 0.5], [np.nan, 0.0]], (8, 4))
    array([ 1., nan])
    """
    a = as_uv("uv_a", uv_a, allow_inf=True)
    b = as_uv("uv_b", uv_b, allow_inf=True)
    h, w = texture_size(shape)
    try:
        np.broadcast_shapes(a.shape, b.shape)
    except ValueError:
        raise ValueError(
            f"uv_a and uv_b must broadcast together, got {a.shape} and {b.shape}"
        ) from None
    d = a - b
    return np.hypot(d[..., 0] * w, d[..., 1] * h)
