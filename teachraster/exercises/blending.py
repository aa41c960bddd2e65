"""Exercises ``over(src, dst)``, ``over_to_premultiplied(src, dst)`` and
``over_premultiplied(src, dst)`` of lesson 12b (the blend equation), and
``atop_premultiplied(src, dst)``, exercise 9.2b.

``over_to_premultiplied`` takes straight colours (a translucent destination too) and returns
the premultiplied result, from Porter and Duff's coverage argument (exercise 9.2 derives
straight over and premultiplied atop the same way). Lesson 12b §4 states the rule on premultiplied inputs without deriving it, and
premultiplying first, then applying that rule, gives the same numbers: the check cannot tell a
derivation from that route, and the notebook says so (r9: it claimed the lesson printed
neither); both alphas 0 is the case where the straight form has no colour. ``over_premultiplied`` holds a
glow (alpha 0, light in it), which no straight colour holds: a solution that divides by alpha
to reuse 9.2a loses it, and is named.

``atop_premultiplied`` is Porter and Duff's *atop* on premultiplied colours, derived from the
same two assumptions as 9.2a (r20 D-1: 9.2b was ``over_premultiplied``, the rule lesson 12b §1
and §4 print; lesson 12b prints no *atop*). It is one GL factor pair, (DST_ALPHA,
ONE_MINUS_SRC_ALPHA), so its expected answers come from the core's blend equation too.

Explanations print both colours with one number format (:func:`colour_texts`); the figure
shows src and dst as swatches, and the expected blend only beside an answer.

The expected colours come from the core: :func:`teachraster.blend_equation` with the factor
pairs of ``render(..., blend="over" | "premultiplied")``. Each mistake is a wrong blend the
checker computes itself; a colour computed in float32 is right (within 1e-6).
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import BLEND_MODES, apply_blend, blend_equation, factor
from .answers import as_numbers
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer
from .package_answers import CHECKER_WORDS
from .scalars import NOISE, num, vec
from .tolerance import all_close

SEED = 20241126
#: Porter and Duff's *atop* as a GL factor pair: the source where the destination covers, the
#: destination where the source does not (exercise 9.2b).
ATOP = ("DST_ALPHA", "ONE_MINUS_SRC_ALPHA")
#: The factor pairs of the modes whose inputs are premultiplied, by mode.
FACTORS = {**BLEND_MODES, "atop": ATOP}
#: Modes whose cases hold premultiplied colours (a glow among them).
PREMULTIPLIED_IN = ("premultiplied", "atop")


def blend_cases(mode: str) -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (src, dst), expected) for ``mode`` "over", "premultiplied", "atop"
    (premultiplied in and out), "from straight" (straight inputs, the premultiplied result) or
    "straight" (straight in and out)."""
    pairs = [
        ("opaque red over blue", [1, 0, 0, 1], [0, 0, 1, 1]),
        ("half red over blue", [1, 0, 0, 0.5], [0, 0, 1, 1]),
        ("half red over transparent black", [1, 0, 0, 0.5], [0, 0, 0, 0]),
        ("transparent over grey", [0.3, 0.6, 0.9, 0.0], [0.5, 0.5, 0.5, 1]),
        ("quarter green over half grey", [0, 1, 0, 0.25], [0.5, 0.5, 0.5, 0.5]),
    ]
    if mode in ("from straight", "straight"):  # "nothing at all when α = 0" (r8: never tested)
        pairs.append(("both transparent", [0.3, 0.6, 0.9, 0.0], [0.5, 0.2, 0.1, 0.0]))
        # r20 D-3: a guard "α < 0.01 → (0, 0, 0, 0)" passed; a faint pixel still has a colour
        pairs.append(("faint red over transparent black", [1, 0, 0, 0.004], [0, 0, 0, 0]))
        pairs.append(("faint over faint", [0.2, 0.9, 0.4, 0.003], [0.8, 0.1, 0.6, 0.002]))
    if mode == "atop":  # r22 D-1: a guard "α_d < 0.01 → (0, 0, 0, 0)" passed 55 of 60 runs
        pairs.append(("half red over faint blue", [1, 0, 0, 0.5], [0, 0, 1, 0.004]))
        pairs.append(("faint green over half grey", [0, 1, 0, 0.004], [0.5, 0.5, 0.5, 0.5]))
    rng = np.random.default_rng(SEED + 1)
    for k in range(20):
        pairs.append((f"random colours {k}", *rng.uniform(0, 1, (2, 4)).round(3)))
    now = drawn_rng()  # r11 09-B: a few drawn for this check, so a harvested table fails
    for k in range(DRAWN):
        pairs.append((f"colours drawn for this check {k + 1}", *now.uniform(0, 1, (2, 4)).round(3)))
    out = []
    for label, src, dst in pairs:
        src, dst = np.asarray(src, float), np.asarray(dst, float)
        label = label.replace(" over ", " atop ") if mode == "atop" else label
        if mode in PREMULTIPLIED_IN:
            src = np.r_[src[:3] * src[3], src[3]]  # these cases hold premultiplied colours
            dst = np.r_[dst[:3] * dst[3], dst[3]]
        if mode == "from straight":  # straight in, premultiplied out
            out.append((label, (src, dst), from_straight(src, dst)))
            continue
        if mode == "straight":  # straight in, straight out (exercise 9.2a)
            out.append((label, (src, dst), straight_over(src, dst)))
            continue
        out.append((label, (src, dst), blend_equation(src, dst, *FACTORS[mode])))
    if mode in PREMULTIPLIED_IN:  # what no straight colour holds: 9.2b's case to reason about
        src, dst = np.array(GLOW), np.array([0.25, 0.25, 0.5, 0.5])
        verb = "atop" if mode == "atop" else "over"
        out.insert(5, (f"a glow (light, alpha 0) {verb} half blue", (src, dst),
                       blend_equation(src, dst, *FACTORS[mode])))  # fmt: skip
    if mode == "atop":  # r22 D-2: a glowing destination (alpha 0) keeps its light under atop
        src, dst = np.array([0.2, 0.1, 0.0, 0.5]), np.array(GLOW)
        out.insert(6, ("half orange atop a glow (light, alpha 0)", (src, dst),
                       blend_equation(src, dst, *ATOP)))  # fmt: skip
    return out


