"""Exercise ``robust_fill`` (lesson 07): make a naive rasteriser pass the hard-case catalogue.

The notebook gives a naive fill (raw floats, E ≥ 0, the edge functions in the absolute form
A x + B y + C in float32: the catalogue's :func:`~teachraster.study.hardcases.naive_coverage`)
and runs it against the catalogue; the student repairs it until every case passes: snap the
vertices to the 1/256-px grid, orient the *snapped* triangle, give a snapped zero-area
triangle nothing, decide ties by the top-left rule, and compute the edge functions from
differences in float64, so that a triangle 10⁶ px from the origin is filled as at the origin.

The cases are the catalogue's screen-space triangles with their raw (unsnapped) vertices,
``far_from_origin`` at 10⁴, 10⁵ and 10⁶ px (one with a centre 2⁻¹⁵ px² inside an edge, which
A x + B y + C in float64 rounds to a tie there), a triangle 900 px across (whose E in
1/256-px integers overflows int32), two 800-px triangles whose E float32 cannot hold
(:mod:`.hard_case_precision`), a zero-area triangle in a window that is not square, and
seeded random off-grid triangles; the task promises
exactness within :data:`MOST_FAR` px of the origin and :data:`MOST_ACROSS` px across. Expected
answers are the package's fill (:func:`teachraster.rasterize`). Each failure is named by the
naive variant that reproduces it (:func:`~teachraster.study.hardcases.naive_coverage` with
one of its options), then explained at its first wrong pixel with the top-left rule.
"""

from __future__ import annotations

import copy
from dataclasses import replace
from functools import cache
from types import SimpleNamespace

import numpy as np

from ..core.fill import METHODS, rasterize
from ..core.snapping import snap
from ..core.triangle import Triangle
from ..pipeline.rasterization.batched_fill import rasterize_batch
from ..study.bench.ground_truth import exact_coverage
from ..study.exact_spans import span_fill_int_dda
from ..study.hardcases import CASES, naive_coverage
from ..study.hardcases.precision_cases import fill_window
from ..study.operation_counts import rule_coverage
from ..study.precision import coverage as precision_coverage
from .answers import refuse_non_answers, short
from .cases import DRAWN_WORD, SEED, drawn_rng
from .coverage import explain_pixel
from .coverage_checks import TIE_RULE_ANSWERS
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .hard_case_precision import (
    FLOAT32_CASES,
    SLIP_WORDS,
    all_covered,
    centre_grid,
    float32_rounds,
    float32_words,
    refused_or_raw_words,
    slip_variants,
    small_area_refused,
    step32_fill,
)
from .running import WrongAnswerType

#: Kinds of catalogue case the exercise runs (screen-space triangles).
KINDS = ("triangle", "triangles", "mesh")


def fill_cases() -> list[tuple[str, tuple, np.ndarray]]:
    """The cases (built once, then copied; see :func:`_fill_cases`), then a few drawn for
    this check (every kind of :func:`_random_cases`), so a harvested table fails (r49)."""
    drawn = _random_cases(drawn_rng(), DRAWN_WORD)[::3]
    return copy.deepcopy(_fill_cases()) + [(lb, a, expected_fill(*a)) for lb, a in drawn]


def fixed_cases() -> list[tuple[str, tuple, np.ndarray]]:
    """The cases without those drawn for each check (a copy; 10.3 names a case of them)."""
    return copy.deepcopy(_fill_cases())


@cache
def _fill_cases() -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (xy, width, height, origin), coverage) with raw vertices; origin = (row, col)."""
    out = []
    for name, case in CASES.items():
        if case.kind not in KINDS or "triangles" not in case.inputs:
            continue
        w, h = (int(v) for v in case.inputs["size"])
        tris = np.asarray(case.inputs["triangles"], dtype=float)
        for k, xy in enumerate(tris):
            label = name + (f", triangle {k}" if len(tris) > 1 else "")
            out.append((label, (xy.copy(), w, h, (0, 0))))
    local = np.asarray(CASES["far_from_origin"].inputs["local"], dtype=float)
    for offset in CASES["far_from_origin"].inputs["offsets"]:
        o = int(offset)
        if o:
            out.append((f"far_from_origin at {o} px", (local + o, 16, 16, (o, o))))
    # a window whose row and column differ: origin is (row, col), not (x, y)
    o = int(max(CASES["far_from_origin"].inputs["offsets"]))
    out.append((f"far_from_origin at row {o}, column {o // 2 + 7}",
                (local + [o // 2 + 7, o], 16, 16, (o, o // 2 + 7))))  # fmt: skip
    # vertices on the 1/256 grid but off float32's (1/16 px apart at 10⁶): a right edge
    # 3/256 px right of a column of centres, which float32 storage moves onto them
    off = np.array([[2 + 5 / 256, 1 + 37 / 256], [12.5 + 3 / 256, 3 + 11 / 256],
                    [12.5 + 3 / 256, 14 + 21 / 256]])  # fmt: skip
    out.append(
        (f"far_from_origin at {o} px, vertices on the 1/256 grid", (off + o, 16, 16, (o, o)))
    )
    # a vertex exactly half-way between two grid points: half to even (np.rint, a GPU's
    # fixed-point conversion) puts the left edge through centres, half up beside them
    half = np.array([[2.5 + 1 / 512, 1.0], [2.5 + 1 / 512, 9.0], [9.0, 5.0]])
    out.append(("half step: vertices half-way between 1/256 grid points", (half, 12, 12, (0, 0))))
    # r373 W24: a centre 2 steps of E (2 · 2⁻¹⁶ px²) inside a right edge at 10⁶ px, where
    # A x + B y + C in float64 rounds to 2⁻¹² px²: the absolute form reads it as a tie
    out.append((f"far_from_origin at {o} px, a centre 2⁻¹⁵ px² inside an edge",
                (NEAR_TIE + o, 16, 16, (o, o))))  # fmt: skip
    # r373 W41: a triangle about 900 px across, whose E in 1/256-px integers reaches 5e10,
    # past int32; the window straddles its right edge
    out.append((f"a triangle {WIDE_ACROSS} px across (window at row 400, column 685)",
                (WIDE.copy(), 16, 16, (400, 685))))  # fmt: skip
    # r386 NW28, NW29: E in float32 (24 bits) on a triangle about 1,000 px across, whose E
    # on the 1/256 grid needs about 36: stepped along rows, or after shifting to the window
    for label, (xy, origin) in FLOAT32_CASES.items():
        out.append((label, (xy.copy(), 64, 64, origin)))
    # r386 NW11: a zero-area triangle in a window that is not square (shape (height, width))
    out.append(("collinear, in a window 8 wide and 4 high",
                (np.array([[1.0, 0.5], [3.0, 1.5], [7.0, 3.5]]), 8, 4, (0, 0))))  # fmt: skip
    out += _random_cases(np.random.default_rng(SEED + 50), "random")
    # r441 W1, W2: listed last, so that every earlier first failure stays where it was
    out.append(("half step, odd: a vertex at 641.5/256 px, half-way between 641 and 642",
                (HALF_ODD.copy(), 12, 12, (0, 0))))  # fmt: skip
    out.append(("a centre one step of E (2⁻¹⁶ px²) outside a left edge",
                (ONE_STEP.copy(), 12, 12, (0, 0))))  # fmt: skip
    # r457 W1: a sliver far out, whose area float32 rounds to 0 (listed last, as r441's)
    sliver = np.asarray(CASES["snap_flips_winding"].inputs["triangles"], dtype=float)[0]
    out.append((f"snap_flips_winding at {o} px", (sliver + o, 6, 6, (o, o))))
    return [(label, args, expected_fill(*args)) for label, args in out]


#: r373 W24: a snapped triangle (local coordinates; the case adds 10⁶ px) with a centre, pixel
#: (6, 4), 2⁻¹⁵ px² inside its edge v2→v3: float64 rounds A x + B y + C there to 2⁻¹² px².
NEAR_TIE = np.array([[5.34765625, 10.48046875], [5.55078125, 7.83984375], [2.7109375, 4.21875]])
#: r441 W1: a vertex at an odd + ½ step of the grid (641.5/256 px in x and in y): half to even
#: (np.rint) moves it to 642, half down (np.ceil(x · 256 − ½)) to 641, and centre (3.5, 6.5)
#: changes sides of its edges (at an even + ½ step, the "half step" case, half down and half
#: to even agree; there half up fails).
HALF_ODD = np.array([[3.703125, 7.31640625], [9.02734375, 4.73828125], [641.5 / 256, 641.5 / 256]])
#: r441 W2: on the 1/256 grid, centre (4.5, 8.5) lies one step of E, 2⁻¹⁶ px², outside the left
#: edge v3→v1, inside the two others: a tolerance on the ties (|E| ≤ ε as a tie) covers it.
ONE_STEP = np.array([[4.25390625, 8.01171875], [8.82421875, 5.3125], [4.98828125, 9.46875]])
#: r373 W41: a triangle hundreds of pixels across (on the 1/256 grid, near the origin).
WIDE = np.array([[0.25, 0.5], [900.5, 3.75], [450.125, 880.0]])
WIDE_ACROSS = int(np.ptp(WIDE, axis=0).max())
#: The inputs the task promises (the notebook states them; tests hold the cases to them):
#: every coordinate within this many px of the origin, a triangle at most this many px across.
MOST_FAR, MOST_ACROSS = 2**20, 1024


def _random_cases(rng, word) -> list[tuple[str, tuple]]:
    """Off-grid triangles: anywhere, within 1/512 px of a pixel centre (snapping decides
    ties), tiny ones (snapping flips or flattens them)."""
    out = []
    for k in range(10):
        xy = rng.uniform(0.5, 11.5, (3, 2))
        out.append((f"{word} {k + 1}: anywhere, off the 1/256 grid", (xy, 12, 12, (0, 0))))
    for k in range(6):
        xy = rng.integers(1, 11, (3, 2)) + 0.5 + rng.uniform(-1, 1, (3, 2)) / 512
        out.append((f"{word} {k + 11}: within 1/512 px of centres", (xy, 12, 12, (0, 0))))
    for k in range(4):
        xy = 5.5 + rng.uniform(-1, 1, (3, 2)) / 300
        out.append((f"{word} {k + 17}: a few 1/256 px across", (xy, 12, 12, (0, 0))))
    return out


def expected_fill(xy, width: int, height: int, origin) -> np.ndarray:
    """The package's coverage of the window at ``origin`` (row, col)."""
    shift = np.array([origin[1], origin[0]], dtype=float)  # integer shift: snapping commutes
    return rasterize(Triangle(np.asarray(xy, float) - shift), width, height).coverage


