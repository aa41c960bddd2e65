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

The test itself, the compare and what ``depth_test=False`` means, is :func:`passes_depth_test`
and nowhere else (the developers' brief: one place for each rule, every consumer reads
it): the depth stage, MSAA's per-sample test, the pixel history's replay, Hi-Z and the
overlays call it, or :func:`passed_on_arrival` and :func:`resolve`, which do;
:func:`surely_in_front` is the one bound the shortcuts (MSAA's whole pixels, Hi-Z) use to
skip the test where its answer is already known. tests/test_depth_test_one_place.py
checks that no other module writes the compare again.

>>> pixel, depth = np.array([5, 5, 5, 2]), np.array([0.5, 0.25, 0.25, 0.75])
>>> resolve(pixel, depth, 8, depth_test=True)[0][[2, 5]].tolist()   # ties keep the earlier
[3, 1]
>>> passed_on_arrival(pixel, depth).tolist()
[True, True, False, True]
"""

from __future__ import annotations

import numpy as np

#: The compare op :func:`passes_depth_test` applies, with the test on and off, as the APIs name
#: it (``GL_LESS`` / ``VK_COMPARE_OP_LESS``, ``GL_ALWAYS``): what a pixel history's header says
#: (review r298 S1: it said "depth test on" and never which compare).
COMPARE_ON, COMPARE_OFF = "LESS", "ALWAYS"


def passes_depth_test(depth, buffer, depth_test: bool = True) -> np.ndarray:
    """Does a fragment (or sample) with stored depth ``depth`` pass the depth test against
    the value ``buffer`` it finds there? Elementwise, broadcast: the one place the test is
    decided.

    With the test on it is GL's default ``GL_LESS`` (the glDepthFunc reference page:
    "passes if the incoming depth value is less than the stored depth value"; Ritschel,
    *Interpolation and z-buffering*): strictly nearer passes, so of equal depths the one
    already in the buffer stays (ties keep the earlier). The empty buffer holds +inf, so
    any finite depth passes there and an infinite one does not. A NaN depth compares false
    and never passes (so it is never written). Off (``depth_test=False``) every fragment
    passes whatever its depth, NaN included (``GL_ALWAYS``): the last one drawn shows and,
    where it writes depth, leaves its own (``frame.depth``).

    Parameters
    ----------
    depth, buffer : array-like of float
        The incoming stored depths and the buffer's values, broadcast against each other.
    depth_test : bool
        Whether the test is on.

    Returns
    -------
    passed : ndarray of bool
        The broadcast shape of ``depth`` and ``buffer``.

    >>> passes_depth_test([0.25, 0.5, 0.75, np.nan, np.inf], [0.5, 0.5, 0.5, 0.5, np.inf]).tolist()
    [True, False, False, False, False]
    >>> passes_depth_test([0.75, np.nan], 0.5, depth_test=False).tolist()
    [True, True]
    """
    depth, buffer = np.asarray(depth), np.asarray(buffer)
    if not depth_test:
        return np.ones(np.broadcast_shapes(depth.shape, buffer.shape), dtype=bool)
    return depth < buffer


def surely_in_front(farthest, nearest) -> np.ndarray:
    """Elementwise: does a depth range whose far end is ``farthest`` lie wholly in front of
    one whose near end is ``nearest``, so that the test (:func:`passes_depth_test`, with the test
    on) keeps the first over the second at every sample whichever is drawn first: drawn
    later, the first passes against the second, and the second fails against the first?
    The bound of the shortcuts that skip the test where its answer is known: MSAA's whole
    pixels and dropped samples, the renderer's Hi-Z. Written with the compare, so it stays
    true for any monotone compare (with ``GL_LESS``: ``farthest < nearest``).

    >>> surely_in_front([0.25, 0.5, np.nan], [0.5, 0.5, 0.5]).tolist()   # equal: not sure
    [True, False, False]
    """
    return passes_depth_test(farthest, nearest) & ~passes_depth_test(nearest, farthest)


def resolve(pixel: np.ndarray, depth: np.ndarray, n_pixels: int, depth_test: bool):
    """The winning fragment per pixel (-1 none) and the number of contested pixels.

    Parameters
    ----------
    pixel : (m,) int64
        Flat pixel index of every fragment, fragments in drawing order.
    depth : (m,) float64
        Their stored depths.
    n_pixels : int
        Pixels in the frame.
    depth_test : bool
        With the test the strictly nearer fragment wins (ties keep the earlier; NaN and +inf
        never pass, :func:`passes_depth_test`); without it the last one drawn wins.

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
    # what passes against the empty buffer (+inf): every fragment without the test
    live = passes_depth_test(depth, np.inf, depth_test)
    if not live.all():
        pixel, depth, index = pixel[live], depth[live], index[live]
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
    # after it passed against it (:func:`passes_depth_test`), what the sequential test keeps.
    ties = depth == nearest[pixel]
    winner = np.full(n_pixels, m, dtype=np.int64)
    np.minimum.at(winner, pixel[ties], index[ties])
    winner[winner == m] = -1
    return winner, tested


def passed_on_arrival(pixel: np.ndarray, depth: np.ndarray, writes=None,
                      depth_test: bool = True) -> np.ndarray:  # fmt: skip
    """(m,) bool: did each fragment pass the depth test when it arrived (drawing order)?

    A fragment passes when :func:`passes_depth_test` says so against the buffer it finds: the
    nearest depth written before it at its pixel (its sample, when ``pixel`` numbers
    samples), +inf while none was. ``writes`` (m,) bool is each fragment's depth mask
    (GL's ``glDepthMask``; None: all write): a fragment that does not write is still
    tested, and leaves the buffer as it was; nor does one that fails (NaN, +inf) write.
    ``depth_test=False``: every fragment passes.

    Fragments are grouped by pixel (a stable sort keeps drawing order within a pixel) and
    the buffer each one found is the running minimum of the depths written before it in
    its group (:func:`running_min`; +inf for a fragment that writes nothing).

    >>> passed_on_arrival(np.array([0, 0, 0]), np.array([0.5, 0.7, 0.6]),
    ...                   np.array([False, True, True])).tolist()
    [True, True, True]
    """
    m = len(pixel)
    if m == 0 or not depth_test:
        return passes_depth_test(np.zeros(m), np.inf, depth_test)
    order = np.argsort(pixel, kind="stable")
    pix = pixel[order]
    ranked = depth[order]
    # a depth that passes nowhere is never written (a finite one that fails is no nearer
    # than the buffer, so writing it would not change the running minimum)
    mask = passes_depth_test(ranked, np.inf)
    if writes is not None:
        mask &= np.asarray(writes)[order]
    written = ranked if mask.all() else np.where(mask, ranked, np.inf)
    first = np.flatnonzero(np.r_[True, pix[1:] != pix[:-1]])
    longest = int(np.diff(np.r_[first, m]).max())
    buffer = np.empty(m)  # the buffer each fragment found: the running minimum before it
    buffer[1:] = running_min(pix, written, longest)[:-1]
    buffer[first] = np.inf  # a pixel's first fragment finds it empty
    passed = np.empty(m, dtype=bool)
    passed[order] = passes_depth_test(ranked, buffer)
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
