"""Small figures of a case for :meth:`Report.plot` (matplotlib is imported only in here,
and only when a report is drawn)."""

from __future__ import annotations

import numpy as np

from .scalars import num

#: Pixel states: right and empty, right and covered, missing, extra.
STATE_COLOURS = ("#ffffff", "#c8c8c8", "#2b7bba", "#d7301f")
STATE_NAMES = ("", "covered", "missing (the rule covers it)", "extra (the rule does not)")
EDGE_COLOUR = "#ff9f1c"


def draw_coverage(ax, case, xy, expected, got, edge, pixel):
    """Pixels of the window coloured by state, the triangle, the deciding edge, the pixel.

    ``got`` None (the function gave no answer): the rule's pixels alone.
    """
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    h, w = expected.shape
    if got is None:
        state = expected.astype(int)
    else:
        state = np.where(expected == got, expected.astype(int), np.where(expected, 2, 3))
    x0, y0 = case.origin
    artists = [
        ax.imshow(
            state,
            cmap=ListedColormap(STATE_COLOURS),
            vmin=0,
            vmax=3,
            extent=(x0, x0 + w, y0 + h, y0),
            interpolation="nearest",
        )
    ]
    ax.set_xticks(np.arange(x0, x0 + w + 1), minor=True)
    ax.set_yticks(np.arange(y0, y0 + h + 1), minor=True)
    ax.grid(which="minor", color="#eeeeee", linewidth=0.5)
    ring = np.vstack([xy, xy[:1]])
    artists += ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    artists += vertex_labels(ax, xy, (w + h) / 40, (x0, y0, w, h))
    if edge is not None:
        a, b = xy[edge], xy[(edge + 1) % 3]
        artists += ax.plot([a[0], b[0]], [a[1], b[1]], color=EDGE_COLOUR, linewidth=3)
    if pixel is not None:
        i, j = pixel
        artists += ax.plot(x0 + j + 0.5, y0 + i + 0.5, "o", mfc="none", mec="black", ms=9)
    # only the states drawn (r6: "missing" listed where no pixel was missing); covered always
    shown = [s for s in (1, 2, 3) if s == 1 or (state == s).any()]
    handles = [Patch(color=STATE_COLOURS[s], label=STATE_NAMES[s]) for s in shown]
    if got is None:
        handles = [Patch(color=STATE_COLOURS[1], label="covered by the rule")]
    # outside the axes, to the right: the legend must never hide a pixel
    legend = ax.legend(
        handles=handles, fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)
    )
    artists.append(legend)
    ax.set_xlim(x0, x0 + w)
    ax.set_ylim(y0 + h, y0)
    plain_ticks(ax)
    ax.set_aspect("equal")
    return artists


def vertex_labels(ax, xy, near: float, window, names=("v1", "v2", "v3")) -> list:
    """Each vertex's name beside it, pushed away from the triangle's centre so that no label
    sits on an edge (back inwards at the border of ``window`` = (x0, y0, w, h), where it would
    leave the picture); vertices closer than ``near`` (px) share one label, "v1, v2, v3"
    (r347 FIG: a 0.04-px triangle printed its three names over each other), and each is a
    dot, so a triangle too small to see still shows where it is."""
    xy = np.asarray(xy, dtype=float)
    centre = xy.mean(axis=0)
    x0, y0, w, h = window
    lo, hi = np.array([x0, y0]) + 2 * near, np.array([x0 + w, y0 + h]) - 2 * near
    artists = ax.plot(xy[:, 0], xy[:, 1], ".", color="black", ms=3)
    done: set[int] = set()
    for k, v in enumerate(xy):
        if k in done:
            continue
        group = [m for m in range(len(xy)) if m not in done and np.hypot(*(xy[m] - v)) < near]
        done.update(group)
        away = v - centre
        norm = np.hypot(*away)
        away = away / norm if norm > 1e-9 else np.array([0.7, -0.7])
        away = np.where(((v < lo) & (away < 0)) | ((v > hi) & (away > 0)), -away, away)
        artists.append(ax.annotate(
            ", ".join(names[m] for m in group), v, xytext=tuple(9 * away * (1, -1)),
            textcoords="offset points", fontsize="x-small", color="black",
            ha="left" if away[0] >= 0 else "right", va="center",
        ))  # fmt: skip
    return artists


