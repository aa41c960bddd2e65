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

import copy
import math
from fractions import Fraction
from functools import cache

import numpy as np

from ..core.fill import rasterize
from ..core.triangle import Triangle
from .answers import as_numbers, short
from .cases import catalogue_coverage, drawn_coverage, proper_triangles, winding
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .running import WrongAnswerType
from .scalars import num


# -- cases ------------------------------------------------------------------------------------
def span_cases() -> list[tuple[str, tuple, frozenset]]:
    """(label, (xy, row), covered columns) for rows that decide: ties, the split, the ends
    (built once, then copied), and the rows of a few triangles drawn for this check, so a
    table of the fixed cases' answers fails (r46 X1)."""
    out = copy.deepcopy(_span_cases())
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
    out += _wide_cases()
    # first (the drawing of a passing check): a row with covered centres on a vertex's line
    first = next(k for k, case in enumerate(out) if case[2] and "vertex" in case[0])
    return [out[first]] + out[:first] + out[first + 1 :]


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
    if stop - first > 10**6:
        raise WrongAnswerType(f"returned {short(value)}: a span of {stop - first} columns")
    out = Span(range(first, stop))
    out.pair = (first, stop)
    return out


def same_span(got: frozenset, expected: frozenset, args=None) -> bool:
    return set(got) == set(expected)


def _returned(got) -> tuple[int, int] | None:
    return getattr(got, "pair", None)


def _constant_span(value) -> str:
    """A span that never changes, in the student's terms (r39 02-3: not ``frozenset()``)."""
    pair = _returned(value)
    if not value:
        shown = f"{pair} " if pair else ""
        return (
            f"your function returns the same empty span {shown}(stop ≤ first: no column) on "
            "every case, whatever its arguments: a placeholder (such as `return 0, 0`) left "
            "in, or a `return` reached too early?"
        )
    return (
        f"your function returns {_span_words(value)} on every case, whatever its arguments: a "
        "placeholder left in, or a `return` reached too early?"
    )


def _swapped_fits(args, expected, got) -> bool:
    pair = _returned(got)
    return bool(expected) and pair is not None and frozenset(range(pair[1], pair[0])) == expected


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
    # "near" a crossing: only float32's own span names it there
    return near < 1 and min(abs(float(x) - centre) for x in xs) <= near


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
def crossings(xy: np.ndarray, y) -> tuple[Fraction, Fraction] | None:
    """Exact x_l <= x_r where the horizontal line at ``y`` meets the closed triangle (None:
    it misses it, or the triangle has zero area)."""
    v = [(Fraction(float(p[0])), Fraction(float(p[1]))) for p in xy]
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


def _columns(lo, hi) -> frozenset:
    return frozenset(range(lo, hi))


def _variants(xy: np.ndarray, row: int) -> dict[str, frozenset]:
    """The columns typical wrong roundings give on ``row`` (exact crossings)."""
    out = {}
    centre, top = crossings(xy, Fraction(2 * row + 1, 2)), crossings(xy, row)
    half = Fraction(1, 2)
    if centre is not None:
        xl, xr = centre
        # r73 02-1: int(x + ½), C's habit: centres right, ties the wrong way round (it passes
        # every row without a tie, so it is no "sampled at x = col")
        out["ties reversed"] = _columns(math.floor(xl + half), math.floor(xr + half))
        out["corners"] = _columns(math.ceil(xl), math.ceil(xr))
        out["right inclusive"] = _columns(math.ceil(xl - half), math.floor(xr - half) + 1)
        out["left exclusive"] = _columns(math.floor(xl - half) + 1, math.ceil(xr - half))
        out["rounded"] = _columns(round(xl), round(xr))
    out["row top"] = frozenset() if top is None else _columns(math.ceil(top[0] - half),
                                                               math.ceil(top[1] - half))  # fmt: skip
    return out


