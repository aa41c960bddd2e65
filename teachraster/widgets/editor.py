"""``TriangleEditor``: move the vertices of a triangle and watch the fill and the error follow."""

from __future__ import annotations

import math
import time

import ipywidgets as widgets
import numpy as np

from ..core.edges import edge_function
from ..core.fill import rasterize
from ..core.triangle import Triangle
from ..core.validate import as_finite, as_size
from ..plotting import COLORS, FillView, InterpolationView
from ..plotting.blitting import MOVING
from .common import (
    Holdable,
    close_tree,
    control_row,
    display_with_fallback,
    fill_axes,
    fit_width,
    labelled,
    standin_html,
    style_context,
    title_html,
)
from .display import COMPARISON_DPI, FigureDisplay, comparison_axes, new_figure, resolve_backend
from .dragging import PageDisplay, comparison_edit_blit, fill_edit_blit, hidden, same_or_new

#: Step of the x and y sliders: the rasteriser's snapping grid (8 sub-pixel bits).
GRID = 1 / 256


def on_grid(value: float, direction: int = 0) -> float:
    """``value`` on the 1/256 px grid: nearest, or rounded down (-1) or up (1).

    >>> on_grid(10.6123), on_grid(-1.3, -1)
    (10.61328125, -1.30078125)
    """
    scaled = float(value) / GRID
    whole = (
        round(scaled) if direction == 0 else (math.floor if direction < 0 else math.ceil)(scaled)
    )
    return whole * GRID


#: Key entries of a fill's steps, not of a finished fill (the editor has no current step).
STEP_ONLY = {"pixel under test, × centre", "raster line, its pixels", "span x_left .. x_right",
             "its centre covered", "its centre not", "block under test"}  # fmt: skip

#: Range of the w sliders: w is a depth, so the slider is logarithmic (equal steps are equal
#: ratios, which is what perspective depends on).
W_RANGE = (0.2, 10.0)

#: Step of the w sliders in log10 w: 30 steps per doubling (about 2.3 % each).
W_STEP = math.log10(2) / 30


def w_grid(w: float) -> tuple[float, float]:
    """(min, max) in log10 of a w slider that starts at ``w``: W_RANGE (or more, to hold
    ``w``) on a grid of W_STEP that runs through ``w`` itself.

    The page snaps a log slider's start to min + k·step and sends that back: with a grid
    from log10(0.2), the tour's w3 = 4 came back as 3.99 (review r256 W1).

    >>> lo, hi = w_grid(4.0)
    >>> round((math.log10(4.0) - lo) / W_STEP, 9) % 1, 10**lo <= 0.2, 10**hi >= 10
    (0.0, True, True)
    """
    at = math.log10(w)
    below = math.ceil(round((at - math.log10(W_RANGE[0])) / W_STEP, 9))
    above = math.ceil(round((math.log10(W_RANGE[1]) - at) / W_STEP, 9))
    return at - max(below, 0) * W_STEP, at + max(above, 0) * W_STEP


def w_value(value: float) -> float:
    """A w slider's value to 12 significant digits: the page sends base**(min + k·step),
    an ulp or two off the w it started at (4.000000000000001 for 4)."""
    return float(f"{float(value):.12g}")


