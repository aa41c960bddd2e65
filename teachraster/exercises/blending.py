"""Exercises ``over(src, dst)``, ``over_to_premultiplied(src, dst)`` and
``over_premultiplied(src, dst)`` of lesson 12: the blend equation.

``over_to_premultiplied`` takes straight colours (a translucent destination too) and returns
the premultiplied result: the derivation exercise 9.2 asks for, which lesson 12 does not print
(it prints the rule on premultiplied inputs).

The expected colours come from the core: :func:`teachraster.blend_equation` with the factor
pairs of ``render(..., blend="over" | "premultiplied")``. Each mistake is a wrong blend the
checker computes itself; a colour computed in float32 is right (within 1e-6).
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import BLEND_MODES, blend_equation
from .answers import as_numbers
from .exercise import Exercise, Mistake, PackageAnswer
from .scalars import vec
from .tolerance import all_close

SEED = 20241126


def blend_cases(mode: str) -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (src, dst), expected) for ``mode`` "over", "premultiplied" or "from
    straight" (straight inputs, the premultiplied result)."""
    pairs = [
        ("opaque red over blue", [1, 0, 0, 1], [0, 0, 1, 1]),
        ("half red over blue", [1, 0, 0, 0.5], [0, 0, 1, 1]),
        ("half red over transparent black", [1, 0, 0, 0.5], [0, 0, 0, 0]),
        ("transparent over grey", [0.3, 0.6, 0.9, 0.0], [0.5, 0.5, 0.5, 1]),
        ("quarter green over half grey", [0, 1, 0, 0.25], [0.5, 0.5, 0.5, 0.5]),
    ]
    if mode == "from straight":  # the task's "nothing at all when α = 0" (r8: never tested)
        pairs.append(("both transparent", [0.3, 0.6, 0.9, 0.0], [0.5, 0.2, 0.1, 0.0]))
    rng = np.random.default_rng(SEED + 1)
    for k in range(20):
        pairs.append((f"random colours {k}", *rng.uniform(0, 1, (2, 4)).round(3)))
    out = []
    for label, src, dst in pairs:
        src, dst = np.asarray(src, float), np.asarray(dst, float)
        if mode == "premultiplied":
            src = np.r_[src[:3] * src[3], src[3]]  # these cases hold premultiplied colours
            dst = np.r_[dst[:3] * dst[3], dst[3]]
        if mode == "from straight":  # straight in, premultiplied out (exercise 9.2)
            out.append((label, (src, dst), from_straight(src, dst)))
            continue
        out.append((label, (src, dst), blend_equation(src, dst, *BLEND_MODES[mode])))
    return out


def _rgba(value) -> np.ndarray:
    return as_numbers(value, (4,), "an RGBA colour, shape (4,)")


def explain_blend(args, expected, got) -> str:
    src, dst = args
    return (
        f"src = {vec(src)}, dst = {vec(dst)}: the blend is {vec(expected, got)}; yours is "
        f"{vec(got, expected)}"
    )


#: The premultiplied rule as exercise 9.2 asks for it: derived, so the explanation of a wrong
#: answer says how to derive it, never the factors to type (that would be the answer).
#: (Porter and Duff, 1984, work in premultiplied colours themselves: the divided rule for
#: straight colours is a later rewriting, "the straight-alpha form of over".)
_DERIVE = (": the straight-alpha form of over, with src and dst written as c = α·C, "
           "multiplied through by the result's alpha, on all four channels")  # fmt: skip
_FROM_STRAIGHT = (": the straight-alpha form of over multiplied through by the result's alpha: "
                  "each colour weighted by how much of it is seen, alpha as what either "
                  "covers")  # fmt: skip


def _rule(mode: str):
    if mode == "premultiplied":
        return lambda *a: _DERIVE
    if mode == "from straight":
        return lambda *a: _FROM_STRAIGHT
    s, d = BLEND_MODES[mode]
    return lambda *a: f": src·{s} + dst·{d} (glBlendFunc({s}, {d})), on all four channels"


def _scaled(src, dst, s, d):
    """src·s + dst·d, with s and d one factor or one per channel."""
    return np.asarray(src, float) * s + np.asarray(dst, float) * d


def _colour_only(src, dst, alpha):
    return np.r_[src[:3] * src[3] + dst[:3] * (1 - src[3]), alpha]


