"""Exercise ``box`` (exercise 1, task 1.2): the rows and columns of pixel centres a triangle's
bounding box can hold a covered centre in, clamped to the image (issue 30, r453 T1).

``box(xy, width, height)`` returns ``(i0, i1, j0, j1)``: rows ``i0 <= i < i1`` and columns
``j0 <= j < j1``, the smallest such box, computed from the bounding box [x_min, x_max] ×
[y_min, y_max] alone, that holds every centre *some* triangle with that bounding box covers
under the top-left rule. A centre on the bounding box's top or left side can be covered (a
horizontal top edge, a vertical left edge owns it); one on its right or bottom side never is
(only a right or bottom edge, or the rightmost or lowest vertex, lies there). So the box is
half-open on both axes: ⌈x_min − ½⌉ ≤ j < ⌈x_max − ½⌉, ⌈y_min − ½⌉ ≤ i < ⌈y_max − ½⌉, clamped
to [0, width] and [0, height]. Lesson 02 §1 prints the closed box (⌊x_max − ½⌋ + 1, the
package's :func:`~teachraster.core.bbox.pixel_bbox` too), which keeps a row or column the
rule never covers: pasted, it fails on the ties at x_max and y_max.

Expected answers are exact (:class:`fractions.Fraction` of the 1/256-px vertices); the tests
cross-check them against the package: the bounding rectangle filled as two triangles by
:func:`teachraster.rasterize` (watertight, so it covers exactly the centres the box holds)
covers exactly the box's first and last rows and columns.
"""

from __future__ import annotations

import math
from dataclasses import replace
from fractions import Fraction
from functools import cache

import numpy as np

from ..core.bbox import pixel_bbox
from ..core.fill import rasterize
from .answers import short
from .cases import drawn_rng, winding
from .drawing import note_beside
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .running import WrongAnswerType
from .scalars import num

HALF = Fraction(1, 2)


def _bounds(xy) -> tuple[Fraction, Fraction, Fraction, Fraction]:
    """(x_min, x_max, y_min, y_max), exactly."""
    xs = [Fraction(float(p[0])) for p in xy]
    ys = [Fraction(float(p[1])) for p in xy]
    return min(xs), max(xs), min(ys), max(ys)


def _clamp(v: int, n: int) -> int:
    return min(max(int(v), 0), n)


def centre_box(xy, width: int, height: int) -> tuple[int, int, int, int]:
    """The right answer, exactly: (i0, i1, j0, j1), ⌈min − ½⌉ … ⌈max − ½⌉ clamped.

    >>> xy = np.array([[2.5, 1.5], [6.5, 1.5], [2.5, 5.5]])  # centres on all four sides
    >>> centre_box(xy, 10, 8)
    (1, 5, 2, 6)
    >>> centre_box(xy, 4, 3)  # clamped to the image
    (1, 3, 2, 4)
    """
    x0, x1, y0, y1 = _bounds(xy)
    return (_clamp(math.ceil(y0 - HALF), height), _clamp(math.ceil(y1 - HALF), height),
            _clamp(math.ceil(x0 - HALF), width), _clamp(math.ceil(x1 - HALF), width))  # fmt: skip


def is_empty(b) -> bool:
    return b[1] <= b[0] or b[3] <= b[2]


def same_box(got, expected, args=None) -> bool:
    """The same centres: equal boxes, or both empty (``range(5, 3)`` loops over nothing, as
    ``range(3, 3)`` does). For a triangle of zero area an empty box is right too."""
    if got is None:
        return False
    if is_empty(got) or is_empty(expected):
        return (is_empty(got) and is_empty(expected)) or (
            args is not None and is_empty(got) and _area2(args[0]) == 0
        )
    return tuple(got) == tuple(expected)


def _area2(xy) -> Fraction:
    (ax, ay), (bx, by), (cx, cy) = ([Fraction(float(v)) for v in p] for p in xy)
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)


def as_box(value) -> tuple[int, int, int, int]:
    """Four whole numbers (i0, i1, j0, j1) as ints; floats are refused (``range`` needs ints)."""
    if value is None:
        raise WrongAnswerType("returned None (a missing `return`?)")
    if isinstance(value, (str, bytes)):
        raise WrongAnswerType(f"returned the text {short(value)}; expected four ints (i0, i1, "
                              "j0, j1)")  # fmt: skip
    if isinstance(value, (dict, set)) or not hasattr(value, "__len__"):
        raise WrongAnswerType(f"returned {short(value)}; expected four ints (i0, i1, j0, j1)")
    items = list(value)
    if len(items) != 4:
        raise WrongAnswerType(
            f"returned {short(value)}, {len(items)} values; expected four ints (i0, i1, j0, j1)"
        )
    out = []
    for v in items:
        if isinstance(v, (bool, np.bool_)):
            raise WrongAnswerType(f"returned {short(value)}: bools, not row or column numbers")
        if isinstance(v, (int, np.integer)):
            out.append(int(v))
            continue
        if isinstance(v, (float, np.floating)) and math.isfinite(v) and float(v).is_integer():
            raise WrongAnswerType(
                f"returned {short(value)}, floats: the fill's `range(i0, i1)` takes ints only "
                "(np.ceil and np.floor return floats): convert each with int(...)"
            )
        what = "a text" if isinstance(v, (str, bytes)) else "not a whole int"
        raise WrongAnswerType(f"returned {short(value)}: {short(v)} is {what}; each of i0, i1, j0, "
                              "j1 is a whole int")  # fmt: skip
    return tuple(out)


