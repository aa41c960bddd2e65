"""Exercise ``resolve_fragments(fragments, sample_fragment, background)`` (lesson 08, task 6.2).

Compressed multisample storage (AMD's EQAA, NVIDIA's CSAA, and the colour compression of
every MSAA target since): a pixel of S samples stores F ≤ S distinct colours, its
*fragments*, and for each sample the index of the fragment it shows, −1 where no triangle
covered it. The resolve must still give what the pixel's whole area shows, each sample an
equal share (lesson 08), but the student has to derive the weights: a fragment weighs by the
samples pointing at it, not 1/F; a fragment no sample points at (overwritten by a later
triangle, as the storage keeps it) weighs 0; an uncovered sample is the background, and
``fragments[sample_fragment]`` silently takes the *last* fragment for −1 (NumPy's wrap).

Expected answers are an independent float64 sum (:func:`expected_fragments`); the tests
compare each with the package's :meth:`Frame.resolve` of the samples expanded
(``fragments[i]`` where ``i >= 0``, NaN elsewhere).
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import linear_to_srgb, srgb_to_linear
from ..pipeline.render_triangles import Frame
from .antialiasing import as_colour, draw_resolve_case, same_colour
from .cases import SEED, fixed_and_drawn
from .exercise import Exercise, Mistake, PackageAnswer
from .scalars import vec


def counts(sample_fragment, f: int) -> np.ndarray:
    """How many samples point at each of the F fragments (0 for an orphan).

    >>> counts([2, 0, 2, -1], 4).tolist()
    [1, 0, 2, 0]
    """
    idx = np.asarray(sample_fragment)
    return np.array([int((idx == j).sum()) for j in range(f)])


def expected_fragments(fragments, sample_fragment, background) -> np.ndarray:
    """The resolved colour: every sample an equal share, an uncovered one the background.

    >>> expected_fragments([[1.0, 0, 0], [0, 0, 1.0]], [0, 0, 0, -1], [1.0, 1, 1]).tolist()
    [1.0, 0.25, 0.25]
    """
    fr = np.asarray(fragments, dtype=float).reshape(-1, 3)
    idx = np.asarray(sample_fragment)
    c = counts(idx, len(fr))
    uncovered = int((idx < 0).sum())
    total = (c[:, None] * fr).sum(axis=0) + uncovered * np.asarray(background, dtype=float)
    return total / len(idx)


def expanded(fragments, sample_fragment) -> np.ndarray:
    """The S samples' colours (NaN where uncovered), as an uncompressed MSAA target holds
    them: the input of exercise 6.2's earlier resolve and of :meth:`Frame.resolve`."""
    fr = np.asarray(fragments, dtype=float).reshape(-1, 3)
    idx = np.asarray(sample_fragment)
    out = np.full((len(idx), 3), np.nan)
    out[idx >= 0] = fr[idx[idx >= 0]]
    return out


def package_resolve(fragments, sample_fragment, background) -> np.ndarray:
    """The package's resolve of the expanded samples (the cross-check of the tests)."""
    from types import SimpleNamespace

    pixel = SimpleNamespace(sample_triangle_id=np.asarray(sample_fragment)[None, None])
    colours = expanded(fragments, sample_fragment)[None, None]
    return Frame.resolve(pixel, colours, np.asarray(background, dtype=float))[0, 0]


def case(label, fragments, sample_fragment, background, dtype=float):
    fr = np.asarray(fragments, dtype=dtype).reshape(-1, 3)
    args = (fr, np.asarray(sample_fragment, dtype=np.int64), np.asarray(background, float))
    return (label, args, expected_fragments(*args))


RED, GREEN, BLUE = np.eye(3)
WHITE, GREY = np.ones(3), np.array([0.2, 0.3, 0.4])


