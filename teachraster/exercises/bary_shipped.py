"""The ``barycentric`` exercise 3 ships with two defects (the notebook's locked cell; r488).

Its own module, outside the checker's (r495 W2): the check of ``defect_case`` watches every
function of :mod:`.bary_repair`, and the student may call this one (the notebook's copy of it)
to try candidates. :func:`patched_barycentric` repairs it knob by knob: exercise 3.1b's check
(:mod:`.bary_repair`) judges the student's cases with it, and 3.1's (:mod:`.interpolation`) tells
the shipped defects it reproduces by their symptoms (r506 T1).
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


#: The defects, in the task's words.
DEFECTS = ("zero-area test", "area")
#: The shipped zero-area test: refuse when the condition number exceeds this.
COND_LIMIT = 1e8


def patched_barycentric(xy, p, repaired=()):
    """:func:`shipped_barycentric` with the defects named in ``repaired`` repaired (an exact
    ``E == 0`` test; E signed).

    >>> xy = [[0, 0], [0, 4], [4, 0]]  # E = -16
    >>> patched_barycentric(xy, (1, 1), ("zero-area test",)).tolist()
    [-0.5, -0.25, 1.75]
    >>> patched_barycentric(xy, (1, 1), DEFECTS).tolist()
    [0.5, 0.25, 0.25]
    """
    v, p = np.asarray(xy, dtype=float), np.asarray(p, dtype=float)

    def e(a, b, c):
        return float((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))

    area = e(v[0], v[1], v[2])
    if "zero-area test" in repaired:
        if area == 0:
            raise ValueError("zero area")
    elif np.linalg.cond(np.vstack([v.T, np.ones(3)])) > COND_LIMIT:
        raise ValueError("zero area")
    if "area" not in repaired:
        area = abs(area)
    l1, l2 = e(v[1], v[2], p) / area, e(v[2], v[0], p) / area
    return np.array([l1, l2, 1.0 - l1 - l2])
