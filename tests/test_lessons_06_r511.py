"""Lesson 06, review r511: each test fails on the lesson before the fix.

S1: "the camera rolled 25°" was typed in §1's text; the roll is the study's constant
(``bench.FLOOR_ROLL``) and is printed with the floor under the interpolation table.
S2: "One span" typed 65 pixels, 64 steps and 256 texels; the question under it and the
explorer's subtitle print the span.
S3: §2 typed "24 random triangles (12 ...)" and named two columns for three mesh offsets; the
table's error column is now printed split (random triangles, the mesh at each offset).
S4: cell 44 pointed at a line of totals for "the multiply-adds outlast the reciprocal"; the line
now prints the pipe's cycles beside the reciprocal's, and the set-up's counts the text quotes.
"""

from __future__ import annotations

import inspect
import json
import re

from notebook_runs import ROOT, executed, lesson, printed_and_folded

NAME = "06_what_accuracy_costs"


def _cells() -> list[tuple[str, str]]:
    nb = json.loads((ROOT / "notebooks" / f"{NAME}.ipynb").read_text())
    return [(c["cell_type"], "".join(c["source"])) for c in nb["cells"]]


def _markdown() -> str:
    return " ".join(" ".join(s for k, s in _cells() if k == "markdown").split())


def test_s1_the_roll_is_printed_not_typed():
    from teachraster.study import bench

    assert inspect.signature(bench.floor_quad).parameters["roll"].default == bench.FLOOR_ROLL
    assert "25°" not in _markdown() and "roll=25" not in "".join(s for _, s in _cells())
    printed = printed_and_folded(executed(NAME).notebook())
    assert f"the camera rolled {bench.FLOOR_ROLL:g}°" in printed


def test_s2_one_span_types_no_number():
    (md,) = [s for k, s in _cells() if k == "markdown" and s.startswith("### One span")]
    assert not re.search(r"\d", md)
    from teachraster.study import span_subdivision as spans

    assert f"one span of {spans.SPAN_PIXELS - 1} steps" in lesson(NAME).span_question


def test_s3_the_edge_error_column_is_printed_split():
    ns = lesson(NAME)
    md = next(s for k, s in _cells() if k == "markdown" and s.startswith("## 2. Edge functions"))
    assert not re.search(r"\b(24|12)\b", md) and "split the error" in md
    assert (len(ns.random_tris), ns.on_grid) == (24, 12)
    printed = " ".join(printed_and_folded(executed(NAME).notebook()).split())
    assert "24 random triangles (12 on the half-pixel grid) + the mesh @0 + @1e5 + @1e6:" in printed
    for arith, parts in ns.error_parts.items():
        total = sum(parts.values())
        (row,) = [r for r in ns.rows if r["variant"] == f"{arith} direct"]
        assert total == row["error"]
        if total:
            shown = " + ".join(f"{v:,}" for v in parts.values())
            assert f"{arith} {shown} = {total:,}" in printed


def test_s4_cell_44_points_at_lines_that_print_its_claims():
    ns = lesson(NAME)
    printed = printed_and_folded(executed(NAME).notebook())
    pipe, rcp = ns.pipe_gpu["perspective"], ns.GPU_DIVIDE
    assert pipe > rcp  # the multiply-adds outlast the reciprocal
    assert (f"GPU prices, {ns.GPU_ATTRIBUTES} attributes, cheapest first:" in printed
            and f"perspective-correct: multiply-add pipe {pipe:g} cycles, reciprocal "
            f"{rcp:g} beside it" in printed)  # fmt: skip
    md = _markdown()
    assert 'the lines "GPU prices, 16 attributes")' in md and ns.GPU_ATTRIBUTES == 16
    m, plane = ns.SETUP_M, ns.SETUP_PLANE
    assert (f"costs one divide, {m['multiplies']} multiplies and {m['additions']} additions, each "
            f"attribute's plane {plane['multiplies']} multiplies and {plane['additions']} "
            "additions") in md  # fmt: skip
    assert (
        f"M 1 divide, {m['multiplies']} multiplies, {m['additions']} additions; each plane "
        f"{plane['multiplies']} multiplies, {plane['additions']} additions"
    ) in printed
    assert (
        f"{ns.setup_cycles / 4:.3g} for 4 px" in printed and ns.setup_cycles / 4 > ns.P5["divides"]
    )


def test_s5_fewer_pointers_the_numbers_quoted_where_printed_beside():
    ns = lesson(NAME)
    # SPAN_WHY: the derivation and the cuts in two paragraphs; "towards 2" quotes r = 100's cut
    why = ns.SPAN_WHY.split("\n\n")
    assert len(why) == 2 and why[1].startswith("Near $\\rho = 1$")
    assert ns.SPAN_WHY.count("the lines above") == 1
    assert f"towards 2 ({ns.span_cut[100.0]:.2f} at $r = 100$)" in ns.SPAN_WHY
    # FILL_TEXT: the limit quoted (as printed under the table), no "(the last lines)"
    fill = " ".join(ns.FILL_TEXT.split())
    assert "(the printed limit)" not in fill and "(the last lines)" not in fill
    assert f"per covered pixel: {ns.fill_limit:.1f} at 512²" in fill
    printed = printed_and_folded(executed(NAME).notebook())
    assert f"so the ratio tends to {ns.fill_limit:.1f}x" in printed
    # cell 47: one pointer for its three trades, not three
    (bits,) = [s for k, s in _cells() if k == "markdown" and s.startswith("**And in bits**")]
    flat = " ".join(bits.split())
    assert flat.count("the line") == 1 and "(the lines above measure three trades)" in flat
