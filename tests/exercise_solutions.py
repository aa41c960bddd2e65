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


# -- typical mistakes (issue 10), each with words its explanation must contain -----------------
def _covers_with(rule, orient=True, dtype=float, offset=0.0):
    """A covers() built from a tie rule ``rule(e, a, b) -> bool`` for E == 0 on edge a→b."""

    def fn(xy, p):
        v = [np.asarray(q, dtype=dtype) for q in xy]
        p = np.asarray(p, dtype=dtype) - dtype(offset)
        area = edge_function(v[0], v[1], v[2])
        if area == 0:
            return False
        if area < 0 and orient:
            v = [v[0], v[2], v[1]]
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e = edge_function(a, b, p)
            if e < 0 or (e == 0 and not rule(a, b)):
                return False
        return True

    return fn


def _fill_from(covers_fn, offset=0.0):
    def fn(xy, width, height):
        out = np.zeros((height, width), dtype=bool)
        for i in range(height):
            for j in range(width):
                out[i, j] = covers_fn(xy, (j + offset, i + offset))
        return out

    return fn


both_own = _covers_with(lambda a, b: True)
none_own = _covers_with(lambda a, b: False)
one_winding = _covers_with(_owns, orient=False)
bottom_right = _covers_with(lambda a, b: not _owns(a, b))
covers_float32 = _covers_with(_owns, dtype=np.float32)
fill_at_corners = _fill_from(covers, offset=0.0)


def edge_function_float32(a, b, p):
    a, b, p = (np.asarray(x, dtype=np.float32) for x in (a, b, p))
    return float((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]))


def split_without_u1(v):
    (u1, v1), (_, v2), (u3, v3) = v
    return (v2 - v1) / (v3 - v1) * (u3 - u1)


def barycentric_absolute_float32(xy, p):
    (ax, ay), (bx, by), (cx, cy) = np.asarray(xy, dtype=np.float32)
    x, y = np.asarray(p, dtype=np.float32)
    # each weight as a plane A x + B y + C in absolute coordinates
    planes = [
        (by - cy, cx - bx, bx * cy - cx * by),
        (cy - ay, ax - cx, cx * ay - ax * cy),
        (ay - by, bx - ax, ax * by - bx * ay),
    ]
    area = planes[0][2] + planes[1][2] + planes[2][2]
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.array([(A * x + B * y + C) / area for A, B, C in planes], dtype=np.float64)


def perspective_affine(lam, w, f):
    return float(np.dot(lam, f))


def perspective_times_w(lam, w, f):
    lam, w, f = (np.asarray(x, dtype=float) for x in (lam, w, f))
    q = lam * w
    return float(q @ f / q.sum())


def depth_less_equal(incoming, stored):
    return incoming <= stored


def clip_nothing(v):
    return np.asarray(v, dtype=float)


def clip_after_divide(v):
    """Tests z/w >= -1 after the divide (wrong for w < 0) and cuts there."""
    v = np.asarray(v, dtype=float)
    out = []
    for i in range(3):
        a, b = v[i], v[(i + 1) % 3]
        with np.errstate(divide="ignore", invalid="ignore"):
            da, db = a[2] / a[3] + 1, b[2] / b[3] + 1
            if da >= 0:
                out.append(a)
            if (da >= 0) != (db >= 0):
                out.append(a + da / (da - db) * (b - a))
    return np.array(out).reshape(-1, 4)


#: (exercise, wrong function, words the explanation of its first failure must contain)
MISTAKES = {
    "both edges own a centre": ("covers", both_own, "covered twice"),
    "no edge owns a centre": ("covers", none_own, "covered by neither"),
    "one winding only": ("covers", one_winding, "handle both windings"),
    "bottom-right rule": ("covers", bottom_right, "bottom-right rule"),
    "sampling at integer coordinates": ("fill", fill_at_corners, "pixel corners"),
    "float32 edge functions": ("covers", covers_float32, "float32"),
    "float32 edge function values": ("edge_function", edge_function_float32, "float32"),
    "u4 without its offset": ("split_point", split_without_u1, "did you add u1?"),
    "absolute float32 barycentrics": ("barycentric", barycentric_absolute_float32, "cancels"),
    "affine instead of perspective": ("perspective", perspective_affine, "the affine Σλf"),
    "multiplying by w": ("perspective", perspective_times_w, "multiplied by w"),
    "<= in the depth test": ("depth_test", depth_less_equal, "use <, not <="),
    "no clipping": ("clip_near", clip_nothing, "unclipped"),
    "testing after the divide": ("clip_near", clip_after_divide, "before dividing by w"),
}


# -- other correct solutions: a different algorithm, order or form must pass as well -----------
def fill_vectorised(xy, width, height):
    """Half-planes over the whole image at once, in exact integers (1/512-px units)."""
    v = np.rint(np.asarray(xy, dtype=float) * 512).astype(np.int64)
    area = edge_function(v[0], v[1], v[2])
    if area == 0:
        return np.zeros((height, width), dtype=bool)
    if area < 0:
        v = v[[0, 2, 1]]
    y, x = np.mgrid[0:height, 0:width] * 512 + 256
    out = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        out &= (e >= 0) if _owns(a, b) else (e > 0)
    return out


def split_point_from_v3(v):
    """The same point reached from the other end of the long edge."""
    (u1, v1), (_, v2), (u3, v3) = v
    return u3 - (v3 - v2) / (v3 - v1) * (u3 - u1)


def clip_near_rotated_with_duplicates(v):
    """Starts at v2 and repeats its first vertex (allowed: consecutive duplicates are removed)."""
    poly = clip_near(np.roll(np.asarray(v, dtype=float), -1, axis=0))
    return np.vstack([poly[:1], poly])


def depth_test_numpy(incoming, stored):
    return np.less(incoming, stored)


ALTERNATIVES = {
    "fill": fill_vectorised,
    "split_point": split_point_from_v3,
    "clip_near": clip_near_rotated_with_duplicates,
    "depth_test": depth_test_numpy,
}

# lesson 12's exercises (line_pixels, over, over_premultiplied) live in their own file
from lines_blending_solutions import ALTERNATIVES as _LB_ALTERNATIVES  # noqa: E402
from lines_blending_solutions import CORRECT as _LB_CORRECT  # noqa: E402
from lines_blending_solutions import MISTAKES as _LB_MISTAKES  # noqa: E402

CORRECT.update(_LB_CORRECT)
MISTAKES.update(_LB_MISTAKES)
ALTERNATIVES.update(_LB_ALTERNATIVES)
