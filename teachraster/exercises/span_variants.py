"""More wrong spans of exercise 2.1 (``span``, r372) and the rows that tell them apart.

Each variant is a whole wrong solution the checker runs on a case: a crossing computed in
another order of its operations (divide first, as lesson 01 writes Ek's formula, or the slope
first), a wrong formula for one crossing (the slope inverted, the long edge's sign, the upper
short edge divided by the long edge's height), a wrong choice of the edges or of x_l (the
winding as given, before the sort; the vertices sorted by x; the long edge used again below the
split; the lower short edge above it), or the vertices moved to pixel centres. A variant is
named only where it gives every answer of the check (:mod:`.spans`).

>>> a, b = (0.5, 19.5), (84.5, 103.5)
>>> float_crossing(a, b, 42.5, "divide first"), float_crossing(a, b, 42.5, "multiply first")
(23.500000000000004, 23.5)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from fractions import Fraction

import numpy as np

#: r372 P1: lesson 01's triangle ``big`` (vertices on centres, edges 84 and 88 px high): its
#: rows 42, 46, 65 and 73 are crossed exactly on a centre, where a crossing divided first
#: lands a hair off it; and two triangles of random centres (numpy seed 372) whose rows 64 and
#: 89 do the same to a crossing computed slope first, (y − y1)·((x3 − x1)/(y3 − y1)).
TIE_ROWS = (
    (((0.5, 19.5), (1.5, 107.5), (84.5, 103.5)), (42, 46, 65, 73)),
    (((89.5, 57.5), (49.5, 69.5), (119.5, 19.5)), (64,)),
    (((37.5, 114.5), (55.5, 4.5), (9.5, 14.5)), (89,)),
)

#: r372 P2, F1: triangles left of and above the origin (``int()`` truncates toward zero, a
#: clip at column 0 empties them), one across column 0, and a bottom edge on a centre line
#: that is no sliver.
PLACED = (
    ("left of and above the origin", ((-10.25, -11.5), (-2.75, -8.75), (-7.125, -2.5)),
     (-11, -9, -7, -4)),
    ("across column 0", ((-6.5, 2.25), (5.75, 4.5), (-1.25, 9.75)), (3, 5, 8)),
    ("a vertical left edge at x = 3", ((3.0, 0.5), (3.0, 8.5), (9.25, 6.75)), (4,)),
    ("a horizontal bottom edge on a centre line, 6 px wide", ((3.25, 1.75), (9.5, 6.5),
     (3.5, 6.5)), (5, 6)),
)  # fmt: skip

#: r385 P4: a crossing exactly on a centre on every edge (the long one, the upper and the lower
#: short one), where a crossing taken from the edge's upper end or from its lower end, divided
#: first, slope first or as the lerp (1 − t)·a + t·b, lands a hair right of it (numpy seed 385,
#: vertices on centres; one row per edge, end and order); and the reader's rows where divide
#: first on the long edge only (m30) or from the lower end (m32) did.
TIE_ENDS = (
    (((97.5, 39.5), (90.5, 83.5), (27.5, 109.5)), 86),
    (((116.5, 9.5), (24.5, 38.5), (62.5, 90.5)), 24),
    (((8.5, 9.5), (98.5, 60.5), (85.5, 79.5)), 59),
    (((20.5, 35.5), (112.5, 36.5), (104.5, 119.5)), 60),
    (((42.5, 18.5), (2.5, 32.5), (111.5, 54.5)), 42),
    (((22.5, 9.5), (1.5, 60.5), (92.5, 109.5)), 19),
    (((3.5, 5.5), (93.5, 59.5), (107.5, 103.5)), 38),
    (((99.5, 54.5), (45.5, 63.5), (22.5, 86.5)), 57),
    (((85.5, 36.5), (0.5, 71.5), (71.5, 87.5)), 57),
    (((8.5, 8.5), (112.5, 86.5), (50.5, 104.5)), 41),
    (((6.5, 10.5), (81.5, 58.5), (7.5, 109.5)), 26),
    (((0.5, 21.5), (85.5, 91.5), (95.5, 116.5)), 49),
    (((98.5, 23.5), (106.5, 86.5), (2.5, 112.5)), 101),
    (((48.5, 13.5), (67.5, 83.5), (1.5, 101.5)), 89),
    (((114.5, 5.5), (3.5, 89.5), (117.5, 115.5)), 102),
    (((64.5, 1.5), (27.5, 81.5), (102.5, 111.5)), 89),
    (((99.5, 54.5), (45.5, 63.5), (22.5, 86.5)), 85),
    (((21.5, 54.5), (7.5, 64.5), (67.5, 116.5)), 77),
    (((12.5, 99.5), (22.5, 24.5), (122.5, 11.5)), 59),
    (((1767.5, 1226.5), (1868.5, 980.5), (256.5, 1724.5)), 1382),
    (((1562.5, 1488.5), (375.5, 1003.5), (30.5, 778.5)), 838),
)

#: r385 P5: crossings a hair right of a centre, not on it (4·10^-8 and 6·10^-10 px), inside the
#: stated range: an epsilon "for safety" covers that centre (their rows are 10^5 and 1.5·10^4 px
#: tall: their columns come from the exact crossings, :func:`.spans.exact_columns`).
NEAR_TIES = (
    (((0.5, 0.5), (0.50390625, 100000.5), (1000.5, 500.5)), 1),
    (((100.38671875, 0.5), (1828.921875, 15259.29296875), (5100.38671875, 20.5)), 1),
)

#: r385 P6: horizontal edges off the centre lines, a top edge with y's fraction above ½ (row 19,
#: y = 19.89…) and a bottom edge with one below ½ (row 7, y = 7.25): a row test on ⌊y⌋ visits
#: rows whose centre lines miss the triangle.
FLOOR_ROWS = (
    ("a horizontal top edge below the centre line", ((8.875, 19.89453125),
     (19.94921875, 19.89453125), (30.92578125, 35.125)), (19,)),
    ("a horizontal bottom edge above the centre line", ((3.5, 2.0), (1.25, 7.25),
     (9.75, 7.25)), (7,)),
)  # fmt: skip

ORDERS = ("multiply first", "divide first", "slope first")

#: The range the task states (session 35, r385 T1): vertices on the 1/256-px grid with |x|,
#: |y| below 2^30 px (256·x then needs 38 bits: every vertex is a float64 exactly). Lesson 01
#: §4b proves its multiply-first crossing exact "for coordinates below 2^18 px", a sufficient
#: bound, not a sharp one (its built ties are missed from 2^19 px on, below 2^20 px); here the
#: product (y − a_y)(b_x − a_x) may need up to 2·39 = 78 bits (differences below 2^31 px in
#: 2^-8 steps) and rounds, so a crossing exactly on a centre can land a hair off it
#: (:data:`FAR_TIES`), and one a hair off a centre can land on it (:data:`FAR_NEAR_TIES`).
#: Every case lies within the range but the triangle 10^12 px wide, whose asked rows are exact
#: in any order.
EXACT_BELOW = 2**30

#: Lesson 01 §4b's bound: below it, its multiply-first crossing in float64 is exact (r403 C1:
#: 2^18, as the lesson proves and prints; not 2^17).
FLOAT64_EXACT_BELOW = 2**18

#: r403 P7: crossings a hair (1.9·10^-9 px) right of a centre, not on it, near 2^29 px, where
#: float64's numbers are 6·10^-8 px apart: any float, even an exact crossing rounded to float64
#: at the last step (``math.ceil(n / d / 256 - 0.5)``, ``float(Fraction)``), lands on the
#: centre and moves the end (x_r on the first triangle's row 268435457, x_l on the mirrored
#: one's row 268435455); and crossings a hair left of a centre (their other rows), where a float
#: that lands past the centre does. Columns from the exact crossings.
FAR_NEAR_TIES = (
    ("x_r a hair right of a centre", ((536870912.0, 0.0), (536869912.0, 536870906.0),
     (536870913.0, 536870913.0)), 268435457),
    ("x_r a hair left of a centre", ((536870912.0, 0.0), (536869912.0, 536870906.0),
     (536870913.0, 536870913.0)), 268435455),
    ("x_l a hair right of a centre", ((-536870912.0, 0.0), (-536869912.0, 536870906.0),
     (-536870913.0, 536870913.0)), 268435455),
    ("x_l a hair left of a centre", ((-536870912.0, 0.0), (-536869912.0, 536870906.0),
     (-536870913.0, 536870913.0)), 268435457),
)  # fmt: skip

#: r413 P8: thin triangles below 2^29 px whose middle vertex lies a hair (4.4·10^-11 and
#: 3·10^-11 px) right, then left, of the long edge, where float64's numbers are ~10^-8 px apart:
#: lesson 01's side test in float64 (``u4 < MID[0]``, divided or multiplied first) ties or picks
#: the wrong side, and the asked row has a centre exactly on the left edge (the long one, then
#: the upper short one), so a swapped or empty span loses it. Columns from the exact crossings.
FAR_SIDES = (
    ("the middle vertex a hair right of the long edge", ((0.5, 0.5),
     (72127644.9296875, 88640195.55078125), (143810118.5, 176733304.5)), 88366652),
    ("the middle vertex a hair left of the long edge", ((0.5, 0.5), (132199458.5, 91582510.5),
     (168931804.4921875, 117029214.25390625)), 45791255),
)  # fmt: skip

#: r424 P1, P2: far ties (the long edge's crossing exactly on a centre, |c| < 2^30 px) that float64
#: multiply first is not the only precision to miss. The first has a vertex, y = 609198140.72265625,
#: whose shortest repr, '609198140.7226562', drops the last digit of its 1/256 step
#: (``Fraction(str(x))`` or ``Decimal(str(x))`` moves it 5·10^-8 px, and x_r off the centre); the
#: second's product (y − a_y)(b_x − a_x) needs 65 bits, one more than np.longdouble's (x86's
#: 80-bit float) 64, so multiplied first in longdouble x_l lands a hair right of its centre
#: (the reader's long edges and rows; the middle vertex moved 300 px beside the tie, so that
#: the span is 300 columns, not 2.4·10^7).
FAR_PRECISE = (
    ("a vertex whose shortest repr drops a digit", ((-291258562.71875, -56187862.671875),
     (-144614888.75390625, 150539866.0078125), (180738347.1015625, 609198140.72265625)),
     150539863),
    ("a product of 65 bits", ((-381131973.453125, -15026292.703125),
     (-142320162.24609375, 174588730.0078125), (-50642808.578125, 247380278.171875)),
     174588727),
)  # fmt: skip

#: r439 P1, P4, M1: far ties (the long edge's crossing exactly on a centre, |y| < 2^30 px, spans of
#: about 300 columns) that the other limited precisions miss, between them every one: np.longdouble
#: multiplied first from the lower end, divided first and slope first, and ``decimal`` at 29 to 31
#: digits from either end. Each triangle is at most 2·10^6 px wide, so that a scan of its bounding
#: box's columns stays cheap (decimal at 32 to 34 digits needs a product of 33 to 35 digits, an edge
#: 10^7 to 10^9 px wide: r454 asks them on FAR_DIGITS_35, after the column scans stop). Searched with random.Random(23) (/tmp/r439/fix/search5.py).
FAR_DIGITS = (
    ("a product of 66 bits", ((128409.95703125, -991496292.2421875),
     (-737206.5546875, -124974987.44140625), (-1651659.0859375, 789808797.015625)), -124977559),
    ("a quotient that rounds", ((-21789.875, -14801250.4765625),
     (-444470.59765625, 194191606.6875), (-861134.1875, 399908769.35546875)), 194188928),
    ("a product of 31 digits from the lower end", ((69398.734375, -272132346.390625),
     (560945.53515625, 105601364.40234375), (1032325.78515625, 467387378.31640625)), 105601755),
    ("a product of 32 digits", ((-99125.63671875, -811124669.15234375),
     (-661595.9296875, 154267674.37890625), (-1160757.5703125, 1011971036.3359375)), 154265906),
    ("a slope that rounds", ((-1259854.453125, -838847525.5703125),
     (-413256.9609375, -204692610.3515625), (-137583.75, 2105065.875)), -204690710),
    ("a product of 32 digits from the lower end", ((-1917138.2109375, -257676455.5390625),
     (-2740336.4921875, 147340409.3984375), (-3906363.58984375, 721388696.21484375)), 147341018),
)  # fmt: skip

#: r439 P2, P3: the side of the long edge where a wider float or integer still errs, each triangle
#: under 10^6 px wide. The first, a sliver whose middle vertex lies a lattice step right of the long
#: edge (its side's products need 75 bits): np.longdouble's side (64 bits) comes out 0 or
#: negative there, in every form (the edge function, lesson 01's u4 either way), so the one centre
#: on the left edge is lost; the second, a triangle whose side (x2 − x1)(y3 − y1) − (y2 − y1)(x3 −
#: x1) in 1/256-px units needs 64 bits: numpy's int64 wraps it to the wrong sign (a wrapped
#: difference is exact below 2^63, so only a side this large shows it), on a row of 250 columns.
FAR_WIDE_SIDES = (
    ("the middle vertex a lattice step right of the long edge", ((605210.03515625,
     -552092783.74609375), (1171066.265625, 125328731.86328125),
     (1459170.96484375, 470236698.74609375)), -40928043),
    ("a side of 64 bits", ((1890825.86328125, -511500459.43359375),
     (1738445.59375, -74961807.7734375), (1967256.00390625, 376716536.921875)), -510926459),
)  # fmt: skip

#: r454 (r439 P4): far ties whose product (y − a_y)(b_x − a_x) needs 35 significant digits in
#: decimal (long edges about 2^31 px in x and in y, the middle vertex 300 px right of the tie and 10
#: rows below it, so the span is 300 columns): multiplied first at 33 or 34 digits, the first from
#: its upper end (33) and lower end (33, 34), the second from its upper end (33, 34), the tie goes
#: to the wrong side; 35 digits hold every product of the range. Searched with random.Random(454).
FAR_DIGITS_35 = (
    ("a product of 35 digits", ((932150973.9453125, -925812551.6015625),
     (31958595.5, -1587297.5), (-718202269.87109375, 768600395.91796875)), -1587308),
    ("a product of 35 digits, upper end", ((-896313076.31640625, -850867739.27734375),
     (25117810.5, 75059072.5), (762261979.953125, 815800503.921875)), 75059062),
)  # fmt: skip

#: r454 P1: the closest an exact crossing off a centre comes to it in the stated range: 1/(256·d) px,
#: d the edge's height in 1/256 px (below 2^39), here 2^-47 ≈ 7.1·10^-15 px right of the centre
#: 4.5 on a left edge 2^31 px tall and 3.3 px wide (the span 949 columns): an epsilon of any size
#: above it (1e-14 passed) covers that centre. Near x = 4.5 float64's numbers are 8.9·10^-16 px
#: apart, so no float order moves it: only a tolerance does. Built by the extended Euclid
#: algorithm ((y − a_y)·Δx ≡ 1 mod d).
FAR_HAIR = (
    ("x_l 7.1e-15 px right of a centre on an edge 2^31 px tall", ((2.9296875, -1073741819.94921875),
     (6.23046875, 1073741820.0), (1002.9296875, 0.0)), -52098716),
)  # fmt: skip


#: r385 T1: rows with a crossing exactly on a centre where lesson 01's multiply-first crossing
#: in float64, x = a_x + (y − a_y)(b_x − a_x)/(b_y − a_y), lands a hair right of it (so a
#: first or a stop one column too far right), on each edge (the long one, the upper and the
#: lower short one), taken from its upper end and from its lower end (searched with numpy
#: seed 35: edges about 10^9 px long on the 1/256-px grid through a centre near x = 0, the
#: middle vertex 2^12 to 2^16 px off the long edge; the product needs over 53 bits). Their
#: columns come from the exact crossings.
FAR_TIES = (
    ("the long edge, from its upper end", ((-471482858.58203125, -508593872.34765625),
     (-349399692.828125, -388101312.828125), (280607075.94921875, 233802605.80859375)),
     -44596074),
    ("the long edge, from its lower end", ((-303250476.0546875, -429849303.7265625),
     (100171454.09375, -8419525.63671875), (254840221.12890625, 153177908.85546875)),
     -111834461),
    ("the upper short edge, from its upper end", ((-233344274.79296875, -259334516.4609375),
     (93194924.6171875, 141841776.484375), (138490108.6640625, 197542921.9921875)), 27219978),
    ("the upper short edge, from its lower end", ((321815705.71875, -314069313.515625),
     (-265173699.515625, 324955681.1796875), (-370372363.5703125, 439532792.0)), 34489774),
    ("the lower short edge, from its upper end", ((-259184064.12109375, -485626579.921875),
     (-201309143.53125, -405968103.7109375), (103014231.515625, 13282672.10546875)),
     -126467587),
    ("the lower short edge, from its lower end", ((494394810.92578125, -362998464.41015625),
     (333897981.76171875, -242306986.03515625), (-200698615.45703125, 159675691.62109375)),
     8932187),
)  # fmt: skip


def float_crossing(a, b, y: float, order: str = "multiply first") -> float:
    """x where the line at height ``y`` meets edge a-b, in float64, its operations in
    ``order``: ``a_x + (y − a_y)(b_x − a_x)/(b_y − a_y)`` (multiply first), ``(y − a_y)/(b_y −
    a_y)·(b_x − a_x) + a_x`` (divide first: lesson 01's ``crossing``), ``a_x + (y − a_y)·((b_x −
    a_x)/(b_y − a_y))`` (slope first)."""
    (ax, ay), (bx, by) = (float(a[0]), float(a[1])), (float(b[0]), float(b[1]))
    if order == "divide first":
        return (y - ay) / (by - ay) * (bx - ax) + ax
    if order == "slope first":
        return ax + (y - ay) * ((bx - ax) / (by - ay))
    return ax + (y - ay) * (bx - ax) / (by - ay)


HALF = Fraction(1, 2)


class Pair(frozenset):
    """The columns first <= col < stop, with the pair (first, stop) itself (``pair``), which a
    solution that picks x_l by a side test may return the wrong way round (r372 M2)."""

    pair: tuple[int, int] | None = None
    wide: bool = False  # over 10^6 columns: ``pair`` alone, the set empty (r424 S1)
    strict: bool = False  # compared as it is, never with float64's ends far out (r413 P8)
    from_side: bool = False  # a side test's swap: (stop, first) or (0, 0) only (r454 M1)


def pair_columns(x_left, x_right, wide: bool = False) -> Pair | None:
    """The columns of the crossings x_left, x_right taken as they are (exact for Fractions,
    float64 for floats), with their pair; ``wide``: over 10^6 columns held by the pair alone
    (r424 S1: the bounding box of the 10^12-px triangle, whose ends are vertices), else
    None there."""
    first, stop = math.ceil(x_left - HALF), math.ceil(x_right - HALF)
    if stop - first > 10**6 and wide:
        out = Pair()
        out.pair, out.wide = (first, stop), True
        return out
    if stop - first > 10**6:  # r385: a wrong crossing of the leaning edge 10^5 px tall lies
        return None  # 2.6·10^7 px out: a span whose float ends no variant matches
    out = Pair(range(first, stop))
    out.pair = (first, stop)
    return out


def _cols(lo, hi) -> frozenset:
    return pair_columns(lo, hi)


def _at(a, b, y):
    return a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])


def _pick(long_x, short_x, long_is_left: bool) -> frozenset:
    return _cols(long_x, short_x) if long_is_left else _cols(short_x, long_x)


#: The kinds of :func:`more_variants`, in the table's order.
KINDS = (
    "divide first", "slope first", "upper denominator", "slope inverted", "long edge sign",
    "side by given winding", "side by the short edge", "long edge below the split", "lower edge above the split",
    "sorted by x", "vertices on centres", "not sorted", "vertices truncated", "longest edge",
    "bounding box", "side in float64", "vertices rounded", "vertices rounded half up",
    "vertices on the 1/16 grid", "vertices on the 1/64 grid", "vertices on the 1/128 grid",
    "vertices in int32", "ceil, negative divisor", "vertices through str()",
    "longdouble multiply first",
    "longdouble multiply first, lower end", "longdouble divide first", "longdouble slope first",
    # r454: the most digits first, so that where several give the answer the student's (the
    # highest that fails) is named: a 34-digit student fails where 28 digits fail too
    *(f"decimal at {prec} digits{end}" for prec in range(34, 28, -1) for end in ("", ", lower end")),
    "decimal at 28 digits", "decimal at 28 digits, lower end",
    "side in longdouble", "side in int64",
    "vertices to 6 decimals", "vertices by limit_denominator(100)",
    "x and y sorted apart",
)  # fmt: skip

#: r424 P1, P2, M2 (r439 M1): limited precisions other than float64, each named only where it
#: gives every answer (``only_whole``: a float64 student also misses these far ties)
PRECISION_KINDS = (
    "vertices through str()", "longdouble multiply first", "decimal at 28 digits",
    "decimal at 28 digits, lower end", "longdouble multiply first, lower end",
    "longdouble divide first", "longdouble slope first",
    *(f"decimal at {prec} digits{end}" for prec in range(29, 35) for end in ("", ", lower end")),
    "side in longdouble", "side in int64",
)  # fmt: skip

#: r439 M2, M3: tidy-ups named only where they give every failing answer (a float64 student's far
#: tie or an epsilon's near tie may come out as a tidied vertex's by coincidence)
TIDY_KINDS = ("vertices to 6 decimals", "vertices by limit_denominator(100)")

#: r413 H8: vertices moved off the 1/256 grid before computing: kind -> (how, the move).
MOVES = {
    "vertices rounded": ("rounded the vertices to whole pixels (round())", np.round),
    "vertices rounded half up": ("rounded the vertices to whole pixels (⌊c + ½⌋)",
                                 lambda c: np.floor(c + 0.5)),
    "vertices on the 1/16 grid": ("snapped the vertices to the 1/16-px grid (round(16·c)/16)",
                                  lambda c: np.round(c * 16) / 16),
    # r454 H5: any coarser power-of-two grid than the vertices' 1/256
    **{f"vertices on the 1/{n} grid": (f"snapped the vertices to the 1/{n}-px grid "
                                       f"(round({n}·c)/{n})", lambda c, n=n: np.round(c * n) / n)
       for n in (64, 128)},
    # r454 M6: 256·c stored as np.int32, which holds 2^31 (8388608 px): numpy's cast of a larger
    # float is the platform's (no wrap, no error), so the move is numpy's own cast
    "vertices in int32": ("stored 256·c as np.int32, which holds up to 2^31, i.e. 8388608 px: "
                          "numpy casts a larger value to garbage, silently (keep Python ints: "
                          "round(256 * c), or dtype=object)", lambda c: _int32(c)),
    # r439 M2, M3: a tidy-up that reads as exact: a few decimals (round(c, 6), f"{c:.6f}": a
    # 1/256 step needs 8), the nearest fraction with a small denominator
    "vertices to 6 decimals": ("rounded them to 6 decimals (round(c, 6), f\"{c:.6f}\"; a "
                               "1/256-px step needs 8: 1/256 = 0.00390625)",
                               lambda c: _decimals(c, 6)),
    "vertices by limit_denominator(100)": (
        "replaced them by the nearest fraction with a denominator of at most 100 "
        "(Fraction(c).limit_denominator(100); the vertices' denominator is 256)",
        lambda c: _limited(c, 100)),
}  # fmt: skip


def _int32(c: np.ndarray) -> np.ndarray:
    """The coordinates as ``np.round(256 * c).astype(np.int32) / 256`` makes them (r454 M6)."""
    with np.errstate(invalid="ignore"):
        return np.round(np.asarray(c, dtype=float) * 256).astype(np.int32).astype(float) / 256


def _limited(c: np.ndarray, most: int) -> np.ndarray:
    """The coordinates as ``Fraction(c).limit_denominator(most)`` moves them (exact Fractions:
    a float of the moved value would move it again)."""
    return _exactly(c, lambda v: Fraction(v).limit_denominator(most))


def _decimals(c: np.ndarray, places: int) -> np.ndarray:
    """The coordinates as ``Fraction(f"{c:.{places}f}")`` reads them (exact Fractions)."""
    return _exactly(c, lambda v: Fraction(f"{v:.{places}f}"))


def _exactly(c: np.ndarray, move) -> np.ndarray:
    c = np.asarray(c, dtype=float)
    return np.array([[move(float(v)) for v in p] for p in c], dtype=object).reshape(c.shape)


#: r413 H9 (w44): a ceiling (n + d − 1)//d with d < 0
NEGATIVE_DIVISOR = (
    "where a crossing lies exactly on a centre, your end is one column right of it: a ceiling "
    "written (n + d − 1)//d is one too large there when the divisor d is negative (an edge "
    "taken from its lower end up, so its height y_a − y_b < 0); −(−n // d) is the ceiling for "
    "either sign, or take each edge from its upper end"
)


def _shown(value, other) -> str:
    """``value`` to 10 digits, or all of its float's where ``other`` reads the same so (r439: a
    vertex moved 4·10^-6 px by 6 decimals read "-233344274.8 became -233344274.8")."""
    if f"{float(value):.10g}" != f"{float(other):.10g}":
        return f"{float(value):.10g}"
    return repr(float(value))


def _moved_words(kind: str):
    """r413 H8: the words of a move, with the first coordinate it changes on the case."""
    how, move = MOVES[kind]

    def words(args, expected, got) -> str:
        xy = np.asarray(args[0], dtype=float)
        moved = move(xy)
        k, axis = next(zip(*np.nonzero(moved != xy)), (None, None))
        where = "" if k is None else (
            f" (here {'xy'[axis]} = {_shown(xy[k, axis], moved[k, axis])} of v{k + 1} became "
            f"{_shown(moved[k, axis], xy[k, axis])})"
        )  # fmt: skip
        return (
            f"your span is the one of the triangle with its vertices moved: you {how} before "
            f"computing{where}. Use the vertices as given: they lie on the 1/256-px grid "
            "(256·c is a whole number), anywhere inside a pixel"
        )

    return words


def more_variants(xy: np.ndarray, row: int, exact: Callable) -> dict[str, frozenset]:
    """{kind: the columns that wrong solution gives on ``row``}, each the right answer
    (``exact(xy, row)``, the exact columns) wherever the mistake changes nothing. The side of
    the long edge is judged as the lesson's loop judges it (the middle vertex against the long
    edge at its height), so a crossing moved past the other one empties the span."""
    right = exact(xy, row)
    out = dict.fromkeys(KINDS, right)
    out["vertices on centres"] = exact(np.floor(np.asarray(xy, dtype=float)) + 0.5, row)
    out["sorted by x"] = _sorted_by_x(xy, row)
    # r385 M7, M8: the vertices truncated with int(), used in the order given, the longest edge
    out["vertices truncated"] = exact(np.trunc(np.asarray(xy, dtype=float)), row)
    for kind, (_, move) in MOVES.items():  # r413 H8: rounded, or on a coarser grid
        out[kind] = exact(move(np.asarray(xy, dtype=float)), row)
        if kind in TIDY_KINDS:  # r439: exact, so never matched with float64's ends far out
            out[kind] = _strict(out[kind])
    out["vertices through str()"] = _strict(exact(_through_str(xy), row))  # r424 P1
    out["x and y sorted apart"] = exact(np.sort(np.asarray(xy, dtype=float), axis=0), row)
    out["not sorted"] = _unsorted(xy, row)
    out["longest edge"] = _longest_edge(xy, row)
    ys, xs = [float(p[1]) for p in xy], [Fraction(float(p[0])) for p in xy]
    inside = min(ys) <= row + 0.5 < max(ys)  # r385 M7 (m28): the bounding box's x-range
    out["bounding box"] = pair_columns(min(xs), max(xs), wide=True) if inside else frozenset()
    v = sorted(((Fraction(float(x)), Fraction(float(y))) for x, y in xy), key=lambda p: p[1])
    (x1, y1), (x2, y2), (x3, y3) = v
    y = Fraction(2 * row + 1, 2)
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    if area != 0 and y1 == y2 == y != y3:  # r413 H9: along a top edge, its ends (the long
        # edge's at the top vertex, the first of the two listed: a sort by y alone keeps it)
        ends = sorted((_past_tie(x1), x2))
        out["ceil, negative divisor"] = _cols(*ends)
    if area == 0 or not y1 <= y <= y3 or y1 == y2 == y or y2 == y3 == y:
        return out
    upper = y < y2
    short = (v[0], v[1]) if upper else (v[1], v[2])
    long_is_left = x2 > _at(v[0], v[2], y2)
    long_x, short_x = _at(v[0], v[2], y), _at(*short, y)
    fv = [(float(a), float(b)) for a, b in v]
    fshort = (fv[0], fv[1]) if upper else (fv[1], fv[2])
    for order in ("divide first", "slope first"):
        out[order] = _pick(float_crossing(fv[0], fv[2], float(y), order),
                           float_crossing(*fshort, float(y), order), long_is_left)  # fmt: skip
    if upper:  # r372 M3: the upper short edge divided by the long edge's height
        out["upper denominator"] = _pick(long_x, x1 + (y - y1) * (x2 - x1) / (y3 - y1),
                                         long_is_left)  # fmt: skip
    (ax, ay), (bx, by) = short
    inverted = ax + (y - ay) * (by - ay) / (bx - ax) if bx != ax else ax  # r372 M4
    out["slope inverted"] = _pick(long_x, inverted, long_is_left)
    out["long edge sign"] = _pick(x1 - (y - y1) * (x3 - x1) / (y3 - y1), short_x, long_is_left)
    a, b, c = ((Fraction(float(p[0])), Fraction(float(p[1]))) for p in xy)
    given = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    out["side by given winding"] = _pick(long_x, short_x, given > 0)  # r372 M1 (w36)
    out["side by the short edge"] = _pick(long_x, short_x, x2 > short_x)  # r372 M1 (w24)
    if _float_side_wrong(fv, long_is_left):  # r413 P8: lesson 01's u4 < MID[0] in float64
        out["side in float64"] = _pick(long_x, short_x, not long_is_left)
        if out["side in float64"] is not None:  # matched as it is: its ends are exact
            out["side in float64"].strict = out["side in float64"].from_side = True
    # r413 H9 (w44): ⌈n/d⌉ as (n + d − 1)//d with d < 0 (an edge taken from its lower end up):
    # one column right where the long edge's crossing is exactly on a centre (every edge's so:
    # "ties reversed", C's int(x + 0.5), the same answers)
    out.update(_precision_variants(xy, row, long_is_left))  # r424 P2, M2
    for kind, errs in (
        ("side in longdouble", _longdouble_side_errs(v)),
        ("side in int64", _int64_side_errs(v)),
    ):  # r439 P2, P3
        if errs:
            out[kind] = _strict(_pick(long_x, short_x, not long_is_left))
            if out[kind] is not None:  # r454 M1: (stop, first) or (0, 0), matched so
                out[kind].from_side = True
    if y < y3:  # (the bottom vertex's line has no span to move)
        out["ceil, negative divisor"] = _pick(_past_tie(long_x), short_x, long_is_left)
    if not upper:  # r372 M4 (w43): the long edge taken as the lower short one too
        out["long edge below the split"] = pair_columns(long_x, long_x)
    elif y2 != y3:  # r372 H1 (w44): the lower short edge's line above the split too
        out["lower edge above the split"] = _pick(long_x, _at(v[1], v[2], y), long_is_left)
    return out


def _strict(cols) -> Pair | None:
    """Columns matched as they are, never with float64's ends far out (r424: a precision
    variant is its own rounding)."""
    if cols is None:
        return None
    out = Pair(cols)
    out.strict = True
    return out


def _through_str(xy) -> np.ndarray:
    """r424 P1: the vertices as ``Fraction(str(c))`` reads them: the shortest decimal that reads
    back to the float, which drops a 1/256 step's last digit near 2^29 px."""
    return np.array([[Fraction(repr(float(c))) for c in p] for p in xy], dtype=object)


