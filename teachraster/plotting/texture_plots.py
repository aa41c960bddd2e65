"""Texture filtering plots: 2×2 quads and helper pixels, the level-of-detail map, the mip
pyramid, and filters side by side with their error against the true footprint average.

Every function draws on the Axes it is given (a row of Axes for the comparison) and returns
an :class:`~.common.Artists` dataclass, as everywhere in :mod:`teachraster.plotting`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from matplotlib.cm import ScalarMappable
from matplotlib.collections import LineCollection, PatchCollection
from matplotlib.colors import (
    BoundaryNorm,
    LinearSegmentedColormap,
    ListedColormap,
    Normalize,
    to_rgba,
)
from matplotlib.patches import Rectangle

from ..pipeline.rendering.render_triangles import Frame
from ..pipeline.texturing.texture_filters import LevelsRead, nearest_level
from .common import Artists, bar_in, fs, lw, pixel_axes, rgba_image, set_image, show_image
from .style import ERROR_CMAP, OKABE_ITO

#: One colour per triangle in quad plots, and one per mip level in LOD maps (levels beyond
#: the palette repeat it).
TRIANGLE_COLORS = [OKABE_ITO[k] for k in ("blue", "orange", "bluish_green", "reddish_purple")]
LEVEL_COLORS = [
    "#0072B2", "#56B4E9", "#009E73", "#F0E442", "#E69F00", "#D55E00", "#CC79A7",
    "#999999", "#000000", "#7F3C8D", "#11A579", "#3969AC", "#F2B701",
]  # fmt: skip


# -- quads and helper pixels -------------------------------------------------------------------
@dataclass
class QuadArtists(Artists):
    """Shaded pixels (filled, one colour per triangle), helper pixels (dashed, inset),
    the quads' outlines and the triangles' edges."""

    shaded: PatchCollection
    helpers: PatchCollection
    outlines: LineCollection
    edges: LineCollection
    n_quads: int = 0
    n_helpers: int = 0


def plot_quads(ax, frame: Frame, *, grid: bool = True) -> QuadArtists:
    """The 2×2 quads ``render`` evaluated for derivatives, over the pixel grid.

    Parameters
    ----------
    ax : matplotlib Axes
    frame : Frame
        From ``tr.render(..., derivatives=True, trace=True)``.
    grid : bool
        Set the Axes up as pixel axes of the frame's size.

    Returns
    -------
    QuadArtists
        Pixels a triangle shows are filled in its colour; its helper pixels (evaluated
        on its interpolation for the differences, never written) are dashed squares inset
        in the same colour, so a quad straddling two triangles shows both sets.
    """
    trace = frame.trace
    if trace is None or trace.quads is None:
        raise ValueError("plot_quads needs tr.render(..., derivatives=True, trace=True)")
    q = trace.quads
    height, width = frame.triangle_id.shape
    if grid:
        pixel_axes(ax, width, height)
    lanes = [(0, 0), (1, 0), (0, 1), (1, 1)]
    shaded, helpers, shaded_c, helper_c = [], [], [], []
    for i in range(len(q.row)):
        colour = TRIANGLE_COLORS[int(q.triangle[i]) % len(TRIANGLE_COLORS)]
        inset = 0.14 + 0.08 * (int(q.triangle[i]) % 2)  # two triangles' helpers stay apart
        for lane, (dc, dr) in enumerate(lanes):
            x, y = q.col[i] + dc, q.row[i] + dr
            if q.shaded[i, lane]:
                shaded.append(Rectangle((x, y), 1, 1))
                shaded_c.append(colour)
            else:
                helpers.append(Rectangle((x + inset, y + inset), 1 - 2 * inset, 1 - 2 * inset))
                helper_c.append(colour)
    shaded_pc = PatchCollection(shaded, facecolors=shaded_c, edgecolors="none", alpha=0.45,
                                zorder=1)  # fmt: skip
    helper_pc = PatchCollection(helpers, facecolors="none", edgecolors=helper_c,
                                linestyles="--", linewidths=lw(0.5), zorder=3)  # fmt: skip
    boxes = [
        [(c, r), (c + 2, r), (c + 2, r + 2), (c, r + 2), (c, r)]
        for r, c in set(zip(q.row.tolist(), q.col.tolist()))
    ]
    outlines = LineCollection(boxes, colors="black", linewidths=lw(0.6), zorder=4)
    xy = trace.window[:, :, :2]
    edge_lines = LineCollection(
        [np.vstack([t, t[:1]]) for t in xy[~trace.culled]],
        colors="black", linewidths=lw(0.35), linestyles=":", zorder=5,
    )  # fmt: skip
    for coll in (shaded_pc, helper_pc, outlines, edge_lines):
        ax.add_collection(coll, autolim=False)
    return QuadArtists(shaded_pc, helper_pc, outlines, edge_lines, len(boxes), len(helpers))


# -- level of detail ---------------------------------------------------------------------------
@dataclass
class LodArtists(Artists):
    """The level map, its colour bar (one tick per level) and the number of levels."""

    image: object
    colorbar: object = None
    levels: int = 0

    def update(self, lam) -> None:
        """Show new λ values in the same image (same number of levels)."""
        self.image = set_image(self.image, level_image(lam, self.levels))


def level_image(lam, n_levels: int) -> np.ndarray:
    """(H, W) float: the level GL's nearest-mip rule picks from λ, NaN kept."""
    lam = np.asarray(lam, dtype=np.float64)
    level = nearest_level(np.nan_to_num(lam, nan=0.0, neginf=-1.0), n_levels - 1).astype(float)
    level[np.isnan(lam)] = np.nan
    return level


