"""Review r94 (exercises 03, 08, 12 played as students): the mistakes it found misnamed,
the wrong answer that passed, and the words that gave the answer on the first try.

A first try is checked with the staged hints on (as in a fresh kernel), the named mistakes
with the hints spent (as after two different failing answers).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from test_exercises_r85 import _first_try, _words  # a first try in a fresh kernel

from teachraster import exercises as ex
from teachraster.exercises import tries


@pytest.fixture
def plt():
    pytest.importorskip("matplotlib").use("Agg")
    import matplotlib.pyplot as pyplot

    yield pyplot
    pyplot.close("all")


def _hiz(bound):
    """hiz_rejects from the plane at the four extreme centres of the tile's part inside the
    triangle's bounding box (bare; +inf where it holds no centre, r126 N8-1) and the nearest
    vertex, combined by ``bound(plane_min, plane_max, nearest_vertex, buffer) -> bool``."""

    def hiz_rejects(xyz, row0, col0, size, buffer):
        (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = np.asarray(xyz, dtype=float)
        c0, c1 = (
            max(col0, math.ceil(min(x1, x2, x3) - 0.5)),
            min(col0 + size - 1, math.floor(max(x1, x2, x3) - 0.5)),
        )
        r0, r1 = (
            max(row0, math.ceil(min(y1, y2, y3) - 0.5)),
            min(row0 + size - 1, math.floor(max(y1, y2, y3) - 0.5)),
        )
        if c0 > c1 or r0 > r1:
            return bool(bound(np.inf, np.inf, min(z1, z2, z3), np.asarray(buffer)))
        cols = np.array([c0, c1, c0, c1]) + 0.5
        rows = np.array([r0, r0, r1, r1]) + 0.5
        area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
        lam2 = ((cols - x1) * (y3 - y1) - (rows - y1) * (x3 - x1)) / area
        lam3 = ((x2 - x1) * (rows - y1) - (y2 - y1) * (cols - x1)) / area
        plane = z1 + lam2 * (z2 - z1) + lam3 * (z3 - z1)
        return bool(bound(plane.min(), plane.max(), min(z1, z2, z3), np.asarray(buffer)))

    return hiz_rejects


def test_hiz_right_answer_passes():
    assert ex.check("hiz_rejects", _hiz(lambda lo, hi, v, b: max(lo, v) >= b.max())).passed


@pytest.mark.parametrize(("bound", "named", "wrong"), [
    # r94 D8-6 (a): both bounds computed, the smaller taken: told "use ≥", "nearest vertex"
    (lambda lo, hi, v, b: min(lo, v) >= b.max(), "smaller of the two bounds",
     ("use ≥", "compared the triangle's nearest vertex", "bare plane")),
    # r94 D8-6 (b): the plane's largest corner: told "the triangle's farthest vertex"
    (lambda lo, hi, v, b: max(hi, v) >= b.max(), "the plane's largest value at the corners",
     ("farthest vertex",)),
])  # fmt: skip
def test_hiz_names_the_mistake_on_every_failure_and_no_other(bound, named, wrong):
    report = ex.check("hiz_rejects", _hiz(bound))
    assert not report.passed
    for f in report.failures:
        assert named in f.explanation, str(report)
    for w in wrong:
        assert w not in _words(report), str(report)


def test_hiz_an_empty_pixel_read_as_gls_clear_value_passes():
    """r94 D8-5 named an empty pixel read as the far plane, 1.0; r248 S2: that is what a GPU
    holds after a clear (GL's default 1.0), and the check accepts it (the two readings differ
    only for a triangle at exactly depth 1.0)."""
    assert ex.check("hiz_rejects", _hiz(lambda lo, hi, v, b: max(lo, v) >= np.where(np.isinf(b), 1.0, b).max())).passed  # fmt: skip


def test_hiz_first_try_keeps_the_extreme_centres_and_the_larger_bound():
    """r94 D8-3: row and column swapped gave the tile's extreme centres on the first try."""

    def swapped(xyz, row0, col0, size, buffer):
        return _hiz(lambda lo, hi, v, b: max(lo, v) >= b.max())(xyz, col0, row0, size, buffer)

    first = _words(_first_try("hiz_rejects", swapped))
    assert "you swapped the tile's row and column" in first, first
    assert "col0 + ½" not in first, first
    assert "col0 + ½" in _words(ex.check("hiz_rejects", swapped))
    smaller = _words(_first_try("hiz_rejects", _hiz(lambda lo, hi, v, b: min(lo, v) >= b.max())))
    assert "smaller of the two bounds" in smaller and "the larger of the two" not in smaller


