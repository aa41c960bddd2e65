"""Review r126 (exercises 03, 08, 12 played as students in fresh processes): 3.2 had one
point outside the triangle of 71 cases and told abs(λ) only the general rule (D3-3); cell 4
of 03 gave far triangles as the only reason for float64 while the check fails float32 at the
origin (D3-2); 8.2's outer-corner and plane-only mistakes were each caught by one case (D8-3);
the capstone failed a scene whose pixels all matched, for 3.2's w = 1e-310 (D12-1).
"""

from __future__ import annotations

from pathlib import Path

import nbformat
import numpy as np

from teachraster import exercises as ex
from teachraster.exercises import tries

EXERCISES = Path(__file__).parents[1] / "notebooks/exercises"


def _check(name, fn, *, fresh=True):
    if fresh:
        tries.forget_hints(name)
    try:
        return ex.check(name, fn, budget=60)
    finally:
        tries.spend_hints([name])


def _cell(notebook: str, index: int) -> str:
    return " ".join(nbformat.read(EXERCISES / notebook, 4).cells[index].source.split())


def test_absolute_lambda_is_named_on_several_points_outside_the_triangle():
    """D3-3: abs(λ) failed one case of 71 and was told "write λ_i in terms of μ ..."."""
    from teachraster.exercises.perspective_weighting import weights_cases

    outside = [label for label, (lam, _), _ in weights_cases() if label.startswith("p outside")]
    assert len(outside) >= 5, outside
    for label, (lam, w), mu in weights_cases():
        # (r429 W1: the two outside beyond a GPU's range have μ = (1, -0, -0))
        if label.startswith("p outside") and "w beyond" not in label:
            assert (lam < 0).sum() == 1 and (lam / w).sum() > 0 and (mu < 0).sum() == 1, label

    def absolute(lam, w):
        lam, w = np.asarray(lam, float), np.asarray(w, float)
        live = lam != 0  # r421 T2: by the smallest w that weighs (the smallest of all underflows)
        q = np.zeros(3)
        q[live] = np.abs(lam[live]) * (w[live].min() / w[live])
        return q / q.sum()

    report = _check("perspective_weights", absolute)
    assert len(report.failures) >= 5, str(report)
    for failure in report.failures:
        assert "you took abs(λ)" in failure.explanation, failure.explanation


def _naive_weights(lam, w):
    """Lesson 04's formula as printed: λ_i / w_i over their sum, in float64."""
    with np.errstate(all="ignore"):
        q = np.asarray(lam, float) / np.asarray(w, float)
        return q / q.sum()


def test_lesson_04s_formula_passes_the_floor_and_fails_3_2_beyond_a_gpu():
    """D12-1: "fails, though all 1728 pixels match the package's" for w = 1e-310, which
    exercise 3 calls "the simulator's concern, not a GPU's"; D3-1 left such w ungraded. Since
    r421 T2 3.2 grades them again: the formula fails 3.2 there, and the floor still passes,
    with a note that 3.2's own check counts them."""
    from test_capstone import _mine

    report = ex.capstone(
        "textured_floor", **_mine("textured_floor", perspective_weights=_naive_weights)
    )
    text = str(report)
    assert report.passed and report.n_wrong == 0, text
    assert "all 1728 pixels match the package's" in text, text
    assert "exercise 3.2's own check does: a simulator meets them" in text, text
    assert not _check("perspective_weights", _naive_weights).passed
    cell = " ".join(_cell("12_capstone.ipynb", 9).split())  # 12.3 (r199: a folded cell at 2)
    assert "which only a simulator meets, do not count here: 3.2 grades those itself" in cell


