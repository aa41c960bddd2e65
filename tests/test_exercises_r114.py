"""Review r114 (exercises 03, 08, 12 played as students in fresh processes): the checker's own
verdicts passed 8.1 and 8.2, a correct float64 plane failed 8.2's ties and was called float32,
the tile's middle was told "the plane's largest value at the corners", four-corner code was
told "only 2 of the 4", a winding-dependent tie rule was called "top-right", and a culling
classify_block was named on some draws only.
"""

from __future__ import annotations

import numpy as np
import pytest
from exercise_solutions import per_block
from student_variants import hiz_box

from teachraster import exercises as ex


def _reference(name):
    if name == "classify_block":
        from teachraster.exercises.tile_blocks import expected_block

        return expected_block
    from teachraster.exercises.hiz_tile import expected_reject

    return expected_reject


@pytest.mark.parametrize("name", ["classify_block", "hiz_rejects"])
@pytest.mark.parametrize("how", ["handed in", "called"])
def test_the_checkers_own_verdict_does_not_count(name, how):
    """r114 D8-1: ``return expected_reject(...)`` passed all 35 cases, ``expected_block`` all
    47, though docs/exercises.md says the checker's own code is not counted."""
    ref = _reference(name)
    fn = ref if how == "handed in" else (lambda *a: _reference(name)(*a))
    report = ex.check(name, fn, budget=120)
    assert not report.passed, str(report)
    assert "the checker's own code" in (report.package or ""), report.package
    assert report.failures == [], report.failures


def _hiz_absolute_plane(xyz, row0, col0, size, buffer):
    """The notes' plane A x + B y + C z + D = 0 in absolute coordinates, in float64 (it
    rounds otherwise than the renderer's plane, by an ulp)."""
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = np.asarray(xyz, float)
    a = y1 * (z2 - z3) + y2 * (z3 - z1) + y3 * (z1 - z2)
    b = z1 * (x2 - x3) + z2 * (x3 - x1) + z3 * (x1 - x2)
    c = x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2)
    d = -(x1 * (y2 * z3 - y3 * z2) + x2 * (y3 * z1 - y1 * z3) + x3 * (y1 * z2 - y2 * z1))
    box = hiz_box(xyz, row0, col0, size)  # r126 N8-1: the tile's centres inside the box
    if box is None:
        return True
    c0, c1, r0, r1 = box
    xs = np.array([c0, c1, c0, c1]) + 0.5
    ys = np.array([r0, r0, r1, r1]) + 0.5
    z = -(a * xs + b * ys + d) / c
    return bool(max(z.min(), min(z1, z2, z3)) >= np.max(buffer))


def test_a_float64_plane_in_the_notes_form_passes_the_near_ties():
    """r114 D8-2: the random ties were the renderer's plane bit for bit; this right float64
    plane failed two and was asked "did you compute in float32?". Now they lie 2^-36 off."""
    from teachraster.exercises import hiz_tile as hz

    report = ex.check("hiz_rejects", _hiz_absolute_plane, budget=120)
    assert report.passed, str(report)
    ties = [c for c in hz.hiz_cases() if hz._tie_gap(c[1]) not in (None, 0.0)]
    assert len(ties) >= 4 and {c[2] for c in ties} == {True, False}, ties


def _hiz_at_middle(xyz, row0, col0, size, buffer):
    xyz = np.asarray(xyz, float)
    a, b, c = np.linalg.solve(np.column_stack([xyz[:, 0], xyz[:, 1], np.ones(3)]), xyz[:, 2])
    middle = a * (col0 + size / 2) + b * (row0 + size / 2) + c
    return bool(max(middle, xyz[:, 2].min()) >= np.max(buffer))


def test_the_plane_at_the_tiles_middle_is_named_so():
    """r114 D8-3: the plane at the tile's middle was told "you took the plane's largest value
    at the corners, its farthest"."""
    report = ex.check("hiz_rejects", _hiz_at_middle, budget=120)
    assert not report.passed
    assert {f.kind for f in report.failures} == {"tile middle"}, str(report)
    assert "largest value at the corners" not in str(report), str(report)


def _block(**knobs):
    from teachraster.exercises.tile_blocks import classify_with

    return lambda xy, x0, y0, size: classify_with(xy, x0, y0, size, **knobs)


def _oriented(xy):
    xy = [tuple(map(float, p)) for p in xy]
    (x1, y1), (x2, y2), (x3, y3) = xy
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    return (xy if area > 0 else [xy[0], xy[2], xy[1]]), area


def _top_left(a, b):
    return b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])


def _four_centres(x0, y0, size):
    return [(x0 + dx, y0 + dy) for dy in (0.5, size - 0.5) for dx in (0.5, size - 0.5)]


def _edge_ok(a, b, p, owns):
    e = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
    return e > 0 or (e == 0 and owns)


def _any_corner_rejects(xy, x0, y0, size):
    """All four extreme centres tested; an edge that passes at most one of them rejects."""
    v, area = _oriented(xy)
    if area == 0:
        return "rejected"
    accepted = True
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        ok = [_edge_ok(a, b, p, _top_left(a, b)) for p in _four_centres(x0, y0, size)]
        if sum(ok) <= 1:
            return "rejected"
        accepted = accepted and all(ok)
    return "accepted" if accepted else "partial"