#: A premultiplied colour with alpha 0 and light in it (a "superluminous" colour: a channel
#: above its alpha): premultiplied over, src + (1 − α_s)·dst, holds for any α_s, so it covers
#: nothing and adds its light (additive blending with no change of blend mode). No straight
#: colour holds it, so a solution that divides by alpha to reuse 9.2a loses it.
GLOW = (0.3, 0.2, 0.05, 0.0)


def _rgba(value) -> np.ndarray:
    return as_numbers(value, (4,), "an RGBA colour, shape (4,)")


def colour_texts(expected, got) -> tuple[str, str]:
    """Two RGBA colours, printed alike: each value with the same number of decimals in both
    (exact when 5 suffice, else the fewest that tell every two values apart), so that one
    value never prints two ways and two values never print alike (r8: 0.4375 was printed
    "0.4375" in one colour and "0.438" in the other).

    >>> colour_texts([0.1875, 0.4375, 0.1875, 0.625], [0.1875, 0.4375, 0.1875, 0.4375])
    ('(0.1875, 0.4375, 0.1875, 0.625)', '(0.1875, 0.4375, 0.1875, 0.4375)')
    >>> colour_texts([0.3, 0.12345678], [0.3, 0.12345679])
    ('(0.3, 0.12345678)', '(0.3, 0.12345679)')
    """
    e, g = np.asarray(expected, float).ravel(), np.asarray(got, float).ravel()
    values = [x for x in np.r_[e, g] if np.isfinite(x)]

    def text(x, d):
        if not np.isfinite(x):
            return repr(float(x))
        t = f"{x:.{d}f}".rstrip("0").rstrip(".")
        return "0" if t in ("", "-0") else t

    def tells_apart(d):
        return all(text(x, d) != text(y, d) for x in values for y in values
                   if abs(x - y) > NOISE * max(1.0, abs(x), abs(y)))  # fmt: skip

    exact = next((d for d in range(3, 6) if all(float(text(x, d)) == x for x in values)), None)
    digits = exact or next((d for d in range(3, 17) if tells_apart(d)), 17)
    return tuple("(" + ", ".join(text(x, digits) for x in v) + ")" for v in (e, g))


def explain_blend(args, expected, got) -> str:
    src, dst = args
    want, yours = colour_texts(expected, got)
    return f"src = {vec(src)}, dst = {vec(dst)}: the blend is {want}; yours is {yours}"


#: The premultiplied rule as exercise 9.2 asks for it: derived, so the explanation of a wrong
#: answer says how to derive it, never the factors to type (that would be the answer). The
#: task gives Porter and Duff's coverage argument (Compositing Digital Images, 1984), not a
#: formula (r8: stating the straight form down to its numerator made 9.2a a transcription).
# r12 09-8: "your 9.2a ..." read as a diagnosis of the student's answer; it is the rule
_DERIVE = (": the blend is 9.2a's derivation with src and dst written as c = α·C (each "
           "already carries its alpha), on all four channels")  # fmt: skip
_FROM_STRAIGHT = (": each colour counts in the share of the pixel where it shows (the source "
                  "in α_s, the destination in α_d of the 1 − α_s the source leaves), the "
                  "result's alpha is the share either covers, and the answer is premultiplied, "
                  "the colour times that alpha")  # fmt: skip


#: 9.2a's general message: the task asks the student to derive the weights, so a wrong answer
#: no mistake names is sent back to the derivation's steps, not given them (r19 E-2: this
#: stated both weights, the answer to step 1, on any careless first try).
_STRAIGHT_RULE = (": go back through the derivation's steps: (1) in what share of the pixel "
                  "does the source show, and in what share the destination, which covers α_d "
                  "of any part of the pixel? (2) the light is each colour times its share, "
                  "summed; (3) the result's alpha α is the share either covers; (4) the "
                  "straight colour is that light divided by α, and where that division has no "
                  "answer, the task says what to return")  # fmt: skip


def _rule(mode: str):
    if mode == "premultiplied":
        return lambda *a: _DERIVE
    if mode == "straight":
        return lambda *a: _STRAIGHT_RULE
    if mode == "atop":
        return lambda *a: _ATOP_RULE
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
#: COMMON's outputs with words true of premultiplied colours (r18 D-2: COMMON's "the source
#: alpha weighs the source" is the straight rule, and following it on premultiplied colours
#: gives "premultiplied twice"). Each names what the answer did, never the weights the rule
#: gives (r20 D-5: "the source covers its share α_s … multiplied by its alpha" was the rule).
_CARRIES = "a premultiplied colour already carries its alpha (c = α·C)"
COMMON_PREMULTIPLIED = [
    ("destination unchanged", "that is the destination unchanged, as if the source were not "
     "there: a source that covers some of the pixel, or carries light, changes it",
     COMMON[0][2]),
    ("source unchanged", "that is the source unchanged, as if it covered the whole pixel: "
     "where its alpha is below 1 some of the destination still shows", COMMON[1][2]),
    ("destination alpha", "you weighted the source and the destination by the destination's "
     f"alpha: {_CARRIES}, and the shares in which each shows depend on what covers what",
     COMMON[2][2]),
    ("weights swapped", "you swapped the two weights, the source's and the destination's "
     f"({_CARRIES})", COMMON[3][2]),
    ("kept source alpha", "you multiplied the source colour by its alpha again and kept the "
     f"source's alpha: {_CARRIES}, and the alpha channel blends like the colours",
     COMMON[4][2]),
    ("kept destination alpha", "you multiplied the source colour by its alpha again and kept "
     f"the destination's alpha: {_CARRIES}, and the alpha channel blends like the colours",
     COMMON[5][2]),
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
    # r20 D-2: "multiply the straight rule through by α" alone led to "9.2a reused"
    ("straight rule on premultiplied", "you applied the straight-alpha rule to premultiplied "
     "colours (9.2a's over_straight): their red, green and blue already carry their alpha, so "
     "weighting them by α again and dividing by the result's alpha counts alpha twice; "
     "multiply the straight rule through by the result's alpha, then write each colour in it "
     "as c = α·C (its weight α_s or α_d is already in c)", _straight_rule),
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
    # r8: the most natural slip after 9.2a, and the destination's own alpha as its weight
    ("9.2a reused", "you applied 9.2a's light (its sum before the division by α) to "
     "premultiplied colours: it multiplies each colour by its alpha, and these carry it "
     "already (c = α·C), so src and dst are both multiplied by their alpha twice (the dark "
     "fringe)", lambda s, d: from_straight(s, d)),
    ("destination's own alpha", "you weighted the destination by 1 − its own alpha: what "
     "shows of it is the share the source leaves uncovered, 1 − α_s",
     lambda s, d: _scaled(s, d, 1, 1 - d[3])),
]  # fmt: skip


