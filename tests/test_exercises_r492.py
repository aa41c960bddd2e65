"""r492 (a fresh read of exercise 2 after r477): 2.2 told 2.1's edge slips, the offsets read in
the wrong units and a zero-area tolerance by the bare rule (or "rows at the centre line"); both
tasks now name them. The variants themselves run in test_checker_corpus.py (R492); here, each
new kind's answers apart from every other variant's, and the edge slips' answers at the sample."""

from __future__ import annotations

import numpy as np
from student_variants import R471, R477, R492

from teachraster.exercises import sample_spans as ss
from teachraster.exercises import spans


def test_each_new_kind_gives_answers_no_other_variant_does():
    cases = ss.sample_span_cases()
    answers, kinds = {}, {}
    for label, (name, fn, _, kind) in {**R471, **R477, **R492}.items():
        if name != "sample_span" or kind in ("tie lands off", "float32"):
            continue
        answers[label] = [ss.as_sample_span(fn(*args)) for _, args, _ in cases]
        kinds[label] = kind
    for label in R492:
        if label not in answers:
            continue
        mine = answers[label]
        assert any(a.pair != tuple(e and (min(e), max(e) + 1)) for a, (_, _, e) in zip(mine, cases)
                   if e), label  # fmt: skip
        for other, theirs in answers.items():
            if kinds[other] != kinds[label]:
                assert any(a.pair != b.pair for a, b in zip(mine, theirs)), (label, other)


def test_the_edge_slips_at_a_sample_are_two_one_s_on_the_moved_triangle():
    xy = np.array([[0.0, 0.0], [-8.0, 4.0], [0.0, 8.0]])  # the middle vertex left of the long edge
    slips = ss.edge_slips(xy, 5, (0.375, 0.125))  # the line y = 5.125: x_l = -5.75, x_r = 0
    assert sorted(ss.sample_columns(xy, 5, (0.375, 0.125))) == list(range(-6, 0))
    assert slips["long edge left"].pair == (0, -6)
    assert slips["x_l and x_r swapped"].pair == (0, -6)


def test_a_small_area_is_no_zero_area():
    tiny = np.array([[2.5, 2.5], [2.5390625, 2.50390625], [2.51953125, 2.5]])
    assert spans.doubled_area(tiny) != 0
    assert spans.small_area_fits(tiny, frozenset({2}), spans.as_span((0, 0)))
    assert not spans.small_area_fits(tiny, frozenset({2}), spans.as_span((3, 2)))  # swapped
    assert "5/65536 px²" in spans.small_area_words(tiny)
