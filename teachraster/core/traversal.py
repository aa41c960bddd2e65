"""Traversal orders: in which order a rasteriser walks the cells of a grid.

A rasteriser that tests pixels (or blocks) one after the other must pick an order. The order
changes nothing in the result, only *where the memory traffic goes*: neighbouring visits
touch neighbouring pixels of the frame buffer and texels of a texture (McCormack and McNamara,
*Tiled polygon traversal using half-plane edge functions*, 2000).

- ``"scanline"``: row by row, left to right (the half-plane loop of lesson 02);
- ``"serpentine"``: row by row, every other row right to left (boustrophedon), so each step
  goes to a 4-neighbour and an incremental walker only ever adds or subtracts one step;
- ``"tiled"``: ``tile`` × ``tile`` tiles row by row, scanline inside each tile (what a
  block-based walker such as llvmpipe's does at each level);
- ``"morton"``: Z-order, the bits of row and column interleaved: tiles of tiles of tiles,
  recursively, so every aligned power-of-two square is visited in one go.

>>> traversal_order((2, 3), "serpentine").tolist()
[[0, 0], [0, 1], [0, 2], [1, 2], [1, 1], [1, 0]]
>>> traversal_order((2, 2), "morton").tolist()
[[0, 0], [0, 1], [1, 0], [1, 1]]
"""

from __future__ import annotations

import numpy as np

from .validate import as_int, check_choice

TRAVERSALS = ("scanline", "serpentine", "tiled", "morton")


def morton_code(i: np.ndarray, j: np.ndarray) -> np.ndarray:
    """Z-order code of cells (i, j): bits of ``j`` at even, bits of ``i`` at odd positions.

    >>> morton_code(np.array([0, 0, 1, 1, 2]), np.array([0, 1, 0, 1, 0])).tolist()
    [0, 1, 2, 3, 8]
    """
    i, j = np.asarray(i, dtype=np.int64), np.asarray(j, dtype=np.int64)
    code = np.zeros(np.broadcast(i, j).shape, dtype=np.int64)
    for b in range(31):  # cells below 2**31 in each direction: codes fit int64
        code |= ((j >> b) & 1) << (2 * b)
        code |= ((i >> b) & 1) << (2 * b + 1)
    return code


def traversal_rank(i, j, shape: tuple[int, int], traversal: str, tile: int = 4) -> np.ndarray:
    """A sort key of cells (i, j) of a grid of ``shape``: smaller keys are visited first.

    Keys are distinct for distinct cells but need not be contiguous.
    """
    check_choice("traversal", traversal, TRAVERSALS)
    tile = as_int("tile", tile, minimum=1)
    i, j = np.asarray(i, dtype=np.int64), np.asarray(j, dtype=np.int64)
    ncols = int(shape[1])
    if traversal == "scanline":
        return i * ncols + j
    if traversal == "serpentine":
        return i * ncols + np.where(i % 2 == 0, j, ncols - 1 - j)
    if traversal == "tiled":
        tiles_across = -(-ncols // tile)
        tile_index = (i // tile) * tiles_across + j // tile
        return tile_index * tile * tile + (i % tile) * tile + j % tile
    return morton_code(i, j)


def traversal_order(shape, traversal: str = "scanline", tile: int = 4) -> np.ndarray:
    """(n, 2) (row, col) of every cell of a grid of ``shape``, in visiting order.

    ``tile`` is the tile side of ``"tiled"``. Every cell appears exactly once.
    """
    nrows, ncols = (as_int("shape", s, minimum=0) for s in shape)
    i, j = np.indices((nrows, ncols)).reshape(2, -1)
    order = np.argsort(traversal_rank(i, j, (nrows, ncols), traversal, tile), kind="stable")
    return np.stack([i[order], j[order]], axis=1)


def visit_index(shape, traversal: str = "scanline", tile: int = 4) -> np.ndarray:
    """(rows, cols) int: the position of each cell in the visit (0 = first).

    >>> visit_index((2, 2), "serpentine").tolist()
    [[0, 1], [3, 2]]
    """
    cells = traversal_order(shape, traversal, tile)
    out = np.empty(tuple(int(s) for s in shape), dtype=np.int64)
    out[cells[:, 0], cells[:, 1]] = np.arange(len(cells))
    return out