def premultiplied_atop(src, dst) -> np.ndarray:
    """Premultiplied src atop premultiplied dst (exercise 9.2b's reference): GL's blend with
    :data:`ATOP`'s factor pair."""
    return blend_equation(np.asarray(src, float), np.asarray(dst, float), *ATOP)


def _atop(colour, s, d) -> np.ndarray:
    """A colour with atop's right alpha, the destination's."""
    return np.r_[colour, d[3]]


def _as_straight(c) -> np.ndarray:
    c = np.asarray(c, float)
    return np.r_[np.divide(c[:3], c[3], out=np.zeros(3), where=c[3] > 0), c[3]]


def _atop_via_straight(src, dst):
    """Both divided by their alpha (0 where it is 0), atop derived on straight colours, then
    premultiplied: a glow's light is lost."""
    s, d = _as_straight(src), _as_straight(dst)
    return np.r_[s[:3] * s[3] * d[3] + d[:3] * d[3] * (1 - s[3]), d[3]]


#: 9.2b's general message: the derivation's steps, never its weights (r19 E-2, r20 D-5).
_ATOP_RULE = (": go back through the derivation: (1) split the pixel into the shares src and "
              "dst cover together, alone, or neither covers (their coverages are "
              "uncorrelated); (2) which colour shows in each share under atop; (3) the light "
              "is each colour times the share where it shows, and the result's alpha the "
              "share something shows in; (4) the inputs and the answer are premultiplied: "
              "write each colour as c = α·C")  # fmt: skip

#: 9.2b's named mistakes: each says what the answer did (r20 D-1). s and d are premultiplied.
ATOP_MISTAKES = [
    ("over, not atop", "that is over, lesson 12b §4's rule: it lets the source show in its "
     "whole share of the pixel, also where the destination does not cover it",
     lambda s, d: s + d * (1 - s[3])),
    ("over, not atop", "your alpha is right, but your colour is over's, lesson 12b §4's rule: "
     "it lets the source show in its whole share of the pixel, also where the destination "
     "does not cover it", lambda s, d: _atop(s[:3] + d[:3] * (1 - s[3]), s, d)),
    ("straight rule on premultiplied", "you derived atop for straight colours and applied it "
     "to premultiplied ones: src and dst already carry their alpha (c = α·C), so each got "
     "its alpha twice (the dark fringe); write each colour of your light as c = α·C",
     lambda s, d: _atop(s[:3] * s[3] * d[3] + d[:3] * d[3] * (1 - s[3]), s, d)),
    ("straight rule on premultiplied", "you derived atop for straight colours, applied it to "
     "premultiplied ones and divided the light by the result's alpha: src and dst already "
     "carry their alpha (c = α·C), and the answer stays premultiplied (no division)",
     lambda s, d: _atop(s[:3] * s[3] + d[:3] * (1 - s[3]), s, d)),
    # r24 D-6: "its alpha counts α_s twice"; it is α_s·α_s + α_d(1 − α_s)
    ("GL's straight blend", "you used GL's straight blend, src·α_s + dst·(1 − α_s), on "
     f"premultiplied colours: {_CARRIES}", lambda s, d: _scaled(s, d, s[3], 1 - s[3])),
    ("premultiplied twice", "you multiplied the source by its alpha again, but it is "
     f"premultiplied already (the dark fringe): {_CARRIES}",
     lambda s, d: _atop(s[:3] * s[3] * d[3] + d[:3] * (1 - s[3]), s, d)),
    ("premultiplied twice", "you multiplied the source by its alpha again, on all four "
     f"channels, but it is premultiplied already (the dark fringe): {_CARRIES}",
     lambda s, d: s * s[3] * d[3] + d * (1 - s[3])),
    ("destination premultiplied twice", "you multiplied the destination by its alpha again, "
     f"but it is premultiplied already: {_CARRIES}",
     lambda s, d: _atop(s[:3] * d[3] + d[:3] * d[3] * (1 - s[3]), s, d)),
    ("returned straight", "you returned a straight colour (divided by the result's alpha): "
     "the answer is premultiplied, as src and dst are", lambda s, d: _as_straight(
         premultiplied_atop(s, d))),
    ("weights swapped", "you swapped the two weights, the source's and the destination's "
     f"({_CARRIES})", lambda s, d: s * (1 - s[3]) + d * d[3]),
    # r22 D-8: the same on red, green and blue, with atop's alpha
    ("weights swapped", "your alpha is right, but you swapped the colour's two weights, the "
     f"source's and the destination's ({_CARRIES})",
     lambda s, d: _atop(s[:3] * (1 - s[3]) + d[:3] * d[3], s, d)),
    ("destination not scaled", "you added the whole destination: where the source covers it, "
     "the source hides it", lambda s, d: s * d[3] + d),
    ("destination's own alpha", "you weighted the destination by 1 − its own alpha: what "
     "hides it is the source", lambda s, d: s * d[3] + d * (1 - d[3])),
    ("source where the destination is not", "you weighted the source by 1 − α_d: that draws "
     "it where the destination does not cover it (Porter and Duff's *out*, or their *xor*)",
     lambda s, d: _atop(s[:3] * (1 - d[3]) + d[:3] * (1 - s[3]), s, d)),
    ("source where the destination is not", "you weighted the source by 1 − α_d, on all four "
     "channels: that draws it where the destination does not cover it (Porter and Duff's "
     "*xor*)", lambda s, d: s * (1 - d[3]) + d * (1 - s[3])),
    ("destination left out", "you left the destination out (Porter and Duff's *in*): where "
     "the source does not cover it, it still shows", lambda s, d: s * d[3]),
    ("destination unchanged", "that is the destination unchanged, as if the source were not "
     "there: where both cover the pixel, or the source carries light, it changes the pixel",
     lambda s, d: np.asarray(d, dtype=float)),
    ("source unchanged", "that is the source unchanged: atop draws it only on what the "
     "destination covers, and some of the destination shows where the source does not cover",
     lambda s, d: np.asarray(s, dtype=float)),
    ("arguments swapped", "you computed dst atop src: the first argument, src, is the "
     "incoming fragment, drawn on the second, dst, what the buffer holds",
     lambda s, d: premultiplied_atop(d, s)),
]  # fmt: skip

