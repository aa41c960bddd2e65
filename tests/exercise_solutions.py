"""Independent solutions of the exercises (and typical wrong ones), for the checker's tests.

Written from the conventions only, with no call into teachraster: exact rational arithmetic
(:class:`fractions.Fraction`) for the coverage rules, plain float64 formulas elsewhere.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np


# -- correct ----------------------------------------------------------------------------------
def edge_function(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def _exact_points(points) -> list[list[int]]:
    """The points exactly, as integers over one common denominator (the signs and ties of
    edge functions are those of the rationals: a positive scale changes neither). Integers,
    not Fractions: the checker calls ``covers`` once per pixel of every case."""
    ratios = [
        (c if isinstance(c, Fraction) else float(c)).as_integer_ratio() for q in points for c in q
    ]
    den = math.lcm(*(d for _, d in ratios))
    ints = [n * (den // d) for n, d in ratios]
    return [ints[k : k + 2] for k in range(0, len(ints), 2)]


def _owns(a, b):
    """Top-left for the directed edge a→b with the interior on its positive side."""
    return b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])


#: Coordinates the float shortcut of :func:`covers` takes as they are (each exactly a float).
_FLOATS = (float, np.float64, np.float32)
_INTS = (int, np.int64, np.int32)


def _sign(a, b, p):
    """The sign of E(a, b, p) computed in floats, or None where the rounding could have made
    it (Shewchuk's bound for orient2d, (3 + 16ε)ε of |left| + |right|, here with a margin of
    over a thousand: a tie is always None)."""
    left = (b[0] - a[0]) * (p[1] - a[1])
    right = (b[1] - a[1]) * (p[0] - a[0])
    e = left - right
    if abs(e) > 1e-12 * (abs(left) + abs(right)):
        return 1 if e > 0 else -1
    return None


def _covers_by_floats(xy, p):
    """covers(xy, p) from float edge functions when no sign is in doubt (every coordinate an
    exact float below 1e15, so no product overflows and a rounded E keeps its exact sign),
    else None: the exact integers decide."""
    pts = []
    for q in (*xy, p):
        if len(q) != 2:
            return None
        for c in q:
            if not (type(c) in _FLOATS or (type(c) in _INTS and abs(c) <= 2**53)):
                return None
            if not abs(c) < 1e15:  # NaN and infinity too
                return None
        pts.append((float(q[0]), float(q[1])))
    *v, p = pts
    area = _sign(v[0], v[1], v[2])
    if area is None:
        return None
    if area < 0:
        v = [v[0], v[2], v[1]]
    for k in range(3):
        e = _sign(v[k], v[(k + 1) % 3], p)
        if e is None:
            return None
        if e < 0:
            return False
    return True


def covers(xy, p):
    fast = _covers_by_floats(xy, p)
    if fast is not None:
        return fast
    *v, p = _exact_points([*xy, p])
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
    if area == 0:  # exercise 3.1: a zero-area triangle has no weights
        raise ValueError("zero area")
    return np.array([edge_function(b, c, p), edge_function(c, a, p), edge_function(a, b, p)]) / area


def perspective(lam, w, f):
    lam, w, f = (np.asarray(x, dtype=float) for x in (lam, w, f))
    q = lam / w
    return float(q @ f / q.sum())


def depth_test(incoming, stored):
    return incoming < stored


def clip_against(v, distance=lambda p: p[2] + p[3], t=None, new=True):
    """Sutherland-Hodgman against one plane: ``distance`` (z + w: the near plane), the crossing
    parameter ``t(a, b)`` (default d_a / (d_a − d_b)); ``new=False`` adds no crossing vertex
    (the last two are a student's mistakes)."""
    v = np.asarray(v, dtype=float)
    out = []
    for i in range(3):
        a, b = v[i], v[(i + 1) % 3]
        with np.errstate(divide="ignore", invalid="ignore"):
            da, db = distance(a), distance(b)
            if da >= 0:
                out.append(a)
            if (da >= 0) != (db >= 0) and new:
                out.append(a + (da / (da - db) if t is None else t(a, b)) * (b - a))
    return np.array(out).reshape(-1, 4)


def clip_near(v):
    return clip_against(v)


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
    return clip_against(v, lambda p: p[2] / p[3] + 1)


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
def fill_vectorised(xy, width, height, centre=256, orient=True):
    """Half-planes over the whole image at once, in exact integers (1/512-px units); a
    student's mistakes: ``centre=0`` samples pixel corners, ``orient=False`` one winding."""
    v = np.rint(np.asarray(xy, dtype=float) * 512).astype(np.int64)
    area = edge_function(v[0], v[1], v[2])
    if area == 0:
        return np.zeros((height, width), dtype=bool)
    if area < 0 and not orient:
        return np.zeros((height, width), dtype=bool)
    if area < 0:
        v = v[[0, 2, 1]]
    y, x = np.mgrid[0:height, 0:width] * 512 + centre
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

# lessons 12a and 12b's exercises (line_pixels, over, over_premultiplied) live in their own file
from lines_blending_solutions import ALTERNATIVES as _LB_ALTERNATIVES  # noqa: E402
from lines_blending_solutions import CORRECT as _LB_CORRECT  # noqa: E402
from lines_blending_solutions import MISTAKES as _LB_MISTAKES  # noqa: E402

CORRECT.update(_LB_CORRECT)
MISTAKES.update(_LB_MISTAKES)
ALTERNATIVES.update(_LB_ALTERNATIVES)

# == exercises 05–08 (issue 20): independent solutions, other correct ones, typical mistakes ==
# Written from the conventions only (no call into teachraster): exact Fractions where a rule
# decides ties (rounding, coverage, block corners), plain float64 formulas elsewhere.


def depth_to_unorm(z, bits):
    return int(np.rint(z * (2**bits - 1)))


def depth_to_unorm_exact_half_up(z, bits):
    """Exact product, ties rounded up: the other neighbour at a tie must be accepted too."""
    return math.floor(Fraction(z) * (2**bits - 1) + Fraction(1, 2))


def _snap_exact(v):
    return [Fraction(round(Fraction(float(c)) * 256), 256) for c in v]  # half to even


def coverage_fraction(xy, pixel, samples):
    v = [_snap_exact(q) for q in xy]
    row, col = pixel
    # snapped vertices and sample points are dyadic, so covers' float round trip is exact
    hits = [covers(v, (col + Fraction(ox), row + Fraction(oy))) for ox, oy in samples]
    return sum(hits) / len(hits)


def coverage_fraction_integers(xy, pixel, samples):
    """Vectorised in integer 1/512-px units: all samples at once."""
    v = np.rint(np.asarray(xy, dtype=float) * 256).astype(np.int64) * 2
    area = edge_function(v[0], v[1], v[2])
    if area == 0:
        return 0.0
    if area < 0:
        v = v[[0, 2, 1]]
    p = (np.asarray(samples, dtype=float) * 512).astype(np.int64) + np.array(pixel[::-1]) * 512
    inside = np.ones(len(p), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = (b[0] - a[0]) * (p[:, 1] - a[1]) - (b[1] - a[1]) * (p[:, 0] - a[0])
        inside &= (e >= 0) if _owns(a, b) else (e > 0)
    return float(inside.mean())


def resolve(sample_colours, sample_ids, background):
    covered = np.asarray(sample_ids)[:, None] >= 0
    return np.where(covered, sample_colours, np.asarray(background, dtype=float)).mean(axis=0)


def resolve_by_counting(sample_colours, sample_ids, background):
    total, n = np.zeros(3), len(sample_ids)
    for colour, i in zip(sample_colours, sample_ids):
        total += colour if i >= 0 else np.asarray(background, dtype=float)
    return total / n


def _srgb_decode(c):  # the exact sRGB curve, written out (IEC 61966-2-1)
    c = np.asarray(c, dtype=float)
    return np.where(c <= 0.04045, c / 12.92, ((np.maximum(c, 0.04045) + 0.055) / 1.055) ** 2.4)


def resolve_srgb(sample_colours, sample_ids, background):
    """Decode to linear light, resolve there (the background too), encode the mean."""
    covered = np.asarray(sample_ids)[:, None] >= 0
    light = np.where(covered, _srgb_decode(np.nan_to_num(sample_colours)), _srgb_decode(background))
    mean = light.mean(axis=0)
    return np.where(mean <= 0.0031308, mean * 12.92, 1.055 * mean ** (1 / 2.4) - 0.055)


def resolve_srgb_with_tools(sample_colours, sample_ids, background):
    """The same with the package's curves and exercise 6.2's own resolve."""
    import teachraster as tr

    light = np.where(np.isnan(sample_colours), 0.0, np.nan_to_num(sample_colours))
    return tr.linear_to_srgb(resolve(tr.srgb_to_linear(light), sample_ids,
                                     tr.srgb_to_linear(background)))  # fmt: skip


def mip_level(ddx, ddy, size):
    h, w = size
    rx = math.hypot(ddx[0] * w, ddx[1] * h)
    ry = math.hypot(ddy[0] * w, ddy[1] * h)
    return math.log2(max(rx, ry))


def mip_level_squares(ddx, ddy, size):
    h, w = size
    sx = (ddx[0] * w) ** 2 + (ddx[1] * h) ** 2
    sy = (ddy[0] * w) ** 2 + (ddy[1] * h) ** 2
    return 0.5 * np.log2(max(sx, sy))


def _wrap(i, n, wrap):
    return i % n if wrap == "repeat" else min(max(i, 0), n - 1)


def bilinear(texture, uv, wrap):
    tex = np.asarray(texture, dtype=float)
    h, w = tex.shape[:2]
    x, y = uv[0] * w - 0.5, uv[1] * h - 0.5
    i, j = math.floor(y), math.floor(x)
    fy, fx = y - i, x - j
    out = 0.0
    for di, wy in ((0, 1 - fy), (1, fy)):
        for dj, wx in ((0, 1 - fx), (1, fx)):
            out = out + wy * wx * tex[_wrap(i + di, h, wrap), _wrap(j + dj, w, wrap)]
    return out


def bilinear_lerp(texture, uv, wrap):
    """Two lerps along x, one along y, indices wrapped with numpy."""
    tex = np.asarray(texture, dtype=float)
    h, w = tex.shape[:2]
    x, y = uv[0] * w - 0.5, uv[1] * h - 0.5
    x0, y0 = np.floor(x), np.floor(y)
    cols = np.array([x0, x0 + 1], dtype=int)
    rows = np.array([y0, y0 + 1], dtype=int)
    if wrap == "repeat":
        cols, rows = cols % w, rows % h
    else:
        cols, rows = np.clip(cols, 0, w - 1), np.clip(rows, 0, h - 1)
    quad = tex[np.ix_(rows, cols)]
    top = quad[0, 0] + (x - x0) * (quad[0, 1] - quad[0, 0])
    bottom = quad[1, 0] + (x - x0) * (quad[1, 1] - quad[1, 0])
    return top + (y - y0) * (bottom - top)


def trilinear(pyramid, uv, lod, wrap="repeat"):
    q = len(pyramid) - 1
    lam = min(max(lod, 0.0), q)
    d = math.floor(lam)
    t = lam - d
    a = bilinear(pyramid[d], uv, wrap)
    b = bilinear(pyramid[min(d + 1, q)], uv, wrap)
    return (1 - t) * a + t * b


def trilinear_ceil(pyramid, uv, lod, wrap="repeat"):
    """Levels ⌊λ⌋ and ⌈λ⌉ (equal at integers): the same answer."""
    lam = float(np.clip(lod, 0, len(pyramid) - 1))
    lo, hi = math.floor(lam), math.ceil(lam)
    a, b = bilinear_lerp(pyramid[lo], uv, wrap), bilinear_lerp(pyramid[hi], uv, wrap)
    return a + (lam - lo) * (b - a)


def _classify(xy, x0, y0, size, corner_trick=True, points=None, owns=None):
    """The corner trick, or (``corner_trick=False``) every one of ``points`` (default: the four
    extreme centres) tested; ``owns(a, b)`` decides a point on an edge (default: top-left)."""
    owns = owns or _owns
    v = [[Fraction(float(c)) for c in p] for p in xy]
    area = edge_function(v[0], v[1], v[2])
    if area == 0:
        return "rejected"
    if area < 0:
        v = [v[0], v[2], v[1]]
    xs = (x0 + Fraction(1, 2), x0 + size - Fraction(1, 2))
    ys = (y0 + Fraction(1, 2), y0 + size - Fraction(1, 2))
    accepted = True
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]

        def ok(p, a=a, b=b):
            e = edge_function(a, b, p)
            return e > 0 or (e == 0 and owns(a, b))

        if corner_trick:  # E grows with y when b.x > a.x, with x when b.y < a.y
            hi = (xs[1] if b[1] < a[1] else xs[0], ys[1] if b[0] > a[0] else ys[0])
            lo = (xs[0] if b[1] < a[1] else xs[1], ys[0] if b[0] > a[0] else ys[1])
            best, worst = ok(hi), ok(lo)
        else:
            passes = [ok(p) for p in (points or [(x, y) for x in xs for y in ys])]
            best, worst = any(passes), all(passes)
        if not best:
            return "rejected"
        accepted = accepted and worst
    return "accepted" if accepted else "partial"


def per_block(fn):
    """A one-block classifier ``fn(xy, x0, y0, size)`` looped over a grid of blocks (``x0``,
    ``y0`` integer arrays of one shape): classify_block's loop solution, an array of texts."""

    def grid(xy, x0, y0, size):
        x0, y0 = np.broadcast_arrays(np.asarray(x0), np.asarray(y0))
        out = np.empty(x0.shape, dtype=object)
        for idx in np.ndindex(x0.shape):
            out[idx] = fn(xy, int(x0[idx]), int(y0[idx]), size)
        return out

    grid.__name__ = grid.__qualname__ = f"per_block_{fn.__name__}"
    return grid


def classify_block_offsets(xy, x0, y0, size, dtype=float):
    """The set-up's way (the task's): per edge A, B and the reject and accept offsets, once;
    one evaluation of E per block at its first pixel centre, for the whole grid with numpy."""
    v = np.asarray(xy, dtype=float).astype(dtype)
    px = np.asarray(x0).astype(dtype) + dtype(0.5)
    py = np.asarray(y0).astype(dtype) + dtype(0.5)
    area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
    if area == 0:
        return np.full(px.shape, "rejected")
    if area < 0:
        v = v[[0, 2, 1]]
    rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        A, B = a[1] - b[1], b[0] - a[0]  # E = A·(x − a.x) + B·(y − a.y)
        reject = dtype(size - 1) * (max(A, 0) + max(B, 0))  # to E's largest value
        accept = dtype(size - 1) * (min(A, 0) + min(B, 0))  # to E's smallest value
        e0 = A * (px - a[0]) + B * (py - a[1])
        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        rejected |= (e0 + reject < 0) if top_left else (e0 + reject <= 0)
        accepted &= (e0 + accept >= 0) if top_left else (e0 + accept > 0)
    return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))


