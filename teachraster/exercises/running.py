"""Call a student's function safely: within a CPU-time budget, its exceptions become messages.

A check must never crash on a student's bug, and an endless loop must not hang the notebook.
:func:`budget` opens the time budget of one check: ``seconds`` of **CPU time of the student's
code** (10 unless told; a lecturer raises it for a whole class with the environment variable
``TEACHRASTER_CHECK_BUDGET``, see :func:`check_seconds`). :func:`run_case` runs one case
within a limit derived from what remains (at most a fifth of the budget: 2 s of CPU of 10), so
that a loop is reported after 2 s, not after the whole budget; a case that waits without
computing, and a whole check on a machine too busy to give it CPU, are bounded in wall-clock
time too (:mod:`.alarm`). A case past its limit is stopped by :class:`CaseInterrupt`, a
``BaseException`` (as ``KeyboardInterrupt`` is), so that ``except Exception`` cannot swallow it
(:mod:`.interrupt`). Outside the main thread a case runs in a thread of its own, which the
check abandons if it cannot be stopped (a ``time.sleep`` there cannot be cut short), so that
the check still returns in time; otherwise it reports what it reports in the main thread.

The checker's own comparisons and explanations run through :func:`run_checker`, with limits of
their own (they do not eat the student's budget). A ``SystemExit`` (``exit()`` in the student's
code) is a failure like any other; ``KeyboardInterrupt`` (the notebook's stop button) still
stops everything.
"""

from __future__ import annotations

import functools
import math
import numbers
import os
import sys
import threading
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import output
from .alarm import CASE_WALL_FACTOR, LONGEST, WAIT_FACTOR, Alarm
from .interrupt import CaseInterrupt, busy

__all__ = [
    "CaseInterrupt", "Outcome", "WrongAnswerType", "budget", "one_call", "run_case", "run_checker",
]  # fmt: skip

#: CPU seconds of a check's budget when ``check`` is not told otherwise.
DEFAULT_BUDGET = 10.0
#: The environment variable that raises every check's budget (a lecturer's, for a class).
BUDGET_VARIABLE = "TEACHRASTER_CHECK_BUDGET"
#: The share of the budget one case may take: 2 s of CPU of the default 10 s.
CASE_SHARE = 0.2
#: Seconds one case may take under the default budget (kept for callers that pass a limit).
CASE_LIMIT = DEFAULT_BUDGET * CASE_SHARE
#: Wall-clock seconds a whole check may take, per CPU second of its budget (a busy machine).
WALL_FACTOR = 10.0
#: CPU seconds one comparison or explanation of the checker may take, and all of them together.
CHECKER_CALL, CHECKER_TOTAL = 2.0, 10.0
#: The call that raises a check's budget, as the student writes it (the capstone names its own).
RAISE_CALL = "check(..., budget={seconds:g})"
#: What the time-out words ask of a slow function; an exercise whose function is called once
#: per point says its own (:attr:`.exercise.Exercise.slow`, r175 B7).
PER_PIXEL = " (a Python call per pixel?)"
#: Seconds a case that could not be stopped is given to unwind before the check abandons it.
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
    #: Where it raised in the student's own code (:func:`student_line`; "" where it did not
    #: raise, or not there); an exercise with ``call_words`` says it (r248 S1).
    where: str = ""

    @property
    def ok(self) -> bool:
        return self.error is None and not self.not_implemented


