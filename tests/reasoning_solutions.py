"""Solutions of issue 30's exercises, as the teacher notebooks hold them (and as the capstone
uses them): imported by tests/test_reasoning_exercises.py and tests/test_capstone.py."""

import math
from fractions import Fraction

import numpy as np


def box(xy, width, height):
    """Exercise 1.2 (r487): the rows and columns whose centres a triangle with xy's bounding
    box can cover, half-open on both axes, clamped to the image."""
    xs, ys = [p[0] for p in xy], [p[1] for p in xy]

    def clamp(k, n):
        return min(max(k, 0), n)

    i0, i1 = math.ceil(min(ys) - 0.5), math.ceil(max(ys) - 0.5)
    j0, j1 = math.ceil(min(xs) - 0.5), math.ceil(max(xs) - 0.5)
    return clamp(i0, height), clamp(i1, height), clamp(j0, width), clamp(j1, width)


def span(xy, row):
    # exact in integers (1/256-px units): in float64 a crossing's product rounds past 2^18 px
    v = [(round(256 * float(x)), round(256 * float(y))) for x, y in xy]
    y = 256 * int(row) + 128
    xs = []  # crossings as (numerator, denominator > 0) in 1/256 px
    for k in range(3):
        (ax, ay), (bx, by) = v[k], v[(k + 1) % 3]
        if ay == by:
            if ay == y:
                xs += [(ax, 1), (bx, 1)]
        elif min(ay, by) <= y <= max(ay, by):
            xs.append((ax * (by - ay) + (y - ay) * (bx - ax), by - ay) if by > ay else
                      (ax * (ay - by) - (y - ay) * (bx - ax), ay - by))  # fmt: skip
    (ax, ay), (bx, by), (cx, cy) = v
    if not xs or (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) == 0:
        return 0, 0
    left = min(xs, key=lambda q: Fraction(*q))
    right = max(xs, key=lambda q: Fraction(*q))
    for k in range(3):  # a horizontal edge on this line: covered only if it is a top edge
        (ax, ay), (bx, by), (cx, cy) = v[k], v[(k + 1) % 3], v[(k + 2) % 3]
        if ay == by == y and cy < y:
            return 0, 0
    return tuple(-((128 * d - n) // (256 * d)) for n, d in (left, right))


def perspective_weights(lam, w):
    """Scaled by the smallest w that weighs (r421 T2: the smallest of all underflows every term
    where its vertex's λ is 0 and the other w are 1e610 larger)."""
    lam, w = np.asarray(lam, float), np.asarray(w, float)
    live = lam != 0
    q = np.zeros(3)
    q[live] = lam[live] * (w[live].min() / w[live])
    return q / q.sum()


def depth_passes(depths, writes):
    stored, out = math.inf, []
    for d, write in zip(depths, writes):
        passes = d < stored
        out.append(passes)
        if passes and write:
            stored = d
    return out


def safe_near(z, gap, far, bits):
    step = 1 / (2**bits - 1)
    return step * far * z**2 / (gap * far + step * z**2)


def reverse_z_gap(z, near, far):
    d = (near / z - near / far) / (1 - near / far)  # reverse-Z: 1 at near, 0 at far
    step = float(np.spacing(np.float32(d)))  # float32's step at the stored value
    return step / (near / ((1 - near / far) * z * z))  # over |dd/dz|


def reverse_z_worst(z_min, z_max, near, far):
    # Δz grows like z² within a binade of d and halves where d falls below 2^e: the coarsest
    # is z_max's or the limit just nearer than such a depth, where the step is 2^(e - 23)
    worst = reverse_z_gap(z_max, near, far)
    d = lambda z: (near / z - near / far) / (1 - near / far)  # noqa: E731
    for e in range(int(np.ceil(np.log2(d(z_max)))), int(np.floor(np.log2(d(z_min)))) + 1):
        z = near / (2.0**e * (1 - near / far) + near / far)  # d(z) = 2^e
        if z_min <= z <= z_max:  # r414 F5: z_min on a crossing counts (the binade above)
            worst = max(worst, 2.0 ** (e - 23) * (1 - near / far) * z * z / near)
    return worst


def depth_setup(z, gap, far, nearest):
    if safe_near(z, gap, far, 24) <= nearest:  # allowed: unorm24 (depth, stencil in 32 bits)
        # at the farthest allowed near plane: Δz ∝ 1/n, the finest unorm24 gives this scene
        step = 1 / (2**24 - 1)
        return "unorm24", nearest, step * (far - nearest) * z * z / (far * nearest)
    dz = reverse_z_gap(z, nearest, far)  # 5.2: hardly depends on the near plane
    return ("reverse-z" if dz <= gap else "neither"), nearest, dz


def decal_bias(z, tilt, pixel, near, far, bits, reverse, clear):
    r = 1 / (2**bits - 1)  # one step of the buffer
    # MaxDepthSlope: z_win = f/(f - n) (1 - n/z) and, on the tilted plane, 1/z = (1 - s tan θ)/z
    # with s = x/z, which moves by `pixel` per pixel
    m = far * near / (far - near) * np.tan(np.radians(tilt)) / z * pixel
    z_win = lambda zz: far / (far - near) * (1 - near / zz)  # noqa: E731
    if r + m > z_win(z) - z_win(z - clear) - m:  # the object in front, drawn first, keeps a tie
        return float("nan")
    return (r + m) if reverse else -(r + m)


def robust_fill(xy, width, height, origin=(0, 0)):
    v = np.rint(np.asarray(xy, dtype=float) * 256) / 256

    def e(a, b, x, y):
        return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])

    area = e(v[0], v[1], v[2][0], v[2][1])
    if area == 0:
        return np.zeros((height, width), dtype=bool)
    if area < 0:
        v = v[[0, 2, 1]]
    rows = origin[0] + np.arange(height)[:, None] + 0.5
    cols = origin[1] + np.arange(width)[None, :] + 0.5
    inside = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        ek = e(a, b, cols, rows)
        top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        inside &= (ek >= 0) if top_left else (ek > 0)
    return inside


