"""Unwind a student's function that runs past its time limit, even one that catches everything.

:class:`CaseInterrupt` is what stops a case: a ``BaseException`` (as ``KeyboardInterrupt`` is),
so that ``except Exception`` cannot swallow it. :class:`.alarm.Alarm` raises it once the case's
limit has passed and again every ``TICK`` seconds until the case unwinds to the checker: a loop
around ``try: ... except: pass`` catches one interrupt, not all of them. From the second
interrupt on, a tracer watches the student's frames instruction by instruction and raises at
the first instruction from which the exception cannot be caught before it reaches the checker
(:func:`escapes`, reading Python 3.11+ exception tables), so that even a bare ``except:``
inside a loop inside a ``try`` lets it through. In a thread other than the main one the
interrupt is an asynchronous exception (:func:`send_async`), which lands at the thread's next
check for pending work: once the case ends, one still on its way is dropped
(:func:`drain_async`), and one that lands in the checker's clean-up first is caught there
(``running._guarded``), so that none reaches a report or the caller, in any thread.
"""

from __future__ import annotations

import dis
import os
import sys
import threading

#: Seconds between two interrupts once a case is past its limit.
TICK = 0.05

_CLEANUP_OPS = {
    "CACHE",
    "COPY",
    "POP_EXCEPT",
    "POP_TOP",
    "SWAP",
    "NOP",
    "LOAD_CONST",
    "STORE_FAST",
    "STORE_NAME",
    "DELETE_FAST",
    "DELETE_NAME",
}


class CaseInterrupt(BaseException):
    """A case ran past its time limit.

    Derived from ``BaseException``, as ``KeyboardInterrupt`` is, so that a student's
    ``except Exception`` does not swallow it.
    """


class ThreadInterrupt(CaseInterrupt):
    """The interrupt a watchdog sends to another thread.

    Python builds it in the interrupted thread, where the exception is raised: from the second
    interrupt on, building it sets the tracer on that thread (only that thread can).
    """

    def __init__(self, *args):
        super().__init__(*args)
        alarm = getattr(busy, "alarm", None)
        if alarm is not None and alarm.active and alarm.fires > 1 and sys.version_info >= (3, 11):
            alarm._trace_frames(sys._getframe(1))


def _exception_table(code) -> list[tuple[int, int, int]]:
    """(start, end, target) byte offsets of ``code``'s exception table (Python 3.11+).

    The format is CPython's Objects/exception_handling_notes.txt: varints of 6-bit chunks,
    bit 6 set on all chunks but the last, bit 7 marking the start of an entry.
    """
    raw = iter(getattr(code, "co_exceptiontable", b""))

    def varint():
        b = next(raw)
        value = b & 63
        while b & 64:
            b = next(raw)
            value = (value << 6) | (b & 63)
        return value

    entries = []
    try:
        while True:
            start = varint() * 2
            end = start + varint() * 2
            target = varint() * 2
            varint()  # depth and lasti
            entries.append((start, end, target))
    except StopIteration:
        return entries


_tables: dict = {}


def _handler_at(code, offset: int) -> int | None:
    """The byte offset of the handler covering ``offset``, or None (the exception leaves)."""
    if code not in _tables:
        if len(_tables) > 1000:
            _tables.clear()
        _tables[code] = _exception_table(code)
    for start, end, target in _tables[code]:
        if start <= offset < end:
            return target
    return None


def _reraise_of_cleanup(code, target: int) -> int | None:
    """The RERAISE ending a handler that only cleans up and re-raises, or None if it may catch."""
    raw = code.co_code
    for offset in range(target, len(raw), 2):
        name = dis.opname[raw[offset]]
        if name == "RERAISE":
            return offset
        if name not in _CLEANUP_OPS:
            return None
    return None


def _catches(code, offset: int) -> bool:
    """Could an exception raised at ``offset`` be caught (or suppressed) inside this frame?"""
    for _ in range(64):  # handlers chain through clean-up blocks; a few links at most
        target = _handler_at(code, offset)
        if target is None:
            return False
        offset = _reraise_of_cleanup(code, target)
        if offset is None:
            return True  # an except clause, a finally or a with: it may swallow the exception
    return True


#: The checker's own frames between a student's function and the guard whose handlers only
#: clean up and re-raise (a ``finally`` calling a function, which :func:`_reraise_of_cleanup`
#: cannot tell from an ``except``): read as catching, they hid every way out (stop 36's CI hung
#: on exercise 11's endless loop).
_TRANSPARENT: set = set()


