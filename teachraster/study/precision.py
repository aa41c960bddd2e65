"""Cheaper and costlier ways of evaluating edge functions: the accuracy-vs-time study.

The core (:func:`teachraster.rasterize`) decides coverage one way only: vertices snapped to
1/256 px, edge functions in exact int64 arithmetic, each pixel's value computed directly
from a vertex. This module evaluates the *same* half-plane test (edge functions of the
CONVENTIONS, top-left tie rule) in the other arithmetics a rasteriser might use, so the
benchmark (:mod:`teachraster.study.bench`) and lesson 06 can measure what each one gets wrong and
what it costs. It is a study tool, not a second rasteriser: nothing in the core calls it.

Arithmetics (``arithmetic=``):

- ``"fixed8"``: snap to 1/256 px, int64 (exact; equals :func:`teachraster.rasterize`);
- ``"fixed4"``: snap to 1/16 px, int64 (exact on a coarser grid, as older GPUs did);
- ``"float64"``: snap to 1/256 px, then E in float64;
- ``"float32"``: snap to 1/256 px, then coordinates, differences and products in float32;
- ``"unsnapped"``: raw float64 positions, E in float64 (no grid at all).

Evaluations (``evaluation=``):

- ``"direct"``: E at each pixel centre from a vertex, ``dx (p.y - a.y) - dy (p.x - a.x)``,
  as the core does;
- ``"incremental"``: E at the first pixel of each row directly, then one addition of the
  per-pixel step ``-dy`` per pixel along the row, in the arithmetic's own number type (seed
  002's ``dx``/``dy`` stepping). Integer stepping is exact; floating-point stepping
  accumulates one rounding per pixel and drifts.

Every function takes an optional integer ``origin = (x0, y0)``: the image is the window of
pixels ``x0 <= x < x0 + width``, ``y0 <= y < y0 + height`` of an unbounded screen, and the
vertices are given in *absolute* screen pixels. The arithmetic sees absolute coordinates
(pixel centres at ``x0 + j + 0.5``), so a mesh at 1e5 px is evaluated with 1e5-sized
numbers, as a rasteriser with no window-relative set-up would. For the exact (integer)
arithmetics this changes nothing: subtracting a whole number of pixels is exact, so they
give the same pixels as :func:`teachraster.rasterize` on ``xy - origin``.

>>> xy = [[0.3, 0.2], [7.9, 1.1], [2.2, 6.7]]
>>> a = coverage(xy, 8, 8, "fixed8")
>>> bool((a == coverage(xy, 8, 8, "float32", "incremental")).all())    # small: all agree
True
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.snapping import to_units
from ..core.validate import as_size

ARITHMETICS = ("fixed8", "fixed4", "float64", "float32", "unsnapped")
EVALUATIONS = ("direct", "incremental")

#: Sub-pixel bits of the snapped arithmetics (None: raw positions).
BITS = {"fixed8": 8, "fixed4": 4, "float64": 8, "float32": 8, "unsnapped": None}
#: Number type in which each arithmetic computes edge functions.
DTYPES = {
    "fixed8": np.int64,
    "fixed4": np.int64,
    "float64": np.float64,
    "float32": np.float32,
    "unsnapped": np.float64,
}


@dataclass(frozen=True)
class _Setup:
    """A triangle prepared in one arithmetic: oriented vertices and per-edge tie rules.

    ``p`` holds the vertices in the arithmetic's number type (int64 units of
    ``1 / unit`` px for fixed point, pixels otherwise), reordered so that the triangle's
    signed area, *as computed in that arithmetic*, is positive.
    """

    p: np.ndarray  # (3, 2) oriented vertices
    top_left: np.ndarray  # (3,) bool
    empty: bool  # zero area in this arithmetic: covers nothing
    unit: int  # internal units per pixel (1 for the float arithmetics)
    dtype: type


def _check(arithmetic: str, evaluation: str) -> None:
    if arithmetic not in ARITHMETICS:
        raise ValueError(f"arithmetic must be one of {ARITHMETICS}, got {arithmetic!r}")
    if evaluation not in EVALUATIONS:
        raise ValueError(f"evaluation must be one of {EVALUATIONS}, got {evaluation!r}")


def _check_window(width, height, origin) -> tuple[int, int, int, int]:
    width, height = as_size("width", width), as_size("height", height)
    ox, oy = origin
    if int(ox) != ox or int(oy) != oy:
        raise ValueError(f"origin must be whole pixels, got {origin!r}")
    return width, height, int(ox), int(oy)


def _as_xy(xy) -> np.ndarray:
    arr = np.asarray(xy, dtype=np.float64)
    if arr.shape != (3, 2):
        raise ValueError(f"xy must have shape (3, 2), got {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError("xy contains NaN or infinity")
    return arr


def _setup(xy: np.ndarray, arithmetic: str) -> _Setup:
    """Convert, orient and classify one triangle's edges in ``arithmetic``."""
    bits, dtype = BITS[arithmetic], DTYPES[arithmetic]
    if dtype is np.int64:
        # Units of 1 / 2**(bits + 1) px: pixel centres are integers too (see snapping).
        v, unit = to_units(xy, bits), 2 ** (bits + 1)
    else:
        # Snap in float64 (exact: power-of-two scaling, round half to even), then round
        # once to the working type: float32 loses the low bits of big coordinates here.
        v = xy if bits is None else np.rint(xy * 2.0**bits) / 2.0**bits
        v, unit = v.astype(dtype), 1
    (ax, ay), (bx, by), (cx, cy) = v
    # The winding, too, is decided in the working arithmetic: in float32 a sliver's area can
    # round to zero or change sign, and a real rasteriser would then act on that.
    area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    p = v[[0, 2, 1]] if area2 < 0 else v
    top_left = np.array(
        [
            bool(p[(k + 1) % 3, 1] < p[k, 1])
            or bool(p[(k + 1) % 3, 1] == p[k, 1] and p[(k + 1) % 3, 0] > p[k, 0])
            for k in range(3)
        ]
    )
    return _Setup(p=p, top_left=top_left, empty=bool(area2 == 0), unit=unit, dtype=dtype)


