"""r457, exercise 10 (10.2 robust_fill): the reader's wrong pass (W1, the orientation from an
area in float32) fails and is named; the misnamed (M1 the vertices moved by +origin, M2 lesson
02's integer fill in int32) and half-named (H1 lesson 02's bias on the top and left edges, H2 a
constant all-True image, H3 snapping relative to v1) first explanations name the mistake."""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import DIFFERENT, R457
from variant_checks import assert_first_named, assert_passes

from teachraster.core.snapping import snap
from teachraster.exercises import hard_case_fill as hcf


@pytest.mark.parametrize("label", list(R457))
def test_each_r457_variant_fails_and_is_named_in_its_first_words(label):
    name, fn, words, kind = R457[label]
    report = assert_first_named(name, fn, words, kind)
    assert {f.kind for f in report.failures} == {kind}, [f.kind for f in report.failures]


def test_the_far_sliver_is_listed_last_and_float32_cannot_orient_it():
    label, (xy, width, height, origin), expected = hcf._fill_cases()[-1]
    assert label.startswith("snap_flips_winding at") and expected.any()
    s = snap(np.asarray(xy, float))
    (ax, ay), (bx, by), (cx, cy) = s.astype(np.float32)
    assert (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) == 0  # float32: no area at all
    assert hcf._area(s) == -5 * 2.0**-16  # exact: small, not zero, and flipped by snapping


@pytest.mark.parametrize("label", [k for k in DIFFERENT if "(r457" in k or k.endswith("(r457)")])
def test_r457s_correct_fills_pass(label):
    """T1 (left): lesson 02's integer fill with the origin added passes, as it should."""
    name, fn = DIFFERENT[label]
    assert_passes(name, fn)
