"""Exercises ``barycentric(xy, p)`` and ``perspective(lam, w, f)`` (lesson 03).

Expected values come from the core (:func:`~teachraster.core.barycentrics.barycentric`;
:func:`~teachraster.core.interpolation.perspective_weights` with
:func:`~teachraster.core.interpolation.blend`). Every mistake below is a wrong solution the
checker runs itself (:mod:`.diagnosis`).
"""

from __future__ import annotations

import itertools
import re
import traceback

import numpy as np

from ..core.barycentrics import barycentric
from ..core.edges import edge_function
from ..core.interpolation import blend, perspective_weights
from ..core.plane_equations import attribute_plane, plane_equation, setup_matrix
from ..study.hardcases import CASES
from .answers import as_number, as_numbers, short
from .bary_shipped import patched_barycentric
from .cases import DRAWN, SEED, WINDOW, drawn_rng, proper_triangles
from .diagnosis import held_by_precision, near, scaled_mistake
from .exercise import Exercise, Mistake, PackageAnswer
from .package_answers import CHECKER_WORDS
from .scalars import centre_near, num, tri_words, vec
from .tolerance import TOL, all_close, close


# -- barycentric ------------------------------------------------------------------------------
def barycentric_cases():
    rng = np.random.default_rng(SEED + 1)
    out = []
    n_fixed = 2 * len(proper_triangles())
    for label, xy in proper_triangles():
        lo, hi = xy.min(axis=0), xy.max(axis=0)
        first, second = centre_near(xy.mean(axis=0)), centre_near(rng.uniform(lo, hi))
        if np.array_equal(first, second):  # r141 D3-b: a small triangle's case twice (and its
            second = first + [1.0, 0.0]  # failure printed twice): the next centre, outside it
        for p in (first, second):
            out.append((f"{label}, p={vec(p)}", (xy, p), barycentric(xy, p)))
    now = drawn_rng()  # r46 X1: a few drawn for this check, so a harvested table fails
    while len(out) < n_fixed + DRAWN:
        xy = np.round(now.uniform(0, WINDOW, (3, 2)) * 256) / 256  # on the 1/256-px grid
        if abs(_area(xy)) >= 1:  # a proper triangle, not a sliver the tolerance cannot judge
            p = centre_near(now.uniform(xy.min(axis=0), xy.max(axis=0)))
            out.append((f"drawn for this check {len(out) - n_fixed + 1}: "
                        f"{tri_words(xy)}, p={vec(p)}", (xy, p), barycentric(xy, p)))  # fmt: skip
    for what, xy, p in (*OFF_CENTRE, *THIN_FAR):
        xy, p = np.array(xy), np.array(p)
        out.append((f"{what}: {tri_words(xy)}, p={vec(p)}", (xy, p), barycentric(xy, p)))
    return out + degenerate_cases()


#: r429 W2: points off the pixel centre (every other p is one, so p snapped to its centre
#: passed): MSAA sample positions (4× rotated grid, offsets (3/8, 1/8) … from the pixel's
#: corner), a 1/256-px grid offset, and a p on an edge between two centres; exercises 06 and 12
#: (the capstone) weigh such samples
OFF_CENTRE = (
    ("MSAA sample (3/8, 1/8)", [[1.5, 1.25], [14.75, 3.5], [4.25, 13.5]],
     (6.375, 5.125)),
    ("MSAA sample (1/8, 5/8)", [[12.5, 2.0], [15.25, 14.75], [2.5, 9.5]],
     (9.125, 8.625)),
    ("off the centre, 1/256-px grid", [[2.0, 3.0], [13.5, 5.25], [6.75, 14.0]],
     (7.73046875, 8.26171875)),
    # r440 H1: a p on the 1/16-px grid (a GPU's 4 sub-pixel bits), not the 1/8-px one: p
    # rounded to 1/8 px and to 1/16 px give different weights only here
    ("off the centre, 1/16-px grid", [[2.0, 3.0], [13.5, 5.25], [6.75, 14.0]],
     (7.5625, 8.4375)),
    ("on the edge v1 v2, off the centres", [[2.0, 2.0], [14.0, 6.0], [5.0, 13.0]],
     (8.0, 4.0)),
)  # fmt: skip

#: r348 item 1: thin but proper triangles 100 000 px out, whose E(v1, v2, v3) (2^-8, 2^-16)
#: float64 computes exactly from differences of the coordinates; a refusal by the 3×3 matrix's
#: condition number (7.7e12 here) or by a threshold relative to x² (1e-12·x² = 0.01) passed
#: every other case
THIN_FAR = (
    ("thin, 100 000 px out, E(v1, v2, v3) = 1/256",
     [[100000.0, 100000.0], [100001.0, 100000.0], [100000.5, 100000.00390625]],
     (100000.5, 100000.5)),
    ("thinner, 100 000 px out, E(v1, v2, v3) = 1/65536",
     [[100000.0, 100000.0], [100000.00390625, 100000.0], [100000.5, 100000.00390625]],
     (100000.5, 100000.5)),
    # r421 W2: thin ones whose 3×3 matrix np.linalg.matrix_rank calls singular (its smallest
    # singular value below the tolerance that grows with the largest), though E ≠ 0: the
    # first is the report's, the second drawn by a seeded search for such triangles
    ("thin, 90 000 px out, E(v1, v2, v3) = 0.000137",
     [[90387.18359375, 20345.5234375], [90387.21875, 20341.80859375],
      [90386.97265625, 20367.81640625]], (90387.5, 20351.5)),
    ("thin, 87 000 px out, E(v1, v2, v3) = 0.000137",
     [[59232.2578125, 87093.6328125], [59232.29296875, 87075.3515625],
      [59232.234375, 87105.82421875]], (59232.5, 87091.5)),
    # r440 W4: a sliver 200 px long near the origin, E = 2^-15: float32 holds its vertices
    # exactly, but not the products in E (up to 2^14 px² on the 1/256-px grid: 30 bits),
    # and every float32 form of E (about each vertex, or in absolute coordinates) rounds to
    # 0, so a zero-area test in float32 refused it (r429's slivers were all short)
    ("a sliver 200 px long, E(v1, v2, v3) = 2^-15",
     [[3.8046875, 2.52734375], [186.62890625, 92.6875], [76.8203125, 38.53515625]],
     (40.3125, 20.53125)),  # the midpoint of v1 v3: λ = (½, 0, ½)
    # r495 W1: thin (E = 2^-16), 200 px long and 100 000 px out: its 3×3 matrix has a
    # condition number of 4.5e17, beyond 1/ε = 4.5e15, so ``cond(M) > 1 / np.finfo(float).eps``
    # (the textbook's "numerically singular") refused it, and passed every other case. p = v1:
    # λ = (1, 0, 0), which a solve in absolute coordinates still gets exactly
    ("a sliver 200 px long, 100 000 px out, E(v1, v2, v3) = 2^-16",
     [[99800.0, 99990.0], [100000.0, 99990.00390625], [99999.99609375, 99990.00390625]],
     (99800.0, 99990.0)),
    # r506 W1: a zero-area test relative to the triangle's size (|E| < 1e-12 · an edge's length
    # squared, or · the perimeter squared) refused no sliver of the check (all 200 px long at
    # most): this one spans the range, 283 000 px, E = 2^-16, so any such threshold above
    # 2e-16 · L² refuses it. p = v2, λ = (0, 1, 0), which a solve in absolute coordinates or
    # about any vertex (np.linalg.solve) still gets exactly
    ("a sliver 283 000 px long through the origin, E(v1, v2, v3) = 2^-16",
     [[-100000.0, -100000.0], [100000.0, 99999.99609375], [-99999.99609375, -99999.99609375]],
     (100000.0, 99999.99609375)),
)  # fmt: skip


#: The answer read from a ``barycentric`` that raised ValueError: what a triangle of zero area
#: must give (it has no weights: every p on its line has infinitely many, any other none).
REFUSED = "raised ValueError"

#: Zero-area triangles (exactly: E(v1, v2, v3) is exact in float64 on the 1/256-px grid), each
#: with a point on its line and one off it.
DEGENERATE = (
    ("three vertices on one line", [[1.5, 1.5], [5.5, 3.5], [9.5, 5.5]], (3.5, 2.5)),
    ("two vertices equal", [[2.5, 6.5], [7.25, 1.5], [2.5, 6.5]], (4.5, 4.5)),
    ("flat, on the row y = 3.5", [[1.5, 3.5], [9.5, 3.5], [4.5, 3.5]], (4.5, 3.5)),
    # r153 D3-1: np.linalg.solve raises LinAlgError (a ValueError) only where elimination
    # ends on an exact 0; on these (random collinear vertices on the grid, as r153 found for
    # 780 of 2000) it ends on rounding noise and returns weights of about 1e14 instead
    ("three vertices on one slanted line",
     [[9.2578125, 3.9375], [21.546875, 1.765625], [-3.03125, 6.109375]], (9.7578125, 4.1875)),
    ("three vertices on one steep line",
     [[10.0, 14.35546875], [1.171875, 23.15234375], [5.5859375, 18.75390625]], (10.5, 14.5)),
    ("three vertices on one line, 1000 px out",
     [[1007.94921875, 1003.9609375], [992.32421875, 994.1171875],
      [1000.13671875, 999.0390625]], (1007.5, 1003.5)),
    ("three vertices on one line, 100 000 px out",
     [[100009.6796875, 100010.20703125], [100011.08984375, 100007.4140625],
      [100008.26953125, 100013.0]], (100009.5, 100010.5)),
    # r421 W1: collinear on the grid, but np.linalg.det's LU elimination leaves 1.2e-9 and
    # 2e-9 (the report's, and the largest of a seeded search): a test |det| < 1e-9 lets them
    # through, and the solve returns weights of about 1e9
    ("three vertices on one line, 85 000 px out",
     [[63715.5703125, 84699.8359375], [63748.73828125, 84658.73828125],
      [63687.140625, 84735.0625]], (63717.5, 84697.5)),
    ("three vertices on one line, 97 000 px out",
     [[84953.11328125, 97356.546875], [84997.2734375, 97302.37890625],
      [84921.5703125, 97395.23828125]], (84957.5, 97351.5)),
    # r506 W2: collinear on the grid, but every 2×2 form of the equations about a vertex (each
    # vertex, either order of the edges, as columns or rows) leaves LU elimination with
    # rounding noise: ``np.linalg.det(2×2) == 0`` and a solve's LinAlgError let it through
    # (the cases above end on an exact 0 in those forms). A seeded search's first such one
    ("three vertices on one slanted line, where no 2×2 elimination ends on 0",
     [[54.125, 1.87109375], [25.5390625, 16.70703125], [11.24609375, 24.125]], (25.5, 16.5)),
)  # fmt: skip


def degenerate_cases():
    """(label, (xy, p), REFUSED) for each triangle of :data:`DEGENERATE`."""
    out = []
    for what, xy, p in DEGENERATE:
        xy, p = np.array(xy), np.array(p)
        out.append((f"zero area, {what}: {tri_words(xy)}, p={vec(p)}", (xy, p), REFUSED))
    return out


