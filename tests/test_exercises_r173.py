"""r173 (exercise 08_tiles): each finding with the reader's wrong answer (written as a student
would) and the words or picture the check must give, and must not.

F1: "float64 holds these edge functions exactly" was true only near the origin: 7 of 300 ties
6·10^5 px out got a wrong verdict from the notebook's own solution (r232: it counts in
integers now). M1 (8.2): a box one column
(row) too wide on its low side was told "the tile's outer corners" and, on the first try, the
task's answer. M2: the box clipped to the tile but not rounded to centres was told, on a case
with centres in the box, that its box held none. G1: 8.2's figure drew where the bound is taken
on the first try. G2: the first words answered cell 5's question of the border. C: cell 2's
length, β given three times, "on screen", E in y-down form. D1: the wrongly covered pixels of
the scene barely visible, and not explained. D5: a failing check's traceback printed the
package's source and the report again.
"""

from __future__ import annotations

import math
import random
from pathlib import Path

import numpy as np
import pytest
from graded_cells import graded_cell

# the fixtures of r162's tests: a first try's words, the full words, pyplot
from test_exercises_r162 import _plane, first_words, full_words, plt  # noqa: F401

from teachraster import exercises as ex
from teachraster.exercises import hiz_tile, tile_blocks, tries
from teachraster.exercises.report import CheckFailed

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"


def _cell(grade_id: str) -> str:
    return graded_cell(NOTEBOOK, grade_id)


def _solution(grade_id: str):
    """The notebook's own solution, as the teacher's notebook defines it."""
    ns = {"np": np}
    exec(_cell(grade_id), ns)
    return ns[grade_id.removesuffix("_solution")]


# -- F1: float64 is exact within a reach, and the cell says so -------------------------------


