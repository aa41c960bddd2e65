"""Half-plane fill: bounding box, then three edge tests per pixel (Ek, *Triangles and Perspective Correct Interpolation*, §1.2, the CS148 rasterisation notes (*Why Triangles?*)).

Every pixel centre in the bounding box is tested against the three edges in turn
(walking round the triangle: v1→v2, v2→v3, v3→v1 in positive winding, the edges E12, E23, E31). A scalar loop
would bail out at the first failing test; here all pixels are tested at once (as a GPU
does, in lock-step) and the trace records, per pixel, how many tests the bail-out
version would have run and which one rejected it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .bbox import BBox
from .edges import EdgeSetup


@dataclass(frozen=True)
class HalfPlaneTrace:
    """What the half-plane fill did, per pixel of the bounding box (bbox-local arrays).

    Pixels are visited in row-major order over the bounding box. The fill's own edge
    values are kept as computed (exact, in internal units), so recording costs no copy;
    the properties below derive what the presentation shows.

    Attributes
    ----------
    edge_units : tuple of three (rows, cols) arrays
        E_k at each pixel centre in internal units², in test order.
    passed : tuple of three (rows, cols) bool arrays
        Whether each pixel passed test k (top-left rule included).
    px2_per_unit2 : float
        Converts ``edge_units`` to px².
    """

    edge_units: tuple[np.ndarray, np.ndarray, np.ndarray]
    passed: tuple[np.ndarray, np.ndarray, np.ndarray]
    px2_per_unit2: float

    @property
    def edge_values(self) -> np.ndarray:
        """(rows, cols, 3) float64: E_k in px² (positive = inside edge k), in test order."""
        return np.stack(self.edge_units, axis=-1).astype(np.float64) * self.px2_per_unit2

    @property
    def tests_run(self) -> np.ndarray:
        """(rows, cols) int8: edge tests a bail-out loop runs at each pixel (1, 2 or 3)."""
        ok0, ok1, _ = self.passed
        return (1 + ok0.astype(np.int8) + (ok0 & ok1)).astype(np.int8)

    @property
    def rejected_by(self) -> np.ndarray:
        """(rows, cols) int8: position of the first failing test, -1 where covered."""
        ok0, ok1, ok2 = self.passed
        return np.where(~ok0, 0, np.where(~ok1, 1, np.where(~ok2, 2, -1))).astype(np.int8)

    def visit_order(self) -> np.ndarray:
        """(n, 2) bbox-local (row, col) of each visited pixel, in visiting order."""
        r, c = np.indices(self.tests_run.shape)
        return np.stack([r.ravel(), c.ravel()], axis=1)


def fill(setup: EdgeSetup, bbox: BBox, record: bool) -> tuple[np.ndarray, HalfPlaneTrace | None]:
    """Coverage of the bounding box (bbox-local bool array) and, if asked, the trace."""
    rows, cols = bbox.rows(), bbox.cols()
    covered = np.ones(bbox.shape, dtype=bool)
    values, passed = [], []
    for k in range(3):
        # E is affine in the pixel position: one subtraction per pixel (exact in int64;
        # raw floats of astronomical size may overflow to inf, which the test handles).
        with np.errstate(over="ignore", invalid="ignore"):
            row_term, col_term = setup.edge_terms(k, rows, cols)
            e = row_term[:, None] - col_term[None, :]
        ok = setup.inside(k, e)
        covered &= ok  # a loop would stop here at the first failure; see tests_run
        if record:
            values.append(e)
            passed.append(ok)
    if not record:
        return covered, None
    return covered, HalfPlaneTrace(tuple(values), tuple(passed), setup.pixels_per_unit2())
