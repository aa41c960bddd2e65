"""Exercise ``covered_counts(code, fg_code, bg_code, S)`` (lesson 08 §6 with 12b, task 6.3).

The inverse of an 8-bit sRGB resolve: a triangle of grey code ``fg_code`` covers k of a
pixel's S samples on a background of code ``bg_code``; the resolve averages light and the
screen shows the mean encoded and rounded to 8 bits. Given the code shown, which k could it
have been? The student has to build the forward model (decode both codes, mix k/S of the
light, encode, round to 0–255), see that shares are shares of light, not of codes, and that
the 8-bit rounding (dark greys, a triangle close to its background) can give several k the
same code: the answer is every k that gives it, sorted.

Expected answers are an independent float64 computation (:func:`forward_code`); the tests
compare every case's codes with the package's ``srgb8_codes`` (the 8-bit sRGB target of
:mod:`teachraster.pipeline.blending.colour_blending`) and keep every case at least
:data:`TIE_MARGIN` of a code away from a rounding tie, so that neither float64 nor a correct
float32 computation can flip one.
"""

from __future__ import annotations

import re

import numpy as np

from .answers import as_numbers, refuse_non_answers
from .cases import SEED, fixed_and_drawn
from .exercise import Exercise, Mistake, PackageAnswer
from .package_answers import CHECKER_WORDS
from .running import WrongAnswerType


def _decode(c):
    c = np.asarray(c, dtype=float)
    return np.where(c <= 0.04045, c / 12.92, ((np.maximum(c, 0.04045) + 0.055) / 1.055) ** 2.4)


def _encode(x):
    x = np.asarray(x, dtype=float)
    return np.where(
        x <= 0.0031308, 12.92 * x, 1.055 * np.maximum(x, 0.0031308) ** (1 / 2.4) - 0.055
    )


#: How far every case's 255 × encoded means stay from a rounding tie (x.5), in codes: above
#: float32's rounding of a correct forward model (eight roundings of 2⁻²⁴ at 255: 1.2e-4 of a
#: code; r508 F1: at 1e-6 one drawn case in 20 000, 139.4999987, gave 140 in float32).
TIE_MARGIN = 5e-4


def forward_value(k, fg_code, bg_code, s, decode=_decode, encode=_encode) -> float:
    """255 × the encoded mean light of k samples of ``fg_code`` and S − k of ``bg_code``,
    before rounding (the tests keep it off the ties)."""
    light = (k * decode(fg_code / 255) + (s - k) * decode(bg_code / 255)) / s
    return float(encode(light) * 255)


def forward_code(k, fg_code, bg_code, s) -> int:
    """The code the screen shows for k of S samples covered.

    >>> [forward_code(k, 0, 255, 4) for k in range(5)]
    [255, 225, 188, 137, 0]
    """
    return int(np.round(forward_value(k, fg_code, bg_code, s)))


def tie_distance(k, fg_code, bg_code, s) -> float:
    """How far 255 × the encoded mean lies from a rounding tie (x.5), in codes."""
    v = forward_value(k, fg_code, bg_code, s)
    return abs(v - np.floor(v) - 0.5)


def expected_counts(code, fg_code, bg_code, s) -> tuple[int, ...]:
    """Every k in 0..S whose resolve shows ``code``, sorted.

    >>> expected_counts(188, 0, 255, 4), expected_counts(50, 50, 50, 2)
    ((2,), (0, 1, 2))
    """
    return tuple(k for k in range(s + 1) if forward_code(k, fg_code, bg_code, s) == code)


def case(label, k, fg, bg, s):
    code = forward_code(k, fg, bg, s)
    return (f"{label}, code {code}", (code, fg, bg, s), expected_counts(code, fg, bg, s))


