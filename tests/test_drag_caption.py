"""Issue 31: the PlaneExplorer's vertex dragged at 21-22 fps (round trip 83 ms, the editor's 47).
Each position sent its caption twice, as a trait sync and in the frame message, and the page laid
the text out twice. Mid-drag the caption now travels only with its picture; the trait follows at
the release (what a re-opened view shows)."""

from __future__ import annotations

import re
from pathlib import Path

from teachraster.widgets import PlaneExplorer

DRAG_JS = Path(__file__).resolve().parents[1] / "teachraster" / "widgets" / "static" / "drag.js"


def _pressed(page, i, x, y, final):
    page._on_page_message(page, {"type": "move", "i": i, "x": x, "y": y, "seq": 1,
                                 "final": final}, [])  # fmt: skip


def test_a_drag_sends_its_caption_with_each_picture_and_syncs_it_at_the_release():
    ex = PlaneExplorer(backend="image")
    page = ex.display.widget
    sent, synced = [], []
    page.send = lambda content, buffers=None: sent.append(content)
    page.observe(lambda change: synced.append(change["new"]), "caption")
    before = page.caption
    _pressed(page, 0, 4.0, 2.0, final=False)
    frame = [m for m in sent if m["type"] == "frame"][-1]
    assert synced == [] and page.caption == before  # no trait message mid-drag
    assert "4.00" in frame["caption"] and frame["caption"] != before  # v1 x = 4 in its system
    assert ex.info.value == frame["caption"]  # what the explorer says it shows
    _pressed(page, 0, 4.5, 2.0, final=True)
    final = [m for m in sent if m["type"] == "frame"][-1]
    assert synced and page.caption == synced[-1] == final["caption"] == ex.info.value
    assert "4.50" in page.caption and page.drag_caption is None
    ex.x[0].value = 3.0  # a slider outside a drag: the trait, as before
    assert page.caption == ex.info.value and "3.00" in page.caption
    ex.close()


def test_the_page_lays_out_a_caption_only_when_its_text_changes():
    source = DRAG_JS.read_text(encoding="utf-8")
    body = re.search(r"function setCaption\(html\) \{(.*?)\n  \}", source, re.S).group(1)
    assert "=== captionShown) return" in body


def test_the_editors_probe_verdict_names_a_zero_area_triangle_and_a_vertex():
    """Review r181 02-5: with all three E zero (a zero-area triangle) the probe's line said
    "one is 0: on an edge (the top-left rule decides)", with "+0.00" for each value."""
    from teachraster import Triangle
    from teachraster.widgets import TriangleEditor

    flat = TriangleEditor(Triangle([[2.0, 2.0], [8.0, 8.0], [14.0, 14.0]]), 16, 16, backend="image",
                          probe=(5.0, 5.0), comparison=False)  # fmt: skip
    line = flat.probe_text()
    assert "all three 0: a zero-area triangle, nothing covered" in line
    assert "E12 = 0, E23 = 0, E31 = 0" in line and "+0.00" not in line
    tri = Triangle([[2.0, 2.0], [14.0, 2.0], [2.0, 14.0]])
    at_vertex = TriangleEditor(tri, 16, 16, backend="image", probe=(2.0, 2.0), comparison=False)
    assert "two are 0: on a vertex" in at_vertex.probe_text()
    on_edge = TriangleEditor(tri, 16, 16, backend="image", probe=(8.0, 2.0), comparison=False)
    assert "one is 0: on an edge" in on_edge.probe_text()
    inside = TriangleEditor(tri, 16, 16, backend="image", probe=(5.0, 5.0), comparison=False)
    assert "inside" in inside.probe_text() and "is 0" not in inside.probe_text()
    for editor in (flat, at_vertex, on_edge, inside):
        editor.close()
