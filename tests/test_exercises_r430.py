"""r430, exercise 10.1 (``edge_bits``): F1, ``round(log2(across))`` passed every case (each odd
``across`` lay in the top of its binade): ranges in the bottom half fail it, and it is named;
a count from the largest values, one bit tighter there, passes. F2: the three-term sum
counted as two bits is named beside "each factor one bit wide". F3: a sign bit per factor in
both forms is named; a one-form count slip beside another says what it does, not a total it
is not; a doubled across is named. F5/F6: 10.2 points to the tie rule without naming the fix,
10.1 to lesson 02's count; the figure has no empty half."""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib
import pytest
from student_variants import R430_EDGE_BITS, R430_EDGE_BITS_DIFFERENT

from teachraster import exercises as ex
from teachraster.exercises import edge_bits as eb
from teachraster.exercises import tries

matplotlib.use("Agg")

NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb"


def _check(fn):
    tries.forget_hints("edge_bits")
    try:
        return ex.check("edge_bits", fn)
    finally:
        tries.forget_hints("edge_bits")


def _bottom(args) -> bool:
    r, a, s = args
    return a * 2**s - 1 < 2 ** ((a - 1).bit_length() + s - 0.5)


def test_some_ranges_lie_in_the_bottom_half_of_their_binade_and_rounding_changes_a_type():
    bottom = [args for args in eb.RANGES if _bottom(args)]
    assert len(bottom) >= 3
    nearest = [eb.KNOBS.gives(*a, exponent="across rounded to nearest") for a in bottom]
    assert all(n != eb.answer(*a) for n, a in zip(nearest, bottom))
    assert any(n[1][1] != eb.answer(*a)[1][1] for n, a in zip(nearest, bottom))
    # the ranges before them are unchanged, so every earlier slip fails where it did
    assert eb.RANGES[:12] == ((20, 1024, 8), (16, 64, 4), (10, 16, 8), (11, 256, 4),
                              (18, 512, 8), (23, 2048, 8), (24, 4096, 8), (8, 8, 2),
                              (12, 32, 1), (16, 200, 8), (20, 1000, 8), (12, 100, 4))  # fmt: skip


@pytest.mark.parametrize("label", list(R430_EDGE_BITS))
def test_each_r430_variant_fails_and_is_named_in_its_first_words(label):
    _, fn, words, kind = R430_EDGE_BITS[label]
    report = _check(fn)
    assert not report.passed
    first = report.failures[0]
    assert words in first.explanation, first.explanation
    assert first.kind == kind, (first.kind, first.explanation)


@pytest.mark.parametrize("label", list(R430_EDGE_BITS_DIFFERENT))
def test_a_count_from_the_largest_values_passes_where_it_is_one_bit_tighter(label):
    assert _check(R430_EDGE_BITS_DIFFERENT[label][1]).passed
    assert eb.tight(16, 130, 8)[1][0] == eb.answer(16, 130, 8)[1][0] - 1


def test_floor_and_rounding_to_nearest_are_told_apart():
    floor = _check(lambda r, a, s: eb.KNOBS.gives(r, a, s, exponent="across rounded down"))
    nearest = _check(lambda r, a, s: eb.KNOBS.gives(r, a, s, exponent="across rounded to nearest"))
    assert floor.failures[0].kind == "across's exponent rounded down"
    assert nearest.failures[0].kind == "across's exponent rounded to nearest"
    assert "rounds across's exponent down" in floor.failures[0].explanation
    assert {f.kind for f in floor.failures} == {"across's exponent rounded down"}


def test_a_one_form_slip_beside_another_says_what_it_does_not_a_total():
    """x3: floored and one short: 31 is three bits short of 34, never "one bit short"."""
    fn = R430_EDGE_BITS["edge bits, the relative form floored and by E's own bound (r430 x3)"][1]
    report = _check(fn)
    both = [f for f in report.failures if "and" in f.kind]
    assert both, [f.kind for f in report.failures]
    for f in both:
        assert "is one bit short" not in f.explanation, f.explanation
        assert "leaves out one bit" in f.explanation, f.explanation
        assert f.explanation.count("count is right)") <= 1, f.explanation


def test_the_tasks_point_to_lesson_02s_count_and_to_the_tie_rule():
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
             for c in json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]}  # fmt: skip
    assert "lesson 02's bit count\n(section 5b)" in cells["edge_bits_task"]
    task = cells["robust_fill_task"]
    assert "teachraster row of lesson\n07's table" in task and "half-way" in task
    lesson07 = json.loads((NOTEBOOK.parents[1] / "07_hard_cases.ipynb").read_text("utf-8"))
    assert any("| teachraster |" in "".join(c["source"]) and "round half to even" in
               "".join(c["source"]) for c in lesson07["cells"])  # fmt: skip


def test_the_figure_has_no_empty_right_half():
    import matplotlib.pyplot as plt

    case = eb.cases()[0]
    fig, ax = plt.subplots(figsize=(7, 4))
    eb.draw(ax, case, ((58, "int64"), (37, "float64")))
    assert ax.get_xlim()[1] < 2.2
    labels = [t.get_text() for t in ax.texts]
    plt.close(fig)
    assert "yours: 37 bits (wrong)\nfloat64" in labels, labels
