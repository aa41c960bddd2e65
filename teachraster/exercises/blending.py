"""Exercise 9.2's and lesson 12b's blend checks: their cases and exercises, and lesson 12b's
``over(src, dst)`` (GL's straight blend) and ``over_premultiplied(src, dst)``.

The tasks' references and mistakes live by task: :mod:`.blend_straight` (9.2a's
``over_straight`` and lesson 12b's ``over_to_premultiplied``), :mod:`.blend_atop` (9.2b's
``atop_premultiplied``), :mod:`.blend_mistakes` (the mistakes they share: wrong alphas,
rounding, the glow) and :mod:`.blend_display` (colours in words and as swatches). Their
functions are the checker's own code too: each exercise names those modules as its
:attr:`~.exercise.Exercise.reference`, so a call into them is not counted.

``over_premultiplied`` holds a glow (alpha 0, light in it), which no straight colour holds: a
solution that divides by alpha to reuse 9.2a loses it, and is named.

The expected colours come from the core: :func:`teachraster.blend_equation` with the factor
pairs of ``render(..., blend="over" | "premultiplied")``. Each mistake is a wrong blend the
checker computes itself; a colour computed in float32 is right (within 1e-6).
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import BLEND_MODES, apply_blend, blend_equation, factor
from .blend_atop import ATOP, ATOP_RULE, atop_mistakes, premultiplied_atop
from .blend_display import as_rgba, blend_drawer, explain_blend
from .blend_display import colour_texts as colour_texts  # the tests import it from here
from .blend_mistakes import (
    CARRIES,
    EIGHT_BIT,
    GLOW,
    GLOW_DIVIDED,
    WHOLE_NUMBERS,
    ZERO_DIVIDED,
    alpha_mistakes,
    colour_only,
    glow_skipped_words,
    scaled,
)
from .blend_straight import (
    COMMON,
    FROM_STRAIGHT_RULE,
    STRAIGHT_RULE,
    STRAIGHT_STEP_WORDS,
    call_over_straight,
    from_straight,
    from_straight_mistakes,
    same_straight,
    straight_mistakes,
    straight_over,
)
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer
from .package_answers import CHECKER_WORDS
from .tolerance import all_close

#: The modules of the blend checks' own code, watched with this one (:mod:`.package_answers`).
BLEND_MODULES = tuple(f"{__package__}.{m}" for m in ("blend_atop", "blend_display",
                                                     "blend_mistakes", "blend_straight"))  # fmt: skip


SEED = 20241126


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
    if mode == "straight":  # r445 W2: a guard "α < 1e-3 → (0, 0, 0, 0)" passed
        pairs.append(("very faint blue over transparent black", [0, 0, 1, 1e-5], [0, 0, 0, 0]))
        # r513 W1: a guard on the light (no light → (0, 0, 0, 0)) passed: black still covers
        pairs.append(("half black over transparent black", [0, 0, 0, 0.5], [0, 0, 0, 0]))
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


#: The premultiplied rule as exercise 9.2 asks for it: derived, so the explanation of a wrong
#: answer says how to derive it, never the factors to type (that would be the answer). The
#: task gives Porter and Duff's coverage argument (Compositing Digital Images, 1984), not a
#: formula (r8: stating the straight form down to its numerator made 9.2a a transcription).
# r12 09-8: "your 9.2a ..." read as a diagnosis of the student's answer; it is the rule
_DERIVE = (": the blend is 9.2a's derivation with src and dst written as c = α·C (each "
           "already carries its alpha), on all four channels")  # fmt: skip


def _rule(mode: str):
    if mode == "premultiplied":
        return lambda *a: _DERIVE
    if mode == "straight":
        return lambda *a: STRAIGHT_RULE
    if mode == "atop":
        return lambda *a: ATOP_RULE
    if mode == "from straight":
        return lambda *a: FROM_STRAIGHT_RULE
    s, d = BLEND_MODES[mode]
    return lambda *a: f": src·{s} + dst·{d} (glBlendFunc({s}, {d})), on all four channels"


COMMON_PREMULTIPLIED = [
    ("destination unchanged", "that is the destination unchanged, as if the source were not "
     "there: a source that covers some of the pixel, or carries light, changes it",
     COMMON[0][2]),
    ("source unchanged", "that is the source unchanged, as if it covered the whole pixel: "
     "where its alpha is below 1 some of the destination still shows", COMMON[1][2]),
    ("destination alpha", "you weighted the source and the destination by the destination's "
     f"alpha: {CARRIES}, and the shares in which each shows depend on what covers what",
     COMMON[2][2]),
    ("weights swapped", "you swapped the two weights, the source's and the destination's "
     f"({CARRIES})", COMMON[3][2]),
    ("kept source alpha", "you multiplied the source colour by its alpha again and kept the "
     f"source's alpha: {CARRIES}, and the alpha channel blends like the colours",
     COMMON[4][2]),
    ("kept destination alpha", "you multiplied the source colour by its alpha again and kept "
     f"the destination's alpha: {CARRIES}, and the alpha channel blends like the colours",
     COMMON[5][2]),
]  # fmt: skip


OVER = [
    ("destination not scaled", "the destination was not scaled by (1 − α)",
     lambda s, d: scaled(s, d, s[3], 1)),
    ("source not multiplied", "the source was not multiplied by its alpha (that is the "
     "premultiplied rule)", lambda s, d: scaled(s, d, 1, 1 - s[3])),
    ("Porter-Duff alpha", "alpha was composed as Porter-Duff's a + (1 − a)·b; GL's 'over' uses "
     "one factor pair, SRC_ALPHA, for all four channels (alpha a² + (1 − a)·b)",
     lambda s, d: colour_only(s, d, s[3] + d[3] * (1 - s[3]))),
]  # fmt: skip


def _returned_straight(src, dst):
    """The right premultiplied blend, then divided by its alpha: a straight colour."""
    src, dst = np.asarray(src, float), np.asarray(dst, float)
    out = src + dst * (1 - src[3])
    return np.r_[np.divide(out[:3], out[3], out=np.zeros(3), where=out[3] > 0), out[3]]


def _destination_again(src, dst):
    src, dst = np.asarray(src, float), np.asarray(dst, float)
    return np.r_[src[:3] + dst[:3] * dst[3] * (1 - src[3]), src[3] + dst[3] * (1 - src[3])]


#: What premultiplying a source twice does to the picture (the same words in each entry).
TOO_DARK = ("every translucent source then shows only α of its colour, α·c where c belongs, "
            "and comes out too dark; at a soft edge, where α falls off, that draws a dark "
            "fringe like lesson 12b §4's")  # fmt: skip

PREMULTIPLIED = [
    ("destination not scaled", "the destination was not scaled by (1 − α)",
     lambda s, d: scaled(s, d, 1, 1)),
    # Exercise 9.3 gives the straight rule and asks for the premultiplied one: the mistakes of
    # that derivation (issue 30: "straight alpha where premultiplied is expected").
    # r20 D-2: "multiply the straight rule through by α" alone led to "9.2a reused"
    ("straight rule on premultiplied", "you applied the straight-alpha rule to premultiplied "
     "colours (9.2a's over_straight): their red, green and blue already carry their alpha, so "
     "weighting them by α again and dividing by the result's alpha counts alpha twice; "
     "multiply the straight rule through by the result's alpha, then write each colour in it "
     "as c = α·C (its weight α_s or α_d is already in c)", straight_over),
    ("returned straight", "you returned a straight colour (divided by the result's alpha): "
     "the buffer holds premultiplied colours, so the result stays multiplied by its alpha",
     _returned_straight),
    ("destination premultiplied twice", "you multiplied the destination by its alpha again, "
     "but it is premultiplied already: it is weighted by (1 − α) of the source alone",
     _destination_again),
    # r341 (capstone 12.9): the same slip on all four channels was told only the rule
    ("destination premultiplied twice", "you multiplied the destination by its alpha again, "
     "on all four channels (its alpha too: α_d·α_d), but it is premultiplied already: it is "
     "weighted by (1 − α) of the source alone", lambda s, d: s + d * d[3] * (1 - s[3])),
    # r222 item 6: "(the dark fringe)" was said of glass darkened all over: the source is too
    # dark wherever it is translucent, a fringe only at a soft edge
    ("premultiplied twice", f"you multiplied the source by its alpha again, but it is "
     f"premultiplied already ({TOO_DARK}); a premultiplied source already carries its alpha",
     lambda s, d: scaled(s, d, s[3], 1 - s[3])),
    ("premultiplied twice", f"you multiplied the source colour by its alpha again, but it is "
     f"premultiplied already ({TOO_DARK}): it already carries its alpha",
     lambda s, d: colour_only(s, d, s[3] + d[3] * (1 - s[3]))),
    # r8: the most natural slip after 9.2a, and the destination's own alpha as its weight
    ("9.2a reused", "you applied 9.2a's light (its sum before the division by α) to "
     "premultiplied colours: it multiplies each colour by its alpha, and these carry it "
     "already (c = α·C), so src and dst are both multiplied by their alpha twice (the dark "
     "fringe)", lambda s, d: from_straight(s, d)),
    ("destination's own alpha", "you weighted the destination by 1 − its own alpha: what "
     "shows of it is the share the source leaves uncovered, 1 − α_s",
     lambda s, d: scaled(s, d, 1, 1 - d[3])),
]  # fmt: skip


def _unpremultiplied(src, dst):
    """9.2a reused after dividing by alpha (0 where alpha is 0): a glow's light is lost."""

    def straight(c):
        c = np.asarray(c, float)
        return np.r_[np.divide(c[:3], c[3], out=np.zeros(3), where=c[3] > 0), c[3]]

    return from_straight(straight(src), straight(dst))


