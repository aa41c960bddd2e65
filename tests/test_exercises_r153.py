"""Reader 153 on exercise 03: np.linalg.solve's LinAlgError taken for the zero-area test passed
(D3-1); float32 with abs(E) was blamed on the abs where E > 0 (D3-2: a mistake is named only
where it changes the answer); rounded weights were told "you added a small number to E" and
"did you compute in float32?" (D3-3, D3-5); 3.2's epsilon in the normaliser read "they sum to
1, and weights sum to 1" (D3-4); the hint's ".343" (D3-6); weights reversed where E < 0 (D3-7);
ZeroDivisionError said nothing of ValueError (D3-8); the failure figures (E13-E16)."""

from __future__ import annotations

import re
import warnings

import matplotlib
import numpy as np
import pytest

from teachraster import exercises as ex
from teachraster.exercises import diagnosis as dg
from teachraster.exercises import interpolation as ip

matplotlib.use("Agg")


def _e(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def _lam(xy, p, kind=float):
    v1, v2, v3 = np.asarray(xy, kind)
    q = np.asarray(p, kind)
    area = _e(v1, v2, v3)
    if area == 0:
        raise ValueError("zero area")
    return np.array([_e(v2, v3, q), _e(v3, v1, q), _e(v1, v2, q)]) / area, area


def check(name, fn):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ex.check(name, fn)


def kinds(report) -> set:
    """The kinds of the failures on a GPU's w: r421 T2 grades 3.2's w beyond that range again,
    where the slips these tests write on lesson 04's formula overflow too (test_exercises_r421
    names that)."""
    return {f.kind for f in report.failures if BEYOND_A_GPU not in f.case}  # (r429: outside too)


#: The label of 3.2's cases whose w no GPU meets (r421 T2)
BEYOND_A_GPU = "w beyond a GPU's range"


# -- D3-1: a solver's LinAlgError is no zero-area test ----------------------------------------
def by_solve_only(xy, p):
    """The reader's: numpy's LinAlgError (raised on an exact 0 pivot only) as the test."""
    a = np.vstack([np.asarray(xy, float).T, np.ones(3)])
    try:
        return np.linalg.solve(a, [p[0], p[1], 1.0])
    except np.linalg.LinAlgError:
        raise ValueError("singular") from None


def test_the_readers_collinear_triangle_is_in_the_check_and_solve_returns_numbers_there():
    xy = [[9.2578125, 3.9375], [21.546875, 1.765625], [-3.03125, 6.109375]]
    zero = [np.asarray(a[0]).tolist() for _, a, e in ip.barycentric_cases() if isinstance(e, str)]
    assert xy in zero
    offsets = set()
    for _, (tri, p), expected in ip.barycentric_cases():
        if isinstance(expected, str):
            assert _e(*np.asarray(tri, float)) == 0
            try:
                got = by_solve_only(tri, p)
            except ValueError:
                continue
            assert np.abs(got).max() > 1e6  # huge "weights", not a refusal
            offsets.add(int(np.log10(max(1.0, float(np.abs(tri).max())))))
    assert {0, 1} & offsets and {3, 5} <= offsets, offsets  # near the origin, 1e3 and 1e5


def test_linalg_error_as_the_zero_area_test_fails_and_is_named():
    report = check("barycentric", by_solve_only)
    assert not report.passed
    assert kinds(report) == {"no zero-area check"}
    words = report.failures[0].explanation
    assert "your solver returned weights for a zero-area triangle" in words
    assert "test the area exactly, E == 0" in words
    assert "NaN" not in words and "float32" not in words


def test_the_exact_test_with_a_solver_still_passes():
    def solve_after_test(xy, p):
        _lam(xy, p)  # raises ValueError on E == 0
        return np.linalg.solve(np.vstack([np.asarray(xy, float).T, np.ones(3)]), [*p, 1.0])

    assert check("barycentric", solve_after_test).passed


# -- D3-2: a mistake is named only where it changes the answer --------------------------------
def f32_abs_area(xy, p):
    lam, area = _lam(xy, p, np.float32)
    return lam * area / abs(area)


def _vertices(label: str) -> np.ndarray:
    """v1, v2, v3 as the explanation prints them (exactly, on the grid)."""
    found = re.search(r"v1=\(([^)]*)\), v2=\(([^)]*)\), v3=\(([^)]*)\)", label)
    return np.array([[float(x) for x in g.split(",")] for g in found.groups()])


def test_float32_with_abs_area_is_float32_where_e_is_positive_and_abs_where_negative():
    report = check("barycentric", f32_abs_area)
    assert not report.passed
    seen = set()
    for f in report.failures:
        if f.case.startswith("zero area"):  # 100 000 px out: float32 leaves the grid
            assert f.kind == "float32" and "E is no longer 0" in f.explanation, f.explanation
            continue
        area = _e(*_vertices(f.explanation))
        if "absolute value" in f.explanation:
            assert area < 0, f.explanation  # the abs changes only a negative area's answer
            seen.add("abs")
        if area > 0:
            assert "negative" not in f.explanation.split("weights are")[-1], f.explanation
            assert f.kind == "float32", (f.kind, f.explanation)
            seen.add("float32")
    assert seen == {"abs", "float32"}
    first = report.failures[0]  # d3d_split_square, E = +25: the reader's first line
    assert first.case.startswith("d3d_split_square")
    assert "float32" in first.explanation and "absolute value" not in first.explanation


def test_the_general_rule_a_mistake_giving_the_right_answer_explains_no_failure():
    spec = ex.checks.exercise("barycentric")
    xy, p = np.array([[1.5, 1.5], [6.5, 1.5], [6.5, 6.5]]), np.array([4.5, 3.5])
    right = ip.barycentric(xy, p)
    got = right + 1e-8  # float32-sized off, on a case where E > 0
    r = dg.Result(0, (xy, p), right, got, False)
    absolute = next(m for m in spec.all_mistakes() if m.kind == "absolute area")
    assert dg._fits(spec, absolute, r) is None  # says nothing: abs(E) = E here
    flipped = dg.Result(0, (xy[::-1], p), ip.barycentric(xy[::-1], p), None, False)
    flipped = dg.Result(0, flipped.args, flipped.expected, -flipped.expected, False)
    assert dg._fits(spec, absolute, flipped) is True  # E < 0: the abs is the cause


# -- D3-3, D3-5: rounded weights ---------------------------------------------------------------
@pytest.mark.parametrize("decimals", [4, 6, 8])
def test_rounded_weights_are_named_rounded_not_epsilon_nor_float32(decimals):
    report = check("barycentric", lambda xy, p: np.round(_lam(xy, p)[0], decimals))
    assert not report.passed
    assert kinds(report) == {"rounded"}, kinds(report)
    words = report.failures[0].explanation
    assert f"rounded to {decimals} decimals" in words
    for f in report.failures:
        assert "added a small number" not in f.explanation
        assert not dg.blames_precision(f.explanation), f.explanation


def test_seven_significant_digits_are_not_asked_about_float32():
    def sig7(xy, p):
        return np.array([float(f"{x:.7g}") for x in _lam(xy, p)[0]])

    report = check("barycentric", sig7)
    assert not report.passed
    for f in report.failures:
        assert "did you compute in float32" not in f.explanation, f.explanation


def test_a_rounded_perspective_answer_is_not_sent_back_to_derive():
    def rounded(lam, w):
        q = np.asarray(lam) / np.asarray(w)
        return np.round(q / q.sum(), 4)

    report = check("perspective_weights", rounded)
    assert kinds(report) == {"rounded"}, kinds(report)
    for f in report.failures:
        if BEYOND_A_GPU in f.case:  # r421 T2: lesson 04's formula overflows there
            continue
        assert "rounded to" in f.explanation and "turn that around" not in f.explanation


def test_float32_is_asked_only_of_float32_numbers():
    e = np.array([1 / 3, 1 / 3, 1 / 3])
    assert not dg.held_by_precision(e, np.round(e, 8))
    assert dg.held_by_precision(e, e.astype(np.float32))
    assert dg.held_by_precision(e, e.astype(np.float32).astype(float))


# -- D3-4: 3.2's epsilon in the normaliser ----------------------------------------------------
def test_an_epsilon_in_the_normaliser_is_named_with_a_sum_that_is_not_1():
    def nudged(lam, w):
        q = np.asarray(lam) / np.asarray(w)
        return q / (q.sum() + 1e-9)

    report = check("perspective_weights", nudged)
    assert kinds(report) == {"epsilon added to the sum"}, kinds(report)
    words = report.failures[0].explanation
    assert "they sum to 0.999999999, not 1" in words and "about 1e-09" in words
    assert "they sum to 1," not in words


# -- D3-6, D3-7, D3-8 -------------------------------------------------------------------------
def test_the_hint_replaces_the_whole_area_not_up_to_its_point():
    def unnormalised_far(xy, p):
        lam, area = _lam(xy, p)
        return lam * area

    report = check("barycentric", unnormalised_far)
    for f in report.failures:
        assert "on this case." not in f.explanation, f.explanation
    text = ": λ_i = E of the edge opposite v_i at p, divided by E(v1, v2, v3) = 9.343; yours"
    for pattern, short in ex.checks.exercise("barycentric").hints[:1]:
        assert pattern.sub(short, text).endswith("on this case; yours")


def test_weights_reversed_where_the_area_is_negative_are_named():
    def reversed_where_negative(xy, p):
        v = np.asarray(xy, float)
        return _lam(v[::-1] if _e(*v) < 0 else v, p)[0]

    report = check("barycentric", reversed_where_negative)
    assert kinds(report) == {"reversed where E < 0"}, kinds(report)
    assert "reverse order" in report.failures[0].explanation


def test_zero_division_error_is_told_value_error_is_expected():
    def plain(xy, p):
        v1, v2, v3 = [tuple(map(float, v)) for v in xy]
        q = tuple(map(float, p))
        area = _e(v1, v2, v3)  # plain floats: 1.0 / 0.0 raises ZeroDivisionError
        return [_e(v2, v3, q) / area, _e(v3, v1, q) / area, _e(v1, v2, q) / area]

    report = check("barycentric", plain)
    raised = [f for f in report.failures if "ZeroDivisionError" in f.explanation]
    assert raised
    assert all("expects ValueError" in f.explanation for f in raised)


# -- E13-E16: figures -------------------------------------------------------------------------
def _figure(report):
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    fig.canvas.draw()
    return fig, ax


def test_the_zero_area_figure_has_no_empty_axes_and_shows_the_answer():
    import matplotlib.pyplot as plt

    fig, ax = _figure(check("barycentric", by_solve_only))
    assert not ax.get_xticks().size and not ax.get_yticks().size
    assert not any(s.get_visible() for s in ax.spines.values())
    texts = [t.get_text() for t in ax.texts]
    assert any("yours:" in t for t in texts), texts
    inset = ax.child_axes[0]
    assert not any(t.get_text().startswith("λ") for t in inset.texts)  # nothing piles on p
    plt.close(fig)


def test_p_is_drawn_above_the_labels_and_float32_bars_are_said_equal():
    import matplotlib.pyplot as plt

    def f32(xy, p):
        return _lam(xy, p, np.float32)[0]

    fig, ax = _figure(check("barycentric", f32))
    inset = ax.child_axes[0]
    dots = [ln for ln in inset.lines if ln.get_marker() == "o"]
    labels = [t for t in inset.texts if t.get_text().startswith("λ")]
    assert dots and all(d.get_zorder() > t.get_zorder() for d in dots for t in labels)
    assert any("equal at this scale" in t.get_text() for t in ax.texts)
    plt.close(fig)
