"""Review r85 (exercises 01, 04, 07 played as students): the first failing try gives no
formula away, and the mistakes it left unnamed or misnamed are named.

Each test checks a student's first try (the staged hints on) or, where the mistake is named
in the full words, the full words (the hints spent, as after two different failing answers).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from exercise_solutions import CORRECT
from reasoning_solutions import CORRECT as REASONING

from teachraster import exercises as ex
from teachraster.exercises import tries
from teachraster.exercises.level_of_detail import level_with


def _first_try(name, fn):
    """The report of a student's first failing check of task ``name`` in a fresh kernel."""
    tries.forget_hints(name)
    try:
        return ex.check(name, fn, budget=60)
    finally:
        tries.spend_hints([name])


def _words(report) -> str:
    return "\n".join(f.explanation for f in report.failures)


def test_mip_levels_first_try_gives_neither_the_axes_in_texels_nor_rho():
    """r85 07 D1: "the footprint's axis along x is 8 texels, along y 2 texels (ρ = 8), λ = 3"
    answered 7.1's three steps on the first failure."""
    report = _first_try("mip_level", lambda *a: level_with(*a, scale="units"))
    words = _words(report)
    assert not report.passed and "a hint only" in str(report)
    assert "ρ" not in words and "texels (" not in words and "u times W" not in words, words
    assert "texture, λ = 0; yours is -6" in words, words


@pytest.mark.parametrize(("knobs", "named"), [
    ({"log": "floor"}, "rounded λ down to a whole level"),
    ({"pair": "coordinate"}, "paired the derivatives by coordinate"),
])  # fmt: skip
def test_mip_level_mistakes_r85_left_half_named(knobs, named):
    """r85 07: a floored λ and axes built per coordinate got only the rule restated."""
    report = ex.check("mip_level", lambda *a: level_with(*a, **knobs))
    assert named in report.failures[0].explanation, str(report)


def test_one_texel_is_singular():
    """r85 07 D4: "the footprint's axis along x is 1 texels"."""
    report = ex.check("mip_level", lambda *a: level_with(*a, scale="units"))
    words = _words(report)
    assert not re.search(r"(?<![\d.])1 texels", words) and "= 1 texel," in words, words


def test_trilinear_that_drops_wrap_is_told_so():
    """r85 07 D3: a trilinear calling bilinear with 'repeat' whatever `wrap` was told to
    rethink its levels and weights, which were right."""
    bilinear = CORRECT["bilinear"]

    def trilinear(pyramid, uv, lod, wrap="repeat"):
        q = len(pyramid) - 1
        lam = min(max(lod, 0.0), q)
        lower = int(math.floor(lam))
        upper, t = min(lower + 1, q), lam - lower
        a, b = bilinear(pyramid[lower], uv, "repeat"), bilinear(pyramid[upper], uv, "repeat")
        return (1 - t) * np.asarray(a) + t * np.asarray(b)

    for report in (_first_try("trilinear", trilinear), ex.check("trilinear", trilinear)):
        assert "pass trilinear's `wrap` on" in report.failures[0].explanation, str(report)


def _clip(t_of):
    def clip_near(v):
        v, out = np.asarray(v, dtype=float), []
        for i in range(3):
            a, b = v[i], v[(i + 1) % 3]
            da, db = a[2] + a[3], b[2] + b[3]
            if da >= 0:
                out.append(a)
            if (da >= 0) != (db >= 0):
                out.append(a + t_of(a, b, da, db) * (b - a))
        return np.array(out).reshape(-1, 4)

    return clip_near


@pytest.mark.parametrize(("t_of", "words"), [
    (lambda a, b, da, db: 0.5, "halfway along its edge (t = ½)"),  # the midpoint
    (lambda a, b, da, db: da / (da + db), "you took t = d_a/(d_a + d_b)"),  # a sign slip
])  # fmt: skip
def test_a_crossing_off_the_plane_is_named(t_of, words):
    """r85 04: t = ½ was told its symptom only ("keeps (…), whose z + w < 0"), a wrong sign
    the generic rule; r306: then "not on the near plane", the quantity, not the slip."""
    report = _first_try("clip_near", _clip(t_of))
    assert words in report.failures[0].explanation, str(report)


def test_t_from_z_alone_says_where_the_vertex_lies_once():
    """r85 04: the hinted words said "where z + w = 0, where z + w, …, is 0" (twice)."""
    report = _first_try("clip_near", _clip(lambda a, b, da, db: a[2] / (a[2] - b[2])))
    first = report.failures[0].explanation
    assert "you took t from z alone" in first, first
    assert "z + w = 0, where" not in first and first.count("reaches 0") == 1, first


def test_edge_functions_first_try_prints_the_value_not_the_formula():
    """r85 01: every failure printed E = (b.x − a.x)(p.y − a.y) − …, the whole of 1.1."""

    def negated(a, b, p):
        return (b[1] - a[1]) * (p[0] - a[0]) - (b[0] - a[0]) * (p[1] - a[1])

    first = _words(_first_try("edge_function", negated))
    assert "(b.x − a.x)" not in first and "E = 25; yours is -25" in first, first
    assert "(b.x − a.x)" in _words(ex.check("edge_function", negated))