class TriangleEditor(Holdable):
    """Edit a triangle's vertices (x, y and w) and see the fill, u4 and the error heatmap follow.

    Two figures update in place at every change: a :class:`~teachraster.plotting.FillView`
    of the finished fill (with span tables: the split line at u4 and the two flat parts) and
    an :class:`~teachraster.plotting.InterpolationView` of one attribute, affine vs
    perspective-correct, with the heatmap of their difference. It grows where w changes
    fastest across the triangle, and vanishes when all three w are equal.

    The vertices can be dragged in the fill figure with the pointer: in the page
    (:mod:`teachraster.widgets.dragging`: pointer feedback at once, positions coalesced so
    the kernel renders the latest, the release exact), or under ipympl with matplotlib's
    events; the sliders follow. Each move redraws only the triangle's artists over cached
    backgrounds.

    Parameters
    ----------
    tri : Triangle
        The starting triangle. If it has no attribute ``attribute``, ``u = [0, 1, 0]`` is
        added (0 at v1 and v3, 1 at v2).
    width, height : int
        Image size in pixels.
    method : {"span", "halfplane"}
        Fill method shown (span tables show the split at u4).
    attribute : str
        Attribute compared in the interpolation figure.
    backend : {"auto", "ipympl", "image"}
        As for :class:`~teachraster.widgets.FillPlayer`.
    style : str, optional
        Plotting style for this widget's figures.
    probe : (2,) array-like, optional
        A point (x, y) in pixels, marked in the fill figure, at which the info line gives the
        three edge functions E12, E23, E31 of the vertices as given (lesson 02): all three
        positive inside a clockwise triangle, all negative inside a counter-clockwise one.
        The cross is dragged like a vertex (in the page; :meth:`set_probe` from code).
    comparison : bool
        Show the interpolation figure (affine vs perspective-correct, lesson 04). Lesson 02,
        whose w are all 1, leaves it out, and the w sliders with it (``w`` still holds them);
        the figure is then not made at all (``interp_view`` and ``interp_display`` are None),
        so no picture of it sits in a saved notebook's widget state.

    Attributes
    ----------
    widget : ipywidgets.VBox
    x, y, w : lists of three sliders
        ``x[i]``, ``y[i]``: vertex i in pixels; ``w[i]``: its clip-space w (depth).
    method : ToggleButtons
    info : HTML
        Area and winding, pixels covered, u4 and the largest interpolation error in words.
    view, interp_view : FillView, InterpolationView or None
    fig : Figure
        The FillView's figure, shown whole in one ``<img>`` (or the ipympl canvas);
        ``view.ax`` is its Axes and ``xy`` the vertices, so a vertex's place on the page
        follows from ``view.ax.transData``.
    tri, fill : Triangle, Fill
        What is on show.
    last_update_s : float
        Seconds the last re-render took (kernel side).

    Examples
    --------
    >>> import teachraster as tr
    >>> editor = TriangleEditor(tr.Triangle([[1, 1], [14, 4], [5, 14]]), 16, 16, backend="image")
    >>> editor.x[1].value = 9.0
    >>> editor.fill.trace.snapped[1].tolist()
    [9.0, 4.0]
    >>> editor.close()
    """

    def __init__(
        self,
        tri: Triangle,
        width: int,
        height: int,
        *,
        method: str = "span",
        attribute: str = "u",
        backend: str = "auto",
        style: str | None = None,
        probe=None,
        comparison: bool = True,
    ) -> None:
        if not isinstance(tri, Triangle):
            raise TypeError(f"tri must be a teachraster.Triangle, got {type(tri).__name__}")
        attrs = dict(tri.attrs)
        attrs.setdefault(attribute, [0.0, 1.0, 0.0])
        self.tri = Triangle(tri.xy, w=tri.w, z=tri.z, attrs=attrs)
        self.width, self.height = as_size("width", width), as_size("height", height)
        self.attribute = attribute
        self.probe = None if probe is None else as_finite("probe", probe, (2,))
        if not isinstance(comparison, bool):
            raise TypeError(f"comparison must be True or False, got {comparison!r}")
        self.comparison = comparison
        self.backend = resolve_backend(backend)
        self._dragging: int | None = None
        self._pending = None
        self._drag_xy = None  # the vertices during a drag in the page (the sliders wait)
        self._last_done = 0.0
        self.last_update_s = 0.0
        self.fill = self._rasterize(self.tri, method)

        with style_context(style):
            self._make_figures()

        # -- controls ---------------------------------------------------------------------------
        xy, w = self.tri.xy, self.tri.w
        style_kw = {"description_width": "95px"}
        layout = fit_width(widgets.Layout(width="320px"))
        self.x, self.y, self.w, columns = [], [], [], []
        for i in range(3):
            x = widgets.FloatSlider(value=on_grid(xy[i, 0]), min=on_grid(min(0.0, xy[i, 0]), -1),
                                    max=on_grid(max(float(width), xy[i, 0]), 1), step=GRID,
                                    description=f"x{i + 1} (px)", readout_format=".2f",
                                    style=style_kw, layout=layout)  # fmt: skip
            y = widgets.FloatSlider(value=on_grid(xy[i, 1]), min=on_grid(min(0.0, xy[i, 1]), -1),
                                    max=on_grid(max(float(height), xy[i, 1]), 1), step=GRID,
                                    description=f"y{i + 1} (px)", readout_format=".2f",
                                    style=style_kw, layout=layout)  # fmt: skip
            lo, hi = w_grid(w[i])  # the grid runs through w[i]: the page keeps it exact
            wi = widgets.FloatLogSlider(value=w[i], base=10, min=lo, max=hi, step=W_STEP,
                                        description=f"w{i + 1} (depth)", readout_format=".2f",
                                        style=style_kw, layout=layout)  # fmt: skip
            for s in (x, y, wi):
                s.observe(self._on_slider, "value")
            self.x.append(x)
            self.y.append(y)
            self.w.append(wi)
            # without the comparison a w changes nothing on show: no slider for it (review
            # r93 02-9: three dead sliders); ``w[i]`` still sets it from code
            shown = [x, y, wi] if comparison else [x, y]
            columns.append(widgets.VBox([widgets.HTML(f"<b>vertex v{i + 1}</b>"), *shown]))
        self.method = widgets.ToggleButtons(
            options=[("span tables", "span"), ("half-planes", "halfplane")],
            value=method,
        )
        self.method.style.button_width = "auto"
        self.method.observe(self._on_method, "value")
        # room for three lines (an HTML widget's line is --jp-widgets-inline-height high):
        # the probe's line wraps once when the cross enters a triangle walked
        # counter-clockwise, and the figure below jumped 28 px under the pointer in mid-drag
        # (review r328 02-3)
        self.info = widgets.HTML(
            layout=widgets.Layout(min_height="calc(3 * var(--jp-widgets-inline-height, 28px))")
        )
        self._set_info()

        hint = (
            "Drag a vertex in the upper figure, or move it and change its depth w here"
            if comparison
            else "Drag a vertex in the figure, or move it here"
        )
        if self.backend == "ipympl":
            self.fig.canvas.mpl_connect("button_press_event", self._on_press)
            self.fig.canvas.mpl_connect("motion_notify_event", self._on_motion)
            self.fig.canvas.mpl_connect("button_release_event", self._on_release)
        if comparison:
            title = title_html(
                "Edit a triangle: fill, split point and interpolation error",
                hint + ". The error heatmap is |affine − perspective-correct| of "
                f"<i>{attribute}</i>: zero when all three w are equal.",
            )
        else:
            title = title_html("Edit a triangle: its fill and its edge functions", hint + ".")
        figures = [self.display.widget, *([self.interp_display.widget] if comparison else [])]
        self.widget = widgets.VBox([
            title, control_row(columns), labelled("method", self.method), self.info, *figures,
        ])  # fmt: skip

    def _make_figures(self) -> None:
        """The fill figure (dragged in the page, or an ipympl canvas) and the comparison."""
        width, height = self.width, self.height
        self.fig = new_figure((7, 5), self.backend)
        ax = fill_axes(self.fig, width, height, side=4.0)
        # a finished fill has no step to explain; the info line says what matters here
        # no steps here: the header names the method only, not "step 172 of 0–172"
        self.view = FillView(self.fill, ax=ax, step=-1, caption=False, step_header=False)
        self.probe_marker = None
        if self.probe is not None:  # marked, over the fill: the point the info line reads
            # not the current pixel's vermillion, nor the split's purple (span tables)
            (self.probe_marker,) = ax.plot(*self.probe, "X", ms=15, mfc=COLORS["edge"],
                                           mec="white", mew=1.5, zorder=7)  # fmt: skip
        self._tidy_key()
        # a move changes the triangle's artists only: the grid, labels, centres and legend
        # stay in a cached background (dragging.fill_edit_blit)
        self._blits = {"fill": self._fill_blit()}
        if self.backend == "ipympl":
            self.display = FigureDisplay(self.fig, self.backend, draw=self._draw_fill)
        else:
            self.display = PageDisplay(self.fig, self.view.ax, self._draw_fill, self._handles,
                                       on_move=self._on_page_move)  # fmt: skip
        self.interp_view = self.interp_display = None
        if not self.comparison:  # no figure, no picture of it in the widget state
            return
        ifig = new_figure((10, 4), self.backend, dpi=COMPARISON_DPI)
        axes = comparison_axes(ifig, height, width)
        # the labels inside the panels, wherever a vertex is dragged (review r459 S3)
        self.interp_view = InterpolationView(self.fill, self.attribute, axes=axes, inside=True)
        self._blits["interp"] = comparison_edit_blit(self.interp_view)
        self.interp_display = FigureDisplay(ifig, self.backend, draw=self._draw_interp)

    def _tidy_key(self) -> None:
        """The key of a finished fill: the step-only entries hidden, the probe's cross named.

        The FillView's key lists the current pixel and raster line of a step; the editor
        shows no step, so those lines go, and a free line below the rest names the cross.
        """
        self._parts_over_coverage()
        key = self.view.legend
        if key is None:
            return
        label = "E12, E23, E31 here"
        shown = [text.get_visible() and text.get_text() not in {*STEP_ONLY, label}
                 for text in key.texts]  # fmt: skip
        for swatch, text, on in zip(key.swatches, key.texts, shown):
            swatch.set_visible(on)
            text.set_visible(on)
        if self.probe_marker is not None and sum(shown) < len(key.texts):
            k = sum(shown)  # the step-only entries come last: the first hidden line is free
            key.swatches[k].set(visible=True, marker="X", mfc=COLORS["edge"], mec="white")
            key.texts[k].set(visible=True, text=label)

    def _parts_over_coverage(self) -> None:
        """Span tables' two parts hatched over the covered pixels: painted under them, the
        parts the key names showed only as slivers beside the edges (review r93 02-9b)."""
        self.view.split.hatch_over_coverage()

    def _fill_blit(self):
        """The fill figure's blit, the probe's cross drawn over everything (it moves too)."""
        blit = fill_edit_blit(self.view)
        if self.probe_marker is not None:
            blit.plan.append((MOVING, [self.probe_marker]))
        return blit

    def _draw_fill(self) -> None:
        self._blits["fill"] = same_or_new(self._blits["fill"], self._fill_blit())
        if not self._dragging_in_page:
            self._blits["fill"].draw()
            return
        # While dragging, the labels (boxed annotations: half the cost of a frame) and the
        # edges' arrows (fancy arrows: a sixth of what is left) wait for the release; the
        # page's ring marks the vertex in hand meanwhile.
        t = self.view.triangle
        with hidden([*t.labels, *t.edge_labels, self.view.split.label, *t.arrows]):
            self._blits["fill"].draw()

    def _draw_interp(self) -> None:
        fresh = comparison_edit_blit(self.interp_view)
        self._blits["interp"] = same_or_new(self._blits["interp"], fresh)
        self._blits["interp"].draw()

    @property
    def _dragging_in_page(self) -> bool:
        """A drag in the page is under way (its positions are not the last)."""
        return not getattr(getattr(self, "display", None), "final", True)

    def _handles(self) -> np.ndarray:
        """The vertices on show (the triangle's own until the sliders exist), then the
        probe's cross."""
        if self.probe is None:
            return self.tri.xy
        return np.vstack([self.tri.xy, self.probe])

    def set_probe(self, x: float, y: float) -> None:
        """Move the probe's cross to (x, y) (on the 1/256 px grid) and update the info line."""
        if self.probe is None:
            raise ValueError("this editor has no probe: give probe=(x, y) when making it")
        self.probe = np.array([on_grid(x), on_grid(y)])
        self.probe_marker.set_data([self.probe[0]], [self.probe[1]])
        self._set_info()
        self.display.refresh()

    def _on_page_move(self, i: int, x: float, y: float, final: bool) -> None:
        """A position from the page (the latest of a drag, or where it ended)."""
        if i == 3:  # the probe's cross: its values follow at every position
            self.set_probe(x, y)
            return
        self.display.final = final
        try:
            self.set_vertex(i, x=x, y=y)
        finally:
            self.display.final = True

    # -- geometry ---------------------------------------------------------------------------
    def _rasterize(self, tri: Triangle, method: str):
        return rasterize(tri, self.width, self.height, method=method, trace=True)

    @property
    def xy(self) -> np.ndarray:
        """(3, 2) vertex positions set on the sliders (or, while a drag in the page is under
        way, where it has them: the sliders follow at the release). Outside a drag the
        sliders rule: a drag's positions left over never hold the figure (review r354 W1)."""
        if self._drag_xy is not None and self._dragging_in_page:
            return self._drag_xy.copy()
        return np.array([[self.x[i].value, self.y[i].value] for i in range(3)])

    @property
    def w_values(self) -> np.ndarray:
        """(3,) w set on the sliders (to 12 significant digits: see :func:`w_value`)."""
        return np.array([w_value(s.value) for s in self.w])

    def set_vertex(self, i: int, x: float | None = None, y: float | None = None,
                   w: float | None = None) -> None:  # fmt: skip
        """Move vertex ``i`` (any of x, y, w) and re-render once.

        Values beyond a slider's range are clipped to it (as a slider does); x and y are
        taken on the 1/256 px grid, the rasteriser's snapping grid and the sliders' step
        (off it, the page's slider would round the value and send it back: a second
        render, and a vertex a little off where the pointer let go).
        """
        x, y = (None if v is None else on_grid(v) for v in (x, y))
        if self._dragging_in_page and w is None:
            # Mid-drag: the sliders (two more messages to the page per frame) and the info
            # line wait for the release; the position is clipped to the sliders' range.
            xy = self.xy
            for k, (slider, value) in enumerate(((self.x[i], x), (self.y[i], y))):
                if value is not None:
                    xy[i, k] = min(max(value, slider.min), slider.max)
            self._drag_xy = xy
            self.update()
            return
        self._drag_xy = None
        with self._holding():
            for slider, value in ((self.x[i], x), (self.y[i], y), (self.w[i], w)):
                if value is not None:
                    slider.value = value
        self.update()

    def _on_slider(self, change) -> None:
        if not self._quiet:
            self.update()

    def _on_method(self, change) -> None:
        # the key (legend) of the other method is new background
        self.update()
        self._blits["fill"].invalidate()
        self.display.refresh()

    def update(self) -> None:
        """Re-rasterise the triangle on the sliders and update both figures in place.

        While a vertex is being dragged in the page, only the fill figure follows each
        position (what the pointer moves); the comparison figure, whose colour bars cost
        more to draw than the whole fill, follows at the release.
        """
        t0 = time.perf_counter()
        dragging = self._dragging_in_page
        if not dragging:  # the sliders have it now (see xy)
            self._drag_xy = None
        self.tri = Triangle(self.xy, w=self.w_values, z=self.tri.z, attrs=self.tri.attrs)
        self.fill = self._rasterize(self.tri, self.method.value)
        self.view.set_fill(self.fill, step=-1, draw=False)
        self._tidy_key()  # a new method's key is made afresh
        self.display.refresh()  # first: what the pointer moved (the comparison costs more)
        if not dragging:
            if self.comparison:
                self.interp_view.update(self.fill, draw=False)
            self._set_info()
            if self.comparison:
                self.interp_display.refresh()
        self._last_done = time.perf_counter()
        self.last_update_s = self._last_done - t0

    def _set_info(self) -> None:
        trace = self.fill.trace
        area = trace.signed_area
        covered = int(trace.covered.sum())
        if area == 0:
            # a number after "area", as every other state gives (review r169 02-8)
            parts = ["area 0.00 px² after snapping (<b>zero area</b>): the triangle covers no "
                     "pixel"]  # fmt: skip
        else:
            facing = "front-facing (counter-clockwise" if area < 0 else "back-facing (clockwise"
            parts = [f"area {abs(area):.2f} px², {facing} on screen)",
                     f"{covered} pixel{'s' * (covered != 1)} covered"]  # fmt: skip
        if trace.span is not None:  # only span tables split (half-planes test the box)
            if trace.span.u4 is not None and area != 0:  # zero area: nothing to split
                parts.append(f"split at u4 = {trace.span.u4:.2f}")
        elif trace.halfplane is not None:
            parts.append(f"{trace.bbox.size} centres of the bounding box tested")
        m = self.interp_view.maximum if self.comparison else np.nan
        if np.isfinite(m):
            parts.append(f"largest |affine − perspective| of {self.attribute} = {m:.3g}")
        info = " · ".join(parts)
        if self.probe is not None:
            info += "<br>" + self.probe_text()
        self.info.value = info

    def edge_values(self) -> np.ndarray | None:
        """(3,) E12, E23, E31 of the snapped vertices as given at :attr:`probe` (None
        without a probe): each twice the signed area of the edge and the probe."""
        if self.probe is None:
            return None
        v = self.fill.trace.snapped
        return np.array([float(edge_function(v[k], v[(k + 1) % 3], self.probe))
                         for k in range(3)])  # fmt: skip

    def probe_text(self) -> str:
        """The info line's second line: E12, E23, E31 at the probe, and what they say."""
        e = self.edge_values()
        x, y = self.probe
        values = ", ".join(f"E{n} = {v:+.2f}" if v else f"E{n} = 0"
                           for n, v in zip(("12", "23", "31"), e))  # fmt: skip
        zeros = int((e == 0).sum())
        if zeros == 3:  # every point is on the line the three vertices share
            verdict = "all three 0: a zero-area triangle, nothing covered"
        elif (e > 0).all():
            verdict = "all positive: inside (clockwise on screen)"
        elif (e < 0).all():  # the package tests the edges walked backwards, E21 = −E12 ...
            # short: the readout wrapped to one more line and the figure jumped (r343)
            verdict = "all negative: inside (counter-clockwise: tested as E21, E32, E13)"
        elif zeros and ((e >= 0).all() or (e <= 0).all()):
            verdict = ("one is 0: on an edge (the top-left rule decides)" if zeros == 1 else
                       "two are 0: on a vertex (covered only if both edges are top or left)")  # fmt: skip
        else:
            verdict = "signs differ: outside"
        # 2 decimals, as the values: a dragged cross is at 1/256 px, "(2.98828, 8.05859)"
        return f"at the cross ({x:.2f}, {y:.2f}): {values} · {verdict}"

    # -- mouse dragging (ipympl) ------------------------------------------------------------
    def _on_press(self, event) -> None:
        if event.inaxes is not self.view.ax or event.button != 1 or event.xdata is None:
            return
        d = np.hypot(*(self.xy - [event.xdata, event.ydata]).T)
        i = int(np.argmin(d))
        # within about a pixel, or a few percent of the grid on large grids
        if d[i] <= max(1.0, 0.04 * max(self.width, self.height)):
            self._dragging = i

    def _on_motion(self, event) -> None:
        if self._dragging is None or event.inaxes is not self.view.ax or event.xdata is None:
            return
        self._pending = (event.xdata, event.ydata)
        # Mouse events queue up while a re-render runs; one that arrives right after the
        # last render finished is such a backlog, so skip it (the release applies the last).
        if time.perf_counter() - self._last_done < 0.02:
            return
        self._apply_pending()

    def _on_release(self, event) -> None:
        if self._dragging is not None:
            self._apply_pending()
        self._dragging = None

    def _apply_pending(self) -> None:
        if self._pending is not None and self._dragging is not None:
            x, y = self._pending
            self._pending = None
            self.set_vertex(self._dragging, x=float(x), y=float(y))

    # -- display ----------------------------------------------------------------------------
    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    def _ipython_display_(self) -> None:
        poster = getattr(self.display.widget, "poster", b"")  # the picture in the page
        if not poster:  # ipympl: the canvas restores its own picture
            from IPython.display import display

            display(self._repr_mimebundle_(), raw=True)
            return
        html = standin_html("", "editor", poster)  # the hint every stand-in gives
        display_with_fallback(self._repr_mimebundle_(), html)

    def close(self) -> None:
        """Close every widget of the editor."""
        for d in (self.display, self.interp_display):
            if d is not None:
                d.close()
        close_tree(self.widget)