def _longdouble_crossing(a, b, y, order: str = "multiply first"):
    """The crossing in np.longdouble (r424 P2, W34: multiplied first, a_x + (y − a_y)(b_x −
    a_x)/(b_y − a_y)); r439 P1, M1: from the lower end b, divided first or slope first."""
    ld = np.longdouble
    (ax, ay), (bx, by) = (ld(a[0]), ld(a[1])), (ld(b[0]), ld(b[1]))
    if order == "multiply first, lower end":
        return bx + (y - by) * (ax - bx) / (ay - by)
    if order == "divide first":
        return (y - ay) / (by - ay) * (bx - ax) + ax
    if order == "slope first":
        return ax + (y - ay) * ((bx - ax) / (by - ay))
    return ax + (y - ay) * (bx - ax) / (by - ay)


#: r439: the orders of :func:`_longdouble_crossing`, each its own kind
LONGDOUBLE_ORDERS = ("multiply first", "multiply first, lower end", "divide first", "slope first")

#: r439 P4: decimal precisions below the 35 digits a product may need in the stated range
FEW_DIGITS = tuple(range(34, 28, -1))


def _decimal_crossing(a, b, y, lower: bool, minus_half: bool = False, prec: int = 28):
    """Multiply first in ``decimal`` at ``prec`` digits (r424 M2, W41: its default 28; r439 P4:
    up to 34), from the edge's upper end, or from its lower one (``minus_half``: then x − ½,
    rounded again)."""
    import decimal

    with decimal.localcontext() as context:
        context.prec = prec
        (ax, ay), (bx, by) = ((decimal.Decimal(float(c)) for c in p) for p in (a, b))
        if lower:
            (ax, ay), (bx, by) = (bx, by), (ax, ay)
        line = decimal.Decimal(y.numerator) / y.denominator
        x = ax + (line - ay) * (bx - ax) / (by - ay)
        return x - decimal.Decimal("0.5") if minus_half else x


