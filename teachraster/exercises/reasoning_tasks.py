"""The exercises that replace the course's one-line tasks, and those of lessons 07, 09-12
(issue 30), as the registry runs them.

Each is checked like every value exercise (:func:`.value_checks.check_value_exercise`: the
time budget, strict answers, one failure of each kind first); its cases, expected answers,
named mistakes and drawings live in its own module:

- ``span`` (lesson 01, :mod:`.spans`), ``perspective_weights`` (04,
  :mod:`.perspective_weighting`), ``depth_passes`` (05a, :mod:`.zbuffer_pixel`),
  ``safe_near`` (05b, :mod:`.near_plane`): reasoning in place of ``split_point``,
  ``perspective``, ``depth_test`` and ``depth_to_unorm`` (still checked, for notebooks of
  earlier versions);
- ``robust_fill`` (07, :mod:`.hard_case_fill`): the naive rasteriser against the catalogue;
- ``quad_derivatives`` (09, :mod:`.quad_difference`), ``hiz_rejects`` (10, :mod:`.hiz_tile`),
  ``front_to_back`` (12, :mod:`.front_to_back`);
- ``broken_frame_1`` … ``broken_frame_6`` (11, :mod:`.broken_frames`).
"""

from __future__ import annotations

from collections.abc import Callable

from . import broken_frames as bf
from . import front_to_back as fb
from . import hard_case_fill as hf
from . import hiz_tile as hz
from . import near_plane as npl
from . import perspective_weighting as pw
from . import quad_difference as qd
from . import spans
from . import zbuffer_pixel as zb
from .answers import as_bool, as_number
from .value_checks import ValueExercise, check_value_exercise

#: name: how it is checked.
SPECS = {
    "span": ValueExercise(spans.span_cases, spans.as_span, spans.same_span, spans.explain_span,
                          spans.draw_span, spans.span_pattern),
    "perspective_weights": ValueExercise(pw.weights_cases, pw.as_weights, pw.same_weights,
                                         pw.explain_weights, pw.draw_weights),
    "depth_passes": ValueExercise(zb.depth_cases, zb.as_passes, zb.same_passes, zb.explain_depth,
                                  zb.draw_depth_passes, zb.depth_pattern),
    "safe_near": ValueExercise(npl.near_cases, as_number, npl.same_near, npl.explain_near,
                               npl.draw_near),
    "robust_fill": ValueExercise(hf.fill_cases, hf.as_image, hf.same_image, hf.explain_fill,
                                 hf.draw_fill, hf.fill_pattern),
    "quad_derivatives": ValueExercise(qd.quad_cases, qd.as_pair, qd.same_pair, qd.explain_quad,
                                      qd.draw_quad),
    "hiz_rejects": ValueExercise(hz.hiz_cases, as_bool, hz.same_verdict, hz.explain_hiz,
                                 hz.draw_hiz),
    "front_to_back": ValueExercise(fb.layer_cases, fb.as_rgba, fb.same_rgba, fb.explain_layers,
                                   fb.draw_layers),
}  # fmt: skip


def _checker(name: str) -> Callable:
    def check(fn):
        return check_value_exercise(name, fn, SPECS[name])

    check.__name__ = f"check_{name}"
    return check


#: The exercises in course order, and what checks each.
EXERCISES: dict[str, Callable] = {
    **{name: _checker(name) for name in ("span", "perspective_weights", "depth_passes",
                                         "safe_near", "robust_fill", "quad_derivatives",
                                         "hiz_rejects")},
    **bf.EXERCISES,
    "front_to_back": _checker("front_to_back"),
}  # fmt: skip
