"""Lesson 11, review r476: S1, S2, S3, S4 and S8 (see each test's docstring)."""

from __future__ import annotations

import json
import re
from pathlib import Path

from notebook_runs import lesson

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks" / "11_debugging_a_frame.ipynb"


def _cells():
    return json.loads(NOTEBOOK.read_text())["cells"]


def _text(cell):
    return " ".join("".join(cell["source"]).split())


def _sampled_by(h):
    """{triangle: samples of the pixel it covers}, as the lesson's ``sampled_by``."""
    return {
        t: sum(x.triangle == t and x.outcome != "not_covered" for x in h)
        for t in sorted({x.triangle for x in h})
    }


def test_11_r476_answer_code_hidden_and_question_2_names_its_pixels():
    """S2: the folded answers' code (45 to 76 lines: the hub search, the palest quads, Question
    4's bound, the layer weights) stood between each inspector question and the inspector;
    it is hidden, as the predictions' code is. S3: Question 2 asked about "the pixels around
    its centre" while its answer holds for one pixel; it names the four that touch the
    centre, and the answer prints that they read alike (one pixel out they do not)."""
    cells = _cells()
    folds = [c for c in cells if c["cell_type"] == "code" and "folded(\n" in "".join(c["source"])]
    assert len(folds) == 4  # Questions 2 to 5
    for c in folds:
        meta = c["metadata"]
        assert meta["jupyter"]["source_hidden"] is True and "hide-input" in meta["tags"]
    q2 = next(_text(c) for c in cells if _text(c).startswith("**Question 2.**"))
    assert "look at the four pixels that touch its centre, where the triangles meet" in q2
    ns = lesson("11_debugging_a_frame")
    assert ns.hub in ns.around and len(ns.around) == 4 and ns.same
    reach = {len(_sampled_by(ns.fan1.history(*rc))) for rc in ns.around}
    sampled = {sum(n > 0 for n in _sampled_by(ns.fan4.history(*rc)).values()) for rc in ns.around}
    assert reach == sampled == {3} and ns.alike == {(3, 3)}
    assert ns.read == "alike: 3 triangles reach each, and as many get a sample of it."
    # one pixel out (above the centre's upper-right pixel) only one triangle gets a sample
    r, c = min(ns.around)
    assert sum(n > 0 for n in _sampled_by(ns.fan4.history(r - 1, c + 1)).values()) == 1


def test_11_r476_one_inspector_hint_for_question_1():
    """S1: cell 15 repeated the held reading's inspector hint after §2's z-fighting part; the
    hint is said once, in the held reading after Question 1, with cell 15's one new sentence.
    The inspector's comment points there."""
    cells = _cells()
    whole = " ".join(_text(c) for c in cells)
    assert whole.count("choose `intersecting_triangles`, untick *depth test on") == 1
    assert "which §2's reading after Question 1 sends you back to" in whole
    ids = [c.get("id") for c in cells]
    # §2 ends on the z-fighting reading; §3 follows it
    z_why = next(i for i, c in enumerate(cells) if _text(c).startswith("**Why a band along"))
    assert _text(cells[z_why + 1]).startswith("## 3. ")
    assert "farwhy" in ids


def test_11_r476_word_budget_tables_folded_and_the_shader_debugger():
    """S4: 4,157 words of markdown (cell 4 alone 325 before the first figure). Cell 4 is thinned
    to the columns, Hi-Z and the replay; the two standards tables (early tests, tools) are
    folded in <details>, so what a student reads without opening a fold is under 3,710 words;
    the held API table after Question 1 is folded too, and the Summary is shorter.
    S8: the step a pixel history leads to, the shader debugger at that pixel, is named."""
    cells = _cells()
    md = ["".join(c["source"]) for c in cells if c["cell_type"] == "markdown"]
    words = sum(len(t.split()) for t in md)
    shown = sum(len(re.sub(r"<details>.*?</details>", "", t, flags=re.S).split()) for t in md)
    assert words <= 4050, words
    assert shown <= 3710, shown
    first = next(_text(c) for c in cells if _text(c).startswith("Read the table row by row"))
    assert len(first.split()) <= 250
    for start in ("**Testing before shading.**", "**What the standards and the tools offer.**"):
        cell = next(t for t in md if t.startswith(start))
        shown_part = re.sub(r"<details>.*?</details>", "", cell, flags=re.S)
        assert "\n| " not in shown_part and "<details><summary>" in cell, start
    held = "".join(next(c["source"] for c in cells if c.get("id") == "farwhy"))
    assert held.index("<details><summary>The three settings") < held.index("| OpenGL 4.6 |")
    assert held.index("| teachraster |") < held.index("</details>")
    tools = next(_text(c) for c in cells if _text(c).startswith("**What the standards"))
    assert "(RenderDoc's *Debug Pixel*, PIX's shader debugging); teachraster runs no shader" in (
        tools
    )
