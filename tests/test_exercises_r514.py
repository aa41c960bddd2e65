"""Review r514 (exercise 5, a verifying reader after r458): 5.4 passed "reverse-Z only under
half the gap" and "unorm24 with 1 % slack" (P1, P2), 5.3 the room rounded to whole steps as one
difference (P3); 5.2b's slope without 1 − n/f was told "a margin" (M1), a margin itself the rule
(r458 w_X6); 5.4's unorm24 as 32 bits and its Δz without (f − n)/f were told only "not what
your set-up resolves" (H)."""

from __future__ import annotations

import pytest
from student_variants import DIFFERENT, R514
from variant_checks import assert_first_named

from teachraster import exercises as ex


@pytest.mark.parametrize("label", sorted(R514))
def test_each_r514_variant_is_named_by_its_cause(label):
    assert_first_named(*R514[label])


@pytest.mark.parametrize("label", sorted(k for k in DIFFERENT if "(r514" in k))
def test_each_r514_right_variant_passes(label):
    name, fn = DIFFERENT[label]
    report = ex.check(name, fn)
    assert report.passed, str(report)
