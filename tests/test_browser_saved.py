"""A saved lesson reopened the next day, in JupyterLab in headless Chromium.

A notebook with a FillPlayer and a TriangleEditor is run, saved with its outputs, its kernel
shut down, and opened again: the widgets' models are gone (a new kernel knows none of
them), so JupyterLab's widget manager would say "Error displaying widget: model not found"
in place of each. What the student must see instead is each widget's stand-in (a Predict's
question and choices, a picture) and a hint that works, "Run All (Run ▸ Run All Cells) to
bring it back" (teachraster.widgets.common.display_with_fallback); while the widgets are
live, that stand-in is hidden. An editor whose kernel is gone says so when a
vertex is dragged ("The kernel does not answer ...").

Uses the JupyterLab server and page of tests/test_browser.py; skipped, saying why, where
Playwright or Chromium is missing (CI makes them required).
"""

from __future__ import annotations

import json
import urllib.request

import pytest
from notebook_browser import (
    API,
    CELL_SHOWN,
    open_cells,
    put_notebook,
    save_and_read,
    wait_until_idle,
)
from test_browser import WHY, _shut_down_kernels, lab, page  # noqa: F401

pytestmark = [
    pytest.mark.browser,
    pytest.mark.skipif(WHY is not None, reason=f"browser test skipped: {WHY}"),
]

NAME = "saved_lesson.ipynb"
CELLS = [
    "import teachraster as tr\nfrom teachraster.widgets import FillPlayer, TriangleEditor\n"
    "tri = tr.Triangle([[1.3, 1.2], [14.6, 4.7], [5.2, 14.1]], attrs={'u': [0, 1, 0]})",
    "FillPlayer(tri, 16, 16, interval=20)",
    "editor = TriangleEditor(tri, 16, 16)\neditor",
    "import json\npage = editor.display.widget\n"
    "print('EDITOR', json.dumps({'transform': page.transform, 'size': page.size, "
    "'handles': page.handles}))",
    "from teachraster.widgets import Predict\n"
    "Predict('Which way does it wind?', ['clockwise', 'counter-clockwise'], 'clockwise')",
    "from teachraster.widgets import BlendingExplorer\nBlendingExplorer(size=(16, 16))",
]
#: The stand-ins' hint (the editor's own words are its module's: teachraster/widgets/editor.py)
HINT = "Run All (Run \u25b8 Run All Cells) to bring it back"


def _api(tab, method: str, path: str, body: str | None = None) -> int:
    """A REST call from the page (the server wants the page's XSRF cookie on writes)."""
    return tab.evaluate(API, [method, path, body])


def _put_notebook(tab, cells=CELLS, name=NAME) -> None:
    """Write a notebook of ``cells`` (code) to the lab's folder as ``name``."""
    put_notebook(tab, cells, name)


def _run_all(base: str, tab, cells, name) -> None:
    """A fresh kernel, a notebook of ``cells`` written as ``name``, opened, every cell run."""
    open_cells(tab, base, cells, name)
    wait_until_idle(tab, base, name)
    assert tab.locator(".jp-FileBrowser").first.is_visible()  # the file browser is open
    tab.click(".lm-MenuBar-itemLabel:text-is('Run')")
    tab.click(".lm-Menu-itemLabel:text-is('Run All Cells')")


def _stop_kernels(tab, base: str) -> None:
    with urllib.request.urlopen(f"{base}/api/kernels", timeout=10) as r:
        for k in json.load(r):
            assert _api(tab, "DELETE", f"/api/kernels/{k['id']}") == 204


def _open(tab, base: str) -> None:
    tab.goto(f"{base}/lab/tree/{NAME}?reset")
    tab.wait_for_selector(CELL_SHOWN, timeout=90_000)
    tab.wait_for_selector("#jp-main-statusbar >> text=/\\| Idle/", timeout=90_000)


