"""The widgets, driven from code (no browser): every control moves the figures it should, the
figures update in place, degenerate triangles never raise, the benchmark script runs."""

import matplotlib

matplotlib.use("Agg")

import importlib.util  # noqa: E402
import sys  # noqa: E402
import zlib  # noqa: E402
from pathlib import Path  # noqa: E402
from types import SimpleNamespace  # noqa: E402

import ipywidgets as widgets  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.widgets import (  # noqa: E402
    FillPlayer,
    TexturedPlaneViewer,
    TriangleEditor,
    display,  # noqa: E402
    resolve_backend,
)
from teachraster.widgets.player import COMPARISON_HINT, COMPARISON_HINT_OPEN  # noqa: E402
from teachraster.widgets.textured import plane_clip  # noqa: E402

W = H = 16
XY = ((1.3, 1.2), (14.6, 4.7), (5.2, 14.1))


def triangle(xy=XY, w=(1.0, 3.0, 6.0)):
    return tr.Triangle(xy, w=w, attrs={"u": [0.0, 1.0, 0.0]})


@pytest.fixture
def player():
    p = FillPlayer(triangle(), W, H, backend="image")
    yield p
    p.close()


@pytest.fixture
def editor():
    e = TriangleEditor(triangle(), W, H, backend="image")
    yield e
    e.close()


def shown_coverage(view) -> np.ndarray:
    return np.asarray(view.coverage.image.get_array()).astype(bool)


