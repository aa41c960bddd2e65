"""The page slider's flow control (``widgets/static/slider.js``) in headless Chromium, with a
stand-in for the widget model: no kernel, no JupyterLab.

A slider moved by an arrow key held down sends each step as a final value. The kernel
renders one value at a time (1-4 s for the FilterExplorer on a loaded machine), so sending
every step queued a minute of stale renders (review 08-09-r5, 09 item 2). At most
``IN_FLIGHT`` values may be unanswered; a final value that comes meanwhile waits, replaced
by the next, and the newest goes when an answer frees a slot.
Skipped, saying why, where Playwright or Chromium is missing.
"""

from __future__ import annotations

import json

import pytest
from test_page_offline import ARGS, CHROMIUM, WHY

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

#: a stand-in for the anywidget model: traits in a dict, messages to the kernel kept in
#: ``window.sent``, ``window.answer(seq)`` the kernel's "done"
HARNESS = """
async (code) => {
  const traits = {value: 3, min: 0, max: 40, step: 1, description: "tilt",
                  readout_format: ".0f", base: 0, link: ""};
  const handlers = {};
  const model = {
    get: (k) => traits[k],
    on: (evt, cb) => { (handlers[evt] = handlers[evt] || []).push(cb); },
    send: (msg) => window.sent.push(msg),
  };
  window.sent = [];
  window.answer = (seq) => (handlers["msg:custom"] || []).forEach((cb) =>
    cb({type: "done", seq, kernel_ms: 1}));
  const url = URL.createObjectURL(new Blob([code], {type: "text/javascript"}));
  const mod = await import(url);
  const el = document.createElement("div");
  document.body.append(el);
  mod.default.render({model, el});
}
"""


@pytest.fixture(scope="module")
def tab():
    from notebook_browser import driver

    from teachraster.widgets.live_slider import slider_js

    browser = driver().chromium.launch(executable_path=CHROMIUM, args=ARGS, headless=True)
    try:
        page = browser.new_page()
        errors: list[str] = []
        page.on("pageerror", lambda exc: errors.append(str(exc)))
        page.set_content("<html><body></body></html>")
        page.evaluate(HARNESS, slider_js())
        yield page
        assert not errors, errors[:3]
    finally:
        browser.close()


def _sent(page) -> list[dict]:
    return json.loads(page.evaluate("() => JSON.stringify(window.sent)"))


def test_a_held_arrow_key_sends_only_the_newest_value(tab):
    """Twenty presses with no answer: two values go (the limit), the rest wait; the first
    answer sends the newest position, final, and nothing between; once all are answered
    nothing more is sent. Before the fix every press was sent: 20 values queued."""
    handle = tab.locator(".tr-live-slider input[type=range]")
    handle.focus()
    for _ in range(20):
        tab.keyboard.press("ArrowRight")
    tab.wait_for_timeout(100)
    sent = _sent(tab)
    assert [m["value"] for m in sent] == [4, 5] and all(m["final"] for m in sent)
    assert handle.input_value() == "23"  # the slider itself moved every step
    tab.evaluate("() => window.answer(1)")
    sent = _sent(tab)
    assert len(sent) == 3 and sent[2]["value"] == 23 and sent[2]["final"]
    tab.evaluate("() => { window.answer(2); window.answer(3); }")
    tab.wait_for_timeout(100)
    assert len(_sent(tab)) == 3
    # a single press with the kernel free goes at once
    tab.keyboard.press("ArrowLeft")
    sent = _sent(tab)
    assert len(sent) == 4 and sent[3]["value"] == 22 and sent[3]["final"]
