"""How close is close enough: 1e-9 relative, or absolute near zero; polygons up to rotation."""

from __future__ import annotations

import numpy as np

#: Relative tolerance of every comparison (and absolute one for values near zero).
TOL = 1e-9


def close(got, expected, tol: float = TOL) -> bool:
    """``got`` equals ``expected`` within ``tol`` (relative, or absolute near zero).

    >>> close(1.0 + 1e-12, 1.0), close(1e-12, 0.0), close(1.001, 1.0)
    (True, True, False)
    """
    got, expected = float(got), float(expected)
    if not (np.isfinite(got) and np.isfinite(expected)):
        return got == expected or (np.isnan(got) and np.isnan(expected))
    return abs(got - expected) <= tol * max(1.0, abs(got), abs(expected))


def all_close(got: np.ndarray, expected: np.ndarray, tol: float = TOL) -> bool:
    """Elementwise :func:`close` of arrays of the same shape.

    Non-finite entries must be equal, as in :func:`close` (r286 C1: the scale
    max(1, |got|, |expected|) is inf where got is, and inf ≤ tol·inf held, so an answer of
    ±inf passed):

    >>> all_close([1.0, np.inf], [1.0, 2.0]), all_close([np.nan, -np.inf], [np.nan, -np.inf])
    (False, True)
    """
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    if got.shape != expected.shape:
        return False
    finite = np.isfinite(got) & np.isfinite(expected)
    same = (got == expected) | (np.isnan(got) & np.isnan(expected))
    if not np.all(finite | same):
        return False
    g, e = got[finite], expected[finite]
    scale = np.maximum(1.0, np.maximum(np.abs(g), np.abs(e)))
    return bool(np.all(np.abs(g - e) <= tol * scale))


def dedupe(poly: np.ndarray, tol: float = TOL) -> np.ndarray:
    """Drop vertices equal (within ``tol``) to their predecessor, cyclically.

    >>> dedupe(np.array([[0.0, 0], [0, 0], [1, 0], [0, 0]])).tolist()
    [[0.0, 0.0], [1.0, 0.0]]
    """
    keep = []
    for v in poly:
        if not keep or not all_close(v, keep[-1], tol):
            keep.append(v)
    while len(keep) > 1 and all_close(keep[-1], keep[0], tol):
        keep.pop()
    return np.array(keep, dtype=float).reshape(-1, poly.shape[1] if poly.ndim == 2 else 0)


def same_polygon(got: np.ndarray, expected: np.ndarray, tol: float = TOL) -> bool:
    """Same vertices in the same cyclic order (any start), consecutive duplicates removed.

    >>> sq = np.array([[0.0, 0], [1, 0], [1, 1]])
    >>> same_polygon(np.roll(sq, 1, axis=0), sq), same_polygon(sq[::-1], sq)
    (True, False)
    """
    g, e = dedupe(got, tol), dedupe(expected, tol)
    if g.shape != e.shape:
        return False
    return any(all_close(np.roll(g, k, axis=0), e, tol) for k in range(max(len(g), 1)))
