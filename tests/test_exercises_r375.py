"""Review r375 (exercise 07, texture filtering): the "answer first" questions of 7.1-7.4
answered by the passing figures, the trilinear figure drawing the levels λ reads, the bilinear
figure's weights at classroom size and off the sample point, and three slips named (the
coordinate wrapped then clamped, named from the fixed cases; the rows blended by x's fraction;
a float16 λ told as rounding)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from exercise_solutions import CORRECT
from reasoning_solutions import CORRECT as REASONING
from student_variants import R375

from teachraster import exercises as ex
from teachraster.exercises import tries
from teachraster.exercises.level_of_detail import level_questions
from teachraster.exercises.quad_difference import FLOOR, helper_question, quad_questions
from teachraster.exercises.texture_filtering import (
    bilinear_questions,
    level_weights,
    trilinear_questions,
)

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "07_texture_filtering.ipynb"


def _passing_figure(plt, name, fn):
    report = ex.check(name, fn)
    assert report.passed, str(report)
    fig, ax = plt.subplots(figsize=(9.0, 3.8), layout="constrained")
    report.plot(ax)
    fig.canvas.draw()
    return fig, ax


def _words(ax) -> str:
    return " ".join([ax.get_xlabel(), *(t.get_text() for t in ax.texts)])


# -- F2, F5: the questions answered ------------------------------------------------------------


def test_the_levels_and_weights_of_7_3s_lods():
    """7.3 asks for λ = 1.25, 3.4 and −0.7 on levels 0 to 3: two levels where λ lies between
    them, one where it is clamped."""
    assert level_weights(3, 1.25) == {1: 0.75, 2: 0.25}
    assert level_weights(3, 3.4) == {3: 1.0}
    assert level_weights(3, -0.7) == {0: 1.0}
    assert level_weights(3, 2.0) == {2: 1.0}
    words = trilinear_questions(3)
    for said in ("λ = 1.25: 0.75·level 1 + 0.25·level 2", "λ = 3.4: level 3 alone (λ clamped to 3)",
                 "λ = -0.7: level 0 alone (λ clamped to 0)"):  # fmt: skip
        assert said in words, words


def test_the_trilinear_pass_figure_draws_the_two_levels_it_reads(plt):
    """F5: level 0 was drawn at λ = 1.5; the pass figure draws levels 1 and 2 at λ = 1.25,
    each with its level weight and its four texel weights, and answers 7.3's three λ's."""
    fig, ax = _passing_figure(plt, "trilinear", CORRECT["trilinear"])
    titles = [t.get_text() for t in ax.texts if t.get_text().startswith("level ")]
    assert titles == ["level 1 (4×4), weight 0.75", "level 2 (2×2), weight 0.25"], titles
    assert len(ax.get_images()) == 2
    weights = [float(t.get_text()[2:]) for t in ax.texts if t.get_text().startswith("w ")]
    assert len(weights) == 8 and abs(sum(weights) - 2) < 0.05, weights
    assert "λ = 1.25: 0.75·level 1 + 0.25·level 2" in ax.get_xlabel()
    assert trilinear_questions(3) in _words(ax)


def test_a_failing_trilinear_figure_draws_the_pyramid_without_weights(plt):
    """Before the method is earned every level is drawn, none weighted (7.3's answer)."""
    tries.forget_hints("trilinear")
    try:
        report = ex.check("trilinear", lambda p, uv, lod, wrap="repeat": float(np.mean(p[0])))
        fig, ax = plt.subplots()
        report.plot(ax)
    finally:
        tries.spend_hints(["trilinear"])
    titles = [t.get_text() for t in ax.texts if t.get_text().startswith("level ")]
    assert titles and all("weight" not in t for t in titles), titles
    assert len(titles) == len(ax.get_images()) >= 2
    assert not [t for t in ax.texts if t.get_text().startswith("w ")]


def test_the_bilinear_pass_figure_answers_7_2s_other_questions(plt):
    words = bilinear_questions(4, 0.05)
    assert "u = 0.05 takes column 0 alone (columns -1 and 0 both clamped to it)" in words
    assert "u = 0.125, 0.375, 0.625, 0.875" in words
    assert "columns 1 and 2 averaged at u = 0.5" in words
    fig, ax = _passing_figure(plt, "bilinear", CORRECT["bilinear"])
    assert "columns 1 and 2 averaged at" in _words(ax).replace("\n", " ")


def test_the_mip_pass_figure_answers_7_1s_other_question(plt):
    words = level_questions(1.0, 16.0)
    assert "the shorter axis gives λ = 0" in words and "crosses 16 texels" in words
    assert "the axes' mean gives λ = 3.087" in words
    fig, ax = _passing_figure(plt, "mip_level", CORRECT["mip_level"])
    assert "the axes' mean gives" in _words(ax).replace("\n", " ")


def test_the_quad_pass_figure_marks_7_4s_pixels_and_their_quads(plt):
    words = quad_questions()
    assert "(28, 14) and (29, 15) in the quad at (28, 14)" in words
    assert "(29, 16) in the quad at (28, 16)" in words
    fig, ax = _passing_figure(plt, "quad_derivatives", REASONING["quad_derivatives"])
    caption = ax.get_xlabel().replace("\n", " ")
    assert "(29, 16) in the quad at (28, 16)" in caption and helper_question() in caption
    dashed = [p for p in ax.patches if p.get_linestyle() == "--"]
    assert len(dashed) == 4, "three pixels and the other quad"
    assert ax.get_xlim()[1] >= 18 and ax.get_ylim()[0] >= 30, "the other quad in view"


def test_the_helper_question_takes_a_quad_whose_right_column_lies_outside():
    """7.4's third question: a helper's value at the triangle's nearest point stops the change
    at the edge, so ddx shrinks against the extrapolated one."""
    from teachraster.exercises.quad_difference import expected_pair, inside

    words = helper_question()
    r0, c0 = (int(v) for v in words.split("quad at (")[1].split(")")[0].split(", "))
    xy, w, f = FLOOR
    covered = [inside(xy, c0 + dc + 0.5, r0 + dr + 0.5) for dr in (0, 1) for dc in (0, 1)]
    assert covered == [True, False, True, False]
    near, right = (float(v) for v in words.split("ddx ")[1].split(":")[0].split(", not "))
    assert abs(right - expected_pair(xy, w, f, r0, c0)[0]) < 1e-3 and abs(near) < abs(right)


def test_the_notebook_says_the_pass_figures_answer_the_questions():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    text = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in cells}
    assert "its figure answers the three" in text["texel_weights_task"].replace("\n", " ")  # r491
    # r390 F1: 7.4's quads are now a step of 7.1's λ at a pixel
    assert "and answers the three" in text["pixel_lod_task"].replace("\n", " ")
    assert all(not c.get("outputs") for c in cells if c["cell_type"] == "code")


