"""Blending: the colour buffer, fragment after fragment in submission order.

After the depth test each fragment's RGBA colour is combined with what the colour buffer holds
(:func:`teachraster.blend_equation`, GL's ``glBlendFunc``), per pixel, or per sample under MSAA
(then the resolve averages the samples). Unlike the z-buffer (:mod:`.zbuffer`) the result
depends on the order: every layer at a pixel is applied in turn. The layers are applied all
pixels at once, one *layer* at a time (the first fragment at every pixel, then the second, ...),
so the loop runs as often as the deepest pixel has layers, never once per fragment.

This stage decides nothing about visibility: the fill (or, under MSAA, the per-sample
coverage), the depth test in drawing order and the attribute evaluation hand it the
fragments that passed and their colours (:func:`blend_layers`), the same decisions the
frame's ids, depth, history and overlays read.

Blending off is a state too: with ``blend=None`` a fragment that passes writes its colour
over the target's, as GL does with ``GL_BLEND`` disabled. Transparent geometry is drawn
with ``depth_write=False`` (``glDepthMask``, independent of blending): it is tested against
the depth buffer (opaque geometry hides it) but does not write it, so it never hides what
comes after. A fragment passes when it is strictly nearer than every earlier fragment *that
wrote depth*.

The target's format: ``"float64"`` keeps every value as computed (unclamped); ``"srgb8"``
is GL's ``SRGB8_ALPHA8`` with ``GL_FRAMEBUFFER_SRGB``: the source and the target are clamped
to [0, 1], the target is decoded to linear to blend, and the result is clamped, encoded and
rounded to 8 bits after *every* layer (:func:`store_colour`), alpha stored linearly.

The plan's "blending" effect counts the fragments blended: those whose result is not their
own colour (``"over"``/``"premultiplied"`` with alpha 1 replace what is there: written as
they are), whether onto an earlier fragment or onto the clear colour; its text says how many
of them landed on an earlier fragment.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ...core.blend_factors import BLEND_MODES, FACTORS, apply_blend, linear_to_srgb, srgb_to_linear
from ...core.validate import as_bool, as_finite, check_choice, short_repr
from ..planning.render_plan import Effect

#: What the colour buffer stores: float64 as computed, or GL's ``SRGB8_ALPHA8``.
COLOR_FORMATS = ("float64", "srgb8")


@dataclass(frozen=True)
class BlendState:
    """Checked colour-buffer arguments of ``render``.

    Attributes
    ----------
    mode : str or None
        The blend mode ("custom" for a factor pair); None: blending disabled, a fragment's
        colour replaces the target's.
    factors : (str, str) or None
        The ``glBlendFunc`` pair (None without blending).
    depth_write : (N,) bool
        Per input triangle, its depth mask.
    clear_color : (4,) float64
        The colour the buffer starts at, as the format stores it.
    color_format : str
        :data:`COLOR_FORMATS`.
    buffer : bool
        Whether there is a colour buffer at all: the attributes are RGBA (k = 4).
    equation : callable or None
        A caller's blend rule ``equation(src (4,), dst (4,)) -> (4,)`` replacing the
        factors' equation for every fragment blended (``overrides``, see
        :mod:`teachraster.pipeline.planning.overrides`); None: the package's.
    """

    mode: str | None
    factors: tuple[str, str] | None
    depth_write: np.ndarray
    clear_color: np.ndarray
    color_format: str = "float64"
    buffer: bool = True
    equation: Callable | None = field(default=None, compare=False)

    @property
    def blending(self) -> bool:
        """Whether fragments are blended (rather than written as they are)."""
        return self.mode is not None


def check_blend(blend, depth_write, clear_color, attrs: np.ndarray,
                color_format="float64", equation=None) -> BlendState:  # fmt: skip
    """``render``'s colour-buffer arguments checked (naming them); ``equation`` a caller's
    blend rule (it needs a blend mode: it replaces that mode's equation)."""
    n = len(attrs)
    if isinstance(depth_write, bool | np.bool_):
        writes = np.full(n, as_bool("depth_write", depth_write))
    else:
        writes = np.asarray(depth_write)
        if writes.shape != (n,) or writes.dtype != bool:
            raise ValueError(f"depth_write must be a bool or (N,) = ({n},) bools; "
                             f"got {short_repr(depth_write)}")  # fmt: skip
    clear = as_finite("clear_color", clear_color, (4,))
    check_choice("color_format", color_format, COLOR_FORMATS)
    if isinstance(blend, tuple):
        if len(blend) != 2:
            raise ValueError(f"blend: a (src_factor, dst_factor) pair, got {short_repr(blend)}")
        for name, f in zip(("blend source factor", "blend destination factor"), blend):
            check_choice(name, f, FACTORS)
        mode, factors = "custom", (str(blend[0]), str(blend[1]))
    else:
        check_choice("blend", blend, (None, *BLEND_MODES))
        mode, factors = blend, (None if blend is None else BLEND_MODES[blend])
    rgba = attrs.shape[2] == 4
    if equation is not None and mode is None:
        raise ValueError("overrides: the blend rule replaces a blend equation; give blend= a "
                         "mode (such as 'over') for it to replace")  # fmt: skip
    if mode is not None and not rgba:
        raise ValueError(f"attrs: blending needs RGBA attributes (k = 4), got k = {attrs.shape[2]}")
    return BlendState(mode, factors, writes, store_colour(clear, color_format), color_format,
                      rgba, equation)  # fmt: skip


def store_colour(rgba: np.ndarray, color_format: str) -> np.ndarray:
    """What a target of ``color_format`` stores for linear ``rgba`` (..., 4), as linear
    float64: itself ("float64"), or ("srgb8") the value of the 8-bit code GL writes:
    clamped to [0, 1], RGB encoded by the sRGB curve and alpha as it is, each rounded to
    the nearest of 255 steps, RGB then decoded again.

    >>> store_colour(np.array([0.5, 0.5, 0.5, 0.5]), "srgb8").round(6).tolist()
    [0.502886, 0.502886, 0.502886, 0.501961]
    """
    if color_format == "float64":
        return rgba
    out = srgb8_codes(rgba) / 255.0
    out[..., :3] = srgb_to_linear(out[..., :3])
    return out


def srgb8_codes(rgba: np.ndarray) -> np.ndarray:
    """The 8-bit codes (0 to 255, as float64) an "srgb8" target stores for linear ``rgba``
    (..., 4): clamped to [0, 1], RGB encoded by the sRGB curve and alpha as it is, each
    rounded to the nearest code. :func:`store_colour` decodes them again.

    >>> srgb8_codes(np.array([0.5, 0.5, 0.5, 0.5])).tolist()
    [188.0, 188.0, 188.0, 128.0]
    """
    c = np.clip(np.asarray(rgba, dtype=np.float64), 0.0, 1.0)
    out = np.empty_like(c)
    out[..., :3] = np.round(linear_to_srgb(c[..., :3]) * 255.0)
    out[..., 3] = np.round(c[..., 3] * 255.0)
    return out


def write_colour(src: np.ndarray, dst: np.ndarray, state: BlendState) -> np.ndarray:
    """The target's colour (n, 4) after fragments of colour ``src`` (n, 4) pass onto
    ``dst`` (n, 4): the one rule of the colour stage, and of the pixel history's replay.

    Without blending the fragment's colour replaces the target's; "over" and
    "premultiplied" with alpha 1 replace it too (written as they are); the other
    fragments go through the blend equation. An 8-bit target clamps the source first
    and stores the result rounded (:func:`store_colour`).
    """
    return _write(src, dst, state)[0]


def _write(src, dst, state: BlendState):
    """:func:`write_colour`, and how many of the fragments went through the equation."""
    if state.color_format != "float64":
        src = np.clip(src, 0.0, 1.0)  # GL clamps to a normalised target's range first
    mixed = 0
    if state.equation is not None:  # a caller's rule blends every fragment, one by one
        src = _by_rule(src, dst, state.equation)
        mixed = len(src)
    elif state.blending:
        mix = ~_replaces(src, state)
        mixed = int(np.count_nonzero(mix))
        if mixed == len(src):
            src = apply_blend(src, dst, *state.factors)
        elif mixed:
            src = src.copy()
            src[mix] = apply_blend(src[mix], dst[mix], *state.factors)
    return store_colour(src, state.color_format), mixed


def _by_rule(src: np.ndarray, dst: np.ndarray, equation: Callable) -> np.ndarray:
    """(n, 4): ``equation(src[i], dst[i])`` row by row (ValueError unless 4 values each)."""
    out = np.empty((len(src), 4))
    for i in range(len(src)):
        value = np.asarray(equation(src[i].copy(), dst[i].copy()), dtype=np.float64)
        if value.shape != (4,):
            raise ValueError(f"the blend rule must return 4 values (RGBA), got shape {value.shape}")
        out[i] = value
    return out


def _replaces(src: np.ndarray, state: BlendState) -> np.ndarray:
    """(n,) bool: fragments whose blended result is their own colour (alpha 1 "over" or
    "premultiplied"), which GPUs write without reading the target."""
    opaque = state.factors in (BLEND_MODES["over"], BLEND_MODES["premultiplied"])
    if not state.blending or not opaque:
        return np.full(len(src), not state.blending)
    return src[:, 3] == 1.0


def blend_layers(slot: np.ndarray, n_slots: int, src: np.ndarray, state: BlendState):
    """Apply the fragments that passed (drawing order within each slot) layer by layer onto
    the clear colour: the colour buffer (n_slots, 4), how many fragments were blended and
    how many of those landed on an earlier fragment.

    A slot is a pixel (one sample) or a sample of a pixel (``pixel * S + sample``).
    """
    buffer = np.broadcast_to(state.clear_color, (n_slots, 4)).copy()
    order = np.argsort(slot, kind="stable")
    pix = slot[order]
    start = np.r_[True, pix[1:] != pix[:-1]]
    index = np.arange(len(pix))
    layer = index - np.maximum.accumulate(np.where(start, index, 0))
    # Group by layer once (stable: slots stay in order), then walk the groups in turn.
    by_layer = np.argsort(layer, kind="stable")
    frags = order[by_layer]
    bounds = np.searchsorted(layer[by_layer], np.arange(int(layer.max(initial=-1)) + 2))
    blended = on_something = 0
    for k in range(len(bounds) - 1):
        here = frags[bounds[k] : bounds[k + 1]]
        p = slot[here]
        buffer[p], mixed = _write(src[here], buffer[p], state)
        blended += mixed
        on_something += mixed if k else 0
    return buffer, blended, on_something


def blend_stage(slot, src, shape, n_samples: int, state: BlendState):
    """The colour buffer of a render: (H, W, 4) resolved colour, (H, W, S, 4) per sample
    (None for one sample), and the plan's "blending" effect.

    ``slot`` (e,) and ``src`` (e, 4) are the fragments (samples) that passed the depth test,
    in drawing order within each slot (pixel, or ``pixel * S + sample``), and their colours;
    ``shape`` = (height, width).
    """
    height, width = shape
    buffer, blended, on_something = blend_layers(slot, height * width * n_samples, src, state)
    sample_color = buffer.reshape(height, width, n_samples, 4)
    color = sample_color.mean(axis=2) if n_samples > 1 else sample_color[:, :, 0]
    effect = _effect(state, (len(slot), blended, on_something), n_samples)
    return color, (sample_color if n_samples > 1 else None), effect


def replaced_colour(covered: np.ndarray, values: np.ndarray, state: BlendState) -> np.ndarray:
    """The colour buffer without blending, (..., 4): each covered pixel (sample) holds the
    colour of the fragment it shows (``values``), the others the clear colour."""
    return store_colour(np.where(covered[..., None], values, state.clear_color),
                        state.color_format)  # fmt: skip


def _effect(state: BlendState, counts, n_samples: int) -> Effect:
    """The plan entry: how many fragments (samples) were blended, and onto what.

    Its count is every fragment blended: one blended onto the clear colour is blended too
    (the clear colour is the target it reads), so "applied to" and "blended" are one number.
    """
    passed, blended, on_something = (int(c) for c in counts)
    unit = "fragments" if n_samples == 1 else "samples"
    why = (f"{state.mode} {state.factors}: {blended:,} transparent {unit} blended, "
           f"{on_something:,} of them onto an earlier fragment, the rest onto the clear colour; "
           f"{passed - blended:,} opaque ones written as they are")  # fmt: skip
    return Effect("blending", blended > 0, blended, passed, unit, why)
