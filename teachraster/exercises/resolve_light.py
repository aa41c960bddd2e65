"""Exercise ``resolve_srgb`` (lesson 08 §6, lesson 12b): the MSAA resolve in linear light.

Exercise 6.2's resolve averages the numbers it is given. The samples of an 8-bit framebuffer
are sRGB-encoded, and encoded numbers are not light: half of a black pixel and half of a white
one must show the light of 50 % white, which encodes as 0.735, not 0.5. So the resolve
decodes every sample (and the background) to linear light, averages there, and encodes the
mean again (lesson 08 §6 and lesson 12b; Direct3D promises it, D3D11.3 §5.6.6, Vulkan says
"should", GL does not promise it, GL 4.6 §18.3.1: lesson 08's table of the standards). The
student works out that order; the curves are the package's tools (``srgb_to_linear``,
``linear_to_srgb``). Cases: exercise 6.2's, read as sRGB-encoded, and black on white at
each coverage of 4 samples.
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import linear_to_srgb, srgb_to_linear
from ..pipeline.render_triangles import Frame
from .antialiasing import (
    CHANNEL_ORDER,
    ON_255,
    UNCOVERED_AS_BLACK,
    as_colour,
    draw_resolve_case,
    expected_resolve,
    fixed_count_mistake,
    resolve_case,
    resolve_cases,
    same_colour,
    swatch_words,
    uncovered_as_black,
)
from .blend_mistakes import EIGHT_BIT
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
    # r422 HN2: a dark code between the two curves' thresholds (0.0031308 < c ≤ 0.04045),
    # where a decode or encode with the other's threshold differs
    out.append(resolve_case("white on a dark grey, 2 of 4 samples", [0, -1, 0, -1], [white] * 4,
                            np.full(3, 0.02)))  # fmt: skip
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


def _mix(colours, ids, background, decode, encode, covered_only=False, background_decode=None):
    """A resolve with the decoding and encoding given (identity: the numbers as they are);
    ``background_decode`` where the background is decoded otherwise than the samples."""
    c = _covered(ids)
    if covered_only:
        if not c.any():
            return None
        return encode(decode(np.asarray(colours, float)[c]).mean(axis=0))
    mixed = np.where(c[:, None], decode(np.nan_to_num(np.asarray(colours, float))),
                     (background_decode or decode)(np.asarray(background, float)))  # fmt: skip
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
    return _mix(colours, ids, background, _decode, _encode, background_decode=_same)


def _in_light(resolve):
    """A 6.2 resolve (or a slip of one) done the right way round: samples and background
    decoded, the mean encoded (r308: 6.2's slips made in light, one model for both)."""
    return lambda c, i, b: _encode(resolve(_decode(c), np.asarray(i), srgb_to_linear(b)))


def _background_in_codes(colours, ids, background):
    """The covered samples averaged in light and encoded, then mixed with the encoded
    background by their shares (r308 HN: two resolves, one in light, one in codes)."""
    c = _covered(ids)
    s, k = len(c), int(c.sum())
    if k == 0:
        return None
    covered = _encode(_decode(np.asarray(colours, float)[c]).mean(axis=0))
    return (k * covered + (s - k) * np.asarray(background, float)) / s


def _uncovered_words(ids) -> str:
    """ "the 3 uncovered samples join" / "the 1 uncovered sample joins" (r482 S1)."""
    n = int((~_covered(ids)).sum())
    return f"{n} uncovered sample{'s' * (n != 1)} join{'s' * (n == 1)}"


def _twice(x):
    return srgb_to_linear(srgb_to_linear(x))


def _background_twice_words(args, expected, got) -> str:
    """r315 HN: the background decoded, then decoded again (a decoded value handed to a
    function that decodes), said with its numbers."""
    b = np.asarray(args[2], dtype=float)
    return (
        f": you decoded the background twice: {vec(b)} encoded is the light "
        f"{vec(srgb_to_linear(b))}, and decoding that again gives {vec(_twice(b))}, a darker "
        "background; decode every value once (srgb_to_linear), average, encode the mean once"
    )


def _powers_swapped_words(gamma: float):
    def words(args, expected, got) -> str:
        return (
            f": you raised the samples to 1/{num(gamma)} and the mean to {num(gamma)}: that "
            "encodes where you should decode (and the other way round), with a plain power for "
            "sRGB's curve; srgb_to_linear takes the encoded samples to light, linear_to_srgb "
            "takes the mean back"
        )

    return words


def _black_words(args, expected, got) -> str:
    return (": " + UNCOVERED_AS_BLACK.format(bg=vec(args[2])) + " (np.nan_to_num makes "
            "them 0): put the background in them, decoded like the samples")  # fmt: skip


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
    # r315 HN: the two below were told only the rule
    Mistake("background decoded twice", _background_twice_words,
            gives=lambda c, i, b: _mix(c, i, b, _decode, _encode, background_decode=_twice)),
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
    *(Mistake("powers swapped", _powers_swapped_words(g),
              gives=lambda c, i, b, g=g: _mix(c, i, b, lambda x: _power(x, 1 / g),
                                              lambda x: _power(x, g)))
      for g in (2.2, 2.4)),
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
    # r308 MN1, HN: 6.2's slips in light, and the decoding or encoding half done
    Mistake("uncovered as black", _black_words, gives=_in_light(uncovered_as_black)),
    fixed_count_mistake(decode=srgb_to_linear),
    fixed_count_mistake(": you averaged the sRGB-encoded numbers, as 6.2's resolve does"),
    Mistake("only the background decoded", ": you decoded the background but not the "
            "samples: they are sRGB-encoded too; decode every value before averaging",
            gives=lambda c, i, b: _mix(c, i, b, _same, _encode,
                                       background_decode=srgb_to_linear)),
    Mistake("encoded without decoding", ": you encoded the mean without decoding first: the "
            "samples and the background are sRGB-encoded already, so your mean is a mean of "
            "codes; decode them (srgb_to_linear), average, then encode",
            gives=lambda c, i, b: _mix(c, i, b, _same, _encode)),
    Mistake("background mixed in codes", lambda a, e, g: ": you averaged the covered "
            "samples in light but mixed in the background's share as encoded numbers: the "
            f"{_uncovered_words(a[1])} the average in light too "
            "(decode the background, average all S samples, encode once)",
            gives=_background_in_codes),
    CHANNEL_ORDER,
    ON_255,
    # r368: a resolve stored as an 8-bit sRGB framebuffer would (lesson 08's code 188) was
    # sent back to its decode/encode order, which was right
    EIGHT_BIT,
    # r443 HN8, HN9: told only the rule
    Mistake("background encoded", ": you encoded the background (linear_to_srgb) where it "
            "must be decoded: it is sRGB-encoded like the samples; decode it (srgb_to_linear) "
            "before it joins the average",
            gives=lambda c, i, b: _mix(c, i, b, _decode, _encode, background_decode=linear_to_srgb)),
    Mistake("light rounded to 8 bits", ": you rounded the light (the decoded values) to 8 bits "
            "(x·255 rounded) before averaging; the steps are right (decode every value, average, "
            "encode the mean), but 8 bits of light lose the dark steps sRGB's code keeps: "
            "average the decoded values unrounded",
            gives=lambda c, i, b: _mix(c, i, b, lambda x: _eight_bits(_decode(x)), _encode)),
    # r482 HN11: lesson 08's cell (its cube on white) pasted, 1.0 for the background
    Mistake("background white", lambda a, e, g: ": the uncovered samples count as white (1, "
            f"1, 1), not as the background {vec(a[2])}: lesson 08's cube was cleared to "
            "white, and here the background is an argument (`background`); decode it like the "
            "samples", gives=lambda c, i, b: _mix(c, i, np.ones(np.shape(b)), _decode, _encode)),
    Mistake("triangle 0 only", ": you counted only the samples of triangle 0 as covered "
            "(ids == 0): every id ≥ 0 is a triangle that covers the sample, and only −1 marks "
            "an uncovered one", gives=lambda c, i, b: _mix(
                c, np.where(np.asarray(i) == 0, 0, -1), b, _decode, _encode)),
]  # fmt: skip


