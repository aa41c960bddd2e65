"""r489 (issue 30): exercise 4.3 is ``clipped_colours(v, colours, polygon)``, the colours of a
clipper's polygon recovered from its positions (was ``clip_near_colour``, 4.2's loop with three
columns appended: r456 "Transcription"). The wrong and different variants are in
student_variants.py (R489); here: the reference against the core clipper, the cases' claims,
the task's text, the cost."""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np
import pytest
from student_variants import DIFFERENT, R489

from teachraster import exercises as ex
from teachraster.exercises import clip_colour as cc
from teachraster.exercises.depth_clipping import clip_with
from teachraster.pipeline.geometry.clipping import clip_polygon

ROOT = Path(__file__).parents[1]
NOTEBOOK = ROOT / "notebooks" / "exercises" / "04_depth_and_clipping.ipynb"


def _core(v, c, given):
    """The core clipper's (positions, colours) that made ``given``: near plane only, near and
    far, or near, far and the side planes x, y = ±w."""
    tries = [clip_with(np.column_stack([v, c]))]
    tries += [np.column_stack(clip_polygon(v, c, guard)) for guard in (None, 1.0)]
    for p in tries:
        if p is None:
            continue
        if {tuple(np.round(q, 5)) for q in p[:, :4]} == {tuple(np.round(q, 5)) for q in given}:
            return p[:, :4], p[:, 4:]
    raise AssertionError("no clipper makes this polygon")


def test_the_reference_is_the_core_clippers_colours_on_every_case():
    """Expected colours (least squares on all five equations) against the core's
    Sutherland-Hodgman carrying the colours as attributes, vertex by vertex."""
    for label, (v, c, given), expected in cc.colour_cases():
        given = np.asarray(given, float)
        pos, col = _core(v, c, given)
        assert expected.shape == (len(given), 3), label
        for k, p in enumerate(given):
            j = int(np.argmin(np.abs(pos - p).max(axis=1)))
            np.testing.assert_allclose(expected[k], col[j], atol=1e-9, err_msg=label)


def test_the_cases_hold_what_their_labels_claim():
    cases = {label.split(";")[0]: args for label, args, _ in cc.colour_cases()}
    subsets = {k: cc._open_subsets(a[0]) for k, a in cases.items()}
    assert ((0, 1, 3), False) in subsets["w = 2x + y at every vertex"]
    assert ((2, 3), True) in subsets["z = w − 2 at every vertex"]
    assert ((0, 1), True) in subsets["x + y = 1 at every vertex"]  # the screen works there
    v3 = "v3 = v1 + v2: the triangle's plane holds the origin of clip space"
    assert ((0, 1, 2, 3), False) in subsets[v3]
    inside = cases["cut by the near plane and the side plane x = w: a corner inside the triangle"]
    assert any(cc._on_edge(inside[0], p) is None and cc._kept(inside[0], p) is None
               for p in np.asarray(inside[2], float))  # fmt: skip
    forms = [
        label for label, args, _ in cc.colour_cases() if np.asarray(args[2]).dtype == np.float32
    ]
    assert len(forms) >= 8
    assert {len(a[2]) for a in cases.values()} >= {0, 3, 4, 5, 6}


def test_correct_variants_pass_and_wrong_ones_are_named():
    """The three students' variants: none correct fails; every wrong one fails with its cause
    first (the corpus test replays them too, each on its own)."""
    for label, (name, fn) in DIFFERENT.items():
        if name == "clipped_colours":
            assert ex.check(name, fn).passed, label
    assert len([k for k, (n, _) in DIFFERENT.items() if n == "clipped_colours"]) >= 8
    assert len(R489) >= 25
    for label, (name, fn, words, kind) in list(R489.items())[::4]:  # a sample: cost
        first = ex.check(name, fn).failures[0]
        assert words in first.explanation and first.kind == kind, (label, first.explanation)


def test_the_packages_clip_polygon_is_not_counted():
    def clipped_colours(v, colours, polygon):
        q, a = clip_polygon(np.asarray(v, float), np.asarray(colours, float), 1.0)
        p = np.asarray(polygon, float).reshape(-1, 4)
        return np.array([a[np.argmin(((q - x) ** 2).sum(1))] for x in p]).reshape(-1, 3)

    report = ex.check("clipped_colours", clipped_colours)
    assert not report.passed and "not counted" in str(report) and "clip_polygon" in str(report)


def test_a_failing_check_is_cheap():
    start = time.process_time()
    report = ex.check("clipped_colours", lambda v, c, p: np.zeros((len(p), 3)))
    assert not report.passed
    assert time.process_time() - start < 1.5


def _task_text() -> str:
    nb = json.loads(NOTEBOOK.read_text())
    cell = next(c for c in nb["cells"] if "## 4.3" in "".join(c["source"]))
    return "".join(cell["source"])


def test_the_task_asks_and_does_not_answer():
    text = _task_text()
    assert "clipped_colours(v, colours, polygon)" in text
    for asked in ("Which equations give", "float32", "either way", "x/w and y/w"):
        assert asked in text, asked
    for answer in ("lstsq", "least squares", "pinv", "all five", "λ1 + λ2", "a + t"):
        assert answer not in text, answer


def test_no_lesson_prints_the_answer():
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        for cell in json.loads(path.read_text())["cells"]:
            src = "".join(cell["source"])
            assert "clipped_colours" not in src or cell["cell_type"] == "markdown", path
            if "lstsq" in src:  # lesson 04's ray hit (3-D, eye space) and 03's plane fit only
                assert "np.ones(3)" not in src or "vstack" not in src, path


@pytest.mark.parametrize("form", cc._FORMS)
def test_each_form_of_the_polygon_is_graded(form):
    assert any(form in label for label, _, _ in cc.colour_cases())


def test_the_numbers_the_task_quotes_are_the_checks():
    text = _task_text()
    assert "within 10⁻⁴" in text and cc.COLOUR_TOL == 1e-4
    sizes = {len(args[2]) for _, args, _ in cc.colour_cases()}
    assert "n = 0 to 6" in text and min(sizes) == 0 and max(sizes) == 6
