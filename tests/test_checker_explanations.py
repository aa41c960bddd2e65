"""The checker's advice is right: the true cause named, each kind of mistake shown, numbers
printed with the digits that tell them apart."""

from __future__ import annotations

import re

import numpy as np
import pytest
from exercise_solutions import CORRECT, _covers_with, _owns, covers_float32, edge_function_float32

from teachraster import exercises as ex
from teachraster.exercises import interpolation
from teachraster.exercises.depth_clipping import depth_test_cases
from teachraster.exercises.scalars import num

E = CORRECT["edge_function"]
NOISE = re.compile(r"\d(0{9}|9{9})\d*[1-9]")  # 0.80000000000000004, 0.29999999999999999


def explanations(report) -> str:
    return "\n".join(f.explanation for f in report.failures)


# -- the right advice ---------------------------------------------------------------------------
@pytest.mark.parametrize(
    "absolute",
    [
        lambda a, b, p: abs(E(a, b, p)),
        lambda a, b, p: float(np.abs(E(a, b, p))),
        lambda a, b, p: -E(a, b, p) if E(a, b, p) < 0 else E(a, b, p),
    ],
)
def test_abs_of_e_is_explained_as_a_lost_sign_not_as_swapped_products(absolute):
    report = ex.check("edge_function", absolute)
    assert 0 < len(report.failures) < report.n_cases  # right on the cases where E >= 0
    for f in report.failures:
        assert f.kind == "abs" and "|E|" in f.explanation and "sign" in f.explanation
        assert "other way round" not in f.explanation


def test_negated_e_is_explained_as_swapped_products():
    report = ex.check("edge_function", lambda a, b, p: -E(a, b, p))
    assert len(report.failures) > report.n_cases // 2  # all but E == 0
    assert all("other way round" in f.explanation for f in report.failures)


def split_float32(v):
    return np.float32(CORRECT["split_point"](np.asarray(v, dtype=np.float32)))


def split_through_float32(v):
    return float(CORRECT["split_point"](np.asarray(v, dtype=np.float32)))


def bary_float32(xy, p):
    return CORRECT["barycentric"](xy, p).astype(np.float32)


def persp_float32(lam, w, f):
    return np.float32(CORRECT["perspective"](lam, w, f))


def depth_float32(incoming, stored):
    return np.float32(incoming) < np.float32(stored)


FLOAT32 = {
    "edge_function": edge_function_float32,
    "covers": covers_float32,
    "split_point": split_float32,
    "split_point computed in float32": split_through_float32,
    "barycentric": bary_float32,
    "perspective": persp_float32,
    "depth_test": depth_float32,
}
# clip_near in float32 passes within 1e-6, as colours do (r64 04-4: every GPU clips in
# float32): test_checker_corpus's "clip in float32"


@pytest.mark.parametrize("label", list(FLOAT32))
def test_float32_is_named_in_every_exercise_where_it_is_the_cause(label):
    name = label.split()[0]
    report = ex.check(name, FLOAT32[label], budget=60)
    assert report.failures, label
    for f in report.failures:
        assert "float32" in f.explanation, f.explanation


def test_fill_in_float32_near_the_origin_is_right():
    def fill32(xy, width, height):
        return CORRECT["fill"](xy, width, height).astype(np.float32)

    assert ex.check("fill", fill32, budget=120).passed


def one_winding_bottom_right(xy, p):
    return _covers_with(lambda a, b: not _owns(a, b), orient=False)(xy, p)


def raises_far_from_origin(xy, p):
    if xy[0][0] > 1000:
        raise OverflowError("too far")
    return _covers_with(lambda a, b: True)(xy, p)


@pytest.mark.parametrize("fn", [one_winding_bottom_right, raises_far_from_origin])
def test_two_different_mistakes_are_both_in_the_summary(fn):
    report = ex.check("covers", fn, budget=60)
    kinds = {f.kind for f in report.failures}
    assert len(kinds) >= 2
    assert {f.kind for f in report.shown()} == kinds
    text = str(report)
    for kind in kinds:
        example = next(f for f in report.failures if f.kind == kind)
        assert example.explanation in text


def test_the_winding_mistake_is_not_hidden_behind_tie_rule_failures():
    text = str(ex.check("covers", one_winding_bottom_right, budget=60))
    assert "handle both windings" in text
    assert "bottom-right" in text or "lies exactly on edge" in text


# -- fill: the beginner's way passes, a transposed image is recognised ---------------------------
@pytest.mark.parametrize(
    "form",
    [
        lambda cov: cov.astype(float),
        lambda cov: cov.astype(np.uint8),
        lambda cov: cov.astype(int).tolist(),
        lambda cov: np.where(cov, 1.0, 0.0),
    ],
)
def test_a_correct_fill_in_zeros_and_ones_passes(form):
    def fill(xy, width, height):
        return form(CORRECT["fill"](xy, width, height))

    assert ex.check("fill", fill, budget=120).passed


def test_the_beginners_fill_passes():
    def fill(xy, width, height):
        out = np.zeros((height, width))
        for i in range(height):
            for j in range(width):
                if CORRECT["covers"](xy, (j + 0.5, i + 0.5)):
                    out[i, j] = 1.0
        return out

    assert ex.check("fill", fill, budget=120).passed


@pytest.mark.parametrize("scale, shown", [(255, "255"), (0.5, "0.5"), (-1, "-1")])
def test_values_other_than_zero_and_one_are_explained(scale, shown):
    def fill(xy, width, height):
        return CORRECT["fill"](xy, width, height) * scale

    report = ex.check("fill", fill, budget=120)
    f = report.failures[0]
    assert f.kind == "type" and f"holding {shown} at row" in f.explanation


