"""r222 (exercise 12, the capstone, a fresh read): the coverage explanation prints E as the
conventions define it, whatever the winding (C); a depth test that passes only the nearest
fragment of the pixel is named from exercise 4's table (half-named); ``over``'s check is named
by the lesson that teaches it; the wordings that read backwards; and the ten scenes' check
cells let Run All go on past a failing scene, as exercise 8's do."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest
import reasoning_solutions as sol
from test_capstone_r174 import NOTEBOOK, _cell

from teachraster import edge_function
from teachraster import exercises as ex
from teachraster.exercises import blending, capstone_explain, coverage, tries, zbuffer_pixel
from teachraster.exercises.capstone_render import SCENES
from teachraster.exercises.capstone_scenes import capstone_scene


def _mine(scene, **changed):
    return {name: changed.get(name, sol.CAPSTONE[name]) for name in SCENES[scene].uses}


# -- 1 (C): E printed with the conventions' sign ---------------------------------------------------
def _one_winding(xy, p):
    """covers that tests E ≥ 0 on the edges as given: a counter-clockwise triangle (on
    screen) covers nothing."""
    v1, v2, v3 = xy
    for a, b in ((v1, v2), (v2, v3), (v3, v1)):
        e = edge_function(a, b, p)
        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        if e < 0 or (e == 0 and not top_left):
            return False
    return True


#: "centre (x, y) is strictly inside all three edges (E = a, b, c px²" or "... outside edge
#: vi→vj (E = a px²": the centre and the E values a report prints.
_INSIDE = re.compile(r"centre \(([-\d.e+]+), ([-\d.e+]+)\) is strictly inside all three edges "
                     r"\(E = ([-\d.e+]+), ([-\d.e+]+), ([-\d.e+]+) px²")  # fmt: skip
_OUTSIDE = re.compile(r"centre \(([-\d.e+]+), ([-\d.e+]+)\) is outside edge v(\d)→v\d \(E = "
                      r"([-\d.e+]+) px²")  # fmt: skip


def _triangles(n=200, seed=222):
    rng = np.random.default_rng(seed)
    for _ in range(n):
        xy = np.rint(rng.uniform(0, 12, (3, 2)) * 256) / 256
        if coverage.area2(xy) != 0:
            yield xy, np.floor(rng.uniform(0, 12, 2)) + 0.5


def test_every_printed_e_is_the_conventions_e_in_both_windings():
    """r222 C: a counter-clockwise triangle's E were printed with their sign flipped (the
    student's own edge_function gives the other sign); now each number is E(a, b, p)."""
    seen = {"inside": set(), "outside": set()}
    for xy, c in _triangles():
        text, _, kind = coverage.explain_pixel(xy, c, True)
        sign = int(np.sign(coverage.area2(xy)))
        if kind == "inside":
            printed = [float(v) for v in _INSIDE.match(text).groups()[2:]]
            want = [float(edge_function(xy[k], xy[(k + 1) % 3], c)) for k in range(3)]
            assert np.allclose(printed, want, atol=1e-3), text
            assert all(np.sign(v) == sign for v in printed), text
            seen["inside"].add(sign)
        elif kind == "outside":
            m = _OUTSIDE.match(text)
            k = int(m.group(3)) - 1
            want = float(edge_function(xy[k], xy[(k + 1) % 3], c))
            assert np.isclose(float(m.group(4)), want, atol=1e-3), text
            assert np.sign(want) == -sign, text  # the side away from the interior
            seen["outside"].add(sign)
        # the words on the interior's sign are said in one place, and only with its sign
        assert coverage.interior_side(xy) in text or kind not in ("inside", "outside"), text
        assert ("must flip the sign" in text) == (sign < 0 and kind in ("inside", "outside"))
    assert seen == {"inside": {1, -1}, "outside": {1, -1}}, seen


