"""``DepthPrecisionExplorer``: how bits, the near plane and reverse-Z set the depth resolution.

Lesson 05b's widget. The figure plots the smallest change in view depth the depth buffer
still sees, :func:`teachraster.pipeline.depth.depth_resolution`, against the distance, for the
chosen format, near plane and mapping (window depth or reverse-Z), with two surfaces a gap
``delta`` apart as a horizontal line: where the curve rises above the line they can store the
same depth and z-fight (:func:`teachraster.pipeline.depth.fights`). Past that crossing a pair
fights with probability ``1 - delta / resolution`` (the pair shares a step unless a step boundary
falls between them); a dotted line marks where that reaches one half, ``resolution = 2 delta``.
A faint reference curve keeps the starting configuration on screen for comparison, or the
one on show when "keep as reference" is pressed.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from ..pipeline.visibility.depth import depth_resolution, fights
from ..plotting import COLORS
from ..plotting.blitting import MOVING, STILL, LayeredBlit
from .common import Shown, close_tree, labelled, style_context, title_html
from .display import new_figure, resolve_backend
from .dragging import same_or_new
from .live_slider import LiveSlider, info_line, slider_display

#: The picture's alternative text in the page
ALT = "the smallest visible depth difference against view depth"

#: Formats offered (float64 never fights at these distances, so it adds nothing to explore).
FORMATS = ("unorm16", "unorm24", "float32")
#: Mappings offered: OpenGL's window depth (near -> 0) and reverse-Z (near -> 1).
MAPPINGS = ("perspective", "reversed")
#: The dotted line's key entry, and what it says when there is no such line (the pair fights
#: at less than half its pixels up to the far plane)
HALF_LABEL = "fights half the time (Δz = 2δ)"
HALF_NOWHERE = "fights half the time: nowhere here"
# the key in two columns under the axes, where no curve or line can run (review r67 05b-4)
#: At the figure's lower left corner, below the z label (the layout keeps its height free:
#: anchored to the axes it covered the label, review r79 05b-12), anchored at its left edge:
#: the "now" entry (first column, under the reference) then keeps its place when the other
#: column's text changes ("nowhere here"), where the "now" label drawn alone (_now_text) was
#: put once (centred, the legend moved under it: a moved explorer drew its label elsewhere
#: than a fresh one). From the figure's edge, not the axes', the widest key (float32,
#: reverse-Z, "nowhere here") fits the figure's width.
LEGEND_PLACE = {"loc": "lower left", "bbox_to_anchor": (0.0, 0.0), "ncols": 2,
                "borderaxespad": 0.3, "columnspacing": 1.0, "handlelength": 1.6}  # fmt: skip


def distance(z: float) -> str:
    """A view depth for the info line: three figures, whole numbers from 100 on (no "1e+03").

    >>> distance(6.0912), distance(120.4), distance(1000.0)
    ('6.09', '120', '1,000')
    """
    return f"{z:,.0f}" if z >= 100 else f"{z:.3g}"


def first_fight(z, delta: float, near: float, far: float, fmt: str, mapping: str):
    """The nearest distance in ``z`` (sorted) where surfaces ``delta`` apart store one depth.

    Returns ``None`` when no distance of ``z`` fights.

    Examples
    --------
    >>> z = np.geomspace(1, 1000, 200)
    >>> round(first_fight(z, 0.01, 0.1, 1000.0, "unorm16", "perspective"), 1)
    9.9
    >>> first_fight(z, 0.01, 0.1, 1000.0, "float32", "reversed") is None
    True
    """
    z = np.asarray(z, dtype=np.float64)
    hit = fights(z, z + delta, near, far, fmt, mapping=mapping)
    return float(z[np.argmax(hit)]) if hit.any() else None


def where_reaches(z, resolution, level: float):
    """The view depth at which ``resolution`` (increasing along sorted ``z``) first reaches
    ``level``, interpolated on log scales; ``None`` if it stays below ``level`` throughout.

    With ``level = 2 delta`` this is where two surfaces ``delta`` apart fight with probability
    one half: a pair shares a step with probability ``1 - delta / resolution``.

    Examples
    --------
    >>> z = np.geomspace(1.0, 100.0, 50)
    >>> round(where_reaches(z, 1e-4 * z**2, 0.01), 3)
    10.0
    >>> where_reaches(z, 1e-4 * z**2, 10.0) is None
    True
    """
    z, resolution = np.asarray(z, dtype=np.float64), np.asarray(resolution, dtype=np.float64)
    above = resolution >= level
    if not above.any():
        return None
    i = int(np.argmax(above))
    if i == 0:
        return float(z[0])
    pair = slice(i - 1, i + 1)  # the curve reaches the level between these two depths
    return float(np.exp(np.interp(np.log(level), np.log(resolution[pair]), np.log(z[pair]))))


class DepthPrecisionExplorer:
    """Depth resolution against distance: pick the format, the near plane, reverse-Z.

    Parameters
    ----------
    fmt : {"unorm16", "unorm24", "float32"}
    near, far : float
        Clip planes (the near slider runs from 0.01 to 10, log scale).
    reverse : bool
        Start with reverse-Z.
    delta : float
        Gap between the two surfaces whose fighting is predicted.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    widget : ipywidgets.VBox
    format : ToggleButtons
    near : LiveSlider
    reverse : Checkbox
    keep : Button
        Makes the curve on show the grey reference (:meth:`keep_reference`).
    z : ndarray
        Distances plotted, from ``near`` to ``far``.
    resolution : ndarray
        Resolution at ``z`` for the current settings (what the curve shows).
    fight_from : float or None
        Nearest plotted distance where the two surfaces z-fight.
    half_from : float or None
        Distance where the resolution reaches ``2 delta``: beyond it two surfaces ``delta``
        apart fight at more than half of their pixels (the dotted line).

    Examples
    --------
    >>> ex = DepthPrecisionExplorer("float32", backend="image")
    >>> ex.fight_from is not None
    True
    >>> ex.reverse.value = True
    >>> ex.fight_from is None
    True
    >>> ex.close()
    """

    def __init__(self, fmt: str = "unorm24", near: float = 0.1, far: float = 1000.0, *,
                 reverse: bool = False, delta: float = 0.005, backend: str = "auto",
                 style: str | None = None) -> None:  # fmt: skip
        self.far, self.delta = float(far), float(delta)
        self.backend = resolve_backend(backend)
        self.format = widgets.ToggleButtons(options=FORMATS, value=fmt)
        # in the page, coalesced: the kernel renders the latest value, never a queue
        self.near = LiveSlider(value=near, base=10, min=-2, max=1, step=0.05,
                               description="near", readout_format=".3g")  # fmt: skip
        self.reverse = widgets.Checkbox(value=reverse, description="reverse-Z")
        self._compute()
        self._start_near = self.z_near  # where the grey curve of the start begins
        with style_context(style):
            self.fig = new_figure((9.0, 5.5), self.backend)
            self.fig.set_layout_engine("constrained")
            ax = self.fig.add_subplot()
            # wide and light under the "now" curve: at the start a grey halo round it, so the
            # key's "start" entry names something on show (review r99 05b-2)
            (self.reference,) = ax.loglog(self.z, self.resolution, color="#C8C8C8", lw=8,
                                          label=f"start: {self._label()}",
                                          solid_capstyle="butt")  # fmt: skip
            # the axis starts at the slider's lowest near plane (0.01): what lies left of the
            # near plane on show is said to be so, not an unexplained blank band (r99 05b-2)
            self.band = ax.axvspan(0.01, self.z_near, color=(0.0, 0.0, 0.0, 0.06), lw=0, zorder=0)
            self.band_text = ax.text(0.0, 0.97, "nearer than the near plane", rotation=90,
                                     ha="center", va="top", color="0.3", fontsize="small",
                                     transform=ax.get_xaxis_transform(),
                                     bbox=dict(boxstyle="round,pad=0.2", fc="white",
                                               ec="none", alpha=0.75))  # fmt: skip
            (self.curve,) = ax.loglog(self.z, self.resolution, color=COLORS["edge"], lw=3,
                                      label="now")  # fmt: skip
            ax.axhline(self.delta, color=COLORS["outside"], ls="--", lw=2,
                       label=f"gap δ = {self.delta:g}")  # fmt: skip
            # where a pair δ apart fights with probability ½ (Δz = 2δ), not where one sampled
            # pair happens to fight (review r54 05b-2); last in the legend, so the "now" entry
            # stays the second (_now_text)
            self.marker = ax.axvline(np.nan, color=COLORS["outside"], lw=2, ls=":",
                                     label=HALF_LABEL)  # fmt: skip
            ax.set(xlabel="view depth z", ylabel="smallest visible Δz", ylim=(1e-12, 1e3),
                   xlim=(0.01, self.far))  # fmt: skip
            ax.grid(True, which="major", alpha=0.3)
            # below the axes, not over them: inside, the widest "now" entry (unorm16,
            # reverse-Z) hid the dotted line and the curve it marks (review r67 05b-4)
            self.ax = ax
            self._legend()
            self.now = None  # the "now" entry's text, drawn alone (see _now_text)
            self._draw()
            self._keep_room_for_legend()
            self.fig.canvas.draw()  # the constrained layout, once: the blit keeps it
            self.fig.set_layout_engine("none")
            self.now = self._now_text()
            self._draw()
            self._blit = self._edit_blit()
            self.display = slider_display(
                self.fig,
                self.backend,
                draw=self._draw_figure,
                drafting=lambda: self.near.dragging,
                alt=ALT,
            )
        self.info, info_widgets = info_line(self.display)
        self.info.value = self._info_html()
        self.near.observe(lambda change: self.update(), "value")
        for control in (self.format, self.reverse):  # the pictures drawn ahead go stale
            control.observe(lambda change: self.update(restart=True), "value")
        title = title_html(
            "Depth precision: bits, near plane, reverse-Z",
            "Where the curve rises above the dashed line, two surfaces δ apart can store the "
            "same depth: z-fighting becomes possible, and likely further out. Move the near "
            "plane out, add bits, or reverse Z with float32.",
        )
        # a narrow column (1024 x 768) moves whole controls to a second line; a row that
        # shrank them instead cut the label and wrapped the format's toggles
        # review r170 05b-11: the Try-it's before and after (unorm16 at near 0.1, then 1)
        # were never on screen together: the grey reference kept only the start
        self.keep = widgets.Button(description="keep as reference",
                                   tooltip="the grey curve becomes the one on show")  # fmt: skip
        self.keep.on_click(lambda _: self.keep_reference())
        # the button on a line of its own, under the controls: in their row, at 1024 x 768 and
        # 150 % (a 315-px column) it made a fourth line, or was cut beside the check box
        controls = widgets.HBox([labelled("format", self.format), self.near, self.reverse],
                                layout=widgets.Layout(flex_flow="row wrap"))  # fmt: skip
        self.widget = widgets.VBox([title, controls, widgets.HBox([self.keep]), *info_widgets,
                                    self.display.widget])  # fmt: skip
        if self.backend != "ipympl":
            # drawn while the kernel idles; a draft here is the full picture, so a release
            # on one needs no picture from the kernel (issue 31: 106-126 ms after the release)
            self._ahead = self.display.ahead(self.near, self, full=True)

    def keep_reference(self) -> None:
        """The grey reference curve becomes the curve on show, its key entry "kept: ..."."""
        self.reference.set_data(self.z, self.resolution)
        self._start_near = self.z_near  # the band's words stay left of the grey curve
        label = f"kept: {self._label()}"
        self.reference.set_label(label)
        self.ax.get_legend().get_texts()[0].set_text(label)
        self._blit.invalidate()  # the reference and the key are cached: drawn anew
        self._draw()
        self.display.refresh()
        if getattr(self, "_ahead", None) is not None:  # pictures drawn ahead show the old one
            self._ahead.restart()

    @property
    def mapping(self) -> str:
        """``"reversed"`` with reverse-Z on, else ``"perspective"`` (window depth)."""
        return "reversed" if self.reverse.value else "perspective"

    def _label(self) -> str:
        rz = ", reverse-Z" if self.reverse.value else ""
        return f"{self.format.value}, near {self.z_near:.3g}{rz}"

    def _compute(self) -> None:
        self._compute_at(self.near.value)

    def _compute_at(self, near: float) -> None:
        near = float(near)
        self.z_near = near  # the near plane of the curve on show
        self.z = np.geomspace(near * 1.001, self.far, 400)
        fmt, mapping = self.format.value, self.mapping
        self.resolution = depth_resolution(self.z, near, self.far, fmt, mapping=mapping)
        self.fight_from = first_fight(self.z, self.delta, near, self.far, fmt, mapping)
        self.half_from = where_reaches(self.z, self.resolution, 2 * self.delta)

    def _draw(self) -> None:
        self.curve.set_data(self.z, self.resolution)
        self.curve.set_label(f"now: {self._label()}")
        self.band.set_width(self.z_near - 0.01)  # from the axis's left end to the near plane
        # in the middle of the band on the log axis, or of its part left of the start's grey
        # curve (which begins at the first near plane): the words never cross that curve
        room = min(self.z_near, self._start_near)
        self.band_text.set_x(np.sqrt(0.01 * room))
        self.band_text.set_visible(room >= 0.06)  # wide enough for the words (one line)
        x = np.nan if self.half_from is None else self.half_from
        self.marker.set_xdata([x, x])
        legend = self.ax.get_legend() or self._legend()
        # no dotted line, no key entry for one: it says so, greyed (review r59 05b-1)
        half = legend.get_texts()[-1]
        label = HALF_LABEL if self.half_from is not None else HALF_NOWHERE
        if half.get_text() != label:
            half.set_text(label)
            half.set_color("black" if self.half_from is not None else "0.55")
            legend.legend_handles[-1].set_alpha(1.0 if self.half_from is not None else 0.3)
            if getattr(self, "_blit", None) is not None:
                self._blit.invalidate()
        # The legend keeps room for the widest "now" label of this format (every near value
        # has as many digits at most), its own text transparent: a new value then draws the
        # label alone (_now_text), not the legend's boxes again (about 12 ms a value).
        entry = legend.get_texts()[1]
        if entry.get_text() != self._widest():
            entry.set_text(self._widest())  # a new format: the legend is laid out again
            if getattr(self, "_blit", None) is not None:
                self._blit.invalidate()
        if self.now is not None:
            entry.set_color((0.0, 0.0, 0.0, 0.0))
            self.now.set_text(self.curve.get_label())

    def _legend(self):
        """The key at the figure's lower left corner, outside the layout (its room is kept
        by :meth:`_keep_room_for_legend`)."""
        legend = self.ax.legend(**LEGEND_PLACE, bbox_transform=self.fig.transFigure)
        legend.set_in_layout(False)
        return legend

    def _keep_room_for_legend(self) -> None:
        """Lay the axes out above the key: its height (two rows, whatever the format) and a
        small gap are taken from the bottom of the constrained layout."""
        # the layout as a draw solves it (the second solve starts from this one), and the
        # key measured: no picture rendered for either
        self.fig.get_layout_engine().execute(self.fig)
        key = self.ax.get_legend().get_window_extent(self.fig.canvas.get_renderer())
        bottom = (key.y1 + 0.1 * self.fig.dpi) / self.fig.bbox.height
        self.fig.get_layout_engine().set(rect=(0.0, bottom, 1.0, 1.0 - bottom))

    def _widest(self) -> str:
        """The "now" label of this format with the widest near value (same-width digits)."""
        rz = ", reverse-Z" if self.reverse.value else ""
        return f"now: {self.format.value}, near 0.0000{rz}"

    def _now_text(self):
        """A text over the legend's "now" entry, where the legend put that entry's text."""
        entry = self.ax.get_legend().get_texts()[1]
        x, y = entry.get_transform().transform(entry.get_position())  # pixels, baseline
        dpi = self.fig.dpi
        return self.fig.text(x / dpi, y / dpi, self.curve.get_label(), ha="left",
                             va="baseline", color=entry.get_color(),
                             fontproperties=entry.get_fontproperties(),
                             transform=self.fig.dpi_scale_trans, zorder=6)  # fmt: skip

    def _edit_blit(self) -> LayeredBlit:
        """A new value changes the curve, the z-fighting mark and the "now" label; the axes,
        the reference curve and the gap line stay in a cached background, the legend in a
        still layer over the curve."""
        return LayeredBlit(self.fig, [(MOVING, [self.band, self.band_text, self.curve,
                                               self.marker]),
                                      (STILL, [self.ax.get_legend()]), (MOVING, [self.now])])  # fmt: skip

    def _draw_figure(self) -> None:
        self._blit = same_or_new(self._blit, self._edit_blit())
        self._blit.draw()

    def _set_artists(self) -> None:
        self._draw()

    def update(self, *, restart: bool = False) -> None:
        """Recompute from the controls and redraw the same artists (``restart``: another
        control than the near plane changed, the pictures drawn ahead are stale)."""
        self._compute()
        self._draw()
        self.info.value = self._info_html()
        self.display.refresh()
        if restart and getattr(self, "_ahead", None) is not None:
            self._ahead.restart()

    def _info_html(self) -> str:
        # only distances beyond the near plane: nothing nearer is drawn (np.interp would
        # quote the curve's first value for them)
        at = [d for d in (1.0, 10.0, 100.0) if self.z[0] <= d <= self.z[-1]]
        res = np.interp(at, self.z, self.resolution)
        cross = where_reaches(self.z, self.resolution, self.delta)
        if self.fight_from is None or cross is None:
            where = "<b>no z-fighting</b> up to the far plane"
        else:
            # possible from the crossing on, at half the pixels where Δz = 2δ (1 - δ/Δz = ½),
            # at more pixels beyond it (review r59 05b-2: "from" read as "half from there on")
            where = f"z-fighting possible from Δz = δ at <b>z ≈ {distance(cross)}</b>"
            if self.half_from is None:
                where += ", at less than half the pixels up to the far plane,"
            else:
                where += (
                    f", at half the pixels at <b>z ≈ {distance(self.half_from)}</b> (Δz = 2δ) "
                    "and at more pixels beyond it,"
                )
        text = f"{self._label()}, far {self.far:g}: {where} for surfaces δ = {self.delta:g} apart"
        if at:
            text += (f" · Δz at z = {', '.join(f'{d:g}' for d in at)}: "
                     f"{', '.join(f'{r:.2g}' for r in res)}")  # fmt: skip
        return text

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_

    def close(self) -> None:
        """Close every widget of the explorer."""
        self.display.close()
        close_tree(self.widget)
