"""Benchmark frame debugging: what ``trace=True``, the overlays and a pixel history cost.

Run from anywhere (the repository root is put on ``sys.path``)::

    python benchmarks/bench_history.py            # full run (the 1024² sphere)
    python benchmarks/bench_history.py --quick    # smoke run (256²)

Measurements, on the UV sphere of ``bench_scenes.py`` (19,800 triangles, one uv attribute,
depth test on), each timed *in turn* with the plain render after one warm-up (CPU time of this process,
``time.process_time``), the ratio the median of the per-round ratios:

1. ``render(..., trace=True)`` over ``trace=False``; then ``trace=True`` plus every overlay
   (overdraw, depth complexity, quad overshading, triangle size, Hi-Z, NaN) over
   ``trace=False``. Target: ≤ 2×.
2. Memory: the peak Python-allocated bytes (``tracemalloc``) of the traced render with all
   overlays, beyond the plain render's peak, in units of one (H, W) float64 array. Target:
   "a few frame-sized arrays" (no per-fragment Python objects).
3. One pixel history (a click in the inspector): median over pixels across the sphere.
4. The same at 4× MSAA (informative: the overlays recompute the per-sample coverage).

Speed is never asserted in tests; tests/test_frame_history.py smoke-runs ``--quick``.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
import tracemalloc
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
for path in (HERE.parent, HERE):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))

from bench_scenes import sphere_scene  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.pipeline.debugging.overlays import KINDS  # noqa: E402

TARGET = 2.0


def in_turn(fns, repeat: int) -> list[list[float]]:
    """CPU seconds of this process (``time.process_time``) for each of ``fns``, called in
    turn ``repeat`` times after one warm-up each: on a shared 2-core machine other
    processes' load changes wall time far more than it changes our own CPU time."""
    for fn in fns:
        fn()
    times = [[] for _ in fns]
    for _ in range(repeat):
        for fn, out in zip(fns, times):
            start = time.process_time()
            fn()
            out.append(time.process_time() - start)
    return times


def traced_with_overlays(clip, uv, size, samples=1):
    frame = tr.render(clip, size, size, attrs=uv, trace=True, samples=samples)
    for kind in KINDS:
        frame.overlay(kind)
    return frame


def ratio_row(label, times, base):
    ratios = [t / b for t, b in zip(times, base)]
    r = statistics.median(ratios)
    verdict = "PASS" if r <= TARGET else "over target"
    print(f"  {label:<44} {statistics.median(times) * 1e3:8.1f} ms  "
          f"{r:5.2f}x  (target <= {TARGET:g}x: {verdict})")  # fmt: skip
    return r


def bench_speed(clip, uv, size, repeat, samples=1):
    plain = lambda: tr.render(clip, size, size, attrs=uv, samples=samples)  # noqa: E731
    traced = lambda: tr.render(clip, size, size, attrs=uv, samples=samples, trace=True)  # noqa: E731
    every = lambda: traced_with_overlays(clip, uv, size, samples)  # noqa: E731
    base, t1, t2 = in_turn([plain, traced, every], repeat)
    print(f"  {'trace=False':<44} {statistics.median(base) * 1e3:8.1f} ms")
    ratio_row("trace=True", t1, base)
    ratio_row("trace=True + all six overlays", t2, base)
    frame = tr.render(clip, size, size, attrs=uv, samples=samples, trace=True)
    for kind in KINDS:
        start = time.process_time()
        frame.overlay(kind)
        print(f"    overlay {kind:<36} {(time.process_time() - start) * 1e3:8.1f} ms")


def bench_memory(clip, uv, size):
    frame_bytes = size * size * 8
    tracemalloc.start()
    tr.render(clip, size, size, attrs=uv)
    plain = tracemalloc.get_traced_memory()[1]
    tracemalloc.reset_peak()
    frame = traced_with_overlays(clip, uv, size)
    traced = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    m = len(frame.trace.fragment_row)
    print(
        f"  peak, trace=False: {plain / 2**20:7.1f} MiB ({plain / frame_bytes:.1f} frames); "
        f"trace=True + overlays: {traced / 2**20:7.1f} MiB ({traced / frame_bytes:.1f} frames)"
    )
    print(f"  extra: {(traced - plain) / frame_bytes:.1f} frame-sized float64 arrays, "
          f"{m:,} fragments ({(traced - plain) / max(m, 1):.0f} bytes per fragment), "
          f"no per-fragment Python objects")  # fmt: skip


def bench_click(clip, uv, size, repeat):
    frame = tr.render(clip, size, size, attrs=uv, trace=True)
    rng = np.random.default_rng(1)
    rows, cols = np.nonzero(frame.coverage)
    pick = rng.choice(len(rows), size=max(repeat, 3))
    times = []
    for i in pick:
        start = time.process_time()
        h = frame.history(int(rows[i]), int(cols[i]))
        times.append(time.process_time() - start)
    print(f"  one pixel history (median of {len(pick)} pixels): "
          f"{statistics.median(times) * 1e3:.1f} ms, e.g. {len(h)} records")  # fmt: skip


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true", help="smoke run at 256x256")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args(argv)
    size = 256 if args.quick else 1024
    clip, uv = sphere_scene()
    print(f"UV sphere, {len(clip):,} triangles, {size}x{size}, uv, depth test on")
    print("1. time")
    bench_speed(clip, uv, size, args.repeat)
    print("2. memory")
    bench_memory(clip, uv, size)
    print("3. a click")
    bench_click(clip, uv, size, args.repeat)
    print("4. 4x MSAA (informative)")
    bench_speed(clip, uv, size if args.quick else 512, max(1, args.repeat // 2), samples=4)
    return 0


if __name__ == "__main__":
    sys.exit(main())
