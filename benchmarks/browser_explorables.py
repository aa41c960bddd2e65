"""The explorables computed in the page (issue 31), timed by ``bench_browser.py``: each one's
drag (the first picture after the press, pictures per second, the last picture after the
release) or click (to its picture), counted on the canvas' ``data-frames`` (``painter`` in
``teachraster/widgets/static/explore_base.js``)."""

from __future__ import annotations

import math
import statistics

from browser_js import (
    ARM,
    COUNT,
    DONE,
    DRAG_SLIDER,
    DT,
    MARK_RELEASE,
    MOVES,
    RELEASED,
    TIMES,
    latency,
)

#: The notebook cells: one explorable each, tagged with a CSS class the benchmark finds it by.
CELLS = [
    """from teachraster.widgets import (AttributeSurfaces, CrackExplorer, DepthValuesExplorer,
    DiamondExplorer, EdgeFunctionExplorer, EyeRayExplorer, FootprintExplorer, PipelineMap)
def tagged(x, css_class):
    x.add_class(css_class)
    return x""",
    'tagged(PipelineMap(), "bench-pipeline")',
    'tagged(EdgeFunctionExplorer(), "bench-edges")',
    'tagged(AttributeSurfaces(), "bench-surfaces")',
    'tagged(EyeRayExplorer(), "bench-eye")',
    'tagged(CrackExplorer(), "bench-cracks")',
    'tagged(DepthValuesExplorer(), "bench-depthvalues")',
    'tagged(FootprintExplorer(), "bench-footprint")',
    'tagged(DiamondExplorer(), "bench-diamonds")',
]

#: A vertex moved to and fro along x, one position per animation frame (canvas px)
SWING = [(-d, 0) for d in (0, 8, 16, 24, 32, 24, 16, 8)]


def stop_count(page) -> list[float]:
    """The times of the pictures counted since ``COUNT`` (and stop counting)."""
    return page.evaluate("() => { const c = window.__count; c.ob.disconnect(); return c.t; }")


def rate(times, end, release=None) -> tuple[float, float]:
    """Pictures per second before ``end`` (the last move) and ms from ``release`` (default
    ``end``) to the last picture."""
    during = [t for t in times if t <= end]
    fps = (len(during) - 1) / ((during[-1] - during[0]) / 1e3) if len(during) > 2 else 0.0
    release = end if release is None else max(release, end)
    # none after the release: the last picture came with the moves (0, not a negative time)
    return fps, max(0.0, times[-1] - release) if times else math.nan


def drag_canvas(page, sel, start, offsets=SWING, ms=None) -> tuple[float, float, float]:
    """Press the canvas ``sel`` at ``start`` (its px at natural size), move by ``offsets`` in
    turn at every animation frame for ``ms``, release; returns the ms from the press to the
    first picture, the pictures per second and the ms from the last move to the last picture.

    The press and release are Playwright's (real pointer events); the moves are synthesized
    in the page at display rate, as a mouse sends them (Playwright's own arrive at about 20
    a second on this machine).
    """
    canvas = page.locator(sel).first
    canvas.scroll_into_view_if_needed()
    page.wait_for_timeout(200)
    box = canvas.bounding_box()
    scale = box["width"] / canvas.evaluate("c => c.logical.w")
    points = [(box["x"] + (start[0] + dx) * scale, box["y"] + (start[1] + dy) * scale)
              for dx, dy in offsets]  # fmt: skip
    page.evaluate(COUNT, [sel, "data-frames"])
    page.evaluate(ARM, [sel, ["pointerdown"], sel, "data-frames"])
    page.mouse.move(*points[0])
    page.mouse.down()
    page.evaluate(MOVES, {"sel": sel, "points": points, "ms": ms or TIMES["drag"]})
    page.evaluate(MARK_RELEASE)
    page.mouse.up()
    page.wait_for_timeout(500)
    paint = page.evaluate("() => window.__count.p.filter(x => x >= 0)")
    if paint:  # where a slow drag's time goes: the page's own drawing, or elsewhere
        print(f"{sel}: drawing a picture takes {statistics.median(paint):.1f} ms (median of "
              f"{len(paint)})")  # fmt: skip
    first = page.evaluate(DT) if page.evaluate(DONE) else math.nan
    fps, after = rate(stop_count(page), page.evaluate("() => window.__dragEnd"),
                      page.evaluate(RELEASED))  # fmt: skip
    return first, fps, after


def drag_range(page, sel, watch) -> tuple[float, float]:
    """Drag the page's range input ``sel`` (every animation frame a step) for 1.5 s;
    pictures per second on ``watch``'s ``data-frames``, ms from release to the last one."""
    page.locator(sel).first.scroll_into_view_if_needed()
    page.evaluate(COUNT, [watch, "data-frames"])
    page.evaluate(DRAG_SLIDER, [sel, TIMES["drag"]])
    page.wait_for_timeout(500)
    return rate(stop_count(page), page.evaluate("() => window.__dragEnd"))