def test_the_grid_s_winding_report_agrees_with_its_own_numbers():
    """The reader's V1: the pixel's E and the example's E were printed +3.673 … and 9, 117, 9
    beside E(v1, v2, v3) = −135; each triple now sums to its triangle's E(v1, v2, v3)."""
    report = ex.capstone("grid", covers=_one_winding)
    text = str(report)
    assert not report.passed
    assert "E = -3.673, -2.314, -0.761 px², all negative" in text, text
    assert "E = -9, -117, -9 px², all negative" in text, text
    assert "E = 3.673, 2.314, 0.761" not in text and "E = 9, 117, 9" not in text, text
    assert "E(v1, v2, v3) = -6.748 < 0" in text and "E(v1, v2, v3) = -135" in text, text
    assert "a test for E > 0 must flip the sign first or swap two vertices" in text, text


def test_exercise_1_s_own_report_prints_the_same_signed_e():
    report = ex.check("covers", _one_winding)
    text = "\n".join(f.explanation for f in report.failures)
    assert "E = 9, 117, 9" not in text, text
    triples = re.findall(r"E = ([-\d.]+), ([-\d.]+), ([-\d.]+) px², all (\w+)", text)
    assert triples, text
    for a, b, c, sign in triples:
        values = np.array([float(a), float(b), float(c)])
        assert np.all(values < 0 if sign == "negative" else values > 0), text


# -- 2 (half-named): only the nearest fragment passes --------------------------------------------
def _nearest_only(depths, writes):
    """The reader's D4: np.argmin over the pixel (raises on no fragments, as theirs did)."""
    d = np.asarray(depths, dtype=float)
    return [bool(x) for x in np.arange(len(d)) == np.argmin(d)]


def _nearest_all(depths, writes):
    d = np.asarray(depths, dtype=float)
    return [bool(x) for x in d == d.min()] if len(d) else []


def _right(depths, writes):
    stored, out = np.inf, []
    for d, w in zip(depths, writes):
        out.append(d < stored)
        if d < stored and w:
            stored = d
    return out


def _nearest_from_four(depths, writes):
    """Right below four fragments, nearest-only from four: no one mistake gives it all."""
    return _nearest_only(depths, writes) if len(depths) >= 4 else _right(depths, writes)


@pytest.mark.parametrize("fn, words", [(_nearest_only, zbuffer_pixel.NEAREST_WORDS),
                                       (_nearest_all, zbuffer_pixel.NEAREST_TIES_WORDS)])  # fmt: skip
@pytest.mark.parametrize("first_try", [True, False])
def test_only_the_nearest_is_named_in_exercise_4_and_the_capstone(fn, words, first_try):
    if first_try:
        tries.forget_hints("depth_passes")
    own = ex.check("depth_passes", fn)
    assert not own.passed and words in str(own), str(own)
    if first_try:
        tries.forget_hints("depth_passes")
    report = ex.capstone("intersecting_triangles", depth_passes=fn)
    said = report.failures[0].explanation
    assert report.failures[0].kind == "depth test" and words in said, said
    assert "A fragment passes when it is strictly nearer" not in said, said


def test_the_nearest_mistake_is_named_only_where_it_gives_every_answer():
    """Reproducing all the cases: a test wrong only from four fragments on is not told it."""
    own = ex.check("depth_passes", _nearest_from_four)
    assert not own.passed
    assert "nearest fragment of the whole pixel" not in str(own), str(own)
    assert ex.check("depth_passes", _right).passed
    first = ex.check("depth_passes", lambda d, w: [k == 0 for k in range(len(d))])
    assert "only the first fragment passes" in str(first), str(first)


def test_the_nearest_mistake_reproduces_the_reader_s_answers():
    for _, (depths, writes), _ in zbuffer_pixel.depth_cases():
        if len(depths):
            mistake = next(m for m in zbuffer_pixel.DEPTH_MISTAKES if m.kind == "nearest only")
            assert mistake.gives(depths, writes).tolist() == _nearest_only(depths, writes)


# -- 3: names and wordings -------------------------------------------------------------------------
def _straight_over(src, dst):
    src, dst = np.asarray(src, dtype=float), np.asarray(dst, dtype=float)
    return src * src[3] + dst * (1 - src[3])


