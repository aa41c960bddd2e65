"""Exercise ``robust_fill`` (lesson 07), r386: E's precision in the task's stated range, and
the mistakes that two causes fit alike.

The task promises exactness for vertices within 2²⁰ px of the origin and triangles up to
1,024 px across. On the 1/256-px grid E is a whole number of steps of 2⁻¹⁶ px²; a 1,000-px
triangle's E reaches about 2³⁶ such steps, more than float32's 24 bits hold, so E computed
or stepped in float32 changes a verdict near a long edge, far from the origin or not (r386
NW28: stepped along a row; NW29: float32 after shifting to the window). Here: the cases that
show it, a fill that steps E in float32, the test whether an answer is wrong only within
float32's rounding of E, and words that name it with the E that rounds.
"""

from __future__ import annotations

import numpy as np

from ..core.snapping import snap
from ..study.hardcases import naive_coverage

#: r386 NW28, NW29: triangles 784 and 823 px across (on the 1/256 grid, within the stated
#: range) and a 64-px window (row, col) where E in float32 changes a verdict: stepped from
#: the first centre (pixel [49, 36]: E = 48 · 2⁻¹⁶ px² on edge v1→v2, outside; the reader's own
#: example was 1,599 px tall, past the range), or from differences after shifting to the
#: window (pixel [23, 42]: E = 33 · 2⁻¹⁶ px² on edge v1→v2, outside).
FLOAT32_CASES = {
    "a triangle 784 px across, a centre 48 · 2⁻¹⁶ px² outside an edge": (
        np.array([[5249.953125, 3936.2578125], [5427.234375, 4720.1953125],
                  [5648.6796875, 4630.828125]]), (4296, 5306)),
    "a triangle 823 px across, a centre 33 · 2⁻¹⁶ px² outside an edge": (
        np.array([[4330.41015625, 2441.29296875], [3507.359375, 3200.30078125],
                  [4015.984375, 3032.265625]]), (2995, 3662)),
}  # fmt: skip

#: E's step on the snapped grid (px²): (1/256)².
STEP = 2.0**-16


#: The types exercise 10.1 (:mod:`.edge_bits`) names, in order of the bits each holds exactly.
TYPES = ("float32", "int32", "float64", "int64")


def exact_bits(name: str) -> int:
    """The bits, sign included, of the whole numbers type ``name`` holds exactly: a float's
    significand (its hidden bit counted) and its sign bit, an integer's width.

    >>> [exact_bits(t) for t in TYPES]
    [25, 32, 54, 64]
    """
    t = np.dtype(name)
    return int(np.finfo(t).nmant + 2 if t.kind == "f" else np.iinfo(t).bits)


def narrowest(bits: int, held=exact_bits) -> str | None:
    """The first of :data:`TYPES` that holds ``bits`` bits (sign included) exactly, by
    ``held`` (None: none of them).

    >>> narrowest(38), narrowest(58), narrowest(66)
    ('float64', 'int64', None)
    """
    return next((t for t in TYPES if held(t) >= bits), None)


def centre_grid(origin, width: int, height: int) -> tuple[np.ndarray, np.ndarray]:
    """The window's pixel centres, y as a column and x as a row (broadcast to (height, width)):
    row i and column j of the window whose first pixel is ``origin`` = (row, col).

    >>> y, x = centre_grid((2, 5), 3, 2)
    >>> y.ravel().tolist(), x.ravel().tolist()
    ([2.5, 3.5], [5.5, 6.5, 7.5])
    """
    y = origin[0] + np.arange(height)[:, None] + 0.5
    x = origin[1] + np.arange(width)[None, :] + 0.5
    return y, x


def oriented(s) -> np.ndarray:
    """The snapped vertices ``s`` ordered so that E(v1, v2, v3) > 0 (y down)."""
    (ax, ay), (bx, by), (cx, cy) = s
    return s[[0, 2, 1]] if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0 else s


def edge_values(xy, width: int, height: int, origin, *, orient=True) -> list:
    """(exact E, the size of its two products) on each edge of the snapped triangle (oriented
    so that E(v1, v2, v3) > 0, or as given), at the window's centres: float64 differences,
    exact on the grid within the stated range."""
    s = snap(np.asarray(xy, float))
    v = oriented(s) if orient else s
    y, x = centre_grid(origin, width, height)
    out = []
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        p, q = (b[0] - a[0]) * (y - a[1]), (b[1] - a[1]) * (x - a[0])
        out.append((p - q, np.abs(p) + np.abs(q)))
    return out


