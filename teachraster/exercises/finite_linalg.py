"""numpy's SVD-based solvers refusing ±inf while a student's function runs (exercise 4.3, r507
T1).

On a matrix holding ±inf, ``np.linalg.lstsq``, ``np.linalg.svd`` and ``np.linalg.pinv`` never
return with the OpenBLAS numpy ships (LAPACK's bidiagonal SVD loops for ever: numpy issue
#32591), and one call into C cannot be interrupted by the check's time limit
(docs/exercises.md). Exercise 4.3's cases hold a vertex with w = 0, so lesson 04's weights on
the screen, solved by least squares, divide by 0 and would hang the check cell for good. While
:func:`refusing_inf` is active these three functions raise :class:`InfiniteMatrix` (a
``LinAlgError``, as numpy raises for NaN) on such a matrix instead; on finite input they are
numpy's own. A solver imported by name before the check (``from numpy.linalg import lstsq``)
is not covered.
"""

from __future__ import annotations

import contextlib
import threading

import numpy as np

#: The functions of ``numpy.linalg`` that never return on ±inf (pinv calls svd internally).
HANGING = ("lstsq", "svd", "pinv")

_LOCK = threading.Lock()
_ACTIVE = [0]
_ORIGINAL = {name: getattr(np.linalg, name) for name in HANGING}


class InfiniteMatrix(np.linalg.LinAlgError):
    """A matrix holding ±inf handed to a solver that would never return on it."""


def _has_inf(value) -> bool:
    try:
        a = np.asarray(value)
    except Exception:  # noqa: BLE001 - numpy itself will say what is wrong
        return False
    return a.dtype.kind in "fc" and bool(np.isinf(a).any())


def _refusing(name: str):
    original = _ORIGINAL[name]

    def refusing(a, *args, **kwargs):
        if _has_inf(a):
            raise InfiniteMatrix(
                f"np.linalg.{name} was handed a matrix holding inf, on which it never returns "
                "(LAPACK's SVD loops for ever): the check refused the call"
            )
        return original(a, *args, **kwargs)

    refusing.__name__ = refusing.__qualname__ = name
    refusing.__doc__ = original.__doc__
    return refusing


_GUARDED = {name: _refusing(name) for name in HANGING}


@contextlib.contextmanager
def refusing_inf():
    """Within: ``np.linalg.lstsq``, ``svd`` and ``pinv`` raise :class:`InfiniteMatrix` on a
    matrix holding ±inf (nested and threaded uses count; numpy's own functions come back
    after the last).

    >>> with refusing_inf():
    ...     np.linalg.lstsq(np.array([[np.inf, 1.0], [1.0, 1.0]]), np.ones(2), rcond=None)
    Traceback (most recent call last):
    ...
    teachraster.exercises.finite_linalg.InfiniteMatrix: np.linalg.lstsq was handed a matrix holding inf, on which it never returns (LAPACK's SVD loops for ever): the check refused the call
    >>> np.linalg.lstsq is _ORIGINAL["lstsq"]
    True
    """
    with _LOCK:
        if not _ACTIVE[0]:
            for name in HANGING:
                setattr(np.linalg, name, _GUARDED[name])
        _ACTIVE[0] += 1
    try:
        yield
    finally:
        with _LOCK:
            _ACTIVE[0] -= 1
            if not _ACTIVE[0]:
                for name in HANGING:
                    setattr(np.linalg, name, _ORIGINAL[name])
