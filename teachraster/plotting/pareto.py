"""Error against cost with its Pareto front: lesson 06's one chart, and its widget's.

A variant is on the **Pareto front** when no other is at least as cheap and at least as
accurate, and better on one of the two (``study.bench.FRONT_DEFINITION``, one wording). The plot
puts each variant's error (down is better, log scale) against a cost (left is cheaper), joins
the front with a step line and labels each point beside it. Exact variants (error 0, or below
``EXACT_BELOW``: float64 rounding, not a method's error) cannot sit on a log axis: they are drawn
on a dashed floor line labelled "0 (exact)", and no error tick is labelled at or below it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.artist import Artist
from matplotlib.ticker import Formatter, Locator, NullFormatter

from ..study.bench.report import pareto_front
from .style import COLORS

#: Errors below this count as exact (float64 rounding of an exact method), drawn on the floor.
EXACT_BELOW = 1e-9


@dataclass
class ParetoArtists:
    """What :func:`plot_pareto` drew: one marker per variant, the front line, the labels."""

    points: dict
    front_line: object
    labels: dict
    floor: float
    front: list
    short: object = None
    xlim: object = None  # cost limits: fixed, a function of the costs, or None (cost_limits)
    spreader: object = None  # places the labels again at each draw (_LabelSpreader)
    hollow_on_line: bool = False  # off-front points on the front line drawn hollow over it


def shown_y(row, y: str, art) -> float:
    """Where ``row`` is drawn: its error, or the floor when it counts as exact."""
    return art.floor if row[y] < EXACT_BELOW else row[y]


def error_floor(rows, y: str = "error") -> float:
    """Where exact (zero-error) rows are drawn: a tenth of the smallest non-zero error."""
    nonzero = [r[y] for r in rows if r[y] >= EXACT_BELOW]
    return min(nonzero) / 10 if nonzero else 1.0


def plot_pareto(ax, rows, x: str, *, y: str = "error", xlabel: str = "", ylabel: str = "",
                title: str = "", short=None, logx: bool = True, xlim=None,
                hollow_on_line: bool = False) -> ParetoArtists:  # fmt: skip
    """Draw ``rows`` as error ``y`` against cost ``x`` with their Pareto front.

    The point labels and "0 (exact)" are the style's "small" size (15 pt in the classroom
    style: 12 px or more with the figure shrunk to a 556-px column at 1024 x 768, review r20).

    Parameters
    ----------
    ax : matplotlib Axes
    rows : list of dict
        One dict per variant, with ``"variant"``, ``x`` and ``y``.
    x, y : str
        Keys of the cost and the error.
    short : callable, optional
        Maps a variant name to the label drawn beside its point.
    logx : bool
        Log scale for the cost.
    xlim : (float, float) or callable, optional
        The cost axis' limits at every update (e.g. :func:`cost_limits` of every cost a
        widget can show, so that its layout and ticks never change), or a function of each
        update's costs returning them; default: :func:`cost_limits` of each update's costs.
    hollow_on_line : bool
        Draw an off-front point that the front's step line runs through (it ties a front
        point on cost and is less accurate, or on error and costs more) hollow, over the
        line, so that it does not read as on the front.

    Returns
    -------
    ParetoArtists
        Update it with :func:`update_pareto` when the costs change.
    """
    short = short or (lambda name: name)
    floor = error_floor(rows, y)
    # the scales first, on an axes with no data yet: turned log after the floor line, the
    # autoscale saw one y value, the floor, and at a decade (10, 0.01: lesson 06's explorer)
    # matplotlib's log limits of it came out equal ("identical low and high ylims")
    ax.set(xscale="log" if logx else "linear", yscale="log", xlabel=xlabel, ylabel=ylabel,
           title=title)  # fmt: skip
    points, labels = {}, {}
    for r in rows:
        (points[r["variant"]],) = ax.plot([], [], ls="none", ms=11, marker="o")
        labels[r["variant"]] = ax.annotate(short(r["variant"]), (0, 0), textcoords="offset points",
                                           xytext=(8, 6), fontsize="small")  # fmt: skip
    (line,) = ax.step([], [], where="post", color=COLORS["outside"], lw=2.5, label="Pareto front")
    ax.axhline(floor, color="gray", ls="--", lw=1)
    exact = ax.text(0.01, floor, " 0 (exact)", transform=ax.get_yaxis_transform(),
                    va="bottom", fontsize="small", color="gray")  # fmt: skip
    art = ParetoArtists(points, line, labels, floor, [], short, xlim,
                        hollow_on_line=hollow_on_line)  # fmt: skip
    art.spreader = ax.add_artist(_LabelSpreader([labels[r["variant"]] for r in rows], [exact]))
    ax.xaxis.set_minor_formatter(NullFormatter())  # no crowded minor tick labels
    floor_ticks(ax, floor)
    update_pareto(ax, art, rows, x, y=y)
    return art


def floor_ticks(ax, floor: float, formatter=None) -> None:
    """Label the error axis above the "0 (exact)" floor only (``formatter``: the major tick
    labels' format, default the axis' own).

    The floor is a stand-in for zero on a log axis: a tick labelled 20 below a floor drawn at
    45 would read as "less than exact", and points on the floor as 45 wrong pixels. Major ticks
    up to twice the floor are dropped, not left bare: a decade mark without its number read as a
    scale break (review r6, 06-2). Minor ticks start at the lowest major tick: marks between
    the floor and it, or under the floor, suggested values below "0" (review r56 06-4).
    """
    yaxis = ax.yaxis
    major = formatter if formatter is not None else yaxis.get_major_formatter()
    minor = yaxis.get_minor_formatter()
    yaxis.set_major_locator(_MajorAboveFloor(yaxis.get_major_locator(), floor))
    yaxis.set_major_formatter(_AboveFloor(major, floor))
    yaxis.set_minor_formatter(_AboveFloor(minor, floor))
    yaxis.set_minor_locator(_MinorAboveMajor(yaxis.get_minor_locator(), floor))


class _MajorAboveFloor(Locator):
    """``base``'s tick positions above twice ``floor`` (where :class:`_AboveFloor` labels)."""

    def __init__(self, base, floor: float) -> None:
        self.base, self.floor = base, floor

    def set_axis(self, axis) -> None:
        super().set_axis(axis)
        self.base.set_axis(axis)

    def tick_values(self, vmin, vmax):
        return self._above(self.base.tick_values(vmin, vmax))

    def __call__(self):
        return self._above(self.base())

    def _above(self, locs):
        locs = np.asarray(locs, dtype=float)
        return locs[locs > 2.0 * self.floor]