def _decimal_ends(v, y, short, long_is_left, lower: bool, prec: int):
    ends = [math.ceil(_decimal_crossing(a, b, y, lower, minus_half=True, prec=prec))
            for a, b in ((v[0], v[2]), short)]  # fmt: skip
    return _strict(_ends_pick(*ends, long_is_left))


def _precision_variants(xy, row: int, long_is_left: bool) -> dict:
    """r424 P2, M2: the span with both crossings in a limited precision: np.longdouble (where it
    is wider than float64: x86's 80-bit float) in each order (r439 P1), decimal at 28 digits and
    (r439 P4) at 29 to 34 (far out only), from the edges' upper ends or their lower ones; the side
    and the rounding exact."""
    v = sorted(((float(x), float(y)) for x, y in xy), key=lambda p: p[1])
    y = Fraction(2 * row + 1, 2)
    short = (v[0], v[1]) if y < Fraction(v[1][1]) else (v[1], v[2])
    out = {}
    if np.finfo(np.longdouble).nmant > 52:
        ld_y = np.longdouble(row) + np.longdouble(0.5)
        for order in LONGDOUBLE_ORDERS:
            ends = [int(np.ceil(_longdouble_crossing(a, b, ld_y, order) - np.longdouble(0.5)))
                    for a, b in ((v[0], v[2]), short)]  # fmt: skip
            out[f"longdouble {order}"] = _strict(_ends_pick(*ends, long_is_left))
    for lower, end in ((False, ""), (True, ", lower end")):
        out[f"decimal at 28 digits{end}"] = _decimal_ends(v, y, short, long_is_left, lower, 28)
        if max(abs(c) for p in v for c in p) < 2**20:  # (products of at most 28 digits)
            continue
        for prec in FEW_DIGITS:
            out[f"decimal at {prec} digits{end}"] = _decimal_ends(v, y, short, long_is_left,
                                                                  lower, prec)  # fmt: skip
    return out


