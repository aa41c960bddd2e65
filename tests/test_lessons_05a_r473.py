"""Lesson 05a, review r473: each test fails on the lesson before the fix.

M-1: issue 29 asks for a third of the questions answered on a figure; only q_order was. q_step
is now asked on the stepper's own picture of the triangle it opens on (a ``PredictPixels``
grid, "none of them" a choice): click where the final picture still shows it. S-1: the
failing fragments of cell 24 were black beside the stepper's vermillion "failed"; they are
vermillion now, and the painter's wrong pixels are outlined in black.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parent.parent
NAME = "05a_zbuffer"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _cells() -> dict[str, str]:
    return {c["id"]: "".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]}


@pytest.mark.notebook
def test_m1_a_third_of_the_questions_on_a_figure():
    from teachraster.plotting.zbuffer_steps import fragment_classes
    from teachraster.widgets import PredictPixels

    cells = _cells()
    kinds = {q: next(t.split(f"{q} = ", 1)[1].split("(", 1)[0] for t in cells.values()
                     if f"\n{q} = " in f"\n{t}")
             for q in ("q_order", "q_culled", "q_step", "q_clip")}  # fmt: skip
    assert kinds == {"q_order": "PredictOrder", "q_culled": "Predict", "q_step": "PredictPixels",
                     "q_clip": "Predict"}  # fmt: skip
    asked = cells["stepper_q"]
    assert "answer=(cube.triangle_id == k_open)[step_crop]," in asked
    assert 'none="none of them",' in asked and "draw=draw_step," in asked
    ns = lesson(NAME)
    # the picture is the stepper's at k_open, its passed and failed fragments, the cube whole
    classes = fragment_classes(ns.cube, ns.k_open)[ns.step_crop]
    assert int((classes == 2).sum()) == ns.cube_steps[ns.k_open][0] == ns.shown_other
    assert int((classes == 3).sum()) == ns.cube_steps[ns.k_open][1]
    assert int(ns.cube.coverage[ns.step_crop].sum()) == int(ns.cube.coverage.sum())
    answer = (ns.cube.triangle_id == ns.k_open)[ns.step_crop]
    assert not answer.any() and ns.shown_at_end == 0  # none: a later triangle covers all 96
    q = PredictPixels("q_step", answer=answer, none="none of them")
    assert q.given is None
    q.given = []
    assert q.correct
    q.given = np.argwhere(classes == 2).tolist()  # "the blue ones stay": wrong
    assert q.correct is False and q.counts()["extra"] == ns.shown_other


def test_s1_failed_is_vermillion_as_in_the_stepper():
    cell = _cells()["c12"]
    assert 'plot_coverage(ax, failed_px, color=COLORS["outside"])' in cell
    assert 'outline(ax, painter_wrong, "black")' in cell
    assert 'color="black", lw=2.5, label="painter wrong (outline)"' in cell


def test_s3_s4_s6_s7_s8_s9_words():
    cells = _cells()
    # S-6: "Each API spells them its own way" leads into the table of spellings
    off = " ".join(cells["c02_off"].split())
    assert "Each API spells them its own way: the same four settings in the other APIs" in off
    assert "its own way: What each" not in off
    # S-7: the stored depth in Direct3D and Vulkan
    rule = " ".join(cells["c02"].split())
    assert "in Direct3D and Vulkan $z/w$ already runs from 0 to 1 and is stored as it is" in rule
    # S-8: the strip's early test says when it may run
    assert "only\\nif the shader writes " in cells["pipeline_strip"]
    assert "optional" not in cells["pipeline_strip"].split("early = ")[1].split("\n")[0]
    # S-4: a rounded edge moves by up to (|n_x| + |n_y|)/2 of a step, not half a step
    assert "(|n_x| + |n_y|)/2 of a step" in cells["guard_snap_fig"]
    assert "Either may move by up to half a snapping step" not in cells["guard_snap_fig"]
    # S-3: "sameness, not accuracy" once in the main text's place of it (fold and summary)
    assert "That is sameness, not accuracy" not in cells["guard_fig_md"]
    # S-9: the question does not repeat the widget's own instructions
    assert "click one to keep the order shown" not in cells["b979115f"]


def test_s2_s5_teachraster_band_folded_and_short_options():
    cells = _cells()
    # S-2: the simulator's band formula is folded; the main text keeps what the cut shows
    guard = cells["guard_md"]
    shown, folded = guard.split("<details>", 1)
    assert "2^{29-s}" not in shown and "0.999" not in shown
    assert "g = 2 \\cdot 0.999\\,L/\\max(W, H) - 1" in folded and "</details>" in folded
    assert "against the band's plane $x = g\\,w$" in shown
    # S-5: the question says "points of the original edge" once; the options are short
    asked = cells["c16q"]
    options = asked.split("clip_choices = [", 1)[1].split("]", 1)[0]
    assert "edge's points" not in options and '"only the first vertex"' in options
