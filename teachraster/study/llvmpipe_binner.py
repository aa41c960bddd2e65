"""How Mesa's llvmpipe bins a triangle: its choices re-enacted on whole pixels, for lesson 10.

llvmpipe (Mesa's software rasteriser) cuts the screen into 64×64 tiles and sorts each triangle
into the *bins* of the tiles it touches before any tile is rasterised. Three of its choices
are re-enacted here, each from the Mesa source file that makes it, so that lesson 10 can show
the result beside its own tiled walk (:mod:`teachraster.core.tiles`) without reproducing the
source in a notebook:

- :func:`steps_in_32_bits`: whether a triangle is stepped in 32-bit or 64-bit integers
  (``lp_setup_tri.c``, with ``MAX_FIXED_LENGTH32`` of ``lp_rast.h``);
- :func:`small_triangle_command`: the command a triangle inside one tile gets
  (``lp_setup_bin_triangle`` in ``lp_setup_tri.c``: ``TRIANGLE_3_4``, ``TRIANGLE_3_16``),
  with the block and pixel tests it makes;
- :func:`bin_rows`: the binner's loop over the 64×64 tiles of a larger triangle's box
  (``lp_setup_bin_triangle``), which leaves a row at its first outside tile after the
  triangle.

llvmpipe's positions are in 1/256 px (``FIXED_ORDER = 8``) with pixel centres on whole
numbers; here they are re-enacted in floating point on the same tests (the cases the lesson
uses have no ties), which is enough to say which tiles and blocks are tested, not to decide
a centre on an edge.

>>> MAX_FIXED_LENGTH32
128
>>> steps_in_32_bits(0, 127, 0, 127), steps_in_32_bits(2, 129, 0, 127)
(True, False)
>>> small_triangle_command([[100.3, 100.2], [102.3, 100.2], [100.3, 102.2]])
('TRIANGLE_3_16', (99, 101), 16, 96)
"""

from __future__ import annotations

import numpy as np

