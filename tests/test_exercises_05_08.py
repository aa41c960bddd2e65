"""Exercises 05–08 (issue 20): principled references, explanations, pictures and notebooks.

The generic promises (independent and other correct solutions pass, each typical mistake is
caught and explained, reports draw) run for these exercises too in ``test_exercises.py``,
from the solutions at the end of ``exercise_solutions.py``.
"""

from __future__ import annotations

import json
import math
import re
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from conftest import sample
from exercise_solutions import CORRECT, MISTAKES

from teachraster import exercises as ex
from teachraster.exercises import (
    antialiasing,
    depth_precision,
    level_of_detail,
    texture_filtering,
    tile_blocks,
)
from teachraster.exercises.coverage import covered
from teachraster.exercises.student_version import student_notebook

LATER = ["depth_to_unorm", "coverage_fraction", "resolve", "resolve_srgb", "mip_level", "bilinear",
         "trilinear", "classify_block"]  # fmt: skip
NOTEBOOKS = sorted(
    (Path(__file__).resolve().parent.parent / "notebooks" / "exercises").glob("0[5-8]_*.ipynb")
)


def test_the_new_exercises_follow_the_first_eight():
    assert ex.names()[8 : 8 + len(LATER)] == LATER


# -- references: exact, independent of the package's own arithmetic --------------------------
def test_depth_reference_is_the_exactly_rounded_product_or_a_tie():
    for _, (z, bits), expected in depth_precision.depth_cases():
        exact = Fraction(z) * (2**bits - 1)
        low = math.floor(exact)
        nearest = low + (exact - low > Fraction(1, 2))
        if exact - low != Fraction(1, 2) and abs(exact - low - Fraction(1, 2)) > 1e-6:
            assert expected == nearest and depth_precision.accepted(z, bits) == (nearest,)
        else:
            assert set(depth_precision.accepted(z, bits)) == {low, low + 1}


def test_at_an_exact_half_either_neighbour_passes_and_only_there():
    assert ex.check("depth_to_unorm", lambda z, b: math.floor(z * (2**b - 1) + 0.5)).passed
    assert ex.check("depth_to_unorm", lambda z, b: math.ceil(z * (2**b - 1) - 0.5)).passed
    off_by_one = ex.check("depth_to_unorm", lambda z, b: round(z * (2**b - 1)) + (z == 0.25))
    assert len(off_by_one.failures) == 2  # z = 0.25 with 16 and with 24 bits


def test_coverage_cases_hold_the_hard_ones_and_snapping_decides_some():
    cases = antialiasing.coverage_cases()
    labels = " ".join(label for label, _, _ in cases)
    for words in ("on a left edge", "on a right edge", "on a top edge", "on a bottom edge",
                  "a vertex on sample", "off the grid", "rounds to even", "zero area",
                  "counter-clockwise", "random"):  # fmt: skip
        assert words in labels
    decided_by_snapping = [
        label
        for label, (xy, pixel, samples), expected in cases
        if not math.isclose(
            covered(xy, antialiasing.sample_points(pixel, samples), vertices="exact").mean(),
            expected,
        )
    ]
    assert len(decided_by_snapping) >= 3, decided_by_snapping


@pytest.mark.parametrize("raw", [0, 1])
def test_coverage_fraction_snapping_one_coordinate_only_fails_and_is_named(raw):
    """r40 06-1 (issue 30): x snapped and y left raw passed all 34 cases (every off-grid case
    moved x only); a vertex 1/1024 px off the grid in y now decides two cases."""
    from teachraster import edge_function

    def one_axis(xy, pixel, samples):
        v = np.asarray(xy, float).copy()
        v[:, 1 - raw] = np.rint(v[:, 1 - raw] * 256) / 256  # the other coordinate stays raw
        area = edge_function(v[0], v[1], v[2])
        if area == 0:
            return 0.0
        if area < 0:
            v = v[[0, 2, 1]]
        points = np.asarray(samples, float) + [pixel[1], pixel[0]]
        inside = np.ones(len(points), dtype=bool)
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = edge_function(a, b, points)
            top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            inside &= (e >= 0) if top_left else (e > 0)
        return float(inside.mean())

    report = ex.check("coverage_fraction", one_axis)
    assert not report.passed and report.failures, str(report)
    axis = "xy"[raw]
    assert all(f"left {axis} unsnapped" in f.explanation for f in report.failures), str(report)