def _ends_pick(long_end: int, short_end: int, long_is_left: bool) -> frozenset | None:
    first, stop = (long_end, short_end) if long_is_left else (short_end, long_end)
    return None if stop - first > 10**6 else frozenset(range(first, stop))


def _past_tie(x: Fraction) -> Fraction:
    """x moved a hair right where it lies exactly on a centre (its column one further right)."""
    return x + Fraction(1, 2**80) if (x - Fraction(1, 2)).denominator == 1 else x


def _float_sides(fv) -> list[tuple[float, float]]:
    """(u4, x2 − u4) of lesson 01's side test in float64 on sorted vertices ``fv``, the long
    edge's x at the middle vertex's height divided first (its ``span_fill``) and multiplied
    first (r413 P8)."""
    (x1, y1), (x2, y2), (x3, y3) = fv
    out = []
    for u4 in ((y2 - y1) / (y3 - y1) * (x3 - x1) + x1, x1 + (y2 - y1) * (x3 - x1) / (y3 - y1)):
        out.append((u4, x2 - u4))
    return out


def _float_side_wrong(fv, long_is_left: bool) -> bool:
    """Lesson 01's side test in float64 ties (x2 − u4 == 0) or picks the other side."""
    return any(side == 0 or (side > 0) != long_is_left for _, side in _float_sides(fv))


