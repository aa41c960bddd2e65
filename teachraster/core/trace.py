"""The trace: every step of one fill, recorded as plain data for the presentation layer.

A trace holds numpy arrays and small frozen dataclasses only (never one Python object per
pixel): steps are *numbered* and their captions are written on demand, so recording a
256×256 fill costs a few arrays. Per-pixel arrays cover the bounding box; use
:meth:`FillTrace.image` to place one in the whole image.

Steps run in this order: set-up steps (snap, winding, bounding box, and for span tables
sort and split; for tiles the block sizes), then the work steps (one per raster line for
span tables, one per visited pixel for half-planes, one per classified block for tiles),
then one interpolation step.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass

import numpy as np

from .bbox import BBox
from .half_planes import HalfPlaneTrace
from .span_tables import SpanTrace
from .tile_trace import TileTrace


@dataclass(frozen=True)
class Step:
    """One step of a fill, as the widgets show it.

    ``kind`` is one of ``"snap"``, ``"winding"``, ``"bbox"``, ``"sort"``, ``"split"``,
    ``"blocks"``, ``"row"``, ``"pixel"``, ``"block"``, ``"interpolate"``. ``row``/``col``
    are image indices where the step concerns one raster line, pixel or block (its
    top-left pixel).
    """

    index: int
    kind: str
    caption: str
    row: int | None = None
    col: int | None = None


@dataclass(frozen=True)
class FillTrace:
    """Everything :func:`teachraster.rasterize` did for one triangle (``trace=True``).

    Attributes
    ----------
    method, interpolation : str
        As passed to ``rasterize``.
    subpixel_bits : int or None
        Snapping precision used (None = raw floats).
    width, height : int
        Image size.
    xy, snapped : (3, 2) float
        Vertex positions as given and after snapping, in pixels.
    signed_area : float
        Area in px² of the snapped triangle, positive when clockwise on screen.
    front_facing, culled : bool
        Counter-clockwise on screen; removed by back/front-face culling.
    edges : (3, 2) int
        Original vertex indices (from, to) of the edges, in test order.
    top_left : (3,) bool
        Whether each edge is a top or left edge (decides centres exactly on it).
    bbox : BBox
        Pixels whose centres lie in the bounding box, clipped to the image.
    filled_at : (rows, cols) int32
        Step index at which each bbox pixel was filled, -1 if never.
    pixel_barycentric : (n, 3) float64
        Screen-space weights of vertices 0, 1, 2 at each covered pixel, in row-major order
        (the order of ``np.nonzero(filled_at >= 0)``); the ``barycentric`` property places
        them in a bbox-local image.
    pixel_affine, pixel_perspective : mapping of name to (n,) or (n, k) float64
        Both interpolations of every attribute at each covered pixel (properties
        ``affine`` and ``perspective`` give bbox-local images, NaN outside coverage).
    pixel_depth : (n,) float64 or None
        Interpolated window depth at each covered pixel (property ``depth``).
    span, halfplane, blocks : SpanTrace or HalfPlaneTrace or TileTrace or None
        The algorithm-specific record (the others are None).
    setup : tuple of (kind, caption)
        The set-up steps.
    subdivision : int or None
        N of ``interpolation="subdivided"``; None for the other modes.
    pixel_subdivided : mapping of name to (n,) or (n, k) float64, or None
        The subdivided values actually written (``interpolation="subdivided"`` only).
    """

    method: str
    interpolation: str
    subpixel_bits: int | None
    width: int
    height: int
    xy: np.ndarray
    snapped: np.ndarray
    signed_area: float
    front_facing: bool
    culled: bool
    edges: np.ndarray
    top_left: np.ndarray
    bbox: BBox
    filled_at: np.ndarray
    pixel_barycentric: np.ndarray
    pixel_affine: Mapping[str, np.ndarray]
    pixel_perspective: Mapping[str, np.ndarray]
    pixel_depth: np.ndarray | None
    span: SpanTrace | None
    halfplane: HalfPlaneTrace | None
    setup: tuple[tuple[str, str], ...]
    subdivision: int | None = None
    pixel_subdivided: Mapping[str, np.ndarray] | None = None
    blocks: TileTrace | None = None

    # -- per-pixel values as bbox-local images (NaN outside coverage) -----------------
    @property
    def covered(self) -> np.ndarray:
        """(rows, cols) bool: bbox pixels the triangle covers."""
        return self.filled_at >= 0

    def _local(self, values: np.ndarray) -> np.ndarray:
        out = np.full((*self.bbox.shape, *values.shape[1:]), np.nan)
        out[self.covered] = values
        return out

    @property
    def barycentric(self) -> np.ndarray:
        """(rows, cols, 3) screen-space barycentrics, NaN outside coverage."""
        return self._local(self.pixel_barycentric)

    @property
    def affine(self) -> dict[str, np.ndarray]:
        """Affine (screen-space) value of every attribute, bbox-local, NaN outside."""
        return {k: self._local(v) for k, v in self.pixel_affine.items()}

    @property
    def perspective(self) -> dict[str, np.ndarray]:
        """Perspective-correct value of every attribute, bbox-local, NaN outside."""
        return {k: self._local(v) for k, v in self.pixel_perspective.items()}

    @property
    def depth(self) -> np.ndarray | None:
        """Window depth, bbox-local, NaN outside coverage (None without z)."""
        return None if self.pixel_depth is None else self._local(self.pixel_depth)

    # -- stepping -------------------------------------------------------------------
    @property
    def n_work(self) -> int:
        """Work steps: raster lines (span), visited pixels (half-plane) or blocks (tiled)."""
        if self.culled:
            return 0
        if self.span is not None:
            return len(self.span.rows)
        if self.blocks is not None:
            return len(self.blocks)
        return self.bbox.size

    def __len__(self) -> int:
        return len(self.setup) + self.n_work + 1

    def __iter__(self) -> Iterator[Step]:
        return (self.step(k) for k in range(len(self)))

    @property
    def first_work_step(self) -> int:
        return len(self.setup)

    def step(self, k: int) -> Step:
        """Step ``k`` (negative counts from the end), with its caption."""
        n = len(self)
        if not -n <= k < n:
            raise IndexError(f"step {k} out of range for a trace of {n} steps")
        k %= n
        if k < len(self.setup):
            kind, caption = self.setup[k]
            return Step(k, kind, caption)
        i = k - len(self.setup)
        if i == self.n_work:
            return Step(k, "interpolate", self._interpolation_caption())
        if self.span is not None:
            return self._row_step(k, i)
        if self.blocks is not None:
            b = self.blocks
            caption = b.caption(i, self.edges)
            return Step(k, "block", caption, row=int(b.row[i]), col=int(b.col[i]))
        return self._pixel_step(k, i)

    def caption(self, k: int) -> str:
        """The one-line plain-English caption of step ``k``."""
        return self.step(k).caption

    def coverage_at(self, k: int) -> np.ndarray:
        """(height, width) bool: the pixels filled once steps 0..k have run.

        ``k`` counts from the end when negative, as in :meth:`step`.
        """
        k = self.step(k).index  # validates k and resolves negative indices
        done = (self.filled_at >= 0) & (self.filled_at <= k)
        return self.image(done, fill=False)

    def image(self, local: np.ndarray, fill=np.nan) -> np.ndarray:
        """Place a bbox-local array into a full (height, width, ...) image."""
        b = self.bbox
        out = np.full((self.height, self.width, *local.shape[2:]), fill, dtype=local.dtype)
        out[b.row0 : b.row1, b.col0 : b.col1] = local
        return out

    # -- captions -------------------------------------------------------------------
    def _row_step(self, k: int, i: int) -> Step:
        s = self.span
        row, part = int(s.rows[i]), ("flat-bottom", "flat-top")[s.half[i]]
        start, stop = int(s.col_start[i]), int(s.col_stop[i])
        where = f"row {row} (y = {row + 0.5:g}, {part} part)"
        if np.isfinite(s.x_left[i]) and np.isfinite(s.x_right[i]):
            where += f": span x = {s.x_left[i]:.2f} .. {s.x_right[i]:.2f}"
        if stop > start:
            cols = f"column {start}" if stop == start + 1 else f"columns {start}-{stop - 1}"
            text = f"{where} covers {cols}"
        else:
            text = f"{where} covers no pixel centre"
        return Step(k, "row", text, row=row)

    def _pixel_step(self, k: int, i: int) -> Step:
        h = self.halfplane
        r, c = divmod(i, self.bbox.shape[1])
        row, col = self.bbox.row0 + r, self.bbox.col0 + c
        e = h.edge_values[r, c]
        run = int(h.tests_run[r, c])
        parts = []
        for t in range(run):
            a, b = self.edges[t]
            passed = e[t] > 0 or (e[t] == 0 and self.top_left[t])
            rel = ">" if e[t] > 0 else "<" if e[t] < 0 else "="
            tie = " (on a top-left edge)" if e[t] == 0 and passed else ""
            tie = " (on an edge that is not top-left)" if e[t] == 0 and not passed else tie
            parts.append(f"E{a}{b} = {e[t]:.3g} {rel} 0{tie}")
        rejected = int(h.rejected_by[r, c])
        verdict = (
            "inside: covered"
            if rejected < 0
            else f"outside: rejected by test {rejected + 1} of 3"
            + (", later tests skipped" if run < 3 else "")
        )
        text = f"pixel (row {row}, col {col}) at ({col + 0.5:g}, {row + 0.5:g}): "
        return Step(k, "pixel", text + ", ".join(parts) + f" -> {verdict}", row=row, col=col)

    def _interpolation_caption(self) -> str:
        n = int((self.filled_at >= 0).sum())
        if self.culled:
            return "triangle culled: nothing to interpolate"
        names = list(self.pixel_affine)
        if self.pixel_depth is not None:
            names.append("depth z (affine)")
        if not names:
            return f"{n} pixels covered; no attributes to interpolate"
        how = {
            "perspective": "perspective-correct (f/w and 1/w are affine on screen)",
            "affine": "affine in screen space",
            "subdivided": f"perspective-correct at every {self.subdivision}th pixel of each "
            "span and at its ends, affine in between",
        }[self.interpolation]
        return f"interpolated {', '.join(names)} at {n} covered pixels, {how}"
