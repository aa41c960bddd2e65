"""Run a notebook as a student does: Run All Cells in JupyterLab, in headless Chromium.

``notebook_runs.executed`` uses this in the full run, so that each notebook is executed once
per run *in the browser* and every test reads that one execution: the browser test (no error
output, figures on the page, no error in the page) and the tests that read what a lesson
printed, drew and kept in its globals. Before, each notebook ran twice, once headless under
nbclient and once in the browser.

One JupyterLab server and one Chromium per process (an xdist worker), started on first use on a
private copy of ``notebooks/`` and stopped when the process exits. The server's kernels start
with the probe of ``benchmarks/bench_notebooks.py`` (figure sizes, memory after every cell);
a worker runs one notebook at a time, so one probe log serves them all in turn.
"""

from __future__ import annotations

import atexit
import functools
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
# Playwright adds --headless itself; without the networking flags Chromium keeps trying to
# reach the internet, which this machine does not have.
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-dev-shm-usage",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-quic",
]
#: Longest a notebook may take to run all its cells in the browser.
RUN_SECONDS = 300
#: ``polling`` (ms) of a ``wait_for_function`` that waits on the kernel (a notebook's run, the
#: pictures drawn ahead): Playwright's default evaluates the predicate at every animation
#: frame, which keeps Chromium producing frames for the whole wait. On lesson 03's page that
#: cost 1.1-1.3 s of CPU per 15 s of waiting, every 250 ms nothing measurable over an idle
#: page (measured 2026-12-06); 100 ms adds at most a tenth of a second to such a wait.
POLL_MS = 100


def unavailable() -> str | None:
    """Why notebooks cannot run in the browser here, or None."""
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError as exc:
        return f"playwright is not installed ({exc})"
    if not Path(CHROMIUM).exists():
        return f"no Chromium at {CHROMIUM} (Debian: apt-get install chromium)"
    if shutil.which("jupyter", path=str(Path(sys.executable).parent)) is None:
        return "JupyterLab is not installed in this environment"
    return None


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _settings(folder: Path) -> None:
    """No news toast over the page; every cell attached to the DOM (no virtual scrolling)."""
    news = folder / "@jupyterlab/apputils-extension"
    news.mkdir(parents=True)
    (news / "notification.jupyterlab-settings").write_text(
        json.dumps({"fetchNews": "false", "checkForUpdates": False})
    )
    cells = folder / "@jupyterlab/notebook-extension"
    cells.mkdir(parents=True)
    (cells / "tracker.jupyterlab-settings").write_text(json.dumps({"windowingMode": "none"}))


#: nbgrader's server and page extensions: a test dependency (``teachraster[dev]``), not in a
#: student's JupyterLab (``teachraster[lab]``). Left on, the server imported nbgrader at each
#: start (3.2 s) and every page load activated its four page plugins, which ask the server
#: for courses and assignments; no browser test uses them (test_nbgrader runs nbgrader alone).
NBGRADER_SERVER_EXTENSIONS = tuple(
    f"nbgrader.server_extensions.{name}"
    for name in ("formgrader", "validate_assignment", "assignment_list", "course_list")
)


def _page_config(config: Path) -> None:
    """The page extensions the test server's pages leave out: nbgrader's
    (:data:`NBGRADER_SERVER_EXTENSIONS`) and MathJax, whose typesetting cost Chromium about 2 s
    of CPU a lesson (about 45 s a run, measured 2026-12-06 on lessons 00, 03, 09) and which no
    browser test reads: the lessons' formulas are checked in their sources and in the exported
    pages' MathML (tests/test_page_math.py)."""
    labconfig = config / "labconfig"
    labconfig.mkdir(parents=True, exist_ok=True)
    disabled = {"@jupyter/nbgrader": True, "@jupyterlab/mathjax-extension": True}
    (labconfig / "page_config.json").write_text(json.dumps({"disabledExtensions": disabled}))


@dataclass
class Lab:
    """A JupyterLab server on a copy of ``notebooks/`` and a Chromium page open on it."""

    base: str
    root: Path
    probe_log: Path
    process: subprocess.Popen
    page: object
    errors: list
    stop_browser: object

    def stop(self) -> None:
        try:
            self.stop_browser()
        finally:
            self.process.terminate()  # the server shuts its kernels down on SIGTERM
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()


