"""Benchmark teachraster's triangle fills and print a table of medians, ratios and targets.

Run from anywhere (the repository root is put on ``sys.path``, so no installation is needed)::

    python benchmarks/bench_fill.py            # full run (about 15 s)
    python benchmarks/bench_fill.py --quick    # smoke run: smaller loop image, fewer repeats
    python benchmarks/bench_fill.py --repeat 11 --profile

Measurements (each a median of ``--repeat`` calls timed with ``time.perf_counter``, after one
warm-up call):

1. Fill of a 1024×1024 image by one triangle covering about half of it, with w = [1, 2, 4] and
   three attributes (``u`` and ``v`` scalars, ``rgb`` of shape (3, 3)), for both methods and
   both interpolations. Target: under 0.2 s.
2. Cost of recording the trace: the same fills with ``trace=True`` over ``trace=False``, at
   1024×1024 and at the teaching size 256×256. Target: at most 2×.
3. The vectorised fill against a straightforward per-pixel Python loop of the same algorithm
   (:func:`straightforward_halfplane`, at 256×256), after checking that both give the same
   coverage and attributes within 1e-9. Target: ≥ 100×. Hand-tuned pure-Python loops
   (:func:`python_loop_halfplane`, :func:`python_loop_span`: ints in flat lists) are timed
   too, at 1024×1024, to show how much of the gap is the interpreter and how much numpy.

Targets are reported as PASS/MISS for the reader and never change the exit status: it is
non-zero only on errors (a failed correctness check, a crash).

Importing this module only defines functions (and puts the repository root on ``sys.path``).
"""

from __future__ import annotations

import argparse
import cProfile
import os
import platform
import pstats
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

import teachraster as tr  # noqa: E402

#: Triangle vertices as fractions of (width, height): about 46% of the image is covered.
TRI_FRACTIONS = ((0.01, 0.02), (0.985, 0.06), (0.196, 0.977))
#: Clip-space w per vertex: different, so perspective-correct interpolation does real work.
W_PER_VERTEX = (1.0, 2.0, 4.0)
#: Per-vertex attributes: two scalars and one 3-vector (each vertex a pure primary colour).
ATTRS = {"u": [0.0, 1.0, 0.0], "v": [0.0, 0.0, 1.0], "rgb": np.eye(3)}

FILL_SIZE = 1024
TRACE_SIZES = (1024, 256)
LOOP_SIZE, QUICK_LOOP_SIZE = 1024, 128  # the tuned loops take about 1 s at 1024²
BASELINE_SIZE, QUICK_BASELINE_SIZE = 256, 64  # the straightforward loop: ~10 µs per pixel
FILL_TARGET_S = 0.2
TRACE_TARGET = 2.0
LOOP_TARGET = 100.0
ATTR_TOLERANCE = 1e-9

METHODS = ("halfplane", "span")
MODES = ("perspective", "affine")


class BenchmarkError(RuntimeError):
    """A correctness check failed: the timings would compare different work."""


@dataclass(frozen=True)
class Row:
    """One line of the report; ``fn`` re-runs the measured call (for ``--profile``)."""

    label: str
    figures: str
    target: str
    passed: bool | None  # None: shown for comparison, no target
    fn: Callable[[], object] | None = None

    @property
    def verdict(self) -> str:
        return {True: "PASS", False: "MISS", None: "info"}[self.passed]


# --------------------------------------------------------------------------------------------
# Inputs and timing


def make_triangle(width: int, height: int) -> tr.Triangle:
    """The benchmark triangle scaled to a ``width`` × ``height`` image (non-integer vertices)."""
    xy = np.array(TRI_FRACTIONS) * [width, height]
    return tr.Triangle(xy, w=W_PER_VERTEX, attrs=ATTRS)


