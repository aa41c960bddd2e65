"""Exercise ``sample_span`` (lesson 01 with lesson 08, task 2.2): one raster line's span at a sample.

Task 2.1 asks for the columns whose *centres* (col + ½, row + ½) a triangle covers; lesson 01
prints that loop with its ½ written out five times. Task 2.2 asks for the columns whose *sample
point* (col + sx, row + sy) is covered, for a sample offset (sx, sy) inside the pixel measured
from its top-left corner, y down (CONVENTIONS.md, *Multisampling*; the standard 4× pattern
``tr.sample_pattern(4)``, in 1/16 px). The student has to see which ½ is the sample's x and
which its y, and that the top-left rule does not move: the samples of row ``row`` lie on the
line y = row + sy, the rows are those with y1 ≤ row + sy < y3 (a top edge on that line owns
its samples), and the covered columns are ⌈x_l − sx⌉ ≤ col < ⌈x_r − sx⌉.

Expected answers cost nothing new: a point p lies in a triangle T exactly when p + d lies in
T + d, so the sample (col + sx, row + sy) is covered by T exactly when the centre (col + ½,
row + ½) is covered by T moved by d = (½ − sx, ½ − sy). The offsets are multiples of 1/16
px, so the moved vertices stay on the 1/256-px grid and 2.1's exact columns
(:func:`.spans.exact_columns`) give the answer exactly; the tests check it against the
package's own multisample coverage. The cases are 2.1's near ones moved the other way (the
sample falls where 2.1's centre fell: ties on samples, vertices on sample lines), each at one
of the four standard positions, and rows built for the new mistakes: a middle vertex between
the sample line and the centre line (a split decided at row + ½ takes the wrong short edge),
a top or bottom vertex between them (rows counted at row + ½).
"""

from __future__ import annotations

import math
from dataclasses import replace
from fractions import Fraction
from functools import cache

import numpy as np

from ..core.fill import rasterize
from ..study.exact_spans import span_fill_int_dda
from .cases import drawn_coverage, drawn_rng, winding
from .drawing import note_beside
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .scalars import num
from .spans import MISTAKES as SPAN_WORDS
from .spans import (
    Span,
    as_span,
    crossings,
    edge_variants,
    exact_columns,
    same_span,
    small_area_fits,
    small_area_words,
    span_cases,
    span_words,
)

HALF = Fraction(1, 2)

#: Direct3D's standard 4× positions (``tr.sample_pattern(4)``), from the pixel's top-left
#: corner, y down, exact in 1/16 px (CONVENTIONS.md, *Multisampling*)
STANDARD_4 = ((Fraction(6, 16), Fraction(2, 16)), (Fraction(14, 16), Fraction(6, 16)),
              (Fraction(2, 16), Fraction(10, 16)), (Fraction(10, 16), Fraction(14, 16)))  # fmt: skip

#: The widest triangle asked (px): a scan of the bounding box's columns, each sample tested
#: with the edge functions, is a right answer too and must finish well within the budget
MAX_WIDTH = 200


def columns_at(xy, row: int, ox, oy) -> frozenset:
    """The columns of ``row`` whose point (col + ox, row + oy) the triangle covers (top-left
    rule), exactly: 2.1's columns of the triangle moved by (½ − ox, ½ − oy). Any offsets (a
    wrong solution's too) on the 1/256-px grid.

    >>> xy = np.array([[0.0, 0.0], [8.0, 0.0], [0.0, 8.0]])
    >>> sorted(columns_at(xy, 2, Fraction(3, 8), Fraction(1, 8)))  # x_r = 5.875
    [0, 1, 2, 3, 4, 5]
    """
    d = np.array([float(HALF - Fraction(ox)), float(HALF - Fraction(oy))])
    return exact_columns(np.asarray(xy, dtype=float) + d, row)


def sample_columns(xy, row: int, sample) -> frozenset:
    """The right answer: the columns whose sample point ``sample`` = (sx, sy) is covered."""
    sx, sy = (Fraction(float(s)) for s in sample)
    return columns_at(xy, row, sx, sy)


def _fractions(sample) -> tuple[Fraction, Fraction]:
    return Fraction(float(sample[0])), Fraction(float(sample[1]))