def _start_server(work: Path, env: dict) -> tuple[str, subprocess.Popen]:
    port = _free_port()
    log = open(work / "lab.log", "w")  # noqa: SIM115 (the server writes it until it stops)
    process = subprocess.Popen(
        [
            sys.executable, "-m", "jupyter", "lab", "--no-browser", "--allow-root",
            "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}",
            "--ServerApp.port_retries=0", "--IdentityProvider.token=", "--ServerApp.password=",
            # the tests stop kernels through the REST API, which has no XSRF cookie: without
            # this every DELETE was refused (403) and each run's kernel stayed alive, 27 idle
            # kernels by the end of a run (memory, and CPU for their heartbeats)
            "--ServerApp.disable_check_xsrf=True",
            f"--ServerApp.root_dir={work / 'notebooks'}",
            f"--LabApp.user_settings_dir={work / 'settings'}",
            f"--LabApp.workspaces_dir={work / 'workspaces'}",
            *(f"--ServerApp.jpserver_extensions={name}=False"
              for name in NBGRADER_SERVER_EXTENSIONS),
        ],
        stdout=log, stderr=subprocess.STDOUT, env=env, cwd=work,
    )  # fmt: skip
    base = f"http://127.0.0.1:{port}"
    deadline = time.time() + 90
    while True:
        try:
            urllib.request.urlopen(f"{base}/api/status", timeout=2).close()
            return base, process
        except OSError:
            if process.poll() is not None or time.time() > deadline:
                process.kill()
                raise RuntimeError(
                    "JupyterLab did not start:\n" + (work / "lab.log").read_text()[-3000:]
                ) from None
            time.sleep(0.5)


@functools.cache
def driver():
    """This process's Playwright (sync API), started once and stopped at exit: one thread can
    hold only one, so every browser test of a worker launches its browsers from this one."""
    from playwright.sync_api import sync_playwright

    return sync_playwright().start()


@functools.cache
def lab() -> Lab:
    """This process's server and browser (started once, stopped at exit)."""
    import notebook_runs

    work = Path(tempfile.mkdtemp(prefix="teachraster-lab-"))
    shutil.copytree(ROOT / "notebooks", work / "notebooks")
    _settings(work / "settings")
    _page_config(work / "config")
    env = dict(
        os.environ,
        JUPYTER_CONFIG_DIR=str(work / "config"),
        JUPYTER_RUNTIME_DIR=str(work / "runtime"),
        JUPYTER_DATA_DIR=str(work / "data"),
    )
    env.pop("MPLBACKEND", None)  # the notebook chooses its own backend, as a student's does
    log = work / "probe.json"
    env.update(notebook_runs._bench().probe_environment(work / "ipython", log))
    base, process = _start_server(work, env)
    browser = driver().chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
    page = browser.new_context(viewport={"width": 1400, "height": 1000}).new_page()
    errors: list[str] = []
    page.on("pageerror", lambda exc: _keep_error(errors, str(exc)))
    page.on("console", lambda message: _keep_warning(errors, message.type, message.text))
    return Lab(base, work / "notebooks", log, process, page, errors, browser.close)


#: Notebook 7's own error when it opens a page of a server a JupyterLab page used before
#: (nothing visible; the browser probe of 2026-12-01 saw it too). It can arrive after the
#: next test started on the same page, so it is left out here, for every test.
NOTEBOOK_7_ERROR = "reading 'schema'"

#: JupyterLab's and Notebook 7's own rejection, word for word, when a notebook's session or
#: document context is disposed while a request of it is still under way (``changeKernel``,
#: ``_handleNewSession``, ``_maybeSave`` in @jupyterlab/apputils and docregistry: ``throw
#: Error("Disposed")``): the page leaves a notebook for the next one before the server
#: answered. Seen once in 2026-12-06's CI run (stop 51) during the layout test in Notebook 7;
#: the package's page-side code throws no such error (its errors name themselves).
FRONT_END_DISPOSED = "Disposed"


def _keep_error(errors: list, message: str) -> None:
    if NOTEBOOK_7_ERROR not in message and message.strip() != FRONT_END_DISPOSED:
        errors.append(message)


#: What the package's page-side code says when something went wrong that it could recover
#: from (a picture that could not be decoded, a message whose pictures do not match it): the
#: page carries on, so only the console tells, and a browser test fails on it as on an error.
WARNING_PREFIX = "teachraster:"


def _keep_warning(errors: list, kind: str, text: str) -> None:
    if text.startswith(WARNING_PREFIX):
        errors.append(f"console {kind}: {text}")


def listed(errors) -> list:
    """The page's errors for a failure message: every one of the package's console warnings
    (each tells what went wrong with which picture), then the first three others."""
    warnings = [e for e in errors if e.startswith("console ")]
    return warnings + [e for e in errors if e not in warnings][:3]


