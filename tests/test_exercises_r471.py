"""r471 (r454 T1): exercise 2.2, ``sample_span(xy, row, sample)``, the span at a sample point.

2.1's span is lesson 01's loop nearly whole; 2.2 asks for the columns whose sample point
(col + sx, row + sy) is covered, offsets from the pixel's top-left corner (CONVENTIONS.md,
*Multisampling*). Its expected columns are 2.1's of the moved triangle; here they are checked
against the package's own per-sample coverage, the cases against what they promise (each
standard position, ties on samples, a vertex between the sample line and the centre line),
and each named mistake against the others. The variants themselves (correct ones that pass,
wrong ones named) run in test_checker_corpus.py from student_variants.py (R471).
"""

from __future__ import annotations

import json
import math
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from reasoning_solutions import sample_span
from student_variants import R471

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import sample_spans as ss
from teachraster.exercises import tries

NOTEBOOK = (
    Path(__file__).resolve().parent.parent / "notebooks" / "exercises" / "02_span_split.ipynb"
)


def _index(sample) -> int:
    return [tuple(float(s) for s in p) for p in ss.STANDARD_4].index(tuple(sample))


def test_the_positions_are_the_packages_standard_four():
    assert np.array_equal(np.array(ss.STANDARD_4, dtype=float), tr.sample_pattern(4))


def test_expected_columns_are_the_packages_per_sample_coverage():
    """Every case's columns are those whose sample the package's 4× fill covers."""
    for label, (xy, row, sample), cols in ss.sample_span_cases():
        # r477: rows row - 2 to row + 2 only (the hair rows' triangles are 98 304 px tall)
        c0, r0, h = math.floor(xy[:, 0].min()) - 2, row - 2, 5
        w = math.ceil(xy[:, 0].max()) + 3 - c0
        fill = tr.rasterize(tr.Triangle(xy - np.array([c0, r0], float)), w, h, samples=4)
        covered = np.flatnonzero(fill.sample_coverage[row - r0, :, _index(sample)]) + c0
        assert frozenset(covered.tolist()) == cols, label


def test_cases_ask_each_position_ties_on_samples_and_vertices_between_the_lines():
    ties, between = set(), set()
    for _, (xy, row, sample), cols in ss.sample_span_cases():
        sx, sy = (Fraction(s) for s in sample)
        cross = ss.crossings(xy, row + sy)
        if cols and cross and any((x - sx).denominator == 1 for x in cross):
            ties.add(_index(sample))
        ys = [Fraction(float(y)) for y in xy[:, 1]]
        if any(min(row + sy, row + Fraction(1, 2)) < y < max(row + sy, row + Fraction(1, 2))
               for y in ys):  # fmt: skip
            between.add(_index(sample))
    assert ties == between == {0, 1, 2, 3}


def test_each_named_mistake_gives_answers_no_other_does():
    """Every wrong variant fails on some case where every other variant passes or differs
    from it: no two kinds are told apart by luck alone."""
    cases = ss.sample_span_cases()
    answers = {}
    for label, (_, fn, _, kind) in R471.items():
        if kind in ("tie lands off", "float32"):  # symptoms: a few rows only, by their numbers
            continue
        answers[label] = [ss.as_sample_span(fn(*args)) for _, args, _ in cases]
    for label, mine in answers.items():
        assert any(set(a) != set(e) for a, (_, _, e) in zip(mine, cases)), label
        for other, theirs in answers.items():
            if other != label:
                assert any(set(a) != set(b) for a, b in zip(mine, theirs)), (label, other)


def test_the_solution_passes_and_2_1s_span_is_named():
    assert ex.check("sample_span", sample_span).passed
    report = ex.check("sample_span", lambda xy, row, sample: _span21(xy, row))
    assert not report.passed and report.failures[0].kind == "2.1's span", str(report)


def _span21(xy, row):
    from reasoning_solutions import span

    return span(xy, row)


def test_the_first_try_does_not_print_the_rounding():
    tries.forget_hints("sample_span")
    fn = R471["sample span, sx added to the crossings"][1]
    report = ex.check("sample_span", fn)
    text = "\n".join(f.explanation for f in report.failures)
    assert "x_l − sx" not in text and "which columns' samples lie at or right of x_l" in text


@pytest.mark.parametrize("cell", ["task_2_2", "sample_span_solution", "sample_span_check"])
def test_the_notebook_asks_2_2_graded_after_2_1(cell):
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in cells]
    assert ids.index("span_check") < ids.index(cell)
    meta = cells[ids.index("sample_span_check")]["metadata"]["nbgrader"]
    assert meta["grade"] and meta["points"] == 1
    task = "".join(cells[ids.index("task_2_2")]["source"])
    assert "top-left corner" in task and "sample_pattern(4)" in task
    assert "− sx" not in task and "- sx" not in task and "⌈" not in task  # no formula to type
