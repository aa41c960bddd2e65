"""Review r122 (exercises 03, 08, 12 played as students in fresh processes): a correct
barycentric printing 200 lines a call was told "the check ran for 0.088 s of wall-clock time
... the machine is too busy" (D3-2), 3.2's and trilinear's checks gave the answer's words on a
first try (N3-2, N12-1), 8.2 called its bound "the nearest depth the triangle can have", and
the reference of 8.2 also clamped the plane to the farthest vertex (D8-6).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from exercise_solutions import CORRECT

from teachraster import exercises as ex
from teachraster.exercises import output, running
from teachraster.exercises.alarm import Alarm


class Costly:
    """An argument whose formatting is counted (a big array's ``str`` costs CPU)."""

    formatted = 0

    def __str__(self):
        Costly.formatted += 1
        return "costly"


def test_printing_past_the_cap_formats_nothing_and_costs_no_cpu():
    """D3-2: formatting the prints of a chatty function ate the CPU budget (10.4 s of CPU for
    30 000 prints of arrays: "the check's budget ... ran out on case 140"). Past the lines kept,
    a print is counted, not formatted."""
    Costly.formatted = 0
    right = CORRECT["barycentric"]

    def chatty(xy, p):
        for k in range(200):
            print("debug", k, Costly())
        return right(xy, p)

    report = ex.check("barycentric", chatty, budget=60)
    assert report.passed, str(report)
    assert Costly.formatted <= output.KEEP, Costly.formatted
    assert f"your function printed {200 * report.n_cases} lines" in str(report), str(report)


def test_print_to_a_file_of_ones_own_is_not_swallowed(tmp_path):
    path = tmp_path / "log.txt"
    with output.captured() as out, open(path, "w") as fh:
        for k in range(output.KEEP + 5):
            print("x", k)
        print("kept", file=fh)
    assert path.read_text() == "kept\n"
    assert out.lines == output.KEEP + 5


def _stopped_on_the_wall(cap: float, seconds: float, check_wall: float) -> str:
    b = running.Budget(10.0)
    b.start -= check_wall
    b.used = 0.507  # run_case adds the case's CPU (0.007 s below) before it asks for the words
    alarm = Alarm(seconds, None, 5 * seconds, cap)
    alarm.why = "wall"
    alarm._end = (0.007, cap)  # frozen: CPU and wall seconds of the case
    return running._timeout(alarm, b, "120 of 150").error


def test_the_checks_wall_clock_limit_quotes_the_checks_time_not_the_cases():
    """D3-2: the case's share of what was left (0.088 s) was quoted as the check's time."""
    text = _stopped_on_the_wall(cap=0.088, seconds=2.0, check_wall=99.95)
    assert "0.088 s" not in text, text
    assert text.startswith("the check ran for 100 s of wall-clock time (its limit: 100 s"), text
    assert "your function computed for 0.51 s of it: the machine is too busy" in text, text


def test_a_cases_own_wall_clock_cap_is_quoted_as_the_cases():
    text = _stopped_on_the_wall(cap=40.0, seconds=2.0, check_wall=41.0)
    assert text.startswith("the case ran for 40 s of wall-clock time on case 120 of 150"), text
    assert "computed for 0.007 s of it" in text, text


def _first_words(name, fn):
    from teachraster.exercises import tries

    tries.forget_hints(name)
    try:
        report = ex.check(name, fn, budget=60)
    finally:
        tries.spend_hints([name])
    assert not report.passed
    return report.failures[0].explanation, str(report)


def test_lesson_04s_formula_passes_3_2_on_a_gpus_w():
    """N3-2 asked an overflowing answer back for w = 1e-310; r126 D3-1 graded only w a GPU
    meets, and lesson 04's formula as printed passes them; r421 T2 grades w = 1e-310 again:
    the formula fails there alone, its overflow named."""

    def naive(lam, w):
        q = np.asarray(lam, float) / np.asarray(w, float)
        return q / q.sum()

    report = ex.check("perspective_weights", naive, budget=60)
    # r429 M1: a NaN is told by its sources on the case; on the first, the overflow alone
    assert {f.kind for f in report.failures} == {"NaN beyond a GPU's range"}, str(report)
    assert all("w beyond a GPU's range" in f.case for f in report.failures), str(report)
    first = report.failures[0].explanation
    assert "only an infinite term makes a NaN: λ_i / w_i overflows to inf at v1" in first, first


def test_trilinears_clamp_is_asked_back_on_the_first_try():
    """N12-1: "clamp it to [0, q] = [0, 3] first, then take its levels and the weight (below 0
    ... level 0 alone is filtered)" on a first try, in 7.3 and the capstone's floor."""
    from teachraster.exercises.texture_filtering import trilinear_with

    for mode in ("weight", "extrapolate", "index"):
        first, report = _first_words("trilinear", lambda *a, m=mode: trilinear_with(*a, clamp=m))
        assert "clamp it to" not in report and "level 0 alone is filtered" not in report, report
        assert "the pyramid's levels run from 0 to q = 3: what λ does the filter use" in first
        assert "a hint only" in report, report


def _task_rule(xyz, row0, col0, size, buffer):
    """8.2's rule as cell 5 states it, in float64: the larger of the plane's minimum over the
    tile's centres inside the triangle's bounding box (r126 N8-1; none: rejected) and the
    nearest vertex, at or behind the farthest stored depth."""
    from student_variants import hiz_box

    xyz = np.asarray(xyz, float)
    box = hiz_box(xyz, row0, col0, size)
    if box is None:
        return True
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = xyz
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    a = ((z2 - z1) * (y3 - y1) - (z3 - z1) * (y2 - y1)) / area
    b = ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1)) / area
    xs = np.array(box[:2]) + 0.5
    ys = np.array(box[2:]) + 0.5
    plane = min(z1 + a * (x - x1) + b * (y - y1) for x in xs for y in ys)
    return bool(max(plane, xyz[:, 2].min()) >= np.max(buffer))


