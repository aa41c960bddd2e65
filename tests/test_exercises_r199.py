"""r199 (exercise 12, the capstone, a fresh read): each finding fixed, as a class, with a test
that fails on the code before the fix. (C1, the time-out's CPU counted twice, is
tests/test_capstone_r174.py's.)"""

from __future__ import annotations

import json

import numpy as np
import reasoning_solutions as sol
from test_capstone_r174 import NOTEBOOK, _cell

from teachraster import exercises as ex
from teachraster.exercises import antialiasing, capstone_explain, capstone_glass, tries
from teachraster.exercises.capstone_render import SCENES
from teachraster.pipeline.visibility.zbuffer import passed_on_arrival


def _first(report) -> str:
    assert not report.passed
    return report.failures[0].explanation


# -- C2: 12.7's tint, C3: 12.9's number of samples ------------------------------------------------
def test_12_7_says_what_its_panels_show_of_the_tint():
    text = _cell("12.7")
    assert "lavender" in text and "too faint to tell" not in text
    assert "faintly" not in _cell("12.10")


def test_12_9_says_the_own_cases_vary_the_number_of_samples():
    text = _cell("12.9")
    assert "the 4 samples of a pixel" not in text
    assert "the S samples of a pixel" in text and "vary S" in text


# -- C3: a resolve that divides by a fixed number of samples ----------------------------------------
def _divided_by(n):
    def resolve(sample_colours, sample_ids, background):
        c = np.where(np.asarray(sample_ids)[:, None] >= 0, sample_colours, background)
        return c.sum(axis=0) / n

    return resolve


def test_a_resolve_dividing_by_4_is_told_the_number_of_samples_varies():
    said = _first(ex.check("resolve", _divided_by(4)))
    assert "you divided by 4 whatever the number of samples" in said, said
    assert "no triangle covered the sample" not in said, said


def test_a_resolve_dividing_by_3_is_told_so_on_a_pixel_with_every_sample_covered():
    """r199 12-6: `sum / 3` was asked about the share no triangle covered, on a case with none."""
    said = _first(ex.check("resolve", _divided_by(3)))
    assert "you divided by 3 whatever the number of samples" in said, said


def _max_where_covered(sample_colours, sample_ids, background):
    """Right wherever a sample is uncovered; the brightest sample where all are covered."""
    ids = np.asarray(sample_ids)
    if (ids >= 0).all():
        return np.asarray(sample_colours, dtype=float).max(axis=0)
    return sol.CAPSTONE["resolve"](sample_colours, sample_ids, background)


def test_the_resolves_question_asks_of_an_uncovered_share_only_where_there_is_one():
    tries.forget_hints("resolve")
    try:
        report = ex.check("resolve", _max_where_covered)
        failing = [f.explanation for f in report.failures]
        assert failing, report
        for said in failing:
            assert "no triangle covered the sample" not in said, said
        assert "every sample is covered here" in failing[0], failing[0]
    finally:
        tries.spend_hints(["resolve"])


def test_the_rule_for_a_pixel_with_every_sample_covered_has_no_background_share():
    covered = (np.ones((2, 3)), np.array([0, 1]), np.ones(3))
    uncovered = (np.ones((2, 3)), np.array([0, -1]), np.ones(3))
    assert "background" not in antialiasing._resolve_rule(covered, None, None)
    assert "background" in antialiasing._resolve_rule(uncovered, None, None)


# -- 12-4: depth_passes letting the first fragment alone pass --------------------------------------
def _first_only(depths, writes):
    return [k == 0 for k in range(len(depths))]


def test_exercise_4_names_a_test_that_lets_the_first_fragment_alone_pass():
    said = _first(ex.check("depth_passes", _first_only))
    assert "only the first fragment passes" in said, said


def test_a_mistake_that_fits_one_pixel_alone_is_not_named_there():
    """r199 12-4: at a pixel of three fragments, one verdict list fits ">" by chance; a mistake
    is named from the pixel only where it also gives the function's answers to exercise 4's
    named sequences (here a function right everywhere but at this pixel)."""
    depths, writes = np.array([0.968, 0.967, 0.968]), np.array([True, True, True])
    expected = passed_on_arrival(np.zeros(3, np.int64), depths, writes)

    def odd(d, w):
        if np.array_equal(np.asarray(d), depths):
            return [True, False, False]
        return sol.CAPSTONE["depth_passes"](d, w)

    said = capstone_explain._depth_mistake({"depth_passes": odd}, depths, writes,
                                           [True, False, False], expected)  # fmt: skip
    assert ">, not <" not in said, said
    named = capstone_explain._depth_mistake({"depth_passes": _first_only}, depths, writes,
                                            [True, False, False], expected)  # fmt: skip
    assert "only the first fragment passes" in named, named


def test_a_buffer_never_written_is_asked_whether_it_takes_a_depth():
    def never_writes(depths, writes):
        return [d < np.inf for d in depths]

    said = _first(ex.check("depth_passes", never_writes))
    assert "does the buffer ever take a depth" in said, said


# -- 12-5: the A-buffer's over with its arguments swapped, and sorted by alpha ----------------------
def _over(src, dst):
    src, dst = np.asarray(src, dtype=float), np.asarray(dst, dtype=float)
    return src + dst * (1 - src[3])


