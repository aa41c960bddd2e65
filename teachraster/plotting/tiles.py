"""Plots of the tiled fill: blocks by kind at each level, the counters, traversal orders.

``fill = tr.rasterize(tri, W, H, method="tiled", trace=True)``; then

- :func:`plot_blocks` -- the classified blocks over the pixel grid, coloured by kind
  (rejected / accepted / partial): one level of the hierarchy (``level=``), or every block
  visited up to a step of a traversal (``upto=``, ``traversal=``);
- :func:`plot_hierarchy` -- one panel per block size, with the coverage and the triangle;
- :func:`plot_block_counters` -- llvmpipe's counters as a small table;
- :func:`plot_traversal` -- the visiting order of a grid's cells (scanline, serpentine,
  tiled, Morton) as colours and a path.
- :func:`plot_llvmpipe_bins` -- llvmpipe's binning pass over the 64×64 tiles of a box.
- :func:`plot_block_values` -- one edge's values over a block, its two extreme corners
  marked (the corner trick).

Every function takes an Axes (``plot_hierarchy`` a sequence of them) and returns artists.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import matplotlib as mpl
import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.colors import BoundaryNorm, ListedColormap, to_rgba
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle
from matplotlib.patheffects import withStroke
from matplotlib.table import Table
from matplotlib.text import Text

from ..core.tile_trace import KINDS, PARTIAL, TileTrace
from ..core.trace import FillTrace
from ..core.traversal import TRAVERSALS, traversal_order
from ..core.validate import check_choice
from .common import Artists, as_trace, fs, lw, nice_step, pixel_axes, show_image, tint
from .plots import grid_segments, plot_pixel_grid, plot_triangle
from .style import COLORS, OKABE_ITO, VALUE_CMAP

#: The colour of each block kind.
BLOCK_COLORS = {
    "rejected": "#BDBDBD",
    "accepted": OKABE_ITO["bluish_green"],
    "partial": OKABE_ITO["orange"],
}
#: Fill opacity of a block: opaque, so that a child drawn over its partial parent (and a
#: block over the coverage) shows its own colour, never a mixture with no key.
BLOCK_ALPHA = 1.0
#: Block outlines: white, so that neighbouring blocks of one kind stay apart.
BLOCK_EDGE = "white"
#: What a view shows where no block is (yet): the white page and its pixel grid.
UNCLASSIFIED = "not classified (yet)"
#: The key's name for the outline of the block a walk visits now (``current=True``).
CURRENT_BLOCK = "the block visited now"
#: The key's name for the children of a visited partial block that the walk has not reached
#: yet (``current=True``): a paler orange with the white page's outline, not the parent's
#: orange, which read as "partial" before they were classified (review r70, lesson 10 #2).
PENDING = "inside a partial block: not visited yet"
#: ... and their colour: the partial orange at this opacity over white.
PENDING_TINT = 0.35
#: The key's name for the blocks a level's view shows that a larger block decided (accepted
#: or rejected whole, :func:`decided_mask`): hatched, so that the tests made at the size shown
#: (solid) stand apart from the pixels filled or skipped with no test of their own; at the
#: 1×1 level, the pixel tests from the pixels filled by an accepted block (review r235 FIG1:
#: both were the same green). Two lines: on one, the explorer's key widened its picture by
#: 1.5 inches and shrank the grid in a notebook column.
DECIDED = "hatched: decided by a larger block,\nno test of its own"
#: ... their hatch, in white over the kind's colour.
DECIDED_HATCH = "//"


def tile_trace(fill, what: str = "this plot") -> tuple[FillTrace, TileTrace]:
    """The FillTrace and its TileTrace of a tiled fill (``method="tiled"``, ``trace=True``)."""
    trace = as_trace(fill, what)
    if trace.blocks is None:
        raise ValueError(
            f"{what} needs a tiled fill: tr.rasterize(..., method='tiled', trace=True)"
        )
    return trace, trace.blocks


def pending_children(blocks: TileTrace, shown: np.ndarray) -> np.ndarray:
    """(n,) bool: the blocks not ``shown`` whose parent is (the children of a visited partial
    block that a walk has not reached yet)."""
    shown = np.asarray(shown, dtype=bool)
    parent = np.asarray(blocks.parent)
    has = parent >= 0
    pending = np.zeros(len(shown), dtype=bool)
    pending[has] = shown[parent[has]] & ~shown[has]
    return pending


def decided_mask(blocks: TileTrace, level: int | None) -> np.ndarray:
    """(n,) bool: the blocks that a view of ``level`` shows (:func:`block_mask`) and that a
    larger block decided: accepted or rejected at a size above ``block_sizes[level]``, so no
    block of the size shown was tested inside them. None: no level, none decided."""
    if level is None:
        return np.zeros(len(blocks), dtype=bool)
    return (blocks.level < level) & (blocks.kind_code != PARTIAL)


def block_mask(
    blocks: TileTrace, *, level: int | None = None, upto: int | None = None, traversal="scanline"
) -> np.ndarray:
    """(n,) bool: the blocks a view shows.

    ``level=L``: the hierarchy after classifying size ``block_sizes[L]``: accepted and
    rejected blocks of the larger sizes and every block of size L. ``upto=k``: the first
    ``k + 1`` blocks visited in ``traversal`` order. Neither: every block.
    """
    n = len(blocks)
    if level is not None:
        return ((blocks.level < level) & (blocks.kind_code != PARTIAL)) | (blocks.level == level)
    if upto is not None:
        shown = np.zeros(n, dtype=bool)
        shown[blocks.visit_order(traversal)[: max(int(upto) + 1, 0)]] = True
        return shown
    return np.ones(n, dtype=bool)


@dataclass
class BlockArtists(Artists):
    """Blocks of a :func:`plot_blocks` (one PolyCollection) and its legend handles."""

    blocks: PolyCollection
    legend: object | None = None
    order: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    kinds: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    sizes: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))
    #: the outline of the block visited now (``plot_blocks(..., current=True)``), else None
    current: Line2D | None = None
    #: its line width in points, the style's when plotted (thinner around small blocks)
    current_width: float = 2.0
    #: the pixel grid drawn over the blocks of a zoomed window (:meth:`show_window`), else None
    window_grid: LineCollection | None = None
    #: the window shown: (col, row, width, height) of pixels, or None (the whole image)
    window: tuple[int, int, int, int] | None = None
    #: the hatch over the blocks a larger block decided (``plot_blocks(..., decided=True)``,
    #: :data:`DECIDED`), else None
    decided: PolyCollection | None = None
    #: the blocks' rectangles in drawing order, which the hatch layer picks from
    rects: np.ndarray = field(default_factory=lambda: np.zeros((0, 4, 2)))

    def show_current(self, blocks: TileTrace, b: int | None) -> None:
        """Outline block ``b`` of ``blocks`` (:func:`current_block_xy`), or nothing when
        ``b`` is None, in place. Inside a zoomed :attr:`window` a small block is large on
        screen: its outline alone, without the ticks pointing at it."""
        if self.current is None:
            return
        self.current.set_visible(b is not None)
        if b is not None:
            rows, cols = blocks.extent[b]
            # the ticks' lengths are pixels of the image: zoomed 4x, they became crosses
            # reaching 4 px past the block and off the axes (review r62, lesson 10 #1)
            pointers = self.window is None
            xy = current_block_xy(blocks.row[b], blocks.col[b], rows, cols, pointers=pointers)
            self.current.set_data(*xy)
            width = self.current_width
            if pointers and max(int(rows), int(cols)) < SMALL_BLOCK:  # thinner, not a hairline
                width = min(width, max(SMALL_LINE * width, THINNEST))
            _outline_width(self.current, width)

    def show_window(self, ax, width: int, height: int, window=None) -> None:
        """Show the ``height`` × ``width`` image whole (``window`` None), or zoom ``ax`` on
        ``window`` = (col, row, w, h) pixels: exactly those pixels, ticks on them, and
        its pixel grid drawn over the blocks (the image's grid lies under the opaque blocks:
        a zoomed 4×4 block showed no pixel in it). Call :meth:`show_current` next."""
        self.window = None if window is None else tuple(int(v) for v in window)
        if self.window is None:
            pixel_axes(ax, width, height)
            if self.window_grid is not None:
                self.window_grid.set_visible(False)
            return
        c, r, w, h = self.window
        # exactly the block: half a pixel of margin showed strips of the neighbouring blocks
        # (review r70, lesson 10 #1); the current outline is not clipped, so it stays whole
        ax.set(xlim=(c, c + w), ylim=(r + h, r))
        for axis, start, n in ((ax.xaxis, c, w), (ax.yaxis, r, h)):
            idx = np.arange(start, start + n, nice_step(n, 4))
            axis.set_ticks(idx + 0.5, labels=[str(i) for i in idx])
        if self.window_grid is None:
            self.window_grid = window_grid(ax)
        segments = np.asarray(grid_segments(w, h), dtype=float) + (c, r)
        self.window_grid.set_segments(segments)
        self.window_grid.set_visible(True)

    def show(self, mask: np.ndarray, pending: np.ndarray | None = None,
             decided: np.ndarray | None = None) -> None:  # fmt: skip
        """Show only the blocks where ``mask`` (indexed like the trace) is True, in place,
        those where ``pending`` is True in the :data:`PENDING` style (not yet classified), and
        hatch those where ``decided`` is True (:data:`DECIDED`; with a hatch layer only)."""
        visible = np.asarray(mask, dtype=bool)[self.order]
        if self.decided is not None:
            hatched = np.zeros(len(visible), dtype=bool)
            if decided is not None:
                hatched = np.asarray(decided, dtype=bool)[self.order] & visible
            # only the hatched blocks' outlines: a hatch has no colour of its own to hide
            self.decided.set_verts(self.rects[hatched])
        face = _colors(self.kinds, BLOCK_ALPHA)
        edge = np.tile(to_rgba(BLOCK_EDGE), (len(self.kinds), 1))
        ones = np.asarray(self.sizes) == 1  # a white outline would hide a 1×1 block's colour
        edge[ones] = face[ones]
        face[~visible, 3] = 0.0
        edge[~visible, 3] = 0.0
        if pending is not None:
            waiting = np.asarray(pending, dtype=bool)[self.order] & ~visible
            face[waiting] = tint(BLOCK_COLORS["partial"], PENDING_TINT)
            edge[waiting] = to_rgba(COLORS["grid"])
        self.blocks.set_facecolor(face)
        self.blocks.set_edgecolor(edge)

    def set_order(self, blocks: TileTrace, order: np.ndarray) -> None:
        """Draw the same ``blocks`` in another visiting ``order`` (another traversal), in
        place: what :func:`plot_blocks` draws with that traversal, without new artists.
        Call :meth:`show` next."""
        self.order = np.asarray(order)
        self.kinds = blocks.kind_code[self.order].astype(int)
        self.sizes = blocks.size[self.order]
        self.rects = _rectangles(blocks, self.order)
        self.blocks.set_verts(self.rects)


def _colors(kinds: np.ndarray, alpha: float) -> np.ndarray:
    table = np.array([to_rgba(BLOCK_COLORS[k], alpha) for k in KINDS])
    return table[kinds].reshape(-1, 4)


def _rectangles(blocks: TileTrace, order: np.ndarray) -> np.ndarray:
    r, c = blocks.row[order], blocks.col[order]
    h, w = blocks.extent[order, 0], blocks.extent[order, 1]
    return np.stack(
        [np.stack([c, r], 1), np.stack([c + w, r], 1), np.stack([c + w, r + h], 1),
         np.stack([c, r + h], 1)], axis=1,
    ).astype(float)  # fmt: skip


def plot_blocks(
    ax,
    fill,
    *,
    level: int | None = None,
    upto: int | None = None,
    traversal: str = "scanline",
    legend: bool = True,
    unclassified: bool | None = None,
    current: bool = False,
    decided: bool = False,
) -> BlockArtists:
    """Draw the classified blocks of a tiled fill, coloured by kind.

    Parameters
    ----------
    ax : matplotlib Axes
        Pixel axes (e.g. from :func:`~teachraster.plotting.plot_pixel_grid`).
    fill : Fill (``method="tiled"``, ``trace=True``) or its FillTrace
    level : int, optional
        Show the hierarchy down to ``block_sizes[level]`` (see :func:`block_mask`).
    upto : int, optional
        Show the blocks visited up to this block step (0 = the first block).
    traversal : {"scanline", "serpentine", "tiled", "morton"}
        Sibling order of the walk; blocks are drawn in visiting order, so a child lies on
        top of its partial parent.
    legend : bool
        A legend of the three kinds and of the white page where no block is
        (:func:`block_legend_handles`).
    unclassified : bool, optional
        Whether the key lists the white page "not classified (yet)". None (default): only
        when the blocks drawn leave part of the bounding box's blocks unclassified (a key
        entry no panel shows misleads). A view that later shows fewer blocks passes True.
    current : bool
        An outline for the block a walk visits now, hidden until
        ``show_current(blocks, b)`` places it (:func:`current_block_outline`), and its key
        entry (:data:`CURRENT_BLOCK`).
    decided : bool
        A hatch over the blocks a larger block decided (:func:`decided_mask`: at ``level``,
        or as ``show(..., decided=)`` says later), and its key entry (:data:`DECIDED`).

    Returns
    -------
    BlockArtists
        ``blocks`` (PolyCollection); ``show(mask)`` changes which blocks are visible;
        ``current`` the outline (or None).
    """
    _, blocks = tile_trace(fill, "plot_blocks")
    check_choice("traversal", traversal, TRAVERSALS)
    order = blocks.visit_order(traversal)
    rects = _rectangles(blocks, order)
    coll = PolyCollection(rects, linewidths=lw(0.5), zorder=2.5)
    ax.add_collection(coll, autolim=False)
    result = BlockArtists(coll, order=order, kinds=blocks.kind_code[order].astype(int),
                          sizes=blocks.size[order], rects=rects)  # fmt: skip
    if decided:
        result.decided = decided_layer(ax)
    shown = block_mask(blocks, level=level, upto=upto, traversal=traversal)
    result.show(shown, decided=decided_mask(blocks, level))
    if current:
        result.current = current_block_outline(ax)
        result.current_width = result.current.get_linewidth()
        result.window_grid = window_grid(ax)
    if legend:
        if unclassified is None:
            unclassified = has_unclassified(blocks, shown)
        handles = block_legend_handles(unclassified=unclassified, decided=decided)
        if current:
            handles.append(Patch(facecolor=tint(BLOCK_COLORS["partial"], PENDING_TINT),
                                 edgecolor=COLORS["grid"], label=PENDING))  # fmt: skip
            handles.append(Patch(facecolor="none", edgecolor=COLORS["current"],
                                 linewidth=lw(0.8), label=CURRENT_BLOCK))  # fmt: skip
        result.legend = ax.legend(handles=handles, loc="upper left",
                                  bbox_to_anchor=(1.02, 1), fontsize=fs(0.7),
                                  frameon=False)  # fmt: skip
    return result


#: Blocks narrower than this many pixels get four ticks pointing at their outline: a 1×1
#: block of a 64-pixel grid is a few screen pixels wide.
SMALL_BLOCK = 4
#: Around such a block the outline and ticks are this much thinner, and the ticks stop
#: :data:`TICK_GAP` pixels short of it: at the full width they joined the outline into a
#: cross that hid the pixel (review r12, lesson 10: "the 1×1 ticks read as a bracket").
SMALL_LINE, TICK_GAP = 0.5, 1.0
#: The thinnest that outline gets, in points (two screen pixels at 96 dpi).
THINNEST = 1.5


def current_block_xy(row: int, col: int, rows: int, cols: int, reach: float = 3.0, *,
                     pointers: bool = True):  # fmt: skip
    """(x, y) of the current block's marker: the outline of its ``rows`` × ``cols`` pixels
    from (``row``, ``col``), and (``pointers``) for a block under :data:`SMALL_BLOCK` pixels
    four ticks ``reach`` pixels long pointing at it from :data:`TICK_GAP` pixels outside (NaN
    separates the pieces). A view zoomed on the block passes ``pointers=False``.

    >>> current_block_xy(4, 32, 4, 4)
    ([32, 36, 36, 32, 32], [4, 4, 8, 8, 4])
    >>> current_block_xy(0, 0, 1, 1, pointers=False)
    ([0, 1, 1, 0, 0], [0, 0, 1, 1, 0])
    """
    r, c, h, w = int(row), int(col), int(rows), int(cols)
    x, y = [c, c + w, c + w, c, c], [r, r, r + h, r + h, r]
    if pointers and max(h, w) < SMALL_BLOCK:
        gap, mx, my, t = np.nan, c + w / 2, r + h / 2, TICK_GAP
        x += [gap, c - t - reach, c - t, gap, c + w + t, c + w + t + reach,
              gap, mx, mx, gap, mx, mx]  # fmt: skip
        y += [gap, my, my, gap, my, my, gap, r - t - reach, r - t,
              gap, r + h + t, r + h + t + reach]  # fmt: skip
    return x, y


def current_block_outline(ax) -> Line2D:
    """A hidden outline for the block a walk visits now: the course's colour of the current
    step (vermillion), over the triangle, with a white halo that keeps it apart from an
    orange partial block and the black edges (review r11, lesson 10: a student could not
    see where the walk was among 800 blocks)."""
    # not clipped: the ticks that point at a small block on the image's border reach into
    # the margin (review r26: at block 5, a 1×1 block in row 0, the upper tick was cut off)
    (outline,) = ax.plot([], [], color=COLORS["current"], zorder=5, solid_capstyle="butt",
                         visible=False, clip_on=False)  # fmt: skip
    _outline_width(outline, lw(0.8))
    return outline


def window_grid(ax) -> LineCollection:
    """A hidden pixel grid above the blocks (below the triangle) for a zoomed window
    (:meth:`BlockArtists.show_window`): the image's grid lies under the opaque blocks."""
    grid = LineCollection([], colors=COLORS["grid"], linewidths=max(0.6, lw(0.25)),
                          zorder=2.6, visible=False)  # fmt: skip
    ax.add_collection(grid, autolim=False)
    return grid