def test_the_reference_rejects_as_the_tasks_rule_does_beyond_the_farthest_vertex():
    """D8-6 (r114, latent): the reference clamped the plane to the farthest vertex's depth
    too, and kept a tile the task's rule rejects."""
    from teachraster.exercises.hiz_tile import expected_reject, hiz_cases

    xyz = np.array([[0, 0, 0.1], [8, 0, 0.3], [0, 8, 0.5]])
    tile = (xyz, 16, 16, 8, np.full((8, 8), 0.6))
    assert _task_rule(*tile) and expected_reject(*tile)
    for label, args, expected in hiz_cases():
        assert _task_rule(*args) == expected, label


def test_hiz_words_name_the_bound_not_the_nearest_depth():
    """N8-2: a covered-centres answer was told "the nearest depth the triangle can have in
    the tile is 0.065" while no fragment there is nearer than 0.166."""
    from teachraster.exercises.hiz_tile import _covered_bound

    def covered_min(xyz, row0, col0, size, buffer):
        got = _covered_bound(np.asarray(xyz, float), row0, col0, size, np.asarray(buffer))
        return False if got is None else got

    first, report = _first_words("hiz_rejects", covered_min)
    assert "nearest depth the triangle can have" not in report, report
    # r232 S2: the first words go from the stored depth and the verdicts to the cause, with no
    # line naming the bound in between; the bound itself only once the hints are spent
    assert "the tile's farthest stored depth is 0.166: the block is kept" in first, first
    assert "so the bound (no nearer than the nearest vertex) is" not in first, first
    spent = ex.check("hiz_rejects", covered_min, budget=60).failures[0].explanation
    assert "so the bound (no nearer than the nearest vertex) is" in spent, spent


def _naive_weights(lam, w):
    """Lesson 04's formula as printed: λ_i / w_i over their sum, in float64."""
    q = np.asarray(lam, float) / np.asarray(w, float)
    return q / q.sum()


def test_3_2_grades_w_beyond_a_gpus_last_and_says_so():
    """N3-1 / r126 D3-1 made w = 1e-310 an ungraded extra; r421 T2 grades such w again (the
    reasoning of 3.2, beside lesson 04's printed formula), as the last cases, and the text
    says so; on every other case lesson 04's formula is right."""
    import nbformat

    from teachraster.exercises.perspective_weighting import (
        beyond_a_gpu,
        same_weights,
        weights_cases,
    )

    cases = weights_cases()
    beyond = [label for label, _, _ in cases if beyond_a_gpu(label)]
    assert beyond and [label for label, _, _ in cases[-len(beyond) :]] == beyond
    for label, (lam, w), mu in cases:
        if not beyond_a_gpu(label):
            assert same_weights(_naive_weights(lam, w), mu), label
    path = Path(__file__).parents[1] / "notebooks/exercises/03_interpolation.ipynb"
    text = " ".join(nbformat.read(path, 4).cells[9].source.split())
    assert "the check also asks it of those extreme w" in text
    assert "w = (1e-310, 2e-310, 4e-310)" in text and "An extra, not graded" not in text
    assert "`perspective_w_ratio_1e6` case, w from 1e-3 to 1e3" in text


def test_the_affine_floor_marks_every_floor_pixel_as_cell_8_says():
    """N12-2: cell 8 said a wrong (u, v) "bends or shifts its squares"; affine weights mark
    every pixel of the floor (one solid block in the third panel)."""
    from test_capstone import _mine

    from teachraster.exercises import capstone_render as cr

    spec = cr.SCENES["textured_floor"]
    floor = np.zeros((cr.H, cr.W), bool)
    for part in cr._parts(spec, cr._frame(spec)):
        floor |= np.isfinite(part).all(axis=2)
    report = ex.capstone(
        "textured_floor",
        **_mine("textured_floor", perspective_weights=lambda lam, w: np.asarray(lam, float)),
    )
    assert report.n_wrong == int(floor.sum()) > 0, (report.n_wrong, floor.sum())


def test_a_triangle_missed_whole_is_shown_by_a_pixel_strictly_inside():
    """D12-3 (r114, carried): the one-winding covers' example was a tie pixel ("centre (2.5,
    5.5) lies exactly on edge v1→v2"), as if the top-left rule were the mistake."""
    from test_capstone import _one_winding

    report = ex.check("covers", _one_winding, budget=60)
    words = next(f.explanation for f in report.failures if "For example" in f.explanation)
    example = words.split("For example", 1)[1]
    assert "strictly inside" in example and "lies exactly on edge" not in example, words


def test_a_product_of_ratios_to_the_largest_w_fails_beyond_a_gpus_w_only():
    """D3-3 (r114): λ_i·w_j·w_k with the w scaled by the largest underflowed only for w =
    1e-310; right on a GPU's w (r126 D3-1), it fails only the w r421 T2 grades again."""

    def products(lam, w):
        lam, w = np.asarray(lam, float), np.asarray(w, float) / np.max(w)
        q = lam * np.array([w[1] * w[2], w[0] * w[2], w[0] * w[1]])
        return q / q.sum()

    report = ex.check("perspective_weights", products, budget=60)
    assert not report.passed and all("w beyond a GPU's range" in f.case for f in report.failures)
