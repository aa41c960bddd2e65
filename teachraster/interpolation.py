"""Affine (screen-space) and perspective-correct interpolation (seeds 000, 003, 004).

Screen-space barycentrics λ are affine in (x, y). Under perspective a vertex attribute f
is *not*: what is affine in screen space is f/w and 1/w (seed 000, eq. 19; seed 004). So

- affine ("noperspective"):       f = Σ λ_i f_i
- perspective-correct ("smooth"): f = Σ λ_i f_i/w_i / Σ λ_i/w_i

Both are written as ``f_0 + μ_1 (f_1 - f_0) + μ_2 (f_2 - f_0)`` (recentred at vertex 0,
seed 004), so an attribute that is the same at all three vertices comes out exactly
constant, with no rounding at all.
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
    """``f_0 + μ_1 (f_1 - f_0) + μ_2 (f_2 - f_0)`` for values (3,) or (3, k).

    Evaluated as one matrix product ``[1, μ_1, μ_2] @ [f_0; f_1 - f_0; f_2 - f_0]`` for all
    pixels and attributes at once. For a constant attribute the differences are exactly
    zero, so the result is exactly f_0 whatever order the sum is taken in.

    >>> blend(np.array([[0.2, 0.3, 0.5]]), np.array([7.0, 7.0, 7.0]))
    array([7.])
    """
    f0 = values[0]
    rows = np.stack([f0, values[1] - f0, values[2] - f0]).reshape(3, -1)
    ones = np.array(weights, dtype=np.float64)  # a copy: column 0 becomes the 1 of f_0
    ones[:, 0] = 1.0
    return (ones @ rows).reshape(len(weights), *values.shape[1:])


def interpolate(lam: np.ndarray, values: np.ndarray, w: np.ndarray, mode: str) -> np.ndarray:
    """Interpolate vertex ``values`` at pixels with barycentrics ``lam`` (n, 3)."""
    weights = perspective_weights(lam, w) if mode == "perspective" else lam
    return blend(weights, values)
