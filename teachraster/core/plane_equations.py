"""Attributes as planes over the screen: *Triangle Rasterisation II - Interpolation*'s A, B, C, D and Fatahalian's (CMU 15-462, *Texture*) matrix M.

The post *Triangle Rasterisation II - Interpolation* treats the three points (x_i, y_i, f_i) as a plane ``A x + B y + C f + D = 0``,
so ``f = -(A x + B y + D) / C``; stepping one pixel right adds ``dx = -A/C`` and one row
down adds ``dy = -B/C``, turning the inner loop into one addition per pixel.

Fatahalian (CMU 15-462, *Texture*) recentres at vertex a: ``f(x, y) = f_a + A (x - a_x) + B (y - a_y)`` with
``[A, B] = M [f_b - f_a, f_c - f_a]``. M depends only on the triangle, so it is set up
once and reused for every attribute, and working near the origin keeps precision.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .validate import as_finite, as_size, check_shape


def _values(f) -> np.ndarray:
    arr = as_finite("f", f, None)
    check_shape("f", arr.shape, (3,) if arr.ndim == 1 else (3, None))
    return arr


def _nondegenerate(c) -> None:
    if c == 0:
        raise ValueError("xy: zero-area triangle: the attribute plane is not defined")


def _working_type(dtype) -> np.dtype:
    # The arithmetic of a set-up and of its evaluation: float64 (the package's) or float32
    # (a GPU's interpolators, Direct3D 11.3 §15.16.2; lesson 03 §4 compares the two).
    dtype = np.dtype(dtype)
    if dtype not in (np.float32, np.float64):
        raise ValueError(f"dtype must be float32 or float64, got {dtype}")
    return dtype


def _as_type(values, dtype: np.dtype) -> np.ndarray:
    # x, y as the set-up's type: float64 first (any input), then rounded once to float32.
    return np.asarray(values, dtype=np.float64).astype(dtype, copy=False)


@dataclass(frozen=True)
class PlaneEquation:
    """``A x + B y + C f + D = 0`` through the three points (x_i, y_i, f_i) (*Triangle Rasterisation II - Interpolation*).

    A, B, D have the attribute's shape (scalar or (k,)); C is twice the signed area. All are
    computed, and the plane evaluated, in the type :func:`plane_equation` was given (float64
    unless asked otherwise).
    """

    A: np.ndarray
    B: np.ndarray
    C: float
    D: np.ndarray

    @property
    def dx(self) -> np.ndarray:
        """Change of f per pixel to the right: ``-A / C``."""
        return -self.A / self.C

    @property
    def dy(self) -> np.ndarray:
        """Change of f per row down: ``-B / C``."""
        return -self.B / self.C

    def __call__(self, x, y) -> np.ndarray:
        """Evaluate directly: ``f = -(A x + B y + D) / C``."""
        dtype = np.result_type(self.A)
        x, y = _as_type(x, dtype), _as_type(y, dtype)
        if np.ndim(self.A):
            x, y = x[..., None], y[..., None]
        return -(self.A * x + self.B * y + self.D) / self.C

    def stepped(self, x0: float, y0: float, ncols: int, nrows: int) -> np.ndarray:
        """Evaluate on a grid by incremental stepping, as in *Triangle Rasterisation II - Interpolation*'s inner loop.

        Starts from the exact value at (x0, y0), then adds ``dy`` once per row and ``dx``
        once per pixel, strictly in order, so rounding errors accumulate the way they
        do in a real incremental rasteriser. Shape (nrows, ncols[, k]).

        >>> plane = plane_equation([[0, 0], [4, 0], [0, 4]], [0.0, 4.0, 8.0])
        >>> plane.stepped(0.5, 0.5, 3, 2)
        array([[1.5, 2.5, 3.5],
               [3.5, 4.5, 5.5]])
        """
        ncols, nrows = as_size("ncols", ncols), as_size("nrows", nrows)
        start = self(x0, y0)
        shape = np.shape(start)
        col_steps = np.broadcast_to(self.dx, shape)
        row_steps = np.broadcast_to(self.dy, shape)
        # np.add.accumulate adds left to right: the same sequence of roundings as a loop.
        firsts = np.add.accumulate(
            np.concatenate([start[None], np.repeat(row_steps[None], nrows - 1, axis=0)])
        )
        steps = np.repeat(col_steps[None, None], ncols - 1, axis=1)
        steps = np.broadcast_to(steps, (nrows, ncols - 1, *shape))
        return np.add.accumulate(np.concatenate([firsts[:, None], steps], axis=1), axis=1)


def plane_equation(xy, f, dtype=np.float64) -> PlaneEquation:
    """The plane through (x_i, y_i, f_i), with *Triangle Rasterisation II - Interpolation*'s formulas (absolute coordinates).

    ``dtype`` (float64 or float32): the arithmetic of every coefficient and of the plane's
    evaluation, the positions and values rounded to it first.

    >>> p = plane_equation([[0, 0], [4, 0], [0, 4]], [1.0, 3.0, 5.0])
    >>> float(p.dx), float(p.dy), float(p(1, 1))
    (0.5, 1.0, 2.5)
    >>> plane_equation([[0, 0], [4, 0], [0, 4]], [1.0, 3.0, 5.0], dtype=np.float32)(1, 1).dtype
    dtype('float32')
    """
    dtype = _working_type(dtype)
    (x1, y1), (x2, y2), (x3, y3) = as_finite("xy", xy, (3, 2)).astype(dtype)
    f = _values(f).astype(dtype)
    r1, r2, r3 = f
    A = y1 * (r2 - r3) + y2 * (r3 - r1) + y3 * (r1 - r2)
    B = r1 * (x2 - x3) + r2 * (x3 - x1) + r3 * (x1 - x2)
    C = x1 * (y2 - y3) + x2 * (y3 - y1) + x3 * (y1 - y2)
    D = -(x1 * (y2 * r3 - y3 * r2) + x2 * (y3 * r1 - y1 * r3) + x3 * (y1 * r2 - y2 * r1))
    _nondegenerate(C)
    return PlaneEquation(A=A, B=B, C=float(C) if dtype == np.float64 else C, D=D)


def setup_matrix(xy, dtype=np.float64) -> np.ndarray:
    """Fatahalian's (CMU 15-462, *Texture*) once-per-triangle matrix M, which maps vertex differences to gradients.

    ``M = 1/det [[c_y - a_y, a_y - b_y], [a_x - c_x, b_x - a_x]]`` with
    ``det = (b_x - a_x)(c_y - a_y) - (c_x - a_x)(b_y - a_y)``.

    ``dtype`` (float64 or float32): its arithmetic, the positions rounded to it first.

    >>> setup_matrix([[0, 0], [4, 0], [0, 2]])
    array([[0.25, 0.  ],
           [0.  , 0.5 ]])
    """
    dtype = _working_type(dtype)
    (ax, ay), (bx, by), (cx, cy) = as_finite("xy", xy, (3, 2)).astype(dtype)
    det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
    _nondegenerate(det)
    return np.array([[cy - ay, ay - by], [ax - cx, bx - ax]], dtype=dtype) / det


@dataclass(frozen=True)
class AttributePlane:
    """``f(x, y) = value + A (x - origin_x) + B (y - origin_y)``: the plane recentred at a.

    ``A`` and ``B`` are Fatahalian's names (*Texture*, CMU 15-462) for the gradient; the
    lessons write it ``g_x, g_y`` (aliases below), because *Triangle Rasterisation II* uses
    ``A, B`` for other numbers (:class:`PlaneEquation`, where ``g_x = -A/C``).
    """

    origin: tuple[float, float]
    value: np.ndarray
    A: np.ndarray
    B: np.ndarray

    @property
    def g_x(self) -> np.ndarray:
        """∂f/∂x, the lessons' name for ``A``.

        >>> float(attribute_plane([[10, 10], [14, 10], [10, 14]], [1.0, 3.0, 5.0]).g_x)
        0.5
        """
        return self.A

    @property
    def g_y(self) -> np.ndarray:
        """∂f/∂y, the lessons' name for ``B``."""
        return self.B

    def __call__(self, x, y) -> np.ndarray:
        dtype = np.result_type(self.A)  # the set-up's arithmetic, float64 unless asked
        dx = _as_type(x, dtype) - dtype.type(self.origin[0])
        dy = _as_type(y, dtype) - dtype.type(self.origin[1])
        if np.ndim(self.A):
            dx, dy = dx[..., None], dy[..., None]
        return self.value + self.A * dx + self.B * dy


def attribute_plane(xy, f, M: np.ndarray | None = None, dtype=np.float64) -> AttributePlane:
    """Plane of attribute ``f`` from the setup matrix: ``[A, B] = M [f_b - f_a, f_c - f_a]``.

    Pass ``M`` to reuse one set-up for many attributes. ``dtype`` (float64 or float32): the
    arithmetic of the set-up and of the plane's evaluation, positions and values rounded to
    it first.

    >>> plane = attribute_plane([[10, 10], [14, 10], [10, 14]], [1.0, 3.0, 5.0])
    >>> float(plane.A), float(plane.B), float(plane(11, 11))
    (0.5, 1.0, 2.5)
    """
    dtype = _working_type(dtype)
    v = as_finite("xy", xy, (3, 2)).astype(dtype)
    f = _values(f).astype(dtype)
    M = setup_matrix(v, dtype) if M is None else np.asarray(M, dtype=np.float64).astype(dtype)
    diffs = np.stack([f[1] - f[0], f[2] - f[0]])
    A, B = np.tensordot(M, diffs, axes=1)
    return AttributePlane(origin=(float(v[0, 0]), float(v[0, 1])), value=f[0], A=A, B=B)
