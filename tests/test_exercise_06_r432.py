"""r432 (exercise 6): np.isclose on the distance to the edge passed 6.1 (WP1); E in float32
as A·x + B·y + C was told "a tolerance" (MN1); the standard pattern in place of the given
samples and the pixel centre as an extra sample got only the rule (HN1); the stubs' row plot
was titled "orange line" with none drawn (S3).

The variants themselves (each named right in its first explanation) are in
``student_variants.R432``, run by test_checker_corpus.py and test_reasoning_exercises.py.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R423, R432
from variant_checks import assert_first_named

from teachraster import exercises as ex
from teachraster.core.snapping import snap
from teachraster.exercises.antialiasing import covered_samples, expected_fraction, sample_points
from teachraster.exercises.checks import exercise

#: the 2048 px edge: E = 2⁻¹⁷ px² inside a right edge, the sample 3.7e-9 px from it
LONG = ([[2.375, -100], [2.37890625, 1948], [-50, 150]], (924, 2), [0.376953125, 1 / 512])


def test_the_2048_px_edge_is_a_case_below_isclose_atol():
    xy, pixel, offset = LONG
    xy, samples = np.array(xy, float), np.array([offset], float)
    assert expected_fraction(xy, pixel, samples) == 1.0
    assert covered_samples(snap(xy), sample_points(pixel, samples)).all()
    points = sample_points(pixel, samples)
    from teachraster.core.edges import edge_function

    e = edge_function(xy[0], xy[1], points)[0]
    assert e == 2.0**-17 and e / np.hypot(*(xy[1] - xy[0])) < 1e-8
    fixed = [args for _, args, _ in exercise("coverage_fraction").cases()]
    assert any(
        np.array_equal(a[0], xy) and a[1] == pixel and np.array_equal(a[2], samples) for a in fixed
    )


@pytest.mark.parametrize("label", list(R432))
def test_each_variant_is_named_on_every_failure(label):
    assert_first_named(*R432[label], every_failure=True)


def test_the_difference_form_in_float32_is_right_on_the_2048_px_edge():
    """E in float32 as (b − a)·(p − a) is exact there: it fails the 4K triangle only (and
    r482's 1880 px sliver, whose area E(v1, v2, v3) is 0 in float32)."""
    for label in (k for k in R423 if "float32" in k):
        report = ex.check(*R423[label][:2])
        cases = [f.case for f in report.failures]
        assert not any("2048" in c for c in cases), str(report)
        assert any("4K" in c for c in cases), str(report)
        assert all("4K" in c or "sliver, its area 0 in float32" in c for c in cases), str(report)


def test_the_stubs_row_plot_names_no_orange_line():
    import matplotlib.pyplot as plt

    from teachraster.exercises.resolve_light import show_two_resolves

    def stub(sample_colours, sample_ids, background):
        raise NotImplementedError

    fig, axes = plt.subplots(1, 3)
    show_two_resolves(stub, stub, axes)
    title = axes[2].get_title()
    plt.close(fig)
    assert "orange" not in title and "not implemented yet" in title, title