#: 9.2b's wrong alphas with the right colour (its right alpha is the destination's, so
#: :data:`ALPHAS`'s "alpha of the destination" would be no mistake).
ATOP_ALPHAS = [
    ("alpha of over", "you composed the alpha as over does: atop's result covers only the "
     "shares where something of it shows", lambda s, d: s[3] + d[3] * (1 - s[3])),
    ("alpha of the source", "you kept the source's alpha: atop's result covers only the "
     "shares where something of it shows", lambda s, d: s[3]),
    ("alpha of the shared share", "your alpha is the share both cover: where the destination "
     "covers alone, it still shows", lambda s, d: s[3] * d[3]),
    ("alpha summed", "you added the two alphas: atop's result covers only the shares where "
     "something of it shows", lambda s, d: s[3] + d[3]),
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


def straight_over(src, dst) -> np.ndarray:
    """Straight src over straight dst, as a straight RGBA (C, α), (0, 0, 0, 0) where α = 0:
    exercise 9.2a's reference (r11 09-A: asked for the premultiplied result, 9.2a was lesson
    12 §9's rule on premultiplied inputs, and the check could not tell the two apart)."""
    return _straight_result(src, dst)


def _divided(c) -> np.ndarray:
    """A premultiplied RGBA as a straight one (0 where its alpha is 0)."""
    c = np.asarray(c, float)
    return np.r_[np.divide(c[:3], c[3], out=np.zeros(3), where=c[3] != 0), c[3]]


#: 9.2a's mistakes, straight result: each names what the answer shows.
STRAIGHT = [
    ("returned premultiplied", "you added the colours, each weighted by the share of the pixel "
     "where it shows, and stopped: that is α·C, the premultiplied colour; the task asks for "
     "the straight colour C, that light spread over the share α either covers, so divide it "
     "by α", from_straight),
    ("lesson's rule on straight colours", "you applied the rule for premultiplied colours, "
     "src + (1 − α_s)·dst, to straight ones: a straight colour does not carry its coverage, so "
     "each must first count in the share of the pixel where it shows (C·α), and the sum, "
     "α·C, divided by α", lambda s, d: _scaled(s, d, 1, 1 - s[3])),
    ("GL's straight blend", "you used GL's straight blend, src·α_s + dst·(1 − α_s) on all four "
     "channels: over a translucent destination its colour is wrong unless the source is "
     "opaque or wholly transparent (a translucent destination shows in α_d of the share "
     "1 − α_s, not in all of it), and its alpha weighs α_s by itself (α_s squared)",
     lambda s, d: _scaled(s, d, s[3], 1 - s[3])),
    ("destination alpha ignored", "your alpha is right, but you weighted the destination's "
     "colour by (1 − α_s) alone, as GL's straight blend does: a translucent destination shows "
     "only in α_d of that share, and the sum is then divided by α",
     lambda s, d: np.r_[s[:3] * s[3] + d[:3] * (1 - s[3]), s[3] + d[3] * (1 - s[3])]),
    # r18 D-3: the same GL habit with the task's division by α, the likelier form
    ("destination alpha ignored", "your alpha is right and you divided by it, but you weighted "
     "the destination's colour by (1 − α_s) alone, as GL's straight blend does: a translucent "
     "destination shows only in α_d of that share, so its light is C_d·α_d·(1 − α_s)",
     lambda s, d: _divided(np.r_[s[:3] * s[3] + d[:3] * (1 - s[3]),
                                 s[3] + d[3] * (1 - s[3])])),
    ("weights swapped", "you swapped the weights of over: the source counts in its own share "
     "α_s of the pixel, not in the 1 − α_s it leaves uncovered, and the destination in α_d of "
     "that uncovered share", lambda s, d: _divided(np.r_[
         s[:3] * (1 - s[3]) + d[:3] * d[3] * s[3], s[3] + d[3] * (1 - s[3])])),
    ("destination not scaled", "you did not scale the destination by (1 − α_s): it shows only "
     "in the share of the pixel the source leaves uncovered, so its colour counts "
     "α_d·(1 − α_s), not α_d", lambda s, d: _divided(np.r_[
         s[:3] * s[3] + d[:3] * d[3], s[3] + d[3] * (1 - s[3])])),
    ("arguments swapped", "you blended dst over src: the first argument, src, is the incoming "
     "fragment, the second, dst, what the buffer holds", lambda s, d: straight_over(d, s)),
]  # fmt: skip


def _faint_as_nothing(args, expected, got) -> bool:
    """(0, 0, 0, 0) where the result's alpha is above 0: a guard below some small alpha
    (r20 D-3: ``α < 0.01 → (0, 0, 0, 0)`` passed)."""
    g = np.asarray(got, float).ravel()
    return g.shape == (4,) and not g.any() and expected[3] > 0


def _faint_words(why: str):
    """The words of "faint as nothing", ending in ``why`` (the exercise's reason). The alpha
    is the case's, so they call the pixel covered, not "faint" (r22 D-6: α = 0.377 was "a
    faint pixel")."""

    def words(args, expected, got) -> str:
        return (f"you returned (0, 0, 0, 0), nothing there, but the result's alpha here is "
                f"{num(float(expected[3]), 0.0)}: something covers this pixel, however little "
                f"of it, so it is not empty; {why}")  # fmt: skip

    return words


#: "faint as nothing" only where it fits every failing answer (r22 D-6: an answer rounded to
#: whole numbers is (0, 0, 0, 0) wherever the blend rounds to 0, and was told it there too).
FAINT_STRAIGHT = Mistake(
    "faint as nothing", _faint_words("the division in step 4 has an answer wherever α is "
                                     "above 0"),
    fits=_faint_as_nothing, only_whole=True)  # fmt: skip
_FAINT_ATOP = _faint_words("atop draws the source on whatever the destination covers, "
                           "however little, and premultiplied colours blend as they are, "
                           "with no test on alpha")  # fmt: skip


def _dst_where_nothing(args, expected, got) -> bool:
    """dst returned where both alphas are 0 (r24 D-5: ``if alpha == 0: return dst``)."""
    dst, g = np.asarray(args[1], float), np.asarray(got, float).ravel()
    return g.shape == (4,) and expected[3] == 0 and dst.any() and all_close(g, dst, 1e-6)


#: r24 D-5: 9.2a's "α = 0 → dst" got "go back through the derivation's steps".
DST_WHERE_NOTHING = Mistake(
    "dst where nothing covers", lambda a, e, g: (
        f"both alphas are 0 and you returned dst {vec(a[1])} unchanged: nothing covers the "
        "pixel, so no colour shows there; the task gives the answer there, (0, 0, 0, 0)"),
    fits=_dst_where_nothing)  # fmt: skip


def _nothing_returned(args, expected, got) -> bool:
    """(0, 0, 0, 0) where the blend is not: a guard on a small alpha, or 9.2a's "(0, 0, 0, 0)
    where α = 0" carried over to a glow (r22 D-1, D-2)."""
    g = np.asarray(got, float).ravel()
    return g.shape == (4,) and not g.any() and bool(np.asarray(expected, float).any())


def _nothing_words(args, expected, got) -> str:
    if expected[3] > 0:
        return _FAINT_ATOP(args, expected, got)
    glow = next((f"{n} {vec(c)} is a glow" for n, c in zip(("src", "dst"), args) if _is_glow(c)),
                "an input is a glow")  # fmt: skip
    return (f"you returned (0, 0, 0, 0) where the result's alpha is 0, but {glow}: "
            "premultiplied light with alpha 0, covering nothing. A premultiplied colour with "
            "alpha 0 is (0, 0, 0, 0) only when it carries no light, and atop keeps the "
            "destination's light wherever the source does not cover it")  # fmt: skip


def _source_skipped(args, expected, got) -> bool:
    """The destination returned where the source carries something: a guard that skips a
    faint source, or a glow, for its alpha."""
    src, dst = (np.asarray(c, float) for c in args)
    g = np.asarray(got, float).ravel()
    return g.shape == (4,) and src.any() and all_close(g, dst, 1e-6)


def _source_skipped_words(args, expected, got) -> str:
    if _is_glow(args[0]):
        return _glow_skipped_words(args, expected, got)
    return (f"your answer is the destination unchanged, as if src {vec(args[0])} were not "
            "there: a source with a small alpha still draws its share on the destination "
            "(premultiplied colours blend as they are, with no test on alpha)")  # fmt: skip


#: r22 D-1: a guard "α_s < 0.01 → dst" (named at the glow, general at the faint source).
SOURCE_SKIPPED = Mistake("source skipped", _source_skipped_words, fits=_source_skipped,
                         only_whole=True)  # fmt: skip


#: Named only where it fits every failing answer: a rounded answer is (0, 0, 0, 0) wherever
#: the blend rounds to 0 (r22 D-6), and is "whole numbers".
NOTHING_ATOP = Mistake("nothing returned", _nothing_words, fits=_nothing_returned,
                       only_whole=True)  # fmt: skip


def _glow_added_whole(src, dst):
    """A glowing source's light added whole ("it covers nothing, so its light just adds"),
    the rest atop (r22 D-8); None where the source is no glow (nothing to say)."""
    return np.asarray(src, float) + np.asarray(dst, float) if _is_glow(src) else None


def _dst_glow_kept(src, dst):
    """A glowing destination's light kept whole under the source (r22 D-2); None where the
    destination is no glow."""
    s, d = np.asarray(src, float), np.asarray(dst, float)
    return s * d[3] + d if _is_glow(d) else None


def _clamped_to_alpha(src, dst):
    """Atop with its colour clamped to its alpha ("a premultiplied colour never exceeds its
    alpha"), true of coverage, not of light (r22 D-8)."""
    out = premultiplied_atop(src, dst)
    return np.r_[np.minimum(out[:3], out[3]), out[3]]


GLOW_MISTAKES = [
    Mistake("glow added whole", lambda a, e, g: (
        f"src {vec(a[0])} is a glow (alpha 0, light in it) and you added all of its light: "
        "atop shows the source, a glow's light too, only where the destination covers, "
        "in the share α_d of the pixel"), gives=_glow_added_whole),
    Mistake("glow added whole", lambda a, e, g: (
        f"dst {vec(a[1])} is a glow (alpha 0, light in it) and you kept all of its light: "
        "the source hides it where the source covers, in the share α_s of the pixel, as it "
        "hides any destination"), gives=_dst_glow_kept),
    Mistake("colour clamped to alpha", "you clamped the colour to the result's alpha: a "
            "premultiplied colour stays below its alpha only when it is a straight colour "
            "times its coverage; light (a glow) can exceed it, and atop keeps it",
            gives=_clamped_to_alpha),
]  # fmt: skip


def _nan_at_zero(args, expected, got) -> bool:
    """Both alphas 0 and a NaN (or inf) returned: divided by α = 0."""
    src, dst = args
    return src[3] == 0 and dst[3] == 0 and not np.isfinite(np.asarray(got, float)).all()


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
    # r9 (issue 30: "over with swapped weights"; O9): alpha right, the colour's weights wrong
    ("weights swapped", "you swapped the weights of over: the source counts in its own share "
     "α_s of the pixel (C_s·α_s), not in the 1 − α_s it leaves uncovered, and the destination "
     "in α_d of that uncovered share, α_d·(1 − α_s), not in α_d·α_s",
     lambda s, d: _with_alpha(s[:3] * (1 - s[3]) + d[:3] * d[3] * s[3], s, d)),
    ("weights swapped", "you swapped the weights of over, on all four channels: the source "
     "counts in its own share α_s of the pixel, not in the 1 − α_s it leaves uncovered, and the "
     "destination in the share α_d·(1 − α_s) of what the source leaves, not in α_d·α_s",
     lambda s, d: np.r_[s[:3] * (1 - s[3]) + d[:3] * d[3] * s[3], 1 - s[3] + d[3] * s[3]]),
    ("destination not scaled", "you did not scale the destination by (1 − α_s) (your alpha is "
     "right): it shows only in the share of the pixel the source leaves uncovered, so its "
     "colour counts α_d·(1 − α_s), not α_d",
     lambda s, d: _with_alpha(s[:3] * s[3] + d[:3] * d[3], s, d)),
    ("source unchanged", "that is the source unchanged: it is blended over the destination, "
     "weighted by its alpha", lambda s, d: np.asarray(s, dtype=float)),
    # r11 09-F: got the rule restated
    ("GL's straight colour times α", "you took GL's straight colour, C_s·α_s + C_d·(1 − α_s), "
     "and multiplied it by the result's alpha: GL weights a translucent destination by "
     "(1 − α_s) alone, as if it covered the pixel, but it shows only in α_d of that share; "
     "the colours added up, each weighted by the share where it shows, are already α·C",
     lambda s, d: _times_alpha(np.r_[s[:3] * s[3] + d[:3] * (1 - s[3]),
                                     s[3] + d[3] * (1 - s[3])])),
    ("multiplied by alpha twice", "you multiplied by the result's alpha twice: the colours "
     "added up, each weighted by how much of it is seen, are already the premultiplied colour "
     "α·C", lambda s, d: _times_alpha(from_straight(s, d))),
]  # fmt: skip


