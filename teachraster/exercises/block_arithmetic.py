"""Exercise 8.1's arithmetic (r248): what float64 pixels, int32 registers and a bias that is not
a whole number of units do to ``classify_block``'s exact sign tests, each named by its cause.

The task counts in integer units of 1/256 px, as lesson 10 §4 counts on a GPU's grid (the
package's own walker keeps 512 units a pixel): every vertex and pixel centre is then a whole
number of units, E a whole number of units² (2^-16 px²), and int64 holds every value of the
check's cases (cell 1 prints the count). Three ways out of it:

- **float64 pixels.** A product such as A·(x − x₁) carries 16 bits after the point (8 from each
  factor), so float64's 53 bits hold it exactly only below 2^37 px², for coordinate differences
  up to about 3.7·10⁵ px. The check's vertices reach 2·10⁶ px: E₀ itself is then rounded, and a
  tie or a centre 2^-16 px² off an edge goes either way, with the bias added before the offset or
  after it (r248 F1: "(E₀ + R) + β is exact", the check's own advice, passed every case; the far
  ties of :data:`.tile_blocks.FLOAT64_TIES` now show it).
- **int32 units.** A value past 2^31 wraps (lesson 10 §4: to a negative number or, past 2^32,
  back to a positive one), and the signs the tests read are wrong.
- **a bias of −0.5 units.** E₀ + β is then a float64, and from 2^53 units² on it rounds back to
  a whole number.
"""

from __future__ import annotations

import itertools

import numpy as np

from ..core.edges import setup_edges
from ..core.snapping import SUBPIXEL_BITS
from .block_grid import UNITS, grid_of, same_kind, superscript, verdicts
from .exercise import Mistake
from .scalars import vec

#: float64's significand: a whole number of units² is exact in px² up to this many bits.
FLOAT64_BITS = 53
#: The largest value an int32 register holds.
INT32_MAX = 2**31 - 1


