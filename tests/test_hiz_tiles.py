"""Hi-Z in ``render`` (teachraster.pipeline.hiz_tiles): blocks of raster lines hidden behind
a triangle covering their whole tile are dropped before their depth is interpolated.

The frame is bit-identical with Hi-Z planned, forced, everything forced and Hi-Z switched
off, on every built-in scene and on random scenes; every rejected fragment is strictly
farther than the final z-buffer at its pixel; occluders are the tiled walk's accepted
8×8 blocks; the counts agree with each other and, where the plan runs, with the forced run.
"""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest
from conftest import examples
from hypothesis import given, settings
from hypothesis import strategies as st
from test_render import clip_from_window, random_clip

import teachraster as tr
import teachraster.pipeline.hiz_tiles as hz
import teachraster.pipeline.render_triangles as rt
from teachraster.pipeline.scenes import SCENES, get_scene

W, H = 40, 32  # 5 x 4 whole 8x8 tiles


def render_without_hiz(clip, width, height, **kw):
    """The render with the Hi-Z hook switched off (what it would be without Hi-Z)."""
    with mock.patch.object(rt, "HiZCut", lambda *a, **k: None):
        return tr.render(clip, width, height, **kw)


def always_planned():
    """Let the plan run Hi-Z however little it expects to save (small test images)."""
    return mock.patch.multiple(hz, MIN_SAVING=0, LINE_COST=0)


def assert_identical(a, b, msg=""):
    """Bit-identical ids, depth and attributes (``force="all"`` also forces perspective
    and every fragment's attributes, which may move them by an ulp: 1e-12 there)."""
    np.testing.assert_array_equal(a.triangle_id, b.triangle_id, err_msg=msg)
    np.testing.assert_array_equal(a.depth, b.depth, err_msg=msg)  # NaN in the same places
    if msg.endswith(" all"):
        np.testing.assert_allclose(a.attrs, b.attrs, rtol=0, atol=1e-12, err_msg=msg)
    else:
        np.testing.assert_array_equal(a.attrs, b.attrs, err_msg=msg)


def layers(z_values, width=W, height=H, inset=0.0):
    """Full-frame rectangles (two triangles each) at window depths ``z_values``, in order."""
    a, b = -inset, [width + inset, height + inset]
    quads = []
    for z in z_values:
        for xy in ([[a, a], [b[0], a], [a, b[1]]], [[b[0], a], b, [a, b[1]]]):
            quads.append(clip_from_window(xy, z, 1.0, width, height))
    return np.array(quads)