def _with_alpha(colour, src, dst) -> np.ndarray:
    """A colour with the right alpha of straight src over dst."""
    return np.r_[colour, src[3] + dst[3] * (1 - src[3])]


def _times_alpha(c) -> np.ndarray:
    return np.r_[c[:3] * c[3], c[3]]


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

#: 9.2a's wrong alphas: :data:`ALPHAS` and two more a straight answer reaches (r23 D-4).
STRAIGHT_ALPHAS = [
    *ALPHAS,
    ("alpha of the shared share", "your alpha is the share both cover, α_s·α_d; where one "
     "covers alone, something still shows", lambda s, d: s[3] * d[3]),
    ("alpha the larger", "your alpha is the larger of the two; where the one with it leaves "
     "the pixel uncovered, the other still covers some of it", lambda s, d: max(s[3], d[3])),
    # r24 D-5: min(1, α_s + α_d) got the general message
    ("alpha summed, clamped to 1", "you added the two alphas and clamped the sum to 1: that "
     "counts the share both cover twice; the destination covers only its share α_d of what "
     "the source leaves uncovered", lambda s, d: min(1.0, s[3] + d[3])),
]  # fmt: skip


def _divided_by_wrong_alpha() -> list[Mistake]:
    """9.2a's light divided by a wrong alpha of :data:`STRAIGHT_ALPHAS` ((0, 0, 0, 0) where
    that alpha is 0): the colour is off too (r23 D-4: GL's single-pair alpha
    α_s·α_s + α_d·(1 − α_s), which lesson 12b prints, got the general message)."""

    def gives(alpha):
        def wrong(src, dst):
            s, d = np.asarray(src, float), np.asarray(dst, float)
            a = float(alpha(s, d))
            light = s[:3] * s[3] + d[:3] * d[3] * (1 - s[3])
            return np.zeros(4) if a == 0 else np.r_[light / a, a]

        return wrong

    head = "your alpha is wrong, and your colour is the light divided by it, so it is off too: "
    return [Mistake(f"{k}, colour divided by it", head + w, gives=gives(a))
            for k, w, a in STRAIGHT_ALPHAS]  # fmt: skip