def _variants(xy, width, height, origin) -> dict[str, np.ndarray]:
    """Coverage under the naive rasteriser with one repair missing (each its own mistake)."""
    s = snap(np.asarray(xy, float))
    kw = dict(origin=tuple(origin))
    raw_area = _area(xy)
    flipped = s if raw_area >= 0 else s[[0, 2, 1]]  # oriented by the unsnapped area
    o = np.asarray(origin)
    return {
        "nothing covered": np.zeros((height, width), dtype=bool),
        "origin swapped": expected_fill(xy, width, height, (o[1], o[0])),
        "origin ignored": expected_fill(xy, width, height, (0, 0)),
        "origin added twice": expected_fill(xy, width, height, 2 * o),  # r386 NW05
        "pixel corners": expected_fill(np.asarray(xy, float) + 0.5, width, height, origin),
        "transposed": expected_fill(xy, height, width, origin).T if width == height else None,
        # built [col, row] from origin read (col, row) (r6: told precision far from the origin)
        "transposed, origin swapped": expected_fill(xy, height, width, o[::-1]).T,
        "vertex x and y swapped": expected_fill(
            np.asarray(xy, float)[:, ::-1], width, height, origin
        ),  # fmt: skip
        "no snapping": naive_coverage(xy, width, height, rule="top_left", **kw),
        "half-up snapping": naive_coverage(
            np.floor(np.asarray(xy, float) * 256 + 0.5) / 256, width, height, rule="top_left", **kw
        ),  # fmt: skip
        "float32 vertices": tie_fill(s.astype(np.float32).astype(float), width, height, origin),
        "floor snapping": naive_coverage(
            np.floor(np.asarray(xy, float) * 256) / 256, width, height, rule="top_left", **kw
        ),  # fmt: skip
        "E >= 0": naive_coverage(s, width, height, rule="inclusive", **kw),
        "E > 0": naive_coverage(s, width, height, rule="strict", **kw),
        "no top edges": tie_fill(s, width, height, origin, top=False),
        "no left edges": tie_fill(s, width, height, origin, left=False),
        **_reversed(s, width, height, kw, expected_fill(xy, width, height, origin)),
        "one winding": naive_coverage(s, width, height, rule="top_left", orient="none", **kw),
        "oriented before snapping": naive_coverage(
            flipped, width, height, rule="top_left", orient="none", **kw
        ),  # fmt: skip
        "absolute form": naive_coverage(
            s, width, height, rule="top_left", absolute=True, dtype=np.float32, **kw
        ),  # fmt: skip
        "float32": naive_coverage(s, width, height, rule="top_left", dtype=np.float32, **kw),
        **_more_variants(xy, width, height, origin),
    }


def _more_variants(xy, width, height, origin) -> dict[str, np.ndarray]:
    """r373's typical mistakes, each one repair done another way: the window one row or
    column off, one axis snapped, ceil snapping, the tie rule read off the vertices as given,
    both horizontal edges as top, A x + B y + C in float64, 1/256-px integers in int32."""
    raw, s = np.asarray(xy, float), snap(np.asarray(xy, float))
    kw = dict(rule="top_left", origin=tuple(origin))
    o = np.asarray(origin)
    out = {f"{axis} off by one{sign}": expected_fill(xy, width, height, o + step)
           for axis, steps in (("rows", ((1, 0), (-1, 0))), ("columns", ((0, 1), (0, -1))))
           for sign, step in zip(("", ", the other way"), steps)}  # fmt: skip
    for k, axis in enumerate(("x", "y")):
        one = raw.copy()
        one[:, k] = np.rint(raw[:, k] * 256) / 256
        out[f"only {axis} snapped"] = naive_coverage(one, width, height, **kw)
    out["ceil snapping"] = naive_coverage(np.ceil(raw * 256) / 256, width, height, **kw)
    # r441 W1: half-way values rounded down (np.ceil(x · 256 − ½))
    out["half-down snapping"] = naive_coverage(np.ceil(raw * 256 - 0.5) / 256, width, height,
                                               **kw)  # fmt: skip
    for given in ("index", "edge"):
        out[f"tie rule before orienting ({given})"] = edge_fill(s, width, height, origin,
                                                                given=given)  # fmt: skip
    out["any horizontal edge is top"] = edge_fill(s, width, height, origin, owns=_any_flat)
    out["absolute form in float64"] = naive_coverage(s, width, height, absolute=True, **kw)
    out["int32 overflow"] = int32_fill(xy, width, height, origin)
    out["float32 E"] = step32_fill(xy, width, height, origin)  # r386 NW28
    out["area in float32"] = area32_fill(xy, width, height, origin)  # r457 W1
    out["int32 area"] = int32_fill(xy, width, height, origin, area_only=True)  # r457 M2
    out["int32 E"] = int32_fill(xy, width, height, origin, edges_only=True)  # r493 H2
    out["both reversed, as not top-left"] = edge_fill(
        s, width, height, origin, owns=_not_top_left
    )  # r457 H1
    out["snapped relative to a vertex"] = vertex_frame_fill(xy, width, height, origin)  # r457 H3
    out["everything covered"] = np.ones((height, width), dtype=bool)  # r457 H2
    out.update(slip_variants(xy, width, height, origin, expected_fill))
    return out


def _top_left(a, b) -> bool:
    """The top-left rule on an edge a→b of a triangle oriented so that E(v1, v2, v3) > 0."""
    return bool(b[1] < a[1] or (b[1] == a[1] and b[0] > a[0]))


def _not_top_left(a, b) -> bool:
    """r457 H1: ties on every edge that is not top or left (lesson 02's bias of −1 put on the
    top and left edges instead), a = b included: a point triangle then covers everything."""
    return not _top_left(a, b)


def area32_fill(xy, width: int, height: int, origin) -> np.ndarray:
    """r457 W1: the right fill, but oriented (and refused at area 0) by the snapped triangle's
    area computed in float32, from float32 vertices: far out it rounds to 0 or flips."""
    s = snap(np.asarray(xy, float))
    (ax, ay), (bx, by), (cx, cy) = s.astype(np.float32)
    area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    if area == 0:
        return np.zeros((height, width), dtype=bool)
    v = s[[0, 2, 1]] if area < 0 else s
    return naive_coverage(v, width, height, rule="top_left", orient="none", origin=tuple(origin))


