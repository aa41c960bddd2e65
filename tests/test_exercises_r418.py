"""Review r418 (exercise 07): F1 only a try at the task counts towards the full steps (junk that
reads uv or the pyramid never does); F2 the reader's half-named variants are named (they are
student_variants.R418_PIXEL); F3 a NaN (u, v) passed to the student's own trilinear is
explained, not a raw error; P1 7.3's stub figure does not say "the same (u, v)"; P2 7.4's
questions are not answered by its words or by 7.3."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import student_variants as sv

from teachraster import exercises as ex
from teachraster.exercises import pixel_level as pl
from teachraster.exercises import pixel_sampler as ps
from teachraster.exercises import tries

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "07_texture_filtering.ipynb"


@pytest.mark.parametrize("label", list(sv.R418_PIXEL))
def test_the_readers_variants_are_named(label):
    name, fn, words, kind = sv.R418_PIXEL[label]
    tries.spend_hints([name])
    first = ex.check(name, fn).failures[0]
    tries.forget_hints(name)
    assert first.kind == kind and words in first.explanation, (first.kind, first.explanation)


def _lod(body):
    space = {"np": np}
    exec(f"def pixel_lod(xy, w, uv, size, row, col):\n    return {body}", space)  # noqa: S102
    return space["pixel_lod"]


def _sample(body):
    space = {"np": np}
    exec(f"def pixel_sample(pyramid, xy, w, uv, row, col, wrap):\n    return {body}", space)  # noqa: S102, E501
    return space["pixel_sample"]


def test_junk_that_reads_the_inputs_never_unlocks_the_steps():
    """F1: ``uv[1][0] + uv[2][1]`` then ``np.sum(uv) + size[0]`` (7.1), ``pyramid[-1][0, 0]``
    then ``pyramid[0][row % 2, col % 2]`` (7.4) brought the whole recipe; each is told how it
    fails to behave like the task's quantity, and none counts."""
    junk = {
        "pixel_lod": (pl.RULE, [_lod("float(uv[1][0] + uv[2][1])"),
                                _lod("float(np.sum(uv) + size[0])"),
                                _lod("float(np.log2(size[0] * np.abs(uv).sum()))")]),
        "pixel_sample": (ps.RULE, [_sample("pyramid[-1][0, 0]"),
                                   _sample("pyramid[0][row % 2, col % 2]"),
                                   _sample("2 * pyramid[0][0, 0]")]),
    }  # fmt: skip
    for name, (rule, fns) in junk.items():
        tries.forget_hints(name)
        for fn in fns:
            said = str(ex.check(name, fn))
            assert rule not in said, said
        assert not tries.hints_spent(name), name
        tries.forget_hints(name)
    said = str(ex.check("pixel_lod", junk["pixel_lod"][1][0]))
    assert "does not behave like a level of detail" in said and "from 12 to 24" in said, said
    said = str(ex.check("pixel_sample", junk["pixel_sample"][1][1]))
    assert "yours stays 0.966: does your value follow this pixel's (u, v)?" in said, said
    tries.forget_hints()


def test_two_tries_at_the_task_unlock_the_steps():
    """An unnamed try that behaves like a λ (the geometric mean of the two steps; a weighted
    mean: r462 names the Frobenius norm), or a sample that filters the pyramid at a (u, v) (a (u, v) scaled, a λ scaled),
    counts: the second one gets the steps."""
    tries.forget_hints()
    lods = [sv._lod405(RHO="(lambda a, b: np.sqrt(a * b))"),
            sv._lod405(RHO="(lambda a, b: (a + 2 * b) / 3)")]  # fmt: skip
    samples = [sv._ps405(RET="trilinear(pyramid, uvh * 1.1, lod, wrap)"),
               sv._ps405(RET="trilinear(pyramid, uvh, lod * 0.8, wrap)")]  # fmt: skip
    for name, rule, (first, second) in (("pixel_lod", pl.RULE, lods),
                                        ("pixel_sample", ps.RULE, samples)):  # fmt: skip
        assert rule not in str(ex.check(name, first))
        assert rule in str(ex.check(name, second)), name
    tries.forget_hints()


def test_a_nan_uv_passed_to_the_students_trilinear_is_explained():
    name, fn, _, _ = sv.R418_PIXEL["pixel sample passing a NaN (u, v) to its own trilinear"]
    first = ex.check(name, fn).failures[0].explanation
    assert "inside your trilinear, called with (u, v) = (nan, nan)" in first, first
    assert "a 0/0 in your weights" in first, first


def test_7_3s_stub_figure_keeps_the_same_uv_for_the_method(plt):
    from teachraster.exercises.texture_filtering import draw_pyramid_case, trilinear_cases

    tries.forget_hints("trilinear")
    case = trilinear_cases()[0]
    fig, ax = plt.subplots()
    draw_pyramid_case(ax, case, None)
    assert "the same (u, v)" not in ax.get_xlabel() and "× on level 0" in ax.get_xlabel()
    assert len([line for line in ax.lines if line.get_marker() == "x"]) == 1


def test_7_4_asks_before_it_tells():
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]).replace("\n", " ")
             for c in json.loads(NOTEBOOK.read_text())["cells"]}  # fmt: skip
    task = cells["pixel_sample_task"]
    for told in ("as it shares λ", "which share λ", "own (u, v)", "which level is read"):
        assert told not in task, told
    assert "Pixel (27, 3) is covered" in task
    assert "one pair for the pixels run together" not in cells["pixel_lod_task"]


def test_the_stub_figures_draw_the_whole_floor_with_the_questions_pixels(plt):
    """FIG1: 7.1's and 7.4's stub figures showed a 6 × 6 window, never the floor whose pixels
    the questions name; a failing 7.1 figure outlines the quad once the hints are spent."""

    def stub(*args):
        raise NotImplementedError

    for name, pixels in (("pixel_lod", pl.QUESTION_PIXELS), ("pixel_sample", ps.SAMPLE_PIXELS)):
        fig, ax = plt.subplots()
        ex.check(name, stub).plot(ax)
        names = {t.get_text() for t in ax.texts}
        assert {f"({r}, {c})" for r, c in pixels} <= names, names
        assert ax.get_xlim() == (0, 32) and "the floor the check draws" in ax.get_xlabel()
    tries.spend_hints(["pixel_lod"])
    fig, ax = plt.subplots()
    ex.check("pixel_lod", sv._lod405(EXTRAP="False")).plot(ax)
    tries.forget_hints("pixel_lod")
    quads = [p for p in ax.patches if p.get_width() == 2 and p.get_height() == 2]
    assert len(quads) == 1 and quads[0].get_xy() == (2, 26), quads
