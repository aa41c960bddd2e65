"""Stage overrides (issue 30's capstone): a caller's rules replace the package's, one place each.

The package's own rules written as plain per-element Python functions must give the package's
frame bit for bit (ids, depth, attributes, colour, shaded image), so the override path
changes nothing but who decides; a wrong rule must change the frame, and the trace and the
pixel history must tell the overridden story.
"""

from __future__ import annotations

import numpy as np
import pytest
from reasoning_solutions import (
    barycentric,
    bilinear,
    covers,
    depth_passes,
    over,
    perspective_weights,
    resolve,
    trilinear,
)

import teachraster as tr
from teachraster.pipeline.planning.overrides import StageOverrides, check_overrides

W, H = 24, 18


def _e(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def _same(a, b):
    return np.array_equal(a, b, equal_nan=True) or np.allclose(a, b, rtol=1e-12, atol=1e-12,
                                                                equal_nan=True)  # fmt: skip


@pytest.mark.parametrize(
    "scene, kwargs, rules",
    [
        ("fan", {}, {"coverage": covers}),
        ("cube", {}, {"coverage": covers, "weights": barycentric,
                      "perspective": perspective_weights, "depth": depth_passes}),
        ("intersecting_triangles", {"depth_format": "unorm16"}, {"depth": depth_passes}),
        ("textured_floor", {"texture_filter": "bilinear"}, {"bilinear": bilinear}),
        ("textured_floor", {"texture_filter": "trilinear"}, {"trilinear": trilinear}),
        ("cube", {"samples": 4}, {"resolve": resolve}),
    ],
)  # fmt: skip
def test_the_packages_rules_written_out_give_the_packages_frame(scene, kwargs, rules):
    s = tr.get_scene(scene)
    ref = tr.render(s, None, W, H, trace=True, **kwargs)
    mine = tr.render(s, None, W, H, trace=True, overrides=rules, **kwargs)
    assert np.array_equal(mine.triangle_id, ref.triangle_id)
    assert _same(mine.depth, ref.depth) and _same(mine.attrs, ref.attrs)
    assert _same(mine.image, ref.image)


def _glass():
    s = tr.get_scene("intersecting_triangles")
    clip = s.clip(W / H)
    rgba = np.concatenate([s.mesh.corner("color"), np.full((len(clip), 3, 1), 0.7)], axis=2)
    return clip, dict(attrs=rgba, blend="over", depth_write=False, clear_color=(1, 1, 1, 1),
                      trace=True)  # fmt: skip


def test_a_blend_rule_reaches_the_colour_buffer_and_the_historys_replay():
    clip, kw = _glass()
    ref = tr.render(clip, W, H, **kw)
    same = tr.render(clip, W, H, overrides={"blend": over, "depth": depth_passes}, **kw)
    assert _same(same.color, ref.color)
    swapped = tr.render(clip, W, H, overrides={"blend": lambda s, d: d * s[3] + s * (1 - s[3])},
                        **kw)  # fmt: skip
    row, col = np.argwhere(ref.overlay("overdraw") == 2)[0]
    assert not np.allclose(swapped.color[row, col], ref.color[row, col])
    h = swapped.history(row, col)
    assert np.array_equal(h.replay_color()[0], swapped.color[row, col])


def test_a_wrong_coverage_rule_changes_the_fragments_and_the_history_says_so():
    square = np.array([[2.5, 2.5], [10.5, 2.5], [10.5, 10.5], [2.5, 10.5]])  # centres
    xy = square[[[0, 1, 2], [0, 2, 3]]]  # split along the diagonal through centres
    fan = np.concatenate([2 * xy / [W, H] - 1, np.zeros((2, 3, 1)), np.ones((2, 3, 1))], axis=2)
    fan[..., 1] *= -1
    ref = tr.render(fan, W, H, trace=True)

    def inclusive(xy, p):  # E >= 0 on every edge: centres on shared edges covered twice
        on_edge = any(_e(xy[k], xy[(k + 1) % 3], p) == 0 for k in range(3))
        return covers(xy, p) or (on_edge and _inside_closed(xy, p))

    mine = tr.render(fan, W, H, trace=True, overrides={"coverage": inclusive})
    twice = np.argwhere(mine.overlay("overdraw") > ref.overlay("overdraw"))
    assert len(twice)
    row, col = twice[0]
    mine_h, ref_h = mine.history(row, col), ref.history(row, col)
    assert mine_h.outcomes.count("not_covered") < ref_h.outcomes.count("not_covered")
    assert mine.trace.hiz_tiles is None  # Hi-Z decides by the package's coverage: off


def _inside_closed(xy, p):
    e = [_e(xy[k], xy[(k + 1) % 3], p) for k in range(3)]
    return all(v >= 0 for v in e) or all(v <= 0 for v in e)


def test_a_wrong_depth_rule_decides_the_frame_and_its_trace():
    s = tr.get_scene("intersecting_triangles")
    ref = tr.render(s, None, W, H, trace=True)
    farthest = lambda depths, writes: [d >= max(depths[: i + 1]) for i, d in enumerate(depths)]  # noqa: E731
    mine = tr.render(s, None, W, H, trace=True, overrides={"depth": farthest})
    assert mine.trace.hiz is None  # no package early-z to replay
    changed = np.argwhere(mine.triangle_id != ref.triangle_id)
    assert len(changed)
    row, col = changed[0]
    h = mine.history(row, col)
    assert h.replay()[0][0] == mine.triangle_id[row, col]
    shown = next(r for r in h.records if r.shown)
    assert shown.depth > min(r.depth for r in h.records if np.isfinite(r.depth))


def test_interpolation_rules_reach_the_frame_and_the_history():
    s = tr.get_scene("textured_floor")
    ref = tr.render(s, None, W, H, trace=True)
    affine = tr.render(s, None, W, H, trace=True, overrides={"perspective": lambda lam, w: lam})
    assert not _same(affine.attrs, ref.attrs)
    row, col = np.argwhere(~np.isclose(affine.attrs, ref.attrs, equal_nan=True).all(axis=2))[0]
    shown = next(r for r in affine.history(row, col).records if r.shown)
    assert np.allclose(shown.value, affine.attrs[row, col])


def test_overrides_are_checked_and_name_what_is_wrong():
    s = tr.get_scene("fan")
    assert check_overrides(None) is None and check_overrides({"coverage": None}) is None
    assert check_overrides(StageOverrides(depth=depth_passes)).given == ("depth",)
    with pytest.raises(ValueError, match="unknown rule 'covers'"):
        tr.render(s, None, W, H, overrides={"covers": covers})
    with pytest.raises(TypeError, match="coverage must be a function"):
        tr.render(s, None, W, H, overrides={"coverage": True})
    with pytest.raises(TypeError, match="overrides must be"):
        tr.render(s, None, W, H, overrides=[covers])
    with pytest.raises(ValueError, match="samples=1"):
        tr.render(s, None, W, H, samples=4, overrides={"coverage": covers})
    clip, kw = _glass()
    with pytest.raises(ValueError, match="give blend= a mode"):
        tr.render(clip, W, H, attrs=kw["attrs"], overrides={"blend": over})
    with pytest.raises(ValueError, match="the weights rule must return 3 weights"):
        tr.render(tr.get_scene("cube"), None, W, H, overrides={"weights": lambda xy, p: 1.0})
    with pytest.raises(ValueError, match="one truth value per fragment"):
        tr.render(tr.get_scene("cube"), None, W, H, overrides={"depth": lambda d, w: True})
