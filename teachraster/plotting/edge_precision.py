"""float32 far from the origin, drawn: the grid its positions keep, the pixels it draws.

Lesson 06 (section 2) claims that at 10⁶ px float32 *is* 4-bit sub-pixel fixed point.
:func:`plot_float32_spacing` draws the claim's reason, float32's spacing against the distance
from the origin beside the 1/256 and 1/16 px grids; :func:`plot_mesh_differences` draws its
consequence on the study's mesh, the pixels float32 gets wrong there and fixed4's. The numbers
come from :mod:`teachraster.study.bench` (``mesh_wrong_pixels``, ``jittered_mesh``).
"""

from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.ticker import FixedLocator, NullFormatter, NullLocator

from .style import COLORS, OKABE_ITO

#: The distances drawn, in px: from one pixel to past 2²².
SPACING_RANGE = (1.0, 2.0**22.5)


def _grid_label(bits: int) -> str:
    return "1" if bits == 0 else f"1/{2**bits:,}"


def plot_float32_spacing(ax, marks: dict, *, grids=(8, 4)) -> dict:
    """float32's spacing (the step between neighbouring values) against |x|, log-log.

    Parameters
    ----------
    ax : matplotlib Axes
    marks : dict
        ``{label: distance_px}``: points marked on the staircase (e.g. the mesh's offsets).
    grids : tuple of int
        Sub-pixel bits whose grids (1/2**bits px) are drawn as horizontal lines.

    Returns
    -------
    dict
        The artists: ``"steps"`` (the staircase), ``"grids"`` and ``"marks"`` (lists).
    """
    x = np.geomspace(*SPACING_RANGE, 4000)
    spacing = np.spacing(x.astype(np.float32)).astype(float)
    (steps,) = ax.plot(x, spacing, color=COLORS["inside"], lw=2.5, drawstyle="steps-post")
    ax.set_xscale("log", base=10)
    ax.set_yscale("log", base=2)
    grid_artists = []
    for bits, colour in zip(grids, (OKABE_ITO["bluish_green"], COLORS["outside"])):
        step = 2.0**-bits
        grid_artists.append(ax.axhline(step, color=colour, ls="--", lw=2))
        # under the line at the left, where the staircase is far below it
        grid_artists.append(ax.text(1.5, step / 1.3, f"{bits} sub-pixel bits",
                                    color=colour, fontsize="small", va="top"))  # fmt: skip
    mark_artists = []
    for label, at in marks.items():
        s = float(np.spacing(np.float32(at)))
        mark_artists += ax.plot(at, s, "o", color="black", ms=9, zorder=3)
        text = f"{label}: {_grid_label(round(-np.log2(s)))} px"
        if s >= 2.0 ** -min(grids):  # on the coarsest grid's line: left of the point, above
            where = dict(xytext=(-10, 4), ha="right", va="bottom")
        else:  # below and right of the point, where the staircase has not yet climbed
            where = dict(xytext=(6, -6), ha="left", va="top")
            text = text.replace(": ", "\n", 1)
        mark_artists.append(ax.annotate(text, (at, s), textcoords="offset points",
                                        fontsize="small", **where))  # fmt: skip
    exps = list(range(-20, 1, 4))
    ax.yaxis.set_major_locator(FixedLocator([2.0**e for e in exps]))
    ax.set_yticklabels([_grid_label(-e) if e >= -8 else f"2$^{{{e}}}$" for e in exps])
    ax.yaxis.set_minor_locator(NullLocator())
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set_ylim(2.0**-22, 2.0**1)
    ax.set_xlim(*SPACING_RANGE)
    ax.set(xlabel="distance from the origin (px)", ylabel="float32's spacing (px)")
    ax.grid(True, which="major", alpha=0.3)
    return {"steps": steps, "grids": grid_artists, "marks": mark_artists}


def plot_mesh_differences(ax, tris, size: int, wrong, also=None, *, labels=("", "")) -> dict:
    """A mesh's edges and the pixels an arithmetic covers wrongly (filled squares), with a
    second set (``also``, crosses) drawn over them to show where the two agree.

    Parameters
    ----------
    ax : matplotlib Axes
    tris : (N, 3, 2) array
        The mesh's triangles, in window pixels.
    size : int
        The window, ``size`` x ``size`` px.
    wrong, also : (size, size) arrays
        Pixels with a non-zero value are marked; ``also`` may be None.
    labels : (str, str)
        The legend's names for the two sets.

    Returns
    -------
    dict
        ``"edges"`` (a LineCollection), ``"wrong"`` and ``"also"`` (scatter, or None).
    """
    tris = np.asarray(tris, dtype=float)
    segments = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    edges = LineCollection(segments, colors=COLORS["grid"], linewidths=1.0)
    ax.add_collection(edges)
    rows, cols = np.nonzero(np.asarray(wrong))
    shown = ax.scatter(cols + 0.5, rows + 0.5, s=42, marker="s", color=COLORS["outside"],
                       label=labels[0], zorder=3)  # fmt: skip
    crosses = None
    if also is not None:
        rows_b, cols_b = np.nonzero(np.asarray(also))
        crosses = ax.scatter(cols_b + 0.5, rows_b + 0.5, s=30, marker="x", color="black",
                             linewidths=1.2, label=labels[1], zorder=4)  # fmt: skip
    ax.set_xlim(0, size)
    ax.set_ylim(size, 0)  # y down
    ax.set_aspect("equal")
    ax.set(xlabel="x (px)", ylabel="y (px)")
    return {"edges": edges, "wrong": shown, "also": crosses}
