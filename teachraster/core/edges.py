"""Edge functions, winding and the top-left rule: the per-triangle set-up both fills share.

The edge function of the directed edge a→b at point p is the z-component of the cross
product (b - a) × (p - a) (lesson: half-planes, Ek, *Triangles and Perspective Correct Interpolation*, §1.2)::

    E(a, b, p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)

With the vertices ordered so that the triangle's own area E(v1, v2, v3) is positive, a
point is inside when all three edge functions are positive. A centre exactly on an edge
(E == 0) is inside only for a *top* or *left* edge, so a centre on an edge shared by two
triangles belongs to exactly one of them.

Exactness: on the snapped grid all coordinates are int64 below 2**30 in magnitude
(:data:`teachraster.core.snapping.UNIT_LIMIT`), so each difference is below 2**31, each product
below 2**62 and E below 2**63: computed in int64, E is exact, and the sign tests and the
``E == 0`` ties are decided without rounding.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .snapping import to_units, units_per_pixel
from .validate import as_finite


@dataclass(frozen=True)
class EdgeSetup:
    """Once-per-triangle set-up, in internal units (int64 snapped, or float64 raw).

    ``p`` holds the vertices re-ordered so that the area is positive; ``perm[k]`` is the
    original index of ``p[k]``. Edge ``k`` runs ``p[k] → p[(k + 1) % 3]``. A batch (see
    :func:`setup_edges`) has leading axes on every array; the per-pixel methods below are
    for one triangle.
    """

    p: np.ndarray  # (..., 3, 2) oriented vertices, internal units
    perm: np.ndarray  # (..., 3) original vertex index of each oriented vertex
    area2: int | float | np.ndarray  # (...) E(p0, p1, p2) >= 0, in units²
    original_area2: int | float | np.ndarray  # (...) E(v1, v2, v3) in the caller's order
    top_left: np.ndarray  # (..., 3) bool per edge
    unit: int | float  # internal units per pixel
    exact: bool  # True on the snapped integer grid
    #: Where inside each pixel the tests run, (x, y) from its top-left corner in units;
    #: None is the pixel centre. Multisampling sets one per sample (see :meth:`at_sample`).
    sample: tuple[int, int] | tuple[float, float] | None = None

    @property
    def half(self) -> int | float:
        """Offset of a pixel centre from the pixel's corner, in units."""
        return self.unit // 2 if self.exact else 0.5

    @property
    def offset_x(self) -> int | float:
        """x of the tested point from the pixel's corner, in units (the centre by default)."""
        return self.half if self.sample is None else self.sample[0]

    @property
    def offset_y(self) -> int | float:
        """y of the tested point from the pixel's corner, in units (the centre by default)."""
        return self.half if self.sample is None else self.sample[1]

    def at_sample(self, ox, oy) -> EdgeSetup:
        """The same triangle tested at offset (ox, oy) units inside every pixel.

        Everything else (vertices, winding, the top-left flags) is shared: a sample is
        decided exactly like a pixel centre, only at another point of the pixel.
        """
        return replace(self, sample=(ox, oy))

    @property
    def edges(self) -> np.ndarray:
        """(3, 2) original vertex indices (from, to) of each directed edge, in test order."""
        return np.stack([self.perm, np.roll(self.perm, -1)], axis=1)

    def centre_x(self, cols: np.ndarray) -> np.ndarray:
        """x of the tested points (pixel centres, or the sample) of columns ``cols``, in units."""
        return np.asarray(cols, dtype=self.p.dtype) * self.unit + self.offset_x

    def centre_y(self, rows: np.ndarray) -> np.ndarray:
        """y of the tested points (pixel centres, or the sample) of rows ``rows``, in units."""
        return np.asarray(rows, dtype=self.p.dtype) * self.unit + self.offset_y

    def edge_terms(self, k: int, rows: np.ndarray, cols: np.ndarray):
        """Row and column parts of E_k: ``E_k[r, c] = row_term[r] - col_term[c]``.

        Separating the two parts is what makes the half-plane test cheap: E is affine in
        the pixel position, so one multiply per row and one per column suffice.
        """
        a, b = self.p[k], self.p[(k + 1) % 3]
        ys = self.centre_y(rows) - a[1]
        xs = self.centre_x(cols) - a[0]
        return (b[0] - a[0]) * ys, (b[1] - a[1]) * xs

    def inside(self, k: int, e: np.ndarray) -> np.ndarray:
        """The tie-aware test of edge k: E > 0, or E >= 0 on a top-left edge."""
        return passes(e, self.top_left[k])

    def pixels_per_unit2(self) -> float:
        """Factor converting E (units²) to px²."""
        return 1.0 / float(self.unit) ** 2


def edge_function(a, b, p) -> np.ndarray:
    """E(a, b, p) in float64 for points ``p`` of shape (..., 2).

    >>> float(edge_function([0, 0], [4, 0], [1, 3]))   # p below a→b (y down): inside
    12.0
    """
    a, b = as_finite("a", a, (2,)), as_finite("b", b, (2,))
    p = as_finite("p", p, None)
    if p.shape[-1:] != (2,):
        raise ValueError(f"p must have shape (..., 2), got {p.shape}")
    return (b[0] - a[0]) * (p[..., 1] - a[1]) - (b[1] - a[1]) * (p[..., 0] - a[0])