def vertex_frame_fill(xy, width: int, height: int, origin) -> np.ndarray:
    """r457 H3: coordinates taken relative to the raw v1, then snapped (a grid shifted by v1's
    fraction), the rest right, in that frame."""
    raw = np.asarray(xy, float)
    v = np.rint((raw - raw[0]) * 256) / 256
    if _area(v) == 0:
        return np.zeros((height, width), dtype=bool)
    v = v[[0, 2, 1]] if _area(v) < 0 else v
    y, x = centre_grid(origin, width, height)
    y, x = y - raw[0, 1], x - raw[0, 0]
    inside = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        inside &= (e >= 0) if _top_left(a, b) else (e > 0)
    return inside


def _any_flat(a, b) -> bool:
    """r373 W35: a left edge, or any horizontal one (top and bottom alike)."""
    return bool(b[1] <= a[1])


def edge_fill(s, width: int, height: int, origin, *, owns=_top_left, given=None, eps=None):
    """Coverage of the snapped triangle ``s`` from float64 differences, a centre on edge a→b
    inside when ``owns(a, b)``; ``given`` ("index", "edge"): the tie rule read off the vertices
    as given, not as oriented (edge k of the given order, or the same edge run the given way:
    r373 W40); ``eps`` = (ε, form): E compared with a tolerance, "tie" (E > −ε on an owned
    edge, E > ε on the others), "loose" (E ≥ −ε everywhere), "strict" (E > ε everywhere) or, r441 W2,
    "ties only" (|E| ≤ ε read as a tie: E ≥ −ε on an owned edge, E > 0 on the others, as
    ``np.isclose(e, 0, atol=ε)`` beside E > 0 does)."""
    w = np.asarray(s, float)
    v = w[[0, 2, 1]] if _area(w) < 0 else w
    y, x = centre_grid(origin, width, height)
    inside = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        if given == "index":
            tie = owns(w[k], w[(k + 1) % 3])
        elif given == "edge" and v is not w:
            tie = owns(b, a)
        else:
            tie = owns(a, b)
        if eps is None or (eps[1] == "ties only" and not tie):
            inside &= (e >= 0) if tie else (e > 0)
        elif eps[1] == "ties only":
            inside &= e >= -eps[0]
        else:
            eps_value, form = eps
            low = -eps_value if form == "loose" or (form == "tie" and tie) else eps_value
            inside &= (e >= low) if form == "loose" else (e > low)
    return inside


def int32_fill(
    xy, width: int, height: int, origin, area_only: bool = False, edges_only: bool = False
) -> np.ndarray:
    """r373 W41: the fill in 1/256-px integers (centres at 256 j + 128, the top-left rule as a
    bias of −1), every product in int32, which wraps past 2³¹; ``area_only`` (r457 M2, lesson
    02's code with int32 vertices): the area in int32, each E in int64 (its centres are);
    ``edges_only`` (r493 H2): each E in int32, the area in int64."""
    v = np.rint(np.asarray(xy, float) * 256).astype(np.int32)
    centre = np.int64 if area_only else np.int32
    ys = (origin[0] + np.arange(height, dtype=centre))[:, None] * 256 + 128
    xs = (origin[1] + np.arange(width, dtype=centre))[None, :] * 256 + 128
    out = np.ones((height, width), dtype=bool)
    with np.errstate(over="ignore"):
        w = v.astype(np.int64) if edges_only else v
        (ax, ay), (bx, by), (cx, cy) = w
        area = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if area == 0 and not area_only:  # (lesson 02's code refuses nothing)
            return ~out
        if area < 0:
            v = v[[0, 2, 1]]
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            dx, dy = b[0] - a[0], b[1] - a[1]
            if area_only:
                dx, dy = np.int64(dx), np.int64(dy)
            e = dx * (ys - a[1]) - dy * (xs - a[0])
            out &= e + (0 if (dy < 0 or (dy == 0 and dx > 0)) else -1) >= 0
    return out


def _reversed(s, width, height, kw, expected) -> dict[str, np.ndarray]:
    """The tie rule with a direction reversed, on every case (so that a reversed rule, which
    gives every answer, is named first; a forgotten rule, which covers fewer pixels, gives
    every answer of its own student and comes first in :data:`MISTAKES`)."""
    return {kind: naive_coverage(s, width, height, rule=rule, **kw)
            for kind, rule in REVERSED.items()}  # fmt: skip


#: The reversed tie rules, as :func:`naive_coverage` names them.
REVERSED = {"top edge reversed": "bottom_left", "left edge reversed": "top_right",
            "both reversed": "bottom_right"}  # fmt: skip

#: Grids coarser than the GPU's 1/256 px that a student may snap to (sub-pixel bits 0 to 7).
COARSE_BITS = range(8)


def _coarse_grids(args, got, bits_range=COARSE_BITS) -> list[int]:
    """The grids (1/2^bits px, bits in ``bits_range``) whose snapping gives ``got`` here."""
    return [bits for bits in bits_range if np.array_equal(_on_grid(bits)(*args), got)]


def _grid(bits: int) -> str:
    return "1 px" if bits == 0 else f"1/{2**bits} px"


def _coarse_words(args, expected, got) -> str:
    bits = _coarse_grids(args, got)
    grids = _grid(bits[0]) if len(bits) == 1 else f"{_grid(bits[0])} to {_grid(bits[-1])}"
    return (f"you snap to a coarser grid than 1/256 px (a grid of {grids} gives this answer): "
            "the course's GPU keeps 8 sub-pixel bits, as Direct3D requires (GL and Vulkan ask "
            "for at least 4), so snap to 1/256 px, np.rint(xy * 256) / 256; a coarser grid moves a vertex far enough to carry an edge across pixel centres")  # fmt: skip


def _rounded_fill(vertices, width, height, origin) -> np.ndarray:
    """The right fill (float64 differences, the top-left rule) of vertices rounded some way."""
    return naive_coverage(vertices, width, height, rule="top_left", origin=tuple(origin))


def _on_grid(bits: int):
    """``gives``: the fill of the vertices snapped to a grid of 1/2^bits px."""

    def gives(xy, width, height, origin):
        raw = np.asarray(xy, float)
        return _rounded_fill(np.rint(raw * 2**bits) / 2**bits, width, height, origin)

    return gives


def _fine_words(args, expected, got) -> str:
    bits = _coarse_grids(args, got, FINE_BITS)
    grids = _grid(bits[0]) if len(bits) == 1 else f"{_grid(bits[0])} to {_grid(bits[-1])}"
    return (f"you snap to a finer grid than 1/256 px (a grid of {grids} gives this answer): "
            "the course's GPU keeps exactly 8 sub-pixel bits, so its vertices sit on the "
            "1/256-px grid and no finer; a vertex on your grid can lie up to 1/512 px from "
            "the GPU's, enough to carry an edge across a centre near it")  # fmt: skip


def _decimal_words(d: int) -> str:
    return (f"you round to {10.0**-d:g} px (np.round(xy, {d})), not to the 1/256-px grid: "
            f"{10.0**-d:g} is no power of 2, so your vertices land between the GPU's grid "
            "points, and a centre near an edge changes sides")  # fmt: skip


def _epsilon_words(eps: float, form: str = "tie") -> str:
    if form == "ties only":  # r441 W2: np.isclose(e, 0, atol=ε) as the tie test
        return (f"you read a centre within ε = {eps:g} px² of an edge as on it (a tolerance on "
                f"the tie test, np.isclose(e, 0, atol={eps:g})?; an ε of about that size gives "
                f"your answer): on the snapped grid E is exact, a whole number of steps of "
                f"2⁻¹⁶ = {2.0**-16:.2g} px², so a centre even one step outside a top or left "
                "edge (E = −2⁻¹⁶ px²) is outside it, not a tie; compare E == 0")  # fmt: skip
    return (f"you compare E with a tolerance, ε = {eps:g} px² (an ε of about that size gives "
            f"your answer): on the snapped grid E is exact, "
            f"a whole number of steps of 2⁻¹⁶ = {2.0**-16:.2g} px², so no tolerance is needed, "
            f"and yours moves every centre within {eps:g} px² of an edge to the other side of "
            "it; compare E with 0 and let the top-left rule decide E = 0")  # fmt: skip


def _rounded(d: int):
    return lambda xy, w, h, origin: _rounded_fill(np.round(np.asarray(xy, float), d), w, h, origin)


