"""Review r168 of lesson 12a (lines), and the items of r160 it found partly or not fixed.

12a-1 (C): the joins cell's comment said 3 px where the code and text say 4. 12a-2: the
join/cap figure squeezed three 22 × 16 grids into 7.8 in; now the bend, cropped, in two
panels ("bevel", "miter") with the join's pixels crossed, and the whole line with its caps
on its own. 12a-3: ticks every 2 columns on cells 12 and 35. 12a-4: the lone DDA column
ringed. 12a-5: the LinePlayer's caption ran below its figure at the tie step. 12a-6: an end
point's label pushed off its dot gets a leader. q_dda: the spacings are the spacings, half of
one is the error. 12a-8: perspective-correct t along a line, printed. 12a-9: the clipping
cell asks llvmpipe. 12a-10, 11, 12: Direct3D 12's line modes, framebuffer limits,
Cohen–Sutherland's trivial accept and reject.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from explorables_node import call_js
from notebook_runs import executed, lesson

matplotlib.use("Agg")

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "12a_lines.ipynb"
LINES = ("raster_rules", "explore_lines")


def _source(cell_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return "".join(next(c for c in cells if c.get("id") == cell_id)["source"])


def _flat(cell_id: str) -> str:
    return " ".join(_source(cell_id).split())


@pytest.fixture(scope="module")
def ns():
    return lesson("12a_lines")


@pytest.mark.notebook
def test_joins_comment_figure_and_crop(ns):
    """12a-1, 12a-2: the comment says the width the code sets; two cropped panels titled on
    their own, holding every pixel a join adds, and the whole line apart, all in the column."""
    src = _source("joinsfig")
    assert "4 px wide bending at jb" in src and "3 px" not in src and ns.jw == 4.0
    figures = [f for f in executed("12a_lines").probe["figures"]
               if f["titles"][:2] == ["bevel", "miter"] or f["titles"] == ["miter and square caps"]]  # fmt: skip
    assert len(figures) == 2 and all(round(f["width"]) <= 940 for f in figures)
    x0, x1 = ns.crop_x
    y0, y1 = ns.crop_y
    assert x1 - x0 <= ns.JW / 2 and y1 - y0 <= ns.JH / 2  # at least twice the old pixel size
    for r, c in np.argwhere(ns.miter):  # the bevel's pixels are the miter's too
        assert x0 <= c and c + 1 <= x1 and y0 <= r and r + 1 <= y1
    text = _flat("widetbl")
    assert "the join's own pixels are crossed" in text and "whole polyline with square caps" in text


def _tick_step(ticks: int, width: int, height: int) -> int:
    import matplotlib.pyplot as plt

    from teachraster.plotting import plot_pixel_grid

    fig, ax = plt.subplots()
    plot_pixel_grid(ax, width, height, ticks=ticks)
    labels = [int(t) for t in ax.get_xticks()]
    plt.close(fig)
    return labels[1] - labels[0]


def test_ticks_every_other_column_where_pixels_are_read_off():
    """12a-3 (r160 item 8): cell 35's outlined pixel and cell 12's polyline are read off
    ticks every 2 columns, as cell 30's, not every 4."""
    for cell_id, width, height in (("polylinefig", 12, 6), ("smoothcell", 16, 10)):
        (ticks,) = re.findall(rf"plot_pixel_grid\(ax, {width}, {height}, ticks=(\d+)\)",
                              _source(cell_id))  # fmt: skip
        assert _tick_step(int(ticks), width, height) == 2, cell_id


@pytest.mark.notebook
def test_lone_dda_column_is_ringed_and_the_framebuffer_limits_named(ns):
    """12a-4 (r160 item 9), 12a-11 (r160 item 12)."""
    src = _source("1ef67203")
    assert "ax.plot(last_column, last_drift," in src and 'label="the lone column"' in src
    assert ns.last_column == 59_996
    text = _flat("7c91d88d")
    assert "16,384 pixels a side" in text and "32,768" in text and "ringed" in text


@pytest.mark.notebook
def test_dda_question_calls_the_powers_spacings_and_halves_them(ns):
    """q_dda: "half the spacing …: 2⁻²⁵" read as half-spacings gives 74.5 columns; the
    powers are the spacings, and each addition errs by half of one (37 columns)."""
    stem = _source("ddaq").split("q_dda = Predict(")[1].split("answer=")[0]
    stem = " ".join(stem.replace('"', "").split())
    assert "The spacing of float32 numbers is 2⁻²⁵ px between ¼ and ½" in stem
    assert "errs by at most half the spacing" in stem
    assert np.spacing(np.float32(0.3)) == 2.0**-25 and round(ns.dda_worst_run) == 37


