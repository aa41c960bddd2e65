"""r14 09-1: the checker's own reference code handed in as the answer does not count.

``line_pixels = lambda p0, p1: list(lines.diamond_pixels(p0, p1))`` passed all 50 cases
unflagged: ``diamond_pixels`` is the checker's own rule with knobs, public in its module.
Every function of the modules that compute an exercise's expected answers is watched now,
as the package's own answers are (:func:`teachraster.exercises.package_answers.checker_modules`);
the tools a student is given (``ex.broken_frame``) are not.
"""

from __future__ import annotations

import importlib
import sys
import types

import pytest

from teachraster import exercises as ex
from teachraster.exercises import blending, checks, lines
from teachraster.exercises import package_answers as pa

#: Checker modules that only build cases or format numbers, never an expected answer.
INFRASTRUCTURE = {"teachraster.exercises.cases", "teachraster.exercises.scalars",
                  "teachraster.exercises.answers"}  # fmt: skip


@pytest.mark.parametrize(
    "line",
    [
        lambda p0, p1: list(lines.diamond_pixels(p0, p1)),
        lambda p0, p1: list(lines.diamond_pixels(p0, p1, eps=(-1e-5, -1e-10))),
        lambda p0, p1: list(lines._expected_pixels(p0, p1)),
    ],
    ids=["diamond_pixels", "diamond_pixels with another eps", "_expected_pixels"],
)
def test_the_checkers_own_line_rule_handed_in_does_not_count(line):
    report = ex.check("line_pixels", line, budget=60)
    assert not report.passed and "the checker's own code" in (report.package or ""), str(report)
    assert report.failures == [], report.failures  # right, but not the student's work


def _right_blend(s, d):
    """A student's own premultiplied over, to tell the table's lambda from the student's."""
    return s + d * (1 - s[3])


@pytest.mark.parametrize("how", ["handed in", "called"])
def test_a_lambda_from_the_checkers_own_tables_does_not_count(how):
    """``blending.OVER[1][2]`` (the mistake "source not multiplied" of exercise ``over``) is
    ``over_premultiplied``'s answer: taken from the checker's table, handed in or called from
    the student's own function, it passed unflagged (it is no module-level function)."""
    table = blending.OVER[1][2]
    assert ex.check("over_premultiplied", _right_blend).passed  # the right answer it equals
    fn = table if how == "handed in" else (lambda s, d: blending.OVER[1][2](s, d))
    report = ex.check("over_premultiplied", fn)
    verb = "is" if how == "handed in" else "calls"
    assert not report.passed, str(report)
    assert f"{verb} teachraster's blending.OVER[1][2]" in (report.package or ""), report.package
    assert "the checker's own code" in report.package
    assert report.failures == [], report.failures


def _module_functions(module: str) -> dict:
    """The functions defined in ``module``, by name."""
    found = {}
    for key, value in vars(importlib.import_module(module)).items():
        g = getattr(value, "__wrapped__", value)
        if isinstance(g, types.FunctionType) and g.__module__ == module and key[:2] != "__":
            found[key] = g
    return found


def _reference_calls(spec) -> set:
    """The module-level functions of the checker called while ``spec``'s cases (its expected
    answers) are built, outside :data:`INFRASTRUCTURE`."""
    called = set()

    def seen(frame, event, arg):
        module = frame.f_globals.get("__name__", "")
        if event == "call" and module.startswith("teachraster.exercises"):
            called.add((module, frame.f_code))

    sys.setprofile(seen)
    try:
        spec.cases()
    finally:
        sys.setprofile(None)
    out = set()
    for module, code in called:
        if module not in INFRASTRUCTURE:
            out |= {g for g in _module_functions(module).values() if g.__code__ is code}
    return out


@pytest.mark.parametrize("name", checks.names())
def test_every_reference_helper_of_every_check_is_watched(name):
    """Each function of the modules that build a check's expected answers (the module of
    its cases, and every checker function its cases call) is watched: a student's call of
    it is not counted. The tools a student is given are not watched."""
    spec = checks.exercise(name)
    watched = {pa._function(a) for a in (*spec.answers, *pa._module_helpers(spec))}
    tools = {getattr(ex, t) for t in ex.__all__ if callable(getattr(ex, t))}
    for module in pa.checker_modules(spec):
        for key, g in _module_functions(module).items():
            if g not in tools and not pa.is_transparent(g.__code__):
                assert g in watched, (name, module, key)
    missing = {f"{g.__module__}.{g.__qualname__}" for g in _reference_calls(spec) - watched - tools}
    assert not missing, (name, sorted(missing))
    assert not tools & watched, (name, tools & watched)
