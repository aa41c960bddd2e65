"""Benchmark the widgets in a real browser: JupyterLab in headless Chromium, driven by Playwright.

Run from anywhere (needs JupyterLab, Playwright and Debian's Chromium)::

    python benchmarks/bench_browser.py            # full run (about 5 minutes)
    python benchmarks/bench_browser.py --quick    # smoke run (fewer tries)
    python benchmarks/bench_browser.py --only FilterExplorer   # the baselines and one explorer
    python benchmarks/bench_browser.py --only TriangleEditor,PlaneExplorer   # side by side

JupyterLab starts on a free loopback port with its own config, data, runtime and settings
folders (in a temporary directory, removed afterwards) and opens a small notebook holding:
two baselines, a do-nothing ``IntSlider`` -> ``Output`` round trip and a plain matplotlib
figure redrawn from an ``IntSlider`` with the widgets' own display (a PNG in an
``ipywidgets.Image``); a half-plane ``FillPlayer`` (16 x 16, ``interval=20``) and a
``TriangleEditor`` (16 x 16), and the four slider explorers whose sliders are page-side
``LiveSlider``s (coalesced): ``TexturedPlaneViewer``, ``FilterExplorer``, ``PlaneExplorer``
and ``DepthPrecisionExplorer``; then every explorable computed in the page
(``browser_explorables.py``) and every control of issue 31 that goes through the kernel
(``browser_controls.py``). Chromium (1400 x 900) then drives them like a student:

- latency: from the input event (key, click or pointer) to the change on the page (the
  figure's ``src``, the canvas' step, the output's text), timed in the page;
- frame rates: pictures changed per second while the step slider is dragged with the mouse,
  while Play runs at 20 ms/step, and re-rendered fills per second while a vertex of the
  editor or of the ``PlaneExplorer`` is dragged continuously, 1 grid pixel per pointer move
  (:func:`bench_vertex_drag`), and while each explorer's
  slider is dragged (its next step at every animation frame, :func:`bench_slider`); how
  long after the drag the last picture comes (coalesced: about one render, never a queue);
  the kernel's time per slider value, as the page hears it. The slider explorers' pictures
  drawn ahead (``teachraster.widgets.ahead``) are awaited before anything is timed, as the
  player's frames are: a key then shows the page's own picture first (timed) and the
  kernel's full picture second (timed too).

It prints one Markdown table (``browser_table.py``: interaction, median, max, ratio to rt,
target ✓ or ✗), with the date, the load average and rt above it, and the rows that miss
their target below. Absolute times on these machines vary 2x from day to day: the figures to
report are the ratios to the round trip measured in the same run, and the frame rates
beside the idle page's own animation frames. Every server and browser started here
is stopped by its process id. The exit status is non-zero only on errors.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import browser_table as table
from browser_controls import CELLS as CONTROL_CELLS
from browser_controls import bench_controls
from browser_explorables import CELLS as EXPLORABLE_CELLS
from browser_explorables import bench_explorables
from browser_js import (
    ARM,
    ARM_SECOND,
    COUNT,
    DONE,
    DRAG,
    DRAG_SLIDER,
    DT,
    MARK_RELEASE,
    MOVES,
    RELEASED,
    TIMES,
    latency,
)
from browser_js import (
    settle as wait_to_settle,
)

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
ARGS = ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync",
        "--disable-quic"]  # fmt: skip

CELLS = [
    """import json
import ipywidgets as w
import numpy as np
import teachraster as tr
from teachraster.widgets import FillPlayer, TexturedPlaneViewer, TriangleEditor
from teachraster.widgets.display import FigureDisplay, new_figure
tri = tr.Triangle([[1.3, 1.2], [14.6, 4.7], [5.2, 14.1]], w=[1, 3, 6], attrs={"u": [0, 1, 0]})
def drag_info(tag, display):
    # where a dragged figure's handles are in its picture (bench_vertex_drag reads it)
    w_ = display.widget
    print(tag, json.dumps({"transform": w_.transform, "size": w_.size, "handles": w_.handles}))""",
    # baseline 1: a do-nothing round trip
    """rt = w.IntSlider(description="rt")
rt_out = w.Output()
rt_out.add_class("bench-rt-out")
def _echo(change):
    rt_out.outputs = ({"output_type": "stream", "name": "stdout", "text": str(change["new"])},)
rt.observe(_echo, "value")
box = w.VBox([rt, rt_out]); box.add_class("bench-rt"); box""",
    # baseline 2: a plain figure redrawn from a slider, shown as the widgets show figures
    """fig = new_figure((7.2, 5.4), "image")
ax = fig.add_subplot()
image = ax.imshow(np.random.default_rng(0).random((16, 16)))
plain = FigureDisplay(fig, "image")
fs = w.IntSlider(description="fig", max=100)
def _redraw(change):
    image.set_data(np.random.default_rng(change["new"]).random((16, 16)))
    plain.refresh()
fs.observe(_redraw, "value")
box = w.VBox([fs, plain.widget]); box.add_class("bench-fig"); box""",
    """player = FillPlayer(tri, 16, 16, method="halfplane", interval=20)
player.widget.add_class("bench-player")
player""",
    """viewer = TexturedPlaneViewer(tilt=60)
viewer.widget.add_class("bench-viewer")
viewer""",
    # the other slider explorers (LiveSliders, coalesced), each with its lesson's settings
    """from teachraster.widgets import FilterExplorer
explorer = FilterExplorer(tilt=80, filter="trilinear")
explorer.widget.add_class("bench-filter")
explorer""",
    """from teachraster.widgets import PlaneExplorer