COMMON = [
    ("destination unchanged", "that is the destination unchanged: the source is blended over "
     "it, weighted by its alpha", lambda s, d: np.asarray(d, dtype=float)),
    ("source unchanged", "that is the source unchanged: it is blended over the destination, "
     "weighted by its alpha", lambda s, d: np.asarray(s, dtype=float)),
    ("destination alpha", "the destination alpha was used instead of the source alpha",
     lambda s, d: _scaled(s, d, d[3], 1 - d[3])),
    ("weights swapped", "you gave the source the weight 1 − α and the destination α: the "
     "source alpha weighs the source", lambda s, d: _scaled(s, d, 1 - s[3], s[3])),
    ("kept source alpha", "the alpha channel blends too: the result's alpha is not the "
     "source's", lambda s, d: _colour_only(s, d, s[3])),
    ("kept destination alpha", "the alpha channel blends too: the result's alpha is not the "
     "destination's", lambda s, d: _colour_only(s, d, d[3])),
]  # fmt: skip
OVER = [
    ("destination not scaled", "the destination was not scaled by (1 − α)",
     lambda s, d: _scaled(s, d, s[3], 1)),
    ("source not multiplied", "the source was not multiplied by its alpha (that is the "
     "premultiplied rule)", lambda s, d: _scaled(s, d, 1, 1 - s[3])),
    ("Porter-Duff alpha", "alpha was composed as Porter-Duff's a + (1 − a)·b; GL's 'over' uses "
     "one factor pair, SRC_ALPHA, for all four channels (alpha a² + (1 − a)·b)",
     lambda s, d: _colour_only(s, d, s[3] + d[3] * (1 - s[3]))),
]  # fmt: skip


def _porter_duff(src, dst):
    """(colour (3,), alpha) of straight src over straight dst (Porter and Duff)."""
    a = src[3] + dst[3] * (1 - src[3])
    weighted = src[:3] * src[3] + dst[:3] * dst[3] * (1 - src[3])
    return np.divide(weighted, a, out=np.zeros(3), where=a > 0), a


def _straight_rule(src, dst):
    """The straight-alpha rule copied onto premultiplied colours: alpha counted twice."""
    colour, a = _porter_duff(np.asarray(src, float), np.asarray(dst, float))
    return np.r_[colour, a]


def _returned_straight(src, dst):
    """The right premultiplied blend, then divided by its alpha: a straight colour."""
    src, dst = np.asarray(src, float), np.asarray(dst, float)
    out = src + dst * (1 - src[3])
    return np.r_[np.divide(out[:3], out[3], out=np.zeros(3), where=out[3] > 0), out[3]]


def _destination_again(src, dst):
    src, dst = np.asarray(src, float), np.asarray(dst, float)
    return np.r_[src[:3] + dst[:3] * dst[3] * (1 - src[3]), src[3] + dst[3] * (1 - src[3])]


PREMULTIPLIED = [
    ("destination not scaled", "the destination was not scaled by (1 − α)",
     lambda s, d: _scaled(s, d, 1, 1)),
    # Exercise 9.3 gives the straight rule and asks for the premultiplied one: the mistakes of
    # that derivation (issue 30: "straight alpha where premultiplied is expected").
    ("straight rule on premultiplied", "you applied the straight-alpha rule to premultiplied "
     "colours: their red, green and blue already carry their alpha, so weighting them by α "
     "again and dividing by the result's alpha counts alpha twice; multiply the straight rule "
     "through by the result's alpha instead", _straight_rule),
    ("returned straight", "you returned a straight colour (divided by the result's alpha): "
     "the buffer holds premultiplied colours, so the result stays multiplied by its alpha",
     _returned_straight),
    ("destination premultiplied twice", "you multiplied the destination by its alpha again, "
     "but it is premultiplied already: it is weighted by (1 − α) of the source alone",
     _destination_again),
    ("premultiplied twice", "you multiplied the source by its alpha again, but it is "
     "premultiplied already (that darkens the edges: the dark fringe); a premultiplied source "
     "already carries its alpha", lambda s, d: _scaled(s, d, s[3], 1 - s[3])),
    ("premultiplied twice", "you multiplied the source colour by its alpha again, but it is "
     "premultiplied already (the dark fringe): it already carries its alpha",
     lambda s, d: _colour_only(s, d, s[3] + d[3] * (1 - s[3]))),
]  # fmt: skip


def _premultiply(c) -> np.ndarray:
    c = np.asarray(c, float)
    return np.r_[c[:3] * c[3], c[3]]


