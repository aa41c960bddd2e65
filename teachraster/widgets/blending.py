"""``BlendingExplorer``: reorder transparent triangles, pick the blend state, toggle sRGB.

Lesson 12b's blending widget. A few transparent triangles are drawn with ``render(...,
blend=...)``; the list on the left is the submission order (select one, move it earlier or
later, or sort back to front). Above it the blend state: the mode ("over", "premultiplied",
"additive", "multiply", each with its factor pair in the status line) and one alpha for every
triangle (review r263 M3: additive and multiply differ in any order only by rounding,
whose size the status line gives: review r324 C1); the status line
says what the mode does to the colour and to the stored alpha (one factor pair serves both).
Picking "additive" unticks "clear to opaque white", on which every sum shows white, and
leaving it ticks the box again (review r275 W1). The left panel shows the colour buffer in the chosen order,
the right one the same triangles sorted back to front, with how many pixels differ. Both show
the RGB written, opaque, as a window displays it (review r31: the stored alpha drawn over a
checkerboard greyed every colour); the "stored alpha" checkbox draws them over a checkerboard
by their stored alpha instead. "clear to opaque white" clears the buffer to (1, 1, 1, 1)
instead of transparent black (0, 0, 0, 0): the background of the lesson's figures, where
straight and premultiplied colours display alike ("premultiplied": ``blend="premultiplied"``,
colours multiplied by alpha first: the same RGB on this buffer, a different stored alpha).
The other checkboxes switch to an 8-bit sRGB framebuffer (``color_format="srgb8"``, as
GL's: the triangles' colours taken as linear light, blended in linear light, encoded and
rounded to 8 bits after every layer) rather than blending the numbers directly. A separate
box, "colours sRGB-encoded (decode)", takes the triangles' colours as sRGB codes and decodes
them to linear first, as sampling an sRGB texture does; one name, one meaning (review r117
12b-2: the framebuffer box used to decode the colours too, which GL's framebuffer does not).
"""

from __future__ import annotations

from dataclasses import dataclass

import ipywidgets as widgets
import numpy as np

from ..core.blend_factors import BLEND_MODES, srgb_to_linear
from ..core.validate import check_choice
from ..pipeline.blending.colour_blending import srgb8_codes
from ..pipeline.render_triangles import render
from ..plotting.lines import plot_rgba, rgba_shown
from .common import Shown, control_row, labelled, style_context, title_html
from .display import FigureDisplay, new_figure, resolve_backend

#: The explorer's blend states: ``render``'s modes, each with its factor pair (FUNC_ADD).
BLEND_CHOICES = {mode: BLEND_MODES[mode] for mode in ("over", "premultiplied", "additive",
                                                      "multiply")}  # fmt: skip


def default_scene():
    """Three overlapping transparent triangles at different depths (clip (3, 3, 4), RGBA
    (3, 3, 4) straight alpha), the red one in front."""
    clip = np.array([
        [[-0.9, -0.7, 0.2, 1], [0.5, -0.8, 0.2, 1], [-0.3, 0.8, 0.2, 1]],
        [[-0.5, 0.9, -0.4, 1], [-0.4, -0.6, -0.4, 1], [0.9, 0.3, -0.4, 1]],
        [[0.0, -0.9, 0.6, 1], [0.9, 0.9, 0.6, 1], [-0.9, 0.2, 0.6, 1]],
    ])  # fmt: skip
    rgba = np.array([[0.0, 0.45, 0.7, 0.6], [0.85, 0.2, 0.1, 0.6], [0.95, 0.8, 0.1, 0.6]])
    return clip, np.repeat(rgba[:, None, :], 3, axis=1)