def _bilinear_with(kind):
    """A bilinear with one slip: weights swapped along x, or repeat done as (u, v) % 1 with
    the texels then clamped."""

    def bilinear(texture, uv, wrap):
        tex = np.asarray(texture, dtype=float)
        h, w = tex.shape[:2]
        u, v = (uv[0] % 1, uv[1] % 1) if kind == "mod" else uv
        x, y = u * w - 0.5, v * h - 0.5
        x0, y0 = np.floor(x), np.floor(y)
        fx, fy = x - x0, y - y0
        cols, rows = np.array([x0, x0 + 1], dtype=int), np.array([y0, y0 + 1], dtype=int)
        if wrap == "repeat" and kind != "mod":
            cols, rows = cols % w, rows % h
        else:
            cols, rows = np.clip(cols, 0, w - 1), np.clip(rows, 0, h - 1)
        if kind == "swap x":
            fx = 1 - fx
        top = (1 - fx) * tex[rows[0], cols[0]] + fx * tex[rows[0], cols[1]]
        bottom = (1 - fx) * tex[rows[1], cols[0]] + fx * tex[rows[1], cols[1]]
        return (1 - fy) * top + fy * bottom

    return bilinear


@pytest.mark.parametrize(("kind", "words"), [
    ("swap x", "the weights along x are swapped"),
    ("mod", "you wrapped (u, v) into [0, 1) and then clamped the texels"),
])  # fmt: skip
def test_bilinear_slips_that_give_one_texel_are_named_not_called_nearest(kind, words):
    """r40 07-1: both were told "that is one texel alone, nearest filtering"."""
    report = ex.check("bilinear", _bilinear_with(kind))
    assert not report.passed
    assert all(words in f.explanation for f in report.failures), str(report)
    assert all("nearest" not in f.explanation for f in report.failures), str(report)


def test_resolve_srgb_needs_the_order_of_decoding_and_names_each_slip():
    """r40 06-2: 6.2's resolve was one line from the text; 6.3 asks where light is needed.
    6.2's resolve handed in here is told it averaged encoded numbers; the 0.735 the text
    quotes is the encoded half of white."""
    import teachraster as tr

    assert round(float(tr.linear_to_srgb(0.5)), 3) == 0.735
    plain = ex.check("resolve_srgb", CORRECT["resolve"])
    assert {f.kind for f in plain.failures} == {"encoded average"}, str(plain)
    half = next(f for f in plain.failures if f.case.startswith("black on white, 2 of 4"))
    assert "(0.735, 0.735, 0.735); yours is (0.5, 0.5, 0.5)" in half.explanation


def test_block_cases_hold_the_corner_tricks_pitfalls():
    # each hard block is the first of its grid
    grids = {label.split(":")[0]: expected for label, _, expected in tile_blocks.block_cases()}
    cases = {label: str(np.asarray(kinds).flat[0]) for label, kinds in grids.items()}
    assert cases["a block beyond a vertex, outside the triangle"] == "partial"
    assert cases["a small triangle inside a big block"] == "partial"
    assert cases["a left edge through the left corners"] == "accepted"
    assert cases["a right edge through the right corners"] == "partial"
    assert cases["one pixel, its centre on a right edge"] == "rejected"
    assert cases["zero area"] == "rejected"
    assert set(cases.values()) == {"rejected", "accepted", "partial"}
    assert all(np.shape(kinds) == np.shape(args[1]) for _, args, kinds in tile_blocks.block_cases())


