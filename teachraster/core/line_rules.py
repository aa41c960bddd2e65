"""Which pixels a one-pixel line lights: the diamond-exit rule, Bresenham and DDA.

All three work on the snapped end points in internal units (:mod:`.snapping`: pixel centres
are integers too) and walk the *major axis* (x when ``|dx| >= |dy|``), one step per column
(or row) the line crosses. Each returns a :class:`LineSteps`: the candidate pixels it looked
at in each step and what it decided, which the trace turns into captions.

The diamond-exit rule is the GL specification's (§14.5.1, "Basic line segment
rasterization") and Direct3D's: pixel (row i, col j) owns the open diamond
``|x - (j + 1/2)| + |y - (i + 1/2)| < 1/2``; a fragment is produced where the segment from
p0 towards p1 meets the diamond, except the diamond p1 lies in (so a polyline lights each
shared vertex once). GL removes ties by moving both end points by ``-(ε, ε²)``; here that
perturbation is carried symbolically (values ``n0 + n1 ε + n2 ε²`` compared
lexicographically), so the answer is exact on the snapped grid, not an approximation with a
small ε. It is applied to these y-down numbers, as Vulkan's *Bresenham Line Segment
Rasterization* applies it in its framebuffer coordinates (origin upper left); GL applies it
in its y-up window, which decides one kind of tie the other way (:func:`gl_decides_otherwise`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

RULES = ("diamond", "bresenham", "dda")

#: Candidate pixels per major-axis step on each side of the line (the diamond rule): a line
#: with |slope| <= 1 meets at most the diamonds of rows floor(y) - 1 .. floor(y) + 1.
SPREAD = 2

# Candidate states.
MISSED, LIT, ENDS_INSIDE = 0, 1, 2


@dataclass(frozen=True)
class LineSteps:
    """What a line rule did, one step per major-axis column (or row) it visited.

    ``major`` (n,) the column (x-major) or row index of each step; ``value`` (n,) what the
    rule computed there (diamond: the exact minor coordinate of the line at the centre, px;
    Bresenham: the error term before its decision; DDA: the accumulated float32 minor
    coordinate, px). Candidates: ``step`` (m,) the step each belongs to, ``rows``, ``cols``
    (m,) the pixel, ``state`` (m,) int8 :data:`MISSED`, :data:`LIT` or :data:`ENDS_INSIDE`;
    ``tie`` (m,) bool (diamond rule, traced) where the perturbation by ``-(ε, ε²)`` (y down)
    decided the candidate's state (the segment touches its diamond's boundary), else None.
    """

    x_major: bool
    major: np.ndarray
    value: np.ndarray
    step: np.ndarray
    rows: np.ndarray
    cols: np.ndarray
    state: np.ndarray
    tie: np.ndarray | None = None

    @property
    def lit(self) -> np.ndarray:
        """(m,) bool: the candidates the rule lit."""
        return self.state == LIT


def gl_decides_otherwise(p0, p1) -> bool:
    """Whether GL decides this line's ties otherwise than the y-down rule here.

    Both move the end points by ``-(ε, ε²)``, GL in its window (y up, GL 4.6 §14.5.1),
    this module and Vulkan (*Bresenham Line Segment Rasterization*) with y down. On a sloped
    line the shift by ε, the same on both grids, moves every crossing far more than ε², and a
    vertical line is moved across by ε alone; only a horizontal line lying on a row boundary
    is moved by ε² alone, up here and down in GL: here it lights the row above the boundary,
    in GL the row below.

    Parameters
    ----------
    p0, p1 : (2,) array-like
        The snapped end points, px (y down).

    Returns
    -------
    bool
        True for a horizontal segment on a row boundary (integer y).

    >>> gl_decides_otherwise((0.3, 1.0), (8.3, 1.0)), gl_decides_otherwise((0.5, 0.5), (8.5, 4.5))
    (True, False)
    """
    y0, y1 = float(p0[1]), float(p1[1])
    return y0 == y1 and float(p0[0]) != float(p1[0]) and y0.is_integer()


def major_axis(d) -> bool:
    """True when the line is x-major: ``|dx| >= |dy|`` (45° lines count as x-major)."""
    return bool(abs(d[0]) >= abs(d[1]))


def _major_range(a, b, unit, size, axis) -> np.ndarray:
    """Major-axis pixel indices whose diamonds can meet the segment, clipped to the image.

    Diamond j spans the open interval (j, j + 1) along the major axis, and the segment,
    moved by ``-ε`` (``-ε²`` along y), spans [lo - ε, hi - ε]: they overlap exactly for
    ``ceil(lo) - 1 <= j <= ceil(hi) - 1``. No column (row) the segment never reaches is
    walked (a segment ending at x = 12.5 walked column 13 too).
    """
    lo, hi = sorted((a[axis], b[axis]))
    first = max(int(-(-lo // unit)) - 1, 0)
    last = min(int(-(-hi // unit)) - 1, size - 1)
    return np.arange(first, last + 1, dtype=np.int64)


def _minor_at(a, d, centres, axis):
    """The line's minor coordinate (units, float64) where the major coordinate is ``centres``."""
    other = 1 - axis
    return a[other] + (centres - a[axis]) * (float(d[other]) / float(d[axis]))


