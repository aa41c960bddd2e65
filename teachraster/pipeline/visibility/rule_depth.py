"""The z-buffer with a caller's rule: one call per pixel, its fragments in drawing order.

:mod:`.zbuffer` decides for all pixels at once with the package's test (strictly nearer than
the depth last written passes). A caller (a student's ``depth_passes`` in the course's
capstone, :mod:`teachraster.pipeline.planning.overrides`) can decide instead with
``rule(depths, writes)``: for each pixel with fragments, it gets their depths (as the buffer
stores them) and depth masks, in drawing order, and returns which of them pass. The pixel
then shows the last fragment that passed and keeps the depth of the last that passed and
wrote (:func:`.zbuffer.last_written`), as with the package's test.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np


def passed_by_rule(pixel: np.ndarray, depth: np.ndarray, writes, rule: Callable) -> np.ndarray:
    """(m,) bool: which fragments ``rule`` lets pass, asked once per pixel.

    ``pixel`` (m,) flat indices and ``depth`` (m,) of the fragments in drawing order,
    ``writes`` (m,) bool depth masks (None: all write). The rule's answer must hold one
    truth value per fragment of the pixel (ValueError otherwise).

    >>> less = lambda d, w: [i == 0 or d[i] < min(d[:i]) for i in range(len(d))]
    >>> passed_by_rule(np.array([3, 3, 1, 3]), np.array([0.5, 0.7, 0.2, 0.1]), None,
    ...                less).tolist()
    [True, False, True, True]
    """
    m = len(pixel)
    passed = np.ones(m, dtype=bool)
    if m == 0:
        return passed
    masks = np.ones(m, dtype=bool) if writes is None else np.asarray(writes, dtype=bool)
    order = np.argsort(pixel, kind="stable")  # by pixel, drawing order inside
    pix = pixel[order]
    starts = np.flatnonzero(np.r_[True, pix[1:] != pix[:-1]])
    for start, stop in zip(starts.tolist(), np.r_[starts[1:], m].tolist()):
        group = order[start:stop]
        answer = np.asarray(rule(depth[group].copy(), masks[group].copy()))
        if answer.shape != (len(group),):
            raise ValueError(
                f"the depth rule must return one truth value per fragment ({len(group)} "
                f"here), got shape {answer.shape}"
            )
        passed[group] = answer.astype(bool)
    return passed
