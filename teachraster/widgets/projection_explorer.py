"""``ProjectionExplorer``: slide a point along the screen and watch where it lands in the world.

Lesson 04's picture of Ek's derivation (*Triangles and Perspective Correct Interpolation*, §2,
Figures 6-7): the eye, the screen line z = 1 and a segment receding in depth. The slider moves
the screen parameter q; the eye ray through that screen point meets the segment at the world
parameter t, drawn on the picture and on the curve t(q) below it. Equal steps of q are
marked on the screen, and the rays through them hit the segment at unequal steps.

The q slider is a :class:`~teachraster.widgets.LiveSlider` whose positions are drawn ahead
(:mod:`teachraster.widgets.ahead`) while the kernel idles: dragging it shows the page's own
pictures, at the screen's rate; a plain slider sent every value to the kernel, which
re-rendered the whole figure for each (3 pictures in 1.5 s, issue 31).
"""

from __future__ import annotations

import ipywidgets as widgets
from matplotlib.legend import Legend

from ..plotting.blitting import MOVING, LayeredBlit
from ..plotting.projection import Segment, frame_of, plot_projection
from .common import Shown, style_context, title_html
from .display import new_figure, resolve_backend
from .live_slider import LiveSlider, info_line, slider_display

#: The picture's alternative text in the page
ALT = "the eye, the screen and the segment, and the curve t(q)"
#: The z1 / z0 slider's range
RATIOS = (1.0, 8.0)


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
    q : LiveSlider
    ratio : ipywidgets.FloatSlider
        z1 / z0, the far end's depth over the near end's (1 to 8). The far end moves along its
        own eye ray, so the segment's picture on the screen stays where it is: only how the
        screen steps fall on it changes (review r3 04: |t − q| depends on the ratio only).
        The axes are fitted to the segment at the current ratio, on one scale in x and z:
        held for every ratio (review r144 04-2), they left two thirds of the picture empty at
        the default ratio and squeezed the screen, its ticks and the hits into a strip
        (review r234 04-FIG1). The segment's image on the screen is the same at every ratio;
        only the scale of the page changes.
    t : float
        World parameter at the current q.
    largest_gap : float
        The largest |t − q| over the screen at the current ratio.
    peak_q : float
        The q where it occurs (marked on the curve t(q)).
    info : PageCaption or ipywidgets.HTML
        The line above the picture (its ``value``).
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
        # in the page, its positions drawn ahead (coalesced where they are not)
        self.q = LiveSlider(value=q, min=0.0, max=1.0, step=0.01, description="q",
                            readout_format=".2f")  # fmt: skip
        self._q = float(self.q.value)  # the q of the picture on show
        with style_context(style):
            self.fig = new_figure((9.0, 7.0), self.backend)
            self.fig.set_layout_engine("constrained")
            # the picture on the left, as tall as the figure (one scale in x and z makes it
            # tall and narrow); its key and the curve t(q) on the right
            axd = self.fig.subplot_mosaic(
                [["picture", "key"], ["picture", "curve"]],
                width_ratios=[1.15, 1.0],
                height_ratios=[1.0, 1.2],
            )
            self.axes = [axd["picture"], axd["curve"]]
            self._key_ax = axd["key"]
            self.n_steps, self.style = n_steps, style
            self._plot()
            self._lay_out()
            self.display = slider_display(self.fig, self.backend, draw=self._draw_figure,
                                          drafting=lambda: self.q.dragging, alt=ALT)  # fmt: skip
        self.ratio = widgets.FloatSlider(
            value=self.segment.z1 / self.segment.z0, min=RATIOS[0], max=RATIOS[1], step=0.25,
            description="z1 / z0", continuous_update=False, readout_format=".2f",
        )  # fmt: skip
        # the caption of the page's picture: a picture drawn ahead brings its own
        self.info, info_widgets = info_line(self.display)
        self.info.value = self._info_html()
        self.q.observe(lambda change: self.update(), "value")
        self.ratio.observe(lambda change: self.set_ratio(change["new"]), "value")
        title = title_html(
            "Equal steps on the screen, unequal steps in the world",
            "Move q along the screen: the eye ray through it meets the segment at t. The hollow "
            "circle is where affine interpolation (t = q) would put it. Move z1 / z0: the far "
            "end slides along its own ray, deeper or nearer.",
        )
        self.widget = widgets.VBox([title, self.q, self.ratio, *info_widgets,
                                    self.display.widget])  # fmt: skip
        self._ahead = None
        if self.backend != "ipympl":
            # full pictures: a draft here looks as the final picture does, so a release
            # on a position drawn ahead needs no picture from the kernel (issue 31: the
            # last picture came up to 105 ms after the release)
            self._ahead = self.display.ahead(self.q, self, full=True)

    def _plot(self) -> None:
        ax, curve = self.axes
        for each in (ax, curve, self._key_ax):
            each.clear()
        # fitted to the current ratio (frame_of the segment alone) at one scale in x and z
        self.artists = plot_projection(ax, self.segment, n_steps=self.n_steps, q=self._q,
                                       curve_ax=curve, frame=frame_of([self.segment]))  # fmt: skip
        self.t = self.artists.update(self._q)
        # the picture's key in an Axes of its own above the curve: beside the picture it took
        # the picture's own width, inside it lay over the rays at some q. The curve's short
        # key stays in its upper left, above the line t = q, where t(q) never goes (z1 >= z0).
        key = ax.get_legend()
        self._key_ax.add_artist(Legend(
            self._key_ax, key.legend_handles, [t.get_text() for t in key.get_texts()],
            loc="center", fontsize=key.get_texts()[0].get_fontsize(), borderaxespad=0.0))  # fmt: skip
        key.remove()
        self._key_ax.axis("off")
        a = self.artists
        # a new q moves these only: the rest (the rays of equal steps, the segment, the
        # axes, the keys beside them) stays in a cached background
        self._blit = LayeredBlit(self.fig, [
            (MOVING, [a.ray, a.screen_point, a.world_point, a.affine_point, a.label,
                      a.curve_point])])  # fmt: skip
        self.peak_q, self.largest_gap = self.segment.peak()

    def _lay_out(self) -> None:
        """Lay the figure out (constrained), then keep that layout: a new q moves artists
        only, so its picture is a plain draw, and the pictures drawn ahead line up."""
        self.fig.set_layout_engine("constrained")
        self.fig.canvas.draw()
        self.fig.set_layout_engine("none")
        # the line above the picture (the axes' title) pinned where this draw put it:
        # hidden while the blit draws its background, matplotlib would move it out of sight
        label = self.artists.label
        self.axes[0].set_title(label.get_text(), loc="left", y=label.get_position()[1],
                               fontsize=label.get_fontsize())  # fmt: skip

    def _draw_figure(self) -> None:
        self._blit.draw()

    def _info_html(self) -> str:
        r = self.segment.z1 / self.segment.z0
        where = f"at q = {self.peak_q:.3f}" if self.largest_gap > 1e-12 else "t = q everywhere"
        # both ends on the screen line z = 1: the segment and its image are one line, which
        # read as a missing segment (review r272 FIG4); the pale band under it is the screen
        on_screen = all(abs(z - 1.0) < 1e-12 for z in (self.segment.z0, self.segment.z1))
        note = (" · both ends at depth 1: the segment lies <i>on</i> the screen and is its own "
                "image (the pale band under it)") if on_screen else ""  # fmt: skip
        return (f"depth ratio z1 / z0 = {r:.2f} · largest |t − q| over the screen: "
                f"<b>{self.largest_gap:.3f}</b>, {where}{note}")  # fmt: skip

    def set_ratio(self, ratio: float) -> None:
        """Move the far end along its eye ray to depth ``ratio`` · z0, and redraw."""
        # the readout first says a picture is coming: a new ratio redraws the whole figure,
        # seconds on a loaded machine, and a stale "4.00" under a 7.50 slider read as a wrong
        # answer (review r77, 04)
        self.info.value = f"depth ratio z1 / z0 = {float(ratio):.2f} · <i>drawing…</i>"
        self.segment = self.segment.with_ratio(ratio)  # the same image on the screen
        with style_context(self.style):
            self._plot()
            self._lay_out()
        self.info.value = self._info_html()
        self.display.refresh()
        if self._ahead is not None:  # the pictures drawn ahead show the old segment
            self._ahead.restart()

    def update(self) -> None:
        """Move the ray to the slider's q and redraw (its artists only)."""
        self._compute_at(self.q.value)
        self._set_artists()
        self.display.refresh()

    # what the pictures drawn ahead need (teachraster.widgets.ahead.FramesAhead)
    def _compute_at(self, q: float) -> None:
        self._q = float(q)

    def _set_artists(self) -> None:
        self.t = self.artists.update(self._q)