def empty_steps(x_major: bool = True) -> LineSteps:
    """No step at all: a zero-length line lights nothing (its end's diamond is its start's),
    nor does one whose major-axis range misses the image."""
    none = np.zeros(0, np.int64)
    return LineSteps(x_major, none, none.astype(np.float64), none, none, none,
                     none.astype(np.int8), np.zeros(0, bool))  # fmt: skip


def _walk(a, b, unit, width, height):
    """The major axis, the major-axis indices walked and the line's minor coordinate at each
    one's centre (units, float64)."""
    d = (b[0] - a[0], b[1] - a[1])
    x_major = major_axis(d)
    axis = 0 if x_major else 1
    major = _major_range(a, b, unit, width if x_major else height, axis)
    centres = major * unit + unit // 2 if isinstance(unit, int) else major + 0.5
    return x_major, major, _minor_at(a, d, centres, axis)


def _candidates(x_major, major, minor, first_step, unit, limit):
    """Candidate pixels near the line for steps ``first_step + k`` (the diamond rule): rows
    (x-major) or columns floor(minor) - SPREAD .. + SPREAD, inside the image."""
    base = np.floor(minor / unit).astype(np.int64)
    offsets = np.arange(-SPREAD, SPREAD + 1)
    minor_idx = (base[:, None] + offsets).ravel()
    step = np.repeat(np.arange(first_step, first_step + len(major)), len(offsets))
    major_idx = np.repeat(major, len(offsets))
    keep = (minor_idx >= 0) & (minor_idx < limit)
    rows, cols = (minor_idx, major_idx) if x_major else (major_idx, minor_idx)
    return step[keep], rows[keep], cols[keep]


# -- the diamond-exit rule, exact ---------------------------------------------------------------
def _bound(c, a_coord, d, tie):
    """The parameter t = (c - a') / d as (n0, n1, n2, den) with den > 0.

    ``a' = a - ε - tie·ε²`` is the perturbed start along a diagonal axis (u = x + y: tie +1;
    v = x - y: tie -1), so ``c - a' = (c - a) + ε + tie·ε²``.
    """
    s = np.sign(d)
    return (c - a_coord) * s, s, s * tie, np.abs(d)


def _less(x, y):
    """x < y for perturbed values (n0, n1, n2, den), lexicographic in powers of ε."""
    return _less_tie(x, y)[0]


def _less_tie(x, y):
    """(x < y, whether ε decided it): the comparison of :func:`_less` and where the values'
    ε-free parts are equal, so that only the perturbation tells them apart."""
    out = np.zeros(np.broadcast(x[0], y[0]).shape, dtype=bool)
    undecided = np.ones_like(out)
    by_eps = np.zeros_like(out)
    for k in range(3):
        lhs, rhs = x[k] * y[3], y[k] * x[3]
        decided = undecided & (lhs != rhs)
        out |= decided & (lhs < rhs)
        if k:
            by_eps |= decided
        undecided &= lhs == rhs
    return out, by_eps | undecided


def _pick(mask, x, y):
    """Component-wise ``where(mask, x, y)`` for perturbed values."""
    return tuple(np.where(mask, xi, yi) for xi, yi in zip(x, y, strict=True))


def _axis_bounds(centre, a_coord, d, half, tie):
    """Open bounds (lo, hi) on t for ``|u(t) - centre| < half`` along one diagonal axis,
    whether the axis admits any t when the segment is parallel to it (d == 0), and whether
    the perturbation decided that (the segment runs along the slab's boundary)."""
    near, far = (centre - half, centre + half) if d > 0 else (centre + half, centre - half)
    if d == 0:
        off = a_coord - centre  # the perturbed start a - ε... is inside iff -h < off <= h
        ok = (off > -half) & (off <= half)
        n = np.ones_like(centre)
        return (-n, 0 * n, 0 * n, n), (2 * n, 0 * n, 0 * n, n), ok, np.abs(off) == half
    none = np.zeros(len(centre), bool)
    return _bound(near, a_coord, d, tie), _bound(far, a_coord, d, tie), ~none, none


