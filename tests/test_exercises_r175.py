"""Reader 175 on exercise 03: cell 0 counted "three" zero-area cases of seven (A1); the
setup_matrix wrapper was told "M maps p − v1 to λ2 and λ3" (A2, M·(p − v1) is not the
weights: Mᵀ(p − v1) is); the 3.1 hint's "largest value at v1" held for one winding (A3); an
ε guard on a zero area was told "your solver" (B4); ``np.linalg.det(M) == 0`` was told to
"test the area exactly" (B5); a time-out asked about "a Python call per pixel" of a
per-point function (B7); an ε added to each w in 3.2 got only the rule; 3.2's float32 bars
said nothing (D11); literal underscores in 3.2's text and negative zeros (D12)."""

from __future__ import annotations

import re

import matplotlib
import numpy as np
import pytest

# the same students and readers as reader 153's and 164's tests (exercise 03 too)
from test_exercises_r126 import _cell
from test_exercises_r153 import _e, _lam, check, kinds
from test_exercises_r164 import by_setup_matrix

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import interpolation as ip

matplotlib.use("Agg")

NOTEBOOK = "03_interpolation.ipynb"
NUMBER_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7,
                "eight": 8, "nine": 9, "ten": 10}  # fmt: skip


# -- A1: cell 0's count of the zero-area cases is the check's ---------------------------------
def test_cell_0_states_no_count_of_zero_area_cases_other_than_the_checks():
    zero = [c for c in ip.barycentric_cases() if isinstance(c[2], str)]
    assert len(zero) == len(ip.DEGENERATE) >= 4  # several: more than the "three" it said
    text = _cell(NOTEBOOK, 0)
    said = re.search(r"and (\w+) of zero area", text)
    assert said is not None, text
    word = said.group(1).lower()
    count = NUMBER_WORDS.get(word, int(word) if word.isdigit() else None)
    assert count in (None, len(zero)), (word, len(zero))


# -- A2: the set-up matrix maps value differences to the gradient: (λ2, λ3) = Mᵀ(p − v1) ---
def test_setup_matrix_note_states_the_packages_convention():
    xy, p = np.array([[1.5, 1.5], [6.5, 1.5], [6.5, 6.5]]), np.array([4.5, 3.5])  # the reader's
    m, lam = tr.setup_matrix(xy), tr.barycentric(xy, p)
    assert np.allclose(m.T @ (p - xy[0]), lam[1:])
    assert not np.allclose(m @ (p - xy[0]), lam[1:])  # M·(p − v1) is not the weights
    f = np.array([0.25, 2.0, -1.0])  # and M maps value differences to the gradient
    plane = tr.attribute_plane(xy, f)
    assert np.allclose(m @ (f[1:] - f[0]), [plane.A, plane.B])
    report = check("barycentric", by_setup_matrix)
    note = report.package
    assert note is not None and "calls teachraster's setup_matrix" in note, note
    assert "(λ2, λ3) = Mᵀ(p − v1)" in note and "to the plane's gradient" in note, note
    assert "M maps p − v1" not in note


# -- B4: an ε that hides a zero area is named as the ε ----------------------------------------
def eps_guard(xy, p):
    v1, v2, v3 = np.asarray(xy, float)
    q = np.asarray(p, float)
    return np.array([_e(v2, v3, q), _e(v3, v1, q), _e(v1, v2, q)]) / (_e(v1, v2, v3) + 1e-9)


def test_an_epsilon_guard_on_a_zero_area_is_told_it_turned_0_over_0_into_0():
    report = check("barycentric", eps_guard)
    zero = [f for f in report.failures if f.case.startswith("zero area")]
    assert len(zero) == len(ip.DEGENERATE), [f.case for f in zero]
    assert {f.kind for f in zero} == {"epsilon hid the zero area"}
    on_line = next(f for f in zero if "three vertices on one line:" in f.case)
    assert "your ε turned each 0/0 into 0" in on_line.explanation, on_line.explanation
    for f in zero:
        assert "solver" not in f.explanation and "raise ValueError" in f.explanation
    assert "epsilon added to the area" in kinds(report)  # and on the proper ones, as before


def test_zeros_returned_for_a_zero_area_are_no_epsilon_and_no_solver():
    def zeros(xy, p):
        lam_or_none = None if _e(*np.asarray(xy, float)) == 0 else _lam(xy, p)[0]
        return np.zeros(3) if lam_or_none is None else lam_or_none

    report = check("barycentric", zeros)
    assert kinds(report) == {"no zero-area check"}, kinds(report)
    for f in report.failures:
        assert "solver" not in f.explanation and "ε" not in f.explanation, f.explanation
        assert "you returned weights for a zero-area triangle" in f.explanation


