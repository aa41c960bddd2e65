"""Plots of one fill: the pixel grid, the triangle, the bounding box, the split, each step.

Every function draws on the Axes it is given and returns an :class:`~.common.Artists`
dataclass (iterable like a list of the artists it created). Results that a view updates in
place also have an ``update(...)`` method, which changes the *existing* artists' data
(``set_data``, ``set_xy``, ``set_text``, ``set_visible``) and never adds new ones.

Coordinates follow CONVENTIONS: pixel (row i, col j) is the square [j, j+1] × [i, i+1] with
y down, its centre (the sample point) at (j + 0.5, i + 0.5).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap, Normalize
from matplotlib.lines import Line2D
from matplotlib.patches import FancyArrowPatch, Patch, Polygon, Rectangle
from matplotlib.patheffects import withStroke
from matplotlib.text import Text

from ..core.bbox import BBox
from ..core.fill import Fill
from ..core.trace import FillTrace, Step, edge_name
from ..core.triangle import Triangle
from ..core.validate import as_int, as_size
from .common import (
    Artists,
    annotate_near,
    as_coverage,
    as_trace,
    fs,
    label_box,
    lw,
    ms,
    pixel_axes,
    set_image,
    show_image,
    tint,
    two_colour,
)
from .label_places import (
    boxes_around,
    inside_share,
    length_inside,
    place_edge_labels,
    place_vertex_labels,
)
from .style import COLORS, SIGNED_CMAP, VALUE_CMAP

#: Above this many pixels along a side the grid lines would merge into grey: none are drawn.
GRID_LIMIT = 96
#: Numbers are written into cells only when the plotted region has at most this many pixels.
ANNOTATE_LIMIT = 256


# -- the pixel grid ----------------------------------------------------------------------------
@dataclass
class GridArtists(Artists):
    """Pixel boundaries (one LineCollection) of a :func:`plot_pixel_grid`."""

    lines: LineCollection

    ticks: int = 8

    def update(self, width: int, height: int) -> None:
        """Redraw for a new image size (same artist)."""
        self.lines.set_segments(grid_segments(width, height))
        pixel_axes(self.lines.axes, width, height, ticks=self.ticks > 0, most=self.ticks)


def grid_segments(width: int, height: int) -> list:
    """The pixel grid's lines of a ``width`` × ``height`` image as segments (none past
    ``GRID_LIMIT``), for a LineCollection."""
    # Python ints: np.arange(np.uint8(255) + 1) would wrap to an empty grid.
    width, height = as_size("width", width), as_size("height", height)
    if max(width, height) > GRID_LIMIT:
        return []
    xs, ys = np.arange(width + 1), np.arange(height + 1)
    vertical = [((x, 0), (x, height)) for x in xs]
    horizontal = [((0, y), (width, y)) for y in ys]
    return vertical + horizontal


def plot_pixel_grid(ax, width: int, height: int, *, ticks: bool | int = True) -> GridArtists:
    """Draw the boundaries of a ``height`` × ``width`` pixel grid and set up pixel axes.

    The axes get x from 0 to ``width``, y from ``height`` (bottom) to 0 (top), equal aspect,
    and ticks on pixel centres labelled with column and row indices (x axis on top).

    Parameters
    ----------
    ax : matplotlib Axes
    width, height : int
        Image size in pixels. Beyond :data:`GRID_LIMIT` pixels no lines are drawn.
    ticks : bool or int
        Label rows and columns: True for at most 8 labels per axis, an int for at most that
        many (fewer labels also draw faster), False for no ticks at all.

    Returns
    -------
    GridArtists
        ``lines``: the LineCollection of pixel boundaries.
    """
    lines = LineCollection(
        grid_segments(width, height),
        colors=COLORS["grid"],
        linewidths=max(0.6, lw(0.25)),
        zorder=1.5,  # above images (zorder 0), below everything else
    )
    ax.add_collection(lines, autolim=False)
    if isinstance(ticks, bool | np.bool_):
        most = 8 if ticks else 0
    else:
        most = as_int("ticks", ticks, minimum=0)
    pixel_axes(ax, width, height, ticks=most > 0, most=most)
    return GridArtists(lines, most)


# -- pixel centres -----------------------------------------------------------------------------
@dataclass
class CentreArtists(Artists):
    """Pixel centres of a :func:`plot_pixel_centres`: covered (filled dots) and the rest."""

    inside: Line2D
    outside: Line2D

    def update(self, width: int, height: int, coverage=None) -> None:
        """Move the dots to a new grid size and/or coverage."""
        (xi, yi), (xo, yo) = _centres(width, height, coverage)
        self.inside.set_data(xi, yi)
        self.outside.set_data(xo, yo)


def _centres(width, height, coverage):
    width, height = as_size("width", width), as_size("height", height)
    rows, cols = np.indices((height, width))
    x, y = cols.ravel() + 0.5, rows.ravel() + 0.5
    if coverage is None:
        return (x[:0], y[:0]), (x, y)
    cov = as_coverage(coverage).ravel()
    return (x[cov], y[cov]), (x[~cov], y[~cov])


def plot_pixel_centres(ax, width: int, height: int, coverage=None) -> CentreArtists:
    """Mark every pixel centre (j + 0.5, i + 0.5), the point where coverage is decided.

    Parameters
    ----------
    ax : matplotlib Axes
    width, height : int
        Image size in pixels.
    coverage : (height, width) bool array, Fill, Frame or FillTrace, optional
        If given, covered centres are drawn as filled dots and the others as small hollow
        ones; otherwise all as small grey dots.

    Returns
    -------
    CentreArtists
        ``inside`` and ``outside``: marker-only Line2D artists (fast to redraw).
    """
    (xi, yi), (xo, yo) = _centres(width, height, coverage)
    size = ms(0.32) if max(width, height) <= 48 else ms(0.2)
    inside = ax.plot(xi, yi, "o", ms=size * 1.3, color=COLORS["edge"], zorder=3.5)[0]
    outside = ax.plot(
        xo, yo, "o", ms=size, mfc=COLORS["centre"] if coverage is None else "none",
        mec=COLORS["centre"], mew=max(0.8, lw(0.25)), zorder=3.5,
    )[0]  # fmt: skip
    return CentreArtists(inside, outside)


# -- coverage ----------------------------------------------------------------------------------
@dataclass
class CoverageArtists(Artists):
    """The coverage image of :func:`plot_coverage` (its data is exactly the coverage, 0/1)."""

    image: object

    def update(self, coverage) -> None:
        """Show new coverage in the same image."""
        self.image = set_image(self.image, as_coverage(coverage).astype(np.float64))


def plot_coverage(ax, coverage, *, color=None, alpha: float | None = None) -> CoverageArtists:
    """Colour the covered pixels; uncovered ones stay transparent so the grid shows through.

    Parameters
    ----------
    ax : matplotlib Axes
    coverage : (H, W) bool array, Fill, Frame or FillTrace
        Which pixels to colour (a Frame: pixels any triangle wrote).
    color : colour, optional
        Default: the "fill" colour of :data:`~teachraster.plotting.style.COLORS`.
    alpha : float, optional
        Opacity of the filled pixels (default opaque, which is also fastest to draw).

    Returns
    -------
    CoverageArtists
        ``image``: an AxesImage whose data is the coverage as 0.0 / 1.0.
    """
    cov = as_coverage(coverage).astype(np.float64)
    cmap = two_colour(COLORS["fill"] if color is None else color)
    im = show_image(ax, cov, cmap=cmap, vmin=0, vmax=1, alpha=alpha, zorder=0.5)
    return CoverageArtists(im)


# -- the triangle ------------------------------------------------------------------------------
def _vertices(tri) -> np.ndarray:
    """(3, 2) positions to draw: snapped ones for a fill (what was filled), else as given."""
    if isinstance(tri, FillTrace):
        return tri.snapped
    if isinstance(tri, Fill):
        return as_trace(tri, "plot_triangle").snapped
    if isinstance(tri, Triangle):
        return tri.xy
    xy = np.asarray(tri, dtype=np.float64)
    if xy.shape != (3, 2):
        raise ValueError(f"triangle positions must have shape (3, 2), got {xy.shape}")
    return xy


def _default_edges(tri) -> np.ndarray:
    if isinstance(tri, Fill | FillTrace):
        return as_trace(tri).edges
    return np.array([[0, 1], [1, 2], [2, 0]])


def vertex_names(tri) -> list[str]:
    """Names of the vertices at input positions 0, 1, 2: ``["v1", "v2", "v3"]``.

    One naming everywhere (captions, labels, lessons): vertices are v1, v2, v3 in the order
    given, whatever the method; span tables name their sorted order by role (top, middle,
    bottom) in the captions instead of renaming the vertices. ``tri`` is accepted so that
    callers need not care what they draw.
    """
    return [f"v{k + 1}" for k in range(3)]


def _outward(points: np.ndarray, centre: np.ndarray, dist: float, ax) -> list:
    """Offsets in points pushing labels at ``points`` away from ``centre`` (y flipped)."""
    out = []
    flip = -1.0 if ax.yaxis_inverted() else 1.0  # data y down -> screen y up
    for p in points:
        d = p - centre
        n = float(np.hypot(*d))
        d = d / n if n > 1e-12 else np.array([0.0, -1.0])
        out.append((dist * d[0], flip * dist * d[1]))
    return out


def _area2(xy: np.ndarray) -> float:
    """Twice the signed area of the triangle ``xy`` (3, 2); 0 for three points on one line."""
    (ax_, ay), (bx, by), (cx, cy) = xy[:3]
    return float((bx - ax_) * (cy - ay) - (cx - ax_) * (by - ay))


def _square_to_line(points: np.ndarray, dist: float, ax) -> list:
    """Offsets in points pushing the labels of three points on one line off it, square to it
    and all to one side (above it on the screen; right of a vertical line).

    Pushed away from their centre, as :func:`_outward` does, the labels lay on the line itself
    and their white boxes hid it: review r143 03-9, PlaneExplorer's collinear state showed
    v2-v3 only.
    """
    span = points[:, None, :] - points[None, :, :]
    far = np.unravel_index(np.argmax(np.hypot(span[..., 0], span[..., 1])), span.shape[:2])
    d = span[far]
    n = float(np.hypot(*d))
    if n == 0:  # one point three times: any side will do
        return _outward(points, points[0], dist, ax)
    normal = np.array([-d[1], d[0]]) / n
    up = -1.0 if ax.yaxis_inverted() else 1.0  # which sign of data y is up on the screen
    if normal[1] * up < 0 or (normal[1] == 0 and normal[0] < 0):
        normal = -normal
    flip = -1.0 if ax.yaxis_inverted() else 1.0  # data y down -> screen y up
    return [(dist * normal[0], flip * dist * normal[1])] * len(points)


def _within_sides(ax, points, offsets, size: float) -> list:
    """``offsets`` (points) with the horizontal part mirrored where a label would stick out of
    the Axes' left or right side.

    A vertex at the edge of the grid had its label pushed out of the Axes, onto a key beside
    it (review r13, lesson 02's TriangleEditor) or cut off by the figure (lesson 03's
    PlaneExplorer); mirrored, it stays beside its vertex, inside. ``size``: the labels' font
    size in points (a label is about two characters in a padded box).
    """
    ax.get_xlim()  # brings autoscaled limits up to date before transLimits is read
    width = ax.get_window_extent().width * 72 / ax.figure.dpi  # the Axes' width in points
    if not width > 0:
        return list(offsets)
    # A label may overhang the side by less than half its width (about 0.65 size in its box),
    # as it always could; mirroring every label near a side moved labels that fitted onto
    # the pixels (lesson 00's v2 at x = 13.7 of 16).
    reach = 0.3 * size
    out = []
    for p, (dx, dy) in zip(points, offsets):
        x = ax.transLimits.transform(p)[0] * width  # from the Axes' left side, in points
        if (dx > 0 and x + dx + reach > width) or (dx < 0 and x + dx - reach < 0):
            dx = -dx
        # a label that still overhangs the side (its half width, 0.65 size, past it) was cut
        # by the frame (review r91 04-D: lesson 04's v2, 1.25 px from the side; r93 02-6:
        # lesson 02's v2, by the key): moved in until it touches the side, and above or
        # below its dot if it would cover the dot
        half = 0.85 * size  # two bold characters in their padded box
        inward = min(max(dx, half - x), width - half - x)
        if inward != dx:
            dx = inward
            if abs(dx) < half:
                dy = np.copysign(max(abs(dy), 0.9 * size), dy if dy else 1.0)
        out.append((dx, dy))
    return out


def _within_top_bottom(ax, points, offsets, size: float) -> list:
    """``offsets`` (points) with the vertical part mirrored, or moved in, where a label would
    stick out of the Axes' top or bottom: lesson 03's PlaneExplorer cut "v3" off at the
    figure's bottom with v3 at (16, 14), and drew "v1" over the top of the frame with v1 at
    (2, 1) (review r106 03-W1). A label moved in so far that it would cover its dot is moved
    sideways too. ``size``: the labels' font size in points."""
    height = ax.get_window_extent().height * 72 / ax.figure.dpi  # the Axes' height in points
    width = ax.get_window_extent().width * 72 / ax.figure.dpi
    if not height > 0:
        return list(offsets)
    half, side = 0.75 * size, 0.85 * size  # half of a label's padded box: its height, width
    out = []
    for p, (dx, dy) in zip(points, offsets):
        x, y = ax.transLimits.transform(p) * (width, height)  # from the bottom left, in points
        if not half <= y + dy <= height - half and half <= y - dy <= height - half:
            dy = -dy  # mirrored, it fits
        inward = min(max(dy, half - y), height - half - y)
        if inward != dy:
            dy = inward
            if abs(dy) < half:  # beside its dot rather than on it, and still inside
                dx = np.copysign(max(abs(dx), 1.4 * side), dx if dx else 1.0)
                if not side <= x + dx <= width - side:
                    dx = -dx
        out.append((dx, dy))
    return out


