"""Blending: the blend equation, sRGB, and ``render(..., blend=)`` in submission order, with
depth writes off for transparent geometry, per sample under MSAA, and its plan entry."""

from __future__ import annotations

import numpy as np
import pytest

import teachraster as tr
from teachraster.pipeline.visibility.zbuffer import passed_on_arrival

RED, BLUE = [1.0, 0.0, 0.0, 0.5], [0.0, 0.0, 1.0, 0.5]


def quad(x0, y0, x1, y1, z=0.0):
    """Two clip-space triangles covering the NDC rectangle, at depth z."""
    a, b, c, d = [x0, y0, z, 1], [x1, y0, z, 1], [x1, y1, z, 1], [x0, y1, z, 1]
    return np.array([[a, b, c], [a, c, d]], dtype=float)


def coloured(rgba):
    return np.broadcast_to(np.asarray(rgba, float), (2, 3, 4))


def test_blend_equation_named_pairs():
    src, dst = np.array([0.2, 0.4, 0.6, 0.25]), np.array([0.5, 0.5, 0.5, 1.0])
    np.testing.assert_allclose(tr.blend_equation(src, dst), src * 0.25 + dst * 0.75)
    np.testing.assert_allclose(
        tr.blend_equation(src, dst, "ONE", "ONE_MINUS_SRC_ALPHA"), src + dst * 0.75
    )
    np.testing.assert_allclose(tr.blend_equation(src, dst, "ONE", "ONE"), src + dst)
    np.testing.assert_allclose(tr.blend_equation(src, dst, "DST_COLOR", "ZERO"), src * dst)
    np.testing.assert_allclose(
        tr.blend_equation(src, dst, "ONE", "ONE", "FUNC_REVERSE_SUBTRACT"), dst - src
    )
    np.testing.assert_allclose(tr.blend_equation(src, dst, equation="MAX"), np.maximum(src, dst))


def test_premultiplied_over_equals_straight_over_after_premultiplying():
    rng = np.random.default_rng(0)
    src, dst = rng.uniform(0, 1, (50, 4)), rng.uniform(0, 1, (50, 4))
    straight = tr.blend_equation(src, dst)
    pre = src.copy()
    pre[:, :3] *= src[:, 3:]
    premult = tr.blend_equation(pre, dst, "ONE", "ONE_MINUS_SRC_ALPHA")
    np.testing.assert_allclose(premult[:, :3], straight[:, :3])
    # alpha differs: straight "over" multiplies alpha by itself (a² + ...), premultiplied is
    # the Porter-Duff a + (1 - a) b
    np.testing.assert_allclose(premult[:, 3], src[:, 3] + (1 - src[:, 3]) * dst[:, 3])


def test_srgb_round_trip_and_exact_curve():
    x = np.linspace(0, 1, 1001)
    np.testing.assert_allclose(tr.linear_to_srgb(tr.srgb_to_linear(x)), x, atol=1e-12)
    assert tr.srgb_to_linear(0.04045) == pytest.approx(0.04045 / 12.92)
    assert tr.linear_to_srgb(0.5) == pytest.approx(0.7353569830524495)


def test_blend_equation_bad_input():
    with pytest.raises(ValueError, match="src"):
        tr.blend_equation([1, 0, 0], [0, 0, 0, 0])
    with pytest.raises(ValueError, match="src_factor"):
        tr.blend_equation([1, 0, 0, 1], [0, 0, 0, 0], "SRC_ALPHA_SATURATE")
    with pytest.raises(ValueError, match="equation"):
        tr.blend_equation([1, 0, 0, 1], [0, 0, 0, 0], equation="ADD")


def test_order_dependence():
    red_quad, blue_quad = quad(-1, -1, 0.5, 0.5), quad(-0.5, -0.5, 1, 1)
    clip_a, clip_b = np.concatenate([red_quad, blue_quad]), np.concatenate([blue_quad, red_quad])
    a = np.concatenate([coloured(RED), coloured(BLUE)])
    b = np.concatenate([coloured(BLUE), coloured(RED)])
    red_first = tr.render(clip_a, 8, 8, attrs=a, blend="over", depth_write=False).color
    blue_first = tr.render(clip_b, 8, 8, attrs=b, blend="over", depth_write=False).color
    both = (red_first != blue_first).any(axis=2)
    assert both.sum() == 16  # the 4 × 4 overlap
    # red then blue: blue on top, 0.5·(0, 0, 1) + 0.5·(0.5, 0, 0) = (0.25, 0, 0.5)
    np.testing.assert_allclose(red_first[3, 3, :3], [0.25, 0.0, 0.5])
    np.testing.assert_allclose(blue_first[3, 3, :3], [0.5, 0.0, 0.25])
    # additive blending commutes
    add_a = tr.render(clip_a, 8, 8, attrs=a, blend="additive", depth_write=False).color
    add_b = tr.render(clip_b, 8, 8, attrs=b, blend="additive", depth_write=False).color
    np.testing.assert_allclose(add_a, add_b)


def test_opaque_first_then_transparent_without_depth_writes():
    near_glass = quad(-1, -1, 1, 1, z=-0.5)
    wall = quad(-1, -1, 1, 1, z=0.0)
    far_glass = quad(-1, -1, 1, 1, z=0.5)
    clip = np.concatenate([wall, near_glass, far_glass])
    attrs = np.concatenate([coloured([0, 1, 0, 1]), coloured(RED), coloured(BLUE)])
    frame = tr.render(clip, 4, 4, attrs=attrs, blend="over",
                      depth_write=np.array([True, True, False, False, False, False]))  # fmt: skip
    # far glass is behind the wall: hidden; near glass blends over the wall
    np.testing.assert_allclose(frame.color[0, 0], [0.5, 0.5, 0.0, 0.75])
    # with depth writes on, the near glass would also hide the far one: the same here
    everything = tr.render(clip, 4, 4, attrs=attrs, blend="over")
    np.testing.assert_allclose(everything.color, frame.color)


