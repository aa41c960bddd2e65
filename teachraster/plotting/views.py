"""Composite figures that update in place: stepping through a fill, comparing interpolations.

The views draw their artists once. Afterwards :meth:`FillView.show_step`,
:meth:`FillView.set_fill`, :meth:`ComparisonView.update` and :meth:`InterpolationView.update`
only change those artists' data (``set_data``, ``set_xy``, ``set_text``, ``set_visible``),
never clear the Axes or add artists, then ask the canvas for a redraw with ``draw_idle``. That
keeps a step or a vertex drag fast enough for a slider in a notebook, and lets widgets drive
the views from code. For the fastest steps, :meth:`FillView.redraw` renders the canvas by
blitting (:mod:`teachraster.plotting.blitting`): a cached background and still layers, with
only the moving artists drawn again.

The figures use fixed margins rather than a layout engine: a layout engine would run again at
every redraw.
"""

from __future__ import annotations

import textwrap

import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import Normalize, to_rgba, to_rgba_array
from matplotlib.patches import Rectangle
from matplotlib.path import Path
from matplotlib.patheffects import withStroke
from matplotlib.transforms import Affine2D, ScaledTranslation

from ..core.trace import FillTrace, Step
from .antialiasing import BOLD_STYLE, TRIANGLE_COLORS
from .blitting import MOVING, STILL, LayeredBlit
from .common import (
    Artists,
    as_trace,
    fs,
    image_shape,
    quiet_nanmax,
    set_image,
    show_image,
    two_colour,
)
from .images import ImageArtists, attribute_image, plot_error_heatmap, plot_profile, show_values
from .plots import (
    TriangleArtists,
    plot_bbox,
    plot_coverage,
    plot_current_pixel,
    plot_pixel_centres,
    plot_pixel_grid,
    plot_raster_line,
    plot_split,
    plot_triangle,
)
from .setup_marks import TURN_COLOR, plot_setup_marks
from .style import COLORS, VALUE_CMAP

#: Outline colours of classified blocks (tiles), by ``TileTrace.kind_code``: rejected (a grey
#: darker than the pixel grid's), accepted, partial.
BLOCK_COLORS = (COLORS["centre"], COLORS["flat_bottom"], COLORS["bbox"])

METHOD_NAMES = {"span": "Span tables", "halfplane": "Half-planes", "tiled": "Tiles"}


def first_channel(values) -> np.ndarray:
    """(n,) values of an attribute recorded as (n,) or (n, k): channel 0 of a vector."""
    values = np.asarray(values, dtype=np.float64)
    return values.reshape(len(values), -1)[:, 0]


def _new_figure(figsize, rect):
    """A pyplot figure (so notebooks display it) with one Axes at ``rect``, no layout engine."""
    import matplotlib.pyplot as plt  # pyplot only when a view makes its own figure

    fig = plt.figure(figsize=figsize)
    return fig, fig.add_axes(rect)


#: The key's entry for the pixel a half-plane step tests (shown only at such a step: at the
#: last step nothing is under test, review r8 lesson 04 c15).
PIXEL_UNDER_TEST = "pixel under test, × centre"
#: The key's entry for the pixels a multisampled fill shades for a covered sample alone.
SAMPLE_ONLY = "centre out, a sample in"


def sample_only_face(coloured: bool):
    """The face of a pixel shaded for a covered sample alone: none over the values' colours
    (its outline marks it), else a pale shade of the covered blue, its own (the box's cream
    means "not tested yet"). One rule for the picture and its key.

    >>> sample_only_face(True)
    'none'
    """
    return "none" if coloured else to_rgba(COLORS["fill"], 0.4)