def _alpha_mistakes(right, alphas=ALPHAS, share=_SHARE) -> list[Mistake]:
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


def _swapped_colours(src, dst, alpha) -> list[np.ndarray]:
    """The colours over's factor pair gives swapped, source by 1 − α_s and destination by
    α_s: GL's pair (the destination's own alpha left out) and Porter and Duff's (α_d kept),
    each as it is and divided by ``alpha``."""
    a = src[3]
    out = []
    for colour in (src[:3] * (1 - a) + dst[:3] * a, src[:3] * (1 - a) + dst[:3] * dst[3] * a):
        out.append(colour)
        if alpha != 0:
            out.append(colour / alpha)
    return out


def _swapped_any_alpha(args, expected, got) -> bool:
    """The swapped factor pair, whatever the alpha (r19 E-1: swapped on all four channels it
    was told "your red, green and blue are right", true only where α_s = ½ makes the two
    weights equal, and its alpha mended, it got the general recipe)."""
    src, dst = (np.asarray(c, float) for c in args)
    g = np.asarray(got, float).ravel()
    if g.shape != (4,) or not np.isfinite(g).all():
        return False
    alphas = {float(g[3]), float(expected[3])}
    return any(all_close(g[:3], c, 1e-6) for a in alphas for c in _swapped_colours(src, dst, a))


def _swapped_words(args, expected, got) -> str:
    alpha = ("" if all_close(np.asarray(got, float)[3:], expected[3:], 1e-6) else
             "; your alpha is wrong too: the result's alpha is the share of the pixel src or dst "
             "covers")  # fmt: skip
    return ("you swapped the weights of over: the source counts in its "
            "own share α_s of the pixel, not in the 1 − α_s it leaves uncovered, and the "
            "destination in α_d of that uncovered share, not in the share α_s the source "
            "covers" + alpha)  # fmt: skip


def _unpremultiplied(src, dst):
    """9.2a reused after dividing by alpha (0 where alpha is 0): a glow's light is lost."""

    def straight(c):
        c = np.asarray(c, float)
        return np.r_[np.divide(c[:3], c[3], out=np.zeros(3), where=c[3] > 0), c[3]]

    return from_straight(straight(src), straight(dst))


def _is_glow(c) -> bool:
    return c[3] == 0 and bool((np.asarray(c[:3]) > 0).any())


def _glowing(args) -> str | None:
    """ "src (…)" or "dst (…)": the first input that is a glow (9.2b has a glowing
    destination too, r22 D-2), or None."""
    return next((f"{n} {vec(c)}" for n, c in zip(("src", "dst"), args) if _is_glow(c)), None)


def _glow_lost(args, expected, got) -> bool:
    """A glow (alpha 0, light in it) among the inputs and a NaN answer: divided by its alpha."""
    return _glowing(args) is not None and bool(np.isnan(np.asarray(got, float)).any())


