"""Call a student's function safely: exceptions become messages, slow cases are stopped.

A check must never crash on a student's bug, and a student's infinite loop must not hang the
notebook: each case runs under a time limit (``SIGALRM`` where the platform has it and the
call comes from the main thread, which is where a Jupyter kernel runs cells; elsewhere the
time is measured afterwards and an overrun reported all the same).
"""

from __future__ import annotations

import signal
import threading
import time
import traceback
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any

#: Seconds one case may take (a case may call the function a few hundred times).
CASE_LIMIT = 10.0


class CaseTimeout(Exception):
    """A case ran past its time limit."""


class WrongAnswerType(TypeError):
    """The function returned something of the wrong type or shape (the message says what)."""


@dataclass(frozen=True)
class Outcome:
    """What running one case gave: a value, or why there is none.

    ``error`` is the last line of the student's exception (or the time-limit message);
    ``not_implemented`` is True when the function raised ``NotImplementedError``.
    """

    value: Any = None
    error: str | None = None
    not_implemented: bool = False

    @property
    def ok(self) -> bool:
        return self.error is None and not self.not_implemented


@contextmanager
def time_limit(seconds: float):
    """Raise :class:`CaseTimeout` inside the block once ``seconds`` have passed."""
    usable = hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
    start = time.perf_counter()
    if not usable:
        yield
        if time.perf_counter() - start > seconds:
            raise CaseTimeout(f"took longer than the limit of {seconds:g} s")
        return

    def stop(signum, frame):
        raise CaseTimeout(f"took longer than the limit of {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, stop)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def last_line(exc: BaseException) -> str:
    """The exception as Python's last traceback line says it: ``ValueError: ...``."""
    return traceback.format_exception_only(type(exc), exc)[-1].strip()


def run_case(body: Callable[[], Any], limit: float | None = None) -> Outcome:
    """Run ``body`` (which calls the student's function) and capture what happens.

    >>> run_case(lambda: 1 / 0).error
    'your function raised ZeroDivisionError: division by zero'
    >>> run_case(lambda: 2).value
    2
    """
    limit = CASE_LIMIT if limit is None else limit
    try:
        with time_limit(limit):
            return Outcome(value=body())
    except NotImplementedError:
        return Outcome(not_implemented=True)
    except CaseTimeout as exc:
        return Outcome(error=f"your function was stopped: it {exc}")
    except WrongAnswerType as exc:
        return Outcome(error=f"your function {exc}")
    except Exception as exc:  # a student's bug of any kind is a failed case, never a crash
        return Outcome(error=f"your function raised {last_line(exc)}")
