"""Figures inside widgets: an ipympl canvas, or a PNG in an ``ipywidgets.Image``.

With ``%matplotlib widget`` (ipympl) the figure's canvas *is* a widget: it goes into the box
as it is and redraws in the browser when asked (``draw_idle``). With any other backend
(the inline default, and headless runs such as nbclient) the figure is drawn by Agg and its
PNG bytes go into an ``ipywidgets.Image``, replaced at each update. Either way the figure is
made here, not by pyplot, so it is never also shown a second time by the inline backend at
the end of a cell, and it does not pile up in pyplot's list of open figures.
"""

from __future__ import annotations

import functools
import math
import sys

import ipywidgets as widgets
import matplotlib as mpl
import numpy as np
from matplotlib.figure import Figure
from matplotlib.text import Text

from ..plotting.common import fs
from ..plotting.frames import encode_png
from .common import SLIDER_COLUMN_WIDTH

BACKENDS = ("auto", "ipympl", "image")

#: Resolution of figures shown as PNG images: crisp on an ordinary screen, and small enough
#: for a step to be drawn, encoded and sent within a Play interval.
IMAGE_DPI = 96
#: Resolution of the three-panel comparison figures: lower, so that they fit the width of a
#: notebook also as an ipympl canvas (which, unlike an image, does not scale down).
COMPARISON_DPI = 80


def resolve_backend(backend: str = "auto") -> str:
    """``"ipympl"`` or ``"image"``: how figures are shown.

    Parameters
    ----------
    backend : {"auto", "ipympl", "image"}
        ``"auto"`` picks ipympl when matplotlib's backend is ipympl (``%matplotlib widget``
        or ``%matplotlib ipympl``), else a PNG image.

    Examples
    --------
    >>> resolve_backend("image")
    'image'
    """
    if backend not in BACKENDS:
        raise ValueError(f"backend must be one of {BACKENDS}, got {backend!r}")
    if backend != "auto":
        return backend
    # get_backend() would *resolve* a pending auto backend (and may import a GUI toolkit);
    # the raw rcParam says what the user chose without side effects.
    name = str(dict.__getitem__(mpl.rcParams, "backend")).lower()
    return "ipympl" if ("ipympl" in name or "widget" in name) else "image"


def new_figure(figsize: tuple[float, float], mode: str, *, dpi: float | None = None) -> Figure:
    """A figure with a canvas suited to ``mode`` (``"ipympl"`` or ``"image"``), not in pyplot."""
    if mode == "ipympl":
        FigureManager = ipympl_module().FigureManager  # noqa: N806 (ipympl's class)

        fig = Figure(figsize=figsize, dpi=dpi)
        canvas = fast_ipympl_canvas()(fig)
        # The manager wires the canvas to its toolbar and the browser; registering it with
        # pyplot (as plt.figure would) would show the figure a second time.
        FigureManager(canvas, 0)
        canvas.header_visible = False
        canvas.footer_visible = False
        canvas.resizable = False
        canvas.toolbar_visible = False
        return fig
    if mode != "image":
        raise ValueError(f"mode must be 'ipympl' or 'image', got {mode!r}")
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = Figure(figsize=figsize, dpi=dpi or IMAGE_DPI)
    FigureCanvasAgg(fig)
    return fig


@functools.cache
def ipympl_module():
    """``ipympl.backend_nbagg``, imported without leaving it as pyplot's backend.

    Importing it makes ipympl matplotlib's backend as a side effect; a widget that asks for
    an ipympl canvas of its own must not change what ``plt.show()`` does in the student's
    other cells (nor in the tests that run after it), so the backend setting is put back.
    """
    raw = dict.__getitem__(mpl.rcParams, "backend")  # as set, unresolved
    import ipympl.backend_nbagg as module

    dict.__setitem__(mpl.rcParams, "backend", raw)
    return module