def _cases(rng, word):
    teal, orange = np.array([0.0, 0.5, 0.5]), np.array([1.0, 0.6, 0.0])
    hard = [
        ("4 samples, 2 fragments: 3 samples red, 1 blue", [RED, BLUE], [0, 0, 1, 0], GREY),
        ("4 samples, 1 fragment on 1 sample, white background", [GREEN], [-1, 0, -1, -1], WHITE),
        ("4 samples, an orphan fragment (overwritten): no sample points at blue",
         [RED, BLUE, GREEN], [0, 2, 2, 0], WHITE),
        ("4 samples, none covered, no fragment stored (F = 0)", np.zeros((0, 3)), [-1] * 4, GREY),
        ("4 samples, none covered, an orphan fragment kept", [teal], [-1] * 4, GREY),
        ("4 samples, F = S: every sample its own fragment", [RED, GREEN, BLUE, teal], [2, 0, 3, 1],
         WHITE),
        ("8 samples, 3 fragments listed out of sample order, 2 uncovered",
         [orange, teal, BLUE], [2, 2, -1, 0, 2, 1, -1, 2], WHITE),
        ("4 samples, the last fragment an orphan, 1 uncovered", [RED, GREEN, BLUE], [0, 1, -1, 1],
         np.zeros(3)),
        ("1 sample, covered", [GREEN], [0], WHITE),
        ("1 sample, not covered, an orphan kept", [GREEN], [-1], GREY),
        ("16 samples, 2 fragments 9 and 2, 5 uncovered", [RED, BLUE],
         [0] * 9 + [1] * 2 + [-1] * 5, WHITE),
        ("2 samples, 2 fragments, none uncovered", [RED, BLUE], [1, 0], GREY),
    ]  # fmt: skip
    out = [case(*c) for c in hard]
    for n in range(10):
        s = (2, 4, 8, 16)[n % 4]
        f = int(rng.integers(1, s + 1))
        idx = rng.integers(-1, f, size=s)
        out.append(case(f"{word} {n + 1}: {s} samples, {f} fragments", rng.uniform(0, 1, (f, 3)),
                        idx, rng.uniform(0, 1, 3)))  # fmt: skip
    label = "8 samples, 3 fragments in float32 (as from imread), an orphan last"
    out.append(case(label, rng.uniform(0, 1, (3, 3)), [0, 1, -1, 0, 1, 1, -1, 0],
                    rng.uniform(0, 1, 3), np.float32))  # fmt: skip
    return out


cases = fixed_and_drawn(_cases, SEED + 490)


# -- how the answer is explained --------------------------------------------------------------
def explain(args, expected, got) -> str:
    fr, idx, bg = args
    return (
        f"{len(fr)} fragment{'s' * (len(fr) != 1)} {_colours(fr)}, sample_fragment "
        f"{idx.tolist()}, background {vec(bg)}: the pixel shows {vec(expected, got)}; yours "
        f"is {vec(got, expected)}"
    )


def _colours(fr) -> str:
    return "[" + ", ".join(vec(c) for c in fr) + "]" if len(fr) <= 4 else f"of shape {fr.shape}"


RULE = (
    "; each of the S samples stands for an equal share of the pixel: a fragment weighs by the "
    "number of samples pointing at it (0 for one no sample points at), an uncovered sample "
    "(−1) is the background, and the sum is divided by S"
)
HINT = (
    "; how much of the pixel's area does each fragment stand for, and each sample marked "
    "−1? Work this case's numbers through by hand, sample by sample"
)


def _sums(fr, idx, bg):
    c = counts(idx, len(fr))
    return c, (c[:, None] * fr).sum(axis=0), int((idx < 0).sum()), np.asarray(bg, float)


def _wrapped(fr, idx, bg):
    """``fragments[sample_fragment].mean(axis=0)``: −1 takes the last fragment."""
    return fr[idx].mean(axis=0) if len(fr) else None