def _tolerant(eps: float, form: str):
    return lambda xy, w, h, origin: edge_fill(snap(np.asarray(xy, float)), w, h, origin,
                                              eps=(eps, form))  # fmt: skip


#: Grids finer than 1/256 px (sub-pixel bits 9 to 16), decimal roundings (1 to 6 places),
#: tolerances of E (px²; below E's step on the snapped grid, 2⁻¹⁶ px², one changes nothing)
#: that a student may use (r373 W31, W21, W33: told "raw vertices", "E > 0", "float32").
FINE_BITS, DECIMALS = range(9, 17), range(1, 7)
EPSILONS = tuple(10.0**-k for k in range(1, 6))
EPS_FORMS = ("tie", "loose", "strict", "ties only")


def _roundings() -> list[Mistake]:
    """Snapping to another grid, rounding to decimals, a tolerance in the edge test: one
    mistake per grid (per tolerance), each named only where it gives every answer of the
    check, passing ones included (a grid may match one case by coincidence)."""
    out = [Mistake("coarse snapping", _coarse_words, gives=_on_grid(b), only_whole=True)
           for b in COARSE_BITS]  # fmt: skip
    out += [Mistake("fine snapping", _fine_words, gives=_on_grid(b), only_whole=True)
            for b in FINE_BITS]  # fmt: skip
    out += [Mistake("decimal rounding", _decimal_words(d), gives=_rounded(d), only_whole=True)
            for d in DECIMALS]  # fmt: skip
    out += [Mistake("epsilon", _epsilon_words(eps, form), gives=_tolerant(eps, form),
                    only_whole=True)
            for eps in EPSILONS for form in EPS_FORMS]  # fmt: skip
    return out


def _thin(args, expected, got) -> bool:
    """r373 W19: nothing covered where the snapped triangle has a small area, not zero."""
    area = abs(_area(snap(np.asarray(args[0], float))))
    return got.dtype == bool and not got.any() and bool(expected.any()) and 0 < area < 8


def _thin_words(args, expected, got) -> str:
    xy, width, height, origin = args
    s = snap(np.asarray(xy, float))
    raw = naive_coverage(s if _area(xy) >= 0 else s[[0, 2, 1]], width, height,
                         rule="top_left", orient="none", origin=tuple(origin))  # fmt: skip
    if np.array_equal(raw, got):  # r386 NW08: oriented by the raw area gives it too
        return refused_or_raw_words(args, expected, got)
    area = abs(_area(snap(np.asarray(args[0], float)))) / 2
    return (f"you gave nothing to a thin triangle: snapped, its area is {area:.3g} px², small "
            "but not zero, and it covers the centres strictly inside it; only a snapped area "
            "of exactly 0 covers nothing")  # fmt: skip


THIN = Mistake("thin triangles refused", _thin_words, fits=_thin, only_whole=True)


def _far(args) -> float:
    """How far (px) the case's triangle lies from the origin."""
    return float(np.abs(np.asarray(args[0], float)).max())


def _far_words(args, expected, got) -> str:
    far = _far(args)
    step = float(np.spacing(np.float32(far)))
    return (f"this triangle lies {far:.0f} px from the origin, where float32's numbers are "
            f"{step:g} px apart, coarser than the 1/256-px grid: a precision failure; keep "
            "the vertices in float64 (or integers in 1/256 px) and compute each edge function "
            "in float64 (from differences to a vertex is safest: A x + B y + C cancels two "
            "products of size x·y)")  # fmt: skip


#: What is wrong, by the catalogue's family, where no single mistake gives the answer (two or
#: more at once, as in the naive fill): far from the origin (precision), off the grid
#: (snapping), so that one failure of each family shows first.
FAR = Mistake("far from origin", _far_words, fits=lambda a, e, g: _precision_decides(a, g),
              symptom=True, with_others=True)  # fmt: skip

#: float32's spacing must exceed this (px) before precision can move a snapped vertex.
GRID = 1 / 256


def _precision_decides(args, got) -> bool:
    """Is the case so far out that float32 cannot hold the 1/256-px grid (beyond 2^16 px),
    and does ``got`` equal a float32 evaluation that float64 would not give? (r6: said at
    10013 px, where float32 is 1/1024 px apart, and to a transposed float64 function.)"""
    if float(np.spacing(np.float32(_far(args)))) <= GRID:
        return False
    xy, width, height, origin = args
    raw = np.asarray(xy, float)
    for vertices in (raw, snap(raw)):
        for rule in ("inclusive", "strict", "top_left"):
            for absolute in (True, False):
                kw = dict(rule=rule, absolute=absolute, origin=tuple(origin))
                low = naive_coverage(vertices, width, height, dtype=np.float32, **kw)
                if np.array_equal(low, got) and not np.array_equal(
                    low, naive_coverage(vertices, width, height, **kw)
                ):
                    return True
    return False


def _snapping_changes(args, expected) -> bool:
    """Does snapping change this case's answer (off-grid vertices, raw ones fill otherwise)?"""
    xy, width, height, origin = args
    raw = np.asarray(xy, float)
    if np.array_equal(snap(raw), raw):
        return False
    unsnapped = naive_coverage(raw, width, height, rule="top_left", origin=tuple(origin))
    return not np.array_equal(unsnapped, expected)


def _snapping_decides(args, expected, got) -> bool:
    """Does snapping decide this case, and is ``got`` what a fill of the raw vertices gives
    (some tie rule, float64 or float32, either form of E)? r373: said of any wrong answer on
    an off-grid case, it told functions that snap to "snap first" (it is also named only
    where it fits every failing case that snapping decides, and beside named failures)."""
    xy, width, height, origin = args
    raw = np.asarray(xy, float)
    if not _snapping_changes(args, expected):
        return False
    return any(np.array_equal(got, naive_coverage(raw, width, height, rule=rule, dtype=dtype,
                                                  absolute=absolute, origin=tuple(origin)))
               for rule in _RULES for dtype in (np.float64, np.float32)
               for absolute in (False, True))  # fmt: skip


def _on_edge(args) -> np.ndarray:
    """The window's centres on an edge of the snapped triangle (E ≥ 0 covers them, E > 0
    does not): where only the tie rule decides."""
    xy, width, height, origin = args
    s, kw = snap(np.asarray(xy, float)), dict(origin=tuple(origin))
    return (naive_coverage(s, width, height, rule="inclusive", **kw)
            & ~naive_coverage(s, width, height, rule="strict", **kw))  # fmt: skip


#: The vertices a tie mistake may sit beside: (how they were read, words naming that).
_VERTEX_READINGS = (
    ("snapped", ""),
    ("raw", "you decide on the raw vertices (snap them first: np.rint(xy * 256) / 256), and "),
    ("float32", "you store the vertices in float32 before snapping (keep them in float64), "
     "and "),
)  # fmt: skip


def _readings(xy) -> dict[str, np.ndarray]:
    raw = np.asarray(xy, float)
    return {"snapped": snap(raw), "raw": raw, "float32": raw.astype(np.float32).astype(float)}


def _tie_reading(rule: str, args, got) -> str | None:
    """How the vertices were read (:data:`_VERTEX_READINGS`) when ``got`` is what the tie
    ``rule`` gives on them, in float64 or float32; None when it is not. Never when float32
    rounding of A x + B y + C gives ``got`` (:func:`_rounding_decides`): a vertex tested with
    E ≥ 0 then comes out missing, as if E > 0 (r40 10-1)."""
    if _rounding_decides(args, got):
        return None
    xy, width, height, origin = args
    for reading, v in _readings(xy).items():
        for dtype in (np.float64, np.float32):
            if np.array_equal(got, naive_coverage(v, width, height, rule=rule, dtype=dtype,
                                                  origin=tuple(origin))):  # fmt: skip
                return reading
    return None


def _tie_rule_decides(rule: str):
    """``fits``: ``got`` is what the tie ``rule`` gives on the raw or snapped vertices, in
    float64 or float32 (the tie mistake beside another one, such as no snapping)."""

    def fits(args, expected, got) -> bool:
        return _tie_reading(rule, args, got) is not None

    return fits


def _tie_words(kind: str, rule: str):
    """The tie mistake's words, with the vertex mistake beside it named first (r40 10-2: "E ≥
    0" alone was said of a pixel left out, which only the raw vertices could leave out)."""

    def words(args, expected, got) -> str:
        reading = _tie_reading(rule, args, got) or "snapped"
        return dict(_VERTEX_READINGS)[reading] + MISTAKES[kind]

    return words


