"""r394, exercise 10 (robust_fill): a cause is said only where it holds. A zero-area triangle
covered is told its zero area, not "covers every pixel"; "you read origin as (x, y)" and
"E > 0" are said only where they give every answer; the "must flip the sign" advice only where
the answer is that of a function that never orients; a (width, height) early return is told
its shape, not a transpose."""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R386, R394

from teachraster import exercises as ex
from teachraster.exercises import hard_case_fill as hcf


@pytest.mark.parametrize("label", list(R394))
def test_each_variant_gets_its_words_and_never_a_cause_it_lacks(label):
    fn, words, kind, never = R394[label]
    report = ex.check("robust_fill", fn)
    assert not report.passed
    assert words in report.failures[0].explanation, str(report)
    assert report.failures[0].kind == kind, str(report)
    assert all(never not in f.explanation for f in report.failures), str(report)


def test_the_flip_advice_is_said_to_a_function_that_never_orients():
    def unoriented(xy, width, height, origin=(0, 0)):
        v = np.rint(np.asarray(xy, dtype=float) * 256) / 256
        rows = origin[0] + np.arange(height)[:, None] + 0.5
        cols = origin[1] + np.arange(width)[None, :] + 0.5
        inside = np.ones((height, width), dtype=bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = (b[0] - a[0]) * (rows - a[1]) - (b[1] - a[1]) * (cols - a[0])
            own = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            inside &= (e >= 0) if own else (e > 0)
        return inside

    report = ex.check("robust_fill", unoriented)
    assert not report.passed
    assert any(hcf.FLIP_ADVICE in f.explanation for f in report.failures), str(report)


def test_a_width_height_early_return_is_told_its_shape_not_a_transpose():
    report = ex.check("robust_fill", R386["fill returning (width, height) for zero area"][0])
    text = report.failures[0].explanation
    assert "your image has shape (8, 4), (width, height) (an early return" in text, text
    assert "no .T" not in text and "transposed" not in text, text
