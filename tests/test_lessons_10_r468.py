"""Lesson 10, review r468: P1, S1, S2 and S3 (see the test's docstring)."""

from __future__ import annotations

import numpy as np
from test_lessons_b import _lesson_10_run, _lesson_10_sources


def test_10_r468_items():
    """Review r468, lesson 10. P1: only q_hiz of the 5 predictions was answered on a figure
    (issue 29 asks a third); q_trav now asks the student to click, on the 8×8 grid with its
    four tiles drawn and no path, the cells at which serpentine arrives in another tile (9).
    S1: cell 27 asked "where the picture goes wrong" above a question about the share
    inside. S2: cell 38's block colours are named in cell 37. S3: q_tile's explain said
    "doubling ... gives 13,312 − 2,259"."""
    ns, printed, shown = _lesson_10_run()
    cells, text, md, code = _lesson_10_sources()
    # P1: a PredictPixels on the grid; its answer is the cells the table counts
    ask = next(i for i, t in enumerate(text) if "q_trav = PredictPixels(" in t)
    assert "answer=serp_entries," in text[ask] and "draw=draw_tiles," in text[ask]
    assert text[ask + 1].startswith("q_trav.hold()") and "plot_traversal(" in text[ask + 1]
    assert "plot_traversal(" not in text[ask]  # no path drawn on the question's grid
    want = [[0, 4], [1, 3], [2, 4], [3, 3], [4, 0], [4, 4], [5, 3], [6, 4], [7, 3]]
    assert np.argwhere(ns.serp_entries).tolist() == want
    assert int(ns.serp_entries.sum()) == ns.serp == ns.tile_changes["serpentine"] == 9
    assert f"{'serpentine':12s}{ns.jumps['serpentine']:6d}{9:12d}" in printed
    assert "(row 3 to row 4, " in text[ask] and "column 0) enters another tile" in text[ask]
    # S1
    assert "Then predict how its wrong pixels split between inside and outside." in md
    assert "predict where the picture goes wrong" not in md
    # S2
    assert "coloured as in §2 (grey rejected, green accepted, orange partial)" in md
    # S3: the two numbers the explain subtracts, and no "doubling ... gives" subtraction
    ask = next(t for t in text if "q_tile = Predict(" in t)
    assert "doubling the " not in ask and "and so does what " in ask
    at8 = ns.tile_counts["front to back", 8]
    assert ns.doubled_rim == at8["hiz_rejected"] - at8["early_z_killed"] == 11_053
    assert abs(ns.doubled_rim - ns.q_tile_answer) <= 500
