"""Name the mistake behind wrong answers, only where it is the cause.

Given every answer of a check, :func:`diagnose` decides, for each failing case, which words
explain it, in this order:

1. **A constant answer.** When the function returned the same value on every case (what it
   returned, before the answer is read: a ``span`` returned as (stop, first) covers nothing on
   every case but is computed) while the expected answers differ, it ignores its arguments
   (``return 0`` left in): that is said first, on every failure, whatever else would give the
   same answers, and nothing else is said (no mistake's name, no rule: r64 04-1, 06-1). An
   exercise whose computed mistake gives the same answer everywhere holds a case where it
   does not (``clip_near``'s z − w keeps a triangle beyond the far plane).
2. **A mistake that gives every answer.** Each :class:`~.exercise.Mistake` is run on every
   answered case; one that gives the student's answer on all of them (passing cases
   included) is the cause, named on every failure it explains. On a failing case a mistake
   counts only where it changes the answer (its answer there is not the right one): a named
   mistake reproduces the student's numbers on the very case it is named on (r153 D3-2). A single mistake is preferred
   to a combination, an earlier one in the exercise's table to a later one. An answer of
   float32's numbers is also compared with the mistake computed on the case's numbers as
   float32 holds them (r164 F1: abs(E) 100 000 px out, where float32 moves the vertices).
   A mistake with a :attr:`~.exercise.Mistake.parameter` (an ε, a factor) is named only
   where that parameter is one number on every failing case it fits; one with
   :attr:`~.exercise.Mistake.reads` only where the student's code reads that name (r175 B5:
   ``np.linalg.det``, whose answers are a bare solve's).
3. **A mistake that gives this answer.** Otherwise each failure gets the mistake that gives
   its answer and agrees with the most answers overall, provided it agrees with four answers
   in five (else its answer here is a coincidence, frequent where answers are few: three
   verdicts, a bool); symptoms ("keeps a vertex behind the plane") only when no cause fits.
   A mistake with ``must_fit`` (a tie rule) is named only where it gives the answer of every
   failing case ``must_fit`` picks (every tie case), else nowhere (r84 10-2).
   An exercise with ``partial_names=False`` names here only a mistake that gives every
   failing answer.
4. **Rounded**: the right numbers rounded to N decimals (or significant digits), when that
   gives every failing answer. **Low precision**, asked only of numbers that precision holds
   (``np.float32(x) == x``), and only when the error is within the rounding of the precision named
   (float32: ``8 · 2**-24`` of the case's scale, see :attr:`.exercise.Exercise.float32`), and
   **NaN or infinity** in the answer.

Whatever names it (this engine's words, an exercise's mistake, its rule), an explanation
that puts the error down to float32, float16 or cancellation is said only where
:func:`precision_may_be_named` allows it on that case: the answer within that precision's
rounding of the case (:func:`rounding_bound`), or the very answer a float32 computation of the
case gives. Elsewhere the rule is said, or plainly that the numbers differ by more than
rounding (issue 30: "never blame float32 where the answer is off by more than float32's
rounding"). One rule, here, for every exercise.
5. **An argument handed back**: every answer is one of the arguments, unchanged
   (``return background``), and no mistake of the table gives every failing answer: said as
   a constant is, by the argument's name (r64 06-1, never the rule).
6. Otherwise the rule, with the case's numbers.

Each failure's kind is the kind of the mistake named (for a combination, of the parts that
change this case's answer; for a "float32" mistake, the answer's own precision, float16 where it
is), so that one failure of each kind can be shown first.
"""

from __future__ import annotations

import re
import threading
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from .answers import short
from .exercise import Exercise, Mistake, case_key, copies
from .running import run_checker
from .scalars import num, vec

#: Relative rounding of one float32 operation, and how many operations' worth counts as float32.
FLOAT32_EPS, FLOAT32_OPS = 2.0**-24, 8
FLOAT16_EPS = 2.0**-11
#: Tolerance of "this mistake gives the student's answer" (two codings of one mistake may round
#: differently).
MATCH_TOL = 1e-6
#: A mistake named on some cases only must agree with at least this share of all its answers.
COINCIDENCE = 0.8


@dataclass(frozen=True)
class Result:
    """One answered case: its index in the check, arguments, expected answer and the student's."""

    index: int
    args: tuple
    expected: object
    got: object
    ok: bool
    #: What the function returned, before it was read (one value of it, when it is called
    #: once per pixel), and a key of all it returned on this case (None: not comparable).
    raw: object = None
    key: frozenset | None = None

    @cached_property
    def case(self):
        """A key of the case's arguments (:func:`.exercise.case_key`; None: none), by which
        each mistake's answer here is remembered (:func:`mistake_answer`)."""
        return case_key(self.args)


_EXACT = (str, bytes, bool, np.bool_, set, frozenset)
_FLOATS = (float, np.float64)


def near(a, b, tol: float = MATCH_TOL) -> bool:
    """The same answer: numbers within ``tol`` relative (NaN equals NaN), others equal.

    >>> near(1.0, 1.0 + 1e-9), near([1, 2], (1.0, 2.0)), near(True, 1.0), near("a", "a")
    (True, True, False, True)
    """
    ta, tb = type(a), type(b)
    if ta in _FLOATS and tb in _FLOATS:  # the same test as below, without numpy
        a, b = float(a), float(b)
        # r286 C1: a finite difference only (inf is within tol·inf of every number)
        if a == b or abs(a - b) <= tol * max(1.0, abs(a), abs(b)) < np.inf:
            return True
        return a != a and b != b  # both NaN
    if ta is tb is str:
        return a == b
    if ta is tb is np.ndarray and a.dtype == b.dtype == np.bool_ and a.shape == b.shape:
        return tol >= 1.0 or bool((a == b).all())  # 0 and 1 apart by 1, within a scale of 1
    if isinstance(a, _EXACT) or isinstance(b, _EXACT):
        if type(a) is not type(b) and not (
            isinstance(a, (bool, np.bool_)) and isinstance(b, (bool, np.bool_))
        ):
            return False
        try:
            return bool(a == b)
        except Exception:  # noqa: BLE001 - an odd answer simply does not match
            return False
    x, y = _numbers(a), _numbers(b)
    if x is None or y is None:
        try:
            return bool(np.all(a == b))
        except Exception:  # noqa: BLE001
            return False
    if x.shape != y.shape:
        if x.size != 1 or y.size != 1:
            return False
        x, y = x.reshape(()), y.reshape(())
    with np.errstate(invalid="ignore", over="ignore"):
        scale = np.maximum(1.0, np.maximum(np.abs(x), np.abs(y)))
        ok = (x == y) | (np.abs(x - y) <= tol * scale) & (scale < np.inf)
        ok |= np.isnan(x) & np.isnan(y)
    return bool(np.all(ok))


