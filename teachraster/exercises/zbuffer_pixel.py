"""Exercise ``depth_passes`` (lesson 05a): the z-buffer of one pixel, fragment by fragment.

The fragments that reach one pixel arrive in drawing order, each with its depth and its
depth mask (``depth_write``: glass is drawn without writing depth). The buffer starts empty;
a fragment passes when it is strictly nearer than the depth the buffer holds (Ritschel,
*Interpolation and z-buffering*; CONVENTIONS: ties keep the earlier fragment), and only a
fragment that passes *and* writes changes what the buffer holds. The student returns which
fragments pass: that also says which one the pixel shows (the last that passed).

Expected answers: :func:`teachraster.pipeline.visibility.zbuffer.passed_on_arrival`, the
renderer's own test in drawing order.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..pipeline.visibility.zbuffer import passed_on_arrival, passes_depth_test
from .answers import refuse_non_answers, short
from .cases import DRAWN, SEED, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer
from .running import WrongAnswerType
from .scalars import num

#: Named sequences: (label, depths, writes).
NAMED = (
    ("a wall, glass in front of it, then a nearer wall", [0.4, 0.3, 0.35], [True, False, True]),
    ("one fragment", [0.6], [True]),
    ("each nearer than the last", [0.7, 0.5, 0.3], [True, True, True]),
    ("each farther than the last", [0.3, 0.5, 0.7], [True, True, True]),
    ("a tie: two coplanar triangles", [0.5, 0.5], [True, True]),
    ("a tie after a nearer fragment", [0.6, 0.4, 0.4, 0.5], [True, True, True, True]),
    ("nearer, farther, then between", [0.5, 0.2, 0.8, 0.3], [True, True, True, True]),
    ("glass in front, then the wall behind it", [0.3, 0.6], [False, True]),
    ("a wall, then glass behind it", [0.4, 0.6], [True, False]),
    ("two panes of glass, then a wall between them", [0.2, 0.6, 0.4], [False, False, True]),
    ("glass, then a wall at the same depth", [0.5, 0.5], [False, True]),
    # r294 W1: glass on a tie with the wall drawn before it fails (GL_LESS); without this case
    # a rule that lets such glass pass (`<=` for glass only) passed every fixed case
    ("a wall, then glass at the same depth", [0.4, 0.4], [True, False]),
    ("nothing drawn", [], []),
    # r39 04-4: a buffer cleared to the far value 1.0 (GL's default) differs from an empty one
    # only for a fragment exactly on the far plane
    ("a fragment exactly on the far plane (depth 1)", [1.0], [True]),
    ("the far plane, then a nearer wall", [1.0, 0.7], [True, True]),
    # r448 W1: every depth above lies on a 0.1 grid, so a margin in the test (`d < stored -
    # 0.05`) passed; these are nearer (or farther) by 0.01 and by 1e-7 (still two float32s)
    ("a wall, then one nearer by 0.01", [0.5, 0.49], [True, True]),
    (
        "a wall, one nearer by 1e-7, then the first depth again",
        [0.3, 0.2999999, 0.3],
        [True, True, True],
    ),
    # r448 M1: glass after two walls, the nearer second: glass between them fails
    ("two walls, the nearer second, then glass between them", [0.6, 0.3, 0.4], [True, True, False]),
    # r456 W4: a mask looked up by depth (`writes[depths.index(d)]`) read the wall as glass
    (
        "glass, a wall at the same depth, then a wall behind both",
        [0.5, 0.5, 0.6],
        [False, True, True],
    ),
    # r456 W1-W3: margins below 1e-7 passed. Two neighbouring float32s (a float32 buffer holds
    # them apart: relative 6e-8, the finest it can), and depths near the near plane, where an
    # absolute margin of any usual size (1e-9, 1e-12, machine epsilon) is larger than the gap
    (
        "a wall, then one nearer by one float32 step (6e-8 relative)",
        [0.4999999701976776, 0.4999999403953552],
        [True, True],
    ),
    (
        "a wall a hair behind the near plane (depth 1e-20), then one at half its depth",
        [1e-20, 5e-21],
        [True, True],
    ),
)


def depth_cases() -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (depths, writes), passed) for the named sequences and seeded random ones
    (depths on a coarse grid so that ties happen, a third of them glass)."""
    rng = np.random.default_rng(SEED + 40)
    seqs = [(label, np.array(d, float), np.array(w, bool)) for label, d, w in NAMED]
    for k in range(16):
        n = int(rng.integers(2, 8))
        depths = rng.integers(1, 10, n) / 10
        writes = rng.uniform(size=n) > (0.35 if k % 2 else 0.0)
        seqs.append((f"random {k + 1}: {n} fragments", depths, writes))
    now = drawn_rng()  # r46 X1: a few drawn for this check, so a harvested table fails
    for k in range(DRAWN):
        n = int(now.integers(3, 8))
        depths = now.integers(1, 10, n) / 10
        writes = now.uniform(size=n) > (0.35 if k % 2 else 0.0)
        seqs.append((f"drawn for this check {k + 1}: {n} fragments", depths, writes))
    out = []
    for label, depths, writes in seqs:
        passed = passed_on_arrival(np.zeros(len(depths), np.int64), depths, writes)
        # r448 F1, F2: lists of Python floats and bools, as the task says (`if not depths:`
        # raised on an array, and a numpy bool `is True` never is)
        out.append((label, (depths.tolist(), writes.tolist()), passed))
    return out