def _egcd(a: int, b: int):
    if b == 0:
        return a, 1, 0
    g, x, y = _egcd(b, a % b)
    return g, y, x - (a // b) * y


def _ties(count: int, scale: float, out: tuple[float, float], seed: int = 3):
    """The reader's ties: an edge on the 1/256 grid ``scale`` px long whose E at a pixel centre
    ``out`` px from the origin is ±2^-16 px² exactly (extended Euclid), each a one-pixel block:
    (xy, x0, y0)."""
    rnd = random.Random(seed)
    made = []
    while len(made) < count:
        while True:
            dx = rnd.randint(int(scale * 128), int(scale * 256))
            dy = -rnd.randint(int(scale * 128), int(scale * 256))
            if math.gcd(dx, dy) == 1:
                break
        sign = rnd.choice([1, -1])
        _, s, t = _egcd(dx, -dy)  # dx·s − dy·t = 1: E = 1 unit at the centre
        v, u = s * sign, t * sign
        k = round(-(u * dx + v * dy) / (dx * dx + dy * dy) + 0.4)  # the centre mid-edge
        u, v = u + k * dx, v + k * dy
        p = np.array([math.floor(rnd.uniform(*out)) + 0.5, math.floor(rnd.uniform(*out)) + 0.5])
        a = p - np.array([u, v]) / 256
        b = a + np.array([dx, dy]) / 256
        n = np.array([-(b[1] - a[1]), b[0] - a[0]])
        c = np.round(((a + b) / 2 + n * 0.5) * 256) / 256
        xy = np.array([a, b, c])
        if np.abs(xy).max() >= 2**21:
            continue
        made.append((xy, np.array([int(p[0] - 0.5)]), np.array([int(p[1] - 0.5)])))
    return made


def _wrong(fn, ties) -> int:
    return sum(
        str(np.asarray(fn(xy, x0, y0, 1))[0])
        != str(np.asarray(tile_blocks.expected_block(xy, x0, y0, 1))[0])  # fmt: skip
        for xy, x0, y0 in ties
    )


def test_f1_the_readers_far_ties_are_exact_in_integers():
    """The reader's case: float64 misjudged some ties 6·10^5 px out. r232 M1: the notebook's
    solution now counts in lesson 10 §4's integer units and is right on all of them, far and
    near; the reader's own example too."""
    solution = _solution("classify_block_solution")
    assert "np.int64" in _cell("classify_block_solution")
    assert _wrong(solution, _ties(300, 6e5, (1e5, 5e5))) == 0
    assert _wrong(solution, _ties(300, 4e4, (2e4, 8e4), seed=5)) == 0
    xy = np.array([[-153507.19140625, 586460.484375], [416628.75390625, 69181.08203125],
                   [390200.484375, 612888.7578125]])  # fmt: skip
    x0, y0 = np.array([307363]), np.array([168316])
    assert str(tile_blocks.expected_block(xy, x0, y0, 1)[0]) == "rejected"
    assert str(np.asarray(solution(xy, x0, y0, 1))[0]) == "rejected"


def test_f1_the_bit_count_is_printed_and_the_cases_keep_to_it(monkeypatch):
    """r232 M1: cell 1 prints lesson 10 §4's bit count for the check's cases (the float64
    reach is gone with float64); a register too small for them is refused."""
    said = tile_blocks.integer_budget()
    assert "2·30 + 2 = 62 bits" in said and "int64 holds every value exactly" in said
    assert "print(integer_budget())" in _cell("setup") and "float64_reach" not in _cell("setup")
    task = " ".join(_cell("classify_block_task").split())
    # r248 C1: lesson 10 §4 counts on a GPU's grid (the walker keeps 512 units a pixel)
    assert "**Count in integers**, as lesson 10 §4 counts, on a GPU's grid" in task
    assert "exact in int64 (cell 1)" in task and "2¹⁷" not in task
    monkeypatch.setattr(tile_blocks, "INT_BITS", 32)
    with pytest.raises(AssertionError):
        tile_blocks.integer_budget()


# -- M1, M2, G2: 8.2's words ------------------------------------------------------------------


def box_bound(low_wide=False, clip_only=False, low_strict=False):
    """hiz_rejects as the reader wrote it: ``low_wide``: ⌈xmin − ½⌉ − 1 (one column and row
    too many on the box's low side, r173 M1); ``clip_only``: the box clipped to the tile's
    extreme centres, not rounded to centres (M2); ``low_strict``: ⌊xmin − ½⌋ + 1, the left
    and top border left out (G2)."""

    def hiz_rejects(xyz, row0, col0, size, buffer):
        p = np.asarray(xyz, float)
        lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
        if clip_only:
            xs = [max(col0 + 0.5, lo[0]), min(col0 + size - 0.5, hi[0])]
            ys = [max(row0 + 0.5, lo[1]), min(row0 + size - 0.5, hi[1])]
            if xs[0] > xs[1] or ys[0] > ys[1]:
                return True
        else:
            first = [np.floor(v - 0.5) + 1 if low_strict else np.ceil(v - 0.5) - low_wide for v in lo]  # fmt: skip
            c0, c1 = max(col0, first[0]), min(col0 + size - 1, np.floor(hi[0] - 0.5))
            r0, r1 = max(row0, first[1]), min(row0 + size - 1, np.floor(hi[1] - 0.5))
            if c0 > c1 or r0 > r1:
                return True
            xs, ys = [c0 + 0.5, c1 + 0.5], [r0 + 0.5, r1 + 0.5]
        f = _plane(p)
        return bool(max(min(f(x, y) for x in xs for y in ys), p[:, 2].min()) >= np.max(buffer))

    return hiz_rejects


def test_correct_answers_still_pass():
    for fn in (_solution("hiz_rejects_solution"), box_bound()):
        assert ex.check("hiz_rejects", fn, budget=120).passed
    assert ex.check("classify_block", _solution("classify_block_solution"), budget=120).passed


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_m1_a_box_one_column_wide_on_its_low_side_is_named_so(words, request):
    request.getfixturevalue(words)
    report = ex.check("hiz_rejects", box_bound(low_wide=True), budget=120)
    assert report.failures
    for f in report.failures:
        assert f.kind == "one before", (f.case, f.kind)
        assert "a column (or row) before the box's first" in f.explanation
        assert "outer corners" not in f.explanation
        # the task's answer is not given, on any try
        assert "extreme centres of the tile's part inside" not in f.explanation


def test_m1_the_outer_corner_words_ask_on_the_first_try(first_words):  # noqa: F811
    def tile_outer_corners(xyz, row0, col0, size, buffer):
        f = _plane(xyz)
        corners = [f(x, y) for x in (col0, col0 + size) for y in (row0, row0 + size)]
        return bool(max(min(corners), np.asarray(xyz, float)[:, 2].min()) >= np.max(buffer))

    report = ex.check("hiz_rejects", tile_outer_corners, budget=120)
    said = [f.explanation for f in report.failures if "the tile's outer corners" in f.explanation]
    assert said and not any("extreme centres of the tile's part" in s for s in said)


def test_m2_each_flaw_is_said_only_on_the_cases_it_decides(full_words):  # noqa: F811
    report = ex.check("hiz_rejects", box_bound(clip_only=True), budget=120)
    cases = {c[0]: c[1] for c in hiz_tile.HIZ_REJECTS.cases()}
    kinds = set()
    for f in report.failures:
        xyz, row0, col0, size, _ = cases[f.case]
        empty = hiz_tile._box_corners(xyz, row0, col0, size) is None
        kinds.add(empty)
        assert ("holds no centre of the tile" in f.explanation.split(": you")[-1]) == empty, f.explanation  # fmt: skip
        assert ("the bounding box's own corners" in f.explanation) != empty, f.explanation
    assert kinds == {True, False}  # both flaws show, each on its own cases


def test_g2_the_first_words_do_not_answer_which_border_centres(first_words):  # noqa: F811
    report = ex.check("hiz_rejects", box_bound(low_strict=True), budget=120)
    assert report.failures
    for f in report.failures:
        assert "left or top border" in f.explanation
        assert "on the box's left or top side the triangle can cover" not in f.explanation


# -- G1: the figure holds the site back ---------------------------------------------------------


def _keys(plt, case):  # noqa: F811
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    hiz_tile.draw_hiz(ax, case, not case[2])
    stars = [line for line in ax.lines if line.get_marker() == "*"]
    return stars, [t.get_text() for t in ax.get_legend().get_texts()]


def test_g1_the_first_figure_shows_the_box_and_centres_not_the_bound(plt, first_words):  # noqa: F811
    """On every case with a centre in the box: no star and no legend of where the bound is
    taken or of the nearest vertex until two answers have failed; the box and centres always."""
    cases = [c for c in hiz_tile.HIZ_REJECTS.cases() if hiz_tile.bound_site(*c[1][:4]) is not None]  # fmt: skip
    by_vertex = next(c for c in cases if hiz_tile.bound_site(*c[1][:4])[3])
    for case in (cases[0], by_vertex):
        stars, keys = _keys(plt, case)
        assert not stars and "pixel centres" in keys, keys
        assert not any("bound is taken" in k or "nearest vertex" in k for k in keys), keys
    tries.spend_hints(["hiz_rejects"])
    stars, keys = _keys(plt, by_vertex)
    assert len(stars) == 1 and any("no nearer than" in k for k in keys), keys


# -- C: cell 2 ----------------------------------------------------------------------------------


def test_c_llvmpipe_is_folded_after_the_verdicts_and_beta_is_asked_once():
    task = _cell("classify_block_task")
    verdicts = task.index("**The verdicts.**")
    folded = task.index("<details><summary>How llvmpipe does it")
    assert verdicts < folded < task.index("lp_setup_bin_triangle") < task.index("</details>", folded)  # fmt: skip
    # the fixed-point unit only in the folded paragraph; the hint no longer points at β
    assert task.index("in its fixed-point units") > folded
    assert "multiple of some power of ½" not in task
    assert task.count("which values can E take at a centre?") == 1
    # what a student reads before "The set-up": a few sentences, not Mesa's internals
    assert len(task[: task.index("**The set-up.**")].split()) < 180


def test_c_the_winding_is_on_screen_and_e_is_given_y_down():
    text = " ".join(_cell("classify_block_task").split())
    assert "counter-clockwise *on screen* (y pointing down)" in text
    assert "E(x, y) = (x₂ − x₁)·(y − y₁) − (y₂ − y₁)·(x − x₁)" in text
    assert "a *left* edge when it runs up the screen (y₂ < y₁)" in text
    # the formula and the tests it states are the package's: the notebook's own solution (its
    # A, B and top-left test) passes, and its form is the one written
    solution = _cell("classify_block_solution")
    assert "A, B = a[1] - b[1], b[0] - a[0]" in solution
    assert "top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])" in solution


# -- D1: the scene's wrongly covered pixels -------------------------------------------------------


def no_bias(xy, x0, y0, size):
    """The reader's W04: the top-left rule left out (β = 0 on every edge)."""
    v = np.asarray(xy, float)
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
        e0 = A * (px - a[0]) + B * (py - a[1])
        rejected |= e0 + (size - 1) * (max(A, 0) + max(B, 0)) < 0
        accepted &= e0 + (size - 1) * (min(A, 0) + min(B, 0)) >= 0
    return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))