@functools.cache
def fast_ipympl_canvas():
    """ipympl's Canvas, encoding the frames it sends with :func:`encode_png`.

    ipympl sends each new frame as a PNG of the pixels that changed (transparent elsewhere),
    encoded by Pillow at its default level: 10-15 ms for a notebook-wide figure, more than
    a blitted step costs. This subclass encodes the same pixels the fast way; the browser
    side is ipympl's own.
    """

    class FastCanvas(ipympl_module().Canvas):
        def get_diff_image(self):
            # matplotlib's FigureCanvasWebAggCore.get_diff_image, but for the encoder
            if not self._png_is_old:
                return None
            pixels = np.asarray(self.get_renderer().buffer_rgba())
            buff = pixels.view(np.uint32).squeeze(2)
            # any transparency forces a full frame; on little-endian machines alpha is the
            # high byte of each 32-bit pixel, so one contiguous comparison finds it
            clear = (buff < 0xFF000000).any() if sys.byteorder == "little" else (
                pixels[:, :, 3] != 255).any()  # fmt: skip
            if self._force_full or buff.shape != self._last_buff.shape or clear:
                self.set_image_mode("full")
                output = buff
            else:
                self.set_image_mode("diff")
                output = np.where(buff != self._last_buff, buff, 0)
            self._last_buff = buff.copy()
            self._force_full = False
            self._png_is_old = False
            return encode_png(output.view(np.uint8).reshape(*output.shape, 4))

    return FastCanvas


def png_bytes(fig: Figure) -> bytes:
    """The figure's last Agg drawing as PNG bytes (draw the figure first).

    The Agg buffer goes to zlib as it is (RGBA, no PNG filter, the fastest compression
    level): a few milliseconds for a figure of a notebook's width, where ``savefig`` would
    draw the figure again and Pillow's default encoding takes several times longer, for a
    file about as small (figures are mostly flat colour).
    """
    return encode_png(np.asarray(fig.canvas.buffer_rgba()))


class FigureDisplay:
    """A figure and the widget that shows it; :meth:`refresh` after changing its artists.

    Parameters
    ----------
    fig : Figure
        Made by :func:`new_figure` with the same ``mode``.
    mode : {"ipympl", "image"}
    draw : callable, optional
        Renders the figure into its Agg canvas (for example a view's blitting ``redraw``);
        default ``fig.canvas.draw``. Under ipympl the result is then sent with
        ``canvas.blit()``, so every refresh reaches the browser (no skipped steps).

    Attributes
    ----------
    widget : ipywidgets widget
        The ipympl canvas itself, or an ``ipywidgets.Image`` holding the PNG.
    draws : int
        How many times :meth:`refresh` has run (for tests).
    """

    def __init__(self, fig: Figure, mode: str, draw=None) -> None:
        self.fig = fig
        self.mode = mode
        self.draw = draw
        self.draws = 0
        if mode == "ipympl":
            fit_column(fig)
            self.widget = fig.canvas
        else:
            # natural size (the width is set by refresh), but never wider than the notebook
            # column (the image scales down): the column less ipywidgets' margin on each
            # side, or a figure wider than the column overflowed its box by 4 px and
            # scrolled (the PixelInspector at a 1280-px window, review r194)
            layout = widgets.Layout(max_width=SLIDER_COLUMN_WIDTH, height="auto")
            self.widget = widgets.Image(format="png", layout=layout)
            self.widget.add_class("teachraster-figure")  # a handle for browser tests
        self.refresh()

    def refresh(self, png: bytes | None = None) -> None:
        """Show the figure's current state.

        ipympl: draw with the given ``draw`` and send the new pixels (``canvas.blit``), or
        without one ask the browser for a redraw (``draw_idle``); image: draw with Agg now
        and replace the PNG. ``png`` (image mode): show this picture, drawn before (a
        picture kept, :class:`~teachraster.widgets.ahead.PicturesAhead`), instead.
        """
        if png is not None:
            if self.mode == "ipympl":
                raise ValueError("png: only an image display shows a picture drawn before")
            self.widget.value = png
            return
        self.draws += 1
        canvas = self.fig.canvas
        if self.mode == "ipympl":
            if self.draw is None:
                canvas.draw_idle()
            else:
                self.draw()
                canvas.blit(self.fig.bbox)
            return
        (canvas.draw if self.draw is None else self.draw)()
        # the widget's width follows the figure's, which may have been resized since: the
        # inspector's history chart widens in glass (review r274 FIG1: kept at its first
        # width, the image was shrunk by 0.66 and its text read 9 px instead of 14)
        self.widget.layout.width = f"{int(round(self.fig.get_figwidth() * self.fig.dpi))}px"
        self.widget.value = png_bytes(self.fig)

    def close(self) -> None:
        """Release the widget (and the browser-side canvas)."""
        self.widget.close()


def fit_column(fig: Figure) -> None:
    """Lower the figure's dpi so that it is at most as wide as the notebook column.

    An ipympl canvas, unlike an image, does not scale down: a figure wider than the column
    is cut off (its legend, its colour bars).
    """
    from ..plotting.style import COLUMN_WIDTH_PX

    width = fig.get_figwidth() * fig.dpi
    if width > COLUMN_WIDTH_PX:
        fig.set_dpi(fig.dpi * COLUMN_WIDTH_PX / width)