def _outline_width(outline: Line2D, width: float) -> None:
    """The outline's line width and its white halo's (3 points wider)."""
    outline.set_linewidth(width)
    outline.set_path_effects([withStroke(linewidth=width + 3, foreground="white")])


def decided_layer(ax) -> PolyCollection:
    """An empty hatch layer over the blocks (under their current outline and the pixel grid of
    a zoomed window) for :attr:`BlockArtists.decided`: white lines, no face, no edge."""
    layer = PolyCollection(np.zeros((0, 4, 2)), facecolors="none", edgecolors="none",
                           linewidths=0, hatch=DECIDED_HATCH, hatchcolor="white",
                           zorder=2.55)  # fmt: skip
    layer.set_hatch_linewidth(1.6)  # read on a projector over green and grey alike
    ax.add_collection(layer, autolim=False)
    return layer


def block_legend_handles(*, unclassified: bool = True, decided: bool = False) -> list[Patch]:
    """The key of :func:`plot_blocks`: one patch per kind, (``unclassified``) the page where no
    block is (yet), and (``decided``) the hatch over blocks a larger block decided."""
    handles = [Patch(facecolor=BLOCK_COLORS[k], edgecolor=BLOCK_COLORS[k], label=k)
               for k in KINDS]  # fmt: skip
    if decided:  # the hatch over the accepted green, as most hatched blocks show it
        key = Patch(facecolor=BLOCK_COLORS["accepted"], edgecolor=BLOCK_COLORS["accepted"],
                    hatch=DECIDED_HATCH, label=DECIDED)  # fmt: skip
        key.set_hatchcolor("white")
        handles.append(key)
    if unclassified:
        handles.append(Patch(facecolor="white", edgecolor=COLORS["grid"], label=UNCLASSIFIED))
    return handles


