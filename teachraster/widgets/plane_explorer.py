"""``PlaneExplorer``: an attribute as a plane over the screen, and the set-up that finds it.

Lesson 03's widget. Drag a vertex in the picture (or move it on its sliders) or change a
vertex value and watch the three views of the
same plane agree: the attribute at every pixel centre with its (straight, parallel) contour
lines, Fatahalian's 3 × 3 system and its set-up matrix M (CMU 15-462 *Texture*), and the
coefficients A, B, C, D of *Triangle Rasterisation II - Interpolation* with its steps
dx = −A/C, dy = −B/C.

Symbols (lesson 00's table): vertices v1, v2, v3 (Fatahalian's **a**, **b**, **c**), vertex
values f1, f2, f3 (his too; in code ``f[0]`` is f1); the plane f(x, y) = g_x x + g_y y + g_0
(Fatahalian writes A, B, C for g_x, g_y, g_0; the other note's A, B, C, D are different
numbers, C being twice the signed area).
"""

from __future__ import annotations

from contextlib import contextmanager

import ipywidgets as widgets
import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.text import Text
from matplotlib.ticker import FuncFormatter, MaxNLocator

from ..core.fill import rasterize
from ..core.plane_equations import attribute_plane, plane_equation, setup_matrix
from ..core.triangle import Triangle
from ..plotting import COLORS, plot_attribute, plot_pixel_grid, plot_triangle
from ..plotting.blitting import MOVING, STILL, LayeredBlit
from ..plotting.common import fs, label_box, screen_ticks
from ..plotting.label_places import boxes_around, place_on_line
from .common import (
    Shown,
    close_tree,
    control_row,
    fit_width,
    picture_row,
    projector_text,
    style_context,
    title_html,
)
from .display import new_figure, resolve_backend
from .dragging import hidden, same_or_new
from .live_slider import LiveSlider, info_line, slider_display
from .sprites import ColourBarSprite, text_boxes

#: The picture's alternative text in the page
ALT = "the attribute plane over the pixel grid"

#: At most this many steps of f between the smallest and largest vertex value: the contour
#: lines lie at round values (review r216 03-6: six equal steps gave f = -0.57, -0.14, ...),
#: 4 to 8 of them for the sliders' values
LEVELS = 8

#: The steps of f between two contour lines: 1, 2, 2.5 or 5 times a power of ten
LEVEL_STEPS = [1, 2, 2.5, 5, 10]

#: With more lines than this, only every other one (the multiples of twice the step) carries
#: its value: a few labels, not a column of them
ALL_LABELLED = 4

#: The figure's size in inches (at the page's 96 dpi: 605 × 413 px): the grid, as wide as
#: the room left by its ticks and the colour bar allows, fills its height.
FIGSIZE = (6.3, 4.3)

#: The numbers beside the figure: 15 px, readable on a projector (review r78 03-7: the
#: page's 13 px was below classroom size); the 3 × 3 system's table too (r96 03-3)
INFO_SIZE = "15px"
INFO_DIV = f"<div style='margin-left:16px; font-size:{INFO_SIZE}'>"

#: Each slider's width in the page: at the projector's 16 px (``common.PROJECTOR_CSS``) its
#: name (5 em), track (120 px at least) and value (4 em) need 280 px; 260 did at 13 px
SLIDER_WIDTH = "290px"

#: What the colours are (the colour bar's label; the Axes have no title).
COLOUR_LABEL = "f at the pixel centres"

#: The widest tick label of the colour bar: f runs from −1 to 2 in tenths on the sliders and
#: the ticks step by 1, 2 or 5 times a power of ten, so a label has a sign, one digit before
#: the point and at most two after it. The layout, solved once, leaves room for it.
WIDEST_TICK = "−0.00"


