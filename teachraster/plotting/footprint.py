"""A pixel's footprint drawn in texture space, with what each filter reads of it (lesson 09).

The pixel square maps onto the texture, to first order, as the parallelogram spanned by the
two derivative vectors ``∂(uW, vH)/∂x`` and ``∂(uW, vH)/∂y`` (texels per pixel step), and the
ellipse inscribed in it has those two vectors (halved) as conjugate semi-diameters. Beside it:

- the square of side ρ = max of the two lengths: what an isotropic filter (trilinear) averages,
  at level λ = log2 ρ, which covers the long axis and blurs across the short one (where
  λ ≤ 0, magnified, trilinear is one bilinear read of level 0: its 2 × 2 texels instead);
- the ``N`` anisotropic probes of ``EXT_texture_filter_anisotropic``, spaced along the major
  axis at ``i / (N + 1) − ½`` (i = 1 … N), each a square of side ``P_max / N`` (their level
  ``log2(P_max / N)``), as :func:`teachraster.pipeline.texture_filters.sample_anisotropic`
  places them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.colors import to_rgba
from matplotlib.patches import Polygon, Rectangle

from .style import COLORS, OKABE_ITO

#: The second shade of the anisotropic probes, their outlines and centres: a darker bluish
#: green, told from the first on a projector.
PROBE_DARK = "#005A45"


@dataclass(frozen=True)
class Footprint:
    """The numbers the figure shows for one pixel (lengths in texels of level 0)."""

    centre: np.ndarray  # (2,) texel coordinates (u W, v H)
    axis_x: np.ndarray  # ∂(uW, vH)/∂x
    axis_y: np.ndarray  # ∂(uW, vH)/∂y
    rho: float
    lam: float
    probes: int
    probe_lam: float
    probe_centres: np.ndarray  # (N, 2)
    #: where trilinear is one bilinear read of level 0 (magnified, λ ≤ 0): the first of the
    #: 2 × 2 texels it reads, (column, row) in texels of level 0 (unwrapped); else None
    bilinear: np.ndarray | None = None

    @property
    def extents(self) -> tuple[float, float]:
        """The lengths of the two derivative vectors, ``|axis_x|`` and ``|axis_y|``: GL's
        ``P_x`` and ``P_y`` (``EXT_texture_filter_anisotropic``), from which ρ and the
        anisotropic probes are counted."""
        return float(np.hypot(*self.axis_x)), float(np.hypot(*self.axis_y))

    @property
    def ellipse_axes(self) -> tuple[float, float]:
        """The footprint ellipse's two principal axes (whole lengths, the longer first): the
        singular values of the matrix whose columns are ``axis_x`` and ``axis_y``. They are
        :attr:`extents` only where the two derivative vectors are perpendicular; on a
        sheared footprint the ellipse is longer and thinner than the extents say."""
        major, minor = np.linalg.svd(np.column_stack([self.axis_x, self.axis_y]),
                                     compute_uv=False)  # fmt: skip
        return float(major), float(minor)


def footprint(uv, ddx, ddy, texture_shape, max_anisotropy: int = 16) -> Footprint:
    """The footprint of one pixel with texture coordinate ``uv`` and derivatives ``ddx``, ``ddy``.

    >>> f = footprint([0.5, 0.5], [8 / 64, 0.0], [0.0, 1 / 64], (64, 64))
    >>> f.rho, f.lam, f.probes, f.probe_lam
    (8.0, 3.0, 8, 0.0)
    """
    from ..pipeline.texturing.mip_pyramid import level_sizes
    from ..pipeline.texturing.texel_fetch import bilinear_corner
    from ..pipeline.texturing.texture_filters import anisotropic_probes, linear_levels

    h, w = texture_shape[:2]
    scale = np.array([w, h], dtype=float)
    ax_, ay_ = np.asarray(ddx, float)[:2] * scale, np.asarray(ddy, float)[:2] * scale
    rho = float(max(np.hypot(*ax_), np.hypot(*ay_)))
    # the probes as the sampler places them (one rule: the engine's)
    n, probe_lam, major = anisotropic_probes(np.asarray(ddx, float)[None, :2],
                                             np.asarray(ddy, float)[None, :2], w, h,
                                             max_anisotropy)  # fmt: skip
    n = int(n[0])
    centre = np.asarray(uv, float)[:2] * scale
    offsets = np.array([i / (n + 1) - 0.5 for i in range(1, n + 1)])
    lam = float(np.log2(rho))
    # the levels trilinear reads, and the texels of a bilinear read, as the sampler takes them
    first, _, weight = linear_levels(np.array([lam]), len(level_sizes(h, w)) - 1)
    bilinear = None
    if first[0] == 0 and weight[0] == 0:  # one read of level 0: its 2 × 2 texels
        u, v = np.asarray(uv, float)[:2]
        x0, y0, _, _ = bilinear_corner(np.array([u]), np.array([v]), h, w)
        bilinear = np.array([x0[0], y0[0]])
    return Footprint(centre, ax_, ay_, rho, lam, n, float(probe_lam[0]),
                     centre + offsets[:, None] * (major[0] * scale), bilinear)  # fmt: skip


def plot_footprint(ax, fp: Footprint, texture=None, *, margin: float = 1.2, legend: bool = True,
                   centred: bool = True):  # fmt: skip
    """Draw ``fp`` in texels of level 0, over ``texture`` (wrapped) if given.

    ``centred``: coordinates relative to the pixel's centre in the texture (0 at the
    centre), so that the ticks read as sizes; else absolute texel coordinates (for a texture
    repeated many times, numbers like 1003.75 that say nothing). Where a single probe is
    taken it is trilinear's square: filled, under trilinear's outline. Where trilinear is one
    bilinear read of level 0 (``fp.bilinear``: magnified), what it reads is drawn instead of
    the square of side ρ: the 2 × 2 texels of that read, dashed (and filled: the one probe).

    Returns the dict of artists: ``parallelogram``, ``ellipse``, ``square``, ``probes`` (the
    centres), ``dots`` (drawn at them, over everything).
    """
    a, b = fp.axis_x, fp.axis_y
    shift = fp.centre if centred else np.zeros(2)
    c = fp.centre - shift
    corners = c + np.array([-a - b, a - b, a + b, -a + b]) / 2
    # what trilinear reads: the square of side ρ at level λ, or where it is one bilinear read
    # of level 0 (magnified) the 2 × 2 texels of that read, drawn dashed
    if fp.bilinear is None:
        read_lo, read_side = c - fp.rho / 2, fp.rho
    else:
        read_lo, read_side = fp.bilinear - shift, 2.0
    reach = np.abs(np.vstack([read_lo, read_lo + read_side]) - c).max()
    half = max(np.abs(corners - c).max(), fp.rho / 2, reach) * margin
    lo, hi = c - half, c + half
    if texture is not None:
        tex = np.asarray(texture)
        th, tw = tex.shape[:2]
        cols = np.arange(np.floor(lo[0] + shift[0]), np.ceil(hi[0] + shift[0])).astype(int)
        rows = np.arange(np.floor(lo[1] + shift[1]), np.ceil(hi[1] + shift[1])).astype(int)
        if len(cols) * len(rows) <= 512 * 512:  # a readable window of texels
            patch = tex[np.ix_(rows % th, cols % tw)]
            extent = (cols[0] - shift[0], cols[-1] + 1 - shift[0], rows[-1] + 1 - shift[1],
                      rows[0] - shift[1])  # fmt: skip
            ax.imshow(patch, extent=extent, cmap="gray", vmin=0, vmax=1, alpha=0.45,
                      interpolation="nearest")  # fmt: skip
    art = {}
    art["parallelogram"] = ax.add_patch(Polygon(corners, closed=True, fill=False, lw=2,
                                                ls="--", ec=COLORS["edge"],
                                                label="pixel square, mapped"))  # fmt: skip
    t = np.linspace(0, 2 * np.pi, 200)
    ell = c + (np.outer(np.cos(t), a) + np.outer(np.sin(t), b)) / 2
    (art["ellipse"],) = ax.plot(*ell.T, color=OKABE_ITO["blue"], lw=3,
                                label="footprint ellipse")  # fmt: skip
    label = (f"trilinear: ρ = {fp.rho:.2f}, λ = {fp.lam:.2f}" if fp.bilinear is None else
             f"trilinear (λ = {fp.lam:.2f} ≤ 0): bilinear, 2 × 2 texels of level 0")  # fmt: skip
    art["square"] = ax.add_patch(Rectangle(read_lo, read_side, read_side, fill=False, lw=2.5,
                                           ls="-" if fp.bilinear is None else "--",
                                           ec=OKABE_ITO["orange"], zorder=3, label=label))  # fmt: skip
    side = fp.rho / fp.probes
    probes = fp.probe_centres - shift
    if fp.bilinear is not None:  # magnified: the one probe is the same bilinear read
        probes, side = read_lo[None, :] + 1.0, 2.0
    # Overlapping probes (spaced P_max / (N + 1), each P_max / N wide) merged into one band:
    # two shades in turn, each outlined, and a dot at each centre, so that they can be
    # counted. One probe is trilinear's own read: filled only, its outline would hide the
    # orange; its dot is drawn too, over everything (review r336 S4: the near panel's one
    # probe had no dot, and the ellipse's line would have covered one drawn under it).
    green = OKABE_ITO["bluish_green"]
    for k, p in enumerate(probes):
        face = to_rgba(green if k % 2 == 0 else PROBE_DARK, 0.35)
        edge = "none" if len(probes) == 1 else to_rgba(PROBE_DARK, 0.9)
        ax.add_patch(Rectangle(p - side / 2, side, side, fill=True, lw=1.2, ec=edge, fc=face,
                               zorder=2,
                               label=(f"{fp.probes} anisotropic probes, λ = {fp.probe_lam:.1f}"
                                      if k == 0 else None)))  # fmt: skip
    # at the probes' own centres (a magnified pixel's one read: its sample point, not the
    # 2 x 2 texels' middle), over the ellipse and the squares' outlines
    (art["dots"],) = ax.plot(*np.asarray(fp.probe_centres - shift).T, "o",
                             ms=4 if len(probes) > 1 else 6, color=PROBE_DARK, mec="white",
                             mew=0.8, zorder=6)  # fmt: skip
    art["probes"] = fp.probe_centres
    what = "texels from the centre" if centred else "texels"
    ax.set(xlim=(lo[0], hi[0]), ylim=(hi[1], lo[1]), aspect="equal",
           xlabel=f"u · W ({what})", ylabel=f"v · H ({what})")  # fmt: skip
    if legend:
        ax.legend(loc="upper left", fontsize=11, framealpha=0.9)
    return art


def footprint_contains(uv, ddx, ddy, texture_shape, point) -> np.ndarray:
    """Which pixels' footprint ellipses (as :func:`plot_footprint` draws them) hold ``point``.

    The ellipse of a pixel has the derivative vectors (halved, in texels) as conjugate
    semi-diameters: ``c + (cos t · a + sin t · b) / 2``; ``point`` (texels of level 0) lies in
    it when ``2 (point - c) = s a + t b`` has ``s² + t² <= 1``. Pixels with a NaN
    coordinate (not covered) or a degenerate footprint hold nothing.

    Parameters
    ----------
    uv, ddx, ddy : (..., k) array-like, k >= 2
        Texture coordinates and their screen-space derivatives per pixel.
    texture_shape : tuple
        ``(H, W)`` or ``(H, W, C)`` of level 0.
    point : (2,) array-like
        A point in texels of level 0, ``(u W, v H)``.

    Returns
    -------
    (...) bool

    Examples
    --------
    >>> footprint_contains([[0.5, 0.5]], [[4 / 64, 0]], [[0, 2 / 64]], (64, 64), [33.9, 32.0])
    array([ True])
    """
    h, w = texture_shape[:2]
    scale = np.array([w, h], dtype=float)
    c = np.asarray(uv, float)[..., :2] * scale
    a = np.asarray(ddx, float)[..., :2] * scale
    b = np.asarray(ddy, float)[..., :2] * scale
    r = 2.0 * (np.asarray(point, float) - c)
    det = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        s = (r[..., 0] * b[..., 1] - r[..., 1] * b[..., 0]) / det
        t = (a[..., 0] * r[..., 1] - a[..., 1] * r[..., 0]) / det
        return (det != 0) & (s * s + t * t <= 1.0)


def trilinear_reads(uv, ddx, ddy, texture_shape, point) -> np.ndarray:
    """Which pixels' trilinear filter fetches a texel holding ``point`` (texels of level 0).

    A pixel reads, at each level L it uses (⌊λ⌋, and ⌊λ⌋ + 1 where the blend weight is not
    0; level 0 where the texture is magnified), the 2 × 2 texels around ``u W_L - ½``,
    ``v H_L - ½`` (:func:`teachraster.pipeline.texturing.texel_fetch.filtered`); a texel of
    level L covers ``2**L`` texels of level 0 each way. Positions are unwrapped: the floor's
    repeats are told apart.

    Examples
    --------
    >>> trilinear_reads([[0.5, 0.5]], [[1 / 64, 0]], [[0, 1 / 64]], (64, 64), [31.2, 32.9])
    array([ True])
    """
    from ..pipeline.texturing.mip_pyramid import level_sizes
    from ..pipeline.texturing.texture_filters import linear_levels, mip_level

    h, w = texture_shape[:2]
    q = len(level_sizes(h, w)) - 1
    uv = np.asarray(uv, float)[..., :2]
    lam = mip_level(ddx, ddy, texture_shape)
    first, second, t = linear_levels(np.nan_to_num(lam, nan=0.0), q)
    p = np.asarray(point, float)
    out = np.zeros(uv.shape[:-1], dtype=bool)
    for level, use in ((first, np.ones_like(t, bool)), (second, t > 0)):
        size = 2.0**level
        x0 = np.floor(uv[..., 0] * (w / size) - 0.5)  # the level's width is w / 2**L
        y0 = np.floor(uv[..., 1] * (h / size) - 0.5)
        inside = ((p[0] >= x0 * size) & (p[0] < (x0 + 2) * size)
                  & (p[1] >= y0 * size) & (p[1] < (y0 + 2) * size))  # fmt: skip
        out |= use & inside
    return out & np.isfinite(uv).all(axis=-1)