# -- r422 HN2: a wrong curve named by its curve, the steps being right ------------------------
def _dec_at(threshold):
    """sRGB's decode with its straight part up to ``threshold`` (0.04045 is sRGB's)."""

    def dec(c):
        c = np.asarray(c, dtype=float)
        return np.where(c <= threshold, c / 12.92,
                        ((np.maximum(c, threshold) + 0.055) / 1.055) ** 2.4)  # fmt: skip

    return dec


def _enc_at(threshold, offset=0.055):
    """sRGB's encode with its straight part up to ``threshold`` (0.0031308 is sRGB's) and
    ``offset`` subtracted from the power (0.055 is sRGB's)."""

    def enc(x):
        x = np.clip(np.asarray(x, dtype=float), 0, None)
        return np.where(x <= threshold, 12.92 * x,
                        1.055 * np.maximum(x, threshold) ** (1 / 2.4) - offset)  # fmt: skip

    return enc


def _eight_bits(x):
    return np.round(np.asarray(x, dtype=float) * 255) / 255


#: (kind, what is wrong, decode, encode): curves a student writes or picks instead of sRGB's.
CURVES = [
    ("encode by a power", "you decoded with sRGB's curve but encoded the mean with a plain "
     "power 1/2.2", srgb_to_linear, lambda x: _power(x, 1 / 2.2)),
    ("encode by a power", "you decoded with sRGB's curve but encoded the mean with a plain "
     "power 1/2.4", srgb_to_linear, lambda x: _power(x, 1 / 2.4)),
    ("decode by a power", "you decoded with a plain power 2.2 but encoded with sRGB's curve",
     lambda x: _power(x, 2.2), _encode),
    ("decode by a power", "you decoded with a plain power 2.4 but encoded with sRGB's curve",
     lambda x: _power(x, 2.4), _encode),
    ("power 2", "you decoded by squaring and encoded by a square root (a gamma of 2): sRGB's "
     "curve is a straight line near black and a power of 2.4 above it",
     lambda x: _power(x, 2), np.sqrt),
    ("curve thresholds swapped", "your encode's straight part ends at 0.04045, the decode's "
     "threshold (a code); the encode's is 0.0031308 (light)", srgb_to_linear, _enc_at(0.04045)),
    ("curve thresholds swapped", "your decode's straight part ends at 0.0031308, the encode's "
     "threshold (light); the decode's is 0.04045 (a code)", _dec_at(0.0031308), _encode),
    ("curve thresholds swapped", "your two curves' thresholds are swapped: the decode's "
     "straight part ends at code 0.04045, the encode's at light 0.0031308",
     _dec_at(0.0031308), _enc_at(0.04045)),
    ("encode without its offset", "your encode leaves out the − 0.055 of 1.055·x^(1/2.4) − "
     "0.055", srgb_to_linear, _enc_at(0.0031308, offset=0.0)),
    ("8-bit codes", "you rounded the samples and the background to 8-bit codes (x·255 "
     "rounded) before decoding, and the mean after: the numbers given are exact, and the "
     "answer is their exact resolve, unrounded", lambda x: srgb_to_linear(_eight_bits(x)),
     lambda x: _eight_bits(_encode(x))),
]  # fmt: skip