def units_edges(xy) -> list[dict]:
    """The triangle's edges as the task orients them, in integer units of 1/256 px (Python
    ints, exact): per edge its name (v1→v2 …), top-left flag, start vertex and A, B."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    scale = int(setup.unit) // UNITS  # the package's 512 units a pixel: vertices are even there
    p = [(int(x) // scale, int(y) // scale) for x, y in setup.p]
    out = []
    for k in range(3):
        (ax, ay), (bx, by) = p[k], p[(k + 1) % 3]
        name = f"v{setup.perm[k] + 1}→v{setup.perm[(k + 1) % 3] + 1}"
        out.append({"name": name, "top_left": bool(setup.top_left[k]), "a": (ax, ay),
                    "A": ay - by, "B": bx - ax})  # fmt: skip
    return out


def block_terms(edge: dict, bx: int, by: int, size: int) -> dict:
    """Edge ``edge`` over block (bx, by) in units² (exact): E₀, R, T, E at the block's best and
    worst centre (E₀ + R, E₀ + T), the corners, and every term a float64 pixel computation
    rounds (the products of E₀ and of E at the two corners, the sums, the A·x + B·y + C form's)."""
    (ax, ay), A, B = edge["a"], edge["A"], edge["B"]
    x, y = bx * UNITS + UNITS // 2, by * UNITS + UNITS // 2  # the block's first centre
    step = UNITS * (size - 1)
    R, T = step * (max(A, 0) + max(B, 0)), step * (min(A, 0) + min(B, 0))
    e0 = A * (x - ax) + B * (y - ay)
    hi = (x + (step if A > 0 else 0), y + (step if B > 0 else 0))
    lo = (x + (step if A < 0 else 0), y + (step if B < 0 else 0))
    terms = [A * (x - ax), B * (y - ay), e0, R, T, e0 + R, e0 + T, A * x, B * y, A * ax + B * ay]
    for cx, cy in (hi, lo):
        terms += [A * (cx - ax), B * (cy - ay)]
    return {"e0": e0, "R": R, "T": T, "best": e0 + R, "worst": e0 + T, "hi": hi, "lo": lo,
            "terms": terms}  # fmt: skip


def _significant_bits(v: int) -> int:
    """The bits of ``v`` from its highest set bit to its lowest (0 for 0)."""
    v = abs(v)
    return 0 if v == 0 else v.bit_length() - ((v & -v).bit_length() - 1)


def _near_tests(xy, bx: int, by: int, size: int) -> list[tuple]:
    """The sign tests of block (bx, by) that float64 pixels can decide either way: (E at the
    test's centre in units², edge, its terms, "best" (the reject test) or "worst" (the accept
    test)) for each edge with a term float64 does not hold exactly whose E there lies within a
    few of float64's steps of 0, the tests' threshold."""
    found = []
    for edge in units_edges(xy):
        t = block_terms(edge, bx, by, size)
        if max(map(_significant_bits, t["terms"])) <= FLOAT64_BITS:
            continue
        big = max(abs(v) for v in t["terms"])
        reach = 1 << max(big.bit_length() - (FLOAT64_BITS - 3), 0)  # 8 of its steps
        found += [(t[key], edge, t, key) for key in ("best", "worst") if abs(t[key]) <= reach]
    return found


def float64_slip(xy, bx: int, by: int, size: int) -> tuple | None:
    """Where float64 pixels can decide block (bx, by) wrongly (:func:`_near_tests`): (edge,
    its terms, "best" or "worst") of the test nearest its threshold; None where there is none
    (float64 is exact there, or no centre lies that close)."""
    found = _near_tests(xy, bx, by, size)
    if not found:
        return None
    _, edge, t, key = min(found, key=lambda f: abs(f[0]))
    return edge, t, key


def float64_exact(xy, x0, y0, size) -> bool:
    """Does float64 hold every term of every block of the grid exactly (a bound from the
    coordinates' magnitude: every term of :func:`block_terms` is below 16·M², M the largest
    coordinate in units, a block's far side included)?"""
    m = max(float(np.abs(np.asarray(xy, dtype=float)).max()),
            float(np.abs(np.asarray(x0)).max()) + size, float(np.abs(np.asarray(y0)).max()) + size)  # fmt: skip
    units = int(np.ceil(m)) * UNITS + UNITS
    return (16 * units * units).bit_length() <= FLOAT64_BITS


def _differing(args, expected, got):
    """The blocks (x0, y0) of the grid whose verdicts differ."""
    _, x0, y0, _ = args
    gx, gy = np.broadcast_arrays(np.asarray(x0), np.asarray(y0))
    want = np.broadcast_to(np.asarray(expected), gx.shape)
    have = np.broadcast_to(np.asarray(got), gx.shape)
    wrong = want != have
    return [(int(x), int(y)) for x, y in zip(gx[wrong], gy[wrong], strict=True)]


def float64_verdicts(xy, bx: int, by: int, size: int) -> set[str]:
    """The verdicts float64 pixels can give block (bx, by): an edge with a term float64 does
    not hold exactly and E at one of the block's four extreme centres within a few of its steps
    of 0 may pass or fail either test (a slip beside float64 tests other corners), every other
    edge's tests exact (r248: a verdict float64 can never give is not put down to it)."""
    edges = units_edges(xy)
    loose = []
    passes = {}
    for e in edges:
        t = block_terms(e, bx, by, size)
        beta = 0 if e["top_left"] else -1  # E > 0 is E − 1 ≥ 0 in units²
        passes[e["name"]] = (t["best"] + beta >= 0, t["worst"] + beta >= 0)
        step = UNITS * (size - 1)
        corners = [t["e0"] + step * da * e["A"] + step * db * e["B"] for da in (0, 1) for db in (0, 1)]  # fmt: skip
        big = max(abs(v) for v in t["terms"])
        reach = 1 << max(big.bit_length() - (FLOAT64_BITS - 3), 0)  # 8 of its steps
        inexact = max(map(_significant_bits, t["terms"])) > FLOAT64_BITS
        if inexact and min(abs(c) for c in corners) <= reach:
            loose.append(e["name"])
    out = set()
    for free in itertools.product(itertools.product((False, True), repeat=2), repeat=len(loose)):
        tests = dict(passes, **dict(zip(loose, free, strict=True)))
        rejected = not all(best for best, _ in tests.values())
        accepted = all(worst for _, worst in tests.values())
        out.add("rejected" if rejected else ("accepted" if accepted else "partial"))
    return out if loose else set()


def rounded_in_float64(args, expected, got) -> bool | None:
    """Does the answer differ only at blocks float64 pixels can get wrong, each time with a
    verdict float64 can give there (:func:`float64_verdicts`)? None otherwise: the case says
    nothing of float64 (another mistake's, or none's: :attr:`.exercise.Mistake.with_others`
    keeps the words from an answer whose other failures no mistake names)."""
    blocks = _differing(args, expected, got)
    if not blocks or float64_exact(*args):
        return None
    xy, x0, y0, size = args
    gx, gy = np.broadcast_arrays(np.asarray(x0), np.asarray(y0))
    have = np.broadcast_to(np.asarray(got), gx.shape)
    given = {(int(x), int(y)): str(g) for x, y, g in zip(gx.ravel(), gy.ravel(), have.ravel(), strict=True)}  # fmt: skip
    return True if all(given[b] in float64_verdicts(xy, *b, size) for b in blocks) else None


def _px2(units2: int) -> float:
    return units2 / UNITS**2


def sci(x: float) -> str:
    """``x`` with 3 significant digits, as m·10ⁿ ("3.07·10¹¹", "-4.58·10⁻⁵"; 0 as "0")."""
    if x == 0:
        return "0"
    exp = int(np.floor(np.log10(abs(x))))
    if -3 <= exp <= 3:
        return f"{x:.{max(3, exp + 1)}g}"
    return f"{x / 10**exp:.3g}·10{superscript(exp)}"


def float64_words(args, expected, got) -> str:
    """r248 F1: the first block float64 pixels got wrong, its edge, the size of E₀'s products
    and float64's steps there, and what one float form gives."""
    xy, size = args[0], args[3]
    bx, by = _differing(args, expected, got)[0]
    edge, t, key = float64_slip(xy, bx, by, size)
    cx, cy = t["hi"] if key == "best" else t["lo"]
    centre = vec(((cx) / UNITS, (cy) / UNITS))
    e = t[key]
    where = (
        "lies exactly on that edge (E = 0)"
        if e == 0
        else f"lies {abs(e)}/65536 px² {'inside' if e > 0 else 'outside'} that edge"
    )
    big = max(abs(v) for v in t["terms"][:2])  # E₀'s products
    spacing = np.spacing(_px2(big))
    # one float form of it, as a student writes it: A·(x − x₁) + B·(y − y₁), then the offset
    (ax, ay), A, B = edge["a"], edge["A"] / UNITS, edge["B"] / UNITS
    e0 = A * (bx + 0.5 - ax / UNITS) + B * (by + 0.5 - ay / UNITS)
    test = e0 + _px2(t["R"] if key == "best" else t["T"])
    which = "E₀ + R" if key == "best" else "E₀ + T"
    gives = (
        f"; computed as A·(x − x₁) + B·(y − y₁), then + {which[-1]}, it comes out at "
        f"{sci(test)} px², not {sci(_px2(e))}"
        if test != _px2(e)
        else ""
    )
    return (
        "you computed in float64 pixels: with vertices on the 1/256 grid a product such as "
        "A·(x − x₁) has 16 bits after the point, so float64's 53 bits hold it exactly only "
        f"below 2^37 px² ({sci(2.0**37)}, coordinate differences up to about "
        f"{sci(2.0**18.5)} px). Here, "
        f"on edge {edge['name']}, E₀'s products reach {sci(_px2(big))} px², where float64's "
        f"numbers lie 2^{int(np.log2(spacing))} px² apart, more than E's step at a centre "
        f"(2^-16 px²), and the block's centre {centre} {where}: E₀ is rounded, so {which} "
        f"can land on either side{gives}. No bias helps, added before the offset or after it: "
        "the error is in E₀ itself. Count in integer units (256 a pixel, as lesson 10 §4 "
        "counts): int64 holds every value of the check exactly (cell 1)"
    )


#: r248 F1: float64 pixels (E > 0 and E ≥ 0 written out per edge, or the bias added after the
#: offset, as the check itself advised) passed every case: named where the answer differs only
#: at blocks float64 can get wrong, with a verdict float64 can give there, and only where every
#: other failing case is named too (a second slip beside another; a random answer's verdict
#: there is no cause). Before :data:`.tile_blocks.BIAS_LOST`, which also covers these blocks
#: (a bias lost to rounding *and* E₀ rounded: both said, each on its case).
FLOAT64_PIXELS = Mistake(
    "float64 pixels", float64_words, fits=rounded_in_float64, only_whole=True, with_others=True
)


def _grid_reach(xy, x0, y0, size) -> int:
    """The largest |value| (units²) the task's count meets on this grid: twice the area, and
    E₀, R, T and E at the best and worst centre of every block."""
    gx, gy = grid_of(x0, y0)
    edges = units_edges(xy)
    (ax, ay), A, B = edges[0]["a"], edges[0]["A"], edges[0]["B"]
    c = edges[2]["a"]
    reach = abs(B * (c[1] - ay) + A * (c[0] - ax))  # twice the area: E₁₂ at v3
    for edge in edges:
        for bx, by in {(int(gx.min()), int(gy.min())), (int(gx.max()), int(gy.max())),
                       (int(gx.min()), int(gy.max())), (int(gx.max()), int(gy.min()))}:  # fmt: skip
            t = block_terms(edge, bx, by, size)
            reach = max(reach, *(abs(t[k]) for k in ("e0", "R", "T", "best", "worst")))
    return reach


def int32_fits(args, expected, got) -> bool | None:
    """Does this case meet a value past int32's range (so an int32 count wraps on it)?"""
    if not _differing(args, expected, got):
        return None
    return _grid_reach(*args) > INT32_MAX


def int32_words(args, expected, got) -> str:
    reach = _grid_reach(*args)
    return (
        f"your values passed 2^31 and wrapped (lesson 10 §4): counted in units of 1/256 px, "
        f"this case's E reaches {reach:,} units² (about 2^{reach.bit_length() - 1}), past "
        f"int32's 2^31 − 1 = {INT32_MAX:,}; an int32 register wraps around silently, to a "
        "negative number or, past 2^32, back to a positive one, so the signs your tests read "
        "are wrong. Count in int64 (np.int64, or Python's ints): cell 1 prints lesson 10 §4's "
        "count of the bits the check's cases need"
    )


#: r248 half-named 1: int32 units (``astype(np.int32)``; NumPy 1.x's ``astype(int)`` on
#: Windows) failed 12 cases, each told the rule at one centre. Named where the code reads int32
#: and every failing case meets a value past 2^31.
INT32 = Mistake("int32 wrap", int32_words, fits=int32_fits, only_whole=True, reads="int32")


def classify_units(xy, x0, y0, size, beta=-1):
    """The task's answer counted in integer units (the notebook's model solution), the bias
    ``beta`` (units²) added to E₀ of every edge that is neither top nor left: a float β turns
    E₀ + β and both tests into float64 (r248 half-named 7)."""
    gx, gy = grid_of(x0, y0)
    px, py = gx.ravel() * UNITS + UNITS // 2, gy.ravel() * UNITS + UNITS // 2
    edges = units_edges(xy)
    (ax, ay), A, B = edges[0]["a"], edges[0]["A"], edges[0]["B"]
    if B * (edges[2]["a"][1] - ay) + A * (edges[2]["a"][0] - ax) == 0:
        return verdicts(np.ones(gx.shape, bool), False, gx.shape, gx.ndim == 0)
    rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
    step = UNITS * (size - 1)
    for edge in edges:
        (ax, ay), A, B = edge["a"], edge["A"], edge["B"]
        R, T = step * (max(A, 0) + max(B, 0)), step * (min(A, 0) + min(B, 0))
        e0 = A * (px - ax) + B * (py - ay) + (0 if edge["top_left"] else beta)
        rejected |= e0 + R < 0
        accepted &= e0 + T >= 0
    return verdicts(rejected, accepted & ~rejected, gx.shape, gx.ndim == 0)


def half_unit_words(args, expected, got) -> str:
    xy, size = args[0], args[3]
    bx, by = _differing(args, expected, got)[0]
    # the tie the bias should have decided: E = 0 at an extreme centre of an edge neither top
    # nor left, the one with the largest E₀
    ties = [(abs(t["e0"]), e["name"], t) for e in units_edges(xy) if not e["top_left"]
            for t in [block_terms(e, bx, by, size)] if 0 in (t["best"], t["worst"])]  # fmt: skip
    _, name, t = max(ties, key=lambda f: f[0]) if ties else (0, "", None)
    at = (
        f"; here E₀ = {t['e0']:,} units² on edge {name}, and its centre "
        f"{vec([c / UNITS for c in (t['hi'] if t['best'] == 0 else t['lo'])])} lies exactly on "
        "that edge, neither top nor left: E₀ + β rounds to a whole number, and the centre "
        "passes as if there were no bias"
        if t is not None
        else ""
    )
    return (
        "your bias is not a whole number of units (−0.5?): in integer units E, R and T are "
        "whole numbers, but E₀ + β is then a float64, and from 2^53 units² on float64's "
        f"numbers lie 2 or more units² apart{at}. A bias that is a whole number of units keeps "
        "every sum an exact int64 (which whole number is it?)"
    )


def half_unit_fits(args, expected, got) -> bool:
    """Is the answer exactly that of integer units with β = −0.5 (no float64 block left out:
    float64 pixels with a bias of −2^-16 px² fail the same huge tie, and the far float64 ties
    besides, which this count passes)?"""
    return same_kind(got, classify_units(*args, beta=-0.5), args)


#: r248 half-named 7: integer units with β = −0.5 was told "add the bias after the offset, or
#: count in integer units", which the student does. Fitted exactly, not by the exercise's
#: match, which leaves out blocks float64 decides either way.
HALF_UNIT_BIAS = Mistake(
    "bias not a whole number of units", half_unit_words, fits=half_unit_fits, only_whole=True
)
