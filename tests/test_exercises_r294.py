"""r294 (exercise 04, depth and clipping, played as students): a glass tie passed 4.1, and
clip_near told answers of the wrong form "its t is wrong" or only their shape.

W1, C1: no case had a wall then glass at its depth, so `<=` for glass passed (and the text's
glass rule, "nothing opaque … lies in front of it", allowed it). M-dp1, H-dp1: that slip and
glass that never passes are named. M-cn1..3: a polygon divided by w, transposed, or clipped
against the far plane too. M-cn4: a kept vertex rounded is no new vertex. H-cn1..4: one of the
two crossings only, a crossing before its edge's first vertex, the inside test turned round, a
t a little off (told "keeps a vertex behind"). R-cn1: a ragged answer was "your function
raised ValueError".
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from teachraster import exercises as ex
from teachraster.exercises import tries
from teachraster.exercises.depth_clipping import clip_with
from teachraster.exercises.zbuffer_pixel import depth_cases

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "04_depth_and_clipping.ipynb"


def _check(name, fn):
    """The report with the full words (the staged hints spent), as after two failing tries."""
    tries.spend_hints([name])
    try:
        return ex.check(name, fn, budget=60)
    finally:
        tries.forget_hints(name)


def _depth(glass_tie=False, glass_fails=False):
    def depth_passes(depths, writes):
        stored, out = np.inf, []
        for d, w in zip(depths, writes):
            ok = d <= stored if glass_tie and not w else d < stored
            ok = ok and (w or not glass_fails)
            out.append(ok)
            if ok and w:
                stored = d
        return out

    return depth_passes


def test_a_wall_then_glass_at_its_depth_is_a_fixed_case():
    cases = {label: (args, passed) for label, args, passed in depth_cases()}
    (depths, writes), passed = cases["a wall, then glass at the same depth"]
    assert list(depths) == [0.4, 0.4] and list(writes) == [True, False]
    assert list(passed) == [True, False]


@pytest.mark.parametrize(("fn", "kind", "words"), [
    (_depth(glass_tie=True), "glass ties", "a tie fails for glass too"),
    (_depth(glass_fails=True), "glass never passes", "glass never passes in your answer"),
])  # fmt: skip
def test_glass_slips_fail_and_are_named(fn, kind, words):
    report = _check("depth_passes", fn)
    assert not report.passed, str(report)
    first = report.failures[0]
    assert first.kind == kind and words in first.explanation, (first.kind, first.explanation)


def test_the_text_says_glass_at_the_walls_depth_is_not_seen():
    cell = "".join(json.loads(NOTEBOOK.read_text())["cells"][2]["source"])
    assert "lies in front of\n  it or at its depth" in cell
    assert "the check draws it in any order" in cell


def _clip(**knobs):
    return lambda v: clip_with(v, **knobs)


def _divided(v):
    p = clip_with(v)
    return p / p[:, 3:4] if len(p) else p


def _far_too(v):
    p = clip_with(v)
    return clip_with(p, lambda q: q[3] - q[2]) if len(p) else p


SLIPS = [
    (_divided, "divided by w", "you divided your vertices by w"),
    (lambda v: clip_with(v).T, "transposed", "your polygon is transposed"),
    (_far_too, "far plane too", "you clipped against the far plane too"),
    (_clip(distance=lambda p: -(p[2] + p[3])), "inside turned round", "turned round"),
    (_clip(crossings="leaving"), "one crossing", "only where an edge leaves the kept side"),
    (_clip(crossings="entering"), "one crossing", "only where an edge comes back"),
    (_clip(crossing_first=True), "crossing before its edge", "comes before the first vertex"),
    (_clip(t_from=lambda a, b: 1.0001 * (a[2] + a[3]) / (a[2] + a[3] - b[2] - b[3])),
     "crossing off the plane", "so its t is wrong"),
]  # fmt: skip


@pytest.mark.parametrize(("fn", "kind", "words"), SLIPS, ids=[s[1] for s in SLIPS])
def test_clip_slips_are_named_by_their_cause_on_the_first_failure(fn, kind, words):
    report = _check("clip_near", fn)
    assert not report.passed, str(report)
    first = report.failures[0]
    assert first.kind == kind and words in first.explanation, (first.kind, first.explanation)
    if kind != "crossing off the plane":
        assert "t is wrong" not in first.explanation, first.explanation


def test_a_kept_vertex_rounded_is_not_called_a_new_vertex():
    """M-cn4: float16's rounding of v1 was "your new vertex (-1, -1, 1.804, 2) … t is wrong"."""
    report = _check("clip_near", lambda v: clip_with(v).astype(np.float16).astype(float))
    assert not report.passed
    for f in report.failures:
        assert "new vertex (-1, -1, 1.804, 2)" not in f.explanation, f.explanation


def _own_clip(v, dtype=float):
    """A student's right clip_near (not the checker's clip_with, which is flagged as such)."""
    v, out = np.asarray(v, dtype=dtype), []
    for a, b in zip(v, np.roll(v, -1, axis=0)):
        da, db = a[2] + a[3], b[2] + b[3]
        if da >= 0:
            out.append(a)
        if (da >= 0) != (db >= 0):
            out.append(a + da / (da - db) * (b - a))
    return np.array(out, dtype=dtype).reshape(-1, 4)


@pytest.mark.parametrize("fn", [
    lambda v: _own_clip(v, np.float32),  # a GPU's precision
    lambda v: _own_clip(v).tolist(),
])  # fmt: skip
def test_right_polygons_still_pass(fn):
    assert ex.check("clip_near", fn).passed


def test_a_ragged_answer_is_told_by_its_shape_not_as_the_students_exception():
    report = _check("clip_near", lambda v: [[1.0, 2, 3], [1.0, 2, 3, 4]])
    first = report.failures[0]
    assert "your function raised" not in first.explanation, first.explanation
    assert "not an (n, 4) array of vertices" in first.explanation, first.explanation
