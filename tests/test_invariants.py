"""Invariants over random inputs (hypothesis), the property-based half of issue 5's suite.

- no NaN or inf in any output inside coverage (``rasterize`` and ``render``, w of any sign);
- every pixel of a watertight mesh (a jittered grid, a random fan) covered exactly once;
- barycentrics in [0, 1] summing to 1 within 1e-12 inside coverage;
- constant attributes exactly constant;
- results unchanged by vertex order and by translating a triangle by whole pixels;
- perspective equals affine, exactly, when w is constant.

Example counts are kept small enough for the whole module to run in well under 30 s.
"""

import itertools

import numpy as np
from conftest import METHODS, MODES, any_triangle, edge_exact, examples, snapped_vertices
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import teachraster as tr

FAST = settings(
    max_examples=examples(300), deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
PERMUTATIONS = list(itertools.permutations(range(3)))
SIZE = 16

methods = st.sampled_from(METHODS)
modes = st.sampled_from(MODES)
w_values = st.lists(st.floats(0.05, 20.0), min_size=3, max_size=3).map(np.array)
attr_values = st.lists(
    st.tuples(st.floats(-1e3, 1e3), st.floats(-1.0, 1.0)), min_size=3, max_size=3
).map(np.array)


def fill(xy, method, mode="perspective", w=None, attrs=None, size=(SIZE, SIZE), z=None):
    tri = tr.Triangle(xy, w=w, z=z, attrs={} if attrs is None else {"f": attrs})
    return tr.rasterize(tri, *size, method=method, interpolation=mode, trace=True)


# -- no NaN or inf -----------------------------------------------------------------------------
@FAST
@given(
    any_triangle,
    methods,
    modes,
    w_values,
    attr_values,
    st.lists(st.floats(0, 1), min_size=3, max_size=3),
)
def test_outputs_finite_inside_coverage(xy, method, mode, w, attrs, z):
    out = fill(xy, method, mode, w, attrs, z=z)
    cov = out.coverage
    for name, arr in (("f", out.attrs["f"]), ("depth", out.depth)):
        assert np.isfinite(arr[cov]).all(), f"{name} not finite inside coverage: xy={xy.tolist()}"
        assert np.isnan(arr[~cov]).all(), f"{name} set outside coverage"
    d = out.depth[cov]
    assert ((d >= 0) & (d <= 1)).all()


clip_coord = st.floats(-3.0, 3.0)
clip_w = st.one_of(st.floats(-2.0, 3.0), st.sampled_from([0.0, 1e-9, -1e-9, 1e-300]))
clip_vertex = st.tuples(clip_coord, clip_coord, clip_coord, clip_w)


@FAST
@given(st.lists(st.lists(clip_vertex, min_size=3, max_size=3), min_size=1, max_size=3))
def test_render_finite_inside_coverage(tris):
    clip = np.array(tris, dtype=np.float64)
    attrs = np.arange(clip.shape[0] * 3 * 2, dtype=np.float64).reshape(-1, 3, 2)
    frame = tr.render(clip, SIZE, SIZE, attrs=attrs)
    cov = frame.coverage
    assert np.isfinite(frame.attrs[cov]).all(), f"attrs not finite: clip={clip.tolist()}"
    assert np.isfinite(frame.depth[cov]).all(), f"depth not finite: clip={clip.tolist()}"
    d = frame.depth[cov]
    assert ((d >= 0) & (d <= 1)).all(), f"depth outside [0, 1]: clip={clip.tolist()}"
    assert np.isnan(frame.depth[~cov]).all()
    for k in range(len(clip)):  # attributes stay within the (clipped) triangle's range
        vals = frame.attrs[frame.triangle_id == k]
        lo, hi = attrs[k].min(axis=0) - 1e-9, attrs[k].max(axis=0) + 1e-9
        assert ((vals >= lo) & (vals <= hi)).all()


# -- watertight meshes -------------------------------------------------------------------------
def counts_of(tris, method, size):
    counts = np.zeros(size[::-1], dtype=np.int64)
    for xy in tris:
        counts += tr.rasterize(tr.Triangle(xy), *size, method=method).coverage
    return counts


@settings(max_examples=examples(100), deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(2, 5), methods)
def test_jittered_grid_covered_exactly_once(seed, n, method):
    """An n x n grid of quads, interior vertices jittered, each quad split on a random diagonal.

    The outline stays the rectangle [2, 2 + n*4]² (its vertices move only along it, on the
    1/256 grid), so every centre strictly inside the rectangle must be covered exactly once.
    """
    rng = np.random.default_rng(seed)
    step, lo = 4.0, 2.0
    g = lo + step * np.stack(np.meshgrid(np.arange(n + 1), np.arange(n + 1), indexing="xy"), -1)
    g = g.astype(np.float64)
    jitter = rng.uniform(-0.3, 0.3, size=g.shape) * step
    inner = np.zeros(g.shape[:2] + (2,), dtype=bool)
    inner[:, 1:-1, 0] = True  # interior columns move in x
    inner[1:-1, :, 1] = True  # interior rows move in y
    g = np.where(inner, g + jitter, g)
    g = np.where(inner, g, np.round(g * 256) / 256)  # the outline on the snapping grid
    tris = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = g[i, j], g[i, j + 1], g[i + 1, j + 1], g[i + 1, j]
            pair = [(a, b, c), (a, c, d)] if rng.random() < 0.5 else [(a, b, d), (b, c, d)]
            for t in pair:
                t = np.array(t)
                # a valid mesh: no triangle folded over (same winding as the grid's)
                assume(edge_exact(*t) > 0)
                tris.append(t[rng.permutation(3)])
    size = int(lo + step * n + 3)
    counts = counts_of(tris, method, (size, size))
    assert counts.max() <= 1, f"seed {seed}: covered twice at {np.argwhere(counts > 1)[:5]}"
    centres = np.arange(size) + 0.5
    inside = (centres > lo) & (centres < lo + step * n)
    interior = inside[:, None] & inside[None, :]
    holes = np.argwhere(interior & (counts != 1))
    assert holes.size == 0, f"seed {seed}: cracks at {holes[:5].tolist()}"


@settings(max_examples=examples(100), deadline=None)
@given(
    st.integers(0, 2**32 - 1),
    st.integers(4, 9),
    st.sampled_from(["float", "centre"]),
    methods,
)
def test_random_fan_covered_exactly_once(seed, n, hub_kind, method):
    """A closed fan around a hub (on a pixel centre or not), angular gaps below 180 degrees.

    Interior pixel centres are those strictly inside a triangle, on a spoke strictly between
    hub and rim, or on the hub itself (interior because every angular gap is < 180 degrees).
    """
    rng = np.random.default_rng(seed)
    size = 24
    hub = np.array([11.5, 11.5]) if hub_kind == "centre" else rng.uniform(10, 13, size=2)
    angles = (np.arange(n) + rng.uniform(-0.3, 0.3, size=n)) * 2 * np.pi / n
    radii = rng.uniform(4, 10, size=n)
    if rng.random() < 0.5:  # spokes along lattice directions through centres, now and then
        radii = np.round(radii)
    rim = hub + np.stack([np.cos(angles), np.sin(angles)], -1) * radii[:, None]
    tris = [np.array([hub, rim[k], rim[(k + 1) % n]])[rng.permutation(3)] for k in range(n)]
    counts = counts_of(tris, method, (size, size))
    assert counts.max() <= 1, f"seed {seed}: covered twice at {np.argwhere(counts > 1)[:5]}"

    scale = 2**9  # exact interior test on the snapped grid, integers in 1/512 px
    h = [int(c * scale) for c in snapped_vertices([hub])[0]]
    r = [[int(c * scale) for c in p] for p in snapped_vertices(rim)]
    for i in range(size):
        for j in range(size):
            p = ((2 * j + 1) * scale // 2, (2 * i + 1) * scale // 2)
            interior = p == tuple(h)
            for k in range(n):
                a, b = r[k], r[(k + 1) % n]
                e = [edge_exact(h, a, p), edge_exact(a, b, p), edge_exact(b, h, p)]
                if all(x > 0 for x in e) or all(x < 0 for x in e):
                    interior = True
                on_spoke = (
                    edge_exact(h, a, p) == 0
                    and 0
                    < ((p[0] - h[0]) * (a[0] - h[0]) + (p[1] - h[1]) * (a[1] - h[1]))
                    < (a[0] - h[0]) ** 2 + (a[1] - h[1]) ** 2
                )
                interior |= on_spoke
            if interior:
                assert counts[i, j] == 1, f"seed {seed}: interior centre ({i}, {j}) not covered"


# -- barycentrics and attributes ----------------------------------------------------------------
@FAST
@given(any_triangle, methods)
def test_barycentrics_in_unit_interval_and_sum_to_one(xy, method):
    lam = fill(xy, method).trace.pixel_barycentric
    assert ((lam >= 0) & (lam <= 1)).all(), f"xy={xy.tolist()}"
    assert np.all(np.abs(lam.sum(axis=1) - 1) <= 1e-12), f"xy={xy.tolist()}"


@FAST
@given(any_triangle, methods, modes, w_values, st.floats(-1e6, 1e6))
def test_constant_attribute_exactly_constant(xy, method, mode, w, c):
    out = fill(xy, method, mode, w, attrs=np.full(3, c))
    assert (out.attrs["f"][out.coverage] == c).all()


@FAST
@given(any_triangle, methods, modes, w_values, attr_values)
def test_vertex_order_changes_nothing(xy, method, mode, w, attrs):
    ref = fill(xy, method, mode, w, attrs)
    for p in PERMUTATIONS[1:]:
        p = list(p)
        out = fill(xy[p], method, mode, w[p], attrs[p])
        assert (out.coverage == ref.coverage).all(), f"order {p}: xy={xy.tolist()}"
        err = np.abs(out.attrs["f"] - ref.attrs["f"])[ref.coverage]
        assert (err <= 1e-12 * np.maximum(1, np.abs(attrs).max())).all(), f"order {p}"


@FAST
@given(any_triangle, methods, modes, w_values, attr_values, st.integers(0, 40), st.integers(0, 40))
def test_whole_pixel_translation_changes_nothing(xy, method, mode, w, attrs, dx, dy):
    ref = fill(xy, method, mode, w, attrs, size=(SIZE, SIZE))
    moved = fill(xy + [dx, dy], method, mode, w, attrs, size=(SIZE + dx, SIZE + dy))
    assert (moved.coverage[dy:, dx:] == ref.coverage).all(), f"shift {(dx, dy)}: {xy.tolist()}"
    err = np.abs(moved.attrs["f"][dy:, dx:] - ref.attrs["f"])[ref.coverage]
    assert (err <= 1e-12 * np.maximum(1, np.abs(attrs).max())).all(), f"shift {(dx, dy)}"


@FAST
@given(any_triangle, methods, st.floats(1e-3, 1e3), attr_values)
def test_perspective_equals_affine_for_constant_w(xy, method, w, attrs):
    persp = fill(xy, method, "perspective", np.full(3, w), attrs)
    affine = fill(xy, method, "affine", np.full(3, w), attrs)
    np.testing.assert_array_equal(persp.attrs["f"], affine.attrs["f"])
