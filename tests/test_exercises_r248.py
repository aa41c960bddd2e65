"""r248 (exercise 08_tiles): a fresh read playing 60 + 30 students.

F1 (wrongly passed 1, 2): float64 pixels passed all 56 cases of 8.1, with E > 0 / E ≥ 0 written
out per edge or with the bias added after the offset (the check's own advice, "(E₀ + R) + β
... are exact"): every far tie had whole-pixel vertices. Six far ties with 1/256 vertices
(:data:`tile_blocks.FLOAT64_TIES`, the reader's first) now fail every float form tried, named
"float64 pixels" with the cause (products exact only below 2^37 px²); the false advice is gone.
Half-named 1-8: int32 units, a missing accept or reject offset, A's sign lost in the offsets,
llvmpipe's +1 without its −1, the verdict texts swapped, a bias of −0.5 units, and 8.2's
"nearest vertex" read on screen are each named by their cause. S1: a case that gave no answer
quotes its call (8.2) and the traceback's last line in the student's code; 8.1's labels are a
call. C1: lesson 10 §4 counts on a GPU's 256-unit grid, its walker keeps 512. S2: an empty
pixel read as GL's clear value 1.0 passes too. FIG1, S4: the inset's labels inside its frame,
the box's key, the units and the marked pixel's key.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from exercise_solutions import classify_block_loops, classify_block_units
from graded_cells import flat, graded_cell
from test_exercises_r149 import full_words, plt  # noqa: F401
from test_exercises_r162 import first_words  # noqa: F401
from test_exercises_r198 import _hiz_variant, _variant

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import block_arithmetic, hiz_tile, tile_blocks

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks/exercises/08_tiles.ipynb"
LESSON_10 = ROOT / "notebooks/10_tiles_and_hierarchical_z.ipynb"
#: The reader's far tie: the block's best centre (0.5, 131071.5) exactly on a right edge.
READER_TIE = (
    [(-276483.12109375, -153034.4765625), (805634.4921875, 958915.953125),
     (-92323.4140625, 497252.1015625)], 0, 0, 131072,
)  # fmt: skip


def _kinds(report) -> set[str]:
    return {f.kind for f in report.failures}


def float_pixels(form: str = "delta", bias: str = "written", no_t: bool = False):
    """classify_block in float64 pixels, right in exact arithmetic: E as A·(x − x₁) + B·(y − y₁)
    ("delta"), the conventions' (x₂ − x₁)(y − y₁) − (y₂ − y₁)(x − x₁) ("conv") or A·x + B·y + C
    ("abc"); the tie rule as E > 0 / E ≥ 0 per edge ("written", the reader's first), as a bias
    of −2^-16 px² after the offset ("after", the reader's second, the check's old advice) or E
    evaluated at the extreme centres themselves ("corner"); ``no_t``: a second slip, the accept
    test without its offset."""

    def classify_block(xy, x0, y0, size):
        v = np.asarray(xy, dtype=float)
        px, py = np.asarray(x0) + 0.5, np.asarray(y0) + 0.5
        area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
        if area == 0:
            return np.full(px.shape, "rejected")
        if area < 0:
            v = v[[0, 2, 1]]
        rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            A, B, d = a[1] - b[1], b[0] - a[0], size - 1
            R, T = d * (max(A, 0) + max(B, 0)), (0 if no_t else d * (min(A, 0) + min(B, 0)))
            top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])

            def e(x, y, a=a, b=b, A=A, B=B):
                if form == "delta":
                    return A * (x - a[0]) + B * (y - a[1])
                if form == "conv":
                    return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
                return A * x + B * y - (A * a[0] + B * a[1])

            if bias == "corner":
                hi = e(px + (d if A > 0 else 0), py + (d if B > 0 else 0))
                lo = e(px + (d if A < 0 else 0), py + (d if B < 0 else 0))
            else:
                hi, lo = e(px, py) + R, e(px, py) + T
            if bias == "after":
                beta = 0.0 if top_left else -(2.0**-16)
                rejected |= hi + beta < 0
                accepted &= lo + beta >= 0
            else:
                rejected |= (hi < 0) if top_left else (hi <= 0)
                accepted &= (lo >= 0) if top_left else (lo > 0)
        return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))

    return classify_block


FLOAT_FORMS = [(f, b) for f in ("delta", "conv", "abc") for b in ("written", "after", "corner")]


# -- F1: float64 pixels ---------------------------------------------------------------------------


def test_f1_the_readers_tie_is_a_case_and_every_exact_answer_agrees():
    cases = [c for c in tile_blocks.block_cases() if c[0].startswith("far out in float64")]
    assert len(cases) == len(tile_blocks.FLOAT64_TIES) == 6
    xy, x0, y0, size = READER_TIE
    first = cases[0][1]
    assert np.array_equal(first[0], xy) and first[3] == size
    assert (first[1].tolist(), first[2].tolist()) == ([[x0]], [[y0]])
    assert str(cases[0][2][0, 0]) == "rejected"
    model = _variant()
    for label, args, want in cases:
        for fn in (model, classify_block_units, classify_block_loops):
            assert np.array_equal(np.asarray(fn(*args)), want), label
        # each decided at a centre on an edge or a few 2^-16 px² from it, where float64's
        # products are inexact: E₀'s products past 2^37 px²
        edge, t, key = block_arithmetic.float64_slip(args[0], int(args[1][0, 0]), int(args[2][0, 0]), args[3])  # fmt: skip
        assert abs(t[key]) <= 5 and max(abs(v) for v in t["terms"][:2]) > 2**53, label
    # the reader's numbers: E₀ + R exactly 0 in integers, 3.05·10⁻⁵ px² in float64
    edge, t, key = block_arithmetic.float64_slip(np.array(xy), x0, y0, size)
    assert (key, t["best"], edge["top_left"]) == ("best", 0, False)
    assert t["e0"] / 65536 == pytest.approx(-141834237690.39, abs=0.01)


@pytest.mark.parametrize(("form", "bias"), FLOAT_FORMS, ids=[f"{f}-{b}" for f, b in FLOAT_FORMS])
def test_f1_every_float64_form_fails_the_new_ties(form, bias):
    fn = float_pixels(form, bias)
    wrong = [label for label, args, want in tile_blocks.block_cases()
             if label.startswith("far out in float64") and not np.array_equal(fn(*args), want)]  # fmt: skip
    assert len(wrong) >= 3, (form, bias, wrong)
    # the last two (one-pixel blocks, a centre a few 2^-16 px² off an edge) fail every form
    assert all(any(label.startswith(c[0]) for label in wrong)
               for c in tile_blocks.block_cases()[-2:]), wrong  # fmt: skip


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("bias", ["written", "after"])
def test_f1_the_readers_two_float_answers_fail_named_by_their_cause(bias, words, request):
    request.getfixturevalue(words)
    report = ex.check("classify_block", float_pixels("delta", bias), budget=120)
    assert not report.passed and _kinds(report) == {"float64 pixels"}, str(report)
    first = report.failures[0]
    assert first.case.startswith("far out in float64: a 131,072-px block")
    said = first.explanation
    assert said.index("you computed in float64 pixels") < said.index("2^37 px²"), said
    for part in ("the block's centre (0.5, 131071.5) lies exactly on that edge (E = 0)",
                 "it comes out at 3.05·10⁻⁵ px², not 0", "No bias helps, added before the "
                 "offset or after it", "Count in integer units"):  # fmt: skip
        assert part in said, said


def test_f1_a_slip_in_float64_pixels_is_named_with_float64_on_the_far_ties():
    """A second slip beside another: each named on its own cases (Mistake.with_others)."""
    never_adds_t = float_pixels("delta", "written", no_t=True)
    report = ex.check("classify_block", never_adds_t, budget=120)
    assert _kinds(report) == {"no accept offset", "float64 pixels"}, str(report)
    floats = [f for f in report.failures if f.kind == "float64 pixels"]
    assert floats and all(f.case.startswith("far out in float64") for f in floats)
    assert report.failures[0].kind == "no accept offset"


def test_f1_a_random_answer_is_never_told_float64():
    """Its verdicts at the far float64 ties are no cause while its other failures are named by
    none (r248: they were, by coincidence, before float64 asked for the rest)."""
    import random

    for seed in range(4):
        rng = random.Random(seed)
        report = ex.check("classify_block", lambda *a, rng=rng: rng.choice(tile_blocks.KINDS), budget=120)  # fmt: skip
        assert "float64 pixels" not in _kinds(report), (seed, str(report))


def test_f1_the_checkers_false_advice_is_gone():
    """'(E₀ + T) + β and (E₀ + R) + β are exact' and 'float64 ... holds them exactly'."""
    report = ex.check("classify_block", _float_bias_first(), budget=120)
    text = " ".join(f.explanation for f in report.failures)
    assert "are exact), or count" not in text and "Adding it after the offset is no cure" in text
    assert _kinds(report) == {"bias lost to rounding", "float64 pixels"}, str(report)
    words = tile_blocks.FLOAT32.say(None, None, None)
    assert "which holds them exactly" not in words and "only below 2^37 px²" in words


def _float_bias_first():
    """r232's float model solution: the bias added to E₀ before the offsets."""
    inner = float_pixels("delta", "written")

    def classify_block(xy, x0, y0, size):
        v = np.asarray(xy, dtype=float)
        px, py = np.asarray(x0) + 0.5, np.asarray(y0) + 0.5
        area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
        if area == 0:
            return inner(xy, x0, y0, size)
        if area < 0:
            v = v[[0, 2, 1]]
        rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            A, B = a[1] - b[1], b[0] - a[0]
            R = (size - 1) * (max(A, 0) + max(B, 0))
            T = (size - 1) * (min(A, 0) + min(B, 0))
            top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            e0 = A * (px - a[0]) + B * (py - a[1]) + (0.0 if top_left else -1e-12)
            rejected |= e0 + R < 0
            accepted &= e0 + T >= 0
        return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))

    return classify_block


