"""The plotting layer: every plot returns its artists, the views update in place and agree
with the trace, the style switches and comes back, the error heatmap reports the true maximum."""

import matplotlib

matplotlib.use("Agg")

import itertools  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import warnings  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from conftest import sample  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster import plotting as tp  # noqa: E402
from teachraster.pipeline.scenes import get_scene  # noqa: E402

METHODS = ("span", "halfplane")
W = H = 16


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def make_fill(method="halfplane", xy=((1.3, 1.2), (14.6, 4.7), (5.2, 14.1)), size=(W, H), **kw):
    tri = tr.Triangle(
        xy, w=[1.0, 3.0, 6.0], z=[0.1, 0.5, 0.9], attrs={"u": [0.0, 1.0, 0.0], "rgb": np.eye(3)}
    )
    return tr.rasterize(tri, *size, method=method, trace=True, **kw)


# Awkward fills: culled, zero area, one row high, partly and wholly outside the image.
ODD = {
    "culled": dict(xy=((1, 1), (12, 2), (4, 13)), cull="back"),
    "zero_area": dict(xy=((1, 1), (5, 5), (9, 9))),
    "one_point": dict(xy=((3, 3), (3, 3), (3, 3))),
    "flat_top": dict(xy=((1, 2), (14, 2), (6, 13))),
    "thin": dict(xy=((0.2, 4.4), (15.7, 4.6), (8.0, 4.55))),
    "partly_outside": dict(xy=((-5, -3), (30, 4), (6, 25))),
    "outside": dict(xy=((40, 40), (50, 41), (45, 60))),
}


def on_axes(result, ax):
    """The result lists artists, every one of them on ``ax``."""
    artists = list(result)
    assert artists, "no artists returned"
    assert all(a.axes is ax for a in artists), [a for a in artists if a.axes is not ax]
    children = ax.get_children()
    assert all(a in children for a in artists)
    return artists


