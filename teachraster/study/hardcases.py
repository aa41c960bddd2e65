"""A catalogue of named hard cases: inputs that break naive rasterisers, and what must happen.

Each :class:`HardCase` holds its inputs, a one-line ``why``, what a correct rasteriser must do
(``expect`` in words, :meth:`HardCase.check` as code), a :meth:`HardCase.run` that executes it
with the core (:func:`teachraster.rasterize` for screen-space triangles,
:func:`teachraster.pipeline.render_triangles.render` for clip-space ones) and, where it is instructive, a
:meth:`HardCase.naive` version: what a straightforward implementation computes instead, written
out below in a few lines of numpy so that lesson 07 can show "naive vs ours" side by side.

>>> case = get_case("d3d_split_square")
>>> case.why
'a square with corners on pixel centres split along its \\\\ diagonal ...'
>>> result = case.run(method="span")
>>> case.check(result)                 # raises AssertionError if the rasteriser is wrong
>>> int(result.counts.max()), int(case.naive().counts.max())   # ours once, naive twice
(1, 2)

Results
-------
- screen-space cases (``kind`` "triangle", "triangles", "mesh") return a :class:`Fills`: one
  :class:`~teachraster.core.fill.Fill` per triangle and their summed coverage ``counts``;
- clip-space cases ("clip") return a :class:`Rendered`: the frame and the union coverage of
  the clipped window triangles filled again with the chosen method;
- precision and depth cases return a small dataclass of measured numbers.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from types import MappingProxyType
from typing import Any

import numpy as np

from ..core import half_planes, span_tables
from ..core.barycentrics import barycentric_pixels
from ..core.bbox import pixel_bbox
from ..core.edges import setup_edges
from ..core.fill import Fill, rasterize
from ..core.interpolation import blend
from ..core.plane_equations import attribute_plane, plane_equation
from ..core.snapping import SUBPIXEL_BITS, snap
from ..core.triangle import Triangle
from ..core.validate import as_int, as_size
from ..pipeline.camera import perspective
from ..pipeline.render_triangles import Frame
from ..pipeline.render_triangles import render as render_clip

#: Fill methods a screen-space case runs with.
FILL_METHODS = ("halfplane", "span")
#: Depth buffer formats, from most to fewest bits.
DEPTH_ORDER = ("float64", "float32", "unorm24", "unorm16")


# -- results ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class Fills:
    """Result of a screen-space case: one fill per triangle, and how often each pixel was hit."""

    fills: tuple[Fill, ...]
    counts: np.ndarray  # (H, W) int: number of triangles covering each pixel centre
    extra: Mapping[str, Any] | None = None  # case-specific results (e.g. culled coverage)


@dataclass(frozen=True)
class Rendered:
    """Result of a clip-space case.

    ``coverage`` is the union of the clipped window triangles (``frame.trace.window``) filled
    again by :func:`teachraster.rasterize` with the case's fill method: it must equal
    ``frame.coverage``, so the clip cases exercise both fill methods too.
    """

    frame: Frame
    coverage: np.ndarray


@dataclass(frozen=True)
class Naive:
    """What a naive implementation computed (fields depend on the case; unused ones are None).

    Attributes
    ----------
    counts : (H, W) int or None
        Naive coverage counts of the case's triangles.
    window : (N, 3, 3) float or None
        Window coordinates after dividing by w *before* clipping.
    values : mapping or None
        Named measurements (errors, coverages per offset, ...).
    """

    counts: np.ndarray | None = None
    window: np.ndarray | None = None
    values: Mapping[str, Any] | None = None


# -- the case --------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class HardCase:
    """One named hard case.

    Attributes
    ----------
    name : str
        Registry key.
    why : str
        One line: what makes it hard.
    kind : str
        "triangle", "triangles" (independent), "mesh" (watertight), "clip", "precision",
        "depth".
    expect : str
        What a correct rasteriser must do, in words (:meth:`check` is the same in code).
    inputs : mapping
        The case's data (read-only arrays).
    naive_does : str
        What the naive version does wrong ("" when the case has none).
    methods : tuple of str
        Fill methods the case runs with.
    """

    name: str
    why: str
    kind: str
    expect: str
    inputs: Mapping[str, Any]
    runner: Callable[[Mapping[str, Any], str], Any] = field(repr=False)
    checker: Callable[[Mapping[str, Any], Any], None] = field(repr=False)
    naive_does: str = ""
    naive_runner: Callable[[Mapping[str, Any]], Naive] | None = field(default=None, repr=False)
    naive_shows: Callable[[Mapping[str, Any], Any, Naive], str | None] | None = field(
        default=None, repr=False
    )
    methods: tuple[str, ...] = FILL_METHODS

    def run(self, method: str | None = None):
        """Execute the case with the core and return its result (see the module docstring).

        ``method`` is one of :attr:`methods` (default: the first).
        """
        method = self.methods[0] if method is None else method
        if method not in self.methods:
            raise ValueError(f"{self.name}: method must be one of {self.methods}, got {method!r}")
        return self.runner(self.inputs, method)

    def check(self, result) -> None:
        """Raise ``AssertionError`` (saying what is wrong) unless ``result`` meets ``expect``."""
        self.checker(self.inputs, result)

    @property
    def has_naive(self) -> bool:
        return self.naive_runner is not None

    def naive(self) -> Naive:
        """What the naive implementation described by ``naive_does`` computes."""
        if self.naive_runner is None:
            raise ValueError(f"{self.name} has no naive variant")
        return self.naive_runner(self.inputs)

    def naive_difference(self, ours, naive: Naive) -> str | None:
        """How the naive result visibly differs from ours (one line), or None if it does not."""
        if self.naive_shows is None:
            return None
        return self.naive_shows(self.inputs, ours, naive)

    @property
    def triangles(self) -> np.ndarray | None:
        """(n, 3, 2) screen-space triangles of a screen-space case, else None."""
        return self.inputs.get("triangles")


def _frozen(**inputs) -> Mapping[str, Any]:
    for value in inputs.values():
        if isinstance(value, np.ndarray):
            value.flags.writeable = False
    return MappingProxyType(inputs)


# -- naive helpers (numpy only; deliberately what the core does *not* do) -------------------
def naive_coverage(
    xy,
    width: int,
    height: int,
    *,
    rule: str = "inclusive",
    dtype=np.float64,
    orient: str = "unsnapped",
    absolute: bool = False,
    origin: tuple[int, int] = (0, 0),
) -> np.ndarray:
    """Coverage by raw floating-point edge functions: no snapping and (unless asked) no tie rule.

    Parameters
    ----------
    xy : (3, 2) array-like
        Vertices in pixels.
    width, height : int
        Size of the window of pixels tested.
    rule : {"inclusive", "strict", "top_left"}
        A centre on an edge is inside (``E >= 0``: shared edges are drawn twice), outside
        (``E > 0``: shared edges are drawn by nobody), or decided by the top-left rule.
    dtype : numpy float type
        Arithmetic of the edge functions (float32 as on old GPUs and in shaders).
    orient : {"unsnapped", "none"}
        Orient by the sign of the float area, or assume clockwise-on-screen input (a
        counter-clockwise triangle then covers nothing).
    absolute : bool
        Evaluate ``E = A x + B y + C`` with absolute coordinates (*Triangle Rasterisation II - Interpolation*'s plane form),
        which cancels catastrophically far from the origin, instead of from differences.
    origin : (row, col)
        Pixel index of the window's top-left pixel (for triangles far from the origin).
    """
    v = np.asarray(xy, dtype=np.float64).astype(dtype)
    (ax, ay), (bx, by), (cx, cy) = v
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if orient == "unsnapped" and area < 0:
        v = v[[0, 2, 1]]
    rows = np.arange(origin[0], origin[0] + height)
    cols = np.arange(origin[1], origin[1] + width)
    py = (rows.astype(np.float64) + 0.5).astype(dtype)[:, None]
    px = (cols.astype(np.float64) + 0.5).astype(dtype)[None, :]
    inside = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        if absolute:
            A, B = a[1] - b[1], b[0] - a[0]
            C = a[0] * b[1] - a[1] * b[0]
            e = A * px + B * py + C
        else:
            e = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
        if rule == "inclusive":
            ok = e >= 0
        elif rule == "strict":
            ok = e > 0
        else:
            top_left = b[1] < a[1] or (b[1] == a[1] and b[0] > a[0])
            ok = e >= 0 if top_left else e > 0
        inside &= ok
    return inside


def naive_counts(triangles, width: int, height: int, **kwargs) -> np.ndarray:
    """Sum of :func:`naive_coverage` over triangles."""
    width, height = as_size("width", width), as_size("height", height)
    counts = np.zeros((height, width), dtype=np.int64)
    for xy in triangles:
        counts += naive_coverage(xy, width, height, **kwargs)
    return counts


def naive_window(clip, width: int, height: int) -> np.ndarray:
    """Divide by w *before* clipping: a vertex behind the eye is mirrored, w = 0 gives inf/NaN."""
    width, height = as_size("width", width), as_size("height", height)
    c = np.asarray(clip, dtype=np.float64)
    with np.errstate(divide="ignore", invalid="ignore"):
        ndc = c[..., :3] / c[..., 3:4]
    x = (ndc[..., 0] + 1.0) * (width / 2)
    y = (1.0 - ndc[..., 1]) * (height / 2)
    return np.stack([x, y, ndc[..., 2] * 0.5 + 0.5], axis=-1)


def naive_stepped32(xy, f, x0: float, y0: float, ncols: int, nrows: int) -> np.ndarray:
    """Seed 002's incremental stepping (start, then ``+= dx`` per pixel) in float32."""
    ncols, nrows = as_size("ncols", ncols), as_size("nrows", nrows)
    plane = plane_equation(xy, f)
    start = np.float32(plane(x0, y0))
    dx, dy = np.float32(plane.dx), np.float32(plane.dy)
    firsts = np.add.accumulate(np.r_[start, np.full(nrows - 1, dy, dtype=np.float32)])
    grid = np.empty((nrows, ncols), dtype=np.float32)
    grid[:, 0] = firsts
    grid[:, 1:] = dx
    return np.add.accumulate(grid, axis=1, dtype=np.float32).astype(np.float64)


def naive_affine(xy, f, width: int, height: int) -> np.ndarray:
    """Screen-space (affine) interpolation everywhere in the image, ignoring w."""
    width, height = as_size("width", width), as_size("height", height)
    v = np.asarray(xy, dtype=np.float64)
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    (ax, ay), (bx, by), (cx, cy) = v
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    l0 = ((cx - bx) * (ys - by) - (cy - by) * (xs - bx)) / area
    l1 = ((ax - cx) * (ys - cy) - (ay - cy) * (xs - cx)) / area
    l2 = 1.0 - l0 - l1
    f = np.asarray(f, dtype=np.float64)
    return l0 * f[0] + l1 * f[1] + l2 * f[2]


def naive_perspective32(lam: np.ndarray, w, f) -> np.ndarray:
    """Perspective-correct weights in float32, as a shader would: ``(λ/w) / Σ λ/w``."""
    lam32 = lam.astype(np.float32)
    with np.errstate(all="ignore"):
        q = lam32 / np.asarray(w, dtype=np.float64).astype(np.float32)
        q = q / q.sum(axis=1, keepdims=True)
    return (q.astype(np.float64) @ np.asarray(f, dtype=np.float64)).astype(np.float64)


# -- shared runners and checks ---------------------------------------------------------------
def _fill_all(inputs, method: str, **kwargs) -> Fills:
    width, height = inputs["size"]
    attrs = inputs.get("attrs")
    fills = []
    counts = np.zeros((height, width), dtype=np.int64)
    for k, xy in enumerate(inputs["triangles"]):
        tri = Triangle(
            xy,
            w=None if "w" not in inputs else inputs["w"][k],
            attrs={} if attrs is None else {"f": attrs[k]},
        )
        fill = rasterize(tri, width, height, method=method, trace=True, **kwargs)
        fills.append(fill)
        counts += fill.coverage
    return Fills(tuple(fills), counts)


def _where(mask: np.ndarray, limit: int = 8) -> list:
    return np.argwhere(mask)[:limit].tolist()


def _check_finite(result: Fills) -> None:
    """Attributes and barycentrics finite and sane inside coverage, NaN outside."""
    for k, fill in enumerate(result.fills):
        for name, values in fill.attrs.items():
            inside = values[fill.coverage]
            assert np.isfinite(inside).all(), f"triangle {k}: {name} not finite inside coverage"
            assert np.isnan(values[~fill.coverage]).all(), f"triangle {k}: {name} set outside"
        lam = fill.trace.pixel_barycentric
        assert np.isfinite(lam).all(), f"triangle {k}: barycentrics not finite"
        assert ((lam >= 0) & (lam <= 1)).all(), f"triangle {k}: barycentrics outside [0, 1]"
        assert np.allclose(lam.sum(axis=1), 1.0, rtol=0, atol=1e-12), f"triangle {k}: Σλ != 1"


def _check_mask(inputs, result: Fills) -> None:
    """Counts equal the hand-derived ``expected`` mask of the case (0/1 per pixel)."""
    _check_finite(result)
    want = inputs["expected"].astype(np.int64)
    got = result.counts
    bad = got != want
    assert not bad.any(), (
        f"coverage differs from the expected pixels at (row, col) {_where(bad)}: "
        f"got counts {got[bad][:8].tolist()}, want {want[bad][:8].tolist()}"
    )


def _check_nothing(inputs, result: Fills) -> None:
    for k, fill in enumerate(result.fills):
        assert not fill.coverage.any(), (
            f"triangle {k} has zero area after snapping but covers {_where(fill.coverage)}"
        )
        for name, values in fill.attrs.items():
            assert np.isnan(values).all(), f"triangle {k}: {name} not NaN everywhere"


def _check_watertight(inputs, result: Fills) -> None:
    """No pixel twice; every centre strictly inside the mesh's outline exactly once."""
    _check_finite(result)
    twice = result.counts > 1
    assert not twice.any(), f"pixel centres covered twice: {_where(twice)}"
    holes = inputs["interior"] & (result.counts != 1)
    assert not holes.any(), f"interior pixel centres not covered (cracks): {_where(holes)}"


def _naive_double_hits(inputs, ours: Fills, naive: Naive) -> str | None:
    twice = int((naive.counts > 1).sum())
    return (
        f"naive covers {twice} pixel centre(s) twice" if twice and ours.counts.max() <= 1 else None
    )


def _naive_differs(inputs, ours: Fills, naive: Naive) -> str | None:
    diff = naive.counts != ours.counts
    if not diff.any():
        return None
    return f"naive coverage differs at {int(diff.sum())} pixel(s), e.g. {_where(diff, 3)}"


def _naive_mesh(rule: str, **kwargs):
    def run(inputs) -> Naive:
        width, height = inputs["size"]
        return Naive(counts=naive_counts(inputs["triangles"], width, height, rule=rule, **kwargs))

    return run


def _tris(*tris) -> np.ndarray:
    return np.array(tris, dtype=np.float64)


def _mask(height, width, fn) -> np.ndarray:
    i, j = np.indices((height, width))
    return fn(i, j)


def _strictly_inside(polygon, width: int, height: int) -> np.ndarray:
    """Pixel centres strictly inside a convex polygon given in order (exact: dyadic inputs)."""
    p = np.asarray(polygon, dtype=np.float64)
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    sides = []
    for k in range(len(p)):
        a, b = p[k], p[(k + 1) % len(p)]
        sides.append((b[0] - a[0]) * (ys - a[1]) - (b[1] - a[1]) * (xs - a[0]))
    sides = np.array(sides)
    return (sides > 0).all(axis=0) | (sides < 0).all(axis=0)


# -- coverage cases --------------------------------------------------------------------------
CASES: dict[str, HardCase] = {}


def _add(case: HardCase) -> None:
    assert case.name not in CASES, case.name
    CASES[case.name] = case


def _split_square(name, diagonal):
    lo, hi = 1.5, 6.5
    tl, tr_, br, bl = (lo, lo), (hi, lo), (hi, hi), (lo, hi)
    tris = (
        _tris((tl, tr_, br), (tl, br, bl))
        if diagonal == "\\"
        else _tris((tl, tr_, bl), (tr_, br, bl))
    )
    expected = _mask(8, 8, lambda i, j: (i >= 1) & (i <= 5) & (j >= 1) & (j <= 5))
    _add(
        HardCase(
            name,
            f"a square with corners on pixel centres split along its {diagonal} diagonal "
            "(through centres): every edge is a tie",
            "mesh",
            "exactly the 25 centres (1..5, 1..5) covered, each once: the top and left sides "
            "and the diagonal's centres go to exactly one triangle, the right and bottom "
            "sides to none (Direct3D's split-square example)",
            _frozen(
                triangles=tris,
                size=(8, 8),
                expected=expected,
                attrs=np.array([[0.0, 1.0, 2.0], [0.0, 2.0, 3.0]]),
            ),  # fmt: skip
            _fill_all,
            _check_mask,
            "raw floats with E >= 0 (no top-left rule) give the diagonal's centres to both "
            "triangles, and also fill the right and bottom sides",
            _naive_mesh("inclusive"),
            _naive_double_hits,
        )
    )


_split_square("d3d_split_square", "\\")
_split_square("d3d_split_square_other_diagonal", "/")

# Integer directions in angular order: every spoke from a pixel centre passes through centres.
_LATTICE = [(1, 0), (2, 1), (1, 1), (1, 2), (0, 1), (-1, 2), (-1, 1), (-2, 1),
            (-1, 0), (-2, -1), (-1, -1), (-1, -2), (0, -1), (1, -2), (1, -1), (2, -1)]  # fmt: skip


def _fan_case():
    centre = np.array([9.5, 9.5])
    rim = [centre + 3 * np.array(d, dtype=float) for d in _LATTICE]
    tris = _tris(*[(centre, rim[k], rim[(k + 1) % len(rim)]) for k in range(len(rim))])
    _add(
        HardCase(
            "fan_spokes_through_centres",
            "16 triangles around a pixel centre whose spokes and rim pass through pixel centres",
            "mesh",
            "no pixel centre covered twice (the shared centre vertex included), every centre "
            "strictly inside the fan's outline covered exactly once",
            _frozen(triangles=tris, size=(20, 20), interior=_strictly_inside(rim, 20, 20)),
            _fill_all,
            _check_watertight,
            "raw floats with E >= 0 hit every spoke's centres twice and the hub 16 times",
            _naive_mesh("inclusive"),
            _naive_double_hits,
        )
    )


_fan_case()


def _six_orders():
    base = np.array([[1.5, 1.5], [13.5, 4.5], [4.5, 13.5]])  # every edge passes through centres
    f = np.array([[0.0, 1.0], [10.0, -2.0], [3.0, 7.5]])
    perms = list(itertools.permutations(range(3)))
    tris = np.array([base[list(p)] for p in perms])
    attrs = np.array([f[list(p)] for p in perms])
    w = np.array([np.array([1.0, 2.5, 4.0])[list(p)] for p in perms])

    def check(inputs, result: Fills) -> None:
        _check_finite(result)
        first = result.fills[0]
        assert first.coverage.any(), "the triangle covers nothing"
        for k, fill in enumerate(result.fills[1:], start=1):
            bad = fill.coverage != first.coverage
            assert not bad.any(), f"vertex order {perms[k]} changes coverage at {_where(bad)}"
            err = np.nanmax(np.abs(fill.attrs["f"] - first.attrs["f"]))
            assert err <= 1e-12, f"vertex order {perms[k]} changes attributes by {err:.3g}"

    def shows(inputs, ours: Fills, naive: Naive) -> str | None:
        empty = [perms[k] for k in range(6) if not naive.values["coverage"][k].any()]
        return f"naive covers nothing for orders {empty}" if empty else None

    def naive(inputs) -> Naive:
        cov = [naive_coverage(xy, 16, 16, rule="top_left", orient="none") for xy in tris]
        return Naive(values={"coverage": cov})

    _add(
        HardCase(
            "six_vertex_orders",
            "the same triangle given in all 6 vertex orders (both windings), edges through centres",
            "triangles",
            "identical coverage for all 6 orders (both windings are filled; ties follow the "
            "geometry, not the order) and attributes (perspective, unequal w) equal within "
            "1e-12",
            _frozen(triangles=tris, size=(16, 16), attrs=attrs, w=w),
            _fill_all,
            check,
            "assuming one winding (no re-orientation) covers nothing for the 3 reversed orders",
            naive,
            shows,
        )
    )


_six_orders()

_add(
    HardCase(
        "flat_top",
        "a flat-top triangle (horizontal top edge through centres): the span split degenerates",
        "triangle",
        "exactly the centres with i >= 1, j >= 1, i + j < 8 (21 pixels): the top and left "
        "edges' centres covered, the hypotenuse's (a right edge) not",
        _frozen(
            triangles=_tris(((1.5, 1.5), (7.5, 1.5), (1.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 6.0, 12.0]]),
            expected=_mask(10, 10, lambda i, j: (i >= 1) & (j >= 1) & (i + j < 8)),
        ),
        _fill_all,
        _check_mask,
        "raw floats with E > 0 drop the whole top row and left column",
        _naive_mesh("strict"),
        _naive_differs,
    )
)

_add(
    HardCase(
        "flat_bottom",
        "a flat-bottom triangle (horizontal bottom edge through centres): no lower half",
        "triangle",
        "exactly the centres with 1 <= j < i <= 6 (15 pixels): the left edge's centres "
        "covered; the hypotenuse (the interior is below-left of it: a right edge) and the "
        "bottom edge not",
        _frozen(
            triangles=_tris(((1.5, 1.5), (1.5, 7.5), (7.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 6.0, 12.0]]),
            expected=_mask(10, 10, lambda i, j: (j >= 1) & (j < i) & (i <= 6)),
        ),
        _fill_all,
        _check_mask,
        "raw floats with E >= 0 also fill the bottom row and the diagonal",
        _naive_mesh("inclusive"),
        _naive_differs,
    )
)

_add(
    HardCase(
        "near_flat",
        "the flat-top triangle with one top vertex 1/256 px lower: the split point u4 is "
        "1/256 px below v1",
        "triangle",
        "the top edge now slopes down (not a top edge): row 1 loses every centre, the "
        "vertex pixel (1, 1) included; the hypotenuse moved right by < 1/256 px, so its "
        "centres i + j = 8 are now strictly inside: 2 <= i <= 6, j >= 1, i + j <= 8 (20)",
        _frozen(
            triangles=_tris(((1.5, 1.5), (7.5, 1.5 + 1 / 256), (1.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 6.0, 12.0]]),
            expected=_mask(10, 10, lambda i, j: (i >= 2) & (i <= 6) & (j >= 1) & (i + j <= 8)),
        ),
        _fill_all,
        _check_mask,
        "raw floats with E >= 0 and no tie rule keep the vertex (1, 1) and (7, 1) on the "
        "sloped edges",
        _naive_mesh("inclusive"),
        _naive_differs,
    )
)

_add(
    HardCase(
        "collinear",
        "three distinct vertices on one line through pixel centres: zero area",
        "triangle",
        "covers nothing, attributes NaN everywhere, no warning or division by zero",
        _frozen(
            triangles=_tris(((1.5, 1.5), (4.5, 4.5), (7.5, 7.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 1.0, 2.0]]),
        ),
        _fill_all,
        _check_nothing,
        "raw floats with E >= 0 fill the 7 centres on the line (every E is 0 there)",
        _naive_mesh("inclusive"),
        _naive_differs,
    )
)

_add(
    HardCase(
        "coincident_vertices",
        "two vertices in the same place: zero area, and an edge of length 0",
        "triangle",
        "covers nothing, attributes NaN everywhere",
        _frozen(
            triangles=_tris(((2.5, 2.5), (2.5, 2.5), (6.5, 4.5))),
            size=(10, 10),
            attrs=np.array([[0.0, 1.0, 2.0]]),
        ),
        _fill_all,
        _check_nothing,
        "raw floats with E >= 0 fill the centres on the remaining segment",
        _naive_mesh("inclusive"),
        _naive_differs,
    )
)


def _subpixel():
    tris = _tris(
        ((3.3, 2.3), (3.8, 2.4), (3.45, 2.9)),  # contains the centre (3.5, 2.5)
        ((6.6, 2.6), (7.4, 2.7), (7.0, 3.4)),  # between centres
        ((5.5, 5.5), (5.8, 5.5), (5.5, 5.8)),  # vertex on a centre, top and left edges there
        ((9.5, 9.5), (9.2, 9.5), (9.5, 9.2)),  # vertex on a centre, bottom and right edges
    )
    expected = np.zeros((12, 12), dtype=bool)
    expected[2, 3] = expected[5, 5] = True

    def naive(inputs) -> Naive:
        rounded = np.rint(inputs["triangles"])  # no sub-pixel bits: whole-pixel vertices
        return Naive(counts=naive_counts(rounded, 12, 12, rule="top_left"))

    _add(
        HardCase(
            "subpixel_triangles",
            "triangles smaller than a pixel: each covers one centre or none",
            "triangles",
            "exactly pixels (2, 3) (contains its centre) and (5, 5) (a vertex on the centre "
            "with a top and a left edge there); the one between centres and the one with a "
            "bottom and a right edge at its centre vertex cover nothing",
            _frozen(triangles=tris, size=(12, 12), expected=expected),
            _fill_all,
            _check_mask,
            "vertices rounded to whole pixels (no sub-pixel precision) lose the first "
            "triangle's centre and collapse or move the others",
            naive,
            _naive_differs,
        )
    )


_subpixel()


def _slivers():
    g = 1 / 256
    tris = _tris(
        ((0.5, 1.5), (60.5, 1.5), (60.5, 1.5 - g)),  # above the shared edge y = 1.5
        ((0.5, 1.5), (60.5, 1.5 + g), (60.5, 1.5)),  # below it
    )
    interior = _mask(4, 64, lambda i, j: (i == 1) & (j >= 1) & (j <= 59))
    _add(
        HardCase(
            "sliver_pair",
            "two slivers (60 px long, 1/256 px high, area 0.12 px²) sharing an edge along "
            "a row of centres",
            "mesh",
            "the 59 centres (1, 1..59) on the shared edge covered exactly once (by the "
            "sliver below it: a top edge), none twice",
            _frozen(
                triangles=tris,
                size=(64, 4),
                interior=interior,
                attrs=np.array([[0.0, 1.0, 2.0], [0.0, 1.0, 2.0]]),
            ),  # fmt: skip
            _fill_all,
            _check_watertight,
            "raw floats with E >= 0 draw the whole row twice",
            _naive_mesh("inclusive"),
            _naive_double_hits,
        )
    )

    xy = _tris(((0.5, 0.5), (63.5, 63.5), (63.5, 63.5 - g)))

    def check(inputs, result: Fills) -> None:
        _check_finite(result)
        cov = result.fills[0].coverage
        want = _mask(64, 64, lambda i, j: (i == j) & (i >= 1) & (i <= 62))
        bad = cov != want
        assert not bad.any(), f"diagonal sliver: coverage wrong at {_where(bad)}"
        f = result.fills[0].attrs["f"][cov]
        assert (f >= 0).all() and (f <= 2).all(), "attributes outside the vertex range"

    _add(
        HardCase(
            "diagonal_sliver",
            "an 89 px diagonal sliver of area 0.12 px² whose long edge runs through 64 centres",
            "triangle",
            "exactly the diagonal centres (k, k) for k = 1..62: the long edge goes up (a left "
            "edge, so its centres count); the end centres (0, 0) and (63, 63) are vertices "
            "that also lie on a down-going (right) edge; barycentrics in [0, 1], attributes "
            "finite and in range",
            _frozen(triangles=xy, size=(64, 64), attrs=np.array([[0.0, 1.0, 2.0]])),
            _fill_all,
            check,
            "raw floats with E > 0 lose every diagonal centre: the sliver vanishes",
            _naive_mesh("strict"),
            _naive_differs,
        )
    )


_slivers()


# -- far from the origin ---------------------------------------------------------------------
@dataclass(frozen=True)
class FarResult:
    """Coverage and attributes of one triangle in a window near each offset.

    ``coverage[o]`` (h, w) bool and ``attrs[o]`` (h, w) float are window-local, for the
    triangle translated by ``(o, o)`` pixels; offset 0 is the reference.
    """

    coverage: Mapping[int, np.ndarray]
    attrs: Mapping[int, np.ndarray]


_FAR_WINDOW = 16


def fill_window(xy, f, row0: int, col0: int, size: int, method: str):
    """Fill ``xy`` into the ``size`` x ``size`` window at pixel (row0, col0) with the core.

    :func:`teachraster.rasterize` allocates the whole image from (0, 0); far from the origin
    that is gigabytes, so this runs the same core steps (snap and set up edges, bounding box,
    fill, exact barycentrics, blend) on the window only.
    """
    row0, col0, size = as_int("row0", row0), as_int("col0", col0), as_size("size", size)
    setup = setup_edges(np.asarray(xy, dtype=np.float64), SUBPIXEL_BITS)
    box = pixel_bbox(setup, col0 + size, row0 + size)
    assert box.row0 >= row0 and box.col0 >= col0, "triangle leaves the window"
    fills = {"halfplane": half_planes.fill, "span": span_tables.fill}
    local, _ = fills[method](setup, box, False)
    if setup.area2 == 0:
        local[:] = False
    cov = np.zeros((size, size), dtype=bool)
    cov[box.row0 - row0 : box.row1 - row0, box.col0 - col0 : box.col1 - col0] = local
    rows, cols = np.nonzero(cov)
    lam = barycentric_pixels(setup, rows + row0, cols + col0)
    values = np.full((size, size), np.nan)
    values[cov] = blend(lam, np.asarray(f, dtype=np.float64))
    return cov, values


def _far_case():
    local = np.array([[0.5, 0.5], [13.25, 3.5], [4.75, 11.5]])  # ties on centres
    f = np.array([0.1, 7.3, -2.9])
    offsets = (0, 10_000, 100_000, 1_000_000)

    def run(inputs, method) -> FarResult:
        cov, att = {}, {}
        for o in offsets:
            cov[o], att[o] = fill_window(local + o, f, o, o, _FAR_WINDOW, method)
        return FarResult(MappingProxyType(cov), MappingProxyType(att))

    def check(inputs, result: FarResult) -> None:
        ref_c, ref_a = result.coverage[0], result.attrs[0]
        assert ref_c.any(), "the triangle covers nothing at the origin"
        for o in offsets[1:]:
            bad = result.coverage[o] != ref_c
            assert not bad.any(), f"offset {o:g}: coverage differs at (local) {_where(bad)}"
            err = np.nanmax(np.abs(result.attrs[o] - ref_a))
            assert err <= 1e-12, f"offset {o:g}: attributes differ by {err:.3g}"

    def naive(inputs) -> Naive:
        values = {}
        for o in offsets:
            for name, dtype in (("float32", np.float32), ("float64", np.float64)):
                values[f"coverage_{name}_{o}"] = naive_coverage(
                    local + o, _FAR_WINDOW, _FAR_WINDOW, rule="top_left", dtype=dtype,
                    absolute=True, origin=(o, o),
                )  # fmt: skip
            # *Triangle Rasterisation II - Interpolation*'s plane in absolute coordinates, float64, at the local pixel centres
            ys, xs = np.mgrid[0:_FAR_WINDOW, 0:_FAR_WINDOW] + 0.5
            values[f"plane_{o}"] = plane_equation(local + o, f)(xs + o, ys + o)
            values[f"recentred_{o}"] = attribute_plane(local + o, f)(xs + o, ys + o)
        return Naive(values=MappingProxyType(values))

    def shows(inputs, ours: FarResult, naive: Naive) -> str | None:
        v = naive.values
        diffs = {o: int((v[f"coverage_float32_{o}"] != ours.coverage[o]).sum()) for o in offsets}
        far = offsets[-1]
        plane_err = float(
            np.nanmax(np.abs(v[f"plane_{far}"] - ours.attrs[far])[ours.coverage[far]])
        )
        if not (diffs[100_000] and diffs[far]) or plane_err <= 1e-9:
            return None
        return (
            "naive float32 absolute edge functions get "
            + ", ".join(f"{n} pixel(s) wrong at {o:g}" for o, n in diffs.items())
            + f"; the float64 absolute plane equation is off by {plane_err:.2g} at {far:g}"
        )

    _add(
        HardCase(
            "far_from_origin",
            "the same small triangle at 1e4, 1e5 and 1e6 px from the origin, edges through centres",
            "precision",
            "coverage identical to the triangle at the origin and attributes within 1e-12 "
            "at every offset (the snapped int64 edge functions are exact up to ±2**21 px)",
            _frozen(local=local, f=f, offsets=offsets),
            run,
            check,
            "float32 edge functions in absolute form (A x + B y + C with C ~ x·y) lose the "
            "bits that decide coverage (wrong pixels from 1e5); *Triangle Rasterisation II - Interpolation*'s absolute plane "
            "equation in float64 is off by ~3e-6 at 1e6",
            naive,
            shows,
        )
    )


_far_case()


def _translation_case():
    base = np.array([[0.3, 0.3], [6.7, 6.7], [0.3, 6.9]])  # the long edge is the diagonal
    f = np.array([[1.0, 0.1], [2.0, 0.2], [3.0, -0.7]])
    shifts = ((0, 0), (1, 0), (0, 3), (10, 3), (17, 29), (31, 5))
    size = (48, 48)

    def run(inputs, method) -> Fills:
        tris = np.array([base + s for s in shifts])
        return _fill_all({"triangles": tris, "size": size, "attrs": [f] * len(shifts)}, method)

    def check(inputs, result: Fills) -> None:
        _check_finite(result)
        ref = result.fills[0]
        for (dx, dy), fill in zip(shifts[1:], result.fills[1:]):
            moved = np.roll(np.roll(ref.coverage, dy, axis=0), dx, axis=1)
            bad = fill.coverage != moved
            assert not bad.any(), (
                f"shift {(dx, dy)}: coverage is not the shifted one: {_where(bad)}"
            )
            back = fill.attrs["f"][dy : dy + 16, dx : dx + 16]
            err = np.nanmax(np.abs(back - ref.attrs["f"][:16, :16]))
            assert err <= 1e-12, f"shift {(dx, dy)}: attributes differ by {err:.3g}"

    def naive(inputs) -> Naive:
        cov = [naive_coverage(base + s, *size, rule="top_left") for s in shifts]
        return Naive(values={"coverage": cov})

    def shows(inputs, ours: Fills, naive: Naive) -> str | None:
        ref = naive.values["coverage"][0]
        moved = [
            s for s, c in zip(shifts[1:], naive.values["coverage"][1:])
            if (c != np.roll(np.roll(ref, s[1], axis=0), s[0], axis=1)).any()
        ]  # fmt: skip
        return f"naive coverage changes under the shifts {moved}" if moved else None

    _add(
        HardCase(
            "translation_invariance",
            "a triangle with an edge through centres, moved by whole pixels: 0.3 + 10 is not "
            "exactly 10.3 in binary",
            "triangles",
            "coverage moves with the triangle, pixel for pixel, and attributes are equal "
            "within 1e-12 (snapping to 1/256 px commutes with whole-pixel shifts)",
            _frozen(triangles=np.array([base + s for s in shifts]), size=size),
            run,
            check,
            "raw floats (top-left rule, no snapping) decide the diagonal's ties by rounding, "
            "which changes with the shift",
            naive,
            shows,
        )
    )


_translation_case()


# -- snapping changes the triangle -----------------------------------------------------------
def _snap_cases():
    g = 1 / 256
    c = np.array([2.5, 2.5])
    # Unsnapped: E(v0, v1, v2) = 10g * 0.4g - 0.6g * 5g = +g² (clockwise, back-facing).
    # Snapped: v1 -> (10g, g), v2 -> (5g, 0): E = 10g * 0 - g * 5g = -5g² (front-facing).
    flip = _tris((c, c + (10 * g, 0.6 * g), c + (5 * g, 0.4 * g)))

    def run_flip(inputs, method) -> Fills:
        base = _fill_all(inputs, method)
        culled = {
            cull: rasterize(Triangle(flip[0]), 6, 6, method=method, cull=cull).coverage
            for cull in ("back", "front")
        }
        return Fills(base.fills, base.counts, MappingProxyType(culled))

    def check_flip(inputs, fills: Fills) -> None:
        culled = fills.extra
        _check_finite(fills)
        fill = fills.fills[0]
        assert Triangle(flip[0]).signed_area > 0, "case set-up: unsnapped should be clockwise"
        assert fill.trace.signed_area < 0, "the snapped triangle should be counter-clockwise"
        want = np.zeros((6, 6), dtype=bool)
        want[2, 2] = True
        bad = fill.coverage != want
        assert not bad.any(), f"snapped triangle coverage wrong at {_where(bad)}"
        assert culled["back"].any(), "culled as back-facing by the unsnapped winding"
        assert not culled["front"].any(), "not culled as front-facing, though it is once snapped"

    def naive_flip(inputs) -> Naive:
        # Winding decided on the unsnapped floats, edges tested on the snapped vertices.
        snapped = snap(flip[0])
        v = snapped if Triangle(flip[0]).signed_area > 0 else snapped[[0, 2, 1]]
        cov = naive_coverage(v, 6, 6, rule="top_left", orient="none")
        return Naive(counts=cov.astype(np.int64))

    _add(
        HardCase(
            "snap_flips_winding",
            "a tiny clockwise triangle whose snapped vertices run counter-clockwise",
            "triangle",
            "everything follows the snapped triangle: it is front-facing (cull='front' "
            "removes it, cull='back' keeps it) and covers exactly pixel (2, 2), where its "
            "snapped vertex sits with a top and a left edge; both methods agree",
            _frozen(triangles=flip, size=(6, 6)),
            run_flip,
            check_flip,
            "orienting by the unsnapped area but testing the snapped edges puts the inside "
            "on the negative side: pixel (2, 2) is lost",
            naive_flip,
            _naive_differs,
        )
    )

    d = 0.001  # < 1/512 px: every vertex snaps onto the centre (2.5, 2.5)
    collapse = _tris((c + (-d, -d), c + (1.5 * d, -d), c + (0, 1.5 * d)))
    _add(
        HardCase(
            "snap_degenerate",
            "a triangle 0.0025 px wide around a pixel centre: all three vertices snap to it",
            "triangle",
            "zero area after snapping: covers nothing (though the unsnapped triangle "
            "contains the centre), attributes NaN, no division by zero",
            _frozen(triangles=collapse, size=(6, 6), attrs=np.array([[0.0, 1.0, 2.0]])),
            _fill_all,
            _check_nothing,
            "raw floats see the centre strictly inside and fill pixel (2, 2)",
            _naive_mesh("strict"),
            _naive_differs,
        )
    )


_snap_cases()


# -- incremental stepping ----------------------------------------------------------------------
@dataclass(frozen=True)
class DriftResult:
    """Largest error against the exact value, over the pixels the triangle covers.

    ``ours`` is the core's fill (exact barycentrics then a blend); ``recentred`` Fatahalian's (CMU 15-462, *Texture*)
    plane evaluated directly at each pixel; ``stepped64`` *Triangle Rasterisation II - Interpolation*'s incremental stepping in
    float64 (:meth:`teachraster.PlaneEquation.stepped`).
    """

    ours: float
    recentred: float
    stepped64: float
    pixels: int


def _exact_affine(xy, f):
    """Exact f(x, y) = f0 + A (x - x0) + B (y - y0) of the plane through (xy, f), as Fractions."""
    (ax, ay), (bx, by), (cx, cy) = ((Fraction(x), Fraction(y)) for x, y in xy)
    f0, f1, f2 = (Fraction(v) for v in f)
    det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
    A = ((cy - ay) * (f1 - f0) - (by - ay) * (f2 - f0)) / det
    B = ((bx - ax) * (f2 - f0) - (cx - ax) * (f1 - f0)) / det
    return lambda x, y: f0 + A * (Fraction(x) - ax) + B * (Fraction(y) - ay)


def _drift_case():
    width, height = 4096, 8
    xy = np.array([[0.0, 0.0], [4096.0, 0.0], [0.0, 8.0]])  # on the grid: snapping is a no-op
    f = np.array([0.1, 1000.7, 3.3])  # dx = 1000.6 / 4096 is not a short binary fraction

    def errors(values: np.ndarray, cov: np.ndarray) -> float:
        exact = _exact_affine(xy, f)
        rows, cols = np.nonzero(cov)
        # Exact comparison at a sample of covered pixels (Fractions are slow), the far end of
        # every row included: that is where stepping has accumulated the most.
        pick = np.unique(np.r_[np.arange(0, len(rows), 61), np.flatnonzero(np.diff(rows)), -1])
        err = [
            abs(float(Fraction(values[r, c]) - exact(c + 0.5, r + 0.5)))
            for r, c in zip(rows[pick], cols[pick])
        ]
        return max(err)

    def run(inputs, method) -> DriftResult:
        fill = rasterize(Triangle(xy, attrs={"f": f}), width, height, method=method)
        cov = fill.coverage
        ys, xs = np.mgrid[0:height, 0:width] + 0.5
        recentred = attribute_plane(xy, f)(xs, ys)
        stepped = plane_equation(xy, f).stepped(0.5, 0.5, width, height)
        return DriftResult(
            ours=errors(fill.attrs["f"], cov),
            recentred=errors(recentred, cov),
            stepped64=errors(stepped, cov),
            pixels=int(cov.sum()),
        )

    def check(inputs, result: DriftResult) -> None:
        assert result.pixels > 10_000, f"only {result.pixels} pixels: not a long run"
        assert result.ours <= 1e-9, f"the core's attributes are off by {result.ours:.3g}"
        assert result.recentred <= 1e-9, f"direct recentred plane off by {result.recentred:.3g}"

    def naive(inputs) -> Naive:
        stepped32 = naive_stepped32(xy, f, 0.5, 0.5, width, height)
        cov = rasterize(Triangle(xy), width, height).coverage
        return Naive(values={"stepped32": errors(stepped32, cov)})

    def shows(inputs, ours: DriftResult, naive: Naive) -> str | None:
        e32 = naive.values["stepped32"]
        if e32 <= 1e-3 or e32 <= 1e3 * max(ours.ours, 1e-300):
            return None
        return (
            f"float32 stepping drifts by {e32:.3g} over 4096 pixels (float64 stepping "
            f"{ours.stepped64:.2g}, ours {ours.ours:.2g})"
        )

    _add(
        HardCase(
            "stepping_drift",
            "an attribute stepped incrementally (f += dx per pixel) along 4096-pixel rows "
            "accumulates rounding",
            "precision",
            "the core evaluates every pixel directly from exact edge functions: error <= 1e-9 "
            "everywhere (so is Fatahalian's (CMU 15-462, *Texture*) recentred plane); *Triangle Rasterisation II - Interpolation*'s stepping in float64 "
            "drifts measurably (reported), in float32 visibly",
            _frozen(xy=xy, f=f, size=(width, height)),
            run,
            check,
            "float32 stepping (as in a fixed-function inner loop) drifts by ~1e-2 by the end "
            "of a row",
            naive,
            shows,
        )
    )


_drift_case()


# -- clip space: behind the eye ----------------------------------------------------------------
_PROJ = perspective(90.0, 1.0, 0.1, 100.0)
_CLIP_SIZE = 32


def _to_clip(view) -> np.ndarray:
    v = np.c_[np.asarray(view, dtype=np.float64), np.ones(len(view))]
    return v @ _PROJ.T


def _render_run(inputs, method) -> Rendered:
    size = _CLIP_SIZE
    frame = render_clip(inputs["clip"], size, size, attrs=inputs["attrs"], trace=True)
    cov = np.zeros((size, size), dtype=bool)
    for xyz, culled in zip(frame.trace.window, frame.trace.culled):
        if not culled:
            cov |= rasterize(Triangle(xyz[:, :2]), size, size, method=method).coverage
    return Rendered(frame, cov)


def _render_check(inputs, result: Rendered) -> None:
    frame = result.frame
    cov = frame.coverage
    assert cov.any(), "nothing drawn: the visible part of the triangle was lost"
    bad = result.coverage != cov
    assert not bad.any(), f"refilling the clipped triangles covers other pixels: {_where(bad)}"
    for name, arr in (("attrs", frame.attrs[cov]), ("depth", frame.depth[cov])):
        assert np.isfinite(arr).all(), f"{name} not finite inside coverage"
    assert np.isnan(frame.depth[~cov]).all(), "depth set outside coverage"
    d = frame.depth[cov]
    assert ((d >= 0) & (d <= 1)).all(), f"depth outside [0, 1]: {d.min():.3g} .. {d.max():.3g}"
    a = np.asarray(inputs["attrs"])[0]
    vals = frame.attrs[cov]
    lo, hi = a.min(axis=0) - 1e-12, a.max(axis=0) + 1e-12
    assert ((vals >= lo) & (vals <= hi)).all(), "attributes outside the vertices' range"
    mirrored = cov[: _CLIP_SIZE // 2]
    assert not mirrored.any(), f"pixels above the horizon (mirrored): {_where(mirrored)}"
    assert cov[-1].any(), "the floor should reach the bottom row (cut at the near plane)"


def _clip_cases():
    front = [[-1.0, -1.0, -2.0], [1.0, -1.0, -2.0]]  # on the floor, 2 units in front
    uv = np.array([[[0.0, 0.0], [1.0, 0.0], [0.5, 1.0]]])

    behind = _to_clip(front + [[0.0, -1.0, 2.0]])[None]  # w = -2: behind the eye
    on_eye = _to_clip(front + [[0.0, -1.0, 0.0]])[None]  # w = 0 exactly
    hair = _to_clip(front + [[0.0, -1.0, -1e-9]])[None]  # w = 1e-9: in front, inside near

    def naive(inputs) -> Naive:
        win = naive_window(inputs["clip"], _CLIP_SIZE, _CLIP_SIZE)
        counts = None
        if np.isfinite(win).all() and np.abs(win[..., :2]).max() < 1e6:
            counts = naive_counts(win[..., :2], _CLIP_SIZE, _CLIP_SIZE, rule="top_left")
        return Naive(counts=counts, window=win)

    def shows_mirror(inputs, ours: Rendered, naive: Naive) -> str | None:
        top = naive.counts[: _CLIP_SIZE // 2] if naive.counts is not None else None
        if top is None or not top.any():
            return None
        return f"naive mirrors the vertex above the horizon: {int(top.sum())} pixels in the sky"

    def shows_nonfinite(inputs, ours: Rendered, naive: Naive) -> str | None:
        bad = ~np.isfinite(naive.window)
        return f"naive window coordinates are {naive.window[bad][:3]}" if bad.any() else None

    def shows_far(inputs, ours: Rendered, naive: Naive) -> str | None:
        z = naive.window[..., 2]
        y = naive.window[..., 1]
        if (z >= 0).all() and np.abs(y).max() < 1e6:
            return None
        return f"naive window depth {z.min():.3g} (outside [0, 1]) and y {y.max():.3g} px"

    common = (
        "clip",
        "clipped at the near plane in clip space: only the floor below the horizon is drawn "
        "(rows 16-31), reaching the bottom row; attributes finite and within the vertices' "
        "range, depth in [0, 1]; re-filling the clipped triangles with either method gives "
        "the frame's pixels",
    )
    _add(
        HardCase(
            "behind_camera",
            "a floor triangle with one vertex behind the eye (w = -2)",
            *common,
            _frozen(clip=behind, attrs=uv),
            _render_run,
            _render_check,
            "dividing by w before clipping mirrors the vertex through the eye, into the sky",
            naive,
            shows_mirror,
        )
    )
    _add(
        HardCase(
            "eye_plane_vertex",
            "a floor triangle with one vertex exactly on the eye plane (w = 0)",
            *common,
            _frozen(clip=on_eye, attrs=uv),
            _render_run,
            _render_check,
            "dividing by w = 0 gives inf and NaN window coordinates",
            naive,
            shows_nonfinite,
        )
    )
    _add(
        HardCase(
            "hair_in_front_of_eye",
            "a floor triangle with one vertex a hair in front of the eye (w = 1e-9)",
            *common,
            _frozen(clip=hair, attrs=uv),
            _render_run,
            _render_check,
            "dividing by w = 1e-9 throws the vertex 1e10 px away, beyond any exact "
            "fixed-point range, with window depth -1e8",
            naive,
            shows_far,
        )
    )


_clip_cases()


# -- perspective denominators ----------------------------------------------------------------
def _exact_perspective(xy, w, f, cols, rows) -> np.ndarray:
    """Exact perspective-correct f at pixel centres of the *snapped* triangle (Fractions)."""
    (ax, ay), (bx, by), (cx, cy) = ((Fraction(x), Fraction(y)) for x, y in snap(xy))
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    wf = [Fraction(float(v)) for v in w]
    ff = [Fraction(float(v)) for v in f]
    out = []
    for r, c in zip(rows, cols):
        px, py = Fraction(int(c)) + Fraction(1, 2), Fraction(int(r)) + Fraction(1, 2)
        lam = (
            ((cx - bx) * (py - by) - (cy - by) * (px - bx)) / area,
            ((ax - cx) * (py - cy) - (ay - cy) * (px - cx)) / area,
            ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / area,
        )
        q = [lam[i] / wf[i] for i in range(3)]
        out.append(float(sum(q[i] * ff[i] for i in range(3)) / sum(q)))
    return np.array(out)


def _persp_run(inputs, method) -> Fills:
    xy, f, size = inputs["xy"], inputs["f"], inputs["size"]
    tris = np.array([xy] * len(inputs["ws"]))
    return _fill_all(
        {"triangles": tris, "size": size, "w": inputs["ws"], "attrs": [f] * len(tris)}, method
    )


def _persp_check(inputs, result: Fills) -> None:
    _check_finite(result)
    xy, f = inputs["xy"], inputs["f"]
    span = float(np.ptp(f))
    for w, fill in zip(inputs["ws"], result.fills):
        rows, cols = np.nonzero(fill.coverage)
        assert len(rows), "covers nothing"
        exact = _exact_perspective(xy, w, f, cols, rows)
        err = np.max(np.abs(fill.attrs["f"][rows, cols] - exact)) / span
        assert err <= 1e-9, f"w = {w.tolist()}: perspective-correct value off by {err:.3g}"


def _persp_cases():
    xy = np.array([[1.25, 1.5], [30.5, 6.75], [7.5, 29.25]])
    f = np.array([0.0, 1.0, 0.25])
    ratio = np.array([[1e-3, 1e3, 1e3], [1e3, 1e-3, 1.0], [1.0, 1e3, 1e-3]])

    def naive_ratio(inputs) -> Naive:
        # affine ignores w, so one image serves every w of the case
        return Naive(values={k: naive_affine(xy, f, 32, 32) for k in range(len(ratio))})

    def shows_ratio(inputs, ours: Fills, naive: Naive) -> str | None:
        worst = 0.0
        for k, fill in enumerate(ours.fills):
            cov = fill.coverage
            worst = max(worst, float(np.max(np.abs(naive.values[k][cov] - fill.attrs["f"][cov]))))
        return f"affine interpolation is off by up to {worst:.2f}" if worst > 0.1 else None

    _add(
        HardCase(
            "perspective_w_ratio_1e6",
            "vertex w differing by a factor 1e6 (a vertex at the near plane, two at the far "
            "one): one λ/w term dominates the sum",
            "triangles",
            "perspective-correct values within 1e-9 (of the attribute's range) of the exact "
            "rational value at every covered pixel, finite, barycentrics in [0, 1]",
            _frozen(xy=xy, f=f, size=(32, 32), ws=ratio),
            _persp_run,
            _persp_check,
            "affine (screen-space) interpolation ignores w: off by most of the range",
            naive_ratio,
            shows_ratio,
        )
    )

    base = np.array([1.0, 2.0, 4.0])
    scales = (1.0, 1e300, 1e-300, 1e-310)
    ws = np.array([base * s for s in scales])

    def check_scale(inputs, result: Fills) -> None:
        ref = result.fills[0].attrs["f"]
        for s, fill in zip(scales[1:], result.fills[1:]):
            cov = fill.coverage
            got = fill.attrs["f"][cov]
            assert np.isfinite(got).all(), (
                f"w scaled by {s:g} (w = {(base * s).tolist()}): {int((~np.isfinite(got)).sum())}"
                " non-finite values; perspective weights depend only on ratios of w"
            )
            err = np.max(np.abs(got - ref[cov]))
            assert err <= 1e-12, f"w scaled by {s:g}: values change by {err:.3g}"
        _persp_check(inputs, Fills(result.fills[:1], result.counts))
        _check_finite(result)

    def naive_scale(inputs) -> Naive:
        out = {}
        for s, fill in zip(scales, _persp_run(inputs, "halfplane").fills):
            lam = fill.trace.pixel_barycentric
            out[s] = naive_perspective32(lam, base * s, f)
        return Naive(values=out)

    def shows_scale(inputs, ours: Fills, naive: Naive) -> str | None:
        bad = [s for s in scales if not np.isfinite(naive.values[s]).all()]
        return f"float32 λ/w gives NaN or inf for w scaled by {bad}" if bad else None

    _add(
        HardCase(
            "perspective_w_scale",
            "the same w ratios at w ~ 1e300 and w ~ 1e-300 or 1e-310 (subnormal): 1/w and "
            "Σ λ/w near overflow and underflow",
            "triangles",
            "identical values (within 1e-12) to w = (1, 2, 4): perspective weights depend only "
            "on the ratios of w, so scaling all three must change nothing; never NaN or inf",
            _frozen(xy=xy, f=f, size=(32, 32), ws=ws),
            _persp_run,
            check_scale,
            "float32 λ/w: 1/w overflows or underflows, giving inf/inf or 0/0 = NaN",
            naive_scale,
            shows_scale,
        )
    )


_persp_cases()


# -- depth precision -------------------------------------------------------------------------
@dataclass(frozen=True)
class DepthResult:
    """Per depth format (and per tilt), pixels of the overlap won by the wrong triangle.

    ``wrong[(fmt, tilt)]`` counts pixels where the triangle that is *not* truly nearer
    (or, for exact ties, not the earlier one) wrote the pixel; ``overlap`` is the number of
    pixels both triangles cover; ``max_gap[tilt]`` the largest |depth B - depth A| over the
    overlap in float64.
    """

    wrong: Mapping[tuple[str, float], int]
    overlap: int
    max_gap: Mapping[float, float]


def _depth_run_factory(make_clip, truth):
    """``truth(tilt, x_ndc)`` -> True where triangle B (drawn second) is truly nearer."""

    def run(inputs, method) -> DepthResult:
        size = inputs["size"]
        wrong, max_gap, overlap = {}, {}, 0
        xs = (np.arange(size) + 0.5) / size * 2 - 1
        x_ndc = np.broadcast_to(xs, (size, size))
        for tilt in inputs["tilts"]:
            clip = make_clip(tilt)
            a = render_clip(clip[:1], size, size)
            b = render_clip(clip[1:], size, size)
            both = a.coverage & b.coverage
            overlap = int(both.sum())
            max_gap[tilt] = float(np.max(np.abs(b.depth[both] - a.depth[both])))
            b_nearer = truth(tilt, x_ndc)
            for fmt in DEPTH_ORDER:
                frame = render_clip(clip, size, size, depth_format=fmt)
                won_b = frame.triangle_id == 1
                wrong[(fmt, tilt)] = int((both & (won_b != b_nearer)).sum())
        return DepthResult(MappingProxyType(wrong), overlap, MappingProxyType(max_gap))

    return run


def _depth_cases():
    size = 32

    def ortho_clip(tilt):
        # w = 1 and dyadic positions: window positions are on the snapping grid and the
        # window depth of a point is exactly (z + 1) / 2, so both triangles share one plane.
        def z(x, y):
            return 0.25 + tilt * (0.5 * x + 0.25 * y)

        a = [(-3.0, -3.0), (3.0, -3.0), (0.0, 3.0)]
        b = [(-2.5, 2.5), (2.5, 2.0), (0.5, -3.0)]
        return np.array([[[x, y, z(x, y), 1.0] for x, y in t] for t in (a, b)])

    def check_coplanar(inputs, result: DepthResult) -> None:
        assert result.overlap > 500, "the triangles barely overlap"
        for fmt in DEPTH_ORDER:
            n = result.wrong[(fmt, 0.0)]
            assert n == 0, f"{fmt}: camera-facing coplanar: the later triangle won {n} ties"
        for tilt, gap in result.max_gap.items():
            assert gap <= 4e-16, f"tilt {tilt}: coplanar depths differ by up to {gap:.3g}"
            for fmt in DEPTH_ORDER[1:]:
                n = result.wrong[(fmt, tilt)]
                assert n == 0, f"{fmt}, tilt {tilt}: rounding noise not collapsed to ties ({n})"

    _add(
        HardCase(
            "coplanar_overlap",
            "two overlapping triangles in exactly the same plane (a decal): every depth "
            "comparison is a tie",
            "depth",
            "camera-facing: the first triangle keeps every overlap pixel in every format (ties "
            "keep the earlier); tilted: the two interpolated depths agree within 4e-16, so "
            "float64 may fight by rounding alone (the later triangle wins where its value is "
            "an ulp smaller) while float32, unorm24 and unorm16 round both to the same value: "
            "exact ties, the earlier triangle everywhere",
            _frozen(size=size, tilts=(0.0, 0.25, 0.01)),
            _depth_run_factory(ortho_clip, lambda tilt, x: np.zeros_like(x, dtype=bool)),
            check_coplanar,
            methods=("batch",),
        )
    )

    def near_clip(tilt):
        # w = 1 (orthographic), dyadic positions on the snapping grid: window depth is exactly
        # affine, so only the buffer's format decides. Both triangles rise gently with y
        # (0.6 +- 0.01), so each row samples a different position within a depth step; B
        # adds ``tilt * x``: it crosses A along x = 0 and is truly nearer (smaller depth)
        # left of it.
        def depth(x, y, t):
            return 0.6 + 0.01 * y + t * x

        xy = [(-3.0, -3.0), (3.0, -3.0), (0.0, 3.0)]
        return np.array([[[x, y, 2 * depth(x, y, t) - 1, 1.0] for x, y in xy] for t in (0.0, tilt)])

    def check_near(inputs, result: DepthResult) -> None:
        w = result.wrong
        for tilt in inputs["tilts"]:
            row = {fmt: w[(fmt, tilt)] for fmt in DEPTH_ORDER}
            assert row["float64"] == 0, f"tilt {tilt}: float64 fights: {row}"
            assert row["unorm16"] > 0, f"tilt {tilt}: 16-bit depth should fight: {row}"
            assert max(row["float32"], row["unorm24"]) <= row["unorm16"], (
                f"tilt {tilt}: fewer bits gave fewer wrong pixels: {row}"
            )
        steep, shallow = inputs["tilts"]
        assert w[("unorm24", steep)] == 0 and w[("float32", steep)] == 0, (
            f"tilt {steep}: 24 bits should resolve it: {dict(w)}"
        )
        assert w[("unorm24", shallow)] > 0 and w[("float32", shallow)] > 0, (
            f"tilt {shallow}: 24 bits should fight too: {dict(w)}"
        )

    _add(
        HardCase(
            "nearly_coplanar_overlap",
            "two triangles crossing at a shallow angle: near the crossing their depths "
            "differ by less than one buffer step",
            "depth",
            "float64: no wrong pixel; unorm16: a band of wrong pixels beside the crossing "
            "for both slopes; float32 and unorm24: none at slope 1e-4, a band at 1e-6; never "
            "fewer wrong pixels with fewer bits (the first-drawn triangle keeps the ties). "
            "Depth is linear here (w = 1); a perspective camera makes the step grow like z²",
            _frozen(size=size, tilts=(1e-4, 1e-6)),
            _depth_run_factory(near_clip, lambda tilt, x: x < 0),
            check_near,
            methods=("batch",),
        )
    )


_depth_cases()


# -- registry --------------------------------------------------------------------------------
def get_case(name: str) -> HardCase:
    """The case called ``name``; ``ValueError`` lists the names when there is none."""
    if name not in CASES:
        raise ValueError(f"unknown hard case {name!r}; choose from {', '.join(CASES)}")
    return CASES[name]


def list_cases(kind: str | None = None) -> list[str]:
    """Names of all cases (of one ``kind`` if given), in catalogue order."""
    return [name for name, case in CASES.items() if kind is None or case.kind == kind]
