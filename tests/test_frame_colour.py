"""One per-sample decision for every consumer of a frame (colour, ids, depth, history,
overlays), ``depth_write=False`` everywhere, blending off as a state, the colour before and
after in the pixel history, and the 8-bit sRGB target (issue 28)."""

from __future__ import annotations

import pickle
import warnings

import numpy as np
import pytest

import teachraster as tr
from teachraster.pipeline.blending.colour_blending import store_colour

W = H = 24
#: custom sample offsets: not on the standard pattern, one of them off the 1/16 grid
OFFSETS = np.array([[0.1, 0.2], [0.7, 0.3], [0.33, 0.8], [0.9, 0.9]])
CLEAR = (0.1, 0.2, 0.3, 0.4)


def coplanar(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """n overlapping triangles in one sloped plane (z-fighting everywhere), each opaque with
    its own red level (i + 1) / 64, so the colour names the triangle."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-0.2, 1.2, (n, 3, 2))
    ndc = np.stack([xy[..., 0] * 2 - 1, 1 - xy[..., 1] * 2], -1)
    z = (0.1 + 0.3 * ndc[..., 0] + 0.17 * ndc[..., 1])[..., None]
    clip = np.concatenate([ndc, z, np.ones((n, 3, 1))], -1)
    colour = np.zeros((n, 3, 4))
    colour[..., 0] = (np.arange(n) + 1)[:, None] / 64.0
    colour[..., 3] = 1.0
    return clip, colour


def random_scene(n: int, seed: int, w_range=(1.0, 1.0)):
    """n triangles with per-vertex depth, w and RGBA (alpha in [0.2, 1])."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(-0.2, 1.2, (n, 3, 2))
    ndc = np.stack([xy[..., 0] * 2 - 1, 1 - xy[..., 1] * 2], -1)
    z = rng.uniform(-0.9, 0.9, (n, 3, 1))
    w = rng.uniform(*w_range, (n, 3, 1))
    clip = np.concatenate([ndc, z, np.ones((n, 3, 1))], -1) * w
    colour = rng.uniform(0, 1, (n, 3, 4))
    colour[..., 3] = rng.uniform(0.2, 1.0, (n, 3))
    return clip, colour


def quad(x0, y0, x1, y1, z):
    a, b, c, d = [x0, y0, z, 1], [x1, y0, z, 1], [x1, y1, z, 1], [x0, y1, z, 1]
    return np.array([[a, b, c], [a, c, d]], dtype=float)


def per_sample(frame, name):
    """frame.sample_<name> or, for one sample, frame.<name> with a sample axis."""
    if frame.samples is None:
        return getattr(frame, "color" if name == "color" else name)[:, :, None]
    return getattr(frame, f"sample_{name}" if name != "triangle_id" else "sample_triangle_id")


# -- one decision per sample: colour, ids, depth, attributes ---------------------------------
@pytest.mark.parametrize(
    "samples, bits, depth_format",
    [(4, 8, "float64"), (4, 8, "unorm16"), (OFFSETS, 8, "float64"), (4, 2, "float64"),
     (OFFSETS, 0, "float64"), (4, None, "float64"), (8, 8, "float32"), (1, 8, "float64")],
)  # fmt: skip
def test_opaque_blending_shows_the_frames_own_triangle_at_every_sample(samples, bits,
                                                                        depth_format):  # fmt: skip
    """Blending used to re-rasterise each sample by moving the triangles and snapping again:
    another coverage, another depth (z-fighting coplanar triangles: 4,669 of 9,023 samples
    showed another triangle at 48x48), other samples with custom offsets or few bits."""
    clip, colour = coplanar(40, 1)
    frame = tr.render(clip, W, H, attrs=colour, blend="over", samples=samples,
                      subpixel_bits=bits, depth_format=depth_format)  # fmt: skip
    ids = per_sample(frame, "triangle_id")
    named = np.round(per_sample(frame, "color")[..., 0] * 64).astype(int) - 1
    assert (ids >= 0).sum() > 0.5 * ids.size
    np.testing.assert_array_equal(named, ids)


@pytest.mark.parametrize("samples", [4, OFFSETS])
def test_colour_is_the_frames_one_evaluation_per_pixel_and_triangle(samples):
    """With centroid sampling (and extrapolated centres) every sample's colour is the very
    value ``sample_attrs`` holds (it used to be evaluated at the centre: 0.02 off)."""
    clip, colour = random_scene(12, 5, w_range=(0.5, 3.0))
    for centroid in (False, True):  # (ONE, ZERO): each sample keeps the last colour as it is
        frame = tr.render(clip, W, H, attrs=colour, blend=("ONE", "ZERO"), samples=samples,
                          centroid=centroid, clear_color=CLEAR)  # fmt: skip
        covered = frame.sample_triangle_id >= 0
        want = np.where(covered[..., None], frame.sample_attrs, CLEAR)
        np.testing.assert_array_equal(frame.sample_color, want)


def test_blending_off_is_the_fragment_colour_over_the_clear_colour():
    clip, colour = random_scene(10, 7)
    for samples in (1, 4):
        frame = tr.render(clip, W, H, attrs=colour, samples=samples, clear_color=CLEAR)
        covered = per_sample(frame, "triangle_id") >= 0
        values = frame.attrs[:, :, None] if samples == 1 else frame.sample_attrs
        want = np.where(covered[..., None], values, CLEAR)
        np.testing.assert_array_equal(per_sample(frame, "color"), want)
        np.testing.assert_array_equal(frame.color, want.mean(axis=2))
        assert "blending" not in [e.name for e in frame.plan]  # nothing was blended
        fresh = tr.render(clip, W, H, attrs=colour, samples=samples, clear_color=CLEAR)
        again = pickle.loads(pickle.dumps(fresh))  # built on first read, still picklable
        np.testing.assert_array_equal(again.color, frame.color)
        # the depth mask is independent of blending
        glass = tr.render(clip, W, H, attrs=colour, samples=samples, depth_write=False)
        assert np.isnan(glass.depth).all() and glass.color is not None
    # without RGBA attributes there is no colour buffer
    assert tr.render(clip, W, H, attrs=colour[..., :3]).color is None


# -- depth_write=False everywhere ------------------------------------------------------------
def glass_over_wall():
    """A wall (writes depth, left half, z = 0), then near glass (z = -0.5) and glass between
    (z = -0.2), both over everything without depth writes: the second glass is behind the
    first, but the first wrote no depth, so both pass."""
    clip = np.concatenate([quad(-1, -1, 0, 1, 0.0), quad(-1, -1, 1, 1, -0.5),
                           quad(-1, -1, 1, 1, -0.2)])  # fmt: skip
    colour = np.repeat(np.array([[0, 1, 0, 1]] * 2 + [[1, 0, 0, 0.5]] * 2 + [[0, 0, 1, 0.5]] * 2,
                                float)[:, None], 3, axis=1)  # fmt: skip
    writes = np.array([True, True, False, False, False, False])
    return clip, colour, writes


@pytest.mark.parametrize("samples", [1, 4])
def test_depth_writes_off_reach_depth_ids_history_and_overlays(samples):
    clip, colour, writes = glass_over_wall()
    frame = tr.render(clip, 8, 8, attrs=colour, blend="over", depth_write=writes,
                      samples=samples, trace=True)  # fmt: skip
    wall = np.zeros((8, 8), dtype=bool)
    wall[:, :4] = True
    # the depth buffer holds only the wall's depth: nothing was written on the right
    np.testing.assert_array_equal(frame.depth[wall], 0.5)
    assert np.isnan(frame.depth[~wall]).all()
    if samples > 1:
        assert np.isnan(frame.sample_depth[~wall]).all()
    # the id is the last fragment that passed (the far glass), as the colour shows
    assert set(np.unique(frame.triangle_id)) == {4, 5}
    h = frame.history(3, 1)
    assert [r.outcome for r in h if r.outcome != "not_covered"] == ["passed"] * 3 * samples
    glass = [r for r in h if r.triangle >= 2 and r.outcome == "passed"]
    assert all(r.depth_before == r.depth_after == 0.5 for r in glass)  # nothing written
    tri, depth = h.replay()
    np.testing.assert_array_equal(depth, per_sample(frame, "depth")[3, 1])
    np.testing.assert_array_equal(tri, per_sample(frame, "triangle_id")[3, 1])
    # every fragment passed: GL_SAMPLES_PASSED counts 3 layers per sample on the left
    complexity = frame.overlay("depth_complexity")
    np.testing.assert_array_equal(complexity, np.where(wall, 3, 2) * samples)
    per_triangle = tr.pipeline.debugging.passed_per_triangle(frame)
    assert per_triangle.sum() == complexity.sum()


def test_depth_writes_off_never_make_a_hi_z_occluder():
    """A near quad without depth writes drawn first, then a far one that writes: the far
    one passes everywhere (the buffer was empty), so no Hi-Z may drop its blocks, neither
    the renderer's (``force="hi_z"`` compares every line) nor the in-order replay."""
    clip = np.concatenate([quad(-1, -1, 1, 1, -0.5), quad(-1, -1, 1, 1, 0.5)])
    writes = np.array([False, False, True, True])
    for force in (None, "hi_z"):
        frame = tr.render(clip, 32, 32, depth_write=writes, force=force)
        assert (frame.triangle_id >= 2).all(), force
        np.testing.assert_array_equal(frame.depth, 0.75)
    frame = tr.render(clip, 32, 32, depth_write=writes, force="hi_z", trace=True)
    assert frame.trace.hiz_tiles.occluders.max() == 1  # only the far quad covers tiles
    assert not frame.trace.hiz.fragment_rejected.any()
    assert frame.trace.fragment_passed.all()
    assert frame.overlay("hi_z").sum() == 0
    outcomes = frame.history(16, 16).outcomes
    assert outcomes.count("passed") == 2 and "hi_z" not in outcomes


@pytest.mark.parametrize("samples", [1, 4])
def test_replay_rebuilds_ids_depth_and_colour_bit_for_bit(samples):
    """Every pixel's records replayed (depth writes mixed, blending on and off, an 8-bit
    sRGB target, centroid sampling) give the frame's ids, depth buffer and colour."""
    configs = [("over", "mixed", "float64", False), ("additive", False, "srgb8", True),
               (None, "mixed", "float64", True), ("premultiplied", True, "srgb8", False)]  # fmt: skip
    for k, (blend, writes, fmt, centroid) in enumerate(configs):
        clip, colour = random_scene(8, 20 + k, w_range=(1.0, 2.0))
        mask = np.arange(8) % 2 == 0 if writes == "mixed" else writes
        frame = tr.render(clip, 10, 10, attrs=colour, blend=blend, depth_write=mask,
                          samples=samples, trace=True, color_format=fmt, centroid=centroid,
                          clear_color=CLEAR)  # fmt: skip
        ids, depth = per_sample(frame, "triangle_id"), per_sample(frame, "depth")
        colour_buffer = per_sample(frame, "color")
        for row in range(10):
            for col in range(10):
                h = frame.history(row, col)
                tri, dep = h.replay()
                np.testing.assert_array_equal(tri, ids[row, col])
                np.testing.assert_array_equal(dep, depth[row, col])
                np.testing.assert_array_equal(h.replay_color(), colour_buffer[row, col])
                passed = [r for r in h if r.outcome == "passed"]
                for r in h:  # a record that did not pass leaves the colour as it was
                    assert len(r.color_before) == len(r.color_after) == 4
                    assert r.outcome == "passed" or r.color_before == r.color_after
                for s in range(h.n_samples):
                    mine = [r for r in passed if r.sample == s]
                    if mine:
                        assert mine[-1].color_after == tuple(colour_buffer[row, col, s])


def test_history_shows_the_colour_before_and_after_each_fragment():
    import matplotlib.pyplot as plt

    import teachraster.plotting as tp

    clip, colour, writes = glass_over_wall()
    frame = tr.render(clip, 8, 8, attrs=colour, blend="over", depth_write=writes, trace=True,
                      clear_color=(1, 1, 1, 1))  # fmt: skip
    h = frame.history(3, 1)
    passed = [r for r in h if r.outcome == "passed"]
    assert passed[0].color_before == (1.0, 1.0, 1.0, 1.0)
    assert passed[0].color_after == (0.0, 1.0, 0.0, 1.0)  # the opaque wall replaces
    assert passed[1].color == (1.0, 0.0, 0.0, 0.5)
    assert passed[1].color_after == (0.5, 0.5, 0.0, 0.75)  # red glass over the wall
    assert "before -> fragment -> after" in str(h)
    # blended over, not hidden: the wall's colour is in the result
    assert "passed (under 3)" in str(h) and "hidden by" not in str(h)
    off = tr.render(clip, 8, 8, attrs=colour, blend=None, depth_write=writes, trace=True)
    assert "passed (hidden by 3)" in str(off.history(3, 1))  # blending off: written over
    fig, ax = plt.subplots()
    plain = tr.render(clip, 8, 8, attrs=colour[..., :3], depth_write=writes, trace=True)
    assert len(tp.plot_history(ax, h).parts) > len(tp.plot_history(ax, plain.history(3, 1)).parts)
    plt.close(fig)


# -- the 8-bit sRGB target and the sRGB curve ---------------------------------------------
def gl_srgb_reference(layers, mode):
    """GL's SRGB8_ALPHA8 blending, one pixel, with integer codes: decode, clamp, blend,
    clamp, encode, round, after every layer (an independent scalar loop)."""
    code = np.zeros(4, dtype=np.int64)  # cleared to 0
    for src in layers:
        src = np.clip(src, 0, 1)
        dst = np.array([*(tr.srgb_to_linear(code[:3] / 255)), code[3] / 255])
        if mode == "over":
            out = src * src[3] + dst * (1 - src[3])
        else:
            out = src + dst
        out = np.clip(out, 0, 1)
        code = np.r_[np.round(tr.linear_to_srgb(out[:3]) * 255), np.round(out[3] * 255)]
    return code


@pytest.mark.parametrize("mode, n", [("over", 16), ("additive", 40)])
def test_srgb8_target_rounds_after_every_layer(mode, n):
    rng = np.random.default_rng(n)
    rgba = rng.uniform(0, 1, (n, 4)) * ([1, 1, 1, 1] if mode == "over" else [0.1] * 4)
    clip = np.concatenate([quad(-1, -1, 1, 1, 0.0)[:1]] * n)
    attrs = np.repeat(rgba[:, None], 3, axis=1)
    frame = tr.render(clip, 2, 2, attrs=attrs, blend=mode, depth_write=False,
                      color_format="srgb8")  # fmt: skip
    got = frame.color[1, 0]  # under the triangle
    codes = np.r_[np.round(tr.linear_to_srgb(got[:3]) * 255), np.round(got[3] * 255)]
    np.testing.assert_array_equal(codes, gl_srgb_reference(rgba, mode))
    np.testing.assert_array_equal(store_colour(got, "srgb8"), got)  # a stored value
    unrounded = tr.render(clip, 2, 2, attrs=attrs, blend=mode, depth_write=False).color[1, 0]
    assert not np.allclose(unrounded, got, atol=1e-3)  # rounding every layer matters here


def test_srgb_to_linear_of_negative_values_does_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = tr.srgb_to_linear([-0.5, -0.06, -0.01, 0.5])
        back = tr.linear_to_srgb([-0.5, 0.2])
    np.testing.assert_allclose(out[:3], np.array([-0.5, -0.06, -0.01]) / 12.92)
    assert np.isfinite(out).all() and np.isfinite(back).all()


def test_frame_inspector_shows_a_scene_as_glass_with_its_colours():
    from teachraster.widgets.frame_inspector import FrameInspector

    w = FrameInspector("intersecting_triangles", 32, 24, backend="image", glass=True)
    try:
        w.row.value, w.col.value = 12, 16
        assert w.history.blend is not None and "before -&gt; fragment" in w.table.value
        np.testing.assert_array_equal(w.history.replay_color()[0], w.frame.color[12, 16])
        w.glass.value = False  # back to the shaded scene: no colour buffer
        assert w.history.blend is None
    finally:
        w.close()


def test_each_records_swatches_are_named_where_they_fit():
    """Review r55 #7 / r62: "before | fragment on white | after" stood once at the left, over
    the first record's swatches only. Where the words fit over the swatches, each passed
    record's three are named; where not (a narrow chart, many records), the one label."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.pipeline.debugging.frame_history import SWATCH_WORDS
    from teachraster.plotting import plot_history, use_style
    from teachraster.widgets.frame_inspector import glass_frame

    h = glass_frame("intersecting_triangles", 64, 48).history(24, 34)
    passed = sum(r.outcome == "passed" for r in h)
    for size, named in (((9, 4.5), True), ((2.5, 4.5), False)):
        with matplotlib.rc_context():
            use_style("classroom")  # the lessons' (the words at least 9 pt: 12 px)
            fig, ax = plt.subplots(figsize=size, layout="constrained")
            plot_history(ax, h)
        words = [t.get_text() for t in ax.texts]
        if named:
            assert all(words.count(w) == passed for w in SWATCH_WORDS), words
        else:  # r90 11-6; r211 11-4: the short form where the long one runs past the Axes
            assert "before | fragment (over checks) | after" in words or (
                "before | fragment | after" in words
            ), words
        plt.close(fig)


def test_identical_sample_colour_lines_fold_into_one():
    """Review r90 11-7: under 4x MSAA a glass sphere's pixel listed one colour line per
    sample, four identical lines for triangle 415; folded, one line names "s0-3"."""
    from teachraster.pipeline.debugging.frame_history import colour_lines
    from teachraster.widgets.frame_inspector import glass_frame

    h = glass_frame("uv_sphere", 64, 48, samples=4).history(23, 31)
    full, folded = colour_lines(h), colour_lines(h, fold=True)
    assert len(folded) < len(full)
    assert any(" s0-3 " in line for line in folded)
    # nothing lost: each folded line stands for the unfolded lines it replaces
    bodies = lambda lines: {line[line.index("(") :] for line in lines[1:]}  # noqa: E731
    assert bodies(folded) == bodies(full)
