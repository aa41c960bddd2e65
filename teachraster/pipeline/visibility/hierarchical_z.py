"""Early-z and hierarchical z (Hi-Z) of a GPU drawing in order: a replay, for the trace.

A GPU draws triangles in order. **Early-z** tests each fragment's depth against the buffer
*before* shading it, so a hidden fragment costs a depth interpolation and a test, but no
shading. **Hi-Z** goes one step further: it keeps, per screen tile, the *largest* depth
stored in the tile (a conservative summary of the buffer), and before interpolating any
depth of a triangle's block (its fragments in one tile) it compares the smallest depth the
triangle can have there with that maximum. If the triangle is nowhere nearer, the whole
block fails the depth test and is rejected at once: its fragments are never interpolated.

This module replays that on the fragments of a ``render(..., trace=True)`` and records,
per block and fragment, what a GPU drawing in this order would reject and kill
(``RenderTrace.hiz``). It changes no work of the renderer: ``render`` runs its own Hi-Z,
with a bound that holds whatever the drawing order (:mod:`teachraster.pipeline.hiz_tiles`,
the plan's ``hi_z`` entry), and really drops the hidden blocks before their depth exists.

Exactness. The block's smallest depth is the triangle's depth plane at the tile's extreme
pixel centres (the corner trick of the tiled fill: the plane is affine, and the float
expression that :meth:`Fragments.plane` evaluates is monotone along rows and columns), after
the same quantisation as the buffer: no fragment of the block is stored nearer. That
expression clamps to the range of the triangle's vertex depths, so the bound is the tighter
of the corner bound and the triangle's nearest vertex (lesson 11 §5 says so). The tile
maximum is taken over the buffer *as it was when the triangle arrived* (a running minimum
per pixel in drawing order). A rejected fragment is therefore one the depth test would
have failed.

Which blocks are compared. A fragment on a pixel that no other fragment reaches (depth
complexity one) can never be hidden, and a block holding one such fragment has a tile
whose buffer was still empty somewhere when it arrived, so it cannot be rejected. The
replay compares only blocks whose every fragment lies where the depth complexity is above
one; ``test_all`` compares every block; both reject the same blocks
(tests/test_hierarchical_z.py).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from ..rasterization.batched_fill import Fragments
from .depth import quantize
from .zbuffer import passes_depth_test, running_min

#: Side of a Hi-Z tile, in pixels (hardware uses 8×8 or larger).
HIZ_TILE = 8


@dataclass(frozen=True)
class HiZResult:
    """What early-z and Hi-Z did, per block (a triangle's fragments in one tile) and per
    fragment (drawing order, as ``Fragments``).

    Attributes
    ----------
    tile : int
        Tile side in pixels.
    block_triangle : (b,) int64
        The triangle (after clipping) of each block; blocks in drawing order.
    block_row, block_col : (b,) int64
        Top-left pixel of the block's tile.
    block_tested : (b,) bool
        Whether Hi-Z compared the block with its tile (all blocks when forced).
    block_rejected : (b,) bool
        Rejected whole: the triangle is nowhere nearer than the tile's farthest depth.
    block_nearest : (b,) float64
        Smallest depth the triangle can store in the tile (NaN where not tested).
    tile_farthest : (b,) float64
        The tile's largest stored depth when the triangle arrived (inf: not yet full);
        NaN where not needed: untested, nearer than the tile's *final* maximum (the
        buffer only gets nearer, so such a block can never be rejected), arriving
        while a pixel of the tile is still empty (the maximum is then inf), or at least
        as far as the largest *first* depth over the tile's pixels (rejected for sure).
    fragment_block : (m,) int64
        The block of every fragment.
    fragment_passed : (m,) bool
        Passed the depth test on arrival (early-z shades exactly these).
    """

    tile: int
    block_triangle: np.ndarray
    block_row: np.ndarray
    block_col: np.ndarray
    block_tested: np.ndarray
    block_rejected: np.ndarray
    block_nearest: np.ndarray
    tile_farthest: np.ndarray
    fragment_block: np.ndarray
    fragment_passed: np.ndarray

    @property
    def fragment_rejected(self) -> np.ndarray:
        """(m,) bool: killed by Hi-Z, before any depth was interpolated."""
        return self.block_rejected[self.fragment_block]

    @property
    def counts(self) -> dict[str, int]:
        """Fragments: all, rejected by Hi-Z, depth-interpolated, killed by early-z, shaded."""
        m = len(self.fragment_block)
        hiz = int(self.fragment_rejected.sum())
        shaded = int(self.fragment_passed.sum())
        return {
            "fragments": m,
            "hiz_rejected": hiz,
            "interpolated": m - hiz,
            "early_z_killed": m - hiz - shaded,
            "shaded": shaded,
        }


def replay_stage(frags: Fragments, window: np.ndarray, visible, width: int, height: int,
                 depth_format: str, test_all: bool = False,
                 tile: int = HIZ_TILE) -> HiZResult | None:  # fmt: skip
    """Early-z and Hi-Z of a GPU drawing the resolved fragments in order (for the trace).

    ``visible`` is the depth stage's :class:`~teachraster.pipeline.stages.Visibility`
    (stored depth and pixel of every fragment, all fragments kept). Returns None when the
    depth test is off. Only blocks whose every fragment lies where the depth complexity is
    above one are compared with their tile (``test_all``: every block; the same blocks are
    rejected). This replay changes no work of the renderer, which runs its own,
    order-independent Hi-Z (:mod:`teachraster.pipeline.hiz_tiles`): it shows what a GPU
    drawing in this order would save, so it runs only with ``render(..., trace=True)``.
    """
    if not visible.depth_test:
        return None
    count = np.bincount(visible.pixel, minlength=width * height)
    contested = count[visible.pixel] > 1  # depth complexity above one at the fragment
    tiles_x = -(-width // tile)
    tile_id = (frags.row // tile) * tiles_x + frags.col // tile
    n_tiles = tiles_x * -(-height // tile)
    keys, block = _unique_runs(frags.tri * n_tiles + tile_id)
    block_tri, block_tile = keys // n_tiles, keys % n_tiles
    b_row, b_col = (block_tile // tiles_x) * tile, (block_tile % tiles_x) * tile
    open_pixels = np.bincount(block, weights=~contested, minlength=len(keys))
    tested = np.ones(len(keys), bool) if test_all else open_pixels == 0
    arrivals = _Arrivals(visible.pixel, visible.depth, frags.tri, width * height, visible.writes)
    nearest = np.full(len(keys), np.nan)
    farthest = np.full(len(keys), np.nan)
    rejected = np.zeros(len(keys), dtype=bool)
    idx = np.flatnonzero(tested)
    if len(idx):
        nearest[idx] = _corner_depths(frags, window, block_tri[idx], b_row[idx], b_col[idx],
                                      (height, width), depth_format, tile)  # fmt: skip
        # The buffer only ever gets nearer, so the tile's final maximum bounds its maximum
        # at any arrival from below: a block nearer than that somewhere is never rejected,
        # and only the others need the buffer as it was (the costly part).
        final = arrivals.tile_final((height, width), tile)[block_tile[idx]]
        ready = arrivals.tile_ready((height, width), tile)[block_tile[idx]]
        # ... and a tile with a pixel no earlier triangle reached is still open (inf).
        idx = idx[~passes_depth_test(nearest[idx], final) & (ready < block_tri[idx])]
        # Every pixel of such a tile holds a depth no farther than its first fragment's,
        # so a block at least as far as the tile's largest first depth is rejected for
        # sure, without the buffer as it was (most hidden blocks of a closed mesh).
        first = arrivals.tile_first((height, width), tile)[block_tile[idx]]
        sure = ~passes_depth_test(nearest[idx], first)
        rejected[idx[sure]] = True
        idx = idx[~sure]
        farthest[idx] = arrivals.tile_farthest(block_tri[idx], b_row[idx], b_col[idx],
                                               (height, width), tile)  # fmt: skip
    # the block's nearest point fails against the tile's farthest depth: so does all of it
    rejected[idx] = ~passes_depth_test(nearest[idx], farthest[idx])
    return HiZResult(tile, block_tri, b_row, b_col, tested, rejected, nearest, farthest,
                     block, arrivals.passed)  # fmt: skip


def replay_tiles(trace, tile: int) -> HiZResult:
    """The replay of a traced one-sample render (its ``RenderTrace``) again, with Hi-Z tiles
    of ``tile`` pixels a side: what a GPU whose tiles have that size would reject, for the
    tile size's trade-off (lesson 10). ``tile`` = :data:`HIZ_TILE` gives ``trace.hiz``.

    The fragments, their stored depths and depth masks are the trace's own; only the tiles
    change. Raises ValueError for a render without the depth test or with MSAA (its trace
    keeps no single-sample fragments).
    """
    debug = getattr(trace, "debug", None)
    if trace.hiz is None or debug is None or debug.fragments is None:
        raise ValueError("replay_tiles needs a one-sample tr.render(..., trace=True) with the "
                         "depth test on")  # fmt: skip
    a, frags = debug.inputs, debug.fragments
    writes = None if debug.writes is None else debug.writes[frags.tri]  # per fragment
    visible = SimpleNamespace(depth_test=True, pixel=debug.pixel, depth=trace.fragment_depth,
                              writes=writes)  # fmt: skip
    return replay_stage(frags, trace.window, visible, a.width, a.height, a.depth_format,
                        tile=int(tile))  # fmt: skip


def _unique_runs(key: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(key, return_inverse=True)`` for keys that come in runs (the fragments of
    one raster line in one tile): only the runs' first keys are sorted, a few times fewer."""
    if len(key) == 0:
        return key, np.zeros(0, dtype=np.int64)
    new = np.empty(len(key), dtype=bool)
    new[0] = True
    np.not_equal(key[1:], key[:-1], out=new[1:])
    keys, inverse = np.unique(key[new], return_inverse=True)
    return keys, inverse.reshape(-1)[np.cumsum(new) - 1]


