"""Sample patterns: where inside a pixel a multisampled rasteriser tests coverage.

A pattern is an (S, 2) array of offsets from the pixel's top-left corner, x right and y down,
each in [0, 1): sample s of pixel (row i, col j) lies at ``(j + ox_s, i + oy_s)`` (CONVENTIONS,
*Multisampling*). The pixel centre is ``(0.5, 0.5)``.

- ``"standard"``: the Direct3D standard patterns for 1, 2, 4, 8 and 16 samples, given by
  Direct3D in 1/16 px from the centre (so every offset is a multiple of 1/16, exact on the
  snapped grid). 4 samples form a *rotated grid*, which llvmpipe uses too: no two samples share
  a row or a column, so a near-horizontal or near-vertical edge sweeps four coverage levels.
- ``"grid"``: the ordered k × k grid (cell centres), n = k²: only k levels for such edges.
- ``"jittered"``: one random point in each cell of the k × k grid (stratified), n = k².
- ``"random"``: n independent uniform points.

Random points are drawn on the 1/256 px grid, like vertices, so that they are tested exactly.

>>> sample_pattern(4)
array([[0.375, 0.125],
       [0.875, 0.375],
       [0.125, 0.625],
       [0.625, 0.875]])
>>> sample_pattern(4, "grid")
array([[0.25, 0.25],
       [0.75, 0.25],
       [0.25, 0.75],
       [0.75, 0.75]])
"""

from __future__ import annotations

import math

import numpy as np

from .validate import as_int, as_real, check_choice

KINDS = ("standard", "grid", "jittered", "random")

#: Direct3D 10.1+ standard sample positions, in 1/16 px from the pixel centre (y down).
_D3D = {
    1: [(0, 0)],
    2: [(4, 4), (-4, -4)],
    4: [(-2, -6), (6, -2), (-6, 2), (2, 6)],
    8: [(1, -3), (-1, 3), (5, 1), (-3, -5), (-5, 5), (-7, -1), (3, 7), (7, -7)],
    16: [
        (1, 1), (-1, -3), (-3, 2), (4, -1), (-5, -2), (2, 5), (5, 3), (3, -5),
        (-2, 6), (0, -7), (-4, -6), (-6, 4), (-8, 0), (7, -4), (6, 7), (-7, -8),
    ],
}  # fmt: skip

#: Sample counts an int ``samples=`` may name (the standard patterns).
STANDARD_COUNTS = tuple(_D3D)

#: Resolution of random offsets: the sub-pixel grid of the vertices.
_RANDOM_GRID = 256


def sample_pattern(n: int, kind: str = "standard", seed: int = 0) -> np.ndarray:
    """(n, 2) sample offsets inside the pixel (x right, y down, in [0, 1)).

    Parameters
    ----------
    n : int
        Number of samples: 1, 2, 4, 8 or 16 for ``"standard"``, a square (1, 4, 9, 16, ...)
        for ``"grid"`` and ``"jittered"``, any positive count for ``"random"``.
    kind : {"standard", "grid", "jittered", "random"}
        See the module docstring.
    seed : int
        Seed of the random generator (``"jittered"`` and ``"random"``; ignored otherwise).

    Raises
    ------
    ValueError
        Naming ``n`` when the kind cannot make that many samples, ``kind`` when unknown.

    Examples
    --------
    >>> sample_pattern(1)
    array([[0.5, 0.5]])
    >>> sample_pattern(3)
    Traceback (most recent call last):
    ...
    ValueError: n: the standard patterns have 1, 2, 4, 8 or 16 samples, got 3
    """
    n = as_int("n", n, minimum=1)
    check_choice("kind", kind, KINDS)
    seed = as_int("seed", seed, minimum=0)
    if kind == "standard":
        if n not in _D3D:
            raise ValueError(f"n: the standard patterns have 1, 2, 4, 8 or 16 samples, got {n}")
        out = np.array(_D3D[n], dtype=np.float64) / 16 + 0.5
    elif kind == "random":
        rng = np.random.default_rng(seed)
        out = rng.integers(0, _RANDOM_GRID, size=(n, 2)) / _RANDOM_GRID
    else:
        k = math.isqrt(n)
        if k * k != n:
            raise ValueError(f"n: a {kind} pattern needs a square number of samples, got {n}")
        cy, cx = np.divmod(np.arange(n), k)  # row-major: left to right, top to bottom
        cells = np.stack([cx, cy], axis=1).astype(np.float64)
        if kind == "grid":
            out = (cells + 0.5) / k
        else:  # jittered: one point per cell, on the 1/256 grid, never leaving its cell
            rng = np.random.default_rng(seed)
            lo = np.ceil(cells * _RANDOM_GRID / k)
            hi = np.ceil((cells + 1) * _RANDOM_GRID / k)  # exclusive
            out = (lo + np.floor(rng.random((n, 2)) * (hi - lo))) / _RANDOM_GRID
    out.flags.writeable = False
    return out


def as_samples(samples) -> np.ndarray:
    """``samples=`` as an (S, 2) offset array: an int names a standard pattern.

    Raises a ValueError (or TypeError) naming ``samples`` for counts without a standard
    pattern and for arrays that are not (S, 2), finite and inside [0, 1)².

    >>> as_samples(2)
    array([[0.75, 0.75],
           [0.25, 0.25]])
    >>> as_samples([[0.5, 1.0]])
    Traceback (most recent call last):
    ...
    ValueError: samples: offsets must lie in [0, 1) (inside the pixel), got [[0.5, 1.0]]
    """
    if np.ndim(samples) == 0:
        n = as_int("samples", samples, minimum=1)
        if n not in _D3D:
            raise ValueError(
                f"samples must be 1, 2, 4, 8 or 16 (a standard pattern) or an (S, 2) array of "
                f"offsets, got {n}"
            )
        return sample_pattern(n)
    try:
        arr = np.array(as_real("samples", samples), dtype=np.float64)  # no strings, complex
    except (TypeError, ValueError) as exc:
        raise TypeError(
            f"samples must be an int or an (S, 2) array of real offsets: {exc}"
        ) from None
    if np.asarray(samples).dtype.kind == "b":
        raise TypeError("samples must be an int or an (S, 2) array of offsets, got booleans")
    if arr.ndim != 2 or arr.shape[1] != 2 or len(arr) == 0:
        raise ValueError(
            f"samples: an offset array must have shape (S, 2), S >= 1, got {arr.shape}"
        )
    if not np.isfinite(arr).all() or (arr < 0).any() or (arr >= 1).any():
        raise ValueError(
            f"samples: offsets must lie in [0, 1) (inside the pixel), got {arr.tolist()}"
        )
    arr.flags.writeable = False
    return arr


def is_single(samples) -> bool:
    """True when ``samples`` asks for the ordinary one-sample fill (the int 1)."""
    return np.ndim(samples) == 0 and not isinstance(samples, bool | np.bool_) and samples == 1