def median_seconds(fn: Callable[[], object], repeat: int, warmup: int = 1) -> float:
    """Median wall time of ``fn()`` over ``repeat`` calls (``time.perf_counter``)."""
    for _ in range(warmup):
        fn()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def fill_call(tri: tr.Triangle, size: int, method: str, mode: str, trace: bool = False):
    """A zero-argument call of ``tr.rasterize`` with these settings."""
    return lambda: tr.rasterize(tri, size, size, method=method, interpolation=mode, trace=trace)


def fmt_time(seconds: float) -> str:
    """``12.3 ms`` or ``1.234 s``."""
    return f"{seconds * 1e3:.1f} ms" if seconds < 1 else f"{seconds:.3f} s"


# --------------------------------------------------------------------------------------------
# Scalar reference implementations (pure Python, one pixel at a time)


def _scalar_setup(tri: tr.Triangle, bits: int = tr.SUBPIXEL_BITS):
    """Snap to integer units (``2**(bits+1)`` per pixel, so centres are integers), orient.

    Returns ``(p, order, area2, top_left, unit, half)``: oriented vertices ``p`` (positive
    area), the original index ``order[k]`` of ``p[k]``, twice the area, the top-left flag of
    each edge ``p[k] -> p[k+1]``, and units per pixel and per half pixel.
    """
    scale = 2**bits
    # round() on a float rounds half to even, as the conventions require.
    pts = [(2 * round(x * scale), 2 * round(y * scale)) for x, y in tri.xy.tolist()]
    (ax, ay), (bx, by), (cx, cy) = pts
    area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    order = [0, 2, 1] if area2 < 0 else [0, 1, 2]
    p = [pts[i] for i in order]
    top_left = []
    for k in range(3):
        (x0, y0), (x1, y1) = p[k], p[(k + 1) % 3]
        top_left.append(y1 < y0 or (y1 == y0 and x1 > x0))
    unit = 2 * scale
    return p, order, abs(area2), top_left, unit, unit // 2


