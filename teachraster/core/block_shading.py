"""Shading whole blocks: what a tiled rasteriser does with the blocks its walk accepts.

A block that every edge accepts needs no per-pixel coverage test (:mod:`.tiles`), and its
pixels need no per-pixel bookkeeping either: hardware steps the edge functions (and so the
barycentrics) across the block from one corner and writes the block out whole. Here every
``cell`` × ``cell`` cell of the image grid that the walk left fully covered (accepted whole,
or filled completely by its children's tests) is shaded as a dense block: its edge values
are one row term minus one column term, broadcast over the cell (E is affine: Ek,
*Triangles and Perspective Correct Interpolation*, §1.2, Pineda's edge functions as
llvmpipe's ``lp_rast_tri.c`` steps them), and its values are written into the image as a
block instead of pixel by pixel. The remaining
covered pixels (the triangle's border) take the per-pixel path.

The weights come from the same exact edge values through the same operations as the
per-pixel path, so the image is bit for bit the one the other methods produce.
"""

from __future__ import annotations

import numpy as np

from .barycentrics import barycentric_from_edges, barycentric_pixels
from .edges import EdgeSetup
from .interpolation import blend, interpolate


def whole_cells(coverage: np.ndarray, cell: int) -> np.ndarray:
    """(H // cell, W // cell) bool: the aligned cells of the image grid wholly covered.

    >>> cov = np.zeros((4, 6), dtype=bool); cov[:2, :4] = True
    >>> whole_cells(cov, 2).astype(int)
    array([[1, 1, 0],
           [0, 0, 0]])
    """
    h, w = coverage.shape[0] // cell * cell, coverage.shape[1] // cell * cell
    blocks = coverage[:h, :w].reshape(h // cell, cell, w // cell, cell)
    return blocks.all(axis=(1, 3))


def cell_edge_values(setup: EdgeSetup, ci, cj, cell: int, shape) -> np.ndarray:
    """(n, cell, cell, 3) E_k at the pixel centres of cells (ci, cj): one row term minus one
    column term per cell and edge, broadcast (no per-pixel multiply, no per-pixel gather)."""
    d = np.arange(cell)
    rows, cols = np.arange(shape[0]), np.arange(shape[1])
    out = np.empty((len(ci), cell, cell, 3), dtype=setup.p.dtype)
    for k in range(3):
        row_term, col_term = setup.edge_terms(k, rows, cols)
        np.subtract(
            row_term[ci[:, None] * cell + d][:, :, None],
            col_term[cj[:, None] * cell + d][:, None, :],
            out=out[..., k],
        )
    return out


def shade_blocks(tri, setup: EdgeSetup, coverage: np.ndarray, packed: np.ndarray,
                 interpolation: str, cell: int):  # fmt: skip
    """Attribute image (H, W, K) and depth image (H, W) or None: whole cells as blocks,
    the other covered pixels one by one; NaN where uncovered."""
    height, width = coverage.shape
    cells = whole_cells(coverage, cell)
    ci, cj = np.nonzero(cells)
    h, w = cells.shape[0] * cell, cells.shape[1] * cell
    rest = coverage.copy()
    rest[:h, :w].reshape(cells.shape[0], cell, cells.shape[1], cell)[ci, :, cj, :] = False
    rows, cols = np.nonzero(rest)
    e = cell_edge_values(setup, ci, cj, cell, coverage.shape).reshape(-1, 3)
    lam = np.concatenate([barycentric_from_edges(setup, e), barycentric_pixels(setup, rows, cols)])
    n = len(e)

    def image(values: np.ndarray) -> np.ndarray:
        k = values.shape[1:]
        out = np.full((height, width, *k), np.nan)
        blocks = out[:h, :w].reshape(cells.shape[0], cell, cells.shape[1], cell, *k)
        blocks[ci, :, cj, :] = values[:n].reshape(len(ci), cell, cell, *k)
        out[rows, cols] = values[n:]
        return out

    attrs = image(interpolate(lam, packed, tri.w, interpolation))
    depth = None if tri.z is None else image(blend(lam, tri.z))
    return attrs, depth


def cell_size(block_sizes) -> int:
    """The cell shaded whole: the smallest block size of at least 8 px (a 4×4 cell is too
    small for block writes to beat pixel writes), else the largest size there is."""
    big = [s for s in block_sizes if s >= 8]
    return min(big) if big else max(block_sizes)
