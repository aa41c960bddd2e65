"""``FillPlayer``: play a traced fill step by step, switch method and interpolation."""

from __future__ import annotations

import os
import uuid

import ipywidgets as widgets
from matplotlib.patheffects import withStroke

from ..core.fill import rasterize
from ..core.triangle import Triangle
from ..core.validate import as_int, as_size
from ..plotting import FillView, InterpolationView, plot_samples
from ..plotting.common import fs
from ..plotting.frames import encode_png, frame_rgba, render_group, step_info, step_texts
from ..plotting.pages import page_data, player_fragment
from .common import (
    FALLBACK_CSS,
    SAMPLE_PATTERNS,
    STANDIN_PLAIN,
    Holdable,
    close_tree,
    display_with_fallback,
    fill_axes,
    labelled,
    later,
    pattern_samples,
    settle,
    standin_html,
    style_context,
    title_html,
)
from .display import (
    COMPARISON_DPI,
    FigureDisplay,
    comparison_axes,
    new_figure,
    readable_text,
    resolve_backend,
)
from .dragging import comparison_edit_blit, same_or_new
from .frames import FramesWidget

METHOD_OPTIONS = [("span tables", "span"), ("half-planes", "halfplane"), ("tiles", "tiled")]
INTERPOLATION_OPTIONS = [("affine", "affine"), ("perspective-correct", "perspective")]
#: The tile fill tests pixel centres only (``rasterize`` refuses ``method="tiled"`` with
#: several samples): with tiles chosen the player shows one sample and says so.
ONE_SAMPLE = "1 (centre)"
TILES_NOTE = "<i>tiles test pixel centres only: shown with 1 sample per pixel</i>"
#: The steps' grid (its longer side, inches) and the key's column (inches at the style's font
#: scale): the figure stays within the column (930 px at the classroom style's 96 dpi), and
#: the player with its steps stays within a 900-px screen (5.4 in made it 906 px tall).
PLAYER_SIDE, PLAYER_KEY = 4.8, 1.75

#: The comparison's greatest height on screen (px): with the title and the controls above it,
#: the open comparison fits a 900-px-high screen (the steps fold meanwhile, unless the
#: interpolation toggle opened it).
COMPARISON_MAX_PX = 660
#: Appended, as a sentence of its own, to the last step's caption when the triangle has
#: attributes: both interpolations are in the comparison. Closed, the hint says how to open
#: it and that the steps then fold (review r208 00-2: they vanished with no word why); open,
#: only where it is (r208 00-3: "click its title to open it" stood under an open one).
COMPARISON_HINT = (
    "Both ways side by side: click the comparison's title below to open it. It then takes "
    "the steps' place, to fit one screen; close it to step again."
)
COMPARISON_HINT_OPEN = "Both ways side by side: the comparison below."
#: Added to the hint when the samples menu asks for more than one sample: the comparison
#: keeps one sample per pixel (its title says so; review r241 S5: the caption pointed to it
#: as if it showed the 72 pixels of the MSAA fill, not the 59 of one sample per pixel).
COMPARISON_ONE_SAMPLE = "It shows the fill at one sample per pixel, the pixel centres."
#: The comparison's width on screen at 1024 x 768 with JupyterLab's file browser open (CSS
#: px): the output column (592) less the accordion's padding (review r20, 00 c14). Its text
#: is sized to read 12 px there.
COMPARISON_SHOWN_PX = 556
#: A classroom's notebook column (CSS px: JupyterLab at 1400 px or more, the file browser
#: closed), where the comparison is scaled down by its height (COMPARISON_MAX_PX), not its
#: width: its text is sized to read COMPARISON_CLASSROOM_PX there, as the lessons' own
#: figures do, and its panels are COMPARISON_PANEL of comparison_axes' size to make room
#: (review r225 FIG1: ticks and labels read 11-13 px beside the lesson's figures' 17; review
#: r241 FIG1: at 20 px their digits were still 14-15 px tall, at 22 they are 16).
CLASSROOM_COLUMN_PX = 920
COMPARISON_CLASSROOM_PX = 22.0
COMPARISON_PANEL = 0.8
#: Inches the comparison's colour bars are moved away from their panels: room for a vertex
#: label beside a panel's side (:func:`labels_off_frames`; "v2" lay over a colour bar, reviews
#: r225 and r241 FIG1)
BAR_SHIFT = 0.5


