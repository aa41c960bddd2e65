"""Issue 30's exercises: correct solutions written differently pass, each typical mistake is
named right in the first explanation (its kind and its words), and the broken frames' hints
are true and never give the answer away."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import reasoning_solutions as sol
import student_variants as sv
from exercise_solutions import CORRECT
from student_variants import DIFFERENT, KINDS, WRONG, _hiz_with

import teachraster as tr
from teachraster import exercises as ex
from teachraster.study.hardcases import naive_coverage


def _passes(name, fn):
    report = ex.check(name, fn)
    assert report.passed, str(report)


def _named(name, fn, kind, words):
    report = ex.check(name, fn)
    assert not report.passed
    first = report.failures[0]
    assert first.kind == kind, (kind, str(report))
    assert words in first.explanation, (words, first.explanation)
    return report


# -- robust_fill -----------------------------------------------------------------------------
def _fill(**kw):
    def fill(xy, width, height, origin=(0, 0)):
        v = np.asarray(xy, float) if kw.get("raw") else np.rint(np.asarray(xy, float) * 256) / 256
        return naive_coverage(v, width, height, origin=tuple(origin),
                              rule=kw.get("rule", "top_left"), dtype=kw.get("dtype", np.float64),
                              absolute=kw.get("absolute", False))  # fmt: skip

    return fill


# -- quad_derivatives ------------------------------------------------------------------------
def _quad(change):
    from teachraster import barycentric, perspective_weights

    def quad_derivatives(xy, w, f, row, col):
        def value(x, y):
            lam = barycentric(xy, [x, y])
            if change == "affine":
                return float(lam @ f)
            return float(perspective_weights(lam[None], w, extrapolate=change != "clamp")[0] @ f)

        r0, c0 = (row, col) if change == "unaligned" else (row - row % 2, col - col % 2)
        ul = value(c0 + 0.5, r0 + 0.5)
        dx, dy = value(c0 + 1.5, r0 + 0.5) - ul, value(c0 + 0.5, r0 + 1.5) - ul
        return (dx, -dy) if change == "up" else (dx, dy)

    return quad_derivatives


def step(bits):
    return 1 / (2**bits - 1)


def solve(s, z, gap, far):
    """The near plane where step (f - n) z² / (f n) = gap."""
    return s * far * z * z / (gap * far + s * z * z)


# Correct solutions written differently and typical mistakes (their words and kinds) are in
# student_variants.py (DIFFERENT, WRONG, KINDS), run by test_checker_corpus.py.


def test_every_issue_30_exercise_has_correct_variants_and_named_mistakes():
    issue_30 = set(ex.names()) - set(CORRECT)
    assert issue_30 == set(sol.CORRECT)
    wrong = {name for name, _, _ in WRONG.values()}
    different = {name for name, _ in DIFFERENT.values()}
    frames = {f"broken_frame_{n}" for n in sol.BROKEN_FRAMES}
    assert issue_30 - frames <= wrong & different
    assert {label for label, (name, _, _) in WRONG.items() if name in issue_30} <= set(KINDS)


def test_perspective_weights_as_lesson_04_prints_them_fail_beyond_a_gpus_w():
    """r126 D3-1 graded only w a GPU meets, where λ/w normalised is right; r421 T2 grades w =
    1e-310 again (3.2 was the printed formula): it fails there, its overflow named."""
    report = ex.check("perspective_weights", lambda lam, w: (lam / w) / (lam / w).sum())
    # r429 M1: its NaN told by the steps that make one on the case (the overflow alone first)
    assert {f.kind for f in report.failures} == {"NaN beyond a GPU's range"}, str(report)
    assert "λ_i / w_i overflows to inf" in report.failures[0].explanation, str(report)


def test_safe_near_never_blames_float32_for_a_named_mistake():
    report = _named("safe_near", lambda z, g, f, b: solve(2 / (2**b - 1), z, g, f), "ndc", "NDC")
    assert all("float32's rounding" not in f.explanation for f in report.failures)


def test_robust_fill_names_the_absolute_form_and_fails_the_naive_fill_often():
    report = ex.check("robust_fill", _fill(rule="top_left", absolute=True, dtype=np.float32))
    assert "absolute form" in {f.kind for f in report.failures}, str(report)
    naive = ex.check("robust_fill", _fill(raw=True, rule="inclusive"))
    assert len(naive.failures) >= 5  # the naive fill fails the catalogue in many places


@pytest.mark.parametrize("rule", ["inclusive", "top_left"])
def test_robust_fill_names_float32_rounding_not_a_tie_rule_the_code_does_not_have(rule):
    """r40 10-1: the notebook's naive fill (E ≥ 0, A x + B y + C in float32, raw vertices) and
    its first repair (the top-left rule) were told "you cover no centre on an edge (E > 0)"
    where float32's rounding left E = −4.8e−07 at a vertex; and 10-2: "E ≥ 0" was said of a
    pixel left out, which only the raw vertices leave out."""
    report = ex.check("robust_fill", _fill(raw=True, rule=rule, absolute=True, dtype=np.float32))
    assert all(f.kind != "E > 0" for f in report.failures), str(report)
    sub = next(f for f in report.failures if f.case == "subpixel_triangles, triangle 2")
    assert sub.kind == "float32 rounding" and "differences to a vertex" in sub.explanation
    for f in report.failures:
        missing = int(f.explanation.rsplit("; ", 1)[-1].split(" missing")[0])
        if f.kind == "E >= 0" and missing:  # a pixel left out: the raw vertices are named too
            assert "you decide on the raw vertices" in f.explanation, f.explanation


def test_robust_fill_accepts_the_absolute_form_in_float64_except_where_it_rounds():
    """r40 10-3: A x + B y + C in float64 on the snapped vertices passes every case near the
    origin, so no message there may forbid it; r373 W24: 10⁶ px out it rounds a centre 2⁻¹⁵
    px² inside an edge to a tie, and that one case fails, named."""
    report = ex.check("robust_fill", _fill(absolute=True))
    assert [(f.case, f.kind) for f in report.failures] == [
        ("far_from_origin at 1000000 px, a centre 2⁻¹⁵ px² inside an edge",
         "absolute form in float64")], str(report)  # fmt: skip


@pytest.mark.parametrize(
    ("tie", "kind"),
    [(lambda a, b: b[1] < a[1], "no top edges"),
     (lambda a, b: b[1] == a[1] and b[0] > a[0], "no left edges")],
)  # fmt: skip
def test_robust_fill_names_a_forgotten_tie_case_on_every_failure(tie, kind):
    """A fill that forgets half of the top-left rule only misses pixels: every failure names
    the forgotten half, never a reversed rule, E > 0 or the unsnapped orientation."""
    from student_variants import _fill_with

    report = ex.check("robust_fill", _fill_with(tie=tie))
    assert report.failures and {f.kind for f in report.failures} == {kind}, str(report)


def test_robust_fill_names_a_reversed_rule_first_and_a_forgotten_one_only_where_it_misses():
    """A reversed tie rule gives every answer: it is named on every failure, the first
    included (r5: a reversed top rule was first called "no top edges"); a forgotten one only
    misses pixels, and is named only where pixels are missing only."""
    from student_variants import _fill_with, _owns_bottom_left, _owns_top_right, _owns_y_up_both

    forgotten = {"no top edges", "no left edges", "E > 0"}
    for tie, kind in ((_owns_bottom_left, "top edge reversed"),
                      (_owns_top_right, "left edge reversed"),
                      (_owns_y_up_both, "both reversed")):  # fmt: skip
        report = ex.check("robust_fill", _fill_with(tie=tie))
        assert {f.kind for f in report.failures} == {kind}, str(report)
    for tie in (
        lambda a, b: False,
        lambda a, b: b[1] < a[1],
        lambda a, b: b[1] == a[1] and b[0] > a[0],
    ):
        for f in ex.check("robust_fill", _fill_with(tie=tie)).failures:
            missing, extra = (int(n) for n in re.findall(r"(\d+) missing, (\d+) extra",
                                                         f.explanation)[-1])  # fmt: skip
            assert f.kind in forgotten and missing > 0 and extra == 0, f.explanation


def test_robust_fill_names_a_coarse_grid_never_float32_or_orientation():
    """Snapping to 1/16 px (4 sub-pixel bits) is a coarser grid, on every failure: never
    float32 (its vertices are float64) nor the unsnapped orientation (r5)."""
    from student_variants import _fill_with

    for grid in (16, 64, 2):
        report = ex.check("robust_fill", _fill_with(grid=grid))
        assert {f.kind for f in report.failures} == {"coarse snapping"}, str(report)
        assert "float32" not in str(report) and "unsnapped" not in str(report)


def test_the_naive_fills_report_shows_each_family_of_its_failures_first():
    """The naive fill (raw vertices, E >= 0, absolute float32) fails ties, snapping and
    precision at once: one failure of each family comes first, the far case says precision
    (r5: 48 failures of kind "value" hid the float32 and snapping ones)."""
    report = ex.check("robust_fill", _fill(raw=True, rule="inclusive", absolute=True,
                                           dtype=np.float32))  # fmt: skip
    shown = report.shown()
    kinds = [f.kind for f in shown]
    assert {"far from origin", "off the grid", "zero area"} <= set(kinds), kinds
    far = next(f for f in shown if f.kind == "far from origin")
    assert "precision" in far.explanation and "float32" in far.explanation


def test_robust_fill_blames_float32_only_where_its_spacing_and_the_answer_say_so():
    """The far-from-origin (precision) words need float32 coarser than 1/256 px (beyond
    2^16 px) and an answer a float32 evaluation gives (r6: said at 10013 px, where float32
    is 1/1024 px apart, to an E >= 0 fill, and to a transposed float64 fill)."""
    from student_variants import _fill_with

    def transposed(xy, width, height, origin=(0, 0)):  # built [col, row], origin read (x, y)
        return _fill_with()(xy, height, width, (origin[1], origin[0])).T

    naive = _fill_with(snap=False, dtype=np.float32, vertices=np.float32, tie=lambda a, b: True)
    report = ex.check("robust_fill", naive)
    near = [f for f in report.failures if f.case == "far_from_origin at 10000 px"]
    assert near and all(f.kind == "E >= 0" for f in near), str(report)
    report = ex.check("robust_fill", transposed)
    assert "far from origin" not in {f.kind for f in report.failures}, str(report)
    assert "float32" not in str(report) and "precision" not in str(report), str(report)


def test_robust_fill_never_names_a_tie_rule_the_function_does_not_follow():
    """r84 10-2: a fill whose tie rule is the top-left rule's mirror (x and y swapped in, the
    image transposed back) was told "you cover no centre on an edge (E > 0)" on one case and
    "you cover every centre on an edge (E ≥ 0)" on another: each gave that case only. A tie
    rule is named only where it gives every failing tie case; else the rule at the case."""
    from student_variants import _fill_with

    from teachraster.exercises.hard_case_fill import TIE_KINDS

    good = _fill_with()

    def mirrored(xy, width, height, origin=(0, 0)):
        return good(np.asarray(xy, float)[:, ::-1], height, width, (origin[1], origin[0])).T

    report = ex.check("robust_fill", mirrored)
    assert not report.passed
    kinds = {f.kind for f in report.failures}
    assert not kinds & set(TIE_KINDS), str(report)
    assert "E ≥ 0" not in str(report) and "E > 0" not in str(report), str(report)
    assert "the top-left rule" in report.failures[0].explanation
    # a tie rule the function follows everywhere is still named, on every failing case
    report = ex.check("robust_fill", _fill_with(tie=lambda a, b: True))
    assert {f.kind for f in report.failures} == {"E >= 0"}, str(report)


def test_the_naive_fills_report_hints_at_the_repairs_and_gives_them_after_a_try():
    """r84 10-1: the naive fill's report, run in the notebook before the task, printed each
    repair as code (np.rint(xy * 256) / 256, the E formula from differences): a to-do list.
    The naive fill is the first answer: hints; the student's first try, a second answer,
    gets the full words."""
    from student_variants import _fill_with

    from teachraster.exercises import tries

    naive = _fill(raw=True, rule="inclusive", absolute=True, dtype=np.float32)
    tries.forget_hints("robust_fill")
    try:
        text = str(ex.check("robust_fill", naive))
        for code in ("np.rint", "(b.x − a.x)(p.y − a.y)", "from differences to a vertex",
                     "keep the vertices in float64", "the top-left rule gives it"):  # fmt: skip
            assert code not in text, (code, text)
        assert "a hint only" in text
        tried = str(ex.check("robust_fill", _fill_with(snap=False)))
        assert "np.rint(xy * 256) / 256" in tried, tried
    finally:
        tries.spend_hints(["robust_fill"])


def test_robust_fill_task_keeps_the_goal_and_leaves_the_causes_to_the_checker():
    """Exercise 10's task names no fix: the catalogue's failures, explained, teach them."""
    import json
    from pathlib import Path

    path = Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    task = next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == "robust_fill_task")
    text = "".join(task["source"])
    for fix in ("np.rint", "1/256", "top-left rule", "winding", "snap"):
        assert fix not in text, fix


def test_quad_derivatives_clamped_at_helpers():
    report = ex.check("quad_derivatives", _quad("clamp"))
    assert report.failures and report.failures[0].kind == "clamped", str(report)


def test_hiz_rejects_without_the_vertex_clamp():
    report = ex.check("hiz_rejects", _hiz_with(clamp=False))
    assert "no clamp" in {f.kind for f in report.failures}, str(report)


def _hiz_in(dtype):
    """The notebook's hiz_rejects (the plane's gradients, at the extreme centres of the tile's
    part inside the box) in ``dtype``."""

    def hiz_rejects(xyz, row0, col0, size, buffer):
        (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = np.asarray(xyz, dtype=dtype)
        area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
        a = ((z2 - z1) * (y3 - y1) - (z3 - z1) * (y2 - y1)) / area
        b = ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1)) / area
        # r126 N8-1: the tile's centres inside the triangle's bounding box
        c0 = max(col0, math.ceil(min(x1, x2, x3) - 0.5))
        c1 = min(col0 + size - 1, math.floor(max(x1, x2, x3) - 0.5))
        r0 = max(row0, math.ceil(min(y1, y2, y3) - 0.5))
        r1 = min(row0 + size - 1, math.floor(max(y1, y2, y3) - 0.5))
        if c0 > c1 or r0 > r1:
            return True
        xs = np.array([c0 + 0.5, c1 + 0.5], dtype=dtype)
        ys = np.array([r0 + 0.5, r1 + 0.5], dtype=dtype)
        corners = z1 + a * (xs[:, None] - x1) + b * (ys[None, :] - y1)
        return bool(max(corners.min(), min(z1, z2, z3)) >= np.max(buffer))

    return hiz_rejects


def test_hiz_rejects_in_float32_is_told_float32_not_a_mistake_it_does_not_make():
    """r40 08-1: float32 broke the cases' exact ties and was told "you took the bare plane" or
    "the tile's outer corners"; a ">" that breaks every tie is still told to use ≥."""
    assert ex.check("hiz_rejects", _hiz_in(np.float64)).passed
    report = ex.check("hiz_rejects", _hiz_in(np.float32))
    assert report.failures and {f.kind for f in report.failures} == {"float32"}, str(report)
    assert "compute the plane in float64" in report.failures[0].explanation.lower()
    strict = ex.check("hiz_rejects", _hiz_with(compare=lambda n, b: n > np.max(b)))
    assert {f.kind for f in strict.failures} == {"strict"}, str(strict)


# The broken frames (exercise 11) are tested in test_broken_frames.py.


RIGHT = dict(sol.CORRECT)
FIRST_WRONG = {}
for _name, _fn, _ in WRONG.values():
    FIRST_WRONG.setdefault(_name, _fn)
for _n in sol.BROKEN_FRAMES:  # a cause that is not the frame's
    FIRST_WRONG.setdefault(
        f"broken_frame_{_n}",
        lambda b: ("texture filtering", (24, 28), (0.5, 0.5, 0.5)),
    )


@pytest.mark.parametrize("name", list(RIGHT))
def test_reports_draw_passing_failing_and_missing(name):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def stub(*args):
        raise NotImplementedError

    for fn in (RIGHT[name], FIRST_WRONG[name], stub):
        report = ex.check(name, fn)
        if fn is stub:
            assert report.not_implemented and "not implemented yet" in str(report)
        fig, ax = plt.subplots(figsize=(3, 3))
        artists = report.plot(ax)
        assert artists and ax.get_title().startswith(name)
        fig.canvas.draw()
        plt.close(fig)


def test_an_unnormalised_barycentric_is_told_that_its_own_weights_sum_wrong():
    """r5: "the weights are (0.4, 0.2, 0.4), which sum to 25" (it is the student's λ)."""
    report = ex.check("barycentric", lambda xy, p: sol_areas(xy, p))
    first = report.failures[0].explanation
    assert "which sum to" not in first and "; yours sum to" in first, first


def sol_areas(xy, p):
    """λ not divided by E(v1, v2, v3)."""
    v1, v2, v3 = np.asarray(xy, float)
    return np.array([tr.edge_function(v2, v3, p), tr.edge_function(v3, v1, p),
                     tr.edge_function(v1, v2, p)])  # fmt: skip


def test_the_fill_plot_leaves_the_titles_corner_free():
    """r5: the check plot's title ran into the y tick "0" at the top edge."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("robust_fill", _fill(raw=True, rule="inclusive"))
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    assert min(ax.get_yticks()) > min(ax.get_ylim()), ax.get_yticks()
    plt.close(fig)


# -- over_premultiplied (9.2): derived from the straight rule ---------------------------------
def test_over_premultiplied_is_derived_and_a_wrong_answer_never_gets_the_factors():
    """Exercise 9.2 gives Porter and Duff's straight rule only; the derivation's slips are
    named (the straight rule copied onto premultiplied colours, the result divided back to
    straight, a side multiplied by its alpha again, the weights swapped), and no explanation
    hands over the answer's factors (before: 'glBlendFunc(ONE, ONE_MINUS_SRC_ALPHA)' and
    'src + dst·(1 − α)' after any wrong answer made it transcription again)."""
    import json
    from pathlib import Path

    from student_variants import KINDS, WRONG

    labels = [k for k, (name, _, _) in WRONG.items() if name == "over_premultiplied"]
    assert {KINDS[k] for k in labels if k in KINDS} >= {
        "straight rule on premultiplied", "returned straight", "destination premultiplied twice",
        "weights swapped"}  # fmt: skip
    tries = [WRONG[k][1] for k in labels] + [lambda s, d: np.asarray(s) * 0.5 + d[3]]
    for fn in tries:
        report = ex.check("over_premultiplied", fn)
        assert not report.passed
        for f in report.failures:
            for answer in ("ONE_MINUS_SRC_ALPHA", "src + dst", "glBlendFunc(ONE"):
                assert answer not in f.explanation, f.explanation
    last = ex.check("over_premultiplied", tries[-1]).failures[0].explanation
    assert "9.2a's derivation with src and dst written as c = α·C" in last, last
    assert "your 9.2a" not in last, last  # r12 09-8: the rule, not a diagnosis
    nb = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/exercises/09_lines_and_blending.ipynb").read_text())  # fmt: skip
    task = next("".join(c["source"]) for c in nb["cells"]
                if c["metadata"]["nbgrader"]["grade_id"] == "over_straight_task")  # fmt: skip
    # r8: the task gives the coverage argument, not the straight form's formula to transcribe;
    # r25 D-7: nor the share the source leaves (step 1) or the division (step 4)
    assert "straight" in task and "hides what lies behind it" in task and "uncorrelated" in task
    assert "1 − α_s" not in task and "divided by α" not in task and "division" not in task
    for answer in ("ONE_MINUS_SRC_ALPHA", "src + dst", "c_s + c_d", "GL_ONE", "α_d·(1 − α_s)",
                   "α_s + α_d"):  # fmt: skip
        assert answer not in task, answer


def test_exercise_9_2_credits_the_straight_form_rightly_and_asks_what_lesson_12_does_not_print():
    """r7 09-1: "Porter and Duff ... give over for straight colours" was wrong (they work
    premultiplied); 09-2: lesson 12 §9 prints the premultiplied rule, so 9.2 first asks for
    straight inputs returned premultiplied, which it does not print."""
    import json
    from pathlib import Path

    nb = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/exercises/09_lines_and_blending.ipynb").read_text())  # fmt: skip
    text = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in nb["cells"]}
    task = text["over_straight_task"]
    assert "Porter and Duff" in task and "give *over* for **straight**" not in task
    assert "over_straight(src, dst)" in task and "lesson 12, §9" not in task
    assert "lesson 12b, §4" not in task
    assert "over_straight_check" in text and "atop_premultiplied_task" in text  # r20 D-1
    # r11 09-A, 09-G: no shortcut offered, and GL's default is no blending
    assert "cannot tell the two apart" not in task and "textbook default" not in task
    said = str(ex.check("over_premultiplied", lambda s, d: np.asarray(s) * 0.5 + d[3]))
    assert "9.2a's derivation with src and dst" in said and "Porter and Duff's rule" not in said
    lesson = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/12b_blending.ipynb").read_text())  # fmt: skip
    printed = " ".join("".join(c["source"]) for c in lesson["cells"])
    # the Summary names the exercise's functions (r8); no cell defines or computes it
    assert "def over_to_premultiplied" not in printed and "over_to_premultiplied(" not in printed
    from teachraster.exercises.blending import from_straight

    src, dst = [0.2, 0.4, 0.6, 0.5], [1.0, 0.5, 0.0, 0.5]
    assert np.allclose(from_straight(src, dst), [0.35, 0.325, 0.3, 0.75])  # 0.6·0.5 + 0·0.5·0.5
    _passes("over_to_premultiplied", sol.over_to_premultiplied)
    said = str(ex.check("over_to_premultiplied", from_straight))
    assert "not counted" in said or "package" in said, said
    _named("over_to_premultiplied", lambda s, d: np.asarray(s) + np.asarray(d) * (1 - s[3]),
           "inputs not premultiplied", "as if they were premultiplied")  # fmt: skip
    _named("over_to_premultiplied",
           lambda s, d: np.r_[np.asarray(s[:3]) * s[3] + np.asarray(d[:3]) * (1 - s[3]),
                              s[3] + d[3] * (1 - s[3])],
           "destination alpha ignored", "α_d·(1 − α_s)")  # fmt: skip


def test_the_fill_legend_lists_only_the_states_drawn():
    """r6 10-3: the legend listed "missing (the rule covers it)" where no pixel was missing."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("robust_fill", _fill(rule="inclusive"))  # E >= 0: extra pixels only
    assert not report.passed
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    plt.close(fig)
    assert "covered" in labels and any(t.startswith("extra") for t in labels), labels
    assert not any(t.startswith("missing") for t in labels), labels