plane = PlaneExplorer()
plane.widget.add_class("bench-plane")
drag_info("BENCH-PLANE", plane.display)
plane""",
    """from teachraster.widgets.depth_explorer import DepthPrecisionExplorer
depth = DepthPrecisionExplorer("unorm24", near=0.1, far=1000.0)
depth.widget.add_class("bench-depth")
depth""",
    # the explorables computed in the page, then the kernel controls (issue 31): inserted
    # here by write_notebook, so that the editor's cells stay last
    """editor = TriangleEditor(tri, 16, 16)
editor.widget.add_class("bench-editor")
drag_info("BENCH-EDITOR", editor.display)
editor""",
    # the line run_all_cells waits for
    'print("BENCH-END")',
]


#: The smoke run's (``--quick``) explorers with the most pictures drawn ahead, smaller (as large
#: on the page): each slider position is drawn in the kernel and decoded in the page, again
#: after every control moved. The PlaneExplorer on an 8 x 7 grid, not the lesson's 16 x 14,
#: and its sliders in whole pixels and halves of f, not quarters and tenths: 72 pictures a
#: round, not 459 (279 with the quarters and tenths, tests/test_browser_plane_drag's; 6.3 ->
#: 1.4 s of kernel CPU a round, and the smoke run draws about four rounds: at Run All, after v1
#: x, after f2 and after the vertex's drag); its vertices and f on those positions. The
#: FilterExplorer's texture 64 x 48, not 160 x 120 (tests/test_browser_filter_keys': its 90
#: full pictures 5.6 -> 1.9 s of kernel CPU), and its tilt and the TexturedPlaneViewer's in
#: steps of 5°, not 1° (18 and 19 pictures a round, not 90 and 91: 2.1 -> 0.4 s and 1.2 ->
#: 0.3 s of kernel CPU). The FillPlayer on an 8 x 8 grid (the triangle halved), not 16 x 16:
#: a quarter of the steps, so a quarter of the frames the kernel draws and sends at Run All
#: and again after each of its three toggles, each waited for. The ProjectionExplorer's q in
#: steps of 0.05, not 0.01 (21 pictures a round, not 101, each ~14 ms of kernel CPU: 1.45 ->
#: 0.3 s a round; q starts at 0.5, on those steps). Their rows are measured as in
#: the report's run; only their figures differ, and the smoke run's figures are not the
#: report's.
QUICK_CELLS = {
    "viewer = TexturedPlaneViewer(tilt=60)":
        "viewer = TexturedPlaneViewer(tilt=60)\nviewer.tilt.step = 5.0",
    "plane = PlaneExplorer()":
        "plane = PlaneExplorer(((2.0, 1.0), (7.0, 3.0), (3.0, 6.0)), (0.0, 1.0, 0.5), width=8,"
        " height=7)\nfor _s in (*plane.x, *plane.y):\n    _s.step = 1.0\nfor _s in plane.f:\n"
        "    _s.step = 0.5",
    'explorer = FilterExplorer(tilt=80, filter="trilinear")':
        'explorer = FilterExplorer(64, 48, tilt=80, filter="trilinear")\nexplorer.tilt.step = 5.0',
    "projection = ProjectionExplorer()":
        "projection = ProjectionExplorer()\nprojection.q.step = 0.05",
    'player = FillPlayer(tri, 16, 16, method="halfplane", interval=20)':
        'player = FillPlayer(tr.Triangle([[0.65, 0.6], [7.3, 2.35], [2.6, 7.05]], w=[1, 3, 6],'
        ' attrs={"u": [0, 1, 0]}), 8, 8, method="halfplane", interval=20)',
}  # fmt: skip

#: ``polling`` (ms) of the waits on the kernel (Run All's groups, the pictures drawn ahead):
#: Playwright's default evaluates the predicate at every animation frame, which keeps Chromium
#: drawing frames for the whole wait (1.1-1.3 s of CPU per 15 s on lesson 03's page,
#: tests/notebook_browser.py's POLL_MS); nothing timed here starts or ends on these waits.
POLL_MS = 100

#: JupyterLab's notebook windowing mode in the benchmark
WINDOWING = os.environ.get("BENCH_WINDOWING", "none")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def write_notebook(folder: Path, only: list | None = None, quick: bool = False) -> str:
    """The benchmark's notebook in ``folder``; with ``only`` (the CSS classes of slider
    explorers or dragged figures) the baselines and those widgets alone, then the line
    :func:`run_all_cells` waits for; ``quick``: the smoke run's (:data:`QUICK_CELLS`)."""
    import nbformat

    nb = nbformat.v4.new_notebook()
    cells = [*CELLS[:-2], *EXPLORABLE_CELLS, *CONTROL_CELLS, *CELLS[-2:]]
    if only is not None:
        chosen = [c for c in CELLS if any(f'add_class("{cls}")' in c for cls in only)]
        cells = [*CELLS[:3], *chosen, CELLS[-1]]
    if quick:
        for full, small in QUICK_CELLS.items():
            assert sum(full in c for c in cells) <= 1, full
            cells = [c.replace(full, small) for c in cells]
    nb.cells = [nbformat.v4.new_code_cell(c) for c in cells]
    # a kernel named up front: JupyterLab would otherwise ask which one
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}  # fmt: skip
    nbformat.write(nb, folder / "bench.ipynb")
    return "bench.ipynb"