def _shut_down_kernels(base: str) -> None:
    """Stop every kernel (closing its session), so notebooks run one after another do not
    pile up in memory; a refused request raises (it once failed silently for a whole run).

    This process's page leaves its notebook first (closes its tabs, which closes their
    connections to the kernels, or goes to about:blank). Its players still fetch
    groups in the background, and a kernel that exits while it sends can glue two messages'
    frames together (a zero-copy send raising mid-message once pyzmq's garbage collector is
    down: "zmq gc socket requested during shutdown" in the server's log): the page got a
    group whose buffers were the next message's frames, and its error about them came after
    the run's errors were read, counted against the next notebook (lesson 03 after 02)."""
    if lab.cache_info().currsize and not _close_all_tabs(lab().page, base):
        lab().page.goto("about:blank")
    try:
        for what in ("sessions", "kernels"):
            with urllib.request.urlopen(f"{base}/api/{what}", timeout=10) as r:
                ids = [item["id"] for item in json.load(r)]
            for i in ids:
                req = urllib.request.Request(f"{base}/api/{what}/{i}", method="DELETE")
                urllib.request.urlopen(req, timeout=30).close()
    except urllib.error.HTTPError:
        raise
    except OSError:
        pass  # the server is gone: nothing left to stop


#: Done when no cell is queued or running and the last cell (the test's, never collapsed) ran,
#: or a cell raised (Run All stops there, as it does for a student). A collapsed cell
#: (``source_hidden``: the Predict cells) shows no prompt, so the last one is the witness.
_FINISHED = """n => {
    const prompts = [...document.querySelectorAll('.jp-Notebook .jp-CodeCell .jp-InputPrompt')];
    if (prompts.length !== n || prompts.some(p => p.textContent.includes('*'))) return false;
    const failed = document.querySelector(
        '.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.error"]');
    return failed !== null || /\\[\\d+\\]/.test(prompts[n - 1].textContent);
}"""


def _menu(page, menu: str, item: str) -> None:
    page.click(f".lm-MenuBar-itemLabel:text-is('{menu}')", timeout=MENU_MS)
    page.click(f".lm-Menu-itemLabel:text-is('{item}')", timeout=MENU_MS)


#: How long a menu or dialog of an open JupyterLab may take to answer before the page is
#: loaded again instead (a loaded machine: the page's own work is queued behind the kernel's).
MENU_MS = 15_000
#: A cell of the notebook on show: a tab of an earlier notebook that is still closing keeps
#: its cells in the page, hidden, and the first cell in the page can be one of those (a CI
#: run waited 90 s on such a hidden cell of five).
CELL_SHOWN = ".jp-Notebook .jp-Cell >> visible=true"


#: Every tab closed, or a "Save changes?" dialog waiting for an answer.
_CLOSED_OR_ASKING = """() => document.querySelector('.jp-Dialog')
    || !document.querySelector('.jp-Notebook')"""


def _close_all_tabs(page, base: str) -> bool:
    """Close every tab of the JupyterLab page (discarding changes), if the page is one of
    this server's; True when it was and no notebook is left open in it."""
    from playwright.sync_api import Error

    if not page.url.startswith(f"{base}/lab"):
        return False
    try:
        _menu(page, "File", "Close All Tabs")
        for _ in range(8):  # one "Save changes?" per changed notebook
            # A dirty tab asks before it closes (its notebook stays in the page meanwhile), so
            # "no notebook and no dialog" is the end, not a moment between two dialogs. Waited
            # for, rather than a dialog for 1 s each time: that second was spent on every
            # clean close, twice per notebook run (2 s of each of a run's 27 notebooks).
            page.wait_for_function(_CLOSED_OR_ASKING, timeout=MENU_MS)
            dialog = page.query_selector(".jp-Dialog")
            discard = dialog and dialog.query_selector("button:has-text('Discard')")
            if not discard:
                break  # every tab closed; or a dialog of another kind: checked below
            discard.click(timeout=MENU_MS)
            dialog.wait_for_element_state("hidden", timeout=MENU_MS)  # gone (or detached)
    except Error:
        pass  # a menu or dialog did not answer: checked below
    try:
        page.wait_for_function(
            "() => !document.querySelector('.jp-Notebook, .jp-Dialog')", timeout=MENU_MS
        )
    except Error:
        return False
    return True