# -- explanations name the rule and quote the numbers ----------------------------------------
def _first(mistake):
    name, fn, words = MISTAKES[mistake]
    return next(f.explanation for f in ex.check(name, fn).failures if words in f.explanation)


def test_the_issues_three_explanations():
    assert "you sampled at texel corners: texel centres are at (i + ½)/W" in _first(
        "bilinear at texel corners"
    )
    assert (
        "your λ uses the sum of the derivatives; GL takes the longer of the two footprint axes"
        in _first("λ from the sum of the axes")
    )
    text = _first("accept by the maximising corner")
    assert re.search(
        r"this corner, \([\d.]+, [\d.]+\) \(E = -[\d.]+\), is the one that minimises E for edge "
        r"v\d→v\d, and it fails; you tested the maximising one",
        text,
    ), text


def test_explanations_quote_the_case():
    assert _first("depth by truncation") == (
        "in float64 z·(2^16 − 1) = 0.25·65535 = 16383.75; the buffer stores the nearest "
        "integer, 16384; yours is 16383: int() truncates (it drops the fraction); round to the "
        "nearest integer instead"
    )
    text = _first("resolve of covered samples only")
    assert "ids [-1, 0, -1, -1] (1 of 4 samples covered)" in text
    assert "you averaged the 1 covered sample only" in text
    assert "the 3 uncovered ones counting as the background" in text
    assert "(2.3759765625, -1) → (2.375, -1)" in _first("coverage without snapping")
    assert "λ = -2 lies outside the pyramid" in _first("trilinear without clamping λ")


def test_a_wrong_type_is_named():
    report = ex.check("classify_block", lambda xy, x0, y0, size: "Partial")
    assert "expected one of 'rejected', 'accepted', 'partial'" in report.failures[0].explanation
    report = ex.check("resolve", lambda c, i, b: 0.5)
    assert "expected one colour of 3 channels" in report.failures[0].explanation


def test_a_student_writing_into_the_pyramid_changes_nothing():
    def vandal(pyramid, uv, lod, wrap="repeat"):
        for level in pyramid:
            level[...] = 0
        return CORRECT["trilinear"](pyramid, uv, lod, wrap)

    report = ex.check("trilinear", vandal)
    assert not report.passed
    assert ex.check("trilinear", CORRECT["trilinear"]).passed


def test_the_level_of_detail_is_the_packages():
    for _, (dx, dy, size), expected in level_of_detail.level_cases():
        assert math.isclose(expected, CORRECT["mip_level"](dx, dy, size), abs_tol=1e-12)


def test_bilinear_at_a_texel_centre_is_the_texel():
    tex = np.arange(12.0).reshape(3, 4)
    assert texture_filtering.expected_bilinear(tex, (2.5 / 4, 1.5 / 3), "clamp") == 6.0


# -- whole pictures, side by side -------------------------------------------------------------


PICKS = {
    "depth_to_unorm": "depth by truncation",
    "coverage_fraction": "coverage, both edges own a sample",
    "resolve": "resolve of covered samples only",
    "mip_level": "λ from the shorter axis",
    "bilinear": "bilinear at texel corners",
    "trilinear": "trilinear from the nearest level",
    "classify_block": "accept by the maximising corner",
}


#: The exercises of 05–08 with a whole picture (6.3's resolve in linear light has none).
PICTURED = [name for name in LATER if name != "resolve_srgb"]


