"""Exercise 10.3 (r457 T1, r470): ``breaking_case(repair)``, a case for each repair of the naive
fill. The teacher's cases pass; each wrong answer a student gives (the same case for every
repair, a case of another repair, one the naive fill gets right, one that needs a second
repair, a catalogue case copied, one outside the bounds, a window that misses the pixel,
invalid input) fails and is named by its kind in its first words."""

from __future__ import annotations

import time

import numpy as np
import pytest
from reasoning_solutions import breaking_case
from student_variants import DIFFERENT, R470, R478
from variant_checks import assert_first_named, assert_passes

from teachraster import Triangle, rasterize
from teachraster import exercises as ex
from teachraster.exercises import breaking_case as bc
from teachraster.exercises.hard_case_fill import expected_fill, fixed_cases


@pytest.mark.parametrize("label", list(R470))
def test_each_wrong_case_fails_and_is_named_in_its_first_words(label):
    name, fn, words, kind = R470[label]
    assert_first_named(name, fn, words, kind)


@pytest.mark.parametrize("label", list(R478))
def test_each_r478_wrong_case_fails_and_is_named_in_its_first_words(label):
    name, fn, words, kind = R478[label]
    assert_first_named(name, fn, words, kind)


@pytest.mark.parametrize("label", [k for k in DIFFERENT if k.endswith(("(r470)", "(r478)"))])
def test_other_right_cases_pass(label):
    assert_passes(*DIFFERENT[label])


def test_the_teachers_cases_pass_in_well_under_a_second():
    start = time.process_time()
    assert_passes("breaking_case", breaking_case)
    assert time.process_time() - start < 1.0


def test_every_repair_done_is_the_gpus_fill_on_10_2s_cases():
    """One place for each rule: the fill with every repair is rasterize on 10.2's cases."""
    for label, args, expected in fixed_cases():
        assert np.array_equal(bc.repaired_fill(*args, bc.REPAIRS), expected), label


def test_each_teachers_case_needs_its_repair_and_no_other():
    """("orient after snapping" presupposes snapping: its case needs "snap" too.)"""
    for repair in bc.REPAIRS:
        needs = {repair, "snap"} if repair == "orient after snapping" else {repair}
        xy, width, height, origin = breaking_case(repair)
        case = (np.asarray(xy, float), width, height, origin)
        ref = expected_fill(*case)
        for other in bc.REPAIRS:
            without = [r for r in bc.REPAIRS if r != other]
            assert np.array_equal(bc.repaired_fill(*case, without), ref) == (other not in needs)


def test_no_catalogue_case_meets_the_bounds_of_the_repair_it_breaks():
    """The bounds stop copying: a case of 10.2's check that is a breaking case of a repair is
    outside that repair's bounds, or is named a catalogue case."""
    for label, (xy, width, height, origin), _ in fixed_cases():
        case = (np.asarray(xy, float), width, height, origin)
        assert bc.catalogue_label(xy) is not None, label
        for repair in bc.REPAIRS:
            found = bc.verdict(repair, case)
            assert found is not None, (label, repair)


def _search_tie_case(judge):
    """r478 W1: a breaking_case that searches for its tie case at run time with ``judge``."""

    def naive(xy, tie):
        v = np.asarray(xy, float)
        v = v if bc.edge_function(*v) > 0 else v[[0, 2, 1]]
        p = np.stack(np.meshgrid(np.arange(6) + 0.5, np.arange(6) + 0.5), axis=-1)
        out = np.ones((6, 6), bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = bc.edge_function(a, b, p)
            out &= (e > 0) | ((e == 0) & (not tie or bool(bc.is_top_left(a, b))))
        return out

    def breaking_case(repair):
        if repair != "tie rule":
            return breaking_case_teacher(repair)
        rng = np.random.default_rng(3)
        for _ in range(500):
            xy = np.round(rng.uniform(0.5, 4, (3, 2)) * 2) / 2
            if abs(bc.edge_function(*xy)) < 1:
                continue
            e = judge(xy)
            if (naive(xy, False) != e).any() and (naive(xy, True) == e).all():
                return xy, 6, 6, (0, 0)
        return breaking_case_teacher(repair)

    return breaking_case


breaking_case_teacher = breaking_case


@pytest.mark.parametrize("judge, words", [
    (lambda xy: rasterize(Triangle(xy), 6, 6).coverage, "calls teachraster's rasterize: a fill of "
     "the package's, which the check judges your cases by: a search"),
    (lambda xy: bc.repaired_fill(xy, 6, 6, (0, 0), bc.REPAIRS), "the checker's own code"),
])  # fmt: skip
def test_a_search_at_run_time_is_not_counted(judge, words):
    """r478 W1: a search with the package's fill (or the checker's own) passes every case and
    is not counted."""
    report = ex.check("breaking_case", _search_tie_case(judge))
    assert not report.passed and words in str(report), str(report)


def test_catalogue_cases_turned_or_mirrored_are_named_and_the_teachers_are_not():
    """r478 W2: every case of 10.2's check under the grid's 8 symmetries, moved by whole
    pixels, is a catalogue case; the teacher's cases are none."""
    for label, (xy, *_), _ in fixed_cases():
        xy = np.asarray(xy, float)
        for words, m in bc.SYMMETRIES:
            moved = xy @ np.array(m, float).T + [3, -7]
            assert bc.catalogue_label(moved[[2, 0, 1]]) is not None, (label, words)
    for repair in bc.REPAIRS:
        assert bc.catalogue_label(breaking_case(repair)[0]) is None, repair
