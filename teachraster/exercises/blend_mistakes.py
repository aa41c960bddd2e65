"""Mistakes and words the blend checks share (exercise 9.2, lesson 12b's blend exercises, and
:mod:`.front_to_back`): the scaled sums the tables build their wrong blends from, a right
colour with a wrong alpha, an answer rounded to whole numbers or to 8 bits, a guard that
returns nothing for a faint pixel, and the glow (a premultiplied colour with alpha 0 and
light in it), which no straight colour holds and a division by alpha loses."""

from __future__ import annotations

import numpy as np

from .channel_order import channel_order_mistake
from .exercise import Mistake
from .scalars import num, vec
from .tolerance import all_close

#: A premultiplied colour with alpha 0 and light in it (a "superluminous" colour: a channel
#: above its alpha): premultiplied over, src + (1 − α_s)·dst, holds for any α_s, so it covers
#: nothing and adds its light (additive blending with no change of blend mode). No straight
#: colour holds it, so a solution that divides by alpha to reuse 9.2a loses it.
GLOW = (0.3, 0.2, 0.05, 0.0)


def scaled(src, dst, s, d):
    """src·s + dst·d, with s and d one factor or one per channel."""
    return np.asarray(src, float) * s + np.asarray(dst, float) * d


def colour_only(src, dst, alpha):
    return np.r_[src[:3] * src[3] + dst[:3] * (1 - src[3]), alpha]


#: The right colour in another channel order (r289 M1: ARGB, BGRA, red and alpha swapped got
#: "go back through the derivation"), in 9.2a and 9.2b.
CHANNEL_ORDER = channel_order_mistake("the right colours in another channel order", ": return "
                                      "(r, g, b, a), alpha last", tol=1e-6)  # fmt: skip


#: COMMON's outputs with words true of premultiplied colours (r18 D-2: COMMON's "the source
#: alpha weighs the source" is the straight rule, and following it on premultiplied colours
#: gives "premultiplied twice"). Each names what the answer did, never the weights the rule
#: gives (r20 D-5: "the source covers its share α_s … multiplied by its alpha" was the rule).
CARRIES = "a premultiplied colour already carries its alpha (c = α·C)"


def faint_words(why: str):
    """The words of "faint as nothing", ending in ``why`` (the exercise's reason). The alpha
    is the case's, so they call the pixel covered, not "faint" (r22 D-6: α = 0.377 was "a
    faint pixel")."""

    def words(args, expected, got) -> str:
        return (f"you returned (0, 0, 0, 0), nothing there, but the result's alpha here is "
                f"{num(float(expected[3]), 0.0)}: something covers this pixel, however little "
                f"of it, so it is not empty; {why}")  # fmt: skip

    return words


#: Colour right, alpha wrong (r8: these got the generic sentence): the alpha each slip gives.
_RIGHT_COLOUR = "your red, green and blue are right, your alpha is not: "


ALPHAS = [
    ("alpha summed", "you added the two alphas; the destination covers only its share α_d of "
     "what the source leaves uncovered", lambda s, d: s[3] + d[3]),
    ("alpha squared", "you weighted the source's alpha by itself, α_s·α_s, as GL's straight "
     "blend does on the fourth channel; the source covers α_s of the pixel",
     lambda s, d: s[3] * s[3] + d[3] * (1 - s[3])),
    ("alpha of the source", "you kept the source's alpha; where it leaves the pixel uncovered "
     "the destination covers some of it too", lambda s, d: s[3]),
    ("alpha of the destination", "you kept the destination's alpha; the source covers its "
     "share α_s of the pixel first", lambda s, d: d[3]),
]  # fmt: skip


_SHARE = "the result's alpha is the share of the pixel src or dst covers"


def alpha_mistakes(right, alphas=ALPHAS, share=_SHARE) -> list[Mistake]:
    """The colour ``right(src, dst)`` gives with each wrong alpha of ``alphas``, then the
    symptom for any other alpha."""

    def gives(alpha):
        return lambda s, d: np.r_[
            right(s, d)[:3], alpha(np.asarray(s, float), np.asarray(d, float))
        ]

    def colour_right(args, expected, got):
        g = np.asarray(got, float)
        return all_close(g[:3], expected[:3], 1e-6) and not all_close(g[3:], expected[3:], 1e-6)

    out = [Mistake(k, _RIGHT_COLOUR + w, gives=gives(a)) for k, w, a in alphas]
    words = _RIGHT_COLOUR + share
    return out + [Mistake("alpha only", words, fits=colour_right, symptom=True)]


