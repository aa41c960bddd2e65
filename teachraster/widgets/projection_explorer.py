"""``ProjectionExplorer``: slide a point along the screen and watch where it lands in the world.

Lesson 04's picture of Ek's derivation (*Triangles and Perspective Correct Interpolation*, §2,
Figures 6-7): the eye, the screen line z = 1 and a segment receding in depth. The slider moves
the screen parameter q; the eye ray through that screen point meets the segment at the world
parameter t, drawn on the picture and on the curve t(q) below it. Equal steps of q are
marked on the screen, and the rays through them hit the segment at unequal steps.
"""

from __future__ import annotations

import ipywidgets as widgets

from ..plotting.projection import Segment, plot_projection
from .common import Shown, style_context, title_html
from .display import FigureDisplay, new_figure, resolve_backend


class ProjectionExplorer(Shown):
    """The eye–screen–segment picture with a slider for the screen parameter q.

    Parameters
    ----------
    segment : Segment, optional
        The world segment (default: from depth 1.5 to depth 6).
    q : float
        Starting screen parameter.
    n_steps : int
        Equal screen steps marked.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    q : ipywidgets.FloatSlider
    t : float
        World parameter at the current q.
    widget : ipywidgets.VBox

    Examples
    --------
    >>> ex = ProjectionExplorer(backend="image")
    >>> ex.q.value = 0.5
    >>> round(ex.t, 3)
    0.2
    >>> ex.close()
    """

    #: ``teachraster html``: the offline page steps through every point along the screen (:mod:`.offline`)
    _offline_sweep_ = "q"

    def __init__(self, segment: Segment | None = None, q: float = 0.5, *, n_steps: int = 8,
                 backend: str = "auto", style: str | None = None) -> None:  # fmt: skip
        self.segment = Segment() if segment is None else segment
        self.backend = resolve_backend(backend)
        self.q = widgets.FloatSlider(value=q, min=0.0, max=1.0, step=0.01, description="q",
                                     continuous_update=True, readout_format=".2f")  # fmt: skip
        with style_context(style):
            self.fig = new_figure((9.0, 10.0), self.backend)
            self.fig.set_layout_engine("constrained")
            ax, curve = self.fig.subplots(2, 1, height_ratios=[1.6, 1.0])
            self.artists = plot_projection(ax, self.segment, n_steps=n_steps, q=q, curve_ax=curve)
            self.t = self.artists.update(q)
            self.display = FigureDisplay(self.fig, self.backend)
        self.q.observe(lambda change: self.update(), "value")
        title = title_html(
            "Equal steps on the screen, unequal steps in the world",
            "Move q along the screen: the eye ray through it meets the segment at t. The hollow "
            "circle is where affine interpolation (t = q) would put it.",
        )
        self.widget = widgets.VBox([title, self.q, self.display.widget])

    def update(self) -> None:
        """Move the ray to the slider's q and redraw."""
        self.t = self.artists.update(self.q.value)
        self.display.refresh()
