"""Review r440 (exercise 3 read again): four wrong answers passed (W1 a tiny λ masked by a
tolerance, W2 an ε in the normaliser after the right scaling, W3 a reference w from the
extremes, W4 3.1's zero-area test in float32), two were misnamed (M1 an ε in each w told
"λ1 = 0 … 0 / 0 is NaN" on a case with neither, M2 float32 ratios told to redo the
derivation) and three half-named (H1 p truncated told p − ½, H2 a weight where λ = 0, H3 a
float32 sum told "they sum to 0.9999999"). The students are in ``student_variants.R440``;
here, each is checked once, and the cases that catch them.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import DIFFERENT, KINDS, R440

from teachraster import exercises as ex
from teachraster.core.edges import edge_function
from teachraster.exercises import interpolation as ip
from teachraster.exercises import perspective_weighting as pw


@pytest.mark.parametrize("label", sorted(R440))
def test_each_slip_fails_named_in_its_first_explanation(label):
    name, fn, words, kind = R440[label]
    report = ex.check(name, fn)
    assert not report.passed, f"{label}: {report}"
    first = report.failures[0]
    assert words in first.explanation, f"{label}: {first.explanation}"
    assert first.kind == kind == KINDS[label], (label, first.kind)


@pytest.mark.parametrize(
    "label",
    ["barycentric by the sub-areas over their sum",
     "perspective weights as lesson 04 prints them where finite, scaled elsewhere"],
)  # fmt: skip
def test_the_new_cases_fail_no_correct_solution(label):
    name, fn = DIFFERENT[label]
    assert ex.check(name, fn).passed


def test_the_long_sliver_is_real_and_flat_in_every_float32_form_of_e():
    """W4: float32 holds the sliver's vertices, yet E about each vertex and in absolute
    coordinates rounds to 0 there; float64's E is 2^-15."""
    (_, xy, _) = next(c for c in ip.THIN_FAR if c[0].startswith("a sliver"))
    v = np.array(xy)
    assert np.array_equal(v.astype(np.float32).astype(float), v)
    assert float(edge_function(*v)) == 2.0**-15
    f = v.astype(np.float32)
    for k in range(3):
        a, b, c = f[k], f[(k + 1) % 3], f[(k + 2) % 3]
        assert (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) == 0
    (x1, y1), (x2, y2), (x3, y3) = f
    assert x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2) == 0


def test_the_near_edge_and_1e_320_cases_are_graded():
    """W1-W3: a tiny λ at the smallest w weighs 1e-4 of μ; w1 = 1e-320 is beyond a GPU's w."""
    cases = {label: (args, mu) for label, args, mu in pw.weights_cases()}
    near = [mu for label, (_, mu) in cases.items() if label.startswith("p next to the edge")]
    assert len(near) == 2 and abs(near[0][0] - 1e-4) < 1e-6 and abs(near[1][0] - 0.5) < 1e-9
    assert any("1e-320" in label for label in cases)
    assert pw.beyond_a_gpu(next(label for label in cases if "1e-320" in label))


def test_an_epsilon_in_w_beyond_a_gpu_never_says_lambda_0_or_nan():
    """M1: the words of the smallest w of all ("but λ1 = 0", "0 / 0 is NaN") are said only
    where λ1 is 0: a slip that gives the right answer on a case says nothing there."""
    _, fn, _, _ = R440["perspective weights scaled right, an ε in each w"]
    first = ex.check("perspective_weights", fn).failures[0]
    assert "λ1 = 0" not in first.explanation and "NaN" not in first.explanation, first


def test_a_weight_where_lambda_is_0_is_said_so():
    """H2: np.divide(..., where=) without out= leaves memory where λ = 0 (not reproducible:
    the symptom is given an answer directly)."""
    case = next(c for c in pw.weights_cases() if c[0].startswith("λ = (1, 0, 0), w = (1, 2, 4)"))
    _, args, mu = case
    got = np.array([4 / 3, 0.0, -1 / 3])
    symptom = next(m for m in pw.SYMPTOMS if m.kind == "weight where λ = 0")
    assert symptom.fits(args, mu, got)
    assert "your weight of v3 is -0.333, not 0" in symptom.say(args, mu, got)
