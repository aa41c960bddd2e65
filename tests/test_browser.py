"""End to end in a real browser: lesson 01 in JupyterLab, driven like a student would.

JupyterLab runs on 127.0.0.1 (no token, a free port, its state in a temporary directory,
stopped by its PID afterwards) on a *copy* of the notebooks, so nothing in the repository is
written. Debian's Chromium, headless and driven by Playwright, opens lesson 01, runs all
cells, then presses Play and moves the step slider with the keyboard. Each action must change
the slider's value, the caption and the picture; the pictures are the kernel's (matplotlib
draws every step once) and reach the page on request, so this proves the whole kernel ->
page path of the page-side player.

Skipped, saying why, where Playwright or Chromium is missing; ``.ci/run`` installs both and
sets TEACHRASTER_REQUIRE_BROWSER so that in CI this test runs.
"""

from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LESSON = "01_span_tables.ipynb"
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
REQUIRED = bool(os.environ.get("TEACHRASTER_REQUIRE_BROWSER"))


def _unavailable() -> str | None:
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError as exc:
        return f"playwright is not installed ({exc})"
    if not Path(CHROMIUM).exists():
        return f"no Chromium at {CHROMIUM} (Debian: apt-get install chromium)"
    if shutil.which("jupyter", path=str(Path(sys.executable).parent)) is None:
        return "JupyterLab is not installed in this environment"
    return None


WHY = _unavailable()
if WHY and REQUIRED:
    raise RuntimeError(f"TEACHRASTER_REQUIRE_BROWSER is set but {WHY}")
pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """A JupyterLab server on a copy of notebooks/, stopped by its PID at the end."""
    work = tmp_path_factory.mktemp("lab")
    shutil.copytree(ROOT / "notebooks", work / "notebooks")
    settings = work / "settings"
    # No news toast over the page; every cell attached to the DOM (no virtual scrolling).
    (settings / "@jupyterlab/apputils-extension").mkdir(parents=True)
    (settings / "@jupyterlab/apputils-extension/notification.jupyterlab-settings").write_text(
        json.dumps({"fetchNews": "false", "checkForUpdates": False})
    )
    (settings / "@jupyterlab/notebook-extension").mkdir(parents=True)
    (settings / "@jupyterlab/notebook-extension/tracker.jupyterlab-settings").write_text(
        json.dumps({"windowingMode": "none"})
    )
    env = dict(
        os.environ,
        JUPYTER_CONFIG_DIR=str(work / "config"),
        JUPYTER_RUNTIME_DIR=str(work / "runtime"),
        JUPYTER_DATA_DIR=str(work / "data"),
        IPYTHONDIR=str(work / "ipython"),
    )
    env.pop("MPLBACKEND", None)  # the notebook chooses its own backend
    port = _free_port()
    log = open(work / "lab.log", "w")  # noqa: SIM115 (closed in the finaliser below)
    proc = subprocess.Popen(
        [
            sys.executable, "-m", "jupyter", "lab", "--no-browser", "--allow-root",
            "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}",
            "--ServerApp.port_retries=0", "--IdentityProvider.token=", "--ServerApp.password=",
            f"--ServerApp.root_dir={work / 'notebooks'}",
            f"--LabApp.user_settings_dir={settings}",
            f"--LabApp.workspaces_dir={work / 'workspaces'}",
        ],
        stdout=log, stderr=subprocess.STDOUT, env=env, cwd=work,
    )  # fmt: skip
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.time() + 90
        while True:
            try:
                urllib.request.urlopen(f"{base}/api/status", timeout=2)
                break
            except OSError:
                if proc.poll() is not None or time.time() > deadline:
                    raise RuntimeError(
                        "JupyterLab did not start:\n" + (work / "lab.log").read_text()[-3000:]
                    ) from None
                time.sleep(0.5)
        yield base
    finally:
        proc.terminate()  # the server shuts its kernels down on SIGTERM
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        log.close()


@pytest.fixture(scope="module")
def page(lab):
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
        context = browser.new_context(viewport={"width": 1400, "height": 1000})
        page = context.new_page()
        errors: list[str] = []
        page.on("pageerror", lambda exc: errors.append(str(exc)))
        page.errors = errors
        yield page
        browser.close()


def _wait_changed(read, before, what: str, timeout: float = 30.0):
    deadline = time.time() + timeout
    now = read()
    while now == before and time.time() < deadline:
        time.sleep(0.1)
        now = read()
    assert now != before, f"{what} did not change within {timeout:g} s"
    return now


def _shown_step(canvas) -> str:
    return canvas.get_attribute("data-step") or ""


