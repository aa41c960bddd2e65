"""A ``PredictChoice`` in headless Chromium with no kernel at all: Check at the pick.

Review r98, 07 (q_far): an ipywidgets ``Predict`` enabled Check only after the kernel had
heard of the pick, over a second later on a busy kernel (a student who clicked Check at once
got no response). A ``PredictChoice`` is judged in the page, as the figure predictions are:
here its page runs with no kernel behind it (an offline page, every request aborted), so
whatever Check does, the page does by itself. Skipped, saying why, where Playwright or
Chromium is missing.
"""

from __future__ import annotations

import pytest
from test_page_offline import WHY, opened_offline

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

CHOICES = ["under a pixel", "tens of pixels", "thousands of pixels"]


def test_a_choice_enables_check_at_the_pick_and_reveals_in_the_page(tmp_path):
    from teachraster.widgets import PredictChoice

    q = PredictChoice("How far can an edge move?", CHOICES, answer="thousands of pixels",
                      explain="One gap of 65,536 over the edge's length.")  # fmt: skip
    page_file = tmp_path / "choice.html"
    page_file.write_text(f"<!doctype html><html><body>{q.offline_html()}</body></html>")
    with opened_offline(page_file) as page:
        check = page.get_by_role("button", name="Check")
        check.wait_for(timeout=20_000)
        assert check.is_disabled()  # no answer yet
        pick = page.get_by_role("button", name="tens of pixels")
        pick.click()
        # at once, in the same turn of the page: no kernel is there to answer
        state = page.evaluate(
            """() => [...document.querySelectorAll('.tr-choices button, .tr-x-row button')]
                     .map(b => [b.textContent, b.disabled, b.getAttribute('aria-pressed')])"""
        )
        assert ["Check", False, None] in state, state
        assert ["tens of pixels", False, "true"] in state, state
        assert ["under a pixel", False, "false"] in state, state
        check.click()
        verdict = page.locator(".tr-predict-verdict")
        assert verdict.inner_text() == (
            "Not quite. You predicted tens of pixels; the answer is thousands of pixels."
        )
        assert "65,536" in page.locator(".tr-predict").inner_text()
        # checked once: the options and Check are locked, the right one and the pick marked
        assert check.is_disabled() and pick.is_disabled()
        assert "wrong" in (pick.get_attribute("class") or "")
        right = page.get_by_role("button", name="thousands of pixels")
        assert "right" in (right.get_attribute("class") or "")