def comparison_axes(fig: Figure, height: int, width: int, colorbars=(True, True), *,
                    below: bool = False, profile: bool = False, ticks: bool = True,
                    panel: float = 1.0) -> list:  # fmt: skip
    """Three equal panels for a ComparisonView / InterpolationView, as many per row as fit.

    The views add colour bars to the middle and right panels with ``fig.colorbar(ax=...)``,
    which takes 20% of the panel's width; those panels are made wider by as much here, so
    that all three images end up the same size. ``colorbars`` says which of the middle and
    right panels get one; ``below`` leaves a line of room under the panels (for a note such
    as "in use"). The figure is resized to fit.

    Margins, gaps and the panels themselves grow with the font size (``font_scale``), as in
    ``fill_axes``: with ``use_style("classroom")`` the titles, the row labels and the colour
    bars' labels keep their room instead of overlapping or being cut off. Panels that would
    make the figure wider than the notebook column (``COLUMN_WIDTH_PX`` at the figure's dpi)
    wrap onto a second row: shrinking the figure instead would shrink its text.

    With ``profile`` a fourth Axes (for :func:`~teachraster.plotting.plot_profile`) fills the
    rest of a row the heatmap has to itself, so that no quarter of the figure stays empty;
    it is None when the three panels share one row (there is no empty room to fill).

    ``ticks=False``: no panel shows tick labels (``TexturedPlaneViewer``'s renders), so the
    room kept for them goes: the first row keeps room for its titles alone, and when the
    heatmap's row wraps, the first row's panels grow to fill the column and the profile
    sits nearer the colour bar (review r219 04-3: the titles floated ~70 px above two small
    renders, and a wide gap parted the colour bar from the profile).

    ``panel``: the panels' size relative to the default, the margins kept. A figure shown
    scaled down to a height (the FillPlayer's, :data:`~teachraster.widgets.player.COMPARISON_MAX_PX`)
    keeps larger text with smaller panels (review r225 FIG1).
    """
    from .common import font_scale

    s = font_scale()
    pw = 2.6 * max(1.0, 0.75 * s) * panel  # inches per panel: titles need room at large fonts
    ph = pw * height / width
    if ph > 3.2 * max(1.0, 0.75 * s) * panel:  # tall images: limit the height instead
        ph = 3.2 * max(1.0, 0.75 * s) * panel
        pw = ph * width / height
    # left: row tick labels and "row i"; top: title above the column tick labels and
    # "column j"; gap and right: a colour bar's tick labels and its label
    left, top = (0.6 * s, 0.8 * s) if ticks else (0.25 * s, 0.45 * s)
    bottom = 0.2 + (0.3 * s if below else 0.0)
    gaps = [0.35 * s] + [(0.75 * s if c else 0.35 * s) for c in colorbars]
    widths = [pw] + [pw / 0.8 + 0.3 if c else pw for c in colorbars]
    rows = _wrap_panels(widths, gaps, left, column_inches(fig))
    fw = max(left + sum(widths[i] + gaps[i] for i in row) for row in rows)
    # only the first row has the first panel's column labels above it: a wrapped row needs
    # room for its title alone
    tops = [top] + [0.45 * s] * (len(rows) - 1)
    # the profile's row needs room under it for its tick labels and axis label
    alone = profile and len(rows) > 1 and len(rows[-1]) == 1
    bottoms = [bottom] * (len(rows) - 1) + [max(bottom, 0.2 + 0.6 * s) if alone else bottom]
    # after the heatmap's gap, room for the profile's value labels on its left; without
    # ticks, 0.85 s after the heatmap's panel in all (its colour bar's labels lie inside it)
    profile_gap = 0.85 * s if ticks else 0.85 * s - gaps[rows[-1][-1]]
    if alone and not ticks:  # the column's width: the first row's panels grow into it
        fw = max(fw, column_inches(fig))
    elif alone:  # the profile as wide as a panel, if the column has room for it
        start = left + widths[rows[-1][0]] + gaps[rows[-1][0]] + profile_gap
        fw = min(max(fw, start + pw + 0.25), max(fw, column_inches(fig)))
    grow = [_row_growth(fw - left - 0.25, [widths[i] for i in row],
                        [gaps[i] for i in row[:-1]]) if not ticks and alone and k == 0 else 1.0
            for k, row in enumerate(rows)]  # fmt: skip
    fh = sum(ph * g + t + b for g, t, b in zip(grow, tops, bottoms))
    fig.set_size_inches(fw, fh)
    axes = []
    y = fh
    for row, g, t, b in zip(rows, grow, tops, bottoms):
        x, y = left, y - (ph * g + t + b)
        for i in row:
            axes.append(fig.add_axes((x / fw, (y + b) / fh, widths[i] * g / fw, ph * g / fh)))
            x += widths[i] * g + gaps[i]
    if profile:
        # the rest of the heatmap's row, less room for the profile's value labels on its left
        x += profile_gap
        room = fw - x - 0.25
        axes.append(fig.add_axes((x / fw, (y + bottoms[-1]) / fh, room / fw, ph / fh))
                    if alone and room > 0.5 * pw else None)  # fmt: skip
    return axes