# -- r39: exercises 01-05 played as a student -------------------------------------------------
def test_span_in_float32_fails_far_from_the_origin_and_is_named():
    """r39 02-1: a float32 span passed every case; rows 100 000 px out where float32 moves an
    end now refuse it, and name float32."""
    # the reasoning solutions' float form (exact in integers since session 35), in float32
    float32 = sv._span_minmax_float64
    report = ex.check("span", lambda xy, row: float32(np.asarray(xy, np.float32), np.float32(row)))
    assert not report.passed
    near = [f for f in report.failures if not f.case.startswith("far out")]  # session 35
    assert {f.kind for f in near} == {"float32"}, str(report)
    assert "cannot hold the vertices' 1/256-px grid" in report.failures[0].explanation


def test_span_by_scanning_the_columns_stops_on_the_wide_triangle():
    """r46 02-4: testing every centre of the row with the top-left rule passed every case; a
    triangle 10^12 px wide (a few columns covered near its apex) stops the scan at the CPU
    limit, and the case's label says why (the span is two crossings at any width)."""
    report = ex.check("span", sv.span_by_testing)
    assert not report.passed
    assert len(report.failures) == 1, str(report)
    label, words = report.failures[0].case, report.failures[0].explanation
    assert "10^12 px wide" in label and "never ends" in label, label
    assert "10^12 px wide" in str(report)
    assert "2 s of CPU" in words and "or over the columns?" in words, words