def has_unclassified(blocks: TileTrace, shown: np.ndarray) -> bool:
    """Whether the ``shown`` blocks leave a pixel of the top-level blocks uncovered.

    The top-level blocks tile the triangle's bounding box: a pixel of theirs that no shown
    block covers is the white page the key calls "not classified (yet)".
    """
    shown = np.asarray(shown, dtype=bool)
    if len(blocks) == 0:
        return False
    bottom = int((blocks.row + blocks.extent[:, 0]).max())
    right = int((blocks.col + blocks.extent[:, 1]).max())
    todo = np.zeros((bottom, right), dtype=bool)
    done = np.zeros_like(todo)
    for i in range(len(blocks)):
        if blocks.level[i] != 0 and not shown[i]:
            continue
        r, c = int(blocks.row[i]), int(blocks.col[i])
        window = (slice(r, r + int(blocks.extent[i, 0])), slice(c, c + int(blocks.extent[i, 1])))
        if blocks.level[i] == 0:
            todo[window] = True
        if shown[i]:
            done[window] = True
    return bool((todo & ~done).any())


def plot_hierarchy(axes, fill, *, triangle: bool = True) -> list[BlockArtists]:
    """One panel per block size: the hierarchy after classifying that size.

    Each panel shows the pixel grid, the triangle and the blocks (opaque: at every level they
    tile the bounding box, so the coverage is theirs to show); the blocks a larger one decided
    are hatched (:data:`DECIDED`), the ones classified at the panel's size solid. Its title
    gives the size and that level's counts.
    """
    trace, blocks = tile_trace(fill, "plot_hierarchy")
    axes = list(np.ravel(axes))
    if len(axes) < len(blocks.block_sizes):
        raise ValueError(f"plot_hierarchy needs {len(blocks.block_sizes)} Axes, got {len(axes)}")
    out = []
    c = blocks.counters
    for lev, (ax, size) in enumerate(zip(axes, blocks.block_sizes)):
        plot_pixel_grid(ax, trace.width, trace.height, ticks=4)
        if triangle:
            plot_triangle(ax, trace.snapped, arrows=False, labels=False)
        out.append(plot_blocks(ax, trace, level=lev, legend=lev == len(axes) - 1,
                               decided=True))  # fmt: skip
        ax.set_title(
            f"{size}×{size}: {c.empty[lev]} rejected, {c.full[lev]} accepted, "
            f"{c.partial[lev]} partial",
            fontsize=fs(0.8),
        )
    return out