def test_f1_the_task_quotes_the_printed_limit():
    printed = tile_blocks.float64_limit()
    task = flat(graded_cell(NOTEBOOK, "classify_block_task"))
    for number in ("2³⁷ px²", "370,728 px", "2,000,000 px"):
        assert number in printed and number in task, number
    assert "beyond, a tie goes either way, bias or not" in task
    assert "print(float64_limit())" in graded_cell(NOTEBOOK, "setup")


# -- C1: 256 units on a GPU's grid, 512 in the walker ---------------------------------------------


def test_c1_the_task_says_what_lesson_10s_walker_keeps():
    task = flat(graded_cell(NOTEBOOK, "classify_block_task"))
    assert ("as lesson 10 §4 counts, on a GPU's grid of 256 units a pixel (the package's "
            "walker keeps 512)") in task  # fmt: skip
    assert "lesson 10 §4's walker does" not in task
    lesson = " ".join(flat("".join(c["source"])) for c in json.loads(LESSON_10.read_text())["cells"])  # fmt: skip
    # §4 counts and walks in int32 on a GPU's grid (256 units a pixel); the simulator's own
    # grid (512 units a pixel, printed from units_per_pixel) is named beside it
    assert "The simulator's own grid" in lesson and "units_per_pixel(8)" in lesson
    assert "on a GPU's grid, 256 units a pixel (§4's count), not the simulator's 512" in lesson
    assert "Count on a GPU's own grid" in lesson and "**256 units a pixel**" in lesson
    assert "walker does" not in graded_cell(NOTEBOOK, "classify_block_solution")