#: r505 WP1: a box that changes ``xy`` in place (``xy -= 0.5``, ``xy.sort(axis=0)``) returned
#: the right box, but the given fill calls ``covers(xy, …)`` on the same array after it
CHANGED_XY = (
    "changed xy in place ({how}): the given fill calls box(xy, …) and then covers(xy, …) on "
    "the same array, so covers would test another triangle. Compute on new values (xs = "
    "xy[:, 0] - 0.5 makes a new array; xy -= 0.5, xy.sort() and xy[...] = … change the "
    "caller's)"
)


def call_box(fn, args) -> tuple[int, int, int, int]:
    """The student's box, read strictly; refused where the call changed ``xy``."""
    xy = args[0]
    before = np.array(xy, dtype=float, copy=True)
    value = fn(*args)
    after = np.asarray(xy)
    if after.shape != before.shape or not np.array_equal(after, before):
        how = (
            "its vertices reordered: xy.sort()?"
            if after.shape == before.shape and np.array_equal(np.sort(after, 0), np.sort(before, 0))
            else f"v1 was {tuple(float(v) for v in before[0])}, now "
            f"{tuple(float(v) for v in np.ravel(after)[:2])}"
        )
        raise WrongAnswerType(CHANGED_XY.format(how=how))
    return as_box(value)


# -- cases ------------------------------------------------------------------------------------
def _case(label, xy, width, height):
    xy = np.array(xy, dtype=float)
    return (label, (xy, width, height), centre_box(xy, width, height))


@cache
def _fixed() -> list:
    far = 100000.0
    return [
        _case("centres on all four sides of the bounding box (a top edge, a vertical left edge)",
              [[2.5, 1.5], [6.5, 1.5], [2.5, 5.5]], 10, 8),
        _case("centres on its right and bottom sides only (x_max, y_max at vertices)",
              [[1.25, 0.75], [5.5, 3.25], [2.0, 6.5]], 9, 9),
        _case("no centre on a side, bounds past the half",
              [[1.75, 2.75], [7.25, 1.625], [4.0, 6.25]], 10, 9),
        # r494 M1, M2: bounds 1/256 px off a centre, near the origin (float32 holds them): a
        # tolerance subtracted (added) before rounding up moves them, float32 does not
        _case("x_min and y_max 1/256 px past a centre, x_max 1/256 px before one",
              [[2.50390625, 1.75], [7.49609375, 3.0], [4.0, 5.50390625]], 10, 8),
        # r494 H1: x_min − ½ and y_min − ½ between −1 and 0, where int() truncates up
        _case("x_min and y_min within half a pixel of the image's top-left corner",
              [[-0.25, 0.25], [5.75, 2.0], [2.0, 4.75]], 8, 7),
        _case("whole-number bounds (a pixel's corners)",
              [[3.0, 2.0], [8.0, 4.0], [5.0, 7.0]], 11, 9),
        _case("centres on its left and top sides only (x_min = 3.5, y_min = 5.5)",
              [[3.5, 5.5], [8.25, 6.75], [6.0, 10.25]], 12, 12),
        _case("the same triangle clockwise", [[2.5, 1.5], [2.5, 5.5], [6.5, 1.5]], 10, 8),
        _case("reaching past every border of a 12 × 9 image",
              [[-3.25, -2.5], [14.75, 3.0], [2.0, 12.5]], 12, 9),
        _case("past the left and top borders", [[-2.5, -1.25], [5.25, -0.75], [1.0, 4.5]], 10, 7),
        _case("past the right and bottom borders of an 11 × 8 image",
              [[6.5, 3.25], [13.75, 5.0], [8.0, 11.5]], 11, 8),
        _case("left of the image", [[-9.5, 1.0], [-3.25, 2.0], [-6.0, 5.0]], 10, 8),
        _case("right of and below the image", [[12.5, 9.0], [15.0, 10.0], [13.0, 14.0]], 10, 8),
        _case("covering the whole image", [[-20.0, -20.0], [60.0, -20.0], [-20.0, 60.0]], 16, 12),
        _case("tiny, between four centres (no centre in its bounding box)",
              [[2.625, 3.625], [2.875, 3.625], [2.75, 3.875]], 8, 8),
        _case("a vertical sliver with its left edge on centres",
              [[4.5, 1.0], [4.5390625, 6.0], [4.5, 7.25]], 9, 9),
        _case("a flat sliver with its top edge on centres",
              [[1.0, 3.5], [7.0, 3.5], [4.0, 3.53125]], 9, 6),
        # r494 WP1: the triangle covers no centre, its bounding box holds 18
        _case("a sliver covering no centre (its bounding box holds some)",
              [[1.25, 1.0], [6.75, 3.75], [6.75, 3.8125]], 9, 7),
        _case("zero area (three vertices on a line)", [[1.0, 1.0], [3.0, 3.0], [5.0, 5.0]], 8, 8),
        _case("100 000 px from the origin in x, in a 100 008 × 6 image",
              [[far + 0.50390625, 1.25], [far + 3.75, 2.0], [far + 1.0, 3.75]], 100008, 6),
        _case("100 000 px from the origin in y, in a 5 × 100 008 image",
              [[1.25, far + 0.50390625], [2.0, far + 3.75], [3.75, far + 1.0]], 5, 100008),
    ]  # fmt: skip