def as_passes(value) -> np.ndarray:
    """One truth value per fragment (True/False, or 1/0), as a bool array."""
    refuse_non_answers(value, "one True/False per fragment")
    if isinstance(value, (list, tuple, np.ndarray)) and len(value) > 64:
        raise WrongAnswerType(f"returned {short(value)}: far more values than fragments")
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {short(value)}, not one True/False per fragment") from None
    if arr.ndim != 1:
        raise WrongAnswerType(
            f"returned {short(value)}: return a list with one True/False per fragment"
        )
    if arr.size and arr.dtype.kind not in "biuf":
        raise WrongAnswerType(f"returned {short(value)}: not True/False values")
    if arr.size and not np.isin(arr, (0, 1)).all():
        raise WrongAnswerType(f"returned {short(value)}: only True and False (or 1 and 0)")
    return arr.astype(bool)


def same_passes(got: np.ndarray, expected: np.ndarray, args=None) -> bool:
    return got.shape == expected.shape and bool(np.array_equal(got, expected))


def _simulate(depths, writes, *, ties=False, mask=True, test_all=True, update=True,
              previous=False, start=np.inf, glass_ties=False, glass_fails=False,
              glass_hides_glass=False, margin=0.0) -> np.ndarray:  # fmt: skip
    """The z-buffer with one rule changed (each keyword is one typical mistake; ``margin``:
    a fragment passes only when nearer by more than it, or, below 0, when farther by less)."""
    stored, last, out, pane = start, start, [], np.inf
    depths, writes = np.asarray(depths, dtype=float), np.asarray(writes, dtype=bool)
    for d, write in zip(depths.tolist(), writes.tolist()):
        against = last if previous else stored
        if glass_hides_glass and not write:
            against = min(against, pane)
        ok = d <= against if ties or (glass_ties and not write) else d < against
        if margin:
            ok = against - d >= margin if ties else against - d > margin
        if not test_all and not write:
            ok = True
        if glass_fails and not write:
            ok = False
        out.append(ok)
        if (ok or not update) and (write or not mask):
            stored = d
        if ok and not write:
            pane = min(pane, d)
        last = d
    return np.array(out, dtype=bool)


def explain_depth(args, expected, got) -> str:
    """The first fragment decided wrongly: its depth, what the buffer holds, both verdicts."""
    depths, writes = args
    if len(got) != len(expected):  # r306 S3: the shape's words say how many you returned
        return f"{len(depths)} fragment(s) arrive"
    k = int(np.flatnonzero(got != expected)[0])
    glass = ", glass: no depth write" if not writes[k] else ""
    held = _held_depth(depths, writes, expected, k)
    # r448 W1: 0.2999999 beside a buffer holding 0.3 printed as "0.3" on both sides
    shown = "nothing yet (empty)" if held is None else num(held, depths[k])
    return (
        f"fragment {k} (depth {num(depths[k], held)}{glass}) meets a buffer holding "
        f"{shown}: it {'passes' if expected[k] else 'fails'}, you "
        f"said it {'passes' if got[k] else 'fails'}"
    )