# -- cases ------------------------------------------------------------------------------------
def sample_span_cases() -> list[tuple[str, tuple, frozenset]]:
    """(label, (xy, row, sample), covered columns): the fixed cases (built once, then copied),
    then rows of triangles drawn for this check at a sample drawn with them."""
    out = [(label, (xy.copy(), row, sample), cols) for label, (xy, row, sample), cols
           in _fixed_cases()]  # fmt: skip
    rng = drawn_rng()
    for case in drawn_coverage(2):
        xy = case.triangles[0]
        k = int(rng.integers(4))
        lo, hi = math.floor(float(xy[:, 1].min())), math.ceil(float(xy[:, 1].max()))
        for row in sorted({lo, (lo + hi) // 2, hi - 1}):
            sample = tuple(float(s) for s in STANDARD_4[k])
            out.append((f"{case.label}, row {row}, sample {k}", (xy.copy(), row, sample),
                        sample_columns(xy, row, sample)))  # fmt: skip
    return out


@cache
def _fixed_cases() -> list[tuple[str, tuple, frozenset]]:
    built = _built_cases()
    moved = _moved_cases()
    # first: a row whose two crossings lie exactly on samples (the drawing of a passing check)
    return moved[:1] + built + _hair_cases() + _half_cases() + moved[1:]


def _half_cases() -> list[tuple[str, tuple, frozenset]]:
    """r477: a vertical left edge at x = col + sx + ½, halfway between two samples: ⌈x_l − sx⌉
    and round(x_l − sx) give the right first column, ⌈x_l − sx − ½⌉ (both ½ and sx taken
    off) one column left of it (at samples 0 and 3)."""
    out = []
    for k in (0, 3):
        sx, _ = _floats(k)
        row = 9
        xy = np.array([[sx + 1.5, row - 1.0], [sx + 1.5, row + 2.0], [sx + 9.5, row + 0.5]])
        label = f"x_l halfway between two samples (a vertical left edge), row {row}, sample {k}"
        out.append((label, (xy, row, _floats(k)), sample_columns(xy, row, _floats(k))))
    return out


#: r477 P1-P3: an exact crossing off a sample lies at least 1/(256·d) px from it, d the edge's
#: height in 1/256 px. This long edge, 515/256 px wide and d = 25 165 819 (98 304 px, odd: no
#: binary fraction) tall, crosses the line 12 509 611/256 px below its top vertex 1/(256·d) ≈
#: 1.6e-10 px right of a sample (12 509 611 · 515 ≡ 1 mod 256·d): an epsilon of 1e-9 on the
#: ends moves that end, float64 does not; narrow, so that a fill of its bounding box (the
#: package's, whose call is not counted) stays well within a case's time
HAIR_EDGE = (515, 25165819, 12509611)  # (width, height, depth), in 1/256 px


def _hair_cases() -> list[tuple[str, tuple, frozenset]]:
    """Rows whose long edge crosses the sample line a hair (≈1.6e-10 px) right of a sample:
    as x_l (the sample just left of it not covered) at samples 0 and 2, as x_r (covered) at
    samples 1 and 3."""
    width, height, depth = (Fraction(n, 256) for n in HAIR_EDGE)
    out = []
    for k, (sx, sy) in enumerate(STANDARD_4):
        row = math.ceil(depth)
        top = row + sy - depth  # the line y = row + sy lies depth below the top vertex
        side = 8 if k % 2 == 0 else -8  # the middle vertex right: the long edge is x_l
        middle = top + Fraction(round(128 * height), 256)
        v = [(sx, top), (sx + width, top + height), (sx + side, middle)]
        xy = np.array([[float(x), float(y)] for x, y in v])
        end = "x_l" if side > 0 else "x_r"
        label = f"{end} 1.6e-10 px right of a sample (not on it), row {row}, sample {k}"
        out.append((label, (xy, row, _floats(k)), sample_columns(xy, row, _floats(k))))
    return out


def _moved_cases() -> list[tuple[str, tuple, frozenset]]:
    """2.1's near, narrow cases moved by −d = (sx − ½, sy − ½): its centres become samples,
    so its expected columns carry over. The ties (a crossing exactly on a centre) at all four
    positions, the rest at one each, in turn."""
    out = []
    for n, (label, (xy, row), cols) in enumerate(_near_span_cases()):
        k = n % 4
        sx, sy = STANDARD_4[k]
        moved = xy + np.array([float(sx - HALF), float(sy - HALF)])
        words = label.replace("centre line", "sample line").replace("centres", "samples")
        words = words.replace("a centre", "a sample")
        out.append((f"{words}, sample {k}", (moved, row, _floats(k)), cols))
    return out


def _near_span_cases() -> list[tuple[str, tuple, frozenset]]:
    """2.1's fixed cases near the origin and at most :data:`MAX_WIDTH` px wide (its far rows
    are about exactness in float64, not asked again here), one row of each triangle but on
    its ties (a crossing or a vertex exactly on the centre line), whose rows are all kept."""
    out, seen = [], set()
    for label, (xy, row), cols in span_cases():
        xy = np.asarray(xy, dtype=float)
        if "drawn for this check" in label or "pixels' top" in label:
            continue
        if float(np.abs(xy).max()) > 2e5 or float(np.ptp(xy[:, 0])) > MAX_WIDTH:
            continue
        tie = "on a centre" in label or "centre line" in label
        key = xy.tobytes()
        if tie or key not in seen:
            out.append((label, (xy, row), cols))
            seen.add(key)
    return out


def _floats(k: int) -> tuple[float, float]:
    return float(STANDARD_4[k][0]), float(STANDARD_4[k][1])


def _built_cases() -> list[tuple[str, tuple, frozenset]]:
    """Rows built for the new mistakes, at each standard position: the middle vertex between
    the sample line and the centre line (on either side of the long edge), and the top or the
    bottom vertex between them."""
    out = []
    for k, (_, sy) in enumerate(STANDARD_4):
        row = 3 + k
        between = float(sy + HALF) / 2 + row  # halfway from the sample line to the centre line
        for x2 in (24.0, -24.0):
            xy = np.array([[0.25, row - 1.0], [x2 + 0.125, between], [0.5, row + 1.0]])
            out.append((f"the middle vertex between the sample line and the centre line "
                        f"({'right' if x2 > 0 else 'left'} of the long edge), row {row}, "
                        f"sample {k}", (xy, row, _floats(k))))  # fmt: skip
        if sy < HALF:  # the bottom vertex between the lines: the sample line still inside
            xy = np.array([[-9.75, row - 1.0], [10.25, row - 1.0], [0.5, between]])
            what = "the bottom vertex between the sample line and the centre line"
        else:  # the top vertex between them: the sample line already inside
            xy = np.array([[0.5, between], [10.25, row + 2.0], [-9.75, row + 2.0]])
            what = "the top vertex between the centre line and the sample line"
        out.append((f"{what}, row {row}, sample {k}", (xy, row, _floats(k))))
    return [(label, args, sample_columns(*args)) for label, args in out]


# -- reading and comparing --------------------------------------------------------------------
def as_sample_span(value):
    """The student's (first, stop), read as 2.1's (:func:`.spans.as_span`)."""
    return as_span(value)


# -- why a span is wrong ----------------------------------------------------------------------
def _tie_rounded(xy, row: int, sample, first, stop, ox=None, ox_stop=None, pair=None):
    """The columns ``first(x_l − ox)`` ≤ col < ``stop(x_r − ox_stop)`` on the sample line (the
    offsets sx unless given; ``pair(first, stop)``: what the student then does with them),
    2.1's rows and horizontal edges kept (a slip of the rounding only)."""
    sx, sy = _fractions(sample)
    right = sample_columns(xy, row, sample)
    cross = crossings(xy, row + sy)
    if cross is None or not right and not _inside(xy, row + sy):
        return right
    ox = sx if ox is None else ox
    lo, hi = first(cross[0] - ox), stop(cross[1] - (ox if ox_stop is None else ox_stop))
    if pair is not None:
        lo, hi = pair(lo, hi)
    return None if hi - lo > 10**6 else frozenset(range(lo, hi))


def _inside(xy, y: Fraction) -> bool:
    """The line at y has samples the rule may cover: y1 ≤ y < y3 and no bottom edge on it."""
    ys = sorted(Fraction(float(p[1])) for p in xy)
    if not ys[0] <= y < ys[2]:
        return False
    return not (ys[1] == ys[2] == y)


def _split_at_centre(xy, row: int, sample, line=HALF) -> frozenset | None:
    """The crossings on the sample line, but the short edge chosen by another line (row +
    ``line`` against y2; the centre line by default): beyond the middle vertex that edge is
    extended past its end."""
    sx, sy = _fractions(sample)
    v = sorted(((Fraction(float(x)), Fraction(float(y))) for x, y in xy), key=lambda p: p[1])
    (x1, y1), (x2, y2), (x3, y3) = v
    y, centre = row + sy, row + line
    right = sample_columns(xy, row, sample)
    if not right or y1 == y2 or y2 == y3 or (y < y2) == (centre < y2):
        return right

    def at(a, b):
        return a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])

    short = at(v[0], v[1]) if centre < y2 else at(v[1], v[2])
    lo, hi = sorted((at(v[0], v[2]), short))
    return frozenset(range(math.ceil(lo - sx), max(math.ceil(hi - sx), math.ceil(lo - sx))))