def page_picture(player, k: int) -> np.ndarray:
    """What the page paints for step k: its group's key frame, then the patches up to k."""
    from io import BytesIO

    from PIL import Image

    key = player.frames.key
    places, pngs = player._group(k // key)
    picture = np.asarray(Image.open(BytesIO(pngs[0])).convert("RGBA")).copy()
    for (x, y), png in list(zip(places, pngs))[1 : k % key + 1]:
        if png:
            patch = np.asarray(Image.open(BytesIO(png)).convert("RGBA"))
            picture[y : y + patch.shape[0], x : x + patch.shape[1]] = patch
    return picture


def work_kinds(trace) -> set:
    return {s.kind for s in trace} - {
        "snap",
        "winding",
        "bbox",
        "rows",
        "sort",
        "split",
        "interpolate",
    }


# -- FillPlayer --------------------------------------------------------------------------------
@pytest.mark.parametrize("method", ["span", "halfplane"])
def test_step_slider_sets_caption_and_coverage(method):
    player = FillPlayer(triangle(), W, H, method=method, backend="image")
    trace = player.trace
    assert player.slider.min == 0 and player.slider.max == len(trace) - 1
    pngs = set()
    for k in sorted({0, 1, 3, len(trace) // 2, len(trace) - 2, len(trace) - 1}):
        player.slider.value = k
        assert player.step == k
        assert player.caption_text == trace.caption(k)
        assert np.array_equal(shown_coverage(player.view), trace.coverage_at(k))
        pngs.add(page_picture(player, k).tobytes())
    assert len(pngs) > 1  # the picture itself changes, not just the artists
    player.close()


@pytest.mark.parametrize("method", ["span", "halfplane"])
def test_the_page_paints_exactly_the_step_the_view_draws(method):
    """Key frame + patches (what frames.js paints) == the view's own drawing of that step."""
    player = FillPlayer(triangle(), W, H, method=method, backend="image")
    for k in sorted({0, 1, 15, 16, 17, len(player.trace) // 2, len(player.trace) - 1}):
        picture = page_picture(player, k)
        player.view.show_step(k, draw=False)
        player.view.blit.invalidate()
        player.view.redraw()
        np.testing.assert_array_equal(picture, np.asarray(player.fig.canvas.buffer_rgba()))
    player.close()


def test_the_page_gets_captions_as_text_and_groups_on_request(player):
    player.method.value = "halfplane"
    frames = player.frames
    captions = [s.caption for s in player.trace]  # text: the page never parses it
    assert frames.captions[:-1] == captions[:-1]
    assert frames.infos[0] == f"of 0–{len(player.trace) - 1} (snap)"
    # review r9/r10 (lesson 04 c15): the last step's picture shows the values it interpolates
    # (coloured by them, keyed); its caption points to the comparison of both ways, and
    # its readout stays short: a long one pushed the speed menu onto a new line and
    # pointed at a folded comparison (review r91 00-B)
    assert player.interp_view is not None  # the fixture's triangle has attributes
    # review r208 00-3: the hint is a sentence of its own, after a full stop
    assert frames.captions[-1] == f"{captions[-1]}. {COMPARISON_HINT}"
    assert "click the comparison's title" in frames.captions[-1]
    assert frames.infos[-1] == f"of 0–{len(player.trace) - 1} (interpolate)"
    player.view.show_step(-1, draw=False)
    assert player.view.values.get_visible()
    bar = player.view.value_bar  # the key's colour bar of u (review r11: two swatches)
    assert bar.title.get_visible() and bar.title.get_text() == "u at the covered centres"
    sent = []
    frames.send = lambda content, buffers=None: sent.append((content, buffers))
    frames._on_page_message(frames, {"type": "group", "group": 1, "gen": frames.gen}, [])
    frames._on_page_message(frames, {"type": "group", "group": 0, "gen": frames.gen - 1}, [])
    assert len(sent) == 1  # a request for an earlier fill is dropped
    content, pngs = sent[0]
    assert content["group"] == 1 and len(pngs) == len(content["places"]) == frames.key
    assert pngs[0].startswith(b"\x89PNG")  # the key frame
    assert player.view.step == frames.value  # rendering a group leaves the view in place


def test_static_fallback_is_a_poster_or_the_whole_offline_player(player, monkeypatch):
    bundle = player._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert (
        "Run All (Run ▸ Run All Cells)" in bundle["text/html"]
        and "data:image/png" in bundle["text/html"]
    )
    monkeypatch.setenv("TEACHRASTER_STATIC_PAGES", "1")
    page = player._repr_mimebundle_()["text/html"]
    assert "mountStatic(" in page and '<script type="module">' in page
    # no address: "http:"/"https:" (a colon is never in base64, so the embedded PNGs cannot
    # match by chance, as a bare "http" did once a picture changed)
    script = page.split("<script", 1)[1].replace("http://www.w3.org", "")
    assert "http:" not in script and "https:" not in script


def test_step_buttons_move_the_slider(player):
    assert player.slider.value == 0
    player.next.click()
    player.next.click()
    assert player.slider.value == 2
    player.prev.click()
    assert player.slider.value == 1
    player.first.click()
    player.prev.click()  # stays at the first step
    assert player.slider.value == 0
    player.last.click()
    player.next.click()  # stays at the last step
    assert player.slider.value == player.slider.max == len(player.trace) - 1
    assert player.caption_text == player.trace.caption(-1)


def test_method_toggle_rasterises_again_and_the_slider_follows(player):
    assert work_kinds(player.trace) == {"row"}
    span_steps = len(player.trace)
    player.slider.value = 5
    player.method.value = "halfplane"
    trace = player.trace
    assert trace.method == "halfplane" and work_kinds(trace) == {"pixel"}
    assert len(trace) != span_steps
    assert player.slider.max == player.play.max == len(trace) - 1
    assert player.slider.value == 5  # the same step index
    assert player.caption_text == trace.caption(5)
    assert np.array_equal(shown_coverage(player.view), trace.coverage_at(5))
    # a finished fill stays finished when switching back
    player.last.click()
    player.method.value = "span"
    assert work_kinds(player.trace) == {"row"}
    assert player.slider.value == player.slider.max == span_steps - 1
    assert player.view.step == span_steps - 1
    assert player.caption_text == player.trace.caption(-1)


def test_a_wrapped_heatmap_has_its_title_close_above_it():
    """Review r2 00-4: the heatmap wrapped onto a row of its own (classroom fonts) had its
    title a panel-gap above it (room for column labels it does not have)."""
    player = FillPlayer(triangle(), W, H, backend="image", style="classroom")
    view = player.interp_view
    fig, heat = view.fig, view.axes[2]
    assert heat.get_position().y0 < view.axes[0].get_position().y0  # a row of its own
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    gap = heat.title.get_window_extent(renderer).y0 - heat.get_window_extent(renderer).y1
    assert 0 <= gap < 0.15 * fig.dpi  # the title sits on its panel
    player.close()


def _empty_quarters(fig) -> list:
    """The quarters of ``fig`` (2 x 2) that no visible Axes reaches into."""
    boxes = [ax.get_position() for ax in fig.axes if ax.get_visible() and ax.axison]
    empty = []
    for qx in (0, 1):
        for qy in (0, 1):
            x0, y0 = 0.5 * qx, 0.5 * qy
            if not any(b.x1 > x0 + 0.05 and b.x0 < x0 + 0.45 and b.y1 > y0 + 0.05
                       and b.y0 < y0 + 0.45 for b in boxes):  # fmt: skip
                empty.append((qx, qy))
    return empty


def test_the_interpolation_comparison_leaves_no_quarter_empty():
    """Review r3 00/04: the wrapped heatmap left the lower right quarter empty; the values
    along the row of the largest error fill it, dashed on the heatmap, read from the trace."""
    player = FillPlayer(triangle(), W, H, backend="image", style="classroom")
    view = player.interp_view
    assert _empty_quarters(view.fig) == []
    assert view.fig.get_figwidth() * view.fig.dpi <= 940 + 1e-6
    row = view.heatmap.worst[0]
    affine, persp = (np.asarray(line.get_ydata()) for line in view.profile.lines)
    np.testing.assert_array_equal(affine, view.images[0].image.get_array()[row].filled(np.nan))
    np.testing.assert_array_equal(persp, view.images[1].image.get_array()[row].filled(np.nan))
    assert f"row {row}" in view.profile.title.get_text()
    assert np.nanmax(np.abs(affine - persp)) == pytest.approx(view.maximum)
    # a new fill moves the row with the largest error
    other = tr.Triangle([[1.0, 14.0], [15.0, 12.0], [3.0, 1.0]], w=[4.0, 1.0, 1.0],
                        attrs={"u": [1.0, 0.0, 0.0]})  # fmt: skip
    view.update(tr.rasterize(other, W, H, trace=True))
    assert view.profile.index == view.heatmap.worst[0] != row
    player.close()


def test_interpolation_toggle_opens_the_comparison_below_the_steps(player):
    """Review r7 00-2: pressing "affine" opened the comparison in the steps' place and the
    whole step player vanished. The toggle, one of the steps' controls, now opens it below
    them; opened by its own header it still takes their place (the two fit one screen)."""
    shown = lambda: player.frames.layout.display != "none"  # noqa: E731
    assert player.comparison.selected_index is None and shown()
    player.interpolation.value = "affine"
    assert player.comparison.selected_index == 0 and shown()  # open, the steps still there
    player.interpolation.value = "perspective"
    assert player.comparison.selected_index == 0 and shown()
    player.comparison.selected_index = None  # closed by its header
    assert shown()
    player.comparison.selected_index = 0  # opened by its header: in the steps' place
    assert not shown()
    player.interpolation.value = "affine"  # already open: as it was
    assert player.comparison.selected_index == 0 and not shown()
    player.comparison.selected_index = None
    assert shown()


def test_the_last_caption_says_where_the_comparison_is_and_that_its_title_folds_the_steps(
    player,
):
    """Review r208 00-2, 00-3: opened by its title the comparison folds the steps with no
    word why, and the last caption, "…on screen) Both ways side by side: the comparison
    below (click its title to open it).", lacked a full stop and still said to open it once
    the toggle had. Closed, the hint says both how to open it and that the steps fold;
    open, only where it is; closed again, the first hint is back."""
    frames, last = player.frames, player.trace.caption(-1)
    assert frames.captions[-1] == f"{last}. {COMPARISON_HINT}"
    assert (
        "takes the steps' place" in COMPARISON_HINT and "close it to step again" in COMPARISON_HINT
    )
    player.interpolation.value = "affine"  # opens the comparison below the steps
    last = player.trace.caption(-1)
    assert frames.captions[-1] == f"{last}. {COMPARISON_HINT_OPEN}"
    assert "title" not in frames.captions[-1]
    assert frames.captions[:-1] == [s.caption for s in player.trace][:-1]
    player.comparison.selected_index = None
    assert frames.captions[-1] == f"{last}. {COMPARISON_HINT}"
    player.method.value = "halfplane"  # a new fill, the comparison closed: the closed hint
    assert frames.captions[-1] == f"{player.trace.caption(-1)}. {COMPARISON_HINT}"
    player.comparison.selected_index = 0
    assert frames.captions[-1].endswith(COMPARISON_HINT_OPEN)


def test_interpolation_toggle_changes_the_interpolation_view(player):
    view = player.interp_view
    assert view is not None
    affine_mark, persp_mark = player.in_use
    assert persp_mark.get_visible() and not affine_mark.get_visible()
    assert persp_mark.get_text() == "in use"
    png = player.interp_display.widget.value
    player.interpolation.value = "affine"
    assert player.trace.interpolation == "affine"
    assert affine_mark.get_visible() and not persp_mark.get_visible()
    # the panel not in use keeps its colours, readable against the colour bar (review r2 00-4)
    assert {im.image.get_alpha() for im in view.images[:2]} <= {None, 1.0}
    assert player.interp_display.widget.value != png
    # the last step says which interpolation ran
    player.last.click()
    assert "affine in screen space" in player.caption_text
    player.interpolation.value = "perspective"
    assert "perspective-correct" in player.caption_text


def test_interpolation_view_follows_the_method_toggle(player):
    before = player.interp_view.trace
    player.method.value = "halfplane"
    assert player.interp_view.trace is player.trace is not before


def test_play_speed_is_set_from_code(player):
    assert player.interval == player.frames.interval == 400
    player.interval = 150
    assert player.frames.interval == 150
    fast = FillPlayer(triangle(), W, H, backend="image", interval=20)
    assert fast.frames.interval == 20
    with pytest.raises(ValueError, match="interval"):
        fast.interval = 0
    fast.close()


def test_player_without_attributes_has_no_interpolation_view():
    p = FillPlayer(tr.Triangle(XY), W, H, backend="image")
    assert p.interp_view is None
    # it would change nothing on show: not offered
    assert not any(c is p.interpolation for c in walk(p.widget))
    p.interpolation.value = "affine"
    p.slider.value = p.slider.max
    assert "no attributes" in p.caption_text
    p.close()


DEGENERATE = {
    "zero_area": ((1, 1), (5, 5), (9, 9)),
    "one_point": ((3, 3), (3, 3), (3, 3)),
    "outside": ((40, 40), (50, 41), (45, 60)),
    "thin": ((0.2, 4.4), (15.7, 4.6), (8.0, 4.55)),
}


@pytest.mark.parametrize("xy", DEGENERATE.values(), ids=DEGENERATE)
def test_player_steps_through_degenerate_triangles(xy):
    p = FillPlayer(triangle(xy), W, H, backend="image")
    for method in ("span", "halfplane"):
        p.method.value = method
        for k in range(p.slider.max + 1):
            p.slider.value = k
            assert p.caption_text == p.trace.caption(k)
    p.close()


def test_stepping_updates_artists_in_place(player):
    ax = player.view.ax
    n_children, n_axes = len(ax.get_children()), len(player.fig.axes)
    artists = set(map(id, ax.get_children()))
    for k in range(50):
        player.slider.value = k % (player.slider.max + 1)
    assert len(ax.get_children()) == n_children
    assert set(map(id, ax.get_children())) == artists  # the very same artists
    assert len(player.fig.axes) == n_axes
    # toggles reuse them too
    ifig = player.interp_view.fig
    n_interp = [len(a.get_children()) for a in ifig.axes]
    for _ in range(3):
        player.method.value = "halfplane"
        player.interpolation.value = "affine"
        player.method.value = "span"
        player.interpolation.value = "perspective"
    assert len(ax.get_children()) == n_children
    assert [len(a.get_children()) for a in ifig.axes] == n_interp


def walk(w):
    yield w
    for c in getattr(w, "children", ()):
        yield from walk(c)


def test_player_widget_holds_the_controls_and_displays(player):
    inside = list(walk(player.widget))
    for control in (player.frames, player.method, player.interpolation, player.samples,
                    player.interp_display.widget):  # fmt: skip
        assert any(control is w for w in inside)
    assert player.slider is player.play is player.frames
    assert isinstance(player.interp_display.widget, widgets.Image)
    assert player.fig is player.view.fig
    assert "application/vnd.jupyter.widget-view+json" in player._repr_mimebundle_()


def test_player_rejects_bad_input():
    with pytest.raises(TypeError, match="Triangle"):
        FillPlayer(XY, W, H, backend="image")
    with pytest.raises(ValueError, match="method"):
        FillPlayer(triangle(), W, H, method="scanline", backend="image")
    with pytest.raises(ValueError, match="backend"):
        FillPlayer(triangle(), W, H, backend="svg")


def test_style_applies_to_the_widget_only():
    size = matplotlib.rcParams["font.size"]
    p = FillPlayer(triangle(), W, H, backend="image", style="classroom")
    assert matplotlib.rcParams["font.size"] == size
    assert p.view.caption_text.get_fontsize() > size  # classroom fonts inside the figure
    p.close()


# -- backends ----------------------------------------------------------------------------------
def test_auto_backend_follows_matplotlib(monkeypatch):
    assert resolve_backend("auto") == "image"  # Agg here
    for name in ("module://ipympl.backend_nbagg", "widget", "ipympl"):
        monkeypatch.setattr(display.mpl, "rcParams", {"backend": name})
        assert resolve_backend("auto") == "ipympl"
    monkeypatch.setattr(display.mpl, "rcParams", {"backend": "module://matplotlib_inline"})
    assert resolve_backend("auto") == "image"
    with pytest.raises(ValueError, match="backend"):
        resolve_backend("qt")


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # raised inside ipympl
def test_ipympl_backend_puts_the_canvas_in_the_box():
    pytest.importorskip("ipympl")
    from ipympl.backend_nbagg import Canvas

    p = FillPlayer(triangle(), W, H, backend="ipympl")
    from teachraster.plotting.style import COLUMN_WIDTH_PX

    ifig = p.interp_view.fig
    assert ifig.get_figwidth() * ifig.dpi <= COLUMN_WIDTH_PX + 1e-6  # fits the column
    # the steps are page frames; the interpolation figure is the live canvas
    assert isinstance(p.interp_view.fig.canvas, Canvas)
    assert any(c is p.interp_view.fig.canvas for c in walk(p.widget))
    p.slider.value = 4
    assert np.array_equal(shown_coverage(p.view), p.trace.coverage_at(4))
    p.close()
    e = TriangleEditor(triangle(), W, H, backend="ipympl")
    assert any(c is e.fig.canvas for c in e.widget.children)
    e.close()


# -- TriangleEditor ----------------------------------------------------------------------------
def test_vertex_sliders_move_the_triangle(editor):
    editor.x[1].value = 9.0
    editor.y[1].value = 3.25
    trace = editor.fill.trace
    assert trace.snapped[1].tolist() == [9.0, 3.25]
    assert editor.view.trace is trace and editor.interp_view.trace is trace
    assert editor.view.step == len(trace) - 1  # the finished fill
    assert np.array_equal(shown_coverage(editor.view), trace.coverage_at(len(trace) - 1))
    # snapping to 1/256 px happens in the core; the editor shows the snapped triangle
    editor.x[0].value = 2.0 + 0.3 / 256
    assert editor.fill.trace.snapped[0, 0] == 2.0


def test_probe_gives_the_edge_functions_and_is_dragged_like_a_vertex():
    """Lesson 02: the editor's info line gives E12, E23, E31 at a marked point (the cross),
    which the page drags as a fourth handle; bad arguments are named."""
    e = TriangleEditor(triangle(), W, H, backend="image", probe=(7.5, 7.5), comparison=False)
    try:
        v = e.fill.trace.snapped
        want = [tr.edge_function(v[k], v[(k + 1) % 3], (7.5, 7.5)) for k in range(3)]
        assert np.allclose(e.edge_values(), want)
        assert "E12 = " in e.info.value and "E31 = " in e.info.value
        assert "largest |affine" not in e.info.value  # no comparison figure, no error quoted
        assert len(e._handles()) == 4
        e._on_page_move(3, 0.5, 0.5, True)
        assert e.probe.tolist() == [0.5, 0.5] and "outside" in e.info.value
        # review r169 02-8: the point with 2 decimals, as the values (a drag leaves 1/256 px)
        e._on_page_move(3, 2.98828125, 8.05859375, True)
        assert "at the cross (2.99, 8.06):" in e.info.value
        e._on_page_move(3, 0.5, 0.5, True)
        assert e.probe_marker.get_xydata().tolist() == [[0.5, 0.5]]
        assert e.view.header.get_text() == "Span tables"  # a finished fill: no step count
        keyed = [t.get_text() for t in e.view.legend.texts if t.get_visible()]
        assert "raster line, its pixels" not in keyed and "E12, E23, E31 here" in keyed
        e.method.value = "halfplane"
        keyed = [t.get_text() for t in e.view.legend.texts if t.get_visible()]
        assert keyed == ["covered", "tested, rejected", "bounding box", "E12, E23, E31 here"]
        e.x[1].value = 9.0  # a move keeps the key as it is (one cross, once)
        assert [t.get_text() for t in e.view.legend.texts if t.get_visible()] == keyed
    finally:
        e.close()
    plain = TriangleEditor(triangle(), W, H, backend="image")
    assert plain.edge_values() is None and len(plain._handles()) == 3
    with pytest.raises(ValueError, match="no probe"):
        plain.set_probe(1, 1)
    plain.close()
    with pytest.raises(ValueError, match="probe"):
        TriangleEditor(triangle(), W, H, backend="image", probe=(1, 2, 3))
    with pytest.raises(TypeError, match="comparison"):
        TriangleEditor(triangle(), W, H, backend="image", comparison="no")


def test_split_point_follows_the_middle_vertex(editor):
    u4 = editor.fill.trace.span.u4
    assert f"u4 = {u4:.2f}" in editor.info.value
    editor.y[1].value = 8.0
    new = editor.fill.trace.span.u4
    assert new != u4
    # both lines where there is room left of point 4, its number alone where not (r19);
    # the info line always gives the value
    assert editor.view.split.label.get_text() in (f"point 4\nu4 = {new:.2f}", "4")
    assert f"u4 = {new:.2f}" in editor.info.value
    # half-planes split nothing: the line names the centres they test instead (review a1, 02)
    editor.method.value = "halfplane"
    assert "u4" not in editor.info.value and "split" not in editor.info.value
    assert f"{editor.fill.trace.bbox.size} centres of the bounding box tested" in editor.info.value


def test_depth_sliders_drive_the_error_heatmap(editor):
    for s in editor.w:
        editor._quiet = True
        s.value = 2.0
    editor._quiet = False
    editor.update()
    assert editor.interp_view.maximum < 1e-12  # equal w: affine is exact
    editor.w[2].value = 8.0
    big = editor.interp_view.maximum
    assert big > 0.05
    assert f"{big:.3g}" in editor.interp_view.heatmap.title.get_text()


def test_zero_area_positions_do_not_raise(editor):
    # all three on one line, one slider at a time (the way a student drags into it)
    for i, (x, y) in enumerate([(2.0, 2.0), (6.0, 6.0), (10.0, 10.0)]):
        editor.x[i].value = x
        editor.y[i].value = y
    trace = editor.fill.trace
    assert trace.signed_area == 0 and not trace.covered.any()
    assert "zero area" in editor.info.value
    assert "area 0.00 px²" in editor.info.value  # review r169 02-8: "area" with its number
    assert "u4" not in editor.info.value  # nothing to split
    assert not shown_coverage(editor.view).any()
    editor.set_vertex(1, x=2.0, y=2.0)  # two vertices on top of each other
    editor.set_vertex(2, x=2.0, y=2.0)  # a single point
    editor.method.value = "halfplane"
    editor.w[0].value = 5.0
    assert not editor.fill.coverage.any()


def test_set_vertex_renders_once(editor):
    before = editor.display.draws
    editor.set_vertex(0, x=3.0, y=2.0, w=2.5)
    assert editor.display.draws == before + 1
    assert editor.fill.trace.snapped[0].tolist() == [3.0, 2.0]
    assert editor.tri.w[0] == pytest.approx(2.5)


def test_dragging_a_vertex_with_the_mouse(editor):
    ax = editor.view.ax

    def event(x, y, inaxes=ax):
        return SimpleNamespace(inaxes=inaxes, button=1, xdata=x, ydata=y)

    x1, y1 = editor.xy[1]
    editor._on_press(event(x1 + 0.3, y1 - 0.2))  # near v1
    assert editor._dragging == 1
    editor._last_done = 0.0  # no backlog
    editor._on_motion(event(11.0, 6.0))
    editor._on_release(event(11.0, 6.0))
    assert editor._dragging is None
    assert editor.fill.trace.snapped[1].tolist() == [11.0, 6.0]
    assert (editor.x[1].value, editor.y[1].value) == (11.0, 6.0)
    # a press far from every vertex drags nothing
    editor._on_press(event(8.0, 15.5))
    assert editor._dragging is None


# -- TexturedPlaneViewer -----------------------------------------------------------------------
def test_tilt_slider_changes_both_images_and_the_error_grows():
    viewer = TexturedPlaneViewer(64, 48, tilt=0.0, backend="image")
    assert viewer.depth is viewer.tilt
    assert viewer.maximum < 1e-9  # facing the camera: all w equal, affine is exact
    maxima, previous = [], (viewer.affine, viewer.perspective)
    for tilt in (15.0, 30.0, 45.0, 60.0, 75.0, 90.0):
        viewer.tilt.value = tilt
        a, p = viewer.affine, viewer.perspective
        assert not np.array_equal(a, previous[0], equal_nan=True)
        assert not np.array_equal(p, previous[1], equal_nan=True)
        # what is shown is what was rendered
        shown = np.asarray(viewer.view.images[1].image.get_array())
        assert shown.shape[:2] == (48, 64)
        maxima.append(viewer.maximum)
        previous = (a, p)
    assert all(b > a for a, b in zip(maxima, maxima[1:])), maxima
    assert maxima[-1] > 5.0  # several texels off: the warp is obvious
    assert f"{maxima[-1]:.3g}" in viewer.view.heatmap.title.get_text()
    viewer.close()


@pytest.mark.parametrize("tilt", [0.0, 40.0, 75.0, 90.0])
def test_the_square_is_fully_on_screen(tilt):
    viewer = TexturedPlaneViewer(64, 48, tilt=tilt, backend="image")
    covered = ~np.isnan(viewer.perspective[..., 0])
    assert covered.sum() > 0.15 * covered.size
    # nothing touches the border: the whole square is in the frame
    assert not (covered[0].any() or covered[-1].any() or covered[:, 0].any()
                or covered[:, -1].any())  # fmt: skip
    clip = plane_clip(tilt, viewer.camera, 64 / 48)
    ndc = clip[..., :2] / clip[..., 3:]
    assert np.abs(ndc).max() <= 0.92 + 1e-9
    viewer.close()


def test_textured_viewer_draws_v_down_the_middle_column():
    """The fourth panel (review r3 00/04: the quarter was empty): v down the middle column,
    evenly stepped for affine (a straight line in the row), bunched for perspective-correct."""
    viewer = TexturedPlaneViewer(tilt=60, checks=4, backend="image", style="classroom")
    assert _empty_quarters(viewer.fig) == []
    prof = viewer.profile
    # screen y on x, v on y (review r77 04-1: with v on x the far edge's fast change lay flat)
    rows, v_affine = (np.asarray(d, dtype=float) for d in prof.lines[0].get_data())
    v_persp = np.asarray(prof.lines[1].get_ydata(), dtype=float)
    np.testing.assert_array_equal(rows, np.arange(viewer.height) + 0.5)
    assert prof.title.axes.get_xlabel() == "screen y (px)"
    assert prof.title.axes.get_ylabel() == "texture v"
    np.testing.assert_array_equal(v_affine, viewer.uv_affine[:, viewer.width // 2, 1])
    np.testing.assert_array_equal(v_persp, viewer.uv_perspective[:, viewer.width // 2, 1])
    ok = np.isfinite(v_affine)
    steps_a, steps_p = np.diff(v_affine[ok]), np.diff(v_persp[ok])
    assert np.ptp(steps_a) < 1e-9  # affine: equal steps
    assert steps_p.max() > 3 * steps_p.min()  # perspective: bunched towards the far edge
    # steepest at the far edge, the top rows: on the left of the plot, as the text says
    assert np.argmax(steps_p) < len(steps_p) // 4
    viewer.tilt.value = 0.0  # facing the camera: the two curves are one
    np.testing.assert_allclose(prof.lines[0].get_ydata(), prof.lines[1].get_ydata(), atol=1e-12)
    # no error anywhere: no marker pointing at an arbitrary pixel (review r3 04-5)
    hm = viewer.view.heatmap
    assert not hm.marker.get_visible() and not hm.note.get_visible()
    assert "0 everywhere" in hm.title.get_text()
    viewer.close()


def test_textured_viewer_redraws_the_profiles_ticks_when_they_change():
    """Review r219 04-2: after a tilt change, ghosts of the profile's old tick labels seemed to
    stay. The blit draws the profile's Axes (its ticks too) at every picture: the picture
    after 60° -> 0° -> 90° (ticks 30 60 90, then 25 50 75 100) is a fresh viewer's at 90°.
    (The ghosts were the page's: tests/test_browser_ahead.py.)"""
    from teachraster.plotting import use_style

    with use_style("classroom"):  # as lesson 04 shows it: the profile has a row of its own
        viewer = TexturedPlaneViewer(tilt=60, checks=4, backend="image")
        labels = viewer.profile.title.axes.get_xticklabels
        before = [t.get_text() for t in labels()]
        viewer.tilt.value = 0.0
        viewer.tilt.value = 90.0
        assert [t.get_text() for t in labels()] != before
        fresh = TexturedPlaneViewer(tilt=90, checks=4, backend="image")
        assert _shown(viewer) == _shown(fresh)
    viewer.close()
    fresh.close()


def test_textured_viewer_titles_sit_on_their_renders_which_fill_the_row():
    """Review r219 04-3: the titles floated ~70 px above two 250 x 190 px renders (room kept
    for column labels the renders do not have), and a wide gap parted the colour bar from
    the profile."""
    from teachraster.plotting import use_style

    with use_style("classroom"):
        viewer = TexturedPlaneViewer(tilt=60, checks=4, backend="image")
        fig = viewer.fig
        renderer = fig.canvas.get_renderer()
        px = fig.dpi / 72  # pixels per point
        width = fig.get_figwidth() * fig.dpi
        affine, persp, heat = viewer.view.axes[:3]
        for ax in (affine, persp):
            gap = ax.title.get_window_extent(renderer).y0 - ax.bbox.y1
            assert 0 <= gap <= 8 * px, gap  # a few points, not the room of tick labels
        assert affine.bbox.width > heat.bbox.width > 0  # the renders take the first row
        assert persp.bbox.x1 > 0.9 * width
        bar = viewer.view.heatmap.colorbar.ax.get_tightbbox(renderer)
        profile = viewer.profile.title.axes.get_tightbbox(renderer)
        assert 0 < profile.x0 - bar.x1 < 0.5 * fig.dpi  # under half an inch between them
        assert width <= 940 + 1e-6
    viewer.close()


def test_textured_viewer_shows_texel_error_in_place():
    viewer = TexturedPlaneViewer(48, 36, tilt=50.0, backend="image")
    axes = viewer.fig.axes
    children = [len(a.get_children()) for a in axes]
    err = np.asarray(viewer.view.heatmap.image.get_array(), dtype=float)
    assert np.nanmax(err) == pytest.approx(np.nanmax(viewer.error))
    for tilt in range(0, 91, 5):
        viewer.tilt.value = float(tilt)
    assert [len(a.get_children()) for a in viewer.fig.axes] == children
    viewer.close()


# -- benchmark script --------------------------------------------------------------------------
@pytest.mark.bench
def test_widget_benchmark_quick_run_succeeds(capsys):
    path = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_widgets.py"
    spec = importlib.util.spec_from_file_location("bench_widgets", path)
    bench = importlib.util.module_from_spec(spec)
    sys.modules["bench_widgets"] = bench
    spec.loader.exec_module(bench)
    assert bench.main(["--quick"]) == 0
    out = capsys.readouterr().out
    assert "step slider" in out and "vertex" in out and ("PASS" in out or "MISS" in out)


def test_far_away_vertices_render_without_their_labels():
    # vertices around 1e6 px: labels there used to overflow FreeType's rasteriser
    tri = tr.Triangle([[-1e6, -1e6], [1e6, 8], [8, 1e6]], attrs={"u": [0, 1, 0]})
    player = FillPlayer(tri, 16, 16, backend="image")
    editor = TriangleEditor(tri, 16, 16, backend="image")
    for view in (player.view, editor.view):
        renderer = view.fig.canvas.get_renderer()
        drawn = [label._check_xy(renderer) for label in view.triangle.labels]
        assert drawn == [False, False, False]
    assert player.frames.poster and editor.interp_display.widget.value
    player.close()
    editor.close()


def test_player_names_vertices_in_the_order_given_for_every_method():
    tri = tr.Triangle([[14.0, 12.0], [2.0, 1.5], [7.0, 6.0]])
    player = FillPlayer(tri, 16, 16, method="span", backend="image")
    assert list(player.trace.span.order) != [0, 1, 2]
    labels = player.view.triangle.labels
    assert [label.get_text() for label in labels] == ["v1", "v2", "v3"]
    player.method.value = "halfplane"  # same label artists, same names
    assert player.view.triangle.labels is labels
    assert [label.get_text() for label in labels] == ["v1", "v2", "v3"]
    player.close()


# -- fast ticks --------------------------------------------------------------------------------
def test_fast_png_decodes_to_the_figure():
    from PIL import Image

    p = FillPlayer(triangle(), W, H, method="halfplane", backend="image", step=40)
    png = bytes(p.frames.poster)
    shown = np.asarray(Image.open(__import__("io").BytesIO(png)).convert("RGBA"))
    np.testing.assert_array_equal(shown, np.asarray(p.fig.canvas.buffer_rgba()))
    with pytest.raises(ValueError, match="RGBA"):
        display.encode_png(np.zeros((2, 2, 3), dtype=np.uint8))
    p.close()


@pytest.mark.parametrize("method", ["span", "halfplane"])
def test_play_shows_every_step(method):
    """Every step has its frame in the page; every work step (a raster line, a pixel)
    changes the picture. (Set-up steps such as snap -> winding differ only in the caption
    and the step label.)"""
    p = FillPlayer(triangle(), W, H, method=method, backend="image")
    trace = p.trace
    key = p.frames.key
    n = min(p.slider.max, trace.first_work_step + 40)
    groups = [p._group(g) for g in range(n // key + 1)]
    for k in range(1, n + 1):
        pngs = groups[k // key][1]
        if trace.first_work_step <= k < trace.interpolation_step:
            assert k % key == 0 or pngs[k % key], k  # a patch: the picture changed
    p.close()


def test_player_blits_its_steps_and_keeps_its_fills(player):
    player._group(0)
    player.view.show_step(3, draw=False)
    assert not player.view.redraw()  # the step was blitted: nothing left to draw fully
    span = player.fill
    player.method.value = "halfplane"
    player.method.value = "span"
    assert player.fill is span  # toggling back reuses the fill, no new rasterisation


def test_player_with_samples_steps_as_its_poster_shows_rings_where_it_colours_by_u():
    """Review r11 (lesson 00 c14, 4× MSAA): the last step's filled sample dots hid its u
    colours; they were rings there, which r33 could not tell from the uncovered samples'
    dots: now filled blue and drawn only in the pixels an edge crosses. And the page's frames (blitted) are the pictures a poster
    (a full draw) shows: the dots' layer lay above the labels, over v1 and E31, in frames only."""
    from teachraster.plotting.frames import frame_rgba

    p = FillPlayer(triangle(), W, H, method="halfplane", samples="4 standard (rotated grid)",
                   backend="image")  # fmt: skip
    try:
        covered = p.sample_dots.covered
        last = p.frames.max
        for k in (last, 2):
            p.view.show_step(k, draw=False)
            p.fig.canvas.draw()  # as a poster is drawn
            poster = frame_rgba(p.fig).astype(int)
            p.view.redraw()  # as the page's frames are
            diff = np.abs(frame_rgba(p.fig).astype(int) - poster).max(axis=-1)
            assert diff.max() <= 8, (k, int((diff > 8).sum()))
            # filled at every step (plot_samples' bold, review r33): never white rings
            assert (covered.get_facecolor()[:, 3] == 1).all()
    finally:
        p.close()


def _colour_showing(p) -> float:
    """The share of the screen inside the fill's inner pixels (every sample of the pixel and
    of its eight neighbours covered) that shows the pixel's own colour at the last step."""
    from teachraster.plotting.frames import frame_rgba

    p.view.show_step(p.frames.max, draw=False)
    p.fig.canvas.draw()
    rgb = frame_rgba(p.fig)[..., :3] / 255.0
    full = p.fill.sample_coverage.all(axis=2)
    inner = full.copy()
    inner[1:-1, 1:-1] &= np.all([np.roll(np.roll(full, dr, 0), dc, 1)[1:-1, 1:-1]
                                 for dr in (-1, 0, 1) for dc in (-1, 0, 1)], axis=0)  # fmt: skip
    inner[[0, -1], :] = inner[:, [0, -1]] = False
    image = p.view.values
    to_px, height = p.view.ax.transData.transform, rgb.shape[0]
    shown = total = 0
    for i, j in zip(*np.nonzero(inner)):
        colour = np.asarray(image.cmap(image.norm(image.get_array()[i, j])))[:3]
        (x0, y0), (x1, y1) = to_px((j, i)), to_px((j + 1, i + 1))  # y0 > y1: rows run down
        cut = rgb[int(height - y0) + 3 : int(height - y1) - 3, int(x0) + 3 : int(x1) - 3]
        shown += int((np.abs(cut - colour).max(axis=-1) < 0.1).sum())
        total += cut.shape[0] * cut.shape[1]
    assert total > 0
    return shown / total


@pytest.mark.parametrize("samples", ["4 standard (rotated grid)", "8 standard", "16 standard"])
def test_player_rings_leave_the_pixels_colour_visible(samples):
    """Review r12 (lesson 00's FillPlayer at 8 and 16 samples): the last step's rings, at the
    style's size and width, covered the triangle's colours. Rings and their outlines scale
    with the samples' spacing: at least half of the inner pixels shows their colour, as at 4
    samples (0.52 with the style's rings; 0.25 at 8 and 0.06 at 16, now 0.65 to 0.74)."""
    import matplotlib as mpl

    from teachraster.plotting import use_style

    with mpl.rc_context():
        use_style("classroom")  # as lesson 00 runs it
        p = FillPlayer(triangle(), W, H, method="span", samples=samples, backend="image")
        try:
            assert _colour_showing(p) > 0.5, samples
        finally:
            p.close()


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # raised inside ipympl
def test_ipympl_sends_one_fast_frame_per_step():
    pytest.importorskip("ipympl")
    from io import BytesIO

    from matplotlib.backends.backend_webagg_core import FigureCanvasWebAggCore
    from PIL import Image

    from teachraster.plotting import FillView
    from teachraster.widgets.common import fill_axes

    fig = display.new_figure((8, 6), "ipympl")
    fill = tr.rasterize(triangle(), W, H, method="halfplane", trace=True)
    view = FillView(fill, ax=fill_axes(fig, W, H), step=0, caption=False)
    shown = display.FigureDisplay(fig, "ipympl", draw=view.redraw)
    canvas = fig.canvas
    canvas.syncing_data_url = False  # as once a browser shows it
    sent = []
    canvas.send_binary = sent.append

    class Step:  # what a widget does at each step
        def __setattr__(self, name, k):
            view.show_step(k, draw=False)
            shown.refresh()

    p = SimpleNamespace(slider=Step(), close=shown.close)
    for k in range(1, 6):
        p.slider.value = k
        assert len(sent) == k  # each step reaches the browser
    # the fast encoder sends the pixels matplotlib's own would
    before = canvas._last_buff.copy()
    p.slider.value = 30
    frame = np.asarray(Image.open(BytesIO(sent[-1])).convert("RGBA"))
    canvas._last_buff, canvas._png_is_old = before, True
    theirs = FigureCanvasWebAggCore.get_diff_image(canvas)
    np.testing.assert_array_equal(frame, np.asarray(Image.open(BytesIO(theirs)).convert("RGBA")))
    p.close()


def test_step_label_follows_the_slider(player):
    # review r249 S5: the steps are numbered from 0, so the readout gives their range ("9 of
    # 0–17"), not the last number ("9 of 17" read as a count of 17 steps), as FillView does
    player.slider.value = 0
    assert player.step_info == f"of 0–{len(player.trace) - 1} (snap)"
    player.method.value = "halfplane"
    player.slider.value = player.trace.first_work_step
    assert player.step_info == f"of 0–{len(player.trace) - 1} (pixel)"
    assert player.view.header.get_text() == "Half-planes"  # still: drawn once, not per step


def test_the_last_step_of_a_triangle_without_attributes_is_named_result():
    """Review r354 02-S5: lesson 02's player read "172 of 0–172 (interpolate)" beside "no
    attributes to interpolate"; the last step of a bare triangle shows the result."""
    from teachraster.plotting.frames import step_info

    bare = tr.rasterize(tr.Triangle([[1, 1], [14, 4], [5, 14]]), W, H, trace=True).trace
    assert "no attributes to interpolate" in bare.step(-1).caption
    assert step_info(bare, -1) == f"of 0–{len(bare) - 1} (result)" and not bare.interpolates
    from teachraster.plotting import FillView

    view = FillView(bare, step=-1)  # the figure's header names it alike
    assert view.header.get_text().endswith(f"step {len(bare) - 1} of 0–{len(bare) - 1} (result)")
    assert tr.rasterize(triangle(), W, H, trace=True).trace.interpolates


# -- dragging in the page ----------------------------------------------------------------------
def test_page_drag_moves_the_vertex_and_answers_each_position(editor):
    page = editor.display.widget
    sent = []
    page.send = lambda content, buffers=None: sent.append((content, buffers))
    interp_draws = editor.interp_display.draws
    for seq, (x, y) in enumerate([(10.0, 5.0), (10.5, 5.25), (11.0, 6.0)], start=1):
        page._on_page_message(page, {"type": "move", "i": 1, "x": x, "y": y, "seq": seq}, [])
        assert sent[-1][0]["seq"] == seq  # the answer the page waits for before sending more
        _, _, pw, ph = sent[-1][0]["place"]
        assert len(sent[-1][1][0]) == 4 * pw * ph > 0  # the changed rectangle, raw RGBA
    assert editor.interp_display.draws == interp_draws  # the comparison waits for the release
    assert editor.view.triangle.labels[0].get_visible()  # hidden for the drag's frames only
    page._on_page_message(
        page, {"type": "move", "i": 1, "x": 11.25, "y": 6.5, "seq": 4, "final": True}, []
    )
    assert editor.fill.trace.snapped[1].tolist() == [11.25, 6.5]  # exactly where it let go
    assert (editor.x[1].value, editor.y[1].value) == (11.25, 6.5)
    assert editor.interp_display.draws == interp_draws + 1
    assert editor.interp_view.trace is editor.fill.trace
    # the page knows where the vertices are on the figure
    x0, y0, sx, sy = page.transform
    px, py = editor.view.ax.transData.transform(editor.xy[1])
    assert x0 + sx * 11.25 == pytest.approx(px)
    assert y0 + sy * 6.5 == pytest.approx(page.size[1] - py)
    assert page.handles[1] == [11.25, 6.5]


def test_page_drag_a_position_arriving_after_the_release_leaves_the_figure_at_the_release(
    editor,
):
    """Review r354 W1: after a fast drag, the figure and the area stayed on the drag's first
    position while the sliders showed where it was let go (ipykernel 7 handed the busy
    kernel the first position after the release). It is dropped, and outside a drag the
    sliders, not a drag's left-over positions, say where the vertices are."""
    page = editor.display.widget
    page.send = lambda content, buffers=None: None
    move = {"type": "move", "i": 1, "view": "a"}
    page._on_page_message(page, {**move, "x": 10.0, "y": 5.0, "seq": 2}, [])
    page._on_page_message(page, {**move, "x": 2.5, "y": 5.5, "seq": 3, "final": True}, [])
    page._on_page_message(page, {**move, "x": 10.5, "y": 5.0, "seq": 1}, [])  # late: dropped
    assert editor._drag_xy is None and (editor.x[1].value, editor.y[1].value) == (2.5, 5.5)
    assert editor.fill.trace.snapped[1].tolist() == [2.5, 5.5] == page.handles[1]
    assert f"area {abs(editor.fill.trace.signed_area):.2f}" in editor.info.value
    page._on_page_message(page, {**move, "view": "b", "x": 9.0, "y": 5.0, "seq": 1}, [])
    assert editor.fill.trace.snapped[1].tolist() == [9.0, 5.0]  # another view's drag: taken
    editor.y[1].value = 6.0  # a slider outside a drag: the drag's position is not kept
    assert editor.fill.trace.snapped[1].tolist() == [2.5, 6.0] and editor._drag_xy is None


def test_editor_redraws_only_the_triangle(editor):
    editor.set_vertex(1, x=9.0, y=4.0)
    blit = editor._blits["fill"]
    editor.set_vertex(1, x=9.5, y=4.5)
    assert editor._blits["fill"] is blit  # same plan, cached background
    assert not blit.draw()  # nothing left that needs a full draw
    # the blitted picture is the figure's own drawing
    blitted = np.asarray(editor.fig.canvas.buffer_rgba()).copy()
    editor.fig.canvas.draw()
    full = np.asarray(editor.fig.canvas.buffer_rgba())
    assert (blitted != full).any(axis=2).mean() < 0.01  # up to anti-aliased edges


def test_toggling_back_sends_the_frames_made_before_instead_of_a_poster(player):
    frames = player.frames
    sent = []
    frames.send = lambda content, buffers=None: sent.append(content)
    frames._on_page_message(frames, {"type": "group", "group": 0, "gen": frames.gen}, [])
    player.method.value = "halfplane"
    assert frames.poster  # a fill never shown: one full draw
    player.method.value = "span"
    assert frames.poster == b"" and sent[-1]["group"] == 0 and sent[-1]["gen"] == frames.gen


def test_player_and_editor_display_a_picture_output_before_the_widget(player, editor,
                                                                      monkeypatch):  # fmt: skip
    import IPython.display

    shown = []
    monkeypatch.setattr(IPython.display, "publish_display_data",
                        lambda data, **kw: shown.append(data))  # fmt: skip
    view = "application/vnd.jupyter.widget-view+json"
    for widget in (player, editor):
        shown.clear()
        widget._ipython_display_()
        picture, live = shown
        # what a reopened notebook shows (JupyterLab: the widget's output is an error then)
        assert view not in picture and "teachraster-static" in picture["text/html"]
        assert "to bring " in picture["text/html"]  # the editor's own words (editor.py)
        assert (
            "data:image/png;base64," in picture["text/html"] and "<style>" in picture["text/html"]
        )
        # the view's own text/html is empty: where it is rendered in place of the widget (an
        # untrusted notebook, a converter) the stand-in above stands once (review r158)
        assert view in live and live["text/html"] == ""


def test_pictures_drawn_ahead_are_the_ones_a_toggle_draws_and_leave_the_fill_as_it_was():
    ahead = FillPlayer(triangle(), W, H, backend="image")
    fresh = FillPlayer(triangle(), W, H, backend="image")
    for p in (ahead, fresh):
        p.frames.send = lambda content, buffers=None: None
        p.frames.value = 5
    for _ in range(3):  # one neighbouring fill per call (the kernel's event loop chains them)
        ahead._draw_ahead()
    assert {key for key, _ in ahead._posters} == set(ahead._neighbours())
    # the fill on show is untouched: the same frames as a player that drew nothing ahead
    assert ahead._group(0) == fresh._group(0) and ahead.step == fresh.step == 5
    ahead.method.value = fresh.method.value = "halfplane"
    assert ahead.frames.poster == fresh.frames.poster  # used, and what the toggle draws
    assert not any(key[0] == "halfplane" for key, _ in ahead._posters)  # taken once
    for p in (ahead, fresh):
        p.close()


def test_page_drag_sends_patches_during_the_drag_and_a_whole_frame_at_the_release(editor):
    from teachraster.plotting.frames import frame_rgba

    page = editor.display.widget
    sent = []
    page.send = lambda content, buffers=None: sent.append((content, buffers))
    poster = page.poster
    for seq, x in enumerate([10.0, 10.5, 11.0], start=1):
        page._on_page_message(page, {"type": "move", "i": 1, "x": x, "y": 5.0, "seq": seq}, [])
    patches = [c for c, _ in sent]
    # each patch is the rectangle that changed, numbered after the frame it applies to
    assert all(c["place"] is not None for c in patches)
    assert [c["n"] for c in patches] == list(range(patches[0]["n"], patches[0]["n"] + 3))
    w, h = page.size
    for c, (raw,) in sent:
        px, py, pw, ph = c["place"]  # raw RGBA pixels of the rectangle (no decode in the page)
        assert len(raw) == 4 * pw * ph and pw * ph < w * h  # smaller than the figure
        assert 0 <= px and px + pw <= w and 0 <= py and py + ph <= h
    assert page.poster == poster  # the poster is a whole frame: it waits for the release
    page._on_page_message(page, {"type": "move", "i": 1, "x": 11.0, "y": 5.5, "seq": 4,
                                 "final": True}, [])  # fmt: skip
    content, (png,) = sent[-1]
    assert content["place"] is None and page.poster == png and page.poster_frame == content["n"]
    assert content["handles"][1] == [11.0, 5.5] == page.handles[1]
    assert frame_rgba(editor.fig).shape[:2] == (h, w)


def test_live_slider_applies_page_values_and_answers_each(monkeypatch):
    from teachraster.widgets import LiveSlider

    s = LiveSlider(value=30.0, min=0.0, max=90.0, step=1.0, description="tilt (°)")
    seen, sent = [], []
    s.observe(lambda change: seen.append(change["new"]), "value")
    s.send = lambda content, buffers=None: sent.append(content)
    for seq, v in enumerate([40.0, 55.0, 120.0], start=1):
        s._on_page_message(s, {"type": "value", "value": v, "seq": seq}, [])
    assert seen == [40.0, 55.0, 90.0] and s.value == 90.0  # clipped to the range
    assert [c["seq"] for c in sent] == [1, 2, 3] and s.messages == 3
    log = LiveSlider(value=0.1, base=10, min=-2, max=1, step=0.05)
    log.value = 1e-5
    assert log.value == pytest.approx(0.01)


# -- drafts while a LiveSlider is dragged --------------------------------------------------------
def _page_value(slider, value, final, seq=[0]):  # noqa: B006 (a counter across calls)
    seq[0] += 1
    slider._on_page_message(slider, {"type": "value", "value": value, "final": final,
                                     "seq": seq[0]}, [])  # fmt: skip


def test_live_slider_marks_drafts_and_calls_back_on_release():
    from teachraster.widgets import LiveSlider

    s = LiveSlider(value=10.0, min=0.0, max=90.0, step=1.0)
    s.send = lambda content, buffers=None: None
    seen, released = [], []
    s.observe(lambda change: seen.append((change["new"], s.dragging)), "value")
    s.on_release(lambda: released.append(s.value))
    for v in (11.0, 12.0):
        _page_value(s, v, False)
    _page_value(s, 12.0, True)  # released where the last draft was: the callback
    assert seen == [(11.0, True), (12.0, True)] and released == [12.0] and not s.dragging
    _page_value(s, 13.0, False)
    _page_value(s, 14.0, True)  # released elsewhere: the observers, not a draft
    assert seen[-1] == (14.0, False) and released == [12.0]
    _page_value(s, 20.0, True)  # a key: final at once
    assert seen[-1] == (20.0, False) and released == [12.0]


def _shown(widget) -> bytes:
    """The pixels a slider explorer sent the page last (its figure's Agg buffer)."""
    return bytes(widget.display.widget._last)


@pytest.mark.parametrize("name", ["viewer", "filter", "plane"])
def test_a_drag_ends_on_the_full_picture(name):
    from teachraster.widgets import FilterExplorer, PlaneExplorer

    def make():
        if name == "viewer":
            w = TexturedPlaneViewer(64, 48, tilt=60.0, backend="image")
            return w, w.tilt, [61.0, 63.0, 70.0, 75.0], 30.0
        if name == "filter":
            w = FilterExplorer(48, 36, tilt=80.0, samples=3, backend="image")
            return w, w.tilt, [61.0, 63.0, 70.0, 75.0], 30.0
        w = PlaneExplorer(backend="image")
        return w, w.f[1], [1.2, 1.5, 1.8], -0.5

    dragged, slider, values, elsewhere = make()
    direct, direct_slider, _, _ = make()
    for s in (slider, direct_slider):
        s.send = lambda content, buffers=None: None
    for v in values:
        _page_value(slider, v, False)
    assert slider.dragging is False  # only while the observers run
    draft = _shown(dragged)
    _page_value(slider, values[-1], True)  # released on the last draft
    direct_slider.value = values[-1]
    assert _shown(dragged) == _shown(direct) != draft
    _page_value(slider, values[0], False)
    _page_value(slider, elsewhere, True)  # released on a new value
    direct_slider.value = elsewhere
    assert _shown(dragged) == _shown(direct)
    dragged.close()
    direct.close()


def test_the_filter_explorers_colour_bar_comes_from_its_cache_at_a_new_tilt():
    """Issue 31: the error's colour bar was drawn afresh at every release (~26 ms of ~65):
    its range was the error's maximum, new at every tilt. The range is now fixed, one scale
    for every filter and tilt (review r26, 09), and the note sits clear of the bar, so a new
    tilt or filter puts the bar back, and the picture is the one a fresh explorer draws."""
    from teachraster.widgets import FilterExplorer
    from teachraster.widgets.filter_explorer import ERROR_RANGE

    ex = FilterExplorer(tilt=80.0, backend="image")  # the lesson's size: the layout counts
    error = ex.panels["error"]
    assert error.image.get_clim() == (0.0, ERROR_RANGE)
    ex.tilt.value = 60.0  # another maximum, the same range
    assert 0 < error.maximum < ERROR_RANGE
    assert error.image.get_clim() == (0.0, ERROR_RANGE) and ex._bar.last == "cached"
    fresh = FilterExplorer(tilt=60.0, backend="image")
    assert _shown(ex) == _shown(fresh)
    ex.filter.value = "nearest"  # another filter (maximum 0.46): still the same bar
    assert error.image.get_clim() == (0.0, ERROR_RANGE) and ex._bar.last == "cached"
    ex.close()
    fresh.close()


def test_a_colour_bar_put_back_from_its_cache_is_the_one_drawn():
    viewer = TexturedPlaneViewer(64, 48, tilt=30.0, backend="image")
    first = _shown(viewer)
    viewer.tilt.value = 50.0
    viewer.tilt.value = 30.0  # the colour bar's range comes round again
    assert viewer._bar.last == "cached"
    assert _shown(viewer) == first
    # the range ends on a round number (25 at 30° and 31°, whose maxima differ), so a new
    # tilt puts the bar back too, and the picture is a fresh viewer's at that tilt; the
    # bar ends near the maximum the title states (review r91 04-E: it ran to 40 for 31.7)
    viewer.tilt.value = 31.0
    assert viewer._bar.last == "cached" and viewer.view.heatmap.image.get_clim() == (0.0, 25.0)
    assert 25.0 - viewer.maximum < 0.2 * viewer.maximum
    fresh = TexturedPlaneViewer(64, 48, tilt=31.0, backend="image")
    assert _shown(viewer) == _shown(fresh)
    fresh.close()
    viewer.tilt.value = 70.0  # a range not drawn before (35): drawn
    assert viewer._bar.last == "drawn" and viewer.view.heatmap.image.get_clim() == (0.0, 35.0)
    # the two renders are labelled alike (no ticks) and the affine curve is not hidden
    assert not viewer.view.axes[0].get_xticks().size and not viewer.view.axes[1].get_xticks().size
    viewer.close()
    # the lesson's size and style, where the v-curve has a row of its own
    wide = TexturedPlaneViewer(tilt=0.0, backend="image", style="classroom")
    affine, persp = wide.profile.lines  # at 0° they coincide: the affine one dashed, on top
    assert affine.get_zorder() > persp.get_zorder() and affine.get_linestyle() == "--"
    wide.close()


def test_a_slider_explorer_sends_patches_and_keeps_the_final_picture_as_its_poster():
    from teachraster.plotting.frames import encode_png

    viewer = TexturedPlaneViewer(64, 48, tilt=30.0, backend="image")
    page, sent = viewer.display.widget, []
    page.send = lambda content, buffers=None: sent.append((content, buffers))
    viewer.tilt.send = lambda content, buffers=None: None
    poster = page.poster
    _page_value(viewer.tilt, 40.0, False)  # a draft: a patch, the poster as it was
    _page_value(viewer.tilt, 45.0, True)  # a key (final): a patch too, then the poster
    w, h = page.size
    for content, (packed,) in sent:
        px, py, pw, ph = content["place"]  # RGBA (zlib), painted at once by the page
        assert content["deflate"] and len(zlib.decompress(packed)) == 4 * pw * ph
        assert 0 < pw * ph <= w * h
    assert page.poster != poster and page.poster_frame == sent[-1][0]["n"]
    assert page.poster == encode_png(page._last)  # a re-opened view shows the final picture
    viewer.close()


def test_a_vertex_dragged_in_a_slider_explorer_comes_back_deflated_and_holds_drawing_ahead():
    """Issue 31: the PlaneExplorer's vertex drag answered each position with 0.5-0.7 MB of
    raw pixels, which the server, the browser and the page each handled (21 fps against the
    editor's 36 at 0.5 MB). Its drafts are deflated now (the page inflates them without
    the browser process, drag.js), as a slider's are; the release's picture stays raw
    (painted at once); each is the picture's changed pixels. While a point is dragged in
    any figure of the kernel, nothing is drawn ahead (dragging.dragged_within)."""
    from teachraster.widgets import PlaneExplorer
    from teachraster.widgets.dragging import dragged_within

    e = PlaneExplorer(backend="image")
    page, sent = e.display.widget, []
    page.send = lambda content, buffers=None: sent.append((content, buffers))
    for s in e.x + e.y + e.f:
        s.send = lambda content, buffers=None: None
    for seq, x in enumerate([12.0, 11.0], start=1):
        page._on_page_message(page, {"type": "move", "i": 1, "x": x, "y": 5.0, "seq": seq}, [])
        assert dragged_within(5.0)
    page._on_page_message(page, {"type": "move", "i": 1, "x": 10.0, "y": 5.0, "seq": 3,
                                 "final": True}, [])  # fmt: skip
    assert not dragged_within(5.0)  # released
    frames = [(c, b) for c, b in sent if c["type"] == "frame"]
    assert len(frames) == 3
    for content, (data,) in frames:
        px, py, pw, ph = content["place"]
        final = content is frames[-1][0]  # the release's: raw, painted at once
        raw = data if final else zlib.decompress(data)
        assert content["deflate"] != final and len(raw) == 4 * pw * ph
        assert final or len(raw) > 8 * len(data)
        picture = page._ref.copy()
        picture[py : py + ph, px : px + pw] = np.frombuffer(raw, np.uint8).reshape(ph, pw, 4)
    assert np.array_equal(picture, page._last)  # the last: the final picture
    assert e.x[1].value == 10.0
    sent.clear()
    _page_value(e.x[1], 9.0, False)  # a slider's draft: deflated as before
    content, (packed,) = next((c, b) for c, b in sent if c["type"] == "frame")
    _, _, pw, ph = content["place"]
    assert content["deflate"] and len(zlib.decompress(packed)) == 4 * pw * ph
    e.close()


def test_filter_truths_computed_ahead_are_the_truths_at_those_tilts():
    from teachraster.widgets import FilterExplorer

    ex = FilterExplorer(48, 36, tilt=80.0, samples=3, backend="image")
    ex._truths_ahead()  # one step up, then (next call) one step down
    ex._truths_ahead()
    assert {("square", 79.0), ("square", 81.0)} <= set(ex._truths)  # keyed by scene and tilt
    ahead = ex._truths["square", 81.0]
    ex.tilt.value = 81.0  # an arrow key: the truth at hand
    assert ex.truth is ahead
    direct = FilterExplorer(48, 36, tilt=81.0, samples=3, backend="image")
    np.testing.assert_array_equal(ahead, direct.truth)
    ex.close()
    direct.close()


def test_filter_truths_ahead_reach_every_tilt_nearest_first_so_a_drag_ends_on_one():
    from teachraster.widgets import FilterExplorer

    ex = FilterExplorer(16, 12, tilt=80.0, samples=2, backend="image")
    order = []
    while (ahead := ex._next_truth_ahead()) is not None:
        order.append(ahead)
        ex._truths_ahead()
    assert order[:4] == [81.0, 79.0, 82.0, 78.0]  # nearest first, the next one up first
    assert set(ex._truths) == {("square", float(t)) for t in range(90)}  # every one, none lost
    kept = ex._truths["square", 3.0]
    ex.tilt.value = 3.0  # a drag released far from 80 (or a value set from code) ...
    assert ex.truth is kept  # ... finds its truth kept, not computed again
    ex.close()


def test_depth_explorer_drafts_end_on_the_picture_set_from_code():
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    dragged, direct = (DepthPrecisionExplorer(backend="image") for _ in range(2))
    for w in (dragged, direct):
        w.near.send = lambda content, buffers=None: None
    for v in (0.5, 1.0, 3.0):
        _page_value(dragged.near, v, False)
    _page_value(dragged.near, 3.0, True)
    direct.near.value = 3.0
    assert _shown(dragged) == _shown(direct)
    assert dragged.now.get_text() == direct.curve.get_label() == "now: unorm24, near 3"
    for w in (dragged, direct):  # a new format lays the legend out again, the same way
        w.reverse.value, w.format.value = True, "float32"
    assert _shown(dragged) == _shown(direct)
    dragged.close()
    direct.close()


# -- text size on screen at 1024 x 768 (issue 29) ----------------------------------------
#: JupyterLab's output column at 1024 x 768 with the file browser open (CSS px).
NARROW_COLUMN_PX = 585


def smallest_text_px(fig, *, max_height: float | None = None, ignore=(),
                     column: float = NARROW_COLUMN_PX) -> tuple[float, str]:  # fmt: skip
    """The smallest drawn text of ``fig`` (but ``ignore``) in CSS px as shown in a
    ``column`` px wide column: an image widget is at most the column's width (and
    ``max_height``), scaled whole."""
    from matplotlib.text import Text

    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    w, h = fig.get_figwidth() * fig.dpi, fig.get_figheight() * fig.dpi
    scale = min(1.0, column / w, (max_height / h) if max_height else 1.0)
    sizes = []
    for text in fig.findobj(Text):
        if not (text.get_visible() and text.get_text().strip()) or text.get_text() in ignore:
            continue
        if text.axes is not None and not text.axes.get_visible():
            continue
        box = text.get_window_extent(renderer)
        if box.width > 0 and box.overlaps(fig.bbox):  # drawn, inside the figure
            sizes.append((text.get_fontsize() * fig.dpi / 72 * scale, text.get_text()))
    return min(sizes)


def _comparison_figure():
    from teachraster.widgets.player import COMPARISON_MAX_PX

    tri = tr.Triangle([[1.5, 2.25], [14.75, 5.5], [4.25, 14.5]], w=[1.0, 2.0, 4.0],
                      attrs={"u": [0.0, 1.0, 0.0]})  # fmt: skip
    p = FillPlayer(tri, W, H, method="halfplane", step=-1, backend="image")
    return p, p.interp_display.fig, COMPARISON_MAX_PX


def _steps_figure():
    tri = tr.Triangle([[1.5, 2.25], [14.75, 5.5], [4.25, 14.5]], w=[1.0, 2.0, 4.0],
                      attrs={"u": [0.0, 1.0, 0.0]})  # fmt: skip
    p = FillPlayer(tri, W, H, method="halfplane", step=40, backend="image")  # E12 ... shown
    return p, p.fig, None


def _viewer_figure():
    v = TexturedPlaneViewer(tilt=60, checks=4, backend="image")
    return v, v.fig, None


def _filter_figure():
    from teachraster.widgets import FilterExplorer

    f = FilterExplorer(tilt=0, filter="nearest", repeats=6, backend="image")  # as lesson 09
    return f, f.fig, None


def _plane_figure():
    from teachraster.widgets import PlaneExplorer

    e = PlaneExplorer(backend="image")  # lesson 03's triangle and values are the defaults
    return e, e.fig, None


def _divide_cost_figure():
    from teachraster.study import bench
    from teachraster.study import operation_counts as ops
    from teachraster.widgets.divide_cost import DivideCostExplorer

    rows = bench.bench_interpolation(bench.sizes(True), 1, bench.Progress(1, enabled=False))
    e = DivideCostExplorer(ops.with_counts(rows), backend="image")  # lesson 06's, r20 06-6
    return e, e.fig, None


@pytest.mark.parametrize("make", [_steps_figure, _comparison_figure, _viewer_figure,
                                  _filter_figure, _plane_figure, _divide_cost_figure])  # fmt: skip
def test_widget_figures_read_12_px_in_the_column_at_1024_px(make):
    """Reviews r9/r10 (00 c14, 04 c15, 04 c25): the player's comparison and lesson 04's
    viewer, 940 px wide at 80 dpi, are shown 585 px wide at 1024 x 768, where their tick
    labels, colour-bar ticks, key and notes read 7-11 px (the steps' key and edge names
    11.7). Lessons use the classroom style; the FilterExplorer (lesson 09) and
    PlaneExplorer (03) are checked alike."""
    from teachraster.plotting import use_style

    with use_style("classroom"):
        widget, fig, max_height = make()
    try:
        size, text = smallest_text_px(fig, max_height=max_height)
        assert size >= 12.0, (size, text)  # r15: the comparison's v1, v2, v3 read 11.8
    finally:
        widget.close()


def test_the_comparison_reads_12_px_inside_its_accordion_at_1024_px():
    """Review r20 (00 c14): inside the player's accordion the comparison is shown 556 px wide
    at 1024 x 768 with the file browser open (the column less the accordion's padding), where
    its text read 11.8 px; it is sized for that width. Its heatmap and colour bar name the
    error |Δu|, as lesson 00's heatmap does, and the row's curves fill their panel."""
    from teachraster.plotting import use_style
    from teachraster.widgets.player import COMPARISON_SHOWN_PX

    with use_style("classroom"):
        widget, fig, max_height = _comparison_figure()
    try:
        size, text = smallest_text_px(fig, max_height=max_height, column=COMPARISON_SHOWN_PX)
        assert size >= 12.0, (size, text)
        from matplotlib.text import Text

        view = widget.interp_view
        texts = [t.get_text() for t in fig.findobj(Text)]
        assert "|Δu|" in texts and any(t.startswith("|Δu|: max") for t in texts)
        assert not any("error" in t for t in texts)
        x0, x1 = view.profile.title.axes.get_xlim()
        shown = np.isfinite(view.profile.lines[0].get_ydata())
        centres = np.asarray(view.profile.lines[0].get_xdata())[shown]
        assert x0 <= centres.min() - 0.5 and centres.max() + 0.5 <= x1  # every covered pixel
        assert x1 - x0 <= centres.max() - centres.min() + 3  # and one pixel either side
    finally:
        widget.close()


def test_the_comparison_reads_classroom_size_and_rings_beside_its_pixel_r225():
    """Review r225 FIG1 (lesson 00 c14): in a classroom's 920-px column the comparison, scaled
    down to its greatest height, read 11-13 px beside the lesson's figures' 17; its text now
    reads 20 px there (the panels a little smaller) and 13 in the accordion at 1024 px. The
    ring round the largest error lay on that pixel and hid its colour: it now runs round it,
    clear of its corners."""
    from teachraster.plotting import use_style
    from teachraster.widgets.player import (
        CLASSROOM_COLUMN_PX,
        COMPARISON_CLASSROOM_PX,
        COMPARISON_SHOWN_PX,
    )

    with use_style("classroom"):
        widget, fig, max_height = _comparison_figure()
    try:
        size, text = smallest_text_px(fig, max_height=max_height, column=CLASSROOM_COLUMN_PX)
        assert size >= COMPARISON_CLASSROOM_PX - 0.5, (size, text)
        size, text = smallest_text_px(fig, max_height=max_height, column=COMPARISON_SHOWN_PX)
        assert size >= 13.0, (size, text)
        ring = widget.interp_view.heatmap.marker
        ax = ring.axes
        (x0, _), (x1, _) = ax.transData.transform([(0.0, 0.0), (1.0, 0.0)])
        pixel = abs(x1 - x0) * 72 / fig.dpi  # points
        inner = ring.get_markersize() / 2 - ring.get_markeredgewidth() / 2
        assert ring.get_visible() and inner >= 0.75 * pixel > 0.5 * np.sqrt(2) * pixel
    finally:
        widget.close()


def test_the_comparison_reads_22_px_with_its_labels_off_the_frames_r241():
    """Review r241 FIG1 (lesson 00's player): at 20 px the comparison's digits were 14-15 px
    tall beside the lesson's figures' 17; the row tick "0" ran into the v1 label ("0-v1"),
    and v1's white box sat on the panel's frame (on the orange frame of the panel in use).
    Its text now reads 22 px in a classroom's column, the titles stand clear of the column
    labels that grew with them, the first panel has no row 0, and every vertex label lies
    wholly inside its panel or wholly beside it, haloed, not boxed, also after a toggle."""
    from matplotlib.transforms import Bbox

    from teachraster.plotting import use_style
    from teachraster.widgets.player import CLASSROOM_COLUMN_PX, COMPARISON_MAX_PX

    tri = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]], w=[1.0, 2.0, 4.0],
                      attrs={"u": [0.0, 1.0, 0.0]})  # fmt: skip  # lesson 00's triangle
    with use_style("classroom"):
        p = FillPlayer(tri, 16, 16, method="span", step=9, backend="image")
    try:
        fig, view = p.interp_display.fig, p.interp_view
        size, text = smallest_text_px(fig, max_height=COMPARISON_MAX_PX,
                                      column=CLASSROOM_COLUMN_PX)  # fmt: skip
        assert size >= 22.0 - 0.5, (size, text)
        rows = [t.get_text() for t in view.axes[0].get_yticklabels()]
        assert rows == ["4", "8", "12"]
        for toggle in (None, "affine"):
            if toggle is not None:
                p.interpolation.value = toggle
            fig.canvas.draw()
            renderer = fig.canvas.get_renderer()
            for tri_art in view.triangles:
                frame = tri_art.outline.axes.get_window_extent(renderer)
                for label in tri_art.labels:
                    box = label.get_window_extent(renderer)
                    inside = frame.x0 < box.x0 and box.x1 < frame.x1
                    beside = box.x1 < frame.x0 or frame.x1 < box.x0
                    assert inside or beside, (label.get_text(), box, frame)
                    assert frame.y0 < box.y0 and box.y1 < frame.y1, label.get_text()
                    assert label.get_bbox_patch() is None and label.get_path_effects()
            # each title above its panel's column labels, the labels of one vertex on one
            # panel apart from another panel's and from the colour bars
            ax = view.axes[0]
            top = Bbox.union([t.get_window_extent(renderer) for t in ax.get_xticklabels()]
                             + [ax.xaxis.label.get_window_extent(renderer)])  # fmt: skip
            assert ax.title.get_window_extent(renderer).y0 > top.y1
            labels = [lb.get_window_extent(renderer) for t in view.triangles for lb in t.labels]
            bars = [im.colorbar.ax.get_window_extent(renderer)
                    for im in (*view.images, view.heatmap) if im.colorbar]  # fmt: skip
            for i, a in enumerate(labels):
                assert not any(a.overlaps(b) for b in labels[i + 1 :] + bars)
    finally:
        p.close()


def test_the_hint_says_the_comparison_keeps_one_sample_per_pixel_r241():
    """Review r241 S5: with 4 samples the last caption counted 72 pixels and pointed to the
    comparison below, which shows the 59 of one sample per pixel (its title says so)."""
    from teachraster.widgets.player import COMPARISON_ONE_SAMPLE

    p = _player_at_4_samples()
    try:
        last = p.frames.captions[-1]
        assert "72 pixels" in last and last.endswith(f"{COMPARISON_HINT} {COMPARISON_ONE_SAMPLE}")
        assert "1 sample per pixel" in p.comparison.get_title(0)
        p.samples.value = "1 (centre)"
        assert p.frames.captions[-1].endswith(COMPARISON_HINT)
    finally:
        p.close()


def test_the_split_labels_keep_off_the_raster_line_r225():
    """Review r225 FIG2 (lesson 00's player at its opening step 9, row 5 under the split):
    the "4" sat on row 5's outline and a hollow centre, and "v2" on the dashed split line.
    Both now lie above the split line and row 5's outline, clear of the long edge."""
    from teachraster.plotting import use_style

    tri = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]], w=[1.0, 2.0, 4.0],
                      attrs={"s": [0.0, 1.0, 0.0]})  # fmt: skip  # lesson 00's triangle
    with use_style("classroom"):
        p = FillPlayer(tri, 16, 16, method="span", step=9, backend="image")
    try:
        view = p.view
        view.fig.canvas.draw()
        renderer = view.fig.canvas.get_renderer()
        split = view.split
        assert split.label.get_text() == "4" and split.label.xy == (2.0, 4.5)
        v_mid = float(view.trace.span.sorted_xy[1, 1])
        top_of_row = view.ax.transData.transform([(0.0, 5.0)])[0][1]  # row 5's outline
        line = view.ax.transData.transform([(0.0, v_mid)])[0][1]
        v2 = view.triangle.labels[1]
        for label in (split.label, v2):
            box = label.get_window_extent(renderer)
            assert box.y0 > max(top_of_row, line), label.get_text()  # above both (y up)
    finally:
        p.close()


def keyed(view) -> list[str]:
    """The labels a FillView's key shows."""
    return [t.get_text() for t in view.legend.texts if t.get_visible()]


def _player_at_4_samples(**kw):
    tri = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]], w=[1.0, 2.0, 4.0],
                      attrs={"u": [0.0, 1.0, 0.0]})  # fmt: skip  # lesson 00's triangle
    return FillPlayer(tri, 16, 16, method="span", samples="4 standard (rotated grid)",
                      backend="image", **kw)  # fmt: skip


def test_player_samples_are_filled_or_hollow_and_large_at_every_step():
    """Review r33 (lesson 00 c14): at 4 samples the covered samples (white rings) and the
    uncovered ones (white dots) were about 5 px across at a 592-px column and read alike. Now
    covered filled blue, uncovered hollow vermillion, the same at every step, and at least
    6 px (a quarter pixel) across shown in a 592-px column (a white halo round each)."""
    from matplotlib.colors import to_rgba

    from teachraster.plotting.antialiasing import BOLD_STYLE

    p = _player_at_4_samples()
    try:
        dots, width_px = p.sample_dots, p.fig.get_figwidth() * p.fig.dpi
        (x0, _), (x1, _) = p.view.ax.transData.transform([(0, 0), (1, 0)])
        pixel = abs(x1 - x0) * 592 / width_px  # one of the grid's pixels, in the column
        for k in (p.frames.max // 2, p.frames.max):
            p.view.show_step(k, draw=False)
            face = dots.covered.get_facecolor()
            assert len(face) and np.allclose(face, to_rgba(BOLD_STYLE["covered"][0]))
            assert dots.uncovered.get_markerfacecolor() == "none"
            assert len(dots.uncovered.get_xdata())
            for d in (dots.diameter(), np.sqrt(dots.covered.get_sizes()[0])):
                shown = d * p.fig.dpi / 72 * 592 / width_px  # px in a 592-px column
                assert shown >= 6 and shown >= pixel / 4, (k, shown)  # was 3.8 px
    finally:
        p.close()


def test_player_samples_read_10_px_and_the_key_fits_the_figure():
    """Review r37 (lesson 00 c14): at 4 samples each dot was about 7 px across in an 897-px
    picture whose grid took 420 px. The grid now takes most of the width (the key's column
    only as wide as its longest line), the dots at least 9 px (a 5.4-in grid gave 10.3 px but
    made the player 906 px tall: it must fit a 900-px screen, test_browser_player), every key
    line inside (lesson 00's classroom style)."""
    from matplotlib.text import Text

    from teachraster.plotting.style import COLUMN_WIDTH_PX

    p = _player_at_4_samples(style="classroom")
    try:
        fig = p.fig
        width_px = fig.get_figwidth() * fig.dpi
        assert width_px <= COLUMN_WIDTH_PX
        for k in (0, p.frames.max):
            p.view.show_step(k, draw=False)
            fig.canvas.draw()
            assert p.sample_dots.diameter() * fig.dpi / 72 >= 9.0, k
            renderer = fig.canvas.get_renderer()
            for text in fig.findobj(Text):
                if text.get_visible() and text.get_text().strip():
                    box = text.get_window_extent(renderer)
                    assert box.x1 <= width_px + 0.5, (k, text.get_text())
        grid = p.view.ax.get_window_extent()
        assert grid.width >= 0.5 * width_px  # was 422 of 897 px (0.47)
    finally:
        p.close()


def test_player_shows_samples_untested_until_their_step_and_keys_only_what_is_drawn():
    """Review r33 (lesson 00 c14, step 0): the key listed eight entries (the split's parts,
    the raster line, its span and centres) that the snap step does not draw, and the samples
    were coloured covered / not before any step had tested them. Before the first fill step
    every sample is untested and the key lists that alone; a raster line's samples show
    their result from its step on; the last step shows every one."""
    from teachraster.plotting.frames import frame_rgba

    p = _player_at_4_samples()
    try:
        dots, trace = p.sample_dots, p.view.trace
        p.view.show_step(0, draw=False)
        # r239 01-W1: the snap's own marks too (each vertex's snapped position), keyed first
        snap = ["vertex (its position", "on the 1/256 px grid):"]  # then how far it moved
        assert keyed(p.view) == [*snap, "moved by ≤ 0.0017 px", "sample not tested yet"]
        assert not len(dots.covered.get_offsets()) and not len(dots.uncovered.get_xdata())
        assert len(dots.untested.get_xdata())
        k = trace.first_work_step + 3  # the raster line of the box's fourth row
        p.view.show_step(k, draw=False)
        row = trace.bbox.row0 + 3
        for _x, y in (dots.uncovered.get_data(), dots.covered.get_offsets().T):
            assert (np.floor(y) <= row).all()
        assert (np.floor(dots.untested.get_ydata()) > row).all()
        assert {"sample covered", "sample not covered", "sample not tested yet"} <= set(
            keyed(p.view)
        )
        p.view.show_step(p.frames.max, draw=False)
        assert not len(dots.untested.get_xdata()) and "sample not tested yet" not in keyed(p.view)
        # blitted frames as a full draw shows them, while the tested rows grow
        for k in (trace.first_work_step + 2, trace.first_work_step + 5):
            p.view.show_step(k, draw=False)
            p.view.redraw()
            fast = frame_rgba(p.fig).astype(int)
            p.fig.canvas.draw()
            assert np.abs(fast - frame_rgba(p.fig).astype(int)).max() <= 8, k
    finally:
        p.close()


def test_player_v1_label_leaves_row_1_centre_dots_visible():
    """Review r33 (lesson 00 c14): the "v1" label's white box blanked the centre dots of row
    1, columns 1 and 2. The vertex labels have a white halo round their letters instead of a
    box; the vertex dots stay above them (zorder 6.2, CasePicker's hub at 6.3)."""
    from teachraster.plotting.frames import frame_rgba

    p = _player_at_4_samples()
    try:
        p.view.show_step(0, draw=False)
        p.fig.canvas.draw()
        rgb = frame_rgba(p.fig)[..., :3].astype(int)
        height = rgb.shape[0]
        for j in (1, 2):
            x, y = p.view.ax.transData.transform((j + 0.5, 1.5))
            spot = rgb[int(round(height - y)) - 1 : int(round(height - y)) + 2,
                       int(round(x)) - 1 : int(round(x)) + 2]  # fmt: skip
            assert spot.min() < 160, j  # the grey dot, not a white box
        labels = p.view.triangle.labels
        assert all(label.get_bbox_patch() is None for label in labels)
        assert p.view.triangle.vertices.get_zorder() > max(lab.get_zorder() for lab in labels)
    finally:
        p.close()


def test_depth_explorer_keeps_every_near_end_on_its_axes():
    """Review r38 05b c25: at near 0.01 the float32 curves ran off the bottom (1e-9) of the
    axes; the y range holds each curve from the near plane to the far plane's last half."""
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    w = DepthPrecisionExplorer(backend="image")
    bottom = w.ax.get_ylim()[0]
    w.near.value = 0.01
    for fmt in ("unorm16", "unorm24", "float32"):
        for reverse in (False, True):
            w.format.value, w.reverse.value = fmt, reverse
            # reverse-Z float32 plunges at the far plane itself (denormals): the text says so
            assert w.resolution[w.z < w.far / 2].min() >= bottom, (fmt, reverse)
    w.close()


def test_depth_explorer_legend_names_the_half_the_time_line():
    """Review r47 05b-7: the dotted line had no legend entry; it is named last, so the "now"
    entry stays the second. Review r54 05b-2: it marks where a pair fights half the time
    (Δz = 2δ), no longer where the grid's one pair per depth first fought."""
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    w = DepthPrecisionExplorer("unorm16", near=0.1, far=1000.0, backend="image")
    texts = [t.get_text() for t in w.ax.get_legend().get_texts()]
    assert texts[-1] == "fights half the time (Δz = 2δ)" and texts[1].startswith("now")
    assert np.isfinite(w.marker.get_xdata()).all()  # unorm16 fights: the line is drawn
    w.close()


def test_depth_explorer_names_the_band_left_of_the_near_plane_and_shows_its_start():
    """Review r99 05b-2: the axis starts at the slider's lowest near plane (0.01), so at the
    default near 0.1 its left fifth was an empty band; and the grey "start" curve lay hidden
    under the "now" curve, a key entry for nothing on show. The band is shaded and named, and
    the start curve is a wider halo round the "now" curve."""
    from teachraster.widgets.depth_explorer import DepthPrecisionExplorer

    w = DepthPrecisionExplorer("unorm24", near=0.1, far=1000.0, backend="image")
    assert w.ax.get_xlim()[0] == 0.01
    assert w.band.get_x() == 0.01 and w.band.get_width() == pytest.approx(0.1 - 0.01)
    assert w.band_text.get_visible() and w.band_text.get_text() == "nearer than the near plane"
    assert w.reference.get_linewidth() > w.curve.get_linewidth() + 2  # seen round "now"
    w.near.value = 10.0
    assert w.band.get_width() == pytest.approx(10.0 - 0.01)
    assert w.band_text.get_position()[0] < 0.1  # left of the start curve, which begins at 0.1
    w.near.value = 0.01
    assert w.band.get_width() == pytest.approx(0.0) and not w.band_text.get_visible()
    w.close()


def test_filter_status_line_says_computing_while_a_picture_is_pending():
    """Review r81 09-8: after a filter change and keys the status line still read the last
    picture's numbers ("largest λ 1.8" at 30°); it now says the new picture is on its way
    until it is drawn, and the explorer's caption names the ring round the worst pixel."""
    from teachraster.widgets import FilterExplorer
    from teachraster.widgets.common import PROJECTOR_CSS

    ex = FilterExplorer(16, 12, tilt=0.0, samples=2, backend="image")
    seen = []
    original = type(ex)._render

    def render_and_look(self):
        seen.append(self.info.value)  # what the page shows while the kernel renders
        original(self)

    try:
        type(ex)._render = render_and_look
        ex.filter.value = "nearest_mipmap_nearest"
        ex.tilt.value = 30.0
    finally:
        type(ex)._render = original
    assert seen and all("computing" in s for s in seen), seen
    assert "30°" in seen[-1] and "nearest_mipmap_nearest" in seen[-1]
    assert "computing" not in ex.info.value and "largest λ" in ex.info.value
    title = ex.widget.children[0].value
    assert "ring in the error panel marks the worst pixel" in title
    assert title.startswith(PROJECTOR_CSS) and "tr-projector" in ex.widget._dom_classes
    ex.close()


def test_half_plane_player_at_4_samples_counts_and_greys_as_rasterize_does():
    """Review r93 02-1: at 4 samples lesson 02's player ended "70 pixels covered" where
    ``tr.rasterize(..., samples=4)`` gives 83 pixels with a covered sample, and pixel (4, 10)
    was grey "rejected by test 1" under a covered sample dot. The captions read the recorded
    sample tests: every pixel step says how many of its samples are covered, a pixel with a
    covered sample is never greyed, and the last step counts what ``rasterize`` covers."""
    import re

    tri = tr.Triangle([[2.25, 1.75], [14.5, 6.25], [5.75, 14.5]])  # lesson 02's
    p = FillPlayer(tri, 16, 16, method="halfplane", backend="image")
    try:
        p.samples.value = "4 standard (rotated grid)"
        msaa = tr.rasterize(tri, 16, 16, samples=4)
        trace = p.trace
        p.show_step(-1)
        shown = re.match(r"([\d,]+) pixels with a covered sample \(([\d,]+) with their centre",
                         p.caption_text)  # fmt: skip
        assert shown, p.caption_text
        assert int(shown[1]) == msaa.coverage.sum() == 83  # was "70 pixels covered"
        assert int(shown[2]) == tr.rasterize(tri, 16, 16).coverage.sum() == 70
        assert not (trace.rejected_at(-1) & msaa.coverage).any()
        assert (trace.rejected_at(-1) | msaa.coverage).sum() == trace.bbox.size
        k = trace.first_work_step + (4 - trace.bbox.row0) * trace.bbox.shape[1] + 10
        k -= trace.bbox.col0
        p.show_step(k)
        assert (trace.step(k).row, trace.step(k).col) == (4, 10)
        assert "centre outside: rejected by test 1" in p.caption_text
        assert p.caption_text.endswith("its 4 samples: 1 covered, the pixel is shaded (MSAA)")
        assert not trace.rejected_at(k)[4, 10] and "centre covered" in keyed(p.view)
        for step in trace:  # every pixel step's count is the recorded samples'
            if step.kind == "pixel":
                n = int(msaa.sample_coverage[step.row, step.col].sum())
                assert f"its 4 samples: {n or 'none'} covered" in step.caption, step.caption
    finally:
        p.close()


def test_editor_without_comparison_shows_no_w_sliders_and_keeps_v2_label_inside():
    """Review r93 02-6/9/9b: in lesson 02 (``comparison=False``) three w sliders changed
    nothing on show and the header spoke of "the upper figure"; "v2" at x = 14.5 of 16
    crossed the right spine; in span mode the two parts lay under the covered pixels."""
    from ipywidgets import FloatLogSlider

    from teachraster.widgets import TriangleEditor

    tri = tr.Triangle([[2.25, 1.75], [14.5, 6.25], [5.75, 14.5]])  # lesson 02's
    e = TriangleEditor(tri, 16, 16, method="halfplane", probe=[7.5, 7.5], comparison=False,
                       backend="image")  # fmt: skip
    try:
        sliders = [w for col in e.widget.children[1].children for w in col.children]
        assert not any(isinstance(w, FloatLogSlider) for w in sliders) and len(e.w) == 3
        title = e.widget.children[0].value
        assert "upper figure" not in title and "Drag a vertex in the figure" in title
        e.fig.canvas.draw()
        renderer = e.fig.canvas.get_renderer()
        right = e.view.ax.get_window_extent(renderer).x1
        assert e.view.triangle.labels[1].get_window_extent(renderer).x1 < right
        e.method.value = "span"
        ax_z = e.view.coverage.image.get_zorder()
        assert e.view.split.flat_top.get_zorder() > ax_z and e.view.split.flat_top.get_hatch()
    finally:
        e.close()


def test_divide_cost_attribute_slider_moves_where_n2_leaves_the_front():
    """Review r152 06-9: the explorer showed only u and v (k = 2), where N = 2 leaves the front
    only for a divide of at most 3 cycles; the lesson's conclusion (GPUs never subdivide:
    16 or more attributes share the one reciprocal) happened off the chart. An attribute
    slider re-prices every variant for k attributes, and the headline says up to which divide
    N = 2 is no cheaper than the exact divide: 2k - 1 cycles in the lesson's model."""
    from teachraster.study import operation_counts as ops
    from teachraster.widgets.divide_cost import ATTRIBUTE_COUNTS, DivideCostExplorer

    errors = {"affine": 209.5, "perspective": 1e-13, "subdivided N=2": 5.76,
              "subdivided N=4": 14.6, "subdivided N=16": 51.0}  # fmt: skip
    rows = ops.with_counts([{"group": "interpolation", "variant": v, "error": e,
                             "mean_abs_texels": e / 100} for v, e in errors.items()])  # fmt: skip
    ex = DivideCostExplorer(rows, backend="image")
    try:
        assert ex.attributes.value == 2 and {1, 2, 16, 32} <= set(ATTRIBUTE_COUNTS)
        sliders = ex.widget.children[1].children[1]  # the controls' second row: the sliders
        assert ex.attributes in sliders.children and ex.divide in sliders.children
        assert "up to 3 cycles" in ex.info.value  # d + 7 against 2 + (d + 13)/2 (Pentium)
        ex.divide.value = 4.0
        assert "subdivided N=2" in ex.front
        xlim2 = ex.ax.get_xlim()
        ex.attributes.value = 16  # q_price's 16 attributes, at the Pentium's multiply
        ex.divide.value = 12.0
        assert "<b>16 attributes" in ex.info.value and "up to 31 cycles" in ex.info.value
        cost = {p: ex.art.points[p].get_xdata()[0] for p in ex.art.points}
        assert cost["perspective"] == 61.0 and cost["subdivided N=2"] == 70.5  # d + 3k + 1
        assert ex.front == ["affine", "subdivided N=16", "subdivided N=4", "perspective"]
        ex.divide.value = 30.0
        assert "subdivided N=2" not in ex.front
        ex.divide.value = 40.0  # past 2k - 1: N = 2 cheaper again, and more accurate than N=4
        assert "subdivided N=2" in ex.front
        lo, hi = ex.ax.get_xlim()  # a new axis for the dearer variants, every point inside it
        assert hi > xlim2[1] and lo < min(cost.values()) and max(cost.values()) < hi
        ex.attributes.value = 2
        assert ex.ax.get_xlim() != xlim2  # r252 FIG1: d = 40 reaches past d = 4's stretch
        ex.divide.value = 4.0
        assert ex.ax.get_xlim() == xlim2 and "up to 3 cycles" in ex.info.value
        # r228 C1: at the GPU's prices (q_price's), 16 attributes: the lesson's order; r238
        # S3: a current GPU's, its reciprocal at an eighth of the multiply-add rate
        ex.attributes.value = 16
        ex.prices.value = "GPU (Ampere GA10x, Ada, Hopper)"
        # r252 F1: the reciprocal on its own unit: max(d, 2k + 2) and N = 2's k + (4k + 2)/2
        assert ex.divide.value == 8.0 and "up to 49 cycles" in ex.info.value
        cost = {p: ex.art.points[p].get_xdata()[0] for p in ex.art.points}
        assert cost["perspective"] == 34.0 and cost["subdivided N=2"] == 49.0
        assert ex.front == ["affine", "subdivided N=16", "subdivided N=4", "perspective"]
        ex.prices.value = "Pentium (P5)"
        assert ex.divide.value == 17.0 and "(a multiply 2)" in ex.info.value
    finally:
        ex.close()
    with pytest.raises(ValueError, match="attributes"):
        DivideCostExplorer(rows, attributes=5, backend="image")