def _wrap_words(args, expected, got) -> str:
    fr, idx, _ = args
    return (
        f": your uncovered samples took the colour of the last fragment {vec(fr[-1])}: "
        "fragments[-1] is the last row (NumPy's index −1 wraps around), not a missing colour; "
        "where sample_fragment is −1 no fragment covers the sample"
    )


def _per_fragment(fr, idx, bg):
    """One equal weight per stored fragment, the uncovered share the background's."""
    _, _, u, b = _sums(fr, idx, bg)
    if not len(fr):
        return None
    return (1 - u / len(idx)) * fr.mean(axis=0) + u / len(idx) * b


def _per_used_fragment(fr, idx, bg):
    _, _, u, b = _sums(fr, idx, bg)
    used = np.unique(idx[idx >= 0])
    if not len(used):
        return None
    return (1 - u / len(idx)) * fr[used].mean(axis=0) + u / len(idx) * b


def _orphans_counted(fr, idx, bg):
    """Every stored fragment counted, an orphan as one more sample."""
    c, _, u, b = _sums(fr, idx, bg)
    w = np.maximum(c, 1)
    return ((w[:, None] * fr).sum(axis=0) + u * b) / (w.sum() + u)


def _per_fragment_words(args, expected, got) -> str:
    fr, idx, _ = args
    c = counts(idx, len(fr))
    return (
        f": you gave each of the {len(fr)} fragments the same weight, but they cover "
        f"{', '.join(str(int(n)) for n in c)} of the {len(idx)} samples: a fragment stands for "
        "as much of the pixel as the samples that point at it"
    )


def _orphan_words(args, expected, got) -> str:
    fr, idx, _ = args
    orphans = [j for j, n in enumerate(counts(idx, len(fr))) if n == 0]
    return (
        f": you counted fragment {', '.join(map(str, orphans))} (no sample points at it: a triangle drawn later "
        "covered all its samples, and the storage still holds it) as part of the pixel"
    )


def _covered_only(fr, idx, bg):
    _, total, u, _ = _sums(fr, idx, bg)
    return total / (len(idx) - u) if u < len(idx) else None


def _uncovered_black(fr, idx, bg):
    return _sums(fr, idx, bg)[1] / len(idx)


def _by_f(fr, idx, bg):
    _, total, u, b = _sums(fr, idx, bg)
    return (total + u * b) / len(fr) if len(fr) else None


def _s_minus_f(fr, idx, bg):
    _, total, _, b = _sums(fr, idx, bg)
    return (total + (len(idx) - len(fr)) * b) / len(idx)


def _shifted(fr, idx, bg):
    """``np.bincount(sample_fragment + 1)`` read one place off: fragment j weighed by the
    samples of fragment j − 1 (the uncovered ones for fragment 0)."""
    c = np.bincount(idx + 1, minlength=len(fr) + 1)
    return ((c[: len(fr), None] * fr).sum(axis=0) + c[0] * np.asarray(bg, float)) / len(idx)


def _by_sample_index(fr, idx, bg):
    """6.2's earlier resolve pasted: fragment s taken as sample s's colour."""
    if len(fr) != len(idx):
        return None
    return np.where(idx[:, None] >= 0, fr, bg).mean(axis=0)


def _background_once(fr, idx, bg):
    _, total, u, b = _sums(fr, idx, bg)
    return (total + b) / (len(idx) - u + 1) if u else None


# -- r499: typical mistakes the staged question and the rule left unnamed ---------------------
def _with_uncovered_as(fr, idx, bg, colour):
    """The right sum with every uncovered sample taken as ``colour``."""
    _, total, u, _ = _sums(fr, idx, bg)
    return (total + u * np.asarray(colour, float)) / len(idx)


def _white(fr, idx, bg):
    return _with_uncovered_as(fr, idx, bg, np.ones(3)) if (idx < 0).any() else None


def _as_fragment(j):
    """−1 read as fragment j (np.maximum(i, 0): fragment 0; np.abs(i): fragment 1)."""

    def gives(fr, idx, bg):
        if not len(fr) or not (idx < 0).any():
            return None
        return _with_uncovered_as(fr, idx, bg, fr[min(j, len(fr) - 1)])

    return gives


