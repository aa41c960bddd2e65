"""r441, exercise 10: 10.2's wrong passes (W1 half-down snapping, W2 a tolerance on the tie
test, W3 the package's own fills) fail and are named; 10.1's misnamed and half-named first
explanations (M1 a factor one bit narrow, M2 every type without its sign, H1 largest-values
slips, H2 a float's range or no float) name the mistake."""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R441

from teachraster import exercises as ex
from teachraster.exercises import hard_case_fill as hcf
from teachraster.exercises import tries
from teachraster.study.hardcases import naive_coverage
from teachraster.study.operation_counts import rule_coverage


def _check(name, fn):
    tries.forget_hints(name)
    try:
        return ex.check(name, fn)
    finally:
        tries.forget_hints(name)


@pytest.mark.parametrize("label", list(R441))
def test_each_r441_variant_fails_and_is_named_in_its_first_words(label):
    name, fn, words, kind = R441[label]
    report = _check(name, fn)
    assert not report.passed
    assert {f.kind for f in report.failures} == {kind}, [f.kind for f in report.failures]
    assert words in report.failures[0].explanation, report.failures[0].explanation
    assert "float32" not in str(report), str(report)  # r441 n27: was told "E in float32"


def test_the_new_cases_are_listed_last_and_hold_what_they_claim():
    labels = [label for label, _, _ in hcf._fill_cases()]
    # (r457 lists its far sliver after them)
    assert labels[-3].startswith("half step, odd") and labels[-2].startswith("a centre one step")
    raw = hcf.HALF_ODD * 256
    assert raw[2].tolist() == [641.5, 641.5] and np.rint(raw[2]).tolist() == [642, 642]
    v = hcf.ONE_STEP[[2, 0]]  # the left edge v3 → v1, and centre (4.5, 8.5)
    a, b, p = v[0], v[1], np.array([4.5, 8.5])
    assert (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) == -(2.0**-16)


def _snapped(xy):
    return np.rint(np.asarray(xy, dtype=float) * 256) / 256


@pytest.mark.parametrize(
    "fn",
    [lambda xy, w, h, origin=(0, 0): naive_coverage(_snapped(xy), w, h, rule="top_left",
                                                    origin=tuple(origin)),
     lambda xy, w, h, origin=(0, 0): rule_coverage(_snapped(xy) - [origin[1], origin[0]], w, h,
                                                   "top-left")],
)  # fmt: skip
def test_the_package_fills_pass_but_are_not_counted(fn):
    """W3: lesson 07's naive_coverage and lesson 06's rule_coverage with the top-left rule, on
    snapped vertices, are the answer itself."""
    report = _check("robust_fill", fn)
    assert not report.passed and not report.failures and report.package is not None, str(report)
    # the other rules are the naive fill's tools, free to use (they fail, unflagged)
    loose = _check("robust_fill", lambda xy, w, h, origin=(0, 0): naive_coverage(
        _snapped(xy), w, h, rule="inclusive", origin=tuple(origin)))  # fmt: skip
    assert loose.failures and loose.package is None, str(loose)


def test_lesson_06s_bit_budget_is_not_counted():
    """S1: bit_budget, range_budget's sibling (differences up to extent px), is flagged too."""
    from teachraster.core.fixed_point import bit_budget

    def edge_bits(range_bits, across, sub_bits):
        def pick(n):
            held = {"float32": 25, "int32": 32, "float64": 54, "int64": 64}
            return next((t for t, h in held.items() if h >= n), None)

        counts = (bit_budget(2**range_bits, sub_bits, centre_bit=False).needed,
                  bit_budget(across, sub_bits, centre_bit=False).needed)  # fmt: skip
        return tuple((n, pick(n)) for n in counts)

    report = _check("edge_bits", edge_bits)
    assert not report.passed and report.package is not None, str(report)
