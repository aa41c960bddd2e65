"""Blending against a real GPU: the same scenes and blend state through Mesa's llvmpipe
(moderngl + EGL). RGBA32F colour buffer: within 1e-6 (relative above 1), blending on or off,
per-triangle depth masks (glDepthMask) and 4x MSAA included; the ids and depth buffer under
glDepthMask(GL_FALSE) exactly. SRGB8_ALPHA8 with GL_FRAMEBUFFER_SRGB against
``color_format="srgb8"``: one layer within one 8-bit step; more layers within the bounds
measured here, since llvmpipe's sRGB conversions are approximations (decoding codes below 16
as c / 12.6, encoding within 0.64 of a step) whose errors each rounded layer reads back.
Skipped, with the reason, without OpenGL."""

from __future__ import annotations

import numpy as np
import pytest
from gl_required import require_gl

require_gl()

import teachraster as tr
from teachraster.study.opengl import gl_render
from teachraster.study.opengl_blend import gl_blend

pytestmark = pytest.mark.gl

W, H = 32, 32
MODES = ["over", "premultiplied", "additive", "multiply"]
CLEAR = (0.1, 0.2, 0.3, 0.4)


def scene(seed, n=8, smooth=False):
    """n triangles, vertices on the 1/256 grid, each at one depth, RGBA per triangle (or per
    vertex with ``smooth``)."""
    rng = np.random.default_rng(seed)
    xy = rng.integers(0, W * 256, (n, 3, 2)) / 256
    ndc = np.stack([xy[..., 0] * 2 / W - 1, 1 - xy[..., 1] * 2 / H], axis=-1)
    z = np.repeat(rng.uniform(-0.8, 0.8, (n, 1)), 3, axis=1)[..., None]
    clip = np.concatenate([ndc, z, np.ones((n, 3, 1))], axis=-1)
    colours = (
        rng.uniform(0, 1, (n, 3, 4)) if smooth else np.repeat(rng.uniform(0, 1, (n, 1, 4)), 3, 1)
    )
    return clip, colours


def close(ours, gl):
    scale = np.maximum(1.0, np.abs(ours))
    return np.abs(ours - gl) / scale <= 1e-6


@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("writes", ["all", "none", "mixed"])
def test_rgba32f_agrees_within_1e6(mode, writes):
    clip, colours = scene(MODES.index(mode) * 3 + ["all", "none", "mixed"].index(writes))
    depth_write = {"all": True, "none": False, "mixed": np.arange(len(clip)) % 2 == 0}[writes]
    ours = tr.render(clip, W, H, attrs=colours, blend=mode, depth_write=depth_write,
                     clear_color=CLEAR).color  # fmt: skip
    gl = gl_blend(clip, W, H, colours, blend=mode, depth_write=depth_write, clear_color=CLEAR)
    assert close(ours, gl).all(), np.abs(ours - gl).max()


def test_rgba32f_with_interpolated_colours():
    clip, colours = scene(40, smooth=True)
    ours = tr.render(clip, W, H, attrs=colours, blend="over", depth_write=False).color
    gl = gl_blend(clip, W, H, colours, blend="over", depth_write=False)
    assert close(ours, gl).all(), np.abs(ours - gl).max()


def test_order_dependence_is_gls_too():
    clip, colours = scene(41)
    back = slice(None, None, -1)
    ours = tr.render(clip[back], W, H, attrs=colours[back], blend="over", depth_write=False)
    gl = gl_blend(clip[back], W, H, colours[back], blend="over", depth_write=False)
    forward = tr.render(clip, W, H, attrs=colours, blend="over", depth_write=False).color
    assert close(ours.color, gl).all()
    assert not close(forward, ours.color).all()


@pytest.mark.parametrize("mode", ["over", "premultiplied"])
def test_msaa_blending_then_resolve(mode):
    clip, colours = scene(42 + MODES.index(mode))
    ours = tr.render(clip, W, H, attrs=colours, blend=mode, depth_write=False, samples=4,
                     clear_color=CLEAR).color  # fmt: skip
    gl = gl_blend(clip, W, H, colours, blend=mode, depth_write=False, samples=4,
                  clear_color=CLEAR)  # fmt: skip
    assert close(ours, gl).all(), np.abs(ours - gl).max()


def test_blending_off_and_depth_masks_agree():
    """``blend=None`` is GL with GL_BLEND disabled (the fragment colour replaces), and the
    depth mask is independent of blending: colours, ids and the depth buffer itself."""
    for seed in range(4):
        clip, colours = scene(70 + seed, smooth=seed % 2 == 1)
        writes = np.random.default_rng(seed).random(len(clip)) < 0.5
        ours = tr.render(clip, W, H, attrs=colours, depth_write=writes, clear_color=CLEAR)
        gl = gl_blend(clip, W, H, colours, blend=None, depth_write=writes, clear_color=CLEAR)
        assert close(ours.color, gl).all(), np.abs(ours.color - gl).max()
        ids = gl_render(clip, W, H, depth_write=writes)
        np.testing.assert_array_equal(ours.triangle_id, ids.triangle_id)
        np.testing.assert_array_equal(np.isnan(ours.depth), np.isnan(ids.depth_buffer))
        np.testing.assert_allclose(ours.depth, ids.depth_buffer, atol=1e-7)  # float32 depth
        assert np.isnan(ours.depth).sum() > np.isnan(tr.render(clip, W, H).depth).sum()


