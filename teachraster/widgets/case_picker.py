"""``CasePicker``: browse the hard-case catalogue, ours beside the naive rasteriser.

Lesson 07's widget. Pick a screen-space case of :mod:`teachraster.study.hardcases` and a naive
rule: the left panel colours every pixel by the triangle that owns it (vermillion where a
pixel is covered twice), the right panel shows what a naive rasteriser covers (the case's own
naive version, or one of :data:`~teachraster.study.hardcases.NAIVE_RULES` applied to the
case: no tie rule either way, whole-pixel vertices, one winding), and the text gives the
case's *why*, what a correct rasteriser *must* do (and, only if ours fails it, that it does),
and how the naive version differs. Both panels are ticked with the image's own rows and
columns.

Some cases are not meshes but separate copies of one triangle (every vertex order, whole-pixel
shifts): their copies overlap by design, and a pixel covered by two of them is no error. For
those both panels move every copy back onto the first (:func:`copy_offsets`,
:func:`aligned_counts`) and show where the copies agree and where they do not.
"""

from __future__ import annotations

import html
from types import SimpleNamespace

import ipywidgets as widgets
import numpy as np
from matplotlib.patches import Circle, Rectangle

from ..core.snapping import snap
from ..plotting import COLORS, plot_coverage, plot_pixel_centres, plot_pixel_grid, plot_triangle
from ..plotting.common import remove_drawn
from ..study import hardcases
from .ahead import PicturesAhead, show_kept
from .common import (
    Shown,
    close_tree,
    control_row,
    fit_width,
    labelled,
    style_context,
    title_html,
)
from .display import FigureDisplay, new_figure, png_bytes, resolve_backend

#: What the picker holds about the picture on show (set by ``_run`` and ``_draw``): a picture
#: drawn ahead brings them with it.
PICTURE_STATE = ("_case", "owner", "passed", "failure", "naive_counts", "difference", "offsets",
                 "copies", "naive_copies", "_box", "hubs", "view", "colors", "methods_differ",
                 "naive_triangles", "naive_says", "zoomed")  # fmt: skip

#: The naive rule the right panel starts with: the case's own naive version (what its
#: ``naive_does`` says); the others are :data:`~teachraster.study.hardcases.NAIVE_RULES`.
CASE_NAIVE = "case's own"
RULES = (CASE_NAIVE, *hardcases.NAIVE_RULES)

#: Owner value of a pixel covered by no triangle, and by more than one.
NONE, SEVERAL = -1, -2
#: One colour per owning triangle: blues, greens, purples, olives and greys, light and dark
#: alternating so that neighbours differ, and no red or orange (vermillion means "covered
#: twice" in every figure of the course).
OWNER_COLORS = ("#1f77b4", "#98df8a", "#9467bd", "#dbdb8d", "#17becf", "#c7c7c7", "#393b79",
                "#8ca252", "#aec7e8", "#2ca02c", "#c5b0d5", "#7f7f7f", "#9edae5", "#637939",
                "#6b6ecf", "#bcbd22")  # fmt: skip
#: The picker's owner colours, strongest contrast first: §1's fan colours (sky blue, yellow),
#: then Okabe-Ito's bluish green, a purple and a grey, no two closer than ΔE 37 (CIELAB; no
#: red or orange either, and not Okabe-Ito's blue: ΔE 26 from the sky blue).
#: :func:`owner_colors` gives every owner its own while they fit, and otherwise colours the
#: owners so that neighbours never share one: 16 colours for the fan's 16 owners put near
#: twins side by side (review r11, 07: "two olives, two greys and two purples").
NEIGHBOUR_COLORS = (COLORS["fill"], "#F0E442", "#009E73", "#9467bd", "#999999")
#: The naive panel's "covered once": a light grey, not the sky blue that is triangle 1's colour
#: in the owner panel beside it (review r13, 07: one colour, two meanings in one picture).
NAIVE_ONCE = "#c8c8c8"
#: Separate copies of one triangle: pixels every copy covers, and pixels only some cover.
EVERY_COPY, SOME_COPIES = COLORS["fill"], COLORS["inside"]


def owner_image(fills) -> np.ndarray:
    """(H, W) index of the triangle covering each pixel; NONE (-1) or SEVERAL (-2) otherwise.

    Parameters
    ----------
    fills : sequence of Fill (or of (H, W) bool arrays), one per triangle

    Examples
    --------
    >>> a = np.array([[1, 1, 0]], bool); b = np.array([[0, 1, 1]], bool)
    >>> owner_image([a, b]).tolist()
    [[0, -2, 1]]
    """
    masks = [np.asarray(getattr(f, "coverage", f), dtype=bool) for f in fills]
    owner = np.full(masks[0].shape, NONE, dtype=np.int64)
    count = np.zeros(masks[0].shape, dtype=np.int64)
    for k, m in enumerate(masks):
        owner[m] = k
        count += m
    owner[count > 1] = SEVERAL
    return owner


def counts_difference(ours: np.ndarray, naive: np.ndarray) -> str:
    """How a naive rule's coverage counts differ from ours, in one line.

    >>> counts_difference(np.array([[1, 1, 0, 0]]), np.array([[2, 0, 1, 0]]))
    'naive covers 1 centre(s) more than once, 1 that ours leaves to a neighbour, misses 1 that ours covers: 3 pixel(s) differ'
    >>> counts_difference(np.array([[1, 0]]), np.array([[1, 0]]))
    'naive covers the same centres as ours'
    """
    differ = int((ours != naive).sum())
    if not differ:
        return "naive covers the same centres as ours"
    twice, extra = int((naive > 1).sum()), int(((naive > 0) & (ours == 0)).sum())
    missed = int(((naive == 0) & (ours > 0)).sum())
    covers = [f"{twice} centre(s) more than once"] * bool(twice) + [
        f"{extra} that ours leaves to a neighbour"
    ] * bool(extra)
    parts = [f"covers {', '.join(covers)}"] * bool(covers)
    parts += [f"misses {missed} that ours covers"] * bool(missed)
    return f"naive {', '.join(parts)}: {differ} pixel(s) differ"


def owner_color(k: int) -> str:
    """The colour of triangle ``k`` in :func:`plot_owners` (:data:`OWNER_COLORS`, cycled)."""
    return OWNER_COLORS[k % len(OWNER_COLORS)]


def owner_neighbours(owner: np.ndarray, triangles=None) -> set:
    """Pairs (a, b), a < b, of owners whose pixels touch along a side, or whose triangles
    share an edge (two vertices): the owners a picture must tell apart.

    >>> owner_neighbours(np.array([[0, 0, 1], [2, -1, 1]]))
    {(0, 1), (0, 2)}
    """
    pairs = set()
    for a, b in ((owner[:, :-1], owner[:, 1:]), (owner[:-1, :], owner[1:, :])):
        touch = (a >= 0) & (b >= 0) & (a != b)
        pairs |= {(min(p, q), max(p, q)) for p, q in zip(a[touch].tolist(), b[touch].tolist())}
    tris = [] if triangles is None else [{tuple(v) for v in t.tolist()}
                                         for t in np.asarray(triangles, dtype=float)]  # fmt: skip
    for a in range(len(tris)):
        pairs |= {(a, b) for b in range(a + 1, len(tris)) if len(tris[a] & tris[b]) >= 2}
    return pairs


