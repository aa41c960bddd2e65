"""Exercise ``span`` (lesson 01): one raster line of a triangle, from its edges' crossings.

The span-table fill never tests a pixel: on raster line ``row`` it intersects the centre line
y = row + ½ with the triangle's edges (the two edges that bound it there change at the
middle vertex, the split) and turns the crossings x_l ≤ x_r into a range of columns. The
top-left rule becomes a rounding choice: a centre exactly on the left edge is covered, one
on the right edge is not, so the covered columns are ⌈x_l − ½⌉ ≤ col < ⌈x_r − ½⌉; a row
whose centre line runs along a horizontal edge is covered only if that edge is a top edge.

The expected columns come from the package's fill (:func:`teachraster.rasterize`, on a
window around the triangle); the crossings that explain them are exact (the vertices are on
the 1/256-px grid, so :class:`fractions.Fraction` holds every number exactly).
"""

from __future__ import annotations

import dataclasses
import math
import re
from fractions import Fraction
from functools import cache

import numpy as np

from ..core.fill import rasterize
from ..core.triangle import Triangle
from ..study.exact_spans import span_fill_int_dda
from .answers import as_numbers, short
from .cases import catalogue_coverage, copied, drawn_coverage, proper_triangles, winding
from .drawing import note_beside
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .running import WrongAnswerType
from .scalars import num
from .span_variants import (
    FAR_DIGITS,
    FAR_DIGITS_35,
    FAR_HAIR,
    FAR_NEAR_TIES,
    FAR_PRECISE,
    FAR_SIDES,
    FAR_TIES,
    FAR_WIDE_SIDES,
    FLOAT64_EXACT_BELOW,
    FLOOR_ROWS,
    NEAR_TIES,
    NO_FLOAT_ORDER,
    PLACED,
    PRECISION_KINDS,
    TIDY_KINDS,
    TIE_ENDS,
    TIE_ROWS,
    float_crossing,
    float_side_errs,
    more_variants,
    pair_columns,
)
from .span_variants import WORDS as MORE_WORDS


# -- cases ------------------------------------------------------------------------------------
def span_cases() -> list[tuple[str, tuple, frozenset]]:
    """(label, (xy, row), covered columns) for rows that decide: ties, the split, the ends
    (built once, then copied), and the rows of a few triangles drawn for this check, so a
    table of the fixed cases' answers fails (r46 X1)."""
    out = copied(_span_cases())
    for case in drawn_coverage():
        xy = case.triangles[0]
        rows = _rows(xy)
        covered = _covered_rows(xy, [row for row, _ in rows])
        out += [(f"{case.label}, row {row} ({why})", (xy.copy(), row), covered[row])
                for row, why in rows]  # fmt: skip
    return out


@cache
def _span_cases() -> list[tuple[str, tuple, frozenset]]:
    triangles = proper_triangles()
    flat = [(c.label, c.triangles[0]) for c in catalogue_coverage()
            if c.label in ("collinear", "coincident_vertices")]  # fmt: skip
    out = []
    chosen = [(label, xy) for label, xy in triangles if not label.startswith("random")
              or any(w in label for w in ("horizontal", "100000 px", "smaller than"))]  # fmt: skip
    for label, xy in chosen + flat:
        rows = _rows(xy)
        covered = _covered_rows(xy, [row for row, _ in rows])
        for row, why in rows:
            out.append((f"{label}, row {row} ({why})", (xy.copy(), row), covered[row]))
    # r39 02-1: far from the origin float32 cannot hold the 1/256-px grid, but no row above
    # turned on it (a float32 span passed every case): rows where it does
    for k, (xy, row) in enumerate(_float32_rows()):
        covered = _covered_rows(xy, [row])
        out.append((f"random far {k}, 100000 px from the origin, row {row} (float32 moves an "
                    "end)", (xy, row), covered[row]))  # fmt: skip
    out += _wide_cases() + _edge_cases() + _half_cases() + _r372_cases() + _r385_cases()
    out += _far_cases()  # last: a mistake of the table is named on the rows before them
    # first (the drawing of a passing check, and the first failure most students see): a row
    # with covered centres whose crossings of two slanted edges lie on centres (r355 S2: a row
    # along a top edge, whose x_l and x_r are vertices, was called "the left edge")
    first = next(k for k, case in enumerate(out) if case[2] and _slanted_tie(*case[1]))
    return [out[first]] + out[:first] + out[first + 1 :]


def _slanted_tie(xy: np.ndarray, row: int) -> bool:
    """The row's centre line crosses two slanted edges, each exactly on a centre."""
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    return (cross is not None and not _horizontal_edge(xy, row + 0.5)
            and all((x - Fraction(1, 2)).denominator == 1 for x in cross))  # fmt: skip


#: r355 M4, M5: rows no triangle above asks about. A middle vertex exactly on a centre line with
#: slanted edges on both sides of it (a strict ``min(ay, by) < y < max(ay, by)`` drops the
#: crossing there from both short edges, and passed every other row), in both windings and
#: with the middle vertex right and left of the long edge; and a zero-area triangle lying along
#: a centre line (without the area test its ends read as a horizontal edge's).
EDGE_CASES = (
    (
        "a middle vertex on the centre line, slanted edges",
        ((0.5, 0.5), (10.5, 5.5), (2.5, 10.5)),
        5,
    ),
    ("a middle vertex on the centre line, slanted edges", ((9.5, 0.5), (0.5, 4.5), (7.25, 9.5)), 4),
    ("a zero-area triangle along a centre line", ((0.5, 1.5), (5.5, 1.5), (3.25, 1.5)), 1),
    # r424 M1: a top edge 1/256 px below the pixels' top tells y = row + 1/256 (256·row + 1)
    # from row + 1/512 (256·row + 0.5), which no other row does
    ("a horizontal top edge 1/256 px below the pixels' top", ((1.25, 3.00390625),
     (9.75, 3.00390625), (5.5, 8.5)), 3),
)  # fmt: skip


def _edge_cases() -> list[tuple[str, tuple, frozenset]]:
    out = []
    for label, points, row in EDGE_CASES:
        xy = np.array(points)
        turn = "" if "zero-area" in label else f" ({winding(xy)})"
        out.append((f"{label}{turn}, row {row}", (xy, row), _covered_rows(xy, [row])[row]))
    return out


#: Half the base of the wide cases' triangles: 5·10^11 px (their vertices stay on the 1/256-px
#: grid in float64, whose integers are exact to 2^53 / 256 ≈ 3.5·10^13 px).
WIDE = 5 * 10**11


def _wide_cases() -> list[tuple[str, tuple, frozenset]]:
    """Rows near the apex of a triangle 10^12 px wide, in both windings: a few covered columns
    each. A span is two crossings at any width (Ek, *Triangles and Perspective Correct
    Interpolation*, §1.1: the fill never tests a pixel), but a scan of the triangle's columns
    cannot finish (r39/r46 02-4: testing every centre with ``covers`` passed every case). The
    package's fixed-point fill does not reach 10^12 px, so these rows' columns come from the
    exact crossings and the top-left rounding (:func:`exact_columns`, checked against the
    package on every other case by the tests)."""
    apex, base = (1000.25, 10.125), 10.125 + WIDE
    out = []
    for order in ((0, 1, 2), (0, 2, 1)):
        xy = np.array([apex, (1000.25 - WIDE, base), (1000.25 + WIDE, base)])[list(order)]
        for row in (10, 13):
            out.append((f"a triangle 10^12 px wide, row {row} near its apex ({winding(xy)}; "
                        "a span is two crossings at any width: a scan of the triangle's columns "
                        "never ends)", (xy, row), exact_columns(xy, row)))  # fmt: skip
    return out


def exact_columns(xy: np.ndarray, row: int) -> frozenset:
    """The covered columns of ``row`` from the exact crossings: ⌈x_l − ½⌉ ≤ col < ⌈x_r − ½⌉
    (the top-left rule as a rounding), none along a bottom edge or for zero area.

    >>> sorted(exact_columns(np.array([[0.0, 0.0], [4.0, 4.0], [0.0, 4.0]]), 2))  # x = 2.5 right
    [0, 1]
    """
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    if cross is None or _horizontal_edge(xy, row + 0.5) == "bottom":
        return frozenset()
    half = Fraction(1, 2)
    return _columns(math.ceil(cross[0] - half), math.ceil(cross[1] - half))


def _float32_rows(count: int = 3) -> list[tuple[np.ndarray, int]]:
    """(xy, row) of seeded random triangles 100 000 px from the origin, on the 1/256-px grid,
    where the span computed in float32 differs from the exact one (a few hundred triangles
    searched: about 1 row in 200 differs)."""
    rng = np.random.default_rng(2026)
    out = []
    for _ in range(2000):
        xy = 100000.0 + np.round(rng.uniform(0, 12, (3, 2)) * 256) / 256
        rows = list(range(100000, 100012))
        covered = _covered_rows(xy, rows)
        row = next((r for r in rows if (_span_float32(xy, r) or frozenset()) != covered[r]), None)
        if row is not None:
            out.append((xy, row))
        if len(out) == count:
            break
    return out


#: r363 M1: rows in the middle of each half (above and below the middle vertex) of random
#: triangles on the 1/256-px grid (numpy seed 363, found by comparing the variant with the
#: exact columns) where the middle vertex's side, judged by the long edge at the row instead
#: of at the middle vertex's height, swaps x_l and x_r: every other row asks only near a
#: vertex, where the two agree, and that student passed every case.
HALF_CASES = (
    ("upper", ((26.33203125, 30.13671875), (20.5, 10.76171875), (24.0234375, 27.703125)), 19),
    ("upper", ((1.7578125, 23.69921875), (23.63671875, 0.4921875), (13.47265625, 18.52734375)),
     9),
    ("lower", ((26.0625, 10.62890625), (31.24609375, 7.85546875), (21.94140625, 18.96875)), 14),
    ("lower", ((15.33203125, 1.16796875), (22.90625, 24.18359375), (24.40625, 31.44921875)), 27),
)  # fmt: skip


def _half_cases() -> list[tuple[str, tuple, frozenset]]:
    out = []
    for half, points, row in HALF_CASES:
        xy = np.array(points)
        out.append((f"random, row {row} (the middle of the {half} half: which side of the long "
                    "edge is the middle vertex?)", (xy, row), _covered_rows(xy, [row])[row]))  # fmt: skip
    return out


def _labelled_rows(table) -> list[tuple[str, tuple, frozenset]]:
    """One case per row of each ``(label, points, rows)`` in ``table``, its columns from the
    package's fill."""
    out = []
    for label, points, rows in table:
        xy = np.array(points)
        covered = _covered_rows(xy, list(rows))
        out += [(f"{label}, row {row}", (xy.copy(), row), covered[row]) for row in rows]
    return out


def _r372_cases() -> list[tuple[str, tuple, frozenset]]:
    """r372 P1, P2, F1: rows where a crossing divided first (or slope first) lands a hair off
    the centre it lies exactly on; triangles left of and above the origin and across column 0;
    a horizontal bottom edge on a centre line that is no sliver."""
    out = []
    for points, rows in TIE_ROWS:
        xy = np.array(points)
        covered = _covered_rows(xy, list(rows))
        out += [(f"vertices on centres, row {row} (a crossing exactly on a centre)",
                 (xy.copy(), row), covered[row]) for row in rows]  # fmt: skip
    return out + _labelled_rows(PLACED)


