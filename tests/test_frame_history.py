"""Pixel history and overlays (issue 21): exact, in submission order, free without a trace.

The key property: replaying a pixel's history (its "passed" records, in order) gives the
frame's triangle and depth at every sample bit for bit, on random scenes (overlaps, depth
ties, clipping, culling, depth test off, quantised depth) and on every built-in scene, at 1×
and 4× MSAA; the records' counts add up to the "overdraw" and "depth_complexity" overlays;
and recording changes nothing (traced == untraced frames, bit for bit).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from conftest import cases, examples, sample
from hypothesis import given, settings
from hypothesis import strategies as st
from test_plan import random_scene
from test_render import H, W, clip_from_window

import teachraster as tr
from teachraster.pipeline.debugging.frame_history import OUTCOMES
from teachraster.pipeline.debugging.overlays import KINDS
from teachraster.pipeline.scenes import SCENES, get_scene


def assert_identical(a, b, msg=""):
    for name in ("triangle_id", "depth", "attrs"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=f"{msg} {name}")
    if a.samples is not None:
        for name in ("sample_triangle_id", "sample_depth"):
            np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=msg)


def check_every_pixel(frame, msg=""):
    """Replay every pixel's history against the frame and the overlays."""
    height, width = frame.triangle_id.shape
    overdraw = frame.overlay("overdraw")
    complexity = frame.overlay("depth_complexity")
    ids = frame.sample_triangle_id
    depths = frame.sample_depth
    if ids is None:
        ids, depths = frame.triangle_id[..., None], frame.depth[..., None]
    for row in range(height):
        for col in range(width):
            h = frame.history(row, col)
            try:
                _check_pixel(frame, h, row, col, ids, depths, overdraw, complexity)
            except AssertionError as exc:  # the history's table only for a failing pixel
                raise AssertionError(f"{msg} pixel ({row}, {col})\n{h}\n{exc}") from None


def _check_pixel(frame, h, row, col, ids, depths, overdraw, complexity):
    """One pixel of :func:`check_every_pixel` (printing ``h`` for every pixel, passing or
    not, was an eighth of the test's time)."""
    tri, depth = h.replay()
    np.testing.assert_array_equal(tri, ids[row, col])
    np.testing.assert_array_equal(depth, depths[row, col])
    assert set(h.outcomes) <= set(OUTCOMES)
    covered = sum(o in ("hi_z", "failed_depth", "passed") for o in h.outcomes)
    assert covered == overdraw[row, col]
    assert h.outcomes.count("passed") == complexity[row, col]
    orders = [(r.piece, r.sample) for r in h.records]
    assert orders == sorted(orders)  # submission order, then sample
    shown = [r for r in h.records if r.shown]
    assert sorted(r.sample for r in shown) == np.flatnonzero(tri >= 0).tolist()
    if frame.samples is None and shown:
        np.testing.assert_allclose(shown[0].value, frame.attrs[row, col], rtol=0, atol=1e-12)


@pytest.mark.parametrize("samples", [1, 4])
def test_replay_reproduces_random_scenes(rng, samples):
    for index in range(cases(14)):  # every pixel of each; the hypothesis test below explores more
        clip, attrs, kw = random_scene(rng, index)
        frame = tr.render(clip, W, H, attrs=attrs, samples=samples, trace=True, **kw)
        plain = tr.render(clip, W, H, attrs=attrs, samples=samples, **kw)
        msg = f"scene {index} {kw} samples={samples}"
        assert_identical(frame, plain, msg)
        check_every_pixel(frame, msg)


@pytest.mark.parametrize("name", sample(SCENES, keep=2))
@pytest.mark.parametrize("samples", [1, 4])
def test_replay_reproduces_builtin_scenes(name, samples):
    frame = tr.render(get_scene(name), None, 32, 24, samples=samples, trace=True)
    plain = tr.render(get_scene(name), None, 32, 24, samples=samples)
    assert_identical(frame, plain, name)
    check_every_pixel(frame, name)


@settings(max_examples=examples(25))
@given(
    st.lists(st.tuples(st.integers(0, 12), st.integers(0, 10)), min_size=3, max_size=12),
    st.lists(st.sampled_from([0.2, 0.4, 0.4, 0.6]), min_size=4, max_size=4),
    st.sampled_from([1, 4]),
    st.booleans(),
)
def test_replay_on_overlaps_and_ties(points, depths, samples, depth_test):
    """Triangles on integer corners (shared edges, exact ties of depth) replay exactly."""
    n = len(points) // 3
    xy = np.array(points[: 3 * n], dtype=float).reshape(n, 3, 2)
    z = np.array([depths[i % 4] for i in range(n)])[:, None].repeat(3, axis=1)
    clip = clip_from_window(xy, z, width=12, height=10)
    frame = tr.render(clip, 12, 10, samples=samples, depth_test=depth_test, trace=True)
    check_every_pixel(frame)


