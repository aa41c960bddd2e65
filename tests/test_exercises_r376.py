"""r376, a fresh read of exercise 08: two-mistake answers misnamed or told only the rule, two
mistakes missing from 8.1's table, and 8.2's graded part spelled out in words.

- F1: an int64 classify_block with two slips (size steps and no tie bias; one winding only and
  the bias added) was told "you computed in float64 pixels" at the far float64 ties: a second
  slip (``with_others``) now yields to a mistake that gives those answers too, a pair included,
  and with the edges as given the tie flags are read off those edges (the bias's too).
- F2: ``int()`` at both ends of 8.2's box was told "the bounding box's own corners": now named
  "one before" and "int for floor", each on its own failures (a case tells the corners apart).
- F3: "one axis only" (B's term dropped from R, or from R and T) is in 8.1's table.
- F4: "edge kinds read before orienting" is in the table, with a hard case that catches it.
- F5: R and T swapped with an accept test "> 0" (8.1), and "strict" beside lesson 10's bound
  or an unclamped plane (8.2), are each named on their own failures.
- 8.2's task no longer states the bound in words; the check asks it first, then says it.
"""

from __future__ import annotations

from collections import Counter
from functools import cache
from pathlib import Path

import pytest
from graded_cells import flat, graded_cell
from student_variants import R376

from teachraster import exercises as ex
from teachraster.exercises import hiz_tile, tile_blocks

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks/exercises/08_tiles.ipynb"
BUDGET = 120


@cache
def _report(label):
    name, fn, _, _ = R376[label]
    return ex.check(name, fn, budget=BUDGET)


def _kinds(label) -> Counter:
    return Counter(f.kind for f in _report(label).failures)


def test_f1_int64_with_size_steps_and_no_bias_is_never_told_float64():
    report = _report("blocks in int64 with size steps and no tie bias")
    assert not report.passed
    assert all("float64" not in f.explanation for f in report.failures), str(report)
    kinds = _kinds("blocks in int64 with size steps and no tie bias")
    assert set(kinds) <= {
        "size steps for size − 1",
        "no top-left rule (E ≥ 0)",
        "size steps for size − 1 and no top-left rule (E ≥ 0)",
    }, kinds
    # the far float64 ties are told the two slips that decide them there
    far = [f for f in report.failures if "far out in float64" in str(f.case)]
    assert far and all("float64 pixels" not in f.kind for f in far)


def test_f1_one_winding_with_the_bias_added_names_the_bias():
    label = "blocks in int64 of one winding, the bias added"
    report = _report(label)
    assert all("float64" not in f.explanation for f in report.failures), str(report)
    kinds = _kinds(label)
    assert "one winding only" in kinds and "tie-rule bias added" in kinds, kinds
    assert "no top-left rule (E ≥ 0)" not in kinds, kinds
    text = str(report)
    assert "your bias has the wrong sign" in text and "handle both windings" in text


def test_f1_the_clockwise_mirror_case_tells_the_bias_added_from_no_bias():
    labels = [c[0] for c in tile_blocks.block_cases()]
    assert any(c.startswith("far out, clockwise, a centre 1/65536 px² outside a right edge")
               for c in labels)  # fmt: skip
    case = next(c for c in tile_blocks.block_cases() if "far out, clockwise" in c[0])
    added = tile_blocks.classify_with(*case[1], orient=False, tie="bias added")
    loose = tile_blocks.classify_with(*case[1], orient=False, tie="loose")
    assert not tile_blocks.same_kind(added, loose, case[1])


@pytest.mark.parametrize(
    ("label", "kind", "words"),
    [
        ("blocks with B's term dropped from R", "offsets of one axis only (reject x only)",
         "your reject offset R takes A's term alone and drops B's"),
        ("blocks with B's term dropped from R and T", "offsets of one axis only (x only)",
         "your offsets R and T take A's term alone and drop B's"),
    ],
)  # fmt: skip
def test_f3_one_axis_only_is_named(label, kind, words):
    assert set(_kinds(label)) == {kind}, _kinds(label)
    assert all(words in f.explanation for f in _report(label).failures)
    assert (
        "E also changes downwards across the block's rows" in _report(label).failures[0].explanation
    )


