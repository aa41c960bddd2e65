"""The checker tells the truth: no "passes" unless passed, None and text named as such."""

from __future__ import annotations

import itertools
import re

import numpy as np
import pytest
from conftest import sample
from endless_loops import forever

from teachraster import exercises as ex

NAMES = ex.names()


def returns(value):
    def fn(*args):
        return value

    return fn


def raises(exc):
    def fn(*args):
        raise exc

    return fn


def forgets_return(*args):
    total = 0
    for _ in args:
        total += 1  # computes something, returns nothing


BROKEN = {
    "raises": raises(ValueError("my bug")),
    "loops": forever,
    "returns None": returns(None),
    "forgets return": forgets_return,
    "returns text": returns("25.0"),
    "returns a dict": returns({"a": 1}),
    "exits": raises(SystemExit(1)),
}


@pytest.fixture
def axes():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(3, 3))
    yield ax
    fig.canvas.draw()  # every drawing renders
    plt.close(fig)


@pytest.mark.parametrize("name, how", sample(itertools.product(NAMES, BROKEN), keep=4))
def test_a_broken_function_never_gets_a_passing_title(name, how, axes):
    report = ex.check(name, BROKEN[how], budget=1.0)
    assert not report.passed
    artists = report.plot(axes)
    title = axes.get_title()
    assert title.startswith(name) and not re.search(r"\bpass", title), title
    texts = " ".join(a.get_text() for a in artists if hasattr(a, "get_text"))
    first = report.failures[0].explanation
    # the note says what happened: the explanation's opening, or (r153: 3.1's figure of a case
    # the function refused shows the triangle's E and "you raised ...") the exception itself
    said = first.split(":")[0][:30] in texts.replace("\n", " ")
    assert said or (how == "raises" and "you raised ValueError" in texts), (first, texts)
    if how in ("returns None", "forgets return"):
        assert "returned None" in title


@pytest.mark.parametrize("name", sample(NAMES))
def test_only_a_passing_report_is_titled_so(name, axes):
    from exercise_solutions import CORRECT
    from reasoning_solutions import CORRECT as ISSUE_30  # issue 30's exercises

    report = ex.check(name, {**CORRECT, **ISSUE_30}[name], budget=120)
    report.plot(axes)
    assert report.passed and "pass" in axes.get_title()


def test_a_report_stopped_without_failures_is_not_passed():
    report = ex.Report("depth_test", [], 30, stopped="ran out", n_run=3)
    assert not report.passed
    assert "stopped" in str(report)
    with pytest.raises(AssertionError):
        report.assert_passed()


@pytest.mark.parametrize("name", sample(NAMES))
def test_a_forgotten_return_is_named_in_every_exercise(name):
    for fn in (returns(None), forgets_return):
        report = ex.check(name, fn)
        assert len(report.failures) == report.n_cases
        for f in report.failures:
            # (r248 S1: 8.2's lines quote the case's call first)
            assert f.explanation.endswith("your function returned None (a missing `return`?)")
            assert f.kind == "none" and f.got is None
        text = str(report)
        assert "nan" not in text and "object" not in text and "shape ()" not in text


@pytest.mark.parametrize(
    "name, text",
    sample(itertools.product(NAMES, ["25.0", "True", "1", b"0.5", np.str_("0.25")]), keep=4),
)
def test_text_is_not_an_answer(name, text):
    report = ex.check(name, returns(text))
    assert len(report.failures) == report.n_cases
    assert all("text" in f.explanation and f.kind == "type" for f in report.failures)


@pytest.mark.parametrize(
    "name, value",
    [
        ("barycentric", ["0.2", "0.3", "0.5"]),
        ("clip_near", [["0", "0", "0", "1"]] * 3),
        ("edge_function", [2.5, "x"]),
        ("edge_function", True),
        ("perspective", 1 + 2j),
        ("split_point", [1.0, 2.0]),
        ("depth_test", 0.5),
        ("covers", 2),
        ("fill", "0" * 9),
    ],
)
def test_wrong_kinds_of_values_are_explained(name, value):
    report = ex.check(name, returns(value))
    assert len(report.failures) == report.n_cases
    first = report.failures[0]
    assert first.kind == "type" and first.explanation.startswith("your function returned")


def test_not_implemented_on_some_inputs_only_is_one_failure_among_others():
    def ties_unfinished(incoming, stored):
        if incoming == stored:
            raise NotImplementedError("ties: later")
        return incoming <= stored  # and a real mistake elsewhere? none: < and <= agree here

    report = ex.check("depth_test", ties_unfinished)
    assert not report.not_implemented and not report.passed
    assert "not implemented yet" not in str(report)
    ties = [f for f in report.failures if f.kind == "not implemented"]
    assert ties and len(ties) == len(report.failures) < report.n_cases
    assert "NotImplementedError: ties: later" in ties[0].explanation


def test_not_implemented_on_some_inputs_beside_a_wrong_answer():
    def half_done(xy, p):
        if xy[0][0] > 10:
            raise NotImplementedError
        return True

    report = ex.check("covers", half_done)
    assert not report.not_implemented
    kinds = {f.kind for f in report.failures}
    assert "not implemented" in kinds and len(kinds) > 1
    shown = {f.kind for f in report.shown()}
    assert "not implemented" in shown and len(shown) > 1


@pytest.mark.parametrize("name", sample(NAMES, keep=2))
def test_the_untouched_stub_alone_is_not_implemented_yet(name):
    report = ex.check(name, raises(NotImplementedError()))
    assert report.not_implemented and report.failures == []
    assert "not implemented yet" in str(report)


def test_exact_numbers_are_numbers_and_other_objects_are_named():
    from decimal import Decimal
    from fractions import Fraction

    from exercise_solutions import CORRECT

    E = CORRECT["edge_function"]
    for kind in (Fraction, Decimal, np.float64, int):

        def fn(a, b, p, kind=kind):
            e = E(a, b, p)
            return kind(e) if kind is not int or float(e).is_integer() else e

        assert ex.check("edge_function", fn).passed, kind
    report = ex.check("edge_function", returns(object()))
    assert "of type object" in report.failures[0].explanation
    report = ex.check("edge_function", returns(10**400))
    assert "too large for a float" in report.failures[0].explanation


@pytest.mark.parametrize(
    "name, values",
    [
        ("edge_function", [np.inf, np.nan, 1e308]),
        ("split_point", [-np.inf, -1e308]),
        ("perspective", [np.inf, 1e300]),
        ("barycentric", [[np.inf, 0, 0], [1e308, -1e308, 1], [np.nan] * 3]),
        ("clip_near", [np.full((4, 4), 1e308), np.full((3, 4), np.inf), np.full((3, 4), np.nan)]),
    ],
)
def test_infinite_and_huge_answers_are_explained_and_drawn_without_warnings(name, values, axes):
    import warnings

    for value in values:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            report = ex.check(name, returns(value))
            report.plot(axes)
            axes.figure.canvas.draw()
        assert not report.passed and report.failures[0].kind != "type"
        axes.clear()
