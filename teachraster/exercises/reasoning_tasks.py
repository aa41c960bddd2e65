"""The exercises that replace the course's one-line tasks, and those of lessons 07, 09-12
(issue 30), as the registry runs them.

Each is an :class:`~.exercise.Exercise` (its cases, its answer's reading, its table of
typical mistakes), defined in its own module:

- ``box`` (lesson 02, :mod:`.centre_box`): the box of centres, in place of ``fill``;
- ``defect_case`` (lesson 03, :mod:`.bary_repair`): a case for each defect of a shipped
  ``barycentric``;
- ``span`` (lesson 01, :mod:`.spans`), ``sample_span`` (01 with 08, :mod:`.sample_spans`), ``perspective_weights`` (04,
  :mod:`.perspective_weighting`), ``depth_passes`` (05a, :mod:`.zbuffer_pixel`),
  ``clipped_colours`` (05a, :mod:`.clip_colour`), ``safe_near`` (05b, :mod:`.near_plane`):
  reasoning in place of ``split_point``,
  ``perspective``, ``depth_test`` and ``depth_to_unorm`` (still checked, for notebooks of
  earlier versions); ``reverse_z_gap`` (05b, :mod:`.reverse_z`): float32 reverse-Z;
  ``reverse_z_worst`` (05b, :mod:`.reverse_z_worst`): its coarsest depth over a range;
  ``decal_bias`` (05b, :mod:`.decal_bias`): the depth offset a tilted decal needs;
  ``depth_setup`` (05b, :mod:`.depth_setup`): unorm24 or float32 reverse-Z for a scene, and
  its near plane, from the student's own ``safe_near`` and ``reverse_z_gap``;
- ``resolve_fragments`` (08, :mod:`.resolve_fragments`): the resolve of compressed
  samples, and ``covered_counts`` (08 with 12b, :mod:`.resolve_codes`): the 8-bit sRGB
  resolve inverted, in place of ``resolve`` and ``resolve_srgb`` (still checked: the
  capstone's 12.9, and notebooks of earlier versions);
- ``edge_bits`` (07 with 06, :mod:`.edge_bits`): the bits E needs in either form, and the
  type that holds them; ``robust_fill`` (07, :mod:`.hard_case_fill`): the naive rasteriser
  against the catalogue; ``breaking_case`` (07, :mod:`.breaking_case`): a case for each
  repair of that rasteriser;
- ``quad_derivatives`` (09, :mod:`.quad_difference`; still checked, for notebooks of earlier
  versions), ``pixel_lod`` (09, :mod:`.pixel_level`: the quad differences, ρ and λ composed, in
  place of ``mip_level`` and ``quad_derivatives``), ``texel_weights`` (09,
  :mod:`.texel_footprint`: the texels and weights of a trilinear fetch, in place of ``bilinear``
  and ``trilinear``, still checked), ``pixel_sample`` (09, :mod:`.pixel_sampler`:
  the whole sampler at a pixel, from the student's own ``pixel_lod`` and ``trilinear``),
  ``hiz_rejects`` (10, :mod:`.hiz_tile`),
  ``front_to_back`` (12, :mod:`.front_to_back`);
- ``broken_frame_1`` … ``broken_frame_9`` (11, :mod:`.broken_frames`), and
  ``broken_frame_3_steps`` (11 with 05b, :mod:`.broken_frame_steps`): the depth bits frame 3 needs.
"""

from __future__ import annotations

from collections.abc import Callable

from . import bary_repair as br
from . import breaking_case as bc
from . import broken_frame_steps as bfs
from . import broken_frames as bf
from . import centre_box as cb
from . import clip_colour as cc
from . import decal_bias as db
from . import depth_setup as ds
from . import edge_bits as eb
from . import front_to_back as fb
from . import hard_case_fill as hf
from . import hiz_tile as hz
from . import near_plane as npl
from . import perspective_weighting as pw
from . import pixel_level as pl
from . import pixel_sampler as ps
from . import quad_difference as qd
from . import resolve_codes as rc
from . import resolve_fragments as rf
from . import reverse_z as rz
from . import reverse_z_worst as rzw
from . import sample_spans as ss
from . import spans
from . import texel_footprint as tfp
from . import zbuffer_pixel as zb
from .exercise import Exercise

#: The exercises in course order, and how to build each (for :func:`.checks._registry`).
EXERCISES: dict[str, Callable[[], Exercise]] = {
    "box": lambda: cb.BOX,  # 1.2: the centres a bounding box can hold (r453 T1)
    "span": lambda: spans.SPAN,
    "sample_span": lambda: ss.SAMPLE_SPAN,  # 2.2: the span at a sample (r454 T1)
    "defect_case": lambda: br.DEFECT_CASE,  # 3.1b: a case for each defect (r488)
    "perspective_weights": lambda: pw.PERSPECTIVE_WEIGHTS,
    "depth_passes": lambda: zb.DEPTH_PASSES,
    "clipped_colours": lambda: cc.CLIPPED_COLOURS,  # 4.3 (r489: was clip_near_colour)
    "safe_near": lambda: npl.SAFE_NEAR,
    "reverse_z_gap": lambda: rz.REVERSE_Z_GAP,
    "reverse_z_worst": lambda: rzw.REVERSE_Z_WORST,
    "decal_bias": lambda: db.DECAL_BIAS,
    "depth_setup": lambda: ds.DEPTH_SETUP,
    "resolve_fragments": lambda: rf.RESOLVE_FRAGMENTS,  # 6.2: compressed samples (r482 T1)
    "covered_counts": lambda: rc.COVERED_COUNTS,  # 6.3: the 8-bit sRGB resolve inverted (r482 T1)
    "edge_bits": lambda: eb.EDGE_BITS,
    "robust_fill": lambda: hf.ROBUST_FILL,
    "breaking_case": lambda: bc.BREAKING_CASE,
    "quad_derivatives": lambda: qd.QUAD_DERIVATIVES,
    "pixel_lod": lambda: pl.PIXEL_LOD,
    "texel_weights": lambda: tfp.TEXEL_WEIGHTS,  # 7.2: in place of bilinear, trilinear (r491)
    "pixel_sample": lambda: ps.PIXEL_SAMPLE,
    "hiz_rejects": lambda: hz.HIZ_REJECTS,
    **bf.EXERCISES,
    "broken_frame_3_steps": lambda: bfs.BROKEN_FRAME_3_STEPS,
    "front_to_back": lambda: fb.FRONT_TO_BACK,
}
