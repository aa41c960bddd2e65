"""Every widget leaves a readable stand-in in the saved notebook, with a hint that works.

A lesson run, saved with its outputs and reopened with a new kernel has no widget models:
JupyterLab would show "Error displaying widget: model not found" in place of each widget
(issue 31: 43 of them over the 14 lessons). Each widget of this package therefore displays a
stand-in in an output of its own just before its view (``common.display_with_fallback``): a
``Predict`` its question and choices, an explorer or player its last picture, and the hint
"Run All (Run ▸ Run All Cells) to bring it back" (running the cell alone fails with
``NameError``: its names come from the cells above). ``tests/test_browser_saved.py`` checks
what JupyterLab then shows; these tests check the outputs themselves, without a browser.
"""

from __future__ import annotations

import base64
import re

import IPython.display
import nbformat
import pytest
from widget_examples import examples

from teachraster.widgets.common import Shown, _pictures

VIEW = "application/vnd.jupyter.widget-view+json"
HINT = "Run All (Run ▸ Run All Cells) to bring it back"

#: Widgets that display through ``Shown`` without inheriting it (each borrows its
#: ``_ipython_display_``; a base class of their own): the explorers of lessons 03 to 11.
BORROWS_SHOWN = {"TileExplorer", "TexturedPlaneViewer", "PixelInspector", "FilterExplorer",
                 "FrameInspector", "PlaneExplorer", "DepthPrecisionExplorer",
                 "CasePicker"}  # fmt: skip


def _in_scope():
    return sorted(examples())


def _shows_like_shown(widget) -> bool:
    return isinstance(widget, Shown) or type(widget)._ipython_display_ is Shown._ipython_display_


@pytest.fixture
def shown(monkeypatch):
    """What a widget publishes when displayed: a list of mime bundles, in order."""
    out = []
    monkeypatch.setattr(IPython.display, "publish_display_data",
                        lambda data, **kw: out.append(data))  # fmt: skip
    return out


def _pngs(html: str) -> list[bytes]:
    return [
        base64.b64decode(m) for m in re.findall(r"data:image/png;base64,([A-Za-z0-9+/=]+)", html)
    ]


def test_the_widgets_that_borrow_shown_are_widgets():
    assert BORROWS_SHOWN <= set(examples())  # a renamed widget is noticed here


@pytest.mark.parametrize("name", _in_scope())
def test_each_widget_view_follows_a_standin_with_a_hint_that_works(name, shown):
    widget = examples()[name]()
    if name == "Predict":
        widget.headless = False  # as in a student's kernel (the tests' backend is Agg)
    widget._ipython_display_()
    views = [i for i, d in enumerate(shown) if VIEW in d]
    assert views, f"{name} showed no widget"
    for i in views:
        standin = shown[i - 1].get("text/html", "") if i else ""
        assert "teachraster-static" in standin and VIEW not in shown[i - 1]
        assert HINT in standin and "Run this cell" not in standin
        assert "<style>" in standin  # hides it while the widget lives
    # the picture drawn by the kernel (an explorable's comes from its page, once drawn there;
    # the PredictOrder example has no picture)
    drawn = ("FillPlayer", "PredictPixels", "PredictPoint", "TriangleEditor")
    if _shows_like_shown(widget) or name in drawn:
        assert any(p.startswith(b"\x89PNG") for p in _pngs(shown[views[0] - 1]["text/html"]))


def test_a_predict_standin_reads_as_the_question():
    from teachraster.widgets import Predict

    q = Predict("Which <i>row</i>?", ["row 2", "row 3 & 4"], "row 2", headless=False)
    html = q.standin_html()
    assert "Which <i>row</i>?" in html and "row 2" in html and "row 3 &amp; 4" in html
    n = Predict("How many?", answer=3, headless=False).standin_html()
    assert "a number" in n and HINT in n
    order = examples()["PredictOrder"]()._standin()
    assert "Nearest first?" in order and ">a</span>" in order and ">b</span>" in order


def test_an_explorers_standin_follows_its_picture(shown, monkeypatch):
    updates = []
    monkeypatch.setattr(IPython.display, "update_display",
                        lambda data, **kw: updates.append((data, kw)))  # fmt: skip
    explorer = examples()["ProjectionExplorer"]()
    explorer._ipython_display_()
    first = _pngs(shown[0]["text/html"])
    explorer.q.value = explorer.q.max  # no event loop here: the stand-in follows at once
    data, kw = updates[-1]
    assert kw["display_id"] == explorer._standin_id and kw["raw"]
    assert HINT in data["text/html"] and _pngs(data["text/html"]) != first


