"""A slider whose range the kernel changes: its End key reaches the new last value in the page.

Issue 31 (review r27, lesson 12): an ipywidgets 8 ``IntSlider`` is drawn by noUiSlider, whose
``updateOptions`` takes a new range for the pointer and the arrow keys but whose Home and End
keys keep the range the slider was created with (``options.spectrum``, never updated). The
TileExplorer's block slider (lesson 10) went from 0..68 blocks to 0..388 with the block
sizes 16 / 4 -> 16 / 4 / 1, and End stopped at 68. The widgets now put in a new slider
(:func:`teachraster.widgets.common.renew_slider`). The level slider, a range input of the
package's own (``LiveSlider``), changes its range in place: the browser's keys read its max.

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright or Chromium is missing (CI makes them required).
"""

from __future__ import annotations

import pytest
from test_browser import WHY, _shut_down_kernels, lab, page  # noqa: F401
from test_browser_explorables import _kernel
from test_browser_player import _run

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

CELLS = [
    "import json\nimport teachraster as tr\nfrom teachraster.widgets import TileExplorer\n"
    "from teachraster.widgets.line_player import LinePlayer\n"
    "ex = TileExplorer(tr.Triangle([[1, 1], [30, 6], [9, 29]]), 32, 32, block_sizes=(16, 4))\n"
    "ex",
    "player = LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, rule='bresenham', step=2)\nplayer",
]

#: The boxes from a slider up to its output that scroll sideways or hold more than their
#: width, and the slider itself where it reaches past its output's right edge
OVERFLOW = """(slider) => {
  const out = slider.closest('.jp-OutputArea-output');
  const found = [];
  for (let e = slider.parentElement; e && e !== out.parentElement; e = e.parentElement)
    if (e.scrollLeft !== 0 || e.scrollWidth > e.clientWidth)
      found.push(`${e.className.slice(0, 50)}: scrolled ${e.scrollLeft}, ${e.scrollWidth} px `
                 + `in ${e.clientWidth}`);
  const past = slider.getBoundingClientRect().right - out.getBoundingClientRect().right;
  if (past > 0.5) found.push(`slider ${past} px past the output`);
  return found;
}"""


def _end_then_home(tab, slider, top: int) -> tuple[str, str]:
    """The readout of the noUiSlider ``slider`` after End, then after Home, once its handle
    says the range ends at ``top`` (the new slider is in the page)."""
    handle = slider.locator(".noUi-handle").first
    tab.wait_for_function("([h, top]) => Number(h.getAttribute('aria-valuemax')) === top",
                          arg=[handle.element_handle(), top], timeout=30_000)  # fmt: skip
    readout = slider.locator(".widget-readout").first
    handle.scroll_into_view_if_needed()
    handle.focus()
    tab.keyboard.press("End")
    tab.wait_for_timeout(300)
    end = readout.inner_text()
    tab.keyboard.press("Home")
    tab.wait_for_timeout(300)
    return end, readout.inner_text()


def test_end_reaches_the_new_last_value_after_the_range_changes(lab, page):  # noqa: F811
    _run(page, lab, CELLS, "slider_range.ipynb")
    block = page.locator(".widget-slider", has_text="block").first
    block.wait_for(timeout=120_000)
    step = page.locator(".widget-slider", has_text="step").first
    step.wait_for(timeout=60_000)
    assert _end_then_home(page, block, 68) == ("68", "0")  # as created: 68 blocks
    page.keyboard.press("End")  # the walk's last block, then new sizes
    page.wait_for_timeout(300)
    # more blocks: the sizes menu, as a student picks it
    page.locator("select", has=page.locator("option", has_text="16 / 4 / 1")).first \
        .select_option(label="16 / 4 / 1")  # fmt: skip
    assert _kernel(page, "ex.block.max") == 388
    block = page.locator(".widget-slider", has_text="block").first
    # the new sizes renumber the blocks: the new slider reads 0, not the old 68 (review r45)
    assert _kernel(page, "ex.block.value") == 0
    handle = block.locator(".noUi-handle").first
    page.wait_for_function("h => Number(h.getAttribute('aria-valuemax')) === 388",
                           arg=handle.element_handle(), timeout=30_000)  # fmt: skip
    assert block.locator(".widget-readout").first.inner_text() == "0"
    assert _end_then_home(page, block, 388) == ("388", "0")  # End stopped at 68
    page.keyboard.press("End")
    page.wait_for_timeout(500)
    assert _kernel(page, "ex.block.value") == 388  # the kernel has it too
    # review r103 10-D: a number typed into the readout takes the walk there, and the explorer
    # stays put. The slider, 100 % wide plus ipywidgets' 2-px margins, overflowed its box by
    # 4 px, and the box scrolled to the readout being typed in, cutting the explorer's left
    # edge ("lock sizes", "evel 1")
    assert block.evaluate(OVERFLOW) == []  # as shown
    block.locator(".widget-readout").first.click()
    page.keyboard.press("Control+A")
    page.keyboard.type("200")
    assert block.evaluate(OVERFLOW) == []  # while typing
    page.keyboard.press("Enter")
    page.wait_for_timeout(500)
    assert _kernel(page, "ex.block.value") == 200
    assert block.evaluate(OVERFLOW) == []
    # the level slider, the package's own (a range input: its keys read the max it has now)
    # keeps its place: 0..1 became 0..2 in place, and End reaches 2
    level = page.locator(".tr-live-slider input[type=range]").first
    assert level.get_attribute("max") == "2"
    level.focus()
    page.keyboard.press("End")
    assert level.input_value() == "2"
    # the LinePlayer's step slider: Bresenham's 0..13 to the diamond rule's 0..14
    page.get_by_role("button", name="diamond", exact=True).click()
    assert _kernel(page, "player.slider.max") == 14
    step = page.locator(".widget-slider", has_text="step").first
    assert _end_then_home(page, step, 14) == ("14", "0")
    assert not page.errors, page.errors[:3]
