"""A right colour with its channels in another order (ARGB, BGRA, reversed, two swapped): one
rule for every exercise whose answer is one colour (r286 M3: exercise 7.2's bilinear; r289
M1: 9.2a's over and 9.2b's atop told such an answer to go back through the derivation).
"""

from __future__ import annotations

import itertools

import numpy as np

from .exercise import Mistake
from .tolerance import all_close

#: The orders a student's code likeliest writes, tried first: where a colour repeats a value,
#: several orders give the same numbers, and the words name the likeliest of them.
_LIKELY = {
    4: ((3, 0, 1, 2), (2, 1, 0, 3), (3, 2, 1, 0), (3, 1, 2, 0), (1, 2, 3, 0)),
    3: ((2, 1, 0),),
}


def other_order(expected, got, tol: float) -> tuple[int, ...] | None:
    """The order ``perm`` in which ``got`` holds ``expected``'s channels (got[k] =
    expected[perm[k]] within ``tol``), where ``got`` is not ``expected`` itself; None if there
    is none (a colour of 2 to 4 channels only)."""
    e, g = np.asarray(expected, float).ravel(), np.asarray(got, float).ravel()
    if e.shape != g.shape or not 2 <= e.size <= 4 or not np.isfinite(g).all():
        return None
    if all_close(g, e, tol):
        return None
    for perm in (*_LIKELY.get(e.size, ()), *itertools.permutations(range(e.size))):
        if all_close(g, e[list(perm)], tol):
            return perm
    return None


def order_name(perm, names: str = "RGBA") -> str:
    """ "ARGB for RGBA", "BGR for RGB, reversed", "ABGR … (R and A swapped)"."""
    letters = names[: len(perm)]
    name = "".join(letters[i] for i in perm) + f" for {letters}"
    moved = [k for k, i in enumerate(perm) if i != k]
    if tuple(perm) == tuple(range(len(perm)))[::-1] and len(perm) > 2:
        return name + ", reversed"
    if len(moved) == 2:
        return name + f", {letters[moved[0]]} and {letters[moved[1]]} swapped"
    return name


def channel_order_mistake(lead: str, tail: str, *, tol: float, kind: str = "channel order",
                          names: str = "RGBA") -> Mistake:  # fmt: skip
    """The mistake: ``lead`` (the order) ``tail``, named only where every failing answer is
    the right one in another order (a grey or a repeated value passes in any order)."""

    def fits(args, expected, got):
        return other_order(expected, got, tol) is not None

    def words(args, expected, got):
        perm = other_order(expected, got, tol)
        return f"{lead} ({order_name(perm, names)}){tail}"

    return Mistake(kind, words, fits=fits, only_whole=True)
