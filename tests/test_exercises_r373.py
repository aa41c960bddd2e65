"""r373, exercise 10 (robust_fill): no wrong fill passes (the float64 absolute form 10⁶ px out,
int32 fixed point on a wide triangle), the task states the inputs' range, each of the reader's
misnamed or half-named variants is named by its own words on every failure (never by a cause
its code does not have: "snap first", float32), NaN is said as NaN, and the grid's code and
E's formula stay hints until two answers of the student's own have failed."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from student_variants import R373, _fill_r373

from teachraster import exercises as ex
from teachraster.exercises import hard_case_fill as hcf
from teachraster.exercises import tries
from teachraster.study.hardcases import naive_coverage

NOTEBOOK = Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb"


def _own_fill(v, width, height, origin=(0, 0), absolute=False, eps=None):
    """The top-left rule's fill in float64, written out (r441 W3: the package's naive_coverage
    with the top-left rule is the answer itself, and is not counted); with ``eps``, the ties
    decided by E > −ε and E > ε instead of E ≥ 0 and E > 0."""
    v = np.asarray(v, dtype=float)
    (ax, ay), (bx, by), (cx, cy) = v
    v = v[[0, 2, 1]] if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0 else v
    y = origin[0] + np.arange(height)[:, None] + 0.5
    x = origin[1] + np.arange(width)[None, :] + 0.5
    inside = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        if absolute:
            e = (a[1] - b[1]) * x + (b[0] - a[0]) * y + (a[0] * b[1] - a[1] * b[0])
        else:
            e = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        tie = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        if eps is None:
            inside &= (e >= 0) if tie else (e > 0)
        else:
            inside &= (e > -eps) if tie else (e > eps)
    return inside


def _teacher(xy, width, height, origin=(0, 0)):
    v = np.rint(np.asarray(xy, dtype=float) * 256) / 256
    return _own_fill(v, width, height, origin)


def _int64_bias(xy, width, height, origin=(0, 0)):
    """r373 C2: 1/256-px integers in int64, the top-left rule as a bias E + b >= 0."""
    v = np.rint(np.asarray(xy, dtype=float) * 256).astype(np.int64)
    (ax, ay), (bx, by), (cx, cy) = v
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if area == 0:
        return np.zeros((height, width), dtype=bool)
    v = v[[0, 2, 1]] if area < 0 else v
    ys = (origin[0] + np.arange(height, dtype=np.int64))[:, None] * 256 + 128
    xs = (origin[1] + np.arange(width, dtype=np.int64))[None, :] * 256 + 128
    out = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        dx, dy = b[0] - a[0], b[1] - a[1]
        out &= (
            dx * (ys - a[1]) - dy * (xs - a[0]) + (0 if dy < 0 or (dy == 0 and dx > 0) else -1) >= 0
        )
    return out


def _shifted_absolute(xy, width, height, origin=(0, 0)):
    """r373 C4: shifted by the window's origin first, then A x + B y + C in float64 (exact
    for small coordinates on the snapped grid)."""
    v = np.rint(np.asarray(xy, dtype=float) * 256) / 256 - [origin[1], origin[0]]
    return _own_fill(v, width, height, absolute=True)


def _tiny_epsilon(xy, width, height, origin=(0, 0)):
    """r373 C9: an ε of 1e-9 px², below E's step on the snapped grid, as a float image."""
    v = np.rint(np.asarray(xy, dtype=float) * 256) / 256
    return _own_fill(v, width, height, origin, eps=1e-9) * 1.0


@pytest.mark.parametrize("fn", [_int64_bias, _shifted_absolute, _tiny_epsilon])
def test_correct_fills_written_otherwise_pass(fn):
    assert ex.check("robust_fill", fn).passed


def test_the_fills_that_passed_now_fail_on_their_own_cases():
    """W24 fails the centre 2⁻¹⁵ px² inside an edge 10⁶ px out, W41 the 900-px triangle."""
    for label, case in (("fill in the absolute form in float64", "a centre 2⁻¹⁵ px²"),
                        ("fill in 1/256-px integers in int32", "px across")):  # fmt: skip
        report = ex.check("robust_fill", R373[label][0])
        # r386: int32 also fails the two float32 cases (784 and 823 px across)
        assert report.failures and all(case in f.case for f in report.failures), str(report)


