"""Exercise 8.1 redesigned (r126 D8-2, r131 D8-7: it was near-transcription of lesson 10 §1–§2):
a grid of blocks classified with one evaluation of each edge function per block plus two
offsets per edge computed once (llvmpipe's ``lp_setup_tri.c``, Abrash's Larrabee rasteriser).

Each typical wrong answer, written here as a student would (not with the checker's knobs), is
named by its own words; correct-but-different answers (numpy, loops over blocks, four corners
per block, float32 where float32 is exact) pass.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from exercise_solutions import (
    classify_block_float32,
    classify_block_four_corners,
    classify_block_loops,
    classify_block_offsets,
)

from teachraster import exercises as ex
from teachraster.exercises import tile_blocks, tries

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"


def student(offsets="right", span="size - 1", tie="top-left", orient=True, start=0.5):
    """classify_block as a student writes it, with one slip: ``offsets`` "right", "x mirrored",
    "y mirrored", "far corner", "sign flipped", "swapped", "reject by T" (the accept test
    right); ``span`` "size - 1", "size", "one" (a one-pixel block's offset, not scaled) or
    "size / 2"; ``tie`` "top-left", "E >= 0", "E > 0" or "accept strict" (the rule in the
    reject test only); ``orient`` False: the edges as given, "flipped": the interior on their
    negative side; ``start`` where E₀ is evaluated, from (x0, y0)."""

    def classify_block(xy, x0, y0, size):
        v = np.asarray(xy, dtype=float)
        px, py = np.asarray(x0) + start, np.asarray(y0) + start
        area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
        if area == 0:
            return np.full(px.shape, "rejected")
        if (area > 0) if orient == "flipped" else (area < 0 and orient):
            v = v[[0, 2, 1]]
        d = {"size - 1": size - 1, "size": size, "one": 1, "size / 2": size / 2}[span]
        rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            A, B = a[1] - b[1], b[0] - a[0]
            R, T = d * (max(A, 0) + max(B, 0)), d * (min(A, 0) + min(B, 0))
            R, T = {
                "right": (R, T),
                "x mirrored": (d * (min(A, 0) + max(B, 0)), d * (max(A, 0) + min(B, 0))),
                "y mirrored": (d * (max(A, 0) + min(B, 0)), d * (min(A, 0) + max(B, 0))),
                "far corner": (d * (A + B), 0.0),
                "sign flipped": (-R, -T),
                "swapped": (T, R),
                "reject by T": (T, T),
            }[offsets]
            e0 = A * (px - a[0]) + B * (py - a[1])
            top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            owns = {"top-left": top_left, "E >= 0": True, "E > 0": False,
                    "accept strict": top_left}[tie]  # fmt: skip
            rejected |= (e0 + R < 0) if owns else (e0 + R <= 0)
            accepted &= (e0 + T >= 0) if owns and tie != "accept strict" else (e0 + T > 0)
        return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))

    return classify_block


#: Each typical mistake: (student, the kind the report gives it, words its explanation holds).
MISTAKES = {
    "offset of the wrong corner (x)": (
        student(offsets="x mirrored"), "offsets of another corner (x)", "wrong column"),
    "offset of the wrong corner (y)": (
        student(offsets="y mirrored"), "offsets of another corner (y)", "wrong row"),
    "offset of one fixed corner": (
        student(offsets="far corner"), "offsets of one fixed corner", "ignore the signs of A"),
    "offset sign flipped": (
        student(offsets="sign flipped"), "offset signs flipped", "you subtracted the offsets"),
    # r141 D8.1-5, D8.1-7: both give the same verdicts; the words say only what both do
    "accept and reject offsets swapped": (
        student(offsets="swapped"), "rejected by the smallest value",
        "you rejected by E's smallest value over the block, E₀ + T"),
    "rejected by E₀ + T, accepted right": (
        student(offsets="reject by T"), "rejected by the smallest value",
        "you rejected by E's smallest value over the block, E₀ + T"),
    # r141 D8.1-3: a one-pixel block's offset not scaled was told "Corners outside the triangle
    # do not reject a block"; size/2 steps too
    "offsets not scaled (one step)": (
        student(span="one"), "offsets not scaled", "llvmpipe's offset for a one-pixel block"),
    "offsets of size/2 steps": (
        student(span="size / 2"), "offsets of size/2 steps", "your offsets span size/2 steps"),
    # r141 D8.1-4, D8.1-6: the flipped orientation, the tie rule missing from the accept test
    "oriented the wrong way": (
        student(orient="flipped"), "oriented the wrong way", "oriented the wrong way round"),
    "tie rule in the reject test only": (
        student(tie="accept strict"), "no top-left rule in the accept test",
        "your accept test leaves out the top-left rule"),
    "size instead of size - 1": (
        student(span="size"), "size steps for size − 1", "your offsets span size steps"),
    "E at the outer corner": (
        student(start=0.0, span="size"), "outer corners", "the block's outer corners"),
    "ignoring the tie rule (E >= 0)": (
        student(tie="E >= 0"), "no top-left rule (E ≥ 0)", "lies exactly on edge"),
    "ignoring the tie rule (E > 0)": (
        student(tie="E > 0"), "no top-left rule (E > 0)", "lies exactly on edge"),
    "ignoring winding": (student(orient=False), "one winding only", "handle both windings"),
    "a constant array": (
        lambda xy, x0, y0, size: np.full(np.shape(x0), "partial"), "always partial",
        "says 'partial' for every block of every grid"),
}  # fmt: skip


@pytest.fixture
def full_words():
    """The checks give their full words (as after two different failing answers)."""
    tries.spend_hints(["classify_block"])
    yield
    tries.forget_hints("classify_block")


@pytest.mark.parametrize("mistake", list(MISTAKES))
def test_each_typical_mistake_is_named_by_its_own_words(mistake, full_words):
    fn, kind, words = MISTAKES[mistake]
    report = ex.check("classify_block", fn, budget=120)
    assert not report.passed
    assert report.failures, str(report)
    first = report.failures[0]
    assert first.kind == kind, (first.kind, first.explanation)
    assert words in first.explanation, first.explanation
    # no other mistake's words on the same report's first failure
    # (r141 D8.1-6: the tie rule missing from the accept test says the tie, as b06's words do)
    shared = {"lies exactly on edge"} if kind == "no top-left rule in the accept test" else set()
    others = {w for m, (_, _, w) in MISTAKES.items() if w != words} - shared
    assert not [w for w in others if w in first.explanation], first.explanation
    # every failing case of a single slip is that slip's (or an engine's constant note)
    assert {f.kind for f in report.failures if f.kind} == {kind}, [f.kind for f in report.failures]


def test_a_constant_text_is_named_by_the_engine():
    report = ex.check("classify_block", lambda *a: "partial", budget=120)
    assert "returns 'partial' on every case" in report.failures[0].explanation


@pytest.mark.parametrize(
    "fn", [classify_block_offsets, classify_block_loops, classify_block_four_corners,
           student()], ids=["numpy offsets", "loops (Fractions)", "loops, four corners",
                            "numpy, written here"],
)  # fmt: skip
def test_correct_but_different_solutions_pass(fn):
    report = ex.check("classify_block", fn, budget=120)
    assert report.passed, str(report)


def test_float32_passes_where_it_is_exact_and_is_named_where_not(full_words):
    report = ex.check("classify_block", classify_block_float32, budget=120)
    assert report.failures, "float32 should round the 1/65536 px² ties 3000 px out"
    assert all(f.case.startswith("far out, a centre 1/65536") for f in report.failures), [
        f.case for f in report.failures
    ]
    assert all("in float32" in f.explanation for f in report.failures)


def test_the_solution_cell_passes_and_asks_for_a_grid():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    code = next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == "classify_block_solution")  # fmt: skip
    space = {"np": np}
    exec("".join(code["source"]), space)  # noqa: S102 - the notebook's own solution
    assert ex.check("classify_block", space["classify_block"], budget=120).passed


def test_the_task_says_what_the_lesson_does_not():
    """The task asks for the offsets from A, B and size, one evaluation per block over a grid,
    links lesson 10's figure, and does not hand over lesson 10's corner code or the offsets."""
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    task = "".join(next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == "classify_block_task")["source"])  # fmt: skip
    for words in ("once\nper block", "from A, B and `size` alone", "E₀ + R", "E₀ + T",
                  "(../10_tiles_and_hierarchical_z.ipynb)", "lp_setup_tri.c", "Larrabee",
                  "either winding", "zero-area triangle", "top-left rule", "integer NumPy arrays",
                  "a little\nover a thousand blocks at most"):  # fmt: skip
        assert words in task, words
    for answer in ("(s - 1)", "size - 1) *", "max(A, 0)", "int(step_down > 0)"):
        assert answer not in task, answer


def test_the_cases_cover_the_hard_ones():
    """Ties on block corners, exact half-pixel centres, both windings, zero area, 1×1, 64 and
    2^19-px blocks, far coordinates, grids of both shapes."""
    cases = tile_blocks.block_cases()
    labels = " | ".join(label for label, _, _ in cases)
    for words in ("a left edge through the left corners", "one pixel, its centre on a left edge",
                  "counter-clockwise, a right edge through the right corners", "zero area",
                  "far out, a centre 1/65536 px²", "the whole triangle in one 64-block",
                  "blocks of 2^19 × 2^19 px", "counter-clockwise, blocks of 2^19"):  # fmt: skip
        assert words in labels, words
    sizes = {args[3] for _, args, _ in cases}
    assert {1, 4, 16, 64, tile_blocks.HUGE} <= sizes
    assert {np.ndim(args[1]) for _, args, _ in cases} == {1, 2}
    # the task: "the check's grids hold a little over a thousand blocks at most"
    assert 1000 < max(np.size(args[1]) for _, args, _ in cases) < 1300
    verdicts = set(np.concatenate([np.ravel(k) for _, _, k in cases]).tolist())
    assert verdicts == set(tile_blocks.KINDS)


def test_a_wrong_shape_is_explained():
    report = ex.check("classify_block", lambda xy, x0, y0, size: np.ravel(classify_block_offsets(xy, x0, y0, size)))  # fmt: skip
    assert "expected one per block, an array of shape" in report.failures[0].explanation
