"""Lesson 01, review r265: each test fails on the lesson before the fix.

C1: the float error's size, as printed; P2: q_row on the mirrored triangle, whose middle
vertex's pixel is filled; M1/M2: the fill-rule table and the exercise; P1: q_fail a number on
a 0-200 line; FIG1-FIG3: the prestep's changed pixels, the crack explorer's marks at 32 x 32,
the player's vertex tags.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "01_span_tables.ipynb"


def _cells() -> list[dict]:
    return json.loads(NOTEBOOK.read_text())["cells"]


def _source(cell_id: str) -> str:
    return " ".join("".join(next(c for c in _cells() if c.get("id") == cell_id)["source"]).split())


@pytest.mark.notebook
def test_c1_the_float_error_keeps_its_sign_but_not_its_size():
    """Cell 26 said the float error "grows" down the edge; the table shrinks on row 6."""
    ns = lesson("01_span_tables")
    assert ns.float_signs == {1} and ns.float_peak == 5
    assert abs(ns.float_off[6]) < abs(ns.float_off[5])  # shrinks on row 6
    told = _source("dda_walk_text")
    assert "keeps its sign and grows" not in told
    assert "it grows to row 5 and shrinks on row 6" in told


@pytest.mark.notebook
def test_p2_q_row_needs_the_rule_at_the_middle_vertex():
    """q_row's new rows had empty answers, and row 9 repeated the worked row 5: clicking row 9
    alone passed. On the mirrored triangle row 9 starts at v2, a left end: its pixel is in."""
    import numpy as np

    ns = lesson("01_span_tables")
    (u2, v2) = ns.mirrored[1]
    assert ns.row_answer[int(v2), int(u2)] and ns.mirror_filled == [False, True, False]
    # "a vertex's pixel is never filled", true of the triangle as given, now misses one
    assert ns.vertex_filled == [False, False, False]
    guess = ns.row_answer.copy()
    guess[int(v2), int(u2)] = False
    assert not np.array_equal(guess, ns.row_answer)
    explain = " ".join(_source("ece0fd62").split("explain=")[1].split())
    assert "the first is v2's own" in explain and "<i>left</i> edges now" in explain
    assert "is v2 itself, where the two short edges meet" in explain


def test_m1_m2_the_rule_in_the_apis_and_the_exercise():
    """No fill-rule table where the lesson first applies the rule; no pointer to the exercise."""
    ids = [c.get("id") for c in _cells()]
    table = _source("c11-apis")
    assert ids.index("c11-apis") == ids.index("c11") + 1  # after q_row's last held cell
    for where in ("§14.6.1", "§3.4.2.1 *Top-Left Rule*", "§3.4.1 *Coordinate Snapping*",
                  "*Basic Polygon Rasterization*", "llvmpipe", "teachraster"):  # fmt: skip
        assert where in table, where
    assert "*are* Direct3D's top-left rule written for span tables" in table
    assert "left and top edges closed, right and bottom edges open" in table
    end = _source(ids[-1])
    assert "[exercises/02_span_split](exercises/02_span_split.ipynb)" in end
    assert (ROOT / "notebooks" / "exercises" / "02_span_split.ipynb").exists()


@pytest.mark.notebook
def test_p1_q_fail_is_a_count_on_a_line():
    """q_fail was a five-bucket choice ("21 to 100") where the census gives a number."""
    ns = lesson("01_span_tables")
    ask = _source("c19-q-fail")
    assert "q_fail = PredictPoint(" in ask and "PredictChoice(" not in ask
    assert "xlim=(0, n_random)" in ask and "along=((0, 0.5), (n_random, 0.5))" in ask
    assert "start=(0, 0.5)" in ask  # no count suggested
    assert ns.fail_point == (ns.n_float, 0.5) == (60, 0.5)
    assert round(ns.guess) == 59 and abs(ns.guess - 60) <= ns.fail_tolerance < 109 - 60
    ids = [c.get("id") for c in _cells()]
    held = _cells()[ids.index("c19-q-fail") + 1]
    assert "".join(held["source"]).startswith("q_fail.hold()")  # the count printed after it


def test_fig2_crack_marks_keep_their_screen_size_on_the_32_grid():
    """On 32 x 32 the canvas is wider than the column, which shrinks it: the tie squares, the
    marks and the key's icons were drawn at about 6 px. They grow as the type does now."""
    from explorables_node import call_js

    cracks = ("raster_rules", "explore_cracks")
    screen = {}
    for size in (16, 32):
        (g,) = call_js(cracks, [("panelLayout", [size, size])])  # the narrow column, 585 px
        (k,) = call_js(cracks, [("markScale", [g["width"]])])
        sizes = call_js(cracks, [("markPx", [g["cell"], "2", k]),
                                 ("markPx", [g["cell"], "⇄", k]), ("tieSize", [g["cell"], k])])  # fmt: skip
        screen[size] = [s * min(1.0, 585 / g["width"]) for s in sizes]
    assert screen[16] == [14, 16, 8]  # unchanged where the canvas fits
    for got, small in zip(screen[32], screen[16]):
        assert got >= 0.9 * small, (screen[32], screen[16])
    source = (ROOT / "teachraster/widgets/static/explore_cracks.js").read_text()
    assert "Math.round(16 * k)" in source.split("function drawKey(")[1]  # the key's icons too


