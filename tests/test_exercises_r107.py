"""Review r107 (exercises 03, 08, 12 played as students): a tie rule told it tested pixel
corners, the capstone's first try given the words the exercises hold back, wrong answers that
passed (weights scaled by w1, float32 edge functions), NaN told "placeholder".

A first try is checked with the staged hints on (as in a fresh kernel), the named mistakes
with the hints spent (as after two different failing answers).
"""

from __future__ import annotations

import numpy as np
import pytest
from test_exercises_r85 import _first_try, _words  # a first try in a fresh kernel

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


def test_weights_scaled_by_the_first_w_fail_3_2_beyond_a_gpus_w_only():
    """r107 N3-1 named w scaled by w1, which overflowed only for w = 1e-310 beside 1e300;
    r126 D3-1 graded only w a GPU meets, where scaling by any w is right; r421 T2 grades such
    w again: it fails 3.2 there alone, named, and passes the floor with a note."""
    from test_capstone import _mine

    report = ex.check("perspective_weights", _weights_by_w1)
    # r429 M1: its NaN is told by the case's sources (a scale w larger than the smallest)
    assert {f.kind for f in report.failures} == {"NaN beyond a GPU's range"}, str(report)
    assert "makes its ratio" in report.failures[0].explanation, str(report)
    cap = ex.capstone("textured_floor", **_mine("textured_floor",
                                                perspective_weights=_weights_by_w1))  # fmt: skip
    assert cap.passed and cap.n_wrong == 0 and "beyond float32's range" in str(cap), str(cap)


def test_exercise_3_says_how_far_apart_the_w_are():
    """r107 N3-5: "w from equal to 1e300 apart"; since r126 D3-1 the widest triple is the
    catalogue's 1e-3 to 1e3."""
    from test_exercises_r94 import _markdown

    text = _markdown("03_interpolation")
    assert "1e300 apart" not in text and "1e610" not in text and "1e6 apart, 1e-3 to 1e3" in text


def _block(owns=None, points=None):
    """classify_block in exact Fractions (tests/exercise_solutions.py), a tie rule ``owns(a,
    b)`` or the ``points(x0, y0, size)`` tested in place of the corner trick."""
    from exercise_solutions import _classify, per_block

    def classify_block(xy, x0, y0, size):
        pts = None if points is None else points(x0, y0, size)
        return _classify(xy, x0, y0, size, corner_trick=pts is None, points=pts, owns=owns)

    return per_block(classify_block)  # one block at a time over the grid


def _bottom_right(a, b):
    return b[1] > a[1] or (b[1] == a[1] and b[0] < a[0])


def _top_right(a, b):
    return b[1] > a[1] or (b[1] == a[1] and b[0] > a[0])


@pytest.mark.parametrize(("owns", "rule"), [(_bottom_right, "bottom-right rule"),
                                            (_top_right, "top-right rule")])  # fmt: skip
def test_a_mirrored_tie_rule_is_named_not_pixel_corners(owns, rule):
    """r107 N8-2: the bottom-right (top-right) rule with the right centres was told "you
    tested the pixels' top-left corners …" as its first explanation."""
    for report in (_first_try("classify_block", _block(owns)),
                   ex.check("classify_block", _block(owns))):  # fmt: skip
        assert all(f.kind == rule for f in report.failures), str(report)
        assert "top-left corners" not in _words(report), str(report)


def _centre_only(x0, y0, size):
    from fractions import Fraction

    return [(x0 + Fraction(size, 2), y0 + Fraction(size, 2))]


@pytest.mark.parametrize("fn", [
    _block(points=_centre_only),  # a one-point test at the block's geometric centre
    # never accepts (r248: np.where over the grid; the scalar form raised on every grid of
    # more than one block, and answered the far float64 ties' one-block grids only)
    lambda *a: (lambda k: np.where(k == "accepted", "partial", k))(np.asarray(_block()(*a))),
])  # fmt: skip
def test_no_line_of_the_summary_names_a_mistake_the_function_does_not_make(fn):
    """r107 N8-2 (a), (b): later lines named "only 2 of the 4 extreme centres", "x0 + size + ½
    lies beyond" (a verdict one mistake shares on one case); now the rule at the case."""
    for report in (_first_try("classify_block", fn), ex.check("classify_block", fn)):
        words = _words(report)
        assert "only 2 of the 4" not in words and "beyond" not in words, words
        assert "size + ½" not in words and "top-left rule includes" not in words, words


