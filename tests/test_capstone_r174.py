"""r174 (exercise 12, the capstone, a fresh read): each finding, as a class, with a test that
fails on the code before the fix."""

from __future__ import annotations

import json
import math
import time
from pathlib import Path

import numpy as np
import pytest
import reasoning_solutions as sol
import student_variants as sv

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import alarm as alarm_module
from teachraster.exercises import running, tries
from teachraster.exercises.alarm import Alarm
from teachraster.exercises.capstone_render import SCENES

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/12_capstone.ipynb"


def _mine(scene, **changed):
    return {name: changed.get(name, sol.CAPSTONE[name]) for name in SCENES[scene].uses}


def _cell(heading: str) -> str:
    for cell in json.loads(NOTEBOOK.read_text())["cells"]:
        text = "".join(cell["source"])
        if text.startswith(f"## {heading} "):
            return text
    raise AssertionError(f"no cell under ## {heading}")


# -- 12-1: exercise 6.3's resolve in linear light, plugged in --------------------------------------
def _resolve_as_6_3(sample_colours, sample_ids, background):
    c = np.where(np.asarray(sample_ids)[:, None] >= 0, sample_colours, background)
    return tr.linear_to_srgb(np.mean(tr.srgb_to_linear(c), axis=0))


def test_the_linear_light_resolve_of_6_3_is_named_not_sent_to_the_uncovered_share():
    """It was asked what the pixel shows where no triangle covered the sample, which it
    handled right: the space it averages in is the mistake (the samples are light)."""
    text = str(ex.capstone("cube_msaa", **_mine("cube_msaa", resolve=_resolve_as_6_3)))
    assert "lesson 08's sRGB resolve" in text and "light already" in text, text
    assert "where no triangle covered the sample" not in text, text


def test_12_9_says_the_samples_are_light_and_which_resolve_is_wanted():
    text = _cell("12.9")
    assert "light already" in text and "6.2's plain mean" in text, text


# -- 12-2: a slow function and the busy machine -------------------------------------------------
def _stopped_at_the_wall(cpu: float, seconds: float = 10.0) -> Alarm:
    """An alarm stopped by the check's wall-clock limit after ``cpu`` seconds of CPU."""
    alarm = Alarm(seconds, None, cap=running.WALL_FACTOR * seconds)
    alarm.begin = time.perf_counter() - 100.0
    alarm._clock, alarm._cpu_start, alarm._cpu_now = (lambda: cpu), 0.0, 0.0
    return alarm


def test_more_cpu_than_the_budget_is_too_slow_not_a_busy_machine():
    """r174 12-2: "computed for 11.2 s of it: the machine is too busy" under a 10 s budget."""
    # run_case adds the case's CPU to the budget's before it asks for the words
    slow = running._too_busy(_stopped_at_the_wall(11.2), running.Budget(10.0, used=11.2), "")
    assert "too busy" not in slow and "more than the check's budget of 10 s" in slow, slow
    assert "far slower than needed" in slow, slow
    busy = running._too_busy(_stopped_at_the_wall(3.0), running.Budget(10.0, used=3.0), "")
    assert "too busy" in busy, busy


def test_the_case_stopped_at_the_wall_is_counted_once():
    """r199 C1: the words added the stopped case's CPU to a budget that already held it: a
    correct function that had computed for 7.1 s (3.55 s in the stopped case) of a 10-s
    budget was told it computed for 10.65 s, "more than the check's budget"."""
    words = running._too_busy(_stopped_at_the_wall(3.55), running.Budget(10.0, used=7.1), "")
    assert "computed for 7.1 s of it" in words and "too busy" in words, words
    assert "more than the check's budget" not in words, words


def test_the_advice_names_the_call_the_student_made():
    """The capstone's advice named check(..., budget=30), which its notebook never calls."""
    said = []

    def covers(xy, p):  # what the budget running this call would tell the student
        said.append(running.current().more_time())
        return sol.covers(xy, p)

    assert ex.capstone("grid", covers=covers).passed
    # the render's calls come first (its own exercise's check, run after it, says check(...))
    assert said[0] == "ex.capstone('grid', ..., budget=30)", set(said)
    with running.budget(1.0) as b:  # ex.check's own advice is unchanged
        assert "check(..., budget=30) gives it more time" in running._timeout(None, b, None).error


