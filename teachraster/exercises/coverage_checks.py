"""The coverage exercises, ``covers`` (one centre) and ``fill`` (a whole image), as exercises.

A case is a window of pixels with one triangle or more (:mod:`.cases`); its answer is one
(h, w) bool image per triangle. ``covers`` is called once per pixel of a window around each
triangle; ``fill`` once per triangle, and may return bools or 0/1 numbers
(``np.zeros((h, w))`` filled with 1.0 is a correct answer). The mistakes are the rule with a
knob turned (:func:`.coverage.rule_images`): the tie rule by the kinds of edges that own their
centres, one winding only, sampling at pixel corners, vertices rounded to whole pixels; and an
empty answer, a transposed or upside-down image, x and y swapped, float32 far from the origin;
r347's: border rows or columns a loop skips, a bounding box one short, a left-right mirror,
other sampling points, vertices moved to pixel centres, tolerances on E, a tie test that forgot
"exactly horizontal"; r352's (:mod:`.coverage_boxes`): a bounding box clamped at its upper end
only (negative indices wrap), one short at any side, a point a tiny step off the centre, and
the clamp said where a box raises IndexError. An explanation names the mistake, then shows it
on one wrong pixel, the most telling one; where no mistake gives the answer it says what
differs, in facts only
(:func:`.coverage.differences`), with the possible causes (:data:`TIE_CAUSES`) listed as such
only where every wrong centre is a tie.
"""

from __future__ import annotations

import re
from functools import cache

import numpy as np

from ..core.edges import is_top_left, passes, top_left_edges
from ..core.fill import rasterize
from . import coverage as cov
from . import coverage_boxes as boxes
from . import edge_slips, plane32
from . import point_slips as ps
from . import sample_steps as steps
from .answers import as_bool, as_coverage, short
from .cases import (
    DRAWN_WORD,
    SEED,
    CoverageCase,
    catalogue_coverage,
    drawn_coverage,
    drawn_rng,
    random_coverage,
)
from .diagnosis import constant_words
from .exercise import Exercise, Knobs, Mistake, PackageAnswer, Slip
from .near_ties import (
    LONG_NEAR_TIES,
    SLIVER32,
    float32_safe,
    long_near_tie_case,
    near_tie_cases,
    sliver32_case,
    winding32_images,
)
from .package_answers import values_read

FLOAT32_EPS = 2.0**-24


def tested(case: CoverageCase, xy: np.ndarray) -> np.ndarray:
    """(h, w) bool: the pixels ``covers`` is asked about, the triangle's box and one more."""
    w, h = case.size
    lo = np.floor(xy.min(axis=0) - case.origin).astype(int) - 1
    hi = np.ceil(xy.max(axis=0) - case.origin).astype(int) + 1
    mask = np.zeros((h, w), dtype=bool)
    mask[max(lo[1], 0) : min(hi[1], h), max(lo[0], 0) : min(hi[0], w)] = True
    return mask


def _masks(case: CoverageCase) -> np.ndarray:
    return np.array([tested(case, xy) for xy in case.triangles])


def call_covers(fn, args) -> np.ndarray:
    """The student's covers at every tested centre of every triangle: (n, h, w) bool."""
    (case,) = args
    w, h = case.size
    out = np.zeros((len(case.triangles), h, w), dtype=bool)
    x0, y0 = case.origin
    for t, xy in enumerate(case.triangles):
        for i, j in np.argwhere(tested(case, xy)):
            p = np.array([x0 + j + 0.5, y0 + i + 0.5])
            out[t, i, j] = as_bool(fn(xy.copy(), p))
    return out


def call_fill(fn, args):
    """The student's fill of every triangle: (n, h, w) (or (n, w, h), transposed) bool."""
    (case,) = args
    w, h = case.size
    images = [as_coverage(fn(xy.copy(), w, h), h, w) for xy in case.triangles]
    if len({im.shape for im in images}) == 1:
        return np.array(images)
    return tuple(images)


def same_coverage(got, expected, args) -> bool:
    return (
        isinstance(got, np.ndarray)
        and got.shape == expected.shape
        and bool(np.array_equal(got, expected))
    )


def _expected(case: CoverageCase) -> np.ndarray:
    return np.array([cov.expected_coverage(case, xy) for xy in case.triangles])


def covers_cases():
    """The fixed cases (built once), a few drawn for this check (r46 X1) and a long edge
    drawn for it where float32 products put a centre on the wrong side (r46 E1)."""
    drawn = [*drawn_coverage(), long_edge_coverage(drawn_rng()), *_drawn_near_ties()]
    return _covers_cases() + [(c.label, (c,), _expected(c)) for c in drawn]


def _drawn_near_ties() -> list[CoverageCase]:
    """r420 W1, W2: two small near ties and a large one, drawn for this check."""
    rng = drawn_rng()
    return near_tie_cases(rng, f" {DRAWN_WORD}", signs=(1, -2), large=(int(rng.choice((1, -1))),))


@cache
def fixed_near_ties() -> list[CoverageCase]:
    """r420 W1, W2: the fixed near ties (a tolerance of 3e-5 on the edge test, or of 1e-9 of
    the area, passed every case)."""
    return near_tie_cases(np.random.default_rng(SEED + 420), "")


@cache
def long_near_ties() -> CoverageCase:
    """r428 WP1, WP2: near ties beside long edges (a step of 1e-7 px to the right, and
    math.isclose on the edge function's products, passed every case)."""
    return long_near_tie_case(np.random.default_rng(SEED + 428))


def _products32(a, b, px, py):
    """E(a, b, p) at centres (px, py) with the two products rounded to float32 (the
    differences are exact): a student's float32 arithmetic."""
    f = np.float32
    return f(b[0] - a[0]) * (py - a[1]).astype(f) - f(b[1] - a[1]) * (px - a[0]).astype(f)


def long_edge_coverage(rng) -> CoverageCase:
    """A triangle near the origin whose edge v1→v2 is 3000-5000 px long, and an 8 × 8 window
    on it around a centre that the edge function with float32 products puts on the wrong
    side (its exact E is within float32's rounding of the ~40-bit products, and not 0)."""
    while True:
        a = np.rint(rng.uniform(0, 64, 2) * 256) / 256
        b = a + np.rint(rng.uniform((2000, 2000), (3500, 3500)) * 256) / 256
        y = np.arange(int(a[1]) + 8, int(b[1]) - 8) + 0.5
        x = np.floor(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]) - 0.5) + 0.5
        px, py = np.r_[x, x + 1], np.r_[y, y]  # the centres either side of the edge
        exact = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
        # a→b runs down: not a top-left edge, so a centre is inside it only where E > 0
        wrong = (exact != 0) & ((_products32(a, b, px, py) > 0) != (exact > 0))
        if wrong.any():
            k = int(np.flatnonzero(wrong)[0])
            # c on the interior side of a→b (clockwise on screen): a covers that swaps two
            # vertices of the other winding still evaluates a→b, whose products were drawn
            xy = np.array([a, b, np.rint((a + b) / 2 + (-1500.0, 1500.0))])
            label = (f"a long edge drawn for this check ({cov.fmt(float(np.hypot(*(b - a))))} "
                     "px), centres close to it")  # fmt: skip
            return CoverageCase(label, xy[None], (int(px[k]) - 4, int(py[k]) - 4), (8, 8))


def sample_point_case() -> CoverageCase:
    """lesson 07's split square moved so that its vertices and its diagonal lie on the points
    (j + 0.375, i + 0.125), where ``covers`` is asked (the window's origin is fractional)."""
    shift = np.array(ps.SAMPLE) - 0.5
    square = np.array([[[1.5, 1.5], [6.5, 1.5], [6.5, 6.5]], [[1.5, 1.5], [6.5, 6.5], [1.5, 6.5]]])
    label = (f"{ps.SAMPLE_LABEL}: covers asked at p = (j + {ps.SAMPLE[0]}, i + {ps.SAMPLE[1]}), "
             "Direct3D's 4× sample 0, as capstone 12's MSAA scene asks it; a square split along "
             "its diagonal, its corners and diagonal on those points (a mesh)")  # fmt: skip
    return CoverageCase(label, square + shift, tuple(shift.tolist()), (8, 8), mesh=True)


@cache
def _covers_cases():
    cases = catalogue_coverage() + random_coverage() + fixed_near_ties() + [long_near_ties()]
    cases += [sliver32_case()]  # r438 WP1: last, so earlier first explanations stay
    cases += [sample_point_case()]  # r453 WP1: covers asked off the centres (capstone 12)
    return [(c.label, (c,), _expected(c)) for c in cases]


def fill_cases():
    """The fixed cases (built once) and a few drawn for this check (r46 X1)."""
    drawn = drawn_coverage() + _drawn_near_ties()
    return _fill_cases() + [(c.label, (c,), _expected(c)) for c in drawn]