def draw_mesh(ax, case, expected, ties) -> list:
    """A case every triangle of which the answer got right (a passing check, r347 FIG): each
    pixel in its triangle's colour, the pixel centres as dots, the centres lying exactly on
    an edge (``ties``, (h, w) bool) ringed, and every triangle's outline and vertices."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    n, h, w = expected.shape
    x0, y0 = case.origin
    palette = ("#ffffff", "#9ecae1", "#fdae6b", "#a1d99b", "#bcbddc", "#fc9272")
    owner = np.zeros((h, w), dtype=int)
    for k in range(n):
        owner[expected[k]] = 1 + k % (len(palette) - 1)
    artists = [ax.imshow(owner, cmap=ListedColormap(palette), vmin=0, vmax=len(palette) - 1,
                         extent=(x0, x0 + w, y0 + h, y0), interpolation="nearest")]  # fmt: skip
    ax.set_xticks(np.arange(x0, x0 + w + 1), minor=True)
    ax.set_yticks(np.arange(y0, y0 + h + 1), minor=True)
    ax.grid(which="minor", color="#eeeeee", linewidth=0.5)
    cy, cx = np.indices((h, w)) + 0.5
    artists += ax.plot(x0 + cx.ravel(), y0 + cy.ravel(), ".", color="#555555", ms=2)
    ti, tj = np.nonzero(ties)
    artists += ax.plot(x0 + tj + 0.5, y0 + ti + 0.5, "o", mfc="none", mec="black", ms=7)
    for xy in case.triangles:
        ring = np.vstack([xy, xy[:1]])
        artists += ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
        if n == 1:
            artists += vertex_labels(ax, xy, (w + h) / 40, (x0, y0, w, h))
    handles = [Patch(color=palette[1 + k % (len(palette) - 1)],
                     label=f"covered by triangle {k}" if n > 1 else "covered")
               for k in range(n)]  # fmt: skip
    handles.append(ax.plot([], [], "o", mfc="none", mec="black", label="centre on an edge")[0])
    artists.append(ax.legend(handles=handles, fontsize="x-small", loc="upper left",
                             bbox_to_anchor=(1.02, 1)))  # fmt: skip
    ax.set_xlim(x0, x0 + w)
    ax.set_ylim(y0 + h, y0)
    plain_ticks(ax)
    if max(w, h) <= 16:  # a small window: a tick on every pixel border
        ax.set_xticks(np.arange(x0, x0 + w + 1))
        ax.set_yticks(np.arange(y0, y0 + h + 1))
    ax.set_aspect("equal")
    return artists


#: The attribute a drawing sets on its axes to have :meth:`.report.Report.plot`'s note (no
#: answer to draw: an endless loop, an exception) set beside them, right, not across them.
NOTE_BESIDE = "teachraster_note_beside"


def note_beside(ax) -> None:
    """Ask for the report's note beside ``ax`` (r214 item 2: over a small equal-aspect panel the
    note's box covered the drawing and its tick labels)."""
    setattr(ax, NOTE_BESIDE, True)


def plain_ticks(ax) -> None:
    """Whole coordinates on both axes, never matplotlib's offset ("+1e5" over ticks 0…12: r64
    01-3, a window 100 000 px from the origin)."""
    from matplotlib.ticker import MaxNLocator, ScalarFormatter

    for axis in (ax.xaxis, ax.yaxis):
        fmt = ScalarFormatter(useOffset=False)
        fmt.set_scientific(False)
        axis.set_major_formatter(fmt)
        axis.set_major_locator(MaxNLocator(nbins=3, integer=True))
    if max(abs(v) for v in (*ax.get_xlim(), *ax.get_ylim())) >= 1e5:  # long labels: tilted
        ax.tick_params(axis="x", labelrotation=30)


