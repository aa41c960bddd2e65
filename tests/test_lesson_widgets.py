"""The lessons' own widgets (plane explorer, depth-precision explorer, case picker), driven
from code: every control changes what is shown, and the numbers shown are the package's."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.widgets.plane_explorer import (  # noqa: E402
    PlaneExplorer,
    level_segments,
    plane_system,
)


# -- PlaneExplorer -------------------------------------------------------------------------------
@pytest.fixture
def explorer():
    ex = PlaneExplorer([[2, 1], [13, 5], [5, 12]], [0.2, 0.9, 0.5], 16, 14, backend="image")
    yield ex
    ex.close()


def test_plane_system_three_ways_agree():
    rng = np.random.default_rng(3)
    for _ in range(20):
        xy, f = rng.uniform(0, 20, (3, 2)), rng.uniform(-1, 1, 3)
        s = plane_system(xy, f)
        gx, gy, g0 = s["g"]
        assert np.allclose(s["system"] @ s["g"], f)  # the 3 x 3 system is solved
        assert np.allclose(s["g_recentred"], [gx, gy])  # M gives the same gradient
        A, B, C, D = s["ABCD"]
        assert np.isclose(C, s["area2"])
        assert np.allclose([-A / C, -B / C], [gx, gy])  # dx, dy of the other note
        assert np.allclose(tr.attribute_plane(xy, f)(*xy.T), f)


def _page_move(ex, i, x, y, final, seq=1):
    """A position of vertex ``i`` as the page's drag sends it (static/drag.js)."""
    ex.display.widget._on_page_message(
        None, {"type": "move", "i": i, "x": x, "y": y, "seq": seq, "final": final}, []
    )


def test_plane_explorer_vertices_are_dragged_in_the_page(explorer):
    """Issue 31: lesson 03's explorer was slider-only. Its vertices are the page figure's
    handles (the TriangleEditor's drag, static/drag.js): mid-drag the kernel fills the
    dragged triangle with tr.rasterize (the top-left rule) and sends drafts, and the sliders
    take each position (r209 03-4: their readouts kept the old value until the release), on
    their quarter-pixel grid, within their range; the handles follow for the next press."""
    page = explorer.display.widget
    assert page.handles == [[2.0, 1.0], [13.0, 5.0], [5.0, 12.0]] and page.on_move is not None
    draws = explorer.display.draws
    _page_move(explorer, 0, 3.1, 2.4, final=False)
    assert explorer.display.draws == draws + 1 and explorer._drafting()
    labels = [a for a in explorer.triangle.artists if a.get_visible() and hasattr(a, "get_text")]
    assert labels  # hidden for the draft only (half its cost): shown on the figure again
    # the sliders follow mid-drag, without a picture of their own (one draw above)
    assert [explorer.x[0].value, explorer.y[0].value] == [3.0, 2.5] and explorer._drafting()
    dragged = [[3.0, 2.5], [13.0, 5.0], [5.0, 12.0]]
    assert explorer.shown_xy.tolist() == dragged
    _page_move(explorer, 0, 8.0, 13.0, final=False, seq=2)  # v1 onto the edge v2 v3's line
    _page_move(explorer, 0, 20.4, -3.0, final=True, seq=3)  # let go beyond the grid: clipped
    assert not explorer._drafting()
    assert [explorer.x[0].value, explorer.y[0].value] == [16.0, 0.0]
    xy = [[16.0, 0.0], [13.0, 5.0], [5.0, 12.0]]
    assert page.handles == xy and explorer.shown_xy.tolist() == xy
    inside = tr.rasterize(tr.Triangle(xy), 16, 14).coverage
    assert np.array_equal(~np.isnan(explorer.values), inside)
    assert np.allclose(explorer.system["g"], plane_system(xy, [0.2, 0.9, 0.5])["g"])
    _page_move(explorer, 2, 5.13, 11.88, final=True, seq=4)  # a click: one final position
    assert [explorer.x[2].value, explorer.y[2].value] == [5.25, 12.0]


def test_plane_explorer_reads_positions_as_lesson_03_does(explorer):
    """Ticks at whole screen coordinates (v1 = (2, 1) on its ticks, as lesson 03's figure),
    and a colour bar that says what it measures (review a1, 03)."""
    ax = explorer.ax
    assert ax.get_xlabel() == "x" and ax.get_ylabel() == "y"
    assert 2.0 in ax.get_xticks() and 0.5 not in ax.get_xticks()
    assert [t.get_text() for t in ax.get_xticklabels()][:2] == ["0", "2"]
    # what the colours are: on the colour bar (the title's row saved: one screen)
    assert explorer.image.colorbar.ax.get_ylabel() == "f at the pixel centres"


def test_plane_explorer_text_at_projector_size(explorer):
    """Review r96 03-3: the sliders' names and values and the 3 x 3 system were 12-13 px,
    the smallest text of lesson 03. The sliders take the projector's 16 px (wide enough for
    it: name, track and value need 280 px there), the numbers beside the figure 15 px, the
    system's monospace table included."""
    from teachraster.widgets.common import PROJECTOR_CSS

    title = explorer.widget.children[0].value
    assert title.startswith(PROJECTOR_CSS) and "tr-projector" in explorer.widget._dom_classes
    assert ".tr-live-slider" in PROJECTOR_CSS and "font-size: 16px" in PROJECTOR_CSS
    for s in (*explorer.x, *explorer.y, *explorer.f):
        assert int(s.layout.width.removesuffix("px")) >= 280
    info = explorer.info.value
    assert "font-size:15px" in info.split("3 × 3 system")[0]
    assert "<table style='font-family:monospace; font-size:15px" in info


def test_plane_explorer_fits_one_screen_with_its_sliders(explorer):
    """Lesson 03's explorer under its three rows of sliders on a projector (1024 x 768, about
    600 px for the widget): its figure was 576 px high, a title row above the ticks; now at
    most 450 px (at the page's dpi and at the classroom style's), the grid most of it."""
    from teachraster.plotting import use_style

    with use_style("classroom"):
        ex = PlaneExplorer(backend="image")
    try:
        fig = ex.fig
        for dpi in (fig.dpi, 100):  # the page's 96 dpi, the classroom style's 100
            assert fig.get_figheight() * dpi <= 450
        fig.canvas.draw()
        grid = ex.ax.get_window_extent()
        assert grid.height >= 0.8 * fig.bbox.height and not ex.ax.get_title()
        assert grid.x1 <= fig.bbox.x1 and grid.width >= 0.6 * fig.bbox.width
    finally:
        ex.close()


@pytest.mark.parametrize("f", [(-1.0, 2.0, 0.5), (0.2, 0.9, -0.3), (-0.8, -0.9, -0.85),
                               (-1.0, -1.0, -1.0), (-0.1, 0.0, -0.2)])  # fmt: skip
def test_plane_explorer_colour_bar_label_fits_whatever_the_values(f):
    """Review r11 (03 c33): the layout, solved once with positive tick labels, left no room
    for "−1.0": with any f below 0 the colour bar's label "f at the pixel centres", the only
    text saying what the colours are, ran off the figure's right edge. Room is left for the
    widest label the sliders can make; labels and ticks stay whole."""
    from teachraster.plotting import use_style

    with use_style("classroom"):
        ex = PlaneExplorer(backend="image")
    try:
        for k, value in enumerate(f):
            ex.f[k].value = value
        fig, bar = ex.fig, ex.image.colorbar
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        label = bar.ax.yaxis.label
        assert label.get_text() == "f at the pixel centres"
        box = bar.ax.get_tightbbox(renderer)  # the bar, its tick labels and its label
        assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1, (f, box.x1, fig.bbox.x1)
        assert label.get_window_extent(renderer).x1 <= fig.bbox.x1
        assert ex.ax.get_window_extent().x1 < box.x0  # beside the grid, not over it
        ticks = [t.get_text() for t in bar.ax.get_yticklabels() if t.get_text()]
        assert ticks and all(len(t) <= 5 for t in ticks), ticks  # "−0.00" at most
    finally:
        ex.close()


def test_plane_explorer_starts_every_slider_on_one_of_its_positions(explorer):
    """Review r7 03-3: with f in steps of 0.25, lesson 03's f = 0.2 and 0.9 sat between two
    positions (the thumb at 0.25, the readout 0.20) and could never be set again."""
    from teachraster.widgets.ahead import slider_positions

    for s in [*explorer.x, *explorer.y, *explorer.f]:
        assert np.isclose(slider_positions(s), s.value, atol=1e-9).any(), (s.description, s.value)


def test_plane_explorer_colours_the_pixels_rasterize_covers(explorer):
    """Review r112 03-W1: the explorer coloured every centre with all λ >= 0, so a centre
    exactly on a non-top-left edge (common on the sliders' quarter-pixel grid) was drawn:
    453 of 2,000 reachable triangles differed from ``tr.rasterize``. Its coverage now comes
    from the core's fill (the one top-left rule), for every triangle the sliders reach."""
    explorer.display.refresh = lambda: None  # the values are tested, not the picture
    rng = np.random.default_rng(112)
    ys, xs = np.mgrid[0:14, 0:16] + 0.5
    centres = np.stack([xs, ys], axis=-1)
    triangles = [np.array([[7.5, 13.5], [8.25, 0.25], [12.25, 2.0]])]  # r112's example
    triangles += [np.column_stack([rng.integers(0, 65, 3), rng.integers(0, 57, 3)]) / 4
                  for _ in range(300)]  # fmt: skip
    on_an_edge = 0
    for xy in triangles:
        # the six sliders set quietly, then one update from them (as a vertex dragged in the
        # page sets its two, _on_page_move): a picture per slider moved cost six updates a
        # triangle, five of them of a triangle not checked; update() reads only the sliders
        explorer._quiet = True
        try:
            for k in range(3):
                explorer.x[k].value, explorer.y[k].value = xy[k]
        finally:
            explorer._quiet = False
        explorer.update()
        assert np.array_equal(explorer.xy, xy)
        covered = tr.rasterize(tr.Triangle(xy), 16, 14).coverage
        assert np.array_equal(~np.isnan(explorer.values), covered), xy.tolist()
        e = [tr.edge_function(xy[k], xy[(k + 1) % 3], centres) for k in range(3)]
        on_an_edge += any(
            ((ek == 0) & (el * em > 0)).any()
            for ek, el, em in [(e[0], e[1], e[2]), (e[1], e[2], e[0]), (e[2], e[0], e[1])]
        )
    assert on_an_edge >= 30  # the ties the old rule got wrong are well represented


