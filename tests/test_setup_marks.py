"""What a fill's set-up steps find is drawn, read from the trace (review r229 01-W1, 01-FIG1).

Lesson 01's player showed its set-up steps 0-3 as one picture (the stage PNGs of steps 1, 2
and 3 byte-identical): only the captions changed. Now the winding step draws an arrow turning
the way v1 -> v2 -> v3 run, the rows step the raster lines to visit (the bottom vertex's
dotted: traced, not visited), the sort and split steps the roles; the key names what each
step draws (the split's step its two tinted parts, the last step no raster line), and the
long edge's arrowhead no longer sits on point 4.
"""

from __future__ import annotations

import hashlib

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.core.trace import ROLES  # noqa: E402
from teachraster.plotting import FillView, use_style  # noqa: E402
from teachraster.plotting.frames import frame_rgba  # noqa: E402
from teachraster.plotting.views import drawn_edges  # noqa: E402

#: Lesson 01's triangle, listed counter-clockwise on screen (review r229 01-S3), and the same
#: triangle the other way round.
CCW = [[8.5, 17.5], [18.5, 9.5], [4.5, 1.5]]
CW = [[8.5, 17.5], [4.5, 1.5], [18.5, 9.5]]


def keyed(view) -> list[str]:
    return [t.get_text() for t in view.legend.texts if t.get_visible()]


@pytest.fixture
def player():
    """The player's view of lesson 01's triangle (drawn by blitting, as the player does)."""
    from teachraster.widgets import FillPlayer

    with plt.style.context("default"):
        use_style("classroom")
        p = FillPlayer(tr.Triangle(CCW), 20, 20, method="span", backend="image")
        yield p
        p.close()
        plt.close("all")


def picture(view, k: int) -> np.ndarray:
    view.show_step(k, draw=False)
    view.redraw()
    return frame_rgba(view.fig)


def test_each_set_up_step_draws_a_picture_of_its_own(player):
    """r229 01-W1: steps 1 (winding), 2 (rows) and 3 (sort) were byte-identical frames."""
    view = player.view
    digests = [hashlib.md5(picture(view, k).tobytes()).hexdigest() for k in range(6)]
    assert len(set(digests)) == 6, digests


def test_the_set_up_marks_are_read_from_the_trace(player):
    view, trace = player.view, player.view.trace
    marks, span = view.setup_marks, trace.span
    view.show_step(1, draw=False)  # winding: the arrow and the trace's word for it
    assert marks.arc.get_visible() and marks.head.get_visible()
    assert trace.turn == "counter-clockwise" and marks.turn_label.get_text().replace(
        "-\n", "-"
    ).endswith(trace.turn)
    # the arc turns the way the signed area says (y down: negative is counter-clockwise)
    x, y = marks.arc.get_data()
    rx, ry = np.asarray(x) - np.mean(x), np.asarray(y) - np.mean(y)
    turning = rx[:-1] * np.diff(ry) - ry[:-1] * np.diff(rx)  # z of (r x dr)
    assert (np.sign(turning) == np.sign(trace.signed_area)).all()
    assert not marks.band.get_visible() and not any(r.get_visible() for r in marks.roles)
    assert "v1→v2→v3: its winding" in keyed(view)
    view.show_step(2, draw=False)  # rows: a band over span.rows, a line along each centre
    assert marks.band.get_visible() and not marks.arc.get_visible()
    assert marks.band.get_y() == span.rows[0] and marks.band.get_height() == len(span.rows)
    lines = marks.lines.get_segments()
    assert [seg[0][1] for seg in lines] == list(span.rows + 0.5)
    dotted = [style[1] is not None for style in marks.lines.get_linestyles()]
    assert dotted == list(~trace.visited) and dotted[-1] and not any(dotted[:-1])
    assert "raster lines to step through" in keyed(view)
    for k in (3, 4):  # sort, split: the roles at the sorted vertices, in the trace's order
        view.show_step(k, draw=False)
        assert [r.get_text() for r in marks.roles] == list(ROLES)
        assert [tuple(r.xy) for r in marks.roles] == [tuple(p) for p in span.sorted_xy]
        assert all(r.get_visible() for r in marks.roles) and not marks.band.get_visible()
    view.show_step(trace.first_work_step, draw=False)  # the row steps: none of them
    assert not any(a.get_visible() for a in marks.artists)