def drawable(values, reference) -> np.ndarray:
    """``values`` with what cannot be drawn beside ``reference`` (inf, nan, or a million times
    larger) replaced by nan: the bar or point is left out, the explanation quotes the value."""
    v = np.asarray(values, dtype=float)
    scale = 1e6 * max(1.0, float(np.nanmax(np.abs(np.asarray(reference, dtype=float)), initial=0)))
    with np.errstate(invalid="ignore"):
        return np.where(np.isfinite(v) & (np.abs(v) <= scale), v, np.nan)


def _off_chart(ax, values, drawn) -> list:
    """A note naming the values left out of the chart."""
    left_out = np.asarray(values, dtype=float)[np.isnan(drawn) & ~np.isnan(values)]
    if not left_out.size:
        return []
    text = "yours, off the chart: " + ", ".join(f"{v:.3g}" for v in left_out[:3])
    return [ax.text(0.02, 0.98, text, transform=ax.transAxes, va="top", fontsize="x-small")]


def draw_values(ax, labels, expected, got):
    """Expected and got side by side as bars (``got`` may be None: nothing to show yet)."""
    x = np.arange(len(labels))
    artists = list(ax.bar(x - 0.2, expected, width=0.4, color="#c8c8c8", label="expected"))
    if got is not None:
        shown = drawable(got, expected)
        artists += _off_chart(ax, got, shown)
        got = shown
        ok = np.isclose(got, expected, rtol=1e-9, atol=1e-9)
        colours = np.where(ok, "#c8c8c8", STATE_COLOURS[3])
        artists += list(ax.bar(x + 0.2, got, width=0.4, color=colours, hatch="//", label="yours"))
    ax.set_xticks(x, labels)
    ax.axhline(0, color="black", linewidth=0.5)
    artists.append(ax.legend(fontsize="x-small"))
    return artists


def difference_note(ax, expected, got, where=(0.02, 0.86)) -> list:
    """A note "yours differ by …" where the student's numbers differ from the expected ones by
    too little to see in the bars (a float32 answer: r153 E16 in 3.1, r175 D11 in 3.2, whose
    red and blue bars were drawn identical and said nothing), else nothing."""
    g, e = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if g.shape != e.shape or not np.isfinite(g).all():
        return []
    error = float(np.max(np.abs(g - e)))
    if not 0 < error < 1e-3 * max(1.0, float(np.abs(e).max())):
        return []
    note = f"yours differ by {error:.1g}:\nequal at this scale"
    return [ax.text(*where, note, transform=ax.transAxes, fontsize="x-small", va="top")]


def draw_bars(ax, labels, values, wrong):
    """One bar per value; ``wrong[k]`` marks the student's bar that is wrong in red."""
    colours = [STATE_COLOURS[3] if bad else "#c8c8c8" for bad in wrong]
    shown = drawable(values, values[:2])
    artists = _off_chart(ax, values, shown)
    artists += list(ax.bar(np.arange(len(values)), shown, color=colours))
    ax.set_xticks(np.arange(len(values)), labels)
    ax.axhline(0, color="black", linewidth=0.5)
    return artists


def draw_split(ax, v, expected, got):
    """The sorted triangle (points 1, 2, 3 by height), the line through point 2, the true point 4
    and the student's."""
    ring = np.vstack([v, v[:1]])
    artists = ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    artists += ax.plot([v[0, 0], v[2, 0]], [v[0, 1], v[2, 1]], color=EDGE_COLOUR, linewidth=3)
    artists.append(ax.axhline(v[1, 1], color="#888888", linestyle=":"))
    artists += ax.plot(expected, v[1, 1], "o", color="#2b7bba", label="point 4 (expected)")
    if got is not None and np.isfinite(drawable(got, v)):
        artists += ax.plot(got, v[1, 1], "x", color=STATE_COLOURS[3], ms=10, label="your u4")
    for k, p in enumerate(v):
        artists.append(ax.annotate(f"point {k + 1}", p, fontsize="x-small"))
    ax.set_ylim(v[:, 1].max() + 1, v[:, 1].min() - 1)
    ax.set_aspect("equal", adjustable="datalim")
    artists.append(ax.legend(fontsize="x-small"))
    return artists


