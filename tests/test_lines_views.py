"""Line and blending plots and widgets: they draw what the trace says and update in place."""

from __future__ import annotations

import re

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.plotting.lines import LineView, plot_diamonds, plot_rgba  # noqa: E402


@pytest.fixture
def ax():
    fig, ax = plt.subplots()
    yield ax
    plt.close(fig)


def test_plot_diamonds_draws_the_traces_candidates(ax):
    fill = tr.rasterize_line((0.5, 0.5), (4.5, 2.5), 6, 4, trace=True)
    art = plot_diamonds(ax, fill)
    assert len(art.lit.get_paths()) == int(fill.coverage.sum())
    assert len(art.ends.get_paths()) == 1  # p1's own diamond
    assert art.segment in ax.lines


def test_plot_diamonds_can_leave_out_the_walks_candidates(ax):
    # review r51 12a-2: only the diamonds that lost a tie, not the simulator's window
    fill = tr.rasterize_line((0.5, 0.5), (8.5, 4.5), 10, 6, trace=True)
    s = fill.trace.steps
    art = plot_diamonds(ax, fill, tested="ties")
    assert len(art.missed.get_paths()) == int((s.tie & (s.state == 0)).sum()) == 4
    assert len(plot_diamonds(ax, fill, tested="all").missed.get_paths()) == int(
        (s.state == 0).sum()
    )
    assert not plot_diamonds(ax, fill, tested="none").missed.get_paths()
    with pytest.raises(ValueError, match="tested"):
        plot_diamonds(ax, fill, tested="some")


def test_plot_diamonds_needs_a_trace(ax):
    with pytest.raises(TypeError, match="trace=True"):
        plot_diamonds(ax, tr.rasterize_line((0.5, 0.5), (4.5, 2.5), 6, 4))


def test_line_view_updates_in_place(ax):
    fill = tr.rasterize_line((0.5, 0.5), (9.5, 4.5), 11, 6, rule="bresenham", trace=True)
    view = LineView.create(ax, fill, step=0)
    before = list(ax.get_children())
    for k in range(len(fill.trace)):
        view.show_step(k)
        # the caption as the trace words it, wrapped at the axes' width (review r101 12a-C)
        assert view.caption.get_text().split() == fill.trace.caption(k).split()
    assert list(ax.get_children()) == before
    assert view.current.get_visible() and view.current.get_x() == fill.trace.step(-1).col


def test_line_view_draws_the_diamonds_its_captions_speak_of(ax):
    """Diamond rule: step k shows the diamonds of its own column the line comes near thick,
    and every such diamond the steps so far tested, lit or ended in; at the end they are
    plot_diamonds' own with tested="near" (review r262 FIG1: not the walk's whole window).
    Other rules (and the set-up steps) draw none."""
    fill = tr.rasterize_line((0.5, 0.5), (8.5, 4.5), 10, 6, trace=True)
    s = fill.trace.steps
    view = LineView.create(ax, fill, step=0)
    assert all(len(c.get_paths()) == 0 for c in view.diamonds.values())
    view.show_step(3)  # column 1: the tie
    now = {tuple(p.vertices[0]) for p in view.diamonds["now"].get_paths()}
    assert (
        now
        == {(1.5, r + 0.0) for r in s.rows[(s.step == 1) & fill.trace.near()]}
        == {(1.5, 0.0), (1.5, 1.0)}
        and "column 1" in view.caption.get_text()
    )
    lit = view.diamonds["lit"].get_paths()
    assert len(lit) == int(fill.trace.coverage_at(3).sum()) == 2
    view.show_step(-1)
    whole = plot_diamonds(ax, fill, tested="near")
    for name, drawn in (("lit", whole.lit), ("ends", whole.ends), ("tested", whole.missed)):
        assert len(view.diamonds[name].get_paths()) == len(drawn.get_paths()), name
    view.trace = tr.rasterize_line((0.5, 0.5), (8.5, 4.5), 10, 6, rule="dda", trace=True).trace
    view.show_step(-1)
    assert all(len(c.get_paths()) == 0 for c in view.diamonds.values())


