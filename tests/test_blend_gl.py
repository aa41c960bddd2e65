"""Blending against a real GPU: the same scenes and blend state through Mesa's llvmpipe
(moderngl + EGL). RGBA32F colour buffer: within 1e-6 (relative above 1); SRGB8_ALPHA8 with
GL_FRAMEBUFFER_SRGB: within one 8-bit step. Skipped, with the reason, without OpenGL."""

from __future__ import annotations

import numpy as np
import pytest
from gl_required import require_gl

require_gl()

import teachraster as tr
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


@pytest.mark.parametrize("mode", ["over", "premultiplied"])
def test_srgb_framebuffer_within_one_step(mode):
    """GL stores sRGB, converts to linear to blend and back (8 bits each time); ours blends in
    linear float64 and is encoded once at the end: one 8-bit step apart at most."""
    clip, colours = scene(50 + MODES.index(mode), n=4)
    ours = tr.render(clip, W, H, attrs=colours, blend=mode, depth_write=False).color
    gl = gl_blend(clip, W, H, colours, blend=mode, depth_write=False, srgb=True)
    rgb = np.round(tr.linear_to_srgb(np.clip(ours[..., :3], 0, 1)) * 255)
    alpha = np.round(np.clip(ours[..., 3], 0, 1) * 255)  # alpha is stored linear
    assert np.abs(rgb - gl[..., :3]).max() <= 1
    assert np.abs(alpha - gl[..., 3]).max() <= 1


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
