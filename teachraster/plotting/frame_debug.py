"""Frame debugging views: an overlay of the whole frame and the history of one pixel.

:func:`plot_overlay` draws ``frame.overlay(kind)`` (see
:mod:`teachraster.pipeline.debugging.overlays`) with a colour bar that says what a colour means in
numbers: counts get one colour per integer (0 light grey, never hidden), the quad
overshading a fraction of helper lanes from 0 to 3/4, the triangle size a log scale of
pixels. :func:`plot_history` draws ``frame.history(row, col)``: one tile per fragment at its
depth on a written-out depth axis, coloured by outcome, with the depth buffer before and
after it (and, with a colour buffer, the colour before and after it).
Both read the frame's trace; neither recomputes an algorithm.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import matplotlib as mpl
import numpy as np
from matplotlib.colors import BoundaryNorm, ListedColormap, LogNorm, Normalize

from ..core.validate import check_choice
from ..pipeline.debugging.overlays import KINDS, helper_share, visible_triangle_sizes
from .common import Artists, clear_axes, pixel_axes, show_image
from .style import ERROR_CMAP, VALUE_CMAP

#: What one unit of each overlay is, for the colour bar.
OVERLAY_LABELS = {
    "overdraw": "fragments per pixel",
    "depth_complexity": "passed depth test, per pixel",
    "quad_overshading": "helper share of quad lanes",
    "triangle_size": "px per triangle (log)",
    "hi_z": "Hi-Z rejections per pixel",
    "nan": "non-finite values per pixel",
}

#: The labels that change under MSAA, where those overlays count (triangle, sample) pairs.
OVERLAY_LABELS_MSAA = {
    "overdraw": "covered samples per pixel",
    "depth_complexity": "samples passed depth, per pixel",
}

#: The "hi_z" view's title under MSAA: teachraster replays Hi-Z at one sample only, so the
#: view is 0 there. Said, since "Hi-Z: 0" at 4 samples read as "MSAA defeats Hi-Z" (review
#: r261 W1), which GPUs do not show: their Hi-Z summary of a tile is then the farthest depth
#: over all its samples.
HIZ_MSAA_TITLE = "Hi-Z: not modelled with MSAA (GPUs keep it)"

#: The colour of "nothing arrived here" (a count of 0, or no triangle).
NOTHING = (0.93, 0.93, 0.93)

#: The colour of a covered pixel that the overlay counts 0 in the sparse views (``SPARSE``).
COVERED = (0.76, 0.76, 0.76)

#: Overlays that are 0 on most covered pixels: they draw the scene's coverage under the
#: counts, so the few counted pixels can be placed on it (review r13, 11).
SPARSE = ("hi_z", "nan")

#: Counts up to this many get one colour per integer; beyond, a continuous scale.
DISCRETE_LIMIT = 32


@dataclass
class OverlayArtists(Artists):
    """The overlay image of :func:`plot_overlay` and its colour bar."""

    image: object
    colorbar: object | None = None


@dataclass
class HistoryArtists(Artists):
    """The bars, buffer markers and legend of :func:`plot_history`."""

    parts: list = field(default_factory=list)


def overlay_style(kind: str, values: np.ndarray):
    """(data to show, cmap, norm, colour-bar ticks) for an overlay's ``values``."""
    if kind == "quad_overshading":
        cmap = mpl.colormaps[ERROR_CMAP]
        return values, cmap, Normalize(0.0, 0.75), [0, 0.25, 0.5, 0.75]
        # (quads without work are made transparent by plot_overlay)
    if kind == "triangle_size":
        top = max(float(values.max(initial=1)), 2.0)
        shown = np.where(values > 0, values.astype(float), np.nan)  # no triangle: transparent
        return shown, mpl.colormaps[VALUE_CMAP], LogNorm(1.0, top), log_ticks(top)
    top = int(values.max(initial=0))
    base = mpl.colormaps[VALUE_CMAP if kind != "nan" else ERROR_CMAP]
    if top <= DISCRETE_LIMIT:
        # a sparse view draws its 0 on the covered pixels only, in their grey, and the bar
        # shows that grey (review r323 S3: its "0" had the background's, not on the frame);
        # a view that is 0 everywhere gets a bar of 0 alone (a "1" there meant nothing)
        n = top
        zero = COVERED if kind in SPARSE else NOTHING
        colours = [(*zero, 1.0)] + [base(0.15 + 0.85 * i / max(n - 1, 1)) for i in range(n)]
        cmap = ListedColormap(colours[: n + 1])
        norm = BoundaryNorm(np.arange(-0.5, n + 1.0), cmap.N)
        step = max(1, -(-(n + 1) // 12))
        return values.astype(float), cmap, norm, list(range(0, n + 1, step))
    return values.astype(float), base, Normalize(0, top), None


def log_ticks(top: float, most: int = 7) -> list:
    """Ticks for a log colour bar from 1 to ``top``: powers of 2 (of 4, 16, ... when more
    than ``most`` would crowd it), ending at ``top`` itself, so that the largest values
    present are labelled (a fan of 57 px triangles reads 57, not 16)."""
    powers = [2**k for k in range(int(np.floor(np.log2(top))) + 1)]
    stride = 1
    while len(powers[::stride]) > most:
        stride *= 2
    ticks = powers[::stride]
    if top > ticks[-1]:
        if top < 1.5 * ticks[-1]:  # the two labels would overlap: the top one stays
            ticks.pop()
        ticks.append(int(top) if float(top).is_integer() else top)
    return ticks


def overlay_label(kind: str, n_samples: int = 1) -> str:
    """What one unit of overlay ``kind`` is: under MSAA (``n_samples`` > 1) overdraw and
    depth complexity count covered samples, not fragments."""
    if n_samples > 1 and kind in OVERLAY_LABELS_MSAA:
        return OVERLAY_LABELS_MSAA[kind]
    return OVERLAY_LABELS[kind]


def plot_overlay(ax, frame, kind: str, *, colorbar: bool = True, cax=None,
                 orientation: str = "vertical") -> OverlayArtists:  # fmt: skip
    """Draw ``frame.overlay(kind)`` on ``ax`` with a colour bar in numbers; the title
    gives the total (or the range). ``frame`` needs ``trace=True`` except for "nan".

    The colour bar takes its room from ``ax`` unless ``cax`` is given: an Axes of its own
    (cleared and reused), so a figure that redraws overlays keeps ``ax`` where it is.
    ``orientation`` ("vertical" or "horizontal") is the bar's: a horizontal one lies under
    the frame, its label read without turning the head."""
    check_choice("kind", kind, KINDS)
    check_choice("orientation", orientation, ("vertical", "horizontal"))
    values = frame.overlay(kind)
    offsets = getattr(frame, "samples", None)  # the frame's sample pattern, None for one
    n_samples = 1 if offsets is None else len(offsets)
    height, width = values.shape
    shown, cmap, norm, ticks = overlay_style(kind, values)
    if kind == "quad_overshading":  # no work in the quad: the background shows
        shown = np.where(frame.overlay("overdraw") > 0, shown, np.nan)
    pixel_axes(ax, width, height, ticks=max(width, height) <= 64)
    ax.set_facecolor(NOTHING)
    if kind in SPARSE:  # the scene in a second grey under the counts
        covered = np.asarray(frame.coverage, dtype=bool)
        show_image(ax, np.where(covered, 1.0, np.nan), cmap=ListedColormap([COVERED]),
                   norm=Normalize(0.0, 1.0), zorder=0.5)  # fmt: skip
        shown = np.where(values > 0, shown, np.nan)  # 0: the covered grey or the background
    im = show_image(ax, shown, cmap=cmap, norm=norm)
    result = OverlayArtists(im)
    hiz = getattr(getattr(frame, "trace", None), "hiz", None)
    if kind == "hi_z" and hiz is not None:  # Hi-Z rejects whole tiles: draw them
        tile = hiz.tile
        ax.vlines(np.arange(0, width + 1, tile), 0, height, color="white", lw=0.8, zorder=2)
        ax.hlines(np.arange(0, height + 1, tile), 0, width, color="white", lw=0.8, zorder=2)
    if colorbar:
        room = dict(ax=ax, shrink=0.8) if cax is None else dict(cax=cax)
        if cax is not None:
            clear_axes(cax)
        result.colorbar = ax.figure.colorbar(im, **room, ticks=ticks, format="%g",
                                             orientation=orientation)  # fmt: skip
        label = overlay_label(kind, n_samples)
        if kind in SPARSE:
            label += "\n(lighter grey: no triangle)"
        result.colorbar.set_label(label, fontsize="small")
        result.colorbar.minorticks_off()  # a log bar's minor labels ("6 × 10⁰") crowd it
    share = helper_share(frame) if kind == "quad_overshading" else None
    sizes = visible_triangle_sizes(frame) if kind == "triangle_size" else None
    ax.set_title(overlay_title(kind, values, n_samples, share=share, sizes=sizes),
                 fontsize="small")  # fmt: skip
    return result


def plot_triangle_edges(
    ax,
    frame,
    *,
    min_pixels: float = 12.0,
    color: str = "#222222",
    lw: float = 0.6,
    alpha: float = 0.45,
):
    """Draw thin the edges of every triangle the frame submitted (its trace's window
    positions, after clipping) whose bounding box reaches the image and that was not culled,
    as RenderDoc's wireframe overlay does, so that where triangles meet can be seen even
    where their colours blend into one another (review r90 11-4: the fan's hub, white on
    white). A triangle that covers no pixel centre (a sliver between the rows of centres,
    :func:`~teachraster.pipeline.debugging.overlays.covered_pieces`) is drawn dashed: it
    reaches no pixel's history as a fragment, and without its outline no view showed it
    (review r298 W1: exercise 11's frames 6 and 8). Left out (None returned) where the
    triangles the frame shows cover fewer than ``min_pixels`` pixels each on average: edges
    a pixel or two apart would hide the picture (a 64 x 48 uv_sphere: 3 px a triangle).
    Also None without a trace. Returns the LineCollection, one segment an edge.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> import teachraster as tr
    >>> fan = tr.render(tr.get_scene("fan"), None, 64, 48, trace=True)
    >>> fig, ax = plt.subplots()
    >>> len(plot_triangle_edges(ax, fan).get_segments())  # 12 triangles, 3 edges each
    36
    >>> sphere = tr.render(tr.get_scene("uv_sphere"), None, 64, 48, trace=True)
    >>> plot_triangle_edges(ax, sphere) is None
    True
    >>> plt.close(fig)
    """
    from matplotlib.collections import LineCollection

    from ..pipeline.debugging.overlays import covered_pieces

    trace = getattr(frame, "trace", None)
    if trace is None or getattr(trace, "debug", None) is None:
        return None
    owners = frame.triangle_id[frame.triangle_id >= 0]
    if not owners.size or owners.size / np.unique(owners).size < min_pixels:
        return None
    height, width = frame.triangle_id.shape
    xy = trace.window[:, :, :2]
    with np.errstate(invalid="ignore"):  # a NaN corner: its triangle is left out
        reaches = ((xy[:, :, 0].max(axis=1) >= 0) & (xy[:, :, 0].min(axis=1) <= width)
                   & (xy[:, :, 1].max(axis=1) >= 0) & (xy[:, :, 1].min(axis=1) <= height))  # fmt: skip
    drawn = np.flatnonzero(reaches & ~np.asarray(trace.culled, bool))
    if not len(drawn):
        return None
    covered = covered_pieces(frame)[drawn]
    edges = np.stack([xy[drawn], np.roll(xy[drawn], -1, axis=1)], axis=2).reshape(-1, 2, 2)
    # each edge from its left end: a sliver's two long edges, walked opposite ways, would
    # start their dashes at opposite ends and fill each other's gaps into a solid line
    flip = edges[:, 0, 0] > edges[:, 1, 0]
    edges[flip] = edges[flip, ::-1]
    each = np.repeat(covered, 3)
    # a dashed triangle is drawn darker and twice as thick: a sliver is the one to find
    rgba = [mpl.colors.to_rgba(color, alpha if c else min(1.0, 2 * alpha)) for c in each]
    lines = LineCollection(edges, colors=rgba, linewidths=np.where(each, lw, 2 * lw), zorder=3,
                           linestyles=["solid" if c else (0, (3, 2)) for c in each])  # fmt: skip
    ax.add_collection(lines, autolim=False)
    return lines


def fit_title(ax, margin: float = 4.0):
    """Shrink ``ax``'s title until it lies inside its figure (a fixed-size widget figure in the
    classroom style's large fonts); returns the title."""
    title = ax.title
    canvas = ax.figure.canvas
    renderer = canvas.get_renderer() if hasattr(canvas, "get_renderer") else None
    if renderer is None or not title.get_text():
        return title
    width = ax.figure.bbox.width
    for _ in range(8):
        box = title.get_window_extent(renderer)
        if box.x0 >= margin and box.x1 <= width - margin:
            break
        title.set_fontsize(title.get_fontsize() * 0.9)
    return title


def overlay_title(kind: str, values: np.ndarray, n_samples: int = 1, *,
                  share: float | None = None, sizes: np.ndarray | None = None) -> str:  # fmt: skip
    """A one-line summary of an overlay in numbers (under MSAA, overdraw and depth
    complexity say that they count samples; Hi-Z says that it is not modelled,
    :data:`HIZ_MSAA_TITLE`). The quad overshading's is the frame's
    ``share`` of helpers among all lanes launched
    (:func:`~teachraster.pipeline.debugging.overlays.helper_share`), not a mean of the
    per-quad fractions, which would drop the quads without helpers. The triangle size's is
    the median of ``sizes``, one per triangle shown
    (:func:`~teachraster.pipeline.debugging.overlays.visible_triangle_sizes`), not over the
    pixels, which weights a triangle by its size (lesson 11 prints the same median)."""
    if kind == "quad_overshading":
        if share is None:
            return "quad overshading"
        return f"quad overshading: helpers {share:.0%} of all lanes"
    if kind == "triangle_size":
        if sizes is None:  # the overlay alone: its pixels, said so
            seen = values[values > 0]
            median = float(np.median(seen)) if len(seen) else 0.0
            return f"triangle size: median {median:,g} px over its pixels"
        median = float(np.median(sizes)) if len(sizes) else 0.0
        return f"triangle size: median {median:,g} px per triangle shown"
    if kind == "hi_z" and n_samples > 1:  # not a count of 0: no replay was run
        return HIZ_MSAA_TITLE
    total, top = int(values.sum()), int(values.max(initial=0))
    name = kind.replace("_", " ").replace("hi z", "Hi-Z").replace("nan", "NaN")
    unit = " samples" if n_samples > 1 and kind in OVERLAY_LABELS_MSAA else ""
    return f"{name}: {total:,}{unit} (max {top}/px)"


def plot_history(ax, frame_or_history, row=None, col=None) -> HistoryArtists:
    """Draw a pixel's history (``frame.history(row, col)``, or a history itself): one tile
    per fragment at its depth, coloured by outcome (a cross for a record without one), on a
    depth axis written out in full; the buffer before (○) and after (●); with a
    colour buffer, above each record that reached it, swatches of the target's colour
    before, the fragment's own and the target's after."""
    h = frame_or_history
    if row is not None or col is not None:
        h = frame_or_history.history(row, col)
    if not hasattr(h, "records"):
        raise TypeError(f"frame_or_history must be a frame (with row, col) or a PixelHistory, "
                        f"got {type(h).__name__}")  # fmt: skip
    return HistoryArtists(list(h.plot(ax)))
