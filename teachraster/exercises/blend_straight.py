"""Over on straight colours: exercise 9.2a's ``over_straight`` (straight in and out) and
lesson 12b's ``over_to_premultiplied`` (straight in, premultiplied out), their references and
their mistakes.

``over_to_premultiplied`` takes straight colours (a translucent destination too) and returns
the premultiplied result, from Porter and Duff's coverage argument (exercise 9.2 derives
straight over and premultiplied atop the same way). Lesson 12b §4 states the rule on
premultiplied inputs without deriving it, and premultiplying first, then applying that rule,
gives the same numbers: the check cannot tell a derivation from that route, and the notebook
says so (r9: it claimed the lesson printed neither); both alphas 0 is the case where the
straight form has no colour.
"""

from __future__ import annotations

import warnings

import numpy as np

from ..core.blend_factors import BLEND_MODES, blend_equation
from .blend_display import as_rgba
from .blend_mistakes import (
    ALPHAS,
    CHANNEL_ORDER,
    alpha_mistakes,
    colour_only,
    faint_words,
    scaled,
)
from .exercise import Mistake
from .scalars import num, vec
from .tolerance import all_close


def _porter_duff(src, dst):
    """(colour (3,), alpha) of straight src over straight dst (Porter and Duff)."""
    a = src[3] + dst[3] * (1 - src[3])
    weighted = src[:3] * src[3] + dst[:3] * dst[3] * (1 - src[3])
    return np.divide(weighted, a, out=np.zeros(3), where=a > 0), a


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


FROM_STRAIGHT_RULE = (": each colour counts in the share of the pixel where it shows (the source "
                  "in α_s, the destination in α_d of the 1 − α_s the source leaves), the "
                  "result's alpha is the share either covers, and the answer is premultiplied, "
                  "the colour times that alpha")  # fmt: skip


#: 9.2a's general message: the task asks the student to derive the weights, so a wrong answer
#: no mistake names is sent back to the derivation's steps, not given them (r19 E-2: this
#: stated both weights, the answer to step 1, on any careless first try).
STRAIGHT_RULE = (": go back through the derivation's steps: (1) in what share of the pixel "
                  "does the source show, and in what share the destination, which covers α_d "
                  "of any part of the pixel? (2) the light is each colour times its share, "
                  "summed; (3) the result's alpha α is the share either covers; (4) the "
                  "straight colour is that light divided by α, and where that division has no "
                  "answer, the task says what to return")  # fmt: skip


COMMON = [
    ("destination unchanged", "that is the destination unchanged: the source is blended over "
     "it, weighted by its alpha", lambda s, d: np.asarray(d, dtype=float)),
    ("source unchanged", "that is the source unchanged: it is blended over the destination, "
     "weighted by its alpha", lambda s, d: np.asarray(s, dtype=float)),
    ("destination alpha", "the destination alpha was used instead of the source alpha",
     lambda s, d: scaled(s, d, d[3], 1 - d[3])),
    ("weights swapped", "you gave the source the weight 1 − α and the destination α: the "
     "source alpha weighs the source", lambda s, d: scaled(s, d, 1 - s[3], s[3])),
    ("kept source alpha", "the alpha channel blends too: the result's alpha is not the "
     "source's", lambda s, d: colour_only(s, d, s[3])),
    ("kept destination alpha", "the alpha channel blends too: the result's alpha is not the "
     "destination's", lambda s, d: colour_only(s, d, d[3])),
]  # fmt: skip


def _gl_colour(src, dst) -> np.ndarray:
    """GL's straight colour, C_s·α_s + C_d·(1 − α_s) (a translucent destination weighted by
    1 − α_s alone), with over's right alpha."""
    s, d = np.asarray(src, float), np.asarray(dst, float)
    return np.r_[s[:3] * s[3] + d[:3] * (1 - s[3]), s[3] + d[3] * (1 - s[3])]


