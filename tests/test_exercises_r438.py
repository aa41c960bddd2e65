"""r438 (exercise 1): a tolerance on the distance to the edge's line, a bias on the edges that
do not own their ties, λ3 = 1 − λ1 − λ2, the winding in float32 and a fill whose rows are one
list object, each named (the variants: student_variants.R438, run by test_checker_corpus)."""

import numpy as np
from student_variants import R438

from teachraster import exercises as ex
from teachraster.exercises import sample_steps as st
from teachraster.exercises.coverage_checks import (
    _expected,
    covers_cases,
    fill_cases,
    long_near_ties,
)
from teachraster.exercises.near_ties import SLIVER32, sliver32_case, winding32_images


def test_the_sliver_is_dropped_by_float32_alone():
    case = sliver32_case()
    (xy,) = case.triangles
    expected = _expected(case)
    assert expected.sum() == 1 and expected[0, 5, 2]  # v3 = (2.5, 5.5), a centre
    v = xy.astype(np.float32)
    e32 = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
    assert e32 == 0 and not winding32_images(case, expected).any()
    for cases in (covers_cases(), fill_cases()):
        assert cases[-1][0].startswith(SLIVER32) or any(c[0].startswith(SLIVER32) for c in cases)


def test_distance_bias_and_products_tolerances_differ_on_the_long_near_ties():
    case = long_near_ties()
    images = {
        "distance": [st.image(case, xy, rel=1e-8, length=True) for xy in case.triangles],
        "bias": [
            st.image(case, xy, rel=2e-5, absolute=True, one_sided=True) for xy in case.triangles
        ],  # fmt: skip
        "products": [st.image(case, xy, rel=1e-9) for xy in case.triangles],
    }
    wrong = {k: tuple(int((a != e).sum()) for a, e in zip(v, _expected(case)))
             for k, v in images.items()}  # fmt: skip
    assert len(set(wrong.values())) == 3, wrong
    assert all(sum(w) for w in wrong.values()), wrong


def test_the_new_slips_are_named_first():
    for label in ("covers with a bias of 1e-4 px² on the edges that do not own their ties "
                  "(r438 M3)", "fill by [[False] * width] * height (r438 M4)"):  # fmt: skip
        name, fn, words, kind = R438[label]
        report = ex.check(name, fn)
        first = report.failures[0]
        assert words in first.explanation and first.kind == kind, first.explanation
        assert "float32" not in first.explanation