@dataclass
class CounterArtists(Artists):
    """The table of a :func:`plot_block_counters` and its title."""

    table: Table
    title: Text | None = None


def plot_block_counters(ax, fill, *, title: bool = True) -> CounterArtists:
    """llvmpipe's counters as a table: rejected / accepted / partial blocks per size (llvmpipe:
    empty / full / partial), pixel tests.

    Accepts a tiled Fill or FillTrace, or a :class:`~teachraster.core.tile_trace.BlockCounters`.
    """
    counters = getattr(fill, "counters", None)
    if counters is None:
        counters = tile_trace(fill, "plot_block_counters")[1].counters
    rows = [[lab, str(e), str(f), str(p)] for lab, e, f, p in counters.table()]
    # the pixels' numbers under a header of their own: under "acc." and "part." they read as
    # blocks, and the 1×1 row above says 0 partial (reviews r30, r36 lesson 10)
    rows.append(["pixels", "", "no test", "tested"])
    # the numbers' row labelled too (review r52, lesson 10: it read as a stray row)
    rows.append(["count", "", f"{counters.pixels_accepted:,}", f"{counters.pixel_tests:,}"])
    ax.set_axis_off()
    table = ax.table(
        cellText=rows,
        colLabels=["block", "rej.", "acc.", "part."],  # short: they fit a half-width panel
        loc="center",
        cellLoc="center",
        # the last two columns wider: "no test" and "tested" ran into one word (review r100)
        colWidths=[0.25, 0.19, 0.28, 0.28],
    )
    table.auto_set_font_size(False)
    table.set_fontsize(fs(0.8))
    table.scale(1.0, 1.6)
    pixel_header = len(rows) - 1  # the table's row index of the pixels' header (0: columns)
    for (r, c), cell in table.get_celld().items():
        if r == 0 and c:
            cell.set_facecolor(to_rgba(BLOCK_COLORS[KINDS[c - 1]], 0.45))
        if r == pixel_header:
            cell.set_facecolor("0.9")
            if c == 0:  # the header's name bold; its two columns' names in normal weight
                cell.get_text().set_fontweight("bold")
    result = CounterArtists(table)
    if title:
        result.title = ax.set_title("counters per block size", fontsize=fs(0.7))
    return result