def owner_colors(owner: np.ndarray, triangles=None) -> dict:
    """``{owner: colour}`` from :data:`NEIGHBOUR_COLORS`: one colour for each owner while
    they fit; otherwise a colouring in which no two neighbours (:func:`owner_neighbours`)
    share a colour (the most constrained owner first, ties by number: DSatur), falling back
    on :func:`owner_color` only if the palette runs out.

    >>> row = owner_colors(np.array([[0, 1, 2, 3, 4, 5, 6]]))  # 7 owners in a row: 2 colours
    >>> len(set(row.values())), row[0] == row[2] != row[1]
    (2, True)
    """
    owners = sorted({int(k) for k in np.unique(owner) if k >= 0})
    if len(owners) <= len(NEIGHBOUR_COLORS):
        return {k: NEIGHBOUR_COLORS[i] for i, k in enumerate(owners)}
    near: dict = {k: set() for k in owners}
    for a, b in owner_neighbours(owner, triangles):
        if a in near and b in near:
            near[a].add(b)
            near[b].add(a)
    colour: dict = {}
    while len(colour) < len(owners):
        # DSatur: the owner whose neighbours already use the most colours, then the most
        # neighbours, then the lowest number
        k = min((k for k in owners if k not in colour),
                key=lambda k: (-len({colour[n] for n in near[k] if n in colour}),
                               -len(near[k]), k))  # fmt: skip
        used = {colour[n] for n in near[k] if n in colour}
        free = [c for c in NEIGHBOUR_COLORS if c not in used]
        colour[k] = free[0] if free else owner_color(k)
    return colour


#: Grids wider than this many pixels get thin outlines: at the classroom line width an outline
#: covers a whole pixel there, and a sliver's owned pixels vanish under it.
THIN_ABOVE = 32


#: Cases of more triangles than this get thin outlines too: the fan's sixteen outlines, at the
#: classroom width and on a projector's 1024 x 768 screen, hid the owners' colours (review
#: r145, 07-17).
THIN_TRIANGLES = 8


def thin_lines(shape, triangles: int = 1) -> bool:
    """Whether a grid of ``shape`` (rows, columns) of ``triangles`` triangles gets thin
    outlines (see :data:`THIN_ABOVE`, :data:`THIN_TRIANGLES`)."""
    return max(shape) > THIN_ABOVE or triangles > THIN_TRIANGLES


#: Triangles smaller than this (pixels, their bounding box's longer side) get no vertex marks
#: and a fine outline (TINY_WIDTH points): even small marks and the classroom's thick line
#: covered them, triangle 1 of ``subpixel_triangles`` a black blot and triangle 4 a dot
#: (review r145, 07-16; r236 FIG-2; the lesson's own figure of them draws no marks either).
TINY_BELOW, TINY_WIDTH = 1.0, 1.5
#: Triangles smaller still (ZOOM_BELOW px) are a speck at any scale that shows their pixels:
#: each gets an inset that magnifies it ZOOM_SIDE times its size (:func:`zoom_inset`).
ZOOM_BELOW, ZOOM_SIDE = 0.1, 1.6
#: The ring round a speck (radius, px) and the grey of it and of the line to the inset.
ZOOM_RING, ZOOM_GREY = 0.3, "0.45"


def tiny_triangles(triangles) -> bool:
    """Whether every triangle is smaller than :data:`TINY_BELOW` pixels each way."""
    xy = np.asarray(triangles, dtype=float)
    return bool((np.ptp(xy, axis=1).max(axis=-1) < TINY_BELOW).all())


#: Vertex marks of the picker's outlines: hollow squares (points across) in VERTEX_COLOR, not
#: dots. The vertices of these cases lie on pixel centres, and a black vertex dot looked like
#: the "covered" centre dot: the split square's three uncovered corners seemed covered (review
#: r65, 07-1). Hollow, so the centre's own dot shows inside; small, so that a pixel centre at a
#: shared vertex (the fan's hub) is not hidden under a pile of them.
VERTEX_MARK, VERTEX_COLOR = 9, COLORS["split"]

#: The pixel centres' dots above the outlines (zorder 4) and below the vertex marks (6.2): an
#: outline along a row of uncovered centres hid their small hollow dots.
CENTRE_Z = 4.6


def mark_vertices(art, *, thin: bool = False, tiny: bool = False) -> None:
    """The vertices of :func:`~teachraster.plotting.plot_triangle`'s ``art`` as hollow squares
    (:data:`VERTEX_MARK`), told apart from the pixel centres' dots; ``tiny`` (triangles
    smaller than a pixel): none, a mark would hide the triangle."""
    if tiny:
        art.vertices.set_visible(False)
        return
    art.vertices.set(marker="s", markersize=VERTEX_MARK * (0.7 if thin else 1),
                     markerfacecolor="none", markeredgecolor=VERTEX_COLOR,
                     markeredgewidth=1.2 if thin else 2)  # fmt: skip


def centres_on_top(ax, width: int, height: int, coverage) -> None:
    """:func:`~teachraster.plotting.plot_pixel_centres` above the outlines (:data:`CENTRE_Z`),
    the uncovered ones filled white."""
    centres = plot_pixel_centres(ax, width, height, coverage)
    for line in (centres.inside, centres.outside):
        line.set_zorder(CENTRE_Z)
    centres.outside.set_markerfacecolor("white")  # a hollow dot on an outline: still hollow


def outline(ax, xy, *, thin: bool = False, tiny: bool = False):
    """A triangle's outline without arrows or labels, its vertices marked (:func:`mark_vertices`);
    ``thin``: a fine, half-transparent line too, so that the pixels under it stay visible on a
    large grid; ``tiny``: no vertex marks and a fine line (:data:`TINY_WIDTH`), so that a
    triangle smaller than a pixel shows its shape."""
    art = plot_triangle(ax, xy, labels=False, arrows=False)
    mark_vertices(art, thin=thin, tiny=tiny)
    if thin:
        art.outline.set(linewidth=0.6, alpha=0.6)
    elif tiny:
        art.outline.set(linewidth=TINY_WIDTH)
    if is_point(xy):  # no outline to see: a diamond, as the lesson draws it
        ax.plot(*np.asarray(xy, dtype=float)[0], "D", ms=8, color=COLORS["outside"], zorder=6.2)
    return art


def is_point(xy) -> bool:
    """Whether the three vertices of ``xy`` are one point (a triangle rounded to zero size)."""
    return len({tuple(v) for v in np.asarray(xy, dtype=float).tolist()}) == 1


