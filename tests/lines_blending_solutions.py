"""Independent solutions of lessons 12a and 12b's exercises (no call into teachraster): the diamond rule
in exact Fractions with GL's perturbation as a concrete tiny ε, the blend equations by hand;
and the typical mistakes the checker must catch and explain."""

from __future__ import annotations

from fractions import Fraction

import numpy as np

EPS = Fraction(1, 2**80)
HALF = Fraction(1, 2)


def _meets(a, b, cx, cy) -> bool:
    """Does the closed segment a→b meet the open diamond around (cx, cy)? (Cyrus-Beck)"""
    lo, hi, lo_open, hi_open = Fraction(0), Fraction(1), False, False
    dx, dy = b[0] - a[0], b[1] - a[1]
    for sx, sy in ((1, 1), (1, -1), (-1, 1), (-1, -1)):
        c = HALF - sx * (a[0] - cx) - sy * (a[1] - cy)
        rate = sx * dx + sy * dy
        if rate == 0:
            if c <= 0:
                return False
            continue
        t = c / rate
        if rate > 0 and (t < hi or (t == hi and not hi_open)):
            hi, hi_open = t, True
        elif rate < 0 and (t > lo or (t == lo and not lo_open)):
            lo, lo_open = t, True
    return lo < hi or (lo == hi and not (lo_open or hi_open))


def _far_from_line(p0, p1):
    """``far(x, y)``: is the point more than ¾ px (in floats) from the line through p0 and p1?
    Every point of a diamond of radius ½ lies within ½ px of its centre, and the end points
    move by far less than the ¼ px margin, so a centre this far has a diamond the segment
    cannot meet: only the exact test of the others decides (a long line's box holds far
    more centres than its band, each an exact test in Fractions)."""
    (x0, y0), (x1, y1) = (float(p0[0]), float(p0[1])), (float(p1[0]), float(p1[1]))
    dx, dy = x1 - x0, y1 - y0
    length = (dx * dx + dy * dy) ** 0.5
    if not 0 < length < 1e12:
        return lambda x, y: False
    return lambda x, y: abs(dx * (y - y0) - dy * (x - x0)) > 0.75 * length


def line_with(eps_x, eps_y, order="row col", clip=True):
    """The diamond-exit rule with the end points moved by (eps_x, eps_y) (GL: (−ε, −ε²)),
    pairs as (row, col), or (col, row) for the mistake; ``clip=False`` keeps pixels left of
    or above the image (r14 09-8)."""

    def fn(p0, p1):
        a = (Fraction(p0[0]) + eps_x, Fraction(p0[1]) + eps_y)
        b = (Fraction(p1[0]) + eps_x, Fraction(p1[1]) + eps_y)
        far = _far_from_line(p0, p1)
        out = []
        for row in range(int(min(a[1], b[1])) - 1, int(max(a[1], b[1])) + 2):
            for col in range(int(min(a[0], b[0])) - 1, int(max(a[0], b[0])) + 2):
                if far(col + 0.5, row + 0.5):  # its diamond cannot meet the segment
                    continue
                cx, cy = col + HALF, row + HALF
                inside_end = abs(b[0] - cx) + abs(b[1] - cy) < HALF
                inside = (row >= 0 and col >= 0) or not clip
                if inside and _meets(a, b, cx, cy) and not inside_end:
                    out.append((row, col) if order == "row col" else (col, row))
        return out

    return fn


line_pixels = line_with(-EPS, -EPS * EPS)


def over(src, dst):
    a = src[3]
    return [s * a + d * (1 - a) for s, d in zip(src, dst)]


def over_premultiplied(src, dst):
    a = src[3]
    return [s + d * (1 - a) for s, d in zip(src, dst)]


def atop_premultiplied(src, dst):
    """Porter and Duff's atop, premultiplied: the source on what dst covers, dst where src is
    not (exercise 9.2b since r20)."""
    return [s * dst[3] + d * (1 - src[3]) for s, d in zip(src, dst)]


def over_to_premultiplied(src, dst):
    """Straight in, premultiplied out: each colour as much as it is seen."""
    a = src[3] + dst[3] * (1 - src[3])
    return [*(s * src[3] + d * dst[3] * (1 - src[3]) for s, d in zip(src[:3], dst[:3])), a]