def test_span_cases_of_the_wide_triangle_follow_the_package_rule():
    """The wide rows' columns come from the exact crossings (the package's fill does not reach
    10^12 px); that rounding equals the package's fill on every other case, fixed and drawn."""
    from teachraster.exercises import spans

    cases = [c for c in spans.span_cases() if "10^12" not in c[0]]
    assert len(cases) > 150
    for label, (xy, row), covered in cases:
        assert spans.exact_columns(xy, row) == covered, label
    wide = [c for c in spans.span_cases() if "10^12" in c[0]]
    assert len(wide) == 4 and all(len(c[2]) >= 1 for c in wide)
    assert all(set(range(*sol.span(*args))) == covered for _, args, covered in wide)


def test_span_returned_as_stop_first_is_named_not_a_placeholder():
    """r39 02-2: (stop, first) covers nothing on every case, but it is computed, not left in."""
    report = _named("span", lambda xy, row: sol.span(xy, row)[::-1], "first and stop swapped",
                    "you returned (stop, first)")  # fmt: skip
    assert all("placeholder" not in f.explanation for f in report.failures)


def test_span_one_column_short_reads_its_ends_from_the_pair():
    """r363 C6: (3, 3) where column 3 is covered was told "your first is one column too far
    right"; its stop is the one too far left."""
    from teachraster.exercises import spans

    args = (np.array([[3.30078125, 2.30078125], [3.80078125, 2.3984375],
                      [3.44921875, 2.8984375]]), 2)  # fmt: skip
    words = spans._ends_words(args, frozenset({3}), spans.as_span((3, 3)))
    assert words.startswith("your stop is one column too far left") and "here 4" in words
    assert spans._ends_words(args, frozenset({3}), spans.as_span((4, 4))).startswith("your first")


