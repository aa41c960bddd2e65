"""A catalogue of named hard cases: inputs that break naive rasterisers, and what must happen.

Each :class:`HardCase` holds its inputs, a one-line ``why``, what a correct rasteriser must do
(``expect`` in words, :meth:`HardCase.check` as code), a :meth:`HardCase.run` that executes it
with the core (:func:`teachraster.rasterize` for screen-space triangles,
:func:`teachraster.pipeline.render_triangles.render` for clip-space ones) and, where it is instructive, a
:meth:`HardCase.naive` version: what a straightforward implementation computes instead, written
out below in a few lines of numpy so that lesson 07 can show "naive vs ours" side by side.

>>> case = get_case("d3d_split_square")
>>> case.why
'a square with corners on pixel centres split along its \\\\ diagonal ...'
>>> result = case.run(method="span")
>>> case.check(result)                 # raises AssertionError if the rasteriser is wrong
>>> int(result.counts.max()), int(case.naive().counts.max())   # ours once, naive twice
(1, 2)

The catalogue is a package: :mod:`.case` (the case, its results, the registry),
:mod:`.naive` (the naive variants), :mod:`.checks` (shared runners and checks) and one module
per family of cases (:mod:`.coverage_cases`, :mod:`.precision_cases`, :mod:`.clip_space_cases`).
Line cases (:mod:`.line_cases`) have their own registry, :data:`LINE_CASES`.

Results
-------
- screen-space cases (``kind`` "triangle", "triangles", "mesh") return a :class:`Fills`: one
  :class:`~teachraster.core.fill.Fill` per triangle and their summed coverage ``counts``;
- clip-space cases ("clip") return a :class:`Rendered`: the frame and the union coverage of
  the clipped window triangles filled again with the chosen method;
- precision and depth cases return a small dataclass of measured numbers.
"""

# Importing the case modules registers their cases, in catalogue order.
# isort: off
from . import coverage_cases  # noqa: F401
from . import precision_cases  # noqa: F401
from . import clip_space_cases  # noqa: F401

# isort: on
from .case import (
    CASES,
    DEPTH_ORDER,
    FILL_METHODS,
    Fills,
    HardCase,
    Naive,
    Rendered,
    get_case,
    list_cases,
)
from .clip_space_cases import DepthResult, coplanar_clip, perspective_errors
from .line_cases import LINE_CASES, LineCase, LineResult, get_line_case, list_line_cases
from .naive import (
    NAIVE_RULES,
    naive_affine,
    naive_counts,
    naive_coverage,
    naive_perspective32,
    naive_rule_masks,
    naive_stepped32,
    naive_window,
)
from .precision_cases import DriftResult, FarResult, drift_along_row, fill_window

__all__ = [
    "CASES",
    "DEPTH_ORDER",
    "FILL_METHODS",
    "DepthResult",
    "DriftResult",
    "FarResult",
    "LINE_CASES",
    "LineCase",
    "LineResult",
    "NAIVE_RULES",
    "Fills",
    "HardCase",
    "Naive",
    "Rendered",
    "coplanar_clip",
    "drift_along_row",
    "fill_window",
    "get_case",
    "get_line_case",
    "list_cases",
    "list_line_cases",
    "naive_affine",
    "naive_counts",
    "naive_coverage",
    "naive_perspective32",
    "naive_rule_masks",
    "naive_stepped32",
    "naive_window",
    "perspective_errors",
]
