"""Benchmark the scene pipeline: what the plan saves, how the cost scales, and llvmpipe beside it.

    python benchmarks/bench_scenes.py            # full run
    python benchmarks/bench_scenes.py --quick    # smoke run
    python benchmarks/bench_scenes.py --profile  # also: where the sphere's time goes

1. Every built-in scene rendered as planned (``tr.render(scene, None, W, H)``) and with every
   effect forced on (``force="all"``): medians, their ratio, and the planning overhead of the
   single-triangle scene (target: the plan costs < 10 % of the render, i.e. planned <= 1.1×
   all-on).
2. A UV sphere of about 20,000 triangles filling a 1024×1024 image (perspective camera, one
   texture-coordinate attribute, depth test on): ``tr.render`` against llvmpipe (upload,
   draw and read-back of float32 targets), timed *in turn* and the ratio taken pair by
   pair (median of the per-pair ratios; target <= 3×). Skipped with a reason where no
   OpenGL context can be made.
3. The all-clipped scene: 20,000 thin triangles that each cross the near plane (256×256,
   depth test, two attributes) against the same triangles cut at the near plane beforehand
   and fanned (the fragments are identical; target ratio <= 1.5), with llvmpipe drawing
   the uncut triangles.
4. Depth complexity: the same number of fragments as L layers of quads stacked on one spot,
   L = 16 ... 4096 (256×256); the z-buffer resolves in one pass, so the time must stay flat
   (target: slowest / fastest <= 2× with Hi-Z switched off, so that every layer count runs
   the same resolve; as planned, Hi-Z only makes the shallow stacks faster), with llvmpipe
   beside it.
5. Hi-Z: the planned render against the same render with Hi-Z switched off (the hook
   patched out), timed in turn, on the depth-complexity sweep, the overlap scenes at
   640×480 and 1920×1080 and the sphere; with the fragments Hi-Z rejected (planned and
   forced) and whether the plan ran it (target: faster wherever it runs, and no slower
   where it is skipped).
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

sys.path.insert(0, str(Path(__file__).resolve().parent))  # the sibling bench_fill

from bench_fill import median_seconds  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.pipeline.clipping import clip_triangles  # noqa: E402
from teachraster.pipeline.scenes import uv_sphere  # noqa: E402

SPHERE_TARGET = 3.0  # within 3x of llvmpipe
CLIP_TARGET = 1.5  # clipped / pre-cut
FLAT_TARGET = 2.0  # slowest / fastest of the depth-complexity sweep
PLAN_TARGET = 1.1  # planned / all-on on the single-triangle scene


def in_turn(fns, repeat: int) -> list[list[float]]:
    """Seconds of each of ``fns``, called in turn ``repeat`` times (after one warm-up each).

    Taking the runs in turn exposes every function to the same load on a shared machine,
    so the ratio of two of them is best taken pair by pair (see :func:`pair_ratio`).
    """
    for fn in fns:
        fn()
    times = [[] for _ in fns]
    for _ in range(repeat):
        for fn, out in zip(fns, times):
            start = time.perf_counter()
            fn()
            out.append(time.perf_counter() - start)
    return times


def cpu_seconds(fn, repeat: int) -> float:
    """Median CPU time of this process for ``fn()`` (``time.process_time``): on a machine
    shared with other jobs it moves much less than wall time (llvmpipe's worker threads
    count too, so it is no fair basis for comparing with GL)."""
    fn()
    times = []
    for _ in range(repeat):
        start = time.process_time()
        fn()
        times.append(time.process_time() - start)
    return statistics.median(times)


def pair_ratio(a: list[float], b: list[float]) -> float:
    """Median of the per-run ratios a[i] / b[i]."""
    return statistics.median(x / y for x, y in zip(a, b))


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
    scene = tr.get_scene("single_triangle")
    a, b = in_turn(
        [
            lambda: tr.render(scene, None, width, height),
            lambda: tr.render(scene, None, width, height, force="all"),
        ],
        max(repeat * 4, 5),
    )
    ratio = pair_ratio(a, b)
    verdict = "PASS" if ratio <= PLAN_TARGET else "MISS"
    print(
        f"  single_triangle in turn: planned {statistics.median(a) * 1e3:.1f} ms, all on "
        f"{statistics.median(b) * 1e3:.1f} ms, ratio {ratio:.2f}  target <= {PLAN_TARGET}  "
        f"{verdict}"
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
    from teachraster.study.opengl import gl_available, gl_render

    ok, why = gl_available()
    if not ok:
        ours = median_seconds(lambda: tr.render(clip, size, size, attrs=uv), repeat)
        print(f"  teachraster tr.render       {ours * 1e3:8.1f} ms")
        print(f"  llvmpipe                    skipped: {why}")
    else:
        mine, gl = in_turn(
            [
                lambda: tr.render(clip, size, size, attrs=uv),
                lambda: gl_render(clip, size, size, attrs=uv),
            ],
            repeat,
        )
        ratio = pair_ratio(mine, gl)
        verdict = "PASS" if ratio <= SPHERE_TARGET else "MISS"
        print(f"  teachraster tr.render       {statistics.median(mine) * 1e3:8.1f} ms")
        print(f"  llvmpipe (moderngl, {why[:30]})  {statistics.median(gl) * 1e3:8.1f} ms")
        print(
            f"  ratio ours / llvmpipe       {ratio:8.1f}x   (median of {repeat} pairs taken in "
            f"turn)  target <= {SPHERE_TARGET:g}x  {verdict}"
        )
        same = (gl_render(clip, size, size, attrs=uv).triangle_id == frame.triangle_id).mean()
        print(f"  triangle ids identical at {same:.4%} of pixels")
    if profile:
        print("\n  where teachraster's time goes (cProfile, top 10 by own time):")
        profiler = cProfile.Profile()
        profiler.runcall(tr.render, clip, size, size, attrs=uv)
        pstats.Stats(profiler, stream=sys.stdout).strip_dirs().sort_stats("tottime").print_stats(10)


def thin_crossing_triangles(n: int = 20_000, seed: int = 0):
    """``n`` thin triangles that each cross the near plane (two vertices in front of the
    camera, one behind the eye), in clip space, with two attributes each."""
    rng = np.random.default_rng(seed)
    proj = tr.perspective(60.0, 1.0, 0.1, 10.0)
    centre = rng.uniform(-1, 1, (n, 1, 2))
    view = np.zeros((n, 3, 4))
    view[..., 3] = 1.0
    view[:, :2, :2] = centre + rng.normal(0, 0.02, (n, 2, 2))
    view[:, :2, 2] = rng.uniform(-3, -1, (n, 2))
    view[:, 2, :2] = 0.05 * centre[:, 0]
    view[:, 2, 2] = 0.5  # behind the eye
    return view @ proj.T, rng.uniform(0, 1, (n, 3, 2))


def bench_clipped(size: int, n: int, repeat: int) -> None:
    """Section 3: the all-clipped scene against the same triangles cut beforehand."""
    clip, attrs = thin_crossing_triangles(n)
    cut = clip_triangles(clip, attrs)
    frame = tr.render(clip, size, size, attrs=attrs)
    same = (frame.triangle_id >= 0) == tr.render(cut.clip, size, size, attrs=cut.attrs).coverage
    print(
        f"\n3. all clipped: {n:,} thin triangles each crossing the near plane, {size}x{size}, "
        f"2 attributes, depth test; pre-cut: {len(cut.clip):,} triangles; same coverage "
        f"{same.all()}"
    )
    fns = [
        lambda: tr.render(clip, size, size, attrs=attrs),
        lambda: tr.render(cut.clip, size, size, attrs=cut.attrs),
    ]
    from teachraster.study.opengl import gl_available, gl_render

    ok, why = gl_available()
    if ok:
        fns.append(lambda: gl_render(clip, size, size, attrs=attrs))
    times = in_turn(fns, repeat)
    ratio = pair_ratio(times[0], times[1])
    verdict = "PASS" if ratio <= CLIP_TARGET else "MISS"
    print(f"  clipped by tr.render        {statistics.median(times[0]) * 1e3:8.1f} ms")
    print(f"  cut beforehand and fanned   {statistics.median(times[1]) * 1e3:8.1f} ms")
    print(f"  ratio clipped / pre-cut     {ratio:8.2f}x   target <= {CLIP_TARGET}  {verdict}")
    if ok:
        print(
            f"  llvmpipe (clips itself)     {statistics.median(times[2]) * 1e3:8.1f} ms   "
            f"ours / llvmpipe {pair_ratio(times[0], times[2]):.1f}x"
        )
    else:
        print(f"  llvmpipe                    skipped: {why}")


def stacked_quads(layers: int, size: int, seed: int = 0) -> np.ndarray:
    """``layers`` squares (two triangles each) on one spot at random depths, covering
    ``size**2 / layers * 16`` pixels each: always 16 full images' worth of fragments."""
    rng = np.random.default_rng(seed)
    side = size * 4 / np.sqrt(layers)  # pixels per side: layers * side**2 = 16 size**2
    half = side / size  # in NDC: the square spans [-half, half] around the centre
    x0, x1 = -min(half, 1.0), min(half, 1.0)
    z = rng.uniform(-0.9, 0.9, layers)
    quad = np.array([[x0, x0], [x1, x0], [x1, x1], [x0, x1]])
    tris = quad[[[0, 1, 2], [0, 2, 3]]]  # (2, 3, 2)
    out = np.zeros((layers, 2, 3, 4))
    out[..., :2] = tris
    out[..., 2] = z[:, None, None]
    out[..., 3] = 1.0
    return out.reshape(-1, 3, 4)