# -- B5: a rounded LU determinant is no exact area test ---------------------------------------
def by_det(xy, p):
    m = np.vstack([np.asarray(xy, float).T, np.ones(3)])
    if np.linalg.det(m) == 0:
        raise ValueError("zero area")
    return np.linalg.solve(m, [p[0], p[1], 1.0])


def test_det_equal_to_0_is_told_a_rounded_determinant_is_no_area_test():
    report = check("barycentric", by_det)
    assert not report.passed
    assert kinds(report) == {"rounded determinant"}, kinds(report)
    for f in report.failures:
        words = f.explanation
        assert "np.linalg.det" in words and "rounded arithmetic" in words, words
        assert "A rounded determinant is no exact area test" in words and "E == 0" in words


def test_a_solver_alone_is_still_told_of_its_solver_and_det_with_the_exact_test_passes():
    from test_exercises_r153 import by_solve_only

    report = check("barycentric", by_solve_only)
    assert kinds(report) == {"no zero-area check"}
    assert "np.linalg.det" not in str(report)

    def det_and_exact(xy, p):
        _lam(xy, p)  # raises ValueError on E == 0, exactly
        m = np.vstack([np.asarray(xy, float).T, np.ones(3)])
        assert np.linalg.det(m) != 0
        return np.linalg.solve(m, [p[0], p[1], 1.0])

    assert check("barycentric", det_and_exact).passed


# -- B7: a time-out of a per-point function asks of no pixel ----------------------------------
@pytest.mark.parametrize("name", ["barycentric", "perspective_weights"])
def test_a_time_out_of_a_per_point_function_asks_of_no_pixel(name):
    def endless(*args):
        while True:
            pass

    report = ex.check(name, endless, budget=1.0)  # 0.2 s a case
    assert report.stopped is not None and report.failures
    for text in (report.stopped, report.failures[0].explanation, str(report)):
        assert "per pixel" not in text and "should take microseconds" in text, text


# -- B: an ε added to each w --------------------------------------------------------------------
def test_an_epsilon_added_to_each_w_is_named_with_its_size():
    def eps_in_w(lam, w):
        q = np.asarray(lam, float) / (np.asarray(w, float) + 1e-6)
        return q / q.sum()

    report = check("perspective_weights", eps_in_w)
    assert kinds(report) == {"epsilon added to w"}, kinds(report)
    for f in report.failures:
        if "w beyond a GPU's range" in f.case:  # r421 T2: ε ≫ w, λ itself there
            continue
        assert "about 1e-06" in f.explanation and "to each w" in f.explanation
        assert "in terms of μ" not in f.explanation


def test_the_right_3_2_and_a_larger_constant_in_w_are_not_told_epsilon():
    def right(lam, w):  # r421 T2: by the smallest w that weighs, right beyond a GPU's w too
        lam, w = np.asarray(lam, float), np.asarray(w, float)
        live = lam != 0
        q = np.zeros(3)
        q[live] = lam[live] * (w[live].min() / w[live])
        return q / q.sum()

    assert check("perspective_weights", right).passed

    def plus_one(lam, w):  # no guard: a constant of 1 changes every weight
        q = np.asarray(lam, float) / (np.asarray(w, float) + 1.0)
        return q / q.sum()

    assert "epsilon added to w" not in kinds(check("perspective_weights", plus_one))


# -- D11: 3.2's float32 bars say how much they differ ------------------------------------------
def test_the_float32_failure_of_3_2_notes_the_difference():
    import matplotlib.pyplot as plt

    def in_float32(lam, w):
        q = np.asarray(lam, np.float32) / np.asarray(w, np.float32)
        return q / q.sum()

    report = check("perspective_weights", in_float32)
    assert not report.passed and "float32" in kinds(report), kinds(report)
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    texts = [t.get_text() for t in ax.texts]
    assert any(t.startswith("yours differ by") for t in texts), texts
    plt.close(fig)


# -- D12: no literal underscores in 3.2's text, no negative zeros -------------------------------
def test_3_2_text_writes_no_literal_underscores():
    for index in (9,):  # r488: 3.2's text after 3.1b's three cells
        text = re.sub(r"`[^`]*`", "", _cell(NOTEBOOK, index))  # code spans keep theirs
        assert not re.search(r"[^\W\d_]_[a-z]\b", text), re.findall(r"\S*_[a-z]\b", text)
    assert "μ1·f1 + μ2·f2 + μ3·f3" in _cell(NOTEBOOK, 9)


def test_no_negative_zero_is_printed():
    def flipped(xy, p):
        lam, _ = _lam(xy, p)
        return -lam

    report = check("barycentric", flipped)
    expected = [np.asarray(f.expected, float) for f in report.failures
                if not isinstance(f.expected, str)]  # fmt: skip
    assert any(np.signbit(e[e == 0]).any() for e in expected)  # a -0.0 is there to print
    for f in report.failures:
        assert not re.search(r"(?<![\d.e])-0(?![\d.])", f.explanation), f.explanation
