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

    def update(self, source) -> None:
        """Show another multisampled fill or frame (any size and pattern)."""
        ids, offsets = sample_data(source)
        x, y, t = _positions(ids, offsets)
        hit = t >= 0
        self.covered.set_offsets(np.column_stack([x[hit], y[hit]]))
        self._faces = [TRIANGLE_COLORS[i % len(TRIANGLE_COLORS)] for i in t[hit]]
        self.set_rings(self.rings)
        self.uncovered.set_data(x[~hit], y[~hit])
        d = _dot_diameter(self.covered.axes, offsets)
        self.covered.set_sizes([d**2])
        self.uncovered.set_markersize(d)
        if self.fraction is not None:
            self.fraction.update((ids >= 0).mean(axis=2))

    def set_rings(self, on: bool) -> None:
        """Covered samples as hollow rings (``on``) or dots filled in their triangle's colour.

        A fill's last step colours its pixels by an attribute: filled dots, four to a pixel
        under 4× MSAA, hid those colours, and their blue read as the colour map's low end
        (review r11, lesson 00 c14). A ring shows the pixel's colour through it; white with
        a black rim, it stays visible on the dark and the light end of the map alike.
        """
        self.rings = bool(on)
        edge, ring, rim = self._widths
        if self.rings:
            self.covered.set_facecolor("none")
            self.covered.set_edgecolor("white")
            self.covered.set_linewidth(ring)
            self.covered.set_path_effects([withStroke(linewidth=rim, foreground=COLORS["edge"])])
        else:
            self.covered.set_facecolor(self._faces)
            self.covered.set_edgecolor(COLORS["edge"])
            self.covered.set_linewidth(edge)
            self.covered.set_path_effects([])


