"""r439 (exercise 2.1 ``span``, a verifying reader after r424's fixes): the classes r424 fixed
case by case stay closed. np.longdouble in every order and as the side test, an int64 side test
and ``decimal`` at 29 to 34 digits fail on far cases built for them (P1-P4) and are named by
their precision, never "float64" (M1); vertices moved by a tidy-up (M2, M3), None for an empty
line (M4), ``-int(-t)``, (first, count), the split tested by the row, the line left in px and
``np.sort(xy, axis=0)`` are named (H1-H5)."""

import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from student_variants import KINDS, R439, WRONG  # noqa: E402

from teachraster import exercises as ex  # noqa: E402
from teachraster.exercises import span_variants, spans  # noqa: E402


@pytest.mark.parametrize("label", sorted(R439))
def test_each_r439_student_is_named_by_its_slip(label):
    name, fn, words = WRONG[label]
    report = ex.check(name, fn)
    assert not report.passed
    first = report.failures[0]
    if KINDS[label].startswith("decimal at"):  # the digits that give the answers: 30 or 34
        assert first.kind.startswith("decimal at") and "28" not in first.kind, str(report)
    else:
        assert first.kind == KINDS[label], str(report)
    assert words in first.explanation, str(report)
    if KINDS[label] in span_variants.PRECISION_KINDS:
        assert {f.kind for f in report.failures} == {first.kind}, str(report)
        assert "float64" not in first.explanation.split("float64 53")[0], str(report)


def test_the_new_far_cases_lie_in_the_stated_range():
    """On the 1/256-px grid, |c| < 2^30 px, spans of a few hundred columns at most (cheap to
    compare and draw); the ties lie exactly on a centre."""
    for label, points, row in span_variants.FAR_DIGITS + span_variants.FAR_WIDE_SIDES:
        xy = np.array(points)
        assert span_variants.FLOAT64_EXACT_BELOW < np.abs(xy).max() < span_variants.EXACT_BELOW
        assert all((Fraction(c) * 256).denominator == 1 for c in xy.ravel()), label
        assert 0 < len(spans.exact_columns(xy, row)) < 1000, label
    for label, points, row in span_variants.FAR_DIGITS:
        cross = spans.crossings(np.array(points), Fraction(2 * row + 1, 2))
        assert any((x - Fraction(1, 2)).denominator == 1 for x in cross), label


def test_the_int64_side_wraps_and_the_longdouble_side_rounds():
    (_, sliver, _), (_, fat, _) = span_variants.FAR_WIDE_SIDES
    fat_v = sorted(((Fraction(x), Fraction(y)) for x, y in fat), key=lambda p: p[1])
    exact, wrapped = span_variants._int64_side(fat_v)
    assert exact.bit_length() > 63 and (exact > 0) != (wrapped > 0)
    v = sorted(((Fraction(x), Fraction(y)) for x, y in sliver), key=lambda p: p[1])
    if np.finfo(np.longdouble).nmant > 52:
        assert span_variants._longdouble_side_errs(v)


@pytest.mark.parametrize("prec", [35, 40])
def test_decimal_with_enough_digits_passes(prec):
    """35 digits hold every product in the range (and the quotient's rounding cannot move a
    column: a crossing off a centre lies at least 2^-47 px from it)."""
    from student_variants import _R439_DEC, _r439

    assert ex.check("span", _r439(prec=prec, **_R439_DEC)).passed


def test_limit_denominator_of_256_or_more_is_exact_and_passes():
    from student_variants import _r439

    fn = _r439(READ="(lambda c: Fraction(c).limit_denominator(1000))")
    assert ex.check("span", fn).passed


def test_a_none_for_a_line_with_covered_centres_is_still_a_missing_return():
    report = ex.check("span", lambda xy, row: None)
    assert "a missing `return`" in report.failures[0].explanation, str(report)
