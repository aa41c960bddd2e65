"""r219 (exercise 12, the capstone): 12.7 and 12.10 name exercise 7.2's new slips from the
same table (tests/test_exercises_r219.py), a named mistake only where it gives the student's
answer at the pixel and at the scene's other points tried (:data:`.hiz_tile.EXACT`'s
discipline), and "How the check works" quotes the scene's wall-clock cap."""

from __future__ import annotations

import json
import re

import exercise_solutions as es
import numpy as np
import pytest
import reasoning_solutions as sol
from test_capstone_r174 import NOTEBOOK
from test_exercises_r219 import COL_ROW, SLIPS, solution_with

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import alarm, capstone_explain, running
from teachraster.exercises.capstone_render import SCENES
from teachraster.exercises.capstone_scenes import capstone_scene
from teachraster.exercises.texture_filtering import plain_bilinear

CAPSTONE = "12_capstone.ipynb"
NAMED = 'the bilinear check (ex.check("bilinear", bilinear) runs it) names the mistake: '


def _slipped(edits):
    return solution_with(CAPSTONE, edits)


def _first(scene: str, bilinear) -> str:
    used = {name: sol.CAPSTONE[name] for name in SCENES[scene].uses}
    report = ex.capstone(scene, **{**used, "bilinear": bilinear})
    assert not report.passed
    return report.failures[0].explanation


@pytest.mark.parametrize("kind", list(SLIPS))
def test_each_slip_is_named_at_the_floor_s_first_pixel(kind):
    said = _first("floor_bilinear", _slipped(SLIPS[kind][0]))
    assert NAMED in said, said
    for words in SLIPS[kind][1][:2]:
        assert words in said, said


def test_texture_col_row_is_said_with_the_scene_s_texture():
    """Words that quote the case say the pixel's texture (128 × 128), not the exercise's."""
    said = _first("floor_bilinear", _slipped(list(COL_ROW)))
    assert "the H = 128 rows" in said and "in its own case" not in said, said


def test_the_sphere_names_the_wrap_modes_exchanged_not_always_clamp():
    """Every capstone point asks for 'repeat', where "always clamp" gives the same answers:
    the kind exercise 7.2's check names decides (it asks 'clamp' too)."""
    said = _first("sphere", _slipped([('if wrap == "repeat":', 'if wrap == "clamp":')]))
    assert NAMED + "the wrap modes are exchanged" in said, said


def _two_faced(texture, uv, wrap):
    """v flipped on the exercise's small textures, u flipped on the scenes' large ones."""
    small = np.shape(texture)[0] <= 8
    return plain_bilinear(texture, uv, wrap, flip_v=small, flip_u=not small)


def test_a_mistake_the_exercise_names_is_not_said_of_a_pixel_it_does_not_give():
    assert ex.check("bilinear", _two_faced).failures[0].kind == "v flipped"
    said = _first("floor_bilinear", _two_faced)
    assert "you flipped v" not in said and "you flipped u" not in said, said
    assert "no such mistake gives your answers here" in said, said


def test_one_point_that_cannot_tell_two_swaps_apart_takes_the_scene_s_others():
    """At y − ⌊y⌋ = ½ the weights swapped along x alone and along both axes give the same
    value: the scene's other points tell them apart (both were told there before, r219)."""
    tex = capstone_scene("textured_floor", True, True).texture
    uv = np.array([0.3, 65 / 128])  # y = 64.5
    along_x = lambda t, p, w: plain_bilinear(t, p, w, swap="x")  # noqa: E731
    both = plain_bilinear(tex, uv, "repeat", swap=True)
    yours = along_x(tex, uv, "repeat")
    assert np.allclose(yours, both)  # this point alone cannot tell them apart
    ours = tr.sample(tex, uv[None], "bilinear")[0]
    rng = np.random.default_rng(219)
    also = [((tex, p, "repeat"), tr.sample(tex, p[None], "bilinear")[0])
            for p in rng.uniform(-0.25, 1.25, size=(6, 2))]  # fmt: skip
    used = {"bilinear": along_x}
    said = capstone_explain.named_mistake(
        used, "bilinear", case=((tex, uv, "repeat"), ours, yours), also=also
    )
    assert "the weights along x are swapped" in said and "(lower)" not in said, said


RIGHT = {
    "vectorised (the notebook's)": _slipped([]),
    "loops": es.bilinear,
    "lerps with np.ix_": es.bilinear_lerp,
    "float32 texture": _slipped([("dtype=float)", "dtype=np.float32)")]),
}


@pytest.mark.parametrize("name", list(RIGHT))
def test_right_solutions_written_otherwise_pass_the_floor(name):
    report = ex.capstone("floor_bilinear", bilinear=RIGHT[name])
    assert report.passed, str(report)


# -- the wall-clock cap, quoted where the check's limits are said -----------------------------------
def _cells() -> list:
    return json.loads(NOTEBOOK.read_text())["cells"]


def test_how_the_check_works_quotes_the_wall_clock_cap():
    how = "".join(_cells()[2]["source"])
    assert how.startswith("<details><summary><b>How the check works</b>")
    said = re.findall(r"(\d+(?:\.\d+)?) s of wall-clock time", how)
    assert said == [f"{ex.CAPSTONE_WALL_LIMIT:g}"], said
    assert "ex.CAPSTONE_WALL_LIMIT" in how
    setup = "".join(_cells()[1]["source"])
    assert "{ex.CAPSTONE_WALL_LIMIT:g} s of wall-clock" in setup


def test_the_wall_clock_cap_is_the_one_a_scene_is_given(monkeypatch):
    """The constant is what a scene's render is capped at: its one case's cap."""
    caps = []

    class Recording(alarm.Alarm):
        def __init__(self, seconds, guard, wait=None, cap=None, call=None):
            super().__init__(seconds, guard, wait, cap, call)
            if call is not None:  # the render: calls of the student's function inside
                caps.append(self.cap)

    monkeypatch.setattr(running, "Alarm", Recording)
    monkeypatch.delenv(running.BUDGET_VARIABLE, raising=False)
    assert ex.capstone("floor_bilinear", bilinear=sol.CAPSTONE["bilinear"]).passed
    assert caps and caps[0] == pytest.approx(ex.CAPSTONE_WALL_LIMIT, abs=1.0), caps
    assert ex.CAPSTONE_WALL_LIMIT == 100