MISTAKES = {
    "ties reversed": "your columns are right wherever no centre lies exactly on a crossing, "
    "but your ties go the wrong way round: a centre exactly on x_l (the left edge) you left out "
    "and one exactly on x_r (the right edge) you covered (rounding x + ½ down, C's "
    "int(x + 0.5)?): under the top-left rule, which of the two edges owns a centre that lies on "
    "it?",
    "corners": "you rounded the crossings to columns as if pixel col were sampled at x = col "
    "(its left edge): its centre is at x = col + ½, so the first column is ⌈x_l − ½⌉",
    "right inclusive": "you covered the centre that lies exactly on the right edge: by the "
    "top-left rule it belongs to the triangle on the other side (the span stops before it, "
    "⌈x_r − ½⌉ is the first column *not* covered)",
    "left exclusive": "you left out the centre that lies exactly on the left edge: a left edge "
    "owns its centres under the top-left rule (⌈x_l − ½⌉, not ⌊x_l − ½⌋ + 1)",
    "rounded": "you rounded the crossings to the nearest integer: a column is covered when "
    "its centre col + ½ lies between them, so take ⌈x_l − ½⌉ and ⌈x_r − ½⌉",
    "row top": "you intersected the edges with y = row, the top of the pixels, not with the "
    "line of their centres, y = row + ½",
}


def explain_span(args, expected: frozenset, got: frozenset) -> str:
    """The exact crossings of the row's centre line, the covered columns and yours."""
    xy, row = args
    y = row + 0.5
    cross = crossings(xy, Fraction(2 * row + 1, 2))
    if cross is None:
        return (
            f"the centre line y = {num(y)} of row {row} does not cross this {winding(xy)} "
            f"triangle ({_vertices(xy)}), so no column is covered; yours covers {_span_words(got)}"
        )
    xl, xr = cross
    kind = _horizontal_edge(xy, y)
    if kind:  # r85 02: "crosses … from 0.5 to 60.5, so the covered centres are none" read
        # as a contradiction where the line runs along a bottom edge
        owns = "," if kind == "top" else "; a bottom edge owns none of its centres,"
        return (
            f"the centre line y = {num(y)} runs along the triangle's horizontal {kind} edge "
            f"({_vertices(xy)}) from x = {_frac(xl)} to {_frac(xr)}{owns} so the covered "
            f"centres are {_span_words(expected)}; yours: {_span_words(got)}"
        )
    return (
        f"the centre line y = {num(y)} crosses the triangle ({_vertices(xy)}) from x_l = "
        f"{_frac(xl)} to x_r = {_frac(xr)}, so the covered centres are "
        f"{_span_words(expected)}; yours: {_span_words(got)}"
    )


def _rule(args, expected, got) -> str:
    return (
        ": a column is covered when its centre col + ½ lies between the crossings, a centre "
        "on the left edge included and one on the right edge not: ⌈x_l − ½⌉ ≤ col < ⌈x_r − ½⌉"
    )


def _horizontal_fits(args, expected, got) -> bool:
    xy, row = args
    return bool(_horizontal_edge(xy, row + 0.5)) and bool(got) != bool(expected)


def _horizontal_words(args, expected, got) -> str:
    xy, row = args
    if _horizontal_edge(xy, row + 0.5) == "top":
        return (f"you left out the centres on row {row}'s centre line, which runs along a "
                "horizontal top edge: a top edge owns its centres")  # fmt: skip
    return (f"you covered the centres on row {row}'s centre line, the edge's ends taken as "
            "crossings: the triangle lies above the line, and the centres on its bottom edge "
            "go to what lies below it")  # fmt: skip


def _ends_fits(args, expected, got) -> bool:
    return bool(expected) and (
        got == expected - {min(expected)} or got == expected | {max(expected) + 1}
    )


SYMPTOMS = (
    Mistake(
        "first and stop swapped",
        "you returned (stop, first): the pair is (first, stop), "
        "the first covered column and the first one past the span, and a span with stop ≤ "
        "first covers nothing",
        fits=_swapped_fits,
    ),  # fmt: skip
    Mistake("float32", _far_float32_words, fits=_far_float32_fits),
    Mistake("horizontal edge", _horizontal_words, fits=_horizontal_fits, symptom=True),
    Mistake("ends", "one end of your span is off by one column", fits=_ends_fits, symptom=True),
)


