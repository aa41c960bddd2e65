"""Lesson 05a, review r498 (density): each test fails on the lesson before the fix.

M-1: no word budget held the lesson (5,060 Markdown words); it is capped at the length left.
S-1: the pointer to exercise 4.3 read "asks the colours of ...". S-2: §4 described llvmpipe's
band three times and the GPUs' bands twice. S-3: the main flow printed teachraster's L and
the band's derivation (the simulator's integers); the formula is the fold's, the cell checks
it and prints g. S-4: early-z's "the vendor decides" was said in the main text and again in
the fold. S-5: cell 4 quoted three specifications in a list for one rule. S-6: cell 8 spent
a paragraph on what the folded cells do. S-7: "It does not follow the pseudo-code" after a
paragraph on OpenGL meant ``tr.render``. S-9: q_clip's options all began "those from the
first vertex to".
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from notebook_runs import executed, lesson, streams

ROOT = Path(__file__).resolve().parent.parent
NAME = "05a_zbuffer"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"
#: The Markdown cells' words after r498 (5,060 before): cut elsewhere to add.
WORD_BUDGET = 4553


def _cells() -> dict[str, str]:
    return {c["id"]: "".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]}


def _words(text: str) -> int:
    return len(text.split())


def test_m1_word_budget():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    words = sum(_words("".join(c["source"])) for c in cells if c["cell_type"] == "markdown")
    assert words <= WORD_BUDGET, words


def test_s1_exercise_4_3_pointer_reads_as_a_sentence():
    clipper = " ".join(_cells()["c15b"].split())
    assert "asks the colours" not in clipper
    assert ("Exercise 4.3 turns this round: the colours of a clipper's polygon from its "
            "positions alone.") in clipper  # fmt: skip
    exercises = (ROOT / "notebooks" / "exercises" / "04_depth_and_clipping.ipynb").read_text()
    assert "## 4.3 The colours of a clipped polygon" in exercises
    assert "def clipped_colours(v, colours, polygon):" in exercises


def test_s2_s6_bands_told_once_and_no_cell_tours():
    cells = _cells()
    gpus = " ".join(cells["guard_md"].split("<details>")[0].split())
    assert "`freedreno_guardband.h`" in gpus and "$|x|, |y| \\le 2w$" in gpus
    for cid in ("guard_gpus_md", "guard_fig_md"):
        flat = " ".join(cells[cid].split())
        assert "2w" not in flat and "larger from Gen7" not in flat and "twice its width" not in flat
    assert _words(cells["guard_gpus_md"]) <= 80 and _words(cells["guard_fig_md"]) <= 270
    # S-6: one sentence on the folded cells, not a paragraph on each
    tour = cells["sticks_md"].split("\n\n")[-1]
    assert tour.startswith("The next four cells are folded") and _words(tour) <= 40


@pytest.mark.notebook
def test_s3_teachraster_band_checked_and_printed_once():
    cell = _cells()["guard_band"]
    assert "assert np.isclose(band, band_formula)" in cell and "2**30 units" not in cell
    ns = lesson(NAME)
    assert ns.band == pytest.approx(ns.band_formula) and f"{ns.band:,.0f}" == "26,187"
    out = streams(executed(NAME).notebook())
    assert "teachraster's band for 160 x 120: |x/w| <= g = 26,187" in out
    assert "L = 2**30" not in out and "the renderer's guard_band" not in out


def test_s4_s5_s7_one_statement_each():
    cells = _cells()
    early = " ".join(cells["c11"].split())
    assert early.count("vendor") == 1 and "not a promise of speed" not in early
    assert "profile on the GPUs you ship for" in early.split("<details>")[0]
    off = " ".join(cells["c02_off"].split())
    assert off.count("in all three APIs") == 1 and "In `tr.render` that is both switches" not in off
    assert _words(cells["c02_off"]) <= 400
    assert "`tr.render` does *not* follow the pseudo-code" in " ".join(cells["c02"].split())


def test_s9_q_clip_options_do_not_repeat_their_start():
    asked = _cells()["c16q"]
    options = asked.split("clip_choices = [", 1)[1].split("]", 1)[0]
    assert "those from the first vertex" not in options and '"only the first vertex"' in options
    assert "up to the near plane, z/w = −1" in options