def test_plane_system_zero_area_has_no_plane():
    s = plane_system([[0, 0], [1, 1], [2, 2]], [0, 1, 2])
    assert s["area2"] == 0 and "g" not in s and "M" not in s


def test_level_segments_lie_on_their_level():
    g = np.array([0.3, -0.7, 1.1])
    for level, seg in zip([0.0, 2.5], level_segments(g, [0.0, 2.5], 16, 14)):
        assert np.allclose(seg @ g[:2] + g[2], level)
    assert level_segments([0.0, 0.0, 1.0], [1.0], 8, 8) == []


def test_explorer_shows_the_plane_and_follows_the_sliders(explorer):
    shown = np.asarray(explorer.image.image.get_array(), dtype=float)
    fill = tr.rasterize(tr.Triangle(explorer.xy, attrs={"f": explorer.fvals}), 16, 14)
    inside = fill.coverage  # no centre lies on an edge here, so coverage = inside
    assert np.allclose(shown[inside], fill.attrs["f"][inside])
    assert np.isnan(shown[~inside]).all()
    before = explorer.info.value
    explorer.f[2].value = 1.7
    assert explorer.info.value != before and "1.70" in explorer.info.value
    assert np.isclose(np.nanmax(explorer.values), 1.7, atol=0.3)
    segments = explorer.contours.get_segments()
    g = explorer.system["g"]
    assert len(segments) > 0
    for seg in segments:  # all parallel: the same value along each
        values = np.asarray(seg) @ g[:2] + g[2]
        assert np.isclose(values[0], values[1])


def test_explorer_survives_a_zero_area_triangle(explorer):
    for k, (x, y) in enumerate([(1, 1), (5, 5), (9, 9)]):
        explorer.x[k].value, explorer.y[k].value = x, y
    assert "zero area" in explorer.info.value
    assert np.isnan(explorer.values).all()
    assert explorer.contours.get_segments() == []
    # review r143 03-9: the panel says what lesson 03's text promises, C = 0 and no M
    assert "C = 2 × signed area = 0.000" in explorer.info.value
    assert "M (which carries 1/C) does not exist" in explorer.info.value


def test_explorer_collinear_labels_leave_the_line_visible(explorer):
    """Review r143 03-9: on one line (v2 = (2.75, 3.75) on v3v1) the labels were pushed along
    the line, and their white boxes hid the segment v1v2; now they stand beside it."""
    explorer.x[1].value, explorer.y[1].value = 2.75, 3.75
    assert explorer.system["area2"] == 0
    explorer.fig.canvas.draw()
    v1, v2 = explorer.ax.transData.transform(explorer.xy[:2])
    # the segment v1v2 between the vertex dots: no point of it under a label's box
    points = v1 + np.linspace(0.15, 0.85, 29)[:, None] * (v2 - v1)
    for label in explorer.triangle.labels:
        box = label.get_bbox_patch().get_window_extent()
        inside = [box.contains(*point) for point in points]
        assert not any(inside), label.get_text()


def test_explorer_title_says_the_contours_go_on_beyond_the_triangle(explorer):
    """Review r143 03-9: the dashed lines cross the whole grid, outside the triangle too; the
    title says that the plane goes on there (lessons 08 and 09 read it outside)."""
    assert "go on beyond the triangle" in explorer.widget.children[0].value
    xs = np.concatenate([np.asarray(seg)[:, 0] for seg in explorer.contours.get_segments()])
    assert xs.min() < 0 and xs.max() > explorer.width  # not clipped to the triangle


CORNERS = {  # review r216 03-5: the vertices the sliders' ends give, labels crowded
    "v1 at (0, 0)": [[0, 0], [13, 5], [5, 12]],
    "v1 at (16, 14)": [[16, 14], [13, 5], [5, 12]],
    "v2 at (16, 14), v3 at (0, 0)": [[2, 1], [16, 14], [0, 0]],
    "three corners": [[0, 14], [16, 0], [16, 14]],
    "v2 and v3 side by side": [[0, 0], [16, 14], [15, 14]],
    "a small triangle": [[8, 7], [9, 7], [8, 8]],
}


@pytest.fixture
def classroom_explorer():
    """Lesson 03's explorer as the lesson shows it: in the classroom style's large labels."""
    from teachraster.plotting import use_style

    with use_style("classroom"):
        ex = PlaneExplorer(backend="image")
    yield ex
    ex.close()


def _label_boxes(ex):
    ex.fig.canvas.draw()
    return [label.get_bbox_patch().get_window_extent() for label in ex.triangle.labels]


@pytest.mark.parametrize("name", sorted(CORNERS))
def test_plane_explorer_vertex_labels_leave_dots_edges_and_each_other(classroom_explorer, name):
    """Review r216 03-5: with v1 at (0, 0) its label's box covered the dot and the first 2 px
    of both edges; at (16, 14) the dot; with v3 at (0, 0) "v3" lay on "v1". Every label now
    stays inside the grid, off every dot, off the edges and off the other labels."""
    explorer = classroom_explorer
    xy = np.array(CORNERS[name], dtype=float)
    for k in range(3):
        explorer.x[k].value, explorer.y[k].value = xy[k]
    boxes = _label_boxes(explorer)
    frame = explorer.ax.get_window_extent()
    dots = explorer.ax.transData.transform(xy)
    radius = explorer.triangle.vertices.get_markersize() / 2 * explorer.fig.dpi / 72
    for k, box in enumerate(boxes):
        assert frame.x0 - 1 <= box.x0 and box.x1 <= frame.x1 + 1, (name, k)
        assert frame.y0 - 1 <= box.y0 and box.y1 <= frame.y1 + 1, (name, k)
        for dot in dots:  # no dot under a box, nor a box over part of one
            assert not box.padded(radius).contains(*dot), (name, k)
        for j in range(k):
            assert not box.overlaps(boxes[j]), (name, k, j)
        for a, b in zip(dots, np.roll(dots, -1, axis=0)):  # the edges, between the dots
            points = a + np.linspace(0, 1, 201)[:, None] * (b - a)
            points = points[
                (np.hypot(*(points - a).T) > radius) & (np.hypot(*(points - b).T) > radius)
            ]
            assert not any(box.contains(*p) for p in points), (name, k)
    assert not explorer.triangle.vertices.get_clip_on()  # a dot at a corner shown whole


@pytest.mark.parametrize("f, levels", [((0.2, 0.9, 0.5), [0.3, 0.4, 0.5, 0.6, 0.7, 0.8]),
                                       ((-1.0, 2.0, 0.5), [-0.5, 0.0, 0.5, 1.0, 1.5]),
                                       ((0.2, 0.2, 0.5), [0.25, 0.3, 0.35, 0.4, 0.45])])  # fmt: skip
def test_plane_explorer_contours_at_round_values_some_labelled(classroom_explorer, f, levels):
    """Review r216 03-6: the contour lines lay at f = -0.57, -0.14, 0.29, ... (steps of 0.429)
    and no line carried its value. They lie at round steps now, and every other line (all of
    a few) carries its value on the line, inside the grid, clear of the vertex labels and of
    one another."""
    explorer = classroom_explorer
    for k, value in enumerate(f):
        explorer.f[k].value = value
    assert explorer.levels.tolist() == levels
    boxes = _label_boxes(explorer)
    shown = [t for t in explorer.level_labels if t.get_visible()]
    assert 2 <= len(shown) <= 3
    g = explorer.system["g"]
    frame = explorer.ax.get_window_extent()
    for t in shown:
        value = float(t.get_text().replace("−", "-"))
        assert value in levels and np.isclose(np.dot(g[:2], t.get_position()) + g[2], value)
        box = t.get_bbox_patch().get_window_extent()
        assert frame.contains(box.x0, box.y0) and frame.contains(box.x1, box.y1)
        assert not any(box.overlaps(b) for b in boxes)
        boxes.append(box)
    if min(levels) < 0:  # a minus sign, not a hyphen
        assert "f = −0.5, 0.0" in explorer.info.value and "-0.5" not in explorer.info.value


def test_plane_explorer_promises_values_on_the_lines_only_where_they_stand(explorer):
    """Review r226 W1: with v1 at x = 16 (a sliver) the six contour lines packed into a band a
    pixel wide, one value or none fitted, and the numbers still said "values on the lines"."""
    visible = lambda: sum(t.get_visible() for t in explorer.level_labels)  # noqa: E731
    assert visible() == explorer.labels_placed == 3
    assert "(steps of 0.1; values on the lines)" in explorer.info.value
    explorer.x[0].value = 16.0
    assert visible() == explorer.labels_placed < 3
    assert "values on the lines)" not in explorer.info.value
    assert "values on the lines where they fit)" in explorer.info.value
    explorer.labels_placed = 0  # none fitted: the numbers say so
    assert "the lines too close together here for their values" in explorer._info_html()