def test_line_view_draws_bresenhams_midpoint_and_the_gap_d_measures(ax):
    """Review r43 12a-3: under Bresenham each column's picture marks the midpoint between the
    next column's candidates and the line's crossing there; their gap times 2·dx is the
    caption's D (the lesson's line: dx = 12, D = -2, 8, -6, 4, ...; y-major lines running up
    too). Other rules and the set-up steps mark nothing."""
    for p0, p1, size in (((0.5, 0.5), (12.5, 5.5), (14, 7)), ((3.5, 9.5), (1.5, 0.5), (6, 12))):
        fill = tr.rasterize_line(p0, p1, *size, rule="bresenham", trace=True)
        s, trace = fill.trace.steps, fill.trace
        axis = 0 if s.x_major else 1
        d_major = abs(np.floor(p1[axis]) - np.floor(p0[axis]))
        sign_minor = 1 if np.floor(p1[1 - axis]) >= np.floor(p0[1 - axis]) else -1
        view = LineView.create(ax, fill, step=0)
        gap, mid, cross = view.midpoint
        assert np.isnan(mid.get_xdata()).all()  # set-up: no test yet
        for work in range(len(s.major)):
            view.show_step(2 + work)
            (mx, my), (lx, ly) = trace.midpoint(2 + work)
            assert (mid.get_xdata()[0], cross.get_ydata()[0]) == (mx, ly)
            m, line = (my, ly) if s.x_major else (mx, lx)
            assert abs(m - round(m)) < 1e-9  # on the border between the two candidates
            assert np.isclose(2 * d_major * sign_minor * (line - m), s.value[work])
            assert f"D = {s.value[work]:g}" in view.caption.get_text()
    assert trace.midpoint(1) is None
    view.trace = tr.rasterize_line((0.5, 0.5), (8.5, 4.5), 10, 6, trace=True).trace
    view.show_step(-1)
    assert np.isnan(mid.get_xdata()).all() and np.isnan(gap.get_xdata()).all()


def test_line_player_caption_stays_within_its_axes():
    """Review r101 12a-C: the diamond step's caption ran past the axes to the edge of the
    output (matplotlib's wrap=True wraps at the figure's edge); it wraps at the axes' width."""
    from teachraster.widgets import LinePlayer

    player = LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, rule="diamond", step=14, backend="image")
    player.fig.canvas.draw()
    caption = player.view.caption
    assert "ends inside its diamond" in caption.get_text().replace("\n", " ")
    assert "\n" in caption.get_text()
    renderer = player.fig.canvas.get_renderer()
    text_box = caption.get_window_extent(renderer)
    axes_box = player.view.caption.axes.get_window_extent(renderer)
    assert text_box.x1 <= axes_box.x1 + 1
    player.close()


def test_plot_rgba_shows_the_rgb_written_or_alpha_over_a_checkerboard(ax):
    color = np.zeros((4, 5, 4))
    color[1, 2] = [0.25, 0, 0, 0.5]
    # review r31 12b-3: by default the RGB written, opaque, as a window displays it
    art = plot_rgba(ax, color, premultiplied=True)
    np.testing.assert_allclose(art.image.get_array()[1, 2], [0.25, 0, 0, 1])
    assert not art.checker.get_visible()
    # view="alpha": the colour (un-premultiplied) by its stored alpha, over the checkerboard
    art = plot_rgba(ax, color, premultiplied=True, view="alpha")
    np.testing.assert_allclose(art.image.get_array()[1, 2], [0.5, 0, 0, 0.5])
    assert art.checker.get_visible()
    with pytest.raises(ValueError, match="view"):
        plot_rgba(ax, color, view="checker")
    with pytest.raises(ValueError, match="color"):
        plot_rgba(ax, color[..., :3])


def test_blending_explorer_controls_keep_their_text():
    """At 1024 x 768 the buttons' column shrank inside a fixed row and cut "sort back to
    front" to "sort back to fron" (review r7): each control keeps its own width (flex
    "0 0 auto", width auto) and the row wraps whole controls instead (control_row)."""
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24))
    try:
        row = ex.widget.children[2]  # children[1]: the blend state's row (review r263 M3)
        assert (
            row.layout.flex_flow == "row wrap" and ex.widget.children[1].children[1] is ex.opacity
        )
        for column in row.children[1:]:
            assert column.layout.flex == "0 0 auto"
        controls = (ex.earlier, ex.later, ex.sort, ex.srgb, ex.decode, ex.white)
        for control in controls:
            assert control.layout.width == "auto" and control.layout.flex == "0 0 auto"
        assert not ex.srgb.indent and not ex.white.indent
    finally:
        ex.close()