@cache
def _fill_cases():
    # fill draws the image from the origin: cases far from it have no pixel to show
    cases = [c for c in catalogue_coverage() + random_coverage(far=False) if c.origin == (0, 0)]
    cases += _oblong_cases() + _border_cases() + fixed_near_ties() + [long_near_ties()]
    cases += [sliver32_case()]  # r438 WP1
    return [(c.label, (c,), _expected(c)) for c in cases]


def _border_cases() -> list[CoverageCase]:
    """Triangles that reach every border row and column of the image (r347 1: a loop that
    skipped the last column or the first row passed every case): one larger than the image
    (clockwise on screen), and a mesh of two splitting the image along its diagonal, one of
    each winding."""
    big = np.array([[[-3.0, -2.0], [25.0, -2.0], [-3.0, 20.0]]])
    half = np.array([[[0.0, 0.0], [10.0, 7.0], [0.0, 7.0]], [[0.0, 0.0], [10.0, 7.0], [10.0, 0.0]]])
    # r352 1: out at the top only, then at the left only (each winding), most pixels empty: a
    # box clamped at its upper end alone wraps its negative rows (columns) round to the bottom
    # (right), where the larger triangle's real rows overwrote them again
    out = np.array([[[2.0, -3.0], [7.0, 2.0], [1.0, 3.0]], [[-3.0, 2.0], [2.0, 7.0], [3.0, 1.0]]])
    return [
        CoverageCase("a triangle larger than the image: a 9 × 6 image (width × height), every "
                     "pixel covered", big, (0, 0), (9, 6)),
        CoverageCase("two triangles splitting a 10 × 7 image along its diagonal (a mesh)",
                     half, (0, 0), (10, 7), mesh=True),
        CoverageCase("two triangles reaching out of an 8 × 8 image, one at the top, one at the "
                     "left (not a mesh)", out, (0, 0), (8, 8)),
    ]  # fmt: skip


def _oblong_cases() -> list[CoverageCase]:
    """Seeded random triangles in images wider than tall and taller than wide (r39 01-1: one
    case of 39 told (height, width) from (width, height))."""
    rng = np.random.default_rng(3901)
    out = []
    for k, (w, h) in enumerate([(23, 9), (8, 19), (30, 13)]):
        xy = np.round(rng.uniform(0, 1, (3, 2)) * (w, h) * 256) / 256
        while cov.area2(xy) == 0:  # pragma: no cover - a seeded draw that is never flat
            xy = np.round(rng.uniform(0, 1, (3, 2)) * (w, h) * 256) / 256
        label = f"random oblong {k + 1}: a {w} × {h} image (width × height)"
        out.append(CoverageCase(label, xy[None], (0, 0), (w, h)))
    return out


# -- the mistakes -------------------------------------------------------------------------------
def _winding_words(args, expected, got, which="counter-clockwise") -> str:
    (case,) = args
    sign = -1 if which == "counter-clockwise" else 1
    xy = next((t for t in case.triangles if np.sign(cov.area2(t)) == sign), case.triangles[0])
    return (
        f"you covered nothing of a triangle whose vertices run {which} on screen "
        f"(E(v1, v2, v3) = {cov.fmt(cov.area2(xy))}): handle both windings (swap two vertices, "
        "or accept all-negative edge functions)"
    )


def _far_words(args, expected, got) -> str:
    (case,) = args
    far = max(case.origin)
    ulp = float(np.spacing(np.float32(far)))
    return (
        f"this triangle lies {cov.fmt(far)} px from the origin, where float32 numbers are "
        f"{cov.fmt(ulp)} px apart and cannot hold the 1/256-px grid: compute the edge functions "
        "in float64 (or exact integers), relative to a vertex"
    )


def _products_words(args, expected, got) -> str:
    (case,) = args
    xy = case.triangles[0]
    longest = max(float(np.hypot(*(xy[k] - xy[k - 1]))) for k in range(3))
    return (
        f"this triangle's longest edge runs {cov.fmt(longest)} px: an edge function multiplies "
        "differences of thousands of px held to 1/256 px (about 40 bits), float32 keeps 24, "
        "so a centre this close to an edge lands on the wrong side: did you compute in "
        "float32? Compute the edge functions in float64 (plain Python floats or np.float64)"
    )


def _float32_words(args, expected, got) -> str:
    (case,) = args
    # r428: far is the window's place (a long near tie's vertices lie 10^4 px away, its
    # centres at the origin)
    far = max(abs(q) for q in case.origin) >= 1e4
    return (_far_words if far else _products_words)(args, expected, got)


def _float32_fits(args, expected, got) -> bool:
    """Every wrong centre lies within float32's rounding of an edge: far from the origin
    (the coordinates round), or near it on a long edge (the ~40-bit products round: r46 E1).
    One mistake for both, so a float32 answer failing both kinds of case is named on both."""
    (case,) = args
    far = float(np.abs(case.triangles).max())
    if not isinstance(got, np.ndarray) or got.shape != expected.shape or float32_safe(case):
        return False  # r420 M2: float32 gives the rule's answer on a near tie
    if case.label.startswith(SLIVER32):  # r438 WP1: float32's E(v1, v2, v3) is 0 there
        return bool(np.array_equal(got, winding32_images(case, expected)))
    for k, xy in enumerate(case.triangles):
        extent = float(np.abs(xy - xy[0]).max()) + 1.0
        if far < 1e4 and extent < 1000:  # near the origin and short: float32 is exact enough
            return False
        tol = 8 * FLOAT32_EPS * (far if far >= 1e4 else extent) * extent
        for i, j in np.argwhere(got[k] != expected[k]):
            c = np.array([case.origin[0] + j + 0.5, case.origin[1] + i + 0.5])
            e = np.abs(cov.values_at(xy, c)).min()
            if e > tol or (far < 1e4 and e == 0):  # near the origin a tie is the rule's
                return False
    return True


def _tested(case: CoverageCase, masked: bool):
    return _masks(case) if masked else True


def _winding32(case: CoverageCase):
    """r438 WP1: the rule's images with the winding (and zero area) decided in float32, on the
    sliver built for it (None elsewhere: the far cases' float32 rounding has other words)."""
    if not case.label.startswith(SLIVER32):
        return None
    return winding32_images(case, _expected(case))


def _winding32_words(args, expected, got) -> str:
    (case,) = args
    a, b, c = np.asarray(case.triangles[0], dtype=float)
    big = max(abs((b[0] - a[0]) * (c[1] - a[1])), abs((b[1] - a[1]) * (c[0] - a[0])))
    step = cov.fmt(float(np.spacing(np.float32(big))))
    return (
        f"your winding (or zero-area) test is computed in float32: this sliver's E(v1, v2, v3) "
        f"= {cov.fmt(cov.area2(case.triangles[0]))} px² is the difference of two products of "
        f"{cov.fmt(big)} px², which float32 holds in steps of {step} px², so it comes out 0 (or "
        "of the wrong sign) "
        "and the triangle is dropped, though the rule covers a centre of it. Vertices on the "
        "1/256-px grid make E(v1, v2, v3) exact in float64: decide the winding as you compute "
        "the edge tests, in float64"
    )


def _constant_mistakes(name: str, masked: bool) -> list[Mistake]:
    def nothing(case):
        return np.zeros((len(case.triangles), case.size[1], case.size[0]), dtype=bool)

    def everything(case):
        return _masks(case) if masked else ~nothing(case)

    what = "returns False for every centre" if name == "covers" else "returns an empty image"
    return [
        Mistake("covers nothing", f"your function never covers anything: it {what} of every "
                "triangle (a placeholder such as `return False` left in, or "
                f"{CONSTANT_TESTS['False']}?)", gives=nothing),
        Mistake("covers everything", "your function covers every pixel it is asked about, "
                "inside the triangle or not (a placeholder such as `return True` left in, or "
                f"{CONSTANT_TESTS['True']}?)", gives=everything),
    ]  # fmt: skip


def _rule(masked: bool):
    def gives(case, owns=cov.TOP_LEFT, winding="both", at="centres", vertices="snapped"):
        if winding == "ties as given":
            images = _ties_as_given(case, owns, at, vertices)
        else:
            images = cov.rule_images(case, owns=owns, winding=winding, at=at, vertices=vertices)
        return images & _masks(case) if masked else images

    return gives


#: The tie rule a counter-clockwise triangle gets from a student who accepts both windings
#: but decides a tie by the edge as given (v1→v2, ...): every edge runs the other way round.
_FLIPPED = {"top": "bottom", "bottom": "top", "left": "right", "right": "left"}


def _ties_as_given(case, owns, at, vertices) -> np.ndarray:
    """Both windings covered, ties decided by the unoriented edges (r64 01-2)."""
    flipped = frozenset(_FLIPPED[k] for k in owns)
    return np.array([
        cov.rule_image(case, xy, owns=flipped if cov.area2(xy) < 0 else owns, at=at,
                       vertices=vertices)
        for xy in case.triangles
    ])  # fmt: skip


