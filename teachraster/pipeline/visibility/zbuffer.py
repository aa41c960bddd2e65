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


def passed_on_arrival(pixel: np.ndarray, depth: np.ndarray, writes=None) -> np.ndarray:
    """(m,) bool: did each fragment pass the depth test when it arrived (drawing order)?

    A fragment passes when it is strictly nearer than every earlier fragment at its pixel
    *that wrote depth*: ``writes`` (m,) bool is each fragment's depth mask (GL's
    ``glDepthMask``; None: all write). A fragment that does not write is still tested,
    and leaves the buffer as it was.

    Fragments are grouped by pixel (a stable sort keeps drawing order within a pixel) and
    the buffer each one found is the running minimum of the depths written before it in
    its group (:func:`running_min`; +inf for a fragment that writes nothing).

    >>> passed_on_arrival(np.array([0, 0, 0]), np.array([0.5, 0.7, 0.6]),
    ...                   np.array([False, True, True])).tolist()
    [True, True, True]
    """
    m = len(pixel)
    if m == 0:
        return np.ones(0, dtype=bool)
    order = np.argsort(pixel, kind="stable")
    pix = pixel[order]
    ranked = depth[order]
    written = ranked if writes is None else np.where(np.asarray(writes)[order], ranked, np.inf)
    first = np.flatnonzero(np.r_[True, pix[1:] != pix[:-1]])
    longest = int(np.diff(np.r_[first, m]).max())
    buffer = np.empty(m)  # the buffer each fragment found: the running minimum before it
    buffer[1:] = running_min(pix, written, longest)[:-1]
    buffer[first] = np.inf  # a pixel's first fragment finds it empty
    passed = np.empty(m, dtype=bool)
    passed[order] = ranked < buffer
    return passed


def running_min(group_key: np.ndarray, values: np.ndarray, longest: int) -> np.ndarray:
    """Running minimum of ``values`` within runs of equal ``group_key`` (sorted input) no
    longer than ``longest``: log2(longest) doubling steps, each one pass over the array.

    >>> running_min(np.array([0, 0, 0, 1, 1]), np.array([3.0, 1.0, 2.0, 5.0, 4.0]), 3).tolist()
    [3.0, 1.0, 1.0, 5.0, 4.0]
    """
    out = values.copy()
    step = 1
    while step < longest:
        same = group_key[step:] == group_key[:-step]
        np.minimum(out[step:], np.where(same, out[:-step], np.inf), out=out[step:])
        step *= 2
    return out


def last_written(pixel: np.ndarray, passed: np.ndarray, writes, n_pixels: int):
    """Per pixel, the last fragment that passed (the one whose colour and id the pixel
    keeps: later passes overwrite) and the last that passed *and* wrote depth (the one
    whose depth the buffer keeps), -1 where none; fragments in drawing order.

    With every fragment writing and the test on, both are :func:`resolve`'s winner.

    >>> last_written(np.array([1, 1, 1]), np.array([True, True, False]),
    ...              np.array([True, False, True]), 3)[1].tolist()
    [-1, 0, -1]
    """
    index = np.arange(len(pixel))
    shown = np.full(n_pixels, -1, dtype=np.int64)
    np.maximum.at(shown, pixel[passed], index[passed])
    if writes is None:
        return shown, shown
    stored = np.full(n_pixels, -1, dtype=np.int64)
    keep = passed & np.asarray(writes)
    np.maximum.at(stored, pixel[keep], index[keep])
    return shown, stored
