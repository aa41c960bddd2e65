"""r198 (exercise 08_tiles): each finding with the reader's wrong answer (the notebook's solution
with one slip, as a student writes it) and the words or picture the check must give, and must not.

M1: a transposed result (``.T`` on the verdicts) was told a corner mistake on the square grids
and its shape only third, on a non-square one; any exercise's 2-D answer transposed is now named
so (:func:`.diagnosis.transposed_mistake`, :func:`.answers.transposed_shape_words`). B: three
8.1 slips were told only the rule: E₀ at (x0 + 1, y0 + 1), offsets ±(size − 1)(|A| + |B|), and
the second winding handled by a test of its own. C1: 8.2's case "a tile the triangle's bounding
box misses by 0.2 px" (the box starts inside the tile). Figures: C.1 the case panel cropped the
grid its title names; C.3 the scene's caption named the block twice, once as "(36, 20)" beside a
(row, col) pixel.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from graded_cells import graded_cell

# the fixtures of r149's tests: pyplot, the full words; r162's: the first try's words
from test_exercises_r149 import full_words, plt  # noqa: F401
from test_exercises_r162 import first_words  # noqa: F401

from teachraster import exercises as ex
from teachraster.exercises import answers, diagnosis, hiz_tile, tile_blocks, tries
from teachraster.exercises.running import WrongAnswerType

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"


def _cell(grade_id: str) -> str:
    return graded_cell(NOTEBOOK, grade_id)


def _solution_with(cell: str, name: str, edits) -> object:
    """Function ``name`` of the notebook's solution cell ``cell``, each (old, new) edit made
    once (a student's slip)."""
    source = _cell(cell)
    for old, new in edits:
        assert source.count(old) == 1, old
        source = source.replace(old, new)
    ns = {"np": np}
    exec(source, ns)
    return ns[name]


def _variant(*edits: tuple[str, str]):
    """The notebook's classify_block with each (old, new) edit made once (a student's slip)."""
    return _solution_with("classify_block_solution", "classify_block", edits)


RETURN = 'np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))'
TRANSPOSED = _variant((RETURN, f"{RETURN}.T"))
#: r198 B, the three slips once told only the rule ("every edge includes the block's four
#: corner centres"), with the kind each is now named by
SLIPS = {
    "E₀ at (x0 + 1, y0 + 1)": (
        _variant(
            ("* 256 + 128, np.asarray(y0) * 256 + 128", "* 256 + 256, np.asarray(y0) * 256 + 256")
        ),
        "pixels' bottom-right corners",
    ),
    "offsets ±(size − 1)(|A| + |B|)": (
        _variant(
            ("step * (max(A, 0) + max(B, 0))", "step * (abs(A) + abs(B))"),
            ("step * (min(A, 0) + min(B, 0))", "-step * (abs(A) + abs(B))"),
        ),
        "offsets both ways",
    ),
    "the reject test flipped for the other winding": (
        _variant(
            ("v = v[[0, 2, 1]]", "v = v"),
            ("rejected |= e0 + R < 0", "rejected |= (e0 + R < 0) if area > 0 else (e0 - T > 0)"),
        ),
        "counter-clockwise only",
    ),
}
#: words of the generic rule the slips were told, and must not be now
RULE_WORDS = ("includes the block's four corner centres", "at the pixel centre of the block where")


# -- M1: a transposed answer is named first, on every exercise with a 2-D answer ---------------


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_m1_transposed_verdicts_are_named_transposed_first(words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", TRANSPOSED, budget=120)
    assert report.failures
    first = report.shown()[0]
    assert first.kind == "transposed" and "your answer is transposed" in first.explanation
    for f in report.failures:
        assert "transposed" in f.explanation, f.explanation  # the square grids and the others
        assert not any(w in f.explanation for w in RULE_WORDS), f.explanation
    shaped = [f for f in report.failures if "verdicts of shape" in f.explanation]
    assert shaped and all("the expected shape reversed" in f.explanation for f in shaped)


def test_m1_the_transposed_test_is_the_exercises_and_says_nothing_of_symmetric_answers():
    e = np.array([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
    assert diagnosis._transposed_to(e, e.T) is True
    assert diagnosis._transposed_to(e, e.T[::-1]) is False  # transposed and flipped: another cause
    square = np.array([[1.0, 2.0], [3.0, 4.0]])
    assert diagnosis._transposed_to(square, square.T) is True
    assert diagnosis._transposed_to(square, square + 1) is False  # another cause
    assert diagnosis._transposed_to(np.eye(2), np.eye(2)) is None  # symmetric: no say
    assert diagnosis._transposed_to(np.arange(3.0), np.arange(3.0)[::-1]) is None  # 1-D
    mistake = diagnosis.transposed_mistake()
    assert mistake.only_whole and mistake.fits(None, square, square.T)


def test_m1_a_reversed_shape_is_called_transposed_by_the_shared_reader():
    with pytest.raises(WrongAnswerType, match="your answer is transposed"):
        answers.as_numbers(np.zeros((2, 3)), (3, 2), "a (3, 2) array")
    with pytest.raises(WrongAnswerType) as other:
        answers.as_numbers(np.zeros((2, 2)), (3, 2), "a (3, 2) array")
    assert "transposed" not in str(other.value)  # another shape: no such claim
    assert answers.transposed_shape_words((4, 4), (4, 4)) == ""


# -- B: the three slips once told the rule -----------------------------------------------------


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("name", list(SLIPS))
def test_b_the_slips_once_told_the_rule_are_named(name, words, request):
    request.getfixturevalue(words)
    _every_failure_named("classify_block", *SLIPS[name], RULE_WORDS)


def _every_failure_named(check: str, fn, kind: str, general: tuple) -> None:
    """Every failure of ``fn`` under ``check`` has ``kind`` and none of the ``general`` words."""
    report = ex.check(check, fn, budget=120)
    assert report.failures
    for f in report.failures:
        assert f.kind == kind, (f.case, f.kind, f.explanation)
        assert not any(w in f.explanation for w in general), f.explanation


def test_b_the_first_try_asks_what_the_full_words_say(first_words):  # noqa: F811
    """The first block's centre and which steps count are the task's question: asked on the
    first try, said once two answers have failed."""
    corner = ex.check("classify_block", SLIPS["E₀ at (x0 + 1, y0 + 1)"][0], budget=120)
    assert all("(x0 + ½, y0 + ½)" not in f.explanation for f in corner.failures)
    tries.forget_hints("classify_block")  # a fresh kernel: the second answer's first try
    both = ex.check("classify_block", SLIPS["offsets ±(size − 1)(|A| + |B|)"][0], budget=120)
    for f in both.failures:
        assert "A where A > 0" not in f.explanation
        assert "which steps raise E and which lower it?" in f.explanation


def test_b_the_full_words_give_the_numbers(full_words):  # noqa: F811
    corner = ex.check("classify_block", SLIPS["E₀ at (x0 + 1, y0 + 1)"][0], budget=120)
    f = corner.shown()[0]
    assert "bottom-right corners" in f.explanation and "(x0 + ½, y0 + ½)" in f.explanation
    both = ex.check("classify_block", SLIPS["offsets ±(size − 1)(|A| + |B|)"][0], budget=120)
    assert all("A where A > 0, B where B > 0" in f.explanation for f in both.failures)


def test_b_counter_clockwise_only_is_a_symptom_left_to_the_causes(full_words):  # noqa: F811
    """Edges as given (one winding only) keep their own words, though they too fail only
    counter-clockwise triangles; a clockwise failure is never told the winding."""
    one_winding = _variant(("v = v[[0, 2, 1]]", "v = v"))
    report = ex.check("classify_block", one_winding, budget=120)
    assert report.failures and all(f.kind != "counter-clockwise only" for f in report.failures)
    assert tile_blocks.CCW_ONLY.symptom and tile_blocks.CCW_ONLY.only_whole
    corners = ex.check("classify_block", SLIPS["E₀ at (x0 + 1, y0 + 1)"][0], budget=120)
    assert all(f.kind != "counter-clockwise only" for f in corners.failures)


def test_correct_answers_still_pass():
    assert ex.check("classify_block", _variant(), budget=120).passed


# -- C1: 8.2's label says what its box does -----------------------------------------------------


def test_c1_the_label_says_the_box_holds_no_centre_and_it_is_so():
    cases = {c[0]: c[1] for c in hiz_tile.HIZ_REJECTS.cases()}
    assert not any("misses by" in name for name in cases)
    name = next(n for n in cases if "holds no centre of the tile (it starts 0.2 px past" in n)
    xyz, row0, col0, size, _ = cases[name]
    start = float(np.asarray(xyz, float)[:, 0].min())
    last = col0 + size - 0.5  # the last column's centre
    assert last < start < col0 + size  # inside the tile, past its last centre
    assert start - last == pytest.approx(0.2)


# -- figures ------------------------------------------------------------------------------------


def test_c_figure_the_case_panel_shows_the_whole_small_grid_and_its_vertex(plt):  # noqa: F811
    case = next(c for c in tile_blocks.block_cases() if c[0].startswith("a block holding a vertex"))  # fmt: skip
    xy, gx, gy, size = case[1]
    got = np.array(case[2], dtype="<U8").copy()
    got.ravel()[1] = "rejected"  # the middle block differs
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    tile_blocks.draw_block_case(ax, case, got)
    (x_lo, x_hi), (y_hi, y_lo) = ax.get_xlim(), ax.get_ylim()
    assert x_lo <= np.min(gx) and x_hi >= np.max(gx) + size  # every block of the row
    assert y_lo <= np.min(gy) and y_hi >= np.max(gy) + size
    v1 = np.asarray(xy, float)[0]
    assert x_lo < v1[0] < x_hi and y_lo < v1[1] < y_hi  # the vertex the title names


def test_c_figure_a_wide_grid_is_still_zoomed_on_the_block_that_differs(plt):  # noqa: F811
    case = next(c for c in tile_blocks.block_cases() if np.size(c[1][1]) > 1
                and (np.ptp(c[1][1]) + c[1][3] > tile_blocks.SMALL_GRID))  # fmt: skip
    got = np.array(case[2], dtype="<U8").copy()
    got.ravel()[-1] = "partial" if got.ravel()[-1] != "partial" else "accepted"
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    tile_blocks.draw_block_case(ax, case, got)
    x_lo, x_hi = ax.get_xlim()
    assert x_hi - x_lo < np.ptp(case[1][1]) + case[1][3]


def test_c_figure_the_scene_caption_names_the_block_once_as_x0_y0():
    corner = _variant(("* 256 + 128, np.asarray(y0) * 256 + 128", "* 256, np.asarray(y0) * 256"))
    report = ex.check("classify_block", corner, budget=120)
    row, col = (int(v) for v in report.differing_pixels()[0])
    words = report.explain_pixel(row, col)
    assert "x0=" in words and "y0=" in words, words
    assert "of size" not in words and not words.startswith("block ("), words


# -- D.3, D.4: the task's text ------------------------------------------------------------------


def test_d3_no_caret_is_left_in_the_markdown():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    for cell in cells:
        if cell["cell_type"] == "markdown":
            text = "".join(cell["source"])
            assert "^" not in text.replace("$", ""), text[text.find("^") - 30 : text.find("^") + 30]


def _box(xy, row0, col0, size):
    return (
        max(col0, np.ceil(xy[:, 0].min() - 0.5)),
        min(col0 + size - 1, np.floor(xy[:, 0].max() - 0.5)),
        max(row0, np.ceil(xy[:, 1].min() - 0.5)),
        min(row0 + size - 1, np.floor(xy[:, 1].max() - 0.5)),
    )


def test_d4_snapping_changes_no_cases_box_as_82_says():
    task = " ".join(_cell("hiz_rejects_task").split())
    assert "snaps x and y to the 1/256 grid" in task and "no case's box gains or loses" in task
    moved = []
    for name, (xyz, row0, col0, size, _), _ in hiz_tile.HIZ_REJECTS.cases():
        xy = np.asarray(xyz, float)[:, :2]
        if _box(tile_blocks.snap(xy), row0, col0, size) != _box(xy, row0, col0, size):
            moved.append(name)
    assert not moved, moved


# -- B (8.2): two slips once told the rule -------------------------------------------------------


def _hiz_variant(*edits: tuple[str, str]):
    """The notebook's hiz_rejects with each (old, new) edit made once."""
    return _solution_with("hiz_rejects_solution", "hiz_rejects", edits)


HIZ_SLIPS = {
    "the plane at (c, r), the box right": (
        _hiz_variant(
            ("np.array([c_lo + 0.5, c_hi + 0.5])", "np.array([c_lo, c_hi])"),
            ("np.array([r_lo + 0.5, r_hi + 0.5])", "np.array([r_lo, r_hi])"),
        ),
        "plane at integer points",
    ),
    "dz/dy's sign slipped": (
        _hiz_variant(
            (
                "b = ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1))",
                "b = ((z2 - z1) * (x3 - x1) - (z3 - z1) * (x2 - x1))",
            ),
        ),
        "dz/dy sign",
    ),
}


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("name", list(HIZ_SLIPS))
def test_b_82_slips_once_told_the_rule_are_named(name, words, request):
    request.getfixturevalue(words)
    general = ("The block is rejected when the task's lower bound",)
    _every_failure_named("hiz_rejects", *HIZ_SLIPS[name], general)


def test_b_82_the_sign_words_quote_a_vertex_the_plane_misses(full_words):  # noqa: F811
    report = ex.check("hiz_rejects", HIZ_SLIPS["dz/dy's sign slipped"][0], budget=120)
    f = report.shown()[0]
    assert "dz/dy has the wrong sign" in f.explanation and "whose depth is" in f.explanation
    assert ex.check("hiz_rejects", _hiz_variant(), budget=120).passed


def test_d1_the_visible_task_stays_short():
    """r198 D.1: 762 visible words; r232 M1 replaced the folded float64 reach with a visible
    paragraph on counting in integers, and the task stayed within r214's limit."""
    import re

    task = _cell("classify_block_task")
    assert "How far float64 is exact" not in task
    visible = re.sub(r"<details>.*?</details>", "", task, flags=re.S)
    assert "**Count in integers**" in visible and len(visible.split()) < 600