def _one_winding_mirrored(ccw: bool):
    """r428 H2: the top-left rule on one winding, a bottom-left rule on the other (a y-up
    habit: E negated for the other winding and the rule mirrored with it)."""

    def images(case):
        bottom_left = frozenset({"bottom", "left"})
        return np.array([
            cov.rule_image(case, xy, owns=bottom_left if (cov.area2(xy) < 0) == ccw else cov.TOP_LEFT)
            for xy in case.triangles
        ])  # fmt: skip

    return images


def _one_winding_words(ccw: bool) -> str:
    wrong, right = ("counter-clockwise", "clockwise") if ccw else ("clockwise", "counter-clockwise")
    sign = "<" if ccw else ">"
    return (
        f"your coverage follows a bottom-left rule on {wrong} triangles only (E(v1, v2, v3) "
        f"{sign} 0); {right} ones follow the top-left rule: you mirror the tie rule with the "
        "winding (a y-up habit?), but the rule is one for both windings. Orient the triangle "
        "first (swap two vertices, or negate every E), then apply the one top-left rule to the "
        "oriented edges"
    )


def _ties_as_given_words(args, expected, got) -> str:
    return (
        "you accept both windings, but decide a centre on an edge by the edge as given (v1→v2, "
        "v2→v3, v3→v1): for a counter-clockwise triangle those run the other way round, so "
        "every tie goes the wrong way there; orient the triangle first, then apply the tie "
        "rule to the oriented edges"
    )


# -- each mistake's own example (r85 01-1: the corner and transposed words ended with "For
# example, … lies exactly on edge v1→v2: the top-left rule covers it", a tie that has nothing
# to do with either mistake) ---------------------------------------------------------------
#: How a mistake's words begin their own example: :func:`compose` then adds no other.
OWN_EXAMPLE = ". For example, "


def _first_wrong(args, expected, got):
    """(case, k, e, g): the first triangle whose image is wrong, with the student's image as
    given (None when its shape is not the expected one's)."""
    (case,) = args
    k = cov.wrong_triangle(got, expected)
    g = np.asarray(got[k], dtype=bool)
    return case, k, expected[k], (g if g.shape == expected[k].shape else None)


def _own_example(text: str, describe):
    """Words: ``text``, then an example of this very mistake: ``describe(case, xy, e, g, i,
    j)`` -> (sentence, ties) for a wrong pixel (i, j), or None where the pixel does not show
    the mistake; the sentence with the fewest points on an edge is chosen. Where no pixel
    shows it (a combination of mistakes), ``text`` alone, and :func:`compose` adds the usual
    example."""

    def words(args, expected, got) -> str:
        try:
            case, k, e, g = _first_wrong(args, expected, got)
        except (TypeError, ValueError, IndexError):  # an answer of another form
            return text
        if g is None:
            return text
        said = [describe(case, case.triangles[k], e, g, int(i), int(j))
                for i, j in np.argwhere(g != e)]  # fmt: skip
        said = sorted((ties, n, t) for n, (t, ties) in enumerate(x for x in said if x))
        if not said:
            return text
        tri = "" if "v1, v2, v3 = " in said[0][2] else cov.which_triangle(case, k)
        missing, extra = int((e & ~g).sum()), int((g & ~e).sum())
        return f"{text}{OWN_EXAMPLE}{tri}{said[0][2]} ({missing} pixel(s) missing, {extra} extra)"

    return words


def _centre(case, i: int, j: int, ox: float = 0.5, oy: float = 0.5) -> np.ndarray:
    return np.array([case.origin[0] + j + ox, case.origin[1] + i + oy], dtype=float)


def _yours(covered) -> str:
    return "your function covered it" if covered else "your function left it uncovered"


def _sampled_at(ox: float, oy: float):
    """A pixel sampled at (j + ox, i + oy), not its centre: the two points' verdicts."""

    def describe(case, xy, e, g, i, j):
        c, s = _centre(case, i, j), _centre(case, i, j, ox, oy)
        return _point_instead(xy, e, g, i, j, c, s, "sampled")

    return describe


def _moved_vertices(how: str):
    """Vertices rounded (or truncated) to whole pixels: the triangle the student filled."""

    def describe(case, xy, e, g, i, j):
        v = cov.MOVES[how](xy)
        c = _centre(case, i, j)
        if bool(cov.covered(xy, c, vertices=how)[0]) != g[i, j]:
            return None
        where = cov.where_point(xy, c), cov.where_point(v, c)
        vs = ", ".join(cov.point(q) for q in xy)
        return (f"v1, v2, v3 = {vs} become {', '.join(cov.point(q) for q in v)}; the centre "
                f"{cov.point(c)} of pixel (row {i}, col {j}) lies {where[0]}, but {where[1]} "
                f"of the {how} triangle, and {_yours(g[i, j])}", cov.ties_of(*where))  # fmt: skip

    return describe


def _mirrored_pixel(case, xy, e, g, i, j, other: tuple[int, int], what: str):
    """The student's [i, j] holds the verdict of pixel ``other``: the two pixels' verdicts."""
    oi, oj = other
    if not (0 <= oi < e.shape[0] and 0 <= oj < e.shape[1]) or e[oi, oj] != g[i, j]:
        return None
    c, d = _centre(case, i, j), _centre(case, oi, oj)
    where = cov.where_point(xy, c), cov.where_point(xy, d)
    state = "covered" if e[i, j] else "not covered"
    other_state = "covered" if e[oi, oj] else "not covered"
    return (f"pixel (row {i}, col {j}), centre {cov.point(c)}, lies {where[0]}: it is {state}; "
            f"your image's [{i}, {j}] holds {what} (row {oi}, col {oj}, centre {cov.point(d)}, "
            f"{where[1]}: {other_state})", cov.ties_of(*where))  # fmt: skip


def _transposed_pixel(case, xy, e, g, i, j):
    return _mirrored_pixel(case, xy, e, g, i, j, (j, i), "the pixel across the diagonal")


def _flipped_pixel(case, xy, e, g, i, j):
    return _mirrored_pixel(case, xy, e, g, i, j, (e.shape[0] - 1 - i, j),
                           "the pixel in the mirrored row")  # fmt: skip


#: r347 3: −E (E(b, a, p)) under the right tie test gives a bottom-right rule's very coverage.
NEGATED_E = (
    "; an edge function returning −E (a and b the other way round) under the conventions' "
    'tie test gives this very coverage: if your tie test is right, run ex.check("edge_function", '
    "edge_function)"
)


def _owns_words(owns) -> str:
    words = cov.owns_words(owns)
    return words + NEGATED_E if owns == frozenset({"bottom", "right"}) else words


#: r420 S1: fill's words for a mistake of covers (the tie rule, the winding) said where it is.
IN_COVERS = " (in `covers`, if `fill` calls it: the 1.1 check names it too)"


def _in_covers(words, fill: bool):
    if not fill:
        return words
    if callable(words):
        return lambda *a: words(*a) + IN_COVERS
    return words + IN_COVERS


def _rule_knobs(masked: bool, corners: bool) -> Knobs:
    knobs = {
        "owns": [Slip(cov.owns_kind(o), _owns_words(o), o) for o in cov.owns_variants()],
        "winding": [
            Slip("ties by the edges as given", _ties_as_given_words, "ties as given"),
            Slip("one winding only", _winding_words, "clockwise only"),
            Slip("one winding only", lambda *a: _winding_words(*a, which="clockwise"),
                 "counter-clockwise only"),
        ],
        "vertices": [
            Slip("vertices rounded", _own_example(
                "you rounded the vertices to whole pixels: a vertex keeps its position, "
                "snapped to the 1/256-px grid only", _moved_vertices("rounded")), "rounded"),
            Slip("vertices truncated", _own_example(
                "you truncated the vertices to whole pixels (int()): a vertex keeps its "
                "position, snapped to the 1/256-px grid only", _moved_vertices("truncated")),
                "truncated"),
        ],
    }  # fmt: skip
    for name in ("owns", "winding"):
        knobs[name] = [Slip(k.kind, _in_covers(k.words, corners), k.value) for k in knobs[name]]
    if corners:
        knobs["at"] = [
            Slip("pixel corners", _own_example(
                "your coverage is the triangle sampled at pixel corners (j, i) instead of the "
                "pixel centres (j + 0.5, i + 0.5)", _sampled_at(0.0, 0.0)), "corners"),
            # r64 01-1: half a pixel off in one axis was sent to the top-left rule in covers
            Slip("half a pixel off in x", _own_example(
                "your column j is sampled at x = j, not at its centre x = j + 0.5 (the rows "
                "are right: y = i + 0.5)", _sampled_at(0.0, 0.5)), "x at corners"),
            Slip("half a pixel off in y", _own_example(
                "your row i is sampled at y = i, not at its centre y = i + 0.5 (the columns "
                "are right: x = j + 0.5)", _sampled_at(0.5, 0.0)), "y at corners"),
        ]  # fmt: skip
    return Knobs(_rule(masked), knobs, most=2)


