"""The trace: recording never changes the pixels, and what it records is consistent and small."""

import dataclasses
from collections.abc import Mapping
from fractions import Fraction

import numpy as np
import pytest
from conftest import (
    METHODS,
    MODES,
    any_triangle,
    edge_exact,
    examples,
    random_triangles,
    snapped_vertices,
    top_left,
)
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr

W, H = 13, 11
KINDS = ("float", "subpixel", "centre", "tie", "outside")


def cases(seed, n):
    rng = np.random.default_rng(seed)
    for kind in KINDS:
        for xy in random_triangles(rng, kind, n, W, H):
            yield tr.Triangle(
                xy,
                w=rng.uniform(0.2, 5, 3),
                z=rng.uniform(0, 1, 3),
                attrs={"u": rng.uniform(-1, 1, 3), "rgb": rng.uniform(0, 1, (3, 3))},
            )


def traced(tri, method, **kw):
    return tr.rasterize(tri, W, H, method=method, trace=True, **kw)


# -- tracing never changes the result ---------------------------------------------------------
@pytest.mark.parametrize("mode", MODES)
@pytest.mark.parametrize("method", METHODS)
def test_trace_never_changes_coverage_attrs_or_depth(method, mode):
    """trace=True gives bit-identical coverage, attributes and depth to trace=False."""
    for tri in cases(1, 40):
        plain = tr.rasterize(tri, W, H, method=method, interpolation=mode)
        rec = tr.rasterize(tri, W, H, method=method, interpolation=mode, trace=True)
        np.testing.assert_array_equal(plain.coverage, rec.coverage)
        np.testing.assert_array_equal(plain.depth, rec.depth)  # NaN == NaN here
        assert plain.attrs.keys() == rec.attrs.keys()
        for name in plain.attrs:
            np.testing.assert_array_equal(plain.attrs[name], rec.attrs[name])
        assert plain.trace is None
        assert rec.trace is not None


def test_trace_records_both_interpolations_matching_the_fills():
    """trace.affine / trace.perspective hold exactly what each interpolation mode produces."""
    for tri in cases(2, 10):
        t = traced(tri, "halfplane").trace
        for mode, recorded in (("affine", t.affine), ("perspective", t.perspective)):
            fill = tr.rasterize(tri, W, H, interpolation=mode)
            for name, local in recorded.items():
                np.testing.assert_array_equal(t.image(local), fill.attrs[name])
        np.testing.assert_array_equal(t.image(t.depth), tr.rasterize(tri, W, H).depth)


# -- set-up records ---------------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_trace_setup_fields(method):
    """snapped, signed area, facing, edges and top-left flags follow the conventions exactly."""
    for tri in cases(3, 20):
        fill = traced(tri, method)
        t = fill.trace
        snapped = snapped_vertices(tri.xy)
        assert [(Fraction(x), Fraction(y)) for x, y in t.snapped] == snapped
        area = edge_exact(*snapped) / 2
        assert Fraction(t.signed_area) == area
        assert t.front_facing == (area < 0)
        assert (t.method, t.width, t.height, t.subpixel_bits) == (method, W, H, 8)
        np.testing.assert_array_equal(t.xy, tri.xy)
        if area != 0:
            # Edges walk the triangle with the interior on the positive side.
            edges = [tuple(e) for e in t.edges.tolist()]
            assert sorted(sum(edges, ())) == [0, 0, 1, 1, 2, 2]
            for (a, b), flag in zip(edges, t.top_left):
                c = 3 - a - b
                assert edge_exact(snapped[a], snapped[b], snapped[c]) > 0
                assert flag == top_left(snapped[a], snapped[b])