def _dashed_square() -> Path:
    """A square marker drawn in dashes, for the key's bounding box: the picture draws the box
    dashed (:func:`~teachraster.plotting.plot_bbox`), and a solid orange square named it and
    the tiles' partial blocks alike (review r115 00-A)."""
    pieces = [(-1.0, -0.5), (-0.17, 0.17), (0.5, 1.0)]  # along each side: corners and middle
    verts = []
    for a, b in pieces:
        verts += [(a, -1), (b, -1), (a, 1), (b, 1), (-1, a), (-1, b), (1, a), (1, b)]
    codes = [Path.MOVETO, Path.LINETO] * (len(verts) // 2)
    return Path(verts, codes)


#: The key's marker for the bounding box: a dashed square (not filled).
DASHED_SQUARE = _dashed_square()


def sample_test_steps(trace: FillTrace) -> np.ndarray | None:
    """(height, width) int: the step that tests each pixel's samples, as the trace tells it
    for the pixel centres: the raster line through the pixel (span tables; the samples of a
    row's pixels lie about its centre line) or the visit of the pixel (half-planes, tiles),
    the nearest pixel of the bounding box for a pixel outside it. None for a culled fill.
    """
    b, last = trace.bbox, trace.interpolation_step
    if trace.culled or b.row1 <= b.row0 or b.col1 <= b.col0:
        return None
    if trace.span is not None:  # every pixel of a raster line, covered or not
        line = trace.first_work_step + np.arange(b.row1 - b.row0)
        local = np.broadcast_to(line[:, None], (b.row1 - b.row0, b.col1 - b.col0))
    else:
        local = trace.visit_step
    rows = np.clip(np.arange(trace.height) - b.row0, 0, b.row1 - b.row0 - 1)
    cols = np.clip(np.arange(trace.width) - b.col0, 0, b.col1 - b.col0 - 1)
    steps = np.array(local[np.ix_(rows, cols)])
    steps[steps < 0] = last
    return steps


#: The key's line for the roles the sort gives (drawn beside the vertex labels from the sort
#: step to the split): a word in the roles' colour, as the picture writes them.
ROLES_ENTRY = ("role after the sort", COLORS["split"], COLORS["split"], r"$\mathit{top}$")


def walk_entry(trace: FillTrace) -> tuple:
    """The key's line for the edges' arrowheads: the walk the winding step chose, the
    trace's edges in their order (v1→v3→v2 for a triangle given counter-clockwise on
    screen, review r239 01-C1); for span tables, which walk nothing, the way the loop runs
    down each edge (:func:`drawn_edges`)."""
    if trace.span is not None:
        return ("each edge, top to bottom", COLORS["edge"], COLORS["edge"], r"$\rightarrow$")
    walk = "→".join(f"v{int(a) + 1}" for a, _ in trace.edges)
    return (f"edges walked {walk}", COLORS["edge"], COLORS["edge"], r"$\rightarrow$")


def drawn_edges(trace: FillTrace) -> np.ndarray:
    """(3, 2) int: the edges as the arrowheads point. Span tables run down every edge, the
    long one and the short one of each part, top to bottom: the arrows a walk round the
    triangle drew (v1→v3→v2, clockwise on screen) read as its winding, which the text calls
    counter-clockwise (review r344 01-C1). The other methods: the walk the winding step
    chose (``trace.edges``), whose edge functions they test."""
    s = trace.span
    if s is None:
        return trace.edges
    top, mid, bot = (int(i) for i in s.order)
    return np.array([[top, bot], [top, mid], [mid, bot]])


def _snap_entries(trace: FillTrace) -> list:
    """The key's lines for the snap's step: each vertex tagged with its snapped position
    (:func:`~teachraster.plotting.setup_marks.plot_setup_marks`), and how far the snap moved
    the farthest one (none: a vertex already on the grid, as on pixel centres)."""
    c = COLORS
    bits = trace.subpixel_bits
    if bits is None:
        return [("vertex (its position)", c["edge"], c["edge"], "o"),
                ("raw floats: no snapping", "none", "none")]  # fmt: skip
    moved = float(np.hypot(*(np.asarray(trace.xy, float) - trace.snapped).T).max())
    # each line as long as the key's column allows (about 24 characters)
    by = "the snap moved none" if moved == 0 else f"moved by ≤ {moved:.2g} px"
    # one sentence over three lines: "vertex (its position on the 1/256 px grid): the snap
    # moved none" (review r302 02-9: "vertex, (its position) on the ... grid" read garbled)
    return [("vertex (its position", c["edge"], c["edge"], "o"),
            (f"on the 1/{2**bits} px grid):", "none", "none"),
            (by, "none", "none")]  # fmt: skip


def _split_entries() -> list:
    """The key's lines for what :func:`~teachraster.plotting.plot_split` draws: the two parts'
    tints, then the split line and point 4 (named without x, y, u or v: the captions write y
    where lesson 01 writes v, review r229 01-S2)."""
    c = COLORS
    return [("flat-bottom part", to_rgba(c["flat_bottom"], 0.5), c["flat_bottom"]),
            ("flat-top part", to_rgba(c["flat_top"], 0.6), c["flat_top"]),
            ("split line, point 4", c["split"], "white", "D")]  # fmt: skip


def _arrow_off_point_4(triangle: TriangleArtists, trace: FillTrace) -> None:
    """Span tables: move the long edge's arrow from the middle of the edge, where point 4 often
    lies (exactly, when the middle vertex is halfway down), to its lower part: the arrowhead
    sat on point 4 and its "4" (review r229 01-FIG1). (In its upper part it sat on lesson
    01's row 5, whose span ends the text reads off the picture.)"""
    s = trace.span
    if s is None or s.u4 is None or not triangle.arrows:
        return
    xy = np.asarray(trace.snapped, dtype=np.float64)
    long_edge = {int(s.order[0]), int(s.order[2])}
    for arrow, (a, b) in zip(triangle.arrows, drawn_edges(trace)):
        if {int(a), int(b)} != long_edge:
            continue
        pa, pb = xy[a], xy[b]
        t0, t1 = (0.7, 0.84) if a == s.order[0] else (0.16, 0.3)  # near the bottom vertex
        arrow.set_positions(tuple(pa + t0 * (pb - pa)), tuple(pa + t1 * (pb - pa)))


class FillView:
    """Step through one fill: a figure whose artists each step updates in place.

    It shows the pixel grid and centres, the triangle (edges in test order, with arrows from
    the step after the winding on, which chooses that order, and the edge-function names used
    in the captions), the bounding box, the pixels filled so far,
    for half-planes the pixels tested and rejected so far, the current raster line (span
    tables) or pixel (half-planes), the split at u4 (span tables), a header and the caption of
    the current step. The bounding box appears from its set-up step on and the split from the
    split step on, as the algorithm finds them.

    Parameters
    ----------
    fill : Fill (rasterised with ``trace=True``) or FillTrace
    ax : matplotlib Axes, optional
        Draw into this Axes (the caption goes just below it). Default: a new figure.
    step : int, optional
        Step to show first; default the last one (the finished fill).
    legend : bool
        A legend of the colours, to the right of the grid.
    centres : bool
        Mark the pixel centres (where coverage is decided).
    caption : bool
        Write the caption below the Axes (a widget may show it itself instead).
    step_header : bool
        Header "Half-planes: step k of n (kind)"; False: just the method, and a widget shows
        the step (the header is then still, which makes a blitted step cheaper by half).
    values : bool
        At the last step (``interpolate``) colour the covered pixels by the interpolated
        attribute, as its caption says (read from the trace: the values it records as
        written); off, the finished fill keeps its coverage colour.
    attribute : str, optional
        The attribute ``values`` shows (channel 0 of a vector); default the first.
    sample_key : bool
        The key names the sample dots of a multisampled fill, which the caller draws
        (:func:`~teachraster.plotting.plot_samples`, as FillPlayer does).

    A step asks the trace for :meth:`~teachraster.core.trace.FillTrace.step` once and hands
    the Step to the artists; which pixels are filled or rejected, and from which step on
    the bounding box and the split show, come from the trace's accessors too.
    :meth:`redraw` renders a step by blitting (only what moves is drawn again).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import teachraster as tr
    >>> fill = tr.rasterize(tr.Triangle([[1, 1], [7, 2], [3, 7]]), 8, 8, trace=True)
    >>> view = FillView(fill, step=0)
    >>> view.show_step(5).kind
    'pixel'
    >>> bool((view.coverage.image.get_array() == fill.trace.coverage_at(5)).all())
    True
    >>> import matplotlib.pyplot as plt; plt.close(view.fig)
    """

    def __init__(self, fill, *, ax=None, step: int | None = None, legend: bool = True,
                 centres: bool = True, caption: bool = True, step_header: bool = True,
                 values: bool = False, attribute: str | None = None,
                 sample_key: bool = False) -> None:  # fmt: skip
        trace = as_trace(fill, "FillView")
        if ax is None:
            # room on the right for the legend and below for a three-line caption
            ax = _new_figure((12.0, 9.5), (0.07, 0.13, 0.62, 0.745))[1]
        self.fig, self.ax = ax.figure, ax
        W, H = trace.width, trace.height
        self.grid = plot_pixel_grid(ax, W, H, ticks=5)  # few labels: each costs a step time
        zeros = np.zeros((H, W))
        # Pixels tested and rejected so far (half-planes): the work span tables avoid.
        self.rejected = show_image(ax, zeros, cmap=two_colour(COLORS["rejected"]), vmin=0,
                                   vmax=1, zorder=0.45)  # fmt: skip
        self.coverage = plot_coverage(ax, zeros)
        # The last step's picture: the covered pixels coloured by the interpolated attribute
        # (review r9/r10, lesson 04 c15: the caption spoke of u over plain coverage).
        self.values = show_image(ax, zeros, cmap=VALUE_CMAP, vmin=0, vmax=1, zorder=0.55)
        self.values.set_visible(False)
        # at that step, with several samples, the pixels shaded only because a sample is
        # covered (their centre is not): outlined, so that the caption's "72 with a covered
        # sample (59 with their centre covered; 13 ...)" shows (review r23, lesson 00 c14);
        # with no values to colour them, filled with a shade of their own as well (review
        # r169 02-3: drawn in the box's cream, they read as "not tested yet")
        self.sample_only = ax.add_collection(PolyCollection(
            [], facecolors="none", edgecolors=COLORS["outside"], linewidths=fs(0.17),
            zorder=3.5))  # fmt: skip
        self.sample_only.set_visible(False)
        # tiles: the outline of every block classified so far, coloured by its verdict, so that
        # the walk over the grid of blocks stays visible once passed (review r77 00-2)
        self.block_outlines = ax.add_collection(PolyCollection(
            [], facecolors="none", linewidths=fs(0.14), zorder=3.4))  # fmt: skip
        self.block_outlines.set_visible(False)
        self._values = (values, attribute)  # asked for; _shown: (name, lo, hi) or None
        self._shown = None
        self._sample_key = sample_key
        self.bbox = plot_bbox(ax, trace)
        self.split = plot_split(ax, trace)
        self.centres = plot_pixel_centres(ax, W, H) if centres else None
        # inside: the key sits beside the Axes
        self.triangle = plot_triangle(
            ax, trace, edges=drawn_edges(trace), edge_labels=True, inside=True
        )
        if centres:  # the edge names between the centre dots, not over them (review r291 02-3)
            u, v = np.meshgrid(np.arange(W) + 0.5, np.arange(H) + 0.5)
            self.triangle.keep_clear = np.column_stack([u.ravel(), v.ravel()])
        # the vertex names without their white boxes, a white halo round the letters instead:
        # v1's box blanked row 1's centre dots, in a lesson about which centres are covered
        # (review r33, lesson 00). The vertex dots stay above (6.2), as in plot_triangle.
        for label in self.triangle.labels:
            label.set_bbox(None)
            label.set_path_effects([withStroke(linewidth=max(2.5, fs(0.22)), foreground="white")])
        self.raster_line = plot_raster_line(ax, trace, 0)
        self.pixel = plot_current_pixel(ax, trace, 0)
        # what the set-up steps find: the winding, the raster lines, the roles (review r229
        # 01-W1: steps 0-3 of a span fill drew one picture, only their captions differed)
        self.setup_marks = plot_setup_marks(ax, trace, self.triangle.labels)
        # the edge names and the snapped positions haloed, not boxed, as the vertex names: a
        # box reached over the centre dots beside it (review r291 02-3)
        halo = max(2.5, fs(0.22))
        self.triangle.edge_halo = halo  # kept off the centre dots too
        for label in [*self.triangle.edge_labels, *self.setup_marks.coords]:
            label.set_bbox(None)
            label.set_path_effects([withStroke(linewidth=halo, foreground="white")])
        # An explicit title position: automatic placement (above the top ticks) costs time
        # at every draw.
        self.header = ax.set_title("", y=1.0, pad=fs(3.2), loc="left")
        # Wrapped by hand (textwrap, width from the figure): matplotlib's wrap=True measures
        # every word at every draw, which costs more than the rest of a step.
        self.caption_text = ax.text(0.0, -0.03, "", transform=ax.transAxes, va="top",
                                    ha="left", fontsize=fs(0.85), linespacing=1.3)  # fmt: skip
        # A widget may show the caption itself (in full, selectable) instead.
        self.caption_text.set_visible(caption)
        self._step_header = step_header
        self._caption = ""
        # eleven lines: span tables with samples list the split and three sample dots (r22, r33)
        self.legend = Key(ax, 11) if legend else None
        # the last step's colours as a short colour bar in the key (values asked for)
        self.value_bar = ValueBar(self.legend) if legend and values else None
        self.sample_dots = None  # drawn by the caller: show_samples
        self._sample_steps = None  # (trace, sample_test_steps(trace)), made when needed
        self._trace: FillTrace | None = None
        self._step = -1
        self._keyed = None  # (testing, coloured, split) the key lists, see _key_entries
        self._extra = None  # the pixels shaded for a sample alone (_mark_sample_only)
        self.set_fill(fill, step=step, draw=False)

    # -- state -----------------------------------------------------------------------------
    @property
    def trace(self) -> FillTrace:
        """The trace of the fill on show."""
        return self._trace

    @property
    def n_steps(self) -> int:
        """Number of steps of the current fill (a slider runs from 0 to ``n_steps - 1``)."""
        return len(self._trace)

    @property
    def step(self) -> int:
        """Index of the step on show."""
        return self._step

    @property
    def caption(self) -> str:
        """Caption of the step on show, as ``trace.caption(step)`` (displayed wrapped)."""
        return self._caption

    def _wrap(self, text: str) -> str:
        """``text`` broken into lines that fit between the Axes' left edge and the figure's."""
        fig_w = self.fig.get_figwidth() * 72.0  # points
        x0 = self.ax.get_position().x0
        # DejaVu Sans averages about 0.55 em per character of running text
        chars = int((1.0 - x0) * fig_w * 0.95 / (0.55 * self.caption_text.get_fontsize()))
        return textwrap.fill(text, max(chars, 20), break_on_hyphens=False,
                             break_long_words=False)  # fmt: skip

    @property
    def artists(self) -> list:
        """Every artist the view created (for tests and custom styling)."""
        parts = [self.grid, self.coverage, self.bbox, self.split, self.centres, self.triangle,
                 self.raster_line, self.pixel, self.setup_marks, self.legend,
                 self.value_bar]  # fmt: skip
        out = [a for p in parts if isinstance(p, Artists) for a in p.artists]
        return out + [self.rejected, self.values, self.sample_only, self.block_outlines,
                      self.header, self.caption_text]  # fmt: skip

    @property
    def _sample_only_n(self) -> int:
        """How many pixels the last step shades for a covered sample alone (outlined)."""
        return len(self.sample_only.get_paths())

    # -- updates ---------------------------------------------------------------------------
    def show_step(self, k: int, *, draw: bool = True) -> Step:
        """Show the fill after steps 0..k, updating the existing artists in place.

        Parameters
        ----------
        k : int
            Step index; negative counts from the end. Out of range raises IndexError.
        draw : bool
            Ask the canvas to redraw (``draw_idle``) afterwards.

        Returns
        -------
        Step
            The step now on show (its ``caption`` is the caption displayed).
        """
        trace = self._trace
        step = trace.step(k)  # the one resolve of this tick: artists get the Step
        k = self._step = step.index
        self.coverage.image = set_image(self.coverage.image, trace.coverage_at(k).astype(float))
        # half-planes reject pixel by pixel, tiles whole blocks too (review r22: a rejected
        # block left no mark once passed)
        if trace.halfplane is not None or trace.blocks is not None:
            rejected = trace.rejected_at(k)
            self.rejected = set_image(self.rejected, rejected.astype(float))
            # nothing rejected yet: skip drawing the layer at all
            self.rejected.set_visible(bool(rejected.any()))
        self._show_blocks(trace, k)
        boxed = k >= trace.bbox_step
        # span tables test no box of pixels (Ek §1.1: the sort gives the rows, each span its
        # columns): the box is drawn for the methods that test it
        self.bbox.outline.set_visible(boxed and trace.span is None)
        # the pixels of the box are work only for half-planes, which test every one of them
        self.bbox.cells.set_visible(boxed and trace.halfplane is not None)
        split = trace.split_step is not None and k >= trace.split_step
        if split:
            self.split.update(trace)  # shows the parts that exist
        else:
            self.split.set_visible(False)
        # a pixel (half-planes) or a block (tiles) under test: outlined in the current colour
        testing = step.kind in ("pixel", "block")
        last = step.kind == "interpolate"
        coloured = last and self._shown is not None
        self.values.set_visible(coloured)
        self.sample_only.set_visible(last and self._sample_only_n > 0)
        self.sample_only.set_facecolor(sample_only_face(coloured))
        if coloured:  # the parts' tints would read as values (the flat-top yellow: a high u)
            self.split.flat_bottom.set_visible(False)
            self.split.flat_top.set_visible(False)
            # and "u4 = 3.15" (screen x) beside the key's u (the attribute): two meanings of
            # u in one picture (review r11, lesson 00 c14)
            self.split.label.set_visible(False)
        tested = self._show_tested(k)
        if self.sample_dots is not None:  # rings: the colours show through (review r11)
            self.sample_dots.set_rings(coloured)
        if self.value_bar is not None:
            self.value_bar.set_visible(coloured)
        # the key and the split's tints are background: each state has its own cache (the
        # sample dots too: with bold dots, as many as there are pixels tested)
        setup = k < trace.first_work_step
        # (the key lists less before the first fill step, review r58: a state of its own;
        # each set-up step keys what it draws, review r229 01-W1)
        self._still = (boxed, split, testing, coloured, tested,
                       step.kind if setup and self.legend is not None else False, last)  # fmt: skip
        # the edges' arrowheads show the walk the winding step chooses (trace.edges: a
        # counter-clockwise triangle is walked the other way round): none before it, and
        # none at it, where they turned against its arc labelled v1→v2→v3 (review r239 01-C1).
        # Span tables: each edge top to bottom, from the sort on, which finds the top
        if trace.span is not None:
            walked = k >= trace.sort_step
        else:
            walked = k > trace.setup_kinds.index("winding")
        for arrow in self.triangle.arrows:
            arrow.set_visible(walked)
        self._still += (walked,)
        self.raster_line.update(step)
        self.pixel.update(step)
        # the roles while the set-up speaks of them (sort, split); the row steps name parts
        roles = setup and trace.sort_step is not None and k >= trace.sort_step
        self.setup_marks.show(step.kind if setup else None, roles)
        kind = step.kind if setup else None  # each set-up step draws its own marks and key
        keyed = (testing, coloured, split, boxed, kind, last, roles, walked)
        if self.legend is not None and keyed != self._keyed:
            entries = self._key_entries(trace, testing, coloured, split, boxed=boxed,
                                        setup=kind, last=last, roles=roles)  # fmt: skip
            self.legend.set_entries(entries)
            self._keyed = keyed
        method = METHOD_NAMES.get(trace.method, trace.method)
        if self._step_header:
            # the steps are numbered from 0: "of 0-22" rather than "of 22", which reads as a count
            self.header.set_text(f"{method}: step {k} of 0–{len(trace) - 1} ({trace.phase(step)})")
        else:
            self.header.set_text(method)
        self._caption = step.caption
        if self.caption_text.get_visible():
            self.caption_text.set_text(self._wrap(step.caption))
        if draw:
            self.fig.canvas.draw_idle()
        return step

    def _show_blocks(self, trace: FillTrace, k: int) -> None:
        """Tiles: outline every block classified by step ``k``, read from the trace (its
        position, extent and verdict): accepted green, rejected grey, partial orange."""
        blocks = trace.blocks
        shown = blocks is not None and k >= trace.first_work_step and len(blocks) > 0
        self.block_outlines.set_visible(shown)
        if not shown:
            return
        n = min(k - trace.first_work_step + 1, len(blocks))  # block i is step first + i
        r0, c0 = blocks.row[:n], blocks.col[:n]
        r1, c1 = r0 + blocks.extent[:n, 0], c0 + blocks.extent[:n, 1]
        corners = [(c0, r0), (c1, r0), (c1, r1), (c0, r1)]
        self.block_outlines.set_verts(np.stack([np.stack(p, -1) for p in corners], 1))
        self.block_outlines.set_edgecolor(to_rgba_array(BLOCK_COLORS)[blocks.kind_code[:n]])

    def set_fill(self, fill, *, step: int | None = None, draw: bool = True) -> Step:
        """Show another fill (a moved vertex, the other method, ...), reusing the artists.

        Parameters
        ----------
        fill : Fill (with trace) or FillTrace
        step : int, optional
            Step to show. Default: the last step if the view was on the last step (a
            finished fill stays finished while a vertex moves), else the same step index,
            clipped to the new fill's steps.
        draw : bool
            Ask the canvas to redraw afterwards.

        Returns
        -------
        Step
        """
        trace = as_trace(fill, "FillView.set_fill")
        old = self._trace
        if step is None:
            at_end = old is None or self._step >= len(old) - 1
            step = len(trace) - 1 if at_end else min(self._step, len(trace) - 1)
        W, H = trace.width, trace.height
        if old is None or (old.width, old.height) != (W, H):
            self.grid.update(W, H)
            if self.centres is not None:
                self.centres.update(W, H)
            # same artists for the same size; new ones (same colours) for a new size
            self.rejected = set_image(self.rejected, np.zeros((H, W)))
            self.coverage.image = set_image(self.coverage.image, np.zeros((H, W)))
        self._trace = trace
        self._extra = self._mark_sample_only(fill, trace)
        self._show_values(fill, trace)
        if trace.halfplane is None and trace.blocks is None:
            self.rejected.set_visible(False)
        self.raster_line.width = W
        self.triangle.update(trace, drawn_edges(trace))
        self._lift_middle_label(trace)
        _arrow_off_point_4(self.triangle, trace)
        self.setup_marks.update(trace, self.triangle.labels)
        # the edge names are what half-plane captions talk about; span captions do not
        for label in self.triangle.edge_labels:
            label.set_visible(trace.method == "halfplane")
        self.bbox.update(trace)
        self._keyed = None  # the key is filled again for this fill (show_step)
        self.blit = self._blit_plan()  # new still artists; images may be new artists too
        return self.show_step(step, draw=draw)

    def _lift_middle_label(self, trace) -> None:
        """The middle vertex's label off the split line, which runs through that vertex: put
        beside it, the label lay on the dashed line and the raster line outlined just under it
        (review r225 FIG2, lesson 00's player at its opening step). Above the line, unless
        the vertex is in the grid's top row."""
        s = trace.span
        if s is None or s.u4 is None or not self.triangle.labels:
            return
        xy = np.asarray(self.triangle.vertices.get_xydata(), dtype=np.float64)
        label = self.triangle.labels[int(np.argmin(np.abs(xy - s.sorted_xy[1]).sum(axis=1)))]
        dx, dy = label.get_position()  # offset points, y up
        reach = 0.5 * label.get_fontsize() + fs(0.35)  # half the text, the line and a gap
        if abs(dy) < reach:
            label.set_position((dx, reach if s.sorted_xy[1, 1] >= 1.0 else -reach))

    # -- fast redraws ----------------------------------------------------------------------
    def _blit_plan(self):
        """What moves at a step and what stays, in drawing order (see LayeredBlit)."""
        t, r, p = self.triangle, self.raster_line, self.pixel
        split = self.split
        middle = [self.grid.lines, *self.ax.spines.values(), self.bbox.outline, split.line,
                  t.outline, *t.arrows, self.sample_only]  # fmt: skip
        if self.centres is not None:
            middle[1:1] = [self.centres.inside, self.centres.outside]
        if self.sample_dots is not None:
            # among the triangle's lines, where their zorder puts them in a full draw: a
            # layer of their own above the labels hid v1 and E31 in every blitted frame
            middle += list(self.sample_dots)
        s = self.setup_marks
        return LayeredBlit(self.fig, [
            (MOVING, [self.rejected, self.coverage.image, self.values, r.band, s.band,
                      s.lines]),  # fmt: skip
            (STILL, middle),
            (MOVING, [self.block_outlines, r.cells, p.box, r.span, r.covered, r.missed,
                      p.centre, s.turn_label, s.arc, s.head, *s.roles, *s.coords]),  # fmt: skip
            # the vertex dots above their labels' boxes, as in a full draw (review r23)
            (STILL, [split.point, split.label, *t.labels, *t.edge_labels, t.vertices]),
            # text costs more to draw than the pixels: the header moves only with the step
            (MOVING, [self.header] if self._step_header else []),
            (MOVING, [self.caption_text]),
        ])  # fmt: skip

    def redraw(self) -> bool:
        """Render the figure into its (Agg-based) canvas now, as fast as the change allows.

        After :meth:`show_step` only the moving artists (pixels filled and rejected, the
        current raster line or pixel, step header, caption) are drawn again, over a cached
        background and still layers (blitting); the first time, after :meth:`set_fill` and
        when the bounding box or the split appears, the whole figure is drawn. Call
        ``view.blit.invalidate()`` after changing other artists yourself. The result equals
        ``fig.canvas.draw()`` up to rounding at anti-aliased edges.

        Returns
        -------
        bool
            True when the whole figure was drawn.
        """
        return self.blit.draw(self._still)

    def _show_tested(self, k: int) -> int:
        """Show the bold sample dots' results from the step that tests them (untested
        before, review r33 lesson 00: at the snap step they gave the final coverage away).
        Returns how many pixels' samples are tested (-1: every one, or no bold dots)."""
        dots = self.sample_dots
        if dots is None or not getattr(dots, "bold", False):
            return -1
        if self._sample_steps is None or self._sample_steps[0] is not self._trace:
            self._sample_steps = (self._trace, sample_test_steps(self._trace))
        steps = self._sample_steps[1]
        if steps is None or k >= self._trace.interpolation_step:
            dots.set_tested(None)
            return -1
        tested = steps <= k
        dots.set_tested(tested)
        return int(tested.sum())

    def show_samples(self, dots) -> None:
        """Step with the sample dots ``dots`` (:func:`~teachraster.plotting.plot_samples` on
        this view's Axes), drawn as a full draw orders them; at the last step with values
        the covered samples are rings, so that the pixels' colours show (review r11)."""
        self.sample_dots = dots
        self.blit = self._blit_plan()
        self._keyed = None  # bold dots have their own key lines
        dots.set_rings(self._still[3])  # coloured: see show_step
        tested = self._show_tested(self._step)
        self._still = (*self._still[:4], tested, *self._still[5:])

    def _show_values(self, fill, trace: FillTrace) -> None:
        """Put the values the last step writes into ``values``: the trace's record of the
        interpolation in use at the covered centres (read, never recomputed); with several
        samples also the pixels with only a sample covered, whose values a Fill holds
        (``fill.attrs``; the caption counts them). The colour range, and the key's bar, are
        those of the interpolation on show: a range shared with the other one named values
        this one never reaches (review r166 00-6: 0.88, the affine top, under perspective's
        0.86); the player's comparison shows both on one range."""
        wanted, attribute = self._values
        names = list(trace.pixel_affine)
        name = attribute if attribute in names else (names[0] if names else None)
        self._shown = None
        if not wanted or name is None or trace.culled or not trace.covered.any():
            return
        written = {"affine": trace.pixel_affine, "perspective": trace.pixel_perspective,
                   "subdivided": trace.pixel_subdivided}[trace.interpolation]  # fmt: skip
        shown = first_channel(written[name])
        local = np.full(trace.bbox.shape, np.nan)
        local[trace.covered] = shown  # row-major, as recorded
        lo, hi = float(shown.min()), float(shown.max())
        data = trace.image(local)
        where = "at the covered centres"
        extra = self._extra
        if extra is not None:
            data[extra] = first_channel(fill.attrs[name][extra])
            if extra.any():  # extrapolated to centres outside: the bar spans them too (r12)
                where = "at the pixel centres"
                lo, hi = min(lo, float(data[extra].min())), max(hi, float(data[extra].max()))
        self.values = set_image(self.values, data)
        self.values.set_clim(lo, hi if hi > lo else lo + 1.0)
        self._shown = (name, lo, hi)
        if self.value_bar is not None:
            self.value_bar.set_range(name, lo, hi, self.values.get_cmap(), where)

    def _mark_sample_only(self, fill, trace: FillTrace) -> np.ndarray | None:
        """Put the pixels shaded for a covered sample alone (their centre is not covered)
        into ``sample_only``, each a square a little inside its pixel so that two side by
        side stay two; return them as an (H, W) mask (None: one sample, or a bare trace)."""
        self.sample_only.set_verts([])
        if trace.samples is None or isinstance(fill, FillTrace):
            return None
        extra = fill.coverage & ~trace.image(trace.covered, fill=False)
        rows, cols = np.nonzero(extra)
        inset = np.array([[0.1, 0.1], [0.9, 0.1], [0.9, 0.9], [0.1, 0.9]])
        self.sample_only.set_verts(np.column_stack([cols, rows])[:, None, :] + inset)
        return extra

    def _key_entries(self, trace: FillTrace, testing: bool, coloured: bool,
                     split: bool = False, *, boxed: bool = True,
                     setup: str | None = None, last: bool = False,
                     roles: bool = False) -> list:  # fmt: skip
        """What the step on show draws: the pixel or block under test only while there is one
        (reviews r8, lesson 04 c15; r22, lesson 00), the split line and point 4 once found
        (r22), the sample dots of a multisampled fill, and at the last step with values their
        colours instead of "covered" and the split's tints, which it hides. ``setup``: the
        kind of a set-up step on show (None at a work step or the last)."""
        c, method = COLORS, trace.method
        if setup:
            return self._setup_entries(trace, setup, split, boxed, roles)
        # coloured: the first lines are the value bar's (a colour bar, not two swatches that
        # gave its ends only, the top 0.88 not v2's 1 unexplained: review r11, lesson 00)
        # with samples the blue is the centre's pass; a pixel shaded by a sample alone shows
        # its covered dot (review r93 02-1)
        covered = "covered" if trace.samples is None else "centre covered"
        entries = [None] * ValueBar.LINES if coloured else [(covered, c["fill"], c["fill"])]
        if method == "halfplane":
            entries.append(("tested, rejected", c["rejected"], c["rejected"]))
        elif method == "tiled":  # rejected with their block, or tested in a partial one
            entries.append(("rejected", c["rejected"], c["rejected"]))
        if method != "span":  # span tables draw no box (see show_step)
            entries.append(("bounding box", "none", c["bbox"], DASHED_SQUARE))
        if method == "span" and not coloured:
            if split:  # the parts' tints, the split line and point 4 (plot_split) appear
                # together, at the split's step (review r58 00-4: keyed before it was drawn)
                entries += _split_entries()
        elif method == "span" and split:
            # the last step hides the parts' tints but keeps the dashed line and the diamond
            # at point 4: keyed there too (review r52, lesson 00: an unkeyed pink diamond)
            entries.append(_split_entries()[-1])
        if method == "span" and not coloured and not last:  # the last step draws no raster
            # line, nor its span and centres (review r229 01-FIG1: keyed there all the same)
            entries += [("raster line, its pixels", to_rgba(c["current"], 0.15), c["current"]),
                        ("span x_left .. x_right", c["current"], c["current"], "|"),
                        ("its centre covered", c["edge"], "white", "o"),
                        ("its centre not", "white", c["edge"], "o")]  # fmt: skip
        if method == "tiled":  # the outlines of the blocks classified (review r77 00-2)
            entries += [(f"block {kind}", "none", colour)
                        for kind, colour in zip(("rejected", "accepted", "partial"), BLOCK_COLORS)]  # fmt: skip
        if testing and method == "tiled":  # the block's outline (plot_current_pixel)
            entries.append(("block under test", "none", c["current"]))
        elif testing:
            # the cross at its centre (plot_current_pixel) is named too (review r3, 02)
            entries.append((PIXEL_UNDER_TEST, "none", c["current"]))
        return entries + self._sample_entries(trace, coloured, last=last)

    def _setup_entries(self, trace: FillTrace, kind: str, split: bool, boxed: bool,
                       roles: bool) -> list:  # fmt: skip
        """The key of a set-up step: what that step draws, and the box, split and roles
        once found. Before the first fill step the picture shows the vertices, the box once
        found, the split and the untested samples: eight lines for parts, spans and centres
        not drawn yet read as on show (reviews r33 and r58, lesson 00 step 0; one sample per
        pixel too, and tiles' "covered, rejected" at their step 0). Review r229 01-W1/FIG1:
        the winding, the raster lines and the roles are drawn and keyed at their steps, and
        the split's step keys the two parts it tints."""
        c, entries = COLORS, []
        if kind == "snap":  # review r239 01-W1: the snap's step drew and keyed nothing
            entries += _snap_entries(trace)
        elif self.triangle.arrows and self.triangle.arrows[0].get_visible():  # the arrowheads
            entries.append(walk_entry(trace))
        if kind == "winding" and trace.turn is not None:
            arrow = r"$\circlearrowright$" if trace.turn == "clockwise" else r"$\circlearrowleft$"
            entries.append(("v1→v2→v3: its winding", TURN_COLOR, TURN_COLOR, arrow))
        if boxed and trace.method != "span":
            entries.append(("bounding box", "none", c["bbox"], DASHED_SQUARE))
        if kind == "rows" and trace.span is not None and len(trace.span.rows):
            entries += [("raster lines to step through", to_rgba(c["current"], 0.15), c["current"]),
                        ("dotted: the bottom vertex's", "none", "none"),
                        ("line, traced, not visited", "none", "none")]  # fmt: skip
        if roles:
            entries.append(ROLES_ENTRY)
        if split:
            entries += _split_entries()
        return entries + self._sample_entries(trace, False, setup=self._bold_dots)

    @property
    def _bold_dots(self) -> bool:
        return self.sample_dots is not None and getattr(self.sample_dots, "bold", False)

    def _sample_entries(self, trace: FillTrace, coloured: bool, setup: bool = False,
                        last: bool = False) -> list:  # fmt: skip
        """The key's lines for the sample dots (none when they are not keyed), and at the last
        step for the pixels shaded for a sample alone, drawn as show_step draws them."""
        c, entries = COLORS, []
        sample_only = last and self._sample_only_n
        if sample_only:
            sample_only = [(SAMPLE_ONLY, sample_only_face(coloured), c["outside"])]
        if self._sample_key and self._bold_dots and trace.samples is not None:
            entries += self._bold_entries(coloured or last, setup) + (sample_only or [])
        elif self._sample_key and trace.samples is not None:  # review r9: dots without a key
            # at the coloured step a ring (plot_samples' set_rings) with a colour inside: a
            # white face would read as the white dot of a sample not covered
            # drawn as the picture draws it: a white ring with a dark rim (review r22)
            ring = self.values.get_cmap()(0.5)
            covered = (
                (ring, "white", "o", c["edge"])
                if coloured
                else (TRIANGLE_COLORS[0], c["edge"], "o")
            )
            entries += [("sample covered", *covered),
                        ("sample not covered", "white", c["centre"], "o")]  # fmt: skip
            entries += sample_only or []
        return entries

    def _bold_entries(self, done: bool, setup: bool) -> list:
        """Bold dots (plot_samples' ``bold``): untested ones before the step that tests
        them (before the fill steps, only those; ``done``: the last step, every one tested),
        covered filled and uncovered hollow; the pixels shaded for a sample alone are keyed
        by _sample_entries."""
        style, entries = BOLD_STYLE, []
        if not done:
            entries.append(("sample not tested yet", "white", style["untested"][1], "o"))
        if setup:
            return entries
        entries += [("sample covered", style["covered"][0], style["covered"][1], "o", "white"),
                    ("sample not covered", "white", style["uncovered"][1], "o")]  # fmt: skip
        return entries


class Key(Artists):
    """A legend drawn as plain markers and texts beside an Axes.

    It looks like a legend but costs a third of one at every draw (a matplotlib Legend lays
    out its boxes again each time), and its entries change in place.
    """

    def __init__(self, ax, n: int, *, x: float = 1.04, y: float = 1.0) -> None:
        self.swatches, self.texts = [], []
        self.ax, self.x, self.y = ax, x, y
        # 0.8 of the style's size: a player's figure, shown shrunk to the column at 1024 px,
        # showed 0.75 (13.5 pt) at 11.7 px (issue 29)
        self.size = size = fs(0.8)
        for i in range(n):
            # each entry one line lower, measured in inches so it follows the font size
            trans = ax.transAxes + ScaledTranslation(0, -i * self.spacing / 72,
                                                     ax.figure.dpi_scale_trans)  # fmt: skip
            self.swatches.append(ax.plot([x], [y], "s", ms=size * 1.1, mew=2.0,
                                         transform=trans, clip_on=False)[0])  # fmt: skip
            self.texts.append(ax.text(x + 0.04, y, "", transform=trans, va="center",
                                      ha="left", fontsize=size, clip_on=False))  # fmt: skip

    @property
    def spacing(self) -> float:
        """From one entry's line to the next, in points."""
        return self.size * 1.7

    @property
    def artists(self) -> list:
        return self.swatches + self.texts

    def points(self):
        """A transform from points, with (0, 0) at the centre of the first swatch."""
        fig = self.ax.figure
        return (Affine2D().scale(1 / 72) + fig.dpi_scale_trans
                + ScaledTranslation(self.x, self.y, self.ax.transAxes))  # fmt: skip

    def show_entry(self, label: str, on: bool) -> None:
        """Show or hide the entry whose text is ``label`` (none: nothing changes)."""
        for swatch, text in zip(self.swatches, self.texts):
            if text.get_text() == label:
                swatch.set_visible(on)
                text.set_visible(on)

    def set_entries(self, entries) -> None:
        """``entries``: (label, face colour, edge colour[, marker[, rim colour]]) per line
        (marker default a square swatch; a rim: a stroke around the edge, as sample rings are
        drawn), or None for a line left empty (for another artist: :class:`ValueBar`); the
        rest are hidden."""
        for i, (swatch, text) in enumerate(zip(self.swatches, self.texts)):
            on = i < len(entries) and entries[i] is not None
            swatch.set_visible(on)
            text.set_visible(on)
            if on:
                label, face, edge, *marker = entries[i]
                swatch.set_marker(marker[0] if marker else "s")
                rim = marker[1] if len(marker) > 1 else None
                swatch.set_path_effects([withStroke(linewidth=4.0, foreground=rim)] if rim else [])
                swatch.set_markerfacecolor(face)
                swatch.set_markeredgecolor(edge)
                text.set_text(label)


class ValueBar(Artists):
    """A short colour bar on the first :data:`LINES` lines of a :class:`Key`: what the
    colours are, the colour map, and the values at its two ends under them.

    Two swatches named the colour map's ends only, not the colours between (review r11,
    lesson 00 c14); the title says where the range comes from.
    """

    #: The key lines it takes: its title, the bar, the numbers at its ends.
    LINES = 3

    #: Colour steps along the bar (each about 2 px wide at the classroom size).
    STEPS = 64

    def __init__(self, key: Key) -> None:
        ax, size, line = key.ax, key.size, key.spacing
        trans = key.points()
        left = -0.55 * size  # the swatches' left edge
        right = left + 9.0 * size  # about as long as "tested, rejected"
        half = 0.45 * size
        edges = np.linspace(left, right, self.STEPS + 1)
        y = -line  # the bar on the second line
        quads = [[(a, y - half), (b, y - half), (b, y + half), (a, y + half)]
                 for a, b in zip(edges[:-1], edges[1:])]  # fmt: skip
        self.bar = PolyCollection(quads, array=(np.arange(self.STEPS) + 0.5) / self.STEPS,
                                  norm=Normalize(0.0, 1.0), edgecolors="face",
                                  linewidths=0.3, transform=trans, clip_on=False)  # fmt: skip
        ax.add_collection(self.bar, autolim=False)
        self.frame = ax.add_patch(Rectangle((left, y - half), right - left, 2 * half,
                                            fill=False, edgecolor=COLORS["edge"], lw=0.8,
                                            transform=trans, clip_on=False))  # fmt: skip
        text = {"fontsize": size, "va": "center", "transform": trans, "clip_on": False}
        self.title = ax.text(left, 0.0, "", ha="left", **text)
        self.low = ax.text(left, -2 * line, "", ha="left", **text)
        self.high = ax.text(right, -2 * line, "", ha="right", **text)

    def set_range(self, name: str, lo: float, hi: float, cmap,
                  where: str = "at the covered centres") -> None:  # fmt: skip
        """The colours run from ``lo`` to ``hi`` of ``name`` in ``cmap``, read ``where``.

        Under MSAA a pixel with only a sample covered shows its value extrapolated to its
        uncovered centre: ``where`` then says "at the pixel centres" (review r12, lesson 00).
        """
        self.bar.set_cmap(cmap)
        self.title.set_text(f"{name} {where}")
        self.low.set_text(f"{lo:.2f}")
        self.high.set_text(f"{hi:.2f}")

    @property
    def artists(self) -> list:
        return [self.bar, self.frame, self.title, self.low, self.high]


class ComparisonView:
    """Two images side by side and the heatmap of their difference, updated in place.

    For example affine vs perspective-correct values of an attribute, or two renders of a
    textured floor. Value images share one colour range, so equal colours mean equal values.

    Parameters
    ----------
    a, b : (H, W) or (H, W, 3) arrays
        The two images (NaN: not covered, drawn transparent).
    titles : (str, str)
        Titles of the two images.
    label : str
        What the heatmap shows (its title says the maximum too).
    axes : three matplotlib Axes, optional
        Default: a new figure with three panels.
    vmin, vmax : float, optional
        Fixed colour range of the value images; default the range of both images, renewed at
        every update.
    grid : bool
        Pixel boundaries on every panel (up to the grid size limit).
    round_range : bool
        The heatmap's colour range ends on a round number (``plotting.common.round_up``), so a
        new maximum that rounds to a range drawn before puts the colour bar back from a cache.
    """

    def __init__(self, a, b, *, titles=("a", "b"), label: str = "|a − b|", axes=None,
                 vmin=None, vmax=None, grid: bool = True,
                 round_range: bool = False) -> None:  # fmt: skip
        a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
        h, w = a.shape[:2]
        caxes = [None, None, None]
        if axes is None:
            import matplotlib.pyplot as plt

            # Three equal panels whose boxes match the image's aspect, each colour bar exactly
            # as tall as its panel, the figure as tall as the panels need: computed once here,
            # so no layout engine runs at every draw. Sizes in inches.
            pw = 4.4
            ph = pw * h / w
            if ph > 5.4:  # tall images: limit the height instead
                ph, pw = 5.4, 5.4 * w / h
            fw, fh = 18.0, ph + 1.9  # room above for titles and column labels
            fig = plt.figure(figsize=(fw, fh))
            bottom = 0.35 / fh
            lefts = (0.81, 6.39, 12.24)

            def rect(x, width):
                return (x / fw, bottom, width / fw, ph / fh)

            axes = [fig.add_axes(rect(x, pw)) for x in lefts]
            if a.ndim == 2:  # colour images have no colour bar
                caxes[1] = fig.add_axes(rect(lefts[1] + pw + 0.2, 0.2))
            caxes[2] = fig.add_axes(rect(lefts[2] + pw + 0.2, 0.2))
        self.axes = list(axes)
        self.fig = self.axes[0].figure
        self._fixed = (vmin, vmax)
        lo, hi = self._range(a, b)
        # Row and column labels on the first panel only (the panels show the same pixels):
        # tick labels are the dearest part of a redraw.
        self.grids = [plot_pixel_grid(ax, w, h, ticks=5 if i == 0 else False) if grid else None
                      for i, ax in enumerate(self.axes)]  # fmt: skip
        self.images: list[ImageArtists] = []
        for ax, data, title, cax in zip(self.axes[:2], (a, b), titles, caxes):
            # One colour bar, by the second panel: both value images share the range.
            self.images.append(show_values(ax, data, vmin=lo, vmax=hi, colorbar=False))
            if ax is self.axes[1] and data.ndim == 2:
                cb_kw = {"cax": cax} if cax is not None else {"ax": ax, "shrink": 0.85}
                self.images[-1].colorbar = self.fig.colorbar(self.images[-1].image, **cb_kw)
            ax.set_title(title, y=1.0, pad=fs(3.4))
        # fixed position: no per-draw layout. The pad leaves room for the first panel's column
        # labels; a heatmap wrapped onto a row of its own has none, and its title sits close.
        beside = abs(self.axes[2].get_position().y0 - self.axes[0].get_position().y0) < 1e-9
        self.axes[2].set_title("", y=1.0, pad=fs(3.4) if beside else fs(0.5))
        own_figure = caxes[2] is not None
        self.heatmap = plot_error_heatmap(self.axes[2], a, b, label=label,
                                          colorbar=not own_figure,
                                          round_range=round_range)  # fmt: skip
        if own_figure:
            self.heatmap.colorbar = self.fig.colorbar(self.heatmap.image, cax=caxes[2],
                                                      label=label)  # fmt: skip

    def _range(self, a, b):
        vmin, vmax = self._fixed
        if a.ndim == 3:
            return 0.0, 1.0
        lo = quiet_nanmax(-np.concatenate([a.ravel(), b.ravel()]))
        hi = quiet_nanmax(np.concatenate([a.ravel(), b.ravel()]))
        lo = -lo if np.isfinite(lo) else 0.0
        hi = hi if np.isfinite(hi) else 1.0
        if hi <= lo:
            lo, hi = lo - 0.5, hi + 0.5  # a constant image still needs a colour range
        return (lo if vmin is None else vmin), (hi if vmax is None else vmax)

    @property
    def maximum(self) -> float:
        """The largest |a − b| on show (NaN when nothing is covered)."""
        return self.heatmap.maximum

    def update(self, a, b, *, draw: bool = True) -> None:
        """Show new images in the same artists."""
        a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
        h, w = a.shape[:2]
        old = image_shape(self.images[0].image)[:2]
        if (h, w) != old:
            for g in self.grids:
                if g is not None:
                    g.update(w, h)
        lo, hi = self._range(a, b)
        for art, data in zip(self.images, (a, b)):
            art.update(data)
            if data.ndim == 2:
                art.image.set_clim(lo, hi)
        self.heatmap.update(a, b)
        if draw:
            self.fig.canvas.draw_idle()


class InterpolationView(ComparisonView):
    """Affine vs perspective-correct values of one attribute of a fill, and their error.

    Both interpolations come from the fill's trace (a traced fill records both, whatever
    ``interpolation`` it was made with). The triangle is outlined, with vertex labels, on every
    panel.

    Parameters
    ----------
    fill : Fill (with trace) or FillTrace
    name : str, optional
        Attribute to show; may be left out when the triangle has only one.
    channel : int, optional
        One channel of a vector attribute (a 3-channel one is otherwise shown as colour).
    axes : three (or four) matplotlib Axes, optional
        A fourth Axes (not None) shows the two interpolations along the row of the largest
        error (:func:`~teachraster.plotting.plot_profile`), dashed on the heatmap: a straight
        line for affine, a curve for perspective-correct.
    vmin, vmax : float, optional
        Fixed colour range of the values (default: their range, renewed at every update).
    inside : bool
        Keep the vertex labels inside the panels, clear of the dots, the edges and one another
        (``plot_triangle``'s ``inside`` and ``clear``), for a view whose vertices are dragged
        anywhere (the TriangleEditor: pushed outwards, a vertex at the top put "v3" over the
        heatmap's title, review r459 S3). Default: pushed outwards (the player places them
        off the frames itself).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import teachraster as tr
    >>> tri = tr.Triangle([[1, 1], [15, 3], [4, 14]], w=[1, 4, 2], attrs={"u": [0, 1, 0]})
    >>> view = InterpolationView(tr.rasterize(tri, 16, 16, trace=True))
    >>> view.maximum > 0.1     # w differs across the vertices: affine is visibly wrong
    True
    >>> import matplotlib.pyplot as plt; plt.close(view.fig)
    """

    def __init__(self, fill, name: str | None = None, *, channel: int | None = None, axes=None,
                 vmin=None, vmax=None, inside: bool = False) -> None:  # fmt: skip
        trace = as_trace(fill, "InterpolationView")
        self.name = name
        self.channel = channel
        a, b = self._images(trace)
        label = self.name + ("" if channel is None else f"[{channel}]")
        axes = None if axes is None else list(axes)
        profile_ax = axes.pop(3) if axes is not None and len(axes) > 3 else None
        # Short titles, so that they fit their panels at classroom font sizes too; the
        # attribute's name labels the colour bar of the values.
        # the error is named as lesson 00's heatmap names it, |Δu| (review r20, 00 c14)
        super().__init__(
            a, b, titles=("affine", "perspective-correct"), label=f"|Δ{label}|", axes=axes,
            vmin=vmin, vmax=vmax,
        )  # fmt: skip
        self.profile = None
        if profile_ax is not None and a.ndim == 3:
            profile_ax.set_axis_off()  # colours have no single value to draw along a row
        elif profile_ax is not None:
            self.profile = plot_profile(
                profile_ax, a, b, index=self._profile_row(a), labels=("affine", "perspective"),
                value=label, guides=[self.axes[2]], vlim=None if vmin is None else (vmin, vmax),
            )  # fmt: skip
        colorbar = self.images[1].colorbar
        if colorbar is not None:
            colorbar.set_label(label)
        self.triangles = [plot_triangle(ax, trace, arrows=False, inside=inside, clear=inside)
                          for ax in self.axes]  # fmt: skip
        for tri in self.triangles:
            tri.outline.set_linewidth(tri.outline.get_linewidth() * 0.6)
        self._trace = trace
        self.in_use = None  # the "in use" notes of highlight(), made when first needed
        # The heatmap's title states the maximum and its ring marks the pixel: the note beside
        # the ring only covered a vertex label (review r13, 00 c14: "max 0.152" over v2).
        self.heatmap.show_note = False
        self.heatmap.note.set_visible(False)

    def _images(self, trace):
        if self.name is None:
            names = list(trace.pixel_affine)
            if len(names) != 1:
                raise ValueError(f"pick an attribute by name: {names or 'none given'}")
            self.name = names[0]
        a = attribute_image(trace, self.name, mode="affine", channel=self.channel)
        b = attribute_image(trace, self.name, mode="perspective", channel=self.channel)
        return a, b

    def _profile_row(self, a) -> int:
        """The row of the marked largest error (the middle row when nothing is covered)."""
        worst = self.heatmap.worst
        return worst[0] if worst is not None else a.shape[0] // 2

    @property
    def trace(self) -> FillTrace:
        return self._trace

    def highlight(self, interpolation: str | None) -> None:
        """Mark the panel of the interpolation in use ("affine" or "perspective"); None shows
        both alike.

        The mark is an "in use" note under the panel (in its title it would not fit at large
        fonts) and a thick frame in the colour of the current step. The other panel keeps its
        full colours: faded, its values could not be read against the colour bar.
        """
        if self.in_use is None:
            self.in_use = [
                ax.text(0.5, -0.03, "in use", transform=ax.transAxes, ha="center", va="top",
                        fontsize=fs(0.9), fontweight="bold", color=COLORS["current"])
                for ax in self.axes[:2]
            ]  # fmt: skip
        for i, (ax, mark) in enumerate(zip(self.axes[:2], self.in_use)):
            used = interpolation is not None and (i == 0) == (interpolation == "affine")
            mark.set_visible(used)
            for spine in ax.spines.values():
                spine.set_edgecolor(COLORS["current"] if used else "black")
                spine.set_linewidth(3.0 if used else 0.8)

    def update(self, fill, *, draw: bool = True) -> None:  # type: ignore[override]
        """Show another fill (e.g. after a vertex or its w moved) in the same artists."""
        trace = as_trace(fill, "InterpolationView.update")
        a, b = self._images(trace)
        self._trace = trace
        for tri in self.triangles:
            tri.update(trace)
        super().update(a, b, draw=False)
        if self.profile is not None:
            self.profile.update(a, b, self._profile_row(a))
        if draw:
            self.fig.canvas.draw_idle()