def test_blending_explorer_clears_to_black_or_white():
    """The reader asked for the white of the lesson's figures (r43 item 9): the "clear to
    opaque white" box clears both buffers to (1, 1, 1, 1); uncovered pixels show it, stored
    alpha under "over" then stays below 1 where a triangle blended, and the order still
    matters."""
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24))
    try:
        bare = np.isnan(ex.color).any(axis=2) | (ex.color[..., 3] == 0)
        assert bare.any() and np.allclose(ex.color[bare], 0)
        black_differ = ex.differ
        ex.white.value = True
        assert np.allclose(ex.color[bare], 1) and np.allclose(ex.sorted_color[bare], 1)
        assert "cleared to opaque white" in ex.info.value
        assert ex.differ > 0 and ex.color[~bare, 3].min() < 1
        ex.mode.value = "premultiplied"  # over white, the two encodings display alike
        premultiplied_rgb = ex.color[..., :3].copy()
        ex.mode.value = "over"
        assert np.allclose(ex.color[..., :3], premultiplied_rgb)
        ex.white.value = False
        assert ex.differ == black_differ
        assert "cleared to transparent black" in ex.info.value  # named either way (r71)
    finally:
        ex.close()


def test_blending_explorer_order_and_toggles():
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24))
    try:
        # the readout names both orders it compares (lesson 12b compares blue, red, yellow with yellow, red, blue)
        back = " → ".join(str(t) for t in ex.depth_order)
        assert ex.order != ex.depth_order and f"back to front ({back})" in ex.info.value
        assert ex.depth_order == [2, 0, 1]  # the default scene: yellow farthest, red nearest
        assert f"drawn {' → '.join(map(str, ex.order))}:" in ex.info.value
        ex.sort.click()
        assert ex.differ == 0
        ex.select.value = 0
        ex.later.click()
        assert ex.differ > 0
        straight = ex.color.copy()
        ex.mode.value = "premultiplied"
        # premultiplied "over" into a transparent buffer gives Porter-Duff's alpha
        # 1 - Π(1 - a) (three layers of 0.6 where all overlap); straight alpha squares it
        assert np.isclose(ex.color[..., 3].max(), 1 - 0.4**3)
        assert straight[..., 3].max() < ex.color[..., 3].max()
        moved = ex.color.copy()
        ex.srgb.value = True
        assert not np.allclose(ex.color, moved)
        ex.mode.value = "over"
        # an 8-bit sRGB target: whole codes after every layer (ex.color holds linear values)
        codes = tr.linear_to_srgb(np.clip(ex.color[..., :3], 0, 1)) * 255
        assert np.allclose(codes, np.round(codes), atol=1e-6)
        # review r31 12b-3: the panels show the RGB written, opaque; "stored alpha" the checker
        shown = ex.artists.image.get_array()
        assert np.all(shown[..., 3] == 1) and not ex.artists.checker.get_visible()
        ex.alpha.value = True
        assert ex.artists.checker.get_visible() and ex.artists.image.get_array()[..., 3].min() < 1
    finally:
        ex.close()


def test_line_player_switches_rule():
    from teachraster.widgets.line_player import LinePlayer

    player = LinePlayer((0.5, 0.5), (20.5, 3.5), 22, 5, backend="image")
    try:
        player.rule.value = "dda"
        assert "float32" in player.view.caption.get_text() or player.slider.value < 2
        player.slider.value = 4
        assert "float32 sum" in player.view.caption.get_text()
        # the line above the figure names the step by its column, the caption is not repeated
        assert player.caption.value == "step 4 (0 to 21): column 2 (steps 0 and 1 set the line up)"
    finally:
        player.close()


def test_line_player_gets_a_new_slider_when_the_rule_changes_the_step_count():
    """Review r27 (lesson 12, cell 12): from Bresenham (0 to 13) to the diamond rule (0 to 14),
    the page's slider took the new range for the pointer but its End key stopped at 13 (the
    page's noUiSlider keeps the range it was created with for Home and End). The player now
    shows a new slider with the new range, linked to Play and to the picture."""
    from teachraster.widgets.line_player import LinePlayer

    player = LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, rule="bresenham", step=2, backend="image")
    try:
        first = player.slider
        assert first.max == 13 and first in player.controls.children
        player.rule.value = "diamond"
        assert player.slider is not first and player.slider.max == player.play.max == 14
        assert player.slider in player.controls.children and first not in player.controls.children
        assert player.slider.value == player.play.value == 2  # the step shown stays
        player.slider.value = 14  # the new slider drives the picture and the caption
        assert player.caption.value.startswith("step 14 (0 to 14): column 12")
        player.rule.value = "bresenham"
        assert player.slider.max == 13 and player.slider.value == 13  # clamped to the new end
        assert player.caption.value.startswith("step 13 (0 to 13)")
    finally:
        player.close()