def _open_notebook(page, base: str, name: str, in_app: bool) -> None:
    """Open notebook ``name`` (a path under the server's root) alone in the page.

    In the JupyterLab already loaded (``in_app``: its tabs were closed), through its own
    File menu: loading JupyterLab again costs the browser 3 to 4 s of CPU, for each of the
    27 notebooks of a run. Otherwise, or if the menu does not answer, the page is loaded
    again (?reset: a fresh workspace, so no tab of an earlier notebook is restored beside
    this one).
    """
    from playwright.sync_api import Error

    if in_app:
        try:
            _menu(page, "File", "Open from Path…")
            page.locator(".jp-Dialog input").fill(name, timeout=MENU_MS)
            page.keyboard.press("Enter")
            current = ".lm-DockPanel-tabBar .lm-TabBar-tab.lm-mod-current"
            tab = page.locator(current, has_text=name.rsplit("/", 1)[-1])
            tab.wait_for(timeout=60_000)
            return
        except Error:
            pass
    page.goto(f"{base}/lab/tree/{name}?reset")


#: A REST call from a page of the server (the server wants the page's XSRF cookie on writes).
API = """async ([method, path, body]) => {
  const xsrf = (document.cookie.match(/_xsrf=([^;]+)/) || [])[1] || "";
  const r = await fetch(path, { method, body, headers: { "X-XSRFToken": xsrf,
    "Content-Type": "application/json" } });
  return r.status;
}"""


def put_notebook(page, cells, name: str) -> None:
    """Write a notebook of ``cells`` (code) to the server's folder as ``name``, from ``page``
    (one of the server's pages)."""
    import nbformat

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in cells]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}  # fmt: skip
    body = json.dumps({"type": "notebook", "format": "json", "content": nb})
    assert page.evaluate(API, ["PUT", f"/api/contents/{name}", body]) in (200, 201)


def save_and_read(page, base: str, name: str) -> dict:
    """Save the open notebook as a student's File > Save does, and read back what the server
    stored for ``name`` (its cells with their outputs)."""
    page.click(".lm-MenuBar-itemLabel:text-is('File')")
    page.click(".lm-Menu-itemLabel:text-is('Save Notebook')")
    page.wait_for_function(
        "() => !document.querySelector('.jp-mod-current.jp-mod-dirty')", timeout=30_000
    )
    with urllib.request.urlopen(f"{base}/api/contents/{name}", timeout=30) as r:
        return json.load(r)["content"]


def open_cells(page, base: str, cells, name: str, app: str = "lab/tree") -> None:
    """A notebook of ``cells`` written as ``name`` and opened alone in ``app`` ("lab/tree",
    JupyterLab, or "notebooks", Notebook 7) with a fresh kernel; not run.

    Every kernel is stopped first. In JupyterLab the page already loaded opens it through its
    own File menu (``_open_notebook``): a page load costs the browser 3 to 4 s of CPU, and
    these tests opened some twenty notebooks of their own, two loads each."""
    _shut_down_kernels(base)  # closes this page's tabs when it is the lab's
    if not (app == "lab/tree" and _lab_is_empty(page, base)):
        page.goto(f"{base}/lab?reset")  # the REST calls go from a page of the server
        page.wait_for_selector("#jp-main-statusbar", timeout=90_000)
    put_notebook(page, cells, name)
    if app == "lab/tree":
        _open_notebook(page, base, name, in_app=True)
    else:
        page.goto(f"{base}/{app}/{name}")
    page.wait_for_selector(CELL_SHOWN, timeout=90_000)


#: JupyterLab's status bar once the open notebook's kernel waits for work.
IDLE = "#jp-main-statusbar >> text=/\\| Idle/"


def wait_until_idle(page, base: str, name: str, timeout: int = 60_000) -> None:
    """Wait for the kernel of notebook ``name``, just opened, to be idle; if it never gets
    there, load the notebook's page again once (?reset) and wait again.

    CI's stop 58: after "Open from Path…" in the loaded page the status bar showed no
    "| Idle" for 90 s (seen once in some 300 openings; every local run reached it). What
    the tests check comes after the kernel is up, so a kernel that did not start is tried
    again once; a second failure says what the status bar showed both times."""
    from playwright.sync_api import Error

    try:
        page.wait_for_selector(IDLE, timeout=timeout)
        return
    except Error:
        first = _status_text(page)
    page.goto(f"{base}/lab/tree/{name}?reset")
    page.wait_for_selector(CELL_SHOWN, timeout=90_000)
    try:
        page.wait_for_selector(IDLE, timeout=90_000)
    except Error as error:
        raise AssertionError(
            f"{name}: no idle kernel; the status bar said {first!r}, "
            f"then after a reload {_status_text(page)!r}"
        ) from error


def _status_text(page) -> str:
    """What JupyterLab's status bar shows ("" when it is not in the page)."""
    bar = page.query_selector("#jp-main-statusbar")
    return bar.inner_text() if bar else ""