def _mirrored(kind: str, words, flip) -> Mistake:
    return Mistake(kind, words, gives=lambda case: np.array([flip(e) for e in _expected(case)]))


TRANSPOSED = (
    "your image is transposed: its [i, j] holds the pixel in row j and column i. An image is "
    "indexed [row, column] = [y, x]: np.zeros((height, width)), and out[i, j] is the pixel "
    "whose centre is (x, y) = (j + 0.5, i + 0.5)"
)
UPSIDE_DOWN = (
    "your image is upside down: row i holds the pixels whose centres have y = i + 0.5, with y "
    "pointing down (row 0 at the top), so do not flip the rows (height − 1 − i)"
)
SWAPPED = (
    "your coverage is the rule's mirrored across the diagonal: x and y are swapped somewhere. A "
    "point is (x, y) = (p[0], p[1]), x to the right, y down, and so is each vertex"
)


def _transposed_and_wrong(args, expected, got) -> bool:
    g = got if isinstance(got, np.ndarray) else None
    return g is not None and g.shape == expected.shape[:1] + expected.shape[:0:-1] != expected.shape


def _transposed_words(args, expected, got) -> str:
    shape = expected.shape[1:]
    return (
        f"your image has shape {shape[::-1]} = (width, height): arrays are [row, col], so an "
        f"image is (height, width) = {shape}, np.zeros((height, width)), its row i the pixels "
        "whose centres have y = i + 0.5 and its column j those with x = j + 0.5"
    )


# -- r347: loops that skip a border, a box one short, a mirror, other sampling points, tolerances
#: The sides of an image a loop may skip, and how many rows or columns (range(1, n), range(n - 1),
#: range(n - 2)): (top, bottom, left, right).
_BANDS = sorted(
    ((t, b, lft, r) for t in range(3) for b in range(3) for lft in range(3) for r in range(3)),
    key=sum,
)[1:]


def _banded(e: np.ndarray, band) -> np.ndarray:
    t, b, lft, r = band
    out = e.copy()
    out[:t], out[out.shape[0] - b :], out[:, :lft], out[:, out.shape[1] - r :] = 0, 0, 0, 0
    return out


def _skipped_band(args, expected, got):
    """The fewest border rows and columns (top, bottom, left, right) whose pixels, all left
    out, turn the rule's images into the student's (the rest right), or None. (A triangle
    wholly inside them leaves an empty image: :data:`_always` names it only where every
    failing case fits.)"""
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return None
    for band in _BANDS:
        if all(np.array_equal(_banded(e, band), g) for e, g in zip(expected, got)):
            return band
    return None


def _band_words(args, expected, got) -> str:
    (case,) = args
    w, h = case.size
    t, b, lft, r = _skipped_band(args, expected, got)

    def lines(n, first, what, total):
        if n == 0:
            return []
        rng = f"range(1, {total})" if first else f"range({total} - 1)"
        if n == 2:
            rng = f"range(2, {total})" if first else f"range({total} - 2)"
        where = ("the first" if first else "the last") + (f" {n} {what}s" if n > 1 else f" {what}")
        index = 0 if first else (h if what == "row" else w) - 1
        name = f"{what} {index} ({where})" if n == 1 else where
        return [(name, rng)]

    parts = (lines(t, True, "row", "height") + lines(b, False, "row", "height")
             + lines(lft, True, "column", "width") + lines(r, False, "column", "width"))  # fmt: skip
    names = " and ".join(n for n, _ in parts)
    loops = " or ".join(f"`{g}`" for _, g in parts)
    return (
        f"your loop skips {names} of the image: every pixel there is False, the rest of the "
        f"image is right ({int((expected & ~got).sum())} pixel(s) missing there). A loop "
        f"such as {loops} leaves it out: `range(n)` runs over 0 … n − 1, every row "
        "(range(height)) and every column (range(width)) of the image"
    )


def _short_sides(args, expected, got):
    (case,) = args
    return boxes.short_sides(case, expected, got)


#: r352 2: the words for a box one short at its first row or column, or its last.
BOX_SHORT_START = (
    "your loop over the bounding box misses its {sides}: a pixel whose centre {centre} lies "
    "inside can have {cond} ({ceil} skips it, round() too where the fraction is ½ or more); "
    "start at {floor} (clamped to 0)"
)
BOX_SHORT = (
    "your bounding box stops one pixel short at the {sides}: the last column (row) whose "
    "centre the triangle may cover is ceil(x_max) − 1 (ceil(y_max) − 1), so the loop is "
    "range(floor(x_min), ceil(x_max)) with its end exclusive (clamped to the image), not "
    "range(…, ceil(x_max) − 1) (nor floor(x_max), round(x_max) or floor(x_max − 0.5), the "
    "last centre's column, as an exclusive end)"
)


def _box_short_words(args, expected, got) -> str:
    """Which sides of the box the student's loop misses, over every triangle of the case, and
    one pixel of them (:func:`.coverage_boxes.short_sides`)."""
    found = [any(t[n] for t in _short_sides(args, expected, got)) for n in range(4)]
    top, bottom, left, right = found
    parts = []
    if left or top:
        both = left and top
        parts.append(BOX_SHORT_START.format(
            sides=" and its ".join(s for s, f in (("first column", left), ("first row", top)) if f),
            centre="(j + ½, i + ½)" if both else ("j + ½" if left else "i + ½"),
            cond="j < x_min or i < y_min" if both else ("j < x_min" if left else "i < y_min"),
            ceil="ceil(min)" if both else ("ceil(x_min)" if left else "ceil(y_min)"),
            floor="floor(x_min) and floor(y_min)" if both else (
                "floor(x_min)" if left else "floor(y_min)"),
        ))  # fmt: skip
    if right or bottom:
        sides = " and the ".join(s for s, f in (("right", right), ("bottom", bottom)) if f)
        parts.append(BOX_SHORT.format(sides=sides))
    return _own_example("; and ".join(parts), _box_side_pixel)(args, expected, got)


def _box_side_pixel(case, xy, e, g, i, j):
    """A pixel the short box leaves out: which side of the box, and the box's formula there."""
    if not e[i, j] or g[i, j]:
        return None
    w, h = case.size
    r0, r1, c0, c1 = boxes.box(case, xy)
    x_min, y_min = (np.asarray(xy, dtype=float) - case.origin).min(axis=0)
    x_max, y_max = (np.asarray(xy, dtype=float) - case.origin).max(axis=0)
    sides = (
        (j == c0, f"first column is floor(x_min) = floor({cov.fmt(x_min)}) = {c0}"),
        (i == r0, f"first row is floor(y_min) = floor({cov.fmt(y_min)}) = {r0}"),
        (j == c1 - 1 < w, f"last column is ceil(x_max) − 1 = ceil({cov.fmt(x_max)}) − 1 = {j}"),
        (i == r1 - 1 < h, f"last row is ceil(y_max) − 1 = ceil({cov.fmt(y_max)}) − 1 = {i}"),
    )
    side = next((words for on, words in sides if on), None)
    if side is None:
        return None
    c = _centre(case, i, j)
    where = cov.where_point(xy, c)
    return (f"the box's {side}; pixel (row {i}, col {j}), centre {cov.point(c)}, lies {where}: "
            "the rule covers it, your image leaves it uncovered", cov.ties_of(where))  # fmt: skip


#: r352 1: a box clamped at its upper end only passed (the one case out at the top covered
#: every pixel, so the wrapped writes were right there).
WRAPPED = (
    "your bounding box is not clamped at 0: a negative row/column index wraps to the other "
    "side of the image in numpy (image[-1] is the last row), so the box's rows above the image "
    "(columns left of it) are written into its last rows (columns): start the loop at "
    "max(0, floor(y_min)) (max(0, floor(x_min)))"
)


def _wrapped_pixel(case, xy, e, g, i, j):
    """Pixel [i, j] holds the verdict of a row or column of the box outside the image."""
    si, sj = boxes.wrapped_source(case, xy, i, j)
    w, h = case.size
    if (si >= 0 and sj >= 0) or si == h or sj == w:
        return None
    s, c = _centre(case, si, sj), _centre(case, i, j)
    if bool(cov.covered(xy, s)[0]) != g[i, j]:
        return None
    where = cov.where_point(xy, s), cov.where_point(xy, c)
    state = "covered" if g[i, j] else "not covered"
    return (f"your image's [{i}, {j}] holds the verdict of the box's row {si}, column {sj} "
            f"(centre {cov.point(s)}, {where[0]}: {state}), since [{si}, {sj}] is [{i}, {j}] "
            f"in numpy; pixel [{i}, {j}] itself, centre {cov.point(c)}, lies {where[1]}: "
            f"{'covered' if e[i, j] else 'not covered'}",
            cov.ties_of(*where))  # fmt: skip


