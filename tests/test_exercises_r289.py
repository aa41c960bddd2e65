"""r289 (exercise 09, lines and blending): nine wrong answers were half-named, and one
secondary explanation inferred a stop the function never made.

M1: the right colour in another channel order (ARGB, BGRA, red and alpha swapped) got "go back
through the derivation" in 9.2a and 9.2b; it is named by the rule exercise 7.2's bilinear uses
(:mod:`teachraster.exercises.channel_order`, one place). M2: double premultiplication in 9.2a.
C1: a function that read all 23 layers and returned the last was told "you stopped after layer
1 of 23". S1: a closed diamond with no ε, two rounding DDAs; S2: colour added without 1 − A;
S3: the tie rule came before the cause; M3/S4/S5/S8: the notebook's hints and boxes.
"""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from teachraster import exercises as ex
from teachraster.exercises.channel_order import order_name, other_order
from teachraster.exercises.lines import rounded_dda


def _first(name, fn):
    report = ex.check(name, fn, budget=60)
    assert not report.passed, f"{name}: a wrong variant passes"
    assert all(f.kind for f in report.failures), "every failure has a kind"
    return report.failures[0]


def _over(s, d):
    s, d = np.asarray(s, float), np.asarray(d, float)
    a = s[3] + d[3] * (1 - s[3])
    if a == 0:
        return np.zeros(4)
    return np.r_[(s[:3] * s[3] + d[:3] * d[3] * (1 - s[3])) / a, a]


def _atop(s, d):
    s, d = np.asarray(s, float), np.asarray(d, float)
    return np.r_[s[:3] * d[3] + d[:3] * (1 - s[3]), d[3]]


ORDERS = {"ARGB": [3, 0, 1, 2], "BGRA": [2, 1, 0, 3], "red and alpha swapped": [3, 1, 2, 0]}


@pytest.mark.parametrize("order", list(ORDERS))
@pytest.mark.parametrize(("name", "right"), [("over_straight", _over),
                                              ("atop_premultiplied", _atop)])  # fmt: skip
def test_a_right_colour_in_another_channel_order_is_named(name, right, order):
    perm = ORDERS[order]
    first = _first(name, lambda s, d: right(s, d)[perm])
    assert first.kind == "channel order", first.explanation
    said = first.explanation.split("yours is", 1)[1]
    assert said.split(": ", 1)[1].startswith("the right colours in another channel order ("), said
    assert "return (r, g, b, a), alpha last" in said and "derivation" not in said, said


def test_the_channel_order_rule_is_one_place_for_07_and_09():
    """The rule names the order the student wrote, the likeliest where values repeat."""
    assert other_order([1, 0, 0, 1], [1, 1, 0, 0], 1e-6) == (3, 0, 1, 2)
    assert order_name((3, 0, 1, 2)) == "ARGB for RGBA"
    assert order_name((2, 1, 0)) == "BGR for RGB, reversed"
    assert order_name((3, 1, 2, 0)) == "AGBR for RGBA, R and A swapped"
    assert other_order([0.5, 0.5, 0.5, 1], [0.5, 0.5, 0.5, 1], 1e-6) is None  # the answer
    assert other_order([0.2, 0.4, 0.6], [0.2, 0.4, 0.7], 1e-6) is None
    from teachraster.exercises import blend_mistakes, texture_filtering

    src = Path(texture_filtering.__file__).read_text() + Path(blend_mistakes.__file__).read_text()
    assert src.count("channel_order_mistake(") == 2 and "permutations" not in src


def test_double_premultiplication_is_named_in_over_straight():
    def twice(s, d):
        s, d = np.asarray(s, float), np.asarray(d, float)
        a = s[3] + d[3] * (1 - s[3])
        if a == 0:
            return np.zeros(4)
        return np.r_[(s[:3] * s[3] ** 2 + d[:3] * d[3] ** 2 * (1 - s[3])) / a, a]

    first = _first("over_straight", twice)
    assert first.kind == "premultiplied twice", first.explanation
    assert "you multiplied each colour by its alpha twice" in first.explanation


def test_blend_equations_default_is_named_as_the_packages():
    """S7: ``tr.blend_equation(src, dst)``, its default pair, is GL's straight blend."""
    from teachraster.core.blend_factors import blend_equation

    first = _first("over_straight", lambda s, d: blend_equation(np.asarray(s), np.asarray(d)))
    assert "blend_equation(src, dst) does by default" in first.explanation, first.explanation


def _walk(step):
    def front_to_back(layers):
        acc = np.zeros(4)
        for layer in layers:
            acc = step(acc, np.asarray(layer, float))
            if acc[3] >= 1:
                break
        return acc

    return front_to_back


