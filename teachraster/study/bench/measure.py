"""The whole study: every group in turn, with times relative to each group's baseline."""

from __future__ import annotations

import time
from collections.abc import Callable

from .groups import bench_depth, bench_edges, bench_fill, bench_interpolation
from .settings import GROUPS, sizes, variant_names
from .timing import Progress


def run(
    quick: bool = False,
    *,
    repeat: int | None = None,
    progress: bool = False,
    clock: Callable[[], float] = time.perf_counter,
) -> list[dict]:
    """Measure every variant of every group; one dict per variant.

    Parameters
    ----------
    quick : bool
        Smaller images and meshes (same variants): a smoke run of a few seconds.
    repeat : int, optional
        Timed runs per variant (median taken); default 7, or 3 with ``quick``.
    progress : bool
        Draw a progress bar on stderr.
    clock : callable, default ``time.perf_counter``
        What the timer reads: the wall clock, or ``time.process_time``, this process's CPU
        time, which leaves out the time spent waiting for a core on a busy machine (lesson 06
        judges numpy's signs on it).

    Returns
    -------
    list of dict
        Keys :data:`COMMON_COLUMNS` plus each group's own measures.
    """
    cfg = sizes(quick)
    repeat = (3 if quick else 7) if repeat is None else int(repeat)
    names = variant_names(quick)
    # one step per variant (its error measured), one per timed block of variants
    steps = sum(len(v) for v in names.values()) + len(GROUPS) + 1  # fill: two sizes
    bar = Progress(steps, enabled=progress)
    rows = []
    for bench in (bench_interpolation, bench_edges, bench_fill, bench_depth):
        rows += bench(cfg, repeat, bar, clock=clock)
    return rows
