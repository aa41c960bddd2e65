"""r395 (exercise 11 read a third time): on 11.3b the nearest-bit words claimed a fraction
below ½ for log₂(1/gap) = 19.9999993 and printed "1 of a step" (N3); the third redraw's gap
sat on a half-step margin's boundary, so that slip passed on float noise (N4); a huge constant
from the histories' tied depths plus ε was "a placeholder" (N2); the first hint was a broken
sentence (N5); the stub's note promised the rule's answer, which 11.3b never draws (N6); every
wall near 0.65-0.7 let the depth divided by the gap pass for nearest-bit (N1). The slips are
corpus cases too (``student_variants.R395``)."""

from __future__ import annotations

import math

import pytest
from student_variants import KINDS, R395

from teachraster import exercises as ex
from teachraster.exercises import broken_frame_steps as bfs
from teachraster.exercises import tries
from teachraster.exercises.report import NOTHING_DRAWN_FOR, NOTHING_DRAWN_YET

NAME = "broken_frame_3_steps"


@pytest.mark.parametrize("label", sorted(R395))
def test_each_slip_fails_a_case_and_is_named_in_the_first_explanation(label):
    name, fn, words, kind = R395[label]
    report = ex.check(name, fn)
    assert not report.passed, label
    first = report.failures[0]
    assert first.kind == kind == KINDS[label], (label, first.kind, first.explanation)
    assert words in first.explanation, (label, first.explanation)


def test_nearest_bit_is_said_only_where_the_fraction_is_below_a_half():
    """N3: every failure of round(log₂(1/gap)) says "below ½" only where it is, with 8 digits."""
    report = ex.check(NAME, lambda b: int(round(math.log2(1 / bfs._gap(b)))))
    assert not report.passed
    frames = {name: b for name, (b,), _ in bfs._cases()}
    for f in report.failures:
        b = frames[f.case]
        log = math.log2(1 / bfs._gap(b))
        assert ("below ½" in f.explanation) == (log % 1 < 0.5), f.explanation
        assert " 1 of a step" not in f.explanation and "20.00," not in f.explanation


def test_the_third_redraw_lies_inside_the_band_not_on_its_midpoint():
    """N4: the third redraw's gap 1/(2²⁰ − 0.75): a half-step margin gives 20, the answer 21."""
    gaps = [bfs._gap(b) for _, (b,), _ in bfs._cases()]
    third = gaps[3]
    assert 2**20 - 1 < 1 / third < 2**20 - 0.5
    assert math.ceil(math.log2(1 / third + 0.5)) == 20 != bfs._bits(third) == 21


def test_a_wall_far_from_the_others_parts_relative_precision_from_the_answer():
    """N1: one wall far from 0.65, where log₂(wall/gap) and log₂(1/gap) differ by over a bit."""
    cases = bfs._cases()
    walls = [bfs._drawn(b)[0] for _, (b,), _ in cases]
    assert min(walls) < 0.3, walls
    assert any(math.ceil(math.log2(bfs._drawn(b)[0] / bfs._gap(b))) != e and
               round(math.log2(1 / bfs._gap(b))) == e for _, (b,), e in cases)  # fmt: skip


def test_the_hint_is_a_sentence_and_the_stub_note_promises_what_is_drawn():
    """N5: "…whatever they are (lesson 05b)? The gap is …"; N6: 11.3b's stub note."""
    tries.forget_hints(NAME)
    first = ex.check(NAME, lambda b: bfs._bits(bfs._gap(b)) + 3).failures[0].explanation
    tries.forget_hints(NAME)
    assert "whatever they are (lesson 05b)? The gap is the wall's depth minus" in first, first
    assert "? (lesson 05b), the gap being" not in first
    note = NOTHING_DRAWN_FOR[NAME]
    assert note != NOTHING_DRAWN_YET and "rule's answer beside yours" not in note
    assert "never the rule's answer" in note
