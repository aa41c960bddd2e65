"""Per-pixel images: barycentrics, attributes, the error heatmap, depth, colour, the plan.

Every function draws on the Axes it is given and returns an :class:`~.common.Artists`
dataclass; the images also have an ``update(...)`` method that changes the data of the same
artists (for views that follow a moving vertex or slider). NaN (no coverage) is drawn
transparent, so whatever is below (the pixel grid, the background) shows through.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.text import Text
from matplotlib.ticker import MaxNLocator

from ..core.fill import Fill
from ..core.trace import FillTrace
from ..pipeline.planning.render_plan import Plan
from ..pipeline.rendering.render_scenes import SceneFrame
from ..pipeline.rendering.render_triangles import Frame
from .common import (
    Artists,
    as_trace,
    bar_in,
    fs,
    label_box,
    lw,
    ms,
    quiet_nanmax,
    rgba_image,
    round_up,
    set_image,
    show_image,
    tint,
)
from .style import COLORS, ERROR_CMAP, VALUE_CMAP


@dataclass
class ImageArtists(Artists):
    """One image (and its colour bar, on its own Axes, if any)."""

    image: object
    colorbar: object = None

    def update(self, data) -> None:
        """Show new values (same shape or not) in the same image."""
        data = np.asarray(data, dtype=np.float64)
        if data.ndim == 3:
            data = rgba_image(data)
        self.image = set_image(self.image, data)
        if self.colorbar is not None and self.colorbar.mappable is not self.image:
            self.colorbar.update_normal(self.image)


def show_values(ax, data, *, cmap=None, vmin=None, vmax=None, colorbar=True, label=None, **kw):
    """imshow a (H, W) value image (with a colour bar) or an (H, W, 3) colour image."""
    data = np.asarray(data, dtype=np.float64)
    if data.ndim == 3:
        return ImageArtists(show_image(ax, rgba_image(data), zorder=0.5, **kw))
    if data.ndim != 2:
        raise ValueError(f"expected an (H, W) or (H, W, 3) image, got shape {data.shape}")
    im = show_image(ax, data, cmap=cmap or VALUE_CMAP, vmin=vmin, vmax=vmax, zorder=0.5, **kw)
    cbar = ax.figure.colorbar(im, ax=ax, shrink=0.85, label=label) if colorbar else None
    return ImageArtists(im, cbar)


# -- barycentric coordinates -------------------------------------------------------------------
def plot_barycentric(
    ax, fill, channel: int | None = None, *, colorbar: bool = True, title: bool = True
) -> ImageArtists:
    """Screen-space barycentric weights λ1, λ2, λ3 at the covered pixel centres (λk is 1 at vk).

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
    channel : {None, 0, 1, 2}
        None: all three at once as red, green and blue (each vertex its primary colour,
        mixtures in between); 0, 1 or 2: that one weight as a value map with a colour bar
        (indices from 0: channel 0 is λ1, the weight of v1).
    colorbar : bool
        Colour bar for a single channel.
    title : bool
        Set the Axes title.

    Returns
    -------
    ImageArtists
    """
    trace = as_trace(fill, "plot_barycentric")
    lam = trace.image(trace.barycentric)
    if channel is None:
        result = show_values(ax, np.clip(lam, 0.0, 1.0))
        name = "λ1, λ2, λ3 as red, green, blue"
    else:
        if channel not in (0, 1, 2):
            raise ValueError(f"channel must be None, 0, 1 or 2, got {channel!r}")
        result = show_values(ax, lam[..., channel], vmin=0, vmax=1, colorbar=colorbar,
                       label=f"λ{channel + 1}")  # fmt: skip
        name = f"barycentric λ{channel + 1}: 1 at v{channel + 1}, 0 opposite"
    if title:
        ax.set_title(name)
    return result


# -- attributes --------------------------------------------------------------------------------
def attribute_image(source, name: str | None = None, *, mode: str | None = None,
                    channel: int | None = None) -> np.ndarray:  # fmt: skip
    """An interpolated attribute as an (H, W) value image or an (H, W, 3) colour image.

    Parameters
    ----------
    source : Fill, FillTrace, Frame, SceneFrame or array
        Where the values come from. A Fill gives ``fill.attrs[name]``; with ``mode`` (or for
        a FillTrace) the trace's ``"affine"`` or ``"perspective"`` values, both of which a
        traced fill records. A SceneFrame gives ``frame.attr(name)``, a Frame ``frame.attrs``.
    name : str, optional
        Attribute name; may be left out when there is only one.
    mode : {None, "affine", "perspective"}
        Which interpolation (needs a trace); None: the one the fill was made with.
    channel : int, optional
        Pick one channel of a vector attribute. Without it, a 3-channel attribute is a colour
        image, one channel is squeezed, and for others channel 0 is taken.
    """
    if isinstance(source, Fill | FillTrace):
        trace = source if isinstance(source, FillTrace) else source.trace
        if isinstance(source, FillTrace) or mode is not None:
            if trace is None:
                raise ValueError(f"mode={mode!r} needs a traced fill: rasterize(..., trace=True)")
            mode = trace.interpolation if mode is None else mode
            if mode not in ("affine", "perspective"):
                raise ValueError(f"mode must be 'affine' or 'perspective', got {mode!r}")
            values = trace.affine if mode == "affine" else trace.perspective
            values = {k: trace.image(v) for k, v in values.items()}
        else:
            values = dict(source.attrs)
        if not values:
            raise ValueError("the triangle has no attributes: give Triangle(..., attrs={...})")
        if name is None:
            if len(values) > 1:
                raise ValueError(f"several attributes, pick one by name: {sorted(values)}")
            name = next(iter(values))
        if name not in values:
            raise KeyError(f"no attribute {name!r}; the triangle has {sorted(values)}")
        data = values[name]
    elif isinstance(source, SceneFrame) and name is not None:
        data = source.attr(name)
    elif isinstance(source, Frame):
        data = source.attrs
    else:
        data = source
    data = np.asarray(data, dtype=np.float64)
    if data.ndim == 3:
        if channel is not None:
            data = data[..., channel]
        elif data.shape[2] == 1:
            data = data[..., 0]
        elif data.shape[2] != 3:
            data = data[..., 0]
    return data


def plot_attribute(
    ax,
    source,
    name: str | None = None,
    *,
    mode: str | None = None,
    channel: int | None = None,
    cmap=None,
    vmin: float | None = None,
    vmax: float | None = None,
    colorbar: bool = True,
    title: str | None = None,
) -> ImageArtists:
    """An interpolated attribute: a value map with a colour bar, or colours.

    Parameters
    ----------
    ax : matplotlib Axes
    source, name, mode, channel
        As for :func:`attribute_image`.
    cmap, vmin, vmax
        Colour map and its range for a value map (default: the value colour map and the
        data's range; give the same range to two plots that should be compared).
    colorbar : bool
        Colour bar for a value map.
    title : str, optional
        Axes title (default: the attribute's name and interpolation, where known).

    Returns
    -------
    ImageArtists
    """
    data = attribute_image(source, name, mode=mode, channel=channel)
    result = show_values(ax, data, cmap=cmap, vmin=vmin, vmax=vmax, colorbar=colorbar,
                   label=name)  # fmt: skip
    if title is None and name is not None:
        how = mode or (source.trace.interpolation if isinstance(source, Fill) and source.trace
                       else None)  # fmt: skip
        title = name + (f" ({how})" if how else "")
    if title:
        ax.set_title(title)
    return result


# -- the error heatmap -------------------------------------------------------------------------
def abs_error(a, b) -> np.ndarray:
    """(H, W) |a - b|; for (H, W, k) the largest channel error. NaN where either is NaN."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if a.shape != b.shape:
        raise ValueError(f"a and b must have the same shape, got {a.shape} and {b.shape}")
    err = np.abs(a - b)
    if err.ndim == 3:
        bad = np.isnan(err).all(axis=-1)
        err = np.where(bad, np.nan, np.nanmax(np.where(np.isnan(err), -np.inf, err), axis=-1))
    elif err.ndim != 2:
        raise ValueError(f"expected (H, W) or (H, W, k) images, got shape {err.shape}")
    return err


@dataclass
class HeatmapArtists(Artists):
    """Artists of :func:`plot_error_heatmap`; ``maximum`` is the largest error, ``ringed``
    the ringed one's, which the note states (the same unless ``skip_columns`` holds the
    maximum)."""

    image: object
    marker: Line2D
    note: Text
    title: Text | None
    label: str = "|a − b|"
    maximum: float = float("nan")
    colorbar: object = None
    worst: tuple[int, int] | None = None  # (row, col) of the marked maximum
    fixed_note: bool = False  # the note stays where it was put, off the picture
    show_note: bool = True  # False: the title alone states the maximum, the ring marks it
    round_range: bool = False  # True: the colour range ends on a round number (round_up)
    vmax: float | None = None  # a fixed top of the colour range (images compared side by side)
    #: columns the ring's search leaves out, and the note's words for them: a stripe every
    #: filter shows, which is no filter's defect (FilterExplorer's middle line, review r336 S9)
    skip_columns: tuple[int, ...] = ()
    skipped: str = ""
    ringed: float = float("nan")  # the ringed pixel's error, the note's "max"

    def update(self, a, b) -> None:
        """Show the error of new images (same artists; the colour bar follows)."""
        err = abs_error(a, b)
        self.maximum = quiet_nanmax(err)
        searched = err
        if self.skip_columns:
            searched = err.copy()
            searched[:, list(self.skip_columns)] = np.nan
        m = self.ringed = quiet_nanmax(searched)
        self.worst = None
        self.image = set_image(self.image, err)
        if self.colorbar is not None and self.colorbar.mappable is not self.image:
            self.colorbar.update_normal(self.image)
        h, w = err.shape
        # A zero (or no) error still needs a valid, non-empty colour range.
        top = self.maximum if np.isfinite(self.maximum) and self.maximum > 0 else 1.0
        if self.vmax is not None:
            top = self.vmax
        elif self.round_range:
            top = round_up(top)
        self.image.set_clim(0.0, top)
        if np.isfinite(m):
            i, j = np.unravel_index(np.nanargmax(searched), err.shape)
            self.worst = (int(i), int(j))
            self.marker.set_data([j + 0.5], [i + 0.5])
            self.marker.set_markersize(ring_size(self.marker))
            self.note.xy = (j + 0.5, i + 0.5)
            if not self.fixed_note:
                # keep the note inside the image: it points left in the right half, and so on
                self.note.set_position((-fs(1.2) if j > w / 2 else fs(1.2),
                                        fs(1.2) if i > h / 2 else -fs(1.2)))  # fmt: skip
                self.note.set_horizontalalignment("right" if j > w / 2 else "left")
            self.note.set_text(f"max {m:.3g}" + (" (ringed)" if self.fixed_note else "")
                               + (f", {self.skipped}" if self.skip_columns else ""))  # fmt: skip
            # a zero maximum has no pixel to point at: every pixel is one (all w equal)
            self.marker.set_visible(m > 0)
            self.note.set_visible(m > 0 and self.show_note)
            self._set_title(
                f"{self.label}: max {m:.3g}" if m > 0 else f"{self.label}: 0 everywhere"
            )
        else:
            self.marker.set_visible(False)
            self.note.set_visible(False)
            self._set_title(f"{self.label}: no pixel to compare")

    def _set_title(self, text: str) -> None:
        if self.title is not None:
            self.title.set_text(text)


def ring_size(marker: Line2D, smallest: float | None = None) -> float:
    """A ring marker's size (points) that leaves the pixel it rings in view: its inner edge
    round the pixel's corners, a tenth of a pixel clear (at the Axes' present size), and at
    least ``smallest`` (default ``ms(2.0)``, the size on images of many small pixels).

    On lesson 00's 16 x 16 grids a ring of ``ms(2.0)`` lay on the largest error's own pixel
    and hid its colour, the one pixel it was there to show (review r225 FIG1).
    """
    smallest = ms(2.0) if smallest is None else smallest
    ax = marker.axes
    (x0, _), (x1, _) = ax.transData.transform([(0.0, 0.0), (1.0, 0.0)])
    pixel = abs(x1 - x0) * 72.0 / ax.figure.dpi  # one image pixel, in points
    # the centre line at half the diagonal plus a tenth of a pixel plus half the line width
    return float(max(smallest, 2 * (0.8 * pixel) + marker.get_markeredgewidth()))


def plot_error_heatmap(
    ax, a, b, *, label: str = "|a − b|", colorbar: bool = True, title: bool = True,
    cax=None, note_at: tuple[float, float] | None = None, round_range: bool = False,
    vmax: float | None = None,
) -> HeatmapArtists:  # fmt: skip
    """Heatmap of |a − b| with a colour bar, the maximum marked and stated in the title.

    The usual use: ``a`` affine and ``b`` perspective-correct values of one attribute, which
    differ most where the triangle recedes fastest (Ek, *Triangles and Perspective Correct Interpolation*, §2, Fatahalian, CMU 15-462 *Texture*).

    Parameters
    ----------
    ax : matplotlib Axes
    a, b : (H, W) or (H, W, k) arrays
        The two images; NaN (uncovered) in either gives a transparent pixel. For k channels
        the largest channel error is shown.
    label : str
        What is compared, for the title and colour bar.
    colorbar : bool
        Add a colour bar (0 to the maximum).
    title : bool
        Put ``"{label}: max ..."`` in the Axes title (the ``note`` by the marked pixel
        says it too).
    cax : matplotlib Axes, optional
        Where the colour bar goes (horizontal if ``cax`` is wider than tall); default:
        beside ``ax``, taken from its room.
    note_at : (float, float), optional
        A fixed place for the note, in axes fraction of ``ax`` (its top right corner), e.g.
        below the picture: there it hides no pixel, and needs no line to the ringed one.
        Default: beside the marked pixel, with a line to it.
    round_range : bool
        End the colour range on a round number at least the maximum
        (:func:`~teachraster.plotting.common.round_up`) rather than on the maximum itself.
    vmax : float, optional
        A fixed top of the colour range, whatever the maximum (larger errors take the top
        colour; the note still states the maximum): heatmaps meant to be compared with each
        other, such as one explorer's filters, share one scale.

    Returns
    -------
    HeatmapArtists
        ``image``, ``marker`` (ring round the worst pixel), ``note``, ``title``, ``colorbar``
        and ``maximum``, which equals ``np.nanmax(abs(a - b))`` (NaN if nothing is covered).
    """
    err = abs_error(a, b)
    im = show_image(ax, err, cmap=ERROR_CMAP, vmin=0.0, vmax=1.0, zorder=0.5)
    marker = ax.plot([], [], "o", ms=ms(2.0), mfc="none", mec=COLORS["fill"], mew=ms(0.3),
                     zorder=5)[0]  # fmt: skip
    if note_at is None:
        note = ax.annotate(
            "", (0, 0), xytext=(0, 0), textcoords="offset points", fontsize=fs(0.8),
            color="black", bbox=label_box(0.9), zorder=7, annotation_clip=False,  # above labels
            arrowprops={"arrowstyle": "-", "color": COLORS["fill"], "lw": ms(0.2)},
        )  # fmt: skip
    else:
        note = ax.annotate("", (0, 0), xytext=note_at, textcoords="axes fraction",
                           fontsize=fs(), color="black", ha="right", va="top", zorder=7,
                           annotation_clip=False)  # fmt: skip
    title_text = ax.title if title else None
    result = HeatmapArtists(im, marker, note, title_text, label, fixed_note=note_at is not None,
                            round_range=round_range, vmax=vmax)  # fmt: skip
    result.update(a, b)
    if colorbar:
        where = {"ax": ax, "shrink": 0.85} if cax is None else bar_in(cax)
        # a fixed top clips larger errors to its colour: the bar's arrow says so (FilterExplorer
        # at 89° with nearest: max 0.529 over a bar ending at 0.5; review r35, 09 item 6)
        extend = "max" if vmax is not None else "neither"
        result.colorbar = ax.figure.colorbar(im, label=label, extend=extend, **where)
    return result


# -- depth and colour --------------------------------------------------------------------------
@dataclass
class ProfileArtists(Artists):
    """Artists of :func:`plot_profile`: two images' values along one row or column."""

    lines: list  # the two curves, ``a`` first
    guides: list  # the dashed row (column) drawn on the images it runs across
    title: Text
    axis: str = "row"
    index: int = 0
    vlim: tuple | None = None  # fixed value range, or None (the values' own)

    def update(self, a, b, index: int | None = None) -> None:
        """Show new images (and, with ``index``, another row or column) in the same artists."""
        a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
        if index is not None:
            self.index = int(index)
        along_row = self.axis == "row"
        pick = (lambda im: im[self.index, :]) if along_row else (lambda im: im[:, self.index])
        pos = np.arange(a.shape[1 if along_row else 0]) + 0.5  # the pixel centres
        # the screen position on x, the value on y, along a column too: with the value on x
        # a curve that changes fast per pixel row lay flat, and "steeper" read backwards
        # (review r77 04-1)
        for line, image in zip(self.lines, (a, b)):
            line.set_data(pos, pick(image))
            line.set_marker("o" if pos.size <= 40 else "")  # dots only where they stay apart
        for guide in self.guides:
            guide.set_data(([0, a.shape[1]], [self.index + 0.5] * 2) if along_row
                           else ([self.index + 0.5] * 2, [0, a.shape[0]]))  # fmt: skip
        ax = self.title.axes
        # only the row's (column's) covered pixels and one on either side: over the whole
        # image the curves took a third of the panel (reviews r19/r20, lesson 00's player)
        ax.set_xlim(*_covered_span(pick(a), pick(b)))
        lo, hi = self.vlim or _value_range(pick(a), pick(b))
        if along_row and self.vlim is None:
            # headroom above the curves for the key, in the upper left: inside the curves'
            # own range "best" was decided once and a new row's curves ran under it (review
            # r13, 04 c15: the key covered the lower ends of both curves)
            hi += KEY_ROOM * (hi - lo)
        ax.set_ylim(lo, hi)
        if along_row and self.vlim is None:
            self.clear_key()
        self.title.set_text(f"{'row' if along_row else 'column'} {self.index} (dashed)")

    def clear_key(self) -> None:
        """Raise the value axis' top until no dot of the curves lies under the key (upper
        left), at the key's size now: KEY_ROOM is room for it at the style's font size, and a
        widget that enlarges the key's text afterwards calls this again (review r249 FIG3:
        at the player's classroom size the key covered the affine curve's last dot). Nothing
        changes where KEY_ROOM suffices, or where no renderer can measure the key."""
        ax = self.title.axes
        key, get_renderer = ax.get_legend(), getattr(ax.figure.canvas, "get_renderer", None)
        if key is None or get_renderer is None:
            return
        renderer = get_renderer()
        frame = ax.get_window_extent(renderer)
        box = key.get_window_extent(renderer)
        lo, hi = ax.get_ylim()
        to_data = ax.transData.inverted()
        # the key's sides in data x, widened by a dot's radius; its foot as a share of the height
        radius = max(line.get_markersize() for line in self.lines) / 2 * ax.figure.dpi / 72.0
        x0, x1 = to_data.transform([[box.x0 - radius, 0.0], [box.x1 + radius, 0.0]])[:, 0]
        foot = (box.y0 - frame.y0 - radius - 6.0) / frame.height  # 6 px of air
        if foot < 0.3:  # a key this tall leaves no room worth keeping for the curves
            return
        top = hi
        for line in self.lines:
            x, y = np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)
            under = np.isfinite(y) & (x >= x0) & (x <= x1)
            if under.any():
                top = max(top, lo + (float(y[under].max()) - lo) / foot)
        ax.set_ylim(lo, top)


#: The share of a row profile's value range added above the curves for its key.
KEY_ROOM = 0.45


#: The fewest pixels a profile's position axis spans: a short row is not stretched flat.
PROFILE_MIN_SPAN = 6


def _covered_span(a, b) -> tuple[int, int]:
    """The positions (pixel edges) from one pixel before the first covered value of ``a`` or
    ``b`` to one after the last, at least :data:`PROFILE_MIN_SPAN` wide and inside the image.

    >>> nan = float("nan")
    >>> _covered_span(np.array([nan] * 3 + [1.0] * 5 + [nan] * 8), np.full(16, nan))
    (2, 9)
    """
    n = len(a)
    covered = np.flatnonzero(np.isfinite(a) | np.isfinite(b))
    if not covered.size:
        return 0, n
    start, stop = int(covered[0]) - 1, int(covered[-1]) + 2
    short = max(0, min(PROFILE_MIN_SPAN, n) - (stop - start))
    start -= short // 2
    stop += short - short // 2
    shift = max(0, -start) - max(0, stop - n)  # back inside the image
    return max(0, start + shift), min(n, stop + shift)


def _value_range(a, b) -> tuple[float, float]:
    both = np.concatenate([a[np.isfinite(a)], b[np.isfinite(b)]])
    if not both.size:
        return 0.0, 1.0
    lo, hi = float(both.min()), float(both.max())
    pad = 0.06 * (hi - lo) if hi > lo else 0.5
    return lo - pad, hi + pad


def plot_profile(ax, a, b, *, axis: str = "row", index: int = 0, labels=("a", "b"),
                 value: str = "value", guides=(), vlim=None) -> ProfileArtists:  # fmt: skip
    """The values of two images along one row (or column), as two curves over the pixel centres.

    Beside an affine/perspective comparison it shows what the colours only suggest: along
    any line of the screen the affine values change by equal steps (a straight line), the
    perspective-correct ones do not (Ek, *Triangles and Perspective Correct Interpolation*,
    §2).

    Parameters
    ----------
    ax : matplotlib Axes
    a, b : (H, W) arrays
        The two images (NaN where not covered: a gap in the curve).
    axis : {"row", "column"}
        Along a row, x is the centres' screen x, j + 0.5; along a column, the centres'
        screen y, i + 0.5 (the image's top row on the left). The value is always on y, so
        that a value changing fast per pixel is a steep curve.
    index : int
        Which row (column).
    labels : (str, str)
        Legend entries of ``a`` and ``b``.
    value : str
        What the values are (the value axis' label).
    guides : Axes
        Axes showing the images, on which the row (column) is drawn dashed.
    vlim : (float, float), optional
        Fixed value range (default: the values on show, renewed at every update).
    """
    if axis not in ("row", "column"):
        raise ValueError(f"axis must be 'row' or 'column', got {axis!r}")
    styles = [dict(ls="-", marker="o", mfc="white"), dict(ls="-", marker="o")]
    lines = [ax.plot([], [], label=label, lw=lw(0.8), ms=ms(0.7), color=color, **kw)[0]
             for label, color, kw in zip(labels, (COLORS["bbox"], COLORS["inside"]), styles)]  # fmt: skip
    guide_lines = [g.plot([], [], ls=(0, (4, 3)), color=COLORS["fill"], lw=lw(0.8))[0]
                   for g in guides]  # fmt: skip
    h, w = np.shape(a)[:2]
    # the values sit at the pixel centres, j + 0.5 (i + 0.5): labelled as the screen position
    # they are at, not "column j", whose point sat half-way to the next column's tick
    # (review r45, lesson 00-6)
    ax.set(xlim=(0, w if axis == "row" else h), ylabel=value,
           xlabel=f"screen {'x' if axis == 'row' else 'y'} (px)")  # fmt: skip
    # whole columns (rows) only: a few pixels' span drew ticks at 2.5, 5.0, 7.5
    # along a column of a tall image, a few: seven ticks of a 120-row column touched (r77)
    ax.xaxis.set_major_locator(MaxNLocator("auto" if axis == "row" else 4, integer=True))
    title = ax.set_title("", fontsize=fs(0.9))
    result = ProfileArtists(lines, guide_lines, title, axis, int(index),
                            None if vlim is None else tuple(vlim))  # fmt: skip
    result.update(a, b)
    # along a row (own value range): the upper left, kept free by KEY_ROOM; else where best
    loc = "upper left" if axis == "row" and vlim is None else "best"
    ax.legend(loc=loc, fontsize=fs(0.75), handlelength=1.2, borderpad=0.3)
    return result


def plot_depth(
    ax, source, *, cmap=None, vmin=None, vmax=None, colorbar: bool = True, title: bool = True
) -> ImageArtists:
    """The depth buffer: window depth z_win per pixel (0 near, 1 far), NaN transparent.

    Parameters
    ----------
    ax : matplotlib Axes
    source : Fill, FillTrace, Frame or (H, W) array
        A fill needs a triangle with ``z``; a Frame gives the depth its buffer stores.
    cmap, vmin, vmax
        Colour map (default: the value colour map, dark = near) and range (default: the
        data's, for contrast; pass 0 and 1 for the full range).
    colorbar, title : bool

    Returns
    -------
    ImageArtists
    """
    if isinstance(source, Fill | Frame):
        depth = source.depth
    elif isinstance(source, FillTrace):
        depth = None if source.depth is None else source.image(source.depth)
    else:
        depth = source
    if depth is None:
        raise ValueError("no depth: give the triangle window depths, Triangle(..., z=[...])")
    result = show_values(ax, depth, cmap=cmap, vmin=vmin, vmax=vmax, colorbar=colorbar,
                   label=r"window depth $z_\mathrm{win}$ (dark = nearer)")  # fmt: skip
    if title:
        ax.set_title("depth buffer")
    return result


#: Behind a texture-mapped render, where nothing is drawn: a pale blue. On the page's white the
#: light checks of :func:`~teachraster.pipeline.texturing.texture.checkerboard` (0.92 grey)
#: merged into the background and a floor lost its outline (review r234 04-FIG3)
BEHIND_RENDER = tint(COLORS["fill"], 0.45)


def plot_image(ax, source, *, title: str | None = None, background=None) -> ImageArtists:
    """A colour image, e.g. the texture-mapped result of a scene; NaN pixels transparent.

    Parameters
    ----------
    ax : matplotlib Axes
    source : SceneFrame or (H, W, 3) array with values in [0, 1]
    title : str, optional
    background : colour, optional
        The Axes' colour, seen where nothing is drawn (NaN pixels), e.g. ``BEHIND_RENDER``;
        default: the Axes' own.

    Returns
    -------
    ImageArtists
    """
    rgb = source.image if isinstance(source, SceneFrame) else source
    if rgb is None:
        raise ValueError("this frame has no shaded image")
    result = show_values(ax, rgb)
    if background is not None:
        ax.set_facecolor(background)
    if title:
        ax.set_title(title)
    return result


# -- the render plan ---------------------------------------------------------------------------
def format_plan(plan, width: int = 64) -> str:
    """A render plan as a text table: effect, ran or skipped, how much, and why (wrapped)."""
    plan = plan.plan if isinstance(plan, Frame) else plan
    if not isinstance(plan, Plan):
        raise TypeError(f"expected a Plan or a Frame, got {type(plan).__name__}")
    lines = [f"{'effect':<12}{'':<8}how much", "-" * width]
    for e in plan:
        state = "forced" if e.forced else ("ran" if e.ran else "skipped")
        lines.append(f"{e.name:<12}{state:<8}{e.count:,} of {e.total:,} {e.unit}")
        lines += textwrap.wrap(e.why, width, initial_indent="    ", subsequent_indent="    ")
    return "\n".join(lines)


@dataclass
class PlanArtists(Artists):
    """The text of :func:`plot_plan`."""

    text: Text

    def update(self, plan) -> None:
        self.text.set_text(format_plan(plan))


def plot_plan(ax, plan, *, title: bool = True) -> PlanArtists:
    """The render plan (which effects ran, for how much, and why) as a text table.

    Parameters
    ----------
    ax : matplotlib Axes
        Its frame and ticks are turned off.
    plan : Plan or Frame
    title : bool

    Returns
    -------
    PlanArtists
    """
    ax.set_axis_off()
    text = ax.text(0.0, 1.0, format_plan(plan), transform=ax.transAxes, va="top", ha="left",
                   family="monospace", fontsize=fs(0.7))  # fmt: skip
    if title:
        ax.set_title("render plan", loc="left")
    return PlanArtists(text)