def _alpha_one(src, dst):
    out = np.asarray(sol.CAPSTONE["over"](src, dst), dtype=float)
    out[3] = 1.0
    return out


@pytest.mark.parametrize("over", [_straight_over, _alpha_one])
@pytest.mark.parametrize("scene", ["glass", "glass_sorted"])
def test_over_s_check_is_named_by_the_lesson_that_teaches_it(scene, over):
    report = ex.capstone(scene, **_mine(scene, over=over))
    text = str(report)
    assert not report.passed
    assert "over_premultiplied exercise" not in text, text
    assert "lesson 12b §4's premultiplied over" in text, text
    assert 'ex.check("over_premultiplied", over)' in text, text
    cells = "".join("".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"])
    assert "over_premultiplied exercise" not in cells
    assert capstone_explain.check_words("depth_passes") == "the depth_passes exercise's check"


def test_premultiplying_twice_is_no_fringe_on_the_glass():
    """The glass darkens all over: the words say what the slip does, and where a fringe shows."""
    report = ex.capstone("glass", **_mine("glass", over=_straight_over))
    text = str(report)
    assert "(the dark fringe)" not in text and blending.TOO_DARK in text, text
    assert "too dark" in blending.TOO_DARK and "soft edge" in blending.TOO_DARK


def test_red_grows_from_column_to_column_as_the_text_says():
    untinted = np.asarray(capstone_scene("textured_floor").texture, dtype=float)
    tinted = np.asarray(capstone_scene("textured_floor", tiled=True).texture, dtype=float)
    light = untinted[..., 0] > 0
    red = np.where(light, tinted[..., 0] / np.where(light, untinted[..., 0], 1), np.nan)
    green = np.where(light, tinted[..., 1] / np.where(light, untinted[..., 1], 1), np.nan)
    assert np.all(np.diff(np.nanmean(red, axis=0)) > 0)  # along a row, column by column
    assert np.nanstd(red, axis=0).max() < 1e-12  # the same down each column
    assert np.all(np.diff(np.nanmean(green, axis=1)) > 0)  # down a column, row by row
    assert "red grows from column to column (left to right, with u)" in " ".join(
        _cell("12.7").split()
    )
    assert "along its columns" not in _cell("12.7") and "along the columns" not in _cell("12.10")


def test_how_the_check_works_names_every_stage_a_report_names():
    text = " ".join(_cell_text(2).split())
    stages = ("coverage", "sample coverage", "depth test", "interpolation", "blending",
              "texture filtering", "resolve", "sorting", "A-buffer resolve")  # fmt: skip
    source = open(capstone_explain.__file__).read()
    for stage in stages:
        assert stage in text, stage
        assert f'"{stage}"' in source, stage  # a name explain_pixel returns


def test_the_glass_cell_says_what_exercise_4_checks():
    text = " ".join(_cell("12.6").split())
    assert "check that it does" not in text
    assert "check that it rejects glass behind a wall" in text
    cases = {label: (args, passed) for label, args, passed in zbuffer_pixel.depth_cases()}
    (depths, writes), passed = cases["a wall, then glass behind it"]
    assert not writes[1] and passed.tolist() == [True, False]


def _cell_text(i: int) -> str:
    return "".join(json.loads(NOTEBOOK.read_text())["cells"][i]["source"])


# -- 4: Run All goes on past a failing scene ---------------------------------------------------------
def test_every_scene_s_check_cell_lets_run_all_go_on():
    """As exercise 8's (r162 D6): nbgrader's metadata as tested in test_nbgrader, the tag
    beside it; cell 0 no longer asks to run the scenes one at a time."""
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    checks = [c for c in cells if c["metadata"].get("nbgrader", {}).get("grade")]
    assert len(checks) == len(SCENES) == 10
    for c in checks:
        assert "report.assert_passed()" in "".join(c["source"])
        assert c["metadata"]["tags"] == ["raises-exception"], c["metadata"]
        assert set(c["metadata"]) == {"nbgrader", "tags"}
    intro = " ".join(_cell_text(0).split())
    assert "Run the scenes one at a time" not in intro and "*Run All* goes on past it" in intro