def _longdouble_side_errs(v) -> bool:
    """r439 P2: the side test in np.longdouble on sorted vertices ``v`` (exact Fractions): the
    edge function or lesson 01's u4 (divided or multiplied first) ties or picks the other side;
    False where longdouble is float64 (lesson 01's float64 test is :func:`_float_side_wrong`)."""
    if np.finfo(np.longdouble).nmant <= 52:
        return False
    (x1, y1), (x2, y2), (x3, y3) = v
    exact = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    (a1, b1), (a2, b2), (a3, b3) = ((np.longdouble(float(a)), np.longdouble(float(b)))
                                    for a, b in v)  # fmt: skip
    sides = ((a2 - a1) * (b3 - b1) - (b2 - b1) * (a3 - a1),
             a2 - ((b2 - b1) / (b3 - b1) * (a3 - a1) + a1),
             a2 - (a1 + (b2 - b1) * (a3 - a1) / (b3 - b1)))  # fmt: skip
    return exact != 0 and any(side == 0 or (side > 0) != (exact > 0) for side in sides)


def _int64_side(v) -> tuple[int, int]:
    """(the exact side, int64's wrapped one) of (x2 − x1)(y3 − y1) − (y2 − y1)(x3 − x1) in
    1/256-px units on sorted vertices ``v`` (r439 P3)."""
    (x1, y1), (x2, y2), (x3, y3) = ((int(256 * a), int(256 * b)) for a, b in v)
    exact = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    wrapped = (exact + 2**63) % 2**64 - 2**63  # a difference of wrapped products, wrapped
    return exact, wrapped