def compose(
    clip,
    rgba,
    order,
    *,
    premultiplied=False,
    srgb=False,
    decode=False,
    size=(48, 48),
    clear_color=(0.0, 0.0, 0.0, 0.0),
    mode=None,
    alpha=None,
):
    """The (H, W, 4) colour buffer of triangles ``order`` blended in that order.

    ``rgba`` holds straight-alpha colours. ``srgb``: an 8-bit sRGB framebuffer
    (``color_format="srgb8"``, GL's ``SRGB8_ALPHA8`` with ``GL_FRAMEBUFFER_SRGB``): the colours
    are taken as linear light, as GL takes a fragment shader's output, blended in linear light
    with the decoded buffer, encoded and rounded to 8 bits after every layer; the result is
    returned as linear values (``frame.color``; :func:`rgba_shown` encodes them). Else the
    numbers are blended as they are. ``decode``: the colours are sRGB codes (as an sRGB
    texture's texels are) and are decoded to linear light before anything else; without
    ``srgb`` the buffer then stores those linear numbers unencoded.
    ``premultiplied``: multiply colour by alpha first and blend with (ONE, ONE_MINUS_SRC_ALPHA);
    the result is the buffer as stored, premultiplied.
    ``mode``: one of :data:`BLEND_CHOICES` (``render``'s ``blend``), instead of
    ``premultiplied``: "premultiplied" multiplies the colours by alpha first as above;
    "additive" (ONE, ONE) and "multiply" (DST_COLOR, ZERO) take the colours as they are.
    ``alpha``: every triangle's alpha replaced by this one (None: the colours' own).
    ``clear_color``: the buffer's RGBA before the first triangle (linear values; black and
    white are the same in either encoding), as ``render``'s.
    """
    colours = np.array(rgba, dtype=np.float64)[list(order)]
    if alpha is not None:
        colours[..., 3] = alpha
    if decode:
        colours[..., :3] = srgb_to_linear(colours[..., :3])
    if mode is None:
        mode = "premultiplied" if premultiplied else "over"
    check_choice("mode", mode, tuple(BLEND_CHOICES))
    if mode == "premultiplied":
        colours[..., :3] *= colours[..., 3:]
    return render(np.asarray(clip)[list(order)], *size, attrs=colours, blend=mode,
                  depth_write=False, clear_color=clear_color,
                  color_format="srgb8" if srgb else "float64").color  # fmt: skip


#: Float rounding, not order: each layer rounds its sum or product once (to within half a unit
#: in the last place), so a few layers in two orders part by a few units; "over" parts by
#: some 1e15 units.
ROUNDING_ULPS = 16


@dataclass(frozen=True)
class OrderGap:
    """How far apart two colour buffers of the same triangles, drawn in two orders, are.

    ``differ``: the pixels where any channel differs at all (float64: in any bit; an "srgb8"
    target: in any stored code); ``largest``: the largest difference of one channel, in the
    values stored; ``ulps``: that in units in the last place of float64 there; ``codes``:
    the largest difference in stored 8-bit codes ("srgb8"; None for float64).
    """

    differ: int
    largest: float
    ulps: int
    codes: int | None

    @property
    def rounding(self) -> bool:
        """Only rounding parts the two: float64's last bits, or one 8-bit code."""
        return self.codes <= 1 if self.codes is not None else self.ulps <= ROUNDING_ULPS

    def words(self) -> str:
        """How far, for a status line: "" where nothing differs."""
        if not self.differ:
            return ""
        if self.codes is not None:
            return f", by up to {self.codes} code(s)" + (
                ": rounding to 8 bits" if self.rounding else ""
            )
        if self.rounding:
            return (f", by at most {self.ulps} unit(s) in the last place ({self.largest:.1e}): "
                    "float rounding")  # fmt: skip
        return f", by up to {self.largest:.3f}"


def order_gap(a, b, srgb: bool = False) -> OrderGap:
    """:class:`OrderGap` of colour buffers ``a`` and ``b`` (H, W, 4): every difference
    counts, as lesson 12b §2 counts them (review r324 C1: the explorer ignored those below
    1e-9, and so reported 0 where §2 found multiply's last bits apart). ``srgb``: the
    buffers are an "srgb8" target's (linear values of stored codes), compared code by code.

    >>> a = np.full((1, 1, 4), 0.1)
    >>> order_gap(a, np.nextafter(a, 1)).words()  # the next float64 up
    ', by at most 1 unit(s) in the last place (1.4e-17): float rounding'
    """
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    diff = np.abs(a - b)
    ulps = diff / np.spacing(np.maximum(np.abs(a), np.abs(b)))
    codes = int(np.abs(srgb8_codes(a) - srgb8_codes(b)).max()) if srgb else None
    return OrderGap(int((diff > 0).any(axis=2).sum()), float(diff.max()),
                    int(np.ceil(ulps.max())), codes)  # fmt: skip


