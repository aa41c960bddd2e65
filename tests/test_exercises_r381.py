"""Review r381 (exercise 05): a 5.3 room measured between rounded depths fails and is named,
code with no room test is told so (apart from a test against `clear` in view units), and the
last half-named slips of 5.1, 5.2 and 5.4 are named."""

from __future__ import annotations

import math

import pytest
from student_variants import KINDS, R381, WRONG

from teachraster import exercises as ex
from teachraster.exercises import decal_bias as db
from teachraster.exercises import tries


def _first(label: str):
    name, fn, words = WRONG[label]
    tries.forget_hints(name)
    report = ex.check(name, fn)
    assert not report.passed, str(report)
    return report.failures[0], words


@pytest.mark.parametrize("label", [*R381, "decal bias computing room, never testing it"])
def test_each_variant_is_told_its_own_mistake_first(label):
    first, words = _first(label)
    assert words in first.explanation, first.explanation
    assert first.kind == KINDS[label], (first.kind, first.explanation)


def _rounded_room(args) -> float:
    z, tilt, pixel, near, far, bits, reverse, clear = args
    scale = 2**bits - 1
    z_win = lambda zz: far / (far - near) * (1 - near / zz)  # noqa: E731
    return (round(z_win(z) * scale) - round(z_win(z - clear) * scale)) / scale


def test_the_rounded_room_cases_lie_within_a_step_of_the_bound_one_each_way():
    """F1: one case where the rounded room overshoots (NaN expected, an offset given) and one
    where it falls short (an offset expected, NaN given), each far beyond float32's rounding
    of the bound."""
    cases = {args: e for _, args, e in db.bias_cases()}
    ways = set()
    for setting, clear in db.ROUNDED:
        args = (*setting, clear)
        r, m = db.step(args[5]), db.slope(*args[:5])
        lo, hi = db.bounds(*args)
        assert 0.2 < abs(hi - lo) / r < 0.8  # within a step of the bound, well off it
        rounded_nan = r + m > _rounded_room(args) - m
        assert rounded_nan != math.isnan(cases[args])
        ways.add(rounded_nan)
    assert ways == {True, False}


def test_the_rounded_room_fails_and_says_why_the_unrounded_one_is_right():
    first, _ = _first("decal bias with room between rounded depths")
    words = first.explanation
    assert "Rounding to nearest keeps order" in words and "a tie keeps the object" in words
    assert "compare the unrounded depths" in words


def test_no_room_test_and_a_room_in_view_units_are_told_apart():
    """F2: both return r + m on the usual tight cases; on the steep case (z² < n) a test
    against `clear` says NaN, and code with no test does not."""
    (setting,) = db.STEEP
    _, args, expected = next(c for c in db.bias_cases() if c[1][:7] == setting)
    z, tilt, pixel, near, far, bits, reverse, clear = args
    r, m = db.step(bits), db.slope(*args[:5])
    assert math.isnan(expected) and r + m > clear - m  # view units: NaN, rightly
    assert db.room(z, near, far, clear) > clear  # window depth moves faster than view depth
    first, _ = _first("decal bias computing room, never testing it")
    assert "did not fire" not in first.explanation and "`clear` itself" not in first.explanation
    view, _ = _first("decal bias with room taken as clear itself")
    assert "your test for NaN compares with `clear` itself" in view.explanation
    assert "no test of the room" not in view.explanation


def test_the_swapped_set_up_quotes_its_numbers_in_their_places():
    first, _ = _first("depth set-up with near and dz swapped")
    assert "return (format, near, dz)" in first.explanation
    assert "at your near plane" not in first.explanation.split("yours is")[1]


def test_a_signed_ndc_step_names_the_negative_value():
    first, _ = _first("gap through signed GL NDC")
    assert "np.spacing of a negative float32 is negative" in first.explanation
    assert "2d − 1 = -" in first.explanation and "[−1, 1]" in first.explanation
    assert "a gap is a positive distance" not in first.explanation


def test_the_correct_solutions_still_pass_the_new_cases():
    from reasoning_solutions import decal_bias

    assert ex.check("decal_bias", decal_bias).passed
    labels = [label for label, _, _ in db.bias_cases()]
    assert any("clear 0.082" in label for label in labels)


def test_one_step_is_said_in_the_singular_and_hints_still_hold_it_back():
    """F7: "(not enough: 1 steps, …)" in the full words; the hint's pattern takes "1 step"."""
    from teachraster.exercises.decal_bias import HINTS, _steps

    assert _steps(1.0) == "1 step" and _steps(174.662) == "174.662 steps"
    pattern, _ = HINTS[2]
    assert pattern.search("(not enough: 1 step, where the decal can lie 3 steps behind)")


def test_an_answer_of_the_wrong_form_is_echoed_with_short_numbers():
    """F7: 5.4's (near, format, dz) was echoed with 17 digits."""
    from teachraster.exercises.depth_setup import as_setup
    from teachraster.exercises.running import WrongAnswerType

    with pytest.raises(WrongAnswerType) as caught:
        as_setup((0.014900940040703407, "unorm24", 0.01))
    assert "(0.0149009, 'unorm24', 0.01)" in str(caught.value)


def test_the_sign_slip_keeps_the_solved_denominator_until_the_hints_are_spent():
    """F5: the first words of a sign slip gave gap·f + step·z², the solved formula's
    denominator (docs/exercises.md holds the inequality for n back until two answers fail)."""
    name = "safe_near"
    tries.forget_hints(name)

    def slipped(z, gap, far, bits):
        s = 1 / (2**bits - 1)
        return s * far * z**2 / (gap * far - s * z**2)

    first = ex.check(name, slipped).failures[0].explanation
    assert "a sign slipped" in first and "gap·f + step·z²" not in first
    tries.forget_hints(name)