def _drawn(rng) -> list:
    out = []
    for k in range(8):
        w, h = int(rng.integers(6, 20)), int(rng.integers(6, 20))
        # 1/256-px vertices, half of them on a half-integer (a centre's line): ties
        xy = rng.integers(-3 * 256, (max(w, h) + 3) * 256, size=(3, 2)) / 256
        tie = rng.random((3, 2)) < 0.5
        xy = np.where(tie, np.floor(xy) + 0.5, xy)
        out.append(_case(f"drawn for this check {k + 1}, {winding(xy)}", xy, w, h))
    return out


def box_cases() -> list:
    """(label, (xy, width, height), (i0, i1, j0, j1)): the fixed cases, then 8 drawn ones."""
    return [(lab, (a[0].copy(), a[1], a[2]), e) for lab, a, e in _fixed()] + _drawn(drawn_rng())


# -- mistakes ---------------------------------------------------------------------------------
def _f(v: Fraction, form: str) -> int:
    """One end by a formula (exact; Python's round halves to even, as np.round does)."""
    return {
        "ceil-half": lambda: math.ceil(v - HALF),
        "floor-half+1": lambda: math.floor(v - HALF) + 1,
        "floor": lambda: math.floor(v),
        "ceil": lambda: math.ceil(v),
        "round": lambda: round(v),
        "round-half": lambda: round(v - HALF),
        "floor-half": lambda: math.floor(v - HALF),
        "ceil+half": lambda: math.ceil(v + HALF),
        "ceil-half-1": lambda: math.ceil(v - HALF) - 1,
        "trunc": lambda: math.trunc(v - HALF) + (0 if (v - HALF).denominator == 1 else 1),
        "ceil-1": lambda: math.ceil(v) - 1,
    }[form]()


#: The first row's (column's) forms and their words; the right one is "ceil-half".
FIRST = {
    "floor-half+1": "you leave out a centre lying exactly on the bounding box's {lo} side "
    "(your first {what} is the first centre strictly past {vmin}): can the rule cover a centre "
    "there: a {edge} lying on that side owns its centres",
    "floor": "your first {what} is the first pixel the bounding box touches (⌊{vmin}⌋), not the "
    "first whose centre lies in it: a pixel whose centre lies before {vmin} holds no covered "
    "centre",
    "ceil": "your first {what} is ⌈{vmin}⌉, the first whole coordinate: pixel k's centre is at "
    "k + ½, so a pixel whose centre lies past {vmin} is left out",
    "round": "your first {what} is {vmin} rounded (round() or np.round: half to even), which "
    "goes the wrong way where {vmin} lies on a centre",
    # r505 H1, H2: round() goes to the nearest whole number, not only wrong on a corner
    "round-half": "your first {what} rounds {vmin} − ½ to the nearest whole number (round() or "
    "np.round): where {vmin} lies past a pixel's centre, that is the pixel {vmin} lies in, "
    "whose centre comes before {vmin} (and on a pixel's corner round() halves to even); the "
    "first centre at or past {vmin} is the first {what} of the box",
    # r505 H2: ⌈v⌉ − 1, the pixel v lies in (one before it where v is whole)
    "ceil-1": "your first {what} is ⌈{vmin}⌉ − 1, the pixel {vmin} lies in (and one before it "
    "where {vmin} is whole): where {vmin} lies past that pixel's centre, the centre comes "
    "before {vmin}; the first centre at or past {vmin} is the first {what} of the box",
    "floor-half": "your first {what} is the last centre at or before {vmin} (⌊{vmin} − ½⌋), "
    "one before the first centre inside",
    "ceil+half": "your first {what} is ⌈{vmin} + ½⌉: pixel k's centre is at k + ½, and adding "
    "½ moves the bound the wrong way",
    # r494 H1: a ceil made by hand, int(t) + 1, and int() truncates toward 0
    "trunc": "your first {what} is int({vmin} − ½) + 1 (a ceil made with int()?): int() "
    "truncates toward 0, not down, so where {vmin} − ½ lies between −1 and 0 it gives 1, not "
    "⌈{vmin} − ½⌉ = 0, and the image's first {what} is left out (math.ceil rounds up for "
    "negative numbers too)",
}
#: The end row's (column's) forms; the right one is "ceil-half".
END = {
    "floor-half+1": "you keep the {what} whose centre lies exactly on the bounding box's {hi} "
    "side ({vmax}), as lesson 02 §1's closed box does: only a right or bottom edge, or the "
    "rightmost or lowest vertex, can lie on that side, and the top-left rule never covers a "
    "centre on them",
    "ceil": "your end {what} is ⌈{vmax}⌉, past the last pixel the bounding box touches, not the "
    "last centre inside it: pixel k's centre is at k + ½",
    "floor-half": "your box stops one {what} short: ⌊{vmax} − ½⌋ is the last centre at or "
    "before {vmax}, and the end of a half-open range is one past the last {what} it holds",
    "floor": "your end {what} is ⌊{vmax}⌋: a centre between ⌊{vmax}⌋ + ½ and {vmax} is left out, "
    "and one at ⌊{vmax}⌋ − ½ kept whatever",
    "round": "your end {what} is {vmax} rounded (round() or np.round: half to even)",
    # r505 H3: told as ⌊x_max⌋, whose values it has off the whole numbers
    "round-half": "your end {what} rounds {vmax} − ½ to the nearest whole number (round() or "
    "np.round): where {vmax} lies less than half a pixel past a centre, that centre's {what} "
    "is left out, though it lies before {vmax}",
    "ceil+half": "your end {what} is ⌈{vmax} + ½⌉: pixel k's centre is at k + ½, and adding ½ "
    "moves the bound the wrong way",
    "ceil-half-1": "your end {what} is the last {what} the box holds: the task's end is one "
    "past it (a half-open range, as range(i0, i1))",
}
AXES = {
    "rows": dict(what="row", lo="top", hi="bottom", vmin="y_min", vmax="y_max",
                 edge="horizontal top edge"),
    "columns": dict(what="column", lo="left", hi="right", vmin="x_min", vmax="x_max",
                    edge="vertical left edge"),
}  # fmt: skip