def test_the_wall_clock_factors_live_in_one_place():
    assert running.WAIT_FACTOR is alarm_module.WAIT_FACTOR
    assert running.CASE_WALL_FACTOR is alarm_module.CASE_WALL_FACTOR
    alarm = Alarm(0.5, None)
    assert alarm.wait == alarm_module.WAIT_FACTOR * 0.5
    assert alarm.cap == alarm_module.CASE_WALL_FACTOR * 0.5


# -- 12-3: the package's functions inside the composite pieces -----------------------------------
def _trilinear_on_the_packages_bilinear(pyramid, uv, lod, wrap="repeat"):
    q = len(pyramid) - 1
    lam = min(max(lod, 0.0), q)
    lo = math.floor(lam)
    hi, t = min(lo + 1, q), lam - lo
    uv = np.asarray(uv, dtype=float)[None]
    a = tr.sample(pyramid[lo], uv, "bilinear", wrap)[0]
    b = tr.sample(pyramid[hi], uv, "bilinear", wrap)[0]
    return (1 - t) * a + t * b


def _a_buffer_on_blend_equation(depths, colours, background):
    result = np.asarray(background, dtype=float)
    for k in np.argsort(-np.asarray(depths)):
        result = tr.blend_equation(colours[k], result, "ONE", "ONE_MINUS_SRC_ALPHA")
    return result


def test_a_trilinear_on_the_packages_bilinear_is_not_counted():
    """12.8 and 7.3 ask for each level filtered by the student's own bilinear."""
    report = ex.capstone("floor_trilinear", trilinear=_trilinear_on_the_packages_bilinear)
    assert not report.passed and "not counted" in str(report), str(report)
    assert "your trilinear calls teachraster's sample" in str(report), str(report)
    own = ex.check("trilinear", _trilinear_on_the_packages_bilinear)  # one rule: 7.3's too
    assert not own.passed and own.package is not None, str(own)
    assert ex.capstone("floor_trilinear", trilinear=sol.CAPSTONE["trilinear"]).passed


def test_an_a_buffer_blending_with_blend_equation_is_not_counted():
    """The same call as over is refused in 12.5 and 12.6; inside a_buffer it passed."""
    report = ex.capstone(
        "glass_sorted", **_mine("glass_sorted", a_buffer=_a_buffer_on_blend_equation)
    )
    assert not report.passed and "not counted" in str(report), str(report)
    assert "your a_buffer calls teachraster's blend_equation" in str(report), str(report)
    assert ex.capstone("glass_sorted", **_mine("glass_sorted")).passed


# -- 12-4 to 12-7: explanations half-named, or the whole fix on a first try -----------------------
_LE = sv.WRONG["passes with <="][1]


def test_a_tie_mistake_is_asked_about_before_its_fix_is_given():
    """12.4's <= was told "use <, not <=" (and the package's "strictly nearer") at once."""
    tries.forget_hints("depth_passes")
    try:
        first = str(ex.capstone("intersecting_triangles", depth_passes=_LE))
        assert "use <, not <=" not in first and "strictly nearer" not in first, first
        assert "which of the two must the pixel keep" in first, first
    finally:
        tries.spend_hints(["depth_passes"])
    full = ex.check("depth_passes", _LE)
    assert any("use <, not <=" in f.explanation for f in full.failures), str(full)


def _bilinear_swapped(texture, uv, wrap, axes="xy"):
    tex = np.asarray(texture, dtype=float)
    h, w = tex.shape[:2]
    x, y = uv[0] * w - 0.5, uv[1] * h - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = x - x0, y - y0
    fx, fy = (1 - fx if "x" in axes else fx), (1 - fy if "y" in axes else fy)
    cols, rows = np.array([x0, x0 + 1], dtype=int) % w, np.array([y0, y0 + 1], dtype=int) % h
    top = (1 - fx) * tex[rows[0], cols[0]] + fx * tex[rows[0], cols[1]]
    bottom = (1 - fx) * tex[rows[1], cols[0]] + fx * tex[rows[1], cols[1]]
    return (1 - fy) * top + fy * bottom


