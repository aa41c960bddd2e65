"""The checker's time budget: an endless loop is stopped and reported, whatever it catches.

Every test here is bounded by a few seconds: the budget is 1 s (0.2 s per case) and each
assertion allows the budget plus 2 s.
"""

from __future__ import annotations

import contextlib
import signal
import sys
import threading
import time

import numpy as np
import pytest

from teachraster import exercises as ex

BUDGET = 1.0
SLACK = 2.0


def timed_check(name, fn, budget=BUDGET):
    start = time.perf_counter()
    report = ex.check(name, fn, budget=budget)
    return report, time.perf_counter() - start


def helper_loop():
    while True:
        pass


def plain_loop(incoming, stored):
    while True:
        pass


def except_exception_loop(incoming, stored):
    while True:
        try:
            helper_loop()
        except Exception:
            pass


def bare_except_loop(incoming, stored):
    while True:
        try:
            while True:
                pass
        except:  # noqa: E722 - the student's code under test
            pass


def base_exception_around_a_call(incoming, stored):
    while True:
        try:
            helper_loop()
        except BaseException:
            continue


def nested_excepts(incoming, stored):
    while True:
        try:
            try:
                while True:
                    pass
            except BaseException:
                pass
        except BaseException:
            pass


def everything_inside_a_try(incoming, stored):
    try:
        while True:
            try:
                while True:
                    pass
            except BaseException as exc:
                del exc
    except BaseException:
        pass
    return True


def suppress_in_a_loop(incoming, stored):
    while True:
        with contextlib.suppress(BaseException):
            helper_loop()


def finally_continue(incoming, stored):
    while True:
        try:
            helper_loop()
        finally:
            continue  # noqa: B012 - swallows the exception: the student's code under test


def catches_and_returns(incoming, stored):
    try:
        helper_loop()
    except BaseException:
        return incoming < stored


def sleeps(incoming, stored):
    time.sleep(100)


LOOPS = [
    plain_loop,
    except_exception_loop,
    bare_except_loop,
    base_exception_around_a_call,
    nested_excepts,
    everything_inside_a_try,
    suppress_in_a_loop,
    finally_continue,
    catches_and_returns,
    sleeps,
]


@pytest.mark.parametrize("fn", LOOPS, ids=[f.__name__ for f in LOOPS])
def test_an_endless_loop_is_stopped_and_reported_whatever_it_catches(fn):
    trace = sys.gettrace()
    report, took = timed_check("depth_test", fn)
    assert took < BUDGET + SLACK
    assert not report.passed and report.stopped is not None
    first = report.failures[0]
    assert first.kind == "timeout" and first.got is None
    assert first.explanation == (
        "your function did not return within 0.2 s on case 1 of 30: an endless loop?"
    )
    assert report.n_run == 1 and len(report.failures) == 1  # stopped at the first case
    assert "the check stopped after case 1 of 30" in str(report)
    assert sys.gettrace() is trace  # a debugger's or coverage's tracer is given back


def test_the_interrupt_is_not_an_exception():
    from teachraster.exercises.running import CaseInterrupt

    assert issubclass(CaseInterrupt, BaseException) and not issubclass(CaseInterrupt, Exception)


def test_a_loop_on_a_later_case_keeps_the_failures_before_it():
    def loops_on_ties(incoming, stored):
        while incoming == stored:
            pass
        return incoming <= stored

    report, took = timed_check("depth_test", loops_on_ties)
    assert took < BUDGET + SLACK
    assert report.failures[-1].kind == "timeout"
    assert report.n_run < report.n_cases


def test_a_slow_function_runs_out_of_the_budget_and_says_so():
    def slow(incoming, stored):
        time.sleep(0.12)
        return incoming < stored

    report, took = timed_check("depth_test", slow)
    assert took < BUDGET + SLACK
    assert not report.passed
    last = report.failures[-1]
    assert last.kind == "budget"
    assert "budget of 1 s ran out" in last.explanation and "budget=30" in last.explanation
    assert 3 <= report.n_run < report.n_cases


def test_the_budget_covers_every_exercise():
    def forever(*args):
        while True:
            try:
                while True:
                    pass
            except BaseException:
                pass

    start = time.perf_counter()
    for name in ex.names():
        report = ex.check(name, forever, budget=0.5)
        assert not report.passed and report.failures[0].kind == "timeout", name
    assert time.perf_counter() - start < len(ex.names()) * 0.5 + SLACK


@pytest.mark.parametrize("fn", LOOPS[:-1], ids=[f.__name__ for f in LOOPS[:-1]])
def test_off_the_main_thread_the_loop_is_stopped_too(fn):
    """A watchdog thread interrupts (time.sleep cannot be cut short there: not tested)."""
    out = {}

    def run():
        out["report"], out["took"] = timed_check("depth_test", fn)

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(BUDGET + SLACK + 1)
    assert not thread.is_alive()
    assert out["took"] < BUDGET + SLACK
    assert out["report"].failures[0].kind == "timeout"


def test_exit_is_a_reported_failure_never_an_escape():
    report = ex.check("depth_test", lambda incoming, stored: sys.exit(3))
    assert not report.passed and report.failures[0].kind == "exit"
    assert report.failures[0].explanation.startswith("your function called exit()")
    report = ex.check("edge_function", lambda a, b, p: exit())
    assert report.failures[0].kind == "exit" and len(report.failures) == report.n_cases


def test_the_stop_button_still_stops_the_check():
    def interrupted(incoming, stored):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        ex.check("depth_test", interrupted)


def test_a_huge_answer_costs_no_time():
    def huge(v):
        return np.zeros((100_000, 4))

    report, took = timed_check("clip_near", huge, budget=10.0)
    assert took < 2.0
    assert "at most 4 vertices" in report.failures[0].explanation

    def huge_list(v):
        return [[0.0, 0.0, 0.0, 1.0]] * 100_000

    report, took = timed_check("clip_near", huge_list, budget=10.0)
    assert took < 2.0 and not report.passed


def test_someone_elses_alarm_and_handler_are_given_back():
    def handler(signum, frame):
        raise AssertionError("the outer alarm fired during the check")

    previous = signal.signal(signal.SIGALRM, handler)
    try:
        signal.setitimer(signal.ITIMER_REAL, 60)
        ex.check("depth_test", plain_loop, budget=0.5)
        left, _ = signal.setitimer(signal.ITIMER_REAL, 0)
        assert 50 < left <= 60
        assert signal.getsignal(signal.SIGALRM) is handler
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def test_budget_is_checked():
    with pytest.raises(TypeError, match="budget"):
        ex.check("depth_test", plain_loop, budget="10")
    with pytest.raises(ValueError, match="budget"):
        ex.check("depth_test", plain_loop, budget=0)
    with pytest.raises(ValueError, match="budget"):
        ex.check("depth_test", plain_loop, budget=float("inf"))