def _curve_mistake(kind, what, dec, enc) -> Mistake:
    steps = "; the steps are right (decode every value, average, encode the mean)"
    curve = (
        ""
        if kind == "8-bit codes"
        else (", the curve is not sRGB's: srgb_to_linear and linear_to_srgb compute it exactly")
    )
    words = f": {what}{steps}{curve}"
    return Mistake(kind, words, gives=lambda c, i, b: _mix(c, i, b, dec, enc))


def _not_inverse(args, expected, got) -> bool | None:
    """A pixel with no sample covered is the background, unchanged: an answer that differs
    there changes the value between decoding and encoding (r423 MN3: the curves not each
    other's inverse is one cause of several; the words name them all)."""
    _, ids, background = args
    if _covered(ids).any():
        return None
    g = np.asarray(got, dtype=float).ravel()
    return g.shape == (3,) and bool(np.isfinite(g).all()) and not np.allclose(g, background)


def _not_inverse_words(args, expected, got) -> str:
    b = np.asarray(args[2], dtype=float)
    return (
        f": no sample is covered here, so the pixel is the background {vec(b)} unchanged, "
        "whatever is averaged (decoded, averaged alone, encoded back); yours is not, so "
        "something between your decode and your encode changes the value: curves that are "
        "not each other's inverse (srgb_to_linear and linear_to_srgb are an exact pair), a "
        "rounding, or a step left out or done twice"
    )


CURVE_MISTAKES = [_curve_mistake(*c) for c in CURVES] + [
    Mistake("curves not each other's inverse", _not_inverse_words, fits=_not_inverse),
]


def explain(args, expected, got) -> str:
    colours, ids, background = args
    s, k = len(ids), int(_covered(ids).sum())
    return (f"ids {np.asarray(ids).tolist()} ({k} of {s} sample{'s' * (s != 1)} covered), sRGB-encoded "
            f"background {vec(background)}: the resolve in linear light, encoded, is "
            f"{vec(expected, got)}; yours is {vec(got, expected)}")  # fmt: skip


#: r422 WF1: Frame.resolve averages the numbers it is given, 6.2's answer, not 6.3's: said so.
FRAME_RESOLVE = (
    "that is exercise 6.2's answer (the package's resolve of the numbers it is given), and "
    "6.3 builds on your own 6.2: the check does not count the package's 6.2 inside 6.3. Call "
    "your own resolve from 6.2 there instead"
)


