"""Span tables: split at u4 into a flat-bottom and a flat-top triangle, fill row by row.

Ek, *Triangles and Perspective Correct Interpolation*, §1.1: sort the vertices by y into top,
middle and bottom (Ek's points 1, 2, 3; in this module's code ``v1, v2, v3`` and ``(u1, v1)``
are those points, not the caller's v1, v2, v3, which keep their names in every caption). The
horizontal line through the middle one meets the long edge at point 4,
``u4 = (v2 - v1) / (v3 - v1) * (u3 - u1) + u1`` (similar triangles), which splits the
triangle into a flat-bottom one (top, middle, point 4) and a flat-top one (middle, point 4,
bottom). Each raster line of either is one span between a left and a right edge.

To cover exactly the pixels the half-plane method covers, each span end is computed as
the exact solution of that edge's test on the row: on the snapped grid the last covered
column is an integer floor division, with the top-left tie rule folded in. A row applies
the test of every edge whose y-range contains it: the two edges of its flat triangle,
and on the split row itself also the other short edge (the middle vertex lies on both); a horizontal
edge keeps or drops its whole row by the top-edge rule.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .bbox import BBox
from .edges import EdgeSetup, passes
from .validate import as_finite


@dataclass(frozen=True)
class SpanTrace:
    """What the span-table fill did.

    Attributes
    ----------
    order : (3,) int
        Original indices (from 0) of the top, middle and bottom vertex (sorted by y, then x).
    sorted_xy : (3, 2) float
        Top, middle and bottom vertex (snapped), in pixels.
    u4 : float or None
        x of the split point, point 4 = (u4, middle y); None for a zero-height triangle.
    flat_bottom, flat_top : (3, 2) float or None
        (top, middle, point 4) and (middle, point 4, bottom); None when that part has zero
        height.
    rows : (n,) int
        Raster lines, top to bottom (every row whose centre is within the y-range).
    half : (n,) int8
        0 when the row belongs to the flat-bottom triangle, 1 for the flat-top one.
    x_left, x_right : (n,) float
        Where the row's centre line crosses its left and right edges, in pixels.
    col_start, col_stop : (n,) int
        Covered columns ``col_start <= j < col_stop`` (clipped to the image).
    """

    order: np.ndarray
    sorted_xy: np.ndarray
    u4: float | None
    flat_bottom: np.ndarray | None
    flat_top: np.ndarray | None
    rows: np.ndarray
    half: np.ndarray
    x_left: np.ndarray
    x_right: np.ndarray
    col_start: np.ndarray
    col_stop: np.ndarray


def split_point(sorted_xy: np.ndarray) -> float | None:
    """``u4 = (v2 - v1) / (v3 - v1) * (u3 - u1) + u1`` for vertices sorted by y.

    >>> split_point(np.array([[2.0, 0.0], [0.0, 2.0], [6.0, 4.0]]))
    4.0
    """
    (u1, v1), (_, v2), (u3, v3) = as_finite("sorted_xy", sorted_xy, (3, 2))
    if v3 == v1:  # zero height: no split, and no division by zero
        return None
    return float((v2 - v1) / (v3 - v1) * (u3 - u1) + u1)


#: "No bound" for a column range: far beyond any image, and safe in int64 arithmetic.
NO_BOUND = 2**62


def edge_bounds(
    a, b, top_left, y, unit, half, exact: bool, first_col=0, last_col=0, crossings=True
):
    """Columns allowed by directed edges a→b on raster lines with centre y (internal units).

    Solves the edge's tie-aware test ``E >= 0`` (top-left) or ``E > 0`` for the column j
    of the pixel centre ``X = j * unit + half`` on each row. All arguments broadcast, so
    one triangle's edge over many rows and many triangles' edges at once work alike.

    On the snapped grid the answer is one exact integer division. With raw floats
    (``exact=False``) the answer is searched for among columns ``first_col .. last_col``
    (bisection on E itself; outside that range only "before" or "after" is reported).

    Returns
    -------
    lo, hi : int64 arrays
        The edge allows ``lo <= j <= hi``; an edge going up (dy < 0, inside on its right)
        gives ``lo``, one going down gives ``hi``; the other is +-NO_BOUND.
    ok : bool array
        False only on the line of a horizontal edge whose tie excludes the whole row.
    crossing : float array or None
        Where the row's centre line crosses the edge, in pixels (NaN if horizontal); None
        with ``crossings=False`` (the batched fill needs only the bounds).
    """
    a, b = np.asarray(a), np.asarray(b)
    ax, ay = a[..., 0], a[..., 1]
    dx, dy = b[..., 0] - ax, b[..., 1] - ay
    K = dx * (y - ay)  # on this row, E = K - dy * (X - a.x)
    flat = dy == 0
    safe = np.where(flat, 1, dy)
    crossing = None
    if crossings:
        with np.errstate(over="ignore", invalid="ignore"):  # raw floats may be astronomically far
            crossing = np.where(flat, np.nan, (ax + K / safe) / float(unit))
    if exact:
        bias = np.where(top_left, 0, 1)  # on integers, E > 0 is E >= 1
        # dy > 0: E >= bias  <=>  X - a.x <= floor((K - bias) / dy)        (upper bound)
        # dy < 0: E >= bias  <=>  X - a.x >= ceil((K - bias) / dy)
        #                                  = -((K - bias) // -dy)          (lower bound)
        # so one floor division by |dy| serves both; units per pixel are a power of two,
        # so the division to columns is an (arithmetic, i.e. flooring) shift.
        q = (K - bias) // np.abs(safe)
        x_edge = np.where(dy > 0, ax + q, ax - q)
        shift = int(unit).bit_length() - 1
        hi = np.where(dy > 0, (x_edge - half) >> shift, NO_BOUND)
        lo = np.where(dy < 0, -((half - x_edge) >> shift), -NO_BOUND)
        ok = ~flat | (K >= bias)
    else:
        # Raw floats: the crossing, rounded, can disagree with how the half-plane method's
        # own rounding of E decides a tie (or be far off for astronomically distant
        # vertices). E is monotonic along a row even in floating point, so a bisection on
        # the very test the half-plane method evaluates, with the same operations, finds
        # the column where its verdict changes: both methods then agree on every pixel.
        def inside(j):
            with np.errstate(over="ignore", invalid="ignore"):
                e = K - dy * ((j * unit + half) - ax)
            return passes(e, top_left)

        shape = np.broadcast(K, dy, first_col, last_col).shape
        below = np.broadcast_to(np.asarray(first_col, dtype=np.int64) - 1, shape)
        above = np.broadcast_to(np.asarray(last_col, dtype=np.int64) + 1, shape)
        down = np.broadcast_to(dy > 0, shape)  # inside on the left: true, then false
        for _ in range(int(np.max(above - below, initial=1)).bit_length()):
            mid = (below + above) // 2
            if_inside = inside(mid) == down  # "mid is on the same side as `below`"
            below = np.where(if_inside & (above - below > 1), mid, below)
            above = np.where(~if_inside & (above - below > 1), mid, above)
        hi = np.where(dy > 0, below, NO_BOUND)
        lo = np.where(dy < 0, above, -NO_BOUND)
        ok = ~flat | passes(K, top_left)
    return lo, hi, ok, crossing


def _edge_index(i: int, j: int) -> int:
    """Index k of the oriented edge p_k -> p_(k+1) that joins vertices i and j."""
    return i if j == (i + 1) % 3 else j


def fill(setup: EdgeSetup, bbox: BBox, record: bool) -> tuple[np.ndarray, SpanTrace | None]:
    """Coverage of the bounding box (bbox-local bool array) and, if asked, the trace."""
    rows = bbox.rows()
    y = setup.centre_y(rows)  # one raster line per row of tested points (centres or a sample)
    # Sort by y (then x): v1 on top, v3 at the bottom (Ek, *Triangles and Perspective Correct Interpolation*, §1.1).
    v1, v2, v3 = np.lexsort((setup.p[:, 0], setup.p[:, 1]))
    long_edge, top_edge, bottom_edge = _edge_index(v1, v3), _edge_index(v1, v2), _edge_index(v2, v3)
    split_y = setup.p[v2, 1]
    # Rows above v2 belong to the flat-bottom triangle (v1, v2, v4): its span runs between
    # the long edge and the short top edge. Rows from v2 down belong to the flat-top one
    # (v2, v4, v3): between the long edge and the short bottom edge. On the split row itself
    # v2 lies on both short edges, so both are tested there.
    upper = y < split_y
    parts = (
        (upper, (long_edge, top_edge)),
        (~upper, (long_edge, bottom_edge)),
        (y == split_y, (top_edge,)),
    )
    if not setup.exact:
        # With raw floats, rounding can make the mathematically redundant third test fail
        # (far-away vertices cancel catastrophically), so every row gets all three, as in
        # the half-plane method: both then cover exactly the same pixels.
        parts = ((np.ones(len(rows), dtype=bool), (0, 1, 2)),)
    lo = np.full(len(rows), bbox.col0, dtype=np.int64)
    hi = np.full(len(rows), bbox.col1 - 1, dtype=np.int64)
    row_ok = np.ones(len(rows), dtype=bool)
    x_left = np.full(len(rows), -np.inf)
    x_right = np.full(len(rows), np.inf)
    for part, edges in parts:
        if not part.any():
            continue
        for k in edges:
            a, b = setup.p[k], setup.p[(k + 1) % 3]
            low, high, ok, crossing = edge_bounds(
                a, b, setup.top_left[k], y[part], setup.unit, setup.offset_x, setup.exact,
                first_col=bbox.col0, last_col=bbox.col1 - 1,
            )  # fmt: skip
            lo[part] = np.maximum(lo[part], low)
            hi[part] = np.minimum(hi[part], high)
            row_ok[part] &= ok  # a horizontal edge keeps or drops its whole row
            if b[1] < a[1]:  # going up: the left end of the span
                x_left[part] = np.maximum(x_left[part], crossing)
            elif b[1] > a[1]:
                x_right[part] = np.minimum(x_right[part], crossing)
    hi = np.where(row_ok, hi, lo - 1)  # a dropped row is an empty span
    cols = bbox.cols()
    covered = (cols[None, :] >= lo[:, None]) & (cols[None, :] <= hi[:, None])
    if not record:
        return covered, None
    return covered, _trace(setup, rows, y, lo, hi, x_left, x_right)


def _trace(setup, rows, y, lo, hi, x_left, x_right) -> SpanTrace:
    px = 1.0 / float(setup.unit)
    oriented = np.lexsort((setup.p[:, 0], setup.p[:, 1]))
    sorted_units = setup.p[oriented]
    sorted_xy = sorted_units.astype(np.float64) * px
    u4 = split_point(sorted_xy)
    v1, v2, v3 = sorted_xy
    v4 = None if u4 is None else np.array([u4, v2[1]])
    flat_bottom = None if v4 is None or v2[1] == v1[1] else np.stack([v1, v2, v4])
    flat_top = None if v4 is None or v3[1] == v2[1] else np.stack([v2, v4, v3])
    stop = np.maximum(lo, hi + 1)
    return SpanTrace(
        order=setup.perm[oriented],
        sorted_xy=sorted_xy,
        u4=u4,
        flat_bottom=flat_bottom,
        flat_top=flat_top,
        rows=rows,
        # the split row goes with the flat-top part, unless there is none (flat bottom)
        half=((y >= sorted_units[1, 1]) & (flat_top is not None)).astype(np.int8),
        x_left=x_left,
        x_right=x_right,
        col_start=lo,
        col_stop=stop,
    )