def test_a_transposed_fill_is_recognised_on_square_and_oblong_images():
    def fill(xy, width, height):
        return CORRECT["fill"](xy, width, height).T

    report = ex.check("fill", fill, budget=120)
    assert report.failures
    assert all(f.kind == "transposed" for f in report.failures)
    assert all("transposed" in f.explanation for f in report.failures)
    oblong = [f for f in report.failures if np.shape(f.got) != np.shape(f.expected)]
    assert oblong  # sliver_pair is 64 x 4


# -- numbers: the fewest digits that tell two values apart ---------------------------------------
def test_num_prints_the_shortest_digits_that_differ():
    assert num(0.8, 0.8000000000000002) == "0.8"
    assert num(0.8000000000000002, 0.8) == "0.8000000000000002"
    assert num(0.3, 0.30000000000000004) == "0.3"
    assert num(0.5, np.nextafter(0.5, 0)) == "0.5"
    assert num(np.nextafter(0.5, 0), 0.5) == "0.4999999999999999"  # 16 digits tell it apart
    assert num(25.0, 25.0000025) == "25" and num(25.0000025, 25.0) == "25.000003"
    assert num(3.04545) == "3.045" and num(0.1 + 0.2) == "0.3"
    for x, y in [(1.0, 1.0 + 2**-52), (1e6, 1e6 + 1e-9), (-0.125, -0.12500001), (1e-7, 2e-7)]:
        assert num(x, y) != num(y, x)
        assert float(num(x, y)) == pytest.approx(x) and float(num(y, x)) == pytest.approx(y)


def test_depth_labels_never_show_two_different_depths_alike():
    for label, (a, b), _ in depth_test_cases():
        if a != b and label.startswith("incoming"):
            m = re.match(r"incoming (\S+), stored (\S+)", label)
            assert m.group(1) != m.group(2), label


def perturbed(name):
    """The correct answer off by 1e-7 (relative): wrong, and close enough to print alike
    (clip_near: 2e-5, just past its float32 tolerance of 1e-5, r64 04-4)."""
    off = 2e-5 if name == "clip_near" else 1e-7

    def fn(*args):
        value = CORRECT[name](*args)
        return np.asarray(value, dtype=float) * (1 + off) + off

    return fn


@pytest.mark.parametrize(
    "name, pattern",
    [
        # r153 D3-5: a float64 answer off by 1e-7 is no float32 number: no float32 sentence
        # follows it now, so the number may end the text
        ("edge_function", r"= (\S+); yours is (\S+?)(?:\.\s|\.?$)"),
        ("split_point", r"your u4 is (\S+) for .* at u = (\S+?)[ :]"),
        ("barycentric", r"your λ = (\(.*?\)).*the weights are (\(.*?\))"),
        ("perspective", r"your (\S+?);? the perspective-correct value is (\S+?)[ :=]"),
        ("clip_near", r"your polygon (\[.*?\]) should be (\[.*?\])"),
    ],
)
def test_yours_and_expected_never_print_alike(name, pattern):
    report = ex.check(name, perturbed(name))
    assert report.failures
    for f in report.failures:
        assert not NOISE.search(f.explanation), f.explanation
        m = re.search(pattern, f.explanation)
        assert m, f.explanation
        assert m.group(1) != m.group(2), f.explanation


def test_depth_explanations_tell_near_ties_apart():
    report = ex.check("depth_test", lambda incoming, stored: incoming > stored)
    for f in report.failures:
        m = re.search(r"incoming depth (\S+) .*the stored (\S+)", f.explanation)
        if m and "equals" not in f.explanation:
            assert m.group(1) != m.group(2), f.explanation


def test_barycentric_sign_mistakes_are_told_apart():
    def over_abs_area(xy, p):
        a, b, c = (np.asarray(q, dtype=float) for q in xy)
        if E(a, b, c) == 0:  # 3.1 since ex30b: a zero area has no weights
            raise ValueError("zero area")
        w = np.array([E(b, c, p), E(c, a, p), E(a, b, p)])
        return w / abs(E(a, b, c))

    def edges_reversed(xy, p):
        a, b, c = (np.asarray(q, dtype=float) for q in xy)
        if E(a, b, c) == 0:
            raise ValueError("zero area")
        return np.array([E(c, b, p), E(a, c, p), E(b, a, p)]) / E(a, b, c)

    report = ex.check("barycentric", over_abs_area)
    assert report.failures and all(f.kind == "absolute area" for f in report.failures)
    assert "not by its absolute value" in report.failures[0].explanation
    report = ex.check("barycentric", edges_reversed)
    # all but the zero-area ones (r153 D3-1: seven of them)
    assert len(report.failures) == report.n_cases - len(interpolation.DEGENERATE)
    assert all(f.kind == "sign" for f in report.failures)
    assert all("absolute value" not in f.explanation for f in report.failures)


def test_an_upside_down_fill_is_recognised():
    def fill(xy, width, height):
        return CORRECT["fill"](xy, width, height)[::-1]

    report = ex.check("fill", fill, budget=120)
    assert report.failures and all(f.kind == "upside down" for f in report.failures)
    assert "upside down" in report.failures[0].explanation


def test_covers_with_x_and_y_swapped_is_named():
    def covers(xy, p):
        return CORRECT["covers"](np.asarray(xy)[:, ::-1], np.asarray(p)[::-1])

    report = ex.check("covers", covers, budget=120)
    swapped = [f for f in report.failures if f.kind == "transposed"]
    assert swapped and "x and y are swapped" in swapped[0].explanation
    assert "np.zeros" not in swapped[0].explanation
