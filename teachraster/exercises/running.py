"""Call a student's function safely: within a time budget, its exceptions become messages.

A check must never crash on a student's bug, and an endless loop must not hang the notebook.
:func:`budget` opens the time budget of one check (10 s unless told); :func:`run_case` runs one
case within a limit derived from what remains (at most a fifth of the budget: 2 s of 10), so
that a loop is reported after 2 s, not after the whole budget. A case past its limit is stopped
by :class:`CaseInterrupt`, a ``BaseException`` (as ``KeyboardInterrupt`` is) so that
``except Exception`` cannot swallow it; :mod:`.interrupt` re-fires it until the case unwinds.
The checker's own comparison and explanation run through :func:`run_checker`, inside the same
budget. A ``SystemExit`` (``exit()`` in the student's code) is a failure like any other;
``KeyboardInterrupt`` (the notebook's stop button) still stops everything.
"""

from __future__ import annotations

import math
import numbers
import sys
import threading
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .interrupt import Alarm, CaseInterrupt

__all__ = ["CaseInterrupt", "Outcome", "WrongAnswerType", "budget", "run_case", "run_checker"]

#: Seconds of a check's budget when ``check`` is not told otherwise.
DEFAULT_BUDGET = 10.0
#: The share of the budget one case may take: 2 s of the default 10 s.
CASE_SHARE = 0.2
#: Seconds one case may take under the default budget (kept for callers that pass a limit).
CASE_LIMIT = DEFAULT_BUDGET * CASE_SHARE
#: Seconds the checker's own explanations may take after the budget (once, for all of them).
GRACE = 0.5
#: Explanation of a case that did not run because the check had stopped.
SKIPPED = "not run: the check stopped at an earlier case"


class WrongAnswerType(TypeError):
    """The function returned something of the wrong type or shape (the message says what)."""


@dataclass(frozen=True)
class Outcome:
    """What running one case gave: a value, or why there is none.

    ``error`` is the explanation when there is no value (the student's exception, the time
    limit, a wrong type); ``not_implemented`` is True when the function raised
    ``NotImplementedError``; ``kind`` names the reason in one word ("raised", "timeout",
    "budget", "exit", "type", "none", "skipped", "not implemented"; "" for a value).
    """

    value: Any = None
    error: str | None = None
    not_implemented: bool = False
    kind: str = ""

    @property
    def ok(self) -> bool:
        return self.error is None and not self.not_implemented


@dataclass
class Budget:
    """The time one check may take, and why it stopped early (``stopped``), if it did."""

    seconds: float
    start: float = field(default_factory=time.perf_counter)
    stopped: str | None = None
    share: float = CASE_SHARE

    def remaining(self) -> float:
        return self.seconds - (time.perf_counter() - self.start)

    def case_limit(self) -> float:
        return min(self.remaining(), self.seconds * self.share)


_local = threading.local()


def current() -> Budget:
    """The budget of the check running in this thread.

    Outside a check (a comparison drawn later, a caller of :func:`run_case`), one call may
    take the whole default budget.
    """
    stack = getattr(_local, "stack", None)
    return stack[-1] if stack else Budget(DEFAULT_BUDGET, share=1.0)


class budget:  # noqa: N801 - used as a context manager, named like one
    """``with budget(seconds) as b:`` every :func:`run_case` inside shares ``seconds``.

    >>> with budget(5.0) as b:
    ...     run_case(lambda: 2).value, b.stopped
    (2, None)
    """

    def __init__(self, seconds: float = DEFAULT_BUDGET):
        self.budget = Budget(check_seconds(seconds))

    def __enter__(self) -> Budget:
        _local.stack = getattr(_local, "stack", []) + [self.budget]
        return self.budget

    def __exit__(self, *exc) -> None:
        _local.stack = _local.stack[:-1]


def check_seconds(seconds, name: str = "budget") -> float:
    """A positive, finite number of seconds, or a ``TypeError``/``ValueError`` naming it."""
    if isinstance(seconds, bool) or not isinstance(seconds, numbers.Real):
        raise TypeError(f"{name} must be a number of seconds, got {type(seconds).__name__}")
    if not (math.isfinite(seconds) and seconds > 0):
        raise ValueError(f"{name} must be a positive, finite number of seconds, got {seconds!r}")
    return float(seconds)


