"""Under ``%matplotlib widget`` (ipympl, which lessons 01 and 02 recommend for dragging), the
figures fit the notebook column in JupyterLab at 1400 x 900 with the file browser open.

An ipympl canvas does not scale down as an image does: a figure wider than the column is cut
off (its legend, its colour bars). A small notebook holds a figure as the lessons make them
(the classroom style, ``plt.subplots`` 9.2 inches wide, a colour bar and a legend) and the
widgets' own figures (the ``TriangleEditor``'s fill and comparison, the ``FillPlayer``'s
comparison unfolded); every canvas must lie inside its output area, and no label or toggle
of the widgets may be clipped.

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright, Chromium or ipympl is missing (CI makes the browser required).
"""

from __future__ import annotations

import pytest
from notebook_browser import POLL_MS
from test_browser import WHY, lab, page  # noqa: F401
from test_browser_saved import _run_all

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

NAME = "ipympl_fit.ipynb"
CELLS = [
    "%matplotlib widget\nimport matplotlib.pyplot as plt\nimport numpy as np\n"
    "import teachraster as tr\nfrom teachraster import plotting as tp\n"
    "from teachraster.widgets import FillPlayer, TriangleEditor\ntp.use_style('classroom')\n"
    "tri = tr.Triangle([[1.3, 1.2], [14.6, 4.7], [5.2, 14.1]], w=[1, 3, 6], "
    "attrs={'u': [0, 1, 0]})",
    # a figure as lessons 01/02 make them: two panels, a heatmap's colour bar, a legend
    "fig, (a, b) = plt.subplots(1, 2, figsize=(9.2, 5.6))\n"
    "im = a.imshow(np.random.default_rng(0).random((16, 16)))\nfig.colorbar(im, ax=a)\n"
    "b.plot([0, 1], [0, 1], label='an edge')\nb.legend(loc='upper right')\nplt.show()",
    "editor = TriangleEditor(tri, 16, 16)\neditor",
    "player = FillPlayer(tri, 16, 16)\nplayer.comparison.selected_index = 0\nplayer",
]


def test_ipympl_figures_fit_the_column(lab, page):  # noqa: F811
    pytest.importorskip("ipympl")
    _run_all(lab, page, CELLS, NAME)
    # the lesson figure, the editor's two and the player's comparison
    canvases = page.locator(".jupyter-matplotlib-canvas-div")
    page.wait_for_function(
        "() => document.querySelectorAll('.jupyter-matplotlib-canvas-div').length >= 4",
        timeout=120_000, polling=POLL_MS)  # fmt: skip
    page.wait_for_timeout(1500)  # sized once their first frame is in
    boxes = page.evaluate("""() => [...document.querySelectorAll('.jupyter-matplotlib-canvas-div')]
        .map(div => {
            const out = div.closest('.jp-OutputArea-output').getBoundingClientRect();
            const c = div.querySelector('canvas').getBoundingClientRect();
            return { left: c.left, right: c.right, width: c.width, outLeft: out.left,
                     outRight: out.right };
        })""")
    assert len(boxes) == canvases.count() >= 4
    for b in boxes:
        assert b["width"] > 200, b  # drawn, not collapsed
        assert b["left"] >= b["outLeft"] - 1 and b["right"] <= b["outRight"] + 1, (
            f"a canvas {b['width']:.0f} px wide is cut off by its column "
            f"({b['outRight'] - b['outLeft']:.0f} px): {b}"
        )
    # no clipped label or toggle (ipywidgets' default widths cut "method" to "metho")
    clipped = page.evaluate("""() => [...document.querySelectorAll(
            '.jp-OutputArea-output .widget-toggle-button, .jp-OutputArea-output .widget-label,'
            + ' .jp-OutputArea-output .widget-button, .jp-OutputArea-output select')]
        .filter(e => e.offsetParent !== null && e.scrollWidth > e.clientWidth + 1)
        .map(e => e.textContent.trim() || e.value)""")
    assert not clipped, f"clipped at 1400 x 900 with the file browser open: {clipped}"
