"""Exercise ``breaking_case`` (exercise 10.3, lesson 07; r457 T1): a case for each repair.

r457 T1: 10.2 (:mod:`.hard_case_fill`) is passed by lesson 02 §5b's ``biased_coverage`` with
the origin added, a transcription: no case can ask for reasoning there. 10.3 asks the other
way round. For each repair the naive fill of exercise 10 lacks (:data:`REPAIRS`), the student
returns ``(xy, width, height, origin)``, a triangle and a window on which

- the naive fill with every *other* repair done still differs from :func:`teachraster.rasterize`
  (the repair is needed), and
- the naive fill with that repair alone is right (nothing else is needed; "orient after
  snapping" presupposes "snap", so alone it means both).

Each fill is :func:`repaired_fill`: the catalogue's
:func:`~teachraster.study.hardcases.naive_coverage` with the knobs the repairs set (one place
for each rule). With every repair it is the GPU's fill on the task's range (10.2's reference
solution). Bounds that no catalogue case meets (:data:`BOUNDS`) keep lesson 07 and 10.2's check
from being copied; a case of either is named as such. The check is four cases, a few fills
of at most 64 × 64 pixels each.
"""

from __future__ import annotations

import itertools
from functools import cache

import numpy as np

from ..core.edges import edge_function, is_top_left
from ..core.snapping import snap
from ..core.validate import as_finite, as_int, as_size
from ..study.hardcases import naive_coverage
from .answers import refuse_non_answers, short
from .case_verdicts import CaseVerdicts
from .exercise import Exercise, PackageAnswer
from .hard_case_fill import (
    FILL_LABELS,
    MOST_ACROSS,
    MOST_FAR,
    PACKAGE_FILLS,
    draw_fill,
    expected_fill,
    fixed_cases,
)
from .running import WrongAnswerType

#: The repairs, in the words of the task (naive_fill lacks each).
REPAIRS = ("snap", "orient after snapping", "tie rule", "precision")
#: The largest window side (pixels), as 10.2's.
MOST_WINDOW = 64
#: "precision": every coordinate (vertices, the window's pixels) within this many px of the
#: origin; float32 holds the 1/256-px grid up to 2^16 px (2^24 steps), but A·x + B·y + C needs
#: 2·(10 + 8) + 2 = 38 bits here (10.1's count), float32 24.
PRECISION_FAR = 2**10
#: "tie rule": the snapped triangle at most this many px across (lesson 07's tie cases are wider).
TIE_ACROSS = 4
#: "orient after snapping": the snapped triangle at least this many px across
#: (``snap_flips_winding`` is 0.04 px across).
ORIENT_ACROSS = 2
#: Each repair's own bound, in the task's words.
BOUNDS = {
    "snap": None,
    "orient after snapping": f"a triangle at least {ORIENT_ACROSS} px across (snapped)",
    "tie rule": f"a triangle at most {TIE_ACROSS} px across (snapped)",
    "precision": f"every vertex and pixel within 2^10 = {PRECISION_FAR:,} px of the origin",
}


def repaired_fill(xy, width: int, height: int, origin, repairs) -> np.ndarray:
    """exercise 10's ``naive_fill`` with ``repairs`` done (:data:`REPAIRS`), by the knobs of
    :func:`~teachraster.study.hardcases.naive_coverage`.

    Without "snap" the raw vertices are filled; without "orient after snapping" the triangle
    is oriented by its raw area (with it, by the snapped area, and a snapped area of 0 covers
    nothing); without "tie rule" a centre on an edge is inside (E ≥ 0), with it the top-left
    rule decides; without "precision" E is A·x + B·y + C in float32, with it the differences
    to a vertex in float64.

    >>> xy = [[4.5, 1.0], [4.5, 4.0], [1.5, 2.5]]          # a right edge through centres
    >>> int(repaired_fill(xy, 6, 6, (0, 0), ()).sum()), int(repaired_fill(xy, 6, 6, (0, 0), REPAIRS).sum())
    (8, 5)
    """
    raw = np.asarray(xy, dtype=float)
    snapped = "snap" in repairs
    v = snap(raw) if snapped else raw
    after = snapped and "orient after snapping" in repairs
    area = float(edge_function(*(v if after else raw)))
    if after and area == 0:
        return np.zeros((height, width), dtype=bool)
    if area < 0:
        v = v[[0, 2, 1]]
    precise = "precision" in repairs
    return naive_coverage(
        v, width, height, rule="top_left" if "tie rule" in repairs else "inclusive",
        dtype=np.float64 if precise else np.float32, absolute=not precise, orient="none",
        origin=tuple(origin),
    )  # fmt: skip


