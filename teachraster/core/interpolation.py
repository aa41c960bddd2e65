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

Inside coverage the weights are made convex first (:func:`convex_weights`), so every
covered pixel centre gets a finite value within the range of the vertex values whatever
the w ratios (see :func:`weights_per_row` for why this is guaranteed). Every function
here takes ``extrapolate=True`` for evaluation points *outside* the triangle (MSAA pixel
centres, helper pixels of a 2×2 quad): the weights are then used as given, negative ones
included, and nothing is clamped.
"""

from __future__ import annotations

import numpy as np

from .validate import as_real

MODES = ("perspective", "affine")

#: Modes of :func:`teachraster.rasterize`: also the cheaper subdivided perspective.
FILL_MODES = (*MODES, "subdivided")


def convex_weights(lam: np.ndarray) -> np.ndarray:
    """Barycentrics made a convex combination: every weight >= 0, each row summing to 1.

    A pixel centre that is *covered* lies inside the triangle, so its true weights are
    already convex. Computed ones can still come out slightly negative: ``tr.render``
    decides coverage on the snapped triangle but sets up the weights from the unsnapped
    positions (as llvmpipe does), and a centre that snapping brought inside an edge lies a
    hair outside the unsnapped one. Such weights are clamped to 0 and their row
    renormalised (the nearest convex weights up to rounding); rows that are already
    non-negative are returned bit for bit, so vertices (a weight of exactly 1) and edges
    (exactly 0) keep their exact values. Two degenerate cases that only rounding can
    produce are settled explicitly so that the result is *always* convex: a weight that
    overflowed to +inf (a set-up area that underflowed) takes the whole row, and a row
    whose weights were all <= 0 (or NaN) becomes (1/3, 1/3, 1/3).

    >>> convex_weights(np.array([[-0.25, 0.5, 0.75], [0.2, 0.3, 0.5]]))
    array([[0. , 0.4, 0.6],
           [0.2, 0.3, 0.5]])
    """
    lam = np.asarray(lam, dtype=np.float64)
    if lam.size == 0 or _plainly_convex(lam):
        return lam
    # A NaN or an infinite weight makes its row's total NaN or infinite, so negative weights
    # and bad totals are all there is to find (written per column: faster than axis=-1).
    negative = (lam[..., 0] < 0) | (lam[..., 1] < 0) | (lam[..., 2] < 0)
    with np.errstate(invalid="ignore", over="ignore"):  # inf - inf, 1e308 + 1e308: fixed below
        total = lam[..., 0] + lam[..., 1] + lam[..., 2]
    fix = negative | ~((total > 0) & (total < np.inf))
    if not fix.any():
        return lam
    out = lam.copy()
    rows = np.fmax(out[fix], 0.0)  # fmax: a NaN weight (never from finite input) counts as 0
    huge = np.isposinf(rows)
    some = huge.any(axis=-1)
    rows[some] = huge[some]
    # Divided by their largest entry first, so that the sum cannot overflow (weights near
    # the float maximum); the largest entry becomes exactly 1.
    top = rows.max(axis=-1, keepdims=True)
    none = ~(top[:, 0] > 0)
    rows[none], top[none] = 1.0, 1.0
    rows /= top
    out[fix] = rows / rows.sum(axis=-1, keepdims=True)
    return out


def _plainly_convex(lam: np.ndarray) -> bool:
    """Whether every row is already fine: weights in [0, 2], positive sums (the usual case).

    Whole-array reductions and one matrix product, several times faster than the per-row
    tests, which then run only when some weight is negative, huge or NaN (NaN fails
    ``min() >= 0``). Weights <= 2 cannot overflow a sum.
    """
    return bool(lam.min() >= 0 and lam.max() <= 2.0 and ((lam @ _ONES) > 0).all())


_ONES = np.ones(3)


def perspective_weights(lam: np.ndarray, w: np.ndarray, *, extrapolate: bool = False) -> np.ndarray:
    """Perspective-correct weights μ_i = (λ_i / w_i) / Σ_j (λ_j / w_j).

    When all w are equal the division changes nothing mathematically, so λ is returned
    as it is: affine interpolation is then exact (and skips a per-pixel divide).

    By default λ first goes through :func:`convex_weights`, which makes μ a convex
    combination for every row (see :func:`weights_per_row` for why); ``extrapolate=True``
    keeps λ as given, for evaluation points outside the triangle (MSAA pixel centres,
    helper pixels) that must extrapolate the triangle's interpolation.

    >>> perspective_weights(np.array([[0.5, 0.5, 0.0]]), np.array([1.0, 3.0, 1.0]))
    array([[0.75, 0.25, 0.  ]])
    >>> perspective_weights([[0.5, 0.5, 0.0]], [1, -3, 1])
    Traceback (most recent call last):
    ...
    ValueError: w must be > 0 and finite for every vertex (a vertex on or behind the eye has no perspective weight), got [1.0, -3.0, 1.0]
    """
    lam, w = _checked_weights(lam, w)
    if np.all(w == w[0]):
        return lam if extrapolate else convex_weights(lam)
    return weights_per_row(lam, np.broadcast_to(w, lam.shape), extrapolate=extrapolate)


def _checked_weights(lam, w) -> tuple[np.ndarray, np.ndarray]:
    """``lam`` (..., 3) and ``w`` (3,) of :func:`perspective_weights`, or an error naming them.

    Float64 arrays (the rasterisers' own, already checked) pass with O(1) shape tests only.
    """
    if not (isinstance(lam, np.ndarray) and lam.dtype == np.float64):
        lam = as_real("lam", lam)
    if lam.ndim < 1 or lam.shape[-1] != 3:
        raise ValueError(f"lam must have shape (..., 3): three weights per point, got {lam.shape}")
    w = as_real("w", w, (3,))
    if not ((w > 0) & (w < np.inf)).all():
        raise ValueError(
            "w must be > 0 and finite for every vertex (a vertex on or behind the eye has no "
            f"perspective weight), got {w.tolist()}"
        )
    return lam, w


def weights_per_row(lam: np.ndarray, w: np.ndarray, *, extrapolate: bool = False) -> np.ndarray:
    """:func:`perspective_weights` with its own three w on every row: lam, w (n, 3).

    Why the result is always a convex combination (finite, >= 0, summing to 1): λ is
    made convex first (:func:`convex_weights`), and each w_i > 0 is replaced by the ratio
    ``min(w) / w_i`` in (0, 1] (only ratios of w matter), so every q_i = λ_i min(w)/w_i
    lies in [0, 1]: nothing can overflow and no two terms can cancel, the total is in
    [0, 3] and the vertex holding the smallest w keeps its full λ. The total can be 0
    only when every q with λ_i > 0 underflowed (w ratios beyond ~1e308); those rows are
    redone in logarithms, where the largest term becomes exactly 1 (λ has a positive
    entry, so its log is finite). Dividing each q_i by a total >= q_i then gives weights
    in [0, 1].

    ``extrapolate=True`` skips the clamping of λ, for evaluation points outside the
    triangle: there the total may legitimately be <= 0 (the point lies beyond the
    horizon of the triangle's plane, where 1/w changes sign); such rows come out
    non-finite, as on a GPU (no log-domain rescue: a logarithm needs positive weights). A
    row whose every term underflowed is scaled again by the smallest w among the vertices
    with λ_i ≠ 0 (the smallest w may be that of a vertex whose λ is 0): λ = (0, ½, ½) with
    w = (1e-310, 1e300, 1e300) gives (0, ½, ½), not NaN.
    """
    if lam.ndim != 2:  # one point (3,) or a grid (h, w, 3): the rows' rescues index a total
        # per row, which one point's 0-d total cannot take (r421: a raw TypeError at
        # w = (1e-310, 1e300, 1e300), where every term underflows)
        rows = weights_per_row(lam.reshape(-1, 3), np.broadcast_to(w, lam.shape).reshape(-1, 3),
                               extrapolate=extrapolate)  # fmt: skip
        return rows.reshape(lam.shape)
    if not extrapolate:
        lam = convex_weights(lam)
    # λ_i / w_i is affine in screen space, like 1/w itself. Only the ratios of w matter,
    # so scale by each row's smallest w: 1/w alone overflows for tiny (even subnormal) w.
    smallest = np.minimum(np.minimum(w[..., 0], w[..., 1]), w[..., 2])[..., None]
    with np.errstate(under="ignore"):  # (a reduction over an axis of 3 is slow in numpy)
        q = lam * (smallest / w)
    total = q[..., 0] + q[..., 1] + q[..., 2]
    if extrapolate:
        # r348 F1: the smallest w may belong to a vertex whose λ is 0 (a point on the edge
        # opposite it), and every other term underflow (w 1e-310 against 1e300): those rows
        # are scaled again by the smallest w among the vertices that weigh, where the term
        # of that vertex is its λ itself
        redo = total == 0
        if redo.any():
            q[redo] = _scaled_by_weighing(lam[redo], w[redo])
            total[redo] = q[redo].sum(axis=-1)
        with np.errstate(divide="ignore", invalid="ignore"):
            return q / total[..., None]
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


def _scaled_by_weighing(lam: np.ndarray, w: np.ndarray) -> np.ndarray:
    """λ_i · s / w_i, s the smallest w among each row's vertices with λ_i ≠ 0 (a term of 0
    where λ_i = 0: never 0 · inf); a row of three zero λ stays zero."""
    weighing = lam != 0
    s = np.min(np.where(weighing, w, np.inf), axis=-1, keepdims=True)
    with np.errstate(under="ignore", invalid="ignore", over="ignore"):
        return np.where(weighing, lam * (s / w), 0.0)


def normalised_weights(q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Convex weights from unnormalised terms, in place: ``max(q_i, 0) / Σ_j max(q_j, 0)``.

    ``q`` (n, 3) holds ``λ_i s_i`` for any positive per-row factors ``s_i``; with
    ``s_i = min(w) / w_i`` the result is :func:`weights_per_row` of λ (ratios of 1/w,
    Ek, *Triangles and Perspective Correct Interpolation*, eq. 19), computed without
    normalising λ first: clamping λ_i to 0 and scaling its row by a constant are both
    undone by the final division. That is why a renderer can fold ``s_i / area`` into the
    barycentric pass and skip the per-pixel ``λ = E / area`` divide (see
    ``Fragments.weights_at(..., scale=)``). Rows whose total is not in (0, inf) (every term
    underflowed or was clamped, a NaN or an overflow from a degenerate set-up) are
    returned as ``bad`` and left for the caller to redo with :func:`weights_per_row`,
    which settles them; every other row is convex (each term in [0, total]).

    >>> q, bad = normalised_weights(np.array([[-1.0, 1.0, 3.0], [0.0, 0.0, 0.0]]))
    >>> q[0], bad
    (array([0.  , 0.25, 0.75]), array([False,  True]))
    """
    np.maximum(q, 0.0, out=q)  # a NaN stays NaN, and its row is bad
    with np.errstate(over="ignore", invalid="ignore"):
        total = q[..., 0] + q[..., 1] + q[..., 2]
    if len(total) and total.min() > 0 and total.max() < np.inf:  # the usual case, two passes
        bad = np.zeros(len(total), dtype=bool)
    else:  # NaN fails both tests
        bad = ~((total > 0) & (total < np.inf))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        q /= total[..., None]  # not * (1 / total): a subnormal total's reciprocal overflows
    return q, bad


def blend(weights: np.ndarray, values: np.ndarray, *, extrapolate: bool = False) -> np.ndarray:
    """``Σ μ_i f_i`` clamped to the vertex values' range, for values (3,) or (3, k).

    One matrix product for all pixels and attributes at once. With convex weights the
    sum lies in the range up to rounding; the clamp removes that last-ulp overshoot (and
    an overflow to ±inf when the values are near the float maximum, which it brings back
    to the finite extreme value). ``extrapolate=True`` leaves the sum unclamped.

    >>> blend(np.array([[0.2, 0.3, 0.5]]), np.array([7.0, 7.0, 7.0]))
    array([7.])
    >>> blend(np.array([[0.0, 2 / 11, 9 / 11]]), np.array([1.0, 0.0, 0.0]))  # not -1e-16
    array([0.])
    """
    flat = values.reshape(3, -1)
    if extrapolate:
        out = _unclamped(weights, flat)
    else:
        with np.errstate(over="ignore"):
            out = weights @ flat
        np.clip(out, flat.min(axis=0), flat.max(axis=0), out=out)
    return out.reshape(len(weights), *values.shape[1:])


def _unclamped(weights: np.ndarray, flat: np.ndarray) -> np.ndarray:
    """``weights @ flat`` for extrapolation, flat (3, m): columns of huge values first scaled
    by a power of two (exact), so that the sum overflows only where its true value does
    (then ±inf, as a GPU's float would), never ``inf - inf = NaN`` from two large terms."""
    e = huge_exponents(flat[None])[0]
    with np.errstate(over="ignore", invalid="ignore"):
        if not e.any():
            return weights @ flat
        return np.ldexp(weights @ np.ldexp(flat, -e), e)


#: Values whose binary exponent exceeds this are scaled down before an unclamped sum.
HUGE_EXP = 512


def huge_exponents(values: np.ndarray) -> np.ndarray:
    """(n, k) powers of two that bring per-vertex values (n, 3, k) near the float maximum
    down to magnitudes below 1, 0 for ordinary ones (|f| < 2**HUGE_EXP, left bit-identical).

    Interpolation is linear in the values, so ``ldexp(values, -e)`` in and ``ldexp(result, e)``
    out is exact; in between, differences and products that extrapolation or derivatives
    take cannot overflow (callers: :func:`blend_each`, the quad derivatives).

    >>> huge_exponents(np.array([[[1e308], [0.5], [-2.0]]])).tolist()
    [[1024]]
    """
    peak = np.maximum(np.maximum(np.abs(values[:, 0]), np.abs(values[:, 1])), np.abs(values[:, 2]))
    e = np.frexp(peak)[1]
    return np.where(e > HUGE_EXP, e, 0)


def blend_each(
    weights: np.ndarray, values: np.ndarray, index=None, *, extrapolate: bool = False
) -> np.ndarray:
    """:func:`blend` with different vertex values per row: weights (n, 3), values (n, 3, k).

    With ``index`` (n,), ``values`` holds one (3, k) block per triangle (M, 3, k) and row i
    uses block ``index[i]``, gathered here one channel at a time (cheaper than gathering
    the whole (n, 3, k) block first). ``extrapolate=True`` leaves the sums unclamped.

    >>> blend_each(np.array([[0.5, 0.5, 0.0]]), np.array([[[0.0], [2.0], [9.0]]]))
    array([[1.]])
    """
    n, k = len(weights), values.shape[2]
    out = np.empty((k, n))  # returned transposed: each channel contiguous
    # One contiguous 1-D array per weight and per vertex value: written out per vertex and
    # per channel, because reductions over an axis of length 3, and arithmetic on strided
    # (n, 3, k) views, are slow in numpy.
    if extrapolate:
        scale = huge_exponents(values)
        if scale.any():
            values = np.ldexp(values, -scale[:, None, :])
            out = blend_each(weights, values, index, extrapolate=True)
            with np.errstate(over="ignore"):
                return np.ldexp(out, scale if index is None else scale[index])
    m0, m1, m2 = (np.ascontiguousarray(weights[:, i]) for i in range(3))
    # Each block's range, gathered rather than recomputed per row (and not as a reduction
    # over the axis of three, which is slow even on the small per-block array).
    lo = np.minimum(np.minimum(values[:, 0], values[:, 1]), values[:, 2])
    hi = np.maximum(np.maximum(values[:, 0], values[:, 1]), values[:, 2])
    for j in range(k):
        v0, v1, v2 = (np.ascontiguousarray(values[:, i, j]) for i in range(3))
        low, high = np.ascontiguousarray(lo[:, j]), np.ascontiguousarray(hi[:, j])
        if index is not None:
            v0, v1, v2, low, high = v0[index], v1[index], v2[index], low[index], high[index]
        with np.errstate(over="ignore", invalid="ignore"):  # near the float max: see above
            o = m0 * v0
            o += m1 * v1
            o += m2 * v2
        if not extrapolate:
            np.maximum(o, low, out=o)
            np.minimum(o, high, out=o)
        out[j] = o
    return out.T


def interpolate(
    lam: np.ndarray, values: np.ndarray, w: np.ndarray, mode: str, *, extrapolate: bool = False
) -> np.ndarray:
    """Interpolate vertex ``values`` at pixels with barycentrics ``lam`` (n, 3).

    Inside coverage (the default) the weights are made convex, so every value is finite
    and within the vertex values' range; ``extrapolate=True`` evaluates the triangle's
    own affine or perspective interpolation as it is, outside the triangle too.
    """
    if mode == "perspective":
        weights = perspective_weights(lam, w, extrapolate=extrapolate)
    else:
        weights = lam if extrapolate else convex_weights(lam)
    return blend(weights, values, extrapolate=extrapolate)


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
    exact = blend(perspective_weights(lam[anchor], w), values)  # the only divides by w
    slot = np.cumsum(anchor) - 1  # where each anchor's value sits in `exact`
    a0 = first[span] + (offset // step) * step
    a1 = np.minimum(a0 + step, last[span])
    # the place between the anchors: a divide per pixel here, a step (t += 1/N) in a scalar
    # rasteriser; numpy pays per pass either way
    t = np.where(a1 > a0, (index - a0) / np.maximum(a1 - a0, 1), 0.0)
    f0, f1 = exact[slot[a0]], exact[slot[a1]]
    t = t.reshape(-1, *([1] * (f0.ndim - 1)))
    out = f0 + t * (f1 - f0)
    flat = values.reshape(3, -1)
    lo, hi = flat.min(axis=0), flat.max(axis=0)
    return np.clip(out.reshape(n, -1), lo, hi).reshape(out.shape)
