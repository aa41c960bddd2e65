"""The render plan: simulate only what a scene needs, and say so — without changing a pixel.

The key property (issue 3): the planned render equals the everything-on render
(``force="all"``): identical triangle ids, attributes and depth within 1e-12, on every built-in
scene and on hundreds of random ones; forcing any single effect changes nothing either. The
counts the plan reports are checked against numbers computed here independently.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import cases
from test_render import H, W, clip_from_window, random_clip, reference_fill

import teachraster as tr
from teachraster.pipeline.render_plan import FORCEABLE, Effect, Plan, parse_force
from teachraster.pipeline.scenes import SCENES, get_scene

EFFECTS = (
    "clipping",
    "culling",
    "depth_test",
    "hi_z",
    "perspective",
    "attributes",
    "derivatives",
)


def assert_same_render(a, b, msg=""):
    """Identical triangle ids; attrs and depth within 1e-12 (NaN in the same places)."""
    np.testing.assert_array_equal(a.triangle_id, b.triangle_id, err_msg=msg)
    np.testing.assert_allclose(a.attrs, b.attrs, rtol=0, atol=1e-12, err_msg=msg)
    np.testing.assert_allclose(a.depth, b.depth, rtol=0, atol=1e-12, err_msg=msg)


def random_scene(rng, index):
    """A small random scene: overlapping, some equal-w, some crossing near/far, some ties."""
    n = int(rng.integers(1, 10))
    clip = random_clip(rng, n, equal_w=index % 3 == 0, cross=index % 2 == 1)
    if index % 5 == 0:  # an exact duplicate: a depth tie
        clip = np.concatenate([clip, clip[-1:]])
    if index % 7 == 0:  # a constant-depth layer pair (same w, the affine shortcut exact)
        clip = np.concatenate([clip, clip_from_window([[1, 1], [22, 2], [3, 16]], 0.4)[None]])
    attrs = rng.uniform(-1, 1, (len(clip), 3, int(rng.integers(0, 4))))
    kwargs = {}
    if index % 4 == 2:
        kwargs["cull"] = ("back", "front")[index % 8 == 2]
    if index % 6 == 1:
        kwargs["depth_format"] = "unorm16"
    if index % 9 == 4:
        kwargs["depth_test"] = False
    if index % 10 == 3:
        kwargs["interpolation"] = "affine"
    return clip, attrs, kwargs


# -- the key property --------------------------------------------------------------------------
#: How many of the effects each random scene forces alone (the others on other scenes): each
#: effect is forced alone on about 3/7 of the 300 scenes (~130), every scene is compared with
#: force='all' (CI time: all seven on every scene was 2,700 renders, 16 s of the full tier).
FORCED_PER_SCENE = 3


def test_planned_equals_everything_on_random_scenes(rng):
    """300 random scenes: planned == force='all' == each effect forced alone (three effects
    per scene, drawn from its own generator: each effect on ~130 scenes)."""
    clipped = perspective = tested = 0
    forced_on = dict.fromkeys(FORCEABLE, 0)
    for index in range(cases(300)):
        clip, attrs, kw = random_scene(rng, index)
        planned = tr.render(clip, W, H, attrs=attrs, **kw)
        msg = f"scene {index}: clip={clip.tolist()}, kwargs={kw}"
        assert_same_render(planned, tr.render(clip, W, H, attrs=attrs, force="all", **kw), msg)
        # the scene's own generator: the scenes stay those of the rng, whichever are forced
        chosen = np.random.default_rng([20240611, index]).permutation(len(FORCEABLE))
        for name in [FORCEABLE[i] for i in sorted(chosen[:FORCED_PER_SCENE])]:
            forced_on[name] += 1
            forced = tr.render(clip, W, H, attrs=attrs, force=name, **kw)
            assert_same_render(planned, forced, f"{msg}, force={name}")
            # forcing is meaningless (and not reported) for the divide of affine
            # interpolation and for the test of a render without depth test
            moot = (name == "perspective" and kw.get("interpolation") == "affine") or (
                name in ("depth_test", "hi_z") and kw.get("depth_test") is False
            )
            if name == "multisampling":  # one sample per pixel: no such effect to report
                assert name not in [e.name for e in forced.plan]
                continue
            assert forced.plan[name].forced != moot
        clipped += planned.plan["clipping"].ran
        perspective += planned.plan["perspective"].ran
        tested += planned.plan["depth_test"].ran
    # the scenes exercise every shortcut both ways (bounds for 300 scenes, scaled to those run)
    n, k = cases(300), cases(300) / 300
    assert min(forced_on.values()) > 100 * k, forced_on
    assert 50 * k < clipped < n - 50 * k and 50 * k < perspective < n - 50 * k
    assert 50 * k < tested < n - 10 * k


@pytest.mark.parametrize("name", list(SCENES))
def test_planned_equals_everything_on_builtin_scene(name):
    """Every built-in scene, through tr.render(scene, None, W, H) and as clip arrays."""
    scene = get_scene(name)
    width, height = 80, 60
    planned = tr.render(scene, None, width, height)
    every = tr.render(scene, None, width, height, force="all")
    np.testing.assert_array_equal(planned.triangle_id, every.triangle_id)
    np.testing.assert_allclose(planned.depth, every.depth, rtol=0, atol=1e-12)
    for used in scene.uses:
        np.testing.assert_allclose(planned.attr(used), every.attr(used), rtol=0, atol=1e-12)
    # the same scene as plain clip arrays with every mesh attribute
    clip = scene.clip(width / height)
    blocks = [scene.mesh.corner(a) for a in sorted(scene.mesh.attrs)]
    attrs = np.concatenate([b[..., None] if b.ndim == 2 else b for b in blocks], axis=2)
    a = tr.render(clip, width, height, attrs=attrs)
    assert_same_render(a, tr.render(clip, width, height, attrs=attrs, force="all"), name)
    np.testing.assert_array_equal(a.triangle_id, planned.triangle_id)
    for kw in ({"cull": "back"}, {"depth_format": "unorm16"}, {"depth_test": False}):
        b = tr.render(clip, width, height, attrs=attrs, **kw)
        assert_same_render(b, tr.render(clip, width, height, attrs=attrs, force="all", **kw))


# -- what the plan says --------------------------------------------------------------------------
def test_plan_lists_every_effect_with_a_reason(rng):
    """Effects come in pipeline order, each with a non-empty why and sane counts."""
    clip, attrs, _ = random_scene(rng, 1)
    frame = tr.render(clip, W, H, attrs=attrs)
    plan = frame.plan
    assert isinstance(plan, Plan)
    assert tuple(e.name for e in plan) == EFFECTS
    for effect in plan:
        assert isinstance(effect, Effect)
        assert effect.why.strip() and effect.unit
        assert 0 <= effect.count <= effect.total
        assert effect.ran == (effect.ran is True)
    text = str(plan)
    assert all(name in text for name in EFFECTS)
    with pytest.raises(KeyError, match="effects are"):
        plan["shadows"]


def test_plan_counts_match_independent_counts(rng):
    """On unclipped scenes: clipping 0 of N; depth test on the pixels that 2+ triangles
    cover (from per-triangle tr.rasterize) of all covered; perspective on the visible
    triangles with unequal w; attributes at the visible pixels of all fragments."""
    for index in range(40):
        n = int(rng.integers(1, 8))
        clip = random_clip(rng, n, equal_w=index % 2 == 0)
        if index % 4 == 1:  # some triangles with unequal w among equal ones
            clip = np.concatenate([clip, random_clip(rng, 2)])
        attrs = rng.uniform(0, 1, (len(clip), 3, 2))
        frame = tr.render(clip, W, H, attrs=attrs)
        plan = frame.plan
        cover = np.stack([reference_fill(c, None).coverage for c in clip]).sum(axis=0)
        covered, multi, fragments = int((cover > 0).sum()), int((cover > 1).sum()), int(cover.sum())
        visible = np.unique(frame.triangle_id[frame.coverage])
        unequal = int((~np.all(clip[visible, :, 3] == clip[visible, :1, 3], axis=1)).sum())
        got = {e.name: (e.ran, e.count, e.total) for e in plan}
        assert got["clipping"] == (False, 0, len(clip))
        assert got["culling"] == (False, 0, len(clip))
        assert got["depth_test"] == (multi > 0, multi, covered)
        assert got["perspective"] == (unequal > 0, unequal, len(clip))
        assert got["attributes"] == (True, covered, fragments)
        assert frame.coverage.sum() == covered


def test_clipping_plan_counts_crossing_triangles():
    """Clipping runs for exactly the triangles that cross near or far, and says why."""
    inside = clip_from_window([[2, 2], [20, 3], [4, 15]], 0.5, 2.0)
    crossing = inside.copy()
    crossing[0, 2] = -1.5 * crossing[0, 3]  # one vertex in front of the near plane
    hidden = inside * [1, 1, 1, -1]
    plan = tr.render(np.stack([inside, crossing, crossing, hidden]), W, H).plan["clipping"]
    assert plan.ran and (plan.count, plan.total) == (2, 4)
    assert "2 triangle" in plan.why and "dropped" in plan.why
    quiet = tr.render(inside[None], W, H).plan["clipping"]
    assert not quiet.ran and quiet.count == 0 and "nothing to clip" in quiet.why


def test_equal_w_reports_perspective_skipped(rng):
    """Equal w at every triangle's vertices: perspective correction is skipped, and says why;
    forcing it gives the same values (affine is exact there)."""
    clip = random_clip(rng, 6, equal_w=True)
    attrs = rng.uniform(0, 1, (6, 3, 3))
    frame = tr.render(clip, W, H, attrs=attrs)
    effect = frame.plan["perspective"]
    assert not effect.ran and effect.count == 0 and "equal" in effect.why
    forced = tr.render(clip, W, H, attrs=attrs, force="perspective")
    assert forced.plan["perspective"].ran and forced.plan["perspective"].forced
    assert forced.plan["perspective"].count == 6
    assert_same_render(frame, forced)
    # a single unequal w switches it on for that triangle only
    clip[2, 0, :] *= 2.0  # same window position and depth, different w
    effect = tr.render(clip, W, H, attrs=attrs).plan["perspective"]
    assert effect.ran and effect.count == 1


def test_affine_interpolation_reports_no_divide(rng):
    """interpolation='affine' runs no perspective divide, and the plan says so."""
    clip = random_clip(rng, 4)
    effect = tr.render(clip, W, H, attrs=np.ones((4, 3)), interpolation="affine").plan
    assert not effect["perspective"].ran and "affine" in effect["perspective"].why


def test_culling_and_depth_test_plan_entries():
    """Culling ran only when asked, counting the removed triangles; depth test off says so."""
    cw = clip_from_window([[2.0, 2.0], [20.0, 3.0], [4.0, 15.0]])
    clip = np.stack([cw, cw[[0, 2, 1]], cw])
    assert not tr.render(clip, W, H).plan["culling"].ran
    back = tr.render(clip, W, H, cull="back").plan["culling"]
    assert back.ran and (back.count, back.total) == (2, 3) and "back" in back.why
    front = tr.render(clip, W, H, cull="front").plan["culling"]
    assert front.ran and front.count == 1
    off = tr.render(clip, W, H, depth_test=False).plan["depth_test"]
    assert not off.ran and "off" in off.why


def test_no_attributes_reported():
    """Without attributes nothing is interpolated, and the plan says so."""
    plan = tr.render(clip_from_window([[[2, 2], [20, 3], [4, 15]]]), W, H).plan
    assert not plan["attributes"].ran and not plan["perspective"].ran
    assert "no attributes" in plan["attributes"].why


def test_force_all_marks_every_forceable_effect():
    """force='all' (and a list of names) marks the effects forced and ran."""
    clip = clip_from_window([[[2, 2], [20, 3], [4, 15]]])
    plan = tr.render(clip, W, H, attrs=np.ones((1, 3)), force="all").plan
    for name in FORCEABLE:
        if name == "multisampling":  # reported only with samples > 1
            continue
        assert plan[name].forced and plan[name].ran, name
    plan = tr.render(clip, W, H, attrs=np.ones((1, 3)), force="all", samples=4).plan
    # quad derivatives and Hi-Z are simulated with samples=1 only: a multisampled plan has none
    single_only = ("derivatives", "hi_z")
    assert all(
        plan[name].forced and plan[name].ran for name in FORCEABLE if name not in single_only
    )
    assert not plan["culling"].forced
    plan = tr.render(clip, W, H, attrs=np.ones((1, 3)), force=["clipping", "depth_test"]).plan
    assert [e.name for e in plan if e.forced] == ["clipping", "depth_test"]
    assert parse_force(None) == frozenset() and parse_force("all") == frozenset(FORCEABLE)


@pytest.mark.parametrize("force", ["everything", ["perspective", "shadows"], "culling"])
def test_unknown_force_raises_naming_force(force):
    """An unknown effect name raises ValueError whose message names ``force``."""
    clip = clip_from_window([[[2, 2], [20, 3], [4, 15]]])
    with pytest.raises(ValueError, match="force"):
        tr.render(clip, W, H, force=force)
    with pytest.raises(ValueError, match="force"):
        tr.render(get_scene("fan"), None, 16, 12, force=force)


# -- the plan of the built-in scenes -------------------------------------------------------------
def test_builtin_scene_plans():
    """What each teaching scene needs: flat scenes facing the camera need no perspective
    divide, the floor does; only behind_camera is clipped; a watertight fan needs no depth
    test, a cube does; normals are never interpolated."""
    plans = {name: tr.render(get_scene(name), None, 80, 60).plan for name in SCENES}
    for name in ("single_triangle", "fan"):
        p = plans[name]["perspective"]
        assert not p.ran and p.count == 0 and "equal" in p.why, name
    floor = plans["textured_floor"]["perspective"]
    assert floor.ran and floor.count == floor.total > 0
    assert [n for n in SCENES if plans[n]["clipping"].ran] == ["behind_camera"]
    assert not plans["fan"]["depth_test"].ran and not plans["grid"]["depth_test"].ran
    assert plans["cube"]["depth_test"].ran and plans["cyclic_overlap"]["depth_test"].ran
    assert not plans["grid"]["attributes"].ran  # flat shading uses no attribute
    assert "normal" in plans["uv_sphere"]["attributes"].why  # skipped, and said so


def test_plan_reports_only_what_really_ran():
    """A culled or off-screen triangle is not counted as perspective-corrected, a render
    without depth test reports no test even when forced, and a triangle trimmed only at the
    guard band is not said to cross the near or far plane."""
    back = [[-1, -1, 0, 1], [-1, 1, 0, 2], [1, -1, 0, 4]]  # w differs
    frame = tr.render([back], 8, 8, attrs=[[0, 1, 2]], cull="back")
    assert frame.coverage.sum() == 0 and not frame.plan["perspective"].ran
    assert frame.plan["perspective"].count == 0
    shown = tr.render([back], 8, 8, attrs=[[0, 1, 2]])
    assert shown.plan["perspective"].ran and shown.plan["perspective"].count == 1
    t = [[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]
    off = tr.render([t, t], 8, 8, depth_test=False, force="depth_test").plan["depth_test"]
    assert not off.ran and not off.forced and off.count == 0
    wide = tr.render([[[-1e8, -1, 0, 1], [1e8, -1, 0, 1], [-1, 1, 0, 1]]], 8, 8).plan
    assert "nothing to clip" in wide["clipping"].why and "guard band" in wide["clipping"].why


def test_multisampling_plan_says_shaded_once_per_pixel():
    """MSAA's plan says what the renderer does at a partly covered pixel: coverage, depth and
    colour per sample, one shading per triangle and pixel (per-sample shading would be
    supersampling). The attributes stored at the covered samples of such a pixel are equal."""
    clip = clip_from_window([[[1.3, 1.2], [14.7, 2.1], [3.1, 13.9]]], width=16, height=16)
    rgb = [[[1, 0, 0], [0, 1, 0], [0, 0, 1]]]
    frame = tr.render(clip, 16, 16, attrs=rgb, samples=4)
    why = frame.plan["multisampling"].why
    assert "shading per sample" not in why and "once per triangle and pixel" in why
    assert "colour stored per sample" in why
    sc = frame.sample_triangle_id >= 0
    partial = np.argwhere((sc.sum(axis=2) >= 2) & ~sc.all(axis=2))
    assert len(partial) > 0
    for i, j in partial:
        covered = frame.sample_attrs[i, j][sc[i, j]]
        assert np.array_equal(covered, np.broadcast_to(covered[0], covered.shape))
