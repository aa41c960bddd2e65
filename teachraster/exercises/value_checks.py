"""Check an exercise whose answer is a value (a number, a few numbers, a bool, a polygon).

Three steps, all inside the check's time budget: run every case (the student's function and the
conversion of its answer, :func:`~.running.run_case`), stopping at the first case past its
limit; compare each answer with the expected one; explain each failure, knowing the answers to
all cases (a pattern such as ``abs(E)`` shows only across cases). Comparisons and explanations
run through :func:`~.running.run_checker`: a strange answer costs a plain explanation, never
the budget.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .answers import low_precision, short
from .report import Failure, Report
from .running import SKIPPED, current, run_case, run_checker
from .scalars import num

#: Outcome kinds after which the check stops (the time is spent).
STOPS = ("timeout", "budget")


@dataclass(frozen=True)
class ValueExercise:
    """How to check one value exercise.

    ``cases()`` gives (label, args, expected); ``convert`` reads the student's answer (raising
    :class:`~.running.WrongAnswerType`); ``same(got, expected)`` compares;
    ``explain(args, expected, got, **pattern)`` returns the explanation, or (kind, explanation);
    ``draw(ax, case, got)`` draws a case; ``pattern(results)`` (optional) looks at every
    (args, expected, got) and returns keyword arguments for ``explain``.
    """

    cases: Callable
    convert: Callable
    same: Callable
    explain: Callable
    draw: Callable
    pattern: Callable | None = None


def run_all(fn, cases, convert) -> list:
    """(case, outcome) of each case run, in order, until the check stops."""
    ran = []
    for k, (label, args, expected) in enumerate(cases):
        copies = tuple(np.array(a, copy=True) if isinstance(a, np.ndarray) else a for a in args)
        outcome = run_case(
            lambda copies=copies: convert(fn(*copies)), case=f"{k + 1} of {len(cases)}"
        )
        if outcome.error == SKIPPED:
            break
        ran.append(((label, args, expected), outcome))
        if outcome.kind in STOPS:
            break
    return ran


def all_not_implemented(ran) -> bool:
    """The untouched stub: every case that ran raised NotImplementedError."""
    return bool(ran) and all(outcome.not_implemented for _, outcome in ran)


def check_value_exercise(name: str, fn, spec: ValueExercise) -> Report:
    """Run, compare and explain (see the module docstring); the report of exercise ``name``."""
    cases = spec.cases()
    ran = run_all(fn, cases, spec.convert)
    first = _drawer(spec.draw, cases[0], None)
    if all_not_implemented(ran):
        return Report(name, [], len(cases), True, first)
    answered = [(case, o.value) for case, o in ran if o.error is None]
    same = [run_checker(lambda c=c, g=got: bool(spec.same(g, c[2])), False) for c, got in answered]
    wrong = [(c, got) for (c, got), ok in zip(answered, same) if not ok]
    results = [(c[1], c[2], got) for c, got in answered]
    pattern = run_checker(lambda: spec.pattern(results), {}) if spec.pattern else {}
    explained = {id(c): _failure(spec, c, got, pattern) for c, got in wrong}
    failures = []
    for case, outcome in ran:
        if outcome.error is not None:
            draw = _drawer(spec.draw, case, None)
            failures.append(Failure(case[0], outcome.error, case[2], None, draw, outcome.kind))
        elif id(case) in explained:
            failures.append(explained[id(case)])
    example = _drawer(spec.draw, cases[0], cases[0][2])
    return Report(name, failures, len(cases), False, example, current().stopped, len(ran))


def _failure(spec: ValueExercise, case, got, pattern: dict) -> Failure:
    label, args, expected = case
    fallback = ("value", f"yours is {short(got)}, expected {short(expected)}")
    said = run_checker(lambda: spec.explain(args, expected, got, **pattern), fallback)
    kind, text = said if isinstance(said, tuple) else ("value", said)
    text = run_checker(lambda: float32_note(text, got, expected), text)
    if "float32" in text and kind == "value":
        kind = "float32"
    return Failure(label, text, expected, got, _drawer(spec.draw, case, got), kind)


def float32_note(text: str, got, expected) -> str:
    """Add that float32 is the cause, where the answer is a float32 or off by its rounding."""
    if "float32" in text or "float16" in text:
        return text
    dtype = low_precision(got)
    if dtype is not None:
        digits = 7 if dtype == "float32" else 3
        return _then(
            text,
            f"Your answer is a {dtype} (about {digits} significant digits): compute in float64 "
            "and return that",
        )
    g, e = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if g.shape != e.shape or not (np.isfinite(g).all() and np.isfinite(e).all()):
        return text
    error = float(np.max(np.abs(g - e) / np.maximum(1.0, np.abs(e)), initial=0.0))
    if 0 < error < 1e-5:
        return _then(
            text,
            f"The difference ({num(error)} relative) is about float32's rounding (6e-8 relative "
            "per operation): did you compute in float32? Use float64",
        )
    return text


def _then(text: str, sentence: str) -> str:
    """``text`` followed by another sentence."""
    text = text.rstrip()
    return f"{text}{'' if text.endswith('.') else '.'} {sentence}"


def _drawer(draw, case, got):
    def drawing(ax):
        return draw(ax, case, got)

    return drawing