#: The label of draw_clip's blank strip (an inset that is no panel; r364 FIG1: 4.3 drew the
#: expected colours on it, and every disc moved off its vertex, when the answer was None).
BLANK_STRIP = "blank strip"


def clip_panels(ax) -> list:
    """The panels :func:`draw_clip` drew in ``ax``, x first (its blank strip left out)."""
    return [a for a in ax.child_axes if a.get_label() != BLANK_STRIP]


def draw_clip(ax, v, expected, got, colours=None):
    """The triangle and the polygons in two panels sharing z + w (the near plane is the line
    z + w = 0): x on the left, y on the right (r306 FIG1: with x alone a polygon wrong only
    in y was drawn on the expected one). Where y is the same at every vertex drawn (the floor
    triangle) the y panel is one vertical line: the value is said instead (r310 FIG1). Without
    an answer, the x panel alone, on the right: the report's note takes the left part. An
    empty polygon is said so (r306 FIG2). A vertex outside the zoomed panel is marked at its
    edge, with its z + w (and its colour, ``colours``: r357 FIG2, v3 behind the camera was
    off the panel)."""
    ax.set_axis_off()
    ys = np.concatenate([np.asarray(v, float)[:, 1], np.asarray(expected, float)[:, 1]])
    if got is not None and len(got) and np.isfinite(drawable(got, v)).all():
        ys = np.concatenate([ys, np.asarray(got, float).reshape(-1, 4)[:, 1]])
    flat_y = bool(np.ptp(ys) <= 1e-9 * max(1.0, float(np.abs(ys).max())))
    if got is None:
        boxes = [(0.56, 0.44)]
        # r357 FIG2: a blank strip for the panel's y label and ticks, so that the report's
        # note (in the widest strip no inset covers) keeps off them
        strip = ax.inset_axes([0.4, 0.0, 0.16, 1.0])
        strip.set_axis_off()
        strip.set_label(BLANK_STRIP)  # not a panel: 4.3 draws its discs on the panels alone
    else:
        boxes = [(0.0, 0.7)] if flat_y else [(0.0, 0.45), (0.55, 0.45)]
    panels = []
    for left, width in boxes:
        share = {"sharey": panels[0]} if panels else {}
        panels.append(ax.inset_axes([left, 0.0, width, 1.0], **share))
    artists = []
    for k, panel in enumerate(panels):
        artists += _clip_panel(panel, k, v, expected, got)
    _zoom_on_kept(panels, v, expected, got)
    for k, panel in enumerate(panels):
        artists += _mark_off_panel(panel, k, v, colours)
    for panel in panels:  # a label in the right half on the vertex's left, off the spine (r310)
        middle = sum(panel.get_xlim()) / 2
        for label in panel.texts:
            if hasattr(label, "xyann") and label.xy[0] > middle:
                label.xyann = (-5, 5)
                label.set_horizontalalignment("right")
    panels[0].set_ylabel("z + w (inside ≥ 0)")
    handles, labels = panels[0].get_legend_handles_labels()
    if flat_y and got is not None:
        handles += panels[0].plot([], [], " ")
        labels.append(f"y = {num(ys[0])} at every vertex:\nno y panel")
    artists.append(panels[-1].legend(handles, labels, fontsize="x-small", loc="upper left",
                                     bbox_to_anchor=(1.04, 1)))  # fmt: skip
    return artists