def _axis_words(axis: str, end: str, form: str) -> str:
    table = FIRST if end == "first" else END
    text = table[form].format(**AXES[axis])
    return f"{axis}: {text}"


def _box_with(xy, width, height, forms=None, clamp="both", swap_axes=False, f32=False):
    """A box with wrong parts: ``forms`` {(axis, first|end): form}, the clamping, axes read
    the other way round, vertices in float32."""
    forms = forms or {}
    if f32:
        v = np.asarray(xy, dtype=np.float32)
        xs = [np.float32(p[0]) for p in v]
        ys = [np.float32(p[1]) for p in v]

        def end(vals, first):
            m = min(vals) if first else max(vals)
            return int(np.ceil(m - np.float32(0.5)))

        r0, r1, c0, c1 = end(ys, True), end(ys, False), end(xs, True), end(xs, False)
    else:
        x0, x1, y0, y1 = _bounds(xy)
        r0 = _f(y0, forms.get(("rows", "first"), "ceil-half"))
        r1 = _f(y1, forms.get(("rows", "end"), "ceil-half"))
        c0 = _f(x0, forms.get(("columns", "first"), "ceil-half"))
        c1 = _f(x1, forms.get(("columns", "end"), "ceil-half"))
    nr, nc = (width, height) if clamp == "swapped" else (height, width)
    if swap_axes:
        r0, r1, c0, c1 = c0, c1, r0, r1
    if clamp in ("both", "swapped"):
        return _clamp(r0, nr), _clamp(r1, nr), _clamp(c0, nc), _clamp(c1, nc)
    if clamp == "none":
        return r0, r1, c0, c1
    if clamp == "low":
        return max(r0, 0), max(r1, 0), max(c0, 0), max(c1, 0)
    if clamp == "high":
        return min(r0, nr), min(r1, nr), min(c0, nc), min(c1, nc)
    if clamp == "last":  # the end clamped to n − 1, as an index
        return (_clamp(r0, nr - 1), _clamp(r1, nr - 1), _clamp(c0, nc - 1), _clamp(c1, nc - 1))
    if clamp == "first last":  # r505 H4: the first clamped to n − 1, the end to n
        return _clamp(r0, nr - 1), _clamp(r1, nr), _clamp(c0, nc - 1), _clamp(c1, nc)
    raise ValueError(clamp)


def _form_kinds() -> dict:
    """{kind: ({(axis, end): form}, words)}: one wrong end form on both axes, then on one."""
    out = {}
    for end, table in (("end", END), ("first", FIRST)):
        for form in table:
            both = {("rows", end): form, ("columns", end): form}
            words = table[form].format(
                what="row or column", lo="top or left", hi="right or bottom",
                vmin="x_min (y_min)", vmax="x_max (y_max)",
                edge="horizontal top edge or a vertical left edge")  # fmt: skip
            out[f"{end} {form}, both axes"] = (both, words)
            for axis in AXES:
                out[f"{end} {form}, {axis}"] = ({(axis, end): form}, _axis_words(axis, end, form))
    # two slips at once, on both axes: lesson 02 §1's closed box with its first row or column
    # wrong too, the box of the pixels the bounding box touches (⌊min⌋, ⌈max⌉), ...
    both = dict(what="row or column", lo="top or left", hi="right or bottom",
                vmin="x_min (y_min)", vmax="x_max (y_max)",
                edge="horizontal top edge or a vertical left edge")  # fmt: skip
    for first in FIRST:
        for end in END:
            forms = {(a, "end"): end for a in AXES} | {(a, "first"): first for a in AXES}
            words = {("floor", "ceil"): PIXEL_BOX, ("floor", "floor"): FLOORED}.get(
                (first, end), FIRST[first].format(**both) + "; and " + END[end].format(**both)
            )
            out[f"first {first} and end {end}"] = (forms, words)  # fmt: skip
    return out


