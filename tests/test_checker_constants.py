"""A constant answer is the checker's first diagnosis, in every exercise (issue 30, r64 04-1).

A function that returns the same value whatever its arguments (``return 0`` left in, an empty
polygon from ``clip_near``) is told "your function returns … on every case", on every failure,
before any mistake of the exercise's table: never another mistake's name (r64: an empty
``clip_near`` was called the far plane's z − w) and never the rule or formula. An argument
handed back unchanged (``return background``) is told the same way, where no mistake of the
table gives it.
"""

from __future__ import annotations

import copy
import re

import numpy as np
import pytest
from exercise_solutions import CORRECT as _CORRECT
from exercise_solutions import clip_against
from reasoning_solutions import CORRECT as _REASONING

from teachraster import exercises as ex
from teachraster.exercises import tries
from teachraster.exercises.checks import exercise

CORRECT = {**_CORRECT, **_REASONING}
#: Exercises with fewer than three cases (a redrawn broken frame): no answer is a constant.
FEW = [name for name in ex.names() if name.startswith("broken_frame_")]
FEW.append("defect_case")  # r488: two cases, too few to call an answer constant
#: Words of a rule or a mistake's name that a constant's explanation must not hold.
TELLING = ("top-left rule", "z − w", "d_a/", "linear_to_srgb", "u·W", "formula", "float32")


def _first_answer(name: str):
    """What the reference returns on the exercise's first case (one value of it, for an
    exercise whose function is called once per pixel)."""
    spec = exercise(name)
    args = spec.cases()[0][1]
    if spec.call is None:
        return CORRECT[name](*copy.deepcopy(args))
    seen = []

    def recorded(*a):
        seen.append(CORRECT[name](*a))
        return seen[-1]

    spec.call(recorded, copy.deepcopy(args))
    return seen[0]


def _constants():
    """(exercise, constant function): the first case's answer returned on every case, where
    that answer's shape does not depend on the case (``fill``'s image does: its constant is
    an empty image, below)."""
    out = []
    for name in ex.names():
        if name in FEW or name == "fill":
            continue
        value = _first_answer(name)
        out.append((name, lambda *a, v=value: copy.deepcopy(v)))
    return out


@pytest.mark.parametrize("name,fn", _constants(), ids=[n for n, _ in _constants()])
def test_a_constant_is_named_first_in_every_exercise(name, fn):
    tries.spend_hints([name])
    report = ex.check(name, fn, budget=60)
    assert not report.passed and report.failures, str(report)
    for f in report.failures:
        if f.kind in ("type", "shape"):  # an answer of another case's size: read, not named
            continue
        assert f.kind == "constant", (name, f.kind, f.explanation)
        assert "on every case" in f.explanation or " for every " in f.explanation
        # the case's numbers come first (compose); the words after them name no rule
        # (from the first word "your"/"yours": "yo" alone also starts "beyond" in a case's words)
        words = f.explanation[re.search(r"\byour", f.explanation).start() :]
        assert not any(t in words for t in TELLING), words


@pytest.mark.parametrize(
    "name,fn,words",
    [
        ("clip_near", lambda v: np.zeros((0, 4)), "returns an empty polygon on every case"),
        ("covers", lambda xy, p: False, "returns False for every centre of every triangle"),
        ("covers", lambda xy, p: True, "returns True for every centre of every triangle"),
        ("fill", lambda xy, w, h: np.zeros((h, w)), "never covers anything"),
        ("hiz_rejects", lambda *a: False, "returns False on every case"),
        ("classify_block", lambda *a: "rejected", "returns 'rejected' on every case"),
        ("depth_passes", lambda d, w: [False] * len(d), "no fragment pass"),
        ("resolve_srgb", lambda c, i, background: background, "returns its argument background"),
    ],
    ids=["clip empty", "covers False", "covers True", "fill empty", "hiz False",
         "classify rejected", "depth_passes none", "resolve_srgb background"],
)  # fmt: skip
def test_a_placeholder_is_told_without_the_rule(name, fn, words):
    """The first failing try of a placeholder gets the placeholder's words and nothing of
    the rule (r64 04-1, 06-1: an empty polygon was told z − w; ``return background`` got
    the whole formula)."""
    tries.forget_hints(name)
    report = ex.check(name, fn, budget=60)
    first = report.failures[0].explanation
    assert words in first, first
    assert not any(t in first for t in TELLING), first


def test_a_computed_answer_that_is_empty_everywhere_is_not_a_placeholder():
    """z − w keeps nothing of a triangle in front of the far plane; the case with a vertex
    beyond it tells the computed clipper from ``return []`` (r39 04-1 kept, r64 04-1)."""
    report = ex.check("clip_near", lambda v: clip_against(v, lambda p: p[2] - p[3]), budget=60)
    assert all(f.kind == "far plane's distance" for f in report.failures), str(report)


def test_a_span_returned_as_stop_first_is_computed_not_constant():
    """(stop, first) covers nothing on every case, but what the function returned differs."""
    from reasoning_solutions import span

    report = ex.check("span", lambda xy, row: span(xy, row)[::-1], budget=60)
    assert all(f.kind != "constant" for f in report.failures), str(report)
