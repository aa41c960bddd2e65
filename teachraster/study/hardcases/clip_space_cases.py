"""Clip-space cases: vertices behind the eye, perspective denominators, depth precision."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction
from types import MappingProxyType

import numpy as np

from ...core.fill import rasterize
from ...core.snapping import snap
from ...core.triangle import Triangle
from ...pipeline.geometry.camera import perspective
from ...pipeline.rendering.render_triangles import render as render_clip
from .case import DEPTH_ORDER, Fills, HardCase, Naive, Rendered, add_case, frozen_inputs
from .checks import check_finite, fill_all, first_pixels
from .naive import naive_affine, naive_counts, naive_perspective32, naive_window

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
    assert not bad.any(), (
        f"refilling the clipped triangles covers other pixels: {first_pixels(bad)}"
    )
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
    assert not mirrored.any(), f"pixels above the horizon (mirrored): {first_pixels(mirrored)}"
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
    add_case(
        HardCase(
            "behind_camera",
            "a floor triangle with one vertex behind the eye (w = -2)",
            *common,
            frozen_inputs(clip=behind, attrs=uv),
            _render_run,
            _render_check,
            "dividing by w before clipping mirrors the vertex through the eye, into the sky",
            naive,
            shows_mirror,
        )
    )
    add_case(
        HardCase(
            "eye_plane_vertex",
            "a floor triangle with one vertex exactly on the eye plane (w = 0)",
            *common,
            frozen_inputs(clip=on_eye, attrs=uv),
            _render_run,
            _render_check,
            "dividing by w = 0 gives inf and NaN window coordinates",
            naive,
            shows_nonfinite,
        )
    )
    add_case(
        HardCase(
            "hair_in_front_of_eye",
            "a floor triangle with one vertex a hair in front of the eye (w = 1e-9)",
            *common,
            frozen_inputs(clip=hair, attrs=uv),
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
    return fill_all(
        {"triangles": tris, "size": size, "w": inputs["ws"], "attrs": [f] * len(tris)}, method
    )


def _float32_perspective(xy, w, f, cols, rows) -> np.ndarray:
    """Perspective-correct f at pixel centres computed as a GPU's interpolator does, in
    float32 throughout: λ from the snapped edge functions, then Σ λ_i (f_i / w_i) over
    Σ λ_i / w_i."""
    v = snap(xy).astype(np.float32)
    px = cols.astype(np.float32) + np.float32(0.5)
    py = rows.astype(np.float32) + np.float32(0.5)
    (ax, ay), (bx, by), (cx, cy) = v
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    lam = [((cx - bx) * (py - by) - (cy - by) * (px - bx)) / area,
           ((ax - cx) * (py - cy) - (ay - cy) * (px - cx)) / area,
           ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / area]  # fmt: skip
    inv_w = (np.float32(1) / np.asarray(w, dtype=np.float32)).astype(np.float32)
    f_w = (np.asarray(f, dtype=np.float32) * inv_w).astype(np.float32)
    num = sum(lam[i] * f_w[i] for i in range(3))
    den = sum(lam[i] * inv_w[i] for i in range(3))
    return (num / den).astype(np.float64)


def perspective_errors(inputs, result: Fills, *, float32: bool = False) -> list[float]:
    """The largest error of each fill's attribute against the exact rational
    perspective-correct value (Fractions), over its covered pixels, as a fraction of the
    attribute's range: one number per row of ``inputs["ws"]``.

    Parameters
    ----------
    inputs : mapping
        A perspective case's inputs (``xy``, ``f``, ``ws``).
    result : Fills
        Its :meth:`HardCase.run` (its coverage; with ``float32`` its values are not used).
    float32 : bool
        Measure a GPU's arithmetic instead of the simulator's float64: λ, 1/w and the two
        sums in float32 (lesson 07 §4 prints both).

    Returns
    -------
    list of float
    """
    xy, f = inputs["xy"], inputs["f"]
    span = float(np.ptp(f))
    errors = []
    for w, fill in zip(inputs["ws"], result.fills):
        rows, cols = np.nonzero(fill.coverage)
        assert len(rows), "covers nothing"
        exact = _exact_perspective(xy, w, f, cols, rows)
        got = (_float32_perspective(xy, w, f, cols, rows) if float32
               else fill.attrs["f"][rows, cols])  # fmt: skip
        errors.append(float(np.max(np.abs(got - exact)) / span))
    return errors


def _persp_check(inputs, result: Fills) -> None:
    check_finite(result)
    for w, err in zip(inputs["ws"], perspective_errors(inputs, result)):
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

    add_case(
        HardCase(
            "perspective_w_ratio_1e6",
            "vertex w differing by a factor 1e6 (a vertex at the near plane, two at the far "
            "one): one λ/w term dominates the sum",
            "triangles",
            "perspective-correct values within 1e-9 (of the attribute's range) of the exact "
            "rational value at every covered pixel, finite, barycentrics in [0, 1]",
            frozen_inputs(xy=xy, f=f, size=(32, 32), ws=ratio),
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
        check_finite(result)

    def naive_scale(inputs) -> Naive:
        out = {}
        for s, fill in zip(scales, _persp_run(inputs, "halfplane").fills):
            lam = fill.trace.pixel_barycentric
            out[s] = naive_perspective32(lam, base * s, f)
        return Naive(values=out)

    def shows_scale(inputs, ours: Fills, naive: Naive) -> str | None:
        bad = [s for s in scales if not np.isfinite(naive.values[s]).all()]
        return f"float32 λ/w gives NaN or inf for w scaled by {bad}" if bad else None

    add_case(
        HardCase(
            "perspective_w_scale",
            "the same w ratios at w ~ 1e300 and w ~ 1e-300 or 1e-310 (subnormal): 1/w and "
            "Σ λ/w near overflow and underflow",
            "triangles",
            "identical values (within 1e-12) to w = (1, 2, 4): perspective weights depend only "
            "on the ratios of w, so scaling all three must change nothing; never NaN or inf",
            frozen_inputs(xy=xy, f=f, size=(32, 32), ws=ws),
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
    overlap in float64; ``wrong_pixels[(fmt, tilt)]`` the (size, size) bool image of the
    pixels counted in ``wrong``, and ``both`` that of the overlap (lesson 07 draws them).
    """

    wrong: Mapping[tuple[str, float], int]
    overlap: int
    max_gap: Mapping[float, float]
    wrong_pixels: Mapping[tuple[str, float], np.ndarray] | None = None
    both: np.ndarray | None = None


