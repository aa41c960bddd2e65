"""r162 (exercise 08_tiles): misdiagnoses, unnamed causes, contradictions and figures, each with
the reader's wrong answer (written as a student would) and the words its report must give and
must not.

M1: offsets that stop short of the block's last pixel centre (size − 2 steps; the half span
from the first centre; the centre form with integer division) were told "Corners outside the
triangle do not reject a block" or "you tested the maximising one". M2 (8.2): the plane at the
bounding box's own corners (with an empty box kept) was told "you took lesson 10's bound" (both
0.300 on the first failing case). Unnamed: ``<=`` in the reject test, ``>`` in the accept test,
vertices cast to int, 8.2's columns one past the tile. C1: +∞ against GL's clear value 1.0. C2:
cases drawn afresh on every check. F1: llvmpipe's reject test one unit outside a top or left
edge. Figures: the endless loop's note over the key; an off-screen bounding box in the legend.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from graded_cells import graded_cell
from test_exercise_8_1_offsets import student

# the fixtures of r149's tests: pyplot, the full words
from test_exercises_r149 import full_words, plt  # noqa: F401

from teachraster import exercises as ex
from teachraster.exercises import tries

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"
#: The generic rule's guesses at a cause that M1's answers do not have.
WRONG_CAUSES = ("Corners outside the triangle do not reject", "you tested the maximising one")


@pytest.fixture
def first_words():
    """The words of a first failing check (hint only), as a fresh kernel gives them."""
    tries.forget_hints("classify_block")
    tries.forget_hints("hiz_rejects")
    yield
    tries.forget_hints("classify_block")
    tries.forget_hints("hiz_rejects")


def centre_floored(xy, x0, y0, size):
    """The reader's third M1: the centre form with integer division, E at x0 + size//2 and a
    half span of (size − 1)//2 steps."""
    p = np.array(xy, dtype=float)
    area = (p[1, 0] - p[0, 0]) * (p[2, 1] - p[0, 1]) - (p[1, 1] - p[0, 1]) * (p[2, 0] - p[0, 0])
    x0, y0 = np.asarray(x0, dtype=float), np.asarray(y0, dtype=float)
    if area == 0:
        return np.full(x0.shape, "rejected", dtype=object)
    if area < 0:
        p = p[::-1]
    cx, cy = x0 + size // 2, y0 + size // 2
    rejected, accepted = np.zeros(x0.shape, bool), np.ones(x0.shape, bool)
    for i in range(3):
        (ax, ay), (bx, by) = p[i], p[(i + 1) % 3]
        a, b = ay - by, bx - ax
        c = -(a * ax + b * ay)
        half = ((size - 1) // 2) * (abs(a) + abs(b))
        top_left = by < ay or (by == ay and bx > ax)
        e = a * cx + b * cy + c
        beta = 0.0 if top_left else -(2.0**-16)  # after the offset, where it is exact (r232)
        rejected |= e + half + beta < 0
        accepted &= e - half + beta >= 0
    return np.select([rejected, accepted], ["rejected", "accepted"], "partial")


UNDERSHOOT = {
    "size - 2 steps": (student(span="size - 2", bias=2.0**-16), "offsets of size − 2 steps"),
    "half span from the first centre": (
        student(span="(size - 1) / 2", bias=2.0**-16), "half span from the first centre"),
    "centre form with //": (centre_floored, "centre form, integer division"),
}  # fmt: skip


@pytest.mark.parametrize("name", list(UNDERSHOOT))
def test_m1_offsets_short_of_the_last_centre_are_named_so(name, full_words):  # noqa: F811
    fn, kind = UNDERSHOOT[name]
    report = ex.check("classify_block", fn, budget=120)
    assert not report.passed
    assert _kinds_apart_from_float64(report) == {kind}, [f.kind for f in report.failures]
    for f in report.failures:
        if f.kind == "float64 pixels":
            continue
        assert "short of the block's" in f.explanation, f.explanation
        assert not [w for w in WRONG_CAUSES if w in f.explanation], f.explanation


@pytest.mark.parametrize("name", list(UNDERSHOOT))
def test_m1_the_first_words_name_it_without_the_answer(name, first_words):
    fn, kind = UNDERSHOOT[name]
    first = ex.check("classify_block", fn, budget=120).failures[0]
    assert first.kind == kind and "short of the block's" in first.explanation, first.explanation
    assert not [w for w in WRONG_CAUSES if w in first.explanation], first.explanation
    # the task's answer (size − 1 steps) is asked, not told, on a first failure
    assert "scale the offsets by size − 1" not in first.explanation, first.explanation
    assert "(size − 1)/2, not" not in first.explanation, first.explanation


def test_m1_the_generic_rule_guesses_no_cause(full_words):  # noqa: F811
    """A wrong answer no mistake fits gets the rule, with no guessed cause (r162 M1)."""
    from teachraster.exercises.tile_blocks import _by_verdicts, _edge_table

    xy = [[2.5, 2.5], [29.5, 6.5], [8.5, 27.5]]
    edges = _edge_table(xy, 16, 4, 4)
    for want, got in (("partial", "rejected"), ("partial", "accepted")):
        words = _by_verdicts(edges, want, got)
        assert not [w for w in WRONG_CAUSES if w in words], words


def vertices_as_int(xy, x0, y0, size):
    return student(bias=2.0**-16)(np.asarray(xy).astype(int), x0, y0, size)


SLIPS = {
    "reject with <=": (student(bias=2.0**-16, ops=("<=", ">=")), "reject test E ≤ 0",
                       "your reject test rejects when E₀ + R + β ≤ 0"),
    "accept with >": (student(bias=2.0**-16, ops=("<", ">")), "accept test E > 0",
                      "your accept test asks E₀ + T + β > 0"),
    "vertices cast to int": (vertices_as_int, "vertices cast to int",
                             "you cast the vertices to int"),
}  # fmt: skip


@pytest.mark.parametrize("name", list(SLIPS))
def test_unnamed_8_1_slips_are_named(name, full_words):  # noqa: F811
    fn, kind, words = SLIPS[name]
    report = ex.check("classify_block", fn, budget=120)
    assert not report.passed
    assert _kinds_apart_from_float64(report) == {kind}, [f.kind for f in report.failures]
    assert all(words in f.explanation for f in report.failures if f.kind == kind), report.failures[0].explanation  # fmt: skip


def _kinds_apart_from_float64(report) -> set:
    """The report's kinds, those of the far float64 ties left out where they are float64
    pixels' (r248 F1: these students compute in float64 pixels, a second slip of their own)."""
    far = [f for f in report.failures if f.case.startswith("far out in float64")]
    assert all(f.kind == "float64 pixels" for f in far if f.kind not in {g.kind for g in report.failures if g not in far})  # fmt: skip
    return {f.kind for f in report.failures if f not in far or f.kind != "float64 pixels"}


def _plane(xyz):
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = np.asarray(xyz, float)
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    a = ((z2 - z1) * (y3 - y1) - (z3 - z1) * (y2 - y1)) / area
    b = ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1)) / area
    return lambda x, y: z1 + a * (x - x1) + b * (y - y1)