def _cases(rng, word):
    # the labels say what is given, never k (the answer): "code 188" is added by case()
    hard = [
        ("black on white, S = 4", 2, 0, 255, 4),
        ("black on white, S = 4", 1, 0, 255, 4),
        ("white on black (the triangle lighter than its background), S = 4", 1, 255, 0, 4),
        ("black on white, S = 4", 4, 0, 255, 4),
        ("black on white, S = 4", 0, 0, 255, 4),
        ("mid greys, S = 8", 3, 60, 200, 8),
        ("a triangle of the background's own code, S = 4", 2, 128, 128, 4),
        ("dark greys, S = 16", 2, 0, 14, 16),
        ("dark greys, S = 16", 11, 0, 14, 16),
        ("dark greys, S = 4", 1, 11, 14, 4),
        ("a triangle one code from its background, S = 4", 1, 200, 201, 4),
        ("light greys, S = 16", 7, 220, 255, 16),
        ("black on white, S = 16", 15, 0, 255, 16),
        ("1 sample", 1, 30, 240, 1),
        ("2 samples, a dark triangle on a mid grey", 1, 20, 128, 2),
        # r499 WP1, WP2: codes over 256 give [] on the first, float16 light on the second
        ("2 samples, a light triangle on a dark grey", 1, 162, 14, 2),
        ("2 samples, two mid greys", 1, 86, 128, 2),
        # r508 WP1: k = 3 gives 223.5022 (code 224): np.isclose(v, 223, atol=0.5) keeps it
        ("two light greys two codes apart, S = 4", 4, 223, 225, 4),
    ]  # fmt: skip
    out = [case(*c) for c in hard]
    n = 0
    while n < 10:
        s = (2, 4, 8, 16)[n % 4]
        fg, bg = (int(v) for v in rng.integers(0, 256, size=2))
        k = int(rng.integers(0, s + 1))
        if min(tie_distance(j, fg, bg, s) for j in range(s + 1)) > TIE_MARGIN:  # off the ties
            n += 1
            out.append(case(f"{word} {n}: S = {s}", k, fg, bg, s))
    return out


cases = fixed_and_drawn(_cases, SEED + 491)


def as_counts(value) -> tuple:
    """The possible k as a sorted tuple of numbers (a single number: that one k)."""
    refuse_non_answers(value, "a list of the possible k")
    if isinstance(value, (bool, np.bool_)):
        raise WrongAnswerType(f"returned {value}, a bool: return the possible k as a list")
    if _bools(value):  # r508: a mask over k = 0 … S
        raise WrongAnswerType(
            f"returned {_short_list(value)}, a list of bools (a mask over k = 0 … S): return "
            "the k themselves, those where it is True ([k for k, ok in enumerate(mask) if ok])"
        )
    arr = as_numbers(np.atleast_1d(value) if np.ndim(value) == 0 else value, (-1,),
                     "a list of the possible k (whole numbers 0 … S)", max_size=64)  # fmt: skip
    return tuple(sorted(float(v) for v in arr))


def _bools(value) -> bool:
    try:
        arr = np.asarray(value)
    except (ValueError, TypeError):
        return False
    return arr.ndim == 1 and arr.size > 0 and arr.dtype == bool


def _short_list(value) -> str:
    items = [bool(v) for v in value]
    return "[" + ", ".join(map(str, items[:6])) + (", …]" if len(items) > 6 else "]")


def same_counts(got, expected, args) -> bool:
    return tuple(got) == tuple(float(k) for k in expected)


def _ks(values) -> str:
    return "[" + ", ".join(f"{v:g}" for v in values) + "]"


def explain(args, expected, got) -> str:
    code, fg, bg, s = args
    return (
        f"code {code} shown, a triangle of code {fg} on a background of code {bg}, S = {s}: "
        f"the covered counts that show it are {_ks(expected)}; yours are {_ks(got)}"
    )


def _table(args) -> str:
    code, fg, bg, s = args
    return ", ".join(f"k = {k}: {forward_code(k, fg, bg, s)}" for k in range(s + 1))


def rule(args, expected, got) -> str:
    return (
        "; k covered samples show round(255 · encode((k·decode(fg) + (S − k)·decode(bg)) / S)), "
        f"codes / 255 decoded, light mixed, then encoded and rounded: here {_table(args)}; "
        "the answer is every k whose code is the one shown"
    )


HINT = (
    "; which code does the resolve show for each possible k, from the two codes given, and "
    "which of those k show this one? Work this case through by hand"
)
RULE_TEXT = re.compile(
    r"; k covered samples show round\(255 .*? the answer is every k whose code is the one shown"
)


def _matching(value_of):
    def gives(code, fg, bg, s):
        return tuple(float(k) for k in range(s + 1) if value_of(k, fg, bg, s) == code)

    return gives


def _in_codes(code, fg, bg, s):
    return (float(np.round(s * (code - bg) / (fg - bg))),) if fg != bg else None


def _light_rounded(code, fg, bg, s):
    lf, lb = _decode(fg / 255), _decode(bg / 255)
    return (float(np.round(s * (_decode(code / 255) - lb) / (lf - lb))),) if fg != bg else None


