"""Lesson 06, review r512: each test fails on the lesson before the fix.

S1: NVIDIA's reciprocal rates were told four times (cell 3 prints them; cells 4, 39, 45 retold
them): the prose states them once, the slider's section and "What a GPU pays" point to §1.
S5: the checkerboard's counts printed and drawn with a thousands separator, as the rest of the
lesson prints its counts.
"""

from __future__ import annotations

import json

from notebook_runs import ROOT, executed, lesson, printed_and_folded

NAME = "06_what_accuracy_costs"


def _markdown() -> str:
    nb = json.loads((ROOT / "notebooks" / f"{NAME}.ipynb").read_text())
    cells = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown"]
    return " ".join(" ".join(cells).split())


def test_s1_the_reciprocals_rates_told_once():
    md = _markdown()
    for rate in ("a sixth", "an eighth", "a quarter"):
        assert md.count(rate) <= 1, rate
    printed = printed_and_folded(executed(NAME).notebook())
    assert "1/6: Kepler (2012)" in printed and "1/8: Ampere GA10x (2020)" in printed
    slider = md.split("### A divide's price on a slider")[1].split("Predict")[0]
    assert "(§1)" in slider and "eighth" not in slider


def test_s5_checkerboard_counts_with_separators():
    ns = lesson(NAME)
    printed = printed_and_folded(executed(NAME).notebook())
    affine = ns.check_wrong["affine"]
    assert affine >= 1000 and f"affine {affine:,}" in printed
