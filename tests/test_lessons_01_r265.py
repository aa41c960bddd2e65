"""Lesson 01, review r265: each test fails on the lesson before the fix.

C1: the float error's size, as printed; P2: q_row on the mirrored triangle, whose middle
vertex's pixel is filled; M1/M2: the fill-rule table and the exercise; P1: q_fail a number on
a 0-200 line; FIG1-FIG3: the prestep's changed pixels, the crack explorer's marks at 32 x 32,
the player's vertex tags.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "01_span_tables.ipynb"


def _cells() -> list[dict]:
    return json.loads(NOTEBOOK.read_text())["cells"]


def _source(cell_id: str) -> str:
    return " ".join("".join(next(c for c in _cells() if c.get("id") == cell_id)["source"]).split())


@pytest.mark.notebook
def test_c1_the_float_error_keeps_its_sign_but_not_its_size():
    """Cell 26 said the float error "grows" down the edge; the table shrinks on row 6."""
    ns = lesson("01_span_tables")
    assert ns.float_signs == {1} and ns.float_peak == 5
    assert abs(ns.float_off[6]) < abs(ns.float_off[5])  # shrinks on row 6
    told = _source("dda_walk_text")
    assert "keeps its sign and grows" not in told
    assert "it grows to row 5 and shrinks on row 6" in told


@pytest.mark.notebook
def test_p2_q_row_needs_the_rule_at_the_middle_vertex():
    """q_row's new rows had empty answers, and row 9 repeated the worked row 5: clicking row 9
    alone passed. On the mirrored triangle row 9 starts at v2, a left end: its pixel is in."""
    import numpy as np

    ns = lesson("01_span_tables")
    (u2, v2) = ns.mirrored[1]
    assert ns.row_answer[int(v2), int(u2)] and ns.mirror_filled == [False, True, False]
    # "a vertex's pixel is never filled", true of the triangle as given, now misses one
    assert ns.vertex_filled == [False, False, False]
    guess = ns.row_answer.copy()
    guess[int(v2), int(u2)] = False
    assert not np.array_equal(guess, ns.row_answer)
    explain = " ".join(_source("ece0fd62").split("explain=")[1].split())
    assert "the first is v2's own" in explain and "<i>left</i> edges now" in explain
    assert "Row {r_mid}: x<sub>left</sub> = {mid_l:g} is v2 itself" in explain


def test_m1_m2_the_rule_in_the_apis_and_the_exercise():
    """No fill-rule table where the lesson first applies the rule; no pointer to the exercise."""
    ids = [c.get("id") for c in _cells()]
    table = _source("c11-apis")
    assert ids.index("c11-apis") == ids.index("c11") + 1  # after q_row's last held cell
    for where in ("§14.6.1", "§3.4.2.1 *Top-Left Rule*", "§3.4.1 *Coordinate Snapping*",
                  "*Basic Polygon Rasterization*", "llvmpipe", "teachraster"):  # fmt: skip
        assert where in table, where
    assert "*are* Direct3D's top-left rule written for span tables" in table
    assert "left and top edges closed, right and bottom edges open" in table
    end = _source(ids[-1])
    assert "[exercises/02_span_split](exercises/02_span_split.ipynb)" in end
    assert (ROOT / "notebooks" / "exercises" / "02_span_split.ipynb").exists()


@pytest.mark.notebook
def test_p1_q_fail_is_a_count_on_a_line():
    """q_fail was a five-bucket choice ("21 to 100") where the census gives a number."""
    ns = lesson("01_span_tables")
    ask = _source("c19-q-fail")
    assert "q_fail = PredictPoint(" in ask and "PredictChoice(" not in ask
    assert "xlim=(0, n_random)" in ask and "along=((0, 0.5), (n_random, 0.5))" in ask
    assert "start=(0, 0.5)" in ask  # no count suggested
    assert ns.fail_point == (ns.n_float, 0.5) == (60, 0.5)
    assert round(ns.guess) == 59 and abs(ns.guess - 60) <= ns.fail_tolerance < 109 - 60
    ids = [c.get("id") for c in _cells()]
    held = _cells()[ids.index("c19-q-fail") + 1]
    assert "".join(held["source"]).startswith("q_fail.hold()")  # the count printed after it
