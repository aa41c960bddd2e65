"""PixelInspector: driven from code like a student would, its figure follows the controls."""

import re

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.text import Text  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.core.tile_trace import edge_name  # noqa: E402
from teachraster.plotting.antialiasing import edge_value_text  # noqa: E402
from teachraster.plotting.style import VALUE_CMAP  # noqa: E402
from teachraster.widgets import PixelInspector  # noqa: E402
from teachraster.widgets.common import SAMPLE_PATTERNS as PATTERNS  # noqa: E402
from teachraster.widgets.common import pattern_samples  # noqa: E402


@pytest.fixture
def scene():
    return np.array([[[-1, 1, 0, 1], [1, 1, 0, 1], [-1, -1, 0, 1]],
                     [[1, 1, 0.5, 1], [1, -1, 0.5, 1], [-1, -1, 0.5, 1]]], float)  # fmt: skip


def test_every_pattern_and_pixel_of_a_scene(scene):
    w = PixelInspector(scene, 8, 6, backend="image")
    try:
        for label in PATTERNS:
            w.pattern.value = label
            n = PATTERNS[label][0]
            assert w.result.sample_triangle_id.shape == (6, 8, n)
            assert len(w.pixel.dots) == n and len(w.samples.covered.get_offsets()) == 6 * 8 * n
        w.row.value, w.col.value = 3, 5
        x, y = w.marker.get_data()
        assert (min(x), min(y)) == (5, 3)
        # more than 4 samples: each labelled by its number only (readable at 16)
        assert [t.get_text() for t in w.pixel.labels] == [str(s) for s in range(len(w.pixel.dots))]
        w.pattern.value = "4 standard (rotated grid)"
        ids = w.result.sample_triangle_id[3, 5]
        for s, label in enumerate(w.pixel.labels):
            assert f"triangle {ids[s]}" in label.get_text()
    finally:
        w.close()


def test_single_triangle_labels_edge_values():
    tri = tr.Triangle([[0.6, 0.4], [9.3, 2.1], [2.2, 7.7]])
    w = PixelInspector(tri, 10, 8, row=2, col=1, backend="image")
    try:
        e = w.result.trace.samples.edge_values(2, 1)
        name = edge_name(*w.result.trace.edges[2])  # the third edge tested, e.g. "E31"
        # the edge names once, in the title's order; each label holds the sample's values
        assert name in w.pixel.square.axes.get_title()
        assert all(
            edge_value_text(e[s, 2]) in lab.get_text() for s, lab in enumerate(w.pixel.labels)
        )
        w.pattern.value = "1 (centre)"
        assert w.result.sample_coverage.shape[2] == 1
        assert isinstance(pattern_samples("4 ordered grid"), np.ndarray)
    finally:
        w.close()


def test_fill_player_samples_chooser():
    from teachraster.widgets import FillPlayer

    tri = tr.Triangle([[1.3, 1.2], [14.6, 4.7], [5.2, 14.1]], attrs={"u": [0, 1, 0]})
    p = FillPlayer(tri, 16, 16, backend="image")
    try:
        assert p.sample_dots is None and p.fill.sample_coverage is None
        p.slider.value = 12
        p.samples.value = "4 standard (rotated grid)"
        cov = p.fill.sample_coverage
        assert cov.shape == (16, 16, 4)
        # drawn only in the pixels an edge crosses (review r23, 00 c14: four dots in every
        # pixel hid the fill)
        partial = cov.any(axis=2) & ~cov.all(axis=2)
        # a sample shows as covered once the step that tests its pixel has come (at step 12
        # some, at the last step all of them)
        assert 0 < len(p.sample_dots.covered.get_offsets()) <= cov[partial].sum()
        assert p.slider.value == 12 and p.caption_text == p.trace.caption(12)
        p.slider.value = p.slider.max
        assert len(p.sample_dots.covered.get_offsets()) == cov[partial].sum() > 0
        p.method.value = "halfplane"  # the samples follow the method change
        assert p.fill.sample_coverage.shape == (16, 16, 4)
        p.samples.value = "16 jittered"
        cov = p.fill.sample_coverage
        partial = cov.any(axis=2) & ~cov.all(axis=2)
        assert len(p.sample_dots.covered.get_offsets()) == cov[partial].sum() > 0
        p.samples.value = "1 (centre)"
        assert not p.sample_dots.covered.get_visible()
        assert p.frames.gen > 0  # each fill shown was sent to the page
    finally:
        p.close()


