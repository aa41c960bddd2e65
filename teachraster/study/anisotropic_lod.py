"""The anisotropic level of detail without the ceiling: Vulkan's and Direct3D's (lesson 09, §6).

The package's sampler (:func:`teachraster.sample`, ``filter="anisotropic"``) follows the one
formula GL writes down, ``ARB_texture_filter_anisotropic``'s "one particular approach":
``N = min(⌈P_max / P_min⌉, maxAniso)`` probes, each at ``λ' = log2(P_max / N)``, a level
taken from the rounded-up count. Two other standards take the level from the ratio itself:

- Vulkan (chapter *Image Operations*, *Scale Factor Operation* and *LOD Operation*):
  ``η = min(ρ_max / ρ_min, maxAniso)``, ``N = ⌈η⌉`` samples, ``λ_base = log2(ρ_max / η)``;
  "an implementation may use the value of N as an approximation of η", which is GL's formula.
- Direct3D 11.3 (§7.18.11, *LOD Calculations*): ``ratioOfAnisotropy = major² / |det J|``,
  clamped to ``MaxAnisotropy``, and ``LOD = log2(minor)`` with ``minor = |det J| / major``
  (``major / MaxAnisotropy`` where the ratio is clamped): the parallelogram's width across
  its longer side, not the shorter derivative vector. (Its later clamp, which raises the
  ratio where ``minor < 1``, is left out: it changes no probe's level.)

Where the two derivative vectors are perpendicular the two agree. :func:`continuous_probes`
gives either, :func:`sample_continuous` samples with it on the engine's own probes
(:func:`~teachraster.pipeline.texturing.texture_filters.sample_probes`: the same places
along the major axis, ``i / (N + 1) - ½``, the count and level the only parameters), so that
the lesson can set each standard's formula beside GL's on one footprint. Where the footprint
is magnified Vulkan still counts ``N = ⌈η⌉`` (it lets an implementation take fewer); each
probe then reads level 0.
"""

from __future__ import annotations

import numpy as np

from ..pipeline.texturing.mip_pyramid import as_pyramid
from ..pipeline.texturing.texel_fetch import as_uv, texture_size
from ..pipeline.texturing.texture_filters import MAX_ANISOTROPY, sample_probes

#: How the shorter scale factor is measured: Vulkan's ρ_min (the shorter derivative
#: vector's length) or Direct3D 11.3's minor (|det J| / major).
MINORS = ("lengths", "area")


def continuous_probes(ddx, ddy, texture_shape, max_anisotropy=MAX_ANISOTROPY,
                      minor: str = "lengths"):  # fmt: skip
    """Vulkan's (``minor="lengths"``) or Direct3D's (``"area"``) anisotropic probes.

    Parameters
    ----------
    ddx, ddy : (n, k) array-like, k >= 2
        Screen-space derivatives of ``(u, v)``; channels 0 and 1 are used.
    texture_shape : tuple
        ``(H, W)`` or ``(H, W, C)`` of level 0.
    max_anisotropy : number
        The sampler's cap (``maxAnisotropy``, ``MaxAnisotropy``), clamped to the device's
        :data:`~teachraster.pipeline.texturing.texture_filters.MAX_ANISOTROPY`.
    minor : {"lengths", "area"}

    Returns
    -------
    n : (n,) intp
        ``⌈η⌉``, η the ratio of anisotropy clamped to the cap (1 for a point footprint).
    lam : (n,) float64
        ``log2(ρ_max / η)``: not rounded with ``n``.
    major : (n, 2) float64
        The longer derivative vector (uv per pixel), along which the probes lie.

    Examples
    --------
    >>> n, lam, _ = continuous_probes([[8.000008 / 64, 0]], [[0, 8 / 64]], (64, 64))
    >>> n.tolist(), round(float(lam[0]), 9)     # two probes, trilinear's level: log2 8
    ([2], 3.0)
    """
    if minor not in MINORS:
        raise ValueError(f"minor must be one of {MINORS}, got {minor!r}")
    h, w = texture_size(texture_shape, "texture_shape")
    scale = np.array([w, h], dtype=float)
    dx = np.asarray(ddx, float).reshape(-1, np.shape(ddx)[-1])[:, :2]
    dy = np.asarray(ddy, float).reshape(-1, np.shape(ddy)[-1])[:, :2]
    px, py = np.hypot(*(dx * scale).T), np.hypot(*(dy * scale).T)
    rho_max = np.maximum(px, py)
    if minor == "lengths":
        rho_min = np.minimum(px, py)
    else:
        det = np.abs((dx[:, 0] * dy[:, 1] - dx[:, 1] * dy[:, 0]) * w * h)
        with np.errstate(invalid="ignore", divide="ignore"):
            rho_min = np.where(rho_max > 0, det / rho_max, 0.0)
    cap = min(float(max_anisotropy), MAX_ANISOTROPY)
    with np.errstate(invalid="ignore", divide="ignore"):
        # a line (ρ_min = 0) is as anisotropic as allowed, a point (both 0) isotropic
        eta = np.where(rho_max == 0, 1.0, np.minimum(rho_max / rho_min, cap))
        lam = np.log2(rho_max / eta)
    major = np.where((px >= py)[:, None], dx, dy)
    return np.ceil(eta).astype(np.intp), lam, major


def sample_continuous(texture, uv, ddx, ddy, max_anisotropy=MAX_ANISOTROPY,
                      minor: str = "lengths", wrap: str = "repeat") -> np.ndarray:  # fmt: skip
    """Anisotropic filtering with :func:`continuous_probes`' count and level.

    Parameters
    ----------
    texture : array or list of arrays
        A texture (its pyramid is built) or a pyramid, as for :func:`teachraster.sample`.
    uv : (n, 2) array-like
        Texture coordinates, finite.
    ddx, ddy, max_anisotropy, minor
        As for :func:`continuous_probes`.
    wrap : {"repeat", "clamp"}

    Returns
    -------
    (n,) or (n, C) float64
        As :func:`teachraster.sample` returns: one value per point, or C channels.

    Examples
    --------
    >>> tex = np.arange(16.0).reshape(4, 4)      # a ramp: the probes' mean is its centre
    >>> sample_continuous(tex, [[0.5, 0.5]], [[0.5, 0]], [[0, 0.25]]).round(6).tolist()
    [7.5]
    """
    levels = as_pyramid(texture)
    uv = as_uv("uv", uv).reshape(-1, 2)
    h, w = levels[0].shape[:2]
    n, lam, major = continuous_probes(ddx, ddy, (h, w), max_anisotropy, minor)
    values = sample_probes(levels, uv[:, 0], uv[:, 1], n, lam, major, wrap)
    return values.reshape((len(uv),) + levels[0].shape[2:])