#: 9.2a's mistakes, straight result: each names what the answer shows.
STRAIGHT = [
    ("returned premultiplied", "you added the colours, each weighted by the share of the pixel "
     "where it shows, and stopped: that is α·C, the premultiplied colour; the task asks for "
     "the straight colour C, that light spread over the share α either covers, so divide it "
     "by α", from_straight),
    ("lesson's rule on straight colours", "you applied the rule for premultiplied colours, "
     "src + (1 − α_s)·dst, to straight ones: a straight colour does not carry its coverage, so "
     "each must first count in the share of the pixel where it shows (C·α), and the sum, "
     "α·C, divided by α", lambda s, d: scaled(s, d, 1, 1 - s[3])),
    ("GL's straight blend", "you used GL's straight blend (as the package's "
     "blend_equation(src, dst) does by default), src·α_s + dst·(1 − α_s) on all four "
     "channels: over a translucent destination its colour is wrong unless the source is "
     "opaque or wholly transparent (a translucent destination shows in α_d of the share "
     "1 − α_s, not in all of it), and its alpha weighs α_s by itself (α_s squared)",
     lambda s, d: scaled(s, d, s[3], 1 - s[3])),
    ("destination alpha ignored", "your alpha is right, but you weighted the destination's "
     "colour by (1 − α_s) alone, as GL's straight blend does: a translucent destination shows "
     "only in α_d of that share, and the sum is then divided by α",
     _gl_colour),
    # r18 D-3: the same GL habit with the task's division by α, the likelier form
    ("destination alpha ignored", "your alpha is right and you divided by it, but you weighted "
     "the destination's colour by (1 − α_s) alone, as GL's straight blend does: a translucent "
     "destination shows only in α_d of that share, so its light is C_d·α_d·(1 − α_s)",
     lambda s, d: _divided(_gl_colour(s, d))),
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
    # r289 M2: named in 9.2b and 9.3, and here it got the derivation's steps
    # r326 M3: the same rule with the task's division by α got the derivation's steps
    ("lesson's rule on straight colours, divided by α", "you added the straight colours "
     "without weighting them by their alphas (lesson 12b §4's rule for premultiplied colours, "
     "src + (1 − α_s)·dst, on straight inputs), then divided by α: a straight colour does not "
     "carry its coverage, so each must first count in the share of the pixel where it shows, "
     "C_s·α_s and C_d·α_d·(1 − α_s), before the sum is divided by α",
     lambda s, d: _divided(scaled(s, d, 1, 1 - s[3]))),
    ("premultiplied twice", "you multiplied each colour by its alpha twice (C·α·α, the dark "
     "fringe): the light of a straight colour is C·α, once, and the sum divided by α",
     lambda s, d: _divided(np.r_[s[:3] * s[3] ** 2 + d[:3] * d[3] ** 2 * (1 - s[3]),
                                 s[3] + d[3] * (1 - s[3])])),
    ("premultiplied twice", "you multiplied each colour by its alpha twice (C·α·α, the dark "
     "fringe) and did not divide: the light of a straight colour is C·α, once, and the "
     "straight answer is that light divided by α", lambda s, d: np.r_[
         s[:3] * s[3] ** 2 + d[:3] * d[3] ** 2 * (1 - s[3]), s[3] + d[3] * (1 - s[3])]),
]  # fmt: skip


def _faint_as_nothing(args, expected, got) -> bool:
    """(0, 0, 0, 0) where the result's alpha is above 0: a guard below some small alpha
    (r20 D-3: ``α < 0.01 → (0, 0, 0, 0)`` passed)."""
    g = np.asarray(got, float).ravel()
    return g.shape == (4,) and not g.any() and expected[3] > 0


#: "faint as nothing" only where it fits every failing answer (r22 D-6: an answer rounded to
#: whole numbers is (0, 0, 0, 0) wherever the blend rounds to 0, and was told it there too).
FAINT_STRAIGHT = Mistake(
    "faint as nothing", faint_words("the division in step 4 has an answer wherever α is "
                                     "above 0"),
    fits=_faint_as_nothing, only_whole=True)  # fmt: skip


def _dark_as_nothing(args, expected, got) -> bool:
    """(0, 0, 0, 0) where no light reaches you but something covers the pixel (r513 W1: a
    guard ``not light.any()`` passed)."""
    g = np.asarray(got, float).ravel()
    return g.shape == (4,) and not g.any() and expected[3] > 0 and not np.any(expected[:3])


#: r513 W1: before "faint as nothing", whose words say the alpha is faint
DARK_AS_NOTHING = Mistake(
    "no light as nothing",
    lambda a, e, g: (
        f"you returned (0, 0, 0, 0) where no light reaches you (black over black or over "
        f"nothing), but the result's alpha here is {num(float(e[3]), 0.0)}: black covers the "
        "pixel, it is not empty. (0, 0, 0, 0) is the answer only where α = 0: test the alpha, "
        "not the light"
    ),
    fits=_dark_as_nothing,
    only_whole=True,  # an answer rounded to whole numbers gives (0, 0, 0, 0) there too
)


def _where_nothing(which: int):
    """``fits``: input ``which`` (0 src, 1 dst) returned unchanged where both alphas are 0
    (r24 D-5: ``if alpha == 0: return dst``; r32 D9-1: ``return src`` there)."""

    def fits(args, expected, got) -> bool:
        given, g = np.asarray(args[which], float), np.asarray(got, float).ravel()
        return g.shape == (4,) and expected[3] == 0 and given.any() and all_close(g, given, 1e-6)

    return fits