def start_lab(work: Path):
    """JupyterLab on a free port, state under ``work``; returns (process, base URL, log)."""
    settings = work / "settings"
    (settings / "@jupyterlab/apputils-extension").mkdir(parents=True)
    (settings / "@jupyterlab/apputils-extension/notification.jupyterlab-settings").write_text(
        json.dumps({"fetchNews": "false", "checkForUpdates": False}))  # fmt: skip
    (settings / "@jupyterlab/notebook-extension").mkdir(parents=True)
    (settings / "@jupyterlab/notebook-extension/tracker.jupyterlab-settings").write_text(
        json.dumps({"windowingMode": WINDOWING}))  # fmt: skip
    # no nbgrader, as in a student's JupyterLab (``teachraster[lab]``; it is a test dependency):
    # its server extensions cost the server 3.2 s at each start and its four page plugins ask
    # the server for courses at each page load (tests/notebook_browser.py leaves them out too)
    (work / "config" / "labconfig").mkdir(parents=True)
    (work / "config" / "labconfig" / "page_config.json").write_text(
        json.dumps({"disabledExtensions": {"@jupyter/nbgrader": True}}))  # fmt: skip
    env = dict(os.environ, JUPYTER_CONFIG_DIR=str(work / "config"),
               JUPYTER_RUNTIME_DIR=str(work / "runtime"), JUPYTER_DATA_DIR=str(work / "data"),
               IPYTHONDIR=str(work / "ipython"),
               PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))  # fmt: skip
    env.pop("MPLBACKEND", None)
    port = free_port()
    log = open(work / "lab.log", "w")  # noqa: SIM115 (closed by stop_lab)
    proc = subprocess.Popen(
        [sys.executable, "-m", "jupyter", "lab", "--no-browser", "--allow-root",
         "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
         "--IdentityProvider.token=", "--ServerApp.password=",
         f"--ServerApp.root_dir={work / 'nb'}", f"--LabApp.user_settings_dir={settings}",
         f"--LabApp.workspaces_dir={work / 'workspaces'}",
         *(f"--ServerApp.jpserver_extensions=nbgrader.server_extensions.{name}=False"
           for name in ("formgrader", "validate_assignment", "assignment_list", "course_list"))],
        stdout=log, stderr=subprocess.STDOUT, env=env, cwd=work,
    )  # fmt: skip
    base = f"http://127.0.0.1:{port}"
    deadline = time.time() + 120
    while True:
        try:
            urllib.request.urlopen(f"{base}/api/status", timeout=2).close()
            return proc, base, log
        except OSError:
            if proc.poll() is not None or time.time() > deadline:
                stop_lab(proc, log)
                raise RuntimeError(
                    "JupyterLab did not start:\n" + (work / "lab.log").read_text()[-2000:]
                ) from None
            time.sleep(0.5)


def stop_lab(proc, log) -> None:
    proc.terminate()  # by its PID; the server shuts its kernels down on SIGTERM
    try:
        proc.wait(timeout=20)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
    log.close()


def run_all_cells(page, base: str, name: str, ahead=None) -> None:
    page.goto(f"{base}/lab/tree/{name}?reset")
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=120_000)
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=120_000)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    try:
        page.locator(".jp-OutputArea-output", has_text="BENCH-END").first.wait_for(timeout=600_000)
    except Exception:  # a cell failed (Run All stops there): say which
        errors = page.locator(".jp-OutputArea-output[data-mime-type*='error']").all_inner_texts()
        raise RuntimeError("the notebook did not finish: " + "\n".join(errors)[-3000:]) from None
    # every group of the player's frames in the page, every picture drawn ahead (``ahead``:
    # of these explorers only, and no player: ``--only``)
    if ahead is None:
        wait_for_groups(page)
    wait_for_ahead(page, ahead)


#: The explorers whose slider positions are drawn ahead (PlaneExplorer: its first slider, v1 x;
#: SamplingExplorer: samples; TileExplorer: level).
AHEAD = ("bench-viewer", "bench-filter", "bench-plane", "bench-depth", "bench-projection",
         "bench-sampling", "bench-tiles")  # fmt: skip


def wait_for_ahead(page, classes=None) -> None:
    """Until the slider explorers' pictures drawn ahead are all in the page (the kernel
    draws them while it idles after the cells ran, as a student's would: the baselines are
    timed on an idle kernel); ``classes``: of these explorers only."""
    for cls in AHEAD if classes is None else classes:
        page.wait_for_function(
            "(c) => { const r = document.querySelector(`.${c} input[type=range]`);"
            " const i = document.querySelector(`.${c} .tr-drag img`);"
            " if (!r || !i) return false;"
            " const n = Math.floor((Number(r.max) - Number(r.min)) / Number(r.step) + 1e-9) + 1;"
            " return i && Number(i.dataset.ahead || 0) >= n; }",
            arg=cls, timeout=300_000, polling=POLL_MS)  # fmt: skip


def ahead_settled(page, css_class: str, still_s: float = 1.5, timeout_s: float = 300) -> None:
    """Until the pictures drawn ahead for the explorer ``css_class`` stop arriving (some in
    the page, none new for ``still_s``): after a vertex is let go the kernel draws those of
    the slider moved last (not necessarily the first: :func:`wait_for_ahead` counts those)."""
    count = f"() => document.querySelector('.{css_class} .tr-drag img').dataset.ahead || '0'"
    last, since, end = None, time.time(), time.time() + timeout_s
    while time.time() < end:
        n = page.evaluate(count)
        if n != last:
            last, since = n, time.time()
        elif int(n) > 0 and time.time() - since >= still_s:
            return
        page.wait_for_timeout(200)
    raise RuntimeError(f"{css_class}: pictures drawn ahead still arriving after {timeout_s} s")