def test_plane_explorer_labels_wait_for_a_drag_to_end(explorer):
    """The values on the lines are hidden while a vertex is in hand, as the vertex labels."""
    _page_move(explorer, 0, 3.1, 2.4, final=False)
    explorer._draw()
    assert any(t.get_visible() for t in explorer.level_labels)  # hidden for the draft only
    _page_move(explorer, 0, 3.1, 2.4, final=True, seq=2)
    assert any(t.get_visible() for t in explorer.level_labels)


# -- DepthPrecisionExplorer ---------------------------------------------------------------------
def test_depth_explorer_curve_is_the_package_resolution():
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    ex = DepthPrecisionExplorer("unorm16", near=0.1, far=1000.0, backend="image")
    try:
        x, y = ex.curve.get_data()
        assert np.allclose(y, tr.depth_resolution(x, 0.1, 1000.0, "unorm16"))
        first16 = ex.fight_from
        assert first16 is not None and "z-fighting possible from Δz = δ at" in ex.info.value
        # the crossing Δz = δ, then the dotted line where a pair fights half the time, Δz = 2δ
        # (1 - δ/Δz = ½; review r54 05b-2), at √2 times the crossing: Δz grows like z²
        cross = float(ex.info.value.split("Δz = δ at <b>z ≈ ")[1].split("<")[0])
        assert cross == pytest.approx(
            float(np.sqrt(0.005 * 1000.0 * 0.1 / ((1000.0 - 0.1) / (2**16 - 1)))), rel=1e-2
        )
        assert ex.half_from == pytest.approx(np.sqrt(2) * cross, rel=1e-2)
        assert ex.marker.get_xdata()[0] == ex.half_from
        assert float(tr.depth_resolution(ex.half_from, 0.1, 1000.0, "unorm16")) == pytest.approx(
            0.01, rel=1e-3
        )
        ex.format.value = "unorm24"  # more bits: fighting starts farther away
        assert ex.fight_from > first16
        ex.near.value = 1.0  # the classic fix: a farther near plane
        assert ex.fight_from is None or ex.fight_from > 100
        x, y = ex.curve.get_data()
        assert x[0] >= 1.0 and np.allclose(y, tr.depth_resolution(x, 1.0, 1000.0, "unorm24"))
        # the reference curve stays where it started
        assert np.allclose(ex.reference.get_ydata()[:3], tr.depth_resolution(
            ex.reference.get_xdata()[:3], 0.1, 1000.0, "unorm16"))  # fmt: skip
        # review r170 05b-11: "keep as reference" puts the curve on show there, so the
        # Try-it's before and after are on screen together
        ex.keep.click()
        assert np.array_equal(ex.reference.get_ydata(), ex.curve.get_ydata())
        assert ex.ax.get_legend().get_texts()[0].get_text() == "kept: unorm24, near 1"
        ex.near.value = 0.1
        assert ex.reference.get_xdata()[0] >= 1.0 and ex.curve.get_xdata()[0] < 1.0
    finally:
        ex.close()


def test_depth_explorer_reverse_z_helps_float32_only():
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer, first_fight

    ex = DepthPrecisionExplorer("float32", backend="image")
    try:
        assert ex.fight_from is not None
        ex.reverse.value = True
        assert ex.mapping == "reversed" and ex.fight_from is None
        assert "no z-fighting" in ex.info.value
        # review r59 05b-1: no dotted line, so its key entry says so instead of naming one
        half = ex.ax.get_legend().get_texts()[-1]
        assert not np.isfinite(ex.marker.get_xdata()).any()
        assert half.get_text() == "fights half the time: nowhere here"
        ex.format.value = "unorm24"  # an even step: reversing gains nothing
        z = np.geomspace(1, 1000, 300)
        assert first_fight(z, 0.005, 0.1, 1000.0, "unorm24", "reversed") == first_fight(
            z, 0.005, 0.1, 1000.0, "unorm24", "perspective"
        )
        assert ex.fight_from is not None
    finally:
        ex.close()


# -- CasePicker ----------------------------------------------------------------------------------
def test_owner_image_marks_double_hits_and_gaps():
    from teachraster.widgets.case_picker import NONE, SEVERAL, owner_image

    a = np.zeros((3, 3), bool)
    b = np.zeros((3, 3), bool)
    a[0, :2] = True
    b[0, 1:] = True
    owner = owner_image([a, b])
    assert owner[0].tolist() == [0, SEVERAL, 1] and (owner[1:] == NONE).all()


def test_case_picker_copies_are_not_drawn_as_double_hits():
    # six_vertex_orders and translation_invariance are separate copies of one triangle: the
    # picker lays them onto the first instead of painting their overlap "covered twice", and
    # draws the naive coverage the lesson draws (it said "no naive coverage" for both)
    from teachraster.widgets.case_picker import CasePicker, copy_offsets

    picker = CasePicker("six_vertex_orders", backend="image")
    try:
        assert picker.offsets == [(0, 0)] * 6
        assert set(np.unique(picker.copies)) == {0, 6}  # every order: the same pixels
        assert int(((picker.naive_copies > 0) & (picker.naive_copies < 6)).sum()) == 63
        titles = [ax.get_title() for ax in picker.axes]
        assert "0 px differ" in titles[0] and "63 px differ" in titles[1]
        assert "no naive coverage" not in " ".join(titles) and "key" in picker.info.value
        picker.case.value = "translation_invariance"
        assert picker.offsets[1:] == [(1, 0), (0, 3), (10, 3), (17, 29), (31, 5)]
        assert set(np.unique(picker.copies)) == {0, 6}
        assert ((picker.naive_copies > 0) & (picker.naive_copies < 6)).any()
        picker.case.value = "fan_spokes_through_centres"  # a mesh: owners again
        assert picker.offsets is None and picker.copies is None
        assert copy_offsets([[[0, 0], [1, 0], [0, 1]], [[0, 0], [2, 0], [0, 1]]]) is None
    finally:
        picker.close()


def test_case_picker_titles_fit_and_a_long_sliver_stays_visible():
    """Review r2, 07: the two panel titles ran into each other ("…pixel → triangle" into
    "naive: max 16 hit(s) per pixel"), and diagonal_sliver's 62 owned pixels lay under a thick
    outline, two blank grids for a case whose point is 62 against 0."""
    from teachraster.widgets.case_picker import RULES, CasePicker, screen_cases

    picker = CasePicker("fan_spokes_through_centres", backend="image", style="classroom")
    try:
        # review r227 FIG-1: every case with every rule, in the lesson's classroom style:
        # titles apart, and each panel (its tick numbers too) inside the figure. The rules in
        # a snake order (a case's first rule is the last case's last), so that one change
        # draws each picture, not two; the picker's display drew it on the figure's canvas
        # (FigureDisplay.refresh), so the layout is read off that drawing, not a third one.
        draws = picker.display.draws
        for i, name in enumerate(screen_cases()):
            for rule in RULES if i % 2 == 0 else RULES[::-1]:
                before = (picker.case.value, picker.rule.value)
                picker.case.value, picker.rule.value = name, rule
                # drawn once (a change of case alone or of rule alone), or shown already
                assert picker.display.draws == draws + ((name, rule) != before), (name, rule)
                draws = picker.display.draws
                renderer = picker.fig.canvas.get_renderer()
                left, right = (ax.title.get_window_extent(renderer) for ax in picker.axes)
                assert not left.overlaps(right) and left.x0 >= 0, name
                assert right.x1 <= picker.fig.bbox.width, name
                for ax in picker.axes:
                    box = ax.get_tightbbox(renderer)
                    assert box.x0 >= 0 and box.y0 >= 0, (name, rule)
                    assert box.x1 <= picker.fig.bbox.width, (name, rule)
                    assert box.y1 <= picker.fig.bbox.height, (name, rule)
                assert picker.fig.get_suptitle().startswith(f"{name}, naive: {rule}")
        picker.case.value = "diagonal_sliver"
        titles = [ax.get_title() for ax in picker.axes]
        assert "62 px" in titles[0] and "0 px" in titles[1]  # the case's point, in the titles

        def outline_widths():
            return [line.get_linewidth() for ax in picker.axes for line in ax.lines
                    if line.get_linestyle() == "-"]  # fmt: skip

        assert outline_widths() and max(outline_widths()) < 1  # thin on the 64 x 64 grid
        picker.case.value = "d3d_split_square"  # an 8 x 8 grid keeps the classroom line width
        assert min(outline_widths()) > 1
    finally:
        picker.close()


