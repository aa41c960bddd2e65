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
    classify_block_units,
)

from teachraster import exercises as ex
from teachraster.exercises import tile_blocks, tries

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/08_tiles.ipynb"


def student(offsets="right", span="size - 1", tie="top-left", orient=True, start=0.5, bias=None, ops=("<", ">=")):  # fmt: skip
    """classify_block as a student writes it, with one slip: ``offsets`` "right", "x mirrored",
    "y mirrored", "far corner", "sign flipped", "swapped", "reject by T" (the accept test
    right); ``span`` "size - 1", "size", "one" (a one-pixel block's offset, not scaled) or
    "size / 2"; ``tie`` "top-left", "E >= 0", "E > 0" or "accept strict" (the rule in the
    reject test only); ``orient`` False: the edges as given, "flipped": the interior on their
    negative side; ``start`` where E₀ is evaluated, from (x0, y0); ``bias`` (px²): the
    top-left rule folded into E as the task asks (E − bias ≥ 0 on an edge that is neither top
    nor left, every test one sign test; ex30a), or None: the rule written out per edge;
    ``ops``: the comparisons of the reject and accept sign tests with a bias (r162: "<=", ">").
    ``span`` also "size - 2" and "(size - 1) / 2" (r162 M1: offsets short of the last centre)."""

    def classify_block(xy, x0, y0, size):
        v = np.asarray(xy, dtype=float)
        px, py = np.asarray(x0) + start, np.asarray(y0) + start
        area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
        if area == 0:
            return np.full(px.shape, "rejected")
        if (area > 0) if orient == "flipped" else (area < 0 and orient):
            v = v[[0, 2, 1]]
        d = {"size - 1": size - 1, "size": size, "one": 1, "size / 2": size / 2,
             "size - 2": size - 2, "(size - 1) / 2": (size - 1) / 2}[span]  # fmt: skip
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
            if bias is not None:  # the set-up's bias: one sign test each, as llvmpipe's
                # (r232: added after the offset, where it is exact; added to E₀ first it is
                # lost to float64's rounding at the far ties, another mistake)
                beta = 0.0 if top_left else bias
                rejected |= (e0 + R - beta < 0) if ops[0] == "<" else (e0 + R - beta <= 0)
                accepted &= (e0 + T - beta >= 0) if ops[1] == ">=" else (e0 + T - beta > 0)
                continue
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
    # ex30a: the top-left rule folded into a bias (the task's sign tests) of the wrong size
    "bias of 1/256 px²": (
        student(bias=2.0**-8), "tie-rule bias too large", "a bias of the wrong size"),
    "bias of 1 px²": (
        student(bias=1.0), "tie-rule bias too large", "a bias of the wrong size"),
    # r149 M4: a bias of the right size with the wrong sign covers a centre 1/65536 px² outside
    # a right edge (the case "far out, ... outside a right edge"), and is named so
    "bias added, not subtracted": (
        student(bias=-(2.0**-16)), "tie-rule bias added", "your bias has the wrong sign"),
    "bias of 1/2 px²": (
        student(bias=0.5), "tie-rule bias too large", "a bias of the wrong size"),
    # r162 M1: offsets that stop short of the block's last centre were told "Corners outside
    # the triangle do not reject a block" or "you tested the maximising one"
    "offsets of size - 2 steps": (
        student(span="size - 2", bias=2.0**-16), "offsets of size − 2 steps",
        "your offsets span size − 2 steps"),
    "half span from the first centre": (
        student(span="(size - 1) / 2", bias=2.0**-16), "half span from the first centre",
        "your offsets span (size − 1)/2 steps from the first centre"),
    # r162: the sign tests' comparisons slipped were told only the rule
    "reject test with <=": (
        student(bias=2.0**-16, ops=("<=", ">=")), "reject test E ≤ 0",
        "your reject test rejects when E₀ + R + β ≤ 0"),
    "accept test with >": (
        student(bias=2.0**-16, ops=("<", ">")), "accept test E > 0",
        "your accept test asks E₀ + T + β > 0"),
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
    # every failing case of a single slip is that slip's (or an engine's constant note); r248
    # F1: these students count in float64 pixels, a second slip of their own, which the far
    # float64 ties name (and only they)
    far = [f for f in report.failures if f.case.startswith(FLOAT64_TIE)]
    assert {f.kind for f in report.failures if f.kind} - {"float64 pixels"} == {kind}, [f.kind for f in report.failures]  # fmt: skip
    assert all(f in far for f in report.failures if f.kind == "float64 pixels")


