"""``PixelInspector``: choose a pixel, see its samples, who owns each, and the edge values."""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize
from matplotlib.patheffects import withStroke

from ..core.fill import rasterize
from ..core.trace import edge_name
from ..core.triangle import Triangle
from ..pipeline.geometry.viewport import to_window
from ..pipeline.rendering.render_triangles import render
from ..plotting import plot_pixel_grid, plot_pixel_samples, plot_samples
from ..plotting.antialiasing import edge_value_text, sample_data
from ..plotting.common import nice_step
from ..plotting.style import VALUE_CMAP
from .common import (
    SAMPLE_PATTERNS,
    SLIDER_COLUMN_WIDTH,
    Holdable,
    Shown,
    close_tree,
    control_row,
    pattern_samples,
    style_context,
    title_html,
)
from .display import FigureDisplay, new_figure, png_bytes, resolve_backend
from .frame_inspector import click_image, clicked_point

#: Up to 4 samples the left panel's covered fraction is a light grey under the dots (``Greys``
#: from 0 to 1 / FEW_SAMPLES_GREY); with more it is the picture, in the colour map of lesson
#: 08's other coverage figures (VALUE_CMAP: 0 dark blue, 1 yellow; review r136 08-7).
FEW_SAMPLES_GREY = 2.5

#: The left panel shows a window of the image around the chosen pixel, each pixel at least
#: this many inches wide: the whole 20 × 14 image of lesson 08 drew 4 samples' dots about
#: 3 px across, unreadable at the back of a room (review r230 FIG2).
WINDOW_PIXEL_IN = 0.38
#: Inches kept under the window for the colour key of the covered fraction and its label.
KEY_ROOM_IN = 0.75


def window_size(ax, width: int, height: int) -> tuple[int, int]:
    """(columns, rows) of the window ``ax`` shows: as many pixels as fit at
    :data:`WINDOW_PIXEL_IN` inches each above the key's room, at most the whole image."""
    box = ax.get_position(original=True)
    fig_w, fig_h = ax.figure.get_size_inches()
    cols = max(1, int(box.width * fig_w / WINDOW_PIXEL_IN))
    rows = max(1, int((box.height * fig_h - KEY_ROOM_IN) / WINDOW_PIXEL_IN))
    return min(cols, width), min(rows, height)


