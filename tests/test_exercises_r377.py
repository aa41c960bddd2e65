"""r377 (exercise 11 read again): the first culled triangle, unmatched by corners, passed
frame 2 (the redrawn cube kept each face's pair in order); frame 8's wall depth, read off the
intended frame as asked, was told "the other frame's value"; 11.3b's pane read off the broken
frame was told the unorm16 rule; eight wrong values were told only what they are not; frame
6's note said the sliver lies between the rows of centres; frame 1's note gave depths only;
the failing figure left its height empty and keyed the sliver at 5 pt; 11.8 and 11.9 did not
repeat the 30 s wait; 11.3b was a transcription (F4): it now asks the fewest depth bits in
which frame 3's pane would win wherever the wall lies. The slips are corpus cases too
(``student_variants.R377``)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
import reasoning_solutions as sol
from student_variants import KINDS, R377

from teachraster import exercises as ex
from teachraster.exercises import broken_frames as bf

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "11_broken_frames.ipynb"


def _cells():
    nb = json.loads(NOTEBOOK.read_text())
    return {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in nb["cells"]}


@pytest.mark.parametrize("label", sorted(R377))
def test_each_slip_is_named_by_its_record_in_the_first_explanation(label):
    name, fn, words, kind = R377[label]
    report = ex.check(name, fn)
    assert not report.passed, label
    first = report.failures[0]
    assert first.kind == kind == KINDS[label], (label, first.kind, first.explanation)
    assert words in first.explanation, (label, first.explanation)


def _first_culled(b, row, col):
    return next((r.triangle for r in b.frame.history(row, col).records
                 if r.outcome == "culled"), None)  # fmt: skip


def test_the_first_culled_triangle_fails_a_case_wherever_a_history_culls_two():
    """F1: 'the first culled triangle' was right in both cases at 439 of the 446 changed
    pixels where it was right in the frame shown. The redrawn cube lists its triangles
    backwards, so wherever the broken history culls two or more, one case fails it, in every
    look the check may draw; the reviewer's (24, 32) fails the redrawn frame."""
    shown = ex.broken_frame(2)
    for look in bf._REDRAWN:
        redrawn = bf._redrawn(2, look)
        for row, col in np.argwhere(bf._differs(shown))[::5]:
            row, col = int(row), int(col)
            culled = [r for r in shown.frame.history(row, col).records if r.outcome == "culled"]
            if len(culled) < 2:
                continue
            verdicts = [bf._judged_on(b, ("culled winding", (row, col), _first_culled(b, row, col)))[0]
                        for b in (shown, redrawn)]  # fmt: skip
            assert "right" not in verdicts or verdicts.count("right") == 1, (look, row, col)
    report = ex.check("broken_frame_2", lambda b: ("culled winding", (24, 32),
                                                   _first_culled(b, 24, 32)))  # fmt: skip
    assert [f.case for f in report.failures] == ["the frame redrawn"], str(report)
    assert ex.check("broken_frame_2", sol.diagnosis(2)).passed  # matched by corners: passes


def test_the_other_frame_is_said_only_where_the_named_history_lacks_the_value():
    """F2's rule, on every depth the two histories hold at frame 8's pixel: a value the
    intended frame's history (the one the sliver's depth is read from) holds is a record
    there, never 'the other frame's value'."""
    b = ex.broken_frame(8)
    thin = next(r.outside for r in b.frame.history(21, 39).records if r.triangle == 2)
    meant = {r.depth for r in b.intended.history(21, 39).records if np.isfinite(r.depth)}
    for r in b.frame.history(21, 39).records:
        if not np.isfinite(r.depth):
            continue
        verdict = bf._judged(8, ("sliver", (21, 39), (thin, r.depth)))[0]
        assert verdict == ("record" if r.depth in meant else "other"), (r.depth, verdict)


def test_a_triangle_number_under_a_depth_cause_is_quoted_as_a_whole_number():
    """F6e: W34's triangle 3 was quoted "3.0"."""
    report = ex.check("broken_frame_1", lambda b: ("culled winding", (24, 28), 3))
    assert "with triangle 3:" in report.failures[0].explanation, str(report)
    assert "3.0" not in report.failures[0].explanation