@dataclass
class TriangleArtists(Artists):
    """Artists of :func:`plot_triangle`."""

    outline: Line2D
    vertices: Line2D
    arrows: list = field(default_factory=list)
    labels: list = field(default_factory=list)
    edge_labels: list = field(default_factory=list)
    inside: bool = False  # vertex labels kept off the Axes' sides (see plot_triangle)
    clear: bool = False  # vertex labels placed clear of the edges, dots and each other
    #: with ``clear``: the display boxes (3, 4) the vertex labels were given room for
    label_boxes: np.ndarray = field(default_factory=lambda: np.zeros((0, 4)))
    #: points (n, 2, data coordinates: the pixel centres of a grid) the edge labels keep
    #: clear of, placed on the grid's row boundaries (:func:`place_edge_labels`); None: pushed
    #: outwards from their edges' midpoints
    keep_clear: np.ndarray | None = None
    #: the width (points) of the white halo round the edge labels' letters, if any: the
    #: placement keeps the halo, too, off the centres of ``keep_clear``
    edge_halo: float = 0.0

    def update(self, tri, edges=None) -> None:
        """Move everything to a new triangle (same artists)."""
        xy = _vertices(tri)
        edges = _default_edges(tri) if edges is None else np.asarray(edges)
        closed = np.vstack([xy, xy[:1]])
        self.outline.set_data(closed[:, 0], closed[:, 1])
        self.vertices.set_data(xy[:, 0], xy[:, 1])
        for arrow, (a, b) in zip(self.arrows, edges):
            pa, pb = xy[a], xy[b]
            arrow.set_positions(pa + 0.42 * (pb - pa), pa + 0.58 * (pb - pa))
        ax = self.outline.axes
        centre = xy.mean(axis=0)
        names = vertex_names(tri)
        offsets = _outward(xy, centre, fs(0.9), ax)
        if _area2(xy) == 0:
            offsets = _square_to_line(xy, fs(0.9), ax)
        if self.clear and self.labels:
            offsets = self._clear_offsets(xy)
        elif self.inside:
            offsets = _within_top_bottom(ax, xy, _within_sides(ax, xy, offsets, fs(0.95)), fs(0.95))
        for label, name, p, off in zip(self.labels, names, xy, offsets):
            label.xy = tuple(p)
            label.set_position(off)
            label.set_text(name)
        mids = np.array([(xy[a] + xy[b]) / 2 for a, b in edges])
        if self.keep_clear is not None and self.edge_labels and not self.clear:
            # the vertex labels' boxes, for the edge labels to keep clear of: after the flip
            # "E21" was drawn over "v1", far from its own edge (review r354 FIG1)
            self.label_boxes = self._label_boxes(xy, offsets)
        offsets = _outward(mids, centre, fs(0.9), ax)
        if self.keep_clear is not None and self.edge_labels:
            offsets = self._edge_offsets(xy, mids, edges)
        for label, (a, b), p, off in zip(self.edge_labels, edges, mids, offsets):
            label.xy = tuple(p)
            label.set_position(off)
            label.set_text(edge_name(a, b))

    def _edge_offsets(self, xy: np.ndarray, mids: np.ndarray, edges: np.ndarray) -> list:
        """Offsets (points) of the edge labels from their edges' midpoints, each where its box
        covers no pixel centre of ``keep_clear``, no vertex dot, edge or other label (review
        r291 02-3: the boxes hid the centres the lesson is about)."""
        ax = self.outline.axes
        ax.get_xlim()  # brings autoscaled limits up to date before transData is read
        scale = ax.figure.dpi / 72.0  # display pixels per point
        size = self.edge_labels[0].get_fontsize() * scale
        # three italic characters (their text box is about 2 by 1 font sizes), in their padded
        # box or haloed (the views): the halo's stroke reaches half its width beyond the
        # letters. Review r302 02-FIG1: a box 0.84 font sizes high, smaller than the letters,
        # let "E12" touch row 3's centre dots in the player, and the editor's labels sit by them
        boxed = self.edge_labels[0].get_bbox_patch() is not None
        halo = self.edge_halo / 2 * scale
        half = (1.3 * size, 0.62 * size) if boxed else (1.0 * size + halo, 0.5 * size + halo)
        shown = ax.transData.transform
        dot = (self.vertices.get_markersize() / 2 + 1.5) * scale
        # a centre dot (2.5 points wide in the classroom style) and a gap of about as much
        centre = 0.3 * size
        dots = np.vstack([boxes_around(shown(self.keep_clear), (centre, centre)),
                          boxes_around(shown(xy), (dot, dot))])  # fmt: skip
        # the vertex names as labels: over one costs more than over a centre dot, and more
        # the more of it is hidden (as dots, "E21" still sat on "v1": every place near its
        # short edge by the frame covered a dot or the triangle, review r354 FIG1)
        centres = place_edge_labels(mids, half, edges=edges, to_display=shown,
                                    frame=ax.bbox.extents, triangle=shown(xy), dots=dots,
                                    labels=self.label_boxes)  # fmt: skip
        return [tuple((c - p) / scale) for c, p in zip(centres, shown(mids))]

    def _vertex_label_half(self) -> tuple:
        """(display pixels per point, the half-size of a vertex label's box in display
        pixels): two bold characters in their padded box."""
        ax = self.outline.axes
        scale = ax.figure.dpi / 72.0
        size = self.labels[0].get_fontsize() * scale
        return scale, (0.85 * size, 0.75 * size)

    def _label_boxes(self, xy: np.ndarray, offsets) -> np.ndarray:
        """The display boxes (n, 4) of the vertex labels shown, at ``offsets`` (points)."""
        shown = [label.get_visible() for label in self.labels]
        if not any(shown):
            return np.zeros((0, 4))
        ax = self.outline.axes
        ax.get_xlim()  # brings autoscaled limits up to date before transData is read
        scale, half = self._vertex_label_half()
        centres = ax.transData.transform(xy) + np.asarray(offsets, dtype=np.float64) * scale
        return boxes_around(centres[np.asarray(shown)], half)

    def _clear_offsets(self, xy: np.ndarray) -> list:
        """Offsets (points) of the vertex labels from their vertices, each where its box
        covers no edge, dot or other label and stays inside the Axes
        (:func:`~teachraster.plotting.label_places.place_vertex_labels`); the boxes are kept
        in ``label_boxes``."""
        ax = self.outline.axes
        ax.get_xlim()  # brings autoscaled limits up to date before transData is read
        scale, half = self._vertex_label_half()
        dot = (self.vertices.get_markersize() / 2 + 1.5) * scale  # its radius and a gap
        shown = ax.transData.transform(xy)
        centres = place_vertex_labels(shown, half, dot, ax.bbox.extents)
        self.label_boxes = boxes_around(centres, half)
        return [tuple((c - p) / scale) for c, p in zip(centres, shown)]