def _sign_flipped_ties_as_given(xy, x0, y0, size):
    """E's sign flipped for the other winding, ties by the top-left test of each edge as given
    (a bottom-right rule on a counter-clockwise triangle)."""
    v = [tuple(map(float, p)) for p in xy]
    _, area = _oriented(v)
    if area == 0:
        return "rejected"
    s = 1 if area > 0 else -1
    accepted = True
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        ok = []
        for p in _four_centres(x0, y0, size):
            e = s * ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]))
            ok.append(e > 0 or (e == 0 and _top_left(a, b)))
        if not any(ok):
            return "rejected"
        accepted = accepted and all(ok)
    return "accepted" if accepted else "partial"


# 8.1 classifies a grid of blocks (r131 D8-7): the one-block functions above, looped over it
_any_corner_rejects = per_block(_any_corner_rejects)
_sign_flipped_ties_as_given = per_block(_sign_flipped_ties_as_given)


def test_four_corner_code_is_never_told_it_tested_two():
    """r114 D8-7: code testing all four centres (rejecting where at most one passes) was told
    "you tested only 2 of the 4 extreme centres" as its first explanation; a true two-corner
    test still is."""
    from test_exercises_r85 import _first_try, _words

    for report in (_first_try("classify_block", _any_corner_rejects),
                   ex.check("classify_block", _any_corner_rejects)):  # fmt: skip
        assert not report.passed and "only 2 of the 4" not in _words(report), _words(report)
    two = ex.check("classify_block", _block(offsets="two corners"))
    assert {f.kind for f in two.failures} == {"two corners only"}, str(two)


def test_a_winding_dependent_tie_rule_is_not_called_top_right():
    """r114 D8-4: the top-left test of the edges as given, E's sign flipped for the other
    winding, was told "your edge tests follow a top-right rule"."""
    report = ex.check("classify_block", _sign_flipped_ties_as_given)
    assert not report.passed
    # r248 F1: in float64 pixels, a slip of its own the far float64 ties name
    far = [f for f in report.failures if f.case.startswith("far out in float64")]
    kinds = {f.kind for f in report.failures if f not in far}
    assert kinds == {"tie rule of the edges as given"}, str(report)
    assert {f.kind for f in far} <= kinds | {"float64 pixels"}, str(report)
    assert "top-right" not in str(report), str(report)


def test_a_culling_classify_block_is_named_on_every_draw():
    """r114 item 5 (r107 N8-2's xfail): rejecting every block of a counter-clockwise triangle
    was told the rule on some fresh draws; each check draws six new blocks."""
    from student_variants import classify_one_winding

    for _ in range(4):
        report = ex.check("classify_block", classify_one_winding, budget=120)
        assert not report.passed
        assert {f.kind for f in report.failures} == {"culled one winding"}, str(report)
        assert "both windings" in report.failures[0].explanation


def test_the_capstone_grid_asks_the_edge_kind_on_the_first_try():
    """r114 D12-2: the grid scene's coverage sentence said "lies exactly on edge v1→v2, a
    right edge" on the first try, the kind exercise 1's check asks as a question until two
    different answers have failed."""
    import re

    from student_variants import WRONG
    from test_capstone import _mine
    from test_exercises_r85 import _words

    from teachraster.exercises import tries

    loose = WRONG["covers with E >= 0"][1]
    tries.forget_hints("covers")
    try:
        first = _words(ex.capstone("grid", **_mine("grid", covers=loose)))
    finally:
        tries.spend_hints(["covers"])
    assert "which kind of edge is it" in first, first
    assert not re.search(r"edge v\d→v\d, a (top|left|bottom|right) edge", first), first
    later = _words(ex.capstone("grid", **_mine("grid", covers=loose)))
    # r273 12-2: an edge of a triangle wound the other way carries its conventions' name
    assert re.search(r"edge v\d→v\d( \(E\d\d[^()]*\))?, a (top|left|bottom|right) edge", later), (
        later
    )


def test_capstone_glass_points_to_no_over_that_exercise_9_lacks():
    """r114 D12-1: cell 16 said "copy it from there (or from your exercise 9)"; exercise 9
    no longer asks for a premultiplied *over* (9.2b is atop)."""
    from test_exercises_r94 import _markdown

    text = " ".join(_markdown("12_capstone").split())
    assert "or from your exercise 9" not in text
    # and nothing says it is derived there (r94 D12-2: it is lesson 12b §4's rule, copied)
    assert "copy it from there" in text and "shares derive" not in text


def test_exercise_3_asks_beyond_what_lessons_03_and_04_print():
    """r114 D3-1: 3.1 asked to "find" the weights lesson 03 §1 prints as area ratios, 3.2 to
    "work out" lesson 04 §3's derivation line by line; now 3.1 works from the definition
    (a solve the lesson does not show) and 3.2 asks for the form that survives w 1e610 apart;
    since r126 D3-1 3.2 derives μ from the divide by w alone."""
    import json
    from pathlib import Path

    path = Path(__file__).parents[1] / "notebooks/exercises/03_interpolation.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]

    def task(grade_id):
        cell = next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == grade_id)
        return " ".join("".join(cell["source"]).split())

    first, second = task("task_3_1"), task("task_3_2")
    # r488: 3.1 repairs a shipped barycentric (its two defects), 3.1b a case for each
    assert "two defects" in first and "np.linalg.cond" in first and "abs" in first, first
    # r126 D3-1: 3.2 derives μ from the divide by w on a GPU's w; r421 T2: 1e-310 graded again
    assert "Derive μ from λ and the three clip-space w using only these facts" in second, second
    assert "1e610" not in second and "the check also asks it of those extreme w" in second
    assert "Only the ratios of the three w matter" not in second
    assert "then turn that around" not in second