def _int64_side_errs(v) -> bool:
    """r439 P3: numpy's int64 side wraps around to 0 or to the other sign."""
    exact, wrapped = _int64_side(v)
    return exact != 0 and (wrapped == 0 or (wrapped > 0) != (exact > 0))


def float_side_errs(xy) -> bool:
    """r413 P8: a side or area test in float64 errs on this triangle: lesson 01's u4 against
    x2 (:func:`_float_side_wrong`), or the edge function (x2 − x1)(y3 − y1) − (y2 − y1)(x3 − x1)
    computed in floats, zero or of the wrong sign (a float64 student's area test drops the
    row)."""
    v = sorted(_frac_points(xy), key=lambda p: p[1])
    (x1, y1), (x2, y2), (x3, y3) = v
    exact = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    if exact == 0:
        return False
    fv = [(float(a), float(b)) for a, b in v]
    (a1, b1), (a2, b2), (a3, b3) = fv
    area = (a2 - a1) * (b3 - b1) - (b2 - b1) * (a3 - a1)
    return area == 0 or (area > 0) != (exact > 0) or _float_side_wrong(fv, x2 > _at(v[0], v[2], y2))


def _float_side_words(args, expected, got) -> str:
    """r413 P8: the middle vertex's exact distance from the long edge, beside float64's."""
    xy, _ = args
    v = sorted(_frac_points(xy), key=lambda p: p[1])
    (x1, y1), (x2, y2), (x3, y3) = v
    u4 = x1 + (y2 - y1) * (x3 - x1) / (y3 - y1)
    where = "right" if x2 > u4 else "left"
    fu4, fside = _float_sides([(float(a), float(b)) for a, b in v])[0]
    said = "on it" if fside == 0 else ("right of it" if fside > 0 else "left of it")
    # r454 H1: any float64 side test (a cross product, np.cross, np.linalg.det, tr.edge_function
    # on floats), not only lesson 01's u4, which is quoted as one example
    return (
        f"your side test is computed in float64 (lesson 01's u4 < x2, or a cross product or "
        f"determinant of floats): here the middle vertex lies {float(abs(x2 - u4)):.2g} px "
        f"{where} of the long edge, and float64's numbers near {float(x2):.3g} px are "
        f"{float(np.spacing(float(x2))):.2g} px apart, so the side comes out 0 or of the wrong "
        f"sign (lesson 01's u4 comes out {fu4!r} and puts the vertex {said}): your x_l and x_r "
        "are swapped (or your span is empty). Compare exactly: the sign of an integer cross "
        "product, (x2 − x1)(y3 − y1) − (y2 − y1)(x3 − x1) in 1/256-px units (or with "
        "fractions.Fraction)"
    )


def _frac_points(xy) -> list[tuple[Fraction, Fraction]]:
    return [(Fraction(float(x)), Fraction(float(y))) for x, y in xy]


def _steps_in_order(v, row: int, *, rows_sorted: bool) -> frozenset | None:
    """The exercise's own steps on vertices ``v`` taken as top, middle and bottom in the order
    they come: None where a crossing divides by zero (the student's function raises there).
    ``rows_sorted``: the row is tested as y1 <= y <= y3 (as the steps write it after a sort),
    else between y1 and y3 either way round."""
    (x1, y1), (x2, y2), (x3, y3) = v
    y = Fraction(2 * row + 1, 2)
    on_rows = y1 <= y <= y3 if rows_sorted else min(y1, y3) <= y <= max(y1, y3)
    if (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1) == 0 or not on_rows:
        return frozenset()
    if y2 == y3 == y:
        return frozenset()
    if y1 == y2 == y:
        return _cols(min(x1, x2), max(x1, x2))
    try:
        long_x = _at(v[0], v[2], y)
        short_x = _at(*((v[0], v[1]) if y < y2 else (v[1], v[2])), y)
        u4 = _at(v[0], v[2], y2)
    except ZeroDivisionError:
        return None
    return _pick(long_x, short_x, x2 > u4)


def _sorted_by_x(xy: np.ndarray, row: int) -> frozenset | None:
    """The span of the exercise's own steps with the roles given by x, not y (r372 M6): None
    where it divides by zero (the student's function raises there)."""
    v = sorted(_frac_points(xy), key=lambda p: p[0])
    return _steps_in_order(v, row, rows_sorted=True)


def _unsorted(xy: np.ndarray, row: int) -> frozenset | None:
    """The exercise's steps with the vertices taken as top, middle and bottom in the order
    given, no sort (r385 M7, m18): None where it divides by zero."""
    return _steps_in_order(_frac_points(xy), row, rows_sorted=False)