def _r385_cases() -> list[tuple[str, tuple, frozenset]]:
    """r385 P4, P5, P6: a crossing exactly on a centre on every edge, reached from either end
    (any crossing that rounds there fails); a crossing a hair right of a centre (an epsilon
    fails); horizontal edges off the centre lines (a row test on ⌊y⌋ fails). The triangles
    over 1000 px take their columns from the exact crossings (the package's fill of a window
    that size is slow), the rest from the package."""
    out = []
    for points, row in TIE_ENDS:
        xy = np.array(points)
        big = float(np.ptp(xy)) > 1000
        covered = exact_columns(xy, row) if big else _covered_rows(xy, [row])[row]
        out.append((f"vertices on centres, row {row} (a crossing exactly on a centre: a tie "
                    "on each edge, from either end)", (xy, row), covered))  # fmt: skip
    for points, row in NEAR_TIES:
        xy = np.array(points)
        out.append((f"a tall edge leaning a little, row {row} (a crossing a hair right of a "
                    "centre, not on it)", (xy, row), exact_columns(xy, row)))  # fmt: skip
    return out + _labelled_rows(FLOOR_ROWS)


def _far_cases() -> list[tuple[str, tuple, frozenset]]:
    """r385 T1 (session 35): rows 10^8 px out where lesson 01's multiply-first crossing, in
    float64, lands a hair right of the centre it lies on exactly, on each edge from each end
    (its §4b proves it exact below 2^18 px); r403 P7: rows near 2^29 px whose crossing lies
    a hair off a centre, where any float step moves an end. Columns from the exact crossings."""
    ties = [(f"far out, {label}, row {row} (a crossing exactly on a centre, 10^8 px out)",
             (np.array(points), row), exact_columns(np.array(points), row))
            for label, points, row in FAR_TIES]  # fmt: skip
    near = [(f"far out, {label}, row {row} (not on it, near 2^29 px)",
             (np.array(points), row), exact_columns(np.array(points), row))
            for label, points, row in FAR_NEAR_TIES]  # fmt: skip
    # r413 P8: the side of the long edge decided in float64 (lesson 01's u4 < MID[0])
    sides = [(f"far out, {label}, row {row} (a centre on the left edge, near 2^28 px)",
              (np.array(points), row), exact_columns(np.array(points), row))
             for label, points, row in FAR_SIDES]  # fmt: skip
    # r424 P1, P2: a vertex whose shortest repr drops a 1/256 digit (read through str()), and
    # a product over 64 bits (np.longdouble multiply first)
    precise = [(f"far out, {label}, row {row} (a crossing exactly on a centre, near 2^29 px)",
                (np.array(points), row), exact_columns(np.array(points), row))
               for label, points, row in FAR_PRECISE + FAR_DIGITS]  # fmt: skip
    # r439 P2, P3: a side that np.longdouble rounds to 0, one that int64 wraps to the other sign
    wide = [(f"far out, {label}, row {row} (the side of the long edge, near 2^29 px)",
             (np.array(points), row), exact_columns(np.array(points), row))
            for label, points, row in FAR_WIDE_SIDES]  # fmt: skip
    # r454 P1: the nearest an exact crossing comes to a centre in the range (an epsilon of 1e-14)
    hair = [(f"far out, {label}, row {row} (not on it: no exact crossing off a centre comes "
             "closer in the stated range)", (np.array(points), row),
             exact_columns(np.array(points), row)) for label, points, row in FAR_HAIR]  # fmt: skip
    # r454 (r439 P4): decimal at 33 or 34 digits, on edges 2^31 px wide
    wider = [(f"far out, {label}, row {row} (a crossing exactly on a centre, near 2^30 px)",
              (np.array(points), row), exact_columns(np.array(points), row))
             for label, points, row in FAR_DIGITS_35]  # fmt: skip
    return (
        ties + near + sides + precise + hair + wider + wide
    )  # (r454: the hair before the sliver it
    # shares an epsilon's answer with, so an epsilon's first failure is the one only it gives)


def _far(xy: np.ndarray) -> bool:
    """Beyond the range where lesson 01's multiply-first crossing is exact in float64 (and no
    wider than the 1/256-px grid holds: the 10^12-px triangle's rows are exact in any order)."""
    return FLOAT64_EXACT_BELOW <= float(np.abs(xy).max()) < 2**30


def _span_float32(xy: np.ndarray, row: int) -> frozenset | None:
    """The span of a student who computes the crossings in float32 (None: no crossing)."""
    v = np.asarray(xy, np.float32)
    y, half = np.float32(row + 0.5), np.float32(0.5)
    xs = []
    for k in range(3):
        (ax, ay), (bx, by) = v[k], v[(k + 1) % 3]
        if ay != by and min(ay, by) <= y <= max(ay, by):
            xs.append(ax + (y - ay) * (bx - ax) / (by - ay))
    if not xs:
        return None
    return _columns(math.ceil(min(xs) - half), math.ceil(max(xs) - half))


def _rows(xy: np.ndarray) -> list[tuple[int, str]]:
    """The rows worth asking about: one through a vertex or along a horizontal edge, the row
    just below the middle vertex (the split), the first covered one and one outside."""
    ys = sorted(xy[:, 1])
    picks = {}
    on_line = [y for y in ys if (y - 0.5).is_integer()]
    if on_line:
        picks[int(on_line[0] - 0.5)] = "a vertex on the centre line"
    mid = math.floor(ys[1] - 0.5) + 1
    picks.setdefault(mid, "just below the middle vertex: the split")
    first = math.ceil(ys[0] - 0.5)
    picks.setdefault(first, "the first centre line inside the y-range")
    picks.setdefault(math.floor(ys[0] - 0.5) - 1, "above the triangle")
    return sorted(picks.items())[:4]


def _covered_rows(xy: np.ndarray, rows: list[int]) -> dict[int, frozenset]:
    """The package's covered columns of each of ``rows`` (its fill, once, on a window around
    the triangle: an integer shift leaves the snapped grid, and so the coverage, as it is)."""
    c0 = math.floor(float(xy[:, 0].min())) - 2
    r0 = min(math.floor(float(xy[:, 1].min())) - 2, *rows)
    w = math.ceil(float(xy[:, 0].max())) + 3 - c0
    h = max(math.ceil(float(xy[:, 1].max())) + 3, *(r + 1 for r in rows)) - r0
    cov = rasterize(Triangle(xy - np.array([c0, r0], dtype=float)), w, h).coverage
    return {r: frozenset((np.flatnonzero(cov[r - r0]) + c0).tolist()) for r in rows}


# -- reading and comparing the answer ---------------------------------------------------------
class Span(frozenset):
    """The covered columns, with the pair (first, stop) the student returned (``pair``): two
    answers that cover nothing may still differ (r39 02-2: ``(stop, first)`` is no
    placeholder)."""

    pair: tuple[int, int] = (0, 0)


def as_span(value) -> Span:
    """The columns first <= col < stop of a returned (first, stop) pair of whole numbers."""
    arr = as_numbers(value, (2,), "a pair (first, stop) of column numbers")
    if not np.isfinite(arr).all() or (arr != np.round(arr)).any():
        raise WrongAnswerType(f"returned {short(value)}: columns are whole numbers")
    first, stop = (int(v) for v in arr)
    if stop - first > 10**6:  # r424 S1 (r413 m1): two integers are a span like any other,
        return _wide(first, stop)  # compared and explained as one, never listed column by column
    out = Span(range(first, stop))
    out.pair = (first, stop)
    return out


class _Wide(Span):
    """A span of over 10^6 columns (first, stop) = ``pair``, held by its ends alone: no case's
    span is that wide, so it equals no expected answer and no mistake's (its set is empty)."""

    wide = True


def _wide(first: int, stop: int) -> Span:
    out = _Wide()
    out.pair = (first, stop)
    return out


def same_span(got: frozenset, expected: frozenset, args=None) -> bool:
    wide = [getattr(s, "wide", False) for s in (got, expected)]
    if any(wide):  # r424 S1: wide spans by their ends alone
        return all(wide) and got.pair == expected.pair
    return _same_columns(got, expected)


def _same_columns(a, b) -> bool:
    """The same columns; two sets compared as they are (r454: a copy of each into a set cost a
    check a tenth of its time on the far rows' spans of 10^5 to 10^6 columns)."""
    if isinstance(a, frozenset) and isinstance(b, frozenset):
        return frozenset.__eq__(a, b)
    return set(a) == set(b)


def _returned(got) -> tuple[int, int] | None:
    return getattr(got, "pair", None)


def _constant_span(value) -> str:
    """A span that never changes, in the student's terms (r39 02-3: not ``frozenset()``)."""
    pair = _returned(value)
    if not value and not getattr(value, "wide", False):
        shown = f"{pair} " if pair else ""
        return (
            f"your function returns the same empty span {shown}(stop ≤ first: no column) on "
            "every case, whatever its arguments: a placeholder (such as `return 0, 0`) left "
            "in, or a `return` reached too early?"
        )
    return (
        f"your function returns {span_words(value)} on every case, whatever its arguments: a "
        "placeholder left in, or a `return` reached too early?"
    )


def _far_float32_fits(args, expected, got) -> bool:
    """Far out, the student's span is float32's, or differs by one column whose centre lies
    within a few float32 steps of a crossing (only there can float32 move an end). r46 S1: a
    float64 stop one too far (⌈x_r − ½⌉ + 1) was blamed on float32 in every far case."""
    xy, row = args
    far = float(np.abs(xy).max())
    moved = expected ^ set(got)
    if far < 1e4 or not moved:
        return False
    if _span_float32(*args) == set(got):
        return True
    xs = crossings(xy, row + 0.5)
    if len(moved) != 1 or xs is None:
        return False
    centre, near = min(moved) + 0.5, 4 * float(np.spacing(np.float32(far)))
    # where float32's steps pass a pixel (the 10^12-px triangle: 32768 px) every column is
    # "near" a crossing: only float32's own span names it there. r355 C3: a crossing exactly
    # on a centre (a tie) is float64's off-by-one (stop + 1, (first, last)), not float32's
    gap = min(abs(float(x) - centre) for x in xs)
    return near < 1 and 0 < gap <= near


def _far_float32_words(args, expected, got) -> str:
    far = float(np.abs(args[0]).max())
    spacing = float(np.spacing(np.float32(far)))
    return (
        f": {num(far)} px from the origin float32 numbers are {num(spacing)} px apart and "
        "cannot hold the vertices' 1/256-px grid, so a crossing computed in float32 can move "
        "past a centre. Did you compute in float32 (np.float32, or an array of that type)? "
        "Compute in float64 (plain Python floats or np.float64)"
    )


# -- why a span is wrong ----------------------------------------------------------------------
#: :func:`crossings` by (vertices' float64 bytes, y): the diagnosis asks each row's crossings
#: of every mistake (its spans and :func:`_float64_same`), in exact Fractions each time
#: (bounded: cleared when full; the answers are immutable tuples of Fractions, or None)
_CROSSINGS: dict = {}
_CROSSINGS_MOST = 4096


def crossings(xy: np.ndarray, y) -> tuple[Fraction, Fraction] | None:
    """Exact x_l <= x_r where the horizontal line at ``y`` meets the closed triangle (None:
    it misses it, or the triangle has zero area).

    >>> crossings(np.array([[0.0, 0.0], [4.0, 4.0], [0.0, 4.0]]), Fraction(5, 2))
    (Fraction(0, 1), Fraction(5, 2))
    """
    key = None
    if type(xy) is np.ndarray and xy.dtype == np.float64 and type(y) in (int, Fraction):
        key = (xy.shape, xy.tobytes(), y)
        out = _CROSSINGS.get(key, _CROSSINGS)  # (the dict itself: not yet computed)
        if out is not _CROSSINGS:
            return out
    out = _crossings(xy, y)
    if key is not None:
        if len(_CROSSINGS) >= _CROSSINGS_MOST:
            _CROSSINGS.clear()
        _CROSSINGS[key] = out
    return out


def _crossings(xy, y) -> tuple[Fraction, Fraction] | None:
    v = [(_exact(p[0]), _exact(p[1])) for p in xy]
    y = Fraction(y)
    xs = []
    for (ax, ay), (bx, by) in zip(v, v[1:] + v[:1]):
        if ay == by:
            if ay == y:
                xs += [ax, bx]
        elif min(ay, by) <= y <= max(ay, by):
            xs.append(ax + (y - ay) * (bx - ax) / (by - ay))
    area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])
    return (min(xs), max(xs)) if xs and area != 0 else None


