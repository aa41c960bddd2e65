"""Exercise 9.2b, ``atop_premultiplied``: Porter and Duff's *atop* on premultiplied colours,
derived from the same two assumptions as 9.2a (r20 D-1: 9.2b was ``over_premultiplied``, the
rule lesson 12b §1 and §4 print; lesson 12b prints no *atop*). It is one GL factor pair,
(DST_ALPHA, ONE_MINUS_SRC_ALPHA), so its expected answers come from the core's blend equation
too. Its cases hold a glow as the source and as the destination: a solution that divides by
alpha, skips an input for its alpha, or clamps a colour to its alpha loses its light, and is
named.
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import blend_equation
from .blend_mistakes import (
    CARRIES,
    CHANNEL_ORDER,
    GLOW_DIVIDED,
    ZERO_DIVIDED,
    alpha_mistakes,
    faint_words,
    glow_skipped_words,
    glowing,
    is_glow,
    scaled,
)
from .exercise import Mistake
from .scalars import vec
from .tolerance import all_close

#: Porter and Duff's *atop* as a GL factor pair: the source where the destination covers, the
#: destination where the source does not (exercise 9.2b).
ATOP = ("DST_ALPHA", "ONE_MINUS_SRC_ALPHA")


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
ATOP_RULE = (": go back through the derivation: (1) split the pixel into the shares src and "
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
     f"premultiplied colours: {CARRIES}", lambda s, d: scaled(s, d, s[3], 1 - s[3])),
    ("premultiplied twice", "you multiplied the source by its alpha again, but it is "
     f"premultiplied already (the dark fringe): {CARRIES}",
     lambda s, d: _atop(s[:3] * s[3] * d[3] + d[:3] * (1 - s[3]), s, d)),
    ("premultiplied twice", "you multiplied the source by its alpha again, on all four "
     f"channels, but it is premultiplied already (the dark fringe): {CARRIES}",
     lambda s, d: s * s[3] * d[3] + d * (1 - s[3])),
    ("destination premultiplied twice", "you multiplied the destination by its alpha again, "
     f"but it is premultiplied already: {CARRIES}",
     lambda s, d: _atop(s[:3] * d[3] + d[:3] * d[3] * (1 - s[3]), s, d)),
    # r483 H3: the same on all four channels got the derivation's steps restated
    ("destination premultiplied twice", "you multiplied the destination by its alpha again, "
     f"on all four channels, but it is premultiplied already: {CARRIES}",
     lambda s, d: s * d[3] + d * d[3] * (1 - s[3])),
    ("returned straight", "you returned a straight colour (divided by the result's alpha): "
     "the answer is premultiplied, as src and dst are", lambda s, d: _as_straight(
         premultiplied_atop(s, d))),
    ("weights swapped", "you swapped the two weights, the source's and the destination's "
     f"({CARRIES})", lambda s, d: s * (1 - s[3]) + d * d[3]),
    # r22 D-8: the same on red, green and blue, with atop's alpha
    ("weights swapped", "your alpha is right, but you swapped the colour's two weights, the "
     f"source's and the destination's ({CARRIES})",
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


_FAINT_ATOP = faint_words("atop draws the source on whatever the destination covers, "
                           "however little, and premultiplied colours blend as they are, "
                           "with no test on alpha")  # fmt: skip


def _nothing_returned(args, expected, got) -> bool:
    """(0, 0, 0, 0) where the blend is not: a guard on a small alpha, or 9.2a's "(0, 0, 0, 0)
    where α = 0" carried over to a glow (r22 D-1, D-2)."""
    g = np.asarray(got, float).ravel()
    return g.shape == (4,) and not g.any() and bool(np.asarray(expected, float).any())


def _nothing_words(args, expected, got) -> str:
    if expected[3] > 0:
        return _FAINT_ATOP(args, expected, got)
    glow = f"{glowing(args) or 'an input'} is a glow"
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
    if is_glow(args[0]):
        return glow_skipped_words(args, expected, got)
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
    return np.asarray(src, float) + np.asarray(dst, float) if is_glow(src) else None


def _dst_glow_kept(src, dst):
    """A glowing destination's light kept whole under the source (r22 D-2); None where the
    destination is no glow."""
    s, d = np.asarray(src, float), np.asarray(dst, float)
    return s * d[3] + d if is_glow(d) else None


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


def _atop_glow_lost_words(args, expected, got) -> str:
    """9.2b's "glow lost" (:func:`_atop_via_straight`, or both inputs' colours clamped to
    their alpha), in words true of the input that glows (r23 D-1: at a glowing destination
    the answer, (0, 0, 0, 0), was called "the destination unchanged" and the source, alpha
    ½, "a glow")."""
    if is_glow(args[0]):
        return glow_skipped_words(args, expected, got)
    return (f"your answer is atop as if dst {vec(args[1])} carried no light, but it is a "
            "glow: premultiplied light with alpha 0, covering nothing but carrying light. "
            "Dividing it by its alpha 0 to work on straight colours, as 9.2a does (or clamping "
            "its colour to that alpha), loses its light; atop keeps a destination's light "
            "wherever the source does not cover it, a glow's too")  # fmt: skip


def atop_mistakes() -> list[Mistake]:
    """9.2b's: the glow (divided by its alpha, or skipped for it), then the table's, then the
    colour right with a wrong alpha."""
    table = [Mistake(k, w, gives=g) for k, w, g in ATOP_MISTAKES]
    share = "the result's alpha is the share of the pixel in which something of it shows"
    return [Mistake("glow lost", _atop_glow_lost_words, gives=_atop_via_straight),
            GLOW_DIVIDED, ZERO_DIVIDED, *table, CHANNEL_ORDER, *GLOW_MISTAKES,
            NOTHING_ATOP, SOURCE_SKIPPED, *alpha_mistakes(premultiplied_atop, ATOP_ALPHAS, share)]  # fmt: skip
