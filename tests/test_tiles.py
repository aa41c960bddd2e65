"""The tiled fill (``method="tiled"``): exact coverage, block classification, counters, orders.

Every classification is re-derived here from exact integer edge values at the four extreme
pixel centres of each block (written from CONVENTIONS.md with conftest's reference helpers,
not from the package code), and coverage is compared with the exact reference and with the
half-plane fill.
"""

from __future__ import annotations

import numpy as np
import pytest
from conftest import (
    KINDS,
    any_triangle,
    cases,
    edge_exact,
    examples,
    explain,
    random_triangles,
    raster,
    reference_coverage,
    snapped_vertices,
    tie_coords,
    top_left,
    triangles,
)
from hypothesis import given, settings
from hypothesis import strategies as st

import teachraster as tr
from teachraster.core import fixed_point as fp
from teachraster.core import traversal as tv
from teachraster.study import hardcases as hc

W, H = 13, 11
SIZES = [(64, 16, 4), (8, 4, 2, 1), (4,), (6, 3), (16, 8)]


def tiled(xy, width, height, **kwargs):
    return tr.rasterize(tr.Triangle(xy), width, height, method="tiled", **kwargs)


# -- coverage ------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", KINDS)
def test_bulk_random_triangles_match_reference(kind):
    """600 seeded triangles per kind and block sizes: tiled == exact reference == half-plane."""
    rng = np.random.default_rng(1300 + KINDS.index(kind))
    for n, xy in enumerate(random_triangles(rng, kind, cases(600), W, H)):
        want = reference_coverage(xy, W, H)
        got = raster(xy, W, H, method="tiled", block_sizes=SIZES[n % len(SIZES)])
        assert np.array_equal(got, want), explain(xy, got, want)


@pytest.mark.parametrize("bits", [None, 0, 4, 16])
def test_other_precisions_match_halfplane(bits):
    """Raw floats and other grids: tiled == half-plane (== span), triangle after triangle."""
    rng = np.random.default_rng(1400 + (bits or 99))
    for kind in ("float", "tie", "outside", "huge"):
        for n, xy in enumerate(random_triangles(rng, kind, cases(150), 37, 29)):
            want = raster(xy, 37, 29, subpixel_bits=bits)
            got = raster(xy, 37, 29, method="tiled", subpixel_bits=bits, block_sizes=SIZES[n % 5])
            assert np.array_equal(got, want), explain(xy, got, want)


def test_large_image_several_top_blocks_match():
    """Images larger and not multiples of 64: blocks clipped at the border, still exact."""
    rng = np.random.default_rng(15)
    for xy in rng.uniform(-20, 220, size=(60, 3, 2)):
        want = raster(xy, 203, 141)
        assert np.array_equal(raster(xy, 203, 141, method="tiled"), want), xy.tolist()


@settings(max_examples=examples(300), deadline=None)
@given(any_triangle, st.sampled_from(SIZES))
def test_hypothesis_tiled_equals_reference(xy, sizes):
    want = reference_coverage(xy, W, H)
    got = raster(xy, W, H, method="tiled", block_sizes=sizes)
    assert np.array_equal(got, want), explain(xy, got, want)


@settings(max_examples=examples(150), deadline=None)
@given(triangles(tie_coords(7)), st.sampled_from([(4, 2, 1), (2, 1), (8, 2)]))
def test_hypothesis_ties_on_block_corners(xy, sizes):
    """Half-pixel lattice: edges run through block corners' centres all the time."""
    want = reference_coverage(xy, 8, 8)
    got = raster(xy, 8, 8, method="tiled", block_sizes=sizes)
    assert np.array_equal(got, want), explain(xy, got, want)


# -- accepted blocks shaded whole ------------------------------------------------------------------
def _shaded_pair(xy, w, z, values, size, interpolation, sizes, bits):
    tri = tr.Triangle(xy, w=w, z=z, attrs={"u": values[:, 0], "rgb": values})
    kw = {"interpolation": interpolation, "subpixel_bits": bits}
    half = tr.rasterize(tri, *size, method="halfplane", **kw)
    return half, tr.rasterize(tri, *size, method="tiled", block_sizes=sizes, **kw)


