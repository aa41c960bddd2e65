"""r443 (exercise 6): the zero-area test made on the vertices as given passed 6.1 (WP1); the
samples rounded onto the 1/256 grid half up were told "a tolerance" and vertices snapped up
"unsnapped" (MN1, MN2); ÷ samples.size, the edge tests averaged and sample 0 alone (6.1), the
shares by integer division, the background once, the last sample and ids == 0 (6.2), the
background encoded, the light rounded to 8 bits and ids == 0 (6.3) got only the rule (HN1-HN9);
6.2's scene explained its pixel by numbers only (r432 S2).

The variants (each named right in its first explanation) are ``student_variants.R443``; the
correct ones ``R443_RIGHT``.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R443, R443_RIGHT
from variant_checks import assert_first_named, assert_passes

from teachraster import exercises as ex
from teachraster.core.edges import edge_function
from teachraster.core.snapping import snap
from teachraster.exercises.antialiasing import expected_fraction
from teachraster.exercises.checks import exercise

#: collinear as given, a sliver once snapped, a sample strictly inside it
SLIVER = ([[0.5 / 256, 0], [1.5 / 256, 4], [2.5 / 256, 8]], (5, 0), [[3 / 512, 0.5]])


def test_the_sliver_is_collinear_as_given_only_and_a_fixed_case():
    xy, pixel, samples = (np.array(SLIVER[0], float), SLIVER[1], np.array(SLIVER[2], float))
    assert float(edge_function(*xy)) == 0 and float(edge_function(*snap(xy))) > 0
    assert expected_fraction(xy, pixel, samples) == 1.0
    fixed = [args for _, args, _ in exercise("coverage_fraction").cases()]
    assert any(
        np.array_equal(a[0], xy) and a[1] == pixel and np.array_equal(a[2], samples) for a in fixed
    )


@pytest.mark.parametrize("label", list(R443))
def test_each_variant_is_named_on_every_failure(label):
    assert_first_named(*R443[label], every_failure=True)


@pytest.mark.parametrize("label", list(R443_RIGHT))
def test_each_correct_variant_passes(label):
    assert_passes(*R443_RIGHT[label])


def test_the_resolve_scene_names_the_cause_of_its_pixel():
    def covered_only(sample_colours, sample_ids, background):
        covered = np.asarray(sample_ids) >= 0
        c = np.asarray(sample_colours, float)
        return c[covered].mean(axis=0) if covered.any() else background

    report = ex.check("resolve", covered_only)
    row, col = report.differing_pixels()[0]
    words = report.explain_pixel(int(row), int(col))
    assert "covered sample only" in words, words
