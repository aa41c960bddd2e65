"""r149 (exercise 08_tiles): misdiagnoses M1–M4, each with the reader's wrong answer, the words
its report must give and the wrong words it must not.

M1: forgetting to orient (the edges as given, no area, so zero area fails too) was told
"Corners outside the triangle do not reject a block". M2: a bias of any wrong size was quoted
as "a bias of 1/256 px²". M3 (8.2): the tile's outer corners were told "you compared the
triangle's nearest vertex". M4: a bias added, not taken off, was told "no top-left rule".
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from graded_cells import graded_cell
from test_exercise_8_1_offsets import student

from teachraster import exercises as ex
from teachraster.exercises import tries


@pytest.fixture
def plt():
    pytest.importorskip("matplotlib").use("Agg")
    import matplotlib.pyplot as pyplot

    yield pyplot
    pyplot.close("all")


@pytest.fixture
def full_words():
    tries.spend_hints(["classify_block", "hiz_rejects"])
    yield
    tries.forget_hints("classify_block")
    tries.forget_hints("hiz_rejects")


def no_orient_no_area(xy, x0, y0, size):
    """The reader's M1: the vertices in the given order, no area computed (so no zero-area
    rejection either), the rest right."""
    v = np.asarray(xy, dtype=float)
    px, py = np.asarray(x0) + 0.5, np.asarray(y0) + 0.5
    rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        A, B = a[1] - b[1], b[0] - a[0]
        R, T = (size - 1) * (max(A, 0) + max(B, 0)), (size - 1) * (min(A, 0) + min(B, 0))
        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        e0 = A * (px - a[0]) + B * (py - a[1])
        beta = 0.0 if top_left else -(2.0**-16)  # after the offset, where it is exact (r232)
        rejected |= e0 + R + beta < 0
        accepted &= e0 + T + beta >= 0
    return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))


def test_m1_no_orientation_names_the_winding_on_every_failing_case(full_words):
    report = ex.check("classify_block", no_orient_no_area, budget=120)
    assert not report.passed
    # r248 F1: in float64 pixels, a slip of its own the far float64 ties name (and only they)
    floats = [f for f in report.failures if f.kind == "float64 pixels"]
    assert all(f.case.startswith("far out in float64") for f in floats)
    assert {f.kind for f in report.failures} - {"float64 pixels"} == {
        "one winding only, no area"
    }, [(f.kind, f.explanation[-200:]) for f in report.failures]
    for f in report.failures:
        if f in floats:
            continue
        assert "handle both windings" in f.explanation, f.explanation
        assert "never computed the triangle's area" in f.explanation, f.explanation
        assert "Corners outside the triangle do not reject" not in f.explanation, f.explanation
    zero = [f for f in report.failures if "zero area" in f.case]
    assert zero and "collinear" in zero[0].explanation
    ccw = [f for f in report.failures if "zero area" not in f.case and f not in floats]
    assert all("counter-clockwise on screen" in f.explanation for f in ccw)


@pytest.mark.parametrize("bias", [2.0**-9, 2.0**-10, 2.0**-12, 2.0**-14, 2.0**-15, 1.5 * 2.0**-16])  # fmt: skip
def test_m2_a_bias_of_the_wrong_size_is_measured_not_quoted_as_1_256(bias, full_words):
    report = ex.check("classify_block", student(bias=bias), budget=120)
    assert not report.passed
    first = report.failures[0]
    assert first.kind == "tie-rule bias too large", (first.kind, first.explanation)
    assert "a bias of the wrong size" in first.explanation, first.explanation
    # the measured range holds the student's own bias
    assert "yours acts like a bias above 1/65536 px² and at most 26.43 px²" in first.explanation
    assert "1/256 px²" not in first.explanation, first.explanation


def test_m2_the_measured_range_holds_a_large_bias(full_words):
    report = ex.check("classify_block", student(bias=1.0), budget=120)
    words = " ".join(f.explanation for f in report.failures)
    assert "a bias of 1/256" not in words
    assert "a bias of the wrong size" in words and "yours acts like a bias above" in words


def test_m4_a_bias_added_is_named_by_its_sign(full_words):
    report = ex.check("classify_block", student(bias=-(2.0**-16)), budget=120)
    # r248 F1: the student computes in float64 pixels, named so on the far float64 ties
    far = [f for f in report.failures if f.case.startswith("far out in float64")]
    assert {f.kind for f in report.failures if f not in far} == {"tie-rule bias added"}
    assert {f.kind for f in far} <= {"tie-rule bias added", "float64 pixels"}
    labels = [f.case for f in report.failures]
    assert any("outside a right edge" in label for label in labels), labels
    for f in report.failures:
        if f not in far:
            assert "your bias has the wrong sign" in f.explanation
        assert "lies exactly on edge" not in f.explanation
        assert "no top-left rule" not in f.kind


def test_m4_no_tie_rule_is_still_told_the_tie(full_words):
    """E ≥ 0 (no bias at all) differs from the bias added on the new case, and keeps its words."""
    report = ex.check("classify_block", student(tie="E >= 0"), budget=120)
    # r248 F1: in float64 pixels, a slip of its own the far float64 ties name (and only they)
    floats = [f for f in report.failures if f.kind == "float64 pixels"]
    assert all(f.case.startswith("far out in float64") for f in floats)
    assert {f.kind for f in report.failures} - {"float64 pixels"} == {"no top-left rule (E ≥ 0)"}
    assert not any("outside a right edge" in f.case for f in report.failures)


def _plane(xyz):
    x, y, z = np.asarray(xyz, dtype=float).T
    m = np.array([[x[1] - x[0], y[1] - y[0]], [x[2] - x[0], y[2] - y[0]]])
    a, b = np.linalg.solve(m, [z[1] - z[0], z[2] - z[0]])
    return lambda px, py: z[0] + a * (px - x[0]) + b * (py - y[0])


def tile_outer_corners(xyz, row0, col0, size, buffer):
    """The reader's M3: lesson 10's bound taken at the tile's outer corners."""
    xs, ys = np.meshgrid([col0, col0 + size], [row0, row0 + size])
    bound = max(_plane(xyz)(xs, ys).min(), np.asarray(xyz)[:, 2].min())
    return bool(bound >= np.max(buffer))


