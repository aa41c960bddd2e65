"""A check off the main thread says what it says on the main thread (issue 30).

A lecturer's grading script, an nbgrader preprocessor, an asyncio executor or a widget callback
may run ``ex.check`` in a thread of its own: there a case is stopped by an asynchronous
exception from a watchdog (:mod:`teachraster.exercises.alarm`), not by ``SIGALRM``. The
interrupt that drains a pending one once escaped its ``try``, and every case of every check
off the main thread failed with "your function raised ..._Drained". Every check here is
bounded by a few seconds of CPU (the loops run under a 1 s budget, 0.2 s per case).
"""

from __future__ import annotations

import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest
from endless_loops import forever
from exercise_solutions import CORRECT
from student_variants import level_w_h_swapped
from test_checker_time import BUDGET, LOOP_WORDS, SLACK, timed_check

from teachraster import exercises as ex
from teachraster.exercises import running
from teachraster.exercises.interrupt import CaseInterrupt, drain_async

#: Words of the checker's internals that no report may show.
INTERNALS = ("_Drained", "Interrupt", "teachraster.exercises")


def in_thread(fn, *args):
    """``fn(*args)`` run in a ``threading.Thread``; what it returned."""
    out = {}

    def run():
        out["value"] = fn(*args)

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(60)
    assert not thread.is_alive()
    return out["value"]


def in_pool(fn, *args):
    """``fn(*args)`` run in a ``ThreadPoolExecutor``'s worker; what it returned."""
    with ThreadPoolExecutor(max_workers=2) as pool:
        return pool.submit(fn, *args).result(timeout=60)


RUNNERS = {"Thread": in_thread, "ThreadPoolExecutor": in_pool}


@pytest.mark.parametrize("where", RUNNERS)
@pytest.mark.parametrize("name", ["mip_level", "depth_test"])
def test_a_correct_solution_passes_off_the_main_thread_with_the_same_report(name, where):
    here = ex.check(name, CORRECT[name])
    there = RUNNERS[where](ex.check, name, CORRECT[name])
    assert here.passed, str(here)
    assert there.passed, str(there)
    assert str(there) == str(here)


@pytest.mark.parametrize("where", RUNNERS)
def test_a_wrong_solution_is_explained_off_the_main_thread_as_on_it(where):
    here = ex.check("mip_level", level_w_h_swapped)
    there = RUNNERS[where](ex.check, "mip_level", level_w_h_swapped)
    assert not here.passed and "scaled u by H and v by W" in here.failures[0].explanation
    assert there.failures[0].explanation == here.failures[0].explanation  # (random cases follow)
    assert {f.kind for f in there.failures} == {f.kind for f in here.failures}, str(there)
    assert not any(word in str(there) for word in INTERNALS), str(there)


@pytest.mark.parametrize("where", RUNNERS)
def test_an_endless_loop_off_the_main_thread_ends_within_the_budget(where):
    report, took = RUNNERS[where](timed_check, "depth_test", forever)
    assert took.within(BUDGET + SLACK)
    assert report.failures[0].kind == "timeout"
    assert report.failures[0].explanation == LOOP_WORDS
    assert "the check stopped after case 1 of 30" in str(report)


def test_two_checks_in_two_threads_at_once_are_both_right():
    """Each thread has its own alarm and watchdog: one check's interrupt, or its drain, never
    lands in the other; an endless loop beside a correct solution stops that loop alone."""
    expected = {name: str(ex.check(name, CORRECT[name])) for name in ("mip_level", "depth_test")}
    start = threading.Barrier(2)

    def check(name, fn):
        start.wait(10)
        return timed_check(name, fn)

    with ThreadPoolExecutor(max_workers=2) as pool:
        both = [pool.submit(check, name, CORRECT[name]) for name in expected]
        first, second = (f.result(timeout=60)[0] for f in both)
        assert str(first) == expected["mip_level"]
        assert str(second) == expected["depth_test"]
        looped = pool.submit(check, "depth_test", forever)
        right = pool.submit(check, "mip_level", CORRECT["mip_level"])
        (report, took), (correct, _) = looped.result(timeout=60), right.result(timeout=60)
    assert str(correct) == expected["mip_level"]
    assert report.failures[0].explanation == LOOP_WORDS
    assert took.within(BUDGET + SLACK)


def test_the_checkers_own_calls_off_the_main_thread_return_their_value():
    """``run_checker`` (the comparisons and explanations) runs in the calling thread: off the
    main one it gave its fallback for every call."""
    assert in_thread(running.run_checker, lambda: 5, "fallback") == 5
    assert in_pool(running.run_checker, lambda: 1 / 0, "fallback") == "fallback"


def test_cases_that_end_as_their_limit_passes_are_a_value_or_a_timeout():
    """A case that returns just as the watchdog fires: its interrupt may arrive after the
    student's function has returned, and is caught by the guard, never reported as "raised"
    (each case in a budget of its own: after a case past its limit, a check runs no more)."""

    def burn():
        end = time.thread_time() + 0.01
        while time.thread_time() < end:
            pass
        return 7

    def case():
        with running.budget(1.0):
            return running.run_case(burn, limit=0.01)

    outcomes = in_thread(lambda: [case() for _ in range(30)])
    for outcome in outcomes:
        assert outcome.value == 7 or outcome.kind in ("timeout", "budget"), outcome


def test_drain_async_raises_nothing_in_any_thread():
    """It replaces a pending interrupt by one of its own and catches that: the sending, inside
    its ``try``, once returned through its ``except`` and the exception escaped."""

    def drain_then_loop():
        drain_async()
        for _ in range(100_000):  # nothing left pending to land here
            pass
        return "quiet"

    assert drain_then_loop() == "quiet"
    assert in_thread(drain_then_loop) == "quiet"


class _StopCutShort:
    """An alarm whose first two stops are cut short by an interrupt (one on its way as the case
    ended, one the watchdog sent as it was leaving): the most there can be."""

    def __init__(self):
        self.stops, self.fired, self.active, self.leaving, self.guard = 0, True, False, False, None

    def start(self):
        self.active = True

    def stop(self):
        self.stops += 1
        if self.stops <= 2:
            raise CaseInterrupt("landed in stop()")


@pytest.mark.parametrize("body, ok", [(lambda: 5, True), (lambda: 1 / 0, False)])
def test_an_interrupt_landing_in_stop_is_caught_and_the_stop_finished(body, ok):
    alarm = _StopCutShort()
    done, got = running._guarded(alarm, body)
    assert done is ok and alarm.stops == 3 and alarm.leaving
    assert (got == 5) if ok else isinstance(got, ZeroDivisionError)