def _light_no_255(code, fg, bg, s):
    lf, lb = _decode(fg), _decode(bg)
    return (float(np.round(s * (_decode(code) - lb) / (lf - lb))),) if fg != bg else None


def _first(code, fg, bg, s):
    ks = expected_counts(code, fg, bg, s)
    return (float(ks[0]),) if len(ks) > 1 else None


def _last(code, fg, bg, s):
    ks = expected_counts(code, fg, bg, s)
    return (float(ks[-1]),) if len(ks) > 1 else None


def _some(code, fg, bg, s):
    return () if len(expected_counts(code, fg, bg, s)) > 1 else None


def _power(g):
    return lambda k, fg, bg, s: int(
        np.round(
            forward_value(
                k, fg, bg, s, lambda c: np.asarray(c) ** g, lambda x: np.asarray(x) ** (1 / g)
            )
        )
    )


def _several_words(args, expected, got) -> str:
    return (
        f": here {len(expected)} different k show code {args[0]} ({_table(args)}); the code "
        "cannot tell them apart, so the answer is every one of them, not one (the nearest k "
        "or the first found)"
    )


# -- r499: curves, roundings and tolerances the shape words stood in for ----------------------
def _nolinear_decode(c):
    return ((np.asarray(c, dtype=float) + 0.055) / 1.055) ** 2.4


def _nolinear_encode(x):
    return 1.055 * np.asarray(x, dtype=float) ** (1 / 2.4) - 0.055


def _curves(decode=_decode, encode=_encode, scale=255):
    """The forward code with other curves (or codes over ``scale``), rounded."""

    def code_of(k, fg, bg, s):
        light = (k * decode(fg / scale) + (s - k) * decode(bg / scale)) / s
        return int(np.round(float(encode(light)) * scale))

    return _matching(code_of)


def _float16_light(k, fg, bg, s):
    h = np.float16
    light = h((h(k) * h(_decode(fg / 255)) + h(s - k) * h(_decode(bg / 255))) / h(s))
    return int(np.round(float(_encode(float(light))) * 255))


def _within(width):
    def gives(code, fg, bg, s):
        return tuple(float(k) for k in range(s + 1)
                     if abs(forward_value(k, fg, bg, s) - code) < width)  # fmt: skip

    return gives


def _light_within(code, fg, bg, s):
    lf, lb, lc = _decode(fg / 255), _decode(bg / 255), _decode(code / 255)
    return tuple(float(k) for k in range(s + 1)
                 if abs((k * lf + (s - k) * lb) / s - lc) <= 0.5 / 255)  # fmt: skip


def _linear_8bit(k, fg, bg, s):
    light = (k * _decode(fg / 255) + (s - k) * _decode(bg / 255)) / s
    return int(np.round(float(light) * 255))


def _linear_8bit_gives(code, fg, bg, s):
    target = int(np.round(float(_decode(code / 255)) * 255))
    return tuple(float(k) for k in range(s + 1) if _linear_8bit(k, fg, bg, s) == target)


def _same_codes(args, expected, got):
    """fg = bg special-cased: every k shows the one code there."""
    _, fg, bg, s = args
    return None if fg != bg else tuple(got) != tuple(expected)


def _which_differ(args, expected, got) -> str:
    """The symptom, where no cause fits: the k missing or extra, each with its code."""
    code, fg, bg, s = args
    words = []
    missing = [k for k in expected if float(k) not in got]
    extra = [k for k in got if k not in {float(e) for e in expected}]
    if missing:
        words.append(f"yours leaves out k = {_ks(missing)[1:-1]}, whose resolve shows {code} too")
    for k in extra[:3]:
        kk = int(k) if float(k).is_integer() and 0 <= k <= s else None
        shown = (
            f"shows {forward_code(kk, fg, bg, s)}, not {code}"
            if kk is not None
            else "is no count 0 … S"
        )
        words.append(f"yours holds k = {k:g}, whose resolve {shown}")
    twice = sorted({k for k in got if list(got).count(k) > 1})
    if twice:  # r508 HN9: the words were empty for [2, 2]
        words.append(f"yours holds k = {_ks(twice)[1:-1]} more than once")
    return ": " + "; ".join(words) + rule(args, expected, got)


def _one_sided(g, side):
    power = (
        (lambda c: np.asarray(c, float) ** g)
        if side == "decode"
        else (lambda x: np.asarray(x, float) ** (1 / g))
    )
    return _curves(decode=power) if side == "decode" else _curves(encode=power)


