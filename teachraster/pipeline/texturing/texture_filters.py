"""Texture filters across mip levels: the level of detail λ, mipmapped and anisotropic sampling.

The pixel's footprint on the texture decides how much must be averaged. Its size comes from
the screen-space derivatives of ``(u, v)`` (2 × 2 quads, :mod:`.render_triangles`), in texels:

    ρ = max(‖∂(u W, v H)/∂x‖, ‖∂(u W, v H)/∂y‖),   λ = log2 ρ            (GL 4.6, eq. 8.7)

λ ≤ 0 magnifies (a texel covers a pixel or more): level 0. Above, the filters choose levels
of the pyramid (:mod:`.mip_pyramid`) as OpenGL's minifying filters do:

=========================  ==========================================  =========  ==============
filter                     levels                                      in a level  GL name
=========================  ==========================================  =========  ==============
``nearest_mipmap_nearest`` the nearest: 0 if λ ≤ ½, else ⌈λ + ½⌉ − 1     nearest    NEAREST_MIPMAP_NEAREST
``linear_mipmap_nearest``  the nearest                                 bilinear   LINEAR_MIPMAP_NEAREST
``nearest_mipmap_linear``  ⌊λ⌋ and ⌊λ⌋ + 1, blended by λ − ⌊λ⌋        nearest    NEAREST_MIPMAP_LINEAR
``trilinear``              ⌊λ⌋ and ⌊λ⌋ + 1, blended by λ − ⌊λ⌋        bilinear   LINEAR_MIPMAP_LINEAR
``anisotropic``            N trilinear probes along the major axis      bilinear   EXT_texture_filter_anisotropic
=========================  ==========================================  =========  ==============

Levels are clamped to the pyramid (0 … q). Anisotropic filtering follows the
``EXT_texture_filter_anisotropic`` spec: with P_max and P_min the longer and shorter of the
two footprint axes (in texels), ``N = min(⌈P_max / P_min⌉, max_anisotropy)`` probes at
``λ = log2(P_max / N)`` (about the minor axis's level), spaced evenly along the major axis:
``uv + (i / (N + 1) − ½) · ∂uv/∂major`` for i = 1 … N, averaged. Where the footprint is
magnified (P_max ≤ 1 texel) one probe is taken: bilinear on level 0, like every other filter.

>>> float(mip_level([[0.25, 0.0]], [[0.0, 0.25]], (8, 8))[0])    # 2 texels per pixel
1.0
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.validate import as_real
from .mip_pyramid import level_sizes
from .texel_fetch import filtered, level_table, texture_size

#: Filters that use the pyramid, each as (how levels are chosen, the filter within a level).
MIPMAP_FILTERS = {
    "nearest_mipmap_nearest": ("nearest", "nearest"),
    "linear_mipmap_nearest": ("nearest", "bilinear"),
    "nearest_mipmap_linear": ("linear", "nearest"),
    "trilinear": ("linear", "bilinear"),
    "anisotropic": ("linear", "bilinear"),
}


#: The most probes ``anisotropic`` takes (GL's ``MAX_TEXTURE_MAX_ANISOTROPY``, 16 on llvmpipe
#: and on most GPUs): a larger ``max_anisotropy`` is clamped to it, as GL clamps the parameter.
MAX_ANISOTROPY = 16

#: How far below an integer the ratio P_max / P_min may lie and still count as that integer
#: of probes (relative, in units of float64's epsilon): a face-on square's two axes, each
#: from differences of interpolated uv across one pixel, differ by rounding alone, about
#: epsilon times the image's width in pixels (118 epsilon measured on a 512-pixel-wide
#: face-on square), and the ceiling must not turn that into a second probe. 4096 epsilon
#: (9e-13) keeps a millionth of a real stretch a second probe.
ANISOTROPY_ROUNDING = 4096 * np.finfo(float).eps


def _as_derivative(name: str, value) -> np.ndarray:
    arr = as_real(name, value)  # NaN passes: an uncovered pixel's derivative
    if np.asarray(value).dtype.kind == "b":
        raise TypeError(f"{name} must be numeric (real numbers), got booleans")
    if arr.ndim < 1 or arr.shape[-1] < 2:
        raise ValueError(
            f"{name} must have shape (..., k) with k >= 2 (its first two channels are the "
            f"derivatives of u and v), got {arr.shape}"
        )
    return arr[..., :2]


def footprint_axes(ddx, ddy, texture_shape) -> tuple[np.ndarray, np.ndarray]:
    """Lengths in texels of the footprint's two axes, ``‖∂(uW, vH)/∂x‖`` and ``…/∂y``."""
    h, w = texture_size(texture_shape, "texture_shape")
    dx, dy = _as_derivative("ddx", ddx), _as_derivative("ddy", ddy)
    if dx.shape != dy.shape:
        raise ValueError(f"ddx and ddy must have the same shape, got {dx.shape} and {dy.shape}")
    with np.errstate(over="ignore"):  # inf only where the true length overflows
        return np.hypot(dx[..., 0] * w, dx[..., 1] * h), np.hypot(dy[..., 0] * w, dy[..., 1] * h)