def nearest_vertex(xyz, row0, col0, size, buffer):
    return bool(np.asarray(xyz)[:, 2].min() >= np.max(buffer))


def test_m3_a_stored_depth_between_the_two_bounds_tells_them_apart(full_words):
    label = "the stored depth between the plane at the tile's outer corners and the nearest vertex"  # fmt: skip
    outer = ex.check("hiz_rejects", tile_outer_corners, budget=120)
    vertex = ex.check("hiz_rejects", nearest_vertex, budget=120)
    assert not any(label in f.case for f in outer.failures)
    assert any(label in f.case for f in vertex.failures)
    assert {f.kind for f in outer.failures} == {"tile outer corners"}, [f.kind for f in outer.failures]  # fmt: skip
    first = outer.failures[0].explanation
    assert "you evaluated the plane at the tile's outer corners" in first, first
    assert "nearest vertex (or a bound never above it" not in first, first
    assert "you compared the triangle's nearest vertex" in vertex.failures[0].explanation


def test_e1_the_picture_counts_coverage_apart_from_the_walk(plt):
    """r149 E1: "320 pixels differ" where pixels were covered wrongly and the rest only walked
    differently; cautious offsets (size steps) change the walk only: coverage right."""
    for fn, covered in ((student(tie="E >= 0"), "covered wrongly (red)"), (student(span="size"), "coverage right")):  # fmt: skip
        report = ex.check("classify_block", fn, budget=120)
        fig, axes = plt.subplots(1, 3)
        report.compare(axes, pixel="first")
        title = " ".join(axes[2].get_title().split())  # (wrapped to the panel's width)
        assert covered in title and "walked differently (orange)" in title, title
        assert "pixels differ" not in title, title


NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"


def _cell(grade_id: str) -> str:
    return graded_cell(NOTEBOOK, grade_id)


def test_c1_the_block_walk_is_not_credited_to_pineda():
    text = _cell("intro")
    assert "(Pineda, *A Parallel Algorithm for Polygon Rasterization*; Mesa's" not in text
    assert "came later (Greene" in text and "Abrash" in text and "McCormack" in text


def test_f1_llvmpipes_reject_test_is_said_right():
    text = _cell("classify_block_task")
    assert "so that the same `< 0` decides every edge, top-left or not." not in text
    assert "Its trivial *reject* does not use that −1" in text
    assert "`lp_setup_bin_triangle` tests `cx + eo` without it" in text
    assert "is the exact one" in text


def test_the_hiz_hint_asks_and_does_not_give_the_algorithm():
    text = _cell("hiz_rejects_task")
    hint = text[text.index("<details>") :]
    assert "the larger of that minimum and the" not in hint
    assert "is smallest at one of its four extreme centres" not in hint
    assert hint.count("?") >= 3


def test_e3_the_hiz_figure_shows_centres_and_its_labels_do_not_meet(plt):
    from teachraster.exercises import hiz_tile

    tries.spend_hints(["hiz_rejects"])
    try:
        case = next(c for c in hiz_tile.HIZ_REJECTS.cases() if c[1][3] == 16)
        fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
        hiz_tile.draw_hiz(ax, case, not case[2])
        fig.canvas.draw()
        assert any(line.get_label() == "pixel centres" for line in ax.lines)
        boxes = [t.get_window_extent() for t in ax.texts if t.get_text()[:1] in "0123456789"]
        assert len(boxes) == 4
        assert not [(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1 :] if a.overlaps(b)]
    finally:
        tries.forget_hints("hiz_rejects")