@dataclass
class TraversalArtists(Artists):
    """Visit-number colours, the path through the cells and the numbers of a traversal."""

    image: object
    path: Line2D | None = None
    texts: list = field(default_factory=list)


def plot_traversal(
    ax, width: int, height: int, traversal: str = "scanline", *, tile: int = 4,
    numbers: bool | None = None, path: bool = True,
) -> TraversalArtists:  # fmt: skip
    """Colour each cell of a ``height`` × ``width`` grid by when a traversal visits it.

    The path joins the cell centres in visiting order: long jumps are where a walker
    leaves the neighbourhood it just loaded (cache misses); Morton and tiled orders keep
    nearby cells together at every scale.
    """
    check_choice("traversal", traversal, TRAVERSALS)
    cells = traversal_order((height, width), traversal, tile)
    index = np.empty((height, width))
    index[cells[:, 0], cells[:, 1]] = np.arange(len(cells))
    pixel_axes(ax, width, height, ticks=False)
    im = show_image(ax, index, cmap=VALUE_CMAP, vmin=0, vmax=max(len(cells) - 1, 1), zorder=0.5)
    result = TraversalArtists(im)
    if path:
        result.path = ax.plot(cells[:, 1] + 0.5, cells[:, 0] + 0.5, "-", color=COLORS["edge"],
                              lw=lw(0.4), zorder=3)[0]  # fmt: skip
    if numbers if numbers is not None else len(cells) <= 64:
        colors = im.cmap(im.norm(np.arange(len(cells))))
        for n, (r, c) in enumerate(cells):
            ink = "black" if colors[n, :3] @ [0.299, 0.587, 0.114] > 0.5 else "white"
            result.texts.append(ax.text(c + 0.5, r + 0.5, str(n), ha="center", va="center",
                                        fontsize=fs(0.45), color=ink, zorder=4))  # fmt: skip
    ax.set_title(traversal if traversal != "tiled" else f"tiled ({tile}×{tile})")
    return result


#: What :func:`plot_early_z` can count per pixel.
EARLY_Z_KINDS = ("hi_z", "early_z", "shaded", "dropped")


@dataclass
class EarlyZArtists(Artists):
    """The per-pixel count image of a :func:`plot_early_z` and its colour bar."""

    image: object
    colorbar: object | None = None


def early_z_counts(frame, kind: str = "hi_z") -> np.ndarray:
    """(H, W) int: fragments per pixel that a GPU drawing in order would reject by Hi-Z
    (``"hi_z"``), kill by early-z (``"early_z"``) or shade (``"shaded"``), from
    ``frame.trace.hiz``; or that the renderer's own Hi-Z dropped before interpolating their
    depth (``"dropped"``, from ``frame.trace.hiz_tiles``)."""
    check_choice("kind", kind, EARLY_Z_KINDS)
    trace = getattr(frame, "trace", None)
    if trace is None or getattr(trace, "hiz", None) is None:
        raise ValueError("early_z_counts needs tr.render(..., trace=True) with the depth test on")
    if kind == "dropped":
        pick = trace.hiz_tiles.fragment_rejected
    else:
        rejected, passed = trace.hiz.fragment_rejected, trace.hiz.fragment_passed
        pick = {"hi_z": rejected, "early_z": ~passed & ~rejected, "shaded": passed}[kind]
    height, width = frame.triangle_id.shape
    flat = trace.fragment_row[pick] * width + trace.fragment_col[pick]
    return np.bincount(flat, minlength=width * height).reshape(height, width)


def plot_early_z(ax, frame, kind: str = "hi_z", *, colorbar: bool = True) -> EarlyZArtists:
    """Per pixel, how many fragments Hi-Z rejected whole, early-z killed, or were shaded
    (a GPU drawing in order), or the renderer's own Hi-Z dropped (see :func:`early_z_counts`).

    One discrete colour per count; zero is transparent over the covered pixels in light grey.
    The title gives the total.
    """
    counts = early_z_counts(frame, kind)
    height, width = counts.shape
    pixel_axes(ax, width, height, ticks=False)
    # The covered pixels in light grey underneath, so that the scene's outline shows where
    # the counts are zero.
    covered = np.where(np.asarray(frame.coverage, dtype=bool), 1.0, np.nan)
    show_image(
        ax, covered, cmap=ListedColormap([tint(COLORS["grid"], 0.3)]), vmin=0, vmax=1, zorder=0.3
    )
    # Counts are small integers: one discrete colour per count, 0 transparent.
    top = max(int(counts.max()), 1)
    cmap = ListedColormap(mpl.colormaps[VALUE_CMAP](np.linspace(0.25, 1.0, top)))
    norm = BoundaryNorm(np.arange(top + 1) + 0.5, top)
    shown = np.where(counts > 0, counts.astype(float), np.nan)
    im = show_image(ax, shown, cmap=cmap, norm=norm, zorder=0.5)
    result = EarlyZArtists(im)
    if colorbar:
        result.colorbar = ax.figure.colorbar(im, ax=ax, shrink=0.8, label="fragments",
                                             ticks=np.arange(1, top + 1))  # fmt: skip
    name = {
        "hi_z": "rejected by Hi-Z",
        "early_z": "killed by early-z",
        "shaded": "shaded",
        "dropped": "dropped by render's Hi-Z",
    }[kind]
    ax.set_title(f"{int(counts.sum()):,} fragments {name}")
    return result


