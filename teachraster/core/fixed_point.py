"""Fixed-point edge functions: how many bits the stepping needs, and what happens without them.

On the snapped grid every coordinate is an integer number of internal units (``2**(s + 1)``
per pixel for ``s`` sub-pixel bits: the extra bit puts pixel centres on the grid too). An
edge function is a difference of two products of coordinate differences::

    E = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)

If every difference that enters is at most ``L`` pixels (the *extent*: the triangle's
bounding box together with the block pixels the walker evaluates, or the whole guard band
when any vertex may lie anywhere in it), then in units ``|Δ| <= L·2**(s+1) < 2**d`` with
``d = bit_length(L·2**(s+1))``, each product is below ``2**(2d)``, their difference below
``2**(2d+1)``, and a signed register needs ``2d + 2`` bits. Stepping only adds increments
between values that are themselves edge values inside the extent, so it needs no more.

The same count with coordinates stored on the ``1/2**s`` grid itself (no extra bit) and
anywhere in a range of ``R`` pixels, as Direct3D's 16.8 fixed point is over its ``2**16``-pixel
range, gives ``|Δ| < R·2**s`` (:func:`range_budget`): 50 bits for Direct3D, term by term. One
rule, in :func:`_budget`, counts both.

That count is term by term, and for E itself it is one bit high: E is twice the signed area
of the triangle ``a b p``, and a triangle inside a square of side ``M`` (the largest
difference) has at most half the square's area, so ``|E| <= M**2`` (three corners of the
square reach it). Each product is below ``2**(2d)`` too, so ``2d + 1`` bits and a sign hold
every product and E (:attr:`BitBudget.least_needed`): 49 bits for Direct3D. The term-by-term
count (llvmpipe's, and the package's :attr:`BitBudget.needed`) keeps the bit to spare.

Mesa's llvmpipe makes the same count (``MAX_FIXED_LENGTH32`` in ``lp_rast.h``): with 8
sub-pixel bits a triangle whose box spans at most 128 px is rasterised in 32-bit
integers, any larger one in 64-bit. teachraster steps in int64: its coordinates stay
below ``2**30`` units (:data:`.snapping.UNIT_LIMIT`), a guard band of ±2**21 px with 8 bits,
so ``d <= 31`` and 64 bits suffice for every triangle it accepts.

>>> budget = bit_budget(1024, subpixel_bits=8, int_bits=32)
>>> budget.needed, budget.fits
(42, False)
>>> max_extent(8, 32), max_extent(8, 64)
(63, 4194303)
>>> d3d = range_budget(2**16, subpixel_bits=8)     # Direct3D's 16.8 over 2**16 px
>>> d3d.needed, d3d.least_needed                  # term by term; E's own bound
(50, 49)
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from . import tiles
from .bbox import pixel_bbox
from .edges import setup_edges
from .snapping import SUBPIXEL_BITS, check_bits
from .triangle import Triangle
from .validate import as_int, as_size, check_choice

#: Register widths the narrow walk can use (numpy's signed integer types).
INT_TYPES = {16: np.int16, 32: np.int32, 64: np.int64}


@dataclass(frozen=True)
class BitBudget:
    """The integer width an edge-function walk needs, term by term.

    Attributes
    ----------
    extent_px : int
        Largest coordinate difference that enters, in pixels.
    subpixel_bits, int_bits : int
        Snapping precision and register width.
    units_per_pixel : int
        ``2**(subpixel_bits + 1)``.
    delta_bits : int
        Magnitude bits of a coordinate difference (``|Δ| < 2**delta_bits``).
    product_bits, edge_bits : int
        Magnitude bits of one product and of E (a difference of two products).
    needed : int
        ``edge_bits`` plus the sign bit: the term-by-term count, one bit above
        :attr:`least_needed` (a designer sizing the adders term by term keeps it).
    max_delta : int
        The largest coordinate difference, in units (``|Δ| <= max_delta < 2**delta_bits``).
    within : bool
        False: differences reach ``extent_px`` (:func:`bit_budget`); True: they stay below it,
        coordinates anywhere in a range of ``extent_px`` pixels (:func:`range_budget`).
    """

    extent_px: int
    subpixel_bits: int
    int_bits: int
    units_per_pixel: int
    delta_bits: int
    product_bits: int
    edge_bits: int
    needed: int
    max_delta: int = 0
    within: bool = False

    @property
    def area_bits(self) -> int:
        """Magnitude bits of the largest ``|E|``: ``max_delta**2`` (E is twice a triangle's
        signed area, and a triangle in a square of side ``max_delta`` has at most half of it)."""
        return (self.max_delta**2).bit_length()

    @property
    def least_needed(self) -> int:
        """The fewest bits, sign included, that hold E exactly: ``area_bits`` and a sign.

        Every product is below ``2**product_bits <= 2**area_bits`` as well, so no term
        overflows either. At least one bit fewer than :attr:`needed` (``max_delta < 2**d``
        puts ``max_delta**2`` below ``2**(2d)``; Direct3D: 49 against 50).

        >>> b = range_budget(2**16, subpixel_bits=8)
        >>> b.max_delta**2 < 2**48 <= 2 * b.max_delta**2, b.area_bits, b.least_needed
        (True, 48, 49)
        """
        return self.area_bits + 1

    @property
    def fits(self) -> bool:
        """True when every edge value fits a signed ``int_bits`` register."""
        return self.needed <= self.int_bits

    @property
    def headroom(self) -> int:
        """Spare bits (negative: bits missing)."""
        return self.int_bits - self.needed

    def lines(self) -> list[str]:
        """The count in words, one line per term.

        Counts carry thousands separators, as every count the lessons print does.

        Examples
        --------
        >>> for line in bit_budget(1024, subpixel_bits=8, int_bits=32).lines():
        ...     print(line)
        coordinates: 8 sub-pixel bits + 1 for pixel centres = 512 units per pixel
        differences: up to 1,024 px = 524,288 units < 2^20
        products of two differences: < 2^40
        E = difference of two products: < 2^41, plus a sign bit = 42 bits
        42 bits needed: does NOT fit int32: 10 bits short, values wrap
        """
        u = self.units_per_pixel
        verdict = (
            f"fits int{self.int_bits} with {self.headroom} bits to spare"
            if self.fits
            else f"does NOT fit int{self.int_bits}: {-self.headroom} bits short, values wrap"
        )
        centre = " + 1 for pixel centres" if u == 2 ** (self.subpixel_bits + 1) else ""
        reach = (
            f"below {self.extent_px:,} px: at most {self.max_delta:,} units"
            if self.within
            else f"up to {self.extent_px:,} px = {self.max_delta:,} units"
        )
        return [
            f"coordinates: {self.subpixel_bits} sub-pixel bits{centre} = {u:,} units per pixel",
            f"differences: {reach} < 2^{self.delta_bits}",
            f"products of two differences: < 2^{self.product_bits}",
            f"E = difference of two products: < 2^{self.edge_bits}, plus a sign bit = "
            f"{self.needed} bits",
            f"{self.needed} bits needed: {verdict}",
        ]


def bit_budget(
    extent_px, subpixel_bits: int = SUBPIXEL_BITS, int_bits: int = 64, *, centre_bit: bool = True
) -> BitBudget:
    """The bits edge functions need when coordinate differences reach ``extent_px`` pixels,
    on the package's grid (``2**(s+1)`` units a pixel) or, ``centre_bit=False``, on a GPU's
    (``2**s``: Direct3D's 16.8, llvmpipe's ``FIXED_ORDER``).

    >>> bit_budget(320, 8, 32, centre_bit=False).needed == bit_budget(160, 8, 32).needed == 36
    True
    """
    extent = as_int("extent_px", extent_px, minimum=1)
    bits = check_bits(subpixel_bits)
    if bits is None:
        raise ValueError("subpixel_bits: a fixed-point budget needs a number of bits, got None")
    width = as_int("int_bits", int_bits, minimum=2)
    unit = 2 ** (bits + bool(centre_bit))
    return _budget(extent, bits, width, unit, extent * unit, within=False)


def range_budget(
    range_px, subpixel_bits: int = SUBPIXEL_BITS, int_bits: int = 64, *, centre_bit: bool = False
) -> BitBudget:
    """The bits edge functions need when every coordinate lies in a range of ``range_px`` px.

    Coordinates are stored with ``subpixel_bits`` fraction bits (``2**s`` units per pixel;
    ``centre_bit=True``: teachraster's ``2**(s+1)``), so two of them differ by less than
    ``range_px`` pixels: at most ``range_px·units − 1`` units. Direct3D's 16.8 fixed point
    over its ``2**16``-pixel range: 24-bit coordinates, differences below ``2**24`` units,
    products below ``2**48``, E (a difference of two products) below ``2**49`` term by term,
    50 bits with the sign; E itself, twice a triangle's area, stays at most ``(2**24 - 1)**2 <
    2**48``: 49 bits with the sign (:attr:`BitBudget.least_needed`).

    >>> b = range_budget(2**16, subpixel_bits=8)
    >>> b.delta_bits, b.product_bits, b.edge_bits, b.needed, b.least_needed
    (24, 48, 49, 50, 49)
    """
    extent = as_int("range_px", range_px, minimum=1)
    bits = check_bits(subpixel_bits)
    if bits is None:
        raise ValueError("subpixel_bits: a fixed-point budget needs a number of bits, got None")
    width = as_int("int_bits", int_bits, minimum=2)
    unit = 2 ** (bits + bool(centre_bit))
    return _budget(extent, bits, width, unit, extent * unit - 1, within=True)


def _budget(extent, bits, width, unit, max_delta, *, within) -> BitBudget:
    """The one count: ``|Δ| <= max_delta < 2**d``, a product of two differences below
    ``2**(2d)``, E (a difference of two products) below ``2**(2d+1)``, and the sign bit.

    It counts term by term, as llvmpipe does (``lp_rast.h``): the difference of two products
    bounded as if both could reach their bound with opposite signs. They cannot: E itself is
    twice a triangle's signed area, at most ``max_delta**2`` when all three points lie within
    the range, so :attr:`BitBudget.least_needed` is one bit less; a designer sizing the adders
    term by term keeps that bit to spare.
    """
    d = int(max_delta).bit_length()
    return BitBudget(extent, bits, width, unit, d, 2 * d, 2 * d + 1, 2 * d + 2, int(max_delta),
                     bool(within))  # fmt: skip


def max_extent(subpixel_bits: int = SUBPIXEL_BITS, int_bits: int = 64) -> int:
    """The largest extent (px) whose edge values fit a signed ``int_bits`` register."""
    bits = check_bits(subpixel_bits)
    if bits is None:
        raise ValueError("subpixel_bits: a fixed-point budget needs a number of bits, got None")
    width = as_int("int_bits", int_bits, minimum=4)
    delta = (width - 2) // 2  # 2 * delta + 2 <= width
    return (2**delta - 1) // 2 ** (bits + 1)


def max_range(subpixel_bits: int = SUBPIXEL_BITS, int_bits: int = 64, *, centre_bit=False) -> int:
    """The widest range (px) of coordinates whose edge values fit a signed ``int_bits`` register.

    Coordinates anywhere in a range of ``R`` pixels differ by less than ``R`` pixels
    (:func:`range_budget`); ``2d + 2 <= int_bits`` allows differences below ``2**d`` units, so
    ``R = 2**d`` units. On a GPU's own grid (``2**s`` units a pixel, no centre bit) with 8
    sub-pixel bits and int32 that is ``2**15 / 256 = 128`` px: llvmpipe's ``MAX_FIXED_LENGTH32``
    (``lp_rast.h``). ``centre_bit=True`` counts on the package's ``2**(s+1)`` grid.

    >>> max_range(8, 32), max_range(8, 32, centre_bit=True), max_range(8, 64)
    (128, 64, 8388608)
    >>> range_budget(128, 8, 32).fits, range_budget(129, 8, 32).fits
    (True, False)
    """
    bits = check_bits(subpixel_bits)
    if bits is None:
        raise ValueError("subpixel_bits: a fixed-point budget needs a number of bits, got None")
    width = as_int("int_bits", int_bits, minimum=4)
    delta = (width - 2) // 2  # 2 * delta + 2 <= width: differences below 2**delta units
    return 2**delta // 2 ** (bits + bool(centre_bit))


def fill_extent(xy, width: int, height: int, subpixel_bits=SUBPIXEL_BITS, block_sizes=None) -> int:
    """Extent (px) of a tiled fill: the vertices and every pixel centre the walk evaluates.

    The walk evaluates E at pixel centres of the top-level blocks over the bounding box, so
    their pixels count as well as the triangle's own box.
    """
    sizes = tiles.check_block_sizes(tiles.BLOCK_SIZES if block_sizes is None else block_sizes)
    setup = setup_edges(np.asarray(xy, dtype=np.float64), check_bits(subpixel_bits))
    box = pixel_bbox(setup, as_size("width", width), as_size("height", height))
    px = setup.p.astype(np.float64) / float(setup.unit)
    lo, hi = px.min(axis=0), px.max(axis=0)
    if box.size:
        s = sizes[0]
        lo = np.minimum(lo, [box.col0 // s * s, box.row0 // s * s])
        hi = np.maximum(hi, [((box.col1 - 1) // s + 1) * s, ((box.row1 - 1) // s + 1) * s])
    return max(1, int(np.ceil((hi - lo).max())))


@dataclass(frozen=True)
class NarrowFill:
    """A tiled walk in a narrow register next to the exact one (:func:`narrow_fill`)."""

    coverage: np.ndarray  # (H, W) bool, stepped in int_bits
    exact: np.ndarray  # (H, W) bool, stepped in int64 (equal to the half-plane coverage)
    budget: BitBudget

    @property
    def wrong(self) -> np.ndarray:
        """(H, W) bool: pixels the overflow got wrong."""
        return self.coverage != self.exact


def narrow_fill(
    tri: Triangle,
    width: int,
    height: int,
    *,
    int_bits: int = 32,
    subpixel_bits: int = SUBPIXEL_BITS,
    block_sizes=tiles.BLOCK_SIZES,
    centre_bit: bool = True,
) -> NarrowFill:
    """Run the tiled walk with ``int_bits``-bit edge registers, and the exact walk beside it.

    When :func:`bit_budget` says the extent does not fit, the stepped values wrap around and
    whole blocks are accepted or rejected wrongly: the overflow demonstration. The walk runs
    on the package's grid (``2**(s+1)`` units a pixel), or with ``centre_bit=False`` on a
    GPU's (``2**s``, as Direct3D's 16.8 and llvmpipe count; needs ``s >= 1``, where pixel
    centres lie on that grid): every value there is the package's divided by 4, exactly, so
    only where the values wrap changes, never the exact coverage.
    """
    if not isinstance(tri, Triangle):
        raise TypeError(f"tri must be a teachraster.Triangle, got {type(tri).__name__}")
    check_choice("int_bits", int_bits, tuple(INT_TYPES))
    width, height = as_size("width", width), as_size("height", height)
    bits = check_bits(subpixel_bits)
    if bits is None:
        raise ValueError("subpixel_bits: fixed-point stepping needs a number of bits, got None")
    setup = setup_edges(tri.xy, bits)
    box = pixel_bbox(setup, width, height)
    if not centre_bit:
        setup = _gpu_grid(setup)
    out = {}
    for name, dtype in (("narrow", INT_TYPES[int_bits]), ("exact", None)):
        local, _ = tiles.fill(
            setup, box, False, block_sizes=block_sizes, image=(height, width), dtype=dtype
        )
        out[name] = np.zeros((height, width), dtype=bool)
        out[name][box.row0 : box.row1, box.col0 : box.col1] = local
    extent = fill_extent(tri.xy, width, height, bits, block_sizes)
    budget = bit_budget(extent, bits, int_bits, centre_bit=centre_bit)
    return NarrowFill(out["narrow"], out["exact"], budget)


def _gpu_grid(setup):
    """The same snapped triangle on ``2**s`` units a pixel: the package's coordinates halved.

    With ``s >= 1`` sub-pixel bits every snapped vertex and pixel centre is an even number of
    the package's ``2**(s+1)`` units (the centre bit is needed only at ``s = 0``), so halving
    is exact and every edge value is the package's divided by 4: same signs, same ties.
    """
    if setup.unit < 4 or (setup.p % 2).any():
        raise ValueError("centre_bit=False needs a sub-pixel bit: pixel centres on the grid")
    return replace(setup, p=setup.p // 2, unit=setup.unit // 2, area2=setup.area2 // 4,
                   original_area2=setup.original_area2 // 4)  # fmt: skip