def test_the_sliver_notes_say_what_the_frames_show_and_frame_1s_how_it_was_made():
    """F6b: "between the rows of pixel centres" of a triangle across 13 rows; F6c: frame 1's
    note printed depths only. The numbers are computed from the thin triangle's corners."""
    for n in (6, 8):
        note = " ".join(ex.frame_note(n, ex.check(f"broken_frame_{n}", sol.diagnosis(n))).split())
        assert "between the rows" not in note, note
        frame = ex.broken_frame(n).frame
        xy = frame.trace.window[int(np.argmin(bf._altitudes(frame))), :, :2]
        rows = int(np.floor(xy[:, 1].max()) - np.floor(xy[:, 1].min())) + 1
        assert f"runs across {rows} rows of pixels" in note and rows > 10, note
        clear = float(re.search(r"centres, ([\d.]+) px or more from each", note)[1])
        tall = float(re.search(r"at most ([\d.]+) px tall", note)[1])
        assert 0 < clear < 0.5 and 0 < tall < 0.1 + 5e-4, note
        centres = np.arange(0.5, bf.H)  # no centre of the columns crossed lies in the triangle
        for x in np.arange(np.ceil(xy[:, 0].min() - 0.5), xy[:, 0].max() - 0.5) + 0.5:
            assert not any(_covers(xy, x, y) for y in centres), (n, x)
    note = ex.frame_note(1, ex.check("broken_frame_1", sol.diagnosis(1)))
    assert note.startswith("Frame 1 is not contrived") and "GL_GREATER" in note, note
    assert "frame 1 at (24, 28): in front (triangle 9) 0.039988" in note


def _covers(xy, x, y) -> bool:
    """Is (x, y) strictly inside the triangle ``xy``?"""
    e = [(b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
         for a, b in zip(xy, np.roll(xy, -1, axis=0), strict=True)]  # fmt: skip
    return all(v > 0 for v in e) or all(v < 0 for v in e)


def test_the_failing_figure_is_as_tall_as_its_pictures_and_keys_the_sliver_legibly():
    """F6a: a 7 x 3.1 in figure held the frames and the zoom in its middle third; the key was
    6 pt. The notebook's show() makes the figure as tall as the pictures at its width; the
    key is 0.7 of the classroom font and lies inside the figure, clear of the tick labels."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.plotting import use_style

    namespace = {}
    setup = _cells()["setup"].replace("%matplotlib inline", "")
    setup = setup.split("from teachraster.widgets")[0]
    with use_style("classroom"):
        exec(setup, namespace)
        shown = []
        namespace["plt"].show = lambda: shown.append(plt.gcf())
        report = ex.check("broken_frame_8", lambda b: ("sliver", (21, 39), (0.0566, 0.6)))
        namespace["show"](report)
        fig = shown[-1]
        try:
            fig.canvas.draw()
            ax = fig.axes[0]
            assert fig.get_figheight() < 3.0, fig.get_figheight()
            frames = ax.get_window_extent()
            assert frames.height / fig.bbox.height > 0.55, (frames, fig.bbox)
            key = ax.get_legend()
            assert key.get_texts()[0].get_fontsize() >= 0.7 * 18 - 1e-9
            box = key.get_window_extent()
            assert box.x1 <= fig.bbox.width + 1 and box.y0 >= 0, box
            for label in ax.get_xticklabels():
                assert not box.overlaps(label.get_window_extent()), label.get_text()
        finally:
            plt.close("all")


def test_frames_8_and_9_repeat_the_wait_for_a_wrong_cause():
    """F6d: only 11.7 said that a wrong cause waits from the first; W25 on frame 9 waited."""
    from teachraster.exercises import tries

    cells = _cells()
    for n in (8, 9):
        task = " ".join(cells[f"frame_{n}_task"].split())
        assert f"a check naming a wrong cause waits {tries.CAUSE_STEP:g} s" in task, task
        assert "until a check of this frame passes or the kernel restarts" in task, task


def test_11_3b_needs_the_drawn_depths_and_a_whole_step_and_its_figure_hides_the_answer():
    """F4: the question is answered from the trace's drawn depths (the histories print the
    pane tied at the wall's), by the whole-step reasoning of lesson 05b; the redrawn cases
    change the answer; the failing figure marks the student's n alone, never the curve whose
    crossing of the whole step is the answer."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.exercises import broken_frame_steps as bfs

    cases = bfs.BROKEN_FRAME_3_STEPS.cases()
    answers = [c[2] for c in cases]
    assert len(set(answers)) == len(answers) == 5, answers  # r388: a third redraw; r395 N1
    for _, (b,), bits in cases:
        gap = bfs._gap(b)
        assert gap * (2**bits - 1) > 1 >= gap * (2 ** (bits - 1) - 1), (gap, bits)
        tied = [r.depth for r in b.frame.history(*bfs.PIXEL).records if r.outcome != "not_covered"]
        assert len(set(tied)) == 1, tied  # the histories print the pane tied at the wall
    assert ex.check("broken_frame_3_steps", sol.broken_frame_3_steps).passed
    report = ex.check("broken_frame_3_steps", lambda b: 2 + sol.broken_frame_3_steps(b))
    fig, ax = plt.subplots()
    try:
        report.plot(ax)
        assert [len(line.get_xdata()) for line in ax.lines if line.get_marker() == "x"] == [1]
        assert all(len(line.get_xdata()) <= 2 for line in ax.lines), "a curve over n"
    finally:
        plt.close(fig)
