"""r221 (exercise 08_tiles): a fresh read playing three students.

1 (C): every horizontal edge taken as top (``b.y <= a.y``, "runs right" forgotten) passed all
   47 cases of 8.1: none put a centre on a bottom edge. Two cases now do, and the slip is
   named.
2 (C): a box ∩ tile of one column or one row read as empty (``c_lo >= c_hi``) passed all 68
   cases of 8.2: two tiles now meet the box in one column and one row, in front of the stored
   depth, and the slip is named.
3 (M): left edges with no top clause were told "a bottom-left rule": named as what they are.
4 (M): ``buffer[0, 0]`` compared was told "the nearest depth stored in the tile": named as the
   tile's first stored depth, where it gives every answer of the check.
"""

from __future__ import annotations

import numpy as np
import pytest
from test_exercises_r149 import full_words  # noqa: F401
from test_exercises_r162 import first_words  # noqa: F401
from test_exercises_r198 import _hiz_variant, _variant

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import hiz_tile, tile_blocks

_TOP_LEFT = "top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])"
#: the reader's w_any_horizontal_is_top
EVERY_HORIZONTAL_TOP = _variant((_TOP_LEFT, "top_left = b[1] <= a[1]"))
#: the reader's w_left_only_no_top
LEFT_ONLY = _variant((_TOP_LEFT, "top_left = b[1] < a[1]"))
#: the reader's w_top_runs_left: a bottom-left rule indeed
TOP_RUNS_LEFT = _variant((_TOP_LEFT, "top_left = b[1] < a[1] or (b[1] == a[1] and b[0] < a[0])"))
#: the reader's w_single_column_empty
ONE_LINE_EMPTY = _hiz_variant(("if c_lo > c_hi or r_lo > r_hi:", "if c_lo >= c_hi or r_lo >= r_hi:"))  # fmt: skip
#: the reader's w_buffer_corner_only
FIRST_STORED = _hiz_variant(("nearest >= np.max(buffer)", "nearest >= np.asarray(buffer)[0, 0]"))


def _kinds(report) -> set[str]:
    return {f.kind for f in report.failures}


# -- 1 (C), 3 (M): a centre on a bottom edge -----------------------------------------------------


