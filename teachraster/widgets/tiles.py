"""``TileExplorer``: walk the block hierarchy of a tiled fill, level by level or block by block."""

from __future__ import annotations

import ipywidgets as widgets

from ..core.fill import rasterize
from ..core.traversal import TRAVERSALS
from ..core.triangle import Triangle
from ..plotting import plot_blocks, plot_pixel_grid, plot_triangle
from ..plotting.blitting import MOVING, STILL, LayeredBlit
from ..plotting.tiles import (
    CURRENT_BLOCK,
    UNCLASSIFIED,
    block_mask,
    decided_mask,
    pending_children,
)
from .common import (
    SLIDER_COLUMN_WIDTH,
    Holdable,
    Shown,
    control_row,
    fill_axes,
    labelled,
    renew_slider,
    style_context,
    title_html,
)
from .display import html_escape, new_figure, resolve_backend
from .live_slider import LiveSlider, info_line, slider_display

#: Block-size choices: llvmpipe's, and smaller hierarchies that read on a small grid.
SIZE_OPTIONS = [
    ("64 / 16 / 4 (llvmpipe)", (64, 16, 4)),
    ("16 / 4 / 1", (16, 4, 1)),
    ("8 / 4 / 2", (8, 4, 2)),
    ("16 / 4", (16, 4)),
    ("8 / 2", (8, 2)),
]


#: The explorer's key entry for the white page: only the block slider leaves blocks
#: unclassified (every level of the level slider is classified whole).
STEPPED_UNCLASSIFIED = "not classified yet (block slider)"
#: ... and only the block slider has one block visited now (outlined).
STEPPED_CURRENT = "the block visited now (block slider)"
#: The level slider's label while it shows its level, and while the block slider does: its
#: value then is not what the picture shows (it read "level 0" over a 1×1 block; review
#: r52, lesson 10), only where moving it goes.
LEVEL_LABELS = {True: "level", False: "show level"}
#: The traversal menu's labels: siblings are tiled in 2×2 tiles, so "tiled" and Morton
#: visit a 4×4 grid of siblings (every block ratio of 4) in the same order; the menu says so
#: rather than offer two names for one path (review r255 S4, lesson 10).
TRAVERSAL_LABELS = {
    "scanline": "scanline",
    "serpentine": "serpentine",
    "tiled": "tiled: 2×2 tiles, row by row",
    "morton": "morton: Z-order (= tiled on 4×4 siblings)",
}
#: Blocks this small (px) or smaller are shown zoomed on their top-level block while the
#: block slider visits them: a 1×1 block of a 64 × 64 grid was a ~6 px square found only by
#: its outline (reviews r45 #7, r52 #10).
ZOOM_AT = 2


