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

import math
import numbers
import operator
from collections.abc import Mapping, Set

import numpy as np

#: Integer arguments must fit a C long (int64): numpy indexes and sizes with them.
INT_LIMIT = 2**63 - 1

_FLOAT64 = np.dtype(np.float64)
#: Arrays up to this size are tested for NaN and infinity in Python (:func:`as_finite`).
_FEW = 16

#: Largest image (pixels) a call allocates unless the caller raises ``max_pixels``:
#: 16384 × 16384, already several GiB of float64 buffers.
MAX_PIXELS = 2**28


def as_int(name: str, value, *, minimum: int | None = None, maximum: int | None = None) -> int:
    """``value`` as a Python int within [minimum, maximum], or a TypeError/ValueError.

    Booleans are refused (``True`` is an int to Python, never a size to a student), and so
    are integers beyond a C long (±2**63), which numpy could not index with.

    >>> as_int("subdivision", 10**30)
    Traceback (most recent call last):
    ...
    ValueError: subdivision is too large: 1000000000000000000000000000000 does not fit a 64-bit integer
    """
    if isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be an int, got {value!r}")
    try:
        out = operator.index(value)
    except TypeError:
        raise TypeError(f"{name} must be an int, got {short_repr(value)}") from None
    if not -INT_LIMIT - 1 <= out <= INT_LIMIT:
        raise ValueError(f"{name} is too large: {out} does not fit a 64-bit integer")
    if minimum is not None and out < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {out}")
    if maximum is not None and out > maximum:
        raise ValueError(f"{name} must be <= {maximum}, got {out}")
    return out


def as_float(name: str, value, *, finite: bool = True) -> float:
    """A real number (Python or numpy, not a bool, string or complex) as a Python float.

    >>> as_float("fov_y", np.float32(60))
    60.0
    >>> as_float("near", 10**400)
    Traceback (most recent call last):
    ...
    ValueError: near is too large for a float: 1000000000000000000000000000000000000000000000000000000000000000000000...
    """
    scalar = isinstance(value, numbers.Real) or (
        isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf"
    )
    if not scalar or isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be a real number, got {short_repr(value)}")
    try:
        out = float(value)
    except OverflowError:
        raise ValueError(f"{name} is too large for a float: {short_repr(value)}") from None
    if finite and not math.isfinite(out):
        raise ValueError(f"{name} must be finite, got {out}")
    return out


def as_size(name: str, value) -> int:
    """A positive image dimension (``width``, ``height``) as a Python int."""
    out = as_int(name, value)
    if out <= 0:
        raise ValueError(f"{name} must be positive, got {out}")
    return out


def check_pixels(width: int, height: int, max_pixels, bytes_per_pixel: int) -> int:
    """Refuse an image of more than ``max_pixels`` pixels *before* anything is allocated.

    ``max_pixels`` (default :data:`MAX_PIXELS`, 2**28) is the caller's explicit way to
    allow more; the message says what the image would cost at ``bytes_per_pixel``.
    Returns ``max_pixels`` as a Python int.

    >>> check_pixels(100_000, 100_000, None, 40)
    Traceback (most recent call last):
    ...
    ValueError: width x height = 100000 x 100000 = 10,000,000,000 pixels is more than max_pixels = 268,435,456 (2**28); it would need about 373 GiB of memory. Pass max_pixels= to allow a larger image.
    """
    limit = MAX_PIXELS if max_pixels is None else as_int("max_pixels", max_pixels, minimum=1)
    n = width * height
    if n > limit:
        gib = n * bytes_per_pixel / 2**30
        default = " (2**28)" if max_pixels is None else ""
        raise ValueError(
            f"width x height = {width} x {height} = {n:,} pixels is more than "
            f"max_pixels = {limit:,}{default}; it would need about {gib:,.3g} GiB of memory. "
            "Pass max_pixels= to allow a larger image."
        )
    return limit


def as_bool(name: str, value) -> bool:
    """``value`` if it is a bool (Python or numpy), else a TypeError.

    Strings are refused on purpose: ``depth_test="no"`` is truthy and would switch the
    test *on*.
    """
    if not isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be True or False, got {short_repr(value)}")
    return bool(value)


def check_choice(name: str, value, choices) -> None:
    """Raise a ValueError naming ``name`` unless ``value`` is one of ``choices``."""
    try:
        ok = value in choices
    except (TypeError, ValueError):  # unhashable values (a dict, a list) against a dict of
        ok = False  # choices; an array compared element by element has no single truth value
    if not ok:
        raise ValueError(
            f"{name} must be one of {', '.join(map(repr, choices))}; got {short_repr(value)}"
        )