def test_case_picker_zooms_to_each_case_and_shows_the_hub():
    """Review r5, 07-2: the fan sat in the middle third of its 20 x 20 image with the hub pixel
    under sixteen vertex dots, and sliver_pair (64 x 4) was a strip a few screen pixels high.
    Each case is now shown in its own box, no wider than MAX_ASPECT times its height, and a
    centre at a vertex of many triangles is drawn on top of their outlines."""
    from matplotlib.patches import Rectangle

    from teachraster.widgets.case_picker import (
        FIG_HEIGHT,
        MAX_ASPECT,
        MAX_VIEW,
        MIN_VIEW,
        VERTEX_COLOR,
        VERTEX_MARK,
        CasePicker,
    )

    picker = CasePicker("fan_spokes_through_centres", backend="image")
    try:
        r0, r1, c0, c1 = picker.view
        assert (r1 - r0, c1 - c0) == (15, 15) and picker.axes[0].get_xlim() == (c0, c1)
        assert picker.hubs == [(9, 9)] and picker.naive_counts[9, 9] == 16
        hub = [
            p for p in picker.axes[0].patches if isinstance(p, Rectangle) and p.get_xy() == (9, 9)
        ]
        assert hub and hub[0].get_zorder() > max(line.get_zorder() for line in picker.axes[0].lines)
        assert (
            "pixel (9, 9)" in picker.info.value
            and f"triangle {picker.owner[9, 9] + 1}" in picker.info.value  # numbered from 1
        )
        # review r65 07-1: vertices are hollow squares, not the "covered" centre's black dot,
        # and the centres' dots lie above the outlines; the key names both
        marks = [line for line in picker.axes[0].lines if line.get_marker() == "s"]
        # review r145 07-17: sixteen triangles get thin outlines and smaller marks (the owners
        # were unreadable under them on a projector)
        assert marks and {line.get_markersize() for line in marks} == {0.7 * VERTEX_MARK}
        assert max(line.get_linewidth() for line in picker.axes[0].lines
                   if line.get_marker() in ("None", "")) < 1  # fmt: skip
        assert all(line.get_markerfacecolor() == "none" for line in marks)
        assert all(line.get_markeredgecolor() == VERTEX_COLOR for line in marks)
        dots = [line for line in picker.axes[0].lines if line.get_marker() == "o"]
        outlines = [line for line in picker.axes[0].lines if line.get_marker() in ("None", "")]
        assert min(d.get_zorder() for d in dots) > max(o.get_zorder() for o in outlines)
        assert "□</span> a triangle's vertex" in picker.info.value
        assert "whose pixels share a side never alike" in picker.info.value
        picker.case.value = "sliver_pair"
        r0, r1, c0, c1 = picker.view
        assert picker.owner.shape == (4, 64) and (c1 - c0) <= MAX_ASPECT * (r1 - r0)
        assert (c0, c1) == (0, 12) and "columns 0–11 of 64" in picker.fig.get_suptitle()
        # review r6, 07-4: the 4 x 12 view in a figure as high as it needs, not 2/3 white
        assert picker.fig.get_figheight() < 0.65 * FIG_HEIGHT and picker.fig.get_figwidth() == 9.0
        assert picker.hubs == [] and "outlined in black" not in picker.info.value
        # review r7, 07: diagonal_sliver was a dotted diagonal on the whole 64 x 64 grid; it is
        # now its first MAX_VIEW x MAX_VIEW corner, named in the title (thin outlines: above)
        picker.case.value = "diagonal_sliver"
        r0, r1, c0, c1 = picker.view
        assert (r0, r1, c0, c1) == (0, MAX_VIEW, 0, MAX_VIEW) and picker.owner.shape == (64, 64)
        assert int((picker.owner[r0:r1, c0:c1] >= 0).sum()) == MAX_VIEW - 1  # (1, 1) .. (15, 15)
        title = picker.fig.get_suptitle()
        assert title.endswith(f"rows 0–{MAX_VIEW - 1}, columns 0–{MAX_VIEW - 1} of 64 × 64")
        picker.fig.canvas.draw()
        extent = picker.fig._suptitle.get_window_extent(picker.fig.canvas.get_renderer())
        assert extent.x0 >= 0 and extent.x1 <= picker.fig.bbox.width  # not clipped
        picker.case.value = "snap_flips_winding"  # a tiny triangle keeps a grid around it
        r0, r1, c0, c1 = picker.view
        assert min(r1 - r0, c1 - c0) >= MIN_VIEW
        assert picker.fig.get_figheight() == FIG_HEIGHT  # a square view: the full height
    finally:
        picker.close()


def test_case_picker_magnifies_a_speck_in_an_inset():
    """Review r236 FIG-2: snap_flips_winding's triangle (0.04 by 0.002 px) and snap_degenerate's
    (0.0025 px) were specks under their vertex marks. Each panel now magnifies them in an inset
    away from the covered pixel, the snapped vertices dashed (a diamond where they meet in one
    point), the 1/256-px grid and the pixel centre drawn; no vertex marks on the grid."""
    from teachraster.core.snapping import snap
    from teachraster.widgets.case_picker import CasePicker

    picker = CasePicker("snap_flips_winding", backend="image")
    try:
        assert picker.zoomed == list(picker.axes) and "the inset magnifies" in picker.info.value
        given = picker._case.triangles[0]
        for ax in picker.axes:
            (inset,) = ax.child_axes
            (x0, x1), (y1, y0) = inset.get_xlim(), inset.get_ylim()
            for x, y in np.concatenate([given, snap(given)]):
                assert x0 < x < x1 and y0 < y < y1
            (scale,) = [t.get_text() for t in inset.texts]
            assert scale == "× 40 by 323"  # stretched up and down: a sliver's winding seen
            box = inset.get_position()
            assert box.x0 > ax.get_position().x0 + 0.4 * ax.get_position().width  # lower right
            assert not [ln for ln in ax.lines if ln.get_marker() == "s" and ln.get_visible()]
        picker.case.value = "snap_degenerate"
        for ax in picker.axes:
            (inset,) = ax.child_axes
            points = [ln.get_xydata()[0].tolist() for ln in inset.lines if ln.get_marker() == "D"]
            assert points == [[2.5, 2.5]]  # every vertex snapped onto the centre
        picker.case.value = "subpixel_triangles"  # a third of a pixel and up: seen on the grid
        assert picker.zoomed == [] and not any(ax.child_axes for ax in picker.axes)
        assert "the inset magnifies" not in picker.info.value
    finally:
        picker.close()


def test_case_picker_inset_points_with_a_ring_not_a_triangle_or_a_dot():
    """Review r244 FIG-1: matplotlib's zoom indicator joined the speck to the inset by two
    black connectors at an outline's weight, which read as a large triangle, and drew its box
    round snap_degenerate's 0.0025-px triangle as a filled black dot on centre (2, 2) of the
    "ours: 0 px" panel: a covered centre. Now a dashed grey ring, larger than a centre's dot
    and hollow, marks the speck, and one thin dashed grey line leads to the inset's nearest
    corner."""
    from matplotlib.colors import to_rgba
    from matplotlib.inset import InsetIndicator
    from matplotlib.patches import Circle

    from teachraster.widgets.case_picker import ZOOM_GREY, CasePicker

    picker = CasePicker("snap_degenerate", backend="image")
    try:
        for case in ("snap_degenerate", "snap_flips_winding"):
            picker.case.value = case
            assert picker.zoomed == list(picker.axes)
            for ax in picker.axes:
                assert not [a for a in ax.get_children() if isinstance(a, InsetIndicator)]
                (ring,) = [p for p in ax.patches if isinstance(p, Circle)]
                assert not ring.get_fill() and ring.get_linestyle() == "--"
                assert ring.get_radius() >= 0.25 and np.allclose(ring.center, (2.5, 2.5), atol=0.05)
                pointers = [ln for ln in ax.lines if ln.get_linestyle() == "--"]
                assert len(pointers) == 1  # one line: two met at the speck like a triangle
                (line,) = pointers
                assert line.get_linewidth() <= 1.2 and line.get_color() == ZOOM_GREY
                assert to_rgba(ring.get_edgecolor()) == to_rgba(ZOOM_GREY)
                # the line starts on the ring and ends on the inset's nearest corner
                (x0, y0), (x1, y1) = np.column_stack(line.get_data())
                assert np.hypot(x0 - 2.5, y0 - 2.5) == pytest.approx(ring.get_radius(), abs=0.05)
                (inset,) = ax.child_axes
                picker.fig.canvas.draw()
                box = inset.get_window_extent()
                corner = ax.transData.transform((x1, y1))
                corners = [(box.x0, box.y0), (box.x0, box.y1), (box.x1, box.y0), (box.x1, box.y1)]
                assert min(np.hypot(*(corner - c)) for c in corners) < 2  # display pixels
            # the centre under the speck keeps its own dot: white in "ours" (not covered)
            ours = picker.axes[0]
            white = [ln for ln in ours.lines if ln.get_marker() == "o" and
                     ln.get_markerfacecolor() == "white" and len(ln.get_xdata()) > 3]  # fmt: skip
            if case == "snap_degenerate":
                assert any((2.5, 2.5) in set(zip(ln.get_xdata(), ln.get_ydata())) for ln in white)
        assert "in the dashed ring" in picker.info.value
    finally:
        picker.close()


def test_divide_cost_slider_starts_at_the_model_and_holds_the_lessons_prices():
    """Review r5, 06-2: a log slider of step 1/4 octave has no 30, and the browser showed the
    model's 30 cycles as 32 ("37x") while lesson 06 printed 30 ("35x")."""
    from widget_examples import _rows

    from teachraster.study.bench import FRONT_DEFINITION
    from teachraster.study.operation_counts import GPU_CYCLES, PENTIUM_CYCLES
    from teachraster.widgets.divide_cost import DivideCostExplorer, divide_positions

    ex = DivideCostExplorer(_rows(), backend="image")
    try:
        assert ex.divide.value == PENTIUM_CYCLES["divides"] == 17
        assert ex.divide.label == "17" and "divide = 17 cycles" in ex.info.value
        values = [v for _, v in ex.divide.options]
        assert values == sorted(values) and values[0] == 1 and values[-1] == 128
        assert {1, 2, 4, 17, 30, 40, 128} <= set(values)  # the prices lesson 06 prints
        assert GPU_CYCLES["divides"] in values
        # the subtitle defines the front in the words of the rule the chart applies (r6, 06-1)
        assert FRONT_DEFINITION in ex.widget.children[0].value
        ex.divide.value = 1.0  # N = 2 costs more than perspective-correct and is less accurate
        assert "perspective" in ex.front and "subdivided N=2" not in ex.front
    finally:
        ex.close()
    odd = DivideCostExplorer(_rows(), divide=7, backend="image")
    try:
        assert odd.divide.value == 7 and 7 in divide_positions(7)
    finally:
        odd.close()
    for bad, error in [(0, ValueError), (float("inf"), ValueError), ("30", TypeError)]:
        with pytest.raises(error, match="divide"):
            DivideCostExplorer(_rows(), divide=bad, backend="image")