class TileExplorer(Holdable):
    """Step through the blocks of a tiled fill: one level at a time, or one block at a time.

    The **level** slider shows the hierarchy after each block size is classified (rejected
    grey, accepted green, partial orange; partial blocks are split at the next level; the
    blocks a larger block decided hatched, so that the tests made at the level's size stand
    out: at a 1×1 level, the pixel tests from the pixels filled with none). Moving it puts the
    block slider back to 0, where the picture is a level's. The
    **block** slider walks the blocks in the chosen **traversal** order (depth first, the
    children of a partial block right after it): at ``k`` the first ``k`` blocks are shown,
    the ``k``-th outlined (``current``: its index in the trace, None on the level slider)
    and captioned; the page stays white where no block has been classified
    yet, a visited partial block's children not reached yet are a paler orange, and a child
    covers its partial parent (opaque colours: each one in the key).
    The **block sizes** and **traversal** menus fill the triangle again and put the block
    slider back to 0 (block ``k`` is another block in another order). The counters
    (rejected / accepted / partial per size, llvmpipe's empty / full / partial, and the pixel tests run) are shown below.

    Parameters
    ----------
    tri : Triangle
    width, height : int
        Image size (a 64 × 64 grid or smaller reads best).
    block_sizes : tuple of int
        Initial sizes (one of :data:`SIZE_OPTIONS`' values, or any valid hierarchy).
    traversal : {"scanline", "serpentine", "tiled", "morton"}
    backend : {"auto", "ipympl", "image"}
    style : str, optional
        ``"classroom"`` for projector-sized fonts (only inside the widget).

    Examples
    --------
    >>> import teachraster as tr
    >>> ex = TileExplorer(tr.Triangle([[1, 1], [30, 6], [9, 29]]), 32, 32,
    ...                   block_sizes=(16, 4, 1), backend="image")
    >>> ex.level.value = 1
    >>> int(ex.shown.sum()) > 0
    True
    >>> ex.close()
    """

    #: ``teachraster html``: the offline page steps through every block of the traversal (:mod:`.offline`)
    _offline_sweep_ = "block"

    def __init__(self, tri: Triangle, width: int = 64, height: int = 64, *,
                 block_sizes=(16, 4, 1), traversal: str = "scanline", backend: str = "auto",
                 style: str | None = None) -> None:  # fmt: skip
        self.tri, self.width, self.height = tri, width, height
        self.backend = resolve_backend(backend)
        block_sizes = tuple(int(s) for s in block_sizes)
        options = list(SIZE_OPTIONS)
        if block_sizes not in [v for _, v in options]:
            options.append((" / ".join(map(str, block_sizes)), block_sizes))
        self.sizes = widgets.Dropdown(options=options, value=block_sizes)
        self.traversal = widgets.Dropdown(options=[(TRAVERSAL_LABELS[k], k) for k in TRAVERSALS],
                                          value=traversal)  # fmt: skip
        # in the page, its few positions drawn ahead (ahead.FramesAhead): a drag shows the
        # page's own pictures (issue 31: 1.3-5.5 fps through the kernel)
        self.level = LiveSlider(value=0, min=0, max=len(block_sizes) - 1, step=1,
                                description="level", readout_format=".0f")  # fmt: skip
        # hundreds of blocks (864 with 16/4/1 on 64×64): a track as wide as the level slider's
        # and the column, not ipywidgets' ~120 px (review r26, lesson 10 c23); arrow keys step
        # one block
        self.block = widgets.IntSlider(value=0, min=0, max=0, description="block",
                                       layout=widgets.Layout(width=SLIDER_COLUMN_WIDTH))  # fmt: skip
        self.counters = widgets.HTML()
        self._fill()
        with style_context(style):
            fig = new_figure((6, 6), self.backend)
            ax = fill_axes(fig, width, height)
            plot_pixel_grid(ax, width, height)
            plot_triangle(ax, self.fill.trace.snapped, arrows=False, labels=False)
            self.ax, self.fig = ax, fig
            self.artists = None
            self._draw_blocks()
            # the first picture is the level-0 view: it becomes the page's reference and poster,
            # and a patch sent before the page shows the figure is lost (review r26, lesson 10
            # c23: the finished walk stood under the caption "level 0")
            self._compute_at(self.level.value)
            self._set_artists()
            _fit_margins(fig, ax)
            self.display = slider_display(fig, self.backend, draw=self._draw_figure,
                                          drafting=lambda: self.level.dragging,
                                          alt="the blocks of the tiled fill")  # fmt: skip
        # the caption (the page figure's own line: a picture drawn ahead brings its own)
        self.info, info_widgets = info_line(self.display)
        self.sizes.observe(self._on_refill, "value")
        self.traversal.observe(self._on_traversal, "value")
        self.level.observe(lambda _: None if self._quiet else self._on_level(), "value")
        self._wire_block(self.block)
        title = title_html(
            "Tiles: accept or reject whole blocks, test pixels only where an edge passes",
            "Level by level, or block by block in a traversal order.",
        )
        menus = control_row([labelled("block sizes", self.sizes),
                              labelled("traversal", self.traversal)])  # fmt: skip
        self.widget = widgets.VBox([title, menus, self.level, self.block, *info_widgets,
                                    self.display.widget, self.counters])  # fmt: skip
        self._ahead = None
        if self.backend == "ipympl":
            self.show_level()
        else:
            self.info.value = self._info_html()  # the picture is sent already (above)
        if self.backend != "ipympl":
            self._ahead = self.display.ahead(self.level, self)  # drawn while the kernel idles

    # -- state ----------------------------------------------------------------------------
    def _fill(self) -> None:
        self.fill = rasterize(self.tri, self.width, self.height, method="tiled",
                              block_sizes=self.sizes.value, trace=True)  # fmt: skip
        self.blocks = self.fill.trace.blocks
        self.order = self.blocks.visit_order(self.traversal.value)
        with self._holding():
            self.level.max = len(self.sizes.value) - 1
            # as an IntSlider does, a value beyond the new end moves to it
            self.level.value = min(self.level.value, self.level.max)
            self._block_range(len(self.blocks))
        self.counters.value = _counter_table(self.blocks.counters)

    def _block_range(self, n: int) -> None:
        # new block sizes renumber every block and the picture falls back to the level
        # view: the block slider starts again at 0 (it kept its number, "block 10" over
        # "level 0: 64×64 blocks"; review r45, lesson 10). A new block slider, not its max
        # changed in place: the page's slider (noUiSlider) kept its first range for the End
        # key, which stopped at 68 of 388 blocks after 16 / 4 -> 16 / 4 / 1 (issue 31;
        # renew_slider). Before the widget is shown, or with the same range, in place.
        if self.block.max == n or getattr(self, "widget", None) is None:
            self.block.value = 0
            self.block.max = n
            return
        self.block = renew_slider(self.block, self.widget, max=n, value=0, wire=self._wire_block)

    def _wire_block(self, slider) -> None:
        slider.observe(lambda _: None if self._quiet else self.show_block(), "value")

    def _draw_blocks(self) -> None:
        if self.artists is not None:
            for artist in self.artists:
                artist.remove()
        # the block slider shows blocks not classified yet, and the key is drawn once (below)
        self.artists = plot_blocks(self.ax, self.fill, traversal=self.traversal.value,
                                   unclassified=True, current=True, decided=True)  # fmt: skip
        # the whole image: new artists know no window, the Axes may still be zoomed
        self.artists.show_window(self.ax, self.width, self.height, None)
        # the key stays while the level slider shows every block classified: it says where
        # the white page appears (review r8, lesson 10 c23)
        renamed = {UNCLASSIFIED: STEPPED_UNCLASSIFIED, CURRENT_BLOCK: STEPPED_CURRENT}
        for text in self.artists.legend.get_texts():
            text.set_text(renamed.get(text.get_text(), text.get_text()))
        # a level or a block step changes which blocks show, nothing else: the pixel grid,
        # the ticks and the key stay in a cached background, what lies over the blocks (the
        # triangle, the frame) in a still layer (a full draw cost 4-5x more; issue 31: the
        # level slider dragged at 1.3 fps); the current block's outline moves too, over all
        coll, current, hatch = self.artists.blocks, self.artists.current, self.artists.decided
        moving = (coll, current, hatch)  # the blocks, their hatch and the outline change
        above = [a for a in self.ax.get_children() if all(a is not m for m in moving)
                 and a.get_zorder() >= coll.get_zorder()]  # fmt: skip
        self._blit = LayeredBlit(self.ax.figure, [(MOVING, [coll, hatch]), (STILL, above),
                                                  (MOVING, [current])])  # fmt: skip

    def _draw_figure(self) -> None:
        self._blit.draw()

    def _on_traversal(self, _change) -> None:
        # the same fill and blocks, visited in another order: the blocks' artist redrawn in
        # that order over the cached background (a new fill and artists cost 150 ms and
        # more, and a full draw of the background; issue 31: 126-177 ms in the page)
        self.order = self.blocks.visit_order(self.traversal.value)
        self.artists.set_order(self.blocks, self.order)
        with self._holding():  # block k is another block in another order: start again
            self.block.value = 0
        self.show_level()
        self._restart_ahead()

    def _on_refill(self, _change) -> None:
        self._fill()
        self._draw_blocks()
        self.show_level()
        self._restart_ahead()

    def _restart_ahead(self) -> None:
        # the pictures drawn ahead show the blocks before
        if self._ahead is not None:
            self._ahead.restart()

    # -- views ----------------------------------------------------------------------------
    def _on_level(self) -> None:
        # the level slider shows a whole level: the block slider goes back to 0, where the
        # picture is a level's (it kept "12" over "level 2: 1×1 blocks"; review r235 W1)
        with self._holding():
            self.block.value = 0
        self.show_level()

    def show_level(self, level: int | None = None) -> None:
        """Show the hierarchy down to block size ``block_sizes[level]``."""
        self.level.description = LEVEL_LABELS[True]
        self._compute_at(self.level.value if level is None else level)
        self._refresh()

    # what the pictures drawn ahead need (teachraster.widgets.ahead.FramesAhead)
    def _compute_at(self, level) -> None:
        level = int(round(level))
        self.shown = block_mask(self.blocks, level=level)
        self.decided = decided_mask(self.blocks, level)  # hatched: no test at this size
        self.pending = None  # every block of the level is classified
        self.current = None  # a whole level: no one block visited now
        c, size = self.blocks.counters, self.sizes.value[level]
        text = (
            f"level {level}: {size}×{size} blocks — {c.empty[level]} rejected, "
            f"{c.full[level]} accepted, {c.partial[level]} partial"
        )
        if level == len(self.sizes.value) - 1 and size == 1:
            text += f": each is a pixel test ({c.pixel_tests} in all)"
        elif level == len(self.sizes.value) - 1:
            text += f"; {c.pixel_tests} pixel tests in the partial ones"
        self.caption_text = text

    def _set_artists(self) -> None:
        self.artists.show(self.shown, self.pending, self.decided)
        window = self._window()
        if window != self.artists.window:
            # limits, ticks and the zoomed block's pixel grid: the cached background and the
            # still layer show the old window
            self.artists.show_window(self.ax, self.width, self.height, window)
            self._blit.invalidate()
        self.artists.show_current(self.blocks, self.current)

    def zoom_block(self) -> int | None:
        """The top-level block the picture is zoomed on (its index), or None: the whole
        image. Zoomed while the block slider visits a block of :data:`ZOOM_AT` px or less."""
        b = self.blocks
        if self.current is None or int(b.size[self.current]) > ZOOM_AT:
            return None
        top = int(self.current)
        while b.parent[top] >= 0:
            top = int(b.parent[top])
        return top

    def _window(self) -> tuple[int, int, int, int] | None:
        """(col, row, width, height) of the pixels the picture is zoomed on, or None."""
        top = self.zoom_block()
        if top is None:
            return None
        b = self.blocks
        x0, y0, size = int(b.col[top]), int(b.row[top]), int(b.size[top])
        return x0, y0, min(size, self.width - x0), min(size, self.height - y0)

    def _info_html(self) -> str:
        return html_escape(self.caption_text)

    def show_block(self, k: int | None = None) -> None:
        """Show the first ``k`` blocks of the traversal (0: none yet), captioning the last."""
        k = self.block.value if k is None else int(k)
        self.shown = block_mask(self.blocks, upto=k - 1, traversal=self.traversal.value)
        self.decided = None  # the walk shows the blocks it tested, one by one
        # a visited partial block's children the walk has not reached: not its orange
        self.pending = pending_children(self.blocks, self.shown)
        # the block visited now, outlined (review r11, lesson 10: where is the walk?)
        self.current = int(self.order[k - 1]) if k > 0 and len(self.order) else None
        self.level.description = LEVEL_LABELS[False]  # the picture is no level's
        n = len(self.blocks)
        if not n:
            self.caption_text = "no block to classify (no pixel centre in the box, or zero area)"
        elif k == 0:
            self.caption_text = (
                f"{n} blocks will be classified, depth first, siblings in "
                f"{self.traversal.value} order: move the block slider"
            )
        else:
            b = int(self.order[k - 1])
            caption = self.blocks.caption(b, self.fill.trace.edges)
            top, zoom = self.zoom_block(), ""
            if top is not None:
                size = int(self.blocks.size[top])
                zoom = f" (picture zoomed on its {size}×{size} block)"
            self.caption_text = f"block {k} of {n}{zoom}: {caption}"
        self._refresh()

    def _refresh(self) -> None:
        self._set_artists()
        self.info.value = self._info_html()
        self.display.refresh()

    def _offline_page_(self):
        # every block of the traversal, not the few levels the page draws ahead
        from .offline import swept_page

        return swept_page(self)

    def _repr_mimebundle_(self, **kwargs):
        return self.widget._repr_mimebundle_(**kwargs)

    # a saved notebook reopened without a kernel shows its last picture, not "model not found"
    _ipython_display_ = Shown._ipython_display_

    def close(self) -> None:
        """Close every widget of the explorer (depth first)."""
        self.display.close()
        stack = [self.widget]
        while stack:
            widget = stack.pop()
            stack.extend(getattr(widget, "children", ()))
            widget.close()