def _exact(c) -> Fraction:
    """A coordinate as an exact fraction (a Fraction as it is: r424 P1's vertices read through
    ``str()``, which the variants move off the float)."""
    return c if isinstance(c, Fraction) else Fraction(float(c))


def _columns(lo, hi) -> frozenset | None:
    """The columns lo <= col < hi (None: over 10^6 of them, an answer :func:`as_span` refuses;
    r385: a wrong crossing of a near tie's edge, 10^5 px tall, lies 10^7 px out)."""
    return None if hi - lo > 10**6 else frozenset(range(lo, hi))


def _variants(xy: np.ndarray, row: int) -> dict[str, frozenset]:
    """The columns typical wrong solutions give on ``row`` (exact crossings). A rounding
    variant keeps the bottom-edge rule and the area test (r355 C2: without them "ties
    reversed" also gave a missing bottom-edge rule's answer, so that second mistake was never
    named)."""
    out = {}  # r403 M9, H4: far rows too, exactly (a float64 student's, :func:`_match`)
    y = Fraction(2 * row + 1, 2)
    centre = crossings(xy, y)
    half = Fraction(1, 2)
    # r424 H1: the line through the bottom vertex alone (x_l = x_r) has no span for a rounding
    # slip either (rows y1 <= y < y3): "stop + 1" there covered a column no student covers
    lowest = max(Fraction(float(p[1])) for p in xy)
    bottom = _horizontal_edge(xy, y) == "bottom" or y == lowest
    if centre is not None:
        xl, xr = centre
        lo, hi = math.ceil(xl - half), math.ceil(xr - half)
        rounded = {
            # r73 02-1: int(x + ½), C's habit: centres right, ties the wrong way round (it
            # passes every row without a tie, so it is no "sampled at x = col")
            "ties reversed": _columns(math.floor(xl + half), math.floor(xr + half)),
            "corners": _columns(math.ceil(xl), math.ceil(xr)),
            # r363 C6: ⌊x⌋ for both ends was told the rule, then "first too far right"
            "floor": _columns(math.floor(xl), math.floor(xr)),
            # r403 H4: ⌊x − ½⌋ at both ends (the centre at or left of each crossing)
            "floor(x − ½)": _columns(math.floor(xl - half), math.floor(xr - half)),
            "right inclusive": _columns(lo, math.floor(xr - half) + 1),
            "left exclusive": _columns(math.floor(xl - half) + 1, hi),
            "rounded": _columns(round(xl), round(xr)),
            "stop + 1": _columns(lo, hi + 1),
            "last": _columns(lo, hi - 1),
            # r372 P2, H1: C's int() as floor (toward zero), a clip at column 0, round(x − ½)
            "int() for floor": _columns(_int_ceil(xl - half), _int_ceil(xr - half)),
            # r403 (w06): C's int(x + 0.5), ties reversed and truncated toward zero
            "int(x + ½)": _columns(int(xl + half), int(xr + half)),
            "clip at 0": _columns(max(lo, 0), max(hi, 0)),
            # r439 H1: −int(−t) for the ceiling, which truncates: right only for t <= 0
            "-int(-t) for ceil": _columns(-int(half - xl), -int(half - xr)),
            # r439 H2: (first, count), the count of columns as the second number
            "first and count": _columns(lo, max(hi - lo, 0)),
            "round(x − ½)": _columns(round(xl - half), round(xr - half)),
            # r413 M10: an integer crossing floored to the 1/256 grid, then rounded exactly
            "crossing on the 1/256 grid": _Strict(
                _columns(math.ceil(_on_grid(xl) - half), math.ceil(_on_grid(xr) - half))
            ),
            # r454 M5: rounded to the nearest grid point (round(256·x)/256) instead
            "crossing to the nearest 1/256": _Strict(
                _columns(math.ceil(_nearest_grid(xl) - half), math.ceil(_nearest_grid(xr) - half))
            ),
            # r403 P7: the exact crossing, then a float at the last step (float(Fraction),
            # n / d / 256): a crossing a hair off a centre far out lands on it
            "float at the last step": _Strict(
                _columns(math.ceil(float(xl) - 0.5), math.ceil(float(xr) - 0.5))
            ),
        }
        out.update({k: frozenset() if bottom else v for k, v in rounded.items()})
        if hi > lo and not bottom:  # r372 M1, M2: the pair the wrong way round on every
            # row with a span; or on all but those along a top edge, whose ends need no side
            out["first and stop swapped"] = _reversed(lo, hi)
            if not _horizontal_edge(xy, y):
                out["x_l and x_r swapped"] = _reversed(lo, hi)
        out["horizontal reversed"] = _horizontal_reversed(xy, row, lo, hi)
        # r363 C3: a top edge left out, a bottom edge right, was named "y = row"
        top = _horizontal_edge(xy, y) == "top"
        out["no top edge"] = frozenset() if top else exact_columns(xy, row)
    out.update(edge_variants(xy, row))
    lines = {kind: row + dy for kind, dy in SHIFTS.items()}
    lines.update({kind: line(row) for kind, line in {**SCALED, **UNSCALED}.items()})  # r413 H6
    for kind, y_wrong in lines.items():  # the wrong line: the pixels' top, bottom, the next row
        cross = crossings(xy, y_wrong)  # (a bottom edge on that line owns none, r372)
        bottom = _horizontal_edge(xy, float(y_wrong)) == "bottom"
        out[kind] = frozenset() if cross is None or bottom else _columns(math.ceil(cross[0] - half),
                                                               math.ceil(cross[1] - half))  # fmt: skip
    # r439 H4: vertices times 256, the line left in px (row + ½) and the columns in 1/256 px too
    cross = crossings(xy, Fraction(2 * row + 1, 512))
    out["line in px, columns in 1/256 px"] = (
        frozenset()
        if cross is None or _horizontal_edge(xy, (row + 0.5) / 256) == "bottom"
        else _columns(math.ceil(256 * cross[0] - half), math.ceil(256 * cross[1] - half))
    )
    swapped = np.asarray(xy)[:, ::-1]
    if np.ptp(swapped[:, 0]) < 10**6:  # (the 10^12-px triangle's swap: no span to hold)
        out["x and y swapped"] = exact_columns(swapped, row)
    out.update(more_variants(xy, row, exact_columns))
    out.update(_row_range_variants(xy, row))
    if _far(np.asarray(xy)):  # r403 M9: far out a mistake speaks where it changes the answer
        # (a float64 student with another slip may miss a far row by its rounding alone)
        right = exact_columns(xy, row)
        out = {k: None if v is not None and same_span(v, right) else v for k, v in out.items()}
    return out


def _row_range_variants(xy: np.ndarray, row: int) -> dict[str, frozenset]:
    """r454 H6: the rows clipped at 0 (lesson 01's raster_lines clips them to its image), the
    span exact on the rows kept. (r454 H4, rows ⌊y1 + ½⌋ ≤ row < ⌊y3 + ½⌋, gives "no top edge"'s
    answers on every case: said in its words.)"""
    right = exact_columns(xy, row)
    return {"rows clipped at 0": right if row >= 0 else frozenset()}


class _Strict(frozenset):
    """A mistake's columns that float64's rounding is no part of: matched as they are, not
    with float64's ends on far rows (:func:`_float64_same`; the float at the last step is
    itself float64's rounding)."""


def _nearest_grid(x: Fraction) -> Fraction:
    """x rounded to the nearest point of the 1/256-px grid (round(), halves to even)."""
    return Fraction(round(256 * x), 256)


def _on_grid(x: Fraction) -> Fraction:
    """x floored to the 1/256-px grid (integer floor division in 1/256-px units)."""
    return Fraction(math.floor(256 * x), 256)


def _int_ceil(t: Fraction) -> int:
    """A ceiling made with C's ``int()``, which truncates toward zero: one too far right for
    a negative t that is no integer (r372 P2: ``int(t) if t == int(t) else int(t) + 1``)."""
    return int(t) if t == int(t) else int(t) + 1


def _reversed(lo: int, hi: int) -> Span:
    """The answer (stop, first) of the columns lo <= col < hi, compared by its pair."""
    out = Span()
    out.pair = (hi, lo)
    return out


def _match(got, answer, args) -> bool:
    """A mistake gives the student's answer: the same columns; where the student returned a
    pair the wrong way round (stop < first) and the mistake's answer is a pair too (a side
    test's), the same pair (r372 M2: (6, 2) is no "none" that any empty span gives, such as
    the long edge taken twice below the split)."""
    mine, theirs = _returned(got), getattr(answer, "pair", None)
    if getattr(got, "wide", False) or getattr(answer, "wide", False):  # r424 S1: by its ends
        return same_span(got, answer)
    # r454 M1: a side test in a limited precision swaps the ends, (stop, first), or reads a side
    # of 0 as no area, (0, 0); an empty (c, c) on a sliver's near tie is an epsilon's
    if getattr(answer, "from_side", False) and mine is not None and mine[0] <= mine[1] != 0:
        return False
    if mine is not None and theirs is not None and mine[1] < mine[0]:
        return theirs == mine or _float64_same(got, answer, args)
    return _same_columns(got, answer) or _float64_same(got, answer, args)


def _float64_same(got, answer, args) -> bool:
    """r403 M9: on a far row, the student's answer is the mistake's but for ends (at most two
    columns off) whose exact crossing lies on a centre or within float64's rounding of one:
    there a float64 student with that mistake (int() for a ceiling, say) rounds the crossing
    to either side first, and the table is evaluated exactly."""
    xy, row = args
    mine = _returned(got)
    strict = isinstance(answer, _Strict) or getattr(answer, "strict", False)
    if mine is None or strict or not _far(np.asarray(xy)):
        return False
    # (a frozenset's emptiness without a copy of its far row's 10^5 columns into a set)
    empty = len(got) == 0 if isinstance(got, frozenset) else not set(got)
    if empty and float_side_errs(xy):  # r413 P8: a float64 side or area test drops
        return True  # the thin far rows' span, whatever the other slip
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    if cross is None:
        return False
    centres = [Fraction(math.floor(x)) + HALF for x in cross]  # the centre nearest each
    if not any(x == c or _within_float64(x, c) for x, c in zip(cross, centres)):
        return False  # (before the mistake's ends: min and max of 10^5 columns each time)
    theirs = getattr(answer, "pair", None) or (answer and (min(answer), max(answer) + 1))
    if not theirs or _horizontal_edge(xy, row + 0.5):
        return False
    return all(abs(end - its) <= 2 for end, its in zip(mine, theirs))


#: The lines a student may intersect instead of the centre line y = row + ½ (r355: y = row − ½,
#: row + 1 and row + 1.5 were named "row top" or "ends").
SHIFTS = {"row top": Fraction(0), "row − ½": Fraction(-1, 2), "row + 1": Fraction(1),
          "row + 1.5": Fraction(3, 2)}  # fmt: skip


#: r403/r413 H6 (r403 w28): the centre line in units twice or half the vertices' (vertices in
#: 1/512 px, the line 1024·row + 256 of 1/256-px thinking: y = 2·row + ½ px)
SCALED = {"line 2·row + ½": lambda row: 2 * row + HALF,
          "line (row + ½)/2": lambda row: Fraction(2 * row + 1, 4),
          # r439 H4: vertices times 256, the line left in px (row + ½)
          "line (row + ½)/256": lambda row: Fraction(2 * row + 1, 512)}  # fmt: skip


#: r424 M1: the line in 1/256-px units with the ½ left unscaled (256·row + 0.5 or 256·row + 1):
#: y = row + 1/512 or row + 1/256, just below the pixels' top
UNSCALED = {"line row + 1/512": lambda row: row + Fraction(1, 512),
            "line row + 1/256": lambda row: row + Fraction(1, 256)}  # fmt: skip