def window_origin(index: int, size: int, extent: int) -> int:
    """The first column (row) of a window of ``size`` that keeps ``index`` in its middle,
    inside an image of ``extent``.

    >>> window_origin(13, 10, 20), window_origin(1, 10, 20), window_origin(19, 10, 20)
    (8, 0, 10)
    """
    return int(min(max(index - size // 2, 0), extent - size))


def fraction_key(fig, ax, width: int, height: int):
    """A horizontal colour bar under ``ax``'s grid of ``width`` x ``height`` pixels (drawn at
    equal aspect, anchored at the top of its box): the covered fraction 0 to 1 in the colours
    the left panel uses with many samples (review r61 08-2: no key said which colour is 1)."""
    box = ax.get_position()
    fig_w, fig_h = fig.get_size_inches()
    grid_h = min(box.width * fig_w * height / width / fig_h, box.height)
    bottom = box.y1 - grid_h - 0.08  # below the grid, clear of its last row
    cax = fig.add_axes((box.x0 + 0.15 * box.width, bottom, 0.7 * box.width, 0.035))
    key = fig.colorbar(ScalarMappable(Normalize(0, 1), VALUE_CMAP), cax=cax, orientation="horizontal",
                       ticks=[0, 0.25, 0.5, 0.75, 1])  # fmt: skip
    cax.tick_params(labelsize=13)
    cax.set_visible(False)
    return key


class PixelInspector(Holdable):
    """The samples of a small image, and one pixel magnified with what decided each sample.

    The left panel shows a window of the image around the chosen pixel, its pixels at least
    :data:`WINDOW_PIXEL_IN` inches wide (the whole image when it fits); a click on it picks
    a pixel (:meth:`click_at`), as the row and column sliders do.

    Parameters
    ----------
    source : Triangle or (N, 3, 4) clip-space array
        One triangle (``tr.rasterize`` with the trace: every sample labelled with its edge
        values) or a scene (``tr.render``: every sample labelled with the triangle it shows).
    width, height : int
    pattern : str
        A key of :data:`teachraster.widgets.common.SAMPLE_PATTERNS`.
    row, col : int
        The pixel shown magnified first.
    backend, style
        As for the other widgets.

    Examples
    --------
    >>> import teachraster as tr
    >>> w = PixelInspector(tr.Triangle([[0.6, 0.4], [9.3, 2.1], [2.2, 7.7]]), 10, 8,
    ...                    backend="image")
    >>> w.col.value = 6; w.row.value = 2
    >>> int(w.result.sample_coverage[2, 6].sum())
    4
    >>> w.click_at(3.5, 5.5); (w.row.value, w.col.value)  # a click at window (x, y)
    (5, 3)
    >>> w.pattern.value = "16 standard"
    >>> len(w.pixel.dots)
    16
    >>> w.close()
    """

    #: ``teachraster html``: the offline page steps through every sample pattern (:mod:`.offline`)
    _offline_sweep_ = "pattern"

    def __init__(self, source, width: int = 12, height: int = 10, *,
                 pattern: str = "4 standard (rotated grid)", row: int = 0, col: int = 0,
                 backend: str = "auto", style: str | None = None) -> None:  # fmt: skip
        self.source, self.width, self.height = source, width, height
        self._style = style  # labels redrawn on a change keep the figure's sizes
        self.backend = resolve_backend(backend)
        self.pattern = widgets.Dropdown(options=list(SAMPLE_PATTERNS), value=pattern,
                                        description="samples")  # fmt: skip
        self.row = widgets.IntSlider(value=row, min=0, max=height - 1, description="row")
        self.col = widgets.IntSlider(value=col, min=0, max=width - 1, description="col")
        self._compute()
        with style_context(style):
            fig = new_figure((9, 4.4), self.backend)  # fits the notebook column
            # room on the left for the y label; the right panel's labels at classroom size
            left, right = (
                fig.add_axes((0.09, 0.13, 0.43, 0.73)),
                fig.add_axes((0.6, 0.1, 0.39, 0.66)),
            )
            plot_pixel_grid(left, width, height)
            left.set_anchor("N")  # the grid at the top of its box: room for the key under it
            self._left = left
            # the window first: the dots are sized for the pixels as large as it draws them
            self._window_size = window_size(left, width, height)
            self._show_window()
            # the dots as large as the window's pixels allow (each pixel's samples apart)
            self.samples = plot_samples(left, self.result, largest=1.2)
            for tri in self._triangles():
                closed = np.vstack([tri, tri[:1]])
                # a white rim: the black edge shows on the dark blue of an empty pixel too
                left.plot(
                    closed[:, 0],
                    closed[:, 1],
                    color="k",
                    lw=1.2,
                    path_effects=[withStroke(linewidth=3.5, foreground="white")],
                )
            # not clipped: the last row's and column's pixels are marked whole
            self.marker = left.plot([], [], color="#D55E00", lw=2.5, zorder=6, clip_on=False)[0]
            # what the left panel shows, under it (its column label sits on top)
            self._left_note = left.text(0.5, -0.03, "", transform=left.transAxes, ha="center",
                                        va="top", fontsize=14)  # fmt: skip
            self.fraction_key = fraction_key(fig, left, *self._window_size)
            self.pixel = plot_pixel_samples(right, self.result, row, col,
                                            triangles=self._pixel_triangles())  # fmt: skip
            self._mark()
            self._few_or_fraction()
            self.fig = fig
            picture = self._make_display()
        for control in (self.pattern, self.row, self.col):
            control.observe(self._changed, "value")
        title = title_html(
            "Pixel inspector: coverage sample by sample",
            "Pick a pixel (click it on the left, or move row and col): each of its samples is "
            "tested against the edges like a pixel centre (top-left rule included). Change the "
            "pattern to see what it catches.",
        )
        controls = control_row([self.pattern, self.row, self.col])
        #: every sample's edge values in a table (a label per sample fits up to 4 only)
        self.table = widgets.HTML(self._table_html())
        self.widget = widgets.VBox([title, controls, picture, self.table])

    def _compute(self) -> None:
        samples = pattern_samples(self.pattern.value)
        if isinstance(self.source, Triangle):
            self.result = rasterize(self.source, self.width, self.height, samples=samples,
                                    trace=True)  # fmt: skip
            if self.result.sample_coverage is None:  # one sample: show it as a pattern of one
                self.result = rasterize(self.source, self.width, self.height,
                                        samples=[[0.5, 0.5]], trace=True)  # fmt: skip
        else:
            if isinstance(samples, int) and samples == 1:
                samples = [[0.5, 0.5]]
            self.result = render(self.source, self.width, self.height, samples=samples)

    def _triangles(self):
        if isinstance(self.source, Triangle):
            return [np.asarray(self.source.xy)]
        return list(to_window(np.asarray(self.source, float), self.width, self.height)[..., :2])

    def _pixel_triangles(self):
        return None if isinstance(self.source, Triangle) else self._triangles()

    def _few_or_fraction(self) -> None:
        """Up to 4 samples per pixel the left panel draws every sample; with more they are a
        field of overlapping dots, so it shows each pixel's covered fraction (in VALUE_CMAP, as
        the lesson's coverage figures) and leaves the samples to the magnified pixel."""
        n = len(sample_data(self.result)[1])
        few = n <= 4
        self.samples.covered.set_visible(few)
        self.samples.uncovered.set_visible(few)
        if self.samples.fraction is not None:  # the lesson's colours when they are the picture
            image = self.samples.fraction.image
            image.set_cmap("Greys" if few else VALUE_CMAP)
            image.set_clim(0, FEW_SAMPLES_GREY if few else 1.0)
        self._left_note.set_text("every sample around it (filled = covered)" if few else "")
        # with more samples the colours are the picture: a key says which is which fraction
        self.fraction_key.ax.set_visible(not few)
        self.fraction_key.set_label(f"{n} samples: covered fraction", fontsize=14)

    def _mark(self) -> None:
        r, c = self.row.value, self.col.value
        self.marker.set_data([c, c + 1, c + 1, c, c], [r, r, r + 1, r + 1, r])
        self._show_window()

    def _show_window(self) -> None:
        """Move the left panel's window to keep the chosen pixel in its middle, its ticks
        screen coordinates x and y on the pixels' borders, as the magnified pixel's: pixel
        (row i, col j) lies between the ticks j and j + 1 in both panels."""
        (cols, rows), ax = self._window_size, self._left
        c0 = window_origin(self.col.value, cols, self.width)
        r0 = window_origin(self.row.value, rows, self.height)
        ax.set_xlim(c0, c0 + cols)
        ax.set_ylim(r0 + rows, r0)
        for axis, start, n, name in ((ax.xaxis, c0, cols, "x"), (ax.yaxis, r0, rows, "y")):
            step = nice_step(n)
            at = [i for i in range(start, start + n + 1) if i % step == 0]
            axis.set_ticks(at, labels=[str(i) for i in at])
            axis.set_label_text(name)

    # -- display and clicks --------------------------------------------------------------
    def _make_display(self):
        """The widget that shows the figure: ipympl's canvas (clicks through matplotlib), a
        picture that reports clicks (anywidget), or a plain picture without anywidget."""
        self.display, self.clicker = None, None
        if self.backend == "ipympl":
            self.display = FigureDisplay(self.fig, "ipympl")
            self.fig.canvas.mpl_connect("button_press_event", self._on_press)
            return self.display.widget
        self.clicker = click_image(alt="the pixel inspector: click a pixel on the left")
        if self.clicker is None:
            self.display = FigureDisplay(self.fig, "image")
            return self.display.widget
        self.clicker.observe(self._on_click, "click")
        # never wider than the column less ipywidgets' margins, as FigureDisplay's picture
        self.clicker.layout = widgets.Layout(max_width=SLIDER_COLUMN_WIDTH)
        self._refresh()
        return self.clicker

    def _refresh(self) -> None:
        if self.display is not None:
            self.display.refresh()
            return
        self.fig.canvas.draw()
        self.clicker.value = png_bytes(self.fig)

    def click_at(self, x: float, y: float) -> None:
        """Choose the pixel under window point (x, y) (pixels, y down), as a click does."""
        col, row = int(np.floor(x)), int(np.floor(y))
        if 0 <= row < self.height and 0 <= col < self.width:
            with self._holding():
                self.row.value, self.col.value = row, col
            self._changed({"owner": self.row})

    def _on_press(self, event) -> None:
        if event.inaxes is self._left and event.xdata is not None:
            self.click_at(event.xdata, event.ydata)

    def _on_click(self, change) -> None:
        point = clicked_point(self.fig, self._left, change["new"], inside=True)
        if point is not None:
            self.click_at(*point)

    def _changed(self, change) -> None:
        if self._quiet:
            return
        if change["owner"] is self.pattern:
            self._compute()
            self.samples.update(self.result)
            self._few_or_fraction()
        with style_context(self._style):
            self.pixel.update(self.result, self.row.value, self.col.value,
                              triangles=self._pixel_triangles())  # fmt: skip
        self._mark()
        self.table.value = self._table_html()
        self._refresh()

    def _table_html(self) -> str:
        """The chosen pixel's samples: offset, edge values (px², positive = inside) and
        whether covered; a value exactly 0 is on its edge, and the sample is covered only if
        that edge is a top or left edge. Empty for a scene (its samples show triangles)."""
        trace = getattr(self.result, "trace", None)
        if trace is None or getattr(trace, "samples", None) is None:
            return ""
        r, c = self.row.value, self.col.value
        values = trace.samples.edge_values(r, c)
        names = [edge_name(a, b) for a, b in trace.edges]
        # which edges take a sample exactly on them (review r230 S8: nothing said which)
        top_left = [n for n, tl in zip(names, trace.samples.top_left) if tl]
        # a property of the triangle, not of this pixel (review r313 S3)
        rule = (f"the triangle's top or left edge(s), which cover a sample exactly on them: "
                f"{', '.join(top_left) or 'none'}")  # fmt: skip
        covered = self.result.sample_coverage[r, c]
        offsets = self.result.samples
        head = "".join(f"<th>{n}</th>" for n in ("sample", "offset (x, y)", *names, "covered"))
        rows = []
        for s, (e, (ox, oy)) in enumerate(zip(values, offsets)):
            cells = "".join(
                f"<td>{edge_value_text(v)}{' (on the edge)' if v == 0 else ''}</td>" for v in e
            )
            rows.append(f"<tr><td>s{s}</td><td>({ox:.4f}, {oy:.4f})</td>{cells}"
                        f"<td>{'yes' if covered[s] else 'no'}</td></tr>")  # fmt: skip
        return (
            f"<details{' open' if len(offsets) > 4 else ''}><summary>pixel (row {r}, col {c}): every sample's edge values (px², positive = "
            f"inside); {rule}</summary><table class='tr-samples' style='font-variant-numeric:"
            f"tabular-nums'><tr>{head}</tr>{''.join(rows)}</table></details>"
        )

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_
    noun = "inspector"  # the stand-in's hint: "No kernel is running this inspector"

    def close(self) -> None:
        """Close every widget of the inspector."""
        if self.display is not None:
            self.display.close()
        close_tree(self.widget)