def tidy_comparison(view) -> None:
    """The comparison's text, once raised to its classroom size (``readable_text``), given
    the room it needs (review r241 FIG1): the first row's titles lifted above the column
    labels, which grew with them; the first panel's row ticks without row 0, where the label
    of a vertex near the top left stands ("0-v1"), as lesson 00's own error map does; the
    vertex labels haloed, not boxed, and off the panels' frames (:func:`labels_off_frames`)."""
    ax = view.axes[0]
    ticks = ax.xaxis.get_ticklabels()[0].get_fontsize() if ax.xaxis.get_ticklabels() else 0.0
    # above the title: the tick labels, the axis label, the ticks and their pads
    pad = ticks + ax.xaxis.label.get_fontsize() + 20.0
    for panel in view.axes[:2]:
        title = panel.title
        panel.set_title(title.get_text(), pad=pad, fontsize=title.get_fontsize(),
                        fontweight=title.get_fontweight())  # fmt: skip
    rows = [(y, t.get_text()) for y, t in zip(ax.get_yticks(), ax.get_yticklabels())]
    kept = [(y, text) for y, text in rows if text != "0"]
    if kept and len(kept) < len(rows):
        ax.set_yticks([y for y, _ in kept], labels=[text for _, text in kept])
    halo = [withStroke(linewidth=max(2.5, fs(0.22)), foreground="white")]
    for tri in view.triangles:
        for label in tri.labels:
            label.set_bbox(None)
            label.set_path_effects(halo)
    labels_off_frames(view)
    if view.profile is not None:  # its key grew with the text: the curves kept from under it
        view.profile.clear_key()


def labels_off_frames(view) -> None:
    """Each vertex label of the comparison wholly inside its panel or wholly beside it, never
    over its frame (review r241 FIG1: v1's box lay on the frame, and on the orange frame of
    the panel in use): a label over a side moves out past it, one over the top or the bottom
    moves in. Placed again after every update, which places the labels afresh."""
    fig = view.fig
    renderer = fig.canvas.get_renderer()
    gap, points = 3.0, 72.0 / fig.dpi  # display pixels; points per display pixel
    for tri in view.triangles:
        ax = tri.outline.axes
        ax.apply_aspect()  # the box a draw gives the equal-aspect panel, not the one it was given
        frame = ax.get_window_extent(renderer)
        for label in tri.labels:
            if not label.get_visible():
                continue
            box = label.get_window_extent(renderer)
            dx = dy = 0.0
            # within a gap of a side counts as on it: a label touching the frame reads as
            # crossing it
            if box.x0 - gap < frame.x0 < box.x1 + gap:
                dx = frame.x0 - gap - box.x1
            elif box.x0 - gap < frame.x1 < box.x1 + gap:
                dx = frame.x1 + gap - box.x0
            if box.y0 - gap < frame.y0 < box.y1 + gap:
                dy = frame.y0 + gap - box.y0
            elif box.y0 - gap < frame.y1 < box.y1 + gap:
                dy = frame.y1 - gap - box.y1
            x, y = label.get_position()  # offset points from the vertex
            label.set_position((x + dx * points, y + dy * points))


def shown_samples(method: str, samples: str) -> str:
    """The sample pattern the player fills with: the menu's, or one sample for tiles.

    >>> shown_samples("tiled", "4 standard (rotated grid)"), shown_samples("span", "2 standard")
    ('1 (centre)', '2 standard')
    """
    return ONE_SAMPLE if method == "tiled" else samples


