"""Exercise 09 (lesson 12), review r8's items: each mistake class named by what the answer
shows, no wrong variant passes, the α = 0 cases, one number format for two colours, figures
that show src and dst and never the answer first, and a front-to-back walk that must read the
layers nearest first and stop at an opaque one.

The correct solutions and most generic mistakes run in ``test_exercises.py`` and
``test_checker_corpus.py``; the classes added for r8 are tested here, each with one check.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

import numpy as np
import pytest
import student_variants as sv
from lines_blending_solutions import EPS, _meets, line_pixels, line_with, over_straight
from lines_blending_solutions import atop_premultiplied as atop_pm
from lines_blending_solutions import over_premultiplied as over_pm
from lines_blending_solutions import over_to_premultiplied as over_tp
from reasoning_solutions import front_to_back
from student_variants import _under_with, front_to_back_by_reversing, layers_vectorised

from teachraster import exercises as ex
from teachraster.exercises.blending import colour_texts
from teachraster.exercises.front_to_back import layer_stream
from teachraster.exercises.lines import as_pixels


def _first(name, fn):
    report = ex.check(name, fn, budget=60)
    assert not report.passed, f"{name}: a wrong variant passes"
    assert all(f.kind for f in report.failures), "every failure has a kind"
    return report.failures[0]


# -- 9.1 line_pixels -------------------------------------------------------------------------
E2 = EPS * EPS


@pytest.mark.parametrize(
    ("move", "kind", "words"),
    [
        # r8: (−ε, −ε) was "you swapped the two"
        ((-EPS, -EPS), "ε in y", "you moved y by −ε, as much as x"),
        ((-E2, -EPS), "ε in y, ε² in x", "you moved x by −ε² and y by −ε"),
        ((-EPS, EPS), "+ε in y", "you moved y by +ε"),
        ((EPS, 0), "+ε in x, y not moved", "you moved x by +ε"),
        ((0, -E2), "x not moved", "you did not move x"),
    ],
)
def test_each_perturbation_slip_is_named_by_what_it_moved(move, kind, words):
    first = _first("line_pixels", line_with(*move))
    assert first.kind == kind and words in first.explanation, first.explanation
    assert "swapped the two" not in first.explanation


def test_a_float_eps_squared_lost_to_rounding_is_said_so():
    """r8: ε² = 1e-18 vanishes beside 3.0 in float64; the student did move y."""

    def floats(p0, p1):
        return line_with(0, 0)((p0[0] - 1e-9, p0[1] - 1e-18), (p1[0] - 1e-9, p1[1] - 1e-18))

    first = _first("line_pixels", floats)
    assert "you did not move y (or yours was lost in floating point" in first.explanation
    assert "Fraction" in first.explanation and "left y as it is" not in first.explanation


@pytest.mark.parametrize(
    "fn",
    [
        line_with(E2, -EPS),
        line_with(0, EPS),
        line_with(EPS, E2),
        line_with(-EPS, 0),
        line_with(-EPS, E2),
        line_with(-EPS, -E2, "col row"),
    ],  # fmt: skip
    ids=["+e2,-e", "0,+e", "+e,+e2", "no e2", "+e2 in y", "col row"],
)
def test_no_wrong_perturbation_or_order_passes(fn):
    _first("line_pixels", fn)


def test_an_empty_array_of_pairs_is_an_empty_answer():
    """r8: np.array([]) (shape (0,)) was called "not a list of (row, col) pairs"."""
    assert as_pixels(np.array([])) == frozenset() == as_pixels(np.zeros((0, 2)))
    report = ex.check("line_pixels", lambda p0, p1: np.array(line_pixels(p0, p1)), budget=60)
    assert report.passed, str(report)


def _line_knobs(end_unmoved=False, start=False):
    """The exact rule (Fraction) with one of r9's mistakes: p1's diamond tested before p1 was
    moved, or the diamond p0 lies in left dark."""
    half = Fraction(1, 2)

    def fn(p0, p1):
        a = (Fraction(p0[0]) - EPS, Fraction(p0[1]) - EPS * EPS)
        b = (Fraction(p1[0]) - EPS, Fraction(p1[1]) - EPS * EPS)
        end = (Fraction(p1[0]), Fraction(p1[1])) if end_unmoved else b
        out = []
        for row in range(max(int(min(a[1], b[1])) - 1, 0), int(max(a[1], b[1])) + 2):
            for col in range(max(int(min(a[0], b[0])) - 1, 0), int(max(a[0], b[0])) + 2):
                cx, cy = col + half, row + half
                inside_end = abs(end[0] - cx) + abs(end[1] - cy) < half
                inside_start = start and abs(a[0] - cx) + abs(a[1] - cy) < half
                if _meets(a, b, cx, cy) and not inside_end and not inside_start:
                    out.append((row, col))
        return out

    return fn


def test_the_tie_words_agree_with_lesson_12_and_conventions():
    """r9 09-1: the text said GL moves y up and lights row k − 1; lesson 12 §1 prints that GL
    lights the lower row, teachraster (and Direct3D) the upper one."""
    first = _first("line_pixels", line_with(-EPS, 0))
    assert "GL moves the segment" not in first.explanation
    # r289 S8: lesson 12a §1 calls the y-down −(ε, ε²) Vulkan's rule, Direct3D's "another"
    assert "row k − 1, the upper row, as Vulkan's rule does" in first.explanation
    assert "lights the lower row, row k: lesson 12a §1" in first.explanation
    assert "GL moves it up" not in _first("line_pixels", line_with(-EPS, E2)).explanation
    import json
    from pathlib import Path

    nb = Path(__file__).parent.parent / "notebooks/exercises/09_lines_and_blending.ipynb"
    task = "".join(json.loads(nb.read_text())["cells"][2]["source"])
    assert "GL\nsettles" not in task and "lights the lower row" in task.replace("\n", " ")


@pytest.mark.parametrize("denominator", [100, 64, 128])
def test_an_eps_too_large_fails_and_is_named(denominator):
    """r9 09-2: ε = 1/100 passed every case."""
    e = Fraction(1, denominator)
    first = _first("line_pixels", line_with(-e, -e * e))
    assert first.kind == "ε not small enough", first.explanation
    assert "your ε is not small enough" in first.explanation
    # r14 09-4: ε = 1/64 was told "those an ε of 1/50 gives" (the table's first that fits)
    assert f"1/{denominator}" in first.explanation.split("ε² in y")[0], first.explanation


def test_p1_tested_before_moving_is_named_and_never_called_eps_in_y():
    """r9 09-3: "p1 in its diamond" with the unmoved p1 was told "you moved y by −ε"."""
    first = _first("line_pixels", _line_knobs(end_unmoved=True))
    assert first.kind == "end tested before moving", first.explanation
    assert "with p1 unmoved" in first.explanation and "−ε, as much as x" not in first.explanation


def test_p1_never_moved_is_not_told_it_was_moved_for_the_segment():
    """r18 D-6: a line moving p0 alone (p1 unmoved in the segment and in the end test) was
    told "move p1 ... for that test as well, as for the rest of the segment"."""

    def p0_only(p0, p1):
        p1 = (Fraction(p1[0]) + EPS, Fraction(p1[1]) + EPS * EPS)  # undoes the move of p1
        return line_with(-EPS, -EPS * EPS)(p0, p1)

    report = ex.check("line_pixels", p0_only, budget=60)
    assert not report.passed, str(report)
    first = report.failures[0]
    assert first.kind.startswith("end tested before moving"), (first.kind, first.explanation)
    assert "as for the rest of the segment" not in first.explanation, first.explanation
    assert "with p1 unmoved" in first.explanation, first.explanation


def test_a_mistake_is_named_only_where_it_gives_every_failing_answer():
    """r9 09-3, the class: (−ε, −ε) shared one failing answer with another mistake. A student
    with two unrelated slips gets the rule, not one of them named."""

    def two(p0, p1):  # (−ε, −ε), and one pixel of the first line dropped for another reason
        out = sorted(line_with(-EPS, -EPS)(p0, p1))
        return out[1:] if tuple(p0) == (1.5, 2.5) else out

    report = ex.check("line_pixels", two, budget=60)
    assert not report.passed
    kinds = {f.kind for f in report.failures}
    assert "ε in y" not in kinds and "end tested before moving" not in kinds, kinds


def test_start_diamond_dark_closed_diamond_and_bresenham_are_named():
    """r9: these got the rule restated."""
    first = _first("line_pixels", _line_knobs(start=True))
    assert first.kind == "start diamond dark" and "p0 = " in first.explanation
    import teachraster as tr

    def bresenham(p0, p1):
        cov = tr.rasterize_line(p0, p1, 12, 12, rule="bresenham").coverage
        return [tuple(map(int, rc)) for rc in np.argwhere(cov)]

    first = _first("line_pixels", bresenham)
    assert first.kind == "Bresenham" and "Bresenham's error term" in first.explanation


def test_a_reversed_segment_is_named_without_a_false_clause():
    """r24 D-4: its message said "the −(ε, ε²) perturbation is not symmetric"; both end
    points move alike, and reversing changes only which end's diamond stays dark."""
    first = _first("line_pixels", lambda p0, p1: line_pixels(p1, p0))
    assert first.kind == "reversed", (first.kind, first.explanation)
    assert "not symmetric" not in first.explanation, first.explanation
    assert "changes only which end's diamond stays dark" in first.explanation


def test_9_2a_gl_blend_says_alpha_squared_not_counted_twice():
    """r24 D-6: GL's one-pair alpha is α_s·α_s + α_d(1 − α_s): α_s squared, not twice."""
    first = _first("over_straight", lambda s, d: np.asarray(s) * s[3] + np.asarray(d) * (1 - s[3]))
    assert first.kind == "GL's straight blend", (first.kind, first.explanation)
    assert "its alpha weighs α_s by itself (α_s squared)" in first.explanation
    assert "twice" not in first.explanation, first.explanation


def _over_straight_with(alpha, at_zero):
    """9.2a's straight over with ``alpha(s, d)`` as the result's alpha and ``at_zero(s, d)``
    where it is 0."""

    def fn(s, d):
        s, d = np.asarray(s, float), np.asarray(d, float)
        a = alpha(s, d)
        if a == 0:
            return at_zero(s, d)
        return np.r_[(s[:3] * s[3] + d[:3] * d[3] * (1 - s[3])) / a, a]

    return fn


def test_src_returned_where_nothing_covers_is_named_not_called_swapped():
    """r32 D9-1: ``if alpha == 0: return src`` was told "you swapped the weights of over" (the
    swapped pair gives src there too); it is named as "α = 0 → dst" is. A swapped pair that
    fails elsewhere is still named swapped at that case (see the swapped-pair test)."""
    right = lambda s, d: s[3] + d[3] * (1 - s[3])  # noqa: E731
    report = ex.check("over_straight", _over_straight_with(right, lambda s, d: s), budget=60)
    assert not report.passed
    assert [f.kind for f in report.failures] == ["src where nothing covers"], [
        (f.kind, f.explanation) for f in report.failures
    ]
    words = report.failures[0].explanation
    assert "you returned src (0.3, 0.6, 0.9, 0) unchanged" in words, words
    assert "(0, 0, 0, 0)" in words and "swapped" not in words, words


def _ftb_alpha_clamped(layers):
    acc = np.zeros(4)
    for c in layers:
        acc = np.r_[acc[:3] + (1 - acc[3]) * c[:3], min(1.0, acc[3] + c[3])]
        if acc[3] >= 1:
            break
    return acc


def test_r24_natural_slips_are_named():
    """r24 D-5: α = 0 → dst and α = min(1, α_s + α_d) in 9.2a, and 9.3's alphas summed and
    clamped (colour right), got a general message."""
    right = lambda s, d: s[3] + d[3] * (1 - s[3])  # noqa: E731
    zero = lambda s, d: np.zeros(4)  # noqa: E731
    assert ex.check("over_straight", _over_straight_with(right, zero)).passed
    first = _first("over_straight", _over_straight_with(right, lambda s, d: d))
    assert first.kind == "dst where nothing covers", (first.kind, first.explanation)
    assert "you returned dst (0.5, 0.2, 0.1, 0) unchanged" in first.explanation
    first = _first("over_straight", _over_straight_with(lambda s, d: min(1, s[3] + d[3]), zero))
    assert first.kind.startswith("alpha summed, clamped to 1"), (first.kind, first.explanation)
    assert "counts the share both cover twice" in first.explanation
    first = _first("front_to_back", _ftb_alpha_clamped)
    assert first.kind == "alpha summed, clamped", (first.kind, first.explanation)
    assert "clamped the sum to 1" in first.explanation


def test_a_closed_diamond_is_named():
    from teachraster.exercises.lines import diamond_pixels

    first = _first("line_pixels", lambda p0, p1: diamond_pixels(p0, p1, eps=(0, 0), closed=True))
    assert "closed diamond" in first.kind and "includes its boundary" in first.explanation


