"""The z-buffer resolved for a whole batch of fragments (Ritschel, *Interpolation and z-buffering*).

A GPU keeps, per pixel, the depth of the nearest fragment so far and tests each arriving
fragment against it: strictly nearer wins, so of equal depths the earlier fragment stays.
Here all fragments of a frame are known at once, and the same answer follows in one pass
whatever the depth complexity: the buffer's final value is the *minimum* depth at each pixel
(one ``np.minimum.at``), and the fragment shown is the earliest fragment that reaches it (a
second ``np.minimum.at`` over fragment indices). Without the depth test the last fragment
drawn wins (``np.maximum.at``). Each costs O(fragments), not O(fragments × layers).

Whether each fragment passed the test *when it arrived* (the trace) is a running minimum
in drawing order per pixel, computed only when asked (:func:`passed_on_arrival`).

>>> pixel, depth = np.array([5, 5, 5, 2]), np.array([0.5, 0.25, 0.25, 0.75])
>>> resolve(pixel, depth, 8, depth_test=True)[0][[2, 5]].tolist()   # ties keep the earlier
[3, 1]
>>> passed_on_arrival(pixel, depth).tolist()
[True, True, False, True]
"""

from __future__ import annotations

import numpy as np


def resolve(pixel: np.ndarray, depth: np.ndarray, n_pixels: int, depth_test: bool):
    """The winning fragment per pixel (-1 none) and the number of contested pixels.

    Parameters
    ----------
    pixel : (m,) int64
        Flat pixel index of every fragment, fragments in drawing order.
    depth : (m,) float64
        Their stored depths (finite).
    n_pixels : int
        Pixels in the frame.
    depth_test : bool
        With the test the strictly nearer fragment wins (ties keep the earlier); without it
        the last one drawn wins.

    Returns
    -------
    winner : (n_pixels,) int64
        Index of the fragment each pixel shows, -1 where none arrives.
    tested : int
        Pixels that 2+ fragments reach (where a GPU's test decides something).
    """
    m = len(pixel)
    count = np.bincount(pixel, minlength=n_pixels)
    tested = int((count > 1).sum())
    index = np.arange(m)
    if tested == 0:  # one fragment per pixel at most: nothing to resolve
        winner = np.full(n_pixels, -1, dtype=np.int64)
        winner[pixel] = index
        return winner, tested
    if not depth_test:  # painter's order: the last fragment drawn wins
        winner = np.full(n_pixels, -1, dtype=np.int64)
        np.maximum.at(winner, pixel, index)
        return winner, tested
    nearest = np.full(n_pixels, np.inf)
    np.minimum.at(nearest, pixel, depth)
    # Of the fragments at the nearest depth, the earliest: it arrived first and nothing
    # after it was strictly nearer, exactly what the sequential test keeps.
    ties = np.flatnonzero(depth == nearest[pixel])
    winner = np.full(n_pixels, m, dtype=np.int64)
    np.minimum.at(winner, pixel[ties], ties)
    winner[winner == m] = -1
    return winner, tested


def passed_on_arrival(pixel: np.ndarray, depth: np.ndarray) -> np.ndarray:
    """(m,) bool: did each fragment pass the depth test when it arrived (drawing order)?

    A fragment passes when it is strictly nearer than every earlier fragment at its pixel.
    Fragments are grouped by pixel (a stable sort keeps drawing order within a pixel) and a
    running minimum of depth *ranks* is taken per group: ranks are integers, so the groups
    can be offset to keep one running maximum from leaking across pixels.
    """
    m = len(pixel)
    if m == 0:
        return np.ones(0, dtype=bool)
    order = np.argsort(pixel, kind="stable")
    pix = pixel[order]
    group = np.cumsum(np.r_[False, pix[1:] != pix[:-1]])
    _, rank = np.unique(depth[order], return_inverse=True)  # equal depths, equal rank
    # Running minimum of rank within each group, as a running maximum of
    # group * m + (m - 1 - rank): later groups always exceed earlier ones.
    key = group * m + (m - 1 - rank)
    best = np.maximum.accumulate(key)
    before = np.r_[-1, best[:-1]]  # the best key before each fragment
    new_group = np.r_[True, pix[1:] != pix[:-1]]
    passed_sorted = new_group | (key > before)  # strictly smaller rank than all before
    passed = np.empty(m, dtype=bool)
    passed[order] = passed_sorted
    return passed
