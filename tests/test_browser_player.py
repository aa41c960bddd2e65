"""The FillPlayer's controls in JupyterLab in headless Chromium: drawn icons, a speed menu.

The browser probe of 2026-12-01 (issue 31) found ⏮/⏭ shown as empty boxes on a machine
without an emoji font, and Play fixed at 400 ms a step (lesson 02's 172-step fill took 69 s).
The icons are now SVG drawn by the page, and a speed menu beside the step sets the interval
(the kernel's ``player.interval`` follows it).

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright or Chromium is missing (CI makes them required).
"""

from __future__ import annotations

import pytest
from notebook_browser import POLL_MS, open_cells
from test_browser import WHY, _shut_down_kernels, lab, page  # noqa: F401
from test_browser_explorables import _kernel

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]


@pytest.fixture(autouse=True)
def _own_errors(page):  # noqa: F811
    """Each test counts only the page errors of its own run: the module's tests share one page,
    and one "[anywidget] Failed to initialize model" under load used to fail every later test."""
    del page.errors[:]


PLAYER = [
    "import json\nimport teachraster as tr\nfrom teachraster.widgets import FillPlayer\n"
    "tri = tr.Triangle([[1.3, 1.2], [14.6, 4.7], [5.2, 14.1]])\n"
    "player = FillPlayer(tri, 16, 16, method='halfplane')\nplayer",
]


def _run(tab, base: str, cells, name: str, app: str = "lab/tree") -> None:
    """A notebook of ``cells`` written as ``name``, opened in ``app`` with a fresh kernel,
    every cell run."""
    tab.set_viewport_size({"width": 1400, "height": 900})
    open_cells(tab, base, cells, name, app=app)
    if app == "lab/tree":  # the kernel is up: JupyterLab's status bar says so
        tab.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)
    else:  # Notebook 7 has no status bar
        tab.wait_for_timeout(2000)
    tab.keyboard.press("Escape")
    tab.click(".lm-MenuBar-itemLabel:text-is('Run')")
    tab.click(".lm-Menu-itemLabel:text-is('Run All Cells')")


def test_the_players_icons_are_drawn_and_its_speed_is_chosen_in_the_page(lab, page):  # noqa: F811
    _run(page, lab, PLAYER, "player_controls.ipynb")
    player = page.locator(".tr-frames").first
    player.locator("canvas[data-step]").wait_for(timeout=120_000)
    bar = player.locator(".tr-bar")
    # icons drawn, not characters a font may lack (U+23EE, U+23ED showed as boxes)
    assert not any(c in bar.inner_text() for c in "\u23ee\u23ed\u25b6\u25c0\u23f8")
    buttons = bar.locator("button")
    assert buttons.count() == 5
    for b in buttons.all():
        box = b.locator("svg.tr-icon path").bounding_box()
        assert box and box["width"] >= 6 and box["height"] >= 6
    # the speed menu: the player's 400 ms (2.5 steps a second) chosen, faster ones offered
    speed = player.get_by_role("combobox", name="speed")
    assert speed.input_value() == "400" and player.get_attribute("data-interval") == "400"
    speed.select_option("40")
    assert player.get_attribute("data-interval") == "40"
    assert _kernel(page, "player.interval") == 40  # the kernel follows the menu
    # Play at that speed runs to the last step (and the button shows Pause meanwhile)
    player.get_by_role("button", name="play").click()
    assert player.get_by_role("button", name="pause").locator("svg.tr-icon").count() == 1
    slider = player.get_by_role("slider", name="step")
    page.wait_for_function("s => s.value === s.max", arg=slider.element_handle(), timeout=60_000,
                           polling=POLL_MS)  # fmt: skip
    player.get_by_role("button", name="play").wait_for(timeout=10_000)  # stopped at the end
    assert not page.errors, page.errors[:3]


NB7 = [
    *PLAYER,
    "from teachraster.widgets.live_slider import LiveSlider\n"
    "live = LiveSlider(value=3.0, min=0.0, max=10.0, step=1.0, description='live')\nlive",
    "import ipywidgets\nplain = ipywidgets.IntSlider(value=3, min=0, max=10, description='plain')\n"
    "plain",
    *(
        f"x{i} = {i}  # more cells below: a key taken by the notebook jumps to one"
        for i in range(6)
    ),
]
ACTIVE = (
    "() => [...document.querySelectorAll('.jp-Cell')]"
    ".findIndex(c => c.classList.contains('jp-mod-active'))"
)


def _three_right(tab, handle, read) -> tuple[str, str]:
    """Focus ``handle``, press the right arrow three times; the value read before and after
    (the active cell must not move meanwhile)."""
    handle.scroll_into_view_if_needed()
    handle.focus()
    before, active = read(), tab.evaluate(ACTIVE)
    for _ in range(3):
        tab.keyboard.press("ArrowRight")
    tab.wait_for_timeout(300)
    assert tab.evaluate(ACTIVE) == active, "the notebook took the key (the view jumped)"
    return before, read()