R499 = [
    Mistake("codes over 256", ": you divided the codes by 256 (and multiplied by 256): an 8-bit "
            "code c stands for c / 255 (255 is white)", gives=_curves(scale=256), only_whole=True),
    Mistake("float16", ": you held the light in float16 (about 3 significant digits), which "
            "moves the encoded mean by more than the rounding allows here: compute in float64",
            gives=_matching(_float16_light), only_whole=True),
    Mistake("curve without its linear part", ": your sRGB curve has no linear part near black "
            "(decode: c / 12.92 for c ≤ 0.04045; encode: 12.92·L for L ≤ 0.0031308): use "
            "srgb_to_linear and linear_to_srgb", gives=_curves(decode=_nolinear_decode)),
    Mistake("curve without its linear part", ": your sRGB curve has no linear part near black "
            "(encode: 12.92·L for L ≤ 0.0031308): use linear_to_srgb",
            gives=_curves(encode=_nolinear_encode)),
    *(Mistake("power curve", f": you {side}d with a plain power {g} and the other way with "
              "sRGB's curve: use srgb_to_linear and linear_to_srgb, the exact pair",
              gives=_one_sided(g, side)) for g in (2.2, 2.4) for side in ("decode", "encode")),
    Mistake("code rounded up", ": you rounded 255 · encode(…) up (ceil); the target rounds to "
            "the nearest code", gives=_matching(lambda k, fg, bg, s: int(np.ceil(
                forward_value(k, fg, bg, s))))),
    Mistake("a tolerance of a code", ": you took every k within one code of the code shown "
            "(|255 · encode(…) − code| < 1); the target rounds to the nearest code, so only "
            "a value within ½ of it shows it", gives=_within(1.0)),
    Mistake("a tolerance in light", ": you compared the mixed light with the code's own light "
            "within half a code of light (0.5 / 255); the target rounds the encoded mean, and "
            "half a code is far more light near white than near black: encode, round, then "
            "compare codes", gives=_light_within),
    Mistake("light rounded to 8 bits", ": you rounded the light to 8 bits and compared there; "
            "the target stores the encoded mean rounded, not the light",
            gives=_linear_8bit_gives),
    Mistake("fg = bg", lambda a, e, g: f": the triangle and the background have the same code "
            f"{a[1]}, so every k shows code {a[0]}: the answer is every k from 0 to S = {a[3]}",
            fits=_same_codes),
    Mistake("one code undecoded", ": you decoded the background's code but not the "
            "triangle's (fg_code / 255 taken as light)", gives=_matching(
                lambda k, fg, bg, s: int(np.round(255 * float(_encode(
                    (k * fg / 255 + (s - k) * _decode(bg / 255)) / s))))),
            ),
    Mistake("one code undecoded", ": you decoded the triangle's code but not the "
            "background's (bg_code / 255 taken as light)", gives=_matching(
                lambda k, fg, bg, s: int(np.round(255 * float(_encode(
                    (k * _decode(fg / 255) + (s - k) * bg / 255) / s))))),
            ),
    Mistake("the k differ", _which_differ, fits=lambda a, e, g: tuple(g) != tuple(e) or None,
            symptom=True),
]  # fmt: skip


# -- r508: a tolerance just over ½, the curves swapped, k + 1, duplicates, the background's
# light unweighted, each code's light rounded, ÷ (S + 1) ---------------------------------------
#: How far past ½ a code a "just over half" tolerance reaches (np.isclose's rtol adds 0.00255 at
#: code 255); wider ones are other mistakes (a tolerance of one code).
OVER_HALF = 0.51


def _over_half(args, expected, got):
    """A test that accepts a k whose value lies just over ½ a code from the code shown (np.isclose
    adds rtol · |code| to atol = 0.5): the right k, and the extra ones are each the nearest
    beyond ½, by at most :data:`OVER_HALF`."""
    code, fg, bg, s = args
    right = {float(k) for k in expected}
    extra = [k for k in got if k not in right]
    if not extra or not right <= set(got) or len(set(got)) != len(got):
        return None
    if not all(float(k).is_integer() and 0 <= k <= s for k in extra):
        return None
    far = [abs(forward_value(int(k), fg, bg, s) - code) for k in extra]
    if not all(0.5 < d <= OVER_HALF for d in far):  # a tolerance of a whole code: _within(1)
        return None
    reach = max(far)  # every k within the same reach must be in the answer
    return all(float(k) in got for k in range(s + 1)
               if abs(forward_value(k, fg, bg, s) - code) <= reach)  # fmt: skip


