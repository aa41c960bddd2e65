"""Review r348 (exercise 03 read afresh): a thin triangle 100 000 px out refused by a condition
number or a relative threshold passed 3.1 (item 1, the corpus's R348 block names them); 3.2's
solution and ``perspective_weights(..., extrapolate=True)`` gave NaN for λ = (0, ½, ½),
w = (1e-310, 1e300, 1e300) (F1); the words of two new 3.2 slips that give the repair away are
hints on a first try (P1).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import perspective_weighting as pw
from teachraster.exercises import tries

NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/03_interpolation.ipynb"
EDGE = (np.array([0.0, 0.5, 0.5]), np.array([1e-310, 1e300, 1e300]))


def _cell(grade_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    return "".join(
        next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == grade_id)["source"]
    )


def test_weights_on_the_edge_opposite_a_tiny_w_are_finite():
    """F1: scaled by the smallest w, every term underflowed to 0 and 0/0 gave NaN; the
    package and the notebook's solution now scale by the smallest w that weighs."""
    lam, w = EDGE
    for extrapolate in (False, True):
        mu = tr.perspective_weights(lam[None], w, extrapolate=extrapolate)[0]
        np.testing.assert_array_equal(mu, [0.0, 0.5, 0.5])
    space: dict = {"np": np}
    exec(_cell("perspective_weights_solution"), space)  # the teacher's 3.2
    np.testing.assert_array_equal(space["perspective_weights"](lam, w), [0.0, 0.5, 0.5])
    text = " ".join(_cell("task_3_2").split())
    assert "λ = (0, 0.5, 0.5), w = (1e-310, 1e300, 1e300)" in text, text
    assert "the check also asks it of those extreme w" in text, text  # r421 T2: graded
    report = ex.check("perspective_weights", space["perspective_weights"])
    assert report.passed, str(report)


def test_the_new_3_2_slips_are_hinted_on_a_first_try():
    def linear_w(lam, w):
        return lam / w * (lam @ w)

    def by_max(lam, w):
        return (lam / w) / np.max(lam / w)

    for fn, full in ((linear_w, pw.W_NOT_AFFINE), (by_max, pw.BY_THEIR_SUM)):
        tries.forget_hints("perspective_weights")
        try:
            first = str(ex.check("perspective_weights", fn))
        finally:
            tries.spend_hints(["perspective_weights"])
        assert full not in first and "a hint only" in first, first