#: The tie rules a student may write, as :func:`naive_coverage` names them.
_RULES = ("inclusive", "strict", "top_left")


def _rounding_decides(args, got) -> bool:
    """Near the origin (float32 holds the 1/256 grid there), is ``got`` what A x + B y + C
    evaluated in float32 gives, on the raw or snapped vertices with some tie rule, where the
    same rule from differences in float64 gives another answer? Then float32 rounding moved
    a centre across an edge it lies on (E exactly 0 at a vertex becomes −4.8e−07)."""
    if float(np.spacing(np.float32(_far(args)))) > GRID:
        return False  # far from the origin: FAR says it
    xy, width, height, origin = args
    for v in _readings(xy).values():
        for rule in _RULES:
            kw = dict(rule=rule, origin=tuple(origin))
            low = naive_coverage(v, width, height, absolute=True, dtype=np.float32, **kw)
            if np.array_equal(low, got) and not np.array_equal(
                low, naive_coverage(v, width, height, **kw)
            ):
                return True
    return False


ROUNDING = Mistake(
    "float32 rounding", "your edge functions round: A x + B y + C in float32 computes C = "
    "x_a y_b − y_a x_b as a difference of two products, and its rounding leaves E slightly "
    "negative (or positive) at a centre that lies on an edge (or, on a large triangle, a few "
    "steps of 2⁻¹⁶ px² from one), so that centre changes sides; compute E from differences to a vertex, "
    "(b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − a.x), in float64: on the snapped grid it is "
    "then exact", fits=lambda a, e, g: _rounding_decides(a, g), symptom=True,
    with_others=True,
)  # fmt: skip


OFF_GRID = Mistake(
    "off the grid", "this triangle's vertices lie off the 1/256-px grid, and snapping them "
    "changes which centres it covers: snap first (np.rint(xy * 256) / 256), then decide ties "
    "by the top-left rule on the snapped triangle", fits=_snapping_decides, symptom=True,
    must_fit=lambda a, e, g: _snapping_changes(a, e), with_others=True,
)  # fmt: skip


def tie_fill(s, width: int, height: int, origin, *, top: bool = True, left: bool = True):
    """Coverage of the snapped triangle ``s`` with the top-left rule missing a part: a centre
    on a top edge is inside only if ``top``, on a left edge only if ``left`` (a forgotten
    case of the rule covers fewer pixels, never more)."""
    v = np.asarray(s, float)
    if _area(v) < 0:
        v = v[[0, 2, 1]]
    y, x = centre_grid(origin, width, height)
    inside = np.ones((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])
        tie = (left and b[1] < a[1]) or (top and b[1] == a[1] and b[0] > a[0])
        inside &= (e >= 0) if tie else (e > 0)
    return inside


def _area(xy) -> float:
    (ax, ay), (bx, by), (cx, cy) = np.asarray(xy, float)
    return float((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))


def _float32_vertices(args, expected, got) -> str:
    """Words for snapped vertices stored in float32, with the case's spacing of float32."""
    far = float(np.abs(np.asarray(args[0], float)).max())
    step = float(np.spacing(np.float32(far)))
    return (f"you store the snapped vertices in float32: {far:.0f} px from the origin its "
            f"numbers are {step:g} px apart and cannot hold the 1/256-px grid, so a vertex "
            "moves before the edges are computed; keep them in float64 (or as integers in "
            "1/256 px)")  # fmt: skip


MISTAKES = {
    "nothing covered": "your function never covers anything: it returns an image of False "
    "for every triangle (a placeholder left in, or a test that no centre can pass, such as "
    "an orientation test reversed, which makes every triangle clockwise?)",
    "origin swapped": "you read origin as (x, y): it is (row, col), the window's first row "
    "and first column, so pixel [i, j] has its centre at x = col + j + ½, y = row + i + ½",
    "origin ignored": "you ignored origin: the window's pixel [i, j] has its centre at "
    "x = origin[1] + j + ½, y = origin[0] + i + ½, not at (j + ½, i + ½)",
    "origin added twice": "you add origin twice: your centres are at x = 2 · origin[1] + j + ½, "
    "y = 2 · origin[0] + i + ½ (origin added to the indices, and again to the centres); the "
    "window's pixel [i, j] has its centre at x = origin[1] + j + ½, y = origin[0] + i + ½",
    "pixel corners": "you tested the pixel corners (j, i): a pixel's centre is at "
    "(j + ½, i + ½) (plus the window's origin)",
    "transposed": "your image is transposed: pixel [i, j] is row i (y), column j (x), so the "
    "image has shape (height, width) and is indexed [row, col]",
    "vertex x and y swapped": "you read each vertex as (y, x): a vertex is (x, y), x along "
    "the columns and y down the rows",
    "no snapping": "you decide on the raw vertices: snap them to the 1/256-px grid first "
    "(np.rint(xy * 256) / 256), as a GPU's fixed-point set-up does, so that a triangle and "
    "its neighbour agree on every tie",
    "half-up snapping": "you round a vertex half-way between two grid points up "
    "(np.floor(x · 256 + ½)): the course's fixed-point conversion (teachraster's, lesson 07's "
    "table) rounds half to even, as np.rint does, so a vertex exactly on a half step goes to the even grid point and a centre on the "
    "edge changes sides",
    "float32 vertices": _float32_vertices,
    "floor snapping": "you snap by truncating (np.floor): every vertex moves up to 1/256 px "
    "left and up, always the same way, so centres near an edge change sides; round to the "
    "nearest grid point, np.rint(xy * 256) / 256",
    "E >= 0": "you cover every centre on an edge (E ≥ 0): a centre on an edge shared by two "
    "triangles is covered twice; the top-left rule gives it to one of them",
    "E > 0": "you cover no centre on an edge (E > 0): a centre on a shared edge is covered by "
    "neither triangle, and a sliver whose edge runs through centres vanishes",
    "no top edges": "you give no centre on a top edge to the triangle: your rule covers a "
    "centre on a left edge (one that runs up, b.y < a.y, with E(v1, v2, v3) > 0) but not "
    "the other half of the top-left rule, a horizontal edge running right (b.y == a.y, "
    "b.x > a.x); such a centre is covered by neither triangle that shares the edge",
    "no left edges": "you give no centre on a left edge to the triangle: your rule covers a "
    "centre on a top edge (horizontal, running right) but not the other half of the "
    "top-left rule, an edge running up (b.y < a.y, with E(v1, v2, v3) > 0); such a centre is "
    "covered by neither triangle that shares the edge",
    "top edge reversed": "your top edges are the bottom ones: on screen (y down), with the "
    "triangle oriented so that E(v1, v2, v3) > 0, a top edge is horizontal and runs right "
    "(b.x > a.x); the rule written for y up reads it the other way",
    "left edge reversed": "your left edges are the right ones: on screen (y down), with the "
    "triangle oriented so that E(v1, v2, v3) > 0, a left edge runs up (b.y < a.y)",
    "both reversed": "you give ties to bottom and right edges, the reverse of the top-left "
    "rule: on screen (y down), with the triangle oriented so that E(v1, v2, v3) > 0, a left "
    "edge runs up (b.y < a.y) and a top edge is horizontal and runs right (b.x > a.x); if "
    "your rule reads so, your E is the course's negated ((p − a) × (b − a), not "
    "(b − a) × (p − a)): the triangle you orient then runs the other way round",
    "one winding": "you assume one winding: orient the triangle first (swap two vertices when "
    "its edge function E(v1, v2, v3) is negative)",
    "oriented before snapping": lambda a, e, g: _raw_orientation_words(a, e, g),
    "absolute form": "you evaluate E = A x + B y + C from absolute coordinates in float32: far "
    "from the origin C = x_a y_b - y_a x_b cancels two products of size x·y; compute E in "
    "float64 (from differences to a vertex is safest)",
    "float32": lambda a, e, g: _float32_any_words(a, e, g),
    "float32 E": float32_words,
}
MISTAKES_ORIGIN_TWICE = MISTAKES["origin added twice"]
MISTAKES["transposed, origin swapped"] = (
    f"{MISTAKES['transposed']}; and {MISTAKES['origin swapped']}"
)


def _raw_orientation_words(args, expected, got) -> str:
    """r386 NW08: where an area tolerance gives the same empty image, both are said."""
    if small_area_refused(args, expected, got):
        return refused_or_raw_words(args, expected, got)
    return ("you oriented the triangle by its unsnapped area: snapping can flip a tiny "
            "triangle's winding, so orient the snapped one")  # fmt: skip