def test_inspector_legible_at_16_samples_and_at_the_last_pixel():
    """Review r2, 08: at 16 samples the left panel was a field of overlapping dots, the last
    pixel's marker was half clipped, the right panel's labels were 8-9 pt."""
    import matplotlib as mpl

    tri = tr.Triangle([[1.3, 0.6], [19.4, 4.2], [5.1, 13.7]])
    w = PixelInspector(tri, 20, 14, row=13, col=19, backend="image")
    try:
        assert not w.marker.get_clip_on()  # the last row's and column's marker drawn whole
        assert w.samples.covered.get_visible()  # 4 samples: every sample drawn
        size = float(mpl.rcParams["font.size"])
        assert all(lab.get_fontsize() >= 0.75 * size for lab in w.pixel.labels)
        w.pattern.value = "16 standard"
        assert not w.samples.covered.get_visible() and not w.samples.uncovered.get_visible()
        # review r61 08-2: the greys have a key, 0 to 1, under the grid, clear of it
        key = w.fraction_key
        assert key.ax.get_visible() and "covered fraction" in key.ax.get_xlabel()
        assert key.mappable.norm.vmin == 0 and key.mappable.norm.vmax == 1
        w.fig.canvas.draw()
        r = w.fig.canvas.get_renderer()
        grid, bar = w._left.get_window_extent(r), key.ax.get_tightbbox(r)
        assert bar.y1 < grid.y0 and bar.y0 >= 0, (bar, grid)
        # the key's colour at 1 is that of a fully covered pixel; review r136 08-7: in the
        # colour map of the lesson's other coverage figures, not in greys
        full = w.samples.fraction.image
        for f in (0.0, 0.5, 1.0):
            assert np.allclose(full.cmap(full.norm(f)), key.cmap(key.norm(f)))
        assert full.cmap.name == key.cmap.name == VALUE_CMAP
        assert all(lab.get_fontsize() >= 0.75 * size for lab in w.pixel.labels)
        w.pattern.value = "4 ordered grid"  # back to few samples: the dots return
        assert w.samples.covered.get_visible() and "every sample" in w._left_note.get_text()
        assert not w.fraction_key.ax.get_visible()  # the dots show it: no key
        # the ordered grid's edge-value labels do not overlap (they point out of the pixel)
        w.row.value, w.col.value = 3, 13
        w.fig.canvas.draw()
        r = w.fig.canvas.get_renderer()
        boxes = [lab.get_window_extent(r) for lab in w.pixel.labels]
        assert not any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1 :])
    finally:
        w.close()