def test_hiz_case_figure_draws_the_extreme_centres_only_once_the_hints_are_spent(plt):
    """r94 D8-3: the first failing try's figure drew the four extreme centres and the plane
    there (the answer); D8-12: the triangle tinted the stored depths."""
    from teachraster.exercises.hiz_tile import draw_hiz, hiz_cases

    case = hiz_cases()[4]
    tries.forget_hints("hiz_rejects")
    try:
        fig, ax = plt.subplots()
        draw_hiz(ax, case, False)
        keys = [t.get_text() for t in ax.get_legend().get_texts()]
        assert not any("circles" in k for k in keys) and not ax.texts, keys
        assert not any(p.get_fill() for p in ax.patches)
    finally:
        tries.spend_hints(["hiz_rejects"])
    fig, ax = plt.subplots()
    draw_hiz(ax, case, False)
    keys = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("circles" in k for k in keys) and len(ax.texts) == 4, keys


def test_capstone_quotes_the_depth_mistake_at_the_pixel_not_the_exercises_first():
    """r94 D12-1: ``<=`` with glass writing depth, at a tie where every fragment writes,
    was told the glass's words (exercise 4's first failure)."""
    import student_variants as sv
    from test_capstone import _mine

    both = sv._passes_with(ties=True, mask=False)
    report = ex.capstone("intersecting_triangles", **_mine("intersecting_triangles",
                                                            depth_passes=both))  # fmt: skip
    first = report.failures[0].explanation
    assert "use <, not <=" in first and "leaves the buffer" not in first, first


def _block(**knobs):
    from teachraster.exercises.tile_blocks import classify_with

    return lambda xy, x0, y0, size: classify_with(xy, x0, y0, size, **knobs)


def _covered_corners(xy, x0, y0, size):
    """Accepted iff the four extreme centres are covered; rejected per edge (r94 c3), block
    by block over the grid."""
    from exercise_solutions import per_block

    return per_block(_covered_corners_one)(xy, x0, y0, size)


def _covered_corners_one(xy, x0, y0, size):
    from exercise_solutions import _one_block

    kind = _one_block(xy, x0, y0, size)
    if kind == "rejected":
        return kind
    # each extreme centre's coverage, exact (a one-pixel block there is accepted iff it is
    # covered; r248 F1: the checker's float64 ``covered`` rounds at the far float64 ties)
    corners = [(x0 + dx, y0 + dy) for dx in (0, size - 1) for dy in (0, size - 1)]
    inside = all(_one_block(xy, x, y, 1) == "accepted" for x, y in corners)
    return "accepted" if inside else "partial"


def test_block_corners_inside_words_are_true_and_said_once():
    """r94 D8-1: "(nor do corners inside accept it)" was false (accepting by the four covered
    corner centres passes); D8-2: "Corners outside … per edge" said twice."""
    assert ex.check("classify_block", _covered_corners).passed
    report = ex.check("classify_block", _block(logic="inside"))
    words = _words(report)
    assert "corners outside the triangle do not reject" in words, words
    assert "nor do corners inside" not in words
    for f in report.failures:
        assert f.explanation.lower().count("corners outside the triangle do not reject") <= 1