def _box_raised(args, error: str) -> str:
    """r352 3: an index outside the image (a box clamped at its lower end only) was told the
    IndexError alone."""
    if "IndexError" not in error:
        return ""
    (case,) = args
    w, h = case.size
    return (f"; an index outside the image ({w} × {h} here, width × height): clamp the box to "
            f"the image (0..width−1, 0..height−1), range(max(0, floor(y_min)), min(height, "
            "ceil(y_max))) and the same in x")  # fmt: skip


X_MIRRORED = (
    "your image is mirrored left–right: column j holds the pixels whose centres have "
    "x = j + 0.5, x pointing right (column 0 at the left), so do not flip the columns "
    "(width − 1 − j)"
)

#: Sampling points a fill may take for pixel (i, j) instead of its centre (r347 2, 3): kind,
#: words.
OFFSETS = {
    (1.0, 1.0): ("sampled at (j + 1, i + 1)", "your pixel (row i, col j) is sampled at (j + 1, "
                 "i + 1), its bottom-right corner, not its centre (j + 0.5, i + 0.5) (half a "
                 "pixel added twice?)"),
    (0.5, 1.0): ("sampled at y = i + 1", "your row i is sampled at y = i + 1, the pixel's "
                 "bottom side, not at its centre y = i + 0.5 (the columns are right: x = j + 0.5)"),
    (1.0, 0.5): ("sampled at x = j + 1", "your column j is sampled at x = j + 1, the pixel's "
                 "right side, not at its centre x = j + 0.5 (the rows are right: y = i + 0.5)"),
    (-0.5, -0.5): ("sampled at (j − 0.5, i − 0.5)", "your pixel (row i, col j) is sampled at "
                   "(j − 0.5, i − 0.5), the centre of the pixel above and to the left, not its "
                   "own (j + 0.5, i + 0.5): half a pixel taken off instead of added"),
}  # fmt: skip


def _sampling_mistakes() -> list[Mistake]:
    return [
        Mistake(kind, _own_example(words, _sampled_at(ox, oy)),
                gives=lambda case, at=(ox, oy): cov.rule_images(case, at=at))
        for (ox, oy), (kind, words) in OFFSETS.items()
    ]  # fmt: skip


#: r420 H5: other constant sampling points (j + ox, i + oy) a fill may take, on a quarter-pixel
#: grid (an MSAA pattern's offset, (j + ¼, i + ¼), was told "a tiny step off its centre"); the
#: named ones (:data:`OFFSETS`, the corners) come first in the table.
_QUARTERS = [(ox / 4, oy / 4) for ox in range(-2, 5) for oy in range(-2, 5)]
_OTHER_OFFSETS = [
    o for o in _QUARTERS
    if o != (0.5, 0.5) and o not in OFFSETS and o not in ((0.0, 0.0), (0.0, 0.5), (0.5, 0.0))
]  # fmt: skip


def _offset_mistakes() -> list[Mistake]:
    """r420 H5: one constant sampling point off the centre, each a mistake the checker runs
    (named where it gives every failing answer, or most: :mod:`.diagnosis`)."""

    def words(ox, oy):
        return _own_example(
            f"your pixel (row i, col j) is sampled at (j + {cov.fmt(ox)}, i + {cov.fmt(oy)}), "
            "not at its centre (j + 0.5, i + 0.5): the conventions sample a pixel at its centre "
            "(an MSAA sample's offset, or one measured from another point, used for the "
            "pixel?)",
            _sampled_at(ox, oy),
        )

    return [Mistake("sampled off the centre", words(ox, oy),
                    gives=lambda case, at=(ox, oy): cov.rule_images(case, at=at))
            for ox, oy in _OTHER_OFFSETS]  # fmt: skip


def _centred_words(args, expected, got) -> str:
    return _own_example(
        "you moved each vertex to the nearest pixel centre (round(v − 0.5) + 0.5): a vertex "
        "keeps its position, snapped to the 1/256-px grid only",
        _moved_vertices("centred"),
    )(args, expected, got)


def _owns_right_running(a, b) -> bool:
    """A tie test that forgot 'exactly horizontal': every edge running right owns its ties."""
    return bool(b[1] < a[1] or b[0] > a[0])


RIGHT_RUNNING = (
    "your tie test counts every edge that runs to the right as a top edge, the right edges "
    "running down and to the right too: a top edge is one exactly horizontal (y the same at "
    "both ends), its interior below it"
)


def _owns_left_running(a, b) -> bool:
    """r453 H4: a "left" edge taken for one that runs to the left (b.x < a.x)."""
    return bool(b[0] < a[0] or (b[1] == a[1] and b[0] > a[0]))


LEFT_RUNNING = (
    "your tie test takes an edge that runs to the left (b.x < a.x) for a left edge: a left edge "
    "is one with the interior to its right as seen on screen (y down), and the way an edge runs "
    "in x does not decide that (work out which way a left edge of the positively oriented "
    "triangle runs)"
)


def _owns_vertical_left(a, b) -> bool:
    """r494 H8: only a vertical edge taken for a left edge (top edges right)."""
    return bool((b[0] == a[0] and b[1] < a[1]) or (b[1] == a[1] and b[0] > a[0]))


VERTICAL_LEFT = (
    "your tie test takes only a vertical edge for a left edge: a left edge is any edge with "
    "the interior to its right as seen on screen (y down), a sloped one too (work out which "
    "way the sloped left edges of the positively oriented triangle run)"
)


def _tiny(xy) -> bool:
    return 0 < abs(cov.area2(xy)) < 1.0


def _float32_exact(case) -> bool:
    """Near the origin and short: float32 would give the rule's answer here, so an E taken
    as 0 that is not is a tolerance, not float32's rounding (:func:`_float32_fits`); a near
    tie (:func:`.near_ties.float32_safe`) is drawn so, whatever its size."""
    if float32_safe(case):
        return True
    xy = np.asarray(case.triangles, dtype=float)
    extent = float(np.abs(xy - xy[:, :1]).max())
    return float(np.abs(xy).max()) < 1e4 and extent < 1000


def _area_tolerance_fits(args, expected, got) -> bool:
    """Every wrong triangle is a tiny one (0 < |E(v1, v2, v3)| < 1 px²) left empty, the rest
    right: a zero-area test with a tolerance (abs(E) < 1e-3)."""
    (case,) = args
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return False
    if not (_float32_exact(case) or case.label.startswith(SLIVER32)):  # r438: its E is 0.043
        return False
    wrong = [k for k in range(len(got)) if not np.array_equal(got[k], expected[k])]
    return bool(wrong) and all(_tiny(case.triangles[k]) and not got[k].any() for k in wrong)


def _area_tolerance_words(args, expected, got) -> str:
    (case,) = args
    k = cov.wrong_triangle(got, expected)
    area = cov.fmt(cov.area2(case.triangles[k]))
    # r420 H2: the tolerance quoted is the case's own (a fixed "1e-3" contradicted E = 0.284)
    return (
        f"you covered nothing of a triangle whose E(v1, v2, v3) = {area} px² is tiny but not "
        f"0: a zero-area test with a tolerance (abs(E) below a bound above {area.lstrip('-')} "
        "px²) takes it for a flat one. The vertices are on the 1/256-px grid, so E is exact: "
        "only E == 0 is zero area"
    )


def _edge_tolerance(args, expected, got) -> float | None:
    """The least tolerance ε such that E within ε of 0 taken as 0 (a tie) gives the student's
    every image of this case, if it is below 0.1 px² and changes something, else None."""
    (case,) = args
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return None
    if not (_float32_exact(case) or case.label.startswith(LONG_NEAR_TIES)):
        return None
    values = [cov.centre_values(case, xy)[0] for xy in case.triangles]
    eps = 0.0
    for k, e in enumerate(values):
        wrong = e[:, got[k] != expected[k]]
        if wrong.size:
            small = np.where(wrong != 0, np.abs(wrong), np.inf).min(axis=0)
            eps = max(eps, float(small.max()))
    if not 0 < eps < 0.1:
        return None
    for k, xy in enumerate(case.triangles):
        if not np.array_equal(_tolerant_image(case, xy, np.nextafter(eps, 1)), got[k]):
            return None
    return eps
    # r428: ε relative to the triangle's area (1e-9 · E(v1, v2, v3)), on a case of several
    areas = [abs(cov.area2(xy)) for xy in case.triangles]
    rel = max((float(np.where(e[:, got[k] != expected[k]] != 0, np.abs(e[:, got[k] != expected[k]]),
                              np.inf).min(axis=0).max()) / areas[k]
               for k, e in enumerate(values) if (got[k] != expected[k]).any()), default=0.0)  # fmt: skip
    for k, xy in enumerate(case.triangles):
        if not np.array_equal(_tolerant_image(case, xy, np.nextafter(rel * areas[k], 1)), got[k]):
            return None
    return eps