def wait_for_groups(page) -> None:
    """Until every group of the player's frames is in the page."""
    page.wait_for_function(
        "() => { const c = document.querySelector('.bench-player canvas.teachraster-figure');"
        " const r = c && c.closest('.tr-frames').querySelector('input[type=range]');"
        " return c && Number(c.dataset.groups) >= Math.ceil((Number(r.max) + 1) / 8); }",
        timeout=300_000, polling=POLL_MS)  # fmt: skip


def bench_baselines(page, tries):
    rt = latency(page, ".bench-rt .noUi-handle", ["keydown"], ".bench-rt-out", None,
                 lambda: page.locator(".bench-rt .noUi-handle").press("ArrowRight"), tries)  # fmt: skip
    fig = latency(page, ".bench-fig .noUi-handle", ["keydown"], ".bench-fig img", "src",
                  lambda: page.locator(".bench-fig .noUi-handle").press("ArrowRight"), tries)  # fmt: skip
    return rt, fig


#: Animation frames the page gets in 1.5 s doing nothing else: the ceiling of every frame
#: rate measured here (60 on a quiet machine; a loaded one gives the browser fewer)
FRAMES = """async () => {
  const t0 = performance.now();
  let n = 0;
  while (performance.now() - t0 < 1500) { await new Promise(requestAnimationFrame); n += 1; }
  return n / ((performance.now() - t0) / 1e3);
}"""


