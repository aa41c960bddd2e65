"""The z-buffer resolved for a whole batch of fragments (Ritschel, *Interpolation and z-buffering*).

A GPU keeps, per pixel, the depth of the nearest fragment so far and tests each arriving
fragment against it. Here all fragments of a frame are known at once, so the same answer is
computed for every pixel together: which fragment the pixel finally shows, and whether each
fragment passed the test *when it arrived* (for the trace).
"""

from __future__ import annotations

import numpy as np


def resolve(pixel: np.ndarray, depth: np.ndarray, n_pixels: int, depth_test: bool, force: bool):
    """The winning fragment per pixel (-1 none), per-fragment pass flags, pixels tested.

    Parameters
    ----------
    pixel : (m,) int64
        Flat pixel index of every fragment, fragments in drawing order.
    depth : (m,) float64
        Their stored depths.
    n_pixels : int
        Pixels in the frame.
    depth_test : bool
        With the test the strictly nearer fragment wins (ties keep the earlier); without it
        the last one drawn wins.
    force : bool
        Test every fragment, even at pixels only one fragment reaches.

    Returns
    -------
    winner : (n_pixels,) int64
    passed : (m,) bool
    tested : int
        Pixels that fragments of 2+ triangles reach.
    """
    count = np.bincount(pixel, minlength=n_pixels)
    multi = count[pixel] > 1
    tested = int((count > 1).sum())
    winner = np.full(n_pixels, -1, dtype=np.int64)
    single = np.flatnonzero(~multi)
    winner[pixel[single]] = single
    passed = np.ones(len(pixel), dtype=bool)
    idx = np.arange(len(pixel)) if force else np.flatnonzero(multi)
    if len(idx) == 0:
        return winner, passed, tested
    # Group the contested fragments by pixel, keeping drawing order within each pixel.
    order = idx[np.argsort(pixel[idx], kind="stable")]
    pix = pixel[order]
    starts = np.flatnonzero(np.r_[True, pix[1:] != pix[:-1]])
    rank = np.arange(len(order)) - np.repeat(starts, np.diff(np.r_[starts, len(order)]))
    if not depth_test:  # painter's order: the last fragment drawn wins
        last = np.r_[starts[1:], len(order)] - 1
        winner[pix[last]] = order[last]
        return winner, passed, tested
    # One layer at a time: layer r holds the r-th fragment of every contested pixel, so
    # each layer touches a pixel at most once and the buffer update is a plain scatter.
    buffer = np.full(n_pixels, np.inf)
    for r in range(int(rank.max()) + 1):
        layer = order[rank == r]
        p = pixel[layer]
        ok = depth[layer] < buffer[p]
        passed[layer] = ok
        buffer[p[ok]] = depth[layer[ok]]
        winner[p[ok]] = layer[ok]
    return winner, passed, tested