def _mistakes(mode: str) -> list[Mistake]:
    return [*_cause_mistakes(mode), WHOLE_NUMBERS, EIGHT_BIT]


def _cause_mistakes(mode: str) -> list[Mistake]:
    if mode == "atop":
        return atop_mistakes()
    if mode == "straight":
        return straight_mistakes()
    if mode == "from straight":
        return from_straight_mistakes()
    table = OVER + COMMON if mode == "over" else PREMULTIPLIED + COMMON_PREMULTIPLIED
    factors = BLEND_MODES[mode]
    swapped = ("arguments swapped", "you blended dst over src: the first argument, src, is "
               "the incoming fragment, the second, dst, what the buffer holds",
               lambda s, d: blend_equation(d, s, *factors))  # fmt: skip
    out = [Mistake(kind, words, gives=gives) for kind, words, gives in table + [swapped]]
    if mode == "premultiplied":
        out = [Mistake("glow lost", glow_skipped_words, gives=_unpremultiplied),
               GLOW_DIVIDED, ZERO_DIVIDED, *out]  # fmt: skip
        out += alpha_mistakes(lambda s, d: blend_equation(s, d, *factors))
    return out


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


def _exercise(name: str, mode: str, answers=None, call=None, same=None) -> Exercise:
    """The check of ``name``, whose cases are :func:`blend_cases` of ``mode``; ``answers``: the
    package's functions it does not count (default :func:`blend_answers`)."""
    return Exercise(
        name, lambda: blend_cases(mode), as_rgba, same or (lambda g, e, a: all_close(g, e, 1e-6)),
        explain_blend, _rule(mode), _mistakes(mode), answers=answers or blend_answers(),
        draw=blend_drawer(mode), inputs_drawn=True, example=5 if mode in PREMULTIPLIED_IN else 4,  # glow; quarter
        reference=BLEND_MODULES,  # the tasks' modules compute expected answers too
        call=call,
    )  # fmt: skip


OVER_EXERCISE = _exercise("over", "over")
FROM_STRAIGHT_EXERCISE = _exercise("over_to_premultiplied", "from straight")
PREMULTIPLIED_EXERCISE = _exercise("over_premultiplied", "premultiplied")
#: Exercise 9.2b since r20 (D-1): the checker's reference is its own code, not counted.
ATOP_EXERCISE = _exercise(
    "atop_premultiplied", "atop",
    (*blend_answers(), PackageAnswer(premultiplied_atop, words=CHECKER_WORDS)),
)  # fmt: skip
#: Exercise 9.2a: the package's blend is a step of it, the checker's reference its own code.
STRAIGHT_EXERCISE = _exercise(
    "over_straight", "straight",
    (*blend_answers(STRAIGHT_STEP_WORDS, CHECKER_WORDS),
     PackageAnswer(straight_over, words=CHECKER_WORDS)),  # r20 D-8
    call_over_straight, same_straight,  # r483 W2: where= without out= passed by luck
)  # fmt: skip