def step32_fill(xy, width: int, height: int, origin) -> np.ndarray:
    """r386 NW28: E at the window's first centre in float64, then stepped in float32, by B
    down the rows and by A along each row (the top-left rule on the oriented snapped
    triangle, zero area covers nothing)."""
    s = snap(np.asarray(xy, float))
    v = oriented(s)
    out = np.ones((height, width), dtype=bool)
    (ax, ay), (bx, by), (cx, cy) = v
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) == 0:
        return ~out
    x0, y0 = origin[1] + 0.5, origin[0] + 0.5
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        dx, dy = b[0] - a[0], b[1] - a[1]
        first = np.float32(dx * (y0 - a[1]) - dy * (x0 - a[0]))
        rows = np.add.accumulate(np.r_[first, np.full(height - 1, dx, np.float32)]
                                 .astype(np.float32))  # fmt: skip
        grid = np.empty((height, width), dtype=np.float32)
        grid[:, 0] = rows
        grid[:, 1:] = np.float32(-dy)
        e = np.add.accumulate(grid, axis=1, dtype=np.float32)
        out &= (e >= 0) if (dy < 0 or (dy == 0 and dx > 0)) else (e > 0)
    return out


def float32_rounds(args, expected, got) -> bool:
    """Is every wrong pixel a centre whose exact E on some edge is not 0 but within float32's
    rounding of E there (a spacing of its products, times the steps a stepped E takes), on a
    case where that rounding passes E's step? (A wrong pixel at E = 0 is a tie: the rule.)"""
    xy, width, height, origin = args
    if got.dtype != bool or got.shape != expected.shape:
        return False
    wrong = got != expected
    near = np.zeros_like(wrong)
    for e, size in edge_values(xy, width, height, origin):
        bound = (width + height + 2) * np.spacing(size.astype(np.float32)).astype(float)
        near |= (e != 0) & (np.abs(e) <= bound) & (bound >= STEP)
    return bool(wrong.any() and not (wrong & ~near).any())


def float32_words(args, expected, got) -> str:
    """float32 named by its 24 bits and a sign (25 with it, 10.1's count: r409 F5), the bits E needs on this triangle, and the E that rounds
    at the first wrong pixel (its exact value in steps of 2⁻¹⁶ px²)."""
    xy, width, height, origin = args
    values = edge_values(xy, width, height, origin, orient=False)  # as given, as explained
    i, j = np.argwhere(got != expected)[0]
    k = min(range(3), key=lambda n: abs(values[n][0][i, j]) or np.inf)
    e, size = values[k][0][i, j], values[k][1][i, j]
    s = snap(np.asarray(xy, float))
    sign = 1 if oriented(s) is s else -1  # the interior is where E has the area's sign
    inside = e * sign > 0
    most = max(float(sizes.max()) for _, sizes in values)
    bits = int(np.ceil(np.log2(most / STEP)))
    across = float(np.ptp(s, axis=0).max())
    held32, held64 = exact_bits("float32") - 1, exact_bits("float64") - 1  # without the sign
    return (f"you compute E in float32, which holds {held32} bits and a sign ({held32 + 1} with "
            "it, 10.1's count): on this triangle, "
            f"{across:,.0f} px across, E's products reach {most:,.0f} px², about {bits} bits and a sign in steps of "
            f"2⁻¹⁶ px², and float32's numbers there are {float(np.spacing(np.float32(size))):g} "
            f"px² apart; at pixel [{i}, {j}] the exact E on edge v{k + 1}→v{(k + 1) % 3 + 1} is "
            f"{int(round(e / STEP))} · 2⁻¹⁶ = {e:.3g} px², {'inside' if inside else 'outside'} "
            "by less than float32's rounding, which puts it on the other side; compute E in "
            f"float64 from differences to a vertex (exact here: {held64} bits and a sign) or in int64, "
            "directly at each centre rather than stepped")  # fmt: skip


def refused_or_raw_words(args, expected, got) -> str:
    """r386 NW08: nothing covered on a tiny triangle whose snapped area is small, not zero:
    a triangle refused under an area tolerance and one oriented by its unsnapped area give
    the same empty image there, so both are said."""
    (ax, ay), (bx, by), (cx, cy) = snap(np.asarray(args[0], float))
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (f"snapped, this triangle's E(v1, v2, v3) is {int(round(area / STEP))} · 2⁻¹⁶ = "
            f"{area:.2g} px², small but not zero, so it covers the centres strictly inside it; "
            "two mistakes give your empty image here, and only your code tells which: a "
            "tolerance on the zero-area test (abs(area) < ε refuses it: only a snapped area of "
            "exactly 0 covers nothing), or orienting by the unsnapped area (snapping flipped "
            "this one's winding: orient the snapped triangle)")  # fmt: skip