@pytest.mark.parametrize(
    "pattern", ["4 standard (rotated grid)", "4 ordered grid", "2 standard", "1 (centre)"]
)
def test_edge_value_labels_stay_inside_the_panel_clear_of_the_pixel_and_each_other(pattern):
    """Review r10 (lesson 08 c32): s1's label "+132.31" ran over the panel's right frame;
    reviews r8-r11 (08-1): the labels ("+132.31", "+127.91") crossed the pixel's grey frame.
    Every label (and its box) lies inside the panel, outside the pixel's frame, clear of
    every other label, on its dot's side of the pixel, joined to its dot by a leader.
    Review r29 (08-2): the triangle's edge line ran through s0's "+127.91" and, with one
    sample, "+53.53": no edge line crosses a label's box."""
    from teachraster.plotting import use_style

    with use_style("classroom"):  # as lesson 08: the largest labels
        tri = tr.Triangle([[1.3, 1.6], [18.7, 4.2], [6.1, 12.8]])
        w = PixelInspector(tri, 20, 14, row=3, col=13, pattern=pattern, backend="image")
        try:
            for row, col in ((3, 13), (0, 0), (13, 19), (8, 10), (7, 3)):  # (7, 3): on E31
                w.row.value, w.col.value = row, col
                w.fig.canvas.draw()
                r = w.fig.canvas.get_renderer()
                ax = w.pixel.square.axes
                frame = ax.get_window_extent(r)
                pixel = w.pixel.square.get_window_extent(r)  # the grey frame, its line width in
                boxes = [lab.get_bbox_patch().get_window_extent(r) for lab in w.pixel.labels]
                assert len(boxes) == len(w.pixel.dots)
                edges = [e.get_transform().transform_path(e.get_path()) for e in w.pixel.edges]
                for s, (lab, box) in enumerate(zip(w.pixel.labels, boxes)):
                    where = (pattern, row, col, s)
                    assert frame.x0 < box.x0 and box.x1 < frame.x1, where
                    assert frame.y0 < box.y0 and box.y1 < frame.y1, where
                    assert not box.overlaps(pixel), where  # crosses no side of the pixel
                    assert not any(box.overlaps(b) for b in boxes[s + 1 :]), where
                    assert not any(e.intersects_bbox(box, filled=False) for e in edges), where
                    dot = w.pixel.dots[s].get_xydata()[0]
                    assert np.allclose(lab.xy, dot) and lab.arrow_patch is not None
                    left = dot[0] - col < 0.5  # beside the pixel on the dot's side
                    assert box.x1 < pixel.x0 if left else box.x0 > pixel.x1, where
        finally:
            w.close()


def test_sixteen_samples_numbers_clear_each_other_and_the_table_gives_edge_values():
    """Review 08-09-r5 (08 item 4): at "16 random" the numbers collided ("2" and "13" read
    "213") and the "0" sat on the centre's cross; at 8 and 16 samples no edge value was
    shown; at 4 samples the left panel's dots overlapped. Now the numbers are placed clear
    of each other, the dots and the cross; a table lists every sample's edge values (one
    precision, "0" exactly on an edge); the left panel's dots are smaller than their gaps."""
    tri = tr.Triangle([[1.3, 1.6], [18.7, 4.2], [6.1, 12.8]])  # lesson 08's
    w = PixelInspector(tri, 20, 14, row=3, col=13, backend="image")
    try:
        # 4 standard samples on the left: dots narrower than the closest two samples
        ax = w.samples.covered.axes
        (x0, x1), bbox = ax.get_xlim(), ax.get_window_extent()
        pt_per_px = bbox.width / abs(x1 - x0) * 72 / w.fig.dpi
        gap = min(np.hypot(*(a - b)) for i, a in enumerate(w.result.samples)
                  for b in w.result.samples[i + 1 :])  # fmt: skip
        assert w.samples.uncovered.get_markersize() < gap * pt_per_px
        for pattern in ("16 random", "16 standard", "8 standard"):
            w.pattern.value = pattern
            w.fig.canvas.draw()
            r = w.fig.canvas.get_renderer()
            # the numbers' own boxes (an annotation's extent includes its leader, which may
            # cross the pixel's side from a dot near it)
            boxes = [Text.get_window_extent(lab, r) for lab in w.pixel.labels]
            assert len(boxes) == len(w.result.samples)
            # review r136 08-10: each number joined to its dot by a leader (at 16 random a
            # number sat between two dots and named either)
            for lab, dot in zip(w.pixel.labels, w.pixel.dots):
                assert lab.arrow_patch is not None and np.allclose(lab.xy, dot.get_xydata()[0])
            assert not any(a.overlaps(b) for i, a in enumerate(boxes) for b in boxes[i + 1 :])
            centre = w.pixel.centre.get_window_extent(r)
            assert not any(b.overlaps(centre) for b in boxes), pattern
            # review r29 (08-2): no number on the edge line or on a side of the pixel (placed
            # with the pixel's size as drawn, after the equal aspect shrank the panel)
            edges = [e.get_transform().transform_path(e.get_path()) for e in w.pixel.edges]
            square = w.pixel.square.get_transform().transform_path(w.pixel.square.get_path())
            for b in boxes:
                assert not any(e.intersects_bbox(b, filled=False) for e in edges), pattern
                assert not square.intersects_bbox(b, filled=False), pattern
            e = w.result.trace.samples.edge_values(3, 13)
            assert w.table.value.count("<tr>") == len(e) + 1
            assert all(edge_value_text(v) in w.table.value for v in e.ravel())
        # review r61 08-2: every offset at one precision, 4 decimals ("0.03906" was "0.0391")
        offsets = re.findall(r"<td>\(([^)]*)\)</td>", w.table.value)
        assert len(offsets) == len(w.result.samples) and all(
            re.fullmatch(r"\d\.\d{4}, \d\.\d{4}", o) for o in offsets
        )
        w.row.value = 4  # the table follows the pixel
        assert "pixel (row 4, col 13)" in w.table.value
    finally:
        w.close()