def diamond_states(a, b, unit, rows, cols, *, ties: bool = False):
    """For candidate pixels, whether the perturbed segment a→b meets their open diamond and
    whether it ends inside it: int8 :data:`LIT`, :data:`ENDS_INSIDE` or :data:`MISSED`;
    with ``ties=True`` also (m,) bool, where the perturbation decided that state (a
    comparison equal but for its ε terms while the others hold, or the end point on the
    diamond's boundary; the
    page's ``diamondState`` marks the same ones).

    In the rotated coordinates u = x + y, v = x - y the diamond is the open square
    ``|u - u_c| < h, |v - v_c| < h`` (h half a pixel), so meeting it is a clip of t ∈ [0, 1]
    against two open slabs (Liang-Barsky), done exactly on the perturbed values.
    """
    half = unit // 2 if isinstance(unit, int) else 0.5
    cx, cy = cols * unit + half, rows * unit + half
    au, av, bu, bv = a[0] + a[1], a[0] - a[1], b[0] + b[1], b[0] - b[1]
    lo_u, hi_u, ok_u, along_u = _axis_bounds(cx + cy, au, bu - au, half, +1)
    lo_v, hi_v, ok_v, along_v = _axis_bounds(cx - cy, av, bv - av, half, -1)
    # which slab is entered (left) last only picks the bound: equal bounds pick the same t, so
    # a tie there decides nothing (a line through a diamond's corner and on into it, review
    # r63); only the comparisons with hi, 0 and 1 can turn on GL's ε
    u_first, _ = _less_tie(lo_u, lo_v)
    h_first, _ = _less_tie(hi_u, hi_v)
    lo, hi = _pick(u_first, lo_v, lo_u), _pick(h_first, hi_u, hi_v)
    one, zero = (1, 0, 0, 1), (0, 0, 0, 1)
    (c1, t3), (c2, t4), (c3, t5) = _less_tie(lo, hi), _less_tie(lo, one), _less_tie(zero, hi)
    meets = ok_u & ok_v & c1 & c2 & c3
    # b' = b - (ε, ε²) is inside the diamond iff -h < off <= h on both diagonal axes.
    du, dv = bu - (cx + cy), bv - (cx - cy)
    ends = (du > -half) & (du <= half) & (dv > -half) & (dv <= half)
    state = np.where(meets, np.where(ends, ENDS_INSIDE, LIT), MISSED).astype(np.int8)
    if not ties:
        return state
    on_edge = (np.abs(du) + np.abs(dv) <= 2 * half) & ((np.abs(du) == half) | (np.abs(dv) == half))
    # a comparison's tie decides the state only where the other two hold (or tie too): an
    # end point on a diamond's edge line extended ties lo with 1 or hi with 0 on diamonds the
    # line never comes near, which c1 rejects anyway (review r71)
    h1, h2, h3 = c1 | t3, c2 | t4, c3 | t5
    decides = (t3 & h2 & h3) | (t4 & h1 & h3) | (t5 & h1 & h2)
    tie = along_u | along_v | (ok_u & ok_v & decides) | on_edge
    return state, tie


#: Major-axis steps decided together: bounds the temporaries of a very long line.
CHUNK = 2**15


def diamond(a, b, unit, width, height, keep_missed: bool = True) -> LineSteps:
    """The diamond-exit rule (see the module docstring), exact on the snapped grid.

    ``keep_missed=False`` keeps only the candidates lit or ending inside (what the pixels
    need; the trace keeps the rejected ones too, to draw them).
    """
    if tuple(a) == tuple(b):
        return empty_steps()
    x_major, major, minor = _walk(a, b, unit, width, height)
    if len(major) == 0:  # the walk's range misses the image: no column (row) to decide
        return empty_steps(x_major)
    limit = height if x_major else width
    parts = []
    for lo in range(0, len(major), CHUNK):
        hi = lo + CHUNK
        step, rows, cols = _candidates(x_major, major[lo:hi], minor[lo:hi], lo, unit, limit)
        if keep_missed:  # the trace: every candidate, and which ones a tie decided
            state, tie = diamond_states(a, b, unit, rows, cols, ties=True)
        else:
            state = diamond_states(a, b, unit, rows, cols)
            keep = state != MISSED
            step, rows, cols, state = step[keep], rows[keep], cols[keep], state[keep]
            tie = np.zeros(len(state), bool)
        parts.append((step, rows, cols, state, tie))
    step, rows, cols, state, tie = (np.concatenate(p) for p in zip(*parts, strict=True))
    return LineSteps(x_major, major, minor / unit, step, rows, cols, state,
                     tie if keep_missed else None)  # fmt: skip