def small_area_refused(args, expected, got) -> bool:
    """Nothing covered where the snapped triangle's E(v1, v2, v3) is not 0 but below 8 px²
    and the answer has covered centres (a tolerance, or the raw orientation, refuses it)."""
    (ax, ay), (bx, by), (cx, cy) = snap(np.asarray(args[0], float))
    area = abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    return got.dtype == bool and not got.any() and bool(expected.any()) and 0 < area < 8


def slip_variants(xy, width: int, height: int, origin, fill) -> dict[str, np.ndarray]:
    """r386's geometric slips, each seen in the answer's shape: rows or columns tested
    without the ½, the image upside down, every pixel covered, the bounding box one pixel
    short (every pixel covered: :func:`all_covered`), a 1/255 grid, vertices floored to whole pixels (``//``), centres at 127/256 of a
    pixel, a grid offset by half a step, the tie rule read off the raw vertices. ``fill``:
    the right fill of (xy, width, height, origin)."""
    raw = np.asarray(xy, float)
    s = snap(raw)
    right = fill(raw, width, height, origin)
    kw = dict(rule="top_left", origin=tuple(origin))
    c0, r0 = (max(0, int(np.floor(s[:, k].min())) - origin[1 - k]) for k in (0, 1))
    c1, r1 = (min(n, int(np.floor(s[:, k].max())) - origin[1 - k])
              for k, n in ((0, width), (1, height)))  # fmt: skip
    box = np.zeros((height, width), dtype=bool)
    box[r0 : max(r0, r1), c0 : max(c0, c1)] = True
    return {
        "rows without the half": fill(raw + [0, 0.5], width, height, origin),
        "columns without the half": fill(raw + [0.5, 0], width, height, origin),
        "upside down": right[::-1],
        "bounding box one short": right & box,
        "1/255 grid": naive_coverage(np.rint(raw * 255) / 255, width, height, **kw),
        "vertices on whole pixels": naive_coverage(np.floor(s), width, height, **kw),
        "centres 1/256 px short": naive_coverage(s + 1 / 256, width, height, **kw),
        "grid offset by half a step": naive_coverage(
            (np.rint(raw * 256 - 0.5) + 0.5) / 256, width, height, **kw
        ),
        "tie rule from the raw vertices": raw_tie_fill(raw, width, height, origin),
        **slip_variants_r394(raw, width, height, origin, fill),
    }


def slip_variants_r394(raw, width: int, height: int, origin, fill) -> dict[str, np.ndarray]:
    """r394's slips: one axis without its origin, the window's last row missing, a rounded
    bounding box, one sign wrong in E, centres 1/256 px right, both windings accepted with
    the tie rule on one only."""
    s = snap(raw)
    right = fill(raw, width, height, origin)
    last = right.copy()
    last[-1] = False
    box = np.zeros((height, width), dtype=bool)
    lo = [max(0, int(round(s[:, k].min())) - origin[1 - k]) for k in (0, 1)]
    hi = [min(n, int(round(s[:, k].max())) - origin[1 - k]) for k, n in ((0, width), (1, height))]
    box[lo[1] : max(lo[1], hi[1]), lo[0] : max(lo[0], hi[0])] = True
    return {
        "rows without origin": fill(raw, width, height, (0, origin[1])),
        "columns without origin": fill(raw, width, height, (origin[0], 0)),
        "last row missing": last,
        "rounded bounding box": right & box,
        "centres 1/256 px right": naive_coverage(
            s - [1 / 256, 0], width, height, rule="top_left", origin=tuple(origin)
        ),
        "one sign wrong in E": edge_sign_fill(s, width, height, origin, both=False),
        "both windings, ties on one": edge_sign_fill(s, width, height, origin, both=True),
    }


def edge_sign_fill(s, width: int, height: int, origin, both: bool) -> np.ndarray:
    """r394 W20 (``both`` False): E with + between its two products, on the oriented
    triangle; W15 (``both``): no orienting, the tie rule for E > 0 and E < 0 strict."""
    (ax, ay), (bx, by), (cx, cy) = s
    if (bx - ax) * (cy - ay) - (by - ay) * (cx - ax) == 0:
        return np.zeros((height, width), dtype=bool)
    v = s if both else oriented(s)
    y, x = centre_grid(origin, width, height)
    pos = np.ones((height, width), dtype=bool)
    neg = pos.copy()
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        d = (b[1] - a[1]) * (x - a[0])
        e = (b[0] - a[0]) * (y - a[1]) + (-d if both else d)
        tie = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
        pos &= (e >= 0) if tie else (e > 0)
        neg &= e < 0
    return pos | neg if both else pos


