"""``LinePlayer``: step through a line like a fill, and switch its rule.

Lesson 12a's player: Play/Pause and a step slider over the steps of
:func:`teachraster.rasterize_line` (``trace=True``): the snap, the major axis, then one step
per column (or row) with the rule's decision in the caption: the diamond test, Bresenham's
error term or the DDA's float32 sum. The figure is a :class:`~teachraster.plotting.lines.LineView`
whose artists are updated in place.
"""

from __future__ import annotations

import ipywidgets as widgets

from ..core.line_rules import RULES
from ..core.lines import rasterize_line
from ..plotting.lines import LineView, fit_caption
from .common import (
    Shown,
    control_row,
    labelled,
    renew_slider,
    style_context,
    title_html,
)
from .display import FigureDisplay, html_escape, new_figure, resolve_backend

#: The figure's share kept below the axes for the step's caption, out of the layout: the axes
#: box is then the same for every step and every rule (review r83 12a-6: it moved sideways by
#: some 20 px when the rule, and with it the caption, changed). The least share: the figure
#: grows taller when the longest caption of any rule needs more (:func:`caption_room`).
CAPTION_ROOM = 0.2


def caption_room(fig, view, traces) -> float:
    """Make the room under ``view``'s axes hold the longest caption of ``traces``.

    The figure keeps its width and the height its axes have (so the wrap width and the axes
    box stay those of every step and rule) and grows by what the caption needs beyond
    :data:`CAPTION_ROOM` of it; the layout is redone with the new share.

    Parameters
    ----------
    fig : matplotlib Figure
        The player's figure, laid out with ``rect=(0, room, 1, 1 - room)``.
    view : LineView
        Its view; ``view.caption`` is the Text under the axes.
    traces : list of LineTrace
        Every trace the player can show (one per rule).

    Returns
    -------
    float
        The room's share of the (new) figure height.
    """
    text, shown = view.caption, view.caption.get_text()
    renderer = fig.canvas.get_renderer()
    need = 0.0  # inches, from the axes' bottom to the caption's last line, box included
    for trace in traces:
        for k in range(len(trace)):
            text.set_text(fit_caption(text, trace.caption(k)))
            text.update_bbox_position_size(renderer)  # the box is otherwise set when drawn
            box = text.get_bbox_patch()
            extent = (box if box is not None else text).get_window_extent(renderer)
            need = max(need, (view.image.axes.bbox.y0 - extent.y0) / fig.dpi)
    text.set_text(shown)
    width, height = fig.get_size_inches()
    above = height * (1 - CAPTION_ROOM)  # the axes' part, kept
    room = max(height * CAPTION_ROOM, need + 0.1)
    share = room / (above + room)
    if share > CAPTION_ROOM:
        fig.set_size_inches(width, above + room)
        fig.set_layout_engine("constrained", rect=(0, share, 1, 1 - share))
        fig.draw_without_rendering()
    return max(share, CAPTION_ROOM)


