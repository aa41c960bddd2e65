"""Tiled fill: classify whole blocks by their corners, test pixels only where an edge passes.

The half-plane fill tests every pixel centre of the bounding box; about half of them lie
outside the triangle. A hierarchical walker (Pineda's edge functions as Mesa's llvmpipe uses
them, ``lp_rast_tri.c``, with blocks of 64, 16 and 4 pixels) tests *blocks*:

- an edge function is affine, so over the pixel centres of a rectangle it is largest at one
  corner and smallest at the opposite one; which corner depends only on the signs of the
  edge's two gradients (the *corner trick*, decided once per triangle);
- **rejected**: one edge excludes even its largest corner: no centre of the block is
  covered;
- **accepted**: every edge includes even its smallest corner: every centre is covered, and
  the block is filled with no per-pixel test;
- **partial** otherwise: its children (the next block size, clipped to the image) are
  classified the same way, and a partial block of the smallest size is tested pixel by
  pixel.

The corner tests use the one top-left rule, :meth:`EdgeSetup.inside`: a threshold on E
(``E >= 0`` or ``E > 0``), so "both extreme corners pass" implies "every centre passes" and
the coverage is exactly the half-plane coverage.

**Fixed-point stepping.** On the snapped grid E is an integer. The walker evaluates E once
per top-level block (at its first pixel centre) and from then on only *adds* integer
increments, precomputed once per triangle: to reach a child's first centre (a q × q table
per level), the block's extreme corners, and each pixel of a smallest block (an s × s
table), as llvmpipe's ``plane->step`` tables do. Unsnapped floats cannot step without
drift, so for ``subpixel_bits=None`` every value is evaluated directly with the half-plane
fill's own formula (still exact coverage: the float formula is monotone along rows and
columns). :mod:`teachraster.core.fixed_point` computes the bit budget.

Every level is one set of numpy operations over all of its blocks; nothing loops over
pixels in Python.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .bbox import BBox
from .edges import EdgeSetup
from .tile_trace import (
    ACCEPTED,
    BLOCK_SIZES,
    PARTIAL,
    REJECTED,
    BlockCounters,
    TileTrace,
    depth_first,
)
from .tile_trace import check_block_sizes as check_block_sizes


@dataclass
class _Level:
    """The blocks of one size (internal, breadth-first): positions, values, verdicts."""

    size: int
    row: np.ndarray
    col: np.ndarray
    extent: np.ndarray  # (n, 2) rows, cols inside the image
    parent: np.ndarray  # index into the level above, -1 at the top
    sibling: np.ndarray  # (n, 2) position among its siblings
    e0: np.ndarray | None  # (n, 3) E at the first pixel centre (exact stepping only)
    kind: np.ndarray | None = None
    e_max: np.ndarray | None = None
    e_min: np.ndarray | None = None
    rejected_by: np.ndarray | None = None
    crossing: np.ndarray | None = None
    covered: np.ndarray | None = None


class _Stepper:
    """Per-triangle constants of the walk: E's increments (exact) or its row/col terms."""

    def __init__(self, setup: EdgeSetup, rows: np.ndarray, cols: np.ndarray, dtype=None):
        self.setup, self.dtype = setup, dtype
        p, unit = setup.p, setup.unit
        d = np.roll(p, -1, axis=0) - p  # (3, 2) edge vectors b - a
        # E(row + 1) - E(row) = dx * unit, E(col + 1) - E(col) = -dy * unit: exact integers
        self.down = d[:, 0] * unit
        self.right = -d[:, 1] * unit
        self.base = (int(rows[0]), int(cols[0])) if len(rows) else (0, 0)
        # Row and column terms over every pixel of the top-level blocks, as the half-plane
        # fill computes them (E = row_term - col_term): used for the exact first values and
        # for every value in raw floats.
        self.terms = [setup.edge_terms(k, rows, cols) for k in range(3)]

    def direct(self, k: int, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        """E_k at pixel centres (rows, cols), evaluated (broadcasting), no stepping."""
        row_term, col_term = self.terms[k]
        # Pixels past the image (in blocks cut by its border) are masked out by the caller;
        # clamping keeps their index inside the terms, which stop at the image.
        r = np.minimum(rows - self.base[0], len(row_term) - 1)
        c = np.minimum(cols - self.base[1], len(col_term) - 1)
        return row_term[r] - col_term[c]

    def steps(self, drow: np.ndarray, dcol: np.ndarray) -> np.ndarray:
        """(..., 3) table of increments from a centre to the centre ``(drow, dcol)`` away."""
        return self.wrap(drow[..., None] * self.down + dcol[..., None] * self.right)

    def wrap(self, values: np.ndarray) -> np.ndarray:
        """Values as a ``dtype``-bit register holds them (wrapping silently), if one was set.

        Addition and multiplication modulo 2**bits commute with the cast, so wrapping the
        exact int64 results at each step gives what a narrower adder computes throughout
        (see :mod:`.fixed_point`). Without ``dtype`` this is the identity (exact int64).
        """
        if self.dtype is None or not self.setup.exact:
            return values
        return np.asarray(values).astype(self.dtype)


def fill(
    setup: EdgeSetup,
    bbox: BBox,
    record: bool,
    *,
    block_sizes=BLOCK_SIZES,
    image: tuple[int, int] | None = None,
    dtype=None,
) -> tuple[np.ndarray, TileTrace | None]:
    """Coverage of the bounding box (bbox-local bool array) and, if asked, the trace.

    ``image`` is ``(height, width)``: blocks are clipped to the image, not to the box
    (default: the box's far corner, for callers that fill a window). ``dtype`` (e.g.
    ``np.int32``) makes the snapped walk step in that integer width, wrapping on overflow
    as hardware registers do: only for :func:`.fixed_point.narrow_fill`'s demonstration.
    """
    sizes = check_block_sizes(block_sizes)
    height, width = (bbox.row1, bbox.col1) if image is None else image
    local = np.zeros(bbox.shape, dtype=bool)
    levels: list[_Level] = []
    grids: list[tuple[int, int]] = []
    if bbox.size and setup.area2 != 0:  # a zero-area triangle classifies no block
        top, grid, stepper = _top_level(setup, bbox, sizes[0], (height, width), dtype)
        canvas = _Canvas(stepper.base, grid, sizes, (height, width))
        grids.append(grid)
        level = top
        for depth, size in enumerate(sizes):
            _classify(level, stepper)
            canvas.accept(level)
            levels.append(level)
            partial = np.flatnonzero(level.kind == PARTIAL)
            if depth == len(sizes) - 1:
                _test_pixels(canvas, level, partial, stepper)
                break
            q = size // sizes[depth + 1]
            grids.append((q, q))
            level = _children(level, partial, sizes[depth + 1], (height, width), stepper)
        local = canvas.crop(bbox)
        for upper, lower in zip(levels[-2::-1], levels[:0:-1]):  # bottom-up: partial totals
            np.add.at(upper.covered, lower.parent, lower.covered)
    if not record:
        return local, None
    return local, _trace(levels, sizes, tuple(grids), setup, _counters(levels, sizes))


def _top_level(setup: EdgeSetup, box: BBox, size: int, image: tuple[int, int], dtype=None):
    """The blocks of the largest size on the image grid that overlap the bounding box."""
    gr0, gr1 = box.row0 // size, (box.row1 - 1) // size + 1
    gc0, gc1 = box.col0 // size, (box.col1 - 1) // size + 1
    # Only the rows and columns inside the image: a block larger than the image costs what
    # the image costs, not size² (every corner and pixel the walk visits lies in the image).
    rows = np.arange(gr0 * size, min(gr1 * size, image[0]))
    cols = np.arange(gc0 * size, min(gc1 * size, image[1]))
    stepper = _Stepper(setup, rows, cols, dtype)
    bi, bj = np.indices((gr1 - gr0, gc1 - gc0)).reshape(2, -1)
    row, col = (gr0 + bi) * size, (gc0 + bj) * size
    e0 = None
    if setup.exact:  # the only evaluation of E; every later value is stepped from these
        e0 = stepper.wrap(np.stack([stepper.direct(k, row, col) for k in range(3)], axis=1))
    level = _Level(
        size, row, col, _extent(row, col, size, image), np.full(len(row), -1),
        np.stack([bi, bj], axis=1), e0,
    )  # fmt: skip
    return level, (gr1 - gr0, gc1 - gc0), stepper


def _extent(row, col, size, image) -> np.ndarray:
    height, width = image
    return np.stack([np.minimum(size, height - row), np.minimum(size, width - col)], axis=1)


def _classify(level: _Level, stepper: _Stepper) -> None:
    """Rejected / accepted / partial for every block of the level at once."""
    setup, n = stepper.setup, len(level.row)
    last = level.extent - 1  # (n, 2) offsets of the far row and column
    # The corner trick: per edge, the corner where E is largest (smallest) follows from the
    # signs of its row and column increments alone.
    go_down_max = stepper.down > 0
    go_right_max = stepper.right > 0
    rows_max = np.where(go_down_max, last[:, :1], 0)  # (n, 3) row offset of each edge's max
    cols_max = np.where(go_right_max, last[:, 1:], 0)
    rows_min = np.where(stepper.down < 0, last[:, :1], 0)
    cols_min = np.where(stepper.right < 0, last[:, 1:], 0)
    if level.e0 is not None:  # exact: corner = first centre + integer increments
        e_max = stepper.wrap(level.e0 + rows_max * stepper.down + cols_max * stepper.right)
        e_min = stepper.wrap(level.e0 + rows_min * stepper.down + cols_min * stepper.right)
    else:
        e_max, e_min = np.empty((n, 3)), np.empty((n, 3))
        for k in range(3):
            e_max[:, k] = stepper.direct(k, level.row + rows_max[:, k], level.col + cols_max[:, k])
            e_min[:, k] = stepper.direct(k, level.row + rows_min[:, k], level.col + cols_min[:, k])
    pass_max = np.stack([setup.inside(k, e_max[:, k]) for k in range(3)], axis=1)
    pass_min = np.stack([setup.inside(k, e_min[:, k]) for k in range(3)], axis=1)
    rejected = ~pass_max.all(axis=1)
    accepted = pass_min.all(axis=1) & ~rejected
    level.kind = np.where(rejected, REJECTED, np.where(accepted, ACCEPTED, PARTIAL)).astype(np.int8)
    level.rejected_by = np.where(rejected, np.argmin(pass_max, axis=1), -1).astype(np.int8)
    level.crossing = pass_max & ~pass_min  # the edge passes one corner and fails another
    level.e_max, level.e_min = e_max, e_min
    level.covered = np.where(accepted, level.extent[:, 0] * level.extent[:, 1], 0)


def _children(level: _Level, partial: np.ndarray, size: int, image, stepper) -> _Level:
    """The next-size blocks of every partial block, dropping those outside the image."""
    q = level.size // size
    # Children beyond the image are dropped below; never make more than the image can hold
    # (q² children of a block far larger than the image would cost size², not the image).
    qr, qc = min(q, -(-image[0] // size)), min(q, -(-image[1] // size))
    di, dj = np.indices((qr, qc)).reshape(2, -1)
    row = (level.row[partial, None] + di * size).ravel()
    col = (level.col[partial, None] + dj * size).ravel()
    parent = np.repeat(partial, qr * qc)
    sibling = np.tile(np.stack([di, dj], axis=1), (len(partial), 1))
    e0 = None
    if level.e0 is not None:  # child's first centre = parent's + a per-level table
        table = stepper.steps(di * size, dj * size)  # (q*q, 3), once per level
        e0 = stepper.wrap(level.e0[partial, None, :] + table[None]).reshape(-1, 3)
    keep = (row < image[0]) & (col < image[1])
    return _Level(
        size, row[keep], col[keep], _extent(row[keep], col[keep], size, image), parent[keep],
        sibling[keep], None if e0 is None else e0[keep],
    )  # fmt: skip


class _Canvas:
    """Coverage over the top-level blocks, cut at the image: accepted blocks marked as cells
    (one mark per cell, not per pixel), tested pixels as pixels; merged once."""

    def __init__(self, base: tuple[int, int], grid, sizes, image: tuple[int, int]):
        self.base = base
        self.cell = _cell_size(sizes[-1])
        c = self.cell
        # The canvas ends at the image (rounded up to a whole cell), whatever the block size.
        shape = [min(g * sizes[0], -(-n // c) * c - b) for g, n, b in zip(grid, image, base)]
        self.pixels = np.zeros(shape, dtype=bool)
        self.cells = np.zeros((shape[0] // c, shape[1] // c), dtype=bool)

    def accept(self, level: _Level) -> None:
        """Mark every accepted block of the level (all its cells inside the canvas at once)."""
        acc = level.kind == ACCEPTED
        if not acc.any():
            return
        reach = int(level.extent[acc].max())  # a block's cells beyond the image are not drawn
        d = np.arange(min(level.size, -(-reach // self.cell) * self.cell) // self.cell)
        i0 = (level.row[acc] - self.base[0]) // self.cell
        j0 = (level.col[acc] - self.base[1]) // self.cell
        # Clamping to the canvas's last cell marks a cell of the same block (the block reaches
        # the image border there), so blocks cut by the border stay exact.
        ii = np.minimum(i0[:, None, None] + d[:, None], self.cells.shape[0] - 1)
        jj = np.minimum(j0[:, None, None] + d, self.cells.shape[1] - 1)
        self.cells[ii, jj] = True

    def set_pixels(self, rows: np.ndarray, cols: np.ndarray) -> None:
        self.pixels[rows - self.base[0], cols - self.base[1]] = True

    def crop(self, box: BBox) -> np.ndarray:
        """The bbox-local coverage: cells spread to their pixels (one broadcast), cropped."""
        (r, c), s = self.cells.shape, self.cell
        self.pixels.reshape(r, s, c, s)[...] |= self.cells[:, None, :, None]
        r0, c0 = box.row0 - self.base[0], box.col0 - self.base[1]
        # Accepted blocks and covered pixels lie inside the triangle, hence inside the box.
        return self.pixels[r0 : r0 + box.shape[0], c0 : c0 + box.shape[1]].copy()


def _test_pixels(canvas: _Canvas, level: _Level, partial: np.ndarray, stepper) -> None:
    """Pixel by pixel in the partial blocks of the smallest size (per edge, all blocks)."""
    s, setup = level.size, stepper.setup
    ext = level.extent[partial]
    # Pixels beyond the image are never tested: the table spans the largest extent only.
    sr, sc = (min(s, int(ext[:, i].max(initial=1))) for i in (0, 1))
    dr, dc = np.indices((sr, sc))
    covered = (dr < ext[:, :1, None]) & (dc < ext[:, 1:, None])  # (n, s, s) inside the image
    rows = level.row[partial, None] + np.arange(sr)  # (n, sr)
    cols = level.col[partial, None] + np.arange(sc)
    table = stepper.steps(dr, dc)  # (s, s, 3) increments from the first centre, once
    for k in range(3):
        if level.e0 is not None:  # exact: one addition per pixel
            e = stepper.wrap(level.e0[partial, k, None, None] + table[None, :, :, k])
        else:
            e = stepper.direct(k, rows[:, :, None], cols[:, None, :])
        covered &= setup.inside(k, e)
    n, a, b = np.nonzero(covered)
    canvas.set_pixels(level.row[partial][n] + a, level.col[partial][n] + b)
    level.covered[partial] = covered.sum(axis=(1, 2))


def _cell_size(smallest: int) -> int:
    """The canvas's cell: the smallest block size, or its largest divisor up to 64 when it is
    larger (cells only mark accepted blocks; any divisor of every size works)."""
    return max(c for c in range(1, min(smallest, 64) + 1) if smallest % c == 0)


def _counters(levels: list[_Level], sizes) -> BlockCounters:
    """The walker's own counts, per size (a size never reached counts zero).

    A 1×1 block's corner test *is* the pixel test: when the smallest size is 1, every block
    of that size counts as a pixel test, and the pixels it accepts are not "filled with no
    test"."""
    counts = [np.bincount(lv.kind, minlength=3) for lv in levels]
    counts += [np.zeros(3, dtype=np.int64)] * (len(sizes) - len(levels))
    last = levels[-1] if len(levels) == len(sizes) else None
    smallest = np.zeros(0, dtype=bool) if last is None else last.kind == PARTIAL
    tested = smallest if last is None or sizes[-1] > 1 else np.ones(len(last.kind), dtype=bool)
    untested = [lv for lv in levels if lv.size > 1]
    return BlockCounters(
        sizes=sizes,
        empty=tuple(int(c[REJECTED]) for c in counts),
        full=tuple(int(c[ACCEPTED]) for c in counts),
        partial=tuple(int(c[PARTIAL]) for c in counts),
        pixel_tests=0 if last is None else int(np.prod(last.extent[tested], axis=1).sum()),
        non_empty=0 if last is None else int((last.covered[smallest] > 0).sum()),
        pixels_accepted=int(
            sum(np.prod(lv.extent[lv.kind == ACCEPTED], axis=1).sum() for lv in untested)
        ),
    )


def _empty_level(size: int, dtype) -> _Level:
    none, pairs = np.zeros(0, np.int64), np.zeros((0, 2), np.int64)
    level = _Level(size, none, none, pairs, none, pairs, None, np.zeros(0, np.int8))
    level.e_max = level.e_min = np.zeros((0, 3), dtype)
    level.rejected_by, level.covered = np.zeros(0, np.int8), none
    level.crossing = np.zeros((0, 3), dtype=bool)
    return level


def _trace(levels: list[_Level], sizes, grids, setup: EdgeSetup, counters) -> TileTrace:
    """Concatenate the levels and put every block in depth-first (scanline) visit order."""
    if not levels:  # nothing classified: empty arrays of the right shapes and types
        levels, grids = [_empty_level(sizes[0], setup.p.dtype)], grids or ((0, 0),)
    offsets = np.cumsum([0] + [len(lv.row) for lv in levels])
    level = np.concatenate([np.full(len(lv.row), i, np.int8) for i, lv in enumerate(levels)])
    parent = np.concatenate(
        [np.where(lv.parent >= 0, lv.parent + offsets[max(i - 1, 0)], -1) for i, lv in enumerate(levels)]
    )  # fmt: skip

    def cat(name):
        return np.concatenate([getattr(lv, name) for lv in levels])

    sibling = cat("sibling")
    ncols = np.array([g[1] for g in grids], dtype=np.int64)[level]
    order = depth_first(parent, level, sibling[:, 0] * ncols + sibling[:, 1])
    new = np.empty_like(order)
    new[order] = np.arange(len(order))
    return TileTrace(
        block_sizes=sizes,
        size=np.array(sizes, dtype=np.int64)[level][order],
        row=cat("row")[order],
        col=cat("col")[order],
        kind_code=cat("kind").astype(np.int8)[order],
        level=level[order],
        parent=np.where(parent[order] >= 0, new[np.maximum(parent[order], 0)], -1),
        extent=cat("extent")[order],
        e_max=cat("e_max")[order],
        e_min=cat("e_min")[order],
        covered=cat("covered")[order],
        counters=counters,
        px2_per_unit2=setup.pixels_per_unit2(),
        rejected_by=cat("rejected_by").astype(np.int8)[order],
        crossing=cat("crossing").astype(bool)[order],
        sibling=sibling[order],
        grids=tuple(grids),
    )