#: The labels of the far ties only float64 pixels fail (r248 F1).
FLOAT64_TIE = "far out in float64"


def test_a_constant_text_is_named_by_the_engine():
    report = ex.check("classify_block", lambda *a: "partial", budget=120)
    assert "returns 'partial' on every case" in report.failures[0].explanation


def classify_block_integer_bias(xy, x0, y0, size):
    """The right answer as llvmpipe's set-up writes it (ex30a): integer units of 1/256 px,
    E in units² (exact Python ints), the top-left rule a bias of −1 unit² off the top and
    left edges, each block decided by sign tests only; one block at a time."""
    v = [(round(x * 256), round(y * 256)) for x, y in np.asarray(xy, dtype=float).tolist()]
    area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])
    if area < 0:
        v = [v[0], v[2], v[1]]
    planes = []
    for k in range(3):
        (ax, ay), (bx, by) = v[k], v[(k + 1) % 3]
        a, b = ay - by, bx - ax  # per unit step; a pixel step is 256 units
        bias = 0 if (by < ay or (by == ay and bx > ax)) else -1
        n = 256 * (size - 1)
        planes.append((a, b, ax, ay, bias, n * (max(a, 0) + max(b, 0)), n * (min(a, 0) + min(b, 0))))  # fmt: skip
    out = []
    for bx0, by0 in zip(np.ravel(x0).tolist(), np.ravel(y0).tolist(), strict=True):
        if area == 0:
            out.append("rejected")
            continue
        px, py = 256 * bx0 + 128, 256 * by0 + 128
        e0 = [a * (px - ax) + b * (py - ay) + bias for a, b, ax, ay, bias, _, _ in planes]
        if any(e + p[5] < 0 for e, p in zip(e0, planes, strict=True)):
            out.append("rejected")
        elif all(e + p[6] >= 0 for e, p in zip(e0, planes, strict=True)):
            out.append("accepted")
        else:
            out.append("partial")
    return np.array(out).reshape(np.shape(x0))


@pytest.mark.parametrize(
    "fn", [classify_block_units, classify_block_loops, classify_block_four_corners,
           classify_block_integer_bias],
    ids=["numpy, integer units", "loops (Fractions)", "loops, four corners",
         "integer units, bias of 1 unit²"],
)  # fmt: skip
def test_correct_but_different_solutions_pass(fn):
    report = ex.check("classify_block", fn, budget=120)
    assert report.passed, str(report)


@pytest.mark.parametrize(
    "fn", [classify_block_offsets, student(), student(bias=2.0**-16)],
    ids=["numpy offsets", "numpy, written here", "numpy, the bias of 2^-16 px²"],
)  # fmt: skip
def test_float64_pixels_fail_the_far_float64_ties_only(fn):
    """r248 F1: right in exact arithmetic, these passed every case; float64 rounds E₀ once
    its products pass 2^37 px², and the far float64 ties show it, named so."""
    report = ex.check("classify_block", fn, budget=120)
    assert report.failures and all(f.case.startswith(FLOAT64_TIE) for f in report.failures)
    assert {f.kind for f in report.failures} == {"float64 pixels"}, str(report)


def test_float32_passes_where_it_is_exact_and_is_named_where_not(full_words):
    report = ex.check("classify_block", classify_block_float32, budget=120)
    assert report.failures, "float32 should round the 1/65536 px² ties 3000 px out"
    # (r248 F1: and the far float64 ties, which float32 rounds all the more)
    assert all(f.case.startswith(("far out, a centre 1/65536", FLOAT64_TIE))
               for f in report.failures), [f.case for f in report.failures]  # fmt: skip
    assert report.failures[0].case.startswith("far out, a centre 1/65536")
    assert all("in float32" in f.explanation for f in report.failures
               if not f.case.startswith(FLOAT64_TIE))  # fmt: skip


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
                  "E₀ + R + β < 0", "E₀ + T + β ≥ 0", "lp_rast_tri.c", "a bias β",
                  "(../10_tiles_and_hierarchical_z.ipynb)", "lp_setup_tri.c", "Larrabee",
                  "either winding", "zero-area triangle", "top-left rule", "integer NumPy arrays",
                  "a little\nover a thousand blocks at most"):  # fmt: skip
        # r214: the words as read (the task was re-wrapped when trimmed)
        assert " ".join(words.split()) in " ".join(task.split()), words
    for answer in ("(s - 1)", "size - 1) *", "max(A, 0)", "int(step_down > 0)", "2^-16",
                   "1/65536", "number of steps times"):  # fmt: skip
        assert answer not in task, answer