def _float32_any_words(args, expected, got) -> str:
    """float32 far from the origin (its spacing coarser than the grid), or float32 holding
    too few bits of E on a large triangle (r386 NW29: told "10⁵ px from the origin")."""
    far = _far(args)
    step = float(np.spacing(np.float32(far)))
    if step <= GRID:
        return float32_words(args, expected, got)
    return (f"you compute in float32: {far:,.0f} px from the origin its numbers are {step:g} px "
            "apart and cannot hold the 1/256-px grid; use float64")  # fmt: skip


def _off_by_one(axis: str, sign: str) -> str:
    coord, index, at = ("y", "origin[0] + i", "row") if axis == "rows" else ("x", "origin[1] + j",
                                                                             "column")  # fmt: skip
    near = "+ 1.5, the centre of the next " if not sign else "− 0.5, the centre of the previous "
    return (f"your {axis} are off by one: you test pixel [i, j] at {coord} = {index} {near}{at}; "
            f"its centre is at {coord} = {index} + ½")  # fmt: skip


def _absolute64_words(args, expected, got) -> str:
    far = _far(args)
    return (f"you evaluate E = A x + B y + C from absolute coordinates: {far:.0f} px from the "
            f"origin its products x·y are about {far * far:.0e} px², where float64's numbers "
            f"are {float(np.spacing(far * far)):.2g} px² apart, coarser than E's step on the "
            f"snapped grid, 2⁻¹⁶ = {2.0**-16:.2g} px², so a centre a step or two inside an edge "
            "reads E = 0 (or changes sides); compute E from differences to a vertex, which "
            "are small and exact there")  # fmt: skip


