"""End to end in a real browser: lesson 01 in JupyterLab, driven like a student would.

JupyterLab runs on 127.0.0.1 (no token, a free port, its state in a temporary directory,
stopped by its PID afterwards) on a *copy* of the notebooks, so nothing in the repository is
written. Debian's Chromium, headless and driven by Playwright, opens lesson 01's player (its
setup, its triangle and its player cell: the whole lesson runs in the browser once per run,
``test_every_notebook_runs_in_the_browser``), runs all cells, then presses Play and moves
the step slider with the keyboard. Each action must change
the slider's value, the caption and the picture; the pictures are the kernel's (matplotlib
draws every step once) and reach the page on request, so this proves the whole kernel ->
page path of the page-side player.

Skipped, saying why, where Playwright or Chromium is missing; ``.ci/run`` installs both and
sets TEACHRASTER_REQUIRE_BROWSER so that in CI this test runs.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest
from notebook_browser import CHROMIUM as CHROMIUM  # the other browser tests read these here
from notebook_browser import CHROMIUM_ARGS as CHROMIUM_ARGS
from notebook_browser import POLL_MS, listed, open_cells, unavailable
from notebook_browser import _shut_down_kernels as _shut_down_kernels  # for the other files

ROOT = Path(__file__).resolve().parents[1]
LESSON = "01_span_tables.ipynb"
REQUIRED = bool(os.environ.get("TEACHRASTER_REQUIRE_BROWSER"))
_unavailable = unavailable

WHY = _unavailable()
if WHY and REQUIRED:
    raise RuntimeError(f"TEACHRASTER_REQUIRE_BROWSER is set but {WHY}")
pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]


@pytest.fixture(scope="module")
def lab():
    """This worker's JupyterLab server on a copy of notebooks/ (``notebook_browser``: one per
    worker, shared with the notebooks' runs). Module scope is safe: a worker runs its tests in
    collection order, browser and notebook tests first, and stops the server only after them
    (``conftest.pytest_runtest_teardown``)."""
    from notebook_browser import lab as running

    return running().base


@pytest.fixture(scope="module")
def page(lab):
    """This worker's Chromium page, its error list emptied."""
    from notebook_browser import lab as running

    page = running().page
    page.errors = running().errors
    del page.errors[:]
    return page


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


def player_cells(path: Path = ROOT / "notebooks" / LESSON) -> list[str]:
    """Lesson 01's cells its first player needs: the setup (the first code cell), the cell
    that makes ``W, H`` and ``tri``, and the player's cell. The player is the lesson's last
    cell: running all of the lesson here ran it a second time (~25 s of kernel, CI time)."""
    import nbformat

    code = [c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "code"]
    shape = next(s for s in code if "W, H = " in s and "tri = " in s)
    player = next(s for s in code if "= FillPlayer(tri, W, H" in s)
    assert code.index(shape) < code.index(player), "the triangle is made after the player"
    return [code[0], shape, player]


def test_lesson_01_plays_and_steps_in_the_browser(lab, page, tmp_path):
    """The page-side player: arrow keys on the step slider and Play change the picture and
    the caption in the page; the kernel hears of the step when Play is paused."""
    from playwright.sync_api import expect

    open_cells(page, lab, player_cells(), "lesson01_player.ipynb")
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")

    # The first fill player of the lesson: its step slider, play button, caption and frames.
    player = page.locator(".jp-OutputArea-output").filter(has=page.locator(".tr-frames")).first
    # waited for as a selector is (Playwright backs off between looks): ``expect`` looked
    # every few frames, 2.6 s of CPU per 15 s of the lesson's cells running, against 0.5
    player.wait_for(state="visible", timeout=120_000)
    slider = player.get_by_role("slider", name="step")
    canvas = player.locator("canvas.teachraster-figure").first
    caption = player.locator(".teachraster-caption").first
    page.wait_for_function("el => el.dataset.step !== undefined", arg=canvas.element_handle(),
                           timeout=60_000, polling=POLL_MS)  # fmt: skip
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
    assert not page.errors, f"errors in the page: {listed(page.errors)}"


def test_the_packages_console_warnings_count_as_page_errors(page):
    """What the page-side code says on the console when it recovers from something wrong (a
    picture it could not decode, a message whose buffers do not match it) starts with
    "teachraster:" and fails a browser test like an error; other console lines do not."""
    del page.errors[:]
    page.evaluate("""() => {
        console.warn("teachraster: a picture could not be decoded (a test)");
        console.log("not ours");
        console.warn("Teachraster is not the prefix");
    }""")
    deadline = time.time() + 10
    while not page.errors and time.time() < deadline:
        page.wait_for_timeout(50)
    page.wait_for_timeout(200)  # the other two, had they been kept
    found = list(page.errors)
    del page.errors[:]
    assert found == ["console warning: teachraster: a picture could not be decoded (a test)"]
    assert listed(["a", "b", "c", "d", *found]) == [*found, "a", "b", "c"]


def test_only_the_front_ends_own_disposed_rejection_is_left_out():
    """JupyterLab's ``Error("Disposed")`` (a notebook left before its session answered) is not
    the package's; anything else that merely mentions it still fails a test."""
    from notebook_browser import _keep_error

    kept: list = []
    for message in ["Disposed", "Error: Disposed while drawing", "teachraster: Disposed"]:
        _keep_error(kept, message)
    assert kept == ["Error: Disposed while drawing", "teachraster: Disposed"]


NOTEBOOKS = sorted(
    str(p.relative_to(ROOT / "notebooks")) for p in (ROOT / "notebooks").rglob("*.ipynb")
)


@pytest.mark.parametrize("name", NOTEBOOKS)
def test_every_notebook_runs_in_the_browser(name):
    """Every lesson and exercise notebook runs top to bottom in JupyterLab in Chromium, as a
    student would run it (Run All Cells): no error output, and its figures are on the page.

    This is the run every other test of the notebook reads (``notebook_runs``): each notebook
    is executed once per test run, here."""
    from notebook_runs import executed, in_browser

    assert in_browser(), "notebooks run headless although the browser is here"
    run = executed(name.removesuffix(".ipynb"))
    assert run.in_browser
    if run.error:
        pytest.fail(f"{name}: error output in the browser:\n{run.error[-2000:]}")
    assert run.figures_on_page > 0, f"{name}: no figure on the page"
    # the package's console warnings too ("teachraster: a picture could not be decoded ...")
    assert not run.page_errors, f"{name}: errors in the page: {listed(run.page_errors)}"