PIXEL_BOX = (
    "your box is that of the pixels the bounding box touches (⌊min⌋ … ⌈max⌉), not of the "
    "pixels whose centre it holds: the first row or column whose centre (k + ½) lies at or "
    "past the minimum, and the end where the centres reach the maximum"
)


#: r494 H3: the vertices cast to int (``astype(int)``) before the right formula gives ⌊v⌋ at
#: both ends.
FLOORED = (
    "your box runs from ⌊min⌋ to ⌊max⌋, as if the vertices were rounded down to whole numbers "
    "first (int(), astype(int)?): they lie on the 1/256-px grid, keep them as they are; pixel "
    "k's centre is at k + ½, so the first centre at or past a bound is not ⌊bound⌋"
)


FORM_KINDS = _form_kinds()

CLAMP_WORDS = {
    "none": "your box is not clamped to the image: a row or column index below 0 or at or "
    "past height (width) lies outside it (numpy wraps a negative index round to the far side)",
    "low": "your box is clamped below (at 0) but not above: an end past height (width) "
    "indexes outside the image",
    "high": "your box is clamped above (at height, width) but not below: a negative first "
    "row or column wraps round to the image's far side in numpy",
    "last": "you clamped the ends to height − 1 and width − 1, the last index: the end of a "
    "half-open range is one past it, so the image's last row or column is left out",
    "swapped": "you clamped the rows to width and the columns to height: rows count down the "
    "image's height, columns across its width",
    "first last": "you clamped the first row (column) to height − 1 (width − 1), the last index: "
    "where the triangle lies wholly below (right of) the image, its box must be empty, and "
    "yours holds the image's last row (column); the first is clamped to the same range as the "
    "end, 0 to height (width)",
}


def _variants(xy, width, height) -> dict:
    out = {}
    for kind, (forms, _) in FORM_KINDS.items():
        out[kind] = _box_with(xy, width, height, forms)
    for clamp in CLAMP_WORDS:
        out[f"clamp {clamp}"] = _box_with(xy, width, height, clamp=clamp)
    out["closed, not clamped"] = _box_with(
        xy, width, height, {(a, "end"): "floor-half+1" for a in AXES}, clamp="none"
    )
    out["closed, clamped to n − 1"] = _box_with(
        xy, width, height, {(a, "end"): "floor-half+1" for a in AXES}, clamp="last"
    )
    out["an empty axis as row or column 0"] = _empty_axis_as_zero(centre_box(xy, width, height))
    out["axes swapped"] = _box_with(xy, width, height, swap_axes=True)
    r0, r1, c0, c1 = centre_box(xy, width, height)
    out["columns first"] = (c0, c1, r0, r1)
    out["first, first, end, end"] = (r0, c0, r1, c1)
    out["float32"] = _box_with(xy, width, height, f32=True)
    out["whole image"] = (0, height, 0, width)
    out["y up"] = (_clamp(height - r1, height), _clamp(height - r0, height), c0, c1)
    a = np.asarray(xy, dtype=float)
    out["min over axis 1"] = _from_bounds(a.min(axis=1)[:2], a.max(axis=1)[:2], width, height)
    for pair, kind in PAIRS.items():  # r505 H5: v1 and v3 too
        two = a[list(pair)]
        out[kind] = _from_bounds(two.min(axis=0), two.max(axis=0), width, height)
    lo, hi = a.min(), a.max()  # r505 H6: np.min(xy) without axis=0
    out["mixed axes"] = _from_bounds((lo, lo), (hi, hi), width, height)
    x0, y0 = a.min(axis=0)
    x1, y1 = a.max(axis=0)
    for kind, (lo, hi) in {  # r505 H7 (r494 H5): one end from the other axis
        "first row from x": ((x0, x0), (x1, y1)), "end row from x": ((x0, y0), (x1, x1)),
        "first column from y": ((y0, y0), (x1, y1)), "end column from y": ((x0, y0), (y1, y1)),
    }.items():  # fmt: skip
        out[kind] = _from_bounds(lo, hi, width, height)
    return out


#: (vertex indices): kind, for a bounding box of two vertices only
PAIRS = {(0, 1): "two vertices", (0, 2): "vertices v1, v3", (1, 2): "vertices v2, v3"}


def _empty_axis_as_zero(b):
    """r494 H4: an axis with no centre replaced by row (column) 0, as ``[...] or [0]`` does."""
    r0, r1, c0, c1 = b
    rows = (0, 1) if r1 <= r0 else (r0, r1)
    cols = (0, 1) if c1 <= c0 else (c0, c1)
    return None if (*rows, *cols) == tuple(b) else (*rows, *cols)


def _from_bounds(lo, hi, width, height):
    """The right formula on wrong bounds (lo = (x_min, y_min), hi = (x_max, y_max))."""
    first = [math.ceil(Fraction(float(v)) - HALF) for v in (*lo, *hi)]
    return (
        _clamp(first[1], height),
        _clamp(first[3], height),
        _clamp(first[0], width),
        _clamp(first[2], width),
    )