def _rule(args, expected, got) -> str:
    return (
        ". A fragment passes when it is strictly nearer than the depth the buffer holds, and "
        "only one that passes and writes depth changes what the buffer holds"
    )


def _mistake(kind: str, words: str, **change) -> Mistake:
    return Mistake(kind, words, gives=lambda d, w: _simulate(d, w, **change))


#: The tie mistake's words: its repair, staged as a hint on the first wrong tries.
TIE_WORDS = "a tie keeps the fragment already stored (strictly nearer passes): use <, not <="

#: Why a test that passes only the nearest fragment of the whole pixel is wrong (r222 item 2).
_ON_ARRIVAL = (
    "the test is decided as each fragment arrives, against the depth the buffer holds then, "
    "so the first fragment passes (the buffer is empty), and each later one passes when it is "
    "strictly nearer than that depth, even if a nearer one comes after it"
)
NEAREST_WORDS = f"only the nearest fragment of the whole pixel passes in your answer: {_ON_ARRIVAL}"
NEAREST_TIES_WORDS = (
    "only the nearest fragments of the whole pixel (every one at its smallest depth) pass in "
    f"your answer: {_ON_ARRIVAL}"
)


def _nearest_only(depths, ties: bool = False, writes=None) -> np.ndarray:
    """True for the nearest fragment alone (the first of equal nearest ones; ``ties``: every
    one of them), whatever the drawing order; nothing for no fragments. With ``writes``, of
    the opaque fragments alone (r306 H4: glass never passes)."""
    d = np.asarray(depths, dtype=float)
    if writes is not None:
        d = np.where(np.asarray(writes, dtype=bool), d, np.inf)
    if d.size == 0 or not np.isfinite(d).any():
        return np.zeros(d.size, dtype=bool)
    return d == d.min() if ties else np.arange(d.size) == int(np.argmin(d))


def _as_near_as_nearest_opaque(depths, writes) -> np.ndarray:
    """True for every fragment at or nearer than the nearest opaque one of the whole pixel
    (every one when none is opaque): ``d <= min(opaque)`` (r306 H5)."""
    d, w = np.asarray(depths, dtype=float), np.asarray(writes, dtype=bool)
    return d <= (d[w].min() if w.any() else np.inf)


