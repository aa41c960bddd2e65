"""r385 (exercise 02, ``span``, read afresh): five wrong answers passed (divide first on the
long edge only or from each edge's lower end, an epsilon of 1e-6 or 1e-9 "for safety", a row
test on ⌊y⌋); "you left out the centres on … a horizontal top edge" was said of a top edge's
ends in the order given, of truncated vertices, of no sort and of a bounding box; "the long
edge" read as the longest edge was told "strict"; float32's t and the lerp were told only their
ends; a side test wrong on some rows was told only its ends; the figure's roles on a horizontal
top edge contradicted lesson 01 (the smaller x first). The named variants are corpus cases
(``student_variants.R385``): here each is checked for its words and kinds."""

from __future__ import annotations

import json
import math
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from student_variants import R385

from teachraster import exercises as ex
from teachraster.exercises import span_variants, spans

matplotlib.use("Agg")

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "02_span_split.ipynb"

#: the kinds a variant may also have on some failing cases (a ZeroDivisionError where its
#: roles put a horizontal edge between two vertices it divides by)
ALSO = {"span, vertices not sorted": {"raised"}, "span, the bounding box on every row": {"type"}}


def _teacher():
    source = "".join(json.loads(NOTEBOOK.read_text())["cells"][3]["source"])
    scope: dict = {}
    exec(compile(source, "span_solution", "exec"), scope)  # noqa: S102 - the notebook's own cell
    return scope["span"]


def test_the_teachers_solution_passes_the_new_cases():
    assert ex.check("span", _teacher()).passed


@pytest.mark.parametrize("label", sorted(R385))
def test_each_r385_variant_fails_with_its_own_words(label):
    name, fn, words, kind = R385[label]
    report = ex.check(name, fn)
    assert not report.passed
    text = str(report)
    assert words in text, text
    assert report.failures[0].kind == kind, text
    near = {f.kind for f in report.failures if not f.case.startswith("far out")}
    assert near <= {kind} | ALSO.get(label, set()), text


def test_no_top_edge_line_is_said_where_it_is_not_the_students_answer():
    """M7: "you left out the centres on … a horizontal top edge" only where it is the cause."""
    for label in ("span, a top edge's ends in the order given", "span, vertices truncated "
                  "with int()", "span, vertices not sorted", "span, the bounding box on every "
                  "row"):  # fmt: skip
        text = str(ex.check("span", R385[label][1]))
        assert "you left out the centres on" not in text, (label, text)


def test_a_crossing_that_rounds_is_quoted_against_the_exact_one():
    """P4, H2: the student's crossing (as a usual formula gives it) beside the exact one."""
    report = ex.check("span", R385["span, divided first on the long edge only"][1])
    first = report.failures[0].explanation
    assert "is exactly 50.5, a centre" in first, first
    assert "gives 50.50000000000001" in first, first
    lerp = str(ex.check("span", R385["span, the lerp (1 − t)·a + t·b"][1]))
    assert "the lerp (1 − t)·a + t·b" in lerp, lerp


def test_an_epsilon_is_named_with_the_gap():
    report = ex.check("span", R385["span, an epsilon of 1e-6 on the ends"][1])
    assert "x_l lies 3.9e-08 px right of the centre 0.5" in report.failures[0].explanation


def test_every_edge_has_a_tie_from_both_ends_and_the_near_ties_lie_in_range():
    """P4: each edge (long, upper, lower) has a case where divide first, slope first and the
    lerp land a hair right of a tie from each end; P5: the near ties lie under 10^-5 px right
    of a centre, within |x|, |y| < 2^17 (where float64's multiply first is exact)."""
    y_of = {}
    for points, row in span_variants.TIE_ENDS:
        v = sorted(points, key=lambda p: p[1])
        y = row + 0.5
        edges = {"long": (v[0], v[2]), "upper" if y < v[1][1] else "lower":
                 (v[0], v[1]) if y < v[1][1] else (v[1], v[2])}  # fmt: skip
        for role, (a, b) in edges.items():
            exact = spans.crossings(np.array([a, b, (a[0] + 1, a[1])]), y)
            for how in ("divide first", "slope first", "lerp"):
                for p, q, end in ((a, b, "upper"), (b, a, "lower")):
                    got = spans._rounded_crossing(p, q, y, how)
                    if exact is not None and math.ceil(got - 0.5) != math.ceil(_on(a, b, y) - 0.5):
                        y_of[(role, how, end)] = row
    assert len(y_of) == 18, sorted(y_of)
    for points, row in span_variants.NEAR_TIES:
        xy = np.array(points)
        assert np.abs(xy).max() < span_variants.FLOAT64_EXACT_BELOW
        xl = spans.crossings(xy, row + 0.5)[0]
        assert 0 < xl - math.floor(xl) - 0.5 < 1e-6 or 0 < xl - math.floor(xl) + 0.5 < 1e-6


def _on(a, b, y):
    from fractions import Fraction

    a, b = [tuple(map(Fraction, p)) for p in (a, b)]
    return a[0] + (Fraction(y) - a[1]) * (b[0] - a[0]) / (b[1] - a[1])


def test_the_roles_on_a_horizontal_top_edge_follow_lesson_01():
    """F3: two vertices at one height, the smaller x first (np.lexsort): (6.5, 9.5) is the top."""
    import matplotlib.pyplot as plt

    xy = np.array([[9.5, 9.5], [3.5, 12.5], [6.5, 9.5]])
    fig, ax = plt.subplots()
    texts = spans._roles(ax, xy, 0, 16)
    where = {t.get_text(): t.xy for t in texts}
    plt.close(fig)
    assert where["top"] == (6.5, 9.5) and where["middle"] == (9.5, 9.5), where


def test_each_far_row_has_a_tie_that_float64_multiply_first_moves_right():
    """Session 35 (r385 T1): on each far row a crossing lies exactly on a centre, and lesson
    01's multiply-first crossing in float64, from the end the label names, lands a hair right
    of it (first or stop one column too far right); the vertices lie in the stated range."""
    from fractions import Fraction

    for label, points, row in span_variants.FAR_TIES:
        xy = np.array(points)
        assert span_variants.FLOAT64_EXACT_BELOW < np.abs(xy).max() < span_variants.EXACT_BELOW
        assert (xy * 256 == np.round(xy * 256)).all()
        v = sorted(points, key=lambda p: p[1])
        edge = {"long": (v[0], v[2]), "upper": (v[0], v[1]), "lower": (v[1], v[2])}
        a, b = edge[label.split()[1]]
        if "lower end" in label:
            a, b = b, a
        y = row + 0.5
        exact = _on(a, b, y)
        assert (exact - Fraction(1, 2)).denominator == 1, label  # on a centre
        got = span_variants.float_crossing(a, b, y)
        assert got > exact and math.ceil(got - 0.5) == math.ceil(exact - 0.5) + 1, label
        assert exact in spans.crossings(xy, Fraction(2 * row + 1, 2)), label  # x_l or x_r