@pytest.mark.parametrize("name", PICTURED)
def test_compare_shows_yours_the_packages_and_the_differences(name, plt):
    wrong = ex.check(name, MISTAKES[PICKS[name]][1])
    differing = wrong.differing_pixels()
    assert len(differing) > 0
    row, col = differing[0]
    words = wrong.explain_pixel(row, col)
    assert "agree" not in words and len(words) > 40
    fig, axes = plt.subplots(1, 3)
    artists = wrong.compare(axes, pixel="first")
    title = " ".join(axes[2].get_title().split())  # (wrapped to the panel's width)
    covered = wrong.scene.coverage_differs()
    if covered is None:
        assert artists and title.startswith(f"{len(differing)} pixel")
    else:  # r149 E1: the tile walk counts coverage apart from the walk, and marks it first
        # (r248 S4: "… pixels walked differently", the unit said)
        counts = re.findall(r"(\d+) pixels? (?:covered wrongly|walked differently)", title)
        assert artists and sum(map(int, counts)) == len(differing), title
        assert f"{int(covered.sum())} pixel" in title or not covered.any(), title
        if covered.any():
            words = wrong.explain_pixel(*np.argwhere(covered)[0])
    assert words in fig.get_supxlabel().replace("\n", " ")
    fig.canvas.draw()
    right = ex.check(name, CORRECT[name])
    assert len(right.differing_pixels()) == 0
    fig, ax = plt.subplots()  # one Axes is split in three
    right.compare(ax)
    panels = [a for a in fig.axes if a.get_label() != "<colorbar>"]  # a continuous scale's bar
    assert len(panels) == 3 and panels[2].get_title() == "no pixel differs"


def test_the_scenes_say_what_their_colours_mean_and_show_double_coverage(plt):
    """r40 06-4: a spoke covered 1.75 times drew as yellow as a full pixel (the package's scale
    stopped at 1) and no panel had a key; 08-3: the tile walk's colours had no legend."""
    ge = ex.check("coverage_fraction", MISTAKES["coverage, both edges own a sample"][1])
    fig, axes = plt.subplots(1, 3)
    ge.compare(axes)
    mine = axes[0].get_images()[0]
    assert mine.norm.vmax >= float(np.nanmax(mine.get_array())) > 1
    assert any(a.get_label() == "<colorbar>" for a in fig.axes)
    walk = ex.check("classify_block", CORRECT["classify_block"])
    fig, axes = plt.subplots(1, 3)
    walk.compare(axes)
    legend = axes[1].get_legend()
    assert legend is not None
    assert {t.get_text() for t in legend.get_texts()} >= {"rejected", "tested: covered"}


def test_the_bilinear_case_figure_shows_the_texture_the_point_and_the_four_weights(plt):
    """r40 07-3: the case was two bars of one number; it is the texture, the point and the
    four texels bilinear blends there, each with its weight (they sum to 1)."""
    from matplotlib.patches import Rectangle

    report = ex.check("bilinear", _bilinear_with("swap x"))
    fig, ax = plt.subplots()
    report.plot(ax)
    assert ax.get_images(), "the texture is drawn"
    assert len([p for p in ax.patches if isinstance(p, Rectangle)]) >= 4
    weights = [
        float(line[2:])
        for t in ax.texts
        for line in t.get_text().split("\n")
        if line.startswith("w ")
    ]  # r375 F6: a wrapped box's name shares its label
    assert len(weights) == 4 and abs(sum(weights) - 1) < 0.05, weights
    assert "yours" in ax.get_xlabel()


@pytest.mark.parametrize(
    "mistake", sample([m for m, (name, _, _) in MISTAKES.items() if name in PICTURED])
)
def test_every_typical_mistake_shows_in_the_picture(mistake):
    name, fn, _ = MISTAKES[mistake]
    report = ex.check(name, fn)
    differing = report.differing_pixels()
    assert len(differing) > 0
    assert "agree" not in report.explain_pixel(*differing[-1])