def log2_length(d: np.ndarray, w: int, h: int) -> np.ndarray:
    """``log2 ‖(d_u W, d_v H)‖``, i.e. ``½ log2 ((d_u W)² + (d_v H)²)``, for any ``d``.

    The squares are taken as they are where they cannot overflow or underflow (the GL
    formula, bit for bit), and in a power-of-two-scaled form elsewhere, so derivatives of
    1e±200 give their true λ instead of ±inf; ``inf`` for an infinite derivative, ``-inf``
    for a zero one, NaN for NaN.

    >>> float(log2_length(np.array([2.0**-600, 0.0]), 4, 4))
    -598.0
    >>> float(log2_length(np.array([1e200, 0.0]), 1, 1)) == float(np.log2(1e200))
    True
    """
    with np.errstate(all="ignore"):
        out = 0.5 * np.log2((d[..., 0] * w) ** 2 + (d[..., 1] * h) ** 2)
        big = np.maximum(np.abs(d[..., 0]), np.abs(d[..., 1]))
        # Outside about 2**±480 a square (times W² ≤ 2**62) may leave the float range.
        far = np.isfinite(big) & (big > 0) & ((big > 2.0**480) | (big < 2.0**-480))
        if far.any():
            _, e = np.frexp(big[far])
            su, sv = np.ldexp(d[..., 0][far], -e) * w, np.ldexp(d[..., 1][far], -e) * h
            out = np.array(out, dtype=np.float64)
            out[far] = 0.5 * np.log2(su * su + sv * sv) + e
    return out


def mip_level(ddx, ddy, texture_shape) -> np.ndarray:
    """The level of detail λ = log2 ρ per pixel, unclamped (the GL formula).

    Parameters
    ----------
    ddx, ddy : (..., k) array-like, k >= 2
        Screen-space derivatives (per pixel step right, per pixel step down); channels 0
        and 1 are ``u`` and ``v`` (e.g. ``frame.ddx`` of a render with ``attrs=uv``).
    texture_shape : tuple
        ``(H, W)`` or ``(H, W, C)`` of level 0, e.g. ``texture.shape``.

    Returns
    -------
    (...) float64
        λ; ≤ 0 where the texture is magnified, ``-inf`` where it does not change at all,
        NaN where a derivative is NaN (an uncovered pixel).

    Examples
    --------
    >>> mip_level([[1 / 64, 0.0], [0.5, 0.5]], [[0.0, 1 / 64], [0.0, 0.0]], (64, 64))
    array([0. , 5.5])
    """
    h, w = texture_size(texture_shape, "texture_shape")
    dx, dy = _as_derivative("ddx", ddx), _as_derivative("ddy", ddy)
    if dx.shape != dy.shape:
        raise ValueError(f"ddx and ddy must have the same shape, got {dx.shape} and {dy.shape}")
    # log2 of the longer axis. Squared lengths would overflow for derivatives near 1e200
    # (and underflow near 1e-200): each length is taken in a power-of-two-scaled form.
    return np.maximum(log2_length(dx, w, h), log2_length(dy, w, h))


def nearest_level(lam: np.ndarray, q: int) -> np.ndarray:
    """GL's nearest mip level: 0 if λ ≤ ½, else ⌈λ + ½⌉ − 1, clamped to 0 … q (intp).

    >>> nearest_level(np.array([-3.0, 0.5, 0.51, 1.5, 1.51, 40.0]), 4)
    array([0, 0, 1, 1, 2, 4])
    """
    level = np.where(lam <= 0.5, 0.0, np.ceil(lam + 0.5) - 1)
    return np.clip(level, 0, q).astype(np.intp)