def plane_system(xy, f) -> dict:
    """Fatahalian's 3 × 3 system for the plane through ``(x_i, y_i, f_i)``, solved two ways.

    Parameters
    ----------
    xy : (3, 2) array-like
        Vertices v1, v2, v3 in pixels.
    f : (3,) array-like
        Vertex values f1, f2, f3.

    Returns
    -------
    dict
        ``system`` the 3 × 3 matrix with rows (x_k, y_k, 1) of v1, v2, v3;
        ``g`` (g_x, g_y, g_0) solving ``system @ g = f`` (f = g_x x + g_y y + g_0);
        ``M`` the 2 × 2 set-up matrix; ``g_recentred`` ``M @ (f2 - f1, f3 - f1)``, which must
        equal (g_x, g_y); ``ABCD`` the other note's coefficients; ``area2`` = 2 × signed area.
        For a zero-area triangle only ``system`` and ``area2`` (0) are given.

    Examples
    --------
    >>> s = plane_system([[0, 0], [4, 0], [0, 2]], [1.0, 3.0, 2.0])
    >>> s["g"].round(6).tolist(), s["g_recentred"].round(6).tolist()
    ([0.5, 0.5, 1.0], [0.5, 0.5])
    """
    xy = np.asarray(xy, dtype=np.float64).reshape(3, 2)
    f = np.asarray(f, dtype=np.float64).reshape(3)
    system = np.column_stack([xy, np.ones(3)])
    (ax, ay), (bx, by), (cx, cy) = xy
    area2 = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
    out = {"system": system, "area2": float(area2)}
    if area2 == 0:
        return out
    M = setup_matrix(xy)
    plane = plane_equation(xy, f)
    out.update(
        g=np.linalg.solve(system, f),
        M=M,
        g_recentred=M @ np.array([f[1] - f[0], f[2] - f[0]]),
        ABCD=np.array([plane.A, plane.B, plane.C, plane.D], dtype=np.float64),
    )
    return out


def round_levels(lo: float, hi: float) -> np.ndarray:
    """The contour levels strictly between ``lo`` and ``hi``: multiples of a round step
    (:data:`LEVEL_STEPS`), at most :data:`LEVELS` steps across; none where ``hi <= lo``.

    Examples
    --------
    >>> round_levels(0.2, 0.9).tolist()
    [0.3, 0.4, 0.5, 0.6, 0.7, 0.8]
    >>> round_levels(-1.0, 2.0).tolist()
    [-0.5, 0.0, 0.5, 1.0, 1.5]
    """
    if not hi > lo:
        return np.array([])
    ticks = MaxNLocator(nbins=LEVELS, steps=LEVEL_STEPS).tick_values(lo, hi)
    step = ticks[1] - ticks[0]
    inner = ticks[(ticks > lo + 1e-9 * step) & (ticks < hi - 1e-9 * step)]
    return np.array([float(f"{v:.12g}") + 0.0 for v in inner])  # 0.30000000000000004 -> 0.3


def fixed(value: float, places: int = 4) -> str:
    """``value`` to ``places`` decimals as the panel prints it, never a negative zero: with
    v2 straight below v1, M's corner is −0.0 (or −1e-17) and printed "-0.0000" (review r320
    S5); a constant f gave −0.0 for dx, dy alike. A negative value takes the minus sign
    "−", as the lessons' text and the contour levels write it (review r330: "-1.0476").

    Examples
    --------
    >>> fixed(-0.0), fixed(-1e-17), fixed(-1.04762, 4), fixed(109.0, 3)
    ('0.0000', '0.0000', '−1.0476', '109.000')
    """
    text = f"{value:.{places}f}"
    if text.startswith("-"):
        return text[1:] if float(text) == 0 else "−" + text[1:]
    return text


def level_text(levels) -> list[str]:
    """The levels as the labels and the numbers beside the figure write them: as many
    decimals as the step needs, a minus sign for a negative value.

    Examples
    --------
    >>> level_text([-0.5, 0.0, 0.25])
    ['−0.50', '0.00', '0.25']
    """
    levels = np.asarray(levels, dtype=np.float64)
    values = np.concatenate([levels, np.diff(levels)])  # the step's decimals too
    places = next(d for d in range(7) if np.allclose(values * 10**d, np.round(values * 10**d),
                                                     rtol=0, atol=1e-6))  # fmt: skip
    return [f"{v + 0.0:.{places}f}".replace("-", "−") for v in levels]


