"""What each variant of the accuracy study costs in operations, and meshes that crack.

Wall-clock time of numpy code is a poor cost model: numpy pays per array pass, not per
arithmetic operation, and the order of close variants changes between runs. Lesson 06 therefore
counts what a scalar rasteriser would execute, per pixel, for each variant of
:mod:`teachraster.study.bench`: **divides**, **multiplies** and **additions** (subtractions and
comparisons count as additions), and the **bits of precision** the arithmetic keeps. The counts
follow from the formulas, not from timing:

- *interpolation* (floating point), per pixel along a span, the texture's :data:`ATTRIBUTES`
  ``k = 2`` attributes ``u`` and ``v`` (the study measures the error of both): affine steps
  each (``k`` additions); perspective-correct steps ``u/w``, ``v/w`` and ``1/w`` (``k + 1``
  additions), takes one reciprocal of ``1/w`` and multiplies each attribute by it (1 divide,
  ``k`` multiplies); subdivided by ``N`` does that only at an anchor, every ``N``-th pixel,
  turns each attribute's change since the last anchor into a per-pixel step (``k``
  subtractions, ``k`` multiplies by ``1/N``) and steps ``u`` and ``v`` affinely in between
  (per pixel: ``1/N`` divides, ``2k/N`` multiplies, ``k + (2k + 1)/N`` additions);
- *edge functions*, per tested pixel, three edges: direct
  ``E = (b_x - a_x)(p_y - a_y) - (b_y - a_y)(p_x - a_x)`` with the edge's differences set up
  once (2 multiplies, 3 additions per edge), incremental one addition per edge; in floating
  point, or in integers for the fixed-point variants;
- *fill* (integers, as the simulator fills: exact), per triangle, both loops counted alike:
  every pixel a loop visits costs its loop work, ``x += 1`` and ``x < x_end`` (2 additions),
  and every raster line ``y += 1`` and ``y < y_end`` (2 additions). Half-planes visit every
  centre of the bounding box and step it incrementally (3 additions and 3 comparisons per
  centre, 3 additions per raster line to step the row's start); the span loop (lesson 01's)
  computes ``u4`` (1 divide) and two crossings per raster line (1 divide, 1 multiply, 2
  additions each: an integer floor division, ``core/span_tables.py``) and visits the covered
  pixels only, with no test;
- *depth*: one comparison per fragment; the format sets the bits stored.

Integer work is also counted by width (:attr:`OpCount.wide`): on a 32-bit machine an
addition of values wider than 32 bits takes two instructions. Coordinates on the 1/256 px
grid and their differences fit 32 bits; a product of two differences needs 64 (one
32 × 32-bit multiply gives it), and so does everything summed from products: an edge
function's value, its steps, a crossing's numerator.

Price lists weight the counts, in *issue cycles*: how many cycles an operation keeps its unit
from starting the next one. :data:`PENTIUM_CYCLES` is the Pentium's (P5) x87 FPU, the machine
Quake was written for (:data:`PENTIUM_X87`, Agner Fog's measured tables), and
:data:`PENTIUM_INTEGER_CYCLES` its integer unit (:data:`PENTIUM_INTEGER`), which prices the
integer variants; :data:`GPU_CYCLES` a current NVIDIA GPU's (Ampere GA10x, Ada, Hopper),
whose add, multiply and multiply-add issue at one rate and whose reciprocal at an eighth of
it (:data:`NVIDIA_RATES`, the CUDA guide's throughput table) on a unit of its own, in
parallel with them: a pixel costs the slower unit's cycles, not their sum. A GPU list prices floating-point
shader work only: a GPU evaluates edge functions in its fixed-function rasteriser.
:func:`cycles` applies any weights (the Pentium's by default, integer or float by the
variant's arithmetic).

:func:`tie_mesh` and :func:`crack_counts` build a watertight mesh whose shared edges pass
through pixel centres and count the pixels a coverage rule leaves uncovered (gaps) or covers
twice (double hits): the top-left rule gives none, ``E >= 0`` double hits, ``E > 0`` gaps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..core import fixed_point
from ..core.fill import rasterize
from ..core.triangle import Triangle
from . import bench
from .bench.groups import triangulate_grid

#: The Pentium's (P5, 1993) x87 instructions: (clock cycles, issue interval), from Agner
#: Fog's *How to optimize for the Pentium family of microprocessors*, its table of
#: floating-point instructions: FADD, FMUL 3 clock cycles and FDIV 19, 33 or 39 at single,
#: double or extended precision, each overlapping the next floating-point instruction by
#: its last 2 cycles ("fp-ov"), except that an FMUL cannot start in the cycle after another
#: FMUL. The issue interval is what is left: the cycles before the FPU can start another
#: floating-point instruction (the next FMUL, for an FMUL). An FDIV holds the whole FPU:
#: no floating-point instruction starts during its issue interval (integer ones do).
PENTIUM_X87 = {"FADD": (3, 1), "FMUL": (3, 2), "FDIV single": (19, 17), "FDIV double": (33, 31),
               "FDIV extended": (39, 37)}  # fmt: skip
#: Weights of :func:`cycles` for floating-point work: the P5's issue intervals
#: (:data:`PENTIUM_X87`), an FADD each cycle, an FMUL every 2, an FDIV every 17 at single
#: precision, the precision Quake set before drawing ("make FDIV fast",
#: ``Sys_LowFPPrecision`` in ``R_RenderView_``, ``r_main.c``).
PENTIUM_CYCLES = {
    "divides": float(PENTIUM_X87["FDIV single"][1]),
    "multiplies": float(PENTIUM_X87["FMUL"][1]),
    "additions": float(PENTIUM_X87["FADD"][1]),
}
#: The P5's integer instructions a 32-bit loop needs for the study's integer arithmetic, in
#: clock cycles, from the same manual's list of integer instructions: ADD (and ADC) 1;
#: IMUL r32 9, a 32 × 32-bit product, 64 bits in EDX:EAX; IDIV r32 46, EDX:EAX divided by a
#: 32-bit value (DIV, unsigned, 41); IMUL and IDIV do not pair.
PENTIUM_INTEGER = {"ADD": 1, "IMUL r32": 9, "DIV r32": 41, "IDIV r32": 46}
#: Weights of :func:`cycles` for integer work on the P5 (:data:`PENTIUM_INTEGER`): an
#: addition 1, a 64-bit one 2 (ADD, then ADC, which reads ADD's carry and so cannot pair
#: with it), a multiply an IMUL, a divide an IDIV (signed: edge values and crossings have
#: signs). Pairing of two simple instructions in one cycle is left out, for every variant.
PENTIUM_INTEGER_CYCLES = {
    "divides": float(PENTIUM_INTEGER["IDIV r32"]),
    "multiplies": float(PENTIUM_INTEGER["IMUL r32"]),
    "additions": float(PENTIUM_INTEGER["ADD"]),
    "wide additions": 2.0 * PENTIUM_INTEGER["ADD"],
}
#: NVIDIA's *CUDA C++ Programming Guide*, table "Throughput of Native Arithmetic Instructions"
#: (results per clock cycle per multiprocessor): the rows "32-bit floating-point add,
#: multiply, multiply-add" and "32-bit floating-point reciprocal, reciprocal square root, ...",
#: by compute capability (Kepler and Maxwell as in the edition copied as nvidia_throughput.txt
#: in PCSX2's GSdx renderer, Pascal to Turing as in the CUDA 10 edition's table, Ampere to
#: Hopper as in the CUDA 12 edition's). From 8.6 on the multiply-add rate doubled and the
#: reciprocal's did not.
NVIDIA_RATES = {"Kepler (3.x, 2012)": (192, 32), "Maxwell (5.x, 2014)": (128, 32),
                "Pascal GP100 (6.0, 2016)": (64, 16), "Pascal GP10x (6.1, 2016)": (128, 32),
                "Volta, Turing (7.x, 2017-18)": (64, 16), "Ampere A100 (8.0, 2020)": (64, 16),
                "Ampere GA10x (8.6, 2020)": (128, 16), "Ada (8.9, 2022)": (128, 16),
                "Hopper (9.0, 2022)": (128, 16)}  # fmt: skip
#: The GPU generations :data:`GPU_CYCLES` prices: the current ones.
GPU_NOW = "Ada (8.9, 2022)"
#: A GPU's prices in issue cycles (Ampere GA10x, Ada and Hopper, :data:`NVIDIA_RATES`): an
#: addition, a multiply or a multiply-add 1 on the multiply-add (FMA) pipe, a reciprocal 8
#: (its rate is an eighth of theirs; a quarter from Maxwell to the A100). A divide of the
#: model is that reciprocal, a special-function instruction (``MUFU.RCP``) that runs on the
#: special-function units, which each SM partition has beside its FP32 units (NVIDIA Ampere
#: GA102 whitepaper, the SM diagram): the dispatcher spends one issue slot on it
#: (``"divide issue"``) and the FMA pipe goes on while it runs, so :func:`cycles` prices a
#: pixel at the slower of the two units, not at their sum (the CUDA guide's throughput table,
#: §5.4.1 "Arithmetic Instructions", gives each class its own rate).
GPU_CYCLES = {
    "divides": NVIDIA_RATES[GPU_NOW][0] / NVIDIA_RATES[GPU_NOW][1],
    "multiplies": 1.0,
    "additions": 1.0,
    "divide issue": 1.0,
}
#: The two float price lists by the names the lesson and the DivideCostExplorer give them.
PRICES = {"Pentium (P5)": PENTIUM_CYCLES, "GPU (Ampere GA10x, Ada, Hopper)": GPU_CYCLES}
#: Bits of precision the arithmetic keeps: the significand of a float, a whole int64.
BITS_KEPT = {"fixed8": 63, "fixed4": 63, "float64": 53, "float32": 24, "unsnapped": 53}
DEPTH_BITS = {"float64": 53, "float32": 24, "unorm24": 24, "unorm16": 16}
#: Bits each depth format occupies per sample: a float's sign, exponent and significand, or the
#: unorm's integer, padded to the word a GPU stores it in. unorm24 takes 32 bits, its spare 8
#: holding stencil or padding (D24_UNORM_S8_UINT, X8_D24_UNORM_PACK32): no API stores 24 bits
#: per sample (review r53 06-1). No GPU offers float64 depth, the study's exact reference.
DEPTH_STORED_BITS = {"float64": 64, "float32": 32, "unorm24": 32, "unorm16": 16}
#: Attributes the interpolation group prices per pixel: the texture coordinates u and v, the
#: two whose error the study measures (pricing one, u, while measuring both made
#: perspective-correct look 35x affine instead of about 20x: review r48 06-D1).
ATTRIBUTES = 2
RULES = ("top-left", "E >= 0", "E > 0")
#: Fill loops: the loop work per visited pixel or raster line (``x += 1``, ``x < x_end``), and a
#: half-plane centre's 3 incremental steps and 3 sign tests (all counted as additions).
LOOP_ADDITIONS = 2.0
HALFPLANE_TESTS = 6.0


@dataclass(frozen=True)
class OpCount:
    """Operations per pixel (or per triangle for the fill group), and bits kept.

    ``integer`` says the arithmetic is integer (priced by :data:`PENTIUM_INTEGER_CYCLES`
    unless other weights are given); ``wide`` how many of the ``additions`` add values wider
    than 32 bits (two instructions each on a 32-bit machine).
    """

    divides: float
    multiplies: float
    additions: float
    bits: int | None = None
    per: str = "pixel"
    stored: int | None = field(default=None, repr=False)  # depth: bits stored per sample
    integer: bool = field(default=False, repr=False)
    wide: float = field(default=0.0, repr=False)


#: The fills' integer work. A half-plane fill per box centre: its 3 edge steps (64-bit edge
#: values: wide), 3 sign tests (the sign of one word) and the loop; per raster line the three
#: row starts stepped (wide) and the loop.
HALFPLANE_CENTRE = OpCount(0.0, 0.0, HALFPLANE_TESTS + LOOP_ADDITIONS, integer=True, wide=3.0)
HALFPLANE_LINE = OpCount(0.0, 0.0, 3.0 + LOOP_ADDITIONS, integer=True, wide=3.0)
#: The span loop per covered pixel: the loop only; per raster line: the loop; per crossing
#: computed afresh, lesson 01's exact one: the row's offset from the edge's start (an
#: addition), its product with the edge's run (a multiply, 64 bits), the tie's bias taken
#: off (a wide addition) and a floor division by the edge's rise (a divide).
SPAN_PIXEL = OpCount(0.0, 0.0, LOOP_ADDITIONS, integer=True)
SPAN_LINE = OpCount(0.0, 0.0, LOOP_ADDITIONS, integer=True)
SPAN_CROSSING = OpCount(1.0, 1.0, 2.0, integer=True, wide=1.0)
#: Blocked half-planes (lesson 10's walk, one block size): per block of the box's block grid,
#: each edge's value stepped to the block (3 wide additions), its two extreme corners from
#: it (6 wide additions: the corner trick's offsets), their 6 sign tests and the loop.
BLOCK_TEST = OpCount(0.0, 0.0, 3.0 + 6.0 + 6.0 + LOOP_ADDITIONS, integer=True, wide=9.0)
#: The block size of the blocked fill lesson 06 prices (Capens; Giesen's 8 x 8 blocks).
FILL_BLOCK = 8


def interpolation_count(variant: str, attributes: int = ATTRIBUTES) -> OpCount:
    """Operations per pixel of ``attributes`` interpolated attributes (see the module
    docstring); they share one reciprocal of ``1/w``.

    >>> interpolation_count("subdivided N=16")
    OpCount(divides=0.0625, multiplies=0.25, additions=2.3125, bits=53, per='pixel')
    """
    if isinstance(attributes, bool) or not isinstance(attributes, int):
        raise TypeError(f"attributes must be an int, got {attributes!r}")
    if attributes < 1:
        raise ValueError(f"attributes must be at least 1, got {attributes}")
    k = float(attributes)
    if variant == "affine":
        return OpCount(0.0, 0.0, k, 53)
    if variant == "perspective":
        return OpCount(1.0, k, k + 1.0, 53)
    if variant.startswith("subdivided N="):
        n = int(variant.split("=")[1])
        return OpCount(1.0 / n, 2.0 * k / n, k + (2.0 * k + 1.0) / n, 53)
    raise ValueError(f"unknown interpolation variant {variant!r}")


def edge_count(variant: str) -> OpCount:
    """Operations per tested pixel for three edge functions, and the bits kept.

    The fixed-point variants are integer work: per edge the two coordinate differences fit
    32 bits, the two products and E, their difference, need 64 (E's subtraction, or its
    step, is a wide addition).

    >>> edge_count("float32 incremental")
    OpCount(divides=0.0, multiplies=0.0, additions=3.0, bits=24, per='pixel')
    >>> cycles(edge_count("fixed8 direct")), cycles(edge_count("float64 direct"))
    (66.0, 21.0)
    """
    arith, evaluation = variant.split()
    if arith not in BITS_KEPT or evaluation not in ("direct", "incremental"):
        raise ValueError(f"unknown edge-function variant {variant!r}")
    integer = arith.startswith("fixed")
    wide = 3.0 if integer else 0.0  # one 64-bit addition per edge: E's subtraction or step
    if evaluation == "direct":
        return OpCount(0.0, 6.0, 9.0, BITS_KEPT[arith], integer=integer, wide=wide)
    return OpCount(0.0, 0.0, 3.0, BITS_KEPT[arith], integer=integer, wide=wide)


def edge_bits_needed(
    size: int, offset: float, subpixel_bits: int = 8, *, least: bool = False
) -> int:
    """Bits (with the sign) an exact edge function needs: its positions and its products.

    A position up to ``offset + size`` px on a ``1/2**s`` grid needs ``log2(offset + size) + s``
    bits and a sign. The products are counted by
    :func:`teachraster.core.fixed_point.range_budget`, the count lesson 10 uses too:
    coordinates in a ``size``-pixel range differ by less than ``size·2**s`` units
    (``d`` bits), a product needs ``2d`` bits, E (a difference of two) ``2d + 1`` term by
    term, and a sign; with ``least=True``, E's own bound instead (twice a triangle's area, at
    most the largest difference squared: ``BitBudget.least_needed``, one bit fewer). Exact
    arithmetic needs the larger of the position's count and E's.

    >>> edge_bits_needed(64, 0), edge_bits_needed(64, 1_000_000), edge_bits_needed(2**16, 0)
    (30, 30, 50)
    >>> edge_bits_needed(2**16, 0, least=True)
    49
    """
    position = math.ceil(math.log2(offset + size)) + subpixel_bits + 1
    budget = fixed_point.range_budget(size, subpixel_bits)
    return max(position, budget.least_needed if least else budget.needed)


def _total(terms, per: str) -> OpCount:
    """``sum(n * op for n, op in terms)``: integer work, its wide additions summed too."""
    total = {k: sum(n * getattr(op, k) for n, op in terms)
             for k in ("divides", "multiplies", "additions", "wide")}  # fmt: skip
    return OpCount(total["divides"], total["multiplies"], total["additions"], None, per,
                   integer=True, wide=total["wide"])  # fmt: skip


def fill_count(variant: str) -> OpCount:
    """Operations per triangle of the study's fill triangle for ``"halfplane …"`` / ``"span …"``:
    :data:`HALFPLANE_CENTRE` per box centre and :data:`HALFPLANE_LINE` per raster line, or
    :data:`SPAN_PIXEL` per covered pixel, :data:`SPAN_LINE` and two :data:`SPAN_CROSSING`
    per raster line and one divide (the split point ``u4``, with its multiply).

    Counted on the triangle :func:`teachraster.study.bench.fill_triangle` fills at that size
    (the trace adds bookkeeping, not arithmetic: the same counts).

    >>> op = fill_count("span 64²")
    >>> op.divides == op.multiplies + 1 == op.wide + 1   # a crossing: one of each
    True
    """
    method = variant.split()[0].split("+")[0]
    size = int(variant.split()[-1].rstrip("²"))
    filled = rasterize(bench.fill_triangle(size), size, size, method="halfplane", trace=True)
    box = filled.trace.bbox
    rows = box.row1 - box.row0
    if method == "halfplane":  # every centre of the box
        return _total([(box.size, HALFPLANE_CENTRE), (rows, HALFPLANE_LINE)], "triangle")
    if method == "span":  # two crossings per line, then the covered pixels: the loop only
        covered = int(filled.coverage.sum())
        u4 = OpCount(1.0, 0.0, 0.0)  # its multiply is counted with the crossings' (2 per line)
        return _total([(covered, SPAN_PIXEL), (rows, SPAN_LINE), (2 * rows, SPAN_CROSSING),
                       (1, u4)], "triangle")  # fmt: skip
    raise ValueError(f"unknown fill variant {variant!r}")


def blocked_fill_count(size: int, block: int = FILL_BLOCK) -> tuple[OpCount, dict]:
    """Operations per triangle of half-planes in ``block`` × ``block`` blocks on the study's
    fill triangle at ``size``², and the walk's block counts (``rejected``, ``accepted``,
    ``partial``, ``pixel_tests``, ``pixels_accepted``), counted by the tiled fill itself.

    Every block of the box's grid pays :data:`BLOCK_TEST`; a rejected block nothing more; an
    accepted one fills its pixels untested (:data:`SPAN_PIXEL` each, :data:`SPAN_LINE` per
    line); a partial one tests its centres as half-planes do (:data:`HALFPLANE_CENTRE` each,
    :data:`HALFPLANE_LINE` per line).

    >>> op, blocks = blocked_fill_count(64)
    >>> op.divides, blocks["pixel_tests"] == 64 * blocks["partial"]
    (0.0, True)
    """
    filled = rasterize(bench.fill_triangle(size), size, size, method="tiled",
                       block_sizes=(block,), trace=True)  # fmt: skip
    c = filled.trace.blocks.counters
    blocks = {"rejected": c.empty[0], "accepted": c.full[0], "partial": c.partial[0],
              "pixel_tests": c.pixel_tests, "pixels_accepted": c.pixels_accepted}  # fmt: skip
    op = _total([(sum(c.empty + c.full + c.partial), BLOCK_TEST),
                 (c.pixels_accepted, SPAN_PIXEL), (block * c.full[0], SPAN_LINE),
                 (c.pixel_tests, HALFPLANE_CENTRE), (block * c.partial[0], HALFPLANE_LINE)],
                "triangle")  # fmt: skip
    return op, blocks


def count(row: dict) -> OpCount:
    """:class:`OpCount` of a row of :func:`teachraster.study.bench.run`."""
    group, variant = row["group"], row["variant"]
    if group == "interpolation":
        return interpolation_count(variant)
    if group == "edge functions":
        return edge_count(variant)
    if group == "fill":
        return fill_count(variant)
    if group == "depth":
        fmt = variant.split()[1]
        return OpCount(0.0, 0.0, 1.0, DEPTH_BITS[fmt], "fragment", DEPTH_STORED_BITS[fmt])
    raise ValueError(f"unknown group {group!r}")


def cycles(op: OpCount, weights: dict | None = None) -> float:
    """Weighted cost of ``op``: divides, multiplies and additions times their weights, a
    wide addition at ``weights["wide additions"]`` where the list has one (else as any
    addition). Without ``weights``: the Pentium's, :data:`PENTIUM_INTEGER_CYCLES` for
    integer work and :data:`PENTIUM_CYCLES` for floating point.

    Where the list has a ``"divide issue"`` (:data:`GPU_CYCLES`) the divide runs on a unit of
    its own, in parallel: the other pipe pays that issue slot per divide, and the cost is the
    larger of the two units' cycles, ``max(pipe, divides × divide)``.

    >>> cycles(interpolation_count("perspective")), cycles(interpolation_count("perspective"), GPU_CYCLES)
    (24.0, 8.0)
    >>> cycles(interpolation_count("perspective", 16), GPU_CYCLES)  # the reciprocal hidden
    34.0
    """
    if weights is None:
        weights = PENTIUM_INTEGER_CYCLES if op.integer else PENTIUM_CYCLES
    add = weights["additions"]
    wide = weights.get("wide additions", add)
    rest = op.multiplies * weights["multiplies"] + (op.additions - op.wide) * add + op.wide * wide
    divide = op.divides * weights["divides"]
    if "divide issue" not in weights:  # one unit does everything: the cycles add
        return divide + rest
    return max(rest + op.divides * weights["divide issue"], divide)  # two units overlap


def with_counts(rows: list[dict], weights: dict | None = None) -> list[dict]:
    """Copies of ``rows`` with ``divides``, ``multiplies``, ``additions``, ``bits`` (of
    precision kept), ``stored_bits`` (depth formats: bits stored per sample, else None),
    ``cycles``, ``per``, ``integer`` and ``wide`` (its additions wider than 32 bits) added:
    the operation counts beside the measured error. ``weights`` as in :func:`cycles`."""
    out = []
    for row in rows:
        op = count(row)
        out.append({**row, "divides": op.divides, "multiplies": op.multiplies,
                    "additions": op.additions, "bits": op.bits, "stored_bits": op.stored,
                    "per": op.per, "integer": op.integer, "wide": op.wide,
                    "cycles": cycles(op, weights)})  # fmt: skip
    return out


# -- cracks -----------------------------------------------------------------------------------
def tie_mesh(size: int = 24, cells: int = 3, seed: int = 5) -> np.ndarray:
    """A watertight mesh of (2 cells²) triangles whose vertices are all on pixel centres.

    Inner grid vertices move by whole pixels, so every edge, shared or not, passes through
    pixel centres at regular steps: ties (E = 0) on every shared edge.
    """
    rng = np.random.default_rng(seed)
    step = (size - 2) // cells
    g = np.stack(np.meshgrid(np.arange(cells + 1), np.arange(cells + 1)), -1) * step + 1.5
    jitter = rng.integers(-(step // 3), step // 3 + 1, g.shape).astype(float)
    jitter[[0, -1], :, 1] = 0
    jitter[:, [0, -1], 0] = 0
    g = g + jitter
    return triangulate_grid(g)


def rule_coverage(xy, width: int, height: int, rule: str) -> np.ndarray:
    """Coverage of one triangle in float64 under ``rule``: "top-left", "E >= 0" or "E > 0".

    >>> tri = [[0.5, 0.5], [4.5, 0.5], [0.5, 4.5]]          # edges through centres
    >>> [int(rule_coverage(tri, 6, 6, r).sum()) for r in RULES]
    [10, 15, 3]
    """
    if rule not in RULES:
        raise ValueError(f"rule must be one of {RULES}, got {rule!r}")
    xy = np.asarray(xy, dtype=np.float64)
    a, b, c = xy
    if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0:
        xy = xy[[0, 2, 1]]  # inside on the positive side
    px, py = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    ok = np.ones((height, width), dtype=bool)
    for k in range(3):
        p, q = xy[k], xy[(k + 1) % 3]
        e = (q[0] - p[0]) * (py - p[1]) - (q[1] - p[1]) * (px - p[0])
        top_left = q[1] < p[1] or (q[1] == p[1] and q[0] > p[0])
        tie = {"top-left": top_left, "E >= 0": True, "E > 0": False}[rule]
        ok &= (e > 0) | ((e == 0) & tie)
    return ok


def outline_centres(mesh, width: int, height: int) -> np.ndarray:
    """(height, width) bool: the pixel centres on the mesh's outline (edges of one triangle).

    Whether such a centre is drawn depends on the mesh beside this one, which shares the edge:
    it is neither a crack nor a double hit of this mesh.

    >>> quad = [[[0.5, 0.5], [2.5, 0.5], [0.5, 2.5]], [[2.5, 0.5], [2.5, 2.5], [0.5, 2.5]]]
    >>> int(outline_centres(quad, 4, 4).sum())   # the 3x3 centres but the middle one
    8
    """
    tris = np.asarray(mesh, dtype=np.float64)
    uses: dict = {}
    for t in tris:
        for k in range(3):
            key = tuple(sorted((tuple(t[k]), tuple(t[(k + 1) % 3]))))
            uses[key] = uses.get(key, 0) + 1
    px, py = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
    on = np.zeros((height, width), dtype=bool)
    for (a, b), n in uses.items():
        if n != 1:
            continue
        (ax_, ay), (bx, by) = a, b
        cross = (bx - ax_) * (py - ay) - (by - ay) * (px - ax_)
        along = (px - ax_) * (bx - ax_) + (py - ay) * (by - ay)
        on |= (cross == 0) & (along >= 0) & (along <= (bx - ax_) ** 2 + (by - ay) ** 2)
    return on


def crack_counts(mesh, width: int, height: int, rule: str) -> dict:
    """Gaps and double hits of ``mesh`` under ``rule``, inside the mesh's outline.

    Returns ``{"gaps": ..., "double_hits": ..., "counts": (height, width) int array,
    "outline": (height, width) bool}``. A gap is a centre inside the outline (the package
    covers it once) that the rule leaves empty; a double hit a centre inside the outline that
    the rule covers twice or more. Centres on the outline itself (:func:`outline_centres`) are
    counted in neither: the neighbouring mesh decides them.
    """
    outline = outline_centres(mesh, width, height)
    want = sum(rasterize(Triangle(t), width, height).coverage.astype(int) for t in mesh)
    counts = sum(rule_coverage(t, width, height, rule).astype(int) for t in mesh)
    inside = (want > 0) & ~outline
    return {"gaps": int((inside & (counts == 0)).sum()),
            "double_hits": int((~outline & (counts > 1)).sum()), "counts": counts,
            "outline": outline}  # fmt: skip