def _tolerant_image(case, xy, eps: float) -> np.ndarray:
    w, h = case.size
    if cov.area2(xy) == 0:
        return np.zeros((h, w), dtype=bool)
    rows, cols = np.indices((h, w))
    points = np.stack([cols + case.origin[0] + 0.5, rows + case.origin[1] + 0.5], -1)
    e, kinds, area, v = cov._edge_data(np.asarray(xy, dtype=float), points.reshape(-1, 2),
                                       "snapped")  # fmt: skip
    e = np.where(np.abs(e) < eps, 0.0, e)
    return cov._apply((e, kinds, area, v), cov.TOP_LEFT, "both").reshape(h, w)


def _edge_tolerance_words(args, expected, got, eps=None) -> str:
    eps = _edge_tolerance(args, expected, got) if eps is None else eps
    return (
        f"you take an edge function within {cov.fmt(eps)} px² of 0 for 0: a tolerance in the "
        f"edge test (abs(E) < ε with ε above {cov.fmt(eps)} px², or ε relative to the "
        "triangle's area), so a centre that close to an edge is decided by the tie rule, though "
        "it lies strictly on one side. On the 1/256 grid E is exact (vertices on the 1/256-px "
        "grid, centres on the half-pixel grid): a centre off the edge has |E| ≥ 2^-16 px², "
        "so compare E with 0 exactly"
    )


def _always(*args) -> bool:
    return True


#: r505 H9: the loop over the edges stops before the third (told "none of the typical
#: mistakes" with 32 extra pixels)
EDGE_LEFT_OUT = (
    "you test two edges only: the edge from v3 back to v1 is never tested (a loop over "
    "((v1, v2), (v2, v3)), or zip(xy, xy[1:]), stops before it), so centres outside it are "
    "covered too: test all three, v1→v2, v2→v3 and v3→v1"
)


def _r347_mistakes(name: str, masked: bool) -> list[Mistake]:
    """r347's mistakes that no knob reproduces (singles: they do not combine)."""

    def masks(images, case):
        return images & _masks(case) if masked else images

    table = [
        Mistake("right-running edges own their ties", RIGHT_RUNNING,
                gives=lambda case: masks(cov.rule_images(case, owns=_owns_right_running), case)),
        Mistake("left-running edges own their ties", _in_covers(LEFT_RUNNING, not masked),
                gives=lambda case: masks(cov.rule_images(case, owns=_owns_left_running), case)),
        Mistake("vertical left edges only", _in_covers(VERTICAL_LEFT, not masked),
                gives=lambda case: masks(cov.rule_images(case, owns=_owns_vertical_left), case)),
        Mistake("an edge left out", _in_covers(EDGE_LEFT_OUT, not masked),
                gives=lambda case: masks(cov.rule_images(case, skip=2), case)),
        # r347: named only where they give every failing case they must (a fit on one case
        # alone is a coincidence: a point sampled off the centre left a sliver empty)
        Mistake("zero area by a tolerance", _area_tolerance_words, fits=_area_tolerance_fits,
                must_fit=_always, unread="float32"),  # r438: float32's E(v1, v2, v3) of a sliver
        Mistake("edges by a tolerance", _edge_tolerance_words,
                fits=lambda *a: _edge_tolerance(*a) is not None,
                must_fit=lambda args, *_: _float32_exact(args[0])),
        Mistake("vertices moved to pixel centres", _centred_words,
                gives=lambda case: masks(cov.rule_images(case, vertices="centred"), case)),
        *(Mistake("tie rule mirrored for one winding", _one_winding_words(ccw),
                  gives=lambda case, ccw=ccw: masks(_one_winding_mirrored(ccw)(case), case))
          for ccw in (True, False)),
    ]  # fmt: skip
    if name == "fill":
        table += [
            Mistake("border skipped", _band_words,
                    fits=lambda *a: _skipped_band(*a) is not None, must_fit=_always),
            # r352 1, 2: a box clamped at its upper end only; one short at any side
            Mistake("box not clamped at 0", _own_example(WRAPPED, _wrapped_pixel),
                    gives=lambda case: boxes.wrapped_images(case, _expected(case))),
            Mistake("bounding box one short", _box_short_words,
                    fits=lambda *a: _short_sides(*a) is not None, must_fit=_always),
            _mirrored("mirrored left-right", _own_example(X_MIRRORED, _x_flipped_pixel),
                      lambda e: e[:, ::-1]),
            *_sampling_mistakes(),
        ]  # fmt: skip
    return table


def _edge_slip_mistakes(masked: bool) -> list[Mistake]:
    """r420 H1, H5: an unsigned or two-anchor ``edge_function`` under ``covers``, one edge's
    test alone (:mod:`.edge_slips`); the words send the student to the helper's check."""

    def gives(kind):
        def images(case):
            out = edge_slips.images(case, kind)
            return out & _masks(case) if masked else out

        return images

    def remainder(args, expected, got) -> bool:
        """r438 H1: λ3 = 1 − λ1 − λ2, whichever edge's λ is the remainder (the same on every
        triangle of the case)."""
        (case,) = args
        if not isinstance(got, np.ndarray) or got.shape != expected.shape:
            return False
        m = _masks(case) if masked else True
        return any(
            np.array_equal(got, np.array([edge_slips.remainder_image(case, xy, k)
                                          for xy in case.triangles]) & m)
            for k in range(3)
        )  # fmt: skip

    def slip(kind):  # r453 H1, H2
        def images(case):
            out = ps.slip_images(case, kind)
            return out & _masks(case) if masked else out

        return images

    return [
        *(Mistake(kind, edge_slips.WORDS[kind], gives=gives(kind)) for kind in edge_slips.WORDS),
        Mistake("λ as a remainder", edge_slips.REMAINDER, fits=remainder, must_fit=_always),
        Mistake("tie test parenthesised", _in_covers(ps.PRECEDENCE, not masked),
                gives=slip("precedence")),
        Mistake("third edge reversed", _in_covers(ps.THIRD_EDGE, not masked),
                gives=slip("third edge")),
    ]  # fmt: skip


def _nudged(args, expected, got):
    (case,) = args
    return boxes.nudged_direction(case, expected, got)


def _nudged_words(args, expected, got) -> str:
    """r352 3: which tiny step off the centre gives the student's images (the first that does:
    a case may not tell a step along x or y from a diagonal one)."""
    sx, sy = _nudged(args, expected, got)
    way = " and ".join(w for w in ({1: "right", -1: "left"}.get(sx), {1: "down", -1: "up"}.get(sy))
                       if w)  # fmt: skip
    x = {1: "j + 0.5 + 1e-6", -1: "j + 0.5 − 1e-6", 0: "j + 0.5"}[sx]
    y = {1: "i + 0.5 + 1e-6", -1: "i + 0.5 − 1e-6", 0: "i + 0.5"}[sy]
    # along x or y, a tie test by the other axis's direction alone gives the same pixels
    alike = "" if sx and sy else (
        f" (a tie test in `covers` that looks at the edge's {'y' if sx else 'x'} direction "
        "alone gives the same pixels: if `covers` passes its own check, it is the point)")  # fmt: skip
    return (
        "every pixel you get wrong has its centre exactly on an edge, and your images are the "
        f"rule's tested a tiny step off each centre (a step {way}, at ({x}, {y}), gives "
        "them): a centre on an edge then lands on the side the step takes it, and the tie "
        "rule never decides. Test the centre (j + 0.5, i + 0.5) itself: vertices and centres "
        f"are on the 1/256-px grid, so E is exact there{alike}"
    )


def _distance_mistakes(masks, after_step: bool = False) -> list[Mistake]:
    """r438 M1, M2, M3, H2: a tolerance on the distance to the edge's line (snapped to a tie,
    or one-sided), and a bias on the edges that do not own their ties (E − β ≥ 0), fitted on
    the long near ties (:mod:`.sample_steps`); float64 code only, every failing case. A
    distance where the code reads a length (:data:`LENGTHS`), else (``after_step``) only
    where no step off the centre gives the answer (a length written with ``** 0.5``)."""
    forms = {"bias": {"absolute": True, "one_sided": True}, "absolute": {"absolute": True},
             "distance": {"length": True}, "distance, one-sided": {"length": True, "one_sided": True},
             "area": {"per_area": True}}  # fmt: skip

    def fit(form):
        def found(args, expected, got):
            return steps.relative_tolerance(args[0], expected, got, masks(args[0]), **forms[form])

        return found

    def fits(form):
        def fitted(*a) -> bool:
            return fit(form)(*a) is not None

        return fitted

    def words(form):
        def said(args, expected, got):
            r = fit(form)(args, expected, got)
            if form == "bias":
                return steps.bias_words(args[0], r)
            if form == "absolute":
                return _edge_tolerance_words(args, expected, got, r)
            if form == "area":  # r453 M1: λ = E / area within ±ε
                return steps.area_words(args[0], r)
            return steps.distance_words(args[0], r, one_sided=form != "distance")

        return said

    kinds = {"absolute": "edges by a tolerance", "distance": "a tolerance on the distance to the edge",
             "distance, one-sided": "a tolerance on the distance to the edge",
             "bias": "a bias on the edges that do not own their ties",
             "area": "edges by a tolerance"}  # fmt: skip

    def span(form):
        def interval(args, expected, got):
            return steps.tolerance_range(args[0], expected, got, masks(args[0]), **forms[form])

        return interval

    # a distance takes a length: named where the code reads one (a step to the right of 1e-4
    # px gives the same images as a distance of 4e-5 px on every case)
    reads = {"distance": LENGTHS, "distance, one-sided": LENGTHS}
    if after_step:
        forms = {k: v for k, v in forms.items() if k in reads}
        reads = {}
    return [Mistake(kinds[form], words(form), fits=fits(form), only_whole=True, unread="float32",
                    parameter=span(form), reads=name)
            for form in forms for name in reads.get(form, (None,))]  # fmt: skip


