"""When a case has run too long, and the delivery of the interrupt that stops it.

A case is measured in **CPU time of the thread that runs it**, not in wall-clock time: a busy
server, a first call that imports something, or output that the kernel is slow to send does not
count against the student. An :class:`Alarm`'s watchdog thread reads the case's thread CPU
clock (``time.pthread_getcpuclockid``; the process's CPU time where there is none) and wakes
only when the limit could have been reached. It fires when

- the case has used ``seconds`` of CPU (an endless loop, or code far slower than needed), or
- it has run ``wait`` seconds while computing less than ``WAITING`` of the time (it waits:
  ``time.sleep``, ``input()``, a lock; time the thread was ready to compute but queued for
  a core, Linux's per-thread ``schedstat``, counts as computing: on a machine busier than
  its cores a loop is starved, not waiting), or
- it has run ``cap`` seconds of wall-clock time in all (a machine too busy to give it CPU), or
- one call of the student's function inside the case has used ``call`` seconds of CPU (a case
  that calls it many times, the capstone's render once per pixel: :meth:`Alarm.call_begins`).

Firing sends :class:`.interrupt.CaseInterrupt` to the case's thread, again every ``TICK``
seconds until the case unwinds: in the main thread (where a Jupyter kernel runs its cells) by
``SIGALRM`` sent to that thread (which also cuts ``time.sleep`` short), in another thread as an
asynchronous exception. Someone else's ``SIGALRM`` timer is never touched, and a signal of
theirs arriving during a case is passed on to their handler.

What cannot be interrupted: one long call into C that holds the interpreter (``sum(range(10**12))``,
a huge numpy operation). Its case is reported as past its limit once the call returns.
"""

from __future__ import annotations

import gc
import math
import os
import queue
import signal
import sys
import threading
import time

from .interrupt import (
    TICK,
    CaseInterrupt,
    ThreadInterrupt,
    busy,
    drain_async,
    escapes,
    looked_through,
    send_async,
)

#: A case that has run ``wait`` seconds while computing less than this share of them waits.
WAITING = 0.05
#: No wait is ever longer than this (threading refuses larger timeouts).
LONGEST = 1e6
#: A case's wall-clock limits, in multiples of its CPU limit: one while it waits without
#: computing, one in all (a machine too busy to give it CPU). The one place for both:
#: :mod:`.running` derives every case's limits from them.
WAIT_FACTOR, CASE_WALL_FACTOR = 5.0, 20.0


class _Held:
    """A file opened for reading, closed when no one holds it any more."""

    __slots__ = ("fd",)

    def __init__(self, path: str):
        self.fd = os.open(path, os.O_RDONLY)

    def __del__(self):
        fd = getattr(self, "fd", None)  # None: the file could not be opened
        if fd is not None:
            try:
                os.close(fd)
            except OSError:
                pass


def queued_clock(native_id: int):
    """A function returning the seconds thread ``native_id`` of this process has spent ready
    to run but waiting for a core (the second field of Linux's ``schedstat``), or None where
    the platform does not say."""
    try:
        held = _Held(f"/proc/self/task/{native_id}/schedstat")
    except OSError:
        return None

    def queued() -> float:
        # every alarm reads it as it starts: os.pread at offset 0 of a descriptor kept open
        # reads the numbers of now again (a /proc file is made anew at offset 0), 1 µs, where
        # opening, reading and closing it each time took 6 µs of an alarm's ~25 (and a text
        # file object more still: 14 s of a 250-s profile of the checker tests). The closure
        # holds ``held``: the descriptor is closed only once no alarm can read it any more,
        # never reused for another file under an alarm that still reads it.
        return int(os.pread(held.fd, 256, 0).split()[1]) * 1e-9

    try:
        queued()
    except (OSError, ValueError, IndexError):
        return None
    return queued


#: Each thread's :func:`queued_clock`, found once (every alarm asks: trying the file each
#: time cost as much as reading it); a forked child starts afresh (its threads are new).
_own = threading.local()


def _own_queued_clock():
    """:func:`queued_clock` of the calling thread, remembered."""
    try:
        return _own.queued
    except AttributeError:
        _own.queued = queued_clock(threading.get_native_id())
        return _own.queued


def _forked() -> None:
    global _own, _idle, _idle_lock, _watched, _looking, _looker, _wake
    _own = threading.local()
    _idle, _idle_lock = [], threading.Lock()  # the parent's watchdog threads are not here
    _watched, _looking, _looker, _wake = {}, threading.Condition(), None, math.inf