def test_line_player_keeps_its_column_and_axes_box_across_rules():
    """Review r83 12a-6: the slider kept its step index when the rule changed, so Bresenham's
    last step became the diamond rule's next-to-last, and the axes moved sideways with the
    caption's length. Now the column on show stays (the end stays the end), and the axes box
    is the same for every rule and step (the caption has room of its own)."""
    from teachraster.widgets.line_player import LinePlayer

    player = LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, rule="bresenham", step=7, backend="image")
    try:
        boxes = set()
        for rule in ("diamond", "dda", "bresenham", "diamond"):
            player.rule.value = rule
            assert player.caption.value.split(": ")[1].startswith("column 5 "), rule
            player.fig.canvas.draw()
            boxes.add(tuple(np.round(player.view.image.axes.get_position().bounds, 6)))
        player.slider.value = player.slider.max  # the diamond rule's last step, column 12
        for rule in ("bresenham", "dda", "diamond"):
            player.rule.value = rule
            assert player.slider.value == player.slider.max, rule
            player.fig.canvas.draw()
            boxes.add(tuple(np.round(player.view.image.axes.get_position().bounds, 6)))
        assert len(boxes) == 1, boxes
    finally:
        player.close()


def test_line_player_diamond_walk_stays_on_the_segment_and_names_its_tie():
    """Lesson 12a's player, rule diamond (review r7): the segment (0.5, 0.5) -> (12.5, 5.5)
    ends at x = 12.5, so the walk stops at column 12 (it went on to a column 13 with the
    infinite line's y), and column 6, where the line passes y = 3 exactly (a diamond corner,
    c13's column where Bresenham differs), says that GL's ε decided it."""
    from teachraster.widgets.line_player import LinePlayer

    player = LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, rule="diamond", backend="image")
    try:
        trace = player.trace
        assert trace.caption(1) == "x-major: walk columns 0..12, one step each"
        assert trace.steps.major.tolist() == list(range(13))
        captions = [trace.caption(k) for k in range(2, len(trace))]
        tied = [
            c
            for c in captions
            if "a tie, decided by moving the end points by −(ε, ε²) with y down" in c
        ]
        assert len(tied) == 1 and tied[0].startswith(
            "column 6: at x = 6.5, the column's centre, the line is at y = 3;"
        )
        assert "pixel (row 3, col 6)" in tied[0]
        player.slider.value = len(trace) - 1
        assert player.caption.value.startswith("step 14 (0 to 14): column 12")
    finally:
        player.close()


@pytest.mark.parametrize("seed", range(4))
def test_diamond_walk_visits_only_columns_the_segment_reaches(seed):
    """Every walked column (row) overlaps the segment's extent along the major axis, and
    no column of the segment's extent inside the image is left out."""
    rng = np.random.default_rng(seed)
    for _ in range(200):
        p = rng.integers(-8, 40, (2, 2)) / rng.choice([1, 2, 4, 256])
        steps = tr.rasterize_line(p[0], p[1], 24, 16, trace=True).trace.steps
        if len(steps.major) == 0:
            continue
        axis = 0 if steps.x_major else 1
        lo, hi = sorted(p[:, axis])
        size = 24 if steps.x_major else 16
        reached = [j for j in range(size) if j < hi and j + 1 > lo or j + 1 == lo]
        assert steps.major.tolist() == reached, p.tolist()


def test_line_player_first_picture_keeps_its_labels_inside():
    # the first PNG was drawn before constrained layout settled: "column j" cut off at the top
    import io

    from PIL import Image

    from teachraster.plotting import use_style
    from teachraster.widgets.line_player import LinePlayer

    with use_style("classroom"):
        player = LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, rule="bresenham", backend="image")
    try:
        first = np.asarray(Image.open(io.BytesIO(player.display.widget.value)).convert("L"))
        assert (first[:2] < 128).sum() == 0 and (first[-2:] < 128).sum() == 0  # no cut text
    finally:
        player.close()