@pytest.mark.parametrize("method", METHODS)
def test_bbox_contains_every_covered_pixel(method):
    """The bounding box (clipped to the image) contains every covered pixel; its extents are the
    snapped vertices' min/max."""
    for tri in cases(4, 30):
        fill = traced(tri, method)
        b = fill.trace.bbox
        rows, cols = np.nonzero(fill.coverage)
        assert 0 <= b.row0 <= b.row1 <= H and 0 <= b.col0 <= b.col1 <= W
        assert ((rows >= b.row0) & (rows < b.row1)).all()
        assert ((cols >= b.col0) & (cols < b.col1)).all()
        s = fill.trace.snapped
        assert (b.xmin, b.xmax) == (s[:, 0].min(), s[:, 0].max())
        assert (b.ymin, b.ymax) == (s[:, 1].min(), s[:, 1].max())
        # every pixel centre of the image inside the box's extents is in the index ranges
        r, c = np.indices((H, W))
        in_ext = (
            (c + 0.5 >= b.xmin) & (c + 0.5 <= b.xmax) & (r + 0.5 >= b.ymin) & (r + 0.5 <= b.ymax)
        )
        in_box = np.zeros((H, W), dtype=bool)
        in_box[b.row0 : b.row1, b.col0 : b.col1] = True
        np.testing.assert_array_equal(in_ext, in_box)


# -- span tables ------------------------------------------------------------------------------
def test_span_trace_rows_split_and_spans():
    """Span trace: rows sorted, u4 from Ek's *Triangles and Perspective Correct Interpolation* formula, spans reproduce coverage row by row,
    and the crossings bracket the covered centres."""
    for tri in cases(5, 40):
        fill = traced(tri, "span")
        s = fill.trace.span
        assert fill.trace.halfplane is None
        b = fill.trace.bbox
        assert np.all(np.diff(s.rows) > 0)
        np.testing.assert_array_equal(s.rows, np.arange(b.row0, b.row1))
        # sorted by y (then x), and the same points as the snapped vertices
        np.testing.assert_array_equal(s.sorted_xy, fill.trace.snapped[s.order])
        assert sorted(s.order.tolist()) == [0, 1, 2]
        assert np.all(np.diff(s.sorted_xy[:, 1]) >= 0)
        (u1, v1), (_, v2), (u3, v3) = s.sorted_xy
        if v3 == v1:
            assert s.u4 is None and s.flat_bottom is None and s.flat_top is None
        else:
            assert s.u4 == pytest.approx(
                (v2 - v1) / (v3 - v1) * (u3 - u1) + u1, rel=1e-12, abs=1e-12
            )
            assert (s.flat_bottom is None) == (v2 == v1)
            assert (s.flat_top is None) == (v3 == v2)
        for k, row in enumerate(s.rows):
            expected = np.zeros(W, dtype=bool)
            expected[s.col_start[k] : s.col_stop[k]] = True
            np.testing.assert_array_equal(fill.coverage[row], expected)
            assert s.col_start[k] <= s.col_stop[k]
            covered = np.nonzero(fill.coverage[row])[0]
            if covered.size:
                assert s.x_left[k] <= covered[0] + 0.5
                assert covered[-1] + 0.5 <= s.x_right[k]
            # rows from v2 down are the flat-top part, unless there is none (flat bottom)
            assert s.half[k] == (0 if row + 0.5 < v2 or v3 == v2 else 1)


@pytest.mark.parametrize(
    ("xy", "flat_bottom_none", "flat_top_none"),
    [
        ([[1.2, 1.5], [7.7, 1.5], [3.3, 8.1]], True, False),  # already flat-topped (top, middle)
        ([[3.3, 0.4], [1.2, 8.5], [7.7, 8.5]], False, True),  # already flat-bottomed
        ([[1.0, 1.0], [8.0, 5.0], [3.0, 9.0]], False, False),  # general: split in two
    ],
)
def test_span_split_of_flat_triangles(xy, flat_bottom_none, flat_top_none):
    """An already-flat triangle is not split: the missing half is None, and u4 is a vertex x."""
    s = traced(tr.Triangle(xy), "span").trace.span
    assert (s.flat_bottom is None) == flat_bottom_none
    assert (s.flat_top is None) == flat_top_none
    if flat_bottom_none:  # u4 is on the long edge at v1 = v2's height: v1's x
        assert s.u4 == s.sorted_xy[0, 0]
    if flat_top_none:
        assert s.u4 == s.sorted_xy[2, 0]
    if not (flat_bottom_none or flat_top_none):
        np.testing.assert_array_equal(s.flat_bottom[:2], s.sorted_xy[:2])
        np.testing.assert_array_equal(s.flat_bottom[2], [s.u4, s.sorted_xy[1, 1]])
        np.testing.assert_array_equal(s.flat_top[2], s.sorted_xy[2])


