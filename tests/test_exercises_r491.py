"""r491 (r433 T1, r418 T1): exercise 7.2 ``texel_weights(sizes, uv, lod, wrap)`` in place of
7.2 ``bilinear`` and 7.3 ``trilinear`` (lesson 09's printed filter and table row).

The expected answers are :func:`texel_footprint.reference`'s (exact, in Fractions) and are
cross-checked here against the package's own trilinear filter on one-hot pyramids; the
notebook's 7.3 builds ``bilinear`` and ``trilinear`` from the student's weights, which 7.4
and the capstone take.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from reasoning_solutions import texel_weights
from student_variants import DIFFERENT, R491

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import texel_footprint as tf
from teachraster.exercises import tries

NOTEBOOKS = Path(__file__).resolve().parents[1] / "notebooks"
NOTEBOOK = NOTEBOOKS / "exercises" / "07_texture_filtering.ipynb"


def _package_weights(sizes, uv, lod, wrap) -> dict:
    """Each texel's weight as the package filters it: the value of a pyramid that is 1 at
    that texel and 0 elsewhere (levels of any content: tr.sample takes the list as given)."""
    out = {}
    zero = [np.zeros(s) for s in sizes]
    for k, (h, w) in enumerate(sizes):
        for r in range(h):
            for c in range(w):
                levels = [z.copy() for z in zero]
                levels[k][r, c] = 1.0
                v = tr.sample(levels, np.array([uv], float), "trilinear", wrap,
                              lod=np.array([lod], float))[0]  # fmt: skip
                if v != 0:
                    out[(k, r, c)] = float(v)
    return out


def test_expected_weights_are_the_packages_on_every_case():
    for label, args, expected in tf.texel_cases():
        got = _package_weights(*args)
        assert set(got) <= set(expected) | {k for k in got if abs(got[k]) < 1e-12}, label
        assert all(abs(got.get(k, 0.0) - w) < 1e-12 for k, w in expected.items()), label
        assert abs(sum(expected.values()) - 1) < 1e-12, label


def test_the_cases_ask_non_square_pyramids_borders_and_every_range_of_lod():
    cases = tf.texel_cases()
    sizes = [tuple(map(tuple, a[0])) for _, a, _ in cases]
    assert any(s[0][0] != s[0][1] for s in sizes) and any((1, 2) in s for s in sizes)
    lods = [a[2] for _, a, _ in cases]
    assert min(lods) < 0 and any(lo > len(a[0]) - 1 for lo, (_, a, _) in zip(lods, cases))
    assert any(lo == int(lo) for lo in lods)
    # a texel read twice (merged) and a case where clamp and repeat read different texels
    assert any(len(e) < 4 * len({k[0] for k in e}) for _, _, e in cases)
    assert {a[3] for _, a, _ in cases} == {"repeat", "clamp"}


def test_solutions_written_otherwise_pass():
    assert ex.check("texel_weights", texel_weights).passed
    for label, (name, fn) in DIFFERENT.items():
        if name == "texel_weights":
            report = ex.check(name, fn)
            assert report.passed, (label, str(report)[:600])


@pytest.mark.parametrize("label", list(R491))
def test_each_mistake_is_named_first(label):
    name, fn, words, kind = R491[label]
    report = ex.check(name, fn)
    assert not report.passed
    first = report.failures[0]
    assert first.kind == kind and words in first.explanation, (first.kind, first.explanation)
    assert "float32" not in first.explanation, first.explanation


def _value(sizes, uv, lod, wrap):
    return 0.5


def _listed(sizes, uv, lod, wrap):
    return list(texel_weights(sizes, uv, lod, wrap).items())


def _float_keys(sizes, uv, lod, wrap):
    return {tuple(float(i) for i in k): w for k, w in texel_weights(sizes, uv, lod, wrap).items()}


def _by_the_package(sizes, uv, lod, wrap):
    """The weights read off tr.sample on one-hot pyramids (the package's filter)."""
    return _package_weights(sizes, uv, lod, wrap)


def _stub(sizes, uv, lod, wrap):
    raise NotImplementedError()


def _none(sizes, uv, lod, wrap):
    pass


@pytest.mark.parametrize(
    "fn, words",
    [
        (_value, "not a dict"),
        (_listed, "not a dict"),
        (_float_keys, "three whole numbers"),
        (_by_the_package, "not counted"),
        (tf.reference, "not counted"),
        (_stub, "not implemented yet"),
        (_none, "returned None"),
    ],
)
def test_wrong_forms_the_packages_filter_and_stubs_are_told_so(fn, words):
    report = ex.check("texel_weights", fn)
    assert not report.passed
    assert words in str(report), str(report)[:600]


def test_the_first_try_asks_and_the_rule_comes_after_two_different_answers():
    def slip(sizes, uv, lod, wrap):  # no mistake of the table: the weights passed round
        got = texel_weights(sizes, uv, lod, wrap)
        keys = sorted(got)
        return {k: got[keys[i - 1]] for i, k in enumerate(keys)}

    tries.forget_hints("texel_weights")
    first = ex.check("texel_weights", slip).failures[0].explanation
    # r497: an unnamed answer is now split by level (or by axis) before the question
    assert tf.RULE not in first and "level by level" in first, first
    tries.forget_hints("texel_weights")


def test_a_float32_answer_far_out_passes_and_float16_is_named_float16():
    name, fn = DIFFERENT["texel weights in float32 (r491)"]
    assert ex.check(name, fn).passed
    first = ex.check(*R491["texel weights in float16"][:2]).failures[0]
    assert first.kind == "float16"


def test_the_pass_figures_answers_are_the_references():
    text = tf.questions()
    assert f": {len(tf.reference(tf.gl_sizes(2, 8), (0.3, 0.9), 1.5, 'repeat'))} texels" in text
    assert len(tf.reference(tf.gl_sizes(2, 8), (0.3, 0.9), 1.5, "repeat")) < 8
    # the band where clamp and repeat part is half a texel of the level read
    for lod, band in ((0, 1 / 16), (2, 1 / 4)):
        assert f"u < {band:g}" in text.replace("0.0625", "0.0625")
        s = tf.gl_sizes(8, 8)
        inside, outside = band * 0.99, band * 1.01
        assert tf.reference(s, (inside, 0.5), lod, "clamp") != tf.reference(
            s, (inside, 0.5), lod, "repeat"
        )
        assert tf.reference(s, (outside, 0.5), lod, "clamp") == tf.reference(
            s, (outside, 0.5), lod, "repeat"
        )
    assert "(3) 3×5, 1×2, 1×1" in text


def _cells() -> dict:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in cells}


