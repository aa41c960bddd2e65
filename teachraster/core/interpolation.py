"""Affine (screen-space) and perspective-correct interpolation.

Ek, *Triangles and Perspective Correct Interpolation*, §2; Ritschel, *Interpolation and
z-buffering*; Fatahalian, CMU 15-462 *Texture*.

Screen-space barycentrics λ are affine in (x, y). Under perspective a vertex attribute f
is *not*: what is affine in screen space is f/w and 1/w (Ek, *Triangles and Perspective Correct Interpolation*, eq. 19; Fatahalian, CMU 15-462 *Texture*). So

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

#: Modes of :func:`teachraster.rasterize`: also the cheaper subdivided perspective.
FILL_MODES = (*MODES, "subdivided")


def perspective_weights(lam: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Perspective-correct weights μ_i = (λ_i / w_i) / Σ_j (λ_j / w_j).

    When all w are equal the division changes nothing mathematically, so λ is returned
    as it is: affine interpolation is then exact (and skips a per-pixel divide).

    >>> perspective_weights(np.array([[0.5, 0.5, 0.0]]), np.array([1.0, 3.0, 1.0]))
    array([[0.75, 0.25, 0.  ]])
    """
    if np.all(w == w[0]):
        return lam
    return weights_per_row(lam, np.broadcast_to(w, lam.shape))


def weights_per_row(lam: np.ndarray, w: np.ndarray) -> np.ndarray:
    """:func:`perspective_weights` with its own three w on every row: lam, w (n, 3)."""
    # λ_i / w_i is affine in screen space, like 1/w itself. Only the ratios of w matter,
    # so scale by each row's smallest w: 1/w alone overflows for tiny (even subnormal) w.
    with np.errstate(under="ignore"):
        q = lam * (w.min(axis=-1, keepdims=True) / w)
    total = q[..., 0] + q[..., 1] + q[..., 2]
    # Ratios of w beyond the float range (1e200 against 1e-200) can still underflow every
    # term of a row to 0; those rows are redone in logarithms, where nothing overflows.
    bad = ~(total > 0)
    if bad.any():
        with np.errstate(divide="ignore"):  # log(0) = -inf: a zero weight stays zero
            lq = np.log(lam[bad]) - np.log(w[bad])
        q[bad] = np.exp(lq - lq.max(axis=-1, keepdims=True))
        total[bad] = q[bad].sum(axis=-1)
    q /= total[..., None]
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


def blend_each(weights: np.ndarray, values: np.ndarray, index=None) -> np.ndarray:
    """:func:`blend` with different vertex values per row: weights (n, 3), values (n, 3, k).

    With ``index`` (n,), ``values`` holds one (3, k) block per triangle (M, 3, k) and row i
    uses block ``index[i]``, gathered here one channel at a time (cheaper than gathering
    the whole (n, 3, k) block first).

    >>> blend_each(np.array([[0.5, 0.5, 0.0]]), np.array([[[0.0], [2.0], [9.0]]]))
    array([[1.]])
    """
    n, k = len(weights), values.shape[2]
    out = np.empty((n, k))
    # One contiguous 1-D array per weight and per vertex value: written out per vertex and
    # per channel, because reductions over an axis of length 3, and arithmetic on strided
    # (n, 3, k) views, are slow in numpy.
    m0, m1, m2 = (np.ascontiguousarray(weights[:, i]) for i in range(3))
    for j in range(k):
        if index is None:
            v0, v1, v2 = (np.ascontiguousarray(values[:, i, j]) for i in range(3))
        else:
            v0, v1, v2 = (np.ascontiguousarray(values[:, i, j])[index] for i in range(3))
        with np.errstate(over="ignore"):  # values near the float maximum: the clamp below
            o = m0 * v0  # brings an overflowed sum back to the finite extreme value
            o += m1 * v1
            o += m2 * v2
        np.maximum(o, np.minimum(np.minimum(v0, v1), v2), out=o)
        np.minimum(o, np.maximum(np.maximum(v0, v1), v2), out=o)
        out[:, j] = o
    return out


def interpolate(lam: np.ndarray, values: np.ndarray, w: np.ndarray, mode: str) -> np.ndarray:
    """Interpolate vertex ``values`` at pixels with barycentrics ``lam`` (n, 3)."""
    weights = perspective_weights(lam, w) if mode == "perspective" else lam
    return blend(weights, values)


def subdivided(
    lam: np.ndarray, rows: np.ndarray, values: np.ndarray, w: np.ndarray, step: int
) -> np.ndarray:
    """Perspective-correct every ``step``-th pixel of each span, affine in between.

    The classic speed trick of software renderers (Quake's texture mapper, Hecker's
    articles): the per-pixel divide is paid only at the span's start, at every ``step``-th
    pixel and at its end; the pixels between two such anchors are interpolated linearly
    in screen space from the anchors' exact values. ``step = 1`` is exact perspective.

    Parameters
    ----------
    lam : (n, 3)
        Barycentrics of the covered pixels, in row-major order.
    rows : (n,)
        Their rows; each row's pixels form one contiguous span (a triangle is convex).
    values : (3,) or (3, k)
        Vertex values.
    w : (3,)
        Vertex w.
    step : int
        Pixels between exact evaluations.

    >>> lam = np.array([[1 - t, t, 0.0] for t in np.linspace(0, 1, 5)])
    >>> exact = interpolate(lam, np.array([0.0, 1.0, 0.0]), np.array([1.0, 4.0, 1.0]),
    ...                     "perspective")
    >>> sub = subdivided(lam, np.zeros(5, int), np.array([0.0, 1.0, 0.0]),
    ...                  np.array([1.0, 4.0, 1.0]), 2)
    >>> bool(np.allclose(sub[::2], exact[::2])), bool(np.allclose(sub, exact))
    (True, False)
    """
    n = len(lam)
    if n == 0:
        return blend(lam, values)
    new_row = np.r_[True, rows[1:] != rows[:-1]]
    first = np.flatnonzero(new_row)
    last = np.r_[first[1:], n] - 1
    span = np.cumsum(new_row) - 1
    index = np.arange(n)
    offset = index - first[span]  # position along the span
    anchor = (offset % step == 0) | (index == last[span])
    exact = blend(perspective_weights(lam[anchor], w), values)  # the only divides
    slot = np.cumsum(anchor) - 1  # where each anchor's value sits in `exact`
    a0 = first[span] + (offset // step) * step
    a1 = np.minimum(a0 + step, last[span])
    t = np.where(a1 > a0, (index - a0) / np.maximum(a1 - a0, 1), 0.0)
    f0, f1 = exact[slot[a0]], exact[slot[a1]]
    t = t.reshape(-1, *([1] * (f0.ndim - 1)))
    out = f0 + t * (f1 - f0)
    flat = values.reshape(3, -1)
    lo, hi = flat.min(axis=0), flat.max(axis=0)
    return np.clip(out.reshape(n, -1), lo, hi).reshape(out.shape)