def _row_growth(room: float, widths, gaps, most: float = 1.6) -> float:
    """How much a row's panels may grow (at least 1, at most ``most``) to fill ``room``
    inches with their ``gaps`` between them.

    >>> _row_growth(10.0, [3.0, 3.0], [1.0])
    1.5
    """
    return float(min(most, max(1.0, (room - sum(gaps)) / sum(widths))))


def column_inches(fig: Figure) -> float:
    """How many inches of ``fig`` fit the notebook column at the figure's dpi."""
    from ..plotting.style import COLUMN_WIDTH_PX

    return COLUMN_WIDTH_PX / fig.dpi


def _wrap_panels(widths, gaps, left: float, limit: float) -> list[list[int]]:
    """Panel indices per row: each row as wide as fits ``limit`` inches (at least one panel)."""
    rows: list[list[int]] = [[]]
    used = left
    for i, (w, gap) in enumerate(zip(widths, gaps)):
        if rows[-1] and used + w + gap > limit:
            rows.append([])
            used = left
        rows[-1].append(i)
        used += w + gap
    return rows


def html_escape(text: str) -> str:
    """``text`` safe to put in an HTML widget (captions contain ``<`` and ``>``)."""
    import html

    return html.escape(text, quote=False)


#: The smallest text on screen a figure may show (CSS px): the course's projector rule.
MIN_TEXT_PX = 12.0


def readable_text(
    axes=(), *, profile=None, texts=(), shown_px: float | None = None, min_px: float = MIN_TEXT_PX
) -> None:
    """Tick labels of ``axes`` (colour bars' too), the labels drawn in them (v1, v2, v3), a
    profile's ticks, title and legend, and ``texts``: at least the style's font size.

    A comparison figure is drawn at :data:`COMPARISON_DPI`, about 940 px wide, and shown
    shrunk to the column: 585 px at 1024 x 768 with the file browser open, where the style's
    smaller sizes (ticks 15 pt, legends 13.5) came out at 9-11 px (reviews r7 and r9, lesson
    04's viewer and the players' comparison); at the style's 18 pt they read 12. The vertex
    labels, drawn a little smaller for the full-size fill figure, read 11.8 px there (reviews
    r13 and r15, lesson 00's player): they are raised too.

    ``shown_px``: the width the figure is shown at when that is narrower still (an
    accordion's padding takes some of the column): every text of the figure (axis labels
    and titles too) is raised to what reads ``min_px`` there (default :data:`MIN_TEXT_PX`),
    where the style's size does not.
    """
    size = fs(1.0)
    fig = next((a.figure for a in axes if a is not None), None)
    if shown_px is not None and fig is not None:
        width = fig.get_figwidth() * fig.dpi
        # px on screen = points × dpi / 72 × shown / width
        need = min_px * width / min(shown_px, width) * 72 / fig.dpi
        size = max(size, math.ceil(need * 2) / 2)  # a half point up: pixels round
        for text in fig.findobj(Text):
            text.set_fontsize(max(size, text.get_fontsize()))
    for ax in [a for a in axes if a is not None]:
        ax.tick_params(labelsize=size)
        for text in ax.texts:
            text.set_fontsize(max(size, text.get_fontsize()))
    if profile is not None:
        profile.title.axes.tick_params(labelsize=size)
        profile.title.set_fontsize(size)
        legend = profile.title.axes.get_legend()
        if legend is not None:
            for text in legend.get_texts():
                text.set_fontsize(size)
    for text in texts:
        if text is not None:
            text.set_fontsize(size)