# -- half-named: each slip by its cause -----------------------------------------------------------

_REJECT, _ACCEPT = "rejected |= e0 + R < 0", "accepted &= e0 + T >= 0"
#: (the student, the kind, words the first explanation holds)
SLIPS = {
    "int32 units": (_variant(("astype(np.int64)", "astype(np.int32)")), "int32 wrap",
                    "your values passed 2^31 and wrapped (lesson 10 §4)"),
    "int32 everywhere": (
        _variant(("astype(np.int64)", "astype(np.int32)"),
                 ("px, py = np.asarray(x0) * 256 + 128, np.asarray(y0) * 256 + 128",
                  "px, py = np.asarray(x0).astype(np.int32) * 256 + 128, "
                  "np.asarray(y0).astype(np.int32) * 256 + 128")),
        "int32 wrap", "your values passed 2^31 and wrapped"),
    "no T in the accept test": (_variant((_ACCEPT, "accepted &= e0 >= 0")), "no accept offset",
                                "your accept test never adds T"),
    "no R in the reject test": (_variant((_REJECT, "rejected |= e0 < 0")), "no reject offset",
                                "your reject test never adds R"),
    "A's sign lost in the offsets": (
        _variant(("R = step * (max(A, 0) + max(B, 0))", "R = step * (max(b[1] - a[1], 0) + max(B, 0))"),
                 ("T = step * (min(A, 0) + min(B, 0))", "T = step * (min(b[1] - a[1], 0) + min(B, 0))")),
        "A's sign lost in the offsets", "your offsets take A = y₂ − y₁, with its minus sign lost"),
    "llvmpipe's +1 only": (
        _variant(("beta = 0 if top_left else -1", "beta = 1 if top_left else 0")),
        "llvmpipe's +1 without its −1",
        "you took llvmpipe's +1 on the constant of a left or top edge but not its −1"),
    "verdict texts swapped": (
        _variant(('np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))',
                  'np.where(rejected, "accepted", np.where(accepted, "rejected", "partial"))')),
        "verdicts swapped", "your verdicts are the right ones under each other's names"),
    "a bias of −0.5 units": (
        _variant(("beta = 0 if top_left else -1", "beta = 0 if top_left else -0.5")),
        "bias not a whole number of units", "your bias is not a whole number of units"),
}  # fmt: skip


