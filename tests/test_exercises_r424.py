"""r424 (exercise 2.1 ``span``): vertices read through ``str()`` and a crossing multiplied first
in np.longdouble fail and are named (P1, P2); decimal at its default 28 digits is told so, not
"float64" (M2); the centre line with its ½ unscaled (M1), a stop + 1 on every row (H1), an
integer ceiling with a negative divisor (H2) and a zero area left untested (H3) are named."""

import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from student_variants import KINDS, R424, WRONG, _span_r413  # noqa: E402

from teachraster import exercises as ex  # noqa: E402
from teachraster.exercises import span_variants, spans  # noqa: E402


@pytest.mark.parametrize("label", sorted(R424))
def test_each_r424_student_is_named_by_its_slip(label):
    name, fn, words = WRONG[label]
    report = ex.check(name, fn)
    assert not report.passed
    first = report.failures[0]
    assert first.kind == KINDS[label], str(report)
    assert words in first.explanation, str(report)
    if KINDS[label] in span_variants.PRECISION_KINDS or KINDS[label] == "no area test":
        assert {f.kind for f in report.failures} == {KINDS[label]}, str(report)
    if KINDS[label] != "longdouble multiply first":
        assert "float64" not in first.explanation, str(report)


def test_far_precise_cases_need_more_than_a_shortest_repr_or_64_bits():
    """P1: a vertex whose shortest repr is not its value; P2: a product over 64 bits. Both ties
    lie exactly on a centre, within the stated range, with a span of about 300 columns."""
    (_, shown, shown_row), (_, wide, wide_row) = span_variants.FAR_PRECISE
    for points, row in ((shown, shown_row), (wide, wide_row)):
        xy = np.array(points)
        assert span_variants.FLOAT64_EXACT_BELOW < np.abs(xy).max() < span_variants.EXACT_BELOW
        assert all((Fraction(c) * 256).denominator == 1 for c in xy.ravel())
        cross = spans.crossings(xy, Fraction(2 * row + 1, 2))
        assert any((x - Fraction(1, 2)).denominator == 1 for x in cross)
        assert 0 < len(spans.exact_columns(xy, row)) < 1000
    assert any(Fraction(repr(float(c))) != Fraction(c) for c in np.ravel(shown))
    v = sorted(((Fraction(x), Fraction(y)) for x, y in wide), key=lambda p: p[1])
    y = Fraction(2 * wide_row + 1, 2)
    n = abs(int(256 * (y - v[0][1]) * 256 * (v[2][0] - v[0][0])))
    assert n.bit_length() - (n & -n).bit_length() + 1 > 64


def test_the_r424_exact_solutions_pass():
    """Fraction of the float itself, decimal at 80 digits of the float itself: right."""
    source = """
def span(xy, row):
    import decimal
    from decimal import Decimal
    with decimal.localcontext() as c:
        c.prec = 80
        P = sorted(((Decimal(float(x)), Decimal(float(y))) for x, y in xy), key=lambda p: p[1])
        (x1, y1), (x2, y2), (x3, y3) = P
        y = row + Decimal("0.5")
        side = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
        if side == 0 or not (y1 <= y < y3):
            return 0, 0
        cross = lambda a, b: b[0] + (y - b[1]) * (a[0] - b[0]) / (a[1] - b[1])
        xl = cross(P[0], P[2])
        xs = cross(P[0], P[1]) if y < y2 else cross(P[1], P[2])
        left, right = (xl, xs) if side > 0 else (xs, xl)
        return math.ceil(left - Decimal("0.5")), math.ceil(right - Decimal("0.5"))
"""
    assert ex.check("span", _span_r413(source)).passed