def test_the_players_standin_follows_the_step(shown, monkeypatch):
    updates = []
    monkeypatch.setattr(IPython.display, "update_display",
                        lambda data, **kw: updates.append((data, kw)))  # fmt: skip
    player = examples()["FillPlayer"]()
    player._ipython_display_()
    first = _pngs(shown[0]["text/html"])
    player.slider.value = player.slider.max
    data, kw = updates[-1]
    assert kw["display_id"] == player._standin_id
    last = _pngs(data["text/html"])
    assert len(last) == 1 and last != first
    player.method.value = "halfplane"  # another fill: its picture
    assert _pngs(updates[-1][0]["text/html"]) not in (first, last)
    assert player.view.step == player.frames.value  # the view is left on the step on show


CELLS = [
    "import asyncio\nfrom teachraster.widgets import Predict, FillPlayer, PredictOrder\n"
    "from teachraster.widgets.projection_explorer import ProjectionExplorer\n"
    "import teachraster as tr",
    "Predict('Which?', ['a', 'b'], 'a', explain='A.')",
    "PredictOrder('Nearest first?', ['a', 'b'], answer=['b', 'a'])",
    "player = FillPlayer(tr.Triangle([[1.2, 1.5], [13.7, 4.2], [5.1, 12.8]]), 8, 8)\nplayer",
    "explorer = ProjectionExplorer()\nexplorer",
    "player.slider.value = player.slider.max\nexplorer.q.value = explorer.q.max\n"
    "await asyncio.sleep(1.5)  # the stand-ins follow once the pictures settle",
]


@pytest.mark.notebook
def test_saved_outputs_carry_a_standin_before_each_widget_view(monkeypatch, tmp_path):
    """A real kernel (nbclient): the saved notebook's outputs, as JupyterLab would save them."""
    from nbclient import NotebookClient

    monkeypatch.setenv("TEACHRASTER_HEADLESS", "0")  # a student's kernel: widgets, not answers
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in CELLS]
    NotebookClient(nb, timeout=300, kernel_name="python3",
                   resources={"metadata": {"path": str(tmp_path)}}).execute()  # fmt: skip
    outputs = [o for c in nb.cells for o in c.outputs if o.get("output_type") == "display_data"]
    views = [i for i, o in enumerate(outputs) if VIEW in o["data"]]
    assert len(views) == 4
    for i in views:
        assert HINT in outputs[i - 1]["data"].get("text/html", "")
    # both followed their picture (the last step; q at its end) once the cell that moved them
    # let the kernel idle: the stand-in's picture is the one of the widget as it was left
    for i in views[2:]:
        assert _pngs(outputs[i - 1]["data"]["text/html"])
    assert _untrusted_standins(outputs) == [1, 1, 1, 1]


def _untrusted_standins(outputs: list) -> list[int]:
    """How many stand-ins JupyterLab shows round each widget view of an untrusted notebook
    (an nbconvert-executed copy): ``<style>`` is sanitized away, so FALLBACK_CSS hides
    nothing, and each output shows its ``text/html`` (the widget view is not a safe
    renderer). Counted over the view's output and the one before it."""
    datas = [o["data"] if "data" in o else o for o in outputs]
    views = [i for i, d in enumerate(datas) if VIEW in d]
    return [sum("teachraster-static" in datas[j].get("text/html", "") for j in (i - 1, i))
            for i in views]  # fmt: skip


@pytest.mark.parametrize("name", _in_scope())
def test_an_untrusted_notebook_shows_each_standin_once(name, shown):
    """Review r158 (05a): the widget's own output carried the stand-in as its text/html too,
    which an untrusted notebook (no CSS, text/html in place of the widget) showed twice."""
    widget = examples()[name]()
    if name == "Predict":
        widget.headless = False
    widget._ipython_display_()
    assert set(_untrusted_standins(shown)) == {1}


@pytest.mark.parametrize("name", sorted(BORROWS_SHOWN))
def test_the_explorers_that_borrow_shown_show_their_title_and_follow_their_picture(
    name, shown, monkeypatch
):
    """Each class displays through ``Shown`` (its own ``_ipython_display_``, called as a
    notebook would): its title and picture, then the picture it is left on."""
    import numpy as np

    from teachraster.plotting.frames import encode_png

    updates = []
    monkeypatch.setattr(IPython.display, "update_display",
                        lambda data, **kw: updates.append((data, kw)))  # fmt: skip
    widget = examples()[name]()
    assert _shows_like_shown(widget)
    widget._ipython_display_()
    standin, view = shown
    assert VIEW in view and HINT in standin["text/html"]
    assert any(p.startswith(b"\x89PNG") for p in _pngs(standin["text/html"]))
    title = widget.widget.children[0].value  # the box's title line (common.title_html)
    assert re.sub("<[^>]+>", "", title)[:20] in standin["text/html"]
    # it follows the picture too (no event loop here: at once)
    w, trait = _pictures(widget.widget)[0]
    png = encode_png(np.full((2, 3, 4), 200, np.uint8))
    setattr(w, trait, png)
    data, kw = updates[-1]
    assert png in _pngs(data["text/html"]) and kw["display_id"] == widget._standin_id