def test_1_the_bottom_edge_cases_are_what_the_review_asked():
    # (r232 added a far tie on a 131,072-px bottom edge, "far from its first centre")
    cases = [
        c for c in tile_blocks.block_cases() if "bottom edge" in c[0] and "far from" not in c[0]
    ]
    assert len(cases) == 2
    xy = cases[0][1][0]
    # a horizontal edge at y = 20.5 that runs left once oriented: the renderer covers no pixel
    # of row 20, whose centres lie on it
    setup = tile_blocks.setup_edges(xy, tile_blocks.SUBPIXEL_BITS)
    v = setup.p / setup.unit
    kinds = [tile_blocks.edge_kind(v[(k + 1) % 3] - v[k]) for k in range(3)]
    assert "bottom" in kinds
    fill = tr.rasterize(tr.Triangle(xy), 32, 32)
    assert fill.coverage[20].sum() == 0 and fill.coverage[19].sum() > 0
    for _, args, expected in cases:
        got = tile_blocks.classify_with(*args, tie="top-bottom-left")
        assert (np.asarray(got) != np.asarray(expected)).any()


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_1_every_horizontal_edge_top_fails_and_is_named(words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", EVERY_HORIZONTAL_TOP, budget=120)
    # the two bottom-edge cases, and r232's far tie on a bottom edge
    assert not report.passed and len(report.failures) == 3, str(report)
    assert _kinds(report) == {"every horizontal edge top"}, str(report)
    for f in report.failures:
        assert "bottom edge" in f.case
        assert "a horizontal edge is a top edge only if it runs right (x increasing" in f.explanation  # fmt: skip


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_3_left_edges_only_is_no_bottom_left_rule(words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", LEFT_ONLY, budget=120)
    assert not report.passed and _kinds(report) == {"left edges only"}, str(report)
    for f in report.failures:
        assert "bottom-left" not in f.explanation, f.explanation
        assert "your rule counts left edges but no top edge" in f.explanation
    # the slip that is a bottom-left rule is still told so
    report = ex.check("classify_block", TOP_RUNS_LEFT, budget=120)
    assert not report.passed
    assert "your edge tests follow a bottom-left rule" in report.failures[0].explanation


def test_1_the_case_count_and_a_right_answer():
    # r232: 7 far ties; r248: 6 float64 ties; r376: 2; r446: the smallest area
    assert len(tile_blocks.block_cases()) == 65
    report = ex.check("classify_block", _variant(), budget=120)
    assert report.passed and "all 65 cases pass" in str(report)
    # A and B exchanged in the offsets is equivalent (R and T are symmetric in them)
    swapped = _variant(
        ("step * (max(A, 0) + max(B, 0))", "step * (max(B, 0) + max(A, 0))"),
    )
    assert ex.check("classify_block", swapped, budget=120).passed


# -- 2 (C), 4 (M): a box of one column or row; buffer[0, 0] ------------------------------------


def test_2_the_one_line_tiles_are_what_the_review_asked():
    cases = [c for c in hiz_tile.hiz_cases() if "in one column" in c[0] or "in one row" in c[0]]
    assert len(cases) == 2
    for _, args, expected in cases:
        xyz, row0, col0, size, buffer = args
        rows, cols = hiz_tile._box_corners(xyz, row0, col0, size)
        assert rows[0] == rows[3] or cols[0] == cols[3]  # one row or one column
        assert not expected  # kept: the triangle lies in front of the stored depth
    # the renderer draws pixels (7, 1) … (7, 6) of the column case, at depth 0.1
    xyz = cases[0][1][0]
    fill = tr.rasterize(tr.Triangle(xyz[:, :2], z=xyz[:, 2]), 8, 8)
    assert fill.coverage[:, 7].sum() == 6 and fill.coverage[:, :7].sum() == 0


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_2_a_one_line_box_read_as_empty_fails_and_is_named(words, request):
    request.getfixturevalue(words)
    report = ex.check("hiz_rejects", ONE_LINE_EMPTY, budget=120)
    assert not report.passed and len(report.failures) == 2, str(report)
    assert _kinds(report) == {"one line empty"}, str(report)
    said = " ".join(f.explanation for f in report.failures)
    assert "one column of centres, column 7 (x = 7.5)" in said
    assert "one row of centres, row 7 (y = 7.5)" in said
    assert "first > last" in said


@pytest.mark.parametrize("words", ["first_words", "full_words"])
def test_4_buffer_0_0_is_named_the_first_stored_depth(words, request):
    request.getfixturevalue(words)
    report = ex.check("hiz_rejects", FIRST_STORED, budget=120)
    assert not report.passed and _kinds(report) == {"first stored"}, str(report)
    for f in report.failures:
        assert "nearest depth stored" not in f.explanation
        assert "you compared with the tile's first stored depth, buffer[0, 0]" in f.explanation
    # comparing with the tile's nearest depth is still told so
    nearest = _hiz_variant(("nearest >= np.max(buffer)", "nearest >= np.min(buffer)"))
    report = ex.check("hiz_rejects", nearest, budget=120)
    assert not report.passed and _kinds(report) == {"tile min"}, str(report)


def test_2_the_case_count_and_a_right_answer():
    # r232: 2 borders at an odd k + ½; r248 S2: the far-plane case, which either reading of an
    # empty pixel now passes, left out
    assert len(hiz_tile.hiz_cases()) == 72  # r376 F2: one
    report = ex.check("hiz_rejects", _hiz_variant(), budget=120)
    assert report.passed and "all 72 cases pass" in str(report)
