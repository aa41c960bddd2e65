"""Pictures drawn ahead, in the browser: the slider explorers' figures at every slider position
reach the page while the kernel idles; an arrow key or a drag then shows them with no kernel
in the loop, and each is the very picture the kernel draws for that position.

``DepthPrecisionExplorer``'s drafts and final pictures are the same (no colour bar, no note to
leave out), so the picture the page shows from its store at a key press must equal, pixel
for pixel, the one the kernel sends after it: that checks the reference picture, its
patches and the positions' numbering end to end. A drag of ``TexturedPlaneViewer``'s tilt
then sends the kernel nothing but the release.

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright or Chromium is missing (CI makes the browser required).
"""

from __future__ import annotations

import pytest
from test_browser import WHY, lab, page  # noqa: F401
from test_browser_saved import _run_all

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

NAME = "ahead.ipynb"
CELLS = [
    "from teachraster.widgets import TexturedPlaneViewer\n"
    "from teachraster.widgets.depth_explorer import DepthPrecisionExplorer",
    "depth = DepthPrecisionExplorer('unorm24', near=0.1, far=1000.0)\n"
    "depth.widget.add_class('t-depth')\ndepth",
    "viewer = TexturedPlaneViewer(64, 48, tilt=40)\nviewer.widget.add_class('t-viewer')\nviewer",
]
# every position of a widget's slider in its page store (data-ahead on the picture)
ALL_AHEAD = """(c) => { const r = document.querySelector(`.${c} input[type=range]`);
  const i = document.querySelector(`.${c} .tr-drag img`);
  if (!r || !i) return false;
  const n = Math.floor((Number(r.max) - Number(r.min)) / Number(r.step) + 1e-9) + 1;
  return i && Number(i.dataset.ahead || 0) >= n; }"""
# a hash of the picture on show: the canvas of patches over the <img> (the reference)
PIXELS = """(c) => { const cv = document.querySelector(`.${c} canvas.tr-drag-picture`);
  const d = cv.getContext('2d').getImageData(0, 0, cv.width, cv.height).data;
  let h = 0; for (let i = 0; i < d.length; i += 7) h = (h * 31 + d[i]) | 0; return h; }"""
FRAMES = "(c) => Number(document.querySelector(`.${c} .tr-drag img`).dataset.frames || 0)"


def test_pictures_drawn_ahead_are_shown_at_once_and_are_the_kernels(lab, page):  # noqa: F811
    _run_all(lab, page, CELLS, NAME)
    for cls in ("t-depth", "t-viewer"):
        page.wait_for_function(ALL_AHEAD, arg=cls, timeout=120_000)
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=60_000)

    # a key: the picture from the page's store at once, then the kernel's, the same pixels
    slider = page.locator(".t-depth input[type=range]").first
    slider.scroll_into_view_if_needed()
    for key in ("ArrowRight", "ArrowRight", "ArrowLeft"):
        before = page.evaluate(FRAMES, "t-depth")
        caption = page.locator(".t-depth .tr-drag-caption").inner_text()
        slider.press(key)
        page.wait_for_function(f"(c) => ({FRAMES})(c) >= {before + 1}", arg="t-depth")
        ahead = page.evaluate(PIXELS, "t-depth")
        assert page.locator(".t-depth .tr-drag-caption").inner_text() != caption
        page.wait_for_function(f"(c) => ({FRAMES})(c) >= {before + 2}", arg="t-depth",
                               timeout=30_000)  # fmt: skip
        assert page.evaluate(PIXELS, "t-depth") == ahead, f"{key}: the kernel drew otherwise"

    # a drag: pictures from the store, the kernel hears of the release only
    viewer = page.locator(".t-viewer input[type=range]").first
    viewer.scroll_into_view_if_needed()
    sent = "() => (document.querySelector('.t-viewer input[type=range]').kernelMs || []).length"
    before, frames = page.evaluate(sent), page.evaluate(FRAMES, "t-viewer")
    page.evaluate("""async () => {
        const r = document.querySelector('.t-viewer input[type=range]');
        r.dispatchEvent(new PointerEvent('pointerdown', { bubbles: true }));
        for (let v = 41; v <= 70; v++) {
            await new Promise(requestAnimationFrame);
            r.value = String(v);
            r.dispatchEvent(new Event('input', { bubbles: true }));
        }
        r.dispatchEvent(new Event('change', { bubbles: true }));
    }""")
    page.wait_for_function(f"() => ({sent})() >= {before + 1}", timeout=30_000)
    assert page.evaluate(sent) == before + 1  # the release, nothing else
    assert page.evaluate(FRAMES, "t-viewer") >= frames + 20  # pictures changed all the way
    assert not page.errors, page.errors