def test_an_edge_function_truncated_to_an_integer_is_named():
    """r85 01: int(E) got only the numbers."""

    def truncated(a, b, p):
        return float(int((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])))

    report = ex.check("edge_function", truncated)
    assert "truncated to a whole number" in report.failures[0].explanation, str(report)


# -- r84/r85 items left open (fixexr7): each first explanation names its own mistake ------------
def _resolve_nanmean(colours, ids, background):
    return np.nanmean(np.asarray(colours, dtype=float), axis=0)  # the uncovered samples NaN


def _resolve_covered(colours, ids, background):
    return np.asarray(colours, dtype=float)[np.asarray(ids) >= 0].mean(axis=0)


def _depth_from_zero(depths, writes):
    stored = 0.0  # the buffer started at 0: no fragment is nearer, so none passes or writes
    return [d < stored for d in depths]


def _fill_sampled(dx, dy, transposed=False):
    covers = CORRECT["covers"]

    def fill(xy, width, height):
        out = np.zeros((height, width), dtype=bool)
        for i in range(height):
            for j in range(width):
                out[i, j] = covers(xy, (j + dx, i + dy))
        return out.T if transposed else out

    return fill


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # the mean of no samples
@pytest.mark.parametrize("resolve", [_resolve_nanmean, _resolve_covered])
def test_a_resolve_of_the_covered_samples_is_named_where_none_is_covered(resolve):
    """r85 06: np.nanmean over the samples (a mean of the covered ones) was told only "your
    answer holds NaN" on its first failing case, the pixel no triangle covers: the mistake,
    the background's share left out, is named there too."""
    report = _first_try("resolve", resolve)
    first = report.failures[0]
    assert first.case == "4 samples, none covered", str(report)
    assert first.kind == "covered only" and "holds NaN" not in first.explanation, str(report)
    assert "you averaged the covered samples only" in first.explanation, first.explanation
    assert "the background's share here is the whole pixel" in first.explanation
    later = report.failures[1].explanation
    assert "leaving out the background's share of the pixel (3 of its 4 samples)" in later


def test_a_depth_buffer_started_at_zero_is_told_the_cause():
    """r85 04: a buffer started at 0 (nothing is nearer) was told its symptom only ("your
    function lets no fragment pass, ever")."""
    report = _first_try("depth_passes", _depth_from_zero)
    first = report.failures[0]
    assert first.kind == "cleared to 0", str(report)
    # r273 12-3: `>` against +inf gives the same answers, so the causes are said as such
    assert "a buffer started at 0, the nearest depth" in first.explanation, first.explanation
    assert "nothing is strictly nearer than 0" in first.explanation


@pytest.mark.parametrize(("fill", "kind", "own"), [
    (_fill_sampled(0.0, 0.0), "pixel corners", "; you sampled (2, 1), which lies outside"),
    (_fill_sampled(0.5, 0.5, transposed=True), "transposed",
     "holds the pixel across the diagonal (row 3, col 2"),
])  # fmt: skip
def test_a_fills_corner_or_transposed_words_give_an_example_of_that_mistake(fill, kind, own):
    """r85 01-1: the corner and transposed words ended "For example, … lies exactly on edge
    v1→v2: the top-left rule covers it", a tie that shows neither mistake; the example now
    shows the mistake at its pixel, and no other follows."""
    report = _first_try("fill", fill)
    first = report.failures[0]
    assert first.kind == kind, str(report)
    assert own in first.explanation, first.explanation
    assert first.explanation.count("For example") == 1, first.explanation
    assert "top-left rule" not in first.explanation, first.explanation


def test_a_span_along_a_bottom_edge_reads_without_a_contradiction():
    """r85 02: "the centre line y = 1.5 crosses the triangle … from x_l = 0.5 to x_r = 60.5,
    so the covered centres are none" read as a contradiction; the line runs along the
    triangle's bottom edge, which owns none of its centres."""
    span = REASONING["span"]

    def no_horizontal_rule(xy, row):  # a horizontal edge on the line taken as two crossings
        y = row + 0.5
        on = [x for k in range(3) for x in (xy[k][0], xy[(k + 1) % 3][0])
              if xy[k][1] == xy[(k + 1) % 3][1] == y]  # fmt: skip
        if not on:
            return span(xy, row)
        return math.ceil(min(on) - 0.5), math.ceil(max(on) - 0.5)

    first = _first_try("span", no_horizontal_rule).failures[0]
    assert first.kind == "horizontal edge", first.explanation
    text = first.explanation
    assert "runs along the triangle's horizontal bottom edge" in text, text
    assert "a bottom edge owns none of its centres, so the covered centres are none" in text
    assert "crosses the triangle" not in text and text.count("bottom edge") == 3, text