def _mark_off_panel(panel, k, v, colours=None) -> list:
    """Each vertex of ``v`` outside the panel's limits as an arrowhead at the nearest edge,
    pointing its way, labelled with its z + w (r357 FIG2)."""
    (x0, x1), (y0, y1) = panel.get_xlim(), panel.get_ylim()
    d = np.asarray(v, float)[:, 2] + np.asarray(v, float)[:, 3]
    if (d < y0).any():  # room below the plane's vertices for the arrowhead and its label
        y0 -= 0.25 * (y1 - y0)
        panel.set_ylim(y0, y1)
    artists = []
    for j, p in enumerate(np.asarray(v, float)):
        x, d = p[k], p[2] + p[3]
        if x0 <= x <= x1 and y0 <= d <= y1:
            continue
        inset_x, inset_y = 0.03 * (x1 - x0), 0.04 * (y1 - y0)
        at = (min(max(x, x0 + inset_x), x1 - inset_x), min(max(d, y0 + inset_y), y1 - inset_y))
        marker = "v" if d < y0 else "^" if d > y1 else "<" if x < x0 else ">"
        face = "white" if colours is None else np.clip(np.asarray(colours, float)[j], 0, 1)
        artists += panel.plot(*at, marker=marker, markersize=11, color="black",
                              markerfacecolor=face, clip_on=False, zorder=6)  # fmt: skip
        # beside the arrowhead, on the side with more room (off the discs and edges above)
        right = at[0] <= (x0 + x1) / 2
        # near the top or bottom edge the two lines hang inward, off the title (r496 FIG1)
        va = "top" if at[1] > y1 - 0.2 * (y1 - y0) else "bottom" if at[1] < y0 + 0.2 * (
            y1 - y0) else "center"  # fmt: skip
        artists.append(panel.annotate(f"v{j + 1} off the panel:\nz + w = {num(d)}", at,
                                      xytext=(9 if right else -9, 0), textcoords="offset points",
                                      fontsize="x-small", va=va,
                                      ha="left" if right else "right",
                                      bbox={"boxstyle": "round,pad=0.1", "facecolor": "white",
                                            "edgecolor": "none", "alpha": 0.8}))  # fmt: skip
    return artists


def _zoom_on_kept(panels, v, expected, got) -> None:
    """Each panel's limits around the kept polygon, yours and the near plane (r310 FIG1: a
    small polygon sat in a corner of axes scaled to the whole triangle); the triangle runs
    off the panel where it is larger."""
    pts = [np.asarray(expected, float).reshape(-1, 4)]
    if got is not None and len(got) and np.isfinite(drawable(got, v)).all():
        pts.append(np.asarray(got, float).reshape(-1, 4))
    pts = np.vstack(pts)
    if not len(pts):  # nothing kept, nothing of yours: the whole triangle
        return
    d = np.r_[pts[:, 2] + pts[:, 3], 0.0]  # the plane z + w = 0 stays in view
    whole = np.asarray(v, float)
    for k, panel in enumerate(panels):
        for lo, hi, span, setter in (
            (pts[:, k].min(), pts[:, k].max(), np.ptp(whole[:, k]), panel.set_xlim),
            (d.min(), d.max(), np.ptp(whole[:, 2] + whole[:, 3]), panel.set_ylim),
        ):
            pad = max(0.15 * (hi - lo), 0.05 * span, 1e-3)
            setter(lo - pad, hi + pad)