@settings(max_examples=examples(200), deadline=None)
@given(
    xy=st.lists(st.tuples(st.floats(-30, 110), st.floats(-30, 90)), min_size=3, max_size=3),
    log_w=st.lists(st.floats(-3, 3), min_size=3, max_size=3),
    depth=st.booleans(),
    size=st.tuples(st.integers(1, 80), st.integers(1, 70)),
    interpolation=st.sampled_from(["perspective", "affine"]),
    sizes=st.sampled_from([(64, 16, 4), (8,), (32, 8), (4,), (16, 4), (6, 3)]),
    bits=st.sampled_from([8, None, 4, 0]),
)
def test_block_shading_equals_pixel_shading_bit_for_bit(xy, log_w, depth, size, interpolation,
                                                        sizes, bits):  # fmt: skip
    """The tiled fill shades the cells its walk left whole as dense blocks (edge values
    broadcast from one row and one column term, values written block by block): attributes
    and depth identical, bit for bit, to the half-plane fill's per-pixel shading."""
    rng = np.random.default_rng(abs(hash((tuple(xy), size))) % 2**32)
    values = rng.uniform(-1, 1, (3, 3))
    z = rng.uniform(0, 1, 3) if depth else None
    half, tiled_fill = _shaded_pair(np.array(xy), 10.0 ** np.array(log_w), z, values, size,
                                    interpolation, sizes, bits)  # fmt: skip
    assert np.array_equal(half.coverage, tiled_fill.coverage)
    for name in ("u", "rgb"):
        np.testing.assert_array_equal(half.attrs[name], tiled_fill.attrs[name])
    if depth:
        np.testing.assert_array_equal(half.depth, tiled_fill.depth)


def test_block_shading_shades_most_of_a_large_triangle_as_blocks():
    """The 1024² benchmark triangle: nearly every covered pixel lies in a whole 16×16 cell,
    and the images still equal the half-plane fill's."""
    from teachraster.core.block_shading import cell_size, whole_cells

    xy = np.array([[40.0, 30.0], [1000.0, 120.0], [200.0, 1010.0]])
    half, tiled_fill = _shaded_pair(xy, np.array([1.0, 2.0, 4.0]), None,
                                    np.eye(3), (1024, 1024), "perspective", (64, 16, 4), 8)  # fmt: skip
    cell = cell_size((64, 16, 4))
    whole = whole_cells(tiled_fill.coverage, cell).sum() * cell * cell
    assert cell == 16 and whole > 0.9 * tiled_fill.coverage.sum()
    np.testing.assert_array_equal(half.attrs["rgb"], tiled_fill.attrs["rgb"])


SCREEN_CASES = [name for name, case in hc.CASES.items() if case.triangles is not None]


@pytest.mark.parametrize("name", SCREEN_CASES)
def test_every_hard_case_triangle_matches_halfplane(name):
    """Every triangle of every screen-space hard case fills the same pixels tiled."""
    case = hc.get_case(name)
    width, height = case.inputs["size"]
    for xy in case.triangles:
        for sizes in [(64, 16, 4), (2, 1)]:
            want = raster(xy, width, height)
            got = raster(xy, width, height, method="tiled", block_sizes=sizes)
            assert np.array_equal(got, want), explain(xy, got, want)