@pytest.mark.parametrize(("knobs", "named", "kept"), [
    ({"points": "x0 y0 swapped"}, "you swapped x0 and y0", "x0 + ½"),
    ({"points": "beyond"}, "your offsets span size steps", "x0 + size − ½"),
    ({"offsets": "two corners"}, "only 2 of the 4", "test all four"),
])  # fmt: skip
def test_block_first_try_names_the_mistake_without_the_extreme_centres(knobs, named, kept):
    """r94 D8-3: "a hint only" lines gave the extreme centres (or the method)."""
    first = _words(_first_try("classify_block", _block(**knobs)))
    assert named in first and kept not in first, first
    assert kept in _words(ex.check("classify_block", _block(**knobs)))


def test_two_corners_reason_is_this_cases():
    """r94 D8-8: "partial; yours says rejected" was told an edge "can pass both"."""
    report = ex.check("classify_block", _block(offsets="two corners"))
    for f in report.failures:
        if "yours says rejected" in f.explanation:
            assert "can fail both and pass one" in f.explanation, f.explanation
        elif "only 2 of the 4" in f.explanation:
            assert "can pass both and fail one" in f.explanation, f.explanation


def test_block_hint_does_not_call_the_tested_point_the_blocks_centre():
    """r94 D8-4: "even the block's centre where its E is largest" read as the geometric
    centre, the very point a one-point test used."""
    from teachraster.exercises.tile_blocks import BLOCK_HINTS

    # "the block's centres" (all of them, r162's "where do the block's centres begin and
    # end?") is not the one point
    assert not any(re.search(r"block's centre(?!s)", hint) for _, hint in BLOCK_HINTS)


def test_tile_scene_shows_x0_y0_swapped_and_hides_the_centres_on_the_first_try():
    """r94 D8-10: the scene's triangle was symmetric about x = y, so x0 and y0 swapped drew
    the package's picture; D8-3: its caption gave the extreme centres on the first try."""
    from teachraster.exercises.picture_scenes import tile_scene

    scene = tile_scene(_block(points="x0 y0 swapped"))
    mine = scene.run()
    assert (mine != scene.reference).any()
    row, col = np.argwhere(mine != scene.reference)[0]
    tries.forget_hints("classify_block")
    try:
        first = scene.explain_at(mine, row, col)
    finally:
        tries.spend_hints(["classify_block"])
    assert "extreme centres" not in first and "x0=" in first, first
    assert "extreme centres x =" in scene.explain_at(mine, row, col)


@pytest.mark.parametrize("knobs", [
    {"points": "outer corners"}, {"tie": "loose"},
    {"logic": "inside"}, {"offsets": "two corners"}, {"points": "x0 y0 swapped"},
    {"points": "beyond"}, {"points": "pixel corners"},
])  # fmt: skip
def test_tile_scene_still_shows_each_classic_mistake(knobs):
    from teachraster.exercises.picture_scenes import tile_scene

    scene = tile_scene(_block(**knobs))
    assert (scene.run() != scene.reference).any(), knobs


def _bary(order=(0, 1, 2), p_swapped=False, clamp=False, solve=False):
    """barycentric by the signed areas (or a 3×3 solve), with r94's mistakes as knobs."""

    def barycentric(xy, p):
        xy, p = np.asarray(xy, dtype=float), np.asarray(p, dtype=float)
        if p_swapped:
            p = p[::-1]
        if solve:  # r153 D3-1: LinAlgError is no zero-area test; the exact one first
            (x1, y1), (x2, y2), (x3, y3) = xy
            if (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1) == 0:
                raise ValueError("zero area")
            lam = np.linalg.solve(np.vstack([xy.T, np.ones(3)]), np.array([p[0], p[1], 1.0]))
        else:

            def e(a, b, q):
                return (b[0] - a[0]) * (q[1] - a[1]) - (b[1] - a[1]) * (q[0] - a[0])

            v1, v2, v3 = xy
            if e(v1, v2, v3) == 0:  # exercise 3.1 since ex30b: no weights, ValueError
                raise ValueError("zero area")
            lam = np.array([e(v2, v3, p), e(v3, v1, p), e(v1, v2, p)]) / e(v1, v2, v3)
        if clamp:
            lam = np.maximum(lam, 0.0)
            lam = lam / lam.sum()
        return lam[list(order)]

    return barycentric