def box_corners_clamped(xyz, row0, col0, size, buffer):
    """The reader's M2: the plane at the bounding box's own corners, clamped into the tile's
    range of centres, no rounding to a centre and no rejection of an empty box."""
    p = np.asarray(xyz, float)
    lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
    xs = np.clip([lo[0], hi[0]], col0 + 0.5, col0 + size - 0.5)
    ys = np.clip([lo[1], hi[1]], row0 + 0.5, row0 + size - 0.5)
    z = [_plane(p)(x, y) for x in xs for y in ys]
    return bool(max(min(z), p[:, 2].min()) >= np.max(buffer))


def box_corners_empty_rejected(xyz, row0, col0, size, buffer):
    """The same with an empty box rejected (the task's rule there)."""
    p = np.asarray(xyz, float)
    lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
    cols = (max(col0, math.ceil(lo[0] - 0.5)), min(col0 + size - 1, math.floor(hi[0] - 0.5)))
    rows = (max(row0, math.ceil(lo[1] - 0.5)), min(row0 + size - 1, math.floor(hi[1] - 0.5)))
    if cols[0] > cols[1] or rows[0] > rows[1]:
        return True
    return box_corners_clamped(xyz, row0, col0, size, buffer)


def lesson_10_bound(xyz, row0, col0, size, buffer):
    p = np.asarray(xyz, float)
    z = [_plane(p)(x + 0.5, y + 0.5) for x in (col0, col0 + size - 1) for y in (row0, row0 + size - 1)]  # fmt: skip
    return bool(max(min(z), p[:, 2].min()) >= np.max(buffer))