def classify_block_units(xy, x0, y0, size):
    """The same counted in integer units of 1/256 px (lesson 10 §4's count), int64: exact at
    every size. r248 F1: float64 pixels (:func:`classify_block_offsets`) round E₀ once its
    products pass 2^37 px², and the check's far float64 ties fail them."""
    v = np.rint(np.asarray(xy, dtype=float) * 256).astype(np.int64)
    px, py = np.asarray(x0) * 256 + 128, np.asarray(y0) * 256 + 128
    area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[1, 1] - v[0, 1]) * (v[2, 0] - v[0, 0])
    if area == 0:
        return np.full(px.shape, "rejected")
    if area < 0:
        v = v[[0, 2, 1]]
    rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        A, B = a[1] - b[1], b[0] - a[0]
        reject = 256 * (size - 1) * (max(A, 0) + max(B, 0))
        accept = 256 * (size - 1) * (min(A, 0) + min(B, 0))
        e0 = A * (px - a[0]) + B * (py - a[1])
        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        rejected |= (e0 + reject < 0) if top_left else (e0 + reject <= 0)
        accepted &= (e0 + accept >= 0) if top_left else (e0 + accept > 0)
    return np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))


def classify_block_float32(xy, x0, y0, size):
    """The same in float32: exact where the products fit 24 bits (small coordinates)."""
    return classify_block_offsets(xy, x0, y0, size, dtype=np.float32)