def zoom_inset(ax, triangles, centres, fills, *, view) -> list:
    """``triangles`` (n, 3, 2) magnified in an inset of ``ax``, in the corner of the view
    (rows r0:r1, columns c0:c1) farthest from them, joined to where they lie: each as given
    (filled in its colour of ``fills``), its vertices snapped to the 1/256-px grid (dashed; a
    diamond where they collapse to one point), the grid's lines, and every pixel centre inside
    the inset, filled where ``centres`` ((H, W) bool) says covered. For triangles smaller than
    :data:`ZOOM_BELOW` px, which no view of whole pixels shows (review r236 FIG-2).

    Returns the inset and :func:`zoom_pointer`'s ring and line."""
    tris = np.asarray(triangles, dtype=float)
    r0, r1, c0, c1 = view
    every = np.concatenate([tris, snap(tris)]).reshape(-1, 2)  # given and snapped, all seen
    lo, hi = every.min(axis=0), every.max(axis=0)
    # each way ZOOM_SIDE times the triangles' extent, at least 2 snapping steps: a sliver
    # (snap_flips_winding: 0.04 by 0.002 px) is stretched across, its winding seen
    mid, side = (lo + hi) / 2, np.maximum(ZOOM_SIDE * (hi - lo), 2 / 256)
    # the corner of the view farthest from the triangles (axes fraction, y up in the box)
    fx, fy = (mid[0] - c0) / (c1 - c0), 1 - (mid[1] - r0) / (r1 - r0)
    inset_box = (0.55 if fx < 0.5 else 0.03, 0.03 if fy > 0.5 else 0.55, 0.42, 0.42)
    inset = ax.inset_axes(inset_box)
    lo, hi = mid - side / 2, mid + side / 2
    for v in np.arange(np.ceil(lo.min() * 256), np.floor(hi.max() * 256) + 1) / 256:
        inset.axvline(v, color="0.85", lw=0.8, zorder=0)
        inset.axhline(v, color="0.85", lw=0.8, zorder=0)
    for xy, colour in zip(tris, fills):
        inset.fill(*xy.T, color=colour, alpha=0.7, ec="black", lw=1.5, zorder=2)
        snapped = snap(xy)
        if is_point(snapped):  # zero area: a point
            inset.plot(*snapped[0], "D", ms=7, color=COLORS["outside"], zorder=5)  # on a dot
        else:
            inset.fill(*snapped.T, fill=False, ec=VERTEX_COLOR, lw=1.5, ls="--", zorder=3)
    rows = np.arange(np.ceil(lo[1] - 0.5), np.floor(hi[1] - 0.5) + 1).astype(int)
    cols = np.arange(np.ceil(lo[0] - 0.5), np.floor(hi[0] - 0.5) + 1).astype(int)
    for i in rows[(rows >= 0) & (rows < centres.shape[0])]:
        for j in cols[(cols >= 0) & (cols < centres.shape[1])]:
            inset.plot(j + 0.5, i + 0.5, "o", ms=9, mec="black", mew=1.5, zorder=4,
                       mfc=COLORS["edge"] if centres[i, j] else "white")  # fmt: skip
    inset.set(xlim=(lo[0], hi[0]), ylim=(hi[1], lo[1]), xticks=[], yticks=[])
    # magnified against the panel: the inset is 0.42 of the panel's pixels each way
    across, down = (0.42 * np.array([c1 - c0, r1 - r0]) / side).round().astype(int)
    # inside the inset, at its foot: above it the title met the joining lines
    inset.text(0.5, 0.03, f"× {across}" if abs(across - down) <= 0.1 * across
               else f"× {across} by {down}", transform=inset.transAxes, ha="center",
               va="bottom", fontsize="x-small", zorder=5,
               bbox={"fc": "white", "ec": "none", "alpha": 0.85, "pad": 1})  # fmt: skip
    return [inset, *zoom_pointer(ax, mid, view, inset_box)]


def zoom_pointer(ax, mid, view, box) -> list:
    """Where the inset's speck lies on ``ax``: a dashed grey ring round ``mid`` (data
    coordinates), larger than a centre's dot, and one thin dashed grey line from it to the
    corner of the inset (``box``: its axes-fraction x0, y0, width, height) nearest to it.
    Matplotlib's zoom indicator drew two black connectors, which read as a large triangle,
    and its box round a 0.0025-px speck as a filled centre dot: "covered" (review r244 FIG-1)."""
    r0, r1, c0, c1 = view
    x0, y0, w, h = box
    # the inset's corner nearest the speck, in the panel's axes fraction, then in data (y down)
    near_x = x0 if mid[0] < c0 + (x0 + w / 2) * (c1 - c0) else x0 + w
    near_y = y0 if mid[1] > r1 - (y0 + h / 2) * (r1 - r0) else y0 + h  # below: the foot
    corner = np.array([c0 + near_x * (c1 - c0), r1 - near_y * (r1 - r0)])
    ring = Circle(mid, ZOOM_RING, fill=False, ec=ZOOM_GREY, lw=1.2, ls="--", zorder=6.5)
    ax.add_patch(ring)
    start = mid + ZOOM_RING * (corner - mid) / np.hypot(*(corner - mid))
    (line,) = ax.plot(*np.column_stack([start, corner]), color=ZOOM_GREY, lw=1.0, ls="--",
                      zorder=6.5)  # fmt: skip
    return [ring, line]


#: The view of a case: at least MIN_VIEW pixels each way (a tiny triangle keeps some grid
#: around it), at most MAX_ASPECT times as wide as high (a long sliver shows its left end, in
#: pixels large enough to see, instead of a strip a few screen pixels high), and at most
#: MAX_VIEW pixels each way (a long diagonal sliver shows its first corner, instead of a
#: 64 x 64 grid on which its one pixel per row is a dotted line).
MIN_VIEW, MAX_ASPECT, MAX_VIEW = 6, 3, 16

#: The figure's height in inches (its width is 9): at most FIG_HEIGHT, and for a wide view just
#: what two panels of about PANEL_WIDTH inches, their titles and ticks (TITLES_HEIGHT) need.
FIG_HEIGHT, MIN_FIG_HEIGHT, TITLES_HEIGHT, PANEL_WIDTH = 4.6, 2.4, 1.5, 4.1


#: The key's words for :func:`window_ticks`' numbers.
TICKS_KEY = "ticks: the image's rows (left) and columns (on top)"