def plot_lod(ax, lam, n_levels: int | None = None, *, colorbar: bool = True,
             title: str | None = "mip level (GL nearest)") -> LodArtists:  # fmt: skip
    """The classic level-of-detail picture: one flat colour per mip level.

    Parameters
    ----------
    ax : matplotlib Axes
    lam : (H, W) array
        λ per pixel (``tr.mip_level``), NaN where uncovered (transparent).
    n_levels : int, optional
        Levels in the pyramid (default: enough for the largest λ); λ beyond is clamped.
    colorbar : bool
    title : str or None

    Returns
    -------
    LodArtists
        Pixels show the level GL's nearest-mip rule picks (0 if λ ≤ ½, else ⌈λ + ½⌉ − 1):
        bands whose borders are the seams of a nearest-mip filter.
    """
    lam = np.asarray(lam, dtype=np.float64)
    top = np.nanmax(lam) if np.isfinite(lam).any() else 0.0
    n = int(n_levels) if n_levels is not None else max(1, int(np.ceil(max(top, 0) + 0.5)) + 1)
    level = level_image(lam, n)
    colours = [LEVEL_COLORS[i % len(LEVEL_COLORS)] for i in range(n)]
    norm = BoundaryNorm(np.arange(n + 1) - 0.5, n)
    im = show_image(ax, level, cmap=ListedColormap(colours), norm=norm, zorder=0.5)
    cbar = None
    if colorbar:
        cbar = ax.figure.colorbar(im, ax=ax, shrink=0.85, ticks=np.arange(n), label="level")
    if title:
        ax.set_title(title)
    return LodArtists(im, cbar, n)


@dataclass
class LevelsReadArtists(Artists):
    """The levels-read map (an RGBA image), its colour bar (continuous, one tick per level)
    and the number of levels."""

    image: object
    colorbar: object = None
    levels: int = 0

    def update(self, read: LevelsRead) -> None:
        """Show what another filter (or tilt) reads in the same image."""
        self.image = set_image(self.image, levels_read_image(read, self.levels))


def levels_read_image(read: LevelsRead, n_levels: int) -> np.ndarray:
    """(H, W, 4) RGBA: each pixel in its level's colour, two levels' colours mixed by their
    weights where a filter blends them; transparent where nothing is read.

    The levels and weights are the engine's (:class:`LevelsRead`), only coloured here.
    """
    palette = np.array([to_rgba(LEVEL_COLORS[i % len(LEVEL_COLORS)]) for i in range(n_levels)])
    ok = ~np.isnan(read.first)
    rgba = np.zeros((*read.first.shape, 4))
    first = np.clip(read.first[ok].astype(np.intp), 0, n_levels - 1)
    second = np.clip(read.second[ok].astype(np.intp), 0, n_levels - 1)
    t = read.weight[ok][:, None]
    rgba[ok] = (1 - t) * palette[first] + t * palette[second]
    return rgba


