"""r403 (exercise 2.1 ``span``): a float at the last step fails far out and is named; exact
code with one slip is named by that slip on every row, far ones included, never float64."""

import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from student_variants import KINDS, R403, R403_INT, WRONG  # noqa: E402

from teachraster import exercises as ex  # noqa: E402
from teachraster.exercises import span_variants, spans  # noqa: E402


@pytest.mark.parametrize("label", sorted(R403) + sorted(R403_INT))
def test_each_r403_student_is_named_by_its_slip_on_every_failure(label):
    name, fn, words = WRONG[label]
    report = ex.check(name, fn)
    assert not report.passed
    assert words in str(report), str(report)
    assert {f.kind for f in report.failures} == {KINDS[label]}, str(report)
    assert "computed in float64" not in str(report)


def test_far_near_ties_lie_a_hair_off_a_centre_within_the_stated_range():
    """P7: each row's crossing lies within float64's rounding of a centre, never on it."""
    from fractions import Fraction

    for label, points, row in span_variants.FAR_NEAR_TIES:
        xy = np.array(points)
        assert span_variants.FLOAT64_EXACT_BELOW < np.abs(xy).max() < span_variants.EXACT_BELOW
        xl, xr = spans.crossings(xy, Fraction(2 * row + 1, 2))
        x = xl if label.startswith("x_l") else xr
        centre = Fraction(int(np.floor(float(x)))) + Fraction(1, 2)
        assert x != centre and float(x) == float(centre), label


def test_lesson_01s_bound_is_quoted_as_the_lesson_states_it():
    """C1: lesson 01 §4b proves multiply first exact below 2^18 px (sufficient, not sharp)."""
    assert span_variants.FLOAT64_EXACT_BELOW == 2**18
    assert "below 2^18 px" in span_variants.NO_FLOAT_ORDER