class BlendingExplorer(Shown):
    """Submission order, blend state (mode and alpha), premultiplied alpha and sRGB, with the
    colour buffer beside the sorted back-to-front one.

    Parameters
    ----------
    clip, rgba : (N, 3, 4), optional
        Triangles and their straight-alpha colours; default :func:`default_scene`.
    size : (width, height)
    white : bool
        Open with "clear to opaque white" ticked (default: transparent black).
    backend, style : as the other widgets.

    Attributes
    ----------
    order : list of int
        The current submission order; ``select``, ``earlier``, ``later``, ``sort`` change it.
    mode : ToggleButtons
        The blend state, one of :data:`BLEND_CHOICES`: "over" (SRC_ALPHA,
        ONE_MINUS_SRC_ALPHA), "premultiplied" (the colours multiplied by alpha; ONE,
        ONE_MINUS_SRC_ALPHA), "additive" (ONE, ONE), "multiply" (DST_COLOR, ZERO).
    opacity : FloatSlider
        Every triangle's alpha (the scene's own to start with).
    srgb, decode, alpha, white : Checkbox
        ``srgb``: an 8-bit sRGB framebuffer, ``color_format="srgb8"`` (colours linear).
        ``decode``: the colours are sRGB codes, decoded to linear first (an sRGB texture's).
        ``alpha``: draw the stored alpha over a checkerboard instead of the RGB as displayed.
        ``white``: clear to opaque white (1, 1, 1, 1) instead of transparent black.
    depth_order : list of int
        The triangles back to front (farthest first), the order the right panel draws.
    color, sorted_color : (H, W, 4) what the two panels show.
    gap : OrderGap
        How far the two panels lie apart: ``differ`` pixels differ at all (in any bit, or
        in any stored code of the sRGB framebuffer), by how much, and whether only by
        rounding (``gap.rounding``).
    differ : int
        ``gap.differ``.

    Examples
    --------
    >>> ex = BlendingExplorer(backend="image")
    >>> ex.sort.click(); ex.differ
    0
    >>> ex.select.value = 0; ex.later.click(); ex.differ > 0
    True
    >>> ex.white.value = True; ex.color[0, 0].tolist()  # a corner no triangle covers
    [1.0, 1.0, 1.0, 1.0]
    >>> ex.mode.value = "multiply"; ex.gap.rounding  # multiply commutes, up to rounding
    True
    >>> ex.close()
    """

    def __init__(self, clip=None, rgba=None, *, size=(48, 48), white=False, backend="auto",
                 style=None):  # fmt: skip
        if clip is None:
            clip, rgba = default_scene()
        self.clip, self.rgba, self.size = np.asarray(clip, float), np.asarray(rgba, float), size
        self.order = list(range(len(self.clip)))
        self.backend = resolve_backend(backend)
        # Each control as wide as its text and never shrunk by its row (flex "0 0 auto"): in
        # a fixed-width row the buttons' column shrank and cut "sort back to front" to "sort
        # back to fron" at 1024 x 768 (review r7); the row wraps instead (control_row).
        whole = dict(width="auto", flex="0 0 auto")
        self.select = widgets.Select(options=self._options(), value=0, rows=len(self.order),
                                     layout=widgets.Layout(width="220px", max_width="100%"))  # fmt: skip
        self.earlier = widgets.Button(description="earlier ↑", layout=widgets.Layout(**whole))
        self.later = widgets.Button(description="later ↓", layout=widgets.Layout(**whole))
        self.sort = widgets.Button(description="sort back to front",
                                   layout=widgets.Layout(**whole))  # fmt: skip
        # the blend state: the mode (its factor pair in the status line) and one alpha for
        # every triangle (review r263 M3: additive and multiply seen not to depend on order)
        self.mode = widgets.ToggleButtons(options=list(BLEND_CHOICES), value="over",
                                          layout=widgets.Layout(width="auto"),
                                          style={"button_width": "auto"})  # fmt: skip
        alphas = np.unique(self.rgba[..., 3])
        self.opacity = widgets.FloatSlider(
            value=float(alphas[0]) if len(alphas) == 1 else 0.6, min=0.05, max=1.0, step=0.05,
            description="alpha", readout_format=".2f", continuous_update=False,
            layout=widgets.Layout(width="300px", max_width="100%"))  # fmt: skip
        self.srgb = widgets.Checkbox(value=False, description="sRGB framebuffer", indent=False,
                                     layout=widgets.Layout(**whole))  # fmt: skip
        self.decode = widgets.Checkbox(value=False, description="colours sRGB-encoded (decode)",
                                       indent=False, layout=widgets.Layout(**whole))  # fmt: skip
        self.alpha = widgets.Checkbox(value=False, description="stored alpha (checkerboard)",
                                      indent=False, layout=widgets.Layout(**whole))  # fmt: skip
        # lesson 12b opens it on white, the clear colour of its figures (review r63 12b-3)
        self.white = widgets.Checkbox(value=bool(white), description="clear to opaque white",
                                      indent=False, layout=widgets.Layout(**whole))  # fmt: skip
        # the white clear the explorer set aside for "additive" (review r275 W1), to restore
        self._white_set_aside = False
        self._compute()
        with style_context(style):
            self.fig = new_figure((9.0, 5.0), self.backend)
            # Fixed margins: the constrained layout let the titles above the top column labels
            # run off the picture once the square panels were fitted to the width.
            axes = self.fig.subplots(1, 2, gridspec_kw=dict(left=0.08, right=0.99, top=0.8,
                                                            bottom=0.02, wspace=0.22))  # fmt: skip
            self.artists = plot_rgba(axes[0], self.color, **self._shown())
            self.sorted_artists = plot_rgba(axes[1], self.sorted_color, **self._shown())
            axes[0].set_title("submission order")
            axes[1].set_title("sorted back to front")
            self.display = FigureDisplay(self.fig, self.backend)
        self.info = widgets.HTML(self._info())
        self.earlier.on_click(lambda _: self._move(-1))
        self.later.on_click(lambda _: self._move(+1))
        self.sort.on_click(lambda _: self._sort())
        # at the top of the list "earlier" cannot move, at the bottom "later" (review r437 S7)
        self.select.observe(lambda change: self._ends(), "value")
        self._ends()
        self.mode.observe(self._mode_changed, "value")
        self.white.observe(self._white_changed, "value")
        for box in (self.opacity, self.srgb, self.decode, self.alpha):
            box.observe(lambda change: self.update(), "value")
        # Short (review r324 S5: seven lines above the controls repeated the lesson's cell):
        # what each control does, and the one claim the count checks; the lesson has the rest.
        title = title_html(
            "Blending: order, blend state, premultiplied alpha, sRGB",
            "The list is the order drawn, first at the top: move a triangle earlier or later. "
            "'over' depends on the order; additive and multiply commute, so they differ only "
            "by rounding (the line under the controls counts every difference and says how "
            "far). 'clear to opaque white' unticked: cleared to transparent black (0, 0, 0, "
            "0). 'stored alpha' draws alpha over a checkerboard. 'sRGB framebuffer' is "
            "color_format=\"srgb8\" (colours taken as linear light); 'colours sRGB-encoded' "
            "decodes them first.",
        )
        column = dict(flex="0 0 auto", margin="0 12px 0 0")
        buttons = widgets.VBox([self.earlier, self.later, self.sort],
                               layout=widgets.Layout(align_items="stretch", **column))  # fmt: skip
        boxes = widgets.VBox(
            [self.srgb, self.decode, self.alpha, self.white],
            layout=widgets.Layout(**column),
        )
        controls = control_row([self.select, buttons, boxes])
        state = control_row([labelled("blend", self.mode), self.opacity])
        self.widget = widgets.VBox([title, state, controls, self.info, self.display.widget])

    def _options(self):
        # the triangles in the order drawn, by their index (the status line's) and colour; no
        # position number: "1. triangle 0" put two counts on one line (review r102 12b-5)
        names = ("blue", "red", "yellow", "green", "purple")
        return [(f"triangle {t} ({names[t % len(names)]})", k)
                for k, t in enumerate(self.order)]  # fmt: skip

    @property
    def depth_order(self) -> list[int]:
        """The triangles back to front, the order the right panel draws: the largest mean
        window depth z/w (farthest) first, ties kept in index order. One depth per triangle
        is all a sort of whole triangles has (lesson 12b §3: it fails where they cross)."""
        z = self.clip[:, :, 2].mean(axis=1) / self.clip[:, :, 3].mean(axis=1)
        return [int(k) for k in np.argsort(-z, kind="stable")]

    def _shown(self) -> dict:
        """How :func:`rgba_shown` draws the buffers under the current checkboxes."""
        return {"premultiplied": self.mode.value == "premultiplied", "srgb": self.srgb.value,
                "view": "alpha" if self.alpha.value else "displayed"}  # fmt: skip

    def _compute(self) -> None:
        clear = (1.0, 1.0, 1.0, 1.0) if self.white.value else (0.0, 0.0, 0.0, 0.0)
        opts = {"mode": self.mode.value, "alpha": self.opacity.value, "srgb": self.srgb.value,
                "decode": self.decode.value, "size": self.size, "clear_color": clear}  # fmt: skip
        self.color = compose(self.clip, self.rgba, self.order, **opts)
        self.sorted_color = compose(self.clip, self.rgba, self.depth_order, **opts)
        self.gap = order_gap(self.color, self.sorted_color, srgb=self.srgb.value)
        self.differ = self.gap.differ

    def _move(self, delta: int) -> None:
        k = self.select.value
        j = k + delta
        if 0 <= j < len(self.order):
            self.order[k], self.order[j] = self.order[j], self.order[k]
            self.select.options = self._options()
            self.select.value = j
        self.update()

    def _ends(self) -> None:
        self.earlier.disabled = self.select.value == 0
        self.later.disabled = self.select.value == len(self.order) - 1

    def _sort(self) -> None:
        self.order = list(self.depth_order)
        self.select.options = self._options()
        self.select.value = 0
        self.update()

    def update(self) -> None:
        """Recompute both buffers and update the two images in place."""
        self._compute()
        for artists, color in (
            (self.artists, self.color),
            (self.sorted_artists, self.sorted_color),
        ):
            artists.image.set_data(rgba_shown(color, **self._shown()))
            artists.checker.set_visible(self.alpha.value)
        self.info.value = self._info()
        self.display.refresh()

    def _info(self) -> str:
        order = " → ".join(str(t) for t in self.order)
        # name both orders: a lesson may compare other orders of the same triangles (r8)
        back = " → ".join(str(t) for t in self.depth_order)
        src, dst = BLEND_CHOICES[self.mode.value]
        return (f"drawn {order}: <b>{self.differ}</b> pixel(s) differ from back to front "
                f"({back}){self.gap.words()}; blend {self.mode.value!r} = ({src}, {dst}), alpha "
                f"{self.opacity.value:.2f}{self._mode_note()}"
                f"{' (sRGB framebuffer)' if self.srgb.value else ''}"
                f"{' (colours decoded from sRGB)' if self.decode.value else ''}"
                # name the clear either way: unticked it is black (review r71)
                f"; cleared to {'opaque white' if self.white.value else 'transparent black'}"
                f"{self._alpha_note()}")  # fmt: skip

    def _mode_changed(self, change) -> None:
        """Picking "additive" on the white clear unticks it, and leaving "additive" ticks it
        again: onto white every sum exceeds 1 and both panels showed plain white until the
        student acted on the status line (review r275 W1). The status line says so."""
        aside = change["new"] == "additive" and self.white.value
        restore = change["old"] == "additive" and self._white_set_aside
        if aside or restore:
            self.white.value = not self.white.value  # _white_changed updates the panels
        self._white_set_aside = aside
        self.update()

    def _white_changed(self, change) -> None:
        self._white_set_aside = False  # the student's own choice (or the restore) from now on
        self.update()

    #: What each mode does to the colour and to the stored alpha: one factor pair serves both
    #: (§1), so additive and multiply, whose colour ignores alpha, still blend the alphas
    #: (review r275 C1: the line said "alpha unused", yet "stored alpha" changed with it).
    MODE_NOTES = {
        "over": "colour src·a_s + dst·(1 − a_s); stored alpha a_s·a_s + a_d·(1 − a_s)",
        "premultiplied": "colour src·a_s + dst·(1 − a_s), the same RGB as 'over'; stored alpha "
        "a_s + a_d·(1 − a_s): tick 'stored alpha' to see the difference",
        "additive": "alpha does not enter the colour, src + dst; the stored alpha is the sum "
        "of the alphas, a_s + a_d",
        "multiply": "alpha does not enter the colour, src·dst; the stored alpha is the product "
        "of the alphas, a_s·a_d",
    }

    def _mode_note(self) -> str:
        """The status line's word on the mode: what it does to colour and stored alpha, and
        where the clear hides it (additive onto white: every sum exceeds 1 and shows white;
        multiply onto black: every product is 0 and shows black)."""
        note = f" ({self.MODE_NOTES[self.mode.value]})"
        if self.mode.value == "additive" and self._white_set_aside:
            note += ("; <b>'clear to opaque white' unticked for additive</b>: onto white every "
                     "sum exceeds 1 and shows white (ticked again when you leave additive)")  # fmt: skip
        elif self.mode.value == "additive" and self.white.value:
            note += ("; <b>onto white every sum exceeds 1 and shows white</b>: untick 'clear "
                     "to opaque white'")  # fmt: skip
        elif self.mode.value == "multiply" and not self.white.value:
            note += ("; <b>onto black every product is 0 and shows black</b>: tick 'clear to "
                     "opaque white'")  # fmt: skip
        return note

    def _alpha_note(self) -> str:
        """The status line's word on the stored-alpha view: where the buffer is opaque
        everywhere (premultiplied alpha on the white clear) the checkerboard cannot show, and
        the line says why, so the box does not seem to do nothing (review r187)."""
        if not self.alpha.value:
            return ""
        alpha = np.clip(np.minimum(self.color[..., 3], self.sorted_color[..., 3]), 0, 1)
        opaque = bool(np.all(alpha >= 1 - 1e-9))
        return "; stored alpha over a checkerboard" + (
            " (1 everywhere: nothing shows through)" if opaque else ""
        )