def _swapped(depths, colours, background):
    result = np.asarray(background, dtype=float)
    for k in np.argsort(-np.asarray(depths), kind="stable"):
        result = _over(result, colours[k])
    return result


def _background_last(depths, colours, background):
    result = np.zeros(4)
    for k in np.argsort(-np.asarray(depths), kind="stable"):
        result = _over(colours[k], result)
    return _over(background, result)


def _by_alpha(depths, colours, background):
    result = np.asarray(background, dtype=float)
    for k in np.argsort([c[3] for c in colours]):
        result = _over(colours[k], result)
    return result


#: Pixel (10, 23) of the glass (r199): the alpha order is the nearest-first order there.
_DEPTHS = np.array([0.968, 0.967])
_COLOURS = np.array([[0.54, 0.12, 0.12, 0.6], [0.09, 0.135, 0.405, 0.45]])


def _said(a_buffer) -> str:
    ours = capstone_glass.package_resolve(_DEPTHS, _COLOURS, capstone_glass.BACKGROUND)
    yours = a_buffer(_DEPTHS.copy(), _COLOURS.copy(), capstone_glass.BACKGROUND.copy())
    return capstone_glass._mistake(a_buffer, _DEPTHS, _COLOURS, yours, ours)


def test_an_a_buffer_laying_the_background_in_front_is_not_told_a_placeholder():
    for a_buffer in (_swapped, _background_last):
        said = _said(a_buffer)
        assert "placeholder" not in said and "over's two arguments swapped" in said, said


def test_an_a_buffer_that_returns_the_background_is_still_told_a_placeholder():
    said = _said(lambda d, c, b: b)
    assert "placeholder" in said and "arguments swapped" not in said, said


def test_an_a_buffer_sorted_by_alpha_is_not_told_it_sorted_by_depth():
    said = _said(_by_alpha)
    assert "increasing depth" not in said, said
    near_first = _said(lambda d, c, b: capstone_glass.variants(d, c, b)["nearest first"])
    assert "increasing depth" in near_first, near_first


def test_the_capstone_names_swapped_over_arguments_in_the_a_buffer():
    used = {name: sol.CAPSTONE.get(name) for name in SCENES["glass_sorted"].uses}
    used["a_buffer"] = _swapped
    report = ex.capstone("glass_sorted", **used)
    said = _first(report)
    assert "over's two arguments swapped" in said and "placeholder" not in said, said


# -- 12-7: bilinear with v flipped, and along x only ------------------------------------------------
def _bilinear(texture, uv, wrap, *, flip=False, x_only=False):
    tex = np.asarray(texture, dtype=float)
    h, w = tex.shape[:2]
    v = 1 - uv[1] if flip else uv[1]
    x, y = uv[0] * w - 0.5, v * h - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = x - x0, y - y0
    cols, rows = np.array([x0, x0 + 1], dtype=int), np.array([y0, y0 + 1], dtype=int)
    if wrap == "repeat":
        cols, rows = cols % w, rows % h
    else:
        cols, rows = np.clip(cols, 0, w - 1), np.clip(rows, 0, h - 1)
    top = (1 - fx) * tex[rows[0], cols[0]] + fx * tex[rows[0], cols[1]]
    bottom = (1 - fx) * tex[rows[1], cols[0]] + fx * tex[rows[1], cols[1]]
    return top if x_only else (1 - fy) * top + fy * bottom


def test_a_bilinear_with_v_flipped_is_named_and_not_told_one_texel():
    report = ex.check("bilinear", lambda t, uv, w: _bilinear(t, uv, w, flip=True))
    said = [f.explanation for f in report.failures]
    assert any("you flipped v (1 − v)" in s for s in said), said[:2]
    assert not any("texel" in s and "alone" in s for s in said), said[:2]


def test_a_bilinear_along_x_only_is_not_told_one_texel_alone():
    report = ex.check("bilinear", lambda t, uv, w: _bilinear(t, uv, w, x_only=True))
    assert not report.passed
    for f in report.failures:
        assert "one texel alone" not in f.explanation, f.explanation
        assert "texels around (u, v) alone" not in f.explanation, f.explanation


def test_nearest_filtering_is_still_told_one_texel():
    def nearest(texture, uv, wrap):
        tex = np.asarray(texture, dtype=float)
        h, w = tex.shape[:2]
        col, row = int(np.floor(uv[0] * w)), int(np.floor(uv[1] * h))
        if wrap == "repeat":
            return tex[row % h, col % w]
        return tex[min(max(row, 0), h - 1), min(max(col, 0), w - 1)]

    said = _first(ex.check("bilinear", nearest))
    assert "nearest" in said, said


# -- 10: the first cell's length ------------------------------------------------------------------
def test_the_first_cell_is_short_and_the_rest_is_folded_after_the_setup():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    intro = "".join(cells[0]["source"])
    assert len(intro.split()) < 250, len(intro.split())  # r199: 496 words before the first task
    assert "Run All" in intro and "one at a time" in intro
    held = cells[2]
    # r205: a hidden Markdown source opened when the cell ran (Run All): a <details> fold
    # stays closed when rendered
    text = "".join(held["source"])
    assert text.startswith("<details><summary><b>How the check works</b>"), text[:80]
    assert text.rstrip().endswith("</details>")
    assert "report.explain_pixel(row, col)" in "".join(held["source"])