def test_depth_write_off_lets_later_glass_show():
    near, far = quad(-1, -1, 1, 1, z=-0.5), quad(-1, -1, 1, 1, z=0.5)
    clip = np.concatenate([near, far])  # near first: the classic unsorted mistake
    attrs = np.concatenate([coloured(RED), coloured(BLUE)])
    writes = tr.render(clip, 2, 2, attrs=attrs, blend="over").color
    no_writes = tr.render(clip, 2, 2, attrs=attrs, blend="over", depth_write=False).color
    np.testing.assert_allclose(writes[0, 0], [0.5, 0, 0, 0.25])  # far glass lost
    np.testing.assert_allclose(no_writes[0, 0], [0.25, 0, 0.5, 0.375])  # wrong order, shown


def test_passed_with_writes_matches_a_loop():
    rng = np.random.default_rng(4)
    pixel = rng.integers(0, 5, 200)
    depth = rng.integers(0, 10, 200) / 10
    writes = rng.uniform(size=200) < 0.5
    buffer, want = {}, []
    for p, d, w in zip(pixel, depth, writes):
        ok = d < buffer.get(p, np.inf)
        want.append(ok)
        if ok and w:
            buffer[p] = d
    assert passed_on_arrival(pixel, depth, writes).tolist() == want


def test_clear_color_and_uncovered_pixels():
    frame = tr.render(quad(-1, -1, 0, 0), 4, 4, attrs=coloured(RED), blend="over",
                      clear_color=(0.0, 0.0, 0.0, 1.0))  # fmt: skip
    np.testing.assert_allclose(frame.color[0, 0], [0, 0, 0, 1])
    np.testing.assert_allclose(frame.color[3, 0], [0.5, 0, 0, 0.75])


def test_plan_counts_blending_only_where_it_runs():
    clip = np.concatenate([quad(-1, -1, 0, 1), quad(0, -1, 1, 1)])  # side by side
    opaque = np.concatenate([coloured([1, 0, 0, 1]), coloured([0, 0, 1, 1])])
    frame = tr.render(clip, 4, 4, attrs=opaque, blend="over")
    effect = frame.plan["blending"]
    assert not effect.ran and effect.count == 0 and effect.total == 16
    assert "16 opaque" in effect.why
    glass = np.concatenate([coloured(RED), coloured(BLUE)])
    stacked = np.concatenate([quad(-1, -1, 1, 1), quad(-1, -1, 0, 1)])
    frame = tr.render(stacked, 4, 4, attrs=glass, blend="over", depth_write=False)
    effect = frame.plan["blending"]
    # all 24 are blended (16 onto the clear colour, 8 onto the red quad): the line's
    # "applied to" and its "blended" are the same number, the 8 said apart
    assert effect.ran and effect.count == 24 and effect.total == 24
    assert "applied to       24 of        24 fragments" in str(effect)
    assert "24 transparent fragments blended, 8 of them onto an earlier fragment" in effect.why


def test_msaa_blending_per_sample_then_resolve():
    tri = np.array([[[-1, -1, 0, 1], [1, -1, 0, 1], [-1, 1, 0, 1]]], float)
    attrs = np.broadcast_to(np.array([1.0, 1.0, 1.0, 0.5]), (1, 3, 4))
    frame = tr.render(tri, 4, 4, attrs=attrs, blend="over", samples=4)
    assert frame.sample_color.shape == (4, 4, 4, 4)
    np.testing.assert_allclose(frame.color, frame.sample_color.mean(axis=2))
    frac = frame.coverage_fraction
    np.testing.assert_allclose(frame.color[..., 0], 0.5 * frac)
    np.testing.assert_allclose(frame.color[..., 3], 0.25 * frac)


def test_without_rgba_attributes_there_is_no_colour_buffer():
    frame = tr.render(quad(-1, -1, 1, 1), 2, 2, attrs=coloured(RED)[..., :3])
    assert frame.color is None and frame.sample_color is None
    assert "blending" not in [e.name for e in frame.plan]


def test_bad_blend_arguments_name_themselves():
    clip, attrs = quad(-1, -1, 1, 1), coloured(RED)
    with pytest.raises(ValueError, match="blend"):
        tr.render(clip, 2, 2, attrs=attrs, blend="screen")
    with pytest.raises(ValueError, match="attrs"):
        tr.render(clip, 2, 2, attrs=attrs[..., :3], blend="over")
    with pytest.raises(ValueError, match="depth_write"):
        tr.render(clip, 2, 2, attrs=attrs, blend="over", depth_write=[True])
    with pytest.raises(ValueError, match="depth_write"):
        tr.render(clip, 2, 2, attrs=attrs, depth_write=np.array([1, 0]))
    with pytest.raises(ValueError, match="color_format"):
        tr.render(clip, 2, 2, attrs=attrs, color_format="rgba16f")
    with pytest.raises(ValueError, match="clear_color"):
        tr.render(clip, 2, 2, attrs=attrs, blend="over", clear_color=(0, 0, 0))
    frame = tr.render(clip, 2, 2, attrs=attrs, blend=("ONE", "ZERO"))
    np.testing.assert_allclose(frame.color[0, 0], RED)
