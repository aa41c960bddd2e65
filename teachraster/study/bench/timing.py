"""Timing: interleaved medians (a busy machine slows every variant alike) and progress."""

from __future__ import annotations

import statistics
import sys
import time
from collections.abc import Callable

from ...core.validate import as_size
from .settings import ERROR_MEASURE


# -- timing and progress ----------------------------------------------------------------------
def time_interleaved(fns: list[Callable[[], object]], repeat: int) -> list[float]:
    """Median wall time of each ``fn()``, measured round-robin: one call of each per round.

    Other work on the machine (another process, a CPU-frequency change) then slows every
    variant alike instead of whichever happened to be measured at that moment, so the
    ratios between variants stay fair on a busy machine. Two untimed warm-up rounds come
    first.
    """
    return [statistics.median(t) for t in time_samples(fns, repeat)]


def time_samples(
    fns: list[Callable[[], object]], repeat: int, clock: Callable[[], float] = time.perf_counter
) -> list[list[float]]:
    """Every timed call of :func:`time_interleaved`: one list of ``repeat`` times per ``fn``
    (wall times by default), so a report can print the spread beside the median.

    ``clock=time.process_time`` times this process's CPU instead of the wall: time spent
    waiting for a core is not counted, so a sign that must hold on a loaded machine is judged
    on it, on the fastest rounds (lesson 06, ``benchmarks/bench_lesson06_signs.py``).
    """
    repeat = as_size("repeat", repeat)
    for _ in range(2):
        for fn in fns:
            fn()
    times = [[] for _ in fns]
    for _ in range(max(1, repeat)):
        for fn, record in zip(fns, times):
            t0 = clock()
            fn()
            record.append(clock() - t0)
    return times


def time_rows(
    rows: list[dict],
    fns: list,
    repeat: int,
    progress: Progress,
    baseline: str,
    also: tuple[str, list] | None = None,
    clock: Callable[[], float] = time.perf_counter,
):
    """Time a group's variants together (:func:`time_samples`), then add the ratios.

    Each row gets the median (``time_median_s``) and the fastest and slowest run
    (``time_min_s``, ``time_max_s``): on a busy machine the spread says how far to trust it.
    ``also = (name, fns)``, one more call per row timed in the same rounds (so load slows
    both alike), adds ``{name}_median_s``, ``{name}_min_s`` and ``{name}_max_s``: a part of
    the work timed beside the whole. ``clock`` as in :func:`time_samples` (wall time by
    default; ``time.process_time`` for this process's CPU time).
    """
    name, more = also if also is not None else ("", [])
    samples = time_samples(list(fns) + list(more), repeat, clock=clock)
    for row, t in zip(rows, samples):
        row.update(_spread("time", t))
    for row, t in zip(rows, samples[len(fns) :]):
        row.update(_spread(name, t))
    progress.step(f"{rows[0]['group']}: timing")
    return _ratios(rows, baseline)


def _spread(name: str, t: list[float]) -> dict:
    return {f"{name}_median_s": statistics.median(t), f"{name}_min_s": min(t),
            f"{name}_max_s": max(t)}  # fmt: skip


class Progress:
    """A one-line text progress bar on stderr (no dependency)."""

    def __init__(self, total: int, enabled: bool = True, width: int = 30):
        self.total, self.done, self.enabled, self.width = total, 0, enabled, width

    def step(self, label: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        filled = round(self.width * self.done / self.total)
        bar = "#" * filled + "-" * (self.width - filled)
        sys.stderr.write(f"\r[{bar}] {self.done:2d}/{self.total} {label[:40]:<40}")
        if self.done == self.total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def _ratios(rows: list[dict], baseline: str) -> list[dict]:
    base = next(r["time_median_s"] for r in rows if r["variant"] == baseline)
    for r in rows:
        r["time_ratio_to_baseline"] = r["time_median_s"] / base
        r["baseline"] = baseline
        r["error_measure"] = ERROR_MEASURE[r["group"]]
    return rows