def linear_levels(lam: np.ndarray, q: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The two levels ⌊λ⌋ and ⌊λ⌋ + 1 and the blend weight λ − ⌊λ⌋, λ clamped to 0 … q.

    >>> linear_levels(np.array([-1.0, 0.25, 2.5, 9.0]), 3)
    (array([0, 0, 2, 3]), array([1, 1, 3, 3]), array([0.  , 0.25, 0.5 , 0.  ]))
    """
    clamped = np.clip(lam, 0, q)
    d1 = np.floor(clamped)
    return d1.astype(np.intp), np.minimum(d1 + 1, q).astype(np.intp), clamped - d1


def sample_levels(levels, u, v, lam, how: str, within: str, wrap: str, table=None) -> np.ndarray:
    """Mipmapped sampling at finite ``u``, ``v``, ``lam`` (n,): an (n, C) array.

    ``how`` is ``"nearest"`` (one level, :func:`nearest_level`) or ``"linear"`` (two levels,
    :func:`linear_levels`); ``within`` is the filter inside a level. ``table`` is
    ``level_table(levels)`` when the caller has it already.
    """
    q = len(levels) - 1
    table, offset, height, width = level_table(levels) if table is None else table

    def read(level, sel=None):
        uu, vv = (u, v) if sel is None else (u[sel], v[sel])
        return filtered(table, offset[level], height[level], width[level], uu, vv, within, wrap)

    # All pixels in one pass each, every pixel at its own level (as a GPU's texture unit
    # reads only the levels each pixel needs).
    if how == "nearest":
        return read(nearest_level(lam, q))
    first, second, t = linear_levels(lam, q)
    out = read(first)
    blend = np.flatnonzero(t > 0)  # magnified or clamped pixels read one level only
    if len(blend):
        upper = read(second[blend], blend)
        out[blend] += t[blend, None] * (upper - out[blend])
    return out


def anisotropic_probes(dx, dy, w: int, h: int, max_anisotropy) -> tuple:
    """EXT_texture_filter_anisotropic's probes for derivatives ``dx``, ``dy`` (n, 2) of a
    ``w`` × ``h`` level 0: (their number N (n,), their level of detail λ' = log2(P_max / N)
    (n,), the major axis (n, 2)), with N clamped to ``max_anisotropy`` and
    :data:`MAX_ANISOTROPY`, and one probe where the footprint is magnified (P_max ≤ 1)."""
    with np.errstate(over="ignore"):  # inf only where the true length overflows
        px, py = np.hypot(dx[:, 0] * w, dx[:, 1] * h), np.hypot(dy[:, 0] * w, dy[:, 1] * h)
    pmax, pmin = np.maximum(px, py), np.minimum(px, py)
    major = np.where((px >= py)[:, None], dx, dy)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # ⌈P_max / P_min⌉, blind to rounding noise: a ratio of 1 + 8e-15 is 1 probe, not 2
        ratio = np.ceil(pmax / pmin * (1.0 - ANISOTROPY_ROUNDING))
    # pmin = 0 is infinitely anisotropic. Where the texture is magnified (pmax <= 1, λ <= 0)
    # there is nothing to average: one probe at the centre, i.e. bilinear on level 0. The
    # probe count is clamped to MAX_ANISOTROPY whatever max_anisotropy asks (GL clamps it).
    cap = min(max_anisotropy, MAX_ANISOTROPY)
    n = np.where(pmax <= 1, 1, np.fmin(np.nan_to_num(ratio, nan=cap), cap))
    n = np.maximum(n, 1).astype(np.intp)
    with np.errstate(divide="ignore", invalid="ignore"):
        lam = np.log2(pmax / n)
    # Lengths that underflowed or overflowed in the product above: λ from the scaled form.
    odd = (pmax == 0) | np.isinf(pmax)
    if odd.any():
        lam[odd] = np.maximum(log2_length(dx[odd], w, h), log2_length(dy[odd], w, h)) - np.log2(
            n[odd]
        )
    return n, lam, major


def sample_anisotropic(levels, u, v, dx, dy, max_anisotropy, wrap) -> np.ndarray:
    """EXT_texture_filter_anisotropic at finite ``u``, ``v`` (n,) with derivatives (n, 2)."""
    h, w = levels[0].shape[:2]
    n, lam, major = anisotropic_probes(dx, dy, w, h, max_anisotropy)
    return sample_probes(levels, u, v, n, lam, major, wrap)


def sample_probes(levels, u, v, n, lam, major, wrap) -> np.ndarray:
    """The mean of ``n`` (n,) trilinear probes at level of detail ``lam`` (n,), spaced along
    ``major`` (n, 2, in uv per pixel) as EXT_texture_filter_anisotropic places them. The
    probes' count and level are parameters: :func:`anisotropic_probes` gives GL's, and
    :mod:`teachraster.study.anisotropic_lod` Vulkan's, on the same probes."""
    # An infinite derivative has no finite probe offsets: its probes all sit at the centre,
    # on the smallest level (λ = inf), like every other filter's infinite footprint.
    major = np.where(np.isfinite(major), major, 0.0)
    table = level_table(levels)
    out = 0.0
    for i in range(1, int(n.max(initial=1)) + 1):
        # Probe i of N sits at i / (N + 1) - 1/2 along the major axis; pixels with fewer
        # probes than i add nothing (weight 0) this round.
        active = n >= i
        step = np.where(active, i / (n + 1) - 0.5, 0.0)[:, None] * major
        idx = np.flatnonzero(active)
        probe = np.zeros((len(u), levels[0].reshape(*levels[0].shape[:2], -1).shape[2]))
        probe[idx] = sample_levels(levels, u[idx] + step[idx, 0], v[idx] + step[idx, 1],
                                   lam[idx], "linear", "bilinear", wrap, table)  # fmt: skip
        out = out + probe
    return out / n[:, None]


@dataclass(frozen=True)
class LevelsRead:
    """The mip levels a filter reads at each pixel, as :func:`sample` decides them.

    Attributes
    ----------
    first, second : (...) float64
        The level read, and the level blended with it (``second == first`` where one level
        is read: the ``*_mipmap_nearest`` filters, a clamped or magnified λ, the unmipmapped
        ``nearest`` and ``bilinear``, which read level 0). NaN where λ is undefined.
    weight : (...) float64
        The weight of ``second``: λ − ⌊λ⌋ for the ``*_mipmap_linear`` filters and the
        probes of ``anisotropic``, 0 where one level is read.
    probes : (...) intp
        Probes per pixel: N for ``anisotropic``, 1 for the others.
    lod : (...) float64
        The λ the levels come from: the pixel's λ, or the probes' λ' = log2(P_max / N).
    """

    first: np.ndarray
    second: np.ndarray
    weight: np.ndarray
    probes: np.ndarray
    lod: np.ndarray


def levels_read(filter: str, ddx, ddy, texture_shape, max_anisotropy=MAX_ANISOTROPY) -> LevelsRead:  # noqa: A002
    """Which mip level(s) ``filter`` reads at each pixel, with which weights (one rule with
    :func:`teachraster.sample`: the same level choice, the same probes).

    Parameters
    ----------
    filter : str
        ``"nearest"``, ``"bilinear"`` or a key of :data:`MIPMAP_FILTERS`.
    ddx, ddy : (..., k) array-like, k >= 2
        Screen-space derivatives of ``(u, v)``, as for :func:`mip_level`.
    texture_shape : tuple
        ``(H, W)`` or ``(H, W, C)`` of level 0.
    max_anisotropy : number
        As for :func:`teachraster.sample` (clamped to :data:`MAX_ANISOTROPY`).

    Returns
    -------
    LevelsRead

    Examples
    --------
    >>> r = levels_read("trilinear", [[0.375, 0.0]], [[0.0, 0.25]], (8, 8))  # ρ = 3 texels
    >>> r.first.tolist(), r.second.tolist(), round(float(r.weight[0]), 3)
    ([1.0], [2.0], 0.585)
    >>> r = levels_read("anisotropic", [[0.375, 0.0]], [[0.0, 0.25]], (8, 8))  # 3 by 2 texels
    >>> r.probes.tolist(), r.first.tolist(), r.second.tolist()   # 2 probes: λ' = log2(3 / 2)
    ([2], [0.0], [1.0])
    """
    if filter not in ("nearest", "bilinear") and filter not in MIPMAP_FILTERS:
        raise ValueError(f"filter must be 'nearest', 'bilinear' or one of "
                         f"{sorted(MIPMAP_FILTERS)}, got {filter!r}")  # fmt: skip
    h, w = texture_size(texture_shape, "texture_shape")
    q = len(level_sizes(h, w)) - 1
    lam = mip_level(ddx, ddy, texture_shape)
    probes = np.ones(lam.shape, dtype=np.intp)
    if filter == "anisotropic":
        dx, dy = _as_derivative("ddx", ddx), _as_derivative("ddy", ddy)
        ok = ~np.isnan(lam)
        n, lam_probe, _ = anisotropic_probes(dx[ok], dy[ok], w, h, max_anisotropy)
        probes[ok], lam = n, np.where(ok, np.nan, lam)
        lam[ok] = lam_probe
    undefined = np.isnan(lam)
    finite = np.nan_to_num(lam, nan=0.0)
    if filter in ("nearest", "bilinear"):  # no mipmaps: level 0
        first = second = np.zeros(lam.shape, dtype=np.intp)
        weight = np.zeros(lam.shape)
    elif MIPMAP_FILTERS[filter][0] == "nearest":
        first = second = nearest_level(finite, q)
        weight = np.zeros(lam.shape)
    else:
        first, second, weight = linear_levels(finite, q)
        second = np.where(weight > 0, second, first)  # a weight of 0 reads one level
    nan = np.where(undefined, np.nan, 0.0)
    return LevelsRead(first + nan, second + nan, weight + nan, probes, lam)
