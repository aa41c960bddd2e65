"""``DivideCostExplorer``: how the price of a divide re-ranks interpolation's accuracy/cost front.

Lesson 06's widget. Perspective-correct interpolation needs a divide per pixel; subdivided
interpolation (Quake's) divides every N pixels and is affine in between; affine never divides.
Which of them is worth its cost depends on what a divide costs against a multiply and an
addition: tens of cycles on an early-1990s FPU, about as much as a few multiplies on a GPU.
The slider sets that price; the chart re-prices every variant from its operation counts
(:mod:`teachraster.study.operation_counts`) and redraws the Pareto front.
"""

from __future__ import annotations

import ipywidgets as widgets

from ..plotting.pareto import plot_pareto, update_pareto
from ..study.operation_counts import CYCLES_1990S
from .common import (
    Shown,
    control_row,
    fit_width,
    labelled,
    style_context,
    title_html,
)
from .display import FigureDisplay, new_figure, resolve_backend

#: The two error measures offered: the study's largest error and its mean.
ERRORS = {"max error": "error", "mean error": "mean_abs_texels"}


def short_name(variant: str) -> str:
    """``"subdivided N=16"`` -> ``"N=16"``; other names unchanged."""
    return variant.replace("subdivided ", "")


def priced(rows, divide: float, multiply: float = 3.0, addition: float = 1.0) -> list[dict]:
    """Copies of ``rows`` with ``cycles`` recomputed from their operation counts."""
    out = []
    for r in rows:
        c = r["divides"] * divide + r["multiplies"] * multiply + r["additions"] * addition
        out.append({**r, "cycles": float(c)})
    return out


class DivideCostExplorer(Shown):
    """Accuracy against cost of the interpolation variants, with the divide's price a slider.

    Parameters
    ----------
    rows : list of dict
        The study's interpolation rows with their operation counts
        (``ops.with_counts(bench.run(...))`` filtered to ``group == "interpolation"``).
    divide : float
        Starting cost of a divide in cycles of the operation-count model (an addition costs 1,
        a multiply 3: :data:`~teachraster.study.operation_counts.CYCLES_1990S`).
    error : {"max error", "mean error"}
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    divide : ipywidgets.FloatLogSlider
    error : ipywidgets.ToggleButtons
    front : list of str
        The variants on the front, cheapest first, for the current settings.
    widget : ipywidgets.VBox
    """

    #: ``teachraster html``: the offline page steps through every divide cost (:mod:`.offline`)
    _offline_sweep_ = "divide"

    def __init__(self, rows, divide: float = CYCLES_1990S["divides"], *,
                 error: str = "max error", backend: str = "auto",
                 style: str | None = None) -> None:  # fmt: skip
        self.rows = [r for r in rows if r.get("group", "interpolation") == "interpolation"]
        if not self.rows:
            raise ValueError("rows must hold the study's interpolation rows")
        self.backend = resolve_backend(backend)
        self.divide = widgets.FloatLogSlider(value=divide, base=2, min=0, max=7, step=0.25,
                                             description="divide =", readout_format=".3g",
                                             layout=fit_width(widgets.Layout(width="420px")))  # fmt: skip
        self.error = widgets.ToggleButtons(options=list(ERRORS), value=error)
        with style_context(style):
            self.fig = new_figure((9.0, 5.5), self.backend)
            self.fig.set_layout_engine("constrained")
            self.ax = self.fig.add_subplot()
            self._plot()
            self.display = FigureDisplay(self.fig, self.backend)
        self.info = widgets.HTML(self._info_html())
        self.divide.observe(lambda change: self.update(), "value")
        self.error.observe(lambda change: self.update(replot=True), "value")
        title = title_html(
            "What a divide costs decides the price of exactness",
            "Cost per pixel in cycles of the op-count model (an addition = 1, a multiply = 3). "
            "Vermillion: the Pareto front, the variants no other beats on both cost and error.",
        )
        controls = control_row([self.divide, labelled("error", self.error)])
        self.widget = widgets.VBox([title, controls, self.info, self.display.widget])

    @property
    def _ykey(self) -> str:
        return ERRORS[self.error.value]

    def _plot(self) -> None:
        self.ax.clear()
        self.art = plot_pareto(
            self.ax, priced(self.rows, self.divide.value), "cycles", y=self._ykey,
            xlabel="cycles per pixel (op-count model)", ylabel=f"{self.error.value} (texels)",
            short=short_name,
        )  # fmt: skip
        self.front = [r["variant"] for r in self.art.front]

    def update(self, replot: bool = False) -> None:
        """Re-price the variants and redraw (the same artists unless the error measure changed)."""
        if replot:
            self._plot()
        else:
            rows = priced(self.rows, self.divide.value)
            self.front = [r["variant"] for r in update_pareto(self.ax, self.art, rows, "cycles",
                                                               y=self._ykey)]  # fmt: skip
        self.info.value = self._info_html()
        self.display.refresh()

    def _info_html(self) -> str:
        """What the slider changes: the divide's share of the exact divide's cost, and what
        Quake's subdivision (N = 16) still saves at this price."""
        rows = {r["variant"]: r for r in priced(self.rows, self.divide.value)}
        names = " → ".join(short_name(v) for v in self.front)
        exact = rows["perspective"]["cycles"]
        ratio = exact / rows["affine"]["cycles"]
        share = self.divide.value * rows["perspective"]["divides"] / exact
        quake = rows.get("subdivided N=16")
        saving = ""
        if quake is not None:
            saving = (f"; Quake's N=16 costs <b>{quake['cycles'] / exact:.0%}</b> of "
                      "perspective-correct")  # fmt: skip
        return (f"divide = {self.divide.value:.3g} cycles: the divide is <b>{share:.0%}</b> of "
                f"perspective-correct's cost; perspective-correct costs <b>{ratio:.3g}×</b> "
                f"affine{saving}. "
                f"Front, cheapest first: {names}")  # fmt: skip