def _nothing_words(which: int):
    """The words for :func:`_where_nothing`'s answer."""
    name = ("src", "dst")[which]
    return lambda a, e, g: (
        f"both alphas are 0 and you returned {name} {vec(a[which])} unchanged: nothing covers "
        "the pixel, so no colour shows there; the task gives the answer there, (0, 0, 0, 0)")  # fmt: skip


#: r24 D-5: 9.2a's "α = 0 → dst" got "go back through the derivation's steps".
DST_WHERE_NOTHING = Mistake("dst where nothing covers", _nothing_words(1), fits=_where_nothing(1))
#: r32 D9-1: "α = 0 → src" was told "you swapped the weights of over" (the swapped pair gives
#: src there too). only_whole: a swapped pair fails other cases as well, and is named there.
SRC_WHERE_NOTHING = Mistake("src where nothing covers", _nothing_words(0),
                            fits=_where_nothing(0), only_whole=True)  # fmt: skip


def _by_destination_alpha(args, expected, got) -> bool | None:
    """The right light divided by α_d instead of α, the result's alpha right (r326 M3); where
    α_d is 0, the light divided by a guard's tiny number (or inf), each channel without
    light 0 (or 0/0). None where nothing covers the pixel (a guard's answer) or α_d = α."""
    src, dst = (np.asarray(c, float) for c in args)
    g = np.asarray(got, float).ravel()
    a = src[3] + dst[3] * (1 - src[3])
    if g.shape != (4,) or a == 0 or dst[3] == a:
        return None
    if not all_close(g[3:], [a], 1e-6):
        return False
    light = src[:3] * src[3] + dst[:3] * dst[3] * (1 - src[3])
    if dst[3] > 0:
        return np.isfinite(g).all() and all_close(g[:3], light / dst[3], 1e-6)
    with np.errstate(invalid="ignore"):
        dark = (light == 0) & ((g[:3] == 0) | np.isnan(g[:3]))
        huge = (light > 0) & (g[:3] >= 1e6 * light)
    return bool((dark | huge).all())


#: r326 M3: the light divided by the destination's alpha got the derivation's steps.
BY_DESTINATION_ALPHA = Mistake(
    "divided by the destination's alpha", "you divided the light by the destination's alpha "
    "α_d: the straight colour is the light divided by the result's alpha, α = α_s + "
    "α_d·(1 − α_s), the share of the pixel either covers", fits=_by_destination_alpha)  # fmt: skip


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
     lambda s, d: scaled(s, d, 1, 1 - s[3])),
    ("returned straight", "you returned a straight colour (divided by the result's alpha): "
     "the answer is premultiplied, the colour multiplied by the result's alpha",
     _straight_result),
    ("destination alpha ignored", "you weighted the destination by (1 − α_s) alone, as GL's "
     "straight blend does: a translucent destination is seen only as much as its own alpha "
     "covers, α_d·(1 − α_s)", lambda s, d: np.r_[
         scaled(s, d, s[3], 1 - s[3])[:3], s[3] + d[3] * (1 - s[3])]),
    ("GL's straight blend", "you used GL's straight blend, src·α + dst·(1 − α) on all four "
     "channels: it weights a translucent destination by (1 − α_s) alone and returns a "
     "straight colour", lambda s, d: scaled(s, d, s[3], 1 - s[3])),
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
     lambda s, d: _times_alpha(_gl_colour(s, d))),
    ("multiplied by alpha twice", "you multiplied by the result's alpha twice: the colours "
     "added up, each weighted by how much of it is seen, are already the premultiplied colour "
     "α·C", lambda s, d: _times_alpha(from_straight(s, d))),
]  # fmt: skip


def _with_alpha(colour, src, dst) -> np.ndarray:
    """A colour with the right alpha of straight src over dst."""
    return np.r_[colour, src[3] + dst[3] * (1 - src[3])]


def _times_alpha(c) -> np.ndarray:
    return np.r_[c[:3] * c[3], c[3]]


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


#: What 9.2a's report says of a call into the package's blend (r23 D-3: "which computes this
#: very answer" was false: no factor pair gives a straight result, whose colour is divided by
#: α; the blend can compute a step of it).
STRAIGHT_STEP_WORDS = ("the package's blend is not counted as your work: write each step "
                       "yourself (no blend factor pair gives straight over, whose colour is "
                       "divided by the result's alpha, so a blend can only be a step of it)")  # fmt: skip


def _unhidden(src, dst) -> np.ndarray:
    """r445 H6b: the destination in its whole share α_d, the source not hiding it: the mean
    of the colours weighted by their alphas (α_s + α_d: (0, 0, 0, 0) where both are 0)."""
    s, d = np.asarray(src, float), np.asarray(dst, float)
    total, a = s[3] + d[3], s[3] + d[3] * (1 - s[3])
    return np.zeros(4) if total == 0 else np.r_[(s[:3] * s[3] + d[:3] * d[3]) / total, a]