class FillPlayer(Holdable):
    """Step through the fill of one triangle: Play/Pause, a step slider, the step in words.

    Stepping runs in the page (:mod:`teachraster.plotting.frames`): the steps of the
    :class:`~teachraster.plotting.FillView` are drawn once by matplotlib (blitted, as the view
    draws them) and sent to the page in groups, the one on show first; the step slider, the
    first / previous / next / last buttons and Play then change the picture and the caption
    with no round trip, and the kernel hears of the step when the slider is released or Play
    paused. The method, interpolation and samples controls rasterise the triangle again
    (``trace=True``) and send the new fill. When the triangle has attributes, a second figure
    (an :class:`~teachraster.plotting.InterpolationView`) shows one of them interpolated both
    ways and their difference, the interpolation in use highlighted; without attributes
    there is no interpolation toggle (it would change nothing on show).

    Everything can be driven from code: set ``player.slider.value``,
    ``player.method.value`` or ``player.interpolation.value``, or ``click()`` a button.
    Where no kernel runs (an HTML export of the lesson) the player's output falls back to
    an offline page that steps and plays by itself (:meth:`static_fallback`).

    Parameters
    ----------
    tri : Triangle
        The triangle to fill (screen space, pixels).
    width, height : int
        Image size in pixels (a 32 × 32 grid or smaller reads best).
    method : {"span", "halfplane", "tiled"}
        Span tables, half-planes or tiles (one step per classified block), as for
        :func:`teachraster.rasterize`.
    interpolation : {"perspective", "affine"}
        How attributes are interpolated.
    attribute : str, optional
        Attribute shown in the interpolation figure; default the triangle's first.
    step : int
        Step shown first (0: the start; -1: the finished fill).
    interval : int
        Milliseconds per step when playing (``interval=20``: 50 steps a second).
    backend : {"auto", "ipympl", "image"}
        How the interpolation figure is shown (see
        :func:`~teachraster.widgets.resolve_backend`); the steps are always page frames.
    style : str, optional
        Plotting style for this widget's figures (``"classroom"``); default the current one.
    samples : str
        Sample pattern, a key of :data:`~teachraster.widgets.common.SAMPLE_PATTERNS`. With
        more than one sample the steps still follow the pixel centres, every sample of a
        pixel is drawn once its step has run (filled where covered), and the captions read
        the recorded sample tests: a pixel step says how many of its samples are covered,
        a pixel with a covered sample is not greyed as rejected, and the last step counts
        the pixels with a covered sample, as ``rasterize`` does: what MSAA adds. Tiles
        test pixel centres only: with ``method="tiled"`` the fill has one sample per pixel
        whatever the menu says, and a note beside the menu says so (``samples_note``).

    Attributes
    ----------
    widget : ipywidgets.VBox
        Everything, ready to display (the player also displays itself).
    frames : FramesWidget
        The page-side player (buttons, step slider, caption, frames); ``frames.value`` is
        the step, ``frames.interval`` the ms per step. ``slider`` and ``play`` name it too.
    first, prev, next, last : StepButton
        The page's step buttons, pressed from code with ``click()``.
    method, interpolation, samples
        The two ``ToggleButtons`` and the sample-pattern ``Dropdown`` (kernel side).
    view : FillView
    fig : matplotlib Figure
        The FillView's figure.
    interp_view : InterpolationView or None
        None when the triangle has no attributes.
    comparison : ipywidgets.Accordion
        Folds the interpolation figure under the steps (only with attributes). Opened by
        its header it takes the steps' place (they fold, so that the two fit one screen);
        the interpolation toggle opens it below the steps, which stay.
    fill : Fill
        The fill on show.

    Examples
    --------
    >>> import teachraster as tr
    >>> tri = tr.Triangle([[1, 1], [14, 4], [5, 14]], w=[1, 2, 4], attrs={"u": [0, 1, 0]})
    >>> player = FillPlayer(tri, 16, 16, backend="image")
    >>> player.slider.value = 6
    >>> player.caption_text == player.trace.caption(6)
    True
    >>> player.close()
    """

    def __init__(
        self,
        tri: Triangle,
        width: int,
        height: int,
        method: str = "span",
        interpolation: str = "perspective",
        *,
        attribute: str | None = None,
        step: int = 0,
        interval: int = 400,
        backend: str = "auto",
        style: str | None = None,
        samples: str = "1 (centre)",
    ) -> None:
        if not isinstance(tri, Triangle):
            raise TypeError(f"tri must be a teachraster.Triangle, got {type(tri).__name__}")
        self.tri = tri
        self.width, self.height = as_size("width", width), as_size("height", height)
        interval = as_int("interval", interval, minimum=1)
        self.backend = resolve_backend(backend)
        self._fills: dict[tuple[str, str, str], object] = {}
        self._posters: dict = {}  # (fill key, step) -> (PNG, (h, w)) drawn ahead
        self._poster_key = None  # (fill key, step) of frames.poster
        self._standin_png = (None, b"")  # (fill key, step), PNG: the stand-in's picture
        self.samples = widgets.Dropdown(options=list(SAMPLE_PATTERNS), value=samples,
                                        layout=widgets.Layout(width="220px"))  # fmt: skip
        self.fill = self._rasterize(method, interpolation)
        step = self.trace.index(step)
        with style_context(style):
            self._make_figures(attribute, step, interpolation)
            self.sample_dots = None
            self._show_samples()
        self._make_controls(step, interval, method, interpolation)
        self.widget = self._layout()

    # -- building ---------------------------------------------------------------------------
    def _rasterize(self, method: str, interpolation: str, samples: str | None = None):
        """The traced fill for these options (each made once: toggling back costs nothing)."""
        samples = self.samples.value if samples is None else samples
        key = (method, interpolation, shown_samples(method, samples))
        if key not in self._fills:
            self._fills[key] = rasterize(self.tri, self.width, self.height, method=method,
                                         interpolation=interpolation, trace=True,
                                         samples=pattern_samples(key[2]))  # fmt: skip
        return self._fills[key]

    def _show_samples(self) -> None:
        """Every sample of the fill on top of the steps (hidden for one sample per pixel)."""
        if self.fill.sample_coverage is not None:
            if self.sample_dots is None:
                self.sample_dots = plot_samples(
                    self.view.ax, self.fill, fraction=False, partial=True, bold=True
                )
            else:
                self.sample_dots.update(self.fill)
        if self.sample_dots is not None:
            self.sample_dots.set_visible(self.fill.sample_coverage is not None)
            # still, above the pixels the steps fill (the view's plan is new after every
            # set_fill, so the dots are handed to it again each time)
            self.view.show_samples(self.sample_dots)
        self.view.blit.invalidate()

    def _make_figures(self, attribute, step: int, interpolation: str) -> None:
        # The steps are drawn by Agg and shown by the page (frames.js): the fill figure is
        # never a live canvas, whatever the backend.
        self.fig = new_figure((8, 6), "image")
        # the grid as large as the column allows and the key's column only as wide as its
        # longest line ("centre out, a sample in"): 4 samples per pixel read about 10 px
        # across (review r37, lesson 00: 7 px with a 4.4-in grid), the dots at 0.9 of their gap
        ax = fill_axes(self.fig, self.width, self.height, side=PLAYER_SIDE, key=PLAYER_KEY)
        # The caption and the step number are shown by the page beside the frame, in full
        # and selectable; drawing them in the figure as well would cost time at every step.
        # the last step colours the pixels by the attribute it interpolates (review r10, 04
        # c15: its caption spoke of u over plain coverage); the key names the sample dots
        self.view = FillView(self.fill, ax=ax, step=step, caption=False, step_header=False,
                             values=True, attribute=attribute, sample_key=True)  # fmt: skip
        self.interp_view = self.interp_display = None
        if self.tri.attrs:
            name = attribute or next(iter(self.tri.attrs))
            ifig = new_figure((10, 4), self.backend, dpi=COMPARISON_DPI)
            axes = comparison_axes(ifig, self.height, self.width, below=True, profile=True,
                                   panel=COMPARISON_PANEL)  # fmt: skip
            self.interp_view = InterpolationView(self.fill, name, axes=axes)
            self.interp_view.highlight(interpolation)
            # shown shrunk to the accordion at 1024 px: its text sized to read 12 px there
            # (reviews r9 00 c14, 04 c15: ticks, key and notes read 9-11 px; r20: 11.8);
            # in a classroom's column, scaled down to its greatest height: 20 px there
            view = self.interp_view
            bars = [im.colorbar.ax for im in (*view.images, view.heatmap) if im.colorbar]
            # the colour bars a little farther from their panels: the vertex labels, at this
            # size, reach past a panel's side ("v2" lay over a colour bar, review r225 FIG1)
            for bar in bars:
                box = bar.get_position()
                bar.set_position(box.translated(BAR_SHIFT / ifig.get_figwidth(), 0.0))
            fw, fh = ifig.get_size_inches() * ifig.dpi
            for shown, px in ((COMPARISON_SHOWN_PX, 13.0),  # r37: 12.2 px read small
                              (min(CLASSROOM_COLUMN_PX, COMPARISON_MAX_PX * fw / fh),
                               COMPARISON_CLASSROOM_PX)):  # fmt: skip
                readable_text([*view.axes, *bars], profile=view.profile,
                              texts=[view.heatmap.note, *view.in_use], shown_px=shown,
                              min_px=px)  # fmt: skip
            tidy_comparison(view)
            # a toggle changes the images, outlines and colour bars: the rest stays cached
            self._interp_blit = comparison_edit_blit(self.interp_view)
            self.interp_display = FigureDisplay(ifig, self.backend, draw=self._draw_interp)

    def _make_controls(self, step: int, interval: int, method: str, interpolation: str):
        self.frames = FramesWidget(self._group, interval=interval)
        # made once per fill (method, interpolation, samples): toggling back costs nothing
        self._groups, self._texts = {}, {}
        # Stepping runs in the page; these names keep the code that drives a player working.
        self.slider = self.play = self.frames
        self.first = StepButton(lambda: self._go(0))
        self.prev = StepButton(lambda: self._go(self.frames.value - 1))
        self.next = StepButton(lambda: self._go(self.frames.value + 1))
        self.last = StepButton(lambda: self._go(self.frames.max))
        wide = widgets.Layout(width="auto")
        self.method = widgets.ToggleButtons(options=METHOD_OPTIONS, value=method, layout=wide,
                                            tooltips=["sort, split at u4, fill row by row",
                                                      "test every pixel of the bounding box "
                                                      "against the three edges",
                                                      "classify blocks, then their pixels"])  # fmt: skip
        self.interpolation = widgets.ToggleButtons(
            options=INTERPOLATION_OPTIONS, value=interpolation, layout=wide,
            tooltips=["screen-space blend of the vertex values (GLSL noperspective)",
                      "blend f/w and 1/w, then divide (GLSL smooth)"],
        )  # fmt: skip
        for toggle in (self.method, self.interpolation):
            toggle.style.button_width = "auto"
        self._publish(step)
        self.frames.observe(self._on_step, "value")
        self.method.observe(self._on_fill_options, "value")
        self.interpolation.observe(self._on_fill_options, "value")
        self.samples.observe(self._on_fill_options, "value")
        self.samples_note = widgets.HTML()
        self._note_samples()

    def _note_samples(self) -> None:
        """Say why the picture has one sample when the menu asks for more (tiles chosen)."""
        fewer = self.samples.value != shown_samples(self.method.value, self.samples.value)
        self.samples_note.value = TILES_NOTE if fewer else ""

    def _layout(self) -> widgets.VBox:
        title = title_html(
            # a serial loop, one step at a time; a GPU tests a block's pixels at once
            # (review r93 02-2: "How a GPU fills" titled a loop with bail-out)
            "How a serial reference loop fills a triangle, step by step",
            # one line shorter than the two sentences it was (test_browser_player: the player
            # with its comparison closed must fit 860 px, it measured 877); no word on GPUs,
            # an odd header over a span-table walk (review r239 01-S7)
            "Play, drag or step (in the page); the menus ask the kernel.",
        )
        options = [labelled("method", self.method)]
        # Without attributes the interpolation changes nothing on show: no toggle for it.
        if self.tri.attrs:
            options.append(labelled("interpolation", self.interpolation))
        options += [labelled("samples", self.samples), self.samples_note]
        row = widgets.Layout(flex_flow="row wrap", align_items="center")
        return widgets.VBox([title, widgets.HBox(options, layout=row), self.frames,
                             *self._comparison_section()])  # fmt: skip

    def _comparison_section(self) -> list:
        """The interpolation figure, folded under the steps; open, it takes the steps' place
        (they fold) and is no taller than :data:`COMPARISON_MAX_PX`: the steps and the figure
        together were 1,708 px at 1400 x 900, the player now fits a 900-px-high screen."""
        if self.interp_display is None:
            return []
        figure = self.interp_display.widget
        if isinstance(figure, widgets.Image):  # an ipympl canvas keeps its own size
            # scaled down whole, the picture's shape kept (lesson 04's, classroom style: 903 px)
            figure.layout.max_height = f"{COMPARISON_MAX_PX}px"
            figure.layout.object_fit = "contain"
            figure.layout.object_position = "left top"
        self.comparison = widgets.Accordion(
            children=[figure], selected_index=None,
            # one sample per pixel whatever the samples menu says: the title says so, or its
            # 59 pixels read as the MSAA fill's 72 (review r58 00-6); one line at 1400 px (two
            # lines made the player with it open 864 px, past a 900-px screen's 860)
            titles=("affine / perspective-correct, 1 sample per pixel: both interpolations, "
                    "their error, the row of the largest error",),
        )  # fmt: skip
        self._interp_stale = False
        self._keep_steps = False  # opened by the interpolation toggle: the steps stay
        self.comparison.observe(self._refresh_comparison, "selected_index")
        self.comparison.observe(self._fold_steps, "selected_index")
        self.comparison.observe(self._rehint, "selected_index")
        return [self.comparison]

    def _fold_steps(self, change=None) -> None:
        """The steps fold while the comparison is open, and come back as it closes; opened by
        the interpolation toggle, a control of the steps, it comes below them and they stay
        (review r7: pressing "affine" took the whole step player away)."""
        opened = self.comparison.selected_index is not None
        self._keep_steps = opened and self._keep_steps
        self.frames.layout.display = "none" if opened and not self._keep_steps else ""

    def _publish(self, step: int) -> None:
        """Send the fill on show to the page: its steps' texts and the picture of ``step``.

        A fill shown before (a toggle back) has the group of ``step`` made already: it goes
        to the page at once, in place of a poster. Otherwise the poster (one full draw) is
        all the page needs to show the fill; the groups follow when the page asks for them.
        """
        fill_key = self._fill_key()
        if fill_key not in self._texts:
            self._texts[fill_key] = step_texts(self.trace)  # the hint is added on sending
        captions, infos = self._texts[fill_key]
        captions = self._hinted(captions)
        group = step // self.frames.key
        made = self._groups.get((fill_key, group))
        poster, size = b"", (self.frames.frame_height, self.frames.frame_width)
        ahead = self._posters.pop((fill_key, step), None)  # drawn ahead (_draw_ahead)
        if made is None and ahead is not None:
            poster, size = ahead
        elif made is None:
            self.view.show_step(step, draw=False)
            # one plain draw: the blit's background and layers (three draws) are built
            # later, for the groups, after the page shows this poster
            self.fig.canvas.draw()
            rgba = frame_rgba(self.fig)
            poster, size = encode_png(rgba), rgba.shape[:2]
        with self.frames.hold_sync():
            self.frames.value = step
            self.frames.n_steps = len(self.trace)
            self.frames.captions, self.frames.infos = captions, infos
            self.frames.frame_height, self.frames.frame_width = size
            self.frames.poster = poster
            self._poster_key = (fill_key, step) if poster else None
            self.frames.alt = f"the {self.trace.method} fill of a triangle, step by step"
            self.frames.fill = "|".join(fill_key)
            self.frames.gen += 1
        if made is not None:
            self.frames.send_group(group, *made)

    def _hinted(self, captions: list[str]) -> list[str]:
        """``captions`` with the comparison's hint after the last one, as the comparison is
        now (open or closed); unchanged without attributes (no comparison). In the caption,
        not the short readout: a long readout pushed the speed menu onto a new line."""
        if self.interp_view is None:
            return list(captions)
        comparison = getattr(self, "comparison", None)  # made after the first publish: closed
        opened = comparison is not None and comparison.selected_index is not None
        hint = COMPARISON_HINT_OPEN if opened else COMPARISON_HINT
        if self._fill_key()[2] != ONE_SAMPLE:
            hint = f"{hint} {COMPARISON_ONE_SAMPLE}"
        last = captions[-1].rstrip()
        end = "" if last.endswith((".", "!", "?")) else "."  # the step's text is a phrase
        return [*captions[:-1], f"{last}{end} {hint}"]

    def _rehint(self, change=None) -> None:
        """The last caption follows the comparison opening and closing (the page relabels
        the step on show: ``change:captions`` in ``frames.js``)."""
        captions, _infos = self._texts[self._fill_key()]
        self.frames.captions = self._hinted(captions)

    def _fill_key(self) -> tuple[str, str, str]:
        method = self.method.value
        return (method, self.interpolation.value, shown_samples(method, self.samples.value))

    def _group(self, g: int):
        """Frames of group ``g`` for the page (made once per fill); the view is put back on
        the step on show. Once the page has every group, the fills one toggle away are
        drawn ahead (:meth:`_draw_ahead`)."""
        key = (self._fill_key(), g)
        if key not in self._groups:
            self._groups[key] = render_group(self.view, g, self.frames.key)
            self.view.show_step(self.frames.value, draw=False)
            self._ahead_when_idle()
        return self._groups[key]

    def _ahead_when_idle(self) -> None:
        """Draw ahead (:meth:`_draw_ahead`) once the page has every group of the fill."""
        fill_key, groups = self._fill_key(), -(-len(self.trace) // self.frames.key)
        if all((fill_key, g) in self._groups for g in range(groups)):
            later(self._draw_ahead, idle_only=True)

    def _neighbours(self) -> list[tuple[str, str, str]]:
        """The fills one toggle of the method or the interpolation away from the one on show."""
        method, interpolation, samples = self._fill_key()
        keys = [(m, interpolation, shown_samples(m, self.samples.value))
                for _, m in METHOD_OPTIONS if m != method]  # fmt: skip
        if self.tri.attrs:
            keys += [(method, i, samples) for _, i in INTERPOLATION_OPTIONS if i != interpolation]
        return keys

    def _draw_ahead(self) -> None:
        """While the kernel idles, the picture a toggle would show first: one neighbouring
        fill at a time (each a rasterisation and one draw), the view put back afterwards,
        so a toggle answers with a picture drawn already. Never before the page has the
        fill on show; a toggle arriving meanwhile waits for one draw at most."""
        shown, current = self.frames.value, self.fill
        for key in self._neighbours():
            try:
                fill = self._rasterize(*key)
            except ValueError:  # e.g. tiles with several samples: not offered
                continue
            step = self.view.set_fill(fill, draw=False).index  # the step a toggle shows
            if (key, step) in self._posters or (key, step // self.frames.key) in self._groups:
                self.view.set_fill(current, step=shown, draw=False)
                self._show_samples()  # a set_fill makes a new plan: the dots' layer again
                continue
            try:
                self.fill = fill
                self._show_samples()
                self.view.show_step(step, draw=False)
                self.fig.canvas.draw()
                rgba = frame_rgba(self.fig)
                if len(self._posters) >= 32:
                    self._posters.clear()
                self._posters[(key, step)] = (encode_png(rgba), rgba.shape[:2])
            finally:
                self.fill = current
                self.view.set_fill(current, step=shown, draw=False)
                self._show_samples()
            later(self._draw_ahead, idle_only=True)  # the next after whatever is waiting
            return

    # -- state ------------------------------------------------------------------------------
    @property
    def trace(self):
        """The FillTrace on show."""
        return self.fill.trace

    @property
    def step(self) -> int:
        """The step on show."""
        return self.frames.value

    @property
    def caption_text(self) -> str:
        """The caption on show (equal to ``trace.caption(step)``; the page shows it too)."""
        return self.trace.caption(self.frames.value)

    @property
    def step_info(self) -> str:
        """``"of 0–787 (pixel)"``: what the page shows beside the step number."""
        return step_info(self.trace, self.frames.value)

    # -- driving ----------------------------------------------------------------------------
    def show_step(self, k: int) -> None:
        """Show step ``k`` (the same as setting ``slider.value``; negative counts from the end)."""
        self.frames.value = self.trace.index(k)

    @property
    def interval(self) -> int:
        """Milliseconds per step when playing (the page plays; its speed menu sets it, and
        setting it from code moves the menu)."""
        return self.frames.interval

    @interval.setter
    def interval(self, ms: int) -> None:
        self.frames.interval = as_int("interval", ms, minimum=1)

    def _go(self, k: int) -> None:
        self.frames.value = min(max(k, 0), self.frames.max)

    def _on_step(self, change) -> None:
        # the page has drawn the step already; the kernel-side view follows for code that
        # reads it (player.view, player.caption_text)
        if not self._quiet:
            self.view.show_step(change["new"], draw=False)
            self._ahead_when_idle()  # a toggle here shows this step

    def _on_fill_options(self, change) -> None:
        self.fill = self._rasterize(self.method.value, self.interpolation.value)
        self._note_samples()
        # The view decides the step (a finished fill stays finished, else the same index).
        step = self.view.set_fill(self.fill, draw=False)
        self._show_samples()
        with self._holding():
            self._publish(step.index)
        if self.interp_view is not None:
            self.interp_view.update(self.fill, draw=False)
            labels_off_frames(self.interp_view)  # the update placed them afresh
            if change["owner"] is self.interpolation:
                self.interp_view.highlight(self.interpolation.value)
                self._interp_blit.invalidate()  # the highlight is in the background
                # the toggle's effect is in the folded figure: unfold it, or nothing shows;
                # below the steps, which stay (it is one of their controls)
                if self.comparison.selected_index is None:
                    self._keep_steps = True
                    self.comparison.selected_index = 0
            # folded, the figure is drawn when unfolded (a toggle answers sooner)
            self._interp_stale = True
            later(self._refresh_comparison)

    def _refresh_comparison(self, change=None) -> None:
        """Draw the interpolation figure if it is on show and out of date."""
        if self._interp_stale and self.comparison.selected_index is not None:
            self._interp_stale = False
            self.interp_display.refresh()

    def _draw_interp(self) -> None:
        self._interp_blit = same_or_new(self._interp_blit, comparison_edit_blit(self.interp_view))
        self._interp_blit.draw()

    @property
    def in_use(self) -> list:
        """The "in use" notes under the interpolation panels (empty without attributes)."""
        return [] if self.interp_view is None else self.interp_view.in_use

    # -- display ----------------------------------------------------------------------------
    def _repr_mimebundle_(self, **kwargs):
        bundle = self.widget._repr_mimebundle_(**kwargs)
        # What a page shows where no widget can live (an HTML export, a viewer): see
        # static_fallback.
        bundle["text/html"] = self.static_fallback()
        return bundle

    def _ipython_display_(self) -> None:
        if os.environ.get("TEACHRASTER_STATIC_PAGES"):  # `teachraster html`: one output
            from IPython.display import display

            display(self._repr_mimebundle_(), raw=True)
            return
        # the picture and a hint in an output of their own: what a reopened notebook shows;
        # it follows the step on show once the student stops (settle: no copy per step)
        self._standin_id = f"teachraster-standin-{uuid.uuid4().hex}"
        display_with_fallback(self._repr_mimebundle_(), self.static_fallback(full=False),
                              display_id=self._standin_id)  # fmt: skip
        self.frames.observe(lambda _change: settle(self._update_standin), ("value", "gen"))

    def _update_standin(self) -> None:
        from IPython.display import update_display

        update_display({"text/html": FALLBACK_CSS + self.static_fallback(full=False),
                        "text/plain": STANDIN_PLAIN}, raw=True,
                       display_id=self._standin_id)  # fmt: skip

    def static_fallback(self, *, full: bool | None = None) -> str:
        """HTML standing in for the player where no kernel is running.

        With ``full`` (default: when ``TEACHRASTER_STATIC_PAGES`` is set, as ``teachraster
        html`` does) the whole offline player of :mod:`teachraster.widgets.page`, which
        steps and plays with no kernel; else the picture on show and the hint that brings
        the player back (:func:`~teachraster.widgets.common.standin_html`).
        """
        if full is None:
            full = bool(os.environ.get("TEACHRASTER_STATIC_PAGES"))
        if full:
            data = page_data(self.view, step=self.frames.value, interval=self.interval)
            self.view.show_step(self.frames.value, draw=False)
            return player_fragment(data)
        return standin_html("", "player", self._picture_on_show())

    def _picture_on_show(self) -> bytes:
        """The PNG of the step on show: the poster when it is that step's, else one draw."""
        key = (self._fill_key(), self.frames.value)
        if self._poster_key == key and self.frames.poster:
            return self.frames.poster
        if self._standin_png[0] != key:  # drawn once per step the student stops at
            self.view.show_step(self.frames.value, draw=False)
            self.fig.canvas.draw()
            self._standin_png = (key, encode_png(frame_rgba(self.fig)))
        return self._standin_png[1]

    def _offline_page_(self):
        """``teachraster html``: every step of the fill, stepping and playing in the page."""
        from .offline import OfflinePage

        return OfflinePage(self.static_fallback(full=True), "live")

    def close(self) -> None:
        """Close every widget of the player (the figures are freed with it)."""
        if self.interp_display is not None:
            self.interp_display.close()
        close_tree(self.widget)


class StepButton:
    """A step button of the page, pressed from code: ``player.next.click()``."""

    def __init__(self, action) -> None:
        self._action = action

    def click(self) -> None:
        """Do what the button does in the page."""
        self._action()