def _as_fragment_words(j):
    def words(args, expected, got) -> str:
        fr = args[0]
        jj = min(j, len(fr) - 1)
        return (
            f": your uncovered samples (−1) took fragment {jj}'s colour {vec(fr[jj])} (an index "
            "clipped or made positive); a sample marked −1 shows no fragment: it is the "
            f"background {vec(args[2])}"
        )

    return words


def _positional(fr, idx, bg):
    """np.unique's counts of the indices present, paired with fragments[:len(counts)]."""
    _, _, u, b = _sums(fr, idx, bg)
    _, c = np.unique(idx[idx >= 0], return_counts=True)
    return ((c[:, None] * fr[: len(c)]).sum(axis=0) + u * b) / len(idx) if len(c) else None


def _sorted_counts(fr, idx, bg):
    c, _, u, b = _sums(fr, idx, bg)
    return ((np.sort(c)[::-1][:, None] * fr).sum(axis=0) + u * b) / len(idx) if len(fr) else None


def _paired_words(args, expected, got) -> str:
    fr, idx, _ = args
    c = counts(idx, len(fr))
    return (
        ": your counts went to other fragments than the samples point at: here fragments 0 … "
        f"{len(fr) - 1} stand for {', '.join(map(str, c))} samples; fragment j weighs by the "
        "samples whose index is j (np.unique lists only the indices present: pair its counts "
        "with fragments[unique], not with fragments[:len(counts)])"
    )


def _expanded_with_bg(fr, idx, bg):
    out = expanded(fr, idx)
    out[idx < 0] = bg
    return out


def _in_light(fr, idx, bg):
    return linear_to_srgb(srgb_to_linear(_expanded_with_bg(fr, idx, bg)).mean(axis=0))


def _decoded_mean(fr, idx, bg):
    return srgb_to_linear(_expanded_with_bg(fr, idx, bg)).mean(axis=0)


def _no_fragment_black(fr, idx, bg):
    return np.zeros(3) if not len(fr) else expected_fragments(fr, idx, bg)


def _truncated(fr, idx, bg):
    return _expanded_with_bg(fr, idx, bg).astype(int).sum(axis=0) / len(idx)


R499 = [
    Mistake("background white", lambda a, e, g: ": your uncovered samples came out white (1, "
            f"1, 1), not the background {vec(a[2])}: the background is an argument (lesson "
            "08's cube was cleared to white)", gives=_white),
    Mistake("−1 as a fragment", _as_fragment_words(0), gives=_as_fragment(0)),
    Mistake("−1 as a fragment", _as_fragment_words(1), gives=_as_fragment(1)),
    Mistake("counts paired wrong", _paired_words, gives=_positional),
    Mistake("counts paired wrong", _paired_words, gives=_sorted_counts),
    *(Mistake("averaged in light", ": you decoded the colours as sRGB and averaged light: "
              "6.2's fragments are linear values of a float target, averaged as they are "
              "(the sRGB target is 6.3's)", gives=g) for g in (_in_light, _decoded_mean)),
    Mistake("8 bits", ": you rounded the colour to 8 bits (× 255, rounded, / 255): the resolve "
            "of a float target keeps it unrounded",
            gives=lambda f, i, b: np.round(expected_fragments(f, i, b) * 255) / 255),
    Mistake("F = 0 black", lambda a, e, g: ": with no fragment stored (F = 0) every sample is "
            f"uncovered, so the pixel is the background {vec(a[2])}, not black",
            gives=_no_fragment_black, only_whole=True),
    Mistake("colours truncated", ": you truncated the colours to whole numbers (an int array, "
            "or astype(int)) before summing: channels are fractions in [0, 1]", gives=_truncated),
]  # fmt: skip