def test_the_key_names_what_the_step_draws(player):
    """r229 01-FIG1: the split's step tinted two parts its key did not name; the last step
    keyed a raster line, a span and its centres it does not draw; the split's line was keyed
    "split y = v_mid", x and y mixed with u and v."""
    view = player.view
    view.show_step(view.trace.split_step, draw=False)
    assert {"flat-bottom part", "flat-top part", "split line, point 4"} <= set(keyed(view))
    view.show_step(-1, draw=False)
    last = keyed(view)
    for drawn_not in ("raster line, its pixels", "span x_left .. x_right", "its centre covered",
                      "its centre not"):  # fmt: skip
        assert drawn_not not in last
    view.show_step(view.trace.first_work_step + 4, draw=False)
    assert "raster line, its pixels" in keyed(view)
    for k in range(len(view.trace)):
        view.show_step(k, draw=False)
        assert not any("y = v_mid" in t for t in keyed(view)), k


def test_the_long_edges_arrow_is_off_point_4(player):
    """r229 01-FIG1: the long edge's arrowhead sat on point 4 (the middle vertex is halfway
    down, so point 4 is the edge's midpoint) and on its "4"."""
    view, span = player.view, player.view.trace.span
    point_4 = np.array([span.u4, span.sorted_xy[1, 1]])
    xy = view.trace.snapped
    long_edge = {int(span.order[0]), int(span.order[2])}
    edges = drawn_edges(view.trace)
    k = next(i for i, (a, b) in enumerate(edges) if {int(a), int(b)} == long_edge)
    arrow = np.array(view.triangle.arrows[k]._posA_posB)  # tail, head (data units)
    assert np.hypot(*(arrow - point_4).T).min() > 2.5
    # still on the edge, pointing along it
    a, b = xy[edges[k]]
    for p in arrow:
        assert abs((b - a)[0] * (p - a)[1] - (b - a)[1] * (p - a)[0]) < 1e-9
    assert np.dot(arrow[1] - arrow[0], b - a) > 0


@pytest.mark.parametrize("xy", [CCW, CW], ids=["ccw", "cw"])
@pytest.mark.parametrize("method", ["span", "halfplane", "tiled"])
def test_set_up_steps_blit_as_a_full_draw(xy, method):
    """The marks are moving artists: a blitted set-up step equals a full draw."""
    with plt.style.context("default"):
        use_style("classroom")
        fill = tr.rasterize(tr.Triangle(xy), 20, 20, method=method, trace=True)
        view = FillView(fill, step=0)
        try:
            for k in range(fill.trace.first_work_step + 1):
                view.show_step(k, draw=False)
                view.redraw()
                fast = np.asarray(view.fig.canvas.buffer_rgba()).astype(int)
                view.fig.canvas.draw()
                full = np.asarray(view.fig.canvas.buffer_rgba()).astype(int)
                assert np.abs(fast - full).max() <= 8, (method, k)
            view.show_step(1, draw=False)  # every method draws the winding
            assert view.setup_marks.arc.get_visible()
            assert view.setup_marks.band.get_visible() is False
        finally:
            plt.close(view.fig)


def test_a_zero_area_triangle_has_no_winding_arrow():
    fill = tr.rasterize(tr.Triangle([[1.5, 6.5], [7.5, 6.5], [14.5, 6.5]]), 16, 12,
                        method="span", trace=True)  # fmt: skip
    view = FillView(fill, step=1)
    try:
        assert fill.trace.turn is None and not view.setup_marks.arc.get_visible()
        assert not any("winding" in t for t in keyed(view))
    finally:
        plt.close(view.fig)


def test_the_snap_step_tags_each_vertex_with_its_snapped_position(player):
    """r239 01-W1: the player's opening step, the snap, drew the bare triangle and keyed
    nothing (the key's column blank): each vertex now carries the caption's position, and the
    key says how far the snap moved them (none: lesson 01's vertices lie on centres)."""
    view, trace = player.view, player.view.trace
    marks = view.setup_marks
    view.show_step(0, draw=False)
    assert view.trace.step(0).kind == "snap"
    tags = [t.get_text() for t in marks.coords]
    assert tags == ["(8.5, 17.5)", "(18.5, 9.5)", "(4.5, 1.5)"]
    assert all(f"{tag}" in trace.caption(0) for tag in tags)
    assert all(t.get_visible() for t in marks.coords)
    assert [tuple(t.xy) for t in marks.coords] == [tuple(p) for p in trace.snapped]
    assert keyed(view) == ["vertex (its position", "on the 1/256 px grid):", "the snap moved none"]
    for k in range(1, len(trace)):
        view.show_step(k, draw=False)
        assert not any(t.get_visible() for t in marks.coords), k


