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
from .common import (
    Shown,
    control_row,
    labelled,
    style_context,
    title_html,
)
from .display import FigureDisplay, new_figure, resolve_backend


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
        self.rate = widgets.IntSlider(value=rate, min=8, max=64, step=4, description="samples")
        self.width = widgets.FloatSlider(value=width, min=0.0, max=4.0, step=0.25,
                                         description="filter")  # fmt: skip
        self.kernel = widgets.ToggleButtons(options=KERNELS, value=kernel)
        self.result = sample_signal(self.rate.value, self.width.value, self.kernel.value)
        with style_context(style):
            self.fig = new_figure((9.0, 7.5), self.backend)
            self.fig.set_layout_engine("constrained")
            axes = self.fig.subplots(3, 1, sharex=True)
            self.art = plot_sampling(axes, self.result)
            # laid out once: a control moves the same lines, and the layout solver cost
            # about two thirds of each picture (issue 31: 274-327 ms a control)
            self.fig.canvas.draw()
            self.fig.set_layout_engine("none")
            self._blit = self._plan_blit(axes)
            self.display = FigureDisplay(self.fig, self.backend, draw=self._draw_figure)
        self.info = widgets.HTML(self._info_html())
        for control in (self.rate, self.width, self.kernel):
            control.observe(lambda change: self.update(), "value")
        title = title_html(
            "Prefilter → sample → reconstruct",
            "Yellow: the signal is above the Nyquist limit (half the sample rate). Widen the "
            "filter until the reconstruction there is flat instead of a false wave.",
        )
        controls = control_row([self.rate, self.width, labelled("shape", self.kernel)])
        self.widget = widgets.VBox([title, controls, self.info, self.display.widget])

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
        return LayeredBlit(self.fig, [(MOVING, a.spans), (STILL, [a.signal]),
                                      (MOVING, [c for c in curves if c is not None]),
                                      (STILL, over + keys)])  # fmt: skip

    def _draw_figure(self) -> None:
        # the key names the prefiltered line "none (= signal)" at width 0: a layer per text
        self._blit.draw(key=self.art.filtered.axes.get_legend().get_texts()[1].get_text())

    def update(self) -> None:
        """Recompute from the controls and move the same lines."""
        self.result = sample_signal(self.rate.value, self.width.value, self.kernel.value)
        update_sampling(self.art, self.result)
        self.info.value = self._info_html()
        self.display.refresh()

    def _info_html(self) -> str:
        r = self.result
        return (f"{self.rate.value} samples per unit: Nyquist limit {r.nyquist:g} cycles, "
                f"passed from x = {r.alias_from:.2f} on · RMS error of the reconstruction "
                f"against an ideal low-pass: <b>{r.rms_error:.3f}</b>")  # fmt: skip
