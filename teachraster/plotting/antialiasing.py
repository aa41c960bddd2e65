"""Antialiasing plots: sample positions and their coverage, coverage fractions, area errors.

Every function takes an Axes and returns its artists (``update`` redraws them in place):

- :func:`plot_samples` -- every sample of every pixel at its position, filled where covered
  (coloured by triangle for a multisampled Frame), with the pixel's coverage fraction behind;
- :func:`plot_pixel_samples` -- one pixel magnified: its samples, the triangle edges through
  it, and at each sample which triangle owns it or the edge values E_k that decided it;
- :func:`plot_coverage_fraction` -- the fraction of covered samples per pixel (the resolve of
  a white triangle on black);
- :func:`plot_area_error` -- coverage fraction minus the exact area of the triangle in the
  pixel, signed (red: the samples saw too little of the triangle, blue: too much).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patheffects import withStroke
from matplotlib.text import Text
from matplotlib.transforms import Bbox, offset_copy

from ..core.fill import Fill
from ..core.trace import edge_name
from ..pipeline.rendering.render_triangles import Frame
from .common import Artists, fs, label_box, lw, ms, show_image
from .images import ImageArtists
from .style import COLORS, OKABE_ITO, SIGNED_CMAP, VALUE_CMAP

#: Colours of triangle ids 0, 1, 2, ... in per-sample plots (cycled).
TRIANGLE_COLORS = [OKABE_ITO[k] for k in ("blue", "orange", "bluish_green", "vermillion",
                                           "reddish_purple", "sky_blue", "yellow")]  # fmt: skip


def sample_data(source):
    """(H, W, S) per-sample triangle id (-1 none; 0 for a covered sample of a Fill) and the
    (S, 2) offsets, from a multisampled Fill or Frame."""
    if isinstance(source, Fill):
        if source.sample_coverage is None:
            raise ValueError("plot_samples needs a multisampled fill: rasterize(..., samples=4)")
        return np.where(source.sample_coverage, 0, -1), source.samples
    if isinstance(source, Frame):
        if source.sample_triangle_id is None:
            raise ValueError("plot_samples needs a multisampled frame: render(..., samples=4)")
        return source.sample_triangle_id, source.samples
    raise TypeError(f"expected a multisampled Fill or Frame, got {type(source).__name__}")


def _positions(ids, offsets):
    h, w, n_s = ids.shape
    rows, cols, s = np.indices((h, w, n_s)).reshape(3, -1)
    return cols + offsets[s, 0], rows + offsets[s, 1], ids.ravel()


#: The largest sample dot, as a multiple of the style's marker size (at 1 and 4 samples).
DOT_SCALE = 0.55 * 1.26
#: A dot's diameter at most this share of the closest two samples' distance, so that dots
#: never touch; a ring's at most :data:`RING_SHARE` of it, its outline scaled with it, so that
#: the pixel's colour shows between and inside the rings (at 8 and 16 samples rings of the
#: style's width covered the triangle: review r12, lesson 00).
DOT_SHARE, RING_SHARE = 0.8, 0.6
#: Bold dots (the fill player's) take more of the gap: the closest two samples of a pixel
#: are farther apart than the gap, which two neighbouring pixels' samples set, and the white
#: halo keeps two dots apart where they nearly touch (review r37, lesson 00: 7 px at 4 samples).
BOLD_SHARE = 0.9
#: Bold dots take their gap as this quantile of the samples' closest-neighbour distances
#: (the same for the regular patterns; a jittered one has a few very close pairs).
BOLD_GAP = 0.25
#: With ``plot_samples(bold=True)`` (the fill player): covered samples filled in the
#: palette's "tests passed" blue, uncovered ones hollow in its "tests failed" vermillion (a
#: colour-blind-safe pair, neither on the value map's blue-to-yellow), untested ones hollow
#: grey; each with a white halo, so that it reads on the dark and the light end of the map.
#: At 4 samples the white ring of a covered sample and the white dot of an uncovered one
#: were both about 5 px across at a 592-px column and read alike (review r33, lesson 00).
BOLD_SCALE, BOLD_STYLE = (
    1.7,
    {
        "covered": (COLORS["inside"], COLORS["edge"]),
        "uncovered": ("none", COLORS["outside"]),
        "untested": ("none", COLORS["centre"]),
    },
)


@dataclass
class SampleArtists(Artists):
    """Samples of :func:`plot_samples`: covered (coloured by triangle), uncovered (white),
    and the coverage fraction image behind them (or None). :meth:`set_rings` draws the
    covered samples as rings instead, over pixels whose colours must show."""

    fraction: ImageArtists | None
    covered: object
    uncovered: Line2D
    rings: bool = field(default=False, repr=False)
    _faces: list = field(default_factory=list, repr=False)
    #: line widths in points, the style's when the samples were plotted: edge, ring, rim
    _widths: tuple = field(default=(0.5, 0.8, 2.0), repr=False)
    #: the largest dot (points: the style's when plotted) and the closest two samples'
    #: distance on screen (points; inf for one sample a pixel)
    _largest: float = field(default=6.0, repr=False)
    _gap: float = field(default=float("inf"), repr=False)
    #: samples only in pixels partly covered (plot_samples' ``partial``)
    partial: bool = field(default=False, repr=False)
    #: plot_samples' ``bold``: the samples no step has tested yet (else None)
    untested: Line2D | None = None
    _ids: np.ndarray | None = field(default=None, repr=False)
    _offsets: np.ndarray | None = field(default=None, repr=False)
    _tested: np.ndarray | None = field(default=None, repr=False)

    @property
    def bold(self) -> bool:
        """Drawn with ``plot_samples(bold=True)``: filled / hollow at every step."""
        return self.untested is not None

    def update(self, source) -> None:
        """Show another multisampled fill or frame (any size and pattern)."""
        self._ids, self._offsets = sample_data(source)
        self._tested = None  # a new fill: every sample's result on show until set_tested
        # bold dots (the player's) size by a typical sample's closest neighbour, not the
        # closest pair: 16 jittered samples set a pair 0.03 px apart, dots about 3 px across
        # (review r344 01-FIG1); the white halos keep the few closer pairs apart
        self._gap = _sample_gap(self.covered.axes, self._offsets, BOLD_GAP if self.bold else 0.0)
        self._place()
        if self.fraction is not None:
            self.fraction.update((self._ids >= 0).mean(axis=2))

    def set_tested(self, tested: np.ndarray | None) -> None:
        """Show the result of the samples of the pixels ``tested`` ((H, W) bool; None: all)
        and the others as untested (``bold`` only): at the fill's first steps no sample has
        been tested, and their colours gave the final answer away (review r33, lesson 00)."""
        if not self.bold or self._ids is None:
            return
        self._tested = None if tested is None else np.asarray(tested, dtype=bool)
        self._place()

    def _place(self) -> None:
        ids = self._ids
        x, y, t = _positions(ids, self._offsets)
        hit = t >= 0
        shown = np.ones_like(hit)
        if self.partial:  # where an edge crosses the pixel, not where all or none are covered
            some = (ids >= 0).any(axis=2) & (ids < 0).any(axis=2)
            shown = np.repeat(some.ravel(), ids.shape[2])
        waiting = np.zeros_like(hit)
        if self._tested is not None:
            waiting = shown & ~np.repeat(self._tested.ravel(), ids.shape[2])
            shown = shown & ~waiting
        self.covered.set_offsets(np.column_stack([x[hit & shown], y[hit & shown]]))
        self._faces = [TRIANGLE_COLORS[i % len(TRIANGLE_COLORS)] for i in t[hit & shown]]
        self.set_rings(self.rings)
        self.uncovered.set_data(x[~hit & shown], y[~hit & shown])
        self.uncovered.set_markersize(self.diameter())
        if self.untested is not None:
            self.untested.set_data(x[waiting], y[waiting])
            self.untested.set_markersize(self.diameter())

    def diameter(self, rings: bool = False) -> float:
        """A sample's dot (or ``rings``: ring) diameter in points: the style's, or less where
        the closest two samples would make dots touch (the standard 4-sample pattern's
        overlapped in a 12-pixel-wide panel) or rings hide the colour between them."""
        share = RING_SHARE if rings else (BOLD_SHARE if self.bold else DOT_SHARE)
        return float(min(self._largest, share * self._gap))

    def set_rings(self, on: bool) -> None:
        """Covered samples as hollow rings (``on``) or dots filled in their triangle's colour.

        A fill's last step colours its pixels by an attribute: filled dots, four to a pixel
        under 4× MSAA, hid those colours, and their blue read as the colour map's low end
        (review r11, lesson 00 c14). A ring shows the pixel's colour through it; white with
        a black rim, it stays visible on the dark and the light end of the map alike. Rings
        smaller than the style's are drawn with outlines thinner in proportion.
        """
        self.rings = bool(on)
        edge, ring, rim = self._widths
        if self.bold:  # filled and hollow read apart on the colours too: no rings
            self.covered.set_sizes([self.diameter() ** 2])
            self.covered.set_facecolor(BOLD_STYLE["covered"][0])
            return
        if self.rings:
            d = self.diameter(rings=True)
            thin = d / self._largest  # 1 at 1 and 4 samples; about a third at 16
            self.covered.set_sizes([d**2])
            self.covered.set_facecolor("none")
            self.covered.set_edgecolor("white")
            self.covered.set_linewidth(ring * thin)
            self.covered.set_path_effects([withStroke(linewidth=rim * thin,
                                                      foreground=COLORS["edge"])])  # fmt: skip
        else:
            self.covered.set_sizes([self.diameter() ** 2])
            self.covered.set_facecolor(self._faces)
            self.covered.set_edgecolor(COLORS["edge"])
            self.covered.set_linewidth(edge)
            self.covered.set_path_effects([])


def _sample_gap(ax, offsets, quantile: float = 0.0) -> float:
    """The distance of a sample to its closest neighbour (in its pixel or across a pixel
    side), in points at ``ax``'s magnification: the smallest over the pattern, or that
    ``quantile`` of the samples' distances; inf for one sample a pixel."""
    if len(offsets) < 2:
        return float("inf")
    shifts = np.array([[i, j] for i in (-1, 0, 1) for j in (-1, 0, 1)], dtype=float)
    pts = (offsets[None, :, :] + shifts[:, None, :]).reshape(-1, 2)
    gaps = np.hypot(*(offsets[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
    gaps[gaps <= 1e-9] = np.inf  # the sample itself
    gap = float(np.quantile(gaps.min(axis=1), quantile))  # data units (pixels)
    (x0, x1), bbox = ax.get_xlim(), ax.get_window_extent()
    pt_per_px = bbox.width / abs(x1 - x0) * 72.0 / ax.figure.dpi
    return gap * pt_per_px


def plot_samples(
    ax,
    source,
    *,
    fraction: bool = True,
    partial: bool = False,
    bold: bool = False,
    largest: float = DOT_SCALE,
) -> SampleArtists:
    """Every sample of every pixel at ``(j + ox, i + oy)``: filled where covered.

    Parameters
    ----------
    ax : matplotlib Axes
        Usually set up by :func:`~teachraster.plotting.plot_pixel_grid` (magnified pixels).
    source : Fill or Frame
        ``tr.rasterize(..., samples=S)`` (covered samples in the fill colour) or
        ``tr.render(..., samples=S)`` (each sample in the colour of its triangle).
    fraction : bool
        Shade each pixel by the fraction of its samples covered (light = few).
    partial : bool
        Draw the samples only in pixels partly covered, where an edge crosses the pixel
        (inside all are covered, outside none). Four dots in every pixel of a 16 × 16 grid
        hid the fill's shape on a projector (review r23, lesson 00 c14).
    bold : bool
        Larger samples, the same at every step (see :data:`BOLD_STYLE`): covered filled
        blue, uncovered hollow vermillion, and hollow grey those that
        :meth:`SampleArtists.set_tested` says no step has tested yet (the fill player).
    largest : float
        The largest dot, times the style's marker size (:data:`DOT_SCALE` by default); dots
        are smaller where the samples lie closer on screen.

    Returns
    -------
    SampleArtists
    """
    ids, offsets = sample_data(source)
    frac = None
    if fraction:
        frac = ImageArtists(show_image(ax, (ids >= 0).mean(axis=2), cmap="Greys", vmin=0,
                                       vmax=2.5, zorder=0.4))  # fmt: skip
    covered = ax.scatter([], [], zorder=4)  # its style: SampleArtists.set_rings
    uncovered = ax.plot([], [], "o", mfc="white", mec=COLORS["centre"],
                        mew=max(0.6, lw(0.2)), zorder=4)[0]  # fmt: skip
    widths = (max(0.5, lw(0.15)), max(0.8, lw(0.3)), max(2.0, lw(0.7)))
    untested, largest = None, ms(largest)
    if bold:
        largest *= BOLD_SCALE
        untested = ax.plot([], [], "o", zorder=4)[0]
        halo = [withStroke(linewidth=max(2.5, lw(0.8)), foreground="white")]
        for artist, role in ((covered, "covered"), (uncovered, "uncovered"),
                             (untested, "untested")):  # fmt: skip
            face, edge = BOLD_STYLE[role]
            if artist is covered:
                artist.set_edgecolor(edge)
                artist.set_linewidth(widths[0])
            else:
                artist.set_markerfacecolor(face)
                artist.set_markeredgecolor(edge)
                artist.set_markeredgewidth(max(1.2, lw(0.4)))
            artist.set_path_effects(halo)
    result = SampleArtists(frac, covered, uncovered, _widths=widths, _largest=largest,
                           partial=partial, untested=untested)  # fmt: skip
    result.update(source)
    return result


def _value_image(ax, data, cmap, vmin, vmax, colorbar, label) -> ImageArtists:
    im = show_image(ax, np.asarray(data, dtype=np.float64), cmap=cmap, vmin=vmin, vmax=vmax,
                    zorder=0.5)  # fmt: skip
    cbar = ax.figure.colorbar(im, ax=ax, shrink=0.85, label=label) if colorbar else None
    return ImageArtists(im, cbar)


def plot_coverage_fraction(ax, source, *, colorbar: bool = True, title: bool = True):
    """The fraction of each pixel's samples covered: what the resolve shows for a white
    triangle on black (``fill.coverage_fraction`` or ``frame.coverage_fraction``)."""
    data = source.coverage_fraction if isinstance(source, Fill | Frame) else source
    result = _value_image(ax, data, VALUE_CMAP, 0.0, 1.0, colorbar, "covered fraction")
    if title:
        ax.set_title("coverage fraction")
    return result


def plot_area_error(ax, fraction, area, *, colorbar: bool = True, title: bool = True,
                    bound: float | None = None):  # fmt: skip
    """Signed error of a coverage fraction against the exact area in each pixel.

    ``fraction`` is a multisampled Fill or Frame or an (H, W) array; ``area`` the exact area
    of the triangle in each pixel (:func:`teachraster.study.antialiasing.pixel_area`). Red:
    the samples saw too little of the triangle, blue: too much (the diverging map of the
    edge values); pixels where both are 0 are transparent. The title gives the mean and maximum absolute error.
    ``bound``: the colours run from ``-bound`` to ``bound`` (default: the largest error
    shown); maps meant to be compared need the same bound.
    """
    frac = fraction.coverage_fraction if isinstance(fraction, Fill | Frame) else fraction
    err = np.asarray(frac, dtype=np.float64) - np.asarray(area, dtype=np.float64)
    err = np.where((np.asarray(frac) > 0) | (np.asarray(area) > 0), err, np.nan)
    if bound is None:
        bound = float(np.nanmax(np.abs(err), initial=0.0)) or 1.0
    elif not (isinstance(bound, int | float) and np.isfinite(bound) and bound > 0):
        raise ValueError(f"bound must be a positive finite number, got {bound!r}")
    result = _value_image(ax, err, SIGNED_CMAP, -bound, bound, colorbar,
                          "fraction − exact area")  # fmt: skip
    if title:
        e = np.abs(err[np.isfinite(err)])
        mean, worst = (float(e.mean()), float(e.max())) if e.size else (0.0, 0.0)
        ax.set_title(f"error vs exact area: mean {mean:.3f}, max {worst:.3f}")
    return result


# -- one pixel, magnified ----------------------------------------------------------------------
@dataclass
class PixelSampleArtists(Artists):
    """One magnified pixel of :func:`plot_pixel_samples`; :meth:`update` moves it in place."""

    square: Line2D
    centre: Line2D
    edges: list = field(default_factory=list)
    dots: list = field(default_factory=list)
    labels: list = field(default_factory=list)

    def update(self, source, row: int, col: int, *, triangles=None) -> None:
        """Show pixel (row, col) of ``source`` (the pattern may change: dots are redrawn)."""
        ax = self.square.axes
        for artist in [*self.edges, *self.dots, *self.labels]:
            artist.remove()
        self.edges, self.dots, self.labels = [], [], []
        ids, offsets = sample_data(source)
        # wider than tall: a sample near a side has its edge values beside it, in the margin
        ax.set_xlim(col - MARGIN_X, col + 1 + MARGIN_X)
        ax.set_ylim(row + 1 + MARGIN_Y, row - MARGIN_Y)
        ax.set_xticks([col, col + 0.5, col + 1])  # the pixel's sides and centre, uncrowded
        ax.set_yticks([row, row + 0.5, row + 1])
        self.square.set_data([col, col + 1, col + 1, col, col], [row, row, row + 1, row + 1, row])
        self.centre.set_data([col + 0.5], [row + 0.5])
        trace = getattr(getattr(source, "trace", None), "samples", None)
        if triangles is None and trace is not None:
            triangles = [source.trace.snapped]
        frame = isinstance(source, Frame)
        for t, tri in enumerate(np.asarray(triangles if triangles is not None else [])):
            closed = np.vstack([tri, tri[:1]])
            color = TRIANGLE_COLORS[t % len(TRIANGLE_COLORS)] if frame else COLORS["edge"]
            # above the margin labels' boxes (4.5), under the dots (5): a box never breaks an
            # edge where it leaves the pixel (review r13, 08)
            self.edges += ax.plot(closed[:, 0], closed[:, 1], color=color, lw=lw(0.8),
                                  zorder=4.6)  # fmt: skip
        values = None if trace is None else trace.edge_values(row, col)
        names = [] if trace is None else [edge_name(a, b) for a, b in source.trace.edges]
        # room for each sample's edge values; else its number only (labels at least 0.75 of the
        # style's font size: classroom-legible in a panel a third of the column wide)
        few = len(offsets) <= 4
        for s, (ox, oy) in enumerate(offsets):
            t = int(ids[row, col, s])
            color = "white" if t < 0 else TRIANGLE_COLORS[t % len(TRIANGLE_COLORS)]
            self.dots += ax.plot([col + ox], [row + oy], "o", ms=ms(1.4 if few else MANY_DOTS),
                                 mfc=color, mec=COLORS["edge"], zorder=5)  # fmt: skip
            if not few:
                continue
            label = _label(s, t, None if values is None else values[s], names)
            self.labels.append(_margin_label(ax, label, row, col, ox, oy))
        if not few:  # numbers only, each placed clear of the others, the dots and the centre
            ax.apply_aspect()  # the pixel's size as drawn: its sides are obstacles
            self.labels += _place_numbers(ax, col + offsets[:, 0], row + offsets[:, 1],
                                          (col + 0.5, row + 0.5), ms(MANY_DOTS),
                                          lines=self.edges)  # fmt: skip
        else:
            _fit_labels(ax, self.labels, row, col, lines=self.edges)
        covered = int((ids[row, col] >= 0).sum())
        key = ""
        if values is not None:
            key = f"\nbeside each: {', '.join(names)}" if few else "\nedge values: table below"
        ax.set_title(f"pixel (row {row}, col {col})\n{covered} of {len(offsets)} covered{key}",
                     fontsize=fs(0.85))  # fmt: skip


#: Points between the pixel's side and a sample's label box in the margin beside it.
LABEL_GAP = 6.0

#: The magnified pixel's dots with more than 4 samples, times the style's marker size: 1.0
#: drew 16 dots about 10 px across in a 900-px figure, small on a projector (review r230).
MANY_DOTS = 1.2


def _margin_label(ax, text: str, row: int, col: int, ox: float, oy: float):
    """A sample's label in the panel's margin, beside the pixel on the sample's side, at the
    sample's height, joined to its dot by a thin leader.

    Edge values are a column of numbers: drawn next to the dot they ran over the pixel's
    frame (s1's "+132.31" of lesson 08 c32; reviews r8-r11, 08-1), and earlier a label's
    box half-covered a sample's marker (review r9). Outside the frame they cross neither;
    the standard and ordered 4-sample patterns put at most two samples on a side, half a
    pixel apart (:func:`_fit_labels` keeps their labels apart and inside the panel).
    """
    side, size = (-1 if ox < 0.5 else 1), fs(0.75)
    return ax.annotate(
        text, (col + ox, row + oy), xytext=(col + (side > 0), row + oy),
        textcoords=_beside(ax, side, size),
        ha="left" if side > 0 else "right", va="center", fontsize=size, bbox=label_box(0.8),
        zorder=4.5, arrowprops=dict(arrowstyle="-", color=COLORS["centre"], lw=lw(0.3),
                                    ls=(0, (2, 2)), shrinkA=0, shrinkB=ms(1.4) / 2),
    )  # fmt: skip


def _beside(ax, side: int, size: float, dy_pt: float = 0.0):
    """Text coordinates of a margin label: data, moved ``side`` × (LABEL_GAP + the box's pad)
    points across and ``dy_pt`` points up (in points: the panel's limits change, the pixel's
    sides move with them)."""
    return offset_copy(ax.transData, fig=ax.figure, units="points",
                       x=side * (LABEL_GAP + 0.2 * size), y=dy_pt)  # fmt: skip


#: The panel's least margins around the pixel (pixels): wider than tall, as :meth:`update`
#: sets them before the labels widen them.
MARGIN_X, MARGIN_Y = 0.28, 0.15


def _fit_labels(ax, labels, row: int, col: int, *, lines=(), gap_pt: float = 6.0) -> None:
    """Keep the margin labels apart, off the triangle's edge ``lines`` and inside the panel,
    with no more room around the pixel than they take.

    Labels on one side of the pixel that would overlap move apart, and a label an edge line
    runs through moves up or down until it clears it (:func:`_spread_labels`); then the
    margins are solved for: the labels reach a fixed number of points beyond each of the
    pixel's sides, so with ``l`` and ``r`` display pixels of them left and right and an Axes
    box ``W`` wide, the pixel gets ``W - l - r`` display pixels (likewise in height; the
    smaller wins, the aspect is equal, and the box shrinks to the limits in the other
    direction). Each side has its own margin: one margin for both sides left the panel's
    bottom third empty when only the top labels reached out (review r230 FIG2). s1's
    "+132.31" of lesson 08 c32 ran over the panel's right frame (review r10); widening by the
    overflow alone took six rounds (a wider view shrinks the pixel, and the labels move with
    its sides). Heights depend on the pixel's size (the dots move), hence a few rounds.
    """
    if not labels:
        return
    fig = ax.figure
    renderer = fig.canvas.get_renderer()
    to_px = fig.dpi / 72.0
    room = ax.get_position(original=True).transformed(fig.transFigure)  # before the aspect
    for _ in range(4):
        ax.apply_aspect()
        _spread_labels(ax, labels, renderer, gap_pt=2.0, lines=lines)
        (px0, py0), (px1, py1) = ax.transData.transform([(col, row + 1), (col + 1, row)])
        # display pixels beyond each side of the pixel, gap and pad in: left, right, bottom, top
        need = np.zeros(4)
        for label in labels:
            box = label.get_window_extent(renderer)
            pad = (0.2 * label.get_fontsize() + gap_pt) * to_px  # label_box's pad, a gap
            need = np.maximum(need, [px0 - box.x0 + pad, box.x1 - px1 + pad,
                                     py0 - box.y0 + pad, box.y1 - py1 + pad])  # fmt: skip
        side = min(_pixel_side(room.width, need[0], need[1], MARGIN_X),
                   _pixel_side(room.height, need[2], need[3], MARGIN_Y))  # fmt: skip
        # labels too large for the panel (a tiny figure): a pixel a quarter of it, cut labels
        side = max(side, 0.25 * min(room.width, room.height))
        ml, mr = (max(MARGIN_X, n / side) for n in need[:2])
        mb, mt = (max(MARGIN_Y, n / side) for n in need[2:])
        limits = ((col - ml, col + 1 + mr), (row + 1 + mb, row - mt))  # y runs down
        now = (ax.get_xlim(), ax.get_ylim())
        if np.abs(np.subtract(limits, now)).max() * side < 0.5:
            return
        ax.set_xlim(*limits[0])
        ax.set_ylim(*limits[1])


def _pixel_side(room: float, before: float, after: float, least: float) -> float:
    """The pixel's side, in display pixels, when ``room`` holds it and on each side of it the
    larger of what the labels there need (``before``, ``after``) and ``least`` times the side
    (the least margin, in pixels of the image).

    >>> round(_pixel_side(340.0, 0.0, 100.0, 0.28), 1)  # labels on the right only
    187.5
    """
    side = room - before - after
    for _ in range(12):  # each round shrinks the error by 2 * least at most: it converges
        side = room - max(before, least * side) - max(after, least * side)
    return side


def _spread_labels(ax, labels, renderer, *, gap_pt: float, lines=()) -> None:
    """Labels on one side of the pixel, each first at its dot's height, moved apart where
    their boxes would overlap: each pair that would, by half the overlap up and half down
    (the standard and ordered patterns have at most two samples on a side). Then a label
    that an edge line crosses moves to the nearest height where it clears every line and
    label (:func:`_off_lines`): the edge, drawn over the labels' boxes so that no box breaks
    it, ran through the edge values ("+127.91" in lesson 08's inspector)."""
    to_pt = 72.0 / ax.figure.dpi
    for side in (-1, 1):
        mine = [lab for lab in labels if (lab.get_ha() == "left") == (side > 0)]
        moved = {id(lab): 0.0 for lab in mine}  # points up from the dot's height
        for lab in mine:
            lab.anncoords = _beside(ax, side, lab.get_fontsize())
        # top first (display y runs up)
        mine.sort(key=lambda lab: -ax.transData.transform(lab.xy)[1])
        for upper, lower in zip(mine, mine[1:]):
            pad = 0.2 * upper.get_fontsize() + 0.2 * lower.get_fontsize()
            a = upper.get_window_extent(renderer)
            b = lower.get_window_extent(renderer)
            overlap = (b.y1 - a.y0) * to_pt + pad + gap_pt
            if overlap > 0:
                for lab, sign in ((upper, 1), (lower, -1)):
                    moved[id(lab)] += sign * overlap / 2
                    lab.anncoords = _beside(ax, side, lab.get_fontsize(), moved[id(lab)])
        if lines:
            _off_lines(ax, mine, moved, side, renderer, lines, gap_pt=gap_pt)


def _padded_box(label, renderer, gap_pt: float) -> Bbox:
    """The display box of a label's text with its white box's pad (``label_box``) and
    ``gap_pt`` points around it (the Annotation's own extent includes its leader)."""
    label.update_positions(renderer)  # its text where its coordinates now put it
    box = Text.get_window_extent(label, renderer)
    pad = (0.2 * label.get_fontsize() + gap_pt) * label.figure.dpi / 72.0
    return Bbox.from_extents(box.x0 - pad, box.y0 - pad, box.x1 + pad, box.y1 + pad)


def _off_lines(ax, mine, moved, side, renderer, lines, *, gap_pt: float) -> None:
    """Move each label of ``mine`` (one side of the pixel) that a line of ``lines`` crosses
    up or down, by the least number of points that clears every line; a label in the way is
    pushed along, and must clear the lines too. ``moved`` holds each label's shift from its
    dot's height, in points."""
    paths = [line.get_transform().transform_path(line.get_path()) for line in lines]
    to_px = ax.figure.dpi / 72.0
    gap = gap_pt * to_px
    # the panel's whole box: a label pushed beyond it (two edges crossing near a pixel by a
    # triangle's corner) made the margins grow until the pixel shrank to a quarter of the
    # panel and a label sat on the title; there it stays crossed instead
    room = ax.get_position(original=True).transformed(ax.figure.transFigure)

    def crossed(box, dy):
        grown = Bbox.from_extents(box.x0 - gap, box.y0 - gap + dy, box.x1 + gap, box.y1 + gap + dy)
        return any(p.intersects_bbox(grown, filled=False) for p in paths)

    def clear(boxes, shifts):
        inside = all(room.y0 <= b.y0 + dy and b.y1 + dy <= room.y1 for b, dy in zip(boxes, shifts))
        return inside and not any(crossed(b, dy) for b, dy in zip(boxes, shifts) if dy)

    mine = sorted(mine, key=lambda lab: -_padded_box(lab, renderer, 0.0).y0)  # top first
    for i in range(len(mine)):
        boxes = [_padded_box(o, renderer, 0.0) for o in mine]
        if not crossed(boxes[i], 0.0):
            continue
        for step in np.arange(2.0, 120.0, 2.0):  # points, up first, then down
            shifts = next((d for d in (_pushed(boxes, i, sign * step * to_px, gap)
                                       for sign in (1, -1)) if clear(boxes, d)), None)  # fmt: skip
            if shifts is not None:
                for o, dy in zip(mine, shifts):
                    moved[id(o)] += dy / to_px
                    o.anncoords = _beside(ax, side, o.get_fontsize(), moved[id(o)])
                break


def _pushed(boxes, i: int, dy: float, gap: float) -> list:
    """Display shifts of ``boxes`` (a column, top first) when box ``i`` moves ``dy`` up
    (negative: down): the boxes it runs into are pushed on, ``gap`` apart."""
    shifts = [0.0] * len(boxes)
    shifts[i] = dy
    order = range(i - 1, -1, -1) if dy > 0 else range(i + 1, len(boxes))
    prev = i
    for j in order:
        if dy > 0:  # box j is above box prev
            need = boxes[prev].y1 + shifts[prev] + gap - boxes[j].y0
        else:
            need = boxes[prev].y0 + shifts[prev] - gap - boxes[j].y1
        shifts[j] = max(need, 0.0) if dy > 0 else min(need, 0.0)
        prev = j
    return shifts


def _label(s, t, e, names) -> str:
    """A sample's label: its number and the triangle that covers it (a scene), or its number
    and its edge values one per line, in the order ``names`` gives in the title (one triangle:
    the dot's fill already says whether it is covered)."""
    if e is None:  # two lines: a narrow label in the margin leaves the pixel its room
        return f"s{s}\n" + ("—" if t < 0 else f"triangle {t}")
    return f"s{s}\n" + "\n".join(edge_value_text(v) for v in e)


def edge_value_text(v: float) -> str:
    """An edge value as the labels show it: "0" when exactly on the edge (where the top-left
    rule decides), else signed with two decimals (one precision for every label), and in
    scientific notation when that would round a non-zero value to 0.00.

    The sign of a negative value is the minus sign "−", as in the lesson's text (review r287
    S3: "-4.86" beside the text's "−4.86").

    >>> [edge_value_text(v) for v in (0.0, -2.0, 10.3125, 0.001)]
    ['0', '−2.00', '+10.31', '+1.0e-03']
    """
    if v == 0:
        return "0"
    text = f"{v:+.2f}" if abs(v) >= 0.005 else f"{v:+.1e}"
    return "−" + text[1:] if text.startswith("-") else text


def _place_numbers(ax, xs, ys, centre, dot_pt: float, *, lines=()) -> list:
    """Sample numbers ``0 … n-1`` beside the dots at ``xs``, ``ys`` (data), each at the first
    of eight directions (then farther) where its box clears the labels placed before, every
    dot and the centre's cross (``dot_pt``: the dots' and the cross's size in points).
    Random patterns put samples close together: fixed offsets printed "2" and "13" as "213".
    The pixel's sides are obstacles too, and every box keeps ``NUMBER_GAP`` points from the
    next: with 16 random samples "13" and "11" sat on the pixel's top side and "12 9" touched
    (review r26, lesson 08 c34). The triangle's edge ``lines`` are obstacles too (review
    r29, 08-2). A number whose centre lies outside the pixel square counts half a
    collision: the inside wins wherever it is free (review r92: "12", "13" and "15" sat
    outside the square at 16 samples).
    """
    fig = ax.figure
    to_pt = 72.0 / fig.dpi
    pts = ax.transData.transform(np.column_stack([xs, ys])) * to_pt
    c = ax.transData.transform([centre])[0] * to_pt
    size = fs(0.75)
    r = dot_pt / 2 + 1.0
    # obstacles as (x0, y0, x1, y1) in points: the dots, the centre's cross, the pixel's sides
    blocked = [(x - r, y - r, x + r, y + r) for x, y in pts]
    blocked.append((c[0] - r, c[1] - r, c[0] + r, c[1] + r))
    (sx0, sy0), (sx1, sy1) = np.sort(ax.transData.transform(
        [np.subtract(centre, 0.5), np.add(centre, 0.5)]) * to_pt, axis=0)  # fmt: skip
    half = 1.5  # half a side's width, in points
    blocked += [(sx0 - half, sy0, sx0 + half, sy1), (sx1 - half, sy0, sx1 + half, sy1),
                (sx0, sy0 - half, sx1, sy0 + half), (sx0, sy1 - half, sx1, sy1 + half)]  # fmt: skip
    frame = ax.get_window_extent()
    x_lo, y_lo = frame.x0 * to_pt, frame.y0 * to_pt
    x_hi, y_hi = frame.x1 * to_pt, frame.y1 * to_pt
    paths = [line.get_transform().transform_path(line.get_path()) for line in lines]
    to_px = fig.dpi / 72.0
    directions = [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, 1), (1, -1), (-1, -1)]
    labels = []
    for s, (x, y) in enumerate(pts):
        w, h = 0.62 * size * len(str(s)) + 2 + NUMBER_GAP, size + 1 + NUMBER_GAP
        best, best_hits = None, None
        # the leader's room first; without it next (a number by its dot needs no leader) before
        # a number goes further out, or outside the pixel square (review r92 08)
        for reach, lead in ((1.0, LEADER_PT), (1.0, 0.0), (1.8, LEADER_PT), (2.6, LEADER_PT)):
            for dx, dy in directions:
                ox = dx * (r + w / 2 + lead) * reach
                oy = dy * (r + h / 2 + lead) * reach
                box = (x + ox - w / 2, y + oy - h / 2, x + ox + w / 2, y + oy + h / 2)
                inside = box[0] >= x_lo and box[2] <= x_hi and box[1] >= y_lo and box[3] <= y_hi
                hits = sum(_overlap(box, b) for b in blocked) + (0 if inside else 10)
                # outside the pixel square a number is read with no dot (review r92, 08):
                # a half penalty, less than any collision, more than none
                own = sx0 <= x + ox <= sx1 and sy0 <= y + oy <= sy1
                hits += 0 if own else 0.5
                hits += _nearer_dot(pts, s, x + ox, y + oy)
                on_line = Bbox.from_extents(*(np.array(box) * to_px))
                hits += sum(p.intersects_bbox(on_line, filled=False) for p in paths)
                if best_hits is None or hits < best_hits:
                    best, best_hits = (ox, oy, box), hits
                if hits == 0:
                    break
            if best_hits == 0:
                break
        ox, oy, box = best
        blocked.append(box)
        # a leader from the number to its dot: with 16 random samples a number could sit
        # between two dots and name either (review r136 08-10)
        labels.append(ax.annotate(str(s), (xs[s], ys[s]), xytext=(ox, oy),
                                  textcoords="offset points", ha="center", va="center",
                                  fontsize=size, zorder=6,
                                  arrowprops=dict(arrowstyle="-", color="black",
                                                  lw=max(0.8, lw(0.3)), shrinkA=0,
                                                  shrinkB=dot_pt / 2)))  # fmt: skip
    return labels


#: Points kept between two sample numbers' boxes (and a number and a dot or the pixel's side).
NUMBER_GAP = 3.0

#: Points between a sample's dot and its number's box: room for the leader joining them to
#: show (review r136 08-10).
LEADER_PT = 4.0


def _nearer_dot(pts, s: int, x: float, y: float) -> int:
    """1 when a number's centre at ``x``, ``y`` (points) lies nearer another dot of ``pts``
    than its own dot ``s`` (within :data:`OWN_DOT_MARGIN`), else 0: a number read with the
    wrong dot. With 16 random samples "12" stood between three dots, and "10 12" read as a
    pair (review r35, lesson 08 item 6)."""
    d = np.hypot(pts[:, 0] - x, pts[:, 1] - y)
    others = np.delete(d, s)
    return int(others.size > 0 and others.min() < OWN_DOT_MARGIN * d[s])


#: A number's own dot must be this much nearer than any other (see :func:`_nearer_dot`);
#: 1.25 left "6" between its dot and 8's at 16 random samples (review r69, 08-2).
OWN_DOT_MARGIN = 1.6


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def plot_pixel_samples(ax, source, row: int, col: int, *, triangles=None) -> PixelSampleArtists:
    """Pixel (row, col) magnified: its samples, who owns each, the edges that decided it.

    Parameters
    ----------
    source : Fill or Frame
        Multisampled. A Fill rasterised with ``trace=True`` also labels every sample with
        its three edge values, named as in the captions (E12, E23, E31 for v1→v2→v3; px²,
        oriented edges in test order; positive = inside).
    row, col : int
        The pixel.
    triangles : (N, 3, 2) array-like, optional
        Window positions of the triangles, to draw their edges through the pixel (for a
        Fill the traced snapped triangle is drawn by default).
    """
    ax.set_aspect("equal")
    square = ax.plot([], [], color=COLORS["grid"], lw=lw(0.6))[0]
    centre = ax.plot([], [], "+", color=COLORS["centre"], ms=ms(1.0))[0]
    result = PixelSampleArtists(square, centre)
    result.update(source, row, col, triangles=triangles)
    return result