def plot_triangle(
    ax,
    tri,
    *,
    edges=None,
    arrows: bool = True,
    labels: bool = True,
    edge_labels: bool = False,
    color=None,
    inside: bool = False,
    clear: bool = False,
) -> TriangleArtists:
    """Draw a triangle's edges with direction arrows and the vertex labels.

    Vertices are labelled as the captions name them, v1, v2, v3 in the order given (``xy[0]``
    is v1), for every method. A label whose vertex lies far outside the Axes is not drawn.

    Parameters
    ----------
    ax : matplotlib Axes
    tri : Triangle, Fill (with trace), FillTrace or (3, 2) array
        For a fill, the *snapped* vertices are drawn (the ones coverage was decided with).
    edges : (3, 2) int array, optional
        Directed edges as (from, to) vertex indices. Default: for a fill, the edges in the
        order and direction they are tested (``trace.edges``, interior on the right as seen on
        screen); otherwise v1→v2→v3→v1, which shows the winding as given.
    arrows : bool
        An arrowhead in the middle of each edge, pointing along it.
    labels : bool
        Vertex labels v1, v2, v3, pushed outwards.
    edge_labels : bool
        Label each edge with its edge function's name, e.g. ``E12`` (as in the captions).
    color : colour, optional
        Default: the "edge" colour of :data:`~teachraster.plotting.style.COLORS`.
    inside : bool
        Keep a vertex label at the grid's sides, top or bottom inside the Axes (its offset
        mirrored or moved in), for a figure with a key or colour bar beside the Axes and no layout engine
        to make room (the widgets). Default: pushed outwards, where a layout engine makes room.
    clear : bool
        With ``inside``: each vertex label where its box covers neither its vertex's dot nor
        an edge, another dot or another label, inside the Axes, away from the triangle where
        it can (review r216 03-5: at the grid's corners the PlaneExplorer's labels covered
        their own dots and edges, and one another).

    Returns
    -------
    TriangleArtists
        ``outline``, ``vertices`` (Line2D), ``arrows`` (FancyArrowPatch), ``labels`` and
        ``edge_labels`` (Annotation).
    """
    color = COLORS["edge"] if color is None else color
    outline = ax.plot([], [], "-", color=color, lw=lw(0.8), zorder=4, solid_joinstyle="round")[0]
    # the dots above the labels' white boxes (zorder 6): a box pushed against its vertex
    # washed the dot out, and the text is about where the vertices lie (review r23 00-2)
    vertices = ax.plot([], [], "o", color=color, ms=ms(0.7), zorder=6.2)[0]
    result = TriangleArtists(outline, vertices, inside=inside, clear=clear and inside)
    if arrows:
        for _ in range(3):
            arrow = FancyArrowPatch(
                (0, 0), (1, 0), arrowstyle="-|>", mutation_scale=fs(1.3), color=color,
                lw=lw(0.5), shrinkA=0, shrinkB=0, zorder=4.2,
            )  # fmt: skip
            ax.add_patch(arrow)
            result.arrows.append(arrow)
    if labels:
        result.labels = _labels(ax, color, fontsize=fs(0.95), fontweight="bold", alpha=0.85)
    if labels and not inside:
        # the frame above the labels' white boxes: a box over the Axes' side hid a piece of
        # it and left a stub beside the label (reviews r19/r20, lesson 00's heatmaps). Kept
        # below with ``inside`` (the players' steps): there the labels stay off the sides,
        # and the current block, the whole image at a tiles step, is outlined on the frame.
        for spine in ax.spines.values():
            spine.set_zorder(max(spine.get_zorder(), 6.5))
    if edge_labels:
        result.edge_labels = _labels(ax, color, fontsize=fs(0.8), style="italic", alpha=0.7)
    result.update(tri, edges)
    return result


