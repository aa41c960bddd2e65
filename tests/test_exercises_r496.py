"""r496: exercise 4 read again after 4.3's redesign (r489). The words of 4.3 name the equations
a student used (every set of three or four of the five, and the one left out), a raised
LinAlgError lists every set open on the triangle, NaN is blamed on the screen only where every
vertex is NaN; colours of other vertices, one colour for all, lesson 04's weights not
renormalised, 8-bit truncation and NaN where a weight is 0 are named; 4.1's fragments sorted by
depth are named. Every variant of this read is in tests/student_variants.py (R496), replayed by
test_checker_corpus; here each runs once in one test (cost: about 0.4 s a check)."""

import numpy as np
from student_variants import DIFFERENT, R496

from teachraster import exercises as ex
from teachraster.exercises import clip_colour as cc


def test_every_set_of_three_or_four_equations_is_tried_largest_first():
    assert len(cc._SUBSETS) == 15
    sizes = [len(c) + o for c, o in cc._SUBSETS]
    assert sizes == sorted(sizes, reverse=True)


def test_the_largest_open_sets_are_said_and_no_part_of_them():
    v = np.array([[1.0, 0, -2, 1], [0, 1, 0.5, 1], [1, 1, -1.5, 2]])  # v3 = v1 + v2
    assert cc._largest_open(v) == [((0, 1, 2, 3), False)]
    words = cc._raised((v, None, None), "LinAlgError: Singular matrix")
    assert "x, y, z, w (without Σλ = 1) (or any part of one of them)" in words


def test_r496_variants_are_named_and_correct_ones_pass():
    for label, (name, fn, words, kind) in R496.items():
        first = ex.check(name, fn).failures[0]
        assert words in first.explanation and first.kind == kind, (label, first.explanation)
        assert "float32" not in first.explanation, (label, first.explanation)
    for label, (name, fn) in DIFFERENT.items():
        if label.startswith(("clipped colours unsigned", "clipped colours normal", "clipped "
                             "colours homogeneous", "clipped colours gram")):  # fmt: skip
            assert ex.check(name, fn).passed, label
