"""``FilterExplorer``: tilt a textured floor and choose a texture filter; see the level of
detail and the error against the true footprint average change."""

from __future__ import annotations

import ipywidgets as widgets
import matplotlib as mpl
import numpy as np

from ..pipeline.geometry.camera import Camera
from ..pipeline.rendering.render_scenes import render
from ..pipeline.texturing.mip_pyramid import level_sizes
from ..pipeline.texturing.texture import TEXTURE_FILTERS, checkerboard, sample
from ..pipeline.texturing.texture_filters import levels_read, mip_level
from ..plotting import plot_error_heatmap, plot_image, plot_levels_read
from ..plotting.blitting import MOVING, STILL, LayeredBlit
from ..study.texture_truth import footprint_average, texel_reads
from .ahead import TogglesAhead, show_kept
from .common import (
    Shown,
    close_tree,
    control_rows,
    fit_width,
    font_scale,
    later,
    projector_text,
    style_context,
    title_html,
)
from .display import COMPARISON_DPI, column_inches, new_figure, resolve_backend
from .dragging import same_or_new
from .live_slider import LiveSlider, info_line, slider_display
from .sprites import PAD, ColourBarSprite, text_boxes
from .textured import CORNER_UV, TRIANGLES, plane_clip

#: The picture's alternative text in the page
#: The error panel's colour range, 0 to this, the same for every filter and tilt (review r26,
#: 09: the bar rescaled per filter, 0.6 / 0.20 / 0.25 at 89°, so panels could not be compared
#: by colour). Every filter's largest error on the checkerboard is below it (0.47, tested).
ERROR_RANGE = 0.5

ALT = "the filtered texture, its mip levels and its error"

#: Tilts whose footprint average is kept (0.44 MiB each at 160 x 120): every position of
#: the tilt slider (0-89 by 1), drawn while the kernel idles (``_truths_ahead``).
TRUTH_CACHE = 96


#: The figure's greatest height in screen pixels at its own dpi: with the widget's title,
#: controls and status line above it, the whole explorer fits a 1000-px-tall screen in
#: JupyterLab, so the image and the error panel are seen together (review r184, 09-7: stacked
#: in three rows the figure was 875 px tall and the widget 1059-1083 px). The figure is as
#: tall as its four panels need, at most this.
FIGURE_PX = 680

#: The two scenes (``plane_clip``'s placement of the square): lesson 04's square, seen from
#: above its near edge, whose footprints stay under three times as long as wide at every
#: tilt; and a floor seen from an eye low above it, its far edge at a grazing angle, where
#: they reach the cap of 16 (review r233 09 M3: no view of a strongly anisotropic
#: footprint could be moved).
VIEWS = {"square": {},
         "grazing floor": {"distance": 0.6, "below": 0.15, "fit": "depth"}}  # fmt: skip

#: The filter menu's width, its description included
FILTER_MENU = "300px"

#: The status line's RMS error during a drag at a tilt whose footprint mean is not at hand
DRAFT_RMS = "(on release)"

#: The caps a driver offers (``max_anisotropy``; GL's ``TEXTURE_MAX_ANISOTROPY``, Vulkan's
#: ``maxAnisotropy``, Direct3D's ``MaxAnisotropy``): 1 is one probe, trilinear.
CAPS = (1, 2, 4, 8, 16)