def _unscaled_words(kind: str):
    """r424 M1: the ½ of the centre line not scaled to 1/256-px units, with the line's y."""
    steps = {"line row + 1/512": "0.5", "line row + 1/256": "1"}[kind]

    def words(args, expected, got) -> str:
        row = args[1]
        return (f"your span is the one of the line y = {kind.removeprefix('line ')} = "
                f"{_frac(UNSCALED[kind](row))}, just below the pixels' top, not of this row's "
                f"centre line y = row + ½ = {_frac(row + HALF)}: you wrote the line in "
                f"1/256-px units as 256·row + {steps}, the ½ left unscaled; in those units ½ px "
                "is 128 steps, so the centre line is 256·row + 128")  # fmt: skip

    return words


def _scaled_words(kind: str):
    """The words of a centre line in other units, with the line's y on the case."""

    def words(args, expected, got) -> str:
        row = args[1]
        return (f"your span is the one of the line y = {kind.removeprefix('line ')} = "
                f"{_frac(SCALED[kind](row))}, not of this row's centre line y = row + ½ = "
                f"{_frac(row + HALF)}: the centre line and the vertices are in different units "
                "(vertices times 512 and the line in 1/256-px steps, say); with the vertices "
                "times s, the centre line is s·row + s/2")  # fmt: skip

    return words


def _pick_pair(long_x, short_x, long_is_left: bool) -> frozenset:
    return pair_columns(long_x, short_x) if long_is_left else pair_columns(short_x, long_x)


def _horizontal_reversed(xy, row, lo, hi) -> frozenset:
    """The rule for a horizontal edge the wrong way round: a top edge's centres left out, a
    bottom edge's covered (r355: named "row top")."""
    return frozenset() if _horizontal_edge(xy, row + 0.5) == "top" else _columns(lo, hi)


def edge_variants(xy: np.ndarray, row: int) -> dict[str, frozenset]:
    """Wrong choices of the edges that bound the row, each right wherever it changes nothing:
    crossings only strictly inside an edge, no area test, no split (the top-to-middle edge
    used below the middle vertex too), the long edge always the left end (r355 M4, M5 and
    the half-named students)."""
    v = sorted(((Fraction(float(x)), Fraction(float(y))) for x, y in xy), key=lambda p: p[1])
    (x1, y1), (x2, y2), (x3, y3) = v
    y, half = Fraction(2 * row + 1, 2), Fraction(1, 2)
    right = exact_columns(xy, row)
    out = dict.fromkeys(
        (
            "strict",
            "no area test",
            "no split",
            "no split, side test",
            "long edge left",
            "side at row",
            "side x2 > x1",
            "lower denominator",
            "split at row",
        ),
        right,
    )
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    if area == 0:  # every vertex on one line: its crossings are its ends on this line
        xs = [x for x, vy in v if vy == y] if y1 == y3 else [
            a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])
            for a, b in ((v[0], v[2]),) if y1 <= y <= y3]  # fmt: skip
        if xs:
            out["no area test"] = _columns(math.ceil(min(xs) - half), math.ceil(max(xs) - half))
        return out
    if not y1 <= y <= y3 or _horizontal_edge(xy, y):
        return out

    def at(a, b):
        return a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])

    strict = [at(a, b) for a, b in ((v[0], v[1]), (v[1], v[2]), (v[0], v[2]))
              if a[1] < y < b[1]]  # fmt: skip
    out["strict"] = (_columns(math.ceil(min(strict) - half), math.ceil(max(strict) - half))
                     if strict else frozenset())  # fmt: skip
    long_x = at(v[0], v[2])
    no_split = at(v[0], v[1]) if y1 != y2 else at(v[1], v[2])
    out["no split"] = _columns(*sorted((math.ceil(long_x - half), math.ceil(no_split - half))))
    # r403 H4 (w08): the same edge kept past the middle vertex, x_l picked by the side test at
    # the middle vertex (the lesson's u4): below the split the pair may come back reversed
    u4 = x1 + (y2 - y1) * (x3 - x1) / (y3 - y1)
    out["no split, side test"] = _pick_pair(long_x, no_split, x2 > u4) if y < y3 else None
    short_x = at(v[0], v[1]) if y <= y2 else at(v[1], v[2])
    out["long edge left"] = pair_columns(long_x, short_x)
    if row < y2 < y < y3 and y1 != y2:  # r439 H3: the split tested with the row, not its line
        out["split at row"] = _pick_pair(long_x, at(v[0], v[1]), area > 0)
    # r363 M1, C5: the side of the long edge the middle vertex lies on, judged by the long
    # edge at this row (not at the middle vertex's height), or by the top vertex's x
    for kind, long_is_left in (("side at row", x2 > long_x), ("side x2 > x1", x2 > x1)):
        a, b = (long_x, short_x) if long_is_left else (short_x, long_x)
        out[kind] = pair_columns(a, b)
    if y > y2 and y1 != y2:  # r363 C4: the lower short edge divided by the long edge's height
        wrong = x2 + (y - y2) * (x3 - x2) / (y3 - y1)
        out["lower denominator"] = _columns(*sorted((math.ceil(long_x - half),
                                                     math.ceil(wrong - half))))  # fmt: skip
    return out


def _grid_words(args, expected, got, nearest: bool = False) -> str:
    """r413 M10: an integer crossing floored to the 1/256 grid (no float in it); r454 M5:
    ``nearest``, rounded to the nearest grid point."""
    xy, row = args
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    said = ""
    grid = _nearest_grid if nearest else _on_grid
    for name, x in zip(("x_l", "x_r"), cross or ()):
        if math.ceil(grid(x) - HALF) != math.ceil(x - HALF):
            gap = float(x - grid(x))
            said = (
                f" (here {name} = {_frac(x)} lies {abs(gap):.2g} px {'right' if gap > 0 else 'left'} "
                f"of the grid point {_frac(grid(x))}, and the centre "
                f"{num(math.ceil(x - HALF) - 0.5 if gap > 0 else math.ceil(grid(x) - HALF) - 0.5)} "
                "lies between them, so the rounding moved it across)"
            )
            break
    how = (
        "to the nearest point of the 1/256 grid (round(256·x)/256)"
        if nearest
        else "to the 1/256 grid (a floor division in 1/256-px units)"
    )
    return (f"you rounded the crossing {how} "
            f"before rounding it to a column{said}: the crossing is a rational, not on the "
            "grid; divide once, rounding the exact quotient straight to a column: "
            "⌈(n − 128·d) / (256·d)⌉ with n = 256·x·d in integers, d > 0")  # fmt: skip


#: r424 H3: said whatever ends the line's columns came from
ZERO_AREA = (
    "you treated the line as a triangle: a triangle of zero area covers nothing, so the line "
    "covers nothing, whatever its ends: test the area (the edge function of the three "
    "vertices, side == 0) first, before the crossings"
)

#: r403 H4: the task promises to name "a short edge kept past the middle vertex"
NO_SPLIT = (
    "you kept a short edge past the middle vertex: you used the edge from the top vertex to "
    "the middle one below the middle vertex too, but the edge that bounds the triangle on that "
    "side changes at the middle vertex (the split), and below it runs from the middle vertex "
    "to the bottom one"
)

MISTAKES = {
    "ties reversed": "your columns are right wherever no centre lies exactly on a crossing, "
    "but your ties go the wrong way round: a centre exactly on x_l (the left edge) you left out "
    "and one exactly on x_r (the right edge) you covered: rounding x + ½ down (C's "
    "int(x + 0.5)?), or an integer ceiling that is ⌊n/d⌋ + 1 where n/d is whole, such as "
    "(n + d − 1)//d with a negative d (an edge taken from its lower end up: −(−n // d) is the "
    "ceiling for either sign)? Under the top-left rule, which of the two edges owns a centre "
    "that lies on it?",
    "corners": "you rounded the crossings to columns as if pixel col were sampled at x = col "
    "(its left edge): its centre is at x = col + ½, so the first column is ⌈x_l − ½⌉",
    "right inclusive": "you covered the centre that lies exactly on the right edge: by the "
    "top-left rule it belongs to the triangle on the other side (the span stops before it, "
    "⌈x_r − ½⌉ is the first column *not* covered)",
    "left exclusive": "you left out the centre that lies exactly on the left edge: a left edge "
    "owns its centres under the top-left rule (⌈x_l − ½⌉, not ⌊x_l − ½⌋ + 1)",
    "floor": "you rounded both crossings down (⌊x_l⌋, ⌊x_r⌋), as if a column were covered "
    "when its left side, x = col, lay between them: it is covered when its centre col + ½ "
    "does, so you covered a column whose centre lies left of x_l, or left out one whose "
    "centre lies left of x_r; count the columns whose centres lie between x_l and x_r",
    "rounded": "you rounded the crossings to the nearest integer: a column is covered when "
    "its centre col + ½ lies between them, so take ⌈x_l − ½⌉ and ⌈x_r − ½⌉",
    "row top": "you intersected the edges with y = row, the top of the pixels, not with the "
    "line of their centres, y = row + ½",
    "row − ½": "you intersected the edges with y = row − ½, the centres of the row above, "
    "not with this row's centre line, y = row + ½",
    "row + 1": "you intersected the edges with y = row + 1, the bottom of the pixels, not "
    "with the line of their centres, y = row + ½",
    "row + 1.5": "you intersected the edges with y = row + 1.5, the centres of the row below, "
    "not with this row's centre line, y = row + ½",
    **{kind: _scaled_words(kind) for kind in SCALED},
    **{kind: _unscaled_words(kind) for kind in UNSCALED},
    "line in px, columns in 1/256 px": lambda args, expected, got: (
        f"your span is the one of the line y = (row + ½)/256 = {_frac(Fraction(2 * args[1] + 1, 512))}"
        " px, counted in 1/256-px steps, not in columns: your vertices are in 1/256-px units "
        "(times 256) but your centre line, row + ½, is in px; in those units it is 256·row + "
        "128, and the crossings are in 1/256 px too: turn them back into px before rounding "
        "to a column"
    ),
    "no top edge": "you left out the centres on a horizontal top edge that runs along the "
    "centre line: a top edge, with the triangle below it, owns its centres (or your rows leave "
    "out the one through the top vertex on its centre line, such as ⌊y1 + ½⌋ ≤ row: a row "
    "belongs when y1 ≤ row + ½ < y3)",
    "x and y swapped": "you swapped x and y: a vertex is (x, y) = (xy[k, 0], xy[k, 1]), and a "
    "raster line is a horizontal line, y = row + ½, whose crossings are x values",
    "horizontal reversed": "your rule for a horizontal edge on the centre line is the wrong "
    "way round: a top edge (the triangle below it) owns its centres, a bottom edge (the "
    "triangle above it) owns none",
    "stop + 1": "your stop is one column too far right on every row, ties or not (not only "
    "where a centre lies on x_r): stop is the first column *not* covered, one past the last "
    "covered one, with no + 1 after it (the first end, first, is right)",
    "last": "you returned (first, last), the last covered column as the second number: it is "
    "stop, the first column *not* covered (last + 1)",
    # r372 M1, M2: said only where it gives every answer (183 of 200 right was told it)
    "first and stop swapped": "on every row with a span your pair comes back the wrong way "
    "round, as (stop, first), which covers nothing: you returned (stop, first) (the pair is "
    "(first, stop), the first covered column and the first one past the span), or your x_l "
    "and x_r are swapped on every row",
    "x_l and x_r swapped": "your x_l and x_r are swapped on every row with a span but those "
    "along a top edge (whose ends need no side test), so the pair comes back as (stop, first) "
    "and covers nothing: you judged the middle vertex's side of the long edge the wrong way "
    "round (or swapped the two ends where the side test picks them)",
    "int() for floor": "your ends left of x = 0 are one column too far right: int() truncates "
    "toward zero (int(−9.75) is −9, not −10), so a rounding built from int() is one too high "
    "for a negative number that is no integer; math.floor and math.ceil round the same way "
    "on both sides of 0",
    "int(x + ½)": "you rounded with int(x + ½), C's habit, which is wrong twice: your ties go "
    "the wrong way round (a centre exactly on x_l, the left edge, you left out and one exactly "
    "on x_r, the right edge, you covered), and int() truncates toward zero, so left of x = 0 "
    "your ends are one column further right still; under the top-left rule, which of the two "
    "edges owns a centre that lies on it, and which rounding is the same on both sides of 0?",
    "-int(-t) for ceil": "your ends right of x = 0 are one column too far left: −int(−t) is "
    "the ceiling only for t ≤ 0 (int() truncates toward zero, so for a positive t that is no "
    "integer −int(−t) rounds down); math.ceil rounds the same way on both sides of 0",
    "first and count": "your second number is the count of the covered columns, stop − first: "
    "the pair is (first, stop), stop the first column *not* covered (first + the count)",
    "clip at 0": "you clipped the span at column 0: the columns are the plane's, negative ones "
    "too (no image clips them here, as lesson 01's span_fill clips to its image)",
    "round(x − ½)": "you rounded x − ½ to the nearest integer (round()): the first covered "
    "column is the first whose centre col + ½ lies at or right of x_l, which round() misses "
    "whenever x_l − ½ has a fraction below ½ (x_l = 2.8: round(2.3) is 2, yet column 2's "
    "centre 2.5 lies left of 2.8)",
    "strict": "you took a crossing only strictly between an edge's ends (min < y < max): "
    "where the centre line passes through a vertex, both edges that meet there end on it and "
    "a strict test drops its crossing from both; an edge includes its ends (≤)",
    "no area test": ZERO_AREA,
    "no split": NO_SPLIT,
    "no split, side test": NO_SPLIT,
    "floor(x − ½)": "you rounded x − ½ down at both ends (math.floor): that gives the column "
    "whose centre lies at or left of the crossing, but the first covered column is the first "
    "whose centre lies at or right of x_l, and stop the first at or right of x_r: where no "
    "centre lies on a crossing both your ends are one column too far left",
    "side at row": "your x_l and x_r are swapped on this row: you judged which side of the "
    "long edge the middle vertex lies on by the long edge's crossing at this row; judge it "
    "where the long edge reaches the middle vertex's height (or take the smaller crossing as "
    "x_l)",
    "side x2 > x1": "your x_l and x_r are swapped on this row: you judged which side of the "
    "long edge the middle vertex lies on by comparing it with the top vertex (x2 > x1); judge "
    "it by the long edge where it reaches the middle vertex's height (or take the smaller "
    "crossing as x_l)",
    "split at row": lambda args, expected, got: (
        f"you used the edge from the top vertex to the middle one on row {args[1]}, whose "
        f"centre line y = {num(args[1] + 0.5)} lies below the middle vertex (y2 = "
        f"{num(sorted(float(p[1]) for p in args[0])[1])}): the split compares the centre line "
        "row + ½ with y2, not the row; below the middle vertex the short edge runs from it to "
        "the bottom vertex"
    ),
    "lower denominator": "below the middle vertex your crossing of the edge from the middle "
    "vertex to the bottom one is off: you divided by y3 − y1, the long edge's height, not by "
    "that edge's own height y3 − y2: x = x2 + (y − y2)·(x3 − x2)/(y3 − y2)",
    "crossing on the 1/256 grid": _grid_words,
    "crossing to the nearest 1/256": lambda args, expected, got: _grid_words(
        args, expected, got, nearest=True
    ),
    "rows clipped at 0": lambda args, expected, got: (
        f"you left out the rows above row 0 (here row {args[1]}): the rows are the plane's, "
        "negative ones too (no image clips them here, as lesson 01's raster_lines clips them to "
        "its image with max(first, 0))"
    ),
    "float at the last step": lambda args, expected, got: _landed_words(
        args, expected, got, last=True
    ),
    "long edge left": "you took the long edge's crossing (top vertex to bottom one) as the "
    "left end: the long edge is the left one only when the middle vertex lies right of it; "
    "here the middle vertex lies left of it, so the long edge bounds the span on the right "
    "(take the smaller crossing as x_l)",
    **MORE_WORDS,
}