def test_lesson_10_prints_no_corner_formula():
    """ex30a: lesson 10 §1 printed the corner as ``row0 + (s - 1) * int(step_down > 0)``, the
    offsets 8.1 asks for; it now finds the extremes by looking at every value."""
    lesson = NOTEBOOK.parents[1] / "10_tiles_and_hierarchical_z.ipynb"
    cell = "".join(json.loads(lesson.read_text())["cells"][3]["source"])
    assert "values.argmax()" in cell and "values.argmin()" in cell
    for formula in ("(s - 1) * int(", "int(step_down", "int(step_right", "max(step"):
        assert formula not in cell, formula


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


@pytest.mark.parametrize("spent", [False, True], ids=["first try", "hints spent"])
def test_the_hiz_figure_draws_the_box_and_where_the_bound_is_taken(spent):
    """ex30a: 8.2's figure drew neither the triangle's bounding box nor the centre where the
    bound is taken before the hints were spent; the box now on every try, the centre (from
    the checker's own :func:`hiz_tile.bound_site`) once the hints are spent (r173 G1: on the
    first try it answered the words' question), with a legend, in a column-wide figure."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Rectangle

    from teachraster.exercises import hiz_tile
    from teachraster.plotting.style import COLUMN_WIDTH_PX

    case = hiz_tile.hiz_cases()[4]
    xyz, row0, col0, size, _ = case[1]
    (tries.spend_hints(["hiz_rejects"]) if spent else tries.forget_hints("hiz_rejects"))
    try:
        fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
        hiz_tile.draw_hiz(ax, case, not case[2])
        box = [p for p in ax.patches if isinstance(p, Rectangle) and p.get_linestyle() == "--"]
        lo, hi = xyz[:, :2].min(axis=0), xyz[:, :2].max(axis=0)
        assert len(box) == 1 and np.allclose(box[0].get_xy(), lo)
        assert np.isclose(box[0].get_width(), hi[0] - lo[0])
        assert np.isclose(box[0].get_height(), hi[1] - lo[1])
        row, col, _, _ = hiz_tile.bound_site(xyz, row0, col0, size)
        star = [line for line in ax.lines if line.get_marker() == "*"]
        keys = [t.get_text() for t in ax.get_legend().get_texts()]
        # r162 D4: a box whose sides all lie beyond the view (this one's) is said in words
        assert "the triangle" in keys and "its bounding box: beyond this view" in keys, keys
        # r173 G1: the star and its legend (where the bound is taken, and whether the nearest
        # vertex sets it) answer the task: only once the hints are spent
        site = [k for k in keys if k.startswith("where the bound is taken")]
        if spent:
            assert len(star) == 1 and (star[0].get_xdata()[0], star[0].get_ydata()[0]) == (col + 0.5, row + 0.5)  # fmt: skip
            assert site, keys
        else:
            assert not star and not site and not any("vertex" in k for k in keys), keys
        assert fig.get_size_inches()[0] * fig.dpi <= COLUMN_WIDTH_PX
    finally:
        plt.close("all")
        tries.forget_hints("hiz_rejects")


def test_the_bound_site_is_the_checkers_bound():
    """The figure's centre is where :func:`hiz_tile.lower_bound` is taken: the plane there,
    no nearer than the nearest vertex, is the bound, for every case with a centre in the box."""
    from teachraster.exercises import hiz_tile

    seen = 0
    for _, (xyz, row0, col0, size, _), _ in hiz_tile.hiz_cases():
        site = hiz_tile.bound_site(xyz, row0, col0, size)
        if site is None:
            assert hiz_tile.lower_bound(xyz, row0, col0, size) == np.inf
            continue
        row, col, bound, _ = site
        assert row0 <= row < row0 + size and col0 <= col < col0 + size
        assert bound == hiz_tile.lower_bound(xyz, row0, col0, size)
        at = float(hiz_tile.plane_at(xyz, np.array([row]), np.array([col]))[0])
        # the renderer's plane is clamped to the vertices' depths: beyond the farthest, the
        # bare plane is the bound (hiz_tile._bound_at)
        assert bound == at or at >= xyz[:, 2].max(), (bound, at)
        seen += 1
    assert seen > 10