def test_blending_explorer_says_its_background_is_transparent_black():
    """Review r34 12b: the explorer draws on black with no word of it in the widget; its caption
    says the buffer is cleared to transparent black, and that is what the panels show."""
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24))
    try:
        assert "cleared to transparent black (0, 0, 0, 0)" in ex.widget.children[0].value
        empty = ex.color[0, 0]  # a corner no triangle covers
        assert np.array_equal(empty, [0, 0, 0, 0])
    finally:
        ex.close()


def test_blending_explorer_srgb_box_is_color_format_srgb8():
    """Review r117 12b-2: the "sRGB framebuffer" box means what render(color_format="srgb8")
    means, colours taken as linear (as GL takes a shader's output); decoding sRGB colours is
    the separate "colours sRGB-encoded" box."""
    import teachraster as tr
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24), white=True)
    try:
        ex.srgb.value = True
        order = ex.order
        attrs = ex.rgba[order]
        frame = tr.render(ex.clip[order], 24, 24, attrs=attrs, blend="over", depth_write=False,
                          clear_color=(1, 1, 1, 1), color_format="srgb8")  # fmt: skip
        assert np.array_equal(ex.color, frame.color)
        assert "(sRGB framebuffer)" in ex.info.value and "decoded" not in ex.info.value
        ex.decode.value = True
        attrs = attrs.copy()
        attrs[..., :3] = tr.srgb_to_linear(attrs[..., :3])
        frame = tr.render(ex.clip[order], 24, 24, attrs=attrs, blend="over", depth_write=False,
                          clear_color=(1, 1, 1, 1), color_format="srgb8")  # fmt: skip
        assert np.array_equal(ex.color, frame.color)
        assert "(colours decoded from sRGB)" in ex.info.value
        assert 'color_format="srgb8"' in ex.widget.children[0].value
    finally:
        ex.close()


def test_blending_explorer_says_when_stored_alpha_is_one_everywhere():
    """Review r187 (widgets): on the white clear, premultiplied colours store alpha 1 in every
    pixel, so the checkerboard of "stored alpha" cannot show; the status line says so, and
    only then (straight alpha on white stores less than 1 under the triangles)."""
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24), white=True)
    try:
        ex.alpha.value = True
        assert ex.color[..., 3].min() < 1 and "nothing shows through" not in ex.info.value
        assert "stored alpha over a checkerboard" in ex.info.value
        ex.mode.value = "premultiplied"
        assert np.allclose(ex.color[..., 3], 1)
        assert "stored alpha over a checkerboard (1 everywhere: nothing shows through)" in (
            ex.info.value
        )
        ex.alpha.value = False
        assert "checkerboard" not in ex.info.value
    finally:
        ex.close()


def test_blending_explorer_blend_state_and_alpha():
    """Review r263 M3: the explorer gains the blend state: a mode (over, premultiplied,
    additive, multiply, its factor pair in the status line) and one alpha for every triangle.
    Additive and multiply differ in any order only by rounding (review r324 C1: the count
    ignored differences below 1e-9 and so showed 0 for multiply, whose float products part by
    their last bits, as lesson 12b §2 prints; it now counts them and says how far); "over"
    depends on the order at every alpha below 1, and the artists are updated in place."""
    from teachraster.widgets.blending import BLEND_CHOICES, BlendingExplorer, compose

    ex = BlendingExplorer(backend="image", size=(24, 24), white=True)
    try:
        assert list(BLEND_CHOICES) == ["over", "premultiplied", "additive", "multiply"]
        assert ex.opacity.value == 0.6 and "alpha 0.60" in ex.info.value
        image = ex.artists.image
        assert ex.differ > 0 and "(SRC_ALPHA, ONE_MINUS_SRC_ALPHA)" in ex.info.value
        for mode in ("additive", "multiply"):
            ex.mode.value = mode
            assert ex.gap.rounding, mode
            ex.select.value = 0
            ex.later.click()
            assert ex.gap.rounding and f"blend {mode!r}" in ex.info.value
        ex.order = [2, 1, 0]  # multiply on white: §2's last bits (the count used to say 0)
        ex.update()
        assert ex.differ > 0 and ex.gap.ulps <= 2
        assert "unit(s) in the last place" in ex.info.value and "float rounding" in ex.info.value
        ex.order = [0, 1, 2]
        ex.srgb.value = True  # the 8-bit target rounds every layer: a code apart
        assert ex.differ > 0 and ex.gap.codes == 1 and "1 code(s): rounding" in ex.info.value
        ex.srgb.value = False
        # the caption says the same, and briefly (review r324 S5: seven lines of it, some 900
        # characters, stood above the controls)
        caption = re.sub("<[^>]+>", "", ex.widget.children[0].value)
        assert "differ only by rounding" in caption and "0 differing" not in caption
        assert len(caption) < 600
        assert "(DST_COLOR, ZERO)" in ex.info.value and "product of the alphas" in ex.info.value
        ex.white.value = True  # additive unticked it
        ex.mode.value = "additive"
        assert "'clear to opaque white' unticked for additive" in ex.info.value
        ex.mode.value = "over"
        for a in (0.2, 0.9):
            ex.opacity.value = a
            assert ex.differ > 0
            expected = compose(ex.clip, ex.rgba, ex.order, alpha=a, size=(24, 24),
                               clear_color=(1, 1, 1, 1))  # fmt: skip
            assert np.array_equal(ex.color, expected)
        assert ex.artists.image is image  # updated in place
    finally:
        ex.close()