def quad_derivatives(xy, w, f, row, col):
    xy, w, f = (np.asarray(a, float) for a in (xy, w, f))

    def value(x, y):
        (x1, y1), (x2, y2), (x3, y3) = xy
        area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
        lam = (
            np.array(
                [
                    (x2 - x) * (y3 - y) - (y2 - y) * (x3 - x),
                    (x3 - x) * (y1 - y) - (y3 - y) * (x1 - x),
                    (x1 - x) * (y2 - y) - (y1 - y) * (x2 - x),
                ]
            )
            / area
        )
        q = lam / w
        return float(q @ f / q.sum())

    r0, c0 = row - row % 2, col - col % 2
    ul = value(c0 + 0.5, r0 + 0.5)
    return value(c0 + 1.5, r0 + 0.5) - ul, value(c0 + 0.5, r0 + 1.5) - ul


def hiz_rejects(xyz, row0, col0, size, buffer):
    """8.2: the plane over the tile's centres inside the triangle's bounding box (r126 N8-1)."""
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = np.asarray(xyz, dtype=float)
    # the tile's pixels whose centres lie in the triangle's bounding box
    c_lo = max(col0, math.ceil(min(x1, x2, x3) - 0.5))
    c_hi = min(col0 + size - 1, math.floor(max(x1, x2, x3) - 0.5))
    r_lo = max(row0, math.ceil(min(y1, y2, y3) - 0.5))
    r_hi = min(row0 + size - 1, math.floor(max(y1, y2, y3) - 0.5))
    if c_lo > c_hi or r_lo > r_hi:
        return True  # no fragment of the triangle in this tile
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    a = ((z2 - z1) * (y3 - y1) - (z3 - z1) * (y2 - y1)) / area  # dz/dx
    b = ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1)) / area  # dz/dy
    xs = np.array([c_lo + 0.5, c_hi + 0.5])
    ys = np.array([r_lo + 0.5, r_hi + 0.5])
    corners = z1 + a * (xs[:, None] - x1) + b * (ys[None, :] - y1)
    nearest = max(corners.min(), min(z1, z2, z3))
    return bool(nearest >= np.max(buffer))


def front_to_back(layers):
    """Nearest first over the one-pass layers, stopping once opaque (nothing behind shows)."""
    colour, alpha = np.zeros(3), 0.0
    for layer in layers:
        layer = np.asarray(layer, dtype=float)
        colour += (1 - alpha) * layer[:3]
        alpha += (1 - alpha) * layer[3]
        if alpha >= 1:
            break
    return np.array([*colour, alpha])


# -- the capstone's functions: exercises 1, 3, 6, 7 and 9 as their solutions hold them ------
from exercise_solutions import barycentric, bilinear, covers, resolve, trilinear  # noqa: E402
from lines_blending_solutions import over, over_premultiplied, over_to_premultiplied  # noqa: E402, F401 (over: tests import it from here)


