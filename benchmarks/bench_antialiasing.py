"""Benchmark antialiasing: error and time per sample count and pattern, and MSAA on the sphere.

    python benchmarks/bench_antialiasing.py            # full run
    python benchmarks/bench_antialiasing.py --quick    # smoke run

1. The sample-count study (:func:`teachraster.study.antialiasing.sample_error_study`): for
   1, 2, 4, 8, 16 samples and each pattern kind, the mean and max absolute error of
   ``fill.coverage_fraction`` against the exact area of the (snapped) triangle in each pixel,
   and the median time of ``tr.rasterize`` of the study's 12 triangles.
2. The ~20,000-triangle UV sphere of ``bench_scenes.py`` at 1024² (uv attribute, depth test
   on): ``tr.render`` with ``samples=1`` and ``samples=4`` timed round-robin in the same run
   (medians), their ratio (the target is at most 2x, thanks to per-sample work only where a
   pixel's samples can differ), the plan's ``multisampling`` line, and llvmpipe drawing the
   same triangles into a 4-sample framebuffer (draw + reading every sample back with
   ``texelFetch``) next to its 1-sample draw; and how many samples show the same triangle.
   A multisampled frame keeps its per-sample arrays compressed (one triangle per pixel
   decided whole, single samples where the per-sample test ran) and expands them on first
   read, so ``samples=4`` is also timed with ``sample_triangle_id``, ``sample_depth`` and
   ``sample_attrs`` all read (the (1024, 1024, 4[, 2]) arrays built).
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
sys.path.insert(0, str(Path(__file__).resolve().parent))  # the sibling bench_scenes

from bench_scenes import sphere_scene  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.study.antialiasing import sample_error_study  # noqa: E402

RATIO_TARGET = 2.0


def interleaved(fns, repeat: int) -> list[float]:
    """Median seconds of each function, timed round-robin (a busy machine slows them alike)."""
    for fn in fns:
        fn()
    times = [[] for _ in fns]
    for _ in range(repeat):
        for k, fn in enumerate(fns):
            t0 = time.perf_counter()
            fn()
            times[k].append(time.perf_counter() - t0)
    return [statistics.median(t) for t in times]


def bench_study(size: int, repeat: int) -> None:
    print(f"1. coverage fraction vs exact pixel area ({size}x{size}, 12 triangles)")
    print(f"  {'pattern':<10}{'samples':>8}{'mean |err|':>12}{'max |err|':>11}{'time':>10}")
    for r in sample_error_study(size=size, repeat=repeat):
        print(f"  {r['kind']:<10}{r['samples']:>8}{r['mean_error']:>12.4f}"
              f"{r['max_error']:>11.3f}{r['time_s'] * 1e3:>8.1f} ms")  # fmt: skip


def bench_sphere(size: int, repeat: int) -> int:
    clip, uv = sphere_scene()
    print(f"\n2. UV sphere: {len(clip):,} triangles, {size}x{size}, uv, depth test on")

    def expanded():  # the render, then every per-sample array read (built on first read)
        f = tr.render(clip, size, size, attrs=uv, samples=4)
        return f.sample_triangle_id, f.sample_depth, f.sample_attrs

    one, four, full = interleaved(
        [lambda: tr.render(clip, size, size, attrs=uv),
         lambda: tr.render(clip, size, size, attrs=uv, samples=4), expanded], repeat,
    )  # fmt: skip
    ratio = four / one
    frame = tr.render(clip, size, size, attrs=uv, samples=4)
    print(f"  teachraster samples=1  {one * 1e3:8.1f} ms")
    print(f"  teachraster samples=4  {four * 1e3:8.1f} ms   ratio {ratio:.2f} "
          f"(target <= {RATIO_TARGET:g}: {'PASS' if ratio <= RATIO_TARGET else 'MISS'})")  # fmt: skip
    print(f"    + per-sample arrays read {full * 1e3:8.1f} ms   ratio {full / one:.2f}")
    effect = frame.plan["multisampling"]
    print(f"  per-sample work at {effect.count:,} of {effect.total:,} covered pixels "
          f"({effect.count / max(effect.total, 1):.1%})")  # fmt: skip
    from teachraster.study.opengl import gl_available, gl_render, gl_render_samples

    ok, why = gl_available()
    if not ok:
        print(f"  llvmpipe: skipped ({why})")
        return 0
    gl1, gl4 = interleaved(
        [lambda: gl_render(clip, size, size, attrs=uv),
         lambda: gl_render_samples(clip, size, size, samples=4)], repeat,
    )  # fmt: skip
    print(f"  llvmpipe 1 sample (upload, draw, read id/uv/depth)   {gl1 * 1e3:8.1f} ms")
    print(f"  llvmpipe 4 samples (upload, draw, read every sample) {gl4 * 1e3:8.1f} ms")
    same = gl_render_samples(clip, size, size, samples=4).sample_triangle_id
    agree = float((same == frame.sample_triangle_id).mean())
    print(f"  same triangle as llvmpipe at {agree:.4%} of the samples")
    return 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small sizes, for a smoke run")
    parser.add_argument("--repeat", type=int, default=None, help="timed runs per figure")
    args = parser.parse_args(argv)
    repeat = args.repeat or (1 if args.quick else 7)
    bench_study(24 if args.quick else 48, repeat)
    return bench_sphere(256 if args.quick else 1024, repeat)


if __name__ == "__main__":
    sys.exit(main())