def _alone(repair: str) -> tuple[str, ...]:
    """The repair on its own ("orient after snapping" presupposes snapping)."""
    return ("snap", repair) if repair == "orient after snapping" else (repair,)


def _others(repair: str) -> tuple[str, ...]:
    return tuple(r for r in REPAIRS if r != repair)


def as_case(value):
    """``(xy, width, height, origin)`` read strictly: xy (3, 2) finite numbers, width and
    height positive whole numbers, origin two whole numbers (row, col)."""
    refuse_non_answers(value, "a tuple (xy, width, height, origin)")
    if not isinstance(value, (tuple, list)) or len(value) != 4:
        raise WrongAnswerType(
            f"returned {short(value)}: expected a tuple (xy, width, height, origin)"
        )
    xy, width, height, origin = value
    given = getattr(xy, "dtype", None)  # r478 H4: a float16 (or float32 far out) xy
    try:
        xy = as_finite("xy", xy, (3, 2)).astype(float)
        width, height = as_size("width", width), as_size("height", height)
        if not isinstance(origin, (tuple, list, np.ndarray)) or len(origin) != 2:
            raise TypeError(f"origin must be two whole numbers (row, col), got {short(origin)}")
        origin = (as_int("origin[0] (row)", origin[0]), as_int("origin[1] (col)", origin[1]))
    except (TypeError, ValueError) as exc:
        raise WrongAnswerType(f"returned {short(value)}: {exc}") from None
    _note_narrow(xy, given)
    return (xy, width, height, origin)


#: r478 H4: xy (its bytes) -> words, for an xy given in a float type too coarse for the grid
#: there (the case's explanation says so in its first words).
_NARROW: dict = {}


def _note_narrow(xy, given) -> None:
    """Remember words for ``xy`` given as ``given``, a float type whose numbers at the case's
    coordinates lie farther apart than the 1/256-px grid (float16 past 8 px)."""
    if given is None or np.dtype(given).kind != "f" or np.dtype(given).itemsize >= 8:
        return
    far = float(np.abs(xy).max())
    step = float(np.spacing(np.dtype(given).type(far)))
    if step > 1 / 256:
        if len(_NARROW) > 256:
            _NARROW.clear()
        _NARROW[xy.tobytes()] = (
            f" (your xy is {np.dtype(given).name}: at {far:g} px its numbers are {step:g} px "
            "apart, coarser than the 1/256-px grid, so your vertices may not be the ones you "
            "wrote; return float64 numbers)"
        )


def _window_far(case) -> float:
    """The farthest coordinate of the case from the origin: vertices and the window's edges."""
    xy, width, height, (row, col) = case
    return float(max(np.abs(xy).max(), abs(row), abs(col), abs(row + height), abs(col + width)))


def _across(xy) -> float:
    return float(np.ptp(snap(xy), axis=0).max())


#: r478 W2: the grid's symmetries, (words, 2 × 2 matrix on (x, y)); each maps pixel centres
#: onto pixel centres (x → −x takes j + ½ to −(j + 1) + ½), so a catalogue case transformed
#: and moved by whole pixels is the same construction.
SYMMETRIES = (
    ("", ((1, 0), (0, 1))),
    (" with x and y swapped", ((0, 1), (1, 0))),
    (" mirrored left to right", ((-1, 0), (0, 1))),
    (" mirrored top to bottom", ((1, 0), (0, -1))),
    (" turned half a turn", ((-1, 0), (0, -1))),
    (" turned a quarter turn", ((0, -1), (1, 0))),
    (" turned a quarter turn the other way", ((0, 1), (-1, 0))),
    (" with x and y swapped and both mirrored", ((0, -1), (-1, 0))),
)