def _fit_margins(fig, ax, pad: float = 0.12) -> None:
    """Shrink ``fig`` to the Axes, its tick labels and its legend, ``pad`` inches around.

    :func:`~.common.fill_axes` leaves room for a FillView's header and colour key; the
    explorer has neither (its caption is HTML), and the fixed margins left a wide empty band
    right of the key. Measured once: the key is the same for every size and traversal.
    """
    renderer = fig.canvas.get_renderer()
    dpi = fig.dpi
    fw, fh = fig.get_size_inches()
    box = ax.get_position()  # figure fraction
    tight = ax.get_tightbbox(renderer)  # pixels: the Axes with its labels and the legend
    left = box.x0 * fw - tight.x0 / dpi + pad  # inches outside the Axes on each side
    right = tight.x1 / dpi - box.x1 * fw + pad
    bottom = box.y0 * fh - tight.y0 / dpi + pad
    top = tight.y1 / dpi - box.y1 * fh + pad
    aw, ah = box.width * fw, box.height * fh
    nw, nh = left + aw + right, bottom + ah + top
    fig.set_size_inches(nw, nh)
    ax.set_position((left / nw, bottom / nh, aw / nw, ah / nh))


#: Cell padding and right-aligned numbers: without them "16×16 4 1 11" read as "16×164"
#: (review r62, lesson 10 #4).
_CELL = 'style="padding:1px 10px;text-align:{}"'


def _counter_table(counters) -> str:
    num, lab_ = _CELL.format("right"), _CELL.format("left")
    rows = "".join(
        f"<tr><td {lab_}>{lab}</td><td {num}>{e:,}</td><td {num}>{f:,}</td>"
        f"<td {num}>{p:,}</td></tr>"
        for lab, e, f, p in counters.table()
    )
    heads = "".join(f"<th {num}>{h}</th>" for h in ("rejected", "accepted", "partial"))
    return (
        f"<table><tr><th {lab_}>block</th>{heads}</tr>"
        f"{rows}</table>"
        f"pixel tests run: <b>{counters.pixel_tests:,}</b> · pixels filled with no test: "
        f"<b>{counters.pixels_accepted:,}</b>"
    )