def as_finite(name: str, value, shape: tuple[int | None, ...] | None) -> np.ndarray:
    """Return ``value`` as a float64 array of ``shape`` (``None`` = any), or raise.

    Errors name the offending argument, so a student sees *which* input was wrong:
    a TypeError for what is not an array of real numbers (see :func:`as_real`) and a
    ValueError for a wrong shape, NaN, infinity or a number too large for a float
    (``10**400``).

    >>> as_finite("w", [1, 2, 3], (3,))
    array([1., 2., 3.])
    >>> as_finite("w", [1, 2j, 3], (3,))
    Traceback (most recent call last):
    ...
    TypeError: w must be numeric (real numbers), got complex values
    """
    arr = as_real(name, value, shape)
    if arr.size <= _FEW:
        # a point, a vertex, a triangle (the checker's mistakes call core functions per point,
        # ~10,000 times a check): Python's isfinite on each float, 0.6 µs, where numpy's ufunc
        # and reduction took 6 (the same test: these are float64 values)
        if all(map(math.isfinite, arr.ravel().tolist())):
            return arr
    elif np.isfinite(arr).all():  # the common case: one pass, no mask kept
        return arr
    bad = ~np.isfinite(arr)
    if bad.any():
        where = tuple(int(i) for i in np.argwhere(bad)[0]) if arr.ndim else ()
        raise ValueError(
            f"{name} contains NaN or infinity (or a number too large for a float): "
            f"{arr[where].item()!r} at index {list(where)}"
        )
    return arr


def as_real(name: str, value, shape: tuple[int | None, ...] | None = None) -> np.ndarray:
    """``value`` as a float64 array of ``shape`` (``None`` = any); NaN and inf pass.

    A TypeError naming ``name`` for what is not an array of real numbers: strings, bytes,
    mappings, sets, complex numbers (refused rather than silently losing their imaginary
    part), None entries, ragged nested lists; a ValueError for a wrong shape or a Python
    integer too large for a float.
    """
    if type(value) is np.ndarray and value.dtype == _FLOAT64:
        # the fast path (a core function called per point by the checker's mistakes): an
        # array already of float64 needs no check of its entries, only of its shape, and
        # its copy cannot overflow
        if shape is not None:
            check_shape(name, value.shape, shape)
        return np.array(value, dtype=np.float64)
    raw = _as_array(name, value)
    kind = raw.dtype.kind
    if kind not in "biufO":
        what = {"c": "complex values", "U": "strings", "S": "bytes", "V": "records"}
        raise TypeError(f"{name} must be numeric (real numbers), got {what.get(kind, raw.dtype)}")
    if shape is not None:
        check_shape(name, raw.shape, shape)
    if kind == "O":
        for item in raw.flat:
            _check_scalar(name, item)
    try:
        with np.errstate(all="ignore"):  # long doubles beyond float64 become inf: caught later
            return np.array(raw, dtype=np.float64)
    except OverflowError:
        raise ValueError(f"{name} holds a number too large for a float (over 1.8e308)") from None
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name} must be numeric array-like: {exc}") from None


def check_shape(name: str, got: tuple[int, ...], shape: tuple[int | None, ...]) -> None:
    """Raise a ValueError naming ``name`` unless ``got`` matches ``shape`` (None = any)."""
    if got == shape:  # the common case, without the loop below
        return
    ok = len(got) == len(shape) and all(s is None or s == n for s, n in zip(shape, got))
    if not ok:
        dims = ["k" if s is None else str(s) for s in shape]
        want = "(" + ", ".join(dims) + ("," if len(dims) == 1 else "") + ")"
        raise ValueError(f"{name} must have shape {want}, got {got}")


def _as_array(name: str, value) -> np.ndarray:
    """``np.asarray(value)`` with the failures numpy would report in its own words named."""
    if isinstance(value, str | bytes | bytearray | memoryview):
        raise TypeError(f"{name} must be numeric array-like, got {type(value).__name__}")
    if isinstance(value, Mapping | Set):
        raise TypeError(f"{name} must be numeric array-like, got a {type(value).__name__}")
    try:
        with np.errstate(all="ignore"):
            return np.asarray(value)
    except (TypeError, ValueError, OverflowError) as exc:
        raise TypeError(
            f"{name} must be numeric array-like with equal-length rows (not ragged): {exc}"
        ) from None


def _check_scalar(name: str, item) -> None:
    """One entry of an object array: a real number (Python int of any size is fine here)."""
    if isinstance(item, bool | int | float | np.integer | np.floating | np.bool_):
        return
    if isinstance(item, complex | np.complexfloating):
        raise TypeError(f"{name} must be numeric (real numbers), got complex values")
    if isinstance(item, str | bytes | Mapping | Set | list | tuple | np.ndarray) or item is None:
        kind = type(item).__name__
        raise TypeError(f"{name} must be numeric array-like (ragged or mixed?), got a {kind} entry")
    try:
        float(item)  # Fraction, Decimal, ...: anything with a real value
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be numeric (real numbers), got {short_repr(item)}") from None
    except OverflowError:
        pass  # reported by the conversion, with the other too-large numbers


def short_repr(value) -> str:
    """``repr(value)``, cut short: a message must stay readable whatever was passed."""
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."