def test_a_wrong_weight_on_a_gpus_w_still_fails_the_scene_whose_pixels_match():
    """A mistake on a GPU's w fails the scene whose pixels all match."""
    from test_capstone import _mine

    def naive_but_clamped(lam, w):  # right inside the triangle, the floor's only centres
        return _naive_weights(np.maximum(lam, 0.0), w)

    report = ex.capstone(
        "textured_floor", **_mine("textured_floor", perspective_weights=naive_but_clamped)
    )
    assert not report.passed and report.n_wrong == 0, str(report)
    assert "p outside the triangle" in str(report), str(report)


def _float32_barycentric(xy, p):
    xy, p = np.asarray(xy, np.float32), np.asarray(p, np.float32)

    def e(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    v1, v2, v3 = xy
    if e(v1, v2, v3) == 0:  # 3.1 since ex30b: a zero area has no weights
        raise ValueError("zero area")
    return np.array([e(v2, v3, p), e(v3, v1, p), e(v1, v2, p)], np.float32) / e(v1, v2, v3)


def test_cell_4_says_the_check_asks_float64_at_the_origin_too():
    """D3-2: cell 4 gave the far triangles as the only reason for float64, but the check fails
    float32 by 1e-8 on a 5-px triangle at the origin; the text now says so, and why."""
    from test_capstone import _mine

    from teachraster.exercises.interpolation import barycentric_cases
    from teachraster.exercises.tolerance import TOL

    cell = _cell("03_interpolation.ipynb", 2)
    assert TOL == 1e-9 and "compares your weights with float64's to 1e-9" in cell, cell
    assert (
        "off by about 1e-8 (0.40000001 for 0.4)" in cell and "5-px triangle at the origin" in cell
    )
    assert "float32 numbers are 1/128 px apart" in cell
    assert float(np.spacing(np.float32(1e5))) == 1 / 128
    near = []
    for _, (xy, p), lam in barycentric_cases():
        if isinstance(lam, str):  # 3.1's zero area since ex30b: no weights
            continue
        if np.abs(xy).max() < 1e4:
            try:
                near.append(float(np.abs(_float32_barycentric(xy, p) - lam).max()))
            except ValueError:  # r440 W4: the 200-px sliver, whose E float32 rounds to 0
                continue
    assert 5e-9 < float(np.median(near)) < 5e-8, np.median(near)
    first = _check("barycentric", _float32_barycentric).failures[0]
    assert (
        "v2=(6.5, 1.5), v3=(6.5, 6.5)" in first.explanation and "(0.40000001," in first.explanation
    )
    assert "did you compute in float32" in first.explanation, first.explanation
    scene = ex.capstone(
        "single_triangle", **_mine("single_triangle", barycentric=_float32_barycentric)
    )
    assert scene.passed and "right within its rounding, so they pass" in str(scene), str(scene)


def _hiz(outer=False, vertex=True):
    """8.2 in float64 as cell 5 asks (the tile's centres inside the box, r126 N8-1);
    ``outer``: the plane at the extreme pixels' outer corners; ``vertex=False``: the plane's
    bound alone."""
    from student_variants import hiz_box

    def hiz_rejects(xyz, row0, col0, size, buffer):
        (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = np.asarray(xyz, float)
        box = hiz_box(xyz, row0, col0, size)
        if box is None:
            return True
        c0, c1, r0, r1 = box
        area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
        a = ((z2 - z1) * (y3 - y1) - (z3 - z1) * (y2 - y1)) / area
        b = ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1)) / area
        xs = [c0, c1 + 1] if outer else [c0 + 0.5, c1 + 0.5]
        ys = [r0, r1 + 1] if outer else [r0 + 0.5, r1 + 0.5]
        plane = min(z1 + a * (x - x1) + b * (y - y1) for x in xs for y in ys)
        bound = max(plane, min(z1, z2, z3)) if vertex else plane
        return bool(bound >= np.max(buffer))

    return hiz_rejects


