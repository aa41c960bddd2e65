"""Benchmark the scene pipeline: what the plan saves per scene, and a 20k-triangle sphere
side by side with OpenGL's llvmpipe.

    python benchmarks/bench_scenes.py            # full run
    python benchmarks/bench_scenes.py --quick    # smoke run
    python benchmarks/bench_scenes.py --profile  # also: where the sphere's time goes

1. Every built-in scene rendered as planned (``tr.render(scene, None, W, H)``) and with every
   effect forced on (``force="all"``): medians and the time the plan saves.
2. A UV sphere of about 20,000 triangles filling a 1024×1024 image (perspective camera, one
   texture-coordinate attribute, depth test on): ``tr.render`` against llvmpipe (upload,
   draw and read-back of float32 targets, in the same run), and their ratio. Skipped with a
   reason where no OpenGL context can be made.
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the sibling bench_fill

from bench_fill import median_seconds  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.pipeline.scenes import uv_sphere  # noqa: E402

SPHERE_TARGET = 10.0  # within 10x of llvmpipe


def bench_plan(width: int, height: int, repeat: int) -> None:
    """Section 1: planned vs everything-on, per built-in scene."""
    print(f"\n1. the plan per built-in scene, {width}x{height}: planned vs force='all'")
    print(f"  {'scene':<24}{'planned':>10}{'all on':>10}{'saved':>8}  skipped by the plan")
    for name in tr.SCENES:
        scene = tr.get_scene(name)
        planned = median_seconds(lambda s=scene: tr.render(s, None, width, height), repeat)
        forced = median_seconds(
            lambda s=scene: tr.render(s, None, width, height, force="all"), repeat
        )
        plan = tr.render(scene, None, width, height).plan
        skipped = ", ".join(e.name for e in plan if not e.ran) or "-"
        print(
            f"  {name:<24}{planned * 1e3:>8.1f}ms{forced * 1e3:>8.1f}ms"
            f"{1 - planned / forced:>8.0%}  {skipped}"
        )


def sphere_scene(n_lat: int = 100, n_lon: int = 100):
    """A UV sphere of 2 n_lat n_lon - 2 n_lon triangles filling a square image."""
    scene = uv_sphere(n_lat=n_lat, n_lon=n_lon)
    camera = tr.Camera(eye=(0.0, 0.3, 2.15), target=(0.0, 0.0, 0.0), fov_y=60.0, near=0.5, far=10)
    clip = camera.clip(scene.mesh.corner_positions(), 1.0)
    return clip, scene.mesh.corner("uv")


def bench_sphere(size: int, repeat: int, profile: bool) -> None:
    """Section 2: the sphere, ours against llvmpipe in the same run."""
    clip, uv = sphere_scene()
    frame = tr.render(clip, size, size, attrs=uv)
    print(
        f"\n2. UV sphere: {len(clip):,} triangles, {size}x{size}, uv attribute, depth test on; "
        f"covers {frame.coverage.mean():.0%} of the image"
    )
    ours = median_seconds(lambda: tr.render(clip, size, size, attrs=uv), repeat)
    print(f"  teachraster tr.render       {ours * 1e3:8.1f} ms")
    from teachraster.study.opengl import gl_available, gl_render

    ok, why = gl_available()
    if not ok:
        print(f"  llvmpipe                    skipped: {why}")
    else:
        gl = median_seconds(lambda: gl_render(clip, size, size, attrs=uv), repeat)
        ratio = ours / gl
        verdict = "PASS" if ratio <= SPHERE_TARGET else "MISS"
        print(f"  llvmpipe (moderngl, {why[:30]})  {gl * 1e3:8.1f} ms")
        print(
            f"  ratio ours / llvmpipe       {ratio:8.1f}x   target <= {SPHERE_TARGET:g}x  {verdict}"
        )
        same = (gl_render(clip, size, size, attrs=uv).triangle_id == frame.triangle_id).mean()
        print(f"  triangle ids identical at {same:.4%} of pixels")
    if profile:
        print("\n  where teachraster's time goes (cProfile, top 10 by own time):")
        profiler = cProfile.Profile()
        profiler.runcall(tr.render, clip, size, size, attrs=uv)
        pstats.Stats(profiler, stream=sys.stdout).strip_dirs().sort_stats("tottime").print_stats(10)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fast smoke run")
    parser.add_argument("--repeat", type=int, default=None)
    parser.add_argument("--profile", action="store_true")
    args = parser.parse_args(argv)
    repeat = args.repeat or (1 if args.quick else 5)
    print("teachraster scene benchmark" + (" (--quick)" if args.quick else ""))
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}; medians of {repeat}")
    bench_plan(160 if args.quick else 640, 120 if args.quick else 480, repeat)
    bench_sphere(256 if args.quick else 1024, repeat, args.profile)
    return 0


if __name__ == "__main__":
    sys.exit(main())
