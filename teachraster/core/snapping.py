"""Sub-pixel snapping: the fixed-point grid on which coverage is decided exactly.

Direct3D (and llvmpipe) snap every vertex to 1/256 pixel before deciding coverage
(8 sub-pixel bits, round half to even). On that grid every edge-function value is an
integer, so "is this pixel centre on the edge?" has an exact answer and two triangles
that share an edge can never both claim, or both miss, a pixel centre.

Internally positions are held as integers in units of ``1 / 2**(bits + 1)`` pixel: the
extra bit makes pixel *centres* (``j + 0.5``) integers too, so every quantity the fill
rules compare is an integer.
"""

from __future__ import annotations

import numpy as np

from .validate import as_int, as_real

#: Default number of sub-pixel bits (Direct3D 10+).
SUBPIXEL_BITS = 8

#: Largest |coordinate| in internal units. Differences then stay below 2**31, products of
#: two differences below 2**62 and the difference of two products below 2**63: every
#: edge function fits int64 exactly (see :func:`to_units`).
UNIT_LIMIT = 2**30


#: Largest |coordinate| for raw floats: products of two differences stay below 1.8e308.
FLOAT_LIMIT = 1e150


def check_bits(subpixel_bits: int | None) -> int | None:
    """``subpixel_bits`` as a Python int in [0, 16], or None; else raise naming it."""
    if subpixel_bits is None:
        return None
    return as_int("subpixel_bits", subpixel_bits, minimum=0, maximum=16)


def units_per_pixel(subpixel_bits: int | None) -> int | float:
    """Internal units in one pixel: ``2**(bits + 1)``, or 1.0 for raw floats."""
    subpixel_bits = check_bits(subpixel_bits)  # a Python int: 2**9 cannot wrap in an int8
    return 1.0 if subpixel_bits is None else 2 ** (subpixel_bits + 1)


def snap(xy: np.ndarray, subpixel_bits: int | None = SUBPIXEL_BITS) -> np.ndarray:
    """Snap pixel positions to the ``1 / 2**subpixel_bits`` grid (round half to even).

    >>> snap([[0.001953125, 1.0]])       # 0.5 / 256 rounds to even: down to 0
    array([[0., 1.]])
    >>> snap([[0.3, 0.7]], subpixel_bits=2)
    array([[0.25, 0.75]])
    """
    xy = as_real("xy", xy)
    subpixel_bits = check_bits(subpixel_bits)
    if subpixel_bits is None:
        return xy.copy()
    scale = float(2**subpixel_bits)
    # Multiplying by a power of two is exact, and np.rint rounds half to even. A double of
    # magnitude >= 2**(52 - bits) is already a multiple of 1/2**bits: it is kept as it is,
    # which also spares xy * scale from overflowing near the float maximum.
    out = xy.copy()
    small = np.abs(xy) < 2.0 ** (52 - subpixel_bits)
    out[small] = np.rint(xy[small] * scale) / scale
    return out


def to_units(xy: np.ndarray, subpixel_bits: int | None) -> np.ndarray:
    """Positions in internal units: int64 on the snapped grid, float64 when unsnapped.

    Raises ``ValueError`` (naming ``xy``) when a snapped coordinate is too far from the
    origin for the int64 edge functions to stay exact.

    >>> to_units([[1.5, 2.0]], 8)          # 512 units per pixel
    array([[ 768, 1024]])
    """
    xy = np.asarray(xy, dtype=np.float64)
    subpixel_bits = check_bits(subpixel_bits)
    if subpixel_bits is None:
        if np.abs(xy).max(initial=0.0) >= FLOAT_LIMIT:
            raise ValueError(
                f"xy: coordinates beyond ±{FLOAT_LIMIT:g} px overflow float64 edge functions "
                "(a product of two differences would exceed the largest double)"
            )
        return xy.copy()
    with np.errstate(over="ignore"):  # beyond the float range is beyond UNIT_LIMIT too
        units = np.rint(xy * 2.0**subpixel_bits) * 2.0
    if np.abs(units).max(initial=0.0) >= UNIT_LIMIT:
        limit = UNIT_LIMIT / 2 ** (subpixel_bits + 1)
        raise ValueError(
            f"xy: coordinates beyond ±{limit:g} px cannot be rasterised exactly with "
            f"{subpixel_bits} sub-pixel bits (the int64 edge functions would overflow); "
            "clip the triangle first or use fewer sub-pixel bits"
        )
    return units.astype(np.int64)
