"""Exercise 3.1 asks for reasoning lesson 03 does not print: which "triangles" have no weights
(three vertices on one line), refused with ValueError by an exact test; and the checker's one
rule for float32 (issue 30: "never blame float32 where the answer is off by more than float32's
rounding"; "float32 is named in every exercise"), across exercises."""

from __future__ import annotations

import warnings

import exercise_solutions as S
import numpy as np
import pytest

from teachraster import exercises as ex
from teachraster.exercises import diagnosis as dg
from teachraster.exercises import interpolation as ip


def _e(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def by_edges(xy, p):
    v1, v2, v3 = np.asarray(xy, float)
    area = _e(v1, v2, v3)
    if area == 0:
        raise ValueError("zero area")
    return np.array([_e(v2, v3, p), _e(v3, v1, p), _e(v1, v2, p)]) / area


def by_solve(xy, p):
    """The 3×3 system of the definition, with the exact test of the text first."""
    v1, v2, v3 = np.asarray(xy, float)
    if _e(v1, v2, v3) == 0:
        raise ValueError("zero area")
    m = np.vstack([np.asarray(xy, float).T, np.ones(3)])
    return np.linalg.solve(m, [p[0], p[1], 1.0])


def by_cramer_about_v3(xy, p):
    (x1, y1), (x2, y2), (x3, y3) = np.asarray(xy, float)
    det = (x1 - x3) * (y2 - y3) - (x2 - x3) * (y1 - y3)
    if not det:
        raise ValueError("collinear")
    l1 = ((p[0] - x3) * (y2 - y3) - (x2 - x3) * (p[1] - y3)) / det
    l2 = ((x1 - x3) * (p[1] - y3) - (p[0] - x3) * (y1 - y3)) / det
    return [l1, l2, 1 - l1 - l2]


def no_guard(xy, p):
    v1, v2, v3 = np.asarray(xy, float)
    with np.errstate(all="ignore"):
        return np.array([_e(v2, v3, p), _e(v3, v1, p), _e(v1, v2, p)]) / _e(v1, v2, v3)


def threshold(xy, p):
    v1, v2, v3 = np.asarray(xy, float)
    if abs(_e(v1, v2, v3)) < 1:
        raise ValueError("too thin")
    return by_edges(xy, p)


def unnormalised(xy, p):
    v1, v2, v3 = np.asarray(xy, float)
    return by_edges(xy, p) * _e(v1, v2, v3)


def wrong_sign(xy, p):
    return -by_edges(xy, p)


def over_abs_area(xy, p):
    v1, v2, v3 = np.asarray(xy, float)
    return by_edges(xy, p) * _e(v1, v2, v3) / abs(_e(v1, v2, v3))


def check(name, fn):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ex.check(name, fn)


@pytest.mark.parametrize("fn", [by_edges, by_solve, by_cramer_about_v3, S.barycentric])
def test_right_answers_written_differently_pass(fn):
    report = check("barycentric", fn)
    assert report.passed, report


@pytest.mark.parametrize(
    ("fn", "kind", "words"),
    [
        (no_guard, "no zero-area check", "raise ValueError"),
        (threshold, "refused a proper triangle", "refuse only an area of exactly 0"),
        (unnormalised, "not divided", "did not divide"),
        (wrong_sign, "sign", "wrong sign"),
        (over_abs_area, "absolute area", "not by its absolute value"),
    ],
)
def test_each_typical_mistake_is_named(fn, kind, words):
    report = check("barycentric", fn)
    assert not report.passed
    named = [f for f in report.failures if f.kind == kind]
    assert named, [(f.kind, f.explanation) for f in report.failures[:3]]
    assert any(words in f.explanation for f in report.failures), report.failures[0].explanation
    assert not any("float32" in f.explanation for f in report.failures)


def test_the_zero_area_cases_are_in_the_check():
    labels = [label for label, _, expected in ip.barycentric_cases() if isinstance(expected, str)]
    assert len(labels) == len(ip.DEGENERATE) == 10  # r421 W1: two far collinear ones; r506 W2
    for _, (xy, _p), expected in ip.barycentric_cases():
        if isinstance(expected, str):
            assert _e(*xy) == 0


def test_the_notebook_asks_for_the_zero_area_reasoning():
    import json
    from pathlib import Path

    nb = json.loads(Path("notebooks/exercises/03_interpolation.ipynb").read_text())
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in nb["cells"]}
    task = cells["task_3_1"]
    assert "raise\n`ValueError`" in task or "raise `ValueError`" in task
    assert "on one line" in task
    solution = cells["barycentric_solution"]
    assert "raise ValueError" in solution


# -- one rule: float32 only within its rounding ---------------------------------------------------
def _plus(fn, delta):
    def wrong(*args):
        value = fn(*args)
        return np.asarray(value, float) + delta

    wrong.__name__ = fn.__name__
    return wrong


@pytest.mark.parametrize(
    "name", ["barycentric", "perspective", "resolve", "resolve_srgb", "mip_level", "bilinear",
             "trilinear"],
)  # fmt: skip
def test_an_answer_off_by_1e_2_is_never_told_float32(name):
    report = check(name, _plus(getattr(S, name), 1e-2))
    assert not report.passed
    for f in report.failures:
        assert not dg.blames_precision(f"{f.kind} {f.explanation}"), f.explanation


def test_a_right_float32_answer_is_told_float32():
    def f32(xy, p):
        v1, v2, v3 = np.asarray(xy, np.float32)
        q = np.asarray(p, np.float32)
        area = _e(v1, v2, v3)
        if area == 0:
            raise ValueError("zero area")
        return np.array([_e(v2, v3, q), _e(v3, v1, q), _e(v1, v2, q)]) / area

    report = check("barycentric", f32)
    assert {f.kind for f in report.failures} == {"float32"}
    assert all("did you compute in float32" in f.explanation or "float32" in f.explanation
               for f in report.failures)  # fmt: skip
    for name in ("resolve", "bilinear", "trilinear"):
        fn = getattr(S, name)
        report = check(name, lambda *a, fn=fn: np.float32(fn(*a)))
        assert report.passed and "float32" in (report.precision or ""), (name, report)


class _Spec:
    float32 = None


def _result(expected, got):
    return dg.Result(0, ((1.0,),), expected, got, False)


def test_the_rule_allows_float32_within_rounding_only():
    spec = ex.checks.exercise("perspective")
    inside = _result(0.5, np.float32(0.5) + np.float32(2.0**-24))
    outside = _result(0.5, 0.51)
    args = ((np.array([0.2, 0.3, 0.5]), np.array([1.0, 2.0, 4.0]), np.array([0.0, 1.0, 2.0])),)
    inside = dg.Result(0, args[0], 0.5, float(inside.got), False)
    outside = dg.Result(0, args[0], 0.5, 0.51, False)
    assert dg.precision_may_be_named(spec, inside, None)
    assert not dg.precision_may_be_named(spec, outside, None)
    kind, words = dg._honest(spec, outside, "float32", ". about float32's rounding", None)
    assert not dg.blames_precision(f"{kind} {words}"), words
    # a float32 computation of the table that gives the very answer is evidence (a bool)
    depth = ex.checks.exercise("depth_test")
    m = next(m for m in depth.all_mistakes() if m.kind == "float32")
    a, b = 0.5, 0.5 + 2.0**-30
    r = dg.Result(0, (a, b), True, False, False)
    assert dg.precision_may_be_named(depth, r, m)