@pytest.mark.parametrize(
    "xy",
    [[[0.5, 2.5], [6.5, 2.5], [3.5, 2.5]], [[2.0, 2.0]] * 3, [[1, 1], [3, 3], [5, 5]]],
    ids=["flat", "point", "collinear"],
)
def test_span_trace_of_zero_height_or_zero_area_does_not_divide_by_zero(xy):
    """Zero-height / zero-area triangles trace without ZeroDivisionError or warnings."""
    with np.errstate(all="raise"):
        t = traced(tr.Triangle(xy), "span").trace
    if xy[0][1] == xy[1][1] == xy[2][1]:
        assert t.span.u4 is None and t.span.flat_bottom is None and t.span.flat_top is None
        assert "zero height" in t.step(4).caption
    assert not t.coverage_at(len(t) - 1).any()


def test_split_point_formula():
    """tr.split_point implements u4 = (v2 - v1) / (v3 - v1) * (u3 - u1) + u1 (Ek, *Triangles and Perspective Correct Interpolation*, §1.1)."""
    rng = np.random.default_rng(6)
    for _ in range(50):
        pts = rng.uniform(0, 10, (3, 2))
        pts = pts[np.argsort(pts[:, 1])]
        (u1, v1), (_, v2), (u3, v3) = pts
        assert tr.split_point(pts) == pytest.approx((v2 - v1) / (v3 - v1) * (u3 - u1) + u1)
    assert tr.split_point(np.array([[0.0, 1.0], [5.0, 1.0], [9.0, 1.0]])) is None


# -- half-planes ------------------------------------------------------------------------------
def test_halfplane_trace_is_consistent_with_edge_values():
    """rejected_by = first failing test (E < 0, or E == 0 off a top-left edge), tests_run = that
    index + 1 (3 when covered), and edge_values are the exact E in px² at every centre."""
    for tri in cases(7, 30):
        fill = traced(tri, "halfplane")
        t = fill.trace
        h = t.halfplane
        assert t.span is None
        b = t.bbox
        assert h.edge_values.shape == (*b.shape, 3)
        assert h.tests_run.shape == h.rejected_by.shape == b.shape
        e = h.edge_values
        passed = (e > 0) | ((e == 0) & t.top_left[None, None, :])
        first_fail = np.where(
            ~passed[..., 0], 0, np.where(~passed[..., 1], 1, np.where(~passed[..., 2], 2, -1))
        )
        np.testing.assert_array_equal(h.rejected_by, first_fail)
        np.testing.assert_array_equal(h.tests_run, np.where(first_fail < 0, 3, first_fail + 1))
        np.testing.assert_array_equal(
            t.image(h.rejected_by == -1, fill=False)[b.row0 : b.row1, b.col0 : b.col1],
            fill.coverage[b.row0 : b.row1, b.col0 : b.col1],
        )
        snapped = snapped_vertices(tri.xy)
        for r in range(0, b.shape[0], 3):
            for c in range(0, b.shape[1], 3):
                p = (Fraction(2 * (b.col0 + c) + 1, 2), Fraction(2 * (b.row0 + r) + 1, 2))
                for k, (i, j) in enumerate(t.edges):
                    assert Fraction(e[r, c, k]) == edge_exact(snapped[i], snapped[j], p)