def _one_block(xy, x0, y0, size):
    return _classify(xy, x0, y0, size)


def _one_block_four_corners(xy, x0, y0, size):
    return _classify(xy, x0, y0, size, corner_trick=False)


#: The loop solutions: exact Fractions, one block at a time (the corner trick, or all four
#: extreme centres).
classify_block_loops = per_block(_one_block)
classify_block_four_corners = per_block(_one_block_four_corners)
classify_block = classify_block_units


CORRECT.update(
    depth_to_unorm=depth_to_unorm,
    coverage_fraction=coverage_fraction,
    resolve=resolve,
    resolve_srgb=resolve_srgb,
    mip_level=mip_level,
    bilinear=bilinear,
    trilinear=trilinear,
    classify_block=classify_block,
)
ALTERNATIVES.update(
    depth_to_unorm=depth_to_unorm_exact_half_up,
    coverage_fraction=coverage_fraction_integers,
    resolve=resolve_by_counting,
    resolve_srgb=resolve_srgb_with_tools,
    mip_level=mip_level_squares,
    bilinear=bilinear_lerp,
    trilinear=trilinear_ceil,
    classify_block=classify_block_four_corners,
)


# -- typical mistakes of 05–08 ------------------------------------------------------------------
def _coverage_with(snap=True, tie=_owns, orient=True, shift=(0.0, 0.0), centre_only=False):
    def fn(xy, pixel, samples):
        v = [_snap_exact(q) if snap else [Fraction(float(c)) for c in q] for q in xy]
        area = edge_function(v[0], v[1], v[2])
        if area == 0:
            return 0.0
        if area < 0 and orient:
            v = [v[0], v[2], v[1]]
        row, col = pixel
        pts = [(Fraction(1, 2), Fraction(1, 2))] if centre_only else samples
        hits = 0
        for ox, oy in pts:
            p = (col + Fraction(ox) + Fraction(shift[0]), row + Fraction(oy) + Fraction(shift[1]))
            ok = True
            for k in range(3):
                a, b = v[k], v[(k + 1) % 3]
                e = edge_function(a, b, p)
                ok &= e > 0 or (e == 0 and tie(a, b))
            hits += ok
        return hits / len(pts)

    return fn