def call_barycentric(fn, args):
    """The student's weights, read strictly, or :data:`REFUSED` where it raised ValueError
    (another exception is reported as raised)."""
    try:
        value = fn(*args)
    except ValueError as exc:
        if not _raised_by_python(exc):
            return REFUSED
        # r506 M1: ``xs, ys = np.asarray(xy)`` raised "too many values to unpack" on every
        # case, read as a refusal ("returns 'raised ValueError' on every case: a placeholder")
        exc.args = (f"{exc} ({_not_a_refusal(exc, args)})",)
        raise
    except ArithmeticError as exc:  # r153 D3-8: ZeroDivisionError said nothing of ValueError
        raise type(exc)(
            f"{exc} (a triangle of zero area has no weights: 3.1 expects ValueError, raised "
            "by your own test before dividing)"
        ) from None
    return as_numbers(value, (3,), "3 weights, shape (3,)")


def _raised_by_python(exc: ValueError) -> bool:
    """Was ``exc`` raised by Python or numpy on a line of the student's with no ``raise``
    (an unpacking, a reshape, ``math.sqrt`` of a negative), not by a zero-area test? A
    LinAlgError (a solve's singular matrix) counts as a refusal, and so does a line whose
    source is unknown."""
    if isinstance(exc, np.linalg.LinAlgError):
        return False
    frames = traceback.extract_tb(exc.__traceback__)
    line = frames[-1].line if frames else None
    return bool(line) and not re.search(r"\braise\b", line) and "site-packages" not in (
        frames[-1].filename or "")  # fmt: skip


def _not_a_refusal(exc: ValueError, args) -> str:
    shape = ""
    if "unpack" in str(exc):
        shape = ": xy holds one row (x, y) per vertex, shape (3, 2), and p is one (x, y)"
    return ("raised by Python or numpy on a line with no `raise`, not by a zero-area test of "
            f"yours{shape}")  # fmt: skip


def _bary_raised(args, error: str) -> str:
    """r358 5: ``assert E != 0`` on a zero area was told the AssertionError alone."""
    xy, _ = args
    if "AssertionError" not in error or _area(xy) != 0:
        return ""
    return (
        " (this triangle has zero area, and 3.1 expects ValueError: an assert raises "
        "AssertionError, and is skipped under python -O: raise ValueError)"
    )


def same_barycentric(got, expected, args) -> bool:
    if isinstance(expected, str) or isinstance(got, str):
        # a str beside an array compares element by element (r164 C2: the refusing
        # mistakes' ValueError beside expected weights raised, and no mistake was named)
        return isinstance(got, str) and isinstance(expected, str) and got == expected
    return all_close(got, expected, THIN_TOL if _thin_far(args) else TOL)


#: r348 item 1: the tolerance on a thin triangle far from the origin (:data:`THIN_FAR`). Its
#: 3×3 matrix is ill-conditioned (7.7e12, 1.1e15), and a right solve of it in absolute
#: coordinates (np.linalg.solve, as the task allows) loses digits in proportion: 2.5e-9 and
#: 4e-7 of its weights here, where differences to a vertex lose none. These cases test the
#: refusal, not those digits; every wrong formula is off by far more than 1e-6.
THIN_TOL = 1e-6


def _thin_far(args) -> bool:
    """A thin triangle whose 3×3 matrix is ill-conditioned: far from the origin, or (r440 W4)
    a sliver 100 px long or more (condition number about 1e9 at 200 px and E = 2^-15)."""
    xy, _ = args
    if abs(_area(xy)) >= 1:
        return False
    v = np.asarray(xy, dtype=float)
    longest = float(np.max(np.hypot(*(v - np.roll(v, 1, axis=0)).T)))
    return _far(args)[0] >= 1e4 or longest >= 100


def _areas(xy, p) -> np.ndarray:
    """E of the edge opposite each vertex at p: E(v2, v3, p), E(v3, v1, p), E(v1, v2, p)."""
    return np.array([float(edge_function(xy[(k + 1) % 3], xy[(k + 2) % 3], p)) for k in range(3)])


def _area(xy) -> float:
    return float(edge_function(xy[0], xy[1], xy[2]))


def explain_barycentric(args, expected, got) -> str:
    xy, p = args
    if isinstance(expected, str):
        # r421: ``got == REFUSED`` on an array raised, and the report fell back to its bare
        # "yours is …, expected 'raised ValueError'"
        yours = "you raised ValueError" if isinstance(got, str) else f"yours is {short(got)}"
        return f"{tri_words(xy)} has E(v1, v2, v3) = 0 (p={vec(p)}); {yours}"
    if isinstance(got, str):
        return (f"at p={vec(p)} in {tri_words(xy)} you raised ValueError; the weights are "
                f"{vec(expected)}")  # fmt: skip
    got = np.asarray(got, dtype=float)
    return f"at p={vec(p)} in {tri_words(xy)} your λ = {vec(got, expected)}; the weights are {vec(expected, got)}"


def _sum_words(what: str):
    def words(args, expected, got):
        xy, _ = args
        return f"; yours sum to {num(np.sum(got))}: {what.format(area=num(_area(xy)))}"

    return words


def _absolute_area_words(args, expected, got) -> str:
    xy, _ = args
    return (
        f": divide by the signed area E(v1, v2, v3) = {num(_area(xy))} (negative: this triangle "
        "runs counter-clockwise on screen), not by its absolute value"
    )


def _sign_in_two(rest: int, only_negative: bool | None):
    """r429 H1: two weights divided by |E(v1, v2, v3)| (``only_negative``) or by −E, the
    third, number ``rest``, taken as 1 minus their sum (λ3 = 1 − λ1 − λ2, the task's route);
    r495 H1: ``only_negative`` None: by −|E|, the slip on triangles with E > 0 only."""

    def gives(xy, p):
        area = _area(xy)
        if (only_negative and area > 0) or (only_negative is None and area < 0):
            return None  # the same as the right answer: says nothing here
        lam = _areas(xy, p) / area
        two = [k for k in range(3) if k != rest]
        lam[two] = -lam[two]
        lam[rest] = 1.0 - lam[two].sum()
        return lam

    return gives


def _sign_in_two_words(rest: int, only_negative: bool):
    def words(args, expected, got):
        xy, _ = args
        area = _area(xy)
        two = " and ".join(f"λ{k + 1}" for k in range(3) if k != rest)
        took = (f"|E(v1, v2, v3)| = {num(abs(area))}: right on triangles with E > 0, wrong on "
                "every one of the other winding (this one runs counter-clockwise on screen)"
                if only_negative else f"−|E(v1, v2, v3)| = {num(-area)}: right on triangles "
                "with E < 0, wrong on every one of the other winding (this one runs clockwise "
                "on screen)" if only_negative is None else f"−E(v1, v2, v3) = {num(-area)}: the "
                "edges, or the products in E, the other way round")  # fmt: skip
        return (
            f": your {two} have the wrong sign and your λ{rest + 1} = 1 minus their sum makes "
            f"up the rest: you divided by {took}. Divide by the signed E(v1, v2, v3) = "
            f"{num(area)} itself"
        )

    return words


def _scaled_in_two(rest: int, by: str):
    """r495 H2: two weights scaled (``by`` "area": divided by E/2, twice the weights; "not
    divided": E(...) itself, times E) and the third, number ``rest``, 1 minus their sum: the
    shipped code's shape, λ3 = 1 − λ1 − λ2, told the rule only."""

    def gives(xy, p):
        lam = _areas(xy, p) / _area(xy)
        two = [k for k in range(3) if k != rest]
        if by == "unsigned":
            lam[two] = np.abs(lam[two])
        else:
            lam[two] *= 2.0 if by == "area" else _area(xy)
        lam[rest] = 1.0 - lam[two].sum()
        return lam

    return gives


def _scaled_in_two_words(rest: int, by: str):
    def words(args, expected, got):
        area = _area(args[0])
        two = " and ".join(f"λ{k + 1}" for k in range(3) if k != rest)
        did = ("twice the weights: you divided by the triangle's area, E(v1, v2, v3)/2 = "
               f"{num(area / 2)}" if by == "area" else "the sizes of the weights: you took their "
               "absolute values, but where p lies outside an edge its weight is negative"
               if by == "unsigned" else f"the weights times E(v1, v2, v3) = {num(area)}: you "
               "did not divide by it")  # fmt: skip
        return (f": your {two} are {did}, and your λ{rest + 1} = 1 minus their sum makes up the "
                f"rest. Divide by E(v1, v2, v3) = {num(area)} itself: each weight is a ratio of "
                "two edge functions")  # fmt: skip

    return words


def _one_sign(k: int, rest: int | None):
    """r455: λ_k alone with the wrong sign (an edge function of its numerator taken the other
    way round, E(v1, v3, p) for E(v3, v1, p)), and the weight number ``rest``, if any, taken
    as 1 minus the other two, carrying the slip (rule only before)."""

    def gives(xy, p):
        lam = _areas(xy, p) / _area(xy)
        lam[k] = -lam[k]
        if rest is not None:
            lam[rest] = 1.0 - (lam.sum() - lam[rest])
        return lam

    return gives


def _one_sign_words(k: int, rest: int | None):
    def words(args, expected, got):
        carried = ("" if rest is None else f", and your λ{rest + 1} = 1 minus the other two "
                   "carries the slip")  # fmt: skip
        return (
            f": your λ{k + 1} = {num(got[k], expected[k])} has the wrong sign (the weights give "
            f"{num(expected[k], got[k])}){carried}: an edge function taken the other way round "
            "(E(a, b, p) = −E(b, a, p)), or the two products of its numerator swapped. Take each "
            "edge in the triangle's order: λ1 = E(v2, v3, p), λ2 = E(v3, v1, p), "
            "λ3 = E(v1, v2, p), each over E(v1, v2, v3)"
        )

    return words


ORDER = (
    ": the same numbers in another order. λ_i belongs to v_i: the area of the sub-triangle "
    "opposite v_i (p with the other two) over the whole"
)

#: r153 D3-7: vertices reversed to make a negative area positive, the weights not put back
REVERSED_WHERE_NEGATIVE = (
    ": the same numbers in reverse order. Where E(v1, v2, v3) < 0 you reversed the vertices "
    "(to make the area positive?) but returned the weights in that reversed order: λ_i "
    "belongs to v_i, so reverse them back (or keep the signed area)"
)


def _reversed_where_negative(xy, p) -> np.ndarray:
    lam = _areas(xy, p) / _area(xy)
    return lam[::-1] if _area(xy) < 0 else lam


def _clamped(upper: float, renormalised: bool):
    """Negative weights set to 0 (and any above ``upper`` to it: 1 as np.clip(λ, 0, 1) does,
    inf as np.maximum(λ, 0) does), the rest renormalised or not (r358 1: the clip left
    unrenormalised got the rule only): inside the triangle λ itself (r137 D3-2: "None" there
    made the clamp agree with too few answers to be named)."""

    def gives(xy, p):
        kept = np.clip(_areas(xy, p) / _area(xy), 0.0, upper)
        return kept / kept.sum() if renormalised else kept

    return gives