RESOLVE_SRGB = Exercise(
    "resolve_srgb", resolve_srgb_cases, as_colour, same_colour, explain, _rule,
    MISTAKES + CURVE_MISTAKES,
    answers=(PackageAnswer(Frame.resolve, words=FRAME_RESOLVE),), draw=draw_srgb_case,
    reference=("teachraster.exercises.antialiasing",), hints=((RULE, HINT), (_RECIPE, _RECIPE_HINT)), inputs_drawn=True,
    once=((RULE, "; as said for the first failing case"),),
)  # fmt: skip


def _wedges():
    """The 6.1/6.2 fan's samples with its triangles black and white in turn, on white:
    four black wedges whose every edge meets white (r308 M1: 6.3 had no scene)."""
    from .picture_scenes import fan_colours

    ids, _, _, _ = fan_colours()  # 6.2's scene: which triangle covers each sample
    colours = np.where((ids >= 0)[..., None], (ids % 2 == 1)[..., None] * np.ones(3), np.nan)
    return ids, colours, np.ones(3)


def _resolved(fn, ids, colours, background):
    """``fn`` on every pixel's samples (its grey, channel 0), or the words of what it raised."""
    from .scenes import call

    h, w = ids.shape[:2]
    out = np.empty((h, w))
    try:
        for i in range(h):
            for j in range(w):
                out[i, j] = call(fn, as_colour, colours[i, j], ids[i, j], background)[0]
    except NotImplementedError:
        return "not implemented yet"
    except Exception as e:  # noqa: BLE001 — the student's code: said, never raised
        return f"{type(e).__name__}: {e}"[:80]
    return out


def _as_rule(got, rule, ids, colours, background) -> bool:
    """Is ``got`` (channel 0 of each pixel) what ``rule`` gives, within 1e-6?"""
    h, w = ids.shape[:2]
    want = [[rule(colours[i, j], ids[i, j], background)[0] for j in range(w)] for i in range(h)]
    return bool(np.allclose(got, want, rtol=0, atol=1e-6))


def show_two_resolves(resolve, resolve_srgb, axes=None):
    """Your 6.2 resolve and your 6.3 resolve of the same black-and-white wedges side by side
    (the numbers shown as the screen shows codes), and one row of each: averaged as codes,
    every edge pixel is darker, the black wedges bolder. Returns the artists."""
    import textwrap

    import matplotlib.pyplot as plt

    if axes is None:
        axes = plt.subplots(1, 3, figsize=(9.0, 3.4), layout="constrained")[1]
    ids, colours, background = _wedges()
    row = 6  # a row through two wedges' slanted edges
    titles = ("your resolve (6.2): codes averaged", "your resolve_srgb (6.3): light averaged")
    rules = (expected_resolve, expected_resolve_srgb)
    artists, rows = [], []
    for ax, fn, title, rule in zip(axes, (resolve, resolve_srgb), titles, rules):
        got = _resolved(fn, ids, colours, background)
        if not isinstance(got, str) and not _as_rule(got, rule, ids, colours, background):
            # r423 S1: a wrong 6.3 was titled "light averaged" whatever it did
            title = title.split(":")[0] + ": not its rule here (see its check)"
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(textwrap.fill(title, 24), fontsize="small")
        if isinstance(got, str):
            artists.append(ax.text(0.5, 0.5, textwrap.fill(got, 20), ha="center", va="center",
                                   transform=ax.transAxes, fontsize="x-small"))  # fmt: skip
            continue
        artists.append(ax.imshow(got, cmap="gray", vmin=0, vmax=1, interpolation="nearest"))
        artists += ax.plot([-0.5, got.shape[1] - 0.5], [row, row], color="#ff9f1c", lw=0.8)
        rows.append((title.split(":")[0], got[row]))
    for (name, values), style in zip(rows, ("o-", "s--")):
        artists += axes[2].plot(values, style, ms=3, label=name)
    # r432 S3: with neither resolve drawn there is no orange line (nor data) to point at
    where = (
        f"row {row} (orange line):\nthe codes shown" if rows else f"row {row}: not implemented yet"
    )
    axes[2].set_title(where, fontsize="small")
    axes[2].set_xlabel("column", fontsize="x-small")
    axes[2].set_ylim(-0.05, 1.55)  # the key above the curves, none hidden under it
    axes[2].set_yticks([0, 0.5, 1])
    if rows:
        artists.append(axes[2].legend(fontsize="x-small", loc="upper center"))
    return artists