def _rows_at_centre(xy, row: int, sample, line=HALF) -> frozenset | None:
    """Rows counted by another line (y1 ≤ row + ``line`` < y3; the centre line by default),
    the columns at the sample."""
    right = sample_columns(xy, row, sample)
    ys = sorted(Fraction(float(p[1])) for p in xy)
    return right if ys[0] <= row + line < ys[2] else frozenset()


def _horizontal_slips(xy, row: int, sample) -> dict[str, frozenset | None]:
    """r477: a top edge along the sample line left out; a bottom edge along it covered."""
    sx, sy = _fractions(sample)
    right = sample_columns(xy, row, sample)
    ys = sorted((Fraction(float(p[1])), Fraction(float(p[0]))) for p in xy)
    (y1, a), (y2, b), (y3, c) = ys
    y = row + sy
    top = frozenset() if y1 == y2 == y and y3 != y else right
    bottom = right
    if y2 == y3 == y and y1 != y:
        lo, hi = sorted((b, c))
        bottom = frozenset(range(math.ceil(lo - sx), math.ceil(hi - sx)))
    return {"top edge left out": top, "bottom edge owns its samples": bottom}


def _more_variants(xy, row: int, sample) -> dict[str, frozenset | None]:
    """r477: 2.1's rounding slips at the sample, other wrong points and lines, the rows, the
    split on another line, another sample, a coarser grid."""
    sx, sy = _fractions(sample)
    half_up = lambda t: math.floor(t + HALF)  # noqa: E731
    ceil = math.ceil
    eps = lambda t: math.ceil(t - Fraction(1, 10**6))  # noqa: E731 (a sample a hair off, on)
    out = {
        "epsilon": _tie_rounded(xy, row, sample, eps, eps),
        "round(x − sx)": _tie_rounded(xy, row, sample, round, round),
        "⌊x − sx + ½⌋": _tie_rounded(xy, row, sample, half_up, half_up),
        "⌊x − sx⌋ at both ends": _tie_rounded(xy, row, sample, math.floor, math.floor),
        "first floored": _tie_rounded(xy, row, sample, math.floor, ceil),
        "stop floored": _tie_rounded(xy, row, sample, ceil, math.floor),
        "int(x − sx)": _tie_rounded(xy, row, sample, int, int),
        "stop + 1": _tie_rounded(xy, row, sample, ceil, lambda t: ceil(t) + 1),
        "last, not stop": _tie_rounded(xy, row, sample, ceil, lambda t: ceil(t) - 1),
        "clip at 0": _tie_rounded(
            xy, row, sample, ceil, ceil, pair=lambda a, b: (max(a, 0), max(b, 0))
        ),  # fmt: skip
        "½ left in the stop": _tie_rounded(xy, row, sample, ceil, ceil, ox_stop=HALF),
        "½ left in the first": _tie_rounded(xy, row, sample, ceil, ceil, ox=HALF, ox_stop=sx),
        "x mirrored": columns_at(xy, row, 1 - sx, sy),
        "y mirrored": columns_at(xy, row, sx, 1 - sy),
        "sx on the line": columns_at(xy, row, sx, sx),
        "offsets less ½": columns_at(xy, row, sx - HALF, sy - HALF),
        "½ and sx in x": columns_at(xy, row, HALF + sx, sy),
        "sx twice": columns_at(xy, row, 2 * sx, sy),
        "line y = row + sy − ½": columns_at(xy, row, sx, sy - HALF),
        "rows at y = row": _rows_at_centre(xy, row, sample, line=Fraction(0)),
        "rows clipped at 0": sample_columns(xy, row, sample) if row >= 0 else frozenset(),
        "split at y = row": _split_at_centre(xy, row, sample, line=Fraction(0)),
        "split at y = row + 1": _split_at_centre(xy, row, sample, line=Fraction(1)),
        "vertices on the 1/16 grid": sample_columns(
            np.round(16 * np.asarray(xy, float)) / 16, row, sample
        ),  # fmt: skip
    }
    out.update(_horizontal_slips(xy, row, sample))
    out.update(_read_slips(xy, row, sample))
    out.update(edge_slips(xy, row, sample))
    out.update({f"sample {k}": columns_at(xy, row, ox, oy) for k, (ox, oy) in enumerate(STANDARD_4)
                if (ox, oy) != (sx, sy)})  # fmt: skip
    return out


def _read_slips(xy, row: int, sample) -> dict[str, frozenset | None]:
    """r492 H5-H9: the offsets read wrong (sy in the rounding; in 1/16 px or in px inside
    1/256-px arithmetic), the ceiling made as int(t) + 1, the bounding box's columns."""
    sx, sy = _fractions(sample)
    out = {
        "sy in the rounding": columns_at(xy, row, sy, sy),
        "offsets in 1/16 px": columns_at(xy, row, sx / 16, sy / 16),
        "offsets in px, vertices in 1/256 px": columns_at(xy, row, sx / 256, sy / 256),
        "int(x − sx) + 1": _tie_rounded(xy, row, sample, _int_plus_1, _int_plus_1),
    }
    xs = [Fraction(float(p[0])) for p in xy]
    ys = [Fraction(float(p[1])) for p in xy]
    if min(ys) <= row + sy < max(ys):  # every row the triangle reaches, its box's columns
        out["bounding box"] = frozenset(range(math.ceil(min(xs) - sx), math.ceil(max(xs) - sx)))
    else:
        out["bounding box"] = frozenset()
    return out


def _int_plus_1(t) -> int:
    return int(t) + 1


#: r492 H1-H4: 2.1's wrong choices of the bounding edges, said at the sample
EDGE_SLIPS = ("long edge left", "no split", "no split, side test", "side x2 > x1", "side at row",
              "strict", "lower denominator", "no area test")  # fmt: skip