def bench_depth_complexity(size: int, repeat: int, sweep) -> None:
    """Section 4: the same fragments as 16 ... 4096 layers on one spot."""
    from teachraster.study.opengl import gl_available, gl_render

    ok, why = gl_available()
    print(
        f"\n4. depth complexity, {size}x{size}, depth test on, 16 images' worth of fragments "
        "stacked L deep"
    )
    print(
        f"  {'layers':>7}{'triangles':>11}{'fragments':>12}{'ours':>10}{'(cpu)':>9}{'no Hi-Z':>10}"
        f"{'llvmpipe':>10}{'ratio':>8}"
    )
    # Every layer count (ours and llvmpipe) is timed in one rotation, so the load of a
    # shared machine falls on all of them alike and the spread measures the renderer.
    clips = [stacked_quads(layers, size) for layers in sweep]
    fns = [lambda c=c: tr.render(c, size, size) for c in clips]
    fns += [lambda c=c: _without_hiz(c, size, size) for c in clips]
    if ok:
        fns += [lambda c=c: gl_render(c, size, size) for c in clips]
    times = in_turn(fns, repeat)
    ours = [statistics.median(t) for t in times[: len(clips)]]
    no_hiz = [statistics.median(t) for t in times[len(clips) : 2 * len(clips)]]
    times = times[: len(clips)] + times[2 * len(clips) :]
    cpu = [cpu_seconds(fn, repeat) for fn in fns[: len(clips)]]
    for i, (layers, clip) in enumerate(zip(sweep, clips)):
        fragments = len(tr.render(clip, size, size, trace=True).trace.fragment_row)
        gl, ratio = "       -  ", "      -"
        if ok:
            gl_times = times[len(clips) + i]
            gl = f"{statistics.median(gl_times) * 1e3:8.1f}ms"
            ratio = f"{pair_ratio(times[i], gl_times):7.1f}x"
        print(
            f"  {layers:>7}{len(clip):>11,}{fragments:>12,}"
            f"{ours[i] * 1e3:>8.1f}ms{cpu[i] * 1e3:>7.1f}ms{no_hiz[i] * 1e3:>8.1f}ms{gl}{ratio}"
        )
    # The target is the z-buffer's: with Hi-Z switched off every layer count runs the same
    # one-pass resolve. As planned, Hi-Z makes the shallow stacks faster still (section 5),
    # which widens the spread from below without making any case slower.
    flat = max(no_hiz) / min(no_hiz)
    print(
        f"  slowest / fastest, Hi-Z off {flat:8.2f}x   target <= {FLAT_TARGET}  "
        f"{'PASS' if flat <= FLAT_TARGET else 'MISS'}  (the one-pass z-buffer)"
    )
    print(f"  the same in CPU time, planned {max(cpu) / min(cpu):6.2f}x   (less sensitive to load)")
    worse = max(o / n for o, n in zip(ours, no_hiz))
    print(
        f"  as planned (Hi-Z where it pays) {max(ours) / min(ours):4.2f}x: shallow stacks faster, "
        f"none slower than without Hi-Z by more than {max(worse - 1, 0):.0%}"
    )
    if not ok:
        print(f"  llvmpipe                    skipped: {why}")