DEPTH_MISTAKES = [
    _mistake("ties", TIE_WORDS, ties=True),
    _mistake("glass writes", "a fragment that does not write depth (glass) is tested but "
             "leaves the buffer as it was: later fragments are compared with the last depth "
             "*written*", mask=False),
    _mistake("glass untested", "a fragment that does not write depth is still tested: glass "
             "behind a wall is hidden by it", test_all=False),
    # r294 W1, M-dp1: `<=` for glass only passed the fixed cases, and when a drawn case caught
    # it was told "a fragment that fails the test changes nothing"
    _mistake("glass ties", "glass at the same depth as the depth the buffer holds passes in "
             "your answer: a tie fails for glass too (only a strictly nearer fragment passes, "
             "whether or not it writes depth)", glass_ties=True),
    # r357 H2: glass compared with earlier glass too, as if a pane hid what lies behind it
    _mistake("glass hides glass", "in your answer a pane of glass hides the glass behind it: "
             "glass is compared only with the depth the buffer holds, and an earlier pane "
             "wrote nothing there (glass does not write depth)", glass_hides_glass=True),
    # r294 H-dp1: the depth mask folded into the test (`d < stored and write`) was told the rule
    _mistake("glass never passes", "glass never passes in your answer: the depth mask decides "
             "only whether a fragment that passes changes the buffer, not whether it passes; "
             "glass nearer than the depth the buffer holds passes", glass_fails=True),
    _mistake("failed writes", "a fragment that fails the test changes nothing: only a "
             "fragment that passes (and writes) sets the buffer", update=False),
    _mistake("cleared to 1", "you started the buffer at 1.0 (GL clears it to the far value "
             "1.0 by default, and then a fragment exactly on the far plane fails): here the "
             "buffer starts empty, so the first fragment passes whatever its depth, 1.0 "
             "included", start=1.0),
    # r310 H1: `stored = depths[0]`, the usual start of a running minimum, was told the rule
    Mistake("started at the first depth", "you started the buffer at the first fragment's "
            "depth (`stored = depths[0]`), so fragment 0 is compared with its own depth and "
            "fails: the buffer starts empty, so the first fragment passes whatever its depth, "
            "and only a fragment that passes and writes puts its depth in the buffer",
            gives=lambda d, w: _simulate(d, w, start=d[0] if len(d) else np.inf)),
    _mistake("previous", "you compared each fragment with the one just before it; compare "
             "with the depth the buffer holds (the nearest written so far)", previous=True),
    Mistake("farther passes", "you let the farther fragment pass (>, not <): smaller depth "
            "is nearer, and a fragment passes when it is strictly nearer than the depth the "
            "buffer holds", gives=lambda d, w: _simulate(-np.asarray(d, dtype=float), w)),
    # r199 12-4: `[k == 0 for k ...]` was told ">, not <", which gives the same at a pixel of
    # three fragments; this one gives it on every sequence
    Mistake("first only", "only the first fragment passes in your answer, whatever the depths: "
            "a later fragment passes too when it is strictly nearer than the depth the buffer "
            "holds (does your test ask whether the buffer is empty, not whether the fragment "
            "is nearer?)", gives=lambda d, w: np.arange(len(d)) == 0),
    # r222 item 2: the nearest of the whole pixel alone (`np.argmin`, or every fragment equal
    # to the minimum), a reading of "the last fragment that passes is on top", was told the
    # rule only; the test is decided on arrival, before the later fragments are known
    Mistake("nearest only", NEAREST_WORDS, gives=lambda d, w: _nearest_only(d)),
    Mistake("nearest only, ties too", NEAREST_TIES_WORDS,
            gives=lambda d, w: _nearest_only(d, ties=True)),
    # r306 H4, H5: the nearest opaque fragment alone, or every fragment at least as near as
    # it, was told the rule on the first line (the nearest of all on the second)
    Mistake("nearest opaque only", "only the nearest opaque fragment of the whole pixel passes "
            f"in your answer (glass never): {_ON_ARRIVAL}",
            gives=lambda d, w: _nearest_only(d, writes=w)),
    Mistake("as near as the nearest opaque", "in your answer a fragment passes when it is at "
            "least as near as the nearest opaque fragment of the whole pixel: "
            f"{_ON_ARRIVAL}", gives=_as_near_as_nearest_opaque),
    # r306 X2: glass writing and walls not (the mask read the wrong way round) was told
    # "lets every fragment pass, always" on a case with no glass
    Mistake("mask swapped", "you read the depth mask the wrong way round: in your answer "
            "glass (writes False) stores its depth and the opaque fragments (writes True) do "
            "not; an opaque fragment that passes stores its depth, glass leaves the buffer as "
            "it was", gives=lambda d, w: _simulate(d, ~np.asarray(w, dtype=bool))),
    # r199: "lets every fragment pass" said what, not why: a buffer never written does so
    # r306 X2: "always" is said only of an answer that is all True on every case
    Mistake("all pass", "your function lets every fragment pass, always (does the buffer ever "
            "take a depth? A fragment that passes and writes must store its depth, so that "
            "later ones are tested against it)",
            gives=lambda d, w: np.ones(len(d), dtype=bool), only_whole=True),
    # r85 04: a buffer started at 0 was told only its symptom ("lets no fragment pass,
    # ever"); its answers are a placeholder's all False (no depth lies below 0), so both
    # are said, the cause first
    # r273 12-3: `>` against a buffer started at +inf gives the same all False, and was told
    # "you started the buffer at 0" as a fact: every cause of that answer is said
    _mistake("cleared to 0", "no fragment passes, ever (False for every fragment, whatever "
             "the depths). Three ways to that answer: a buffer started at 0, the nearest "
             "depth (nothing is strictly nearer than 0); the test turned round (>) against a "
             "buffer started at +∞ (nothing is farther than +∞); or False left in. Pass a "
             "fragment that is strictly nearer (<) than the depth the buffer holds; here it "
             "starts empty, so the first fragment passes whatever its depth (GL clears it to "
             "the far value, 1.0)", start=0.0),
]  # fmt: skip