def columns_one_past(xyz, row0, col0, size, buffer):
    """The reader's off-by-one: the tile's last column and row taken as col0 + size."""
    p = np.asarray(xyz, float)
    lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
    c = (max(col0, math.ceil(lo[0] - 0.5)), min(col0 + size, math.floor(hi[0] - 0.5)))
    r = (max(row0, math.ceil(lo[1] - 0.5)), min(row0 + size, math.floor(hi[1] - 0.5)))
    if c[0] > c[1] or r[0] > r[1]:
        return True
    z = [_plane(p)(x + 0.5, y + 0.5) for x in c for y in r]
    return bool(max(min(z), p[:, 2].min()) >= np.max(buffer))


HIZ = {
    "box corners, empty kept": (box_corners_clamped, "box corners, empty kept",
                                "you took the plane at the bounding box's own corners"),
    "box corners": (box_corners_empty_rejected, "box corners",
                    "you took the plane at the bounding box's own corners"),
    "lesson 10's bound": (lesson_10_bound, "whole tile", "you took lesson 10's bound"),
    "one past the tile": (columns_one_past, "one past the tile",
                          "one past the tile's last"),
}  # fmt: skip


@pytest.mark.parametrize("name", list(HIZ))
def test_m2_a_bound_is_named_only_where_it_tells_the_answer_apart(name, full_words):  # noqa: F811
    fn, kind, words = HIZ[name]
    report = ex.check("hiz_rejects", fn, budget=120)
    assert not report.passed
    assert {f.kind for f in report.failures} == {kind}, [f.kind for f in report.failures]
    for f in report.failures:
        # r173 M2: the clipped box with an empty box kept says each flaw where it decides
        # (test_exercises_r173); here its box holds a centre of the tile
        if kind == "box corners, empty kept" and "holds no pixel centre" in f.explanation:
            continue
        assert words in f.explanation, f.explanation
        if kind != "whole tile":
            assert "lesson 10's bound" not in f.explanation, f.explanation


def test_m2_the_empty_box_is_said_too(full_words):  # noqa: F811
    """The empty box kept is said on the case whose box holds no centre of the tile (r173 M2:
    only there, where it decides the case)."""
    report = ex.check("hiz_rejects", box_corners_clamped, budget=120)
    said = [f.explanation for f in report.failures
            if "you kept the block where the triangle's bounding box holds no centre" in f.explanation]  # fmt: skip
    assert said and all("holds no pixel centre of the tile" in s for s in said), said


def test_the_first_8_2_failure_does_not_print_the_bound(first_words):
    """C.1 (r149, r162): the task's bound on the case is the answer; a first failure asks."""
    first = ex.check("hiz_rejects", lesson_10_bound, budget=120).failures[0].explanation
    assert "so the bound (no nearer than the nearest vertex) is" not in first, first
    assert "0.312" not in first, first
    # r232 S2: no boilerplate before the cause; C2: the case's arguments, to call it again
    assert "what is it here?" not in first and "decides" not in first, first
    assert first.startswith(  # (r248 S1: statements, runnable as one line)
        "xyz = np.array([[4.2, 4.2, 0.3], [7.8, 4.2, 0.372], [4.2, 7.8, 0.372]]); row0 = 0"
    )
    assert "the tile's farthest stored depth is 0.305: the block is rejected" in first, first


def test_c1_an_empty_pixel_is_said_beside_gls_clear_value(full_words):  # noqa: F811
    def as_far_plane(xyz, row0, col0, size, buffer):
        """The task's bound, right, with an empty pixel read as 1.0 (no package call: the
        checker's own functions are watched and not counted)."""
        p = np.asarray(xyz, float)
        lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
        c = (max(col0, math.ceil(lo[0] - 0.5)), min(col0 + size - 1, math.floor(hi[0] - 0.5)))
        r = (max(row0, math.ceil(lo[1] - 0.5)), min(row0 + size - 1, math.floor(hi[1] - 0.5)))
        if c[0] > c[1] or r[0] > r[1]:
            return True
        z = [_plane(p)(x + 0.5, y + 0.5) for x in c for y in r]
        far = np.max(np.where(np.isinf(buffer), 1.0, buffer))
        return bool(max(min(z), p[:, 2].min()) >= far)

    # r248 S2: GL's clear value is what a GPU holds: the reading passes (the task says both)
    report = ex.check("hiz_rejects", as_far_plane, budget=120)
    assert report.passed, str(report)
    task = _cell("hiz_rejects_task")
    for said in ("GL holds its clear value, 1.0 (lesson 05a)", "`GL_LESS`",
                 "as in lesson 10's replay", "`np.inf` in the check's buffers (*not yet known*"):  # fmt: skip
        assert said in " ".join(task.split()), said  # r214: re-wrapped