def labelled(levels) -> np.ndarray:
    """Which levels carry their value (bool): all of a few, else the multiples of twice the
    step."""
    levels = np.asarray(levels, dtype=np.float64)
    if len(levels) <= ALL_LABELLED:
        return np.ones(len(levels), dtype=bool)
    twice = 2 * (levels[1] - levels[0])
    ratio = levels / twice
    return np.isclose(ratio, np.round(ratio), atol=1e-6)


def level_segments(g, levels, width: float, height: float) -> list:
    """Segments of the lines f = level, for the plane ``f = g_x x + g_y y + g_0``.

    Each line is straight (the plane's contour lines are parallel), given as a segment long
    enough to cross the whole ``width`` × ``height`` image; the axes clip it. Not clipped to
    the triangle, on purpose: the plane goes on beyond it (helper pixels and multisample
    centres outside the triangle read it there, lessons 08 and 09), and the title says so
    (review r143 03-9). A flat plane
    (g_x = g_y = 0) has no contour lines.

    Examples
    --------
    >>> seg = level_segments([1.0, 0.0, 0.0], [3.0], 8, 8)[0]   # f = x: the line x = 3
    >>> seg[:, 0].tolist()
    [3.0, 3.0]
    """
    gx, gy, g0 = (float(v) for v in g)
    norm2 = gx * gx + gy * gy
    if norm2 == 0:
        return []
    centre = np.array([width / 2, height / 2])
    grad, along = np.array([gx, gy]), np.array([-gy, gx]) / np.sqrt(norm2)
    reach = 2.0 * (width + height)
    segments = []
    for level in levels:
        value = gx * centre[0] + gy * centre[1] + g0
        p0 = centre + (level - value) / norm2 * grad  # nearest point of the line to the centre
        segments.append(np.array([p0 - reach * along, p0 + reach * along]))
    return segments