@pytest.mark.parametrize("label", list(R373))
def test_each_variant_is_named_by_its_own_words_on_every_failure(label):
    """The first explanation names the mistake, and no later line blames a cause the code
    does not have (r373 W16, W21, W34, W40: "snap first", floor snapping, float32)."""
    fn, words, kind = R373[label]
    report = ex.check("robust_fill", fn)
    assert words in report.failures[0].explanation, report.failures[0].explanation
    assert {f.kind for f in report.failures} == {kind}, str(report)
    text = str(report)
    for other in ("float32", "snap first", "off the 1/256-px grid", "wrong type"):
        assert other not in text, (other, text)


def test_nan_in_the_image_is_said_as_nan_and_a_float_image_is_fine():
    report = ex.check("robust_fill", R373["fill with NaN at [0, 0]"][0])
    first = report.failures[0]
    assert first.kind == "nan" and "NaN at [0, 0]" in first.explanation, first.explanation
    assert "0 other pixel(s) wrong" in first.explanation, first.explanation
    assert ex.check("robust_fill", lambda *a: _teacher(*a) * 1.0).passed


def test_off_the_grid_is_said_only_of_an_answer_the_raw_vertices_give():
    """r373: OFF_GRID fitted every wrong answer on an off-grid case. A fill that snaps and
    flips one pixel of every window is told the rule, never "snap first"."""

    def flipped(xy, width, height, origin=(0, 0)):
        out = _teacher(xy, width, height, origin)
        out[-1, -1] = ~out[-1, -1]
        return out

    report = ex.check("robust_fill", flipped)
    assert not report.passed
    text = str(report)
    assert "off the grid" not in {f.kind for f in report.failures}, text
    assert "snap first" not in text and "raw vertices" not in text, text
    # the naive fill still gets the family (its answers are the raw vertices')
    naive = ex.check("robust_fill", lambda xy, w, h, origin=(0, 0): naive_coverage(
        xy, w, h, rule="inclusive", dtype=np.float32, absolute=True, origin=tuple(origin)))  # fmt: skip
    assert "off the grid" in {f.kind for f in naive.failures}, str(naive)


def _task() -> str:
    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    return next("".join(c["source"]) for c in cells
                if c["metadata"]["nbgrader"]["grade_id"] == "robust_fill_task")  # fmt: skip


def test_the_task_states_the_range_and_the_cases_reach_it():
    """r373 W41: the task bounds the inputs; the cases stay inside that bound and come near
    it (a triangle over half the width allowed, vertices over half the distance)."""
    text = _task()
    assert hcf.MOST_FAR == 2**20 and "2²⁰ px" in text
    assert f"{hcf.MOST_ACROSS:,} px across" in text and "64 pixels a side" in text
    cases = hcf.fill_cases()
    far = max(float(np.abs(xy).max()) for _, (xy, *_), _ in cases)
    across = max(float(np.ptp(xy, axis=0).max()) for _, (xy, *_), _ in cases)
    side = max(max(w, h) for _, (_, w, h, _), _ in cases)
    assert hcf.MOST_FAR / 2 < far <= hcf.MOST_FAR
    assert hcf.MOST_ACROSS / 2 < across <= hcf.MOST_ACROSS
    assert side == 64


def test_the_code_of_a_repair_is_a_hint_until_two_answers_of_yours_failed():
    """r373 T2: the naive fill's check (cell 3) is no try of the student's (the notebook
    forgets it); the first own try gets hints, the second different one the full words."""
    naive = lambda xy, w, h, origin=(0, 0): naive_coverage(  # noqa: E731
        xy, w, h, rule="inclusive", dtype=np.float32, absolute=True, origin=tuple(origin)
    )
    tries.forget_hints("robust_fill")
    try:
        ex.check("robust_fill", naive)
        tries.forget_hints("robust_fill")  # as the notebook's cell 3 does
        for fn in (R373["fill snapped with ceil"][0], R373["fill with ε = 1e-3 in the edge test"][0],
                   R373["fill in the absolute form in float64"][0]):  # fmt: skip
            tries.forget_hints("robust_fill")
            text = str(ex.check("robust_fill", fn))
            for code in ("np.rint", "(b.x − a.x)(p.y − a.y)", "differences to a vertex"):
                assert code not in text, (code, text)
        tries.forget_hints("robust_fill")
        ex.check("robust_fill", R373["fill snapped with ceil"][0])
        full = str(ex.check("robust_fill", R373["fill snapped with ceil"][0]))
        assert "a hint only" in full  # the same answer again is no second try
        floor = _fill_r373(round_xy=lambda xy: np.floor(xy * 256) / 256)
        full = str(ex.check("robust_fill", floor))
        assert "a hint only" not in full and "np.rint(xy * 256) / 256" in full, full
    finally:
        tries.spend_hints(["robust_fill"])


