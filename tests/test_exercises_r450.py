"""Review r450 (exercise 07): M1 7.4's (u, v) taken modulo 1 by hand was told "is the wrap
argument passed on?"; H1, H3, H4, H6-H9 slips told the generic hint (7.1's max(H, W) for both
axes, 7.2's lesson-09 cell with its 8 pasted and 'clamp' as a border of 0, 7.3's smoothstep
weight and λ rounded, 7.4's λ doubled, pyramid reversed and (u, v) at (col + 1, row + 1)):
each first explanation names the slip, with its kind."""

from __future__ import annotations

import pytest
import student_variants as sv

from teachraster import exercises as ex
from teachraster.exercises import tries
from teachraster.exercises.texture_filtering import TRILINEAR_HINT


@pytest.mark.parametrize("label", list(sv.R450))
def test_each_slip_is_named_first(label):
    name, fn, words, kind = sv.R450[label]
    tries.forget_hints(name)
    report = ex.check(name, fn)
    tries.forget_hints()
    assert not report.passed
    first = report.failures[0]
    assert words in first.explanation, first.explanation
    assert first.kind == kind, (first.kind, first.explanation)
    assert "is the wrap argument passed on" not in first.explanation, first.explanation


def test_trilinear_hint_says_linearly():
    """H6: the generic hint's properties must not hold for a smoothstep weight."""
    assert "linearly" in TRILINEAR_HINT


def test_a_one_element_array_is_no_number():
    """S1: np.array([λ]) in 7.1 and a (1, 1) sample in 7.4 passed (shapes must match); a (3, 2)
    answer keeps its own words (`return uv`)."""
    lod = sv._r426(
        "pixel_lod", "_lod = pixel_lod\ndef pixel_lod(*a):\n    return np.array([_lod(*a)])\n"
    )
    said = ex.check("pixel_lod", lod).failures[0].explanation
    assert "an array of shape (1,), not one number" in said, said
    sample = sv._r426("pixel_sample", "_ps = pixel_sample\ndef pixel_sample(*a):\n"
                      "    return np.atleast_2d(_ps(*a))\n")  # fmt: skip
    said = ex.check("pixel_sample", sample).failures[0].explanation
    assert "returned an array of shape (1, 1)" in said, said
    junk = sv._r426("pixel_sample", "def pixel_sample(pyramid, xy, w, uv, row, col, wrap):\n"
                    "    return uv\n")  # fmt: skip
    said = ex.check("pixel_sample", junk).failures[0].explanation
    assert "returns its argument uv unchanged" in said, said
