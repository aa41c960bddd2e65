"""r394, exercise 10 (robust_fill): a cause is said only where it holds. A zero-area triangle
covered is told its zero area, not "covers every pixel"; "you read origin as (x, y)" and
"E > 0" are said only where they give every answer; the "must flip the sign" advice only where
the answer is that of a function that never orients; a (width, height) early return is told
its shape, not a transpose. T1: exercise 10.1, ``edge_bits``, asks the precision argument as
numbers (the bits E needs in either form, and the type that holds them), before any text that
answers it."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from student_variants import (
    R386,
    R394,
    R394_EDGE_BITS,
    R394_EDGE_BITS_DIFFERENT,
    R409_EDGE_BITS,
    R416_EDGE_BITS,
    R416_EDGE_BITS_DIFFERENT,
)

from teachraster import exercises as ex
from teachraster.exercises import edge_bits as eb
from teachraster.exercises import hard_case_fill as hcf
from teachraster.exercises import hard_case_precision as hcp
from teachraster.exercises import tries


@pytest.mark.parametrize("label", list(R394))
def test_each_variant_gets_its_words_and_never_a_cause_it_lacks(label):
    fn, words, kind, never = R394[label]
    report = ex.check("robust_fill", fn)
    assert not report.passed
    assert words in report.failures[0].explanation, str(report)
    assert report.failures[0].kind == kind, str(report)
    assert all(never not in f.explanation for f in report.failures), str(report)


def test_the_flip_advice_is_said_to_a_function_that_never_orients():
    def unoriented(xy, width, height, origin=(0, 0)):
        v = np.rint(np.asarray(xy, dtype=float) * 256) / 256
        rows = origin[0] + np.arange(height)[:, None] + 0.5
        cols = origin[1] + np.arange(width)[None, :] + 0.5
        inside = np.ones((height, width), dtype=bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = (b[0] - a[0]) * (rows - a[1]) - (b[1] - a[1]) * (cols - a[0])
            own = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            inside &= (e >= 0) if own else (e > 0)
        return inside

    report = ex.check("robust_fill", unoriented)
    assert not report.passed
    assert any(hcf.FLIP_ADVICE in f.explanation for f in report.failures), str(report)


def test_a_width_height_early_return_is_told_its_shape_not_a_transpose():
    report = ex.check("robust_fill", R386["fill returning (width, height) for zero area"][0])
    text = report.failures[0].explanation
    assert "your image has shape (8, 4), (width, height) (an early return" in text, text
    assert "no .T" not in text and "transposed" not in text, text


# -- T1: exercise 10.1, edge_bits ----------------------------------------------------------------
NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb"


def _cells() -> dict[str, str]:
    nb = json.loads(NOTEBOOK.read_text(encoding="utf-8"))
    return {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in nb["cells"]}


def _teacher():
    namespace = {"np": np}
    source = _cells()["edge_bits_solution"]
    exec(source.replace("### BEGIN SOLUTION", "").replace("### END SOLUTION", ""), namespace)
    return namespace["edge_bits"]


def test_the_teachers_edge_bits_passes_and_its_answer_comes_from_lesson_06s_count():
    from teachraster.core.fixed_point import range_budget

    fn = _teacher()
    assert ex.check("edge_bits", fn).passed
    (ab, at), (rb, rt) = fn(20, 1024, 8)
    assert (ab, rb) == (range_budget(2**20, 8).needed, range_budget(1024, 8).needed)
    assert (at, rt) == (hcp.narrowest(ab), hcp.narrowest(rb)) == ("int64", "float64")
    # the ranges differ in every part, so that a typed answer fails
    answers = [eb.answer(*args) for args in eb.RANGES]
    assert len({a for a, _ in answers}) > 5 and len({t for a in answers for _, t in a}) == 5


@pytest.mark.parametrize("label", list(R394_EDGE_BITS_DIFFERENT))
def test_edge_bits_written_differently_passes(label):
    assert ex.check("edge_bits", R394_EDGE_BITS_DIFFERENT[label][1]).passed


@pytest.mark.parametrize("label", list(R394_EDGE_BITS))
def test_each_edge_bits_slip_is_named_with_its_numbers(label):
    _, fn, words, kind = R394_EDGE_BITS[label]
    tries.forget_hints("edge_bits")
    report = ex.check("edge_bits", fn)
    assert not report.passed
    first = report.failures[0]
    assert words in first.explanation and first.kind == kind, str(report)
    assert "float32" not in first.explanation, first.explanation  # never a precision diagnosis


def test_the_worked_count_is_said_once_two_answers_have_failed():
    tries.forget_hints("edge_bits")
    first = ex.check("edge_bits", lambda r, a, s: ((r + s, "int64"), (a, "float64")))
    assert "(worked:" not in str(first) and "a product's bits are" not in str(first)
    second = ex.check("edge_bits", lambda r, a, s: ((r + s + 1, "int64"), (a, "float64")))
    text = str(second)
    # r416 F4: the worked range is one the check does not use (lesson 06's Direct3D 16.8)
    assert eb.WORKED not in eb.RANGES
    assert "(worked: the absolute form's coordinates are below 2^24 steps" in text, text
    assert "50 bits with the sign: a 64-bit float" in text, text
    assert "58 bits with the sign" not in text, text
    tries.forget_hints("edge_bits")


def test_edge_bits_asks_before_any_text_answers_and_gives_the_facts_not_the_count():
    cells = _cells()
    order = list(cells)
    assert order.index("edge_bits_task") < order.index("robust_fill_task")
    task = cells["edge_bits_task"]
    for fact in (
        "1/2^s px",
        "2^`range_bits` px",
        "`across` px",
        "2²⁰ px, 1,024 px across",
        "8 sub-pixel bits",
        "sign bit included",
        "term by term",
        "several ranges",
    ):
        assert fact in task, fact
    for answer in ("58", "38", "2k + 2", "54", "25 bits", "nmant"):
        assert answer not in task, answer
    # the 10.2 task (and the naive fill's report before it) say no count of bits
    assert "bits" not in cells["naive_text"] and "bits" not in cells["robust_fill_task"]
    assert "### BEGIN SOLUTION" in cells["edge_bits_solution"]
    assert 'ex.check("edge_bits", edge_bits)' in cells["edge_bits_check"]


def test_lesson_06s_count_called_is_not_counted():
    from teachraster.core.fixed_point import range_budget

    def edge_bits(range_bits, across, sub_bits):
        out = []
        for limit in (2**range_bits, across):
            n = range_budget(limit, sub_bits).needed
            out.append((n, hcp.narrowest(n)))
        return tuple(out)

    report = ex.check("edge_bits", edge_bits)
    assert not report.passed and report.package is not None, str(report)
    assert not report.failures, str(report)  # right on every case, but not counted


# -- r409: a None is never NaN (F1), types only (F2), C's names (F3), one count slip (F4) -------
@pytest.mark.parametrize("label", list(R409_EDGE_BITS))
def test_r409_edge_bits_variants_are_named_and_never_told_nan(label):
    _, fn, words, kind = R409_EDGE_BITS[label]
    tries.forget_hints("edge_bits")
    report = ex.check("edge_bits", fn)
    assert not report.passed
    first = report.failures[0]
    assert words in first.explanation and first.kind == kind, str(report)
    assert "NaN" not in str(report), str(report)
    tries.forget_hints("edge_bits")


def test_a_types_only_mistake_never_gets_the_counting_hint():
    tries.forget_hints("edge_bits")
    text = str(ex.check("edge_bits", R409_EDGE_BITS["edge bits with > for >="][1]))
    assert "count in steps" not in text and "your counts are right" in text, text
    assert "(recipe:" not in text, text  # the table of what each type holds waits for the hints
    tries.forget_hints("edge_bits")


@pytest.mark.parametrize("name", ["float", "int", "double", "long", "Float", "np.double"])
def test_c_type_names_are_refused_with_the_names_accepted(name):
    with pytest.raises(Exception, match=r"\(C's \w+ is .*: say "):
        eb.as_answer(((58, name), (38, "float64")))


@pytest.mark.parametrize(
    "name", ["float32", "NP.INT64", np.float64, np.dtype("int32"), np.dtype("int64"), "None"]
)
def test_the_four_names_numpy_types_and_none_are_accepted(name):
    assert eb.as_answer(((58, name), (38, None)))[1] == (38, None)


def test_the_full_words_work_one_range_only():
    tries.forget_hints("edge_bits")
    ex.check("edge_bits", lambda r, a, s: ((r + s, "int64"), (a, "float64")))
    text = str(ex.check("edge_bits", lambda r, a, s: ((r + s + 1, "int64"), (a, "float64"))))
    assert text.count("(worked: the absolute form's") == 1, text
    assert "a product's bits are its factors' added" in text, text
    tries.forget_hints("edge_bits")


def test_10_2s_float32_words_say_the_sign_as_10_1_counts_it():
    xy, (row, col) = next(iter(hcp.FLOAT32_CASES.values()))
    expected = np.zeros((4, 4), dtype=bool)
    got = expected.copy()
    got[0, 0] = True
    words = hcp.float32_words((xy, 4, 4, (row, col)), expected, got)
    assert "which holds 24 bits and a sign (25 with it, 10.1's count)" in words, words
    assert "53 bits and a sign" in words, words


def test_an_endless_edge_bits_is_told_microseconds_not_pixels():
    def edge_bits(range_bits, across, sub_bits):
        while True:
            pass

    text = str(ex.check("edge_bits", edge_bits))
    assert "it should take microseconds" in text and "per pixel" not in text, text


def test_the_figure_greys_a_right_part_and_marks_a_wrong_one_red():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    case = next(c for c in eb.cases() if c[1] == (24, 4096, 8))
    fig, ax = plt.subplots()
    eb.draw(ax, case, ((66, None), (68, None)))
    colours = [line.get_color() for line in ax.lines if line.get_marker() == "x"]
    assert colours == ["#888888", "#d7301f"], colours
    texts = [t.get_text() for t in ax.texts]
    # r419 F1: the wrong one says which of its two parts is wrong, as the words do
    assert "yours: 66 bits\nNone (right)" in texts, texts
    assert "yours: 68 bits (wrong)\nNone (wrong)" in texts, texts
    plt.close(fig)


# -- r416: an int's sign (F1), count slips named per form (F2), numpy dtypes (F3) --------------
@pytest.mark.parametrize("label", list(R416_EDGE_BITS))
def test_r416_edge_bits_variants_are_named(label):
    _, fn, words, kind = R416_EDGE_BITS[label]
    tries.forget_hints("edge_bits")
    report = ex.check("edge_bits", fn)
    assert not report.passed
    first = report.failures[0]
    assert words in first.explanation and first.kind == kind, str(report)
    assert "count in steps of the grid" not in first.explanation, first.explanation
    tries.forget_hints("edge_bits")


def test_an_ints_sign_left_out_is_never_told_greater_than():
    """r416 F1: int32 as 31 bits and int64 as 63 fail at 32 and 64 bits only; > also fails at
    54 (float64's edge): each gets its own words."""
    tries.forget_hints("edge_bits")
    text = str(ex.check("edge_bits", R416_EDGE_BITS[
        "edge bits with an int's sign left out (int32 31, int64 63)"][1]))  # fmt: skip
    assert "compare with >=" not in text, text
    greater = str(ex.check("edge_bits", R409_EDGE_BITS["edge bits with > for >="][1]))
    assert "compare with >=, not >" in greater and "an int32 holds" not in greater, greater
    tries.forget_hints("edge_bits")


@pytest.mark.parametrize("label", list(R416_EDGE_BITS_DIFFERENT))
def test_r416_numpy_dtypes_pass(label):
    assert ex.check("edge_bits", R416_EDGE_BITS_DIFFERENT[label][1]).passed


@pytest.mark.parametrize("value", [np.dtype("int64"), np.int64, np.dtype("float32")])
def test_a_numpy_type_is_read_as_numpys_and_python_classes_get_their_own_aside(value):
    assert eb.as_answer(((58, value), (38, None)))[0][1] == np.dtype(value).name
    with pytest.raises(Exception, match="Python's int has no fixed width"):
        eb.as_answer(((58, int), (38, None)))
    with pytest.raises(Exception, match=r"C's long is 32 bits on Windows"):
        eb.as_answer(((58, "long"), (38, None)))