def _checked_setup(xy, width, height, arithmetic, evaluation, origin):
    """Every argument checked (in this order), then the triangle set up: how the public
    functions (through :func:`_local_coverage`, or :func:`edge_values` directly) start.

    Returns ``(setup, width, height, ox, oy)``.
    """
    _check(arithmetic, evaluation)
    width, height, ox, oy = _check_window(width, height, origin)
    return _setup(_as_xy(xy), arithmetic), width, height, ox, oy


def _centres(setup: _Setup, index: np.ndarray) -> np.ndarray:
    """Absolute pixel-centre coordinates of pixel indices, in the arithmetic's type."""
    if setup.dtype is np.int64:
        return index.astype(np.int64) * setup.unit + setup.unit // 2
    # index + 0.5 is exact in float64; the cast rounds it as a float32 rasteriser would.
    return (index + 0.5).astype(setup.dtype)


def _edge_values(setup: _Setup, k: int, rows: np.ndarray, cols: np.ndarray, evaluation: str):
    """E_k over the grid ``rows`` x ``cols`` (absolute indices), in the arithmetic's type."""
    a, b = setup.p[k], setup.p[(k + 1) % 3]
    dx, dy = b[0] - a[0], b[1] - a[1]  # differences in the working type
    ys = _centres(setup, rows) - a[1]
    xs = _centres(setup, cols) - a[0]
    if evaluation == "direct":
        # dx * ys is one product per row and dy * xs one per column, but each pixel's value
        # is still the direct formula's: the same two products and one subtraction.
        return dx * ys[:, None] - dy * xs[None, :]
    # Incremental: the row's first value directly, then E(x + 1) = E(x) - dy, one rounding
    # per pixel. np.add.accumulate runs left to right in the array's own type, exactly the
    # sequence of additions of a scalar loop.
    grid = np.empty((len(rows), len(cols)), dtype=setup.dtype)
    if grid.size == 0:
        return grid
    grid[:, 0] = dx * ys - dy * xs[0]
    grid[:, 1:] = -dy * setup.unit  # one pixel is `unit` internal units (1 for floats)
    return np.add.accumulate(grid, axis=1, dtype=setup.dtype)


def _inside(setup: _Setup, k: int, e: np.ndarray) -> np.ndarray:
    """The same tie-aware test in every arithmetic: E > 0, or E == 0 on a top-left edge."""
    return e >= 0 if setup.top_left[k] else e > 0