def _dot_diameter(ax, offsets) -> float:
    """The samples' dot size in points: the style's, or less where the pattern's closest
    two samples (in a pixel or across a pixel side) would make their dots touch at this
    magnification (the standard 4-sample pattern's dots overlapped in a 12-pixel-wide panel).
    """
    largest = ms(0.55) * 1.26
    if len(offsets) < 2:
        return largest
    shifts = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [-1, 1]], dtype=float)
    pts = (offsets[None, :, :] + shifts[:, None, :]).reshape(-1, 2)
    gaps = np.hypot(*(offsets[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
    gap = float(gaps[gaps > 1e-9].min())  # data units (pixels)
    (x0, x1), bbox = ax.get_xlim(), ax.get_window_extent()
    pt_per_px = bbox.width / abs(x1 - x0) * 72.0 / ax.figure.dpi
    return float(min(largest, 0.8 * gap * pt_per_px))


def plot_samples(ax, source, *, fraction: bool = True) -> SampleArtists:
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
    result = SampleArtists(frac, covered, uncovered, _widths=widths)
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
        ax.set_xlim(col - 0.28, col + 1.28)
        ax.set_ylim(row + 1.15, row - 0.15)
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
            self.edges += ax.plot(closed[:, 0], closed[:, 1], color=color, lw=lw(0.8))
        values = None if trace is None else trace.edge_values(row, col)
        names = [] if trace is None else [edge_name(a, b) for a, b in source.trace.edges]
        # room for each sample's edge values; else its number only (labels at least 0.75 of the
        # style's font size: classroom-legible in a panel a third of the column wide)
        few = len(offsets) <= 4
        for s, (ox, oy) in enumerate(offsets):
            t = int(ids[row, col, s])
            color = "white" if t < 0 else TRIANGLE_COLORS[t % len(TRIANGLE_COLORS)]
            self.dots += ax.plot([col + ox], [row + oy], "o", ms=ms(1.4 if few else 1.0),
                                 mfc=color, mec=COLORS["edge"], zorder=5)  # fmt: skip
            if not few:
                continue
            label = _label(s, t, None if values is None else values[s], names)
            # edge values (a narrow column, one value per line, centred on the dot) point out
            # of the pixel, into the panel's margin, so that the labels of the standard and
            # the ordered 4-sample patterns clear each other
            # (clear of the dot, and under it: a label's box half-covered a sample's marker,
            # review r9 lesson 08 c32)
            side = -1 if ox < 0.5 else 1
            self.labels.append(ax.annotate(
                label, (col + ox, row + oy), xytext=(11 * side, 0), textcoords="offset points",
                ha="left" if side > 0 else "right", va="center", fontsize=fs(0.75),
                bbox=label_box(0.8), zorder=4.5,
            ))  # fmt: skip
        if not few:  # numbers only, each placed clear of the others, the dots and the centre
            self.labels += _place_numbers(ax, col + offsets[:, 0], row + offsets[:, 1],
                                          (col + 0.5, row + 0.5), ms(1.0))  # fmt: skip
        else:
            _fit_labels(ax, self.labels)
        covered = int((ids[row, col] >= 0).sum())
        key = ""
        if values is not None:
            key = f"\nbeside each: {', '.join(names)}" if few else "\nedge values: table below"
        ax.set_title(f"pixel ({row}, {col})\n{covered} of {len(offsets)} covered{key}",
                     fontsize=fs(0.85))  # fmt: skip


def _fit_labels(ax, labels, *, gap_pt: float = 6.0) -> None:
    """Widen the panel's limits (evenly: the pixel stays in the middle) until every label and
    its box lie inside the frame: s1's "+132.31" of lesson 08 c32 ran over the right frame
    (review r10). Measured on the figure's renderer, in a few rounds (a wider view shrinks
    the pixel, which moves the dots, not the labels' offsets in points)."""
    if not labels:
        return
    fig = ax.figure
    renderer = fig.canvas.get_renderer()
    to_px = fig.dpi / 72.0
    for _ in range(4):
        ax.apply_aspect()
        frame = ax.get_window_extent(renderer)
        over_x = over_y = 0.0
        for label in labels:
            box = label.get_window_extent(renderer)
            pad = (0.2 * label.get_fontsize() + gap_pt) * to_px  # label_box's pad, a gap
            over_x = max(over_x, frame.x0 - box.x0 + pad, box.x1 - frame.x1 + pad)
            over_y = max(over_y, frame.y0 - box.y0 + pad, box.y1 - frame.y1 + pad)
        if over_x <= 0.5 and over_y <= 0.5:
            return
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        per_px = abs(x1 - x0) / frame.width  # data units per display pixel (equal aspect)
        if over_x > 0.5:
            ax.set_xlim(x0 - over_x * per_px, x1 + over_x * per_px)
        if over_y > 0.5:  # y runs down: the first limit is the bottom
            ax.set_ylim(y0 + over_y * per_px, y1 - over_y * per_px)


def _label(s, t, e, names) -> str:
    """A sample's label: its number and the triangle that covers it (a scene), or its number
    and its edge values one per line, in the order ``names`` gives in the title (one triangle:
    the dot's fill already says whether it is covered)."""
    if e is None:
        return f"s{s}: " + ("—" if t < 0 else f"triangle {t}")
    return f"s{s}\n" + "\n".join(edge_value_text(v) for v in e)


def edge_value_text(v: float) -> str:
    """An edge value as the labels show it: "0" when exactly on the edge (where the top-left
    rule decides), else signed with two decimals (one precision for every label), and in
    scientific notation when that would round a non-zero value to 0.00.

    >>> [edge_value_text(v) for v in (0.0, -2.0, 10.3125, 0.001)]
    ['0', '-2.00', '+10.31', '+1.0e-03']
    """
    if v == 0:
        return "0"
    return f"{v:+.2f}" if abs(v) >= 0.005 else f"{v:+.1e}"


def _place_numbers(ax, xs, ys, centre, dot_pt: float) -> list:
    """Sample numbers ``0 … n-1`` beside the dots at ``xs``, ``ys`` (data), each at the first
    of eight directions (then farther) where its box clears the labels placed before, every
    dot and the centre's cross (``dot_pt``: the dots' and the cross's size in points).
    Random patterns put samples close together: fixed offsets printed "2" and "13" as "213".
    """
    fig = ax.figure
    to_pt = 72.0 / fig.dpi
    pts = ax.transData.transform(np.column_stack([xs, ys])) * to_pt
    c = ax.transData.transform([centre])[0] * to_pt
    size = fs(0.75)
    r = dot_pt / 2 + 1.0
    # obstacles as (x0, y0, x1, y1) in points: the dots and the centre's cross
    blocked = [(x - r, y - r, x + r, y + r) for x, y in pts]
    blocked.append((c[0] - r, c[1] - r, c[0] + r, c[1] + r))
    frame = ax.get_window_extent()
    x_lo, y_lo = frame.x0 * to_pt, frame.y0 * to_pt
    x_hi, y_hi = frame.x1 * to_pt, frame.y1 * to_pt
    directions = [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, 1), (1, -1), (-1, -1)]
    labels = []
    for s, (x, y) in enumerate(pts):
        w, h = 0.62 * size * len(str(s)) + 2, size + 1
        best, best_hits = None, None
        for reach in (1.0, 1.8, 2.6):
            for dx, dy in directions:
                ox = dx * (r + w / 2 + 1) * reach
                oy = dy * (r + h / 2 + 1) * reach
                box = (x + ox - w / 2, y + oy - h / 2, x + ox + w / 2, y + oy + h / 2)
                inside = box[0] >= x_lo and box[2] <= x_hi and box[1] >= y_lo and box[3] <= y_hi
                hits = sum(_overlap(box, b) for b in blocked) + (0 if inside else 10)
                if best_hits is None or hits < best_hits:
                    best, best_hits = (ox, oy, box), hits
                if hits == 0:
                    break
            if best_hits == 0:
                break
        ox, oy, box = best
        blocked.append(box)
        labels.append(ax.annotate(str(s), (xs[s], ys[s]), xytext=(ox, oy),
                                  textcoords="offset points", ha="center", va="center",
                                  fontsize=size, zorder=6))  # fmt: skip
    return labels


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