def _labels(ax, color, *, alpha: float, **style) -> list:
    """Three empty labels in white boxes, placed later by TriangleArtists.update."""
    return [
        annotate_near(ax, "", (0, 0), xytext=(0, 0), textcoords="offset points", ha="center",
                      va="center", color=color, bbox=label_box(alpha), zorder=6,
                      annotation_clip=False, **style)
        for _ in range(3)
    ]  # fmt: skip


# -- bounding box ------------------------------------------------------------------------------
@dataclass
class BBoxArtists(Artists):
    """Artists of :func:`plot_bbox`: the exact box and the pixels whose centres it holds."""

    outline: Rectangle
    cells: Rectangle

    def update(self, bbox) -> None:
        """Move to a new bounding box (a BBox, Fill or FillTrace)."""
        b = _bbox(bbox)
        self.outline.set_bounds(b.xmin, b.ymin, b.xmax - b.xmin, b.ymax - b.ymin)
        self.cells.set_bounds(b.col0, b.row0, b.col1 - b.col0, b.row1 - b.row0)


def _bbox(obj) -> BBox:
    return obj if isinstance(obj, BBox) else as_trace(obj, "plot_bbox").bbox


def plot_bbox(ax, bbox, *, color=None) -> BBoxArtists:
    """Draw the bounding box: its exact extent (dashed) and the pixels it makes us test.

    Parameters
    ----------
    ax : matplotlib Axes
    bbox : BBox, Fill (with trace) or FillTrace
    color : colour, optional
        Default: the "bbox" colour of :data:`~teachraster.plotting.style.COLORS`.

    Returns
    -------
    BBoxArtists
        ``outline``: dashed Rectangle from (xmin, ymin) to (xmax, ymax);
        ``cells``: lightly shaded Rectangle over the pixels whose centres lie inside
        (clipped to the image), the pixels the half-plane method visits.
    """
    color = COLORS["bbox"] if color is None else color
    outline = Rectangle((0, 0), 0, 0, fill=False, ec=color, lw=lw(0.8), ls=(0, (4, 2)), zorder=3.8)
    cells = Rectangle((0, 0), 0, 0, fc=tint(color, 0.14), ec="none", zorder=0.3)
    ax.add_patch(cells)
    ax.add_patch(outline)
    result = BBoxArtists(outline, cells)
    result.update(bbox)
    return result