@pytest.mark.parametrize("mode", ["additive", "over"])
def test_msaa_blending_with_depth_masks(mode):
    clip, colours = scene(80 + MODES.index(mode), n=10)
    writes = np.arange(len(clip)) % 3 == 0
    ours = tr.render(clip, W, H, attrs=colours, blend=mode, depth_write=writes, samples=4,
                     clear_color=CLEAR).color  # fmt: skip
    gl = gl_blend(clip, W, H, colours, blend=mode, depth_write=writes, samples=4,
                  clear_color=CLEAR)  # fmt: skip
    assert close(ours, gl).all(), np.abs(ours - gl).max()


def layers(mode, n, scale, seed):
    """n full-screen layers, colours varying over the image (every pixel rounds its own way)."""
    rng = np.random.default_rng(seed)
    quad = np.array([[[-1, -1, 0, 1], [1, -1, 0, 1], [1, 1, 0, 1]],
                     [[-1, -1, 0, 1], [1, 1, 0, 1], [-1, 1, 0, 1]]], float)  # fmt: skip
    attrs = rng.uniform(0, 1, (2 * n, 3, 4)) * scale
    attrs[1::2, 0], attrs[1::2, 1] = attrs[0::2, 0], attrs[0::2, 2]  # the shared diagonal
    return np.concatenate([quad] * n), attrs


def srgb_steps(mode, n, scale, seeds, color_format="srgb8"):
    """Per seed, our 8-bit codes minus llvmpipe's (RGB, then alpha)."""
    out = []
    for seed in seeds:
        clip, attrs = layers(mode, n, scale, seed)
        gl = gl_blend(clip, 16, 16, attrs, blend=mode, depth_write=False, srgb=True)
        ours = tr.render(clip, 16, 16, attrs=attrs, blend=mode, depth_write=False,
                         color_format=color_format).color  # fmt: skip
        rgb = np.round(tr.linear_to_srgb(np.clip(ours[..., :3], 0, 1)) * 255)
        alpha = np.round(np.clip(ours[..., 3], 0, 1) * 255)
        out.append((rgb - gl[..., :3], alpha - gl[..., 3]))
    return out


@pytest.mark.parametrize("mode", ["over", "additive"])
def test_srgb8_one_layer_within_one_step(mode):
    for rgb, alpha in srgb_steps(mode, 1, 1.0 if mode == "over" else 0.3, range(6)):
        assert np.abs(rgb).max() <= 1 and np.abs(alpha).max() == 0


def test_srgb8_rounds_and_clamps_every_layer_as_gl_does():
    """16 'over' and 16 'premultiplied' layers: within 2 steps of llvmpipe. Blending in
    float64 and encoding once misses GL's clamp after every layer (premultiplied colours
    above their alpha): tens of steps off."""
    for mode in ("over", "premultiplied"):
        steps = srgb_steps(mode, 16, 1.0, range(8))
        assert max(np.abs(rgb).max() for rgb, _ in steps) <= 2, mode
        assert max(np.abs(alpha).max() for _, alpha in steps) <= 1, mode
    unrounded = srgb_steps("premultiplied", 16, 1.0, range(2), color_format="float64")
    assert max(np.abs(rgb).max() for rgb, _ in unrounded) > 10


def test_srgb8_additive_layers_drift_with_llvmpipes_approximations():
    """40 dim additive layers: llvmpipe reads the dark codes back brighter (c / 12.6 instead
    of the curve's c / 12.92) and adds to that, layer after layer; the bound measured over
    these scenes is 16 steps, and llvmpipe is the brighter one."""
    steps = srgb_steps("additive", 40, 0.01, range(8))
    rgb = np.stack([r for r, _ in steps])
    assert np.abs(rgb).max() <= 16
    assert rgb.mean() < -1  # ours darker on average: the drift has a direction


def test_perspective_correct_colours_within_llvmpipes_float32_setup():
    """With w differing per vertex, llvmpipe's float32 perspective set-up (not the blending)
    limits agreement: a few 1e-6 on slivers (test_opengl.py's kappa-scaled tolerances), so
    this test allows 1e-5; the blending arithmetic itself is checked at 1e-6 above."""
    worst = 0.0
    for seed in range(5):
        clip, colours = scene(60 + seed, smooth=True)
        w = 2.0 ** np.random.default_rng(seed).integers(0, 3, (len(clip), 3, 1))
        clip = clip * w  # same window positions, perspective-correct colours
        ours = tr.render(clip, W, H, attrs=colours, blend="over", depth_write=False).color
        gl = gl_blend(clip, W, H, colours, blend="over", depth_write=False)
        worst = max(worst, float(np.abs(ours - gl).max()))
    assert worst <= 1e-5, worst
