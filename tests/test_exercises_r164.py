"""Reader 164 on exercise 03: wrappers of tr.attribute_plane, tr.plane_equation and
tr.setup_matrix passed 3.1 (C1); float32 with abs(E) far from the origin was blamed on a
plane's cancellation, weights negated (F1); ``E <= 0`` refused was told "however thin it is"
(C2); answers off by a constant factor were told "you added a small number to E" (B4); six
3.2 mistakes got only the rule (B5); 3.1's failure note lay under the triangle inset (D10)."""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

# the same students and readers as reader 153's tests (exercise 03 too)
from test_exercises_r153 import _e, _lam, _vertices, check, f32_abs_area, kinds

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import diagnosis as dg
from teachraster.exercises import interpolation as ip
from teachraster.plotting import use_style

matplotlib.use("Agg")


def _mu(lam, w):
    q = np.asarray(lam, float) / np.asarray(w, float)
    return q / q.sum()


# -- C1: every package function that computes 3.1's weights ----------------------------------
def _guard(xy):
    if _e(*np.asarray(xy, float)) == 0:
        raise ValueError("zero area")


def by_attribute_plane(xy, p):
    _guard(xy)
    return np.array([tr.attribute_plane(xy, f)(p[0], p[1]) for f in np.eye(3)])


def by_plane_equation(xy, p):
    _guard(xy)
    return np.array([tr.plane_equation(xy, f)(p[0], p[1]) for f in np.eye(3)])


def by_setup_matrix(xy, p):
    _guard(xy)
    xy, p = np.asarray(xy, float), np.asarray(p, float)
    m = tr.setup_matrix(xy)
    l2, l3 = (m @ [1.0, 0.0]) @ (p - xy[0]), (m @ [0.0, 1.0]) @ (p - xy[0])
    return np.array([1 - l2 - l3, l2, l3])


@pytest.mark.parametrize(
    ("fn", "name"),
    [(by_attribute_plane, "attribute_plane"), (by_plane_equation, "plane_equation"),
     (by_setup_matrix, "setup_matrix")],
    ids=["attribute_plane", "plane_equation", "setup_matrix"],
)  # fmt: skip
def test_a_wrapper_of_the_packages_planes_is_not_counted(fn, name):
    report = check("barycentric", fn)
    assert not report.passed
    assert report.package is not None and f"calls teachraster's {name}" in report.package
    assert "not count" in report.package
    assert "not counted" in str(report)


def test_the_edge_function_stays_a_tool_and_a_right_answer_passes():
    def with_edge_function(xy, p):
        v1, v2, v3 = np.asarray(xy, float)
        area = float(tr.edge_function(v1, v2, v3))
        if area == 0:
            raise ValueError("zero area")
        e = [tr.edge_function(v2, v3, p), tr.edge_function(v3, v1, p), tr.edge_function(v1, v2, p)]
        return np.array(e, dtype=float) / area

    report = check("barycentric", with_edge_function)
    assert report.passed and report.package is None, str(report)


# -- F1: a sign mistake far from the origin is no float32 rounding ---------------------------
def test_float32_with_abs_area_far_out_is_named_abs_not_cancellation():
    report = check("barycentric", f32_abs_area)
    far_negative = 0
    for f in report.failures:
        if f.case.startswith("zero area"):
            continue
        assert "cancels" not in f.explanation, f.explanation
        xy = _vertices(f.explanation)  # drawn cases differ from one check to the next
        if _e(*np.asarray(xy, float)) < 0:
            assert f.kind == "absolute area", (f.case, f.kind, f.explanation)
            assert "not by its absolute value" in f.explanation
            far_negative += np.abs(xy).max() > 1e4
    assert far_negative >= 4  # random 26, 28 and 30: both of their points


