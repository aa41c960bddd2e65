"""r232 (exercise 08_tiles): a fresh read playing 36 + 38 students, each class the reader found
with the answers that show it and the words or picture the check must give.

Wrongly passed 1 (C): a tie bias of 10⁻¹² or 10⁻⁹ px² added to E₀ before the offset passed all
49 cases of 8.1; float64 rounds it away where E₀ is large, and every tie case had E₀ below 10³
px². Seven far ties (16 … 2^19-px blocks, right and bottom edges, accept and reject side) now
fail it, in words of its own. C1: the notebook's model solution did the same with −2^-16 px² at
a 2^19-px block; M1: it now counts in lesson 10 §4's integer units, exact at any size, and the
task says why.
Wrongly passed 2 (C): round() / np.round (half to even) for 8.2's box passed all 70 cases; two
borders at an odd k + ½ (x and y) now fail it, named.
Half-named 1-4 (M): no bias in the reject test (llvmpipe's trivial reject) or in the accept test
is named as that; vertices read as (y, x) are told so, and where x0/y0 swapped (row0/col0 in
8.2) gives the same answer, both causes are said.
C2: 8.2's failure lines quote the case's arguments. S1: cell 5 states the bound. S2: no
boilerplate before the cause. FIG1: no figure before an answer, and no blank band between the
case and the scene. FIG2: a uniform tile has no colour bar; vertex depths at their vertices.
"""

from __future__ import annotations

import math
import random
import re
from pathlib import Path

import numpy as np
import pytest
from exercise_solutions import classify_block_loops
from graded_cells import flat, graded_cell
from test_exercises_r149 import full_words, plt  # noqa: F401
from test_exercises_r162 import first_words  # noqa: F401
from test_exercises_r198 import _hiz_variant, _variant

import teachraster as tr
from teachraster import exercises as ex
from teachraster.core.edges import setup_edges
from teachraster.exercises import hiz_tile, tile_blocks, tries

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"


def _cell(grade_id: str) -> str:
    return graded_cell(NOTEBOOK, grade_id)


def _kinds(report) -> set[str]:
    return {f.kind for f in report.failures}


def float_student(beta="-(2.0**-16)", last=False):
    """classify_block in float64 pixels, as the notebook's model solution was before r232: the
    bias ``beta`` added to E₀ before the offsets, or ``last``: after them."""

    def classify_block(xy, x0, y0, size):
        v = np.asarray(xy, dtype=float)
        px, py = np.asarray(x0) + 0.5, np.asarray(y0) + 0.5
        area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
        if area == 0:
            return np.full(px.shape, "rejected")
        if area < 0:
            v = v[[0, 2, 1]]
        rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            A, B = a[1] - b[1], b[0] - a[0]
            R = (size - 1) * (max(A, 0) + max(B, 0))
            T = (size - 1) * (min(A, 0) + min(B, 0))
            top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            bias = 0.0 if top_left else eval(beta)  # noqa: S307 - the test's own literal
            e0 = A * (px - a[0]) + B * (py - a[1])
            if last:
                rejected |= (e0 + R) + bias < 0
                accepted &= (e0 + T) + bias >= 0
            else:
                e0 = e0 + bias
                rejected |= e0 + R < 0
                accepted &= e0 + T >= 0
        return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))

    return classify_block


def _far_ties() -> list:
    return [c for c in tile_blocks.block_cases() if "far from its first centre" in c[0]]


# -- wrongly passed 1, C1: a bias lost to rounding ----------------------------------------------