def test_edge_values_exactly_zero_are_marked_in_the_table():
    """A sample exactly on an edge shows E = 0 and "(on the edge)": where the top-left rule
    decides (the cell above the inspector promises it can be seen)."""
    tri = tr.Triangle([[0.0, 0.5], [8.0, 0.5], [0.0, 6.0]])  # top edge through y = 0.5
    w = PixelInspector(tri, 8, 6, row=0, col=2, pattern="1 (centre)", backend="image")
    try:
        assert "0 (on the edge)" in w.table.value and "yes" in w.table.value  # a top edge
    finally:
        w.close()


def test_labels_stay_in_the_panel_by_a_corner_where_two_edges_meet():
    """Pixel (3, 16) of lesson 08's triangle lies by its corner (18.7, 4.2): moving s1's and
    s3's labels off both edges pushed them past the panel, the margins grew until the pixel
    was a quarter of the panel and s1's label sat on the title. A label now moves only within
    the panel (it may touch an edge line there)."""
    from teachraster.plotting import use_style

    with use_style("classroom"):
        tri = tr.Triangle([[1.3, 1.6], [18.7, 4.2], [6.1, 12.8]])
        w = PixelInspector(tri, 20, 14, row=3, col=16, backend="image")
        try:
            w.fig.canvas.draw()
            r = w.fig.canvas.get_renderer()
            ax = w.pixel.square.axes
            frame, title = ax.get_window_extent(r), ax.title.get_window_extent(r)
            pixel = w.pixel.square.get_window_extent(r)
            assert pixel.width > 0.3 * frame.width, (pixel, frame)
            for lab in w.pixel.labels:
                box = lab.get_bbox_patch().get_window_extent(r)
                assert frame.y0 <= box.y0 and box.y1 <= frame.y1 and not box.overlaps(title)
        finally:
            w.close()


def test_sixteen_random_numbers_sit_clearly_nearest_their_own_dot():
    """Review r69 08-2: at pixel (13, 0), "16 random", the numbers crowded by the pixel's top
    side, where dots lie 0.12 px apart: each number's centre is now at least
    OWN_DOT_MARGIN times nearer its own dot than any other (a dot matched to its number
    without the table)."""
    from teachraster.plotting.antialiasing import OWN_DOT_MARGIN

    tri = tr.Triangle([[1.3, 1.6], [18.7, 4.2], [6.1, 12.8]])  # lesson 08's
    w = PixelInspector(tri, 20, 14, row=13, col=0, pattern="16 random", backend="image")
    try:
        for row, col in ((13, 0), (3, 13)):
            w.row.value, w.col.value = row, col
            w.fig.canvas.draw()
            r = w.fig.canvas.get_renderer()
            ax = w.pixel.labels[0].axes
            offsets = w.result.samples
            dots = ax.transData.transform(np.column_stack([col + offsets[:, 0],
                                                           row + offsets[:, 1]]))  # fmt: skip
            for s, lab in enumerate(w.pixel.labels):
                box = lab.get_window_extent(r)
                d = np.hypot(*(dots - [box.x0 + box.width / 2, box.y0 + box.height / 2]).T)
                assert d[s] * OWN_DOT_MARGIN <= np.delete(d, s).min(), (row, col, s)
    finally:
        w.close()


