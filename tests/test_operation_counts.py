"""The operation-count cost model of lesson 06 and the meshes that crack."""

import numpy as np
import pytest

import teachraster as tr
from teachraster.study import operation_counts as ops


def test_interpolation_counts_follow_the_formulas():
    affine, persp = ops.interpolation_count("affine"), ops.interpolation_count("perspective")
    assert (affine.divides, persp.divides) == (0, 1)
    for n in (2, 4, 8, 16, 32):
        sub = ops.interpolation_count(f"subdivided N={n}")
        assert sub.divides == 1 / n and affine.additions < sub.additions
        assert ops.cycles(affine) < ops.cycles(sub) < ops.cycles(persp)
    with pytest.raises(ValueError):
        ops.interpolation_count("cubic")
    with pytest.raises(ValueError, match="attributes"):
        ops.interpolation_count("affine", attributes=0)


def test_interpolation_prices_u_and_v():
    """Review r48 06-D1: the study measures the uv error, so the model prices both texture
    coordinates (k = 2) sharing one reciprocal: d + mk + (k + 1) cycles, 24 at the Pentium's
    prices (r228 F1: its issue intervals), 12x affine's 2; 13 at a current GPU's (r238 S3)."""
    prices = ops.PENTIUM_CYCLES  # one unit: the cycles add
    d, m = prices["divides"], prices["multiplies"]
    for k in (1, 2, 16):
        persp = ops.cycles(ops.interpolation_count("perspective", k), prices)
        assert persp == d + m * k + (k + 1)
        assert ops.cycles(ops.interpolation_count("affine", k), prices) == k
        for n in (2, 16):
            sub = ops.cycles(ops.interpolation_count(f"subdivided N={n}", k), prices)
            assert sub == pytest.approx(k + (d + m * 2 * k + 2 * k + 1) / n)
    # review r252 F1: the GPU's reciprocal runs on the special-function unit beside the FMA
    # pipe, costing it one issue slot: a pixel costs the slower unit, not the sum
    gpu = ops.GPU_CYCLES
    d, i = gpu["divides"], gpu["divide issue"]
    for k in (1, 2, 16):
        persp = ops.cycles(ops.interpolation_count("perspective", k), gpu)
        assert persp == max(d, 2 * k + 1 + i)
        for n in (2, 16):
            sub = ops.cycles(ops.interpolation_count(f"subdivided N={n}", k), gpu)
            assert sub == pytest.approx(max(d / n, k + (4 * k + 1 + i) / n))
    assert ops.cycles(ops.interpolation_count("perspective")) == 24
    assert ops.cycles(ops.interpolation_count("perspective"), ops.GPU_CYCLES) == 8  # not 13
    assert ops.cycles(ops.interpolation_count("perspective", 16), ops.GPU_CYCLES) == 34