def explain_span(args, expected: frozenset, got: frozenset) -> str:
    """The exact crossings of the row's centre line, the covered columns and yours."""
    xy, row = args
    y = row + 0.5
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    if cross is None and winding(xy) == "zero area":  # r355 M5: not "does not cross" a line on it
        return (
            f"the triangle ({_vertices(xy)}) has zero area (its vertices lie on one line), so "
            f"row {row} covers no column; yours covers {span_words(got)}"
        )
    if cross is None:
        return (
            f"the centre line y = {num(y)} of row {row} does not cross this {winding(xy)} "
            f"triangle ({_vertices(xy)}), so no column is covered; yours covers {span_words(got)}"
        )
    xl, xr = cross
    kind = _horizontal_edge(xy, y)
    if kind:  # r85 02: "crosses … from 0.5 to 60.5, so the covered centres are none" read
        # as a contradiction where the line runs along a bottom edge
        owns = "," if kind == "top" else "; a bottom edge owns none of its centres,"
        return (
            f"the centre line y = {num(y)} runs along the triangle's horizontal {kind} edge "
            f"({_vertices(xy)}) from x = {_frac(xl)} to {_frac(xr)}{owns} so the covered "
            f"centres are {span_words(expected)}; yours: {span_words(got)}"
        )
    return (
        f"the centre line y = {num(y)} crosses the triangle ({_vertices(xy)}) from x_l = "
        f"{_frac(xl)} to x_r = {_frac(xr)}, so the covered centres are "
        f"{span_words(expected)}; yours: {span_words(got)}"
    )


def _rule(args, expected, got) -> str:
    """The rule, then (r372 M3, M4: where no mistake gives every answer) the crossings the
    student's pair stands for, beside the exact ones and the edges they lie on."""
    rule = (
        ": a column is covered when its centre col + ½ lies between the crossings, a centre "
        "on the left edge included and one on the right edge not: ⌈x_l − ½⌉ ≤ col < ⌈x_r − ½⌉"
    )
    xy, row = args
    pair = _returned(got)
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    if pair is None or cross is None or _horizontal_edge(xy, row + 0.5):
        return rule
    half = Fraction(1, 2)
    ends = []
    for name, end, x in (("first", pair[0], cross[0]), ("stop", pair[1], cross[1])):
        if end != math.ceil(x - half):
            side = "x_l" if name == "first" else "x_r"
            ends.append(f"your {name} {end} stands for an {side} above {num(end - 0.5)} and at "
                        f"most {num(end + 0.5)}, but {side} is exactly {_frac(x)}, on "
                        f"{_edge_of(xy, row, x)}")  # fmt: skip
    return rule + "".join(f"; {e}" for e in ends)


def _edge_of(xy: np.ndarray, row: int, x: Fraction) -> str:
    """The sorted triangle's edge (or vertex) that the centre line of ``row`` crosses at x."""
    v = sorted(((Fraction(float(a)), Fraction(float(b))) for a, b in xy), key=lambda p: p[1])
    y = Fraction(2 * row + 1, 2)
    if (x, y) in v:
        return f"the {('top', 'middle', 'bottom')[v.index((x, y))]} vertex"
    names = {(0, 2): "the long edge (top vertex to bottom one)",
             (0, 1): "the edge from the top vertex to the middle one",
             (1, 2): "the edge from the middle vertex to the bottom one"}  # fmt: skip
    for (i, j), name in names.items():
        (ax, ay), (bx, by) = v[i], v[j]
        if (
            ay != by
            and min(ay, by) <= y <= max(ay, by)
            and ax + (y - ay) * (bx - ax) / (by - ay) == x
        ):
            return name
    return "an edge"


def _span_raised(args, error: str) -> str:
    """r372 H1: a ZeroDivisionError on a row whose centre line misses the triangle, or runs
    along a horizontal edge (a height of 0), told as such: where a crossing cannot be taken."""
    if "ZeroDivisionError" not in error:
        return ""
    xy, row = args
    y = row + 0.5
    if winding(xy) == "zero area":
        return " (this triangle has zero area: its vertices lie on one line)"
    if not float(xy[:, 1].min()) <= y <= float(xy[:, 1].max()):
        return (f" (the centre line y = {num(y)} misses the triangle, whose vertices lie "
                f"between y = {num(float(xy[:, 1].min()))} and {num(float(xy[:, 1].max()))}: "
                "no edge crosses it, so no crossing can be computed there"
                + _floor_row(xy, row) + ")")  # fmt: skip
    kind = _horizontal_edge(xy, y)
    if kind:
        return (f" (the centre line y = {num(y)} runs along a horizontal {kind} edge, whose "
                "height is 0: a crossing with it would be 0/0)")  # fmt: skip
    return ""


def _span_none(args, expected) -> str:
    """r439 M4: None returned for a line with no covered centre, where a pair is asked for."""
    if expected:
        return ""
    return (
        "your function returned None on a line with no covered centre: the answer is "
        "still a pair, any (first, stop) with stop ≤ first, such as (0, 0), not None"
    )


def _floor_row(xy: np.ndarray, row: int) -> str:
    """r385 P6: a row whose centre line misses the triangle, let in by a test on ⌊y⌋."""
    low, high = float(xy[:, 1].min()), float(xy[:, 1].max())
    if not math.floor(low) <= row <= math.floor(high):
        return ""
    return (f"; a row test on ⌊y⌋ (math.floor(y1) ≤ row ≤ math.floor(y3)) lets row {row} in, "
            f"yet its centres lie on y = {num(row + 0.5)}: test the centre line itself, "
            "y1 ≤ row + ½ ≤ y3")  # fmt: skip


def _horizontal_gives(edge: str):
    """r385 M7: the span of a student whose rule for a horizontal ``edge`` ("top" or "bottom")
    on the centre line is wrong (a top edge's centres left out, a bottom edge's covered), as a
    cause is, so that it is named only where it gives the student's answer and contradicts no
    passing one (not of a triangle of zero area, whose coincident vertices are no edge)."""

    def gives(xy: np.ndarray, row: int) -> Span | None:
        return _horizontal_span(xy, row) if _horizontal_edge(xy, row + 0.5) == edge else None

    return gives


def _horizontal_span(xy: np.ndarray, row: int) -> Span | None:
    kind = _horizontal_edge(xy, row + 0.5)
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    if not kind or cross is None or winding(xy) == "zero area":
        return None
    lo, hi = (math.ceil(x - Fraction(1, 2)) for x in cross)
    out = Span(range(lo, hi)) if kind == "bottom" else Span()
    out.pair = (lo, hi) if kind == "bottom" else (lo, lo)
    return out


def _horizontal_words(args, expected, got) -> str:
    xy, row = args
    if _horizontal_edge(xy, row + 0.5) == "top":
        return (f"you left out the centres on row {row}'s centre line, which runs along a "
                "horizontal top edge: a top edge owns its centres")  # fmt: skip
    return (f"you covered the centres on row {row}'s centre line, the edge's ends taken as "
            "crossings: the triangle lies above the line, and the centres on its bottom edge "
            "go to what lies below it")  # fmt: skip


def _ends_fits(args, expected, got) -> bool:
    return _end_off(expected, got) is not None


def _end_off(expected, got) -> str | None:
    """Which end is one column off ("first" too far right, "stop" too far right or left), read
    from the pair returned (r363 C6: a one-column span returned as (3, 3) was told "your first
    is one column too far right"; its stop is one too far left)."""
    if not expected:
        return None
    lo, hi = min(expected), max(expected) + 1
    pair = _returned(got) or (min(got, default=hi), max(got, default=hi - 1) + 1)
    return {(lo + 1, hi): "first", (lo, hi + 1): "stop right", (lo, hi - 1): "stop left"}.get(
        tuple(pair)
    )


def _end_number(args, expected, got) -> float | None:
    """Which end is off, as a number (one on every case, or the symptom is not said)."""
    end = _end_off(expected, got)
    return None if end is None else float(("first", "stop right", "stop left").index(end) + 1)