# -- span tables: the split at u4 --------------------------------------------------------------
@dataclass
class SplitArtists(Artists):
    """Artists of :func:`plot_split`."""

    flat_bottom: Polygon
    flat_top: Polygon
    line: Line2D
    point: Line2D
    label: Text

    def hatch_over_coverage(self) -> None:
        """The two parts hatched, drawn over the covered pixels: painted under them, the parts
        a key names showed only as slivers beside the edges (review r93 02-9b, the editor;
        review r307 FIG1, lesson 00's two fills)."""
        for poly, name, hatch in ((self.flat_bottom, "flat_bottom", "//"),
                                  (self.flat_top, "flat_top", "\\\\")):  # fmt: skip
            poly.set(zorder=0.6, hatch=hatch, fc="none", hatch_linewidth=lw(0.6),
                     ec=COLORS[name], lw=lw(0.8))  # fmt: skip

    def update(self, fill) -> None:
        """Show the split of another fill; everything is hidden unless it used span tables."""
        trace = as_trace(fill, "plot_split")
        s = trace.span
        if s is None or s.u4 is None:
            self.set_visible(False)
            return
        v2y = float(s.sorted_xy[1, 1])  # the middle vertex's y
        for poly, part in ((self.flat_bottom, s.flat_bottom), (self.flat_top, s.flat_top)):
            poly.set_visible(part is not None)
            if part is not None:
                poly.set_xy(part)
        self.line.set_data([0, trace.width], [v2y, v2y])
        self.point.set_data([s.u4], [v2y])
        # The label sits just below the split line, on the side of point 4 away from the
        # middle vertex: outside the triangle there, so it hides none of the covered centres
        # (above the line, towards the middle vertex, it lay on the row above the split).
        away_left = s.u4 <= s.sorted_xy[1, 0]
        text = f"point 4\nu4 = {s.u4:.2f}"  # two short lines: inside the grid
        dx = -fs(0.5) if away_left else fs(0.5)
        # the text's width and its box, in points (DejaVu Sans bold: about 0.65 em a glyph)
        wide = self.label.get_fontsize() * (0.65 * max(map(len, text.split("\n"))) + 0.8)
        room = _room_left_of(self.label.axes, s.u4)
        size = (wide, self.label.get_fontsize() * (1.2 * (text.count("\n") + 1) + 0.8))
        at, offset = (s.u4, v2y), (dx, -fs(0.6))
        align = ("right" if away_left else "left", "top")
        # no room left of point 4 for both lines: its number alone, still outside the triangle
        # (review r19, lesson 00: starting at the grid's left edge, the label ran over the
        # covered centres right of point 4); the caption gives u4's value. Centred on the
        # pixel corner left of point 4 nearest the split line, between four centres: hung
        # below the line it blanked one centre and touched another (review r77 00-1)
        corner = (float(np.floor(s.u4 - 0.5)), float(np.round(v2y)))
        # better, the row above the split line, midway between two of its centres: on the
        # corner the "4" sat on the outline of the raster line just below the split and
        # on its centre dots (review r225 FIG2); taken where it is clear of the long edge
        above = (corner[0], float(np.floor(v2y - 0.85)) + 0.5)
        if above[1] > 0 and _left_of_long_edge(s.sorted_xy, above, 0.35):
            corner = above
        if away_left and room < wide - dx and corner[0] >= min(self.label.axes.get_xlim()) + 1:
            text, at, offset, align = "4", corner, (0.0, 0.0), ("center", "center")
        elif away_left and room < wide - dx:
            # not even that: the label starts at the grid's left edge instead (review r9 00
            # c14: it stuck out of the grid onto the "row i" axis label)
            offset, align = (fs(0.3) - room, -fs(0.6)), ("left", "top")
        elif not _box_clear(self.label.axes, s.sorted_xy, at, offset, align, size):
            # below the line it lay over the covered pixels and the long edge, when that edge
            # runs on down and away from point 4 (lesson 00's editor, v3 dragged above v1 -> v2,
            # review r296 FIG1): above the line, on the same side, if it fits there; else its
            # number alone, "4", above or below the line (the caption gives u4's value)
            one = (self.label.get_fontsize() * 0.9, self.label.get_fontsize() * 1.15)  # "4", halo
            places = [((dx, fs(0.6)), (align[0], "bottom"), text, size)] + [
                ((dx, dy), (align[0], va), "4", one)
                for dy, va in ((fs(0.3), "bottom"), (-fs(0.3), "top"))]  # fmt: skip
            # then the "4" on the other side of point 4; and if nothing is clear with point 4
            # beside the top or bottom vertex, no label: the diamond and the key name it
            # (review r307 FIG4: at the right frame the label ran out of the grid over the
            # editor's key, and a "4" there lay on v1's name)
            other = "right" if align[0] == "left" else "left"
            mirrored = [((-dx, dy), (other, va), "4", one)
                        for dy, va in ((fs(0.3), "bottom"), (-fs(0.3), "top"))]  # fmt: skip
            # point 4 within a pixel of the top or bottom vertex: a "4" there lies on its name
            near = np.hypot(*(s.sorted_xy[[0, 2]] - (s.u4, v2y)).T).min() < 1.0
            for place, how, words, box in places + (mirrored if not near else []):
                if _box_clear(self.label.axes, s.sorted_xy, at, place, how, box):
                    offset, align, text = place, how, words
                    break
            else:
                text = "" if near else text
        self.label.xy = at
        self.label.set_position(offset)
        self.label.set_horizontalalignment(align[0])
        self.label.set_verticalalignment(align[1])
        self.label.set_text(text)
        # the lone "4" sits on the pink split line: pink on pink read faintly (review r91
        # 00-C), so it is drawn dark grey; the longer label beside the line stays pink
        self.label.set_color("#333333" if text == "4" else COLORS["split"])
        # ... and among the centre dots, between two of them: a white halo round its glyph,
        # not a box, which hid the dot beside it (review r241 FIG2, lesson 00's player)
        lone = text == "4"
        self.label.set_bbox(None if lone or not text else label_box())
        self.label.set_path_effects([withStroke(linewidth=max(2.5, fs(0.22)), foreground="white")]
                                    if lone else [])  # fmt: skip
        for artist in (self.line, self.point, self.label):
            artist.set_visible(True)


def _left_of_long_edge(sorted_xy, point, margin: float) -> bool:
    """Whether ``point`` lies ``margin`` px or more left of the long edge (top to bottom of
    the sorted vertices) at its height, or above the triangle.

    >>> _left_of_long_edge(np.array([[2.0, 1.0], [9.0, 5.0], [5.0, 13.0]]), (2.0, 4.5), 0.3)
    True
    """
    (xt, yt), (xb, yb) = sorted_xy[0], sorted_xy[2]
    x, y = point
    if y <= yt or yb == yt:
        return True
    return bool(x + margin <= xt + (y - yt) / (yb - yt) * (xb - xt))