@pytest.mark.parametrize(("fn", "named"), [
    (_bary(clamp=True), "your weights are never negative"),
    (_bary(p_swapped=True), "you swapped p's x and y"),
])  # fmt: skip
def test_barycentric_common_mistakes_are_named_on_the_first_try(fn, named):
    """r94 D3-5: clamped weights and p's x and y swapped got only the rule."""
    assert (
        ex.check("barycentric", _bary()).passed
        and ex.check("barycentric", _bary(solve=True)).passed
    )
    report = _first_try("barycentric", fn)
    assert named in report.failures[0].explanation, str(report)


def test_weights_in_another_order_are_not_given_the_area_ratio_on_the_first_try():
    """r94 D3-7: a 3×3 solve returned reversed was told "the area of the sub-triangle …"."""
    fn = _bary(order=(2, 1, 0), solve=True)
    first = _words(_first_try("barycentric", fn))
    assert "another order" in first and "sub-triangle" not in first, first
    assert "λ_i = 1 at v_i" in first
    assert "sub-triangle" in _words(ex.check("barycentric", fn))


def _persp(kind):
    def perspective_weights(lam, w):
        lam, w = np.asarray(lam, dtype=float), np.asarray(w, dtype=float)
        if kind == "clamped":
            lam = np.maximum(lam, 0.0)
        if kind == "reversed ratios":
            q = lam * (w.max() / w)
        elif kind == "over w squared":
            q = lam * (w.min() / w) ** 2
        else:  # r421 T2: by the smallest w that weighs (the smallest of all underflows)
            live = lam != 0
            q = np.zeros(3)
            q[live] = lam[live] * (w[live].min() / w[live])
        return q / q.sum()

    return perspective_weights


def test_perspective_weights_that_sum_to_1_are_not_told_to_sum_to_1():
    """r94 D3-3: λ/w² (weights summing to 1) was told "… and make the weights sum to 1"."""
    assert ex.check("perspective_weights", _persp("right")).passed
    for report in (_first_try("perspective_weights", _persp("over w squared")),
                   ex.check("perspective_weights", _persp("over w squared"))):  # fmt: skip
        words = _words(report)
        assert "make the weights sum to 1" not in words and "normalised to sum" not in words
        # r164 B5: λ/w² is named now (it was told the rule, "yours already sum to 1")
        assert "you divided each λ by its w twice" in words, words


def test_clamped_perspective_weights_are_named_here_and_in_the_capstone():
    """r94 D3-3, D12-4: clamping (the package's own default) got the normalisation hint."""
    from test_capstone import _mine

    report = _first_try("perspective_weights", _persp("clamped"))
    assert "your weight is 0 where λ is negative" in _words(report), str(report)
    assert "make the weights sum to 1" not in _words(report)
    cap = ex.capstone("textured_floor", **_mine("textured_floor",
                                                perspective_weights=_persp("clamped")))  # fmt: skip
    last = cap.failures[-1].explanation
    assert "your weight is 0 where λ is negative" in last and "sum to 1" not in last, last


def test_the_direction_of_the_ratio_matters_again_beyond_a_gpus_w():
    """r94 D3-4: λ·(max w / w) passed: no case had w more than 1.8e308 apart; r126 D3-1 graded
    only w a GPU meets, where scaling by any w is right; r421 T2 grades w 1e610 apart again,
    where the ratio overflows, and names it (r429 M1: as the source of its NaN, never by
    NaN == NaN)."""
    report = ex.check("perspective_weights", _persp("reversed ratios"))
    kinds = {f.kind for f in report.failures}
    assert not report.passed and kinds == {"NaN beyond a GPU's range"}, str(report)
    assert all("w beyond a GPU's range" in f.case for f in report.failures), str(report)
    assert "makes its ratio" in report.failures[0].explanation, str(report)


def _markdown(name: str) -> str:
    import json
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "notebooks" / "exercises" / f"{name}.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")


