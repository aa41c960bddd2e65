"""What a ``fill`` over the triangle's bounding box gets wrong, and a point a tiny step off the
centre (r352 1-3): found from the rule's images, for :mod:`.coverage_checks` to name.

- A box clamped to the image at its upper end only: a negative row (column) index wraps round
  in numpy (``image[-1]`` is the last row), so the pixels of the box above (left of) the image
  land in its last rows (columns), wherever the box's real rows did not overwrite them
  (:func:`wrapped_images`).
- A box one row or column short at any side (``range(ceil(min), …)``, ``round``, ``… − 1``):
  the student's image is the rule's restricted to a box one short at some sides
  (:func:`short_sides`).
- A point a tiny step off the centre (``j + 0.5 + 1e-6``): the rule's image sampled there,
  found exactly by the step's direction alone: a centre off every edge keeps its side, one
  on an edge goes to the side the step takes it (:func:`nudged_direction`).
"""

from __future__ import annotations

import itertools

import numpy as np

from ..core.edges import passes
from . import coverage as cov
from .cases import CoverageCase


def box(case: CoverageCase, xy) -> tuple[int, int, int, int]:
    """(first row, end row, first column, end column) of the right box loop, not clamped:
    range(floor(min), ceil(max)) in the case's window."""
    v = np.asarray(xy, dtype=float) - np.asarray(case.origin, dtype=float)
    lo, hi = np.floor(v.min(axis=0)).astype(int), np.ceil(v.max(axis=0)).astype(int)
    return int(lo[1]), int(hi[1]), int(lo[0]), int(hi[0])


def _source(n: int, start: int, end: int) -> np.ndarray:
    """For each index 0 … n − 1 of one axis, the loop index whose write it keeps last (-n … n
    − 1; a negative one wrapped round), or n where no write reaches it. The loop runs start
    … end − 1 with end clamped to n, start not; an index below −n would raise (IndexError),
    and is left out (a student who catches it)."""
    out = np.full(n, n)
    for k in range(max(start, -n), min(end, n)):  # in loop order: the last write wins
        out[k % n] = k
    return out


def wrapped_images(case: CoverageCase, expected: np.ndarray) -> np.ndarray:
    """(n, h, w): a box loop clamped at its upper end only, ``range(floor(min), min(n,
    ceil(max)))``, on every triangle of the case."""
    w, h = case.size
    out = np.zeros_like(expected)
    for t, xy in enumerate(case.triangles):
        r0, r1, c0, c1 = box(case, xy)
        rows, cols = _source(h, r0, r1), _source(w, c0, c1)
        lo_r, lo_c = min(int(rows.min()), 0), min(int(cols.min()), 0)
        # the rule's image on the window grown by the rows (columns) above (left of) it, and
        # one empty row and column more: index n, which no write reaches
        x0, y0 = case.origin
        grown = CoverageCase(case.label, xy[None], (x0 + lo_c, y0 + lo_r), (w - lo_c, h - lo_r))
        image = np.pad(cov.expected_coverage(grown, xy), ((0, 1), (0, 1)))
        out[t] = image[np.ix_(rows - lo_r, cols - lo_c)]
    return out


def wrapped_source(case: CoverageCase, xy, i: int, j: int) -> tuple[int, int]:
    """The box's (row, column) whose verdict the wrapping loop writes into pixel [i, j]."""
    w, h = case.size
    r0, r1, c0, c1 = box(case, xy)
    return int(_source(h, r0, r1)[i]), int(_source(w, c0, c1)[j])


#: A box's sides, in the order (top, bottom, left, right) of :func:`short_sides`.
SIDES = ("first row", "last row", "first column", "last column")
_SHRINKS = sorted(itertools.product((0, 1), repeat=4), key=sum)