def from_straight(src, dst) -> np.ndarray:
    """Straight src over straight dst, as a premultiplied RGBA (the reference)."""
    return blend_equation(_premultiply(src), _premultiply(dst), *BLEND_MODES["premultiplied"])


def _straight_result(src, dst):
    colour, a = _porter_duff(np.asarray(src, float), np.asarray(dst, float))
    return np.r_[colour, a]


def _divided_by_zero(args, expected, got) -> bool:
    """Both alphas 0 and a NaN returned: the straight colour divided by α = 0 first."""
    src, dst = args
    return src[3] == 0 and dst[3] == 0 and bool(np.isnan(np.asarray(got, float)).any())


FROM_STRAIGHT = [
    ("inputs not premultiplied", "you blended the straight colours as if they were "
     "premultiplied: each colour counts as much as it is seen, α·C, before it is added",
     lambda s, d: _scaled(s, d, 1, 1 - s[3])),
    ("returned straight", "you returned a straight colour (divided by the result's alpha): "
     "the answer is premultiplied, the colour multiplied by the result's alpha",
     _straight_result),
    ("destination alpha ignored", "you weighted the destination by (1 − α_s) alone, as GL's "
     "straight blend does: a translucent destination is seen only as much as its own alpha "
     "covers, α_d·(1 − α_s)", lambda s, d: np.r_[
         _scaled(s, d, s[3], 1 - s[3])[:3], s[3] + d[3] * (1 - s[3])]),
    ("GL's straight blend", "you used GL's straight blend, src·α + dst·(1 − α) on all four "
     "channels: it weights a translucent destination by (1 − α_s) alone and returns a "
     "straight colour", lambda s, d: _scaled(s, d, s[3], 1 - s[3])),
    ("destination not scaled", "the destination was not scaled by (1 − α_s)",
     lambda s, d: _premultiply(s) + _premultiply(d)),
    ("source unchanged", "that is the source unchanged: it is blended over the destination, "
     "weighted by its alpha", lambda s, d: np.asarray(s, dtype=float)),
    ("kept source alpha", "the alpha channel blends too: the result's alpha is what either "
     "covers, not the source's", lambda s, d: np.r_[from_straight(s, d)[:3], s[3]]),
]  # fmt: skip


def _mistakes(mode: str) -> list[Mistake]:
    if mode == "from straight":
        swapped = ("arguments swapped", "you blended dst over src: the first argument, src, "
                   "is the incoming fragment, the second, dst, what the buffer holds",
                   lambda s, d: from_straight(d, s))  # fmt: skip
        nan = Mistake("division by zero", "both alphas 0: the result is transparent black, not "
                      "a division by zero (nothing covers the pixel; multiplied through by the "
                      "result's alpha, nothing is left to divide)", fits=_divided_by_zero)  # fmt: skip
        return [nan, *(Mistake(k, w, gives=g) for k, w, g in FROM_STRAIGHT + [swapped])]
    table = (OVER if mode == "over" else PREMULTIPLIED) + COMMON
    factors = BLEND_MODES[mode]
    swapped = ("arguments swapped", "you blended dst over src: the first argument, src, is "
               "the incoming fragment, the second, dst, what the buffer holds",
               lambda s, d: blend_equation(d, s, *factors))  # fmt: skip
    return [Mistake(kind, words, gives=gives) for kind, words, gives in table + [swapped]]


def _exercise(name: str, mode: str) -> Exercise:
    return Exercise(
        name, lambda: blend_cases(mode), _rgba, lambda g, e, a: all_close(g, e, 1e-6),
        explain_blend, _rule(mode), _mistakes(mode), answers=(PackageAnswer(blend_equation),),
        draw=_draw_blend,
    )  # fmt: skip


def _draw_blend(ax, case, got):
    from .drawing import draw_values

    return draw_values(ax, ["R", "G", "B", "A"], case[2], got)


OVER_EXERCISE = _exercise("over", "over")
FROM_STRAIGHT_EXERCISE = Exercise(
    "over_to_premultiplied", lambda: blend_cases("from straight"), _rgba,
    lambda g, e, a: all_close(g, e, 1e-6), explain_blend, _rule("from straight"),
    _mistakes("from straight"), draw=_draw_blend,
    answers=(PackageAnswer(blend_equation), PackageAnswer(from_straight)),
)  # fmt: skip
PREMULTIPLIED_EXERCISE = _exercise("over_premultiplied", "premultiplied")
