"""Exercise 3.1b ``defect_case`` (r488, issue 30: 3.1 was lesson 03 §1 transcribed, r455 T1).

Exercise 3 ships a ``barycentric`` with two defects (a ``np.linalg.cond`` zero-area test,
``abs(E)``); 3.1 repairs it, 3.1b returns a case for each defect alone. The three students'
answers are in ``r488_variants``.
"""

from __future__ import annotations

import inspect
import json
import time
from pathlib import Path

import numpy as np
import pytest
import r488_variants as v

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import bary_repair as br
from teachraster.exercises import interpolation

NOTEBOOK = Path(__file__).resolve().parent.parent / "notebooks/exercises/03_interpolation.ipynb"


def _cells():
    return json.loads(NOTEBOOK.read_text())["cells"]


def _cell(grade_id):
    return next(c for c in _cells() if c["metadata"]["nbgrader"]["grade_id"] == grade_id)


def _notebook_shipped():
    scope = {"np": np}
    exec("".join(_cell("shipped_barycentric")["source"]), scope)
    return scope["shipped_barycentric"]


def test_the_notebook_ships_the_checkers_shipped_code():
    """One place for the shipped code: the locked cell is the module's function, word for word,
    and its threshold is the checker's."""
    source = inspect.getsource(br.shipped_barycentric).rstrip("\n")
    assert "".join(_cell("shipped_barycentric")["source"]) == source
    assert f"> {br.COND_LIMIT:.0e}".replace("e+0", "e") in source
    ship = _notebook_shipped()
    with pytest.raises(ValueError):
        ship(*v.FAR_CCW)
    for case in (v.NEAR_CW, v.NEAR_CCW):
        np.testing.assert_array_equal(ship(*case), br.outcome(case, ()))


@pytest.mark.parametrize("label", sorted(v.CORRECT))
def test_a_correct_case_passes(label):
    report = ex.check("defect_case", v.CORRECT[label])
    assert report.passed, str(report)


@pytest.mark.parametrize("label", sorted(v.WRONG))
def test_a_wrong_case_fails_and_its_first_failure_names_its_cause(label):
    fn, kind = v.WRONG[label]
    report = ex.check("defect_case", fn)
    assert not report.passed
    assert report.failures[0].kind == kind, (label, str(report))
    assert "float32" not in str(report)


@pytest.mark.parametrize("label", sorted(v.STUBS))
def test_a_stub_fails_as_a_stub(label):
    fn, words = v.STUBS[label]
    report = ex.check("defect_case", fn)
    assert not report.passed and words in str(report), str(report)


def test_every_kind_is_met_by_a_students_answer():
    assert {kind for _, kind in v.WRONG.values()} == set(br.KINDS)


def test_the_teachers_answer_passes_and_the_checks_cost_little():
    scope = {"np": np}
    exec("".join(_cell("defect_case_solution")["source"]), scope)
    start = time.process_time()
    assert ex.check("defect_case", scope["defect_case"]).passed
    report = ex.check("defect_case", v.WRONG["A: the far clockwise one for both"][0])
    assert not report.passed
    assert time.process_time() - start < 1.0


def test_exact_weights_agree_with_the_package():
    """The exact (fraction) weights against tr.barycentric, on the students' cases and the
    check's own triangles."""
    cases = [fn(d) for fn in v.CORRECT.values() for d in br.DEFECTS]
    cases += [args for _, args, _ in interpolation.barycentric_cases()
              if not isinstance(_, str) and abs(br._e(*np.asarray(args[0], float))) >= 1]  # fmt: skip
    for xy, p in cases:
        xy, p = np.asarray(xy, float), np.asarray(p, float)
        np.testing.assert_allclose(br.exact_weights(xy, p), tr.barycentric(xy, p), atol=1e-6)


def _notebook_repaired(repaired):
    """The notebook's shipped code with the defects in ``repaired`` repaired (a copy of the
    student's kind: br.patched_barycentric is the checker's own code, not counted since r506)."""
    source = "".join(_cell("shipped_barycentric")["source"])
    if "zero-area test" in repaired:
        source = source.replace(
            "if np.linalg.cond(m) > 1e8:",
            "if (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - "
            "v[0][0]) == 0:",
        )
    if "area" in repaired:
        source = source.replace("area = abs(e(v[0], v[1], v[2]))", "area = e(v[0], v[1], v[2])")
    scope = {"np": np}
    exec(source, scope)
    return scope["shipped_barycentric"]


def test_the_shipped_code_fails_3_1_with_both_defects_named():
    """3.1's check on the shipped code names both defects (r506 T1: by their symptoms and the
    task's questions, not the repair); repaired, it passes 3.1; with one defect, it fails."""
    text = str(ex.check("barycentric", _notebook_shipped()))
    assert "np.linalg.cond(M) > 1e8" in text and "abs(E(v1, v2, v3))" in text, text
    assert "Divide by the signed" not in text and "E == 0" not in text, text
    assert "other winding" not in text and "not whether the area is 0" not in text, text
    report = ex.check("barycentric", _notebook_repaired(br.DEFECTS))
    assert report.passed, str(report)
    for one in br.DEFECTS:
        report = ex.check("barycentric", _notebook_repaired((one,)))
        assert not report.passed


def test_no_lesson_answers_the_task():
    """No lesson reads a condition number or divides by abs(E) (r488: the task is to find why)."""
    for path in sorted((NOTEBOOK.parent.parent).glob("*.ipynb")):
        text = "".join("".join(c["source"]) for c in json.loads(path.read_text())["cells"])
        assert "linalg.cond" not in text and "abs(E)" not in text, path.name
