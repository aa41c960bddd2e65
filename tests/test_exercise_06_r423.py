"""r423 (exercise 6): 6.1's wrong passes (a tolerance on the distance, a relative isclose,
the winding or an edge's kind decided before snapping, E in float32 on a 4K triangle), a
constant 0 of several types, ``//``, rounded samples, and 6.3's "not each other's inverse"
said only as one cause of several.

The wrong variants themselves (each named right in its first explanation) are in
``student_variants.R423`` and ``R423_SRGB``, run by test_checker_corpus.py and
test_reasoning_exercises.py; here the reader's counterexamples are cases of the check.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R423, R423_SRGB

from teachraster import exercises as ex
from teachraster.core.snapping import snap
from teachraster.exercises.antialiasing import covered_samples, expected_fraction, sample_points
from teachraster.exercises.checks import exercise

#: the reader's counterexamples (cex2.py, ex22.py, WP3, cex32b.py): (triangle, pixel,
#: offset, the rule's fraction)
COUNTER = [
    ([[2.375, -100], [2.37890625, 412], [-50, 150]], (156, 2), [0.376953125, 1 / 512], 1.0),
    ([[0.19921875, 0.06347656], [2.74609375, 0.35644531], [1.5559431, 0.21826552]], (0, 1),
     [0.013671875, 0.15625], 1.0),
    ([[0, 1.375], [6, 1.3759765625], [3, 6]], (1, 2), [0.875, 0.375], 1.0),
    ([[1578.640625, 929.24609375], [2995.0234375, 2574.8203125], [2903.03125, 331.234375]],
     (1509, 2078), [0.259765625, 0.7109375], 0.0),
]  # fmt: skip


@pytest.mark.parametrize("xy, pixel, offset, fraction", COUNTER)
def test_the_counterexamples_are_cases_of_the_check(xy, pixel, offset, fraction):
    xy, samples = np.array(xy, float), np.array([offset], float)
    assert expected_fraction(xy, pixel, samples) == fraction
    assert covered_samples(snap(xy), sample_points(pixel, samples)).mean() == fraction
    fixed = [args for _, args, _ in exercise("coverage_fraction").cases()]
    assert any(
        np.array_equal(a[0], xy) and a[1] == pixel and np.array_equal(a[2], samples) for a in fixed
    )


def test_the_sliver_turns_when_snapped():
    from teachraster.core.edges import edge_function

    xy = np.array(COUNTER[1][0])
    assert edge_function(*xy) < 0 < edge_function(*snap(xy))


@pytest.mark.parametrize("label", [k for k in R423 if "float32" in k])
def test_float32_is_named_as_float32_only_on_the_4k_triangle(label):
    report = ex.check(*R423[label][:2])
    assert not report.passed
    # r482 WP2: and the 1880 px sliver whose area is 0 in float32 (that E's area is too)
    assert {f.kind for f in report.failures} == {"float32"}, str(report)
    assert "4K" in report.failures[0].case
    assert all("4K" in f.case or "sliver" in f.case for f in report.failures), str(report)


@pytest.mark.parametrize(
    "label", [k for k in R423 if "zeros" in k or "returning 0" in k or "else 0" in k]
)
def test_zeros_of_several_types_are_one_constant(label):
    report = ex.check(*R423[label][:2])
    assert all(f.kind == "constant" for f in report.failures), str(report)
    assert "windings" not in str(report)


def test_floor_division_is_never_told_windings_or_centres():
    report = ex.check(*R423["coverage by floor division, k // S"][:2])
    text = str(report)
    assert "Integer division" in text
    assert "windings" not in text and "pixel centre only" not in text, text


@pytest.mark.parametrize("label", [k for k, v in R423_SRGB.items() if v[0] == "resolve_srgb"])
def test_the_exact_pair_is_never_told_it_is_not_inverse(label):
    """r423 MN3: these answers call the exact curves; the background's case says only that
    something between decode and encode changes the value."""
    report = ex.check(*R423_SRGB[label][:2])
    text = " ".join(f.explanation for f in report.failures)
    assert "your two curves are not each other's inverse" not in text
    assert "your encode of your decode" not in text


def test_the_two_resolves_titles_say_light_averaged_only_of_a_right_answer():
    """r423 S1: a wrong 6.3 was titled "light averaged" whatever it did."""
    import matplotlib.pyplot as plt
    from exercise_solutions import CORRECT

    from teachraster.exercises.resolve_light import show_two_resolves

    for srgb, said in ((CORRECT["resolve_srgb"], "light averaged"),
                       (R423_SRGB["resolve_srgb averaging codes, then decoding"][1],
                        "not its rule here")):  # fmt: skip
        fig, axes = plt.subplots(1, 3)
        show_two_resolves(CORRECT["resolve"], srgb, axes)
        titles = [ax.get_title().replace("\n", " ") for ax in axes]
        plt.close(fig)
        assert "codes averaged" in titles[0] and said in titles[1], titles