def test_a_click_explains_the_clicked_pixel(plt):
    from types import SimpleNamespace

    from teachraster.exercises.scenes import draw_comparison

    report = ex.check("resolve", MISTAKES["resolve of covered samples only"][1])
    fig, axes = plt.subplots(1, 3)
    draw_comparison(report.scene, axes)
    row, col = report.differing_pixels()[0]
    event = SimpleNamespace(
        name="button_press_event", inaxes=axes[2], xdata=col + 0.5, ydata=row + 0.5,
        canvas=fig.canvas, x=0, y=0, button=1, key=None, guiEvent=None, step=0, dblclick=False,
    )  # fmt: skip
    fig.canvas.callbacks.process("button_press_event", event)
    assert fig.get_supxlabel().startswith(f"pixel ({row}, {col}):")


def test_a_stub_or_a_crash_is_shown_not_raised(plt):
    def stub(*args):
        raise NotImplementedError

    report = ex.check("bilinear", stub)
    assert report.not_implemented
    fig, axes = plt.subplots(1, 3)
    report.compare(axes, pixel="first")
    assert "not implemented yet" in axes[0].texts[0].get_text()
    # r317 P1: the stub's figure (the inputs) does not mark the texel centres 7.2 asks for
    from teachraster.exercises.texture_filtering import bilinear_cases, draw_texture_case

    fig, ax = plt.subplots()
    draw_texture_case(ax, bilinear_cases()[0], None)
    assert not [line for line in ax.lines if line.get_marker() == "."]
    assert "texel centres" not in ax.get_xlabel()
    crash = ex.check("classify_block", lambda *a: 1 / 0)
    assert "ZeroDivisionError" in crash.explain_pixel(0, 0)


# -- notebooks: the grading convention --------------------------------------------------------
def _cells(path):
    return json.loads(path.read_text(encoding="utf-8"))["cells"]


def _source(cell):
    return "".join(cell["source"]) if isinstance(cell["source"], list) else cell["source"]