def _longest_edge(xy: np.ndarray, row: int) -> frozenset:
    """The span with "the long edge" read as the longest edge by length, the other crossing
    from the first other edge that reaches the row (r385 M8, m09)."""
    v = _frac_points(xy)
    (x1, y1), (x2, y2), (x3, y3) = v
    if (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1) == 0:
        return frozenset()
    edges = [(v[0], v[1]), (v[1], v[2]), (v[2], v[0])]
    k = max(range(3), key=lambda i: math.dist(*(tuple(map(float, p)) for p in edges[i])))
    y = Fraction(2 * row + 1, 2)
    a, b = sorted(edges[k], key=lambda p: p[1])
    if not a[1] <= y <= b[1] or a[1] == b[1]:
        return frozenset()
    for i in range(3):
        c, d = sorted(edges[i], key=lambda p: p[1])
        if i != k and c[1] <= y <= d[1] and c[1] != d[1]:
            xs = sorted((_at(a, b, y), _at(c, d, y)))
            return _cols(*xs)
    return frozenset()


def _side_words(how: str) -> str:
    return (
        f"your x_l and x_r are swapped on the rows where this matters: you judged which side of "
        f"the long edge the middle vertex lies on {how}; judge it after the sort, by the long "
        "edge where it reaches the middle vertex's height (or take the smaller crossing as x_l)"
    )


def _tie_off(args, order: str) -> str:
    """Where this order's crossing lands off the centre it lies on exactly (r372 P1)."""
    xy, row = args
    v = sorted(((float(x), float(y)) for x, y in xy), key=lambda p: p[1])
    y = row + 0.5
    for a, b, name in ((v[0], v[2], "the long edge"), (v[0], v[1], "the upper short edge"),
                       (v[1], v[2], "the lower short edge")):  # fmt: skip
        if a[1] == b[1] or not a[1] <= y <= b[1]:
            continue
        exact = _at(*(tuple(map(Fraction, p)) for p in (a, b)), Fraction(2 * row + 1, 2))
        got = float_crossing(a, b, y, order)
        if (exact - Fraction(1, 2)).denominator == 1 and got != exact:
            side = "right" if got > exact else "left"
            return (
                f": on {name} yours lands at {got!r}, a hair {side} of the centre "
                f"{float(exact):g} it lies on exactly, so the tie went to the wrong side"
            )
    return (
        ": it lands a hair to one side of a crossing that lies exactly on a centre, so "
        "the tie went to the wrong side"
    )


#: r403 H5: in the stated range no order of float operations is exact (multiply first too
#: fails the far rows), so the hint for a rounding crossing points to exact arithmetic.
NO_FLOAT_ORDER = (
    "In this range no float order is exact (lesson 01 §4b proves multiply first exact for "
    "coordinates below 2^18 px only, and the check's vertices reach 2^29 px): compute the "
    "crossing in integers (1/256-px units) or fractions.Fraction, and round it to a column "
    "without a float"
)


def _order_words(order: str, what: str):
    def words(args, expected, got) -> str:
        return (f"your crossing divides first: {what} rounds (its quotient has no finite "
                f"binary fraction){_tie_off(args, order)}. {NO_FLOAT_ORDER}")  # fmt: skip

    return words


def _str_words(args, expected, got) -> str:
    """r424 P1: the first coordinate whose shortest repr is not its value, quoted both ways."""
    import decimal

    moved = next((float(c) for p in np.asarray(args[0], dtype=float) for c in p
                  if Fraction(repr(float(c))) != Fraction(float(c))), None)  # fmt: skip
    where = "" if moved is None else (
        f" (here the vertex coordinate {decimal.Decimal(moved)} became {moved!r}, "
        f"{float(abs(Fraction(moved) - Fraction(repr(moved)))):.2g} px off, no 1/256 step)"
    )  # fmt: skip
    return (
        f"the vertex read through str() moved{where}: str() (and repr, and print) of a float "
        "is its shortest decimal that reads back to the same float, not its exact value, so "
        "Fraction(str(x)) or Decimal(str(x)) moves the vertex, and the crossing off the centre "
        "it lies on. Use the float's own value: "
        "Fraction(x), Decimal(x) or x.as_integer_ratio() are exact, and so is round(256·x) as "
        "an integer"
    )


def _precise_tie(args, crossing):
    """(exact crossing, the limited one, its edge's product's significant bits) on the first
    edge of the row whose limited crossing ``crossing(a, b)`` moves its column (None: none)."""
    xy, row = args
    v = sorted(((float(x), float(y)) for x, y in xy), key=lambda p: p[1])
    y = Fraction(2 * row + 1, 2)
    for a, b in ((v[0], v[2]), (v[0], v[1]), (v[1], v[2])):
        if not a[1] < y < b[1]:
            continue
        fa, fb = (Fraction(a[0]), Fraction(a[1])), (Fraction(b[0]), Fraction(b[1]))
        exact = fa[0] + (y - fa[1]) * (fb[0] - fa[0]) / (fb[1] - fa[1])
        value = crossing(a, b)
        if math.ceil(Fraction(*value.as_integer_ratio()) - HALF) != math.ceil(exact - HALF):
            n = abs(int(256 * (y - fa[1]) * 256 * (fb[0] - fa[0])))
            return exact, value, n.bit_length() - (n & -n).bit_length() + 1
    return None


def _longdouble_words(order: str = "multiply first"):
    """r424 P2 (r439 P1, M1: every order): the limited crossing beside the exact one."""

    def words(args, expected, got) -> str:
        y = np.longdouble(args[1]) + np.longdouble(0.5)
        found = _precise_tie(args, lambda a, b: _longdouble_crossing(a, b, y, order))
        bits = np.finfo(np.longdouble).nmant + 1
        why = (f"the product (y − a_y)(b_x − a_x) needs {found[2]} bits on the 1/256-px grid"
               if found is not None and order.startswith("multiply") else
               "a quotient such as (y − a_y)/(b_y − a_y) has no finite binary fraction, so it "
               "rounds at any precision")  # fmt: skip
        said = "" if found is None else (
            f" (exactly {float(found[0])}, yours {np.format_float_positional(found[1])}): "
            f"here {why}"
        )  # fmt: skip
        return (f"your crossing was computed in np.longdouble, {order}, and rounds{said}; "
                f"float80/longdouble holds {bits} bits, float64 53, and in the stated range "
                "the product needs up to 78, so the tie went to the wrong side. "
                f"{NO_FLOAT_ORDER}")  # fmt: skip

    return words


def _digits(args) -> int:
    """The most significant digits of a product (y − a_y)(b_x − a_x) on the row's edges."""
    xy, row = args
    v = sorted(((Fraction(float(x)), Fraction(float(y))) for x, y in xy), key=lambda p: p[1])
    y, most = Fraction(2 * row + 1, 2), 0
    for a, b in ((v[0], v[2]), (v[0], v[1]), (v[1], v[2])):
        for p, q in ((a, b), (b, a)):
            n = abs(int((y - p[1]) * (q[0] - p[0]) * 2**16 * 5**16))
            most = max(most, len(str(n).rstrip("0")) if n else 0)
    return most