def scene_with_occluders(rng, n):
    """Random triangles with a big slanted occluder or two drawn among them."""
    clip = random_clip(rng, n)
    big = clip_from_window(
        [[-20, -10], [70, -5], [-5, 60]], rng.uniform(0.05, 0.6, 3), rng.uniform(0.5, 2, 3), W, H
    )
    parts = [clip[: n // 2], big[None], clip[n // 2 :]]
    if n % 2:
        parts.append(layers([rng.uniform(0.1, 0.9)])[:1])
    return np.concatenate(parts)


def all_ways(clip, width, height, **kw):
    """Planned, planned with Hi-Z always run, forced, everything forced, traced, off."""
    frames = {"planned": tr.render(clip, width, height, **kw)}
    with always_planned():
        frames["always"] = tr.render(clip, width, height, **kw)
        frames["traced"] = tr.render(clip, width, height, trace=True, **kw)
    frames["forced"] = tr.render(clip, width, height, force="hi_z", **kw)
    frames["all"] = tr.render(clip, width, height, force="all", **kw)
    frames["off"] = render_without_hiz(clip, width, height, **kw)
    return frames


def check_rejections_hidden(frame):
    """Every fragment Hi-Z rejects is strictly farther than the final buffer at its pixel."""
    t = frame.trace
    rejected = t.hiz_tiles.fragment_rejected
    assert rejected.shape == t.fragment_row.shape
    final = frame.depth[t.fragment_row, t.fragment_col]
    assert (t.fragment_depth[rejected] > final[rejected]).all()
    # and the buffer ends no farther than each tile's bound
    tile = t.hiz_tiles.tile
    bound = np.repeat(np.repeat(t.hiz_tiles.farthest, tile, 0), tile, 1)[: frame.depth.shape[0]]
    bound = bound[:, : frame.depth.shape[1]]
    finite = np.isfinite(bound)
    assert (frame.depth[finite] <= bound[finite]).all()
    return int(rejected.sum())


def check_counts(frames):
    always, traced, forced = frames["always"], frames["traced"], frames["forced"]
    r = traced.trace.hiz_tiles
    assert r.rejected == int(r.fragment_rejected.sum()) == always.plan["hi_z"].count
    assert r.fragments == len(traced.trace.fragment_row) == always.plan["hi_z"].total
    assert r.interpolated + r.rejected == r.fragments
    assert forced.plan["hi_z"].count == always.plan["hi_z"].count  # planned == forced
    assert forced.plan["hi_z"].forced and forced.plan["hi_z"].ran
    for f in frames.values():  # the plan's totals count every fragment, dropped or not
        if f.plan["attributes"].ran:
            assert f.plan["attributes"].total == r.fragments
    for name in ("always", "forced", "all"):  # the depth test: only over what Hi-Z kept
        assert frames[name].plan["depth_test"].count == traced.plan["depth_test"].count
    assert always.plan["depth_test"].count <= frames["off"].plan["depth_test"].count


@pytest.mark.parametrize("name", list(SCENES))
@pytest.mark.parametrize("size", [(80, 60), (160, 120)])
def test_builtin_scenes_identical_with_and_without_hiz(name, size):
    scene = get_scene(name)
    width, height = size
    clip = scene.clip(width / height)
    blocks = [scene.mesh.corner(a) for a in sorted(scene.mesh.attrs)]
    attrs = np.concatenate([b[..., None] if b.ndim == 2 else b for b in blocks], axis=2)
    for kw in ({}, {"depth_format": "unorm16"}, {"cull": "back"}):
        frames = all_ways(clip, width, height, attrs=attrs, **kw)
        for key, frame in frames.items():
            assert_identical(frames["off"], frame, f"{name} {kw} {key}")
        check_counts(frames)
        check_rejections_hidden(frames["traced"])
    # through the scene front end too (shading, texture filters)
    planned = tr.render(scene, None, width, height)
    every = tr.render(scene, None, width, height, force="all")
    np.testing.assert_array_equal(planned.triangle_id, every.triangle_id)


def test_random_scenes_identical_and_rejections_hidden(rng):
    rejected = 0
    for index in range(60):
        clip = scene_with_occluders(rng, int(rng.integers(2, 9)))
        attrs = rng.uniform(-1, 1, (len(clip), 3, 2))
        kw = [{}, {"depth_format": "unorm16"}, {"depth_format": "float32"}][index % 3]
        frames = all_ways(clip, W, H, attrs=attrs, **kw)
        for key, frame in frames.items():
            assert_identical(frames["off"], frame, f"scene {index} {kw} {key}")
        check_counts(frames)
        rejected += check_rejections_hidden(frames["traced"])
    assert rejected > 500  # the checks saw real rejections


@settings(max_examples=examples(40), deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    n=st.integers(1, 7),
    fmt=st.sampled_from(["float64", "float32", "unorm16"]),
)
def test_hypothesis_hiz_never_changes_the_frame(seed, n, fmt):
    rng = np.random.default_rng(seed)
    clip = scene_with_occluders(rng, n)
    with always_planned():
        planned = tr.render(clip, W, H, depth_format=fmt, trace=True)
    assert_identical(render_without_hiz(clip, W, H, depth_format=fmt), planned)
    check_rejections_hidden(planned)
    forced = tr.render(clip, W, H, depth_format=fmt, force="hi_z", trace=True)
    np.testing.assert_array_equal(
        planned.trace.hiz_tiles.fragment_rejected, forced.trace.hiz_tiles.fragment_rejected
    )


def test_ties_are_kept():
    """Two identical occluders at one depth: neither is strictly farther, none rejected;
    a copy one float step farther is rejected wherever the first covers a whole tile."""
    z = 0.4
    with always_planned():
        frame = tr.render(layers([z, z]), W, H, trace=True)
    assert frame.plan["hi_z"].count == 0 and (frame.triangle_id <= 1).all()
    farther = layers([z, np.nextafter(z, 1)])
    with always_planned():
        frame = tr.render(farther, W, H, trace=True)
    t = frame.trace
    rejected = t.hiz_tiles.fragment_rejected
    assert rejected.sum() == frame.plan["hi_z"].count > W * H // 2
    assert (t.fragment_triangle[rejected] >= 2).all() and (frame.triangle_id <= 1).all()
    # in unorm16 the step is lost: the two store equal depths, nothing is rejected
    with always_planned():
        frame = tr.render(farther, W, H, depth_format="unorm16")
    assert frame.plan["hi_z"].count == 0


def test_occluders_are_the_tiled_walks_accepted_blocks(rng):
    for _ in range(40):
        clip = random_clip(rng, 1, spread=2.5)
        frame = tr.render(clip, W, H, trace=True, force="hi_z")
        win = frame.trace.window[0]
        fill = tr.rasterize(tr.Triangle(win[:, :2]), W, H, method="tiled", block_sizes=(8,),
                            trace=True)  # fmt: skip
        b = fill.trace.blocks
        accepted = np.zeros((H // 8 + 1, W // 8 + 1), dtype=np.int64)
        whole = (b.row + 8 <= H) & (b.col + 8 <= W) & (b.size == 8) & (b.kind == "accepted")
        accepted[b.row[whole] // 8, b.col[whole] // 8] = 1
        occ = frame.trace.hiz_tiles.occluders
        np.testing.assert_array_equal(occ, accepted[: occ.shape[0], : occ.shape[1]])


def test_farthest_is_the_nearest_occluders_largest_depth():
    """Brute force: per tile, the smallest over occluders of their largest stored depth."""
    clip = np.concatenate([layers([0.3])[:1], layers([0.5], inset=4)])
    clip[0, :, 2] = clip[0, :, 3] * np.array([-0.8, 0.2, 0.6])  # a slanted occluder
    frame = tr.render(clip, W, H, trace=True, force="hi_z")
    t = frame.trace
    r = t.hiz_tiles
    for i in range(H // 8):
        for j in range(W // 8):
            best = np.inf
            for tri in np.unique(t.fragment_triangle):
                mine = t.fragment_triangle == tri
                inside = mine & (t.fragment_row // 8 == i) & (t.fragment_col // 8 == j)
                if inside.sum() == 64:
                    best = min(best, t.fragment_depth[inside].max())
            assert r.farthest[i, j] == best


def test_stacked_layers_reject_all_but_the_nearest():
    size = 256
    clip = layers([0.5, 0.2, 0.9, 0.7], size, size)
    frame = tr.render(clip, size, size, trace=True)
    effect, r = frame.plan["hi_z"], frame.trace.hiz_tiles
    # every tile off the rectangles' diagonals is covered whole by all four layers
    assert effect.ran and effect.count == r.layered and effect.total == 4 * size * size
    assert effect.count == 3 * r.occluded_pixels > 0.9 * 3 * size * size
    assert (frame.trace.fragment_triangle[r.fragment_rejected] // 2 != 1).all()
    assert "dropped before their depth was interpolated" in effect.why
    assert (frame.triangle_id // 2 == 1).all()
    # the depth test is left only the diagonal tiles
    diagonal = 4 * size * size - r.occluded_pixels * 4
    assert frame.plan["depth_test"].count <= diagonal
    assert_identical(render_without_hiz(clip, size, size), frame)
    # the plan ran Hi-Z by itself here: forced, it rejects exactly the same fragments
    forced = tr.render(clip, size, size, trace=True, force="hi_z")
    np.testing.assert_array_equal(
        forced.trace.hiz_tiles.fragment_rejected, frame.trace.hiz_tiles.fragment_rejected
    )
    untraced = tr.render(clip, size, size)  # recording changes neither frame nor plan
    assert_identical(untraced, frame)
    assert str(untraced.plan) == str(frame.plan)
    attrs = np.ones((len(clip), 3, 2))
    for force in ("all", "attributes"):
        a = tr.render(clip, size, size, attrs=attrs, force=force)
        b = tr.render(clip, size, size, attrs=attrs, force=force, trace=True)
        assert str(a.plan) == str(b.plan)


def test_plan_words():
    small = clip_from_window([[[2, 2], [9, 3], [4, 9]], [[3, 2], [9, 4], [4, 8]]], 0.5, 1.0, W, H)
    effect = tr.render(small, W, H).plan["hi_z"]
    assert not effect.ran and "could not pay" in effect.why  # a few fragments: not worth it
    with always_planned():
        effect = tr.render(small, W, H).plan["hi_z"]
    assert not effect.ran and "no triangle covers a whole 8x8 tile" in effect.why
    effect = tr.render(layers([0.5, 0.6]), W, H).plan["hi_z"]
    assert not effect.ran and "could not pay" in effect.why
    with mock.patch.object(hz, "MIN_SAVING", 0):  # long lines, but only 2 layers
        effect = tr.render(layers([0.5, 0.6]), W, H).plan["hi_z"]
    assert not effect.ran and "too few" in effect.why
    with always_planned():
        effect = tr.render(layers([0.5]), W, H).plan["hi_z"]
    assert not effect.ran and "lone triangle" in effect.why
    with always_planned():
        count = tr.render(layers([0.5, 0.6]), W, H).plan["hi_z"].count
    assert count > W * H // 2
    off = tr.render(layers([0.5, 0.6]), W, H, depth_test=False, trace=True)
    assert not off.plan["hi_z"].ran and "off" in off.plan["hi_z"].why
    assert off.trace.hiz_tiles is None
    forced = tr.render(layers([0.5, 0.6]), W, H, force="hi_z").plan["hi_z"]
    assert forced.forced and forced.count == count and "every raster line" in forced.why