@dataclass
class Budget:
    """The CPU time one check's student code may take, and why it stopped early, if it did."""

    seconds: float
    start: float = field(default_factory=time.perf_counter)
    stopped: str | None = None
    share: float = CASE_SHARE
    used: float = 0.0  # CPU seconds of the student's code so far
    checker: float = 0.0  # CPU seconds of the checker's own explanations so far
    #: How the student raises this budget, in the call they made (:data:`RAISE_CALL`; r174
    #: 12-2: the capstone's report named ``check``, which its notebook never calls).
    raise_call: str = RAISE_CALL
    #: What the time-out words ask of a slow function (:data:`PER_PIXEL`, or the exercise's own)
    slow: str = PER_PIXEL

    def more_time(self) -> str:
        """The student's call with a larger budget: 30 s, or three times one already larger."""
        return self.raise_call.format(seconds=max(30.0, 3 * self.seconds))

    def remaining(self) -> float:
        return self.seconds - self.used

    def case_limit(self) -> float:
        return min(self.remaining(), self.seconds * self.share)

    def wall_left(self) -> float:
        return wall_limit(self.seconds) - (time.perf_counter() - self.start)


def wall_limit(seconds: float) -> float:
    """Wall-clock seconds a whole check with ``seconds`` of CPU budget may take: a machine too
    busy to give it that CPU (the one place for it; the capstone's notebook quotes it)."""
    return min(WALL_FACTOR * seconds, LONGEST)


_local = threading.local()


def current() -> Budget:
    """The budget of the check running in this thread.

    Outside a check (a comparison drawn later, a caller of :func:`run_case`), one call may
    take the whole default budget.
    """
    stack = getattr(_local, "stack", None)
    return stack[-1] if stack else Budget(DEFAULT_BUDGET, share=1.0)


def nested() -> bool:
    """Is a check running in this thread already (this one is started inside it)?"""
    return bool(getattr(_local, "stack", None))


class budget:  # noqa: N801 - used as a context manager, named like one
    """``with budget(seconds) as b:`` every :func:`run_case` inside shares ``seconds`` of CPU.

    >>> with budget(5.0) as b:
    ...     run_case(lambda: 2).value, b.stopped
    (2, None)
    """

    def __init__(self, seconds: float = DEFAULT_BUDGET, share: float = CASE_SHARE,
                 raise_call: str = RAISE_CALL, slow: str = PER_PIXEL):  # fmt: skip
        self.budget = Budget(check_seconds(seconds), share=share, raise_call=raise_call,
                             slow=slow)  # fmt: skip

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


def class_budget() -> float | None:
    """The lecturer's minimum budget from ``TEACHRASTER_CHECK_BUDGET``, or None when unset.

    A value that is not a positive number of seconds is a ``ValueError`` naming the variable:
    a typo must not silently leave the limits where they were.
    """
    text = os.environ.get(BUDGET_VARIABLE, "").strip()
    if not text:
        return None
    try:
        seconds = float(text)
    except ValueError:
        seconds = float("nan")
    if not (math.isfinite(seconds) and seconds > 0):
        raise ValueError(
            f"the environment variable {BUDGET_VARIABLE} must be a positive number of seconds "
            f"(of CPU, for each check), got {text!r}"
        )
    return seconds


def effective_budget(seconds) -> float:
    """``seconds`` checked, raised to the lecturer's ``TEACHRASTER_CHECK_BUDGET`` if lower."""
    seconds = check_seconds(seconds)
    floor = class_budget()
    return seconds if floor is None else max(seconds, floor)


def last_line(exc: BaseException) -> str:
    """The exception as Python's last traceback line says it: ``ValueError: ...``."""
    return traceback.format_exception_only(type(exc), exc)[-1].strip()


@functools.cache
def _library_dirs() -> tuple[str, ...]:
    """The directories of code that is not the student's: this package, Python's own library
    and the installed packages (numpy's own raises land there); found once per process
    (sysconfig's expansion cost a third of describing an exception)."""
    import sysconfig

    here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # teachraster/
    paths = sysconfig.get_paths()
    found = {here, *(paths.get(k) for k in ("stdlib", "platstdlib", "purelib", "platlib"))}
    return tuple(os.path.abspath(p) + os.sep for p in found if p)


