"""The ``barycentric`` exercise 3 ships with two defects (the notebook's locked cell; r488).

Its own module, outside the checker's (r495 W2): the check of ``defect_case`` watches every
function of :mod:`.bary_repair`, and the student may call this one (the notebook's copy of it)
to try candidates; :mod:`.bary_repair` repairs it knob by knob (``patched_barycentric``).
"""

from __future__ import annotations

import numpy as np


def shipped_barycentric(xy, p):
    """Screen-space barycentric weights of point p in triangle xy (as shipped: two defects)."""
    v = np.asarray(xy, dtype=float)
    p = np.asarray(p, dtype=float)
    m = np.vstack([v.T, np.ones(3)])  # columns (x_i, y_i, 1): m @ weights = (px, py, 1)
    if np.linalg.cond(m) > 1e8:
        raise ValueError("the triangle has zero area: it has no barycentric weights")

    def e(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    area = abs(e(v[0], v[1], v[2]))
    l1 = e(v[1], v[2], p) / area
    l2 = e(v[2], v[0], p) / area
    return np.array([l1, l2, 1.0 - l1 - l2])
