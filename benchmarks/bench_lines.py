"""Benchmark lines and blending: what the exact rules cost.

    python benchmarks/bench_lines.py            # full run
    python benchmarks/bench_lines.py --quick    # smoke run

1. ``tr.rasterize_line`` per rule (diamond, Bresenham, DDA) on a line 1,024 px and 2**18 px
   long (x-major, rising 3 px over its length, in a 5-row image), median time and time per
   lit pixel, and with ``trace=True``.
2. ``tr.render`` of N random transparent triangles at 512² with ``blend="over"`` and
   ``depth_write=False`` against the same render without blending, and with 4× MSAA.
Speed is never asserted; the exit status is non-zero only on errors.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

import teachraster as tr  # noqa: E402


def median_time(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def bench_lines(lengths, repeat: int) -> None:
    print("rasterize_line: median time (time per lit pixel)")
    for n in lengths:
        # x-major, 3 rows of rise over the whole length: a thin image however long the line
        args = ((0.5, 0.3), (n - 0.7, 3.2), n, 5)
        for rule in ("diamond", "bresenham", "dda"):
            for trace in (False, True):
                fill = tr.rasterize_line(*args, rule=rule, trace=trace)

                def call(a=args, r=rule, t=trace):
                    return tr.rasterize_line(*a, rule=r, trace=t)

                t = median_time(call, repeat)
                lit = int(fill.coverage.sum())
                label = f"{n:>7} px  {rule:<9} trace={trace!s:<5}"
                print(f"  {label} {t * 1e3:9.2f} ms  ({t / max(lit, 1) * 1e9:7.1f} ns/pixel)")


def scene(n: int, seed: int = 3):
    rng = np.random.default_rng(seed)
    centre = rng.uniform(-0.8, 0.8, (n, 1, 2))
    xy = centre + rng.uniform(-0.3, 0.3, (n, 3, 2))
    z = np.repeat(rng.uniform(-0.9, 0.9, (n, 1, 1)), 3, axis=1)
    clip = np.concatenate([xy, z, np.ones((n, 3, 1))], axis=-1)
    rgba = np.repeat(rng.uniform(0, 1, (n, 1, 4)), 3, axis=1)
    rgba[..., 3] = 0.5
    return clip, rgba


def bench_blending(n: int, size: int, repeat: int) -> None:
    clip, rgba = scene(n)
    plain = median_time(lambda: tr.render(clip, size, size, attrs=rgba), repeat)
    frame = tr.render(clip, size, size, attrs=rgba, blend="over", depth_write=False)
    blend = median_time(lambda: tr.render(clip, size, size, attrs=rgba, blend="over",
                                          depth_write=False), repeat)  # fmt: skip
    msaa = median_time(lambda: tr.render(clip, size, size, attrs=rgba, blend="over",
                                         depth_write=False, samples=4), repeat)  # fmt: skip
    print(f"render of {n} transparent triangles at {size}²:")
    print(f"  no blending        {plain * 1e3:9.1f} ms")
    print(f"  blend='over'       {blend * 1e3:9.1f} ms  ({blend / plain:.2f}x)")
    print(f"  blend, samples=4   {msaa * 1e3:9.1f} ms  ({msaa / plain:.2f}x)")
    print(f"  {frame.plan['blending']}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a few-second smoke run")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args(argv)
    lengths = (1024,) if args.quick else (1024, 2**18)
    bench_lines(lengths, args.repeat)
    bench_blending(50 if args.quick else 500, 128 if args.quick else 512, args.repeat)
    return 0


if __name__ == "__main__":
    sys.exit(main())
