"""The explorables computed in the page, in JupyterLab in headless Chromium, used as a student would.

One notebook holds every explorable and prediction; it runs once (one server, one browser for
the module), then each test acts on one of them with the pointer or the keys and checks that
the page answered by itself (a new picture, counted on the canvas' ``data-frames``) and that
the kernel heard of the result at the release (a cell printing the widget's state). Further:
a saved notebook reopened with no kernel shows each one's stand-in with its last picture, a
``teachraster html`` export keeps them live with no kernel, Notebook 7 leaves their keys to
them, and at 1024 x 768 (and a 150 % zoom) each fits its column.

Uses the JupyterLab server and page of tests/test_browser.py (skipped, saying why, where
Playwright or Chromium is missing).
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import urllib.request

import pytest
from browser_cells import run_new_cell
from notebook_browser import CELL_SHOWN, POLL_MS, open_cells
from test_browser import CHROMIUM, CHROMIUM_ARGS, WHY, _shut_down_kernels, lab, page  # noqa: F401
from test_browser_saved import _put_notebook, _stop_kernels

from teachraster.widgets import (
    AttributeSurfaces,
    CrackExplorer,
    DepthValuesExplorer,
    DiamondExplorer,
    EdgeFunctionExplorer,
    EyeRayExplorer,
    FootprintExplorer,
    PipelineMap,
)

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

NAME = "explorables.ipynb"
TRIANGLE = "tri = tr.Triangle([[1.5, 1.5], [9.5, 3.5], [3.5, 8.5]])"
CELLS = [
    "import json\nimport teachraster as tr\nfrom teachraster.plotting import plot_triangle\n"
    "from teachraster.widgets import *\n" + TRIANGLE,
    "pipeline = PipelineMap()\npipeline",
    "cracks = CrackExplorer()\ncracks",
    "edges = EdgeFunctionExplorer()\nedges",
    "surfaces = AttributeSurfaces()\nsurfaces",
    "eye = EyeRayExplorer()\neye",
    "depth = DepthValuesExplorer()\ndepth",
    "footprint = FootprintExplorer()\nfootprint",
    "diamonds = DiamondExplorer()\ndiamonds",
    "pixels = PredictPixels('Click the pixels this triangle covers.', "
    "answer=tr.rasterize(tri, 12, 10).coverage, draw=lambda ax: plot_triangle(ax, tri), "
    "picked='covered (E > 0)')\npixels",
    "nopixel = PredictPixels('Which pixels does this triangle draw?', "
    "answer=tr.rasterize(tri, 12, 10).coverage, none='<b>none</b>: it draws no pixel')\nnopixel",
    # the order question last: a click on the last cell (browser_cells) lands on its text
    "point = PredictPoint('Put the point on the line.', answer=(3.0, 2.0), draw=None, "
    "xlim=(0, 4), ylim=(0, 4), along=((0, 2), (4, 2)), start=(0, 2), tolerance=0.3, "
    "reveal_curve=[(0, 0), (4, 4)])\npoint",
    "order = PredictOrder('Order the sticks.', ['a', 'b', 'c'], answer=None, "
    "allow_impossible=True)\norder",
]
#: What each live view shows first: its title (the class's), or its question
TITLES = {key: cls.title for key, cls in [
    ("pipeline", PipelineMap), ("cracks", CrackExplorer), ("edges", EdgeFunctionExplorer),
    ("surfaces", AttributeSurfaces), ("eye", EyeRayExplorer), ("depth", DepthValuesExplorer),
    ("footprint", FootprintExplorer), ("diamonds", DiamondExplorer)]}  # fmt: skip
TITLES.update(
    pixels="Click the pixels this triangle covers",
    nopixel="Which pixels does this triangle draw",
    order="Order the sticks",
    point="Put the point on the line",
)


@pytest.fixture(scope="module")
def lesson(lab, page):  # noqa: F811
    """The notebook of every explorable, run (Run All) in a fresh kernel."""
    page.set_viewport_size({"width": 1400, "height": 900})
    open_cells(page, lab, CELLS, NAME)
    page.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    page.wait_for_function("n => document.querySelectorAll('.jp-OutputArea-output .tr-x').length >= n",
                           arg=len(TITLES), timeout=180_000, polling=POLL_MS)  # fmt: skip
    _wait_idle(page)
    return page


def _wait_idle(tab) -> None:
    tab.wait_for_function(
        """() => [...document.querySelectorAll('.jp-CodeCell .jp-InputPrompt')]
                 .every(p => /\\[\\d+\\]/.test(p.textContent) || p.textContent.trim() === '')""",
        timeout=120_000,
    )
    tab.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=60_000)


def _widget(tab, key: str):
    """The live view (not a stand-in) of the explorable ``key``."""
    return tab.locator(".jp-OutputArea-output .tr-x", has_text=TITLES[key]).first


def _kernel(tab, code: str) -> str:
    """Run ``code`` (one line) in a new cell at the end; its printed output."""
    n = tab.locator(".jp-Notebook .jp-CodeCell").count()
    # a marker no other output holds, matched case-sensitively (Playwright's has_text string
    # is a case-insensitive substring: "OUT" matched an older output saying "without")
    marker = f"KERNEL-SAYS-{n}:"
    run_new_cell(tab, f"print({marker!r} + json.dumps({code}))")
    out = tab.locator(".jp-OutputArea-output", has_text=re.compile(re.escape(marker))).last
    out.wait_for(timeout=60_000)
    return json.loads(out.inner_text().split(marker, 1)[1])


def _frames(canvas) -> int:
    return int(canvas.get_attribute("data-frames") or 0)


def _drag(tab, canvas, start, delta, steps: int = 12) -> None:
    """Drag from ``start`` (canvas px at its natural size) by ``delta`` (the same px)."""
    canvas.scroll_into_view_if_needed()
    box = canvas.bounding_box()
    scale = box["width"] / float(canvas.evaluate("c => c.logical.w"))
    x, y = box["x"] + start[0] * scale, box["y"] + start[1] * scale
    tab.mouse.move(x, y)
    tab.mouse.down()
    tab.mouse.move(x + delta[0] * scale, y + delta[1] * scale, steps=steps)
    tab.mouse.up()


def _handles(canvas) -> list:
    return json.loads(canvas.get_attribute("data-handles"))


def test_edges_drag_in_the_page_and_the_kernel_hears_the_release(lesson):
    w = _widget(lesson, "edges")
    canvas = w.locator("canvas").first
    before, text = _frames(canvas), w.locator(".tr-x-readout").inner_text()
    _drag(lesson, canvas, _handles(canvas)[3], (-40, -40))  # v4 up and left
    assert _frames(canvas) >= before + 3  # the page drew the drag by itself
    assert w.locator(".tr-x-readout").inner_text() != text
    moved = _kernel(lesson, "edges.state['vertices'][3]")
    assert moved != [14.5, 12.5] and all(abs(v * 4 - round(v * 4)) < 1e-9 for v in moved)
    w.get_by_role("button", name="3-D: E as planes").click()
    planes = w.locator("canvas").nth(1)
    planes.wait_for(state="visible", timeout=5_000)  # shown on the page's next frame
    before = _frames(planes)
    _drag(lesson, planes, (280, 200), (60, 20))
    assert _frames(planes) > before
    # the tint buttons name the chosen triangle's own edges
    w.get_by_role("button", name="signs of B (v3 v2 v4)").click()
    w.get_by_role("button", name="E24's").click()
    assert w.get_by_role("button", name="E23's").count() == 0
    assert _kernel(lesson, "edges.state['tint']") == "E23"  # B's second edge
    assert not lesson.errors, lesson.errors[:3]


def test_cracks_reroll_and_tally(lesson):
    w = _widget(lesson, "cracks")
    # the default's first pair: the float DDA gives three ties to the wrong triangle
    w.get_by_text("1 (100.0 %), 3 px").first.wait_for(timeout=5_000)
    # r344 01-FIG1: the key paragraph at the panels' 16 px, not small grey text
    key = w.locator(".tr-x-sub").first
    assert key.evaluate("e => getComputedStyle(e).fontSize") == "16px"
    assert key.evaluate("e => getComputedStyle(e).color") == "rgb(17, 17, 17)"
    w.get_by_role("button", name="Reroll").click()
    w.get_by_text("of 2 (").first.wait_for(timeout=5_000)  # the tally counts two pairs
    w.get_by_role("button", name="Roll 1000 more").click()
    w.get_by_text("of 1002 (").first.wait_for(timeout=10_000)
    state = _kernel(lesson, "cracks.state")
    assert state["roll"] == 1001 and state["tally"]["integer"]["pairs"] == 1002
    assert state["tally"]["integer"]["swapped"] == 0 and state["tally"]["dda"]["swapped"] > 0
    # random pairs on this grid hardly ever crack: the stored pair does, evaluated as listed
    w.get_by_role("button", name="Show a pair that cracks").click()
    listed = w.get_by_role(
        "button", name="evaluate each edge from the end its triangle lists first"
    )
    assert listed.get_attribute("aria-pressed") == "true"
    state = _kernel(lesson, "cracks.state")
    # the toggle changed with it: the tally starts again (review r7: it read "0 of 1001" after
    # a thousand more, the opening pair drawn the other way still counted)
    assert state["stored"] and state["asListed"] and state["tally"]["integer"]["pairs"] == 0
    w.get_by_role("button", name="Roll 1000 more").click()
    w.get_by_text("of 1000 (").first.wait_for(timeout=10_000)
    assert _kernel(lesson, "cracks.state")["tally"]["integer"]["pairs"] == 1000
    assert not lesson.errors, lesson.errors[:3]


def test_cracks_larger_grid_rolls_until_one_cracks(lesson):
    """Review r229 01-W2: with the toggle on, random pairs on 16 x 16 showed no crack ("0 of
    1000"); on the 32 x 32 grid "Roll until one cracks" finds one, each pair counted."""
    w = _widget(lesson, "cracks")
    listed = w.get_by_role(
        "button", name="evaluate each edge from the end its triangle lists first"
    )
    if listed.get_attribute("aria-pressed") != "true":
        listed.click()
    grid = w.get_by_role("button", name="32 × 32 grid")
    canvas = w.locator("canvas").first
    small_w = float(canvas.evaluate("c => c.logical.w"))  # the 16 x 16 grid's panels
    grid.click()
    assert grid.get_attribute("aria-pressed") == "true"
    assert float(canvas.evaluate("c => c.logical.w")) > 800  # two 32-cell panels
    state = _kernel(lesson, "cracks.state")
    assert state["large"] and state["roll"] == 0 and state["tally"]["integer"]["pairs"] == 1
    w.get_by_role("button", name="Roll until one cracks").click()
    w.get_by_text("found after").first.wait_for(timeout=30_000)
    state = _kernel(lesson, "cracks.state")
    tally = state["tally"]
    assert state["roll"] > 0 and tally["integer"]["pairs"] == state["roll"] + 1
    assert tally["dda"]["faulty"] + tally["crossing"]["faulty"] >= 1
    # r239 01-FIG2: the stored pair on 32 x 32 filled a quarter of each panel; zoomed to the
    # 16 x 16 box that holds it, the canvas is that of the 16 x 16 grid, and a line says so
    w.get_by_role("button", name="Show a pair that cracks").click()
    w.get_by_text("16 × 16 corner of the 32 × 32 grid").first.wait_for(timeout=5_000)
    assert float(canvas.evaluate("c => c.logical.w")) == small_w
    assert grid.get_attribute("aria-pressed") == "true"
    w.get_by_role("button", name="Reroll").click()  # a roll: the whole 32 x 32 grid again
    assert w.get_by_text("16 × 16 corner of the 32 × 32 grid").count() == 0
    grid.click()  # back to 16 x 16: the tally from nothing again
    assert _kernel(lesson, "cracks.state")["tally"]["integer"]["pairs"] == 1
    assert not lesson.errors, lesson.errors[:3]


def test_depth_near_plane_dragged(lesson):
    w = _widget(lesson, "depth")
    canvas = w.locator("canvas").first
    handle = _handles(canvas)[0]
    _drag(lesson, canvas, handle, (120, 0))
    near = _kernel(lesson, "depth.near")
    assert near > 0.2
    assert f"(near {near:g}," in w.locator(".tr-x-readout").inner_text()


def test_diamonds_end_snaps_onto_a_tie_and_keys_step(lesson):
    w = _widget(lesson, "diamonds")
    canvas = w.locator("canvas").first
    p1 = _handles(canvas)[1]
    cell = (_handles(canvas)[1][0] - _handles(canvas)[0][0]) / (10.4 - 1.5)
    _drag(lesson, canvas, p1, (cell * 0.1 - 1, -cell * 0.1 + 1))  # near (10.5, 4.5): a centre
    assert _kernel(lesson, "diamonds.state['p1']") == [10.5, 4.5]
    stepper = w.get_by_role("slider", name="step")
    _keys_stay(lesson, canvas, stepper)
    # a drag makes another line: the step shown (2) goes back to all steps, page and kernel
    _drag(lesson, canvas, _handles(canvas)[1], (-cell, 0))
    # "all" is the slider's right end: its left end is step 0 (reviews r51 8, r63 6)
    assert stepper.input_value() == stepper.get_attribute("max")
    assert "All steps" in w.inner_text()
    assert _kernel(lesson, "diamonds.state['step']") == -1


ACTIVE = "() => [...document.querySelectorAll('.jp-Cell')].findIndex(c => c.classList.contains('jp-mod-active'))"


def _keys_stay(tab, canvas, slider) -> None:
    """Arrow keys on the focused canvas step it (all -> 0 -> 1 -> 2), and the notebook's
    shortcuts do not take them (the active cell stays)."""
    canvas.focus()
    active = tab.evaluate(ACTIVE)
    for _ in range(3):
        canvas.press("ArrowRight")
    assert slider.input_value() == "2"
    assert tab.evaluate(ACTIVE) == active


def test_footprint_both_ways(lesson):
    w = _widget(lesson, "footprint")
    screen, texture = w.locator("canvas").nth(0), w.locator("canvas").nth(1)
    screen.scroll_into_view_if_needed()
    box = screen.bounding_box()
    lesson.mouse.click(box["x"] + box["width"] * 0.5, box["y"] + box["height"] * 0.8)  # near
    readout = w.locator(".tr-x-readout")
    readout.get_by_text("Pixel (row ").wait_for(timeout=5_000)
    pixel = _kernel(lesson, "footprint.state['pixel']")
    assert pixel[0] >= 24  # the lower part of the 48 x 36 image: near the camera
    # r104 09-7: the bottom row, where lesson 09 says to start ("the bottom row (the
    # nearest)"), is floor: it answered "not on the floor"
    screen.scroll_into_view_if_needed()
    box = screen.bounding_box()  # the readout above may have moved it
    lesson.mouse.click(box["x"] + box["width"] * 0.5, box["y"] + box["height"] * 35.5 / 36)
    readout.get_by_text("Pixel (row 35, col ").wait_for(timeout=5_000)
    assert "not on the floor" not in readout.inner_text()
    # r184 09-2: the derivative vectors' lengths, not "axes" (the ellipse's differ)
    assert "footprint's extents along x and y" in readout.inner_text()
    assert "footprint's axes" not in readout.inner_text()
    texture.scroll_into_view_if_needed()
    box = texture.bounding_box()
    lesson.mouse.click(box["x"] + box["width"] * 0.5, box["y"] + box["height"] * 0.5)
    readout.get_by_text("is fetched by the trilinear filter of").wait_for(timeout=5_000)
    n = int(readout.inner_text().split("trilinear filter of ")[1].split(" pixel")[0])
    assert n >= 1  # the footprint's own centre is read at least by its pixel
    assert _kernel(lesson, "footprint.state['point'] is not None") is True


def test_surfaces_turn_and_w(lesson):
    w = _widget(lesson, "surfaces")
    canvas = w.locator("canvas").first
    before = _frames(canvas)
    _drag(lesson, canvas, (320, 250), (80, 30))
    assert _frames(canvas) >= before + 3
    text = w.locator(".tr-x-readout").inner_text()
    slider = w.get_by_role("slider", name="w of v3")
    slider.fill("1")
    slider.dispatch_event("change")
    w.get_by_text("Every w is equal").wait_for(timeout=5_000)
    assert w.locator(".tr-x-readout").inner_text() != text
    assert _kernel(lesson, "surfaces.state['w']") == [1.0, 1.0, 1.0]


def test_eye_ray_peak_and_dragged_end(lesson):
    w = _widget(lesson, "eye")
    readout = w.locator(".tr-x-readout")
    assert "3 − 2√2" in readout.inner_text()  # depth ratio 2 at first
    canvas = w.locator("canvas").first
    _drag(lesson, canvas, _handles(canvas)[1], (0, -40))  # the far end farther
    assert "3 − 2√2" not in readout.inner_text()
    ends = _kernel(lesson, "eye.state['ends']")
    assert ends[1][1] > 3.0


def test_pipeline_stage_clicked(lesson):
    w = _widget(lesson, "pipeline")
    w.locator("[data-stage=depth]").click()
    w.get_by_text("Early-z", exact=True).wait_for(timeout=5_000)
    w.locator("[data-stage=vertex]").click()
    w.get_by_text("perspective projection").first.wait_for(timeout=5_000)
    # review r77 00-8: the dashed early-z box opens the depth test, where early-z is explained
    w.locator("[data-early=depth]").click()
    w.get_by_text("Early-z", exact=True).wait_for(timeout=5_000)
    assert _kernel(lesson, "pipeline.state['stage']") == "depth"
    # review r157 00-13: the early box is marked with the depth stage whose page it opens
    assert w.locator("[data-early=depth] rect").get_attribute("fill") == "#fde9c8"
    w.locator("[data-stage=vertex]").click()
    # the page redraws on its next frame: wait for it rather than read the text at once
    w.get_by_text("perspective projection").first.wait_for(timeout=5_000)
    assert w.locator("[data-early=depth] rect").get_attribute("fill") == "#fff"
    assert _kernel(lesson, "pipeline.state['stage']") == "vertex"
    # each box prints the lessons the kernel sent (the page keeps no list of its own)
    sent = _kernel(lesson, "pipeline.data['lessons']['rasterize']")
    box = w.locator("[data-stage=rasterize] text").all_text_contents()  # SVG: no innerText
    # lesson 06 prices the rasteriser's choices (review r23 00-4): three lines, which the
    # 100-px box holds under its one-line name (baselines 55, 73, 91 px; the name's at 30);
    # at most nine characters a line, runs of three as a range (review r97 00-5)
    assert sent == ["01–04,", "06–08,", "10, 12a"] and box[-3:] == sent


#: The pipeline map's texts as shown: each one's size on screen (its font size times the
#: map's scale), whether it lies inside its stage's box, and the map's and column's widths.
MAP_TEXT = """(w) => {
  const s = w.querySelector('.tr-pipe svg');
  const scale = s.getBoundingClientRect().width / s.viewBox.baseVal.width;
  const sizes = [...s.querySelectorAll('text')].map(t => +t.getAttribute('font-size') * scale);
  const outside = [];
  for (const g of s.querySelectorAll('g[data-stage]')) {
    const r = g.querySelector('rect').getBBox();
    for (const b of [...g.querySelectorAll('text')].map(t => t.getBBox())) {
      if (b.x < r.x + 4 || b.x + b.width > r.x + r.width - 4 || b.y < r.y || b.y + b.height > r.y + r.height)
        outside.push(g.dataset.stage);
    }
  }
  const column = s.closest('.jp-OutputArea-output').getBoundingClientRect().width;
  return {least: Math.min(...sizes), outside, map: s.getBoundingClientRect().width, column};
}"""


def test_pipeline_map_reads_15_px_in_a_1280_px_window(lesson):
    """Review r97 00-5 (r91 00-D): at 1280 px the stage names were 13 px bold and the caption
    read 12-13 px. Every text of the map now reads at least 15 px there and at 1400 x 900 (the
    map drawn 1:1 within the column, which it fits), at least 12 px in the 585-px column of a
    1024-px screen, and each stage's name and lessons stay inside its box."""
    w = _widget(lesson, "pipeline")
    try:
        for (width, height), least in [((1400, 900), 15), ((1280, 800), 15), ((1024, 768), 12)]:
            lesson.set_viewport_size({"width": width, "height": height})
            lesson.wait_for_timeout(500)
            got = lesson.evaluate(MAP_TEXT, w.element_handle())
            assert got["least"] >= least and not got["outside"], (width, got)
            assert got["map"] <= got["column"] + 1, (width, got)
    finally:
        lesson.set_viewport_size({"width": 1400, "height": 900})


def test_predictions_wait_for_an_answer_then_show_it(lesson):
    w = _widget(lesson, "pixels")
    check = w.get_by_role("button", name="Check")
    assert check.is_disabled()
    (x0, y0, sx, sy), width = _kernel(lesson, "[pixels.data['transform'], pixels.data['size'][0]]")
    canvas = w.locator("canvas").first
    canvas.scroll_into_view_if_needed()
    box = canvas.bounding_box()
    scale = box["width"] / width
    for row, col in [(2, 2), (2, 3), (4, 4)]:
        lesson.mouse.click(box["x"] + (x0 + sx * (col + 0.5)) * scale,
                           box["y"] + (y0 + sy * (row + 0.5)) * scale)  # fmt: skip
    from playwright.sync_api import expect

    expect(check).to_be_enabled(timeout=5_000)
    check.click()
    w.get_by_text("You marked 3 pixels").wait_for(timeout=5_000)
    assert _kernel(lesson, "[pixels.revealed, pixels.given]") == [True, [[2, 2], [2, 3], [4, 4]]]
    # review r28: checked once; a click on the figure after the reveal marks nothing
    assert check.is_disabled()
    lesson.mouse.click(box["x"] + (x0 + sx * 6.5) * scale, box["y"] + (y0 + sy * 6.5) * scale)
    lesson.wait_for_timeout(300)
    assert _kernel(lesson, "pixels.given") == [[2, 2], [2, 3], [4, 4]] and check.is_disabled()
    o = _widget(lesson, "order")
    ocheck = o.get_by_role("button", name="Check")
    assert ocheck.is_disabled()
    # review r38 05a: the order shown is an answer too; a click on a chip, moving nothing, gives it
    o.locator(".tr-chip").first.click()
    expect(ocheck).to_be_enabled(timeout=5_000)
    assert _kernel(lesson, "[order.given, order.correct]") == [["a", "b", "c"], False]
    assert "aside" not in (o.locator(".tr-chips").get_attribute("class") or "")
    o.get_by_text("no order works").click()
    # review r190 05a-5: ticked, the chips are greyed and a drag on them moves nothing
    expect(o.locator(".tr-chips")).to_have_class(re.compile(r"\baside\b"), timeout=5_000)
    assert o.locator(".tr-chips").get_attribute("aria-disabled") == "true"
    o.locator(".tr-chip").last.drag_to(o.locator(".tr-chip").first)
    lesson.wait_for_timeout(300)
    assert [c.inner_text() for c in o.locator(".tr-chip").all()] == ["a", "b", "c"]
    assert _kernel(lesson, "order.given") is None
    ocheck.click()
    o.get_by_text("Right.").wait_for(timeout=5_000)
    assert _kernel(lesson, "order.correct") is True
    assert ocheck.is_disabled() and o.locator("input[type=checkbox]").is_disabled()


def test_a_pixels_question_offering_none_takes_it_as_an_answer(lesson):
    """Review r183 08-8: "none" is an answer where the question offers it (Check enabled with
    no pixel marked), a marked pixel unticks it, and an empty grid alone is still none."""
    from playwright.sync_api import expect

    w = _widget(lesson, "nopixel")
    check = w.get_by_role("button", name="Check")
    none = w.locator("input[type=checkbox]")
    assert check.is_disabled() and not none.is_checked()
    none.check()
    expect(check).to_be_enabled(timeout=5_000)
    (x0, y0, sx, sy), width = _kernel(
        lesson, "[nopixel.data['transform'], nopixel.data['size'][0]]"
    )
    canvas = w.locator("canvas").first
    canvas.scroll_into_view_if_needed()
    box = canvas.bounding_box()
    scale = box["width"] / width
    at = (box["x"] + (x0 + sx * 2.5) * scale, box["y"] + (y0 + sy * 2.5) * scale)
    lesson.mouse.click(*at)  # a pixel marked: "none" unticked, Check still enabled
    expect(none).not_to_be_checked(timeout=5_000)
    assert check.is_enabled()
    lesson.mouse.click(*at)  # unmarked again: an empty grid is no answer
    expect(check).to_be_disabled(timeout=5_000)
    none.check()
    expect(check).to_be_enabled(timeout=5_000)
    check.click()
    w.get_by_text("You marked 0 pixels").wait_for(timeout=5_000)
    assert _kernel(lesson, "[nopixel.revealed, nopixel.given, nopixel.correct]") == [
        True,
        [],
        False,
    ]
    assert check.is_disabled() and none.is_disabled()


def test_a_click_on_the_point_marker_gives_no_answer(lesson):
    """Review r209 03-5: a click on the marker (on it, off its centre), without a drag, moved
    it to the pointer, enabled Check and had the start point graded. Now it moves nothing:
    Check stays disabled and the kernel has no answer (before the keys of the next test)."""
    w = _widget(lesson, "point")
    canvas = w.locator("canvas").first
    (x0, y0, sx, sy) = _kernel(lesson, "point.data['transform']")
    canvas.scroll_into_view_if_needed()  # after the kernel's cell, which scrolled it away
    lesson.wait_for_timeout(500)
    box = canvas.bounding_box()
    scale = box["width"] / float(canvas.evaluate("c => c.logical.w"))
    marker = (x0 + sx * 0.0, y0 + sy * 2.0)  # its start, (0, 2)
    lesson.mouse.click(box["x"] + (marker[0] + 6) * scale, box["y"] + marker[1] * scale)
    lesson.wait_for_timeout(500)
    assert w.get_by_role("button", name="Check").is_disabled()
    assert _kernel(lesson, "point.given") is None


def test_point_reveal_draws_its_curve(lesson):
    """Review r38 05b c9: after Check, the curve the answer comes from is drawn (green), and
    not before."""
    w = _widget(lesson, "point")
    canvas = w.locator("canvas").first
    canvas.scroll_into_view_if_needed()
    (x0, y0, sx, sy) = _kernel(lesson, "point.data['transform']")
    at = [x0 + sx * 1.0, y0 + sy * 1.0]  # (1, 1) on the curve, far from the answer (3, 2)
    green = (
        "([x, y]) => { const c = document.querySelectorAll('canvas')[%d]; "
        "const d = c.getContext('2d').getImageData(x - 3, y - 3, 7, 7).data; let n = 0; "
        "for (let k = 0; k < d.length; k += 4) n += d[k] < 40 && d[k + 1] > 120 && d[k + 2] < 150"
        " && d[k + 3] > 200; return n; }"
    )
    index = lesson.evaluate(
        "(el) => [...document.querySelectorAll('canvas')].indexOf(el)", canvas.element_handle()
    )
    assert lesson.evaluate(green % index, at) == 0  # the curve is left out of the question
    canvas.focus()
    for _ in range(7):  # Shift: ten key steps of 0.04 each, to x = 2.8, within 0.3 of 3
        lesson.keyboard.press("Shift+ArrowRight")
    check = w.get_by_role("button", name="Check")
    from playwright.sync_api import expect

    expect(check).to_be_enabled(timeout=5_000)
    check.click()
    w.get_by_text("Right.").wait_for(timeout=5_000)
    lesson.wait_for_timeout(300)
    assert lesson.evaluate(green % index, at) > 0


def test_layout_fits_a_small_screen(lesson):
    for size in (
        {"width": 1024, "height": 768},
        {"width": 933, "height": 600},
    ):  # 1400x900 at 150 %
        lesson.set_viewport_size(size)
        lesson.wait_for_timeout(500)
        wide = lesson.evaluate("""() => [...document.querySelectorAll('.jp-OutputArea-output .tr-x')]
            .filter(x => x.scrollWidth > x.parentElement.getBoundingClientRect().width + 2
                    || x.getBoundingClientRect().right > document.documentElement.clientWidth)
            .map(x => x.textContent.slice(0, 40))""")
        assert not wide, f"{size}: wider than the column: {wide}"
    lesson.set_viewport_size({"width": 1400, "height": 900})


def test_saved_notebook_reopened_shows_each_last_picture(lesson, lab):  # noqa: F811
    lesson.wait_for_timeout(1500)  # the pictures of the last changes reach the kernel
    lesson.keyboard.press("Escape")
    lesson.keyboard.press("Control+s")
    lesson.wait_for_function("() => !document.querySelector('.jp-mod-current.jp-mod-dirty')",
                             timeout=30_000)  # fmt: skip
    with urllib.request.urlopen(f"{lab}/api/contents/{NAME}", timeout=30) as r:
        saved = json.load(r)["content"]
    standins = [o["data"]["text/html"] for c in saved["cells"] for o in c.get("outputs", [])
                if "teachraster-static" in o.get("data", {}).get("text/html", "")]  # fmt: skip
    assert len(standins) == len(TITLES)
    # every page sent its last picture to the kernel (the order question has no figure)
    without = [h for h in standins if "data:image/png;base64," not in h]
    assert len(without) == 1 and "Order the sticks." in without[0]
    _stop_kernels(lesson, lab)
    lesson.goto(f"{lab}/lab/tree/{NAME}?reset")
    lesson.wait_for_selector(".teachraster-static", timeout=90_000)
    lesson.wait_for_timeout(2000)  # the widget manager has given up on the models
    shown = [f for f in lesson.locator(".teachraster-static").all() if f.is_visible()]
    assert len(shown) == len(TITLES)
    for f in shown:
        assert "Run All (Run ▸ Run All Cells) to bring it back" in f.inner_text()
    assert "Click the pixels this triangle covers." in " ".join(f.inner_text() for f in shown)


def test_html_export_stays_live(page, tmp_path):  # noqa: F811
    import nbformat

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(CELLS[0]), nbformat.v4.new_code_cell(CELLS[3]),
                nbformat.v4.new_code_cell(CELLS[9])]  # fmt: skip
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}  # fmt: skip
    src, out = tmp_path / "x.ipynb", tmp_path / "x.html"
    nbformat.write(nb, src)
    subprocess.run([sys.executable, "-m", "teachraster", "html", str(src), "-o", str(out)],
                   check=True, capture_output=True, timeout=300)  # fmt: skip
    assert out.read_text().count("mountStatic(document.getElementById(") == 2  # inline
    page.goto(out.as_uri())
    page.wait_for_selector(".tr-x canvas", timeout=30_000)
    w = page.locator(".tr-x", has_text="Edge functions, live").first
    canvas = w.locator("canvas").first
    before = _frames(canvas)
    _drag(page, canvas, _handles(canvas)[0], (30, 30))
    assert _frames(canvas) > before  # live with no kernel
    q = page.locator(".tr-x", has_text="Click the pixels").first
    assert q.get_by_role("button", name="Check").is_disabled()
    # r474: the widget's own line showed "E &gt; 0" (escaped words set as text)
    assert "you expect covered (E > 0) (drag" in q.inner_text(), q.inner_text()
    assert not page.errors, page.errors[:3]


def test_notebook_7_leaves_the_keys_to_the_explorables(lab, page):  # noqa: F811
    _shut_down_kernels(lab)
    page.goto(f"{lab}/lab?reset")  # the REST calls go from a page of the server
    page.wait_for_selector("#jp-main-statusbar", timeout=90_000)
    _put_notebook(page, [CELLS[0], CELLS[8]], "nb7.ipynb")
    page.goto(f"{lab}/notebooks/nb7.ipynb")
    page.wait_for_selector(CELL_SHOWN, timeout=90_000)
    page.wait_for_timeout(3000)
    page.keyboard.press("Escape")
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    w = page.locator(".jp-OutputArea-output .tr-x", has_text=TITLES["diamonds"]).first
    w.wait_for(timeout=120_000)
    _keys_stay(page, w.locator("canvas").first, w.get_by_role("slider", name="step"))