def test_the_task_states_what_not_how_and_no_lesson_prints_the_weights():
    task = _cells()["texel_weights_task"].replace("\n", " ")
    for formula in ("u·W − ½", "u * W - 0.5", "- 0.5", "floor(", "⌊", "λ − ⌊λ⌋", "% w"):
        assert formula not in task, formula
    assert "Answer first" in task and "its figure answers the three" in task
    lessons = " ".join(p.read_text() for p in NOTEBOOKS.glob("*.ipynb"))
    for answer in ("texel_weights", "(level, row, col)", "clamp and repeat part"):
        assert answer not in lessons, answer


def test_7_3_builds_the_filters_7_4_and_the_capstone_take():
    cells = _cells()
    ns = {"np": np}
    exec(cells["texel_weights_solution"], ns)
    exec(cells["filters_given"], ns)
    assert ex.check("bilinear", ns["bilinear"]).passed
    assert ex.check("trilinear", ns["trilinear"]).passed
    exec(cells["pixel_lod_solution"], ns)
    exec(cells["pixel_sample_solution"], ns)
    assert ex.check("pixel_sample", ns["pixel_sample"]).passed
    report = ex.capstone("floor_trilinear", trilinear=ns["trilinear"])
    assert report.passed, str(report)[:400]


def test_a_wrong_texel_weights_shows_in_7_4_through_the_given_trilinear():
    cells = _cells()
    ns = {"np": np, "math": math}
    exec(cells["filters_given"], ns)
    exec(cells["pixel_lod_solution"], ns)
    exec(cells["pixel_sample_solution"], ns)
    ns["texel_weights"] = R491["texel weights at texel corners"][1]
    first = ex.check("pixel_sample", ns["pixel_sample"]).failures[0].explanation
    assert "fix texel_weights first" in first, first