def test_hn1_int32_is_named_only_where_the_code_reads_int32():
    """A student in float64 pixels fails the same far cases: not told int32."""
    report = ex.check("classify_block", float_pixels(), budget=120)
    assert "int32 wrap" not in _kinds(report)


def test_hn7_the_half_unit_bias_is_not_told_to_count_in_integers():
    fn = SLIPS["a bias of −0.5 units"][0]
    report = ex.check("classify_block", fn, budget=120)
    for f in report.failures:
        assert "count in integer units" not in f.explanation.lower(), f.explanation
        assert "(which whole number is it?)" in f.explanation
        assert "on that edge, neither top nor left" in f.explanation


SCREEN = {
    "to the tile": ("lo = np.array([col0, row0]); hi = lo + size; "
                    "g = np.maximum(lo - v, 0) + np.maximum(v - hi, 0)", "vertex nearest on screen"),
    "to its middle": ("g = v - np.array([col0 + size / 2, row0 + size / 2])",
                      "vertex nearest the tile's middle"),
}  # fmt: skip


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("how", list(SCREEN))
def test_hn8_the_vertex_nearest_on_screen_is_named(how, words, request):
    request.getfixturevalue(words)
    gap, kind = SCREEN[how]
    fn = _hiz_variant(("nearest = max(corners.min(), min(z1, z2, z3))",
                       f"v = np.array([[x1, y1], [x2, y2], [x3, y3]]); {gap}; "
                       "nearest = max(corners.min(), (z1, z2, z3)[int(np.argmin(np.hypot(*g.T)))])"))  # fmt: skip
    report = ex.check("hiz_rejects", fn, budget=120)
    assert not report.passed and _kinds(report) == {kind}, str(report)
    first = report.failures[0].explanation
    assert "you kept it" in first or "you rejected it" in first
    assert re.search(r"it: you took the depth of the vertex nearest the tile on screen, v\d", first)
    assert '"the nearest vertex" means the one nearest the eye, with the smallest depth' in first


# -- S1: a case that gave no answer quotes its call and the student's line ------------------------

_RAISES = ("return bool(nearest >= np.max(buffer))", "return bool(nearest >= buffer[size, 0])")


@pytest.mark.parametrize(("edit", "error"), [
    (_RAISES, "your function raised IndexError: index "),
    (("return bool(nearest >= np.max(buffer))", "nearest >= np.max(buffer)"),
     "your function returned None"),
    (("return bool(nearest >= np.max(buffer))", "return float('nan')"),
     "your function returned the number nan"),
], ids=["exception", "None", "NaN"])  # fmt: skip
def test_s1_82_lines_without_an_answer_quote_a_call_that_reruns_it(edit, error):
    report = ex.check("hiz_rejects", _hiz_variant(edit), budget=120)
    cases = {c[0]: c[1] for c in hiz_tile.hiz_cases()}
    said = [f for f in report.failures if f.got is None]
    assert said, str(report)
    for f in said:
        call, _, rest = f.explanation.partition(": your function")
        assert ("your function" + rest).startswith(error), f.explanation
        assert call.endswith("hiz_rejects(xyz, row0, col0, size, buffer)"), call
        if "drawn at random" in call:
            continue
        space = {"np": np, "hiz_rejects": lambda *a: a}
        exec(call.replace("hiz_rejects(", "args = hiz_rejects("), space)  # noqa: S102
        for mine, theirs in zip(space["args"], cases[f.case], strict=True):
            assert np.array_equal(mine, theirs), f.case