def _shift(args, expected, got) -> int | None:
    """+1 when each verdict of ``got`` is the right one of the fragment before it, −1 of the
    one after it, else None (r357 half-named 1)."""
    if len(got) != len(expected) or len(got) < 2:
        return None
    if np.array_equal(got[1:], expected[:-1]):
        return 1
    return -1 if np.array_equal(got[:-1], expected[1:]) else None


def _shift_words(args, expected, got) -> str:
    which = "before" if _shift(args, expected, got) == 1 else "after"
    return (
        f"your verdicts are shifted by one fragment: each is the right verdict of the fragment "
        f"{which} it. Return one True/False per fragment in drawing order, the k-th for "
        "fragment k (is a verdict appended before its fragment is tested, or one too many at "
        "the start?)"
    )


def _shifted(args, expected, got) -> bool | None:
    """Does a shift by one fragment give ``got``? Asked of passing cases too (``consistent``):
    a shifted answer passes only where the verdicts are all alike, so a passed case whose
    verdicts differ says False (r448 M1 again, ~3 % of runs: glass tested against the first
    wall gave [T, T, T, F, F] for [T, T, F, F, F] on one drawn case, a shift there by
    coincidence, while it passed 40 cases with mixed verdicts)."""
    if len(got) != len(expected) or len(got) < 2:
        return None  # no say: a shape, or one fragment
    shift = _shift(args, expected, got)
    if shift is None:
        return False
    # r448 M1: where the verdicts compared are all alike, any one slip is such a "shift"
    # ([True, True, True] against [True, True, False]): no evidence either way
    same = got[1:] if shift == 1 else got[:-1]
    return None if len(set(np.asarray(same).tolist())) < 2 else True


def _margins(depths) -> list[float]:
    """The margins that change a verdict of ``depths``: their differences below 0.1 (the
    random cases' grid), either sign, and ±0.05 (a margin below the grid's step; r448 W1)."""
    d = np.asarray(depths, dtype=float)
    gaps = {abs(a - b) for a in d.tolist() for b in d.tolist()} | {0.05}
    # r456: not the grid's 0.1 itself (0.6 − 0.5 is 0.0999…): a mask slip was "a tolerance"
    return sorted(m * s for m in gaps if 0 < m <= 0.05 for s in (1, -1))


def _margin_of(args, got) -> float | None:
    """The margin (with ``<`` or ``<=``) that gives ``got``, None where none does."""
    depths, writes = args
    for m in _margins(depths):
        for ties in (False, True):
            if np.array_equal(_simulate(depths, writes, ties=ties, margin=m), got):
                return m
    return None


def _margin_words(args, expected, got) -> str:
    depths, writes = args
    k = int(np.flatnonzero(np.asarray(got) != expected)[0])
    held = _held_depth(depths, writes, expected, k)
    gap = abs(depths[k] - held) if held is not None else 0.0
    if got[k]:
        said = "at the same depth as" if gap == 0 else f"{num(gap)} farther than"
        return (
            f"a fragment {said} the depth the buffer holds passes in your answer: a tolerance "
            "in your test (d < stored + ε)? A fragment passes only when it is strictly nearer, "
            "with no tolerance either way"
        )
    return (
        f"a fragment {num(gap)} nearer than the depth the buffer holds fails in your answer: "
        "a margin in your test (d < stored − ε)? A fragment passes when it is strictly nearer "
        "by any amount, d < stored, with no tolerance."
        + ("" if held is None else _rounded_alike(depths[k], held))
    )


def _margin_fits(args, expected, got) -> bool | None:
    """A margin gives ``got``; no say where every wrong verdict is a tie's (the tie rule's
    own mistake, named by its words)."""
    depths, writes = args
    wrong = np.flatnonzero(np.asarray(got) != expected)
    held = [_held_depth(depths, writes, expected, int(k)) for k in wrong]
    if all(h is not None and h == depths[k] for h, k in zip(held, wrong)):
        return None
    return _margin_of(args, got) is not None


