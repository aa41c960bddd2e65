"""r388 (exercise 11 read again): 11.3b's three cases let two wrong methods pass (log₂ rounded
to the nearest bit, a step of 1/2ⁿ) and a third (the pane's stored depth minus its drawn
one), all three walls on the 16-bit grid; "this wall's depth only" was named on one case of
depths rounded to six decimals; one bit too many, ln or log10 for log₂, the gap in 16-bit
steps and a negative gap were half-named or raw; the question, read literally, moved the wall
alone; the rule said "a whole step or more" where rounding half to even ties exactly one; the
figure drew the whole step before the words gave it; frame 1 quoted triangle 3 as "3.0". The
slips are corpus cases too (``student_variants.R388``)."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
import reasoning_solutions as sol
from student_variants import KINDS, R377, R388

from teachraster import exercises as ex
from teachraster.exercises import broken_frame_steps as bfs
from teachraster.exercises import tries

NAME = "broken_frame_3_steps"
NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "11_broken_frames.ipynb"


@pytest.mark.parametrize("label", sorted(R388))
def test_each_slip_fails_a_case_and_is_named_in_the_first_explanation(label):
    name, fn, words, kind = R388[label]
    report = ex.check(name, fn)
    assert not report.passed, label
    first = report.failures[0]
    assert first.kind == kind == KINDS[label], (label, first.kind, first.explanation)
    assert words in first.explanation, (label, first.explanation)
    assert "cannot convert float NaN" not in first.explanation or "negative" in first.explanation


def _gaps():
    return [bfs._gap(b) for _, (b,), _ in bfs.BROKEN_FRAME_3_STEPS.cases()]


def test_the_cases_part_each_slip_from_the_answer():
    """G1-G3: a gap whose log₂(1/gap) has a fraction below ½, one in (1/2ⁿ, 1/(2ⁿ − 1)], a
    wall off the 16-bit grid (stored minus drawn is not the gap), every pane still tied."""
    cases = bfs.BROKEN_FRAME_3_STEPS.cases()
    logs = [math.log2(1 / g) for g in _gaps()]
    assert any(0 < x % 1 < 0.5 for x in logs), logs
    assert any(1 / (2 ** round(x)) < g <= 1 / (2 ** round(x) - 1) for x, g in zip(logs, _gaps()))
    assert any(not math.isclose(bfs._stored_minus_drawn(b), bfs._gap(b), rel_tol=0.1)
               for _, (b,), _ in cases)  # fmt: skip
    for _, (b,), bits in cases:
        assert bfs._bits(bfs._gap(b)) == bits == math.floor(math.log2(1 + 1 / bfs._gap(b))) + 1
        tied = {r.depth for r in b.frame.history(*bfs.PIXEL).records if r.outcome != "not_covered"}
        assert len(tied) == 1, tied
    assert ex.check(NAME, sol.broken_frame_3_steps).passed


def test_this_walls_depth_only_is_named_where_it_gives_every_answer_only():
    """G4: the six-decimal gap's 20 equalled the fewest bits at one redraw's wall alone; now
    that slip is named only where it gives every answer (the R377 variant), and a six-decimal
    gap is named as such, with the gap its number answers."""
    here = R377["frame 3 bits, at this wall's depth only"]
    assert here[2] in ex.check(NAME, here[1]).failures[0].explanation
    _, fn, _, _ = R388["frame 3 bits, depths rounded to six decimals"]
    report = ex.check(NAME, fn)
    assert all("by where the wall lies" not in f.explanation for f in report.failures), report
    first = report.failures[0].explanation
    assert re.search(r"20 bits is the answer for a gap of 1e-06, .*\(0\.\d{6} − 0\.\d{6}\)", first)
    assert "read these depths unrounded" in first


def test_a_constant_is_this_walls_depth_only_where_it_is_that_on_two_cases():
    heres = [bfs._here(b) for _, (b,), _ in bfs.BROKEN_FRAME_3_STEPS.cases()]
    for x in set(heres):
        words = bfs._constant(x)
        assert ("by where the wall lies" in words) == (heres.count(x) >= 2), (x, heres, words)


def test_the_rule_says_more_than_a_step_and_the_gaps_a_number_answers_after_the_hints():
    """G6: rounding half to even ties two depths exactly a step apart; G4: the words say which
    gaps the student's number answers, once the hints are spent (never before: the range
    tells the rule)."""
    assert "more than a whole step" in bfs.RULE and "or more" not in bfs.RULE
    assert round(2.5) == round(1.5) == 2  # exactly a step apart, both stored as 2
    tries.forget_hints(NAME)
    first = str(ex.check(NAME, lambda b: sol.broken_frame_3_steps(b) + 3))
    assert "would be the answer" not in first and "more than a whole step" not in first
    second = str(ex.check(NAME, lambda b: sol.broken_frame_3_steps(b) + 4))
    assert "24 bits would be the answer for a gap above 5.96e-08 up to 1.192e-07" in second
    assert "this pane's gap is 1e-06" in second
    tries.forget_hints(NAME)


def test_the_question_keeps_the_gap_and_moves_the_pair_and_asks_for_all_digits():
    """G5: "drawn where frame 3 draws it ... wherever the wall lies" moved the wall alone."""
    note = " ".join(ex.frame_note(3, ex.check("broken_frame_3", sol.diagnosis(3))).split())
    assert "the same distance in front of the wall as frame 3 draws it" in note, note
    assert "at whatever depth the two are drawn" in note and "wherever the wall lies" not in note
    assert "not the six the histories print" in note
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
             for c in json.loads(NOTEBOOK.read_text())["cells"]}  # fmt: skip
    task = " ".join(cells["frame_3_steps_task"].split())
    assert "redrawn four times" in task and "with all their digits" in task, task


def test_the_figure_draws_the_whole_step_only_once_the_words_give_it():
    """G8: the dashed whole step was drawn from the first failure; the cross's words lay on it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def dashed(report):
        fig, ax = plt.subplots()
        try:
            report.plot(ax)
            fig.canvas.draw()
            lines = [ln for ln in ax.lines if ln.get_linestyle() == "--"]
            texts = [t for t in ax.texts if "bits: the gap is" in t.get_text()]
            if lines and texts:  # the words clear of the line
                y = ax.transData.transform((0, 1.0))[1]
                box = texts[0].get_window_extent()
                assert not box.y0 < y < box.y1, (box, y)
            ylo, yhi = ax.get_ylim()
            assert yhi / ylo <= 1e3, (ylo, yhi)
            return bool(lines)
        finally:
            plt.close(fig)

    tries.forget_hints(NAME)
    assert not dashed(ex.check(NAME, lambda b: sol.broken_frame_3_steps(b) + 3))
    assert dashed(ex.check(NAME, lambda b: sol.broken_frame_3_steps(b) - 4))
    tries.forget_hints(NAME)
    assert dashed(ex.check(NAME, sol.broken_frame_3_steps))


def test_a_whole_number_under_a_depth_cause_is_quoted_without_a_point_zero():
    """G9: ("depth function", (24, 28), 3) was quoted "with 3.0"."""
    report = ex.check("broken_frame_1", lambda b: ("depth function", (24, 28), 3))
    assert "with 3:" in report.failures[0].explanation, str(report)
    assert "3.0" not in str(report)