WORDS = {kind: words for kind, (_, words) in FORM_KINDS.items()}
WORDS |= {f"clamp {k}": w for k, w in CLAMP_WORDS.items()}
WORDS |= {
    "closed, not clamped": END["floor-half+1"].format(what="row or column",
                                                      hi="right or bottom", vmax="x_max (y_max)")
    + "; and " + CLAMP_WORDS["none"],
    "closed, clamped to n − 1": END["floor-half+1"].format(
        what="row or column", hi="right or bottom", vmax="x_max (y_max)")
    + "; and " + CLAMP_WORDS["last"],
    "an empty axis as row or column 0": "where no row (or column) of the image holds a centre "
    "of the box, you return row 0 (column 0), as `[...] or [0]` does: the box is empty there "
    "(i0 == i1 or j0 == j1), and a fill over it must draw nothing",
    "axes swapped": "your rows come from the x coordinates and your columns from y: a row i "
    "is a horizontal line of pixels, its centres at y = i + ½",
    "columns first": "you returned (j0, j1, i0, i1), columns first: the task asks (i0, i1, j0, "
    "j1), rows first, as an image is indexed [row, column]",
    "first, first, end, end": "you returned (i0, j0, i1, j1): the task asks (i0, i1, j0, j1), "
    "the rows' range, then the columns'",
    "float32": "your bounds are computed in float32: far from the origin float32 numbers are "
    "0.0078125 px apart and cannot hold the vertices' 1/256-px grid, so a bound moves past a "
    "centre. Compute in float64 (Python floats)",
    "y up": "your rows count up from the image's bottom (y up): y grows downwards here, row 0 "
    "at the top",
    "min over axis 1": "your bounds are minima and maxima over each vertex's own (x, y) "
    "(axis=1), not over the three vertices' x and y (axis=0 of the 3 × 2 array)",
    "two vertices": "your bounding box is that of the first two vertices only: take every "
    "vertex's",
    "vertices v1, v3": "your bounding box is that of two vertices only, v1 and v3 (xy[0] and "
    "xy[2]): take every vertex's",
    "vertices v2, v3": "your bounding box is that of two vertices only, v2 and v3 (xy[1] and "
    "xy[2]): take every vertex's",
    "mixed axes": "your bounds mix x and y: they are the minimum and maximum over all six "
    "coordinates (np.min(xy) without axis=0?), not over the three x and the three y apart",
    "first row from x": "your first row comes from x_min, not y_min: rows count down, from y",
    "end row from x": "your end row comes from x_max, not y_max: rows count down, from y",
    "first column from y": "your first column comes from y_min, not x_min: columns count "
    "across, from x",
    "end column from y": "your end column comes from y_max, not x_max: columns count across, "
    "from x",
    "whole image": "you returned the whole image (0, height, 0, width): a placeholder? The box "
    "must come from the triangle's bounding box",
}  # fmt: skip


def _covered_box_fits(args, expected, got) -> bool | None:
    """The box of the pixels the package covers (a fill first, then its extent)."""
    xy, w, h = args
    cov = rasterize(_tri(xy), w, h).coverage
    rows, cols = np.flatnonzero(cov.any(axis=1)), np.flatnonzero(cov.any(axis=0))
    if not rows.size:
        return is_empty(got) and not is_empty(expected)
    return tuple(got) == (rows[0], rows[-1] + 1, cols[0], cols[-1] + 1) != tuple(expected)


def _tri(xy):
    from ..core.triangle import Triangle

    return Triangle(np.asarray(xy, dtype=float))


#: r494 M1, M2: the largest tolerance named (ε = 0.004, 0.05 were told as float32 or ⌊x_max⌋).
MAX_TOLERANCE = Fraction(1, 8)
_ENDS = (("rows", "first"), ("rows", "end"), ("columns", "first"), ("columns", "end"))


def _tolerance(args, expected, got):
    """(sign, moved ends) of a box whose bounds were rounded up with a tolerance, ⌈v − ½ ∓ ε⌉
    with 0 < ε ≤ 1/8, that gives ``got`` and not the box; None where none does."""
    xy, w, h = args
    x0, x1, y0, y1 = _bounds(xy)
    ts = [t - HALF for t in (y0, y1, x0, x1)]
    sizes = (h, h, w, w)
    right = [_clamp(math.ceil(t), n) for t, n in zip(ts, sizes)]
    tiny = Fraction(1, 2**20)
    found = []
    for sign in (-1, 1):
        # −ε moves a bound ε or less past a centre; +ε one on a centre or less than ε before it
        gaps = {t - math.floor(t) if sign < 0 else math.ceil(t) - t + tiny for t in ts}
        for eps in sorted(g for g in gaps if 0 < g <= MAX_TOLERANCE + tiny):
            ends = tuple(_clamp(math.ceil(t + sign * eps), n) for t, n in zip(ts, sizes))
            moved = [k for k in range(4) if ends[k] != right[k]]
            # r505 M1: an empty answer only as this very box (any two empty boxes are the
            # same centres, so (0, 0, 0, 0) for a thin triangle fitted an ε)
            fit = tuple(got) == ends if is_empty(got) else same_box(got, ends, args)
            if moved and fit:
                found.append((tuple(got) != ends, sign, moved))  # an exact match first
    return min(found, key=lambda f: f[0])[1:] if found else None