def _box_clear(ax, tri, at, offset, align, size) -> bool:
    """Whether a label box of ``size`` (width, height, in points) at ``offset`` points from
    data point ``at``, aligned ``align`` (ha, va), lies clear of the triangle ``tri`` (3 × 2,
    data units), within the Axes: no edge enters the box and no point of it is inside (with
    no edge in it, the box is wholly in or wholly out: its centre decides)."""
    x, y = ax.transData.transform(at) + np.asarray(offset) * ax.figure.dpi / 72.0
    w, high = (np.asarray(size, dtype=np.float64) * ax.figure.dpi / 72.0).tolist()
    x0 = {"left": x, "right": x - w, "center": x - w / 2}[align[0]]
    y0 = {"bottom": y, "top": y - high, "center": y - high / 2}[align[1]]
    frame = ax.get_window_extent()
    if x0 < frame.x0 or y0 < frame.y0 or x0 + w > frame.x1 or y0 + high > frame.y1:
        return False
    box = np.array([[x0, y0, x0 + w, y0 + high]])
    shown = ax.transData.transform(np.asarray(tri, dtype=np.float64))
    edges = np.stack([shown, np.roll(shown, -1, axis=0)], axis=1)
    return not (length_inside(box, edges)[0] > 0 or inside_share(box, shown)[0] > 0)


def _room_left_of(ax, x: float) -> float:
    """Points between data ``x`` and the Axes' left edge, at the figure's present size."""
    (x0, x1), box = ax.get_xlim(), ax.get_window_extent()
    return abs(x - min(x0, x1)) * box.width / abs(x1 - x0) * 72.0 / ax.figure.dpi


def plot_split(ax, fill) -> SplitArtists:
    """The span-table split: the line through the middle vertex, point 4 on it, the flat parts.

    Ek, *Triangles and Perspective Correct Interpolation*, §1.1: with the vertices sorted by y
    into top, middle and bottom (the notes' points 1, 2, 3; (u, v) = (x, y)), the line
    v = v_mid meets the long edge at point 4, ``u4 = u_top + (v_mid - v_top) / (v_bot - v_top)
    * (u_bot - u_top)``, which splits the triangle into a flat-bottom (top, middle, point 4)
    and a flat-top (middle, point 4, bottom) triangle.

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
        Rasterised with ``method="span"``; for another method (or a zero-height triangle,
        which has no split) the artists are created hidden, so a view can reuse them.

    Returns
    -------
    SplitArtists
        ``flat_bottom``, ``flat_top`` (Polygon), ``line`` (dashed Line2D across the image),
        ``point`` (marker at point 4) and ``label`` (Annotation with the value of u4).
    """
    # opaque tints rather than alpha: the same look on white, and cheaper to redraw
    flat_bottom = Polygon(np.zeros((3, 2)), closed=True, fc=tint(COLORS["flat_bottom"], 0.3),
                          ec=COLORS["flat_bottom"], lw=lw(0.5), zorder=0.4)  # fmt: skip
    flat_top = Polygon(np.zeros((3, 2)), closed=True, fc=tint(COLORS["flat_top"], 0.5),
                       ec=COLORS["flat_top"], lw=lw(0.5), zorder=0.4)  # fmt: skip
    ax.add_patch(flat_bottom)
    ax.add_patch(flat_top)
    line = ax.plot([], [], ls=(0, (6, 3)), color=COLORS["split"], lw=lw(0.7), zorder=3.9)[0]
    point = ax.plot([], [], "D", color=COLORS["split"], ms=ms(0.9), mec="white", zorder=5)[0]
    label = annotate_near(
        ax, "", (0, 0), xytext=(0, 0), textcoords="offset points", va="bottom",
        fontsize=fs(0.9), fontweight="bold", color=COLORS["split"], bbox=label_box(),
        zorder=6, annotation_clip=False,
    )  # fmt: skip
    result = SplitArtists(flat_bottom, flat_top, line, point, label)
    result.update(fill)
    return result


# -- the current step: raster line or pixel ----------------------------------------------------
@dataclass
class RasterLineArtists(Artists):
    """Artists of :func:`plot_raster_line`."""

    band: Rectangle
    span: Line2D
    cells: Rectangle
    covered: Line2D
    missed: Line2D
    width: int = 0

    def update(self, step: Step) -> None:
        """Show the raster line of ``step`` (hidden unless it fills a raster line)."""
        if step.kind != "row":
            self.set_visible(False)
            return
        row = step.row
        self.band.set_y(row)  # x spans the Axes: the band's transform is x-axes, y-data
        self.span.set_visible(step.span_x is not None and step.span_x[1] >= step.span_x[0])
        if step.span_x is not None:
            self.span.set_data(list(step.span_x), [row + 0.5, row + 0.5])
        start, stop = step.columns
        self.cells.set_bounds(start, row, stop - start, 1)
        self.cells.set_visible(stop > start)
        # the row's centres on top of the span: filled where the step covers them, hollow
        # where not, so a centre exactly on a span end shows which side of the rule it is on
        cols = np.arange(self.width)
        inside = (cols >= start) & (cols < stop)
        y = np.full(self.width, row + 0.5)
        self.covered.set_data(cols[inside] + 0.5, y[inside])
        self.missed.set_data(cols[~inside] + 0.5, y[~inside])
        for artist in (self.band, self.covered, self.missed):
            artist.set_visible(True)


def plot_raster_line(ax, fill, k: int) -> RasterLineArtists:
    """Highlight the raster line of step ``k`` of a span-table fill and its span.

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
    k : int
        A step index; unless it is a ``"row"`` step the artists are created hidden.

    Returns
    -------
    RasterLineArtists
        ``band``: the whole raster line, lightly shaded; ``span``: a thin segment along
        y = row + 0.5 from where the line crosses the left edge to the right edge, under the
        centres, with a tick at each end taller than a centre; ``cells``: outline of the covered pixels of that row;
        ``covered``, ``missed``: the row's pixel centres on top of the span, filled where
        covered and hollow where not.
    """
    trace = as_trace(fill, "plot_raster_line")
    c = COLORS["current"]
    # the whole width of the Axes: x in Axes coordinates, y in data (pixel rows)
    band = Rectangle((0, 0), 1, 1, fc=c, ec="none", alpha=0.15, zorder=0.6,
                     transform=ax.get_yaxis_transform())  # fmt: skip
    cells = Rectangle((0, 0), 0, 1, fill=False, ec=c, lw=lw(0.8), zorder=4.8)
    ax.add_patch(band)
    ax.add_patch(cells)
    span = ax.plot([], [], "-", color=c, lw=lw(0.6), marker="|", ms=ms(2.4), mew=lw(0.7),
                   solid_capstyle="butt", zorder=4.9)[0]  # fmt: skip
    size = ms(0.8) if max(trace.width, trace.height) <= 48 else ms(0.45)
    covered = ax.plot([], [], "o", ms=size, color=COLORS["edge"], mec="white", mew=1.0,
                      zorder=4.95)[0]  # fmt: skip
    missed = ax.plot([], [], "o", ms=size, mfc="white", mec=COLORS["edge"], mew=lw(0.35),
                     zorder=4.95)[0]  # fmt: skip
    result = RasterLineArtists(band, span, cells, covered, missed, trace.width)
    result.update(trace.step(k))
    return result