def raw_tie_fill(raw, width: int, height: int, origin) -> np.ndarray:
    """r386 NW16: E from the snapped vertices, the top-left verdicts from the raw ones."""
    s = snap(raw)
    v = oriented(s)
    r = raw if v is s else raw[[0, 2, 1]]
    out = np.ones((height, width), dtype=bool)
    if (s[1, 0] - s[0, 0]) * (s[2, 1] - s[0, 1]) == (s[1, 1] - s[0, 1]) * (s[2, 0] - s[0, 0]):
        return ~out
    y, x = centre_grid(origin, width, height)
    for k in range(3):
        a, b, ra, rb = v[k], v[(k + 1) % 3], r[k], r[(k + 1) % 3]
        e = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        tie = rb[1] < ra[1] or (rb[1] == ra[1] and rb[0] > ra[0])
        out &= (e >= 0) if tie else (e > 0)
    return out


def all_covered(args, expected, got) -> bool:
    """r386 NW12: every pixel of the window covered where some is not (a zero-area triangle
    may still be given nothing)."""
    if got.dtype != bool or got.shape != expected.shape or not got.all():
        return False
    # r394 W24: a zero-area triangle covered is ZERO_AREA's (its own cause), not a placeholder
    s = snap(np.asarray(args[0], float))
    (ax, ay), (bx, by), (cx, cy) = s
    return bool((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) != 0)


#: The slips' words (:func:`slip_variants`, :func:`all_covered`).
SLIP_WORDS = {
    "rows without the half": "you test row i at y = origin[0] + i, its top edge, not its "
    "centre: a pixel's centre is at y = origin[0] + i + ½",
    "columns without the half": "you test column j at x = origin[1] + j, its left edge, not "
    "its centre: a pixel's centre is at x = origin[1] + j + ½",
    "upside down": "your image is upside down: row 0 is the window's top row (y down, as on "
    "screen), so do not flip it (no [::-1], no np.flipud: that is the y-up habit)",
    "everything covered": "your function covers every pixel: it returns an image of True for every "
    "triangle it does not refuse (a placeholder left in, or a test that every centre passes, "
    "such as the three edges' tests combined with | instead of &: every point is inside one "
    "of them?)",
    "bounding box one short": "every pixel you miss is in the last row or column of the "
    "triangle's bounding box: your box stops one short (range(floor(min), floor(max)) leaves "
    "out the pixel holding the largest x or y; run to floor(max) + 1)",
    "1/255 grid": "you snap to 1/255 px (np.rint(xy * 255) / 255), not 1/256: 8 sub-pixel "
    "bits make 2⁸ = 256 steps per pixel, not 2⁸ − 1, so your vertices land between the GPU's "
    "grid points",
    "vertices on whole pixels": "your vertices land on whole pixels: // floors after the "
    "division (np.rint(xy * 256) // 256 is np.floor of the snapped vertex); divide with /",
    "centres 1/256 px short": "your centres are 1/256 px left of and above the pixel centres: "
    "in 1/256-px units a centre is at 256 · j + 128, not 127",
    "grid offset by half a step": "your grid points are at (k + ½)/256 px, half a step off "
    "the GPU's grid k/256: round xy · 256 to the nearest whole number and divide, nothing "
    "added or taken away",
    "rows without origin": "your rows ignore origin[0]: you test row i at y = i + ½, not "
    "y = origin[0] + i + ½ (your columns add origin[1])",
    "columns without origin": "your columns ignore origin[1]: you test column j at x = j + ½, "
    "not x = origin[1] + j + ½ (your rows add origin[0])",
    "last row missing": "every pixel you miss is in the window's last row (row height − 1): "
    "your loop or slice stops one short (range(height - 1), or [:-1])",
    "rounded bounding box": "your bounding box misses pixels whose centres are inside: it "
    "runs from round(min) to round(max); a pixel's centre can be inside from floor(min) to "
    "floor(max) inclusive",
    "centres 1/256 px right": "your centres are 1/256 px right of the pixel centres: a "
    "pixel's centre is at x = origin[1] + j + ½, nothing added",
    "one sign wrong in E": "your E is not the edge function: E(a, b, p) = (b.x − a.x)(p.y − "
    "a.y) − (b.y − a.y)(p.x − a.x), a minus between the two products, not a plus",
    "both windings, ties on one": "you accept both windings without orienting, with the tie "
    "rule on one only: for a triangle with E(v1, v2, v3) < 0 you cover no centre on an edge; "
    "orient first (swap two vertices when E(v1, v2, v3) < 0), then apply one rule",
    "tie rule from the raw vertices": "your top/left verdicts come from the unsnapped "
    "vertices: snapping can make an edge horizontal or turn its direction, so decide top and "
    "left on the snapped (and oriented) triangle, the one whose E you test",
}