def a_buffer(depths, colours, background):  # the capstone's glass: farthest first, over
    result = np.asarray(background, dtype=float)
    for k in np.argsort(-np.asarray(depths), kind="stable"):
        result = np.asarray(over_premultiplied(colours[k], result))
    return result


CAPSTONE = dict(covers=covers, barycentric=barycentric, perspective_weights=perspective_weights,
                depth_passes=depth_passes, over=over_premultiplied, bilinear=bilinear, trilinear=trilinear,
                resolve=resolve, a_buffer=a_buffer)  # fmt: skip

#: A correct answer to each of issue 30's exercises, by name.
#: The broken frames: cause, pixel and evidence as the printed histories show it (r8: a stage
#: named by the cause passed; the evidence is a value of the pixel's own history).
BROKEN_FRAMES = {
    1: ("depth function", (24, 28), 0.026233),  # the depth shown (kept)
    2: ("culled winding", (24, 28), 9),  # culled here, drawn in the intended frame
    3: ("z-fighting", (13, 52), 0.598993),  # the tied fragment's depth in the intended frame
    4: ("missing premultiplication", (13, 52), (0.31, 0.28, 0.24)),  # the fragment colour
    5: ("blend order", (23, 41), (0.52, 0.67, 0.91)),  # the strip's 'after', overwritten
    6: ("sliver", (22, 40), (0.1213, 0.299992)),  # missed by, and the intended depth there
    # r18-3: frame 1's cause on the strip's pixels (at the cube's, frame 1's function passed)
    7: ("depth function", (25, 52), 0.4),  # the depth shown (the wall, mapped 1 - 0.6)
    8: ("sliver", (21, 39), (0.0566, 0.299992)),  # frame 6's cause, another thin triangle
    9: ("blend order", (13, 52), (0.655, 0.64, 0.62)),  # frame 5's cause on the pane
}


def _shown(h):
    return next(r for r in h.records if r.shown)


def _glass(h):
    return next(r for r in h.records if r.outcome == "passed" and r.color[3] < 1)


def _tied_as_meant(b, row, col):
    tie = next(r for r in b.frame.history(row, col).records if r.outcome == "hi_z")
    return next(r for r in b.intended.history(row, col).records if r.triangle == tie.triangle).depth


def _culled_but_drawn(b, row, col):
    drawn = {frozenset(map(tuple, b.intended.trace.window[r.piece, :, :2].round(6).tolist()))
             for r in b.intended.history(row, col).records if r.outcome == "passed"}  # fmt: skip
    return next(r.triangle for r in b.frame.history(row, col).records if r.outcome == "culled"
                and frozenset(map(tuple, b.frame.trace.window[r.piece, :, :2].round(6).tolist()))
                in drawn)  # fmt: skip


def _sliver(b, row, col):
    thin = next(r for r in b.frame.history(row, col).records if r.triangle == 2)
    return thin.outside, _glass(b.intended.history(row, col)).depth


#: How each frame's evidence is read off the histories of the frame pair ``b`` at (row, col)
#: (r9: the answer is a function of the frame it is given, checked on a redrawn frame too).
READ = {
    1: lambda b, row, col: _shown(b.frame.history(row, col)).depth,
    2: _culled_but_drawn,
    3: _tied_as_meant,
    4: lambda b, row, col: _glass(b.frame.history(row, col)).color[:3],
    5: lambda b, row, col: _glass(b.frame.history(row, col)).color_after[:3],
    6: _sliver,
    7: lambda b, row, col: _shown(b.frame.history(row, col)).depth,
    8: _sliver,
    9: lambda b, row, col: _glass(b.frame.history(row, col)).color_after[:3],
}


def diagnosis(number, row=None, col=None):
    """broken_frame_<number>(b): the solution's cause, at (row, col) (default: its pixel)."""
    cause, pixel, _ = BROKEN_FRAMES[number]
    row, col = pixel if row is None else (row, col)
    return lambda b: (cause, (row, col), READ[number](b, row, col))


def clipped_colours(v, colours, polygon):
    """r489: each vertex's share of v1, v2, v3 from all five equations (x, y, z, w, Σ = 1)."""
    v, p = np.asarray(v, float), np.asarray(polygon, float).reshape(-1, 4)
    a, b = np.vstack([v.T, np.ones(3)]), np.vstack([p.T, np.ones(len(p))])
    return np.linalg.lstsq(a, b, rcond=None)[0].T @ np.asarray(colours, float)