def _level_with(rho, log=math.log2):
    def fn(ddx, ddy, size):
        h, w = size
        ax = (ddx[0] * w, ddx[1] * h)
        ay = (ddy[0] * w, ddy[1] * h)
        return log(rho(ax, ay))

    return fn


def _bilinear_with(
    centre=0.5, floor=math.floor, wrap_as=None, swap=False, clamp_x=False, transpose=False
):
    """A bilinear filter with a student's mistakes: ``clamp_x`` clamps x and y to the texel
    centres first, ``transpose`` swaps the texture's rows and columns."""

    def fn(texture, uv, wrap):
        wrap = wrap_as or wrap
        tex = np.asarray(texture, dtype=float)
        tex = np.swapaxes(tex, 0, 1) if transpose else tex
        h, w = tex.shape[:2]
        x, y = uv[0] * w - centre, uv[1] * h - centre
        if clamp_x:
            x, y = min(max(x, 0), w - 1), min(max(y, 0), h - 1)
        i, j = floor(y), floor(x)
        fy, fx = y - i, x - j
        if swap:
            fx, fy = 1 - fx, 1 - fy
        out = 0.0
        for di, wy in ((0, 1 - fy), (1, fy)):
            for dj, wx in ((0, 1 - fx), (1, fx)):
                out = out + wy * wx * tex[_wrap(int(i) + di, h, wrap), _wrap(int(j) + dj, w, wrap)]
        return out

    return fn