def test_line_player_caption_stays_inside_its_figure():
    """12a-5: at the tie step (column 6, step 8) the diamond rule's caption has 5 lines; with
    the room fixed at CAPTION_ROOM the fifth fell below the figure. Every step of every rule
    now fits, and the axes box is the same for every rule."""
    from teachraster.plotting import use_style
    from teachraster.widgets.line_player import LinePlayer

    use_style("classroom")
    player = LinePlayer((0.5, 0.5), (12.5, 5.5), 14, 7, backend="image")
    renderer = player.fig.canvas.get_renderer()
    boxes, lines = set(), []
    for rule in ("diamond", "bresenham", "dda"):
        player.rule.value = rule
        boxes.add(tuple(np.round(player.view.image.axes.get_position().bounds, 6)))
        for k in range(len(player.trace)):
            player.show(k)
            caption = player.view.caption
            lines.append(caption.get_text().count("\n") + 1)
            caption.update_bbox_position_size(renderer)  # as a draw would
            box = caption.get_bbox_patch().get_window_extent(renderer)
            assert box.y0 >= 0, (rule, k, caption.get_text())
    assert max(lines) >= 5 and len(boxes) == 1
    player.close()


def test_end_point_label_pushed_off_its_dot_gets_a_leader():
    """12a-6 (r160 item 6): the first spot (right of and above the dot) needs none; a label
    a cell below the dot is joined to it, from the dot's edge to the label's box."""
    near, far = call_js(LINES, [("leaderLine", [[100, 100], [109, 91, 20, 15]]),
                                ("leaderLine", [[100, 100], [109, 142, 20, 15]])])  # fmt: skip
    assert near is None
    (ax, ay), (bx, by) = far
    assert np.hypot(ax - 100, ay - 100) == pytest.approx(7)
    assert np.hypot(bx - 109, by - 127) == pytest.approx(2)  # 2 px short of the box's corner


@pytest.mark.notebook
def test_perspective_correct_t_along_a_line_is_printed(ns):
    """12a-8: t per lit pixel, the screen's q against Ek's t = q z0 / (z1 − q (z1 − z0))
    (*Triangles and Perspective Correct Interpolation*, eq. 19), which rasterize_line gives."""
    assert ns.w_ends == (1.0, 4.0) and len(ns.persp_rows) == 8
    for r, c, q, t in ns.persp_rows:
        assert ns.persp[r, c] == pytest.approx(t) and t <= q
    assert ns.half[:2] == (2, 4) and round(ns.half[2], 3) == 0.521 and round(ns.half[3], 3) == 0.213
    printed = "".join(o.get("text", "") for c in executed("12a_lines").notebook().cells
                      if c.get("id") == "persp" for o in c.outputs)  # fmt: skip
    assert "(2, 4)        0.521    0.213" in printed and "f is only 0.213" in printed
    assert "eq. 19" in _flat("perspmd") and "Ek's note" in _flat("perspmd")


@pytest.mark.notebook
def test_clipping_cell_says_which_answer_llvmpipe_draws(ns):
    """12a-9: llvmpipe clips at the viewport and snaps the new end: at every pixel clipping
    changes it draws the clipped line's answer; its other departures are §5's kinds."""
    text = _flat("clipmd")
    assert "tilts the whole segment" in text and "which of the two answers a real driver" in text
    if not ns.gl_ok:
        pytest.skip("no OpenGL context")
    assert dict(ns.gl_sides) == {"clipped": ns.pixels_changed} == {"clipped": 8}
    assert (ns.gl_whole["clipped"], ns.gl_whole["as is"]) == (397, 393)
    assert "None" not in ns.gl_other and sum(ns.gl_other.values()) == 5


def test_standards_wording_d3d12_modes_and_cohen_sutherland():
    """12a-10, 12a-12."""
    assert "`LineRasterizationMode`" in _flat("widetbl") and "1.0 px quadrilaterals" in _flat(
        "widetbl"
    )
    text = _flat("clipmd")
    assert "whose two ends lie inside every plane" in text
    assert "whose two ends lie outside the same plane" in text
    assert "wholly outside a plane" not in text