def broken_frame_3_steps(b, row=13, col=52):
    """The fewest bits of a unorm depth buffer in which frame 3's pane wins wherever the wall
    lies (r377 F4): the least n with gap · (2**n - 1) >= 1, the gap read off the trace."""
    records = b.frame.history(row, col).records
    wall = next(r for r in records if r.outcome == "passed" and r.color[3] == 1)
    pane = next(
        r for r in records if r.outcome in ("hi_z", "failed_depth", "passed") and r is not wall
    )
    z = b.frame.trace.window[:, :, 2]
    gap = z[wall.piece, 0] - z[pane.piece, 0]
    return math.ceil(math.log2(1 + 1 / gap))


def pixel_lod(xy, w, uv, size, row, col):
    """7.1: λ from the coarse quad differences of u and of v, written without the package."""
    uv = np.asarray(uv, float)
    (dudx, dudy), (dvdx, dvdy) = (quad_derivatives(xy, w, uv[:, k], row, col) for k in (0, 1))
    h, wt = size
    return math.log2(max(math.hypot(dudx * wt, dvdx * h), math.hypot(dudy * wt, dvdy * h)))


def pixel_sample(pyramid, xy, w, uv, row, col, wrap):
    """7.4: the sampler at a pixel from 7.1's pixel_lod and 7.3's trilinear (exercise_solutions')."""
    xy, w, uv = (np.asarray(a, float) for a in (xy, w, uv))
    lod = pixel_lod(xy, w, uv, np.shape(pyramid[0])[:2], row, col)
    x, y = col + 0.5, row + 0.5
    (x1, y1), (x2, y2), (x3, y3) = xy
    lam = np.array([(x2 - x) * (y3 - y) - (y2 - y) * (x3 - x),
                    (x3 - x) * (y1 - y) - (y3 - y) * (x1 - x),
                    (x1 - x) * (y2 - y) - (y1 - y) * (x2 - x)])  # fmt: skip
    mu = lam / w
    return trilinear(pyramid, mu @ uv / mu.sum(), lod, wrap)


def edge_bits(range_bits, across, sub_bits):
    """Exercise 10.1 (r394 T1): the bits E needs, term by term and sign included, in the
    absolute form (coordinates) and the relative one (differences), and the first type that
    holds them exactly."""

    def held(name):
        t = np.dtype(name)
        return np.finfo(t).nmant + 2 if t.kind == "f" else np.iinfo(t).bits

    out = []
    for factor in (range_bits + sub_bits, (across * 2**sub_bits - 1).bit_length()):
        bits = 2 * factor + 2
        types = [t for t in ("float32", "int32", "float64", "int64") if held(t) >= bits]
        out.append((bits, types[0] if types else None))
    return tuple(out)


