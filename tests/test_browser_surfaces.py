"""Lesson 04's 3-D view of the attribute, in JupyterLab in headless Chromium: it opens on the
sheets its text names.

Review r250 04-W1: the lesson's text says the view opens on u, u/w and 1/w ("Switch on the
affine plane"), and its cell asks for them, but the page opened on u and the affine plane:
the widget changed its synced state in place, which never reached the page. Here the
lesson's own cells (its setup and the view's cell) run in the browser, and the buttons'
``aria-pressed`` are read before anything is touched.

Uses the JupyterLab server and page of tests/test_browser.py (skipped, saying why, where
Playwright or Chromium is missing; TEACHRASTER_REQUIRE_BROWSER makes that an error).
"""

from __future__ import annotations

from pathlib import Path

import nbformat
import pytest
from notebook_browser import open_cells
from test_browser import WHY, lab, page  # noqa: F401 (fixtures)

from teachraster.widgets import AttributeSurfaces

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

LESSON = (
    Path(__file__).resolve().parents[1] / "notebooks/04_perspective_correct_interpolation.ipynb"
)
#: The page's buttons, by the sheet each switches (static/explore_attributes.js's SURFACES)
BUTTONS = {
    "correct": "f, perspective-correct = (f/w) / (1/w)",
    "affine": "f, affine (screen-space plane)",
    "fw": "f/w (a plane)",
    "inv": "1/w (a plane)",
}


def surfaces_cells() -> list[str]:
    """Lesson 04's setup (its first code cell) and the cell that shows the 3-D view."""
    code = [c.source for c in nbformat.read(LESSON, as_version=4).cells if c.cell_type == "code"]
    return [code[0], next(s for s in code if "= AttributeSurfaces(" in s)]


def test_lesson_04_surfaces_open_on_u_and_the_two_planes(lab, page):  # noqa: F811
    open_cells(page, lab, surfaces_cells(), "lesson04_surfaces.ipynb")
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    view = page.locator(".jp-OutputArea-output .tr-x", has_text=AttributeSurfaces.title).first
    view.locator("canvas").first.wait_for(timeout=120_000)
    pressed = {
        sheet: view.get_by_role("button", name=name, exact=True).get_attribute("aria-pressed")
        for sheet, name in BUTTONS.items()
    }
    # as the text says: u, u/w and 1/w on; the affine plane is the student's to switch on
    assert pressed == {"correct": "true", "affine": "false", "fw": "true", "inv": "true"}
    # r342 FIG1: each button keys its sheet's colour, framed in white: the pressed
    # perspective-correct button's stripe, the same blue, had vanished into its background
    styles = {
        sheet: view.get_by_role("button", name=name, exact=True)
        .locator(".tr-x-swatch")
        .evaluate("e => [getComputedStyle(e).backgroundColor, getComputedStyle(e).borderTopColor]")
        for sheet, name in BUTTONS.items()
    }
    # OKABE.blue (0, 114, 178) at the sheets' 0.55 over white, as the picture shows it
    assert styles["correct"] == ["rgb(115, 177, 213)", "rgb(255, 255, 255)"]
    assert len({fill for fill, _ in styles.values()}) == 4
    view.get_by_role("button", name=BUTTONS["affine"], exact=True).click()
    assert (
        view.get_by_role("button", name=BUTTONS["affine"], exact=True).get_attribute("aria-pressed")
        == "true"
    )
    assert not page.errors, page.errors[:3]
