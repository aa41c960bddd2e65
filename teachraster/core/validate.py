"""Argument checks shared by every public entry point: one place, one wording.

Each check names the offending argument, so a student sees *which* input was wrong, and
converts what it accepts to a plain Python value at the boundary (numpy integer scalars
become ``int`` through :func:`operator.index`, so ``2**(bits + 1)`` can never overflow
inside an ``int8``).

>>> as_int("width", np.uint8(200), minimum=1)
200
>>> as_size("width", 0)
Traceback (most recent call last):
...
ValueError: width must be positive, got 0
"""

from __future__ import annotations

import operator

import numpy as np


def as_int(name: str, value, *, minimum: int | None = None, maximum: int | None = None) -> int:
    """``value`` as a Python int within [minimum, maximum], or a TypeError/ValueError.

    Booleans are refused (``True`` is an int to Python, never a size to a student).
    """
    if isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be an int, got {value!r}")
    try:
        out = operator.index(value)
    except TypeError:
        raise TypeError(f"{name} must be an int, got {value!r}") from None
    if minimum is not None and out < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {out}")
    if maximum is not None and out > maximum:
        raise ValueError(f"{name} must be <= {maximum}, got {out}")
    return out


def as_size(name: str, value) -> int:
    """A positive image dimension (``width``, ``height``) as a Python int."""
    out = as_int(name, value)
    if out <= 0:
        raise ValueError(f"{name} must be positive, got {out}")
    return out


def as_bool(name: str, value) -> bool:
    """``value`` if it is a bool (Python or numpy), else a TypeError.

    Strings are refused on purpose: ``depth_test="no"`` is truthy and would switch the
    test *on*.
    """
    if not isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be True or False, got {value!r}")
    return bool(value)


def check_choice(name: str, value, choices) -> None:
    """Raise a ValueError naming ``name`` unless ``value`` is one of ``choices``."""
    try:
        ok = value in choices
    except TypeError:  # unhashable values (a dict, a list) against a dict of choices
        ok = False
    if not ok:
        raise ValueError(f"{name} must be one of {', '.join(map(repr, choices))}; got {value!r}")


def as_finite(name: str, value, shape: tuple[int | None, ...]) -> np.ndarray:
    """Return ``value`` as a float64 array of ``shape`` (``None`` = any), or raise.

    Errors name the offending argument, so a student sees *which* input was wrong.
    """
    try:
        arr = np.array(value, dtype=np.float64)
    except (TypeError, ValueError, OverflowError) as exc:
        raise TypeError(f"{name} must be numeric array-like: {exc}") from None
    ok = arr.ndim == len(shape) and all(s is None or s == n for s, n in zip(shape, arr.shape))
    if not ok:
        dims = ["k" if s is None else str(s) for s in shape]
        want = "(" + ", ".join(dims) + ("," if len(dims) == 1 else "") + ")"
        raise ValueError(f"{name} must have shape {want}, got {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} contains NaN or infinity: {arr.tolist()}")
    return arr