def test_halfplane_visit_order_is_row_major_over_the_bbox():
    """Pixels are visited row by row, left to right, over the bounding box."""
    t = traced(tr.Triangle([[1.2, 2.3], [9.7, 3.1], [4.4, 8.8]]), "halfplane").trace
    rows, cols = t.bbox.shape
    expected = [(r, c) for r in range(rows) for c in range(cols)]
    assert [tuple(p) for p in t.halfplane.visit_order().tolist()] == expected
    for i, (r, c) in enumerate(expected[:20]):
        step = t.step(t.first_work_step + i)
        assert step.kind == "pixel"
        assert (step.row, step.col) == (t.bbox.row0 + r, t.bbox.col0 + c)


# -- stepping ---------------------------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_coverage_grows_monotonically_to_the_final_coverage(method):
    """coverage_at(k) only ever gains pixels, and coverage_at(last) == coverage."""
    for tri in cases(8, 10):
        fill = traced(tri, method)
        t = fill.trace
        prev = np.zeros((H, W), dtype=bool)
        assert not t.coverage_at(t.first_work_step - 1).any()  # set-up fills nothing
        for k in range(len(t)):
            cur = t.coverage_at(k)
            assert not (prev & ~cur).any()
            prev = cur
        np.testing.assert_array_equal(t.coverage_at(len(t) - 1), fill.coverage)
        assert ((t.filled_at == -1) | (t.filled_at >= t.first_work_step)).all()
        np.testing.assert_array_equal(t.image(t.filled_at >= 0, fill=False), fill.coverage)


def test_span_fills_one_raster_line_per_step():
    """Span tables: the step of row k fills exactly the covered pixels of that row."""
    for tri in cases(9, 10):
        fill = traced(tri, "span")
        t = fill.trace
        for k, row in enumerate(t.span.rows):
            step = t.first_work_step + k
            new = t.coverage_at(step) & ~t.coverage_at(step - 1)
            expected = np.zeros((H, W), dtype=bool)
            expected[row] = fill.coverage[row]
            np.testing.assert_array_equal(new, expected)
            assert t.step(step).kind == "row" and t.step(step).row == row


@pytest.mark.parametrize("method", METHODS)
def test_steps_have_one_line_captions_and_a_fixed_structure(method):
    """Every step: non-empty single-line caption, index == position; set-up kinds first,
    then one work step per row (span) / bbox pixel (half-plane), last step "interpolate"."""
    # span tables test no box: their third step finds the raster lines (review r142 01-3)
    setup_kinds = (["snap", "winding", "rows", "sort", "split"] if method == "span"
                   else ["snap", "winding", "bbox"])  # fmt: skip
    for tri in cases(10, 6):
        t = traced(tri, method).trace
        steps = list(t)
        assert len(steps) == len(t)
        for k, s in enumerate(steps):
            assert s.index == k
            assert isinstance(s.caption, str) and s.caption.strip()
            assert "\n" not in s.caption
            assert t.caption(k) == s.caption
        assert [s.kind for s in steps[: len(setup_kinds)]] == setup_kinds
        work = {"span": "row", "halfplane": "pixel"}[method]
        n_work = len(t.span.rows) if method == "span" else t.bbox.size
        assert [s.kind for s in steps[len(setup_kinds) : -1]] == [work] * n_work
        assert t.step(-1).kind == "interpolate"
        assert t.step(-1) == t.step(len(t) - 1)
        with pytest.raises(IndexError):
            t.step(len(t))
        with pytest.raises(IndexError):
            t.step(-len(t) - 1)


def test_culled_trace_has_no_work_steps():
    """A culled triangle: trace.culled, no work steps, the winding caption says so."""
    t = tr.rasterize(
        tr.Triangle([[0.5, 0.5], [6.5, 0.5], [0.5, 6.5]]), 8, 8, trace=True, cull="back"
    ).trace
    assert t.culled and t.n_work == 0 and len(t) == len(t.setup) + 1
    assert "culled" in t.step(1).caption
    assert t.step(-1).kind == "interpolate"


# -- plain data, small ------------------------------------------------------------------------
SCALARS = (int, float, bool, str, type(None), np.integer, np.floating, np.bool_)


