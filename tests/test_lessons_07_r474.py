"""Lesson 07, review r474: each test fails on the lesson before the fix.

P1: q_sum asked which sums "did draw any pixel, in these 64 shifts": at a sum of 0 a stray centre
is possible by rounding, so the right option was decided by the 64 samples, not by the rule. It
asks now where the float32 form can draw more than a stray centre or two.
P2: only 2 of 7 predictions (q_gaps, q_behind) were answered on a figure, under issue 29's
third. q_flat asks the flat top's edge centres on its grid, before the figure that shows them:
the top edge's and the left edge's, v1 (top and left) drawn, v2 and v3 (each also on the
hypotenuse, a right edge) not.
S1: the relative float32 form is exact at 10⁶ px here because these vertices lie on float32's
1/16-px grid there; said beside the claim.
S2: Part 2 said "this section and lesson 02 give the rules"; it is lesson 02 §5b's
``biased_coverage`` turned to y up, and says so.
S3: the fan's counts in a table (tested in test_lessons_b's r145 fan test).
S4: the picker numbers columns on top, as the lesson's grids do.
S6: the far window's axis names at the title's size.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
from notebook_runs import executed, lesson

ROOT = Path(__file__).resolve().parent.parent
NAME = "07_hard_cases"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _cells() -> list[dict]:
    return json.loads(NOTEBOOK.read_text())["cells"]


def _sources() -> list[str]:
    return ["".join(c["source"]) for c in _cells()]


def test_a_third_of_the_predictions_are_answered_on_a_figure():
    asked = [m.group(1) for t in _sources() for m in re.finditer(r"\bq_\w+ = (Predict\w*)\(", t)]
    on_figure = [kind for kind in asked if kind in ("PredictPixels", "PredictPoint")]
    assert len(asked) == 8 and 3 * len(on_figure) >= len(asked), asked


def test_the_flat_top_is_asked_on_its_grid_before_the_figure_shows_it():
    cells, text = _cells(), _sources()
    ask = next(i for i, t in enumerate(text) if "q_flat = PredictPixels(" in t)
    held = next(i for i, t in enumerate(text) if t.startswith("q_flat.hold()"))
    assert held == ask + 1 and 'introduce("flat_top")' in text[held]
    assert cells[ask]["metadata"]["jupyter"]["source_hidden"]
    assert "hide-input" in cells[ask]["metadata"]["tags"]
    # the Markdown before the question no longer says what E > 0 drops
    before = " ".join(text[:ask])
    assert "drops the flat top's top row" not in before and "owns its row" not in before
    # the slivers' text and figure stay visible (r486 P1: the flat top opens §1, before the
    # split square, whose text would answer it; the slivers keep their place after the fan)
    slivers = next(i for i, t in enumerate(text) if t.startswith("**Two slivers**"))
    assert held < slivers and text[slivers + 1].startswith('case, ours = introduce("sliver_pair")')
    ns = lesson(NAME)  # (the widgets themselves are not kept: their inputs are)
    assert ns.flat_answer.sum() == 11 and ns.flat_cells == [[1, c] for c in range(1, 7)] + [
        [r, 1] for r in range(2, 7)
    ]
    # exactly the centres ours draws on an edge: the flat top's 21 less the 10 E > 0 draws
    assert int(ns.flat_ours.sum()) == 21 and int(ns.flat_naive.sum()) == 10
    assert not (ns.flat_naive & ~ns.flat_ours).any()
    assert ns.flat_kept == ["v1 (1, 1)"] and ns.flat_lost == ["v2 (1, 7)", "v3 (7, 1)"]
    assert (ns.flat_top_row, ns.flat_left_col) == (1, 1)
    assert (ns.flat_row_cols, ns.flat_col_rows) == ([1, 2, 3, 4, 5, 6], [2, 3, 4, 5, 6])
    ask_text = " ".join(text[ask].split()).replace('" "', "").replace('" f"', "")
    explain = ask_text.split("explain=")[1]
    for said in ("pixels: row {flat_top_row}, columns {min(flat_row_cols)} to",
                 "drawn only if both are top or left: {' and '.join(flat_kept)} is (top and",
                 "are not (each also on the hypotenuse). E > 0 loses all"):  # fmt: skip
        assert said in explain, said
    question = ask_text.split("q_flat = PredictPixels(")[1].split("answer=")[0]
    assert "v1 = ({:g}, {:g}), v2 = ({:g}, {:g}), v3 = ({:g}, {:g})" in question
    assert "flat_cells" not in question and "11" not in question


def test_q_sum_is_decided_by_the_rule():
    ns = lesson(NAME)
    (ask,) = [" ".join(t.split()) for t in _sources() if "q_sum = PredictChoice(" in t]
    assert "can it draw more than a stray centre or two?" in ask
    assert ns.sum_choices[2] == "+65,536 only"
    # the rule: at 0 the three E's sum to within esum_gap of 0, a region far under a pixel
    assert ns.esum_gap <= 2 and ns.esum_gap / ns.sum_exact < 0.02


def test_the_relative_form_is_exact_here_because_the_vertices_are_on_float32s_grid():
    ns = lesson(NAME)
    far = ns.far_tri + 1_000_000
    assert np.array_equal(far.astype(np.float32).astype(np.float64), far)
    assert float(np.spacing(np.float32(1_000_000))) == 1 / 16
    run = executed(NAME).notebook()
    (held,) = [c for c in run.cells if c.source.startswith("q_far.hold()")]
    told = " ".join(
        " ".join(o["data"]["text/markdown"] for o in held.outputs if "text/markdown" in o.get(
            "data", {})).split()
    )  # fmt: skip
    assert "these vertices lie on its 1/16-px grid at $10^6$ px" in told
    (ask,) = [" ".join(t.split()) for t in _sources() if "q_far = PredictChoice(" in t]
    assert "all right: these vertices lie on float32's 1/16-px grid there" in ask


def test_part_2_says_it_is_lesson_02s_biased_coverage_for_y_up():
    (turn,) = [" ".join(t.split()) for t in _sources() if t.startswith("**Part 2: every coverage")]
    assert "it is lesson 02 §5b's `biased_coverage` turned to $y$ up with Part 1's test" in turn
    assert "(this section and lesson 02 give the rules)" not in turn
    lesson02 = (ROOT / "notebooks" / "02_half_planes.ipynb").read_text()
    assert "def biased_coverage(" in lesson02


def test_the_far_windows_axis_names_are_the_titles_size():
    (cell,) = [t for t in _sources() if "column in the window (px)" in t]
    assert 'set_xlabel("column in the window (px)", fontsize=15)' in cell
    assert 'set_title(f"float32, shifted by' in cell and "fontsize=15)" in cell


def test_the_picker_numbers_columns_on_top_as_the_lesson_does():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.widgets.case_picker import TICKS_KEY, window_ticks

    fig, ax = plt.subplots()
    window_ticks(ax, 0, 8, 0, 8)
    assert ax.xaxis.get_ticks_position() == "top" and "columns (on top)" in TICKS_KEY
    plt.close(fig)
    helpers = next(t for t in _sources() if t.startswith("# The lesson's helpers"))
    assert "ax.xaxis.tick_top()" in helpers  # rc_ticks: the lesson's own grids