#: Lesson 06's interpolation rows: the model's operation counts per pixel and the study's max
#: and mean errors in texels (rounded): (variant, divides, multiplies, additions, max, mean),
#: for u and v (the lesson's counts since r48).
LESSON_06_INTERPOLATION = [
    ("affine", 0.0, 0.0, 2.0, 209.5, 121.0),
    ("perspective", 1.0, 2.0, 3.0, 0.0, 0.0),
    ("subdivided N=2", 0.5, 2.0, 4.5, 5.76, 0.0056),
    ("subdivided N=4", 0.25, 1.0, 3.25, 14.6, 0.026),
    ("subdivided N=8", 0.125, 0.5, 2.625, 23.9, 0.093),
    ("subdivided N=16", 0.0625, 0.25, 2.3125, 51.0, 0.30),
    ("subdivided N=32", 0.03125, 0.125, 2.15625, 72.8, 0.87),
]  # fmt: skip


def test_divide_cost_axis_fits_each_price_inside_the_figure_and_labelled_at_1_2_5():
    """Review r11 06-1: each error measure's layout was solved where it was first shown, the
    cost axis fitted to each price: after divide 1 (the axis ending near 15) and the first
    toggle to mean error, back at 30 the "10²" at the right edge was cut off. Review r23 06-8:
    one range for every price (0.7-600) left two thirds of the plot empty at divide 1. The
    axis is fitted at each price again, the layout keeps room on the right for a label at its
    end (every price and measure inside the figure), and its labels are at 1-2-5, as the error
    axis' (only 10⁰, 10¹, 10² were labelled). Review r41 06-5: refitted at each price, the axis
    moved with the points ("perspective" stood at the same place at every price): one range
    for every price now, from the slider's cheapest and dearest, so the price moves the points.
    Review r56 06-2: that range ends under twice the dearest cost, not five times it."""
    from teachraster.widgets.divide_cost import DivideCostExplorer

    rows = [{"variant": v, "group": "interpolation", "divides": d, "multiplies": m,
             "additions": a, "error": e, "mean_abs_texels": mean, "cycles": 0.0}
            for v, d, m, a, e, mean in LESSON_06_INTERPOLATION]  # fmt: skip
    ex = DivideCostExplorer(rows, backend="image")
    try:
        limits, dearest = {}, {}
        for divide, error in [(1.0, "max error"), (1.0, "mean error"), (17.0, "mean error"),
                              (30.0, "mean error"), (128.0, "mean error"),
                              (128.0, "max error")]:  # fmt: skip
            ex.divide.value, ex.error.value = divide, error
            fig = ex.fig
            fig.canvas.draw()
            box = ex.ax.get_tightbbox(fig.canvas.get_renderer())  # ticks, labels and all
            assert fig.bbox.x0 <= box.x0 and box.x1 <= fig.bbox.x1, (divide, error)
            assert fig.bbox.y0 <= box.y0 and box.y1 <= fig.bbox.y1, (divide, error)
            limits[divide] = ex.ax.get_xlim()
            costs = [p.get_xdata()[0] for p in ex.art.points.values()]
            lo, hi = ex.ax.get_xlim()
            assert lo < min(costs) and max(costs) < hi
            if divide == 128.0:  # the dearest price fills over half the axis' decades
                assert np.log(max(costs) / min(costs)) > 0.5 * np.log(hi / lo), (lo, hi)
            dearest[divide] = max(costs)
        # one axis over each stretch of the slider (AXIS_REACH), the points moving on it
        assert limits[1.0] == limits[17.0] != limits[30.0] != limits[128.0]
        assert dearest[1.0] < 12 < dearest[17.0] < limits[17.0][1]
        assert dearest[1.0] < 12 < dearest[30.0] < 50 < dearest[128.0]
        # review r252 FIG1: at the default (17 cycles) the points fill most of the axis'
        # decades (one axis for the whole slider left its right ~45 % empty)
        lo, hi = limits[17.0]
        assert np.log(hi / dearest[17.0]) < 0.25 * np.log(hi / lo), (lo, hi, dearest[17.0])
        # review r56 06-2: the axis ends just past the dearest point's label room (it ran to
        # about 700 cycles over points that end at 137)
        assert limits[128.0][1] < 2 * dearest[128.0]
        lo, hi = limits[128.0]
        shown = [t.get_text() for t in ex.ax.get_xticklabels()
                 if lo <= t.get_position()[0] <= hi]  # fmt: skip
        assert {"2", "5", "10", "20", "50", "100"} <= set(shown), shown  # it starts at 1.5
    finally:
        ex.close()


def test_divide_cost_error_axis_carries_at_most_eight_labels_in_both_modes():
    """Fresh reader, 2026-12-03: with "mean error" the y axis spans five decades and carried 16
    labels at 1-2-5 (200, 100, 50, ..., 0.002) in about 400 px. It is now labelled at its
    decades; the max error's three decades keep 1-2-5."""
    from teachraster.widgets.divide_cost import MOST_ERROR_LABELS, DivideCostExplorer

    rows = [{"variant": v, "group": "interpolation", "divides": d, "multiplies": m,
             "additions": a, "error": e, "mean_abs_texels": mean, "cycles": 0.0}
            for v, d, m, a, e, mean in LESSON_06_INTERPOLATION]  # fmt: skip
    ex = DivideCostExplorer(rows, backend="image")
    try:
        shown = {}
        for error in ("max error", "mean error", "max error"):
            ex.error.value = error
            ex.fig.canvas.draw()
            lo, hi = ex.ax.get_ylim()
            shown[error] = [t.get_text() for t in ex.ax.yaxis.get_ticklabels(which="both")
                            if t.get_visible() and t.get_text()
                            and lo <= t.get_position()[1] <= hi]  # fmt: skip
            assert 3 <= len(shown[error]) <= MOST_ERROR_LABELS == 8, (error, shown[error])
        assert {"2", "5", "10", "20", "50"} <= set(shown["max error"])  # still 1-2-5
        assert {"0.01", "0.1", "1", "10", "100"} <= set(shown["mean error"])
        assert not {"2", "5", "0.5", "0.05"} & set(shown["mean error"])  # decades only
    finally:
        ex.close()


def test_owner_colours_hold_no_red_or_orange():
    # vermillion means "covered twice" everywhere in the course: no owner may look like it
    import colorsys

    from matplotlib.colors import to_rgb

    from teachraster.widgets.case_picker import OWNER_COLORS

    assert len(set(OWNER_COLORS)) == len(OWNER_COLORS) >= 16  # the fan's 16 triangles differ
    for color in OWNER_COLORS:
        h, _, s = colorsys.rgb_to_hls(*to_rgb(color))
        assert s < 0.2 or 0.12 < h < 0.9, color  # grey, or a hue away from red and orange


def cielab(rgb) -> np.ndarray:
    """CIELAB (D65) of sRGB colours in [0, 1], shape (..., 3): ΔE is the distance."""
    rgb = np.asarray(rgb, dtype=float)
    linear = np.where(rgb <= 0.04045, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
    to_xyz = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722],
                       [0.0193, 0.1192, 0.9505]])  # fmt: skip
    xyz = linear @ to_xyz.T / [0.95047, 1.0, 1.08883]
    f = np.where(xyz > (6 / 29) ** 3, np.cbrt(xyz), xyz / (3 * (6 / 29) ** 2) + 4 / 29)
    return np.stack([116 * f[..., 1] - 16, 500 * (f[..., 0] - f[..., 1]),
                     200 * (f[..., 1] - f[..., 2])], axis=-1)  # fmt: skip


def drawn_owner_colours(picker) -> dict:
    """{(row, col): RGB} the picker's left panel draws at each owned pixel's centre, read
    from the rendered picture with the outlines and the hub's frame hidden."""
    ax = picker.axes[0]
    for art in [*ax.lines, *ax.patches, *ax.collections]:
        art.set_visible(art.__class__.__name__ == "QuadMesh")  # the coverage only
    picker.fig.canvas.draw()
    pixels = np.asarray(picker.fig.canvas.buffer_rgba())[..., :3] / 255
    height = pixels.shape[0]
    r0, r1, c0, c1 = picker.view
    drawn = {}
    for r in range(r0, r1):
        for c in range(c0, c1):
            if picker.owner[r, c] >= 0:
                x, y = ax.transData.transform((c + 0.5, r + 0.5))
                drawn[r, c] = pixels[int(height - y), int(x)]
    return drawn


def test_case_picker_colours_touching_owners_apart():
    """Review r11 (07, r10 07-2): the fan's 16 owners in 16 colours put near twins side by
    side (two olives, two greys, two purples). In the picture, every two owners whose pixels
    touch are drawn in colours at least ΔE 35 apart; the fan takes at most 5 colours, the
    two-owner square §1's two (sky blue, yellow)."""
    from teachraster.widgets.case_picker import CasePicker

    picker = CasePicker("fan_spokes_through_centres", backend="image")
    try:
        for case, most in (("fan_spokes_through_centres", 5), ("d3d_split_square", 2)):
            picker.case.value = case
            drawn, owner = drawn_owner_colours(picker), picker.owner
            close = []
            for (r, c), rgb in drawn.items():
                for n in ((r, c + 1), (r + 1, c)):
                    if n in drawn and owner[n] != owner[r, c]:
                        delta = np.linalg.norm(cielab(rgb) - cielab(drawn[n]))
                        if delta < 35:
                            close.append((case, (r, c), n, round(float(delta))))
            assert close == []
            colours = {tuple(np.round(rgb, 2)) for rgb in drawn.values()}
            assert len(colours) <= most, (case, len(colours))
            # the key says what is drawn: shared colours, or one for each owner
            shared = "16 triangles in 3 colours" if most == 5 else "one colour per triangle"
            assert shared in picker.info.value, picker.info.value
    finally:
        picker.close()