def _zero_divided(args, expected, got) -> bool:
    """An input with alpha 0 (no glow) and a NaN answer: 0/0 from dividing by alpha."""
    src, dst = args
    zero = src[3] == 0 or dst[3] == 0
    return zero and _glowing(args) is None and bool(np.isnan(np.asarray(got, float)).any())


def _glow_words(args, expected, got) -> str:
    """A NaN at the glow: only a division by its alpha 0 gives one (r23 D-1: it named src
    also where the glow is dst)."""
    return (f"{_glowing(args)} is a glow: premultiplied light with alpha 0, covering nothing. "
            "No straight colour holds it, so dividing by alpha (to work on straight colours, "
            "as 9.2a does) divides by zero; blended premultiplied, as it is, its light "
            "counts")  # fmt: skip


def _glow_skipped_words(args, expected, got) -> str:
    """The destination unchanged at the glow, matched by the answer, not the route (r18 D-1:
    a student who skipped a source with alpha 0 was told they had divided by alpha)."""
    return (f"your answer is the destination unchanged, as if src {vec(args[0])} were not "
            "there; it is a glow: premultiplied light with alpha 0, covering nothing but "
            "carrying light. A premultiplied source with alpha 0 draws nothing only when its "
            "red, green and blue are 0 too, so it cannot be skipped for its alpha alone (nor "
            "divided by that alpha to work on straight colours, as 9.2a does, which loses its "
            "light the same way)")  # fmt: skip


def _atop_glow_lost_words(args, expected, got) -> str:
    """9.2b's "glow lost" (:func:`_atop_via_straight`, or both inputs' colours clamped to
    their alpha), in words true of the input that glows (r23 D-1: at a glowing destination
    the answer, (0, 0, 0, 0), was called "the destination unchanged" and the source, alpha
    ½, "a glow")."""
    if _is_glow(args[0]):
        return _glow_skipped_words(args, expected, got)
    return (f"your answer is atop as if dst {vec(args[1])} carried no light, but it is a "
            "glow: premultiplied light with alpha 0, covering nothing but carrying light. "
            "Dividing it by its alpha 0 to work on straight colours, as 9.2a does (or clamping "
            "its colour to that alpha), loses its light; atop keeps a destination's light "
            "wherever the source does not cover it, a glow's too")  # fmt: skip


def _mistakes(mode: str) -> list[Mistake]:
    return [*_cause_mistakes(mode), WHOLE_NUMBERS, EIGHT_BIT]


def _atop_mistakes() -> list[Mistake]:
    """9.2b's: the glow (divided by its alpha, or skipped for it), then the table's, then the
    colour right with a wrong alpha."""
    zero = ("an input has alpha 0: dividing by it to get a straight colour back is 0/0; "
            "premultiplied colours blend as they are, with no division")  # fmt: skip
    table = [Mistake(k, w, gives=g) for k, w, g in ATOP_MISTAKES]
    share = "the result's alpha is the share of the pixel in which something of it shows"
    return [Mistake("glow lost", _atop_glow_lost_words, gives=_atop_via_straight),
            Mistake("glow lost", _glow_words, fits=_glow_lost),
            Mistake("divided by alpha", zero, fits=_zero_divided), *table, *GLOW_MISTAKES,
            NOTHING_ATOP, SOURCE_SKIPPED, *_alpha_mistakes(premultiplied_atop, ATOP_ALPHAS, share)]  # fmt: skip


def _cause_mistakes(mode: str) -> list[Mistake]:
    if mode == "atop":
        return _atop_mistakes()
    if mode == "straight":
        nan = Mistake("division by zero", "both alphas 0: nothing covers the pixel, so α·C is 0 "
                      "and dividing it by α = 0 has no answer; the task gives the answer there, "
                      "(0, 0, 0, 0): test α before you divide", fits=_nan_at_zero)  # fmt: skip
        table = [Mistake(k, w, gives=g) for k, w, g in (*COMMON[:2], *STRAIGHT)]  # r14 09-7
        # only_whole: at α_s = ½ over an opaque destination the swap gives the right colour,
        # so a right colour with a wrong alpha fits it there; named only when it fits them all
        swapped = Mistake("weights swapped", _swapped_words, fits=_swapped_any_alpha,
                          only_whole=True)  # fmt: skip
        return [nan, FAINT_STRAIGHT, DST_WHERE_NOTHING, *table, swapped, *_divided_by_wrong_alpha(),
                *_alpha_mistakes(straight_over, STRAIGHT_ALPHAS)]  # fmt: skip
    if mode == "from straight":
        swapped = ("arguments swapped", "you blended dst over src: the first argument, src, "
                   "is the incoming fragment, the second, dst, what the buffer holds",
                   lambda s, d: from_straight(d, s))  # fmt: skip
        nan = Mistake("division by zero", "both alphas 0: the result is transparent black, not "
                      "a division by zero (nothing covers the pixel, so α·C is 0: the premultiplied "
                      "answer needs no division)", fits=_divided_by_zero)  # fmt: skip
        table = [Mistake(k, w, gives=g) for k, w, g in FROM_STRAIGHT + [swapped]]
        return [nan, *table, *_alpha_mistakes(from_straight)]
    table = OVER + COMMON if mode == "over" else PREMULTIPLIED + COMMON_PREMULTIPLIED
    factors = BLEND_MODES[mode]
    swapped = ("arguments swapped", "you blended dst over src: the first argument, src, is "
               "the incoming fragment, the second, dst, what the buffer holds",
               lambda s, d: blend_equation(d, s, *factors))  # fmt: skip
    out = [Mistake(kind, words, gives=gives) for kind, words, gives in table + [swapped]]
    if mode == "premultiplied":
        zero = (
            "an input has alpha 0: dividing by it to get a straight colour back is 0/0; "
            "premultiplied colours blend as they are, with no division"
        )
        out = [Mistake("glow lost", _glow_skipped_words, gives=_unpremultiplied),
               Mistake("glow lost", _glow_words, fits=_glow_lost),
               Mistake("divided by alpha", zero, fits=_zero_divided), *out]  # fmt: skip
        out += _alpha_mistakes(lambda s, d: blend_equation(s, d, *factors))
    return out


