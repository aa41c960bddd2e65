"""Review r506 (exercise 3 read again after r495): W1 zero-area tests relative to the
triangle's size passed 3.1 (a sliver 283 000 px long is graded now); W2 ``det`` of a 2×2 system
or its solve's LinAlgError as the test passed (a collinear case no 2×2 elimination ends on 0);
W3 3.1 handed on to bary_repair's functions passed uncounted; M1 ``xs, ys = xy`` (Python's
unpacking ValueError) was told "a placeholder"; H1 one weight over |E| or its size told the
rule only; T1 the shipped code's report gave both repairs. The students are in
``student_variants.R506``; here, each is checked once.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import KINDS, R506

from teachraster import exercises as ex
from teachraster.exercises import bary_repair as br
from teachraster.exercises import interpolation as interp


@pytest.mark.parametrize("label", sorted(R506))
def test_each_slip_fails_named_in_its_first_explanation(label):
    name, fn, words, kind = R506[label]
    report = ex.check(name, fn)
    assert not report.passed, f"{label}: {report}"
    first = report.failures[0]
    assert words in first.explanation, f"{label}: {first.explanation}"
    assert first.kind == kind == KINDS[label], (label, first.kind)


def test_the_long_sliver_is_exact_and_any_solve_gets_it():
    """W1: E = 2^-16 over 283 000 px; p = v2, which every solve gets exactly."""
    label, xy, p = next(c for c in interp.THIN_FAR if "283 000 px long" in c[0])
    v = np.asarray(xy)
    assert br._e(*v) == 2.0**-16
    assert np.array_equal(br.exact_weights(xy, p), [0.0, 1.0, 0.0])
    assert np.array_equal(np.linalg.solve(np.vstack([v.T, np.ones(3)]), [*p, 1.0]), [0, 1, 0])
    assert max(np.hypot(*(v - np.roll(v, 1, axis=0)).T)) > 2.8e5


def test_no_2x2_elimination_of_the_new_collinear_case_ends_on_zero():
    """W2: every vertex, either order of the edges, columns or rows: det ≠ 0 though E == 0."""
    label, xy, _ = next(c for c in interp.DEGENERATE if "no 2×2 elimination" in c[0])
    v = np.asarray(xy)
    assert br._e(*v) == 0
    for k in range(3):
        i, j = (n for n in range(3) if n != k)
        for a, b in ((i, j), (j, i)):
            m = np.column_stack([v[a] - v[k], v[b] - v[k]])
            assert np.linalg.det(m) != 0 and np.linalg.det(m.T) != 0


def test_the_checkers_repair_is_not_counted_in_3_1():
    """W3: a wrapper of bary_repair's (or bary_shipped's) patched_barycentric, or of its
    exact weights, is not counted."""
    from teachraster.exercises import bary_shipped

    def wrapped(xy, p):
        return br.patched_barycentric(xy, p, br.DEFECTS)

    def shipped_module(xy, p):
        return bary_shipped.patched_barycentric(xy, p, br.DEFECTS)

    def exact(xy, p):
        if br._e(*np.asarray(xy, float)) == 0:
            raise ValueError("zero area")
        return br.exact_weights(xy, p)

    for fn in (wrapped, shipped_module, exact):
        report = ex.check("barycentric", fn)
        assert not report.passed and "not counted" in str(report), str(report)


def test_a_3_1b_search_through_patched_barycentric_is_not_counted():
    """W3's twin in 3.1b: patched_barycentric moved to bary_shipped, still the judge's."""
    from teachraster.exercises.bary_shipped import patched_barycentric

    def defect_case(defect):
        other = "area" if defect == "zero-area test" else "zero-area test"
        for d in (0.0, 20000.0):
            for xy in ([[d, d], [d + 2, d], [d, d + 2]], [[d, d], [d, d + 2], [d + 2, d]]):
                p = (d + 0.5, d + 0.5)
                try:
                    patched_barycentric(xy, p, (defect,))
                    bad = patched_barycentric(xy, p, (other,))[0] < 0
                except ValueError:
                    bad = defect == "zero-area test"
                if bad:
                    return xy, p
        return None

    report = ex.check("defect_case", defect_case)
    assert not report.passed and "not counted" in str(report), str(report)


def test_a_value_error_of_the_students_own_raise_is_still_a_refusal():
    """M1's fix reads only ValueErrors raised on a line with no ``raise``: the task's test
    (``if E == 0: raise ValueError``) refuses a zero-area triangle, as before."""
    label, xy, p = interp.DEGENERATE[0]
    assert interp.call_barycentric(R506["barycentric with |λ3|"][1], (np.array(xy), p)) == (
        interp.REFUSED
    )
    with pytest.raises(ValueError, match="not by a zero-area test of yours"):
        interp.call_barycentric(R506["barycentric reading xy's rows as x and y"][1],
                                (np.array(xy), p))  # fmt: skip