def test_review_r230_window_dots_tight_panel_clicks_and_top_left_edges():
    """Review r230 FIG2: the magnified panel ran to y = 4.6 below a pixel ending at 4.0, an
    empty band; the left panel drew lesson 08's 280 pixels with 4 dots of about 3 px each.
    Now the left panel shows a window around the chosen pixel (its dots at least 8 points),
    and each side of the magnified pixel has its own margin. S8: a click picks a pixel, and
    the table names the top or left edges."""
    from teachraster.plotting import use_style

    with use_style("classroom"):
        tri = tr.Triangle([[1.3, 1.6], [18.7, 4.2], [6.1, 12.8]])  # lesson 08's
        w = PixelInspector(tri, 20, 14, row=3, col=13, backend="image")
        try:
            assert w._window_size[0] < 20 and w._window_size[1] < 14  # a window, not all
            (x0, x1), (y1, y0) = w._left.get_xlim(), w._left.get_ylim()
            assert x0 <= 13 < 14 <= x1 and y0 <= 3 < 4 <= y1  # around the chosen pixel
            assert w.samples.uncovered.get_markersize() >= 7.5  # points (3 px before)
            w.fig.canvas.draw()
            r = w.fig.canvas.get_renderer()
            ax = w.pixel.square.axes
            frame = ax.get_window_extent(r)
            boxes = [lab.get_bbox_patch().get_window_extent(r) for lab in w.pixel.labels]
            pixel = w.pixel.square.get_window_extent(r)
            low = min([b.y0 for b in boxes] + [pixel.y0])
            high = max([b.y1 for b in boxes] + [pixel.y1])
            gap_pt = 20 * w.fig.dpi / 72  # the labels' pad and gap, and a little more
            assert low - frame.y0 < gap_pt and frame.y1 - high < gap_pt, (low, high, frame)
            # the window follows the pixel, to the image's last column
            w.col.value = 19
            assert w._left.get_xlim()[1] == 20
            # a click on the left panel picks the pixel under it
            w.click_at(5.5, 9.25)
            assert (w.row.value, w.col.value) == (9, 5)
            assert "pixel (row 9, col 5)" in w.pixel.square.axes.get_title()
            assert "pixel (row 9, col 5)" in w.table.value
            # S8: which edges are top or left, from the rule itself
            names = [edge_name(a, b) for a, b in w.result.trace.edges]
            top_left = [n for (a, b), n in zip(w.result.trace.edges, names)
                        if tr.is_top_left(tri.xy[a], tri.xy[b])]  # fmt: skip
            assert top_left == ["E31"]
            assert (
                "the triangle's top or left edge(s), which cover a sample exactly on them: E31"
                in w.table.value
            )
        finally:
            w.close()


def test_both_panels_label_a_pixel_in_screen_coordinates():
    """Review r245 S2 (lesson 08 §8): the left panel labelled row and column indices at pixel
    centres, the magnified pixel coordinates at its borders (13.0 ... 14.0): pixel 13 sat
    between the ticks 12 and 14 on the left, 13 and 14 on the right. Both now give x, y on
    the pixels' borders, the chosen pixel between the ticks j and j + 1 (or a step apart)."""
    tri = tr.Triangle([[1.3, 1.6], [18.7, 4.2], [6.1, 12.8]])
    w = PixelInspector(tri, 20, 14, row=3, col=13, backend="image")
    try:
        left, right = w._left, w.pixel.square.axes
        for ax in (left, right):
            xs, ys = ax.get_xticks(), ax.get_yticks()
            assert np.allclose(xs * 2, np.round(xs * 2)) and np.allclose(ys * 2, np.round(ys * 2))
        # the left panel: whole coordinates only, named x and y, the window's edges included
        assert np.allclose(left.get_xticks(), np.round(left.get_xticks()))
        assert left.get_xlabel() == "x" and left.get_ylabel() == "y"
        x0, x1 = left.get_xlim()
        assert x0 in left.get_xticks() and x0 <= 13 < 14 <= x1
        assert list(right.get_xticks()) == [13, 13.5, 14]
        w.col.value = 4  # the window moves; its ticks stay coordinates on the borders
        assert np.allclose(left.get_xticks(), np.round(left.get_xticks()))
        assert left.get_xlim()[0] <= 4 < 5 <= left.get_xlim()[1]
    finally:
        w.close()