def test_outer_corners_and_the_plane_alone_each_fail_several_clear_cases():
    """D8-3: outer corners failed only "random 16" (a tie 1.5e-11 wide), the plane alone one
    case of 35; now each fails four named cases by 0.018 or more and is named."""
    from test_exercises_r122 import _task_rule

    from teachraster.exercises.hiz_tile import _steep_cases, expected_reject

    assert _check("hiz_rejects", _hiz()).passed
    for mistake, words in ((_hiz(outer=True), "you evaluated the plane at the outer corners of the extreme pixels"),
                           (_hiz(vertex=False), "you took the bare plane at the corners")):  # fmt: skip
        report = _check("hiz_rejects", mistake)
        named = [f.case for f in report.failures if f.case.startswith("a ")]
        assert len(named) >= 4, str(report)
        assert all(words in f.explanation for f in report.failures), str(report)
    for label, args in _steep_cases():
        assert expected_reject(*args) and _task_rule(*args), label


# -- fixex13 (r126 N8-1, D8-1, D3-4, D12-3 and fixex10's note) --------------------------------


def test_8_2_asks_for_a_tighter_bound_than_lesson_10_and_names_the_lessons():
    """N8-1/D8-1: 8.2 copied lesson 10 §7's bound; it now asks for the plane over the tile's
    centres inside the triangle's bounding box, and names the lesson's bound as looser."""
    from student_variants import _hiz_with, hiz_box_corners

    from teachraster.exercises.hiz_tile import _box_cases, expected_reject, tile_bound

    text = " ".join(_cell("08_tiles.ipynb", 5).split())
    assert "Lesson 10 §7 takes the larger of two cheap lower bounds" in text, text
    # r162 C.1: the fact is given (no fragment outside the box), the recipe asked
    assert "no fragment of the triangle lies outside its bounding box" in text, text
    for label, args in _box_cases():  # each named box case: lesson 10's bound keeps it
        assert expected_reject(*args) and tile_bound(*args[:4]) < np.max(args[4]), label
    assert _check("hiz_rejects", _hiz_with()).passed
    for fn, words in ((_hiz_with(box="tile"), "you took lesson 10's bound"),
                      (_hiz_with(box="pixels"), "pixels the triangle's bounding box touches"),
                      (hiz_box_corners, "the bounding box's own corners")):  # fmt: skip
        report = _check("hiz_rejects", fn)
        assert report.failures and all(words in f.explanation for f in report.failures), report


def test_depth_test_and_safe_near_refuse_the_checkers_own_answer():
    """fixex10's note: depth_test and safe_near listed no answer, so the checker's own
    functions, handed in, passed as the student's."""
    from teachraster.exercises.depth_clipping import passes_depth
    from teachraster.exercises.near_plane import expected_near

    for name, fn in (("depth_test", lambda a, b: passes_depth(a, b)),
                     ("safe_near", lambda z, g, f, b: expected_near(z, g, f, b))):  # fmt: skip
        report = _check(name, fn)
        assert not report.passed and "not counted" in str(report), str(report)
    assert _check("depth_test", lambda a, b: a < b).passed


def test_3_1_hands_over_no_tool():
    """D3-4: cell 3 imported the package's edge_function, the decisive tool of 3.1."""
    import nbformat

    path = Path(__file__).parents[1] / "notebooks/exercises/03_interpolation.ipynb"
    code = "\n".join(c.source for c in nbformat.read(path, 4).cells if c.cell_type == "code")
    assert "edge_function" not in code and "import teachraster" not in code, code


def test_a_long_scene_name_keeps_its_title_within_the_panel():
    """D12-3: "intersecting_triangles: yours" was wider than its panel and shifted it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def stub(depths, writes):
        raise NotImplementedError

    report = ex.capstone("intersecting_triangles", depth_passes=stub)
    fig, axes = plt.subplots(1, 3, figsize=(8.8, 3.2), layout="constrained")
    report.compare(axes)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    title = axes[0].title.get_window_extent(renderer)
    panel = axes[0].get_window_extent(renderer)
    assert title.width <= panel.width + 1, (title.width, panel.width, axes[0].get_title())
    plt.close(fig)