def test_hiz_main_text_defines_the_answer_the_check_takes():
    """r94 D8-7: "reject whenever no fragment … could pass" defined the per-pixel answer the
    check fails; the bound asked was stated only in the hint."""
    text = _markdown("08_tiles")
    main = text.split("## 8.2", 1)[1].split("<details>", 1)[0]
    assert "no fragment of the triangle in this tile\ncould pass" not in main
    flat = " ".join(main.split())
    # r126 N8-1: the bound is lesson 10's cut to the box; r162: the main text asks for it (the
    # highest lower bound from the box and lesson 10's two bounds) without giving it away
    assert "no fragment of the triangle lies outside its bounding box" in flat, flat
    # r214 item 10: "the **highest** lower bound" overclaimed (a centre where the plane runs
    # nearer than the nearest vertex cannot hold a fragment either): the bound these facts give
    # for a few numbers per tile
    assert "the **highest** lower bound" not in flat, flat
    # r376: the bound is no longer spelled out, only what gives it
    assert "the one that this fact and lesson 10's two give together" in flat, flat
    assert "never a coverage test per pixel" in flat, flat
    assert "rejected at once when a lower bound" in flat, flat


def test_capstone_says_how_an_uncovered_sample_looks_and_that_over_is_copied():
    """r94 D12-3: nothing said that an uncovered sample's id is −1 and its colour NaN;
    D12-2: `over` is lesson 12b §4's rule, not a derivation."""
    text = _markdown("12_capstone")
    assert "`sample_ids[k]` is −1 where no triangle covers sample k" in text
    assert "its colour is then NaN" in text
    assert "shares derive" not in text and "copy it from there" in text


def test_a_scene_that_agrees_with_a_failing_check_says_so(plt):
    """r94 D8-10: the third panel read "no pixel differs" under a failing check."""
    report = ex.check("classify_block", _block(tie="strict"))
    assert not report.passed
    fig, axes = plt.subplots(1, 3)
    report.compare(axes)
    assert "the failing cases above" in axes[2].get_title(), axes[2].get_title()
    assert len(axes[1].get_title().splitlines()) <= 2, axes[1].get_title()  # r94 D8-11


def test_a_slow_covers_in_the_capstone_is_told_of_its_time_only():
    """r94 D12-5: a correct but slow covers was told why the grid cannot see ties, and "a
    Python call per pixel?" (covers is one call per point)."""
    import time

    import reasoning_solutions as rs
    from test_capstone import _mine

    def slow(xy, p):
        end = time.process_time() + 0.003
        while time.process_time() < end:
            pass
        return rs.CAPSTONE["covers"](xy, p)

    report = ex.capstone("grid", **_mine("grid", covers=slow))
    words = _words(report)
    if "did not finish" not in words:  # the machine was fast enough: nothing to test
        pytest.skip("the slow covers finished in time")
    assert "cannot tell whether ties" not in words and "call per pixel" not in words, words
    assert "should take microseconds" in words


def test_a_negative_sub_triangle_is_drawn_apart(plt):
    """r94 D3-6: λ2 = −0.8's sub-triangle was filled like the others, labelled inside."""
    from teachraster.exercises.interpolation import _draw_bary, barycentric_cases

    case = next(c for c in barycentric_cases() if (np.asarray(c[2]) < 0).sum() == 1)
    fig, ax = plt.subplots()
    _draw_bary(ax, case, None)
    texts = [t.get_text() for a in [ax, *ax.child_axes] for t in a.texts]
    k = int(np.argmin(case[2])) + 1
    assert f"λ{k} < 0" in texts, texts


@pytest.mark.parametrize("name", ["barycentric", "perspective_weights"])
def test_an_answer_nan_on_every_case_is_told_nan(name):
    """r94 D3-2: the convention (CONVENTIONS.md, Exercises) now says what the check does."""
    report = ex.check(name, lambda *a: [float("nan")] * 3)
    assert "your answer holds NaN" in report.failures[0].explanation, str(report)
