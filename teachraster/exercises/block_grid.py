"""The block grid both halves of exercise 08's checker share: the task's unit count, a grid's
integer arrays, its verdict texts and how two answers compare.

:mod:`.tile_blocks` (the cases, mistakes and figures) and :mod:`.block_arithmetic` (what float64
and int32 make of the arithmetic, r248 F1) both read these, so neither imports the other's
internals (lesson 10 §4: the count a GPU's grid keeps).

>>> verdicts(np.array([True, False]), np.array([False, True]), (2,), scalar=False).tolist()
['rejected', 'accepted']
"""

from __future__ import annotations

import numpy as np

#: The three verdicts a block can have.
KINDS = ("rejected", "accepted", "partial")

#: Units a pixel of the task's integer count (lesson 10 §4: Direct3D's and llvmpipe's 8
#: sub-pixel bits): vertices on the 1/256 grid and pixel centres are whole numbers of them.
UNITS = 256


def grid_of(x0, y0) -> tuple[np.ndarray, np.ndarray]:
    """``x0`` and ``y0`` as integer arrays of one shape (scalars: shape ())."""
    return np.broadcast_arrays(np.asarray(x0, dtype=np.int64), np.asarray(y0, dtype=np.int64))


def verdicts(rejected, accepted, shape, scalar: bool):
    """The verdict texts of a grid from its masks (one text for a scalar block)."""
    kinds = np.where(rejected, "rejected", np.where(accepted, "accepted", "partial"))
    kinds = np.asarray(kinds, dtype="<U8").reshape(shape)
    return str(kinds[()]) if scalar else kinds


def superscript(n: int) -> str:
    """``n`` in superscript digits.

    >>> superscript(19)
    '¹⁹'
    """
    return str(n).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))


def same_kind(got, expected, args) -> bool:
    """Do two answers give the same verdict for every block (shape included)?"""
    if isinstance(expected, str) or isinstance(got, str):
        return bool(np.all(np.asarray(got) == np.asarray(expected)))
    return np.shape(got) == np.shape(expected) and bool(np.all(got == expected))