@dataclass
class PixelArtists(Artists):
    """Artists of :func:`plot_current_pixel`."""

    box: Rectangle
    centre: Line2D

    def update(self, step: Step) -> None:
        """Show the pixel of ``step``, or outline the block a tiles step classifies (review
        r19, lesson 00: the caption named a 4×4 block the picture never showed); hidden
        for every other step."""
        if step.kind == "block" and step.extent is not None:
            rows, cols = step.extent
            self.box.set_bounds(step.col, step.row, cols, rows)
            self.box.set_visible(True)
            self.centre.set_visible(False)
            return
        if step.kind != "pixel":
            self.set_visible(False)
            return
        self.box.set_bounds(step.col, step.row, 1, 1)
        self.centre.set_data([step.col + 0.5], [step.row + 0.5])
        self.set_visible(True)


def plot_current_pixel(ax, fill, k: int) -> PixelArtists:
    """Outline the pixel that step ``k`` of a half-plane fill tests, and mark its centre (or
    the block a tiles step classifies).

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
    k : int
        A step index; unless it is a ``"pixel"`` step the artists are created hidden.

    Returns
    -------
    PixelArtists
        ``box`` (Rectangle outline) and ``centre`` (a cross at the sample point).
    """
    c = COLORS["current"]
    box = Rectangle((0, 0), 1, 1, fill=False, ec=c, lw=lw(1.0), zorder=4.8)
    ax.add_patch(box)
    centre = ax.plot([], [], "x", color=c, ms=ms(1.0), mew=lw(0.7), zorder=4.9)[0]
    result = PixelArtists(box, centre)
    result.update(as_trace(fill, "plot_current_pixel").step(k))
    return result


# -- edge functions ----------------------------------------------------------------------------
def edge_images(fill) -> np.ndarray:
    """(H, W, 3) edge-function values E_k (px²) at every pixel centre, in test order.

    The trace's own edge tests (:meth:`~teachraster.core.trace.FillTrace.edge_images`) over
    the whole image, so the half-plane of each edge shows beyond the bounding box too. Exact
    on the snapped grid, and equal to the half-plane trace's values inside the box.
    """
    return as_trace(fill, "edge_images").edge_images()


@dataclass
class EdgeValueArtists(Artists):
    """Artists of :func:`plot_edge_values`."""

    image: object
    boundary: list = field(default_factory=list)
    texts: list = field(default_factory=list)
    legend: object = None
    colorbar: object = None


def _cell_texts(ax, values, fmt, *, rows=None, cols=None, colors=None, scale=0.55) -> list:
    """Write ``fmt(value)`` at the centre of each cell of a (h, w) block (NaN skipped)."""
    h, w = values.shape
    r0 = 0 if rows is None else rows
    c0 = 0 if cols is None else cols
    out = []
    for i in range(h):
        for j in range(w):
            v = values[i, j]
            if isinstance(v, float | np.floating) and np.isnan(v):
                continue
            color = "black" if colors is None else colors[i, j]
            out.append(ax.text(c0 + j + 0.5, r0 + i + 0.5, fmt(v), ha="center", va="center",
                               fontsize=fs(scale), color=color, zorder=5))  # fmt: skip
    return out


def plot_edge_values(
    ax,
    fill,
    k: int,
    *,
    signs: bool = False,
    annotate: bool | None = None,
    colorbar: bool = True,
    title: bool = True,
) -> EdgeValueArtists:
    """The edge function of edge ``k`` at every pixel centre: values or just their signs.

    ``E(a, b, p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)`` is positive on the
    inside (to the right of a→b as seen on screen), negative outside and zero on the line.

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
    k : {0, 1, 2}
        Edge in test order (``trace.edges[k]`` = (a, b), indices from 0, named ``E{a+1}{b+1}``
        as in the captions).
    signs : bool
        Show only the sign (+ inside, − outside, 0 on the edge) instead of the values.
    annotate : bool, optional
        Write the value (or sign) into each pixel. Default: when the image has at most
        :data:`ANNOTATE_LIMIT` pixels.
    colorbar : bool
        A colour bar for values (a legend for signs).
    title : bool
        Set the Axes title.

    Returns
    -------
    EdgeValueArtists
        ``image``, ``boundary`` (the edge's line and its arrow), ``texts``, ``legend``,
        ``colorbar``.
    """
    trace = as_trace(fill, "plot_edge_values")
    if k not in (0, 1, 2):
        raise ValueError(f"k must be 0, 1 or 2 (an edge in test order), got {k!r}")
    e = edge_images(trace)[..., k]
    a, b = trace.edges[k]
    name = edge_name(a, b)
    h, w = e.shape
    if annotate is None:  # values need bigger cells than signs to stay legible
        annotate = h * w <= (ANNOTATE_LIMIT if signs else ANNOTATE_LIMIT // 2)
    if signs:
        sign = np.sign(e)
        cmap = ListedColormap([COLORS["outside"], "#F2F2F2", COLORS["inside"]])
        im = show_image(ax, sign, cmap=cmap, vmin=-1.5, vmax=1.5, alpha=0.55, zorder=0.5)
    else:
        m = float(np.abs(e).max()) or 1.0
        im = show_image(ax, e, cmap=SIGNED_CMAP, norm=Normalize(-m, m), zorder=0.5)
    result = EdgeValueArtists(im)
    pa, pb = trace.snapped[a], trace.snapped[b]
    if np.any(pa != pb):  # a zero-length edge has no line
        result.boundary.append(ax.axline(pa, pb, color=COLORS["edge"], lw=lw(0.7), zorder=4))
        arrow = FancyArrowPatch(pa, pb, arrowstyle="-|>", mutation_scale=fs(1.4),
                                color=COLORS["edge"], lw=lw(0.7), shrinkA=0, shrinkB=0,
                                zorder=4.2)  # fmt: skip
        ax.add_patch(arrow)
        result.boundary.append(arrow)
    if annotate:
        if signs:
            result.texts = _cell_texts(ax, sign, lambda v: {1: "+", -1: "−", 0: "0"}[int(v)],
                                       scale=0.8)  # fmt: skip
        else:
            result.texts = _cell_texts(ax, e, lambda v: f"{v:.3g}", scale=0.42)
    if signs:
        handles = [Patch(fc=COLORS["inside"], alpha=0.55, label=f"{name} > 0: inside"),
                   Patch(fc=COLORS["outside"], alpha=0.55, label=f"{name} < 0: outside")]  # fmt: skip
        result.legend = ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                                  borderaxespad=0.0)  # fmt: skip
    elif colorbar:
        result.colorbar = ax.figure.colorbar(im, ax=ax, shrink=0.85, label=f"{name} (px²)")
    if title:
        what = "sign of " if signs else ""
        tl = "top-left" if trace.top_left[k] else "not top-left"
        ax.set_title(f"{what}{name}: edge v{a + 1} → v{b + 1} ({tl})")
    return result