def _bbox(setup: _Setup, width: int, height: int, ox: int, oy: int):
    """Absolute row and column indices whose centres lie in the vertex bounding box."""
    # Float64 holds every vertex of every arithmetic exactly (int64 units are below 2**30),
    # so this box is the exact box of the vertices the arithmetic works with.
    v = setup.p.astype(np.float64) / setup.unit
    lo, hi = v.min(axis=0), v.max(axis=0)
    c0 = max(int(np.ceil(lo[0] - 0.5)), ox)
    c1 = min(int(np.floor(hi[0] - 0.5)) + 1, ox + width)
    r0 = max(int(np.ceil(lo[1] - 0.5)), oy)
    r1 = min(int(np.floor(hi[1] - 0.5)) + 1, oy + height)
    return np.arange(r0, max(r0, r1)), np.arange(c0, max(c0, c1))


def _local_coverage(xy, width, height, arithmetic, evaluation, origin):
    """Coverage of the bounding box and where it sits in the window (row0, col0)."""
    setup, width, height, ox, oy = _checked_setup(xy, width, height, arithmetic, evaluation, origin)
    rows, cols = _bbox(setup, width, height, ox, oy)
    covered = np.zeros((len(rows), len(cols)), dtype=bool)
    if setup.empty or covered.size == 0:
        return covered, 0, 0
    covered[:] = True
    for k in range(3):
        covered &= _inside(setup, k, _edge_values(setup, k, rows, cols, evaluation))
    return covered, int(rows[0]) - oy, int(cols[0]) - ox


def coverage(
    xy,
    width: int,
    height: int,
    arithmetic: str = "fixed8",
    evaluation: str = "direct",
    origin=(0, 0),
) -> np.ndarray:
    """Half-plane coverage of one triangle, with edge functions in a chosen arithmetic.

    Parameters
    ----------
    xy : (3, 2) array-like
        Vertex positions in absolute screen pixels (x right, y down; CONVENTIONS).
    width, height : int
        Size of the image window.
    arithmetic : {"fixed8", "fixed4", "float64", "float32", "unsnapped"}
        How positions are stored and E is computed (see the module docstring).
    evaluation : {"direct", "incremental"}
        E per pixel from a vertex, or stepped along each row by ``-dy``.
    origin : (int, int)
        Absolute pixel position of the window's top-left pixel.

    Returns
    -------
    (height, width) bool
        Pixels whose centres pass all three edge tests (top-left rule for ties). Only
        centres inside the bounding box of the (converted) vertices are tested, as in the
        core; the incremental walk starts at the box's first column on every row.

    Examples
    --------
    >>> coverage([[0, 0], [4, 0], [0, 4]], 4, 4).astype(int)
    array([[1, 1, 1, 0],
           [1, 1, 0, 0],
           [1, 0, 0, 0],
           [0, 0, 0, 0]])
    >>> far = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]) + 1e5     # same, 1e5 px away
    >>> bool((coverage(far, 4, 4, "fixed8", origin=(100000, 100000))
    ...       == coverage([[0, 0], [4, 0], [0, 4]], 4, 4)).all())
    True
    """
    local, r0, c0 = _local_coverage(xy, width, height, arithmetic, evaluation, origin)
    out = np.zeros((height, width), dtype=bool)
    out[r0 : r0 + local.shape[0], c0 : c0 + local.shape[1]] = local
    return out


def edge_values(
    xy,
    width: int,
    height: int,
    arithmetic: str = "fixed8",
    evaluation: str = "direct",
    origin=(0, 0),
) -> np.ndarray:
    """The three edge functions over the whole window, in px², as computed in ``arithmetic``.

    For showing drift: unlike :func:`coverage`, the incremental walk starts at the window's
    first column (not the bounding box's), so the error can be plotted against the number of
    steps taken. Values are converted to float64 px² after being computed (the conversion
    is exact for the float arithmetics).

    Returns
    -------
    (3, height, width) float64
        E_k for the edges of the oriented triangle (positive inside); all zeros for a
        triangle of zero area in this arithmetic.

    Examples
    --------
    >>> e = edge_values([[0, 0], [4, 0], [0, 4]], 2, 1)
    >>> e[:, 0, 0]                      # at (0.5, 0.5): 4 * 0.5, 4 * 3, 4 * 0.5
    array([ 2., 12.,  2.])
    """
    setup, width, height, ox, oy = _checked_setup(xy, width, height, arithmetic, evaluation, origin)
    out = np.zeros((3, height, width))
    if setup.empty:
        return out
    rows, cols = np.arange(oy, oy + height), np.arange(ox, ox + width)
    for k in range(3):
        out[k] = _edge_values(setup, k, rows, cols, evaluation).astype(np.float64)
    return out / float(setup.unit) ** 2


