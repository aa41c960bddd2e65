"""Hi-Z as ``render`` runs it: hidden blocks are dropped before their depth is interpolated.

A GPU keeps, per screen tile, the farthest depth stored in it and rejects a triangle's block
whose nearest depth is farther still (:mod:`teachraster.pipeline.hierarchical_z` replays
that, in drawing order, for the trace). This renderer knows every triangle of the frame at
once, so it uses a bound that holds whatever the drawing order:

- an **occluder** of a tile is a triangle that covers every pixel centre of it (the tiled
  walk's *accepted* block, top-left rule included; read off the raster lines: all 8 lines
  of the tile span its 8 columns). The buffer can only hold, at each pixel of the tile,
  that triangle's depth or a nearer one, so after the frame every pixel of the tile is at
  most ``farthest[tile]``: the smallest, over the tile's occluders, of the occluder's
  largest stored depth in the tile (its depth plane at the tile's 4 corner centres);
- a **block** is a raster line of a triangle cut at the tile borders (at most 8 pixels). Its
  nearest stored depth is the plane at one of its two ends. If that is *strictly* farther
  than ``farthest[tile]``, every fragment of the block is strictly farther than the
  occluder's fragment at its pixel and can never be shown, nor tie: the block is dropped
  before it becomes fragments, and its depth is never interpolated nor tested. A whole
  line whose nearest end is farther than the bound of every tile it crosses goes at once,
  without being cut.

Exactness. Both bounds use the very expression the depth stage evaluates per fragment,
:meth:`~teachraster.pipeline.batched_fill.Fragments.plane`, then the buffer's quantisation
(``depth_format``): both are monotone along rows and columns (each float operation rounds
monotonically), so the extreme stored depths over a row piece or a rectangle lie at its
ends or corners, bit for bit. The occluder that sets ``farthest[tile]`` is itself never
dropped there (its nearest depth is at most its farthest), so the frame is identical with
and without Hi-Z (tests/test_hiz_tiles.py).

The plan. Only blocks in a tile with an occluder can be rejected, and only where another
triangle reaches it (depth complexity above one). The occluders are read off the raster
lines: a line shorter than 8 pixels cannot help cover a tile, so a scene of small
triangles (the 20,000-triangle sphere) costs one comparison per raster line. Hi-Z then
runs only where it pays for itself: where the occluders over one another hide at least
:data:`MIN_SAVING` pixels, and :data:`LINE_COST` per raster line (comparing lines costs
per line, a rejected fragment saves ~20 ns); it then cuts only the lines that reach a
tile something besides its lone occluder covers. ``force="hi_z"`` compares every line
and rejects a superset (the same blocks wherever the plan ran); the frame is identical
either way.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from ..rasterization.batched_fill import Fragments, flat_ranges
from .depth import quantize
from .hierarchical_z import HIZ_TILE
from .zbuffer import surely_in_front

#: Hi-Z is planned only where it expects to reject at least this many fragments ...
#: (measured, benchmarks/bench_scenes.py section 5: a rejected fragment saves ~20 ns of
#: depth interpolation and z-buffer work, while the depth stage's per-pixel passes and
#: Hi-Z's own fixed cost, a few dozen numpy calls, stay; 128 Ki rejected fragments of the
#: cube at 1920x1080 only break even)
MIN_SAVING = 131_072
#: ... and at least this many per raster line (comparing and cutting a line costs about
#: as much as 16 rejected fragments save: 1,024 stacked layers of 32x32 pixels, 12 per
#: line, are already slower with Hi-Z).
LINE_COST = 16


@dataclass(frozen=True)
class Spans:
    """Raster-line pieces in drawing order: triangle, row, first column, pixel count (each (p,))."""

    tri: np.ndarray
    row: np.ndarray
    col: np.ndarray
    counts: np.ndarray


@dataclass(frozen=True)
class HiZTiles:
    """What Hi-Z did in one render (the trace keeps it as ``RenderTrace.hiz_tiles``).

    Attributes
    ----------
    tile : int
        Tile side in pixels.
    farthest : (ty, tx) float64
        Per tile, the farthest stored depth of its nearest occluder: no pixel of the tile
        ends farther (inf where no triangle covers the whole tile, and everywhere when the
        plan skipped Hi-Z: then no depth was computed).
    occluders : (ty, tx) int64
        How many triangles cover each tile whole (zeros when the plan did not look:
        ``skipped == "short lines"``).
    fragments : int
        Covered pixel centres before Hi-Z (all triangles, after culling).
    raster_lines : int
        Non-empty raster lines (a triangle's span on one row) before Hi-Z.
    rejected : int
        Fragments dropped by Hi-Z, whose depth was never interpolated.
    lines, lines_rejected : int
        Raster lines compared with the tiles they cross, and those rejected whole (their
        nearest depth farther than every tile's bound: no block needs cutting).
    blocks, blocks_rejected : int
        Blocks (a line's pixels within one occluded tile) of the other lines compared with
        their tile, and those rejected.
    ran : bool
        Whether lines were compared at all (False: skipped, see ``skipped``).
    skipped : str
        Why not, when not: "short lines" (too few fragments per raster line, or in all,
        for Hi-Z to pay even if it rejected every one), "no occluder", "too little to
        save" (too few pixels of occluders behind others) or "lone occluders".
    forced : bool
        Every line was compared (``force="hi_z"``).
    fragment_rejected : (m,) bool or None
        With ``trace=True`` nothing is dropped (the trace lists every fragment): per
        fragment of the render, whether Hi-Z rejects it.
    """

    tile: int
    farthest: np.ndarray
    occluders: np.ndarray
    fragments: int
    raster_lines: int = 0
    rejected: int = 0
    lines: int = 0
    lines_rejected: int = 0
    blocks: int = 0
    blocks_rejected: int = 0
    ran: bool = False
    skipped: str = ""
    forced: bool = False
    fragment_rejected: np.ndarray | None = None

    @property
    def interpolated(self) -> int:
        """Fragments whose depth was interpolated (all but the rejected)."""
        return self.fragments - self.rejected

    @property
    def occluded_pixels(self) -> int:
        """Pixels in tiles some triangle covers whole."""
        return int((self.occluders > 0).sum()) * self.tile**2

    @property
    def layered(self) -> int:
        """Pixels of occluders behind another occluder's (tile area times occluders beyond
        the first, summed over tiles): what the plan expects Hi-Z to save at least."""
        return int(np.maximum(self.occluders - 1, 0).sum()) * self.tile**2


class HiZCut:
    """The ``spans`` hook of :func:`~teachraster.pipeline.batched_fill.rasterize_batch`.

    Call it with the raster lines; it returns them with the hidden blocks cut out (none
    cut, only marked, when ``keep_all``) and leaves its record in ``result``.

    Parameters
    ----------
    z : (M, 3) float64
        Window depth of every triangle's vertices.
    image : (height, width)
    depth_format : str
        The buffer's format: bounds are compared as stored.
    forced : bool
        Compare every line (same rejections, more work).
    keep_all : bool
        Drop nothing, only mark (for the trace, which lists every fragment, and for
        blending, where a fragment hidden in the end may still have been blended into the
        colour before its occluder arrived).
    writes : (M,) bool or None
        Each triangle's depth mask (``depth_write``): only triangles that write depth can
        be occluders (None: all write). The bound still holds whatever the order: a
        fragment strictly farther than a written depth at its pixel is never the last to
        pass there.
    """

    def __init__(self, z, image, depth_format: str, forced: bool, keep_all: bool,
                 tile: int = HIZ_TILE, writes=None):  # fmt: skip
        self.z, self.image, self.depth_format = z, image, depth_format
        self.forced, self.keep_all, self.tile = forced, keep_all, tile
        self.writes = writes
        self.result: HiZTiles | None = None

    def __call__(self, lines: Fragments, counts: np.ndarray) -> Spans:
        height, width = self.image
        t = self.tile
        grid = (-(-height // t), -(-width // t))
        n_frags, n_lines = int(counts.sum()), int(np.count_nonzero(counts))
        farthest = np.full(grid[0] * grid[1], np.inf)
        whole = Spans(lines.tri, lines.row, lines.col, counts)
        if not self.forced and n_frags < max(MIN_SAVING, LINE_COST * n_lines):
            # Hi-Z saves at most every fragment (``layered`` <= fragments): with short
            # lines, or few fragments, it cannot pay; decided before looking for occluders.
            base = HiZTiles(t, farthest.reshape(grid), np.zeros(grid, dtype=np.int64),
                            n_frags, raster_lines=n_lines, skipped="short lines")  # fmt: skip
            return self._unchanged(whole, base)
        writers = counts if self.writes is None else np.where(self.writes[lines.tri], counts, 0)
        runs, pairs, occluders = _occluder_tiles(lines, writers, self.image, t)
        base = HiZTiles(t, farthest.reshape(grid), occluders.reshape(grid), n_frags,
                        raster_lines=n_lines, forced=self.forced)  # fmt: skip
        which, skipped = self._lines_to_test(lines, counts, occluders, runs, grid, base)
        if skipped:
            return self._unchanged(whole, dataclasses.replace(base, skipped=skipped))
        if pairs is not None:  # only now the depths: skipping costs no plane evaluation
            self._farthest(lines, pairs, farthest)
        near = self._nearest(lines, which, lines.col[which], lines.col[which] + counts[which])
        far = _range_max(
            farthest.reshape(grid),
            lines.row[which] // t,
            lines.col[which] // t,
            (lines.col[which] + counts[which] - 1) // t,
        )
        gone = surely_in_front(far, near)  # every tile it crosses is in front: all hidden
        rest = which[~gone]
        pieces, owner, rejected = self._blocks(lines, counts, rest, farthest, grid[1])
        record = dataclasses.replace(
            base, ran=True, lines=len(which), lines_rejected=int(gone.sum()),
            blocks=int(np.isfinite(farthest[pieces.tile]).sum()),
            blocks_rejected=int(rejected.sum()),
            rejected=int(counts[which[gone]].sum() + pieces.counts[rejected].sum()),
        )  # fmt: skip
        # Lines with some blocks rejected are replaced by their pieces; the others stay.
        hit = np.bincount(owner[rejected], minlength=len(rest)) > 0
        sel = hit[owner]  # the pieces of those lines
        keep = np.ones(int(sel.sum()), dtype=bool) if self.keep_all else ~rejected[sel]
        out_counts, flag = counts, np.zeros(len(counts), dtype=bool)
        if self.keep_all:
            flag[which[gone]] = True
        else:
            out_counts = counts.copy()
            out_counts[which[gone]] = 0
        out, flags = _merge(
            Spans(lines.tri, lines.row, lines.col, out_counts), flag, rest[hit],
            _select(pieces, sel), np.cumsum(hit)[owner[sel]] - 1, keep, rejected[sel],
        )  # fmt: skip
        if self.keep_all:
            record = dataclasses.replace(record, fragment_rejected=np.repeat(flags, out.counts))
        self.result = record
        return out

    def _unchanged(self, whole: Spans, record: HiZTiles) -> Spans:
        if self.keep_all:
            record = dataclasses.replace(
                record, fragment_rejected=np.zeros(record.fragments, dtype=bool)
            )
        self.result = record
        return whole

    def _lines_to_test(self, lines, counts, occluders, runs, grid, base):
        """The lines to compare with their tiles, or why none are (the plan)."""
        if self.forced:
            return np.flatnonzero(counts > 0), ""
        if runs is None:
            return None, "no occluder"
        # Comparing costs per raster line plus a fixed overhead, and saves per fragment
        # rejected: estimated by the layers of occluders over one another (exact for
        # stacked layers, low where the hidden triangles cover no tile themselves).
        if base.layered < max(MIN_SAVING, LINE_COST * base.raster_lines):
            return None, "too little to save"
        which = _contested_lines(lines, counts, occluders, runs, grid, self.tile)
        return which, ("" if len(which) else "lone occluders")

    def _plane(self, lines: Fragments, tri, row, col) -> np.ndarray:
        """Stored depth of triangles ``tri`` at pixel centres (row, col): the depth stage's
        expression and quantisation, at a few probe points."""
        probe = dataclasses.replace(lines, tri=tri, row=row, col=col)
        depth = probe.plane(self.z)
        return depth if self.depth_format == "float64" else quantize(depth, self.depth_format)

    def _nearest(self, lines, which, start, stop) -> np.ndarray:
        """Nearest stored depth of lines ``which`` over columns start..stop-1: the plane is
        monotone along a row, so it is at one of the two ends."""
        tri, row = lines.tri[which], lines.row[which]
        twice = np.concatenate
        ends = self._plane(lines, twice([tri, tri]), twice([row, row]), twice([start, stop - 1]))
        return np.minimum(ends[: len(which)], ends[len(which) :])

    def _farthest(self, lines: Fragments, pairs, farthest) -> None:
        """Into ``farthest`` (flat tiles, inf), per tile the smallest over its occluders of
        the occluder's farthest stored depth there: its plane at one of the 4 corners."""
        tri, top, left, tile_id = pairs
        t = self.tile
        corners = self._plane(
            lines,
            np.repeat(tri, 4),
            np.stack([top, top, top + t - 1, top + t - 1], axis=1).ravel(),
            np.stack([left, left + t - 1, left, left + t - 1], axis=1).ravel(),
        )
        np.minimum.at(farthest, tile_id, corners.reshape(-1, 4).max(axis=1))

    def _blocks(self, lines: Fragments, counts, which, farthest, tx):
        """Lines ``which`` cut at the tile borders: the pieces (drawing order, with their
        tile), the entry of ``which`` each comes from, and whether each is rejected."""
        t = self.tile
        col, cnt = lines.col[which], counts[which]
        owner, k = flat_ranges(col // t, (col + cnt - 1) // t + 1)
        line = which[owner]
        start = np.maximum(lines.col[line], k * t)
        stop = np.minimum(lines.col[line] + counts[line], (k + 1) * t)
        row, tri = lines.row[line], lines.tri[line]
        tile_id = (row // t) * tx + k
        bound = farthest[tile_id]
        idx = np.flatnonzero(np.isfinite(bound))  # only occluded tiles can reject
        rejected = np.zeros(len(line), dtype=bool)
        near = self._nearest(lines, line[idx], start[idx], stop[idx])
        rejected[idx] = surely_in_front(bound[idx], near)  # never shown, never tied
        return _Pieces(tri, row, start, stop - start, tile_id), owner, rejected


@dataclass(frozen=True)
class _Pieces(Spans):
    tile: np.ndarray


def _select(pieces: _Pieces, mask) -> _Pieces:
    return _Pieces(*(getattr(pieces, f.name)[mask] for f in dataclasses.fields(pieces)))


def _range_max(grid, tile_row, first, last) -> np.ndarray:
    """Per query, the largest entry of ``grid`` (ty, tx) in row ``tile_row``, columns
    ``first..last``: a sparse table (maxima over runs of 2**j columns), two look-ups each."""
    ty, tx = grid.shape
    levels = [grid]
    while 2 ** len(levels) <= tx:
        prev, step = levels[-1], 2 ** (len(levels) - 1)
        nxt = prev.copy()
        nxt[:, : tx - step] = np.maximum(prev[:, : tx - step], prev[:, step:])
        levels.append(nxt)
    table = np.stack(levels).ravel()
    level = np.frexp((last - first + 1).astype(np.float64))[1] - 1  # floor(log2(length))
    at = level * (ty * tx) + tile_row * tx
    return np.maximum(table[at + first], table[at + last - (1 << level) + 1])


def _occluder_tiles(lines: Fragments, counts, image, t):
    """The runs of tiles each triangle covers whole (per tile row, see :func:`_full_runs`),
    every (occluder, tile) pair as (triangle, top row, left column, flat tile), and the
    number of occluders per flat tile (no depth yet: the plan decides on the counts)."""
    height, width = image
    tx = -(-width // t)
    occluders = np.zeros(-(-height // t) * tx, dtype=np.int64)
    runs = _full_runs(lines, counts, (height // t, width // t), t)
    if runs is None:
        return None, None, occluders
    r_tri, r_row, k_lo, k_hi = runs
    owner, k = flat_ranges(k_lo, k_hi + 1)  # every (occluder, tile) pair
    row = r_row[owner]
    tile_id = row * tx + k
    occluders += np.bincount(tile_id, minlength=len(occluders))
    return runs, (r_tri[owner], row * t, k * t, tile_id), occluders


def _full_runs(lines: Fragments, counts, full, t):
    """Per (triangle, tile row) with all ``t`` lines spanning a whole tile: the triangle,
    tile row and the first and last tile column it covers whole (None if there is none).

    Only lines of ``t`` or more pixels can take part, so small triangles cost one
    comparison per line. Lines come by triangle, then row, so each (triangle, tile row)
    is one run of consecutive lines.
    """
    rows_full, cols_full = full
    idx = np.flatnonzero((counts >= t) & (lines.row < rows_full * t))
    if not len(idx) or not cols_full:
        return None
    tri, tile_row = lines.tri[idx], lines.row[idx] // t
    key = tri * rows_full + tile_row
    start = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    size = np.diff(np.r_[start, len(key)])
    lo, stop = lines.col[idx], lines.col[idx] + counts[idx]
    k_lo = np.maximum.reduceat(-(-lo // t), start)  # first tile starting at or after lo
    k_hi = np.minimum(np.minimum.reduceat(stop // t, start) - 1, cols_full - 1)
    good = (size == t) & (k_lo <= k_hi)
    if not good.any():
        return None
    g = start[good]
    return tri[g], tile_row[g], k_lo[good], k_hi[good]


def _contested_lines(lines, counts, occluders, runs, grid, t) -> np.ndarray:
    """Lines worth cutting into blocks: those reaching an occluded tile other than one
    their own triangle occludes alone (a lone occluder is never farther than itself, and
    nothing else reaches such a tile through this line)."""
    if runs is None:
        return np.zeros(0, dtype=np.int64)
    ty, tx = grid
    live = np.flatnonzero(counts > 0)
    col, row = lines.col[live], lines.row[live]
    base = (row // t) * (tx + 1)
    first, last = col // t, (col + counts[live] - 1) // t
    n_occluded = _in_range(occluders > 0, (ty, tx), base, first, last)
    sel = np.flatnonzero(n_occluded > 0)
    if not len(sel):
        return sel
    r_tri, r_row, k_lo, k_hi = runs
    run_key = r_tri * ty + r_row  # ascending: runs come by triangle, then row
    key = lines.tri[live[sel]] * ty + row[sel] // t
    at = np.minimum(np.searchsorted(run_key, key), len(run_key) - 1)
    own = run_key[at] == key
    lo = np.maximum(first[sel], k_lo[at])
    hi = np.where(own, np.minimum(last[sel], k_hi[at]), lo - 1)
    alone = _in_range(occluders == 1, (ty, tx), base[sel], lo, np.maximum(hi, lo - 1))
    return live[sel[n_occluded[sel] > alone]]


def _in_range(flag, grid, base, first, last) -> np.ndarray:
    """Per line, how many tiles ``first..last`` (inclusive; none if last < first) of its
    tile row (``base`` = tile row * (tx + 1)) have ``flag`` (flat (ty * tx,) bool)."""
    ty, tx = grid
    prefix = np.zeros((ty, tx + 1), dtype=np.int64)
    np.cumsum(flag.reshape(ty, tx), axis=1, out=prefix[:, 1:])
    prefix = prefix.ravel()
    return prefix[base + last + 1] - prefix[base + first]


def _merge(whole: Spans, flag, split, pieces: Spans, owner, keep, rejected):
    """``whole`` with lines ``split`` (ascending) replaced by their kept ``pieces``
    (``owner``: the entry of ``split`` each piece comes from), in drawing order; and per
    output span its flag (``flag`` per line, ``rejected`` per piece)."""
    if not len(split):
        return whole, flag
    n_out = np.ones(len(whole.counts), dtype=np.int64)
    n_out[split] = np.bincount(owner[keep], minlength=len(split))
    offset = np.cumsum(n_out) - n_out
    total = int(n_out.sum())
    plain = np.ones(len(whole.counts), dtype=bool)
    plain[split] = False
    at = offset[plain]
    kept = np.flatnonzero(keep)
    first_kept = np.cumsum(n_out[split]) - n_out[split]  # per split line, in ``kept``
    at_kept = offset[split[owner[kept]]] + np.arange(len(kept)) - first_kept[owner[kept]]
    out = []
    for a, b in zip((whole.tri, whole.row, whole.col, whole.counts),
                    (pieces.tri, pieces.row, pieces.col, pieces.counts)):  # fmt: skip
        dst = np.empty(total, dtype=np.int64)
        dst[at], dst[at_kept] = a[plain], b[kept]
        out.append(dst)
    flags = np.zeros(total, dtype=bool)
    flags[at], flags[at_kept] = flag[plain], rejected[kept]
    return Spans(*out), flags