#: Watchdog threads waiting for the next alarm past a limit (each on its own queue of one watch
#: at a time; the looker, below, hands them over): a thread started for every alarm, and waited
#: for until it ran, cost about 45 µs of CPU of the ~115 µs of an alarm, and a check starts one
#: for every case and every step of its diagnosis (about 98,000 in test_checker_corpus.py).
#: Past ``KEPT`` idle ones a thread ends.
_idle: list = []
_idle_lock = threading.Lock()
KEPT = 16


def _watcher(jobs: queue.SimpleQueue) -> None:
    while True:
        jobs.get()()  # one alarm's watch, to its end
        with _idle_lock:
            if len(_idle) >= KEPT:
                return
            _idle.append(jobs)


def _in_watchdog(watch) -> None:
    """Run ``watch`` in a waiting watchdog thread, or in a new one if none waits."""
    with _idle_lock:
        jobs = _idle.pop() if _idle else None
    if jobs is None:
        jobs = queue.SimpleQueue()
        threading.Thread(
            target=_watcher, args=(jobs,), daemon=True, name="teachraster-check-watchdog"
        ).start()
    jobs.put(watch)


#: Every running alarm (a top-level one, with a watchdog), watched by one thread, the looker,
#: until a limit has passed; only then is it handed to a watchdog thread of its own
#: (:func:`_in_watchdog`), which interrupts the case. Handing every alarm to a watchdog as it
#: started woke that thread twice an alarm (at the start and at the stop), about 30 µs of CPU
#: of an alarm's 50, and almost every alarm ends long before a limit could pass: now starting
#: and stopping wakes nobody. The looker wakes when the soonest of them could first be due
#: (:meth:`Alarm._next_look`, as the watchdog's own wait was), looks at those due for a look,
#: and sleeps again; a new alarm that could be due before that wakes it (``_wake``: when it
#: next looks, ``inf`` while it waits for an alarm).
_watched: dict = {}  # alarm -> True; the alarm's ``_look_at`` holds when to look at it next
_looking = threading.Condition()
_looker = None
_wake = math.inf


def _look() -> None:
    """The looker's loop (see ``_watched``)."""
    global _wake
    with _looking:
        while True:
            now = time.perf_counter()
            soonest = math.inf
            for alarm in list(_watched):
                at = alarm._look_at
                if at <= now:
                    try:
                        why = alarm.due()
                    except Exception:  # never the looker's end: the other alarms' limits hold
                        why = None
                    if why is not None:
                        if _watched.pop(alarm, None) is not None:  # not stopped meanwhile
                            _in_watchdog(alarm._firing(why))
                        continue
                    at = alarm._look_at = now + alarm._next_look()
                soonest = min(soonest, at)
            _wake = soonest
            _looking.wait(None if soonest == math.inf else soonest - now)


def _watch(alarm) -> None:
    """Have the looker watch ``alarm`` (started just now) until it is due or stopped."""
    global _looker
    at = alarm._look_at = alarm.begin + alarm._first_look()
    with _looking:
        _watched[alarm] = True
        if _looker is None:
            _looker = threading.Thread(target=_look, daemon=True, name="teachraster-check-looker")
            _looker.start()
        elif at < _wake:
            _looking.notify()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_forked)


def cpu_clock(thread_id: int | None = None):
    """A function returning the CPU seconds of thread ``thread_id`` (default: this one).

    Readable from any thread while that thread lives; the process's CPU time where the
    platform has no per-thread clock.
    """
    try:
        clock = time.pthread_getcpuclockid(thread_id or threading.get_ident())
        time.clock_gettime(clock)
    except (AttributeError, OSError):
        return time.process_time
    return lambda: time.clock_gettime(clock)


