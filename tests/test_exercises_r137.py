"""Review r137 (exercises 03, 08 task 8.2, 12 played as students in fresh processes): 8.2 passed
the nearest vertex taken inside the tile (unsafe, D8-1), an empty box tested in x only (D8-3),
``int()`` for floor (D8-6), the stored depths read inside the box only (D8-10) and an array of
one bool (D8-7); it told the half-open box, which the top-left rule makes safe, that it can
drop a drawn fragment (D8-2), and named one past the box's end and the clipped triangle
wrongly (D8-5, D8-9); 03 cell 2 said lesson 03 only reads the weights off a picture (D3-1).
"""

from __future__ import annotations

from pathlib import Path

import nbformat
import numpy as np
import pytest
from student_variants import DIFFERENT, KINDS, WRONG
from test_exercises_r126 import _cell, _check

import teachraster as tr
from teachraster.exercises import hiz_tile

LESSON_03 = Path(__file__).parents[1] / "notebooks/03_barycentric_and_plane_equations.ipynb"

R137 = (
    "Hi-Z by the nearest vertex inside the tile",
    "Hi-Z with the empty box tested in x only",
    "Hi-Z with int() for floor",
    "Hi-Z against the box's stored depths",
    "Hi-Z one column past the box",
    "Hi-Z over the triangle clipped to the centres",
    "Hi-Z at the box's own corners",
)


@pytest.mark.parametrize("label", R137)
def test_the_readers_wrong_bounds_fail_and_are_named_on_the_first_try(label):
    """D8-1, D8-3, D8-5, D8-6, D8-9, D8-10: each fails, named on every failing case."""
    name, fn, words = WRONG[label]
    report = _check(name, fn)
    assert not report.passed and report.failures, label
    assert {f.kind for f in report.failures} == {KINDS[label]}, (label, str(report))
    assert words in report.failures[0].explanation, (label, str(report))


def test_the_nearest_vertex_inside_the_tile_would_drop_a_drawn_fragment():
    """D8-1: the reader's triangle: the covered centre (7.5, 1.5) lies at 0.363, nearer than
    the stored 0.4, so the block must be kept; the vertices inside the tile lie at 0.5."""
    xyz = np.array([[1.0, 1.0, 0.5], [20.0, 1.0, 0.1], [1.0, 20.0, 0.5]])
    cases = {label: (args, rejected) for label, args, rejected in hiz_tile.hiz_cases()}
    args, rejected = cases["the triangle's nearest vertex far outside the tile, the two inside "
                           "it farther than the plane there"]  # fmt: skip
    assert np.array_equal(args[0], xyz) and np.all(args[4] == 0.4) and not rejected
    assert tr.rasterize(tr.Triangle(xyz[:, :2]), 8, 8).coverage[1, 7]
    assert hiz_tile.plane_at(xyz, np.array([1]), np.array([7]))[0] == pytest.approx(0.363, abs=5e-4)
    assert WRONG["Hi-Z by the nearest vertex inside the tile"][1](*args)


def test_the_half_open_box_is_safe_and_accepted_and_the_border_message_is_true():
    """D8-2: the top-left rule covers no centre at x = xmax or y = ymax (both windings, vertices
    on centres and off), so the half-open box passes; leaving out every border still fails,
    only on the left/top cases, and is told the rule *can* cover a centre there."""
    rng = np.random.default_rng(137)
    for k in range(400):
        xy = (
            rng.integers(0, 10, (3, 2)) + 0.5
            if k % 2
            else np.round(rng.uniform(0, 10, (3, 2)) * 4) / 4
        )
        if abs(tr.edge_function(*xy)) < 1e-9:
            continue
        rows, cols = np.nonzero(tr.rasterize(tr.Triangle(xy), 12, 12).coverage)
        assert not ((cols + 0.5 >= xy[:, 0].max()).any() or (rows + 0.5 >= xy[:, 1].max()).any())
    assert _check("hiz_rejects", DIFFERENT["Hi-Z over the half-open box"][1]).passed
    report = _check("hiz_rejects", WRONG["Hi-Z without the box's border"][1])
    assert not report.passed
    for failure in report.failures:
        assert "right" not in failure.case and "bottom" not in failure.case, failure.case
        assert "triangle can cover such a centre" in failure.explanation
        assert "the triangle covers such a centre" not in failure.explanation
    text = _cell("08_tiles.ipynb", 5)
    assert (
        "leaves out only the border centres the top-left rule can never cover is accepted "
        "too" in " ".join(text.split())
    )