def _levels_key(n_levels: int) -> ScalarMappable:
    """The level panel's colour key: a continuous bar through the levels' colours, each at
    its integer (a tick), mixed linearly between them as :func:`levels_read_image` mixes two
    blended levels, so that a blend's colour can be read off the bar as a fractional level
    (review r195 09-2: seven discrete swatches had no place for the blends' colours)."""
    colours = [LEVEL_COLORS[i % len(LEVEL_COLORS)] for i in range(n_levels)]
    if n_levels < 2:  # one level: one swatch
        return ScalarMappable(BoundaryNorm([-0.5, 0.5], 1), ListedColormap(colours))
    cmap = LinearSegmentedColormap.from_list("levels", colours, N=64 * (n_levels - 1) + 1)
    return ScalarMappable(Normalize(0, n_levels - 1), cmap)


def plot_levels_read(ax, read: LevelsRead, n_levels: int, *, colorbar: bool = True,
                     title: str | None = "mip level(s) read", cax=None) -> LevelsReadArtists:  # fmt: skip
    """The mip level(s) a filter reads at each pixel, as the engine decides them.

    Parameters
    ----------
    ax : matplotlib Axes
    read : LevelsRead
        From :func:`teachraster.pipeline.texturing.texture_filters.levels_read`.
    n_levels : int
        Levels in the pyramid (one colour, and one colour-bar tick, each).
    colorbar : bool
    title : str or None
    cax : matplotlib Axes, optional
        Where the colour bar goes (horizontal if ``cax`` is wider than tall); default:
        beside ``ax``, taken from its room.

    Returns
    -------
    LevelsReadArtists
        One flat colour per level where one level is read (the ``*_mipmap_nearest``
        filters: bands with sharp seams); a mix of ⌊λ⌋'s and ⌊λ⌋ + 1's colours in proportion
        to their weights where two are blended (the ``*_mipmap_linear`` filters and the
        probes of ``anisotropic``, at the probes' finer λ').
    """
    im = show_image(ax, levels_read_image(read, n_levels), zorder=0.5)
    cbar = None
    if colorbar:
        where = {"ax": ax, "shrink": 0.85} if cax is None else bar_in(cax)
        key = _levels_key(n_levels)
        cbar = ax.figure.colorbar(key, ticks=np.arange(n_levels), label="level", **where)
    if title:
        ax.set_title(title)
    return LevelsReadArtists(im, cbar, n_levels)


# -- the pyramid -------------------------------------------------------------------------------
@dataclass
class PyramidArtists(Artists):
    """One image per level, the labels, and the small levels' enlarged copies."""

    images: list = field(default_factory=list)
    labels: list = field(default_factory=list)
    enlarged: list = field(default_factory=list)


def plot_pyramid(ax, levels, *, gap: float = 0.04, zoom: int = 4) -> PyramidArtists:
    """A mip pyramid laid out the classic way: level 0, then each smaller level to its right,
    stacked top to bottom, all at the same texel scale; the levels too small to carry a label
    are drawn again ``zoom`` times larger in the corner beside them, each with its size.

    Parameters
    ----------
    ax : matplotlib Axes
    levels : list of (h, w) or (h, w, 3) arrays (``tr.mipmap(texture)``)
    gap : float
        Space between levels, as a fraction of level 0's width.
    zoom : int
        How much larger the small levels' second copies are drawn.
    """
    h0, w0 = levels[0].shape[:2]
    pad = gap * w0
    out = PyramidArtists()
    x, y = w0 + pad, 0.0
    small = []  # levels too small for a label of their own: drawn again, enlarged
    for i, lv in enumerate(levels):
        h, w = lv.shape[:2]
        x0, y0 = (0.0, 0.0) if i == 0 else (x, y)
        out.images.append(_level_image(ax, lv, x0, y0))
        if i == 0 or h * 8 >= h0:  # label the levels big enough to carry one
            label = f"{i}: {w}×{h}"
            if i == 0:  # below level 0; the others to their right, clear of the next level
                where = {"x": x0 + w / 2, "y": y0 + h + pad * 0.3, "ha": "center", "va": "top"}
            else:
                where = {"x": x0 + w + pad * 0.5, "y": y0 + h / 2, "ha": "left", "va": "center"}
            out.labels.append(ax.text(s=label, fontsize=fs(0.7), **where))
        else:
            small.append(i)
        if i > 0:
            y += h + pad * 1.2
    right, foot = x + w0 * 0.95, max(h0 + 3 * pad, y) + 2 * pad
    if small:
        # review r336 S3: levels 4-7 of a 128² texture were specks under one label, beside
        # an empty third of the panel; that corner now shows them enlarged, each named
        first = levels[small[0]].shape[:2]
        top = sum(levels[k].shape[0] + pad * 1.2 for k in range(1, small[0]))
        end, low = _enlarged(ax, levels, small, x + first[1] + 2 * pad, top, zoom, out)
        right, foot = max(right, end), max(foot, low)
    ax.set_xlim(-pad, right)
    ax.set_ylim(foot, -pad)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return out


