"""The offline page of a fill (``teachraster fill ... -o fill.html``) in Chromium, no network.

The page is opened from a file, alone in its folder, with every non-file request aborted:
it must step (the next button and the step slider show at least three distinct pictures)
and play (the picture changes at least three times in two seconds), and ask for nothing.
Skipped, saying why, where Playwright or Chromium is missing.
"""

from __future__ import annotations

import contextlib
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


@contextlib.contextmanager
def opened_offline(path: Path):
    """``path`` in headless Chromium with every request but the file itself aborted; on
    leaving, no request may have been made and no error raised in the page."""
    from notebook_browser import driver

    asked: list[str] = []
    errors: list[str] = []

    def route(request_route):
        if request_route.request.url.startswith("file:"):
            request_route.continue_()
        else:
            asked.append(request_route.request.url)
            request_route.abort()

    browser = driver().chromium.launch(executable_path=CHROMIUM, args=ARGS, headless=True)
    try:
        page = browser.new_page(viewport={"width": 1400, "height": 900})
        page.on("pageerror", lambda exc: errors.append(str(exc)))
        page.route("**/*", route)
        page.goto(path.as_uri())
        yield page
        assert not errors, f"errors in the page: {errors[:3]}"
        assert not asked, f"the page asked the network for {asked[:3]}"
    finally:
        browser.close()


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
    with opened_offline(offline_page) as page:
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


# -- a lesson exported with `teachraster html`: formulas and every kind of widget -----------
LESSON_WIDGETS = (
    "from teachraster.widgets import BlendingExplorer, LinePlayer, Predict, TexturedPlaneViewer\n"
    "LinePlayer((0.5, 0.5), (6.5, 3.5), 8, 5)",
    "TexturedPlaneViewer(48, 36, tilt=30)",
    "BlendingExplorer(size=(16, 16))",
    'Predict("How many pixels?", ["one", "two"], "two", explain="Two.")',
)


@pytest.fixture(scope="module")
def lesson_page(tmp_path_factory):
    """Lesson 01's text (every formula) and four widgets (a player, a slider over pictures
    drawn ahead, a picture, a question), exported with `teachraster html`."""
    import contextlib
    import io

    import nbformat

    from teachraster.cli import main
    from teachraster.cli.page_math import formulas

    root = Path(__file__).resolve().parent.parent
    lesson = nbformat.read(root / "notebooks" / "01_span_tables.ipynb", as_version=4)
    nb = nbformat.v4.new_notebook()
    nb.cells = [c for c in lesson.cells if c.cell_type == "markdown"]
    nb.cells += [nbformat.v4.new_code_cell(src) for src in LESSON_WIDGETS]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}  # fmt: skip
    folder = tmp_path_factory.mktemp("lesson")
    src, out = folder / "lesson.ipynb", folder / "lesson.html"
    nbformat.write(nb, src)
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        assert main(["html", str(src), "-o", str(out)]) == 0
    n_formulas = sum(len(formulas(c.source)) for c in nb.cells if c.cell_type == "markdown")
    src.unlink()  # the page alone in its folder
    return out, printed.getvalue(), n_formulas


def test_a_lesson_page_is_whole_with_the_network_blocked(lesson_page):
    out, printed, n_formulas = lesson_page
    assert f"4 widget(s): 3 live, 1 pictured, 0 missing; {n_formulas} formula(s)" in printed
    assert n_formulas >= 75
    with opened_offline(out) as page:
        page.wait_for_load_state("load")
        _formulas_are_rendered(page, n_formulas)
        _every_widget_shows_its_picture(page)
        _players_step(page)


def _formulas_are_rendered(page, n_formulas: int) -> None:
    maths = page.evaluate(
        "() => [...document.querySelectorAll('.jp-RenderedMarkdown math')].map(m => {"
        " const r = m.getBoundingClientRect();"
        " return [getComputedStyle(m).display, r.width, r.height]; })"
    )
    assert len(maths) == n_formulas
    assert all(d in ("math", "block math", "inline math") for d, _, _ in maths), maths[:3]
    assert all(w > 0 and h > 0 for _, w, h in maths)
    # laid out as mathematics: every fraction's numerator above its denominator
    fractions = page.evaluate(
        "() => [...document.querySelectorAll('mfrac')].map(f => {"
        " const [a, b] = [...f.children].map(c => c.getBoundingClientRect());"
        " return [a.bottom, b.top]; })"
    )
    assert fractions and all(top <= bottom + 1 for top, bottom in fractions), fractions[:3]
    text = page.evaluate(
        "() => [...document.querySelectorAll('.jp-RenderedMarkdown')]"
        ".map(e => e.innerText).join('\\n')"
    )
    import re

    leftover = re.findall(r"\$[^$\n]+\$|\\(?:frac|text|Delta|begin)\b", text)
    assert not leftover, f"raw TeX left in the page: {leftover[:3]}"


def _every_widget_shows_its_picture(page) -> None:
    page.wait_for_function(
        "() => [...document.querySelectorAll('.teachraster-offline canvas')]"
        ".every(c => c.dataset.step !== undefined)",
        timeout=20_000,
    )
    shown = page.evaluate(
        """() => [...document.querySelectorAll('.teachraster-offline')].map(w => {
          const pics = [...w.querySelectorAll('canvas.teachraster-figure, img')];
          const painted = pics.filter(p => p.tagName === 'IMG'
              ? (p.complete && p.naturalWidth > 100)
              : (p.width > 100 && [...p.getContext('2d').getImageData(0, 0, p.width,
                  p.height).data].some(v => v < 200)));
          return [w.dataset.widget, w.dataset.kind, pics.length, painted.length];
        })"""
    )
    kinds = {name: kind for name, kind, _, _ in shown}
    assert kinds == {"LinePlayer": "live", "TexturedPlaneViewer": "live",
                     "BlendingExplorer": "pictured", "Predict": "live"}  # fmt: skip
    for name, _, pictures, painted in shown:
        if name != "Predict":  # its figure is folded away with the answer
            assert pictures >= 1 and painted == pictures, (name, pictures, painted)


def _players_step(page) -> None:
    for name in ("LinePlayer", "TexturedPlaneViewer"):
        widget = page.locator(f".teachraster-offline[data-widget={name}]")
        canvas = widget.locator("canvas.teachraster-figure")
        widget.get_by_role("button", name="first step").click()
        page.wait_for_timeout(200)
        before = (canvas.get_attribute("data-step"), _canvas_png(canvas))
        assert before[0] == "0", name
        widget.get_by_role("button", name="next step").click()
        page.wait_for_timeout(200)
        after = (canvas.get_attribute("data-step"), _canvas_png(canvas))
        assert int(after[0]) == int(before[0]) + 1 and after[1] != before[1], name


def _canvas_png(canvas) -> str:
    return canvas.evaluate("c => c.toDataURL('image/png')")
