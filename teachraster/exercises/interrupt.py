"""Stop a student's function that runs past its time limit, even one that catches everything.

An :class:`Alarm` raises :class:`CaseInterrupt` in the running code once the limit has passed,
and again every ``TICK`` seconds until the case unwinds to the checker: a loop around
``try: ... except: pass`` catches one interrupt, not all of them. In the main thread (where a
Jupyter kernel runs its cells) the interrupt comes from ``SIGALRM``, which also cuts
``time.sleep`` short; from the second interrupt on, a tracer watches the student's frames
instruction by instruction and raises at the first instruction from which the exception
cannot be caught before it reaches the checker (Python 3.11+ exception tables), so that even a
bare ``except:`` inside a loop inside a ``try`` lets it through. In another thread the
interrupt is an asynchronous exception sent by a watchdog thread; where neither exists, the
time is measured afterwards and an overrun reported all the same.
"""

from __future__ import annotations

import dis
import signal
import sys
import threading
import time

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


class _ThreadInterrupt(CaseInterrupt):
    """The interrupt a watchdog sends to another thread.

    Python builds it in the interrupted thread, where the exception is raised: from the second
    interrupt on, building it sets the tracer on that thread (only that thread can).
    """

    def __init__(self, *args):
        super().__init__(*args)
        alarm = getattr(_busy, "alarm", None)
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


def escapes(frame, guard) -> bool:
    """True when an exception raised now in ``frame`` reaches ``guard`` uncaught."""
    while frame is not None and frame is not guard:
        if _catches(frame.f_code, frame.f_lasti):
            return False
        frame = frame.f_back
    return frame is guard


class Alarm:
    """Interrupts the calling thread ``seconds`` after :meth:`start` until :meth:`stop`.

    ``guard`` is the checker's frame that catches :class:`CaseInterrupt`. ``fired`` tells
    afterwards whether the limit passed (then the case is a timeout, whatever it returned).
    """

    def __init__(self, seconds: float, guard):
        self.seconds = seconds
        self.guard = guard
        self.active = False
        self.fired = False
        self.fires = 0
        self.mode = None
        self._previous = None
        self._trace = None
        self._traced = False

    # -- start and stop ------------------------------------------------------------------------
    def start(self) -> None:
        self.begin = time.perf_counter()
        if getattr(_busy, "on", False):
            return  # a check inside a checked function: the outer alarm governs
        _busy.on = True
        _busy.alarm = self
        self.active = True
        in_main = threading.current_thread() is threading.main_thread()
        if in_main and hasattr(signal, "setitimer"):
            self.mode = "signal"
            self._previous = signal.signal(signal.SIGALRM, self._on_signal)
            self._timer = signal.setitimer(signal.ITIMER_REAL, self.seconds, TICK)
        elif _async_exc is not None:
            self.mode = "watchdog"
            self._start_watchdog()
        else:
            self.mode = "measured"

    def stop(self) -> None:
        """Idempotent: disarm, restore the previous handler, timer and trace function."""
        self.active = False
        mode, self.mode = self.mode, None
        if mode is None:
            return
        _busy.on = False
        _busy.alarm = None
        if mode == "signal":
            signal.setitimer(signal.ITIMER_REAL, 0)
            # None: a handler not installed from Python, which cannot be put back
            signal.signal(signal.SIGALRM, self._previous or signal.SIG_DFL)
            delay, interval = self._timer  # someone else's timer (pytest-timeout...): re-arm
            if delay > 0:
                left = max(delay - (time.perf_counter() - self.begin), 1e-3)
                signal.setitimer(signal.ITIMER_REAL, left, interval)
        elif mode == "watchdog":
            with self._lock:
                self._done.set()
                _async_exc(self._thread_id, None)  # drop an interrupt not yet delivered
        if self._traced:
            self._traced = False
            sys.settrace(self._trace)

    def overran(self) -> bool:
        """The case took longer than its limit (where nothing could interrupt it)."""
        return time.perf_counter() - self.begin > self.seconds

    # -- the interrupt -------------------------------------------------------------------------
    def _on_signal(self, signum, frame):
        if not self.active:
            return
        self.fired = True
        self.fires += 1
        if self.fires > 1 and sys.version_info >= (3, 11):
            self._trace_frames(frame)
        raise CaseInterrupt(f"stopped after {self.seconds:g} s")

    def _trace_frames(self, frame) -> None:
        """Watch every frame between ``frame`` and the guard instruction by instruction."""
        if not self._traced:
            self._trace = sys.gettrace()
            self._traced = True
        f = frame
        while f is not None and f is not self.guard:
            f.f_trace = self._tracer
            f.f_trace_opcodes = True
            f = f.f_back
        sys.settrace(self._tracer)

    def _tracer(self, frame, event, arg):
        if event == "call":
            frame.f_trace_opcodes = True
        elif self.active and escapes(frame, self.guard):
            raise CaseInterrupt(f"stopped after {self.seconds:g} s")
        return self._tracer

    def _start_watchdog(self) -> None:
        self._lock = threading.Lock()
        self._done = threading.Event()
        self._thread_id = threading.get_ident()

        def watch():
            if self._done.wait(self.seconds):
                return
            while True:
                with self._lock:
                    if self._done.is_set():
                        return
                    self.fired = True
                    self.fires += 1
                    _async_exc(self._thread_id, _ThreadInterrupt)
                if self._done.wait(TICK):
                    return

        threading.Thread(target=watch, daemon=True, name="teachraster-check-watchdog").start()


_busy = threading.local()


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


_async_exc = _make_async_exc()