def test_lesson_01_plays_and_steps_in_the_browser(lab, page, tmp_path):
    """The page-side player: arrow keys on the step slider and Play change the picture and
    the caption in the page; the kernel hears of the step when Play is paused."""
    from playwright.sync_api import expect

    page.goto(f"{lab}/lab/tree/{LESSON}")
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=90_000)
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")

    # The first fill player of the lesson: its step slider, play button, caption and frames.
    player = page.locator(".jp-OutputArea-output").filter(has=page.locator(".tr-frames")).first
    expect(player).to_be_visible(timeout=120_000)
    slider = player.get_by_role("slider", name="step")
    canvas = player.locator("canvas.teachraster-figure").first
    caption = player.locator(".teachraster-caption").first
    page.wait_for_function("el => el.dataset.step !== undefined", arg=canvas.element_handle(),
                           timeout=60_000)  # fmt: skip
    page.screenshot(path=str(tmp_path / "lesson01_start.png"), full_page=False)

    # 1. The keyboard: focus the slider and press the right arrow three times; JupyterLab's
    # command-mode shortcuts must not take the keys.
    value0 = int(slider.input_value())
    step0, text0 = _shown_step(canvas), caption.inner_text()
    slider.focus()
    for _ in range(3):
        slider.press("ArrowRight")
    expect(slider).to_have_value(str(value0 + 3), timeout=10_000)
    step1 = _wait_changed(lambda: _shown_step(canvas), step0, "the figure after the arrow keys")
    text1 = _wait_changed(caption.inner_text, text0, "the caption after the arrow keys")
    assert text1.strip(), "empty caption"

    # 2. Play (in the page) for a moment, then pause: the picture stops at once.
    player.get_by_role("button", name="play").click()
    page.wait_for_timeout(2000)
    player.get_by_role("button", name="pause").click()
    value2 = int(slider.input_value())
    assert value2 > value0 + 3, f"Play did not advance the slider ({value0 + 3} -> {value2})"
    paused = _wait_changed(lambda: _shown_step(canvas), step1, "the figure after Play")
    _wait_changed(caption.inner_text, text1, "the caption after Play")
    page.wait_for_timeout(500)
    assert _shown_step(canvas) == paused, "the picture changed after Pause"
    page.screenshot(path=str(tmp_path / "lesson01_played.png"), full_page=False)
    assert not page.errors, f"errors in the page: {page.errors[:3]}"


NOTEBOOKS = sorted(
    str(p.relative_to(ROOT / "notebooks")) for p in (ROOT / "notebooks").rglob("*.ipynb")
)


def _shut_down_kernels(base: str) -> None:
    """Stop every kernel the server runs, so notebooks opened one after another do not pile up."""
    try:
        with urllib.request.urlopen(f"{base}/api/kernels", timeout=10) as r:
            kernels = json.load(r)
        for k in kernels:
            req = urllib.request.Request(f"{base}/api/kernels/{k['id']}", method="DELETE")
            urllib.request.urlopen(req, timeout=10).close()
    except OSError:
        pass  # best effort: the server stops them all at the end anyway


@pytest.mark.parametrize("name", NOTEBOOKS)
def test_every_notebook_runs_in_the_browser(lab, page, name):
    """Every lesson and exercise notebook runs top to bottom in JupyterLab in Chromium, as a
    student would run it (Run All Cells): no error output, and its figures are on the page."""
    _shut_down_kernels(lab)
    # ?reset: a fresh workspace, so no tab of an earlier test is restored beside this one
    page.goto(f"{lab}/lab/tree/{name}?reset")
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=90_000)
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    n_code = page.locator(".jp-Notebook .jp-CodeCell").count()
    # Done when every code cell has an execution count ("[12]:"), none is queued or running.
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    try:
        page.wait_for_function(
            """n => {
                const prompts = [...document.querySelectorAll('.jp-Notebook .jp-CodeCell .jp-InputPrompt')];
                return prompts.length === n && prompts.every(p => /\\[\\d+\\]/.test(p.textContent));
            }""",
            arg=n_code,
            timeout=240_000,
        )
    except PlaywrightTimeout:
        prompts = page.locator(".jp-Notebook .jp-CodeCell .jp-InputPrompt").all_inner_texts()
        pytest.fail(f"{name}: not every cell ran within 240 s; prompts: {prompts}")
    errors = page.locator('.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.error"]')
    if errors.count():
        pytest.fail(f"{name}: error output in the browser:\n{errors.first.inner_text()[-2000:]}")
    figures = page.locator(".jp-OutputArea-output img")
    assert figures.count() > 0, f"{name}: no figure on the page"
    assert not page.errors, f"{name}: errors in the page: {page.errors[:3]}"