def _tolerance_fits(args, expected, got) -> bool | None:
    if got is None or same_box(got, expected, args):
        return None
    return _tolerance(args, expected, got) is not None


def _tolerance_words(args, expected, got) -> str:
    sign, moved = _tolerance(args, expected, got)
    x0, x1, y0, y1 = _bounds(args[0])
    values = (y0, y1, x0, x1)
    names = ("y_min", "y_max", "x_min", "x_max")
    parts = []
    for k in moved:
        v = values[k]
        axis, end = _ENDS[k]
        centre = (math.floor(v - HALF) if sign < 0 else math.ceil(v - HALF)) + HALF
        where = (f"{num(float(abs(v - centre)))} px {'past' if sign < 0 else 'before'} the "
                 f"centre {num(float(centre))}" if v != centre else "exactly on a centre")  # fmt: skip
        parts.append(
            f"your {end} {axis[:-1]} is one {'less' if sign < 0 else 'more'} than the box's "
            f"({names[k]} = {num(float(v))} lies {where})"
        )
    op = "subtracted" if sign < 0 else "added"
    # (no formula: the words that would give the box away are the task's, r487)
    return (
        "; ".join(parts) + f": a tolerance ε {op} before rounding? The vertices lie exactly on "
        "the 1/256-px grid, so a bound is a tie only when it lies exactly on a centre, and a "
        "bound a tiny step off a centre is no tie: compare exactly, with no ε"
    )


#: r505 M1, M2: the largest area (px²) and bounding-box side (px) called thin
THIN_AREA, THIN_SIDE = 4, 2


def _thin(args) -> tuple[Fraction, Fraction, Fraction]:
    """(area, width, height) of the triangle and its bounding box, exactly."""
    x0, x1, y0, y1 = _bounds(args[0])
    return abs(_area2(args[0])) / 2, x1 - x0, y1 - y0


def _thin_empty_fits(args, expected, got) -> bool | None:
    """An empty box for a thin triangle (small area, or a bounding box less than 2 px wide or
    tall) whose box is not empty, where the package covers some centre of it (else the box of
    the covered pixels says more)."""
    if got is None or not is_empty(got) or is_empty(expected):
        return False
    area, w, h = _thin(args)
    if area >= THIN_AREA and min(w, h) >= THIN_SIDE:
        return False
    xy, width, height = args
    return bool(rasterize(_tri(xy), width, height).coverage.any()) or None


def _thin_empty_words(args, expected, got) -> str:
    area, w, h = _thin(args)
    xy, width, height = args
    n = int(rasterize(_tri(xy), width, height).coverage.sum())
    facts = [f"its area is {num(float(area))} px², small but not 0"]
    if min(w, h) < THIN_SIDE:
        side, v = ("wide", w) if w <= h else ("tall", h)
        facts.append(f"its bounding box is {num(float(v))} px {side}")
    return (
        f"your box is empty, yet this thin triangle covers {n} centre(s) ({'; '.join(facts)}): "
        "a test on the area or on the bounding box's width or height with a tolerance (abs(E) "
        "< ε, x_max − x_min < 1)? An empty box is right only for a triangle of zero area (E = 0 "
        "exactly) or where no row or column of the image holds a centre of the bounding box; "
        "the vertices lie exactly on the 1/256-px grid, so compare with no tolerance"
    )


SYMPTOMS = (
    Mistake("empty for a thin triangle", _thin_empty_words, fits=_thin_empty_fits),
    Mistake("a tolerance on the bounds", _tolerance_words, fits=_tolerance_fits),
    Mistake(
        "box of the covered pixels",
        "your box is that of the pixels the triangle covers (filled first?): the box comes "
        "before the fill, from the bounding box alone, and holds every centre a triangle with "
        "this bounding box could cover",
        fits=_covered_box_fits,
        symptom=True,
    ),
)

HINTS = (
    (
        ": only a right or bottom edge, or the rightmost or lowest vertex, can lie on that side, "
        "and the top-left rule never covers a centre on them",
        ": can the top-left rule ever cover a centre there? Which edges and vertices of a "
        "triangle can lie on that side?",
    ),
    (
        "there: a horizontal top edge or a vertical left edge lying on that side owns its "
        "centres",
        "there? Which edges can lie on that side, and does the rule own them?",
    ),
    ("there: a horizontal top edge lying on that side owns its centres",
     "there? Which edges can lie on that side, and does the rule own them?"),
    ("there: a vertical left edge lying on that side owns its centres",
     "there? Which edges can lie on that side, and does the rule own them?"),
)  # fmt: skip


def explain_box(args, expected, got) -> str:
    xy, w, h = args
    x0, x1, y0, y1 = _bounds(xy)
    vertices = ", ".join(f"({num(p[0])}, {num(p[1])})" for p in xy)
    return (
        f"triangle ({vertices}) in a {w} × {h} image: x from {num(float(x0))} to "
        f"{num(float(x1))}, y from {num(float(y0))} to {num(float(y1))}; the box is "
        f"{_box_words(expected)}; yours: {_box_words(got)}"
    )