def test_d1_the_wrongly_covered_pixels_are_ringed_and_explained(plt, first_words):  # noqa: F811
    report = ex.check("classify_block", no_bias, budget=120)
    wrong = report.scene.coverage_differs()
    assert 0 < wrong.sum() <= 40
    fig, axes = plt.subplots(1, 3)
    report.compare(axes, pixel="first")
    rings = [c for c in axes[2].collections if len(c.get_offsets())]
    assert len(rings) == 1
    rows, cols = np.nonzero(wrong)
    assert sorted(map(tuple, rings[0].get_offsets())) == sorted(zip(cols + 0.5, rows + 0.5))
    assert "ringed" in axes[2].get_title()
    assert max(map(len, axes[2].get_title().splitlines())) <= 25  # within its panel
    row, col = np.argwhere(wrong)[0]
    words = report.scene.explain(int(row), int(col))
    assert "yours fills this pixel, the package does not" in words
    assert f"its centre ({col + 0.5}, {row + 0.5}) lies exactly on edge" in words
    # a pixel both cover says nothing of the kind
    assert "fills this pixel" not in report.scene.explain(24, 24)


# -- D5: a failing check's error is one line ----------------------------------------------------


def test_d5_a_failing_check_raises_one_line_not_the_source():
    report = ex.check("hiz_rejects", box_bound(low_wide=True), budget=120)
    with pytest.raises(AssertionError) as caught:
        report.assert_passed()
    error = caught.value
    assert isinstance(error, CheckFailed) and type(error).__name__ == "AssertionError"
    message = str(error)
    assert "\n" not in message and message.startswith("hiz_rejects: 8 of ")  # r376: 72 cases
    assert "the report above says why" in message
    # IPython (JupyterLab, nbconvert) shows this instead of a traceback with report.py's source
    assert error._render_traceback_() == [f"AssertionError: {message}"]