def _clamped_words(args, expected, got) -> str:
    """r358 1: one text for every clamp of the weights, with what it broke on this case."""
    xy, p = args
    g = np.asarray(got, dtype=float)
    total = float(g.sum())
    summed = "" if abs(total - 1) <= 1e-9 else f"sum to {num(total, 1.0)} and "
    return (
        ": your weights are never negative: you clamped them (to [0, 1], or at 0), but where p "
        "lies outside an edge the weight of the vertex opposite that edge is negative, and "
        f"clamping breaks λ1·v1 + λ2·v2 + λ3·v3 = p (yours {summed}rebuild "
        f"{vec(g @ np.asarray(xy, float))}, not p = {vec(p)}); do not clamp them"
    )


def _epsilon_fits(args, expected, got) -> bool | None:
    """λ = E(...)/(E(v1, v2, v3) + δ) for a small δ ≠ 0, in float64 (r141 D3-b: a guard
    against dividing by 0, ``area + 1e-12``, was told "did you compute in float32?")."""
    xy, p = args
    if isinstance(got, str) or isinstance(expected, str):
        return None  # a zero area, or a refusal: it says nothing there
    if held_by_precision(expected, got):  # r153 D3-2: float32's rounding, not a nudge
        return False
    g, area = np.asarray(got, dtype=float), _area(xy)
    total = float(np.sum(g))
    if g.shape != (3,) or not np.isfinite(g).all() or total == 0:
        return False
    delta = _guard(xy, p, g)
    # r164: the sign a guard has, E + ε or E + copysign(ε, E) (a "−8e-05 added to E =
    # −7.63e-05" was half-areas); one ε on every case: :func:`_epsilon`
    guard = delta is not None and (delta > 0 or (delta < 0) == (area < 0))
    if not guard or delta == 0 or abs(delta) > 1e-3 or _rounded(g, expected):
        return False
    # (1e-9: δ read back from a sum of weights of 1e4 cancelling to 0.13, as on the thin
    # triangle of E = 2^-16 of :data:`THIN_FAR`, is good to a few 1e-12 only)
    # (the weight taken as 1 minus the others is near 0 where p lies near its edge: there
    # 1 − λ1 − λ2 cancels, to float64's rounding of the weights' size)
    atol = 1e-300 if _rest_of(g) is None else 4e-16 * max(1.0, float(np.abs(g).max()))
    return bool(np.allclose(g, _guarded(xy, p, delta, _rest_of(g)), rtol=1e-9, atol=atol))


def _rest_of(g) -> int | None:
    """The weight a guarded solve took as 1 minus the other two (r421 H4: the route 3.1
    suggests, λ3 = 1 − λ1 − λ2), read from an answer that sums to 1; None where the three
    were each divided (their sum is then off 1)."""
    return 2 if abs(float(np.sum(g)) - 1) <= 1e-12 else None


def _guarded(xy, p, delta: float, rest: int | None) -> np.ndarray:
    """λ_i = E(...)/(E(v1, v2, v3) + δ), and the weight ``rest`` (if any) 1 minus the others."""
    lam = _areas(xy, p) / (_area(xy) + delta)
    if rest is not None:  # the other two in order, as ``1.0 - l1 - l2`` is written
        i, j = (k for k in range(3) if k != rest)
        lam[rest] = 1.0 - lam[i] - lam[j]
    return lam


def _guard(xy, p, g) -> float | None:
    """δ read back from weights ``g`` divided by E(v1, v2, v3) + δ (the three, or the two
    beside λ3 = 1 − λ1 − λ2), or None."""
    area, total = _area(xy), float(np.sum(g))
    if _rest_of(g) is None:
        return area / total - area if total else None
    areas = _areas(xy, p)
    k = int(np.argmax(np.abs(areas[:2])))
    return float(areas[k] / g[k] - area) if g[k] else None


def _epsilon(args, expected, got) -> float | None:
    """The size of the ε added to E on this case (:func:`_epsilon_fits`), the one number
    that must be the same on every case it is named on (:attr:`.Mistake.parameter`)."""
    xy, p = args
    delta = _guard(xy, p, np.asarray(got, dtype=float))
    return None if delta is None else abs(delta)


def _scaled_words(args, expected, got, c) -> str:
    """r164: answers off by one constant factor (a forgotten or doubled ½) were told
    "you added a small number to E"."""
    return (
        f": your weights are the right ones times {num(c, 1.0)} on every case: off by a "
        f"constant factor, so they sum to {num(c, 1.0)}, not 1 (a factor left in the "
        "numerators or the denominator: each weight is E of the edge opposite its vertex over "
        "E(v1, v2, v3), with nothing else)"
    )


def rounded_decimals(got, expected) -> int | None:
    """The k (1 to 8) such that ``got`` is ``expected`` rounded to k decimals (each exactly so,
    and within half a unit of the k-th of it), or None (r148 D12-2: on a case whose weights
    are equal, λ rounded to 5 decimals is also one common rescale, and was told "you added a
    small number to E")."""
    g = np.asarray(got, dtype=float)
    off = np.max(np.abs(g - np.asarray(expected, dtype=float)))
    return next((k for k in range(1, 9)
                 if np.array_equal(g, np.round(g, k)) and off <= 0.5 * 10.0**-k * (1 + 1e-6)),
                None)  # fmt: skip


def _rounded(got, expected) -> bool:
    return rounded_decimals(got, expected) is not None


def _rounded_words(args, expected, got) -> str:
    return rounded_words(got, expected).replace(";", ":", 1)


def rounded_words(got, expected) -> str:
    """ "; words" on weights ``got`` rounded to a few decimals (:func:`rounded_decimals`)."""
    g = np.asarray(got, dtype=float)
    k = rounded_decimals(g, expected)
    off = float(np.max(np.abs(g - np.asarray(expected, dtype=float))))
    return (
        f"; your weights are rounded to {k} decimals: off by up to {off:.1e}, far more "
        "than float64's rounding (about 1e-16); return them unrounded (round only what "
        "you print)"
    )


def _epsilon_words(args, expected, got) -> str:
    xy, p = args
    area = _area(xy)
    g = np.asarray(got, dtype=float)
    delta = _guard(xy, p, g)
    error = float(np.max(np.abs(g - expected)))
    rest = ("" if _rest_of(g) is None else
            " (your λ3 = 1 − λ1 − λ2 sums them to 1, but λ1 and λ2 carry the ε)")  # fmt: skip
    return (
        f": you added a small number (about {delta:.0e}) to E(v1, v2, v3) = {num(area)} (a guard "
        f"against dividing by 0?){rest}: on this small triangle that moves the weights by "
        f"{error:.1e}; "
        "divide by E(v1, v2, v3) itself, and refuse a zero area with ValueError (on the "
        "1/256-px grid E(v1, v2, v3) is exact, so E == 0 tells it without a nudge)"
    )


#: Weights this large on a zero-area triangle are elimination's rounding noise (about 1e14):
#: a solver's, not the student's own arithmetic (r175 B4: no solver was said to a student
#: who had none).
SOLVER_NOISE = 1e6


def _zero_area_words(args, expected, got) -> str:
    g = np.asarray(got, dtype=float)
    if np.isfinite(g).all() and np.abs(g).max() >= SOLVER_NOISE:
        # r153 D3-1: a solver's LinAlgError is raised only on an exact 0 pivot; rounding
        # left a tiny one here, and the "weights" came out huge
        return (
            ": your solver returned weights for a zero-area triangle: these three vertices lie "
            "on one line (a p on it has infinitely many weights, any other none), and no "
            "solver's error is a test of that; test the area exactly, E == 0 (exact on the "
            "1/256-px grid), and raise ValueError"
        )
    if np.isfinite(g).all():
        return (
            ": you returned weights for a zero-area triangle: these three vertices lie on one "
            "line (a p on it has infinitely many weights, any other none); test the area "
            "exactly, E == 0 (exact on the 1/256-px grid), and raise ValueError"
        )
    return (  # r506 H3: a test of |E| against a size that is 0 here was told "no test"
        ": your answer is NaN or infinity (a division by 0), but these three vertices lie on "
        "one line: the triangle has no area and no weights (a p on the line has infinitely "
        "many, any other none); raise ValueError before dividing (a zero-area test of "
        "yours, if you wrote one, let this triangle through: test E == 0 exactly)"
    )


def _solver_noise(args, expected, got) -> bool:
    """Huge finite weights on a zero-area triangle: elimination's rounding noise."""
    if not isinstance(expected, str) or isinstance(got, str):
        return False
    g = np.asarray(got, float)
    return bool(np.isfinite(g).all()) and float(np.abs(g).max()) >= SOLVER_NOISE


def _refused_words(args, expected, got) -> str:
    xy, _ = args
    area = _area(xy)
    far, _ = _far(args)
    v = np.asarray(xy, dtype=float)
    longest = float(np.max(np.hypot(*(v - np.roll(v, 1, axis=0)).T)))
    if abs(area) < 1 and longest >= 1e4:  # r506 W1: a threshold relative to the size
        return (
            f": you refused a thin but real triangle {num(longest)} px long: its E(v1, v2, v3) "
            f"= {area!r} (twice its area) is exact in float64 and not 0, so the triangle has "
            "weights. A zero-area test that grows with the triangle's size (|E| against a "
            "small multiple of an edge's length squared) refuses a sliver this long, however "
            "small the multiple: only E == 0 exactly is no triangle"
        )
    if abs(area) < 1 and far >= 1e4:  # r348 item 1: a condition number, a relative threshold
        return (
            f": you refused a thin but real triangle {num(far)} px from the origin: its "
            f"E(v1, v2, v3) = {area!r} (twice its area) is exact in float64, computed from "
            "differences of the coordinates on the 1/256-px grid, and it is not 0, so the "
            "triangle has weights. Only E == 0 exactly is no triangle; a "
            "test that grows with the coordinates (a threshold relative to x², a condition "
            "number or a rank of the 3×3 matrix) refuses such a triangle"
        )
    if abs(area) >= 1:  # r164 C2: "however thin" was said of a 67.5-px² triangle
        return (
            f": this triangle's E(v1, v2, v3) = {num(area)} is not 0 (its area is "
            f"{num(abs(area) / 2)} px²), so it has weights: refuse only an area of exactly 0"
        )
    return (
        f": this triangle's E(v1, v2, v3) = {num(area)} is not 0, so it has weights, "
        "however thin it is: refuse only an area of exactly 0 (on the 1/256-px grid float64 "
        "computes E exactly, so no threshold is needed, and one such as |E| < 1 refuses thin "
        "triangles that have weights)"
    )


def _winding_refused(sign: float):
    """The weights, refused (ValueError) where E(v1, v2, v3) has the sign ``sign``: r164 C2,
    ``if E <= 0: raise ValueError`` (a triangle taken to need a positive area)."""

    def gives(xy, p):
        area = _area(xy)
        return REFUSED if area * sign > 0 else _areas(xy, p) / area

    return gives