def test_span_that_is_always_empty_is_told_in_the_students_terms():
    """r39 02-3: never the checker's frozenset()."""
    report = _named("span", lambda xy, row: (0, 0), "constant", "the same empty span (0, 0)")
    assert "frozenset" not in str(report)


def test_depth_passes_with_a_buffer_cleared_to_one_fails_on_the_far_plane():
    """r39 04-4: a buffer cleared to 1.0 passed every case; a fragment at depth 1.0 tells it."""

    def cleared(depths, writes):
        stored, out = 1.0, []
        for d, w in zip(depths, writes):
            out.append(d < stored)
            stored = d if d < stored and w else stored
        return out

    _named("depth_passes", cleared, "cleared to 1", "started the buffer at 1.0")


def _ahead(z, gap, far, bits):
    """Whole steps: the window depths of z and z + gap one step apart (r39 05-2)."""
    s = step(bits)
    return s * far * z * (z + gap) / (gap * far + s * z * (z + gap))


def _behind(z, gap, far, bits):
    """Whole steps: the window depths of z − gap and z one step apart (r39 05-2)."""
    s = step(bits)
    return s * far * z * (z - gap) / (gap * far + s * z * (z - gap))


@pytest.mark.parametrize(
    "fn",
    [lambda z, g, f, b: sol.safe_near(z, g, f, b) * (1 + 1e-5), _ahead, _behind,
     lambda z, g, f, b: sol.safe_near(z, g, f, b) * 1.005],
    ids=["bisected to 1e-5", "whole steps ahead", "whole steps behind", "0.5 % further out"],
)  # fmt: skip
def test_safe_near_accepts_every_near_plane_that_tells_the_surfaces_apart(fn):
    """r39 05-1, 05-2: checked against the criterion, not to 6 digits of one formula."""
    _passes("safe_near", fn)