def _ends_words(args, expected, got) -> str:
    """Which end is off (r355 S3: "one end" left the student to work out which)."""
    end, stop = _end_off(expected, got), max(expected) + 1
    xy, row = args
    cross = crossings(xy, Fraction(2 * row + 1, 2))  # r372 M3: the crossing, not the rule alone
    xl, xr = (f" = {_frac(x)}" for x in cross) if cross is not None else ("", "")
    on = [cross is not None and (x - HALF).denominator == 1 for x in (cross or (0, 0))]
    if end == "first":  # r413 H9 (w36): on a tie, whose the centre is
        tie = (" (x_l lies exactly on that centre, and a left edge owns the centres on it: "
               "the top-left rule)") if on[0] else ""  # fmt: skip
        return (f"your first is one column too far right: column {min(expected)}, whose "
                f"centre lies at or right of x_l{xl}, is the first covered one{tie}")  # fmt: skip
    side = "right" if end == "stop right" else "left"
    tie = (f" (x_r lies exactly on the centre of column {stop}, which a right edge does not "
           "own: the top-left rule)") if on[1] and side == "right" else ""  # fmt: skip
    return (f"your stop is one column too far {side}: stop is the first column *not* covered, "
            f"here {stop}, the first whose centre lies at or right of x_r{xr}{tie} (your first "
            "is right)")  # fmt: skip


def _ties_off(args, got) -> list[tuple[str, int, Fraction]] | None:
    """(end name, the student's end, the exact crossing) of each end that differs from the
    exact one, where every such end lies one column right of it on a crossing exactly on a
    centre (None: another difference, or none)."""

    def one_right_on_a_centre(name, end, right, x):
        return (name, end, x) if end == right + 1 and (x - HALF).denominator == 1 else None

    return _ends_off(args, got, one_right_on_a_centre)


def _ends_off(args, got, judge) -> list | None:
    """``judge(name, end, right, x)`` of each end of the student's span that differs from the
    exact one ``right`` (x: the exact crossing), in the order first, stop; None when the answer
    is no span, the row runs along a horizontal edge, an end differs otherwise (``judge``
    returned None), or no end differs."""
    xy, row = args
    pair, cross = _returned(got), crossings(xy, Fraction(2 * row + 1, 2))
    if pair is None or cross is None or _horizontal_edge(xy, row + 0.5):
        return None
    off = []
    for name, end, x in (("first", pair[0], cross[0]), ("stop", pair[1], cross[1])):
        right = math.ceil(x - HALF)
        if end != right:
            entry = judge(name, end, right, x)
            if entry is None:
                return None
            off.append(entry)
    return off or None


HALF = Fraction(1, 2)


def _tie_edge(xy: np.ndarray, row: int, x: Fraction):
    """The sorted triangle's slanted edge (upper end, lower end) whose crossing of the row's
    centre line is x (None: a vertex, or none)."""
    v = sorted(((float(a), float(b)) for a, b in xy), key=lambda p: p[1])
    y = Fraction(2 * row + 1, 2)
    for i, j in ((0, 2), (0, 1), (1, 2)):
        a, b = v[i], v[j]
        if (
            a[1] < y < b[1]
            and Fraction(a[0])
            + (y - Fraction(a[1])) * Fraction(b[0] - a[0]) / (Fraction(b[1]) - Fraction(a[1]))
            == x
        ):
            return a, b
    return None


#: r385 P4, H2: crossings that round at a tie, each from the edge's upper end (a) and from its
#: lower end (b, the ends exchanged): where one of them gives the student's end it is quoted.
ROUNDINGS = (
    ("(y − a_y)/(b_y − a_y) taken first", "divide first"),
    ("the slope (b_x − a_x)/(b_y − a_y) taken first", "slope first"),
    ("the lerp (1 − t)·a + t·b", "lerp"),
    ("t = (y − a_y)/(b_y − a_y) rounded to float32", "float32 t"),
)


def _rounded_crossing(a, b, y: float, how: str) -> float:
    if how == "lerp":
        t = (y - a[1]) / (b[1] - a[1])
        return (1 - t) * a[0] + t * b[0]
    if how == "float32 t":
        return a[0] + float(np.float32((y - a[1]) / (b[1] - a[1]))) * (b[0] - a[0])
    return float_crossing(a, b, y, how)


def _rounding_of(args, end: int, x: Fraction) -> tuple[str, float] | None:
    """(the words of a rounding crossing, its value) that gives ``end`` at the tie x."""
    xy, row = args
    edge = _tie_edge(xy, row, x)
    if edge is None:
        return None
    for words, how in ROUNDINGS:
        for a, b, start in ((*edge, "upper"), (edge[1], edge[0], "lower")):
            value = _rounded_crossing(a, b, row + 0.5, how)
            if value > x and math.ceil(value - 0.5) == end:
                return f"{words}, from the edge's {start} end,", value
    return None


def _rounds_fits(args, expected, got) -> bool:
    return bool(_ties_off(args, got))


def _rounds_words(args, expected, got) -> str:
    xy, row = args
    name, end, x = _ties_off(args, got)[0]
    side = "x_l" if name == "first" else "x_r"
    found = _rounding_of(args, end, x)
    edge = _edge_of(xy, row, x)
    how = f" ({found[0]} gives {found[1]!r})" if found else ""
    if found and "float32" in found[0]:
        return (f"on {edge} {side} is exactly {_frac(x)}, a centre, and your {name} {end} means "
                f"yours came out a hair right of it{how}: float32 holds 24 bits, and its "
                f"rounding moved the tie. {NO_FLOAT_ORDER}")  # fmt: skip
    return (f"on {edge} {side} is exactly {_frac(x)}, a centre, and your {name} {end} means "
            f"yours came out a hair right of it{how}: your crossing rounds, so the tie went to "
            f"the wrong side. {NO_FLOAT_ORDER}")  # fmt: skip


def _float64_of(args, end: int, x: Fraction) -> tuple[str, float, int] | None:
    """(which end of the edge, the multiply-first crossing in float64, the significant bits of
    its product (y − a_y)(b_x − a_x) on the 1/256-px grid) where that crossing gives ``end``
    at the tie x (None: it gives the right end, or x lies on no slanted edge)."""
    xy, row = args
    edge = _tie_edge(xy, row, x)
    if edge is None:
        return None
    y = row + 0.5
    for a, b, start in ((*edge, "upper"), (edge[1], edge[0], "lower")):
        value = float_crossing(a, b, y)
        if value > x and math.ceil(value - 0.5) == end:
            n = abs(int(256 * (Fraction(y) - Fraction(a[1])) * 256 * Fraction(b[0] - a[0])))
            return start, value, n.bit_length() - (n & -n).bit_length() + 1
    return None


def _float64_fits(args, expected, got) -> bool | None:
    """r385 T1: far out (beyond 2^18 px), every wrong end one column right of a crossing
    exactly on a centre, or (r403 P7) one column left of a crossing that float64 rounds onto
    a centre; None (no say) nearer in, where float64 multiply-first is exact."""
    if not _far(args[0]):
        return None
    return bool(_ties_off(args, got) or _landed_off(args, got))


def _near_tie_off(args, got) -> bool:
    """r413 M10: a near row (where float64 multiply-first is exact) with an end wrong at a
    crossing exactly on a centre: a tie rule's mistake, not float64's, so far ties that fail
    too are no sign of float64 (the "float64 crossing" symptom must fit this row, and cannot)."""
    xy, row = args
    pair, cross = _returned(got), crossings(xy, Fraction(2 * row + 1, 2))
    if _far(np.asarray(xy)) or pair is None or cross is None:
        return False
    return any(end != math.ceil(x - HALF) and (x - HALF).denominator == 1
               for end, x in zip(pair, cross))  # fmt: skip


def _landed_off(args, got) -> list[tuple[str, int, Fraction, Fraction]] | None:
    """(end name, the student's end, the exact crossing, the centre it lies a hair from) of
    each end one column off the exact one, where the crossing lies within a few of float64's
    steps of that centre but not on it (r403 P7: a hair right of it, float64 lands on it and
    the end moves left; a hair left, a float computation that lands past it moves it right).
    None: another difference, or none."""

    def one_off_near_a_centre(name, end, right, x):
        centre = Fraction(min(end, right)) + HALF
        if abs(end - right) != 1 or not _within_float64(x, centre):
            return None
        return (name, end, x, centre)

    return _ends_off(args, got, one_off_near_a_centre)


def _within_float64(x: Fraction, centre: Fraction) -> bool:
    """x lies off ``centre`` by under four of float64's steps there (never on it)."""
    return x != centre and abs(float(x - centre)) < 4 * float(np.spacing(abs(float(centre))))


def _landed_words(args, expected, got, last: bool = False) -> str:
    """r403 P7: a crossing a hair off a centre far out, which a float computation moves onto
    or past it: said with its gap and float64's spacing there; ``last``: the student's
    crossings are exact elsewhere (the table's "float at the last step" gives every answer)."""
    name, end, x, centre = _landed_off(args, got)[0]
    side = "x_l" if name == "first" else "x_r"
    gap = float(x - centre)
    covered = (gap > 0) == (name == "stop")  # right of a centre: x_r covers it, x_l does not
    state, yours = ("covered", "leaves it out") if covered else ("not covered", "covers it")
    lands = "on the centre" if gap > 0 else "past it"
    return (f"{side} lies {abs(gap):.2g} px {'right' if gap > 0 else 'left'} of the centre "
            f"{float(centre):.1f}, not on it, so that centre is {state}; your {name} {end} {yours}: "
            f"{LAST_STEP if last else 'a float anywhere (' + LAST_STEP + ', too)'}: near "
            f"{abs(end):.2g} px float64's numbers are {float(np.spacing(float(abs(end)))):.2g} "
            f"px apart, so it lands {lands}{TOLERANCE}. Round the exact quotient "
            "to a column without a float (integer floor division, or math.ceil of the Fraction "
            "itself)")  # fmt: skip


#: r454 M1, M4: a tolerance gives a float's answers on these rows (the same centre moved)
TOLERANCE = (
    " (or, with no float: a tolerance on the ends, an epsilon that takes a crossing "
    "this close to a centre as on it, moves the same centre; no tolerance is needed)"
)


LAST_STEP = ("an exact crossing, then rounded in float64 at the last step (math.ceil(n / d / "
             "256 - 0.5), math.ceil(float(Fraction) - 0.5))")  # fmt: skip


def _float64_words(args, expected, got) -> str:
    xy, row = args
    if not _ties_off(args, got):
        return _landed_words(args, expected, got)
    name, end, x = _ties_off(args, got)[0]
    side = "x_l" if name == "first" else "x_r"
    found = _float64_of(args, end, x)
    if found is None:  # another rounding order: said as such
        return _rounds_words(args, expected, got)
    start, value, bits = found
    far = math.log2(float(np.abs(xy).max()))
    return (f"on {_edge_of(xy, row, x)} {side} is exactly {_frac(x)}, a centre, and your "
            f"{name} {end} means yours came out a hair right of it: your crossing was computed "
            f"in float64 (multiplied first from the edge's {start} end it lands at {value!r}). "
            f"With vertices near 2^{far:.0f} px the product (y − a_y)(b_x − a_x) needs {bits} "
            "bits on the 1/256-px grid, and float64 holds 53, so it rounds (lesson 01 §4b "
            "proves that order exact for coordinates below 2^18 px, a sufficient bound): "
            "compute the crossing, and its "
            "rounding to a column, exactly, without floats (integers in 1/256-px units, or "
            "fractions.Fraction; a Fraction mixed with a float, such as row + 0.5 or "
            "x - 0.5, is a float)")  # fmt: skip


def _near_off(args, got) -> list[tuple[str, int, Fraction]] | None:
    """Each end one column left of the exact one, where the crossing lies a hair (under
    10^-5 px) right of a centre, not on it (None: another difference, or none)."""

    def one_left_a_hair_right(name, end, right, x):
        if end != right - 1 or not 0 < x - (end + HALF) < Fraction(1, 10**5):
            return None
        return (name, end, x)

    return _ends_off(args, got, one_left_a_hair_right)