def edge_slips(xy, row: int, sample) -> dict[str, frozenset | None]:
    """r492 H1-H4: 2.1's wrong choices of the edges at the sample (2.1's on the triangle moved
    by (½ − sx, ½ − sy), whose centres are this triangle's samples), and the two ends returned
    the wrong way round (on every row with a span; on all but a top edge's: a side test's).

    >>> xy = np.array([[0.0, 0.0], [8.0, 4.0], [0.0, 8.0]])  # the middle vertex right
    >>> edge_slips(xy, 5, (0.375, 0.125))["x_l and x_r swapped"].pair
    (6, 0)
    """
    sx, sy = _fractions(sample)
    moved = np.asarray(xy, dtype=float) + np.array([float(HALF - sx), float(HALF - sy)])
    slips = edge_variants(moved, row)
    out = {kind: slips.get(kind) for kind in EDGE_SLIPS}
    right = sample_columns(xy, row, sample)
    out["first and stop swapped"] = out["x_l and x_r swapped"] = right
    if right:
        lo, hi = min(right), max(right) + 1
        out["first and stop swapped"] = _reversed(lo, hi)
        if not _horizontal(xy, row + sy):  # (along a top edge no side test picks the ends)
            out["x_l and x_r swapped"] = _reversed(lo, hi)
    return out


def _horizontal(xy, y: Fraction) -> bool:
    """A horizontal edge lies on the line at y."""
    return sum(Fraction(float(p[1])) == y for p in xy) >= 2


def _reversed(lo: int, hi: int) -> Span:
    """The pair (stop, first) of the columns lo ≤ col < hi: no column, told by its pair."""
    out = Span()
    out.pair = (hi, lo)
    return out


def _match(got, answer, args) -> bool:
    """r492: a pair the wrong way round (stop < first) is told by its pair, not as "no
    column" (any empty answer), as 2.1's (:func:`.spans.same_span` otherwise)."""
    mine, theirs = getattr(got, "pair", None), getattr(answer, "pair", None)
    wide = getattr(got, "wide", False) or getattr(answer, "wide", False)
    if (
        not wide
        and mine is not None
        and theirs is not None
        and (mine[1] < mine[0] or theirs[1] < theirs[0])
    ):
        return mine == theirs
    return same_span(got, answer)


def _variants(xy, row: int, sample) -> dict[str, frozenset | None]:
    """The columns typical wrong solutions give (exact; each a sample put elsewhere, or 2.1's
    rounding slips at the sample)."""
    sx, sy = _fractions(sample)
    floor1 = lambda t: math.floor(t) + 1  # noqa: E731 (the ceiling that excludes a tie)
    return {
        "2.1's span": columns_at(xy, row, HALF, HALF),
        "½ kept in x": columns_at(xy, row, HALF, sy),
        "½ kept in y": columns_at(xy, row, sx, HALF),
        "sx and sy swapped": columns_at(xy, row, sy, sx),
        "sx left out": columns_at(xy, row, 0, sy),
        "sy left out": columns_at(xy, row, sx, 0),
        "offsets from the centre": columns_at(xy, row, HALF + sx, HALF + sy),
        "offset added in x": columns_at(xy, row, -sx, sy),
        "line y = row − sy": columns_at(xy, row, sx, -sy),
        "offset added in x and y": columns_at(xy, row, -sx, -sy),
        # 2.1's span of the triangle moved by (sx − ½, sy − ½), the wrong way: the sample
        # mirrored through the centre, (1 − sx, 1 − sy) (the 4× pattern's opposite sample)
        "moved the wrong way": columns_at(xy, row, 1 - sx, 1 - sy),
        "split at the centre line": _split_at_centre(xy, row, sample),
        "rows at the centre line": _rows_at_centre(xy, row, sample),
        "ties reversed at the sample": _tie_rounded(xy, row, sample, floor1, floor1),
        "right edge owns the sample": _tie_rounded(xy, row, sample, math.ceil, floor1),
        "left edge loses the sample": _tie_rounded(xy, row, sample, floor1, math.ceil),
        **_more_variants(xy, row, sample),
    }


def _other_line_words(kind: str):
    """The words of a split decided on ``kind``'s line (r477: y = row, y = row + 1)."""
    line = kind.removeprefix("split at ")

    def words(args, expected, got):
        return (
            f"you crossed the edges on the sample line y = row + sy = "
            f"{num(args[1] + float(args[2][1]))}, but chose the short edge by the line {line}: "
            f"the middle vertex (y2 = {num(sorted(float(p[1]) for p in args[0])[1])}) lies "
            "between the two lines, so you took the short edge on its other side, extended "
            "past its end. The split compares the line you cross, y = row + sy, with y2"
        )

    return words


def _other_sample_words(k: int):
    """The words of sample ``k``'s columns given for another sample (the argument unread)."""
    ox, oy = STANDARD_4[k]

    def words(args, expected, got):
        return (
            f"your columns are those of sample {k}, (sx, sy) = ({num(float(ox))}, "
            f"{num(float(oy))}), not of the sample asked, {_sample_words(args)}: `sample` is the "
            "row (sx, sy) of tr.sample_pattern(4) to test, given with each call; read the "
            "offsets from it"
        )

    return words


def _sample_words(args) -> str:
    _, row, (sx, sy) = args
    return f"(sx, sy) = ({num(sx)}, {num(sy)})"