def test_wp1_the_far_ties_are_what_the_review_asked():
    """Seven grids, each a tie at an extreme centre on an edge neither top nor left, far from
    the block's first centre (|E₀| ≥ 6·10⁴ px²), at sizes 16 … 2^19; accept side (the package
    says partial) and reject side (rejected), right and bottom edges."""
    ties = _far_ties()
    assert len(ties) == 7
    assert sorted({args[3] for _, args, _ in ties}) == [16, 64, 256, 1024, 2**19]
    seen = set()
    for label, (xy, gx, gy, size), want in ties:
        setup = setup_edges(xy, tile_blocks.SUBPIXEL_BITS)
        found = False
        for bx, by, kind in zip(gx.ravel(), gy.ravel(), np.ravel(want), strict=True):
            accept = kind == "partial"
            tie = tile_blocks._lost_tie(xy, int(bx), int(by), size, accept)
            if tie is None or kind == "accepted":
                continue
            k = tie[0]
            assert not setup.top_left[k] and abs(tie[2]) >= 6e4, (label, tie[2])
            seen.add((kind, tile_blocks.edge_kind(setup.p[(k + 1) % 3] - setup.p[k])))
            found = True
        assert found, label
    assert seen >= {("partial", "right"), ("rejected", "right"), ("partial", "bottom")}, seen