def test_the_snap_step_keys_how_far_a_vertex_moved():
    with plt.style.context("default"):
        use_style("classroom")
        moved = [[8.5, 17.5], [18.3, 9.7], [4.5, 1.5]]
        fill = tr.rasterize(tr.Triangle(moved), 20, 20, method="span", trace=True)
        view = FillView(fill, step=0)
        try:
            far = np.hypot(*(np.asarray(moved) - fill.trace.snapped).T).max()
            assert 0 < far < 2**-8 and keyed(view)[-1] == f"moved by ≤ {far:.2g} px"
            assert view.setup_marks.coords[1].get_text() == "({:g}, {:g})".format(
                *fill.trace.snapped[1]
            )
            # every tag wholly inside the Axes (r239 01-W1: "middle" crossed the frame)
            view.fig.canvas.draw()
            box = view.ax.get_window_extent()
            for k in (0, 3):
                view.show_step(k, draw=False)
                view.fig.canvas.draw()
                for tag in view.setup_marks.coords if k == 0 else view.setup_marks.roles:
                    # the positions are haloed, not boxed, in a view (review r291 02-3)
                    inner = (tag.get_bbox_patch() or tag).get_window_extent()
                    assert box.x0 - 1 <= inner.x0 and inner.x1 <= box.x1 + 1, (k, tag.get_text())
        finally:
            plt.close(view.fig)


@pytest.mark.parametrize("xy", [CCW, CW], ids=["ccw", "cw"])
@pytest.mark.parametrize("method", ["span", "halfplane"])
def test_the_edges_arrows_show_the_walk_once_the_winding_has_chosen_it(xy, method):
    """r239 01-C1: at the winding step the arc, labelled v1→v2→v3 counter-clockwise, stood
    over arrowheads turning the other way (the package walks a counter-clockwise triangle
    v1→v3→v2). Half-planes: the arrowheads, read from trace.edges, show from the step after
    the winding on, keyed with the walk at the set-up steps. r344 01-C1: span tables walk
    nothing; their arrowheads run down every edge, top to bottom, from the sort on."""
    with plt.style.context("default"):
        use_style("classroom")
        fill = tr.rasterize(tr.Triangle(xy), 20, 20, method=method, trace=True)
        view = FillView(fill, step=0)
        try:
            trace = fill.trace
            walk = "→".join(f"v{a + 1}" for a, _ in trace.edges)
            assert walk == ("v1→v3→v2" if xy is CCW else "v1→v2→v3")
            span = method == "span"
            first = trace.sort_step if span else 2
            entry = "each edge, top to bottom" if span else f"edges walked {walk}"
            assert ("walked" in trace.caption(1)) == (not span and xy is CCW)
            for k in range(len(trace)):
                view.show_step(k, draw=False)
                shown = [a.get_visible() for a in view.triangle.arrows]
                assert shown == [k >= first] * 3, k
                setup = k < trace.first_work_step
                assert (entry in keyed(view)) == (setup and k >= first), k
            # each arrow points along its edge: the trace's walk, or down (v grows) for spans
            xy_s = trace.snapped
            edges = drawn_edges(trace)
            assert np.array_equal(edges, trace.edges) != span
            for arrow, (a, b) in zip(view.triangle.arrows, edges):
                tail, head = np.array(arrow._posA_posB)
                assert np.dot(head - tail, xy_s[b] - xy_s[a]) > 0
                if span:
                    assert head[1] > tail[1]
        finally:
            plt.close(view.fig)


def test_the_player_header_does_not_speak_of_gpus():
    """r239 01-S7: "A GPU tests a block of pixels at once." headed a span-table walk."""
    from teachraster.widgets import FillPlayer

    with plt.style.context("default"):
        p = FillPlayer(tr.Triangle(CCW), 20, 20, method="span", backend="image")
        try:
            header = p.widget.children[0].value
            assert "GPU" not in header and "serial reference loop" in header
        finally:
            p.close()
            plt.close("all")