def _lab_is_empty(page, base: str) -> bool:
    """The page is this server's JupyterLab with no notebook or dialog open."""
    return page.url.startswith(f"{base}/lab") and page.evaluate(
        "() => !document.querySelector('.jp-Notebook, .jp-Dialog')"
    )


def open_file(page, base: str, name: str) -> None:
    """Open notebook ``name`` (under the server's root) alone in JupyterLab with a fresh
    kernel, in the page already loaded where it can (``open_cells``); not run."""
    _shut_down_kernels(base)
    _open_notebook(page, base, name, in_app=_lab_is_empty(page, base))
    page.wait_for_selector(CELL_SHOWN, timeout=90_000)


@dataclass(frozen=True)
class BrowserRun:
    """What the page showed after Run All Cells, and the notebook as JupyterLab saved it."""

    text: str
    error: str
    figures: int
    page_errors: tuple
    probe_record: dict | None
    seconds: float


def run_all(name: str, extra_source: str) -> BrowserRun:
    """Run notebook ``name`` (relative to ``notebooks/``, no suffix) with ``extra_source`` as a
    last cell, in JupyterLab, and save it; the notebook's own copy is never touched."""
    import nbformat

    running = lab()
    page, path = running.page, running.root / f"{name}.ipynb"
    nb = nbformat.read(ROOT / "notebooks" / f"{name}.ipynb", as_version=4)
    nb.cells.append(nbformat.v4.new_code_cell(extra_source))
    nbformat.write(nb, path)
    running.probe_log.unlink(missing_ok=True)
    _shut_down_kernels(running.base)  # the page left the last notebook (closed its tab)
    emptied = (
        page.url.startswith(f"{running.base}/lab") and not page.locator(".jp-Notebook").count()
    )
    del running.errors[:]
    start = time.perf_counter()
    _open_notebook(page, running.base, f"{name}.ipynb", emptied)
    page.wait_for_selector(CELL_SHOWN, timeout=90_000)
    wait_until_idle(page, running.base, f"{name}.ipynb")
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    n_code = page.locator(".jp-Notebook .jp-CodeCell").count()
    page.wait_for_function(_FINISHED, arg=n_code, timeout=RUN_SECONDS * 1000, polling=POLL_MS)
    seconds = time.perf_counter() - start
    failed = page.locator('.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.error"]')
    error = failed.first.inner_text()[-4000:] if failed.count() else ""
    figures = page.locator(".jp-OutputArea-output img").count()
    _save(page, path)
    saved = nbformat.read(path, as_version=4)
    shutil.copyfile(ROOT / "notebooks" / f"{name}.ipynb", path)  # as it was, for the next test
    saved.cells.pop()  # the extra cell is the test's, not the notebook's
    record = json.loads(running.probe_log.read_text()) if running.probe_log.exists() else None
    _shut_down_kernels(running.base)
    return BrowserRun(
        nbformat.writes(saved), error, figures, tuple(running.errors), record, seconds
    )


def _save(page, path: Path, tries: int = 4) -> None:
    """Save the notebook (its outputs are what the tests read) and wait until it is on disk.

    Saved means written and clean. A save is asked again every 15 s: a menu click can be lost
    while the page is busy, and a widget whose state changes after the save (a picture drawn
    ahead arriving late) marks the notebook dirty again. After ``tries`` saves, written is
    enough: the file on disk is whole (JupyterLab writes atomically), only not the very last
    widget state."""
    before = path.stat().st_mtime_ns
    for attempt in range(tries):
        page.click(".lm-MenuBar-itemLabel:text-is('File')")  # the menu: no widget takes the keys
        page.click(".lm-Menu-itemLabel:text-is('Save Notebook')")
        deadline = time.time() + 15
        while time.time() < deadline:
            written = path.stat().st_mtime_ns != before
            if written and not page.locator(".jp-mod-dirty").count():
                return
            time.sleep(0.2)
        if written and attempt == tries - 1:
            return
    raise RuntimeError(f"JupyterLab did not save {path.name} in {tries} tries of 15 s")


def stop() -> None:
    """Stop this process's server, browser and Playwright, if started (``conftest`` calls it
    when the browser tests are through: a started Playwright marks the thread's asyncio loop as
    running between its calls, and code that schedules work on a running loop, like the
    widgets' ``later``, would wait for it forever)."""
    import asyncio

    if lab.cache_info().currsize:
        lab().stop()
        lab.cache_clear()
    if driver.cache_info().currsize:
        driver().stop()
        driver.cache_clear()
    asyncio._set_running_loop(None)


atexit.register(stop)