@dataclass
class BlockPathArtists(Artists):
    """The path of a :func:`plot_block_path` and the numbers on its blocks."""

    path: Line2D
    texts: list = field(default_factory=list)


def plot_block_path(
    ax, fill, traversal: str = "scanline", *, level: int = -1, numbers: bool | None = None
) -> BlockPathArtists:
    """Join the centres of one level's blocks in the order the walk visits them.

    The walk is depth first, so the blocks of a level are visited parent by parent; the
    traversal orders the siblings. ``level`` indexes ``block_sizes`` (default: the smallest).
    """
    _, blocks = tile_trace(fill, "plot_block_path")
    check_choice("traversal", traversal, TRAVERSALS)
    level = range(len(blocks.block_sizes))[level]
    order = blocks.visit_order(traversal)
    order = order[blocks.level[order] == level]
    x = blocks.col[order] + blocks.extent[order, 1] / 2
    y = blocks.row[order] + blocks.extent[order, 0] / 2
    (line,) = ax.plot(x, y, "-", color=COLORS["edge"], lw=lw(0.5), zorder=4)
    result = BlockPathArtists(line)
    if numbers if numbers is not None else len(order) <= 64:
        for n, (u, v) in enumerate(zip(x, y)):
            result.texts.append(ax.text(u, v, str(n), ha="center", va="center",
                                        fontsize=fs(0.45), zorder=5))  # fmt: skip
    size = blocks.block_sizes[level]
    ax.set_title(f"{traversal}: {len(order)} blocks of {size}×{size}")
    return result


@dataclass
class WalkPathArtists(Artists):
    """The steps, jumps and ends of a :func:`plot_walk_path`; ``handles`` and ``labels`` key
    them (one key for several panels)."""

    steps: LineCollection
    jumps: LineCollection
    start: Line2D
    end: Line2D
    blocks: int

    @property
    def handles(self) -> list:
        jump = Line2D([], [], color="black", ls=self.jumps.get_linestyle()[0], lw=1.6)
        return [self.start, self.end, jump]

    labels = ("first block", "last block", "jump: not to a 4-neighbour")


def plot_walk_path(ax, fill, traversal: str = "scanline", *, level: int = -1) -> WalkPathArtists:
    """One level's blocks, coloured by kind, and the walk's path through them, for a projector.

    Steps to a 4-neighbour (the next block left, right, up or down) are solid; every other
    move is a jump, as lesson 10 §5 counts them (a row's end, the last child of one parent to
    the first of the next, a diagonal of Morton's Z), dashed and thinner so that it does not
    hide the blocks it crosses: the dashes can be counted against the printed jumps. A ringed
    star marks the first block (not a dot: the triangle's vertices are dots), a square the last. ``level`` indexes ``block_sizes`` (default:
    the smallest).
    """
    _, blocks = tile_trace(fill, "plot_walk_path")
    level = range(len(blocks.block_sizes))[level]
    size = blocks.block_sizes[level]
    plot_pixel_grid(ax, *fill.coverage.shape[::-1], ticks=False)
    plot_blocks(ax, fill, level=level, traversal=traversal, legend=False)
    path = plot_block_path(ax, fill, traversal, level=level, numbers=False)
    px, py = path.path.get_data()
    path.path.set_visible(False)  # redrawn below: steps and jumps apart
    segments = np.c_[px[:-1], py[:-1], px[1:], py[1:]].reshape(-1, 2, 2)
    jump = np.hypot(np.diff(px), np.diff(py)) > size + 1e-9  # not to a 4-neighbour
    lines = [
        LineCollection(segments[kind], colors="black", linestyles=ls, linewidths=width,
                       alpha=alpha, zorder=4)
        for kind, ls, width, alpha in ((~jump, "-", 2.6, 1.0), (jump, (0, (2.5, 1.5)), 1.8, 0.9))
    ]  # fmt: skip
    for line in lines:
        ax.add_collection(line)
    # a yellow star, ringed in black: a black dot was the triangle's vertex dots, and
    # the first block lies at a vertex (review r281 FIG1, lesson 10)
    start = ax.plot(px[0], py[0], "*", ms=22, mfc=OKABE_ITO["yellow"], mec="black", mew=1.5,
                    zorder=6)[0]  # fmt: skip
    end = ax.plot(px[-1], py[-1], "s", ms=11, mfc="white", mec="black", mew=2, zorder=6)[0]
    ax.set_title(traversal)
    return WalkPathArtists(*lines, start, end, len(px))


