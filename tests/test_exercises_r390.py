"""Review r390 (exercise 07, texture filtering): 7.4's pixels all in quads the floor covers
(N1), trilinear's unclamped-λ index words with the case's own ⌊λ⌋ (N2), the weight labels led
to their texels (N4), 7.2's "one texel's value" answered for both wraps (N5), and the helper
question's quad drawn (N6)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from reasoning_solutions import CORRECT as REASONING

from teachraster import exercises as ex
from teachraster.exercises.quad_difference import (
    FLOOR,
    QUESTION_PIXELS,
    helper_quad,
    helper_question,
)
from teachraster.exercises.texture_filtering import bilinear_questions, trilinear_with

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "07_texture_filtering.ipynb"


def test_7_4s_pixels_lie_in_quads_the_floor_covers():
    """N1: (30, 16)'s quad lay wholly below the floor's bottom edge (never shaded); 7.4's task
    is now a step of 7.1 (F1), whose pixels are covered too."""
    from teachraster.exercises.pixel_level import QUESTION_PIXELS as LOD_PIXELS
    from teachraster.exercises.quad_difference import inside

    xy = FLOOR[0]
    for r, c in QUESTION_PIXELS + LOD_PIXELS:
        r0, c0 = r - r % 2, c - c % 2
        assert any(inside(xy, c0 + dc + 0.5, r0 + dr + 0.5) for dr in (0, 1) for dc in (0, 1))
        assert inside(xy, c + 0.5, r + 0.5), (r, c)
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    task = next("".join(c["source"]) for c in cells
                if c["metadata"].get("nbgrader", {}).get("grade_id") == "pixel_lod_task")  # fmt: skip
    for r, c in LOD_PIXELS:
        assert f"({r}, {c})" in task.replace("\n", " ")
    assert "(30, 16)" not in task


def test_the_index_slip_prints_the_cases_own_floor_and_level():
    """N2: at λ = −2 the code reads pyramid[-2] (level 2), not "pyramid[-1] … the last"."""
    report = ex.check("trilinear", lambda p, uv, lod, wrap="repeat":
                      trilinear_with(p, uv, lod, wrap, clamp="index"))  # fmt: skip
    assert not report.passed
    words = str(report) + " ".join(str(f) for f in report.failures)
    assert "⌊λ⌋ = −1 is not a level: Python's pyramid[-1] is the last" not in words
    assert "⌊λ⌋ = -2 is not a level: Python's pyramid[-2] is level 2" in words, words


def test_7_2s_one_texel_answer_names_both_wraps():
    """N5: with "clamp" every u beyond the outer centres gives one texel's value too."""
    words = bilinear_questions(4, 0.05)
    assert "exactly with 'repeat' at u = 0.125, 0.375, 0.625, 0.875" in words
    assert "with 'clamp' there and at every u ≤ 0.125 and u ≥ 0.875 (column 0 or 3)" in words


def test_the_weight_labels_are_led_to_their_texels(plt):
    """N4: each weight label has a leader line ending inside its own texel."""
    from exercise_solutions import CORRECT

    report = ex.check("bilinear", CORRECT["bilinear"])
    fig, ax = plt.subplots(figsize=(9.0, 3.8), layout="constrained")
    report.plot(ax)
    labels = [t for t in ax.texts if "w " in t.get_text()]
    assert len(labels) == 4
    for t in labels:
        assert t.arrow_patch is not None
        x, y = t.xy
        assert abs(x - np.floor(x) - 0.5) < 0.5 and abs(y - np.floor(y) - 0.5) < 0.5


def test_the_helper_quad_is_drawn_in_the_pass_figure(plt):
    """N6: the helper question's quad (8, 16) was answered but not drawn."""
    r0, c0, left, right, near = helper_quad()
    assert (r0, c0) == (8, 16)
    words = helper_question()
    assert f"the quad at ({r0}, {c0})" in words and "short of the helper's centre" in words
    report = ex.check("quad_derivatives", REASONING["quad_derivatives"])
    fig, ax = plt.subplots(figsize=(9.0, 3.8), layout="constrained")
    report.plot(ax)
    fig.canvas.draw()
    insets = [a for a in ax.child_axes]
    assert len(insets) == 1
    inset = insets[0]
    assert f"quad ({r0}, {c0})" in inset.get_title("left")
    shown = {t.get_text() for t in inset.texts}
    assert f"{left:.3f}" in shown and f"{right:.3f}" in shown
    assert f"{near:.3f}" in inset.get_title("left")