def _corner_depths(frags, window, tri, row, col, image, depth_format, tile) -> np.ndarray:
    """Smallest stored depth of each triangle over its tile: the plane at the 4 corners
    (clamped, as everywhere, to the vertex depths: no nearer than the nearest vertex)."""
    height, width = image
    last_r = np.minimum(row + tile, height) - 1
    last_c = np.minimum(col + tile, width) - 1
    rows = np.stack([row, row, last_r, last_r], axis=1).ravel()
    cols = np.stack([col, last_c, col, last_c], axis=1).ravel()
    # The very expression the depth stage evaluates per fragment, at the corners.
    probe = dataclasses.replace(frags, tri=np.repeat(tri, 4), row=rows, col=cols)
    depth = quantize(probe.plane(window[:, :, 2]), depth_format)
    return depth.reshape(-1, 4).min(axis=1)


class _Arrivals:
    """The z-buffer as each fragment found it: fragments grouped by pixel (drawing order
    kept inside a group) with the running minimum of the depths they wrote (``writes``,
    per fragment: a fragment with depth writes off is tested but writes nothing, so it
    neither lowers a tile's maximum nor fills an empty pixel)."""

    def __init__(self, pixel: np.ndarray, depth: np.ndarray, tri: np.ndarray, n_pixels: int,
                 writes=None):  # fmt: skip
        m = len(pixel)
        # Fragments come in drawing order (by triangle), so a stable sort by pixel orders
        # each pixel's fragments by triangle.
        # (32-bit keys sort faster, and pixel indices fit them: sizes stay below 2**28)
        key = pixel.astype(np.int32) if n_pixels < 2**31 else pixel
        self.order = np.argsort(key, kind="stable")
        self.source_tri = tri  # gathered through ``order`` only where needed (few places)
        self.count = np.bincount(pixel, minlength=n_pixels)
        self.start = np.cumsum(self.count) - self.count  # each pixel's first fragment
        sorted_depth = depth[self.order]
        written = sorted_depth if writes is None else np.where(writes[self.order], sorted_depth,
                                                               np.inf)  # fmt: skip
        longest = int(self.count.max(initial=0))
        sorted_key = key[self.order] if longest > 1 else None
        self.running = running_min(sorted_key, written, longest)
        before = np.empty(m)  # the buffer each fragment found: the running minimum so far
        before[1:] = self.running[:-1]
        before[self.start[self.count > 0]] = np.inf  # a pixel's first fragment: empty
        self.passed = np.empty(m, dtype=bool)  # strictly nearer than all before it
        self.passed[self.order] = passes_depth_test(sorted_depth, before)

    def tile_ready(self, image, tile) -> np.ndarray:
        """Per tile, the triangle after which every pixel of it holds a depth (the largest
        first-arriving triangle over its pixels; beyond the last triangle if one stays
        empty)."""
        height, width = image
        ty, tx = -(-height // tile), -(-width // tile)
        first = np.full((ty * tile, tx * tile), -1, dtype=np.int64)  # beyond the image
        reached = self.count > 0
        arrival = np.full(height * width, np.iinfo(np.int64).max, dtype=np.int64)
        arrival[reached] = self.source_tri[self.order[self.start[reached]]]
        first[:height, :width] = arrival.reshape(height, width)
        return first.reshape(ty, tile, tx, tile).max(axis=(1, 3)).ravel()

    def tile_final(self, image, tile) -> np.ndarray:
        """Largest final buffer depth of every tile (inf where a pixel stays empty): the
        running minimum at each pixel's last fragment."""
        reached = self.count > 0
        return self._tile_max(self.running[(self.start + self.count - 1)[reached]], reached,
                              image, tile)  # fmt: skip

    def tile_first(self, image, tile) -> np.ndarray:
        """Per tile, the largest depth of the first fragment over its pixels (inf where a
        pixel is never reached): a bound from above on the tile's maximum once every pixel
        holds a depth, since each pixel only gets nearer."""
        reached = self.count > 0
        return self._tile_max(self.running[self.start[reached]], reached, image, tile)

    @staticmethod
    def _tile_max(values, reached, image, tile) -> np.ndarray:
        """Per tile, the largest of ``values`` at the ``reached`` pixels (inf if one is not)."""
        height, width = image
        ty, tx = -(-height // tile), -(-width // tile)
        grid = np.full((ty * tile, tx * tile), -np.inf)  # pixels beyond the image: ignored
        depth = np.full(height * width, np.inf)
        depth[reached] = values
        grid[:height, :width] = depth.reshape(height, width)
        return grid.reshape(ty, tile, tx, tile).max(axis=(1, 3)).ravel()

    def tile_farthest(self, tri, row, col, image, tile) -> np.ndarray:
        """Largest buffer depth over each tile just before triangle ``tri`` arrives (inf
        while a pixel of the tile is still empty)."""
        height, width = image
        dr, dc = np.indices((tile, tile)).reshape(2, -1)
        r, c = row[:, None] + dr, col[:, None] + dc  # (b, tile²) pixels of each tile
        inside = (r < height) & (c < width)
        p = np.where(inside, r * width + c, 0)
        start, count = self.start[p], np.where(inside, self.count[p], 0)
        before = np.full(p.shape, np.inf)  # the buffer at arrival
        tri = np.broadcast_to(tri[:, None], p.shape)
        last = len(self.order) - 1
        for k in range(int(count.max(initial=0))):  # depth complexity: a few rounds
            at = np.minimum(start + k, last)
            earlier = (k < count) & (self.source_tri[self.order[at]] < tri)  # earlier triangles
            before = np.where(earlier, self.running[at], before)  # running min: the last
        return np.where(inside, before, -np.inf).max(axis=1)