@pytest.mark.parametrize("name", ["classify_block", "hiz_rejects"])
def test_c2_every_case_is_the_same_on_every_check(name):
    from teachraster.exercises.checks import exercise

    first, second = exercise(name).cases(), exercise(name).cases()
    assert [c[0] for c in first] == [c[0] for c in second]
    for (_, a, want_a), (_, b, want_b) in zip(first, second, strict=True):
        assert all(np.array_equal(x, y) for x, y in zip(a, b, strict=True))
        assert np.array_equal(want_a, want_b)
    assert not [c[0] for c in first if c[0].startswith("drawn for this check")]


def test_c2_the_same_wrong_code_fails_the_same_cases_twice():
    """The reader's "no orientation" failed 17, 18 and 19 of 47 on three runs."""
    fn = student(orient=False)
    runs = [ex.check("classify_block", fn, budget=120) for _ in range(3)]
    assert len({tuple(f.case for f in r.failures) for r in runs}) == 1
    assert "seeded random ones (the same cases on every run" in _cell("intro")


def _cell(grade_id: str) -> str:
    return graded_cell(NOTEBOOK, grade_id)


def test_f1_llvmpipe_also_keeps_a_block_one_unit_outside_a_top_or_left_edge():
    text = " ".join(_cell("classify_block_task").split())
    assert "**or one unit outside a top or left edge** (E = −1)" in text, text
    assert "asks E + 1 < 0 on a top or left edge and E < 0 on any other" in text
    # the bias is the task's question: no px² value given
    assert "1/65536" not in text and "2^-16" not in text


def test_8_1_no_longer_gives_size_minus_one_away():
    assert "so its offsets are 0" not in _cell("classify_block_task")


def test_8_2_states_the_goal_not_the_recipe():
    task = _cell("hiz_rejects_task")
    assert "The bound the check takes is the plane's minimum" not in task
    # r214 item 10: "highest" overclaimed; the bound these facts give for a few numbers
    assert "the **highest** lower bound" not in task
    assert "a few numbers per tile" in " ".join(task.split())


def test_the_endless_loops_note_leaves_the_key_readable(plt):  # noqa: F811
    def loop(xy, x0, y0, size):
        while True:
            pass

    report = ex.check("classify_block", loop, budget=1.0)
    fig, ax = plt.subplots(figsize=(9.0, 3.6), layout="constrained")
    report.plot(ax)
    fig.canvas.draw()
    note = next(t for t in ax.texts if "did not finish" in t.get_text())
    key = ax.get_legend()
    assert key is not None
    assert not note.get_window_extent().overlaps(key.get_window_extent())


def test_the_passing_hiz_figure_lists_no_box_it_does_not_draw(plt):  # noqa: F811
    from teachraster.exercises import hiz_tile

    case = next(c for c in hiz_tile.HIZ_REJECTS.cases() if c[0].startswith("a flat triangle"))
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    hiz_tile.draw_hiz(ax, case, case[2])
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "its bounding box" not in labels and "its bounding box: beyond this view" in labels
    # a box the view shows keeps its entry
    small = next(c for c in hiz_tile.HIZ_REJECTS.cases() if c[0].startswith("a small triangle"))
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    hiz_tile.draw_hiz(ax, small, small[2])
    assert "its bounding box" in [t.get_text() for t in ax.get_legend().get_texts()]


def test_a_failing_check_lets_run_all_go_on():
    """r162 D6: Run All stopped at 8.1's failing check, so 8.2 never ran; the check cells keep
    nbgrader's AssertionError but are tagged ``raises-exception`` (JupyterLab then sends
    ``stop_on_error: false``, and the cells after it run)."""
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    checks = [c for c in cells if c["metadata"].get("nbgrader", {}).get("grade")]
    assert len(checks) == 2
    for c in checks:
        assert "report.assert_passed()" in "".join(c["source"])
        assert "raises-exception" in c["metadata"].get("tags", []), c["metadata"]