def _winding_words(args, expected, got) -> str:
    xy, _ = args
    area = _area(xy)
    way = "counter-clockwise" if area < 0 else "clockwise"
    return (
        f": E(v1, v2, v3) = {num(area)} {'<' if area < 0 else '>'} 0: this triangle runs "
        f"{way} on screen (its area is {num(abs(area) / 2)} px²), and you refused every "
        f"triangle of that winding. 3.1 asks that the same formula serve both windings (each "
        "weight is a ratio of two signed areas, whose signs cancel), so refuse only E == 0"
    )


def _p_shifted(by: float):
    """The weights of p + (by, by): r348, a pixel centre's ½ added to p a second time."""

    def gives(xy, p):
        return _areas(xy, np.asarray(p, float) + by) / _area(xy)

    return gives


def _p_shifted_words(by: float):
    def words(args, expected, got):
        _, p = args
        moved = vec(np.asarray(p, float) + by)
        sign = "+" if by > 0 else "−"
        return (
            f": your weights are those of p {sign} (½, ½) = {moved}, not of p = {vec(p)}: p is "
            "already the point to weigh (a pixel centre's ½ is in it); take p as given"
        )

    return words


def _p_snapped(xy, p):
    """r429 W2: the weights of p's pixel centre, ``floor(p) + ½`` (p read as a pixel)."""
    return _areas(xy, np.floor(np.asarray(p, float)) + 0.5) / _area(xy)


def _p_snapped_words(args, expected, got) -> str:
    _, p = args
    centre = vec(np.floor(np.asarray(p, float)) + 0.5)
    return (
        f": your weights are those of {centre}, the centre of p's pixel, not of p = {vec(p)}: "
        "you snapped p to its pixel centre (floor(p) + ½, or p read as a pixel index); p is any "
        "point, an MSAA sample off the centre here: weigh p as given"
    )


#: r440 H1: p made coarser than the 1/256-px grid it lies on: truncated (``int(p)``: at a
#: pixel centre the same as p − ½, so told apart by the off-centre cases), or rounded to whole
#: pixels or to 1/k px (a GPU's sub-pixel grid: 1/16 px for 4 bits); each with its words
P_COARSENED = {
    "truncated": (np.trunc, "p truncated to whole pixels (int(p), or an int array, truncates)"),
    **{f"rounded to 1/{k} px" if k > 1 else "rounded to whole pixels": (
        lambda p, k=k: np.round(np.asarray(p, float) * k) / k,
        f"p rounded to 1/{k} px (the sub-pixel grid a GPU snaps vertices to, but p here is a "
        "point given on the 1/256-px grid)" if k > 1 else "p rounded to whole pixels")
       for k in (1, 2, 4, 8, 16)},
    # r455: floored to the sub-pixel grid, np.floor(p * 16) / 16 (whole pixels: "truncated")
    **{f"floored to 1/{k} px": (
        lambda p, k=k: np.floor(np.asarray(p, float) * k) / k,
        f"p floored to 1/{k} px (np.floor(p * {k}) / {k}: the sub-pixel grid a GPU snaps "
        "vertices to, but p here is a point given on the 1/256-px grid)")
       for k in (2, 4, 8, 16)},
}  # fmt: skip


def _p_coarsened(how: str):
    """The weights of p truncated or rounded (:data:`P_COARSENED`)."""
    move = P_COARSENED[how][0]

    def gives(xy, p):
        return _areas(xy, move(np.asarray(p, float)) + 0.0) / _area(xy)

    return gives


def _p_coarsened_words(how: str):
    move, said = P_COARSENED[how]

    def words(args, expected, got) -> str:
        _, p = args
        moved = vec(move(np.asarray(p, float)) + 0.0)
        return (
            f": your weights are those of {moved}, {said}, not of p = {vec(p)}: p is any point, "
            "an MSAA sample off the centre say: weigh p as given, in float64"
        )

    return words


#: How vertices lose their fractions (r348: truncated by an int cast; r358 4: rounded),
#: and the words that say how
WHOLE_PIXELS = {
    "truncated": (np.trunc, "an int array, or int(...), truncates"),
    "rounded": (np.round, "np.round, or round(...), rounds to whole pixels"),
}


def _truncated(with_p: bool, how: str = "truncated"):
    """The weights computed from vertices (and p) made whole numbers: cast to int, which
    truncates (r348: ``np.asarray(xy, int)``), or rounded; the zero-area test on them."""
    whole = WHOLE_PIXELS[how][0]

    def gives(xy, p):
        t = whole(np.asarray(xy, float))
        q = whole(np.asarray(p, float)) if with_p else np.asarray(p, float)
        return REFUSED if _area(t) == 0 else _areas(t, q) / _area(t)

    return gives


def _truncated_words(how: str = "truncated", with_p: bool = False):
    whole, said = WHOLE_PIXELS[how]

    def words(args, expected, got) -> str:
        xy, p = (np.asarray(a, float) for a in args)
        k = next((k for k in range(3) if (xy[k] != whole(xy[k])).any()), 0)
        moved = (f", and p = {vec(p)} became {vec(whole(p) + 0.0)}"
                 if with_p and (p != whole(p)).any() else "")  # fmt: skip
        return (
            f": your vertices lost their fractions: v{k + 1} = {vec(xy[k])} became "
            f"{vec(whole(xy[k]) + 0.0)} ({said}){moved}; keep the coordinates as floats: they "
            "lie on the 1/256-px grid, and float64 holds them exactly"
        )

    return words


#: λ3 written with a sign slip, c0 + c1·λ1 + c2·λ2, and how it reads (r348: 1 − λ1 + λ2;
#: r358 3: λ1 + λ2 − 1 got the rule only, so every other choice of the three signs)
LAMBDA3_SLIPS = {
    (1, -1, 1): "1 − λ1 + λ2", (1, 1, -1): "1 + λ1 − λ2", (-1, 1, 1): "λ1 + λ2 − 1",
    (1, 1, 1): "1 + λ1 + λ2", (-1, -1, 1): "λ2 − λ1 − 1", (-1, 1, -1): "λ1 − λ2 − 1",
    (-1, -1, -1): "−1 − λ1 − λ2",
}  # fmt: skip


def _lambda3_typo(signs):
    """λ1 and λ2 right, λ3 = c0 + c1·λ1 + c2·λ2 for the signs ``signs``."""

    def gives(xy, p):
        lam = _areas(xy, p) / _area(xy)
        return np.array([lam[0], lam[1], signs[0] + signs[1] * lam[0] + signs[2] * lam[1]])

    return gives


def _lambda3_words(form: str):
    def words(args, expected, got):
        return (
            f": your λ1 and λ2 are right, but your λ3 = {num(got[2], expected[2])} is "
            f"{form}, a sign slip: the weights sum to 1, so λ3 = 1 − λ1 − λ2 = "
            f"{num(expected[2], got[2])}"
        )

    return words


def _one_weight_mistakes() -> list[Mistake]:
    """r506 H1 (r495's left-overs b16, b18): one weight divided by |E| (the others by E), or
    its size taken, got the rule only."""
    return [
        *(Mistake("one weight over |E|", _one_over_abs_words(k), gives=_one_over_abs(k))
          for k in range(3)),
        *(Mistake("one weight's size", _one_size_words(k), gives=_one_size(k)) for k in range(3)),
    ]  # fmt: skip


def _one_over_abs(k: int):
    """λ_k alone over |E(v1, v2, v3)|, the other two over E (r506 H1)."""

    def gives(xy, p):
        area = _area(xy)
        out = _areas(xy, p) / area
        out[k] = out[k] * area / abs(area)
        return out

    return gives


def _one_over_abs_words(k: int):
    def words(args, expected, got) -> str:
        area = _area(args[0])
        return (
            f": your λ{k + 1} has the wrong sign and the other two are right: E(v1, v2, v3) = "
            f"{num(area)} < 0 here, and you divided λ{k + 1}'s edge function by |E(v1, v2, v3)| "
            "= " f"{num(abs(area))}, the other two by E itself; each weight is a ratio of two "
            "signed edge functions: divide all three by the signed E"
        )  # fmt: skip

    return words


def _one_size(k: int):
    """|λ_k|, the other two weights right (r506 H1: ``abs(1 - l1 - l2)``)."""

    def gives(xy, p):
        out = _areas(xy, p) / _area(xy)
        out[k] = abs(out[k])
        return out

    return gives


def _one_size_words(k: int):
    def words(args, expected, got) -> str:
        return (
            f": your λ{k + 1} = {num(float(np.asarray(got, float)[k]))} is the size of the "
            f"weight {num(float(expected[k]))}: a weight is negative where p lies outside the "
            f"edge opposite its vertex (here p is outside the edge opposite v{k + 1}); keep its "
            "sign (no abs)"
        )

    return words


def _untranslated(k: int):
    """r358 2: the solve about v_k, (v_i − v_k)·λ_i + (v_j − v_k)·λ_j = p − v_k, with p on
    the right in place of p − v_k: the weights of p + v_k."""

    def gives(xy, p):
        return _areas(xy, np.asarray(p, float) + np.asarray(xy, float)[k]) / _area(xy)

    return gives


def _untranslated_words(k: int):
    i, j = (n + 1 for n in range(3) if n != k)
    v = f"v{k + 1}"

    def words(args, expected, got):
        xy, p = (np.asarray(a, float) for a in args)
        return (
            f": your weights are those of p + {v} = {vec(p + xy[k])}, not of p = {vec(p)}: in "
            f"a solve about {v}, (v{i} − {v})·λ{i} + (v{j} − {v})·λ{j} = p − {v}, and you "
            f"put p itself on the right-hand side: subtract {v} from p, as from the vertices"
        )

    return words


def _rebuilds_p(xy, p, got, tol: float = 1e-9) -> bool:
    """Do weights ``got`` rebuild p, λ1·v1 + λ2·v2 + λ3·v3 = p (to ``tol`` of the size of
    the coordinates: 1e-6 where the words print the point, so a float32 answer's rounding
    is no "(4.5, 3.5), not p = (4.5, 3.5)")?"""
    xy, p = np.asarray(xy, float), np.asarray(p, float)
    scale = max(1.0, float(np.abs(xy).max()) * float(np.abs(got).max()))
    return bool(np.all(np.abs(np.asarray(got, float) @ xy - p) <= tol * scale))


def _no_sum_row(args, expected, got) -> bool | None:
    """r348: the weights solve the two equations for x and y but not the sum (a least-squares
    solve of those two alone)."""
    if isinstance(expected, str) or isinstance(got, str):
        return None
    g = np.asarray(got, dtype=float)
    if g.shape != (3,) or not np.isfinite(g).all() or abs(float(g.sum()) - 1) <= 1e-6:
        return False
    xy, p = args
    return _rebuilds_p(xy, p, g)


def _no_sum_row_words(args, expected, got) -> str:
    _, p = args
    return (
        f": your weights rebuild p (λ1·v1 + λ2·v2 + λ3·v3 = {vec(p)}) but sum to "
        f"{num(float(np.sum(got)), 1.0)}, not 1: the third equation, λ1 + λ2 + λ3 = 1, is "
        "missing (the two equations for x and y alone leave a whole line of solutions)"
    )


