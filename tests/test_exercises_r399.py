"""r399 (exercise 11 read a fourth time): depths were judged to 2e-6, so frame 3's pane as the
broken frame draws it (0.599999, 1e-6 in front of the wall) was "the depth of another surface",
the wall's 0.600000 (F1), and depths 1e-6 or 1.5e-6 off passed (F4); the intended pane as drawn
(0.599, stored 0.598993) was told only what it is not (F2); 11.3b's first failure of a bit short
printed the closed form and its figure named the criterion (F5); the half-step margin was
named a step of 1/2ⁿ only (F3); the stub note of 11.1-11.9 promised the rule's answer (F6); the
docs said ≥ 1 where the rule is > 1 (F8). The slips are corpus cases too
(``student_variants.R399``)."""

from __future__ import annotations

from pathlib import Path

import pytest
import reasoning_solutions as sol
from student_variants import KINDS, R395, R399

from teachraster import exercises as ex
from teachraster.exercises import broken_frames as bf
from teachraster.exercises import tries
from teachraster.exercises.report import NOTHING_DRAWN_FOR

NAME = "broken_frame_3_steps"
DOCS = Path(__file__).parents[1] / "docs" / "exercises.md"


@pytest.mark.parametrize("label", sorted(R399))
def test_each_slip_fails_and_is_named_in_the_first_explanation(label):
    name, fn, words, kind = R399[label]
    report = ex.check(name, fn)
    assert not report.passed, label
    first = report.failures[0]
    assert first.kind == kind == KINDS[label], (label, first.kind, first.explanation)
    assert words in first.explanation, (label, first.explanation)
    assert "another surface" not in first.explanation, first.explanation


def test_depths_are_judged_to_half_the_sixth_decimal_below_the_frames_smallest_gap():
    """F1, F4: half a unit of the sixth decimal the history prints, below frame 3's 1e-6."""
    assert 5e-7 <= bf._TOLERANCE["depth"] < 5.0001e-7
    assert bf._TOLERANCE["pair"][1] == bf._TOLERANCE["depth"]
    assert not bf._matches("depth", 0.599999, [0.6])
    assert bf._matches("depth", round(0.5989929, 6), [0.5989929])
    assert ex.check("broken_frame_3", sol.diagnosis(3)).passed


def test_a_bit_short_keeps_the_closed_form_and_the_criterion_for_the_full_words():
    """F5: the first failure said "log₂(1 + 1/gap) rounded down?" and the axis "gap · (2ⁿ − 1)"."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    _, fn, _, _ = R399["frame 3 bits, log₂(1/gap) rounded down"]

    def said(report):
        fig, ax = plt.subplots()
        try:
            report.plot(ax)
            return str(report), ax.get_ylabel()
        finally:
            plt.close(fig)

    tries.forget_hints(NAME)
    try:
        words, axis = said(ex.check(NAME, fn))
        assert "log₂(1 + 1/gap)" not in words and "round up" in words, words
        assert "2ⁿ − 1" not in axis and "steps" in axis, axis
        said(ex.check(NAME, lambda b: sol.broken_frame_3_steps(b) + 3))
        words, axis = said(ex.check(NAME, fn))
        assert "(log₂(1 + 1/gap) rounded down?)" in words, words
        assert axis == "gap · (2ⁿ − 1)"
    finally:
        tries.forget_hints(NAME)


def test_the_half_step_margin_is_named_with_the_step_of_a_power_of_two():
    """F3: ceil(log₂(1/gap + ½)) gives what a step of 1/2ⁿ gives on every case."""
    name, fn, _, _ = R395["frame 3 bits, a half-step margin"]
    first = ex.check(name, fn).failures[0].explanation
    assert "a step of 1/2ⁿ?" in first and "a half-step margin, 2ⁿ − ½?" in first, first


def test_the_frames_stub_note_promises_the_frames_and_the_pixel_never_the_evidence():
    """F6: 11.1-11.9's note said the check draws "the rule's answer beside yours"."""
    for n in range(1, 10):
        note = NOTHING_DRAWN_FOR[f"broken_frame_{n}"]
        assert "rule's answer" not in note and "your pixel marked on both" in note, note


def test_the_docs_say_more_than_a_whole_step():
    """F8: the docs said gap · (2ⁿ − 1) ≥ 1; the rule is > 1 (r388 G6)."""
    row = next(line for line in DOCS.read_text().splitlines() if "broken_frame_3_steps" in line)
    assert "gap · (2ⁿ − 1) > 1" in row and "≥ 1" not in row, row


def test_the_inspector_charts_legend_stands_clear_of_the_buffer_markers():
    """F7: at frame 1's (24, 32), in the classroom style, the legend's lower edge lay on the
    "buffer before" circles at 0.042 (1.3 px above them): now 3 pt or more clear."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.plotting import use_style
    from teachraster.widgets import FrameInspector

    with use_style("classroom"):
        inspector = FrameInspector(
            frames=bf.frames_to_inspect(), pairs=bf.frame_pairs(), marks=bf.frame_marks()
        )
        try:
            inspector.scene.value = "frame 1"
            inspector.row.value, inspector.col.value = 24, 32
            fig, ax = inspector.hist_fig, inspector.hist_ax
            fig.canvas.draw()
            legend = ax.get_legend().get_window_extent()
            for line in ax.lines:
                if line.get_marker() not in ("o", "."):
                    continue
                radius = line.get_markersize() / 2 * fig.dpi / 72
                for x, y in zip(line.get_xdata(), line.get_ydata(), strict=True):
                    if y == y:  # not NaN
                        top = ax.transData.transform((x, y))[1] + radius
                        assert top + 3 * fig.dpi / 72 < legend.y0, (x, y, top, legend.y0)
        finally:
            plt.close(inspector.fig)
            plt.close(inspector.hist_fig)