class PlaneExplorer:
    """Move the vertices, change their values: the plane, its contour lines and its set-up.

    Parameters
    ----------
    xy : (3, 2) array-like
        Starting vertices v1, v2, v3 in pixels.
    f : (3,) array-like
        Starting vertex values f1, f2, f3.
    width, height : int
        Pixel grid.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    widget : ipywidgets.VBox
    x, y, f : lists of three LiveSliders
        Vertex positions and values; setting ``.value`` updates everything.
    values : (height, width) array
        The plane at every pixel centre :func:`~teachraster.rasterize` covers (the top-left
        rule decides centres on an edge; NaN elsewhere): what the image shows.
    system : dict
        :func:`plane_system` of the current triangle.
    info : ipywidgets.HTML
        The system, M and the coefficients, as numbers.

    Examples
    --------
    >>> ex = PlaneExplorer([[1, 1], [14, 4], [5, 13]], [0.0, 1.0, 0.5], backend="image")
    >>> ex.f[1].value = 2.0
    >>> bool(np.allclose(ex.system["g"][:2], ex.system["g_recentred"]))
    True
    >>> ex.close()
    """

    def __init__(self, xy=((2.0, 1.0), (13.0, 5.0), (5.0, 12.0)), f=(0.2, 0.9, 0.5),
                 width: int = 16, height: int = 14, *, backend: str = "auto",
                 style: str | None = None) -> None:  # fmt: skip
        self.width, self.height = width, height
        self.backend = resolve_backend(backend)
        #: the vertices while a drag in the page is under way (the picture is a draft until
        #: the release; the sliders' readouts follow each position); None otherwise
        self._drag_xy: np.ndarray | None = None
        self._quiet = False
        xy = np.asarray(xy, dtype=np.float64).reshape(3, 2)
        f = np.asarray(f, dtype=np.float64).reshape(3)
        self._sliders(xy, f)
        self._compute_at()
        with style_context(style):
            # one screen with its sliders (a projector at 1024 x 768): 605 x 413 px, the grid
            # as large as the room left by its ticks and the colour bar; 7.5 x 6 in was 576 px
            # high, with a title row above the ticks, and the whole widget needed a scroll
            self.fig = new_figure(FIGSIZE, self.backend)
            self.fig.set_layout_engine("constrained")
            self.ax = self.fig.add_subplot()
            self.grid = plot_pixel_grid(self.ax, width, height)
            lo, hi = self._range()
            # no title: the colour bar's label says what the colours are (a row saved)
            self.image = plot_attribute(self.ax, self.values, vmin=lo, vmax=hi, title="")
            self.contours = LineCollection(self._segments(), colors=COLORS["edge"],
                                           linewidths=1.5, linestyles="--")  # fmt: skip
            self.ax.add_collection(self.contours)
            self.triangle = plot_triangle(self.ax, self.xy, arrows=False, inside=True,
                                          clear=True)  # fmt: skip
            # a vertex at the grid's corner shows its whole dot, not a quarter of it (review
            # r216 03-5); the sliders keep every vertex on the grid
            self.triangle.vertices.set_clip_on(False)
            # the values on the contour lines, in white boxes that break the dashes
            self.level_labels = [
                self.ax.text(0, 0, "", ha="center", va="center", fontsize=fs(0.8),
                             color=COLORS["edge"], bbox=label_box(0.9), zorder=5,
                             visible=False)
                for _ in range(LEVELS)
            ]  # fmt: skip
            # positions as the lesson's figures read them: v1 = (2, 1) on its ticks
            screen_ticks(self.ax, width, height)
            bar = self.image.colorbar
            if bar is not None:
                bar.set_label(COLOUR_LABEL)
                # no 2.5 steps: "−0.125" would be wider than WIDEST_TICK
                bar.locator = MaxNLocator(steps=[1, 2, 5, 10])
            # the constrained layout once, then frozen: the blit's background and the
            # artists drawn over it must agree on where the Axes are; solved with room for
            # the widest tick label, or a negative f ("−1.0" is wider than "0.9") pushed the
            # colour bar's label off the figure (review r11, 03 c33)
            with _widest_ticks(bar):
                self.fig.canvas.draw()
            self.fig.set_layout_engine("none")
            self._blit = self._edit_blit()
            image = self.image
            self._bar = None if image.colorbar is None else ColourBarSprite(
                self.fig, lambda: image.image, image.colorbar)  # fmt: skip
            self._set_artists()  # the labels placed in the frozen layout
            # the vertices are dragged in the page (DragFigure, static/drag.js: the
            # TriangleEditor's way); the kernel fills with tr.rasterize at each position
            self.display = slider_display(
                self.fig,
                self.backend,
                draw=self._draw,
                drafting=self._drafting,
                alt=ALT,
                handles=lambda: self.shown_xy,
                on_move=self._on_page_move,
            )
        self.info, info_widgets = info_line(self.display, side="right")
        self.info.value = self._info_html()
        # two lines in a 600-px column (three before, and "listed on the right" was false
        # where the numbers wrap below the figure: JupyterLab's file browser open, r11)
        title = title_html(
            "An attribute is a plane: f = g_x x + g_y y + g_0",
            "Drag a vertex (or use its sliders) or change its value: the dashed contour lines "
            "(f in round steps) stay straight and parallel, and go on beyond the triangle, "
            "where the plane goes on too; the 3 × 3 system, M and A, B, C, D follow.",
        )
        rows = [control_row([self.x[k], self.y[k], self.f[k]]) for k in range(3)]
        # the sliders' names and values at projector size, as FilterExplorer's (review r96
        # 03-3: 12-13 px, the smallest text of lesson 03)
        self.widget = projector_text(widgets.VBox([title, *rows, picture_row(
            [self.display.widget, *info_widgets])]), title)  # fmt: skip
        if self.backend != "ipympl":
            # every slider's positions, drawn while the kernel idles: the slider moved last
            # first, then the values' (f has no other control; a vertex is also dragged in
            # the picture), then the vertices' (issue 31: f2's first drag went through the
            # kernel, 16 fps); full pictures (the colour bar of a new f range too), so a
            # release on one needs no picture from the kernel (up to 122 ms after the
            # release of v1 x)
            self.display.ahead([*self.x, *self.y, *self.f], self, full=True,
                               busy=lambda: self._drag_xy is not None,
                               order=[6, 7, 8, 0, 3, 1, 4, 2, 5])  # fmt: skip

    def _sliders(self, xy, f) -> None:
        def slider(value, lo, hi, name, step=0.25):
            # in the page, coalesced: the kernel renders the latest value, never a queue
            s = LiveSlider(value=value, min=lo, max=hi, step=step, description=name,
                           layout=fit_width(widgets.Layout(width=SLIDER_WIDTH)))  # fmt: skip
            s.observe(lambda change: None if self._quiet else self.update(), "value")
            s.on_release(self.update)  # a drag ended on a draft: the full picture
            return s

        self.x = [slider(xy[k, 0], 0.0, self.width, f"v{k + 1} x") for k in range(3)]
        self.y = [slider(xy[k, 1], 0.0, self.height, f"v{k + 1} y") for k in range(3)]
        # f in tenths: lesson 03's values (0.2, 0.9, 0.5) lie on the slider's positions, so
        # the thumb starts where the readout says and can be brought back there (review r7)
        self.f = [slider(f[k], -1.0, 2.0, f"f{k + 1}", step=0.1) for k in range(3)]

    @property
    def xy(self) -> np.ndarray:
        """The current vertices, (3, 2): the sliders', or where a drag in the page has them."""
        if self._drag_xy is not None:
            return self._drag_xy.copy()
        return np.array([[self.x[k].value, self.y[k].value] for k in range(3)])

    def _on_page_move(self, i: int, x: float, y: float, final: bool) -> None:
        """Vertex ``i`` dragged in the page to (x, y): on the sliders' quarter-pixel grid,
        within their range. Mid-drag the picture is a draft (as a slider's) and the sliders
        take each position, so that their readouts agree with the picture (review r209 03-4:
        "v2 x 13.00" stood beside a v2 dragged to x = 1 until the release); at the release
        one full picture follows."""
        xy = self.xy
        for k, (slider, value) in enumerate(((self.x[i], x), (self.y[i], y))):
            xy[i, k] = min(max(round(value / slider.step) * slider.step, slider.min), slider.max)
        self._drag_xy = None if final else xy
        self._quiet = True  # the sliders' observers would draw a picture each: one is drawn below
        try:
            self.x[i].value, self.y[i].value = xy[i]
        finally:
            self._quiet = False
        self.update()
        ahead = getattr(self.display, "frames_ahead", None)
        # at the release: pictures drawn ahead during the drag may show its positions
        if final and ahead is not None:
            ahead.restart()

    @property
    def fvals(self) -> np.ndarray:
        """The current vertex values, (3,)."""
        return np.array([s.value for s in self.f])

    def _compute_at(self, value: float | None = None, which: int | None = None) -> None:
        """The plane and its values at the sliders' values, slider ``which`` (of x1-x3,
        y1-y3, f1-f3) at ``value`` (pictures drawn ahead: ``widgets.ahead``)."""
        xy, f = self.xy, self.fvals
        if which is not None:
            if which < 6:  # x1, x2, x3, then y1, y2, y3
                xy[which % 3, which // 3] = value
            else:
                f[which - 6] = value
        self.shown_xy, self.shown_f = xy, f
        self.system = plane_system(xy, f)
        ys, xs = np.mgrid[0 : self.height, 0 : self.width] + 0.5
        values = np.full((self.height, self.width), np.nan)
        if self.system["area2"] != 0:
            # the pixels the core fills (snapped edge functions, the top-left rule of
            # lessons 02 and 06), not "all λ >= 0": a centre exactly on an edge, common on
            # the sliders' quarter-pixel grid, is drawn only where tr.rasterize draws it
            inside = rasterize(Triangle(xy), self.width, self.height).coverage
            values[inside] = attribute_plane(xy, f, M=self.system["M"])(xs, ys)[inside]
        self.values = values

    def _range(self) -> tuple[float, float]:
        # The colour range: the vertex values (the plane's extremes on the triangle).
        f = self.shown_f
        lo, hi = float(f.min()), float(f.max())
        return (lo, hi) if hi > lo else (lo - 0.5, hi + 0.5)

    @property
    def levels(self) -> np.ndarray:
        """The values of f on the contour lines: round steps between the vertex values
        (:func:`round_levels`)."""
        f = self.shown_f
        return round_levels(float(f.min()), float(f.max()))

    def _segments(self) -> list:
        if "g" not in self.system:
            return []
        return level_segments(self.system["g"], self.levels, self.width, self.height)

    def _edit_blit(self) -> LayeredBlit:
        """A new value changes the image, the contours and the triangle; the grid and the
        frame (above the image), ticks and title stay in a cached background. The colour
        bar is drawn over it, kept per range (:class:`~.sprites.ColourBarSprite`): moving a
        vertex leaves it as it was."""
        # by zorder: the blit draws in list order, and the labels' white boxes (zorder 6)
        # drawn after the vertex dots (6.2) hid half of v1's dot (review r78 03-7)
        moving = [self.contours, *self.triangle.artists, *self.level_labels]
        above = sorted(moving, key=lambda a: a.get_zorder())
        return LayeredBlit(self.fig, [(MOVING, [self.image.image]),
                                      (STILL, [self.grid.lines, *self.ax.spines.values()]),
                                      (MOVING, above)])  # fmt: skip

    def _drafting(self) -> bool:
        """True while a slider or a vertex in the page is dragged: a draft leaves out a colour bar whose range was
        not drawn before (the release brings the full picture)."""
        return self._drag_xy is not None or any(s.dragging for s in (*self.x, *self.y, *self.f))

    def _draw(self) -> None:
        self._blit = same_or_new(self._blit, self._edit_blit())
        if self._bar is None:
            self._blit.draw()
            return
        labels = [a for a in self.triangle.artists if isinstance(a, Text)] + self.level_labels
        if self._drag_xy is not None:  # a vertex in hand: the labels wait for the release
            with hidden(labels):
                self._bar.draw(self._blit, draft=True, others=[self.ax.bbox])
            return
        self._bar.draw(self._blit, draft=self._drafting(),
                       others=[self.ax.bbox, *text_boxes(labels)])  # fmt: skip

    def update(self) -> None:
        """Recompute from the sliders and redraw the same artists."""
        self._compute_at()
        self._set_artists()
        self.info.value = self._info_html()
        self.display.refresh()

    def _set_artists(self) -> None:
        self.image.update(self.values)
        if self._bar is not None and self._drafting():
            with self._bar.quietly():  # the colour bar follows at the release
                self.image.image.set_clim(*self._range())
        else:
            self.image.image.set_clim(*self._range())
        segments = self._segments()
        self.contours.set_segments(segments)
        self.triangle.update(self.shown_xy)
        self._place_level_labels(segments)

    def _place_level_labels(self, segments) -> None:
        """The values of the :func:`labelled` contour lines, each on its line inside the
        grid, off the triangle's edges, dots and vertex labels and off the other values,
        outside the triangle where it can be (it hides no pixel there); a line with no
        such place goes without. ``labels_placed``: how many found a place (the numbers
        beside the figure promise values on the lines only where some did)."""
        for label in self.level_labels:
            label.set_visible(False)
        self.labels_placed = 0
        if not segments:
            return
        ax, levels = self.ax, self.levels
        scale = self.fig.dpi / 72.0
        triangle = ax.transData.transform(self.shown_xy)
        dot = self.triangle.vertices.get_markersize() / 2 * scale
        taken = [*self.triangle.label_boxes]
        frame = ax.bbox.extents
        texts = level_text(levels)
        for label, segment, text in zip(self.level_labels,
                                        np.asarray(segments)[labelled(levels)],
                                        np.asarray(texts)[labelled(levels)]):  # fmt: skip
            size = label.get_fontsize() * scale
            half = (0.32 * size * len(text) + 0.3 * size, 0.75 * size)  # digits, padded box
            at = place_on_line(ax.transData.transform(segment), half, frame=frame,
                               triangle=triangle, labels=np.reshape(taken, (-1, 4)),
                               dots=boxes_around(triangle, (dot, dot)))  # fmt: skip
            if at is None:
                continue
            label.set_text(text)
            label.set_position(ax.transData.inverted().transform(at))
            label.set_visible(True)
            taken.append(boxes_around(at, half)[0])
            self.labels_placed += 1

    def _info_html(self) -> str:
        s = self.system
        xy, f = self.shown_xy, self.shown_f
        rows = "".join(
            f"<tr><td>[{x:.2f}</td><td>{y:.2f}</td><td>1]</td><td>&nbsp;=&nbsp;{v:.2f}</td></tr>"
            for (x, y), v in zip(xy, f)
        )
        # the table ends its own line: a <br> after it left an empty line (one row less)
        # a gap between the columns, whatever the page's table style: two-digit values ran
        # into the next column ("[5.00 12.00 1]", review r65 03-2)
        system = ("<b>3 × 3 system</b> (rows v1, v2, v3) · (g_x, g_y, g_0) = f:"
                  f"<table style='font-family:monospace; font-size:{INFO_SIZE}; "
                  f"border-collapse:separate; border-spacing:0.8em 0'>{rows}</table>")  # fmt: skip
        parts = []
        if "g" not in s:
            # the lesson's text (03, section 5) promises both: C = 0 and no M (review r143 03-9)
            parts.append(f"<b>zero area</b>: the three points are on one line, so C = 2 × signed "
                         f"area = {s['area2'] + 0.0:.3f}, M (which carries 1/C) does not exist, "
                         "and there is no plane")  # fmt: skip
            return INFO_DIV + system + "<br>".join(parts) + "</div>"
        (m00, m01), (m10, m11) = s["M"]
        gx, gy, g0 = s["g"]
        A, B, C, D = s["ABCD"]
        levels = self.levels
        if len(levels) > 1:
            step = level_text([0.0, levels[1] - levels[0]])[1]
            contours = (f"contour lines (dashed) at f = {', '.join(level_text(levels))} "
                        f"(steps of {step}; {self._values_shown()})")  # fmt: skip
        elif len(levels) == 1:
            contours = f"contour line (dashed) at f = {level_text(levels)[0]}"
        else:
            contours = "contour lines: none (f is constant)"
        g_r, n4 = s["g_recentred"], fixed  # n4(v): four decimals, never "-0.0000"
        parts += [
            contours,
            f"solution: g_x = {n4(gx)}, g_y = {n4(gy)}, g_0 = {n4(g0)}",
            f"<b>M</b> = [[{n4(m00)}, {n4(m01)}], [{n4(m10)}, {n4(m11)}]] (once per triangle)",
            f"M · (f2 − f1, f3 − f1) = ({n4(g_r[0])}, {n4(g_r[1])}) = (g_x, g_y)",
            f"<b>A, B, C, D</b> = {fixed(A, 3)}, {fixed(B, 3)}, {fixed(C, 3)}, {fixed(D, 3)} "
            f"(C = 2 × signed area = {fixed(s['area2'], 3)})",
            f"dx = −A/C = {n4(-A / C)}, dy = −B/C = {n4(-B / C)}",
        ]
        return INFO_DIV + system + "<br>".join(parts) + "</div>"

    def _values_shown(self) -> str:
        """Where the contour lines' values stand, as the picture has them: on the lines, on
        some, or nowhere (review r226 W1: on a sliver the lines pack into a band a pixel wide
        where no value fits, and the numbers still said "values on the lines")."""
        wanted = int(labelled(self.levels).sum())
        placed = getattr(self, "labels_placed", wanted)
        if placed >= wanted:
            return "values on the lines"
        if placed:
            return "values on the lines where they fit"
        return "the lines too close together here for their values"

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_

    def close(self) -> None:
        """Close every widget of the explorer."""
        self.display.close()
        close_tree(self.widget)


@contextmanager
def _widest_ticks(bar):
    """Within: every tick label of the colour bar ``bar`` (None: no change) reads
    :data:`WIDEST_TICK`."""
    if bar is None:
        yield
        return
    formatter = bar.formatter
    bar.formatter = FuncFormatter(lambda value, pos: WIDEST_TICK)
    try:
        yield
    finally:
        bar.formatter = formatter