def window_ticks(ax, r0: int, r1: int, c0: int, c1: int, *, dr: int = 0, dc: int = 0) -> None:
    """Tick the rows r0:r1 and columns c0:c1 a panel shows with the image's own row and column
    numbers, on the pixel centres: every pixel a minor tick, every one or two a number.
    ``dr``, ``dc``: what to add to a panel's own coordinates to get the image's (a panel of
    copies is drawn from its box's corner). The picker's text names pixels of the whole image,
    and a cut-out view counted from its corner found the wrong one (review r227 FIG-1)."""
    # numbers only, no "row" and "column" under them: a label under a panel of equal aspect
    # fell off the figure's bottom (the constrained layout left too little room for it)
    for axis, lo, hi, shift in ((ax.xaxis, c0, c1, dc), (ax.yaxis, r0, r1, dr)):
        step = 1 if hi - lo <= 8 else 2
        first = lo + (-(lo + shift)) % step  # the numbers at multiples of the step
        every = np.arange(first, hi)[::step]
        axis.set_ticks(every + 0.5, labels=[str(k + shift) for k in every], fontsize="small")
        axis.set_ticks(np.arange(lo, hi) + 0.5, minor=True)
    # the columns on top, as on lesson 07's own pixel grids (review r474 S4, r389 S2)
    ax.xaxis.tick_top()


