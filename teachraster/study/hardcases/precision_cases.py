"""Precision cases: far from the origin, snapping that changes a triangle, stepping drift."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction
from types import MappingProxyType

import numpy as np

from ...core import half_planes, span_tables
from ...core.barycentrics import barycentric_pixels
from ...core.bbox import pixel_bbox
from ...core.edges import setup_edges
from ...core.fill import rasterize
from ...core.interpolation import blend
from ...core.plane_equations import attribute_plane, plane_equation
from ...core.snapping import SUBPIXEL_BITS, snap
from ...core.triangle import Triangle
from ...core.validate import as_int, as_size
from .case import Fills, HardCase, Naive, add_case, frozen_inputs, get_case
from .checks import (
    check_finite,
    check_nothing,
    fill_all,
    first_pixels,
    naive_differs,
    naive_mesh,
    triangles_array,
)
from .naive import naive_coverage, naive_stepped32


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


def _offset_words(o: int) -> str:
    """An offset of the far case as the lessons write it: "the origin", "1e5 px" (not 100000
    beside 1e+06).

    >>> _offset_words(0), _offset_words(10_000), _offset_words(1_000_000)
    ('the origin', '1e4 px', '1e6 px')
    """
    return "the origin" if o == 0 else f"{o:.0e} px".replace("e+0", "e")


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
            assert not bad.any(), f"offset {o:g}: coverage differs at (local) {first_pixels(bad)}"
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
            "naive float32 absolute edge functions get pixels wrong: "
            + ", ".join(f"{n} at {_offset_words(o)}" for o, n in diffs.items())
            + f"; the float64 absolute plane equation is off by {plane_err:.2g} at "
            + _offset_words(far)
        )

    add_case(
        HardCase(
            "far_from_origin",
            "the same small triangle at 1e4, 1e5 and 1e6 px from the origin, edges through centres",
            "precision",
            "coverage identical to the triangle at the origin and attributes within 1e-12 "
            "at every offset (the snapped int64 edge functions are exact up to ±2**21 px)",
            frozen_inputs(local=local, f=f, offsets=offsets),
            run,
            check,
            "float32 edge functions in absolute form (A x + B y + C, C = x_a y_b - y_a x_b: two "
            "products of size x·y, ~1e12 at 1e6 px, cancelling to ~1e7) lose the "
            "bits that decide coverage (every pixel wrong at 1e5 and 1e6 px; nearer in, how many "
            "depends on how the products round); *Triangle Rasterisation II - Interpolation*'s absolute plane "
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
    sx = shifts[3][0]
    moved_x = float(base[0, 0]) + sx  # v1's x moved: 0.3 and 10.3 round differently

    def run(inputs, method) -> Fills:
        tris = np.array([base + s for s in shifts])
        return fill_all({"triangles": tris, "size": size, "attrs": [f] * len(shifts)}, method)

    def check(inputs, result: Fills) -> None:
        check_finite(result)
        ref = result.fills[0]
        for (dx, dy), fill in zip(shifts[1:], result.fills[1:]):
            moved = np.roll(np.roll(ref.coverage, dy, axis=0), dx, axis=1)
            bad = fill.coverage != moved
            assert not bad.any(), (
                f"shift {(dx, dy)}: coverage is not the shifted one: {first_pixels(bad)}"
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
        if not moved:
            return None
        # the shifts as the lessons write pairs, (1, 0) and (0, 3), not a Python list (r304 S-2)
        named = [f"({dx:g}, {dy:g})" for dx, dy in moved]
        shown = ", ".join(named[:-1]) + f" and {named[-1]}" if len(named) > 1 else named[0]
        return f"naive coverage changes under the shifts {shown} px (x, y)"

    add_case(
        HardCase(
            "translation_invariance",
            "a triangle with an edge through centres, shifted by whole pixels: "
            f"{moved_x!r} - {sx} gives {moved_x - sx!r}, not {float(base[0, 0])!r}",
            "triangles",
            "coverage moves with the triangle, pixel for pixel, and attributes are equal "
            "within 1e-12 (snapping to 1/256 px commutes with whole-pixel shifts)",
            frozen_inputs(triangles=np.array([base + s for s in shifts]), size=size),
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
    flip = triangles_array((c, c + (10 * g, 0.6 * g), c + (5 * g, 0.4 * g)))

    def run_flip(inputs, method) -> Fills:
        base = fill_all(inputs, method)
        culled = {
            cull: rasterize(Triangle(flip[0]), 6, 6, method=method, cull=cull).coverage
            for cull in ("back", "front")
        }
        return Fills(base.fills, base.counts, MappingProxyType(culled))

    def check_flip(inputs, fills: Fills) -> None:
        culled = fills.extra
        check_finite(fills)
        fill = fills.fills[0]
        assert Triangle(flip[0]).signed_area > 0, (
            "case set-up: unsnapped should be clockwise on screen"
        )
        assert fill.trace.signed_area < 0, (
            "the snapped triangle should be counter-clockwise on screen"
        )
        want = np.zeros((6, 6), dtype=bool)
        want[2, 2] = True
        bad = fill.coverage != want
        assert not bad.any(), f"snapped triangle coverage wrong at {first_pixels(bad)}"
        assert culled["back"].any(), "culled as back-facing by the unsnapped winding"
        assert not culled["front"].any(), "not culled as front-facing, though it is once snapped"

    def naive_flip(inputs) -> Naive:
        # Winding decided on the unsnapped floats, edges tested on the snapped vertices.
        snapped = snap(flip[0])
        v = snapped if Triangle(flip[0]).signed_area > 0 else snapped[[0, 2, 1]]
        cov = naive_coverage(v, 6, 6, rule="top_left", orient="none")
        return Naive(counts=cov.astype(np.int64))

    add_case(
        HardCase(
            "snap_flips_winding",
            # on screen, as CONVENTIONS names facing (the y-down numbers run the other way)
            "a tiny triangle, clockwise on screen (back-facing), its snapped vertices "
            "counter-clockwise on screen (front-facing)",
            "triangle",
            "everything follows the snapped triangle: it is front-facing (cull='front' "
            "removes it, cull='back' keeps it) and covers exactly pixel (2, 2), where its "
            "snapped vertex sits with a top and a left edge; both methods agree",
            frozen_inputs(triangles=flip, size=(6, 6)),
            run_flip,
            check_flip,
            "orienting by the unsnapped area but testing the snapped edges puts the inside "
            "on the negative side: pixel (2, 2) is lost",
            naive_flip,
            naive_differs,
        )
    )

    d = 0.001  # < 1/512 px: every vertex snaps onto the centre (2.5, 2.5)
    collapse = triangles_array((c + (-d, -d), c + (1.5 * d, -d), c + (0, 1.5 * d)))
    add_case(
        HardCase(
            "snap_degenerate",
            "a triangle 0.0025 px wide around a pixel centre: all three vertices snap to it",
            "triangle",
            "zero area after snapping: covers nothing (though the unsnapped triangle "
            "contains the centre), attributes NaN, no division by zero",
            frozen_inputs(triangles=collapse, size=(6, 6), attrs=np.array([[0.0, 1.0, 2.0]])),
            fill_all,
            check_nothing,
            "raw floats see the centre strictly inside and fill pixel (2, 2)",
            naive_mesh("strict"),
            naive_differs,
        )
    )


_snap_cases()


# -- incremental stepping ----------------------------------------------------------------------
@dataclass(frozen=True)
class DriftResult:
    """Largest error against the exact value.

    ``ours`` and ``recentred`` over the pixels the triangle covers; ``stepped64`` over the
    4096 centres of row 0 that the stepper walks (the bounding box's row). ``ours`` is the core's fill (exact barycentrics then a blend); ``recentred`` Fatahalian's (CMU 15-462, *Texture*)
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

    def row_end(values: np.ndarray) -> float:
        # The note's loop steps every pixel of the bounding box's row, written or not: row 0's
        # 4096 centres, the triangle covering the first 3840. Its largest error, exactly.
        exact = _exact_affine(xy, f)
        return max(abs(float(Fraction(v) - exact(c + 0.5, 0.5)))
                   for c, v in enumerate(values[0].tolist()))  # fmt: skip

    def run(inputs, method) -> DriftResult:
        fill = rasterize(Triangle(xy, attrs={"f": f}), width, height, method=method)
        cov = fill.coverage
        ys, xs = np.mgrid[0:height, 0:width] + 0.5
        recentred = attribute_plane(xy, f)(xs, ys)
        stepped = plane_equation(xy, f).stepped(0.5, 0.5, width, height)
        return DriftResult(
            ours=errors(fill.attrs["f"], cov),
            recentred=errors(recentred, cov),
            stepped64=row_end(stepped),
            pixels=int(cov.sum()),
        )

    def check(inputs, result: DriftResult) -> None:
        assert result.pixels > 10_000, f"only {result.pixels} pixels: not a long run"
        assert result.ours <= 1e-9, f"the core's attributes are off by {result.ours:.3g}"
        assert result.recentred <= 1e-9, f"direct recentred plane off by {result.recentred:.3g}"

    def naive(inputs) -> Naive:
        return Naive(values={"stepped32": row_end(naive_stepped32(xy, f, 0.5, 0.5, width, 1))})

    def shows(inputs, ours: DriftResult, naive: Naive) -> str | None:
        e32 = naive.values["stepped32"]
        if e32 <= 1e-3 or e32 <= 1e3 * max(ours.ours, 1e-300):
            return None
        return (
            f"float32 stepping drifts by {e32:.3g} over the {width} pixels of row 0 (float64 "
            f"stepping {ours.stepped64:.2g}, ours {ours.ours:.2g})"
        )

    add_case(
        HardCase(
            "stepping_drift",
            f"f += dx per pixel along all {width} centres of a bounding-box row (covered or "
            "not) accumulates rounding: lesson 03's row",
            "precision",
            "the core evaluates every pixel directly from exact edge functions: error <= 1e-9 "
            "everywhere, as does the recentred plane of Fatahalian (CMU 15-462, *Texture*); "
            "*Triangle Rasterisation II - Interpolation*'s stepping in float64 "
            "drifts measurably (reported), in float32 by hundreds of float32's own steps (yet "
            "below one 8-bit colour step of this row's range)",
            frozen_inputs(xy=xy, f=f, size=(width, height)),
            run,
            check,
            "float32 stepping (as in a fixed-function inner loop) drifts by a few hundredths "
            "of the attribute by the end of a row",
            naive,
            shows,
        )
    )


_drift_case()


def drift_along_row(row: int = 0) -> dict:
    """The signed error of ``stepping_drift``'s attribute along one row of its bounding box,
    against the exact value: *Triangle Rasterisation II - Interpolation*'s stepping (start,
    then ``+= dx``) in float32 and in float64 at every centre of the row (the note's loop
    steps them all, covered or not), and the core's direct evaluation where it covers.

    Parameters
    ----------
    row : int
        The pixel row (row 0: 4096 centres, of which the triangle covers 3840).

    Returns
    -------
    dict
        ``"columns"`` (n,) int, every column of the row; ``"covered"`` (n,) bool, the
        triangle's pixels; ``"float32 stepping"``, ``"float64 stepping"`` and
        ``"ours (direct)"``, (n,) float, value - exact (``nan`` where ours draws nothing).
    """
    case = get_case("stepping_drift")
    xy, f = np.asarray(case.inputs["xy"]), np.asarray(case.inputs["f"])
    width, height = case.inputs["size"]
    row = as_int("row", row)
    fill = rasterize(Triangle(xy, attrs={"f": f}), width, height)
    cols = np.arange(width)
    covered = fill.coverage[row].copy()
    exact = _exact_affine(xy, f)
    truth = [exact(c + 0.5, row + 0.5) for c in cols.tolist()]
    ways = {
        "float32 stepping": naive_stepped32(xy, f, 0.5, 0.5, width, height)[row],
        "float64 stepping": plane_equation(xy, f).stepped(0.5, 0.5, width, height)[row],
        "ours (direct)": np.where(covered, fill.attrs["f"][row], np.nan),
    }
    out = {"columns": cols, "covered": covered}
    for name, values in ways.items():  # exact differences: Fractions, then one rounding
        out[name] = np.array(
            [float(Fraction(v) - t) if np.isfinite(v) else np.nan
             for v, t in zip(values.tolist(), truth)]
        )  # fmt: skip
    return out