def test_safe_near_too_close_is_told_why_truly():
    """r39 05-2: "too coarse" only where the surfaces lie less than one step apart."""
    report = ex.check("safe_near", lambda z, g, f, b: 0.9 * sol.safe_near(z, g, f, b))
    assert not report.passed
    assert all("of a step apart" in f.explanation for f in report.failures), str(report)


def test_safe_near_too_far_out_is_not_told_it_fails_to_tell_them_apart():
    """r84 05-1: "finer than needed: any near plane from 0.152 to 0.154 tells them apart"
    was said of 0.156, which tells them apart too; and 05-3: the figure drew a 3 % miss as
    one line (log axes over a factor 900)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("safe_near", lambda z, g, f, b: 1.02 * sol.safe_near(z, g, f, b))
    finer = [f.explanation for f in report.failures if "farther than needed" in f.explanation]
    assert finer, str(report)
    for words in finer:
        assert "yours tells them apart too" in words and "the check accepts" in words, words
        # r351 item 2: Δz falls with n everywhere; the cost of a farther plane is clipping
        assert "clips" in words and "precision" not in words, words
        assert "tells them apart, and yours" not in words
    from teachraster.exercises.near_plane import draw_near, near_cases

    case = near_cases()[0]
    fig, ax = plt.subplots()
    draw_near(ax, case, 1.03 * case[2])
    lo, hi = ax.get_xlim()
    assert hi / lo < 2, (lo, hi)  # zoomed: both lines apart on the page
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(t.startswith("your n ") for t in labels), labels
    plt.close(fig)


def test_safe_near_with_an_infinite_far_plane_still_fails_where_it_matters():
    _named("safe_near", lambda z, g, f, b: step(b) * z * z / g, "infinite far", "(f − n)/f")


def _brightest(colours, ids, background):
    """A resolve no mistake of the table gives: the brightest sample, NaN as 0."""
    return np.nan_to_num(np.asarray(colours, float)).max(axis=0)


def _mean_texel(texture, uv, wrap):
    """The mean of the texture (itself a named mistake since r286; squared, none is)."""
    return np.asarray(texture, float).mean(axis=(0, 1))


def _ends(pyramid, uv, lod, wrap="repeat"):
    """A trilinear no mistake gives: level 0 and the 1×1 level, half each."""
    from exercise_solutions import bilinear

    return 0.5 * (np.asarray(bilinear(pyramid[0], uv, wrap)) + np.asarray(pyramid[-1][0, 0]))


def _quad_rows_below(rows):
    """A quad_derivatives no mistake gives: the quad ``rows`` rows below the right one."""
    from student_variants import _quad_origin

    return _quad_origin(lambda r, c: (r - r % 2 + rows, c - c % 2))


def _clip_from_end(v):
    from exercise_solutions import clip_against

    return clip_against(v, t=lambda a, b: (b[2] + b[3]) / ((b[2] + b[3]) - (a[2] + a[3])))


@pytest.mark.parametrize(
    ("name", "fn", "other", "formula"),
    [("span", lambda xy, row: (math.floor(_x(xy, row)[0] - 0.5) + 1, math.ceil(_x(xy, row)[1] - 0.5)),
      lambda xy, row: (math.floor(_x(xy, row)[0] - 0.5) + 1, math.ceil(_x(xy, row)[1] - 0.5) + 1),
      "⌈x_l − ½⌉"),
     ("perspective_weights", lambda lam, w: lam * w / (lam @ w), lambda lam, w: lam / w, "λ_i / w_i"),
     ("safe_near", lambda z, g, f, b: 3 * step(b) * z * z / g,
      lambda z, g, f, b: 2 * step(b) * z * z / g, "solve step"),
     # 7.1: every case's words measured the axes as ‖(du/dx·W, dv/dx·H)‖ and took log2 ρ
     ("mip_level", lambda dx, dy, s: 0.5, lambda dx, dy, s: 1.5, "λ = log2 ρ"),
     ("mip_level", lambda dx, dy, s: 0.5, lambda dx, dy, s: 1.5, "(du/dx·W, dv/dx·H)"),
     # r64 06 D1, D2; 07 D1-D3: 6.2, 6.3, 7.2, 7.3, 7.4 gave the rule on the first failure
     ("resolve", _brightest, lambda c, i, b: _brightest(c, i, b) / 2, "(S − k)·background"),
     ("resolve_srgb", _brightest, lambda c, i, b: _brightest(c, i, b) / 2,
      "linear_to_srgb((Σ"),
     ("bilinear", lambda t, uv, w: _mean_texel(t, uv, w) ** 2,
          lambda t, uv, w: _mean_texel(t, uv, w) ** 2 / 2, "u·W − ½"),
     ("trilinear", _ends, lambda p, uv, lod, wrap="repeat": _ends(p, uv, lod, wrap) / 2,
      "clamp λ to [0, q]"),
     ("quad_derivatives", _quad_rows_below(1), _quad_rows_below(2), "row − row mod 2")],
)  # fmt: skip
def test_the_formula_comes_only_after_two_different_wrong_answers(name, fn, other, formula):
    """r39 02-5, 03-3, 05-3: the first wrong try does not print what the task asks to find;
    r46 S2, X2: nor does rerunning it; a second, different wrong answer does."""
    from teachraster.exercises import tries

    tries.forget_hints(name)
    first, again = ex.check(name, fn), ex.check(name, fn)
    for report in (first, again):
        assert formula not in str(report) and "a hint only" in str(report), str(report)
    assert formula in str(ex.check(name, other)), name


@pytest.mark.parametrize(
    ("name", "fn", "formula"),
    [("perspective_weights", lambda lam, w: lam / w, "Σ λ_j / w_j"),
     ("clip_near", _clip_from_end, "d_a/(d_a − d_b)"), ("clip_near", _clip_from_end, "d2/(d2")],
)  # fmt: skip
def test_the_formula_of_other_mistakes_is_staged_too(name, fn, formula):
    """r46 P1, C1: "divide by their sum Σ λ_j / w_j" and the crossing's t were unstaged."""
    from teachraster.exercises import tries

    tries.forget_hints(name)
    report = ex.check(name, fn)
    assert not report.passed and formula not in str(report), str(report)