def assert_plain_data(obj, path="trace"):
    """Arrays (never of dtype object), small dataclasses, scalars, mappings, and short tuples
    (of captions, or one array per edge)."""
    if isinstance(obj, np.ndarray):
        assert obj.dtype != object, f"{path} is an object array"
    elif dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            assert_plain_data(getattr(obj, f.name), f"{path}.{f.name}")
    elif isinstance(obj, Mapping):
        for k, v in obj.items():
            assert isinstance(k, str), f"{path} has key {k!r}"
            assert_plain_data(v, f"{path}[{k!r}]")
    elif isinstance(obj, tuple):
        assert len(obj) < 50, f"{path} is a tuple of {len(obj)} items (one per pixel?)"
        for i, v in enumerate(obj):
            assert isinstance(v, str | tuple | np.ndarray), f"{path}[{i}] is {type(v).__name__}"
            if isinstance(v, tuple):
                assert all(isinstance(x, str) for x in v), f"{path}[{i}]"
            else:
                assert_plain_data(v, f"{path}[{i}]")
    else:
        assert isinstance(obj, SCALARS), f"{path} is a {type(obj).__name__}"


def total_nbytes(obj) -> int:
    if isinstance(obj, np.ndarray):
        return obj.nbytes
    if dataclasses.is_dataclass(obj):
        return sum(total_nbytes(getattr(obj, f.name)) for f in dataclasses.fields(obj))
    if isinstance(obj, Mapping):
        return sum(total_nbytes(v) for v in obj.values())
    if isinstance(obj, tuple):
        return sum(total_nbytes(v) for v in obj)
    return 0


@pytest.mark.parametrize("method", METHODS)
def test_trace_is_plain_numpy_data(method):
    """No per-pixel Python objects: every field is an array, a small dataclass or a scalar."""
    for tri in cases(11, 3):
        assert_plain_data(traced(tri, method).trace)


