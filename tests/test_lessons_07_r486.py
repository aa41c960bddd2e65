"""Lesson 07, review r486: each test fails on the lesson before the fix.

P1: q_flat (click the flat top's tie centres the top-left rule draws) stood after §1's split
square, whose text gives its answer for a triangle of the same shape ("the top and left sides
to the upper-left one", the diagonal's ends to neither). It now opens §1, before the square.
S1: the flat-top figure numbers its rows and columns, as its printout and q_flat name pixels.
S2: BEHIND_TEXT no longer repeats q_behind's explanation (the vertex thrown through the eye).
S3: q_depth's premise said the wrong triangle "wins in a band", ruling out its first option
("none: 24 significant bits are plenty"); it says "may win" now.
"""

from __future__ import annotations

import json
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "07_hard_cases.ipynb"


def _sources() -> list[str]:
    return ["".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]]


def _at(text: list[str], needle: str) -> int:
    return next(i for i, t in enumerate(text) if needle in t)


def test_the_flat_top_is_asked_before_the_split_square_tells_the_rule():
    text = _sources()
    heading = _at(text, "## 1. Ties on pixel centres")
    ask, square = _at(text, "q_flat = PredictPixels("), _at(text, "**The split square.**")
    assert heading < ask < square
    # nothing between the heading and the question says which edge centres are drawn
    before = " ".join(text[heading:ask])
    for said in ("top and left sides", "upper-left one", "go to neither"):
        assert said not in before, said
    told = _at(text, "which go to neither")
    square_text = " ".join(text[told].split())
    assert told > ask and "the top and left sides to the upper-left one" in square_text


def test_the_flat_top_figure_numbers_rows_and_columns():
    (held,) = [t for t in _sources() if t.startswith("q_flat.hold()")]
    assert "ticks=2)" in held


def test_the_behind_camera_reading_does_not_repeat_the_explanation():
    (held,) = [" ".join(t.split()) for t in _sources() if t.startswith("q_behind.hold()")]
    reading = held.split('BEHIND_TEXT = rf"""')[1].split('"""')[0]
    assert "throws the vertex through the eye" not in reading
    assert reading.startswith("The mirrored vertex is the apex reaching up into the sky")


def test_q_depth_leaves_none_a_live_answer():
    (ask,) = [" ".join(t.split()) for t in _sources() if "q_depth = PredictChoice(" in t]
    question = ask.replace('" "', "").split("depth_choices,")[0]
    assert "may win in a band" in question and "wins in a band" not in question
    assert '"none: 24 significant bits are plenty"' in ask