MISTAKES = {
    "2.1's span": lambda args, expected, got: (
        f"yours is 2.1's span, the centres' columns: you kept both ½s of the centre (col + ½, "
        f"row + ½), but this sample, {_sample_words(args)}, lies at (col + sx, row + sy): its "
        "line is y = row + sy, and a column is covered when its sample point col + sx lies "
        "between the crossings"
    ),
    "½ kept in x": lambda args, expected, got: (
        f"you put the samples on the right line, y = row + sy, but rounded the crossings to "
        f"columns as if they still lay at x = col + ½: this sample, {_sample_words(args)}, lies "
        "at x = col + sx (the ½ of 2.1's rounding is the centre's x; here it is the sample's)"
    ),
    "½ kept in y": lambda args, expected, got: (
        f"you rounded the crossings for x = col + sx, but crossed the edges with 2.1's centre "
        f"line y = row + ½: this sample, {_sample_words(args)}, lies on the line y = row + sy "
        f"= {num(args[1] + float(args[2][1]))} (the ½ of 2.1's line is the centre's y)"
    ),
    "sx and sy swapped": lambda args, expected, got: (
        f"you swapped the sample's two offsets: {_sample_words(args)} is (x, y), sx across "
        "from the pixel's left side and sy down from its top, so the line is y = row + sy and "
        "the samples lie at x = col + sx"
    ),
    "sx left out": lambda args, expected, got: (
        f"you rounded the crossings to columns as if the sample lay at x = col, the pixel's "
        f"left side: this sample, {_sample_words(args)}, lies sx to the right of it, at "
        "x = col + sx"
    ),
    "sy left out": lambda args, expected, got: (
        f"you crossed the edges with the line y = row, the pixels' top: this sample, "
        f"{_sample_words(args)}, lies sy below it, on y = row + sy = "
        f"{num(args[1] + float(args[2][1]))}"
    ),
    "offsets from the centre": lambda args, expected, got: (
        f"you measured the offsets from the pixel's centre, putting the sample at (col + ½ + "
        f"sx, row + ½ + sy): the offsets {_sample_words(args)} are measured from the pixel's "
        "top-left corner (col, row), y down, as tr.sample_pattern gives them (each in [0, 1), "
        "inside the pixel), so the sample lies at (col + sx, row + sy)"
    ),
    "offset added in x": lambda args, expected, got: (
        f"your columns are shifted right: you added sx to the crossings where it comes off "
        f"them. Column col's sample lies at x = col + sx (here sx = {num(args[2][0])}), so it "
        "lies at or right of x_l when col ≥ x_l − sx, not x_l + sx"
    ),
    "line y = row − sy": lambda args, expected, got: (
        f"you crossed the edges with the line y = row − sy, above the pixels: y is down, and "
        f"the sample {_sample_words(args)} lies sy below the pixel's top, on y = row + sy"
    ),
    "offset added in x and y": lambda args, expected, got: (
        f"you moved the sample the wrong way in x and y: with {_sample_words(args)} measured "
        "from the pixel's top-left corner, y down, the sample lies at (col + sx, row + sy), "
        "so its line is y = row + sy and col is covered when col + sx lies between the "
        "crossings (col ≥ x_l − sx, not x_l + sx)"
    ),
    "moved the wrong way": lambda args, expected, got: (
        f"yours is the span of the sample mirrored through the pixel's centre, at (col + 1 − "
        f"sx, row + 1 − sy) for {_sample_words(args)}: if you moved the triangle so that the "
        "sample falls on the centre, and took 2.1's span of it, you moved it the wrong way. A "
        "point p lies in the triangle exactly when p + d lies in the triangle moved by d: "
        "which d takes the sample (col + sx, row + sy) to the centre (col + ½, row + ½)?"
    ),
    "split at the centre line": lambda args, expected, got: (
        f"you crossed the edges on the sample line y = row + sy = "
        f"{num(args[1] + float(args[2][1]))}, but chose the short edge by the centre line "
        f"row + ½: the middle vertex (y2 = {num(sorted(float(p[1]) for p in args[0])[1])}) "
        "lies between the two lines, so you took the short edge on its other side, extended "
        "past its end. The split compares the line you cross, y = row + sy, with y2"
    ),
    "rows at the centre line": lambda args, expected, got: (
        f"you decided whether row {args[1]} meets the triangle by its centre line row + ½, "
        f"but its samples lie on y = row + sy = {num(args[1] + float(args[2][1]))}: a row "
        "has covered samples when y1 ≤ row + sy < y3 (here a vertex lies between the two "
        "lines)"
    ),
    "ties reversed at the sample": "your ties go the wrong way round at the sample: a sample "
    "exactly on x_l (the left edge) you left out and one exactly on x_r (the right edge) you "
    "covered. The top-left rule is about the point tested, whatever its offset: a sample on a "
    "left edge is covered, one on a right edge is not, as a centre in 2.1 (⌈x − sx + ε⌉, an "
    "epsilon added for safety, does exactly this)",
    "right edge owns the sample": "you covered the sample that lies exactly on the right edge: "
    "the top-left rule does not change at a sample (a right edge owns none of its points; the "
    "span stops before it; an edge test E ≥ 0 on all three edges, with no tie rule, covers it)",
    "left edge loses the sample": "you left out the sample that lies exactly on the left edge: "
    "the top-left rule does not change at a sample (a left edge owns its points; an edge test "
    "E > 0 on all three edges, with no tie rule, leaves it out, and a top edge's samples too)",
    "epsilon": lambda args, expected, got: _epsilon_words(args, expected, got),
    **{kind: _other_line_words(kind) for kind in ("split at y = row", "split at y = row + 1")},
    "rows at y = row": lambda args, expected, got: (
        f"you decided whether row {args[1]} meets the triangle by the line y = row, the pixels' "
        f"top, but its samples lie on y = row + sy = {num(args[1] + float(args[2][1]))}: a row "
        "has covered samples when y1 ≤ row + sy < y3 (here a vertex lies between the two "
        "lines)"
    ),
    "rows clipped at 0": lambda args, expected, got: (
        f"you left out the rows above row 0 (here row {args[1]}): the rows are the plane's, "
        "negative ones too (no image clips them here, as lesson 01's raster_lines clips them "
        "to its image with max(first, 0))"
    ),
    "top edge left out": "the sample line runs along the triangle's horizontal top edge, and "
    "you covered none of its samples: a top edge (the triangle below it) owns the samples on "
    "it, at a sample as at a centre (rows taken as y1 < row + sy ≤ y3, the row test turned "
    "round, leave that line out too)",
    "bottom edge owns its samples": "the sample line runs along the triangle's horizontal "
    "bottom edge, and you covered its samples: a bottom edge (the triangle above it) owns none "
    "(the row test y1 ≤ row + sy < y3 leaves that line out)",
    "round(x − sx)": "you rounded x − sx to the nearest column (round()): the first covered "
    "column is the first whose sample col + sx lies at or right of x_l, a ceiling, not the "
    "nearest; and the stop the same ceiling of x_r − sx",
    "⌊x − sx + ½⌋": "you rounded x − sx to the nearest column (⌊x − sx + ½⌋): the first "
    "covered column is the first whose sample col + sx lies at or right of x_l, a ceiling, not "
    "the nearest; and the stop the same ceiling of x_r − sx",
    "⌊x − sx⌋ at both ends": "you floored both ends (⌊x − sx⌋): the floor gives the last "
    "column whose sample lies at or left of the crossing; the first covered column is the "
    "first at or right of x_l (a ceiling), and the stop the same ceiling of x_r − sx",
    "first floored": "your first column is one too far left: you floored x_l − sx, which gives "
    "the column whose sample lies at or left of x_l, outside the triangle; the first covered "
    "sample is the first at or right of x_l (a ceiling)",
    "stop floored": "your stop is one too small: you floored x_r − sx, which is the last "
    "covered column, not the one past it (stop is exclusive: first ≤ col < stop)",
    "int(x − sx)": "you rounded with int(), which truncates toward zero: neither the ceiling "
    "the first covered sample needs (col + sx at or right of x_l) nor, for negative x, a "
    "floor",
    "stop + 1": "your stop is one too large: it covers the column whose sample lies at or "
    "right of x_r, outside the triangle (stop is the first column past the span, the ceiling "
    "of x_r − sx)",
    "last, not stop": "you returned the last covered column as the second number: it is the "
    "stop, one past it (first ≤ col < stop, as in 2.1)",
    "clip at 0": "you clipped the columns at 0 (lesson 01 clips them to its image): the "
    "columns are the plane's, negative ones too",
    "½ left in the stop": "your first column is rounded for the sample (x_l − sx), but your stop "
    "still for the centre (x_r − ½): both ends are the same question, which columns' samples "
    "col + sx lie between the crossings",
    "½ left in the first": "your stop is rounded for the sample (x_r − sx), but your first "
    "column still for the centre (x_l − ½): both ends are the same question, which columns' "
    "samples col + sx lie between the crossings",
    "x mirrored": lambda args, expected, got: (
        f"you put the sample at x = col + 1 − sx, measured from the pixel's right side: "
        f"{_sample_words(args)} are measured from the top-left corner, so the sample lies at "
        "x = col + sx"
    ),
    "y mirrored": lambda args, expected, got: (
        f"you crossed the edges with the line y = row + 1 − sy, as if sy were measured up "
        f"from the pixel's bottom: y is down and {_sample_words(args)} is measured from the "
        f"top-left corner, so the line is y = row + sy = {num(args[1] + float(args[2][1]))}"
    ),
    "sx on the line": lambda args, expected, got: (
        f"you crossed the edges with the line y = row + sx: the line of the samples is y = row "
        f"+ sy = {num(args[1] + float(args[2][1]))} ({_sample_words(args)}: sx is the x offset)"
    ),
    "offsets less ½": lambda args, expected, got: (
        f"you put the sample at (col + sx − ½, row + sy − ½), half a pixel up and left: "
        f"{_sample_words(args)} is measured from the pixel's top-left corner (col, row), so "
        "the sample lies at (col + sx, row + sy) (as offsets from the centre they would be "
        "sx − ½ and sy − ½, added to col + ½ and row + ½)"
    ),
    "½ and sx in x": lambda args, expected, got: (
        f"you took both ½ and sx off the crossings (⌈x − sx − ½⌉): the sample lies at x = col "
        f"+ sx ({_sample_words(args)}), so a column is covered when col + sx lies between the "
        "crossings; the ½ belongs to the centre, which this task does not test"
    ),
    "sx twice": lambda args, expected, got: (
        f"you took sx off the crossings twice (⌈x − 2·sx⌉): the sample lies at x = col + sx "
        f"({_sample_words(args)})"
    ),
    "line y = row + sy − ½": lambda args, expected, got: (
        f"you crossed the edges with the line y = row + sy − ½, half a pixel above the "
        f"samples: {_sample_words(args)} is measured from the pixel's top, so the line is "
        f"y = row + sy = {num(args[1] + float(args[2][1]))}"
    ),
    "vertices on the 1/16 grid": "your columns are those of the vertices rounded to the 1/16-px "
    "grid: the offsets are multiples of 1/16, but the vertices lie on the 1/256-px grid; keep "
    "them as they are (multiply by 256, or use fractions.Fraction)",
    **{f"sample {k}": _other_sample_words(k) for k in range(4)},
    # r492: 2.1's words for its edge slips, the same at a sample
    **{kind: SPAN_WORDS[kind] for kind in EDGE_SLIPS if kind != "strict"},
    "strict": SPAN_WORDS["strict"].replace("centre line", "sample line"),
    "first and stop swapped": SPAN_WORDS["first and stop swapped"],
    "x_l and x_r swapped": SPAN_WORDS["x_l and x_r swapped"],
    "sy in the rounding": lambda args, expected, got: (
        f"you took sy off the crossings (⌈x − sy⌉) where sx belongs: the line is y = row + sy, "
        f"but along it the sample lies at x = col + sx ({_sample_words(args)}), so the first "
        "column is ⌈x_l − sx⌉"
    ),
    "offsets in 1/16 px": lambda args, expected, got: (
        f"your samples lie at (col + sx/16, row + sy/16), near the pixel's top-left corner: you "
        f"read the offsets in 1/16 px (16·sx) but used them beside vertices in 1/256 px; in "
        f"1/256 px this sample, {_sample_words(args)}, is ({_steps(args, 0)}, {_steps(args, 1)})"
    ),
    "offsets in px, vertices in 1/256 px": lambda args, expected, got: (
        f"your samples lie at (col + sx/256, row + sy/256), at the pixel's top-left corner: you "
        f"scaled the vertices to 1/256 px but left the offsets in px; in 1/256 px this sample, "
        f"{_sample_words(args)}, is ({_steps(args, 0)}, {_steps(args, 1)})"
    ),
    "int(x − sx) + 1": "you made the ceiling as int(t) + 1: where t is whole (a sample exactly "
    "on a crossing) that is one too many, so a sample on the left edge is left out and one on "
    "the right edge covered; and int() truncates toward zero, so left of x = 0 your ends are "
    "one column further right still: the ceiling is math.ceil (or −(−n // d) in integers)",
    "bounding box": "your span is the triangle's bounding box: ⌈min x − sx⌉ to ⌈max x − sx⌉ on "
    "every row it reaches; a row's samples lie between the two edges' crossings with the "
    "sample line, x_l and x_r (the long edge and a short one), which on most rows lie inside "
    "the box",
}


