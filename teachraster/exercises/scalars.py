"""Numbers in explanations: the fewest digits that tell two values apart, points and vectors.

Every explanation quotes its case's numbers through :func:`num` and :func:`vec`, so that the
student's answer and the expected one never print alike (0.8 beside 0.8000000000000002).
"""

from __future__ import annotations

import numpy as np


def _readable(x: float, exact_grid: bool) -> str:
    if 0 < abs(x) < 1e-3:  # tiny values (w next to the eye plane) keep their digits
        return f"{x:.3g}"
    if exact_grid and (x * 256).is_integer() and abs(x) < 2**40:
        # on the 1/256 grid (positions): exactly, so that the student can reproduce the case
        return f"{x:.8f}".rstrip("0").rstrip(".")
    if abs(x) >= 1e15:
        return f"{x:.6g}"
    text = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


def num(x: float, other: float | None = None) -> str:
    """``x`` with 3 decimals, or with the fewest digits that tell it from ``other``.

    Never more digits than Python's shortest round-trip ``repr``: 0.8 stays 0.8 beside
    0.8000000000000002, and two different numbers never print alike.

    >>> num(3.04545), num(1.0000001, 1.0), num(2.0), num(100009.73828125)
    ('3.045', '1.0000001', '2', '100009.73828125')
    >>> num(0.8, 0.8000000000000002), num(0.8000000000000002, 0.8)
    ('0.8', '0.8000000000000002')
    >>> num(25.0, 25.0000025), num(25.0000025, 25.0)
    ('25', '25.000003')
    >>> num(-0.0), vec([1.0, -0.0, 0.0])
    ('0', '(1, 0, 0)')
    """
    x = float(x) + 0.0  # r175 D12: -0.0 (0 over a negative area) printed "-0"
    if not np.isfinite(x):
        return repr(x)
    text = _readable(x, other is None)
    if other is None:
        return text
    o = float(other)
    if not np.isfinite(o) or x == o or text != _readable(o, False):
        return text
    # more digits than the readable form, never fewer: decimals, or significant digits for
    # tiny and huge values (as the readable form has them)
    decimals = 1e-3 <= abs(x) < 1e15
    for digits in range(3, 21 if decimals else 18):
        form = f".{digits}{'f' if decimals else 'g'}"
        text = format(x, form)
        if text != format(o, form):
            break
    if decimals:
        text = text.rstrip("0").rstrip(".")
    return min(text, repr(x), key=len)


def factor(x: float) -> str:
    """A number to multiply by: negative ones in parentheses."""
    return f"({num(x)})" if x < 0 else num(x)


#: Components closer than this (relative) are float noise, far below every check's tolerance.
NOISE = 1e-9


def vec(v, other=None) -> str:
    """``v`` with each component told from ``other``'s (:func:`num`). Where the two vectors
    differ in some component, a component that agrees within float noise (:data:`NOISE`) prints
    short on both sides: 0.92 beside 0.92, not 0.9199999999999999 beside 0.92.

    >>> vec([0.737, 0.522, 0.9199999999999999], [0.735, 0.521, 0.92])
    '(0.737, 0.522, 0.92)'
    >>> vec([0.8, 1.0], [0.8000000000000002, 1.0])
    '(0.8, 1)'
    """
    v = np.asarray(v, dtype=float).ravel()
    o = [None] * len(v) if other is None else np.asarray(other, dtype=float).ravel()
    if len(o) != len(v):
        o = [None] * len(v)
    elif other is not None:
        with np.errstate(invalid="ignore"):
            noise = np.abs(v - o) <= NOISE * np.maximum(1.0, np.maximum(np.abs(v), np.abs(o)))
        if not noise.all():  # the vectors still print apart: drop the noise's digits
            o = [None if n else b for n, b in zip(noise, o)]
    return "(" + ", ".join(num(a, b) for a, b in zip(v, o)) + ")"


def full_number(x: float) -> str:
    """``x`` as Python prints it (every digit it needs), whole numbers without ".0": a number a
    student can paste to call a function on a case again (8.1's and 8.2's lines).

    >>> full_number(2.0), full_number(-276483.12109375), full_number(float("inf"))
    ('2', '-276483.12109375', 'np.inf')
    """
    x = float(x) + 0.0
    if not np.isfinite(x):
        return "np.inf" if x > 0 else ("-np.inf" if x < 0 else "np.nan")
    return str(int(x)) if x.is_integer() and abs(x) < 1e15 else repr(x)


def tri_words(xy) -> str:
    return f"v1={vec(xy[0])}, v2={vec(xy[1])}, v3={vec(xy[2])}"


def centre_near(p) -> np.ndarray:
    """The pixel centre nearest ``p`` (of the pixel holding it)."""
    return np.floor(p) + 0.5