def compose(head: str, words: str) -> str:
    """The case's numbers, then the reason (after ": ", or directly after punctuation)."""
    if not words:
        return head
    if words[0] in " ;:.,(":
        return head.rstrip() + words
    return f"{head}: {words}"


# -- the engine's own mistakes ----------------------------------------------------------------
def constant_words(value, returned=None) -> str:
    """The words for an answer that never changes; ``returned``: the number the function
    returned, where the check read it as the bool ``value`` (r214 item 12: ``return 0`` was
    told "returns False")."""
    shown = short(value)
    x = None if isinstance(value, _EXACT) else _numbers(value)
    if x is not None and x.size == 1:
        shown = num(float(x.ravel()[0]))
    elif x is not None and 1 < x.size <= 6 and x.ndim == 1:
        shown = vec(x)
    if returned is not None:
        shown = f"{short(returned)} (read as {value})"
    return (
        f"your function returns {shown} on every case, whatever its arguments: a "
        "placeholder left in, or a `return` reached too early?"
    )


def _numbers(x) -> np.ndarray | None:
    """``x`` as a float array, or None (text, objects, sets)."""
    if isinstance(x, _EXACT):
        return None
    try:
        a = np.asarray(x, dtype=float)
    except (TypeError, ValueError):
        return None
    return a


def _constant(results: list[Result], per_call: bool = False) -> object | None:
    """The one answer of every case, when the function returned the same value on every case
    and the expected answers differ; else None. Judged on what it returned where every case
    has a key of that (``(stop, first)`` spans differ, though each covers nothing), else on
    the answers as read. ``per_call``: the function is called once per pixel, and the value
    given is what one call returned (``False``), not the case's answer (an image)."""
    if len(results) < 3:
        return None
    if all(near(r.expected, results[0].expected, 0.0) for r in results[1:]):
        return None
    if all(r.key is not None for r in results):
        keys = frozenset().union(*(r.key for r in results))
        if len(keys) != 1 and not _one_number(keys):
            return None
        return results[0].raw if per_call else results[0].got
    first = results[0].got
    if not all(near(r.got, first, 0.0) for r in results[1:]):
        return None
    return first


def _one_number(keys) -> bool:
    """Are these answers' keys one number of several types (r423 MN1: ``0``, ``0.0`` and
    ``np.float64(0)`` are one constant 0, judged by value as :func:`near` does)?"""
    numbers = (int, float, np.integer, np.floating)
    values = [k[1] for k in keys if isinstance(k, tuple) and len(k) == 2]
    if len(values) != len(keys) or not all(
        isinstance(v, numbers) and not isinstance(v, (bool, np.bool_)) for v in values
    ):
        return False
    return len({float(v) for v in values}) == 1


def _number_read_as_bool(results: list[Result], value) -> object | None:
    """The number every case returned, where the check read it as the bool ``value``; else
    None (judged on what was returned, as :func:`_constant` is)."""
    if not isinstance(value, (bool, np.bool_)) or not all(r.key is not None for r in results):
        return None
    if len(frozenset().union(*(r.key for r in results))) != 1:
        return None
    raw = results[0].raw
    numbers = (int, float, np.integer, np.floating)
    return raw if isinstance(raw, numbers) and not isinstance(raw, (bool, np.bool_)) else None


def _handed_back(results: list[Result]) -> int | None:
    """The position of the argument every answer is, unchanged, when some answer is wrong."""
    if len(results) < 3 or all(r.ok for r in results):
        return None
    for k in range(min(len(r.args) for r in results)):
        if all(near(r.got, r.args[k], 0.0) for r in results):
            return k
    return None


def handed_back_words(name: str) -> str:
    return (
        f"your function returns its argument {name} unchanged on every case, whatever the "
        "others: a placeholder (such as `return "
        f"{name}`) left in, or a `return` reached too early?"
    )


#: The kinds of a failure put down to the arithmetic's precision: the low-precision
#: mistake's kind is the answer's precision (r326 S5: a float16 answer was kind "float32").
PRECISION_KINDS = ("float32", "float16")


def precision_of(got) -> tuple[str, float]:
    """("float16" or "float32", its relative rounding) for the answer's precision."""
    dtype = getattr(got, "dtype", None)
    if dtype is not None and dtype.kind == "f" and dtype.itemsize <= 2:
        return "float16", FLOAT16_EPS
    return "float32", FLOAT32_EPS


def rounding_bound(spec: Exercise, args, expected, got) -> float:
    """How far a float32 (float16) computation of this case may be off: ``FLOAT32_OPS``
    roundings of the case's scale (:attr:`.exercise.Exercise.float32`, else the largest
    number of the right answer), at least of :attr:`.exercise.Exercise.float32_floor` (1
    unless the exercise's answers are far below it)."""
    _, eps = precision_of(got)
    if spec.float32 is not None:
        scale = spec.float32(args)
    else:
        e = _numbers(expected)
        scale = float(np.max(np.abs(e), initial=0.0)) if e is not None and e.size else 0.0
    return FLOAT32_OPS * eps * max(float(scale or 0.0), spec.float32_floor)


def answer_error(expected, got) -> float | None:
    """The largest difference between the answer and the right one, or None where they are
    not numbers of the same size (or the answer holds NaN or infinity)."""
    g, e = _numbers(got), _numbers(expected)
    if g is None or e is None or g.size != e.size or not np.isfinite(g).all():
        return None
    if g.dtype == object or e.dtype == object:
        return None
    return float(np.max(np.abs(g.ravel() - e.ravel()), initial=0.0))


def _within_rounding(spec: Exercise, args, expected, got) -> bool:
    """The answer is off by no more than float32 (float16) rounding of this case."""
    error = answer_error(expected, got)
    return error is not None and error <= rounding_bound(spec, args, expected, got)


#: Words that put an answer's error down to the arithmetic's precision.
PRECISION_WORDS = re.compile(r"float ?32|float ?16|cancel|single precision", re.IGNORECASE)