def _depth_run_factory(make_clip, truth):
    """``truth(tilt, x_ndc)`` -> True where triangle B (drawn second) is truly nearer."""

    def run(inputs, method) -> DepthResult:
        size = inputs["size"]
        wrong, max_gap, overlap, pixels = {}, {}, 0, {}
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
                pixels[(fmt, tilt)] = both & (won_b != b_nearer)
                wrong[(fmt, tilt)] = int(pixels[(fmt, tilt)].sum())
        return DepthResult(MappingProxyType(wrong), overlap, MappingProxyType(max_gap),
                           MappingProxyType(pixels), both)  # fmt: skip

    return run


def coplanar_clip(tilt: float) -> np.ndarray:
    """``coplanar_overlap``'s two clip-space triangles, (2, 3, 4): A (the wall, drawn first)
    and B (the decal) in one plane, tilted by ``tilt`` (0: facing the camera). Lesson 07
    renders them with a depth bias on B.

    w = 1 and dyadic positions: window positions are on the snapping grid and the window
    depth of a point is exactly (z + 1) / 2, so both triangles share one plane.
    """

    def z(x, y):
        return 0.25 + tilt * (0.5 * x + 0.25 * y)

    # a wall inside the image, its outline visible, and a small decal well inside it (a
    # poster on a wall: a decal covering the screen read as the screen changing colour)
    a = [(-0.9375, -0.875), (0.9375, -0.75), (0.0, 0.9375)]
    b = [(-0.5, -0.5625), (0.5, -0.4375), (-0.0625, 0.4375)]
    return np.array([[[x, y, z(x, y), 1.0] for x, y in t] for t in (a, b)])


def _depth_cases():
    size = 32

    def check_coplanar(inputs, result: DepthResult) -> None:
        assert result.overlap > 100, "the triangles barely overlap"
        for fmt in DEPTH_ORDER:
            n = result.wrong[(fmt, 0.0)]
            assert n == 0, f"{fmt}: camera-facing coplanar: the later triangle won {n} ties"
        for tilt, gap in result.max_gap.items():
            assert gap <= 4e-16, f"tilt {tilt}: coplanar depths differ by up to {gap:.3g}"
            for fmt in DEPTH_ORDER[1:]:
                n = result.wrong[(fmt, tilt)]
                assert n == 0, f"{fmt}, tilt {tilt}: rounding noise not collapsed to ties ({n})"

    add_case(
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
            frozen_inputs(size=size, tilts=(0.0, 0.25, 0.01)),
            _depth_run_factory(coplanar_clip, lambda tilt, x: np.zeros_like(x, dtype=bool)),
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
                f"tilt {tilt}: unorm16 gave fewer wrong pixels than 24 bits: {row}"
            )
        steep, shallow = inputs["tilts"]
        assert w[("unorm24", steep)] == 0 and w[("float32", steep)] == 0, (
            f"tilt {steep}: 24 bits should resolve it: {dict(w)}"
        )
        assert w[("unorm24", shallow)] > 0 and w[("float32", shallow)] > 0, (
            f"tilt {shallow}: 24 bits should fight too: {dict(w)}"
        )

    add_case(
        HardCase(
            "nearly_coplanar_overlap",
            "two triangles crossing at a shallow angle: near the crossing their depths "
            "differ by less than one buffer step",
            "depth",
            "float64: no wrong pixel; unorm16: a band of wrong pixels beside the crossing "
            "for both slopes, never narrower than float32's or unorm24's; float32 and unorm24: "
            "none at slope 1e-4, a band at 1e-6, about equally wide (at these depths, in "
            "[0.5, 1), both step by 2^-24; the first-drawn triangle keeps the ties). "
            "Depth is linear here (w = 1); a perspective camera makes the step grow like z²",
            frozen_inputs(size=size, tilts=(1e-4, 1e-6)),
            _depth_run_factory(near_clip, lambda tilt, x: x < 0),
            check_near,
            methods=("batch",),
        )
    )


_depth_cases()