@pytest.mark.parametrize("app", ["notebooks", "lab/tree"])
def test_the_arrow_keys_move_the_sliders_not_the_notebook(lab, page, app):  # noqa: F811
    """Notebook 7 (``notebooks``) handles its shortcuts before the slider sees the key; the
    widgets mark the key as theirs (``data-lm-suppress-shortcuts``, ``static/keys.js``): the
    player's step, a page slider and a plain ipywidgets slider each move, and the active cell
    stays, there as in JupyterLab (``lab/tree``)."""
    _run(page, lab, NB7, "keys.ipynb", app=app)
    player = page.locator(".tr-frames").first
    player.locator("canvas[data-step]").wait_for(timeout=120_000)
    plain = page.locator(".widget-slider", has_text="plain").first
    plain.wait_for(timeout=60_000)
    step = player.get_by_role("slider", name="step")
    assert _three_right(page, step, step.input_value) == ("0", "3")
    live = page.locator(".tr-live-slider input[type=range]").first
    assert _three_right(page, live, live.input_value) == ("3", "6")
    handle = plain.locator(".noUi-handle").first
    readout = plain.locator(".widget-readout").first
    assert _three_right(page, handle, readout.inner_text) == ("3", "6")
    # Notebook 7's own "reading 'schema'" error never reaches page.errors
    # (notebook_browser.NOTEBOOK_7_ERROR); any error here is a widget's
    assert not page.errors, page.errors[:3]


COMPARED = [
    "import numpy as np\nimport teachraster as tr\nfrom teachraster.plotting import use_style\n"
    "from teachraster.widgets import FillPlayer\n"
    "style = use_style('classroom')  # as the lessons run it (large fonts: larger figures)",
    "tri = tr.Triangle([[1.5, 2.25], [14.75, 5.5], [4.25, 14.5]], w=[1.0, 2.0, 4.0],\n"
    "                  attrs={'u': [0.0, 1.0, 0.0]})  # lesson 04's\n"
    "player = FillPlayer(tri, 16, 16, method='halfplane', step=-1)\nplayer",
]
#: the height of the output holding the player (its title, controls, steps and comparison)
PLAYER_HEIGHT = """() => [...document.querySelectorAll('.jp-OutputArea-output')]
    .filter(o => o.querySelector('.tr-frames'))
    .map(o => Math.round(o.getBoundingClientRect().height))"""


def test_the_player_with_its_comparison_open_fits_the_screen(lab, page):  # noqa: F811
    """Issue 31: with its comparison open the player was 1,758 px tall at 1400 x 900 (its
    sliders and the figures they change never on screen together)."""
    _run(page, lab, COMPARED, "player_compared.ipynb")
    player = page.locator(".tr-frames").first
    player.locator("canvas[data-step]").wait_for(timeout=120_000)
    # review r208 00-2: the last step's caption says what opening it by its title does
    caption = player.locator(".tr-caption")
    assert "click the comparison's title below" in caption.inner_text()
    assert "close it to step again" in caption.inner_text()
    header = page.get_by_text("affine / perspective-correct", exact=False).first
    header.click()
    figure = page.locator(".jupyter-widget-Collapse-contents img.teachraster-figure").first
    page.wait_for_function("i => i.complete && i.naturalWidth > 100",
                           arg=figure.element_handle(), timeout=60_000)  # fmt: skip
    assert figure.bounding_box()["height"] > 300  # scaled to fit, not to a thumbnail
    # the steps fold meanwhile (a round trip to the kernel: the figure may be there first)
    player.wait_for(state="hidden", timeout=10_000)
    heights = page.evaluate(PLAYER_HEIGHT)
    assert len(heights) == 1 and heights[0] <= 900 - 40, heights  # 40: the notebook's toolbar
    header.click()  # closed: the steps are back, the player as tall as before
    player.locator("canvas[data-step]").wait_for(state="visible", timeout=10_000)
    assert page.evaluate(PLAYER_HEIGHT)[0] <= 900 - 40
    # the interpolation toggle opens it below the steps, which stay (review r7 00-2: pressing
    # "affine" took the whole step player away)
    page.get_by_role("button", name="affine", exact=True).click()
    figure.wait_for(state="visible", timeout=30_000)
    page.wait_for_timeout(1500)  # a fold would come with the kernel's answer: it is in
    assert player.is_visible() and player.locator("canvas[data-step]").is_visible()
    # r208 00-3: open, the caption no longer says to open it (the page relabels the step)
    page.wait_for_function(
        "c => c.textContent.endsWith('Both ways side by side: the comparison below.')",
        arg=caption.element_handle(), timeout=10_000,
    )  # fmt: skip
    assert "title" not in caption.inner_text()
    assert not page.errors, page.errors[:3]


