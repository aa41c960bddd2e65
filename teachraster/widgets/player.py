"""``FillPlayer``: play a traced fill step by step, switch method and interpolation."""

from __future__ import annotations

import html

import ipywidgets as widgets

from ..core.fill import rasterize
from ..core.triangle import Triangle
from ..core.validate import as_int, as_size
from ..plotting import COLORS, FillView, InterpolationView, plot_samples
from ..plotting.blitting import STILL, LayeredBlit
from .common import (
    SAMPLE_PATTERNS,
    Holdable,
    close_tree,
    fill_axes,
    labelled,
    pattern_samples,
    style_context,
    title_html,
)
from .display import (
    COMPARISON_DPI,
    FigureDisplay,
    comparison_axes,
    html_escape,
    new_figure,
    resolve_backend,
)

METHOD_OPTIONS = [("span tables", "span"), ("half-planes", "halfplane"), ("tiles", "tiled")]
INTERPOLATION_OPTIONS = [("affine", "affine"), ("perspective-correct", "perspective")]


class FillPlayer(Holdable):
    """Step through the fill of one triangle: Play/Pause, a step slider, the step in words.

    The figure is a :class:`~teachraster.plotting.FillView`; moving the step slider calls
    ``view.show_step(k)``, which changes the data of the existing artists (no redraw from
    scratch). The method and interpolation toggles rasterise the triangle again
    (``trace=True``) and hand the new fill to ``view.set_fill``; the slider's range follows
    the new number of steps. When the triangle has attributes, a second figure (an
    :class:`~teachraster.plotting.InterpolationView`) shows one of them interpolated both
    ways and their difference, the interpolation in use highlighted.

    Everything can be driven from code: set ``player.slider.value``,
    ``player.method.value`` or ``player.interpolation.value``, or ``click()`` a button.

    Parameters
    ----------
    tri : Triangle
        The triangle to fill (screen space, pixels).
    width, height : int
        Image size in pixels (a 32 × 32 grid or smaller reads best).
    method : {"span", "halfplane", "tiled"}
        Span tables, half-planes or tiles (one step per classified block), as for
        :func:`teachraster.rasterize`.
    interpolation : {"perspective", "affine"}
        How attributes are interpolated.
    attribute : str, optional
        Attribute shown in the interpolation figure; default the triangle's first.
    step : int
        Step shown first (0: the start; -1: the finished fill).
    interval : int
        Milliseconds per step when playing.
    backend : {"auto", "ipympl", "image"}
        ``"ipympl"`` puts the interactive canvas in the widget (``%matplotlib widget``);
        ``"image"`` shows a PNG, redrawn at each step (any backend, also headless);
        ``"auto"`` picks ipympl when it is matplotlib's backend.
    style : str, optional
        Plotting style for this widget's figures (``"classroom"``); default the current one.
    samples : str
        Sample pattern, a key of :data:`~teachraster.widgets.common.SAMPLE_PATTERNS`. With
        more than one sample the steps still follow the pixel centres, and every sample of
        the finished fill is drawn on top (filled where covered): what MSAA adds.

    Attributes
    ----------
    widget : ipywidgets.VBox
        Everything, ready to display (the player also displays itself).
    play, slider, speed, prev, next, first, last, method, interpolation, samples, caption,
    step_info
        The controls: ``Play`` (jslinked to ``slider``: it runs in the browser), the step
        ``IntSlider``, the Play interval in ms, the step buttons, the two
        ``ToggleButtons``, the ``HTML`` caption of the current step and the ``Label`` by the
        slider with the last step number and the kind of step ("of 787 (pixel)").
    view : FillView
    fig : matplotlib Figure
        The FillView's figure.
    interp_view : InterpolationView or None
        None when the triangle has no attributes.
    fill : Fill
        The fill on show.

    Examples
    --------
    >>> import teachraster as tr
    >>> tri = tr.Triangle([[1, 1], [14, 4], [5, 14]], w=[1, 2, 4], attrs={"u": [0, 1, 0]})
    >>> player = FillPlayer(tri, 16, 16, backend="image")
    >>> player.slider.value = 6
    >>> player.caption_text == player.trace.caption(6)
    True
    >>> player.close()
    """

    def __init__(
        self,
        tri: Triangle,
        width: int,
        height: int,
        method: str = "span",
        interpolation: str = "perspective",
        *,
        attribute: str | None = None,
        step: int = 0,
        interval: int = 400,
        backend: str = "auto",
        style: str | None = None,
        samples: str = "1 (centre)",
    ) -> None:
        if not isinstance(tri, Triangle):
            raise TypeError(f"tri must be a teachraster.Triangle, got {type(tri).__name__}")
        self.tri = tri
        self.width, self.height = as_size("width", width), as_size("height", height)
        interval = as_int("interval", interval, minimum=1)
        self.backend = resolve_backend(backend)
        self._fills: dict[tuple[str, str, str], object] = {}
        self.samples = widgets.Dropdown(options=list(SAMPLE_PATTERNS), value=samples,
                                        layout=widgets.Layout(width="220px"))  # fmt: skip
        self.fill = self._rasterize(method, interpolation)
        step = self.trace.index(step)
        with style_context(style):
            self._make_figures(attribute, step, interpolation)
            self.sample_dots = None
            self._show_samples()
        self._make_controls(step, interval, method, interpolation)
        self.widget = self._layout()

    # -- building ---------------------------------------------------------------------------
    def _rasterize(self, method: str, interpolation: str):
        """The traced fill for these options (each made once: toggling back costs nothing)."""
        key = (method, interpolation, self.samples.value)
        if key not in self._fills:
            self._fills[key] = rasterize(self.tri, self.width, self.height, method=method,
                                         interpolation=interpolation, trace=True,
                                         samples=pattern_samples(self.samples.value))  # fmt: skip
        return self._fills[key]

    def _show_samples(self) -> None:
        """Every sample of the fill on top of the steps (hidden for one sample per pixel)."""
        if self.fill.sample_coverage is not None:
            if self.sample_dots is None:
                self.sample_dots = plot_samples(self.view.ax, self.fill, fraction=False)
            else:
                self.sample_dots.update(self.fill)
        if self.sample_dots is not None:
            self.sample_dots.set_visible(self.fill.sample_coverage is not None)
            # a still layer above the pixels the steps fill (the view's plan is new after
            # every set_fill, so the layer is added again each time)
            blit = self.view.blit
            self.view.blit = LayeredBlit(blit.fig, [*blit.plan, (STILL, list(self.sample_dots))])
        self.view.blit.invalidate()

    def _make_figures(self, attribute, step: int, interpolation: str) -> None:
        self.fig = new_figure((8, 6), self.backend)
        ax = fill_axes(self.fig, self.width, self.height)
        # The caption is a widget below the controls, in full and selectable; drawing it in
        # the figure as well would cost time at every step.
        # The step number and kind go to a label by the slider for the same reason.
        self.view = FillView(self.fill, ax=ax, step=step, caption=False, step_header=False)
        # Steps are blitted: only what moves is drawn again (see FillView.redraw).
        self.display = FigureDisplay(self.fig, self.backend, draw=self.view.redraw)
        self.interp_view = self.interp_display = None
        if self.tri.attrs:
            name = attribute or next(iter(self.tri.attrs))
            ifig = new_figure((10, 4), self.backend, dpi=COMPARISON_DPI)
            axes = comparison_axes(ifig, self.height, self.width, below=True)
            self.interp_view = InterpolationView(self.fill, name, axes=axes)
            self.interp_view.highlight(interpolation)
            self.interp_display = FigureDisplay(ifig, self.backend)

    def _make_controls(self, step: int, interval: int, method: str, interpolation: str):
        n = len(self.trace)
        self.play = widgets.Play(value=step, min=0, max=n - 1, interval=interval,
                                 show_repeat=False, tooltip="play / pause")  # fmt: skip
        self.slider = widgets.IntSlider(value=step, min=0, max=n - 1, description="step",
                                        continuous_update=True,
                                        layout=widgets.Layout(width="420px"))  # fmt: skip
        # Linked in the browser, so playing needs no round trip through the kernel per tick;
        # the kernel hears of each new slider value and redraws.
        self.link = widgets.jslink((self.play, "value"), (self.slider, "value"))
        self.speed = widgets.IntSlider(value=interval, min=50, max=2000, step=50,
                                       description="ms / step",
                                       layout=widgets.Layout(width="300px"))  # fmt: skip
        # A kernel-side link: the interval rarely changes, and this way setting speed.value
        # from code changes the Play too.
        self.speed_link = widgets.link((self.speed, "value"), (self.play, "interval"))
        self._make_buttons()
        self.method = widgets.ToggleButtons(options=METHOD_OPTIONS, value=method,
                                            tooltips=["sort, split at u4, fill row by row",
                                                      "test every pixel of the bounding box "
                                                      "against the three edges"])  # fmt: skip
        self.interpolation = widgets.ToggleButtons(
            options=INTERPOLATION_OPTIONS, value=interpolation,
            tooltips=["screen-space blend of the vertex values (GLSL noperspective)",
                      "blend f/w and 1/w, then divide (GLSL smooth)"],
        )  # fmt: skip
        for toggle in (self.method, self.interpolation):
            toggle.style.button_width = "150px"
        self.caption = widgets.HTML(
            html_escape(self.trace.caption(step)),
            layout=widgets.Layout(min_height="3.2em", width="100%", padding="2px 6px",
                                  border=f"1px solid {COLORS['grid']}"),
        )  # fmt: skip
        self.caption.style.font_size = "15px"
        self.step_info = widgets.Label(self._step_info(self.trace.step(step)))
        self.caption.add_class("teachraster-caption")  # a handle for styling and browser tests
        self.slider.observe(self._on_step, "value")
        self.method.observe(self._on_fill_options, "value")
        self.interpolation.observe(self._on_fill_options, "value")
        self.samples.observe(self._on_fill_options, "value")

    def _make_buttons(self) -> None:
        small = widgets.Layout(width="44px")
        self.first = widgets.Button(icon="fast-backward", tooltip="first step", layout=small)
        self.prev = widgets.Button(icon="step-backward", tooltip="previous step", layout=small)
        self.next = widgets.Button(icon="step-forward", tooltip="next step", layout=small)
        self.last = widgets.Button(icon="fast-forward", tooltip="last step", layout=small)
        self.first.on_click(lambda _: self._go(0))
        self.prev.on_click(lambda _: self._go(self.slider.value - 1))
        self.next.on_click(lambda _: self._go(self.slider.value + 1))
        self.last.on_click(lambda _: self._go(self.slider.max))

    def _layout(self) -> widgets.VBox:
        title = title_html(
            "How a GPU fills a triangle, step by step",
            "Press play, drag the step slider or use the buttons; switch the method and the "
            "interpolation to compare.",
        )
        figures = [self.display.widget]
        if self.interp_display is not None:
            figures.append(self.interp_display.widget)
        return widgets.VBox([
            title,
            widgets.HBox([self.play, self.first, self.prev, self.slider, self.next, self.last,
                          self.step_info]),
            widgets.HBox([labelled("method", self.method),
                          labelled("interpolation", self.interpolation),
                          labelled("samples", self.samples)]),
            self.speed,
            self.caption,
            *figures,
        ])  # fmt: skip

    # -- state ------------------------------------------------------------------------------
    @property
    def trace(self):
        """The FillTrace on show."""
        return self.fill.trace

    @property
    def step(self) -> int:
        """The step on show."""
        return self.view.step

    @property
    def caption_text(self) -> str:
        """The caption on show as plain text (equal to ``trace.caption(step)``)."""
        return html.unescape(self.caption.value)

    # -- driving ----------------------------------------------------------------------------
    def show_step(self, k: int) -> None:
        """Show step ``k`` (the same as setting ``slider.value``; negative counts from the end)."""
        self.slider.value = self.trace.index(k)

    def _go(self, k: int) -> None:
        self.slider.value = min(max(k, self.slider.min), self.slider.max)

    def _on_step(self, change) -> None:
        if not self._quiet:
            self._draw_step(change["new"])

    def _draw_step(self, k: int) -> None:
        step = self.view.show_step(k, draw=False)
        self._show_caption(step)
        self.display.refresh()

    def _show_caption(self, step) -> None:
        self.caption.value = html_escape(step.caption)
        self.step_info.value = self._step_info(step)

    def _step_info(self, step) -> str:
        """``"of 787 (pixel)"``: beside the slider's own readout of the step number."""
        return f"of {len(self.trace) - 1} ({step.kind})"

    def _on_fill_options(self, change) -> None:
        self.fill = self._rasterize(self.method.value, self.interpolation.value)
        # The view decides the step (a finished fill stays finished, else the same index);
        # the slider follows it.
        step = self.view.set_fill(self.fill, draw=False)
        self._show_samples()
        last = len(self.trace) - 1
        with self._holding():
            # widen before moving, narrow after, so the value is never out of range
            self.slider.max = self.play.max = max(last, self.slider.max)
            self.slider.value = step.index
            self.slider.max = self.play.max = last
        self._show_caption(step)
        self.display.refresh()
        if self.interp_view is not None:
            self.interp_view.update(self.fill, draw=False)
            self.interp_view.highlight(self.interpolation.value)
            self.interp_display.refresh()

    @property
    def in_use(self) -> list:
        """The "in use" notes under the interpolation panels (empty without attributes)."""
        return [] if self.interp_view is None else self.interp_view.in_use

    # -- display ----------------------------------------------------------------------------
    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    def close(self) -> None:
        """Close every widget of the player (the figures are freed with it)."""
        for d in (self.display, self.interp_display):
            if d is not None:
                d.close()
        self.link.close()
        self.speed_link.unlink()
        close_tree(self.widget)
