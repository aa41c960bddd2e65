"""r413 (exercise 2.1 ``span``): a side test in float64 (lesson 01's ``u4 < MID[0]``) fails
far out and is named (P8); a crossing floored to the 1/256 grid and exact code with two tie
slips are not told "float64" (M10); int64 overflow is named (H7)."""

import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from student_variants import KINDS, R413, R413_TWO_TIE_SLIPS, WRONG, _span_r413  # noqa: E402

from teachraster import exercises as ex  # noqa: E402
from teachraster.exercises import span_variants, spans  # noqa: E402


@pytest.mark.parametrize("label", sorted(R413))
def test_each_r413_student_is_named_by_its_slip(label):
    name, fn, words = WRONG[label]
    report = ex.check(name, fn)
    assert not report.passed
    assert report.failures[0].kind == KINDS[label], str(report)
    assert words in report.failures[0].explanation, str(report)
    # the int64 answer 2.7·10^6 columns wide is refused as a span ("type"), and said so
    assert {f.kind for f in report.failures} - {"type"} == {KINDS[label]}, str(report)
    if KINDS[label] != "side in float64":
        assert "float64" not in str(report), str(report)


def test_far_sides_put_the_middle_vertex_a_hair_off_the_long_edge_on_either_side():
    """P8: within the stated range, the middle vertex under 10^-10 px from the long edge, once
    right of it and once left, and a centre exactly on the left edge of the asked row."""
    sides = []
    for _, points, row in span_variants.FAR_SIDES:
        xy = np.array(points)
        assert span_variants.FLOAT64_EXACT_BELOW < np.abs(xy).max() < span_variants.EXACT_BELOW
        (x1, y1), (x2, y2), (x3, y3) = sorted(
            ((Fraction(x), Fraction(y)) for x, y in points), key=lambda p: p[1]
        )
        gap = x2 - (x1 + (y2 - y1) * (x3 - x1) / (y3 - y1))
        assert 0 < abs(gap) < 1e-10
        sides.append(gap > 0)
        xl, _ = spans.crossings(xy, Fraction(2 * row + 1, 2))
        assert (xl - Fraction(1, 2)).denominator == 1
        assert spans.exact_columns(xy, row) == {int(xl - Fraction(1, 2))}
    assert sorted(sides) == [False, True]


def test_exact_code_with_two_tie_slips_is_never_told_float():
    """M10: w36 (a left edge owns nothing, open rows) fails near ties where every float order
    is exact, so its far ties are no sign of float64 or of a float order."""
    report = ex.check("span", _span_r413(R413_TWO_TIE_SLIPS))
    assert not report.passed
    kinds = {f.kind for f in report.failures}
    assert not kinds & {"float64 crossing", "divide first", "slope first"}, kinds
    assert "float64" not in str(report) and "divides first" not in str(report)
