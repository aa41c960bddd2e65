"""Reader 420 on exercise 1 (covers, fill): tolerances on the edge test passed (W1: up to
7.6e-5 px²; W2: 1e-9 of the area) or were named as a zero-area tolerance or as float32 (M1,
M2); a tie failure printed no vertices (C1); the package's edge_function inside covers passed
with no word (P1). The wrong variants themselves are in student_variants.R420 (run by
test_checker_corpus)."""

from __future__ import annotations

import numpy as np
import pytest
from exercise_solutions import _covers_with, _owns
from student_variants import R420, _covers_tolerant

from teachraster import exercises as ex
from teachraster.core.edges import edge_function as package_edge_function
from teachraster.exercises import coverage as cov
from teachraster.exercises import near_ties as nt
from teachraster.exercises.checks import exercise
from teachraster.exercises.coverage_checks import fixed_near_ties

STEP = 2.0**-16


def _near(case):
    """(E of the near tie in units of 2^-16, the centre) of a near-tie case."""
    xy = case.triangles[0]
    e, _ = cov.centre_values(case, xy)
    small = np.where(e != 0, np.abs(e), np.inf).min(axis=0)
    i, j = np.unravel_index(np.argmin(small), small.shape)
    return small[i, j] / STEP, (j + 0.5, i + 0.5)


@pytest.mark.parametrize("seed", range(8))
def test_near_ties_hold_a_centre_one_grid_step_off_an_edge_and_float32_gets_them_right(seed):
    """W1: every case has a centre at |E| = 1, 2 or 4 · 2^-16 px², off the edge, where the
    rule and a tolerance disagree; float32 arithmetic gives the rule's image (M2)."""
    cases = nt.near_tie_cases(np.random.default_rng(seed), "")
    assert [c.label.startswith(nt.NEAR_TIE) for c in cases] == [True] * 6
    for case in cases:
        steps, _ = _near(case)
        assert steps in (1, 2, 4), case.label
        xy = case.triangles[0]
        want = cov.expected_coverage(case, xy)
        tolerant = _covers_tolerant(edge_tol=1.5 * STEP * steps)
        f32 = _covers_with(_owns, dtype=np.float32)
        got = np.array([[tolerant(xy, (j + 0.5, i + 0.5)) for j in range(12)] for i in range(12)])
        g32 = np.array([[f32(xy, (j + 0.5, i + 0.5)) for j in range(12)] for i in range(12)])
        assert not np.array_equal(got, want), case.label
        assert np.array_equal(g32, want), case.label
    assert abs(cov.area2(cases[-1].triangles[0])) >= nt.LARGE_AREA  # a relative tolerance too


def test_the_fixed_near_ties_are_in_both_checks():
    labels = {c.label for c in fixed_near_ties()}
    for name in ("covers", "fill"):
        cases = {label for label, *_ in exercise(name).cases()}
        assert labels <= cases
        assert sum(label.startswith(f"{nt.NEAR_TIE} drawn") for label in cases) == 3


@pytest.mark.parametrize(
    "label",
    ["covers, edges by abs(E) < 7.6e-5", "covers, edges by abs(E) ≤ 1e-9 · area",
     "covers, edges by abs(E) ≤ 1e-6 · area, in float64"],
)  # fmt: skip
def test_an_edge_tolerance_fails_and_is_never_called_float32_or_a_zero_area_test(label):
    name, fn, words, kind = R420[label]
    report = ex.check(name, fn)
    assert not report.passed
    for f in report.failures:
        assert "float32" not in f.explanation and "zero-area test" not in f.explanation, f
    first = report.failures[0].explanation
    assert "a centre off the edge has |E| ≥ 2^-16 px²" in first, first


def test_a_tie_failure_prints_the_triangles_vertices():
    """C1: the top-right rule's first failure names v1, v2, v3 with their numbers."""
    report = ex.check(
        "covers", _covers_with(lambda a, b: b[1] < a[1] or (b[1] == a[1] and b[0] < a[0]))
    )
    first = report.failures[0].explanation
    assert "v1, v2, v3 = (" in first and "lies exactly on edge" in first, first


def test_the_package_edge_function_inside_covers_is_said_and_counts():
    """P1: it passes (the side and tie tests are the student's) with a note."""
    g = {"edge_function": package_edge_function, "np": np}
    exec(
        "def covers(xy, p):\n"
        "    v1, v2, v3 = xy\n"
        "    if edge_function(v1, v2, v3) < 0:\n"
        "        v2, v3 = v3, v2\n"
        "    if edge_function(v1, v2, v3) == 0:\n"
        "        return False\n"
        "    for a, b in ((v1, v2), (v2, v3), (v3, v1)):\n"
        "        e = edge_function(a, b, p)\n"
        "        tl = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])\n"
        "        if e < 0 or (e == 0 and not tl):\n"
        "            return False\n"
        "    return True\n",
        g,
    )
    report = ex.check("covers", g["covers"])
    assert report.passed and "package's edge_function" in str(report), str(report)
    mine = ex.check("covers", _covers_with(_owns))
    assert mine.passed and "package's edge_function" not in str(mine)


def test_fill_says_a_tie_rule_or_winding_mistake_lies_in_covers():
    """S1: fill on a covers with one winding named the mistake with no word of covers."""
    from exercise_solutions import _fill_from

    report = ex.check("fill", _fill_from(_covers_with(_owns, orient=False), offset=0.5))
    assert "the 1.1 check names it too" in report.failures[0].explanation, str(report)