def _whole_numbers(args, expected, got) -> bool:
    """The answer rounded, or cut, to whole numbers (``np.round``, ``astype(int)``) where it
    has a fraction (r20 D-7); a guard's (0, 0, 0, 0) is whole too, but not the answer's
    rounding."""
    g, e = np.asarray(got, float).ravel(), np.asarray(expected, float).ravel()
    if g.shape != e.shape or (e == np.round(e)).all():
        return False
    return bool((g == np.round(e)).all() or (g == np.trunc(e)).all())


#: r20 D-7: an answer rounded to whole numbers (or cast to int) got only the general message.
WHOLE_NUMBERS = Mistake(
    "whole numbers", "your answer is whole numbers (rounded, or converted to int): colours "
    "and alphas are fractions between 0 and 1, so keep them as floats",
    fits=_whole_numbers, symptom=True, only_whole=True,  # every failing answer whole
)  # fmt: skip


def _eight_bit(args, expected, got) -> bool:
    """Every channel either right or rounded (or cut) to a step of 1/255, as an 8-bit buffer
    stores it, and some channel off that grid in the expected answer (r23 D-4)."""
    try:
        g = np.asarray(got, float).ravel()
    except (TypeError, ValueError):
        return False
    e = np.asarray(expected, float).ravel()
    if g.shape != e.shape or not np.isfinite(g).all() or (e * 255 == np.round(e * 255)).all():
        return False
    exact = np.abs(g - e) <= 1e-9
    return any(bool((exact | (np.abs(g - q) <= 1e-9)).all())
               for q in (np.round(e * 255) / 255, np.floor(e * 255) / 255))  # fmt: skip


#: r23 D-4: an answer rounded to 8 bits, ``round(x·255)/255``, was sent back to the steps.
EIGHT_BIT = Mistake(
    "8-bit rounding", "your answer is rounded to steps of 1/255, as an 8-bit buffer stores "
    "it: the check compares floats (within 1e-6), so keep them unrounded",
    fits=_eight_bit, symptom=True, only_whole=True,
)  # fmt: skip


def is_glow(c) -> bool:
    return c[3] == 0 and bool((np.asarray(c[:3]) > 0).any())


def glowing(args) -> str | None:
    """ "src (…)" or "dst (…)": the first input that is a glow (9.2b has a glowing
    destination too, r22 D-2), or None."""
    return next((f"{n} {vec(c)}" for n, c in zip(("src", "dst"), args) if is_glow(c)), None)


def _glow_lost(args, expected, got) -> bool:
    """A glow (alpha 0, light in it) among the inputs and a NaN answer: divided by its alpha."""
    return glowing(args) is not None and bool(np.isnan(np.asarray(got, float)).any())


def _zero_divided(args, expected, got) -> bool:
    """An input with alpha 0 (no glow) and a NaN answer: 0/0 from dividing by alpha."""
    src, dst = args
    zero = src[3] == 0 or dst[3] == 0
    return zero and glowing(args) is None and bool(np.isnan(np.asarray(got, float)).any())


def _glow_words(args, expected, got) -> str:
    """A NaN at the glow: only a division by its alpha 0 gives one (r23 D-1: it named src
    also where the glow is dst)."""
    return (f"{glowing(args)} is a glow: premultiplied light with alpha 0, covering nothing. "
            "No straight colour holds it, so dividing by alpha (to work on straight colours, "
            "as 9.2a does) divides by zero; blended premultiplied, as it is, its light "
            "counts")  # fmt: skip


def glow_skipped_words(args, expected, got) -> str:
    """The destination unchanged at the glow, matched by the answer, not the route (r18 D-1:
    a student who skipped a source with alpha 0 was told they had divided by alpha)."""
    return (f"your answer is the destination unchanged, as if src {vec(args[0])} were not "
            "there; it is a glow: premultiplied light with alpha 0, covering nothing but "
            "carrying light. A premultiplied source with alpha 0 draws nothing only when its "
            "red, green and blue are 0 too, so it cannot be skipped for its alpha alone (nor "
            "divided by that alpha to work on straight colours, as 9.2a does, which loses its "
            "light the same way)")  # fmt: skip


#: A glow's light lost to a division by its alpha 0 (a NaN answer), in 9.2b and lesson 12b's
#: ``over_premultiplied``.
GLOW_DIVIDED = Mistake("glow lost", _glow_words, fits=_glow_lost)
#: 0/0 at an input with alpha 0 and no light (a NaN answer), in the same two.
ZERO_DIVIDED = Mistake(
    "divided by alpha", "an input has alpha 0: dividing by it to get a straight colour back is "
    "0/0; premultiplied colours blend as they are, with no division", fits=_zero_divided)  # fmt: skip