class Alarm:
    """Interrupts the calling thread once it has run too long, from :meth:`start` to :meth:`stop`.

    ``seconds`` is the case's CPU limit; ``wait`` and ``cap`` its wall-clock limits (see the
    module docstring); ``guard`` is the checker's frame that catches
    :class:`~.interrupt.CaseInterrupt`. Afterwards ``fired`` tells whether a limit passed,
    ``why`` which ("cpu", "wait" or "wall"), and :meth:`cpu` how much CPU the case used.
    """

    def __init__(self, seconds: float, guard, wait: float | None = None, cap: float | None = None,
                 call: float | None = None):  # fmt: skip
        self.seconds = min(seconds, LONGEST)
        #: CPU seconds one call of the student's function may take (None: no such limit), and
        #: the case's CPU when the call running now began (None: none runs)
        self.call = None if call is None else min(call, LONGEST)
        self.call_began = None
        self.wait = min(WAIT_FACTOR * seconds if wait is None else wait, LONGEST)
        self.cap = min(CASE_WALL_FACTOR * seconds if cap is None else cap, LONGEST)
        self.guard = guard
        self.active = False
        self.leaving = False  # set by the case's thread as it leaves the case: no more interrupts
        self.fired = False
        self.fired_at = None
        self.why = None
        self.fires = 0
        self.mode = None
        self._previous = None
        self._trace = None
        self._traced = False
        self._end = None
        self._queued = None
        self._collected = 0.0  # CPU seconds the garbage collector took in the case's thread
        self._collecting = None
        self._thread = None

    # -- measuring -------------------------------------------------------------------------------
    def cpu(self) -> float:
        """CPU seconds the case has used (until :meth:`stop`, then frozen)."""
        if self._end is not None:
            return self._end[0]
        try:
            now = self._clock()
            self._cpu_now = now - self._cpu_start - self._collected_by(now)
        except OSError:  # the thread has ended: its clock is gone
            pass
        return self._cpu_now

    def _collected_by(self, now: float) -> float:
        """The collector's CPU in the case's thread up to thread-CPU time ``now``: a
        collection under way counts too (the watchdog may look in while its "stop" callback
        runs)."""
        began = self._collecting
        return self._collected + (now - began if began is not None else 0.0)

    def collected(self) -> float:
        """CPU seconds the garbage collector took in the case's thread: not the student's,
        but not waiting either (a collection under a loaded machine outlasted ``wait``, and
        the case was told "it waits")."""
        try:
            return self._collected_by(self._clock())
        except OSError:  # the thread has ended: its clock is gone
            return self._collected

    def _on_collection(self, phase, info) -> None:
        """``gc.callbacks``: a collection in the case's thread is not the student's CPU. A
        full collection walks every object of the process, in a kernel (or a test worker)
        holding millions, seconds of it: a case that merely allocated when it came due was
        told "did not finish within 2 s of CPU" (a correct answer, twice in a full test run)."""
        if threading.get_ident() != self._thread:
            return
        try:
            if phase == "start":
                self._collecting = self._clock()
            elif self._collecting is not None:
                self._collected += self._clock() - self._collecting
                self._collecting = None
        except OSError:  # the thread's clock is gone
            self._collecting = None

    def queued(self) -> float:
        """Seconds the case was ready to compute but queued for a core (0 where unknown)."""
        if self._queued is None:
            return 0.0
        try:
            return self._queued() - self._queued_start
        except (OSError, ValueError, IndexError):  # the thread has ended
            return 0.0

    def wall(self) -> float:
        """Wall-clock seconds since :meth:`start` (until :meth:`stop`, then frozen)."""
        return self._end[1] if self._end is not None else time.perf_counter() - self.begin

    def due(self) -> str | None:
        """ "cpu", "call", "wait" or "wall" once a limit has passed, else None."""
        cpu, wall = self.cpu(), self.wall()
        if cpu > self.seconds:
            return "cpu"
        began = self.call_began
        if self.call is not None and began is not None and cpu - began > self.call:
            return "call"
        if wall > self.cap:
            return "wall"
        if wall > self.wait and cpu + self.collected() + self.queued() < WAITING * wall:
            return "wait"
        return None

    def overran(self) -> bool:
        """A limit passed (also where nothing could interrupt the case)."""
        return self.due() is not None

    def _next_look(self) -> float:
        """Seconds until a limit could first be reached (one thread's CPU runs no faster than
        the clock on the wall; the process's CPU, summed over threads, may)."""
        cpu, wall = self.cpu(), self.wall()
        soonest = [self.seconds - cpu, self.cap - wall, max(self.wait - wall, TICK)]
        if self.call is not None:  # a call may begin any time: no later than its limit
            began = self.call_began
            soonest.append(self.call - (0.0 if began is None else cpu - began))
        if self._clock is time.process_time:
            soonest.append(TICK)
        return min(max(min(soonest), 0.005), LONGEST)

    def _first_look(self) -> float:
        """:meth:`_next_look` at the start (no CPU used, no time passed): no clock read."""
        soonest = min(self.seconds, self.cap, max(self.wait, TICK))
        if self.call is not None:
            soonest = min(soonest, self.call)
        if self._clock is time.process_time:
            soonest = min(soonest, TICK)
        return min(max(soonest, 0.005), LONGEST)

    def call_begins(self) -> None:
        """A call of the student's function begins (under :attr:`call`'s limit)."""
        if self.call is not None:
            self.call_began = self.cpu()

    def call_ends(self) -> None:
        self.call_began = None

    # -- start and stop ------------------------------------------------------------------------
    def start(self) -> None:
        self.begin = time.perf_counter()
        self._clock = cpu_clock()
        self._cpu_start = self._clock()
        self._cpu_now = 0.0
        self._thread = threading.get_ident()
        gc.callbacks.append(self._on_collection)
        self._queued = _own_queued_clock()
        self._queued_start = self._queued() if self._queued is not None else 0.0
        if getattr(busy, "on", False):
            return  # a check inside a checked function: the outer alarm governs
        busy.on = True
        busy.alarm = self
        self.active = True
        in_main = threading.current_thread() is threading.main_thread()
        if in_main and hasattr(signal, "pthread_kill"):
            self.mode = "signal"
            self._previous = signal.signal(signal.SIGALRM, self._on_signal)
        elif send_async is not None:
            self.mode = "watchdog"
        else:
            self.mode = "measured"
            return
        self._start_watchdog()

    def stop(self) -> None:
        """Idempotent: disarm, restore the previous handler and trace function.

        Off the main thread an interrupt the watchdog sent before the case's thread set
        ``leaving`` may land in here (one at most: the watchdog sends none once ``leaving`` is
        set, and none after this has taken its lock); the caller catches it and calls this
        again, which finishes what the interrupt cut short (each step is done once).
        """
        self.active = False
        self.leaving = True
        if self._end is None:
            self._end = (self.cpu(), self.wall())
        if self._on_collection in gc.callbacks:
            gc.callbacks.remove(self._on_collection)
        mode = self.mode
        if mode is None:
            return
        if mode in ("signal", "watchdog"):
            _watched.pop(self, None)  # no lock: one dict operation, whole under the GIL
            with self._lock:
                self._done.set()
            if mode == "watchdog":
                drain_async()  # drop an interrupt not yet delivered: none can follow it
        busy.on = False
        busy.alarm = None
        if mode == "signal":
            # None: a handler not installed from Python, which cannot be put back
            signal.signal(signal.SIGALRM, self._previous or signal.SIG_DFL)
        if self._traced:
            self._traced = False
            sys.settrace(self._trace)
        self.mode = None

    # -- the interrupt -------------------------------------------------------------------------
    def _on_signal(self, signum, frame):
        if not (self.active and self.fired):  # someone else's alarm: theirs to handle
            if callable(self._previous):
                return self._previous(signum, frame)
            return None
        if frame is not None and frame.f_code is _IN_COLLECTION:
            # raised in a gc callback, the exception would be printed as "Exception ignored"
            # and lost: the watchdog sends the next interrupt a tick later, in the case's code
            return None
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
        elif self.active and not looked_through(frame.f_code) and escapes(frame, self.guard):
            # never inside the checker's own code: its clean-up (a finally) runs whole, and
            # the interrupt is raised again once the student's code runs
            raise CaseInterrupt(f"stopped after {self.seconds:g} s")
        return self._tracer

    def _send(self) -> None:
        if self.mode == "signal":
            signal.pthread_kill(self._thread_id, signal.SIGALRM)
        else:
            send_async(self._thread_id, ThreadInterrupt)

    def _start_watchdog(self) -> None:
        self._lock = threading.Lock()
        self._done = threading.Event()
        self._thread_id = threading.get_ident()
        _watch(self)

    def _firing(self, why: str):
        """The watch of this alarm once limit ``why`` has passed, for a watchdog thread of its
        own: interrupt the case, again every ``TICK`` s, until it has left."""

        def watch():
            last = None if why == "cpu" else self.cpu()
            while True:
                with self._lock:
                    if self._done.is_set() or self.leaving:
                        return
                    if not self.fired:
                        self.why, self.fired_at = why, time.perf_counter()
                    self.fired = True
                    now = self.cpu()
                    # an asynchronous exception reaches a thread only while it runs Python: one
                    # left pending on a thread blocked in a call keeps every other thread's
                    # interpreter loop on its slow path, so a blocked thread is not sent one
                    if self.mode == "signal" or last is None or now > last:
                        self.fires += 1
                        self._send()
                    last = now
                if self._done.wait(TICK):
                    return

        return watch


#: the code of :meth:`Alarm._on_collection`, a ``gc.callbacks`` entry: no interrupt is raised there
_IN_COLLECTION = Alarm._on_collection.__code__
