"""``DivideCostExplorer``: how the price of a divide re-ranks interpolation's accuracy/cost front.

Lesson 06's widget. Perspective-correct interpolation needs a divide per pixel; subdivided
interpolation (Quake's) divides every N pixels and is affine in between; affine never divides.
Which of them is worth its cost depends on what a divide costs against a multiply and an
addition: 17 issue cycles on the Pentium's FPU (an addition 1, a multiply 2), eight
multiply-adds' worth on a current GPU (an addition and a multiply 1 each). The **prices**
buttons pick one of the two price lists (:data:`~teachraster.study.operation_counts.PRICES`:
Agner Fog's Pentium tables, NVIDIA's throughput table), the **divide** slider that list's
divide; the chart re-prices every
variant from its operation counts (:mod:`teachraster.study.operation_counts`) and redraws the
Pareto front. A second slider sets
the number of attributes interpolated per pixel: they share the one reciprocal of 1/w, while
subdivision's per-anchor work grows with each of them, so that at a GPU's 16 or more
attributes N = 2 costs more than the exact divide at every price up to 2k - 1 cycles (the
lesson's conclusion, on the chart). The errors stay the study's, measured on u and v.
"""

from __future__ import annotations

import numbers
from types import SimpleNamespace

import ipywidgets as widgets
import numpy as np
from matplotlib.ticker import FixedLocator, FormatStrFormatter, LogLocator
from matplotlib.transforms import Bbox

from ..plotting.pareto import floor_ticks, plot_pareto, update_pareto
from ..study.bench.report import FRONT_DEFINITION
from ..study.operation_counts import ATTRIBUTES, PRICES, OpCount, cycles, interpolation_count
from .ahead import PicturesAhead, show_kept
from .common import (
    Shown,
    control_rows,
    fit_width,
    labelled,
    projector_text,
    style_context,
    title_html,
)
from .display import FigureDisplay, new_figure, png_bytes, resolve_backend

#: At most this many labels on the error axis: 1-2-5 over five decades packed 16 into 400 px.
MOST_ERROR_LABELS = 8
#: The share of the figure's width the layout keeps right of the axes (see ``_lay_out``).
RIGHT_ROOM = 0.03

#: The two error measures offered: the study's largest error and its mean.
ERRORS = {"max error": "error", "mean error": "mean_abs_texels"}

#: The slider's divide costs in cycles, 1 to 128: about a quarter of an octave apart, and
#: holding the prices the lesson prints (1, 2, 4 from Maxwell to the A100, a current GPU's 8,
#: the Pentium's 17, 128, and 30 and 32, 48 and 50 either side of 16 attributes' limits of
#: 31 and 49 at the Pentium's and the GPU's prices, which lesson 06 asks the student to
#: cross: review r329 S3). A starting price not among them is added, so the slider starts
#: exactly where it is asked to.
DIVIDE_CYCLES = (1, 1.5, 2, 3, 4, 5, 6, 8, 10, 12, 17, 20, 24, 30, 32, 40, 48, 50, 64, 80, 96, 128)
#: The status line's font size (CSS px): the size of the chart's axis labels, read from the
#: back of a room (review r228 FIG1: at JupyterLab's 13 px it could not be).
STATUS_PX = 18
#: The caption's font size (CSS px), and the title's, above the status line's.
CAPTION_PX, TITLE_PX = 16, 21
#: The sliders' read-outs ("17", "2") at their labels' size (the projector's 16 px,
#: ``common.PROJECTOR_CSS``, which sizes the labels but not the read-outs): at JupyterLab's 13
#: px they were the smallest text on the widget (review r243 FIG1). And read-only: a
#: SelectionSlider's read-out is ``contenteditable`` in JupyterLab but ignores what is typed
#: into it, which then stood beside a chart drawn at the old value (review r252 W1); no
#: pointer and no editing, so the slider and the arrow keys are the only way to set it.
READOUT_CSS = (
    "<style>.tr-projector .tr-readout .widget-readout {font-size: 16px}"
    " .tr-readout .widget-readout {pointer-events: none; user-select: none;"
    " -webkit-user-modify: read-only}</style>"
)