def _clip_panel(ax, k, v, expected, got) -> list:
    """Component ``k`` (0: x, 1: y) of the triangle and the polygons against z + w."""

    def ring(p):
        p = np.vstack([p, p[:1]])
        return p[:, k], p[:, 2] + p[:, 3]

    artists = list(ax.plot(*ring(v), color="black", linewidth=1, label="triangle"))
    artists.append(ax.axhline(0, color=EDGE_COLOUR, linewidth=2, label="near plane z + w = 0"))
    empty = []
    if len(expected):
        artists += ax.plot(*ring(expected), "o-", color="#2b7bba", label="clipped (expected)")
    else:
        artists += ax.plot([], [], " ", label="clipped (expected): empty")
        empty.append("expected: empty")
    if got is not None and len(got) and np.isfinite(drawable(got, v)).all():
        artists += ax.plot(*ring(got), "x--", color=STATE_COLOURS[3], label="yours")
    elif got is not None and len(got):
        artists += _off_chart(ax, np.ravel(got), drawable(np.ravel(got), v))
    elif got is not None:
        artists += ax.plot([], [], " ", label="yours: empty (no vertex)")
        empty.append("yours: empty")
    if empty:
        # in the middle: zoomed on the polygon, the plane runs near the foot (r310)
        artists.append(ax.text(0.5, 0.5, ", ".join(empty), transform=ax.transAxes,
                               ha="center", va="center", fontsize="small",
                               color=STATE_COLOURS[3] if "yours: empty" in empty else "black"))  # fmt: skip
    at = {}  # vertices drawn at one point get one label ("v1, v2": y is often shared)
    for j, p in enumerate(v):
        at.setdefault((float(p[k]), float(p[2] + p[3])), []).append(f"v{j + 1}")
    for point, names in at.items():  # beside the vertex, not on its marker (r306 FIG3)
        artists.append(ax.annotate(", ".join(names), point, xytext=(5, 5),
                                   textcoords="offset points", fontsize="x-small",
                                   bbox={"boxstyle": "round,pad=0.1", "facecolor": "white",
                                         "edgecolor": "none", "alpha": 0.8}))  # fmt: skip
    ax.margins(0.15)  # room for the labels inside the axes, off the spines
    ax.set_xlabel(f"{'xy'[k]} (clip space)")
    if k:
        ax.tick_params(labelleft=False)
    return artists


#: Colours of coverage counts 0, 1, 2, 3 or more (a watertight fill shows 0 and 1 only).
COUNT_COLOURS = ("#ffffff", "#c8c8c8", "#d7301f", "#7f0000")
#: Colours of count differences −1 (a hole), 0, +1 (covered once too often).
DIFF_COLOURS = ("#2b7bba", "#ffffff", "#d7301f")


def _scene_axes(ax, case, title):
    w, h = case.size
    artists = []
    for xy in case.triangles:
        ring = np.vstack([xy, xy[:1]])
        artists += ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=0.5)
    ax.set_xlim(0, w)
    ax.set_ylim(h, 0)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    artists.append(ax.set_title(title, fontsize="small"))
    return artists


def draw_counts(ax, case, counts, title):
    """How many triangles cover each pixel of a scene, with the triangles' edges."""
    from matplotlib.colors import ListedColormap

    w, h = case.size
    image = ax.imshow(
        np.minimum(counts, 3),
        cmap=ListedColormap(COUNT_COLOURS),
        vmin=0,
        vmax=3,
        extent=(0, w, h, 0),
        interpolation="nearest",
    )
    return [image] + _scene_axes(ax, case, title)


def draw_differences(ax, case, diff):
    """Pixels whose count differs: red where yours covers more, blue where less, with the
    difference written in each."""
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    w, h = case.size
    image = ax.imshow(
        np.clip(diff, -1, 1),
        cmap=ListedColormap(DIFF_COLOURS),
        vmin=-1.5,
        vmax=1.5,
        extent=(0, w, h, 0),
        interpolation="nearest",
    )
    n = int((diff != 0).sum())
    artists = [image] + _scene_axes(ax, case, f"differences: {n} pixel(s)")
    for i, j in np.argwhere(diff != 0):
        artists.append(
            ax.text(j + 0.5, i + 0.5, f"{int(diff[i, j]):+d}", ha="center", va="center", fontsize=5)
        )
    handles = [
        Patch(color=DIFF_COLOURS[2], label="yours covers more"),
        Patch(color=DIFF_COLOURS[0], label="yours covers less (a hole)"),
    ]
    # below the panel: the legend must never hide a pixel, nor leave the figure
    artists.append(
        ax.legend(handles=handles, fontsize="x-small", loc="upper right", bbox_to_anchor=(1, -0.02))
    )
    return artists
