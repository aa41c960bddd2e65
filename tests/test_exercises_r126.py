"""Review r126 (exercises 03, 08, 12 played as students in fresh processes): 3.2 had one
point outside the triangle of 71 cases and told abs(λ) only the general rule (D3-3); cell 4
of 03 gave far triangles as the only reason for float64 while the check fails float32 at the
origin (D3-2); 8.2's outer-corner and plane-only mistakes were each caught by one case (D8-3);
the capstone failed a scene whose pixels all matched, for 3.2's w = 1e-310 (D12-1).
"""

from __future__ import annotations

from pathlib import Path

import nbformat
import numpy as np

from teachraster import exercises as ex
from teachraster.exercises import tries

EXERCISES = Path(__file__).parents[1] / "notebooks/exercises"


def _check(name, fn, *, fresh=True):
    if fresh:
        tries.forget_hints(name)
    try:
        return ex.check(name, fn, budget=60)
    finally:
        tries.spend_hints([name])


def _cell(notebook: str, index: int) -> str:
    return " ".join(nbformat.read(EXERCISES / notebook, 4).cells[index].source.split())


def test_absolute_lambda_is_named_on_several_points_outside_the_triangle():
    """D3-3: abs(λ) failed one case of 71 and was told "write λ_i in terms of μ ..."."""
    from teachraster.exercises.perspective_weighting import weights_cases

    outside = [label for label, (lam, _), _ in weights_cases() if label.startswith("p outside")]
    assert len(outside) >= 5, outside
    for label, (lam, w), mu in weights_cases():
        if label.startswith("p outside"):
            assert (lam < 0).sum() == 1 and (lam / w).sum() > 0 and (mu < 0).sum() == 1, label

    def absolute(lam, w):
        lam, w = np.asarray(lam, float), np.asarray(w, float)
        q = np.abs(lam) * (w.min() / w)
        return q / q.sum()

    report = _check("perspective_weights", absolute)
    assert len(report.failures) >= 5, str(report)
    for failure in report.failures:
        assert "you took abs(λ)" in failure.explanation, failure.explanation


def _naive_weights(lam, w):
    """Lesson 04's formula as printed: λ_i / w_i over their sum, in float64."""
    with np.errstate(all="ignore"):
        q = np.asarray(lam, float) / np.asarray(w, float)
        return q / q.sum()


def test_lesson_04s_formula_passes_the_floor_its_pixels_match_with_a_note():
    """D12-1: "fails, though all 1728 pixels match the package's" for w = 1e-310, which
    exercise 3 calls "the simulator's concern, not a GPU's"; the scene now judges the scene
    and notes what 3.2's check still fails."""
    from test_capstone import _mine

    report = ex.capstone(
        "textured_floor", **_mine("textured_floor", perspective_weights=_naive_weights)
    )
    text = str(report)
    assert report.passed and report.n_wrong == 0, text
    assert "all 1728 pixels match the package's, and the scene passes" in text, text
    assert "still fails 10 of exercise 3.2's cases whose w lie beyond float32's range" in text
    assert "w = (1e-310" in text and "exercise 3.2's check does" in text, text
    assert not _check("perspective_weights", _naive_weights).passed
    cell = _cell("12_capstone.ipynb", 8)
    assert "w = 1e-310" in cell and "not counted" in cell, cell


def test_a_wrong_weight_on_a_gpus_w_still_fails_the_scene_whose_pixels_match():
    """The note is for w beyond float32's range only: a mistake on ordinary w still counts."""
    from test_capstone import _mine

    def naive_but_clamped(lam, w):  # right inside the triangle, the floor's only centres
        return _naive_weights(np.maximum(lam, 0.0), w)

    report = ex.capstone(
        "textured_floor", **_mine("textured_floor", perspective_weights=naive_but_clamped)
    )
    assert not report.passed and report.n_wrong == 0, str(report)
    assert "p outside the triangle" in str(report), str(report)
