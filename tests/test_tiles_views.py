"""Plots and the widget of the tiled fill: what they draw matches the trace, in place."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.colors import to_rgba  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster import plotting as tp  # noqa: E402
from teachraster.core.traversal import TRAVERSALS, visit_index  # noqa: E402
from teachraster.plotting.tiles import UNCLASSIFIED, has_unclassified  # noqa: E402
from teachraster.widgets import TileExplorer  # noqa: E402
from teachraster.widgets.tiles import SIZE_OPTIONS  # noqa: E402

XY = [[3.3, 2.1], [60.2, 14.7], [20.9, 58.4]]


@pytest.fixture
def fill():
    return tr.rasterize(tr.Triangle(XY), 64, 64, method="tiled", block_sizes=(16, 4, 1), trace=True)


@pytest.fixture
def ax():
    fig, ax = plt.subplots()
    yield ax
    plt.close(fig)


def visible(artists):
    return artists.blocks.get_facecolor()[:, 3] > 0


def test_plot_blocks_colours_every_block_by_kind(fill, ax):
    blocks = fill.trace.blocks
    art = tp.plot_blocks(ax, fill)
    assert len(art.blocks.get_paths()) == len(blocks)
    faces = art.blocks.get_facecolor()
    for i, b in enumerate(art.order):
        # opaque: a child over its partial parent shows its own colour, never a mixture
        want = to_rgba(tp.BLOCK_COLORS[blocks.kind[b]], 1.0)
        np.testing.assert_allclose(faces[i], want)
        verts = art.blocks.get_paths()[i].vertices
        assert verts[:, 0].min() == blocks.col[b] and verts[:, 1].min() == blocks.row[b]
        assert verts[:, 0].max() - verts[:, 0].min() == blocks.extent[b, 1]


def test_plot_blocks_levels_and_steps_update_in_place(fill, ax):
    blocks = fill.trace.blocks
    art = tp.plot_blocks(ax, fill, level=0)
    coll = art.blocks
    assert visible(art).sum() == (blocks.level == 0).sum()
    for lev in range(3):
        art.show(tp.block_mask(blocks, level=lev))
        assert art.blocks is coll
        shown = blocks.level[art.order][visible(art)]
        assert (shown <= lev).all() and (shown == lev).sum() == (blocks.level == lev).sum()
    art.show(tp.block_mask(blocks, upto=9, traversal="morton"))
    assert visible(art).sum() == 10
    assert set(art.order[visible(art)]) == set(blocks.visit_order("morton")[:10].tolist())


def test_key_lists_the_unclassified_page_only_where_a_picture_shows_it(fill, ax):
    blocks = fill.trace.blocks

    def keyed(art):
        return [t.get_text() for t in art.legend.get_texts()]

    # every level tiles the bounding box's blocks: nothing is left unclassified
    for lev in range(3):
        assert not has_unclassified(blocks, tp.block_mask(blocks, level=lev))
        art = tp.plot_blocks(ax, fill, level=lev)
        assert UNCLASSIFIED not in keyed(art) and "partial" in keyed(art)
        art.legend.remove()
    # the first blocks of a walk leave the rest of the box white: the key says what it is
    assert has_unclassified(blocks, tp.block_mask(blocks, upto=0))
    art = tp.plot_blocks(ax, fill, upto=0)
    assert UNCLASSIFIED in keyed(art)
    art.legend.remove()
    # only the top level's rejected and accepted blocks: the partial ones' area is white
    top_only = tp.block_mask(blocks, level=0) & (blocks.kind_code != 2)
    assert (blocks.kind_code[blocks.level == 0] == 2).any()
    assert has_unclassified(blocks, top_only)
    assert UNCLASSIFIED in keyed(tp.plot_blocks(ax, fill, unclassified=True, level=2))


def test_explorer_key_keeps_the_unclassified_page_for_its_block_slider(explorer):
    # review r8 (lesson 10 c23): the entry says where the white page shows (the level
    # slider classifies every block it shows)
    from teachraster.widgets.tiles import STEPPED_UNCLASSIFIED

    keyed = [t.get_text() for t in explorer.artists.legend.get_texts()]
    assert STEPPED_UNCLASSIFIED in keyed and UNCLASSIFIED not in keyed
    assert "block slider" in STEPPED_UNCLASSIFIED and explorer.block.description == "block"


def test_hierarchy_and_counters(fill):
    fig, axes = plt.subplots(1, 4)
    try:
        arts = tp.plot_hierarchy(axes[:3], fill)
        c = fill.trace.blocks.counters
        assert len(arts) == 3
        for lev, a in enumerate(axes[:3]):
            assert f"{c.empty[lev]} rejected, {c.full[lev]} accepted" in a.get_title()
        table = tp.plot_block_counters(axes[3], fill).table
        cells = {k: v.get_text().get_text() for k, v in table.get_celld().items()}
        for r, (lab, e, f, p) in enumerate(c.table(), start=1):
            assert [cells[(r, j)] for j in range(4)] == [lab, str(e), str(f), str(p)]
        with pytest.raises(ValueError, match="Axes"):
            tp.plot_hierarchy(axes[:2], fill)
    finally:
        plt.close(fig)


@pytest.mark.parametrize("traversal", TRAVERSALS)
def test_plot_traversal_shows_the_visit_index(ax, traversal):
    art = tp.plot_traversal(ax, 8, 6, traversal)
    np.testing.assert_array_equal(np.asarray(art.image.get_array()).reshape(6, 8),
                                  visit_index((6, 8), traversal))  # fmt: skip
    assert len(art.texts) == 48


def test_plots_refuse_other_fills(ax):
    half = tr.rasterize(tr.Triangle(XY), 64, 64, trace=True)
    with pytest.raises(ValueError, match="tiled"):
        tp.plot_blocks(ax, half)
    with pytest.raises(ValueError, match="trace"):
        tp.plot_blocks(ax, tr.rasterize(tr.Triangle(XY), 64, 64, method="tiled"))


# -- widget -------------------------------------------------------------------------------------
@pytest.fixture
def explorer():
    ex = TileExplorer(tr.Triangle(XY), 64, 64, block_sizes=(16, 4, 1), backend="image")
    yield ex
    ex.close()


def test_level_slider_walks_the_hierarchy(explorer):
    blocks = explorer.blocks
    pngs = set()
    for lev in range(3):
        explorer.level.value = lev
        np.testing.assert_array_equal(explorer.shown, tp.block_mask(blocks, level=lev))
        np.testing.assert_array_equal(
            visible(explorer.artists), explorer.shown[explorer.artists.order]
        )
        assert f"level {lev}" in explorer.caption_text
        pngs.add(bytes(explorer.display.widget._last))  # the picture sent to the page
    assert len(pngs) == 3


def test_block_slider_follows_the_traversal(explorer):
    explorer.traversal.value = "serpentine"
    order = explorer.blocks.visit_order("serpentine")
    assert explorer.block.max == len(order)
    for k in (1, 5, len(order), 0):
        explorer.block.value = k
        assert explorer.shown.sum() == k
        if k:
            assert explorer.caption_text.endswith(
                explorer.blocks.caption(int(order[k - 1]), explorer.fill.trace.edges)
            )
    assert "serpentine order" in explorer.caption_text


def vermillion_box(explorer):
    """(x0, x1, y0, y1) in picture pixels (rows from the top) of the vermillion drawn on the
    grid in the picture the explorer sent to the page (not the key), or None."""
    rgba = np.asarray(explorer.display.widget._last)[..., :3].astype(int)
    target = (np.array(to_rgba(tp.COLORS["current"])[:3]) * 255).round().astype(int)
    near = np.abs(rgba - target).sum(axis=-1) < 30
    near[:, int(explorer.ax.bbox.x1) + 2 :] = False  # the key, right of the grid
    rows, cols = np.nonzero(near)
    return None if not len(rows) else (cols.min(), cols.max(), rows.min(), rows.max())


def test_the_block_visited_now_is_outlined_in_the_picture(explorer):
    """Review r9/r10/r11 (lesson 10, 10-4): nothing showed where the block walk was. The
    block slider outlines the block visited now in the picture sent to the page (blitted:
    the same pixels as a full draw), around the block's place; the level slider shows no
    outline, and the key names the outline."""
    blocks, order = explorer.blocks, explorer.blocks.visit_order("scanline")
    height = np.asarray(explorer.display.widget._last).shape[0]
    for k in (200, 40):  # a 4×4 block (outline), a 1×1 block (outline and ticks)
        explorer.block.value = k
        b = int(order[k - 1])
        r, c, (h, w) = blocks.row[b], blocks.col[b], blocks.extent[b]
        box = vermillion_box(explorer)
        assert box is not None, k
        # the block's corners on the picture: the outline lies on them (ticks reach beyond)
        to_px = explorer.ax.transData.transform
        (x0, y1), (x1, y0) = to_px((c, r)), to_px((c + w, r + h))
        y0, y1 = height - y0, height - y1  # picture rows run down
        assert box[0] <= x0 + 3 and box[1] >= x1 - 3 and box[2] <= y1 + 3 and box[3] >= y0 - 3
        span = 4 * (x1 - x0) + 60 if h < 4 else (x1 - x0) + 12
        assert box[1] - box[0] <= span and box[3] - box[2] <= span, (k, box)
        blitted = np.asarray(explorer.display.widget._last).copy()
        explorer.fig.canvas.draw()
        full = np.asarray(explorer.fig.canvas.buffer_rgba())
        assert (np.abs(blitted.astype(int) - full).max(axis=-1) > 8).sum() < 20
    explorer.level.value = 1
    assert vermillion_box(explorer) is None
    from teachraster.widgets.tiles import STEPPED_CURRENT

    assert STEPPED_CURRENT in [t.get_text() for t in explorer.artists.legend.get_texts()]


def test_a_one_pixel_block_is_pointed_at_not_crossed_out():
    """Review r12 (lesson 10): around a 1×1 block the four ticks joined the thick outline
    into a cross ("the 1×1 ticks read as a bracket"). They stop a pixel short of the block,
    and in the lesson's classroom style outline and ticks are about half as thick as around a
    larger block."""
    import matplotlib as mpl

    from teachraster.plotting import use_style

    # the whole image (the explorer zooms on such a block instead: the test below)
    with mpl.rc_context():
        use_style("classroom")
        fig, ax = plt.subplots()
        fill = tr.rasterize(tr.Triangle(XY), 64, 64, method="tiled", block_sizes=(16, 4, 1),
                            trace=True)  # fmt: skip
        tp.plot_pixel_grid(ax, 64, 64)
        artists = tp.plot_blocks(ax, fill, current=True)
    blocks = fill.trace.blocks
    order = blocks.visit_order("scanline")
    sizes = blocks.size[order]
    artists.show_current(blocks, int(order[np.flatnonzero(sizes == 4)[0]]))
    wide = artists.current.get_linewidth()
    b = int(order[np.flatnonzero(sizes == 1)[0]])
    artists.show_current(blocks, b)
    line = artists.current
    assert line.get_linewidth() <= 0.6 * wide
    r, c = int(blocks.row[b]), int(blocks.col[b])
    x, y = (np.asarray(v, float)[6:] for v in line.get_data())  # past the outline and a NaN
    outside = np.maximum(np.maximum(c - x, x - (c + 1)), np.maximum(r - y, y - (r + 1)))
    assert np.isfinite(outside).sum() == 8 and np.nanmin(outside) >= 1.0
    plt.close(fig)


def test_a_zoomed_block_is_outlined_alone_over_its_pixel_grid(explorer):
    """Review r62 (lesson 10 #1): zoomed on a 16×16 block, the ticks pointing at a 1×1 block
    (lengths in image pixels) became crosses reaching 4 px past it, off the axes over the
    tick labels at block 3, and the opaque blocks hid the pixel grid. Zoomed, the outline is
    the block's own extent, inside the view, and the zoomed block's grid lies over the
    blocks (below the triangle); the whole image hides that grid again."""
    blocks, order = explorer.blocks, explorer.order
    ones = [k for k in range(1, len(order) + 1) if blocks.size[order[k - 1]] == 1]
    for k in (ones[0], ones[5]):  # the first lies in row 0, col 0: on the frame
        explorer.block.value = k
        b = int(order[k - 1])
        r, c = int(blocks.row[b]), int(blocks.col[b])
        x, y = (np.asarray(v, float) for v in explorer.artists.current.get_data())
        assert np.isfinite(x).all() and np.isfinite(y).all()  # one piece: no ticks
        assert (x.min(), x.max(), y.min(), y.max()) == (c, c + 1, r, r + 1)
        (x0, x1), (y1, y0) = explorer.ax.get_xlim(), explorer.ax.get_ylim()
        assert x0 <= x.min() and x.max() <= x1 and y0 <= y.min() and y.max() <= y1
        assert not explorer.artists.current.get_clip_on()  # whole on the frame's edge too
        grid = explorer.artists.window_grid
        top = explorer.zoom_block()
        tc, tr_, size = int(blocks.col[top]), int(blocks.row[top]), int(blocks.size[top])
        segments = np.asarray(grid.get_segments())
        assert grid.get_visible() and len(segments) == 2 * (size + 1)
        assert segments[..., 0].min() == tc and segments[..., 0].max() == tc + size
        assert segments[..., 1].min() == tr_ and segments[..., 1].max() == tr_ + size
        assert blocks_zorder(explorer) < grid.get_zorder() < 3  # over blocks, under the edges
        ticks = explorer.ax.get_xticks()
        assert ticks.min() >= tc and ticks.max() <= tc + size  # the zoomed block's pixels
    explorer.block.value = len(order)  # a 16×16 block: the whole image, no window grid
    assert not explorer.artists.window_grid.get_visible()
    assert explorer.ax.get_xlim() == (0, explorer.width)


def blocks_zorder(explorer):
    return explorer.artists.blocks.get_zorder()


def test_captions_print_edge_values_in_full_with_thousands_separators(fill):
    """Review r12 (lesson 10's TileExplorer): a block's caption printed "E12 = 1.2e+03" where
    the course prints every count in full ("1,184"). The blocks' captions and the half-plane
    fill's pixel steps (one rule for both) print large values as 1,200, never bare or in
    exponent notation."""
    import re

    blocks, edges = fill.trace.blocks, fill.trace.edges
    captions = [blocks.caption(b, edges) for b in range(len(blocks))]
    half = tr.rasterize(tr.Triangle(XY), 64, 64, method="halfplane", trace=True).trace
    captions += [half.caption(k) for k in range(len(half))]
    text = "\n".join(captions)
    assert not re.findall(r"\de[+-]\d", text)  # no exponent notation
    assert not re.findall(r"(?<![\d.,^*/])\d{4,}(?![\d.])", text)
    assert re.search(r"E\d\d = -?\d{1,3}(,\d{3})+ ", text)  # values of 1,000 and more


def test_block_sizes_menu_refills(explorer):
    before = explorer.blocks.counters
    explorer.sizes.value = (8, 2)
    assert explorer.blocks.block_sizes == (8, 2) and explorer.level.max == 1
    assert explorer.blocks.counters != before
    assert len(explorer.artists.blocks.get_paths()) == len(explorer.blocks)
    assert "pixel tests run" in explorer.counters.value


def test_block_sizes_menu_puts_in_a_new_block_slider(explorer):
    """Issue 31: a block slider whose max changed in place kept its first range for the
    page's End key (noUiSlider), which stopped at 68 of 388 blocks. A new slider takes the old
    one's place in the widget, with its settings and its observer, at 0 (the new sizes
    renumber the blocks: review r45)."""
    first = explorer.block
    first.value = 3
    before = first.max
    other = next(v for _, v in SIZE_OPTIONS if v != explorer.sizes.value)
    explorer.sizes.value = other
    block = explorer.block
    assert block.max == len(explorer.blocks) != before
    assert block is not first and block in explorer.widget.children
    assert first not in explorer.widget.children and first.comm is None  # closed
    assert block.value == 0 and block.layout is first.layout and block.description == "block"
    block.value = 2  # the new slider drives the picture and the caption
    assert explorer.caption_text.startswith(f"block 2 of {block.max}:")
    explorer.traversal.value = next(t for t in TRAVERSALS if t != explorer.traversal.value)
    assert explorer.block is block  # the same blocks, the same slider


@pytest.mark.parametrize("sizes", [(64, 16, 4), (16, 4, 1)])  # a new range, the same range
def test_new_block_sizes_or_traversal_start_the_block_slider_again(explorer, sizes):
    """Review r45 (lesson 10, fresh Run All): block slider at 10, then the preset "64 / 16 / 4":
    the readout stayed at 10 while the caption and the picture fell back to "level 0: 64×64
    blocks", and one step on gave "block 11 of 193". New sizes (or a new order) renumber the
    blocks: the slider starts again at 0, and its next step is block 1."""
    explorer.block.value = 10
    assert explorer.caption_text.startswith("block 10 of 864")
    if sizes == explorer.sizes.value:  # the same range: the traversal renumbers instead
        explorer.traversal.value = "morton"
    else:
        explorer.sizes.value = sizes
    n = len(explorer.blocks)
    assert explorer.block.value == 0 and explorer.block.max == n
    assert explorer.caption_text.startswith(f"level 0: {sizes[0]}×{sizes[0]} blocks")
    assert explorer.current is None
    explorer.block.value = 1  # the next step: the walk's first block, of the new count
    assert explorer.caption_text.startswith(f"block 1 of {n}:")
    assert explorer.shown.sum() == 1


def test_renew_slider_refuses_a_box_without_the_slider():
    import ipywidgets as widgets

    from teachraster.widgets.common import renew_slider

    slider = widgets.IntSlider(value=5, min=0, max=10)
    with pytest.raises(ValueError, match="box"):
        renew_slider(slider, widgets.VBox([]), max=20)
    box = widgets.VBox([widgets.Label("x"), slider])
    new = renew_slider(slider, box, max=3)
    assert new.value == 3 and new.max == 3 and box.children[1] is new


def test_degenerate_triangle_never_raises():
    ex = TileExplorer(tr.Triangle([[1, 1], [5, 5], [9, 9]]), 16, 16, backend="image")
    try:
        ex.show_block(0)
        assert "no block" in ex.caption_text
        ex.level.value = 2
    finally:
        ex.close()


def test_plot_early_z_counts_per_pixel(ax):
    from teachraster.pipeline.scenes import get_scene

    clip = get_scene("cube").clip(80 / 60)
    frame = tr.render(clip, 80, 60, trace=True)
    c = frame.trace.hiz.counts
    totals = {k: int(tp.early_z_counts(frame, k).sum()) for k in ("hi_z", "early_z", "shaded")}
    assert totals == {
        "hi_z": c["hiz_rejected"],
        "early_z": c["early_z_killed"],
        "shaded": c["shaded"],
    }
    art = tp.plot_early_z(ax, frame, "shaded")
    assert f"{c['shaded']:,} fragments shaded" in ax.get_title()
    assert art.colorbar is not None
    forced = tr.render(get_scene("cube").clip(4 / 3), 160, 120, trace=True, force="hi_z")
    dropped = tp.early_z_counts(forced, "dropped")
    assert dropped.sum() == forced.plan["hi_z"].count > 0
    tp.plot_early_z(ax, forced, "dropped")
    assert "dropped by render's Hi-Z" in ax.get_title()
    with pytest.raises(ValueError, match="trace=True"):
        tp.early_z_counts(tr.render(clip, 80, 60))
    with pytest.raises(ValueError, match="kind"):
        tp.early_z_counts(frame, "late_z")


def test_fill_player_steps_through_blocks():
    from teachraster.widgets import FillPlayer

    player = FillPlayer(tr.Triangle(XY), 64, 64, method="tiled", backend="image")
    try:
        trace = player.trace
        assert trace.blocks is not None
        k = trace.first_work_step + 2
        player.slider.value = k
        assert player.caption_text == trace.caption(k) and "block" in player.caption_text
        np.testing.assert_array_equal(
            np.asarray(player.view.coverage.image.get_array()).astype(bool), trace.coverage_at(k)
        )
        player.method.value = "span"
        assert player.trace.span is not None
    finally:
        player.close()


def test_cli_fill_with_tiles(tmp_path):
    from teachraster.cli import main

    out = tmp_path / "tiles.png"
    assert (
        main(["fill", "--xy", "2.2,1.5 13.7,5.2 5.1,12.8", "--method", "tiled", "-o", str(out)])
        == 0
    )
    assert out.read_bytes().startswith(b"\x89PNG")


@pytest.mark.parametrize("traversal", TRAVERSALS)
def test_plot_block_path_follows_the_visit_order(fill, ax, traversal):
    blocks = fill.trace.blocks
    art = tp.plot_block_path(ax, fill, traversal, level=1)
    order = blocks.visit_order(traversal)
    order = order[blocks.level[order] == 1]
    x, y = art.path.get_data()
    np.testing.assert_array_equal(x, blocks.col[order] + blocks.extent[order, 1] / 2)
    np.testing.assert_array_equal(y, blocks.row[order] + blocks.extent[order, 0] / 2)
    assert f"{len(order)} blocks of 4×4" in ax.get_title()


def test_fill_player_tiles_with_several_samples_shows_one_and_says_so():
    """Tiles fill pixel centres only: choosing them with a multi-sample pattern (either
    order) shows the one-sample tile fill with a note, never a kernel error with the
    controls naming a fill that is not on show."""
    from teachraster.widgets import FillPlayer
    from teachraster.widgets.player import TILES_NOTE

    player = FillPlayer(tr.Triangle(XY), 24, 24, backend="image")
    try:
        player.samples.value = "4 standard (rotated grid)"
        assert player.fill.sample_coverage is not None and player.samples_note.value == ""
        player.method.value = "tiled"  # raised ValueError in the observer before
        assert player.trace.method == "tiled" and player.fill.sample_coverage is None
        assert player.samples_note.value == TILES_NOTE
        assert player.frames.fill == "tiled|perspective|1 (centre)"
        player.samples.value = "16 random"  # the other order
        assert player.trace.method == "tiled" and player.samples_note.value == TILES_NOTE
        player.method.value = "halfplane"  # back to a method with samples: the menu's 16
        assert player.fill.sample_coverage.shape[-1] == 16 and player.samples_note.value == ""
        player.samples.value = "1 (centre)"
        player.method.value = "tiled"
        assert player.samples_note.value == ""  # one sample asked, one shown: nothing to say
    finally:
        player.close()
    with_menu = FillPlayer(tr.Triangle(XY), 24, 24, method="tiled", samples="2 standard",
                           backend="image")  # fmt: skip
    assert with_menu.trace.method == "tiled" and with_menu.samples_note.value == TILES_NOTE
    with_menu.close()


def test_a_block_that_is_the_whole_image_says_so():
    """Review r20 (lesson 00's player, tiles): on a 16 × 16 image the 64×64 and 16×16 blocks
    at (0, 0) are the whole image, outlined on its frame, and the steps seemed to change
    nothing. Their captions say so; a smaller block, or one that leaves part of the image
    out, does not."""
    tri = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]])
    trace = tr.rasterize(tri, 16, 16, method="tiled", trace=True).trace
    blocks = [trace.step(k) for k in range(len(trace)) if trace.step(k).kind == "block"]
    whole = [s for s in blocks if s.extent == (16, 16)]
    assert len(whole) == 2  # the 64×64 block and the 16×16 one
    assert all("(the whole image, outlined by its frame)" in s.caption for s in whole)
    assert not any("whole image" in s.caption for s in blocks if s.extent != (16, 16))
    wide = tr.rasterize(tri, 20, 16, method="tiled", trace=True).trace  # 16 rows, 20 columns
    said = [wide.step(k).extent for k in range(len(wide)) if "whole image" in wide.caption(k)]
    assert said == [(16, 20)]  # the 64×64 block only: the 16×16 one leaves 4 columns out


def test_level_slider_label_says_when_it_does_not_show_its_level():
    """Review r52, lesson 10: with a 1×1 block shown the slider still read "level 0"; while
    the block slider shows the picture, the level slider is labelled as where moving it goes
    ("show level"), and "level" again once it shows its level."""
    from teachraster.widgets.tiles import LEVEL_LABELS

    ex = TileExplorer(tr.Triangle([[2.2, 3.1], [25.6, 8.3], [9.4, 27.7]]), 32, 32,
                      backend="image")  # fmt: skip
    try:
        assert ex.level.description == LEVEL_LABELS[True] == "level"
        last = len(ex.blocks.block_sizes) - 1
        ex.block.value = 1 + int(np.flatnonzero(ex.blocks.level[ex.order] == last)[0])
        assert ex.caption_text.startswith(f"block {ex.block.value} of ")
        assert "1×1 block" in ex.caption_text and ex.level.value == 0
        assert ex.level.description == LEVEL_LABELS[False] == "show level"
        ex.level.value = 1
        assert ex.level.description == "level" and ex.caption_text.startswith("level 1:")
        assert ex.block.value == 0  # review r235 W1: the block readout follows the level
        ex.block.value = 1
        ex.block.value = 0  # the block slider's start: no level's picture either
        assert ex.level.description == "show level"
        ex.traversal.value = "morton"  # back to the level view
        assert ex.level.description == "level"
    finally:
        ex.close()


def test_block_slider_zooms_on_small_blocks(explorer):
    """Reviews r45 #7, r52 #10: a 1×1 block of the 64 × 64 grid was a ~6 px square; the
    picture zooms on its top-level block while the block slider visits it, and the level
    slider shows the whole image again."""
    from teachraster.widgets.tiles import ZOOM_AT

    blocks, order = explorer.blocks, explorer.order
    small = next(k for k in range(1, len(order) + 1) if blocks.size[order[k - 1]] <= ZOOM_AT)
    explorer.block.value = small
    top = explorer.zoom_block()
    assert top is not None and blocks.parent[top] == -1
    # exactly the block (review r70, lesson 10 #1: half a pixel of the neighbours showed)
    c, r, size = int(blocks.col[top]), int(blocks.row[top]), int(blocks.size[top])
    assert explorer.ax.get_xlim() == (c, c + size) and explorer.ax.get_ylim() == (r + size, r)
    assert "zoomed on its" in explorer.caption_text
    explorer.block.value = 1  # a top-level block: the whole image
    assert explorer.zoom_block() is None and explorer.ax.get_xlim() == (0, explorer.width)
    explorer.block.value = small
    explorer.level.value = 1
    assert explorer.ax.get_xlim() == (0, explorer.width)


def test_unvisited_children_of_a_partial_block_are_not_its_orange(explorer):
    """Review r70 (lesson 10 #2): on the block slider, the 4×4 children of the current 16×16
    block that the walk has not reached were painted the parent's "partial" orange. They are
    drawn in the key's paler "not visited yet" style until visited; the level slider, where
    every block of the level is classified, has none."""
    from matplotlib.colors import to_rgba

    from teachraster.plotting.style import COLORS
    from teachraster.plotting.tiles import BLOCK_COLORS, PENDING

    blocks, order = explorer.blocks, explorer.order
    first = next(k for k in range(1, len(order) + 1) if blocks.parent[order[k - 1]] >= 0)
    explorer.block.value = first  # the first child of the first partial 16×16 block
    parent = int(blocks.parent[order[first - 1]])
    waiting = np.flatnonzero((blocks.parent == parent) & ~explorer.shown)
    assert len(waiting) >= 1 and explorer.pending[waiting].all()
    shown_parents = np.flatnonzero(explorer.shown)
    under = np.isin(blocks.parent, shown_parents) & ~explorer.shown  # and the 1×1 under child
    assert np.array_equal(explorer.pending, under) and under.sum() > len(waiting)
    face = dict(zip(explorer.artists.order.tolist(), explorer.artists.blocks.get_facecolor()))
    orange = np.array(to_rgba(BLOCK_COLORS["partial"]))
    for b in waiting:
        assert face[int(b)][3] == 1 and not np.allclose(face[int(b)], orange)
    edge = dict(zip(explorer.artists.order.tolist(), explorer.artists.blocks.get_edgecolor()))
    assert np.allclose(edge[int(waiting[0])], to_rgba(COLORS["grid"]))
    assert np.allclose(face[parent], orange)  # the parent itself stays partial
    keyed = [t.get_text() for t in explorer.artists.legend.get_texts()]
    assert PENDING in keyed
    explorer.block.value = first + 1  # the next child, visited now: its own colour
    b = int(order[first])
    assert not explorer.pending[b]
    explorer.level.value = 1  # a whole level: nothing pending
    assert explorer.pending is None


def test_walk_path_splits_steps_from_jumps(fill, ax):
    """Review r176 10-4: the path through one level's blocks, steps solid, jumps dashed, both
    ends marked; every visit of the level is on it."""
    art = tp.plot_walk_path(ax, fill, "morton", level=-1)
    blocks = fill.trace.blocks
    n = int((blocks.level == len(blocks.block_sizes) - 1).sum())
    assert art.blocks == n == len(art.steps.get_segments()) + len(art.jumps.get_segments()) + 1
    assert len(art.jumps.get_segments()) > 0 and len(art.handles) == len(art.labels) == 3


def test_early_z_panels_draw_the_hi_z_tiles_and_say_the_key():
    """Review r176 10-5: the Hi-Z panel draws the GPU's tiles; the key says what a colour
    counts in words (not "as titled")."""
    clip = np.array([[[-1, -1, 0.4, 1], [1, -1, 0.4, 1], [0, 1, 0.4, 1]],
                     [[-1, -1, -0.4, 1], [1, -1, -0.4, 1], [0, 1, -0.4, 1]]], float)  # fmt: skip
    frame = tr.render(clip, 48, 32, trace=True)
    fig, axes = plt.subplots(1, 3)
    try:
        key = tp.plot_early_z_panels(axes, frame)
        labels = [t.get_text() for t in key.get_texts()]
        assert any("1 fragment in the pixel" in t for t in labels)
        assert any(f"{frame.trace.hiz.tile}×{frame.trace.hiz.tile} tiles" in t for t in labels)
        assert not any("as titled" in t for t in labels)
        lines = [[c for c in a.collections if type(c).__name__ == "LineCollection"] for a in axes]
        grids = lines[0]
        assert grids and not lines[1]  # the tiles on the Hi-Z panel only
        assert len(grids[-1].get_segments()) == 48 // 8 + 1 + 32 // 8 + 1
    finally:
        plt.close(fig)


def test_levels_hatch_what_a_larger_block_decided(fill, ax):
    """Review r235 FIG1: at the 1×1 level the pixels an accepted 4×4 block filled (no test)
    were the same green as the pixels tested. A level's view hatches the blocks a larger block
    decided, the blocks classified at its own size stay solid; no level, no hatch."""
    blocks = fill.trace.blocks
    art = tp.plot_blocks(ax, fill, level=2, decided=True)
    want = tp.decided_mask(blocks, 2)
    assert want.sum() > 0 and not (want & (blocks.level == 2)).any()
    assert not (want & (blocks.kind_code == 2)).any()  # a partial block is split, not decided
    assert len(art.decided.get_paths()) == int(want.sum())
    for path, b in zip(art.decided.get_paths(), art.order[want[art.order]]):
        assert (
            path.vertices[:, 0].min() == blocks.col[b]
            and path.vertices[:, 1].min() == blocks.row[b]
        )
    art.show(tp.block_mask(blocks, level=0), decided=tp.decided_mask(blocks, 0))
    assert len(art.decided.get_paths()) == 0 and not tp.decided_mask(blocks, None).any()
    assert tp.plot_blocks(ax, fill, level=2).decided is None  # opt-in: the path figure has none


def test_llvmpipe_bins_refuse_an_unknown_kind(ax):
    with pytest.raises(ValueError, match="unknown tile kinds"):
        tp.plot_llvmpipe_bins(ax, np.array([["full", "half"]], dtype=object))


def test_plot_block_values_marks_the_corners_the_step_signs_pick(ax):
    """Review r247 M1 (lesson 10 §1): the corner trick drawn. The block's 64 values are written
    in their cells; the largest is outlined as the reject test's corner, the smallest as the
    accept test's, and they are the opposite corners the signs of the two steps pick."""
    from teachraster.plotting.tiles import CORNER_MARKS

    v1, v2 = np.array(XY[0]), np.array(XY[1])
    row0, col0, s = 16, 8, 8
    jj, ii = np.meshgrid(np.arange(col0, col0 + s) + 0.5, np.arange(row0, row0 + s) + 0.5)
    values = (v2[0] - v1[0]) * (ii - v1[1]) - (v2[1] - v1[1]) * (jj - v1[0])
    right, down = -(v2[1] - v1[1]), v2[0] - v1[0]
    art = tp.plot_block_values(ax, values, row0, col0, steps=(right, down))
    assert [t.get_text() for t in art.texts] == [f"{v:.0f}" for v in values.ravel()]
    corners = {which: (int(box.get_y()), int(box.get_x()))
               for (which, _, _), box in zip(CORNER_MARKS, art.corners)}  # fmt: skip
    pick = {True: s - 1, False: 0}
    assert corners["largest"] == (row0 + pick[down > 0], col0 + pick[right > 0])
    assert corners["smallest"] == (row0 + pick[down < 0], col0 + pick[right < 0])
    labels = " ".join(t.get_text() for t in art.labels)
    assert "largest E12: reject test" in labels and "smallest E12: accept test" in labels
    assert f"one step right: {right:+.1f}" in labels and f"one step down: {down:+.1f}" in labels
    assert len(art.arrows) == 2


def test_plot_block_values_can_write_only_the_corners_large(ax):
    """Review r255 FIG (lesson 10 §1): 64 four-digit values were about 7 pt on a projector.
    ``numbers="corners"`` writes the four corners only, larger: the two extremes in their
    labels, the other two in their cells; anything else is refused."""
    from teachraster.plotting.common import fs

    v1, v2 = np.array(XY[0]), np.array(XY[1])
    row0, col0, s = 16, 8, 8
    jj, ii = np.meshgrid(np.arange(col0, col0 + s) + 0.5, np.arange(row0, row0 + s) + 0.5)
    values = (v2[0] - v1[0]) * (ii - v1[1]) - (v2[1] - v1[1]) * (jj - v1[0])
    art = tp.plot_block_values(ax, values, row0, col0, numbers="corners")
    corners = {f"{values[i, j]:.0f}" for i in (0, s - 1) for j in (0, s - 1)}
    extremes = {f"{values.max():.0f}", f"{values.min():.0f}"}
    assert {t.get_text() for t in art.texts} == corners - extremes and len(art.texts) == 2
    assert all(t.get_fontsize() >= fs(0.7) for t in art.texts)
    labels = " ".join(t.get_text() for t in art.labels)
    assert f"largest E12 = {values.max():.0f}: reject test" in labels
    assert f"smallest E12 = {values.min():.0f}: accept test" in labels
    with pytest.raises(ValueError, match="numbers must be"):
        tp.plot_block_values(ax, values, row0, col0, numbers="some")


def test_traversal_menu_tells_tiled_from_morton_and_resets_the_block_slider(explorer):
    """Review r255 S4 (lesson 10 §6): the menu offered "tiled" and "morton" as two names for
    one path (siblings are tiled 2×2: on a 4×4 grid of siblings both visit alike); its labels
    now say what each is and where they coincide. They part on a larger grid (8 / 2's 8×8
    top level). A traversal change puts the block slider back to 0, and the docstring says so."""
    from teachraster.widgets.tiles import TRAVERSAL_LABELS, TileExplorer

    labels = dict((v, k) for k, v in explorer.traversal.options)
    assert labels == TRAVERSAL_LABELS and len(set(labels.values())) == 4
    assert "= tiled on 4×4 siblings" in labels["morton"] and "2×2 tiles" in labels["tiled"]
    blocks = explorer.blocks  # 16 / 4 / 1: every sibling grid is 4×4
    assert np.array_equal(blocks.visit_order("tiled"), blocks.visit_order("morton"))
    wide = tr.rasterize(tr.Triangle(XY), 64, 64, method="tiled", block_sizes=(8, 2), trace=True)
    b8 = wide.trace.blocks
    assert not np.array_equal(b8.visit_order("tiled"), b8.visit_order("morton"))
    explorer.block.value = 30
    explorer.traversal.value = "morton"
    assert explorer.block.value == 0 and explorer.traversal.label == TRAVERSAL_LABELS["morton"]
    assert "put the block\n    slider back to 0" in TileExplorer.__doc__
