"""The in-order replay of early-z and Hi-Z in ``render(..., trace=True)``
(``RenderTrace.hiz``, what a GPU drawing in order would save): sound (only hidden fragments
rejected), exact against a sequential z-buffer replayed here, the same rejections whether
every block or only the contested ones are compared. The renderer's own Hi-Z is tested in
tests/test_hiz_tiles.py."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from test_render import H, W, clip_from_window, random_clip

import teachraster as tr
from teachraster.pipeline.batched_fill import rasterize_batch
from teachraster.pipeline.depth import quantize
from teachraster.pipeline.hierarchical_z import HIZ_TILE, replay_stage
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
        frame = tr.render(clip, W, H, trace=True, **kw)
        check_frame(frame, W, H)
        rejected += frame.trace.hiz.counts["hiz_rejected"]
    assert rejected > 100  # the check saw real rejections


def test_layered_scene_rejects_the_hidden_blocks():
    frame = tr.render(layered_clip(), W, H, trace=True)
    hiz = frame.trace.hiz
    c = hiz.counts
    assert c["hiz_rejected"] > 0
    # the far triangles are hidden everywhere; whole tiles of them never get a depth
    assert c["shaded"] == (frame.triangle_id == 0).sum() == W * H
    assert c["hiz_rejected"] + c["early_z_killed"] == c["fragments"] - W * H
    check_frame(frame, W, H)
    # drawn back to front nothing is hidden on arrival: the replay rejects nothing
    back = tr.render(layered_clip()[::-1], W, H, trace=True)
    assert back.trace.hiz.counts["hiz_rejected"] == 0
    # the renderer's own Hi-Z does not depend on the order (forced: the image is small)
    ours = [tr.render(c, W, H, force="hi_z").plan["hi_z"].count
            for c in (layered_clip(), layered_clip()[::-1])]  # fmt: skip
    assert ours[0] == ours[1] > 0


def test_block_nearest_is_the_minimum_over_the_tile():
    """The corner trick on the depth plane: the 4 corners give the exact minimum."""
    frame = tr.render(layered_clip(), W, H, trace=True)
    hiz = frame.trace.hiz
    win = frame.trace.window
    frags = rasterize_batch(win[:, :, :2], W, H, snapped_weights=False)
    assert hiz.block_tested.any()
    for b in np.flatnonzero(hiz.block_tested):
        r0, c0 = int(hiz.block_row[b]), int(hiz.block_col[b])
        rr, cc = np.mgrid[r0 : min(r0 + HIZ_TILE, H), c0 : min(c0 + HIZ_TILE, W)]
        probe = dataclasses.replace(
            frags, tri=np.full(rr.size, hiz.block_triangle[b]), row=rr.ravel(), col=cc.ravel()
        )
        every = quantize(probe.plane(win[:, :, 2]), "float64")
        assert hiz.block_nearest[b] == every.min()


def replays(clip, width, height, **kw):
    """The replay as ``render`` runs it, and the same comparing every block."""
    from teachraster.pipeline.stages import depth_stage

    frame = tr.render(clip, width, height, trace=True, **kw)
    win = frame.trace.window
    frags = rasterize_batch(win[:, :, :2], width, height, snapped_weights=False)
    fmt = kw.get("depth_format", "float64")
    visible, _ = depth_stage(frags, win, width, height, True, fmt, frozenset())
    every = replay_stage(frags, win, visible, width, height, fmt, test_all=True)
    return frame, every


def test_comparing_every_block_rejects_the_same(rng):
    for index in range(80):
        clip = random_clip(rng, int(rng.integers(1, 9)))
        if index % 3 == 0:
            clip = np.concatenate([layered_clip()[:1], clip])
        frame, every = replays(clip, W, H)
        a = frame.trace.hiz
        np.testing.assert_array_equal(a.fragment_rejected, every.fragment_rejected)
        np.testing.assert_array_equal(a.fragment_passed, every.fragment_passed)
        assert a.block_tested.sum() <= every.block_tested.sum() == len(every.block_tested)


def test_no_replay_without_depth_test():
    off = tr.render(layered_clip(), W, H, depth_test=False, trace=True)
    assert not off.plan["hi_z"].ran and "off" in off.plan["hi_z"].why
    assert off.trace.hiz is None
    assert not tr.render(layered_clip(), W, H, depth_test=False, force="hi_z").plan["hi_z"].forced
    assert tr.render(layered_clip(), W, H).trace is None  # nothing replayed unless traced


@pytest.mark.parametrize("name", list(SCENES))
def test_builtin_scenes_replay(name):
    scene = get_scene(name)
    clip = scene.clip(80 / 60)
    frame, every = replays(clip, 80, 60)
    if frame.trace.hiz is not None:
        c = frame.trace.hiz.counts
        assert c["shaded"] == frame.trace.fragment_passed.sum()
        np.testing.assert_array_equal(frame.trace.hiz.fragment_rejected, every.fragment_rejected)


def test_replay_tiles_other_tile_sizes_are_exact_and_8_is_the_trace():
    """Review r264 M2 (lesson 10 measures the tile size): ``replay_tiles`` replays a traced
    frame with other tiles. At 8 it is the trace's own replay; at 4 and 16 it rejects only
    fragments the sequential z-buffer fails, and every block it compares against the tile's
    farthest depth as that z-buffer had it; it refuses a frame without a one-sample trace."""
    from teachraster.pipeline.visibility.hierarchical_z import replay_tiles

    clip = get_scene("uv_sphere").clip(W / H)
    frame = tr.render(clip, W, H, trace=True)
    same = replay_tiles(frame.trace, HIZ_TILE)
    assert np.array_equal(same.block_rejected, frame.trace.hiz.block_rejected)
    assert same.counts == frame.trace.hiz.counts
    for tile in (4, 16):
        hiz = replay_tiles(frame.trace, tile)
        assert hiz.tile == tile and hiz.counts["fragments"] == same.counts["fragments"]
        passed, farthest = replay(frame, W, H, tile)
        np.testing.assert_array_equal(hiz.fragment_passed, passed)
        assert not (hiz.fragment_rejected & passed).any()
        for b in np.flatnonzero(hiz.block_rejected):
            key = (int(hiz.block_triangle[b]), int(hiz.block_row[b]) // tile,
                   int(hiz.block_col[b]) // tile)  # fmt: skip
            assert hiz.block_nearest[b] >= farthest[key]
    with pytest.raises(ValueError, match="one-sample"):
        replay_tiles(tr.render(clip, W, H, trace=True, depth_test=False).trace, 4)
