"""Review r390 F1 and F8 (exercise 07): the four transcription tasks composed. 7.1 is the λ a GPU
uses at a pixel of a triangle (7.1's λ and 7.4's quad differences merged), 7.4 the whole
sampler from the student's own 7.1 and 7.3; neither task prints a step as a formula, each
named mistake's first words ask rather than give the rule, and the pass figures answer the
tasks' questions."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import reasoning_solutions as sol
import student_variants as sv

from teachraster import exercises as ex
from teachraster.exercises import pixel_level as pl
from teachraster.exercises import pixel_sampler as ps

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "07_texture_filtering.ipynb"


def _cells():
    return {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
            for c in json.loads(NOTEBOOK.read_text())["cells"]}  # fmt: skip


def test_the_composed_tasks_print_no_step_as_a_formula():
    text = _cells()
    for task in ("pixel_lod_task", "pixel_sample_task"):
        flat = text[task].replace("\n", " ")
        for formula in ("log2", "log₂", "row − row mod 2", "row % 2", "max(", "√", "hypot",
                        "upper right − upper left", "u·W", "⌊λ⌋"):  # fmt: skip
            assert formula not in flat, (task, formula)


def test_the_notebook_grades_four_points():
    """r491: 7.2's texel_weights (two points) stands in for bilinear and trilinear."""
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    graded = [c["metadata"]["nbgrader"] for c in cells if c["metadata"]["nbgrader"]["grade"]]
    assert [g["grade_id"] for g in graded] == ["pixel_lod_check", "texel_weights_check",
                                               "pixel_sample_check"]  # fmt: skip
    assert sum(g["points"] for g in graded) == 4


@pytest.mark.parametrize(
    "table, name",
    [(sv.R390_PIXEL_LOD, "pixel_lod"), (sv.R390_PIXEL_SAMPLE, "pixel_sample")],
)
def test_each_named_mistake_asks_first_and_keeps_the_steps(table, name):
    """F8: the first explanation names the mistake and asks; the steps (the rule) come only
    once two different answers have failed."""
    from teachraster.exercises import tries

    rule = {"pixel_lod": pl.RULE, "pixel_sample": ps.RULE}[name]
    for fn, _, kind in table.values():
        tries.forget_hints(name)
        first = ex.check(name, fn).failures[0]
        assert first.kind == kind
        assert rule not in first.explanation, (kind, first.explanation)
    tries.forget_hints(name)


def test_the_pass_figures_answer_the_questions(plt):
    for name, words in (
        ("pixel_lod", pl.lod_questions()[:60]),
        ("pixel_sample", "7.4: (27, 3) gets its quad's λ"),
    ):
        report = ex.check(name, sol.CORRECT[name])
        fig, ax = plt.subplots()
        report.plot(ax)
        assert report.passed and words in ax.get_xlabel().replace("\n", " "), ax.get_xlabel()
    said = pl.lod_questions()
    assert "(5, 14): λ = 6.635, the step down (ddy) decides" in said
    assert "(28, 14): λ = 3.267, the step right (ddx) decides" in said
    assert "clamped λ would be 1.525, smaller" in said


def test_the_sampler_cases_are_all_covered_pixels_and_the_tip_asks_above_the_pyramid():
    from teachraster.exercises.quad_difference import inside

    cases = ps.sample_cases()
    assert all(inside(a[1], a[5] + 0.5, a[4] + 0.5) for _, a, _ in cases)
    # r418 P2: the tip's level is 7.3's question; 7.4 asks where (27, 3) gets λ and (u, v)
    assert ps.expected_lod(*cases[2][1][1:4], (8, 8), 5, 14) > len(cases[2][1][0]) - 1
    said = ps.sample_questions(cases[2][1][0])
    assert "λ = 0.373, from the (u, v) of the three helpers alone" in said
    assert "(u, v) = (0.08, 0.105), not at a helper's (upper-left: (-0.142, 0.153))" in said