def passes(e, top_left) -> np.ndarray:
    """The top-left rule on edge values: E > 0, or E >= 0 where the edge is top-left.

    ``top_left`` broadcasts against ``e`` (one flag, or one per edge in the last axis).

    >>> passes(np.array([1, 0, 0, -1]), np.array([False, False, True, True])).tolist()
    [True, False, True, False]
    """
    if np.ndim(top_left) == 0:  # one edge: one comparison (the hot path of the fills)
        return e >= 0 if top_left else e > 0
    return np.where(top_left, e >= 0, e > 0)


def is_top_left(a, b) -> bool:
    """True when the directed edge a→b (interior on its positive side) is top or left.

    In y-down coordinates: the edge goes up (``b.y < a.y``, a left edge) or is exactly
    horizontal going right (``b.x > a.x``, a top edge with the interior below it).

    >>> is_top_left((0, 0), (4, 0)), is_top_left((0, 4), (0, 0)), is_top_left((4, 0), (0, 4))
    (True, True, False)
    """
    return bool(top_left_edges(as_finite("a", a, (2,)), as_finite("b", b, (2,))))


def top_left_edges(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """:func:`is_top_left` for arrays of directed edges ``a → b`` (..., 2): (...,) bool."""
    return (b[..., 1] < a[..., 1]) | ((b[..., 1] == a[..., 1]) & (b[..., 0] > a[..., 0]))


def facing(area2) -> np.ndarray:
    """Facing of triangles from their signed area E(v1, v2, v3): int8 +1, -1 or 0.

    +1 clockwise on screen (back-facing), -1 counter-clockwise (front-facing, CONVENTIONS'
    winding), 0 zero area.

    >>> facing(np.array([12, -3, 0])).tolist()
    [1, -1, 0]
    """
    return np.sign(area2).astype(np.int8)


def culled(area2, cull: str | None) -> np.ndarray:
    """The culling test, the one place it is written: which triangles ``cull`` removes.

    ``area2`` is E(v1, v2, v3) of the *snapped* triangle in the caller's vertex order (the
    triangle that is actually filled); ``cull`` is None, "back" or "front". Zero-area
    triangles are never culled (they cover nothing anyway).

    >>> culled(np.array([12, -3, 0]), "back").tolist(), culled(np.array([12, -3, 0]), None).tolist()
    ([True, False, False], [False, False, False])
    """
    side = facing(area2)
    if cull == "back":
        return side > 0
    if cull == "front":
        return side < 0
    return np.zeros(np.shape(side), dtype=bool)


def setup_edges(xy: np.ndarray, subpixel_bits: int | None) -> EdgeSetup:
    """Snap, orient and classify the edges of a triangle (once per triangle).

    ``xy`` is (3, 2) for one triangle or (..., 3, 2) for a batch: every field of the
    returned :class:`EdgeSetup` then gains the same leading axes (``p`` (..., 3, 2),
    ``perm`` (..., 3), ``area2`` (...), ``top_left`` (..., 3)), so the batched fill shares
    this one snapping, orientation and top-left classification.

    >>> s = setup_edges(np.array([[[0, 0], [0, 4], [4, 0]], [[0, 0], [4, 0], [0, 4]]]), 8)
    >>> s.perm.tolist(), s.original_area2.tolist(), s.top_left.tolist()
    ([[0, 2, 1], [0, 1, 2]], [-4194304, 4194304], [[True, False, True], [True, False, True]])
    """
    v = to_units(xy, subpixel_bits)
    (ax, ay), (bx, by), (cx, cy) = (np.moveaxis(v[..., k, :], -1, 0) for k in range(3))
    area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    # Both windings are filled: a negative area just means swapping two vertices so the
    # interior is on the positive side of every edge (culling is decided by the caller).
    perm = np.where((area2 < 0)[..., None], np.array([0, 2, 1]), np.array([0, 1, 2]))
    p = np.take_along_axis(v, perm[..., None], axis=-2)
    top_left = top_left_edges(p, p[..., [1, 2, 0], :])
    return EdgeSetup(
        p=p,
        perm=perm,
        area2=abs(area2)[()],
        original_area2=area2[()],
        top_left=top_left,
        unit=units_per_pixel(subpixel_bits),
        exact=subpixel_bits is not None,
    )


def edge_values_at(setup: EdgeSetup, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """E_k at the centres of pixels (rows[i], cols[i]): shape (n, 3), in units²."""
    out = np.empty((len(rows), 3), dtype=setup.p.dtype)
    if len(rows) == 0:
        return out
    # One row term per raster line and one column term per column, then gather: the same
    # exact values as evaluating E per pixel, for a fraction of the multiplications.
    r0, c0 = rows.min(), cols.min()
    all_rows, all_cols = np.arange(r0, rows.max() + 1), np.arange(c0, cols.max() + 1)
    for k in range(3):
        row_term, col_term = setup.edge_terms(k, all_rows, all_cols)
        np.subtract(row_term[rows - r0], col_term[cols - c0], out=out[:, k])
    return out