def _epsilon_fits(args, expected, got) -> bool:
    return bool(_near_off(args, got))


def _epsilon_words(args, expected, got) -> str:
    name, end, x = _near_off(args, got)[0]
    side = "x_l" if name == "first" else "x_r"
    gap = float(x - (end + HALF))
    state, yours = (("not covered", "covers it") if name == "first"
                    else ("covered", "leaves it out"))  # fmt: skip
    return (f"{side} lies {gap:.2g} px right of the centre {num(end + 0.5)}, not on it, so that "
            f"centre is {state}; your {name} {end} {yours}: an epsilon on the ends (for "
            "safety)? The crossings are exact in the stated range (lesson 01 §4b), so no "
            "tolerance is needed, and any tolerance moves some centre that close")  # fmt: skip


def _swapped_fits(args, expected, got) -> bool:
    xy, row = args
    pair, cross = _returned(got), crossings(xy, Fraction(2 * row + 1, 2))
    if pair is None or cross is None or _horizontal_edge(xy, row + 0.5) == "bottom":
        return False
    lo, hi = (math.ceil(x - HALF) for x in cross)
    return hi > lo and pair == (hi, lo)


def _swapped_words(args, expected, got) -> str:
    """r385 H3, M7: x_l and x_r swapped on this row, without a side test the student may not
    have made (along a top edge: its ends in the order given)."""
    xy, row = args
    xl, xr = crossings(xy, Fraction(2 * row + 1, 2))
    pair = _returned(got)
    if _horizontal_edge(xy, row + 0.5) == "top":
        return (f"your ends along the top edge come back as {pair}, the wrong way round: the "
                f"edge's left end is x = {_frac(xl)}, its smaller x (x_l), and its right end "
                f"x = {_frac(xr)} (x_r); take them by min and max, not in the order given")  # fmt: skip
    return (f"your x_l and x_r are swapped on this row: your pair {pair} is the right one the "
            f"wrong way round, so it covers nothing; x_l = {_frac(xl)} is the smaller "
            f"crossing (on {_edge_of(xy, row, xl)}), x_r = {_frac(xr)} the larger (on "
            f"{_edge_of(xy, row, xr)}): check the test that picks which crossing is x_l "
            "(or take the smaller one)")  # fmt: skip


def _empty_inside_fits(args, expected, got) -> bool:
    """r413 H9 (w43): an empty span returned on a row whose centre line lies inside the
    triangle's rows (y1 <= y < y3), where the crossings hold a column (not a side or ends mistake: the
    pair is no computed one the wrong way round)."""
    xy, row = args
    pair, y = _returned(got), Fraction(2 * row + 1, 2)
    ys = sorted(Fraction(float(p[1])) for p in xy)
    return (pair is not None and pair[1] <= pair[0] and len(expected) > 0
            and ys[0] <= y < ys[2] and not _horizontal_edge(xy, y)  # (that one's own words)
            and not _swapped_fits(args, expected, got))  # fmt: skip


def _empty_inside_words(args, expected, got) -> str:
    xy, row = args
    ys = sorted(Fraction(float(p[1])) for p in xy)
    return (f"you returned an empty span {_returned(got)} on a row whose centre line "
            f"y = {_frac(Fraction(2 * row + 1, 2))} lies inside the triangle's rows "
            f"(y1 = {_frac(ys[0])} ≤ y < y3 = {_frac(ys[2])}, the top and bottom vertices' y "
            "after the sort by y): which rows does your code take "
            "as the triangle's? A row belongs when its centre line does, y1 ≤ row + ½ < y3 "
            "(⌈y1 − ½⌉ ≤ row < ⌈y3 − ½⌉)")  # fmt: skip


def _int64_bits(args) -> int:
    """r413 H7: the most bits of the integer crossing's products on this row, a_x·d and
    (Y − a_y)(b_x − a_x) in 1/256-px units (d = b_y − a_y), over the edges that reach it."""
    xy, row = args
    v = sorted(((round(256 * float(x)), round(256 * float(y))) for x, y in xy),
               key=lambda p: p[1])  # fmt: skip
    y = 256 * row + 128
    bits = 0
    for (ax, ay), (bx, by) in ((v[0], v[2]), (v[0], v[1]), (v[1], v[2])):
        if ay < by and ay <= y <= by:
            bits = max(bits, abs(ax * (by - ay)).bit_length(),
                       abs((y - ay) * (bx - ax)).bit_length())  # fmt: skip
    return bits


def _int64_fits(args, expected, got) -> bool:
    """An end over two columns off where the products pass int64's 63 bits (r413 H7)."""
    pair = _returned(got)
    if pair is None or _int64_bits(args) <= 63 or not expected:
        return False
    return max(abs(pair[0] - min(expected)), abs(pair[1] - max(expected) - 1)) > 2


def _int64_words(args, expected, got) -> str:
    pair = _returned(got)
    off = max(abs(pair[0] - min(expected)), abs(pair[1] - max(expected) - 1))
    return (f"your answer is {off} columns off: here the products of the crossing, a_x·d and "
            f"(y − a_y)(b_x − a_x) in 1/256-px units, need {_int64_bits(args)} bits, more than "
            "int64's 63: your products overflowed int64 silently (numpy's int64 wraps around, "
            "arrays with no warning at all); use Python ints (int(), or dtype=object) or "
            "fractions.Fraction")  # fmt: skip


def doubled_area(xy) -> Fraction:
    """The edge function of the three vertices, exactly (twice the signed area, px²).

    >>> doubled_area(np.array([[0.0, 0.0], [1 / 256, 0.0], [0.0, 1 / 256]]))
    Fraction(1, 65536)
    """
    (x1, y1), (x2, y2), (x3, y3) = ((Fraction(float(a)), Fraction(float(b))) for a, b in xy)
    return (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)


def small_area_fits(xy, expected, got) -> bool:
    """r492 M1, M2, H12, H13: nothing covered on a row with covered points, of a triangle whose
    area is tiny (doubled, under 1/16 px²: a row slip empties larger ones' rows too, such as
    rows ⌊y1⌋ ≤ row < ⌊y3⌋ on a 0.28 px² one) but not zero: zero area by a tolerance."""
    pair = getattr(got, "pair", None)  # an empty pair, not a computed one the wrong way round
    if len(got) or not expected or pair is None or pair[1] < pair[0]:
        return False
    return 0 < abs(doubled_area(xy)) < Fraction(1, 16)


def small_area_words(xy, point: str = "centre") -> str:
    """The words of :func:`small_area_fits`, with the triangle's doubled area."""
    area = abs(doubled_area(xy))
    return (
        f"this triangle has an area, small but not zero: its doubled area (the edge function "
        f"of its three vertices) is {area.numerator}/{area.denominator} px² = {float(area):.3g} "
        f'px², yet you covered no {point}: did you decide "zero area" with a tolerance '
        "(abs(side) < ε)? On the 1/256-px grid the smallest non-zero doubled area is 1/65536 "
        "px²; a triangle covers nothing only when side == 0 exactly (compute it exactly)"
    )


def _zero_area_fits(args, expected, got) -> bool:
    """r424 H3: a zero-area triangle, and columns covered (whatever the ends: no area test)."""
    return winding(args[0]) == "zero area" and len(got) > 0


SYMPTOMS = (
    Mistake(
        "no area test", lambda args, expected, got: ZERO_AREA, fits=_zero_area_fits, symptom=True
    ),  # fmt: skip
    # r413 H7: only where the code reads int64 (any wrong crossing far out is far off too)
    Mistake("int64 overflow", _int64_words, fits=_int64_fits, reads="int64"),
    # r355 C3: named only where float32 explains every failure: a float64 (first, last) or
    # y = row + 1 also misses the one far row where float32 moves an end, and was asked there
    # whether it computed in float32
    # r385 P5: before float32, which also gives a crossing 10^-9 px right of a centre 15000 px
    # out: named where it gives every failing answer (a float32 student fails the far rows too)
    Mistake("epsilon", _epsilon_words, fits=_epsilon_fits, only_whole=True),
    Mistake("float32", _far_float32_words, fits=_far_float32_fits, only_whole=True),
    # r385 P4, H2: a crossing that rounds at a tie (quoted where a usual formula gives it),
    # float32's t named as float32, an epsilon on the ends, x_l and x_r swapped on a row
    # (only where every failing answer is such a tie: one end off at a tie is no cause alone)
    # r385 T1 (session 35): lesson 01's multiply-first order in float64, past 2^18 px
    Mistake(
        "float64 crossing",
        _float64_words,
        fits=_float64_fits,
        symptom=True,
        with_others=True,
        must_fit=lambda args, expected, got: _near_tie_off(args, got),
    ),
    Mistake("crossing rounds", _rounds_words, fits=_rounds_fits, symptom=True, only_whole=True),
    Mistake("x_l and x_r swapped on this row", _swapped_words, fits=_swapped_fits, symptom=True),
    Mistake("horizontal edge", _horizontal_words, gives=_horizontal_gives("top"), symptom=True),
    Mistake("horizontal edge", _horizontal_words, gives=_horizontal_gives("bottom"), symptom=True),
    Mistake("empty inside", _empty_inside_words, fits=_empty_inside_fits, symptom=True),
    # r492 H13: after it (a row's slip that empties a small triangle's row is that symptom)
    Mistake(
        "zero area by a tolerance",
        lambda args, expected, got: small_area_words(args[0]),
        fits=lambda args, expected, got: small_area_fits(args[0], expected, got),
        symptom=True,
    ),  # fmt: skip
    # r372 M3: one end off the same way on every failing case, or not said
    Mistake("ends", _ends_words, fits=_ends_fits, symptom=True, parameter=_end_number),
)


def _horizontal_edge(xy: np.ndarray, y: float) -> str:
    """ "top" or "bottom" when a horizontal edge lies on the line at ``y``, else "" (also for
    a zero-area triangle lying along the line, r355 M5: it lies neither above nor below)."""
    if all(p[1] == y for p in xy):
        return ""
    for k in range(3):
        a, b, c = xy[k], xy[(k + 1) % 3], xy[(k + 2) % 3]
        if a[1] == b[1] == y:
            return "top" if c[1] > y else "bottom"
    return ""


def _frac(x: Fraction) -> str:
    """x as a float; where that float is a centre x is not on (r403 P7: 2^29 px out), with the
    gap, so that no crossing off a centre reads as a tie."""
    near = float(x)
    centre = Fraction(math.floor(x)) + HALF  # r454: 4.5 + 7.1e-15 is a float, 4.500000000000007
    if x != centre and abs(x - centre) < Fraction(1, 10**6):
        gap = float(x - centre)
        return f"{num(float(centre))} {'+' if gap > 0 else '−'} {abs(gap):.2g}"
    return num(near)


def _vertices(xy) -> str:
    return ", ".join(f"({num(p[0])}, {num(p[1])})" for p in xy)


def span_words(cols: frozenset, count: bool = True) -> str:
    """The columns in words (one function for 2.1's and 2.2's reports); ``count``: a wide span's
    number of columns too.

    >>> span_words(frozenset({3, 4, 5})), span_words(frozenset()), span_words(frozenset({2}))
    ('columns 3 to 5', 'none', 'column 2 only')
    """
    if getattr(cols, "wide", False):
        first, stop = cols.pair
        return f"columns {first} to {stop - 1}" + (f", {stop - first} of them" if count else "")
    if not cols:
        return "none"
    lo, hi = min(cols), max(cols)
    return f"columns {lo} to {hi}" if hi > lo else f"column {lo} only"