@pytest.mark.parametrize("v2", [(14.5, 6.25), (1.0, 8.0)], ids=["clockwise", "flipped"])
def test_the_half_plane_labels_stand_between_the_centre_rows(v2):
    """Review r291 02-3: the edge names' boxes and the snapped positions covered pixel-centre
    dots in the player and the editor. They are haloed and placed on the grid's row
    boundaries, clear of every centre. Review r302 02-FIG1: "E12" still touched row 3's dots
    and after the flip "E21", "E13" sat by them: the letters with their halo keep 2 px from
    every dot."""
    from teachraster.plotting.label_places import boxes_around, overlap_share

    xy = [[2.25, 1.75], v2, [5.75, 14.5]]  # lesson 02's triangle, then v2 across v3 -> v1
    with plt.style.context("default"):
        use_style("classroom")
        fill = tr.rasterize(tr.Triangle(xy), 16, 16, method="halfplane", trace=True)
        view = FillView(fill, step=0)
        try:
            view.fig.canvas.draw()
            scale = view.fig.dpi / 72.0
            u, v = np.meshgrid(np.arange(16) + 0.5, np.arange(16) + 0.5)
            reach = (view.centres.inside.get_markersize() / 2 + view.triangle.edge_halo / 2) * scale
            dots = boxes_around(view.ax.transData.transform(np.column_stack([u.ravel(), v.ravel()])),
                                (reach + 2.0, reach + 2.0))  # fmt: skip
            tags = [*view.triangle.edge_labels, *view.setup_marks.coords]
            assert all(t.get_bbox_patch() is None for t in tags) and view.triangle.edge_halo > 0
            for tag in tags:
                e = tag.get_window_extent()
                share = overlap_share(np.array([[e.x0, e.y0, e.x1, e.y1]]), dots)
                assert share[0] == 0, tag.get_text()
        finally:
            plt.close(view.fig)


def test_the_editors_point_4_label_is_clear_of_the_triangle():
    """r296 FIG1 (lesson 00's editor, v3 dragged above the edge v1 -> v2 to (7.5, 0.5)): the
    label "point 4 / u4 = 8.82" hung below the split line over the covered pixels and the long
    edge; it goes where its box is clear of the triangle (its number alone, "4", where the
    two lines do not fit; the editor's line gives u4)."""
    from teachraster.plotting.plots import _box_clear
    from teachraster.widgets import TriangleEditor

    with plt.style.context("default"):
        use_style("classroom")
        tri = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]], w=[1.0, 2.0, 4.0])
        editor = TriangleEditor(tri, 16, 16)
        try:
            editor.set_vertex(2, 7.5, 0.5)
            label, span = editor.view.split.label, editor.view.trace.span
            size = label.get_fontsize()
            box = (
                (size * 0.9, size * 1.15) if label.get_text() == "4" else (size * 6.65, size * 3.2)
            )
            align = (label.get_horizontalalignment(), label.get_verticalalignment())
            assert _box_clear(label.axes, span.sorted_xy, label.xy, label.get_position(), align,
                              box)  # fmt: skip
            assert "split at u4 = 8.82" in editor.info.value
        finally:
            plt.close(editor.fig)


def _boxes_overlap(a, b) -> bool:
    return a.x0 < b.x1 and b.x0 < a.x1 and a.y0 < b.y1 and b.y0 < a.y1


@pytest.mark.parametrize(
    "size", [(9.12, 6.48), (7.2, 5.8), (9.0, 7.0)]
)  # the player's and two others
def test_no_tag_covers_a_vertex_label_or_the_middle_vertexs_lines(player, size):
    """r452 01-FIG1: the snap step's "(8.5, 17.5)" lay half under "v1" in the browser (the
    nearest place crossing no edge overlapped the label's own box); FIG2: "middle" lay over
    the edge into v2 (and, moved off it, over the split line the split step draws)."""
    view, trace = player.view, player.view.trace
    marks, labels = view.setup_marks, view.triangle.labels
    view.fig.set_size_inches(*size)
    split = next(k for k in range(len(trace)) if trace.step(k).kind == "split")
    for k, tags in ((0, marks.coords), (split, marks.roles)):
        view.show_step(k, draw=False)
        marks.update(trace, labels)
        view.fig.canvas.draw()
        renderer = view.fig.canvas.get_renderer()
        for tag in tags:
            box = tag.get_window_extent(renderer)
            for label in labels:
                assert not _boxes_overlap(box, label.get_window_extent(renderer)), (
                    size, k, tag.get_text(), label.get_text())  # fmt: skip
    box = marks.roles[ROLES.index("middle")].get_window_extent(renderer)
    xy = np.asarray(trace.snapped, dtype=np.float64)
    v_mid = float(trace.span.sorted_xy[1, 1])
    lines = [(xy[k], xy[(k + 1) % 3]) for k in range(3)] + [((0, v_mid), (20, v_mid))]
    for a, b in lines:
        pts = view.fig.axes[0].transData.transform(np.linspace(a, b, 400))
        inside = (pts[:, 0] > box.x0) & (pts[:, 0] < box.x1) & (pts[:, 1] > box.y0) & (
            pts[:, 1] < box.y1)  # fmt: skip
        assert not inside.any(), (size, a, b)
