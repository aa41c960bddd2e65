"""Exercises 05–08 of the course (lessons 05b, 08, 09 and 10), as the registry runs them.

Each entry checks a student's function on its cases (:func:`.scene_report.check_cases`) and
returns a :class:`.scene_report.SceneReport`, which can also draw the function plugged into a
small scene beside the package's (:mod:`.picture_scenes`, :mod:`.compare_scenes`).
"""

from __future__ import annotations

from collections.abc import Callable

from . import antialiasing as aa
from . import depth_precision as dp
from . import level_of_detail as lod
from . import picture_scenes as scenes
from . import texture_filtering as tf
from . import tile_blocks as tb
from .scene_report import check_cases

#: name: (cases, convert, same, explain, draw, scene)
SPECS = {
    "depth_to_unorm": (
        dp.depth_cases, dp.as_count, dp.same_depth, dp.explain_depth, dp.draw_depth,
        scenes.depth_scene,
    ),
    "coverage_fraction": (
        aa.coverage_cases, aa.as_fraction, aa.same_fraction, aa.explain_coverage,
        aa.draw_coverage_case, scenes.coverage_scene,
    ),
    "resolve": (
        aa.resolve_cases, aa.as_colour, aa.same_colour, aa.explain_resolve,
        aa.draw_resolve_case, scenes.resolve_scene,
    ),
    "mip_level": (
        lod.level_cases, aa.as_fraction, aa.same_number, lod.explain_level,
        lod.draw_level_case, scenes.level_scene,
    ),
    "bilinear": (
        tf.bilinear_cases, tf.as_texel_value, tf.same_value, tf.explain_bilinear,
        tf.draw_texture_case, scenes.bilinear_scene,
    ),
    "trilinear": (
        tf.trilinear_cases, tf.as_texel_value, tf.same_value, tf.explain_trilinear,
        tf.draw_texture_case, scenes.trilinear_scene,
    ),
    "classify_block": (
        tb.block_cases, tb.as_kind, tb.same_kind, tb.explain_block, tb.draw_block_case,
        scenes.tile_scene,
    ),
}  # fmt: skip


def _checker(name: str) -> Callable:
    cases, convert, same, explain, draw, scene = SPECS[name]

    def check(fn, budget=None):
        return check_cases(name, fn, cases(), convert, same, explain, draw, scene, budget)

    check.__name__ = f"check_{name}"
    return check


#: The exercises of 05–08 in course order, and what checks each.
EXERCISES: dict[str, Callable] = {name: _checker(name) for name in SPECS}