def test_the_notebook_forgets_the_naive_fills_check():
    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    naive = next("".join(c["source"]) for c in cells
                 if c["metadata"]["nbgrader"]["grade_id"] == "naive_fill")  # fmt: skip
    check = naive.index('ex.check("robust_fill", naive_fill)')
    assert naive.index('tries.forget_hints("robust_fill")') > check


@pytest.mark.parametrize(
    "knobs",
    [dict(round_xy=lambda xy: np.round(xy, 2), any_flat=True),
     dict(round_xy=lambda xy: np.ceil(xy * 256) / 256, eps=1e-3),
     dict(thin=0.5, tie_as_given=True),
     dict(round_xy=lambda xy: np.rint(xy * 512) / 512, eps=1e-2),
     dict(round_xy=lambda xy: np.floor(xy * 256) / 256, any_flat=True)],
)  # fmt: skip
def test_two_mistakes_of_a_float64_fill_that_snaps_get_no_invented_cause(knobs):
    """r373's class: a cause fitted on one coincident case ("snap first", float32 rounding,
    a precision failure, zero area) is not said of a float64 function that snaps; its
    failures get the rule where no one mistake gives them."""
    report = ex.check("robust_fill", _fill_r373(**knobs))
    assert not report.passed
    invented = {"off the grid", "float32 rounding", "far from origin", "zero area", "no snapping"}
    assert not {f.kind for f in report.failures} & invented, str(report)
    assert "float32" not in str(report), str(report)


def test_nothing_covered_is_said_alone_and_a_swapped_shape_once():
    """r373 W26: no rule's example after "never covers anything"; W32: the shape said once,
    then what the window is (not the same shapes twice)."""
    report = ex.check("robust_fill", lambda xy, w, h, origin=(0, 0): np.zeros((h, w), bool))
    assert all("For example" not in f.explanation for f in report.failures), str(report)

    first = ex.check("robust_fill", lambda xy, w, h, origin=(0, 0): np.zeros((w, h), bool))
    words = next(f.explanation for f in first.failures if "sliver_pair" in f.case)
    assert "4 rows (height) by 64 columns (width)" in words and words.count("(64, 4)") == 1


def test_the_absolute_form_in_float64_is_named_however_its_terms_are_grouped():
    """W24 written A x + (B y + C): its rounding differs from the table's A x + B y + C, and
    it is still named by its rounding, on its one failing case."""

    def grouped(xy, width, height, origin=(0, 0)):
        v = np.rint(np.asarray(xy, dtype=float) * 256) / 256
        (ax, ay), (bx, by), (cx, cy) = v
        v = v[[0, 2, 1]] if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0 else v
        y = origin[0] + np.arange(height)[:, None] + 0.5
        x = origin[1] + np.arange(width)[None, :] + 0.5
        out = np.ones((height, width), dtype=bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = (a[1] - b[1]) * x + ((b[0] - a[0]) * y + (a[0] * b[1] - a[1] * b[0]))
            tie = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            out &= (e >= 0) if tie else (e > 0)
        return out

    report = ex.check("robust_fill", grouped)
    assert {f.kind for f in report.failures} == {"absolute form in float64"}, str(report)
    assert "float64's numbers are" in report.failures[0].explanation


def test_a_triangle_smaller_than_a_pixel_is_drawn_again_magnified():
    """r373 E2: snap_flips_winding was a dot with "v1, v2, v3" piled on it; the case figures
    name their axes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("robust_fill", R373["fill with ε = 1e-3 in the edge test"][0])
    assert report.failures[0].case == "snap_flips_winding"
    fig, ax = plt.subplots()
    try:
        report.plot(ax)
        assert ax.get_xlabel().startswith("column") and ax.get_ylabel().startswith("row")
        (inset,) = ax.child_axes
        assert inset.get_title().startswith("magnified")
        assert {t.get_text() for t in inset.texts} >= {"v1", "v2", "v3", "centre"}
    finally:
        plt.close(fig)