def plot_early_z_panels(axes, frame, kinds=("hi_z", "early_z", "shaded"), *, grid: bool = True):
    """One :func:`plot_early_z` panel per kind, zoomed on the covered pixels, with one key.

    Each panel says what it counts; the key says what a colour means in plain words. With
    ``grid`` the Hi-Z panel draws the GPU's tiles (``frame.trace.hiz.tile`` pixels a side),
    faintly, so that a block rejected whole shows as whole tiles. Returns the key (a figure
    legend below the panels).
    """
    rows, cols = np.nonzero(frame.coverage)
    tile = frame.trace.hiz.tile
    for kind, ax in zip(kinds, axes):
        art = plot_early_z(ax, frame, kind, colorbar=False)
        ax.set(xlim=(cols.min() - 4, cols.max() + 5), ylim=(rows.max() + 5, rows.min() - 4))
        total, what = ax.get_title().split(" fragments ", 1)
        ax.set_title(f"{what}:\n{total} fragments", fontsize=14)
        if grid and kind == "hi_z":  # the tiles Hi-Z keeps one farthest depth for
            height, width = frame.coverage.shape
            segs = [[(x, 0), (x, height)] for x in range(0, width + 1, tile)]
            segs += [[(0, y), (width, y)] for y in range(0, height + 1, tile)]
            ax.add_collection(LineCollection(segs, colors="0.35", linewidths=0.7, zorder=0.8))
    one, two = (art.image.cmap(art.image.norm(v)) for v in (1, 2))
    handles = [
        Patch(color=one, label="1 fragment in the pixel, of the kind its panel's title names"),
        Patch(color=two, label="2 fragments in the pixel, both shaded (right panel only)"),
        Patch(color=tint(COLORS["grid"], 0.3), label="covered: no fragment of that kind"),
    ]
    if grid:
        handles.append(
            Line2D(
                [],
                [],
                color="0.35",
                lw=0.7,
                label=f"left: the {tile}×{tile} tiles Hi-Z tests a triangle in",
            )
        )
    return axes[0].figure.legend(handles=handles, loc="outside lower center", ncols=1,
                                 fontsize=13)  # fmt: skip


#: How :func:`plot_llvmpipe_bins` draws each tile kind of llvmpipe's binner
#: (:func:`teachraster.study.llvmpipe_binner.bin_rows`): (face colour, hatch, key entry). The
#: two outside kinds apart, and the tiles no test reached white and dotted: the walk's grey
#: "rejected" hid which tiles llvmpipe tests at all (review r235 FIG2).
BIN_STYLE = {
    "full": (BLOCK_COLORS["accepted"], None, "whole tile: shade-tile command, no pixel test"),
    "partial": (BLOCK_COLORS["partial"], None, "edges cross: triangle command"),
    "empty": (BLOCK_COLORS["rejected"], None, "tested, outside an edge (nr_empty_64)"),
    "exit": ("#8C8C8C", None, "tested, outside an edge: ends its row"),
    "untested": ("white", "..", "never tested: its row had ended"),
}
#: The key's name for a tile :func:`plot_llvmpipe_bins` outlines (``marked``).
BIN_MARKED = "binned by llvmpipe, rejected by this lesson's walk"


@dataclass
class BinArtists(Artists):
    """The tiles of a :func:`plot_llvmpipe_bins`, the outlines of its marked ones, and the
    key's ``handles`` (one per kind drawn, then the outline's)."""

    tiles: list = field(default_factory=list)
    marks: list = field(default_factory=list)
    handles: list = field(default_factory=list)


def plot_llvmpipe_bins(ax, kinds, *, tile: int = 64, marked=()) -> BinArtists:
    """llvmpipe's binning pass over the tiles of a box: each tile by what the binner did with
    it (:data:`BIN_STYLE`), and the tiles ``marked`` (row, col) outlined in the course's
    current-step colour (:data:`BIN_MARKED`).

    ``kinds`` is the (rows, cols) array of :func:`~teachraster.study.llvmpipe_binner.bin_rows`;
    tile (r, c) covers pixels ``r·tile ...`` and ``c·tile ...`` (the box from pixel (0, 0)).
    Draw the pixel grid and the triangle around it; the key is the caller's (``handles``).
    """
    kinds = np.asarray(kinds, dtype=object)
    unknown = set(kinds.ravel()) - set(BIN_STYLE)
    if unknown:
        raise ValueError(f"kinds: unknown tile kinds {sorted(unknown)}; known: {list(BIN_STYLE)}")
    result = BinArtists()
    for (r, c), kind in np.ndenumerate(kinds):
        face, hatch, _ = BIN_STYLE[kind]
        rect = Rectangle((c * tile, r * tile), tile, tile, facecolor=face, edgecolor="white",
                         lw=lw(0.6), hatch=hatch, zorder=2.5)  # fmt: skip
        if hatch:
            rect.set_hatchcolor(COLORS["grid"])
        result.tiles.append(ax.add_patch(rect))
    inset = tile / 20  # inside the tile: on the image's border the frame hid half the line
    for r, c in marked:  # over the tiles and the triangle's edges, with a white halo
        x0, y0 = c * tile + inset, r * tile + inset
        x1, y1 = x0 + tile - 2 * inset, y0 + tile - 2 * inset
        (mark,) = ax.plot([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0], color=COLORS["current"],
                          zorder=5)  # fmt: skip
        _outline_width(mark, lw(1.2))
        result.marks.append(mark)
    for kind in (k for k in BIN_STYLE if (kinds == k).any()):
        face, hatch, label = BIN_STYLE[kind]
        key = Patch(facecolor=face, edgecolor=COLORS["grid"], hatch=hatch, label=label)
        if hatch:
            key.set_hatchcolor(COLORS["grid"])
        result.handles.append(key)
    if result.marks:
        result.handles.append(Line2D([], [], color=COLORS["current"], lw=lw(1.2),
                                     label=BIN_MARKED))  # fmt: skip
    return result


def zoom_on_block(ax, row: int, col: int, size: int = 16, *, every: int = 4) -> None:
    """Zoom ``ax`` (a pixel picture) on the ``size`` × ``size`` block at pixel (row, col).

    Each pixel is outlined thinly in white above the blocks (a 1×1 block is a pixel, and
    64 pixels across a panel were too small to tell apart on a projector); ticks every
    ``every`` pixels sit on pixel centres, as in the other panels.
    """
    ax.set(xlim=(col, col + size), ylim=(row + size, row))
    ticks = np.arange(0, size, every)
    ax.set_xticks(col + ticks + 0.5, labels=[str(col + k) for k in ticks])
    ax.set_yticks(row + ticks + 0.5, labels=[str(row + k) for k in ticks])
    for k in range(size + 1):  # above the blocks (zorder 2.5)
        ax.axvline(col + k, color="white", lw=1.0, zorder=4)
        ax.axhline(row + k, color="white", lw=1.0, zorder=4)