#: What 9.2a's report says of a call into the package's blend (r23 D-3: "which computes this
#: very answer" was false: no factor pair gives a straight result, whose colour is divided by
#: α; the blend can compute a step of it).
STRAIGHT_STEP_WORDS = ("the package's blend is not counted as your work: write each step "
                       "yourself (no blend factor pair gives straight over, whose colour is "
                       "divided by the result's alpha, so a blend can only be a step of it)")  # fmt: skip


def blend_answers(
    words: str | None = None, checker: str | None = None
) -> tuple[PackageAnswer, ...]:
    """Every route into the package's blending (r9: the private ``apply_blend`` passed
    unflagged while ``tr.blend_equation`` was flagged): the blend module's functions, which
    every render blends through, and the checker's own reference. ``words``: what the report
    says of them instead (an exercise whose answer is more than one blend); ``checker``: of
    the checker's reference (default ``words``, else :data:`CHECKER_WORDS`)."""
    step = "the blend this exercise asks you to write"
    return (PackageAnswer(blend_equation, words=words),
            PackageAnswer(apply_blend, what=step, words=words),
            PackageAnswer(factor, what=f"the blend factors, a part of {step}", words=words),
            PackageAnswer(from_straight, words=checker or words or CHECKER_WORDS))  # fmt: skip


def _exercise(name: str, mode: str) -> Exercise:
    return Exercise(
        name, lambda: blend_cases(mode), _rgba, lambda g, e, a: all_close(g, e, 1e-6),
        explain_blend, _rule(mode), _mistakes(mode), answers=blend_answers(),
        draw=_blend_drawer(mode), example=5 if mode in PREMULTIPLIED_IN else 4,  # glow; quarter
    )  # fmt: skip


def swatches(ax, cells, names, straight=(), gap=None):
    """RGBA colours as swatches over a checkerboard, each named with its four numbers below.

    ``cells`` are premultiplied, except those whose index is in ``straight``. From index
    ``gap`` on, the swatches stand a little further right (their labels apart from those
    before them). Returns the artists.
    """
    check = (np.indices((8, 8)).sum(axis=0) % 2)[..., None] * 0.3 + 0.6
    left = [k * 1.3 + (0.6 if gap is not None and k >= gap else 0) for k in range(len(cells))]
    artists = []
    for k, c in enumerate(cells):
        c = np.clip(np.nan_to_num(np.asarray(c, float)), 0, 1)
        rgb = c[:3] * c[3] if k in straight else c[:3]
        image = np.clip(rgb + (1 - c[3]) * check, 0, 1)  # premultiplied over the checkerboard
        artists.append(ax.imshow(image, extent=(left[k], left[k] + 1, 1, 0)))
    ax.set_xlim(-0.15, max(left[-1] + 1.3 if left else 0, 2 * 1.3))
    ax.set_ylim(1.05, -0.05)
    ax.set_xticks([x + 0.5 for x in left], names, fontsize="x-small")
    ax.set_yticks([])
    return artists


def _two_lines(rgba: str) -> str:
    """ "(r, g, b, a)" as "(r, g," over "b, a)": four columns fit under their swatches; with
    numbers of more than four digits, one number a line (r11 09-D: "(0.1875, 0.4375," ran into
    its neighbour's label: four labels share the axes' width, however the swatches are spaced)."""
    r, g, rest = rgba.split(", ", 2)
    if len(f"{r}, {g},") > 13:
        return ",\n".join(rgba.split(", "))
    return f"{r}, {g},\n{rest}"


def _blend_drawer(mode: str):
    """draw(ax, case, got): src and dst as swatches, then the expected blend and yours (r8:
    the bars never showed src and dst); before any answer (``got`` None), src and dst only,
    so that the figure never shows the answer first."""
    straight_in = mode in ("over", "from straight", "straight")

    def draw(ax, case, got):
        src, dst = case[1]
        cells, names = [src, dst], ["src", "dst"]
        if got is not None:
            want, yours = colour_texts(case[2], got)
            cells += [case[2], got]
            names += [f"expected\n{_two_lines(want)}", f"yours\n{_two_lines(yours)}"]
        names[:2] = [f"{n}\n{_two_lines(vec(c))}" for n, c in zip(names[:2], cells[:2])]
        straight = (0, 1) if straight_in else ()
        straight += (2, 3) if mode in ("over", "straight") else ()
        artists = swatches(ax, cells, names, straight)
        kinds = {
            "over": "straight inputs and results",
            "premultiplied": "premultiplied inputs and results",
            "atop": "premultiplied inputs and results",
            "from straight": "straight inputs, premultiplied results",
            "straight": "straight inputs and results",
        }
        artists.append(ax.set_xlabel(f"{kinds[mode]}, drawn over a checkerboard",
                                     fontsize="x-small"))  # fmt: skip
        return artists

    return draw


OVER_EXERCISE = _exercise("over", "over")
FROM_STRAIGHT_EXERCISE = Exercise(
    "over_to_premultiplied", lambda: blend_cases("from straight"), _rgba,
    lambda g, e, a: all_close(g, e, 1e-6), explain_blend, _rule("from straight"),
    _mistakes("from straight"), draw=_blend_drawer("from straight"),
    answers=blend_answers(), example=4,  # quarter green over half grey: both translucent
)  # fmt: skip
PREMULTIPLIED_EXERCISE = _exercise("over_premultiplied", "premultiplied")
#: Exercise 9.2b since r20 (D-1): the checker's reference is its own code, not counted.
ATOP_EXERCISE = Exercise(
    "atop_premultiplied", lambda: blend_cases("atop"), _rgba,
    lambda g, e, a: all_close(g, e, 1e-6), explain_blend, _rule("atop"), _mistakes("atop"),
    draw=_blend_drawer("atop"),
    answers=(*blend_answers(), PackageAnswer(premultiplied_atop, words=CHECKER_WORDS)),
    example=5,  # the glow
)  # fmt: skip
STRAIGHT_EXERCISE = Exercise(
    "over_straight", lambda: blend_cases("straight"), _rgba,
    lambda g, e, a: all_close(g, e, 1e-6), explain_blend, _rule("straight"),
    _mistakes("straight"), draw=_blend_drawer("straight"),
    answers=(*blend_answers(STRAIGHT_STEP_WORDS, CHECKER_WORDS),
             PackageAnswer(straight_over, words=CHECKER_WORDS)),  # r20 D-8
    example=4,  # quarter green over half grey: both translucent
)  # fmt: skip