@pytest.mark.parametrize("method", METHODS)
def test_trace_of_a_256_square_image_is_small(method):
    """Tracing a triangle covering a 256 x 256 image costs a few arrays (< 20 MB), quickly."""
    tri = tr.Triangle(
        [[-10, -10], [600, -5], [-5, 600]],
        z=[0, 0.5, 1],
        attrs={"u": [0, 1, 2], "rgb": np.eye(3)},
    )
    t = tr.rasterize(tri, 256, 256, method=method, trace=True).trace
    assert t.coverage_at(len(t) - 1).all()
    assert total_nbytes(t) < 20e6
    assert_plain_data(t)
    assert t.step(len(t) // 2).caption  # captions are made on demand, even here


@settings(max_examples=examples(100), deadline=None)
@given(any_triangle, st.sampled_from(METHODS), st.sampled_from([None, "back", "front"]))
def test_hypothesis_trace_final_coverage_matches(xy, method, cull):
    """Hypothesis: for any triangle, method and culling, the trace ends at the fill's coverage."""
    fill = tr.rasterize(tr.Triangle(xy), W, H, method=method, trace=True, cull=cull)
    plain = tr.rasterize(tr.Triangle(xy), W, H, method=method, cull=cull)
    np.testing.assert_array_equal(fill.coverage, plain.coverage)
    np.testing.assert_array_equal(fill.trace.coverage_at(len(fill.trace) - 1), fill.coverage)
    assert fill.trace.step(-1).kind == "interpolate"


def test_subdivided_interpolation_is_traced_and_captioned():
    """interpolation="subdivided" records N and the values it wrote, and captions its steps."""
    tri = tr.Triangle([[1, 1], [14, 3], [4, 14]], w=[1, 3, 6], attrs={"u": [0, 1, 0]})
    for method in ("span", "halfplane"):
        fill = tr.rasterize(tri, 16, 16, method=method, interpolation="subdivided",
                            subdivision=4, trace=True)  # fmt: skip
        t = fill.trace
        assert t.subdivision == 4
        np.testing.assert_array_equal(t.pixel_subdivided["u"], fill.attrs["u"][fill.coverage])
        assert all(step.caption for step in t)
        assert "every 4th pixel" in t.caption(-1)
    plain = tr.rasterize(tri, 16, 16, trace=True).trace
    assert plain.subdivision is None and plain.pixel_subdivided is None


# -- the step table's accessors ---------------------------------------------------------------
@pytest.mark.parametrize("method", METHODS)
def test_step_numbers_come_from_the_trace(method):
    """bbox_step, split_step, first_work_step, interpolation_step name the step kinds."""
    for tri in cases(11, 4):
        t = traced(tri, method).trace
        kinds = [s.kind for s in t]
        assert kinds[t.bbox_step] == ("rows" if method == "span" else "bbox")
        if method == "span":
            assert kinds[t.split_step] == "split" and t.split_step < t.first_work_step
        else:
            assert t.split_step is None and "split" not in kinds
        assert t.first_work_step == len(t.setup_kinds) == len(t.setup)
        assert kinds[t.interpolation_step] == "interpolate"
        assert t.index(-1) == t.interpolation_step == len(t) - 1
        assert [caption for _, caption in t.setup] == [t.caption(k) for k in range(len(t.setup))]
        with pytest.raises(IndexError):
            t.index(len(t))


@pytest.mark.parametrize("method", METHODS)
def test_visit_step_numbers_every_pixel_the_fill_reaches(method):
    for tri in cases(12, 4):
        fill = traced(tri, method)
        t, b = fill.trace, fill.trace.bbox
        v = t.visit_step
        assert v.shape == b.shape
        if method == "halfplane" and not t.culled:
            expected = t.first_work_step + np.arange(b.size).reshape(b.shape)
            np.testing.assert_array_equal(v, expected)
        else:  # span tables reach the covered pixels, at the step of their raster line
            np.testing.assert_array_equal(v >= 0, t.covered)
        np.testing.assert_array_equal(t.filled_at, np.where(t.covered, v, -1))
        for row, col in [(b.row0, b.col0), (b.row1 - 1, b.col1 - 1), (-1, 0), (0, W)]:
            inside = b.row0 <= row < b.row1 and b.col0 <= col < b.col1
            expected = int(v[row - b.row0, col - b.col0]) if inside else -1
            assert t.visit_step_of(row, col) == expected
        rows, cols = t.visit_order()
        steps = [t.visit_step_of(r, c) for r, c in zip(rows, cols)]
        assert steps == sorted(steps) and len(steps) == int((v >= 0).sum())
        for k in (t.first_work_step, len(t) // 2, len(t) - 1):
            if t.step(k).kind == "pixel":  # the pixel a step tests is its visit step's
                s = t.step(k)
                assert t.visit_step_of(s.row, s.col) == k


@pytest.mark.parametrize("method", METHODS)
def test_rejected_at_is_what_half_planes_tested_and_left_out(method):
    for tri in cases(13, 4):
        fill = traced(tri, method)
        t = fill.trace
        for k in (0, t.first_work_step, len(t) // 2, len(t) - 1):
            rejected = t.rejected_at(k)
            if method == "span":
                assert not rejected.any()
                continue
            visited = t.image((t.visit_step >= 0) & (t.visit_step <= k), fill=False)
            if method == "tiled" and not t.culled:  # blocks reach beyond the box (r77 00-2)
                np.testing.assert_array_equal(rejected & t.image(t.visit_step >= -1, fill=False),
                                              visited & ~t.coverage_at(-1))  # fmt: skip
                steps = t.block_steps
                visited = (steps >= 0) & (steps <= k)
            np.testing.assert_array_equal(rejected, visited & ~t.coverage_at(-1))
        if method == "halfplane":
            np.testing.assert_array_equal(t.rejected_at(-1) | fill.coverage,
                                          t.image(np.ones(t.bbox.shape, bool), fill=False))  # fmt: skip


def test_pixel_steps_build_no_bbox_sized_arrays(monkeypatch):
    """Captioning one pixel reads that pixel's values only (not edge_values & co.)."""
    from teachraster.core.half_planes import HalfPlaneTrace

    t = tr.rasterize(tr.Triangle([[1, 1], [60, 9], [12, 58]]), 64, 64, trace=True).trace
    expected = [t.step(k) for k in range(t.first_work_step, t.first_work_step + 200)]

    def boom(self):
        raise AssertionError("a whole-box array was built to caption one pixel")

    for name in ("edge_values", "rejected_by", "tests_run"):
        monkeypatch.setattr(HalfPlaneTrace, name, property(boom))
    got = [t.step(k) for k in range(t.first_work_step, t.first_work_step + 200)]
    assert got == expected
    assert "->" in got[0].caption and got[0].kind == "pixel"


def test_bail_out_and_edge_images_are_the_half_plane_tests_for_either_method():
    tri = tr.Triangle([[1.3, 1.2], [11.6, 4.7], [5.2, 10.1]])
    hp, sp = traced(tri, "halfplane").trace, traced(tri, "span").trace
    for a, b in zip(hp.bail_out(), sp.bail_out()):
        np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(hp.edge_images(), sp.edge_images())
    b = hp.bbox
    np.testing.assert_array_equal(hp.edge_images()[b.row0 : b.row1, b.col0 : b.col1],
                                  hp.halfplane.edge_values)  # fmt: skip
    assert sp.edge_tests() is not sp.halfplane  # span traces run the tests afresh
    assert hp.edge_tests() is hp.halfplane


def test_row_steps_carry_their_span():
    t = traced(tr.Triangle([[1.3, 1.2], [11.6, 4.7], [5.2, 10.1]]), "span").trace
    s = t.span
    for i in range(len(s.rows)):
        step = t.step(t.first_work_step + i)
        assert step.work == i and step.columns == (int(s.col_start[i]), int(s.col_stop[i]))
        if np.isfinite(s.x_left[i]) and np.isfinite(s.x_right[i]):
            assert step.span_x == (float(s.x_left[i]), float(s.x_right[i]))
        else:
            assert step.span_x is None


def test_last_caption_counts_the_pixels_a_multisampled_picture_fills():
    """Review r9 (lesson 00 c14): with 4 samples the player's last caption said "at 59 covered
    pixels" (the centre pass) while its picture filled the 72 pixels with a covered sample."""
    tri = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]], w=[1.0, 2.0, 4.0],
                      attrs={"u": [0.0, 1.0, 0.0]})  # fmt: skip
    multi = tr.rasterize(tri, 16, 16, samples=4, trace=True)
    centre = tr.rasterize(tri, 16, 16, trace=True)
    n, m = int(centre.coverage.sum()), int(multi.coverage.sum())
    assert m > n
    assert f"at the {m} pixels with a covered sample ({n} with their centre covered; " in (
        multi.trace.caption(-1)
    )
    # review r23 00-6: the pixels shaded only because of a sample are counted too
    assert f"; {m - n} shaded only because a sample is)" in multi.trace.caption(-1)
    assert f"at {n} covered pixels" in centre.trace.caption(-1)


def test_span_captions_say_what_the_half_open_loop_does():
    """Review r142 01-3: the player's step 2 was labelled "bbox" for span tables, which test
    no box; the bottom vertex's line, which the trace shows but the loop does not visit
    (y_top <= y < y_bot), was captioned like any empty span."""
    import teachraster as tr

    xy = [[8.5, 17.5], [4.5, 1.5], [18.5, 9.5]]
    t = tr.rasterize(tr.Triangle(xy), 20, 20, method="span", trace=True).trace
    assert t.step(2).kind == "rows" and "bbox" not in t.setup_kinds
    assert "v_top <= v < v_bot" in t.caption(2) and "no box" in t.caption(2)
    last_row = t.step(t.interpolation_step - 1)
    assert last_row.row == 17 and "not visited" in last_row.caption
    assert "v_bot" in last_row.caption and "v1" in last_row.caption
    assert "not visited" not in t.caption(t.interpolation_step - 2)  # row 16 fills columns 8-9
    half = tr.rasterize(tr.Triangle(xy), 20, 20, method="halfplane", trace=True).trace
    assert half.step(2).kind == "bbox" and "bounding box" in half.caption(2)