@pytest.mark.notebook
def test_fig1_the_prestep_pixels_are_hatched_in_both_panels():
    """The 7 pixels the missing prestep changes were thin dashed outlines in one panel."""
    import inspect

    from teachraster.plotting import span_figures

    ns = lesson("01_span_tables")
    figure = _source("c5-prestep")
    assert figure.count("marked=pre_differ") == 2  # both panels
    assert ns.pre_gain == 7 == len(ns.pre_differ)  # all filled without the prestep
    drawing = inspect.getsource(span_figures.plot_span_ends)
    assert 'hatch="///"' in drawing and "ls=(0, (2, 1))" not in drawing
    assert "a pixel the two fills differ on" in figure  # keyed


def test_fig3_snap_tags_cross_no_edge_and_sit_by_their_vertex():
    """The player's step 0: "(18.5, 9.5)" cut the edge v3-v2, "(8.5, 17.5)" floated three
    columns from v1. Each tag's box now crosses no edge and lies within 3 px of its vertex."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    import teachraster as tr
    from teachraster.plotting import use_style
    from teachraster.widgets import FillPlayer

    triangles = {  # lessons 00, 01, 02 and 04's players
        "00": ([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]], 16, "span"),
        "01": ([[8.5, 17.5], [18.5, 9.5], [4.5, 1.5]], 20, "span"),
        "02": ([[2.25, 1.75], [14.5, 6.25], [5.75, 14.5]], 16, "halfplane"),
        "04": ([[1.5, 2.25], [14.75, 5.5], [4.25, 14.5]], 16, "halfplane"),
    }
    with plt.style.context("default"):
        use_style("classroom")
        for name, (xy, size, method) in triangles.items():
            p = FillPlayer(tr.Triangle(xy), size, size, method=method, backend="image")
            try:
                view = p.view
                view.show_step(0, draw=True)
                ax = view.ax
                inv = ax.transData.inverted()
                snapped = np.asarray(view.trace.snapped, dtype=float)
                t = np.linspace(0, 1, 400)[:, None]
                for tag, vertex in zip(view.setup_marks.coords, snapped):
                    box = (tag.get_bbox_patch() or tag).get_window_extent()  # r291: haloed, no box
                    (u0, v0), (u1, v1) = inv.transform([[box.x0, box.y0], [box.x1, box.y1]])
                    lo, hi = np.minimum([u0, v0], [u1, v1]), np.maximum([u0, v0], [u1, v1])
                    for k in range(3):
                        a, b = snapped[k], snapped[(k + 1) % 3]
                        pts = a + t * (b - a)
                        hit = ((pts >= lo) & (pts <= hi)).all(axis=1)
                        assert not hit.any(), (name, tag.get_text(), k)
                    gap = np.maximum(np.maximum(lo - vertex, vertex - hi), 0)
                    assert float(np.hypot(*gap)) < 3.0, (name, tag.get_text())
            finally:
                p.close()
                plt.close("all")