def mesh_coverage_counts(
    triangles_xy,
    width: int,
    height: int,
    arithmetic: str = "fixed8",
    evaluation: str = "direct",
    origin=(0, 0),
) -> np.ndarray:
    """How many triangles of a mesh cover each pixel centre.

    On a watertight mesh every pixel centre inside the mesh must be covered exactly once:
    a 0 inside is a *gap* (a crack along a shared edge), a value above 1 a *double hit*
    (a pixel drawn twice, visible with blending).

    Parameters
    ----------
    triangles_xy : (N, 3, 2) array-like
        The mesh's triangles, absolute screen pixels.
    width, height, arithmetic, evaluation, origin
        As for :func:`coverage`.

    Returns
    -------
    (height, width) int32

    Examples
    --------
    >>> square = [[[0, 0], [4, 0], [0, 4]], [[4, 0], [4, 4], [0, 4]]]
    >>> int(mesh_coverage_counts(square, 4, 4).max())       # the diagonal is drawn once
    1
    """
    tris = np.asarray(triangles_xy, dtype=np.float64)
    if tris.ndim != 3 or tris.shape[1:] != (3, 2):
        raise ValueError(f"triangles_xy must have shape (N, 3, 2), got {tris.shape}")
    counts = np.zeros((height, width), dtype=np.int32)
    for xy in tris:
        local, r0, c0 = _local_coverage(xy, width, height, arithmetic, evaluation, origin)
        counts[r0 : r0 + local.shape[0], c0 : c0 + local.shape[1]] += local
    return counts


@dataclass(frozen=True)
class WrongRegions:
    """Where a walk in narrow registers got pixels wrong (:func:`wrong_regions`).

    Attributes
    ----------
    wrongly_in, wrongly_out : int
        Pixels accepted outside the triangle, and rejected inside it.
    near : int
        Wrong pixels whose centre lies within ``near_px`` px of an edge's line.
    near_px : float
    sides : dict
        The pixel sides between a wrong pixel and a right one (4-neighbours), by where they
        lie, each side counted once under the first that applies: ``"box"`` (one of the two
        pixels lies outside the bounding box, where the walk writes nothing), ``"edge"`` (an
        edge's value changes sign between the two centres: the triangle's own edge),
        ``"wrap"`` (an edge's value passes a nonzero multiple of ``2**(int_bits - 1)``, where
        the register's sign flips: a line parallel to that edge), ``"block"`` (on a boundary
        of the smallest blocks: a block misjudged at its corners) and ``"other"``.
    outside, outside_past : int
        Pixel centres inside the bounding box but outside the triangle, and those of them where
        some edge's exact value lies below ``-2**(int_bits - 1)``: only these can wrap to a
        positive value and come out wrongly in.
    inside, inside_past : int
        Centres the exact walk covers, and those where some edge's value reaches
        ``2**(int_bits - 1)``: only these can wrap to a negative one and come out wrongly out.
    peak : float
        The largest edge value at a covered centre, in units of ``2**(int_bits - 1)``.
    """

    wrongly_in: int
    wrongly_out: int
    near: int
    near_px: float
    sides: dict
    outside: int = 0
    outside_past: int = 0
    inside: int = 0
    inside_past: int = 0
    peak: float = 0.0

    @property
    def wrong(self) -> int:
        """All the wrong pixels."""
        return self.wrongly_in + self.wrongly_out