def _steps(args, axis: int) -> int:
    """The sample's offset along ``axis`` in 1/256-px steps."""
    return round(256 * float(args[2][axis]))


#: Words that give the rounding away, said as the hint until two different answers have failed
#: (:attr:`~.exercise.Exercise.hints`, as 2.1's)
HINTS = (
    ("so it lies at or right of x_l when col ≥ x_l − sx, not x_l + sx", "so which columns' "
     "samples lie at or right of x_l?"),
    (" (col ≥ x_l − sx, not x_l + sx)", ""),
    (": a row has covered samples when y1 ≤ row + sy < y3 (here", ": which rows does the "
     "sample line meet? (here"),
)  # fmt: skip


def _moved_ends(args, got) -> list[tuple[str, Fraction, int]] | None:
    """(x_l or x_r, its exact crossing, the student's end) of each end one column off the
    rule's, on a row with two slanted crossings (None: another row, or an end further off)."""
    xy, row, sample = args
    sx, sy = _fractions(sample)
    pair = getattr(got, "pair", None)
    cross = crossings(xy, row + sy)
    if pair is None or cross is None or not _inside(xy, row + sy):
        return None
    if any(p[1] == row + sy for p in ((Fraction(float(a)), Fraction(float(b))) for a, b in xy)):
        return None  # a vertex on the sample line: its ends are no computed crossing
    out = []
    for name, end, x in zip(("x_l", "x_r"), pair, cross):
        right = math.ceil(x - sx)
        if abs(end - right) > 1:
            return None
        if end != right:
            out.append((name, x, end))
    return out or None


