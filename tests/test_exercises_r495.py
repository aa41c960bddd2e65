"""Review r495 (exercise 3 read again after r488's redesign of 3.1): W1 ``cond(M) > 1/ε``
passed 3.1 (a sliver 200 px long 100 000 px out is graded now); W2 a 3.1b search through the
checker's own ``verdict`` passed uncounted; M1/M2 3.1b's p a hair from v3; H1–H4 slips told
the rule only. The students are in ``student_variants.R495``; here, each is checked once.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from student_variants import DIFFERENT, KINDS, R495

from teachraster import exercises as ex
from teachraster.exercises import bary_repair as br
from teachraster.exercises import interpolation as interp

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "03_interpolation.ipynb"


def _cell(grade_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return "".join(next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == grade_id)
                   ["source"])  # fmt: skip


@pytest.mark.parametrize("label", sorted(R495))
def test_each_slip_fails_named_in_its_first_explanation(label):
    name, fn, words, kind = R495[label]
    report = ex.check(name, fn)
    assert not report.passed, f"{label}: {report}"
    first = report.failures[0]
    assert words in first.explanation, f"{label}: {first.explanation}"
    assert first.kind == kind == KINDS[label], (label, first.kind)


def test_no_explanation_says_abs_keeps_a_negative_e_or_p_is_v3_when_it_is_not():
    """M1, M2: the words of E < 0 near v3 say neither "abs(E) = E" nor "at p = v3"."""
    for label in ("defect_case, p 1/256 px from v3 of a huge clockwise triangle",
                  "defect_case, p 1/256 px from v3 100 000 px out"):  # fmt: skip
        text = ex.check("defect_case", R495[label][1]).failures[0].explanation
        assert "abs(E) = E" not in text and "at p = v3" not in text, text


def test_the_cond_words_no_longer_say_it_grows_with_the_distance():
    """H3 (and T1: 3.1b's reasoning): a centred matrix's cond grows with thinness alone."""
    for label in ("barycentric refusing cond(M) > 1/ε",
                  "barycentric refusing a centred matrix's cond > 1e8"):  # fmt: skip
        text = ex.check("barycentric", R495[label][1]).failures[0].explanation
        assert "distance from the origin" not in text, text


def test_the_new_sliver_is_exact_and_refused_by_cond_at_one_over_eps():
    """W1: λ = (1, 0, 0) exactly; cond above 1/ε; E = 2^-16 exact in float64."""
    label, xy, p = next(c for c in interp.THIN_FAR if "200 px long, 100 000 px out" in c[0])
    assert np.array_equal(br.exact_weights(xy, p), [1.0, 0.0, 0.0])
    assert br.cond(xy) > 1 / np.finfo(float).eps
    assert br._e(*np.asarray(xy)) == 2.0**-16


def test_a_search_through_the_checkers_judge_is_not_counted():
    """W2: ``verdict`` (the checker's own code) used to search a case: not counted."""

    def defect_case(defect):
        if defect == "area":
            return np.array([[0.0, 0], [0, 4], [4, 0]]), np.array([1.0, 1])
        d = 1.0
        while True:
            case = (np.array([[d, d], [d + 2, d], [d, d + 2]]), np.array([d + 0.5, d + 0.5]))
            if br.verdict(defect, case) is None:
                return case
            d *= 2

    report = ex.check("defect_case", defect_case)
    assert not report.passed and "not counted" in str(report), str(report)


def test_a_search_calling_the_notebooks_shipped_code_passes():
    """The notebook's locked cell is a tool: a search that calls it is the student's own."""
    scope = {"np": np}
    exec(_cell("shipped_barycentric"), scope)
    shipped = scope["shipped_barycentric"]

    def defect_case(defect):
        if defect == "area":
            return [[0.0, 0.0], [0.0, 4.0], [4.0, 0.0]], (1.0, 1.0)
        d = 16.0
        while True:
            xy, p = [[d, d], [d + 2, d], [d, d + 2]], (d + 0.5, d + 0.5)
            try:
                shipped(xy, p)
            except ValueError:
                return xy, p
            d *= 2

    report = ex.check("defect_case", defect_case)
    assert report.passed, str(report)


def test_the_range_is_per_coordinate_in_the_text_and_the_words():
    """W3: "within 100 000 px of the origin" let a vertex 141 000 px out pass."""
    assert "between −100 000 and 100 000" in _cell("task_3_1b")
    case = (np.array([[0.0, 0.0], [0.0, 4.0], [100000.00390625, 0.0]]), np.array([1.0, 1.0]))
    assert "outside −100,000 to 100,000 px" in br.verdict("area", case)[1]


def test_the_shipped_code_with_both_repairs_passes():
    name, fn = DIFFERENT["barycentric, the shipped code with E == 0 and the signed E (r495)"]
    assert ex.check(name, fn).passed