# -- Bresenham and DDA --------------------------------------------------------------------------
def _centre_steps(a, b, unit, size, axis):
    """Major indices whose centres lie in the half-open range [a, b) along ``axis`` (in the
    direction of travel): the pixels the classic loops visit, the last one left to the next
    segment as the diamond rule does."""
    half = unit // 2 if isinstance(unit, int) else 0.5
    s, e = a[axis], b[axis]
    # Only the indices inside the image are made: a line from far off screen walks no more.
    if e >= s:  # centres c with s <= c < e
        first, last = -((half - s) // unit), -((half - e) // unit) - 1
        return np.arange(max(first, 0), min(last, size - 1) + 1, dtype=np.int64)
    # centres c with e < c <= s, walked downwards
    first, last = (s - half) // unit, (e - half) // unit + 1
    return np.arange(min(first, size - 1), max(last, 0) - 1, -1, dtype=np.int64)


def bresenham(a, b, unit, width, height, keep_missed: bool = True) -> LineSteps:
    """Bresenham's integer midpoint line between the pixels holding the end points.

    The end points are taken to the pixels they lie in (``floor``), then the classic loop
    runs with the error term ``D = 2·dminor·(k + 1) − dmajor − 2·dmajor·(minor_k − minor_0)``:
    step the minor axis when D > 0 (at D == 0, a midpoint exactly on the line, it does not).
    The last pixel is left out, as the diamond rule leaves out the end's diamond.
    """
    p = [int(a[0] // unit), int(a[1] // unit)]
    q = [int(b[0] // unit), int(b[1] // unit)]
    x_major = major_axis((b[0] - a[0], b[1] - a[1]))
    axis = 0 if x_major else 1
    n_major = abs(q[axis] - p[axis])
    n_minor = q[1 - axis] - p[1 - axis]
    sign_major = 1 if q[axis] >= p[axis] else -1
    k = _steps_inside(p[axis], sign_major, n_major, width if x_major else height)
    dm, dn = n_major, abs(n_minor)
    offset = (2 * k * dn + dm - 1) // (2 * dm) if dm else 0 * k
    error = 2 * dn * (k + 1) - dm - 2 * dm * offset
    major = p[axis] + sign_major * k
    minor = p[1 - axis] + np.sign(n_minor) * offset
    rows, cols = (minor, major) if x_major else (major, minor)
    size = (height, width)
    keep = (rows >= 0) & (rows < size[0]) & (cols >= 0) & (cols < size[1])
    state = np.full(len(k), LIT, np.int8)
    steps = np.arange(len(k))
    return LineSteps(
        x_major, major, error.astype(np.float64), steps[keep], rows[keep], cols[keep], state[keep]
    )


def _steps_inside(start: int, sign: int, n: int, size: int) -> np.ndarray:
    """The steps k in [0, n) whose major index ``start + sign·k`` lies in [0, size): each
    step's pixel has a closed form, so a line from far off screen makes only these."""
    if sign > 0:
        lo, hi = max(0, -start), min(n, size - start)
    else:
        lo, hi = max(0, start - size + 1), min(n, start + 1)
    return np.arange(lo, max(lo, hi), dtype=np.int64)


def dda(a, b, unit, width, height, keep_missed: bool = True) -> LineSteps:
    """The digital differential analyser: one step per major-axis pixel centre in [p0, p1),
    the minor coordinate advanced by adding the slope in float32 each step (as a naive
    shader or a 1980s loop would), the pixel taken where it lands (``floor``).

    Adding a rounded slope again and again drifts: on a long line the float32 sum leaves the
    exact line by more than half a pixel and DDA lights a different pixel from the exact rule.
    """
    d = (b[0] - a[0], b[1] - a[1])
    if d == (0, 0):
        return empty_steps()
    x_major = major_axis(d)
    axis = 0 if x_major else 1
    major = _centre_steps(a, b, unit, width if x_major else height, axis)
    half = unit / 2
    if len(major):
        slope = np.float32(float(d[1 - axis]) / float(d[axis]))
        start = np.float32(float(_minor_at(a, d, major[0] * unit + half, axis)) / unit)
        steps = np.full(len(major), slope, np.float32)
        steps[0] = start
        steps[1:] *= np.float32(np.sign(d[axis]))  # walking left (up) subtracts the slope
        minor = np.add.accumulate(steps, dtype=np.float32)
    else:
        minor = np.zeros(0, np.float32)
    minor_idx = np.floor(minor).astype(np.int64)
    rows, cols = (minor_idx, major) if x_major else (major, minor_idx)
    keep = (rows >= 0) & (rows < height) & (cols >= 0) & (cols < width)
    state = np.full(len(major), LIT, np.int8)
    steps_idx = np.arange(len(major))
    return LineSteps(
        x_major,
        major,
        minor.astype(np.float64),
        steps_idx[keep],
        rows[keep],
        cols[keep],
        state[keep],
    )


RULE_FUNCTIONS = {"diamond": diamond, "bresenham": bresenham, "dda": dda}
