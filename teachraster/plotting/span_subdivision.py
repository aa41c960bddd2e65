"""One span subdivided, drawn: the true u, the chords between exact divides, the worst miss.

Lesson 06's :class:`~teachraster.widgets.span_explorer.SpanSubdivisionExplorer` draws with
these; :func:`plot_span` draws once, :func:`update_span` moves the same artists to another
:class:`~teachraster.study.span_subdivision.SpanSubdivision` (the axes stay put, so a
widget can blit). The numbers come from :mod:`teachraster.study.span_subdivision`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from matplotlib.patches import Patch
from matplotlib.ticker import FixedLocator, FormatStrFormatter, NullFormatter

from ..study.span_subdivision import SpanSubdivision, true_u
from .style import COLORS, OKABE_ITO

#: The miss panel's log axis (texels): a miss from ``MISS_FLOOR`` up is drawn at its value; a
#: smaller one (the misses fall to 0 at every exact divide) is drawn at ``MISS_BELOW``, in a
#: grey band under the floor whose tick reads "< 0.01", and the key says so.
MISS_FLOOR, MISS_TOP = 0.01, 400.0
MISS_BELOW, MISS_BOTTOM = 0.0015, 0.0005  # "< 0.01" a line of text under "0.01" (r479 S2)
#: Points per pixel of the fine curves (true u, and the chords' miss between pixel centres).
FINE_PER_PIXEL = 8


@dataclass
class SpanArtists:
    """What :func:`plot_span` drew, moved in place by :func:`update_span`."""

    true: object  # the perspective-correct u, fine
    chords: object  # the affine chords through the anchors
    anchors: object  # the exact divides (dots)
    worst: object  # the worst miss: a vertical segment from the true u to the chord
    worst_text: object  # its value, beside it
    miss: object  # |chord - true| along the span, fine (texels)
    bounds: object  # each piece's closed-form worst miss, a dash over the piece
    pixel_miss: object  # |chord - true| at the pixel centres (dots)


def shown_miss(miss) -> np.ndarray:
    """``|miss|`` where the panel can draw it, ``MISS_BELOW`` (the "< 0.01" band) below that."""
    miss = np.abs(np.asarray(miss, dtype=float))
    return np.where(miss < MISS_FLOOR, MISS_BELOW, miss)


def _fine(s: SpanSubdivision):
    x = np.linspace(0.0, s.length - 1, (s.length - 1) * FINE_PER_PIXEL + 1)
    chord = np.interp(x, s.anchors, s.anchor_u)
    return x, true_u(x, s.length, s.r, s.texels), chord


def _bound_path(s: SpanSubdivision):
    """Each piece's closed-form worst miss as a horizontal dash over the piece (NaN-broken)."""
    xs, ys = [], []
    for k, b in enumerate(s.bound_texels):
        if len(s.anchors) < 2:
            break
        xs += [s.anchors[k], s.anchors[k + 1], np.nan]
        ys += [float(shown_miss(b)), float(shown_miss(b)), np.nan]
    return xs, ys


def _worst_segment(s: SpanSubdivision):
    x = s.worst_x
    return [x, x], [float(true_u(x, s.length, s.r, s.texels)), float(np.interp(x, s.anchors,
                                                                             s.anchor_u))]  # fmt: skip


def plot_span(ax_u, ax_miss, s: SpanSubdivision) -> SpanArtists:
    """The span ``s`` on two axes sharing x (pixels along the span): u in texels (``ax_u``),
    and the chords' miss in texels on a log scale (``ax_miss``)."""
    x, u, chord = _fine(s)
    (true,) = ax_u.plot(x, u, color="0.2", lw=2.5, label="true u (perspective-correct)")
    (chords,) = ax_u.plot(x, chord, color=COLORS["outside"], lw=2.5,
                          label="chords (affine between divides)")  # fmt: skip
    (dots,) = ax_u.plot(s.anchors, s.anchor_u, "o", color=COLORS["outside"], ms=8,
                        label="exact divides")  # fmt: skip
    (worst,) = ax_u.plot(*_worst_segment(s), color=OKABE_ITO["blue"], lw=4,
                         solid_capstyle="butt", label="worst miss at a centre")  # fmt: skip
    worst_text = ax_u.annotate("", (0, 0), xytext=(-10, 0), textcoords="offset points",
                               ha="right", va="center", color=OKABE_ITO["blue"],
                               fontsize="small")  # fmt: skip
    ax_u.set(xlim=(-1, s.length), ylim=(-0.04 * s.texels, 1.04 * s.texels),
             ylabel="u (texels)")  # fmt: skip
    ax_u.legend(loc="upper left", fontsize="small", frameon=False)
    (miss,) = ax_miss.plot(x, shown_miss(chord - u), color=COLORS["outside"], lw=2,
                           label="chord − true")  # fmt: skip
    (bounds,) = ax_miss.plot(*_bound_path(s), color=OKABE_ITO["blue"], lw=2.5, ls="--",
                             label="(√ρ − 1)²/(ρ − 1) · Δu")  # fmt: skip
    (pix,) = ax_miss.plot(np.arange(s.length), shown_miss(s.pixel_miss), "o", color="0.2",
                          ms=3.5, label="at pixel centres")  # fmt: skip
    _miss_axis(ax_miss)
    below = Patch(color="0.88", label="below 0.01 texel: drawn in the grey band")
    # the key under the panel: inside it, any corner hid an arc at some N and r
    ax_miss.figure.legend(handles=[miss, bounds, pix, below], loc="outside lower center",
                          fontsize="small", frameon=False, ncols=2)  # fmt: skip
    for ax in (ax_u, ax_miss):
        ax.grid(True, alpha=0.3)
    art = SpanArtists(true, chords, dots, worst, worst_text, miss, bounds, pix)
    _label_worst(art, s)
    return art