#: The divide prices the cost axis reaches to: the first of them at or above the slider's
#: divide. One axis for every price (review r41 06-5: the points should move, not the axis)
#: left the right ~45 % of the chart empty at the default 17 cycles, where the points end at
#: 24 (review r252 FIG1); these steps keep the axis still over each stretch of the slider and
#: fitted to the points at every price on it.
AXIS_REACH = (20.0, 48.0, 128.0)

#: The attribute counts offered, 1 to 128: the study's u and v (2), and a GPU's 16 and more,
#: up to the 128 the lesson quotes (Fatahalian, CMU 15-462 *Texture*: up to 128 scalar
#: attributes per triangle; review r290 W1: the slider stopped at 32).
ATTRIBUTE_COUNTS = (1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128)


def divide_positions(divide: float) -> list[float]:
    """:data:`DIVIDE_CYCLES` with ``divide`` among them, in order.

    >>> divide_positions(30)[:3], 30.0 in divide_positions(30), 7.0 in divide_positions(7)
    ([1.0, 1.5, 2.0], True, True)
    """
    if isinstance(divide, bool) or not isinstance(divide, numbers.Real):
        raise TypeError(f"divide must be a number of cycles, got {divide!r}")
    if not 0 < divide < float("inf"):
        raise ValueError(f"divide must be a positive finite number of cycles, got {divide}")
    return sorted({float(v) for v in DIVIDE_CYCLES} | {float(divide)})


def cost_axis(costs) -> tuple[float, float]:
    """The cost axis' limits for ``costs`` (the explorer passes those at the slider's cheapest
    and dearest prices, so one range holds every price and a price's change moves the points,
    not the axis: review r41 06-5), with room on the right for the dearest point's label, a
    fixed share of the axis' decades (at divide 128 "perspective" ended on the right spine
    with less: review r22, 06-8). The share is what the label needs, no more: at 0.3 of the
    decades the axis ran to about 700 cycles over points that end at 137 (review r56 06-2).

    >>> [round(float(v), 1) for v in cost_axis([2.0, 137.0])]
    [1.5, 245.9]
    """
    lo, hi = float(np.min(costs)) / 1.3, float(np.max(costs))
    return lo, float(hi * 10 ** (0.02 + 0.12 * np.log10(hi / lo)))


def cost_ticks(lo: float, hi: float) -> list[float]:
    """The cost axis' labelled values in [``lo``, ``hi``]: 1-2-5, and where the first of
    those lies over 1.5 times above ``lo``, one more below it at 1.5, 3 or 7 of a decade, so
    that the cheapest points have a label near them (at 32 attributes affine's 32 cycles
    sat on an axis labelled from 50 only: review r243 FIG1). An axis under two decades long
    that would carry fewer than five labels gets 1-1.5-2-3-5-7 (at 16 attributes the
    Pentium's axis read 15, 20, 50, 100, and perspective's and N = 2's 79 cycles, the
    break-even the lesson asks about, had no label near them: reviews r322 and r329 FIG).

    >>> cost_ticks(24.6, 258.0), cost_ticks(1.5, 246.0)[:3], cost_ticks(14.0, 150.0)
    ([30.0, 50.0, 70.0, 100.0, 150.0, 200.0], [2.0, 5.0, 10.0], [15.0, 20.0, 30.0, 50.0, 70.0, 100.0, 150.0])
    """
    decades = range(int(np.floor(np.log10(lo))), int(np.ceil(np.log10(hi))) + 1)

    def at(subs):
        return [v for e in decades for m in subs if lo <= (v := round(m * 10.0**e, 9)) <= hi]

    ticks = at((1, 2, 5))
    if hi < 100 * lo and len(ticks) < 5:
        return at((1, 1.5, 2, 3, 5, 7))
    if ticks and ticks[0] > 1.5 * lo:
        ticks = [v for v in at((1.5, 3, 7)) if v < ticks[0]][:1] + ticks
    return ticks


def short_name(variant: str) -> str:
    """``"subdivided N=16"`` -> ``"N=16"``; other names unchanged."""
    return variant.replace("subdivided ", "")