def handle(page, sel, k) -> list[float]:
    """The canvas px of handle ``k`` of the canvas ``sel`` (its ``data-handles``)."""
    return page.evaluate(f"(s) => JSON.parse(document.querySelector(s).dataset.handles)[{k}]", sel)


def drags(page, name, sel, start, reps, offsets=SWING) -> list[tuple]:
    """``reps`` // 2 drags (one at least) of :func:`drag_canvas`, as report rows (first
    picture, fps, after)."""
    runs = [drag_canvas(page, sel, start() if callable(start) else start, offsets)
            for _ in range(max(1, reps // 2))]  # fmt: skip
    return [("click", f"{name}, first picture of a drag", [r[0] for r in runs]),
            ("fps", f"{name} dragged", [r[1] for r in runs]),
            ("settle", f"{name}, last picture after a drag", [r[2] for r in runs])]  # fmt: skip


def clicks(page, name, target, watch, acts, reps) -> tuple:
    """``reps`` clicks, ``acts[i % len(acts)]`` each, timed from the first press on
    ``target`` to the next picture on ``watch``."""
    ms = []
    for i in range(reps):
        ms += latency(page, target, ["pointerdown", "mousedown"], watch, "data-frames",
                      acts[i % len(acts)], 1, timeout=5_000)  # fmt: skip
    return ("click", name, ms)


def canvas_click(page, sel, xy):
    """A click at ``xy`` (px of the canvas ``sel`` at its natural size)."""

    def act():
        canvas = page.locator(sel).first
        box = canvas.bounding_box()
        scale = box["width"] / canvas.evaluate("c => c.logical.w")
        page.mouse.click(box["x"] + xy[0] * scale, box["y"] + xy[1] * scale)

    return act


def bench_explorables(page, reps: int) -> list[tuple]:
    """Every explorable's drag or click; report rows ``(kind, label, values)``."""
    rows = []
    pipe = ".bench-pipeline"
    page.locator(pipe).first.scroll_into_view_if_needed()
    stages = page.locator(f"{pipe} g.stage")
    rows.append(clicks(page, "PipelineMap: click a stage", f"{pipe} svg", f"{pipe} canvas",
                       [stages.nth(2).click, stages.nth(7).click], reps))  # fmt: skip
    edges = ".bench-edges canvas"
    rows += drags(page, "EdgeFunctionExplorer: vertex", edges, lambda: handle(page, edges, 0), reps)
    rows += drags(page, "AttributeSurfaces: rotate", ".bench-surfaces canvas", (320, 235), reps,
                  [(d, 0) for d in (0, 20, 40, 60, 80, 60, 40, 20)])  # fmt: skip
    eye = ".bench-eye canvas"
    rows += drags(page, "EyeRayExplorer: segment end", eye, lambda: handle(page, eye, 1), reps)
    for label in ("q", "depth ratio z1/z0"):
        runs = [drag_range(page, f".bench-eye input[aria-label='{label}']", eye)
                for _ in range(max(1, reps // 2))]  # fmt: skip
        rows.append(("fps", f"EyeRayExplorer: {label} slider dragged", [r[0] for r in runs]))
    cracks = ".bench-cracks"
    page.locator(cracks).first.scroll_into_view_if_needed()
    reroll = page.locator(f"{cracks} button", has_text="Reroll").first
    rows.append(clicks(page, "CrackExplorer: reroll", f"{cracks} .tr-x", f"{cracks} canvas",
                       [reroll.click], reps))  # fmt: skip
    depth = ".bench-depthvalues canvas"
    rows += drags(page, "DepthValuesExplorer: near plane", depth, lambda: handle(page, depth, 0),
                  reps, [(d, 0) for d in (0, 10, 20, 30, 40, 30, 20, 10)])  # fmt: skip
    screen = ".bench-footprint canvas[aria-label^='the textured floor']"
    tex = ".bench-footprint canvas[aria-label^='the texture:']"
    page.locator(screen).first.scroll_into_view_if_needed()
    rows.append(clicks(page, "FootprintExplorer: click a pixel", screen, screen,
                       [canvas_click(page, screen, (60, 200)),
                        canvas_click(page, screen, (200, 220))], reps))  # fmt: skip
    rows.append(clicks(page, "FootprintExplorer: click the texture", tex, screen,
                       [canvas_click(page, tex, (40, 40)), canvas_click(page, tex, (90, 70))],
                       reps))  # fmt: skip
    lines = ".bench-diamonds canvas"
    rows += drags(page, "DiamondExplorer: end point", lines, lambda: handle(page, lines, 1), reps)
    return rows