# -- drawing ----------------------------------------------------------------------------------
def draw_span(ax, case, got):
    """The triangle, the row's centre line, its centres coloured by state (covered, missing,
    extra) and the crossings."""
    from matplotlib.patches import Rectangle

    _, (xy, row), expected = case
    y = row + 0.5
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    got_set = set() if got is None else set(got)
    moved = sorted(expected ^ got_set) if got is not None else []
    lo, hi = _window(xy, expected | got_set, cross, moved[0] if moved else None)
    ring = np.vstack([xy, xy[:1]])
    artists = ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    artists.append(ax.axhline(y, color="#888888", linestyle=":", linewidth=1))
    colours = {"covered": "#c8c8c8", "missing": "#2b7bba", "extra": "#d7301f"}
    for col in range(lo, hi):
        state = _state(col in expected, col in got_set, got is None)
        if state:
            artists.append(ax.add_patch(Rectangle((col, row), 1, 1, color=colours[state],
                                                  alpha=0.8)))  # fmt: skip
        artists += ax.plot(col + 0.5, y, ".", color="black", ms=4, zorder=4)
    if cross is not None:
        xs = [float(cross[0]), float(cross[1])]
        artists += ax.plot(xs, [y, y], "|", color="#ff9f1c", ms=14, mew=3, label="x_l, x_r",
                           zorder=3)  # fmt: skip
        # r355 FIG1: the ticks hid the centres the exercise is about, those exactly on a
        # crossing: drawn above them and ringed, as exercise 1's figure rings its ties
        # (r403 P7: exact crossings, not their floats: one a hair off a centre is no tie)
        ties = sorted({float(x) for x in cross
                       if lo <= x - HALF < hi and (x - HALF).denominator == 1})  # fmt: skip
        if ties:
            artists += ax.plot(ties, [y] * len(ties), "o", mfc="none", mec="black", ms=9,
                               mew=1.2, zorder=5, label="centre on a crossing")  # fmt: skip
    for name, colour in colours.items():
        artists.append(ax.add_patch(Rectangle((0, 0), 0, 0, color=colour, label=name)))
    artists += _roles(ax, xy, lo, hi)
    if got is None:  # r372 F2: the note (an exception) beside the axes, the legend below them
        note_beside(ax)
        artists.append(ax.legend(fontsize="x-small", loc="upper center", ncol=3,
                                 bbox_to_anchor=(0.5, -0.3)))  # fmt: skip
    else:
        artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    ax.set_xlim(lo, hi)
    top, bottom = min(float(xy[:, 1].min()), y) - 1, max(float(xy[:, 1].max()), y) + 1
    if bottom - top > 1000:  # a huge triangle: rows near this one (r385 T1: the far rows')
        top = max(top, row - 6)
    bottom = min(bottom, max(top, row - 6) + 14)
    # r372 F1: a sliver 1/256 px high collapsed the axes to a strip, its y-label into the
    # title: at least a third as many rows as columns, around the row
    tall = max(6.0, (hi - lo) / 3)
    if bottom - top < tall:  # r385 F3: around the rows in view, so no vertex is cut off
        middle = (top + bottom) / 2
        top, bottom = middle - tall / 2, middle + tall / 2
    ax.set_ylim(bottom, top)
    if max(abs(lo), abs(top)) > 10**4:  # r385 T1: far rows, ticks in whole numbers (an offset
        from matplotlib.ticker import MaxNLocator  # text ran into the x-label)

        ax.ticklabel_format(useOffset=False, style="plain")
        ax.xaxis.set_major_locator(MaxNLocator(3 if abs(lo) > 10**7 else 4, integer=True))
        ax.yaxis.set_major_locator(MaxNLocator(4, integer=True))
    ax.set_aspect("equal")
    ax.set_xlabel(f"x (px); row {row}: its centres on y = {num(y)}", fontsize="small")
    ax.set_ylabel("y (px, down)", fontsize="small")
    return artists


def _roles(ax, xy: np.ndarray, lo: int, hi: int) -> list:
    """The sorted vertices' roles at the vertices in view (r372 F2: the task is about the
    split, and no figure said which vertex is the middle one)."""
    # r385 F3: lesson 01's order, two vertices at one height the smaller x first (np.lexsort)
    order = sorted(range(3), key=lambda k: (float(xy[k, 1]), float(xy[k, 0])))
    groups: list[tuple[list[str], float, float]] = []  # vertices closer than a pixel: one label
    for name, k in zip(("top", "middle", "bottom"), order):
        x, y = float(xy[k, 0]), float(xy[k, 1])
        near = next((g for g in groups if abs(g[1] - x) < 1 and abs(g[2] - y) < 1), None)
        if near is not None:
            near[0].append(name)
        elif lo <= x <= hi:
            groups.append(([name], x, y))
    out = []
    # right of the vertex, or left of it in the window's right part, above the crossings' ticks
    # (r385 F3: the labels sat on the centre markers)
    for names, x, y in groups:
        right = x > lo + 0.6 * (hi - lo)
        out.append(ax.annotate(", ".join(names), (x, y), xytext=(-4 if right else 4, 8),
                               textcoords="offset points", ha="right" if right else "left",
                               fontsize="x-small", color="#555555", zorder=6))  # fmt: skip
    return out


def _window(xy: np.ndarray, columns: set, cross, focus: int | None = None) -> tuple[int, int]:
    """The columns drawn: the triangle's, at most 40 of them, around the span when the
    triangle is wider (the wide cases are 10^12 px across; r372 F1: 64, so that the 60-px
    sliver shows both ends of its edge)."""
    lo = math.floor(min(float(xy[:, 0].min()), min(columns, default=0))) - 1
    hi = math.ceil(max(float(xy[:, 0].max()), max(columns, default=0) + 1)) + 1
    if hi - lo <= 64:
        return lo, hi
    centre = (min(columns) + max(columns)) // 2 if columns else lo + 20
    if focus is not None:  # r385 T1: a span of 10^4 columns, wrong at one end: that end
        return focus - 20, focus + 20
    if not columns and cross is not None:
        centre = math.floor((cross[0] + cross[1]) / 2)
    return centre - 20, centre + 20


def _state(rule: bool, yours: bool, no_answer: bool) -> str:
    if no_answer or rule == yours:
        return "covered" if rule else ""
    return "missing" if rule else "extra"


def _mistakes() -> list[Mistake]:
    """The table; a wrong solution that gives some failing answers only is named where it
    gives every failing answer it would change and contradicts no passing one (r372 M4). The
    reversed horizontal rule is named only where it gives every answer: a
    student with no horizontal rule at all (both edges' centres covered) differs from the rule
    on bottom-edge rows only, where the reversed rule also gives its answer."""
    out = []
    for m in variant_mistakes(_variants, MISTAKES, SYMPTOMS):
        if m.gives is not None:  # r372 M4: every failing answer it would change, or no name
            must = _changes(m.gives, m.kind in LAST_STEP_KINDS)
            if m.kind in FLOAT_ORDER_KINDS:  # r413 M10: and a near tie it gets right fails
                must = _or_near_tie(must)
            if m.kind in PRECISION_KINDS:  # r424: every failing answer (float64's far ties
                must = _every  # fail where these precisions are right: no say there)
            m = dataclasses.replace(m, must_fit=must)
            # r372 M4: and only where it contradicts no passing answer
            m = dataclasses.replace(m, consistent=True)
        elif m.kind == "epsilon":  # r454 P1, M1: far out only where no float moves the end
            m = dataclasses.replace(m, fits=_near_or_beyond_float64(m.fits))
        elif m.fits is not None and m.kind not in ("float64 crossing", "int64 overflow"):
            m = dataclasses.replace(m, fits=_near_only(m.fits))
        whole = m.kind in ("horizontal reversed", "first and stop swapped", "x_l and x_r swapped",
                           *PRECISION_KINDS, *TIDY_KINDS)  # fmt: skip
        out.append(dataclasses.replace(m, only_whole=True) if whole else m)
    return out


#: r413 M10: float orders whose crossing is exact on the near ties where it gives the answer:
#: a near tie that fails where it does not is a tie rule's mistake (w36), not the order's
FLOAT_ORDER_KINDS = ("divide first", "slope first")


def _every(args, expected, got) -> bool:
    return True


def _or_near_tie(must):
    def both(args, expected, got) -> bool:
        return must(args, expected, got) or _near_tie_off(args, got)

    return both


def _near_or_beyond_float64(fits):
    """r454 P1, M1: the epsilon's ``fits``, far out too where each moved end's crossing lies
    beyond float64's reach of its centre (:data:`FAR_HAIR`, 7.1·10^-15 px off the centre 4.5,
    where float64's numbers are 8.9·10^-16 px apart): there no float computation gives the
    answer, a tolerance does; elsewhere far out it says nothing, as :func:`_near_only`."""

    def fits_here(args, expected, got):
        if not _far(args[0]):
            return fits(args, expected, got)
        off = _near_off(args, got)
        beyond = off and all(not _within_float64(x, Fraction(end) + HALF) for _, end, x in off)
        return True if beyond else None

    return fits_here


def _near_only(fits):
    """A symptom's ``fits`` that says nothing (None) on the far rows (r385 T1): there a student
    in float64 adds the far crossings' rounding to any other mistake, and a symptom named only
    where it fits every failing answer (an epsilon, a rounding order, one end off) would lose
    its name for it; those rows are the "float64 crossing" symptom's."""

    def near(args, expected, got):
        return None if _far(args[0]) else fits(args, expected, got)

    return near


#: r403 P7: named only where it gives every failing far row (a float crossing, lesson 01's,
#: also fails the far ties, where an exact crossing rounded at the last step is right)
LAST_STEP_KINDS = ("float at the last step",)


def _changes(gives, far: bool = False):
    """``must_fit`` of a wrong solution: the failing cases where it changes the answer. It is
    named only where it gives the student's answer on every one of them (r372 M4: an empty or
    shifted span matched a few cases of "long edge left", "x2 > x1" and "no split" by
    coincidence, and all three were named on a crossing computed with the wrong sign);
    ``far``: every failing far row too."""

    def must(args, expected, got) -> bool:
        if far and _far(np.asarray(args[0])):
            return True
        value = gives(*args)
        return value is not None and not same_span(value, expected)

    return must


SPAN = Exercise(
    "span", span_cases, as_span, same_span, explain_span, _rule,
    _mistakes(), answers=(
        PackageAnswer(rasterize),
        # r413 T1: lesson 01 §5 imports the exact integer loop (its code not printed); every
        # function of its module (dda_start, first_centre_at_or_after, ...) is a part of it
        PackageAnswer(span_fill_int_dda, what="lesson 01's exact span fill (the integer DDA)",
                      modules=("teachraster.study.exact_spans",)),
    ),
    draw=draw_span, constant=_constant_span, raised_words=_span_raised, none_words=_span_none,
    # r454 H7: a loop over rows from a vertex (lesson 01's stepped edges) or over the columns
    slow=" (a loop over the rows from a vertex, or over the columns? One row's span is two "
    "crossings: compute them for this row alone)",
    hints=(
        # r39 02-5: the first wrong try printed the rounding the task asks to work out
        ("so the first column is ⌈x_l − ½⌉", "so which is the first column whose centre lies "
         "at or right of x_l?"),
        (", ⌈x_r − ½⌉ is the first column *not* covered)", ": stop is the first column *not* "
         "covered)"),
        (" (⌈x_l − ½⌉, not ⌊x_l − ½⌋ + 1)", ""),
        ("so take ⌈x_l − ½⌉ and ⌈x_r − ½⌉", "so count the columns whose centres lie between "
         "them, not the integers nearest to them"),
        (": ⌈x_l − ½⌉ ≤ col < ⌈x_r − ½⌉", ""),
        # r424 S2 (r439): the integer ceiling the task leaves to the student
        (": ⌈(n − 128·d) / (256·d)⌉ with n = 256·x·d in integers, d > 0", ""),
        # r372: the crossings a student's ends stand for are the rounding itself
        (re.compile(r"stands for an (x_[lr]) above \S+ and at most \S+, but \1 is"),
         r"is not what \1 gives: \1 is"),
    ),
    match=_match,
)  # fmt: skip
