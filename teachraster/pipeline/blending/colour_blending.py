"""Blending: the colour buffer, fragment after fragment in submission order.

After the depth test each fragment's RGBA colour is combined with what the colour buffer holds
(:func:`teachraster.blend_equation`, GL's ``glBlendFunc``), per pixel, or per sample under MSAA
(then the resolve averages the samples). Unlike the z-buffer (:mod:`.zbuffer`) the result
depends on the order: every layer at a pixel is applied in turn. The layers are applied all
pixels at once, one *layer* at a time (the first fragment at every pixel, then the second, ...),
so the loop runs as often as the deepest pixel has layers, never once per fragment.

Transparent geometry is drawn with ``depth_write=False``: it is tested against the depth
buffer (opaque geometry hides it) but does not write it, so it never hides what comes after.
A fragment passes when it is strictly nearer than every earlier fragment *that wrote depth*.

The plan's "blending" effect: blending runs only for fragments whose result is not their own
colour (``"over"``/``"premultiplied"`` with alpha 1 replace what is there: written as they
are), and says how many of those landed on an earlier fragment rather than the clear colour.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.blend_factors import BLEND_MODES, FACTORS, apply_blend
from ...core.interpolation import blend_each, convex_weights, weights_per_row
from ...core.validate import as_bool, as_finite, check_choice, short_repr
from ..planning.render_plan import Effect
from ..rasterization.batched_fill import rasterize_batch
from ..visibility.depth import quantize


@dataclass(frozen=True)
class BlendState:
    """Checked blend arguments of ``render``: the factor pair, per-triangle depth writes (N,)
    and the clear colour (4,)."""

    mode: str
    factors: tuple[str, str]
    depth_write: np.ndarray
    clear_color: np.ndarray


def check_blend(blend, depth_write, clear_color, attrs: np.ndarray) -> BlendState | None:
    """``render``'s blend arguments checked (naming them); None when ``blend`` is None."""
    n = len(attrs)
    if isinstance(depth_write, bool | np.bool_):
        writes = np.full(n, as_bool("depth_write", depth_write))
    else:
        writes = np.asarray(depth_write)
        if writes.shape != (n,) or writes.dtype != bool:
            raise ValueError(f"depth_write must be a bool or (N,) = ({n},) bools; "
                             f"got {short_repr(depth_write)}")  # fmt: skip
    clear = as_finite("clear_color", clear_color, (4,))
    if blend is None:
        if not writes.all():
            raise ValueError("depth_write=False needs a blend mode (it concerns the colour buffer)")
        return None
    if isinstance(blend, tuple):
        if len(blend) != 2:
            raise ValueError(f"blend: a (src_factor, dst_factor) pair, got {short_repr(blend)}")
        for name, f in zip(("blend source factor", "blend destination factor"), blend):
            check_choice(name, f, FACTORS)
        mode, factors = "custom", (str(blend[0]), str(blend[1]))
    else:
        check_choice("blend", blend, (None, *BLEND_MODES))
        mode, factors = blend, BLEND_MODES[blend]
    if attrs.shape[2] != 4:
        raise ValueError(f"attrs: blending needs RGBA attributes (k = 4), got k = {attrs.shape[2]}")
    return BlendState(mode, factors, writes, clear)


def passed_with_writes(pixel: np.ndarray, depth: np.ndarray, writes: np.ndarray) -> np.ndarray:
    """(m,) bool: each fragment (drawing order) is strictly nearer than every earlier fragment
    at its pixel that wrote depth (``writes``); fragments that do not write are still tested.

    As :func:`teachraster.pipeline.zbuffer.passed_on_arrival`: a stable sort by pixel and a
    running maximum of integer keys, offset per pixel so nothing leaks between pixels; a
    fragment that does not write contributes the key of "nothing" (rank m, the farthest).
    """
    m = len(pixel)
    if m == 0:
        return np.ones(0, dtype=bool)
    order = np.argsort(pixel, kind="stable")
    pix = pixel[order]
    group = np.cumsum(np.r_[False, pix[1:] != pix[:-1]]).astype(np.int64)
    _, rank = np.unique(depth[order], return_inverse=True)
    base = group * (m + 1)
    key = base + (m - rank)  # larger key = nearer
    written = np.where(writes[order], key, base)  # a non-writer leaves the buffer as it was
    best = np.maximum.accumulate(written)
    before = np.maximum(np.r_[-1, best[:-1]], base)
    passed = np.empty(m, dtype=bool)
    passed[order] = key > before
    return passed


def _sample_fragments(window, culled, offset, size, bits):
    """Fragments whose *sample* at ``offset`` is covered: the triangles moved so that the
    pixel centres fall where the samples are (exact for offsets on the 1/256 grid)."""
    shift = 0.5 - np.asarray(offset, dtype=np.float64)
    frags = rasterize_batch(window[:, :, :2] + shift, size[0], size[1], subpixel_bits=bits,
                            skip=culled, snapped_weights=False)  # fmt: skip
    return frags, shift