#: The names a length |b − a| is computed with (r438: a distance tolerance reads one).
LENGTHS = ("hypot", "sqrt", "norm", "dist")


def _step_mistakes(masked: bool) -> list[Mistake]:
    """r428 WP1, WP2, M1: a relative tolerance on the edge function's products (named where
    the code reads ``isclose``, else only where it gives every failing case: float32 fails the
    far case too), and a point moved off the centre (:mod:`.sample_steps`)."""

    def masks(case):
        return _masks(case) if masked else np.ones_like(_masks(case))

    def tolerance(args, expected, got):
        return steps.relative_tolerance(args[0], expected, got, masks(args[0]))

    def step(args, expected, got):
        found = steps.stepped(args[0], expected, got, masks(args[0]))
        if found is not None and found[0] == steps.STEPS[0]:  # any step: its size is moot
            found = (None, *found[1:])
        if found is None and not masked:  # r352 3's exact ties, where the step's size is moot
            way = _nudged(args, expected, got)
            found = None if way is None else (None, *way)
        return found

    def tolerance_words(args, expected, got):
        return steps.tolerance_words(args[0], tolerance(args, expected, got))

    def step_words(args, expected, got):
        return steps.step_words(*step(args, expected, got), fill=not masked)

    kind = "a relative tolerance in the edge test"
    # float32 flips some long near ties as a step or a tolerance might: neither is named in
    # code that reads float32, nor (but isclose) where it does not give every failing case
    # (float32 fails the far case too; a step or a tolerance fitting one near tie alone is
    # a coincidence)
    return [
        Mistake(kind, tolerance_words, fits=lambda *a: tolerance(*a) is not None, reads="isclose"),
        *_distance_mistakes(masks),
        Mistake(kind, tolerance_words, fits=lambda *a: tolerance(*a) is not None,
                only_whole=True, unread="float32"),
        Mistake("a point a tiny step off the centre", step_words,
                fits=lambda *a: step(*a) is not None, only_whole=True, unread="float32"),
        *_distance_mistakes(masks, after_step=True),
    ]  # fmt: skip


def _at_vertices(args, expected, got) -> bool:
    """r428 H3: every wrong pixel has a vertex of its triangle at its centre."""
    (case,) = args
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return False
    wrong = [(k, i, j) for k in range(len(got)) for i, j in np.argwhere(got[k] != expected[k])]
    return bool(wrong) and all(
        (np.asarray(case.triangles[k]) == _centre(case, i, j)).all(axis=1).any()
        for k, i, j in wrong
    )


def _on_box_side(args, expected, got) -> bool:
    """r438 H3: every wrong pixel is one the rule covers, its centre on the left or top side
    of its triangle's bounding box (x = x_min or y = y_min): a box test with <= refused it."""
    (case,) = args
    if not isinstance(got, np.ndarray) or got.shape != expected.shape:
        return False
    wrong = [(k, i, j) for k in range(len(got)) for i, j in np.argwhere(got[k] != expected[k])]
    if not wrong or any(got[k][i, j] for k, i, j in wrong):
        return False
    lo = [np.asarray(xy, dtype=float).min(axis=0) for xy in case.triangles]
    return all(((_centre(case, i, j) == lo[k]).any()) for k, i, j in wrong)


ON_BOX_SIDE = (
    "every pixel you leave out that the rule covers has its centre on the left or top side of "
    "its triangle's bounding box (x = x_min or y = y_min): a bounding-box test that refuses "
    "p.x <= x_min (or p.y <= y_min)? A centre there lies on a left or top edge (or is a "
    "vertex of one), which owns it: a box test may refuse only what lies strictly outside, "
    "p.x < x_min, p.x > x_max (and likewise in y)"
)


AT_VERTICES = (
    "every pixel you get wrong has a vertex of its triangle at its centre: a special case for "
    "vertices (p equal to one of them: always covered, or never)? A vertex is decided by the "
    "rule like any other point: it lies on two edges, so it is covered only when both are top "
    "or left edges (E = 0 on each, and each owns its ties), as in the rest of the tie rule"
)


def _masked32(case: CoverageCase, masked: bool) -> np.ndarray:
    out = ps.slip_images(case, "float32 vertices")
    return out & _masks(case) if masked else out


def _x_flipped_pixel(case, xy, e, g, i, j):
    return _mirrored_pixel(case, xy, e, g, i, j, (i, e.shape[1] - 1 - j),
                           "the pixel in the mirrored column")  # fmt: skip


#: r438 M4: ``[[False] * width] * height`` holds one row object height times (told "never
#: covers anything" where the last row is empty).
ONE_ROW = (
    "every row of your image is the same, the rule's last row: a list of lists made with "
    "`[[False] * width] * height` holds one row object height times, so writing out[i][j] "
    "writes that column of every row, and the last row written wins. Make each row anew "
    "(`[[False] * width for _ in range(height)]`) or use `np.zeros((height, width), bool)`"
)


def _last_row_everywhere(case: CoverageCase) -> np.ndarray:
    e = _expected(case)
    return np.broadcast_to(e[:, -1:, :], e.shape).copy()


def mistakes(name: str) -> list:
    """The mistakes table of ``covers`` or ``fill``, most specific first."""
    masked = name == "covers"
    table = []
    if name == "fill":  # before "never covers anything", which it gives where the last row is empty
        table.append(Mistake("one row object", ONE_ROW, gives=_last_row_everywhere,
                             must_fit=_always))  # fmt: skip
    table += _constant_mistakes(name, masked)
    if name == "fill":
        table += [
            _mirrored("transposed", _own_example(TRANSPOSED, _transposed_pixel), lambda e: e.T),
            _mirrored("upside down", _own_example(UPSIDE_DOWN, _flipped_pixel), lambda e: e[::-1]),
        ]
    else:
        table.append(
            Mistake("transposed", SWAPPED, gives=lambda case: rule_swapped(case) & _masks(case))
        )
        table += _point_mistakes()
    table += _edge_slip_mistakes(masked)
    table += _r347_mistakes(name, masked)
    table.append(_rule_knobs(masked, corners=name == "fill"))
    if name == "fill":  # r352 3: after the tie rules, which it may equal on a case
        table.append(Mistake("a point a tiny step off the centre", _nudged_words,
                             fits=lambda *a: _nudged(*a) is not None, must_fit=_always,
                             unread="float32"))  # fmt: skip
    if name == "fill":
        table += _offset_mistakes()
    table += _step_mistakes(masked)
    table.append(Mistake("vertices decided apart", AT_VERTICES, fits=_at_vertices, symptom=True))
    table.append(Mistake("box side refused", ON_BOX_SIDE, fits=_on_box_side, symptom=True))
    table.append(Mistake("winding in float32", _winding32_words, gives=_winding32, reads="float32"))
    table.append(Mistake("vertices in float32", ps.float32_vertex_words, reads="float32",
                         gives=lambda case: _masked32(case, masked)))  # r453 M2  # fmt: skip
    table.append(Mistake("float32 plane form", plane32.WORDS, reads="float32",
                         fits=lambda a, e, g: plane32.fits(a[0], e, g, _tested(a[0], masked))))  # fmt: skip
    table.append(Mistake("float32", _float32_words, fits=_float32_fits, only_whole=True))
    if name == "fill":
        table.append(Mistake("transposed", _transposed_words, fits=_transposed_and_wrong))
    return table


#: r273 12-3: p moved by half a pixel and p's x and y swapped were told only a tie they broke.
PAST_P = (
    "you tested p + (0.5, 0.5), not p: p is already the point to test (a pixel's centre "
    "(j + 0.5, i + 0.5), or in the MSAA scene a sample's position), so adding half a pixel "
    "moves it to the next pixel's corner (sample offsets measured from the pixel's centre "
    "instead of its corner, or half a pixel added twice)"
)
P_SWAPPED = (
    "you tested the point (p[1], p[0]): x and y of p are swapped, the vertices are not. A "
    "point is (x, y) = (p[0], p[1]), x to the right, y down, as each vertex is"
)


