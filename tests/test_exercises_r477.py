"""r477 (a fresh read of exercise 2.2, ``sample_span``): an epsilon on the ends passed (no row
had a crossing a hair off a sample), and most wrong answers were told the bare rule or a
neighbouring slip. The hair rows, the half-way row, and each new kind's answers apart from
every other's; the variants themselves run in test_checker_corpus.py (R477)."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
from student_variants import R471, R477

from teachraster import exercises as ex
from teachraster.exercises import sample_spans as ss


def test_hair_rows_lie_a_hair_off_a_sample_within_the_stated_range():
    for label, (xy, row, sample), cols in ss._hair_cases():
        sx, sy = (Fraction(s) for s in sample)
        gaps = [x - sx - round(x - sx) for x in ss.crossings(xy, row + sy)]
        assert min(abs(g) for g in gaps) < Fraction(2, 10**10), label
        assert all(g != 0 for g in gaps) and float(np.abs(xy).max()) < 2e5, label
        assert cols and np.ptp(xy[:, 0]) < 20, label  # narrow: a fill of the box stays cheap


def test_each_new_kind_gives_answers_no_other_variant_does():
    cases = ss.sample_span_cases()
    answers, kinds = {}, {}
    for label, (_, fn, _, kind) in {**R471, **R477}.items():
        if kind in ("tie lands off", "float32"):
            continue
        answers[label] = [ss.as_sample_span(fn(*args)) for _, args, _ in cases]
        kinds[label] = kind
    for label in R477:
        if label not in answers:
            continue
        mine = answers[label]
        assert any(set(a) != set(e) for a, (_, _, e) in zip(mine, cases)), label
        for other, theirs in answers.items():
            if kinds[other] != kinds[label]:  # (two ways to one mistake: an epsilon, a snap)
                assert any(set(a) != set(b) for a, b in zip(mine, theirs)), (label, other)


def test_an_epsilon_is_named_with_the_gap_in_the_numbers():
    report = ex.check("sample_span", R477["sample span, an epsilon of 1e-9 on the ends"][1])
    first = report.failures[0]
    assert first.kind == "epsilon" and "+ 1.6e-10 to x_r" in first.explanation, str(report)