def test_f4_edge_kinds_read_before_orienting_fail_a_hard_case_every_run():
    label = "blocks with the edge kinds read before orienting"
    report = _report(label)
    assert set(_kinds(label)) == {"edge kinds read before orienting"}, _kinds(label)
    hard = "counter-clockwise, centres on a left and on a right edge"
    assert any(str(f.case).startswith(hard) for f in report.failures), str(report)
    assert "off the edges as given and oriented the triangle after" in str(report)
    # the case is fixed (no random draw), and the triangle is counter-clockwise
    case = next(c for c in tile_blocks.block_cases() if c[0].startswith(hard))
    assert tile_blocks._oriented(case[1][0])[1]


def test_f5_r_and_t_swapped_with_accept_above_zero_names_both():
    label = "blocks in int64, R and T swapped, accept test > 0"
    kinds = _kinds(label)
    assert "value" not in kinds, kinds
    assert "rejected by the smallest value" in kinds and "accept test E > 0" in kinds, kinds


def test_f2_int_at_both_ends_of_the_box_is_named_by_its_two_halves():
    label = "Hi-Z with int() at both ends of the box"
    report = _report(label)
    assert set(_kinds(label)) == {"one before", "int for floor"}, _kinds(label)
    assert "bounding box's own corners" not in str(report)
    # the case that tells the box's own corners from a column before the box
    case = next(c for c in hiz_tile.hiz_cases() if "starts 0.2 px before a centre, inside" in c[0])
    variants = hiz_tile._variants(*case[1])
    assert variants["box corners"] == case[2] != variants["one before"]


@pytest.mark.parametrize(
    ("label", "kinds"),
    [
        ("Hi-Z with > and no vertex clamp", {"strict", "no clamp"}),
        ("Hi-Z by lesson 10's bound with >", {"strict", "whole tile", "whole tile and strict"}),
    ],
)
def test_f5_strict_beside_a_bound_slip_is_named_on_its_own_failures(label, kinds):
    got = _kinds(label)
    assert "value" not in got and set(got) <= kinds and "strict" in got, got
    assert len(set(got) - {"strict"}) >= 1


def test_8_2_states_the_facts_not_the_bound():
    task = flat(graded_cell(NOTEBOOK, "hiz_rejects_task"))
    main = task.split("<details>")[0]
    for spelled in ("the larger of the plane's minimum", "inside the box (its border included) "
                    "and the nearest vertex's depth", "+∞ where the box holds none"):  # fmt: skip
        assert spelled not in main, spelled
    assert "no fragment of the triangle lies outside its bounding box" in main
    assert "Working it out is the task" in main
    assert "says the bound once two different answers have failed" in main
    # and the check does so: its rule states the bound, a question until two answers failed
    rule = hiz_tile._rule(None, True, False)
    assert "its plane's minimum over the tile's centres inside its bounding box" in rule
    hinted = rule
    for old, new in hiz_tile.HIZ_HINTS:
        hinted = old.sub(new, hinted) if hasattr(old, "sub") else hinted.replace(old, new)
    assert "(where in the tile can a fragment lie, where is its depth smallest" in hinted
    assert "no nearer than its nearest vertex" not in hinted


def test_f6_the_scene_says_why_a_pixel_of_the_same_fill_is_explained():
    """F6: with size steps the scene explained pixel (0, 0), a block partial for rejected, with
    no reason (both walks leave it out): now it says that only the walk's work differs."""
    from teachraster.exercises import picture_scenes

    fn = R376["blocks in int64 with size steps and no tie bias"][1]
    codes, _ = picture_scenes.walk(fn)
    reference, _ = picture_scenes.walk(tile_blocks.expected_block)
    assert codes[0, 0] != reference[0, 0]
    why = picture_scenes._pixel_why(codes, 0, 0)
    assert why == (
        "; both walks leave out this pixel: a partial block's pixels are each tested, so here "
        "only the walk's work differs, not the picture"
    )