@cache
def _catalogue() -> tuple[tuple, np.ndarray]:
    """The names ((label, " with x and y swapped")) and the snapped vertices, in each vertex
    order: (n, 6, 3, 2), of 10.2's fixed cases (lesson 07's catalogue and the rest) under
    each of :data:`SYMMETRIES`."""
    orders = [list(o) for o in itertools.permutations(range(3))]
    names, triangles = [], []
    for label, args, _ in fixed_cases():
        c = snap(args[0])
        for words, m in SYMMETRIES:
            names.append((label, words))
            triangles.append((c @ np.array(m, dtype=float).T)[orders])
    return tuple(names), np.array(triangles)


def catalogue_label(xy) -> tuple[str, str] | None:
    """The catalogue case (or 10.2's) whose snapped triangle this is, moved by whole pixels,
    in any vertex order, mirrored or turned (:data:`SYMMETRIES`): its label and the words of
    the transform (``("d3d_split_square, triangle 0", " with x and y swapped")``), or None."""
    names, triangles = _catalogue()
    shift = snap(xy) - triangles  # (n, 6, 3, 2)
    whole = np.all(shift == np.rint(shift), axis=(2, 3))
    found = np.argwhere(whole & np.all(shift == shift[:, :, :1], axis=(2, 3)))
    return names[found[0][0]] if found.size else None


def _diff_pixel(case, repairs) -> tuple[int, int] | None:
    """The first pixel [i, j] where the fill with ``repairs`` differs from the GPU's, or None."""
    got, ref = repaired_fill(*case, repairs), expected_fill(*case)
    bad = np.argwhere(got != ref)
    return None if not bad.size else tuple(int(k) for k in bad[0])


def _smallest_extra(case, repair: str) -> tuple[str, ...] | None:
    """The fewest other repairs that, with ``repair`` alone, make the fill right."""
    rest = [r for r in REPAIRS if r not in _alone(repair)]
    for n in range(1, len(rest) + 1):
        for extra in itertools.combinations(rest, n):
            if _diff_pixel(case, (*_alone(repair), *extra)) is None:
                return extra
    return None


def _is_case_for(case, repair: str) -> bool:
    return (
        _diff_pixel(case, _others(repair)) is not None and _diff_pixel(case, _alone(repair)) is None
    )


def _quoted(repairs) -> str:
    names = [f"'{r}'" for r in repairs]
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def _point(p) -> str:
    return "(" + ", ".join(f"{float(c):.10g}" for c in p) + ")"


def _pixel_words(case, pixel) -> str:
    (i, j), (row, col) = pixel, case[3]
    return f"pixel [{i}, {j}] of your window (centre ({col + j + 0.5:g}, {row + i + 0.5:g}))"


def _range_words(case) -> str | None:
    """What takes the case outside the task's range (10.2's), or None."""
    xy, width, height, _ = case
    if max(width, height) > MOST_WINDOW:
        return (f"your window is {width} × {height} pixels: the task allows at most "
                f"{MOST_WINDOW} a side")  # fmt: skip
    far, across = _window_far(case), _across(xy)
    if far > MOST_FAR:
        return f"your case reaches {far:.10g} px from the origin: the task's range is 2^20 px"
    if across > MOST_ACROSS:
        return f"your triangle is {across:g} px across: the task's range is {MOST_ACROSS:,} px"
    return None


