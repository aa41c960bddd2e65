"""Line plots: the diamond rule over the pixel grid, a line's steps, and colour buffers.

Every function takes an Axes and returns its artists (lessons 12a and 12b):

- :func:`plot_diamonds` -- the diamonds |x - (j + ½)| + |y - (i + ½)| < ½ of the pixels a line
  passes, lit ones filled, the one p1 ends in hatched (left to the next segment), the segment
  itself with its snapped end points;
- :class:`LineView` -- a traced line step by step: ``show_step(k)`` changes the data of the
  existing artists (lit-so-far image, the current column or row, the caption), never redraws;
- :func:`plot_rgba` -- an (H, W, 4) colour buffer as displayed (opaque), or over a
  checkerboard where its stored alpha is the point (:func:`rgba_shown`).

Everything drawn comes from the fill's :class:`~teachraster.core.line_trace.LineTrace`
(the lit pixels, the candidates and their states); nothing is recomputed here.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.patches import Rectangle

from ..core.fill import Fill
from ..core.line_rules import ENDS_INSIDE, LIT, MISSED
from ..core.line_trace import SETUP, LineTrace
from .common import Artists, fs, label_box, lw, ms, pixel_axes, set_image, show_image
from .style import COLORS


def as_line_trace(obj) -> LineTrace:
    """The LineTrace of a line fill (``rasterize_line(..., trace=True)``) or the trace itself."""
    if isinstance(obj, LineTrace):
        return obj
    if isinstance(obj, Fill) and isinstance(obj.trace, LineTrace):
        return obj.trace
    raise TypeError("needs tr.rasterize_line(..., trace=True) or its LineTrace")


def _diamond(row: int, col: int) -> np.ndarray:
    cx, cy = col + 0.5, row + 0.5
    return np.array([[cx, cy - 0.5], [cx + 0.5, cy], [cx, cy + 0.5], [cx - 0.5, cy]])


@dataclass
class DiamondArtists(Artists):
    """What :func:`plot_diamonds` drew."""

    grid: list
    lit: PolyCollection
    ends: PolyCollection
    missed: PolyCollection
    segment: object
    points: object


def plot_diamonds(ax, line, *, grid: bool = True, tested: str = "all") -> DiamondArtists:
    """The diamond-exit rule drawn: every candidate pixel's diamond (lit: filled; p1's own:
    hatched; missed: outlined), the segment p0 → p1 and its end points.

    ``line`` is a traced diamond-rule line (``tr.rasterize_line(..., trace=True)``).
    ``tested`` chooses the missed diamonds drawn: ``"all"`` every one the walk tested (its
    window of candidates, an internal of the simulator), ``"near"`` those the line comes near
    (:meth:`~teachraster.core.line_trace.LineTrace.near`, what the player and the explorer
    draw), ``"ties"`` only those that lost a tie (the line runs through their corner: the ones
    the rule itself had to decide), ``"none"``.
    """
    trace = as_line_trace(line)
    if trace.steps is None:
        raise ValueError("plot_diamonds draws one-pixel lines (line_width=1)")
    if tested not in ("all", "near", "ties", "none"):
        raise ValueError(f"tested must be 'all', 'near', 'ties' or 'none'; got {tested!r}")
    width, height = trace.size
    pixel_axes(ax, width, height)
    lines = []
    if grid:
        for x in range(width + 1):
            lines.append(ax.axvline(x, color=COLORS["grid"], lw=lw(0.4), zorder=0))
        for y in range(height + 1):
            lines.append(ax.axhline(y, color=COLORS["grid"], lw=lw(0.4), zorder=0))
    s = trace.steps
    polys = {state: [_diamond(r, c) for r, c, st in zip(s.rows, s.cols, s.state) if st == state]
             for state in (LIT, ENDS_INSIDE)}  # fmt: skip
    which = {"all": True, "near": trace.near(), "ties": s.tie, "none": False}[tested]
    shown = (s.state == 0) & which
    polys[0] = [_diamond(r, c) for r, c in zip(s.rows[shown], s.cols[shown])]
    lit = PolyCollection(polys[LIT], facecolor=COLORS["fill"], edgecolor=COLORS["edge"],
                         linewidth=lw(0.6), zorder=1)  # fmt: skip
    ends = PolyCollection(polys[ENDS_INSIDE], facecolor="none", edgecolor=COLORS["current"],
                          hatch="///", linewidth=lw(0.8), zorder=1)  # fmt: skip
    missed = PolyCollection(polys[0], facecolor="none", edgecolor=COLORS["centre"],
                            linewidth=lw(0.4), linestyle=":", zorder=1)  # fmt: skip
    for coll in (lit, ends, missed):
        ax.add_collection(coll)
    xs, ys = (trace.p0[0], trace.p1[0]), (trace.p0[1], trace.p1[1])
    (segment,) = ax.plot(xs, ys, color=COLORS["edge"], lw=lw(1.2), zorder=3)
    (points,) = ax.plot(xs, ys, "o", color=COLORS["edge"], ms=ms(0.8), zorder=4)
    return DiamondArtists(lines, lit, ends, missed, segment, points)


@dataclass
class LineView(Artists):
    """A traced line shown step by step (``show_step(k)`` updates the artists in place).

    Build it with :meth:`create`; ``image`` holds the pixels lit so far, ``current`` the
    column (x-major) or row the step works on, ``segment`` the line, ``caption`` the step's
    caption from the trace. Under the diamond rule ``diamonds`` draws the diamonds the
    caption speaks of: those the steps so far tested (dotted), lit (outlined) or ended in
    (hatched), and the current step's (thick); other rules draw none. Under Bresenham
    ``midpoint`` (gap, midpoint, crossing) marks the test of the step's error term D
    (:meth:`~teachraster.core.line_trace.LineTrace.midpoint`): the midpoint between the next
    column's two candidates (open), where the line crosses that column (filled), and the gap
    between them, D / (2·dmajor) px.
    """

    image: object
    current: Rectangle
    segment: object
    caption: object
    trace: LineTrace | None = None
    step: int = -1
    diamonds: dict | None = None
    midpoint: object = None

    @classmethod
    def create(cls, ax, line, step: int = -1) -> LineView:
        """Draw ``line`` (a traced line fill) on ``ax`` at ``step``."""
        trace = as_line_trace(line)
        width, height = trace.size
        pixel_axes(ax, width, height)
        # the pixel grid, over the lit pixels: every rule's steps are counted in pixels
        for x in range(width + 1):
            ax.axvline(x, color=COLORS["grid"], lw=lw(0.4), zorder=1.5)
        for y in range(height + 1):
            ax.axhline(y, color=COLORS["grid"], lw=lw(0.4), zorder=1.5)
        image = show_image(ax, np.where(trace.coverage_at(step), 1.0, np.nan),
                           cmap=_one_colour(), vmin=0, vmax=1, zorder=1)  # fmt: skip
        current = Rectangle((0, 0), 1, height, facecolor="none", edgecolor=COLORS["current"],
                            linewidth=lw(1.5), zorder=2)  # fmt: skip
        ax.add_patch(current)
        xs, ys = (trace.p0[0], trace.p1[0]), (trace.p0[1], trace.p1[1])
        (segment,) = ax.plot(xs, ys, color=COLORS["edge"], lw=lw(1.2), zorder=3)
        caption = ax.text(0.0, -0.02, "", transform=ax.transAxes, va="top", ha="left",
                          fontsize=fs(0.8), bbox=label_box())  # fmt: skip
        diamonds = {name: PolyCollection([], facecolor="none", zorder=2,
                                         **{**style, "linewidth": lw(style["linewidth"])})
                    for name, style in _DIAMOND_STYLES.items()}  # fmt: skip
        for coll in diamonds.values():
            ax.add_collection(coll)
        # Bresenham's test: the midpoint (open) and the line's crossing (filled) of the next
        # column, joined by the gap the error term D measures (D = 2·dmajor·gap)
        (gap,) = ax.plot([], [], color=COLORS["current"], lw=lw(1.2), zorder=4)
        (mid,) = ax.plot([], [], "o", mfc="white", mec=COLORS["current"], mew=lw(0.8),
                         ms=ms(1.0), zorder=5)  # fmt: skip
        (cross,) = ax.plot([], [], "o", color=COLORS["edge"], ms=ms(0.7), zorder=6)
        view = cls(image, current, segment, caption, trace, diamonds=diamonds,
                   midpoint=(gap, mid, cross))  # fmt: skip
        view.show_step(step)
        return view

    def show_step(self, k: int) -> None:
        """Show the line after step ``k`` (negative counts from the end)."""
        trace = self.trace
        k = trace.index(k)
        self.step = k
        set_image(self.image, np.where(trace.coverage_at(k), 1.0, np.nan))
        step = trace.step(k)
        width, height = trace.size
        if step.kind == "column":
            self.current.set_bounds(step.col, 0, 1, height)
        elif step.kind == "row":
            self.current.set_bounds(0, step.row, width, 1)
        self.current.set_visible(step.kind in ("column", "row"))
        self.caption.set_text(fit_caption(self.caption, step.caption))
        if self.diamonds is not None:
            for name, polys in _diamonds_at(trace, k).items():
                self.diamonds[name].set_verts(polys)
        if self.midpoint is not None:
            gap, mid, cross = self.midpoint
            test = trace.midpoint(k)  # None unless Bresenham's work step
            (mx, my), (lx, ly) = test if test is not None else ((np.nan, np.nan),) * 2
            gap.set_data([mx, lx], [my, ly])
            mid.set_data([mx], [my])
            cross.set_data([lx], [ly])


#: How :class:`LineView` draws the diamonds of the diamond rule (line widths in units of the
#: style's line width).
_DIAMOND_STYLES = {
    "tested": dict(edgecolor=COLORS["centre"], linewidth=0.4, linestyle=":"),
    "lit": dict(edgecolor=COLORS["edge"], linewidth=0.9),
    "ends": dict(edgecolor=COLORS["current"], linewidth=0.8, hatch="///"),
    "now": dict(edgecolor=COLORS["current"], linewidth=1.8),
}


def _diamonds_at(trace: LineTrace, k: int) -> dict:
    """The diamonds to draw once steps 0..k have run, by :data:`_DIAMOND_STYLES` name: every
    candidate a finished step tested that the line comes near (:meth:`LineTrace.near`, as
    the diamond explorer draws them), by its state, and those of step k itself. The walk's
    other candidates, rows away from the line, are left out (review r262 FIG1: the player
    outlined five rows of a column, as if the rule tested them all)."""
    out = {name: [] for name in _DIAMOND_STYLES}
    s = trace.steps
    if trace.rule != "diamond" or s is None:
        return out
    work = trace.index(k) - len(SETUP)
    names = {MISSED: "tested", LIT: "lit", ENDS_INSIDE: "ends"}
    for r, c, st, at, near in zip(s.rows, s.cols, s.state, s.step, trace.near()):
        if at <= work and near:
            out[names[int(st)]].append(_diamond(r, c))
            if at == work:
                out["now"].append(_diamond(r, c))
    return out


def _one_colour():
    from matplotlib.colors import ListedColormap

    return ListedColormap([COLORS["fill"]])


@dataclass
class RGBAArtists(Artists):
    """What :func:`plot_rgba` drew: the checkerboard and the colour image over it."""

    checker: object
    image: object


def rgba_shown(color, *, premultiplied: bool = False, srgb: bool = False, view="displayed"):
    """The (H, W, 4) image :func:`plot_rgba` shows of a colour buffer ``color``.

    ``view="displayed"``: the RGB written, opaque (alpha 1), as a window shows its colour
    buffer: a display ignores the stored alpha, so this is the picture rendered.
    ``view="alpha"``: the colour with its stored alpha, for drawing over a checkerboard (what
    a compositor or a later pass reading alpha would make of it); a premultiplied colour is
    divided by its alpha first. ``srgb``: encode linear values with ``linear_to_srgb``.
    Values are clipped to [0, 1] for display only.
    """
    from ..core.blend_factors import linear_to_srgb

    if view not in ("displayed", "alpha"):
        raise ValueError(f"view must be 'displayed' or 'alpha', got {view!r}")
    color = np.asarray(color, dtype=np.float64)
    if color.ndim != 3 or color.shape[2] != 4:
        raise ValueError(f"color must have shape (H, W, 4), got {color.shape}")
    rgb, alpha = color[..., :3], np.clip(color[..., 3:], 0, 1)
    if view == "displayed":
        alpha = np.ones_like(alpha)  # the display shows the RGB stored, whatever the alpha
    elif premultiplied:
        with np.errstate(invalid="ignore", divide="ignore"):
            rgb = np.where(alpha > 0, rgb / alpha, 0.0)
    rgb = np.clip(rgb, 0, 1)
    if srgb:
        rgb = linear_to_srgb(rgb)
    return np.concatenate([rgb, alpha], axis=2)


def plot_rgba(
    ax, color, *, premultiplied: bool = False, srgb: bool = False, view: str = "displayed"
) -> RGBAArtists:
    """An (H, W, 4) colour buffer (``frame.color``): as displayed, or over a checkerboard.

    ``view="displayed"`` (default) shows the RGB written, opaque: what the frame looks like on
    screen. ``view="alpha"`` draws the colour with its stored alpha over a grey checkerboard,
    where alpha itself is the point. ``premultiplied``, ``srgb``: see :func:`rgba_shown`.
    """
    image = rgba_shown(color, premultiplied=premultiplied, srgb=srgb, view=view)
    height, width = image.shape[:2]
    pixel_axes(ax, width, height)
    ii, jj = np.indices((height, width))
    board = np.where((ii // 2 + jj // 2) % 2 == 0, 0.8, 0.6)[..., None] * np.ones(3)
    checker = ax.imshow(board, extent=(0, width, height, 0), interpolation="nearest", zorder=0)
    checker.set_visible(view == "alpha")
    shown = ax.imshow(image, extent=(0, width, height, 0), interpolation="nearest", zorder=1)
    return RGBAArtists(checker, shown)


def fit_caption(text, caption: str) -> str:
    """``caption`` wrapped to the width of the Axes of ``text`` (a matplotlib Text under them).

    matplotlib's own ``wrap=True`` wraps at the figure's edge: a diamond step's caption ran
    past the axes to the edge of the notebook's output (review r101 12a-C).
    """
    ax = text.axes
    width_pt = ax.get_position(original=False).width * ax.figure.get_figwidth() * 72
    chars = max(20, int(width_pt / (0.6 * text.get_fontsize())))  # about 0.6 em a character
    return "\n".join(textwrap.fill(line, chars) for line in caption.split("\n"))
