"""Review r421 (exercise 3 read fresh): two wrong zero-area tests passed (W1 a rounded det,
W2 a matrix rank), a mistake was misnamed (N1 the vertices as (y, x), N2 a p outside
refused), six half-named (H1-H6), small slips of words (S1-S4), and 3.2 was lesson 04's
printed formula (T2: w beyond a GPU's range are graded again). The students themselves are
in ``student_variants.R421`` (run by test_checker_corpus.py); here, the cases and the words.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from student_variants import R421

from teachraster import exercises as ex
from teachraster.core.edges import edge_function
from teachraster.exercises import interpolation as ip
from teachraster.exercises import perspective_weighting as pw
from teachraster.exercises import tries
from teachraster.exercises.tolerance import TOL

NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/03_interpolation.ipynb"


def _cell(grade_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    cell = next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == grade_id)
    return " ".join("".join(cell["source"]).split())


def test_the_far_collinear_and_thin_cases_defeat_det_and_rank():
    """W1, W2: the class, on the check's own fixed cases: collinear on the grid with a nonzero
    LU determinant (|det| ≥ 1e-9), and thin but real with matrix_rank 2."""
    far_collinear = [xy for _, xy, _ in ip.DEGENERATE
                     if abs(np.linalg.det(np.vstack([np.array(xy).T, np.ones(3)]))) >= 1e-9]  # fmt: skip
    assert len(far_collinear) >= 2
    thin_rank = [xy for _, xy, _ in ip.THIN_FAR
                 if np.linalg.matrix_rank(np.vstack([np.array(xy).T, np.ones(3)])) < 3]  # fmt: skip
    assert len(thin_rank) >= 2
    for xy in thin_rank:
        assert float(edge_function(*np.array(xy))) != 0


def test_det_and_rank_tests_fail_named_in_the_first_explanation():
    for label in (
        "barycentric refused by |LU det| < 1e-9",
        "barycentric refused by matrix_rank < 3",
    ):
        name, fn, words, kind = R421[label]
        report = ex.check(name, fn)
        assert not report.passed and report.failures[0].kind == kind, str(report)
        assert words in report.failures[0].explanation, str(report)
        assert "expected 'raised ValueError'" not in report.failures[0].explanation


def test_a_p_outside_refused_is_never_called_a_growing_test():
    """N2: the third kind of the summary called the refusal "a test that grows with the
    coordinates"; every failure of that student is now the refusal of a p outside."""
    _, fn, _, _ = R421["barycentric refusing a p outside"]
    report = ex.check("barycentric", fn)
    assert {f.kind for f in report.failures} == {"refused p outside"}, str(report)
    assert "grows with the coordinates" not in str(report)


def test_the_hint_note_says_when_the_full_words_come():
    """S1: the second different failing answer gets the full words: the note says so."""
    assert "this one counted" in tries.HINT_ONLY
    tries.forget_hints("barycentric")
    try:
        first = ex.check("barycentric", lambda xy, p: np.roll(ip.barycentric(xy, p), 1))
        second = ex.check("barycentric", lambda xy, p: -ip.barycentric(xy, p))
    finally:
        tries.spend_hints(["barycentric"])
    assert tries.HINT_ONLY in str(first) and tries.HINT_ONLY not in str(second), str(second)


def test_the_rebuilt_point_prints_apart_from_p():
    """S2: "(40.5, 1.5), not p = (40.5, 1.5)" (a +1e-6 guard on the sliver pair, the rule's
    words)."""
    xy, p = np.array([[0.5, 1.5], [60.5, 1.5], [60.5, 1.49609375]]), np.array([40.5, 1.5])
    right = ip.barycentric(xy, p)
    area = float(edge_function(*xy))
    got = right * area / (area + 1e-6)
    got[2] = 1.0 - got[0] - got[1]
    words = ip._bary_rule((xy, p), right, got)
    rebuilt, point = words.split("λ1·v1 + λ2·v2 + λ3·v3 = ")[1].split(", not p = ")
    assert rebuilt != point, words


def test_the_tolerances_the_text_states_are_the_checks():
    """S4: cell 2 promised 1e-9; thin triangles far out are compared to 1e-6."""
    text = _cell("task_3_1")
    assert TOL == 1e-9 and ip.THIN_TOL == 1e-6
    assert "to 1e-9 (relative" in text and "; 1e-6 on the thin triangles" in text


def test_3_2_grades_w_beyond_a_gpu_and_the_teachers_solution_passes():
    """T2: the graded reasoning of 3.2; the teacher's solution passes, the two-line formula
    fails with its overflow named, the smallest w of all with its underflow."""
    assert any(pw.beyond_a_gpu(label) for label, _, _ in pw.weights_cases())
    space: dict = {"np": np}
    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    source = "".join(next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"]
                          == "perspective_weights_solution")["source"])  # fmt: skip
    exec(source, space)
    assert ex.check("perspective_weights", space["perspective_weights"]).passed
    for label in ("perspective weights as lesson 04 prints them, beyond a GPU's w",
                  "perspective weights scaled by the smallest w of all"):  # fmt: skip
        name, fn, words, kind = R421[label]
        report = ex.check(name, fn)
        assert {f.kind for f in report.failures} == {kind}, str(report)
        assert all(pw.beyond_a_gpu(f.case) for f in report.failures), str(report)
    assert "the check also asks it of those extreme w" in _cell("task_3_2")
    assert "not graded" not in _cell("task_3_2")