def _crosses(e: np.ndarray, step: float, axis: int) -> tuple[np.ndarray, np.ndarray]:
    """Between 4-neighbours along ``axis`` (one row or column apart): does some edge's value
    change sign, and does it pass a nonzero multiple of ``step``?"""
    a = e.take(np.arange(e.shape[axis + 1] - 1), axis=axis + 1)
    b = e.take(np.arange(1, e.shape[axis + 1]), axis=axis + 1)
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    sign = ((a < 0) != (b < 0)).any(axis=0)
    # the multiples k * step with lo < k * step <= hi: some k other than 0
    first, last = np.floor(lo / step) + 1, np.floor(hi / step)
    wrap = ((first <= last) & ~((first == 0) & (last == 0))).any(axis=0)
    return sign, wrap


def wrong_regions(xy, narrow, *, near_px: float = 2.0, block: int = 4) -> WrongRegions:
    """Where the pixels of a narrow walk (:func:`teachraster.core.fixed_point.narrow_fill`)
    went wrong: inside or outside, near an edge or not, and what the wrong regions' sides
    follow (lesson 10 §4).

    A value stepped in an ``n``-bit register is the exact one modulo ``2**n`` (additions
    wrap, they do not round), so its sign flips where the exact value passes a multiple of
    ``2**(n - 1)``: along lines parallel to the edge. The exact values come from
    :func:`edge_values` (exact px² on the snapped grid), scaled to ``narrow.budget``'s units.

    >>> import teachraster as tr
    >>> from teachraster.core import fixed_point
    >>> big = tr.Triangle([[3.2, 6.4], [312.6, 18.8], [62.8, 312.6]])
    >>> fill = fixed_point.narrow_fill(big, 320, 320, int_bits=32, block_sizes=(16, 4),
    ...                                centre_bit=False)
    >>> found = wrong_regions(big.xy, fill)
    >>> found.wrong == int(fill.wrong.sum()), found.wrongly_out > found.wrongly_in
    (True, True)
    """
    xy = _as_xy(xy)
    height, width = narrow.coverage.shape
    budget = narrow.budget
    e = edge_values(xy, width, height) * float(budget.units_per_pixel) ** 2  # exact, units²
    wrong = narrow.wrong
    setup = _setup(xy, "fixed8")  # the snapped vertices, as the walk has them
    rows, cols = _bbox(setup, width, height, 0, 0)
    box = np.zeros((height, width), dtype=bool)
    box[rows[:, None], cols[None, :]] = True
    p = setup.p.astype(np.float64) / setup.unit
    lengths = np.hypot(*(np.roll(p, -1, axis=0) - p).T)  # edge k runs from p[k] to p[k + 1]
    distance = (np.abs(e) / budget.units_per_pixel**2 / lengths[:, None, None]).min(axis=0)
    sides = dict.fromkeys(("box", "edge", "wrap", "block", "other"), 0)
    for axis in (0, 1):
        keep = np.arange(wrong.shape[axis] - 1)
        side = wrong.take(keep, axis=axis) != wrong.take(keep + 1, axis=axis)
        outside = box.take(keep, axis=axis) != box.take(keep + 1, axis=axis)
        sign, wrap = _crosses(e, 2.0 ** (budget.int_bits - 1), axis)
        on_block = np.expand_dims((keep + 1) % block == 0, 1 - axis)
        left = side.copy()
        for name, where in (("box", outside), ("edge", sign), ("wrap", wrap),
                            ("block", on_block), ("other", True)):  # fmt: skip
            hit = left & where
            sides[name] += int(hit.sum())
            left &= ~hit
    # magnitude: a sign flips only where a value passes 2**(n - 1); outside, the walk stops at
    # the box, so only the box's centres count
    half = 2.0 ** (budget.int_bits - 1)
    outside, inside = box & ~narrow.exact, narrow.exact
    return WrongRegions(
        wrongly_in=int((narrow.coverage & ~narrow.exact).sum()),
        wrongly_out=int((narrow.exact & ~narrow.coverage).sum()),
        near=int((wrong & (distance <= near_px)).sum()),
        near_px=float(near_px),
        sides=sides,
        outside=int(outside.sum()),
        outside_past=int((outside & (e < -half).any(axis=0)).sum()),
        inside=int(inside.sum()),
        inside_past=int((inside & (e >= half).any(axis=0)).sum()),
        peak=float(e[:, inside].max() / half) if inside.any() else 0.0,
    )