def transparent(fn):
    """Mark a checker function whose ``try``/``finally`` only cleans up and re-raises.

    :func:`escapes` looks through its frames instead of treating them as a possible catch.
    """
    _TRANSPARENT.add(fn.__code__)
    return fn


def is_transparent(code) -> bool:
    """Whether ``code`` belongs to a function marked with :func:`transparent`."""
    return code in _TRANSPARENT


#: The package's files with a handler that can catch a :class:`CaseInterrupt` (a bare
#: ``except:``, ``except BaseException``): the guard's (``running``), the drain of a late
#: interrupt (this one) and code never run by a check. tests/test_interrupt_paths.py keeps
#: this list true.
CATCHING_FILES = frozenset({
    "exercises/running.py", "exercises/interrupt.py", "exercises/student_version.py",
    "course/install.py", "study/opengl.py",
})  # fmt: skip

_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep
_looked_through: dict = {}


def looked_through(code) -> bool:
    """Is ``code`` one whose handlers never catch a :class:`CaseInterrupt`?

    Marked :func:`transparent`, a watched answer's stub, or any of the package's own code
    outside :data:`CATCHING_FILES`: its ``except ValueError`` cannot swallow the interrupt, but
    :func:`_catches` reads every ``except`` clause as one that may (stop 45's CI: exercise
    3.1's ``call_barycentric`` and its ``except ValueError`` around a loop catching everything
    hid every way out, and the worker was killed after 900 s).
    """
    if code in _TRANSPARENT:
        return True
    name = code.co_filename
    seen = _looked_through.get(name)
    if seen is None:
        if name.startswith("<teachraster"):
            seen = True
        elif name.startswith(_PACKAGE):
            seen = name[len(_PACKAGE) :].replace(os.sep, "/") not in CATCHING_FILES
        else:
            seen = False
        _looked_through[name] = seen
    return seen


def escapes(frame, guard) -> bool:
    """True when an exception raised now in ``frame`` reaches ``guard`` uncaught."""
    while frame is not None and frame is not guard:
        if not looked_through(frame.f_code) and _catches(frame.f_code, frame.f_lasti):
            return False
        frame = frame.f_back
    return frame is guard


busy = threading.local()


def _make_async_exc():
    """``PyThreadState_SetAsyncExc`` through ctypes (CPython), or None where unavailable."""
    try:
        import ctypes

        setter = ctypes.pythonapi.PyThreadState_SetAsyncExc
    except (ImportError, AttributeError):
        return None
    setter.argtypes = [ctypes.c_ulong, ctypes.py_object]

    def send(thread_id, exc):
        setter(thread_id, ctypes.py_object(exc) if exc is not None else ctypes.py_object())

    return send


#: ``send_async(thread_id, exc)``, or None where Python offers no asynchronous exceptions.
send_async = _make_async_exc()


class _Drained(BaseException):
    """Replaces an interrupt not yet delivered, to be caught at once (:func:`drain_async`)."""


#: How many times :func:`drain_async` sends its :class:`_Drained` before it gives up.
DRAIN_ATTEMPTS = 100


def drain_async() -> None:
    """Drop an asynchronous exception pending on this thread, and the flag it sets.

    CPython keeps one flag for the whole interpreter while any thread has an exception
    pending, and clears it only when that thread raises it: ``send_async(thread, None)``
    would leave it set (every thread's interpreter loop then takes its slow path for good).
    So the pending interrupt is replaced by :class:`_Drained`, which this thread raises at its
    next check for pending work (as the call that sends it returns), and caught: the sending
    and every loop are inside the ``try`` (the sending once was not, and every check off the
    main thread failed every case with "your function raised ..._Drained"). An interrupt that
    lands here before it is replaced is dropped too: it is the one this drains.

    The flag may be cleared by another thread raising its own asynchronous exception between
    the sending and the check: then nothing is raised here, and the sending is repeated. Should
    it never be raised (``DRAIN_ATTEMPTS`` times), the exception is cleared instead, at the
    price of the flag: never left pending, to land later in code that does not expect it.
    """
    if send_async is None:
        return
    try:  # everything inside it: the exception is raised at a call's end or a loop's jump back
        me = threading.get_ident()
        for _ in range(DRAIN_ATTEMPTS):
            send_async(me, _Drained)
            for _ in range(1000):
                pass
        send_async(me, None)
    except (_Drained, CaseInterrupt):
        pass