# -- r508: the sum divided by another count than S, one colour returned whole, equal weights
# per distinct index, the background weighed by the covered share, F / S as the covered share --
def _divisor(args, expected, got) -> float | None:
    """The whole number d ≠ S (1 … 2S) with ``got`` = (the right sum) / d, or None."""
    fr, idx, _ = args
    s = len(idx)
    total, g = np.asarray(expected, float) * s, np.asarray(got, float).ravel()
    if g.shape != (3,) or int((np.abs(total) > 1e-9).sum()) < 2 or abs(g).max() < 1e-12:
        return None  # one channel alone: any multiple fits it (a single colour picked)
    j = int(np.argmax(np.abs(total)))
    d = total[j] / g[j] if g[j] else 0.0
    if not (0.5 < d < 2 * s + 0.5) or abs(d - round(d)) > 1e-6 or round(d) == s:
        return None
    return float(round(d)) if np.allclose(g * round(d), total, atol=1e-6) else None


def _divisor_words(args, expected, got) -> str:
    s, d = len(args[1]), int(_divisor(args, expected, got))
    named = {s - 1: " (S − 1)", s + 1: " (S + 1)"}.get(d, "")
    how = "did not divide it by S" if d == 1 else f"divided it by {d}{named}, not by S"
    return (
        f": you summed the {s} samples' colours (each fragment by its samples, the background by "
        f"the uncovered ones) but {how} = {s}: each sample stands for 1/S of the pixel"
    )


def _picked(args, expected, got) -> str | None:
    """Which input colour the answer is, whole: 'fragment j' or 'the background'."""
    fr, idx, bg = args
    g = np.asarray(got, float).ravel()
    if g.shape != (3,):
        return None
    for j, c in enumerate(fr):
        if np.allclose(g, c, atol=1e-9):
            return f"fragment {j}"
    return "the background" if np.allclose(g, bg, atol=1e-9) else None


def _picked_words(args, expected, got) -> str:
    fr, idx, _ = args
    c, u = counts(idx, len(fr)), int((idx < 0).sum())
    shares = [f"fragment {j}: {n}" for j, n in enumerate(c)] + [f"the background: {u}"]
    return (
        f": your answer is {_picked(args, expected, got)}'s colour alone; the pixel shows the mix "
        f"of all {len(idx)} samples, each colour weighing the samples that show it "
        f"({', '.join(shares)} of {len(idx)})"
    )


def _distinct_equal(fr, idx, bg):
    """Each distinct index present (−1, the background, as one more) one equal weight."""
    present = np.unique(idx)
    return np.mean([np.asarray(bg, float) if j < 0 else fr[j] for j in present], axis=0)


def _background_by_covered(fr, idx, bg):
    _, total, u, b = _sums(fr, idx, bg)
    return total / len(idx) + (len(idx) - u) / len(idx) * b


def _f_over_s(fr, idx, bg):
    """The covered samples' mean mixed with the background by F / S, not k / S."""
    _, total, u, b = _sums(fr, idx, bg)
    if u == len(idx) or not len(fr):
        return None
    a = min(len(fr) / len(idx), 1.0)
    return a * total / (len(idx) - u) + (1 - a) * b