def _is_lstsq(args, got) -> bool:
    """Is ``got`` np.linalg.lstsq's answer to the three equations, sum row included?"""
    xy, p = (np.asarray(a, dtype=float) for a in args)
    m = np.vstack([xy.T, np.ones(3)])
    return near(np.linalg.lstsq(m, np.array([p[0], p[1], 1.0]), rcond=None)[0], got)


def _lstsq_words(args, expected, got) -> str:
    return (
        f": your weights rebuild p but sum to {num(float(np.sum(got)), 1.0)}, not 1: they are "
        "np.linalg.lstsq's answer to the three equations. lstsq treats a singular value below "
        "its rcond (about 7e-16 of the largest) as 0, and this thin triangle far from the "
        "origin has one that small, so lstsq dropped a direction and returned a least-squares "
        "compromise, not the solution. E(v1, v2, v3) is not 0 here, so the three equations "
        "have one exact solution: solve them (Cramer's rule, or np.linalg.solve after a test "
        "E == 0)"
    )


def _proper(gives):
    """A wrong solution of a proper triangle that raises, as it should, on a zero area."""

    def on_case(xy, p):
        return REFUSED if _area(xy) == 0 else gives(xy, p)

    return on_case


def _float32_off_grid(args, expected, got) -> bool | None:
    """A zero-area case whose vertices float32 cannot hold, answered with float32 numbers:
    E == 0 in float32 is no test there (a right float32 solution gives numbers)."""
    if not isinstance(expected, str):
        return None
    if isinstance(got, str):
        return False
    xy, p = args
    moved = not np.array_equal(np.asarray(xy, np.float32).astype(float), np.asarray(xy, float))
    return moved and held_by_precision(np.zeros(3), got)


def _float32_off_grid_words(args, expected, got) -> str:
    far, _ = _far(args)
    return (
        f": your answer is numbers, but these three vertices lie on one line. {num(far)} px "
        f"from the origin float32 numbers are {num(float(np.spacing(np.float32(far))))} px "
        "apart: in float32 the vertices leave the 1/256-px grid and their E is no longer 0. "
        "Keep the coordinates in float64, where E == 0 is exact"
    )


def _epsilon_on_zero(args, expected, got) -> float | None:
    """δ when a zero-area case's answer is E(...)/(0 + δ) for a small δ > 0, the ε of a guard
    ``E + 1e-9`` (0 where p lies on the line: every E(...) is 0, and so is every weight),
    else None (r175 B4: told "your solver", which this student has not)."""
    if not isinstance(expected, str) or isinstance(got, str):
        return None
    xy, p = args
    g, areas = np.asarray(got, dtype=float), _areas(xy, p)
    if g.shape != (3,) or not np.isfinite(g).all():
        return None
    if not areas.any():
        return 0.0 if not g.any() else None
    k = int(np.argmax(np.abs(areas)))
    if g[k] == 0:
        return None
    delta = areas[k] / g[k]
    if not 0 < delta <= 1e-3 or not np.allclose(g, areas / delta, rtol=1e-9, atol=0):
        return None
    return float(delta)


def _epsilon_on_zero_words(args, expected, got) -> str:
    xy, p = args
    delta = _epsilon_on_zero(args, expected, got)
    if delta == 0:
        turned = ("p lies on that line, so every E(...) is 0 as well, and your ε turned each "
                  "0/0 into 0/ε = 0")  # fmt: skip
    else:
        turned = (f"p lies off it, and your ε (about {delta:.0e}) turned each E(...)/0 into E(...)/ε, weights "
                  f"of up to {np.abs(_areas(xy, p)).max() / delta:.0e}")  # fmt: skip
    return (
        ": you divided by E(v1, v2, v3) plus a small number (a guard against dividing by 0?). "
        f"Here E(v1, v2, v3) = 0: these three vertices lie on one line; {turned}, and so hid the "
        "zero area instead of refusing it. Such a triangle has no weights (a p on its line has "
        "infinitely many, any other none): test E == 0 exactly (exact on the 1/256-px grid) "
        "and raise ValueError, with no ε"
    )


def _reads_det_words(args, expected, got) -> str:
    return (
        ": your code reads np.linalg.det, but numpy computes a determinant by LU elimination "
        "in rounded arithmetic: on these three vertices, which lie on one line, it comes out "
        "as rounding noise, not 0, so your test of it (against 0, or against a threshold far "
        "below any real area) let this triangle through and the solve returned noise as "
        "weights. A rounded determinant is no exact area test; E(v1, v2, "
        "v3) of lesson 02, from differences of the coordinates, is exact on the 1/256-px "
        "grid: test E == 0 and raise ValueError"
    )


def _float32_flattened(args, expected, got) -> bool | None:
    """A proper triangle refused where its vertices, as float32 holds them, have E == 0."""
    if isinstance(expected, str) or not isinstance(got, str):
        return None
    xy, _ = args
    return bool(_e32(*np.asarray(xy, dtype=np.float32)) == 0)


def _float32_flattened_words(args, expected, got) -> str:
    far, _ = _far(args)
    xy, _ = args
    v = np.asarray(xy, dtype=float)
    if np.array_equal(v.astype(np.float32).astype(float), v):
        # r440 W4: float32 holds the vertices; E's products are what it rounds
        d = np.abs(v - np.roll(v, 1, axis=0))
        big = float(d[:, 0].max() * d[:, 1].max())
        return (
            ": you refused a thin but real triangle: float32 holds these vertices exactly, but "
            f"not the products in E(v1, v2, v3): they reach {num(big)} px² on the 1/256-px grid, "
            "more digits than float32's 24 bits keep, so the two products round to the same "
            f"number and E, {_area(xy)!r} in float64, becomes 0 in float32. Test E == 0 in "
            "float64, where it is exact"
        )
    return (
        f": you refused a thin but real triangle. {num(far)} px from the origin float32 "
        f"numbers are {num(float(np.spacing(np.float32(far))))} px apart: in float32 its "
        "vertices leave the 1/256-px grid and lie on one line, so its E(v1, v2, v3), "
        f"{_area(xy)!r} in float64, becomes 0. Keep the coordinates in float64, where E is exact"
    )


def _cond_words(args, expected, got) -> str:
    xy, _ = args
    m = np.vstack([np.asarray(xy, float).T, np.ones(3)])
    return (
        f": your code reads np.linalg.cond, and this triangle's 3×3 matrix has a condition "
        f"number of {np.linalg.cond(m):.1e}, yet its E(v1, v2, v3) = {_area(xy)!r} is "
        "exact in float64 and not 0: you refused a thin but real triangle. A condition number "
        "says how much a solve may magnify rounding, not whether the area is 0 (and no limit "
        "on it separates the two); test E == 0 exactly and raise ValueError for it alone"
    )


def _rank_words(args, expected, got) -> str:
    """r421 W2: ``if np.linalg.matrix_rank(M) < 3: raise ValueError`` refused a thin far one."""
    xy, _ = args
    m = np.vstack([np.asarray(xy, float).T, np.ones(3)])
    sigma = np.linalg.svd(m, compute_uv=False)
    return (
        ": your code reads np.linalg.matrix_rank, which counts the singular values of the 3×3 "
        f"matrix above a tolerance that grows with the largest one: here the smallest, "
        f"{sigma.min():.1e}, falls below {sigma.max() * 3 * np.finfo(float).eps:.1e}, so it "
        f"called the matrix singular, yet this triangle's E(v1, v2, v3) = {_area(xy)!r} is exact "
        "in float64 and not 0: you refused a thin but real triangle. A rank (a determinant, "
        "a condition number) computed in floating point is no exact area test; test E == 0 "
        "and raise ValueError for it alone"
    )


def _let_through_words(read: str, what: str):
    """r495: a zero-area test on a floating-point measure (``np.linalg.cond(M) == np.inf``,
    ``np.linalg.slogdet(M)[0] == 0``) that let a collinear triangle through to a division was
    told "raise ValueError before dividing", as if there were no test."""

    def words(args, expected, got) -> str:
        m = np.vstack([np.asarray(args[0], float).T, np.ones(3)])
        value = {"cond": np.linalg.cond(m), "slogdet": np.linalg.slogdet(m)[0]}[read]
        return (
            f": your code reads np.linalg.{read}, and on this triangle, whose three vertices lie "
            f"on one line (E(v1, v2, v3) = 0 exactly), {what} comes out as {value:.3g}: rounding "
            "keeps the 3×3 matrix's floating-point measure away from the value your test waits "
            "for, so the division ran and gave NaN or infinity. Test E == 0 (exact on the "
            "1/256-px grid) and raise ValueError"
        )

    return words


def _let_through(a, e, g) -> bool:
    return isinstance(e, str) and not isinstance(g, str) and not np.isfinite(
        np.asarray(g, float)).all()  # fmt: skip


def _inverse_words(args, expected, got) -> str:
    """r495: ``np.linalg.inv(M) @ (px, py, 1)`` on the thin far sliver (rule only before)."""
    xy, _ = args
    m = np.vstack([np.asarray(xy, float).T, np.ones(3)])
    off = float(np.abs(np.asarray(got, float) - np.asarray(expected, float)).max())
    return (
        f": your code reads np.linalg.inv, and this thin triangle's 3×3 matrix has a condition "
        f"number of {np.linalg.cond(m):.1e}: an inverse of it computed in floating point may "
        f"be off by up to that times float64's rounding, and your weights are off by {off:.2g}. "
        "Solve for the weights from differences to a vertex (two equations about v3, Cramer's "
        "rule), which float64 computes exactly on the 1/256-px grid, not through an inverse"
    )


def _inverse_fits(args, expected, got) -> bool:
    if isinstance(got, str) or isinstance(expected, str) or not _thin_far(args):
        return False
    g = np.asarray(got, float)
    return g.shape == (3,) and bool(np.isfinite(g).all())


