"""``SamplingExplorer``: prefilter, sample, reconstruct a 1-D signal (lessons 08 and 09).

The sample rate is the pixel grid (or the samples of MSAA, or a mip level's texels); the
filter width is how much the signal is blurred first (a pixel's area coverage: a box one
sample wide; a mip level: a box of the footprint's size). The yellow band is where the signal
is above the Nyquist limit: without a prefilter the samples there trace a false, slower wave.
"""

from __future__ import annotations

import ipywidgets as widgets

from ..plotting.blitting import MOVING, STILL, LayeredBlit
from ..plotting.sampling import KERNELS, plot_sampling, sample_signal, update_sampling
from .ahead import TogglesAhead, show_kept
from .common import (
    Shown,
    control_row,
    fit_width,
    labelled,
    projector_text,
    style_context,
    title_html,
)
from .display import new_figure, resolve_backend
from .live_slider import LiveSlider, info_line, slider_display

#: The picture's alternative text in the page
ALT = "the signal prefiltered, sampled and reconstructed, in three panels"


class SamplingExplorer(Shown):
    """Sliders for the sample rate and the prefilter's width, a chooser for its shape.

    Parameters
    ----------
    rate : int
        Samples per unit (8 to 64).
    width : float
        Prefilter width in sample spacings (0 = none, 1 = a pixel's box).
    kernel : {"box", "gaussian"}
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    rate, width : ipywidgets sliders
    kernel : ipywidgets.ToggleButtons
    result : teachraster.plotting.sampling.SamplingResult
        The arrays of the current settings (``result.rms_error``: the reconstruction against
        an ideal low-pass).
    widget : ipywidgets.VBox

    Examples
    --------
    >>> ex = SamplingExplorer(rate=32, width=0.0, backend="image")
    >>> before = ex.result.rms_error
    >>> ex.width.value = 2.0
    >>> ex.kernel.value = "gaussian"
    >>> ex.result.rms_error < before
    True
    >>> ex.close()
    """

    #: ``teachraster html``: the offline page steps through every sample rate (:mod:`.offline`)
    _offline_sweep_ = "rate"

    def __init__(self, rate: int = 32, width: float = 0.0, kernel: str = "box", *,
                 backend: str = "auto", style: str | None = None) -> None:  # fmt: skip
        self.backend = resolve_backend(backend)
        # page sliders whose positions are drawn ahead while the kernel idles (those of the
        # one moved last): a key or a drag shows the page's own picture (issue 31)
        self.rate = LiveSlider(value=rate, min=8, max=64, step=4, description="samples",
                               readout_format=".0f",
                               layout=fit_width(widgets.Layout(width="320px")))  # fmt: skip
        # the width's unit (sample spacings) in its name: "4.00" alone did not say of what
        # (review r26, 08 c10)
        self.width = LiveSlider(value=width, min=0.0, max=4.0, step=0.25,
                                description="filter (spacings)",
                                readout_format=".2f",
                                layout=fit_width(widgets.Layout(width="320px")))  # fmt: skip
        self.kernel = widgets.ToggleButtons(options=KERNELS, value=kernel)
        self._compute_at(self.rate.value, 0)
        with style_context(style):
            # 5.6 in (about 540 px): sliders and all three panels on one 1366 × 900 screen
            # (review r382 S1: at 7.5 in the widget stood 938 px tall)
            self.fig = new_figure((9.0, 5.6), self.backend)
            self.fig.set_layout_engine("constrained")
            axes = self.fig.subplots(3, 1, sharex=True)
            self.art = plot_sampling(axes, self.result)
            # laid out once: a control moves the same lines, and the layout solver cost
            # about two thirds of each picture (issue 31: 274-327 ms a control)
            self.fig.canvas.draw()
            self.fig.set_layout_engine("none")
            self._blit = self._plan_blit(axes)
            dragged = lambda: self.rate.dragging or self.width.dragging  # noqa: E731
            self.display = slider_display(self.fig, self.backend, draw=self._draw_figure,
                                          drafting=dragged, alt=ALT)  # fmt: skip
        # the caption of the page's picture: a picture drawn ahead brings its own
        self.info, info_widgets = info_line(self.display)
        self.info.value = self._info_html()
        for control in (self.rate, self.width):
            control.observe(lambda change: self.update(), "value")
        # at width 0 there is no prefilter, so no shape to choose: the chooser is greyed out
        # (review r287 S2: it showed "box" chosen beside "0.00 (none: the signal)")
        self.kernel.disabled = self.width.value == 0
        self.width.observe(lambda change: setattr(self.kernel, "disabled", change.new == 0),
                           "value")  # fmt: skip
        # another shape: every picture drawn ahead is stale
        self.kernel.observe(lambda change: self.update(restart=True), "value")
        title = title_html(
            "Prefilter → sample → reconstruct",
            "Yellow: the signal is above the Nyquist limit (half the sample rate). Widen the "
            "filter until the reconstruction there is flat instead of a false wave; wider "
            "still, and it blurs the part left of the yellow band too: the RMS error rises "
            "again.",
        )
        controls = control_row([self.rate, self.width, labelled("shape", self.kernel)])
        self.widget = projector_text(
            widgets.VBox([title, controls, *info_widgets, self.display.widget]), title
        )
        self._ahead = self._toggles = None
        if self.backend != "ipympl":
            self._ahead = self.display.ahead([self.rate, self.width], self)
            #: the other shape's picture here, drawn while the kernel idles (for a page)
            self._toggles = TogglesAhead(self.display, self, KERNELS)
            self._ahead.on_listening.append(self._toggles_ahead)

    def _plan_blit(self, axes) -> LayeredBlit:
        """A control moves the yellow bands and the curves only: the axes, their ticks and
        titles stay in a cached background; what lies above them (the grey signal over the
        band; the frames, ticks and keys over every curve) in still layers. A full draw
        cost 200-300 ms a picture (issue 31: 274-420 ms a control in the page)."""
        a = self.art
        # in the order plot_sampling drew them (equal zorders: the faint curve over the samples)
        curves = [a.filtered, a.stems, a.filtered_faint, a.ideal, a.reconstructed]
        over = [child for ax in axes for child in (*ax.spines.values(), ax.xaxis, ax.yaxis)]
        keys = [ax.get_legend() for ax in axes if ax.get_legend() is not None]
        plan = [(MOVING, a.spans), (STILL, [a.signal]),
                (MOVING, [c for c in curves if c is not None]), (STILL, over + keys)]  # fmt: skip
        # the label of panel 1's key names the filter's width (prefiltered_key): redrawn with
        # the curves, where the key's layout put it (its first line as long at every width).
        # Cached with the keys, the page kept "width 0.00 (none: the signal)" beside a slider
        # at 1.00 or 4.00 (review r127 08-1)
        named = a.filtered.axes.get_legend()
        if named is not None:  # beside the panel: nothing still lies over it
            plan.append((MOVING, [named.get_texts()[1]]))
        return LayeredBlit(self.fig, plan)

    def _draw_figure(self) -> None:
        self._blit.draw()

    def update(self, restart: bool = False) -> None:
        """Recompute from the controls and move the same lines (``restart``: the shape
        changed, the pictures drawn ahead are stale; the shape's picture drawn ahead here
        is sent at once)."""
        where = (self.rate.value, self.width.value)
        kept = self._toggles.take(where, self.kernel.value) if restart and self._toggles else None
        if kept is not None:
            show_kept(self, kept)
            self._set_artists()  # for the next picture drawn
        else:
            self._compute_at(self.rate.value, 0)
            self._set_artists()
            self.info.value = self._info_html()
            self.display.refresh()
        if self._ahead is not None and self._ahead.listening:
            self._toggles_ahead()
        if restart and self._ahead is not None:
            self._ahead.restart()

    def _toggles_ahead(self) -> None:
        """The other shape at the samples and filter on show, drawn while the kernel idles."""
        self._toggles.start((self.rate.value, self.width.value), self.kernel.value)

    # what the pictures drawn ahead need (teachraster.widgets.ahead.FramesAhead and
    # TogglesAhead)
    def _compute_at(self, value, which) -> None:
        """The result with slider ``which`` (0: samples, 1: filter) at ``value``, the other
        control where it is; or, ``which`` a shape (``TogglesAhead``), with that shape at
        ``value`` = (samples, filter)."""
        kernel = self.kernel.value
        if isinstance(which, str):
            (rate, width), kernel = value, which
        elif which == 0:
            rate, width = value, self.width.value
        else:
            rate, width = self.rate.value, value
        self.result = sample_signal(int(round(rate)), width, kernel)

    def _set_artists(self) -> None:
        update_sampling(self.art, self.result)

    def close(self) -> None:
        """Close the figure (and what it draws ahead) and every widget of the box."""
        if self._toggles is not None:
            self._toggles.close()
        super().close()

    def _info_html(self) -> str:
        r = self.result
        return (f"{len(r.samples)} samples per unit: Nyquist limit {r.nyquist:g} cycles, "
                f"signal above it from x = {r.alias_from:.2f} · RMS error of the reconstruction "
                f"against an ideal low-pass: <b>{r.rms_error:.3f}</b>")  # fmt: skip