class _MinorAboveMajor(_MajorAboveFloor):
    """``base``'s minor tick positions from the lowest major tick above twice ``floor`` up
    (above twice ``floor`` when no major tick is in view)."""

    def _above(self, locs):
        locs = np.asarray(locs, dtype=float)
        majors = np.asarray(self.axis.get_majorticklocs(), dtype=float)
        lo, hi = sorted(self.axis.get_view_interval())
        majors = majors[(majors > 2.0 * self.floor) & (majors >= lo) & (majors <= hi)]
        start = majors.min() if majors.size else 2.0 * self.floor
        return locs[locs >= start]


class _AboveFloor(Formatter):
    """``base``'s tick labels above 1.5 times ``floor``, none at or below it. Delegates
    ``set_locs``, so a log formatter still chooses which minor ticks to label."""

    def __init__(self, base, floor: float) -> None:
        self.base, self.floor = base, floor

    def set_axis(self, axis) -> None:
        super().set_axis(axis)
        self.base.set_axis(axis)

    def set_locs(self, locs) -> None:
        self.base.set_locs(locs)

    def __call__(self, x, pos=None) -> str:
        return "" if x <= 2.0 * self.floor else self.base(x, pos)


def update_pareto(ax, art: ParetoArtists, rows, x: str, *, y: str = "error") -> list:
    """Move the points, labels and front of ``art`` to the costs ``x`` of ``rows``."""
    front = pareto_front(rows, x=x, y=y)
    on = {r["variant"] for r in front}
    for r in rows:
        yy = shown_y(r, y, art)
        p = art.points[r["variant"]]
        p.set_data([r[x]], [yy])
        front_member = r["variant"] in on
        p.set_color(COLORS["outside"] if front_member else COLORS["edge"])
        p.set_alpha(1.0 if front_member else 0.45)
        p.set_zorder(3 if front_member else 2)  # a front point is never overprinted in grey
        p.set_markerfacecolor(None)  # (back to the colour's, after a hollow one below)
        p.set_markeredgecolor(None)
        if art.hollow_on_line and not front_member and _on_step_line(r[x], yy, front, x, y, art):
            # an off-front point the front's step line runs through (a cost tie that is less
            # accurate: N=2 at divide 1; an error tie that costs more: lesson 06's window
            # float32) read as on the front: drawn over the line, hollow,
            # its ring the grey of a translucent off-front point (review r22, 06-8)
            p.set(alpha=1.0, zorder=3.5, markerfacecolor="white", markeredgecolor=OFF_RING,
                  markeredgewidth=2.5)  # fmt: skip
        else:
            p.set_markeredgewidth(None)
        label = art.labels[r["variant"]]
        label.xy = (r[x], yy)
        label.set_alpha(1.0 if front_member else 0.6)
        # points that coincide share one label: the first names them all
        same = [q["variant"] for q in rows if (q[x], shown_y(q, y, art)) == (r[x], yy)]
        label.set_visible(same[0] == r["variant"])
        label.set_text(" = ".join(art.short(v) for v in same))
    xs = [r[x] for r in front]
    shown = [art.floor if r[y] < EXACT_BELOW else r[y] for r in front]
    art.front_line.set_data(xs, shown)
    allx = [r[x] for r in rows]
    ally = np.array([art.floor if r[y] < EXACT_BELOW else r[y] for r in rows], dtype=float)
    limits = art.xlim(allx) if callable(art.xlim) else art.xlim
    ax.set_xlim(*(limits or cost_limits(allx, log=ax.get_xscale() == "log")))
    ax.set_ylim(ally.min() / 3.0, ally.max() * 3.0)
    if art.spreader is not None:
        art.spreader.spread()
    else:
        spread_labels(ax, [art.labels[r["variant"]] for r in rows])
    art.front = front
    return front


