"""r341 (exercise 12, the capstone, a fresh read) X-1: a right trilinear that passes its wrap on
to a bilinear that ignores it was told "wrap not passed on" (12.8); whether trilinear reads its
``wrap`` tells the two causes of every level tiled apart, in the capstone as in exercise 7 (the
corpus carries both: tests/student_variants.py)."""

from __future__ import annotations

import pytest
import student_variants as sv
from test_capstone import _mine

from teachraster import exercises as ex
from teachraster.exercises.package_answers import parameters_read


@pytest.mark.parametrize("trilinear, said, unsaid", [
    (sv.trilinear_on_a_tiling_bilinear, "the bilinear it calls tiles whatever", "pass trilinear's"),
    (sv.trilinear_wrap_not_passed, "pass trilinear's `wrap` on", "the bilinear it calls"),
])  # fmt: skip
def test_the_capstone_blames_the_piece_that_tiles(trilinear, said, unsaid):
    report = ex.capstone("floor_trilinear", **_mine("floor_trilinear", trilinear=trilinear))
    assert not report.passed
    words = str(report)
    assert said in words and unsaid not in words, words


def test_a_parameter_is_read_in_a_nested_function_or_a_star_argument():
    def nested(pyramid, uv, lod, wrap="repeat"):
        return lambda: (pyramid, wrap)

    def starred(*args, **kwargs):
        return kwargs

    assert parameters_read(nested) == {"pyramid", "wrap"}
    assert parameters_read(starred) == {"kwargs"}
    assert parameters_read(print) == frozenset()  # no Python code: nothing known
