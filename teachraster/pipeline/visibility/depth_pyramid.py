"""Greene's depth pyramid and the bounding-box test made with it (lesson 10, §7).

Greene, Kass and Miller (*Hierarchical Z-Buffer Visibility*, 1993) keep the z-buffer at the
bottom of a pyramid; each value of a level above is the **farthest** of the 2×2 values below
it (a mipmap with the maximum in place of the mean, for ``GL_LESS``: nearer is smaller). An
object is hidden where even its nearest depth is no nearer than the farthest stored depth of
every value its screen bounding box overlaps: a coarse level reads few values but holds
loose ones, a fine level reads more, sharper ones. :func:`box_test` gives each level's
verdict over the whole box; :func:`greene_descent` makes Greene's test, which starts at the
finest level where one value covers the box and goes down a level only under the values
where the test fails. Engines make the same test against a pyramid of a depth buffer to
skip hidden objects before they are submitted.

>>> base = np.array([[1.0, 1.0, 1.0, 1.0], [1.0, 0.3, 0.3, 1.0],
...                  [0.3, 0.3, 0.3, 0.3], [0.3, 0.3, 0.3, 0.3]])
>>> [level.tolist() for level in farthest_pyramid(base, 2)[1:]]
[[[1.0, 1.0], [0.3, 0.3]], [[1.0]]]
>>> for row in box_test(farthest_pyramid(base, 2), (2, 3, 0, 1), nearest=0.5):
...     print(row)
BoxTest(level=2, cells=1, farthest=1.0, hidden=False)
BoxTest(level=1, cells=1, farthest=0.3, hidden=True)
BoxTest(level=0, cells=4, farthest=0.3, hidden=True)
>>> for row in greene_descent(farthest_pyramid(base, 2), (1, 2, 1, 2), nearest=0.5):
...     print(row)
BoxTest(level=2, cells=1, farthest=1.0, hidden=False)
BoxTest(level=1, cells=4, farthest=1.0, hidden=False)
BoxTest(level=0, cells=2, farthest=0.3, hidden=True)
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .zbuffer import passes_depth_test


class BoxTest(NamedTuple):
    """One level's verdict on a box: the values it reads, their farthest, hidden or not."""

    level: int
    cells: int
    farthest: float
    hidden: bool


def farthest_pyramid(base, levels: int) -> list[np.ndarray]:
    """``[base, level 1, ..., level levels]``, each value the farthest of the 2×2 below it.

    Parameters
    ----------
    base : array_like, (R, C)
        The finest level: stored depths (a z-buffer), or the farthest depth of each Hi-Z
        tile. ``R`` and ``C`` must be multiples of ``2**levels``.
    levels : int
        How many levels to build above ``base``.

    Returns
    -------
    list of numpy.ndarray
        Level ``k`` has shape ``(R / 2**k, C / 2**k)``.
    """
    grid = np.asarray(base, dtype=np.float64)
    if grid.ndim != 2 or levels < 0:
        raise ValueError("base must be 2-D and levels >= 0")
    if grid.shape[0] % 2**levels or grid.shape[1] % 2**levels:
        raise ValueError(f"base {grid.shape}: each side must be a multiple of {2**levels}")
    pyramid = [grid]
    for _ in range(levels):
        r, c = pyramid[-1].shape
        pyramid.append(pyramid[-1].reshape(r // 2, 2, c // 2, 2).max(axis=(1, 3)))
    return pyramid


def box_test(pyramid, box, nearest: float) -> list[BoxTest]:
    """The bounding-box test at every level of ``pyramid``, coarsest first.

    Parameters
    ----------
    pyramid : list of numpy.ndarray
        From :func:`farthest_pyramid`.
    box : tuple of int
        ``(row0, row1, col0, col1)``, inclusive, in cells of the pyramid's base.
    nearest : float
        The object's nearest depth.

    Returns
    -------
    list of BoxTest
        For each level: the number of its values the box overlaps, their farthest, and
        whether the object is hidden there (``nearest`` no nearer than that farthest:
        ``GL_LESS`` would fail every fragment of it).
    """
    row0, row1, col0, col1 = (int(v) for v in box)
    out = []
    for level in range(len(pyramid) - 1, -1, -1):
        cells = pyramid[level][row0 >> level : (row1 >> level) + 1,
                               col0 >> level : (col1 >> level) + 1]  # fmt: skip
        farthest = float(cells.max())
        hidden = not bool(passes_depth_test(nearest, farthest))  # GL_LESS fails everywhere
        out.append(BoxTest(level, int(cells.size), farthest, hidden))
    return out


def _start_level(pyramid, box) -> int:
    # the finest level at which one value covers the box (the top level if none does)
    row0, row1, col0, col1 = box
    for level in range(len(pyramid)):
        if row0 >> level == row1 >> level and col0 >> level == col1 >> level:
            return level
    return len(pyramid) - 1


def greene_descent(pyramid, box, nearest: float) -> list[BoxTest]:
    """Greene's bounding-box test: only the values a descent reads, level by level.

    It starts at the finest level where one value covers the box (the top level if none
    does) and goes down a level only under the values where the test fails (``nearest``
    nearer than the value), reading there only the children that overlap the box. It stops
    when no value read fails (the object is hidden) or at the base (a value fails there: the
    object may be visible).

    Parameters
    ----------
    pyramid : list of numpy.ndarray
        From :func:`farthest_pyramid`.
    box : tuple of int
        ``(row0, row1, col0, col1)``, inclusive, in cells of the pyramid's base.
    nearest : float
        The object's nearest depth.

    Returns
    -------
    list of BoxTest
        One per level visited, coarsest first: the values read there, their farthest, and
        whether none of them fails. The object is hidden when the last one is.
    """
    row0, row1, col0, col1 = (int(v) for v in box)
    level = _start_level(pyramid, (row0, row1, col0, col1))
    cells = [(r, c) for r in range(row0 >> level, (row1 >> level) + 1)
             for c in range(col0 >> level, (col1 >> level) + 1)]  # fmt: skip
    out = []
    while True:
        values = [float(pyramid[level][r, c]) for r, c in cells]
        # where the object's nearest depth would pass against the value, it may show there
        failing = [cell for cell, v in zip(cells, values) if passes_depth_test(nearest, v)]
        out.append(BoxTest(level, len(cells), max(values), not failing))
        if not failing or level == 0:
            return out
        level -= 1
        cells = [(r, c) for pr, pc in failing  # the children of a failing value, in the box
                 for r in range(max(2 * pr, row0 >> level), min(2 * pr + 1, row1 >> level) + 1)
                 for c in range(max(2 * pc, col0 >> level), min(2 * pc + 1, col1 >> level) + 1)]  # fmt: skip