def test_every_line_case_has_its_end_points_on_the_eighth_pixel_grid():
    """r18 D-4: the task says the check's end points are on the 1/8-pixel grid inside the
    12 × 12 image (the argument that a concrete ε is small enough rests on it); three named
    cases were decimals such as (2.2, 2.3) → (2.9, 2.6)."""
    from teachraster.exercises import lines

    for label, (p0, p1), _ in lines.line_cases():
        for v in (*p0, *p1):
            assert v * 8 == int(v * 8) and 0 <= v <= 12, (label, p0, p1)
    task = " ".join(_nb_cells()["line_pixels_task"].split())
    assert "end points on the 1/8-pixel grid" in task, task


def test_the_line_figure_says_which_axis_is_x_and_which_is_row():
    """r18 D-9: the trap is (row, col) against (x, y), and the axes had no labels."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("line_pixels", sv.line_bresenham_textbook, budget=60)
    fig, ax = plt.subplots(figsize=(7, 4))
    report.failures[0].draw(ax)
    xlabel, ylabel = ax.get_xlabel(), ax.get_ylabel()
    plt.close(fig)
    assert xlabel == "x = col" and ylabel.startswith("y = row") and "down" in ylabel


def test_the_failing_line_figure_has_a_key_the_diamonds_and_two_kinds_of_end():
    """r9 09-4: no key, no diamonds, p0 and p1 the same black dot."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    ex.check("line_pixels", line_with(-EPS, -EPS), budget=60).plot(ax)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    plt.close(fig)
    assert labels[:3] == ["p0", "p1", "diamonds"] and "lit by both" in labels
    assert any(lab.startswith(("extra", "missing")) for lab in labels)


# -- 9.2 over_to_premultiplied, over_premultiplied -------------------------------------------
def _colour(fn, alpha):
    """fn's colour channels with another alpha."""
    return lambda s, d: np.r_[np.asarray(fn(s, d), float)[:3], alpha(s, d)]


ALPHA_WRONG = [
    (lambda s, d: s[3] + d[3], "alpha summed", "you added the two alphas"),
    (lambda s, d: s[3] ** 2 + d[3] * (1 - s[3]), "alpha squared", "α_s·α_s"),
    (lambda s, d: s[3], "alpha of the source", "you kept the source's alpha"),
    (lambda s, d: d[3], "alpha of the destination", "you kept the destination's alpha"),
    (lambda s, d: s[3] * d[3] + 0.01, "alpha only", "the share of the pixel src or dst covers"),
]


@pytest.mark.parametrize("name", ["over_to_premultiplied", "over_premultiplied"])
@pytest.mark.parametrize(
    ("alpha", "kind", "words"), ALPHA_WRONG, ids=[k for _, k, _ in ALPHA_WRONG]
)
def test_only_the_alpha_wrong_is_said_so(name, alpha, kind, words):
    """r8 (r7 09-3): colour right and alpha wrong got the generic sentence."""
    right = over_tp if name == "over_to_premultiplied" else over_pm
    first = _first(name, _colour(right, alpha))
    assert first.kind == kind, (first.kind, first.explanation)
    assert "your red, green and blue are right, your alpha is not" in first.explanation
    assert words in first.explanation, first.explanation


def test_9_2a_multiplied_by_the_result_alpha_twice_is_named():
    def twice(s, d):
        c = np.asarray(over_tp(s, d), float)
        return np.r_[c[:3] * c[3], c[3]]

    first = _first("over_to_premultiplied", twice)
    assert first.kind == "multiplied by alpha twice", first.explanation


def test_9_2a_reused_on_premultiplied_inputs_is_named():
    """r8: the most natural slip after 9.2a (both inputs multiplied by their alpha again)."""
    first = _first("over_premultiplied", over_tp)
    assert first.kind == "9.2a reused" and "9.2a's light" in first.explanation
    first = _first("over_premultiplied", over_straight)  # r11: 9.2a returns C, α
    assert first.kind == "straight rule on premultiplied", first.explanation
    assert "9.2a's over_straight" in first.explanation


def test_9_2a_gl_habit_divided_by_alpha_is_named():
    """r18 D-3: the destination weighted by (1 − α_s) alone, then divided by the right α as
    the task says, got the rule restated; only the undivided form was named."""

    def gl_divided(s, d):
        a = s[3] + d[3] * (1 - s[3])
        if a == 0:
            return (0.0, 0.0, 0.0, 0.0)
        c = (np.asarray(s[:3]) * s[3] + np.asarray(d[:3]) * (1 - s[3])) / a
        return (*c, a)

    first = _first("over_straight", gl_divided)
    assert first.kind == "destination alpha ignored", (first.kind, first.explanation)
    assert "you divided by it" in first.explanation, first.explanation
    assert "then divided by α" not in first.explanation, first.explanation


def test_the_destination_weighted_by_its_own_alpha_is_named():
    first = _first("over_premultiplied", lambda s, d: np.asarray(s) + np.asarray(d) * (1 - d[3]))
    assert first.kind == "destination's own alpha", first.explanation


def _unpremultiplied(guard):
    def fn(s, d):
        def straight(c):
            c = np.asarray(c, float)
            if guard and c[3] == 0:
                return np.r_[0.0, 0.0, 0.0, 0.0]
            with np.errstate(all="ignore"):
                return np.r_[c[:3] / c[3], c[3]]

        return over_tp(straight(s), straight(d))

    return fn


@pytest.mark.parametrize("guard", [True, False], ids=["guarded", "0/0"])
def test_a_glow_is_lost_by_dividing_by_alpha(guard):
    """9.2b's reasoning case: premultiplied light with alpha 0, which no straight colour holds
    (dividing by alpha to reuse 9.2a passed before; a 0/0 elsewhere is named too)."""
    report = ex.check("over_premultiplied", _unpremultiplied(guard), budget=60)
    glow = [f for f in report.failures if f.case.startswith("a glow")]
    assert glow and glow[0].kind == "glow lost" and "is a glow" in glow[0].explanation
    others = {f.kind for f in report.failures} - {"glow lost"}
    assert others == (set() if guard else {"divided by alpha"}), str(report)
    assert ex.check("over_premultiplied", over_pm).passed


def test_a_glow_skipped_for_its_alpha_is_told_its_answer_not_a_division():
    """r18 D-1: ``if src[3] == 0: return dst`` (the engine habit "alpha 0 draws nothing") was
    told it had divided by alpha to reuse 9.2a; it divided by nothing."""

    def skipped(s, d):
        return np.asarray(d, float) if s[3] == 0 else over_pm(s, d)

    first = _first("over_premultiplied", skipped)
    assert first.kind == "glow lost", (first.kind, first.explanation)
    assert "your answer is the destination unchanged" in first.explanation, first.explanation
    assert "skipped for its alpha alone" in first.explanation, first.explanation
    assert "dividing by alpha" not in first.explanation, first.explanation


def _premultiplied(colour):
    return lambda s, d: np.asarray(colour(np.asarray(s, float), np.asarray(d, float)), float)


#: r18 D-2: 9.2b's answers that got COMMON's straight-alpha words ("the source alpha weighs
#: the source"; doing what they said gave "premultiplied twice"): each named, in words true
#: of premultiplied colours; r20 D-5: and without the rule (the first three stated it).
PREMULTIPLIED_COMMON = [
    (lambda s, d: d, "destination unchanged", "as if the source were not there"),
    (lambda s, d: s, "source unchanged", "the destination still shows"),
    (lambda s, d: s * d[3] + d * (1 - d[3]), "destination alpha",
     "by the destination's alpha"),
    (lambda s, d: s * (1 - s[3]) + d * s[3], "weights swapped", "you swapped the two weights"),
    (lambda s, d: np.r_[s[:3] * s[3] + d[:3] * (1 - s[3]), s[3]], "kept source alpha",
     "multiplied the source colour by its alpha again"),
    (lambda s, d: np.r_[s[:3] * s[3] + d[:3] * (1 - s[3]), d[3]], "kept destination alpha",
     "multiplied the source colour by its alpha again"),
]  # fmt: skip


@pytest.mark.parametrize(
    ("fn", "kind", "words"), PREMULTIPLIED_COMMON, ids=[k for _, k, _ in PREMULTIPLIED_COMMON]
)
def test_9_2b_common_mistakes_get_premultiplied_words(fn, kind, words):
    first = _first("over_premultiplied", _premultiplied(fn))
    assert first.kind == kind and words in first.explanation, (first.kind, first.explanation)
    for straight in ("weighted by its alpha", "the source alpha weighs the source",
                     "instead of the source alpha"):  # fmt: skip
        assert straight not in first.explanation, first.explanation
    words = first.explanation.split("yours is ", 1)[1]
    for rule in ("its share α_s", "leaves uncovered", "1 − α_s", "no alpha weighs the source"):
        assert rule not in words, (rule, words)  # r20 D-5: the mistake, not the rule


def test_both_alphas_zero_is_a_case_and_a_nan_there_is_explained():
    cases = {label: args for label, args, _ in ex.blending.blend_cases("from straight")}
    assert cases["both transparent"][0][3] == 0 == cases["both transparent"][1][3]

    def divided(s, d):  # C = sum / α first: 0/0 there
        s, d = np.asarray(s, float), np.asarray(d, float)
        a = s[3] + d[3] * (1 - s[3])
        with np.errstate(all="ignore"):
            c = (s[:3] * s[3] + d[:3] * d[3] * (1 - s[3])) / a
        return np.r_[c * a, a]

    first = _first("over_to_premultiplied", divided)
    assert first.kind == "division by zero" and "both alphas 0" in first.explanation


def test_two_colours_print_with_one_format():
    """r8 item 5: 0.4375 printed "0.4375" in one colour and "0.438" in the other."""
    want, yours = colour_texts([0.1875, 0.4375, 0.1875, 0.625], [0.1875, 0.4375, 0.1875, 0.4375])
    assert (want, yours) == ("(0.1875, 0.4375, 0.1875, 0.625)", "(0.1875, 0.4375, 0.1875, 0.4375)")
    rng = np.random.default_rng(3)
    for _ in range(200):
        e = rng.uniform(0, 1, 4)
        g = e + rng.choice([0, 1e-5, 1e-3, 0.1], 4)
        texts = [t.strip("()").split(", ") for t in colour_texts(e, g)]
        shown = dict()
        for value, text in zip(np.r_[e, g], texts[0] + texts[1]):
            assert shown.setdefault(text, value) == pytest.approx(value, abs=1e-9), (e, g, texts)
    first = _first("over_premultiplied", lambda s, d: np.r_[over_pm(s, d)[:3], 0.4375])
    m = re.search(r"the blend is \((.*?)\); yours is \((.*?)\)", first.explanation)
    for a, b in zip(m.group(1).split(", "), m.group(2).split(", ")):
        assert (a == b) == (float(a) == float(b)), first.explanation


@pytest.mark.parametrize("name", ["line_pixels", "over_to_premultiplied", "over_premultiplied",
                                  "front_to_back"])  # fmt: skip
def test_a_stub_figure_never_shows_the_answer(name):
    """r8 item 6: the stub's figure drew the first case's expected answer."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def stub(*args):
        raise NotImplementedError

    fig, ax = plt.subplots(figsize=(7, 4))
    ex.check(name, stub).plot(ax)
    ticks = " ".join(t.get_text() for t in ax.get_xticklabels())
    images = [im.get_array() for im in ax.get_images()]
    plt.close(fig)
    assert "expected" not in ticks and "yours" not in ticks
    if name == "line_pixels":  # only the segment: no lit pixel drawn
        assert not images or all(np.all(np.asarray(a) == 0) for a in images)
    elif name != "front_to_back":
        assert ticks.startswith("src") and "dst" in ticks


def test_a_blend_figure_shows_src_and_dst_beside_the_answers():
    """r8 item 4: the bars showed expected and yours, never the case's src and dst."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    ex.check("over_premultiplied", over_tp).plot(ax)
    ticks = [t.get_text().split("\n")[0] for t in ax.get_xticklabels()]
    plt.close(fig)
    assert ticks == ["src", "dst", "expected", "yours"], ticks


# -- 9.3 front_to_back -------------------------------------------------------------------------
def test_a_nearest_first_walk_that_stops_passes_and_the_layers_come_once():
    assert ex.check("front_to_back", front_to_back).passed
    assert ex.check("front_to_back", _under_with(lambda a, c: a + (1 - a[3]) * c)).passed
    stream, read = layer_stream(np.eye(4))
    assert len(list(stream)) == 4 and list(stream) == [] and read() == 4
    with pytest.raises(TypeError, match="read them with a for loop"):
        np.asarray(layer_stream(np.eye(4))[0], dtype=float)