# -- F6: the bilinear figure's labels ----------------------------------------------------------


def test_the_bilinear_weights_are_classroom_size_apart_and_off_the_point(plt):
    """F6: 9 pt labels touched each other and covered the sample point; the texture had no
    frame (a white corner texel read as missing)."""
    from matplotlib.patches import Rectangle

    fig, ax = _passing_figure(plt, "bilinear", CORRECT["bilinear"])
    labels = [t for t in ax.texts if "w " in t.get_text()]
    assert len(labels) == 4
    assert all(t.get_fontsize() >= 12 for t in labels)
    renderer = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(renderer) for t in labels]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1 :]:
            assert not a.overlaps(b), (a, b)
    cross = next(line for line in ax.lines if line.get_marker() == "x")
    point = ax.transData.transform(np.column_stack(cross.get_data()))[0]
    assert not any(b.expanded(1.0, 1.0).contains(*point) for b in boxes)
    h, w = 4, 4
    assert any(isinstance(p, Rectangle) and not p.get_fill() and p.get_width() == w
               and p.get_height() == h for p in ax.patches), "the texture is framed"  # fmt: skip


# -- F3, F4, F7: the slips named ---------------------------------------------------------------


@pytest.mark.parametrize("label", list(R375))
def test_r375s_slips_are_named_first_with_their_kind(label):
    name, fn, words, kind = R375[label]
    for _ in range(3):  # the drawn cases differ per check: the naming must not
        report = ex.check(name, fn)
        first = report.failures[0]
        assert "drawn for this check" not in first.case
        assert words in first.explanation and first.kind == kind, (first.kind, first.explanation)
        assert words in str(report)


def test_the_wrapped_coordinate_is_named_on_the_fixed_cases_only():
    """F7: named only where a random case drawn for the check happened to fit "(u, v) wrapped";
    the fixed case u = 0 names it now."""
    name, fn, words, kind = R375["bilinear with x wrapped into [0, W), the texels clamped"]
    report = ex.check(name, fn)
    fixed = [f for f in report.failures if "drawn for this check" not in f.case]
    assert fixed and all(f.kind == kind for f in fixed), [f.kind for f in fixed]


def test_a_float16_level_is_not_told_to_change_its_algorithm():
    report = ex.check("mip_level", R375["mip level in float16"][1])
    assert "float16's rounding" in report.failures[0].explanation
    assert "λ counts the halvings" not in str(report)


# -- F8: the first, "a hint only", failures give no fix away ------------------------------------


@pytest.mark.parametrize(
    ("fn", "hint", "fix"),
    [(lambda dx, dy, s: _rho(dx, dy, s, max, math.log), "which log counts the halvings",
      "λ = log2 ρ"),
     (lambda dx, dy, s: _rho(dx, dy, s, min, math.log2), "which axis must λ follow",
      "GL takes the longer"),
     (lambda dx, dy, s: 2 * _rho(dx, dy, s, max, math.log2), "is an axis' length its square?",
      "take the square root")],
)  # fmt: skip
def test_the_first_mip_level_failure_asks_instead_of_giving_the_fix(fn, hint, fix):
    tries.forget_hints("mip_level")
    try:
        first = ex.check("mip_level", fn).failures[0].explanation
    finally:
        tries.spend_hints(["mip_level"])
    assert hint in first and fix not in first, first


def _rho(ddx, ddy, size, pick, log):
    h, w = size
    return log(pick(math.hypot(ddx[0] * w, ddx[1] * h), math.hypot(ddy[0] * w, ddy[1] * h)))