def student_line(exc: BaseException) -> str:
    """The traceback's last line inside the student's own code, as "line 9, in hiz_rejects:
    `r = buffer[8, 0]`" (a notebook cell's lines count from the cell's first); "" where no
    frame of it is the student's (r248 S1: "raised IndexError" named no line)."""
    library = _library_dirs()
    frames = [f for f in traceback.extract_tb(exc.__traceback__)
              if not os.path.abspath(f.filename).startswith(library)]  # fmt: skip
    if not frames:
        return ""
    f = frames[-1]
    code = f" `{f.line.strip()}`" if f.line and f.line.strip() else ""
    return f"line {f.lineno}, in {f.name}:{code}" if code else f"line {f.lineno}, in {f.name}"


def seconds_words(s: float) -> str:
    return f"{s:.2g} s" if s < 1 else f"{s:.3g} s"


def _timeout(alarm: Alarm | None, b: Budget, case: str | None, stuck: bool = False) -> Outcome:
    """The outcome of a case stopped by its limits (``alarm``) or by the budget (None)."""
    # "on the picture", not "on case the picture" (r293 S2)
    where = "" if not case else f" on {case}" if case.startswith("the ") else f" on case {case}"
    why = "budget" if alarm is None else (alarm.why or alarm.due() or "cpu")
    if why == "cpu" and alarm.seconds < b.seconds * b.share * (1 - 1e-9):
        why = "budget"  # the case's limit was what remained of the budget
    if why == "budget":
        text = (
            f"the check's budget of {seconds_words(b.seconds)} of CPU ran out{where}: your "
            f"function is far slower than needed{b.slow}. "
            f"{b.more_time()} gives it more time; a lecturer raises it for a class with "
            f"the environment variable {BUDGET_VARIABLE}"
        )
        kind = "budget"
    elif why == "call":  # one of the calls a case makes (r163 12-8: the capstone's render)
        text = (
            f"one call of your function did not finish within {seconds_words(alarm.call)} of "
            f"CPU{where} (the most one call may take of the check's {seconds_words(b.seconds)}): "
            f"an endless loop, or far slower than needed{b.slow}"
        )
        kind = "timeout"
    elif why == "cpu":
        text = (
            f"your function did not finish within {seconds_words(alarm.seconds)} of CPU{where}: "
            f"an endless loop, or far slower than needed{b.slow}"
        )
        kind = "timeout"
    elif why == "wait":
        text = (
            f"your function did not finish within {seconds_words(alarm.wait)}{where}, and "
            f"computed for only {seconds_words(alarm.cpu())} of it: it waits (time.sleep, "
            "input(), a lock, a thread it joins?)"
        )
        kind = "timeout"
    else:
        text = _too_busy(alarm, b, where)
        kind = "budget"
    if stuck:
        text += (
            ". It could not be stopped and still runs in the background (a blocking call, or "
            "code that catches every exception): restart the kernel if the notebook slows down"
        )
    b.stopped = f"{text} (the check stopped there)"
    return Outcome(error=text, kind=kind)


def _too_busy(alarm: Alarm, b: Budget, where: str) -> str:
    """The words for a case stopped by a wall-clock cap: the case's own (``CASE_WALL_FACTOR``
    times its CPU limit) or what was left of the whole check's (``WALL_FACTOR`` times its budget). r122
    D3-2: "the check ran for 0.088 s of wall-clock time" quoted the case's share of what was
    left as the whole check's time. A function that computed for more than its CPU limit by
    then is slow, whatever the load (r174 12-2: "too busy" beside 11.2 s of a 10 s budget)."""
    if alarm.cap < CASE_WALL_FACTOR * alarm.seconds * (1 - 1e-9):  # the check's wall-clock limit
        # b.used holds this case's CPU already (run_case adds it before it asks for the words;
        # r199 C1: adding alarm.cpu() again told a correct function it computed for 14 s of
        # a 10-s budget when the whole process had used 7.1 s)
        wall, cpu, limit = time.perf_counter() - b.start, b.used, b.seconds
        ran = (f"the check ran for {seconds_words(wall)} of wall-clock time (its limit: "
               f"{seconds_words(wall_limit(b.seconds))}, {WALL_FACTOR:g} times "
               f"its budget of CPU){where}, and your function computed for "
               f"{seconds_words(cpu)} of it")  # fmt: skip
        whose = "the check's budget"
    else:
        cpu, limit = alarm.cpu(), alarm.seconds
        ran = (f"the case ran for {seconds_words(alarm.wall())} of wall-clock time{where}, "
               f"and your function computed for {seconds_words(cpu)} of it")  # fmt: skip
        whose = "the case's limit"
    if cpu >= limit:
        return (f"{ran}, more than {whose} of {seconds_words(limit)} of CPU: your function is "
                f"far slower than needed (a Python call per pixel?); {b.more_time()} gives it "
                "more time")  # fmt: skip
    return f"{ran}: the machine is too busy; try again later (or raise the budget: {b.more_time()})"