def _over_half_words(args, expected, got) -> str:
    code, fg, bg, s = args
    k = next(int(k) for k in got if k not in {float(e) for e in expected})
    v = forward_value(k, fg, bg, s)
    return (
        f": you kept k = {k}, whose 255 · encode(…) is {v:.4f}, {abs(v - code):.4f} from {code}: "
        f"it rounds to {forward_code(k, fg, bg, s)}; your test accepts more than half a code "
        f"(np.isclose(v, code, atol=0.5), for one, adds rtol · |code| = {1e-5 * code:.5f}); "
        "the target rounds to the "
        "nearest code: round(v) == code, or |v − code| ≤ 0.5"
    )


def _duplicated(args, expected, got):
    if len(set(got)) == len(got):
        return None
    return sorted(set(got)) == [float(k) for k in expected]


def _one_more(code, fg, bg, s):
    return tuple(float(k + 1) for k in expected_counts(code, fg, bg, s))


def _background_unweighted(k, fg, bg, s):
    light = min(k * float(_decode(fg / 255)) / s + float(_decode(bg / 255)), 1.0)
    return int(np.round(float(_encode(light)) * 255))


def _light_of_codes_rounded(k, fg, bg, s):
    lf, lb = (np.round(float(_decode(c / 255)) * 255) / 255 for c in (fg, bg))
    return int(np.round(float(_encode((k * lf + (s - k) * lb) / s)) * 255))


def _over_s_plus_1(k, fg, bg, s):
    light = (k * _decode(fg / 255) + (s - k) * _decode(bg / 255)) / (s + 1)
    return int(np.round(float(_encode(light)) * 255))


def _neighbours(code, fg, bg, s):
    lf, lb = float(_decode(fg / 255)), float(_decode(bg / 255))
    if lf == lb:
        return None
    t = s * (float(_decode(code / 255)) - lb) / (lf - lb)
    return tuple(float(k) for k in sorted({int(np.floor(t)), int(np.ceil(t))}) if 0 <= k <= s)


R508 = [
    Mistake("encoded with srgb_to_linear", ": you encoded the mixed light with srgb_to_linear, "
            "which decodes (code → light): the screen's code is linear_to_srgb(light) × 255",
            gives=_curves(encode=_decode), only_whole=True),
    Mistake("decoded with linear_to_srgb", ": you decoded the codes with linear_to_srgb, which "
            "encodes (light → code): a code's light is srgb_to_linear(code / 255)",
            gives=_curves(decode=_encode), only_whole=True),
    Mistake("tolerance over ½", _over_half_words, fits=_over_half),
    Mistake("k listed twice", lambda a, e, g: f": your list holds k = "
            f"{_ks(sorted({k for k in g if list(g).count(k) > 1}))[1:-1]} more than once: give "
            "each k once", fits=_duplicated),
    Mistake("k + 1", ": your k are one too many (k + 1 for each: counted from 1?): k is the "
            "number of covered samples, 0 … S", gives=_one_more, only_whole=True),
    Mistake("background unweighted", ": you added the background's whole light to the "
            "triangle's share (k·fg/S + bg): the background shows on the S − k uncovered "
            "samples, so its light weighs (S − k)/S", gives=_matching(_background_unweighted),
            only_whole=True),
    Mistake("light of the codes rounded", ": you rounded each code's light (each sample's) to 8 bits before "
            "mixing; the resolve mixes the decoded light unrounded, and only the encoded mean "
            "is rounded, once", gives=_matching(_light_of_codes_rounded), only_whole=True),
    Mistake("divided by S + 1", ": you divided the mixed light by S + 1; the k covered and "
            "S − k uncovered samples are S in all", gives=_matching(_over_s_plus_1),
            only_whole=True),
    Mistake("codes // 255", ": you divided the codes by 255 with // (integer division): every "
            "code but 255 becomes 0; a code's light is srgb_to_linear(code / 255)",
            gives=_curves(scale=255, decode=lambda c: _decode(np.floor(np.asarray(c) + 1e-9))),
            only_whole=True),
    Mistake("both neighbours of S·t", ": you returned the counts either side of S·t (t the "
            "code's share of the light between the two codes) without checking which of them "
            "shows the code: compute each k's code and keep those that match",
            gives=_neighbours, only_whole=True),
]  # fmt: skip


