"""r413 (exercise 2.1 ``span``): a side test in float64 (lesson 01's ``u4 < MID[0]``) fails
far out and is named (P8); a crossing floored to the 1/256 grid and exact code with two tie
slips are not told "float64" (M10); int64 overflow is named (H7)."""

import json
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent))

from student_variants import (  # noqa: E402
    KINDS,
    R413,
    R413_H6,
    R413_H8_H9,
    R413_TWO_TIE_SLIPS,
    WRONG,
    _span_r413,
)

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


LESSON_01 = Path(__file__).parents[1] / "notebooks" / "01_span_tables.ipynb"
EXERCISE_02 = Path(__file__).parents[1] / "notebooks" / "exercises" / "02_span_split.ipynb"


def _exact_span_from_the_lessons_pieces(xy, row):
    """r413 c4: lesson 01 §5's integer DDA for one row, its pieces now the package's."""
    from teachraster.study.exact_spans import dda_start, first_centre_at_or_after

    s = 256
    pts = sorted(((round(s * float(x)), round(s * float(y))) for x, y in xy),
                 key=lambda p: (p[1], p[0]))  # fmt: skip
    top, mid, bot = pts
    v = s * row + s // 2
    d = bot[1] - top[1]
    u4 = top[0] * d + (mid[1] - top[1]) * (bot[0] - top[0])  # times d
    if not top[1] <= v < bot[1] or u4 == mid[0] * d:
        return 0, 0
    long = dda_start(top, bot, v, s)
    short = dda_start(top, mid, v, s) if v < mid[1] else dda_start(mid, bot, v, s)
    left, right = (long, short) if u4 < mid[0] * d else (short, long)
    return first_centre_at_or_after(left, s), first_centre_at_or_after(right, s)


def test_t1_the_lessons_exact_loop_is_the_packages_and_not_counted():
    """T1: lesson 01 §5 printed the exact integer span fill (r413 c4 passed as the student's
    own). It lives in teachraster.study.exact_spans now, imported by the lesson and not
    printed; a wrapper of its pieces is right on every case and named, not counted."""
    report = ex.check("span", _exact_span_from_the_lessons_pieces)
    assert not report.failures and not report.passed, str(report)
    assert "teachraster's dda_start" in report.package and "does not count" in report.package
    with pytest.raises(AssertionError, match="not counted"):
        report.assert_passed()
    cells = json.loads(LESSON_01.read_text())["cells"]
    code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    for printed in ("def dda_start(", "def dda_step(", "def span_fill_int_dda(",
                    "def first_centre_at_or_after(", "def fixed_start(", "-(-(", "divmod("):  # fmt: skip
        assert printed not in code, printed
    assert "from teachraster.study.exact_spans import" in code
    text = " ".join(
        " ".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown").split()
    )
    # the idea kept, in the notes' notation, and the pointer to the exercise
    assert "= q + \\frac{r}{d}, \\qquad 0 \\le r < d" in text and "**carry** one into $q$" in text
    assert "exercise 2 asks you to write the exact span of one raster line yourself" in text
    task = " ".join("".join(json.loads(EXERCISE_02.read_text())["cells"][2]["source"]).split())
    for said in ("§5 keeps that crossing in integers of 1/256 px as q + r/d",
                 "`teachraster.study.exact_spans`", "|x|, |y| < 2^30 px",
                 "A centre exactly on an edge is covered when that edge is a left edge"):  # fmt: skip
        assert said in task, said


@pytest.mark.parametrize("label", sorted(R413_H8_H9) + sorted(R413_H6))
def test_h8_h9_vertices_moved_ceil_slips_and_dropped_rows_are_named(label):
    """H8: vertices rounded (round(), ⌊c + ½⌋) or snapped to 1/16 px are named with the
    coordinate they moved; H6: a centre line in other units (2·row + ½) is named; H9: (n + d − 1)//d with d < 0, and an empty span returned on a row
    inside the triangle, are named, not told the rule alone."""
    name, fn, words, kind = {**R413_H8_H9, **R413_H6}[label]
    report = ex.check(name, fn)
    assert not report.passed and report.failures[0].kind == kind, str(report)
    assert words in report.failures[0].explanation, str(report)
    assert "float64" not in str(report), str(report)
    if kind != "empty inside":  # (its top-edge row, dropped too, keeps the rule's words)
        assert {f.kind for f in report.failures} == {kind}, str(report)


def test_h9_a_first_one_right_on_a_tie_says_the_left_edge_owns_it():
    """H9 (w36's first line): "your first is one column too far right" on a crossing exactly
    on a centre says whose centre it is."""
    report = ex.check("span", _span_r413(R413_TWO_TIE_SLIPS))
    first = report.failures[0].explanation
    assert "your first is one column too far right" in first, first
    assert "x_l lies exactly on that centre, and a left edge owns the centres on it" in first