def test_precision_is_not_named_where_a_mistake_gives_the_answer():
    spec = ex.checks.exercise("barycentric")
    label, (xy, p), expected = next(
        c for c in ip.barycentric_cases() if c[0].startswith("random 26")
    )
    got = f32_abs_area(xy, p)
    r = dg.Result(0, (xy, p), expected, got, False)
    assert np.abs(got + expected).max() < 1e-5  # negated, off by up to 13
    precision = dg.low_precision_mistake(spec)
    assert dg.precision_may_be_named(spec, r, precision)  # within a cancelling plane's bound
    assert not dg.precision_may_be_named(spec, r, precision, explained=True)
    absolute_fit = dg._Fit(next(m for m in spec.all_mistakes() if m.kind == "absolute area"),
                           0, {0}, 1, True, 1)  # fmt: skip
    assert dg._explained([absolute_fit], [r]) == {0}  # the sign mistake: no rounding
    absolute = next(m for m in spec.all_mistakes() if m.kind == "absolute area")
    assert dg.precision_may_be_named(spec, r, absolute)  # named with the mistake: its rest


# -- C2: a winding refused ---------------------------------------------------------------------
@pytest.mark.parametrize(("sign", "way"), [(-1, "counter-clockwise"), (1, "clockwise")])
def test_refusing_one_winding_is_named_so(sign, way):
    def refuses(xy, p):
        lam, area = _lam(xy, p)
        if area * sign >= 0:
            raise ValueError("back-facing")
        return lam

    report = check("barycentric", refuses)
    assert kinds(report) == {"refused a winding"}, kinds(report)
    words = report.failures[0].explanation
    assert f"runs {way} on screen" in words and "refuse only E == 0" in words
    assert "however thin" not in words and "threshold" not in words


def test_a_threshold_is_still_told_thin_triangles_have_weights():
    def threshold(xy, p):
        lam, area = _lam(xy, p)
        if abs(area) < 1e-2:
            raise ValueError("thin")
        return lam

    report = check("barycentric", threshold)
    assert kinds(report) == {"refused a proper triangle"}
    assert "however thin it is" in report.failures[0].explanation


# -- B4: an epsilon only where one small guard reproduces every answer ----------------------
def test_half_areas_are_named_not_epsilon():
    report = check("barycentric", lambda xy, p: 0.5 * _lam(xy, p)[0])
    assert kinds(report) == {"half areas"}, kinds(report)
    assert all("added a small number" not in f.explanation for f in report.failures)


def test_a_constant_factor_is_named_not_epsilon():
    report = check("barycentric", lambda xy, p: _lam(xy, p)[0] * 1.00000003)
    assert kinds(report) == {"constant factor"}, kinds(report)
    for f in report.failures:
        assert "added a small number" not in f.explanation
        assert "times 1.00000003" in f.explanation


def test_one_parameter_rule():
    m = ex.exercise.Mistake("x", "", fits=lambda a, e, g: True, parameter=lambda a, e, g: a[0])
    results = [dg.Result(k, (v,), 1.0, 2.0, False) for k, v in enumerate([1e-9, 1e-9, 2e-9])]
    assert not dg._one_parameter(m, results)
    assert dg._one_parameter(m, results[:2])


def test_an_epsilon_guard_is_still_named_with_its_size():
    def guarded(xy, p):
        v1, v2, v3 = np.asarray(xy, float)
        q = np.asarray(p, float)
        return np.array([_e(v2, v3, q), _e(v3, v1, q), _e(v1, v2, q)]) / (_e(v1, v2, v3) + 1e-9)

    report = check("barycentric", guarded)
    said = [f for f in report.failures if f.kind == "epsilon added to the area"]
    assert said and all("about 1e-09" in f.explanation for f in said)


@pytest.mark.parametrize(
    ("fn", "kind", "words"),
    [(lambda lam, w: (np.asarray(lam) / np.asarray(w)) / np.sum(1 / np.asarray(w)),
      "sum of 1/w", "you divided by Σ 1/w_j"),
     (lambda lam, w: (np.asarray(lam) / np.asarray(w)) / (np.sum(np.asarray(lam[:2]) / np.asarray(w[:2])) + lam[2]),
      "no 1/w in the sum at v3", "holds λ3 itself")],
    ids=["sum of 1/w", "one term without 1/w"],
)  # fmt: skip
def test_perspective_normalisers_are_named_not_epsilon(fn, kind, words):
    report = check("perspective_weights", fn)
    assert kinds(report) == {kind}, kinds(report)
    assert all("added a small number" not in f.explanation for f in report.failures)
    assert words in report.failures[0].explanation