def _bound_words(repair: str, case) -> str | None:
    """The repair's own bound (:data:`BOUNDS`) the case is outside, in words; or None."""
    across = _across(case[0])
    if repair == "precision" and _window_far(case) > PRECISION_FAR:
        measure = f"yours reaches {_window_far(case):.10g} px"
    elif repair == "tie rule" and across > TIE_ACROSS:
        measure = f"yours is {across:g} px across"
    elif repair == "orient after snapping" and across < ORIENT_ACROSS:
        measure = f"yours is {across:g} px across"
    else:
        return None
    return f"for '{repair}' the task asks for {BOUNDS[repair]}; {measure}"


def _moved_window(case, repair: str):
    """The window the case needed: its origin read (row, col), or one around the triangle."""
    xy, width, height, (row, col) = case
    swapped = (xy, width, height, (col, row))
    if _is_case_for(swapped, repair):
        return "origin as (x, y)", swapped
    s = snap(xy)
    lo, hi = np.floor(s.min(axis=0)).astype(int), np.ceil(s.max(axis=0)).astype(int)
    w, h = (int(n) for n in hi - lo + 1)
    around = (xy, w, h, (int(lo[1]), int(lo[0])))
    if max(w, h) <= MOST_WINDOW and _is_case_for(around, repair):
        return "window misses", around
    return None, None


def _unneeded(repair: str, case) -> tuple[str, str]:
    """(kind, words) for a case on which the fill with every other repair is right."""
    kind, moved = _moved_window(case, repair)
    if kind == "origin as (x, y)":
        return kind, (f"origin is (row, col), and your window at {case[3]} holds no pixel the "
                      f"repair changes; at origin = {moved[3]}, your (x, y) read as (row, col), "
                      "it does")  # fmt: skip
    if kind == "window misses":
        pixel = _diff_pixel(moved, _others(repair))
        r, c = moved[3][0] + pixel[0], moved[3][1] + pixel[1]
        return kind, (f"your window, rows {case[3][0]} to {case[3][0] + case[2] - 1} and "
                      f"columns {case[3][1]} to {case[3][1] + case[1] - 1}, misses the pixel "
                      f"where '{repair}' changes the fill: row {r}, column {c} (centre "
                      f"({c + 0.5:g}, {r + 0.5:g})); the window must hold it (its origin, "
                      "width and height)")  # fmt: skip
    head = f"with every other repair done the naive fill is right on your case: '{repair}' "
    note = _why_unchanged(repair, case)
    cases_for = [r for r in _others(repair) if _is_case_for(case, r)]
    if cases_for:
        why = f" ({note[1]})" if note else _off_grid(case[0])
        return "another repair's case", (f"{head}changes nothing there{why}; your case is one "
                                         f"for {_quoted(cases_for)}")  # fmt: skip
    if note:
        return note
    if _diff_pixel(case, ()) is None:
        note = {"precision": _float32_note, "snap": _snap_note}.get(repair, lambda c: None)(case)
        naive = ("the naive fill itself is right on your case (every pixel of the window as "
                 "rasterize gives it): there is nothing to repair")  # fmt: skip
        return note or ("naive right", naive)
    needed = [r for r in REPAIRS if _diff_pixel(case, _others(r)) is not None]
    off = _off_grid(case[0])
    if needed:
        off = f" (the fill needs {_quoted(needed)} there{'; ' + off[2:-1] if off else ''})"
    else:
        off = " (it needs two repairs together, each of which the others can stand in for)" + off
    return "not needed", f"{head}changes nothing there{off}"


def _why_unchanged(repair: str, case) -> tuple[str, str] | None:
    """(kind, words) for what keeps ``repair`` from changing the case, where one thing says
    it (a vertex on the grid, no flip, no tie), or None."""
    xy, s = case[0], snap(case[0])
    if repair == "snap" and np.array_equal(s, xy):
        return "on the grid", "your vertices are on the 1/256-px grid already: snapping moves none"
    raw, snapped = float(edge_function(*xy)), float(edge_function(*s))
    if repair == "orient after snapping" and (raw < 0) == (snapped < 0):
        return "no flip", (f"snapping keeps your triangle's winding (E(v1, v2, v3) is {raw:.3g} "
                           f"px² raw, {snapped:.3g} px² snapped): it is oriented alike before "
                           "and after snapping")  # fmt: skip
    if repair == "orient after snapping" and not expected_fill(*case).any():
        return "covers nothing", (f"snapping flips your triangle (E(v1, v2, v3) is {raw:.3g} px² "
                                  f"raw, {snapped:.3g} px² snapped), but the snapped triangle "
                                  "covers no centre of your window: turned the wrong way round "
                                  "it loses nothing")  # fmt: skip
    if repair == "tie rule":
        return _tie_note(case)
    return None