def _level_image(ax, lv, x0: float, y0: float, scale: float = 1.0):
    """One level drawn with its top left corner at (``x0``, ``y0``), ``scale`` units a texel."""
    h, w = lv.shape[:2]
    data = rgba_image(lv) if lv.ndim == 3 else lv
    kw = {} if lv.ndim == 3 else {"cmap": "gray", "vmin": 0.0, "vmax": 1.0}
    return ax.imshow(data, extent=(x0, x0 + w * scale, y0 + h * scale, y0),
                     interpolation="nearest", **kw)  # fmt: skip


def _enlarged(ax, levels, small: list, x0: float, top: float, zoom: int, out) -> tuple:
    """The ``small`` levels again, ``zoom`` times larger, in a row from (``x0``, ``top``)
    under a heading, each with its size below it; returns the row's right end and the
    labels' foot."""
    w0 = levels[0].shape[1]
    out.labels.append(ax.text(x0, top, f"{small[0]}–{small[-1]}, drawn {zoom}× larger:",
                              fontsize=fs(0.7), ha="left", va="top"))  # fmt: skip
    base = top + 0.1 * w0 + levels[small[0]].shape[0] * zoom  # one baseline, below the heading
    x = x0
    for k in small:
        h, w = levels[k].shape[:2]
        slot = max(w * zoom, 0.3 * w0)  # at least as wide as the label under it
        out.enlarged.append(_level_image(ax, levels[k], x + (slot - w * zoom) / 2,
                                         base - h * zoom, zoom))  # fmt: skip
        out.labels.append(ax.text(x + slot / 2, base + 0.02 * w0, f"{k}: {w}×{h}",
                                  fontsize=fs(0.7), ha="center", va="top"))  # fmt: skip
        x += slot + 0.02 * w0
    return x, base + 0.12 * w0  # the labels' foot


# -- filters side by side ----------------------------------------------------------------------
@dataclass
class FilterArtists(Artists):
    """Per filter: its image and its error map (against the truth), and the error colour bar."""

    images: list = field(default_factory=list)
    errors: list = field(default_factory=list)
    colorbar: object = None
    rms: dict = field(default_factory=dict)


def plot_filters(axes, images: dict, truth, *, vmax: float = 0.5) -> FilterArtists:
    """Filtered renders (top row) and their error against the footprint average (bottom).

    Parameters
    ----------
    axes : (2, n) array of Axes
        Column ``j`` shows the ``j``-th entry of ``images``.
    images : dict of name -> (H, W, 3) array
        E.g. ``{f: tr.render(scene, ..., texture_filter=f).image for f in filters}``.
    truth : (H, W, 3) array
        The texture averaged over each pixel's footprint
        (:func:`teachraster.study.texture_truth.footprint_average`).
    vmax : float
        Top of the error colour scale (mean absolute error over the channels).

    Returns
    -------
    FilterArtists
        ``rms[name]`` is the root-mean-square error over covered pixels and channels.
    """
    axes = np.asarray(axes).reshape(2, -1)
    out = FilterArtists()
    for j, (name, img) in enumerate(images.items()):
        top, bottom = axes[0, j], axes[1, j]
        for ax in (top, bottom):  # pictures, no ticks: set up first, so none are made (slow)
            pixel_axes(ax, *np.shape(img)[1::-1], ticks=False)
        out.images.append(show_image(top, rgba_image(img), zorder=0.5))
        err = np.abs(np.asarray(img) - truth)
        rms = float(np.sqrt(np.nanmean(err**2)))
        out.rms[name] = rms
        top.set_title(name.replace("_", " "), fontsize=fs(0.8))
        out.errors.append(show_image(bottom, err.mean(axis=-1), cmap=ERROR_CMAP, vmin=0.0,
                                     vmax=vmax, zorder=0.5))  # fmt: skip
        bottom.set_title(f"error, RMS {rms:.3f}", fontsize=fs(0.7))
    if out.errors:
        out.colorbar = axes[1, -1].figure.colorbar(out.errors[-1], ax=list(axes[1]),
                                                   shrink=0.85, label="|error|")  # fmt: skip
    return out