def explorer_axes(fig, height: int, width: int) -> tuple[list, list, tuple[float, float]]:
    """Size ``fig`` to the notebook column and add the explorer's Axes.

    Four panels of one size, at one whole number of figure pixels per image pixel (the
    checks keep equal widths), so that a pixel lies at the same place in each: on the left
    the filtered image above the box average it is measured against, on the right the mip
    level(s) each pixel reads above the error against that average, each with its colour bar
    on its right. The figure is as wide and tall as they need, at most the column and
    :data:`FIGURE_PX`. Three panels
    in one row were each about 190 px wide in a 1280 px browser (review r42, 09-3); three rows
    were taller than the screen (review r184, 09-7); the box average at 0.62 times the
    filtered image's scale could not be compared with it pixel by pixel (review r246, 09 FIG2).

    Returns
    -------
    panels : [Axes, Axes, Axes, Axes]
        The image, the box average, the level panel, the error panel.
    bars : [Axes, Axes]
        The colour bars' Axes, right of the level and the error panel.
    note_at : (float, float)
        Where the error's maximum goes, in axes fraction of the error panel: right-aligned
        under it, off the picture.
    """
    s, r, fw = font_scale(), width / height, column_inches(fig)
    left, right, gap, bottom = 0.15, 0.1, 0.3 * s, 0.1
    title = 0.25 * s + 0.1  # no tick labels: one row of titles (their pad included)
    # a colour bar beside its panel: the gap, the bar and its tick labels (no label: the
    # panel's title says what the colours are)
    pad, bar, beside = 0.09 * s, 0.1 * s, 0.3 * s
    note = 0.45 * s  # the row under the error panel holding its maximum
    room_w = (fw - left - right - gap - pad - bar - beside) / 2
    room_h = (FIGURE_PX / fig.dpi - 2 * title - note - bottom) / 2
    scale = max(int(min(room_w, room_h * r) * fig.dpi / width), 1)
    w = scale * width / fig.dpi
    h = w / r
    # as wide and tall as the panels need: a narrower column shrinks the figure less
    fw, fh = left + 2 * w + gap + pad + bar + beside + right, 2 * title + 2 * h + note + bottom
    fig.set_size_inches(fw, fh)
    panels, bars = [], []
    for x, beside_bar in ((left, False), (left + w + gap, True)):
        for k in range(2):
            y = fh - (k + 1) * (title + h)  # the panel's lower edge
            panels.append(fig.add_axes((x / fw, y / fh, w / fw, h / fh)))
            if beside_bar:
                bars.append(fig.add_axes(((x + w + pad) / fw, y / fh, bar / fw, h / fh)))
    # right-aligned with the error panel's colour bar, below the panel and clear of the
    # bar's lowest tick label (the bar is put back from its cache only where nothing
    # moving overlaps it)
    return panels, bars, ((w + pad + bar) / w, -0.22 * s / h)