def _horizontal_edge(xy: np.ndarray, y: float) -> str:
    """ "top" or "bottom" when a horizontal edge lies on the line at ``y``, else ""."""
    for k in range(3):
        a, b, c = xy[k], xy[(k + 1) % 3], xy[(k + 2) % 3]
        if a[1] == b[1] == y:
            return "top" if c[1] > y else "bottom"
    return ""


def _frac(x: Fraction) -> str:
    return num(float(x))


def _vertices(xy) -> str:
    return ", ".join(f"({num(p[0])}, {num(p[1])})" for p in xy)


def _span_words(cols: frozenset) -> str:
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
    lo, hi = _window(xy, expected | got_set, cross)
    ring = np.vstack([xy, xy[:1]])
    artists = ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    artists.append(ax.axhline(y, color="#888888", linestyle=":", linewidth=1))
    colours = {"covered": "#c8c8c8", "missing": "#2b7bba", "extra": "#d7301f"}
    for col in range(lo, hi):
        state = _state(col in expected, col in got_set, got is None)
        if state:
            artists.append(ax.add_patch(Rectangle((col, row), 1, 1, color=colours[state],
                                                  alpha=0.8)))  # fmt: skip
        artists += ax.plot(col + 0.5, y, ".", color="black", ms=3)
    if cross is not None:
        xs = [float(cross[0]), float(cross[1])]
        artists += ax.plot(xs, [y, y], "|", color="#ff9f1c", ms=14, mew=3, label="x_l, x_r")
    for name, colour in colours.items():
        artists.append(ax.add_patch(Rectangle((0, 0), 0, 0, color=colour, label=name)))
    artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    ax.set_xlim(lo, hi)
    top, bottom = min(float(xy[:, 1].min()), y) - 1, max(float(xy[:, 1].max()), y) + 1
    ax.set_ylim(min(bottom, max(top, row - 6) + 14), top)  # a huge triangle: rows near this one
    ax.set_aspect("equal")
    ax.set_xlabel(f"x (px); row {row}: its centres on y = {num(y)}", fontsize="small")
    return artists


def _window(xy: np.ndarray, columns: set, cross) -> tuple[int, int]:
    """The columns drawn: the triangle's, at most 40 of them, around the span when the
    triangle is wider (the wide cases are 10^12 px across)."""
    lo = math.floor(min(float(xy[:, 0].min()), min(columns, default=0))) - 1
    hi = math.ceil(max(float(xy[:, 0].max()), max(columns, default=0) + 1)) + 1
    if hi - lo <= 40:
        return lo, hi
    centre = (min(columns) + max(columns)) // 2 if columns else lo + 20
    if not columns and cross is not None:
        centre = math.floor((cross[0] + cross[1]) / 2)
    return centre - 20, centre + 20


def _state(rule: bool, yours: bool, no_answer: bool) -> str:
    if no_answer or rule == yours:
        return "covered" if rule else ""
    return "missing" if rule else "extra"


SPAN = Exercise(
    "span", span_cases, as_span, same_span, explain_span, _rule,
    variant_mistakes(_variants, MISTAKES, SYMPTOMS), answers=(PackageAnswer(rasterize),),
    draw=draw_span, constant=_constant_span, hints=(
        # r39 02-5: the first wrong try printed the rounding the task asks to work out
        ("so the first column is ⌈x_l − ½⌉", "so which is the first column whose centre lies "
         "at or right of x_l?"),
        (", ⌈x_r − ½⌉ is the first column *not* covered)", ": stop is the first column *not* "
         "covered)"),
        (" (⌈x_l − ½⌉, not ⌊x_l − ½⌋ + 1)", ""),
        ("so take ⌈x_l − ½⌉ and ⌈x_r − ½⌉", "so count the columns whose centres lie between "
         "them, not the integers nearest to them"),
        (": ⌈x_l − ½⌉ ≤ col < ⌈x_r − ½⌉", ""),
    ),
    match=lambda got, answer, args: set(got) == set(answer),
)  # fmt: skip
