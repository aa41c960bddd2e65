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
    xlim: tuple | None = None  # fixed cost limits (None: each update fits its costs)


def shown_y(row, y: str, art) -> float:
    """Where ``row`` is drawn: its error, or the floor when it counts as exact."""
    return art.floor if row[y] < EXACT_BELOW else row[y]


def error_floor(rows, y: str = "error") -> float:
    """Where exact (zero-error) rows are drawn: a tenth of the smallest non-zero error."""
    nonzero = [r[y] for r in rows if r[y] >= EXACT_BELOW]
    return min(nonzero) / 10 if nonzero else 1.0


def plot_pareto(ax, rows, x: str, *, y: str = "error", xlabel: str = "", ylabel: str = "",
                title: str = "", short=None, logx: bool = True,
                xlim: tuple | None = None) -> ParetoArtists:  # fmt: skip
    """Draw ``rows`` as error ``y`` against cost ``x`` with their Pareto front.

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
    xlim : (float, float), optional
        The cost axis' limits at every update (e.g. :func:`cost_limits` of every cost a
        widget can show, so that its layout and ticks never change); default: fitted to the
        costs of each update.

    Returns
    -------
    ParetoArtists
        Update it with :func:`update_pareto` when the costs change.
    """
    short = short or (lambda name: name)
    floor = error_floor(rows, y)
    points, labels = {}, {}
    for r in rows:
        (points[r["variant"]],) = ax.plot([], [], ls="none", ms=11, marker="o")
        labels[r["variant"]] = ax.annotate(short(r["variant"]), (0, 0), textcoords="offset points",
                                           xytext=(8, 6), fontsize=13)  # fmt: skip
    (line,) = ax.step([], [], where="post", color=COLORS["outside"], lw=2.5, label="Pareto front")
    ax.axhline(floor, color="gray", ls="--", lw=1)
    ax.text(0.01, floor, " 0 (exact)", transform=ax.get_yaxis_transform(), va="bottom",
            fontsize=12, color="gray")  # fmt: skip
    ax.set(xscale="log" if logx else "linear", yscale="log", xlabel=xlabel, ylabel=ylabel,
           title=title)  # fmt: skip
    art = ParetoArtists(points, line, labels, floor, [], short, xlim)
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
    scale break (review r6, 06-2). Minor ticks keep their marks.
    """
    yaxis = ax.yaxis
    major = formatter if formatter is not None else yaxis.get_major_formatter()
    minor = yaxis.get_minor_formatter()
    yaxis.set_major_locator(_MajorAboveFloor(yaxis.get_major_locator(), floor))
    yaxis.set_major_formatter(_AboveFloor(major, floor))
    yaxis.set_minor_formatter(_AboveFloor(minor, floor))


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
    ax.set_xlim(*(art.xlim or cost_limits(allx, log=ax.get_xscale() == "log")))
    ax.set_ylim(ally.min() / 3.0, ally.max() * 3.0)
    spread_labels(ax, [art.labels[r["variant"]] for r in rows])
    art.front = front
    return front


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


#: Where a label may sit relative to its point, in points, tried in this order:
#: up-right, down-right, up-left, down-left.
LABEL_SPOTS = ((1, 1), (1, -1), (-1, 1), (-1, -1))


def spread_labels(ax, labels, gap: float = 6.0) -> None:
    """Move each visible label to the first spot beside its point that overlaps no label
    placed before it (estimated text boxes, no renderer needed, so a widget can call it on
    every update); a label that fits nowhere keeps the up-right spot."""
    to_px = ax.figure.dpi / 72.0
    placed = []
    shown = [lab for lab in labels if lab.get_visible()]
    anchors = {id(lab): ax.transData.transform(lab.xy) for lab in shown}
    for lab in sorted(shown, key=lambda lab: -anchors[id(lab)][1]):  # top first
        size = lab.get_fontsize()
        w, h = 0.6 * size * len(lab.get_text()), 1.2 * size
        x0, y0 = anchors[id(lab)] / to_px  # in points
        for sx, sy in LABEL_SPOTS:
            dx = gap + 2 if sx > 0 else -(gap + 2) - w
            dy = gap if sy > 0 else -gap - h
            box = (x0 + dx, y0 + dy, x0 + dx + w, y0 + dy + h)
            if not any(_overlap(box, other) for other in placed):
                break
        else:
            dx, dy = gap + 2, gap
            box = (x0 + dx, y0 + dy, x0 + dx + w, y0 + dy + h)
        placed.append(box)
        lab.set_position((dx, dy))


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]