def middle_columns(width: int) -> tuple[int, ...]:
    """The two pixel columns either side of the square's middle line, x = ``width`` / 2.

    The square is centred in both scenes, so that line is u = repeats / 2: a check border
    (and, for an even count, a wrap of the texture). It falls exactly between two columns:
    no pixel straddles it, so the box average keeps full contrast on both sides, while every
    filter that blends texels ramps across it: a bright stripe in every filter's error that
    is no filter's defect (lesson 09 §5). The ring's search leaves it out (review r336 S9: on
    the grazing floor at 89° it ringed the stripe's foot, away from the far checks). With an
    odd width a column straddles the line, and there is no stripe.
    """
    return (width // 2 - 1, width // 2) if width % 2 == 0 else ()


def _fixed(html: str, chars: int, align: str = "left") -> str:
    """``html`` in an inline box at least ``chars`` characters wide, aligned ``align`` in it
    (a number right-aligned, so that its padding does not open a gap inside the phrase after
    it: "· 1.0␣␣ texels read", review r195 09-3)."""
    return (f'<span style="display:inline-block;min-width:{chars}ch;text-align:{align}">'
            f"{html}</span>")  # fmt: skip


def _name_panels(axes) -> None:
    """Title the four panels, with no ticks or axis labels."""
    names = ("filtered", "footprint mean", "mip level(s) read", "error vs footprint mean")
    for ax, name in zip(axes, names):
        # at the size of axis labels: the style's title size made "error vs footprint mean"
        # wider than its panel
        ax.set_title(name, fontsize=mpl.rcParams["axes.labelsize"])
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_xlabel("")
        ax.set_ylabel("")


class FilterExplorer:
    """A checkerboard square tilting away from the camera, filtered as you choose.

    Four panels: the filtered image (top left) above the box average it should show (the
    texture averaged over each pixel's true footprint,
    :func:`teachraster.study.texture_truth.footprint_average`), and on the right the mip
    level(s) each pixel reads (as the engine decides them,
    :func:`~teachraster.pipeline.texturing.texture_filters.levels_read`: one
    colour per level, two levels' colours mixed by their weights where a filter blends them,
    the probes' finer levels for ``anisotropic``, level 0 everywhere for ``nearest`` and
    ``bilinear``) above the error against the box average. The square's texture repeats
    ``repeats`` times, so tilting it far makes its checks much smaller than a pixel: the moiré
    of ``nearest`` and ``bilinear``, the blur of ``trilinear``, the sharpness of
    ``anisotropic``. The ``scene`` control lays the square as a floor seen at a grazing angle
    (:data:`VIEWS`), where footprints grow up to 16 times as long as wide, and
    ``max_anisotropy`` caps the anisotropic probes (:data:`CAPS`).

    Parameters
    ----------
    width, height : int
        Image size in pixels.
    tilt : float
        Starting tilt in degrees (0: facing the camera; 90: flat like a floor).
    filter : str
        Starting filter, one of :data:`teachraster.pipeline.texture.TEXTURE_FILTERS`.
    repeats : int
        How often the checkerboard repeats across the square.
    samples : int
        Points per pixel side of the ground truth (``samples``² per pixel).
    view : str
        The starting scene, a key of :data:`VIEWS`.
    max_anisotropy : int
        The starting cap on the anisotropic probes, one of :data:`CAPS`.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    widget : ipywidgets.VBox
    tilt : LiveSlider
    filter : Dropdown
    view : ToggleButtons
    max_anisotropy : Dropdown
    image, truth, error : (H, W, 3), (H, W, 3), (H, W) arrays on show
    lod : (H, W) array
        λ per pixel.
    levels_read : LevelsRead
        What the level panel shows: the level(s) the filter shown reads at each pixel, their
        weights and probes (NaN where uncovered).
    rms : float
        Root-mean-square error against the truth.

    Notes
    -----
    While the tilt is dragged in the page, each value is shown as a draft: the filtered
    image and the levels exact, the error only at tilts whose truth is kept (every position
    in the end, computed while the kernel idles, nearest first; otherwise ``truth`` and
    ``error`` are None and ``rms`` NaN until the release), without its note, and its colour
    bar only if that range was drawn before. The release always brings the full picture, the
    same as setting ``tilt.value`` from code. In a page, the picture at every tilt is drawn
    ahead as that full picture (error, note and colour bar included) while the kernel idles,
    so a drag or key over those tilts sends no drafts at all, and its release sends no
    picture either: the page shows it already (:meth:`FramesAhead.held
    <teachraster.widgets.ahead.FramesAhead.held>`); the kernel only takes the state there.

    Examples
    --------
    >>> ex = FilterExplorer(48, 36, tilt=80.0, filter="nearest", samples=3, backend="image")
    >>> aliased = ex.rms
    >>> ex.filter.value = "trilinear"
    >>> ex.rms < aliased
    True
    >>> ex.close()
    """

    def __init__(
        self,
        width: int = 160,
        height: int = 120,
        *,
        tilt: float = 80.0,
        filter: str = "trilinear",
        repeats: int = 8,
        samples: int = 8,
        view: str = "square",
        max_anisotropy: int = 16,
        backend: str = "auto",
        style: str | None = None,
    ) -> None:
        self.width, self.height = width, height
        self.backend = resolve_backend(backend)
        self.texture = checkerboard(8, 64)
        self.n_levels = len(level_sizes(*self.texture.shape[:2]))
        self.repeats, self.samples = repeats, samples
        self.camera = Camera(eye=(0.0, 0.0, 0.0), target=(0.0, 0.0, -1.0), fov_y=60.0,
                             near=0.05, far=50.0)  # fmt: skip
        # the four controls on one row of the column, so that the whole explorer still fits
        # a 1000-px screen (review r184 09-7)
        narrow = {"description_width": "initial"}
        # wide enough for "nearest_mipmap_nearest" at the projector's 16 px (review r246 09
        # S1: at 250 px it read "nearest_mipmap_neares")
        self.filter = widgets.Dropdown(options=list(TEXTURE_FILTERS), value=filter,
                                       description="filter", style=narrow,
                                       layout=fit_width(widgets.Layout(width=FILTER_MENU)))  # fmt: skip
        self.view = widgets.Dropdown(options=list(VIEWS), value=view, description="scene",
                                     style=narrow, layout=widgets.Layout(width="190px"))  # fmt: skip
        self.max_anisotropy = widgets.Dropdown(options=list(CAPS), value=max_anisotropy,
                                               description="max aniso", style=narrow,
                                               layout=widgets.Layout(width="150px"))  # fmt: skip
        # in the page, coalesced: the kernel renders the latest angle, never a queue
        self.tilt = LiveSlider(value=tilt, min=0.0, max=89.0, step=1.0,
                               description="tilt (°)", readout_format=".0f",
                               layout=fit_width(widgets.Layout(width="330px")))  # fmt: skip
        self._truths: dict = {}
        self._read_counts: dict = {}
        self._render()
        with style_context(style):
            self.fig = new_figure((13, 4), self.backend, dpi=COMPARISON_DPI)
            axes, bars, note_at = explorer_axes(self.fig, height, width)
            self.panels = {
                "image": plot_image(axes[0], self.image),
                "truth": plot_image(axes[1], self.truth),
                "lod": plot_levels_read(axes[2], self.levels_read, self.n_levels, cax=bars[0]),
                "error": plot_error_heatmap(axes[3], self.image, self.truth, label="|error|",
                                            title=False, cax=bars[1], note_at=note_at,
                                            vmax=ERROR_RANGE),
            }  # fmt: skip
            error = self.panels["error"]
            error.skip_columns, error.skipped = middle_columns(width), "middle stripe left out"
            error.update(self.image, self.truth)
            for bar in bars:  # read from the back of the room: the size of axis labels
                bar.tick_params(labelsize=mpl.rcParams["axes.labelsize"])
            # the title says what the colours are; the label's row holds the maximum (the
            # note), clear of the colour bar, which is put back from a cache per range
            self.panels["error"].colorbar.set_label("")
            self.panels["lod"].colorbar.set_label("")
            _name_panels(axes)
            self.axes = axes
            self._blit = self._edit_blit()
            error = self.panels["error"]
            # the ring may lie on the panel's edge: drawn whole, over the margin (review
            # r246 09 FIG2: on the grazing floor at 89° half of it was cut off)
            error.marker.set_clip_on(False)
            self._bar = ColourBarSprite(self.fig, lambda: error.image, error.colorbar)
            self.display = slider_display(
                self.fig, self.backend, draw=self._draw, drafting=self._drafting, alt=ALT
            )
        self.filter.observe(lambda change: self.update(restart=True), "value")
        # another scene or cap: every picture kept (other filters, other tilts) is stale
        for control in (self.view, self.max_anisotropy):
            control.observe(lambda change: self.update(restart=True, stale=True), "value")
        self.tilt.observe(lambda change: self.update(), "value")
        self.tilt.on_release(self.update)  # a drag ended on a draft: the full picture
        self.info, info_widgets = info_line(self.display)
        self.info.value = self._info_html()
        title = title_html(
            "Texture filtering: a floor tilting to the horizon",
            "Tilt until the checks are smaller than a pixel, then compare filters. On the "
            "square the camera sees no footprint more than three times as long as wide, on the "
            "grazing floor up to 16 times: there max aniso matters. The ring in the error "
            'panel marks the worst pixel off the middle stripe, its error the "max" under it.',
        )
        controls = control_rows([self.tilt, self.filter], [self.view, self.max_anisotropy])
        self.widget = projector_text(widgets.VBox([title, controls, *info_widgets,
                                                   self.display.widget]), title)  # fmt: skip
        self._ahead = None
        #: the other filters' pictures at the tilt on show, drawn while the kernel idles
        self._toggles = TogglesAhead(self.display, self, TEXTURE_FILTERS)
        if self.backend != "ipympl":
            # the full picture at every tilt, drawn while the kernel idles: a release or key
            # on a tilt drawn ahead then waits for nothing from the kernel (issue 31: the
            # full picture drawn at the release came 104-175 ms after it, target 100)
            self._ahead = self.display.ahead(self.tilt, self, full=True)
            self._ahead.on_listening.append(self._toggles_ahead)

    def _render(self) -> None:
        self._compute_at(self.tilt.value)

    def clip_at(self, tilt: float, view: str | None = None) -> np.ndarray:
        """The square's two clip-space triangles at ``tilt`` in scene ``view`` (default: the
        scene on show), as the explorer renders them."""
        view = self.view.value if view is None else view
        return plane_clip(tilt, self.camera, self.width / self.height, **VIEWS[view])

    def _compute_at(self, tilt: float, filter: str | None = None) -> None:  # noqa: A002
        clip = self.clip_at(tilt)
        uv = np.broadcast_to(CORNER_UV[TRIANGLES] * self.repeats, (2, 3, 2))
        frame = render(clip, self.width, self.height, attrs=uv, derivatives=True)
        f = self.shown_filter = self.filter.value if filter is None else filter
        cap = self.shown_cap = self.max_anisotropy.value
        self.shown_view = self.view.value
        if f in ("nearest", "bilinear"):
            self.image = sample(self.texture, frame.attrs, f)
        else:
            self.image = sample(self.texture, frame.attrs, f, ddx=frame.ddx, ddy=frame.ddy,
                                max_anisotropy=cap)  # fmt: skip
        self.lod = mip_level(frame.ddx, frame.ddy, self.texture.shape)
        # the engine's choice of levels for this filter, only coloured by the panel
        self.levels_read = levels_read(f, frame.ddx, frame.ddy, self.texture.shape, cap)
        self.frame, self.shown_tilt = frame, tilt
        key = (self.shown_view, tilt)
        if self._drafting() and key not in self._truths:
            # a draft leaves the error out rather than wait for a new truth (at the release)
            self.truth, self.error, self.rms = None, None, float("nan")
            return
        self.truth = self._truth(clip, uv, frame.triangle_id, key)
        self.error = np.abs(self.image - self.truth).mean(axis=-1)
        self.rms = float(np.sqrt(np.nanmean((self.image - self.truth) ** 2)))

    def _drafting(self) -> bool:
        """True while the tilt is dragged: a draft shows the filtered image and the levels,
        and the error only where its truth is at hand, without its note or a colour bar not
        drawn before; the release brings the full picture."""
        return self.tilt.dragging

    def _truth(self, clip, uv, triangle_id, key: tuple) -> np.ndarray:
        """The footprint average at ``key`` (scene, tilt), kept for the last few tilts: the
        filter leaves it alone, and a student drags the slider back and forth."""
        truth = self._truths.pop(key, None)
        if truth is None:
            truth = footprint_average(clip, uv, self.texture, triangle_id, samples=self.samples)
            truth.flags.writeable = False  # shared by every filter shown at this tilt
        self._keep_truth(key, truth)
        return truth

    def _keep_truth(self, key: tuple, truth: np.ndarray) -> None:
        self._truths[key] = truth  # the most recent last
        while len(self._truths) > TRUTH_CACHE:
            self._truths.pop(next(iter(self._truths)))

    def _truths_ahead(self) -> None:
        """While the kernel idles, the truth at the slider position nearest the tilt shown
        that has none yet, one per call (a value arriving meanwhile waits for one truth at
        most), out to every position: an arrow key, or the release of a drag anywhere, then
        finds its truth at hand (computed at the release, it was part of the 104 ms from the
        release to the last picture; issue 31 allows 100, and the colour bar drawn at every
        release keeps it near that still)."""
        ahead = self._next_truth_ahead()
        if ahead is None:
            return
        clip = self.clip_at(ahead)
        uv = np.broadcast_to(CORNER_UV[TRIANGLES] * self.repeats, (2, 3, 2))
        frame = render(clip, self.width, self.height, attrs=uv)
        self._truth(clip, uv, frame.triangle_id, (self.view.value, ahead))  # kept
        later(self._truths_ahead, idle_only=True)  # the next nearest, next time

    def _next_truth_ahead(self) -> float | None:
        """The slider position nearest the tilt shown (the next one up first) whose truth is
        not kept, as the page sends it (``min + k * step``); None when all are kept."""
        lo, step = self.tilt.min, self.tilt.step
        n = int(round((self.tilt.max - lo) / step))
        k0 = int(round((self.tilt.value - lo) / step))
        for d in range(1, n + 1):
            for k in (k0 + d, k0 - d):
                if 0 <= k <= n and (self.view.value, lo + k * step) not in self._truths:
                    return lo + k * step
        return None

    def _edit_blit(self) -> LayeredBlit:
        """A new tilt or filter changes the three images and the error's marked maximum;
        titles, frames and the level key stay in a cached background (the error's colour
        bar is drawn over it, :class:`~teachraster.widgets.sprites.ColourBarSprite`)."""
        error = self.panels["error"]
        images = [self.panels["image"].image, self.panels["truth"].image,
                  self.panels["lod"].image, error.image]  # fmt: skip
        frames = [s for ax in self.axes for s in ax.spines.values()]  # drawn over the images
        return LayeredBlit(self.fig, [(MOVING, images), (STILL, frames),
                                      (MOVING, [error.marker, error.note])])  # fmt: skip

    def _draw(self) -> None:
        self._blit = same_or_new(self._blit, self._edit_blit())
        error = self.panels["error"]
        # the note is plain text under the bar's tick labels: a pad of PAD keeps it clear of
        # the bar's cached box (text_boxes' default 8 reached into it: the bar was drawn
        # afresh at every release, ~26 ms of its ~65)
        others = [ax.bbox for ax in self.axes] + text_boxes([error.note], pad=PAD)
        self._bar.draw(self._blit, draft=self._drafting(), others=others)

    def update(self, *, restart: bool = False, stale: bool = False) -> None:
        """Render again with the controls' values and update the panels in place
        (``restart``: the filter changed, the pictures drawn ahead are stale; ``stale``: the
        scene or the cap changed, the other filters' pictures kept are stale too)."""
        if stale:
            self._toggles.where = None  # none of them is taken, and the next start drops all
        kept = self._toggles.take(self.tilt.value, self.filter.value) if restart else None
        if kept is not None and not self._full(kept[2]):
            kept = None  # only a full picture at the tilt on show stands for a toggle
        if kept is not None:  # a filter drawn ahead at this tilt: its picture at once
            show_kept(self, kept)
            self._set_artists()  # for the next picture drawn
        else:
            # the status line says a new picture is on its way: the last one's numbers were
            # read as the new state's (review r81 09-8)
            self.info.value = self._pending_html()
            self._render()
            self._set_artists()
            self.info.value = self._info_html()
            self.display.refresh()
        if not self._drafting():
            later(self._truths_ahead, idle_only=True)
            if self._ahead is not None and self._ahead.listening:
                self._toggles_ahead()
        if restart and self._ahead is not None:
            self._ahead.restart()

    def _full(self, state: dict) -> bool:
        """True when ``state`` (a picture's, drawn ahead) is the full picture of the
        controls now: this tilt and filter, its error included (not a draft's)."""
        return (state.get("truth", self.truth) is not None
                and state.get("shown_tilt", self.shown_tilt) == self.tilt.value
                and state.get("shown_filter", self.shown_filter) == self.filter.value)  # fmt: skip

    def _toggles_ahead(self) -> None:
        """The other filters at the tilt on show, drawn while the kernel idles (for a page)."""
        self._toggles.start(self.tilt.value, self.filter.value)

    def _set_artists(self) -> None:
        self.panels["image"].update(self.image)
        self.panels["lod"].update(self.levels_read)
        error, truth = self.panels["error"], self.panels["truth"]
        truth.image.set_visible(self.truth is not None)
        if self.truth is not None:
            truth.update(self.truth)
        if self.truth is None:  # a draft without the truth: no error to show
            for artist in (error.image, error.marker, error.note):
                artist.set_visible(False)
        elif self._drafting():
            error.image.set_visible(True)
            with self._bar.quietly():  # the colour bar follows at the release
                error.update(self.image, self.truth)
            error.note.set_visible(False)
        else:
            error.image.set_visible(True)
            error.update(self.image, self.truth)

    def _info_html(self) -> str:
        """The status line: one line at a 1280-px window for every filter, so that switching
        filters never wraps it and moves the figure (review r184, 09-8: the figure jumped
        24 px). The filter's name takes only its own width: a box as wide as the longest name
        left a gap of up to 15 letters after "nearest" (review r314 S1), and a name one
        longer only moves the numbers after it. The RMS error comes last, in a box as wide as
        a drag's "(on release)", so that a drag never lengthens the line either (review
        r246 09 S1: it wrapped while the mouse was held and pushed the figure down a line)."""
        reads = self._reads()
        rms = DRAFT_RMS if self.truth is None else f"{self.rms:.3f}"
        # the picture's own tilt first: during a drag the slider's readout may run ahead of
        # the kernel's picture, and these numbers are the picture's (review r233 09 W1)
        return (
            f"<b>{_fixed(f'{self.shown_tilt:.0f}°', 3, 'right')}</b>: "
            f"<b>{self.shown_filter}</b> · "
            # texel *reads*: a footprint's size in texels is ρ, which λ = log2 ρ gives (review
            # r257 C2: "1.0 texels per pixel · largest λ 1.8" read as a contradiction); "RMS
            # error" as the lesson's tables say it (r314 S1: the longer name wrapped the line)
            f"{_fixed(f'{reads:.1f}', 4, 'right')} texels read per pixel"
            f" · largest λ {np.nanmax(self.lod):.1f} · RMS error "
            f"{_fixed(f'<b>{rms}</b>', len(DRAFT_RMS) + 1)}"
        )

    def _pending_html(self) -> str:
        return (f"filter <b>{self.filter.value}</b> at {self.tilt.value:.0f}° · "
                "<i>computing…</i>")  # fmt: skip

    def _reads(self) -> float:
        key = (self.shown_view, self.shown_tilt, self.shown_filter, self.shown_cap)
        if key not in self._read_counts:  # a few ms: kept, as the truth is
            cov = self.frame.coverage
            self._read_counts[key] = texel_reads(self.shown_filter, self.frame.ddx[cov],
                                                 self.frame.ddy[cov], self.texture.shape,
                                                 self.shown_cap)  # fmt: skip
            if len(self._read_counts) > 4 * TRUTH_CACHE:
                self._read_counts.pop(next(iter(self._read_counts)))
        return self._read_counts[key]

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_

    def close(self) -> None:
        """Close every widget of the explorer."""
        self._toggles.close()
        self.display.close()
        close_tree(self.widget)