def _without_hiz(clip, width, height, **kw):
    """``tr.render`` with the Hi-Z hook patched out: the frame is the same, only the work
    differs (what the render would cost without Hi-Z)."""
    from unittest import mock

    import teachraster.pipeline.render_triangles as rt

    with mock.patch.object(rt, "HiZCut", lambda *a, **k: None):
        return tr.render(clip, width, height, **kw)


def hiz_cases(quick: bool):
    """(name, clip, width, height, attrs) of section 5."""
    # --quick is a smoke run (the tests run it): every section, at its smallest size
    sweep = (4, 16) if quick else (16, 64, 256, 1024, 4096)
    side = 64 if quick else 256
    cases = [
        (f"{n} stacked layers {side}²", stacked_quads(n, side), side, side, None) for n in sweep
    ]
    sizes = [(64, 48)] if quick else [(640, 480), (1920, 1080)]
    for name in ("cube", "cyclic_overlap", "intersecting_triangles", "uv_sphere"):
        scene = tr.get_scene(name)
        for w, h in sizes:
            cases.append((f"{name} {w}x{h}", scene.clip(w / h), w, h, None))
    if not quick:
        clip, uv = sphere_scene()
        cases.append(("sphere 20k 1024²", clip, 1024, 1024, uv))
    return cases