def blames_precision(words: str) -> bool:
    """Do ``words`` put the error down to float32, float16 or cancellation?

    >>> blames_precision("about float32's rounding"), blames_precision("wrong sign")
    (True, False)
    """
    return bool(PRECISION_WORDS.search(words or ""))


def precision_may_be_named(
    spec: Exercise, r: Result, mistake: Mistake | None, explained: bool = False
) -> bool:
    """May float32 (float16, cancellation) be named on case ``r``? Only when the answer is
    within that precision's rounding of the case (:func:`_within_rounding`), when the case
    holds a number float32 cannot hold at all, or when ``mistake``, a float32 computation of
    the exercise's table, gives this very answer (then its error *is* float32's rounding of
    this case, however far that moves a bool or an integer: ``depth_test``'s two depths one
    float32 apart). A description (``fits``) is that evidence only for an answer that is
    no measure (a bool, an image of bools): a number must be within the bound. Never where
    another mistake of the table (a sign, an absolute value), computed in float64 or on the
    numbers float32 holds, gives this answer and is a cause, no coincidence (``explained``:
    :func:`_explained`, r164 F1)."""
    named = mistake is not None and not mistake.parts and mistake.gives is not None
    if named and run_checker(lambda: _fits(spec, mistake, r), False):
        return True
    if explained:
        return False  # r164 F1: a sign mistake far out is no rounding, however large that is
    if run_checker(lambda: _within_rounding(spec, r.args, r.expected, r.got), False):
        return True
    if run_checker(lambda: _outside_float32(r.args), None) is not None:
        return True
    if mistake is None or mistake.parts or named:
        return False
    return answer_error(r.expected, r.got) is None or _is_bools(r.got)


def honest_on(spec: Exercise, args, expected, got, words: str) -> str:
    """``words`` said of another case of ``spec`` (its own check's), now of the case (``args``,
    ``expected``, ``got``), or :func:`more_than_rounding`'s words where they blame float32
    (float16, cancellation) beyond what :func:`precision_may_be_named` allows on it (r163
    12-2: the capstone quoted exercise 3.1's float32 diagnosis, made on a case whose λ is 512,
    of a pixel 50 to 13,000 float32 steps off). The rule is :func:`precision_may_be_named`'s."""
    if not blames_precision(words):
        return words
    r = Result(-1, tuple(args), expected, got, False)
    return words if precision_may_be_named(spec, r, None) else more_than_rounding(spec, r)


def gives_every_answer(spec: Exercise, mistake: Mistake, cases) -> bool:
    """Whether ``mistake`` gives (a symptom: fits) the student's answer on the first of
    ``cases``, a failing one, and contradicts none of the rest, right or wrong: the discipline
    of :data:`.hiz_tile.EXACT` (named only where it gives every answer, passing ones
    included), for answers asked outside the exercise's own cases (r219: the capstone's pixels,
    where one point may not tell two mistakes apart). ``cases``: (args, expected, got)."""
    results = []
    for args, expected, got in cases:
        ok = run_checker(lambda a=args, e=expected, g=got: bool(spec.same(g, e, a)), False)
        results.append(Result(-1, tuple(args), expected, got, ok))
    verdicts = [run_checker(lambda r=r: _fits(spec, mistake, r), False) for r in results]
    return verdicts[0] is True and False not in verdicts[1:]


def named_on(spec: Exercise, mistake: Mistake, args, expected, got) -> str:
    """``mistake``'s words said on the case (``args``, ``expected``, ``got``), as a check says
    them (a combination: the parts that change this answer)."""
    return _named(spec, mistake, Result(-1, tuple(args), expected, got, False))[1]


def _is_bools(value) -> bool:
    dtype = getattr(value, "dtype", None)
    return isinstance(value, (bool, np.bool_)) or (dtype is not None and dtype.kind == "b")


def more_than_rounding(spec: Exercise, r: Result) -> str:
    """The plain words for an answer that float32 cannot explain."""
    error = answer_error(r.expected, r.got)
    name, _ = precision_of(r.got)
    if error is None:
        return f"; this is not what {name}'s rounding gives: the computation itself differs"
    return (
        f"; yours is off by {error:.2g}, far more than {name}'s rounding of this case (at most "
        f"{rounding_bound(spec, r.args, r.expected, r.got):.1g}): the computation itself differs, not its "
        "precision"
    )


def low_precision_mistake(spec: Exercise) -> Mistake:
    """float32 (or float16) named only when the error is within its rounding on this case, or
    the case holds a number float32 cannot hold (1e-300 becomes 0)."""

    def fits(args, expected, got):
        if _numbers(expected) is None:  # no number is right here (3.1's ValueError): no say
            return None
        if isinstance(got, str):  # r348: nor where the answer is no number (3.1's refusal)
            return None
        if spec.float32_makes_inf and not np.isfinite(_numbers(got)).all():
            # r348: float32 flattened a thin far triangle and divided by its E = 0: said by
            # the exercise's float32 words (_inf_by_float32), not weighed as rounding here
            return None
        if _outside_float32(args) is not None:
            # r421 T2: a float64 answer (3.2's λ / w overflowing at w = 1e-310) is no float32
            # one: float32 says nothing of it there
            return True if answer_in_float32(got) else None
        # r153 D3-5: 0.33333333 (np.round(λ, 8)) is within float32's rounding of 1/3 but is
        # no float32 number: the question is asked only of numbers float32 can hold
        if not held_by_precision(expected, got):
            return False
        if _within_rounding(spec, args, expected, got):
            return True  # r164 F1: not where a mistake of the table is the cause (diagnose)
        # r153 D3-2: an answer of float32's type off by more: float32 says nothing of this
        # case (another mistake, abs(E) where E < 0, explains it) and is named where it fits
        dtype = getattr(got, "dtype", None)
        return None if dtype is not None and dtype.kind == "f" and dtype.itemsize <= 4 else False

    def words(args, expected, got):
        if not _within_rounding(spec, args, expected, got):
            return (
                f": {num(_outside_float32(args))} lies outside float32's range (its smallest "
                f"normal number is {F32.tiny:.3g}, its largest {F32.max:.3g}): in float32 it "
                "becomes 0 or infinity. Compute in float64 (plain Python floats or np.float64)"
            )
        special = spec.float32_words(args, expected, got) if spec.float32_words else None
        if special:
            return special
        name, eps = precision_of(got)
        digits = 7 if name == "float32" else 3
        return (
            f". The difference is about {name}'s rounding ({name} keeps about {digits} "
            f"significant digits): did you compute in {name} (np.{name}, or an array of that "
            "type)? Compute in float64 (plain Python floats or np.float64)"
        )

    return Mistake("float32", words, fits=fits, only_whole=True)


