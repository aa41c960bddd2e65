"""Barycentric coordinates as ratios of areas (Ritschel, *Interpolation and z-buffering*), computed relative to a vertex.

``λ_A(P) = t(P, B, C) / t(A, B, C)`` and its two rotations: each weight is the area of the
sub-triangle opposite a vertex over the whole area. Each area is an edge function, which
is evaluated from differences ``p - a`` to a vertex of the edge. Evaluating the same
quantity as a plane ``A x + B y + C`` in absolute coordinates instead cancels
catastrophically far from the origin (Fatahalian, CMU 15-462 *Texture*: "you have greater precision near the
origin").
"""

from __future__ import annotations

import numpy as np

from .edges import EdgeSetup, edge_values_at
from .validate import as_finite


def barycentric(xy, points) -> np.ndarray:
    """Screen-space barycentric coordinates of ``points`` in the triangle ``xy``.

    Parameters
    ----------
    xy : (3, 2) array-like
        Triangle vertices, pixels.
    points : (..., 2) array-like
        Points to locate.

    Returns
    -------
    (..., 3) float64
        Weights of vertices 0, 1, 2; they sum to 1. A zero-area triangle has no
        barycentric coordinates: a ``ValueError`` says so.

    Examples
    --------
    >>> barycentric([[0, 0], [4, 0], [0, 4]], [[1, 1], [0, 0]])
    array([[0.5 , 0.25, 0.25],
           [1.  , 0.  , 0.  ]])
    """
    v = as_finite("xy", xy, (3, 2))
    p = as_finite("points", points, None)
    if p.shape[-1:] != (2,):
        raise ValueError(f"points must have shape (..., 2), got {p.shape}")
    (ax, ay), (bx, by), (cx, cy) = v
    area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if area2 == 0:
        raise ValueError("xy: zero-area triangle has no barycentric coordinates")
    x, y = p[..., 0], p[..., 1]
    # Each sub-area relative to a vertex of its own edge: no large absolute products.
    l0 = ((cx - bx) * (y - by) - (cy - by) * (x - bx)) / area2
    l1 = ((ax - cx) * (y - cy) - (ay - cy) * (x - cx)) / area2
    l2 = ((bx - ax) * (y - ay) - (by - ay) * (x - ax)) / area2
    return np.stack([l0, l1, l2], axis=-1)


def barycentric_pixels(setup: EdgeSetup, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Barycentrics at pixel centres from the exact edge functions, original vertex order.

    On the snapped grid the edge values are exact integers, so each weight is one
    correctly-rounded division: weights are in [0, 1] inside coverage and sum to 1 within
    a few ulps.
    """
    return barycentric_from_edges(setup, edge_values_at(setup, rows, cols))


def barycentric_from_edges(setup: EdgeSetup, e: np.ndarray) -> np.ndarray:
    """Barycentrics (n, 3), original vertex order, from edge values E (n, 3) of ``setup``.

    However E was obtained (evaluated per pixel, or stepped across a block), the same exact
    integers give the same weights, bit for bit.
    """
    e = e.astype(np.float64)
    lam = np.empty_like(e)
    # The weight of oriented vertex k is the edge opposite it: E_{k+1} (p_{k+1} -> p_{k+2}).
    area2 = float(setup.area2)
    for k in range(3):
        lam[:, setup.perm[k]] = e[:, (k + 1) % 3] / area2
    return lam
