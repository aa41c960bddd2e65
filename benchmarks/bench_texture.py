"""Benchmark texture filtering: what mipmaps and anisotropy cost, and what they buy.

    python benchmarks/bench_texture.py            # full run
    python benchmarks/bench_texture.py --quick    # smoke run

1. The built-in textured floor at 1024×768 rendered with each texture filter
   (``tr.render(scene, width=1024, height=768, texture_filter=...)``), timed round-robin in
   the same run: medians and the ratio to ``bilinear``. Target: ``trilinear`` ≤ 2× ``bilinear``
   (it adds the 2×2-quad derivatives, the mip level and a second bilinear lookup).
2. Accuracy against cost (``teachraster.study.texture_truth.filter_study``) at 320×240: each
   filter's RMS error against the texture averaged over the true pixel footprint (16 × 16
   jittered points per pixel on the exact perspective map), overall and on minified pixels,
   with texels read per pixel and time.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import teachraster as tr  # noqa: E402
from teachraster.study.bench import time_interleaved  # noqa: E402
from teachraster.study.texture_truth import STUDY_FILTERS, filter_study  # noqa: E402

TARGET = 2.0  # trilinear within 2x of bilinear


def bench_speed(width: int, height: int, repeat: int) -> float:
    """Section 1: every filter on the floor, round-robin; returns trilinear / bilinear."""
    scene = tr.get_scene("textured_floor")
    filters = list(STUDY_FILTERS)
    fns = [
        (lambda f=f: tr.render(scene, width=width, height=height, texture_filter=f))
        for f in filters
    ]
    times = dict(zip(filters, time_interleaved(fns, repeat)))
    print(f"\n1. textured_floor at {width}x{height}, medians of {repeat} (round-robin)")
    print(f"  {'filter':<24}{'median':>10}{'x bilinear':>12}")
    for f in filters:
        print(f"  {f:<24}{times[f] * 1e3:>8.1f}ms{times[f] / times['bilinear']:>11.2f}x")
    ratio = times["trilinear"] / times["bilinear"]
    verdict = "PASS" if ratio <= TARGET else "MISS"
    print(f"  trilinear / bilinear = {ratio:.2f} (target <= {TARGET:g}): {verdict}")
    return ratio


def bench_accuracy(width: int, height: int, samples: int, repeat: int) -> None:
    """Section 2: error against the footprint average, texels read, time."""
    rows = filter_study(tr.get_scene("textured_floor"), width, height, samples=samples,
                        repeat=repeat)  # fmt: skip
    print(f"\n2. accuracy vs cost at {width}x{height} (truth: {samples}x{samples} points/pixel)")
    print(f"  {'filter':<24}{'RMS error':>10}{'minified':>10}{'texels/px':>11}{'time':>10}")
    for r in rows:
        print(
            f"  {r['filter']:<24}{r['error']:>10.4f}{r['error_minified']:>10.4f}"
            f"{r['texel_reads']:>11.1f}{r['time_median_s'] * 1e3:>8.1f}ms"
        )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fast smoke run")
    parser.add_argument("--repeat", type=int, default=None)
    args = parser.parse_args(argv)
    repeat = args.repeat or (1 if args.quick else 7)
    print("teachraster texture-filtering benchmark" + (" (--quick)" if args.quick else ""))
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}")
    if args.quick:
        bench_speed(256, 192, repeat)
        bench_accuracy(64, 48, 4, repeat)
    else:
        bench_speed(1024, 768, repeat)
        bench_accuracy(320, 240, 16, 3)
    return 0


if __name__ == "__main__":
    sys.exit(main())