def test_blending_explorer_status_line_says_what_each_mode_does_to_alpha():
    """Review r275 C1: the line said "(alpha unused)" for multiply and additive, yet with
    "stored alpha" ticked the alpha slider changed the picture. It now says what each mode does
    to the colour and to the stored alpha, and the stored alpha is what it says: multiply
    stores the product of the alphas, additive their sum (one factor pair serves both)."""
    import teachraster as tr
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24))  # transparent black: a_d starts at 0
    try:
        ex.alpha.value = True
        assert "alpha unused" not in ex.info.value
        assert "stored alpha a_s·a_s + a_d·(1 − a_s)" in ex.info.value  # over
        ex.mode.value = "premultiplied"
        assert "the same RGB as 'over'" in ex.info.value
        assert "stored alpha a_s + a_d·(1 − a_s)" in ex.info.value
        a = 0.05
        ex.opacity.value = a
        ex.mode.value = "additive"
        assert "the stored alpha is the sum of the alphas, a_s + a_d" in ex.info.value
        layers = sum(~np.isnan(tr.render(ex.clip[[k]], 24, 24).depth) for k in range(3))
        assert set(np.unique(layers)) == {0, 1, 2, 3}  # how many triangles cover each pixel
        assert np.allclose(ex.color[..., 3], layers * a)  # the sum of the alphas
        before = ex.color[..., 3].copy()
        ex.opacity.value = 1.0  # the slider changes the stored alpha: 1, 2, 3
        assert np.allclose(ex.color[..., 3], layers) and not np.allclose(before, layers)
        ex.white.value = True  # multiply onto white: a_d starts at 1
        ex.mode.value = "multiply"
        assert "the stored alpha is the product of the alphas, a_s·a_d" in ex.info.value
        ex.opacity.value = a
        assert np.allclose(ex.color[..., 3], a**layers)  # the product of the alphas
        assert "alpha does not enter the colour" in ex.info.value
    finally:
        ex.close()


def test_blending_explorer_additive_sets_the_white_clear_aside():
    """Review r275 W1: "additive" on the default white clear turned both panels plain white.
    Picking it unticks "clear to opaque white" and the status line says so in bold; leaving
    additive ticks it again; a white the student ticks under additive stays, with a warning;
    multiply on black (every product 0) is named too."""
    from teachraster.widgets.blending import BlendingExplorer

    ex = BlendingExplorer(backend="image", size=(24, 24), white=True)
    try:
        ex.mode.value = "additive"
        assert not ex.white.value and np.array_equal(ex.color[0, 0], [0, 0, 0, 0])
        shown = ex.color[..., :3]
        assert ((shown > 0) & (shown < 1)).any()  # something to see: not plain white
        assert "<b>'clear to opaque white' unticked for additive</b>" in ex.info.value
        assert "cleared to transparent black" in ex.info.value
        ex.mode.value = "over"
        assert ex.white.value and "unticked for additive" not in ex.info.value
        ex.mode.value = "additive"
        ex.white.value = True  # the student's choice: kept, and warned
        assert ex.white.value and "untick 'clear to opaque white'" in ex.info.value
        assert (ex.color[..., :3].min(axis=2) >= 1).all()  # every pixel white: why it warns
        ex.white.value = False
        ex.mode.value = "multiply"  # the student unticked it: not restored
        assert not ex.white.value
        assert "onto black every product is 0 and shows black" in ex.info.value
        assert np.allclose(ex.color[..., :3], 0)
    finally:
        ex.close()
