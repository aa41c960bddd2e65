"""The record of a tiled fill: every classified block, its counters, visit orders, captions.

Plain arrays and small frozen dataclasses, as every trace (see :mod:`.trace`); the walker
that fills them in is :mod:`.tiles`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .bbox import BBox
from .traversal import TRAVERSALS, traversal_rank
from .validate import as_int, check_choice

#: llvmpipe's block sizes, largest first.
BLOCK_SIZES = (64, 16, 4)
#: Block kinds, by their code in :attr:`TileTrace.kind_code`.
KINDS = ("rejected", "accepted", "partial")
REJECTED, ACCEPTED, PARTIAL = 0, 1, 2


def edge_name(a, b) -> str:
    """The name of the directed edge from vertex index ``a`` to ``b`` (indices from 0).

    Vertices are v1, v2, v3 in the order given (index 0 is v1), and an edge is named by its
    two vertices in walking order: ``edge_name(0, 1)`` is ``"E12"``, the edge v1→v2 whose edge
    function is E(v1, v2, p); a triangle walked the other way has E13, E32, E21.

    >>> [edge_name(a, b) for a, b in [(0, 1), (1, 2), (2, 0)]]
    ['E12', 'E23', 'E31']
    """
    return f"E{int(a) + 1}{int(b) + 1}"


def value_text(value: float) -> str:
    """An edge function's value in a caption: three significant digits below 100, the whole
    number with thousands separators from 100 on, as the course prints counts ("1.2e+03"
    beside the block counts read as a count in another notation: review r12, lesson 10).

    >>> [value_text(v) for v in (0.0123, 2.5, -13.76, 999.6, 1234.56, -120000.0, 0.0)]
    ['0.0123', '2.5', '-13.8', '1,000', '1,235', '-120,000', '0']
    """
    value = float(value)
    return f"{value:,.0f}" if abs(value) >= 99.95 else f"{value:.3g}"


def check_block_sizes(block_sizes) -> tuple[int, ...]:
    """``block_sizes`` as a tuple of positive ints, each dividing the one before.

    >>> check_block_sizes([64, 16, 4])
    (64, 16, 4)
    >>> check_block_sizes((8, 3))
    Traceback (most recent call last):
    ...
    ValueError: block_sizes: each size must divide the one before, got (8, 3)
    """
    if isinstance(block_sizes, str | bytes) or not hasattr(block_sizes, "__iter__"):
        raise TypeError(f"block_sizes must be a sequence of ints, got {block_sizes!r}")
    sizes = tuple(as_int("block_sizes", s, minimum=1) for s in block_sizes)
    if not sizes:
        raise ValueError("block_sizes must hold at least one size, got ()")
    if any(a % b or a == b for a, b in zip(sizes, sizes[1:])):
        raise ValueError(
            f"block_sizes: each size must divide the one before, got {tuple(block_sizes)}"
        )
    return sizes


@dataclass(frozen=True)
class BlockCounters:
    """llvmpipe-style counters (``nr_empty_64``, ``nr_fully_covered_16``, ...).

    ``empty``, ``full``, ``partial`` hold one count per block size (largest first);
    ``pixel_tests`` counts the pixel centres tested one by one (those of partial blocks of
    the smallest size, inside the image; when the smallest size is 1, every 1×1 block, whose
    corner test is the pixel test), ``non_empty`` the smallest partial blocks with at least
    one covered pixel (llvmpipe's ``nr_non_empty_4``) and ``pixels_accepted`` the pixels
    filled by accepted blocks larger than 1×1, without any test of their own.
    """

    sizes: tuple[int, ...]
    empty: tuple[int, ...]
    full: tuple[int, ...]
    partial: tuple[int, ...]
    pixel_tests: int
    non_empty: int
    pixels_accepted: int

    @property
    def blocks(self) -> int:
        """Blocks classified, at all sizes (1×1 blocks included, which are also pixel tests)."""
        return sum(self.empty) + sum(self.full) + sum(self.partial)

    @property
    def tests(self) -> int:
        """Every test the walk ran, each once: block tests above 1×1 and pixel tests."""
        ones = [e + f + p for s, e, f, p in zip(self.sizes, self.empty, self.full, self.partial)
                if s == 1]  # fmt: skip
        return self.blocks - sum(ones) + self.pixel_tests

    def table(self) -> list[tuple[str, int, int, int]]:
        """Rows ``(size label, empty, full, partial)``, largest size first."""
        return [
            (f"{s}×{s}", e, f, p)
            for s, e, f, p in zip(self.sizes, self.empty, self.full, self.partial)
        ]

    def summary(self) -> str:
        """One line: rejected / accepted / partial blocks per size, then the pixel tests.

        The words are the lessons' (llvmpipe's counters call them empty / full / partial);
        counts carry thousands separators, as the lessons print them.

        >>> BlockCounters((16, 4), (2, 10), (1, 0), (3, 1200), 9600, 0, 256).summary()
        '16×16: 2 rejected / 1 accepted / 3 partial; 4×4: 10 rejected / 0 accepted / 1,200 partial; 9,600 pixel tests'
        """
        parts = [
            f"{lab}: {e:,} rejected / {f:,} accepted / {p:,} partial"
            for lab, e, f, p in self.table()
        ]
        return "; ".join(parts) + f"; {self.pixel_tests:,} pixel tests"  # 1,184 as the lessons


@dataclass(frozen=True)
class TileTrace:
    """What the tiled fill did: every classified block, in visit order (depth first).

    Siblings (the top-level blocks over the bounding box, the children of a partial block)
    are visited in scanline order; :meth:`visit_order` gives the other traversals.

    Attributes
    ----------
    block_sizes : tuple of int
        Block sizes, largest first.
    size, row, col : (n,) int
        Size of each block and its top-left pixel (image indices).
    kind_code : (n,) int8
        0 rejected, 1 accepted, 2 partial (see :attr:`kind`).
    level : (n,) int8
        Index of the block's size in ``block_sizes``.
    parent : (n,) int64
        Index (in these arrays) of the partial block it was split from, -1 at the top.
    extent : (n, 2) int
        Rows and columns of the block inside the image (smaller at the image border).
    e_max, e_min : (n, 3) int64 or float64
        Each edge's value at the block's largest and smallest corner (internal units²):
        the values the reject and accept decisions were taken on.
    covered : (n,) int
        Covered pixels inside each block.
    rejected_by : (n,) int8
        Position (in test order) of the edge that rejected the block, -1 if not rejected.
    crossing : (n, 3) bool
        Edges that include one extreme corner and exclude the other (they cross a
        block that no edge rejects: what makes it partial).
    sibling : (n, 2) int
        Row and column of each block in the grid of its siblings.
    grids : tuple of (rows, cols)
        Shape of the sibling grid at each level: the top-level blocks over the bounding
        box, then q × q children (q = ratio of consecutive sizes).
    counters : BlockCounters
        Counted by the walker as it classified.
    px2_per_unit2 : float
        Converts ``e_max``/``e_min`` to px².
    """

    block_sizes: tuple[int, ...]
    size: np.ndarray
    row: np.ndarray
    col: np.ndarray
    kind_code: np.ndarray
    level: np.ndarray
    parent: np.ndarray
    extent: np.ndarray
    e_max: np.ndarray
    e_min: np.ndarray
    covered: np.ndarray
    counters: BlockCounters
    px2_per_unit2: float
    rejected_by: np.ndarray
    crossing: np.ndarray
    sibling: np.ndarray
    grids: tuple[tuple[int, int], ...]

    def __len__(self) -> int:
        return len(self.size)

    @property
    def kind(self) -> np.ndarray:
        """(n,) str: "rejected", "accepted" or "partial"."""
        return np.array(KINDS)[self.kind_code]

    @property
    def pixel_tests(self) -> np.ndarray:
        """(n,) int: pixel centres tested one by one in each block (smallest partial only, or
        every 1×1 block: its corner test is the pixel test)."""
        smallest = self.level == len(self.block_sizes) - 1
        if self.block_sizes[-1] > 1:
            smallest &= self.kind_code == PARTIAL
        return np.where(smallest, self.extent[:, 0] * self.extent[:, 1], 0)

    def at_level(self, level: int) -> np.ndarray:
        """Indices (in visit order) of the blocks of size ``block_sizes[level]``."""
        return np.flatnonzero(self.level == level)

    def visit_order(self, traversal: str = "scanline") -> np.ndarray:
        """Permutation of the blocks: depth first, siblings in the ``traversal`` order.

        ``"tiled"`` groups siblings in 2 × 2 tiles. ``visit_order("scanline")`` is
        ``arange(n)``: the order the arrays are stored in.
        """
        check_choice("traversal", traversal, TRAVERSALS)
        rank = np.zeros(len(self), dtype=np.int64)
        for lev, grid in enumerate(self.grids):  # one vectorised ranking per level
            idx = self.at_level(lev)
            i, j = self.sibling[idx, 0], self.sibling[idx, 1]
            rank[idx] = traversal_rank(i, j, grid, traversal, tile=2)
        return depth_first(self.parent, self.level, rank)

    def leaf_steps(self, box: BBox, first: int) -> np.ndarray:
        """(rows, cols) int32 over ``box``: the step of the block that decided each pixel.

        Block ``b`` is step ``first + b``. Every pixel of the box lies in exactly one block
        that is not split: rejected, accepted, or partial of the smallest size (its pixel
        tests). -1 where no block was classified (empty box, zero area).
        """
        out = np.full(box.shape, -1, dtype=np.int32)
        last = len(self.block_sizes) - 1
        leaves = (self.kind_code != PARTIAL) | (self.level == last)
        for b in np.flatnonzero(leaves):  # one slice per block (never per pixel)
            r0, c0 = self.row[b] - box.row0, self.col[b] - box.col0
            r1, c1 = r0 + self.extent[b, 0], c0 + self.extent[b, 1]
            out[max(r0, 0) : max(r1, 0), max(c0, 0) : max(c1, 0)] = first + b
        return out

    def setup_caption(self) -> str:
        """The set-up step: block sizes and the top-level blocks to classify."""
        sizes = ", ".join(f"{s}×{s}" for s in self.block_sizes)
        top = int((self.level == 0).sum())
        if not top:
            return f"blocks of {sizes} px: no block to classify (empty box or zero area)"
        rows, cols = self.grids[0]
        s = self.block_sizes[0]
        blocks = f"{top} top-level {s}×{s} blocks ({rows} × {cols}) overlap"
        if top == 1:
            blocks = f"one top-level {s}×{s} block overlaps"
        return (
            f"blocks of {sizes} px: {blocks} the bounding box; each is classified by its "
            "corners, partial ones are split"
        )

    def caption(
        self, b: int, edges: np.ndarray, shape: tuple[int, int] | None = None,
        box: BBox | None = None,
    ) -> str:  # fmt: skip
        """One line on block ``b``: where it is, the deciding edge values, the verdict.

        ``shape``: the image's (height, width), to say so when a block is all of it (its
        outline is then the image's frame, and a step that splits it seems to change nothing:
        review r20, lesson 00's player). ``box``: the bounding box the pictures draw; a
        smallest partial block reaching out of it says how many of its tests lie inside
        (review r23; since review r77 00-2 the player draws them all).
        """
        s, kind = int(self.size[b]), int(self.kind_code[b])
        rows, cols = (int(v) for v in self.extent[b])
        where = f"{s}×{s} block at (row {self.row[b]}, col {self.col[b]})"
        if (rows, cols) != (s, s):
            where += f", {rows}×{cols} inside the image"
        if shape is not None and (self.row[b], self.col[b], rows, cols) == (0, 0, *shape):
            where += " (the whole image, outlined by its frame)"
        name = [edge_name(a, c) for a, c in edges]
        if kind == REJECTED:
            k = int(self.rejected_by[b])
            # a 1x1 block has one centre: its test is the pixel test (review r264 S7)
            at = "its centre" if s == 1 else "its most inside corner"
            why = (
                f"{name[k]} = {value_text(self.e_max[b, k] * self.px2_per_unit2)} at {at} "
                f"fails: rejected, {'it is not' if s == 1 else 'no pixel of it is'} covered"
            )
        elif kind == ACCEPTED:
            low = ", ".join(
                f"{n} = {value_text(v * self.px2_per_unit2)}" for n, v in zip(name, self.e_min[b])
            )
            if s == 1:  # its one corner is its centre: this test is the pixel test (counted so)
                why = f"every edge passes at its centre ({low}): accepted, its pixel test passed, "
                why += "the pixel is written"
            else:
                why = (
                    f"every edge passes at its least inside corner ({low}): accepted, "
                    f"{rows * cols:,} pixel{'s' if rows * cols != 1 else ''} filled with no "
                    "pixel test"
                )
        else:
            names = [n for n, c in zip(name, self.crossing[b]) if c]
            crossing = " and ".join([", ".join(names[:-1]), names[-1]] if len(names) > 1 else names)
            verb = "crosses" if self.crossing[b].sum() == 1 else "cross"
            if self.level[b] < len(self.block_sizes) - 1:
                child = self.block_sizes[self.level[b] + 1]
                then = f"split into {child}×{child} blocks"
            else:
                then = f"{rows * cols:,} pixel tests"
                if box is not None:
                    r0, c0 = int(self.row[b]), int(self.col[b])
                    inside = max(0, min(r0 + rows, box.row1) - max(r0, box.row0)) * max(
                        0, min(c0 + cols, box.col1) - max(c0, box.col0)
                    )
                    if inside < rows * cols:
                        then += f" ({rows * cols - inside:,} of them outside the bounding box)"
                then += f", {int(self.covered[b]):,} covered"
            why = f"{crossing} {verb} it: partial, {then}"
        return f"{where}: {why}"


def depth_first(parent: np.ndarray, level: np.ndarray, rank: np.ndarray) -> np.ndarray:
    """Permutation listing every block before its children, siblings by ``rank``."""
    n = len(parent)
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    depth = int(level.max()) + 1
    keys = np.full((n, depth), -1, dtype=np.int64)
    for lev in range(depth):  # parents come from the level above, already keyed
        idx = np.flatnonzero(level == lev)
        if lev:
            keys[idx, :lev] = keys[parent[idx], :lev]
        keys[idx, lev] = rank[idx]
    return np.lexsort(keys.T[::-1])