def bench_hiz(repeat: int, quick: bool) -> None:
    """Section 5: planned (with Hi-Z where the plan runs it) against Hi-Z switched off."""
    print("\n5. Hi-Z: the planned render against Hi-Z switched off (timed in turn)")
    print(
        f"  {'scene':<34}{'fragments':>11}{'rejected':>10}{'(forced)':>10}"
        f"{'planned':>10}{'off':>10}{'ratio':>7}  plan"
    )
    for name, clip, width, height, attrs in hiz_cases(quick):
        plan = tr.render(clip, width, height, attrs=attrs).plan["hi_z"]
        forced = tr.render(clip, width, height, attrs=attrs, force="hi_z").plan["hi_z"]
        on, off = in_turn(
            [
                lambda c=clip, w=width, h=height, a=attrs: tr.render(c, w, h, attrs=a),
                lambda c=clip, w=width, h=height, a=attrs: _without_hiz(c, w, h, attrs=a),
            ],
            repeat,
        )
        print(
            f"  {name:<34}{plan.total:>11,}{plan.count:>10,}{forced.count:>10,}"
            f"{statistics.median(on) * 1e3:>8.1f}ms{statistics.median(off) * 1e3:>8.1f}ms"
            f"{pair_ratio(on, off):>7.2f}  {'ran' if plan.ran else 'skipped'}"
        )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fast smoke run")
    parser.add_argument("--repeat", type=int, default=None)
    parser.add_argument("--profile", action="store_true")
    args = parser.parse_args(argv)
    repeat = args.repeat or (1 if args.quick else 5)
    print("teachraster scene benchmark" + (" (--quick)" if args.quick else ""))
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}; medians of {repeat}")
    # --quick is a smoke run (the tests run it): every section, at its smallest size
    bench_plan(64 if args.quick else 640, 48 if args.quick else 480, repeat)
    bench_sphere(64 if args.quick else 1024, repeat, args.profile)
    bench_clipped(64 if args.quick else 256, 200 if args.quick else 20_000, repeat)
    sweep = (4, 16) if args.quick else (16, 64, 256, 1024, 4096)
    bench_depth_complexity(64 if args.quick else 256, repeat, sweep)
    bench_hiz(repeat if args.quick else repeat * 2, args.quick)
    return 0


if __name__ == "__main__":
    sys.exit(main())