MISTAKES = [
    Mistake("shares in codes", ": you took the share of the pixel in codes (8-bit sRGB numbers) "
            "as if they were light: a screen's codes are encoded, and the resolve mixes light", gives=_in_codes),
    Mistake("shares in codes", ": you averaged the codes themselves for each k: the resolve "
            "mixes light, so decode the codes first",
            gives=_matching(lambda k, fg, bg, s: int(np.round((k * fg + (s - k) * bg) / s)))),
    Mistake("several k", _several_words, gives=_first),
    Mistake("several k", _several_words, gives=_last),
    Mistake("several k", _several_words, gives=_some),
    Mistake("several k", _several_words, gives=_light_rounded),
    Mistake("codes not / 255", ": you decoded the codes 0–255 as if they were in [0, 1] "
            "(sRGB's curves take a code / 255)", gives=_light_no_255),
    Mistake("code truncated", ": you truncated 255 · encode(…) to 8 bits (int, floor); the "
            "target rounds to the nearest code",
            gives=_matching(lambda k, fg, bg, s: int(forward_value(k, fg, bg, s)))),
    *(Mistake("power curve", f": you decoded and encoded with a plain power {g:g}, not sRGB's "
              "curves (srgb_to_linear, linear_to_srgb: a linear part near black)",
              gives=_matching(_power(g))) for g in (2.2, 2.4, 2.0)),
    Mistake("encoded light not decoded", ": you mixed the light but compared it with the code "
            "/ 255 undecoded (or encoded the mix twice)",
            gives=_matching(lambda k, fg, bg, s: int(np.round(255 * _decode(
                forward_value(k, fg, bg, s) / 255)))), only_whole=True),
    Mistake("every k", ": you returned every k from 0 to S; only the k whose resolve shows "
            "this very code are possible", gives=lambda c, f, b, s: tuple(map(float, range(s + 1)))),
    Mistake("uncovered counted", ": you counted the uncovered samples (S − k), the triangle "
            "and the background swapped",
            gives=lambda c, f, b, s: tuple(float(s - k) for k in expected_counts(c, f, b, s))),
    Mistake("fraction, not count", ": you returned the fraction k / S; the task asks for the "
            "number of samples k", gives=lambda c, f, b, s: tuple(
                k / s for k in expected_counts(c, f, b, s))),
    Mistake("k = S never tried", ": you tried k = 0 … S − 1 only (range(S)): all S samples "
            "covered is possible too",
            gives=lambda c, f, b, s: tuple(float(k) for k in expected_counts(c, f, b, s)
                                           if k < s), only_whole=True),
    Mistake("k = 0 never tried", ": you tried k = 1 … S only: no sample covered is possible "
            "too", gives=lambda c, f, b, s: tuple(float(k) for k in expected_counts(c, f, b, s)
                                                  if k > 0), only_whole=True),
    *R508,
    *R499,
]  # fmt: skip


def draw(ax, case_, got):
    """The two codes and the code shown as framed grey swatches; S and the answers below."""
    from matplotlib.patches import Rectangle

    code, fg, bg, s = case_[1]
    names = [f"triangle\n{fg}", f"background\n{bg}", f"shown\n{code}"]
    artists = []
    for j, c in enumerate((fg, bg, code)):
        grey = str(c / 255)
        artists.append(ax.add_patch(Rectangle((j * 1.4, 0), 1, 1, facecolor=grey,
                                              edgecolor="0.4", linewidth=1)))  # fmt: skip
    ax.set_xlim(-0.1, 4.1)
    ax.set_ylim(1.05, -0.05)
    ax.set_box_aspect(0.3)
    ax.set_xticks([0.5, 1.9, 3.3], names, fontsize="x-small")
    ax.set_yticks([])
    words = f"S = {s} samples"
    if got is not None:
        words += f"; k: expected {_ks(case_[2])}, yours {_ks(got)}"
    ax.set_xlabel(words, fontsize="x-small")
    return artists


COVERED_COUNTS = Exercise(
    "covered_counts", cases, as_counts, same_counts, explain, rule, MISTAKES, draw=draw,
    inputs_drawn=True, hints=((RULE_TEXT, HINT),), reference=("teachraster.exercises.resolve_codes",),
    # the checker's own model handed in (it has no package function to list: r490)
    answers=(PackageAnswer(expected_counts, words=CHECKER_WORDS),),
    match=lambda got, answer, args: same_counts(got, answer, args),
)  # fmt: skip