F32 = np.finfo(np.float32)


def held_by_precision(expected, got) -> bool:
    """Is each of the answer's wrong numbers one that its precision (:func:`precision_of`)
    holds, ``np.float32(x) == x``? A float64 answer rounded to 8 decimals is not."""
    g, e = _numbers(got), _numbers(expected)
    if g is None or e is None or g.size != e.size or g.dtype == object:
        return True  # nothing to weigh: the bound alone decides
    name, _ = precision_of(got)
    kind = np.float16 if name == "float16" else np.float32
    g, e = g.ravel(), e.ravel()
    wrong = g[g != e]
    with np.errstate(over="ignore", invalid="ignore"):
        return bool(np.all(wrong.astype(kind).astype(float) == wrong))


#: Decimals (and significant digits) an answer may be rounded to, for :func:`rounded_mistake`.
ROUNDINGS = range(1, 13)


def _rounded_to(expected, got) -> str | None:
    """The words "N decimals" (or "N significant digits") when the answer is the right one
    rounded so (``np.round(x, N)``, ``f"{x:.Ng}"``); else None."""
    g, e = _numbers(got), _numbers(expected)
    if g is None or e is None or g.size != e.size or g.size == 0 or g.dtype == object:
        return None
    if not (np.isfinite(g).all() and np.isfinite(e).all()) or np.array_equal(g, e):
        return None
    g, e = g.ravel(), e.ravel()
    # every N it could be (1, 0, 0) is the rounding of (0.9999996, 4e-7, 0) to 1-6 decimals
    fit = [n for n in ROUNDINGS if _all_close(g, np.round(e, n), 1e-15)]
    if fit:
        return f"{fit[0]} decimals" if len(fit) == 1 else f"{fit[0]} to {fit[-1]} decimals"
    wrong = g != e
    parts = (np.flatnonzero(wrong)[:1], wrong, ~wrong)
    for n in range(3, 13):
        # the first wrong number alone, then every wrong one, then the right ones: most
        # answers fail at the first, and writing out a whole array for every N cost more
        # than the rest of a check (the test is number by number, so the order is free)
        if all(_all_close(g[k], _significant(e[k], n), 1e-300) for k in parts):
            return f"{n} significant digits"
    return None


def _significant(e: np.ndarray, n: int) -> np.ndarray:
    """Each number of ``e`` written with ``n`` significant digits (``f"{x:.ng}"``)."""
    return np.array([float(f"{x:.{n}g}") for x in e])


def _all_close(g: np.ndarray, r: np.ndarray, atol: float) -> bool:
    """``np.allclose(g, r, rtol=1e-12, atol=atol)`` for float arrays of one size (its very
    test, without its checks and conversions: ``_rounded_to`` asks it 12 to 22 times)."""
    with np.errstate(invalid="ignore", over="ignore"):
        close = (np.abs(g - r) <= atol + 1e-12 * np.abs(r)) & np.isfinite(r) | (g == r)
    return bool(close.all())


def _whole(got) -> bool:
    """Is every number of the answer a finite whole number?"""
    g = _numbers(got)
    if g is None or g.dtype == object:
        return False
    with np.errstate(invalid="ignore"):
        return bool(np.isfinite(g).all() and np.array_equal(np.round(g), g))


def rounded_mistake() -> Mistake:
    """The right numbers rounded (``np.round(λ, 4)``): r153 D3-3, told "you added a small
    number to E" and, in 3.2, to re-derive a right derivation. Named only where it gives
    every failing answer."""

    def fits(args, expected, got):
        g = _numbers(got)
        if _numbers(expected) is None or g is None or g.dtype == object:
            return None  # no number is right here (3.1's ValueError): no say
        if not np.isfinite(g).all():  # r421 T2: a NaN (an overflow beside it) shows no rounding
            return None
        if _rounded_to(expected, got) is not None:
            return True
        return None if _whole(got) else False  # whole numbers show no rounding: no say

    def words(args, expected, got):
        return (
            f": yours are the right numbers rounded to {_rounded_to(expected, got)} (np.round, "
            "or a format?): return them unrounded; the check compares far more digits"
        )

    return Mistake("rounded", words, fits=fits, only_whole=True)


def _transposed_to(expected, got) -> bool | None:
    """Is ``got`` the 2-D answer ``expected`` transposed (and not equal to it)? None where
    the answer is not a 2-D array, or where transposing changes nothing: no say."""
    try:
        g, e = np.asarray(got), np.asarray(expected)
    except (TypeError, ValueError):
        return None
    if g.ndim != 2 or e.ndim != 2 or g.shape != e.shape[::-1] or g.dtype == object:
        return None
    if e.shape[0] == e.shape[1] and np.array_equal(e, e.T):
        return None  # symmetric: its transpose is itself
    return bool(np.array_equal(g.T, e))


#: r198 M1: a transposed answer ([x, y] for [row, column]) on a square grid was told the
#: exercise's rule (a corner, an offset), and the shape only on a non-square case, third.
TRANSPOSED_WORDS = (
    ": your answer is transposed: its [i, j] holds what belongs at [j, i] (rows and columns "
    "swapped). An array is indexed [row, column], that is [y, x]: return it in the shape and "
    "order of the inputs (no .T, no [x, y] indexing)"
)


def transposed_mistake() -> Mistake:
    """The right 2-D answer transposed, on every failing case (r198 M1), for every exercise
    whose answer is a 2-D array; an exercise's own transposed mistake, earlier in its table,
    is named before it. A non-square transposed answer is refused by the shape first
    (:func:`.answers.transposed_shape_words`)."""

    def fits(args, expected, got):
        return run_checker(lambda: _transposed_to(expected, got), None)

    return Mistake("transposed", TRANSPOSED_WORDS, fits=fits, only_whole=True)


def answer_in_float32(got) -> bool:
    """Is the answer in float32 (or float16): an array, or numbers, of that type?"""
    try:
        dtype = np.asarray(got).dtype
    except (TypeError, ValueError):
        return False
    return dtype.kind == "f" and dtype.itemsize <= 4


def _outside_float32(args) -> float | None:
    """A number of the case that float32 cannot hold (it would become 0 or inf), or None."""
    for a in args:
        x = _numbers(a)
        if x is None or x.dtype == object:
            continue
        x = np.abs(x[np.isfinite(x)])
        bad = x[(x > F32.max) | ((x > 0) & (x < F32.tiny))]
        if bad.size:
            return float(bad.ravel()[0])
    return None


