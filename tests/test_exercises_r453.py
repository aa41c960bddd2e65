"""r453 (exercise 1): covers asked off the pixel centres (capstone 12's MSAA scene asks it at
sample positions), and slips named: the centre of p's pixel, p − (½, ½), a λ tolerance, float32
vertices, a parenthesised tie test, the third edge reversed (the variants: student_variants.R453,
run by test_checker_corpus); a fill of an object array of bools passes."""

import numpy as np
from student_variants import DIFFERENT, R453

from teachraster import exercises as ex
from teachraster.exercises.coverage_checks import (
    _expected,
    covers_cases,
    fill_cases,
    sample_point_case,
)
from teachraster.exercises.point_slips import SAMPLE_LABEL, pixel_centre_images


def test_the_sample_point_case_asks_off_the_centres_in_covers_only():
    case = sample_point_case()
    assert any(label.startswith(SAMPLE_LABEL) for label, *_ in covers_cases())
    assert not any(label.startswith(SAMPLE_LABEL) for label, *_ in fill_cases())
    assert np.all(np.mod(case.origin, 1) != 0)  # no point asked is a centre
    expected = _expected(case)
    assert (expected.sum(axis=0) <= 1).all()  # a mesh: every point covered at most once
    assert not np.array_equal(pixel_centre_images(case), expected)


def test_each_r453_slip_is_named_first():
    for label, (name, fn, words, kind) in R453.items():
        report = ex.check(name, fn)
        first = report.failures[0]
        assert words in first.explanation and first.kind == kind, (label, first.explanation)
        if "float32" not in words:
            assert "float32" not in first.explanation, first.explanation


def test_an_object_array_of_bools_is_a_fill():
    name, fn = DIFFERENT["fill into an object array of Python bools (r453 WF1)"]
    assert ex.check(name, fn).passed
