"""Lesson 01's figures of span tables: the similar triangles, the flat cases, the span ends.

Each draws on the Axes it is given and returns an :class:`~.common.Artists` dataclass, as the
plots of :mod:`.plots` do; the lesson keeps its numbers and its prints, these keep the
drawing (review r251 01-S2: two 90-line figure cells, mostly annotation, stood in the lesson).

- :func:`plot_similar_triangles` -- after Ek §1.1: the two similar right triangles on the
  long edge, nested at the top vertex, their legs measured, the shared angle and point 4.
- :func:`plot_flat_case` / :func:`flat_case_key` -- a flat-topped, flat-bottomed or
  zero-height triangle's fill, its split line and ringed vertices; the key of such panels.
- :func:`plot_span_ends` -- a fill with each raster line's span ends ticked, some pixels
  outlined (the prestep figure: ends that leave the edge).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from matplotlib.legend import Legend
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle, Wedge
from matplotlib.text import Text

from .common import Artists
from .plots import (
    CentreArtists,
    SplitArtists,
    TriangleArtists,
    plot_coverage,
    plot_pixel_centres,
    plot_pixel_grid,
    plot_split,
    plot_triangle,
)
from .style import COLORS


@dataclass
class SimilarArtists(Artists):
    """Artists of :func:`plot_similar_triangles`."""

    triangle: TriangleArtists
    legs: list = field(default_factory=list)  # the legs, hypotenuses, tints, right angles
    labels: list = field(default_factory=list)  # Δv and Δu of each, "shared angle", "point 4"
    wedge: Wedge | None = None
    point: Line2D | None = None
    legend: Legend | None = None


def _leg_label(ax, name: str, du: float, dv: float, u_top: float, v_top: float, color) -> list:
    """The dimension line of a vertical leg with its Δv, and the Δu of its horizontal leg."""
    x_dim = u_top - (1.2 if name == "4" else 3.3)  # the two vertical legs side by side
    arrow = ax.annotate("", (x_dim, v_top), (x_dim, v_top + dv),
                        arrowprops={"arrowstyle": "<->", "color": color, "lw": 2.5})  # fmt: skip
    sub = r"\mathrm{bot}" if name == "bot" else name
    dv_text = ax.text(x_dim - 0.3, v_top + dv / 2, rf"$\Delta v_{{{sub}}}$ = {dv:g}",
                      rotation=90, ha="right", va="center", color=color, fontweight="bold")  # fmt: skip
    # Δu_bot below its leg; Δu_4 left of the vertical legs, pointing at its leg, which lies
    # between the vertical leg and the long edge with no room for a label
    small = name == "4"
    du_text = ax.annotate(
        rf"$\Delta u_{{{sub}}}$ = {du:g}",
        (u_top + du / 2, v_top + dv),
        (u_top - 0.15, v_top + dv + 2.4) if small else (u_top + du / 2, v_top + dv + 0.3),
        ha="right" if small else "center",
        va="top",
        color=color,
        fontweight="bold",
        arrowprops={"arrowstyle": "->", "color": color, "lw": 2} if small else None,
    )
    return [arrow, dv_text, du_text]


def plot_similar_triangles(ax, fill, width: int, height: int) -> SimilarArtists:
    """After Ek §1.1: the right triangles on the long edge from the top vertex to the bottom
    one and to point 4, nested at the top vertex, with their legs Δu, Δv and the angle they
    share (a filled wedge: a thin arc round a small angle read as a bar).

    ``fill``: a span-table fill with its trace (``method="span", trace=True``), split in two.
    """
    s = fill.trace.span
    (u_top, v_top), (_, v_mid), (u_bot, v_bot) = s.sorted_xy
    plot_pixel_grid(ax, width, height)
    drawn = plot_triangle(ax, fill, arrows=False)
    drawn.labels[s.order[2]].set_position((18, -4))  # the bottom vertex's right: Δu_bot below
    out = SimilarArtists(drawn)
    legs = {"bot": ((u_bot, v_bot), COLORS["bbox"]), "4": ((s.u4, v_mid), COLORS["flat_bottom"])}
    for name, ((u_end, v_end), color) in legs.items():
        corner = (u_top, v_end)  # the right angle, below the top vertex
        us, vs = [u_top, corner[0], u_end], [v_top, corner[1], v_end]
        if name == "bot":  # the large one tinted, the small one an outline over it
            out.legs += ax.fill(us, vs, color=color, alpha=0.3, zorder=1)
        else:
            out.legs += ax.fill(us, vs, fc="none", ec=color, hatch="//", lw=0, zorder=1.5)
            out.legs += ax.plot([u_top, u_end], [v_top, v_end], color=color, lw=4,
                                ls=(0, (2, 1.5)), zorder=2.5)  # fmt: skip
        out.legs += ax.plot([u_top, u_top, u_end], [v_top, v_end, v_end], color=color, lw=4,
                            zorder=2)  # fmt: skip
        out.legs += ax.plot(*corner, "s", ms=9, mfc="none", mec=color, mew=2.5, zorder=3)
        out.labels += _leg_label(ax, name, u_end - u_top, v_end - v_top, u_top, v_top, color)
    # the angle both share, at the top vertex: between the vertical legs and the long edge
    turn = np.degrees(np.arctan2(v_bot - v_top, u_bot - u_top))
    out.wedge = Wedge((u_top, v_top), 2.5, turn, 90, color=COLORS["split"], alpha=0.8, zorder=4)
    ax.add_patch(out.wedge)
    mid = np.radians((turn + 90) / 2)
    out.labels.append(ax.annotate(
        "shared angle", (u_top + 2.0 * np.cos(mid), v_top + 2.0 * np.sin(mid)),
        (u_top + 2.6, v_top + 6.3), ha="left", va="center", color=COLORS["split"],
        fontweight="bold", arrowprops={"arrowstyle": "-", "color": COLORS["split"], "lw": 1.5},
    ))  # fmt: skip
    out.point = ax.plot(s.u4, v_mid, "D", color=COLORS["split"], ms=11, mec="white", zorder=5)[0]
    out.labels.append(ax.annotate("point 4", (s.u4, v_mid), (12, -6), textcoords="offset points",
                                  ha="left", va="bottom", color=COLORS["split"],
                                  fontweight="bold"))  # fmt: skip
    ax.set_title("similar right triangles on the long edge (after Ek §1.1)", fontsize="medium")
    out.legend = ax.legend(
        handles=[
            Patch(color=COLORS["bbox"], alpha=0.5, label="top vertex to bottom vertex"),
            Patch(fc="none", ec=COLORS["flat_bottom"], hatch="//", label="top vertex to point 4"),
        ],
        loc="upper center",
        bbox_to_anchor=(0.5, -0.01),
        ncols=2,
    )
    return out


@dataclass
class FlatCaseArtists(Artists):
    """Artists of :func:`plot_flat_case`."""

    split: SplitArtists
    triangle: TriangleArtists
    centres: CentreArtists
    #: the ring drawn round each vertex (its style, for the key)
    vertex_ring: dict = field(default_factory=dict)


def plot_flat_case(ax, fill, width: int, height: int, name: str) -> FlatCaseArtists:
    """One flat (or zero-height) triangle's span fill: its covered pixels, the parts of its
    split, its edges without arrowheads (they sat on the ties), the centres over the edges that
    run through them, and each vertex a ring round its centre, whose dot still says whether it
    is covered (a black dot read as "its centre covered" on uncovered centres). Every other
    row and column is numbered (``ticks=7``: the rows the lesson compares are named).
    """
    plot_pixel_grid(ax, width, height, ticks=7)
    plot_coverage(ax, fill)
    split = plot_split(ax, fill)
    split.label.set_visible(False)  # u4 goes in the title, clear of the rows
    drawn = plot_triangle(ax, fill, labels=False, arrows=False)
    centres = plot_pixel_centres(ax, width, height, fill)
    centres.inside.set(zorder=4.6, mec="white", ms=1.5 * centres.inside.get_markersize())
    centres.outside.set(zorder=4.6, mfc="white", ms=1.5 * centres.outside.get_markersize())
    ring = {"marker": "o", "ms": 2.4 * centres.inside.get_markersize(), "mfc": "none",
            "mec": COLORS["edge"], "mew": 2.0}  # fmt: skip
    drawn.vertices.set(zorder=4.7, **ring)
    u4 = fill.trace.span.u4
    ax.set_title(f"{name}\n{int(fill.coverage.sum())} px, u4 = {'none' if u4 is None else f'{u4:g}'}",
                 fontsize="medium")  # fmt: skip
    return FlatCaseArtists(split, drawn, centres, ring)


def flat_case_key(ax, panel: FlatCaseArtists) -> Legend:
    """The key of :func:`plot_flat_case`'s panels, filling ``ax`` (its frame turned off)."""
    centres, line = panel.centres, panel.split.line
    ax.axis("off")
    dot = {"ls": "", "marker": "o"}
    handles = [
        Patch(color=COLORS["fill"], label="covered pixel"),
        Patch(color=COLORS["flat_bottom"], alpha=0.35, label="flat-bottom part, not covered"),
        Patch(color=COLORS["flat_top"], alpha=0.35, label="flat-top part, not covered"),
        Line2D(
            [],
            [],
            **dot,
            ms=centres.inside.get_markersize(),
            color=centres.inside.get_color(),
            mec="white",
            label="its centre covered",
        ),  # fmt: skip
        Line2D(
            [],
            [],
            **dot,
            ms=centres.outside.get_markersize(),
            mfc="white",
            mec=centres.outside.get_markeredgecolor(),
            label="its centre not",
        ),  # fmt: skip
        Line2D([], [], ls="", label="vertex (ringed)", **panel.vertex_ring),
        Line2D(
            [],
            [],
            color=line.get_color(),
            ls=line.get_linestyle(),
            lw=line.get_linewidth(),
            label="split line (v = v_mid)",
        ),  # fmt: skip
    ]
    # the parts' tints (plot_split) show where the triangle's area covers no pixel centre
    return ax.legend(handles=handles, loc="center")