def _holds_none(x) -> bool:
    """Does ``x`` hold None (r409 F1: a legal None, "no type holds it", is never NaN)?"""
    try:
        return any(v is None for v in np.asarray(x, dtype=object).ravel())
    except (TypeError, ValueError):
        return False


def _nan_words(args, expected, got) -> str | None:
    g = _numbers(got)
    if g is None or np.isfinite(g).all() or _holds_none(got):
        return None
    # r286 C1: where, so that one bad channel of a colour is found
    bad = np.isnan(g) if np.isnan(g).any() else ~np.isfinite(g)
    at = "" if g.size == 1 else f" at {[int(i) for i in np.argwhere(bad.reshape(g.shape))[0]]}"
    if np.isnan(g).any():
        return _NAN_WORDS.replace("NaN", f"NaN{at}", 1)
    sign = "-" if (g[bad] < 0).all() else "+" if (g[bad] > 0).all() else "±"
    return f"your answer holds {sign}inf{at} (infinity: a division by zero?)"


def _inf_by_float32(spec: Exercise, r: Result) -> str | None:
    """±inf far from the origin where the exercise's own float32 words name the cause (a
    float32 plane in absolute coordinates cancels its area to 0, then divides by it): said
    with the inf, as before r286 told inf only as "a division by zero?"."""
    # float32 turns finite inputs into inf only through a difference cancelled to 0 then
    # divided by (overflow is _outside_float32's): the exercise says whether it can
    if not spec.float32_makes_inf or spec.float32_words is None:
        return None
    special = spec.float32_words(r.args, r.expected, r.got)
    return f"{_nan_words(r.args, r.expected, r.got)}{special}" if special else None


_NAN_WORDS = "your answer holds NaN (a 0/0, or a NaN input passed on?)"


def _legal_nan(spec: Exercise, words: str | None) -> str:
    """NaN's words, the exercise's own where NaN is a legal answer (not "a 0/0", r340)."""
    words = words or _NAN_WORDS
    return spec.nan_words if spec.nan_words is not None and "NaN" in words else words


def _holds_inf(r: Result) -> bool:
    """Does the answer hold ±inf where the expected answer is finite?"""
    g, e = _numbers(r.got), _numbers(r.expected)
    if g is None or e is None or g.dtype == object or e.dtype == object:
        return False
    return bool(np.isinf(g).any() and np.isfinite(e).all())


def _all_nan(value) -> bool:
    """Is every number of ``value`` NaN or ±inf (a constant answer told NaN, not
    "placeholder")?"""
    x = _numbers(value)
    return x is not None and x.size > 0 and x.dtype != object and not np.isfinite(x).any()


def _shape_words(expected, got) -> str | None:
    g, e = np.shape(got), np.shape(expected)
    if g == e or np.size(got) == np.size(expected) == 1:
        return None
    try:
        if isinstance(got, (str, set)) or isinstance(expected, (str, set)):
            return None
    except TypeError:
        return None
    return f"your answer has {np.size(got)} value(s), shape {g}; the answer here has shape {e}"


# -- the choice ---------------------------------------------------------------------------------
@dataclass
class _Fit:
    mistake: Mistake
    order: int
    failing: set  # indices of the failing cases it explains
    agrees: int  # answered cases it agrees with (passing ones included)
    whole: bool  # it agrees with every answered case it speaks about
    spoken: int = 0  # answered cases it says something about
    contradicts: bool = False  # it gives another answer on a passing case

    @property
    def coincidence(self) -> bool:
        """A wrong solution that gives this answer but disagrees with most of the others: a
        coincidence (frequent where answers are few: three verdicts, a bool), not a cause."""
        return self.mistake.gives is not None and self.agrees < COINCIDENCE * self.spoken


#: Remember each mistake's answer on each case (:func:`mistake_answer`); False computes every
#: one afresh (the tests compare the reports both ways).
REMEMBER = True
#: The most answers remembered anew; past it they become the older generation (the one before
#: is forgotten), from which an answer asked again is taken back, not computed again: the cases
#: drawn afresh for each check fill the book with answers never asked again, and clearing it
#: all threw away the fixed cases' answers too (44,000 of the 199,000 answers computed in
#: test_checker_corpus.py were computed a second time). 200,000, not 100,000: over half the
#: corpus's wrong variants in one process (541 checks, about one worker's share), a generation
#: of 100,000 turned over before the next check of an exercise asked its fixed cases again:
#: 495,000 answers computed, against 357,000 with 200,000 (353,000 with no limit at all);
#: 167 -> 161 s of CPU, side by side, and the same resident memory at the end (2.33 -> 2.28 GB).
REMEMBERED = 200_000
#: Mistake -> {case key (Result.case): answer, None where undefined}: the answers remembered
#: since the last turn, then the generation before
_remembered: list = [{}, {}]
_lock = threading.Lock()
_count = [0]  # answers remembered in the newer generation


def mistake_answer(m: Mistake, r: Result):
    """``m.gives`` on fresh copies of case ``r``'s arguments; None where the mistake says
    nothing about the case or is undefined on it (an ArithmeticError, ValueError,
    IndexError or TypeError). Each mistake's answer on a case is a function of the case
    alone, the same on every check, so it is computed once per process and kept by the
    mistake and the case's key (``Result.case``): every check of an exercise runs the same
    fixed cases, and the diagnosis runs each of up to ~300 mistakes on them (the checker's
    own time, about half of a failing check's). Handed out as a copy (a comparison that
    wrote into it could not change the next check's), computed afresh where the case has no
    key (or :data:`REMEMBER` is off). The student's function is never remembered."""
    key = r.case if REMEMBER else None
    if key is None:
        return _gives(m, r.args)
    newer, older = _remembered
    book = newer.get(m)
    if book is not None and key in book:
        return _fresh(book[key])
    book = older.get(m)
    if book is not None and key in book:
        value = book[key]
    else:
        value = _gives(m, r.args)  # outside the lock: an interrupt may stop it
    with _lock:
        if _count[0] >= REMEMBERED:
            _remembered[:] = [{}, _remembered[0]]
            _count[0] = 0
        _remembered[0].setdefault(m, {})[key] = value
        _count[0] += 1
    return _fresh(value)


