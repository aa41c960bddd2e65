"""The offline page of a fill (``teachraster fill ... -o fill.html``) in Chromium, no network.

The page is opened from a file, alone in its folder, with every non-file request aborted:
it must step (the next button and the step slider show at least three distinct pictures)
and play (the picture changes at least three times in two seconds), and ask for nothing.
Skipped, saying why, where Playwright or Chromium is missing.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
ARGS = ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync"]  # fmt: skip


def _unavailable() -> str | None:
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError as exc:
        return f"playwright is not installed ({exc})"
    if not Path(CHROMIUM).exists():
        return f"no Chromium at {CHROMIUM}"
    return None


WHY = _unavailable()
if WHY and os.environ.get("TEACHRASTER_REQUIRE_BROWSER"):
    raise RuntimeError(f"TEACHRASTER_REQUIRE_BROWSER is set but {WHY}")
pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]


def _picture(page) -> str:
    """A fingerprint of the canvas' pixels."""
    return page.evaluate(
        "() => { const c = document.querySelector('canvas.teachraster-figure');"
        " return c.toDataURL('image/png').length + ':' + c.dataset.step + ':' +"
        " c.toDataURL('image/png').slice(-200); }"
    )


@pytest.fixture(scope="module")
def offline_page(tmp_path_factory):
    from teachraster.cli import main

    folder = tmp_path_factory.mktemp("alone")
    out = folder / "fill.html"
    main(
        [
            "fill",
            "--xy",
            "1,1 11,3 4,10",
            "--method",
            "halfplane",
            "--size",
            "12x12",
            "-o",
            str(out),
            "--quiet",
        ]
    )
    assert sorted(p.name for p in folder.iterdir()) == ["fill.html"]
    return out


def test_the_offline_page_steps_and_plays_with_the_network_blocked(offline_page):
    from playwright.sync_api import sync_playwright

    asked: list[str] = []

    def block(route):
        asked.append(route.request.url)
        route.abort()

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=ARGS, headless=True)
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            errors: list[str] = []
            page.on("pageerror", lambda exc: errors.append(str(exc)))
            page.route("http*://**/*", block)
            page.goto(offline_page.as_uri())
            page.wait_for_selector("canvas.teachraster-figure[data-step]", timeout=20_000)
            caption = page.locator(".teachraster-caption")
            seen = {_picture(page)}
            captions = {caption.inner_text()}
            nxt = page.get_by_role("button", name="next step")
            for _ in range(3):
                nxt.click()
                page.wait_for_timeout(100)
                seen.add(_picture(page))
                captions.add(caption.inner_text())
            assert len(seen) >= 3, "the next button did not show 3 distinct pictures"
            assert len(captions) >= 3, "the caption did not follow the steps"
            slider = page.get_by_role("slider", name="step")
            slider.focus()
            before = _picture(page)
            for _ in range(3):
                page.keyboard.press("ArrowRight")
            assert _picture(page) != before, "the arrow keys on the slider changed nothing"
            assert slider.input_value() == "6"
            page.get_by_role("button", name="first step").click()
            changes, last = 0, _picture(page)
            page.get_by_role("button", name="play").click()
            for _ in range(20):
                page.wait_for_timeout(100)
                now = _picture(page)
                changes += now != last
                last = now
            assert changes >= 3, f"play changed the picture only {changes} times in 2 s"
            page.get_by_role("button", name="pause").click()
            paused = _picture(page)
            page.wait_for_timeout(300)
            assert _picture(page) == paused, "the picture changed after pause"
            assert not errors, f"errors in the page: {errors[:3]}"
            assert not asked, f"the page asked the network for {asked[:3]}"
        finally:
            browser.close()
