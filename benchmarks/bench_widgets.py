"""Benchmark the widgets' latency (kernel side) and print medians against the targets.

Run from anywhere (the repository root is put on ``sys.path``)::

    python benchmarks/bench_widgets.py            # full run (a few seconds)
    python benchmarks/bench_widgets.py --quick    # smoke run
    python benchmarks/bench_widgets.py --repeat 101

Measurements (medians of ``--repeat`` changes, after one warm-up, Agg canvas, PNG mode):

1. Step slider: from setting ``FillPlayer.slider.value = k`` to ``fig.canvas.draw()`` having
   finished, on a 32×32 grid, for span tables and half-planes (steps cycling through the
   fill). Target: under 30 ms. Shown too: the time until the PNG for the browser is ready.
2. Vertex: from setting one vertex slider of a ``TriangleEditor`` (32×32) to both figures
   (fill with the split, and the error heatmap) being drawn, re-rasterising included.
   Target: under 100 ms.
3. For information: a tilt change of the ``TexturedPlaneViewer`` (160×120, two renders).

Targets are reported as PASS/MISS; the exit status is non-zero only on errors.
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

import matplotlib  # noqa: E402

matplotlib.use("Agg")

import teachraster as tr  # noqa: E402
from teachraster.widgets import FillPlayer, TexturedPlaneViewer, TriangleEditor  # noqa: E402

SIZE = 32
STEP_TARGET_MS = 30.0
VERTEX_TARGET_MS = 100.0
#: A triangle over most of the 32×32 grid, with different w (the heatmap has work to do).
TRI = tr.Triangle([[2.3, 1.7], [29.6, 9.1], [9.2, 30.4]], w=[1.0, 3.0, 6.0],
                  attrs={"u": [0.0, 1.0, 0.0]})  # fmt: skip


class DrawClock:
    """Records when the last ``canvas.draw()`` of some figures finished."""

    def __init__(self, *figs) -> None:
        self.done = 0.0
        for fig in figs:
            canvas = fig.canvas
            draw = canvas.draw

            def timed(*args, _draw=draw, **kwargs):
                _draw(*args, **kwargs)
                self.done = time.perf_counter()

            canvas.draw = timed


def time_changes(set_value, values, clock: DrawClock) -> tuple[list[float], list[float]]:
    """Per change: ms until the last draw finished, and ms until the setter returned."""
    drawn, total = [], []
    for v in values:
        t0 = time.perf_counter()
        set_value(v)
        t1 = time.perf_counter()
        drawn.append((clock.done - t0) * 1e3)
        total.append((t1 - t0) * 1e3)
    return drawn, total


def verdict(ms: float, target: float) -> str:
    return "PASS" if ms < target else "MISS"


def bench_steps(method: str, repeat: int) -> tuple[float, float, int]:
    player = FillPlayer(TRI, SIZE, SIZE, method=method, backend="image")
    clock = DrawClock(player.fig)
    n = player.slider.max + 1
    # every step kind (set-up, work, interpolation), spread over the whole fill
    values = [(i * 7 + 1) % n for i in range(repeat + 1)]

    def set_step(k):
        player.slider.value = k if k != player.slider.value else (k + 1) % n

    drawn, total = time_changes(set_step, values, clock)
    player.close()
    return statistics.median(drawn[1:]), statistics.median(total[1:]), n


def bench_vertex(repeat: int) -> tuple[float, float]:
    editor = TriangleEditor(TRI, SIZE, SIZE, backend="image")
    clock = DrawClock(editor.fig, editor.interp_view.fig)
    xs = [20.0 + 8.0 * ((i * 37) % 100) / 100 for i in range(repeat + 1)]

    def set_x(x):
        editor.x[1].value = x

    drawn, total = time_changes(set_x, xs, clock)
    editor.close()
    return statistics.median(drawn[1:]), statistics.median(total[1:])


def bench_tilt(repeat: int) -> tuple[float, float]:
    viewer = TexturedPlaneViewer(160, 120, tilt=10.0, backend="image")
    clock = DrawClock(viewer.fig)
    tilts = [5.0 + (i * 13) % 85 for i in range(repeat + 1)]

    def set_tilt(t):
        viewer.tilt.value = t if t != viewer.tilt.value else t + 1.0

    drawn, total = time_changes(set_tilt, tilts, clock)
    viewer.close()
    return statistics.median(drawn[1:]), statistics.median(total[1:])


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=41, help="timed changes per figure")
    parser.add_argument("--quick", action="store_true", help="smoke run: few repeats")
    args = parser.parse_args(argv)
    repeat = 5 if args.quick else max(args.repeat, 3)

    print(f"teachraster widget latency, kernel side, Agg, PNG mode; median of {repeat} changes")
    print(f"{'what':<44}{'drawn':>10}{'+ PNG':>10}  target")
    for method in ("span", "halfplane"):
        drawn, total, n = bench_steps(method, repeat)
        label = f"step slider, {method} ({n} steps, {SIZE}x{SIZE})"
        print(f"{label:<44}{drawn:>8.1f}ms{total:>8.1f}ms  < {STEP_TARGET_MS:.0f} ms "
              f"{verdict(drawn, STEP_TARGET_MS)}")  # fmt: skip
    drawn, total = bench_vertex(repeat)
    label = f"vertex slider: fill + heatmap ({SIZE}x{SIZE})"
    print(f"{label:<44}{drawn:>8.1f}ms{total:>8.1f}ms  < {VERTEX_TARGET_MS:.0f} ms "
          f"{verdict(drawn, VERTEX_TARGET_MS)}")  # fmt: skip
    drawn, total = bench_tilt(repeat)
    label = "tilt slider, textured plane (160x120)"
    print(f"{label:<44}{drawn:>8.1f}ms{total:>8.1f}ms  (information)")
    print("drawn: until fig.canvas.draw() finished; + PNG: until the PNG for the browser is set")
    return 0


if __name__ == "__main__":
    sys.exit(main())