def test_a_function_that_read_every_layer_is_never_told_it_stopped():
    """C1: the last layer of the 23-layer stack equals its first layer's composite; the
    function read all 23, so "stopped after layer 1" was false."""

    def last_only(layers):
        out = np.zeros(4)
        for layer in layers:
            out = np.asarray(layer, float)
        return out

    report = ex.check("front_to_back", last_only, budget=60)
    assert report.failures[0].kind == "farthest only", str(report)
    assert all("you stopped after layer" not in f.explanation for f in report.failures)
    assert "stopped early" not in {f.kind for f in report.failures}


def test_a_colour_added_without_the_transmittance_is_named():
    """S2: ``c += layer`` with the alpha weighed right got the rule."""
    first = _first("front_to_back", _walk(lambda acc, c: np.r_[
        acc[:3] + c[:3], acc[3] + (1 - acc[3]) * c[3]]))  # fmt: skip
    assert first.kind == "colour not weighed", first.explanation
    assert "without the transmittance 1 − A in front of it" in first.explanation


def _closed_no_eps(p0, p1):
    """The reader's: no ε, and every diamond closed (≤ ½), p1's too."""
    half, a, b = Fraction(1, 2), tuple(map(Fraction, p0)), tuple(map(Fraction, p1))

    def inside(p, cx, cy):
        return abs(p[0] - cx) + abs(p[1] - cy) <= half

    def meets(cx, cy):  # the closed diamond: the segment's nearest point to it, in L1
        ts = {Fraction(0), Fraction(1)}
        for k, c in ((0, cx), (1, cy)):
            if b[k] != a[k] and 0 <= (c - a[k]) / (b[k] - a[k]) <= 1:
                ts.add((c - a[k]) / (b[k] - a[k]))
        return any(inside((a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])), cx, cy)
                   for t in ts)  # fmt: skip

    return [(r, c) for r in range(12) for c in range(12)
            if meets(c + half, r + half) and not inside(b, c + half, r + half)]  # fmt: skip


def test_a_closed_diamond_without_epsilon_is_named_cause_first():
    """S1 and S3: both causes named, and before the tie rule's sentence."""
    first = _first("line_pixels", _closed_no_eps)
    assert first.kind == "closed diamond and no perturbation", first.explanation
    why = first.explanation.split("missing): ", 1)[1]
    assert why.startswith("your diamonds include their boundary"), why
    assert why.index("you did not move the end points") < why.index("at a tie"), why


@pytest.mark.parametrize("centred", [False, True], ids=["from the pixels", "from the centres"])
def test_rounding_ddas_are_named(centred):
    first = _first("line_pixels", lambda p0, p1: sorted(rounded_dda(p0, p1, centred)))
    assert first.kind == "DDA", first.explanation
    assert "you stepped a DDA from pixel to pixel, rounding" in first.explanation


def test_a_tie_explanation_leads_with_the_cause():
    """S3: "you did not move y" came after ~430 characters of rule; S8: Vulkan's rule."""
    from teachraster.exercises.lines import EPS, diamond_pixels

    first = _first("line_pixels", lambda p0, p1: sorted(diamond_pixels(p0, p1, eps=(-EPS, 0.0))))
    why = first.explanation.split("missing): ", 1)[1]
    assert why.startswith("you did not move y"), why
    assert "as Vulkan's rule does" in why and "as Direct3D does" not in why, why


def _cells() -> dict:
    nb = Path(__file__).parents[1] / "notebooks/exercises/09_lines_and_blending.ipynb"
    return {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
            for c in json.loads(nb.read_text(encoding="utf-8"))["cells"]}  # fmt: skip


def test_the_line_hints_name_the_lesson_in_every_layout():
    """M3 and S5: the sketch stands in a second hint; the lesson is named by its file and its
    place under ``teachraster lessons DIR`` (the relative link breaks in a flat copy)."""
    task = _cells()["line_pixels_task"]
    assert task.count("<details>") == 3, task
    assert "`12a_lines.ipynb`" in task and "`DIR/12a_lines.ipynb`" in task, task
    assert "teachraster lessons DIR" in task and "student-version -o DIR" in task, task
    second = task[task.index("<summary>A second hint") :]
    assert "p(t) = p0 + t·(p1 − p0)" in second and "leaves the diamond unless p1" in second


def test_the_9_3_box_is_short():
    """S4: ~230 words of float edge cases; now the stop and the two tests the check accepts."""
    task = _cells()["front_to_back_task"]
    box = task[task.index("<summary>What the check tries") :]
    assert len(box.split()) < 90, len(box.split())
    a = 1 - 2.0**-30  # the box's example, as float64 accumulates it
    assert a + (1 - a) * a == 1.0 and (1 - a) ** 2 > 0