#: r448 W1: a margin in the test passed while every depth lay on a 0.1 grid
MARGIN = Mistake("margin", _margin_words, fits=_margin_fits, only_whole=True)


def _glass_against_nearest_opaque(depths, writes) -> np.ndarray:
    """The rule for opaque fragments; glass passes when nearer than the nearest opaque
    fragment of the whole pixel, walls drawn after it included (r448 M2)."""
    d, w = np.asarray(depths, dtype=float), np.asarray(writes, dtype=bool)
    right = _simulate(d, w)
    near = d[w].min() if w.any() else np.inf
    return np.where(w, right, d < near)


GLASS_WHOLE_PIXEL = Mistake(
    "glass against the whole pixel", "in your answer glass passes only when it is nearer than "
    "the nearest opaque fragment of the whole pixel, walls drawn after it included: glass is "
    "tested on arrival, against the depth the buffer holds then (a wall drawn later covers it "
    "by passing later, not by failing the glass)", gives=_glass_against_nearest_opaque)  # fmt: skip


def _rounded(depths, how: str) -> np.ndarray:
    """``depths`` as a buffer of format ``how`` holds them (r456 M1, M2)."""
    d = np.asarray(depths, dtype=float)
    if how == "float16":
        return d.astype(np.float16).astype(float)
    steps = 2.0 ** int(how[5:]) - 1  # "unorm16", "unorm24"
    return np.round(d * steps) / steps


#: r456 M1, M2: the formats a buffer may round to, finest first (said beside a margin)
_FORMATS = {
    "unorm24": "a 24-bit unorm buffer",
    "unorm16": "a 16-bit unorm buffer",
    "float16": "float16",
}


def _listed(names: list[str]) -> str:
    """The names as words: "a", "a and b", "a, b and c"."""
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"


def _rounded_alike(a: float, b: float) -> str:
    """The words " Or …?" where a buffer of some format holds ``a`` and ``b`` as one depth (a
    rounding gives the same answers as a margin there: both are said), else ""."""
    said = [f for how, f in _FORMATS.items() if len(set(_rounded([a, b], how).tolist())) == 1]
    if not said:
        return ""
    return (
        f" Or does your buffer round the depths? In {_listed(said)} {num(a, b)} and "
        f"{num(b, a)} are one depth: compare the depths as given"
    )


def _mask_by_depth(depths, writes) -> np.ndarray:
    """Each fragment given the mask of the first fragment at its depth (r456 W4:
    ``writes[depths.index(d)]``)."""
    d = np.asarray(depths, dtype=float).tolist()
    return _simulate(d, [bool(writes[d.index(x)]) for x in d])


def _by_depth_words(args, expected, got) -> str:
    depths, writes = args
    k = next(i for i, x in enumerate(depths) if writes[i] != writes[depths.index(x)])
    first = depths.index(depths[k])
    what = ("wall", "glass") if writes[k] else ("glass", "wall")
    return (
        f"in your answer fragment {k} (a {what[0]} at depth {num(depths[k])}) is taken for "
        f"{'' if what[1] == 'glass' else 'a '}{what[1]}, as fragment {first} at the same depth "
        "is: is each mask looked up by its depth (`writes[depths.index(d)]`)? Pair each "
        "fragment's depth with its own mask, `zip(depths, writes)`"
    )


def _glass_needs_a_wall(depths, writes) -> np.ndarray:
    """The rule, but glass fails while the buffer is empty (r456 M3, told "glass never
    passes")."""
    right = _simulate(depths, writes)
    written = np.cumsum(np.asarray(writes, dtype=bool) & right)
    empty = np.r_[0, written[:-1]] == 0 if len(right) else right
    return right & (np.asarray(writes, dtype=bool) | ~empty)


def _farthest_written(depths, writes) -> np.ndarray:
    """Each fragment compared with the farthest depth written so far (r456 H3)."""
    written, out = [], []
    for d, w in zip(np.asarray(depths, float).tolist(), np.asarray(writes, bool).tolist()):
        ok = not written or d < max(written)
        out.append(ok)
        if ok and w:
            written.append(d)
    return np.array(out, dtype=bool)