def _hidden_array(layers):
    """r14 09-2: the stream's own array, read back to front without iterating."""
    acc = np.zeros(4)
    for c in np.asarray(layers._layers)[::-1]:
        acc = np.asarray(c, float) + (1 - c[3]) * acc
    return acc


def _count_reset(layers):
    """r14 09-2: every layer read, back to front, then the stream's counter set back to 0."""
    stack = list(layers)
    layers.read = 0
    acc = np.zeros(4)
    for c in stack[::-1]:
        acc = np.asarray(c, float) + (1 - c[3]) * acc
    return acc


@pytest.mark.parametrize("fn", [_hidden_array, _count_reset], ids=["_layers", "read = 0"])
def test_the_layer_stream_hides_its_layers_and_its_count(fn):
    """r14 09-2: ``layers._layers`` (the stream's array) and ``layers.read = 0`` (its public,
    writable count) let a back-to-front loop pass all 28 cases. The layers and the count now
    live in the check's own closure, a generator: neither is an attribute of the stream."""
    report = ex.check("front_to_back", fn)
    assert not report.passed, str(report)
    stream, _ = layer_stream(np.eye(4))
    assert not any(k in ("read", "_layers") for k in dir(stream)), dir(stream)
    with pytest.raises(AttributeError):
        stream.read = 0


def _no_stop(layers):
    acc = np.zeros(4)
    for c in layers:
        acc = acc + (1 - acc[3]) * np.asarray(c, float)
    return acc


@pytest.mark.parametrize("fn", [front_to_back_by_reversing, layers_vectorised, _no_stop],
                         ids=["reversed list", "vectorised", "never stops"])  # fmt: skip
def test_reading_behind_an_opaque_layer_fails_and_names_the_back_to_front_loop(fn):
    """r8: a loop over layers[::-1] passed the task that asks for a nearest-first walk."""
    first = _first("front_to_back", fn)
    assert first.kind == "read behind the opaque layer", first.explanation
    assert "nothing behind it can show" in first.explanation
    assert "A loop that runs from the farthest layer (the layers reversed)" in first.explanation


def test_stopping_before_the_alpha_is_one_is_named():
    def early(layers):
        acc = np.zeros(4)
        for c in layers:
            acc = acc + (1 - acc[3]) * np.asarray(c, float)
            if acc[3] >= 0.99:
                break
        return acc

    first = _first("front_to_back", early)
    assert first.kind == "stopped early" and "below 1" in first.explanation, first.explanation


def test_alpha_updated_before_the_colour_is_named():
    def step(acc, c):
        alpha = acc[3] + (1 - acc[3]) * c[3]
        return np.r_[acc[:3] + (1 - alpha) * c[:3], alpha]

    first = _first("front_to_back", _under_with(step))
    assert first.kind == "alpha first", first.explanation
    assert "farthest first" not in first.explanation


# -- r9: package routes, and the half-named mistakes of 9.2a and 9.3 ---------------------------
def _premultiply(c):
    c = np.asarray(c, float)
    return np.r_[c[:3] * c[3], c[3]]


def _prefix_back_to_front(layers):
    from teachraster.exercises.front_to_back import back_to_front

    read = []
    for layer in layers:
        read.append(layer)
        if np.prod([1 - x[3] for x in read]) <= 0:
            break
    return back_to_front(np.reshape(read, (-1, 4)))


def _apply_blend(s, d):
    from teachraster.core.blend_factors import BLEND_MODES, apply_blend

    return apply_blend(np.asarray(s, float), np.asarray(d, float), *BLEND_MODES["premultiplied"])


def _factor(s, d):
    from teachraster.core.blend_factors import factor

    s, d = np.asarray(s, float), np.asarray(d, float)
    return s + d * factor("ONE_MINUS_SRC_ALPHA", s, d)


@pytest.mark.parametrize(
    ("name", "fn", "called"),
    [
        ("over_premultiplied", _apply_blend, "apply_blend"),
        ("over_premultiplied", _factor, "factor"),
        (
            "over_to_premultiplied",
            lambda s, d: _apply_blend(_premultiply(s), _premultiply(d)),
            "apply_blend",
        ),
        ("front_to_back", _prefix_back_to_front, "back_to_front"),
    ],  # fmt: skip
    ids=["apply_blend", "factor", "9.2a apply_blend", "back_to_front prefix"],
)
def test_every_package_route_is_flagged_and_not_counted(name, fn, called):
    """r9 09-6, 09-8: the private apply_blend and back_to_front passed unflagged."""
    report = ex.check(name, fn, budget=60)
    assert report.package and f"teachraster's {called}" in report.package, report.package
    assert not report.passed
    with pytest.raises(AssertionError):
        report.assert_passed()


@pytest.mark.parametrize(
    ("fn", "kind", "words"),
    [
        (
            lambda s, d: np.r_[
                s[:3] * (1 - s[3]) + np.asarray(d[:3]) * d[3] * s[3], s[3] + d[3] * (1 - s[3])
            ],
            "weights swapped",
            "swapped the weights",
        ),
        (
            lambda s, d: np.r_[s[:3] * s[3] + np.asarray(d[:3]) * d[3], s[3] + d[3] * (1 - s[3])],
            "destination not scaled",
            "did not scale the destination by (1 − α_s)",
        ),
    ],  # fmt: skip
    ids=["swapped weights", "destination not scaled"],
)
def test_9_2a_swapped_weights_and_unscaled_destination_are_named(fn, kind, words):
    """r9 O4 (issue 30: "over with swapped weights") and O9 got the rule restated."""
    first = _first("over_to_premultiplied", lambda s, d: fn(np.asarray(s), np.asarray(d)))
    assert first.kind == kind and words in first.explanation, first.explanation


def _walk(step, before_opaque=False, straight=False):
    def fn(layers):
        acc = np.zeros(4)
        for c in layers:
            if before_opaque and c[3] >= 1:
                break
            acc = step(acc, np.asarray(c, float))
            if acc[3] >= 1:
                break
        if straight and acc[3] > 0:
            acc = np.r_[acc[:3] / acc[3], acc[3]]
        return acc

    return fn


def _under(a, c):
    return a + (1 - a[3]) * c


@pytest.mark.parametrize(
    ("fn", "kind", "words"),
    [
        (_walk(_under, straight=True), "returned straight", "you returned a straight colour"),
        (_walk(_under, before_opaque=True), "before the opaque layer", "opaque layer itself"),
        (
            _walk(lambda a, c: np.r_[a[:3] + (1 - c[3]) * c[:3], _under(a, c)[3]]),
            "colour by own alpha",
            "1 − its own alpha",
        ),
        (
            _walk(lambda a, c: np.r_[a[:3] + a[3] * c[:3], _under(a, c)[3]]),
            "colour by A",
            "by A, the alpha accumulated",
        ),
        (
            _walk(lambda a, c: np.r_[_under(a, c)[:3], max(a[3], c[3])]),
            "alpha max",
            "the larger alpha",
        ),
    ],  # fmt: skip
    ids=["straight", "before opaque", "own alpha", "by A", "max"],
)
def test_9_3_mistakes_that_got_the_rule_restated_are_named(fn, kind, words):
    """r9 09-9: F8, F7, F6, F11 and F12."""
    first = _first("front_to_back", fn)
    assert first.kind == kind and words in first.explanation, first.explanation


def test_a_passing_figure_shows_a_translucent_case_and_the_task_claims_nothing_false():
    """r9 09-7 and 09-5: the passing figure drew opaque red over blue, where no checkerboard
    shows; 9.2a said "lesson 12 does not print them" though §9 states the premultiplied rule."""
    import json
    from pathlib import Path

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    ex.check("atop_premultiplied", atop_pm).plot(ax)
    ticks = " ".join(t.get_text() for t in ax.get_xticklabels())
    plt.close(fig)
    assert "(0.3, 0.2, 0.05, 0)" in ticks.replace(",\n", ", "), ticks  # the glow
    nb = Path(__file__).parent.parent / "notebooks/exercises/09_lines_and_blending.ipynb"
    text = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
            for c in json.loads(nb.read_text())["cells"]}  # fmt: skip
    assert "does not print" not in text["over_straight_task"]
    # r14: the ids were swapped (9.2a under over_premultiplied_task): each names its task now
    assert "**9.2a.**" in text["over_straight_task"] and "over_premultiplied_step" not in text
    assert "**9.2b.**" in text["atop_premultiplied_task"]


@pytest.mark.parametrize(
    ("knobs", "kind"),
    [({"half": 1.0}, "diamond radius"), ({"centre": 0.0}, "diamond at the corner")],
    ids=["radius 1", "centred on the corner"],
)
def test_a_wrong_diamond_is_named(knobs, kind):
    """r9 L13, L14: the rule restated."""
    from teachraster.exercises.lines import diamond_pixels

    first = _first("line_pixels", lambda p0, p1: sorted(diamond_pixels(p0, p1, **knobs)))
    assert first.kind == kind, first.explanation


def test_only_p0s_pixel_is_named():
    """r9 L18."""
    first = _first("line_pixels", lambda p0, p1: [(int(p0[1]), int(p0[0]))])
    assert first.kind == "p0's pixel only", first.explanation


# -- r11 09-B2: the package's answer called from a worker thread is not counted ---------------
def _in_a_pool(call):
    """A function that hands the answer's work to a thread pool made before the check (the
    profile hook of r9 watched the case's own thread only)."""
    from concurrent.futures import ThreadPoolExecutor

    pool = ThreadPoolExecutor(1)
    pool.submit(int).result(timeout=5)  # its thread exists before the check starts

    def fn(*args):
        return pool.submit(call, *args).result(timeout=5)

    return pool, fn


@pytest.mark.parametrize(
    ("name", "call", "called"),
    [
        ("line_pixels", lambda p0, p1: tr_line(p0, p1), "rasterize_line"),
        ("over_premultiplied", lambda s, d: tr_blend(s, d), "blend_equation"),
    ],
    ids=["rasterize_line", "blend_equation"],
)
def test_a_package_answer_called_from_a_worker_thread_is_not_counted(name, call, called):
    pool, fn = _in_a_pool(call)
    try:
        report = ex.check(name, fn, budget=60)
    finally:
        pool.shutdown(wait=False, cancel_futures=True)
    assert report.package and f"teachraster's {called}" in report.package, str(report)
    assert not report.passed


def tr_line(p0, p1):
    import teachraster as tr

    raster = tr.rasterize_line(p0, p1, 12, 12)
    return {(int(r), int(c)) for r, c in zip(*np.nonzero(raster.coverage))}


def tr_blend(s, d):
    import teachraster as tr

    return tr.blend_equation(s, d, "ONE", "ONE_MINUS_SRC_ALPHA")


def test_the_watch_leaves_every_listed_function_as_it_was():
    """The check swaps the listed answers' code while the cases run, and puts it back."""
    import teachraster as tr

    code, defaults = tr.rasterize_line.__code__, tr.rasterize_line.__kwdefaults__
    seen = []
    ex.check("line_pixels", lambda p0, p1: seen.append(tr.rasterize_line.__code__) or set())
    assert seen and seen[0] is not code  # swapped while the cases ran
    assert tr.rasterize_line.__code__ is code and tr.rasterize_line.__kwdefaults__ is defaults


# -- r11 09-B, 09-C: cases drawn at check time; plain numbers in the messages -----------------
def _harvested(name, answer):
    """A table of the answers to every case one check shows (recorded by a dummy function,
    computed outside the function), handed in as a lookup (r11 g9.py: 44/44)."""
    seen = []
    ex.check(name, lambda *args: seen.append(args) or answer(*args), budget=60)
    table = {repr(args): answer(*args) for args in seen}
    return lambda *args: table.get(repr(args))


@pytest.mark.parametrize(
    ("name", "answer"),
    [
        ("line_pixels", line_pixels),
        ("over_premultiplied", over_pm),
        ("over_to_premultiplied", over_tp),
    ],
    ids=["9.1", "9.2b", "9.2a"],
)
def test_a_table_of_one_checks_answers_fails_the_next_check(name, answer):
    report = ex.check(name, _harvested(name, answer), budget=60)
    assert not report.passed
    failed = {f.case for f in report.failures}
    assert failed and all("drawn for this check" in c for c in failed), failed


def test_front_to_back_draws_stacks_at_check_time():
    from teachraster.exercises.front_to_back import layer_cases

    a, b = layer_cases(), layer_cases()
    drawn = [k for k, c in enumerate(a) if "drawn for this check" in c[0]]
    assert drawn and any(not np.array_equal(a[k][1][0], b[k][1][0]) for k in drawn)


def test_a_line_case_prints_plain_numbers():
    """r11 09-C: "(np.float64(8.125), np.float64(10.125))" in 24 of the 44 case texts."""
    report = ex.check("line_pixels", lambda p0, p1: set(), budget=60)
    text = " ".join(f.explanation for f in report.failures)
    assert "random line" in " ".join(f.case for f in report.failures)
    assert "np.float64" not in text, text[:400]


