"""Lesson 06, review r485: each test fails on the lesson before the fix.

S1: q_quake's explanation called two different pixels "the worst pixel": the one 51 texels off
(on the steepest piece it names) is 4.4 px off on screen; the one 6.8 px off is 33 texels off.
S2: FILL_TEXT (372 words) carried the stepped span loop's exactness (the integer DDA's quotient
and remainder) in the open; it is folded now, as FLOOR_CUTS_TEXT folds its aside.
"""

from __future__ import annotations

import json

import numpy as np
from notebook_runs import ROOT, lesson

NAME = "06_what_accuracy_costs"


def _cells() -> list[str]:
    nb = json.loads((ROOT / "notebooks" / f"{NAME}.ipynb").read_text())
    return ["".join(c["source"]) for c in nb["cells"]]


def test_s1_q_quake_says_the_pixel_worst_on_screen_is_another_one():
    from teachraster.study import bench

    ns = lesson(NAME)
    texels, px, _ = bench.floor_errors(ns.interp_size, "subdivided", 16)
    worst_texel = np.abs(texels).max(axis=-1).argmax()
    # the fact: the pixel worst in texels is not the pixel worst on screen
    assert worst_texel != px.argmax() and px[worst_texel] < px.max()
    assert np.isclose(np.abs(texels).max(), ns.n16["error"]) and px.max() == ns.n16["error_px"]
    (quake,) = [c for c in _cells() if "q_quake = Predict(" in c]
    text = " ".join(quake.replace('"\n    f"', "").replace('"\n    "', "").split())
    assert "the pixel worst on screen, not the same one, shows a texel that belongs" in text
    assert "the worst pixel shows a texel" not in text


def test_s2_fill_text_folds_the_stepped_span_loops_exactness():
    ns = lesson(NAME)
    text = ns.FILL_TEXT
    opened, closed = text.index("<details>"), text.index("</details>")
    inside, outside = text[opened:closed], text[:opened] + text[closed:]
    assert "Lesson 01's integer DDA is exact" in " ".join(inside.split())
    assert "quotient and remainder" in inside and "computes each crossing afresh" in inside
    # what the table and its question read stays in the open
    for words in ("So the ratio tends to 11 / 2", "close to the limit already at 256²",
                  "**Half-planes in blocks**", f"falls only to {ns.early_ratio:.1f}"):  # fmt: skip
        assert words in outside, words
    assert len(outside.split()) < 230 < len(text.split())