def last_line(exc: BaseException) -> str:
    """The exception as Python's last traceback line says it: ``ValueError: ...``."""
    return traceback.format_exception_only(type(exc), exc)[-1].strip()


def seconds_words(s: float) -> str:
    return f"{s:.2g} s" if s < 1 else f"{s:.3g} s"


def _timeout(limit: float, b: Budget, case: str | None) -> Outcome:
    where = f" on case {case}" if case else ""
    if b.remaining() > 0.05 and limit < b.seconds:
        text = (
            f"your function did not return within {seconds_words(limit)}{where}: an endless loop?"
        )
        kind = "timeout"
    else:
        text = (
            f"the check's budget of {seconds_words(b.seconds)} ran out{where}: is your function "
            "very slow, or an endless loop? (check(..., budget=30) gives it more time)"
        )
        kind = "budget"
    b.stopped = f"{text} (the check stopped there)"
    return Outcome(error=text, kind=kind)


def run_case(body: Callable[[], Any], limit: float | None = None, case: str | None = None):
    """Run ``body`` (which calls the student's function) and capture what happens.

    ``limit`` caps the case's seconds (default: the current budget's per-case limit);
    ``case`` (e.g. "3 of 30") is quoted when the case runs out of time. Once a case has run
    out of time the check has stopped, and later cases are not run.

    >>> run_case(lambda: 1 / 0).error
    'your function raised ZeroDivisionError: division by zero'
    >>> run_case(lambda: 2).value
    2
    """
    b = current()
    if b.stopped:
        return Outcome(error=SKIPPED, kind="skipped")
    limit = b.case_limit() if limit is None else min(limit, b.remaining())
    if limit <= 0:
        return _timeout(0.0, b, case)
    alarm = Alarm(limit, sys._getframe())
    try:
        try:
            alarm.start()
            value = body()
        finally:
            alarm.active = False  # first: an interrupt already on its way is now ignored
            alarm.stop()
    except CaseInterrupt:
        alarm.stop()
        return _timeout(limit, b, case)
    except KeyboardInterrupt:
        raise  # the notebook's stop button stops the check too
    except BaseException as exc:  # a student's bug of any kind is a failed case, never a crash
        alarm.stop()
        if alarm.fired:
            return _timeout(limit, b, case)
        return describe_exception(exc)
    if alarm.fired or alarm.overran():  # it caught the interrupt, or nothing could interrupt it
        return _timeout(limit, b, case)
    return Outcome(value=value)


def describe_exception(exc: BaseException) -> Outcome:
    """The outcome of a case whose function raised ``exc`` (never KeyboardInterrupt)."""
    if isinstance(exc, NotImplementedError):
        text = f"your function raised {last_line(exc)} on this case"
        return Outcome(error=text, not_implemented=True, kind="not implemented")
    if isinstance(exc, SystemExit):
        text = (
            f"your function called exit() ({last_line(exc)}): a function gives its answer with "
            "`return`; exit() would stop the whole notebook"
        )
        return Outcome(error=text, kind="exit")
    if isinstance(exc, WrongAnswerType):
        kind = "none" if "returned None" in str(exc) else "type"
        return Outcome(error=f"your function {exc}", kind=kind)
    return Outcome(error=f"your function raised {last_line(exc)}", kind="raised")


def run_checker(body: Callable[[], Any], fallback: Any) -> Any:
    """Run the checker's own comparison or explanation within the budget (plus GRACE s).

    Returns ``fallback`` when it runs out of time or fails (a huge or strange answer).
    """
    b = current()
    left = b.remaining() + GRACE  # the explanations' grace is counted once, not per call
    if left <= 0:
        return fallback
    alarm = Alarm(left, sys._getframe())
    try:
        try:
            alarm.start()
            with np.errstate(all="ignore"):  # inf and huge answers: explained, not warned about
                return body()
        finally:
            alarm.active = False
            alarm.stop()
    except KeyboardInterrupt:
        raise
    except BaseException:  # the student's value may misbehave (its __eq__, its __float__...)
        alarm.stop()
        return fallback