def _point_mistakes() -> list[Mistake]:
    """Mistakes in the point ``covers`` tests: moved half a pixel past it, x and y swapped."""
    return [
        Mistake("tested past p", _own_example(PAST_P, _sampled_at(1.0, 1.0)),
                gives=lambda case: cov.rule_images(case, at="past p") & _masks(case)),
        Mistake("p swapped", _own_example(P_SWAPPED, _swapped_point),
                gives=lambda case: cov.rule_images(case, swap="points") & _masks(case)),
        # r453 WP1, H3: the centre of p's pixel; p − (½, ½), a corner
        Mistake("p's pixel centre", _own_example(ps.PIXEL_CENTRE, ps.describe_pixel_centre),
                gives=lambda case: ps.pixel_centre_images(case) & _masks(case)),
        Mistake("tested before p", _own_example(ps.BEFORE_P, _sampled_at(0.0, 0.0)),
                gives=lambda case: cov.rule_images(case, at="corners") & _masks(case)),
    ]  # fmt: skip


def _swapped_point(case, xy, e, g, i, j):
    """Pixel (i, j) tested at its centre's mirror (y, x): the two points' verdicts."""
    c = _centre(case, i, j)
    return _point_instead(xy, e, g, i, j, c, c[::-1], "tested")


def _point_instead(xy, e, g, i, j, c, s, verb: str):
    """Pixel (i, j) decided at the point ``s`` instead of its centre ``c``: the two points'
    verdicts, or None where the student's answer is not the one ``s`` gives (another mistake
    decides this pixel)."""
    if bool(cov.covered(xy, s)[0]) != g[i, j]:
        return None
    rule = "covers it" if e[i, j] else "leaves it uncovered"
    where = cov.where_point(xy, c), cov.where_point(xy, s)
    return (f"the centre {cov.point(c)} of pixel (row {i}, col {j}) lies {where[0]}, so the "
            f"rule {rule}; you {verb} {cov.point(s)}, which lies {where[1]}, and "
            f"{_yours(g[i, j])}", cov.ties_of(*where))  # fmt: skip


def rule_swapped(case: CoverageCase) -> np.ndarray:
    return cov.rule_images(case, swap=True)


# -- words and drawings -------------------------------------------------------------------------
def explain(args, expected, got) -> str:
    (case,) = args
    text, *_ = cov.head(case, got, expected)
    return text


#: r352 C: what may change only the centres on an edge, said as possibilities where no
#: typical mistake gives the answer (cell 0: "without guessing a cause").
TIE_CAUSES = {
    "covers": "a tie test that decides some edges' centres the other way, or the point tested "
    "a tiny step off p",
    "fill": "a tie test in `covers` that decides some edges' centres the other way (if "
    "`covers` passes its own check, it is not that), each pixel tested a tiny step off its "
    "centre, or a loop that misses some rows or columns",
}


def _differences_of(name: str):
    def words(args, expected, got) -> str:
        (case,) = args
        return cov.differences(case, got, expected, TIE_CAUSES[name])

    return words


def compose(head: str, words: str) -> str:
    """The mistake first, then the pixel that shows it; a placeholder alone (r64: the example
    of an answer that never changes told the top-left rule), and a mistake that gives its own
    example with it (:data:`OWN_EXAMPLE`, r85 01-1)."""
    if PLACEHOLDER in words or OWN_EXAMPLE in words:
        return words
    return f"{words}. For example, {head}" if words else head


#: The words every placeholder's explanation holds (:func:`compose` adds no rule to them).
PLACEHOLDER = "placeholder"


#: r420 H3, H4: the likeliest test behind a constant verdict, beside a placeholder.
CONSTANT_TESTS = {
    "False": "a test that no centre can pass (the triangle oriented the wrong way round, so "
    "that its interior is where E < 0: two vertices swapped where E(v1, v2, v3) > 0 instead "
    "of < 0)",
    "True": "a test that every centre passes (one edge's test instead of all three: a "
    "`return True` as soon as one edge passes, `any` for `all`, `or` for `and`)",
}


def constant(name: str):
    """The words for a ``covers`` that returns one value for every centre (the checker's
    first diagnosis, :mod:`.diagnosis`)."""

    def words(value) -> str:
        shown = short(value)
        if shown in ("True", "False"):
            what = "every centre of every triangle" if name == "covers" else "every triangle"
            verdict = ("covers every pixel it is asked about, inside the triangle or not"
                       if shown == "True" else "never covers anything")  # fmt: skip
            return (f"your function {verdict}: it returns {shown} for {what}, whatever its "
                    f"arguments (a {PLACEHOLDER} such as `return {shown}` left in, a "
                    f"`return` reached too early, or {CONSTANT_TESTS[shown]}?)")  # fmt: skip
        return constant_words(value)

    return words


#: Words that would name the kind of an edge, which the task asks to work out (r46 E3, r64):
#: on the first failing answers the edge is named by its vertices only.
HINTS = (
    (re.compile(r"(edge v\d→v\d(?: \(E\d\d: this triangle runs the other way\))?), a "
                r"(?:top|left|bottom|right) edge: the top-left rule "
                r"(covers it|leaves it uncovered)"),
     r"\1: the top-left rule \2 (which kind of edge is it, with y pointing down?)"),
    (re.compile(r"on edges (v\d→v\d) \((?:top|left|bottom|right)\) and (v\d→v\d) "
                r"\((?:top|left|bottom|right)\)"),
     r"on edges \1 and \2 (which kinds of edge, with y pointing down?)"),
)  # fmt: skip


def draw(ax, case, got):
    from .drawing import draw_coverage

    _, (c,), expected = case
    if got is None:
        return draw_coverage(ax, c, c.triangles[0], expected[0], None, None, None)
    if same_coverage(got, expected, None):  # r347 FIG: the whole mesh, its ties ringed
        from .drawing import draw_mesh

        ties = np.zeros(expected.shape[1:], dtype=bool)
        for xy in c.triangles:
            if cov.area2(xy) != 0:
                e = cov.centre_values(c, xy)[0]
                ties |= (e == 0).any(axis=0) & (e >= 0).all(axis=0)
        return draw_mesh(ax, c, expected, ties)
    _, k, pixel, edge = cov.head(c, got, expected)
    g = np.asarray(got[k])
    g = g if g.shape == expected[k].shape else g.T
    return draw_coverage(ax, c, c.triangles[k], expected[k], g, edge, pixel)


#: The package's top-left rule, a part of every coverage answer (r148 D12-5: the package's
#: internals counted as the student's work); not ``edge_function``, a tool of the same
#: module, so listed by name and not by module.
TIE_RULE_ANSWERS = tuple(
    PackageAnswer(f, what="the top-left rule, a part of this very answer")
    for f in (is_top_left, top_left_edges, passes)
)


def _exercise(name: str, cases, call, scene=None) -> Exercise:
    return Exercise(
        name, cases, convert=None, same=same_coverage, explain=explain,
        rule=_differences_of(name), mistakes=mistakes(name), draw=draw, scene=scene, call=call,
        answers=(PackageAnswer(rasterize), *TIE_RULE_ANSWERS), compose=compose,
        constant=constant(name),
        hints=HINTS,
        # expected_coverage (r14 09-1); the near ties' triangles and their expected centres
        # (r428: built by near_ties, whose functions a student's call must not pass unseen)
        reference=("teachraster.exercises.coverage", "teachraster.exercises.near_ties"),
        raised_words=_box_raised if name == "fill" else None,
        tool_note=_package_edge_function_note,
    )  # fmt: skip


def _uses_package_edge_function(fn) -> bool:
    """Does ``fn`` (or the ``edge_function`` of its module) call the package's edge_function?"""
    import inspect
    import types

    from ..core.edges import edge_function as package

    own = getattr(inspect.unwrap(fn), "__globals__", {}).get("edge_function")
    if own is package:
        return True
    if isinstance(own, types.FunctionType):  # the student's helper, or a wrapper of the package's
        return any(v is package for v in values_read(own, depth=2))
    return any(v is package for v in values_read(fn))


def _package_edge_function_note(fn) -> str | None:
    """r420 P1: the package's edge_function inside ``covers`` passed with no word (issue 30:
    the report must say so); it counts, the tie rule and the sides are the student's."""
    if not _uses_package_edge_function(fn):
        return None
    return ("your code calls the package's edge_function: that counts, the side and tie tests are "
            "yours, but write the helper yourself too (task 1.1) to learn it")  # fmt: skip


def covers_exercise() -> Exercise:
    return _exercise("covers", covers_cases, call_covers)


def fill_exercise() -> Exercise:
    from .picture_scenes import fill_scene

    return _exercise("fill", fill_cases, call_fill, fill_scene)