def bench_frames(page, tries: int) -> list[float]:
    """Animation frames per second of the idle page, ``tries`` // 4 times (one at least)."""
    return [page.evaluate(FRAMES) for _ in range(max(1, tries // 4))]


def bench_player(page, tries):
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    p = ".bench-player"
    canvas = f"{p} canvas.teachraster-figure"
    nxt = page.locator(f"{p} button[aria-label='next step']")
    first = page.locator(f"{p} button[aria-label='first step']")
    first.click()
    step = latency(page, f"{p} button[aria-label='next step']", ["pointerdown", "mousedown"],
                   canvas, "data-step", nxt.click, tries)  # fmt: skip
    # drag the step slider for 1.5 s: a new value at every animation frame, as a pointer
    # dragged along the track gives (Playwright's own mouse moves are slower than that here)
    first.click()
    page.evaluate(COUNT, [canvas, "data-step"])
    page.evaluate(DRAG, [f"{p} input[type=range]", TIMES["drag"]])
    drag = page.evaluate("() => { const c = window.__count; c.ob.disconnect(); return c.t; }")
    drag_fps = (len(drag) - 1) / ((drag[-1] - drag[0]) / 1e3) if len(drag) > 2 else 0.0
    # play at 20 ms/step for 2 s
    first.click()
    page.evaluate(COUNT, [canvas, "data-step"])
    page.locator(f"{p} button[aria-label='play']").click()
    page.wait_for_timeout(TIMES["drag"] + 500)
    # the smoke run's player (64 steps, :data:`QUICK_CELLS`) may have played to its end by
    # now, which leaves no pause button: its frames are counted all the same
    pause = page.locator(f"{p} button[aria-label^='pause']")
    if pause.count():
        try:
            pause.click(timeout=5_000)
        except PlaywrightTimeout:  # it ended as the click was on its way
            pass
    played = page.evaluate("() => { const c = window.__count; c.ob.disconnect(); return c.t; }")
    play_fps = (len(played) - 1) / ((played[-1] - played[0]) / 1e3) if len(played) > 2 else 0.0
    toggles = {"method": [], "interpolation": [], "samples": []}
    pairs = {"method": ("span tables", "half-planes"),
             "interpolation": ("affine", "perspective-correct"),
             "samples": ("4 standard (rotated grid)", "1 (centre)")}  # fmt: skip
    # each toggle to its other option once in the smoke run (a new fill each: the kernel's
    # path); there and back in the report's run (each way is a different fill to record)
    for i in range(tries if tries == 1 else max(tries, 2)):
        for name, (a, b) in pairs.items():
            label = a if i % 2 == 0 else b
            if name == "samples":
                select = page.locator(f"{p} select").first
                act = lambda s=select, v=label: s.select_option(v)  # noqa: E731
                events = ["change", "input"]
            else:
                button = page.locator(f"{p} button", has_text=label).first
                act = button.click
                events = ["pointerdown", "mousedown"]
            # timed from the first input event anywhere in the player (each control's own)
            toggles[name] += latency(page, p, events, canvas, "data-gen", act, 1)
            # as a student looks at the new fill before toggling again: its frames are in
            # the page and the kernel is done (the comparison figure follows the picture)
            wait_for_groups(page)
            page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=60_000)
            page.wait_for_timeout(300)
    return step, drag_fps, play_fps, toggles


def drag_info(page, tag: str) -> dict:
    """What the notebook's ``drag_info(tag, display)`` printed: the transform from data to
    figure pixels, the figure's size and the handles of a dragged figure."""
    out = page.locator(".jp-OutputArea-output", has_text=tag).first
    return json.loads(out.inner_text().split(tag, 1)[1])


#: The figures whose vertices are dragged in the page (``static/drag.js``): (CSS class of
#: the widget, its name in the report, the tag its cell prints ``drag_info`` under)
VERTEX_DRAGS = [
    ("bench-editor", "TriangleEditor", "BENCH-EDITOR"),
    ("bench-plane", "PlaneExplorer", "BENCH-PLANE"),
]


def _main_thread(cdp) -> dict:
    """Seconds the page's main thread has spent so far: in tasks, in script, recalculating
    style and laying out (Chromium's ``Performance.getMetrics``)."""
    metrics = {m["name"]: m["value"] for m in cdp.send("Performance.getMetrics")["metrics"]}
    names = {"tasks": "TaskDuration", "script": "ScriptDuration",
             "style": "RecalcStyleDuration", "layout": "LayoutDuration"}  # fmt: skip
    return {k: metrics.get(v, 0.0) for k, v in names.items()}


def bench_vertex_drag(page, tries, css_class, info, name="editor"):
    """Vertex v2 of the figure in ``css_class`` dragged ``tries`` times (``info``:
    :func:`drag_info`), 0-4 grid pixels left and back at every animation frame.

    Returns the pictures per second during each drag, the ms from the press to the first
    picture and from the release to the last one; prints where the time goes (``name``).
    """
    sel = f".{css_class} .tr-drag img"
    img = page.locator(sel).first
    img.scroll_into_view_if_needed()
    page.wait_for_timeout(300)
    box = img.bounding_box()
    w, h = info["size"]
    x0, y0, sx, sy = info["transform"]
    scale = box["width"] / w

    def at(x, y):
        return box["x"] + (x0 + sx * x) * scale, box["y"] + (y0 + sy * y) * scale

    fps, firsts, kernel, trips, parts, settles = [], [], [], [], [], []
    hx, hy = info["handles"][1]
    # the page's main thread during the drags (Chromium's own counters): where a frame's
    # time goes in the page, script, style or layout, beside the kernel's
    cdp = page.context.new_cdp_session(page)
    cdp.send("Performance.enable")
    before, frames = _main_thread(cdp), 0
    for _ in range(tries):
        if css_class in AHEAD:  # a vertex moved: its slider's pictures drawn ahead again
            ahead_settled(page, css_class)
        page.evaluate(COUNT, [sel, "data-frames"])
        page.evaluate(ARM, [sel, ["pointerdown"], sel, "data-frames"])
        # The press is Playwright's (a real pointer event); the moves are synthesized in the
        # page at display rate, as a mouse sends them (Playwright's own moves arrive at about
        # 20 a second on this machine, too few for the frame rate to mean anything).
        page.mouse.move(*at(hx, hy))
        page.mouse.down()
        page.evaluate(MOVES, {"sel": sel,
                              "points": [at(hx - d, hy) for d in (0, 1, 2, 3, 4, 3, 2, 1)],
                              "ms": TIMES["drag"] + 500})  # fmt: skip
        page.evaluate(MARK_RELEASE)
        page.mouse.up()
        page.wait_for_timeout(400)
        times = page.evaluate("() => { const c = window.__count; c.ob.disconnect(); return c.t; }")
        kernel += page.evaluate("() => window.__count.k.filter(x => x > 0)")
        trips += page.evaluate("() => window.__count.rt.filter(x => x > 0)")
        if page.evaluate(DONE):
            firsts.append(page.evaluate(DT))
        timeline = img.get_attribute("data-first-frame")  # drag.js: where its time goes
        if timeline:
            parts.append(json.loads(timeline))
        end = page.evaluate("() => window.__dragEnd")
        release = max(end, page.evaluate(RELEASED))  # the moves' end, or the pointer's release
        settles.append((times[-1] - release) if times else float("nan"))
        during = [x for x in times if x <= end] if times else []
        frames += len(times or [])
        fps.append((len(during) - 1) / ((during[-1] - during[0]) / 1e3) if len(during) > 2 else 0.0)
    used = {k: v - before[k] for k, v in _main_thread(cdp).items()}
    cdp.detach()
    if frames:
        print(
            f"{name} drag, page main thread per picture: "
            + ", ".join(f"{k} {1e3 * v / frames:.1f} ms" for k, v in used.items())
        )
    if kernel:
        print(f"{name} drag: kernel ms per position median {statistics.median(kernel):.0f}, "
              f"position -> picture round trip median {statistics.median(trips):.0f} ms, "
              f"{len(kernel)} frames")  # fmt: skip
    if parts:

        def med(f):
            return statistics.median(f(t) for t in parts)

        print(
            f"{name} drag, first frame (ms from the press, medians): position sent "
            f"{med(lambda t: t['sent']):.1f}, answer in {med(lambda t: t['reply']):.1f} "
            f"(kernel render {med(lambda t: (t['kernel'] or {}).get('render', 0)):.1f} + "
            f"encode {med(lambda t: (t['kernel'] or {}).get('encode', 0)):.1f}), decoded "
            f"{med(lambda t: t['decoded']):.1f}, painted {med(lambda t: t['painted']):.1f}; "
            f"patch {med(lambda t: t['bytes']) / 1e3:.0f} kB"
        )
    return fps, firsts, settles


#: The fewest drags of a vertex per figure (:func:`vertex_drags`): one in the smoke run
#: (``--quick``, set in ``main``), whose numbers are not the report's. Each drag of the
#: PlaneExplorer's vertex has its kernel draw the 459 pictures of its nine sliders ahead again
#: (about 20 s of CPU, kernel and page): a second one was a third of the smoke run's CPU.
LEAST_DRAGS = [2]


def vertex_drags(page, tries, which) -> list[tuple]:
    """:func:`bench_vertex_drag` of each figure of ``which`` (``VERTEX_DRAGS`` rows),
    ``tries`` // 4 drags (``LEAST_DRAGS`` at least): the report's rows."""
    rows = []
    for css_class, name, tag in which:
        drags = max(LEAST_DRAGS[0], tries // 4)
        fps, firsts, settles = bench_vertex_drag(page, drags, css_class,
                                                 drag_info(page, tag), name)  # fmt: skip
        rows += [("click", f"{name}: first frame of a drag", firsts),
                 ("fps", f"{name}: vertex dragged (fills/s)", fps),
                 ("settle", f"{name}: last picture after a drag", settles)]  # fmt: skip
    return rows


#: The slider explorers benchmarked: (CSS class of the widget, its name in the report, the
#: slider dragged, a toggle (its options) or None).
SLIDERS = [
    ("bench-viewer", "TexturedPlaneViewer: tilt", "tilt", None),
    ("bench-filter", "FilterExplorer: tilt", "tilt", ("nearest", "anisotropic")),
    ("bench-plane", "PlaneExplorer: v1 x", "v1 x", None),
    ("bench-depth", "DepthPrecisionExplorer: near", "near", None),
]


def bench_slider(page, tries, css_class, label="tilt", toggle=None, drags=3):
    """A page-side ``LiveSlider`` of the widget with ``css_class``: one key press, dragged.

    Returns the key latencies (ms: to the first picture, the one drawn ahead where the
    page has it), the pictures per second while the slider is dragged (a new position at
    every animation frame) and the ms from the release to the last picture (each a list,
    one per drag of ``drags``), the latencies of
    ``toggle``'s options chosen in turn in its dropdown (empty without one), and the key
    latencies to the kernel's full picture (the second).
    """
    v = f".{css_class}"
    # the picture: an <img> with a canvas over it that paints the changed pixels; each
    # picture painted counts on the <img>'s data-frames
    target, img = f"{v} input[type=range][aria-label^='{label}']", f"{v} .tr-drag img"
    page.locator(target).first.scroll_into_view_if_needed()
    room = ("(r) => Number(r.value) + Number(r.step) <= Number(r.max) + 1e-9 ? 'ArrowRight'"
            " : 'ArrowLeft'")  # fmt: skip
    slider = page.locator(target).first
    # up a step, or down one at the end of the range (a press that changes nothing is no try)
    key = latency(page, target, ["keydown"], img, "data-frames",
                  lambda: slider.press(slider.evaluate(room)), tries)  # fmt: skip
    page.wait_for_timeout(300)
    # the same keys, to the kernel's full picture (after the one drawn ahead); none comes
    # where the picture drawn ahead is the full one (FilterExplorer): one try says so
    press = lambda: slider.press(slider.evaluate(room))  # noqa: E731
    full = latency(page, target, ["keydown"], img, "data-frames", press, 1, ARM_SECOND, 3000)
    if full[0] == full[0]:  # not NaN: the kernel sends its full picture after a key
        full += latency(page, target, ["keydown"], img, "data-frames", press, tries - 1,
                        ARM_SECOND)  # fmt: skip
    fps, settle = [], []
    for _ in range(drags):  # the last picture is one number per drag: a few drags, not one
        page.wait_for_timeout(300)
        page.evaluate(COUNT, [img, "data-frames"])
        # drag.js sets data-kernel-ms at each picture from the kernel: marked, to tell
        page.evaluate(f'() => {{ document.querySelector("{img}").dataset.kernelMs = "none"; }}')
        page.evaluate(DRAG_SLIDER, [target, TIMES["drag"]])
        wait_to_settle(page)
        came = page.evaluate(f'() => document.querySelector("{img}").dataset.kernelMs')
        times = page.evaluate("() => { const c = window.__count; c.ob.disconnect(); return c.t; }")
        end = page.evaluate("() => window.__dragEnd")
        during = [t for t in times if t <= end]
        span = (during[-1] - during[0]) / 1e3 if len(during) > 2 else 0.0
        fps.append((len(during) - 1) / span if span else 0.0)
        # 0 where the last picture was on show before the release (drawn ahead, full)
        settle.append(max(0.0, times[-1] - end) if times else float("nan"))
        ms = page.evaluate(f'() => (document.querySelector("{target}").kernelMs || []).at(-1)')
        print(
            f"{css_class}: a drag's last picture {settle[-1]:.1f} ms after the release "
            f"(kernel {ms} ms of it; "
            f"{'no picture from the kernel' if came == 'none' else 'the kernel sent one'})"
        )
    kernel = page.evaluate(f'() => document.querySelector("{target}").kernelMs || []')
    if kernel:
        print(f"{css_class}: kernel ms per value median {statistics.median(kernel):.1f} "
              f"over {len(kernel)} values")  # fmt: skip
    toggles = []
    if toggle:
        select = page.locator(f"{v} select").first
        # every option in the report's run; the smoke run shows the row works with the first
        # (nearest: the anisotropic pictures drawn ahead after it took ~a minute of CI)
        for i in range(1 if tries == 1 else max(tries, len(toggle))):
            option = toggle[i % len(toggle)]
            toggles += latency(page, f"{v} select", ["change", "input"], img, "data-frames",
                               lambda o=option: select.select_option(o), 1)  # fmt: skip
        # a new filter: its pictures are drawn ahead again (a second or two of the kernel's
        # idle time); the next widget is timed once they are in the page
        wait_for_ahead(page, [css_class])
    return key, fps, settle, toggles, full


def first_drag_fps(page, css_class, label) -> tuple[float, int]:
    """Pictures per second while the slider ``label`` of ``css_class`` is dragged once (for
    ``PlaneExplorer``, a slider other than the one benchmarked before: its pictures drawn
    ahead may be in the page already, or come from the press while the kernel answers the
    drag's values), and how many of the drag's values went to the kernel (the release
    included)."""
    v = f".{css_class}"
    target, img = f"{v} input[type=range][aria-label^='{label}']", f"{v} .tr-drag img"
    page.locator(target).first.scroll_into_view_if_needed()
    sent = f'() => (document.querySelector("{target}").kernelMs || []).length'
    before = page.evaluate(sent)
    page.evaluate(COUNT, [img, "data-frames"])
    # pressed as a pointer presses it (the kernel hears of it), then dragged
    page.evaluate("(sel) => document.querySelector(sel).dispatchEvent("
                  "new PointerEvent('pointerdown', { bubbles: true }))", target)  # fmt: skip
    page.evaluate(DRAG_SLIDER, [target, TIMES["drag"]])
    wait_to_settle(page)
    times = page.evaluate("() => { const c = window.__count; c.ob.disconnect(); return c.t; }")
    end = page.evaluate("() => window.__dragEnd")
    during = [t for t in times if t <= end]
    fps = (len(during) - 1) / ((during[-1] - during[0]) / 1e3) if len(during) > 2 else 0.0
    return fps, page.evaluate(sent) - before


def first_drag_row(result) -> table.Row:
    """The report's row of :func:`first_drag_fps`'s ``(fps, values sent)``."""
    fps, values = result
    return table.fps("PlaneExplorer: f2, its first drag", [fps],
                     note=f"{values} of its values went to the kernel; v1 x was moved "
                          "before")  # fmt: skip


def slider_rows(results) -> list[tuple]:
    """The report rows of :func:`bench_slider`'s results (name -> its tuple)."""
    rows = []
    for name, (key, fps, settle, toggles, full) in results.items():
        none = all(x != x for x in full)  # NaN: no picture from the kernel after a key
        rows += [("click", f"{name}, one key (drawn ahead)", key),
                 table.info(f"{name}, one key, full picture (kernel)", [] if none else full,
                            "none sent: the picture drawn ahead is the full one" if none
                            else ""),
                 ("settle", f"{name}, last picture after a drag", settle),
                 ("fps", f"{name} dragged", fps)]  # fmt: skip
        if toggles:
            rows.append(("click", f"{name.split(':')[0]}: filter toggle (kernel)", toggles))
    return rows


def make_rows(specs, rt: float) -> list:
    """:class:`browser_table.Row` s from ``(kind, label, values)`` specs (kind: "click",
    "fps", "settle", "info"; or a Row as it is)."""
    makers = {"click": lambda label, v: table.click(label, v, rt), "fps": table.fps,
              "settle": table.settle, "info": table.info}  # fmt: skip
    return [spec if isinstance(spec, table.Row) else makers[spec[0]](*spec[1:]) for spec in specs]


def shots(page, folder: Path) -> None:
    """Screenshots of the player and the editor as a student sees them (1400 x 900)."""
    folder.mkdir(parents=True, exist_ok=True)
    for name in ("player", "editor"):
        page.locator(f".bench-{name}").first.scroll_into_view_if_needed()
        page.wait_for_timeout(300)
        page.screenshot(path=str(folder / f"{name}.png"))
        height = page.locator(f".bench-{name}").first.bounding_box()["height"]
        print(f"{name}: {height:.0f} px high")


def summary(label, ms, rt, target=""):
    med, top = statistics.median(ms), max(ms)
    print(f"{label:<46}{med:>8.1f}{top:>8.1f}{med / rt:>8.2f}  {target}")


class _Stopwatch:
    """Runs a part of the benchmark and tells stderr how long it took (where the run's time
    goes: the smoke run is part of CI)."""

    def __call__(self, name, fn, *args):
        start = time.perf_counter()
        try:
            return fn(*args)
        finally:
            print(f"bench: {name} took {time.perf_counter() - start:.1f} s", file=sys.stderr)


def run(page, args, tries: int, reps: int) -> tuple[list, float]:
    """Every interaction timed in the lab's page: the report's specs and the round trip."""
    # as it first shows (the interpolation toggle unfolds its comparison below)
    player_h = page.locator(".bench-player").first.bounding_box()["height"]
    if args.shots:
        shots(page, args.shots)
    took = _Stopwatch()
    rt, fig = took("baselines", bench_baselines, page, tries)
    frames = took("idle frames", bench_frames, page, tries)
    step, drag_fps, play_fps, toggles = took("player", bench_player, page, tries)
    editor = took("editor", vertex_drags, page, tries, VERTEX_DRAGS[:1])
    sliders = {name: took(name, bench_slider, page, tries, cls, label, toggle,
                          1 if args.quick else 3)
               for cls, name, label, toggle in SLIDERS}  # fmt: skip
    first_drag = took("first drag", first_drag_fps, page, "bench-plane", "f2")
    # the PlaneExplorer's vertex after its sliders: a vertex moved redraws their pictures
    # drawn ahead, which the slider rows above time
    plane = took("plane vertex", vertex_drags, page, tries, VERTEX_DRAGS[1:])
    explorables = took("explorables", bench_explorables, page, reps)
    controls = took("controls", bench_controls, page, reps)
    specs = [
        ("info", "baseline: do-nothing IntSlider -> Output (rt)", rt),
        ("info", "baseline: plain figure redrawn from a slider", fig),
        table.Row(
            "baseline: animation frames of the idle page",
            frames,
            "fps",
            note="the ceiling of every frame rate below",
        ),
        table.Row("FillPlayer: next step (in the page)", step, "ms", 20.0, "≤ 20 ms"),
    ]
    specs += [("click", f"FillPlayer: {n} toggle (kernel)", ms) for n, ms in toggles.items()]
    specs += [table.Row("FillPlayer: height of the whole player", [player_h], "px", 900.0,
                        "≤ 900 px"),
              table.fps("FillPlayer: step slider dragged", drag_fps, 50.0),
              table.fps("FillPlayer: play at 20 ms/step", play_fps, 40.0)]  # fmt: skip
    specs += editor
    specs += slider_rows(sliders)
    specs.append(first_drag_row(first_drag))
    specs += plane
    return specs + explorables + controls, statistics.median(rt)


def run_only(page, args, tries: int, chosen, drags) -> tuple[list, float]:
    """``--only``: the baselines, then the slider explorers ``chosen`` (``SLIDERS`` rows),
    then the figures whose vertices are dragged ``drags`` (``VERTEX_DRAGS`` rows)."""
    took = _Stopwatch()
    rt, fig = took("baselines", bench_baselines, page, tries)
    frames = took("idle frames", bench_frames, page, tries)
    sliders = {name: took(name, bench_slider, page, tries, cls, label, toggle,
                          1 if args.quick else 3)
               for cls, name, label, toggle in chosen}  # fmt: skip
    # f2 after v1 x, as in run
    plane = any(cls == "bench-plane" for cls, *_ in chosen)
    first = [took("first drag", first_drag_fps, page, "bench-plane", "f2")] if plane else []
    # the vertices after the sliders, as in run (a vertex moved redraws their pictures)
    drags = took("vertex drags", vertex_drags, page, tries, drags)
    specs = [("info", "baseline: do-nothing IntSlider -> Output (rt)", rt),
             ("info", "baseline: plain figure redrawn from a slider", fig),
             table.Row("baseline: animation frames of the idle page", frames, "fps",
                       note="the ceiling of every frame rate below")]  # fmt: skip
    specs += slider_rows(sliders) + [first_drag_row(f) for f in first]
    return specs + drags, statistics.median(rt)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="smoke run (CI): 1 try per latency (each toggle's options once), "
                             "1 per new row, 1 per drag")  # fmt: skip
    parser.add_argument("--tries", type=int, default=12, help="tries per latency (default 12)")
    parser.add_argument("--only", default=None, metavar="TEXT",
                        help="only the baselines and the slider explorers and dragged "
                             "figures whose name holds TEXT, or one of several "
                             "comma-separated (e.g. FilterExplorer; "
                             "PlaneExplorer: its sliders and its vertex; TriangleEditor): a "
                             "notebook of those cells alone")  # fmt: skip
    parser.add_argument("--shots", type=Path, default=None,
                        help="folder for screenshots of the player and the editor")  # fmt: skip
    args = parser.parse_args(argv)
    chosen = drags = None
    if args.only is not None:
        # several names, comma-separated: one run measures them under the same load
        wanted = [w.strip().lower() for w in args.only.split(",") if w.strip()]
        chosen = [s for s in SLIDERS if any(w in s[1].lower() for w in wanted)]
        drags = [d for d in VERTEX_DRAGS if any(w in d[1].lower() for w in wanted)]
        if not chosen and not drags:
            names = [s[1] for s in SLIDERS] + [d[1] for d in VERTEX_DRAGS]
            parser.error(f"--only {args.only!r}: none of " + ", ".join(names))
    # the smoke run shows every row works; its figures are not the report's (CI time): one
    # try of each action (a second press of the same key or button was the same path again)
    tries = 1 if args.quick else max(args.tries, 3)
    if args.quick:
        TIMES.update(drag=600, settle=1200)
        LEAST_DRAGS[0] = 1
    reps = 1 if args.quick else tries
    from playwright.sync_api import sync_playwright

    load = os.getloadavg()
    started = time.strftime("%d %b %Y %H:%M UTC", time.gmtime())
    work = Path(tempfile.mkdtemp(prefix="bench-browser-"))
    (work / "nb").mkdir()
    only = None if chosen is None else sorted({x[0] for x in [*chosen, *drags]})
    name = write_notebook(work / "nb", only, args.quick)
    proc, base, log = _Stopwatch()("lab start", start_lab, work)
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS, headless=True)
            try:
                page = browser.new_page(viewport={"width": 1400, "height": 900})
                ahead = None if only is None else [c for c in only if c in AHEAD]
                _Stopwatch()("lab and Run All", run_all_cells, page, base, name, ahead)
                if chosen is None:
                    specs, r = run(page, args, tries, reps)
                else:
                    specs, r = run_only(page, args, tries, chosen, drags)
            finally:
                browser.close()
    finally:
        stop_lab(proc, log)
        shutil.rmtree(work, ignore_errors=True)
    rows = make_rows(specs, r)
    end = os.getloadavg()
    print(f"\nteachraster in JupyterLab + headless Chromium, 1400x900, {started}; {tries} "
          f"{'try' if tries == 1 else 'tries'} per latency ({reps} per explorable or control, "
          f"{max(1, reps // 2)} drags each); "
          f"load average {load[0]:.1f} at the start, {end[0]:.1f} at the end; "
          f"rt = {r:.1f} ms\n")  # fmt: skip
    print(table.markdown(rows, r))
    missed = table.misses(rows)
    print(f"\n{len(missed)} of {sum(x.bound is not None for x in rows)} rows miss their target"
          + (": " + "; ".join(missed) if missed else ""))  # fmt: skip
    return 0


if __name__ == "__main__":
    sys.exit(main())