def view_box(triangles, shape, *masks) -> tuple[int, int, int, int, bool, bool]:
    """Rows r0:r1 and columns c0:c1 a panel shows, and whether rows, and columns, were cut off.

    The bounding box of the triangles and of the pixels set in ``masks``, one pixel around
    it, grown to :data:`MIN_VIEW` pixels each way and clipped to the image of ``shape``;
    a box more than :data:`MAX_VIEW` pixels high keeps its first rows, and one more than
    :data:`MAX_ASPECT` times as wide as high, or more than :data:`MAX_VIEW` pixels wide, its
    first columns.

    >>> view_box([[[0.5, 1.49], [60.5, 1.5], [0.5, 1.51]]], (4, 64))
    (0, 4, 0, 12, False, True)
    >>> view_box([[[3.5, 3.5], [15.5, 3.5], [3.5, 15.5]]], (20, 20))
    (2, 17, 2, 17, False, False)
    >>> view_box([[[0.5, 0.5], [63.5, 63.5], [63.5, 63.49]]], (64, 64))
    (0, 16, 0, 16, True, True)
    """
    h, w = shape
    xy = np.asarray(triangles, dtype=float).reshape(-1, 2)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    for mask in masks:
        rows, cols = np.nonzero(np.asarray(mask))
        if rows.size:
            lo = np.minimum(lo, [cols.min(), rows.min()])
            hi = np.maximum(hi, [cols.max() + 1, rows.max() + 1])

    def span(a, b, size):
        a, b = max(int(np.floor(a)) - 1, 0), min(int(np.ceil(b)) + 1, size)
        grow = max(MIN_VIEW - (b - a), 0)
        a = max(min(a - grow // 2, size - MIN_VIEW), 0)
        return a, min(max(b, a + MIN_VIEW), size)

    (c0, c1), (r0, r1) = span(lo[0], hi[0], w), span(lo[1], hi[1], h)
    cut_rows = r1 - r0 > MAX_VIEW
    if cut_rows:
        r1 = r0 + MAX_VIEW
    widest = min(MAX_ASPECT * (r1 - r0), MAX_VIEW)
    cut_cols = c1 - c0 > widest
    if cut_cols:
        c1 = c0 + widest
    return r0, r1, c0, c1, cut_rows, cut_cols


def shared_vertex_pixels(triangles, shape, least: int = 3) -> list[tuple[int, int]]:
    """(row, col) of the pixels whose centre is a vertex of at least ``least`` triangles (a
    fan's hub): the pixel the case is about, drawn on top of the outlines meeting there.

    >>> fan = [[[9.5, 9.5], [12.5, 9.5], [9.5, 12.5]], [[9.5, 9.5], [9.5, 12.5], [6.5, 9.5]],
    ...        [[9.5, 9.5], [6.5, 9.5], [9.5, 6.5]]]
    >>> shared_vertex_pixels(fan, (20, 20))
    [(9, 9)]
    """
    h, w = shape
    count: dict = {}
    for tri in np.asarray(triangles, dtype=float):
        for x, y in {tuple(v) for v in tri.tolist()}:
            j, i = x - 0.5, y - 0.5
            if j == int(j) and i == int(i) and 0 <= i < h and 0 <= j < w:
                count[(int(i), int(j))] = count.get((int(i), int(j)), 0) + 1
    return sorted(rc for rc, n in count.items() if n >= least)


def mark_pixel(ax, rc, color) -> None:
    """Pixel ``rc`` filled with ``color`` above every outline, and outlined in black."""
    i, j = rc
    # above the vertex dots too (plot_triangle draws them at 6.2, over the labels' boxes): the
    # hub is the centre sixteen vertices meet at, hidden under their dots before (review r5)
    ax.add_patch(Rectangle((j, i), 1, 1, fc=color, ec="black", lw=2.5, zorder=6.3))


def plot_owners(ax, owner: np.ndarray, triangles=None, *, outlines: bool = True,
                thin: bool = False, colors: dict | None = None, tiny: bool = False) -> list:  # fmt: skip
    """Pixels coloured by owning triangle, vermillion where covered twice: triangle k in
    ``colors[k]`` (:func:`owner_colors`), by default in :func:`owner_color` (one each).

    Returns the artists drawn (coverage images, then triangle outlines, thin if ``thin``,
    with small vertex marks if ``tiny``).
    """
    h, w = owner.shape
    artists = [plot_pixel_grid(ax, w, h, ticks=False)]
    for k in range(int(owner.max()) + 1):
        if (owner == k).any():
            color = owner_color(k) if colors is None else colors[k]
            artists.append(plot_coverage(ax, owner == k, color=color))
    if (owner == SEVERAL).any():
        artists.append(plot_coverage(ax, owner == SEVERAL, color=COLORS["outside"]))
    if outlines and triangles is not None:
        for xy in triangles:
            artists.append(outline(ax, xy, thin=thin, tiny=tiny))
    return artists


def copy_offsets(triangles) -> list | None:
    """Whole-pixel offsets (dx, dy) of each triangle from the first, when every triangle is a
    copy of the first (any vertex order, moved by whole pixels); None otherwise.

    >>> t = np.array([[0.5, 0.5], [4.5, 0.5], [0.5, 3.5]])
    >>> copy_offsets([t, t[::-1] + [3, 1]])
    [(0, 0), (3, 1)]
    >>> copy_offsets([t, t * 2]) is None
    True
    """
    tris = np.asarray(triangles, dtype=float)
    if len(tris) < 2:
        return None

    def vertex_set(t):
        return np.array(sorted(map(tuple, t)))

    first = vertex_set(tris[0])
    offsets = []
    for t in tris:
        shift = t.min(axis=0) - tris[0].min(axis=0)
        if not np.allclose(shift, np.round(shift)) or not np.allclose(vertex_set(t - shift), first):
            return None
        offsets.append((int(round(shift[0])), int(round(shift[1]))))
    return offsets


def aligned_counts(masks, offsets, box) -> np.ndarray:
    """How many of the copies cover each pixel of ``box`` (rows r0:r1, columns c0:c1 around the
    first copy), each copy's coverage ``mask`` moved back by its offset (dx, dy).

    >>> a = np.zeros((4, 6), bool); a[1, 1] = True
    >>> b = np.roll(a, 3, axis=1)                  # the same pixel, 3 columns to the right
    >>> aligned_counts([a, b], [(0, 0), (3, 0)], (0, 3, 0, 3)).tolist()
    [[0, 0, 0], [0, 2, 0], [0, 0, 0]]
    """
    r0, r1, c0, c1 = box
    total = np.zeros((r1 - r0, c1 - c0), dtype=np.int64)
    for mask, (dx, dy) in zip(masks, offsets):
        padded = np.pad(np.asarray(mask, dtype=bool), 1)  # a box one pixel past the image
        total += padded[r0 + dy + 1 : r1 + dy + 1, c0 + dx + 1 : c1 + dx + 1]
    return total


def copies_box(triangle, shape) -> tuple[int, int, int, int]:
    """Rows r0:r1 and columns c0:c1 of ``triangle``'s bounding box and one pixel around it,
    within an image of ``shape``."""
    xy = np.asarray(triangle, dtype=float)
    h, w = shape
    c0, r0 = (max(int(np.floor(v)) - 1, 0) for v in xy.min(axis=0))
    c1, r1 = int(min(np.ceil(xy[:, 0].max()) + 1, w)), int(min(np.ceil(xy[:, 1].max()) + 1, h))
    return r0, r1, c0, c1


def plot_copies(ax, counts: np.ndarray, n: int, triangle, box) -> int:
    """``counts`` of :func:`aligned_counts` on ``ax``: sky blue where all ``n`` copies cover a
    pixel, dark blue where only some do; the first copy's outline on top. Returns the number
    of pixels where the copies disagree."""
    r0, r1, c0, c1 = box
    plot_pixel_grid(ax, c1 - c0, r1 - r0, ticks=False)
    plot_coverage(ax, counts == n, color=EVERY_COPY)
    plot_coverage(ax, (counts > 0) & (counts < n), color=SOME_COPIES)
    centres_on_top(ax, c1 - c0, r1 - r0, counts > 0)
    outline(ax, np.asarray(triangle, dtype=float) - [c0, r0])
    return int(((counts > 0) & (counts < n)).sum())


#: Case name -> pixels whose owner the fill methods decide differently (a case's pixels do not
#: change between pickers, so each case is compared once).
_METHODS_DIFFER: dict[str, int] = {}


def screen_cases() -> list[str]:
    """Names of the catalogue's screen-space cases (one fill per triangle), in catalogue order."""
    return [name for name, case in hardcases.CASES.items()
            if case.kind in ("mesh", "triangle", "triangles") and case.triangles is not None]  # fmt: skip


class CasePicker:
    """Choose a hard case and a naive rule; see who owns each pixel, and what naive code does.

    Parameters
    ----------
    case : str
        Starting case (one of :func:`screen_cases`).
    rule : str
        The right panel's naive rasteriser, one of :data:`RULES`: :data:`CASE_NAIVE` (the
        case's own naive version) or a rule of :data:`~teachraster.study.hardcases.NAIVE_RULES`.
    backend : {"auto", "ipympl", "image"}
    style : str, optional

    Attributes
    ----------
    widget : ipywidgets.VBox
    case, rule : Dropdown, ToggleButtons
    owner : (H, W) int
        :func:`owner_image` of our fill (half-planes; what the left panel shows).
    naive_counts : (H, W) int or None
        The naive rasteriser's coverage counts (right panel), if there are any (a case without
        a naive version has none under :data:`CASE_NAIVE`).
    naive_says : str
        What the naive rasteriser shown does, in words.
    methods_differ : int
        Pixels whose owner span tables would decide otherwise than half-planes: 0 in every case,
        as the conventions require (said in the text, not a picture of its own).
    passed : bool
        Whether our result passes the case's check.
    offsets : list of (dx, dy) or None
        :func:`copy_offsets` of the case's triangles: set when they are separate copies of one
        triangle, and then both panels show :func:`aligned_counts` instead of owners.
    copies, naive_copies : (h, w) int or None
        How many copies cover each pixel around the first copy: ours, and the naive version's
        (None when it has no per-copy coverage).
    view : (r0, r1, c0, c1) or None
        The rows and columns both panels show (:func:`view_box`; None for copies, which show
        :func:`copies_box`).
    hubs : list of (row, col)
        Pixels whose centre is a vertex of several triangles (:func:`shared_vertex_pixels`),
        filled and outlined on top of the outlines.
    info : ipywidgets.HTML

    Examples
    --------
    >>> picker = CasePicker("d3d_split_square", backend="image")
    >>> picker.passed, int((picker.owner == SEVERAL).sum())
    (True, 0)
    >>> picker.case.value = "fan_spokes_through_centres"
    >>> int(picker.owner.max())
    15
    >>> picker.rule.value = "E > 0"   # strict: the spokes' centres drawn by no triangle
    >>> int(picker.naive_counts.max()), int((picker.naive_counts == 0).sum()) > 300
    (1, True)
    >>> picker.close()
    """

    #: ``teachraster html``: the offline page steps through every hard case (:mod:`.offline`)
    _offline_sweep_ = "case"

    def __init__(self, case: str = "fan_spokes_through_centres", rule: str = CASE_NAIVE, *,
                 backend: str = "auto", style: str | None = None) -> None:  # fmt: skip
        names = screen_cases()
        if case not in names:
            raise ValueError(f"case must be one of the screen-space cases {names}, got {case!r}")
        if rule not in RULES:
            raise ValueError(f"rule must be one of {list(RULES)}, got {rule!r}")
        self.backend = resolve_backend(backend)
        self.case = widgets.Dropdown(options=names, value=case, description="case",
                                     layout=fit_width(widgets.Layout(width="420px")))  # fmt: skip
        # the naive rule, not the fill method: span tables and half-planes give the same
        # pixels, so a method toggle changed nothing on screen (review r227 W-1); a rule does
        self.rule = widgets.ToggleButtons(options=RULES, value=rule)
        self.rule.style.button_width = "auto"
        self._style = style
        self._new_figure()
        self._run()
        self._draw()
        self._places: dict = {}  # (case, rule) -> where the layout put the axes and title
        self._lay_out()
        self.display = FigureDisplay(self.fig, self.backend)
        self.info = widgets.HTML(self._info_html())
        #: pictures of other cases and rules drawn while the kernel idles (image display
        #: only), from the first change on: a lesson run without a page draws none
        self._ahead = PicturesAhead(self._draw_elsewhere) if self.backend == "image" else None
        for control in (self.case, self.rule):
            control.observe(lambda change: self.update(), "value")
        title = title_html(
            "Hard cases: who owns each pixel?",
            "Left: our fill, each pixel in the colour of the triangle that covers it. Right: "
            "what a naive rasteriser covers: the case's own naive version, or the rule you "
            "pick, applied to the case (E ≥ 0 or E > 0: no tie rule; whole px: vertices "
            "rounded to whole pixels; one winding: no re-orientation). The ticks number the "
            "image's rows and columns; the key is under the case's text.",
        )
        controls = control_row([self.case, labelled("naive", self.rule)])
        self.widget = widgets.VBox([title, controls, self.info, self.display.widget])

    def _new_figure(self) -> None:
        with style_context(self._style):
            self.fig = new_figure((9.0, FIG_HEIGHT), self.backend)  # fits the notebook column
            self.fig.set_layout_engine("constrained")
            self.axes = self.fig.subplots(1, 2)
            for ax in self.axes:
                # each panel at the bottom of its box: the layout reserves the room for the
                # ticks under the box, and a panel of equal aspect centred higher up in it
                # left too little (its column numbers fell off the figure's bottom)
                ax.set_anchor("S")

    def _draw_elsewhere(self, key) -> tuple:
        """``(png, caption, state)`` of case and rule ``key``, drawn on a figure of its own
        (a second picker's, made as this one's and kept for the next): the picture this
        picker draws there (:class:`~teachraster.widgets.ahead.PicturesAhead`)."""
        other = getattr(self, "_elsewhere", None)
        if other is None:
            other = self._elsewhere = object.__new__(CasePicker)
            other.backend, other._style, other._places = "image", self._style, self._places
            other.case, other.rule = SimpleNamespace(value=None), SimpleNamespace(value=None)
            other._new_figure()
        other.case.value, other.rule.value = key
        other._run()
        other._draw()
        other._lay_out()
        other.fig.canvas.draw()  # as this picker's display draws it
        state = {k: v for k, v in vars(other).items() if k in PICTURE_STATE}
        return png_bytes(other.fig), other._info_html(), state

    def _run(self) -> None:
        c = hardcases.get_case(self.case.value)
        self._case = c
        result = c.run(c.methods[0])  # half-planes; span tables: the same (_methods_differ)
        self.owner = owner_image(result.fills)
        self.colors = owner_colors(self.owner, c.triangles)
        try:
            c.check(result)
            self.passed, self.failure = True, ""
        except AssertionError as err:
            self.passed, self.failure = False, str(err)
        self.methods_differ = self._methods_differ(result)
        masks = self._naive(result)
        self._copies(result, masks)
        if self.naive_copies is not None and self.rule.value != CASE_NAIVE:
            # copies of one triangle overlap by design: what differs is where they disagree
            n = len(self.offsets)
            k = int(((self.naive_copies > 0) & (self.naive_copies < n)).sum())
            self.difference = (f"naive: the {n} copies, each moved back onto the first, "
                               f"disagree at {k} pixel(s); ours at none")  # fmt: skip

    def _naive(self, result) -> list | None:
        """The right panel's naive rasteriser on this case: its counts, what it filled, what
        it does in words and how it differs from ours; returns its per-triangle coverage
        where it has one (for copies of one triangle), else None."""
        c, rule = self._case, self.rule.value
        if rule != CASE_NAIVE:
            w, h = c.inputs["size"]
            masks, filled = hardcases.naive_rule_masks(c.triangles, w, h, rule)
            self.naive_counts = np.sum(masks, axis=0, dtype=np.int64)
            self.naive_triangles = None if filled is c.triangles else filled
            self.naive_says = f"{rule}: {hardcases.NAIVE_RULES[rule][0]}"
            self.difference = counts_difference(result.counts, self.naive_counts)
            return masks
        naive = c.naive() if c.has_naive else None
        self.naive_counts = None if naive is None else naive.counts
        # the triangles the naive version fills, where they are not the case's (rounded ones)
        self.naive_triangles = ((naive.values or {}).get("triangles") if naive is not None
                                else None)  # fmt: skip
        self.naive_says = c.naive_does
        diff = c.naive_difference(result, naive) if naive is not None else None
        self.difference = diff or ""
        return None if naive is None else (naive.values or {}).get("coverage")

    def _methods_differ(self, result) -> int:
        """Pixels whose owner span tables would decide otherwise than half-planes: 0 for every
        case (the conventions require it), said under the verdict (review r145, 07-15). Run
        once a case (:data:`_METHODS_DIFFER`): a rule's picture costs no second fill."""
        name = self._case.name
        if name not in _METHODS_DIFFER:
            differ = np.zeros(self.owner.shape, dtype=bool)
            for method in self._case.methods[1:]:
                if method in hardcases.FILL_METHODS:
                    differ |= owner_image(self._case.run(method).fills) != self.owner
            _METHODS_DIFFER[name] = int(differ.sum())
        return _METHODS_DIFFER[name]

    def _copies(self, result, masks) -> None:
        # Separate copies of one triangle (not a mesh): every copy moved back onto the first.
        self.offsets = copy_offsets(self._case.triangles)
        self.copies = self.naive_copies = None
        if self.offsets is None:
            return
        self._box = copies_box(self._case.triangles[0], self.owner.shape)
        self.copies = aligned_counts([f.coverage for f in result.fills], self.offsets, self._box)
        if masks is not None and len(masks) == len(self.offsets):
            self.naive_copies = aligned_counts(masks, self.offsets, self._box)

    def _draw(self) -> None:
        with style_context(self._style):
            for ax in self.axes:
                # not ax.clear(): its ticks made anew cost about a third of each picture;
                # every picture sets the limits, aspect, ticks and titles again
                remove_drawn(ax)
            tris = self._case.triangles
            self.hubs, self.view, self.zoomed = [], None, []
            # the case and the rule above both panels; short two-line titles under it, so
            # that the two panels' titles never run into each other
            self.fig.suptitle(f"{self.case.value}, naive: {self.rule.value}")
            if self.copies is not None:
                self._fit_height(None, None)
                self._draw_copies()
                return
            # each case zoomed to its own box (a fan in the middle of a 20 x 20 image, a 60 px
            # sliver one row high): the pixels the case is about, large enough to see
            shown = [self.owner != NONE] + (
                [] if self.naive_counts is None else [self.naive_counts > 0]
            )
            r0, r1, c0, c1, cut_rows, cut_cols = view_box(tris, self.owner.shape, *shown)
            h, w = self.owner.shape
            if cut_rows:  # a corner of a large case: say which, and of what, on a line of its own
                self.fig.suptitle(f"{self.case.value}, naive: {self.rule.value}\nrows "
                                  f"{r0}–{r1 - 1}, columns {c0}–{c1 - 1} of {h} × {w}")  # fmt: skip
            elif cut_cols:
                self.fig.suptitle(f"{self.case.value}, naive: {self.rule.value} (columns "
                                  f"{c0}–{c1 - 1} of {w})")  # fmt: skip
            self.view = (r0, r1, c0, c1)
            self._fit_height(r1 - r0, c1 - c0)
            # a corner cut from a large case (the diagonal sliver) keeps the thin outlines of
            # its whole grid: at the classroom width the outline covers the pixels it owns
            thin = thin_lines((r1 - r0, c1 - c0), len(tris)) or cut_rows
            tiny = tiny_triangles(tris)
            plot_owners(self.axes[0], self.owner, tris, thin=thin, colors=self.colors, tiny=tiny)
            # the centres, filled where covered, as in the lesson's figures: ownership is
            # decided there (review r57, 07-3: without them the split square's blue looked
            # half a pixel off its outline)
            centres_on_top(self.axes[0], w, h, self.owner != NONE)
            self.axes[0].set_title(f"ours:\n{int((self.owner != NONE).sum())} px, colour = owner")
            ax = self.axes[1]
            if self.naive_counts is None:
                h, w = self.owner.shape
                plot_pixel_grid(ax, w, h, ticks=False)
                ax.set_title("naive:\nno version for this case")
            else:
                n = self.naive_counts
                plot_pixel_grid(ax, n.shape[1], n.shape[0], ticks=False)
                plot_coverage(ax, n == 1, color=NAIVE_ONCE)
                plot_coverage(ax, n >= 2, color=COLORS["outside"])
                # the triangles the naive version filled: the sub-pixel ones rounded to whole
                # pixels (review r145, 07-16: the given ones missed the centres it covers)
                shown_tris = tris if self.naive_triangles is None else self.naive_triangles
                for xy in shown_tris:
                    outline(ax, xy, thin=thin, tiny=tiny)
                centres_on_top(ax, n.shape[1], n.shape[0], n > 0)
                ax.set_title(f"naive:\n{int((n > 0).sum())} px"
                             + (f", up to {int(n.max())} hits" if n.max() > 1 else ""))  # fmt: skip
            # a centre at a vertex of many triangles (the fan's hub) on top of their outlines
            self.hubs = shared_vertex_pixels(tris, self.owner.shape)
            for rc in self.hubs:
                mark_pixel(self.axes[0], rc, self._owner_fill(self.owner[rc]))
                if self.naive_counts is not None:
                    k = self.naive_counts[rc]
                    mark_pixel(
                        ax, rc, "white" if k == 0 else NAIVE_ONCE if k == 1 else COLORS["outside"]
                    )
            for a in self.axes:
                a.set(xlim=(c0, c1), ylim=(r1, r0))
                window_ticks(a, r0, r1, c0, c1)
            self._zoom_specks()

    def _zoom_specks(self) -> None:
        """An inset on each panel magnifying the triangles too small to see in it
        (:data:`ZOOM_BELOW`; :func:`zoom_inset`): ours as given, the naive version's as it
        filled them (rounded to whole pixels, where its rule rounds)."""
        self.zoomed = []
        panels = [(self.axes[0], self._case.triangles, self.owner != NONE, None)]
        if self.naive_counts is not None:
            shown = self._case.triangles if self.naive_triangles is None else self.naive_triangles
            panels.append((self.axes[1], shown, self.naive_counts > 0, NAIVE_ONCE))
        for ax, tris, covered, colour in panels:
            tris = np.asarray(tris, dtype=float)
            size = np.ptp(tris, axis=1).max(axis=-1)
            small = np.flatnonzero((size > 0) & (size < ZOOM_BELOW))  # a point needs no zoom
            # one inset, for specks that lie together (none of the catalogue's lie apart)
            if not len(small) or np.ptp(tris[small].reshape(-1, 2), axis=0).max() >= ZOOM_BELOW:
                continue
            # ours: each triangle in its owner's colour (a grey where it owns no pixel)
            fills = [colour or self.colors.get(k, NAIVE_ONCE) for k in small]
            zoom_inset(ax, tris[small], covered, fills, view=self.view)
            self.zoomed.append(ax)

    def _fit_height(self, rows, cols) -> None:
        """The figure as high as the view needs: a view 3 times as wide as high (the sliver
        pair's 4 x 12 pixels) left two thirds of a 4.4-inch figure white (review r6, 07-4)."""
        height = FIG_HEIGHT
        if rows is not None:  # two panels of PANEL_WIDTH inches, titles above them
            height = min(FIG_HEIGHT, max(MIN_FIG_HEIGHT, TITLES_HEIGHT + PANEL_WIDTH * rows / cols))
        if abs(self.fig.get_figheight() - height) > 0.01:
            self.fig.set_size_inches(self.fig.get_figwidth(), height)

    def _owner_fill(self, k) -> str:
        return "white" if k == NONE else COLORS["outside"] if k == SEVERAL else self.colors[int(k)]

    def _draw_copies(self) -> None:
        n, first = len(self.offsets), self._case.triangles[0]
        differ = plot_copies(self.axes[0], self.copies, n, first, self._box)
        self.axes[0].set_title(f"ours, {n} copies:\n{differ} px differ")
        ax = self.axes[1]
        r0, r1, c0, c1 = self._box
        if self.naive_copies is None:
            plot_pixel_grid(ax, c1 - c0, r1 - r0, ticks=False)
            ax.set_title("naive:\nno per-copy coverage")
        else:
            differ = plot_copies(ax, self.naive_copies, n, first, self._box)
            ax.set_title(f"naive, {n} copies:\n{differ} px differ")  # its rule: above
        for a in self.axes:  # the box's own pixels, numbered as the first copy's in the image
            window_ticks(a, 0, r1 - r0, 0, c1 - c0, dr=r0, dc=c0)

    def _lay_out(self) -> None:
        """Place the two axes as the constrained layout does for this case and rule, solved
        once for each (their grid, ticks and titles set the layout): the solver cost about
        half of each picture (issue 31: 402 ms a control)."""
        # the layout also places the figure's title (matplotlib keeps it in _suptitle)
        title = getattr(self.fig, "_suptitle", None)
        key = (self.case.value, self.rule.value)
        place = self._places.get(key)
        if place is None:
            for ax in self.axes:
                # the solver starts from where the axes stand (their titles sit on the last
                # case's box) and its two passes do not converge: moved from another case,
                # coincident_vertices and sliver_pair got another layout than a fresh picker
                # gives them. Start where a fresh figure's axes stand, in their grid cell.
                ax.set_position(ax.get_subplotspec().get_position(self.fig))
                ax.set_in_layout(True)  # set_position() took it out of the layout
            self.fig.set_layout_engine("constrained")
            # the solver alone, as a draw runs it, without rendering a picture no one sees
            # (the same boxes for all 75 cases and rules; a fifth of each new picture's CPU)
            self.fig.get_layout_engine().execute(self.fig)
            # the box the layout gave each axes, before its equal aspect shrinks it (the
            # next case's grid takes its own shape in the same box)
            place = [ax.get_position(original=True) for ax in self.axes]
            place.append(None if title is None else title.get_position())
            self._places[key] = place
        self.fig.set_layout_engine("none")
        for ax, box in zip(self.axes, place):
            ax.set_position(box, which="original")
        if title is not None and place[-1] is not None:
            title.set_position(place[-1])

    def update(self) -> None:
        """Run the chosen case with the chosen rule and redraw (a picture drawn ahead for
        them: shown at once)."""
        key = (self.case.value, self.rule.value)
        kept = None if self._ahead is None else self._ahead.take(key)
        if kept is not None:
            show_kept(self, kept)
        else:
            self._run()
            self._draw()
            self._lay_out()
            self.info.value = self._info_html()
            self.display.refresh()
            if self._ahead is not None:
                state = {k: v for k, v in vars(self).items() if k in PICTURE_STATE}
                self._ahead.keep(key, (self.display.widget.value, self.info.value, state))
        if self._ahead is not None:
            # the likeliest next choices: the rules either side here, the cases either side
            names, rules = list(self.case.options), list(self.rule.options)
            i, k = names.index(key[0]), rules.index(key[1])
            near = [names[j] for j in (i + 1, i - 1) if 0 <= j < len(names)]
            beside = [rules[j] for j in (k + 1, k - 1) if 0 <= j < len(rules)]
            keys = [(key[0], r) for r in beside] + [(n, key[1]) for n in near]
            self._ahead.want([k for k in keys if k != key])

    def _info_html(self) -> str:
        c = self._case
        # the simulator's self-test speaks only when it fails: the text is about the GPU's
        # rules (review r284 S-5; the lesson's introduce() is silent the same way)
        lines = [f"<b>why</b>: {html.escape(c.why)}", f"<b>must</b>: {html.escape(c.expect)}"]
        if not self.passed:
            lines.append(f"ours: <b style='color:#D55E00'>FAILS</b>: {html.escape(self.failure)}")
        if self.methods_differ:
            lines.append(self._methods_html())
        if self.naive_says:
            lines.append(f"<b>naive</b>: {html.escape(self.naive_says)}")
        if self.difference:
            lines.append(f"→ {html.escape(self.difference)}")
        lines.append(self._key_html())
        return "<br>".join(lines)

    def _methods_html(self) -> str:
        """One line, shown only when the fill methods disagree here: which, and where."""
        names = " and ".join(m for m in self._case.methods if m in hardcases.FILL_METHODS)
        return (f"<b style='color:#D55E00'>{names} differ at {self.methods_differ} "
                "pixel(s)</b>")  # fmt: skip

    def _key_html(self) -> str:
        """The figure's key: what each colour means for this case."""

        def swatch(color, text):
            return f"<span style='color:{color}'>■</span> {text}"

        if self.copies is not None:
            return (f"<b>key</b>: separate copies of one triangle (not a mesh), each moved back "
                    f"onto the first: {swatch(EVERY_COPY, 'covered by every copy')}, "
                    f"{swatch(SOME_COPIES, 'by only some (the copies disagree)')}; "
                    + self._marks_html() + f"; {TICKS_KEY} (the first copy's)")  # fmt: skip
        # triangles numbered from 1, as in the lesson's text (review r119 07-B)
        # name only what the panels draw (review r8, lesson 07: a one-triangle case listed
        # three owner colours and a class of pixels covered twice that neither panel showed)
        owners = sorted({int(k) for k in np.unique(self.owner) if k >= 0})
        if not owners:
            left = "left, no pixel owned"
        elif len(owners) == 1:
            left = f"left, {swatch(self.colors[owners[0]], f'triangle {owners[0] + 1}')}"
        elif len(set(self.colors.values())) == len(owners):
            more = "…" if len(owners) > 3 else ""
            left = (
                "left, one colour per triangle ("
                + "".join(swatch(self.colors[k], "") for k in owners[:3])
                + f"{more})"
            )
        else:  # more owners than colours: neighbours differ (review r11, 07)
            used = [c for c in NEIGHBOUR_COLORS if c in self.colors.values()]
            # every two owners whose pixels touch differ, not only those sharing an edge, as
            # owner_colors() colours them and the lesson says (review r65, 07-2)
            left = (f"left, {len(owners)} triangles in {len(used)} colours ("
                    + "".join(swatch(c, "") for c in used)
                    + "), two triangles whose pixels share a side never alike: the outlines tell the "
                    "others apart")  # fmt: skip
        n = self.naive_counts
        parts = [left]
        if n is not None and (n == 1).any():
            parts.append(f"right, {swatch(NAIVE_ONCE, 'covered once')}")
        twice = [
            name
            for name, drawn in (
                ("left", (self.owner == SEVERAL).any()),
                ("right", n is not None and (n >= 2).any()),
            )
            if drawn
        ]
        if twice:
            where = "both" if len(twice) == 2 else twice[0]
            parts.append(f"{where}, {swatch(COLORS['outside'], 'covered twice or more')}")
        key = "<b>key</b>: " + "; ".join(parts + [self._marks_html(), TICKS_KEY])
        shown = self._case.triangles if self.naive_triangles is None else self.naive_triangles
        if any(is_point(xy) for xy in shown):
            key += (f"; <span style='color:{COLORS['outside']}'>◆</span> a triangle of zero "
                    "size: its vertices rounded to one point")  # fmt: skip
        if self.zoomed:
            key += ("; the inset magnifies a triangle too small to see on the grid, in the dashed "
                    "ring (× across by "
                    "up and down, where they differ): as given "
                    f"(filled), and <span style='color:{VERTEX_COLOR}'>dashed</span> with its "
                    "vertices snapped to the 1/256-px grid (the grey lines), "
                    f"<span style='color:{COLORS['outside']}'>◆</span> where they all snap to "
                    "one point")  # fmt: skip
        for i, j in self.hubs:
            owner = int(self.owner[i, j])
            who = (
                f"triangle {owner + 1}"
                if owner >= 0
                else "no triangle"
                if owner == NONE
                else "several"
            )
            key += (f"; outlined in black, pixel ({i}, {j}): its centre is a vertex of several "
                    f"triangles, ours gives it to {swatch(self._owner_fill(owner), who)}")  # fmt: skip
        return key

    @staticmethod
    def _marks_html() -> str:
        """The key of the marks on both panels: the pixel centres' dots and the vertices."""
        centre, vertex = COLORS["edge"], VERTEX_COLOR
        return (f"<span style='color:{centre}'>●</span> pixel centre covered, "
                f"<span style='color:{COLORS['centre']}'>○</span> not covered, "
                f"<span style='color:{vertex}; font-weight:bold'>□</span> a triangle's vertex")  # fmt: skip

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_
    noun = "case picker"  # the stand-in's hint: "No kernel is running this case picker"

    def close(self) -> None:
        """Close every widget of the picker."""
        if self._ahead is not None:
            self._ahead.close()
        self.display.close()
        close_tree(self.widget)
