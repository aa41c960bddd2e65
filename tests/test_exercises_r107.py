"""Review r107 (exercises 03, 08, 12 played as students): a tie rule told it tested pixel
corners, the capstone's first try given the words the exercises hold back, wrong answers that
passed (weights scaled by w1, float32 edge functions), NaN told "placeholder".

A first try is checked with the staged hints on (as in a fresh kernel), the named mistakes
with the hints spent (as after two different failing answers).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_exercises_r85 import _words

from teachraster import exercises as ex


@pytest.mark.parametrize("name", ["barycentric", "perspective_weights"])
def test_an_array_nan_on_every_case_is_told_nan_not_placeholder(name):
    """r107 N3-2: ``np.full(3, np.nan)`` was told "a placeholder left in", against
    CONVENTIONS.md ("your answer holds NaN (a 0/0, or a NaN input passed on?)")."""
    report = ex.check(name, lambda *a: np.full(3, np.nan))
    words = _words(report)
    assert "your answer holds NaN (a 0/0, or a NaN input passed on?)" in words, words
    assert "placeholder" not in words, words


def _weights_by_w1(lam, w):
    """λ_i · (w_1 / w_i), normalised: right while w_1 is the smallest w (r107 N3-1)."""
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    with np.errstate(all="ignore"):
        q = lam * (w[0] / w)
        return q / q.sum()


def test_weights_scaled_by_the_first_w_fail_named_here_and_in_the_capstone():
    """r107 N3-1, N12-2: w scaled by w1 passed all 67 cases and textured_floor (every
    extreme triple had its smallest w first); w/max(w) products were told "1/w overflows"
    (N3-3), though they take no 1/w."""
    from test_capstone import _mine

    report = ex.check("perspective_weights", _weights_by_w1)
    assert not report.passed
    assert all(f.kind == "scaled by w1" for f in report.failures), str(report)
    assert "w = (1e+300, 1, 1e-310)" in report.failures[0].case, str(report)

    def products(lam, w):
        lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float) / max(w)
        q = np.array([lam[0] * w[1] * w[2], lam[1] * w[0] * w[2], lam[2] * w[0] * w[1]])
        return q / q.sum()

    words = _words(ex.check("perspective_weights", products))
    assert "1/w overflows" not in words and "none of which exceeds 1" in words, words
    cap = ex.capstone("textured_floor", **_mine("textured_floor",
                                                perspective_weights=_weights_by_w1))  # fmt: skip
    assert not cap.passed and "you scaled the w by w1" in _words(cap), str(cap)


def test_exercise_3_says_how_far_apart_the_w_are():
    """r107 N3-5: "w from equal to 1e300 apart"; the widest triple is 1e-310 to 1e300."""
    from test_exercises_r94 import _markdown

    text = _markdown("03_interpolation")
    assert "1e300 apart" not in text and "1e610 apart, 1e-310 to 1e300" in text
