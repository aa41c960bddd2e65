"""Independent solutions of the exercises (and typical wrong ones), for the checker's tests.

Written from the conventions only, with no call into teachraster: exact rational arithmetic
(:class:`fractions.Fraction`) for the coverage rules, plain float64 formulas elsewhere.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np


# -- correct ----------------------------------------------------------------------------------
def edge_function(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def _exact(v):
    return [Fraction(float(c)) for c in v]


def _owns(a, b):
    """Top-left for the directed edge a→b with the interior on its positive side."""
    return b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])


def covers(xy, p):
    v = [_exact(q) for q in xy]
    p = _exact(p)
    if edge_function(v[0], v[1], v[2]) < 0:
        v = [v[0], v[2], v[1]]
    if edge_function(v[0], v[1], v[2]) == 0:
        return False
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = edge_function(a, b, p)
        if e < 0 or (e == 0 and not _owns(a, b)):
            return False
    return True


def fill(xy, width, height):
    out = np.zeros((height, width), dtype=bool)
    for i in range(height):
        for j in range(width):
            out[i, j] = covers(xy, (j + 0.5, i + 0.5))
    return out


def split_point(v):
    (u1, v1), (_, v2), (u3, v3) = v
    return u1 + (u3 - u1) * (v2 - v1) / (v3 - v1)


def barycentric(xy, p):
    a, b, c = (np.asarray(q, dtype=float) for q in xy)
    p = np.asarray(p, dtype=float)
    area = edge_function(a, b, c)
    return np.array([edge_function(b, c, p), edge_function(c, a, p), edge_function(a, b, p)]) / area


def perspective(lam, w, f):
    lam, w, f = (np.asarray(x, dtype=float) for x in (lam, w, f))
    q = lam / w
    return float(q @ f / q.sum())


def depth_test(incoming, stored):
    return incoming < stored


def clip_near(v):
    v = np.asarray(v, dtype=float)
    out = []
    for i in range(3):
        a, b = v[i], v[(i + 1) % 3]
        da, db = a[2] + a[3], b[2] + b[3]
        if da >= 0:
            out.append(a)
        if (da >= 0) != (db >= 0):
            out.append(a + da / (da - db) * (b - a))
    return np.array(out).reshape(-1, 4)


CORRECT = {
    "edge_function": edge_function,
    "covers": covers,
    "fill": fill,
    "split_point": split_point,
    "barycentric": barycentric,
    "perspective": perspective,
    "depth_test": depth_test,
    "clip_near": clip_near,
}