def _centre_range(lo: int, hi: int, half: int, unit: int, n: int) -> range:
    """Indices of pixel centres ``c`` with ``lo <= c <= hi`` (units), clipped to [0, n)."""
    first = max(-((half - lo) // unit), 0)
    last = min((hi - half) // unit, n - 1)
    return range(first, max(first, last + 1))


class _Shader:
    """Per-pixel perspective-correct interpolation into flat Python lists."""

    def __init__(self, tri: tr.Triangle, width: int, height: int):
        self.width, self.height = width, height
        self.inv_w = [1.0 / w for w in tri.w.tolist()]
        self.shapes = {name: f.shape[1:] for name, f in tri.attrs.items()}
        # One channel per scalar component: f0 and the differences to it (recentred at v0).
        self.channels = []
        for f in tri.attrs.values():
            for col in f.reshape(3, -1).T.tolist():
                self.channels.append((col[0], col[1] - col[0], col[2] - col[0]))
        self.out = [[float("nan")] * (width * height) for _ in self.channels]

    def shade(self, index: int, l0: float, l1: float, l2: float) -> None:
        """Interpolate every channel at pixel ``index`` from barycentrics in vertex order."""
        q0, q1, q2 = l0 * self.inv_w[0], l1 * self.inv_w[1], l2 * self.inv_w[2]
        total = q0 + q1 + q2
        m1, m2 = q1 / total, q2 / total
        for out, (f0, d1, d2) in zip(self.out, self.channels):
            out[index] = f0 + m1 * d1 + m2 * d2

    def images(self) -> dict[str, np.ndarray]:
        """The attribute images, shaped like ``tr.rasterize``'s (NaN outside coverage)."""
        result, c = {}, 0
        for name, shape in self.shapes.items():
            k = int(np.prod(shape, dtype=int))
            planes = np.array(self.out[c : c + k]).reshape(k, self.height, self.width)
            result[name] = np.moveaxis(planes, 0, -1).reshape(self.height, self.width, *shape)
            c += k
        return result


def straightforward_halfplane(tri: tr.Triangle, width: int, height: int):
    """The half-plane fill as a student first writes it: one pixel at a time over numpy arrays.

    Same algorithm and rules as ``tr.rasterize`` (snapped vertices, bounding box, three edge
    tests with bail-out and the top-left rule, perspective-correct interpolation), written
    the obvious way: vertices stay numpy arrays, each pixel reads and writes numpy arrays by
    index, and each attribute is interpolated by its own small expression. Snapped
    coordinates are multiples of 1/256 px, so these float64 edge values are exact too.
    This is the baseline of the >= 100x target; :func:`python_loop_halfplane` is a
    hand-tuned pure-Python version (ints in flat lists) shown for comparison.
    """
    v = tr.snap(tri.xy)
    w = tri.w
    if tr.edge_function(v[0], v[1], v[2]) < 0:  # orient so the inside is positive
        order = [0, 2, 1]
    else:
        order = [0, 1, 2]
    p = v[order]
    area = tr.edge_function(p[0], p[1], p[2])
    top_left = [tr.is_top_left(p[k], p[(k + 1) % 3]) for k in range(3)]
    coverage = np.zeros((height, width), dtype=bool)
    attrs = {name: np.full((height, width, *f.shape[1:]), np.nan) for name, f in tri.attrs.items()}
    if area == 0:
        return coverage, attrs
    lo, hi = v.min(axis=0), v.max(axis=0)
    cols = range(max(int(np.ceil(lo[0] - 0.5)), 0), min(int(np.floor(hi[0] - 0.5)), width - 1) + 1)
    rows = range(max(int(np.ceil(lo[1] - 0.5)), 0), min(int(np.floor(hi[1] - 0.5)), height - 1) + 1)
    for i in rows:
        for j in cols:
            centre = np.array([j + 0.5, i + 0.5])
            e = np.zeros(3)
            inside = True
            for k in range(3):
                e[k] = tr.edge_function(p[k], p[(k + 1) % 3], centre)
                if not (e[k] > 0 or (e[k] == 0 and top_left[k])):
                    inside = False
                    break  # bail out at the first failing test
            if not inside:
                continue
            coverage[i, j] = True
            lam = np.zeros(3)
            for k in range(3):  # the weight of oriented vertex k is the edge opposite it
                lam[order[k]] = e[(k + 1) % 3] / area
            q = lam / w
            mu = q / q.sum()
            for name, f in tri.attrs.items():
                attrs[name][i, j] = f[0] + mu[1] * (f[1] - f[0]) + mu[2] * (f[2] - f[0])
    return coverage, attrs


def python_loop_halfplane(tri: tr.Triangle, width: int, height: int):
    """Half-plane fill, one pixel at a time, in pure Python (snapped integer arithmetic).

    Bounding box; for each pixel centre the three edge tests in order with bail-out and the
    top-left rule; then perspective-correct barycentric interpolation of every attribute.
    Returns ``(coverage, attrs)`` like ``tr.rasterize(tri, width, height)``.
    """
    p, order, area2, tl, unit, half = _scalar_setup(tri)
    (x0, y0), (x1, y1), (x2, y2) = p
    tl0, tl1, tl2 = tl
    o0, o1, o2 = order
    shader = _Shader(tri, width, height)
    coverage = [False] * (width * height)
    xs, ys = [x for x, _ in p], [y for _, y in p]
    cols = _centre_range(min(xs), max(xs), half, unit, width)
    rows = _centre_range(min(ys), max(ys), half, unit, height)
    inv_area = 1.0 / area2 if area2 else 0.0
    for i in rows:
        py = i * unit + half
        for j in cols:
            px = j * unit + half
            e0 = (x1 - x0) * (py - y0) - (y1 - y0) * (px - x0)
            if e0 < 0 or (e0 == 0 and not tl0):
                continue
            e1 = (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)
            if e1 < 0 or (e1 == 0 and not tl1):
                continue
            e2 = (x0 - x2) * (py - y2) - (y0 - y2) * (px - x2)
            if e2 < 0 or (e2 == 0 and not tl2) or area2 == 0:
                continue
            index = i * width + j
            coverage[index] = True
            # The weight of oriented vertex k is the edge opposite it, E_{k+1}.
            lam = [0.0, 0.0, 0.0]
            lam[o0], lam[o1], lam[o2] = e1 * inv_area, e2 * inv_area, e0 * inv_area
            shader.shade(index, *lam)
    return np.array(coverage).reshape(height, width), shader.images()


def python_loop_span(tri: tr.Triangle, width: int, height: int):
    """Span-table fill in pure Python: span ends per raster line, then a per-pixel loop.

    Each row's span is narrowed by every edge whose closed y-range contains the row (an
    active edge table), solving that edge's test for the column exactly in integers with
    the top-left rule folded in; a horizontal edge keeps or drops its whole row. Covered
    pixels are interpolated as in :func:`python_loop_halfplane`.
    """
    p, order, area2, tl, unit, half = _scalar_setup(tri)
    o0, o1, o2 = order
    shader = _Shader(tri, width, height)
    coverage = [False] * (width * height)
    xs, ys = [x for x, _ in p], [y for _, y in p]
    cols = _centre_range(min(xs), max(xs), half, unit, width)
    rows = _centre_range(min(ys), max(ys), half, unit, height)
    edges = [(p[k], p[(k + 1) % 3], 0 if tl[k] else 1) for k in range(3)]
    inv_area = 1.0 / area2 if area2 else 0.0
    for i in rows:
        py = i * unit + half
        lo, hi = cols.start, cols.stop - 1
        for (ax, ay), (bx, by), bias in edges:
            if not min(ay, by) <= py <= max(ay, by):
                continue
            dx, dy = bx - ax, by - ay
            k = dx * (py - ay)  # E = k - dy * (X - ax) on this row; inside: E >= bias
            if dy == 0:
                hi = hi if k >= bias else lo - 1
            elif dy > 0:  # upper bound on X
                hi = min(hi, (ax + (k - bias) // dy - half) // unit)
            else:  # lower bound on X
                lo = max(lo, -((half - (ax - ((k - bias) // -dy))) // unit))
        if area2 == 0:
            continue
        for j in range(lo, hi + 1):
            px = j * unit + half
            e = [(bx - ax) * (py - ay) - (by - ay) * (px - ax) for (ax, ay), (bx, by), _ in edges]
            index = i * width + j
            coverage[index] = True
            lam = [0.0, 0.0, 0.0]
            lam[o0], lam[o1], lam[o2] = e[1] * inv_area, e[2] * inv_area, e[0] * inv_area
            shader.shade(index, *lam)
    return np.array(coverage).reshape(height, width), shader.images()


def check_same(name: str, loop_result, fill: tr.Fill) -> str:
    """Raise :class:`BenchmarkError` unless coverage is equal and attrs agree within 1e-9."""
    coverage, attrs = loop_result
    if not np.array_equal(coverage, fill.coverage):
        diff = int((coverage != fill.coverage).sum())
        raise BenchmarkError(f"{name}: coverage differs from tr.rasterize at {diff} pixels")
    worst = 0.0
    for key, ref in fill.attrs.items():
        got = attrs[key]
        if got.shape != ref.shape or not np.array_equal(np.isnan(got), np.isnan(ref)):
            raise BenchmarkError(f"{name}: attrs[{key!r}] shape or NaN pattern differs")
        inside = ~np.isnan(ref)
        worst = max(worst, float(np.abs(got[inside] - ref[inside]).max(initial=0.0)))
    if worst > ATTR_TOLERANCE:
        raise BenchmarkError(f"{name}: attrs differ by {worst:.3g} > {ATTR_TOLERANCE:g}")
    return f"same coverage ({int(coverage.sum())} px), attrs max |diff| {worst:.1e}"


# --------------------------------------------------------------------------------------------
# Measurements


def bench_fills(repeat: int) -> list[Row]:
    """Measurement 1: the 1024×1024 fills against the 0.2 s target."""
    tri = make_triangle(FILL_SIZE, FILL_SIZE)
    rows = []
    for method in METHODS:
        for mode in MODES:
            fn = fill_call(tri, FILL_SIZE, method, mode)
            t = median_seconds(fn, repeat)
            figures = f"{fmt_time(t):>10}  ({t / FILL_TARGET_S:.0%} of target)"
            label = f"fill {FILL_SIZE}² {method:<9} {mode:<11}"
            rows.append(Row(label, figures, f"< {FILL_TARGET_S:g} s", t < FILL_TARGET_S, fn))
    return rows


def bench_trace(repeat: int) -> list[Row]:
    """Measurement 2: ``trace=True`` over ``trace=False`` at each size, target ≤ 2×."""
    rows = []
    for size in TRACE_SIZES:
        tri = make_triangle(size, size)
        for method in METHODS:
            for mode in MODES:
                off = median_seconds(fill_call(tri, size, method, mode, False), repeat)
                on_fn = fill_call(tri, size, method, mode, True)
                on = median_seconds(on_fn, repeat)
                ratio = on / off
                figures = f"{fmt_time(off):>10} -> {fmt_time(on):>9}  = {ratio:.2f}x"
                label = f"trace {size}² {method:<9} {mode:<11}"
                rows.append(
                    Row(label, figures, f"<= {TRACE_TARGET:g}x", ratio <= TRACE_TARGET, on_fn)
                )
    return rows


def bench_loops(
    size: int, repeat: int, loop_repeat: int, baseline_size: int
) -> tuple[list[str], list[Row]]:
    """Measurement 3: per-pixel Python loops against the vectorised fill (checked first).

    The target applies to the straightforward loop (at ``baseline_size``, as it is slow);
    the hand-tuned loops are reported for comparison, against the same >= 100x line.
    """
    notes, rows = [], []
    loops = (
        ("halfplane", straightforward_halfplane, baseline_size),
        ("halfplane", python_loop_halfplane, size),
        ("span", python_loop_span, size),
    )
    for method, loop, size in loops:
        tri = make_triangle(size, size)
        fill = tr.rasterize(tri, size, size, method=method)
        notes.append(
            f"{loop.__name__} {size}²: {check_same(loop.__name__, loop(tri, size, size), fill)}"
        )
        t_loop = median_seconds(partial(loop, tri, size, size), loop_repeat, warmup=0)
        fn = fill_call(tri, size, method, "perspective")
        t_vec = median_seconds(fn, repeat)
        speedup = t_loop / t_vec
        figures = f"{fmt_time(t_loop):>10} vs {fmt_time(t_vec):>9}  = {speedup:,.0f}x"
        kind = "straightforward" if loop is straightforward_halfplane else "tuned pure-Python"
        label = f"loop {size}² {method:<9} {kind:<17}"
        if loop is straightforward_halfplane:
            rows.append(Row(label, figures, f">= {LOOP_TARGET:g}x", speedup >= LOOP_TARGET, fn))
        else:
            rows.append(Row(label, figures, "no target", None, fn))
    return notes, rows


# --------------------------------------------------------------------------------------------
# Report


def machine_info() -> list[str]:
    """Header lines: interpreter, numpy, teachraster, CPUs, platform."""
    try:
        usable = len(os.sched_getaffinity(0))
    except AttributeError:  # not on every platform
        usable = os.cpu_count()
    return [
        f"python {platform.python_version()} ({platform.python_implementation()}), "
        f"numpy {np.__version__}, teachraster {tr.__version__} ({Path(tr.__file__).parent})",
        f"cpu count {os.cpu_count()} (usable {usable}), {platform.machine()}, "
        f"{platform.platform(terse=True)}",
    ]


def triangle_info() -> str:
    """One line describing the benchmark triangle and its coverage."""
    tri = make_triangle(FILL_SIZE, FILL_SIZE)
    share = tr.rasterize(tri, FILL_SIZE, FILL_SIZE).coverage.mean()
    attrs = ", ".join(f"{k} {np.shape(v)}" for k, v in ATTRS.items())
    return (
        f"triangle: vertices at {list(TRI_FRACTIONS)} of (W, H), w = {list(W_PER_VERTEX)}, "
        f"attrs {attrs}; covers {share:.1%} of the image"
    )


def print_section(title: str, rows: list[Row]) -> None:
    """A titled block of rows: label, figures, target, PASS/MISS."""
    print(f"\n{title}")
    for row in rows:
        print(f"  {row.label}  {row.figures:<34}  {row.target:>9}  {row.verdict}")


def profile_rows(rows: list[Row], top: int = 8) -> None:
    """cProfile each missed row's call and print where its time goes (by own time)."""
    for row in rows:
        if row.passed is not False or row.fn is None:
            continue
        print(f"\nprofile of MISS '{row.label.strip()}' (top {top} by own time):")
        profiler = cProfile.Profile()
        profiler.runcall(row.fn)
        stats = pstats.Stats(profiler, stream=sys.stdout)
        stats.strip_dirs().sort_stats("tottime").print_stats(top)


def parse_args(argv: list[str] | None) -> argparse.Namespace:
    """Command-line options."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fast smoke run")
    parser.add_argument("--repeat", type=int, default=None, help="timed calls per figure")
    parser.add_argument("--loop-size", type=int, default=None, help="image size for the loops")
    parser.add_argument("--profile", action="store_true", help="cProfile each missed target")
    args = parser.parse_args(argv)
    if args.repeat is None:
        args.repeat = 2 if args.quick else 7
    if args.loop_size is None:
        args.loop_size = QUICK_LOOP_SIZE if args.quick else LOOP_SIZE
    if args.repeat < 1 or args.loop_size < 1:
        parser.error("--repeat and --loop-size must be positive")
    args.loop_repeat = 1 if args.quick else min(args.repeat, 3)
    return args


def main(argv: list[str] | None = None) -> int:
    """Run every measurement and print the report; 0 unless something went wrong."""
    args = parse_args(argv)
    print("teachraster fill benchmark" + (" (--quick)" if args.quick else ""))
    for line in machine_info():
        print(line)
    print(triangle_info())
    print(
        f"figures: median of {args.repeat} timed calls after 1 warm-up (time.perf_counter); "
        f"Python loops: median of {args.loop_repeat}"
    )
    try:
        fills = bench_fills(args.repeat)
        print_section(f"1. fill time, {FILL_SIZE}x{FILL_SIZE}, trace=False", fills)
        traces = bench_trace(args.repeat)
        print_section("2. trace recording cost: trace=False -> trace=True", traces)
        baseline = QUICK_BASELINE_SIZE if args.quick else BASELINE_SIZE
        notes, loops = bench_loops(args.loop_size, args.repeat, args.loop_repeat, baseline)
        print_section("3. per-pixel Python loop vs tr.rasterize (speed-up)", loops)
        for note in notes:
            print(f"     check: {note}")
    except BenchmarkError as exc:
        print(f"\nERROR: {exc}", file=sys.stderr)
        return 1
    rows = fills + traces + loops
    missed = sum(row.passed is False for row in rows)
    passed = sum(row.passed is True for row in rows)
    print(
        f"\n{passed} PASS, {missed} MISS "
        "(targets are informative; speed never sets the exit status)"
    )
    if args.profile:
        profile_rows(rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
