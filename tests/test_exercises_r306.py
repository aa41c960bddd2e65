"""r306 (exercise 04 read again): the figures and the quoted polygon; the misnamed and
half-named slips are corpus cases (``student_variants.R306``).

FIG1: the clip figure drew x against z + w only, so a polygon wrong in y lay on the expected
one; FIG2: an empty answer was drawn as nothing, unsaid; FIG3: a wrong depth verdict was a
small label on a bar coloured by the right one. S5: the expected polygon was quoted with the
vertex on the plane twice. F1: cell 5 put float32's lost digits in d_a − d_b, which never
cancels at a crossing.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from teachraster.exercises.depth_clipping import clip_cases, clip_with, explain_clip
from teachraster.exercises.drawing import draw_clip
from teachraster.exercises.zbuffer_pixel import WRONG_FRAME, depth_cases, draw_depth_passes

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "04_depth_and_clipping.ipynb"


def _texts(fig) -> str:
    return "\n".join(t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text")))


def test_the_clip_figure_draws_y_and_says_an_empty_answer(plt):
    v = np.array([[-1.0, -1, 1.8, 2], [1, -1, 1.8, 2], [0, 1, -2.2, -2]])
    expected = clip_with(v)
    wrong_y = expected.copy()
    wrong_y[2, 1] = -1.0  # right in x, z and w: only a y panel shows it
    fig, ax = plt.subplots()
    draw_clip(ax, v, expected, wrong_y)
    y_panel = next(a for a in ax.child_axes if a.get_xlabel().startswith("y"))
    yours = next(line for line in y_panel.get_lines() if line.get_label() == "yours")
    assert np.allclose(yours.get_xdata()[:-1], wrong_y[:, 1])
    fig, ax = plt.subplots()
    draw_clip(ax, v, expected, np.zeros((0, 4)))
    assert "yours: empty" in _texts(fig)


def test_a_wrong_depth_verdict_is_framed(plt):
    case = next(c for c in depth_cases() if c[0].startswith("a wall, glass in front"))
    got = np.array(case[2])
    got[2] = not got[2]
    fig, ax = plt.subplots()
    draw_depth_passes(ax, case, got)
    frames = [bar.get_edgecolor() for bar in ax.patches[:3]]
    framed = [f == plt.matplotlib.colors.to_rgba(WRONG_FRAME) for f in frames]
    assert framed == [False, False, True], frames
    assert "✗" in _texts(fig)


def test_the_expected_polygon_is_quoted_once_per_vertex():
    _, args, expected = next(c for c in clip_cases() if c[0].startswith("a vertex on the near"))
    said = explain_clip(args, expected, expected[::-1])
    # twice in the answer quoted (it keeps the repeat), once in the expected polygon
    assert said.count("(0, 0, -1, 1)") == 3 and "may also be given twice" in said


def test_cell_5_puts_float32_s_lost_digits_where_they_are_lost():
    cell = "".join(json.loads(NOTEBOOK.read_text())["cells"][5]["source"])
    assert "two distances nearly cancel" not in cell and "z and w nearly cancel" in cell