ZERO_AREA_MISTAKES = [
    Mistake("refused a winding", _winding_words, gives=_proper(_winding_refused(-1.0))),
    Mistake("refused a winding", _winding_words, gives=_proper(_winding_refused(1.0))),
    Mistake("float32", _float32_off_grid_words, fits=_float32_off_grid),
    # r175 B5: ``if np.linalg.det(M) == 0`` before a solve: named where the code reads det
    # (r506 W2: before the ε, whose E/ε a 2×2 elimination's noise on one case also fits)
    Mistake("rounded determinant", _reads_det_words, reads="det",
            fits=lambda a, e, g: (isinstance(e, str) and not isinstance(g, str)
                                  and bool(np.isfinite(np.asarray(g, float)).all())
                                  and float(np.abs(np.asarray(g, float)).max()) >= SOLVER_NOISE)),
    # r506 W2: a solve's LinAlgError as the only test (the 2×2 elimination's noise)
    Mistake("no zero-area check", _zero_area_words, reads="solve", fits=_solver_noise),
    # r175 B4: ``E + 1e-9`` on a zero area; named only where it gives every zero-area answer
    Mistake("epsilon hid the zero area", _epsilon_on_zero_words, only_whole=True,
            fits=lambda a, e, g: (None if not isinstance(e, str)
                                  else _epsilon_on_zero(a, e, g) is not None)),
    *(Mistake("zero-area test let it through", _let_through_words(read, what), reads=read,
              fits=_let_through)
      for read, what in (("cond", "its condition number"), ("slogdet", "the sign of its determinant"))),
    Mistake("no zero-area check", _zero_area_words,
            fits=lambda a, e, g: isinstance(e, str) and not isinstance(g, str)),
    # r348 item 4: vertices cast to int (truncated), p too or not; the zero-area test on them
    # (r358 4: or rounded)
    *(Mistake(f"vertices {how}", _truncated_words(how, with_p), gives=_truncated(with_p, how))
      for how in WHOLE_PIXELS for with_p in (False, True)),
    # r348 item 1: float32 cannot hold a thin far triangle's vertices: its E becomes 0 (named
    # where the code reads float32: a float64 threshold refuses the same triangle)
    Mistake("float32", _float32_flattened_words, fits=_float32_flattened, reads="float32"),
    # r348 item 1: ``if np.linalg.cond(M) > 1e12: raise ValueError`` refused a thin far one
    Mistake("condition number", _cond_words, reads="cond",
            fits=lambda a, e, g: isinstance(g, str) and not isinstance(e, str)),
    # r421 W2: ``if np.linalg.matrix_rank(M) < 3: raise ValueError`` refused a thin far one
    Mistake("matrix rank", _rank_words, reads="matrix_rank",
            fits=lambda a, e, g: isinstance(g, str) and not isinstance(e, str)),
    Mistake("explicit inverse", _inverse_words, reads="inv", fits=_inverse_fits),
    Mistake("refused a proper triangle", _refused_words,
            fits=lambda a, e, g: isinstance(g, str) and not isinstance(e, str)),
]  # fmt: skip


def _shipped_gives(repaired: tuple):
    def gives(xy, p):
        try:
            return patched_barycentric(xy, p, repaired)
        except ValueError:
            return REFUSED

    return gives


def _shipped_test_words(args, expected, got) -> str:
    return (
        f": this triangle has weights (its E(v1, v2, v3) = {num(_area(args[0]))}, not 0), and "
        "your code refused it with the shipped zero-area test, np.linalg.cond(M) > 1e8: the "
        "users' report 'triangles far from the origin vanish'. What does np.linalg.cond "
        "measure, and how does it change when a triangle keeps its shape and moves across the "
        "screen, or keeps its place and shrinks (3.1's questions)? 3.1 refuses three vertices "
        "on one line, and nothing else"
    )


SHIPPED_AREA_WORDS = (
    ": your λ1 and λ2 have the signs opposite to the weights', and your λ3 = 1 minus their "
    "sum makes up the rest: your code divides by the shipped code's area, abs(E(v1, v2, v3)): "
    "the users' report 'some triangles are shaded with wrong colours'. Which triangles does "
    "abs change, and is there a p of such a triangle where the shipped weights are still right "
    "(3.1's questions)?"
)


def shipped_mistakes() -> list[Mistake]:
    """r506 T1: the shipped code's defects (:func:`.bary_shipped.patched_barycentric`), named
    by their symptoms and the task's questions, not by the repair, where the student's code
    gives the shipped code's answers (one defect or both) on every case. 3.1's text invites the
    check of the shipped code itself: its report told "Divide by the signed E … itself" and
    "test E == 0 exactly", the repair of 3.1 and the reasoning of 3.1b. Any other slip of the
    same kind (a cond limit of 1e12, −|E|) is still named in full by the mistakes after."""
    test = Mistake("the shipped zero-area test", _shipped_test_words, reads="cond",
                   only_whole=True, gives=_shipped_gives(("area",)))  # fmt: skip
    area = Mistake("the shipped area", SHIPPED_AREA_WORDS, reads="abs", only_whole=True,
                   gives=_shipped_gives(("zero-area test",)))  # fmt: skip

    def without(part):
        return _shipped_gives(("zero-area test",) if part.kind == test.kind else ("area",))

    both = Mistake("the shipped zero-area test and the shipped area", "", reads="cond",
                   only_whole=True, gives=_shipped_gives(()), parts=(test, area),
                   without=without)  # fmt: skip
    return [test, area, both]


def barycentric_mistakes() -> list[Mistake]:
    return (shipped_mistakes() + [_degenerate_aware(m) for m in _proper_mistakes()]
            + ZERO_AREA_MISTAKES)  # fmt: skip


def _degenerate_aware(m: Mistake) -> Mistake:
    if m.gives is None:
        return m
    return Mistake(m.kind, m.words, gives=_proper(m.gives))


def _proper_mistakes() -> list[Mistake]:
    out = [
        Mistake("absolute area", _absolute_area_words,
                gives=lambda xy, p: _areas(xy, p) / abs(_area(xy))),
        Mistake("sign", ": every weight has the wrong sign. λ1 = E(v2, v3, p), λ2 = E(v3, v1, p), "
                "λ3 = E(v1, v2, p), each over E(v1, v2, v3): take each edge in the triangle's "
                "order (you have the edges, or the products in E, the other way round)",
                gives=lambda xy, p: -_areas(xy, p) / _area(xy)),
        Mistake("not divided", _sum_words("you did not divide by E(v1, v2, v3) = {area}; the "
                                          "weights always sum to 1"),
                gives=lambda xy, p: _areas(xy, p)),
        Mistake("divided by the area", _sum_words("you divided by the triangle's area, "
                                                  "E(v1, v2, v3)/2; divide by E(v1, v2, v3) = "
                                                  "{area} itself: each weight is a ratio of two "
                                                  "edge functions"),
                gives=lambda xy, p: 2 * _areas(xy, p) / _area(xy)),
        Mistake("unsigned areas", _sum_words("the sub-triangle areas are signed: where p lies "
                                             "outside an edge its weight is negative, so take "
                                             "E(...) itself, not its absolute value"),
                gives=lambda xy, p: np.abs(_areas(xy, p)) / abs(_area(xy))),
        # r94 D3-5: two common mistakes got only the rule (clamping is what the package's
        # perspective_weights does by default)
        *(Mistake("clamped", _clamped_words, gives=_clamped(upper, renormalised))
          for upper in (1.0, np.inf) for renormalised in (True, False)),
        # r421 N1: the vertices read as (y, x) give the very same weights (swapping x and y
        # of every point keeps every ratio of areas), so both are named
        Mistake("p's x and y swapped", ": you swapped p's x and y, or read every vertex as "
                "(y, x) (the two give the same weights): p and the vertices are (x, y), the "
                "column first", gives=lambda xy, p: _areas(xy, np.asarray(p)[::-1]) / _area(xy)),
        Mistake("half areas", _sum_words("you took half of each sub-triangle's E (its "
                                         "area) but divided by the whole E(v1, v2, v3) = "
                                         "{area}, twice the triangle's area: take both as "
                                         "areas or both as E, and the ½ cancels"),
                gives=lambda xy, p: 0.5 * _areas(xy, p) / _area(xy)),
        Mistake("epsilon added to the area", _epsilon_words, fits=_epsilon_fits,
                parameter=_epsilon, only_whole=True),
        scaled_mistake(_scaled_words),
        Mistake("rounded", _rounded_words,
                fits=lambda args, expected, got: _rounded(np.asarray(got, float), expected)),
    ]  # fmt: skip
    out.append(Mistake("reversed where E < 0", REVERSED_WHERE_NEGATIVE,
                       gives=_reversed_where_negative))  # fmt: skip
    # r348 item 4: four slips that got the rule (or its sum) only
    out += [Mistake("p shifted by ½", _p_shifted_words(by), gives=_p_shifted(by))
            for by in (0.5, -0.5)]  # fmt: skip
    out += [Mistake("absolute area, λ3 = 1 − λ1 − λ2" if neg else "sign, λ3 = 1 − λ1 − λ2",
                    _sign_in_two_words(rest, neg), gives=_sign_in_two(rest, neg))
            for neg in (False, True) for rest in range(3)]  # fmt: skip
    # r495 H1, H2: −|E|, E/2 and no division in the shipped code's shape (the rule only)
    out += [Mistake("sign where E > 0, λ3 = 1 − λ1 − λ2", _sign_in_two_words(rest, None),
                    gives=_sign_in_two(rest, None)) for rest in range(3)]  # fmt: skip
    out += [Mistake(f"{by}, λ3 = 1 − λ1 − λ2", _scaled_in_two_words(rest, by),
                    gives=_scaled_in_two(rest, by))
            for by in ("area", "not divided", "unsigned") for rest in range(3)]  # fmt: skip
    out.append(Mistake("p snapped to its pixel centre", _p_snapped_words, gives=_p_snapped))
    out += [Mistake(f"p {how}", _p_coarsened_words(how), gives=_p_coarsened(how))
            for how in P_COARSENED]  # fmt: skip
    out += [Mistake(f"λ3 = {form}", _lambda3_words(form), gives=_lambda3_typo(signs))
            for signs, form in LAMBDA3_SLIPS.items()]  # fmt: skip
    # r455: one weight's sign flipped (after the λ3 slips: λ3 negated is λ1 + λ2 − 1, told so)
    out += [Mistake("one weight's sign", _one_sign_words(k, r), gives=_one_sign(k, r))
            for k in range(3) for r in (None, *(j for j in range(3) if j != k))]  # fmt: skip
    out += _one_weight_mistakes()
    # r358 2: p left untranslated in a solve about one vertex
    out += [Mistake("p not translated", _untranslated_words(k), gives=_untranslated(k))
            for k in range(3)]  # fmt: skip
    out.append(Mistake("no sum equation", _no_sum_row_words,
                       fits=lambda a, e, g: _no_sum_row(a, e, g) and not _is_lstsq(a, g)))  # fmt: skip
    # r455 M1: np.linalg.lstsq on the 3×3 system, the sum row in it: its default rcond drops
    # a thin far triangle's smallest singular value, so it left the sum off by 4e-6 (told
    # "the third equation is missing")
    out.append(Mistake("least squares", _lstsq_words,
                       fits=lambda a, e, g: _no_sum_row(a, e, g) and _is_lstsq(a, g)))  # fmt: skip
    # r421 H2: two vertices swapped to make every triangle run one way, the weights returned
    # in the swapped order (the reversal is "reversed where E < 0" above)
    out += [Mistake("swapped on one winding", _one_winding_words(pair, sign),
                    gives=_one_winding(pair, sign))
            for pair in ((0, 1), (1, 2), (0, 2)) for sign in (-1.0, 1.0)
            if (pair, sign) != ((0, 2), -1.0)]  # fmt: skip
    # r421 H3: the vertices sorted (by y, the scanline habit), the weights in sorted order
    out += [Mistake("vertices sorted", _sorted_words(by), gives=_sorted(by)) for by in SORTS]
    # r421: the sum of the sizes of the three E as the normaliser got the rule only
    out.append(
        Mistake(
            "normalised by Σ|E|",
            _sum_words(
                "you divided by the sum of the sizes |E(...)| of the three sub-triangles, which is "
                "|E(v1, v2, v3)| only where p lies inside, and has no sign; divide by E(v1, v2, v3) = "
                "{area} itself"
            ),
            gives=lambda xy, p: _areas(xy, p) / np.abs(_areas(xy, p)).sum(),
        )
    )
    # r421 N2, H1: a p outside the triangle refused (its negative weight taken for no weights)
    out.append(Mistake("refused p outside", _outside_refused_words, gives=_outside_refused))
    for perm in itertools.permutations(range(3)):
        if perm != (0, 1, 2):
            out.append(Mistake("order", ORDER, gives=lambda xy, p, perm=perm: (_areas(xy, p) / _area(xy))[list(perm)]))  # fmt: skip
    return out