def _miss_axis(ax) -> None:
    """The miss panel's log axis: 0.01 ... 100 texels, and under 0.01 a grey band, "< 0.01"."""
    ax.set_yscale("log")
    ax.axhspan(MISS_BOTTOM, MISS_FLOOR, color="0.88", lw=0, zorder=0)
    tops = [10.0**e for e in range(-2, 3)]  # 0.01 ... 100, not 10⁻²
    ax.set_yticks([MISS_BELOW, *tops], ["< 0.01", *(f"{t:g}" for t in tops)])
    minor = [k * t for t in tops for k in range(2, 10) if k * t <= MISS_TOP]
    ax.yaxis.set_minor_locator(FixedLocator(minor))  # none in the band: it has no scale
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set(ylim=(MISS_BOTTOM, MISS_TOP), xlabel="pixel along the span", ylabel="miss (texels)")


def _label_worst(art: SpanArtists, s: SpanSubdivision) -> None:
    xs, ys = _worst_segment(s)
    art.worst_text.xy = (xs[0], (ys[0] + ys[1]) / 2)
    # left of the miss, unless that puts it over the y-axis ticks (r = 1: the miss at pixel 0)
    left = xs[0] > 0.25 * s.length
    art.worst_text.xyann = (-10 if left else 10, 0)
    art.worst_text.set_horizontalalignment("right" if left else "left")
    art.worst_text.set_text(f"{s.worst_texels:.3g} texels")


def update_span(art: SpanArtists, s: SpanSubdivision) -> None:
    """Move every artist of ``art`` to ``s`` (nothing drawn here)."""
    x, u, chord = _fine(s)
    art.true.set_ydata(u)
    art.chords.set_ydata(chord)
    art.anchors.set_data(s.anchors, s.anchor_u)
    art.worst.set_data(*_worst_segment(s))
    _label_worst(art, s)
    art.miss.set_ydata(shown_miss(chord - u))
    art.bounds.set_data(*_bound_path(s))
    art.pixel_miss.set_ydata(shown_miss(s.pixel_miss))


#: One colour per screen size in :func:`plot_subdivision_law` (256², 512², 1024², ...).
SIZE_COLOURS = (OKABE_ITO["blue"], OKABE_ITO["orange"], OKABE_ITO["bluish_green"])


def plot_subdivision_law(ax, worst: dict, mean: dict) -> list:
    """The floor's error on screen (px) against N, log-log: ``worst[size][N]`` solid with
    dots, ``mean[size][N]`` dashed with squares, one colour per size; grey guides of slope 1
    and 2 (error ∝ N, ∝ N²) through the first size's worst pixel and mean at the smallest N,
    so that each family's slope reads against guides that start on it. Returns the legend's handles."""
    from matplotlib.lines import Line2D

    handles = []
    for colour, size in zip(SIZE_COLOURS, worst):
        ns = sorted(worst[size])
        ax.plot(ns, [worst[size][n] for n in ns], "o-", color=colour, lw=3, ms=8)
        ax.plot(ns, [mean[size][n] for n in ns], "s--", color=colour, lw=2.5, ms=7)
        handles.append(Line2D([], [], color=colour, lw=6, label=f"{size}²"))
    ns = np.array(sorted(next(iter(worst.values()))), dtype=float)
    first = list(worst)[0]  # each family's guides start on its own first point (review r283)
    for family in (worst[first], mean[first]):
        start = family[int(ns[0])]
        for slope, dash in ((1, ":"), (2, "-.")):
            ax.plot(ns, start * (ns / ns[0]) ** slope, dash, color="0.45", lw=2, zorder=1)
            ax.text(ns[-1] * 1.06, start * (ns[-1] / ns[0]) ** slope,
                    f"∝ N{'²' if slope == 2 else ''}", color="0.35", va="center",
                    fontsize="small")  # fmt: skip
    handles += [Line2D([], [], color="0.2", marker="o", lw=3, label="worst pixel"),
                Line2D([], [], color="0.2", marker="s", ls="--", lw=2.5, label="mean")]  # fmt: skip
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xticks(ns, [f"{n:g}" for n in ns])  # 2, 4, ... not 2¹, 2², ...
    ax.set_xlim(ns[0] / 1.25, ns[-1] * 1.6)  # room for the guides' labels
    ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
    ax.yaxis.set_minor_formatter(NullFormatter())
    ax.set(xlabel="N (pixels between exact divides)", ylabel="error on screen (px)")
    ax.grid(True, which="major", alpha=0.3)
    return handles