def _float32_note(case) -> tuple[str, str] | None:
    """r478 H1: words for a "precision" case float32 gets right: how large C's products are,
    float32's steps there, and how near to an edge the nearest centre it decides lies."""
    xy, width, height, (row, col) = case
    s = snap(xy)
    s = s if edge_function(*s) > 0 else s[[0, 2, 1]]
    centres = np.stack(np.meshgrid(col + np.arange(width) + 0.5, row + np.arange(height) + 0.5),
                       axis=-1).reshape(-1, 2)  # fmt: skip
    e = np.stack([edge_function(s[k], s[(k + 1) % 3], centres) for k in range(3)])
    # the edge decides a centre where the other two hold it; its exact E there (on the grid)
    decided = [np.abs(e[k][(e[k] != 0) & np.all(np.delete(e, k, axis=0) >= 0, axis=0)])
               for k in range(3)]  # fmt: skip
    near = np.concatenate(decided)
    if not near.size:
        return None
    products = float(np.abs(s[:, 0] * np.roll(s[:, 1], -1)).max())
    products = max(products, float(np.abs(s[:, 1] * np.roll(s[:, 0], -1)).max()))
    step, d = float(np.spacing(np.float32(products))), float(near.min())
    how = ("more than those steps: float32 cannot put it on the wrong side; a case needs a "
           "centre nearer an edge than float32's rounding of those products" if d > 2 * step
           else "within those steps, but float32's roundings happen to fall on the right side "
           "there; they need not: try the triangle farther out (float32's steps double with "
           "each power of two) or another centre")  # fmt: skip
    return "float32 right", (f"the naive fill itself is right on your case, its float32 "
                             f"A·x + B·y + C too: C's products (a.x·b.y, a.y·b.x) reach "
                             f"{products:,.0f} px² there, where float32's numbers are {step:g} "
                             f"px² apart, and the centre nearest an edge that decides it lies "
                             f"{d:g} px² from it (E, exact on the grid), {how}")  # fmt: skip


def _snap_note(case) -> tuple[str, str] | None:
    """r493 H1: words for a "snap" case the naive fill gets right: where snapping moves each
    vertex (a vertex half-way between grid points goes to the even one, which may be down),
    and that no centre changes sides there."""
    xy, s = case[0], snap(case[0])
    moved = [k for k in range(3) if np.any(s[k] != xy[k])]
    if not moved:
        return None
    said = ", ".join(f"v{k + 1} {_point(xy[k])} to {_point(s[k])}" for k in moved)
    half = [c for c in (xy * 256).ravel().tolist() if c % 1 == 0.5]
    if half:
        c, even = half[0], float(np.rint(half[0]))
        said += (
            f" (half-way between grid points, {c:g} steps of 1/256 px go to {even:g}, the "
            f"even one, as np.rint rounds{'' if even > c else f', not up to {even + 1:g}'})"
        )
    return "snap moves no centre", (
        f"snapping moves {said}, but no centre of your window changes sides of an edge: the "
        "naive fill itself is right on your case (every pixel of the window as rasterize gives "
        "it); a case for 'snap' needs a centre between an edge's raw place and its snapped one"
    )  # fmt: skip


