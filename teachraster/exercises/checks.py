"""``names()`` and ``check(name, fn, budget=10.0)``: the exercises in course order, and the check.

Every exercise is an :class:`~.exercise.Exercise` (its cases, its answer's reading, its
mistakes), checked by the same steps (:func:`.value_checks.check_exercise`). A new exercise is
one more entry in :data:`EXERCISES`.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from dataclasses import replace
from functools import cache

from . import output, tries
from .exercise import Exercise
from .report import Report, issue
from .running import PER_PIXEL, SKIPPED, effective_budget, nested
from .running import budget as time_budget
from .tries import apply_hints
from .value_checks import check_exercise


def _registry() -> dict[str, Callable[[], Exercise]]:
    """Each exercise's name, in course order, and how to build its description."""
    from . import blending, later, lines, reasoning_tasks
    from . import coverage_checks as cc
    from . import depth_clipping as dc
    from . import edges_spans as es
    from . import interpolation as ip

    return {
        "edge_function": lambda: es.EDGE_FUNCTION,
        "covers": cc.covers_exercise,
        "fill": cc.fill_exercise,
        "split_point": lambda: es.SPLIT_POINT,
        "barycentric": lambda: ip.BARYCENTRIC,
        "perspective": lambda: ip.PERSPECTIVE,
        "depth_test": lambda: dc.DEPTH_TEST,
        "clip_near": lambda: dc.CLIP_NEAR,
        **later.EXERCISES,  # 05–08: depth precision, antialiasing, texture filtering, tiles
        "line_pixels": lambda: lines.LINE_PIXELS,  # 09 (lessons 12a, 12b): lines and blending
        "over": lambda: blending.OVER_EXERCISE,
        "over_to_premultiplied": lambda: blending.FROM_STRAIGHT_EXERCISE,
        "over_premultiplied": lambda: blending.PREMULTIPLIED_EXERCISE,
        "over_straight": lambda: blending.STRAIGHT_EXERCISE,  # 9.2a since r11 (09-A)
        "atop_premultiplied": lambda: blending.ATOP_EXERCISE,  # 9.2b since r20 (D-1)
        **reasoning_tasks.EXERCISES,  # issue 30: reasoning tasks, lessons 07-12, broken frames
    }


@cache
def exercise(name: str) -> Exercise:
    """The description of exercise ``name`` (built once)."""
    return _registry()[name]()


def names() -> list[str]:
    """The exercises, in course order.

    >>> names()[:3]
    ['edge_function', 'covers', 'fill']
    """
    return list(_registry())


def _answer(report: Report) -> str:
    """A fingerprint of the student's answer: what it returned on the failing fixed cases (the
    cases drawn for each check differ from run to run, so they are left out)."""
    kept = [f"{f.case}={f.got!r}" for f in report.failures if "drawn for this check" not in f.case]
    return "\n".join(kept[:40])


def _hinted(report: Report, hints, name: str, note: str | None) -> Report:
    """On the first failing check of task ``name`` whose words would give the answer away,
    each of ``hints``' texts as its hint, and a note that the next failing check says more
    (:attr:`~.exercise.Exercise.hints`; a check that fails otherwise, a TypeError, is not
    counted)."""
    telling = any(tries.tells(text, f.explanation) for f in report.failures for text, _ in hints)
    if not telling or not tries.hinted_check(name, _answer(report)):
        return report if note is None else replace(report, tries=note)
    failures = [replace(f, explanation=apply_hints(f.explanation, hints)) for f in report.failures]
    more = tries.HINT_ONLY
    return replace(report, failures=failures, tries=more if note is None else f"{note}. {more}")


def check(name: str, fn: Callable, *, budget: float = 10.0) -> Report:
    """Run exercise ``name``'s cases on the student's ``fn`` and explain every failure.

    Never raises and never hangs because of ``fn``: its exceptions (``SystemExit`` included)
    become failures; ``NotImplementedError`` on every case marks the report "not implemented
    yet". ``budget`` is the CPU time the student's code may take in all (raised to the
    environment variable ``TEACHRASTER_CHECK_BUDGET`` where a lecturer sets it higher); a case
    may take a fifth of it, and the check stops at the first case that runs past its limit (an
    endless loop is reported after 2 s of CPU of the default 10). What the function prints is
    kept aside and shown, capped, after the report. An exercise with
    :attr:`~.exercise.Exercise.tries` (exercise 11) counts the failing checks of each task
    and, past that many, a failing check waits before it answers (:mod:`.tries`; never a
    passing one, never inside another check).
    """
    if not isinstance(name, str) or name not in names():
        raise ValueError(f"name must be one of {names()}, got {name!r}")
    if not callable(fn):
        raise TypeError(f"fn must be a function, got {type(fn).__name__}")
    seconds = effective_budget(budget)
    spec = exercise(name)
    slow = PER_PIXEL if spec.slow is None else spec.slow  # the time-out words' question
    with time_budget(seconds, slow=slow) as b, output.captured() as printed:
        report = check_exercise(spec, fn)
    # past the failing checks allowed, a failing check waits before it answers (outside the
    # budget); a passing one never does (r22 D3: after 27 failing checks a right answer
    # waited 2.1 s, and the notebook says a right cause never waits)
    if not nested() and not report.passed:
        tries.wait(name, spec.tries)
    # the stub not written yet is no try
    note = None if report.not_implemented else tries.counted(name, spec.tries, report.passed)
    if not report.not_implemented and not nested():  # r14 11-4: a wait per wrong cause, too
        named = {f.got[0] for f in report.failures if f.kind == "cause" and f.got}
        causes = tries.wrong_causes(name, spec.tries, named, report.passed, spec.free_causes)
        note = causes if note is None else (note if causes is None else f"{note}. {causes}")
    if spec.hints and not report.passed and not report.not_implemented and not nested():
        report = _hinted(report, spec.hints, name, note)
    elif note is not None:
        report = replace(report, tries=note)
    if b.stopped is not None and report.stopped is None:  # a later step ran out of time
        kept = [f for f in report.failures if f.explanation != SKIPPED]
        n_run = report.n_cases - (len(report.failures) - len(kept))
        report = replace(report, failures=kept, stopped=b.stopped, n_run=n_run)
    if printed.lines or printed.warned:
        report = replace(report, printed=printed.summary())
        printed.replay(sys.stdout)
    return issue(report)