def bilinear_nearest(texture, uv, wrap):
    tex = np.asarray(texture, dtype=float)
    h, w = tex.shape[:2]
    return tex[_wrap(math.floor(uv[1] * h), h, wrap), _wrap(math.floor(uv[0] * w), w, wrap)]


def trilinear_nearest_level(pyramid, uv, lod, wrap="repeat"):
    d = min(max(round(lod), 0), len(pyramid) - 1)
    return bilinear(pyramid[d], uv, wrap)


def trilinear_swapped(pyramid, uv, lod, wrap="repeat"):
    q = len(pyramid) - 1
    lam = min(max(lod, 0.0), q)
    d = math.floor(lam)
    t = lam - d
    return t * bilinear(pyramid[d], uv, wrap) + (1 - t) * bilinear(pyramid[min(d + 1, q)], uv, wrap)


def trilinear_unclamped(pyramid, uv, lod, wrap="repeat"):
    q = len(pyramid) - 1
    d = min(math.floor(lod), q)
    t = lod - d
    return (1 - t) * bilinear(pyramid[d], uv, wrap) + t * bilinear(pyramid[min(d + 1, q)], uv, wrap)


def classify_wrong_accept_corner(xy, x0, y0, size):
    """Accepts when each edge's maximising corner passes (the minimising one is the test)."""
    kind = _one_block(xy, x0, y0, size)
    return "accepted" if kind == "partial" else kind