def _tie_lands_off(args, expected, got) -> bool | None:
    """Every moved end's exact crossing lies exactly on a sample (col + sx): a float crossing
    landed a hair off it."""
    moved = _moved_ends(args, got)
    if moved is None:
        return None
    sx = _fractions(args[2])[0]
    return all((x - sx).denominator == 1 for _, x, _ in moved)


def _tie_words(args, expected, got) -> str:
    sx = _fractions(args[2])[0]
    name, x, _ = next(m for m in _moved_ends(args, got) or () if (m[1] - sx).denominator == 1)
    return (
        f"{name} = {num(float(x))} lies exactly on the sample of column {int(x - sx)} "
        f"({int(x - sx)} + sx), and your {name} came out a hair off it, so the tie went the other "
        "way: a crossing computed in floats (divided first, or through a slope) rounds; compute "
        "it exactly, as in 2.1 (integers of 1/256 px, or fractions.Fraction)"
    )


def _float32_fits(args, expected, got) -> bool | None:
    """Far out (10^4 px and more), each moved end's crossing lies within a few float32 steps
    of the sample it moved past, and on none (a tie is :func:`_tie_lands_off`'s)."""
    xy = args[0]
    far = float(np.abs(xy).max())
    moved = _moved_ends(args, got)
    if moved is None or far < 1e4:
        return None
    sx = _fractions(args[2])[0]
    near = 4 * float(np.spacing(np.float32(far)))
    gaps = [abs(float(x - sx - round(x - sx))) for _, x, _ in moved]
    return all(0 < g <= near for g in gaps)


def _float32_words(args, expected, got) -> str:
    far = float(np.abs(args[0]).max())
    return (
        f": {num(far)} px from the origin float32 numbers are "
        f"{num(float(np.spacing(np.float32(far))))} px apart and cannot hold the vertices' "
        "1/256-px grid, so a crossing computed in float32 can move past a sample. Did you "
        "compute in float32? Compute exactly (or in float64)"
    )


def _hair_ends(args, got) -> list[tuple[str, Fraction, int]] | None:
    """The moved ends whose exact crossing lies within 10^-6 px of a sample but not on it
    (None unless every moved end does)."""
    moved = _moved_ends(args, got)
    if moved is None:
        return None
    sx = _fractions(args[2])[0]
    gaps = [x - sx - round(x - sx) for _, x, _ in moved]
    return moved if all(0 < abs(g) < Fraction(1, 10**6) for g in gaps) else None


def _epsilon_words(args, expected, got) -> str:
    """r477 P1-P3: an end a hair off a sample moved as if the sample lay on the edge."""
    sx = _fractions(args[2])[0]
    hair = _hair_ends(args, got)
    if not hair:
        return (
            "an end of yours moved by one column where a crossing lies a hair off a sample: "
            "an epsilon on the ends? The crossings are exact here; no tolerance is needed"
        )
    name, x, end = hair[0]
    col = round(x - sx)
    gap = float(x - sx - col)
    where, covered = ("right", name == "x_r") if gap > 0 else ("left", name == "x_l")
    what = "first" if name == "x_l" else "stop"
    return (
        f"{name} lies {abs(gap):.2g} px {where} of the sample of column {col} ({col} + sx), "
        f"not on it, so that sample is {'' if covered else 'not '}covered; your {what} = {end} "
        "treats it as lying on the edge: an epsilon on the ends (for safety), or a crossing "
        "snapped to a sample within a tolerance? The crossings are exact here (integers or "
        "fractions.Fraction; float64 multiplied first is exact enough in this range), so no "
        "tolerance is needed, and any tolerance moves some sample that close"
    )


#: r477: kinds named only where they contradict no passing answer (a float crossing that lands
#: a hair off a few left ties is no rule that leaves out every sample on a left edge)
CONSISTENT = ("rows at the centre line", "split at the centre line",  # r492 M1, M2
              "ties reversed at the sample", "right edge owns the sample",
              "left edge loses the sample",
              *list(MISTAKES)[list(MISTAKES).index("left edge loses the sample") + 1:])  # fmt: skip


def _outside_fits(args, expected, got) -> bool | None:
    """r477: columns on a row whose sample line misses the triangle (no row test, or rows
    counted by the pixels the triangle touches)."""
    xy, row, sample = args
    if expected or getattr(got, "pair", None) is None or not got:
        return None
    return not _inside(xy, row + _fractions(sample)[1])


def _outside_words(args, expected, got) -> str:
    return (
        f"the sample line y = {num(args[1] + float(args[2][1]))} does not meet the triangle "
        "(or runs along its bottom edge), yet you covered columns on it: which rows does the "
        "sample line meet? A row has covered samples only when y1 ≤ row + sy < y3; beyond "
        "them the edges' lines, extended past the vertices, still cross it"
    )


def _swapped_fits(args, expected, got) -> bool | None:
    """r492 H4: this row's right pair the wrong way round, (stop, first) (x_l and x_r swapped
    on some rows only: the side judged on the vertices as given, say)."""
    pair = getattr(got, "pair", None)
    if pair is None or not expected:
        return None
    return pair == (max(expected) + 1, min(expected))


def _swapped_words(args, expected, got) -> str:
    return (
        f": your pair is this row's right one the wrong way round, {got.pair}: your x_l and x_r "
        "are swapped on this row, not on every row. Which crossing is x_l depends on which "
        "side of the long edge the middle vertex lies on, judged on the vertices sorted by y "
        "(x2 against the long edge at y2), not on the vertices in the order given, whose "
        "winding may be either"
    )


SYMPTOMS = (
    Mistake("row outside the triangle", _outside_words, fits=_outside_fits, symptom=True),
    Mistake("x_l and x_r swapped on this row", _swapped_words, fits=_swapped_fits, symptom=True),
    Mistake(
        "zero area by a tolerance",
        lambda args, expected, got: small_area_words(args[0], point="sample"),
        fits=lambda args, expected, got: small_area_fits(args[0], expected, got),
        symptom=True,
    ),  # fmt: skip
    Mistake("float32", _float32_words, fits=_float32_fits, symptom=True, only_whole=True),
    Mistake("tie lands off", _tie_words, fits=_tie_lands_off, symptom=True, only_whole=True),
)


