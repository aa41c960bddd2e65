"""Exercises 05–08 of the course (lessons 05b, 08, 09 and 10), each with its whole picture.

Each exercise's module describes it (cases, mistakes); here each is given its scene
(:mod:`.picture_scenes`), which draws the student's function plugged into a small picture
beside the package's.
"""

from __future__ import annotations

from . import antialiasing as aa
from . import depth_precision as dp
from . import level_of_detail as lod
from . import picture_scenes as scenes
from . import resolve_light as rl
from . import texture_filtering as tf
from . import tile_blocks as tb

#: name: how to build its description, in course order.
EXERCISES = {
    "depth_to_unorm": lambda: dp.exercise(scenes.depth_scene),
    "coverage_fraction": lambda: aa.coverage_exercise(scenes.coverage_scene),
    "resolve": lambda: aa.resolve_exercise(scenes.resolve_scene),
    "resolve_srgb": lambda: rl.RESOLVE_SRGB,  # 6.3: the resolve in linear light (r40 06-2)
    "mip_level": lambda: lod.exercise(scenes.level_scene),
    "bilinear": lambda: tf.bilinear_exercise(scenes.bilinear_scene),
    "trilinear": lambda: tf.trilinear_exercise(scenes.trilinear_scene),
    "classify_block": lambda: tb.exercise(scenes.tile_scene),
}