#: The ring of an off-front point drawn hollow over the front line: the grey a 0.45-alpha
#: black marker shows on white.
OFF_RING = "#8c8c8c"


def _on_step_line(px: float, py: float, front, x: str, y: str, art) -> bool:
    """Whether the point (``px``, ``py``) lies on the front's step line (drawn
    ``where="post"``: across at each front point's error, then down at the next one's cost)."""
    xs = [r[x] for r in front]
    ys = [shown_y(r, y, art) for r in front]
    for (x0, y0), (x1, y1) in zip(zip(xs, ys), zip(xs[1:], ys[1:])):
        across = np.isclose(py, y0) and x0 <= px <= x1
        down = np.isclose(px, x1) and min(y0, y1) <= py <= max(y0, y1)
        if across or down:
            return True
    return False


def cost_limits(costs, *, log: bool = True) -> tuple[float, float]:
    """The cost axis' limits for ``costs``, with room on the right for the points' labels.

    >>> cost_limits([2.0, 10.0])
    (1.25, 30.0)
    """
    costs = np.asarray(costs, dtype=float)
    lo, hi = float(costs.min()), float(costs.max())
    if log:
        return lo / 1.6, hi * 3.0
    span = hi - lo or 1.0
    return lo - 0.08 * span, hi + 0.6 * span


#: Where a label may sit relative to its point, tried in this order: up-right, down-right,
#: up-left, down-left, then centred right, left, above and below.
LABEL_SPOTS = ((1, 1), (1, -1), (-1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1))
#: How far out each spot is tried, in gaps: beside the point first, then further from it.
LABEL_REACH = (1.0, 2.0, 3.5)
#: Room a label keeps from every point's marker (its own too), and from the Axes' frame, in
#: points.
LABEL_PAD = 1.5
#: Placements the search tries at most before it settles for the least overlap.
SEARCH_LIMIT = 3000


class _LabelSpreader(Artist):
    """Spreads the labels again at every draw, before they are drawn: a layout engine (the
    lessons' ``layout="constrained"``) moves the Axes only then, so a label placed inside
    the Axes before it can end up outside (lesson 06's edge-function chart grew to 951 px).
    Labels a caller has moved since (lesson 06 places its depth labels itself) are left
    alone. Drawn first (zorder 0), invisible, and outside the layout."""

    def __init__(self, labels, avoid=()) -> None:
        super().__init__()
        self.labels, self.avoid = list(labels), list(avoid)
        self.spots: dict = {}  # id(label) -> the offset this spreader last gave it
        self.set_zorder(0)
        self.set_in_layout(False)

    def spread(self, renderer=None) -> None:
        spread_labels(self.axes, self.labels, avoid=self.avoid, renderer=renderer)
        self.spots = {id(lab): lab.get_position() for lab in self.labels}

    def draw(self, renderer) -> None:
        if any(self.spots.get(id(lab)) != lab.get_position() for lab in self.labels):
            return  # moved by the caller: its placement stands
        self.spread(renderer)


