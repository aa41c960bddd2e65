"""The bounding box: the only pixels worth testing (Ek, *Triangles and Perspective Correct Interpolation*, §1.2, the CS148 rasterisation notes (*Why Triangles?*))."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .edges import EdgeSetup


@dataclass(frozen=True)
class BBox:
    """Pixels whose centres lie in the triangle's bounding box, clipped to the image.

    Rows ``row0 <= i < row1`` and columns ``col0 <= j < col1`` (half-open, so an empty box
    has ``row0 == row1`` or ``col0 == col1``). ``xmin .. ymax`` are the box's extents in
    pixels, before clipping.
    """

    row0: int
    row1: int
    col0: int
    col1: int
    xmin: float
    xmax: float
    ymin: float
    ymax: float

    @property
    def shape(self) -> tuple[int, int]:
        return (self.row1 - self.row0, self.col1 - self.col0)

    @property
    def size(self) -> int:
        return self.shape[0] * self.shape[1]

    def rows(self) -> np.ndarray:
        return np.arange(self.row0, self.row1)

    def cols(self) -> np.ndarray:
        return np.arange(self.col0, self.col1)


def centre_ranges(lo, hi, setup: EdgeSetup, n: int, half=None) -> tuple[np.ndarray, np.ndarray]:
    """Half-open index ranges [first, stop) of pixel centres c with ``lo <= c <= hi``.

    ``lo`` and ``hi`` are arrays (one range per entry, in internal units); the ranges are
    clipped to [0, n) and empty ones have ``stop == first``. Integer floor and ceiling on
    the snapped grid, so the bounds are exact. ``half`` is the tested point's offset from
    the pixel corner in units (default: the centre; a sample's offset when multisampling).
    """
    unit = setup.unit
    half = setup.half if half is None else half
    if setup.exact:  # integer ceil/floor: exact
        first = -((half - lo) // unit)
        last = (hi - half) // unit
    else:
        first = np.ceil((lo - half) / unit)
        last = np.floor((hi - half) / unit)
    first = np.clip(first, 0, n).astype(np.int64)
    # clipped from below too: an unsnapped bound far left of the image (-1e28) would not fit
    # an int64 (numpy then warns and wraps)
    stop = np.maximum(first, np.clip(last, -1, n - 1).astype(np.int64) + 1)
    return first, stop


def centre_range(lo, hi, setup: EdgeSetup, n: int, half=None) -> tuple[int, int]:
    """Half-open index range of pixel centres c with ``lo <= c <= hi``, clipped to [0, n)."""
    first, stop = centre_ranges(np.asarray(lo), np.asarray(hi), setup, n, half)
    return int(first), int(stop)


def pixel_bbox(setup: EdgeSetup, width: int, height: int) -> BBox:
    """Bounding box of the triangle's vertices, as pixel index ranges clipped to the image.

    The pixels whose tested point (centre, or ``setup.sample``) lies in the box.
    """
    lo, hi = setup.p.min(axis=0), setup.p.max(axis=0)
    col0, col1 = centre_range(lo[0], hi[0], setup, width, setup.offset_x)
    row0, row1 = centre_range(lo[1], hi[1], setup, height, setup.offset_y)
    px = 1.0 / float(setup.unit)
    return BBox(
        row0=row0,
        row1=row1,
        col0=col0,
        col1=col1,
        xmin=float(lo[0]) * px,
        xmax=float(hi[0]) * px,
        ymin=float(lo[1]) * px,
        ymax=float(hi[1]) * px,
    )