def _box_words(b) -> str:
    if b is None:
        return "nothing"
    if is_empty(b):
        return f"{tuple(b)}, empty"
    r0, r1, c0, c1 = b
    return f"rows {r0} to {r1 - 1}, columns {c0} to {c1 - 1} {tuple(b)}"


def _rule(args, expected, got) -> str:
    return (
        ": the box holds every centre (j + ½, i + ½) inside the triangle's bounding box that "
        "the top-left rule can cover for some triangle with that bounding box, and no other "
        "row or column; then clamped to the image"
    )


def _constant(value) -> str:
    return (
        f"your function returns {tuple(value)} on every case, whatever its arguments: a "
        "placeholder left in, or a `return` reached too early?"
    )


# -- drawing ----------------------------------------------------------------------------------
def draw_box(ax, case, got):
    """The image's border, the triangle, the centres near it, the box and the student's."""
    from matplotlib.patches import Rectangle
    from matplotlib.ticker import MaxNLocator

    _, (xy, w, h), expected = case
    x0, x1 = float(xy[:, 0].min()), float(xy[:, 0].max())
    y0, y1 = float(xy[:, 1].min()), float(xy[:, 1].max())
    lo_x, hi_x = max(math.floor(x0) - 2, -3), min(math.ceil(x1) + 2, w + 3)
    lo_y, hi_y = max(math.floor(y0) - 2, -3), min(math.ceil(y1) + 2, h + 3)
    if hi_x - lo_x > 30:
        lo_x, hi_x = math.floor(x0) - 2, math.floor(x0) + 12
    if hi_y - lo_y > 30:
        lo_y, hi_y = math.floor(y0) - 2, math.floor(y0) + 12
    artists = [ax.add_patch(Rectangle((0, 0), w, h, fill=False, ec="#888888", lw=1.5,
                                      label="the image"))]  # fmt: skip
    artists.append(ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, ec="#ff9f1c",
                                          ls="--", lw=1, label="bounding box")))  # fmt: skip
    ring = np.vstack([xy, xy[:1]])
    artists += ax.plot(ring[:, 0], ring[:, 1], color="black", lw=1)
    gi, gj = np.mgrid[lo_y:hi_y, lo_x:hi_x]
    artists += ax.plot(gj.ravel() + 0.5, gi.ravel() + 0.5, ".", color="#999999", ms=3)
    if got is None:
        r0, r1, c0, c1 = expected
        if not is_empty(expected):
            artists.append(ax.add_patch(Rectangle((c0, r0), c1 - c0, r1 - r0, color="#2b7bba",
                                                  alpha=0.25, label="the box")))  # fmt: skip
        note_beside(ax)
    else:
        for b, colour, label in ((expected, "#2b7bba", "the box"), (got, "#d7301f", "yours")):
            if b is not None and is_empty(b) and colour == "#d7301f":  # r505: say it is empty
                artists += ax.plot([], [], color=colour, lw=2, label=f"yours: {tuple(b)}, empty")
            if b is not None and not is_empty(b):
                r0, r1, c0, c1 = b
                artists.append(ax.add_patch(Rectangle(
                    (c0, r0), c1 - c0, r1 - r0, fill=colour == "#2b7bba", color=colour,
                    alpha=0.25 if colour == "#2b7bba" else 1, lw=2, label=label)))  # fmt: skip
    artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    ax.set_xlim(lo_x, hi_x)
    ax.set_ylim(hi_y, lo_y)
    # r494 FIG1: 100 000 px out, the axis offset "+1e5" overprinted the x label
    ax.ticklabel_format(useOffset=False, style="plain")
    ax.xaxis.set_major_locator(MaxNLocator(4, integer=True))
    ax.set_aspect("equal")
    ax.set_xlabel("x (px); dots: pixel centres", fontsize="small")
    ax.set_ylabel("y (px, down)", fontsize="small")
    return artists


#: r494: kinds named only where they give every answer of the check: the first two vertices'
#: box is the right one wherever the third vertex lies inside it, so on a few cases it fitted
#: bounds taken from the leftmost and rightmost vertices' y by coincidence.
WHOLE_ONLY = frozenset({*PAIRS.values(), "mixed axes", "first row from x", "end row from x",
                        "first column from y", "end column from y"})  # fmt: skip


def _mistakes() -> list[Mistake]:
    return [
        replace(m, only_whole=True) if m.kind in WHOLE_ONLY else m
        for m in variant_mistakes(_variants, WORDS, SYMPTOMS)
    ]


BOX = Exercise(
    "box", box_cases, as_box, same_box, explain_box, _rule,
    _mistakes(),
    answers=(
        # r505 H8: its coverage is not the box ("this very answer" said it was)
        PackageAnswer(rasterize, what="the pixels the triangle covers, not the box"),
        PackageAnswer(pixel_bbox, what="the closed box of centres (⌊max − ½⌋ + 1)"),
    ),
    draw=draw_box, constant=_constant, call=call_box,
    match=lambda got, answer, args: answer is not None and same_box(got, answer, args),
    hints=HINTS,
)  # fmt: skip