def _gives(m: Mistake, args):
    try:
        return m.gives(*copies(args))
    except (ArithmeticError, ValueError, IndexError, TypeError):  # undefined on this case
        return None


def _fresh(value):
    """A copy of an answer's arrays and lists (tuples of them too), the rest as it is."""
    if isinstance(value, np.ndarray):
        return value.copy()
    if type(value) in (list, tuple):
        return type(value)(_fresh(v) for v in value)
    return value


def _fits(spec: Exercise, m: Mistake, r: Result) -> bool | None:
    """Does mistake ``m`` give (or fit) answer ``r``? None: it says nothing about this case."""
    if m.fits is not None:  # a description of failures: a passing case neither fits nor not,
        if r.ok and not m.consistent:  # unless the description speaks of passing cases too
            return None
        verdict = m.fits(r.args, r.expected, r.got)
        return None if verdict is None else bool(verdict)  # None: it says nothing here
    value = mistake_answer(m, r)
    if value is None:
        return None
    same = _same_answer(spec, value, r) or (not r.ok and _gives_in_precision(spec, m, r, value))
    if same and not r.ok and _passes(spec, value, r):
        # r153 D3-2: a mistake that gives the right answer here does not change this case,
        # so it cannot be why the student's answer is wrong (float32 with abs(E) was blamed
        # on the abs where E > 0): a mistake is named only where it reproduces the student's
        # numbers *and* they differ from the right ones
        return None
    return same


def _precision_inputs(args, got) -> tuple | None:
    """The case's arguments as a float32 (float16) computation holds them, each float rounded
    to the answer's precision (:func:`precision_of`) and back, or None where that changes none
    of them (the mistake's float64 answer is then the one to compare)."""
    _, eps = precision_of(got)
    kind = np.float16 if eps == FLOAT16_EPS else np.float32
    out, moved = [], False
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        for a in copies(args):
            if isinstance(a, np.ndarray) and a.dtype.kind == "f":
                b = a.astype(kind).astype(a.dtype)
            elif isinstance(a, float):
                b = float(kind(a))
            else:
                b = a
            moved = moved or not np.array_equal(b, a)
            out.append(b)
    return tuple(out) if moved else None


def _gives_in_precision(spec: Exercise, m: Mistake, r: Result, value) -> bool:
    """Does mistake ``m``, computed on the case's numbers as float32 holds them, give the
    student's float32 answer, far nearer it than the right answer is? (r164 F1: abs(E) in
    float32, 30 000 px out, where float32 cannot hold the 1/256-px grid: the weights negated,
    off by 13, were put down to float32's cancellation, because the mistake's float64 answer
    differed from the student's by float32's moving of the vertices.) Numbers only, and only
    answers that are float32's numbers (:func:`held_by_precision`)."""
    if _is_bools(r.got) or not held_by_precision(r.expected, r.got):
        return False
    error = answer_error(r.expected, r.got)
    if error is None or error == 0:
        return False
    moved = _precision_inputs(r.args, r.got)
    if moved is None:
        return False
    try:
        rounded = m.gives(*moved)
    except (ArithmeticError, ValueError, IndexError, TypeError):
        return False
    off = answer_error(rounded, r.got) if rounded is not None else None
    if off is None or off > error / 8 or not _within_rounding(spec, r.args, rounded, r.got):
        return False
    # the mistake itself, in float64, already lies nearer the answer than the right one does:
    # float32 accounts for the rest only (E truncated, -10 for -10.97, gave float32's -11
    # once the vertices had moved)
    near_it = answer_error(value, r.got)
    return near_it is not None and near_it <= error / 2


def _explained(fits: list[_Fit], failing: list[Result]) -> set:
    """The failing cases that a mistake of the table which is not itself a precision (a
    sign, an absolute value) gives, computed in float64 or on the numbers float32 holds, and
    is a cause there, no coincidence (:attr:`_Fit.coincidence`): their error is that
    mistake's, not float32's rounding (r164 F1). Only errors beyond the precision's rounding
    of the answer's own size count (a float32 computation far from the origin may round far
    more: a cancelling plane's)."""
    out = set()
    for r in failing:
        error = answer_error(r.expected, r.got)
        e = _numbers(r.expected)
        _, eps = precision_of(r.got)
        if (
            error is None
            or e is None
            or error <= FLOAT32_OPS * eps * max(1.0, float(np.abs(e).max()))
        ):
            continue
        if any(r.index in f.failing and not f.coincidence and f.mistake.gives is not None
               and not f.mistake.parts and not blames_precision(f.mistake.kind)
               for f in fits):  # fmt: skip
            out.add(r.index)
    return out


def _precision_note(spec: Exercise, m: Mistake, r: Result) -> str:
    """What a mistake found in float32 (:func:`_gives_in_precision`) leaves to say: the rest
    of the difference is the precision's (empty where the float64 mistake gives the answer)."""
    if m.gives is None or r.ok:
        return ""
    value = m.gives(*copies(r.args))
    if value is None or _same_answer(spec, value, r):
        return ""
    name, _ = precision_of(r.got)
    rest = answer_error(value, r.got)
    return (
        f"; and you computed in {name}, whose rounding of this case's coordinates moves your "
        f"numbers by a further {rest:.1g}: compute in float64"
    )


def _evaluate(spec: Exercise, mistakes: list[Mistake], results: list[Result]) -> list[_Fit]:
    failing = [r for r in results if not r.ok]
    fits = []
    for order, m in enumerate(mistakes):

        def run(m=m, order=order):
            verdicts = {}
            for r in failing:
                verdicts[r.index] = _fits(spec, m, r)
                # r446: where only a mistake that gives every failing answer is named, one
                # that misses one is never named: the rest of its cases cost time only
                if verdicts[r.index] is False and not spec.partial_names:
                    return None
            hits = {i for i, v in verdicts.items() if v}
            passing = [r for r in results if r.ok]
            if not hits or not _one_parameter(m, [r for r in failing if r.index in hits], passing):
                return None
            said = [_fits(spec, m, r) for r in results if r.ok]
            agrees = len(hits) + sum(1 for s in said if s)
            whole = False not in verdicts.values() and False not in said
            spoken = sum(v is not None for v in [*verdicts.values(), *said])
            return _Fit(m, order, hits, agrees, whole, spoken, False in said)

        fit = run_checker(run, None)
        if fit is not None:
            fits.append(fit)
    return fits


