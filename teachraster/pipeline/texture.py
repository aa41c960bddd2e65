"""Textures: a procedural checkerboard, and nearest / bilinear sampling.

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

import numpy as np

from ..core.validate import as_int, as_real

FILTERS = ("nearest", "bilinear")
WRAPS = ("repeat", "clamp")


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


def sample(texture, uv, filter: str = "nearest", wrap: str = "repeat") -> np.ndarray:
    """Sample ``texture`` at texture coordinates ``uv`` (convention in the module docstring).

    Parameters
    ----------
    texture : (H, W) or (H, W, C) array-like
        Finite texel values (kept as they are: an 8-bit image is not rescaled).
    uv : (..., 2) array-like
        ``(u, v)`` per sample; NaN marks "no sample" (an uncovered pixel).
    filter : {"nearest", "bilinear"}
        Nearest texel, or GL-style bilinear blend of the four nearest texel centres.
    wrap : {"repeat", "clamp"}
        What lies outside [0, 1]: the texture tiled, or its border texels stretched.

    Returns
    -------
    (..., C) float64, or (...) for an (H, W) texture
        NaN wherever ``u`` or ``v`` is NaN.

    Examples
    --------
    >>> tex = np.array([[0.0, 1.0], [2.0, 3.0]])
    >>> sample(tex, [[0.25, 0.75], [1.25, 0.75]])         # texel (1, 0); repeat wraps u = 1.25
    array([2., 2.])
    >>> sample(tex, [[0.5, 0.25], [np.nan, np.nan]], filter="bilinear")   # between (0,0) and (0,1)
    array([0.5, nan])
    >>> sample(tex, [[-3.0, 0.25]], wrap="clamp")
    array([0.])
    """
    tex = _as_texture(texture)
    uv = _as_uv("uv", uv)
    if filter not in FILTERS:
        raise ValueError(f"filter must be one of {FILTERS}, got {filter!r}")
    if wrap not in WRAPS:
        raise ValueError(f"wrap must be one of {WRAPS}, got {wrap!r}")
    h, w = tex.shape[:2]
    lead = uv.shape[:-1]
    flat = uv.reshape(-1, 2)
    # Uncovered pixels carry NaN coordinates (CONVENTIONS); skip them instead of letting NaN
    # reach an integer index, and give them NaN colour so "nothing drawn" stays visible.
    ok = ~np.isnan(flat).any(axis=1)
    u, v = flat[ok, 0], flat[ok, 1]
    # Texels as rows of an (H*W, C) table fetched by one flat index (np.take): a little faster
    # than fancy-indexing [row, col], and it treats (H, W) and (H, W, C) textures alike.
    table = tex.reshape(h * w, -1)

    def fetch(row, col):
        return np.take(table, row * w + col, axis=0)

    if filter == "nearest":
        # The texel whose square [c/W, (c+1)/W) contains u: floor(u * W), then wrap the index.
        values = fetch(_wrap(np.floor(v * h), h, wrap), _wrap(np.floor(u * w), w, wrap))
    else:
        # GL_LINEAR: shift by half a texel so texel centres sit on integers, then blend the
        # four neighbours. Written as a + t (b - a), recentred like interpolation.blend (seed
        # 004), so a constant texture stays exactly constant and t = 0 returns a exactly.
        x, y = u * w - 0.5, v * h - 0.5
        x0, y0 = np.floor(x), np.floor(y)
        fx, fy = (x - x0)[:, None], (y - y0)[:, None]
        c0, c1 = _wrap(x0, w, wrap), _wrap(x0 + 1, w, wrap)
        r0, r1 = _wrap(y0, h, wrap), _wrap(y0 + 1, h, wrap)
        t00, t01 = fetch(r0, c0), fetch(r0, c1)
        t10, t11 = fetch(r1, c0), fetch(r1, c1)
        top = t00 + fx * (t01 - t00)
        values = top + fy * (t10 + fx * (t11 - t10) - top)
    out = np.full((flat.shape[0], table.shape[1]), np.nan)
    out[ok] = values
    return out.reshape(lead + tex.shape[2:])


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
    a = _as_uv("uv_a", uv_a, allow_inf=True)
    b = _as_uv("uv_b", uv_b, allow_inf=True)
    h, w = _texture_size(shape)
    try:
        np.broadcast_shapes(a.shape, b.shape)
    except ValueError:
        raise ValueError(
            f"uv_a and uv_b must broadcast together, got {a.shape} and {b.shape}"
        ) from None
    d = a - b
    return np.hypot(d[..., 0] * w, d[..., 1] * h)


# -- helpers ----------------------------------------------------------------------------------
def _wrap(index: np.ndarray, size: int, wrap: str) -> np.ndarray:
    """Integer texel indices for float indices (already floored), tiled or clamped."""
    if wrap == "repeat":
        index = np.mod(index, size)  # floor-mod: -1 -> size - 1, like GL_REPEAT
    else:
        index = np.clip(index, 0, size - 1)
    return index.astype(np.intp)


def _texture_size(shape) -> tuple[int, int]:
    """``(H, W)`` from a texture shape, or a ValueError naming ``shape``."""
    try:
        dims = tuple(as_int("shape", s) for s in shape)  # 2.7 is no size (int() would floor it)
    except (TypeError, ValueError):
        raise ValueError(
            f"shape must be a texture shape (H, W) or (H, W, C) of ints, got {shape!r}"
        ) from None
    if len(dims) not in (2, 3) or min(dims) < 1:
        raise ValueError(f"shape must be a texture shape (H, W) or (H, W, C), got {shape!r}")
    return dims[0], dims[1]


def _as_texture(texture) -> np.ndarray:
    tex = as_real("texture", texture)
    if tex.ndim not in (2, 3) or min(tex.shape) < 1:
        raise ValueError(f"texture must have shape (H, W) or (H, W, C), got {tex.shape}")
    if not np.isfinite(tex).all():
        raise ValueError("texture contains NaN or infinity")
    return tex


def _as_uv(name: str, uv, allow_inf: bool = False) -> np.ndarray:
    arr = as_real(name, uv)
    if arr.ndim < 1 or arr.shape[-1] != 2:
        raise ValueError(f"{name} must have shape (..., 2): (u, v) pairs, got {arr.shape}")
    if not allow_inf and np.isinf(arr).any():
        # NaN means "uncovered" and is allowed; infinity has no texel at all.
        raise ValueError(f"{name} contains infinity (NaN is allowed and marks no sample)")
    return arr
