"""Exercise ``resolve_srgb`` (lesson 08 §6, lesson 12b): the MSAA resolve in linear light.

Exercise 6.2's resolve averages the numbers it is given. The samples of an 8-bit framebuffer
are sRGB-encoded, and encoded numbers are not light: half of a black pixel and half of a white
one must show the light of 50 % white, which encodes as 0.735, not 0.5. So the resolve
decodes every sample (and the background) to linear light, averages there, and encodes the
mean again (GL's ``FRAMEBUFFER_SRGB`` resolve; lesson 08 §6 and lesson 12b). The student
works out that order; the curves are the package's tools (``tr.srgb_to_linear``,
``tr.linear_to_srgb``). Cases: exercise 6.2's, read as sRGB-encoded, and black on white at
each coverage of 4 samples.
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import linear_to_srgb, srgb_to_linear
from ..pipeline.render_triangles import Frame
from .antialiasing import (
    CHANNEL_ORDER,
    ON_255,
    as_colour,
    draw_resolve_case,
    expected_resolve,
    resolve_case,
    resolve_cases,
    same_colour,
    swatch_words,
)
from .exercise import Exercise, Mistake, PackageAnswer
from .scalars import num, vec


def _decode(colours) -> np.ndarray:
    """sRGB-encoded colours to linear light, NaN (no triangle wrote the sample) kept."""
    c = np.asarray(colours, dtype=float)
    out = np.full_like(c, np.nan)
    finite = np.isfinite(c)
    out[finite] = srgb_to_linear(c[finite])
    return out


def _encode(linear) -> np.ndarray:
    return linear_to_srgb(np.clip(np.asarray(linear, dtype=float), 0.0, 1.0))


def expected_resolve_srgb(colours, ids, background) -> np.ndarray:
    """Decode, resolve (the package's, :func:`.antialiasing.expected_resolve`), encode."""
    linear = expected_resolve(_decode(colours), ids, srgb_to_linear(background))
    return _encode(linear)


def resolve_srgb_cases():
    """Exercise 6.2's cases read as sRGB-encoded, then black on white at 1 to 3 of 4 samples
    (where averaging the encoded numbers is farthest off)."""
    black, white = np.zeros(3), np.ones(3)
    out = []
    for k in (1, 2, 3):
        ids = [0] * k + [-1] * (4 - k)
        out.append(resolve_case(f"black on white, {k} of 4 samples", ids, [black] * 4, white))
    out += list(resolve_cases())
    return [(label, args, expected_resolve_srgb(*args)) for label, args, _ in out]


def _covered(ids) -> np.ndarray:
    return np.asarray(ids) >= 0


#: 6.3's rule, said for an answer no mistake explains once two different answers have
#: failed, and the question asked instead before (r64 06 D1: the first try of a placeholder
#: printed the whole formula).
RULE = (
    "; decode the covered samples and the background to linear light, average over all S "
    "samples there, and encode the mean: linear_to_srgb((Σ srgb_to_linear(covered) + "
    "(S − k)·srgb_to_linear(background)) / S)"
)
#: r73 06-1: the named mistake's recipe, as a question until two different answers have failed.
_RECIPE = "; decode first, average in linear light, encode the mean"
_RECIPE_HINT = "; at which step must the numbers be light, and at which encoded?"
HINT = (
    "; the numbers given and the number returned are sRGB-encoded, and only light adds up: "
    "at which step must each value be light, and at which an encoded number? Work this "
    "case through by hand with srgb_to_linear and linear_to_srgb"
)


def _rule(args, expected, got) -> str:
    return RULE


def _mix(colours, ids, background, decode, encode, covered_only=False):
    """A resolve with the decoding and encoding given (identity: the numbers as they are)."""
    c = _covered(ids)
    if covered_only:
        if not c.any():
            return None
        return encode(decode(np.asarray(colours, float)[c]).mean(axis=0))
    mixed = np.where(c[:, None], decode(np.nan_to_num(np.asarray(colours, float))),
                     decode(np.asarray(background, float)))  # fmt: skip
    return encode(mixed.mean(axis=0))


def _same(x):
    return np.asarray(x, dtype=float)


def _power(x, g):
    return np.clip(np.asarray(x, dtype=float), 0, None) ** g


def _no_linear_part(x):
    """sRGB's power branch used everywhere, below code 0.04045 too."""
    return ((np.asarray(x, dtype=float) + 0.055) / 1.055) ** 2.4


def _no_linear_part_back(y):
    return 1.055 * np.clip(np.asarray(y, dtype=float), 0, None) ** (1 / 2.4) - 0.055


def _background_raw(colours, ids, background):
    c = _covered(ids)
    mixed = np.where(c[:, None], _decode(np.nan_to_num(np.asarray(colours, float))),
                     np.asarray(background, float))  # fmt: skip
    return _encode(mixed.mean(axis=0))


def _encoded_average_words(args, expected, got) -> str:
    """The encoded-average mistake, its example at the case's own count of samples (r49: a
    "1 of 4" case quoted "2 of 4")."""
    _, ids, _ = args
    s, k = len(ids), int(_covered(ids).sum())
    white = (s - k) / s  # the share of white's light where k of s samples are black
    return (
        f": you averaged the sRGB-encoded numbers, as 6.2's resolve does: encoded numbers "
        f"are not light (black on white at {k} of {s} samples must show {num(white)} of "
        f"white's light, {num(float(linear_to_srgb(white)))} encoded, not {num(white)}); "
        + _RECIPE.lstrip("; ")
    )


def draw_srgb_case(ax, case, got):
    """The samples, the expected colour and yours as swatches (6.2's figure), and beside them
    the encoded numbers averaged as 6.2 does: the two swatches' difference in brightness is
    the linear-light point (r49: equal bars showed nothing of it; r64: bars showed no colour).
    Before any answer the samples only."""
    _, (colours, ids, background), _ = case
    codes = _mix(colours, ids, background, _same, _same)
    extra = (f"codes averaged\n(6.2's resolve)\n{swatch_words(vec(codes))}", codes)
    artists = draw_resolve_case(ax, case, got, extra=extra if got is not None else None)
    if got is not None:
        artists.append(ax.set_xlabel("expected: averaged in linear light, then encoded",
                                     fontsize="x-small"))  # fmt: skip
    return artists


MISTAKES = [
    Mistake("encoded average", _encoded_average_words,
            gives=lambda c, i, b: _mix(c, i, b, _same, _same)),
    Mistake("not encoded", ": that is the mean in linear light, not encoded again: the "
            "framebuffer holds sRGB-encoded numbers, so encode it (linear_to_srgb)",
            gives=lambda c, i, b: _mix(c, i, b, srgb_to_linear, _same)),
    Mistake("encoded twice", ": you encoded where you should decode (and the other way "
            "round): srgb_to_linear takes the encoded samples to light, linear_to_srgb takes "
            "the mean back", gives=lambda c, i, b: _mix(c, i, b, linear_to_srgb, srgb_to_linear)),
    Mistake("background not decoded", ": the background is sRGB-encoded like the samples: "
            "decode it too before it joins the average", gives=_background_raw),
    Mistake("covered only", ": you averaged the covered samples only; an uncovered sample "
            "counts as the background", gives=lambda c, i, b: _mix(c, i, b, _decode, _encode,
                                                                   covered_only=True)),
    Mistake("power 2.2", ": that is a plain power of 2.2: sRGB's curve is linear near black "
            "and a power of 2.4 above it (srgb_to_linear, linear_to_srgb compute it exactly)",
            gives=lambda c, i, b: _mix(c, i, b, lambda x: _power(x, 2.2),
                                       lambda x: _power(x, 1 / 2.2))),
    # r293 MN4: a power of 2.4, or the curve without its straight part, was asked "at which
    # step must each value be light?", though the steps were right
    Mistake("power 2.4", ": that is a plain power of 2.4: sRGB's curve is a straight line "
            "near black (c / 12.92 up to code 0.04045) and ((c + 0.055) / 1.055)^2.4 above "
            "(srgb_to_linear, linear_to_srgb compute it exactly)",
            gives=lambda c, i, b: _mix(c, i, b, lambda x: _power(x, 2.4),
                                       lambda x: _power(x, 1 / 2.4))),
    Mistake("curve without its straight part", ": your sRGB curve has no straight part: up "
            "to code 0.04045 (light 0.0031308) it is the line c / 12.92, not the power "
            "(srgb_to_linear, linear_to_srgb compute it exactly)",
            gives=lambda c, i, b: _mix(c, i, b, _no_linear_part, _no_linear_part_back)),
    # r293 HN3: 6.2's slips, told the rule here
    Mistake("triangle 0 as background", ": you counted the samples of triangle 0 as "
            "uncovered: ids number the triangles from 0, and only −1 marks an uncovered sample "
            "(covered is ids ≥ 0, not ids > 0)",
            gives=lambda c, i, b: _mix(c, np.where(np.asarray(i) == 0, -1, i), b, _decode,
                                       _encode)),
    Mistake("NaN samples", ": uncovered samples hold NaN (no triangle wrote them), and a mean "
            "with NaN is NaN: put the background in them",
            gives=lambda c, i, b: _encode(_decode(c).mean(axis=0))
            if (np.asarray(i) < 0).any() else None),
    CHANNEL_ORDER,
    ON_255,
]  # fmt: skip


def explain(args, expected, got) -> str:
    colours, ids, background = args
    s, k = len(ids), int(_covered(ids).sum())
    return (f"ids {np.asarray(ids).tolist()} ({k} of {s} samples covered), sRGB-encoded "
            f"background {vec(background)}: the resolve in linear light, encoded, is "
            f"{vec(expected, got)}; yours is {vec(got, expected)}")  # fmt: skip


RESOLVE_SRGB = Exercise(
    "resolve_srgb", resolve_srgb_cases, as_colour, same_colour, explain, _rule, MISTAKES,
    answers=(PackageAnswer(Frame.resolve),), draw=draw_srgb_case,
    reference=("teachraster.exercises.antialiasing",), hints=((RULE, HINT), (_RECIPE, _RECIPE_HINT)), inputs_drawn=True,
    once=((RULE, "; as said for the first failing case"),),
)  # fmt: skip
