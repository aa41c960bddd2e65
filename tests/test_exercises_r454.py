"""r454 (exercise 2.1 ``span``, a verifying reader after r439's fixes): an epsilon of any size
fails (a far near tie 2^-47 px off a centre, the closest an exact crossing comes in the range)
and is named an epsilon, never a precision whose answer it shares on one sliver (P1, M1-M4); a
float64 side test in any form is said so (H1-H3); a crossing rounded to the nearest 1/256 px,
int32 vertices, a 1/128 grid and rows clipped at 0 are named (M5, M6, H5, H6); rows ⌊y + ½⌋
read "no top edge" with the row range beside it (H4). Correct-but-different solutions pass."""

import math
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from student_variants import KINDS, R454, WRONG, _r439  # noqa: E402
from variant_checks import assert_first_named, assert_passes  # noqa: E402

from teachraster.exercises import span_variants, spans  # noqa: E402


@pytest.mark.parametrize("label", sorted(R454))
def test_each_r454_student_is_named_by_its_slip(label):
    name, fn, words = WRONG[label]
    assert_first_named(name, fn, words, KINDS[label])


def test_the_hair_case_is_the_closest_an_exact_crossing_comes():
    """On the 1/256-px grid, |c| < 2^30 px, under 1000 columns; x_l lies 1/(256·d) px right of a
    centre (d the long edge's height in 1/256 px, below 2^39), where no float64 order moves it."""
    ((label, points, row),) = span_variants.FAR_HAIR
    xy = np.array(points)
    assert np.abs(xy).max() < span_variants.EXACT_BELOW
    assert all((Fraction(c) * 256).denominator == 1 for c in xy.ravel())
    assert 0 < len(spans.exact_columns(xy, row)) < 1000
    x_l = spans.crossings(xy, Fraction(2 * row + 1, 2))[0]
    d = 256 * (Fraction(xy[1, 1]) - Fraction(xy[0, 1]))
    assert x_l - (math.floor(x_l) + Fraction(1, 2)) == 1 / (256 * d) and d < 2**39
    for order in span_variants.ORDERS:  # float64 lands off the centre, on the right side
        x = span_variants.float_crossing(tuple(xy[0]), tuple(xy[1]), row + 0.5, order)
        assert math.ceil(x - 0.5) == math.ceil(x_l - Fraction(1, 2)), order


@pytest.mark.parametrize(
    "end",
    [
        # an epsilon below 2^-47 px moves no centre in the range
        "math.ceil(left - Fraction(1, 2) - Fraction(1, 10**15)), "
        "math.ceil(right - Fraction(1, 2) - Fraction(1, 10**15))",
        # the crossing rounded *up* to the grid, then to a column: nested ceilings are exact
        "-((Fraction(1, 2) - Fraction(math.ceil(256 * left), 256)) // 1), "
        "-((Fraction(1, 2) - Fraction(math.ceil(256 * right), 256)) // 1)",
    ],
)
def test_correct_but_different_ends_pass(end):
    assert_passes("span", _r439(END=end))


def test_the_half_planes_without_sort_or_split_pass():
    """Three edges, each a floor or ceiling bound in integers with the top-left bias."""

    def span(xy, row):
        p = [(round(256 * float(x)), round(256 * float(y))) for x, y in np.asarray(xy).tolist()]
        (ax, ay), (bx, by), (cx, cy) = p
        if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0:
            p = [p[0], p[2], p[1]]
        y, lo, hi = 256 * row + 128, -(1 << 80), 1 << 80
        for k in range(3):
            (ax, ay), (bx, by) = p[k], p[(k + 1) % 3]
            dx, dy = bx - ax, by - ay
            bias = 0 if dy < 0 or (dy == 0 and dx > 0) else 1
            e = dx * (y - ay)  # E(X) = e - dy·(X - ax) >= bias, X = 256·col + 128
            if dy == 0:
                if e < bias:
                    return 0, 0
            elif dy > 0:
                hi = min(hi, (ax + (e - bias) // dy - 128) // 256 + 1)
            else:
                lo = max(lo, -((128 - ax + (e - bias) // -dy) // 256))
        return (lo, hi) if hi > lo else (0, 0)

    assert_passes("span", span)


def test_a_row_loop_from_the_top_vertex_is_asked_about_its_loop():
    """H7: lesson 01's stepped edges in Fractions, walked from the top vertex down to the row,
    run out of time far out: the words ask about a loop over rows or columns, not "a Python
    call per pixel"."""

    def span(xy, row):
        p = sorted(((Fraction(float(x)), Fraction(float(y))) for x, y in np.asarray(xy).tolist()),
                   key=lambda q: q[1])  # fmt: skip
        top = math.ceil(p[0][1] - Fraction(1, 2))
        for _i in range(top, row):  # stepping, one row at a time
            pass
        return _r439()(xy, row) if row >= top else (0, 0)

    report = assert_first_named("span", span, "a loop over the rows from a vertex", "timeout")
    assert "a Python call per pixel" not in str(report)


@pytest.mark.parametrize(("prec", "lower"), [(34, False), (33, True), (34, True)])
def test_decimal_at_33_or_34_digits_fails_and_is_named_by_its_digits(prec, lower):
    """r439 P4: a far tie whose product needs 35 digits (FAR_DIGITS_35); named by decimal's
    digits, never "28" or "float64"."""
    from student_variants import _R439_DEC, _R439_LOWER

    parts = {**_R439_DEC, **({"CROSS": _R439_LOWER} if lower else {})}
    report = assert_first_named(
        "span", _r439(prec=prec, **parts), "decimal", KINDS_DECIMAL[(prec, lower)]
    )
    assert "28" not in report.failures[0].kind and "float64" not in report.failures[0].explanation


KINDS_DECIMAL = {
    (34, False): "decimal at 34 digits",
    (33, True): "decimal at 33 digits, lower end",
    (34, True): "decimal at 34 digits, lower end",
}