def _tie_note(case) -> tuple[str, str] | None:
    """Words for a tie case the rule does not change: no centre on an edge (within the
    triangle: a centre on an edge's line beyond its vertices is no tie), or only on top and
    left edges (which E ≥ 0 covers too)."""
    xy, width, height, (row, col) = case
    s = snap(xy)
    s = s if edge_function(*s) > 0 else s[[0, 2, 1]]
    centres = np.stack(np.meshgrid(col + np.arange(width) + 0.5, row + np.arange(height) + 0.5),
                       axis=-1).reshape(-1, 2)  # fmt: skip
    e = np.stack([edge_function(s[k], s[(k + 1) % 3], centres) for k in range(3)])
    inside = np.all(e >= 0, axis=0)  # r478 H2: on the triangle's edges, not their lines
    ties = [(k, p) for k in range(3) for p in centres[(e[k] == 0) & inside]]
    if not ties:
        return "no tie", ("no pixel centre of your window lies exactly on an edge of your "
                          "snapped triangle: a tie rule decides such centres only")  # fmt: skip
    if all(is_top_left(s[k], s[(k + 1) % 3]) for k, _ in ties):
        p = ties[0][1]
        return "top-left ties", (f"the centres on your triangle's edges (the first: "
                                 f"({p[0]:g}, {p[1]:g})) lie on top or left edges, which the "
                                 "top-left rule covers as E ≥ 0 does: the two differ on "
                                 "right and bottom edges only")  # fmt: skip
    return None


def _also_words(repair: str, case) -> str:
    """Words for a case on which the repair is needed, but alone does not do."""
    pixel = _diff_pixel(case, _alone(repair))
    extra = _smallest_extra(case, repair) or tuple(r for r in REPAIRS if r not in _alone(repair))
    words = (f"'{repair}' is needed on your case, but with it alone the naive fill still "
             f"differs from rasterize at {_pixel_words(case, pixel)}: your case also needs "
             f"{_quoted(extra)}")  # fmt: skip
    return words + (_off_grid(case[0]) if "snap" in extra else "")


def _off_grid(xy) -> str:
    """Words for the first vertex off the 1/256-px grid, or ""."""
    moved = np.argwhere(np.any(snap(xy) != xy, axis=1)).ravel()
    if not moved.size:
        return ""
    k = int(moved[0])
    return (f" (your vertices are off the 1/256-px grid: v{k + 1} {_point(xy[k])} snaps to "
            f"{_point(snap(xy)[k])})")  # fmt: skip


def _verdict_of(repair: str, case) -> tuple[str, str] | None:
    """(kind, words) of what is wrong with ``case`` as a breaking case for ``repair``; None
    if it is one."""
    xy = case[0]
    if edge_function(*snap(xy)) == 0:
        return "degenerate", (f"your triangle is degenerate: snapped, its vertices "
                              f"{', '.join(_point(p) for p in snap(xy))} lie on one line (its "
                              "area is 0), and it covers nothing; the task asks for a triangle "
                              "with an area")  # fmt: skip
    words = _range_words(case)
    if words:
        return "out of range", words
    found = catalogue_label(xy)
    if found is not None:
        return "catalogue", (f"your triangle is the case '{found[0]}' of 10.2's check (lesson "
                             f"07's catalogue or the check's own){found[1]}, moved by whole "
                             "pixels at most: find one of your own")  # fmt: skip
    words = _bound_words(repair, case)
    if words:
        # r493 W82: another repair's case, within its bounds, handed in for this one (a slip
        # of copy and paste): said first, the bound after
        cases_for = [r for r in _others(repair)
                     if not _bound_words(r, case) and _is_case_for(case, r)]  # fmt: skip
        if cases_for:
            return "another repair's case", (f"your case is one for {_quoted(cases_for)}, not "
                                             f"for '{repair}' ({words})")  # fmt: skip
        return "outside the bounds", words
    if _diff_pixel(case, _others(repair)) is None:
        return _unneeded(repair, case)
    if _diff_pixel(case, _alone(repair)) is not None:
        return "also needs", _also_words(repair, case)
    return None