@dataclass
class SpanEndArtists(Artists):
    """Artists of :func:`plot_span_ends`."""

    triangle: TriangleArtists
    ends: Line2D | None = None  # a tick at each span end, on its raster line
    marked: list = field(default_factory=list)  # the outlined pixels
    title: Text | None = None


#: The colour of :func:`plot_span_ends`' marked pixels: neither the fill's, nor the ticks'.
MARKED_COLOR = COLORS["split"]


def plot_span_ends(ax, coverage, ends: dict, xy, width: int, height: int, *, marked=(),
                   title: str = "") -> SpanEndArtists:  # fmt: skip
    """A span fill with each raster line's two span ends ticked where the loop put them.

    Parameters
    ----------
    ax : matplotlib Axes
    coverage : (height, width) bool
    ends : dict
        Row -> ``(x_left, x_right, ...)``, as lesson 01's span loops return them.
    xy : (3, 2) array
        The triangle drawn (the snapped vertices the loop filled).
    marked : sequence of (row, col)
        Pixels hatched and framed in a colour of their own (the lesson: where two fills
        differ), over the fill or the white alike, so that they read on a projector, where a
        thin outline is lost in the grid.
    """
    plot_pixel_grid(ax, width, height)
    plot_coverage(ax, coverage)
    drawn = plot_triangle(ax, np.asarray(xy, dtype=float), arrows=False)
    out = SpanEndArtists(drawn)
    us = [x for i in sorted(ends) for x in ends[i][:2]]
    vs = [i + 0.5 for i in sorted(ends) for _ in range(2)]
    out.ends = ax.plot(us, vs, ls="", marker="|", ms=16, mew=3, color=COLORS["current"],
                       zorder=5)[0]  # fmt: skip
    for i, j in marked:
        box = Rectangle((j + 0.1, i + 0.1), 0.8, 0.8, fc="none", ec=MARKED_COLOR, lw=3,
                        hatch="///", zorder=4.5)  # fmt: skip
        ax.add_patch(box)
        out.marked.append(box)
    out.title = ax.set_title(title, fontsize="medium")
    return out