@dataclass
class BlockValueArtists(Artists):
    """Artists of :func:`plot_block_values`: the values' colours and numbers, the two extreme
    corners' outlines and labels, and the two step arrows."""

    image: object
    texts: list = field(default_factory=list)
    corners: list = field(default_factory=list)
    labels: list = field(default_factory=list)
    arrows: list = field(default_factory=list)


#: The two extreme corners of :func:`plot_block_values`: (which, colour, what its test decides).
CORNER_MARKS = (
    ("largest", COLORS["outside"], "reject test"),
    ("smallest", BLOCK_COLORS["accepted"], "accept test"),
)


def plot_block_values(ax, values, row0: int, col0: int, *, name: str = "E12",
                      steps=None, numbers: str = "all", cmap=VALUE_CMAP,
                      norm=None) -> BlockValueArtists:  # fmt: skip
    """One edge's values at the pixel centres of a block, with its extreme corners marked:
    the corner trick of lesson 10 §1 as a picture (after Abrash's *Rasterization on
    Larrabee*, which draws a block's trivial-reject and trivial-accept corners).

    ``values[i, j]`` is the value at pixel (``row0 + i``, ``col0 + j``). The largest value is
    outlined in the "outside" colour (if even it is negative, no centre is inside: the block
    is rejected), the smallest in the accepted blocks' colour (if even it passes, every centre
    does). ``steps = (right, down)``, the value added by one step right and one step down,
    draws the two steps as arrows along the block's top and left sides, whose signs pick the
    two corners. ``numbers="corners"`` writes only the four corners' values, large enough
    for a projector (64 values of four digits fit a cell only in small print; the colours
    still show the rest): the two extremes' in their labels, the other two in their cells.
    ``cmap`` and ``norm``: a panel beside :func:`plot_edge_values` passes its image's, so that
    a colour means the same value in both (review r281 FIG2, lesson 10).
    """
    if numbers not in ("all", "corners"):
        raise ValueError(f"numbers must be 'all' or 'corners', got {numbers!r}")
    values = np.asarray(values, dtype=float)
    h, w = values.shape
    corners_only = numbers == "corners"
    im = ax.pcolormesh(np.arange(col0, col0 + w + 1), np.arange(row0, row0 + h + 1), values,
                       cmap=cmap, norm=norm, shading="flat", edgecolors="white",
                       lw=0.5)  # fmt: skip
    result = BlockValueArtists(im)
    norm = im.norm
    extremes = {values.argmax(), values.argmin()}  # flat indices: their labels say them
    for (i, j), v in np.ndenumerate(values):
        if corners_only and (i not in (0, h - 1) or j not in (0, w - 1)
                             or i * w + j in extremes):  # fmt: skip
            continue
        shade = np.asarray(im.cmap(norm(v))[:3]) @ [0.299, 0.587, 0.114]
        # a corner's value is wider than its cell: it reaches inwards, over unlabelled cells
        ha = "center" if not corners_only else "left" if j == 0 else "right"
        x = col0 + j + (0.5 if not corners_only else 0.1 if j == 0 else 0.9)
        result.texts.append(ax.text(x, row0 + i + 0.5, f"{v:.0f}", ha=ha, va="center",
                                    fontsize=fs(0.7 if corners_only else 0.45),
                                    fontweight="bold" if corners_only else "normal",
                                    color="black" if shade > 0.5 else "white"))  # fmt: skip
    # room above and left for the step arrows, below for the largest corner's label
    ax.set(xlim=(col0 - 1.6, col0 + w + 0.1), ylim=(row0 + h + 1.1, row0 - 1.7))
    ax.set_aspect("equal")
    ax.set_xticks(col0 + np.arange(w) + 0.5, labels=[str(col0 + j) for j in range(w)])
    ax.set_yticks(row0 + np.arange(h) + 0.5, labels=[str(row0 + i) for i in range(h)])
    ax.tick_params(labelsize=fs(0.7 if corners_only else 0.55), length=0)
    ax.yaxis.tick_right()  # the left side holds the step down
    ax.yaxis.set_label_position("right")
    ax.set(xlabel="column j", ylabel="row i")
    for spine in ax.spines.values():
        spine.set_visible(False)
    places = {"largest": np.unravel_index(values.argmax(), values.shape),
              "smallest": np.unravel_index(values.argmin(), values.shape)}  # fmt: skip
    for which, color, test in CORNER_MARKS:
        i, j = (int(k) for k in places[which])
        box = Rectangle((col0 + j, row0 + i), 1, 1, fill=False, ec=color, lw=lw(1.3), zorder=5)
        ax.add_patch(box)
        result.corners.append(box)
        below = i == h - 1  # a label under a bottom corner, above a top one
        y = row0 + h + 0.25 if below else row0 - 0.25
        said = f" = {values[i, j]:.0f}" if corners_only else ""  # its value, in its label
        result.labels.append(ax.text(col0 + j + 0.5, y, f"{which} {name}{said}: {test}",
                                     ha="left" if j < w / 2 else "right", color=color,
                                     va="top" if below else "bottom", fontsize=fs(0.8),
                                     fontweight="bold"))  # fmt: skip
    if steps is not None:
        right, down = steps
        for (x0, y0, x1, y1), text, rot in (
            ((col0, row0 - 1.2, col0 + 2.2, row0 - 1.2), f"one step right: {right:+.1f}", 0),
            ((col0 - 1.2, row0, col0 - 1.2, row0 + 2.2), f"one step down: {down:+.1f}", -90),
        ):
            arrow = ax.annotate("", (x1, y1), (x0, y0), arrowprops={
                "arrowstyle": "-|>", "color": COLORS["edge"], "lw": lw(0.6)})  # fmt: skip
            result.arrows.append(arrow)
            tx, ty = (x1 + 0.2, y1) if rot == 0 else (x1, y1 + 0.2)
            result.labels.append(ax.text(tx, ty, text, ha="left", va="center", rotation=rot,
                                         rotation_mode="anchor", fontsize=fs(0.8)))  # fmt: skip
    return result