#: what the player shows: the step its canvas paints (and the one it waits for), the readout,
#: the caption and the range's value
SHOWN = """p => ({step: p.querySelector('canvas').dataset.step,
    want: p.querySelector('canvas').dataset.want ?? null,
    info: p.querySelector('.tr-info').textContent,
    caption: p.querySelector('.tr-caption').textContent,
    value: p.querySelector('input[type=range]').value,
    max: p.querySelector('input[type=range]').max})"""
#: a cell that keeps the kernel busy after the player's, as a lesson's later cells do while
#: Run All goes on: the player's pictures wait for it
BUSY = "import time\ntime.sleep(12)  # the kernel busy: the player's pictures wait"


#: the second player of the first-key test (the first is PLAYER's): one key each, on one page
SECOND = "player_end = FillPlayer(tri, 16, 16, method='halfplane')\nplayer_end"
#: each player of the first-key test: (the kernel's name for it, the key pressed on its step)
KEYS = (("player", "ArrowRight"), ("player_end", "End"))


def _first_key(tab, player, key) -> tuple[dict, dict, str]:
    """``key`` pressed on ``player``'s focused step slider, the readout waited for: what it
    showed before and after, and the step it must come to."""
    handle = player.element_handle()
    first = tab.evaluate(SHOWN, handle)
    assert first["step"] == "0" and first["info"].startswith("0 of "), first
    step = player.get_by_role("slider", name="step")
    step.scroll_into_view_if_needed()
    step.focus()
    tab.keyboard.press(key)
    want = first["max"] if key == "End" else "1"
    tab.wait_for_function(
        f"p => ({SHOWN})(p).info.startsWith({want + ' of '!r})", arg=handle, timeout=3_000
    )
    now = tab.evaluate(SHOWN, handle)
    assert now["value"] == want and now["caption"] != first["caption"], now
    return first, now, want


def test_the_first_key_on_the_step_moves_the_readout_at_once(lab, page):  # noqa: F811
    """Review r99 02-5: on a fresh player the first key pressed on the focused step slider
    moved its handle (End: to the last step) while the readout and the picture stayed at
    step 0 ("0 of 172"): the picture of the new step had to come from a kernel still busy
    with the lesson's later cells, and the page changed the readout and the caption only
    with the picture. Now they follow the key at once, the old picture dimmed under a note
    (the player's only one) until the new one comes; then it is painted, and the kernel
    hears of the step.

    Two fresh players on one page, ArrowRight pressed on the first and End on the second,
    both while the kernel is busy (CI time: this was a test per key, each opening its own
    notebook, starting its own kernel and waiting out its own busy cell)."""
    _run(page, lab, [*PLAYER, SECOND, BUSY], "player_first_key.ipynb")
    players = page.locator(".tr-frames")
    for i in range(len(KEYS)):  # the posters, step 0
        players.nth(i).locator("canvas[data-step]").wait_for(timeout=120_000)
    pressed = []
    for i, (_, key) in enumerate(KEYS):
        pressed.append((players.nth(i), *_first_key(page, players.nth(i), key)))
    waiting = [(player, want) for player, _, now, want in pressed if now["step"] != want]
    for player, want in waiting:  # the picture on its way: said so over the old one
        assert player.evaluate(SHOWN)["want"] == want
        assert player.locator(".tr-wait").is_visible()
        assert f"drawing step {want}" in player.locator(".tr-wait").inner_text()
    if waiting:
        # past the 4 s after which a second note, "Waiting for the kernel…", came at the
        # picture's foot (review r9: two notes for one state): still the one step note
        page.wait_for_timeout(5_000)
    for player, want in waiting:
        stage = player.locator(".tr-stage")
        assert "Waiting" not in stage.inner_text() and player.locator(".tr-notice").count() == 0
        if player.evaluate(SHOWN)["want"] == want:
            assert player.locator(".tr-wait").inner_text().startswith(f"drawing step {want}")
    for (name, _), (player, _, now, want) in zip(KEYS, pressed):
        handle = player.element_handle()
        page.wait_for_function(  # the picture comes once the kernel is free
            f"p => ({SHOWN})(p).step === {want!r}", arg=handle, timeout=60_000,
            polling=POLL_MS,
        )  # fmt: skip
        done = page.evaluate(SHOWN, handle)
        assert done["want"] is None and not player.locator(".tr-wait").is_visible(), done
        assert done["info"] == now["info"] and done["caption"] == now["caption"], (now, done)
        assert _kernel(page, f"{name}.step") == int(want)  # the kernel heard of it
        assert _kernel(page, f"{name}.caption_text") == done["caption"]
    assert not page.errors, page.errors[:3]