def test_case_picker_shows_every_screen_case_with_both_methods():
    from teachraster.study import hardcases
    from teachraster.widgets.case_picker import SEVERAL, CasePicker, owner_image, screen_cases

    names = screen_cases()
    assert "fan_spokes_through_centres" in names and "behind_camera" not in names
    picker = CasePicker("d3d_split_square", backend="image")
    picker.display.refresh = lambda: None  # owners, verdicts and text are tested, not pixels
    try:
        for name in names:
            picker.case.value = name
            for method in hardcases.FILL_METHODS:
                result = hardcases.get_case(name).run(method)
                assert np.array_equal(picker.owner, owner_image(result.fills))
            # review r284 S-5: the self-test speaks only when it fails
            assert picker.passed and "passes its check" not in picker.info.value
            assert "span tables" not in picker.info.value
            assert picker.methods_differ == 0
        picker.case.value = "fan_spokes_through_centres"
        assert int(picker.owner.max()) == 15 and not (picker.owner == SEVERAL).any()
        assert picker.naive_counts.max() == 16  # the hub, naive: all sixteen triangles
        with pytest.raises(ValueError, match="screen-space"):
            CasePicker("behind_camera", backend="image")
    finally:
        picker.close()


def test_depth_explorer_quotes_no_distance_in_front_of_the_near_plane():
    """Review a1, 05b: near 10 quoted 'Δz at z = 1, 10, 100', z = 1 in front of the near
    plane (nothing drawn there; the value was the curve's first, clamped)."""
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    ex = DepthPrecisionExplorer("float32", near=0.1, far=1000.0, backend="image")
    try:
        assert "Δz at z = 1, 10, 100:" in ex.info.value
        ex.near.value = 10.0
        assert "Δz at z = 100:" in ex.info.value and "z = 1," not in ex.info.value
        res = tr.depth_resolution(100.0, 10.0, 1000.0, "float32")
        assert f"{float(res):.2g}" in ex.info.value.split("Δz at z = 100:")[1]
    finally:
        ex.close()


def test_depth_explorer_says_fighting_becomes_possible_and_names_the_far_plane():
    """Review r7, 05b-3/4: the subtitle said two surfaces δ apart above the line "store the same
    depth and z-fight" (the lesson: possible, not yet likely), and near 10 printed the first
    fight at "z ≈ 1e+03", the far plane in offset notation."""
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    ex = DepthPrecisionExplorer("unorm24", near=0.1, far=1000.0, backend="image")
    try:
        subtitle = ex.widget.children[0].value
        assert "can store the same depth" in subtitle and "depth and z-fight" not in subtitle
        # review r54 05b-2: the caption quotes the crossing and where half the pairs fight,
        # not where one sampled pair first fought
        assert "from Δz = δ at <b>z ≈ 91.6</b>" in ex.info.value
        # review r59 05b-2: half the pixels at 130, more beyond (not "half from 130 on")
        assert (
            "at half the pixels at <b>z ≈ 130</b> (Δz = 2δ) and at more pixels beyond it"
            in ex.info.value
        )
        assert "half the pixels from" not in ex.info.value
        ex.near.value = 10.0
        assert ex.fight_from == pytest.approx(1000.0) and ex.half_from is None
        assert (
            "at <b>z ≈ 921</b>, at less than half the pixels up to the far plane" in ex.info.value
        )
        assert not np.isfinite(ex.marker.get_xdata()).any()
        assert "e+" not in ex.info.value
    finally:
        ex.close()


def test_projection_explorer_ratio_moves_the_far_end_along_its_ray():
    """Review r3 04: |t - q| depends on the depth ratio only; the explorer's z1 / z0 slider
    moves the far end along its own eye ray (the screen picture stays) and prints the peak,
    3 - 2 sqrt(2) at a ratio of 2, none at 1."""
    from teachraster.plotting.projection import Segment
    from teachraster.widgets import ProjectionExplorer

    ex = ProjectionExplorer(Segment(-1.0, 1.0, 2.0, 4.0), backend="image")
    screen_before = ex.segment.screen([0.0, 1.0])
    ex.ratio.value = 2.0
    assert ex.segment.z1 == pytest.approx(2.0 * ex.segment.z0)
    np.testing.assert_allclose(ex.segment.screen([0.0, 1.0]), screen_before, atol=1e-15)
    assert ex.largest_gap == pytest.approx(3 - 2 * np.sqrt(2), abs=1e-4)
    assert f"{ex.largest_gap:.3f}" in ex.info.value
    ex.q.value = 0.5
    assert ex.t == pytest.approx(float(ex.segment.world_parameter(0.5)[0]))
    ex.ratio.value = 1.0
    assert ex.largest_gap == pytest.approx(0.0, abs=1e-12)
    # review r77 (not confirmed): every change re-renders, and while it draws the readout
    # says so, with the new ratio, never the old one under a moved slider
    shown = []
    # the page figure's caption (a traitlet: sent to the page when set, before the redraw)
    ex.info._page.observe(lambda change: shown.append(change["new"]), "caption")
    for ratio in (8.0, 7.5):
        ex.ratio.value = ratio
        assert ex.segment.z1 == pytest.approx(ratio * ex.segment.z0)
    assert [v.split(" · ")[0] for v in shown] == [f"depth ratio z1 / z0 = {r:.2f}"
                                                  for r in (8.0, 8.0, 7.5, 7.5)]  # fmt: skip
    assert "drawing…" in shown[0] and "drawing…" in shown[2]
    assert "drawing…" not in shown[-1] and f"{ex.largest_gap:.3f}" in shown[-1]
    ex.close()


def test_projection_explorer_fits_each_ratio_at_one_scale_and_the_peak_is_marked():
    """Review r144 04-2/3 held the axes for every ratio of the slider; review r234 04-FIG1: at
    the default ratio that left two thirds of the picture empty, the screen strip 60 px tall,
    and x and z at unequal scales (the rays 2.7 times flatter than they are). The picture is
    fitted to the current ratio at one scale, its keys beside it, over neither panel. The
    curve t(q) marks where |t - q| peaks (computed: q* = sqrt(r) / (1 + sqrt(r)), 0.586 at
    r = 2), the caption prints it."""
    from teachraster.plotting.projection import Segment, frame_of
    from teachraster.widgets import ProjectionExplorer

    ex = ProjectionExplorer(Segment(-1.0, 1.0, 2.0, 4.0), backend="image")
    limits = {}
    for ratio in (1.0, 2.0, 8.0):
        ex.ratio.value = ratio
        picture, curve = ex.axes
        limits[ratio] = (picture.get_xlim(), picture.get_ylim())
        x, z = ex.segment.point([0.0, 1.0]).T
        (x_lo, x_hi), (z_lo, z_top) = limits[ratio]
        assert x_lo < x.min() and x.max() < x_hi and z_lo < z.min() and z.max() < z_top
        lo, hi, top = frame_of([ex.segment])  # this ratio's segment alone
        assert limits[ratio] == ((lo, hi), (-0.2, top)) and picture.get_aspect() == 1.0
        # x and z at one scale on the page too: a unit as many pixels across as up
        ex.fig.canvas.draw()
        (px0, py0), (px1, py1) = picture.transData.transform([(0.0, 0.0), (1.0, 1.0)])
        assert px1 - px0 == pytest.approx(py1 - py0, rel=1e-6)
        # the picture's key beside it, over neither panel; review r250 04-FIG3: the curve's
        # short key in its own upper left, above the line t = q, which t(q) never crosses, so
        # that t(q) gets the height the two keys took
        assert picture.get_legend() is None
        keys = [a for a in ex._key_ax.get_children() if type(a).__name__ == "Legend"]
        assert len(keys) == 1
        box = keys[0].get_window_extent()
        for panel in (picture, curve):
            assert not panel.get_window_extent().overlaps(box)
        corner = curve.get_legend().get_window_extent().transformed(curve.transData.inverted())
        assert corner.x0 < 0.05 and corner.y1 > 0.95 and corner.y0 > corner.x1  # above t = q
        assert curve.get_window_extent().height > 0.4 * ex.fig.bbox.height
        # r250 04-FIG3: at z1 / z0 = 1 the segment lies on the screen; the screen is a wide
        # pale band under it, so both are seen
        lines = {line.get_label(): line for line in picture.get_lines()}
        screen, seg = lines["screen (z = 1)"], lines["segment in the world"]
        assert screen.get_linewidth() > 1.5 * seg.get_linewidth()
        assert screen.get_zorder() < seg.get_zorder() and screen.get_color() != seg.get_color()
        bars = [line for line in curve.get_lines() if "largest |t − q|" in str(line.get_label())]
        if ratio == 1.0:
            assert not bars and "t = q everywhere" in ex.info.value
            continue
        r = ex.segment.z1 / ex.segment.z0
        q_star = np.sqrt(r) / (1 + np.sqrt(r))
        assert ex.peak_q == pytest.approx(q_star, abs=1e-12)
        qq = np.linspace(0.0, 1.0, 100001)
        gap = np.abs(ex.segment.world_parameter(qq) - qq)
        assert qq[gap.argmax()] == pytest.approx(q_star, abs=1e-4)  # the peak found by search
        (bar,) = bars
        np.testing.assert_allclose(bar.get_xdata(), [q_star, q_star])
        assert np.ptp(bar.get_ydata()) == pytest.approx(ex.largest_gap)
        assert f"at q = {q_star:.3f}" in ex.info.value
        assert ratio != 2.0 or "0.172</b>, at q = 0.586" in ex.info.value
    assert limits[1.0] != limits[8.0]  # refitted
    ex.close()