def _sorted(depths, writes, back: bool) -> np.ndarray:
    """The fragments sorted by depth (then mask) before the test, the answers in that order or
    put back in drawing order (``back``; r496 H9)."""
    d, w = np.asarray(depths, float), np.asarray(writes, bool)
    order = np.lexsort((w, d))
    out = _simulate(d[order], w[order])
    if not back:
        return out
    back_out = np.empty_like(out)
    back_out[order] = out
    return back_out


SORTED_WORDS = (
    "you sorted the fragments by depth before testing them: they arrive in drawing order (the "
    "order given), each is decided on arrival against what the fragments drawn before it "
    "wrote, and the answer holds one True or False per fragment in that order"
)


#: r456: first explanations that were the hint alone (H1 to H3) or a false "glass never passes"
MORE_MISTAKES = [
    Mistake("mask looked up by depth", _by_depth_words, gives=_mask_by_depth),
    Mistake("glass needs a wall", "glass fails in your answer while the buffer is still empty "
            "(nothing opaque drawn before it): an empty buffer holds nothing in front of the "
            "glass, so it passes (then a wall drawn later behind it passes too and covers it)",
            gives=_glass_needs_a_wall),
    Mistake("started at the farthest depth", "you started the buffer at the farthest depth of "
            "the pixel (`max(depths)`), so a fragment at that depth fails even when nothing was "
            "drawn before it: the buffer starts empty, and the first fragment passes whatever "
            "its depth", gives=lambda d, w: _simulate(d, w, start=max(d) if len(d) else np.inf)),
    Mistake("drawing order reversed", "you decided the fragments from the last to the first: "
            "they arrive in the order given (drawing order), and each is tested against what the "
            "fragments drawn before it wrote",
            gives=lambda d, w: _simulate(np.asarray(d, float)[::-1], np.asarray(w, bool)[::-1])[::-1]),
    Mistake("sorted by depth", SORTED_WORDS, gives=lambda d, w: _sorted(d, w, back=False)),
    Mistake("sorted by depth", SORTED_WORDS, gives=lambda d, w: _sorted(d, w, back=True)),
    Mistake("answers reversed", "your answers are right but in reverse order (the last "
            "fragment's first): answer k is fragment k's, in drawing order",  # r507 H9
            gives=lambda d, w: _simulate(d, w)[::-1]),
    Mistake("farthest written", "you compared each fragment with the farthest depth written so "
            "far: the buffer holds the depth of the last fragment that passed and wrote, which "
            "is the nearest so far", gives=_farthest_written),
]  # fmt: skip


#: r357 H1: after every cause the checker runs, and only where it fits every failing case (a
#: description, no answer it gives: not in :data:`DEPTH_MISTAKES`, which the capstone runs)
SHIFTED = Mistake("shifted by one", _shift_words, fits=_shifted, only_whole=True, consistent=True)


def _held_depth(depths, writes, passed, k) -> float | None:
    """The depth the buffer holds when fragment ``k`` arrives (None: empty)."""
    written = [d for d, w, p in zip(depths[:k], writes[:k], passed[:k]) if w and p]
    return written[-1] if written else None


#: The frame of a bar whose verdict the student got wrong (r306 FIG3: the wrong verdict was
#: only a small label on a bar coloured by the right one).
WRONG_FRAME = "#ff9f1c"


