"""Lesson 06, review r503: each test fails on the lesson before the fix.

C1: q_quake's explanation pointed at "the table's px column" for the mean on screen (0.35 px);
that column prints the worst only (6.84), the mean is printed under §1's figure.
S1: "0.30 × 168 = 51" read as a wrong product (0.30 × 168 = 50.4): the share has 3 digits.
S2: §5's scene (near 0.1, far 1000, view depths 1 to 500 and 1 to 900) was typed, not printed.
"""

from __future__ import annotations

import json
import re

from notebook_runs import ROOT, lesson

NAME = "06_what_accuracy_costs"


def _cells() -> list[tuple[str, str]]:
    nb = json.loads((ROOT / "notebooks" / f"{NAME}.ipynb").read_text())
    return [(c["cell_type"], "".join(c["source"])) for c in nb["cells"]]


def test_c1_s1_q_quake_explain_points_at_what_is_printed():
    ns = lesson(NAME)
    (quake,) = [s for _, s in _cells() if "q_quake = Predict(" in s]
    explain = quake.split("explain=")[1]
    assert "table's px column)" not in explain  # the mean on screen is not in that column
    assert "the lines under the figure after it the means" in explain
    assert "{share_q:.3f} × {change_q:.0f} = {share_q * change_q:.0f}" in explain
    product = round(ns.share_q, 3) * round(ns.change_q)
    assert round(product) == round(ns.share_q * ns.change_q)  # the printed factors give it


def test_s2_depth_scene_typed_numbers_are_printed_and_true():
    from teachraster.study import bench
    from teachraster.study.bench.groups import SLANTED_DISTANCES

    md = next(s for k, s in _cells() if k == "markdown" and s.startswith("## 5. Depth storage"))
    numbers = re.search(r"near ([\d.]+), far (\d+)\).*?depths (\d+)\s+to (\d+).*?depths (\d+) to (\d+)",
                        " ".join(md.split()))  # fmt: skip
    near, far, f0, f1, s0, s1 = (float(v) for v in numbers.groups())
    assert (near, far) == (bench.NEAR, bench.FAR)
    assert (f0, f1) == (min(bench.DEPTH_DISTANCES), max(bench.DEPTH_DISTANCES))
    assert (s0, s1) == (min(SLANTED_DISTANCES), max(SLANTED_DISTANCES))
    held = next(s for _, s in _cells() if s.startswith("# The depth table"))
    assert 'f"the scene: near {bench.NEAR:g}, far {bench.FAR:g}' in held  # folded with the table
