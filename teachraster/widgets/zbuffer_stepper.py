"""``ZBufferStepper``: step a z-buffer through a scene, one triangle at a time.

Lesson 05a's widget. For the chosen triangle it shows which of its fragments passed the depth
test (and were written) and which failed, beside the depth buffer as it was after that
triangle. Everything comes from the render's trace (:mod:`teachraster.plotting.zbuffer_steps`):
the widget rasterises nothing itself.
"""

from __future__ import annotations

import ipywidgets as widgets

from ..plotting.zbuffer_steps import ZBufferStepView
from .common import (
    Shown,
    control_row,
    style_context,
    title_html,
)
from .display import FigureDisplay, new_figure, resolve_backend


class ZBufferStepper(Shown):
    """Triangle slider and previous/next buttons over a traced render.

    Parameters
    ----------
    frame : Frame
        From ``tr.render(..., trace=True)``.
    k : int
        Triangle shown first.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    triangle : ipywidgets.IntSlider
    previous, next : ipywidgets.Button
    counts : tuple of int
        (passed, failed) fragments of the triangle shown.
    widget : ipywidgets.VBox

    Examples
    --------
    >>> import teachraster as tr
    >>> frame = tr.render(tr.get_scene("cube"), None, 64, 48, trace=True)
    >>> st = ZBufferStepper(frame, backend="image")
    >>> st.next.click()
    >>> st.triangle.value
    1
    >>> st.close()
    """

    #: ``teachraster html``: the offline page steps through every triangle's z-buffer (:mod:`.offline`)
    _offline_sweep_ = "triangle"

    def __init__(self, frame, k: int = 0, *, backend: str = "auto",
                 style: str | None = None) -> None:  # fmt: skip
        if getattr(frame, "trace", None) is None:
            raise ValueError("frame must come from tr.render(..., trace=True)")
        self.backend = resolve_backend(backend)
        with style_context(style):
            self.fig = new_figure((9.0, 5.0), self.backend)
            self.fig.set_layout_engine("constrained")
            ax_f, ax_d = self.fig.subplots(1, 2)
            self.view = ZBufferStepView(frame, ax_f, ax_d)
            self.counts = self.view.show(int(k))
            # laid out once: re-solved per step, the constrained layout moved the panels and
            # resized the colour bar with each title's length (review r59 05a-5)
            self.fig.canvas.draw()
            self.fig.set_layout_engine("none")
            self.display = FigureDisplay(self.fig, self.backend)
        n = self.view.n_triangles
        self.triangle = widgets.IntSlider(value=int(k), min=0, max=n - 1, description="triangle")
        self.previous = widgets.Button(
            description="◀ previous", layout=widgets.Layout(width="auto")
        )
        self.next = widgets.Button(description="next ▶", layout=widgets.Layout(width="auto"))
        self.previous.on_click(lambda _: self._step(-1))
        self.next.on_click(lambda _: self._step(+1))
        self.triangle.observe(lambda change: self.update(), "value")
        self._ends()
        title = title_html(
            "The z-buffer, one triangle at a time",
            "Blue: this triangle's fragments that were nearer than the buffer and were written; "
            "vermillion: those that failed. Right: the depth buffer after this triangle.",
        )
        controls = control_row([self.previous, self.triangle, self.next])
        self.widget = widgets.VBox([title, controls, self.display.widget])

    def _step(self, d: int) -> None:
        self.triangle.value = min(max(self.triangle.value + d, 0), self.triangle.max)

    def _ends(self) -> None:
        # a button that can do nothing says so (review r9, lesson 05a c21)
        self.previous.disabled = self.triangle.value <= 0
        self.next.disabled = self.triangle.value >= self.triangle.max

    def update(self) -> None:
        """Show the slider's triangle and redraw."""
        self.counts = self.view.show(self.triangle.value)
        self._ends()
        self.display.refresh()
