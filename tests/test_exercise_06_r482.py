"""r482 (exercise 6): 6.1's sample positions rounded to 6 decimals and the area E(v1, v2, v3)
alone in float32 passed (WP1, WP2); a zero-area refusal by a tolerance and E in int32 were told
"a tolerance on E" (MN1-MN3); a tie counted as half, two of the three edges, the third edge
walked backwards and sample_pattern(4) hard-coded (6.1), lesson 08's white background pasted
(6.2, 6.3), the channels averaged together and the background as an (S + 1)-th share (6.2) got
only the rule (HN).

The variants (each named right in its first explanation) are ``student_variants.R482``; the
correct ones ``R482_RIGHT``.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R482, R482_RIGHT
from variant_checks import assert_first_named, assert_passes

from teachraster.core.edges import edge_function
from teachraster.exercises.antialiasing import expected_fraction
from teachraster.exercises.checks import exercise

#: WP1: a sample on a right edge, its offset of 9 decimals (x = 2 + 1/512)
NINE = ([[2, 0], [2 + 1 / 256, 2], [0, 1]], (1, 2), [[1 / 512, 0]])
#: WP2: a 1880 px sliver whose area is 0 in float32, a sample on its top-left edge
SLIVER32 = ([[0, 0], [700, 940], [1400.01171875, 1880.015625]], (47, 35), [[0, 0]])


def _fixed(args) -> bool:
    xy, pixel, samples = (np.array(args[0], float), args[1], np.array(args[2], float))
    cases = [a for _, a, _ in exercise("coverage_fraction").cases()]
    return any(
        np.array_equal(a[0], xy) and a[1] == pixel and np.array_equal(a[2], samples) for a in cases
    )


def test_the_two_new_cases_are_fixed_and_what_they_claim():
    xy, pixel, samples = (np.array(NINE[0], float), NINE[1], np.array(NINE[2], float))
    assert expected_fraction(xy, pixel, samples) == 0.0  # on a right edge: not covered
    moved = np.round(samples + [pixel[1], pixel[0]], 6)
    assert float(edge_function(xy[0], xy[1], moved[0])) != 0
    xy = np.array(SLIVER32[0], float)
    assert float(edge_function(*xy)) == -0.078125
    a, b, c = xy.astype(np.float32)
    assert (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) == 0  # in float32
    assert expected_fraction(xy, SLIVER32[1], np.array(SLIVER32[2], float)) == 1.0
    assert _fixed(NINE) and _fixed(SLIVER32)


@pytest.mark.parametrize("label", list(R482))
def test_each_variant_is_named_on_every_failure(label):
    assert_first_named(*R482[label], every_failure=True)


@pytest.mark.parametrize("label", list(R482_RIGHT))
def test_each_correct_variant_passes(label):
    assert_passes(*R482_RIGHT[label])
