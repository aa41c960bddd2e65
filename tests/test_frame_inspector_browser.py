"""The FrameInspector in a real browser: lesson 11 in JupyterLab (headless Chromium), a click
on the frame (the image display, a small anywidget that sends the clicked point to the
kernel) must change the pixel whose history the inspector shows.

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright or Chromium is missing (CI makes them required).
"""

from __future__ import annotations

import re

import pytest
from notebook_browser import open_file
from test_browser import WHY, _shut_down_kernels, _wait_changed, lab, page  # noqa: F401

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

LESSON = "11_debugging_a_frame.ipynb"


def test_clicking_the_frame_shows_that_pixels_history(lab, page):  # noqa: F811
    open_file(page, lab, LESSON)
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    image = page.locator("img.teachraster-clickable").last
    image.wait_for(state="visible", timeout=240_000)
    image.scroll_into_view_if_needed()
    table = page.locator(".jp-OutputArea-output pre", has_text="pixel (row").last
    table.wait_for(timeout=60_000)

    def pixel():
        found = re.search(r"pixel \(row (\d+), col (\d+)\)", table.inner_text())
        return found.groups() if found else None

    before = pixel()
    box = image.bounding_box()
    # the frame's axes fill the left three quarters of the figure: a point on its left side
    page.mouse.click(box["x"] + 0.25 * box["width"], box["y"] + 0.35 * box["height"])
    after = _wait_changed(pixel, before, "the inspected pixel")
    assert after is not None and after != before
    assert not page.errors, f"errors in the page: {page.errors[:3]}"


#: (text width, room) of the chosen option of each menu of the page, in CSS px: the text
#: measured in the menu's own font, the room its box leaves between its padding (a
#: <select> cuts its chosen option's text silently: its scrollWidth says nothing)
MENU_TEXT = """() => [...document.querySelectorAll('.widget-dropdown select')].map(s => {
  const style = getComputedStyle(s);
  const ctx = document.createElement('canvas').getContext('2d');
  ctx.font = `${style.fontStyle} ${style.fontWeight} ${style.fontSize} ${style.fontFamily}`;
  const text = s.options[s.selectedIndex] ? s.options[s.selectedIndex].text : '';
  const room = s.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
  return [text, Math.ceil(ctx.measureText(text).width), Math.floor(room)];
})"""


@pytest.mark.parametrize("app", ["lab/tree", "notebooks"])
def test_every_view_of_the_inspectors_menu_reads_in_full(lab, page, app):  # noqa: F811
    """Review r159 (lesson 11, 5): "nan (0 on built-in scenes)" was cut to "nan (0 on
    built-in scenes" in the 260-px view menu. Each view chosen in turn, its name fits the
    menu's box, in JupyterLab and Notebook 7."""
    from test_browser_player import _run

    cells = ["from teachraster.widgets import FrameInspector\n"
             "FrameInspector('intersecting_triangles', 64, 48, backend='image')"]  # fmt: skip
    _run(page, lab, cells, f"inspector_menu_{app.split('/')[0]}.ipynb", app=app)
    menu = page.get_by_role("combobox", name="view")
    menu.wait_for(timeout=120_000)
    labels = menu.locator("option").all_inner_texts()
    assert any(label.startswith("nan") for label in labels), labels
    for label in labels:
        menu.select_option(label=label)
        page.wait_for_timeout(300)
        cut = [(t, w, room) for t, w, room in page.evaluate(MENU_TEXT) if w > room]
        assert not cut, cut
    assert not page.errors, page.errors[:3]