def _colours(frags, index, shift, clipped, interpolation, msaa):
    """RGBA at fragments ``index``' pixel centres (MSAA: extrapolated where the centre is
    outside); perspective-correct only for triangles whose w differ, as the attribute stage."""
    tri = frags.tri[index]
    x, y = frags.col[index] + 0.5 + shift[0], frags.row[index] + 0.5 + shift[1]
    weights = frags.weights_at(tri, x, y)
    if not msaa:
        weights = convex_weights(weights)
    w = clipped.clip[:, :, 3]
    if interpolation == "perspective":
        unequal = ~np.all(w == w[:, :1], axis=1)[tri]
        if unequal.any():
            weights[unequal] = weights_per_row(weights[unequal], w[tri[unequal]], extrapolate=msaa)
    return blend_each(weights, clipped.attrs, index=tri, extrapolate=msaa)


def _layers(pixel, n_pixels, src, state, opaque):
    """Apply the passed fragments (drawing order) layer by layer onto the clear colour.

    Returns the (n_pixels, 4) buffer, how many fragments were blended and how many of those
    landed on an earlier fragment."""
    buffer = np.broadcast_to(state.clear_color, (n_pixels, 4)).copy()
    order = np.argsort(pixel, kind="stable")
    pix = pixel[order]
    start = np.r_[True, pix[1:] != pix[:-1]]
    index = np.arange(len(pix))
    layer = index - np.maximum.accumulate(np.where(start, index, 0))
    # Group by layer once (stable: pixels stay in order), then walk the groups in turn.
    by_layer = np.argsort(layer, kind="stable")
    frags = order[by_layer]
    bounds = np.searchsorted(layer[by_layer], np.arange(int(layer.max(initial=-1)) + 2))
    blended = on_something = 0
    for k in range(len(bounds) - 1):
        here = frags[bounds[k] : bounds[k + 1]]
        p, colour = pixel[here], src[here]
        mix = ~opaque[here]
        if mix.any():
            colour = colour.copy()
            colour[mix] = apply_blend(colour[mix], buffer[p[mix]], *state.factors)
        buffer[p] = colour
        blended += int(mix.sum())
        on_something += int(mix.sum()) if k else 0
    return buffer, blended, on_something


def blend_stage(clipped, window, culled, offsets, a, state: BlendState):
    """The colour buffer of a render: (H, W, 4) resolved colour, (H, W, S, 4) per sample (None
    for one sample), and the plan's "blending" effect. ``a`` are the checked render inputs."""
    size, n_pixels = (a.width, a.height), a.width * a.height
    offsets = np.array([[0.5, 0.5]]) if offsets is None else np.asarray(offsets)
    writes = state.depth_write[clipped.parent]
    replaces = state.factors == BLEND_MODES["over"] or state.factors == BLEND_MODES["premultiplied"]
    samples, counts = [], np.zeros(3, dtype=np.int64)
    for offset in offsets:
        frags, shift = _sample_fragments(window, culled, offset, size, a.subpixel_bits)
        pixel = frags.row * a.width + frags.col
        passed = np.ones(len(pixel), dtype=bool)
        if a.depth_test:
            depth = frags.plane(window[:, :, 2])
            if a.depth_format != "float64":
                depth = quantize(depth, a.depth_format)
            passed = passed_with_writes(pixel, depth, writes[frags.tri])
        src = _colours(frags, np.flatnonzero(passed), shift, clipped, a.interpolation,
                       len(offsets) > 1)  # fmt: skip
        opaque = (src[:, 3] == 1.0) if replaces else np.zeros(len(src), dtype=bool)
        buffer, blended, on_something = _layers(pixel[passed], n_pixels, src, state, opaque)
        samples.append(buffer.reshape(a.height, a.width, 4))
        counts += (int(passed.sum()), blended, on_something)
    sample_color = np.stack(samples, axis=2)
    color = sample_color.mean(axis=2)
    return color, (sample_color if len(offsets) > 1 else None), _effect(state, counts, len(offsets))


def _effect(state: BlendState, counts, n_samples: int) -> Effect:
    """The plan entry: how many fragments (samples) were blended, and onto what."""
    passed, blended, on_something = (int(c) for c in counts)
    unit = "fragments" if n_samples == 1 else "samples"
    why = (f"{state.mode} {state.factors}: {blended:,} transparent {unit} blended, "
           f"{on_something:,} of them onto an earlier fragment, the rest onto the clear colour; "
           f"{passed - blended:,} opaque ones written as they are")  # fmt: skip
    return Effect("blending", blended > 0, on_something, passed, unit, why)