def test_s1_an_exception_shows_the_traceback_line_in_the_students_code(tmp_path):
    source = "def hiz_rejects(xyz, row0, col0, size, buffer):\n    b = buffer\n    return bool(b[8, 0] > 0)\n"  # fmt: skip
    path = tmp_path / "cell.py"
    path.write_text(source)
    space = {}
    exec(compile(source, str(path), "exec"), space)  # noqa: S102
    report = ex.check("hiz_rejects", space["hiz_rejects"], budget=120)
    raised = [f for f in report.failures if f.kind == "raised"]
    assert raised
    for f in raised:
        assert f.explanation.endswith("; the traceback's last line in your code: line 3, in "
                                      "hiz_rejects: `return bool(b[8, 0] > 0)`"), f.explanation  # fmt: skip


def test_s1_one_exception_object_raised_on_every_case_names_its_line_on_each(tmp_path):
    """One exception object raised again on every case (a module-level ``ERROR``) names the
    same line on each, and is left without the cases' frames: its traceback grew by a case's
    frames at every raise, and describing it walked them all (quadratic: 3/4 of
    test_checker_truth's CPU)."""
    source = "ERROR = IndexError('row 8')\ndef hiz_rejects(xyz, row0, col0, size, buffer):\n    raise ERROR\n"  # fmt: skip
    path = tmp_path / "cell.py"
    path.write_text(source)
    space = {}
    exec(compile(source, str(path), "exec"), space)  # noqa: S102
    report = ex.check("hiz_rejects", space["hiz_rejects"], budget=120)
    raised = [f for f in report.failures if f.kind == "raised"]
    assert len(raised) > 1, str(report)
    for f in raised:
        assert f.explanation.endswith("; the traceback's last line in your code: line 3, in "
                                      "hiz_rejects: `raise ERROR`"), f.explanation  # fmt: skip
    assert space["ERROR"].__traceback__ is None


def test_s1_81_labels_are_a_call_that_reruns_the_case():
    for label, args, _ in tile_blocks.block_cases():
        call = label.split(": xy = ", 1)[1]
        assert call.endswith(f"classify_block(xy, x0, y0, {args[3]})"), label
        space = {"np": np, "classify_block": lambda *a: a}
        exec("xy = " + call.replace("classify_block(", "got = classify_block("), space)  # noqa: S102
        for mine, theirs in zip(space["got"], args, strict=True):
            assert np.array_equal(mine, theirs), label


def test_s1_81_the_first_block_says_where_it_sits_in_the_answer():
    report = ex.check("classify_block", SLIPS["no T in the accept test"][0], budget=120)
    assert "the first, at [1, 1], x0=8, y0=8, size=4" in report.failures[0].explanation


# -- S2: an empty pixel as +inf or as GL's clear value ---------------------------------------------


def test_s2_an_empty_pixel_read_as_gls_clear_value_passes():
    gl = _hiz_variant(("return bool(nearest >= np.max(buffer))",
                       "return bool(nearest >= np.max(np.where(np.isinf(buffer), 1.0, buffer)))"))  # fmt: skip
    assert ex.check("hiz_rejects", gl, budget=120).passed
    assert ex.check("hiz_rejects", _hiz_variant(), budget=120).passed
    # the two readings differ only for a triangle at exactly depth 1.0: both accepted there
    flat_far = np.array([[0.0, 0.0, 1.0], [40.0, 0.0, 1.0], [0.0, 40.0, 1.0]])
    buffer = np.full((8, 8), 0.45)
    buffer[5, 2] = np.inf
    args = (flat_far, 8, 8, 8, buffer)
    assert not hiz_tile.expected_reject(*args)
    assert hiz_tile.same_verdict(True, False, args) and hiz_tile.same_verdict(False, False, args)


def test_s2_the_task_states_both_conventions_and_the_package_draws_at_one():
    task = flat(graded_cell(NOTEBOOK, "hiz_rejects_task"))
    for said in ("An empty pixel holds `np.inf` in the check's buffers (*not yet known*, as in "
                 "lesson 10's replay and the package's z-buffer, where a fragment at 1.0 passes)",
                 "GL holds its clear value, 1.0 (lesson 05a), which that fragment fails under "
                 "`GL_LESS`", "The two readings differ only at depth 1.0: either passes"):  # fmt: skip
        assert said in task, said
    # what the text says of the package: a full-screen triangle at window depth 1.0 is drawn
    far = tr.render(np.array([[[-1, -1, 1, 1], [3, -1, 1, 1], [-1, 3, 1, 1]]], float), 4, 4)
    assert (far.triangle_id == 0).all() and (far.depth == 1.0).all()


