"""Review r345 of lesson 12a (lines), with r280's open items.

M1: the ties table had no llvmpipe column, and the reader, drawing with ``gl_lines`` as it
stands (GL's window y = the lesson's y), saw llvmpipe light row 0 on the horizontal tie where
the table's GL column says "lower row". Both are GL 4.6 §14.5.1's rule: the table's frame is
the picture shown on GL's screen the same way up (y_GL = h - y), where GL and llvmpipe light
the lower row; unmirrored they light row 0, as Vulkan does. The llvmpipe column is measured.
C1: the DDA's drift grows with |y|; screen lines drift more than the long line, and say why.
P1: cell 6's comment gave q_tie away. FIG1/FIG2: the drift plot's marks, q_smooth's square
pixel and its reveal. M2: a line drawn backwards, printed.
"""

from __future__ import annotations

import json
import re
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from explorables_node import call_js
from notebook_runs import lesson

pytestmark = [pytest.mark.filterwarnings("ignore::DeprecationWarning"), pytest.mark.notebook]
NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "12a_lines.ipynb"


def _source(cell_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return "".join(next(c for c in cells if c.get("id") == cell_id)["source"])


def _flat(cell_id: str) -> str:
    return re.sub(r"\s+", " ", _source(cell_id))


@pytest.fixture(scope="module")
def ns():
    return lesson("12a_lines")


def test_ties_table_llvmpipe_column_is_measured(ns):
    """M1: each word of the llvmpipe column is the row (column) llvmpipe lit, drawn as the
    picture stands on GL's screen; it is GL's pixel at all four ties, and unmirrored GL's
    rule and llvmpipe both light row 0 of the horizontal line."""
    if not ns.llvm_ok:
        pytest.skip("no OpenGL context: llvmpipe not measured")
    text = _source("tiestable")
    rows = [r.split("|")[2:-1] for r in text.splitlines() if r.startswith(("| x-", "| horiz"))]
    tie_y = {"dy/dx > 0": 1, "dy/dx < 0": 4, "horizontal on y = 1": 1}
    assert "| llvmpipe (measured) |" in text and len(rows) == 3
    for (name, y), cells in zip(tie_y.items(), rows, strict=True):
        said = y - 1 if "upper" in cells[3] else y if "lower" in cells[3] else None
        assert [said] == ns.llvm_rows[name] == ns.tie_rows[name][1], name  # GL's row
    (steep,) = [r.split("|")[2:-1] for r in text.splitlines() if r.startswith("| y-major")]
    assert "left" in steep[3] and ns.steep_llvm == ns.steep_cols[1] == [0]
    assert ns.flat_unmirrored == ns.flat_rows == [0]
    flat = " ".join(text.split())
    assert "llvmpipe lights GL's pixel at all four ties" in flat
    assert "(derived from the specifications: llvmpipe ignores" not in flat
    assert "parts GL from Vulkan on screen, not in memory" in flat
    assert "at §1's four ties it lights GL's pixel" in _flat("linetbl")


def test_dda_drift_grows_with_y_and_the_text_says_so(ns):
    """C1: the screen lines' drift (0.055 px) is 43 times the long line's lead, because float32's
    spacing at y ~ 900 is 512 times that between 1 and 2; the bound printed holds."""
    assert round(ns.drift, 3) == 0.055 and round(ns.drift / ns.dda_lead) == 43
    assert ns.sp_here / ns.sp_long == 512 and ns.drift <= ns.bound
    assert "a drift that small" not in _flat("7c91d88d")
    assert "a line of screen size at $y$ in the hundreds drifts far more" in _flat("7c91d88d")
    assert "larger than on the long line of the question, not smaller" in _flat("dda_screen_md")


def test_tie_cell_comment_does_not_answer_q_tie(ns):
    """P1: cell 6 is visible under q_tie; its code no longer says which diamond wins."""
    code = _source("9d36d56c")
    assert "top vertex" not in code and "bottom vertex" not in code
    assert [tuple(p) for p in ns.tie_xy] == [(1.5, 1.0), (3.5, 2.0), (5.5, 3.0), (7.5, 4.0)]


def test_line_direction_printed(ns):
    """M2 (r280 M1): §1's line backwards lights (4, 8) instead of (0, 0), its ties' pixels the
    same; §2's line backwards: Bresenham and the diamond rule agree."""
    assert ns.rev_only == [(4, 8)] and ns.fwd_only == [(0, 0)] and ns.rev_ties_kept
    assert len(ns.rev_differ) == 0 and len(ns.differ) == 2
    assert "depends on the line's direction" not in _flat("db845d96")
    # r464 S2: the clause split into sentences
    assert "Drawn backwards, §2's line lights the same pixels under both rules" in _flat("db845d96")


def test_drift_plot_marks_y_1_y_2_and_the_run():
    """FIG1: the plot marks where the sum crosses y = 1 and 2, and names the run's count."""
    code = _source("1ef67203")
    assert 'f"sum at y = {y_mark}"' in code and 'f"{dda_run} columns in row 2"' in code


def test_q_smooth_pixel_square_and_reveal_clear_of_the_outline(ns):
    """FIG2: equal aspect (one scale in x and y); the reveal draws the rectangle's upper edge
    through the answer; "the answer" stays off the pixel's outline wherever the marker is."""
    import matplotlib.pyplot as plt

    import teachraster as tr
    from teachraster.core.lines import wide_line_triangles
    from teachraster.study.antialiasing import pixel_area
    from teachraster.widgets import PredictPoint

    scope = {**vars(ns), "np": np, "plt": plt, "tr": tr, "Fraction": Fraction,
             "PredictPoint": PredictPoint,
             "pixel_area": pixel_area, "wide_line_triangles": wide_line_triangles}  # fmt: skip
    exec(_source("smoothq"), scope)
    q = scope["q_smooth"]
    x0, y0, sx, sy = q.data["transform"]
    assert sx == pytest.approx(sy, rel=0.01) and q.data["size"][0] <= 940
    curve = q._reveal["revealCurve"]
    (x_a, y_a), (x_b, y_b) = curve
    at = y_a + (q.answer[0] - x_a) * (y_b - y_a) / (x_b - x_a)
    assert at == pytest.approx(q.answer[1])  # the edge runs through the answer

    def px(p):
        return [x0 + sx * p[0], y0 + sy * p[1]]

    lines = [[px(a), px(b)] for a, b in call_js(("predict_figure",),
                                                [("labelLines", [q.data, curve])])[0]]  # fmt: skip
    truth, h = px(q.answer), q.data["size"][1]
    mines = [px((q.answer[0], y)) for y in np.linspace(ns.sm_row, ns.sm_row + 1, 21)]
    places = call_js(("predict_figure",), [("answerLabel", [m, truth, None, h, lines])
                                           for m in mines])  # fmt: skip
    boxes = call_js(("predict_figure",), [("labelBox", [p]) for p in places])
    outline = [[px(a), px(b)] for a, b in q.data["keepClear"]]
    for box in boxes:
        for a, b in outline:
            for t in np.linspace(0, 1, 41):
                x, y = a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])
                assert not (box["x0"] <= x <= box["x1"] and box["y0"] <= y <= box["y1"]), box
    q.close()


def test_attribute_plot_and_llvmpipe_wide_line(ns):
    """S6: §6 plots f against q (the figure fits the column). S7 (r280 S6): llvmpipe's own
    4 px line is measured against the parallelogram panel: equal, as the table says."""
    from notebook_runs import executed

    (fig,) = [f for f in executed("12a_lines").probe["figures"]
              if f["titles"] == ["f along the line, far end at w = 4"]]  # fmt: skip
    assert round(fig["width"]) <= 940
    assert "then plots them against $q$" in _flat("perspmd")
    assert "(none where measured)" in _flat("widetbl")
    if not ns.wide_gl_ok:
        pytest.skip("no OpenGL context: llvmpipe's wide line not measured")
    assert int(ns.llvm_wide.sum()) == int(ns.gl_shape.sum()) == 40
    assert not (ns.llvm_wide != ns.gl_shape).any()
