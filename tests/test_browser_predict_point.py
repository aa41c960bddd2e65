"""A ``PredictPoint`` with no ``along`` in headless Chromium, offline: the marker stays on the plot.

Review r215 07-3: lesson 07's q_behind marker, dragged past the plot's top-left corner, left
the picture and vanished; a press on the plot did not bring it back (only the arrow keys did,
and nothing said so), and Check graded the answer off the picture. Here the question's page
runs with no kernel (an offline page, every request aborted), so what the marker and Check do,
the page does by itself. Skipped, saying why, where Playwright or Chromium is missing.
"""

from __future__ import annotations

import json

import pytest
from test_page_offline import WHY, opened_offline

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]


def _question(**state):
    from teachraster.widgets import PredictPoint

    q = PredictPoint("Where does v3 land?", answer=(16.0, 8.0), draw=None, xlim=(0, 32),
                     ylim=(32, 0), start=(28.8, 28.8), tolerance=1.5, units="px")  # fmt: skip
    q.state = {**q.state, **state}
    return q


def _marker_at(page, q, x, y):
    """The page's point (x, y) in data units, as a mouse position on the screen."""
    canvas = page.locator(".tr-predict-box canvas")
    box = canvas.bounding_box()
    x0, y0, sx, sy = q.data["transform"]
    scale = box["width"] / q.data["size"][0]
    return box["x"] + (x0 + sx * x) * scale, box["y"] + (y0 + sy * y) * scale


def test_a_marker_dragged_off_the_plot_stays_on_its_edge(tmp_path):
    q = _question()
    page_file = tmp_path / "point.html"
    page_file.write_text(f"<!doctype html><html><body>{q.offline_html()}</body></html>")
    with opened_offline(page_file) as page:
        check = page.get_by_role("button", name="Check")
        check.wait_for(timeout=20_000)
        assert check.is_disabled()  # no answer yet
        assert "arrow keys" in page.locator(".tr-predict").inner_text()
        # drag from the marker far past the plot's top-left corner, to data (-40, -40)
        page.mouse.move(*_marker_at(page, q, 28.8, 28.8))
        page.mouse.down()
        page.mouse.move(*_marker_at(page, q, -40, -40), steps=15)
        page.mouse.up()
        assert check.is_enabled()
        # the marker stayed on the plot: drawn at its corner (0, 0), its orange ring in sight
        orange = page.evaluate(
            """([x, y]) => { const c = document.querySelector('.tr-predict-box canvas');
                const d = c.getContext('2d').getImageData(x - 12, y - 12, 25, 25).data;
                let n = 0;
                for (let k = 0; k < d.length; k += 4)
                  n += d[k] > 200 && d[k + 1] > 130 && d[k + 1] < 180 && d[k + 2] < 60;
                return n; }""",
            [round(v) for v in q.data["transform"][:2]],
        )
        assert orange > 20, orange
        check.click()
        # graded where it is: (0, 0), hypot(16, 8) = 17.9 px from the answer
        verdict = page.locator(".tr-predict-verdict").inner_text()
        assert verdict == ("Not quite. Your marker is 17.9 px from the answer (green); "
                           "within 1.5 px is right."), verdict  # fmt: skip


def test_an_answer_off_the_plot_keeps_check_disabled(tmp_path):
    """A saved state (a page from before r215) with the marker off the plot: no answer."""
    q = _question()
    page_file = tmp_path / "off.html"
    html = q.offline_html().replace(
        json.dumps(q.state, separators=(",", ":")),
        json.dumps({**q.state, "given": [-5, -5]}, separators=(",", ":")),
    )
    assert '"given":[-5,-5]' in html
    page_file.write_text(f"<!doctype html><html><body>{html}</body></html>")
    with opened_offline(page_file) as page:
        check = page.get_by_role("button", name="Check")
        check.wait_for(timeout=20_000)
        assert check.is_disabled()
        # one arrow key brings it back onto the plot: an answer, at the corner
        page.locator(".tr-predict-box canvas").focus()
        page.keyboard.press("ArrowRight")
        for _ in range(100):  # the key's handler runs a frame later on a loaded machine
            if check.is_enabled():
                break
            page.wait_for_timeout(50)
        assert check.is_enabled()