def test_d5_the_not_counted_error_still_says_so():
    report = ex.check("hiz_rejects", hiz_tile.expected_reject, budget=120)
    with pytest.raises(AssertionError, match="not counted"):
        report.assert_passed()


def test_d5_the_capstone_raises_the_same_one_line_error():
    """One place for the rule: the capstone's scenes raise :class:`CheckFailed` too."""
    import inspect

    from teachraster.exercises import capstone_render

    source = inspect.getsource(capstone_render.CapstoneReport.assert_passed)
    assert "raise CheckFailed(" in source and "raise AssertionError(" not in source


def test_d5_failures_and_the_package_both_said_in_the_one_line():
    """A failing answer that also calls the package's own function: its one line says both."""
    report = ex.check("hiz_rejects", box_bound(low_wide=True), budget=120)
    object.__setattr__(report, "package", "it calls teachraster's expected_reject: does not count")
    with pytest.raises(AssertionError, match=r"8 of 72 cases fail; and not counted"):
        report.assert_passed()


# -- three answers that were told the rule only, now named ---------------------------------------


def hiz_variant(half=-0.5, last=1, vertex=True, whole=False):
    """hiz_rejects as the reader wrote three of them: ``half`` +0.5: the box's ½ the wrong way
    (⌈xmin + ½⌉ … ⌊xmax + ½⌋); ``last`` 2: the tile clamped at col0 + size − 2; ``whole`` and
    not ``vertex``: lesson 10's bound without the nearest vertex."""

    def hiz_rejects(xyz, row0, col0, size, buffer):
        p = np.asarray(xyz, float)
        lo, hi = p[:, :2].min(axis=0), p[:, :2].max(axis=0)
        if whole:
            c, r = (col0, col0 + size - 1), (row0, row0 + size - 1)
        else:
            c = (max(col0, math.ceil(lo[0] + half)), min(col0 + size - last, math.floor(hi[0] + half)))  # fmt: skip
            r = (max(row0, math.ceil(lo[1] + half)), min(row0 + size - last, math.floor(hi[1] + half)))  # fmt: skip
            if c[0] > c[1] or r[0] > r[1]:
                return True
        z = min(_plane(p)(x + 0.5, y + 0.5) for x in c for y in r)
        return bool((max(z, p[:, 2].min()) if vertex else z) >= np.max(buffer))

    return hiz_rejects


NAMED = {
    "the box's ½ the wrong way": (
        hiz_variant(half=0.5),
        "half shifted",
        "the box's ½ the wrong way",
    ),  # fmt: skip
    "the tile one column short": (
        hiz_variant(last=2),
        "one short of the tile",
        "one short of the tile's last",
    ),  # fmt: skip
    "lesson 10's bound, no vertex": (
        hiz_variant(vertex=False, whole=True),
        "whole tile, bare",
        "lesson 10's bound without the nearest vertex",
    ),  # fmt: skip
}


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("name", list(NAMED))
def test_answers_once_told_the_rule_are_named(name, words, request):
    request.getfixturevalue(words)
    fn, kind, said = NAMED[name]
    assert hiz_variant()(*hiz_tile.HIZ_REJECTS.cases()[0][1]) == hiz_tile.HIZ_REJECTS.cases()[0][2]
    report = ex.check("hiz_rejects", fn, budget=120)
    assert report.failures and {f.kind for f in report.failures} == {kind}
    for f in report.failures:
        assert said in f.explanation and "The block is rejected when" not in f.explanation
        assert "extreme centres of the tile's part inside" not in f.explanation


def test_the_reference_form_of_the_variants_passes():
    assert ex.check("hiz_rejects", hiz_variant(), budget=120).passed