def _absolute64_rounds(args, expected, got) -> bool:
    """Is every wrong pixel a centre whose exact E on some edge of the snapped triangle lies
    within float64's rounding of A x + B y + C there (a few spacings of x·y), on a case far
    enough out for that rounding to pass E's step 2⁻¹⁶ px²? The absolute form in float64
    written any way (C first, or A x + (B y + C)), whose roundings differ (r373 W24)."""
    xy, width, height, origin = args
    far = _far(args)
    bound = 8 * float(np.spacing(far * far))
    if got.dtype != bool or got.shape != expected.shape or bound < 2.0**-16:
        return False
    v = snap(np.asarray(xy, float))
    y, x = centre_grid(origin, width, height)
    near = np.zeros((height, width), dtype=bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        near |= np.abs((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) <= bound
    wrong = got != expected
    return bool(wrong.any() and not (wrong & ~near).any())


#: The absolute form in float64 however its terms are grouped: named only where every
#: failing answer is wrong only within its rounding.
ABSOLUTE64 = Mistake("absolute form in float64", lambda a, e, g: _absolute64_words(a, e, g),
                     fits=_absolute64_rounds, only_whole=True)  # fmt: skip


#: r386 NW28, NW29: E in float32 however it is computed (stepped, shifted to the window):
#: named only where every failing answer is wrong only within float32's rounding of E.
FLOAT32_E = Mistake("float32 E", float32_words, fits=float32_rounds, only_whole=True)
#: r386 NW12: the mirror of "never covers anything".
ALL_COVERED = Mistake("everything covered", SLIP_WORDS["everything covered"], fits=all_covered,
                      only_whole=True)  # fmt: skip


def _area32_words(args, expected, got) -> str:
    """r457 W1: the orientation from a float32 area, far out (E itself right)."""
    s = snap(np.asarray(args[0], float))
    (ax, ay), (bx, by), (cx, cy) = s.astype(np.float32)
    area32 = float((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    exact = _area(s)
    far = _far(args)
    said = "0, so you refuse it" if area32 == 0 else f"{area32:g}, the other sign, so you orient it the wrong way"  # fmt: skip
    return (f"you orient the triangle (and test its area for 0) in float32: {far:,.0f} px from "
            f"the origin float32's numbers are {float(np.spacing(np.float32(far))):g} px apart, "
            f"coarser than the 1/256-px grid, so this sliver's E(v1, v2, v3), exactly "
            f"{exact * 2**16:.0f} · 2⁻¹⁶ px² on the snapped grid, comes out {said}; that area "
            "is an edge function too: compute it as you compute E, from "
            "differences in float64 (or in int64), where it is exact")  # fmt: skip


def _int32_reach(args, whose: str) -> str:
    """What both int32 mistakes' words say: the triangle in 1/256-px units, and how far
    ``whose`` products reach past int32's largest number."""
    v = np.rint(np.asarray(args[0], float) * 256)
    across = float(np.ptp(v, axis=0).max())
    return (f"in 1/256-px units this triangle is {across:.0f} across ({across / 256:.0f} px), "
            f"so {whose} products reach about {across * across:.1e}, past int32's largest "
            f"number, {np.iinfo(np.int32).max:,}, and wrap around to the")  # fmt: skip


def _int32_area_words(args, expected, got) -> str:
    """r457 M2: lesson 02's integer fill with int32 vertices: the area wraps, E does not."""
    reach = _int32_reach(args, "the area's")
    return (f"your area E(v1, v2, v3) overflows int32: {reach} other sign, so you orient the triangle the wrong way and cover nothing (your E at "
            "each centre is int64, as the centres are); keep the vertices in int64, as lesson "
            "02's code does: 10.1's count for the relative form says how many bits it needs")  # fmt: skip


def _origin_twice_words(args, expected, got) -> str:
    """r457 M1: origin added twice, or the vertices moved by +origin into the window's frame:
    on a window far from the triangle both give nothing, and both are said."""
    xy, width, height, origin = args
    twice = MISTAKES_ORIGIN_TWICE
    o = np.asarray(origin)
    if np.array_equal(expected_fill(xy, width, height, -o), got):
        return (f"{twice}; or, the same answer here, you moved the vertices by +origin into "
                "the window's frame: there a vertex is at xy − (origin[1], origin[0]), the "
                "window's pixel [i, j] at (j + ½, i + ½)")  # fmt: skip
    return twice


def _int32_words(args, expected, got, *, edges_only: bool = False) -> str:
    """Every product in int32 (r373 W41), or E's only, the area in int64 (r493 H2)."""
    only = " (your area, in int64, does not: E's products wrap)" if edges_only else ""
    reach = _int32_reach(args, "E's")
    return (f"your integer edge functions overflow int32{only}: {reach} "
            "wrong sign; compute them in int64 (exact for every input this task allows) or "
            "float64: 10.1's count for the relative form says how many bits they need")  # fmt: skip


def _int32_edges_words(args, expected, got) -> str:
    return _int32_words(args, expected, got, edges_only=True)


MISTAKES.update(
    {
        **{
            f"{axis} off by one{sign}": _off_by_one(axis, sign)
            for axis in ("rows", "columns")
            for sign in ("", ", the other way")
        },
        "only x snapped": "your y coordinates are not snapped: you round x to the 1/256-px grid "
        "and leave y as it came; a GPU snaps both coordinates of every vertex",
        "only y snapped": "your x coordinates are not snapped: you round y to the 1/256-px grid "
        "and leave x as it came; a GPU snaps both coordinates of every vertex",
        "half-down snapping": "you round a vertex half-way between two grid points down "
        "(np.ceil(x · 256 − ½), or a round-half-down of your own): the course's fixed-point "
        "conversion (teachraster's, lesson 07's table) rounds half to even, as np.rint does, so "
        "a vertex at 641.5 steps goes to 642, not 641, and a centre near its edges changes sides",
        "ceil snapping": "you snap by rounding up (np.ceil): every vertex moves up to 1/256 px "
        "right and down, always the same way, so centres near an edge change sides; round to the "
        "nearest grid point, np.rint(xy * 256) / 256",
        "tie rule before orienting (index)": "your tie rule reads the edges as given, not as "
        "oriented: you decide top and left on the vertices before the swap, so on a triangle "
        "given clockwise on screen (E(v1, v2, v3) < 0) each edge gets another edge's verdict; "
        "decide top and left on the edges of the oriented triangle",
        "tie rule before orienting (edge)": "your tie rule reads the edges as given, not as "
        "oriented: on a triangle given clockwise on screen (E(v1, v2, v3) < 0) your left edges "
        "are its right ones and your top edges its bottom ones; decide top and left on the "
        "edges of the oriented triangle",
        "any horizontal edge is top": "you give ties to both horizontal edges, top and bottom: "
        "with the triangle oriented so that E(v1, v2, v3) > 0, only the top one runs right "
        "(b.y == a.y and b.x > a.x); the bottom one runs left and its centres go to the triangle "
        "below",
        "absolute form in float64": _absolute64_words,
        "int32 overflow": _int32_words,
        "area in float32": _area32_words,
        "int32 area": _int32_area_words,
        "int32 E": _int32_edges_words,
        "both reversed, as not top-left": "your ties go to every edge that is not top or left "
        "(lesson 02's bias of −1 put on the top and left edges, not on the others?): that is "
        "the bottom-right rule, the reverse of the top-left one, and it also gives a point-"
        "sized triangle (v1 = v2 = v3, every edge a→a) every centre; the −1 belongs on the "
        "edges that are neither top nor left",
        "snapped relative to a vertex": "you snap coordinates relative to v1 (xy − xy[0]), "
        "not the vertices on the screen: the GPU's grid is fixed to the screen, at whole "
        "multiples of 1/256 px, and v1 lies off it, so your grid points are shifted by v1's "
        "fraction of a step and every vertex lands beside the GPU's; snap the vertices first, "
        "then shift by a grid point (the window's origin, or the snapped v1) for small numbers",
        "everything covered": "your function covers every pixel of the window for every "
        "triangle, a zero-area one too: it returns an image of True whatever the input (a "
        "placeholder left in, or a test that every centre passes, such as the edges combined "
        "with | instead of &?)",
        "origin added twice": _origin_twice_words,
        **{kind: words for kind, words in SLIP_WORDS.items() if kind != "everything covered"},
    }
)


def _tie_case(args, expected, got) -> bool:
    """Is the answer wrong only at ties: every wrong pixel a centre on an edge of the snapped
    triangle (covered by E ≥ 0 on every edge, not by E > 0)? Then a tie rule named must give
    it (a wrong pixel elsewhere has another cause: precision, snapping; so has float32
    rounding of A x + B y + C, which moves centres across the edges they lie on)."""
    if got.shape != expected.shape or _rounding_decides(args, got):
        return False
    if got.dtype == bool and _precision_decides(args, got):  # r457: float32 far out (FAR's)
        return False
    wrong = got != expected
    return bool(wrong.any() and not (wrong & ~_on_edge(args)).any())


#: The tie mistakes beside another (r6: an unsnapped E >= 0 fill at 10013 px was told
#: precision, where float32 holds the grid): named when no single cause fits.
TIES = tuple(Mistake(kind, _tie_words(kind, rule), fits=_tie_rule_decides(rule), symptom=True,
                     must_fit=_tie_case)
             for kind, rule in (("E >= 0", "inclusive"), ("E > 0", "strict")))  # fmt: skip

#: The tie rules a student may get wrong: each is named only where it gives the answer of
#: every failing tie case (r84 10-2: a mirrored rule was "E > 0" on one, "E ≥ 0" on another).
TIE_KINDS = ("E >= 0", "E > 0", "no top edges", "no left edges", *REVERSED,
             "tie rule before orienting (index)", "tie rule before orienting (edge)",
             "any horizontal edge is top", "both reversed, as not top-left")  # fmt: skip


def _shape_swapped(args, expected, got) -> bool:
    """r394 NW11: an image of shape (width, height) where the answer is one value throughout
    (an early return): a shape, not a transposed image."""
    return got.shape == expected.shape[::-1] != expected.shape and bool(
        expected.size and (expected == expected.flat[0]).all() and (got == expected.flat[0]).all()
    )


def _shape_swapped_words(args, expected, got) -> str:
    return (f"your image has shape {got.shape}, (width, height) (an early return such as "
            f"np.zeros((width, height))?): an image is indexed [row, col], so its shape is "
            f"(height, width), {expected.shape}")  # fmt: skip


SHAPE_SWAPPED = Mistake("transposed", _shape_swapped_words, fits=_shape_swapped)


def _table() -> list[Mistake]:
    """The mistakes table, each tie rule held to every failing tie case; THIN first (r386
    NW08: where a raw orientation gives the same empty image, its words say both, under one
    kind whatever the drawn cases)."""
    table = variant_mistakes(_variants, MISTAKES, (*_roundings(), ABSOLUTE64, FLOAT32_E,
                                                   ALL_COVERED, ZERO_AREA, FAR, ROUNDING, *TIES,
                                                   OFF_GRID))  # fmt: skip
    # r457 W1: a float32 area before THIN, whose empty image on a far sliver it also gives
    area32 = [m for m in table if m.kind == "area in float32"]
    table = [SHAPE_SWAPPED, *area32, THIN] + [m for m in table if m not in area32]
    table = [replace(m, must_fit=_tie_case) if m.kind in TIE_KINDS else m for m in table]
    return [replace(m, only_whole=True) if m.kind in RARE_KINDS else m for m in table]


#: Mistakes that change a few cases only: named only where they give every answer of the
#: check, passing ones included (r373: "floor snapping", "oriented before snapping" were each
#: said on one case whose answer they matched by coincidence, to functions without them).
RARE_KINDS = ("no snapping", "floor snapping", "half-up snapping", "half-down snapping",
              "ceil snapping", "oriented before snapping",
              "float32 vertices", "absolute form in float64", "int32 overflow", "only x snapped",
              "only y snapped", "origin ignored", "origin added twice",
              "float32 E", "float32", "absolute form", *SLIP_WORDS,
              "origin swapped", "E > 0", "area in float32", "int32 area", "int32 E")  # fmt: skip  # r394 W09, W32: one case is no cause


def explain_fill(args, expected, got) -> str:
    """The first wrong pixel, by the top-left rule on the snapped triangle, and the counts."""
    xy, width, height, origin = args
    if got.shape != expected.shape:
        rows, cols = expected.shape
        swapped = got.shape == expected.shape[::-1]
        return (f"this window is {rows} rows (height) by {cols} columns (width)"
                + ("; yours has the two swapped: an image is indexed [row, col], its shape is "
                   "(height, width)" if swapped else ""))  # fmt: skip
    if got.dtype != bool:  # NaN or inf in the image (as_image keeps them)
        bad = ~np.isfinite(got)
        i, j = np.argwhere(bad)[0]
        other = int((np.where(bad, expected, got).astype(bool) != expected).sum())
        return (f"pixel [{i}, {j}] of your image is {'NaN' if np.isnan(got[i, j]) else 'inf'} "
                f"({int(bad.sum())} pixel(s) NaN or inf, {other} other pixel(s) wrong), where "
                f"the answer is {bool(expected[i, j])}")  # fmt: skip
    s = snap(np.asarray(xy, float))
    i, j = np.argwhere(got != expected)[0]
    centre = np.array([origin[1] + j + 0.5, origin[0] + i + 0.5])
    text, _, _ = explain_pixel(s, centre, bool(expected[i, j]))
    if not _unoriented(args, got):  # r394 E2: the imperative only where it is the cause
        text = text.replace(FLIP_ADVICE, "")
    counts = f"{int((expected & ~got).sum())} missing, {int((got & ~expected).sum())} extra"
    return f"{text} (snapped vertices; {counts})"


#: The tail of :func:`.coverage.interior_side` that reads as advice (r394 E2).
FLIP_ADVICE = ", and a test for E > 0 must flip the sign first or swap two vertices"


def _unoriented(args, got) -> bool:
    """Does ``got`` equal the fill of a function that never orients the triangle?"""
    xy, width, height, origin = args
    s = snap(np.asarray(xy, float))
    one = naive_coverage(s, width, height, rule="top_left", orient="none", origin=tuple(origin))
    return got.shape == one.shape and bool(np.array_equal(got, one))


def _rule(args, expected, got) -> str:
    return ""


def compose(head: str, words: str) -> str:
    """The missing repair first, then the first wrong pixel as its example (none after an
    image that never covers anything: no rule is the cause there, r373 W26)."""
    words = words.lstrip(" .:;")
    if words.startswith(MISTAKES["nothing covered"]):
        return words
    return f"{words}. For example, {head}" if words else head


def _zero_area(args, expected, got) -> bool:
    zero = _area(snap(np.asarray(args[0], float))) == 0
    return zero and got.dtype == bool and bool(got.any())


ZERO_AREA = Mistake("zero area", "snapped, this triangle has zero area (its vertices land on "
                    "one line or one point): it covers nothing; refuse a snapped area of 0 before "
                    "testing any centre (on its line E = 0, and a tie rule may cover it)",
                    fits=_zero_area,
                    with_others=True)  # fmt: skip


def draw_fill(ax, case, got):
    """The window's pixels by state (covered, missing, extra) and the snapped triangle."""
    from .drawing import draw_coverage

    _, (xy, width, height, origin), expected = case
    window = SimpleNamespace(origin=(origin[1], origin[0]))
    answer = None if got is None or got.shape != expected.shape else got
    ax.set_xlabel("column (x, px)")  # r373 E2: the axes named
    ax.set_ylabel("row (y, px, down)")
    if answer is not None and answer.dtype != bool:  # NaN or inf: drawn as not covered
        answer = np.where(np.isfinite(answer), answer, 0).astype(bool)
    s = snap(np.asarray(xy, float))
    artists = draw_coverage(ax, window, s, expected, answer, None, None)
    # no y tick on the top edge: its label would run into the report's title
    top = min(ax.get_ylim())
    ax.set_yticks([t for t in ax.get_yticks() if t > top and t <= max(ax.get_ylim())])
    if float(np.ptp(s, axis=0).max()) < SMALL:
        artists += _magnified(ax, s, width, height, origin)
    return artists


#: A snapped triangle smaller than this (px) is drawn again, magnified, in an inset (r373 E2:
#: snap_flips_winding was a dot with "v1, v2, v3" piled on it).
SMALL = 0.5


def _magnified(ax, s, width: int, height: int, origin) -> list:
    """An inset in the window's corner farthest from the triangle: the snapped triangle, its
    vertices named, and the pixel centre nearest to it."""
    from .drawing import vertex_labels

    centre = s.mean(axis=0)
    x0, y0 = origin[1], origin[0]
    right = (centre[0] - x0) < width / 2
    lower = (centre[1] - y0) < height / 2
    inset = ax.inset_axes([0.52 if right else 0.03, 0.03 if lower else 0.52, 0.45, 0.45])
    nearest = np.floor(centre) + 0.5
    pts = np.vstack([s, nearest])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    pad = 0.25 * float((hi - lo).max()) + 1 / 256
    ring = np.vstack([s, s[:1]])
    inset.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    inset.plot(*nearest, "+", color="black", ms=8)
    inset.annotate(
        "centre", nearest, xytext=(3, -11), textcoords="offset points", fontsize="x-small"
    )
    vertex_labels(inset, s, pad / 4, (lo[0] - pad, lo[1] - pad, *(hi - lo + 2 * pad)))
    inset.set_xlim(lo[0] - pad, hi[0] + pad)
    inset.set_ylim(hi[1] + pad, lo[1] - pad)
    inset.set_aspect("equal")
    inset.set_xticks([])
    inset.set_yticks([])
    inset.set_title(f"magnified, {(hi - lo + 2 * pad).max():.2g} px across", fontsize="x-small")
    return [inset]


def as_image(value) -> np.ndarray:
    """A 2-D image of True/False (or 1/0) values, as bools; its shape is compared later."""
    refuse_non_answers(value, "a (height, width) image of True/False")
    if isinstance(value, np.ndarray) and value.size > 1 << 16:
        raise WrongAnswerType(f"returned {short(value)}: far larger than the window")
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {short(value)}, not an image") from None
    finite = np.isfinite(arr) if arr.dtype.kind == "f" else True
    if arr.ndim != 2 or arr.dtype.kind not in "biuf" or not np.isin(arr[finite], (0, 1)).all():
        raise WrongAnswerType(
            f"returned {short(value)}: expected a (height, width) image of True/False"
        )
    # r373 W22: NaN or inf among 0/1 floats is kept, so that the report names it (a float
    # image of 0.0/1.0 is fine; "the wrong type" told the student floats are refused)
    return arr.astype(bool) if np.all(finite) else arr.astype(float)


def same_image(got: np.ndarray, expected: np.ndarray, args=None) -> bool:
    return got.shape == expected.shape and bool(np.array_equal(got, expected))


#: The repairs as the words give them, and what is said instead until two different answers
#: have failed (r84 10-1: the naive fill's report, run before the task, printed each repair as
#: code: the exercise was a to-do list). The naive fill is the first answer; the student's
#: first try of robust_fill the second, so its check says everything.
HINTS = (
    (": snap first (np.rint(xy * 256) / 256), then decide ties by the top-left rule on the "
     "snapped triangle", ": a GPU changes the vertices before it tests any centre "
     "(lesson 07): find what it does to them"),
    ("; compute E from differences to a vertex, (b.x − a.x)(p.y − a.y) − (b.y − a.y)(p.x − "
     "a.x), in float64: on the snapped grid it is then exact", "; find a form of E, and a "
     "precision, in which E is exact for vertices and centres on the snapped grid"),
    ("; keep the vertices in float64 (or integers in 1/256 px) and compute each edge function "
     "in float64 (from differences to a vertex is safest: A x + B y + C cancels two products "
     "of size x·y)", "; find which of your numbers must hold that grid there, and a form of E "
     "without products of size x·y"),
    (" first (np.rint(xy * 256) / 256), as a GPU's fixed-point set-up does,", " first, as a "
     "GPU's fixed-point set-up does,"),
    ("; the top-left rule gives it to one of them", "; a GPU gives it to exactly one of them"),
    (", so orient the snapped one", ""),
    ("; compute E in float64 (from differences to a vertex is safest)", ""),
    # r373 T2: the grid's code and the form of E in the words added since, and in the older
    # words that said them outside the texts above (a coarse grid, floor snapping)
    (" (snap them first: np.rint(xy * 256) / 256)", " (snap them first)"),
    (", np.rint(xy * 256) / 256", ""),
    ("; compute E from differences to a vertex, which are small and exact there", "; find a "
     "form of E without products of size x·y"),
)  # fmt: skip

#: r493 W1: the package's other fills of a window on the GPU's grid, each this answer with
#: the vertices moved by −origin (lesson 02's arithmetics, the rational ground truth, the exact
#: integer DDA, the pipeline's batched fill): none calls ``rasterize``, so each is listed.
OTHER_FILLS = (
    precision_coverage,
    exact_coverage,
    span_fill_int_dda,
    rasterize_batch,
    *METHODS.values(),
)  # and the core's own fills of a box, by its EdgeSetup
#: How the report names a fill whose own name does not say whose it is.
FILL_LABELS = {
    precision_coverage: "study.precision.coverage",
    **{f: f"{f.__module__.removeprefix('teachraster.')}.fill" for f in METHODS.values()},
}
#: Every fill of the package's that gives (or, with its options, can give) the GPU's answer:
#: 10.2's answers, and what a search in 10.3 (:mod:`.breaking_case`) must not run.
PACKAGE_FILLS = (rasterize, naive_coverage, rule_coverage, fill_window, *OTHER_FILLS)

#: r441 W3: the package's fills that are this answer, beside ``rasterize``: lesson 07's
#: ``naive_coverage`` and lesson 06's ``rule_coverage`` with the top-left rule in float64 (on
#: snapped vertices they are the GPU's fill), the catalogue's ``fill_window`` (the core's own
#: fill), and the top-left rule itself, as in exercise 1 (a repair the task asks for).
FILL_ANSWERS = (
    PackageAnswer(rasterize),
    PackageAnswer(naive_coverage, what="the top-left rule's fill in float64, this very answer "
                  "on snapped vertices", when=lambda a: a.get("rule") == "top_left"
                  and np.dtype(a.get("dtype")) == np.float64),
    PackageAnswer(rule_coverage, what="the top-left rule's fill in float64, this very answer "
                  "on snapped vertices", when=lambda a: a.get("rule") == "top-left"),
    PackageAnswer(fill_window, what="the GPU's fill of a window, this very answer"),
    *(PackageAnswer(f, what="a fill of the package's on the GPU's 1/256-px grid, this very "
                    "answer once the vertices are moved by −origin", label=FILL_LABELS.get(f))
      for f in OTHER_FILLS),
    *TIE_RULE_ANSWERS,
    # r493 (w83): the GPU's snapping, a repair the task asks for, as the top-left rule is
    PackageAnswer(snap, what="the GPU's snapping to the 1/256-px grid, a part of this very answer"),
)  # fmt: skip

ROBUST_FILL = Exercise(
    "robust_fill", fill_cases, as_image, same_image, explain_fill, _rule,
    _table(), answers=FILL_ANSWERS,
    draw=draw_fill, compose=compose, hints=HINTS,
)  # fmt: skip
