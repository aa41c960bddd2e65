"""A student's endless loops, one of each way to swallow the checker's interrupt: the checker
tests share them (test_checker_time, test_checker_truth, test_checker_compare, the kernel)."""

from __future__ import annotations

import contextlib
import threading
import time


def helper_loop():
    while True:
        pass


def forever(*args):
    """The loop every checker test uses: an endless loop swallowing every exception."""
    while True:
        try:
            while True:
                pass
        except BaseException:
            pass


def plain_loop(*args):
    while True:
        pass


def except_exception_loop(*args):
    while True:
        try:
            helper_loop()
        except Exception:
            pass


def bare_except_loop(*args):
    while True:
        try:
            while True:
                pass
        except:  # noqa: E722 - the student's code under test
            pass


def base_exception_around_a_call(*args):
    while True:
        try:
            helper_loop()
        except BaseException:
            continue


def nested_excepts(*args):
    while True:
        try:
            try:
                while True:
                    pass
            except BaseException:
                pass
        except BaseException:
            pass


def everything_inside_a_try(*args):
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


def suppress_in_a_loop(*args):
    while True:
        with contextlib.suppress(BaseException):
            helper_loop()


def finally_continue(*args):
    while True:
        try:
            helper_loop()
        finally:
            continue  # noqa: B012 - swallows the exception: the student's code under test


def catches_and_returns(*args):
    try:
        helper_loop()
    except BaseException:
        return args[0] < args[1]


def sleeps(*args):
    time.sleep(100)


def waits_for_an_event(*args):
    threading.Event().wait()


def recursion_catching_everything(*args, _until=None):
    """Each level catches the interrupt and recurses again: no exception ever unwinds it, so
    the checker must abandon it. (It gives up by itself 8 s after it began, so that an abandoned
    one does not spin for the rest of the test session.)"""
    until = time.monotonic() + 8 if _until is None else _until
    while time.monotonic() < until:
        try:
            recursion_catching_everything(*args, _until=until)
        except BaseException:
            pass
    return False


#: Loops that compute (stopped by the CPU limit).
COMPUTING = [
    forever,
    plain_loop,
    except_exception_loop,
    bare_except_loop,
    base_exception_around_a_call,
    nested_excepts,
    everything_inside_a_try,
    suppress_in_a_loop,
    finally_continue,
    catches_and_returns,
]
#: Functions that wait without computing (stopped by the wall-clock limit).
WAITING = [sleeps, waits_for_an_event]
