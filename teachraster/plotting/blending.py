"""Blending plots (lesson 12b): colour buffers side by side, their difference, and the colour
each sample of a multisampled colour buffer holds.

Every function takes Axes and returns the artists it drew:

- :func:`plot_composites` -- several (H, W, 4) colour buffers, one per Axes, as displayed
  (:func:`~teachraster.plotting.lines.plot_rgba`) or with their alpha over a checkerboard,
  each with a short title;
- :func:`plot_colour_difference` -- the largest channel difference |a − b| per pixel, with a
  colour bar from 0 to its maximum;
- :func:`plot_sample_colours` -- every sample of ``frame.sample_color`` as a dot at its
  position in its pixel, in the colour it holds, one pixel outlined.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.patches import Rectangle

from .common import Artists, ms, pixel_axes
from .lines import RGBAArtists, plot_rgba, rgba_shown


def plot_composites(axes, images, titles, *, fontsize="medium", views=None) -> list[RGBAArtists]:
    """Colour buffers side by side, as displayed (the RGB written), without ticks.

    Parameters
    ----------
    axes : sequence of matplotlib Axes
        One per image.
    images : sequence of (H, W, 4) arrays
        Colour buffers (``frame.color``), linear values shown as they are.
    titles : sequence of str
        One per image.
    fontsize : str or float
        The titles' size.
    views : sequence of str, optional
        One per image, :func:`~teachraster.plotting.lines.plot_rgba`'s ``view``: "displayed"
        (the default for every image) or "alpha", the colour with its alpha over a
        checkerboard, for a fragment's colour, which no window displays (lesson 12b §1's
        source).

    Returns
    -------
    list of RGBAArtists
        One per Axes.
    """
    views = ["displayed"] * len(images) if views is None else list(views)
    if not len(axes) == len(images) == len(titles) == len(views):
        raise ValueError(f"{len(axes)} Axes for {len(images)} images, {len(titles)} titles "
                         f"and {len(views)} views")  # fmt: skip
    drawn = []
    for ax, image, title, view in zip(axes, images, titles, views):
        drawn.append(plot_rgba(ax, image, view=view))
        ax.set_title(title, fontsize=fontsize)
        ax.set(xticks=[], yticks=[], xlabel="", ylabel="")
    return drawn


@dataclass
class DifferenceArtists(Artists):
    """What :func:`plot_colour_difference` drew: the image and its colour bar."""

    image: object
    colorbar: object
    maximum: float


def plot_colour_difference(ax, a, b, *, cmap="inferno", shrink=0.8) -> DifferenceArtists:
    """|a − b| per pixel (the largest of the channels compared), 0 to its maximum.

    Parameters
    ----------
    ax : matplotlib Axes
    a, b : (H, W, k) arrays
        Two colour buffers of one shape; every channel is compared.
    cmap : str
        The colour map (dark: no difference).
    shrink : float
        The colour bar's length, as a share of the Axes' height.

    Returns
    -------
    DifferenceArtists
        ``image``, ``colorbar`` (ticks at 0 and the maximum) and ``maximum``.
    """
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if a.shape != b.shape or a.ndim != 3:
        raise ValueError(f"a and b must be (H, W, k) arrays of one shape, got {a.shape}, {b.shape}")
    delta = np.abs(a - b).max(axis=2)
    height, width = delta.shape
    top = float(delta.max())
    image = ax.imshow(delta, cmap=cmap, vmin=0, vmax=top if top > 0 else 1,
                      extent=(0, width, height, 0), interpolation="nearest")  # fmt: skip
    bar = ax.figure.colorbar(image, ax=ax, shrink=shrink, ticks=[0, top], format="%.2f")
    ax.set(xticks=[], yticks=[])
    return DifferenceArtists(image, bar, top)


@dataclass
class SampleColourArtists(Artists):
    """What :func:`plot_sample_colours` drew: the pixel grid, the dots and the outline."""

    grid: list
    dots: object
    outline: object


def plot_sample_colours(ax, sample_color, offsets, *, pixel=None, size=1.0) -> SampleColourArtists:
    """Every sample of a multisampled colour buffer, a dot in the colour it holds.

    Parameters
    ----------
    ax : matplotlib Axes
    sample_color : (H, W, S, 4) array
        ``frame.sample_color``: each sample's colour after blending, before the resolve.
    offsets : (S, 2) array
        The sample positions inside a pixel (``frame.samples``, ``tr.sample_pattern(S)``).
    pixel : (row, col), optional
        A pixel to outline.
    size : float
        The dots' size as a multiple of the style's marker size.

    Returns
    -------
    SampleColourArtists
    """
    sample_color = np.asarray(sample_color, dtype=np.float64)
    offsets = np.asarray(offsets, dtype=np.float64)
    height, width, n_s = sample_color.shape[:3]
    if offsets.shape != (n_s, 2):
        raise ValueError(f"offsets must be ({n_s}, 2) for {n_s} samples, got {offsets.shape}")
    pixel_axes(ax, width, height, ticks=False)
    ax.set_facecolor("0.85")  # a neutral ground: every sample's colour stands on it
    grid = [ax.axvline(x, color="0.6", lw=0.8, zorder=1) for x in range(1, width)]
    grid += [ax.axhline(y, color="0.6", lw=0.8, zorder=1) for y in range(1, height)]
    rows, cols, s = np.indices((height, width, n_s)).reshape(3, -1)
    shown = rgba_shown(sample_color.reshape(-1, 1, 4))[:, 0, :3]  # as displayed, opaque
    dots = ax.scatter(cols + offsets[s, 0], rows + offsets[s, 1], c=shown, s=(ms(size) ** 2),
                      edgecolors="white", linewidths=0.8, zorder=2)  # fmt: skip
    outline = None
    if pixel is not None:
        row, col = pixel
        outline = ax.add_patch(Rectangle((col, row), 1, 1, fill=False, ec="black", lw=2.5,
                                         zorder=3, clip_on=False))  # fmt: skip
    return SampleColourArtists(grid, dots, outline)