def classify_corners_outside(xy, x0, y0, size):
    """Rejects when all four corners lie outside the triangle (not one edge's verdict)."""
    v = [[Fraction(float(c)) for c in p] for p in xy]
    if edge_function(v[0], v[1], v[2]) == 0:
        return "rejected"
    xs = (x0 + Fraction(1, 2), x0 + size - Fraction(1, 2))
    ys = (y0 + Fraction(1, 2), y0 + size - Fraction(1, 2))
    inside = [covers(xy, (x, y)) for x in xs for y in ys]
    if all(inside):
        return "accepted"
    if not any(inside):
        return "rejected"
    return "partial"


def classify_outer_corners(xy, x0, y0, size):
    """Tests the block's outer corners x0, x0 + size (pixel corners, not centres)."""
    return _classify(xy, Fraction(x0) - Fraction(1, 2), Fraction(y0) - Fraction(1, 2), size + 1)


def classify_loose(xy, x0, y0, size):
    """E >= 0 on every edge, no zero-area test: ties and degenerate triangles go wrong."""
    v = [[float(c) for c in p] for p in xy]
    if edge_function(v[0], v[1], v[2]) < 0:
        v = [v[0], v[2], v[1]]
    xs, ys = (x0 + 0.5, x0 + size - 0.5), (y0 + 0.5, y0 + size - 0.5)
    verdicts = []
    for k in range(3):
        e = [edge_function(v[k], v[(k + 1) % 3], (x, y)) >= 0 for x in xs for y in ys]
        verdicts.append((any(e), all(e)))
    if not all(best for best, _ in verdicts):
        return "rejected"
    return "accepted" if all(worst for _, worst in verdicts) else "partial"


