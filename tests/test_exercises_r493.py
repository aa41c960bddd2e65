"""Exercise 10, r493's verifying read: the package's other GPU fills (lesson 02's
``study.precision.coverage``, the rational ground truth, the exact integer DDA, the batched
fill) are 10.2's answer and a search in 10.3, not counted (W1); a "snap" case reasoned with
round-half-up is told where each vertex snaps, half to even (H1); E in int32 with the area in
int64 is told it overflows int32 (H2); and right answers written another way pass."""

from __future__ import annotations

import numpy as np
import pytest
from reasoning_solutions import breaking_case as teacher
from student_variants import DIFFERENT, R493
from variant_checks import assert_first_named, assert_passes

from teachraster import exercises as ex
from teachraster.core.bbox import pixel_bbox
from teachraster.core.edges import setup_edges
from teachraster.core.fill import METHODS
from teachraster.exercises import breaking_case as bc
from teachraster.exercises import hard_case_fill as hf
from teachraster.exercises import tries
from teachraster.pipeline.rasterization.batched_fill import rasterize_batch
from teachraster.study.bench.ground_truth import exact_coverage
from teachraster.study.exact_spans import span_fill_int_dda
from teachraster.study.precision import coverage as precision_coverage


def _batch(xy, width, height):
    f = rasterize_batch(np.asarray(xy, float)[None], width, height)
    out = np.zeros((height, width), bool)
    out[f.row, f.col] = True
    return out


def _core(method):
    """The core's own fill of the triangle's box (an EdgeSetup), put into the window."""

    def fill(xy, width, height):
        setup = setup_edges(np.asarray(xy, float), 8)
        box = pixel_bbox(setup, width, height)
        out = np.zeros((height, width), bool)
        out[box.row0 : box.row1, box.col0 : box.col1] = METHODS[method](setup, box, False)[0]
        return out & (setup.area2 != 0)

    return fill


#: Each of the package's other fills as a student would call it (the window moved to (0, 0)).
WRAPPED = {
    **{f"core {method} fill": _core(method) for method in METHODS},
    "study.precision.coverage": lambda xy, w, h: precision_coverage(xy, w, h, "fixed8"),
    "study.precision.coverage, float64": lambda xy, w, h: precision_coverage(xy, w, h, "float64"),
    "exact_coverage": lambda xy, w, h: exact_coverage(xy, w, h),
    "span_fill_int_dda": span_fill_int_dda,
    "rasterize_batch": _batch,
}


@pytest.mark.parametrize("label", list(R493))
def test_each_r493_wrong_answer_is_named_in_its_first_words(label):
    name, fn, words, kind = R493[label]
    assert_first_named(name, fn, words, kind)


@pytest.mark.parametrize("label", [k for k in DIFFERENT if k.endswith("(r493)")])
def test_r493_right_answers_pass(label):
    assert_passes(*DIFFERENT[label])


def test_every_package_fill_is_listed_for_10_2_and_10_3():
    """One list: 10.3's search watches every fill 10.2 does not count."""
    listed = {a.function for a in hf.FILL_ANSWERS}
    assert set(hf.PACKAGE_FILLS) <= listed
    assert {a.function for a in bc.SEARCH_ANSWERS} == set(hf.PACKAGE_FILLS)


@pytest.mark.parametrize("label", list(WRAPPED))
def test_robust_fill_by_another_package_fill_is_not_counted(label):
    """r493 W1 (w42b, w43b, w78, w80): all 87 cases pass, and the report says why it does
    not count."""
    fill = WRAPPED[label]

    def robust_fill(xy, width, height, origin=(0, 0)):
        return fill(np.asarray(xy, float) - [origin[1], origin[0]], width, height)

    tries.forget_hints("robust_fill")
    report = ex.check("robust_fill", robust_fill)
    tries.forget_hints("robust_fill")
    assert not report.passed and "but not counted" in str(report), str(report)
    assert "a fill of the package's on the GPU's 1/256-px grid" in str(report) or (
        "top-left rule" in str(report)
    ), str(report)


@pytest.mark.parametrize("label", list(WRAPPED))
def test_a_search_with_another_package_fill_is_not_counted(label):
    """r493 W1 (w31, w32, w65): a breaking_case that runs one of them while it runs."""
    fill = WRAPPED[label]

    def breaking_case(repair):
        xy, width, height, origin = teacher(repair)
        if repair == "tie rule":
            fill(np.asarray(xy, float), width, height)  # a candidate tried at run time
        return xy, width, height, origin

    report = ex.check("breaking_case", breaking_case)
    assert not report.passed, str(report)
    assert "a search that runs it while breaking_case runs finds the case for you" in str(report)


def test_snap_words_say_a_half_way_vertex_may_round_down_or_up():
    """r493 H1: 641.5 steps go up to 642 (even), 1154.5 down to 1154 (even)."""
    up = bc.verdict("snap", (np.array([[2.505859375, 1], [2.505859375, 9], [9.00390625, 5]]),
                             12, 12, (0, 0)))  # fmt: skip
    assert up[0] == "snap moves no centre" and "641.5 steps of 1/256 px go to 642" in up[1], up
    assert "not up to" not in up[1]


def test_robust_fill_snapping_with_tr_snap_is_not_counted():
    """r493 (w83): the GPU's snapping is a repair the task asks for, as the top-left rule is."""
    from reasoning_solutions import robust_fill

    import teachraster as tr

    def with_snap(xy, width, height, origin=(0, 0)):
        return robust_fill(tr.snap(np.asarray(xy, float)), width, height, origin)

    tries.forget_hints("robust_fill")
    report = ex.check("robust_fill", with_snap)
    tries.forget_hints("robust_fill")
    assert not report.passed and "calls teachraster's snap" in str(report), str(report)