# -- half-plane bail-out -----------------------------------------------------------------------
@dataclass
class BailoutArtists(Artists):
    """Artists of :func:`plot_bailout`."""

    image: object
    texts: list = field(default_factory=list)
    legend: object = None


BAILOUT_COLORS = (COLORS["fill"], "#F0E442", "#E69F00", "#D55E00")


def bailout(fill) -> tuple[np.ndarray, np.ndarray]:
    """Bbox-local (rejected_by, tests_run) of a bail-out half-plane loop, for any method.

    ``rejected_by`` is -1 where the pixel is covered, else the position (0, 1, 2) of the first
    failing edge test; ``tests_run`` counts the tests a loop stopping at that failure runs.
    As recorded by the trace (:meth:`~teachraster.core.trace.FillTrace.bail_out`).
    """
    return as_trace(fill, "bailout").bail_out()


def plot_bailout(ax, fill, *, annotate: bool | None = None, title: bool = True) -> BailoutArtists:
    """Which edge test rejected each pixel of the bounding box, and how many tests ran.

    A scalar half-plane loop tests the three edges in turn and stops at the first failure,
    so pixels rejected by test 1 cost one test, by test 2 two, and covered pixels all three.

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
        Either method (for span tables the tests are evaluated afresh).
    annotate : bool, optional
        Write the number of tests run into each pixel. Default: when the bounding box has at
        most :data:`ANNOTATE_LIMIT` pixels.
    title : bool
        Set the Axes title (with the average number of tests per pixel).

    Returns
    -------
    BailoutArtists
        ``image`` (0 covered, 1-3 rejected by that test, NaN outside the box), ``texts``,
        ``legend``.
    """
    trace = as_trace(fill, "plot_bailout")
    rejected, run = bailout(trace)
    local = np.where(rejected < 0, 0.0, rejected + 1.0)
    if trace.culled:
        local[:] = np.nan  # nothing is tested: the whole triangle was culled
    image = trace.image(local)
    im = show_image(ax, image, cmap=ListedColormap(BAILOUT_COLORS), vmin=-0.5, vmax=3.5,
                    alpha=0.9, zorder=0.5)  # fmt: skip
    result = BailoutArtists(im)
    b = trace.bbox
    annotate = b.size <= ANNOTATE_LIMIT if annotate is None else annotate
    if annotate and not trace.culled:
        result.texts = _cell_texts(ax, run.astype(float), lambda v: str(int(v)), rows=b.row0,
                                   cols=b.col0, scale=0.6)  # fmt: skip
    names = [edge_name(a, c) for a, c in trace.edges]
    handles = [Patch(fc=BAILOUT_COLORS[0], label="covered: 3 tests")] + [
        Patch(fc=BAILOUT_COLORS[t + 1],
              label=f"out at test {t + 1} ({names[t]}): {t + 1} test" + "s" * (t > 0))
        for t in range(3)
    ]  # fmt: skip
    result.legend = ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                              borderaxespad=0.0, title="tests run per pixel")  # fmt: skip
    if title:
        if trace.culled:
            ax.set_title("bail-out: triangle culled, no pixel tested")
        elif b.size == 0:
            ax.set_title("bail-out: no pixel centre in the bounding box")
        else:
            ax.set_title(f"bail-out: {run.mean():.2f} tests per pixel (3 without)")
    return result


# -- visit order -------------------------------------------------------------------------------
@dataclass
class VisitArtists(Artists):
    """Artists of :func:`plot_visit_order`."""

    image: object
    path: Line2D | None = None
    texts: list = field(default_factory=list)
    colorbar: object = None


def visit_order(fill) -> tuple[np.ndarray, np.ndarray]:
    """(rows, cols) of the pixels a fill touches, in the order it touches them.

    Half-planes visit every pixel of the bounding box in row-major order; span tables write
    only the covered pixels, raster line by raster line, left to right. As numbered by the
    trace (:meth:`~teachraster.core.trace.FillTrace.visit_order`).
    """
    return as_trace(fill, "visit_order").visit_order()


def plot_visit_order(
    ax,
    fill,
    *,
    numbers: bool | None = None,
    path: bool = True,
    colorbar: bool = True,
    title: bool = True,
) -> VisitArtists:
    """Colour each pixel by when the fill reaches it, and trace the path through the centres.

    Parameters
    ----------
    ax : matplotlib Axes
    fill : Fill (with trace) or FillTrace
    numbers : bool, optional
        Write the visit number into each pixel. Default: up to 100 visited pixels.
    path : bool
        Join the centres in visiting order with a thin line.
    colorbar : bool
        A colour bar of the visit number.
    title : bool
        Set the Axes title.

    Returns
    -------
    VisitArtists
        ``image`` (visit number, NaN where never visited), ``path``, ``texts``, ``colorbar``.
    """
    trace = as_trace(fill, "plot_visit_order")
    rows, cols = visit_order(trace)
    order = np.full((trace.height, trace.width), np.nan)
    order[rows, cols] = np.arange(len(rows))
    im = show_image(ax, order, cmap=VALUE_CMAP, vmin=0, vmax=max(len(rows) - 1, 1), alpha=0.85,
                    zorder=0.5)  # fmt: skip
    result = VisitArtists(im)
    if path and len(rows):
        # thick enough to follow on a projector (review r2: the thin path was lost)
        result.path = ax.plot(cols + 0.5, rows + 0.5, "-", color=COLORS["edge"], lw=lw(0.55),
                              alpha=0.75, zorder=3)[0]  # fmt: skip
    numbers = len(rows) <= 100 if numbers is None else numbers
    if numbers:
        colors = im.cmap(im.norm(np.arange(len(rows))))
        for n, (r, c) in enumerate(zip(rows, cols)):
            # black on light cells, white on dark ones
            ink = "black" if colors[n, :3] @ [0.299, 0.587, 0.114] > 0.5 else "white"
            result.texts.append(ax.text(c + 0.5, r + 0.5, str(n), ha="center", va="center",
                                        fontsize=fs(0.5), color=ink, zorder=5))  # fmt: skip
    if colorbar:
        result.colorbar = ax.figure.colorbar(im, ax=ax, shrink=0.85, label="visit number")
    if title:
        if trace.method == "halfplane":
            what = f"half-planes: all {len(rows)} pixels of the box"
        else:
            what = f"span tables: only the {len(rows)} covered"
        ax.set_title(f"visit order, {what}")
    return result