def run_case(
    body: Callable[[], Any], limit: float | None = None, case: str | None = None,
    call: float | None = None,
):  # fmt: skip
    """Run ``body`` (which calls the student's function) and capture what happens.

    ``limit`` caps the case's CPU seconds (default: the current budget's per-case limit);
    ``case`` (e.g. "3 of 30") is quoted when the case runs out of time; ``call`` caps each
    call of the student's function that ``body`` marks (:func:`one_call`), for a case that
    calls it many times (the capstone's render: an endless loop in one call stops there, not
    at the whole render's limit). Once a case has run out of time the check has stopped, and
    later cases are not run.

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
        return _timeout(None, b, case)
    wall = max(min(CASE_WALL_FACTOR * limit, b.wall_left()), 0.0)
    alarm = Alarm(limit, None, WAIT_FACTOR * limit, wall, call)
    in_place = threading.current_thread() is threading.main_thread() or getattr(busy, "on", False)
    if in_place:
        outcome, stuck = _run_here(body, alarm), False
    else:
        outcome, stuck = _run_in_thread(body, alarm)
    b.used += alarm.cpu()
    if outcome is None:  # past a limit
        return _timeout(alarm, b, case, stuck)
    return outcome


def one_call(fn, *args):
    """``fn(*args)``, one call of the student's function inside a case, under the case's
    per-call limit (``run_case(..., call=)``; none outside such a case). No ``try``: the
    interrupt passes this frame as it passes the student's (:func:`.interrupt.escapes`); a
    call that raises ends its case, and the next call begins the count afresh."""
    alarm = getattr(busy, "alarm", None)
    if alarm is None or alarm.call is None:
        return fn(*args)
    alarm.call_begins()
    value = fn(*args)
    alarm.call_ends()
    return value


def _guarded(alarm: Alarm, body) -> tuple[bool, Any]:
    """``(True, body())`` run under ``alarm`` in this thread, or ``(False, the exception)``.

    This frame is the guard: the interrupt unwinds to it. Off the main thread the interrupt is
    an asynchronous exception, which lands at the thread's next check for pending work, so one
    the watchdog sent just before the case ended may land in :meth:`Alarm.stop`, and one more
    that it sent as ``leaving`` was set (two at most: it sends none once it has seen
    ``leaving``, and none after ``stop`` has taken its lock, which then drops any still on its
    way). Each is caught here and ``stop`` called again, which finishes what it cut short:
    none reaches the caller, whatever thread this runs in. ``KeyboardInterrupt`` is raised.
    """
    alarm.guard = sys._getframe()
    try:
        try:
            alarm.start()
            return True, body()
        finally:
            alarm.active = False  # first: an interrupt already on its way is now ignored
            alarm.leaving = True  # and the watchdog sends no more (plain stores: nothing lands)
            try:
                alarm.stop()
            except CaseInterrupt:
                try:
                    alarm.stop()
                except CaseInterrupt:
                    alarm.stop()
    except KeyboardInterrupt:
        raise  # the notebook's stop button stops the check too
    except BaseException as exc:  # a student's bug of any kind is a failed case, never a crash
        return False, exc


def _run_here(body, alarm: Alarm) -> Outcome | None:
    """The outcome of ``body`` run in this thread under ``alarm``; None when past a limit."""
    ok, got = _guarded(alarm, body)
    if not ok:
        if alarm.fired or isinstance(got, CaseInterrupt):
            return None
        try:
            return describe_exception(got)
        finally:
            # one exception object raised on every case (``raise ERROR``, a test's shared
            # ValueError) keeps each raise's frames in its traceback: described, it starts the
            # next case empty (a traceback of 1,300 frames per case, quadratic, was 3/4 of a
            # check's CPU: 240 s of a 310-s profile, and every frame's arrays kept alive)
            got.__traceback__ = None
    if alarm.fired or alarm.overran():  # it caught the interrupt, or nothing could interrupt it
        return None
    return Outcome(value=got)


def _run_in_thread(body, alarm: Alarm) -> tuple[Outcome | None, bool]:
    """(outcome, abandoned) of ``body`` run in a thread of its own, waited for here.

    The thread is abandoned (left to end in the background) when it has not unwound
    ``GRACE`` s after its first interrupt: an asynchronous exception cannot cut a blocking
    call short, and code that catches everything in a recursion may never unwind.
    """
    box: dict = {}

    def target():
        box["outcome"] = _run_here(body, alarm)

    worker = threading.Thread(target=target, daemon=True, name="teachraster-check-case")
    capture = output.current()
    worker.start()
    if capture is not None:
        capture.adopt(worker.ident)
    begin = time.perf_counter()
    while worker.is_alive():
        worker.join(0.05)
        fired = alarm.fired_at
        late = fired is not None and time.perf_counter() - fired > GRACE
        never = alarm.mode == "measured" and time.perf_counter() - begin > alarm.cap + GRACE
        if worker.is_alive() and (late or never):
            alarm.active = False
            return None, True
    return box.get("outcome"), False


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
    if isinstance(exc, StopIteration):  # a bare "raised StopIteration" tells nothing (r23 D4)
        text = (
            "your function raised StopIteration: a next(...) found no item that met its "
            "condition (is the item you look for there, on this case's input?)"
        )
        return Outcome(error=text, kind="raised")
    if isinstance(exc, MemoryError):  # numpy's _ArrayMemoryError too (r73 08-4, 08-5)
        text = (
            "your function asked for more memory than the machine has "
            f"({str(exc) or 'MemoryError'}): an array with one element per pixel of this "
            "case (a scan of every pixel or centre)? A case this large is there because the "
            "answer needs no such scan: a few numbers per edge decide it at any size"
        )
        return Outcome(error=text, kind="memory")
    return Outcome(error=f"your function raised {last_line(exc)}", kind="raised",
                   where=student_line(exc))  # fmt: skip


def run_checker(body: Callable[[], Any], fallback: Any) -> Any:
    """Run the checker's own comparison or explanation within limits of its own.

    Each call may take ``CHECKER_CALL`` s of CPU and all of one check's together
    ``CHECKER_TOTAL`` s (the student's budget is not touched). Returns ``fallback`` when it
    runs out of time or fails (a huge or strange answer: its ``__eq__``, its ``__float__``...).
    """
    b = current()
    left = min(CHECKER_CALL, CHECKER_TOTAL - b.checker)
    if left <= 0:
        return fallback
    alarm = Alarm(left, None, WAIT_FACTOR * left, CASE_WALL_FACTOR * left)
    try:
        # inf and huge answers: explained, not warned about (outside the guard, whose callees
        # the interrupt must pass: a ``with`` there could swallow it, for all escapes() knows)
        with np.errstate(all="ignore"):
            ok, got = _guarded(alarm, body)
    finally:
        b.checker += alarm.cpu()
    return got if ok else fallback