@pytest.mark.parametrize(
    ("beta", "sizes"),
    [("-1e-12", {16, 64, 256, 1024, 2**19}), ("-1e-9", {256, 1024, 2**19}),
     ("-(2.0**-16)", {2**19})],
    ids=["1e-12", "1e-9", "2^-16 (the old model solution)"],
)  # fmt: skip
@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_wp1_a_bias_added_before_the_offset_fails_and_is_named(beta, sizes, words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", float_student(beta), budget=120)
    # r248 F1: float64 pixels, a second slip of this student's, named on the far float64 ties
    lost = [f for f in report.failures if not f.case.startswith("far out in float64")]
    assert not report.passed and {f.kind for f in lost} == {"bias lost to rounding"}, str(report)
    assert _kinds(report) == {"bias lost to rounding", "float64 pixels"}, str(report)
    failing = {int(re.search(r"classify_block\(xy, x0, y0, (\d+)\)$", f.case)[1]) for f in lost}
    assert failing == sizes, failing
    for f in lost:
        assert "far from its first centre" in f.case
        assert "your bias is lost to rounding" in f.explanation
        assert "as if there were no bias" in f.explanation
        assert "Adding it after the offset is no cure" in f.explanation
        assert "integer units" in f.explanation


def test_wp1_the_same_biases_added_after_the_offset_fail_the_float64_ties():
    """E is a multiple of 2^-16 px², so any bias in [−2^-16, 0) added last is right where E₀
    is exact; r248 F1: past 2^37 px² E₀ itself is rounded, and the far float64 ties fail it."""
    for beta in ("-1e-12", "-1e-9", "-(2.0**-16)"):
        report = ex.check("classify_block", float_student(beta, last=True), budget=120)
        assert _kinds(report) == {"float64 pixels"}, str(report)
        assert all(f.case.startswith("far out in float64") for f in report.failures)


def test_wp1_the_new_cases_pass_the_reference_and_the_package():
    for label, args, want in _far_ties():
        for fn in (_variant(), classify_block_loops, float_student(last=True)):
            assert np.array_equal(np.asarray(fn(*args)), np.asarray(want)), label
        # the package's own fill: the accepted blocks hold no pixel the tie excludes
        xy, gx, gy, size = args
        if size <= 64:
            fill = tr.rasterize(tr.Triangle(xy), int(gx.max() + size), int(gy.max() + size))
            for bx, by, kind in zip(gx.ravel(), gy.ravel(), np.ravel(want), strict=True):
                block = fill.coverage[by : by + size, bx : bx + size]
                assert {"accepted": block.all(), "rejected": not block.any(),
                        "partial": block.any() and not block.all()}[str(kind)], (label, bx, by)  # fmt: skip


def test_wp1_a_bias_that_works_is_not_called_lost():
    """The old float form with no bias in its accept test fails small ties too (E₀ = 84 px²,
    where no bias is lost): not told "lost to rounding" (:data:`tile_blocks.LOST_FROM`)."""
    report = ex.check("classify_block", _with_old_accept_loose(), budget=120)
    assert not report.passed and "bias lost to rounding" not in _kinds(report), str(report)


def _with_old_accept_loose():
    inner = float_student()

    def classify_block(xy, x0, y0, size):
        right = np.asarray(inner(xy, x0, y0, size))
        loose = np.asarray(tile_blocks.classify_with(xy, x0, y0, size, tie="accept loose"))
        return np.where(loose == "accepted", loose, right)

    return classify_block


def _egcd(a: int, b: int):
    if b == 0:
        return a, 1, 0
    g, x, y = _egcd(b, a % b)
    return g, y, x - (a // b) * y


def _corner_ties(count: int, seed: int = 232) -> list:
    """Edges on the 1/256 grid through an extreme centre of a block of 64 … 2^19 px, the third
    vertex on either side, within ±2^20 px: (xy, x0 grid, y0 grid, size)."""
    rnd = random.Random(seed)
    out = []
    while len(out) < count:
        size = rnd.choice([64, 1024, 2**16, 2**19])
        x0, y0 = (rnd.randrange(-(2**20), 2**20 - 2 * size) for _ in range(2))
        p = np.array([x0 + 0.5 + rnd.choice([0, size - 1]), y0 + 0.5 + rnd.choice([0, size - 1])])
        d = np.array([rnd.randint(-(2**24), 2**24), rnd.randint(-(2**24), 2**24)]) / 256
        if not d.any():
            continue
        a, b = p - d * rnd.randint(1, 3), p + d * rnd.randint(1, 3)
        n = np.array([-d[1], d[0]]) * rnd.choice([1, -1]) * rnd.uniform(0.5, 3)
        c = np.round((p + n + d * rnd.uniform(-2, 2)) * 256) / 256
        xy = np.array([a, b, c])
        if np.abs(xy).max() >= 2**21 or tr.edge_function(*xy) == 0:
            continue
        gx, gy = tile_blocks._around(x0 - size, y0 - size, size, (3, 3))
        out.append((xy[rnd.sample(range(3), 3)], gx, gy, size))
    return out


def test_c1_the_model_solution_is_exact_at_far_ties():
    """C1, M1: the notebook's solution (integer units) agrees with the package on ties at the
    extreme centres of blocks up to 2^19 px, vertices up to 2^21 px out, where a float bias
    added to E₀ (10⁻⁹ px² here) is lost on many: the ties are sharp."""
    solution = _variant()
    wrong_float = 0
    for xy, gx, gy, size in _corner_ties(120):
        want = tile_blocks.expected_block(xy, gx, gy, size)
        assert np.array_equal(np.asarray(solution(xy, gx, gy, size)), want), (xy, size)
        wrong_float += int((np.asarray(float_student("-1e-9")(xy, gx, gy, size)) != want).any())
    assert wrong_float >= 5, wrong_float
    # the review's own example
    xy = np.array([[-262144, 262144], [262145, 786431], [-524288, 524288]], float)
    x0, y0 = np.array([0]), np.array([0])
    assert str(solution(xy, x0, y0, 2**19)[0]) == "rejected"
    assert str(float_student()(xy, x0, y0, 2**19)[0]) == "partial"


def test_m1_the_solution_counts_in_integers_and_the_task_says_why():
    code = _cell("classify_block_solution")
    assert "np.int64" in code and "beta = 0 if top_left else -1" in code
    assert "lesson 10 §4" in code and "2.0**-16" not in code
    task = flat(_cell("classify_block_task"))
    # r248 C1, F1: lesson 10 §4 counts on a GPU's grid; float64 pixels round E₀ itself
    assert "**Count in integers**, as lesson 10 §4 counts, on a GPU's grid of 256 units a pixel" in task  # fmt: skip
    assert "beyond, a tie goes either way, bias or not" in task
    assert "compute in float64" not in task and "How far float64 is exact" not in task
    # the bias is still the task's question
    assert "which values can E take at a centre?" in task and "−1" not in task.split("<details>")[0]


# -- half-named 1, 2: the bias in one test only --------------------------------------------------

_ACCEPT = "accepted &= e0 + T >= 0"
_REJECT = "rejected |= e0 + R < 0"
#: the reader's: the bias on the accept test only (llvmpipe's trivial reject), and the mirror
NO_REJECT_BIAS = _variant((_REJECT, "rejected |= e0 - beta + R < 0"))
NO_ACCEPT_BIAS = _variant((_ACCEPT, "accepted &= e0 - beta + T >= 0"))


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_hn1_no_bias_in_the_reject_test_is_named(words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", NO_REJECT_BIAS, budget=120)
    assert not report.passed and _kinds(report) == {"no bias in the reject test"}, str(report)
    for f in report.failures:
        assert "your reject test takes no bias off the edges that are neither top nor left" in f.explanation  # fmt: skip
        assert "llvmpipe's trivial reject does the same on those edges" in f.explanation
        assert "yours says partial" in f.explanation


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_hn2_no_bias_in_the_accept_test_is_named(words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", NO_ACCEPT_BIAS, budget=120)
    assert not report.passed and _kinds(report) == {"no bias in the accept test"}, str(report)
    for f in report.failures:
        assert "your accept test takes no bias off the edges that are neither top nor left" in f.explanation  # fmt: skip
        assert "yours says accepted" in f.explanation


def test_hn1_2_no_bias_at_all_keeps_its_own_words():
    report = ex.check("classify_block", _variant(("beta = 0 if top_left else -1", "beta = 0")), budget=120)  # fmt: skip
    assert _kinds(report) == {"no top-left rule (E ≥ 0)"}, str(report)


# -- half-named 3, 4: the vertices read as (y, x) -----------------------------------------------

READ_YX = _variant(
    (
        "v = np.rint(np.asarray(xy, dtype=float) * 256)",
        "v = np.rint(np.asarray(xy, dtype=float)[:, ::-1] * 256)",
    )  # fmt: skip
)
X0_Y0 = _variant(
    ("px, py = np.asarray(x0) * 256 + 128, np.asarray(y0) * 256 + 128",
     "px, py = np.asarray(y0) * 256 + 128, np.asarray(x0) * 256 + 128"),
)  # fmt: skip
BOTH = "you swapped x0 and y0, or read the vertices as (y, x): on this case the two give the same verdicts"  # fmt: skip


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize(("fn", "kind", "own"), [
    (READ_YX, "vertices read as (y, x)", "you read the vertices as (y, x): each row of xy"),
    (X0_Y0, "x0 and y0 swapped", "you swapped x0 and y0: x0 holds"),
], ids=["xy read as (y, x)", "x0 and y0 swapped"])  # fmt: skip
def test_hn3_the_axes_are_said_both_ways_where_both_give_the_answer(fn, kind, own, words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", fn, budget=120)
    assert not report.passed and _kinds(report) == {kind}, str(report)
    both = [f for f in report.failures if BOTH in f.explanation]
    alone = [f for f in report.failures if own in f.explanation]
    assert both and alone and len(both) + len(alone) == len(report.failures)
    for f in both:  # both causes give this case's answer
        args = next(c[1] for c in tile_blocks.block_cases() if c[0] == f.case)
        swapped = tile_blocks.classify_with(*args, points="x0 y0 swapped")
        assert np.array_equal(swapped, tile_blocks._read_yx(*args)), f.case
    for f in alone:  # a tie on a sloped edge tells them apart
        args = next(c[1] for c in tile_blocks.block_cases() if c[0] == f.case)
        swapped = tile_blocks.classify_with(*args, points="x0 y0 swapped")
        assert not np.array_equal(swapped, tile_blocks._read_yx(*args)), f.case


def test_hn4_82_row_and_column_are_said_both_ways_and_always_agree():
    """8.2's bound and the tile's farthest depth are the same mirrored about the diagonal: the
    vertices read as (y, x, depth) and row0/col0 swapped give the same verdict on every case."""
    for label, (xyz, row0, col0, size, buffer), _ in hiz_tile.hiz_cases():
        swapped = hiz_tile.lower_bound(xyz, col0, row0, size) >= np.max(buffer)
        read_yx = hiz_tile.lower_bound(xyz[:, [1, 0, 2]], row0, col0, size) >= np.max(buffer)
        assert swapped == read_yx, label
    yxz = _hiz_variant(("= np.asarray(xyz, dtype=float)", "= np.asarray(xyz, dtype=float)[:, [1, 0, 2]]"))  # fmt: skip
    report = ex.check("hiz_rejects", yxz, budget=120)
    assert not report.passed and _kinds(report) == {"row col swapped"}, str(report)
    for f in report.failures:
        assert "you swapped the tile's row and column, or read each vertex as (y, x, depth)" in f.explanation  # fmt: skip
        assert "the check cannot tell which" in f.explanation


# -- wrongly passed 2: round() half to even for 8.2's box -----------------------------------------

_ROUND = (
    ("np.ceil(min(x1, x2, x3) - 0.5)", "round(min(x1, x2, x3))"),
    ("np.floor(max(x1, x2, x3) - 0.5)", "round(max(x1, x2, x3)) - 1"),
    ("np.ceil(min(y1, y2, y3) - 0.5)", "round(min(y1, y2, y3))"),
    ("np.floor(max(y1, y2, y3) - 0.5)", "round(max(y1, y2, y3)) - 1"),
)


def test_wp2_the_odd_borders_are_holes_for_round():
    """Both cases: the box's left (top) side at 3.5, where round() gives 4; the renderer covers
    centres of column (row) 3 at depth 0.1, in front of the stored 0.13: kept, a hole if not."""
    cases = [c for c in hiz_tile.hiz_cases() if "pixel centres x = 3.5" in c[0] or "pixel centres y = 3.5" in c[0]]  # fmt: skip
    assert len(cases) == 2
    for axis, (label, (xyz, _, _, _, buffer), rejected) in enumerate(cases):
        assert not rejected and round(float(xyz[:, axis].min())) == 4
        fill = tr.rasterize(tr.Triangle(xyz[:, :2], z=xyz[:, 2]), 8, 8)
        line = fill.depth[:, 3] if axis == 0 else fill.depth[3, :]
        assert np.nanmin(line) < buffer.max(), label


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("how", ["round", "np.round"])
def test_wp2_round_half_to_even_fails_and_is_named(how, words, request):
    request.getfixturevalue(words)
    fn = _hiz_variant(*[(old, new.replace("round(", f"{how}(", 1)) for old, new in _ROUND])
    report = ex.check("hiz_rejects", fn, budget=120)
    assert not report.passed and len(report.failures) == 2, str(report)
    assert _kinds(report) == {"round half even"}, str(report)
    said = " ".join(f.explanation for f in report.failures)
    assert "here xmin = 3.5 and round gives 4, skipping column 3" in said
    assert "here ymin = 3.5 and round gives 4, skipping row 3" in said
    assert ("⌈xmin − ½⌉" in said) == (words == "full_words")


def test_wp2_earlier_border_mistakes_keep_their_names():
    floor_half = _hiz_variant(
        ("np.ceil(min(x1, x2, x3) - 0.5)", "np.floor(min(x1, x2, x3) + 0.5)"),
        ("np.ceil(min(y1, y2, y3) - 0.5)", "np.floor(min(y1, y2, y3) + 0.5)"),
    )
    assert _kinds(ex.check("hiz_rejects", floor_half, budget=120)) == {"border low"}
    assert ex.check("hiz_rejects", _hiz_variant(), budget=120).passed


# -- C2, S2: 8.2's lines quote the case, cause first ---------------------------------------------


def test_c2_every_82_failure_quotes_arguments_that_rerun_it(first_words):  # noqa: F811
    """The quoted xyz, row0, col0, size and buffer, run as Python, are the case's own (a buffer
    of random depths is said by its range and its farthest pixel)."""
    whole_tile = _hiz_variant(
        ("c_lo = max(col0, np.ceil(min(x1, x2, x3) - 0.5))", "c_lo = col0"),
        ("c_hi = min(col0 + size - 1, np.floor(max(x1, x2, x3) - 0.5))", "c_hi = col0 + size - 1"),
        ("r_lo = max(row0, np.ceil(min(y1, y2, y3) - 0.5))", "r_lo = row0"),
        ("r_hi = min(row0 + size - 1, np.floor(max(y1, y2, y3) - 0.5))", "r_hi = row0 + size - 1"),
    )
    report = ex.check("hiz_rejects", whole_tile, budget=120)
    assert len(report.failures) >= 10
    cases = {c[0]: c[1] for c in hiz_tile.hiz_cases()}
    for f in report.failures:
        xyz, row0, col0, size, buffer = cases[f.case]
        # r248 S1: statements separated by ";", runnable as one line
        head = re.match(r"(xyz = np\.array\(.*?\); row0 = -?\d+; col0 = -?\d+; size = \d+); (buffer.*?); the ", f.explanation)  # fmt: skip
        assert head, f.explanation[:300]
        space = {"np": np}
        exec(head[1], space)  # noqa: S102 - the checker's own words
        assert np.array_equal(space["xyz"], xyz) and (space["row0"], space["col0"], space["size"]) == (row0, col0, size)  # fmt: skip
        if head[2].startswith("buffer ="):
            exec(head[2], space)  # noqa: S102
            assert np.array_equal(space["buffer"], buffer), f.case
        else:
            assert "the farthest buffer[" in head[2] and repr(float(buffer.max())) in head[2]
        # S2: from the stored depth straight to the verdicts and the cause
        assert "decides (what is it here?)" not in f.explanation


# -- S1: cell 5 states the bound -------------------------------------------------------------------


def test_s1_cell_5_states_the_bound_and_asks_the_why():
    task = flat(_cell("hiz_rejects_task"))
    # r376 (fixex08a): the bound is no longer spelled out (the task's reasoning); the facts are
    assert ("**The bound asked** is the one that this fact and lesson 10's two give together for "
            "a few numbers per tile, with no coverage test.") in task  # fmt: skip
    main = task.split("<details>")[0]
    assert main.count("?") >= 4
    assert "Looser safe bounds are named, not taken" not in task


# -- FIG1: no figure before an answer; no blank band ---------------------------------------------


def _show():
    """Cell 1's ``show`` and ``compare``, as the notebook defines them."""
    code = _cell("setup").replace("%matplotlib inline\n", "")
    code = code.replace("style = use_style", "style = None and use_style")
    space: dict = {}
    exec(code.split("print(integer_budget())")[0], space)  # noqa: S102 - the notebook's own cell
    return space["show"]


@pytest.fixture
def shown(plt, monkeypatch):  # noqa: F811
    """The figures ``show`` hands to ``plt.show``, whatever the backend's show does with them
    (an inline backend left by another test closes them: the figure count read 0 in CI)."""
    figures = []
    monkeypatch.setattr(plt, "show", lambda *a, **k: figures.append(plt.gcf()))
    return figures


def _stub(*args):
    raise NotImplementedError()


@pytest.mark.parametrize("fn", [_stub, lambda *a: None], ids=["raise", "pass"])
@pytest.mark.parametrize("name", ["classify_block", "hiz_rejects"])
def test_fig1_one_line_until_the_function_answers(plt, shown, name, fn):  # noqa: F811
    """The stub's 9 × 8 in (and 9 × 5.6 in) figures of empty frames are one line now (one figure
    still: every graded check shows one, tests/test_nbgrader.py)."""
    plt.close("all")
    _show()(ex.check(name, fn, budget=60))
    (figure,) = shown
    assert tuple(figure.get_size_inches()) == (9.0, 0.35)
    (text,) = figure.axes[0].texts
    assert text.get_text().startswith(f"{name}: ") and "once your function returns answers" in text.get_text()  # fmt: skip


@pytest.mark.parametrize(("fn", "height"), [(NO_ACCEPT_BIAS, 3.3 + 4.5), (_variant(), 3.3 + 3.0)],
                         ids=["a pixel differs", "passing"])  # fmt: skip
def test_fig1_each_part_as_tall_as_what_it_draws(plt, shown, first_words, fn, height):  # noqa: F811
    """r232 FIG1: a 9 × 8 in figure left a band of ~110 px between the case and the scene; the
    scene's part is now as tall as its panels, key and (where a pixel differs) explanation."""
    plt.close("all")
    _show()(ex.check("classify_block", fn, budget=120))
    (figure,) = shown
    assert figure.get_size_inches()[1] == pytest.approx(height)
    top, bottom = figure.subfigs
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    case = top.axes[0].get_tightbbox(renderer)
    panels = [ax.get_tightbbox(renderer) for ax in bottom.axes]
    band = case.y0 - max(b.y1 for b in panels)  # display units: y up
    assert band < 0.45 * figure.dpi, band  # under half an inch (it was about 1.1 in)


# -- FIG2: 8.2's stored depths and vertex depths ------------------------------------------------


def test_fig2_a_uniform_tile_has_no_colour_bar_and_says_its_depth(plt):  # noqa: F811
    case = next(c for c in hiz_tile.hiz_cases() if c[0].startswith("a small triangle in the tile's bottom-right"))  # fmt: skip
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    hiz_tile.draw_hiz(ax, case, not case[2])
    assert len(fig.axes) == 1  # no colour bar (the inset is a child of the main axes)
    keys = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "stored depth 0.305, every pixel" in keys
    # each vertex in view labelled at its vertex in the main panel, none again in the inset
    xyz = case[1][0]
    labels = {t.get_text(): t.xy for t in ax.texts if t.get_text().startswith("v")}
    assert labels == {f"v{k + 1}: {hiz_tile.num(z)}": (x, y) for k, (x, y, z) in enumerate(xyz)}
    assert not ax.child_axes[0].texts


def test_fig2_a_varied_tile_is_coloured_over_its_range_and_its_farthest_pixel_marked(plt):  # noqa: F811
    case = next(c for c in hiz_tile.hiz_cases() if c[0] == "random 2")
    buffer = case[1][4]
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    hiz_tile.draw_hiz(ax, case, not case[2])
    image = ax.images[0]
    assert image.get_clim() == (buffer.min(), buffer.max()) and len(fig.axes) == 2
    keys = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "the farthest stored depth" in keys
    # the vertices lie beyond the view: their depths in the inset, beside a dot at each
    inset = ax.child_axes[0]
    assert len(inset.texts) == 3 and len([ln for ln in inset.lines if ln.get_marker() == "o"]) == 3


def test_the_numbers_the_cells_print_are_the_ones_they_quote():
    said = tile_blocks.integer_budget()
    lo, hi = (float(v.replace(",", "")) for v in re.search(r"x, y = (\S+) … (\S+) px", said).groups())  # fmt: skip
    span = hi - lo
    d = math.ceil(math.log2(256 * span))
    assert f"2·{d} + 2 = {2 * d + 2} bits" in said and 2 * d + 2 <= 64
    assert "print(integer_budget())" in _cell("setup")
    tries.forget_hints("classify_block")