def test_an_array_of_one_bool_is_an_explained_failure():
    """D8-7: np.array([verdict]) passed every case; shapes must match."""
    right = DIFFERENT["Hi-Z at the box's extreme centres"][1]
    report = _check("hiz_rejects", lambda *a: np.array([right(*a)]))
    assert not report.passed
    assert "an array of shape (1,), not a bool" in report.failures[0].explanation, str(report)
    assert _check("hiz_rejects", lambda *a: np.bool_(right(*a))).passed


def test_exercise_3_says_what_lesson_03_gives():
    """D3-1: lesson 03 §1 and its next cell print λ1 = E(v2, v3, p)/E(v1, v2, v3) for any p:
    03 cell 2 says the lesson gives the weights for every p, not that it only reads them off
    a picture of a point inside (without restating the formula: r84 03-1)."""
    text = _cell("03_interpolation.ipynb", 2)
    assert "reads the weights off a picture" not in text and "of a point inside;" not in text
    # r488: 3.1 is a repair of shipped code now; it no longer restates what lesson 03 gives
    lesson = nbformat.read(LESSON_03, 4).cells
    # §1 and "The areas are the edge functions", up to §2 (held cells move the indices)
    one = next(i for i, c in enumerate(lesson) if c.source.startswith("## 1."))
    two = next(i for i, c in enumerate(lesson) if c.source.startswith("## 2."))
    said = " ".join(c.source for c in lesson[one:two] if c.cell_type == "markdown")
    assert "signed" in said and "E(\\mathbf{v}_2,\\mathbf{v}_3,\\mathbf{p})" in said


def _bary(xy, p):
    xy = np.asarray(xy, dtype=float)
    v1, v2, v3 = xy
    e = tr.edge_function
    if e(v1, v2, v3) == 0:  # 3.1 since ex30b: a zero area has no weights
        raise ValueError("zero area")
    return np.array([e(v2, v3, p), e(v3, v1, p), e(v1, v2, p)]) / e(v1, v2, v3)


def _mu(lam, w):
    q = np.asarray(lam, float) / np.asarray(w, float)
    return q / q.sum()


NAMED_03 = [
    # D3-2: clipped to [0, 1] and renormalised (the pipeline's own clamp)
    ("barycentric", lambda xy, p: np.clip(_bary(xy, p), 0, 1) / np.clip(_bary(xy, p), 0, 1).sum(),
     "clamped", "do not clamp them"),
    # D3-3: λ3 = 1 − λ1 + λ2: the sum it breaks was said; since r348 the slip itself
    ("barycentric", lambda xy, p: _bary(xy, p) * [1, 1, 0] + [0, 0, 1 - _bary(xy, p)[0] + _bary(xy, p)[1]],
     "λ3 = 1 − λ1 + λ2", "is 1 − λ1 + λ2, a sign slip"),
    ("perspective_weights", lambda lam, w: (np.asarray(lam) / w) / np.abs(np.asarray(lam) / w).sum(),
     "absolute sum", "the sum of the sizes |λ_j / w_j|"),
    ("perspective_weights", lambda lam, w: _mu([1, 1, 1], w), "no lambda", "leave λ out"),
    ("perspective_weights", lambda lam, w: _mu(lam, np.asarray(w)[::-1]), "w reversed",
     "another vertex's w"),
]  # fmt: skip


@pytest.mark.parametrize("name, fn, kind, words", NAMED_03, ids=[n[3][:20] for n in NAMED_03])
def test_exercise_3s_half_named_answers_are_named_on_the_first_try(name, fn, kind, words):
    """D3-2, D3-3 and 3.2's W5, W7, W10: the mistake (or the broken sum) is said."""
    report = _check(name, fn)
    assert not report.passed
    first = report.failures[0]
    assert words in first.explanation, str(report)
    if kind is not None:
        # (r421 T2: beyond a GPU's w the slips written on lesson 04's formula overflow too)
        # (r429 W1: "p outside the triangle, w beyond a GPU's range" too)
        on_a_gpu = [f for f in report.failures if "w beyond a GPU's range" not in f.case]
        assert {f.kind for f in on_a_gpu} == {kind}, str(report)