def over_straight(src, dst):
    """Straight in, straight out: the light each colour shows, spread over the share covered
    (nothing covers the pixel: (0, 0, 0, 0))."""
    a = src[3] + dst[3] * (1 - src[3])
    if a == 0:
        return [0.0, 0.0, 0.0, 0.0]
    return [*((s * src[3] + d * dst[3] * (1 - src[3])) / a for s, d in zip(src[:3], dst[:3])), a]


CORRECT = {"line_pixels": line_pixels, "over": over,
           "over_to_premultiplied": over_to_premultiplied,
           "over_premultiplied": over_premultiplied, "over_straight": over_straight,
           "atop_premultiplied": atop_premultiplied}  # fmt: skip


# -- typical mistakes -----------------------------------------------------------------------------
def line_with_end(p0, p1):
    """Lights p1's own pixel too (the closed segment)."""
    out = line_pixels(p0, p1)
    if tuple(p0) != tuple(p1):
        out.append((int(p1[1]), int(p1[0])))
    return list(set(out))


def line_round_centres(p0, p1):
    """One pixel per major-axis centre, rounding the line there (DDA-like, no diamond)."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = x1 - x0, y1 - y0
    if dx == dy == 0:
        return []
    out = []
    if abs(dx) >= abs(dy):
        for j in range(int(min(x0, x1)), int(max(x0, x1)) + 1):
            x = j + 0.5
            if min(x0, x1) <= x < max(x0, x1):
                out.append((int(np.floor(y0 + (x - x0) * dy / dx)), j))
    else:
        for i in range(int(min(y0, y1)), int(max(y0, y1)) + 1):
            y = i + 0.5
            if min(y0, y1) <= y < max(y0, y1):
                out.append((i, int(np.floor(x0 + (y - y0) * dx / dy))))
    return out


def over_dst_alpha(src, dst):
    return [s * dst[3] + d * (1 - dst[3]) for s, d in zip(src, dst)]


def over_porter_duff_alpha(src, dst):
    a = src[3]
    return [src[0] * a + dst[0] * (1 - a), src[1] * a + dst[1] * (1 - a),
            src[2] * a + dst[2] * (1 - a), a + dst[3] * (1 - a)]  # fmt: skip


def premultiplied_twice(src, dst):
    a = src[3]
    return [src[0] * a + dst[0] * (1 - a), src[1] * a + dst[1] * (1 - a),
            src[2] * a + dst[2] * (1 - a), a + dst[3] * (1 - a)]  # fmt: skip


#: (exercise, wrong function, words the explanation must contain)
MISTAKES = {
    "lighting the end pixel": ("line_pixels", line_with_end, "p1"),
    "rounding at centres": ("line_pixels", line_round_centres, "diamond"),
    "destination alpha": ("over", over_dst_alpha, "destination alpha"),
    "Porter-Duff alpha in GL's over": ("over", over_porter_duff_alpha, "one factor pair"),
    "premultiplying twice": ("over_premultiplied", premultiplied_twice, "dark fringe"),
    "over for atop": ("atop_premultiplied", over_premultiplied, "that is over"),  # r20 D-1
    "straight blended as premultiplied": ("over_to_premultiplied", over_premultiplied,
                                          "as if they were premultiplied"),
    "GL's straight blend for a translucent destination": ("over_to_premultiplied", over,
                                                           "GL's straight blend"),
}  # fmt: skip


def over_numpy(src, dst):
    src, dst = np.asarray(src), np.asarray(dst)
    return src * src[3] + dst * (1 - src[3])


ALTERNATIVES = {"over": over_numpy}


def over_to_premultiplied_divided(src, dst):
    """The straight form first (divided by α), then multiplied back: NaN when both α are 0."""
    src, dst = np.asarray(src, float), np.asarray(dst, float)
    alpha = src[3] + dst[3] * (1 - src[3])
    with np.errstate(invalid="ignore", divide="ignore"):
        colour = (src[:3] * src[3] + dst[:3] * dst[3] * (1 - src[3])) / alpha
    return np.r_[colour * alpha, alpha]


MISTAKES["divided by zero alpha"] = ("over_to_premultiplied", over_to_premultiplied_divided,
                                     "both alphas 0: the result is transparent black, not a "
                                     "division by zero")  # fmt: skip
MISTAKES["premultiplied returned for the straight result"] = (
    "over_straight",
    over_to_premultiplied,
    "divide it by α",
)  # r11 09-A: 9.2a returns (C, α)