def sample_span(xy, row, sample):
    # 2.2 (r471): the sample at (col + sx, row + sy), offsets from the pixel's top-left
    # corner; the line y = row + sy, the columns ceil(x - sx); the top-left rule unchanged
    sx, sy = (round(256 * float(s)) for s in sample)
    v = sorted(((round(256 * float(x)), round(256 * float(y))) for x, y in xy), key=lambda p: p[1])
    (x1, y1), (x2, y2), (x3, y3) = v
    y = 256 * int(row) + sy
    side = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    if side == 0 or not y1 <= y <= y3 or y2 == y3 == y:
        return 0, 0
    if y1 == y2 == y:
        ends = [(min(x1, x2), 1), (max(x1, x2), 1)]
    else:

        def crossing(a, b):
            (ax, ay), (bx, by) = a, b
            return ax * (by - ay) + (y - ay) * (bx - ax), by - ay

        x_long = crossing(v[0], v[2])
        x_short = crossing(v[0], v[1]) if y < y2 else crossing(v[1], v[2])
        ends = [x_long, x_short] if side > 0 else [x_short, x_long]
    return tuple(-((sx * den - num) // (256 * den)) for num, den in ends)


def breaking_case(repair):
    """Exercise 10.3 (r457 T1, r470): for each repair of exercise 10's naive fill, a triangle
    and a window that need it and nothing else."""
    if repair == "snap":  # v2's 1.6 steps snap to 2: edge v1→v2 crosses centre (5.5, 4.5)
        return [[2.5, 4.5 - 1 / 256], [10.5, 4.5 + 1.6 / 256], [6.0, 1.0]], 12, 8, (0, 0)
    if repair == "orient after snapping":  # v1, v2 snap onto one row; v3 changes sides
        y0 = 2.5 + 1 / 256
        return [[2, y0 + 0.0019], [3, y0 - 0.0019], [11, y0 - 0.030]], 12, 4, (0, 0)
    if repair == "tie rule":  # a right edge through three centres
        return [[4.5, 1.0], [4.5, 4.0], [1.5, 2.5]], 6, 6, (0, 0)
    # centre (1004.5, 1000.5) 17/1024 px² outside v2→v3; float32 rounds C's 10⁶-px² products
    # to 1/16 px² (r478 F1)
    return [[996.5, 1000.5], [1004.5, 1000.5 - 1 / 256], [1000.25, 1006.0]], 12, 12, (996, 996)


def defect_case(defect):
    """Exercise 3.1b (r488): a case for each defect of the shipped barycentric. cond grows as
    (distance)² / E: a 2-px triangle with E = 4 > 0 (abs(E) = E) 20 000 px out is refused;
    a clockwise one (E = -16) at the origin, p not v3, gets λ1 and λ2 negated."""
    if defect == "zero-area test":
        return [[2e4, 2e4], [2e4 + 2, 2e4], [2e4, 2e4 + 2]], (2e4 + 0.5, 2e4 + 0.5)
    return [[0.0, 0.0], [0.0, 4.0], [4.0, 0.0]], (1.0, 1.0)


def texel_weights(sizes, uv, lod, wrap):
    """7.2 (r491): the texels of a trilinear fetch, one axis at a time, in Python floats."""
    q = len(sizes) - 1
    lam = min(max(lod, 0.0), q)
    lower = math.floor(lam)
    out = {}
    for level, share in ((lower, 1 - (lam - lower)), (min(lower + 1, q), lam - lower)):
        h, w = sizes[level]

        def axis(t, n):
            x = t * n - 0.5
            i = math.floor(x)
            taps = {}
            for j, wt in ((i, 1 - (x - i)), (i + 1, x - i)):
                j = j % n if wrap == "repeat" else min(max(j, 0), n - 1)
                taps[j] = taps.get(j, 0.0) + wt
            return taps

        for r, wr in axis(uv[1], h).items():
            for c, wc in axis(uv[0], w).items():
                out[(level, r, c)] = out.get((level, r, c), 0.0) + share * wr * wc
    return out


def resolve_fragments(fragments, sample_fragment, background):
    """Exercise 6.2 (r490): every sample an equal share; a fragment weighs by its samples."""
    f = np.asarray(fragments, dtype=float).reshape(-1, 3)
    ids = np.asarray(sample_fragment)
    weights = np.array([(ids == j).sum() for j in range(len(f))]).reshape(-1)
    return (weights @ f + (ids < 0).sum() * np.asarray(background, dtype=float)) / len(ids)


def covered_counts(code, fg_code, bg_code, S):
    """Exercise 6.3 (r490): every k whose 8-bit sRGB resolve shows ``code``."""
    import teachraster as tr

    fg, bg = tr.srgb_to_linear(fg_code / 255), tr.srgb_to_linear(bg_code / 255)
    shown = [
        round(float(tr.linear_to_srgb((k * fg + (S - k) * bg) / S)) * 255) for k in range(S + 1)
    ]
    return [k for k in range(S + 1) if shown[k] == code]


CORRECT = {
    "box": box,
    "defect_case": defect_case,
    "span": span,
    "sample_span": sample_span,
    "perspective_weights": perspective_weights,
    "depth_passes": depth_passes,
    "clipped_colours": clipped_colours,
    "safe_near": safe_near,
    "reverse_z_gap": reverse_z_gap,
    "reverse_z_worst": reverse_z_worst,
    "decal_bias": decal_bias,
    "depth_setup": depth_setup,
    "resolve_fragments": resolve_fragments,
    "covered_counts": covered_counts,
    "edge_bits": edge_bits,
    "robust_fill": robust_fill,
    "breaking_case": breaking_case,
    "quad_derivatives": quad_derivatives,
    "pixel_lod": pixel_lod,
    "texel_weights": texel_weights,
    "pixel_sample": pixel_sample,
    "hiz_rejects": hiz_rejects,
    **{f"broken_frame_{n}": diagnosis(n) for n in BROKEN_FRAMES},
    "broken_frame_3_steps": broken_frame_3_steps,
    "front_to_back": front_to_back,
}