# -- packaging ---------------------------------------------------------------------------------
def test_core_does_not_import_matplotlib_but_plotting_does():
    code = (
        "import sys, teachraster\n"
        "assert 'matplotlib' not in sys.modules\n"
        "import teachraster.plotting\n"
        "assert 'matplotlib' in sys.modules\n"
        "assert 'matplotlib.pyplot' not in sys.modules, 'plotting should not need pyplot'\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_every_name_in_all_exists():
    for name in tp.__all__:
        assert hasattr(tp, name), name


# -- each plot function ------------------------------------------------------------------------
def _calls(fill):
    t = fill.trace
    split_step = t.split_step or 0
    row_step = t.first_work_step
    return {
        "grid": lambda ax: tp.plot_pixel_grid(ax, W, H),
        "centres": lambda ax: tp.plot_pixel_centres(ax, W, H, fill),
        "coverage": lambda ax: tp.plot_coverage(ax, fill),
        "triangle": lambda ax: tp.plot_triangle(ax, fill, edge_labels=True),
        "triangle_xy": lambda ax: tp.plot_triangle(ax, [[0, 0], [4, 1], [2, 5]]),
        "bbox": lambda ax: tp.plot_bbox(ax, fill),
        "split": lambda ax: tp.plot_split(ax, fill),
        "raster_line": lambda ax: tp.plot_raster_line(ax, fill, max(row_step, split_step)),
        "current_pixel": lambda ax: tp.plot_current_pixel(ax, fill, row_step),
        "edge_values": lambda ax: tp.plot_edge_values(ax, fill, 1),
        "edge_signs": lambda ax: tp.plot_edge_values(ax, fill, 2, signs=True),
        "bailout": lambda ax: tp.plot_bailout(ax, fill),
        "visit_order": lambda ax: tp.plot_visit_order(ax, fill),
        "barycentric": lambda ax: tp.plot_barycentric(ax, fill),
        "barycentric_1": lambda ax: tp.plot_barycentric(ax, fill, 1),
        "attribute": lambda ax: tp.plot_attribute(ax, fill, "u"),
        "attribute_affine": lambda ax: tp.plot_attribute(ax, fill, "u", mode="affine"),
        "attribute_rgb": lambda ax: tp.plot_attribute(ax, fill, "rgb"),
        "heatmap": lambda ax: tp.plot_error_heatmap(
            ax, tp.attribute_image(fill, "u", mode="affine"), fill.attrs["u"]
        ),
        "depth": lambda ax: tp.plot_depth(ax, fill),
        "image": lambda ax: tp.plot_image(ax, fill.attrs["rgb"]),
    }


CALL_NAMES = list(_calls(make_fill()))


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("name", CALL_NAMES)
def test_plot_functions_return_their_artists_on_the_axes(method, name):
    fill = make_fill(method)
    fig, ax = plt.subplots(figsize=(2, 2), dpi=40)  # a small canvas: what is drawn, not how big
    result = _calls(fill)[name](ax)
    if name in ("split", "raster_line") and method == "halfplane":
        # created hidden, so that a view can reuse them for span tables
        assert not any(a.get_visible() for a in result)
    elif name == "current_pixel" and method == "span":
        assert not any(a.get_visible() for a in result)
    on_axes(result, ax)
    fig.canvas.draw()


@pytest.mark.parametrize("case, name", sample(itertools.product(ODD, CALL_NAMES), keep=4))
def test_plot_functions_survive_odd_triangles(case, name):
    method = "span" if name in ("split", "raster_line") else "halfplane"
    fill = make_fill(method, **ODD[case])
    fig, ax = plt.subplots(figsize=(2, 2), dpi=40)  # a small canvas: what is drawn, not how big
    result = _calls(fill)[name](ax)
    assert all(a.axes is ax for a in result)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no all-NaN or divide warnings while drawing
        fig.canvas.draw()
    plt.close(fig)


def test_plot_coverage_data_is_the_coverage():
    fill = make_fill()
    fig, ax = plt.subplots()
    result = tp.plot_coverage(ax, fill)
    np.testing.assert_array_equal(np.asarray(result.image.get_array()), fill.coverage)
    other = make_fill(xy=((0, 0), (15, 0), (0, 15)))
    result.update(other)
    np.testing.assert_array_equal(np.asarray(result.image.get_array()), other.coverage)


def test_pixel_axes_are_y_down_with_centres_on_ticks():
    fig, ax = plt.subplots()
    tp.plot_pixel_grid(ax, 10, 6)
    assert ax.get_xlim() == (0, 10)
    assert ax.get_ylim() == (6, 0)  # y down: row 0 at the top
    assert ax.get_xticks()[0] == 0.5


def test_clear_axes_keeps_the_ticks_and_draws_what_a_cleared_axes_draws():
    """clear_axes (the FrameInspector's redraw) keeps the Tick objects that ax.clear() makes
    anew, and the picture is a cleared Axes' one, bit for bit, across tick changes made
    before the clear (a minor pad, a top axis, a smaller label)."""
    from teachraster.plotting.common import clear_axes

    def picture(clear):
        fig, ax = plt.subplots(figsize=(3, 2), dpi=50)
        tp.plot_pixel_grid(ax, 30, 20)  # many ticks, on top
        ax.set_xticks([0.5, 3.5], ["a", "b"], minor=True, fontsize="x-small")
        ax.tick_params(axis="x", which="minor", pad=12)
        fig.canvas.draw()
        kept = ax.xaxis.majorTicks[1]
        clear(ax)
        tp.plot_pixel_grid(ax, 6, 4)  # fewer ticks, bottom labels gone
        ax.set_xticks([1, 3], ["c", "d"], minor=True)  # between the major ones
        fig.canvas.draw()
        return np.asarray(fig.canvas.buffer_rgba()).copy(), ax.xaxis.majorTicks[1] is kept

    (cleared, _), (ours, same) = picture(lambda ax: ax.clear()), picture(clear_axes)
    assert same and np.array_equal(ours, cleared)


def test_triangle_labels_and_arrows():
    fig, ax = plt.subplots()
    xy = np.array([[1.0, 1.0], [9.0, 2.0], [3.0, 8.0]])
    result = tp.plot_triangle(ax, xy)
    assert [t.get_text() for t in result.labels] == ["v1", "v2", "v3"]
    assert len(result.arrows) == 3
    np.testing.assert_array_equal(result.vertices.get_xydata(), xy)
    # arrows point along v1→v2, v2→v3, v3→v1
    for arrow, (a, b) in zip(result.arrows, [(0, 1), (1, 2), (2, 0)]):
        (x0, y0), (x1, y1) = arrow._posA_posB
        assert np.dot([x1 - x0, y1 - y0], xy[b] - xy[a]) > 0


def test_vertex_labels_stay_inside_the_axes_at_the_grid_sides():
    """Review r13 (02 TriangleEditor, 03 PlaneExplorer): a vertex on the grid's right or left
    side had its label pushed out of the Axes, onto the key beside it or off the figure;
    ``inside=True`` (the widgets) keeps it in, the default still pushes it outwards."""
    fig, ax = plt.subplots(figsize=(5, 5))
    tp.plot_pixel_grid(ax, 16, 16)
    xy = np.array([[16.0, 1.75], [14.5, 6.25], [0.0, 14.5]])  # v1 on the right, v3 on the left
    assert tp.plot_triangle(ax, xy).labels[0].get_position()[0] > 0  # default: outwards
    result = tp.plot_triangle(ax, xy, inside=True)  # as FillView and PlaneExplorer draw it
    fig.canvas.draw()
    box = ax.get_window_extent()
    for label in (result.labels[0], result.labels[2]):
        extent = label.get_window_extent()
        assert box.x0 - 1 <= extent.x0 and extent.x1 <= box.x1 + 1, label.get_text()
    assert result.labels[1].get_position()[0] > 0  # an inner vertex keeps its outward label
    plt.close(fig)


def test_vertex_labels_stay_inside_the_axes_at_the_grid_top_and_bottom():
    """Review r106 03-W1 (PlaneExplorer): with v3 at the grid's bottom corner (16, 14) its
    label was cut off at the figure's bottom edge. ``inside=True`` keeps a label at the top
    or bottom inside the Axes too, beside its dot rather than over it."""
    fig, ax = plt.subplots(figsize=(6.3, 4.3))
    tp.plot_pixel_grid(ax, 16, 14)
    xy = np.array([[0.0, 1.0], [13.0, 5.0], [16.0, 14.0]])  # the reader's extremes
    result = tp.plot_triangle(ax, xy, arrows=False, inside=True)
    fig.canvas.draw()
    box = ax.get_window_extent()
    for label in result.labels:
        extent = label.get_bbox_patch().get_window_extent()
        assert box.y0 - 1 <= extent.y0 and extent.y1 <= box.y1 + 1, label.get_text()
        assert box.x0 - 1 <= extent.x0 and extent.x1 <= box.x1 + 1, label.get_text()
    dot = ax.transData.transform(xy[2])
    extent = result.labels[2].get_window_extent()
    assert not (extent.x0 < dot[0] < extent.x1 and extent.y0 < dot[1] < extent.y1)
    assert tp.plot_triangle(ax, xy).labels[2].get_position()[1] < 0  # default: outwards
    plt.close(fig)


def test_split_shows_u4():
    fill = make_fill("span")
    fig, ax = plt.subplots()
    result = tp.plot_split(ax, fill)
    s = fill.trace.span
    assert f"{s.u4:.2f}" in result.label.get_text()
    assert result.point.get_xdata()[0] == s.u4
    np.testing.assert_array_equal(result.flat_bottom.get_xy()[:3], s.flat_bottom)
    np.testing.assert_array_equal(result.flat_top.get_xy()[:3], s.flat_top)


def test_split_label_hides_no_covered_centre():
    """Review r5 01-7: the label sat above the split, on the covered centres of the row above
    it; it now hangs below the line, on the side of point 4 away from the middle vertex."""
    for xy in ([[8.5, 17.5], [4.5, 1.5], [18.5, 9.5]], [[11.5, 17.5], [15.5, 1.5], [1.5, 9.5]]):
        fill = tr.rasterize(tr.Triangle(xy), 20, 20, method="span", trace=True)
        fig, ax = plt.subplots(figsize=(6, 6))
        ax.set(xlim=(0, 20), ylim=(20, 0))
        label = tp.plot_split(ax, fill).label
        fig.canvas.draw()
        box = label.get_window_extent().transformed(ax.transData.inverted())
        cols, rows = np.meshgrid(np.arange(20) + 0.5, np.arange(20) + 0.5)
        under = (
            (cols > box.x0)
            & (cols < box.x1)
            & (rows > min(box.y0, box.y1))
            & (rows < max(box.y0, box.y1))
        )
        assert under.any() and not (under & fill.coverage).any(), xy
        assert min(box.y0, box.y1) > fill.trace.span.sorted_xy[1, 1]  # below the split
        plt.close(fig)


def test_edge_values_match_the_half_plane_trace():
    fill = make_fill("halfplane")
    t, b = fill.trace, fill.trace.bbox
    mine = tp.edge_images(fill)[b.row0 : b.row1, b.col0 : b.col1]
    np.testing.assert_array_equal(mine, t.halfplane.edge_values)


def test_bailout_of_span_tables_matches_half_planes():
    for xy in ((1.3, 1.2), (14.6, 4.7), (5.2, 14.1)), ((2, 2), (14, 2), (2, 14)):
        hp = tp.bailout(make_fill("halfplane", xy=xy))
        sp = tp.bailout(make_fill("span", xy=xy))
        np.testing.assert_array_equal(hp[0], sp[0])
        np.testing.assert_array_equal(hp[1], sp[1])


def test_visit_order():
    hp, sp = make_fill("halfplane"), make_fill("span")
    rows, cols = tp.visit_order(hp)
    assert len(rows) == hp.trace.bbox.size
    rows, cols = tp.visit_order(sp)
    assert len(rows) == sp.coverage.sum()
    assert sp.coverage[rows, cols].all()
    assert np.all(np.diff(rows) >= 0)  # raster lines top to bottom


# -- the error heatmap -------------------------------------------------------------------------
def test_error_heatmap_reports_the_true_maximum():
    fill = make_fill()
    a = tp.attribute_image(fill, "u", mode="affine")
    b = tp.attribute_image(fill, "u", mode="perspective")
    fig, ax = plt.subplots()
    hm = tp.plot_error_heatmap(ax, a, b)
    want = np.nanmax(np.abs(a - b))
    assert want > 0.05
    assert hm.maximum == want
    assert f"{want:.3g}" in ax.get_title()
    assert hm.colorbar is not None
    assert hm.image.get_clim() == (0.0, want)
    i, j = np.unravel_index(np.nanargmax(np.abs(a - b)), a.shape)
    assert tuple(hm.marker.get_xydata()[0]) == (j + 0.5, i + 0.5)
    # in place: new data, same artists
    before = len(ax.get_children())
    hm.update(a, a)
    assert hm.maximum == 0.0
    assert len(ax.get_children()) == before


def test_error_heatmap_of_colours_and_of_nothing():
    fill = make_fill()
    a = tp.attribute_image(fill, "rgb", mode="affine")
    b = tp.attribute_image(fill, "rgb", mode="perspective")
    fig, ax = plt.subplots()
    hm = tp.plot_error_heatmap(ax, a, b)
    assert hm.maximum == np.nanmax(np.abs(a - b))
    nothing = np.full((4, 4), np.nan)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        hm.update(nothing, nothing)
        fig.canvas.draw()
    assert np.isnan(hm.maximum)
    with pytest.raises(ValueError, match="same shape"):
        tp.abs_error(np.zeros((2, 2)), np.zeros((3, 3)))


# -- FillView ----------------------------------------------------------------------------------
def coverage_shown(view):
    return np.asarray(view.coverage.image.get_array())


@pytest.mark.parametrize("method", METHODS)
def test_fill_view_follows_the_trace_in_place(method):
    fill = make_fill(method)
    trace = fill.trace
    view = tp.FillView(fill, step=0)
    view.fig.canvas.draw()
    n_children = len(view.ax.get_children())
    n_fig = len(view.fig.get_children())
    steps = sorted({0, 1, 2, trace.first_work_step, len(trace) // 2, len(trace) - 2})
    steps += list(range(len(trace)))[:: max(1, len(trace) // 25)] + [len(trace) - 1, -1]
    for k in steps:
        step = view.show_step(k, draw=False)
        assert step == trace.step(k)
        k = step.index  # -1 means the last step (coverage_at wants the index itself)
        np.testing.assert_array_equal(coverage_shown(view), trace.coverage_at(k))
        assert view.caption == trace.caption(k)
        shown = view.caption_text.get_text()
        assert " ".join(shown.split()) == " ".join(trace.caption(k).split())
        assert f"step {k} of 0–{len(trace) - 1}" in view.header.get_text()
        view.fig.canvas.draw()
        assert len(view.ax.get_children()) == n_children
        assert len(view.fig.get_children()) == n_fig
    assert view.step == len(trace) - 1
    np.testing.assert_array_equal(coverage_shown(view), fill.coverage)


def keyed(view) -> list[str]:
    """The labels a FillView's key shows."""
    return [t.get_text() for t in view.legend.texts if t.get_visible()]


def test_fill_view_key_names_the_pixel_under_test_only_while_one_is():
    """Review r8 (lesson 04 c15): the key listed "pixel under test" at the last step, where
    nothing is under test."""
    from teachraster.plotting.views import PIXEL_UNDER_TEST

    fill = make_fill("halfplane")
    view = tp.FillView(fill, step=0)
    pixel = next(k for k in range(len(fill.trace)) if fill.trace.step(k).kind == "pixel")
    for k, on in ((pixel, True), (-1, False), (pixel, True)):
        view.show_step(k, draw=False)
        assert (PIXEL_UNDER_TEST in keyed(view)) == on == view.pixel.box.get_visible()
    view.redraw()
    plt.close(view.fig)


def test_fill_view_shows_the_current_raster_line_and_split():
    fill = make_fill("span")
    t = fill.trace
    view = tp.FillView(fill, step=0)
    assert not view.split.line.get_visible()  # not found yet
    assert not view.bbox.outline.get_visible()
    k = t.first_work_step + 3
    view.show_step(k, draw=False)
    # span tables test no box of pixels (Ek §1.1): no box drawn, none in the key or caption
    assert view.split.line.get_visible() and not view.bbox.outline.get_visible()
    keyed = [text.get_text() for text in view.legend.texts if text.get_visible()]
    assert "bounding box" not in keyed and "flat-top part" in keyed
    assert "no box" in t.caption(t.bbox_step) and "raster lines" in t.caption(t.bbox_step)
    row = t.step(k).row
    assert view.raster_line.band.get_visible()
    assert view.raster_line.band.get_y() == row
    assert not view.pixel.box.get_visible()
    view.set_fill(make_fill("halfplane"), draw=False)  # the methods that test the box show it
    assert view.bbox.outline.get_visible()
    assert "bounding box" in [text.get_text() for text in view.legend.texts]


def test_fill_view_key_tells_the_dashed_box_from_the_partial_blocks():
    """Review r115 00-A: in the tiles view "bounding box" and "block partial" were the same
    solid orange square; the box is drawn dashed, and so is its swatch now."""
    from teachraster.plotting.views import DASHED_SQUARE

    fill = make_fill("tiled")
    view = tp.FillView(fill, step=0)
    for k in (fill.trace.bbox_step, len(fill.trace) // 2, -1):
        view.show_step(k, draw=False)
        swatch = {t.get_text(): s for s, t in zip(view.legend.swatches, view.legend.texts)
                  if t.get_visible()}  # fmt: skip
        box = swatch["bounding box"]
        assert box.get_marker() is DASHED_SQUARE and box.get_markerfacecolor() == "none"
        if "block partial" in swatch:
            assert swatch["block partial"].get_marker() == "s"
    assert view.bbox.outline.get_linestyle() != "-"  # the picture's box is dashed too
    plt.close(view.fig)


def test_fill_view_shows_the_current_pixel_and_rejected_pixels():
    fill = make_fill("halfplane")
    t = fill.trace
    view = tp.FillView(fill)
    k = t.first_work_step + t.bbox.size // 2
    view.show_step(k, draw=False)
    step = t.step(k)
    assert view.pixel.box.get_visible()
    assert view.pixel.box.get_xy() == (step.col, step.row)
    assert not view.raster_line.band.get_visible()
    assert not view.split.line.get_visible()
    rejected = np.asarray(view.rejected.get_array()).astype(bool)
    # every pixel shown rejected was visited already and is not covered
    assert not (rejected & t.coverage_at(k)).any()
    assert rejected.sum() > 0


def test_fill_view_outlines_the_block_a_tiles_step_classifies():
    """Review r19 (lesson 00, the player in tiles mode): the caption named "4×4 block at
    (row 4, col 0)" and the picture outlined nothing. Each block step outlines its block
    (its extent inside the image), and a pixel step after it one pixel again."""
    import teachraster as tr

    xy = np.array([(1.3, 1.2), (14.6, 4.7), (5.2, 14.1)])
    fill = tr.rasterize(tr.Triangle(xy), 16, 16, method="tiled", trace=True)
    t = fill.trace
    view = tp.FillView(fill)
    shown = 0
    for k in range(t.first_work_step, t.first_work_step + len(t.blocks)):
        step = view.show_step(k, draw=False)
        assert step.kind == "block" and step.extent is not None
        rows, cols = step.extent
        assert view.pixel.box.get_visible() and not view.pixel.centre.get_visible()
        assert view.pixel.box.get_bbox().bounds == (step.col, step.row, cols, rows)
        assert f"({step.row}" in step.caption or f"row {step.row}" in step.caption
        shown += 1
    assert shown == len(t.blocks) > 1
    view.show_step(0, draw=False)  # a set-up step: nothing outlined
    assert not view.pixel.box.get_visible()
    half = make_fill("halfplane")
    view.set_fill(half, step=half.trace.first_work_step, draw=False)
    assert view.pixel.box.get_bbox().bounds[2:] == (1, 1) and view.pixel.centre.get_visible()


def test_fill_view_set_fill_reuses_the_artists():
    view = tp.FillView(make_fill("span"))
    n_children = len(view.ax.get_children())
    for method in ("halfplane", "span", "halfplane"):
        for dx in (0.0, 0.7, -1.3):
            xy = np.array([(1.3, 1.2), (14.6, 4.7), (5.2, 14.1)]) + dx
            fill = make_fill(method, xy=xy)
            view.set_fill(fill, draw=False)
            assert view.trace is fill.trace
            assert view.step == len(fill.trace) - 1  # a finished fill stays finished
            np.testing.assert_array_equal(coverage_shown(view), fill.coverage)
            view.fig.canvas.draw()
            assert len(view.ax.get_children()) == n_children
    # mid-way: the same step index, clipped to the new fill
    view.show_step(4, draw=False)
    view.set_fill(make_fill("span"), draw=False)
    assert view.step == 4
    view.set_fill(make_fill("span"), step=0, draw=False)
    assert view.step == 0


def test_fill_view_new_image_size():
    view = tp.FillView(make_fill(size=(16, 16)))
    fill = make_fill(size=(24, 10))
    view.set_fill(fill, draw=False)
    np.testing.assert_array_equal(coverage_shown(view), fill.coverage)
    assert view.ax.get_xlim() == (0, 24) and view.ax.get_ylim() == (10, 0)
    view.fig.canvas.draw()


@pytest.mark.parametrize("case, method", sample(itertools.product(ODD, METHODS), keep=4))
def test_fill_view_odd_triangles(case, method):
    fill = make_fill(method, **ODD[case])
    view = tp.FillView(fill)
    for k in range(len(fill.trace)):
        view.show_step(k, draw=False)
        np.testing.assert_array_equal(coverage_shown(view), fill.trace.coverage_at(k))
        assert view.caption == fill.trace.caption(k)
    view.fig.canvas.draw()


def test_fill_view_on_given_axes_and_errors():
    fig, (ax1, ax2) = plt.subplots(1, 2)
    fill = make_fill()
    view = tp.FillView(fill, ax=ax2, legend=False)
    assert view.ax is ax2 and view.fig is fig
    with pytest.raises(IndexError):
        view.show_step(len(fill.trace))
    with pytest.raises(ValueError, match="trace=True"):
        tp.FillView(tr.rasterize(tr.Triangle([[0, 0], [4, 0], [0, 4]]), 4, 4))


def test_fill_view_draw_idle_is_called():
    view = tp.FillView(make_fill())
    calls = []
    view.fig.canvas.draw_idle = lambda *a, **k: calls.append(1)
    view.show_step(3)
    view.set_fill(make_fill("span"))
    view.show_step(2, draw=False)
    assert len(calls) == 2


# -- interpolation / comparison views ----------------------------------------------------------
def test_interpolation_view_updates_in_place():
    fill = make_fill()
    view = tp.InterpolationView(fill, "u")
    view.fig.canvas.draw()
    counts = [len(ax.get_children()) for ax in view.axes]
    for dx in (0.0, 1.0, -0.5):
        xy = np.array([(1.3, 1.2), (14.6, 4.7), (5.2, 14.1)]) + dx
        f = make_fill(xy=xy)
        view.update(f, draw=False)
        a = tp.attribute_image(f, "u", mode="affine")
        b = tp.attribute_image(f, "u", mode="perspective")
        assert view.maximum == np.nanmax(np.abs(a - b))
        np.testing.assert_array_equal(np.asarray(view.images[0].image.get_array()), a)
        view.fig.canvas.draw()
        assert [len(ax.get_children()) for ax in view.axes] == counts


def test_interpolation_view_heatmap_states_its_maximum_in_the_title_only():
    """Review r13 00 c14: the "max ..." note by the ring covered the v2 label; the heatmap's
    title states the maximum, the ring marks the pixel, and the note stays hidden."""
    view = tp.InterpolationView(make_fill(), "u")
    for dx in (0.0, 1.0):
        view.update(make_fill(xy=np.array([(1.3, 1.2), (14.6, 4.7), (5.2, 14.1)]) + dx), draw=False)
        assert not view.heatmap.note.get_visible() and view.heatmap.marker.get_visible()
        assert f"max {view.maximum:.3g}" in view.heatmap.title.get_text()


def test_row_profile_key_stands_clear_of_the_curves():
    """Review r13 04 c15: the profile's key, placed "best" once, covered the lower ends of
    both curves of another row; it now stands in the upper left, above the curves."""
    with plt.rc_context():
        tp.use_style("classroom")  # the lessons' large fonts: a large key
        # the Axes about the size of the FillPlayer comparison's profile
        fig, ax = plt.subplots(figsize=(3.6, 4.6), layout="constrained")
        fill = make_fill()
        a = tp.attribute_image(fill, "u", mode="affine")
        b = tp.attribute_image(fill, "u", mode="perspective")
        profile = tp.plot_profile(ax, a, b, index=3, labels=("affine", "perspective"))
    for index in (3, 8, 12):
        profile.update(a, b, index)
        fig.canvas.draw()
        key = ax.get_legend().get_window_extent()
        for line in profile.lines:
            xy = line.get_xydata()
            shown = ax.transData.transform(xy[np.isfinite(xy).all(axis=1)])
            inside = (shown[:, 0] >= key.x0) & (shown[:, 0] <= key.x1)
            assert not (inside & (shown[:, 1] >= key.y0) & (shown[:, 1] <= key.y1)).any(), index
    plt.close(fig)


def test_interpolation_view_needs_a_name_when_several():
    with pytest.raises(ValueError, match="pick an attribute"):
        tp.InterpolationView(make_fill())
    view = tp.InterpolationView(make_fill(), "rgb")  # colour attribute
    view.fig.canvas.draw()


def test_interpolation_view_without_perspective_has_no_error():
    tri = tr.Triangle([[1, 1], [14, 3], [4, 13]], attrs={"u": [0, 1, 0]})
    view = tp.InterpolationView(tr.rasterize(tri, W, H, trace=True))
    assert view.maximum < 1e-12


def test_comparison_view_of_textured_floor_renders():
    scene = get_scene("textured_floor")
    a = tr.render(scene, None, 48, 36, interpolation="affine")
    b = tr.render(scene, None, 48, 36)
    view = tp.ComparisonView(a.image, b.image, titles=("affine", "perspective-correct"))
    assert view.maximum == np.nanmax(np.abs(a.image - b.image))
    view.update(b.image, b.image, draw=False)
    assert view.maximum == 0.0
    view.fig.canvas.draw()


# -- frames and scenes -------------------------------------------------------------------------
def test_frames_and_scene_frames():
    scene = get_scene("textured_floor")
    frame = tr.render(scene, None, 40, 30)
    clip = [[[-1, -1, 0.2, 1], [1, -1, 0.5, 1], [-1, 1, 0.9, 1]]]
    bare = tr.render(clip, 12, 10, attrs=[[[0.0], [1.0], [0.0]]])
    fig, axes = plt.subplots(2, 3)
    on_axes(tp.plot_coverage(axes[0, 0], frame), axes[0, 0])
    on_axes(tp.plot_depth(axes[0, 1], frame), axes[0, 1])
    on_axes(tp.plot_image(axes[0, 2], frame), axes[0, 2])
    on_axes(tp.plot_attribute(axes[1, 0], frame, "uv", channel=0), axes[1, 0])
    on_axes(tp.plot_attribute(axes[1, 1], bare), axes[1, 1])
    result = on_axes(tp.plot_plan(axes[1, 2], frame), axes[1, 2])
    text = result[0].get_text()
    assert all(e.name in text for e in frame.plan)
    fig.canvas.draw()
    np.testing.assert_array_equal(
        np.asarray(tp.plot_coverage(axes[0, 0], bare).image.get_array()), bare.coverage
    )


def test_depth_needs_z():
    fill = tr.rasterize(tr.Triangle([[0, 0], [4, 0], [0, 4]]), 4, 4)
    fig, ax = plt.subplots()
    with pytest.raises(ValueError, match="z="):
        tp.plot_depth(ax, fill)


def test_large_images_use_an_image_not_a_mesh():
    fig, ax = plt.subplots()
    big = np.random.default_rng(0).random((200, 300))
    result = tp.plot_attribute(ax, big)
    assert isinstance(result.image, matplotlib.image.AxesImage)
    assert ax.get_ylim() == (200, 0)
    result.update(big[::-1])
    fig.canvas.draw()


# -- style -------------------------------------------------------------------------------------
def test_use_style_changes_rcparams_and_back():
    before = {k: matplotlib.rcParams[k] for k in ("font.size", "lines.linewidth", "backend")}
    with tp.use_style("classroom"):
        assert matplotlib.rcParams["font.size"] == 18
        assert matplotlib.rcParams["lines.linewidth"] == 3.5
        colors = matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
        assert set(colors) <= {c.lower() for c in tp.OKABE_ITO.values()} | set(
            tp.OKABE_ITO.values()
        )
    assert {k: matplotlib.rcParams[k] for k in before} == before


def test_use_style_persists_without_with():
    try:
        tp.use_style("classroom")
        assert matplotlib.rcParams["font.size"] == 18
        tp.use_style("default")
        assert matplotlib.rcParams["font.size"] == matplotlib.rcParamsDefault["font.size"]
        assert matplotlib.get_backend().lower() == "agg"  # the backend is left alone
    finally:
        tp.use_style("default")
    with pytest.raises(ValueError, match="unknown style"):
        tp.use_style("projector")


def test_classroom_figures_draw():
    with tp.use_style("classroom"):
        view = tp.FillView(make_fill("span"))
        view.fig.canvas.draw()
        assert view.caption_text.get_fontsize() > 12


def test_fill_view_names_vertices_in_the_order_given_for_every_method():
    # input order differs from the y order: the top vertex is v2, the bottom one v1, and
    # still every method labels xy[0] v1 (the span captions give the roles instead)
    tri = tr.Triangle([[10.0, 13.0], [3.0, 1.0], [13.0, 6.0]])
    span = tr.rasterize(tri, W, H, method="span", trace=True)
    assert list(span.trace.span.order) != [0, 1, 2]
    view = tp.FillView(span)
    labels = view.triangle.labels
    assert [label.get_text() for label in labels] == ["v1", "v2", "v3"]
    assert "top v2 (3, 1), middle v3 (13, 6), bottom v1 (10, 13)" in span.trace.caption(3)
    # set_fill relabels the same artists, with the same names
    view.set_fill(tr.rasterize(tri, W, H, method="halfplane", trace=True))
    assert view.triangle.labels is labels
    assert [label.get_text() for label in labels] == ["v1", "v2", "v3"]
    moved = tr.Triangle([[3.0, 12.0], [10.0, 2.0], [13.0, 7.0]])
    view.set_fill(tr.rasterize(moved, W, H, method="span", trace=True))
    assert [label.get_text() for label in labels] == ["v1", "v2", "v3"]
    view.fig.canvas.draw()
    plt.close(view.fig)


def test_labels_of_far_away_vertices_are_not_drawn():
    fig, ax = plt.subplots()
    tp.plot_pixel_grid(ax, 16, 16)
    result = tp.plot_triangle(ax, [[-1e6, -1e6], [1e6, 8], [8, 15.5]], edge_labels=True)
    fig.canvas.draw()  # used to overflow FreeType's rasteriser
    renderer = fig.canvas.get_renderer()
    assert [a._check_xy(renderer) for a in result.labels] == [False, False, True]
    plt.close(fig)


# -- one resolve per tick, blitting ------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_a_step_is_resolved_once_per_tick(method, monkeypatch):
    """FillView.show_step asks the trace for the step once and hands it to the artists."""
    view = tp.FillView(make_fill(method), step=0)
    calls = []
    real = type(view.trace).step

    def counting(self, k):
        calls.append(k)
        return real(self, k)

    monkeypatch.setattr(type(view.trace), "step", counting)
    for k in (3, view.trace.first_work_step + 2, -1, 0):
        calls.clear()
        view.show_step(k, draw=False)
        view.redraw()
        assert len(calls) == 1, calls


def rendered(fig):
    return np.asarray(fig.canvas.buffer_rgba()).astype(int)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("size", sample([16, 40], keep=2))
@pytest.mark.parametrize("values", [False, True])
def test_blitted_steps_equal_a_full_redraw(method, size, values):
    """redraw() (background, still layers, moving artists) matches fig.canvas.draw(); with
    ``values`` the last step's colours and key too."""
    s = size / W
    xy = np.array([(1.3, 1.2), (14.6, 4.7), (5.2, 14.1)]) * s
    fill = make_fill(method, xy=xy, size=(size, size))
    view = tp.FillView(fill, step=0, legend=True, values=values)
    n = len(fill.trace)
    steps = [0, 2, fill.trace.first_work_step, n // 3, n // 2, n // 2 + 1, n - 2, n - 1, 5]
    full_draws = []
    for k in steps:
        view.show_step(k, draw=False)
        full_draws.append(view.redraw())
        fast = rendered(view.fig)
        view.fig.canvas.draw()
        diff = np.abs(fast - rendered(view.fig)).max(axis=-1)
        # the same picture; compositing the layers rounds anti-aliased edges by a few levels
        assert diff.max() <= 8, (k, diff.max())
        assert (diff > 0).mean() < 0.5
    # whole draws only when the still artists change: first, bbox found, the first fill step
    # (the key lists the fill's entries from there: review r58), split found (and with values
    # the last step's key)
    assert full_draws[0] and sum(full_draws) <= 4 + (method == "span") + values
    assert not view.redraw()  # nothing changed: blitted


@pytest.mark.parametrize("method", METHODS)
def test_fill_view_colours_the_last_step_by_the_values_the_trace_records(method):
    """Review r9/r10 (lesson 04 c15): the last step's caption says "interpolated u" while the
    picture showed plain coverage. With ``values`` the covered pixels take the colours of
    the values written (subdivided too), only at that step; the key names the colours.
    Review r166 00-6: the range (colours and key) is the interpolation's own; shared with
    the other one, perspective's key read 0.88, the affine top, over values up to 0.86."""
    fills = {m: make_fill(method, interpolation=m) for m in ("affine", "perspective", "subdivided")}
    view = tp.FillView(fills["perspective"], values=True, attribute="u")
    shown = {}
    for mode, fill in fills.items():
        view.set_fill(fill, step=-1, draw=False)
        data = np.ma.filled(view.values.get_array(), np.nan).reshape(H, W)
        assert view.values.get_visible()
        np.testing.assert_array_equal(data, fill.attrs["u"])  # NaN where not covered
        shown[mode] = data
        own = (np.nanmin(fill.attrs["u"]), np.nanmax(fill.attrs["u"]))
        assert view.values.get_clim() == pytest.approx(own)
        bar = view.value_bar
        assert (bar.low.get_text(), bar.high.get_text()) == tuple(f"{v:.2f}" for v in own)
        key = keyed(view)
        # the key names the colours with a colour bar (review r11; two swatches before)
        assert "covered" not in key and view.value_bar.title.get_visible()
        assert "flat-top part" not in key and not view.split.flat_top.get_visible()
        view.show_step(-2, draw=False)  # before the last step: coverage, as before
        assert not view.values.get_visible() and "covered" in keyed(view)
    assert np.nanmax(np.abs(shown["affine"] - shown["perspective"])) > 0.05
    # the two keys differ where the two ranges do
    assert np.nanmax(shown["affine"]) - np.nanmax(shown["perspective"]) > 0.005
    plain = tp.FillView(fills["perspective"])  # values off: the finished fill as coverage
    assert not plain.values.get_visible() and "covered" in keyed(plain)
    plt.close(view.fig)
    plt.close(plain.fig)


def test_fill_view_keys_the_sample_dots_it_is_told_of():
    """Review r9: the player draws sample dots (plot_samples) that the key did not name. With
    several samples the last step colours every pixel with a covered sample, as its caption
    counts them (review r9 00 c14: "72 pixels with a covered sample (59 centres)")."""
    fill = make_fill("halfplane", samples=4)
    for sample_key in (False, True):
        view = tp.FillView(fill, sample_key=sample_key, values=True)
        for k in (2, -1):
            view.show_step(k, draw=False)
            assert ("sample covered" in keyed(view)) == sample_key
            assert ("sample not covered" in keyed(view)) == sample_key
        data = np.ma.filled(view.values.get_array(), np.nan).reshape(H, W)
        np.testing.assert_array_equal(np.isfinite(data), fill.coverage)
        np.testing.assert_array_equal(data, fill.attrs["u"])
        assert fill.coverage.sum() > fill.trace.covered.sum()  # pixels with a sample only
        assert f"at the {int(fill.coverage.sum())} pixels" in view.caption
        plt.close(view.fig)


def test_fill_view_outlines_the_pixels_shaded_for_a_sample_alone():
    """Review r23 (lesson 00 c14): at 4 samples the caption counts 72 pixels = 59 with the
    centre covered + 13 for a sample alone, and the picture did not show which 13. They are
    outlined at the coloured step (and keyed); the player draws the samples only in pixels
    partly covered, not four in every pixel of the grid."""
    fill = make_fill("halfplane", samples=4)
    view = tp.FillView(fill, values=True, sample_key=True)
    dots = tp.plot_samples(view.ax, fill, fraction=False, partial=True)
    view.show_samples(dots)
    extra = fill.coverage & ~fill.trace.image(fill.trace.covered)
    assert extra.any()
    outlined = {tuple(np.floor(p.vertices.mean(axis=0)).astype(int))
                for p in view.sample_only.get_paths()}  # fmt: skip
    assert outlined == {(j, i) for i, j in zip(*np.nonzero(extra))}
    assert view.sample_only.get_visible() and tp.views.SAMPLE_ONLY in keyed(view)
    view.show_step(2, draw=False)
    assert not view.sample_only.get_visible() and tp.views.SAMPLE_ONLY not in keyed(view)
    cover = fill.sample_coverage
    partial = cover.any(axis=2) & ~cover.all(axis=2)
    for x, y in (dots.uncovered.get_data(), dots.covered.get_offsets().T):
        assert len(x) and partial[np.floor(y).astype(int), np.floor(x).astype(int)].all()
    assert len(x) == cover[partial].sum()  # every covered sample of those pixels
    plt.close(view.fig)


def test_fill_view_shades_the_pixels_a_sample_alone_covers_without_values():
    """Review r169 02-3: with no attribute to colour (lesson 02's player) the last step drew
    the pixels shaded for a sample alone in the box's cream ("not tested yet"), unkeyed,
    while the caption counted them. They have a shade of their own and a key line."""
    tri = tr.Triangle([[2.25, 1.75], [14.5, 6.25], [5.75, 14.5]])
    fill = tr.rasterize(tri, 16, 16, method="halfplane", trace=True, samples=4)
    view = tp.FillView(fill, values=True, sample_key=True)
    # the player's dots (bold: untested ones keyed until their step)
    view.show_samples(tp.plot_samples(view.ax, fill, fraction=False, partial=True, bold=True))
    view.show_step(-1, draw=False)
    extra = fill.coverage & ~fill.trace.image(fill.trace.covered, fill=False)
    assert extra.sum() == 13 and view._shown is None  # 83 = 70 centres + 13, no values
    assert view.sample_only.get_visible() and view._sample_only_n == 13
    face = view.sample_only.get_facecolor()
    assert len(face) and face[0][3] > 0  # filled, not only outlined
    assert tuple(face[0]) == tuple(tp.views.sample_only_face(False))
    assert tp.views.SAMPLE_ONLY in keyed(view)
    assert "sample not tested yet" not in keyed(view)  # the last step: every one is tested
    view.show_step(2, draw=False)
    assert not view.sample_only.get_visible() and tp.views.SAMPLE_ONLY not in keyed(view)
    plt.close(view.fig)


def test_fill_view_last_step_keys_its_colours_as_a_bar_and_hides_u4():
    """Review r11 (lesson 00 c14): at the step coloured by u the key gave two swatches
    "u = 0.88" / "u = 0.00" (its ends only, and not why the top is 0.88, not v2's 1) beside
    the split's "u4 = 3.15", a screen x. The key is a short colour bar over the range at the
    covered centres; the split's label is hidden at that step only."""
    xy = ((2.2, 1.5), (13.7, 5.2), (5.1, 12.8))  # the tour's triangle
    fill = make_fill("span", xy=xy)
    view = tp.FillView(fill, values=True, attribute="u")
    bar = view.value_bar
    view.show_step(-2, draw=False)
    assert view.split.label.get_visible() and not bar.title.get_visible()
    view.show_step(-1, draw=False)
    assert not view.split.label.get_visible()
    assert not any(t.startswith("u = ") for t in keyed(view))
    assert all(a.get_visible() for a in bar)
    assert bar.title.get_text() == "u at the covered centres"
    lo, hi = view.values.get_clim()
    assert (bar.low.get_text(), bar.high.get_text()) == (f"{lo:.2f}", f"{hi:.2f}")
    assert hi < 1.0  # v2's own pixel is not covered: the covered centres' range, not [0, 1]
    assert bar.bar.get_cmap().name == view.values.get_cmap().name
    # beside the grid, inside the figure, above the key's other lines (tested, rejected ...)
    view.set_fill(make_fill("halfplane", xy=xy), step=-1, draw=False)
    view.fig.canvas.draw()
    renderer = view.fig.canvas.get_renderer()
    boxes = [a.get_window_extent(renderer) for a in bar]
    assert min(b.x0 for b in boxes) > view.ax.bbox.x1
    assert max(b.x1 for b in boxes) < view.fig.bbox.x1
    lines = [t.get_window_extent(renderer) for t in view.legend.texts if t.get_visible()]
    assert max(b.y1 for b in lines) < min(b.y0 for b in boxes)  # the rest below the bar
    plt.close(view.fig)


def test_fill_view_draws_covered_samples_as_rings_where_it_colours_by_u():
    """Review r11 (lesson 00 c14, 4× MSAA): filled blue sample dots, four to a pixel, hid the
    u colours of the last step (and looked like the map's low end). There they are rings; at
    the other steps filled dots, as before. Blitted, the dots lie where a full draw puts
    them: under the vertex and edge labels (a layer of their own drew them on top)."""
    fill = make_fill("halfplane", samples=4)
    view = tp.FillView(fill, step=2, values=True, sample_key=True)
    dots = tp.plot_samples(view.ax, fill, fraction=False)
    view.show_samples(dots)

    def hollow() -> bool:
        return bool((dots.covered.get_facecolor()[:, 3] == 0).all())

    assert not hollow()
    for k in (-1, 2, -1):
        view.show_step(k, draw=False)
        assert hollow() == (k == -1)
        view.redraw()
        fast = rendered(view.fig)
        view.fig.canvas.draw()
        assert np.abs(fast - rendered(view.fig)).max() <= 8, k
    dots.update(fill)  # a new fill keeps the rings of the step on show
    assert hollow()
    plt.close(view.fig)


def test_fill_view_bar_under_msaa_spans_every_coloured_pixel_and_says_where():
    """Review r12 (lesson 00 c14, 4× MSAA): the bar said "u at the covered centres" and ran
    over those only, while pixels with only a sample covered were coloured by u extrapolated
    to their centres, outside the bar's range (clipped to its end colours)."""
    fill = make_fill("halfplane", samples=4)
    view = tp.FillView(fill, step=-1, values=True)
    shown = view.values.get_array()
    lo, hi = view.values.get_clim()
    assert np.nanmin(shown) >= lo - 1e-12 and np.nanmax(shown) <= hi + 1e-12
    assert view.value_bar.title.get_text() == "u at the pixel centres"
    one = tp.FillView(make_fill("halfplane"), step=-1, values=True)
    assert one.value_bar.title.get_text() == "u at the covered centres"
    plt.close(view.fig)
    plt.close(one.fig)


def test_split_label_stays_inside_the_grid():
    """Review r9 (00 c14): with point 4 near the grid's left edge, "point 4 / u4 = 3.15" stuck
    out of the grid onto the "row i" label; it starts at the grid's edge instead."""
    xy = ((2.2, 1.5), (13.7, 5.2), (5.1, 12.8))  # the tour's triangle: u4 = 3.15
    fig = plt.figure(figsize=(7.0, 5.0))
    view = tp.FillView(make_fill("span", xy=xy), ax=fig.add_axes((0.12, 0.05, 0.5, 0.7)))
    fig.canvas.draw()
    box = view.split.label.get_window_extent(fig.canvas.get_renderer())
    assert view.ax.bbox.x0 <= box.x0 and box.x1 <= view.ax.bbox.x1
    # review r19 (00): starting at the grid's edge it ran over covered centres right of
    # point 4; with no room for both lines it shows point 4's number alone, outside
    # review r77 00-1: hung below the split line, its halo blanked a centre's dot: it is
    # centred on the pixel corner left of point 4, between four centres, over none
    assert view.split.label.get_text() == "4"
    assert view.split.label.get_horizontalalignment() == "center"
    # review r225 FIG2: on that corner it lay on the outline of the raster line under the
    # split; it is now in the row above the split line, between two of its centres
    assert view.split.label.xy == (2.0, 4.5)
    data = box.transformed(view.ax.transData.inverted())
    fill = make_fill("span", xy=xy)
    cols, rows = np.meshgrid(np.arange(16) + 0.5, np.arange(16) + 0.5)
    under = (cols > data.x0) & (cols < data.x1) & (rows > min(data.y0, data.y1))
    under &= rows < max(data.y0, data.y1)
    assert not under.any()  # no centre, covered or not, under the label
    # review r241 FIG2: ... nor under its box, which the extent leaves out: a halo, no box
    assert view.split.label.get_bbox_patch() is None and view.split.label.get_path_effects()
    assert data.x1 < fill.trace.span.u4  # left of point 4, outside the triangle
    assert f"= {fill.trace.span.u4:.3f};" in fill.trace.caption(fill.trace.split_step)
    plt.close(fig)


def test_set_fill_invalidates_the_blit_cache():
    view = tp.FillView(make_fill("span"), step=-1)
    assert view.redraw() and not view.redraw()
    view.set_fill(make_fill("halfplane"), draw=False)
    assert view.redraw()
    fast = rendered(view.fig)
    view.fig.canvas.draw()
    assert np.abs(fast - rendered(view.fig)).max() <= 8


def test_layered_blit_rejects_unknown_kinds():
    from teachraster.plotting.blitting import LayeredBlit

    fig, ax = plt.subplots()
    with pytest.raises(ValueError, match="moving"):
        LayeredBlit(fig, [("static", [])])


def test_artists_update_from_a_step():
    fill = make_fill("span")
    t = fill.trace
    fig, ax = plt.subplots()
    line = tp.plot_raster_line(ax, fill, 0)
    assert not line.band.get_visible()
    step = t.step(t.first_work_step + 4)
    line.update(step)
    assert line.band.get_visible() and line.band.get_y() == step.row
    start, stop = step.columns
    assert line.cells.get_x() == start and line.cells.get_width() == stop - start
    pixel = tp.plot_current_pixel(ax, make_fill("halfplane"), 0)
    pixel.update(make_fill("halfplane").trace.step(9))
    assert pixel.box.get_visible()
    pixel.update(step)  # a row step: no pixel to show
    assert not pixel.box.get_visible()


def test_interpolation_view_highlights_the_mode_in_use():
    view = tp.InterpolationView(make_fill(), "u")
    assert view.in_use is None
    view.highlight("affine")
    affine, persp = view.in_use
    assert affine.get_visible() and not persp.get_visible()
    # marked by its frame, not by fading the other panel (review r2 00-4: washed out)
    assert {im.image.get_alpha() for im in view.images[:2]} <= {None, 1.0}
    assert view.axes[0].spines["top"].get_linewidth() > view.axes[1].spines["top"].get_linewidth()
    n = len(view.axes[0].get_children())
    view.highlight("perspective")
    assert persp.get_visible() and not affine.get_visible()
    view.highlight(None)
    assert not (affine.get_visible() or persp.get_visible())
    assert {im.image.get_alpha() for im in view.images[:2]} <= {None, 1.0}
    assert len(view.axes[0].get_children()) == n  # the same notes, reused


def test_visit_order_path_is_thick_enough_for_a_projector():
    """Review r2 (lesson 02): the visit path was a hairline, lost on a projector."""
    import matplotlib as mpl

    fig, ax = plt.subplots()
    art = tp.plot_visit_order(ax, make_fill("halfplane"))
    assert art.path.get_linewidth() >= 0.5 * float(mpl.rcParams["lines.linewidth"])
    plt.close(fig)


def test_the_frame_is_drawn_above_the_vertex_labels_boxes():
    """Reviews r19/r20 (00 c14, c16): v1's white box over the heatmap's left side hid a piece
    of the frame and left a stub. The frame is drawn above the labels; in a player's steps
    (``inside``) it stays below, where the current block, the whole image at a tiles step, is
    outlined on it."""
    fig, (ax, steps) = plt.subplots(1, 2)
    labels = tp.plot_triangle(ax, make_fill()).labels
    assert all(s.get_zorder() > max(t.get_zorder() for t in labels) for s in ax.spines.values())
    inside = tp.plot_triangle(steps, make_fill(), inside=True).labels
    assert all(s.get_zorder() < min(t.get_zorder() for t in inside) for s in steps.spines.values())
    plt.close(fig)


def test_the_vertex_dots_are_drawn_above_their_labels_boxes():
    """Review r23 (00 c7, c10, c16): the white boxes of v1's and v2's labels washed out their
    dots. The dots are drawn above the labels, in every figure and player."""
    fig, (ax, steps) = plt.subplots(1, 2)
    for art in (
        tp.plot_triangle(ax, make_fill()),
        tp.plot_triangle(steps, make_fill(), inside=True),
    ):
        assert art.vertices.get_zorder() > max(t.get_zorder() for t in art.labels)
    plt.close(fig)


def _segment_distance(p, a, b) -> tuple[float, float]:
    """Distance of ``p`` from the segment a-b and the parameter of its nearest point."""
    d = b - a
    t = float(np.clip((p - a) @ d / (d @ d), 0.0, 1.0))
    return float(np.hypot(*(p - (a + t * d)))), t


@pytest.mark.parametrize("v2", [(14.5, 6.25), (1.0, 12.0), (0.46484375, 6.2890625)],
                         ids=["clockwise", "counter", "editor-by-the-frame"])  # fmt: skip
def test_edge_labels_sit_at_the_edges_they_name(v2):
    """Each edge label lies by the middle of the edge its name denotes (E21 between v2 and v1),
    for either winding: the test order then differs from v1→v2→v3 (review r299 02-3: after
    the flip "E21" and "E13" sat at each other's edge), and clear of the vertex names (review
    r354 FIG1: lesson 02's editor, v2 dragged to the frame: "E21" covered "v1", 3 px from its
    edge)."""
    xy = np.array([(2.25, 1.75), v2, (5.75, 14.5)])
    if v2[0] < 1:
        from teachraster.widgets import TriangleEditor

        editor = TriangleEditor(tr.Triangle(xy), 16, 16, method="halfplane", backend="image",
                                style="classroom", probe=(7.5, 7.5), comparison=False)  # fmt: skip
        view = editor.view
    else:
        view = tp.FillView(make_fill(xy=xy), step=-1)
    view.fig.canvas.draw()
    to_data = view.ax.transData.inverted().transform
    snapped = view.trace.snapped
    names = {f"E{a + 1}{b + 1}" for a, b in view.trace.edges}
    assert {t.get_text() for t in view.triangle.edge_labels} == names
    assert len(names) == 3 and (("E12" in names) != ("E21" in names))  # one winding
    for label in view.triangle.edge_labels:
        box = label.get_window_extent()
        centre = to_data([[(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2]])[0]
        a, b = (int(c) - 1 for c in label.get_text()[1:])
        gap, t = _segment_distance(centre, snapped[a], snapped[b])
        others = [_segment_distance(centre, snapped[i], snapped[j])[0]
                  for i, j in [(0, 1), (1, 2), (2, 0)] if {i, j} != {a, b}]  # fmt: skip
        assert gap < min(others), (label.get_text(), centre)
        assert 0.15 < t < 0.85 and gap < 2.0, (label.get_text(), centre, t, gap)
        assert not any(box.overlaps(v.get_window_extent()) for v in view.triangle.labels)
