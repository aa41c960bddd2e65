"""Affine (screen-space) and perspective-correct interpolation (seeds 000, 003, 004).

Screen-space barycentrics λ are affine in (x, y). Under perspective a vertex attribute f
is *not*: what is affine in screen space is f/w and 1/w (seed 000, eq. 19; seed 004). So

- affine ("noperspective"):       f = Σ λ_i f_i
- perspective-correct ("smooth"): f = Σ λ_i f_i/w_i / Σ λ_i/w_i

Both are evaluated as ``Σ μ_i f_i`` with weights μ (λ itself, or the perspective
weights), then clamped to the range of the three vertex values. The weighted sum makes a
weight of exactly 0 contribute exactly nothing (so a pixel centre on a vertex gets that
vertex's value, and one on an edge ignores the opposite vertex); the clamp removes the
last-ulp overshoot that rounding can leave (depth never leaves [0, 1]) and makes an
attribute that is equal at all three vertices come out exactly constant.
"""

from __future__ import annotations

import numpy as np

MODES = ("perspective", "affine")


def perspective_weights(lam: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Perspective-correct weights μ_i = (λ_i / w_i) / Σ_j (λ_j / w_j).

    When all w are equal the division changes nothing mathematically, so λ is returned
    as it is: affine interpolation is then exact (and skips a per-pixel divide).

    >>> perspective_weights(np.array([[0.5, 0.5, 0.0]]), np.array([1.0, 3.0, 1.0]))
    array([[0.75, 0.25, 0.  ]])
    """
    if np.all(w == w[0]):
        return lam
    q = lam * (1.0 / w)  # λ_i / w_i: affine in screen space, like 1/w itself
    q /= (q[..., 0] + q[..., 1] + q[..., 2])[..., None]
    return q


def blend(weights: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``Σ μ_i f_i`` clamped to the vertex values' range, for values (3,) or (3, k).

    One matrix product for all pixels and attributes at once.

    >>> blend(np.array([[0.2, 0.3, 0.5]]), np.array([7.0, 7.0, 7.0]))
    array([7.])
    >>> blend(np.array([[0.0, 2 / 11, 9 / 11]]), np.array([1.0, 0.0, 0.0]))  # not -1e-16
    array([0.])
    """
    flat = values.reshape(3, -1)
    out = weights @ flat
    np.clip(out, flat.min(axis=0), flat.max(axis=0), out=out)
    return out.reshape(len(weights), *values.shape[1:])


def blend_each(weights: np.ndarray, values: np.ndarray) -> np.ndarray:
    """:func:`blend` with different vertex values per row: weights (n, 3), values (n, 3, k)."""
    v0, v1, v2 = values[:, 0], values[:, 1], values[:, 2]
    # Written out per vertex: reductions over an axis of length 3 are slow in numpy.
    out = weights[:, 0:1] * v0 + weights[:, 1:2] * v1 + weights[:, 2:3] * v2
    np.maximum(out, np.minimum(np.minimum(v0, v1), v2), out=out)
    np.minimum(out, np.maximum(np.maximum(v0, v1), v2), out=out)
    return out


def interpolate(lam: np.ndarray, values: np.ndarray, w: np.ndarray, mode: str) -> np.ndarray:
    """Interpolate vertex ``values`` at pixels with barycentrics ``lam`` (n, 3)."""
    weights = perspective_weights(lam, w) if mode == "perspective" else lam
    return blend(weights, values)
