"""Benchmark the tiled fill against half-planes and span tables, with llvmpipe's counters.

Run from anywhere (the repository root is put on ``sys.path``)::

    python benchmarks/bench_tiles.py            # full run (a few seconds)
    python benchmarks/bench_tiles.py --quick    # smoke run

Measurements (medians of ``--repeat`` calls, ``time.perf_counter``, after one warm-up; in
measurement 1 the methods run in turn within each round and the ratio is the median of the
per-round ratios, so a change of machine load during the run slows both alike):

1. The 1024×1024 single-triangle fill of ``bench_fill.py`` (half the image covered, w = [1,
   2, 4], three attributes): the coverage walk alone (the core's ``fill`` of each method on
   the same set-up), ``tr.rasterize`` without attributes, and ``tr.rasterize`` with them
   (where the tiled fill also shades the cells its walk left whole as blocks,
   :mod:`teachraster.core.block_shading`, while the others shade pixel by pixel).
   Target: ``method="tiled"`` faster than ``"halfplane"`` (accepted blocks skip their pixel
   tests). The block counters are printed next to the times.
2. Other block sizes on the same triangle: how the hierarchy trades block tests for pixel
   tests.
3. Small triangles: the tests per covered pixel of a big triangle and of small ones (why
   small triangles are expensive: every block they touch is partial).

Targets are informative; the exit status is non-zero only on errors (a coverage mismatch).
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
for path in (HERE.parent, HERE):
    if str(path) not in sys.path:
        sys.path.insert(0, str(path))

from bench_fill import fmt_time, machine_info, make_triangle, median_seconds  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.core import fixed_point, half_planes, span_tables, tiles  # noqa: E402
from teachraster.core.bbox import pixel_bbox  # noqa: E402
from teachraster.core.edges import setup_edges  # noqa: E402

SIZE = 1024
METHODS = ("halfplane", "tiled", "span")
OTHER_SIZES = ((64, 16, 4), (32, 8), (16, 4), (64, 8), (8,), (128, 32, 8, 2))
SMALL = (2.0, 8.0, 32.0, 128.0)  # legs of right triangles, px


def _walks(tri):
    setup = setup_edges(tri.xy, tr.SUBPIXEL_BITS)
    box = pixel_bbox(setup, SIZE, SIZE)
    return {
        "halfplane": lambda: half_planes.fill(setup, box, False),
        "tiled": lambda: tiles.fill(setup, box, False, image=(SIZE, SIZE)),
        "span": lambda: span_tables.fill(setup, box, False),
    }


def paired_medians(calls: dict, repeat: int) -> tuple[dict, float]:
    """Median time of each call and the median of the per-round halfplane/tiled ratios.

    The calls run in turn within each round (after one warm-up round), so a machine whose
    load changes during the run slows them alike and the paired ratio stays fair.
    """
    times = {name: [] for name in calls}
    for round_ in range(repeat + 1):
        for name, fn in calls.items():
            start = time.perf_counter()
            fn()
            if round_:
                times[name].append(time.perf_counter() - start)
    ratios = [h / t for h, t in zip(times["halfplane"], times["tiled"])]
    return {k: statistics.median(v) for k, v in times.items()}, statistics.median(ratios)


def bench_main(repeat: int) -> tuple[list[str], bool]:
    """Measurement 1: three figures per method on the 1024² triangle, and the counters."""
    tri = make_triangle(SIZE, SIZE)
    bare = tr.Triangle(tri.xy)
    walks = _walks(tri)
    want = tr.rasterize(bare, SIZE, SIZE).coverage
    for method in METHODS:
        if not np.array_equal(tr.rasterize(bare, SIZE, SIZE, method=method).coverage, want):
            raise RuntimeError(f"{method}: coverage differs from half-planes")
    rows, ratios = [], []
    for label, make in (
        ("coverage walk only", lambda m: walks[m]),
        ("rasterize, no attributes", lambda m: lambda: tr.rasterize(bare, SIZE, SIZE, method=m)),
        ("rasterize, w + 3 attributes", lambda m: lambda: tr.rasterize(tri, SIZE, SIZE, method=m)),
    ):
        t, ratio = paired_medians({m: make(m) for m in METHODS}, repeat)
        ratios.append(ratio)
        rows.append(
            f"  {label:<28} " + "  ".join(f"{m} {fmt_time(t[m]):>9}" for m in METHODS)
            + f"   halfplane/tiled = {ratio:.2f}x  {'PASS' if ratio > 1 else 'MISS'}"
        )  # fmt: skip
    trace = tr.rasterize(bare, SIZE, SIZE, method="tiled", trace=True).trace
    c = trace.blocks.counters
    box = trace.bbox.size
    rows.append(f"  counters: {c.summary()}")
    rows.append(
        f"  pixel tests: half-planes {box} (every centre of the box), tiled {c.pixel_tests} "
        f"({c.pixel_tests / box:.1%}); {c.pixels_accepted} pixels filled with no test"
    )
    budget = fixed_point.bit_budget(fixed_point.fill_extent(tri.xy, SIZE, SIZE), 8, 64)
    rows.append("  bit budget (int64): " + budget.lines()[-1])
    return rows, all(r > 1 for r in ratios)


def bench_sizes(repeat: int) -> list[str]:
    """Measurement 2: the walk with other block sizes, with its block and pixel tests."""
    tri = make_triangle(SIZE, SIZE)
    setup = setup_edges(tri.xy, tr.SUBPIXEL_BITS)
    box = pixel_bbox(setup, SIZE, SIZE)
    rows = []
    for sizes in OTHER_SIZES:
        t = median_seconds(lambda s=sizes: tiles.fill(setup, box, False, block_sizes=s,
                                                      image=(SIZE, SIZE)), repeat)  # fmt: skip
        c = tiles.fill(setup, box, True, block_sizes=sizes, image=(SIZE, SIZE))[1].counters
        label = "/".join(map(str, sizes))
        rows.append(
            f"  {label:<14} {fmt_time(t):>9}  {c.blocks:>6} block tests, "
            f"{c.pixel_tests:>7} pixel tests"
        )
    return rows


def bench_small() -> list[str]:
    """Measurement 3: tests per covered pixel, large against small triangles."""
    rows = []
    for leg in SMALL:
        xy = np.array([[100.3, 100.2], [100.3 + leg, 100.2], [100.3, 100.2 + leg]])
        fill = tr.rasterize(tr.Triangle(xy), 512, 512, method="tiled", trace=True)
        c, covered = fill.trace.blocks.counters, int(fill.coverage.sum())
        tests = c.blocks + c.pixel_tests
        rows.append(
            f"  legs {leg:>5g} px: {covered:>6} px covered, {c.blocks:>4} block tests + "
            f"{c.pixel_tests:>5} pixel tests = {tests / max(covered, 1):.2f} tests per pixel"
        )
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fast smoke run")
    parser.add_argument("--repeat", type=int, default=None, help="timed calls per figure")
    args = parser.parse_args(argv)
    repeat = args.repeat or (2 if args.quick else 9)
    print("teachraster tiled-fill benchmark" + (" (--quick)" if args.quick else ""))
    for line in machine_info():
        print(line)
    print(f"figures: median of {repeat} timed calls after 1 warm-up (time.perf_counter)")
    try:
        rows, passed = bench_main(repeat)
    except RuntimeError as exc:
        print(f"\nERROR: {exc}", file=sys.stderr)
        return 1
    print(f"\n1. {SIZE}x{SIZE} single triangle (bench_fill.py's), block sizes 64/16/4")
    print("\n".join(rows))
    print("\n2. block sizes on the same triangle (coverage walk only)")
    print("\n".join(bench_sizes(max(1, repeat // 2))))
    print("\n3. small triangles are expensive (512x512 image, 64/16/4)")
    print("\n".join(bench_small()))
    print(f"\ntiled faster than halfplane in every figure: {'PASS' if passed else 'MISS'} "
          "(informative; speed never sets the exit status)")  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