def test_a_right_under_loop_through_the_packages_blend_is_told_why_it_is_not_counted():
    """r11 09-E: the under factors through tr.blend_equation were told the function "computes
    this very answer"."""
    import teachraster as tr

    def under(layers):
        acc = np.zeros(4)
        for layer in layers:
            acc = tr.blend_equation(np.asarray(layer, float), acc, "ONE_MINUS_DST_ALPHA", "ONE")
            if acc[3] >= 1:
                break
        return acc

    report = ex.check("front_to_back", under, budget=60)
    assert not report.failures and not report.passed, str(report)
    assert "computes this very answer" not in report.package
    assert "write the step yourself" in report.package and "under" in report.package


# -- r11 09-A: 9.2a asks for the straight result, which lesson 12's rule does not give ------------
def test_lesson_12s_rule_on_premultiplied_inputs_does_not_pass_9_2a():
    """9.2a returned premultiplied: premultiplying and applying lesson 12 §9's rule passed,
    and the notebook said the check could not tell. The straight result needs the division
    and its missing answer at α = 0."""

    def copied(s, d):
        s, d = np.asarray(s, float), np.asarray(d, float)
        ps, pd = np.r_[s[:3] * s[3], s[3]], np.r_[d[:3] * d[3], d[3]]
        return ps + pd * (1 - s[3])

    first = _first("over_straight", copied)
    assert first.kind == "returned premultiplied" and "divide it by α" in first.explanation
    assert ex.check("over_straight", over_straight, budget=60).passed

    def divided(s, d):  # the copy divided by α, with no answer where α = 0
        c = copied(s, d)
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.r_[c[:3] / c[3], c[3]]

    first = _first("over_straight", divided)
    assert first.kind == "division by zero" and "(0, 0, 0, 0)" in first.explanation


def test_gl_straight_colour_times_alpha_is_named_in_9_2a_premultiplied():
    """r11 09-F: "C = C_s·α_s + C_d(1 − α_s), then α·C" got the rule restated."""

    def gl_times_alpha(s, d):
        s, d = np.asarray(s, float), np.asarray(d, float)
        a = s[3] + d[3] * (1 - s[3])
        return np.r_[(s[:3] * s[3] + d[:3] * (1 - s[3])) * a, a]

    first = _first("over_to_premultiplied", gl_times_alpha)
    assert first.kind == "GL's straight colour times α", first.explanation