def _over_summed_alphas(src, dst) -> np.ndarray:
    """r445 H6b: the right light divided by α_s + α_d instead of the result's alpha."""
    s, d = np.asarray(src, float), np.asarray(dst, float)
    total, a = s[3] + d[3], s[3] + d[3] * (1 - s[3])
    light = s[:3] * s[3] + d[:3] * d[3] * (1 - s[3])
    return np.zeros(4) if total == 0 else np.r_[light / total, a]


#: r445 H6b: two answers that got "go back through the derivation's steps".
UNHIDDEN = [
    Mistake("destination not hidden", "you let the destination show in its whole share α_d, "
            "also where the source covers it (your colour is the two colours' mean weighted "
            "by α_s and α_d): where the source covers the pixel it hides what lies behind it, "
            "so the destination shows only in α_d of the 1 − α_s the source leaves uncovered",
            gives=_unhidden),
    Mistake("light divided by α_s + α_d", "your light is right, but you divided it by "
            "α_s + α_d: that counts the share both cover twice; divide by the share either "
            "covers, the result's alpha α (your alpha is right)", gives=_over_summed_alphas),
]  # fmt: skip


class Uninitialised(np.ndarray):
    """An answer whose code called a numpy ufunc with ``where=`` and no ``out=`` (r483 W2):
    where the condition is False its entries are whatever the memory held."""


def call_over_straight(fn, args) -> np.ndarray:
    """Run ``fn``; an answer computed with ``where=`` and no ``out=`` (numpy warns) comes
    back as :class:`Uninitialised`, right or not by luck. Other warnings are passed on."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        value = as_rgba(fn(*args))
    unset = False
    for w in caught:
        if "without 'out'" in str(w.message):
            unset = True
        else:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    return np.asarray(value, float).view(Uninitialised) if unset else value


def same_straight(got, expected, args=None) -> bool:
    """Within 1e-6, and not by uninitialised memory's luck."""
    return not isinstance(got, Uninitialised) and all_close(got, expected, 1e-6)


UNINITIALISED = Mistake(
    "where without out", "you called a numpy function with where= but no out=: wherever its "
    "condition is False (α = 0: both inputs transparent) the entries it returns are "
    "uninitialised memory, any value, so your answer is right or wrong by luck (numpy warns: "
    "'where' used without 'out'). Pass out=np.zeros(3) (the answer there, before the "
    "division), or test α with an if",
    fits=lambda a, e, g: isinstance(g, Uninitialised))  # fmt: skip


def straight_mistakes() -> list[Mistake]:
    """9.2a's mistakes (``over_straight``): the division by α = 0, a guard, an input returned
    where both alphas are 0, the table's, the weights swapped, then a wrong alpha (with the
    colour divided by it, or right)."""
    nan = Mistake("division by zero", "both alphas 0: nothing covers the pixel, so α·C is 0 "
                  "and dividing it by α = 0 has no answer; the task gives the answer there, "
                  "(0, 0, 0, 0): test α before you divide", fits=_nan_at_zero)  # fmt: skip
    table = [Mistake(k, w, gives=g) for k, w, g in (*COMMON[:2], *STRAIGHT)]  # r14 09-7
    # only_whole: at α_s = ½ over an opaque destination the swap gives the right colour,
    # so a right colour with a wrong alpha fits it there; named only when it fits them all
    swapped = Mistake("weights swapped", _swapped_words, fits=_swapped_any_alpha,
                      only_whole=True)  # fmt: skip
    nothing = [DST_WHERE_NOTHING, SRC_WHERE_NOTHING]  # before the swap, which gives src there
    return [UNINITIALISED, nan, DARK_AS_NOTHING, FAINT_STRAIGHT, *nothing, *table, CHANNEL_ORDER, swapped, BY_DESTINATION_ALPHA,
            *_divided_by_wrong_alpha(), *UNHIDDEN,
            *alpha_mistakes(straight_over, STRAIGHT_ALPHAS)]  # fmt: skip


def from_straight_mistakes() -> list[Mistake]:
    """Lesson 12b's ``over_to_premultiplied``: the division by α = 0, the table's, then a wrong
    alpha with the right colour."""
    swapped = ("arguments swapped", "you blended dst over src: the first argument, src, "
               "is the incoming fragment, the second, dst, what the buffer holds",
               lambda s, d: from_straight(d, s))  # fmt: skip
    nan = Mistake("division by zero", "both alphas 0: the result is transparent black, not "
                  "a division by zero (nothing covers the pixel, so α·C is 0: the premultiplied "
                  "answer needs no division)", fits=_divided_by_zero)  # fmt: skip
    table = [Mistake(k, w, gives=g) for k, w, g in FROM_STRAIGHT + [swapped]]
    return [nan, *table, *alpha_mistakes(from_straight)]
