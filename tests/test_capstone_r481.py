"""r481 (exercise 12, the capstone, a verify-read): a perspective slip at large w is not
explained by exercise 3.2's cases beyond a GPU's range, which the scene does not count (MN1);
a function that raises during the render gets its own check's words (HN6); an A-buffer that
blends with the straight rule on all four channels is named (HN7). Unit-level, each well
under a second: the scenes themselves are run by test_capstone*.py."""

from __future__ import annotations

import numpy as np
import pytest

from teachraster.exercises import capstone_glass as glass
from teachraster.exercises.capstone_explain import (
    _divided_by,
    counted_failures,
    named_mistake,
    own_report,
)
from teachraster.exercises.capstone_render import _raised_why
from teachraster.exercises.perspective_weighting import beyond_a_gpu

LAM, W = np.array([0.031, 0.285, 0.684]), np.array([1.095, 40.896, 40.896])


def _squared_far(lam, w):
    """MN1 (W57): λ / w² where some w is far (> 30), λ / w elsewhere."""
    lam, w = np.asarray(lam, float), np.asarray(w, float)
    q = lam / w**2 if w.max() > 30 else lam / w
    return q / q.sum()


def _capped(lam, w):
    """MN1 (W11): every w capped at 20 before the divide."""
    q = np.asarray(lam, float) / np.minimum(np.asarray(w, float), 20.0)
    return q / q.sum()


def test_a_far_w_slip_is_not_told_the_overflow_of_w_1e_310():
    words = named_mistake({"perspective_weights": _squared_far}, "perspective_weights")
    assert "1e-310" not in words and "beyond a GPU" not in words, words


def test_the_cases_beyond_a_gpu_are_not_counted():
    report = own_report("perspective_weights", _plain)
    assert any(beyond_a_gpu(f.case) for f in report.failures)  # 3.2's overflow cases
    assert counted_failures("perspective_weights", report) == []


def _plain(lam, w):
    """λ / w normalised: right on every w a GPU meets, NaN beyond float32's range."""
    q = np.asarray(lam, float) / np.asarray(w, float)
    return q / q.sum()


@pytest.mark.parametrize("fn, words", [
    (_squared_far, "the squares of this pixel's w"),
    (_capped, "is a w changed before the divide"),
])  # fmt: skip
def test_the_w_divided_by_is_read_back_at_the_pixel(fn, words):
    said = _divided_by(LAM, W, fn(LAM, W))
    assert words in said and "this pixel's w are in the ratios (1 : 37.3" in said, said


def test_right_weights_and_rounded_ones_are_not_read_back():
    q = LAM / W
    right = q / q.sum()
    assert _divided_by(LAM, W, right) == ""
    assert _divided_by(LAM, W, right.astype(np.float16).astype(float)) == ""


def test_a_function_raising_in_the_render_gets_its_own_checks_words(monkeypatch):
    """HN6 (W07, a barycentric raising ValueError on the other winding, told the mistake
    "you refused every triangle of that winding" in the variant run): the plumbing, without
    running exercise 3.1's check (some 2 s)."""
    import teachraster.exercises.capstone_explain as explain

    said = "; the barycentric exercise's check names the mistake: you refused every triangle"
    monkeypatch.setattr(explain, "named_mistake", lambda used, name: said)
    assert _raised_why({"barycentric": None}, "barycentric") == said
    unnamed = "; the barycentric exercise's check, on its own cases, says: …"
    monkeypatch.setattr(explain, "named_mistake", lambda used, name: unnamed)
    assert _raised_why({"barycentric": None}, "barycentric") == ""


def _straight_a_buffer(depths, colours, background):
    """HN7 (W58): farthest first, the straight rule on all four channels."""
    out = np.asarray(background, dtype=float)
    for k in np.argsort(-np.asarray(depths), kind="stable"):
        c = np.asarray(colours[k], dtype=float)
        out = c * c[3] + out * (1 - c[3])
    return out


def test_an_a_buffer_with_the_straight_rule_is_named():
    depths = np.array([0.967, 0.968])
    colours = np.array([[0.54, 0.12, 0.12, 0.6], [0.09, 0.135, 0.405, 0.45]])
    yours = _straight_a_buffer(depths, colours, glass.BACKGROUND)
    ours = glass.package_resolve(depths, colours, glass.BACKGROUND)
    said = glass._mistake(_straight_a_buffer, depths, colours, yours, ours)
    assert "the straight rule" in said and "alpha too" in said, said


def _w_rounded(lam, w):
    """r481 (W60): every w rounded to an integer before the divide."""
    q = np.asarray(lam, float) / np.round(np.asarray(w, float))
    return q / q.sum()


def test_a_mistake_named_on_the_own_cases_is_said_at_a_pixel_only_where_it_gives_its_answer():
    q = LAM / W
    mu, yours = q / q.sum(), _w_rounded(LAM, W)
    said = named_mistake({"perspective_weights": _w_rounded}, "perspective_weights",
                         case=((LAM, W), mu, yours))  # fmt: skip
    assert "np.divide" not in said and "no such mistake gives your answer here" in said, said
