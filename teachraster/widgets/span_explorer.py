"""``SpanSubdivisionExplorer``: subdivision on one span, N and the depth ratio r on sliders (06).

Quake divides exactly every N pixels of a span and joins the exact values by affine chords.
Here one span of :data:`~teachraster.study.span_subdivision.SPAN_PIXELS` pixels whose depth
grows by a factor r from its first pixel to its last: the true (perspective-correct) u, the
chords, and the worst miss, which the closed form (√ρ − 1)²/(ρ − 1) of the piece's change
gives for each piece of depth ratio ρ (:mod:`teachraster.study.span_subdivision`, checked
against ``tr.rasterize``'s subdivided interpolation by the tests).
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from ..plotting.blitting import MOVING, STILL, LayeredBlit
from ..plotting.span_subdivision import plot_span, update_span
from ..study.span_subdivision import SPAN_PIXELS, subdivide_span
from .common import Shown, control_row, fit_width, projector_text, style_context, title_html
from .display import new_figure, resolve_backend
from .divide_cost import CAPTION_PX, TITLE_PX  # the explorers' text sizes, one place
from .live_slider import LiveSlider, info_line, slider_display

#: The picture's alternative text in the page
ALT = "one span: the true texture coordinate, the chords between exact divides, their miss"
#: The sliders' ranges: N = 2 ... 64 (the whole span one piece), r = 1 ... 100 (the lesson's
#: floor recedes a hundredfold), both by powers (of 2; of 10 in eighths of a decade).
N_EXPONENTS, R_DECADES, R_STEP = (1, 6), (0.0, 2.0), 0.125


class SpanSubdivisionExplorer(Shown):
    """One span subdivided: N (pixels between exact divides) and r (depth ratio of its ends).

    Parameters
    ----------
    n : int
        Pixels between exact divides, a power of 2 from 2 to 64.
    r : float
        The last pixel's depth over the first's, 1 to 100.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    n, r : LiveSlider
    result : teachraster.study.span_subdivision.SpanSubdivision
        The span at the current settings (``result.worst_texels``, ``result.worst_px``).
    widget : ipywidgets.VBox

    Examples
    --------
    >>> ex = SpanSubdivisionExplorer(16, 1.5, backend="image")  # 65 centres: 64 steps
    >>> before = ex.result.worst_px
    >>> ex.n.value = 8                       # nearly the square law where w changes little
    >>> round(before / ex.result.worst_px, 1)
    3.9
    >>> ex.close()
    """

    #: ``teachraster html``: the offline page steps through every N (:mod:`.offline`)
    _offline_sweep_ = "n"

    def __init__(self, n: int = 16, r: float = 4.0, *, backend: str = "auto",
                 style: str | None = None) -> None:  # fmt: skip
        exponent = float(np.log2(n))
        if (
            n != int(n)
            or exponent != round(exponent)
            or not (N_EXPONENTS[0] <= exponent <= N_EXPONENTS[1])
        ):
            raise ValueError(f"n must be a power of 2 from 2 to 64, got {n!r}")
        if not 1.0 <= float(r) <= 10 ** R_DECADES[1]:
            raise ValueError(f"r must lie in [1, 100], got {r!r}")
        self.backend = resolve_backend(backend)
        self.n = LiveSlider(value=float(n), min=N_EXPONENTS[0], max=N_EXPONENTS[1], step=1,
                            base=2, description="N (pixels between divides)",
                            readout_format=".0f",
                            layout=fit_width(widgets.Layout(width="400px")))  # fmt: skip
        self.r = LiveSlider(value=float(r), min=R_DECADES[0], max=R_DECADES[1], step=R_STEP,
                            base=10, description="r (depth ratio of the ends)",
                            readout_format=".3g",
                            layout=fit_width(widgets.Layout(width="400px")))  # fmt: skip
        self._compute_at(self.n.value, 0)
        with style_context(style):
            self.fig = new_figure((9.0, 6.4), self.backend)
            self.fig.set_layout_engine("constrained")
            ax_u, ax_miss = self.fig.subplots(2, 1, sharex=True, height_ratios=(3, 2))
            self.art = plot_span(ax_u, ax_miss, self.result)
            self.fig.canvas.draw()  # laid out once: the controls move the same artists
            self.fig.set_layout_engine("none")
            self._blit = self._plan_blit((ax_u, ax_miss))
            dragged = lambda: self.n.dragging or self.r.dragging  # noqa: E731
            self.display = slider_display(self.fig, self.backend, draw=self._blit.draw,
                                          drafting=dragged, alt=ALT)  # fmt: skip
        self.info, info_widgets = info_line(self.display)
        self.info.value = self._info_html()
        for control in (self.n, self.r):
            control.observe(lambda change: self.update(), "value")
        title = title_html(
            f"<span style='font-size:{TITLE_PX}px'>One span: an exact divide every N pixels</span>",
            f"<span style='font-size:{CAPTION_PX}px'>A span of {SPAN_PIXELS} pixels "
            f"({SPAN_PIXELS - 1} steps) whose depth w grows by a factor r from its first pixel "
            "to its last. Dark: the true u; vermillion: the chords between the exact divides; "
            "blue: the worst miss at a pixel centre, and each piece's closed form "
            "(√ρ − 1)²/(ρ − 1) of its change of u, ρ the piece's own depth ratio. Below, a miss "
            "under 0.01 texel (at every exact divide it is 0) is drawn in the grey band at the "
            "bottom, marked < 0.01.</span>",
        )
        self.widget = projector_text(
            widgets.VBox([title, control_row([self.n, self.r]), *info_widgets,
                          self.display.widget]), title)  # fmt: skip
        self._ahead = None
        if self.backend != "ipympl":
            self._ahead = self.display.ahead([self.n, self.r], self)

    def _plan_blit(self, axes) -> LayeredBlit:
        """The curves, dots and the worst miss move; frames, ticks and keys lie over them."""
        a = self.art
        over = [child for ax in axes for child in (*ax.spines.values(), ax.xaxis, ax.yaxis)]
        keys = [ax.get_legend() for ax in axes if ax.get_legend() is not None]
        moving = [a.true, a.chords, a.anchors, a.worst, a.worst_text, a.miss, a.bounds,
                  a.pixel_miss]  # fmt: skip
        return LayeredBlit(self.fig, [(MOVING, moving), (STILL, over + keys)])

    def update(self) -> None:
        """Recompute from the sliders and move the same artists."""
        self._compute_at(self.n.value, 0)
        self._set_artists()
        self.info.value = self._info_html()
        self.display.refresh()

    # what the pictures drawn ahead need (teachraster.widgets.ahead.FramesAhead)
    def _compute_at(self, value, which) -> None:
        """The span with slider ``which`` (0: N, 1: r) at ``value``, the other where it is."""
        n, r = (value, self.r.value) if which == 0 else (self.n.value, value)
        self.result = subdivide_span(int(round(n)), float(r))

    def _set_artists(self) -> None:
        update_span(self.art, self.result)

    def _info_html(self) -> str:
        """The worst piece's numbers, all from its pixel centres, and its closed-form bound."""
        s = self.result
        k = s.worst
        a, b = (int(s.anchors[k]), int(s.anchors[k + 1])) if len(s.anchors) > 1 else (0, 0)
        rho, change = float(s.rho[k]), float(s.anchor_u[k + 1] - s.anchor_u[k]) if b else 0.0
        share = float(s.bound_texels[k] / change) if change else 0.0
        # at ρ = 1 the closed form is 0/0: its limit, no miss, said as such (review r283)
        bound = (f"at most (√ρ − 1)²/(ρ − 1) = {share:.3f} of its Δu = {change:.3g} texels "
                 f"and of its {b - a} px" if rho > 1 else
                 f"none (at ρ = 1 u is affine): 0 of its Δu = {change:.3g} "
                 f"texels and of its {b - a} px")  # fmt: skip
        if rho <= 1 and s.worst_texels == 0:  # r515 S3: nothing misses, no worst piece to name
            return f"N = {s.n}, r = {s.r:.3g}: no piece misses (ρ = 1: u is affine)."
        return (f"N = {s.n}, r = {s.r:.3g}: the worst piece, pixels {a}–{b}, ρ = {rho:.3g}. "
                f"At its pixel centres the chord misses by up to <b>{s.worst_texels:.3g} "
                f"texels</b> (pixel {s.worst_x}) and shows a texel that belongs up to "
                f"<b>{s.worst_px:.3g} px</b> away (pixel {s.worst_px_x}). Between centres, "
                + bound)  # fmt: skip
