"""The controls that go through the kernel (issue 31), timed by ``bench_browser.py``: a click,
a menu choice or an arrow key, to the new picture; the kernel sliders dragged (pictures per
second, the last picture after the release)."""

from __future__ import annotations

import math

from browser_explorables import rate, stop_count
from browser_js import COUNT, MARK_RELEASE, MOVES, RELEASED, TIMES, latency, settle

#: The notebook cells (the kernel widgets of lessons 04, 06, 07, 08 and 10, each as its
#: lesson builds it), tagged with a CSS class the benchmark finds each by. Lesson 06's rows:
#: its study's interpolation group alone (the same variants, counts and errors; about 1 s),
#: not the whole study (15 s and more on a loaded machine).
CELLS = [
    """from teachraster.study import operation_counts as ops
from teachraster.study.bench.measure import Progress, bench_interpolation, sizes
from teachraster.widgets import CasePicker, ProjectionExplorer, TileExplorer
from teachraster.widgets.divide_cost import DivideCostExplorer
from teachraster.widgets.sampling_explorer import SamplingExplorer
interp_rows = ops.with_counts(bench_interpolation(sizes(True), 1, Progress(1, enabled=False)))
divide = DivideCostExplorer(interp_rows)
divide.widget.add_class("bench-divide")
divide""",
    """cases = CasePicker()
cases.widget.add_class("bench-cases")
cases""",
    # a filter wide enough for its shape to show (at width 0, the lesson's start, the shape
    # changes nothing in the picture)
    """sampling = SamplingExplorer(width=1.0)
sampling.widget.add_class("bench-sampling")
sampling""",
    """tiles = TileExplorer(tr.Triangle([[3.2, 4.1], [60.5, 21.7], [18.3, 58.9]]), 64, 64)
tiles.widget.add_class("bench-tiles")
tiles""",
    """projection = ProjectionExplorer()
projection.widget.add_class("bench-projection")
projection""",
]

#: Where each widget's picture changes: a PNG ``<img>`` (its ``src``), or a page figure
#: (``.tr-drag img``, its ``data-frames``).
PNG = ("img", "src")


def picture(page, p) -> tuple[str, str]:
    """The selector and attribute that change with the widget ``p``'s picture."""
    if page.locator(f"{p} .tr-drag img").count():
        return f"{p} .tr-drag img", "data-frames"
    return f"{p} img", "src"


def idle(page) -> None:
    """Until the kernel is idle (as a student looks at the picture before the next click)."""
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=60_000)
    page.wait_for_timeout(200)


def control(page, name, p, events, act, reps) -> tuple:
    """``reps`` times ``act(i)``, timed from the first of ``events`` in ``p`` to the picture."""
    watch, attr = picture(page, p)
    ms = []
    for i in range(reps):
        ms += latency(page, p, events, watch, attr, lambda i=i: act(i), 1, timeout=5_000)
        idle(page)
    return ("click", name, ms)


def toggle(page, p):
    """Click the next option of the widget's toggle buttons (one not pressed)."""
    return lambda _i: page.locator(f"{p} .widget-toggle-button:not(.mod-active)").first.click()


def menu(page, p, k=0):
    """Choose the other option of the widget's ``k``-th menu (first and second in turn)."""
    select = page.locator(f"{p} select").nth(k)
    return lambda i: select.select_option(index=(i + 1) % 2)


def key(page, p, k=0):
    """An arrow key on the widget's ``k``-th slider: right, then left (it stays in range)."""
    handle = page.locator(f"{p} .noUi-handle, {p} input[type=range]").nth(k)
    return lambda i: handle.press("ArrowRight" if i % 2 == 0 else "ArrowLeft")


def sweep(handle) -> list[float]:
    """Where along its track (0 to 1) an ``IntSlider`` is dragged, one point per animation
    frame: to and fro over its positions, each point on the next one (31 points along a
    longer track), so that every frame asks for a new value, as the other drags do."""
    lo, hi, now = (float(handle.get_attribute(a) or 0) for a in
                   ("aria-valuemin", "aria-valuemax", "aria-valuenow"))  # fmt: skip
    n = 31 if hi - lo > 30 else int(hi - lo) + 1
    ends = [i / (n - 1) for i in range(n)] if n > 1 else [0.0]
    start = min(range(n), key=lambda i: abs(ends[i] - (now - lo) / ((hi - lo) or 1)))
    cycle = ends + ends[-2:0:-1]  # 0 .. 1 .. back, without repeating the ends
    return [cycle[(start + 1 + i) % len(cycle)] for i in range(len(cycle))]