# -- B5: 3.2's mistakes named precisely -------------------------------------------------------
def _without(k):
    def fn(lam, w):
        q = np.asarray(lam, float) / np.asarray(w, float)
        q[k] = lam[k]
        return q / q.sum()

    return fn


@pytest.mark.parametrize(
    ("fn", "kind", "words"),
    [(_without(2), "no 1/w at v3", "your weight of v3 leaves out its 1/w"),
     (_without(0), "no 1/w at v1", "your weight of v1 leaves out its 1/w"),
     (lambda lam, w: _mu(lam, np.roll(w, -1)), "w of another vertex",
      "you paired λ1 with w2, λ2 with w3 and λ3 with w1"),
     (lambda lam, w: _mu(lam, [w[0], w[0], w[2]]), "w of another vertex", "you paired λ2 with w1"),
     (lambda lam, w: _mu(lam, np.asarray(w) ** 2), "divided by w twice", "by its w twice"),
     (lambda lam, w: _mu(np.clip(lam, 0, 1), w), "clipped", "you clipped λ to [0, 1]")],
    ids=["no 1/w at v3", "no 1/w at v1", "cyclic w", "mu2 with w1", "w squared", "clipped"],
)  # fmt: skip
def test_perspective_mistakes_are_named(fn, kind, words):
    report = check("perspective_weights", fn)
    assert kinds(report) == {kind}, kinds(report)
    for f in report.failures:
        assert "in terms of μ" not in f.explanation and "μ_i ∝" not in f.explanation
    assert words in report.failures[0].explanation


# -- D10: the note beside the inset, never under it -------------------------------------------
def _zero_division(xy, p):
    v1, v2, v3 = [tuple(map(float, v)) for v in xy]
    q = tuple(map(float, p))
    area = _e(v1, v2, v3)
    return [_e(v2, v3, q) / area, _e(v3, v1, q) / area, _e(v1, v2, q) / area]


def _solve_only(xy, p):
    a = np.vstack([np.asarray(xy, float).T, np.ones(3)])
    try:
        return np.linalg.solve(a, [p[0], p[1], 1.0])
    except np.linalg.LinAlgError:
        raise ValueError("singular") from None


@pytest.mark.parametrize(
    "fn",
    [by_attribute_plane, lambda xy, p: _lam(xy, p)[0][:2], _zero_division, _solve_only],
    ids=["not counted", "wrong shape", "ZeroDivisionError", "zero area"],
)
def test_no_text_of_the_figure_lies_under_the_triangle_inset(fn):
    import matplotlib.pyplot as plt

    report = check("barycentric", fn)
    with use_style("classroom"):  # the notebook's style: large fonts
        fig, ax = plt.subplots(figsize=(7, 4))
        report.plot(ax)
        fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    inset = ax.child_axes[0].get_window_extent(renderer)
    texts = [t for t in ax.texts if t.get_text().strip()]
    assert texts
    for t in texts:
        box = t.get_window_extent(renderer)
        patch = t.get_bbox_patch()
        if patch is not None:
            box = patch.get_window_extent(renderer)
        assert box.x1 <= inset.x0, (t.get_text()[:60], box, inset)
    plt.close(fig)


def test_a_not_counted_figure_draws_no_answer_of_the_students():
    import matplotlib.pyplot as plt

    def wrapper(lam, w):
        return tr.perspective_weights(np.asarray(lam)[None], np.asarray(w), extrapolate=True)[0]

    report = check("perspective_weights", wrapper)
    assert report.package is not None and not report.failures, str(report)
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "yours" not in labels, labels  # it was drawn in the passing green
    plt.close(fig)