# -- blocks --------------------------------------------------------------------------------------
def exact_classification(xy, trace, b, bits=8):
    """Kind and (max, min) per edge of block ``b`` from exact integer corner values."""
    scale = 2 ** (bits + 1)
    v = [(int(x * scale), int(y * scale)) for x, y in snapped_vertices(xy, bits)]
    if edge_exact(v[0], v[1], v[2]) < 0:
        v = [v[0], v[2], v[1]]
    row, col = int(trace.row[b]), int(trace.col[b])
    rows, cols = (int(n) for n in trace.extent[b])
    corners = [
        (c * scale + scale // 2, r * scale + scale // 2)
        for r in (row, row + rows - 1)
        for c in (col, col + cols - 1)
    ]
    passes, extremes = [], []
    for k in range(3):
        a, c = v[k], v[(k + 1) % 3]
        values = [edge_exact(a, c, p) for p in corners]
        bias = 0 if top_left(a, c) else 1
        passes.append([e >= bias for e in values])
        extremes.append((max(values), min(values)))
    exact_classification.crossing = [any(p) and not all(p) for p in passes]
    if any(not any(p) for p in passes):
        return "rejected", extremes
    if all(all(p) for p in passes):
        return "accepted", extremes
    return "partial", extremes


def check_blocks(xy, width, height, sizes):
    fill = tiled(xy, width, height, block_sizes=sizes, trace=True)
    t, cov = fill.trace.blocks, fill.coverage
    for b in range(len(t)):
        kind, extremes = exact_classification(xy, t, b)
        assert t.kind[b] == kind, (xy.tolist(), b)
        assert t.crossing[b].tolist() == exact_classification.crossing
        assert [tuple(e) for e in zip(t.e_max[b].tolist(), t.e_min[b].tolist())] == extremes
        r, c = int(t.row[b]), int(t.col[b])
        block = cov[r : r + t.extent[b, 0], c : c + t.extent[b, 1]]
        assert block.shape == tuple(t.extent[b])
        assert t.size[b] == sizes[t.level[b]]
        assert r % t.size[b] == 0 and c % t.size[b] == 0  # on the image grid
        if kind == "accepted":
            assert block.all()
        if kind == "rejected":
            assert not block.any()
        assert t.covered[b] == block.sum()
    return fill


def test_classification_rederived_exactly():
    """Each block's kind and corner extremes equal the exact integer re-derivation."""
    rng = np.random.default_rng(16)
    for n, xy in enumerate(random_triangles(rng, "float", 40, 45, 37)):
        check_blocks(xy, 45, 37, [(16, 4), (8, 4, 2, 1), (64, 16, 4)][n % 3])
    for xy in random_triangles(rng, "tie", 40, 9, 9):
        check_blocks(xy, 9, 9, (4, 2, 1))


def test_hierarchy_is_complete_and_depth_first():
    """Top blocks tile the box's block range; partial blocks (only) have all their children
    inside the image; parents come before their children, children right after each other."""
    xy = np.array([[3.3, 2.1], [140.2, 30.7], [40.9, 120.4]])
    fill = tiled(xy, 150, 130, trace=True)
    t, box = fill.trace.blocks, fill.trace.bbox
    top = np.flatnonzero(t.level == 0)
    want = {
        (r, c)
        for r in range(box.row0 // 64 * 64, box.row1, 64)
        for c in range(box.col0 // 64 * 64, box.col1, 64)
    }
    assert {(int(t.row[b]), int(t.col[b])) for b in top} == want
    for b in range(len(t)):
        kids = np.flatnonzero(t.parent == b)
        if t.kind[b] != "partial" or t.level[b] == 2:
            assert len(kids) == 0
            continue
        s = t.block_sizes[t.level[b] + 1]
        expected = {
            (int(t.row[b]) + i, int(t.col[b]) + j)
            for i in range(0, t.size[b], s)
            for j in range(0, t.size[b], s)
            if t.row[b] + i < 130 and t.col[b] + j < 150
        }
        assert {(int(t.row[k]), int(t.col[k])) for k in kids} == expected
        assert kids.min() > b
    assert (t.parent < np.arange(len(t))).all()
    np.testing.assert_array_equal(t.visit_order("scanline"), np.arange(len(t)))


def test_counters_consistent_with_blocks():
    rng = np.random.default_rng(17)
    for xy in random_triangles(rng, "outside", 30, 90, 70):
        fill = tiled(xy, 90, 70, block_sizes=(32, 8, 2), trace=True)
        t = fill.trace.blocks
        c = t.counters
        for lev, size in enumerate((32, 8, 2)):
            at = t.level == lev
            assert c.empty[lev] == np.sum(at & (t.kind == "rejected"))
            assert c.full[lev] == np.sum(at & (t.kind == "accepted"))
            assert c.partial[lev] == np.sum(at & (t.kind == "partial"))
            assert (t.size[at] == size).all()
        smallest = (t.level == 2) & (t.kind == "partial")
        assert c.pixel_tests == int(np.prod(t.extent[smallest], axis=1).sum())
        assert c.pixel_tests == t.pixel_tests.sum()
        assert c.non_empty == int((t.covered[smallest] > 0).sum())
        accepted = t.kind == "accepted"
        assert c.pixels_accepted == int(np.prod(t.extent[accepted], axis=1).sum())
        assert c.pixels_accepted + t.covered[smallest].sum() == fill.coverage.sum()
        assert c.blocks == len(t)
        # the pixel tests never exceed the half-plane fill's (the bounding box) by more than
        # the smallest partial blocks' overhang
        assert c.pixel_tests <= fill.trace.bbox.size + 4 * 2 * (90 + 70)


def test_one_pixel_blocks_are_pixel_tests_not_untested_fills():
    # lesson 10 (hierarchy 16/4/1): the corner test of a 1x1 block *is* the pixel test, so the
    # counters count those blocks as pixel tests and their pixels as tested (1184 untested of
    # 1492 covered, not 1492 and 0 tests)
    rng = np.random.default_rng(19)
    for xy in random_triangles(rng, "outside", 20, 64, 64):
        fill = tiled(xy, 64, 64, block_sizes=(16, 4, 1), trace=True)
        t, c = fill.trace.blocks, fill.trace.blocks.counters
        ones = t.level == 2
        assert c.pixel_tests == int(ones.sum()) == t.pixel_tests.sum()
        assert not (ones & (t.kind == "partial")).any()
        accepted_one = int((ones & (t.kind == "accepted")).sum())
        assert c.pixels_accepted + accepted_one == fill.coverage.sum()
        assert c.tests == c.blocks - int(ones.sum()) + c.pixel_tests
    # the same triangle with llvmpipe's sizes: tests are blocks plus pixel tests
    c = tiled(xy, 64, 64, block_sizes=(64, 16, 4), trace=True).trace.blocks.counters
    assert c.tests == c.blocks + c.pixel_tests


def test_zero_area_and_empty_box_classify_no_block():
    for xy in ([[1, 1], [5, 5], [9, 9]], [[2, 2], [2, 2], [2, 2]], [[-9, -9], [-5, -9], [-7, -2]]):
        fill = tiled(np.array(xy, float), 16, 16, trace=True)
        assert len(fill.trace.blocks) == 0 and fill.trace.blocks.counters.blocks == 0
        assert not fill.coverage.any()
        assert len(fill.trace) == len(fill.trace.setup) + 1


def test_trace_steps_and_captions():
    xy = np.array([[1.3, 2.2], [60.7, 10.1], [20.5, 50.9]])
    fill = tiled(xy, 64, 64, trace=True)
    trace, t = fill.trace, fill.trace.blocks
    assert trace.method == "tiled" and trace.halfplane is None and trace.span is None
    steps = list(trace)
    work = [s for s in steps if s.kind == "block"]
    assert len(work) == len(t) == trace.n_work
    assert any(s.kind == "blocks" for s in steps)
    for s, b in zip(work, range(len(t))):
        assert (s.row, s.col) == (t.row[b], t.col[b])
        assert t.kind[b] in s.caption and f"{t.size[b]}×{t.size[b]}" in s.caption
    np.testing.assert_array_equal(trace.coverage_at(-1), fill.coverage)
    # a pixel is filled at the step of its accepted block or its smallest partial block
    filled = trace.filled_at[trace.covered]
    for k in np.unique(filled):
        b = int(k) - trace.first_work_step
        assert t.kind[b] == "accepted" or (t.kind[b] == "partial" and t.level[b] == 2)
    box = trace.bbox
    local = fill.coverage[box.row0 : box.row1, box.col0 : box.col1]
    np.testing.assert_array_equal(trace.filled_at >= 0, local)


def test_recording_never_changes_the_result():
    rng = np.random.default_rng(18)
    for xy in random_triangles(rng, "float", 50, W, H):
        tri = tr.Triangle(xy, attrs={"u": [0.0, 1.0, 2.0]})
        a = tr.rasterize(tri, W, H, method="tiled")
        b = tr.rasterize(tri, W, H, method="tiled", trace=True)
        c = tr.rasterize(tri, W, H)
        np.testing.assert_array_equal(a.coverage, b.coverage)
        np.testing.assert_array_equal(a.attrs["u"], c.attrs["u"])


# -- traversal orders ----------------------------------------------------------------------------
@pytest.mark.parametrize("order", tv.TRAVERSALS)
@pytest.mark.parametrize("shape", [(1, 1), (3, 5), (8, 8), (7, 12)])
def test_traversals_are_permutations(order, shape):
    cells = tv.traversal_order(shape, order)
    assert len(cells) == shape[0] * shape[1]
    assert len({tuple(c) for c in cells.tolist()}) == len(cells)
    index = tv.visit_index(shape, order)
    assert sorted(index.ravel().tolist()) == list(range(len(cells)))


def test_traversal_properties():
    serp = tv.traversal_order((5, 7), "serpentine")
    assert (np.abs(np.diff(serp, axis=0)).sum(axis=1) == 1).all()  # always a 4-neighbour
    tiles4 = tv.traversal_order((8, 8), "tiled", tile=4)
    for t in range(4):  # each 4x4 tile is visited in one go
        chunk = tiles4[16 * t : 16 * (t + 1)] // 4
        assert (chunk == chunk[0]).all()
    z = tv.traversal_order((4, 4), "morton")
    assert z[:4].tolist() == [[0, 0], [0, 1], [1, 0], [1, 1]]
    assert z[4:8].tolist() == [[0, 2], [0, 3], [1, 2], [1, 3]]
    for k in (2, 4):  # every aligned k x k square is contiguous
        chunks = z.reshape(-1, k * k, 2) // k
        assert (chunks == chunks[:, :1]).all()


@pytest.mark.parametrize("order", tv.TRAVERSALS)
def test_block_visit_orders_are_depth_first_permutations(order):
    xy = np.array([[3.3, 2.1], [140.2, 30.7], [40.9, 120.4]])
    t = tiled(xy, 150, 130, trace=True).trace.blocks
    perm = t.visit_order(order)
    assert sorted(perm.tolist()) == list(range(len(t)))
    position = np.empty(len(t), dtype=int)
    position[perm] = np.arange(len(t))
    has_parent = t.parent >= 0
    assert (position[t.parent[has_parent]] < position[has_parent]).all()


# -- fixed point ---------------------------------------------------------------------------------
def test_bit_budget_terms():
    b = fp.bit_budget(1024, 8, 32)
    assert (b.units_per_pixel, b.delta_bits, b.product_bits, b.edge_bits, b.needed) == (
        512, 20, 40, 41, 42,
    )  # fmt: skip
    assert not b.fits and b.headroom == -10 and "NOT fit" in b.lines()[-1]
    # issue 31: counts with thousands separators, as the lessons print them (lesson 10 c15)
    assert "up to 1,024 px = 524,288 units < 2^20" in b.lines()[1]
    assert fp.bit_budget(1024, 8, 64).fits
    for bits in (0, 4, 8, 12):
        for width in (16, 32, 64):
            m = fp.max_extent(bits, width)
            if m:
                assert fp.bit_budget(m, bits, width).fits
            assert not fp.bit_budget(m + 1, bits, width).fits
    # teachraster's own guard band: |coordinate| < 2**30 units fits int64
    assert fp.max_extent(8, 64) * 512 >= 2**31 - 512


def test_exact_edge_values_fit_the_budget():
    """Every edge value the walk produced is below the budget's bound."""
    rng = np.random.default_rng(19)
    for xy in random_triangles(rng, "outside", 40, 60, 50):
        t = tiled(xy, 60, 50, trace=True).trace.blocks
        b = fp.bit_budget(fp.fill_extent(xy, 60, 50), 8, 64)
        for values in (t.e_max, t.e_min):
            assert (np.abs(values.astype(object)) < 2**b.edge_bits).all()


def test_narrow_registers_overflow_when_over_budget():
    xy = np.array([[10.2, 20.3], [1000.1, 60.2], [200.7, 1000.4]])
    tri = tr.Triangle(xy)
    narrow = fp.narrow_fill(tri, 1024, 1024, int_bits=32)
    assert not narrow.budget.fits
    assert narrow.wrong.sum() > 1000  # wrapped values accept and reject the wrong blocks
    np.testing.assert_array_equal(narrow.exact, tr.rasterize(tri, 1024, 1024).coverage)
    wide = fp.narrow_fill(tri, 1024, 1024, int_bits=64)
    assert wide.budget.fits and not wide.wrong.any()


def test_narrow_registers_exact_within_budget():
    rng = np.random.default_rng(20)
    checked = 0
    for xy in rng.uniform(0, 30, size=(200, 3, 2)):
        tri = tr.Triangle(xy)
        r = fp.narrow_fill(tri, 30, 30, int_bits=32, block_sizes=(16, 4))
        assert r.budget.fits
        np.testing.assert_array_equal(r.coverage, r.exact)
        checked += 1
    assert checked == 200


def test_narrow_walk_on_a_gpu_grid():
    """Review r235 S2: ``centre_bit=False`` walks on a GPU's 2**s units a pixel (Direct3D's
    16.8, llvmpipe's FIXED_ORDER): every value the package's divided by 4, so the exact walk is
    the same coverage and the budget is §4's count (a 320-px triangle there: 36 bits, as a
    160-px one on the package's 512 units). Whole pixels (s = 0) have no centres on that grid."""
    tri = tr.Triangle(np.array([[3.2, 6.4], [312.6, 18.8], [62.8, 312.6]]))
    gpu = fp.narrow_fill(tri, 320, 320, int_bits=32, block_sizes=(16, 4), centre_bit=False)
    np.testing.assert_array_equal(gpu.exact, tr.rasterize(tri, 320, 320).coverage)
    assert gpu.budget.units_per_pixel == 256 and gpu.budget.needed == 36
    assert (gpu.coverage & ~gpu.exact).any() and (gpu.exact & ~gpu.coverage).any()
    ours = fp.narrow_fill(tri, 320, 320, int_bits=32, block_sizes=(16, 4))
    assert ours.budget.units_per_pixel == 512 and ours.budget.needed == 38
    assert fp.bit_budget(320, 8, 32, centre_bit=False).needed == 36
    with pytest.raises(ValueError, match="sub-pixel bit"):
        fp.narrow_fill(tr.Triangle([[0, 0], [4, 0], [0, 4]]), 8, 8, subpixel_bits=0,
                       centre_bit=False)  # fmt: skip


# -- bad input -----------------------------------------------------------------------------------
@pytest.mark.parametrize("sizes", [(64, 16, 5), (0,), (), (16, 16), (4, 8), (-4,)])
def test_bad_block_sizes_name_the_argument(sizes):
    with pytest.raises(ValueError, match="block_sizes"):
        tiled([[0, 0], [4, 0], [0, 4]], 8, 8, block_sizes=sizes)


@pytest.mark.parametrize("sizes", ["64", 4, (4.5,), (True,), None])
def test_block_sizes_of_wrong_type(sizes):
    with pytest.raises(TypeError, match="block_sizes"):
        tiled([[0, 0], [4, 0], [0, 4]], 8, 8, block_sizes=sizes)


def test_numpy_block_sizes_are_accepted():
    xy = [[0.2, 0.1], [7.7, 0.4], [0.3, 6.6]]
    np.testing.assert_array_equal(
        raster(xy, 8, 8, method="tiled", block_sizes=np.array([4, 2])), raster(xy, 8, 8)
    )


def test_least_needed_is_the_area_bound():
    """Review r60 06-1: E is twice a triangle's signed area, so over a square of side M its
    largest |E| is M**2 (three corners reach it), not the term-by-term 2·M**2: Direct3D's 16.8
    over 2**16 px needs 49 bits with the sign, not 50, and 48 are too few."""
    import itertools

    def edge(a, b, p):
        return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])

    for side in range(1, 6):  # every triple of grid points in a small square
        pts = list(itertools.product(range(side + 1), repeat=2))
        assert max(abs(edge(*t)) for t in itertools.product(pts, repeat=3)) == side**2
    d3d = fp.range_budget(2**16, subpixel_bits=8)
    m = d3d.max_delta
    assert m == 2**24 - 1
    # E is affine in each point: its extremes over the square lie at the corners
    corners = list(itertools.product((0, m), repeat=2))
    largest = max(abs(edge(*t)) for t in itertools.product(corners, repeat=3))
    assert largest == m**2 and 2**47 < largest < 2**48
    assert (d3d.needed, d3d.least_needed, d3d.area_bits) == (50, 49, 48)
    for extent in (1, 5, 64, 1024, 2**16):  # never more than the term-by-term count, less one
        for budget in (fp.bit_budget(extent, 8), fp.range_budget(extent, 8)):
            assert budget.least_needed <= budget.needed - 1
            assert budget.max_delta**2 < 2 ** (budget.least_needed - 1)


def test_fixed_point_bad_input():
    tri = tr.Triangle([[0, 0], [4, 0], [0, 4]])
    with pytest.raises(ValueError, match="int_bits"):
        fp.narrow_fill(tri, 8, 8, int_bits=24)
    with pytest.raises(ValueError, match="subpixel_bits"):
        fp.narrow_fill(tri, 8, 8, subpixel_bits=None)
    with pytest.raises(TypeError, match="tri"):
        fp.narrow_fill([[0, 0], [4, 0], [0, 4]], 8, 8)
    with pytest.raises(ValueError, match="extent_px"):
        fp.bit_budget(0)
    with pytest.raises(ValueError, match="traversal"):
        tv.traversal_order((2, 2), "hilbert")


@pytest.mark.bench
def test_tiles_benchmark_quick_run_succeeds(capsys):
    """The benchmark script runs (speed itself is never asserted)."""
    import importlib.util
    import sys
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "benchmarks" / "bench_tiles.py"
    spec = importlib.util.spec_from_file_location("bench_tiles", path)
    module = importlib.util.module_from_spec(spec)
    sys.modules["bench_tiles"] = module
    spec.loader.exec_module(module)
    assert module.main(["--quick", "--repeat", "1"]) == 0
    out = capsys.readouterr().out
    assert "counters: 64×64" in out and "tests per pixel" in out


def test_a_partial_block_beyond_the_box_tests_and_shows_all_its_pixels():
    """Review r23 (00's player, tiles): a 4×4 block reaching out of the bounding box ran 16
    pixel tests, but the picture greyed only those inside the box. Review r77 00-2: the
    trace gives every one of them (rejected_at over the whole image), the caption says how
    many lie outside the box."""
    tri = tr.Triangle([[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]])
    trace = tr.rasterize(tri, 16, 16, method="tiled", trace=True).trace
    captions = [trace.caption(k) for k in range(trace.first_work_step, trace.interpolation_step)]
    assert any("16 pixel tests (10 of them outside the bounding box)" in c for c in captions)
    k = next(k for k in range(len(trace)) if "outside the bounding box" in trace.caption(k))
    b = trace.blocks
    i = k - trace.first_work_step
    r0, c0 = b.row[i], b.col[i]
    block = (slice(r0, r0 + b.extent[i, 0]), slice(c0, c0 + b.extent[i, 1]))
    tested = trace.rejected_at(k)[block] | trace.coverage_at(k)[block]
    assert tested.all()  # all 16, also the 10 outside the box
    assert trace.rejected_at(-1).sum() > trace.image(~trace.covered, fill=False).sum()
    # recording changes nothing: the same coverage with and without the trace
    np.testing.assert_array_equal(
        tr.rasterize(tri, 16, 16, method="tiled").coverage, trace.coverage_at(-1)
    )
    assert any(c.endswith("16 pixel tests, 15 covered") for c in captions)  # all inside


def test_an_accepted_1x1_block_says_its_pixel_test_passed():
    """Review r176 10-1: the caption of an accepted 1×1 block said "1 pixel filled with no pixel
    test", while lesson 10 (cell 6) and the counters count that corner test as the pixel test
    (pixel_tests = every 1×1 block; pixels_accepted = pixels of larger accepted blocks only).
    A larger accepted block still fills its pixels with no test of their own."""
    xy = [[3.3, 2.1], [60.2, 14.7], [20.9, 58.4]]  # lesson 10's triangle
    fill = tr.rasterize(tr.Triangle(xy), 64, 64, method="tiled", block_sizes=(16, 4, 1), trace=True)
    b, edges = fill.trace.blocks, fill.trace.edges
    accepted = b.kind_code == 1
    ones = [b.caption(k, edges) for k in np.flatnonzero(accepted & (b.size == 1))]
    larger = [b.caption(k, edges) for k in np.flatnonzero(accepted & (b.size > 1))]
    assert ones and larger
    assert all("its pixel test passed, the pixel is written" in c for c in ones)
    assert not any("no pixel test" in c for c in ones)
    assert all("filled with no pixel test" in c and "passed" not in c for c in larger)
    # the counters agree with the words: each accepted 1x1 block is one of the pixel tests
    c = b.counters
    assert c.pixel_tests == c.empty[-1] + c.full[-1] and len(ones) == c.full[-1]
    assert c.pixels_accepted == int(fill.coverage.sum()) - len(ones)
