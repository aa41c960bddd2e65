"""Early-z and Hi-Z in ``render``: sound (only hidden fragments rejected), exact against a
sequential z-buffer replayed here, planned == forced, and the plan's counts."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from test_render import H, W, clip_from_window, random_clip

import teachraster as tr
from teachraster.pipeline.depth import quantize
from teachraster.pipeline.hierarchical_z import HIZ_TILE
from teachraster.pipeline.scenes import SCENES, get_scene


def replay(frame, width, height, tile=HIZ_TILE):
    """Sequential z-buffer in drawing order: passed-on-arrival per fragment and, per block
    (triangle, tile), the tile's largest buffer depth when the triangle arrived."""
    t = frame.trace
    buffer = np.full((height, width), np.inf)
    passed = np.zeros(len(t.fragment_row), dtype=bool)
    farthest = {}
    for tri in np.unique(t.fragment_triangle):
        mine = np.flatnonzero(t.fragment_triangle == tri)
        for r, c in {(int(r) // tile, int(c) // tile) for r, c in
                     zip(t.fragment_row[mine], t.fragment_col[mine])}:  # fmt: skip
            farthest[tri, r, c] = buffer[r * tile : (r + 1) * tile, c * tile : (c + 1) * tile].max()
        for f in mine:  # one fragment after the other, strictly nearer wins
            r, c, d = t.fragment_row[f], t.fragment_col[f], t.fragment_depth[f]
            if d < buffer[r, c]:
                buffer[r, c] = d
                passed[f] = True
    return passed, farthest


def layered_clip():
    """A near triangle over the whole frame drawn first, then far ones behind it."""
    near = clip_from_window([[-30, -30], [150, -30], [-30, 150]], z=0.2)
    far = [clip_from_window(xy, z=0.7) for xy in ([[1, 1], [22, 2], [3, 16]],
                                                   [[20, 1], [23, 17], [2, 17]])]  # fmt: skip
    return np.stack([near, *far])


def check_frame(frame, width, height):
    hiz = frame.trace.hiz
    t = frame.trace
    assert np.array_equal(t.parent, np.arange(len(t.parent)))  # unclipped: ids are indices
    passed, farthest = replay(frame, width, height)
    np.testing.assert_array_equal(hiz.fragment_passed, passed)
    rejected = hiz.fragment_rejected
    assert not (rejected & passed).any()  # Hi-Z only ever rejects hidden fragments
    for b in np.flatnonzero(hiz.block_tested):
        key = (int(hiz.block_triangle[b]), int(hiz.block_row[b]) // HIZ_TILE,
               int(hiz.block_col[b]) // HIZ_TILE)  # fmt: skip
        if not np.isnan(hiz.tile_farthest[b]):  # computed where the final bound allows
            assert hiz.tile_farthest[b] == farthest[key]
        frags = np.flatnonzero(hiz.fragment_block == b)
        assert hiz.block_nearest[b] <= t.fragment_depth[frags].min()
        assert hiz.block_rejected[b] == (hiz.block_nearest[b] >= farthest[key])
    c = hiz.counts
    assert c["interpolated"] + c["hiz_rejected"] == c["fragments"] == len(passed)
    assert c["shaded"] == passed.sum() and c["early_z_killed"] >= 0


def test_rejections_match_a_sequential_zbuffer(rng):
    rejected = 0
    for index in range(60):
        clip = random_clip(rng, int(rng.integers(2, 9)))
        if index % 3 == 0:  # something drawn in front first: Hi-Z has work to do
            clip = np.concatenate([layered_clip()[:1], clip])
        kw = {"depth_format": "unorm16"} if index % 4 == 1 else {}
        frame = tr.render(clip, W, H, trace=True, force="hi_z", **kw)
        check_frame(frame, W, H)
        rejected += frame.trace.hiz.counts["hiz_rejected"]
    assert rejected > 100  # the check saw real rejections


def test_layered_scene_rejects_the_hidden_blocks():
    frame = tr.render(layered_clip(), W, H, trace=True)
    hiz, effect = frame.trace.hiz, frame.plan["hi_z"]
    c = hiz.counts
    assert effect.ran and effect.count == c["hiz_rejected"] > 0
    # the far triangles are hidden everywhere; whole tiles of them never get a depth
    assert c["shaded"] == (frame.triangle_id == 0).sum() == W * H
    assert c["hiz_rejected"] + c["early_z_killed"] == c["fragments"] - W * H
    assert f"{c['hiz_rejected']:,} fragment(s) their depth" in effect.why
    check_frame(frame, W, H)
    # drawn back to front nothing is hidden on arrival: Hi-Z rejects nothing
    back = tr.render(layered_clip()[::-1], W, H, trace=True)
    assert back.trace.hiz.counts["hiz_rejected"] == 0 and back.plan["hi_z"].count == 0


def test_block_nearest_is_the_minimum_over_the_tile():
    """The corner trick on the depth plane: the 4 corners give the exact minimum."""
    frame = tr.render(layered_clip(), W, H, trace=True, force="hi_z")
    hiz = frame.trace.hiz
    from teachraster.pipeline.batched_fill import rasterize_batch

    win = frame.trace.window
    frags = rasterize_batch(win[:, :, :2], W, H, snapped_weights=False)
    for b in np.flatnonzero(hiz.block_tested):
        r0, c0 = int(hiz.block_row[b]), int(hiz.block_col[b])
        rr, cc = np.mgrid[r0 : min(r0 + HIZ_TILE, H), c0 : min(c0 + HIZ_TILE, W)]
        probe = dataclasses.replace(
            frags, tri=np.full(rr.size, hiz.block_triangle[b]), row=rr.ravel(), col=cc.ravel()
        )
        every = quantize(probe.plane(win[:, :, 2]), "float64")
        assert hiz.block_nearest[b] == every.min()


def test_planned_equals_forced(rng):
    for index in range(80):
        clip = random_clip(rng, int(rng.integers(1, 9)), cross=index % 2 == 1)
        if index % 3 == 0:
            clip = np.concatenate([layered_clip()[:1], clip])
        planned = tr.render(clip, W, H, trace=True)
        forced = tr.render(clip, W, H, trace=True, force="hi_z")
        np.testing.assert_array_equal(planned.triangle_id, forced.triangle_id)
        a, b = planned.trace.hiz, forced.trace.hiz
        np.testing.assert_array_equal(a.fragment_rejected, b.fragment_rejected)
        assert planned.plan["hi_z"].count == forced.plan["hi_z"].count
        assert forced.plan["hi_z"].forced and forced.plan["hi_z"].ran
        assert a.block_tested.sum() <= b.block_tested.sum() == len(b.block_tested)


def test_no_overlap_no_hiz_and_depth_test_off():
    one = clip_from_window([[[2, 2], [20, 3], [4, 15]]])
    plan = tr.render(one, W, H).plan
    assert not plan["hi_z"].ran and "depth complexity is one" in plan["hi_z"].why
    off = tr.render(layered_clip(), W, H, depth_test=False, trace=True)
    assert not off.plan["hi_z"].ran and "off" in off.plan["hi_z"].why
    assert off.trace.hiz is None
    assert not tr.render(layered_clip(), W, H, depth_test=False, force="hi_z").plan["hi_z"].forced


@pytest.mark.parametrize("name", list(SCENES))
def test_builtin_scenes_planned_equals_forced(name):
    scene = get_scene(name)
    clip = scene.clip(80 / 60)
    planned = tr.render(clip, 80, 60, trace=True)
    forced = tr.render(clip, 80, 60, trace=True, force="hi_z")
    np.testing.assert_array_equal(planned.triangle_id, forced.triangle_id)
    assert planned.plan["hi_z"].count == forced.plan["hi_z"].count
    if planned.trace.hiz is not None:
        c = planned.trace.hiz.counts
        assert c["shaded"] == planned.trace.fragment_passed.sum()