def _x(xy, row):
    """The crossings of row's centre line with the triangle (min, max), or (0, 0)."""
    y, xs = row + 0.5, []
    for k in range(3):
        (ax, ay), (bx, by) = xy[k], xy[(k + 1) % 3]
        if ay != by and min(ay, by) <= y <= max(ay, by):
            xs.append(ax + (y - ay) * (bx - ax) / (by - ay))
    return (min(xs), max(xs)) if xs else (0.5, 0.5)


def test_numpy_warnings_are_not_reported_as_prints():
    """r39 03-2: numpy's overflow warning was told "your function printed 4 lines"."""

    def warns(lam, w):  # r126 D3-1: 3.2's w no longer overflow: an overflow of its own
        with np.errstate(over="warn"):
            np.float64(1e308) * 10
        return (lam / w) / (lam / w).sum()

    report = ex.check("perspective_weights", warns)
    assert "printed" not in (report.printed or ""), report.printed
    assert "warning" in report.printed and "overflow" in report.printed, report.printed


def test_barycentric_in_float32_far_out_names_the_lost_grid_not_a_plane():
    """r39 03-1: differences to a vertex in float32: the inputs lost the 1/256-px grid."""

    def e(a, b, p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    def bary(xy, p):
        v1, v2, v3 = np.asarray(xy, np.float32)
        p = np.asarray(p, np.float32)
        return np.array([e(v2, v3, p), e(v3, v1, p), e(v1, v2, p)]) / e(v1, v2, v3)

    far = [
        f for f in ex.check("barycentric", bary).failures if "px from the origin" in f.explanation
    ]
    assert far, "the far cases fail"
    for f in far:
        assert "cannot hold the 1/256-px grid" in f.explanation, f.explanation
        assert "absolute coordinates" not in f.explanation, f.explanation


def test_a_failing_check_without_the_formula_does_not_use_up_the_hint():
    """The hint is given the first time the words would give the answer away, not on a first
    check that failed for another reason (a TypeError)."""
    from teachraster.exercises import tries

    tries.forget_hints("safe_near")
    ex.check("safe_near", lambda z, g, f, b: "n")
    first = ex.check("safe_near", lambda z, g, f, b: 3 * step(b) * z * z / g)
    assert "solve step" not in str(first) and "a hint only" in str(first), str(first)


def test_the_hiz_figure_draws_the_triangle_and_its_depth_at_the_extreme_centres():
    """r40 08-4: the triangle was not in view and its depths were text only."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Polygon

    report = ex.check("hiz_rejects", _hiz_with(vertex_only=True))
    fig, ax = plt.subplots()
    report.plot(ax)
    assert any(isinstance(p, Polygon) for p in ax.patches)
    labels = [t.get_text() for t in ax.texts]
    assert len([t for t in labels if t[:1].isdigit()]) >= 4, labels
    plt.close(fig)


def _harvested(name):
    """r46 N1/X1: the arguments of one failing run zipped with its failures' expected answers,
    handed in as a dict: the cases drawn for each check make it fail."""
    args = []
    # Not a number: 1.0 was the right answer to a drawn edge_function case now and then
    # (fresh-clone CI), and a passing case breaks the zip of arguments with failures.
    first = ex.check(name, lambda *a: args.append(a) or "not an answer")
    assert len(first.failures) == len(args), "every case fails a string"
    table = {repr(a): f.expected for a, f in zip(args, first.failures)}

    def answer(*a):
        value = table.get(repr(a), 1.0)
        if isinstance(value, str):  # 3.1's zero area since ex30b: the answer is a ValueError
            raise ValueError(value)
        return value

    return ex.check(name, answer)


def test_safe_near_from_a_harvested_table_fails():
    report = _harvested("safe_near")
    assert not report.passed and all("drawn for this check" in f.case for f in report.failures)


def test_safe_near_with_a_step_of_one_over_two_to_the_bits_is_refused_and_named():
    """r46 N2: 4- and 8-bit cases, where 1/2^bits moves n past the tolerance."""
    report = _named(
        "safe_near", lambda z, g, f, b: solve(1 / 2**b, z, g, f), "2^bits", "2^bits − 1"
    )
    assert {int(f.case.split(", ")[-1].split()[0]) for f in report.failures} == {4, 8}


@pytest.mark.parametrize(
    "name", ["edge_function", "barycentric", "perspective_weights", "clip_near", "depth_passes"]
)
def test_a_harvested_table_of_answers_fails(name):
    """r46 X1: a dict of one run's arguments and expected answers passed 03 and 04."""
    report = _harvested(name)
    assert not report.passed and all("drawn for this check" in f.case for f in report.failures)


def test_span_one_past_the_end_in_float64_is_an_off_by_one_not_float32():
    """r46 S1: ⌈x_r − ½⌉ + 1 in float64 was asked "did you compute in float32" far out."""
    report = ex.check("span", lambda xy, row: (math.ceil(_x(xy, row)[0] - 0.5),
                                               math.ceil(_x(xy, row)[1] - 0.5) + 1))  # fmt: skip
    assert not report.passed
    assert not any("float32" in f.explanation for f in report.failures), str(report)


def test_perspective_weights_that_clamp_lambda_fail_outside_the_triangle():
    """r46 P3: a point outside the triangle has a negative λ; clamping it must fail."""

    def clamped(lam, w):  # (r421 T2: scaled by the smallest w that weighs, right beyond a GPU)
        lam = np.clip(lam, 0, 1)
        live = lam != 0
        q = np.zeros(3)
        q[live] = lam[live] * (w[live].min() / w[live])
        return q / q.sum()

    report = ex.check("perspective_weights", clamped)
    names = [f.case.split(":")[0] for f in report.failures]
    # fixex12 (r126) added more cases outside the triangle: each must fail, and nothing else
    # (r429 W1: two of them with w beyond a GPU's range)
    assert len(names) >= 6 and all(n.startswith("p outside the triangle") for n in names), names


@pytest.mark.parametrize(
    ("label", "name_words", "formula"),
    [("bilinear without −½", "texel corners", "x = u·W − ½"),
     ("bilinear, weights reversed", "went to", "x − ⌊x⌋"),
     ("λ summed before the root", "summed the squares", "ρ = max(|∂/∂x|, |∂/∂y|)"),
     ("trilinear, weights swapped", "the weight of level", "λ − ⌊λ⌋"),
     ("quad at (row // 2, col // 2)", "quad's number", "row − row mod 2"),
     ("quad of this pixel", "even rows", "row − row mod 2"),
     ("resolve of the encoded numbers", "sRGB-encoded", "decode first, average in linear light"),
     ("Hi-Z by the plane alone", "bare plane", "the bound asked is the larger of the two"),
     ("Hi-Z over the covered centres", "the centres it covers", "no nearer than the nearest vertex")],
)  # fmt: skip
def test_a_named_mistake_asks_before_its_formula(label, name_words, formula):
    """r73 07-1, 06-1, 08-2: a recognised mistake is named with a question on the first tries
    (rerunning it too); its fix as a formula only once two different answers have failed."""
    from exercise_solutions import MISTAKES

    from teachraster.exercises import tries

    name, fn = WRONG[label][:2] if label in WRONG else MISTAKES[label][:2]
    tries.forget_hints(name)
    for _ in range(2):
        report = str(ex.check(name, fn))
        assert name_words in report and formula not in report, report
        assert "a hint only" in report, report
    tries.hinted_check(name, "another answer that failed")  # a second, different wrong answer
    assert formula in str(ex.check(name, fn)), label


@pytest.mark.parametrize("label", ["span, (first, last)", "span at y = row + 1"])
def test_a_float64_span_off_by_a_column_is_never_called_float32(label):
    """r355 C3: a float64 (first, last) or y = row + 1 also fails the far row where float32
    moves an end (its crossing 0.02 px from a centre), and was asked there "did you compute in
    float32?": float32 is named only where it explains every failure."""
    report = ex.check("span", sv.WRONG[label][1])
    assert all("float32" not in f.explanation for f in report.failures), str(report)