#: llvmpipe's sub-pixel bits (``FIXED_ORDER`` in ``lp_rast.h``): 256 units a pixel.
FIXED_ORDER = 8
#: llvmpipe's tile side in pixels (``TILE_SIZE``, ``1 << TILE_ORDER`` in ``lp_limits.h``).
TILE = 64
#: The longest box (px) llvmpipe steps in 32 bits: ``1 << ((32/2 - 1) - FIXED_ORDER)``
#: (``lp_rast.h``): a difference of 2**15 units times one of 2**15 is 2**30, and E, a
#: difference of two such products, stays within a signed 32-bit register.
MAX_FIXED_LENGTH32 = 1 << ((32 // 2 - 1) - FIXED_ORDER)

#: What :func:`bin_rows` calls each tile of the box.
TILE_KINDS = ("empty", "exit", "untested", "full", "partial")


def floor_pot(n: int) -> int:
    """The largest power of two at most ``n`` (0 for 0): Mesa's ``floor_pot`` (``u_math.h``).

    >>> [floor_pot(n) for n in (0, 1, 3, 4, 63, 64)]
    [0, 1, 2, 4, 32, 64]
    """
    return 1 << (int(n).bit_length() - 1) if n else 0


def steps_in_32_bits(x0: int, x1: int, y0: int, y1: int) -> bool:
    """True when llvmpipe steps a triangle with pixel box columns ``x0..x1``, rows ``y0..y1``
    (both inclusive) in 32-bit integers, False when in 64-bit (``lp_setup_tri.c``).

    The test is on whole pixels: the last pixel's offsets from the box's start rounded down to
    a multiple of 4 (where its 4×4 blocks begin), x and y OR-ed, at most
    :data:`MAX_FIXED_LENGTH32`. Two offsets below 128 OR to less than 128, so a box of at most
    128 px each way from a 4-aligned start always passes. The OR is not a maximum: offsets of
    128 pass only with offsets of 0 or 128 (a 129 × 129 px box passes, a 129 × 128 one fails).

    >>> steps_in_32_bits(0, 127, 0, 127), steps_in_32_bits(0, 128, 0, 128)
    (True, True)
    >>> steps_in_32_bits(0, 128, 0, 127), steps_in_32_bits(2, 129, 0, 127)
    (False, False)
    """
    return ((x1 - (x0 & ~3)) | (y1 - (y0 & ~3))) <= MAX_FIXED_LENGTH32


def _edge(a, b, u, v):
    # the edge function of a -> b at (u, v), as lesson 02's
    return (b[0] - a[0]) * (v - a[1]) - (b[1] - a[1]) * (u - a[0])


def _outside_at_best(xy, orient, u, v) -> list[bool]:
    # for each edge: negative even at the largest of the block corners (u, v), i.e. outside
    edges = zip(xy, np.roll(xy, -1, axis=0))
    return [bool((orient * _edge(a, b, u, v)).max() < 0) for a, b in edges]


def _box(xy):
    # llvmpipe's box: pixel centres on whole numbers, 1/256 px units, inclusive ends
    pos = np.rint((np.asarray(xy, float) - 0.5) * 2**FIXED_ORDER).astype(int)
    (x0, y0), (x1, y1) = pos.min(axis=0) >> FIXED_ORDER, (pos.max(axis=0) - 1) >> FIXED_ORDER
    return int(x0), int(y0), int(x1), int(y1)


def small_triangle_command(xy):
    """The command ``lp_setup_bin_triangle`` (``lp_setup_tri.c``) gives triangle ``xy``.

    A triangle whose box crosses no 64-pixel tile boundary is binned straight into its one
    tile, with no 64-level test: ``TRIANGLE_3_4`` when the box fits one 4-aligned 4×4 stamp
    (its 16 centres tested, no block test), ``TRIANGLE_3_16`` when it fits a 16×16 block
    aligned to 4 (its sixteen 4×4 blocks tested for reject, then the 16 centres of each block
    kept). llvmpipe tests a 4×4 block's best corner one pixel step beyond its last centre (the
    next block's first centre), so it keeps blocks the exact corner test would reject.

    Parameters
    ----------
    xy : array_like, (3, 2)
        The vertices in pixels (x right, y down).

    Returns
    -------
    command : str
        ``"TRIANGLE_3_4"``, ``"TRIANGLE_3_16"``, ``"its one tile, from the 16x16 blocks"`` or
        ``"the tile walk (§9)"`` (the box crosses a tile boundary).
    columns : tuple of int
        The box's first and last pixel column (inclusive).
    block_tests, pixel_tests : int or None
        The tests the 16-pixel commands make; None for the others.
    """
    xy = np.asarray(xy, float)
    x0, y0, x1, y1 = _box(xy)
    if floor_pot((x0 ^ x1) | (y0 ^ y1)) >= TILE:  # it crosses a 64-pixel tile boundary
        return "the tile walk (§9)", (x0, x1), None, None
    sz = floor_pot((x1 - (x0 & ~3)) | (y1 - (y0 & ~3)))
    if sz < 4:  # one 4-aligned 4x4 stamp: its 16 centres, no block test
        return "TRIANGLE_3_4", (x0, x1), 0, 16
    if sz >= 16:
        return "its one tile, from the 16x16 blocks", (x0, x1), None, None
    # a 16x16 block at the box's 4-aligned corner, kept inside the tile
    bx = x0 - x0 % TILE + min(x0 % TILE & ~3, TILE - 16)
    by = y0 - y0 % TILE + min(y0 % TILE & ~3, TILE - 16)
    orient = np.sign(_edge(xy[0], xy[1], *xy[2]))
    kept = 0
    for r in range(by, by + 16, 4):
        for c in range(bx, bx + 16, 4):
            u, v = np.meshgrid([c + 0.5, c + 4.5], [r + 0.5, r + 4.5])  # 4 steps beyond
            kept += not any(_outside_at_best(xy, orient, u, v))
    return "TRIANGLE_3_16", (x0, x1), 16, 16 * kept


def bin_rows(xy, n_rows: int, n_cols: int) -> np.ndarray:
    """``lp_setup_bin_triangle``'s loop over the 64×64 tiles of a box (``lp_setup_tri.c``).

    The box starts at pixel (0, 0) here. Each tile is tested at its first pixel centre and 64
    steps on (the next tile's first centre, where Mesa adds ``eo`` and ``ei << TILE_ORDER``);
    once a row has entered the triangle, its first outside tile ends the row (the triangle is
    convex: nothing further on the row is inside).

    Parameters
    ----------
    xy : array_like, (3, 2)
        The (snapped) vertices in pixels.
    n_rows, n_cols : int
        The box's tiles.

    Returns
    -------
    numpy.ndarray, (n_rows, n_cols) of str
        Each tile's kind (:data:`TILE_KINDS`): ``"empty"`` (outside an edge before the
        triangle, counted as ``nr_empty_64``), ``"exit"`` (outside, ends its row, not
        counted), ``"untested"`` (after an exit), ``"full"`` (inside all three edges: the
        ``lp_rast_shade_tile`` command) or ``"partial"`` (the triangle command).

    Examples
    --------
    >>> bin_rows([[10.5, 10.5], [200.5, 10.5], [10.5, 120.5]], 2, 4).tolist()
    [['partial', 'partial', 'partial', 'partial'], ['partial', 'partial', 'exit', 'untested']]
    """
    xy = np.asarray(xy, float)
    orient = np.sign(_edge(xy[0], xy[1], *xy[2]))
    kind = np.full((n_rows, n_cols), "untested", dtype=object)
    for r in range(n_rows):
        inside = False
        for c in range(n_cols):
            u, v = np.meshgrid([TILE * c + 0.5, TILE * c + TILE + 0.5],
                               [TILE * r + 0.5, TILE * r + TILE + 0.5])  # fmt: skip
            if any(_outside_at_best(xy, orient, u, v)):
                kind[r, c] = "exit" if inside else "empty"
                if inside:
                    break
                continue
            edges = zip(xy, np.roll(xy, -1, axis=0))
            full = all((orient * _edge(a, b, u, v)).min() >= 0 for a, b in edges)
            kind[r, c] = "full" if full else "partial"
            inside = True
    return kind
