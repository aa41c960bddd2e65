"""``ProjectionExplorer``: slide a point along the screen and watch where it lands in the world.

Lesson 04's picture of Ek's derivation (*Triangles and Perspective Correct Interpolation*, §2,
Figures 6-7): the eye, the screen line z = 1 and a segment receding in depth. The slider moves
the screen parameter q; the eye ray through that screen point meets the segment at the world
parameter t, drawn on the picture and on the curve t(q) below it. Equal steps of q are
marked on the screen, and the rays through them hit the segment at unequal steps.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

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
    ratio : ipywidgets.FloatSlider
        z1 / z0, the far end's depth over the near end's (1 to 8). The far end moves along its
        own eye ray, so the segment's picture on the screen stays where it is: only how the
        screen steps fall on it changes (review r3 04: |t − q| depends on the ratio only).
    t : float
        World parameter at the current q.
    largest_gap : float
        The largest |t − q| over the screen at the current ratio.
    info : ipywidgets.HTML
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
            self.axes = self.fig.subplots(2, 1, height_ratios=[1.6, 1.0])
            self.n_steps, self.style = n_steps, style
            self._plot()
            self.display = FigureDisplay(self.fig, self.backend)
        self.ratio = widgets.FloatSlider(
            value=self.segment.z1 / self.segment.z0, min=1.0, max=8.0, step=0.25,
            description="z1 / z0", continuous_update=False, readout_format=".2f",
        )  # fmt: skip
        self.info = widgets.HTML(self._info_html())
        self.q.observe(lambda change: self.update(), "value")
        self.ratio.observe(lambda change: self.set_ratio(change["new"]), "value")
        title = title_html(
            "Equal steps on the screen, unequal steps in the world",
            "Move q along the screen: the eye ray through it meets the segment at t. The hollow "
            "circle is where affine interpolation (t = q) would put it. Move z1 / z0: the far "
            "end slides along its own ray, deeper or nearer.",
        )
        self.widget = widgets.VBox([title, self.q, self.ratio, self.info, self.display.widget])

    def _plot(self) -> None:
        ax, curve = self.axes
        ax.clear()
        curve.clear()
        self.artists = plot_projection(ax, self.segment, n_steps=self.n_steps, q=self.q.value,
                                       curve_ax=curve)  # fmt: skip
        self.t = self.artists.update(self.q.value)
        qq = np.linspace(0.0, 1.0, 401)
        self.largest_gap = float(np.max(np.abs(self.segment.world_parameter(qq) - qq)))

    def _info_html(self) -> str:
        r = self.segment.z1 / self.segment.z0
        return (f"depth ratio z1 / z0 = {r:.2f} · largest |t − q| over the screen: "
                f"<b>{self.largest_gap:.3f}</b>")  # fmt: skip

    def set_ratio(self, ratio: float) -> None:
        """Move the far end along its eye ray to depth ``ratio`` · z0, and redraw."""
        seg = self.segment
        z1 = float(ratio) * seg.z0
        self.segment = Segment(seg.x0, seg.z0, seg.x1 / seg.z1 * z1, z1)  # same screen point
        with style_context(self.style):
            self._plot()
        self.info.value = self._info_html()
        self.display.refresh()

    def update(self) -> None:
        """Move the ray to the slider's q and redraw."""
        self.t = self.artists.update(self.q.value)
        self.display.refresh()