#: How far apart a mistake's :attr:`~.exercise.Mistake.parameter` may be on two cases and
#: still be one number (it is read back from float64 answers: ε from a sum near 1).
PARAMETER_TOL = 1e-3


def _one_parameter(m: Mistake, hits: list[Result], passing: list[Result] = ()) -> bool:
    """Is ``m``'s parameter one number on every failing case it fits (or has it none)? A
    parameter given as a range (lo, hi) of the numbers that give a case's answer (r438: a
    tolerance) must hold one number on every failing case it fits and every passing case."""
    if m.parameter is None:
        return True
    values = [m.parameter(r.args, r.expected, r.got) for r in hits]
    if values and all(isinstance(v, tuple) for v in values):
        values += [
            v for r in passing if isinstance(v := m.parameter(r.args, r.expected, r.got), tuple)
        ]
        return max(v[0] for v in values) < min(v[1] for v in values)
    if any(v is None or not np.isfinite(v) for v in values):
        return False
    lo, hi = min(values), max(values)
    return hi - lo <= PARAMETER_TOL * max(abs(lo), abs(hi))


def scaled_mistake(words) -> Mistake:
    """The right numbers times one constant c ≠ 1 on every failing case (r164: half-areas,
    ``0.5 * λ``, and ``λ * 1.00000003`` were told "you added a small number to E");
    ``words(args, expected, got, c)``. Named only where c is the same on every failing case
    (:attr:`~.exercise.Mistake.parameter`), and only where it gives every failing answer
    (r148's weights each off by its own factor fitted it where p lay on a vertex)."""

    def factor(args, expected, got):
        g, e = _numbers(got), _numbers(expected)
        if g is None or e is None or g.shape != e.shape or not np.isfinite(g).all():
            return None
        big = int(np.argmax(np.abs(e)))
        if e.ravel()[big] == 0:
            return None
        c = float(g.ravel()[big] / e.ravel()[big])
        # a negative factor is a sign (abs(E) where E < 0, edges reversed): the table's own
        if c == 1 or c <= 0 or not np.allclose(g, c * e, rtol=1e-9, atol=1e-12 * abs(c)):
            return None
        return c

    def fits(args, expected, got):
        if _numbers(expected) is None:
            return None  # no number is right here (3.1's ValueError): no say
        return factor(args, expected, got) is not None

    def say(args, expected, got):
        return words(args, expected, got, factor(args, expected, got))

    return Mistake("constant factor", say, fits=fits, parameter=factor, only_whole=True)


def _all_it_must(fit: _Fit, failing: list[Result]) -> bool:
    """The mistake gives every failing answer its :attr:`~.exercise.Mistake.must_fit` asks
    for (r84 10-2: a tie rule named on one case only, another tie rule on the next)."""
    must = fit.mistake.must_fit
    if must is None:
        return True
    return all(r.index in fit.failing for r in failing
               if run_checker(lambda r=r: bool(must(r.args, r.expected, r.got)), False))  # fmt: skip


def _passes(spec: Exercise, value, r: Result) -> bool:
    """Would ``value`` pass case ``r`` (the exercise's own test, :attr:`.Exercise.same`)?"""
    return bool(run_checker(lambda: spec.same(value, r.expected, r.args), False))


_STUDENT = object()


def _same_answer(spec: Exercise, value, r: Result, got=_STUDENT) -> bool:
    """Does ``value`` (what a mistake gives) equal the student's answer (or ``got``)?"""
    got = r.got if got is _STUDENT else got
    return spec.match(got, value, r.args) if spec.match is not None else near(value, got)


def _active_parts(spec: Exercise, m: Mistake, r: Result) -> list[Mistake]:
    """The parts of a combination that change this case's answer (all of them if none alone)."""
    if not m.parts:
        return [m]
    active = []
    for part in m.parts:
        other = m.without(part)(*copies(r.args))
        if other is None or not _same_answer(spec, other, r):
            active.append(part)
    return active or list(m.parts)


def _named(spec: Exercise, m: Mistake, r: Result) -> tuple[str, str]:
    parts = run_checker(lambda: _active_parts(spec, m, r), list(m.parts) or [m])
    if not m.parts:
        words = run_checker(lambda: m.say(r.args, r.expected, r.got), "")
        kind = m.kind
        if kind == "float32":  # an answer in float16 is told so in words: its kind too
            kind = run_checker(lambda: precision_of(r.got)[0], kind)
        return kind, words + run_checker(lambda: _precision_note(spec, m, r), "")
    kind = " and ".join(p.kind for p in parts)
    words = run_checker(lambda: "; and ".join(p.say(r.args, r.expected, r.got) for p in parts), "")
    return kind, words


