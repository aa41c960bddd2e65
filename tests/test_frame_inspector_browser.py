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