# -- FIG1, S4 --------------------------------------------------------------------------------------


def _hiz_case(label_start: str):
    return next(c for c in hiz_tile.hiz_cases() if c[0].startswith(label_start))


def test_fig1_the_insets_labels_lie_inside_its_frame(plt):  # noqa: F811
    for case in hiz_tile.hiz_cases()[:12]:
        fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
        hiz_tile.draw_hiz(ax, case, case[2])
        fig.canvas.draw()
        renderer = fig.canvas.get_renderer()
        inset = next(c for c in ax.child_axes)
        frame = inset.get_window_extent(renderer)
        for text in inset.texts:
            box = text.get_bbox_patch().get_window_extent(renderer) if text.get_bbox_patch() else text.get_window_extent(renderer)  # fmt: skip
            assert frame.x0 <= box.x0 and box.x1 <= frame.x1, (case[0], text.get_text())
            assert frame.y0 <= box.y0 and box.y1 <= frame.y1, (case[0], text.get_text())
        plt.close(fig)


def test_fig1_the_box_beyond_the_view_has_a_dashed_key(plt):  # noqa: F811
    case = _hiz_case("a flat triangle behind a full tile")
    fig, ax = plt.subplots(figsize=(9.0, 5.6), layout="constrained")
    hiz_tile.draw_hiz(ax, case, case[2])
    legend = ax.get_legend()
    handle = next(h for h, t in zip(legend.legend_handles, legend.get_texts(), strict=True)
                  if t.get_text() == "its bounding box: beyond this view")  # fmt: skip
    assert handle.get_linestyle() == "--" and handle.get_color() == hiz_tile.BOX_COLOUR
    plt.close(fig)


def test_s4_the_scene_says_its_units_and_keys_the_marked_pixel(plt):  # noqa: F811
    report = ex.check("classify_block", SLIPS["no T in the accept test"][0], budget=120)
    fig = plt.figure(figsize=(9.0, 7.8), layout="constrained")
    top, bottom = fig.subfigures(2, 1, height_ratios=(3.3, 4.5))
    case_ax = top.subplots()
    report.plot(case_ax)
    assert case_ax.get_ylabel() == "y (px, down)" and case_ax.get_xlabel().startswith("x (px); ")
    axes = bottom.subplots(1, 3)
    report.compare(axes, pixel="first")
    title = axes[2].get_title().replace("\n", " ")
    assert re.search(r"\d+ pixels? walked differently \(orange\)", title), title
    keys = [t.get_text() for t in axes[1].get_legend().get_texts()]
    assert "the pixel explained below" in keys, keys
    plt.close(fig)


# -- M1: no task 8.3 (noted, not added) -----------------------------------------------------------


def test_m1_the_notebook_still_has_two_tasks_and_both_solutions_pass():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    ids = [c["metadata"].get("nbgrader", {}).get("grade_id") for c in cells]
    assert [i for i in ids if i and i.endswith("_check")] == ["classify_block_check", "hiz_rejects_check"]  # fmt: skip
    assert ex.check("classify_block", _variant(), budget=120).passed
    assert ex.check("hiz_rejects", _hiz_variant(), budget=120).passed


# -- r267: the five half-named slips, each named by its cause first -------------------------------

#: (the student, the kind, words the first explanation holds), 8.1
R267_SLIPS = {
    # cell 3's solution without its cast: np.rint returns float64
    "units held in float64": (
        _variant((".astype(np.int64)", "")), "units held in float64",
        "your units are float64 numbers: np.rint rounds to whole numbers but returns float64"),
    "reject only when every edge fails": (
        _variant(("rejected = np.zeros(px.shape, dtype=bool)",
                  "rejected = np.ones(px.shape, dtype=bool)"),
                 ("rejected |= e0 + R < 0", "rejected &= e0 + R < 0")),
        "reject only when every edge fails",
        "you rejected a block only when every edge fails its reject test"),
}  # fmt: skip


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("slip", [*SLIPS, *R267_SLIPS])
def test_half_named_slips_are_named_by_their_cause_first(slip, words, request):
    """r248's slips (SLIPS) and r267's 8.1 slips (R267_SLIPS), one test for both tables."""
    request.getfixturevalue(words)
    fn, kind, said = {**SLIPS, **R267_SLIPS}[slip]
    with np.errstate(all="ignore"):
        report = ex.check("classify_block", fn, budget=120)
    assert not report.passed and _kinds(report) == {kind}, str(report)
    first = report.failures[0].explanation
    # the case's numbers first, then the cause
    assert re.search(r"yours says (rejected|accepted|partial): " + re.escape(said), first), first


