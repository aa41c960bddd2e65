"""Our part of anywidget's 2 s ``ready`` window: each page-side module, loaded as anywidget
loads it, against an empty module, in headless Chromium with the CPU throttled.

Run from anywhere (needs Playwright and Debian's Chromium)::

    python benchmarks/bench_esm_ready.py              # CPU 4x and 8x slower, 15 loads each
    python benchmarks/bench_esm_ready.py --rates 6 --loads 30

anywidget 0.11 (``labextension/static/528.*.js``, class ``Runtime``) starts
``AbortSignal.timeout(2000)`` when a model is created in the page; its ``ready`` must resolve
before then or it rejects ("[anywidget] Failed to initialize model"), and every message from
the kernel to that model waits on ``ready`` (``AnyModel._handle_comm_msg``): the page never
hears the model again. Within the window: the model's ``_css``, then its ``_esm`` made a Blob
URL and ``import()``-ed (fetched, parsed, evaluated: a new module per model), its default
export (called if a function) and ``initialize({model})`` awaited. Each model's load is timed
here the same way (a stand-in model), interleaved with the same load of an empty module: the
difference of medians is our modules' own part; the empty module's time is the part anywidget
and the browser take whatever the module. The page's own rate is shown by a fixed loop.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")

#: One model's load, as anywidget 0.11's loadEsm, loadWidget and WidgetBinding.bind do it
ONE = """async (esm) => {
  const model = { get: () => undefined, on() {}, off() {}, send() {}, set() {}, save_changes() {} };
  const url = URL.createObjectURL(new Blob([esm], { type: "text/javascript" }));
  const mod = await import(url);
  URL.revokeObjectURL(url);
  const def = typeof mod.default === "function" ? await mod.default() : mod.default;
  if (def.initialize) await def.initialize({ model, signal: new AbortController().signal });
}"""
#: ms of one model's load
LOAD = ("async (esm) => { const t0 = performance.now(); "
        f"await ({ONE})(esm); return performance.now() - t0; }}")  # fmt: skip
#: Models created at once (a page reloaded on its kernel restores them all together, each
#: with its own 2 s): ms until the last one is ready
AT_ONCE = ("async (esms) => { const t0 = performance.now(); "
           f"await Promise.all(esms.map({ONE})); return performance.now() - t0; }}")  # fmt: skip
EMPTY = "export default { render() {} };"
#: ms of a fixed loop: how fast the throttled page runs
SPIN = """() => { const t = performance.now(); let x = 0;
  for (let i = 0; i < 1e7; i++) x += i % 7; return performance.now() - t; }"""


def modules() -> dict:
    """Every anywidget of the package and its module (``_esm``)."""
    from teachraster.widgets.attribute_surfaces import AttributeSurfaces, EyeRayExplorer
    from teachraster.widgets.crack_explorer import CrackExplorer
    from teachraster.widgets.depth_values import DepthValuesExplorer
    from teachraster.widgets.dragging import DragFigure
    from teachraster.widgets.edge_explorer import EdgeFunctionExplorer
    from teachraster.widgets.footprint_explorer import FootprintExplorer
    from teachraster.widgets.frames import FramesWidget
    from teachraster.widgets.line_diamonds import DiamondExplorer
    from teachraster.widgets.live_slider import LiveSlider
    from teachraster.widgets.pipeline_map import PipelineMap
    from teachraster.widgets.predict_figure import FigurePrediction

    classes = [LiveSlider, DragFigure, FramesWidget, FigurePrediction, AttributeSurfaces,
               EyeRayExplorer, CrackExplorer, DepthValuesExplorer, EdgeFunctionExplorer,
               FootprintExplorer, DiamondExplorer, PipelineMap]  # fmt: skip
    return {c.__name__: c._esm for c in classes}


def run(page, cdp, rate: float, loads: int, mods: dict) -> None:
    cdp.send("Emulation.setCPUThrottlingRate", {"rate": rate})
    print(f"\nCPU {rate:g}x slower (a 1e7 loop: {page.evaluate(SPIN):.0f} ms); load average "
          f"{os.getloadavg()[0]:.1f}; {loads} loads of each module, interleaved with an "
          "empty one's")  # fmt: skip
    for esm in mods.values():
        page.evaluate(LOAD, esm)  # the first model of each kind in the page
    times = {name: [] for name in mods}
    empty = []
    for _ in range(loads):
        for name, esm in mods.items():
            empty.append(page.evaluate(LOAD, EMPTY))
            times[name].append(page.evaluate(LOAD, esm))
    e = statistics.median(empty)
    print(f"| module | kB | load median (ms) | ours: minus the empty module's {e:.1f} ms |")
    print("|---|---|---|---|")
    for name, t in times.items():
        m = statistics.median(t)
        print(f"| {name} | {len(mods[name].encode()) / 1e3:.1f} | {m:.1f} | {m - e:+.1f} |")
    # pages of models created at once: the PlaneExplorer's (9 LiveSliders, its DragFigure)
    # and a lesson's worth (every module 4 times), ours against as many empty modules
    plane = [mods["LiveSlider"]] * 9 + [mods["DragFigure"]]
    for label, esms in (("PlaneExplorer's 10 models", plane),
                        (f"{4 * len(mods)} models (each module 4 times)", 4 * list(mods.values()))):  # fmt: skip
        ours, none = [], []
        for _ in range(max(3, loads // 3)):
            none.append(page.evaluate(AT_ONCE, [EMPTY] * len(esms)))
            ours.append(page.evaluate(AT_ONCE, esms))
        o, n = statistics.median(ours), statistics.median(none)
        print(
            f"{label} created at once: the last ready after {o:.0f} ms (empty modules: "
            f"{n:.0f} ms; ours {o - n:+.0f} ms) of the 2000 ms each has"
        )


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rates", type=float, nargs="+", default=[4.0, 8.0],
                        help="CPU throttling rates (default 4 8)")  # fmt: skip
    parser.add_argument("--loads", type=int, default=15, help="loads per module (default 15)")
    args = parser.parse_args(argv)
    from playwright.sync_api import sync_playwright

    mods = modules()
    print(time.strftime("%d %b %Y %H:%M UTC", time.gmtime()), "anywidget ready window probe")
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True,
                                    args=["--no-sandbox", "--disable-gpu"])  # fmt: skip
        try:
            page = browser.new_page()
            page.set_content("<html><body></body></html>")
            cdp = page.context.new_cdp_session(page)
            for rate in args.rates:
                run(page, cdp, rate, args.loads, mods)
        finally:
            browser.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
