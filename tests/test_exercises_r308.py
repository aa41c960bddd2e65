"""Review r308 (exercise 06): what the corpus (student_variants.R308) does not carry.

FIG2: the single-case panel shades the triangle and names the tie sample; M1: 6.3's scene
draws both resolves, the codes darker at the edges; F1/C1/S6: cell 8's wording; S3: the rule
of an all-covered pixel names no uncovered share.
"""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib
import numpy as np
from exercise_solutions import CORRECT

from teachraster import exercises as ex
from teachraster.exercises import antialiasing as aa
from teachraster.exercises import resolve_light as rl

matplotlib.use("Agg")
NB = Path(__file__).parents[1] / "notebooks" / "exercises" / "06_antialiasing.ipynb"


def test_the_case_panel_shades_the_triangle_and_names_the_tie():
    import matplotlib.pyplot as plt

    case = next(c for c in aa.coverage_cases() if c[0].startswith("sample 0 on a left edge"))
    fig, ax = plt.subplots()
    aa.draw_coverage_case(ax, case, case[2])
    assert ax.patches, "the triangle's inside is filled"
    assert (
        "sample 0 lies on edge v3→v1, a left edge: the top-left rule covers it" in ax.get_xlabel()
    )
    plt.close(fig)


def test_the_scene_of_6_3_draws_both_resolves_the_codes_darker():
    import matplotlib.pyplot as plt

    ids, colours, white = rl._wedges()
    codes = rl._resolved(CORRECT["resolve"], ids, colours, white)
    light = rl._resolved(CORRECT["resolve_srgb"], ids, colours, white)
    edge = (codes > 0) & (codes < 1)
    assert edge.any() and np.all(light[edge] > codes[edge])  # sRGB is concave: never darker

    def stub(*args):
        raise NotImplementedError

    assert rl._resolved(stub, ids, colours, white) == "not implemented yet"
    fig, axes = plt.subplots(1, 3)
    rl.show_two_resolves(CORRECT["resolve"], stub, axes)
    plt.close(fig)


def test_cell_8_names_the_srgb_format_and_lesson_08s_section_not_a_case_answer():
    text = "".join(json.loads(NB.read_text())["cells"][8]["source"])
    assert "8-bit **sRGB** framebuffer" in text and "GL 4.6 §17.3.7" in text
    assert "Lesson 08 §6 makes the same point" in text and "ends on" not in text
    assert "0.735" not in text


def test_an_all_covered_pixel_is_told_no_uncovered_share():
    def summed(c, i, b):
        return np.where((np.asarray(i) >= 0)[:, None], c, b).sum(axis=0)

    first = ex.check("resolve", summed).failures[0]
    assert first.case.startswith("4 samples, all covered"), first.case
    assert "the mean over all 4 samples" in first.explanation, first.explanation
    assert "the 0 uncovered" not in first.explanation, first.explanation
