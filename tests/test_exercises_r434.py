"""r434, exercise 10.1 (``edge_bits``): F1, ⌈log2(across − 1)⌉ passed every case (no across of
2^k + 1 px): a range of 129 px fails it, listed last, and it is named; F2, a float taken to hold
``np.finfo(t).nmant`` bits is named apart from the sign alone. F4: the notebook says which of
10.2's cases are drawn afresh."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from student_variants import R434_EDGE_BITS

from teachraster import exercises as ex
from teachraster.exercises import edge_bits as eb
from teachraster.exercises import tries

NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb"


def _check(fn):
    tries.forget_hints("edge_bits")
    try:
        return ex.check("edge_bits", fn)
    finally:
        tries.forget_hints("edge_bits")


def test_an_across_of_a_power_of_two_plus_one_is_listed_last_and_changes_the_type():
    assert eb.RANGES[-1] == (16, 129, 4)
    assert eb.RANGES[:-1] == ((20, 1024, 8), (16, 64, 4), (10, 16, 8), (11, 256, 4),
                              (18, 512, 8), (23, 2048, 8), (24, 4096, 8), (8, 8, 2),
                              (12, 32, 1), (16, 200, 8), (20, 1000, 8), (12, 100, 4),
                              (16, 130, 8), (12, 20, 4), (18, 300, 8))  # fmt: skip
    assert eb.answer(16, 129, 4) == ((42, "float64"), (26, "int32"))
    assert eb.KNOBS.gives(16, 129, 4, exponent="across - 1's log2")[1] == (24, "float32")
    assert eb.tight(16, 129, 4)[1] == (25, "float32")  # one bit tighter, and exact: it passes


@pytest.mark.parametrize("label", list(R434_EDGE_BITS))
def test_each_r434_variant_fails_and_is_named_in_its_first_words(label):
    _, fn, words, kind = R434_EDGE_BITS[label]
    report = _check(fn)
    assert not report.passed
    assert {f.kind for f in report.failures} == {kind}, [f.kind for f in report.failures]
    assert words in report.failures[0].explanation, report.failures[0].explanation


def test_nmant_is_told_apart_from_the_sign_alone_where_a_count_lies_between():
    nmant = R434_EDGE_BITS["edge bits with a float holding np.finfo(t).nmant bits (r434 w13)"]
    report = _check(nmant[1])
    assert "edge_bits(12, 100, 4)" in " ".join(f.case for f in report.failures)
    for f in report.failures:
        assert "hidden" in f.explanation and "significand's bits only" not in f.explanation


def test_the_notebook_says_which_random_cases_are_drawn_afresh():
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
             for c in json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]}  # fmt: skip
    for grade_id in ("intro", "naive_text"):
        assert "drawn afresh" in " ".join(cells[grade_id].split()), grade_id