class LinePlayer(Shown):
    """Play a traced line step by step; ``rule`` toggles diamond / Bresenham / DDA.

    Parameters
    ----------
    p0, p1 : (2,) end points in window px; width, height : image size.
    rule : {"diamond", "bresenham", "dda"}
    step : int, the step shown first (-1: the finished line).
    backend, style : as the other widgets.

    Examples
    --------
    >>> player = LinePlayer((0.5, 0.5), (9.5, 4.5), 11, 6, backend="image")
    >>> player.slider.value = 3
    >>> player.caption.value
    'step 3 (0 to 11): column 1 (steps 0 and 1 set the line up)'
    >>> player.view.caption.get_text().startswith("column 1")
    True
    >>> player.rule.value = "bresenham"
    >>> "error term" in player.trace.caption(3)
    True
    >>> player.where(player.slider.value).split(": ")[1]  # the column kept, not the step index
    'column 1 (steps 0 and 1 set the line up)'
    >>> player.close()
    """

    #: ``teachraster html``: the offline page steps through every step of the line (:mod:`.offline`)
    _offline_sweep_ = "slider"

    def __init__(self, p0, p1, width, height, *, rule="diamond", step=-1, interval=400,
                 backend="auto", style=None):  # fmt: skip
        self.p0, self.p1, self.width, self.height = p0, p1, width, height
        self.backend = resolve_backend(backend)
        self.fill = rasterize_line(p0, p1, width, height, rule=rule, trace=True)
        n = len(self.trace)
        self.rule = widgets.ToggleButtons(options=list(RULES), value=rule)
        self.play = widgets.Play(value=0, min=0, max=n - 1, interval=interval)
        self._link = None
        self.slider = widgets.IntSlider(value=self.trace.index(step), min=0, max=n - 1,
                                        description="step")  # fmt: skip
        self._wire(self.slider)
        with style_context(style):
            self.fig = new_figure((9.0, 5.0), self.backend)
            # the caption (under the axes) is left out of the layout, in room of its own
            self.fig.set_layout_engine("constrained", rect=(0, CAPTION_ROOM, 1, 1 - CAPTION_ROOM))
            self.view = LineView.create(self.fig.add_subplot(), self.fill, self.slider.value)
            self.view.caption.set_in_layout(False)
            # constrained layout settles on the second draw (the first one measured the top
            # axis's labels before they were placed, and cut "column j" and the caption off)
            self.fig.draw_without_rendering()
            # room for the longest caption of every rule, the axes box unchanged (review r168
            # 12a-5: a diamond tie's caption has 5 lines, and its last fell below the figure)
            caption_room(
                self.fig,
                self.view,
                [rasterize_line(p0, p1, width, height, rule=r, trace=True).trace for r in RULES],
            )
            self.display = FigureDisplay(self.fig, self.backend)
        # where the slider is, in the figure's words (its caption, under the picture, says
        # what the rule decided): "step 7" and "column 5" side by side, the caption once
        self.caption = widgets.HTML(html_escape(self.where(self.slider.value)))
        self.rule.observe(lambda change: self._rerun(), "value")
        title = title_html(
            "A line, step by step",
            "One step per column (x-major) or row: which pixel is lit, and why.",
        )
        self.controls = control_row([self.play, self.slider, labelled("rule", self.rule)])
        self.widget = widgets.VBox([title, self.controls, self.caption, self.display.widget])

    @property
    def trace(self):
        """The line's :class:`~teachraster.core.line_trace.LineTrace`."""
        return self.fill.trace

    def where(self, k: int) -> str:
        """Step ``k`` named by what it works on: "step 7 (0 to 14): column 5 (…)"."""
        step = self.trace.step(k)
        last = len(self.trace) - 1
        if step.work is None:
            return f"step {step.index} (0 to {last}): set-up ({step.kind})"
        setup = "(steps 0 and 1 set the line up)"
        if step.kind == "triangle":  # a wide line: two triangles, no columns
            return f"step {step.index} (0 to {last}): triangle {step.work + 1} of 2 {setup}"
        major = step.col if step.kind == "column" else step.row
        return f"step {step.index} (0 to {last}): {step.kind} {major} {setup}"

    def show(self, k: int) -> None:
        """Show step ``k`` (updates the artists, the caption and the step line in place)."""
        self.view.show_step(k)
        self.caption.value = html_escape(self.where(k))
        self.display.refresh()

    def _wire(self, slider: widgets.IntSlider) -> None:
        """Link the step slider ``slider`` to Play and to :meth:`show` (Play moved there)."""
        if self._link is not None:
            self._link.unlink()
        self.play.max = slider.max
        self.play.value = slider.value
        self._link = widgets.jslink((self.play, "value"), (slider, "value"))
        slider.observe(lambda change: self.show(change["new"]), "value")

    def matching_step(self, old_step, at_end: bool) -> int:
        """The step of the current trace that shows what ``old_step`` (a Step of another
        rule's trace) showed: the same column (row), the same set-up step, or the last step
        when the slider was at its end or the column is not walked by this rule."""
        last = len(self.trace) - 1
        if at_end:
            return last
        if old_step.work is None:  # a set-up step: the same one
            return min(old_step.index, last)
        for k in range(last + 1):
            step = self.trace.step(k)
            if (
                step.kind == old_step.kind
                and step.kind in ("column", "row")
                and (
                    (step.col if step.kind == "column" else step.row)
                    == (old_step.col if old_step.kind == "column" else old_step.row)
                )
            ):
                return k
        return last

    def _rerun(self) -> None:
        # the column on show stays on show (review r83 12a-6: the step index stayed, and the
        # last step of Bresenham became the next-to-last of the diamond rule)
        old_step = self.trace.step(self.slider.value)
        at_end = self.slider.value == self.slider.max
        self.fill = rasterize_line(self.p0, self.p1, self.width, self.height,
                                   rule=self.rule.value, trace=True)  # fmt: skip
        self.view.trace = self.trace
        # a new step slider, not its max changed in place: the page's noUiSlider kept its
        # first range for Home and End, and after Bresenham (13 steps) -> diamond (14) End
        # stopped one step short (review r27, lesson 12a; renew_slider)
        self.slider = renew_slider(self.slider, self.controls, max=len(self.trace) - 1,
                                   value=self.matching_step(old_step, at_end),
                                   wire=self._wire)  # fmt: skip
        self.show(self.slider.value)