def _decimal_words(lower: bool, prec: int = 28):
    """r424 M2 (28 digits); r439 P4, M1: any precision, with the digits of the product."""

    def words(args, expected, got) -> str:
        y = Fraction(2 * args[1] + 1, 2)
        found = _precise_tie(args, lambda a, b: _decimal_crossing(a, b, y, lower, prec=prec))
        digits = ("at its default precision, 28 significant digits" if prec == 28 else
                  f"at too few significant digits ({prec} digits{', from the lower end' if lower else ''} "
                  "give your answers here; any precision below 35 may)")  # fmt: skip
        said = "" if found is None else (
            f" (exactly {float(found[0])}, yours {found[1]}: the product "
            f"(y − a_y)(b_x − a_x), with a 1/65536 fraction, has {_digits(args)} significant "
            f"digits here, more than {prec})"
        )  # fmt: skip
        return (f"your crossing was computed in decimal {digits}, and rounds{said}, so the tie went to the wrong side. No float is involved: "
                "decimal rounds every step to its precision. Compute in integers (1/256-px "
                "units) or fractions.Fraction (or give decimal enough digits for every step: "
                "in this range a product needs up to 35, so its default of 28 is not enough)")  # fmt: skip

    return words


def _wide_side_words(kind: str):
    """r439 P2, P3: a side test in np.longdouble, or in int64, that errs on this triangle."""

    def words(args, expected, got) -> str:
        v = sorted(_frac_points(args[0]), key=lambda p: p[1])
        (x1, y1), (x2, y2), (x3, y3) = v
        u4 = x1 + (y2 - y1) * (x3 - x1) / (y3 - y1)
        where = "right" if x2 > u4 else "left"
        exact, wrapped = _int64_side(v)
        bits = max(abs((256 * (x2 - x1)) * (256 * (y3 - y1))),
                   abs((256 * (y2 - y1)) * (256 * (x3 - x1)))).numerator.bit_length()  # fmt: skip
        sides = abs(exact).bit_length()
        if kind == "side in int64":
            how = (f"your side test overflowed int64: its value (x2 − x1)(y3 − y1) − (y2 − y1)"
                   f"(x3 − x1) in 1/256-px units is {exact} here, {sides} bits besides the sign, "
                   "more than int64's 63, and numpy's int64 wraps around silently, so it came "
                   f"out {wrapped}, of the wrong sign: your x_l and x_r are swapped")  # fmt: skip
        else:
            how = (f"your side test is computed in np.longdouble: here the middle vertex lies "
                   f"{float(abs(x2 - u4)):.2g} px {where} of the long edge, and the side's "
                   f"products need {bits} bits, more than longdouble's "
                   f"{np.finfo(np.longdouble).nmant + 1}, so it comes out 0 or of the wrong sign: "
                   "your x_l and x_r are swapped (or your span is empty)")  # fmt: skip
        return (f"{how}. Compare exactly: the sign of the cross product (x2 − x1)(y3 − y1) − "
                "(y2 − y1)(x3 − x1) in Python ints of 1/256-px units (int(), .tolist(), "
                "dtype=object) or with fractions.Fraction")  # fmt: skip

    return words


def _sorted_apart_words(args, expected, got) -> str:
    """r439 H5: np.sort(xy, axis=0) sorts each coordinate on its own."""
    mixed = np.sort(np.asarray(args[0], dtype=float), axis=0)
    shown = ", ".join(f"({p[0]:.10g}, {p[1]:.10g})" for p in mixed)
    return (
        f"your span is the one of the triangle ({shown}): np.sort(xy, axis=0) sorts the x's "
        "and the y's each on its own, so it mixes the vertices' coordinates; sort the "
        "vertices (rows) by y: xy[np.argsort(xy[:, 1])], or sorted(..., key=lambda p: p[1])"
    )


WORDS = {
    "vertices through str()": _str_words,
    **{f"longdouble {order}": _longdouble_words(order) for order in LONGDOUBLE_ORDERS},
    # r454: the most digits first (FEW_DIGITS runs down from 34), 28 last: where several give
    # the student's answers, the highest that fails is named (a 34-digit student's far tie
    # fails at 28 digits too)
    **{
        f"decimal at {prec} digits{end}": _decimal_words(lower, prec)
        for prec in FEW_DIGITS
        for lower, end in ((False, ""), (True, ", lower end"))
    },
    "decimal at 28 digits": _decimal_words(False),
    "decimal at 28 digits, lower end": _decimal_words(True),
    "side in longdouble": _wide_side_words("side in longdouble"),
    "side in int64": _wide_side_words("side in int64"),
    "x and y sorted apart": _sorted_apart_words,
    "side in float64": _float_side_words,
    "divide first": _order_words("divide first", "(y − a_y)/(b_y − a_y)"),
    "slope first": _order_words("slope first", "the slope (b_x − a_x)/(b_y − a_y)"),
    "upper denominator": "above the middle vertex your crossing of the edge from the top "
    "vertex to the middle one is off: you divided by y3 − y1, the long edge's height, not by "
    "that edge's own height y2 − y1",
    "slope inverted": "your crossing of the short edge is off: you multiplied y − y_a by "
    "(y_b − y_a)/(x_b − x_a), the edge's slope dy/dx; along the edge x changes by x_b − x_a "
    "while y changes by y_b − y_a",
    "long edge sign": "your crossing of the long edge is off: you subtracted the step from x1 "
    "(x1 − …) where the edge runs from x1 towards x3: going down by y − y1, x moves by that "
    "share of x3 − x1, added to x1",
    "side by given winding": _side_words(
        "by the winding of the vertices as given (their order before the sort): the sort "
        "reorders them, so the winding says nothing about the sorted roles"
    ),
    "side by the short edge": _side_words(
        "by comparing it with the short edge's crossing at this row (u4 = x_short): point 4 "
        "lies on the long edge, at the middle vertex's height"
    ),
    "long edge below the split": "below the middle vertex you took the long edge (top vertex "
    "to bottom one) as the short one too, so both ends are the long edge's crossing and the "
    "span is empty: the short edge there runs from the middle vertex to the bottom one",
    "lower edge above the split": "you used the edge from the middle vertex to the bottom one "
    "above the middle vertex too: there the other bound is the edge from the top vertex to "
    "the middle one (the split)",
    "sorted by x": "you sorted the vertices by x: the roles top, middle and bottom come from "
    "sorting by y, the direction the raster lines advance in",
    "vertices truncated": "you truncated the vertices to whole numbers (int() or "
    "math.trunc) before computing: the crossings are those of the triangle as given, its "
    "vertices on the 1/256-px grid anywhere inside a pixel",
    "not sorted": "you used the vertices as top, middle and bottom in the order given: sort "
    "them by y first (the smaller x first where two share a y, lesson 01 §1), so that the "
    "long edge runs from the top vertex to the bottom one and the split lies at the middle",
    "longest edge": "you took the longest edge (by length) as the long edge: the long edge is "
    "the one from the top vertex to the bottom one, the only edge spanning the triangle's full "
    "height (points 1 → 3 after the sort by y), however short it is",
    "bounding box": "you covered the triangle's bounding box, from its leftmost vertex to its "
    "rightmost one, on every row: a row's span runs between the two edges that cross its "
    "centre line, x_l and x_r, which move from row to row",
    **{kind: _moved_words(kind) for kind in MOVES},
    "ceil, negative divisor": NEGATIVE_DIVISOR,
    "vertices on centres": "you moved the vertices to pixel centres (⌊c⌋ + ½) before "
    "computing: the crossings are those of the triangle as given, its vertices on the "
    "1/256-px grid anywhere inside a pixel",
}