#: :func:`_verdict_of`, remembered for the check's few answers (one place: case_verdicts).
verdict = CaseVerdicts(_verdict_of, key=lambda case: (case[0].tobytes(), *case[1:]))


#: The kinds of a wrong case, most specific first.
KINDS = ("degenerate", "out of range", "catalogue", "outside the bounds", "origin as (x, y)",
         "window misses", "another repair's case", "on the grid", "no flip", "covers nothing",
         "no tie", "top-left ties", "float32 right", "snap moves no centre", "naive right",
         "not needed",
         "also needs")  # fmt: skip


def cases() -> list[tuple[str, tuple, str]]:
    """One case per repair; the expected answer is the repair's name (any breaking case of
    it is right, so none is quoted)."""
    return [(f"the repair '{r}'", (r,), r) for r in REPAIRS]


def _explain(args, expected, got) -> str:
    xy, width, height, origin = got
    return (f"breaking_case('{args[0]}'): the triangle {', '.join(_point(p) for p in xy)} in "
            f"the {width} × {height} window at origin (row, col) = {origin}"
            f"{_NARROW.get(np.asarray(xy, float).tobytes(), '')}")  # fmt: skip


def _rule(args, expected, got) -> str:
    return ""


def _constant(value) -> str:
    return (f"your function returns the same case, the triangle "
            f"{', '.join(_point(p) for p in value[0])} in a {value[1]} × {value[2]} window, "
            "for every repair, whatever its argument: a placeholder left in, or names that are "
            f"not the task's four ({_quoted(REPAIRS)}, spelled exactly so)? A case "
            "that needs one repair alone cannot need another alone: each repair has a case of "
            "its own")  # fmt: skip


def _compose(head: str, words: str) -> str:
    return f"{head}: {words}" if words else head


def draw_case(ax, case, got):
    """The student's window: where the fill with every other repair (for a case that also
    needs another, the fill with the repair alone) differs from the GPU's (missing, extra),
    and the snapped triangle; nothing before an answer."""
    if isinstance(got, str):  # a passing report's example: its answer is the repair's name
        ax.set_axis_off()
        return [ax.text(0.5, 0.5, "a case for each repair:\nsee the printed report", ha="center",
                        va="center", transform=ax.transAxes)]  # fmt: skip
    if got is None or _range_words(got) or edge_function(*snap(got[0])) == 0:
        ax.set_axis_off()
        return []
    repair = case[1][0]
    found = verdict(repair, got)  # r478 FIG1: the fill the words speak of, named on the axis
    if found is not None and found[0] == "also needs":
        repairs, label = _alone(repair), f"the naive fill with '{repair}' alone"
    else:
        repairs, label = _others(repair), f"the naive fill with every repair but '{repair}'"
    artists = draw_fill(ax, (label, got, expected_fill(*got)), repaired_fill(*got, repairs))
    ax.set_xlabel(f"column (x, px); drawn: {label}, against rasterize")
    return artists


#: r478 W1: the package's fills, run while ``breaking_case`` runs: a search for the case (the
#: checker's own code, its judge ``repaired_fill`` among it, is watched as every checker's);
#: r493 W1: every fill of the package's that gives the GPU's answer (10.2's list), not four.
SEARCH_WORDS = (
    "a fill of the package's, which the check judges your cases by: a search that runs it "
    "while breaking_case runs finds the case for you, and is not counted (try candidates with "
    "it in a cell of your own; breaking_case returns the numbers of the cases you reasoned out)"
)
SEARCH_ANSWERS = tuple(PackageAnswer(f, words=SEARCH_WORDS, label=FILL_LABELS.get(f))
                       for f in PACKAGE_FILLS)  # fmt: skip

BREAKING_CASE = Exercise(
    "breaking_case", cases, as_case, verdict.same, _explain, _rule,
    verdict.mistakes(KINDS), draw=draw_case, compose=_compose, constant=_constant,
    reference=("teachraster.exercises.hard_case_fill",), answers=SEARCH_ANSWERS,
)  # fmt: skip