def pixels_differ(moved, fresh) -> int:
    """How many pixels of ``moved``'s last picture differ from ``fresh``'s (-1: another size).
    Both fresh from the same machine and matplotlib: the pictures must be equal, bit for bit
    (a layout carried over from the last case moves every line by a pixel or two)."""
    from teachraster.plotting.frames import frame_rgba

    a, b = frame_rgba(moved.fig), frame_rgba(fresh.fig)
    if a.shape != b.shape:
        return -1
    return int((a != b).any(axis=-1).sum())


def test_explorers_moved_by_their_controls_draw_what_a_fresh_one_draws():
    """Issue 31's speed-ups keep the pictures: a layout solved once per case or measure,
    artists moved instead of axes cleared. And SamplingExplorer's faint prefiltered curve
    under the samples follows the filter (it stayed at the first one). Every menu of a lesson
    explorer that redraws (kernel, error measure, depth format, traversal, texture filter)."""
    from widget_examples import _rows

    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer
    from teachraster.widgets.divide_cost import DivideCostExplorer
    from teachraster.widgets.filter_explorer import FilterExplorer
    from teachraster.widgets.sampling_explorer import SamplingExplorer
    from teachraster.widgets.tiles import TileExplorer

    def check(moved, fresh):
        assert pixels_differ(moved, fresh) == 0
        fresh.close()

    s = SamplingExplorer(backend="image")
    s.width.value, s.kernel.value = 1.5, "gaussian"
    check(s, SamplingExplorer(32, 1.5, "gaussian", backend="image"))
    d = DivideCostExplorer(_rows(), backend="image")
    d.error.value = "mean error"  # a measure not laid out yet: its label must fit
    check(d, DivideCostExplorer(_rows(), error="mean error", backend="image"))
    d.error.value = "max error"
    check(d, DivideCostExplorer(_rows(), backend="image"))
    tri = tr.Triangle([[1, 1], [30, 6], [9, 29]])
    t = TileExplorer(tri, 32, 32, backend="image")
    t.traversal.value = "morton"
    check(t, TileExplorer(tri, 32, 32, traversal="morton", backend="image"))
    f = FilterExplorer(48, 36, filter="nearest", samples=3, backend="image")
    f.filter.value = "trilinear"
    check(f, FilterExplorer(48, 36, filter="trilinear", samples=3, backend="image"))
    z = DepthPrecisionExplorer("unorm16", backend="image")
    z.format.value = "float32"
    fresh = DepthPrecisionExplorer("float32", backend="image")
    for ex in (z, fresh):  # the grey curve and its key stay at the start, by design
        ex.reference.set_visible(False)
        ex.ax.get_legend().set_visible(False)
        ex.fig.canvas.draw()
    check(z, fresh)
    for ex in (s, d, t, f, z):
        ex.close()


def test_case_picker_moved_to_any_case_draws_what_a_fresh_one_draws():
    """Every case and two rules, reached from the case before it, from the case after it, and
    by the rule toggle, draws the fresh picker's picture. coincident_vertices and sliver_pair
    did not (about 30,000 pixels): the layout, solved once per case and method, started from
    the last case's axes, and the constrained layout does not forget where it starts."""
    from teachraster.widgets.case_picker import CASE_NAIVE, CasePicker, screen_cases

    names, (m0, m1) = screen_cases(), (CASE_NAIVE, "E > 0")
    fresh, wrong = {}, []

    def compare(picker, how):
        key = (picker.case.value, picker.rule.value)
        if key not in fresh:
            fresh[key] = CasePicker(*key, backend="image")
            fresh[key].close()  # its figure stays, with the last picture drawn
        n = pixels_differ(picker, fresh[key])
        if n:
            wrong.append((*key, how, n))

    other = {m0: m1, m1: m0}
    # forward, each case is reached from the one before with m0 at even places and m1 at odd
    # ones; backward, from the one after with the other method: each pair once by a move of
    # the case, once by the toggle
    for walk, order in ((0, names), (1, names[::-1])):
        picker = CasePicker(order[-1], (m0, m1)[walk], backend="image")
        for name in order:
            arrive = (m0, m1)[(names.index(name) + walk) % 2]
            if picker.rule.value != arrive:  # (no extra step with an odd number of cases)
                picker.rule.value = arrive
            picker.case.value = name
            compare(picker, f"from {'before' if walk == 0 else 'after'}")
            picker.rule.value = other[arrive]
            compare(picker, "by the toggle")
        picker.close()
    assert len(fresh) == 2 * len(names)
    assert wrong == []


# -- layout in the notebook column -------------------------------------------------------------
def drawn_texts(fig) -> list:
    """(text, window extent) of every text ``fig`` draws: tick labels beyond their axis's
    limits are left out (matplotlib makes them, but does not draw them)."""
    from matplotlib.text import Text

    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    undrawn = set()
    for ax in fig.axes:
        for axis, limits in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
            lo, hi = sorted(limits)
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                if not lo - 1e-9 * (hi - lo) <= tick.get_loc() <= hi + 1e-9 * (hi - lo):
                    undrawn.update({id(tick.label1), id(tick.label2)})
    return [(t.get_text(), t.get_window_extent(renderer)) for t in fig.findobj(Text)
            if t.get_visible() and t.get_text().strip() and id(t) not in undrawn
            and (t.axes is None or t.axes.get_visible())]  # fmt: skip


def assert_texts_apart(texts, fig, gap_px: float) -> None:
    """Every text inside ``fig``, and any two texts side by side at least ``gap_px`` apart."""
    box = fig.bbox
    for text, b in texts:
        assert box.x0 <= b.x0 and b.x1 <= box.x1 and box.y0 <= b.y0 and b.y1 <= box.y1, text
    for i, (t1, a) in enumerate(texts):
        for t2, b in texts[i + 1 :]:
            if min(a.y1, b.y1) - max(a.y0, b.y0) > 0:  # in one row
                assert max(b.x0 - a.x1, a.x0 - b.x1) >= gap_px, (t1, t2)


def test_filter_explorer_panels_fit_the_column_apart():
    """The three panels of lesson 09's explorer in the column (940 px at the classroom style),
    the image beside the other two: each title within its panel ("error vs footprint mean" ran 4 px past
    both sides of its panel, as wide as the column allows), no label on another, the
    colour bars' end labels apart, nothing cut at the figure's edges."""
    from teachraster.plotting import use_style
    from teachraster.plotting.style import COLUMN_WIDTH_PX
    from teachraster.widgets.filter_explorer import FilterExplorer

    with use_style("classroom"):
        ex = FilterExplorer(tilt=80, filter="anisotropic", repeats=6, samples=2, backend="image")
    try:
        fig = ex.fig
        assert round(fig.get_figwidth() * fig.dpi) <= COLUMN_WIDTH_PX
        texts = drawn_texts(fig)
        assert_texts_apart(texts, fig, gap_px=fig.dpi * 0.25)  # a quarter inch: 20 px
        renderer = fig.canvas.get_renderer()
        for ax in ex.axes:
            title, panel = ax.title.get_window_extent(renderer), ax.get_window_extent(renderer)
            assert panel.x0 <= title.x0 and title.x1 <= panel.x1, ax.get_title()
        # review r184 09-7: the filtered image on the left, the level panel above the error
        # panel on its right, the figure at most FIGURE_PX tall (r42 09-3: three panels in a
        # row were too small). Review r233 09 FIG1: the quarter under the image held nothing:
        # the footprint mean fills it. Review r246 09 FIG2: the footprint mean was drawn at
        # 0.62 times the filtered image's scale: all four panels are one size now, at a whole
        # number of figure pixels per image pixel, so a pixel lies at one place in each
        from teachraster.widgets.filter_explorer import FIGURE_PX

        image, truth, lod, error = (ax.get_window_extent(renderer) for ax in ex.axes)
        for panel in (truth, lod, error):
            assert abs(panel.width - image.width) < 0.5 and abs(panel.height - image.height) < 0.5
        scale = image.width / ex.width
        assert scale >= 2 and abs(scale - round(scale)) < 1e-6
        assert abs(image.x0 - truth.x0) < 0.5 and abs(lod.x0 - error.x0) < 0.5
        assert image.x1 < lod.x0 and truth.y1 < image.y0 and error.y1 < lod.y0
        assert abs(image.y0 - lod.y0) < 0.5 and abs(truth.y0 - error.y0) < 0.5
        assert round(fig.get_figheight() * fig.dpi) <= FIGURE_PX
    finally:
        ex.close()