def _one_winding(pair, sign: float):
    """The weights with λ_i and λ_j of ``pair`` swapped where E(v1, v2, v3) has the sign
    ``sign``: ``if E(v1, v2, v3) < 0: v2, v3 = v3, v2`` (r421 H2)."""

    def gives(xy, p):
        lam = _areas(xy, p) / _area(xy)
        if _area(xy) * sign > 0:
            lam[list(pair)] = lam[list(pair[::-1])]
        return lam

    return gives


def _one_winding_words(pair, sign: float) -> str:
    i, j = (k + 1 for k in pair)
    way = "counter-clockwise (E(v1, v2, v3) < 0)" if sign < 0 else "clockwise (E(v1, v2, v3) > 0)"
    return (
        f": your λ{i} and λ{j} are swapped on the triangles that run {way}, and right on the "
        f"others: you swapped v{i} and v{j} to make every triangle run one way (the habit of "
        "coverage code?) and returned the weights in the swapped order. λ_k belongs to v_k as "
        "given: keep the vertices (the signed area serves both windings), or put the two "
        "weights back"
    )


#: r421 H3: how a student sorts the vertices (a stable sort, as Python's sorted is)
SORTS = {
    "y": lambda v: np.argsort(v[:, 1], kind="stable"),
    "x": lambda v: np.argsort(v[:, 0], kind="stable"),
    "y, then x": lambda v: np.lexsort((v[:, 0], v[:, 1])),
}


def _sorted(by: str):
    def gives(xy, p):
        order = SORTS[by](np.asarray(xy, float))
        return (_areas(xy, p) / _area(xy))[order]

    return gives


def _sorted_words(by: str):
    def words(args, expected, got):
        xy, _ = args
        order = SORTS[by](np.asarray(xy, float))
        named = ", ".join(f"v{k + 1}" for k in order)
        return (
            f": your weights are the right ones in the order of the vertices sorted by {by} "
            f"({named}): you sorted the vertices (the scanline habit?) and returned the weights "
            "in that order. λ_k belongs to v_k as given: sort a copy only, or put the weights "
            "back"
        )

    return words


def _outside_refused(xy, p):
    lam = _areas(xy, p) / _area(xy)
    return REFUSED if (lam < 0).any() else lam


def _outside_refused_words(args, expected, got) -> str:
    k = int(np.argmin(expected))
    return (
        f": p lies outside the triangle (outside the edge opposite v{k + 1}, so λ{k + 1} < 0), "
        "and you refused it: a point outside still has weights, one or two of them negative "
        "(3.1 asks for them everywhere); raise ValueError only for a triangle of zero area"
    )


def _far(args) -> tuple[float, float]:
    xy, p = (np.asarray(a, dtype=float) for a in args)
    far = float(np.abs(np.vstack([xy, p])).max())
    return far, float(np.abs(np.vstack([xy, p]) - xy[0]).max())


def bary_float32_words(args, expected, got) -> str | None:
    """Far from the origin, named from the size of the error (r39 03-1): float32's rounding
    of λ itself (the general words), the inputs rounded to float32 (they lose the 1/256-px
    grid), or more than both (a plane in absolute coordinates cancels)."""
    far, _ = _far(args)
    xy, p = args
    spacing = float(np.spacing(np.float32(far)))
    head = f". {num(far)} px from the origin float32 numbers are {num(spacing)} px apart"
    flat = _e32(*np.asarray(xy, dtype=np.float32)) == 0
    if far >= 1e4 and flat and not np.isfinite(np.asarray(got, float)).all():  # r348: thin
        return (
            f"{head} and cannot hold the 1/256-px grid of the vertices: in float32 this thin "
            f"triangle's vertices lie on one line, so its E(v1, v2, v3) = {_area(xy)!r} "
            "becomes 0, and your weights divide by it. Keep the coordinates in float64 (plain "
            "Python floats or np.float64), where E is exact"
        )
    with np.errstate(invalid="ignore"):
        error = float(np.max(np.abs(np.asarray(got, float) - expected)))
    if far < 1e4 or error <= 8 * 2.0**-24 * max(1.0, float(np.abs(expected).max())):
        return None
    moved = barycentric(np.float32(xy).astype(float), np.float32(p).astype(float))
    by_inputs = float(np.max(np.abs(moved - expected)))
    if error <= 4 * by_inputs + 1e-6:
        return (
            f"{head} and cannot hold the 1/256-px grid of the vertices and p: in float32 they "
            f"move by up to {num(spacing / 2)} px, which alone moves λ by {num(by_inputs)}. "
            "Keep the coordinates in float64 (plain Python floats or np.float64)"
        )
    return (
        f"{head}, and a plane A·x + B·y + C evaluated in absolute coordinates cancels "
        "catastrophically (C is about x², the answer far smaller): in float32, compute "
        "differences p − v to a vertex first; better, compute in float64"
    )


def _float32_lambdas(xy, p) -> list[np.ndarray]:
    """λ as a float32 computation gives it: from differences to a vertex, and from the plane
    A·x + B·y + C of each edge in absolute coordinates (whose C, about far², cancels)."""
    f = np.float32
    v, q = np.asarray(xy, dtype=f), np.asarray(p, dtype=f)
    with np.errstate(all="ignore"):
        diffs = np.array([_e32(v[(k + 1) % 3], v[(k + 2) % 3], q) for k in range(3)])
        planes = []
        for k in range(3):
            a, b = v[(k + 1) % 3], v[(k + 2) % 3]
            planes.append((a[1] - b[1]) * q[0] + (b[0] - a[0]) * q[1] + (a[0] * b[1] - b[0] * a[1]))
        area = _e32(v[0], v[1], v[2])
        return [diffs / area, np.array(planes, dtype=f) / area]


def _e32(a, b, p):
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def bary_float32(args) -> float:
    """The scale whose float32 rounding bounds λ's: twice the largest error of the float32
    computations of this case (:func:`_float32_lambdas`), at least λ's own magnitude; so far
    from the origin a cancelling plane's error is float32's, and an error beyond it is not."""
    xy, p = args
    right = barycentric(xy, p)
    errors = [float(np.max(np.abs(lam.astype(float) - right))) for lam in _float32_lambdas(xy, p)]
    worst = max((e for e in errors if np.isfinite(e)), default=0.0)
    return max(2 * worst / (8 * 2.0**-24), float(np.abs(right).max()))


def _bary_rule(args, expected, got) -> str:
    xy, _ = args
    if isinstance(expected, str) or isinstance(got, str):
        return ": a triangle has weights exactly when E(v1, v2, v3) ≠ 0"
    total = float(np.sum(np.asarray(got, dtype=float)))
    # r137 D3-3: a sum other than 1 is said, whatever broke it (λ3 = 1 − λ1 + λ2, ...)
    off = f"; yours sum to {num(total, 1.0)}, not 1" if abs(total - 1) > 1e-6 else ""
    g = np.asarray(got, dtype=float)
    if g.shape == (3,) and np.isfinite(g).all() and not _rebuilds_p(xy, args[1], g, 1e-6):
        # r348 P1: what the student can check on the case's numbers, hint or not
        rebuilt = g @ np.asarray(xy, float)
        # r421 S2: with the digits that tell the two points apart ("(40.5, 1.5), not p =
        # (40.5, 1.5)" was printed)
        off += (
            f"; yours rebuild λ1·v1 + λ2·v2 + λ3·v3 = {vec(rebuilt, args[1])}, not p = "
            f"{vec(args[1], rebuilt)}"
        )
    return (
        f": λ_i = E of the edge opposite v_i at p, divided by E(v1, v2, v3) = {num(_area(xy))}{off}"
    )


def _draw_bary(ax, case, got):
    """The weights as bars, expected beside yours, and beside them the triangle with p and
    the sub-triangle opposite each vertex, whose share of the whole is that vertex's weight
    (r39 03-5: the bars alone did not say which case they were)."""
    from .drawing import difference_note, draw_values

    _, (xy, p), expected = case
    if got is None or isinstance(expected, str) or isinstance(got, str):
        # a zero area, a refusal, or no answer (r153 E13-14: no empty 0-1 axes beside the
        # words); r164: the report's note (a time limit, an exception, not counted) takes the
        # left part, which it would share with the bars or with these words
        ax.set_xticks([])
        ax.set_yticks([])
        for spine in ax.spines.values():
            spine.set_visible(False)
        inset = ax.inset_axes([0.56, 0.06, 0.42, 0.88])
        if got is None:
            return _draw_triangle_and_p(inset, xy, p)
        if isinstance(expected, str):
            said = f"zero area: no weights\n(E(v1, v2, v3) = {num(_area(xy))})"
            if not isinstance(got, str):  # r164: one number a line (three ran under the inset)
                said += "\n\nyours:\n" + "\n".join(
                    f"λ{k + 1} = {x + 0.0:.3g}" for k, x in enumerate(np.asarray(got, dtype=float))
                )
        else:
            said = f"E(v1, v2, v3) = {num(_area(xy))}:\nits weights are\n{vec(expected)}"
            said += "\n\nyou raised ValueError"
        artists = [ax.text(0.27, 0.5, said, transform=ax.transAxes, ha="center", va="center",
                           fontsize="small")]  # fmt: skip
        return artists + _draw_triangle_and_p(inset, xy, p)
    artists = draw_values(ax, ["λ1", "λ2", "λ3"], expected, got)
    if got is not None:  # r153 E16: a float32 failure drew identical bars that said nothing
        artists += difference_note(ax, expected, got)
    ax.set_xlim(-0.6, 6.0)  # the right part of the axes holds the triangle
    ax.set_ylabel("weight")
    low, high = ax.get_ylim()  # r84 03-4: room above the bars for the legend
    ax.set_ylim(low, high + 0.3 * (high - low))
    artists.append(ax.legend(fontsize="x-small", loc="upper left", ncols=2))
    artists += _draw_triangle_and_p(ax.inset_axes([0.56, 0.06, 0.42, 0.88]), xy, p)
    return artists