def spread_labels(ax, labels, gap: float = 6.0, *, marker: float = 11.0, avoid=(),
                  renderer=None) -> None:  # fmt: skip
    """Place each visible label beside its point: inside the Axes, clear of every point's
    marker (``marker``: its size in points), of the artists in ``avoid`` (the floor's
    "0 (exact)") and of the other labels.

    The spots of :data:`LABEL_SPOTS` are tried at the distances of :data:`LABEL_REACH`; a
    short search (at most :data:`SEARCH_LIMIT` tries) finds one spot per label with no two
    overlapping, the labels taken from the top. Where there is none, each label takes the
    spot that overlaps the others least. Text boxes are measured with ``renderer`` (default:
    the figure's), so a widget can call this on every update without drawing.
    """
    to_px = ax.figure.dpi / 72.0
    if renderer is None:
        renderer = ax.figure._get_renderer()
    shown = [lab for lab in labels if lab.get_visible() and lab.get_text()]
    if not shown:
        return
    ax.get_xlim()  # applies a pending autoscale (transData alone reads the stale limits)
    at = {id(lab): ax.transData.transform(lab.xy) / to_px for lab in labels}  # points
    frame = tuple(np.asarray(ax.bbox.extents) / to_px + [LABEL_PAD, LABEL_PAD, -LABEL_PAD,
                                                          -LABEL_PAD])  # fmt: skip
    reach = marker / 2 + LABEL_PAD
    markers = [(x - reach, y - reach, x + reach, y + reach) for x, y in at.values()
               if np.isfinite(x) and np.isfinite(y)]  # fmt: skip
    if renderer is not None:
        markers += [tuple(np.asarray(a.get_window_extent(renderer).extents) / to_px)
                    for a in avoid if a.get_visible()]  # fmt: skip
    shown.sort(key=lambda lab: -at[id(lab)][1])  # top first
    options = [_label_options(lab, at[id(lab)], gap, reach, frame, markers, renderer, to_px)
               for lab in shown]  # fmt: skip
    picks = _search([[box for box, _ in opts] for opts in options], SEARCH_LIMIT)
    if picks is None:  # crowded beyond any clean placement: the least overlap, greedily
        picks, placed = [], []
        for opts in options:
            costs = [sum(_overlap_area(box, b) for b in placed) for box, _ in opts]
            picks.append(int(np.argmin(costs)))
            placed.append(opts[picks[-1]][0])
    for lab, opts, k in zip(shown, options, picks):
        lab.set_position(opts[k][1])


def _label_options(lab, anchor, gap, reach, frame, markers, renderer, to_px) -> list:
    """[(box in points, offset)] for ``lab`` at its point ``anchor`` (points): the spots
    inside ``frame`` and clear of every marker box, in order of preference; when there is
    none, the one spot that breaks those rules least."""
    w, h, left, below = _text_size(lab, renderer, to_px)
    x0, y0 = anchor
    spots = []
    for r in LABEL_REACH:
        side = r * gap + 2  # beside the marker: clear of its radius (5.5 pt) at the first reach
        up = r * gap
        for sx, sy in LABEL_SPOTS:
            bx = side if sx > 0 else -side - w if sx < 0 else -w / 2  # the box's left ...
            rise = up if sx else side  # (straight above a point: clear of its marker too)
            by = rise if sy > 0 else -rise - h if sy < 0 else -h / 2  # ... and bottom
            box = (x0 + bx, y0 + by, x0 + bx + w, y0 + by + h)
            spots.append((box, (bx + left, by + below)))  # the text's offset for that box
    fits = [
        s for s in spots if _inside(s[0], frame) and not any(_overlap(s[0], m) for m in markers)
    ]
    if fits:
        return fits
    # nowhere clean: inside the frame if it can be, then over as little marker as can be
    return [min(spots, key=lambda s: (_outside(s[0], frame),
                                      sum(_overlap_area(s[0], m) for m in markers)))]  # fmt: skip


def _text_size(lab, renderer, to_px) -> tuple[float, float, float, float]:
    """Width and height of ``lab``'s text box, and where it starts left of and below the
    text's anchor (its position beside the point), in points."""
    if renderer is None:  # a canvas without a renderer: estimated from the font size
        size = lab.get_fontsize()
        return 0.6 * size * len(lab.get_text()), 1.2 * size, 0.0, 0.25 * size
    box = lab.get_window_extent(renderer)
    anchor = lab.axes.transData.transform(lab.xy) + np.asarray(lab.get_position()) * to_px
    return (box.width / to_px, box.height / to_px, (anchor[0] - box.x0) / to_px,
            (anchor[1] - box.y0) / to_px)  # fmt: skip


def _search(options, limit: int):
    """One index per list of ``options`` (boxes) with no two chosen boxes overlapping,
    preferring earlier options for earlier lists; None if none is found within ``limit``
    tries."""
    picks, placed, tries = [], [], 0

    def place(i: int) -> bool:
        nonlocal tries
        if i == len(options):
            return True
        for k, box in enumerate(options[i]):
            tries += 1
            if tries > limit:
                return False
            if not any(_overlap(box, b) for b in placed):
                picks.append(k)
                placed.append(box)
                if place(i + 1):
                    return True
                picks.pop()
                placed.pop()
        return False

    return picks if place(0) else None


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _overlap_area(a, b) -> float:
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


def _inside(box, frame) -> bool:
    return frame[0] <= box[0] and box[2] <= frame[2] and frame[1] <= box[1] and box[3] <= frame[3]


def _outside(box, frame) -> float:
    """How far ``box`` reaches out of ``frame``, summed over its four sides (points)."""
    return (max(0.0, frame[0] - box[0]) + max(0.0, box[2] - frame[2])
            + max(0.0, frame[1] - box[1]) + max(0.0, box[3] - frame[3]))  # fmt: skip