def _whole_weights(fr, idx, bg):
    """Each weight count // S (integer division): 0 unless one colour shows on every sample."""
    c, _, u, b = _sums(fr, idx, bg)
    s = len(idx)
    return ((c // s)[:, None] * fr).sum(axis=0) + (u // s) * b


R508 = [
    Mistake("divided by another count", _divisor_words,
            fits=lambda a, e, g: None if _divisor(a, e, g) is None else True),
    Mistake("weights by //", lambda a, e, g: ": your weights are count // S (integer "
            f"division): 0 for every colour here, as none shows on all {len(a[1])} samples; "
            "divide as floats, count / S", gives=_whole_weights, only_whole=True),
    Mistake("distinct indices equal", lambda a, e, g: ": you gave each distinct index "
            "present the same weight" + (" (the background's −1 as one more colour)" if
                                         (a[1] < 0).any() else "") + ": a fragment, and the "
            "background, weigh by the number of samples that show them", gives=_distinct_equal),
    Mistake("background by the covered share", lambda a, e, g: ": you weighed the background by "
            f"the covered share k/S ({int((a[1] >= 0).sum())}/{len(a[1])}); it shows on the "
            f"uncovered samples: (S − k)/S = {int((a[1] < 0).sum())}/{len(a[1])}",
            gives=_background_by_covered),
    Mistake("F / S as the covered share", lambda a, e, g: f": you took F/S = {len(a[0])}/"
            f"{len(a[1])} (fragments stored / samples) as the covered share; it is the samples "
            f"not marked −1, {int((a[1] >= 0).sum())}/{len(a[1])}, and each fragment weighs by "
            "its own samples", gives=_f_over_s),
    Mistake("channels reversed", ": your channels are in reverse order (B, G, R): the colour's "
            "channels stay in the order given, R, G, B",
            fits=lambda a, e, g: bool(np.allclose(np.asarray(g, float).ravel()[::-1], e,
                                                  atol=1e-9)) if np.size(g) == 3 else None),
    Mistake("one colour picked", _picked_words,
            fits=lambda a, e, g: None if _picked(a, e, g) is None else True, symptom=True),
]  # fmt: skip


MISTAKES = [
    Mistake("index −1 wraps", _wrap_words, gives=_wrapped),
    Mistake("one weight per fragment", _per_fragment_words, gives=_per_fragment),
    Mistake("one weight per fragment", _per_fragment_words,
            gives=lambda f, i, b: f.mean(axis=0) if len(f) else None),
    Mistake("one weight per fragment", _per_fragment_words, gives=_per_used_fragment),
    Mistake("orphans counted", _orphan_words, gives=_orphans_counted),
    Mistake("fragment s as sample s", ": you took fragment s as the colour of sample s (6.2's "
            "uncompressed resolve): sample s shows the fragment sample_fragment[s] names",
            gives=_by_sample_index),
    Mistake("uncovered left out", lambda a, e, g: f": you averaged the covered samples alone; "
            f"the {int((a[1] < 0).sum())} uncovered sample(s) are part of the pixel too, and "
            "show the background", gives=_covered_only),
    Mistake("uncovered as black", lambda a, e, g: ": your uncovered samples count as black "
            f"(0, 0, 0), not as the background {vec(a[2])}", gives=_uncovered_black),
    Mistake("background once", ": the background counted once, as if one sample, however "
            "many samples are uncovered", gives=_background_once),
    Mistake("divided by F", lambda a, e, g: f": you divided by F = {len(a[0])}, the fragments "
            f"stored, not by the S = {len(a[1])} samples", gives=_by_f),
    Mistake("uncovered as S − F", lambda a, e, g: ": you took S − F = "
            f"{len(a[1]) - len(a[0])} samples as uncovered; the uncovered samples are those "
            f"marked −1 ({int((a[1] < 0).sum())} here): a fragment may stand for several samples",
            gives=_s_minus_f),
    Mistake("counts shifted", ": your weights are one fragment off: fragment j got the count "
            "of fragment j − 1 (np.bincount(sample_fragment + 1) counts the −1 samples first)",
            gives=_shifted),
    Mistake("divided by 4", lambda a, e, g: f": you divided by 4 whatever S (here S = "
            f"{len(a[1])})", gives=lambda f, i, b: (_sums(f, i, b)[1]
                                                    + _sums(f, i, b)[2] * b) / 4),
    *R499,
    *R508,
]  # fmt: skip


def raised(args, error) -> str:
    """Words for an exception the case's shape explains (F = 0, an orphan last)."""
    fr, idx, _ = args
    if len(fr) == 0:
        return (" (no fragment is stored here: F = 0 and every sample is −1; indexing an "
                "empty fragments array fails)")  # fmt: skip
    if f"({len(idx)},1) ({len(fr)},3)" in error.replace(", ", ","):
        return (f" (fragments has F = {len(fr)} rows and sample_fragment S = {len(idx)} "
                "entries: sample s shows fragments[sample_fragment[s]], not fragments[s])")  # fmt: skip
    if "negative" in error and (idx < 0).any():  # r499 HN10: np.bincount(sample_fragment)
        return (" (np.bincount takes no negative numbers, and the uncovered samples are −1: "
                "count sample_fragment[sample_fragment >= 0] with minlength=F, or shift by one)")  # fmt: skip
    if ("broadcast" in error or "mismatch" in error) and counts(idx, len(fr))[-1] == 0:
        return (" (the last fragment is an orphan here: np.bincount(sample_fragment[... >= 0]) "
                f"gives {max(int(idx.max()) + 1, 0)} counts, not F = {len(fr)}; "
                "minlength=F)")  # fmt: skip
    return ""


def draw(ax, case_, got):
    """The samples expanded to colours, each marked with its fragment index (−1: the
    background), the answers beside them, and above the samples the F stored fragments, each
    with its index and how many samples show it (r508 FIG1: an orphan was in words only)."""
    from matplotlib.patches import Rectangle

    fr, idx, bg = case_[1]
    artists = draw_resolve_case(ax, (case_[0], (expanded(fr, idx), idx, bg), case_[2]), got)
    s = len(idx)
    for k, j in enumerate(idx):
        colour = bg if j < 0 else fr[j]
        artists.append(ax.text((k + 0.5) * 3.0 / s, 0.5, str(int(j)), ha="center", va="center",
                               fontsize="x-small" if s <= 8 else 5, color=_ink(colour)))  # fmt: skip
    ax.set_ylim(1.05, -1.75)
    ax.set_box_aspect(0.5)
    c = counts(idx, len(fr))
    head = ("stored fragments: index, samples showing it" if len(fr) else
            "no fragment stored (F = 0)")  # fmt: skip
    artists.append(ax.text(0.0, -1.45, head, ha="left", va="center", fontsize="x-small"))
    width = 3.0 / max(len(fr), 1)
    for j, colour in enumerate(fr):
        left, n = j * width, int(c[j])
        artists.append(ax.imshow(np.clip(np.asarray(colour, float), 0, 1)[None, None],
                                 extent=(left + 0.03, left + width - 0.03, -0.2, -1.2),
                                 aspect="auto"))  # fmt: skip
        if not n:  # an orphan: crossed out, no sample shows it
            artists.append(ax.add_patch(Rectangle((left + 0.03, -1.2), width - 0.06, 1.0,
                                                  fill=False, hatch="xx", edgecolor="0.5",
                                                  linewidth=0)))  # fmt: skip
        words = f"{j}: {n}" if n else f"{j}:\norphan"
        artists.append(ax.text(left + width / 2, -0.7, words if width > 0.45 else str(j),
                               ha="center", va="center", fontsize="x-small",
                               color=_ink(colour)))  # fmt: skip
    return artists


def _ink(colour) -> str:
    """Black on a light swatch, white on a dark one."""
    r, g, b = np.clip(np.asarray(colour, float)[:3], 0, 1)
    return "black" if 0.299 * r + 0.587 * g + 0.114 * b > 0.5 else "white"


RESOLVE_FRAGMENTS = Exercise(
    "resolve_fragments", cases, as_colour, same_colour, explain,
    lambda a, e, g: RULE, MISTAKES,
    answers=(PackageAnswer(Frame.resolve),), draw=draw, inputs_drawn=True, example=2,
    hints=((RULE, HINT),), once=((RULE, "; as said for the first failing case"),),
    raised_words=raised,
    reference=("teachraster.exercises.antialiasing", "teachraster.exercises.resolve_fragments"),
)  # fmt: skip