MISTAKES.update(
    {
        "depth by truncation": ("depth_to_unorm", lambda z, b: int(z * (2**b - 1)), "truncates"),
        "depth scaled by 2^bits": (
            "depth_to_unorm",
            lambda z, b: round(z * 2**b),
            "must hold z = 1",
        ),  # fmt: skip
        "depth read back": (
            "depth_to_unorm",
            lambda z, b: round(z * (2**b - 1)) / (2**b - 1),
            "the depth read back",
        ),  # fmt: skip
        "coverage without snapping": ("coverage_fraction", _coverage_with(snap=False), "snap them"),
        "coverage, both edges own a sample": (
            "coverage_fraction",
            _coverage_with(tie=lambda a, b: True),
            "lies exactly on edge",
        ),  # fmt: skip
        "coverage, one winding": (
            "coverage_fraction",
            _coverage_with(orient=False),
            "both windings",
        ),  # fmt: skip
        "coverage at the centre only": (
            "coverage_fraction",
            _coverage_with(centre_only=True),
            "pixel centre only",
        ),  # fmt: skip
        "coverage, offsets from the centre": (
            "coverage_fraction",
            _coverage_with(shift=(0.5, 0.5)),
            "not its centre",
        ),  # fmt: skip
        "resolve of covered samples only": (
            "resolve",
            lambda c, i, b: (
                np.asarray(c)[np.asarray(i) >= 0].mean(axis=0) if (np.asarray(i) >= 0).any() else b
            ),
            "covered sample",
        ),  # fmt: skip
        "resolve with black for uncovered": (
            "resolve",
            lambda c, i, b: np.where(np.asarray(i)[:, None] >= 0, c, 0.0).mean(axis=0),
            "not as black",
        ),  # fmt: skip
        "resolve of every sample's colour": (
            "resolve",
            lambda c, i, b: np.mean(c, axis=0),
            "hold NaN",
        ),  # fmt: skip
        "resolve of the encoded numbers": ("resolve_srgb", resolve, "sRGB-encoded numbers"),
        "resolve in light, not encoded": (
            "resolve_srgb",
            lambda c, i, b: _srgb_decode(
                np.where(np.asarray(i)[:, None] >= 0, np.nan_to_num(c), b)
            ).mean(axis=0),
            "not encoded again",
        ),  # fmt: skip
        "λ from the sum of the axes": (
            "mip_level",
            _level_with(lambda a, b: math.hypot(*a) + math.hypot(*b)),
            "sum of the derivatives",
        ),  # fmt: skip
        "λ from the shorter axis": (
            "mip_level",
            _level_with(lambda a, b: min(math.hypot(*a), math.hypot(*b))),
            "shorter of the two footprint axes",
        ),  # fmt: skip
        "λ without log2": (
            "mip_level",
            _level_with(lambda a, b: max(math.hypot(*a), math.hypot(*b)), log=lambda r: r),
            "λ = log2 ρ",
        ),  # fmt: skip
        "λ from the largest component": (
            "mip_level",
            _level_with(lambda a, b: max(map(abs, (*a, *b)))),
            "largest component",
        ),  # fmt: skip
        "λ in texture units": (
            "mip_level",
            lambda dx, dy, size: math.log2(max(math.hypot(*dx), math.hypot(*dy))),
            "in texels",
        ),  # fmt: skip
        "λ clamped at 0": (
            "mip_level",
            lambda dx, dy, size: max(mip_level(dx, dy, size), 0.0),
            "unclamped",
        ),  # fmt: skip
        "bilinear at texel corners": ("bilinear", _bilinear_with(centre=0.0), "texel corners"),
        "bilinear with int()": ("bilinear", _bilinear_with(floor=int), "int() truncates"),
        "bilinear ignoring repeat": (
            "bilinear",
            _bilinear_with(wrap_as="clamp"),
            "tiles the texture",
        ),  # fmt: skip
        "bilinear with swapped weights": (
            "bilinear",
            _bilinear_with(swap=True),
            "the weight of the right",
        ),  # fmt: skip
        "nearest instead of bilinear": ("bilinear", bilinear_nearest, "nearest texel"),
        "trilinear from the nearest level": ("trilinear", trilinear_nearest_level, "(the nearest)"),
        "trilinear with swapped weights": ("trilinear", trilinear_swapped, "the weight of level"),
        "trilinear without clamping λ": ("trilinear", trilinear_unclamped, "clamp it to [0, q]"),
        "accept by the maximising corner": (
            "classify_block",
            per_block(classify_wrong_accept_corner),
            "you tested the maximising one",
        ),  # fmt: skip
        "reject when the corners lie outside": (
            "classify_block",
            per_block(classify_corners_outside),
            "the test is per edge",
        ),  # fmt: skip
        "block corners for pixel centres": (
            "classify_block",
            per_block(classify_outer_corners),
            "outer corners",
        ),  # fmt: skip
        # two slips (E >= 0 and no zero-area test): since r107 N8-2 classify_block names a
        # mistake only where one gives every failing answer, so the tie is told by the rule,
        # at the corner where E = 0
        "E >= 0 on every edge": (
            "classify_block",
            per_block(classify_loose),
            "(E = 0), fails",
        ),  # fmt: skip
    }
)