def _draw_triangle_and_p(ax, xy, p) -> list:
    """The triangle v1 v2 v3 (y down, as on screen), the point p, and the sub-triangle
    opposite each v_i shaded in λ_i's colour."""
    from matplotlib.patches import Polygon

    xy, p = np.asarray(xy, float), np.asarray(p, float)
    # far from the origin, coordinates relative to a corner (matplotlib's ticks would not
    # tell 100000.5 from 100001)
    far = float(np.abs(xy).max()) >= 1000
    origin = np.floor(xy.min(axis=0)) if far else np.zeros(2)
    v, q = xy - origin, p - origin
    colours = ("#1b9e77", "#d95f02", "#7570b3")
    artists = []
    lam = _areas(xy, p) / _area(xy) if _area(xy) else np.zeros(3)
    # r153 E13-14: on a zero-area or sliver triangle the sub-triangles' labels pile up on p
    extent = float(np.ptp(np.vstack([v, q]), axis=0).max()) or 1.0
    labelled = abs(_area(xy)) >= 0.2 * extent**2  # E is twice the area: 0.87 equilateral
    for k in range(3):
        sub = np.array([q, v[(k + 1) % 3], v[(k + 2) % 3]])
        if lam[k] < 0:  # r94 D3-6: a negative share hatched, labelled outside the triangle
            artists.append(ax.add_patch(Polygon(sub, fill=False, hatch="///", lw=1, ls="--",
                                                edgecolor=colours[k])))  # fmt: skip
            centre, label = (q + sub[1:].mean(axis=0)) / 2, f"λ{k + 1} < 0"
        else:
            artists.append(ax.add_patch(Polygon(sub, color=colours[k], alpha=0.3, lw=0)))
            centre, label = sub.mean(axis=0), f"λ{k + 1}"
        if labelled:
            artists.append(ax.annotate(label, centre, ha="center", va="center",
                                       fontsize="small", color=colours[k], zorder=3,
                                       bbox={"boxstyle": "round,pad=0.1", "facecolor": "white",
                                             "edgecolor": "none", "alpha": 0.8}))  # fmt: skip
    ring = np.vstack([v, v[:1]])
    artists += ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    for k in range(3):
        artists.append(ax.annotate(f"v{k + 1}", v[k], fontsize="small", xytext=(3, 3),
                                   textcoords="offset points"))  # fmt: skip
    # r153 E15: p above the λ labels (a label centred near p hid the dot), its name boxed
    artists += ax.plot(*q, "o", color="black", ms=4, zorder=5)
    artists.append(ax.annotate("p", q, fontsize="small", xytext=(5, -11), textcoords="offset points",
                               zorder=5, bbox={"boxstyle": "round,pad=0.05", "facecolor": "white",
                                               "edgecolor": "none", "alpha": 0.9}))  # fmt: skip
    pts = np.vstack([v, q])
    # r153 E14: a margin in proportion (a fixed 0.5 px shrank a 2-px triangle to a speck)
    pad = 0.12 * float(np.ptp(pts, axis=0).max()) or 0.5
    ax.set_xlim(pts[:, 0].min() - pad, pts[:, 0].max() + pad)
    ax.set_ylim(pts[:, 1].max() + pad, pts[:, 1].min() - pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xticks([])
    ax.set_yticks([])
    if far:
        ax.set_xlabel(f"from ({num(origin[0])}, {num(origin[1])})", fontsize="x-small")
    return artists


#: Every package function that computes 3.1's weights, the one list the check reads
#: (:mod:`.package_answers`): ``barycentric`` and every function of its module (r148 D12-5: the
#: package's internals counted as the student's work), and lesson 03's planes and set-up
#: matrix, whose plane of the values (1, 0, 0) at the vertices is λ1 itself (r164 C1: three
#: one-line wrappers of them passed all 157 cases). ``edge_function`` is a tool, not listed.
BARYCENTRIC_ANSWERS = (
    PackageAnswer(barycentric, modules=("teachraster.core.barycentrics",)),
    *(PackageAnswer(f, what=f"the plane of any value over the triangle {how} (the plane of "
                    "the values (1, 0, 0) at the vertices is λ1 itself)")
      for f, how in ((plane_equation, "from A, B, C, D"),
                     (attribute_plane, "from the set-up matrix"))),
    # r175 F2: M maps the value differences (f2 − f1, f3 − f1) to the plane's gradient
    # (lesson 03 §3, g = M(f2 − f1, f3 − f1)); p − v1 goes through its transpose
    # r506 W3: the shipped code with its defects repaired (exercise 3.1b's judge)
    PackageAnswer(patched_barycentric, words=CHECKER_WORDS),
    PackageAnswer(setup_matrix, what="the set-up matrix M of lesson 03, which maps the value "
                  "differences (f2 − f1, f3 − f1) to the plane's gradient: its columns are "
                  "the gradients of λ2 and λ3, so (λ2, λ3) = Mᵀ(p − v1)"),
)  # fmt: skip


#: r175 B7: 3.1 and 3.2 are called once per point, and have no pixels to loop over
ONE_POINT = " (one call computes one point's three weights: it should take microseconds)"


BARYCENTRIC = Exercise(
    "barycentric", barycentric_cases, lambda v: as_numbers(v, (3,), "3 weights, shape (3,)"),
    same_barycentric, explain_barycentric, _bary_rule, barycentric_mistakes(),
    float32=bary_float32, float32_words=bary_float32_words, float32_makes_inf=True,
    answers=BARYCENTRIC_ANSWERS,
    # r506 W3: a wrapper of exercise 3.1b's checker (bary_repair.patched_barycentric with both
    # defects repaired, its exact_weights) passed uncounted: its modules are watched too
    reference=("teachraster.exercises.bary_repair",),
    draw=_draw_bary, call=call_barycentric, slow=ONE_POINT, raised_words=_bary_raised, hints=(
        # r84 03-1: 3.1 asks for the weights by their definition; the first wrong answer
        # must not print the area ratio that the task leaves to the student (r153 D3-6: the
        # whole number, "= 9.343", not up to its decimal point)
        (re.compile(r": λ_i = E of the edge opposite v_i at p, divided by E\(v1, v2, v3\) = "
                    r"-?[0-9.e+-]*[0-9]"), ": the weights rebuild p (λ1·v1 + λ2·v2 + λ3·v3 = p) and sum "
         "to 1; check yours against both on this case"),
        # r94 D3-7: weights in another order were given the area ratio (a 3×3 solve's too)
        (" λ_i belongs to v_i: the area of the sub-triangle opposite v_i (p with the other "
         "two) over the whole", " λ_i belongs to v_i (λ_i = 1 at v_i)"),
        # r107 N3-4: every sign flipped was given the area ratio in full on the first try
        (" λ1 = E(v2, v3, p), λ2 = E(v3, v1, p), λ3 = E(v1, v2, p), each over E(v1, v2, v3): "
         "take", " Take"),
    ),
)  # fmt: skip


# -- perspective ------------------------------------------------------------------------------
def _perspective(lam, w, f) -> float:
    return float(blend(perspective_weights(np.asarray(lam)[None], np.asarray(w)), np.asarray(f))[0])


def perspective_cases():
    rng = np.random.default_rng(SEED + 2)
    ws = [np.array([1.0, 2.0, 4.0])]
    for name in ("perspective_w_ratio_1e6", "perspective_w_scale"):
        # subnormal w (1e-310) is left to the catalogue's own test: there 1/w overflows and a
        # straightforward correct formula would fail for a reason the exercise does not teach
        ws += [w for w in CASES[name].inputs["ws"] if w.min() >= np.finfo(float).tiny]
    ws += list(np.exp(rng.uniform(np.log(0.1), np.log(100.0), size=(8, 3))))
    lams = [np.array([0.2, 0.3, 0.5]), np.array([1.0, 0, 0]), np.array([0, 0.5, 0.5])]
    out = []
    for n, w in enumerate(ws):
        f = np.array([0.0, 1.0, 2.0]) if n == 0 else np.round(rng.uniform(-5, 5, 3), 2)
        for lam in lams + [rng.dirichlet(np.ones(3))]:
            args = (lam, np.asarray(w, dtype=float), f)
            out.append((f"λ={vec(lam)}, w={vec(w)}, f={vec(f)}", args, _perspective(*args)))
    return out


def explain_perspective(args, expected, got) -> str:
    lam, w, f = args
    return f"at λ={vec(lam)}, w={vec(w)}, f={vec(f)} your {num(got, expected)}"


def _right(expected, got) -> str:
    return f"the perspective-correct value is {num(expected, got)}"


def _persp(words):
    """Words after "your X" that also quote the right value."""

    def say(args, expected, got):
        lam, w, f = args
        return " " + words.format(right=_right(expected, got), inv=num(lam @ (1 / w)))

    return say


PERSPECTIVE_MISTAKES = [
    Mistake("affine", _persp("is the affine Σλf; {right}: divide by w"),
            gives=lambda lam, w, f: float(lam @ f)),
    Mistake("times w", _persp("is Σλ·f·w / Σλ·w: you multiplied by w; {right}: divide by w "
                              "instead"),
            gives=lambda lam, w, f: float((lam * w) @ f / (lam @ w))),
    Mistake("unnormalised", _persp("is Σλf/w; {right}: divide it by Σλ/w = {inv} (the "
                                   "interpolated 1/w)"),
            gives=lambda lam, w, f: float((lam / w) @ f)),
    Mistake("times w, unnormalised", _persp("is Σλ·f·w: you multiplied by w and did not "
                                            "normalise; {right}: Σλf/w ÷ Σλ/w"),
            gives=lambda lam, w, f: float((lam * w) @ f)),
    Mistake("divided by the interpolated w", _persp("is Σλf ÷ Σλw: the affine value divided by "
                                                    "the interpolated w; {right}: interpolate "
                                                    "f/w and 1/w, then divide (Σλf/w ÷ Σλ/w)"),
            gives=lambda lam, w, f: float(lam @ f / (lam @ w))),
    Mistake("times the interpolated w", _persp("is Σλf/w · Σλw; {right}: divide Σλf/w by the "
                                               "interpolated 1/w, Σλ/w = {inv}"),
            gives=lambda lam, w, f: float((lam / w) @ f * (lam @ w))),
]  # fmt: skip


def _persp_rule(args, expected, got) -> str:
    lam, w, f = args
    return f"; {_right(expected, got)} = Σλf/w ÷ Σλ/w = {num((lam / w) @ f)} ÷ {num(lam @ (1 / w))}"


def persp_float32(args) -> float:
    lam, w, f = args
    return float(np.abs(f).max()) * 4


def persp_float32_words(args, expected, got) -> str:
    return (
        f"; {_right(expected, got)}: the difference is about float32's rounding (float32 keeps "
        "about 7 significant digits): did you compute in float32? Compute in float64"
    )


def _draw_persp(ax, case, got):
    from .drawing import draw_bars

    lam, w, f = case[1]
    labels = ["perspective-\ncorrect", "affine Σλf"]
    values = [case[2], float(lam @ f)]
    if got is not None:
        labels.append("yours")
        values.append(got)
    wrong = [False, False, got is not None and not close(got, case[2])]
    return draw_bars(ax, labels, values, wrong[: len(values)])


PERSPECTIVE = Exercise(
    "perspective", perspective_cases, as_number, lambda g, e, a: close(g, e),
    explain_perspective, _persp_rule, PERSPECTIVE_MISTAKES, float32=persp_float32,
    float32_words=persp_float32_words,
    answers=(PackageAnswer(perspective_weights),), draw=_draw_persp,
    slow=" (one call computes one point's value: it should take microseconds)",
)  # fmt: skip
