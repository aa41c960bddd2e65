"""Lesson 05a, review r484: each test fails on the lesson before the fix.

W-1: q_step asks the student to click pixels on a picture whose passed fragments are
Okabe-Ito blue, and ``PredictPixels`` marked a clicked pixel only by filling it with that
blue at 45 %: on a blue pixel nothing showed. Every marked cell is now ringed too, a
near-black line on a white halo (vermillion once revealed, the key's "not among them").
S-1: cell 19 called a traced fragment's own depth "its stored depth".
"""

from __future__ import annotations

import json
from pathlib import Path

import teachraster as tr

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "05a_zbuffer.ipynb"
JS = Path(tr.__file__).parent / "widgets" / "static" / "predict_figure.js"


def _marking_code() -> str:
    # the page's drawing of the pixel grid's marks: mountPixels up to its reveal
    return JS.read_text().split("function mountPixels")[-1].split("function reveal")[0]


def test_w1_a_marked_pixel_is_ringed_not_only_tinted_with_the_pictures_blue():
    from teachraster.plotting.zbuffer_steps import FRAGMENT_COLORS

    js, marks = JS.read_text(), _marking_code()
    assert 'GIVEN_FILL = "rgba(0,114,178,0.45)"' in js  # the fill: the passed fragments' blue
    assert FRAGMENT_COLORS[2].lower() == "#0072b2"  # which is why the fill alone vanished
    given = marks.split("for (const [r, c] of state.given) {")[1].split("if (known) {")[0]
    assert "ctx.fillStyle = GIVEN_FILL" in given
    # a dark line on a white halo round every marked cell, before and after Check
    assert '[3, "white"]' in given and "known ? OKABE.vermillion : GIVEN_LINE" in given
    assert "ctx.strokeRect(" in given
    assert 'GIVEN_LINE = "#111"' in js
    # the key still names the wrong marks by the vermillion border they are drawn with
    assert "border:2px solid ${OKABE.vermillion}`)}" in js


def test_s1_a_traced_fragment_records_its_own_depth_not_a_stored_one():
    text = "\n".join("".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"])
    assert "records every fragment in drawing order, its depth and" in text
    assert "its stored depth" not in text