@pytest.mark.parametrize(
    ("fn", "kind"),
    [
        ("tight_bbox", "search range from the unmoved ends"),
        ("hand_bresenham", "Bresenham"),
        ("centres_at_integers", "diamond at the corner"),
        ("end_closed_unmoved", "end tested before moving, closed"),
    ],
)
def test_the_four_restated_line_mistakes_are_named(fn, kind):
    """r11 09-F: these four got the rule restated (the review's s91b/s91c)."""
    from teachraster.exercises.lines import diamond_pixels, hand_bresenham

    fns = {
        "tight_bbox": lambda p0, p1: {
            (r, c) for r, c in line_pixels(p0, p1)
            if min(int(p0[1] // 1), int(p1[1] // 1)) <= r <= max(int(p0[1] // 1), int(p1[1] // 1))
            and min(int(p0[0] // 1), int(p1[0] // 1)) <= c <= max(int(p0[0] // 1), int(p1[0] // 1))
        },
        "hand_bresenham": hand_bresenham,
        "centres_at_integers": lambda p0, p1: {
            (r, c) for r, c in line_pixels((p0[0] + 0.5, p0[1] + 0.5), (p1[0] + 0.5, p1[1] + 0.5))
            if r < 12 and c < 12
        },
        "end_closed_unmoved": lambda p0, p1: diamond_pixels(p0, p1, end="unmoved closed"),
    }  # fmt: skip
    report = ex.check("line_pixels", fns[fn], budget=60)
    assert not report.passed and report.failures
    assert {f.kind for f in report.failures} == {kind}, str(report)[:600]


# -- r11 09-D: the passing figures' labels do not run into each other -------------------------
@pytest.mark.parametrize(
    ("name", "fn"),
    [("over_straight", over_straight), ("over_premultiplied", over_pm),
     ("over_to_premultiplied", over_tp), ("front_to_back", front_to_back)],
)  # fmt: skip
def test_the_swatch_labels_do_not_overlap(name, fn):
    """c7: "expected (0.1875, 0.4375" ran into "(0.1875, 0.4375,"; c13: "layer 6expected"."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.plotting import use_style

    with use_style("classroom"):
        fig, ax = plt.subplots(figsize=(7, 4))
        try:
            ex.check(name, fn, budget=60).plot(ax)
            fig.canvas.draw()
            boxes = [t.get_window_extent() for t in ax.get_xticklabels() if t.get_text()]
            assert len(boxes) >= 4
            for a, b in zip(boxes, boxes[1:]):  # side by side, or one below the other
                assert a.x1 < b.x0 or a.y1 < b.y0 or b.y1 < a.y0, (name, a, b)
        finally:
            plt.close(fig)


# -- r12 09-1: a private helper of the answer's module, or a copy of its code -----------------
def _thin_line(p0, p1):
    """9.1 through ``teachraster.core.lines._thin`` (``tr.rasterize_line??`` shows it)."""
    from teachraster.core import lines

    ends = lines.snap(np.array([p0, p1], float), 8)
    coverage, _ = lines._thin(ends, "diamond", 12, 12, 8, False)
    return {(int(r), int(c)) for r, c in zip(*np.nonzero(coverage))}


def _diamond_line(p0, p1):
    """9.1 through ``teachraster.core.line_rules.diamond``, a public function of the rule
    module ``_thin??`` shows (r13 09-1: 50/50, no "not counted")."""
    from teachraster.core import line_rules, lines

    units = lines.to_units(lines.snap(np.array([p0, p1], float), 8), 8)
    a, b = (tuple(int(v) for v in u) for u in units)
    steps = line_rules.diamond(a, b, lines.units_per_pixel(8), 12, 12, False)
    return {(int(r), int(c)) for r, c in zip(steps.rows[steps.lit], steps.cols[steps.lit])}


def test_a_function_of_the_line_rule_module_is_not_counted():
    """r13 09-1: the rule module's public functions are the answer's computation too."""
    report = ex.check("line_pixels", _diamond_line, budget=60)
    assert not report.passed and "teachraster's diamond" in (report.package or ""), str(report)
    assert "rasterize_line's own computation" in report.package, report.package
    assert report.failures == [], report.failures  # right, but not the student's work


def _clone(f):
    """A copy of ``f`` made of its code before the check (the watch swaps ``f.__code__``)."""
    import types

    g = types.FunctionType(f.__code__, f.__globals__, f.__name__, f.__defaults__, f.__closure__)
    g.__kwdefaults__ = f.__kwdefaults__
    return g


def test_a_private_helper_or_a_copy_of_the_package_code_is_not_counted():
    """r12 09-1: ``_thin`` and a clone of ``rasterize_line`` made before the check passed 9.1
    50/50 with no "not counted". Both are named now; the same function pasted as source in
    a cell of its own too; an honest solution is not touched."""
    import inspect

    import teachraster as tr

    report = ex.check("line_pixels", _thin_line, budget=60)
    assert not report.passed and "teachraster's _thin" in (report.package or ""), str(report)
    clone = _clone(tr.rasterize_line)

    def via_clone(p0, p1):
        raster = clone(p0, p1, 12, 12)
        return {(int(r), int(c)) for r, c in zip(*np.nonzero(raster.coverage))}

    report = ex.check("line_pixels", via_clone, budget=60)
    assert not report.passed and "a copy of the code of teachraster's rasterize_line" in (
        report.package or ""
    ), str(report)
    space = dict(vars(__import__("teachraster.core.lines", fromlist=["x"])))
    source = inspect.getsource(tr.rasterize_line)
    space.pop("rasterize_line")
    space["__name__"] = "__main__"  # a notebook cell's
    exec(compile(source, "<a student's cell>", "exec"), space)  # pasted, not imported
    pasted = space["rasterize_line"]
    assert pasted is not tr.rasterize_line and pasted.__module__ == "__main__"

    def via_paste(p0, p1):
        raster = pasted(p0, p1, 12, 12)
        return {(int(r), int(c)) for r, c in zip(*np.nonzero(raster.coverage))}

    report = ex.check("line_pixels", via_paste, budget=60)
    assert not report.passed and "a copy of the code" in (report.package or ""), str(report)
    assert ex.check("line_pixels", line_pixels, budget=60).passed


def _tight_box(p0, p1):
    """9.1 searched over the box of the pixels the unmoved end points lie in."""
    ys, xs = sorted((int(p0[1] // 1), int(p1[1] // 1))), sorted((int(p0[0] // 1), int(p1[0] // 1)))
    return {(r, c) for r, c in line_pixels(p0, p1)
            if ys[0] <= r <= ys[1] and xs[0] <= c <= xs[1]}  # fmt: skip


def test_the_unmoved_search_range_is_told_what_it_misses_for_its_own_line():
    """r12 09-2: the words said "a diamond reaches past its pixel's square" (it lies inside
    it) and gave a vertical line's example (column k − 1) for a horizontal line. Now: the end
    point on x = k (y = k) moves into column (row) k − 1, as the case's line has it."""
    report = ex.check("line_pixels", _tight_box, budget=60)
    by_case = {f.case: f.explanation for f in report.failures}
    assert by_case and all("reaches past" not in t for t in by_case.values())
    horizontal = next(t for c, t in by_case.items() if c.startswith("horizontal"))
    assert "on y = 3, move by −ε² into row 2" in horizontal and "column" not in horizontal
    vertical = next(t for c, t in by_case.items() if c.startswith("vertical"))
    assert "on x = 3, move by −ε into column 2" in vertical and "into row" not in vertical
    assert "(row, col) (0, 2), (1, 2)" in vertical

    # the advice is enough: the box of the moved end points' pixels, with no margin, passes
    def moved_box(p0, p1):
        a, b = ((Fraction(p[0]) - EPS, Fraction(p[1]) - EPS * EPS) for p in (p0, p1))
        ys, xs = sorted((a[1] // 1, b[1] // 1)), sorted((a[0] // 1, b[0] // 1))
        return {(r, c) for r, c in line_pixels(p0, p1)
                if ys[0] <= r <= ys[1] and xs[0] <= c <= xs[1]}  # fmt: skip

    assert ex.check("line_pixels", moved_box, budget=60).passed


def test_a_stop_just_below_1_prints_the_alpha_against_1():
    """r12 09-5: a loop stopping after 3 layers was told "where the alpha was 1: below 1" for
    0.99963 (num() alone rounds it to 1)."""

    def three(layers):
        acc = np.zeros(4)
        for k, layer in enumerate(layers):
            if k == 3:
                break
            acc = acc + (1 - acc[3]) * np.asarray(layer, float)
        return acc

    texts = [f.explanation for f in ex.check("front_to_back", three).failures]
    # r289 C1: "you stopped after layer m" where the check counted the layers read, "your
    # composite is that of the m nearest" where it infers the stop from the value
    stopped = [t for t in texts if "where the alpha was" in t]
    assert stopped, texts
    for text in stopped:
        alpha = re.search(r"where the alpha was ([0-9.]+), (just )?below 1", text)
        assert alpha and float(alpha.group(1)) < 1, text
        assert (alpha.group(2) is not None) == (float(alpha.group(1)) > 0.99), text


def test_the_read_count_allowance_is_said_where_the_task_counts_reads():
    """r12 09-6: a loop testing at the top reads one layer behind the opaque one and passes
    (call_front_to_back allows it); the task said only "stops reading once ... 1"."""
    import json
    from pathlib import Path

    nb = Path(__file__).parent.parent / "notebooks/exercises/09_lines_and_blending.ipynb"
    text = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
            for c in json.loads(nb.read_text())["cells"]}  # fmt: skip
    assert "fetching one more layer" in " ".join(text["front_to_back_task"].split())

    def top_test(layers):
        acc = np.zeros(4)
        for layer in layers:
            if acc[3] >= 1:
                break
            acc = acc + (1 - acc[3]) * np.asarray(layer, float)
        return acc

    assert ex.check("front_to_back", top_test).passed


def test_a_wrong_form_is_described_once_in_plain_numbers():
    """r12 09-8: "a bool array of shape (12, 12) of shape (12, 12)" and "(np.float64(1.0),
    np.float64(0.0), np.float64(0.0)) of shape (3,)"."""
    image = _first("line_pixels", lambda p0, p1: np.zeros((12, 12), bool)).explanation
    assert image.count("of shape (12, 12)") == 1, image
    three = _first("over_straight", lambda s, d: tuple(np.float64(v) for v in (1, 0, 0)))
    assert "(1.0, 0.0, 0.0) of shape (3,)" in three.explanation and "np." not in three.explanation


def test_the_9_1_walkthrough_is_folded_so_that_students_try_first():
    """r12 09-4: the paragraph gave the whole algorithm before the student had tried."""
    import json
    from pathlib import Path

    nb = Path(__file__).parent.parent / "notebooks/exercises/09_lines_and_blending.ipynb"
    text = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
            for c in json.loads(nb.read_text())["cells"]}  # fmt: skip
    task = text["line_pixels_task"]
    folded = task[task.index("<details>") : task.index("</details>")]
    # r84 09-1: the box is a hint (the first step); r289 M3: the sketch of one way stands in
    # a second box (a student who reads before coding sees it only by opening it)
    second = task[task.index("<summary>A second hint") :]
    second = second[: second.index("</details>")]
    assert "u = x + y" in folded and "<summary>A hint" in folded
    assert "open interval" in second and "closed [0, 1]" in second
    assert "open interval" not in folded and "Fraction" not in second
    outside = task.replace(folded, "").replace(second, "")
    assert "u = x + y" not in outside and "open interval" not in outside


def test_the_read_past_figure_crosses_out_the_layers_read_behind_the_opaque_one():
    """r12 09-7: the figure drew expected = yours and nothing else: nothing wrong to see."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def never_stops(layers):
        acc = np.zeros(4)
        for layer in layers:
            acc = acc + (1 - acc[3]) * np.asarray(layer, float)
        return acc

    report = ex.check("front_to_back", never_stops)
    failure = next(f for f in report.failures if f.kind == "read behind the opaque layer")
    fig, ax = plt.subplots(figsize=(7, 4))
    failure.draw(ax)
    labels = [t.get_text() for t in ax.get_xticklabels()]
    crosses = [line for line in ax.get_lines() if len(line.get_xdata()) == 4]
    plt.close(fig)
    got = failure.got
    # r18 D-8: the one layer fetched past the opaque one is allowed: labelled so, not crossed
    assert sum(t.endswith("\nread") for t in labels) == got.read - got.opaque - 1 == len(crosses)
    assert len(crosses) > 0 and labels[got.opaque].endswith("\nallowed"), labels
    assert labels[-1] == "yours", labels  # on the line of the others


def test_a_loop_that_stops_late_is_not_told_it_ran_from_the_farthest_layer():
    """r18 D-8: a loop reading two layers past the opaque one (5 of 6) was told that a loop
    from the farthest layer, or one that never stops, must read them all."""

    def two_past(layers):
        acc, late = np.zeros(4), 0
        for layer in layers:
            acc = acc + (1 - acc[3]) * np.asarray(layer, float)
            late += acc[3] >= 1
            if late == 3:  # two layers past the opaque one
                break
        return acc

    report = ex.check("front_to_back", two_past)
    late = [f for f in report.failures if f.kind == "read behind the opaque layer"]
    # where it read them all (3 of 3), the words say which loops read them all, and that one
    # layer past the opaque one is allowed; where it stopped, that it stopped
    stopped = [f for f in late if "Your loop stopped" in f.explanation]
    assert stopped and all("farthest layer" not in f.explanation for f in stopped), str(report)
    assert all("allowed" in f.explanation or "no more" in f.explanation for f in late)


def test_pixels_outside_the_image_fail_and_are_named():
    """r14 09-8: nothing asked for pixels inside the 12 × 12 image only, and no case tested
    it: the teacher's solution without its clip at 0 passed all 50 cases, though moved by −ε
    the line (0, 2.5) → (5, 2.5) starts in the diamond of column −1. The task says so now,
    and a named case starts at x = 0 on a row's centre line."""
    from teachraster.exercises import lines

    labels = {label: args for label, args, _ in lines.line_cases()}
    assert labels["start on the image's left edge (x = 0), on a row's centre line"] == (
        (0.0, 2.5), (5.0, 2.5))  # fmt: skip
    unclipped = line_with(-EPS, -EPS * EPS, clip=False)
    report = ex.check("line_pixels", unclipped, budget=60)
    assert not report.passed and report.failures, str(report)
    first = report.failures[0]
    assert first.kind == "outside the image", (first.kind, first.explanation)
    assert "(row 2, col -1)" in first.explanation and "inside the image" in first.explanation
    task = " ".join(_nb_cells()["line_pixels_task"].split())
    assert "inside the 12 × 12 image" in task and "row, col < 12" in task, task


def _nb_cells() -> dict:
    """Exercise 09's cells by grade_id."""
    import json
    from pathlib import Path

    nb = Path(__file__).parent.parent / "notebooks/exercises/09_lines_and_blending.ipynb"
    return {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"])
            for c in json.loads(nb.read_text())["cells"]}  # fmt: skip


@pytest.mark.parametrize("empty", [[], (), set(), np.zeros((0, 2), int)], ids=repr)
def test_no_pixels_for_every_line_is_said_so(empty):
    """r14 09-5: ``return []`` was told "your function returns set() for every line"."""
    first = _first("line_pixels", lambda p0, p1: empty)
    assert "returns no pixels for every line" in first.explanation, first.explanation
    assert "set()" not in first.explanation


@pytest.mark.parametrize(
    "fn, named",
    [(lambda s, d: d, "destination unchanged"), (lambda s, d: s, "source unchanged")],
    ids=["dst", "src"],
)
def test_over_straight_returning_an_input_unchanged_is_named(fn, named):
    """r14 09-7: ``over_straight`` returning ``dst`` got the rule restated (kind "value"),
    where ``over_premultiplied`` names it: the straight table lacked those two rows."""
    first = _first("over_straight", fn)
    assert first.kind == named, (first.kind, first.explanation)
    assert f"that is the {named}" in first.explanation, first.explanation


@pytest.mark.parametrize(
    "fn, named",
    [(sv.line_bresenham_textbook, "Bresenham"), (sv.line_dda_sampled, "DDA")],
    ids=["Bresenham e2 > -dy", "DDA of n points"],
)
def test_the_textbook_bresenham_and_dda_are_named(fn, named):
    """r14 09-6: the classic Bresenham loop (``e2 > −dy``, ``e2 < dx``, both end pixels) and a
    DDA sampling n = max(|dx|, |dy|) points from p0, both taught by lesson 12 §2-3, got the
    generic rule at p1's pixel; the checker named only Zingl's form and its column DDA."""
    report = ex.check("line_pixels", fn, budget=60)
    kinds = {f.kind for f in report.failures}
    assert kinds == {named}, (kinds, report.failures[0].explanation)


def test_each_task_cells_grade_id_names_the_function_it_asks_for():
    """r14: cell 5 (9.2a, ``over_straight``) carried ``over_premultiplied_task`` and cell 8
    (9.2b) ``over_premultiplied_step``: a lecturer reading the gradebook saw them swapped."""
    for grade_id, source in _nb_cells().items():
        asked = re.findall(r"write `(\w+)\(", source, flags=re.I)
        if grade_id.endswith("_task") and asked:
            assert grade_id == f"{asked[0]}_task", (grade_id, asked)


def test_9_2b_shares_9_2s_one_point_with_9_2a():
    """r14/r16 reading note: 9.2a and 9.2b share 9.2's one point, and the text says so (r20
    D-1: no longer that the lesson prints 9.2b's result: 9.2b is atop, which it does not)."""
    import json
    from pathlib import Path

    nb = Path(__file__).parent.parent / "notebooks/exercises/09_lines_and_blending.ipynb"
    grading = [c["metadata"]["nbgrader"] for c in json.loads(nb.read_text())["cells"]]
    points = {g["grade_id"]: g["points"] for g in grading if g["grade"]}
    assert points["over_straight_check"] + points["atop_premultiplied_check"] == 1, points
    assert points["line_pixels_check"] == points["front_to_back_check"] == 1, points
    first = " ".join(_nb_cells()["over_straight_task"].split())
    assert "half for 9.2a and half for 9.2b" in first and "prints its result" not in first, first


def test_9_2b_asks_its_questions_without_answering_them():
    """r19 E-3, E-4: the alpha question was answered by the next sentence ("That is the rule
    lesson 12 §9 states"), and the glow's "covers nothing and adds its light" and "what no
    straight one can" answered the question asked about it. r20 D-1: both of 9.2b's questions
    were answered by lesson 12 (§6's table, §9's rule); 9.2b is now atop, which the task
    defines in words and asks to derive in 9.2a's steps, and no weight or factor is given."""
    task = " ".join(_nb_cells()["atop_premultiplied_task"].split())
    assert "atop_premultiplied(src, dst)" in task and "uncorrelated" in task, task
    assert "what your rule gives there" in task and "(0.3, 0.2, 0.05, 0)" in task, task
    for answer in ("lesson 12 §9 states", "lesson 12b §4 states", "adds its light", "no straight one can", "covers "
                   "nothing", "glow", "shares 9.2's point", "cannot give it", "DST_ALPHA",
                   "α_s·α_d", "α_d·(1 − α_s)", "c_s·α_d", "the destination's alpha",
                   "ONE_MINUS"):  # fmt: skip
        assert answer not in task, answer


def _lesson_12_text() -> str:
    import json
    from pathlib import Path

    folder = Path(__file__).parent.parent / "notebooks"  # lesson 12, split into 12a and 12b
    return "\n".join(
        "".join(c["source"])
        for name in ("12a_lines", "12b_blending")
        for c in json.loads((folder / f"{name}.ipynb").read_text())["cells"]
    )


def test_lesson_12_prints_no_atop():
    """r20 D-1: 9.2b's answer is nowhere in lesson 12 (nor are its factors), which prints
    over on premultiplied colours (§6's table, §9's rule), 9.2b's task before r20."""
    text = _lesson_12_text()
    assert "ONE_MINUS_SRC_ALPHA" in text  # over's pair is printed; atop's is not
    assert not re.search(r"\batop\b", text)  # (its summary names atop_premultiplied)
    for answer in ("DST_ALPHA", "dst[3]", "a_dst", "α_d"):
        assert answer not in text, answer


def test_9_2a_gives_the_premises_and_asks_for_the_derivation():
    """r18 D-7: 9.2a's text stated each weight ("the destination shows only in the share
    1 − α_s the source leaves uncovered, where it covers α_d of it") and answered its own
    "find them" ("there nothing covers the pixel"). It now gives Porter and Duff's two
    assumptions (alpha is coverage, the coverages are uncorrelated: D-10) and asks for the
    shares step by step; 9.3 says what real ray marchers stop at (D-10)."""
    task = " ".join(_nb_cells()["over_straight_task"].split())
    assert "uncorrelated" in task and "1. In what share of the pixel" in task, task
    for answer in (
        "where it covers α_d of it",
        "α_d of the",
        "each colour in the share of the",
        "there nothing covers the pixel",
        "α_d·(1 − α_s)",
        "(1 − α_s)·α_d",
    ):
        assert answer not in task, answer
    assert "find them, and what they mean for the pixel" in task, task
    step = " ".join(_nb_cells()["atop_premultiplied_task"].split())
    assert "Derive it as you derived 9.2a" in step and "write each colour as c = α·C" in step
    walk = " ".join(_nb_cells()["front_to_back_task"].split())
    assert "threshold just below 1" in walk and "asks for exactly 1" in walk, walk


def test_a_checker_helper_is_named_a_part_of_the_function_that_calls_it():
    """r18 D-5: the private ``_porter_duff`` handed to 9.2a was called "a part of
    from_straight's own computation"; from_straight never calls it, straight_over does."""
    from teachraster.exercises import blend_straight

    def porter_duff(s, d):
        colour, a = blend_straight._porter_duff(np.asarray(s, float), np.asarray(d, float))
        return np.r_[colour, a]

    report = ex.check("over_straight", porter_duff, budget=60)
    assert not report.passed and report.package, str(report)
    # r20 D-8: straight_over and its helpers are the checker's own code, so said
    assert "the checker's own code" in report.package, report.package
    assert "from_straight" not in report.package, report.package


def test_9_2a_general_message_sends_back_to_the_steps_without_the_weights():
    """r19 E-2: a wrong answer no mistake names got the general recipe, which stated the
    weights the task asks the student to derive; it now points at the derivation's steps."""

    def colour_rooted(s, d):  # no mistake names it: the general message (r289 M2: double
        right = over_straight(s, d)  # premultiplication, this test's example, is named now)
        return np.r_[np.sqrt(right[:3]), right[3]]

    report = ex.check("over_straight", colour_rooted, budget=60)
    assert not report.passed
    general = [f.explanation.split("yours is ", 1)[1] for f in report.failures]
    assert general and all("derivation's steps" in w for w in general), general
    for words in general:  # the case's numbers come before "yours is"; the message after it
        words = words.split(": ", 1)[1]
        for weight in ("α_d of the 1 − α_s", "the source in α_s", "(0, 0, 0, 0)", "1 − α_s"):
            assert weight not in words, (weight, words)


@pytest.mark.parametrize(
    "fn",
    [
        lambda s, d: s * (1 - s[3]) + d * s[3],
        lambda s, d: np.r_[s[:3] * (1 - s[3]) + d[:3] * s[3], s[3] + d[3] * (1 - s[3])],
        lambda s, d: np.r_[s[:3] * (1 - s[3]) + d[:3] * d[3] * s[3], min(1.0, s[3] + d[3])],
    ],
    ids=["pair swapped, four channels", "pair swapped, alpha right", "swapped, alpha summed"],
)
def test_9_2a_swapped_pair_is_named_whatever_the_alpha(fn):
    """r19 E-1: the factor pair swapped on all four channels was told "your red, green and
    blue are right, your alpha is not" (true only at α_s = ½), and with its alpha mended got
    the general message: every failing case now names the swap."""
    report = ex.check("over_straight", lambda s, d: fn(np.asarray(s, float), np.asarray(d, float)),
                      budget=60)  # fmt: skip
    assert not report.passed
    assert {f.kind for f in report.failures} == {"weights swapped"}
    assert all("swapped the weights" in f.explanation for f in report.failures)
    assert not any("your red, green and blue are right" in f.explanation
                   for f in report.failures)  # fmt: skip


def test_9_2a_colour_right_alpha_wrong_is_not_called_swapped():
    """The swap fits α_s = ½ over an opaque destination by coincidence: an answer whose colour
    is right everywhere is still told its alpha is wrong, not that it swapped."""
    report = ex.check("over_straight", lambda s, d: np.r_[over_straight(s, d)[:3], 0.123],
                      budget=60)  # fmt: skip
    assert report.failures and not any(f.kind == "weights swapped" for f in report.failures)


def test_9_3_passing_figure_keeps_expected_and_yours_apart():
    """r19 E-6: in the passing 9.3 figure "expected" and "yours" nearly touched."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.plotting import use_style

    # within a block: set for good, the style leaked into later tests of the same worker
    # (CI: test_style_applies_to_the_widget_only read font.size 18)
    with use_style("classroom"):
        fig, ax = plt.subplots(figsize=(7, 4))
        ex.check("front_to_back", front_to_back, budget=60).plot(ax)
        fig.canvas.draw()
        boxes = {t.get_text(): t.get_window_extent() for t in ax.get_xticklabels()}
        gap = boxes["yours"].x0 - boxes["expected"].x1
        plt.close(fig)
    assert gap >= 20, gap  # pixels at the figure's dpi


def test_straight_blend_claim_and_float_alpha_note():
    """r19 E-5: GL's straight blend is exact over an opaque destination and also where the
    source is opaque or wholly transparent ("only over an opaque destination" was false);
    E-7: 9.3 says that float alpha can reach 1.0 while light still gets through."""
    task = " ".join(_nb_cells()["over_straight_task"].split())
    assert "only over an opaque" not in task and "opaque or wholly transparent" in task, task
    assert "the check tries such a case" in task, task
    said = str(ex.check("over_straight", lambda s, d: np.asarray(s) * s[3] + np.asarray(d) *
                        (1 - s[3]), budget=60))  # fmt: skip
    assert "exact only over an opaque" not in said and "opaque or wholly transparent" in said
    walk = " ".join(_nb_cells()["front_to_back_task"].split())
    assert "round to exactly 1.0" in walk and "two layers of alpha 1 − 2⁻³⁰" in walk, walk
    a = 1 - 2.0**-30  # the note's example, as float64 accumulates it
    alpha, through = a + (1 - a) * a, (1 - a) ** 2
    assert alpha == 1.0 and through > 0


# -- r20: 9.2b is atop; the fixes D-2 to D-8 ---------------------------------------------------
def _atop_straight_rule(s, d):
    """Atop derived for straight colours, applied to premultiplied ones (undivided)."""
    return np.r_[s[:3] * s[3] * d[3] + d[:3] * d[3] * (1 - s[3]), d[3]]


def _unpremultiplied_atop(s, d):
    """Divided by alpha (0 where it is 0), atop on straight colours, premultiplied again."""
    S = np.r_[s[:3] / s[3], s[3]] if s[3] else np.zeros(4)
    D = np.r_[d[:3] / d[3], d[3]] if d[3] else np.zeros(4)
    return np.r_[S[:3] * S[3] * D[3] + D[:3] * D[3] * (1 - S[3]), D[3]]


#: (wrong atop, kind, words): r20 D-1's named mistakes of the new 9.2b.
ATOP_WRONG = [
    (lambda s, d: s + d * (1 - s[3]), "over, not atop", "that is over"),
    (lambda s, d: np.r_[s[:3] + d[:3] * (1 - s[3]), d[3]], "over, not atop", "colour is over's"),
    (_atop_straight_rule, "straight rule on premultiplied", "already carry their alpha"),
    (lambda s, d: np.r_[s[:3] * s[3] + d[:3] * (1 - s[3]), d[3]],
     "straight rule on premultiplied", "divided the light"),
    (lambda s, d: s * s[3] + d * (1 - s[3]), "GL's straight blend", "GL's straight blend"),
    (lambda s, d: np.r_[s[:3] * s[3] * d[3] + d[:3] * (1 - s[3]), d[3]], "premultiplied twice",
     "the source by its alpha again"),
    (lambda s, d: np.r_[s[:3] * d[3] + d[:3] * d[3] * (1 - s[3]), d[3]],
     "destination premultiplied twice", "destination by its alpha again"),
    (lambda s, d: np.r_[np.divide(s[:3] * d[3] + d[:3] * (1 - s[3]), d[3], out=np.zeros(3),
                                  where=d[3] > 0), d[3]], "returned straight", "straight colour"),
    (lambda s, d: s * (1 - s[3]) + d * d[3], "weights swapped", "swapped the two weights"),
    (lambda s, d: d * s[3] + s * (1 - d[3]), "arguments swapped", "dst atop src"),
    (lambda s, d: s * d[3] + d, "destination not scaled", "the whole destination"),
    (lambda s, d: s * d[3] + d * (1 - d[3]), "destination's own alpha", "1 − its own alpha"),
    (lambda s, d: s * (1 - d[3]) + d * (1 - s[3]), "source where the destination is not",
     "*xor*"),
    (lambda s, d: s * d[3], "destination left out", "*in*"),
    (lambda s, d: np.r_[s[:3] * d[3] + d[:3] * (1 - s[3]), s[3] + d[3] * (1 - s[3])],
     "alpha of over", "your red, green and blue are right"),
    (lambda s, d: np.r_[s[:3] * d[3] + d[:3] * (1 - s[3]), s[3] * d[3]],
     "alpha of the shared share", "your red, green and blue are right"),
    (lambda s, d: np.round(s * d[3] + d * (1 - s[3])).astype(int), "whole numbers",
     "whole numbers"),
    (_unpremultiplied_atop, "glow lost", "glow"),
]  # fmt: skip


@pytest.mark.parametrize(("fn", "kind", "words"), ATOP_WRONG, ids=[k for _, k, _ in ATOP_WRONG])
def test_9_2b_atop_mistakes_are_named_without_the_answer(fn, kind, words):
    """r20 D-1, D-5: each of the new 9.2b's typical mistakes is named by what the answer did,
    and no message gives atop's weights or its factor pair."""
    assert ex.check("atop_premultiplied", atop_pm).passed
    first = _first("atop_premultiplied", _premultiplied(fn))
    assert first.kind == kind and words in first.explanation, (first.kind, first.explanation)
    said = first.explanation.split("yours is ", 1)[1]
    for answer in ("DST_ALPHA", "c_s·α_d", "src·α_d", "α_s·α_d + ", "is the destination's"):
        assert answer not in said, (answer, said)


def test_9_2b_general_message_and_package_routes():
    """r20 D-1: an answer no mistake names is sent back to the derivation's steps; GL's own
    atop pair through ``tr.blend_equation`` and the checker's reference are not counted."""
    import teachraster as tr
    from teachraster.exercises.blending import premultiplied_atop

    first = _first("atop_premultiplied", lambda s, d: atop_pm(s, d) + np.float64(3e-6))
    assert first.kind == "value" and "go back through the derivation" in first.explanation
    report = ex.check(
        "atop_premultiplied",
        lambda s, d: tr.blend_equation(s, d, "DST_ALPHA", "ONE_MINUS_SRC_ALPHA"),
    )
    assert not report.passed and "blend_equation" in report.package, str(report)
    report = ex.check("atop_premultiplied", lambda s, d: premultiplied_atop(s, d))
    assert not report.passed and "the checker's own code" in report.package, str(report)
    float32 = ex.check("atop_premultiplied", lambda s, d: atop_pm(np.float32(s), np.float32(d)))
    assert float32.passed, str(float32)


def test_the_straight_rule_on_premultiplied_fix_leads_to_the_answer():
    """r20 D-2: "multiply the straight rule through by the result's alpha" alone led a student
    to "9.2a reused"; the advice now ends with c = α·C."""
    first = _first("over_premultiplied", over_straight)
    assert first.kind == "straight rule on premultiplied", first.explanation
    assert "then write each colour in it as c = α·C" in first.explanation, first.explanation


def _guarded(threshold):
    def fn(s, d):
        a = s[3] + d[3] * (1 - s[3])
        return [0, 0, 0, 0] if a < threshold else over_straight(s, d)

    return fn


@pytest.mark.parametrize("threshold", [0.01, 0.005])
def test_a_guard_below_a_small_alpha_fails_9_2a_and_is_named(threshold):
    """r20 D-3: ``α < 0.01 → (0, 0, 0, 0)`` passed: no case had a faint, non-zero alpha."""
    first = _first("over_straight", _guarded(threshold))
    assert first.kind == "faint as nothing", first.explanation
    assert "so it is not empty" in first.explanation, first.explanation
    assert ex.check("over_straight", _guarded(1e-300)).passed  # only α = 0 has no colour


def _stops_at(threshold, top=False, dtype=float):
    def fn(layers):
        acc = np.zeros(4, dtype)
        for layer in layers:
            if top and acc[3] >= threshold:
                break
            acc = acc + (1 - acc[3]) * np.asarray(layer, dtype)
            if not top and acc[3] >= threshold:
                break
        return acc

    return fn


@pytest.mark.parametrize("top", [False, True], ids=["tests after", "tests at the top"])
@pytest.mark.parametrize("gap", [1e-6, 1e-7])
def test_a_stop_just_below_alpha_1_fails_by_the_layers_read(gap, top):
    """r20 D-4: a stop at 1 − 1e-7 or 1 − 1e-6 passed (its composite is within tolerance);
    a stack that stays within 2⁻²⁴ of 1 for two layers tells it by the layers it read, even
    from a loop that tests at the top. A right loop in float32 still passes."""
    report = ex.check("front_to_back", _stops_at(1 - gap, top), budget=60)
    assert not report.passed and report.failures[0].kind == "stopped below alpha 1", str(report)
    assert "stopped at an alpha below 1" in report.failures[0].explanation
    for dtype in (float, np.float32):
        assert ex.check("front_to_back", _stops_at(1.0, top, dtype), budget=60).passed
    task = " ".join(_nb_cells()["front_to_back_task"].split())
    # r25 D-1: not "however close" (no short stack told stops nearer than about 1e-12); r445
    # W1: the stack that stays at 1 − 2⁻⁵³ for three layers tells every stop below 1
    assert "names a stop below 1, even at the last double below 1" in task, task


@pytest.mark.parametrize("top", [False, True], ids=["tests after", "tests at the top"])
@pytest.mark.parametrize("test", [
    lambda a: a >= 1 - 2**-25, lambda a: a >= 1 - 2**-40, lambda a: a >= 1 - 1e-9,
    lambda a: math.isclose(a, 1.0),
], ids=["1 - 2^-25", "1 - 2^-40", "1 - 1e-9", "math.isclose"])  # fmt: skip
def test_a_stop_within_1e_9_of_alpha_1_fails_in_float64_and_passes_in_float32(test, top):
    """r24 D-1: stops closer to 1 than 1 − 4.5e-8, ``math.isclose(A, 1)`` among them, passed
    although the task asks for exactly 1: a stack whose alpha is 1 − 2⁻⁴⁰ for two layers
    tells them by the layers read, in float64; float32, where that alpha is 1, may stop."""

    def fn(dtype):
        def walk(layers):
            acc = np.zeros(4, dtype)
            for layer in layers:
                if top and test(float(acc[3])):
                    break
                acc = acc + (1 - acc[3]) * np.asarray(layer, dtype)
                if not top and test(float(acc[3])):
                    break
            return acc

        return walk

    report = ex.check("front_to_back", fn(float), budget=60)
    assert not report.passed and report.failures[0].kind == "stopped below alpha 1", str(report)
    assert "math.isclose(A, 1) stops there too" in report.failures[0].explanation
    assert ex.check("front_to_back", fn(np.float32), budget=60).passed
    task = " ".join(_nb_cells()["front_to_back_task"].split())
    assert "`math.isclose(A, 1)` is a stop below 1 too" in task, task


def test_a_stop_below_alpha_1_figure_marks_the_layers_not_read():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4))
    ex.check("front_to_back", _stops_at(1 - 1e-7), budget=60).plot(ax)
    ticks = [t.get_text() for t in ax.get_xticklabels()]
    plt.close(fig)
    assert any("not read" in t for t in ticks), ticks


@pytest.mark.parametrize("name", ["over_straight", "atop_premultiplied", "over_premultiplied"])
def test_an_answer_rounded_to_whole_numbers_is_said_so(name):
    """r20 D-7: ``np.round(...).astype(int)`` got only the general message."""
    right = {"over_straight": over_straight, "atop_premultiplied": atop_pm,
             "over_premultiplied": over_pm}[name]  # fmt: skip
    first = _first(name, lambda s, d: np.round(np.asarray(right(s, d), float)).astype(int))
    assert first.kind == "whole numbers" and "whole numbers" in first.explanation, first


def test_the_checkers_straight_over_handed_in_is_the_checkers_own_code():
    """r20 D-8: it was called "the package's own function", unlike lines.diamond_pixels."""
    from teachraster.exercises.blending import from_straight, straight_over

    report = ex.check("over_straight", lambda s, d: straight_over(s, d))
    assert not report.passed and "the checker's own code" in report.package, report.package
    report = ex.check("over_to_premultiplied", lambda s, d: from_straight(s, d))
    assert not report.passed and "the checker's own code" in report.package, report.package


# -- r22: 9.2b's faint and glowing destinations; names of the secondary mistakes -------------
def _atop_guarded(test):
    """Atop, but (0, 0, 0, 0) where ``test(src, dst)`` holds."""
    return lambda s, d: np.zeros(4) if test(np.asarray(s), np.asarray(d)) else atop_pm(s, d)


@pytest.mark.parametrize("guard", [
    lambda s, d: d[3] < 0.01, lambda s, d: d[3] < 0.05, lambda s, d: d[3] == 0,
    lambda s, d: atop_pm(s, d)[3] == 0,
], ids=["faint dst 0.01", "faint dst 0.05", "dst alpha 0", "result alpha 0"])  # fmt: skip
def test_an_atop_guard_on_a_small_alpha_always_fails_named(guard):
    """r22 D-1, D-2: a faint-destination guard passed 55 of 60 runs (only drawn cases caught
    it, then named "whole numbers"), and "(0, 0, 0, 0) where α = 0" passed: a fixed faint
    destination and a glowing one (alpha 0, light) now fail it, on every run, named."""
    report = ex.check("atop_premultiplied", _atop_guarded(guard), budget=60)
    assert not report.passed
    kinds = {f.kind for f in report.failures}
    assert kinds == {"nothing returned"}, str(report)[:800]
    said = " ".join(f.explanation for f in report.failures)
    assert "is a glow" in said and "whole numbers" not in said, said


def test_atop_of_a_glowing_destination_keeps_its_light():
    """r22 D-2: src atop a glow (alpha 0) is src·0 + dst·(1 − α_s): the glow's light, dimmed
    by the source's coverage, alpha 0."""
    from teachraster.exercises.blending import blend_cases

    case = next(c for c in blend_cases("atop") if "atop a glow" in c[0])
    assert np.allclose(case[2], [0.15, 0.1, 0.025, 0.0]), case
    faint = [c for c in blend_cases("atop") if "faint" in c[0]]
    assert len(faint) == 2 and all(0 < c[1][k][3] < 0.01 for c, k in zip(faint, (1, 0)))


@pytest.mark.parametrize("fn,kind,words", [
    (lambda s, d: np.asarray(d, float) + s if s[3] == 0 and any(s[:3]) else atop_pm(s, d),
     "glow added whole", "only where the destination covers"),
    (lambda s, d: np.r_[np.minimum(np.asarray(atop_pm(s, d))[:3], atop_pm(s, d)[3]),
                        atop_pm(s, d)[3]], "colour clamped to alpha", "light (a glow)"),
    (lambda s, d: np.r_[np.asarray(s[:3]) * (1 - s[3]) + np.asarray(d[:3]) * d[3], d[3]],
     "weights swapped", "your alpha is right"),
    (lambda s, d: np.asarray(d, float) if s[3] < 0.01 else atop_pm(s, d), "source skipped",
     "destination unchanged"),
], ids=["glow added whole", "clamped to alpha", "colour weights swapped", "faint src"])  # fmt: skip
def test_atops_glow_mistakes_are_named(fn, kind, words):
    """r22 D-8: the glow question's two natural wrong answers and the colour-only swap got
    the general message; a faint-source guard is named at both its failures."""
    report = ex.check("atop_premultiplied", fn, budget=60)
    assert {f.kind for f in report.failures} == {kind}, str(report)[:800]
    assert words in report.failures[0].explanation, report.failures[0].explanation


@pytest.mark.parametrize("name", ["over_straight", "atop_premultiplied"])
def test_a_rounded_answer_is_never_called_a_faint_pixel(name):
    """r22 D-6: 9.2a's rounded answer got "a faint pixel" (α = 0.377) on a later line."""
    right = {"over_straight": over_straight, "atop_premultiplied": atop_pm}[name]
    report = ex.check(name, lambda s, d: np.round(np.asarray(right(s, d), float)).astype(int),
                      budget=60)  # fmt: skip
    assert {f.kind for f in report.failures} == {"whole numbers"}, str(report)[:800]


@pytest.mark.parametrize("how,kind", [
    (lambda c: np.round(c).astype(int), "whole numbers"),
    (lambda c: c + (1 - c[3]) * np.ones(4), "over white"),
    (lambda c: np.r_[c[:3] + (1 - c[3]), c[3]], "over white"),
])  # fmt: skip
def test_front_to_back_whole_numbers_and_white_are_named(how, kind):
    """r22 D-7: a right loop rounded, or composited over white, got the rule restated."""
    report = ex.check(
        "front_to_back", lambda layers: how(np.asarray(front_to_back(layers), float)), budget=60
    )
    assert report.failures and report.failures[0].kind == kind, str(report)[:800]


def test_r22_text_fixes():
    """r22 D-3, D-4, D-5, D-9, D-10: PDF has over only and SVG's atop is feComposite; the
    heading fits atop; a transparent glow is not "(0, 0, 0, 0)"; the package rule is stated."""
    cells = _nb_cells()
    atop = " ".join(cells["atop_premultiplied_task"].split())
    assert "SVG and PDF composite the same way" not in atop
    assert "feComposite" in atop and "PDF composites with *over* alone" in atop
    task = " ".join(cells["over_straight_task"].split())
    assert task.startswith("## 9.2 Over and atop"), task[:80]
    assert "a transparent pixel is (0, 0, 0, 0)" not in task
    assert "covers nothing and carries no light is (0, 0, 0, 0)" in task
    intro = " ".join(cells["intro"].split())
    assert "`tr.blend_equation`" in intro and "not counted" in intro
    import inspect

    from teachraster.exercises.front_to_back import explain_layers

    assert "within the check's tolerance" in inspect.getsource(explain_layers)


# -- r23: the glowing destination's words, 9.2a's package words, D-4's named slips -----------
def _via_straight(s, d):
    """9.2b through straight colours: both divided by their alpha (0 where it is 0)."""
    s, d = np.asarray(s, float), np.asarray(d, float)
    with np.errstate(all="ignore"):
        S = np.where(s[3] > 0, s[:3] / s[3], 0.0)
        D = np.where(d[3] > 0, d[:3] / d[3], 0.0)
    return np.r_[S * s[3] * d[3] + D * d[3] * (1 - s[3]), d[3]]


def _clamped_inputs(s, d):
    """Both inputs' colours clamped to their alpha, then atop."""
    s, d = np.asarray(s, float), np.asarray(d, float)
    s, d = (np.r_[np.minimum(c[:3], c[3]), c[3]] for c in (s, d))
    return s * d[3] + d * (1 - s[3])


@pytest.mark.parametrize("fn", [_via_straight, _clamped_inputs], ids=["via straight", "clamped"])
def test_a_glowing_destination_lost_is_said_of_the_destination(fn):
    """r23 D-1: at "half orange atop a glow" the answer (0, 0, 0, 0) was told "the destination
    unchanged, as if src (…, 0.5) were not there; it is a glow": the glow is dst."""
    report = ex.check("atop_premultiplied", fn, budget=60)
    by_case = {f.case: f for f in report.failures}
    assert set(by_case) == {"a glow (light, alpha 0) atop half blue",
                            "half orange atop a glow (light, alpha 0)"}, str(report)  # fmt: skip
    dst = by_case["half orange atop a glow (light, alpha 0)"]
    said = dst.explanation.split("yours is ", 1)[1]
    assert dst.kind == "glow lost", said
    assert "destination unchanged" not in said and "src (" not in said, said
    assert "as if dst (0.3, 0.2, 0.05, 0) carried no light, but it is a glow" in said, said
    src = by_case["a glow (light, alpha 0) atop half blue"].explanation
    assert "your answer is the destination unchanged, as if src (0.3, 0.2, 0.05, 0)" in src


def test_a_nan_at_a_glowing_destination_names_the_destination():
    """r23 D-1: a division by alpha with no guard gives NaN at dst's glow too."""

    def unguarded(s, d):
        s, d = np.asarray(s, float), np.asarray(d, float)
        with np.errstate(all="ignore"):
            S, D = s[:3] / s[3], d[:3] / d[3]
            return np.r_[S * s[3] * d[3] + D * d[3] * (1 - s[3]), d[3]]

    report = ex.check("atop_premultiplied", unguarded, budget=60)
    dst = next(f for f in report.failures if f.case.startswith("half orange atop a glow"))
    assert dst.kind == "glow lost" and "dst (0.3, 0.2, 0.05, 0) is a glow" in dst.explanation


def test_9_2a_through_the_packages_blend_is_not_said_to_be_the_answer():
    """r23 D-3: a right 9.2a through ``tr.blend_equation`` (premultiplied over, then divided
    by α) was told the blend "computes this very answer"; no factor pair gives straight over.
    The checker's own reference still says it is the checker's code."""
    import teachraster as tr
    from teachraster.exercises.blending import from_straight

    def through_blend(s, d):
        s, d = np.asarray(s, float), np.asarray(d, float)
        a = s[3] + d[3] * (1 - s[3])
        if a == 0:
            return np.zeros(4)
        pm = tr.blend_equation(np.r_[s[:3] * s[3], s[3]], np.r_[d[:3] * d[3], d[3]],
                               "ONE", "ONE_MINUS_SRC_ALPHA")  # fmt: skip
        return np.r_[pm[:3] / a, a]

    report = ex.check("over_straight", through_blend, budget=60)
    assert not report.passed and "teachraster's blend_equation" in report.package, str(report)
    assert "computes this very answer" not in report.package, report.package
    assert "no blend factor pair gives straight over" in report.package, report.package

    def through_reference(s, d):
        out = from_straight(s, d)
        return np.r_[out[:3] / out[3], out[3]] if out[3] else np.zeros(4)

    report = ex.check("over_straight", through_reference, budget=60)
    assert "the checker's own code" in report.package, report.package


def test_r23_text_fixes():
    """r23 D-2, D-5, D-8: lesson 12 prints Porter and Duff's *plus* too (its additive mode);
    the notebook imports no ``tr``; 9.3 ties the loop to the GPU's own front-to-back blend
    without giving its factor pair (that pair is the step 9.3 asks for)."""
    cells = _nb_cells()
    atop = " ".join(cells["atop_premultiplied_task"].split())
    assert "none of them but" not in atop
    # r24 D-3: lesson 12 never says "plus", and prints its additive mode on a straight colour
    # r25 D-4: lesson 12's "over" mode is the straight pair, over only on an opaque destination
    assert 'prints only *over* (its "premultiplied" mode; its "over" mode is the straight' in atop
    # r359 C1: its colour only, its alpha wrong even there (as 9.2a's text says)
    assert "*over*'s only on an opaque destination, its alpha not even there" in atop, atop
    assert "is their *plus* when the colours are premultiplied" in atop, atop
    assert "PDF composites with *over* alone, its blend modes aside" in atop, atop
    lesson = " ".join(_lesson_12_text().split())
    said = re.findall(r"\bplus\b \w+ \w+", lesson)
    assert said == ["plus a pixel"], said  # never the operator
    assert '"additive"' in lesson and '"premultiplied"' in lesson, lesson[:200]
    intro = " ".join(cells["intro"].split())
    assert "`teachraster.blend_equation`, lesson 12b's `tr.blend_equation`" in intro, intro
    assert "import teachraster as tr" not in cells["setup"]
    ftb = " ".join(cells["front_to_back_task"].split())
    assert "A GPU can composite nearest first too" in ftb and "name that pair" in ftb, ftb
    for answer in ("ONE_MINUS_DST_ALPHA", "DST_ALPHA", "1 − A", "(1 - A)"):
        assert answer not in ftb, answer
    # r25 D-3: the teacher's solution names the pair the task asks the student to name
    solution = _nb_cells()["front_to_back_solution"]
    assert "ONE_MINUS_DST_ALPHA" in solution and "dst factor ONE" in solution, solution


def test_the_tie_rule_is_said_once_with_each_lines_own_numbers():
    """r23 D-6: the ~90-word tie sentence stood on every line of the report, and its float
    clause quoted "3.0 − 1e-17" also on the lines at x = 5 and y = 6."""
    report = ex.check("line_pixels", line_with(0, 0), budget=60)
    text = str(report)
    tie = "at a tie the rule moves both end points by (−ε, −ε²), ε vanishingly small"  # r326 S4
    assert text.count(tie) == 1, text
    said = [f.explanation for f in report.failures]
    assert tie in said[0] and all(tie not in s for s in said[1:]), said
    assert all("as said above" in s for s in said[1:]), said
    for f in report.failures:
        (p0, p1) = re.search(r"segment (\(.*?\)) → (\(.*?\))", f.explanation).groups()
        quoted = re.search(r"floating point: (\S+) − (\S+) == (\S+) in float64", f.explanation)
        v, tiny = float(quoted[1]), float(quoted[2])
        assert v == float(quoted[3]) and v - tiny == v, f.explanation
        assert quoted[1] in p0 + p1, (quoted[1], p0, p1)  # the case's own coordinate


def _over_dividing_by(alpha):
    def fn(s, d):
        s, d = np.asarray(s, float), np.asarray(d, float)
        a = alpha(s, d)
        if a == 0:
            return np.zeros(4)
        return np.r_[(s[:3] * s[3] + d[:3] * d[3] * (1 - s[3])) / a, a]

    return fn


@pytest.mark.parametrize(("alpha", "words"), [
    (lambda s, d: s[3] * s[3] + d[3] * (1 - s[3]), "as GL's straight blend does on the fourth"),
    (lambda s, d: s[3] + d[3], "you added the two alphas"),
    (lambda s, d: s[3] * d[3], "the share both cover"),
    (lambda s, d: max(s[3], d[3]), "the larger of the two"),
], ids=["GL single pair", "sum", "product", "max"])  # fmt: skip
def test_9_2a_a_wrong_alpha_divided_into_the_light_is_named(alpha, words):
    """r23 D-4: GL's one-pair alpha (lesson 12 prints it), α_s + α_d, α_s·α_d and the max,
    each dividing the light, got only the general message."""
    report = ex.check("over_straight", _over_dividing_by(alpha), budget=60)
    assert not report.passed
    said = " ".join(f.explanation for f in report.failures)
    assert {f.kind.endswith("colour divided by it") for f in report.failures} == {True}, said
    assert words in said and "go back through the derivation" not in said, said


@pytest.mark.parametrize("how", [lambda c: np.round(c * 255) / 255,
                                 lambda c: np.r_[np.round(c[:3] * 255) / 255, c[3]],
                                 lambda c: np.floor(c * 255) / 255],
                         ids=["all four", "colour only", "cut"])  # fmt: skip
@pytest.mark.parametrize("name", ["over_straight", "atop_premultiplied", "front_to_back"])
def test_an_answer_rounded_to_8_bits_is_said_so(name, how):
    """r23 D-4: ``round(x·255)/255`` was sent back through the derivation (9.2a) or given the
    rule (9.3)."""
    if name == "front_to_back":
        fn = lambda layers: how(np.asarray(front_to_back(layers), float))  # noqa: E731
    else:
        right = {"over_straight": over_straight, "atop_premultiplied": atop_pm}[name]
        fn = lambda s, d: how(np.asarray(right(s, d), float))  # noqa: E731
    report = ex.check(name, fn, budget=60)
    assert not report.passed
    assert {f.kind for f in report.failures} == {"8-bit rounding"}, str(report)[:800]
    assert "rounded to steps of 1/255" in report.failures[0].explanation


def _walk(stop, top=False, dtype=float):
    """A nearest-first under loop; ``stop(acc, through, layer)`` after each layer (or at the
    top of the loop, before it), ``through`` the light the layers read let through."""

    def fn(layers):
        acc, through = np.zeros(4, dtype), dtype(1)
        for layer in layers:
            layer = np.asarray(layer, dtype)
            if top and stop(acc, through, layer):
                break
            acc = acc + (1 - acc[3]) * layer
            through = through * (1 - layer[3])
            if not top and stop(acc, through, layer):
                break
        return acc

    return fn


@pytest.mark.parametrize("top", [False, True], ids=["tests after", "tests at the top"])
def test_a_loop_that_waits_for_an_opaque_layer_fails_and_is_named(top):
    """r25 D-2: ``if layer[3] >= 1: break`` passed every case: it differs from the task's
    accumulated-alpha test only where no layer is opaque but the composite is. A stack of 23
    layers of alpha 1 − 2⁻⁵³ tells it: the alpha is 1 after two, the light let through
    underflows to 0 after 21. Both stops the task allows still pass, in float64 and float32."""
    from teachraster.exercises.front_to_back import layer_cases, stop_window

    stack = next(a[0] for label, a, _ in layer_cases() if label.startswith("no layer opaque"))
    assert (stack[:, 3] < 1).all() and stop_window(stack) == (2, 21)
    # (tested at the top, a layer's own alpha leaves the opaque layer out: named elsewhere)
    report = ex.check("front_to_back", _walk(lambda a, t, layer: layer[3] >= 1), budget=60)
    assert not report.passed and [f.kind for f in report.failures] == [
        "waited for an opaque layer"], str(report)  # fmt: skip
    words = report.failures[0].explanation
    assert "none of them is opaque by itself" in words and "waits for a layer" in words, words
    assert "accumulated alpha is 1" in words and "test" not in words, words  # names, no rule
    for dtype in (float, np.float32):
        for stop in (lambda a, t, layer: a[3] >= 1, lambda a, t, layer: t <= 0):
            assert ex.check("front_to_back", _walk(stop, top, dtype), budget=60).passed


def test_a_long_stack_is_drawn_folded_with_its_marked_layers():
    """r25 D-2: the 23-layer stack's labels ran into each other: the figure keeps the first
    two and last two layers and those marked, the rest one slot."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("front_to_back", _walk(lambda a, t, layer: layer[3] >= 1), budget=60)
    fig, ax = plt.subplots(figsize=(7, 4))
    report.failures[0].draw(ax)
    labels = [t.get_text() for t in ax.get_xticklabels()]
    plt.close(fig)
    assert labels == ["1", "2", "3–21", "22\nallowed", "23\nread", "expected", "yours"], labels


def test_the_9_1_figure_draws_a_diamond_for_every_pixel_of_its_axes():
    """r25 D-6: the pass figure drew diamonds over x, y ∈ [0, 9] of its 12 × 12 axes, as if
    the grid stopped there."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection

    fig, ax = plt.subplots(figsize=(7, 4))
    ex.check("line_pixels", line_pixels, budget=60).plot(ax)
    drawn = [c for c in ax.collections if isinstance(c, PolyCollection)]
    centres = {
        tuple(np.round(p.vertices[:4].mean(axis=0), 3)) for c in drawn for p in c.get_paths()
    }
    plt.close(fig)
    assert centres == {(j + 0.5, i + 0.5) for i in range(12) for j in range(12)}, len(centres)


def test_the_checks_edge_cases_stand_folded_after_the_tasks():
    """r25 D-8: cell 2's tie details and cell 11's float stops explained the checker's edge
    cases before the student wrote a line: they stand in a <details> after each task."""
    for cell, inside in (("line_pixels_task", ("2⁻⁸⁰", "Direct3D", "1/8-pixel grid")),
                         ("front_to_back_task", ("math.isclose", "2⁻³⁰", "accepts either"))):  # fmt: skip
        task = _nb_cells()[cell]
        start = task.index("<summary>What the check tries")
        folded, before = task[start : task.index("</details>", start)], task[:start]
        for words in inside:
            assert words in folded and words not in before, (cell, words)


def test_9_2a_asks_questions_whose_answers_the_text_does_not_give():
    """r25 D-7: the scaffolding said "the rest of the pixel, 1 − α_s of it, it leaves
    uncovered" and step 4 "the light divided by α": 9.2a was close to transcription."""
    task = " ".join(_nb_cells()["over_straight_task"].split())
    for answer in ("1 − α_s", "divided by α", "division", "leaves uncovered", "summed"):
        assert answer not in task, answer
    for question in ("1. In what share of the pixel does the source show?",
                     "2. How much light does the pixel send you?",
                     "3. What share of the pixel does the result cover?",
                     "Which C sends the same light"):  # fmt: skip
        assert question in task, question


@pytest.mark.parametrize("threshold", [1 - 1e-13, 1 - 2**-53], ids=["1 - 1e-13", "last double"])
def test_a_stop_after_the_update_is_named_however_near_1(threshold):
    """r25 D-1: stops at 1 − 1e-13 and at the last double below 1 passed: the stack of layers
    of alpha 1 − 2⁻⁵³ names them when tested after adding a layer. r445 W1: tested at the top
    (the next layer read first) they passed; the stack whose alpha stays 1 − 2⁻⁵³ for three
    layers names them too, and the task asks for exactly 1."""
    for top in (False, True):
        walk = _walk(lambda a, t, layer: a[3] >= threshold, top=top)
        report = ex.check("front_to_back", walk, budget=60)
        assert not report.passed, (top, str(report))
        assert report.failures[0].kind == "stopped below alpha 1", (top, str(report))
    # r289 S4: the folded note is two sentences now; it no longer spells out this stack


def test_line_pixels_algorithm_is_a_hint_in_the_notebook_and_said_after_two_tries():
    """r84 09-1: 9.1's "How to go about it" box spelled out the whole slab algorithm (turned
    coordinates, open intervals in t, closed [0, 1], Fraction): 9.1 was transcription. The
    box keeps the first step; the checker's rule sketches the rest once two different answers
    have failed."""
    import json
    from pathlib import Path

    from teachraster.exercises import tries

    path = Path(__file__).parents[1] / "notebooks/exercises/09_lines_and_blending.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    text = "".join(cells[2]["source"])
    second = text[text.index("<summary>A second hint") :]
    # r289 M3: the sketch is folded in a second hint, never in the open text
    assert "u = x + y" in text and "open interval" not in text.replace(second, "")
    tries.forget_hints("line_pixels")
    try:
        first = str(ex.check("line_pixels", lambda p0, p1: sorted(line_pixels(p0, p1))[1:]))
        assert "open interval" not in first and "a hint only" in first, first
        second = str(ex.check("line_pixels", lambda p0, p1: sorted(line_pixels(p0, p1))[:-1]))
        assert second.count("open interval") == 1, second  # said in full once
    finally:
        tries.spend_hints(["line_pixels"])


def test_r326_the_end_points_are_x_y_and_the_gl_pairs_alpha_is_wrong_over_opaque():
    """r326 M1: cell 2 and the stub's docstring never said that p0 and p1 are (x, y); S1: the
    textbook pair "gives the right colour over an opaque destination", but not its alpha."""
    cells = _nb_cells()
    task = " ".join(cells["line_pixels_task"].split())
    assert "`p0` and `p1` are points **(x, y)**" in task and "**(row, col)** pairs" in task
    assert "p0 and p1 are (x, y)" in cells["line_pixels_solution"].split("### BEGIN")[0]
    over = " ".join(cells["over_straight_task"].split())
    assert "opaque destination (its alpha is wrong even there)" in over, over


def test_r326_the_passing_9_3_figure_greys_the_layers_no_loop_reads():
    """r326 S3: behind the opaque layer 3 (and the layer a loop may fetch), layers 5 and 6 of
    the passing figure's stack were drawn like the others."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    from teachraster.exercises.front_to_back import draw_layers, layer_cases

    case = next(c for c in layer_cases() if c[0] == "an opaque layer in the middle")
    fig, ax = plt.subplots()
    draw_layers(ax, case, case[2])
    greyed = sorted(round(p.get_x() / 1.3) for p in ax.patches if isinstance(p, Rectangle)
                    and p.get_facecolor()[:3] == (1.0, 1.0, 1.0))  # fmt: skip
    label = ax.get_xlabel()
    plt.close(fig)
    assert greyed == [4, 5] and "greyed: layers no right loop reads" in label, (greyed, label)
