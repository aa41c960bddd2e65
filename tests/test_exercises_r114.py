"""Review r114 (exercises 03, 08, 12 played as students in fresh processes): the checker's own
verdicts passed 8.1 and 8.2, a correct float64 plane failed 8.2's ties and was called float32,
the tile's middle was told "the plane's largest value at the corners", four-corner code was
told "only 2 of the 4", a winding-dependent tie rule was called "top-right", and a culling
classify_block was named on some draws only.
"""

from __future__ import annotations

import numpy as np
import pytest

from teachraster import exercises as ex


def _reference(name):
    if name == "classify_block":
        from teachraster.exercises.tile_blocks import expected_block

        return expected_block
    from teachraster.exercises.hiz_tile import expected_reject

    return expected_reject


@pytest.mark.parametrize("name", ["classify_block", "hiz_rejects"])
@pytest.mark.parametrize("how", ["handed in", "called"])
def test_the_checkers_own_verdict_does_not_count(name, how):
    """r114 D8-1: ``return expected_reject(...)`` passed all 35 cases, ``expected_block`` all
    47, though docs/exercises.md says the checker's own code is not counted."""
    ref = _reference(name)
    fn = ref if how == "handed in" else (lambda *a: _reference(name)(*a))
    report = ex.check(name, fn, budget=120)
    assert not report.passed, str(report)
    assert "the checker's own code" in (report.package or ""), report.package
    assert report.failures == [], report.failures