def test_the_price_lists_are_read_from_their_tables():
    """Review r228 C1/F1: the Pentium's weights are its x87 issue intervals (Agner Fog's
    tables: FADD, FMUL 3 cycles, FDIV 19/33/39, the last 2 overlapping the next
    floating-point instruction; an FMUL not in the cycle after another), FDIV at single
    precision. r238 S3: the GPU's are NVIDIA's throughput rows for the current GPUs (8.6 to
    9.0), the reciprocal at an eighth of the multiply-add rate there, a quarter from Maxwell
    to Turing and on the A100 (a sixth on Kepler). r238 F1/F2: the Pentium's integer unit
    prices integer work: IMUL r32 9, IDIV r32 46 (DIV 41), a 64-bit addition ADD + ADC."""
    for name, (cycles, issue) in ops.PENTIUM_X87.items():
        assert issue == (2 if name == "FMUL" else cycles - 2), name
    assert ops.PENTIUM_CYCLES == {"divides": 17.0, "multiplies": 2.0, "additions": 1.0}
    assert ops.PENTIUM_INTEGER == {"ADD": 1, "IMUL r32": 9, "DIV r32": 41, "IDIV r32": 46}
    assert ops.PENTIUM_INTEGER_CYCLES == {"divides": 46.0, "multiplies": 9.0, "additions": 1.0,
                                          "wide additions": 2.0}  # fmt: skip
    ratio = {g: fma // rcp for g, (fma, rcp) in ops.NVIDIA_RATES.items()}
    assert list(ratio.values()) == [6, 4, 4, 4, 4, 4, 8, 8, 8]
    assert ratio[ops.GPU_NOW] == 8 == ops.GPU_CYCLES["divides"]
    assert ops.GPU_CYCLES["multiplies"] == ops.GPU_CYCLES["additions"] == 1  # one FMA pipe
    assert ops.GPU_CYCLES["divide issue"] == 1  # the reciprocal's slot on it (r252 F1)
    assert list(ops.PRICES) == ["Pentium (P5)", "GPU (Ampere GA10x, Ada, Hopper)"]


def test_edge_counts_and_bits():
    direct, inc = ops.edge_count("fixed8 direct"), ops.edge_count("fixed8 incremental")
    assert (direct.multiplies, direct.additions, inc.multiplies, inc.additions) == (6, 9, 0, 3)
    assert ops.edge_count("float32 direct").bits == 24 < ops.edge_bits_needed(512, 1e6)
    assert ops.edge_count("fixed8 direct").bits >= ops.edge_bits_needed(2048, 1e6)
    assert ops.edge_bits_needed(16, 1_000_000) == 29  # the position dominates (20 + 8 + sign)
    # r238 F2: the same operations, priced as each arithmetic runs on the Pentium: fixed point
    # on its integer unit (6 IMULs, 6 32-bit and 3 64-bit additions), floats on its FPU
    assert direct.integer and direct.wide == inc.wide == 3
    assert ops.cycles(direct) == 6 * 9 + 6 * 1 + 3 * 2 == 66 and ops.cycles(inc) == 6
    floats = ops.edge_count("float64 direct")
    assert not floats.integer and floats.wide == 0 and ops.cycles(floats) == 6 * 2 + 9 == 21
    assert ops.cycles(ops.edge_count("unsnapped incremental")) == 3


def test_edge_bits_are_counted_once_for_lessons_06_and_10():
    """Review r28 06-3: lesson 06 printed 51 bits for Direct3D's 16.8 over 2^16 px (a sign
    counted twice), lesson 10's rule gave another number. One count, in core/fixed_point:
    24-bit coordinates differ by less than 2^24 units, a product is below 2^48, the
    difference of two products below 2^49: 50 bits with the sign."""
    from teachraster.core import fixed_point as fp

    d3d = fp.range_budget(2**16, subpixel_bits=8)
    assert (d3d.delta_bits, d3d.product_bits, d3d.edge_bits, d3d.needed) == (24, 48, 49, 50)
    assert ops.edge_bits_needed(2**16, 0, subpixel_bits=8) == 50 == d3d.needed
    # review r60 06-1: E's own bound (twice a triangle's area) is one bit fewer
    assert ops.edge_bits_needed(2**16, 0, subpixel_bits=8, least=True) == 49 == d3d.least_needed
    # the term-by-term bounds, computed: differences of 24-bit coordinates, their products, and
    # two products of opposite signs (which E itself, twice an area, never reaches: test_tiles)
    lo, hi = -(2**23), 2**23 - 1  # 16.8 two's complement: [-2^15, 2^15) px
    biggest = (hi - lo) * (hi - lo) + (hi - lo) * (hi - lo)
    assert (hi - lo).bit_length() == 24 and (hi - lo) ** 2 < 2**48 and biggest < 2**49
    # the study's mesh: coordinates in a 512-px range, 17-bit differences, 36 bits
    assert ops.edge_bits_needed(512, 0) == 36 == ops.edge_bits_needed(512, 1e6)
    # lesson 10's guard band with teachraster's centre bit: differences below 2^31 units, 64
    band = fp.range_budget(2 * 2**21, 8, centre_bit=True)
    assert band.delta_bits == 31 and band.needed == 64 and band.fits
    assert "below 65,536 px: at most 16,777,215 units < 2^24" in d3d.lines()[1]
    assert "8 sub-pixel bits = 256 units per pixel" in d3d.lines()[0]
    with pytest.raises(ValueError):
        ops.edge_count("float16 direct")


def test_fill_counts_scale_with_the_box_and_the_rows():
    hp, sp = ops.fill_count("halfplane 64²"), ops.fill_count("span+trace 64²")
    filled = tr.rasterize(ops.bench.fill_triangle(64), 64, 64, trace=True)
    box, covered = filled.trace.bbox, int(filled.coverage.sum())
    rows = box.row1 - box.row0
    # review r28 06-2: both loops pay their loop work (x += 1, x < end: 2 per visited pixel,
    # 2 per raster line); half-planes 3 steps and 3 tests per box centre, 3 per line
    assert hp.additions == 8 * box.size + 5 * rows and hp.divides == 0
    assert sp.divides == 1 + 2 * rows and sp.additions == 6 * rows + 2 * covered
    # r238 F1: integer work, as the simulator fills (exact): the half-planes' steps add 64-bit
    # edge values, a crossing's numerator is 64-bit; an IDIV and an IMUL per crossing
    assert hp.integer and sp.integer and hp.wide == 3 * box.size + 3 * rows and sp.wide == 2 * rows
    assert ops.cycles(ops.HALFPLANE_CENTRE) == 11 and ops.cycles(ops.SPAN_PIXEL) == 2
    assert ops.cycles(ops.SPAN_CROSSING) == 46 + 9 + 1 + 2
    assert ops.cycles(sp) == 46 * sp.divides + 9 * sp.multiplies + sp.additions + sp.wide
    assert ops.cycles(sp) < ops.cycles(hp)
    # the ratio grows with size towards 11 per box centre over 2 per covered pixel
    ratio = {n: ops.cycles(ops.fill_count(f"halfplane {n}²")) / ops.cycles(ops.fill_count(
        f"span {n}²")) for n in (64, 256, 1024)}  # fmt: skip
    assert ratio[64] < ratio[256] < ratio[1024] < 11 / 2 * box.size / covered * 1.05


def test_with_counts_adds_columns_to_every_row():
    rows = [{"group": "interpolation", "variant": "affine"},
            {"group": "depth", "variant": "window unorm16"}]  # fmt: skip
    out = ops.with_counts(rows)
    assert (
        out[0]["cycles"] == ops.ATTRIBUTES == 2 and out[1]["bits"] == 16 and "cycles" not in rows[0]
    )
    assert ops.with_counts(rows, {"divides": 0, "multiplies": 0, "additions": 2})[0]["cycles"] == 4
    assert out[0]["integer"] is False and out[0]["wide"] == 0


def test_tie_mesh_is_watertight_and_on_pixel_centres():
    mesh = ops.tie_mesh(24, cells=3)
    assert np.all((mesh - 0.5) % 1 == 0)
    counts = sum(tr.rasterize(tr.Triangle(t), 24, 24).coverage.astype(int) for t in mesh)
    assert counts.max() == 1


def test_only_an_inconsistent_tie_rule_cracks_the_mesh():
    mesh = ops.tie_mesh(24, cells=3)
    good = ops.crack_counts(mesh, 24, 24, "top-left")
    assert good["gaps"] == good["double_hits"] == 0
    # the rule of ops equals the package's own coverage, triangle by triangle
    for t in mesh:
        assert np.array_equal(ops.rule_coverage(t, 24, 24, "top-left"),
                              tr.rasterize(tr.Triangle(t), 24, 24).coverage)  # fmt: skip
    assert ops.crack_counts(mesh, 24, 24, "E >= 0")["double_hits"] > 0
    assert ops.crack_counts(mesh, 24, 24, "E > 0")["gaps"] > 0
    with pytest.raises(ValueError, match="rule"):
        ops.rule_coverage(mesh[0], 4, 4, "E != 0")


def test_cracks_are_counted_inside_the_outline_only():
    # The outline is decided by the neighbouring mesh: E > 0 leaves exactly the shared-edge
    # centres open that E >= 0 draws twice, and neither count includes the outline.
    mesh = ops.tie_mesh(24, cells=3)
    ge, gt = ops.crack_counts(mesh, 24, 24, "E >= 0"), ops.crack_counts(mesh, 24, 24, "E > 0")
    assert ge["double_hits"] == gt["gaps"] > 0 and ge["gaps"] == gt["double_hits"] == 0
    outline = ops.outline_centres(mesh, 24, 24)
    assert np.array_equal(outline, ge["outline"])
    # the tie mesh is a square whose corners are on centres: its outline is the square's border
    lo, hi = int(mesh.min()), int(mesh.max())
    side = hi - lo + 1
    assert outline.sum() == 4 * (side - 1)
    assert (gt["counts"][outline] == 0).all()  # E > 0 leaves the outline to the neighbour


def test_depth_rows_carry_the_bits_they_store():
    rows = [{"group": "depth", "variant": f"window {f}"} for f in ops.DEPTH_STORED_BITS]
    stored = {r["variant"].split()[1]: r["stored_bits"] for r in ops.with_counts(rows)}
    assert stored == {"float64": 64, "float32": 32, "unorm24": 32, "unorm16": 16}  # r53 06-1
    precision = {r["variant"].split()[1]: r["bits"] for r in ops.with_counts(rows)}
    assert precision["float32"] == precision["unorm24"] == 24  # the same step near depth 1
