"""r502: the capstone reports a wrong or unfinished ``texel_weights`` through it.

12.7 gives exercise 7.3's ``trilinear`` and ``bilinear`` built on the student's
``texel_weights``; a stub is "texel_weights is not written yet", a raising one an explained
failure naming texel_weights (no raw error alone), a wrong one exercise 7.2's explanation and
``ex.check("texel_weights", texel_weights)``; never "your bilinear".
"""

from __future__ import annotations

import numpy as np
import pytest
from test_exercises_r497 import SOURCES

import teachraster.exercises as ex
from teachraster.exercises.capstone_texels import CHECK_CALL, texel_source, texels_behind

#: 12.7's given cell (exercise 7.3's filters), as the notebook holds it.
GIVEN = """
def trilinear(pyramid, uv, lod, wrap="repeat"):
    sizes = [np.shape(level)[:2] for level in pyramid]
    texels = texel_weights(sizes, uv, lod, wrap)
    return sum(
        weight * np.asarray(pyramid[k], dtype=float)[row, col]
        for (k, row, col), weight in texels.items()
    )


def bilinear(texture, uv, wrap):
    return trilinear([texture], uv, 0.0, wrap)
"""
STUB = "def texel_weights(sizes, uv, lod, wrap):\n    raise NotImplementedError()\n"
RIGHT = SOURCES["w01_lod_clamped_q_minus_1"].replace("max(q - 1, 0)", "q")
SCENES = {"floor_bilinear": "bilinear", "floor_trilinear": "trilinear"}


def built(source: str) -> dict:
    """The namespace of 12.7's cell with ``source``'s texel_weights."""
    names = {"np": np}
    exec(source + GIVEN, names)  # noqa: S102 - the test's own code
    return names


def report(source: str, scene: str):
    name = SCENES[scene]
    return ex.capstone(scene, **{name: built(source)[name]})


def test_the_given_filters_find_texel_weights():
    names = built(RIGHT)
    assert texel_source(names["bilinear"]) is names["texel_weights"]
    assert texels_behind({"trilinear": names["trilinear"]}) == {"trilinear": names["texel_weights"]}
    assert texels_behind({"bilinear": len}) == {}


def test_the_right_texel_weights_passes_both_scenes():
    for scene in SCENES:
        assert report(RIGHT, scene).passed, scene


@pytest.mark.parametrize("scene", list(SCENES))
def test_an_unfinished_texel_weights_is_named(scene):
    r = report(STUB, scene)
    text = str(r)
    assert r.not_implemented and r.unfinished == "texel_weights"
    assert "texel_weights is not written yet" in text
    assert "bilinear raises" not in text and "trilinear raises" not in text
    assert "texel_weights raises NotImplementedError" in r.no_difference()


@pytest.mark.parametrize("scene", list(SCENES))
@pytest.mark.parametrize(
    ("key", "words"),
    [
        ("w27_weight_list_keys_level_last", "your keys are (row, col, level)"),
        ("w12_t_div_zero", "a division by (upper − lower) = 0?"),
    ],
)
def test_a_raising_texel_weights_is_explained(scene, key, words):
    r = report(SOURCES[key], scene)
    text = str(r)
    assert not r.passed
    assert "texel_weights" in text and words in text and CHECK_CALL in text
    assert f"your {SCENES[scene]} raised" not in text
    assert f"your {SCENES[scene]} fails" not in text
    assert "your function" not in text


@pytest.mark.parametrize("scene", list(SCENES))
def test_a_wrong_texel_weights_points_to_exercise_7_2(scene):
    r = report(SOURCES["w08_v_flipped"], scene)
    text = str(r)
    assert r.n_wrong > 0
    assert "adding up your texel_weights" in text
    assert "exercise 7.2's check fails your texel_weights (v flipped)" in text
    assert "you flipped v (1 − v)" in text and CHECK_CALL in text
    assert f"your {SCENES[scene]}" not in text
    row, col = r.differing_pixels()[0]
    assert "exercise 7.2's check" in r.explain_pixel(int(row), int(col))


def test_the_sphere_names_texel_weights_too():
    """12.10 takes 12.7's bilinear: its texture filtering names texel_weights too."""
    import reasoning_solutions as sol

    from teachraster.exercises.capstone_render import SCENES as ALL

    functions = {name: sol.CAPSTONE[name] for name in ALL["sphere"].uses}
    functions["bilinear"] = built(SOURCES["w08_v_flipped"])["bilinear"]
    r = ex.capstone("sphere", **functions)
    text = str(r)
    assert not r.passed and "texture filtering" in text
    assert "exercise 7.2's check fails your texel_weights" in text
    assert "your bilinear" not in text