def test_float32_edge_functions_fail_named_float32():
    """r107 N8-1: float32 edge functions passed all 45 cases; a centre 1/65536 px² from an
    edge 3000 px out (vertices on the 1/256 grid) rounds onto it in float32."""
    from student_variants import classify_float32

    from teachraster.exercises.tile_blocks import expected_block

    xy = np.array([[3016.83203125, 3010.59375], [2990.40625, 2994.26171875], [6000.0, 0.0]])
    assert (expected_block(xy, 3000, 3000, 1), classify_float32(xy, 3000, 3000, 1)) == (
        "rejected", "accepted")  # fmt: skip
    report = ex.check("classify_block", classify_float32)
    assert not report.passed and report.failures[0].kind == "float32", str(report)
    # r248 F1: the far float64 ties fail float32 too, some named as float64 pixels' rounding
    for f in report.failures:
        assert f.kind == "float32" or f.case.startswith("far out in float64"), (f.case, f.kind)
    assert "x0=3000, y0=3000" in report.failures[0].explanation


def _times_w(lam, w):
    lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
    return lam * w / (lam @ w)


def test_the_capstone_stages_the_exercises_words_as_their_checks_do():
    """r107 N12-1: the capstone gave on the first wrong try the words exercise 3 holds back
    until two different answers have failed (λ_i / w_i, the area ratio); one count, shared
    with the exercise's check."""
    from test_capstone import _mine
    from test_exercises_r94 import _bary, _persp

    from teachraster.exercises import tries

    tries.forget_hints("perspective_weights")
    try:
        cap = ex.capstone("textured_floor", **_mine("textured_floor", perspective_weights=_times_w))
        first = _words(cap)
        assert "λ_i / w_i" not in first and "then turn that around" in first, first
        assert "gives a hint" in first and "a hint only" in first, first
        # a second, different failing answer in the exercise: the full words, here too
        assert not ex.check("perspective_weights", _persp("over w squared")).passed
        again = ex.capstone("textured_floor", **_mine("textured_floor",
                                                      perspective_weights=_times_w))  # fmt: skip
        assert "so the 3-D weights go as λ_i / w_i" in _words(again), _words(again)
        assert "a hint only" not in _words(again)
    finally:
        tries.spend_hints(["perspective_weights"])
    tries.forget_hints("barycentric")
    try:
        rotated = _bary(order=(1, 2, 0))
        words = _words(ex.capstone("single_triangle", **_mine("single_triangle",
                                                              barycentric=rotated)))  # fmt: skip
        assert "sub-triangle" not in words and "λ_i = 1 at v_i" in words, words
    finally:
        tries.spend_hints(["barycentric"])


def test_weights_of_the_wrong_sign_get_no_area_ratio_on_the_first_try():
    """r107 N3-4: every sign flipped was told "λ1 = E(v2, v3, p), …, each over E(v1, v2, v3)"
    on the first try, the area ratio the task leaves to the student."""
    from test_exercises_r94 import _bary

    def flipped(xy, p):
        return -np.asarray(_bary()(xy, p))

    first = _words(_first_try("barycentric", flipped))
    assert "every weight has the wrong sign" in first and "each over E(" not in first, first
    assert "each over E(v1, v2, v3)" in _words(ex.check("barycentric", flipped))


def test_the_docs_say_what_the_hiz_task_states():
    """r107 N8-3: docs/exercises.md said which bound is asked only in a hint; the task now
    says "two cheap lower bounds … the larger" (r94 D8-7)."""
    from pathlib import Path

    docs = (Path(__file__).resolve().parents[1] / "docs" / "exercises.md").read_text("utf-8")
    row = next(line for line in docs.splitlines() if line.startswith("| 8.2 `hiz_rejects"))
    # r126 N8-1: the task now states lesson 10's bound cut to the triangle's bounding box
    assert "tighter bound than lesson 10" in row and "bounding box" in row, row
    assert "which bound the check asks for, the notebook says only in a hint" not in row