def test_filter_explorer_ring_whole_and_a_drag_keeps_the_status_line():
    """Review r246 09 FIG2: on the grazing floor at 89° with anisotropic the worst pixel lies
    in the bottom row (off the middle stripe: r336 S9), and its ring was half cut off by the panel's edge: it is drawn whole.
    S1: during a drag the status line grew by "(on release)" and wrapped, pushing the figure
    down a line while the mouse was held; the draft's line is laid out as the full one (the
    same text outside boxes of fixed width, each box's text no wider than its box)."""
    import re

    from teachraster.widgets.filter_explorer import FilterExplorer

    ex = FilterExplorer(tilt=89, filter="anisotropic", repeats=6, view="grazing floor",
                        backend="image")  # fmt: skip
    try:
        error = ex.panels["error"]
        assert error.worst[0] == ex.height - 1  # on the panel's edge
        # r336 S9: the bright middle stripe (no filter's defect, §5) held the maximum, 0.324,
        # and the ring; the ring's search leaves its two columns out, and the note says so
        middle = (ex.width // 2 - 1, ex.width // 2)
        assert error.worst[1] not in middle and error.ringed < error.maximum
        largest = np.abs(ex.image - ex.truth).max(axis=-1)  # the panel's error, per pixel
        assert error.maximum == np.nanmax(largest[:, middle[0] : middle[1] + 1])
        assert error.note.get_text() == f"max {error.ringed:.3g} (ringed), middle stripe left out"
        assert error.marker.get_clip_on() is False
        full = ex._info_html()
        ex.truth = None  # what a draft at a tilt without its footprint mean shows
        draft = ex._info_html()
    finally:
        ex.close()
    box = r'<span style="display:inline-block;min-width:(\d+)ch;text-align:\w+">(.*?)</span>'

    def layout(html):
        boxes = re.findall(box, html)
        outside = re.sub(box, "[]", html)
        for width, inner in boxes:  # bold takes about a tenth more than 1ch a letter
            assert (
                len(re.sub(r"<[^>]+>", "", inner)) * (1.1 if "<b>" in inner else 1)
                <= int(width) + 0.5
            ), (width, inner)
        return outside, [w for w, _ in boxes]

    assert "(on release)" in draft and "(on release)" not in full
    assert layout(draft) == layout(full)


def test_filter_explorer_menu_fits_its_longest_filter():
    """Review r246 09 S1: the 250-px filter menu cut "nearest_mipmap_nearest" to
    "nearest_mipmap_neares" at the projector's 16 px. Its width holds the description, the
    longest name in DejaVu Sans at 16 px and the menu's arrow and padding (about 40 px)."""
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextPath

    from teachraster.pipeline.texturing.texture import TEXTURE_FILTERS
    from teachraster.widgets.filter_explorer import FilterExplorer

    ex = FilterExplorer(48, 36, tilt=0, filter="nearest", samples=2, backend="image")
    try:
        width = int(ex.filter.layout.width.removesuffix("px"))
        assert ex.filter.layout.max_width == "100%"  # never wider than a narrow column
    finally:
        ex.close()
    font = FontProperties(family="DejaVu Sans", size=16)  # px at 72 dpi: 1 pt = 1 px
    px = lambda text: TextPath((0, 0), text, prop=font).get_extents().width  # noqa: E731
    need = px("filter") + 8 + max(px(f) for f in TEXTURE_FILTERS) + 40
    assert width >= need, (width, need)


def test_filter_explorers_error_panels_share_one_colour_scale():
    """Review r26 (09, cell 36): the error colour bar rescaled per filter (0.6, 0.20, 0.25 at
    89°), so trilinear's and anisotropic's panels could not be compared by colour. Every
    filter and tilt now draws its error on 0 to ERROR_RANGE, and no error runs past it."""
    import matplotlib

    matplotlib.use("Agg")
    from teachraster.pipeline.texturing.texture import TEXTURE_FILTERS
    from teachraster.widgets import FilterExplorer
    from teachraster.widgets.filter_explorer import ERROR_RANGE

    explorer = FilterExplorer(tilt=89, filter="nearest", repeats=6, backend="image")
    try:
        for name in TEXTURE_FILTERS:
            explorer.filter.value = name
            for tilt in (89.0, 0.0):
                explorer.tilt.value = tilt
                assert explorer.panels["error"].image.get_clim() == (0.0, ERROR_RANGE)
                assert np.nanmax(explorer.error) <= ERROR_RANGE, (name, tilt)
    finally:
        explorer.close()


def test_depth_explorer_key_stays_off_the_plot():
    """Review r67 05b-4: with unorm16 and reverse-Z the key hid the dotted line and the curve."""
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    ex = DepthPrecisionExplorer("unorm16", reverse=True, backend="image")
    try:
        ex.fig.canvas.draw()
        renderer = ex.fig.canvas.get_renderer()
        key = ex.ax.get_legend().get_window_extent(renderer)
        assert not key.overlaps(ex.ax.get_window_extent(renderer))
        assert not key.overlaps(ex.ax.xaxis.get_tightbbox(renderer))  # nor the z label
        assert ex.fig.bbox.contains(key.x0, key.y0) and ex.fig.bbox.contains(key.x1, key.y1)
    finally:
        ex.close()


def test_depth_explorer_key_clears_the_z_label_and_fits_in_the_lesson_style():
    """Review r79 05b-12: in lesson 05b (the classroom style, opened on unorm24) the key under
    the axes covered the lower half of "view depth z", and with float32 and reverse-Z ran off
    the figure's right edge. Every format and mapping, switched to as a student does."""
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    for fmt in ("unorm16", "unorm24", "float32"):
        for reverse in (False, True):
            ex = DepthPrecisionExplorer("unorm24", backend="image", style="classroom")
            try:
                ex.format.value, ex.reverse.value = fmt, reverse
                ex.near.value = 0.01  # the widest near plane, kept as the reference (r170)
                ex.keep.click()
                ex.fig.canvas.draw()
                renderer = ex.fig.canvas.get_renderer()
                key = ex.ax.get_legend().get_window_extent(renderer)
                label = ex.ax.xaxis.label.get_window_extent(renderer)
                assert key.y1 < label.y0, (fmt, reverse)  # wholly below the z label
                assert 0 <= key.x0 and key.x1 <= ex.fig.bbox.width, (fmt, reverse, key.x1)
                now = ex.now.get_window_extent(renderer)  # the "now" label inside its key
                assert key.x0 < now.x0 and now.x1 < key.x1 and key.y0 < now.y0 < key.y1
            finally:
                ex.close()


def test_sampling_explorer_title_names_the_band_not_a_half():
    """Review r133 08-D: the title said a wide filter "blurs the left half too", true at 64
    samples only; at the lesson's 32 the signal is below the Nyquist limit left of x = 0.24 (a
    quarter). It names the part left of the yellow band, wherever that band starts."""
    import ipywidgets as widgets

    from teachraster.widgets.sampling_explorer import SamplingExplorer

    def texts(w):
        if isinstance(w, widgets.HTML):
            yield w.value
        for child in getattr(w, "children", ()):
            yield from texts(child)

    s = SamplingExplorer(backend="image")
    try:
        title = " ".join(t for t in texts(s.widget) if "Prefilter" in t)
        assert "blurs the part left of the yellow band too" in " ".join(title.split())
        assert "left half" not in title
        starts = {}
        for rate in (32, 64):
            s.rate.value = rate
            starts[rate] = s.result.alias_from
        assert starts[32] < 0.3 < 0.45 < starts[64] < 0.55  # a quarter at 32, a half at 64
    finally:
        s.close()


def test_sampling_explorer_names_panel_two():
    """Review r133 08-F: panel 2 ("2. sample") has a key, as panels 1 and 3: its dots are the
    samples, its faint line the prefiltered signal they are taken from."""
    from teachraster.widgets.sampling_explorer import SamplingExplorer

    s = SamplingExplorer(backend="image")
    try:
        (panel,) = [ax for ax in s.fig.axes if ax.get_title() == "2. sample"]
        key = [t.get_text() for t in panel.get_legend().get_texts()]
        assert key == ["samples", "prefiltered (faint)"]
    finally:
        s.close()


def test_filter_explorer_grazing_floor_and_max_anisotropy():
    """Review r233 09 M3: the square never showed a footprint more than three times as long as
    wide, and the cap on the probes could not be moved. The grazing floor stretches the far
    footprints to the cap of 16; max aniso changes the anisotropic picture, its error and its
    reads (1 is trilinear); the scene keys the footprint averages kept. W1: the line above the
    picture names the tilt it shows."""
    from teachraster.widgets.filter_explorer import CAPS, FilterExplorer

    ex = FilterExplorer(tilt=89, filter="anisotropic", repeats=6, samples=2,
                        view="grazing floor", backend="image")  # fmt: skip
    try:
        cov = ex.frame.coverage
        ax = [
            np.hypot(*np.moveaxis(d[cov][:, :2] * 64, -1, 0)) for d in (ex.frame.ddx, ex.frame.ddy)
        ]
        assert (np.maximum(*ax) / np.minimum(*ax)).max() >= 15
        errors, reads = {}, {}
        for cap in CAPS:
            ex.max_anisotropy.value = cap
            errors[cap], reads[cap] = ex.rms, ex._reads()
            assert int(np.nanmax(ex.levels_read.probes)) == cap  # the far footprints reach it
        assert [errors[c] for c in CAPS] == sorted(errors.values(), reverse=True)
        assert [reads[c] for c in CAPS] == sorted(reads.values())
        ex.filter.value = "trilinear"
        assert ex.rms == pytest.approx(errors[1], abs=1e-12)
        assert "89°</span></b>: " in ex._info_html()
        grazing = ex.truth
        ex.view.value = "square"
        assert ("square", 89.0) in ex._truths and ("grazing floor", 89.0) in ex._truths
        assert not np.array_equal(np.nan_to_num(grazing), np.nan_to_num(ex.truth))
    finally:
        ex.close()


def test_filter_explorer_status_line_counts_texels_read():
    """Review r257 C2: the status line said "1.0 texels per pixel · largest λ 1.8" at 0°, which
    reads as a contradiction of λ = log2 ρ (ρ = 3.48 texels there): its number counts texel
    *reads*, and says so, as §7's chart axis does."""
    from teachraster.widgets.filter_explorer import FilterExplorer

    ex = FilterExplorer(tilt=0, filter="nearest", repeats=6, backend="image")
    try:
        line = ex._info_html()
    finally:
        ex.close()
    assert "texels read per pixel" in line and "texels per pixel" not in line
    # review r314 S1: the name in a box as wide as the longest left a gap after "nearest"
    assert "</b>: <b>nearest</b> · " in line and "RMS error" in line
