"""The signs of numpy's times in lesson 06's study, measured: PASS/MISS per claim, never a test.

Lesson 06 (*What accuracy costs*) prices its variants in operations and leaves the time of this
simulator's numpy code to this script (review r238 S1: the time describes neither the Pentium
nor a GPU). The claims, with the reason: subdivided interpolation is slower than the exact
divide at every N (the same array passes on its anchors, and more); incremental edge
evaluation is slower than direct in every arithmetic (a cumulative sum besides the products);
affine, which saves a few passes of many, is faster than perspective-correct but takes most of
its time, nowhere near the cycle model's ratio (review r60 06-2: runs gave 0.77 to 0.86). The
same per-pass reading explains the fill times: a textured fill's time is mostly its uv
interpolation, coverage a small part, and the two fills' coverages differ by far less than
their operation counts (20x or more). Times are CPU time of this process, the fastest of
interleaved rounds: waiting for a core is not counted (reviews r17 06-1..3, r20 06-1..4).
Speed is a benchmark's business, not a test's: the suite only runs this script's smoke run
(``--quick``), which checks that every claim is reported.

    python benchmarks/bench_lesson06_signs.py            # 9 rounds at the lesson's 256 px
    python benchmarks/bench_lesson06_signs.py --quick    # smoke run: 64 px, 2 rounds

The exit status is non-zero only on errors, never on a MISS.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import teachraster as tr  # noqa: E402
from teachraster.study import bench, precision  # noqa: E402
from teachraster.study.bench import timing  # noqa: E402


def fastest(fns, rounds: int) -> list[float]:
    """The fastest of ``rounds`` interleaved runs of each fn, in this process's CPU time."""
    return [min(t) for t in timing.time_samples(fns, rounds, clock=time.process_time)]


def claims(size: int, rounds: int) -> list[tuple[str, bool, str]]:
    """(claim, holds, the times behind it) for each sign lesson 06 states."""
    xy, w, uv = bench.floor_quad(size)
    tris = [tr.Triangle(xy[t], w=w[t], attrs={"uv": uv[t]}) for t in range(2)]

    def interp(mode, n=1):
        return lambda: [tr.rasterize(t, size, size, interpolation=mode, subdivision=n)
                        for t in tris]  # fmt: skip

    affine, exact, *sub = fastest([interp("affine"), interp("perspective")]
                                  + [interp("subdivided", n) for n in bench.SUBDIVISIONS], rounds)  # fmt: skip
    ms = lambda s: f"{s * 1e3:.2f} ms"  # noqa: E731
    out = [
        ("affine faster than perspective-correct, but above half its time (model: 2/39)",
         exact / 2 < affine < exact, f"{ms(affine)} vs {ms(exact)}")
    ]  # fmt: skip
    for n, t in zip(bench.SUBDIVISIONS, sub):
        out.append(
            (f"subdivided N={n} slower than the exact divide", t > exact, f"{ms(t)} vs {ms(exact)}")
        )
    edge_tris = bench.random_triangles(size)
    for arith in precision.ARITHMETICS:
        direct, incremental = fastest(
            [lambda ev=ev, a=arith: [precision.coverage(t, size, size, a, ev) for t in edge_tris]
             for ev in ("direct", "incremental")], rounds)  # fmt: skip
        out.append((f"incremental edges slower than direct ({arith})", incremental > direct,
                    f"{ms(incremental)} vs {ms(direct)}"))  # fmt: skip
    for n in (size, 2 * size):
        tri = bench.fill_triangle(n)
        parts = {}
        for method in ("halfplane", "span"):
            whole, parts[method] = fastest([lambda t=t, n=n, m=method: tr.rasterize(t, n, n, method=m)
                                            for t in (tri, tr.Triangle(tri.xy))], rounds)  # fmt: skip
            out.append((f"coverage under half the textured fill ({method}, {n}²)",
                        parts[method] < whole / 2, f"{ms(parts[method])} of {ms(whole)}"))  # fmt: skip
        hp, sp = parts["halfplane"], parts["span"]
        out.append((f"half-planes' coverage under 20x the span's ({n}²)", hp < 20 * sp,
                    f"{ms(hp)} vs {ms(sp)}"))  # fmt: skip
    return out


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smoke run: 64 px, 2 rounds")
    args = parser.parse_args(argv)
    size, rounds = (64, 2) if args.quick else (256, 9)
    rows = claims(size, rounds)
    width = max(len(c) for c, _, _ in rows)
    for claim, holds, times in rows:
        print(f"{claim:<{width}}  {'PASS' if holds else 'MISS'}  {times}")
    print(
        f"{sum(h for _, h, _ in rows)} of {len(rows)} claims hold ({size} px, fastest of {rounds})"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