def diagnose(
    spec: Exercise, results: list[Result], params: tuple = (), reads: frozenset = frozenset()
) -> dict[int, tuple[str, str]]:
    """(kind, explanation) for each failing case of ``results``, by index (module docstring);
    ``params``: the names of the student's function's arguments; ``reads``: the names its
    code reads, its own parameters read included (a mistake with
    :attr:`~.exercise.Mistake.reads` is named only among them, one with
    :attr:`~.exercise.Mistake.unread` only outside them)."""
    failing = [r for r in results if not r.ok]
    if not failing:
        return {}
    out = {}
    # issue 30 (r64 04-1): a constant first, before any mistake of the table is run
    value = run_checker(lambda: _constant(results, spec.call is not None), None)
    if value is not None:
        # r107 N3-2: NaN on every case is a 0/0 far more often than a placeholder
        # (CONVENTIONS.md, Exercises and grading), unless NaN is one of the answers
        nan = _all_nan(value)
        kind = "nan" if nan else "constant"
        if nan and spec.constant_nan is not None:  # r374 F1: NaN legal, so no 0/0 here
            words = spec.constant_nan(results)
        elif nan:  # r286 C1: ±inf everywhere is told as NaN is, not "a placeholder"
            words = _legal_nan(spec, _nan_words((), None, np.ravel(_numbers(value))[:1]))
        elif spec.constant is not None:
            words = spec.constant(value)
        else:
            number = None if spec.call is not None else _number_read_as_bool(results, value)
            words = constant_words(value, number)
        return {r.index: (kind, _said_constant(spec, r, words)) for r in failing}
    rounded = rounded_mistake()
    mistakes = [
        m for m in spec.all_mistakes()
        if (m.reads is None or m.reads in reads) and (m.unread is None or m.unread not in reads)
    ]  # fmt: skip
    # float32 before rounding: where both give every failing answer (158.25 for 158.249, from
    # float32 products of 3.9e6 on one drawn case), the answer is float32's own number
    mistakes += [transposed_mistake(), low_precision_mistake(spec), rounded]
    fits = _evaluate(spec, mistakes, results)
    if all(run_checker(lambda r=r: _whole(r.got), False) for r in failing):
        # rounding to N decimals shows only in an answer with a fraction: whole numbers
        # everywhere are the exercise's own "whole numbers" (r22 D-6's faint pixel, 0)
        fits = [f for f in fits if f.mistake is not rounded]
    fits = [f for f in fits if (f.whole or not f.mistake.only_whole) and _all_it_must(f, failing)
            and not (f.mistake.consistent and f.contradicts)]  # fmt: skip
    explained = run_checker(lambda: _explained(fits, failing), set())
    for f in fits:  # r164 F1: float32 is not chosen where a mistake of the table is the cause
        if f.mistake.gives is None and blames_precision(f.mistake.kind):
            f.failing = f.failing - explained
    whole = sorted(
        (f for f in fits if f.whole and not f.mistake.symptom),
        key=lambda f: (len(f.mistake.parts), f.order),
    )
    back = run_checker(lambda: _handed_back(results), None)
    if back is not None and not any(len(f.failing) == len(failing) for f in whole):
        name = params[back] if back < len(params) else f"number {back + 1}"
        words = handed_back_words(name)
        return {r.index: ("constant", _said_constant(spec, r, words)) for r in failing}
    exact = run_checker(lambda: _exactly(spec, whole, failing), None) or _Fit(None, 0, set(), 0, False)  # fmt: skip
    chosen_of = {}
    for r in failing:
        # r286 C1: inf is said as such, not as a symptom ("one texel alone") of a slip; a
        # slip the checker runs and finds giving that very answer still names it (NaN keeps
        # its symptoms: "both alphas 0 … not a division by zero" says more)
        odd = run_checker(lambda r=r: _holds_inf(r), False)
        ran = [f for f in fits if f.mistake.gives is not None] if odd else fits
        chosen = next(
            (f for f in whole if r.index in f.failing and (f.mistake.gives or not odd)), None
        )
        if chosen is not None and chosen.mistake.with_others and r.index in exact.failing:
            chosen = exact
        if chosen is None:
            here = [f for f in ran if r.index in f.failing and not f.coincidence]
            if not spec.partial_names:  # every failing answer, or no name
                here = [f for f in here if len(f.failing) == len(failing)]
            here.sort(key=lambda f: (f.mistake.symptom, -f.agrees, len(f.mistake.parts), f.order))
            chosen = here[0] if here else None
        chosen_of[r.index] = chosen and chosen.mistake
        if chosen is not None:
            kind, words = _named(spec, chosen.mistake, r)
        else:
            kind, words = _generic(spec, r)
        unnamed_inf = odd and chosen is None
        inf32 = unnamed_inf and run_checker(lambda r=r: _inf_by_float32(spec, r), None)
        if inf32:
            out[r.index] = ("float32", _say(spec, r, inf32))
            continue
        kind, words = _honest(spec, r, kind, words, chosen and chosen.mistake, r.index in explained)
        out[r.index] = (kind, _say(spec, r, words))
    # r248: a second slip is said only where every other failing case is named too
    if None in chosen_of.values():
        for r in failing:
            if chosen_of[r.index] is not None and chosen_of[r.index].with_others:
                kind, words = _generic(spec, r)
                kind, words = _honest(spec, r, kind, words, None, r.index in explained)
                out[r.index] = (kind, _say(spec, r, words))
    return _said_once(spec, out)


def _exactly(spec: Exercise, whole: list[_Fit], failing: list[Result]) -> _Fit | None:
    """r376 F1: the first mistake of the table that gives every answer, each failing one it
    explains exactly (the exercise's own test, not its lenient match), where a second slip
    (``with_others``: float64 pixels at the far ties) also gives every answer: said before it
    (an int64 count whose two slips give its answers at the far ties was told float64). None
    where there is none, or no second slip."""
    if not any(f.mistake.with_others for f in whole):
        return None
    for f in whole:
        if f.mistake.with_others or f.mistake.gives is None:
            continue
        hits = [r for r in failing if r.index in f.failing]
        if all(spec.same(mistake_answer(f.mistake, r), r.got, r.args) for r in hits):
            return f
    return None


def _honest(
    spec: Exercise,
    r: Result,
    kind: str,
    words: str,
    mistake: Mistake | None,
    explained: bool = False,
):
    """(kind, words), or the rule (else plain words) where they blame float32 (float16,
    cancellation) beyond what :func:`precision_may_be_named` allows on this case."""
    if not blames_precision(f"{kind} {words}") or precision_may_be_named(
        spec, r, mistake, explained
    ):
        return kind, words
    kind, words = _generic(spec, r)
    if blames_precision(f"{kind} {words}") or not words:
        return "value", more_than_rounding(spec, r)
    return kind, words


def _said_once(spec: Exercise, out: dict[int, tuple[str, str]]) -> dict[int, tuple[str, str]]:
    """Each of ``spec.once``'s texts in full on its first failing case, short on the rest."""
    for text, short_text in spec.once:
        said = False
        for index in sorted(out):
            kind, words = out[index]
            if text in words:
                if said:
                    out[index] = (kind, words.replace(text, short_text))
                said = True
    return out


def _generic(spec: Exercise, r: Result) -> tuple[str, str]:
    """The shape, NaN or the rule, when no mistake fits."""
    shape = run_checker(lambda: _shape_words(r.expected, r.got), None)
    if shape:
        return "shape", shape
    nan = run_checker(lambda: _nan_words(r.args, r.expected, r.got), None)
    if nan:
        return "nan", _legal_nan(spec, nan)
    rule = run_checker(lambda: spec.rule(r.args, r.expected, r.got), "")
    return "value", rule


def _said_constant(spec: Exercise, r: Result, words: str) -> str:
    """A constant's words after the case's numbers; alone where the exercise's own
    composition follows them with the rule's example (``covers``, ``robust_fill``: "For
    example, … the top-left rule covers it")."""
    return words if spec.compose is not None else _say(spec, r, words)


def _say(spec: Exercise, r: Result, words: str) -> str:
    fallback = f"yours is {short(r.got)}, expected {short(r.expected)}"
    head = run_checker(lambda: spec.explain(r.args, r.expected, r.got), fallback)
    return (spec.compose or compose)(head, words)