def test_a_saved_lesson_reopened_shows_pictures_not_model_not_found(lab, page):  # noqa: F811
    _shut_down_kernels(lab)
    page.goto(f"{lab}/lab?reset")
    page.wait_for_selector("#jp-main-statusbar", timeout=90_000)
    _put_notebook(page)
    _open(page, lab)
    page.click(".lm-MenuBar-itemLabel:text-is('Run')")
    page.click(".lm-Menu-itemLabel:text-is('Run All Cells')")
    canvas = page.locator(".tr-frames canvas.teachraster-figure").first
    canvas.wait_for(state="visible", timeout=120_000)
    editor = page.locator(".tr-drag img").first
    editor.wait_for(state="visible", timeout=60_000)
    for text in ("Which way does it wind?", "Blending: order"):  # the last cells ran
        page.locator(".jupyter-widgets", has_text=text).first.wait_for(timeout=60_000)
    fallbacks = page.locator(".teachraster-static")
    assert fallbacks.count() == 4  # one per widget, in the page but hidden while they live
    assert not any(f.is_visible() for f in fallbacks.all())
    # saved with its outputs, as a student's Ctrl+S does
    saved = save_and_read(page, lab, NAME)
    html = [o["data"].get("text/html", "") for c in saved["cells"] for o in c.get("outputs", [])
            if "data" in o]  # fmt: skip
    # each widget: an output with the picture; the widget's own output has an empty
    # text/html, so an untrusted copy (no CSS) shows the stand-in once (review r158)
    assert sum("teachraster-static" in h for h in html) == 4

    # The kernel goes away under the open page: a vertex dragged says so (no silent editor).
    out = page.locator(".jp-OutputArea-output", has_text="EDITOR").last
    info = json.loads(out.inner_text().split("EDITOR", 1)[1])
    _stop_kernels(page, lab)
    editor.scroll_into_view_if_needed()
    box = editor.bounding_box()
    x0, y0, sx, sy = info["transform"]
    scale = box["width"] / info["size"][0]
    hx, hy = info["handles"][1]
    px, py = box["x"] + (x0 + sx * hx) * scale, box["y"] + (y0 + sy * hy) * scale
    page.mouse.move(px, py)
    page.mouse.down()
    page.mouse.move(px - 8, py, steps=4)
    notice = page.locator(".tr-drag-notice").first
    notice.filter(has_text="does not answer").wait_for(timeout=15_000)
    page.mouse.up()

    # The next day: the notebook opened again (a new kernel, which knows no widget model).
    _stop_kernels(page, lab)
    _open(page, lab)
    fallbacks = page.locator(".teachraster-static")
    fallbacks.first.wait_for(state="visible", timeout=60_000)
    page.wait_for_timeout(2000)  # the widget manager has given up on the models by now
    shown = [f for f in fallbacks.all() if f.is_visible()]
    assert len(shown) == 4
    player, editor, question, explorer = (f.inner_text() for f in shown)
    assert all(HINT in t for t in (player, editor, question, explorer))  # one hint for all
    assert "Which way does it wind?" in question and "counter-clockwise" in question
    assert "Blending" in explorer  # its title
    for f in (shown[0], shown[1], shown[3]):
        img = f.locator("img").first
        assert img.evaluate("i => i.complete && i.naturalWidth > 100")
    errors = page.get_by_text("Error displaying widget")
    assert not any(e.is_visible() for e in errors.all()), "the manager's error is on show"


def test_an_executed_copy_opened_untrusted_shows_each_standin_once(
    lab,  # noqa: F811
    page,  # noqa: F811
    tmp_path,
    monkeypatch,
):
    """Review r158 (05a): a copy executed by nbclient (nbconvert --execute: widget state
    saved, no signature) opened in JupyterLab is untrusted. The sanitizer removes the
    stand-in's <style>, and each output shows its text/html in place of the widget view; the
    widget's own text/html was the stand-in too, so every stand-in stood twice."""
    import nbformat
    from nbclient import NotebookClient

    monkeypatch.setenv("TEACHRASTER_HEADLESS", "0")  # a student's kernel: widgets, not answers
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in CELLS if "EDITOR" not in c]
    NotebookClient(nb, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": str(tmp_path)}}).execute()  # fmt: skip
    assert "widgets" in nb.metadata  # the widget state, as nbconvert saves it
    name = "executed_copy.ipynb"
    _shut_down_kernels(lab)
    page.goto(f"{lab}/lab?reset")
    page.wait_for_selector("#jp-main-statusbar", timeout=90_000)
    body = json.dumps({"type": "notebook", "content": json.loads(nbformat.writes(nb))})
    assert _api(page, "PUT", f"/api/contents/{name}", body) in (200, 201)
    page.goto(f"{lab}/lab/tree/{name}?reset")
    page.wait_for_selector(CELL_SHOWN, timeout=90_000)
    hints = page.get_by_text("No kernel is running")
    hints.first.wait_for(state="visible", timeout=60_000)
    page.wait_for_timeout(3000)  # every output rendered
    shown = [h for h in hints.all() if h.is_visible()]
    assert len(shown) == 4, f"{len(shown)} stand-ins on show for 4 widgets"