def test_r267_float64_pixels_are_not_told_float64_units():
    """float64 pixels give the very answers of float64 units: only np.rint tells them apart."""
    report = ex.check("classify_block", float_pixels(), budget=120)
    assert "units held in float64" not in _kinds(report)
    assert "float64 pixels" in _kinds(report)


_HIZ_BOX = ("c_lo = max(col0, np.ceil(min(x1, x2, x3) - 0.5))", "c_lo = np.ceil(min(x1, x2, x3) - 0.5)")  # fmt: skip
#: (the student, the kind, words the first explanation holds), 8.2
R267_HIZ_SLIPS = {
    "box not cut to the tile": (
        _hiz_variant(
            _HIZ_BOX,
            ("c_hi = min(col0 + size - 1, np.floor(max(x1, x2, x3) - 0.5))",
             "c_hi = np.floor(max(x1, x2, x3) - 0.5)"),
            ("r_lo = max(row0, np.ceil(min(y1, y2, y3) - 0.5))", "r_lo = np.ceil(min(y1, y2, y3) - 0.5)"),
            ("r_hi = min(row0 + size - 1, np.floor(max(y1, y2, y3) - 0.5))",
             "r_hi = np.floor(max(y1, y2, y3) - 0.5)")),
        "box uncut, whole box empty", "you took the extreme centres of the whole bounding box, "
        "not cut to the tile"),
    "dz/dx and dz/dy swapped": (
        _hiz_variant(("corners = z1 + a * (xs[:, None] - x1) + b * (ys[None, :] - y1)",
                      "corners = z1 + b * (xs[:, None] - x1) + a * (ys[None, :] - y1)")),
        "gradients swapped", "your plane's dz/dx and dz/dy are exchanged"),
    "the plane at the first centre only": (
        _hiz_variant(("corners.min()", "corners[0, 0]")),
        "first centre only", "you took the plane at one centre only"),
}  # fmt: skip


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("slip", list(R267_HIZ_SLIPS))
def test_r267_82_half_named_slips_are_named_by_their_cause_first(slip, words, request):
    request.getfixturevalue(words)
    fn, kind, said = R267_HIZ_SLIPS[slip]
    report = ex.check("hiz_rejects", fn)
    assert not report.passed and _kinds(report) == {kind}, str(report)
    first = report.failures[0].explanation
    assert re.search(r"you (rejected|kept) it: " + re.escape(said), first), first


def test_r267_the_nearest_vertex_alone_is_not_told_the_uncut_box():
    fn = _hiz_variant(("nearest = max(corners.min(), min(z1, z2, z3))", "nearest = min(z1, z2, z3)"))  # fmt: skip
    report = ex.check("hiz_rejects", fn)
    assert _kinds(report) == {"vertex"}, str(report)
    assert "uncut" not in report.failures[0].explanation


def test_r267_m2_a_standards_table_with_lessons_02_and_10s_sections():
    task = "".join(json.loads(NOTEBOOK.read_text())["cells"][5]["source"])
    rows = {line.split("|")[1].strip(): line for line in task.splitlines() if line.startswith("| ")}
    assert {"OpenGL 4.6", "Direct3D 11", "Vulkan", "llvmpipe (Mesa)", "teachraster"} <= set(rows)
    lessons = "".join(
        "".join(c["source"])
        for f in (ROOT / "notebooks/02_half_planes.ipynb", LESSON_10)
        for c in json.loads(f.read_text())["cells"]
    )
    # every section the table quotes is one lessons 02 and 10 give
    for section in ("§14.6.1", "§3.4.2.1 *Top-Left Rule*", "*Basic Polygon Rasterization*",
                    "§14.9, *Early Per-Fragment Tests*", "§16.12.2", "*Fragment Operations*"):  # fmt: skip
        assert section in task and section in lessons, section
