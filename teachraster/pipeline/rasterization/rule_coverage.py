"""The fill with a caller's coverage rule: one call per pixel centre of each bounding box.

What :func:`~teachraster.pipeline.rasterization.batched_fill.rasterize_batch` decides with the
package's top-left rule on the exact fixed-point grid, a caller (a student's ``covers`` in the
course's capstone, :mod:`teachraster.pipeline.planning.overrides`) can decide with its own
``rule(xy, p)``: it is asked at every pixel centre ``p`` of every (not culled) triangle's
bounding box, zero-area triangles included (covering nothing is part of the rule), with the
triangle's *snapped* window positions ``xy`` (3, 2), in its vertex order. Everything else
about the fragments (drawing order, facing, the positions the weights are set up from) is the
package's, so every later stage treats them as its own.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from ...core.edges import setup_edges
from .batched_fill import Fragments, rasterize_batch, weight_source


def fill_by_rule(
    xy: np.ndarray, width: int, height: int, bits: int | None, culled: np.ndarray,
    rule: Callable,
) -> Fragments:  # fmt: skip
    """Fragments (drawing order: triangle, row, column) of the centres ``rule`` covers.

    ``xy`` (n, 3, 2) window positions (unsnapped), ``culled`` (n,) bool: triangles the
    rule is never asked about. The rule's answer is read with ``bool()``.

    >>> xy = np.array([[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]])
    >>> f = fill_by_rule(xy, 4, 4, 8, np.zeros(1, bool), lambda t, p: p[0] + p[1] < 2)
    >>> list(zip(f.row.tolist(), f.col.tolist()))
    [(0, 0)]
    """
    keep_none = np.ones(len(xy), dtype=bool)
    base = rasterize_batch(xy, width, height, subpixel_bits=bits, skip=keep_none,
                           snapped_weights=False)  # fmt: skip
    snapped = weight_source(np.asarray(xy, np.float64), setup_edges(xy, bits), True)[0]
    tri, rows, cols = [], [], []
    for t in np.flatnonzero(~np.asarray(culled, dtype=bool)).tolist():
        v = snapped[t]
        r0, r1 = _centres(v[:, 1], height)
        c0, c1 = _centres(v[:, 0], width)
        for r in range(r0, r1):
            for c in range(c0, c1):
                if rule(v.copy(), np.array([c + 0.5, r + 0.5])):
                    tri.append(t)
                    rows.append(r)
                    cols.append(c)
    as_index = [np.array(a, dtype=np.int64) for a in (tri, rows, cols)]
    return replace(base, tri=as_index[0], row=as_index[1], col=as_index[2])


def _centres(values: np.ndarray, size: int) -> tuple[int, int]:
    """The pixel range [first, stop) whose centres k + 0.5 lie within [min, max] of
    ``values``, clipped to [0, size)."""
    first = int(np.ceil(values.min() - 0.5))
    last = int(np.floor(values.max() - 0.5))
    return max(first, 0), min(last + 1, size)