def test_both_weight_pairs_swapped_are_named_both():
    """r163 12-7, r174 12-5: "the weights along y are swapped" for a swap along x and y."""
    text = str(ex.capstone("floor_bilinear", bilinear=_bilinear_swapped))
    assert "right (lower) texel" in text and "left (upper) one" in text, text
    assert "the weights along y are swapped" not in text, text


def _trilinear_reversed(pyramid, uv, lod, wrap="repeat"):
    q = len(pyramid) - 1
    lam = min(max(lod, 0.0), q)
    d = math.floor(lam)
    t = lam - d
    bilinear = sol.CAPSTONE["bilinear"]
    return t * bilinear(pyramid[d], uv, wrap) + (1 - t) * bilinear(pyramid[min(d + 1, q)], uv, wrap)


def test_the_reversed_trilinear_weight_says_where_the_fraction_went():
    """At λ = 0 it returned level 1 alone, and was told "yours went to level 0"."""
    from teachraster.exercises.texture_filtering import NAMED_HINTS
    from teachraster.exercises.tries import apply_hints

    full = ex.check("trilinear", _trilinear_reversed)
    said = next(f.explanation for f in full.failures if f.kind == "weights swapped")
    hinted = apply_hints(said, NAMED_HINTS)
    assert "yours went to" not in hinted, hinted
    assert "yours grows as λ nears level 0 (the two levels' weights are swapped)" in hinted, hinted
    assert "λ − ⌊λ⌋" not in hinted, hinted  # still a hint: the formula is held


def _wrong_over(src, dst):  # dst over src
    return sol.over_premultiplied(dst, src)


def _other_wrong_over(src, dst):  # the source multiplied by its alpha again
    src, dst = np.asarray(src, float), np.asarray(dst, float)
    return src * src[3] + dst * (1 - src[3])


def _a_buffer_calling(over):
    def a_buffer(depths, colours, background):
        result = np.asarray(background, float)
        for k in np.argsort(-np.asarray(depths)):
            result = np.asarray(over(colours[k], result))
        return result

    return a_buffer


def test_failures_of_over_alone_do_not_hand_over_the_a_buffers_order():
    """r174 12-7: two failures in over, with a right a_buffer, brought "start from the
    farthest" on the next failure of a_buffer."""
    tries.forget_hints("a_buffer")
    try:
        frames = set()
        for over in (_wrong_over, _other_wrong_over):
            report = ex.capstone("glass_sorted", over=over, a_buffer=_a_buffer_calling(over))
            frames.add(np.asarray(report.mine.color).tobytes())
        assert len(frames) == 2  # two different failing frames, as two tries of a_buffer are
        assert not tries.hints_spent("a_buffer")
    finally:
        tries.spend_hints(["a_buffer"])


# -- 12-9: the report said twice ------------------------------------------------------------------
def test_a_stubs_failed_assertion_does_not_repeat_its_report():
    def covers(xy, p):
        raise NotImplementedError()

    report = ex.capstone("grid", covers=covers)
    with pytest.raises(AssertionError) as raised:
        report.assert_passed()
    assert "not implemented yet" in str(report)
    assert "not implemented yet" not in str(raised.value), str(raised.value)
    assert "printed above" in str(raised.value)


# -- 12-11, 12-13: what the text says of the figures, and its prose -------------------------------
def test_the_tint_is_said_to_be_faint_where_the_panels_cannot_show_it():
    # r199 C2: the tint itself shows (lavender squares); only the ramps' directions do not
    assert "too gentle to see in the panels" in _cell("12.7")
    assert "red growing along its columns" not in _cell("12.7")
    assert "faintly" not in _cell("12.7") and "faintly" not in _cell("12.10")


def test_the_sky_rows_and_the_parentheses():
    cells = ["".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]]
    assert any("rows 0–15 are sky" in c for c in cells)
    assert ") (" not in _cell("12.2")
