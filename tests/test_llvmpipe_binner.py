"""llvmpipe's binning choices re-enacted (teachraster.study.llvmpipe_binner), Greene's depth
pyramid (teachraster.pipeline.visibility.depth_pyramid) and the bit budget on a GPU's own
grid (fixed_point.max_range): the functions lesson 10 calls instead of reproducing them."""

import numpy as np
import pytest

import teachraster as tr
from teachraster.core import fixed_point
from teachraster.pipeline.visibility.depth_pyramid import (
    box_test,
    farthest_pyramid,
    greene_descent,
)
from teachraster.study import llvmpipe_binner as lb


def test_max_range_is_mesa_max_fixed_length32_on_the_gpu_grid():
    # lp_rast.h: MAX_FIXED_LENGTH32 = 1 << ((32/2 - 1) - FIXED_ORDER) = 128 px
    assert lb.MAX_FIXED_LENGTH32 == fixed_point.max_range(8, 32) == 128
    for bits in (32, 64):
        for centre in (False, True):
            r = fixed_point.max_range(8, bits, centre_bit=centre)
            assert fixed_point.range_budget(r, 8, bits, centre_bit=centre).fits
            assert not fixed_point.range_budget(r + 1, 8, bits, centre_bit=centre).fits
    assert fixed_point.max_range(8, 32, centre_bit=True) == 64 == fixed_point.max_extent(8, 32) + 1
    assert fixed_point.max_range(8, 16) == 0  # nothing fits: not rounded up to a pixel


def test_steps_in_32_bits_reads_the_box_from_its_4_aligned_start():
    assert lb.steps_in_32_bits(0, 127, 0, 127) and not lb.steps_in_32_bits(2, 129, 0, 127)
    assert lb.steps_in_32_bits(4, 131, 0, 0) and not lb.steps_in_32_bits(0, 129, 0, 0)
    assert lb.steps_in_32_bits(0, 128, 0, 0)  # Mesa's test is <=
    # review r189 10-2: x | y, not max(x, y): 128 passes only beside 0 or 128
    assert lb.steps_in_32_bits(0, 128, 0, 128) and not lb.steps_in_32_bits(0, 128, 0, 127)


def test_floor_pot():
    assert [lb.floor_pot(n) for n in (0, 1, 2, 3, 64, 127, 128)] == [0, 1, 2, 2, 64, 64, 128]


@pytest.mark.parametrize(
    ("xy", "command"),
    [
        ([[1.2, 1.2], [3.4, 1.2], [1.2, 3.4]], "TRIANGLE_3_4"),
        ([[100.3, 100.2], [102.3, 100.2], [100.3, 102.2]], "TRIANGLE_3_16"),
        ([[100.3, 100.2], [116.3, 100.2], [100.3, 116.2]], "its one tile, from the 16x16 blocks"),
        ([[60.3, 10.2], [70.3, 10.2], [60.3, 20.2]], "the tile walk (§9)"),
    ],
)
def test_small_triangle_command(xy, command):
    got, (x0, x1), blocks, pixels = lb.small_triangle_command(xy)
    assert got == command and x0 <= x1
    if command == "TRIANGLE_3_4":
        assert (blocks, pixels) == (0, 16)
    elif command == "TRIANGLE_3_16":
        assert blocks == 16 and pixels % 16 == 0 and 16 <= pixels <= 256
    else:
        assert blocks is None and pixels is None


def test_triangle_3_16_keeps_every_block_the_exact_corner_test_keeps():
    # llvmpipe's cautious corners (one step beyond) keep a superset of the exact test's blocks
    xy = [[100.3, 100.2], [102.3, 100.2], [100.3, 102.2]]
    _, _, _, pixels = lb.small_triangle_command(xy)
    fill = tr.rasterize(tr.Triangle(xy), 512, 512, method="tiled", trace=True)
    assert pixels >= fill.trace.blocks.counters.pixel_tests == 16