def draw_depth_passes(ax, case, got):
    """The fragments in drawing order as bars at their depths (hatched: glass, no depth
    write), green where they pass and red where they fail; each tick says yours, and a bar
    whose verdict you got wrong is framed thick, its label marked ✗."""
    _, (depths, writes), expected = case
    n = len(depths)
    if n == 0:
        ax.set_axis_off()
        return [ax.text(0.5, 0.5, "no fragments", ha="center", transform=ax.transAxes)]
    x = np.arange(n)
    # r456: depths near the near plane (1e-20) are drawn on their own scale, not as no bar
    top = 1.0 if max(depths) > 0.05 else max(max(depths), 1e-300)
    colours = ["#7fbf7f" if p else "#d7301f" for p in expected]
    mine = got is not None and len(got) == n
    wrong = [bool(mine and got[i] != expected[i]) for i in range(n)]
    artists = list(ax.bar(x, depths, color=colours,
                          edgecolor=[WRONG_FRAME if w else "black" for w in wrong],
                          linewidth=[4 if w else 1 for w in wrong],
                          hatch=[None if w else "//" for w in writes]))  # fmt: skip
    if mine:
        for i in range(n):
            # at the bar's foot: above it, the buffer's line may run (r64)
            said = "passes" if got[i] else "fails"
            artists.append(ax.text(i, 0.02 * top, f"yours:\n{said}" + (" ✗" if wrong[i] else ""),
                                   ha="center", va="bottom", fontsize="x-small",
                                   fontweight="bold" if wrong[i] else "normal",
                                   bbox={"boxstyle": "round,pad=0.15", "facecolor": "white",
                                         "edgecolor": WRONG_FRAME if wrong[i] else "none",
                                         "alpha": 0.9}))  # fmt: skip
    artists += _buffer_line(ax, depths, writes, top)
    ax.set_xticks(x, [f"{i}" + ("" if writes[i] else "\nglass") for i in range(n)],
                  fontsize="x-small")  # fmt: skip
    ax.set_ylim(0, 1.08 * top)
    key = "green: passes, red: fails" + (";\nframed ✗: your verdict differs" if any(wrong) else "")
    ax.set_xlabel(f"fragments in drawing order\n({key})")
    ax.set_ylabel("depth (smaller is nearer)")
    if top < 1.0:  # the scale in the label, not as an offset above the axis
        exp = int(np.floor(np.log10(top)))
        ax.yaxis.set_major_formatter(lambda y, _: f"{y / 10.0**exp:g}")
        ax.set_ylabel(f"depth (× 1e{exp})\nsmaller is nearer")
    return artists


def _buffer_line(ax, depths, writes, top: float = 1.0) -> list:
    """What the buffer holds as each fragment arrives, by the rule (r46 C3, r64: the bars
    showed the verdicts but not the number they are decided against); empty drawn at the
    top."""
    held, stored = [], np.inf
    for d, w in zip(depths, writes):
        held.append(stored)
        if passes_depth_test(d, stored) and w:
            stored = d
    shown = [min(h, 1.04 * top) for h in held]
    x = np.arange(len(depths))
    artists = list(ax.step(np.r_[x - 0.5, x[-1] + 0.5], np.r_[shown, shown[-1]], where="post",
                           color="#2b2b2b", linewidth=2, linestyle="--",
                           label="the buffer holds,\non arrival\n(top: empty)"))  # fmt: skip
    # outside the axes, to the right: never over a bar, its verdict or the empty buffer's line
    artists.append(ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1), fontsize="x-small"))
    return artists


DEPTH_PASSES = Exercise(
    "depth_passes", depth_cases, as_passes, same_passes, explain_depth, _rule,
    # r448 M1: "glass is still tested" only where no passing answer lets glass behind a wall
    # fail (it was said of glass tested against the first wall written)
    [*(replace(m, consistent=True) if m.kind == "glass untested" else m for m in DEPTH_MISTAKES),
     GLASS_WHOLE_PIXEL, *MORE_MISTAKES, MARGIN, SHIFTED],
    # r456 W5: the package's depth test inside the student's loop passed unflagged
    answers=(PackageAnswer(passed_on_arrival),
             PackageAnswer(passes_depth_test, what="the depth test, a part of this very answer")),
    draw=draw_depth_passes, hints=(
        # issue 30 (r46 C2): the task asks for the buffer's rule; the first wrong try asks back
        ("A fragment passes when it is strictly nearer than the depth the buffer holds, and "
         "only one that passes and writes depth changes what the buffer holds",
         "Which depth must the buffer hold so that the nearest opaque fragment ends up on top "
         "whatever the drawing order, and glass hides nothing? Work the case through by hand"),
        # r174 12-4: the tie's words were the whole fix on the first wrong try
        (TIE_WORDS, "your test settles a tie (two equal depths) otherwise than the rule: which "
         "of the two must the pixel keep, the fragment already stored or the one arriving?"),
    ),
)  # fmt: skip