def drag_noui(page, p, k=0, ms=None) -> tuple[float, float]:
    """Drag the widget's ``k``-th slider to and fro over its positions (:func:`sweep`), a
    move at every animation frame, for ``ms``; pictures per second, ms from the release to
    the last."""
    watch, attr = picture(page, p)
    handle = page.locator(f"{p} .noUi-handle").nth(k)
    handle.scroll_into_view_if_needed()
    track = page.locator(f"{p} .noUi-target").nth(k).bounding_box()
    box = handle.bounding_box()
    y = box["y"] + box["height"] / 2
    points = [(track["x"] + f * track["width"], y) for f in sweep(handle)]
    page.evaluate(COUNT, [watch, attr])
    page.mouse.move(box["x"] + box["width"] / 2, y)
    page.mouse.down()
    page.evaluate(MOVES, {"sel": f"{p} .noUi-handle", "points": points, "ms": ms or TIMES["drag"],
                          "mouse": True})  # fmt: skip
    page.evaluate(MARK_RELEASE)
    page.mouse.up()
    settle(page)
    fps, after = rate(stop_count(page), page.evaluate("() => window.__dragEnd"),
                      page.evaluate(RELEASED))  # fmt: skip
    idle(page)
    return fps, after


def drag_slider(page, name, p, reps, k=0) -> list[tuple]:
    """``reps`` // 2 drags (one at least) of the widget's ``k``-th slider, as report rows."""
    n = max(1, reps // 2)
    if page.locator(f"{p} input[type=range]").count():  # a page slider (LiveSlider)
        from browser_explorables import drag_range

        watch, _ = picture(page, p)
        sel = f"{p} input[type=range]"
        runs = [drag_range(page, sel, watch) for _ in range(n)]
    else:
        runs = [drag_noui(page, p, k) for _ in range(n)]
    return [("fps", f"{name} dragged", [r[0] for r in runs]),
            ("settle", f"{name}, last picture after a drag", [r[1] for r in runs])]  # fmt: skip


def bench_controls(page, reps: int) -> list[tuple]:
    """Every kernel control of issue 31; report rows ``(kind, label, values)``."""
    click, change, keys = ["pointerdown", "mousedown"], ["change", "input"], ["keydown"]
    rows = []
    for p in (".bench-divide", ".bench-cases", ".bench-sampling", ".bench-tiles",
              ".bench-projection"):  # fmt: skip
        page.locator(p).first.scroll_into_view_if_needed()
        watch, _ = picture(page, p)
        if not page.locator(watch).count():
            rows.append(("click", f"{p}: no picture found", [math.nan]))
    rows.append(control(page, "DivideCostExplorer: error toggle (kernel)", ".bench-divide", click,
                        toggle(page, ".bench-divide"), reps))  # fmt: skip
    rows.append(control(page, "CasePicker: naive-rule toggle (kernel)", ".bench-cases", click,
                        toggle(page, ".bench-cases"), reps))  # fmt: skip
    rows.append(control(page, "CasePicker: case menu (kernel)", ".bench-cases", change,
                        menu(page, ".bench-cases"), reps))  # fmt: skip
    rows.append(control(page, "SamplingExplorer: kernel toggle (kernel)", ".bench-sampling",
                        click, toggle(page, ".bench-sampling"), reps))  # fmt: skip
    rows.append(control(page, "SamplingExplorer: samples, one key (drawn ahead)", ".bench-sampling",
                        keys, key(page, ".bench-sampling"), reps))  # fmt: skip
    rows.append(control(page, "TileExplorer: level, one key (drawn ahead)", ".bench-tiles", keys,
                        key(page, ".bench-tiles"), reps))  # fmt: skip
    rows += drag_slider(page, "TileExplorer: level slider", ".bench-tiles", reps)
    rows.append(control(page, "TileExplorer: traversal menu (kernel)", ".bench-tiles", change,
                        menu(page, ".bench-tiles", 1), reps))  # fmt: skip
    rows.append(control(page, "ProjectionExplorer: q, one key", ".bench-projection", keys,
                        key(page, ".bench-projection"), reps))  # fmt: skip
    rows += drag_slider(page, "ProjectionExplorer: q slider", ".bench-projection", reps)
    return rows