def test_bin_rows_agrees_with_the_walk_but_for_its_cautious_corners():
    xy = [[20.5, 12.2], [500.3, 70.7], [140.8, 310.1]]
    fill = tr.rasterize(tr.Triangle(xy), 512, 320, method="tiled", trace=True)
    blocks = fill.trace.blocks
    kinds = lb.bin_rows(fill.trace.snapped, *blocks.grids[0])
    assert set(np.unique(kinds)) <= set(lb.TILE_KINDS)
    top = blocks.level == 0
    walk = np.empty(blocks.grids[0], dtype=object)
    walk[blocks.row[top] // 64, blocks.col[top] // 64] = blocks.kind[top]
    binned = np.isin(kinds, ["full", "partial"])
    assert ((walk == "accepted") == (kinds == "full")).all()
    assert (binned | (walk == "rejected")).all()  # every tile the walk keeps is binned
    # a row ends at its first outside tile after the triangle: nothing tested after it
    for row in kinds:
        if "exit" in row.tolist():
            k = row.tolist().index("exit")
            assert set(row[k + 1 :]) <= {"untested"}


def test_farthest_pyramid_and_box_test():
    base = np.arange(16, dtype=float).reshape(4, 4) / 16
    pyr = farthest_pyramid(base, 2)
    assert [p.shape for p in pyr] == [(4, 4), (2, 2), (1, 1)]
    assert pyr[1][0, 0] == base[:2, :2].max() and pyr[2][0, 0] == base.max()
    tests = box_test(pyr, (0, 0, 0, 1), nearest=base[0, :2].max())
    assert [t.level for t in tests] == [2, 1, 0] and [t.cells for t in tests] == [1, 1, 2]
    assert [t.hidden for t in tests] == [False, False, True]  # only the finest is sharp enough
    # a level is never sharper than the one below it: hidden above means hidden below
    rng = np.random.default_rng(3)
    for _ in range(50):
        pyr = farthest_pyramid(rng.random((8, 8)), 3)
        r0, c0 = rng.integers(0, 8, 2)
        r1, c1 = r0 + rng.integers(0, 8 - r0), c0 + rng.integers(0, 8 - c0)
        verdicts = [t.hidden for t in box_test(pyr, (r0, r1, c0, c1), rng.random())]
        assert verdicts == sorted(verdicts)
    with pytest.raises(ValueError):
        farthest_pyramid(np.zeros((6, 4)), 2)


def test_greene_descent_goes_down_only_under_failing_values():
    """Review r189 10-3: Greene's test goes down a level only where it fails. The descent
    starts at the finest level one value covers; below it, it reads exactly the children (in
    the box) of the values that failed a level up, and its verdict is the base's."""
    rng = np.random.default_rng(7)
    for _ in range(200):
        pyr = farthest_pyramid(rng.random((8, 8)), 3)
        r0, c0 = rng.integers(0, 8, 2)
        r1, c1 = r0 + rng.integers(0, 8 - r0), c0 + rng.integers(0, 8 - c0)
        near = rng.random()
        steps = greene_descent(pyr, (r0, r1, c0, c1), near)
        first = steps[0]
        one = [k for k in range(4) if r0 >> k == r1 >> k and c0 >> k == c1 >> k]
        assert first.level == (min(one) if one else 3) and (first.cells == 1) == bool(one)
        assert steps[-1].hidden == box_test(pyr, (r0, r1, c0, c1), near)[-1].hidden
        # brute force: the in-box cells of each level whose parent fails
        inbox = np.zeros((8, 8), bool)
        inbox[r0 : r1 + 1, c0 : c1 + 1] = True
        for above, step in zip(steps, steps[1:]):
            k = step.level
            box_k = inbox.reshape(8 >> k, 1 << k, 8 >> k, 1 << k).any(axis=(1, 3))
            fails_up = np.repeat(np.repeat(pyr[k + 1] > near, 2, 0), 2, 1)
            assert step.cells == int((box_k & fails_up).sum()) and not above.hidden
        assert all(not s.hidden for s in steps[:-1]) and (steps[-1].hidden or steps[-1].level == 0)
