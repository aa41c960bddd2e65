"""A labelled control keeps its label whole (``widgets.common.labelled``), in JupyterLab.

The browser probe of 2026-12-01 (issue 31) found DepthPrecisionExplorer's "format" label cut
to "forma" at 1400×900 (36 px shown of 43) and to nothing at 1024×768, the LinePlayer's
"rule" cut too, and the player's "method" and "interpolation" at 150 %. Every such label is
made by ``labelled``: it never shrinks below its text.

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright or Chromium is missing (CI makes them required).
"""

from __future__ import annotations

import pytest
from test_browser import WHY, lab, page  # noqa: F401
from test_browser_player import _run

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

CELLS = [
    "from teachraster.widgets import DepthPrecisionExplorer\n"
    "DepthPrecisionExplorer(backend='image')",
]
#: labels whose text is wider than their box (the box cuts them)
CUT = """() => [...document.querySelectorAll('.jp-OutputArea-output .widget-label')]
    .filter(l => l.offsetWidth > 0 && l.scrollWidth > l.clientWidth + 1)
    .map(l => [l.textContent, l.clientWidth, l.scrollWidth])"""
#: rows of controls wider than their box (cut at the column's edge, or scrolled)
WIDE = """() => [...document.querySelectorAll('.jp-OutputArea-output .widget-hbox')]
    .filter(r => r.offsetWidth > 0 && r.scrollWidth > r.clientWidth + 1)
    .map(r => [r.textContent.slice(0, 30), r.clientWidth, r.scrollWidth])"""

#: how many lines each group of toggle buttons takes
TOGGLE_ROWS = """() => [...document.querySelectorAll('.jp-OutputArea-output .widget-toggle-buttons')]
    .filter(g => g.offsetWidth > 0)
    .map(g => new Set([...g.querySelectorAll('button')].map(b => b.offsetTop)).size)"""


def test_labels_are_not_cut(lab, page):  # noqa: F811
    _run(page, lab, CELLS, "labels.ipynb")
    page.get_by_text("format", exact=True).first.wait_for(timeout=120_000)
    for size in ({"width": 1400, "height": 900}, {"width": 1024, "height": 768}):
        page.set_viewport_size(size)
        page.wait_for_timeout(500)
        assert page.evaluate(CUT) == [], size
        # the label's room is not taken from the column: a row too wide wraps (at
        # 1024 x 768 the explorer's row showed 203 px in a 127 px box)
        assert page.evaluate(WIDE) == [], size
        assert page.evaluate(TOGGLE_ROWS) == [1], size  # the format's toggles on one line
    page.set_viewport_size({"width": 1400, "height": 900})
