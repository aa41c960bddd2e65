"""r386, exercise 10 (robust_fill): E in float32 fails inside the stated range (stepped along a
row, or after shifting to the window), a zero-area image in the wrong shape fails, two causes
that give the same empty image are both said, origin added twice is not "ignored", the common
geometric slips are named from the answer's shape, and the naive fill's printed report is
not called robust_fill nor an answer of the student's."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from student_variants import R386, _fill_r386

from teachraster import exercises as ex
from teachraster.exercises import hard_case_fill as hcf
from teachraster.exercises import hard_case_precision as hcp

NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb"


@pytest.mark.parametrize("label", list(R386))
def test_each_variant_is_named_by_its_own_words_on_every_failure(label):
    fn, words, kind = R386[label]
    report = ex.check("robust_fill", fn)
    assert not report.passed
    assert words in report.failures[0].explanation, report.failures[0].explanation
    assert {f.kind for f in report.failures} == {kind}, str(report)


def test_the_float32_cases_are_inside_the_stated_range_and_break_float32_only():
    """NW28, NW29: each case's triangle is within 1,024 px and 2²⁰ px; the float32 fills fail
    both, float64 and int64 forms pass (r373's tests), and the words quote the E that rounds
    in whole steps of 2⁻¹⁶ px²."""
    for label, (xy, _) in hcp.FLOAT32_CASES.items():
        across = float(np.ptp(xy, axis=0).max())
        assert across <= hcf.MOST_ACROSS and np.abs(xy).max() <= hcf.MOST_FAR
        assert f"{across:.0f} px across" in label
        assert np.array_equal(hcp.snap(xy), xy)  # on the grid: E exact in float64
    report = ex.check("robust_fill", R386["fill with E stepped in float32"][0])
    assert {f.case for f in report.failures} == set(hcp.FLOAT32_CASES), str(report)
    first = report.failures[0].explanation
    assert "· 2⁻¹⁶ = " in first and "about 35 bits" in first, first


def test_an_area_tolerance_above_e_step_fails_and_one_below_passes():
    """NW08: abs(area) < ε fails for ε = 1/256, 1e-3, 1e-4 (snap_flips_winding's E(v1, v2, v3)
    is −5 · 2⁻¹⁶ px²), both causes said; ε = 1e-6, below E's step, changes nothing."""
    for eps in (1 / 256, 1e-3, 1e-4):
        report = ex.check("robust_fill", _fill_r386(tolerance=eps))
        text = report.failures[0].explanation
        assert "-5 · 2⁻¹⁶" in text and "orienting by the unsnapped area" in text, text
        assert "a tolerance on the zero-area test" in text, text
    assert ex.check("robust_fill", _fill_r386(tolerance=1e-6)).passed


def test_the_naive_fills_printed_report_is_not_robust_fills():
    """r386 E1: the setup's show() renames the report and says whose answers count."""
    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    setup = next("".join(c["source"]) for c in cells
                 if c["metadata"]["nbgrader"]["grade_id"] == "setup")  # fmt: skip
    assert 'text.replace("robust_fill", name)' in setup and "tries.HINT_ONLY" in setup
