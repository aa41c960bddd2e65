"""Review r455 (exercise 3 read again): three classes of wrong 3.2 answers passed (W1
np.divide(..., where=) without out=, whose skipped entries held zeros in most runs; W2 a mask
|λ| > ε with ε ≤ 1e-15; W3 λ times the reference w before the divide, whose products are
subnormal at w = 1e-320) and 3.1's lstsq with the sum row was told "the third equation is
missing" (M1). The students are in ``student_variants.R455``; here, each is checked once.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import DIFFERENT, KINDS, R455

from teachraster import exercises as ex
from teachraster.exercises import perspective_weighting as pw


@pytest.mark.parametrize("label", sorted(R455))
def test_each_slip_fails_named_in_its_first_explanation(label):
    name, fn, words, kind = R455[label]
    report = ex.check(name, fn)
    assert not report.passed, f"{label}: {report}"
    first = report.failures[0]
    assert words in first.explanation, f"{label}: {first.explanation}"
    assert first.kind == kind == KINDS[label], (label, first.kind)


@pytest.mark.parametrize(
    "label",
    ["perspective weights scaled by powers of 2 from np.frexp",
     "perspective weights by np.divide(out=zeros, where=)"],
)  # fmt: skip
def test_the_new_cases_fail_no_correct_solution(label):
    name, fn = DIFFERENT[label]
    assert ex.check(name, fn).passed


@pytest.mark.filterwarnings("ignore:'where' used without 'out'")
def test_freed_memory_reads_nan_after_the_poison():
    """W1: the buffer np.divide(..., where=) allocates without out= is one numpy freed."""
    with np.errstate(all="ignore"):
        pw.poison_freed_memory()
        q = np.divide(np.ones(3), np.ones(3), where=np.array([True, False, False]))
    assert q[0] == 1.0 and np.isnan(q[1:]).all()


def test_the_new_extreme_cases_are_exact_for_the_right_order():
    """W2, W3: λ·(w_ref / w) gives μ to 1e-12 on both; (λ·w_ref) / w does not on the first."""
    cases = {tuple(w): (lam, mu) for _, (lam, w), mu in pw.weights_cases()}
    lam, mu = cases[(1e-320, 2e-320, 4e-320)]
    assert np.allclose(mu, [0.2 / 0.475, 0.15 / 0.475, 0.125 / 0.475], rtol=0, atol=1e-12)
    lam, mu = cases[(1.0, 1e300, 2e300)]
    assert lam[0] == 1e-300 and np.allclose(mu, [4 / 7, 2 / 7, 1 / 7], rtol=0, atol=1e-12)