def test_history_of_a_zero_area_triangle_under_msaa_raises_no_numpy_warning():
    """A collinear triangle (x + y = 10) has infinite depth gradients; the MSAA history read
    its planes at every sample and numpy warned "invalid value encountered in add" (found by
    the hypothesis test above in a fresh-clone CI). Its records say not covered, silently."""
    import warnings

    xy = np.array([[[7.0, 3.0], [8.0, 2.0], [2.0, 8.0]]])
    clip = clip_from_window(xy, np.full((1, 3), 0.4), width=12, height=10)
    frame = tr.render(clip, 12, 10, samples=4, trace=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for row, col in [(2, 7), (5, 5), (7, 2)]:
            h = frame.history(row, col)
            assert all(r.outcome in ("not_covered", "culled") for r in h), str(h)


def test_history_records_say_why():
    # 0: a far triangle, 1: a near one over it, 2: a sliver, 3: culled (clockwise on screen)
    xy = np.array([[[1, 1], [1, 11], [15, 1]], [[2, 2], [2, 10], [14, 2]],
                   [[0, 4.0], [0, 4.1], [16, 5.0]], [[1, 1], [15, 1], [1, 11]]], float)  # fmt: skip
    clip = clip_from_window(xy, np.array([0.8, 0.3, 0.1, 0.05])[:, None], width=16, height=12)
    frame = tr.render(clip, 16, 12, attrs=np.arange(12.0).reshape(4, 3), cull="back",
                      trace=True)  # fmt: skip
    h = frame.history(4, 4)
    assert [r.triangle for r in h] == [0, 1, 2, 3]
    assert h.outcomes == ["passed", "passed", "not_covered", "culled"]
    assert h[0].hidden_by == 1 and not h[0].shown and h[1].shown
    assert h[0].depth_before == np.inf and h[1].depth_before == h[0].depth == 0.8
    assert h[1].depth_after == 0.3
    assert h[2].edge is not None and h[2].outside > 0
    text = str(h)
    assert "hidden by 1" in text and "passed (shown)" in text and "outside E32" in text
    assert "culled" in text and "row 4, col 4" in text
    # with the far triangle drawn last it fails the depth test
    late = tr.render(clip[[1, 0]], 16, 12, trace=True).history(4, 4)
    assert late.outcomes == ["passed", "failed_depth"]
    assert late[1].depth_before == 0.3
    # review r8 (lesson 11): a passed fragment of a scene without attributes says why its
    # value column is empty, and a colour buffer no fragment reached gets no empty header
    assert "(no attributes: the scene has none)" in str(late)
    rgba = np.tile([0.2, 0.4, 0.6, 0.5], (4, 3, 1))
    glass = tr.render(clip, 16, 12, attrs=rgba, blend="over", trace=True)
    assert "RGBA: before -> fragment -> after" in str(glass.history(4, 4))
    lines = str(glass.history(11, 15)).splitlines()  # a corner no triangle reaches
    assert "no fragment reached it here" in lines[-1] and "RGBA" not in lines[-1]


def test_msaa_history_says_how_many_samples_each_triangle_keeps():
    """Review r30/r36 (lesson 11, D5): under 4x MSAA several triangles were each "passed
    (shown)" at one pixel under a header naming one. True per sample, not a bug: every
    sample keeps its own triangle and the resolve averages them. The table now says
    "kept k of 4", k counted against an independent reference: which fan triangle contains
    each sample point, by float barycentrics (the fan's triangles tile the disc, at equal
    depth, so the one containing a sample is the one it keeps), at pixels where no sample
    lies within 0.01 px of an edge (snapping moves a vertex by at most 1/512 px)."""
    from teachraster.pipeline.debugging.frame_history import samples_kept

    scene = get_scene("fan")
    frame = tr.render(scene, None, 64, 48, samples=4, trace=True)
    window = frame.trace.window[:, :, :2]
    offsets = np.array([[0.375, 0.125], [0.875, 0.375], [0.125, 0.625], [0.625, 0.875]])
    checked = mixed = 0
    for row, col in np.argwhere(frame.coverage)[::3]:
        pts = np.array([col, row]) + offsets  # (4, 2): x, y of the samples
        owner = np.full(4, -1)
        clear = True
        for t, (a, b, c) in enumerate(window):
            m = np.array([[b[0] - a[0], c[0] - a[0]], [b[1] - a[1], c[1] - a[1]]])
            uv = np.linalg.solve(m, (pts - a).T).T
            lam = np.column_stack([1 - uv.sum(axis=1), uv])
            dist = lam * abs(np.linalg.det(m)) / np.array(
                [np.hypot(*(c - b)), np.hypot(*(c - a)), np.hypot(*(b - a))])  # fmt: skip
            if (np.abs(dist) < 0.01).any():
                clear = False
            owner[(lam > 0).all(axis=1)] = t
        if not clear:
            continue
        h = frame.history(row, col)
        reference = {int(t): int((owner == t).sum()) for t in set(owner.tolist()) - {-1}}
        assert samples_kept(h) == reference, (row, col)
        text = str(h)
        rows = [line.split() for line in text.splitlines() if "passed (kept" in line]
        assert rows and all(int(r[5]) == reference[int(r[0])] for r in rows), text
        assert "(shown)" not in text and "most samples" in text
        checked += 1
        mixed += len(reference) > 1
    assert checked > 20 and mixed > 0


def test_hi_z_outcome_matches_the_in_order_replay():
    # a near square drawn first, then a far one: Hi-Z rejects the far one's blocks
    quad = np.array([[[0, 0], [32, 0], [0, 32]], [[32, 0], [32, 32], [0, 32]]], float)
    clip = np.concatenate([clip_from_window(quad, 0.2, width=32, height=32),
                           clip_from_window(quad, 0.7, width=32, height=32)])  # fmt: skip
    frame = tr.render(clip, 32, 32, trace=True)
    assert frame.overlay("hi_z").sum() == frame.trace.hiz.counts["hiz_rejected"] > 0
    h = frame.history(20, 20)
    assert "hi_z" in h.outcomes and h.outcomes.count("passed") == 1
    assert frame.overlay("hi_z")[20, 20] == h.outcomes.count("hi_z")


def test_overlays_count_samples_and_depth_test_off():
    clip = clip_from_window([[[-1, -1], [40, -1], [-1, 40]], [[-1, -1], [40, -1], [-1, 40]]],
                            np.array([[0.5], [0.3]]), width=8, height=8)  # fmt: skip
    one = tr.render(clip, 8, 8, trace=True)
    four = tr.render(clip, 8, 8, samples=4, trace=True)
    assert (one.overlay("overdraw") == 2).all() and (four.overlay("overdraw") == 8).all()
    assert (one.overlay("depth_complexity") == 2).all()  # the second is nearer: passes too
    assert (four.overlay("depth_complexity") == 8).all()
    back = tr.render(clip[::-1], 8, 8, samples=4, trace=True)
    assert (back.overlay("depth_complexity") == 4).all()
    off = tr.render(clip[::-1], 8, 8, samples=4, trace=True, depth_test=False)
    np.testing.assert_array_equal(off.overlay("depth_complexity"), off.overlay("overdraw"))
    assert (one.overlay("triangle_size") == 64).all()
    assert (one.overlay("quad_overshading") == 0).all()


def test_overlays_are_zero_not_nan_where_nothing_arrives():
    clip = clip_from_window([[[1, 1], [3, 1], [1, 3]]], 0.5, width=8, height=8)
    for samples in (1, 4):
        frame = tr.render(clip, 8, 8, trace=True, samples=samples)
        for kind in KINDS:
            out = frame.overlay(kind)
            assert out.shape == (8, 8) and np.isfinite(out).all(), kind
            assert out[7, 7] == 0, kind
    small = tr.render(clip, 8, 8, trace=True)
    assert small.overlay("quad_overshading")[1, 1] == 0.75  # one pixel shaded in its quad
    assert small.overlay("triangle_size")[1, 1] == small.coverage.sum()


def lane_share_from_trace(frame, width):
    """Helpers over all lanes, counted independently from the trace's fragment arrays (one
    sample): 4 lanes per (input triangle, quad) pair with a fragment that passed."""
    t = frame.trace
    passed = t.fragment_passed
    quad = (t.fragment_row[passed] // 2) * ((width + 1) // 2) + t.fragment_col[passed] // 2
    pairs = np.unique(np.column_stack([t.fragment_triangle[passed], quad]), axis=0)
    return 1 - passed.sum() / (4 * len(pairs)) if len(pairs) else 0.0


@pytest.mark.parametrize("name", ["uv_sphere", "textured_floor", "grid", "fan"])
def test_helper_share_is_helpers_over_all_lanes_and_the_overlay_title_prints_it(name):
    """The quad overshading title says the frame's helper share over ALL lanes launched
    (lesson 11 prints it), not the mean over quads with a helper (51 % on the floor against a
    printed 6 %)."""
    import matplotlib.pyplot as plt

    from teachraster.pipeline.debugging import helper_share
    from teachraster.plotting import plot_overlay

    frame = tr.render(get_scene(name), None, 64, 48, trace=True)
    share = helper_share(frame)
    assert share == pytest.approx(lane_share_from_trace(frame, 64), abs=1e-12)
    values = frame.overlay("quad_overshading")
    # the same share from the overlay's per-quad fractions, weighted by the lanes launched
    quads = {(r // 2, c // 2): values[r, c] for r, c in np.argwhere(values > 0)}
    launched = sum(4 * len(tr.pipeline.debugging.quad_triangles(frame, 2 * r, 2 * c))
                   for r, c in np.ndindex(24, 32))  # fmt: skip
    helpers = sum(4 * len(tr.pipeline.debugging.quad_triangles(frame, 2 * r, 2 * c)) * v
                  for (r, c), v in quads.items())  # fmt: skip
    assert share == pytest.approx(helpers / launched)
    fig, ax = plt.subplots()
    try:
        plot_overlay(ax, frame, "quad_overshading")
        assert ax.get_title() == f"quad overshading: helpers {share:.0%} of all lanes"
    finally:
        plt.close(fig)
    if name == "textured_floor":  # the reviewer's case: two big triangles, few helpers
        assert share < 0.1 < values[values > 0].mean()


def test_helper_share_under_msaa_and_without_work():
    from teachraster.pipeline.debugging import helper_share, quad_triangles

    four = tr.render(get_scene("uv_sphere"), None, 32, 24, trace=True, samples=4)
    launched = useful = 0
    for r, c in np.ndindex(12, 16):
        shaded = quad_triangles(four, 2 * r, 2 * c)
        launched, useful = launched + 4 * len(shaded), useful + sum(shaded.values())
    assert 0 < helper_share(four) == pytest.approx(1 - useful / launched)
    empty = tr.render(clip_from_window([[[1, 1], [3, 1], [1, 3]]], 0.5, width=8, height=8)[:0],
                      8, 8, trace=True)  # fmt: skip
    assert helper_share(empty) == 0.0
    with pytest.raises(ValueError, match="trace=True"):
        helper_share(tr.render(get_scene("fan"), None, 16, 12))
    with pytest.raises(ValueError, match="row"):
        quad_triangles(four, 24, 0)


def test_quad_triangles_are_the_passed_records_of_the_quads_four_pixels():
    """What the inspector lists under a quad is what clicking its four pixels shows: the
    triangles whose fragment passed the depth test there, hidden later or not."""
    from teachraster.pipeline.debugging import quad_triangles

    frame = tr.render(get_scene("uv_sphere"), None, 64, 48, trace=True)
    values = frame.overlay("quad_overshading")
    several = 0
    for r0, c0 in [(r, c) for r in range(0, 48, 2) for c in range(0, 64, 2)]:
        shaded = quad_triangles(frame, r0 + 1, c0)
        clicked: dict = {}
        for r, c in ((r0, c0), (r0, c0 + 1), (r0 + 1, c0), (r0 + 1, c0 + 1)):
            for rec in frame.history(r, c):
                if rec.outcome == "passed":
                    clicked[rec.triangle] = clicked.get(rec.triangle, 0) + 1
        assert shaded == clicked, (r0, c0)
        if shaded:
            lanes = 4 * len(shaded)
            assert values[r0, c0] == pytest.approx((lanes - sum(shaded.values())) / lanes)
        several += len(shaded) > len({int(t) for t in frame.triangle_id[r0:r0 + 2, c0:c0 + 2].ravel()
                                      if t >= 0})  # fmt: skip
    assert several > 0  # some quads count a triangle that passed and was hidden later


def test_distances_in_a_history_have_one_precision():
    """One precision per table (4 decimals), not 0.646 beside 0.4258 (review r7)."""
    import re

    from teachraster.pipeline.debugging.frame_history import px_text

    frame = tr.render(get_scene("fan"), None, 64, 48, trace=True)
    texts = " ".join(str(frame.history(r, c)) for r, c in [(20, 30), (24, 32), (10, 10)])
    found = re.findall(r"by (\S+) px", texts)
    assert found and all(re.fullmatch(r"\d+\.\d{4}|\d\.\de-\d+", d) for d in found), found
    assert px_text(2.73) == "2.7300" and px_text(1e-6) == "1.0e-06"


def test_nan_overlay_counts_non_finite_values():
    frame = tr.render(get_scene("textured_floor"), None, 32, 24)
    assert frame.overlay("nan").sum() == 0  # no trace needed
    frame.attrs[3, 4, 0] = np.nan  # a corrupted frame shows up
    if frame.coverage[3, 4]:
        assert frame.overlay("nan")[3, 4] == 1


def test_nan_overlay_does_not_count_depth_glass_never_wrote():
    """Glass (depth_write=False) leaves the depth buffer empty (NaN): not a NaN to hunt;
    an infinite depth still is."""
    scene = get_scene("intersecting_triangles")
    clip = scene.clip(32 / 24)
    rgba = np.concatenate([scene.mesh.corner("color"), np.full((2, 3, 1), 0.6)], axis=2)
    glass = tr.render(clip, 32, 24, attrs=rgba, blend="over", depth_write=False)
    assert glass.coverage.sum() > 0 and np.isnan(glass.depth[glass.coverage]).all()
    assert glass.overlay("nan").sum() == 0
    row, col = np.argwhere(glass.coverage)[0]
    glass.depth[row, col] = np.inf
    assert glass.overlay("nan")[row, col] == 1


def test_overdraw_matches_an_independent_count(rng):
    for index in range(10):
        clip, attrs, kw = random_scene(rng, index)
        frame = tr.render(clip, W, H, attrs=attrs, trace=True, samples=4, **kw)
        count = np.zeros((H, W), dtype=np.int64)
        t = frame.trace
        for piece, v in enumerate(t.window):
            if t.culled[piece]:
                continue
            fill = tr.rasterize(tr.Triangle(v[:, :2]), W, H, samples=4)
            count += fill.sample_coverage.sum(axis=2)
        np.testing.assert_array_equal(frame.overlay("overdraw"), count, err_msg=str(kw))


def test_no_trace_no_history_and_bad_arguments():
    clip = clip_from_window([[[1, 1], [7, 1], [1, 7]]], 0.5, width=8, height=8)
    plain = tr.render(clip, 8, 8)
    assert plain.trace is None
    with pytest.raises(ValueError, match="trace=True"):
        plain.history(1, 1)
    with pytest.raises(ValueError, match="trace=True"):
        plain.overlay("overdraw")
    frame = tr.render(clip, 8, 8, trace=True)
    with pytest.raises(ValueError, match="kind"):
        frame.overlay("wireframe")
    with pytest.raises(ValueError, match="row"):
        frame.history(8, 0)
    with pytest.raises(ValueError, match="col"):
        frame.history(0, -1)
    with pytest.raises(TypeError, match="row"):
        frame.history(1.5, 0)
    assert frame.history(np.int64(2), 2).row == 2
    assert len(frame.history(7, 7)) == 0 and "no triangle" in str(frame.history(7, 7))


def test_history_plot_returns_artists():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    frame = tr.render(get_scene("intersecting_triangles"), None, 32, 24, trace=True)
    fig, ax = plt.subplots()
    artists = frame.history(12, 16).plot(ax)
    assert artists
    plt.close(fig)


@pytest.mark.bench
def test_history_benchmark_quick_run_succeeds(capsys):
    import importlib.util
    import sys
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_history.py"
    spec = importlib.util.spec_from_file_location("bench_history", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules["bench_history"] = module
    spec.loader.exec_module(module)
    assert module.main(["--quick", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "trace=True + all six overlays" in out and "pixel history" in out


# -- the widget ---------------------------------------------------------------------------------
def test_frame_inspector_views_clicks_and_scenes():
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector

    w = FrameInspector("cube", 32, 24, backend="image")
    # the control row fits a 1400-px window: the checkboxes are not indented
    assert not w.depth_test.indent and not w.glass.indent
    for view in ("image", *KINDS):
        w.view.value = view
    assert w.view.value == "nan"
    # r112 11: on the built-in scenes the nan view is always 0 (render refuses NaN input); its
    # label says so
    from teachraster.widgets.frame_inspector import NAN_ON_SCENES

    assert w.view.label == NAN_ON_SCENES and "0 on built-in scenes" in NAN_ON_SCENES
    w.row.value, w.col.value = 10, 14
    assert (w.history.row, w.history.col) == (10, 14)
    assert "row 10, col 14" in w.table.value
    if w.clicker is not None:  # anywidget: a click arrives as fractions of the image
        width, height = w.fig.canvas.get_width_height()
        x, y = w.ax.transData.transform((5.5, 7.5))  # display pixels, y up
        w.clicker.click = [x / width, 1 - y / height, 1]
        assert (w.row.value, w.col.value) == (7, 5)
        assert w.clicker.value[:4] == b"\x89PNG"
    w.row.value, w.col.value = 10, 14
    w.view.value = "quad_overshading"  # the quad's triangles under the history
    shaded = tr.pipeline.debugging.quad_triangles(w.frame, 10, 14)
    assert shaded  # the cube covers this quad
    assert "quad of rows 10–11, cols 14–15" in w.table.value
    assert f"{4 * len(shaded)} lanes launched" in w.table.value
    # review r96 11-1: the counts Question 3 asks for start a line of their own, no line long
    from teachraster.widgets.frame_inspector import quad_text

    text = quad_text(w.frame, 10, 14)
    assert text.splitlines()[-1].startswith(f"{4 * len(shaded)} lanes launched (4 each), ")
    assert max(len(line) for line in text.splitlines()) <= 90
    # review r211 11-3: on uv_sphere at (14, 24), the pixel Question 3 names, six triangles
    # stood on one line and the sixth hid behind the table's sideways scroll; every one is
    # on a line no longer than the table's own lines now
    from teachraster.widgets.frame_inspector import QUAD_TEXT_WIDTH

    sphere = tr.render(tr.get_scene("uv_sphere"), None, 64, 48, trace=True)
    text = quad_text(sphere, 14, 24)
    lines = text.splitlines()
    assert max(len(line) for line in lines) <= QUAD_TEXT_WIDTH < 80
    named = " ".join(lines[1:-1])
    six = tr.pipeline.debugging.quad_triangles(sphere, 14, 24)
    assert all(f"{t} ({n} px)" in named for t, n in six.items())
    assert len(six) == 6 and len(lines) >= 4
    empty = quad_text(sphere, 0, 0)  # no triangle there: short lines too
    assert "no lanes launched" in empty
    assert max(len(line) for line in empty.splitlines()) <= QUAD_TEXT_WIDTH
    w.view.value = "overdraw"
    assert "quad of rows" not in w.table.value
    w.click_at(100.0, 100.0)  # outside the frame: nothing changes
    assert (w.row.value, w.col.value) != (100, 100)
    w.view.value = "image"  # review r8 (11): the title says when the glass frame is drawn
    assert w.ax.get_title() == "cube: the frame"
    w.glass.value = True
    assert w.ax.get_title() == "cube: the frame (glass)"
    w.samples.value = 4
    assert w.frame.samples is not None and w.history.n_samples == 4
    w.depth_test.value = False
    w.scene.value = "cyclic_overlap"
    tri, _ = w.history.replay()
    np.testing.assert_array_equal(tri, w.frame.sample_triangle_id[w.row.value, w.col.value])
    w.close()


def test_frame_inspector_marks_its_pixel_and_says_when_nothing_reaches_it():
    """Review 11-12 r5: a one-pixel outline was lost on a projector, and a pixel no triangle
    reaches drew an empty strip with no word."""
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector

    w = FrameInspector("fan", 32, 24, backend="image")
    try:
        w.row.value, w.col.value = 0, 0  # a corner: the fan does not reach it
        assert not w.history.records
        texts = [t.get_text() for t in w.hist_ax.texts]
        assert "no triangle reaches this pixel" in texts
        w.row.value, w.col.value = 12, 16
        x, y = (np.asarray(v, float) for v in w.marker.get_data())
        outline = np.isfinite(x) & (x >= 16) & (x <= 17) & (y >= 12) & (y <= 13)
        assert outline.sum() >= 5  # the pixel's square ...
        assert np.nanmin(x) <= 14 and np.nanmax(x) >= 19  # ... and ticks pointing at it
        assert np.nanmin(y) <= 10 and np.nanmax(y) >= 15
        assert w.marker.get_path_effects()  # a halo: visible on any colour
        assert w.history.records  # the note goes when records come
        assert "no triangle reaches this pixel" not in [t.get_text() for t in w.hist_ax.texts]
    finally:
        w.close()


def test_frame_inspector_draws_edges_and_saves_the_frame_in_its_stand_in():
    """Review r90 11-4: the fan's hub was a white blur, no edge drawn: the image view draws
    the shown triangles' edges thin (not a 3-px-a-triangle sphere's). 11-5: the picture a
    saved notebook shows without a kernel held the history chart only, not the frame."""
    pytest.importorskip("ipywidgets")
    from matplotlib.collections import LineCollection

    from teachraster.widgets import FrameInspector
    from teachraster.widgets.common import box_standin

    w = FrameInspector("fan", 64, 48, backend="image", view="image", row=23, col=31)
    try:
        edges = [c for c in w.ax.collections if isinstance(c, LineCollection)]
        assert len(edges) == 1 and len(edges[0].get_segments()) == 3 * 12
        hub = np.array([32.0, 24.0])  # the fan's centre, where its 12 triangles meet
        ends = np.concatenate(edges[0].get_segments())
        assert (np.abs(ends - hub).max(axis=1) < 1e-9).sum() >= 12
        pictures = box_standin(w.widget, "inspector").count("data:image/png")
        assert pictures == 2  # the frame, then the history chart
        w.view.value = "overdraw"  # r298 W1: every view outlines the triangles
        assert len([c for c in w.ax.collections if isinstance(c, LineCollection)]) == 1
        w.scene.value = "uv_sphere"
        w.view.value = "image"
        assert not [c for c in w.ax.collections if isinstance(c, LineCollection)]
    finally:
        w.close()


def test_frame_inspector_under_ipympl_takes_mouse_clicks():
    pytest.importorskip("ipympl")
    from matplotlib.backend_bases import MouseEvent

    from teachraster.widgets import FrameInspector

    w = FrameInspector("fan", 32, 24, backend="ipympl")
    x, y = w.ax.transData.transform((20.5, 3.5))
    event = MouseEvent("button_press_event", w.fig.canvas, x, y, button=1)
    w.fig.canvas.callbacks.process("button_press_event", event)
    assert (w.row.value, w.col.value) == (3, 20)
    w.close()


def _shown_controls(widget, shown=None):
    """Every widget a page draws of ``widget``'s tree: a box hidden by its layout
    (``display: none``) hides what it holds."""
    shown = [] if shown is None else shown
    if getattr(getattr(widget, "layout", None), "display", None) == "none":
        return shown
    shown.append(widget)
    for child in getattr(widget, "children", ()) or ():
        _shown_controls(child, shown)
    return shown


def test_frame_inspector_hides_the_controls_its_frames_mode_ignores():
    """Review r11 (exercise 11, 11-F): with ``frames=`` the samples, depth test and glass
    controls do nothing; shown greyed out they read as broken. Hidden, not disabled."""
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector
    from teachraster.widgets.frame_inspector import glass_frame

    frames = {name: glass_frame(name, 16, 12) for name in ("cube", "fan")}
    w = FrameInspector(frames=frames, backend="image")
    try:
        shown = _shown_controls(w.widget)
        assert not [c for c in shown if getattr(c, "disabled", False)]
        assert all(c not in shown for c in (w.samples, w.depth_test, w.glass))
        assert w.scene in shown and w.view in shown and w.row in shown
    finally:
        w.close()
    w = FrameInspector("cube", 16, 12, backend="image")  # the scenes: every control works
    try:
        shown = _shown_controls(w.widget)
        assert all(c in shown and not c.disabled for c in (w.samples, w.depth_test, w.glass))
    finally:
        w.close()


def test_frame_inspector_shows_the_pairs_history_of_the_same_pixel_beside():
    """Review r14 (exercise 11, 11-6): the task compares a pixel's history in a broken frame
    with the intended frame's, and the inspector showed one frame: the other was read from
    memory. With ``pairs`` both histories of the chosen pixel stand side by side, following
    the pixel and the frame chosen; the check box takes the pair away."""
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector
    from teachraster.widgets.frame_inspector import glass_frame

    frames = {"frame 1": glass_frame("cube", 16, 12), "intended 1": glass_frame("fan", 16, 12)}
    w = FrameInspector(frames=frames, pairs={"frame 1": "intended 1"}, backend="image")
    try:
        assert w.beside.value and w.beside in _shown_controls(w.widget)
        w.row.value, w.col.value = 6, 8
        assert str(w.pair_history) == str(frames["intended 1"].history(6, 8))
        assert str(w.history) == str(frames["frame 1"].history(6, 8))
        assert "<b>frame 1</b>" in w.table.value and "<b>intended 1</b>" in w.table.value
        w.scene.value = "intended 1"  # the pairs go both ways
        assert str(w.pair_history) == str(frames["frame 1"].history(6, 8))
        assert w.table.value.index("<b>intended 1</b>") < w.table.value.index("<b>frame 1</b>")
        w.beside.value = False
        assert w.pair_history is None and "<b>" not in w.table.value
    finally:
        w.close()
    with pytest.raises(ValueError, match="pairs"):
        FrameInspector(frames=frames, pairs={"frame 1": "frame 2"}, backend="image")
    with pytest.raises(TypeError, match="pairs"):
        FrameInspector("cube", 16, 12, pairs={"frame 1": "intended 1"}, backend="image")
    w = FrameInspector(frames=frames, backend="image")  # no pairs: no check box
    try:
        assert w.beside not in _shown_controls(w.widget) and w.pair_history is None
    finally:
        w.close()


# -- lesson 11 ------------------------------------------------------------------------------
def _lesson_11_source() -> str:
    import json
    from pathlib import Path

    path = Path(__file__).parents[1] / "notebooks" / "11_debugging_a_frame.ipynb"
    return "".join("".join(c["source"]) for c in json.loads(path.read_text())["cells"])


def _nearest_centre(corners, width, height) -> float:
    """The least distance (px) from a pixel centre to an edge of the triangles ``corners``
    ((n, 3, 2) window positions) in a ``width`` x ``height`` frame."""
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    p = np.stack([xs.ravel(), ys.ravel()], axis=1)
    least = np.inf
    for tri in corners:
        for a, b in zip(tri, np.roll(tri, -1, axis=0)):
            t = np.clip((p - a) @ (b - a) / ((b - a) @ (b - a)), 0, 1)
            least = min(least, np.hypot(*(p - (a + t[:, None] * (b - a))).T).min())
    return float(least)


@pytest.mark.notebook
@pytest.mark.filterwarnings("ignore::DeprecationWarning")
def test_lesson_11_tells_each_story():
    from test_lessons import lesson

    ns = lesson("11_debugging_a_frame")
    assert ns.shown[0] == ns.frame.triangle_id[ns.row, ns.col]
    glass = [r for r in ns.g if r.outcome == "passed"]  # the colour before and after
    assert len(glass) == 2 and glass[0].color_before == (1.0, 1.0, 1.0, 1.0)
    assert glass[1].color_after == tuple(ns.glass.color[ns.row, ns.col])
    assert ns.far_won.outcomes == ["passed", "passed"] and ns.far_won.shows == 1
    assert ns.far_won[0].depth < ns.far_won[1].depth  # the farther one shows
    # Question 1 (r36 11-2, r44 D4: not the set the question before it has just shown):
    # drawn blue first, then red, test off, the buffer keeps red's depth wherever red
    # covers; blue drawn again with the test on passes exactly where blue is nearer and red
    # covers too; an empty buffer (glDisable) would let it pass at all its pixels, a kept
    # nearer depth nowhere
    assert "answer=redraw_passes," in _lesson_11_source()
    red = tr.render(ns.coarse[:1], 12, 9).triangle_id == 0
    blue = ns.blue_alone.triangle_id == 0
    assert np.array_equal(ns.redraw_passes, (ns.coarse_on.triangle_id == 1) & red)
    assert not np.array_equal(ns.redraw_passes, ns.far_wins)
    assert ns.redraw_passes.sum() != ns.far_wins.sum()  # not even the count it just showed
    assert 0 < ns.redraw_passes.sum() < blue.sum()  # the empty-buffer belief: all of blue
    kept = ns.coarse_on.depth  # the nearer depth at each pixel
    assert not (blue & (ns.blue_alone.depth < kept)).any()  # that belief: none passes
    assert (
        ns.far_won[1].depth_after
        == ns.far_won[1].depth
        == ns.off.depth[ns.far_won.row, ns.far_won.col]
    )
    # §5 (r27 D4): llvmpipe's stencil counts and occlusion queries equal the overlays
    if ns.gl_ok:
        assert ns.gl_differ == {1: (0, 0, 0), 4: (0, 0, 0)}
    assert ns.tie[1].outcome == "failed_depth" and ns.tie[1].depth == ns.tie[1].depth_before
    assert len(ns.ties) > 0 and ns.four.coverage.sum() > ns.one.coverage.sum()
    quads = [f.overlay("quad_overshading") for f in (ns.sphere, ns.floor)]
    assert quads[0][quads[0] > 0].mean() > quads[1][quads[1] > 0].mean()
    assert ns.counts["hi_z"] >= 1
    assert sum(ns.counts.values()) == ns.over[ns.hz.row, ns.hz.col]
    assert ns.counts["passed"] == ns.passed[ns.hz.row, ns.hz.col]
    # §1: the Hi-Z-rejected fragment carries no values, and its depth is no nearer than
    # before (review r82 11-A: Hi-Z rejects at nearest >= farthest, so a tie is rejected too;
    # here it is strictly farther)
    (rejected,) = [r for r in ns.h if r.outcome == "hi_z"]
    assert rejected.value == () and rejected.depth > rejected.depth_before
    assert "no nearer than `before`" in _lesson_11_source()
    assert "farther than `before`" not in _lesson_11_source()
    assert all(r.value == () for r in ns.hz if r.outcome == "hi_z")
    # §2's prediction: the far triangle wins where triangle 1 covers a pixel triangle 0 showed
    on, off = ns.coarse_on.triangle_id, ns.coarse_off.triangle_id
    assert np.array_equal(ns.far_wins, (on == 0) & (off == 1)) and 5 <= ns.far_wins.sum() <= 15
    assert (ns.coarse_on.trace.clip_status == 0).all()  # pieces 0, 1 are the two triangles
    # r44 D3: every pixel centre at least 0.2 px from every edge of both triangles (at
    # 0.03 px, under the dashed outline, a centre could not be judged by eye)
    assert _nearest_centre(ns.coarse_on.trace.window[..., :2], 12, 9) >= 0.2
    # r211 11-1: every corner on the grid drawn (blue's lay off it); the line where the two
    # surfaces cross is drawn and named, no centre within 0.4 px of it where both cover, and
    # the answers follow from it: blue nearer left of it, red right
    xy = ns.coarse_on.trace.window[..., :2]
    assert (xy[..., 0] >= 0).all() and (xy[..., 0] <= 12).all()
    assert (xy[..., 1] >= 0).all() and (xy[..., 1] <= 9).all()
    ys, xs = np.mgrid[0:9, 0:12] + 0.5
    gap = ns.depth_gap[0] * xs + ns.depth_gap[1] * ys + ns.depth_gap[2]  # red - blue depth
    both = (tr.render(ns.coarse[:1], 12, 9).triangle_id == 0) & blue
    assert (np.abs(gap[both]) / np.hypot(*ns.depth_gap[:2]) >= 0.4).all()
    assert np.array_equal(ns.far_wins, both & (gap < 0))  # red nearer: right of the line
    assert np.array_equal(ns.redraw_passes, both & (gap > 0))
    assert (ns.near_left, ns.near_right) == ("blue", "red")
    assert abs(ns.depth_gap[1]) < 0.1 * abs(ns.depth_gap[0])  # steep: "left of it" reads
    assert len(ns.crossing) == 2 and np.ptp(ns.crossing[:, 1]) > 3  # drawn across the overlap
    text = _lesson_11_source()
    before = text.split("q_far_wins = PredictPixels(")[0]
    assert "every fragment passes" not in before and "GL_ALWAYS" not in before
    draw = text.split("def draw_outlines(ax):")[1].split("q_far_wins =")[0]
    assert "ax.plot(crossing[:, 0], crossing[:, 1]" in draw and "imshow" not in draw
    # §3: the sliver is counter-clockwise on screen, so its edges are E13, E32, E21
    assert tr.Triangle(ns.sliver_xy).front_facing
    assert all(r.edge in ("E13", "E32", "E21") for r in ns.one.history(ns.r, ns.c)
               if r.outcome == "not_covered")  # fmt: skip
    assert ns.reasons[(28, 37)] == [(1, "clipped_away", "near")]
    assert ns.reasons[(39, 35)] == [(0, "seam", "seam v1–E32∩near")]
    assert ns.reasons[(11, 40)] == [(2, "zero_area", None)]
    # §4's prediction (review r62 #1): the pixels of the quads where both halves of the
    # rectangle cover a centre are shaded twice; the diagonal passes through fewer pixels than
    # that (the trap), and every pixel is covered exactly once
    assert not (ns.half_cov[0] & ns.half_cov[1]).any() and ns.rect_px == 72
    assert ns.twice.sum() == 4 * ns.shared_quads.sum() == 24
    assert all(ns.twice[p] for p in ns.crossed_px) and len(ns.crossed_px) == 12 < ns.twice.sum()
    assert ns.lanes == 96 and ns.useful == 72
    # review r82 11-G: no tint gives the coverage away; no pixel centre lies nearer the
    # diagonal than 0.22 px (it was 0.1 px), so the student judges each centre by eye
    assert 0.22 < ns.diag_gap < 0.23
    draw = _lesson_11_source().split("def draw_quads(ax):")[1].split("q_helpers =")[0]
    asked = _lesson_11_source().split("q_helpers = PredictPixels(")[1].split("answer=")[0]
    assert "imshow" not in draw and "tint" not in asked
    # r90 11-1: the shared diagonal dashed in the first triangle's colour over the second's
    assert "set_dashes" in draw and "(dashed in both colours)" in asked
    # r90 11-2: the text that states the key fact (a quad runs all four lanes) is held
    text = _lesson_11_source()
    assert text.index("q_helpers = PredictPixels(") < text.index("runs all four of its")
    held = text.split("runs all four of its")[0].rsplit("q_helpers.hold()", 1)[1]
    assert "PredictPixels(" not in held
    # §2's tie band (r62 #3): the gap at v1 is under half a unorm16 step, 0.4 is on a step,
    # and the band reaches both ends of the edge v1-v3
    assert 0 < ns.fight_gap[0] < ns.step16 / 2 < ns.fight_gap[1] and ns.fight_gap[2] == 0
    assert 0.4 * 65535 == round(0.4 * 65535)
    assert all(band >= 1 for band, _ in ns.band_rows.values())
    assert ns.z16.triangle_id[2, 2] == 0 and ns.z16.triangle_id[2, 60] == 0
    # §5's nan view (r62 #2): 0 on the built-in scenes; r211 11-6: a NaN made as a vertex
    # shader makes one (normalize of a zero normal) lights every pixel of the triangles that
    # use the vertex, 3 values each (the normal), and the lit triangles share that vertex alone
    assert not any(ns.nan_counts.values())
    lit = ns.broken.overlay("nan")
    uses = (ns.sphere_mesh.triangles == ns.bad_vertex).any(axis=1)
    shown = ns.broken.triangle_id
    assert np.array_equal(lit > 0, (shown >= 0) & uses[np.maximum(shown, 0)])
    assert set(np.unique(lit[lit > 0])) == {3} and len(ns.lit) == (lit > 0).sum() > 0
    assert ns.shared == {ns.bad_vertex} and ns.lit_history.shows in ns.shown_by
    # §6: glass, depth writes off: the farther triangle 1 passes and is blended over the red
    assert ns.glass.color[ns.row, ns.col, 0] == pytest.approx(0.575)
    assert ns.back_first[0] == pytest.approx(0.75)
    assert ns.written.color[ns.row, ns.col, 0] == pytest.approx(0.95)
    assert ns.written.history(ns.row, ns.col).outcomes[1] in ("hi_z", "failed_depth")
    assert "passed (under 1)" in str(ns.g) and all(np.isinf(r.depth_after) for r in ns.g)
    assert ns.glass_counts["hi_z"] == 0 < ns.opaque_hiz
    assert ns.glass_counts["depth_complexity"] == ns.glass_counts["overdraw"]


def test_history_mentions_triangles_clipped_away_whole():
    visible = clip_from_window([[[1, 1], [1, 7], [7, 1]]], 0.5, width=8, height=8)
    behind = np.array([[[0, 0, 0.5, -1.0], [1, 0, 0.5, -1.0], [0, 1, 0.5, -1.0]]])
    frame = tr.render(np.concatenate([behind, visible]), 8, 8, trace=True)
    h = frame.history(2, 2)
    assert h.clipped_away == 1 and [r.triangle for r in h] == [1]
    assert "clipped away whole" in str(h)


def test_msaa_hidden_fragments_carry_the_values_their_pair_would_show():
    """A fragment that passed at a sample and was hidden later carries the attributes of its
    (pixel, triangle) pair, exactly those a render of that triangle alone shows there."""
    scene = tr.get_scene("intersecting_triangles")
    clip = scene.camera.clip(scene.mesh.corner_positions(), 64 / 48)
    colours = scene.mesh.corner("color")
    frame = tr.render(clip, 64, 48, attrs=colours, samples=4, trace=True)
    checked = 0
    for row, col in np.argwhere(frame.triangle_id >= 0)[::7]:
        for rec in frame.history(row, col).records:
            if rec.outcome != "passed" or rec.shown:
                continue
            alone = tr.render(clip[rec.triangle : rec.triangle + 1], 64, 48,
                              attrs=colours[rec.triangle : rec.triangle + 1], samples=4)  # fmt: skip
            np.testing.assert_array_equal(rec.value, alone.sample_attrs[row, col, rec.sample])
            checked += 1
    assert checked > 0


def test_history_plot_marks_depths_on_a_written_out_axis():
    """The strip draws each fragment as a tile of one height at its depth (a bar from the
    foot of a zoomed axis would draw 0.9665 against 0.9686 as 1 : 5), labels the depth axis
    with the depths written out (no "1e-7+9.67634e-1" offset) and only where depths are,
    not beside the colour swatches."""
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    scene = get_scene("intersecting_triangles")
    plain = tr.render(scene, None, 64, 48, trace=True)
    fan4 = tr.render(get_scene("fan"), None, 64, 48, trace=True, samples=4)
    clip = scene.clip(64 / 48)
    rgba = np.concatenate([scene.mesh.corner("color"), np.full((len(clip), 3, 1), 0.5)], axis=2)
    glass = tr.render(clip, 64, 48, attrs=rgba, blend="over", clear_color=(1, 1, 1, 1),
                      trace=True)  # fmt: skip
    for h in (plain.history(24, 34), fan4.history(24, 32), glass.history(24, 34)):
        fig, ax = plt.subplots()
        h.plot(ax)
        fig.canvas.draw()
        depths = {i: r.depth for i, r in enumerate(h) if np.isfinite(r.depth)}
        tiles = [
            p for p in ax.patches if isinstance(p, Rectangle) and np.isclose(p.get_width(), 0.7)
        ]
        assert len(tiles) == len(depths) and len({round(t.get_height(), 15) for t in tiles}) == 1
        for t in tiles:  # centred on its record, at its depth
            assert np.isclose(t.get_y() + t.get_height() / 2, depths[round(t.get_x() + 0.35)])
        depths = list(depths.values())
        assert ax.yaxis.get_offset_text().get_text() == ""
        ticks = ax.get_yticks()
        assert len(ticks) >= 2
        for tick, label in zip(ticks, ax.get_yticklabels()):
            assert float(label.get_text()) == pytest.approx(tick, abs=1e-12)
        lo, hi = min(depths), max(depths)
        assert ticks.max() <= hi + 1.2 * max(hi - lo, 2e-4)  # none beside the swatches
        plt.close(fig)


@pytest.mark.parametrize("depth_write", [False, True])
def test_history_colour_swatches_draw_the_colours_the_table_prints(depth_write):
    """Review r44 D1: the target's before/after swatches were composited over white by the
    target's alpha once more, drawing (245, 179, 179) for a pixel the table prints as
    (0.95, 0.6, 0.6) = (242, 153, 153). Each swatch's face colour, and the pixel at its
    centre in the rendered figure, is the record's RGB (the fragment's: over white)."""
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    from teachraster.pipeline.debugging.frame_history import SWATCH_WIDTH, swatch_colours

    scene = get_scene("intersecting_triangles")
    clip = scene.clip(64 / 48)
    rgba = np.concatenate([scene.mesh.corner("color"), np.full((len(clip), 3, 1), 0.5)], axis=2)
    glass = tr.render(clip, 64, 48, attrs=rgba, blend="over", clear_color=(1, 1, 1, 1),
                      trace=True, depth_write=depth_write)  # fmt: skip
    row, col = np.argwhere(glass.overlay("overdraw") == 2)[0]
    h = glass.history(int(row), int(col))
    passed = [r for r in h if r.outcome == "passed"]
    assert passed and passed[0].color_after != passed[0].color_before
    expected = {  # (record index, offset) -> the RGB the swatch must show
        "color_before": [r.color_before[:3] for r in passed],
        "color_after": [r.color_after[:3] for r in passed],
        "color": [np.multiply(r.color[:3], r.color[3]) + 1 - r.color[3] for r in passed],
    }
    for key, rgbs in expected.items():
        np.testing.assert_allclose(swatch_colours(h, key), np.clip(rgbs, 0, 1), atol=1e-12)
    with pytest.raises(ValueError, match="key"):
        swatch_colours(h, "colour")
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    try:
        h.plot(ax)
        fig.canvas.draw()
        image = np.asarray(fig.canvas.buffer_rgba())
        swatches = [p for p in ax.patches
                    if isinstance(p, Rectangle) and np.isclose(p.get_width(), SWATCH_WIDTH)]  # fmt: skip
        on = [i for i, r in enumerate(h) if r.outcome == "passed"]
        assert len(swatches) == 3 * len(on)
        for p in swatches:
            centre = (p.get_x() + p.get_width() / 2, p.get_y() + p.get_height() / 2)
            k = int(np.argmin([abs(centre[0] - i) for i in on]))  # the record under it
            dx = centre[0] - on[k]
            key = "color_before" if dx < -0.1 else "color_after" if dx > 0.1 else "color"
            want = np.clip(expected[key][k], 0, 1)
            face = np.asarray(p.get_facecolor())
            if key == "color":  # r90 11-6: its own RGB by its alpha, over checks
                r = h.records[on[k]]
                np.testing.assert_allclose(face, np.clip(r.color, 0, 1), atol=1e-12)
            else:
                np.testing.assert_allclose(face[:3], want, atol=1e-12)
            x, y = ax.transData.transform(centre)
            drawn = image[image.shape[0] - 1 - int(round(y)), int(round(x)), :3]
            np.testing.assert_allclose(drawn, np.round(want * 255), atol=1)
    finally:
        plt.close(fig)


def test_history_legend_keys_the_buffer_before_and_after_apart():
    """Lesson 11 says "the buffer before (○) and after (●)": two legend entries, not one."""
    import matplotlib.pyplot as plt

    frame = tr.render(tr.get_scene("intersecting_triangles"), None, 64, 48, trace=True)
    row, col = np.argwhere(frame.overlay("overdraw") == 2)[0]
    fig, ax = plt.subplots()
    try:
        from teachraster.plotting import plot_history

        plot_history(ax, frame, int(row), int(col))
        legend = ax.get_legend()
        labels = [t.get_text() for t in legend.texts]
        handles = dict(zip(labels, legend.legend_handles))
    finally:
        plt.close(fig)
    assert "buffer before" in labels and "buffer after" in labels, labels
    assert handles["buffer before"].get_marker() == "o"
    assert handles["buffer after"].get_marker() == "."


def test_a_record_without_a_fragment_is_keyed_as_having_no_depth():
    """Review r23 D3: a not-covered triangle's cross sits at the axis' foot, which read as its
    depth (0.5999 on an axis from 0.5999 to 0.6002): the key says it has none."""
    import matplotlib.pyplot as plt

    from teachraster.plotting import plot_history

    frame = tr.render(tr.get_scene("intersecting_triangles"), None, 64, 48, trace=True)
    found = next(
        (int(r), int(c))
        for r, c in np.argwhere(frame.overlay("overdraw") >= 1)
        if any(x.outcome == "not_covered" for x in frame.history(int(r), int(c)).records)
    )
    fig, ax = plt.subplots()
    try:
        plot_history(ax, frame, *found)
        labels = [t.get_text() for t in ax.get_legend().texts]
    finally:
        plt.close(fig)
    assert "not_covered (no depth)" in labels and "not_covered" not in labels, labels


def test_sparse_overlays_draw_the_scene_and_hi_z_its_tiles():
    """Review r13, 11: the hi_z and nan views drew only their counts on light grey, so the few
    counted pixels (or none, on a healthy frame) could not be placed on the scene: both draw
    the covered pixels in a second grey, and hi_z the tiles it rejects in."""
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    from teachraster.plotting import plot_overlay
    from teachraster.plotting.frame_debug import COVERED

    frame = tr.render(get_scene("uv_sphere"), None, 64, 48, trace=True)
    for kind in ("hi_z", "nan", "overdraw"):
        fig, ax = plt.subplots()
        try:
            plot_overlay(ax, frame, kind)
            sparse = kind != "overdraw"
            layers = [a for a in ax.collections + ax.images if a.get_zorder() == 0.5]
            assert len(layers) == sparse
            if sparse:  # the scene's coverage, in COVERED, under the counts
                covered = np.asarray(layers[0].get_array()).reshape(48, 64)
                assert np.array_equal(~np.ma.getmaskarray(covered) & (covered == 1),
                                      frame.coverage)  # fmt: skip
                assert tuple(layers[0].get_cmap()(1.0)[:3]) == COVERED
            lines = [c for c in ax.collections if isinstance(c, LineCollection)]
            assert len(lines) == (2 if kind == "hi_z" else 0)  # 8 x 8 tiles: 9 + 7 lines
            if kind == "hi_z":
                assert sorted(len(c.get_segments()) for c in lines) == [7, 9]
        finally:
            plt.close(fig)


def test_the_narrow_history_table_keeps_the_piece_and_sample_columns_where_they_say_something():
    """The FrameInspector's narrow table (12 px in a 592-px column, review r18; lesson 11's
    ``h.table()``) drops the piece column where every record's piece is its triangle and
    the sample column where the pixel has one sample (r36: under MSAA the piece column alone
    pushed every row past 80 characters); print(h) is the wide table, with both."""
    from teachraster.pipeline.debugging.frame_history import NARROW, history_table

    scene = tr.get_scene("intersecting_triangles")
    one = tr.render(scene, None, 32, 24, trace=True).history(12, 16)
    four = tr.render(scene, None, 32, 24, trace=True, samples=4).history(12, 16)
    assert "piece" not in history_table(one, narrow=True) and "piece" in str(one)
    assert "tri smp  outcome" in history_table(four, narrow=True) and "piece" in str(four)
    assert str(four) == history_table(four) and four.table() == history_table(four, narrow=True)
    for h in (one, four):
        lines = history_table(h, narrow=True).splitlines()
        assert lines[0].endswith(":") and "on the way" in lines[1], lines[:2]
        assert max(map(len, lines)) <= NARROW, lines  # the why wraps under its row if not


def _five_outcomes_frame():
    """A 16 x 16 frame whose pixel (6, 6) has all five outcomes: passed, hi_z (a copy
    behind it), failed_depth (a steep triangle nearer elsewhere in the tile), culled (wound
    the other way, cull='back') and not_covered (a small triangle whose box reaches it)."""
    big = [[0, 32], [32, 0], [0, 0]]
    tris = [big, big, [[4, 12], [12, 4], [4, 4]], big[::-1], [[5.6, 7.0], [7.0, 5.6], [5.6, 5.6]]]
    depths = [[0.5] * 3, [0.7] * 3, [1.0, 1.0, 0.0], [0.2] * 3, [0.1] * 3]
    return tr.render(
        clip_from_window(tris, depths, width=16, height=16), 16, 16, trace=True, cull="back"
    )


def test_history_legend_stays_in_the_axes_and_off_the_tick_labels():
    """Review r27 D2: in the inspector's history strip the two-column legend, with the long
    "not_covered (no depth)" key, was wider than the Axes: it ran off the figure ("buffer
    afte") and covered the top depth tick, at the pixels Questions 2 and 3 of lesson 11 send
    the student to. At the inspector's size, in the classroom style, the legend lies inside
    the Axes, covers no tick label, and (as before) no tile or marker; also with all five
    outcomes and seven keys, and at the lesson's own figure size."""
    matplotlib = pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from teachraster.plotting import plot_history, use_style
    from teachraster.widgets.frame_inspector import glass_frame

    sphere = tr.render(get_scene("uv_sphere"), None, 64, 48, trace=True)
    fan4 = tr.render(get_scene("fan"), None, 64, 48, trace=True, samples=4)
    five = _five_outcomes_frame().history(6, 6)
    assert set(five.outcomes) == set(OUTCOMES), five.outcomes
    crowded = [sphere.history(14, 28), sphere.history(10, 28), fan4.history(14, 28), five,
               glass_frame("uv_sphere", 64, 48).history(24, 32)]  # fmt: skip
    with matplotlib.rc_context():  # (the style set for good leaks into later tests)
        use_style("classroom")
        for size, rect in (((4.6, 3.9), (0.26, 0.24, 0.71, 0.66)), ((7, 4.5), None)):
            fig = plt.figure(figsize=size, dpi=96, layout=None if rect else "constrained")
            ax = fig.add_axes(rect) if rect else fig.add_subplot()
            try:
                for h in crowded:
                    ax.clear()
                    plot_history(ax, h)
                    fig.canvas.draw()
                    box, axes = ax.get_legend().get_window_extent(), ax.get_window_extent()
                    where = f"{size}, pixel ({h.row}, {h.col}): legend {box}, Axes {axes}"
                    assert axes.x0 - 0.5 <= box.x0 and box.x1 <= axes.x1 + 0.5, where
                    assert axes.y0 - 0.5 <= box.y0 and box.y1 <= axes.y1 + 0.5, where
                    labels = [t for t in ax.get_yticklabels() + ax.get_xticklabels()
                              if t.get_visible() and t.get_text()]  # fmt: skip
                    assert not [t.get_text() for t in labels
                                if t.get_window_extent().overlaps(box)], where  # fmt: skip
                    tiles = [p for p in ax.patches if np.isclose(p.get_width(), 0.7)]
                    assert not [p for p in tiles if p.get_window_extent().overlaps(box)], where
                    for line in ax.lines:
                        xy = ax.transData.transform(np.c_[line.get_xdata(), line.get_ydata()])
                        assert not [q for q in xy if np.isfinite(q).all() and box.contains(*q)]
            finally:
                plt.close(fig)


def test_history_depth_ticks_stay_within_the_depths_possible():
    """Review r32 D11-3: with room made above the depths for the legend, the inspector's
    chart at exercise 11's frame 7, (21, 32) (a failing fragment at 0.699992), ran its depth
    axis to ~1.4 and ticked 1.0 and past it as if a depth could be above 1. Window depths lie
    in [0, 1]: no tick outside it, the room above left unlabelled. Also at a pixel whose
    depths are near 0 (frame 1, (24, 28)), and at ties of 0.6 (frame 3)."""
    matplotlib = pytest.importorskip("matplotlib")
    import matplotlib.pyplot as plt

    from teachraster import exercises as ex
    from teachraster.pipeline.debugging.frame_history import _tick_range, depth_ticks
    from teachraster.plotting import plot_history, use_style

    with matplotlib.rc_context():
        use_style("classroom")
        fig = plt.figure(figsize=(4.6, 3.9), dpi=96)  # as FrameInspector's history figure
        ax = fig.add_axes((0.26, 0.24, 0.71, 0.66))
        try:
            for n, pixel in ((7, (21, 32)), (5, (21, 32)), (1, (24, 28)), (3, (19, 48))):
                h = ex.broken_frame(n).frame.history(*pixel)
                ax.clear()
                plot_history(ax, h)
                fig.canvas.draw()
                depths = [v for r in h.records for v in (r.depth, r.depth_before)
                          if np.isfinite(v)]  # fmt: skip
                ticks = list(ax.get_yticks())
                where = f"frame {n} {pixel}: ticks {ticks}, ylim {ax.get_ylim()}"
                assert len(ticks) >= 2 and 0 <= min(ticks) and max(ticks) <= 1, where
                assert ax.get_ylim()[0] <= min(ticks) and min(depths) >= 0, where
                if n == 7:  # the room for the legend stays, above the last tick
                    assert ax.get_ylim()[1] > 1 and max(ticks) == 1.0, where
        finally:
            plt.close(fig)
    # depths outside [0, 1] (no window depth; a drawing of other numbers) keep the whole axis
    assert _tick_range(-0.5, 1.4, -0.2, 0.7) == (-0.5, 1.0)
    assert _tick_range(0.2, 1.9, 0.3, 1.2) == (0.2, 1.9)
    assert depth_ticks(*_tick_range(0.295, 1.72, 0.4, 0.699992))[0] == [0.4, 0.6, 0.8, 1.0]


def test_history_strip_keeps_msaa_labels_apart_and_no_depth_axis_without_fragments():
    """Review r50 D3/D4: at 4 samples on ``fan`` the strip's twelve labels "s0".."s3" ran
    together ("s3s0s1s2"); now each record shows its sample's digit, the triangle once
    below its samples, and no two labels touch in a strip as narrow as the inspector's. A
    pixel without a fragment drew a 0-1 depth axis; now no depth ticks, and a note."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.pipeline.debugging.frame_history import draw_history

    fan4 = tr.render(tr.get_scene("fan"), None, 64, 48, trace=True, samples=4)
    h = fan4.history(24, 32)
    assert len(h.records) >= 12
    fig, ax = plt.subplots(figsize=(4.4, 3.2), dpi=100)  # ~300-px Axes, as in the inspector
    try:
        draw_history(ax, h)
        fig.canvas.draw()
        r = fig.canvas.get_renderer()
        for minor in (False, True):
            labels = [t for t in ax.get_xticklabels(minor=minor) if t.get_text()]
            boxes = sorted((t.get_window_extent(r) for t in labels), key=lambda b: b.x0)
            assert all(a.x1 + 1 < b.x0 for a, b in zip(boxes, boxes[1:])), minor
        samples = [t.get_text() for t in ax.get_xticklabels()]
        assert samples == [str(x.sample) for x in h.records]
        tris = [t.get_text() for t in ax.get_xticklabels(minor=True)]
        assert tris == [str(t) for t in dict.fromkeys(x.triangle for x in h.records)]
    finally:
        plt.close(fig)
    plain = tr.render(tr.get_scene("fan"), None, 64, 48, trace=True)
    empty = next(plain.history(r_, c_) for r_, c_ in np.ndindex(48, 64)
                 if plain.history(r_, c_).records
                 and all(x.outcome in ("culled", "not_covered") for x in plain.history(r_, c_)))  # fmt: skip
    for hist, note in ((empty, "no fragment reached this pixel"),
                       (plain.history(0, 0), "no triangle reaches this pixel")):  # fmt: skip
        fig, ax = plt.subplots()
        try:
            draw_history(ax, hist)
            assert not len(ax.get_yticks()) and not ax.get_ylabel()
            assert note in [t.get_text() for t in ax.texts]
        finally:
            plt.close(fig)


def test_frame_inspector_strip_at_4_samples_and_on_an_empty_pixel():
    """Review r50 D3/D4 in the widget itself (kernel side): ``fan`` at 4 samples, pixel
    (24, 32): sample digits that do not touch and the triangles once each; at the corner
    no triangle reaches, no depth ticks."""
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector

    w = FrameInspector("fan", 64, 48, backend="image")
    try:
        w.samples.value = 4
        w.row.value, w.col.value = 24, 32
        w.hist_fig.canvas.draw()
        r = w.hist_fig.canvas.get_renderer()
        labels = [t for t in w.hist_ax.get_xticklabels() if t.get_text()]
        assert len(labels) == len(w.history.records) >= 12
        boxes = [t.get_window_extent(r) for t in labels]
        assert all(a.x1 + 1 < b.x0 for a, b in zip(boxes, boxes[1:]))
        assert [t.get_text() for t in w.hist_ax.get_xticklabels(minor=True)] == [
            str(t) for t in dict.fromkeys(x.triangle for x in w.history.records)
        ]
        w.row.value, w.col.value = 47, 63
        assert not w.history.records and not len(w.hist_ax.get_yticks())
    finally:
        w.close()


def test_frame_inspector_folds_a_triangles_refused_samples_into_one_row():
    """Review r82, 11-F: under 4x MSAA a triangle's consecutive not_covered samples are one
    row of the inspector's table (its samples, the nearest miss); since r96 11-2 the printed
    table (``h.table()``, ``print(h)``) folds them too, and ``fold=False`` gives one row per
    record."""
    from teachraster.pipeline.debugging.frame_history import history_table
    from teachraster.widgets import FrameInspector

    w = FrameInspector("uv_sphere", 64, 48, samples=4, glass=True, backend="image")
    try:
        w.row.value, w.col.value = 24, 32
        h = w.history
        flat = history_table(h, narrow=True, fold=False)
        folded = history_table(h, narrow=True, fold=True)
        assert "4 samples, nearest outside E" in folded and "0-3" in w.table.value
        assert len(folded.splitlines()) < len(flat.splitlines())
        assert h.table() == folded  # what a student prints is what the inspector shows
        # the folded row names the nearest of its samples' misses
        runs = [r for r in h.records if r.outcome == "not_covered" and r.triangle == 384]
        nearest = min(r.outside for r in runs)
        assert f"by {nearest:.4f} px" in folded
        for line in folded.splitlines():
            assert len(line) <= 80, line
    finally:
        w.close()


def test_lesson_11_r82_figures_and_words():
    """Review r82: the z-fighting band keys its white, the sliver's title counts the centres
    in its window, the depth_complexity panel says what it counts, Question 1's last sentence
    reads, and §5's llvmpipe check stands apart from the test file."""
    text = " ".join(_lesson_11_source().split())
    assert "white = centre outside both" in text  # 11-C
    assert "px in the whole frame, {in_window} in this " in text  # 11-D
    assert '"passed the depth test\\n(depth complexity here): ' in _lesson_11_source()  # 11-E
    assert "In the order drawn above" not in text  # 11-H
    assert "In §2's order (red first) the buffer ends with blue's" in text
    assert "*Tested in* `tests/test_frame_history_gl.py`" in text  # 11-I


def test_printed_table_folds_identical_sample_lines_as_the_inspector_does():
    """Review r96 11-2: ``h.table()`` of a glass sphere's pixel under 4x MSAA printed four
    identical colour lines for triangle 415 (one per sample) and four "not_covered" rows of
    triangle 383. Printed, the table folds them as the inspector does ("s0-3", "0-3"); the
    records, the contract, keep one per sample, and every folded line stands for the lines
    it replaces."""
    from teachraster.pipeline.debugging.frame_history import (
        colour_lines,
        history_table,
        sample_list,
    )
    from teachraster.widgets.frame_inspector import glass_frame

    h = glass_frame("uv_sphere", 64, 48, samples=4).history(23, 31)
    printed = h.table()
    assert printed == history_table(h, narrow=True, fold=True) and str(h) == history_table(h)
    lines = printed.splitlines()
    body = lambda t: t[t.index("(") :]  # noqa: E731
    colours = [line for line in lines if line.startswith("  415 ")]
    assert len(colours) == 1 and " s0-3 " in colours[0]
    assert any(line.startswith("383 0-3  not_covered") for line in lines)
    assert any(" s1-2 " in line for line in lines if line.startswith("  592 "))
    # nothing lost: each sample's colour line is one of the folded lines
    full = colour_lines(h)
    folded = colour_lines(h, fold=True)
    assert {body(x) for x in full[1:]} == {body(x) for x in folded[1:]}
    assert len(h.records) == 4 * len({r.triangle for r in h.records})  # one per sample
    assert sum(r.triangle == 415 and r.outcome == "passed" for r in h.records) == 4
    assert len(history_table(h, narrow=True, fold=False).splitlines()) > len(lines)
    assert sample_list([0, 2, 3]) == "0,2-3" and sample_list([3]) == "3"


def test_glass_swatches_in_the_inspector_are_legible():
    """Review r96 11-3: with glass, the inspector's history strip drew each record's
    before/fragment/after swatches about 15 x 30 px. At the inspector's size, one sample,
    each is now at least 20 px wide and 40 px tall."""
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    from matplotlib.patches import Rectangle

    from teachraster.pipeline.debugging.frame_history import SWATCH_WIDTH
    from teachraster.widgets import FrameInspector

    w = FrameInspector("uv_sphere", 64, 48, glass=True, backend="image")
    try:
        w.row.value, w.col.value = 24, 32
        w.hist_fig.canvas.draw()
        swatches = [p for p in w.hist_ax.patches
                    if isinstance(p, Rectangle) and np.isclose(p.get_width(), SWATCH_WIDTH)]  # fmt: skip
        assert len(swatches) == 3 * sum(r.outcome == "passed" for r in w.history)
        for p in swatches:
            box = p.get_window_extent()
            # review r211 11-4: about 16 px wide on screen at 4.6 inches; the chart takes
            # the frame's width where it draws colours
            assert box.width >= 36 and box.height >= 40, (box.width, box.height)
        # ... and the swatches' label lies inside the Axes (it ran past the right edge)
        renderer = w.hist_fig.canvas.get_renderer()
        axes = w.hist_ax.get_window_extent(renderer)
        (header,) = [t for t in w.hist_ax.texts if "fragment" in t.get_text()]
        box = header.get_window_extent(renderer)
        assert axes.x0 <= box.x0 and box.x1 <= axes.x1, (box, axes)
        w.glass.value = False  # no colours: the narrow chart again
        assert w.history.blend is None and w.hist_fig.get_size_inches()[0] < 5
    finally:
        w.close()


def test_the_glass_chart_is_shown_at_its_own_width():
    """Review r274 FIG1: ticking glass widened the history chart to 7 inches, but its image
    kept the width it had (4.6 inches), so the browser shrank it by 0.66: its text read 9
    px, 18 px otherwise. The image widget's width follows the figure's, both ways."""
    pytest.importorskip("matplotlib").use("Agg")
    from teachraster.widgets import FrameInspector

    w = FrameInspector("uv_sphere", 64, 48, backend="image")
    try:

        def shown():  # the widget's width against the figure's, in px
            fig = w.hist_fig
            return w.hist_display.widget.layout.width, f"{round(fig.get_figwidth() * fig.dpi)}px"

        narrow = shown()
        assert narrow[0] == narrow[1]
        w.glass.value = True
        wide = shown()
        assert wide[0] == wide[1] and int(wide[0][:-2]) > int(narrow[0][:-2])
        w.glass.value = False
        assert shown() == narrow
    finally:
        w.close()


def test_the_swatches_label_fits_a_narrow_chart():
    """Review r211 11-4: the one label over the colour swatches ran past a narrow chart's
    right edge; it shrinks (to 9 points at least), then takes its short form."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.pipeline.debugging.frame_history import SWATCH_HEADER, SWATCH_HEADER_SHORT
    from teachraster.plotting import plot_history, use_style
    from teachraster.widgets.frame_inspector import glass_frame

    h = glass_frame("uv_sphere", 64, 48).history(24, 32)
    for width, label in ((4.6, SWATCH_HEADER), (3.2, SWATCH_HEADER_SHORT)):
        with matplotlib.rc_context():
            use_style("classroom")
            fig = plt.figure(figsize=(width, 4.5))
            ax = fig.add_axes((1.2 / width, 0.24, (width - 1.34) / width, 0.66))
            plot_history(ax, h)
        renderer = fig.canvas.get_renderer()
        (header,) = [t for t in ax.texts if "fragment" in t.get_text()]
        box, axes = header.get_window_extent(renderer), ax.get_window_extent(renderer)
        assert header.get_text() == label and box.x1 <= axes.x1, (width, header.get_text())
        assert header.get_fontsize() >= 9
        plt.close(fig)


def test_identical_passed_samples_print_on_one_row():
    """Review r106 11-C2: lesson 11 says the table prints a triangle's samples that say the
    same on one line, but for the fan under 4x MSAA, pixel (23, 31) (Question 2's pixel),
    triangle 5's samples 2 and 3 printed as two identical "passed (kept 2 of 4)" rows. They
    are one row "2-3" now, in the printed table and the inspector alike; samples whose depths
    differ keep rows of their own, and the records keep one per sample."""
    from teachraster.pipeline.debugging.frame_history import history_table
    from teachraster.widgets import FrameInspector

    w = FrameInspector("fan", 64, 48, samples=4, backend="image")
    try:
        w.row.value, w.col.value = 23, 31
        h = w.history
        printed = h.table()
        assert printed == history_table(h, narrow=True, like=w.pair_history, fold=True)
        rows = [line for line in printed.splitlines() if line.startswith("  5 ")]
        assert [line.split()[1] for line in rows] == ["0-1", "2-3"]
        assert "  5 2-3  passed (kept 2 of 4)  0.967634" in printed
        assert "  5 2-3  passed" in w.table.value
        flat = history_table(h, narrow=True, fold=False)
        assert flat.count("  5   2  passed (kept 2 of 4)") == 1
        assert flat.count("  5   3  passed (kept 2 of 4)") == 1
        assert sum(r.triangle == 5 and r.outcome == "passed" for r in h.records) == 2
        # different samples that say different things are not folded: triangles 3 and 4
        # each pass at one sample, with their own value
        assert "  3   1  passed (kept 1 of 4)" in printed and "  4   0  passed" in printed
        # no two rows of the printed table say the same but for their samples
        body = [line[7:] for line in printed.splitlines() if line[:5].strip().isdigit()]
        heads = [line[:3] for line in printed.splitlines() if line[:5].strip().isdigit()]
        pairs = list(zip(zip(heads, body), zip(heads[1:], body[1:])))
        assert not [a for a, b in pairs if a == b]
    finally:
        w.close()


_ROW = re.compile(
    r"^\s*(\d+)\s+([\d,-]+)\s+(.+?)\s+(-|empty|[\d.]+)\s+(empty|[\d.]+)\s+(empty|[\d.]+)(?:\s\s|$)"
)


def _table_rows(text: str) -> list[tuple]:
    """(triangle, samples, outcome, depth, before, after) of each record row of a narrow
    MSAA history table (no piece column), the samples expanded ("1-3" -> [1, 2, 3])."""
    rows = []
    for line in text.splitlines():
        m = _ROW.match(line)
        if m is None:
            continue
        samples = []
        for part in m[2].split(","):
            a, _, b = part.partition("-")
            samples += range(int(a), int(b or a) + 1)
        rows.append((int(m[1]), samples, m[3], m[4], m[5], m[6]))
    return rows


def test_folded_rows_print_the_depths_of_every_sample_they_stand_for():
    """Review r159 C1: for the fan under 4x MSAA, pixel (23, 31) (Question 2's pixel), the
    table folded triangle 4's refused samples 1-3 into one row "not_covered - empty empty",
    though sample 1's buffer held triangle 3's 0.967634 (the depth strip beside it drew it):
    only the reason was compared. A row stands for several samples only where each of them
    prints the same outcome, depth, buffer before and after: sample 1 has a row of its own,
    and at every pixel of the frame each folded row says what the unfolded rows of its
    samples say."""
    from teachraster.pipeline.debugging.frame_history import history_table

    frame = tr.render(get_scene("fan"), None, 64, 48, trace=True, samples=4)
    h = frame.history(23, 31)
    one = [r for r in h.records if (r.triangle, r.sample) == (4, 1)][0]
    assert one.outcome == "not_covered" and one.depth_before == one.depth_after < 1
    rows = [row for row in _table_rows(h.table()) if row[0] == 4]
    assert [row[1] for row in rows] == [[0], [1], [2, 3]]
    assert rows[1][2:] == ("not_covered", "-", f"{one.depth_before:.6f}", f"{one.depth_after:.6f}")
    assert rows[2][2:] == ("not_covered", "-", "empty", "empty")
    for row in range(48):
        for col in range(64):
            h = frame.history(row, col)
            flat = {(r[0], r[1][0]): r[2:] for r in _table_rows(history_table(h, True, fold=False))}
            folded = _table_rows(h.table())
            assert sorted(k for r in folded for k in ((r[0], s) for s in r[1])) == sorted(flat)
            for tri, samples, *said in folded:
                for s in samples:
                    # a folded refused row's outcome text is the same; its why is the nearest
                    assert flat[tri, s] == tuple(said), (row, col, tri, s, h.table())


@pytest.mark.parametrize("name", ["uv_sphere", "textured_floor"])
def test_the_triangle_size_title_is_the_median_per_triangle_shown_as_lesson_11_prints(name):
    """r431 C1: the inspector's triangle-size view said "median 4 px" on uv_sphere beside
    lesson 11's 3 px: its title took the median over the pixels, which weights a triangle
    by its size. One size per triangle shown (each the overlay's value at its pixels)."""
    import matplotlib.pyplot as plt

    from teachraster.pipeline.debugging import visible_triangle_sizes
    from teachraster.plotting import plot_overlay

    frame = tr.render(get_scene(name), None, 64, 48, trace=True)
    sizes = visible_triangle_sizes(frame)
    ids = frame.triangle_id
    shown = np.unique(ids[ids >= 0])
    overlay = frame.overlay("triangle_size")
    assert len(sizes) == len(shown)
    for t, size in zip(shown, sizes):  # a triangle's size is the same at each of its pixels
        assert set(overlay[ids == t].tolist()) == {size}
    fig, ax = plt.subplots()
    try:
        plot_overlay(ax, frame, "triangle_size")
        title = ax.get_title()
    finally:
        plt.close(fig)
    assert f"median {np.median(sizes):,g} px per triangle shown" in title, title
    if name == "uv_sphere":  # the case r431 found: the pixels' median differs
        assert np.median(overlay[ids >= 0]) != np.median(sizes)