def explain_sample_span(args, expected: frozenset, got: frozenset) -> str:
    """The sample line, its exact crossings, the covered samples and yours."""
    xy, row, sample = args
    sx, sy = _fractions(sample)
    y = row + sy
    where = f"row {row}'s samples {_sample_words(args)} lie on y = row + sy = {num(float(y))}"
    cross = crossings(xy, y)
    vertices = ", ".join(f"({num(p[0])}, {num(p[1])})" for p in xy)
    if cross is None:
        return (f"{where}, which does not cross this {winding(xy)} triangle ({vertices}), so no "
                f"sample is covered; yours covers {span_words(got, count=False)}")  # fmt: skip
    xl, xr = cross
    return (
        f"{where}, which crosses the triangle ({vertices}) from x_l = {_x_words(xl, sx)} to "
        f"x_r = {_x_words(xr, sx)}, so the covered samples col + sx are those of "
        f"{span_words(expected, count=False)}; yours: {span_words(got, count=False)}"
    )


def _x_words(x: Fraction, sx: Fraction) -> str:
    """x as a float; a hair off a sample (col + sx), as the sample and the gap (r477: 2.375 +
    7.8e-11 read as 2.375 would look like a tie)."""
    sample = round(x - sx) + sx
    if x != sample and abs(x - sample) < Fraction(1, 10**6):
        gap = float(x - sample)
        return f"{num(float(sample))} {'+' if gap > 0 else '−'} {abs(gap):.2g}"
    return num(float(x))


def _rule(args, expected, got) -> str:
    return (
        ": a column is covered when its sample point (col + sx, row + sy) is, by the same "
        "top-left rule as a centre: on the sample line, one on the left edge included and one "
        "on the right edge not; a top edge along the sample line owns its samples"
    )


def _constant(value) -> str:
    """A span that never changes, in the student's terms (as 2.1's: not ``frozenset()``)."""
    if not value and not getattr(value, "wide", False):
        pair = getattr(value, "pair", None)
        shown = f"{pair} " if pair else ""
        return (
            f"your function returns the same empty span {shown}(stop ≤ first: no column) on "
            "every case, whatever its arguments: a placeholder (such as `return 0, 0`) left "
            "in, or a `return` reached too early?"
        )
    return (
        f"your function returns {span_words(value, count=False)} on every case, whatever its arguments: "
        "a placeholder left in, or a `return` reached too early?"
    )


def _sample_span_none(args, expected) -> str:
    return (
        "returned None: return a pair (first, stop) on every row, (0, 0) for a row with no "
        "covered sample"
    )


# -- drawing ----------------------------------------------------------------------------------
def draw_sample_span(ax, case, got):
    """The triangle, the row's sample line, its samples coloured by state and the crossings."""
    from matplotlib.patches import Rectangle

    _, (xy, row, sample), expected = case
    sx, sy = (float(s) for s in sample)
    y = row + sy
    got_set = set() if got is None else set(got)
    shown = expected | got_set
    lo = math.floor(min(float(xy[:, 0].min()), min(shown, default=0))) - 1
    hi = math.ceil(max(float(xy[:, 0].max()), max(shown, default=0) + 1)) + 1
    if hi - lo > 40:
        mid = (min(shown) + max(shown)) // 2 if shown else (lo + hi) // 2
        lo, hi = mid - 20, mid + 20
    ring = np.vstack([xy, xy[:1]])
    artists = ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    artists.append(ax.axhline(y, color="#888888", linestyle=":", linewidth=1))
    colours = {"covered": "#c8c8c8", "missing": "#2b7bba", "extra": "#d7301f"}
    for col in range(lo, hi):
        rule, yours = col in expected, col in got_set
        state = ("covered" if rule else "") if got is None or rule == yours else (
            "missing" if rule else "extra")  # fmt: skip
        if state:
            artists.append(ax.add_patch(Rectangle((col, row), 1, 1, color=colours[state],
                                                  alpha=0.8)))  # fmt: skip
        artists += ax.plot(col + sx, y, ".", color="black", ms=4, zorder=4)
        artists += ax.plot(col + 0.5, row + 0.5, "+", color="#999999", ms=4, zorder=3)
    cross = crossings(xy, Fraction(float(y)))
    if cross is not None:
        artists += ax.plot([float(c) for c in cross], [y, y], "|", color="#ff9f1c", ms=14,
                           mew=3, label="x_l, x_r", zorder=3)  # fmt: skip
        # a sample exactly on a crossing, ringed above the tick (as 2.1's centres on one)
        ties = sorted({float(x) for x in cross if (x - Fraction(float(sx))).denominator == 1})
        if ties:
            artists += ax.plot(ties, [y] * len(ties), "o", mfc="none", mec="black", ms=9,
                               mew=1.2, zorder=5, label="sample on a crossing")  # fmt: skip
    for name, colour in colours.items():
        artists.append(ax.add_patch(Rectangle((0, 0), 0, 0, color=colour, label=name)))
    if got is None:
        note_beside(ax)
    artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    ax.set_xlim(lo, hi)
    top = max(min(float(xy[:, 1].min()), y) - 1, row - 6)
    bottom = min(max(float(xy[:, 1].max()), y) + 1, row + 8)
    tall = max(6.0, (hi - lo) / 3)  # a flat triangle is no strip (as 2.1's figure, r372 F1)
    if bottom - top < tall:
        middle = (top + bottom) / 2
        top, bottom = middle - tall / 2, middle + tall / 2
    ax.set_ylim(bottom, top)
    ax.set_aspect("equal")
    ax.set_xlabel(f"x (px); row {row}: its samples (·) at x = col + {num(sx)} on y = "
                  f"{num(y)} (+: centres)", fontsize="small")  # fmt: skip
    ax.set_ylabel("y (px, down)", fontsize="small")
    return artists


SAMPLE_SPAN = Exercise(
    "sample_span", sample_span_cases, as_sample_span, same_span, explain_sample_span, _rule,
    [replace(m, consistent=True, only_whole=m.kind == "epsilon") if m.kind in CONSISTENT
     else m for m in variant_mistakes(_variants, MISTAKES, SYMPTOMS)],
    answers=(
        PackageAnswer(rasterize),
        PackageAnswer(span_fill_int_dda, what="lesson 01's exact span fill (the integer DDA)",
                      modules=("teachraster.study.exact_spans",)),
    ),
    reference=("teachraster.exercises.spans", "teachraster.exercises.span_variants"),
    draw=draw_sample_span, constant=_constant, none_words=_sample_span_none,
    match=_match,
    hints=HINTS,
    slow=" (a loop over every column of a wide triangle? One row's span is two crossings)",
)  # fmt: skip