def priced(rows, divide: float, multiply: float = PRICES["Pentium (P5)"]["multiplies"],
           addition: float = 1.0, attributes: int = ATTRIBUTES,
           divide_issue: float | None = None) -> list[dict]:  # fmt: skip
    """Copies of ``rows`` with ``cycles`` recomputed from their operation counts.

    Parameters
    ----------
    rows : list of dict
        Interpolation rows with the operation counts of ``ATTRIBUTES`` (u and v).
    divide, multiply, addition : float
        Cycles per operation (the Pentium's multiply, 2, by default).
    attributes : int
        Attributes interpolated per pixel: each row's counts change by what
        :func:`~teachraster.study.operation_counts.interpolation_count` adds or removes for
        them (none at u and v), the reciprocal shared by all.
    divide_issue : float, optional
        The divide on a unit of its own, costing the other pipe this many issue cycles (a
        GPU's reciprocal: the price list's ``"divide issue"``); the two units overlap
        (:func:`~teachraster.study.operation_counts.cycles`). None: one unit, cycles add.

    >>> rows = [{"variant": "perspective", "divides": 1.0, "multiplies": 2.0, "additions": 3.0}]
    >>> [priced(rows, 17, attributes=k)[0]["cycles"] for k in (2, 16)]  # d + 3k + 1
    [24.0, 66.0]
    >>> [priced(rows, 4, multiply=1, attributes=k)[0]["cycles"] for k in (2, 16)]  # d + 2k + 1
    [9.0, 37.0]
    >>> [priced(rows, 8, 1, divide_issue=1, attributes=k)[0]["cycles"] for k in (2, 16)]
    [8.0, 34.0]
    """
    out = []
    for r in rows:
        ops = [r["divides"], r["multiplies"], r["additions"]]
        if attributes != ATTRIBUTES:
            now, then = (interpolation_count(r["variant"], k) for k in (attributes, ATTRIBUTES))
            ops = [o + getattr(now, n) - getattr(then, n)
                   for o, n in zip(ops, ("divides", "multiplies", "additions"))]  # fmt: skip
        weights = {"divides": divide, "multiplies": multiply, "additions": addition}
        if divide_issue is not None:
            weights["divide issue"] = divide_issue
        c = cycles(OpCount(*ops), weights)  # operation_counts' rule, overlap included
        out.append({**r, "divides": ops[0], "multiplies": ops[1], "additions": ops[2],
                    "cycles": float(c)})  # fmt: skip
    return out


def n2_limit(rows, attributes: int = ATTRIBUTES, multiply: float = 2.0,
             divide_issue: float | None = None) -> float:  # fmt: skip
    """The dearest divide, in cycles, at which subdivision by N = 2 costs at least as much as
    perspective-correct for ``attributes`` attributes. On one unit: ``2k - 1`` whatever a
    multiply costs (an addition 1); both costs are straight lines in the divide's price,
    perspective-correct's of slope 1 and N = 2's of slope 1/2: they meet once. With the
    divide on a unit of its own (``divide_issue``), N = 2 costs its other pipe's work, which
    exceeds perspective-correct's, until the divide alone (perspective-correct's cost once
    the divide is not hidden) passes it: the limit is N = 2's cost at a free divide,
    ``(m + 2)k + 1`` with one issue cycle.

    >>> rows = [{"variant": "perspective", "divides": 1.0, "multiplies": 2.0, "additions": 3.0},
    ...         {"variant": "subdivided N=2", "divides": 0.5, "multiplies": 2.0,
    ...          "additions": 4.5}]
    >>> [n2_limit(rows, k) for k in (2, 16)], n2_limit(rows, 16, multiply=1.0)
    ([3.0, 31.0], 31.0)
    >>> [n2_limit(rows, k, multiply=1.0, divide_issue=1.0) for k in (2, 16)]
    [7.0, 49.0]
    """
    at0, at1 = ({r["variant"]: r["cycles"] for r in priced(rows, d, multiply,
                                                            attributes=attributes,
                                                            divide_issue=divide_issue)}
                for d in (0.0, 1.0))  # fmt: skip
    if divide_issue is not None:  # two units: N = 2's pipe work is the divide's limit
        assert at0["subdivided N=2"] >= at0["perspective"]
        return at0["subdivided N=2"]
    slope = {v: at1[v] - at0[v] for v in ("perspective", "subdivided N=2")}
    gap = at0["subdivided N=2"] - at0["perspective"]  # N = 2's extra cost at a free divide
    return gap / (slope["perspective"] - slope["subdivided N=2"])