#: Checks worth two points (r491: 7.2 `texel_weights` replaced 7.2 and 7.3, a point each).
TWO_POINTS = {"texel_weights": 2}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_follows_the_grading_convention(path):
    cells = _cells(path)
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in cells]  # markdown cells too
    assert len(ids) == len(set(ids))
    solutions = 0
    for k, cell in enumerate(cells):
        meta, source = cell["metadata"]["nbgrader"], _source(cell)
        if cell["cell_type"] == "code":
            assert not cell["outputs"] and cell["execution_count"] is None
        if meta["solution"]:
            fn = meta["grade_id"].removesuffix("_solution")
            assert re.search(r"^ *### BEGIN SOLUTION$.*^ *### END SOLUTION$", source, re.M | re.S)
            assert meta == {"grade": False, "grade_id": f"{fn}_solution", "locked": False,
                            "schema_version": 3, "solution": True, "task": False}  # fmt: skip
            check = cells[k + 1]
            assert _source(check) == (
                f'report = ex.check("{fn}", {fn})\nshow(report)\nreport.assert_passed()'
            )
            assert check["metadata"]["nbgrader"] == {
                "grade": True, "grade_id": f"{fn}_check", "locked": True,
                "points": TWO_POINTS.get(fn, 1),
                "schema_version": 3, "solution": False, "task": False,
            }  # fmt: skip
            solutions += 1
        elif not meta["grade"]:
            assert meta["locked"] and "BEGIN SOLUTION" not in source
    assert solutions >= 1


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_student_version_holds_no_answer_and_the_text_no_formula(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    answers = []
    for cell in nb["cells"]:
        body = re.search(r"### BEGIN SOLUTION\n(.*?)### END SOLUTION", _source(cell), re.S)
        if body:
            answers += [ln.strip() for ln in body.group(1).splitlines() if len(ln.strip()) > 12]
    student = "\n".join(_source(c) for c in student_notebook(nb)["cells"])
    markdown = "\n".join(_source(c) for c in nb["cells"] if c["cell_type"] == "markdown")
    for line in answers:
        assert line not in student, line
        assert line not in markdown, line


def test_a_slow_function_spends_the_budget_and_no_more(monkeypatch):
    import time

    from teachraster.exercises import running

    # about the CPU budget alone: the wall-clock limits (for a machine too busy to compute)
    # set far out; a loaded machine passed a case's 0.3 s "it waits" limit first
    monkeypatch.setattr(running, "WALL_FACTOR", 1000.0)
    monkeypatch.setattr(running, "WAIT_FACTOR", 1000.0)

    def slow(z, bits):
        # half a case's limit (budget / 5 = 0.06 s): at 0.05 s a loaded machine's overhead
        # stopped one case first (stop 59's last full run), never the budget
        end = time.thread_time() + 0.03
        while time.thread_time() < end:
            pass
        return round(z * (2**bits - 1))

    start = time.process_time()  # CPU, not the wall: a loaded machine stretches the wall
    report = ex.check("depth_to_unorm", slow, budget=0.3)
    assert time.process_time() - start < 0.3 + 2
    assert not report.passed and report.stopped is not None
    assert "the check's budget of 0.3 s of CPU ran out" in report.failures[-1].explanation


def test_not_implemented_on_some_cases_only_is_a_failure():
    def half_done(z, bits):
        if bits == 24:
            raise NotImplementedError
        return round(z * (2**bits - 1))

    report = ex.check("depth_to_unorm", half_done)
    assert not report.not_implemented and not report.passed
    assert len(report.failures) == report.n_cases // 2
    assert "NotImplementedError" in report.failures[0].explanation


def test_a_pixel_is_a_pair_of_ints_inside_the_picture():
    report = ex.check("mip_level", CORRECT["mip_level"])
    with pytest.raises(TypeError, match="pixel must be a pair of ints"):
        report.explain_pixel(1.5, 2)
    with pytest.raises(ValueError, match="pixel must lie in the"):
        report.explain_pixel(0, 10_000)
    assert report.explain_pixel(np.int64(20), 10).startswith("yours and the package's agree")


@pytest.mark.parametrize(
    "name",
    ["coverage_fraction", "resolve", "resolve_srgb", "mip_level", "bilinear", "trilinear",
     "quad_derivatives", "robust_fill"],
)  # fmt: skip
def test_a_table_of_the_handed_out_cases_fails_the_drawn_ones(name):
    """r49: ``exercise(name).cases()`` hands out every case with its answer; a dict built from
    them must fail the cases drawn afresh for each check (as exercise 9's do). Exercise 8's
    checks (classify_block, hiz_rejects) draw none since r162 C2: the same code must fail the
    same cases on every run (tests/test_exercises_r162.py)."""
    from teachraster.exercises.checks import check, exercise

    table = {repr(tuple(a)): e for _, a, e in exercise(name).cases()}
    report = check(name, lambda *a: table.get(repr(tuple(a))))
    assert not report.passed
    assert all(f.case.startswith("drawn for this check") for f in report.failures), report


def test_resolve_names_triangle_0_taken_as_background():
    """r49: ``ids > 0`` as covered (triangle 0 turned background) was refused, not named."""
    from teachraster.exercises.checks import check

    def resolve(colours, ids, background):
        covered = (np.asarray(ids) > 0)[:, None]
        return np.where(covered, np.asarray(colours, float), background).mean(axis=0)

    report = check("resolve", resolve)
    assert not report.passed and "triangle 0" in report.failures[0].explanation, str(report)


def test_resolve_srgb_quotes_the_case_own_count_of_samples():
    """r49: a "1 of 4" case's message quoted "black on white at 2 of 4 samples"."""
    from teachraster.exercises.checks import check

    def resolve_srgb(colours, ids, background):
        covered = (np.asarray(ids) >= 0)[:, None]
        return np.where(covered, np.asarray(colours, float), background).mean(axis=0)

    first = check("resolve_srgb", resolve_srgb).failures[0]
    assert first.case.startswith("black on white, 1 of 4"), first.case
    assert "at 1 of 4 samples must show 0.75" in first.explanation, first.explanation


def test_hiz_says_a_safe_loose_bound_is_not_the_one_asked():
    """r49: the vertex-only bound is safe (it never rejects a visible fragment); the message
    must say the larger of the two bounds is asked (r64 08-4: not "the tightest", which the
    per-pixel bound over the covered centres is), not call it unsafe."""
    import student_variants as sv

    from teachraster.exercises.checks import check

    report = check("hiz_rejects", sv._hiz_with(vertex_only=True))
    assert not report.passed
    assert any("the larger of the two bounds is asked" in f.explanation for f in report.failures)
    assert not any("tightest" in f.explanation for f in report.failures), str(report)


def test_resolve_srgb_figure_marks_the_codes_average():
    """r49: 6.3's figure (three equal bars) showed nothing of linear light; it marks the
    encoded numbers' plain average beside the expected bars."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.exercises.resolve_light import draw_srgb_case, resolve_srgb_cases

    fig, ax = plt.subplots()
    case = resolve_srgb_cases()[0]  # black on white, 1 of 4 samples
    draw_srgb_case(ax, case, case[2])
    names = [t.get_text() for t in ax.get_xticklabels()]
    assert any(n.startswith("codes averaged") and "0.75\n(grey)" in n for n in names), names
    # r64 06-5: the colours as swatches: the samples' strip, expected, yours, the codes' average
    swatches = ax.get_images()
    assert len(swatches) == 4, names
    assert np.allclose(swatches[3].get_array()[0, 0], 0.75)  # the codes' average, grey
    assert np.allclose(swatches[1].get_array()[0, 0], case[2])  # expected: lighter, 0.881
    plt.close(fig)


@pytest.mark.parametrize("name", ["coverage_fraction", "resolve", "resolve_srgb", "mip_level",
                                  "bilinear", "trilinear", "quad_derivatives"])  # fmt: skip
def test_the_stub_figure_draws_the_inputs_and_no_answer(name):
    """r64 06-4, 07: the stub's figure drew nothing, its scene the package's answer; it draws
    the first case's inputs, with no expected value in its text."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def stub(*args):
        raise NotImplementedError

    report = ex.check(name, stub)
    assert report.not_implemented and report.example is not None
    fig, ax = plt.subplots()
    report.plot(ax)
    words = " ".join([ax.get_xlabel(), *(t.get_text() for t in ax.texts),
                      *(t.get_text() for t in ax.get_xticklabels())])  # fmt: skip
    assert "expected" not in words and "filtered value" not in words, words
    assert "yours" not in words and "fraction" not in words, words
    assert "(ddx, ddy)" not in words and not any(t.startswith("w ") for t in words.split("\n"))
    assert ax.get_images() or ax.patches or ax.lines or ax.texts, "the inputs are drawn"
    plt.close(fig)


@pytest.mark.parametrize(("name", "fn", "method"), [
    # (not the texture's mean itself: r286 names that mistake)
    ("bilinear", lambda t, uv, w: 0.9 * np.asarray(t, float).mean(axis=(0, 1)) + 0.01 * uv[0],
     "w "),
    ("quad_derivatives", lambda xy, w, f, row, col: (0.001 * row, 0.002 * col), "its quad"),
])  # fmt: skip
def test_the_case_figure_draws_the_method_only_with_the_full_words(name, fn, method, plt):
    """r64 07 D2, D3: 7.2's four weighted texels and 7.4's quad with its lanes are the
    method; the first failing tries' figure leaves them out, as their words do."""
    from teachraster.exercises import tries

    def words(ax):
        legend = ax.get_legend()
        return [t.get_text() for t in ax.texts] + (
            [t.get_text() for t in legend.get_texts()] if legend else []
        )

    tries.forget_hints(name)
    try:
        report = ex.check(name, fn)
        assert "a hint only" in str(report)
        fig, ax = plt.subplots()
        report.plot(ax)
        assert not any(t.startswith(method) for t in words(ax)), words(ax)
        tries.spend_hints([name])
        fig, ax = plt.subplots()
        ex.check(name, fn).plot(ax)
        assert any(t.startswith(method) for t in words(ax)), words(ax)
    finally:
        tries.spend_hints([name])


@pytest.mark.parametrize("name", ["coverage_fraction", "resolve", "mip_level", "bilinear",
                                  "trilinear"])  # fmt: skip
def test_the_stub_scene_shows_its_inputs_not_the_packages_picture(name, plt):
    """r64 06-4, 07: beside the stub's "not implemented yet" stood the package's picture, the
    target; the scene's inputs stand there now, and no difference panel."""

    def stub(*args):
        raise NotImplementedError

    fig, axes = plt.subplots(1, 3)
    ex.check(name, stub).compare(axes, pixel="first")
    assert axes[1].get_title().startswith("the scene's input"), axes[1].get_title()
    assert "package's:" not in " ".join(ax.get_title() for ax in axes)
    assert "none to show yet" in axes[2].texts[0].get_text().replace("\n", " ")


def test_the_pictures_pixel_line_names_the_cause_and_stages_the_formula():
    """r64 06-3: the fan's pixel line named no cause; 7.1's printed the formula on the first
    wrong try, past the check's staging."""
    from teachraster.exercises import tries
    from teachraster.exercises.antialiasing import fraction_with
    from teachraster.exercises.level_of_detail import level_with

    report = ex.check("coverage_fraction", lambda *a: fraction_with(*a, snapping="none"))
    assert "unsnapped vertices" in report.explain_pixel(*report.differing_pixels()[0])
    tries.forget_hints("mip_level")
    try:
        report = ex.check("mip_level", lambda *a: 1.01 * level_with(*a, combine="min"))
        assert "a hint only" in str(report)
        words = report.explain_pixel(*report.differing_pixels()[0])
        assert "log2 ρ" not in words and "(du/dx·W" not in words, words
    finally:
        tries.spend_hints(["mip_level"])


@pytest.mark.parametrize(("name", "fn", "named"), [
    ("resolve", lambda c, i, b: b, "the background alone"),
    ("resolve_srgb", lambda c, i, b: np.asarray(b, float), ""),  # the check's own words
    ("bilinear", lambda t, uv, w: np.asarray(t, float)[0, 0], "texel [0, 0]"),
])  # fmt: skip
def test_a_placeholder_is_named_without_the_rule(name, fn, named):
    """r64 06 D1, D2, 07 D2: `return background` (6.2, 6.3) and `return texture[0, 0]` (7.2)
    got the resolve's formula or bilinear's method on the first try (6.3's words for an
    argument handed back are the checker's, in diagnosis.py)."""
    from teachraster.exercises import tries

    tries.forget_hints(name)
    try:
        text = str(ex.check(name, fn))
    finally:
        tries.spend_hints([name])
    assert named in text, text
    for rule in ("counting as the background", "(S − k)", "linear_to_srgb(", "u·W − ½", "⌊x⌋"):
        assert rule not in text, text


def test_the_passing_texture_figures_draw_the_questions_cases(plt):
    """r362 FIG1: a passing 7.1/7.2 check drew λ = 0 and a texel centre (weights 1, 0, 0, 0);
    they draw the cases 7.1 and 7.2 ask about, the wrapped column named and filled."""
    for name, words in (("mip_level", "λ = 4, yours 4"), ("bilinear", "uv = (0.05, 0.4)")):
        report = ex.check(name, CORRECT[name])
        fig, ax = plt.subplots()
        report.plot(ax)
        assert report.passed and words in ax.get_xlabel(), ax.get_xlabel()
    assert [t for t in ax.texts if "= col 3" in t.get_text().split("\n")], [
        t.get_text() for t in ax.texts
    ]
