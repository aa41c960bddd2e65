"""Lesson 06, review r479: each test fails on the lesson before the fix.

M1: two of seven predictions were answered on a figure (issue 29: at least a third); q_span,
a typed cut, is now a drag of N = 8's worst miss beside N = 16's, revealed by the curve.
S1: cell 9's first held paragraph (221 words) argued three things at once; one each now.
S2: the span explorer's "< 0.01" tick label touched the "0.01" above it.
S3: q_depth's explanation said the facing pairs "need no more than float32's spacing".
S4: FRONT_TEXT listed the divides where N = 2 is off as "d = 1 and d = 2"; it is every d <= 3
(the widget also stops at 1.5 and 3). (Its test: test_lessons_b's r118 test.)
"""

from __future__ import annotations

import json
import re

import numpy as np
from notebook_runs import ROOT, lesson

NAME = "06_what_accuracy_costs"


def _cells() -> dict:
    nb = json.loads((ROOT / "notebooks" / f"{NAME}.ipynb").read_text())
    return {c.get("id"): "".join(c["source"]) for c in nb["cells"]}


def _asked(name: str, cell_id: str):
    """The question ``name`` built from its own cell, in the lesson's globals (the run keeps
    no widgets), as a student's kernel builds it."""
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap

    import teachraster as tr
    from teachraster.study import bench
    from teachraster.widgets import PredictPoint

    ns = lesson(NAME)
    by_name = {(r["group"], r["variant"]): r for r in ns.rows}
    scope = {**vars(ns), "tr": tr, "np": np, "plt": plt, "bench": bench,
             "PredictPoint": PredictPoint, "ListedColormap": ListedColormap,
             "row": lambda g, v: by_name[(g, v)]}  # fmt: skip
    exec(_cells()[cell_id], scope)
    return scope[name], scope


def test_m1_q_span_is_a_drag_on_a_figure_revealed_by_the_curve():
    from teachraster.widgets import PredictPoint

    q, ns_dict = _asked("q_span", "q06span")
    ns = lesson(NAME)
    assert isinstance(q, PredictPoint) and "q_span = PredictPoint(" in _cells()["q06span"]
    # the marker moves on the N = 8 line only, from N = 16's level (no cut yet)
    assert q.data["along"] == [[8.0, 0.0], [8.0, 12.0]]
    assert q.data["start"] == [8.0, ns.far[16].worst_px]
    assert q.given is None and q.correct is None  # Check waits for a drag
    assert list(q.answer) == [8.0, ns.far[8].worst_px]
    assert ns.far[16].worst_px / ns.far[8].worst_px == ns.cut100
    # the answer's curve is what the check reveals: the worst miss at N = 2 to 16, same r
    curve = dict(ns.span_curve)
    assert sorted(curve) == [2, 4, 8, 16] and curve[8] == ns.far[8].worst_px
    assert np.all(np.diff([curve[n] for n in sorted(curve)]) > 0)
    # right at the answer; wrong where the square law (4), the length alone (2) or r = 10's
    # cut (3.08) would put the marker
    q.given = (8, ns.far[8].worst_px + 0.3)
    assert q.correct is True
    # (r516: the floor's least cut, now measured exactly on screen, is 2.38, as near as
    # r = 100's own 2.36, so it is no longer a wrong answer to test)
    for cut in (4, 2, ns.span_cut[ns.span_r[0]]):
        q.given = (8, ns.far[16].worst_px / cut)
        assert q.correct is False, cut
    asked = " ".join(ns.span_question.split())
    assert "drag the marker on the dashed line to N = 8's worst miss" in asked
    assert "Type the cut" not in asked
    assert q.explain.startswith(f"{ns.far[8].worst_px:.2f} px: halving N cut the worst miss ")
    assert "(within ± 0.4 px counts as right)" in asked and ns_dict["span_curve"] == ns.span_curve


def test_m1_a_third_of_the_predictions_act_on_a_figure():
    cells = _cells().values()
    made = [m for c in cells for m in re.findall(r"\b(q_\w+) = (Predict\w*)\(", c)]
    on_figure = [q for q, kind in made if kind in ("PredictPoint", "PredictPixels")]
    assert len(made) == 7 and sorted(on_figure) == ["q_depth", "q_rule", "q_span"]
    assert 3 * len(on_figure) >= len(made)


def test_s1_the_mean_the_texels_and_the_worst_pixel_one_paragraph_each():
    ns = lesson(NAME)
    paragraphs = ns.QUAKE_TEXT.split("\n\n")
    assert max(len(p.split()) for p in paragraphs) < 120, [len(p.split()) for p in paragraphs]
    assert paragraphs[0].endswith("the miss grows like $N^2$, the slope-2 guide.")
    assert paragraphs[1].startswith("In texels the mean falls less at large $N$")
    assert paragraphs[2].startswith("The worst pixel")  # r512: its own paragraph, shorter


def test_s2_the_below_floor_tick_sits_a_line_under_the_floor():
    from teachraster.plotting import span_subdivision as ps

    # on the log axis, "< 0.01" at least 0.7 decades under "0.01" (was 0.46)
    assert np.log10(ps.MISS_FLOOR / ps.MISS_BELOW) >= 0.7
    assert ps.MISS_BOTTOM < ps.MISS_BELOW < ps.MISS_FLOOR


def test_s3_the_facing_gap_against_float32s_spacing():
    from teachraster.study import bench

    ns = lesson(NAME)
    q, _ = _asked("q_depth", _depth_cell_id())
    said = " ".join(q.explain.split())
    assert "need no more than float32's spacing" not in said
    gap = bench.DEPTH_GAP / (bench.FAR - bench.NEAR)
    assert f"{bench.DEPTH_GAP:g} apart, are {gap:.0e} of linear depth's range apart" in said
    assert "far more than float32's spacing, at most 2<sup>−24</sup> (about 6e-08) of it" in said
    assert gap > 100 * 2.0**-24 and ns.lin32["facing_wrong"] == 0


def _depth_cell_id() -> str:
    return next(i for i, c in _cells().items() if "q_depth = PredictPoint(" in c)