def error_locator(low: float, high: float, floor: float, most: int = MOST_ERROR_LABELS):
    """The error axis' major ticks: at 1-2-5 while that labels at most ``most`` values above
    the "0 (exact)" ``floor``, else at every decade (every other one, and so on, when even
    those are too many).

    The mean error spans five decades: at 1-2-5 it carried 16 labels in about 400 px (fresh
    reader, 2026-12-03); the max error's three decades keep 1-2-5.
    """
    fine = LogLocator(subs=(1, 2, 5))
    ticks = np.asarray(fine.tick_values(low, high))
    if np.count_nonzero((ticks > 2.0 * floor) & (ticks >= low) & (ticks <= high)) <= most:
        return fine
    # numticks bounds the decades matplotlib labels (it strides over decades past it)
    return LogLocator(subs=(1,), numticks=most)


class DivideCostExplorer(Shown):
    """Accuracy against cost of the interpolation variants, with the divide's price a slider.

    Parameters
    ----------
    rows : list of dict
        The study's interpolation rows with their operation counts
        (``ops.with_counts(bench.run(...))`` filtered to ``group == "interpolation"``).
    divide : float, optional
        Starting cost of a divide in issue cycles (an addition costs 1); by default the
        ``prices``' own (17 or 8); the slider starts there exactly.
    error : {"max error", "mean error"}
    attributes : int
        Starting number of attributes interpolated per pixel (one of
        :data:`ATTRIBUTE_COUNTS`); 2, the study's u and v, by default.
    prices : {"Pentium (P5)", "GPU (Ampere GA10x, Ada, Hopper)"}
        The price list (:data:`~teachraster.study.operation_counts.PRICES`): a multiply's
        cost, and the divide the slider starts at.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    prices : ipywidgets.ToggleButtons
        Choosing a list moves the divide slider to that list's divide.
    divide : ipywidgets.SelectionSlider
        Over :func:`divide_positions` (:data:`DIVIDE_CYCLES` and the starting price).
    error : ipywidgets.ToggleButtons
    attributes : ipywidgets.SelectionSlider
        Over :data:`ATTRIBUTE_COUNTS`.
    front : list of str
        The variants on the front, cheapest first, for the current settings.
    widget : ipywidgets.VBox
    """

    #: ``teachraster html``: the offline page steps through every divide cost (:mod:`.offline`)
    _offline_sweep_ = "divide"

    def __init__(self, rows, divide: float | None = None, *, error: str = "max error",
                 attributes: int = ATTRIBUTES, prices: str = "Pentium (P5)",
                 backend: str = "auto", style: str | None = None) -> None:  # fmt: skip
        self.rows = [r for r in rows if r.get("group", "interpolation") == "interpolation"]
        if not self.rows:
            raise ValueError("rows must hold the study's interpolation rows")
        if prices not in PRICES:
            raise ValueError(f"prices must be one of {list(PRICES)}, got {prices!r}")
        divide = PRICES[prices]["divides"] if divide is None else divide
        self.backend = resolve_backend(backend)
        # short labels, the full names as tooltips: with the full names the controls took four
        # rows in a 592-px column (test_browser_layout's limit is three)
        self.prices = widgets.ToggleButtons(
            options=[(name.split(" (")[0], name) for name in PRICES], value=prices,
            tooltips=list(PRICES), style={"button_width": "auto"})  # fmt: skip
        # a list of prices, not a log grid: 2^(k/4) skips 30, and the slider snapped the
        # model's 30 to 32 while the lesson printed 30 (review r5, 06-2)
        # the description at its own width, flush left: at the default width it sat right-aligned
        # in a wider box, indented beside the "error" label that wraps under it in a 592-px
        # column (review r24 06-8)
        self.divide = widgets.SelectionSlider(
            options=[(f"{v:g}", v) for v in divide_positions(divide)], value=float(divide),
            description="divide =", style={"description_width": "initial"},
            layout=fit_width(widgets.Layout(width="420px"))).add_class("tr-readout")  # fmt: skip
        self.error = widgets.ToggleButtons(options=list(ERRORS), value=error)
        if attributes not in ATTRIBUTE_COUNTS:
            raise ValueError(f"attributes must be one of {ATTRIBUTE_COUNTS}, got {attributes!r}")
        self.attributes = widgets.SelectionSlider(
            options=[(str(k), k) for k in ATTRIBUTE_COUNTS], value=attributes,
            description="attributes k =", style={"description_width": "initial"},
            layout=fit_width(widgets.Layout(width="420px"))).add_class("tr-readout")  # fmt: skip
        self._style = style
        with style_context(style):
            self._new_figure()
            self._plot()
            self._places: dict = {}  # error measure -> where the layout put the axes
            self._lay_out()
            self.display = FigureDisplay(self.fig, self.backend)
        self.info = widgets.HTML(self._info_html())
        #: the other error measure's picture at this price, drawn while the kernel idles
        #: (image display only), from the first change on: a lesson run without a page
        #: draws none. The figure on show is then stale (a toggle shows the kept picture).
        self._ahead = PicturesAhead(self._draw_elsewhere) if self.backend == "image" else None
        self._stale = False
        self.divide.observe(lambda change: self.update(), "value")
        self.attributes.observe(lambda change: self.update(replot=True), "value")
        self.error.observe(lambda change: self.update(replot=True), "value")
        self.prices.observe(lambda change: self._new_prices(), "value")
        title = title_html(
            f"{READOUT_CSS}<span style='font-size:{TITLE_PX}px'>What a divide costs decides the price of "
            "exactness</span>",
            f"<span style='font-size:{CAPTION_PX}px'>Cost per pixel in issue cycles (an "
            "addition = 1). Vermillion: the Pareto front, the variants for which "
            f"{FRONT_DEFINITION}. Grey: off it. Hollow: on its line, off it.</span>",
        )
        # the two choices on one line, the two sliders under them
        controls = control_rows([labelled("prices", self.prices), labelled("error", self.error)],
                                [self.divide, self.attributes])  # fmt: skip
        self.widget = projector_text(
            widgets.VBox([title, controls, self.info, self.display.widget]), title
        )

    def _new_prices(self) -> None:
        """Another price list: its multiply on the chart, the slider at its divide (one
        picture: the slider's own change is not drawn on the way)."""
        divide = PRICES[self.prices.value]["divides"]
        if self.divide.value == divide:
            self.update(replot=True)
            return
        self._moving_slider = True
        try:
            self.divide.value = divide
        finally:
            self._moving_slider = False
        self.update(replot=True)

    @property
    def _multiply(self) -> float:
        return PRICES[self.prices.value]["multiplies"]

    @property
    def _divide_issue(self) -> float | None:
        """The price list's issue slot for a divide on its own unit (the GPU's), else None."""
        return PRICES[self.prices.value].get("divide issue")

    def _cost_axis(self, attributes: int, divide: float) -> tuple[float, float]:
        """The cost axis' limits at ``attributes``: one range for every price of the slider's
        stretch that holds ``divide`` (:data:`AXIS_REACH`: :func:`cost_axis` over the
        cheapest price's costs and those at the stretch's end). Refitted at each price, the
        axis moved with the points and the slider mostly relabelled its ticks (review r41
        06-5); one range for the whole slider left the default's chart half empty (r252
        FIG1); one range for every attribute count too left the u-and-v chart in the left
        half of it. The layout keeps room on the right for a tick label at the axis' end
        (:meth:`_lay_out`)."""
        prices = [p for _, p in self.divide.options]
        reach = min([r for r in AXIS_REACH if r >= divide] or [prices[-1]])
        ends = [prices[0], min(reach, prices[-1])]
        return cost_axis([r["cycles"] for d in ends
                          for r in priced(self.rows, d, self._multiply,
                                          attributes=attributes,
                                          divide_issue=self._divide_issue)])  # fmt: skip

    def close(self) -> None:
        """Close the figure and every widget of the box."""
        if self._ahead is not None:
            self._ahead.close()
        super().close()

    def _new_figure(self) -> None:
        self.fig = new_figure((9.0, 5.5), self.backend)
        self.fig.set_layout_engine("constrained")
        self.ax = self.fig.add_subplot()

    def _draw_elsewhere(self, key) -> tuple:
        """``(png, caption, state)`` at divide price and error measure ``key``, drawn on a
        figure of its own (a second explorer's, made as this one's and kept for the next):
        the picture this explorer draws there (:class:`~teachraster.widgets.ahead.PicturesAhead`)."""
        other = getattr(self, "_elsewhere", None)
        if other is None:
            other = self._elsewhere = object.__new__(DivideCostExplorer)
            other.rows, other.backend, other._places = self.rows, "image", self._places
            other.divide, other.error, other.attributes, other.prices = (
                SimpleNamespace(value=None, options=self.divide.options) for _ in range(4))  # fmt: skip
            with style_context(self._style):
                other._new_figure()
        other.divide.value, other.error.value, other.attributes.value, other.prices.value = key
        with style_context(self._style):
            other._plot()
            other._lay_out()
        other.fig.canvas.draw()  # as this explorer's display draws it
        return png_bytes(other.fig), other._info_html(), {"front": other.front}

    @property
    def _ykey(self) -> str:
        return ERRORS[self.error.value]

    def _plot(self) -> None:
        # a new attribute count, or a divide in another stretch of the slider: a new axis
        self.xlim = self._cost_axis(self.attributes.value, self.divide.value)
        # the previous measure's artists removed, not the axes cleared: a cleared log axis
        # makes each of its tick marks anew at the next draw (about 60 % of a toggle)
        for artist in getattr(self, "_drawn", ()):
            artist.remove()
        before = set(self.ax.get_children())
        self.art = plot_pareto(
            self.ax, self._priced(), "cycles", y=self._ykey,
            xlabel=f"issue cycles per pixel ({self.prices.value.split(' (')[0]} prices)",
            ylabel=f"{self.error.value} (texels)",
            short=short_name, xlim=self.xlim, hollow_on_line=True,
        )  # fmt: skip
        # labels at 1-2-5 as lesson 06's own charts: a decade apart, only 10 and 100 were
        # (and 10⁰, 10¹, 10² on the cost axis: r11), one more near the axis' cheap end
        self.ax.xaxis.set_major_locator(FixedLocator(cost_ticks(*self.xlim)))
        self.ax.yaxis.set_major_locator(error_locator(*self.ax.get_ylim(), self.art.floor))
        self.ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
        floor_ticks(self.ax, self.art.floor, FormatStrFormatter("%g"))
        self._drawn = [a for a in self.ax.get_children() if a not in before]
        self.front = [r["variant"] for r in self.art.front]

    def _lay_out(self) -> None:
        """Place the axes as the constrained layout does for this error measure, solved once
        per measure (its labels are the only texts that change the layout): the solver cost
        about two thirds of each picture (issue 31: 455 ms a toggle)."""
        place = self._places.get(self.error.value)
        if place is None:
            self.ax.set_in_layout(True)  # set_position() below took it out of the layout
            self.fig.set_layout_engine("constrained")
            self.fig.get_layout_engine().execute(self.fig)  # the solver alone: no picture
            solved = self.ax.get_position()
            # room on the right for half a tick label at the axis' end: the cost axis is
            # fitted at each price, and a label ending it at another price ran off the
            # figure (r11: "10²" at divide 30, after a layout solved at divide 1)
            place = self._places[self.error.value] = Bbox.from_bounds(
                solved.x0, solved.y0, solved.width - RIGHT_ROOM, solved.height
            )
        self.fig.set_layout_engine("none")
        self.ax.set_position(place)

    def update(self, replot: bool = False) -> None:
        """Re-price the variants and redraw (the same artists unless the error measure changed;
        a picture drawn ahead for this price and measure: shown at once)."""
        if getattr(self, "_moving_slider", False):
            return  # a new price list moves the slider: drawn once, by _new_prices
        key = (self.divide.value, self.error.value, self.attributes.value, self.prices.value)
        kept = None if self._ahead is None else self._ahead.take(key)
        if kept is not None:
            show_kept(self, kept)
            self._stale = True  # the figure still shows the picture before
        else:
            if self._cost_axis(self.attributes.value, self.divide.value) != self.xlim:
                replot = True  # the divide left its stretch of the slider (AXIS_REACH)
            if replot or self._stale:
                with style_context(self._style):
                    self._plot()
                    self._lay_out()
                self._stale = False
            else:
                rows = self._priced()
                self.front = [r["variant"] for r in update_pareto(self.ax, self.art, rows,
                                                                   "cycles", y=self._ykey)]  # fmt: skip
            self.info.value = self._info_html()
            self.display.refresh()
            if self._ahead is not None:
                self._ahead.keep(key, (self.display.widget.value, self.info.value,
                                       {"front": self.front}))  # fmt: skip
        if self._ahead is not None:
            # the likeliest next pictures: the other measure here, the prices either side
            prices = [v for _, v in self.divide.options]
            i = prices.index(key[0])
            near = [prices[j] for j in (i + 1, i - 1) if 0 <= j < len(prices)]
            self._ahead.want([(key[0], e, *key[2:]) for e in ERRORS if e != key[1]]
                             + [(p, key[1], *key[2:]) for p in near])  # fmt: skip

    def _priced(self) -> list[dict]:
        """The rows priced at the sliders' divide and attribute count."""
        return priced(self.rows, self.divide.value, self._multiply,
                      attributes=self.attributes.value, divide_issue=self._divide_issue)  # fmt: skip

    def _info_html(self) -> str:
        """What the sliders change: the divide's share of the exact divide's cost, what
        Quake's subdivision (N = 16) still saves at this price, and (the headline) up to
        which price N = 2 is no cheaper than the exact divide with this many attributes."""
        rows = {r["variant"]: r for r in self._priced()}
        names = " → ".join(short_name(v) for v in self.front)
        exact = rows["perspective"]["cycles"]
        ratio = exact / rows["affine"]["cycles"]
        # what the divide adds to perspective-correct: all its cycles on one unit, on a unit of
        # its own only what the other pipe's work does not hide (review r252 F1)
        free = priced([rows["perspective"]], 0.0, self._multiply,
                      divide_issue=self._divide_issue)[0]["cycles"]  # fmt: skip
        share = (exact - free) / exact
        quake = rows.get("subdivided N=16")
        saving = ""
        if quake is not None:
            saving = (f"; Quake's N=16 costs <b>{quake['cycles'] / exact:.0%}</b> of "
                      "perspective-correct")  # fmt: skip
        unit = "cycle" if self.divide.value == 1 else "cycles"
        k = self.attributes.value
        headline = ""
        if "subdivided N=2" in rows:
            limit = n2_limit(self.rows, k, self._multiply, self._divide_issue)
            headline = (f"<b>{k} attribute{'s share' if k > 1 else ' has'} one reciprocal: N=2 "
                        f"costs at least as much as perspective-correct for every divide up to "
                        f"{limit:.3g} {'cycle' if limit == 1 else 'cycles'}.</b> ")  # fmt: skip
        multiply = f"a multiply {self._multiply:g}"
        divide_is = "the divide is"
        if self._divide_issue is not None:  # on its own unit: only what is not hidden counts
            multiply += ", the divide on its own unit, in parallel"
            divide_is = "the divide's cycles not hidden by the multiply-adds are"
        return (f"<div style='font-size:{STATUS_PX}px;line-height:1.35'>{headline}"
                f"divide = {self.divide.value:.3g} {unit} ({multiply}), attributes "
                f"k = {k}: {divide_is} "
                f"<b>{share:.0%}</b> of perspective-correct's cost; perspective-correct costs "
                f"<b>{ratio:.3g}×</b> affine{saving}. "
                f"Front, cheapest first: {names}</div>")  # fmt: skip
