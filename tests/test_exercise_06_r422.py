"""r422 (exercise 6): wrong tie rules that passed 6.1, the checker's own ``covered`` handed in,
``Frame.resolve`` inside 6.3 said truly, the offsets on the renderer's 1/512 px grid.

The wrong variants themselves (each named right in its first explanation) are in
``student_variants.R422``, run by test_checker_corpus.py and test_reasoning_exercises.py.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R422

from teachraster import exercises as ex
from teachraster.core.snapping import snap
from teachraster.exercises.antialiasing import (
    covered_samples,
    expected_fraction,
    sample_points,
)
from teachraster.exercises.checks import exercise
from teachraster.exercises.coverage import covered
from teachraster.pipeline.render_triangles import Frame

#: r422's counterexamples (cex2.py): (triangle, offset, the rule's fraction)
COUNTER = [
    ([[2.375, 1], [3, 1.125], [2.375, 1.25]], [0.375 - 1 / 512, 0.125], 0.0),
    ([[2.375, 1.125], [2.375, 1.1328125], [2.25, 1.125]], [0.375 - 1 / 512, 0.125 + 1 / 512], 1.0),
    ([[0, 1.125], [2.375, 1.125], [1, 3]], [0.375, 0.125], 0.0),
    ([[0, 1.125], [2.5, 1.125], [1, 3]], [0.875, 0.125], 0.0),
]


@pytest.mark.parametrize("xy, offset, fraction", COUNTER)
def test_the_counterexamples_are_cases_of_the_check(xy, offset, fraction):
    xy, samples = np.array(xy, float), np.array([offset], float)
    assert expected_fraction(xy, (1, 2), samples) == fraction
    fixed = [args for _, args, _ in exercise("coverage_fraction").cases()]
    assert any(np.array_equal(a[0], xy) and np.array_equal(a[2], samples) for a in fixed)


@pytest.mark.parametrize(
    "label", [k for k, v in R422.items() if v[0] == "coverage_fraction" and "tolerance" in v[3]]
)
def test_a_tolerance_on_e_is_never_blamed_on_a_grid(label):
    name, fn, _, _ = R422[label]
    report = ex.check(name, fn)
    assert not report.passed
    text = " ".join(f.explanation for f in report.failures)
    assert "sub-pixel bits" not in text and "snapped the sample" not in text, text


def test_the_checkers_own_covered_does_not_count():
    def coverage_fraction(xy, pixel, samples):
        points = np.asarray(samples, float) + [pixel[1], pixel[0]]
        return float(covered(snap(np.asarray(xy, float)), points).mean())

    report = ex.check("coverage_fraction", coverage_fraction)
    assert not report.passed and "the checker's own code" in (report.package or ""), str(report)


def test_frame_resolve_inside_resolve_srgb_is_said_to_be_62s_answer():
    from teachraster import linear_to_srgb, srgb_to_linear

    def resolve_srgb(colours, ids, background):
        pixel = type("P", (), {"sample_triangle_id": np.asarray(ids)[None, None]})
        light = srgb_to_linear(np.nan_to_num(colours))[None, None]
        return linear_to_srgb(Frame.resolve(pixel, light, srgb_to_linear(background))[0, 0])

    report = ex.check("resolve_srgb", resolve_srgb)
    assert not report.passed
    assert "6.2's answer" in report.package and "your own resolve from 6.2" in report.package
    assert "computes this very answer" not in report.package


def test_an_offset_off_the_512_grid_is_explained_where_the_renderer_puts_it():
    """r422 C1: the renderer rounds offsets to 1/512 px; the explanations do too."""
    xy = np.array([[2.375, -1], [6, 1.5], [2.375, 5]])
    samples = np.array([[0.375 - 1 / 1024, 0.125]])
    assert expected_fraction(xy, (1, 2), samples) == 1.0
    assert covered_samples(snap(xy), sample_points((1, 2), samples)).tolist() == [True]