def short_sides(case: CoverageCase, expected, got) -> list[tuple[int, int, int, int]] | None:
    """Per triangle, the fewest sides (top, bottom, left, right: 1 where one row or column
    short) of its box that give the student's image as the rule's restricted to the box so
    shrunk (clamped to the image), or None where no such box gives it (nothing extra is
    allowed) or none is short."""
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return None
    w, h = case.size
    out = []
    for xy, e, g in zip(case.triangles, expected, got):
        r0, r1, c0, c1 = box(case, xy)
        # r453 H7: one short of the last centre inside, floor(max − ½), not of ceil(max) − 1
        # (range(…, floor(x_max − 0.5)) is one short where the fraction is ½ or less too)
        ec, er = np.floor((np.asarray(xy, dtype=float) - case.origin).max(axis=0) - 0.5)
        for t, b, lft, r in _SHRINKS:
            end_r, end_c = (int(er) if b else r1), (int(ec) if r else c1)
            mask = np.zeros((h, w), dtype=bool)
            mask[
                max(r0 + t, 0) : max(min(end_r, h), 0), max(c0 + lft, 0) : max(min(end_c, w), 0)
            ] = True
            if np.array_equal(g, e & mask):
                out.append((t, b, lft, r))
                break
        else:
            return None
    return out if any(map(any, out)) else None


#: Directions of a tiny step off the centre: (sx, sy), x right, y down; along x or y first
#: (the simpler words, where a case cannot tell one from a diagonal). (1, 0) gives the
#: top-left rule's own pixels and (-1, 0) the top-right rule's, named with the tie rules.
DIRECTIONS = [(0, 1), (0, -1), (1, 0), (-1, 0), (1, 1), (-1, -1), (1, -1), (-1, 1)]


def _nudged(case: CoverageCase, xy, s) -> tuple[np.ndarray, np.ndarray]:
    """(the rule's (h, w) image at the centres moved a tiny step in direction ``s``, the
    pixels whose centre lies on an edge a diagonal step runs along: there a float computation
    of E goes either side by its rounding). A step along x or y leaves E exactly 0 on an edge
    parallel to it, and the tie rule decides there: the step up is then told apart from a
    tie test by the edge's x direction alone (own the edges running left), which differs on
    vertical edges only."""
    w, h = case.size
    rows, cols = np.indices((h, w))
    points = np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], -1)
    e, kinds, area, v = cov._edge_data(np.asarray(xy, dtype=float), points.reshape(-1, 2),
                                       "snapped")  # fmt: skip
    if area == 0:
        return np.zeros((h, w), dtype=bool), np.zeros((h, w), dtype=bool)
    inside, loose = np.ones(h * w, dtype=bool), np.zeros(h * w, dtype=bool)
    for k in range(3):
        d = v[(k + 1) % 3] - v[k]
        slope = -d[1] * s[0] + d[0] * s[1]  # E's change along the step
        tie = e[k] == 0
        loose |= tie & (slope == 0) & (s[0] != 0) & (s[1] != 0)
        inside &= passes(np.where(tie, slope, e[k]), kinds[k] in cov.TOP_LEFT)
    return inside.reshape(h, w), loose.reshape(h, w)


def nudged_direction(case: CoverageCase, expected, got) -> tuple[int, int] | None:
    """The direction (sx, sy) of a tiny step off the centre that gives the student's every
    image of this case (every wrong centre on an edge), or None."""
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return None
    ties = []
    for xy in case.triangles:
        e = cov.centre_values(case, xy)[0] if cov.area2(xy) != 0 else None
        ties.append(None if e is None else (e == 0).any(axis=0) & (e >= 0).all(axis=0))
    for e, g, tie in zip(expected, got, ties):
        if (g != e).any() and (tie is None or not tie[g != e].all()):
            return None
    for s in DIRECTIONS:
        images = [_nudged(case, xy, s) for xy in case.triangles]
        if all(np.array_equal(g[~loose], im[~loose]) for g, (im, loose) in zip(got, images)):
            return s
    return None
