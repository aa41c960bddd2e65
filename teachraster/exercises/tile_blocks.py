"""Exercise ``classify_block(xy, x0, y0, size)``: a grid of blocks, one evaluation each.

Lesson 10 classifies one block at a time by two corners per edge. Hardware classifies many
blocks at once: the set-up computes, once per triangle and edge, the coefficients of the edge
function and two constant offsets (llvmpipe's ``lp_setup_tri.c``: a trivial-reject offset
``eo`` of one whole pixel step, shifted to each block size, so that its offsets reach one step
past the block's last centre, and the trivial-accept offset derived from it; Abrash,
*Rasterization on Larrabee*: each edge stepped to the trivial-reject corners of 16 blocks with
one vector add, to their trivial-accept corners with another). Each block then costs one
evaluation of each edge function, E₀ at its top-left pixel centre (x0 + ½, y0 + ½): E₀ + R is
the largest value of E over the block's pixel centres, E₀ + T the smallest, with
R = (size − 1)·(max(A, 0) + max(B, 0)) and T = (size − 1)·(min(A, 0) + min(B, 0)) for
E = A·x + B·y + C oriented so that the interior is positive. A block (``size`` × ``size``
pixels, no image border) is *rejected* when one edge fails at E₀ + R, *accepted* when every
edge passes at E₀ + T, *partial* otherwise; each test is the one top-left rule
(CONVENTIONS, *Tiles*), which the task asks to fold into a per-edge bias β (0 on a top or
left edge, −2^-16 px², E's smallest step at a centre, on the others: llvmpipe's ``c + 1`` in
``lp_setup_tri.c`` and ``c − 1`` in ``lp_rast_tri.c``) so that each test is one sign test;
the verdicts are compared, so either way passes. A zero-area triangle rejects every block.
Vertices are on the 1/256 grid. The task counts in integer units, 256 a pixel, as lesson 10
§4 counts on a GPU's grid (r232 M1; the package's own walker keeps 512, r248 C1): a float bias
of a fraction of a px² added to a large E₀ rounds away, and the far ties of :data:`FAR_TIES`
(|E₀| up to 2^38 px²) name that slip; float64 pixels round E₀ itself once its products pass
2^37 px², and :data:`FLOAT64_TIES` name that one (r248 F1, :mod:`.block_arithmetic`). ``x0`` and ``y0`` are integer arrays of one shape (one block
each) and the answer an array of that shape (a single text stands for every block).

The expected answer is computed from the package's pieces: the snapped, oriented set-up
(:func:`teachraster.core.edges.setup_edges`), its exact edge values at each block's four
extreme centres (:func:`~teachraster.core.edges.edge_values_at`) and its tie-aware test
(:meth:`~teachraster.core.edges.EdgeSetup.inside`). The typical mistakes are the same
classification with one knob turned (:func:`classify_with`): the offset of another corner,
the offsets' sign flipped, reject and accept offsets swapped, ``size`` steps for ``size − 1``
(both offsets, or one alone: llvmpipe's reject offset), another tie rule or a bias larger than
E's step, one winding only, two vertices swapped whatever the winding, one axis's term dropped
from the offsets, the edges' kinds read before orienting (r376). Explanations name the
first block of the grid that differs, the edge that decides it and its extreme value.
"""

from __future__ import annotations

import copy
import re
from functools import cache

import numpy as np

from ..core.edges import edge_values_at, passes, setup_edges
from ..core.snapping import SUBPIXEL_BITS, snap
from .answers import short, transposed_shape_words
from .block_grid import KINDS, UNITS, grid_of, same_kind, superscript, verdicts
from .cases import SEED, seeded
from .coverage import covered
from .exercise import Exercise, Knobs, Mistake, PackageAnswer, Slip
from .package_answers import CHECKER_WORDS
from .running import WrongAnswerType
from .scalars import full_number, num, tri_words, vec


def _corners(x0, y0, size: int):
    """Rows and columns of the four extreme pixel centres of a block (of each block: (4, n))."""
    far_y, far_x = y0 + size - 1, x0 + size - 1
    return np.array([y0, y0, far_y, far_y]), np.array([x0, far_x, x0, far_x])


def expected_block(xy, x0, y0, size):
    """The package's verdict for each block of the grid (one text for scalar x0, y0)."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    gx, gy = grid_of(x0, y0)
    scalar = gx.ndim == 0
    if setup.area2 == 0:
        return verdicts(np.ones(gx.shape, bool), False, gx.shape, scalar)
    rows, cols = _corners(gx.ravel(), gy.ravel(), size)  # (4, n)
    e = edge_values_at(setup, rows.ravel(), cols.ravel())  # (4 n, 3), exact, in units²
    ok = np.stack([setup.inside(k, e[:, k]) for k in range(3)], axis=1).reshape(4, -1, 3)
    rejected = (~ok.any(axis=0)).any(axis=-1)
    return verdicts(rejected, ok.all(axis=(0, 2)), gx.shape, scalar)


#: Where a mistaken classify_block evaluates E once per block, and how many steps its offsets
#: span: (x, y, span) from (x0, y0, size).
POINTS = {
    "centres": lambda x0, y0, s: (x0 + 0.5, y0 + 0.5, s - 1),
    "outer corners": lambda x0, y0, s: (x0 + 0.0, y0 + 0.0, s),
    "beyond": lambda x0, y0, s: (x0 + 0.5, y0 + 0.5, s),
    "x0 y0 swapped": lambda x0, y0, s: (y0 + 0.5, x0 + 0.5, s - 1),
    "pixel corners": lambda x0, y0, s: (x0 + 0.0, y0 + 0.0, s - 1),
    # r141 D8.1-3: a one-pixel block's offsets not scaled to the block, or scaled by size/2
    "one step": lambda x0, y0, s: (x0 + 0.5, y0 + 0.5, 1),
    "half size": lambda x0, y0, s: (x0 + 0.5, y0 + 0.5, s / 2),
    # r162 M1: offsets that stop short of the block's last centre: size − 2 steps; the centre
    # form's half span (size − 1)/2 added to the first centre; the centre form with integer
    # division, E at x0 + size//2 ± (size − 1)//2 steps (½ px short on each side)
    "size - 2": lambda x0, y0, s: (x0 + 0.5, y0 + 0.5, s - 2),
    # r198 B: E₀ at (x0 + 1, y0 + 1), the first pixel's bottom-right corner
    "bottom-right corners": lambda x0, y0, s: (x0 + 1.0, y0 + 1.0, s - 1),
    "half span": lambda x0, y0, s: (x0 + 0.5, y0 + 0.5, (s - 1) / 2),
    # r446 H1, H4: x0 and y0 read as block indices (the block at x0·size); the ½ in one axis
    "block index": lambda x0, y0, s: (x0 * s + 0.5, y0 * s + 0.5, s - 1),
    "half in x only": lambda x0, y0, s: (x0 + 0.5, y0 + 0.0, s - 1),
    "half in y only": lambda x0, y0, s: (x0 + 0.0, y0 + 0.5, s - 1),
    "centre floored": lambda x0, y0, s: (
        x0 + s // 2 - (s - 1) // 2,
        y0 + s // 2 - (s - 1) // 2,
        2 * ((s - 1) // 2),
    ),
}


def _pos(v):
    return np.maximum(v, 0)  # (0, not 0.0: integer units stay integers, r248)


def _neg(v):
    return np.minimum(v, 0)


#: The (reject, accept) offsets from E's coefficients a = ∂E/∂x, b = ∂E/∂y and the span d,
#: right and wrong.
OFFSETS = {
    "right": lambda a, b, d: (d * (_pos(a) + _pos(b)), d * (_neg(a) + _neg(b))),
    "x mirrored": lambda a, b, d: (d * (_neg(a) + _pos(b)), d * (_pos(a) + _neg(b))),
    "y mirrored": lambda a, b, d: (d * (_pos(a) + _neg(b)), d * (_neg(a) + _pos(b))),
    "far corner": lambda a, b, d: (d * (a + b), 0 * a),
    "sign flipped": lambda a, b, d: (-d * (_pos(a) + _pos(b)), -d * (_neg(a) + _neg(b))),
    "swapped": lambda a, b, d: (d * (_neg(a) + _neg(b)), d * (_pos(a) + _pos(b))),
    "two corners": lambda a, b, d: (_pos(d * (a + b)), _neg(d * (a + b))),
    # r198 B: the middle's half span ±(|A| + |B|) taken whole from the first centre
    "both ways": lambda a, b, d: (d * (abs(a) + abs(b)), -d * (abs(a) + abs(b))),
    # r248 half-named 2-4: one test without its offset (E₀ alone), and A taken as y₂ − y₁,
    # its minus sign lost in the offsets (E₀ has it)
    "no accept offset": lambda a, b, d: (d * (_pos(a) + _pos(b)), 0 * a),
    "no reject offset": lambda a, b, d: (0 * a, d * (_neg(a) + _neg(b))),
    "A's sign lost": lambda a, b, d: (d * (_pos(-a) + _pos(b)), d * (_neg(-a) + _neg(b))),
    # r376 F3: one axis only, B's term (the rows) or A's (the columns) dropped, from both
    # offsets or from the reject offset alone
    "x only": lambda a, b, d: (d * _pos(a), d * _neg(a)),
    "y only": lambda a, b, d: (d * _pos(b), d * _neg(b)),
    "reject x only": lambda a, b, d: (d * _pos(a), d * (_neg(a) + _neg(b))),
    "reject y only": lambda a, b, d: (d * _pos(b), d * (_neg(a) + _neg(b))),
    # r396 G1 (r446): the accept offset as the reject offset mirrored, T = −R (or R = −T)
    "accept mirrored": lambda a, b, d: (d * (_pos(a) + _pos(b)), -d * (_pos(a) + _pos(b))),
    "reject mirrored": lambda a, b, d: (-d * (_neg(a) + _neg(b)), d * (_neg(a) + _neg(b))),
}


def _owns(tie: str, setup, k: int, d, tl=None) -> bool:
    """Does edge k (running along ``d``) own a centre exactly on it, under rule ``tie``?
    ``tl``: the edge's top-left flag as the student's code has it (the set-up's by default)."""
    tl = bool(setup.top_left[k]) if tl is None else tl
    owns = {"strict": False, "loose": True, "top-left": tl}.get(tie)
    return edge_kind(d) in tie.split("-") if owns is None else owns


#: A top-left rule folded into the set-up as a bias, llvmpipe's way (``lp_setup_tri.c`` adds 1
#: to a top-left edge's constant, ``lp_rast_tri.c`` subtracts 1 "so we can just check the sign
#: bit"): a slip biases the other edges by a wrong amount (px²), so that E ≥ bias passes there.
#: r149 M2: every size from 2^-15 to 2^-9 gives the verdicts of 2^-8 on the fixed cases, and was
#: told "a bias of 1/256 px²": the words measure the student's own from the answer
#: (:func:`_bias_range`); M4: the bias added, not taken off (E ≥ −2^-16 passes).
BIASES = {"bias 2^-15": 2.0**-15, "bias 1/256": 2.0**-8, "bias 1": 1.0, "bias 1/2": 0.5,
          "bias added": -(2.0**-16)}  # fmt: skip


#: A tie rule for each test, (reject, accept), where the two tests differ: the rule in the reject
#: test only (r141 D8.1-6), or the bias in one test only (r232: no bias in the reject test is
#: llvmpipe's trivial reject on the edges that are neither top nor left).
SPLIT_TIES = {"accept strict": ("top-left", "strict"), "reject loose": ("loose", "top-left"),
              "accept loose": ("top-left", "loose")}  # fmt: skip


def _passes(e, tie: str, setup, k: int, d, tl=None) -> np.ndarray:
    """Edge k's test of the values ``e`` (units² of the package's grid, :func:`classify_with`)
    under rule ``tie`` (a bias: E ≥ it off top-left edges; "plus one": llvmpipe's +1 on a top
    or left edge's constant without its −1 on every one, E ≥ −2^-16 px² there and E ≥ 0
    elsewhere, r248 half-named 5). ``tl``: the edge's top-left flag as the student's code
    has it (r376 F1, F4: an edge as given, or the flag of another edge)."""
    per_px2 = setup.unit**2  # units² a px² (a bias in px² is a whole number of them)
    tl = bool(setup.top_left[k]) if tl is None else tl
    if tie == "plus one":
        return e >= (-round(STEP * per_px2) if tl else 0)
    if tie in BIASES:
        return e >= (0 if tl else round(BIASES[tie] * per_px2))
    return passes(e, _owns(tie, setup, k, d, tl))


def _given_flags(xy, unit) -> list[bool]:
    """The top-left flag of each edge of the triangle as given (v1→v2, v2→v3, v3→v1)."""
    g = np.rint(snap(np.asarray(xy, dtype=float)) * unit).astype(np.int64)
    return [edge_kind(g[(k + 1) % 3] - g[k]) in ("top", "left") for k in range(3)]


def _oriented(xy):
    """The triangle's edge set-up on the 1/256 grid, and whether it runs counter-clockwise on
    screen (y down: the set-up re-ordered its vertices)."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    return setup, bool(setup.perm[1] == 2)


def classify_with(xy, x0, y0, size, *, points="centres", offsets="right", tie="top-left", orient=True, logic="per edge", longer=""):  # fmt: skip
    """classify_block with the usual mistakes as knobs (the defaults are the right answer).

    One evaluation E₀ of each edge per block at ``POINTS[points]``, plus the per-edge
    ``OFFSETS[offsets]``. ``tie``: "top-left", "strict" (E > 0), "loose" (E >= 0), another
    rule of two kinds of edges ("bottom-right", "top-right", "bottom-left", r107 N8-2), or
    "as given": the top-left rule of each edge as given, before orienting it (r114 D8-4: the
    bottom-right rule on a counter-clockwise triangle), or "read before orienting": the flags
    of the edges as given on the oriented edges, index by index (r376 F4), or "accept strict": the rule in the
    reject test only, the accept test E > 0 on every edge (r141 D8.1-6), or a key of
    :data:`BIASES` (the rule folded into a bias of the wrong size, ex30a). ``orient`` False: the
    edges as given; "cull": every block of a counter-clockwise triangle rejected (r114 item 5);
    "flipped": oriented the wrong way, the interior on every edge's negative side (r141
    D8.1-4; the top-left rule then read from those edges' own kinds); "unchecked": the edges
    as given and no area computed, so a zero-area triangle is not rejected either (r149 M1);
    "swap always": two vertices swapped whatever the winding (code for counter-clockwise
    triangles only: a clockwise one is then oriented the wrong way, r214 item 4).
    "reject loose" or "accept loose": no bias in that test alone (r232: E ≥ 0 on every edge
    there, the other test right; :data:`SPLIT_TIES`).
    ``longer``: "reject" or "accept", that offset alone spans one step more (size steps from
    the first centre: llvmpipe's cautious reject offset, r214 item 3). ``logic``
    "inside" rejects a block whose four extreme points all lie outside the triangle and
    accepts one whose points all lie inside (no per-edge test); "accept by the best corner"
    accepts a block every edge's maximising corner passes; "every edge rejects" rejects a block
    only when all three edges fail their reject test (``&=`` for ``|=``, r267); "reject at
    zero", "accept above zero" a test's comparison slipped (r162; r376 F5: combined with the
    others). Edge functions in integer units of
    the package's grid (512 a pixel: vertices on the 1/256 grid and points on the 1/2 grid are
    whole numbers of them), exact at any size (r248 F1: in float64 pixels a slip with no
    effect on a far float64 tie was named there, for float64's rounding).
    """
    gx, gy = grid_of(x0, y0)
    scalar, shape = gx.ndim == 0, gx.shape
    px, py, d = POINTS[points](gx.ravel(), gy.ravel(), size)
    setup, ccw = _oriented(xy)
    if orient == "swap always":  # right for a counter-clockwise triangle, flipped otherwise
        orient = True if ccw else "flipped"
    if (setup.area2 == 0 and orient != "unchecked") or (orient == "cull" and ccw):
        return verdicts(np.ones(shape, bool), False, shape, scalar)
    if logic == "inside":
        xs, ys = np.array([px, px + d, px, px + d]), np.array([py, py, py + d, py + d])
        inside = covered(np.asarray(xy, dtype=float), np.stack([xs.ravel(), ys.ravel()], axis=1))
        inside = inside.reshape(4, -1)
        return verdicts(~inside.any(axis=0), inside.all(axis=0), shape, scalar)
    if tie == "as given":
        tie = "bottom-right" if ccw else "top-left"
    tie, accept_tie = SPLIT_TIES.get(tie, (tie, tie))
    given = orient in (False, "unchecked")
    # r248 F1: in integer units of the package's grid (every point here is on the 1/2 grid,
    # every vertex on the 1/256 one), exact at any size: float64 pixels round past 2^37 px²
    unit = setup.unit
    v = np.rint(snap(np.asarray(xy, dtype=float)) * unit).astype(np.int64) if given else setup.p
    px, py = (np.rint(np.asarray(c, dtype=float) * unit).astype(np.int64) for c in (px, py))
    d = int(round(d * unit))
    if orient == "unchecked" and tie == "top-left":
        tie = accept_tie = "left-top"  # the rule from the kinds of the edges as given
    # r376 F1: the edges as given take their top-left flags (a bias's too) from themselves, as
    # the student's code reads them; F4: "read before orienting", the oriented edges with the
    # flags of the edges as given, index by index
    tl = [None] * 3
    if given or tie == "read before orienting":
        tl = _given_flags(xy, unit)
        tie = "top-left" if tie == "read before orienting" else tie
        accept_tie = "top-left" if accept_tie == "read before orienting" else accept_tie
    if orient == "flipped":
        v = v[[0, 2, 1]]
        # the rule from the kinds of these (wrongly oriented) edges, as the student's code has it
        tie, accept_tie = ("left-top" if t == "top-left" else t for t in (tie, accept_tie))
    rejected = np.zeros(px.shape, bool)
    accepted = np.ones(px.shape, bool)
    every_fails = np.ones(px.shape, bool)
    one_passes = np.zeros(px.shape, bool)
    # r162: a test's comparison slipped (≤ 0 for < 0, > 0 for ≥ 0): its value one step of E at
    # a centre lower; r376 F5: here, so that it combines with the other knobs
    low = round(STEP * unit**2)
    rj, ac = (low if logic == name else 0 for name in SIGN_SLIPS)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        e0 = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
        r, t = OFFSETS[offsets](-(b[1] - a[1]), b[0] - a[0], d)
        if longer:  # one offset a step longer than the other
            r2, t2 = OFFSETS[offsets](-(b[1] - a[1]), b[0] - a[0], d + unit)
            r, t = (r2, t) if longer == "reject" else (r, t2)
        rejected |= ~_passes(e0 + r - rj, tie, setup, k, b - a, tl[k])
        every_fails &= ~_passes(e0 + r - rj, tie, setup, k, b - a, tl[k])
        accepted &= _passes(e0 + t - ac, accept_tie, setup, k, b - a, tl[k])
        one_passes |= _passes(e0 + t - ac, accept_tie, setup, k, b - a, tl[k])
    if logic == "every edge rejects":  # r267 half-named 2: ``rejected &=`` for ``|=``
        rejected = every_fails
    if logic == "accept by the best corner":
        accepted = ~rejected
    if logic == "accept by one edge":  # r446 H3: ``accepted |=`` for ``&=``
        accepted = one_passes
    return verdicts(rejected, accepted & ~rejected, shape, scalar)


#: r162: the sign tests with the wrong comparison: the reject test E₀ + R + β ≤ 0 (a block
#: whose best centre has E + β = 0, which passes the pixel test, rejected), or the accept test
#: E₀ + T + β > 0 (a block whose worst centre has E + β = 0 left partial). E and β are
#: multiples of E's step at a centre, 2^-16 px² (``STEP``), so "> 0" is "≥ STEP".
SIGN_SLIPS = ("reject at zero", "accept above zero")
#: The smallest positive value E takes at a pixel centre (px²), vertices on the 1/256 grid.
STEP = 2.0**-16


def edge_kind(d) -> str:
    """The kind of an edge ("top", "bottom", "left" or "right") running along ``d`` with the
    interior on its positive side (y pointing down)."""
    return ("top" if d[0] > 0 else "bottom") if d[1] == 0 else ("left" if d[1] < 0 else "right")


def as_kind(value):
    """The answer as an array of verdict texts (or one text, standing for every block)."""
    names = ", ".join(repr(k) for k in KINDS)
    if value is None:
        raise WrongAnswerType("returned None (a missing `return`?)")
    if isinstance(value, str):
        if value not in KINDS:
            raise WrongAnswerType(f"returned the text {short(value)}; expected one of {names}")
        return value
    try:
        kinds = np.asarray(value, dtype=object)
    except (TypeError, ValueError):
        kinds = None
    if kinds is None or kinds.dtype != object or kinds.size == 0 and kinds.ndim == 0:
        raise WrongAnswerType(f"returned {short(value)}; expected an array of the texts {names}, one per block")  # fmt: skip
    bad = [k for k in kinds.ravel() if not isinstance(k, str) or k not in KINDS]
    if bad and kinds.ndim == 0:  # r214 item 12: "returned 0, holding 0" said it twice
        raise WrongAnswerType(
            f"returned {short(value)}, not a verdict; expected an array of the texts {names}, "
            "one per block"
        )
    if bad:
        raise WrongAnswerType(
            f"returned {short(value)}, which holds {short(bad[0])}; expected one of the texts "
            f"{names} for each block"
        )
    return kinds.astype("<U8")


def call_block(fn, args):
    """The student's answer on a grid, read strictly: one verdict per block, x0's shape."""
    got = as_kind(fn(*args))
    shape = np.shape(args[1])
    if not isinstance(got, str) and got.shape != shape:
        raise WrongAnswerType(
            f"returned {got.size} verdicts of shape {got.shape}; expected one per block, an "
            f"array of shape {shape}, the shape of x0 and y0{transposed_shape_words(got.shape, shape)}"
        )
    return got


def match_kind(got, answer, args) -> bool:
    """Does a mistake's answer give the student's? Blocks that float64 pixels can decide
    either way (:func:`.block_arithmetic.float64_slip`: E₀'s products past 2^37 px², the
    deciding centre within float64's steps of an edge) are left out of the comparison: the
    mistakes compute in float64 pixels, the student in whatever it chose (r248 F1: a slip in
    float64 or in integer units is named by the slip, the far ties' rounding by its own)."""
    if answer is None:
        return False
    if same_kind(got, answer, args):
        return True
    if isinstance(got, str) or isinstance(answer, str) or np.shape(got) != np.shape(answer):
        return False
    from .block_arithmetic import float64_exact, float64_slip

    xy, x0, y0, size = args
    if float64_exact(xy, x0, y0, size):
        return False
    gx, gy = grid_of(x0, y0)
    differ = np.asarray(got) != np.asarray(answer)
    return all(float64_slip(xy, int(bx), int(by), size) is not None
               for bx, by in zip(gx[differ], gy[differ], strict=True))  # fmt: skip


def first_block(args, expected, got):
    """The first block (in the grid's order) whose verdict differs: (index, scalar args,
    expected, got, how many differ)."""
    xy, x0, y0, size = args
    gx, gy = grid_of(x0, y0)
    want = np.broadcast_to(np.asarray(expected), gx.shape)
    have = np.broadcast_to(np.asarray(got), gx.shape)
    wrong = np.argwhere(want != have)
    idx = tuple(int(i) for i in wrong[0]) if len(wrong) else (0,) * gx.ndim
    block = (xy, int(gx[idx]), int(gy[idx]), size)
    return idx, block, str(want[idx]), str(have[idx]), len(wrong)


def _at_first(words):
    """``words`` of one block, said of the first block of the grid that differs."""
    if not callable(words):
        return words

    def said(args, expected, got):
        _, block, e, g, _ = first_block(args, expected, got)
        return words(block, e, g)

    return said


def _coefficients(xy) -> str:
    """Each oriented edge's A = ∂E/∂x and B = ∂E/∂y, in px."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    v = setup.p / setup.unit
    out = []
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        name = f"v{setup.perm[k] + 1}→v{setup.perm[(k + 1) % 3] + 1}"
        out.append(f"{name}: A = {num(-(b[1] - a[1]))}, B = {num(b[0] - a[0])}")
    return "; ".join(out)


def _two_corners(args, expected, got) -> str:
    xy, x0, y0, size = args
    # r94 D8-8: the reason is this case's ("partial; yours says rejected" was told an edge
    # "can pass both and fail the other two")
    why = (
        "fail both and pass one of the other two: it then rejects nothing"
        if got == "rejected"
        else "pass both and fail one of the other two: the block is then not accepted"
    )
    return (
        f"you tested only 2 of the 4 extreme centres, ({num(x0 + 0.5)}, {num(y0 + 0.5)}) and "
        f"({num(x0 + size - 0.5)}, {num(y0 + size - 0.5)}): an edge can {why}; test all four "
        "(or, per edge, the one its signs pick)"
    )


def _tie_words(args, expected, got) -> str:
    xy, x0, y0, size = args
    edge, c = _on_edge(_edge_table(xy, x0, y0, size), expected, got)
    if edge is None:
        return "a centre on an edge is decided by the top-left rule, as every pixel centre is"
    rule = "includes" if edge["owns"] else "excludes"
    return f"corner {vec(c)} lies exactly on edge {edge['name']}, a {edge['kind']} edge: the top-left rule {rule} it"  # fmt: skip


def _rule_slip(rule: str) -> Slip:
    """A mirrored tie rule (r107 N8-2: the bottom-right rule was told "you tested the pixels'
    top-left corners", whose verdict it shares on a vertical left edge)."""
    kinds = ("top", "bottom", "left", "right")
    mine, others = rule.split("-"), [k for k in kinds if k not in rule.split("-")]

    def words(args, expected, got):
        return (
            f"your edge tests follow a {rule} rule (a centre on a {mine[0]} or {mine[1]} edge "
            f"passes, on a {others[0]} or {others[1]} edge fails): the conventions use the "
            f"top-left rule; here {_tie_words(args, expected, got)}"
        )

    return Slip(f"{rule} rule", _at_first(words), rule)


def _px2(v: float) -> str:
    """A value of E in px², exact (a dyadic fraction: "1/65536", "3/2")."""
    from fractions import Fraction

    f = Fraction(float(v))
    return str(f) if abs(f.numerator) < 1000 else f"{float(v):.4g}"


def _bias_range(xy, x0, y0, size, got):
    """The biases β' (E ≥ β' passes on an edge that is neither top nor left) that give the
    answer's verdicts on this grid: (lo, hi), lo < β' ≤ hi (None where the answer is no bias).

    A block's verdict falls as β' grows: accepted while β' ≤ a (its non-top-left edges'
    smallest E₀ + T), rejected once β' > r (their smallest E₀ + R), partial between; a top-left
    edge's test does not move, so a block it decides says nothing about β'."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    gx, gy = grid_of(x0, y0)
    if setup.area2 == 0:
        return None
    rows, cols = _corners(gx.ravel(), gy.ravel(), size)
    e = (edge_values_at(setup, rows.ravel(), cols.ravel()) / setup.unit**2).reshape(4, -1, 3)
    hi_e, lo_e = e.max(axis=0), e.min(axis=0)  # (n, 3): E₀ + R, E₀ + T in px²
    tl = np.asarray(setup.top_left, bool)
    if not tl.all():
        r = np.where(tl, np.inf, hi_e).min(axis=1)
        a = np.where(tl, np.inf, lo_e).min(axis=1)
    else:
        return None
    fixed_rej = (hi_e[:, tl] < 0).any(axis=1)
    fixed_part = ~(lo_e[:, tl] >= 0).all(axis=1)
    have = np.broadcast_to(np.asarray(got), gx.shape).ravel()
    lo, hi = -np.inf, np.inf
    for i, g in enumerate(have):
        if fixed_rej[i]:
            continue
        if g == "accepted":
            hi = min(hi, a[i])
        elif g == "rejected":
            lo = max(lo, r[i])
        elif fixed_part[i]:
            hi = min(hi, r[i])
        else:
            lo, hi = max(lo, a[i]), min(hi, r[i])
    return (lo, hi) if lo < hi else None


def _bias_words(args, expected, got) -> str:
    """r149 M2, M4: the student's own bias, measured from the answer, and what it loses."""
    span = _bias_range(*args, got)
    if span is None:  # with another slip: no one bias gives this grid's verdicts
        return (
            "your sign tests take a bias of the wrong size or sign off the edges that are "
            "neither top nor left: the bias must be the smallest positive value E can take at "
            "a pixel centre, taken off E there, with vertices on the 1/256 grid (which is it?)"
        )
    lo, hi = span
    if hi <= 0:
        acts = (
            "on such an edge (E = 0), and so one just outside it (E < 0) too"
            if hi == 0
            else f"whose E is as low as {_px2(hi)} px²"
        )
        return (
            "your bias has the wrong sign: on the edges that are neither top nor left your "
            f"sign tests pass a centre {acts}: a centre outside such an edge counts as "
            "inside; there E must be > 0: take the bias off E (β < 0), do not add it"
        )
    lo = max(lo, 0.0)
    upper = f" and at most {_px2(hi)} px²" if np.isfinite(hi) else ""
    return (
        "your sign tests take a bias of the wrong size off the edges that are neither top nor "
        f"left: on this grid yours acts like a bias above {_px2(lo)} px²{upper} (a centre "
        f"there passes only where E ≥ the bias), so a centre with 0 < E ≤ {_px2(lo)} on such "
        "an edge is covered, yet your tests leave it out; the bias must be the smallest "
        "positive value E can take at a pixel centre, with vertices on the 1/256 grid (which "
        "is it?)"
    )


def _bias_slip(name: str) -> Slip:
    """The top-left rule folded into a bias of the wrong size or sign (ex30a: the task's
    sign-only tests, llvmpipe's ``c − 1``): the words measure the student's bias from the
    answer (r149 M2: every size was told "1/256 px²") and say which centres it loses."""
    kind = "tie-rule bias added" if BIASES[name] < 0 else "tie-rule bias too large"
    return Slip(kind, _bias_words, name)


def _unchecked_words(args, expected, got) -> str:
    """r149 M1: the edges taken as given, no area computed: the signature on each failing case
    (a counter-clockwise triangle, or a zero-area one)."""
    xy = np.asarray(args[0], dtype=float)
    why = (
        "you took the edges as given and never computed the triangle's area (twice its signed "
        "area, E₁₂ at v3, is what says the winding): handle both windings (orient the edges so "
        "that the interior is positive) and reject every block of a zero-area triangle"
    )
    if setup_edges(xy, SUBPIXEL_BITS).area2 == 0:
        return f"{tri_words(xy)} are collinear, and a zero-area triangle rejects every block; {why}"  # fmt: skip
    return f"this triangle runs counter-clockwise on screen, so its interior lies on the negative side of the edges as given; {why}"  # fmt: skip


def _offset_words(text: str):
    """A wrong-offset mistake's words, with the case's coefficients (the set-up's numbers)."""
    return lambda a, e, g: f"{text} (this triangle's edges, oriented: {_coefficients(a[0])})"


#: The offset mistakes (the task's question: which constants, added to E₀, give E's largest
#: and smallest value over the block's centres?).
OFFSET_SLIPS = [
    Slip("offsets of another corner (x)", _offset_words(
        "your offsets take the wrong column of the block: E grows to the right where "
        "A = ∂E/∂x > 0, so its largest value lies in the block's right-most column of centres "
        "there and in its left-most where A < 0 (the smallest on the other side); yours take "
        "the opposite column"), "x mirrored"),
    Slip("offsets of another corner (y)", _offset_words(
        "your offsets take the wrong row of the block: E grows downwards where B = ∂E/∂y > 0, "
        "so its largest value lies in the block's bottom row of centres there and in its top "
        "row where B < 0 (the smallest on the other side); yours take the opposite row"),
        "y mirrored"),
    Slip("offsets of one fixed corner", _offset_words(
        "your offsets ignore the signs of A = ∂E/∂x and B = ∂E/∂y: (size − 1)·(A + B) is E's "
        "change to the bottom-right centre, the largest value only where A ≥ 0 and B ≥ 0, and "
        "E₀ itself the smallest only there; each edge's signs pick its own corners"),
        "far corner"),
    Slip("offset signs flipped", "you subtracted the offsets (or flipped their signs): E₀ "
         "minus the reject offset is E at a point up and to the left of the block, outside "
         "it; E's largest value over the block's centres is E₀ + R with R ≥ 0, its smallest "
         "E₀ + T with T ≤ 0", "sign flipped"),
    # r141 D8.1-7: "(E₀ plus the reject offset, ≥ 0)" read as E₀ + R ≥ 0, the opposite of
    # failing. D8.1-5: rejecting by E₀ + T with the accept test right gives the same verdicts
    # as both offsets swapped (a block no edge rejects at E₀ + T passes everywhere), and was
    # told "you accepted by the largest": the words say only what both do
    Slip("rejected by the smallest value", "you rejected by E's smallest value over the "
         "block, E₀ + T (the offsets swapped, or the accept offset in the reject test): a "
         "block is rejected only when one edge fails even at its largest value over the block "
         "(E₀ + R, with R ≥ 0), and accepted when every edge passes even at its smallest "
         "(E₀ + T, with T ≤ 0)", "swapped"),
]  # fmt: skip


def _span_words(what: str, why: str, span):
    """A wrong number of steps in the offsets (r141 D8.1-3: one step, a one-pixel block's
    offset not scaled, was told "Corners outside the triangle do not reject a block")."""

    def words(a, e, g):
        size = a[3]
        steps, need = span(size), size - 1
        # r162 M1: the mirror of the overshoot's "they reach x0 + size + ½": where they stop
        reach = steps + 0.5
        at = f"x0 {'+' if reach >= 0 else '−'} {num(abs(reach))} = {num(a[1] + reach)}"
        how = (
            f"reach only {at} (and y0 alike), short of the block's last pixel centre, so they "
            "fall short of E's largest and smallest values over its centres (a block holding "
            "a covered centre can be rejected: a hole)"
            if steps < need
            else "reach beyond its last centre"
        )
        return (
            f"your offsets span {what} ({num(steps)} for this {size}-px block{why}): they {how}; "
            f"the block's last pixel centre lies size − 1 = {need} steps from its first: scale "
            "the offsets by size − 1"
        )

    return _at_first(words)


def _centre_floored_words(args, expected, got) -> str:
    """r162 M1: the centre form with integer division (x0 + size//2, (size − 1)//2 steps)."""
    _, (_, bx, _, size), _, _, _ = first_block(args, expected, got)
    lo, hi = size // 2 - (size - 1) // 2, size // 2 + (size - 1) // 2
    return (
        "your offsets come from the block's middle with integer division (x0 + size//2, "
        f"(size − 1)//2 steps either way?): for this {size}-px block they reach from "
        f"x0 + {lo} = {num(bx + lo)} to x0 + {hi} = {num(bx + hi)}, short of the block's "
        f"extreme centres {num(bx + 0.5)} and {num(bx + size - 0.5)} (a block holding a covered "
        "centre can be rejected: a hole); the middle of the centres lies at x0 + size/2, and "
        "the half span is (size − 1)/2, not a whole number for an even size"
    )


def _read_yx(xy, x0, y0, size):
    """The package's verdicts with each vertex read as (y, x): the triangle mirrored about the
    diagonal x = y."""
    return expected_block(np.asarray(xy, dtype=float)[:, ::-1], x0, y0, size)


#: r232 half-named 3: the vertices read as (y, x) give the verdicts of x0 and y0 swapped
#: wherever no tie on a sloped edge tells them apart (mirrored about the diagonal, a triangle's
#: top edges become left edges): said both ways where both give the answer.
_AXES = {
    "x0 y0": "you swapped x0 and y0: x0 holds the blocks' first columns (x), y0 their first "
    "rows (y); a block's first pixel centre lies at (x0 + ½, y0 + ½)",
    "yx": "you read the vertices as (y, x): each row of xy is one vertex's (x, y), x first (to "
    "the right), then y (down); read the other way, the triangle is mirrored about the "
    "diagonal x = y",
    "both": "you swapped x0 and y0, or read the vertices as (y, x): on this case the two give "
    "the same verdicts (the blocks mirrored about the diagonal x = y, or the triangle), so the "
    "check cannot tell which; x0 holds the blocks' first columns (x), y0 their first rows (y), "
    "and each row of xy is one vertex's (x, y); a block's first pixel centre lies at "
    "(x0 + ½, y0 + ½)",
}


def _axes_words(primary: str):
    """The words of x0 and y0 swapped (``primary`` "x0 y0") or of the vertices read as (y, x)
    ("yx"): both where both give this case's answer."""

    def words(args, expected, got):
        swapped = same_kind(classify_with(*args, points="x0 y0 swapped"), got, args)
        if swapped and same_kind(_read_yx(*args), got, args):
            return _AXES["both"]
        return _AXES[primary]

    return words


BLOCK_KNOBS = Knobs(classify_with, {
    "points": [
        Slip("outer corners", "you evaluated E at the block's outer corners; the extreme pixel "
             "centres lie ½ px inside (E₀ is E at the centre (x0 + ½, y0 + ½), and the last "
             "centre lies size − 1 px further)", "outer corners"),
        # r141 D8.1-2: llvmpipe's own offsets do this on purpose
        Slip("size steps for size − 1", _at_first(lambda a, e, g: "your offsets span size "
             "steps, so they reach x0 + size + ½ (and y0 + size + ½), beyond the block "
             "(llvmpipe's scaled offsets do so on purpose, a cautious test; the task asks for "
             "the exact ones, over the block's own centres); its "
             f"last pixel centre is x0 + size − ½ = {num(a[1] + a[3] - 0.5)}, size − 1 steps "
             "from its first"), "beyond"),
        # r64 08-2: the pixels' top-left corners were told "only 2 of the 4 extreme centres"
        Slip("pixel corners", _at_first(lambda a, e, g: "you evaluated E at the pixels' "
             f"top-left corners ({a[1]}, {a[2]}) … ({a[1] + a[3] - 1}, {a[2] + a[3] - 1}); the "
             "pixel centres lie ½ px right and down of them"), "pixel corners"),
        Slip("x0 and y0 swapped", _axes_words("x0 y0"), "x0 y0 swapped"),
        Slip("offsets not scaled", _span_words("one pixel step whatever the block's size", "; "
             "llvmpipe's offset for a one-pixel block, not scaled to the block?", lambda s: 1),
             "one step"),
        Slip("offsets of size/2 steps", _span_words("size/2 steps", "", lambda s: s / 2),
             "half size"),
    ],
    "offsets": OFFSET_SLIPS,
    "tie": [
        Slip("no top-left rule (E > 0)", _at_first(_tie_words), "strict"),
        Slip("no top-left rule (E ≥ 0)", _at_first(_tie_words), "loose"),
        *(_rule_slip(rule) for rule in ("bottom-right", "top-right", "bottom-left")),
        # r141 D8.1-6: the rule in the reject test only was given the generic rule
        Slip("no top-left rule in the accept test", _at_first(lambda a, e, g: "your accept test "
             "leaves out the top-left rule (E > 0 on every edge; your reject test has it): "
             "here " + _tie_words(a, e, g)), "accept strict"),
        *(_bias_slip(name) for name in BIASES),
    ],
    "orient": [Slip("one winding only", "this triangle runs counter-clockwise on screen: handle "
                    "both windings (orient the edges so that the interior is positive)", False),
               # r149 M1: the edges as given and no area, so zero area failed too, and the
               # counter-clockwise blocks were told "Corners outside the triangle..."
               Slip("one winding only, no area", _unchecked_words, "unchecked"),
               # r141 D8.1-4: every sign flipped was given the generic rule
               Slip("oriented the wrong way", "your edges are oriented the wrong way round: the "
                    "triangle's interior lies on the negative side of each, so you reject the "
                    "blocks inside it and accept none; orient them so that the interior is "
                    "positive", "flipped")],
    "logic": [
        # r94 D8-1, D8-2: "(nor do corners inside accept it)" was false (the triangle is
        # convex: four covered centres do accept it), and the rule's last sentence said twice
        Slip("corners inside", _at_first(lambda a, e, g: "corners outside the triangle do not "
             "reject a block: the test is per edge; "
             + _by_verdicts(_edge_table(*a), e, g)[2:]), "inside"),
        Slip("best corner accepts", _at_first(lambda a, e, g: _by_verdicts(
             _edge_table(*a), e, "accepted", cause=True)[2:]), "accept by the best corner"),
        # r162: the sign tests' comparisons slipped; r376 F5: knobs, so that a second mistake
        # beside one is named on its own failures (R and T swapped with "> 0" got the rule)
        Slip("reject test E ≤ 0", _at_first(lambda a, e, g: "your reject test rejects when "
             "E₀ + R + β ≤ 0: it also rejects a block whose best centre has E + β exactly 0, "
             "and such a centre passes the pixel test (E + β ≥ 0): reject only when "
             "E₀ + R + β < 0; here " + _by_verdicts(_edge_table(*a), e, g)[2:]),
             "reject at zero"),
        Slip("accept test E > 0", _at_first(lambda a, e, g: "your accept test asks "
             "E₀ + T + β > 0: it leaves partial a block whose worst centre has E + β exactly 0, "
             "and such a centre passes the pixel test (E + β ≥ 0): accept when E₀ + T + β ≥ 0 "
             "on every edge; here " + _by_verdicts(_edge_table(*a), e, g)[2:]),
             "accept above zero"),
    ],
})  # fmt: skip


def _only_whole(kind: str, words, **knobs) -> Mistake:
    """A slip named only where it gives every answer of the check, passing ones too, and
    never combined with another (r114 D8-7, item 5): where it shares a verdict with a
    different function on the failing cases only, naming it misled."""
    return Mistake(kind, _at_first(words), lambda *a: classify_with(*a, **knobs), only_whole=True)


#: r114 D8-7: "you tested only 2 of the 4 extreme centres" was told to code testing all four
#: (rejecting where at most one passes) as its first explanation, and in summary lines to a
#: one-point test: three verdicts, so two corners share one on many a case.
TWO_CORNERS = _only_whole("two corners only", _two_corners, offsets="two corners")

#: r114 D8-4: a winding-dependent tie rule (the top-left test of each edge as given, E's sign
#: flipped for the other winding) was called "a top-right rule".
AS_GIVEN = _only_whole(
    "tie rule of the edges as given",
    lambda a, e, g: (
        "your edge tests apply the top-left rule to each edge as given, before "
        "orienting it: on a counter-clockwise triangle that is a bottom-right rule (a centre on "
        "a bottom or right edge passes, on a top or left edge fails): decide a tie on the "
        "oriented edge (interior on its positive side); here " + _tie_words(a, e, g)
    ),
    tie="as given",
)

#: r376 F4: the tie kinds read off the edges as given, index by index, and the edges then
#: oriented (a counter-clockwise triangle's oriented edge k takes the kind of its edge k as
#: given, another edge or the same one reversed) was caught by one random case and told only
#: "your code for that winding goes wrong"; the hard case "counter-clockwise, centres on a left
#: and a right edge" catches it on every run.
READ_BEFORE_ORIENTING = _only_whole(
    "edge kinds read before orienting",
    lambda a, e, g: (
        "you read each edge's kind (top, left …) off the edges as given and oriented the "
        "triangle after: on a counter-clockwise triangle the swap renumbers the edges, so edge "
        "k of the oriented triangle takes the kind of edge k as given, another edge (or the "
        "same one walked the other way), and its tie goes the wrong way; read the kinds off the "
        "oriented edges, the ones whose E you test; here " + _tie_words(a, e, g)
    ),
    tie="read before orienting",
)

#: r114 item 5 (r107 N8-2's open xfail): a function that rejects every block of a
#: counter-clockwise triangle differs from the "one winding only" slip (the edges as given,
#: which leave some blocks partial) on some fresh draws, and was told the rule there; a knob
#: of its own combined with others and misnamed two functions' summary lines.
CULLED = _only_whole(
    "culled one winding",
    "this triangle runs counter-clockwise on screen and you rejected its blocks, as you do "
    "every block of such a triangle: classify_block culls nothing: handle both windings "
    "(orient the edges so that the interior is positive)",
    orient="cull",
)


def _longer_words(which: str, other: str, effect: str):
    """r214 item 3: one offset of ``size`` steps, the other right (llvmpipe's cautious reject
    offset beside an exact accept offset was told only the rule)."""

    def words(a, e, g):
        return (
            f"your {which} offset spans size steps (your {other} offset is right), so it "
            f"reaches x0 + size + ½ (and y0 + size + ½), one step beyond the block: {effect}; "
            f"its last pixel centre is x0 + size − ½ = {num(a[1] + a[3] - 0.5)}, size − 1 "
            "steps from its first"
        )

    return words


#: r214 item 3: llvmpipe's reject offset (size steps, lesson 10 §3) with the task's accept
#: offset, and the mirror; each named only where it gives every answer of the check.
ONE_OFFSET_LONGER = [
    _only_whole("reject offset of size steps", _longer_words(
        "reject", "accept", "a block whose edge fails at every one of its centres, but passes "
        "a step beyond them, is left partial (llvmpipe's trivial-reject offset does so on "
        "purpose, a cautious test; the task asks for the exact one, over the block's own "
        "centres)"), longer="reject"),
    _only_whole("accept offset of size steps", _longer_words(
        "accept", "reject", "a block every edge passes at each of its centres, but not a step "
        "beyond them, is left partial"), longer="accept"),
]  # fmt: skip

#: r214 item 4: code for counter-clockwise triangles only (two vertices swapped whatever the
#: winding) was told only the rule; the mirror of "one winding only".
SWAPS_ALWAYS = _only_whole(
    "swaps every triangle",
    "this triangle runs clockwise on screen (y pointing down), so its interior already lies "
    "on the positive side of its edges as given, yet yours put it on the negative side: you "
    "swap two vertices whatever the winding (code for counter-clockwise triangles only?); swap "
    "them only where the area (E₁₂ at v3) is negative, a triangle that runs counter-clockwise "
    "on screen",
    orient="swap always",
)

#: r214 item 5: no tie rule at all (E ≥ 0, or E > 0, on every edge) was told the rule at one
#: centre, not the student's own: said so where the slip gives every answer of the check (the
#: knobs' words, the rule at the centre, stay for its combinations).
NO_TIE_RULE = [
    _only_whole("no top-left rule (E ≥ 0)", lambda a, e, g: (
        "your tests count every centre exactly on an edge as inside (E ≥ 0 on all three "
        "edges): there is no top-left rule in them, yet such a centre is inside only where "
        "that edge is a top or a left one; here " + _tie_words(a, e, g)), tie="loose"),
    _only_whole("no top-left rule (E > 0)", lambda a, e, g: (
        "your tests count no centre exactly on an edge as inside (E > 0 on all three edges): "
        "there is no top-left rule in them, yet such a centre is inside where that edge is a "
        "top or a left one; here " + _tie_words(a, e, g)), tie="strict"),
]  # fmt: skip


#: r221 items 1, 3: a horizontal edge taken as top whatever its direction (``b.y <= a.y``,
#: "runs right" forgotten) passed every case, none putting a centre on a bottom edge; and left
#: edges with no top clause (``b.y < a.y``) were told "a bottom-left rule". Each named where it
#: gives every answer of the check.
TIE_KIND_SLIPS = [
    _only_whole("every horizontal edge top", lambda a, e, g: (
        "you counted a centre on every horizontal edge as inside: a horizontal edge is a top "
        "edge only if it runs right (x increasing, the interior below it); one running left "
        "(x decreasing) is a bottom edge, the interior above it, and the top-left rule "
        "excludes a centre on it; here " + _tie_words(a, e, g)), tie="top-bottom-left"),
    _only_whole("left edges only", lambda a, e, g: (
        "your rule counts left edges but no top edge: a centre on a horizontal edge that runs "
        "right (x increasing, the interior below it), a top edge, fails in your tests, and the "
        "top-left rule includes it; here " + _tie_words(a, e, g)), tie="left"),
]  # fmt: skip


#: r232 half-named 1, 2: the bias in one test only was told the rule at one centre ("edge
#: v1→v3 excludes the block's four corner centres", "the top-left rule excludes it"), not the
#: slip; each named where it gives every answer of the check.
BIAS_IN_ONE_TEST = [
    _only_whole("no bias in the reject test", lambda a, e, g: (
        "your reject test takes no bias off the edges that are neither top nor left (E₀ + R < 0 "
        "there; your accept test has the bias): a block whose best centre lies exactly on such "
        "an edge (E = 0) holds no centre the triangle covers, yet you leave it partial. "
        "llvmpipe's trivial reject does the same on those edges, on purpose (a cautious test: "
        "its pixel tests then reject every pixel of the block); the task's reject test is the "
        "exact one, with the same bias as the accept test; here " + _tie_words(a, e, g)),
        tie="reject loose"),
    _only_whole("no bias in the accept test", lambda a, e, g: (
        "your accept test takes no bias off the edges that are neither top nor left (E₀ + T ≥ 0 "
        "there; your reject test has the bias): a block whose worst centre lies exactly on such "
        "an edge (E = 0), a centre the top-left rule leaves out, is accepted, and all its "
        "pixels are filled without a test, that one too, so the triangle beyond that edge "
        "fills it as well (a pixel drawn twice); the accept test needs the same bias as the "
        "reject test; here " + _tie_words(a, e, g)), tie="accept loose"),
]  # fmt: skip


#: The smallest |E₀| (px²) at which a tie's bias is taken to be lost: half float64's spacing of
#: numbers near 2^12 is 2^-41 px², below any bias a student types (10⁻¹² is lost from 2^14 on).
#: A tie with a smaller E₀ decides against a bias that works (the notebook's old float model
#: solution with no bias in its accept test was told "lost" at E₀ = 84 px²).
LOST_FROM = 2.0**12


def _bias_lost(args, expected, got) -> bool | None:
    """Does the answer differ only where it takes the tie bias as 0 (E ≥ 0 on every edge), each
    time at a tie far from the block's first centre (|E₀| ≥ :data:`LOST_FROM`)? (r232: a bias
    of a fraction of a px² added to a large E₀, lost to float64's rounding.)"""
    xy, x0, y0, size = args
    gx, gy = grid_of(x0, y0)
    want = np.broadcast_to(np.asarray(expected), gx.shape)
    have = np.broadcast_to(np.asarray(got), gx.shape)
    differ = want != have
    if not differ.any():
        return None
    from .block_arithmetic import float64_verdicts

    loose = np.broadcast_to(np.asarray(classify_with(*args, tie="loose")), gx.shape)
    for bx, by, g, lo in zip(gx[differ], gy[differ], have[differ], loose[differ], strict=True):
        # r248 F1: float64 pixels also round E₀ itself, bias or not: such a block fits too
        if g in float64_verdicts(xy, int(bx), int(by), size):
            continue
        tie = _lost_tie(xy, int(bx), int(by), size, g == "accepted")
        if g != lo or tie is None or abs(tie[2]) < LOST_FROM:
            return False
    return True


def _lost_tie(xy, bx: int, by: int, size: int, accept: bool):
    """The tie of block (bx, by) on an edge neither top nor left at its extreme centre (the
    smallest E over the block where ``accept``, else the largest): (edge k, corner j, E₀ of
    that edge in px², the set-up, rows, cols); None where there is none."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    rows, cols = _corners(bx, by, size)
    values = edge_values_at(setup, rows, cols) / setup.unit**2  # (4, 3) px², exact
    pick = values.min(axis=0) if accept else values.max(axis=0)
    ties = [k for k in range(3) if not setup.top_left[k] and pick[k] == 0]
    if not ties:
        return None
    k = max(ties, key=lambda k: abs(values[0, k]))  # corner 0: the first centre
    j = int(np.argmin(values[:, k]) if accept else np.argmax(values[:, k]))
    return k, j, float(values[0, k]), setup, rows, cols


def _bias_lost_words(args, expected, got) -> str:
    """The first block where the bias was lost: the tie, the test it passed, E₀ there and
    float64's spacing of numbers near it."""
    from .block_arithmetic import float64_slip, float64_words

    _, (xy, bx, by, size), e, g, _ = first_block(args, expected, got)
    if float64_slip(xy, bx, by, size) is not None:  # r248 F1: E₀ itself rounded
        return float64_words(args, expected, got)
    accept = g == "accepted"
    tie = _lost_tie(xy, bx, by, size, accept)
    if tie is None:  # (the answer differs otherwise: the words of the rule say what)
        return _block_rule(args, expected, got)[2:]
    k, j, e0, setup, rows, cols = tie
    name = f"v{setup.perm[k] + 1}→v{setup.perm[(k + 1) % 3] + 1}"
    where = "accept test (E₀ + T + β ≥ 0)" if accept else "reject test (E₀ + R + β < 0)"
    spacing = f"2^{int(np.log2(np.spacing(abs(e0))))}"
    return (
        f"your bias is lost to rounding: centre {vec((cols[j] + 0.5, rows[j] + 0.5))} lies "
        f"exactly on edge {name}, which is neither top nor left, so the top-left rule excludes "
        f"it, yet it passes your {where} as if there were no bias. You add the bias to a large "
        f"number: at the block's first centre E₀ = {num(e0)} px² on that edge, and float64's "
        f"numbers near it lie {spacing} px² apart, so E₀ + β rounds back to E₀ for any bias "
        "below half that (where E₀ is small, the same bias works). Adding it after the offset "
        "is no cure: float64 holds E₀ itself exactly only while its products stay below "
        f"2^37 px² (vertices on the 1/256 grid), and the check's coordinates reach "
        f"{max(np.abs(coordinate_range())):,.0f} px. Count in integer units (256 a pixel, as "
        "lesson 10 §4 counts), where every value and test is exact"
    )


#: r232 wrongly passed 1, C1: a bias lost to float64's rounding (β = −10⁻¹² or −10⁻⁹ added to
#: E₀, or even −2⁻¹⁶ at a 2^19-px block), named where the answer differs only at ties on edges
#: neither top nor left, taken there as E ≥ 0, or (r248 F1) at blocks float64 pixels round
#: otherwise (:func:`.block_arithmetic.float64_slip`: E₀'s products past 2^37 px², where the
#: float64 words are said). After the tie rules (the table's order): an answer with no bias at
#: all, or none in one test, is told so by their own words.
BIAS_LOST = Mistake("bias lost to rounding", _bias_lost_words, fits=_bias_lost, only_whole=True)


def _float_units_fits(args, expected, got) -> bool | None:
    """Does the answer differ only where float64 rounds a count in units: a tie's bias lost
    (:func:`_bias_lost`) or E₀ itself rounded (:func:`.block_arithmetic.rounded_in_float64`)?"""
    from .block_arithmetic import rounded_in_float64

    lost = _bias_lost(args, expected, got)
    return None if lost is None else bool(lost or rounded_in_float64(args, expected, got))


def _float_units_words(rounds: str):
    """r267 half-named 1: integer units held in float64 (``np.rint`` without its cast)."""

    def words(args, expected, got) -> str:
        from .block_arithmetic import float64_slip, sci

        _, (xy, bx, by, size), e, g, _ = first_block(args, expected, got)
        slip = float64_slip(xy, bx, by, size)
        if slip is not None:  # E₀'s products past 2^53 units²: E₀ itself rounded
            edge, t, key = slip
            big = max(abs(v) for v in t["terms"][:2])
            cx, cy = t["hi"] if key == "best" else t["lo"]
            on = "exactly on that edge" if t[key] == 0 else f"{abs(t[key])} units² from that edge"
            detail = (
                f"on edge {edge['name']} E₀'s products reach {sci(big)} units², where float64's "
                f"numbers lie 2^{int(np.log2(np.spacing(float(big))))} units² apart, and the "
                f"block's centre {vec((cx / UNITS, cy / UNITS))} lies {on}: E₀ itself is "
                f"rounded, so {'E₀ + R' if key == 'best' else 'E₀ + T'} can land on either side"
            )
        else:
            tie = _lost_tie(xy, bx, by, size, g == "accepted")
            if tie is None:  # (a float64 verdict no tie or product explains: the rule)
                return _block_rule(args, expected, got)[2:]
            k, j, e0, setup, rows, cols = tie
            name = f"v{setup.perm[k] + 1}→v{setup.perm[(k + 1) % 3] + 1}"
            e0 = round(e0 * UNITS**2)
            detail = (
                f"centre {vec((cols[j] + 0.5, rows[j] + 0.5))} lies exactly on edge {name}, "
                f"neither top nor left, and at the block's first centre E₀ = {e0:,} units², "
                f"where float64's numbers lie 2^{int(np.log2(np.spacing(abs(float(e0)))))} "
                "units² apart: E₀ + β (β = −1) rounds back to E₀, and the centre passes your "
                f"{'accept' if g == 'accepted' else 'reject'} test as if there were no bias"
            )
        return (
            f"your units are float64 numbers: np.{rounds} rounds to whole numbers but returns "
            "float64, so every E you compute is a float64, exact only up to 2^53 units² "
            f"(2^37 px²). Here, {detail}. Cast the units to integers, "
            f"np.{rounds}(xy * 256).astype(np.int64): int64 holds every value of the check "
            "exactly (cell 1)"
        )

    return words


#: r267 half-named 1: cell 3's solution without ``.astype(np.int64)`` (np.rint returns float64)
#: was told "float64 pixels … 16 bits after the point" and "your bias is lost to rounding":
#: named by its cause where the code reads the rounding function and every failing case is a
#: tie float64 rounds (float64 pixels and float64 units give the very same answers, scaled by
#: 256, so only what the code reads tells them apart). After the half-unit bias (an int64 count
#: with β = −0.5 reads np.rint too), before float64 pixels and the lost bias.
FLOAT_UNITS = [
    Mistake("units held in float64", _float_units_words(name), fits=_float_units_fits,
            only_whole=True, reads=name)
    for name in ("rint", "round", "around")
]  # fmt: skip


READ_YX = Mistake("vertices read as (y, x)", _axes_words("yx"), gives=_read_yx)


def _constant(kind: str) -> Mistake:
    """One verdict for every block of every grid, returned as an array (a text is told by the
    check's own constant-answer rule)."""
    return Mistake(
        f"always {kind}",
        f"your function says {kind!r} for every block of every grid, whatever the triangle: a "
        "placeholder left in, or a `return` reached too early?",
        lambda xy, x0, y0, size: np.full(np.shape(x0), kind, dtype="<U8"),
        only_whole=True,
    )


#: Every centre of a grid listed, at most (beyond, the coverage mistake says nothing).
MOST_CENTRES = 1 << 20


def _by_coverage(xy, x0, y0, size):
    """The verdicts from the coverage of every centre of each block (r73 08-4): none covered,
    rejected; all, accepted. None on a grid too large to list its centres."""
    gx, gy = grid_of(x0, y0)
    if gx.size * size * size > MOST_CENTRES:
        return None
    i, j = np.meshgrid(np.arange(size), np.arange(size))
    xs = gx.reshape(-1, 1) + j.reshape(1, -1) + 0.5
    ys = gy.reshape(-1, 1) + i.reshape(1, -1) + 0.5
    inside = covered(np.asarray(xy, dtype=float), np.stack([xs.ravel(), ys.ravel()], axis=1))
    inside = inside.reshape(gx.size, -1)
    return verdicts(~inside.any(axis=1), inside.all(axis=1), gx.shape, gx.ndim == 0)


#: r73 08-4: an exact test of every centre was told "you tested only 2 of the 4 extreme centres".
BY_COVERAGE = Mistake(
    "by coverage",
    "you decided by the coverage of the block's centres (rejected when none is covered), not "
    "edge by edge: a block is rejected only when one edge alone rules out every centre; here "
    "no centre is covered, yet no single edge rules them all out (which edge passes somewhere "
    "in the block?)",
    gives=_by_coverage,
)


def _float32_verdict(xy, x0, y0, size):
    """The right offsets with every edge function computed in float32."""
    f = np.float32
    v = np.asarray(xy, dtype=float).astype(f)

    def e(a, b, px, py):
        return (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])

    gx, gy = grid_of(x0, y0)
    area = e(v[0], v[1], v[2][0], v[2][1])
    if area == 0:
        return verdicts(np.ones(gx.shape, bool), False, gx.shape, gx.ndim == 0)
    if area < 0:
        v = v[[0, 2, 1]]
    px, py = (gx.ravel() + 0.5).astype(f), (gy.ravel() + 0.5).astype(f)
    rejected, accepted = np.zeros(px.shape, bool), np.ones(px.shape, bool)
    for k in range(3):
        a, b = v[k], v[(k + 1) % 3]
        r, t = OFFSETS["right"](-(b[1] - a[1]), b[0] - a[0], f(size - 1))
        owns = edge_kind(b - a) in ("top", "left")
        e0 = e(a, b, px, py)
        rejected |= ~passes((e0 + f(r)).astype(f), owns)
        accepted &= passes((e0 + f(t)).astype(f), owns)
    return verdicts(rejected, accepted & ~rejected, gx.shape, gx.ndim == 0)


#: r107 N8-1: float32 edge functions passed every case (no centre lay within float32's
#: rounding of an edge); the cases "far out, a centre 1/65536 px² from an edge" show it.
FLOAT32 = Mistake(
    "float32",
    lambda a, e, g: (
        "did you compute the edge functions in float32? With vertices on the 1/256 grid, E's "
        "products have 16 bits after the point, and at 3000 px float32's 24 bits cannot hold "
        "them: this centre, 1/65536 px² from an edge, rounds onto it (or across it). float64 "
        "holds such products exactly only below 2^37 px² (r248 F1), and the check's "
        f"coordinates reach {max(np.abs(coordinate_range())):,.0f} px: count in integer units "
        "(256 a pixel, as lesson 10 §4 counts), in int64, exact at any size"
    ),
    gives=_float32_verdict,
)


def _int_vertices(xy, x0, y0, size):
    """The package's verdicts with the vertices cast to int (truncated toward 0); None where
    every vertex is whole already (the cast changes nothing there)."""
    v = np.asarray(xy, dtype=float)
    if np.array_equal(v, np.trunc(v)):
        return None
    return expected_block(np.trunc(v), x0, y0, size)


def _int_words(args, expected, got) -> str:
    v = np.asarray(args[0], dtype=float)
    k = int(np.argmax((v != np.trunc(v)).any(axis=1)))
    return (
        "you cast the vertices to int (`dtype=int`, `astype(int)` or `int()`), which drops "
        f"their fractions: v{k + 1} = {vec(v[k])} became {vec(np.trunc(v[k]))}, and every edge "
        "through it moved; the vertices lie on the 1/256 grid: keep them as floats (float64)"
    )


#: r162: vertices cast to int (the verdicts of another triangle) were told only the rule.
INT_VERTICES = Mistake("vertices cast to int", _int_words, gives=_int_vertices)


def _single(kind: str, words, **knobs) -> Mistake:
    """A slip of :func:`classify_with` named alone, never combined with the knobs' others: the
    knobs' pairs are what the checker's own time goes to (r162: five more knob values took
    a check past its 10 s of CPU, and every explanation lost its numbers)."""
    return Mistake(kind, words, lambda *a: classify_with(*a, **knobs))


#: r162 M1: offsets that stop short of the block's last centre (size − 2 steps; the centre
#: form's half span from the first centre; the centre form with integer division) were told
#: "Corners outside the triangle do not reject a block" or "you tested the maximising one".
SHORT_OFFSETS = [
    _single("offsets of size − 2 steps", _span_words("size − 2 steps", "", lambda s: s - 2),
            points="size - 2"),
    _single("half span from the first centre", _span_words(
        "(size − 1)/2 steps from the first centre", "; the half span belongs to the block's "
        "middle, (x0 + size/2, y0 + size/2), not to its first centre", lambda s: (s - 1) / 2),
        points="half span"),
    _single("centre form, integer division", _centre_floored_words, points="centre floored"),
]  # fmt: skip

#: r198 B: two offset slips told only the rule ("every edge includes the block's four corner
#: centres"): E₀ at the first pixel's bottom-right corner, and offsets reaching both ways.
OFFSET_SINGLES = [
    _single("pixels' bottom-right corners", _at_first(lambda a, e, g: "you evaluated E at the "
            f"pixels' bottom-right corners ({a[1] + 1}, {a[2] + 1}) … ({a[1] + a[3]}, "
            f"{a[2] + a[3]}), from (x0 + 1, y0 + 1) on; the pixel centres lie ½ px left and up of "
            "them; a block's first pixel centre lies at (x0 + ½, y0 + ½)"),
            points="bottom-right corners"),
    _single("offsets both ways", _offset_words(
        "your offsets ±(size − 1)·(|A| + |B|) reach both ways from E₀, yet E₀ is E at the "
        "block's first (top-left) centre, not its middle: E₀ + (size − 1)·(|A| + |B|) lies "
        "above E's largest value over the block's centres where A or B is negative, and "
        "E₀ − (size − 1)·(|A| + |B|) below its smallest where one is positive, so blocks to "
        "accept or reject stay partial; from the first centre only the steps that raise E "
        "count towards its largest value (A where A > 0, B where B > 0), only those that "
        "lower it towards its smallest"), offsets="both ways"),
]  # fmt: skip


def _block_index(xy, x0, y0, size):
    """r446 H1: the verdicts of the blocks at (x0·size, y0·size); None where those lie past
    the check's coordinates (int64 would wrap there, the student's count too)."""
    gx, gy = grid_of(x0, y0)
    if max(np.abs(gx).max(), np.abs(gy).max()) * size > 2**22:
        return None
    return classify_with(xy, x0, y0, size, points="block index")


#: r446 (r396 G1, H1, H3, H4): slips told only the rule ("every edge includes the block's four
#: corner centres"): one offset mirrored from the other, x0 and y0 read as block indices, a
#: block accepted by one edge, the ½ of the first centre in one axis only.
R446_SLIPS = [
    _single("accept offset −R", _offset_words(
        "your accept offset is your reject offset mirrored, T = −R: E₀ − R is E's smallest "
        "value over the block only where A ≤ 0 and B ≤ 0; from the first centre the steps that "
        "lower E are those with A < 0 (to the right) and B < 0 (down), so "
        "T = (size − 1)·(min(A, 0) + min(B, 0)), which is 0 where A and B are both positive"),
        offsets="accept mirrored"),
    _single("reject offset −T", _offset_words(
        "your reject offset is your accept offset mirrored, R = −T: E₀ − T is E's largest "
        "value over the block only where A ≥ 0 and B ≥ 0; from the first centre the steps that "
        "raise E are those with A > 0 and B > 0, so R = (size − 1)·(max(A, 0) + max(B, 0))"),
        offsets="reject mirrored"),
    Mistake("x0, y0 as block indices", _at_first(lambda a, e, g: "your verdicts are those of "
            f"the blocks at (x0·size, y0·size), here ({a[1] * a[3]}, {a[2] * a[3]}): x0 and y0 "
            "are not block numbers but the block's top-left pixel (column x0, row y0), so its "
            f"first pixel centre is ({num(a[1] + 0.5)}, {num(a[2] + 0.5)})"), _block_index),
    _single("accepted by one edge", _at_first(lambda a, e, g: "you accepted a block when one "
            "edge passes its accept test (accepted |= … for &=?): a block is accepted only when "
            "every edge passes at its smallest value over the block; here "
            + _block_rule(a, e, g)[2:]), logic="accept by one edge"),
    *(_single(f"centre ½ px off in {axis}", _at_first(lambda a, e, g, axis=axis, at=at: (
        f"you put the block's first centre at {at}: the ½ is missing in {axis}; pixel "
        f"(column x0, row y0) has its centre at (x0 + ½, y0 + ½) = ({num(a[1] + 0.5)}, "
        f"{num(a[2] + 0.5)})")), points=f"half in {other} only")
      for axis, other, at in (("y", "x", "(x0 + ½, y0)"), ("x", "y", "(x0, y0 + ½)"))),
]  # fmt: skip


#: r446 H2, r396 G2: the vertices taken onto another grid than the centres: (what the student
#: did, the triangle whose verdicts that gives).
GRIDS = {
    "vertices rounded to 1/16 px (16 units a pixel, 4 sub-pixel bits?)":
        lambda v: np.rint(v * 16) / 16,
    "vertices floored to 1/16 px (16 units a pixel, 4 sub-pixel bits?)":
        lambda v: np.floor(v * 16) / 16,
    "vertices in units of 1/128 px and centres in 1/256 (the triangle halved)":
        lambda v: np.floor(v * 128) / 256,
    "vertices in units of 1/128 px, rounded, and centres in 1/256 (the triangle halved)":
        lambda v: np.rint(v * 128) / 256,
    "vertices in units of 1/512 px and centres in 1/256 (the triangle doubled)": lambda v: v * 2,
}  # fmt: skip


def _grid_slip(what: str) -> Mistake:
    def gives(xy, x0, y0, size):
        v = np.asarray(xy, dtype=float)
        moved = GRIDS[what](v)
        return None if np.array_equal(moved, v) else expected_block(moved, x0, y0, size)

    def words(args, expected, got):
        v = np.asarray(args[0], dtype=float)
        return (
            f"your verdicts are those of another triangle: {what}, v1 = {vec(v[0])} becomes "
            f"{vec(GRIDS[what](v)[0])}; the vertices lie on the 1/256 grid and the pixel "
            "centres at x0 + ½: count both in the same units, 256 a pixel (a vertex at "
            "round(256·x), a centre at 256·x0 + 128)"
        )

    return Mistake(what.split(" (")[0], words, gives=gives)


GRID_SLIPS = [_grid_slip(what) for what in GRIDS]


def _area_tolerance(xy, x0, y0, size):
    """r446 W1: every block rejected where the triangle's area is not 0 but below 1 px² (a
    zero-area test with a tolerance); the package's verdicts elsewhere (named only where it
    gives every answer: a slip that moves the smallest triangle rejects it too)."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    if setup.area2 == 0 or abs(setup.area2) >= 2 * setup.unit**2:
        return expected_block(xy, x0, y0, size)
    gx, gy = grid_of(x0, y0)
    return verdicts(np.ones(gx.shape, bool), False, gx.shape, gx.ndim == 0)


def _area_tolerance_words(args, expected, got) -> str:
    _, (xy, bx, by, size), e, _, _ = first_block(args, expected, got)
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    area = abs(setup.area2) / 2 / setup.unit**2  # px²
    return (
        f"you rejected every block of a triangle whose area is not 0 but {area:.3g} px² "
        f"(2·area = {num(2 * area * UNITS**2)} unit² of 1/256 px): a zero-area test with a "
        f"tolerance (abs(area) < ε?); the block x0={bx}, y0={by}, size={size} is {e}: a "
        "sliver this thin can still cover a centre; with vertices on the 1/256 grid, 2·area "
        "is a whole number of units², so test area == 0 exactly, in integer units"
    )


AREA_TOLERANCE = Mistake(
    "zero area by a tolerance", _area_tolerance_words, gives=_area_tolerance, only_whole=True
)


def _here(a, e, g) -> str:
    """The rule at the first block that differs (its edge and extreme centre), after "here"."""
    return "; here " + _block_rule(a, e, g)[2:]


def _one_axis_words(offsets: str):
    """r376 F3: an offset that drops one axis's term (B's, the rows, or A's, the columns)
    was told only the rule at one centre."""
    kept, dropped = ("A", "B") if "x" in offsets else ("B", "A")
    axis = {"A": ("x", "columns", "to the right"), "B": ("y", "rows", "downwards")}
    one = offsets.startswith("reject")
    which = "reject offset R takes" if one else "offsets R and T take"
    drop = "drops" if one else "drop"

    def words(a, e, g):
        return (
            f"your {which} {kept}'s term alone and {drop} {dropped}'s: E also changes "
            f"{axis[dropped][2]} across the block's {axis[dropped][1]}, by {dropped} = "
            f"∂E/∂{axis[dropped][0]} a step, so E's extreme values over the block's centres "
            f"can lie in another of its {axis[dropped][1]} than the first; each offset needs "
            f"the steps of both axes (this triangle's edges, oriented: {_coefficients(a[0])})"
        )

    return words


#: r376 F3: offsets from one axis only (B's term dropped: R = (size − 1)·max(A, 0)), both or
#: the reject offset alone, were told only the rule ("no edge excludes the block's four corner
#: centres"); named alone, not combined (the checker's own time, r162).
ONE_AXIS = [
    _single(f"offsets of one axis only ({name})", _at_first(_one_axis_words(name)), offsets=name)
    for name in ("x only", "y only", "reject x only", "reject y only")
]  # fmt: skip


#: r248 half-named 2-5: slips that were told the rule at one centre only ("edge v1→v2 fails at
#: the pixel centre of the block where its E is smallest"), each named by its cause.
R248_SLIPS = [
    _single("no accept offset", _at_first(lambda a, e, g: "your accept test never adds T: "
            "it asks E₀ + β ≥ 0, at the block's first centre only, yet E is smaller elsewhere "
            "in the block wherever A < 0 or B < 0; a block is accepted only where every edge "
            "passes even at its smallest value over the block's centres, E₀ + T (T ≤ 0), so "
            "yours accepts blocks that hold centres outside the triangle" + _here(a, e, g)),
            offsets="no accept offset"),
    _single("no reject offset", _at_first(lambda a, e, g: "your reject test never adds R: "
            "it rejects where E₀ + β < 0, at the block's first centre only, yet E is larger "
            "elsewhere in the block wherever A > 0 or B > 0; a block is rejected only where "
            "one edge fails even at its largest value over the block's centres, E₀ + R "
            "(R ≥ 0), so yours rejects blocks that hold covered centres (holes)" + _here(a, e, g)),
            offsets="no reject offset"),
    _single("A's sign lost in the offsets", _offset_words(
        "your offsets take A = y₂ − y₁, with its minus sign lost (your E₀ has it): "
        "E = (x₂ − x₁)·(y − y₁) − (y₂ − y₁)·(x − x₁), so A = ∂E/∂x = y₁ − y₂, and where it is "
        "not 0 your offsets pick the wrong column of the block and add its steps the wrong "
        "way"), offsets="A's sign lost"),
    _single("llvmpipe's +1 without its −1", _at_first(lambda a, e, g: "you took llvmpipe's "
            "+1 on the constant of a left or top edge but not its −1 on every constant: in "
            "units your bias is +1 on top and left edges and 0 on the others, so a centre one "
            "unit (2^-16 px²) outside a top or left edge passes and one exactly on a right or "
            "bottom edge passes too; llvmpipe's two together give 0 on a top or left edge and "
            "−1 on any other: the β asked" + _here(a, e, g)), tie="plus one"),
]  # fmt: skip


def _labels_swapped(xy, x0, y0, size):
    """The package's verdicts with "rejected" and "accepted" swapped."""
    want = expected_block(xy, x0, y0, size)
    if setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS).area2 == 0:
        return want  # (a zero-area triangle's early return has no np.where to swap)
    swap = {"rejected": "accepted", "accepted": "rejected", "partial": "partial"}
    if isinstance(want, str):
        return swap[want]
    return np.vectorize(swap.get, otypes=["<U8"])(want)


#: r248 half-named 6: the texts swapped in the final np.where were told the rule only.
LABELS_SWAPPED = Mistake(
    "verdicts swapped",
    "your verdicts are the right ones under each other's names: where a block is rejected you "
    'say "accepted", and where it is accepted "rejected" (the two texts swapped in your '
    'np.where, or the masks?); a block that one edge rules out is "rejected", one every edge '
    'includes whole is "accepted"',
    _labels_swapped,
    only_whole=True,
)


def _ccw_only(args, expected, got) -> bool:
    """Is this case's triangle counter-clockwise on screen (y down), with area?"""
    setup, ccw = _oriented(args[0])
    return bool(setup.area2 != 0 and ccw)


#: r198 B: the second winding handled by a test of its own (the reject test flipped, the
#: accept test left as it was) was told only the rule, on one counter-clockwise case after
#: another. A symptom: named only where every failing case is counter-clockwise and no
#: mistake of the table (one winding only, culled, oriented the wrong way) gives them.
CCW_ONLY = Mistake(
    "counter-clockwise only",
    "every case you fail is a triangle that runs counter-clockwise on screen (y pointing "
    "down), and the clockwise ones pass: your code for that winding goes wrong. Orient the "
    "triangle once (swap two vertices where its area is negative) so that its interior is "
    "positive on every edge; then the same offsets, bias and two tests serve both windings",
    fits=_ccw_only,
    symptom=True,
    only_whole=True,
)

#: r162: the sign tests' comparisons slipped (≤ for the reject test, > for the accept test)
#: were told only the rule.
SIGN_MISTAKES = [
    # r267 half-named 2: told only the rule ("one such edge rejects the block")
    _single("reject only when every edge fails", _at_first(lambda a, e, g: "you rejected a "
            "block only when every edge fails its reject test (rejected &= … for |=?): the "
            "three edges' outer sides never all hold one centre, so such a block is never "
            "rejected, yet one edge alone that fails at the block's best centre rules out "
            "every centre of it; here " + _by_verdicts(_edge_table(*a), e, g)[2:]),
            logic="every edge rejects"),
]  # fmt: skip


def explain_block(args, expected, got) -> str:
    """The first block of the grid that differs, its extreme centres, and both verdicts."""
    xy, x0, y0, size = args
    idx, (_, bx, by, _), e, g, wrong = first_block(args, expected, got)
    total = int(np.size(grid_of(x0, y0)[0]))
    block = (
        f"x0={bx}, y0={by}, size={size} (extreme centres x = {num(bx + 0.5)}, "
        f"{num(bx + size - 0.5)}; y = {num(by + 0.5)}, {num(by + size - 0.5)})"
    )
    if total == 1:
        return f"the block {block} is {e}; yours says {g}"
    differ = "differs" if wrong == 1 else "differ"
    which = f"all {total} blocks of the grid differ" if wrong == total else f"{wrong} of the grid's {total} blocks {differ}"  # fmt: skip
    # r248 S1: where it sits in your answer, as x0 and y0 index it
    at = "[" + ", ".join(map(str, idx)) + "]"
    return f"{which}; the first, at {at}, {block}, is {e}; yours says {g}"


def _block_rule(args, expected, got) -> str:
    xy = args[0]
    if setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS).area2 == 0:
        return f": {tri_words(xy)} are collinear, and a zero-area triangle rejects every block"
    _, block, e, g, _ = first_block(args, expected, got)
    return _by_verdicts(_edge_table(*block), e, g)


#: The words that say which centres decide a block, or the offsets (the task's question),
#: each replaced by a hint until two different answers have failed (r64 08-3: every first
#: failure's header printed the extreme centres, as mip_level's gave its formula;
#: :attr:`.exercise.Exercise.hints`).
_POINT = r"\([^()]*\) \(E = [^()]*\)"
BLOCK_HINTS = (
    (re.compile(r" \(extreme centres x = [^;()]*; y = [^()]*\)"), ""),
    (re.compile(rf"even the corner that maximises its E, {_POINT}, fails"),
     "even the pixel centre of the block where its E is largest fails (which one is that?)"),
    (re.compile(rf"the lowest of the minimising corners is {_POINT} for edge (v\d→v\d), which "
                "passes"),
     r"even edge \1, at the pixel centre of the block where its E is lowest, passes (which "
     "one?)"),
    (re.compile(rf"this corner, {_POINT}, is the one that minimises E for edge (v\d→v\d), and "
                rf"it fails(?:; you tested the maximising one, {_POINT})?"),
     r"edge \1 fails at the pixel centre of the block where its E is smallest (which one is "
     "it?)"),
    (re.compile(rf" \(each edge's maximising corner passes: (?:v\d→v\d: {_POINT}(?:; )?)+\)"),
     " (each edge passes at the pixel centre of the block where its E is largest)"),
    (re.compile(r"(corner \([^()]*\) lies exactly on edge v\d→v\d), a (?:top|left|bottom|right) "
                r"edge: the top-left rule (includes|excludes) it"),
     r"\1: the top-left rule \2 it (which kind of edge is it, with y pointing down?)"),
    # r94 D8-3: named mistakes that gave the extreme centres (or the method) on the first try
    ("; a block's first pixel centre lies at (x0 + ½, y0 + ½)", ""),
    (re.compile(r"; its last pixel centre is x0 \+ size − ½ = [^,]*, size − 1 steps from its "
                r"first"), "; where is the block's last pixel centre?"),
    (" (E₀ is E at the centre (x0 + ½, y0 + ½), and the last centre lies size − 1 px further)",
     ""),
    ("; test all four (or, per edge, the one its signs pick)", ""),
    # r162 M1: the centre form's reach and half span are the task's question
    (re.compile(r", short of the block's extreme centres [^ ]+ and [^ ]+ \(a block"),
     ", short of the block's extreme centres (a block"),
    ("; the middle of the centres lies at x0 + size/2, and the half span is (size − 1)/2, not "
     "a whole number for an even size", "; where do the block's centres begin and end?"),
    # r141 D8.1-3: the steps the offsets span are the task's question
    (re.compile(r"; the block's last pixel centre lies size − 1 = \d+ steps from its first: "
                r"scale the offsets by size − 1"),
     "; how many steps from its first centre lies the block's last?"),
    (re.compile(r"E grows to the right where A = ∂E/∂x > 0, so its largest value lies in the "
                r"block's right-most column of centres there and in its left-most where A < 0 "
                r"\(the smallest on the other side\); yours take the opposite column"),
     "which column of centres in the block holds E's largest value, for each sign of A?"),
    (re.compile(r"E grows downwards where B = ∂E/∂y > 0, so its largest value lies in the "
                r"block's bottom row of centres there and in its top row where B < 0 \(the "
                r"smallest on the other side\); yours take the opposite row"),
     "which row of centres in the block holds E's largest value, for each sign of B?"),
    (re.compile(r": \(size − 1\)·\(A \+ B\) is E's change to the bottom-right centre, the "
                r"largest value only where A ≥ 0 and B ≥ 0, and E₀ itself the smallest only "
                r"there; each edge's signs pick its own corners"),
     ": which corner of the block is E's largest, for each sign of A and B?"),
    ("; E's largest value over the block's centres is E₀ + R with R ≥ 0, its smallest E₀ + T "
     "with T ≤ 0", "; can the largest value over the block be below E₀?"),
    # r198 B: which steps count is the task's question
    ("; from the first centre only the steps that raise E count towards its largest value (A "
     "where A > 0, B where B > 0), only those that lower it towards its smallest",
     "; from the first centre, which steps raise E and which lower it?"),
)  # fmt: skip


def exercise(scene) -> Exercise:
    from . import block_arithmetic as ba  # (it reads this module's grids and verdicts)

    return Exercise(
        "classify_block", block_cases, as_kind, same_kind, explain_block, _block_rule,
        [ba.INT32, AREA_TOLERANCE, BY_COVERAGE, FLOAT32, INT_VERTICES, READ_YX, *SHORT_OFFSETS, *OFFSET_SINGLES, *R446_SLIPS, *GRID_SLIPS, *ONE_AXIS, *R248_SLIPS, LABELS_SWAPPED, *SIGN_MISTAKES, CULLED, AS_GIVEN, READ_BEFORE_ORIENTING, TWO_CORNERS, *ONE_OFFSET_LONGER, SWAPS_ALWAYS, *NO_TIE_RULE, *TIE_KIND_SLIPS, *BIAS_IN_ONE_TEST, *map(_constant, KINDS), BLOCK_KNOBS, ba.HALF_UNIT_BIAS, *FLOAT_UNITS, ba.FLOAT64_PIXELS, BIAS_LOST, CCW_ONLY],
        draw=draw_block_case, scene=scene, hints=BLOCK_HINTS, call=call_block, match=match_kind,
        # r248 S1: each case's label holds its call (:func:`call_words`); an exception adds
        # the traceback's last line in the student's code
        call_words=lambda *args: "",
        # r107 N8-2 (as r94 D8-6 for hiz_rejects): three verdicts, so many a mistake agrees
        # with a wrong one on one case; named only where it gives every failing answer
        partial_names=False,
        # r114 D8-1: the checker's own verdict, handed in or called, passed all cases: listed
        # as an answer, every function of this module is watched and not counted
        answers=(PackageAnswer(expected_block, words=CHECKER_WORDS),),
        # the cases' blocks and grids are built there too, on some draws only: their
        # functions are watched whatever this check's cases happened to call
        reference=("teachraster.exercises.block_arithmetic", "teachraster.exercises.block_grid"),
    )  # fmt: skip


def _hard_blocks():
    t = [[2.5, 2.5], [29.5, 6.5], [8.5, 27.5]]
    left = [[8.5, 2.0], [8.5, 30.0], [26.0, 16.0]]  # a vertical left edge at x = 8.5
    right = [[11.5, 2.0], [0.0, 16.0], [11.5, 30.0]]  # a vertical right edge at x = 11.5
    top = [[0.0, 8.5], [30.0, 8.5], [15.0, 30.0]]  # a horizontal top edge at y = 8.5
    bottom = [[8.5, 2.0], [26.0, 20.5], [2.0, 20.5]]  # a horizontal bottom edge at y = 20.5
    sharp = [[8.0, 8.0], [24.0, 11.0], [11.0, 24.0]]
    return [
        ("a block inside", t, 8, 8, 4),
        ("a block outside the bounding box", t, 24, 24, 4),
        ("a block an edge crosses", t, 16, 4, 4),
        ("a block holding a vertex", t, 0, 0, 4),
        ("a block beyond a vertex, outside the triangle", sharp, 4, 4, 4),
        ("a left edge through the left corners", left, 8, 12, 4),
        ("a right edge through the right corners", right, 8, 12, 4),
        ("a right edge through the left corners (nothing inside)", right, 11, 12, 4),
        ("a top edge through the upper corners", top, 12, 8, 4),
        ("one pixel, its centre on a left edge", left, 8, 20, 1),
        ("one pixel, its centre on a right edge", right, 11, 20, 1),
        ("a small triangle inside a big block", [[5.5, 5.25], [10.75, 7.5], [6.5, 11.0]], 0, 0, 16),
        ("the whole triangle in one 64-block", t, 0, 0, 64),
        ("counter-clockwise, a block inside", [t[0], t[2], t[1]], 8, 8, 4),
        ("counter-clockwise, a right edge through the right corners", [right[0], right[2], right[1]], 8, 12, 4),  # fmt: skip
        ("zero area", [[0.5, 0.5], [8.5, 8.5], [16.5, 16.5]], 0, 0, 16),
        ("far from the origin", [[4098.5, 4098.5], [4125.5, 4102.5], [4104.5, 4123.5]], 4104, 4104, 4),  # fmt: skip
        # r107 N8-1: E = ±1/65536 px² at the centre (3000.5, 3000.5), 0 in float32
        ("far out, a centre 1/65536 px² outside an edge", [[3016.83203125, 3010.59375], [2990.40625, 2994.26171875], [6000.0, 0.0]], 3000, 3000, 1),  # fmt: skip
        ("far out, a centre 1/65536 px² inside an edge", [[3043.2578125, 3026.92578125], [2974.07421875, 2984.16796875], [0.0, 6000.0]], 3000, 3000, 1),  # fmt: skip
        # r149 M4: the first far-out case mirrored (x → 6001 − x), its −1/65536 px² centre now
        # outside a right edge, where a bias added, not taken off, covers it
        ("far out, a centre 1/65536 px² outside a right edge", [[2984.16796875, 3010.59375], [3010.59375, 2994.26171875], [1.0, 0.0]], 3000, 3000, 1),  # fmt: skip
        # r221 item 1: no case put a centre on a bottom edge (a horizontal edge running left),
        # and every horizontal edge taken as top passed
        ("a bottom edge through the lower corners", bottom, 12, 17, 4),
        ("one pixel, its centre on a bottom edge", bottom, 12, 20, 1),
        # r376 F1: the r149 M4 case with two vertices swapped, clockwise: a bias added, not
        # taken off, is seen there with one winding only too (it was told "E ≥ 0")
        ("far out, clockwise, a centre 1/65536 px² outside a right edge", [[2984.16796875, 3010.59375], [1.0, 0.0], [3010.59375, 2994.26171875]], 3000, 3000, 1),  # fmt: skip
        # r446 W1: the smallest area on the 1/256 grid (2·area = 1 unit²), its vertex on the
        # centre (0.5, 0.5), where a top and a left edge meet: covered (a tolerance lost it)
        ("the smallest area on the 1/256 grid, 2^-17 px², its vertex on a centre", [[0.5, 0.5], [0.50390625, 0.5], [0.5, 0.50390625]], 0, 0, 1),  # fmt: skip
    ]  # fmt: skip


def _around(x0: int, y0: int, size: int, shape=(2, 2)):
    """A grid of blocks of one size whose first block is (x0, y0): (x0 array, y0 array)."""
    if len(shape) == 1:  # a row of blocks
        return x0 + size * np.arange(shape[0]), np.full(shape[0], y0)
    yy, xx = np.mgrid[0 : shape[0], 0 : shape[1]]
    return x0 + size * xx, y0 + size * yy


def _covering(xy, size: int):
    """The grid of blocks of ``size`` over the triangle's bounding box, one block beyond."""
    lo = np.floor(xy.min(axis=0) / size).astype(int) - 1
    hi = np.floor(xy.max(axis=0) / size).astype(int) + 1
    yy, xx = np.mgrid[lo[1] : hi[1] + 1, lo[0] : hi[0] + 1]
    return xx * size, yy * size


def _block_cases(rng, word):
    """Hard blocks (each the first of a small grid), then random grids over triangles."""
    grids = []
    for n, (label, xy, x0, y0, s) in enumerate(_hard_blocks()):
        gx, gy = _around(x0, y0, s, (3,) if n % 4 == 3 else (2, 2))
        grids.append((label, np.array(xy, dtype=float), gx, gy, s))
    # r376 F4: the tie kinds read before orienting failed one random case in 62: here the
    # oriented edges' kinds differ from those of the edges as given, index by index, on a
    # left and on a right edge through centres of the 4-px blocks over the triangle
    ccw = np.array([[12.5, 8.5], [2.5, 4.5], [3.5, 12.5]])
    grids.append(("counter-clockwise, centres on a left and on a right edge", ccw, *_covering(ccw, 4), 4))  # fmt: skip
    for n in range(18):
        xy = snap(rng.uniform(0, 32, size=(3, 2)))
        if n % 3 == 0:
            xy = np.floor(xy) + 0.5  # vertices on pixel centres: edges through corner centres
        size = (1, 4, 8, 16)[n % 4]
        gx, gy = _covering(xy, size)
        grids.append((f"{word} {n + 1}", xy, gx, gy, size))
    big = snap(np.array([[3.3, 2.1], [250.2, 60.7], [40.9, 254.4]]))
    gx, gy = _covering(big, 8)
    grids.append(("a 256-px triangle, every 8-px block over it", big, gx, gy, 8))
    grids += _far_ties(FAR_TIES[:3])
    return _labelled(grids)


def _labelled(grids) -> list:
    """(label with the case's numbers, args, the package's verdicts) of each grid."""
    return [
        (f"{label}: {call_words(xy, gx, gy, s)}", (xy, gx, gy, s),
         expected_block(xy, gx, gy, s))
        for label, xy, gx, gy, s in grids
    ]  # fmt: skip


#: r232 (wrongly passed 1, C1): ties far from the block's first centre, each on an edge that is
#: neither top nor left, where E₀ is large: 6·10⁴ px² and more. A bias of a fraction of a px²
#: added to E₀ before the offset (β = −10⁻¹², −10⁻⁹, even −2⁻¹⁶ at 2^19-px blocks) is lost to
#: float64's rounding there (half its spacing of numbers near E₀ exceeds it), and the tie passes
#: as if there were no bias; every tie case before had E₀ below 10³ px² (or no tie at an extreme
#: centre). Each: (label, vertices, first block (x0, y0), size, grid shape), the tie in the
#: second block of a row (the first accepted, the third rejected) or the first of a 2 × 2 grid.
#: |E₀| at the tie: 6·10⁴, 2.5·10⁵, 2.5·10⁶ px² (−10⁻¹² lost, −10⁻⁹ not), then 6.7·10⁷,
#: 3.3·10⁷, 4.1·10⁷ px² (−10⁻⁹ lost too); the last two lie after the 2^19-px blocks.
FAR_TIES = (
    ("a 4000-px right edge through the right corners of a 16-px block, far from its first centre",
     [[300.5, -992.0], [300.5, 3008.0], [-3000.0, 1008.0]], (269, 1000), 16, (3,)),
    ("a 4000-px right edge through the right corners of a 64-px block, far from its first centre",
     [[1000.5, -968.0], [1000.5, 3032.0], [0.0, 1032.0]], (873, 1000), 64, (3,)),
    ("a 40,000-px right edge through a 64-px block's bottom-left corner, far from its first "
     "centre (nothing inside)",
     [[-19999.5, -19936.5], [20000.5, 20063.5], [-59999.5, 60063.5]], (0, 0), 64, (2, 2)),
    ("a 65,536-px right edge through the right corners of a 1024-px block, far from its first "
     "centre", [[1000.5, 0.0], [1000.5, 65536.0], [-64535.5, 32768.0]], (-1047, 32256), 1024, (3,)),
    ("a 131,072-px bottom edge through the lower corners of a 256-px block, far from its first "
     "centre", [[66164.0, 1000.5], [-64908.0, 1000.5], [628.0, -60000.0]], (500, 745), 256, (2, 2)),
    ("a 40,000-px right edge through a 1024-px block's bottom-left corner, far from its first "
     "centre (nothing inside)",
     [[-19999.5, -18976.5], [20000.5, 21023.5], [-59999.5, 61023.5]], (0, 0), 1024, (2, 2)),
)  # fmt: skip


def _far_ties(ties) -> list:
    """:data:`FAR_TIES` as grids: (label, vertices, x0 array, y0 array, size)."""
    return [(label, np.array(xy, dtype=float), *_around(*first, size, shape), size)
            for label, xy, first, size, shape in ties]  # fmt: skip


def call_words(xy, gx, gy, size) -> str:
    """The case as Python a student can paste to call classify_block on it again (r248 S1:
    "a 2 × 2 grid of blocks, x0=16…20, y0=4…8" was no argument, and read as a range of 5)."""
    rows = ", ".join(
        "[" + ", ".join(full_number(c) for c in p) + "]" for p in np.asarray(xy, float)
    )
    if gx.ndim == 1:  # a row of blocks
        grid = f"x0 = np.array({_values(gx)}); y0 = np.full({gx.size}, {int(gy[0])})"
    else:
        grid = f"x0, y0 = np.meshgrid({_values(gx[0])}, {_values(gy[:, 0])})"
    return f"xy = np.array([{rows}]); {grid}; classify_block(xy, x0, y0, {size})"


def _values(v) -> str:
    """Evenly spaced integers as a list (up to 4) or an ``np.arange`` (more)."""
    v = [int(x) for x in np.ravel(v)]
    if len(v) <= 4:
        return str(v)
    return f"np.arange({v[0]}, {v[-1] + (v[1] - v[0])}, {v[1] - v[0]})"


# r162 C2: every case seeded (r49 drew some afresh per check: the count moved on a re-run)
_seeded_cases = seeded(_block_cases, SEED + 100)

#: The side of the huge blocks: 2^19 px, 2.7·10^11 centres each (vertices stay within the
#: ±2^21 px the package's 8-bit fixed point holds).
HUGE = 2**19


def _huge_blocks() -> list:
    """3 × 3 grids of 2^19 × 2^19 px blocks, every verdict, both windings (r64 08-1: testing
    all size² centres passed every case, though the task asks for one evaluation per block).
    A scan of the centres cannot finish within the CPU limit, and the case's label says why.
    Then the far ties of :data:`FAR_TIES` at 1024 and 256 px (r232), after them: a scan that
    ran past its limit on the huge blocks is told so there, not on these."""
    xy = np.array([[-5e5, -5e5], [2e6, -5e5], [-5e5, 2e6]])
    # r232 C1: the middle block's best centre (0.5, 524287.5) exactly on a right edge, where
    # E₀ ≈ 2^38 px²: float64's numbers there lie 2^-14 px² apart, and β = −2^-16 px² added to
    # E₀ before the offset is lost (the notebook's float model solution said partial)
    tie = np.array([[-262144.0, 262144.0], [262145.0, 786431.0], [-524288.0, 524288.0]])
    why = "a scan of their 2.7·10^11 centres each does not finish; one evaluation per block does"  # fmt: skip
    gx, gy = _around(0, 0, HUGE, (3, 3))
    return _labelled([
        (f"blocks of 2^19 × 2^19 px inside, across and beyond a huge triangle's long edge ({why})", xy, gx, gy, HUGE),
        (f"counter-clockwise, blocks of 2^19 × 2^19 px over a huge triangle ({why})", xy[[0, 2, 1]], gx, gy, HUGE),
        (f"blocks of 2^19 × 2^19 px, a right edge through the middle one's bottom-left corner, "
         f"far from its first centre (nothing inside; {why})", tie, gx - HUGE, gy - HUGE, HUGE),
        *_far_ties(FAR_TIES[3:]),
        *(_float64_tie(*tie) for tie in FLOAT64_TIES),
    ])  # fmt: skip


#: r248 F1: float64 pixels passed every case, whether E > 0 and E ≥ 0 were written out per edge
#: or the bias was added after the offset (the check's own advice), since every far tie had
#: whole-pixel vertices, where E₀'s products stay exact. With 1/256 fractions they are exact
#: only below 2^37 px²: here they reach 3·10¹¹ … 2·10¹² px², each block's deciding centre lies
#: on an edge or a few 2^-16 px² from it, and float64 pixels decide it wrongly in every form
#: tried (A·(x − x₁) + B·(y − y₁), the conventions' E, A·x + B·y + C; with the offsets or at the
#: extreme centre itself: the last four cases), while integer units are exact. The first is the
#: reader's. Each: (vertices, first block (x0, y0), size), a grid of one block.
FLOAT64_TIES = (
    ([[-276483.12109375, -153034.4765625], [805634.4921875, 958915.953125],
      [-92323.4140625, 497252.1015625]], (0, 0), 131072),
    ([[641284.5859375, -241962.359375], [465788.95703125, 1300628.4296875],
      [-29126.953125, 1003905.09375]], (262144, 524288), 262144),
    # r446: a 131,072-px block with the same best centre (49151.5, 262144.5) as the 16,384-px
    # one it replaces (its bottom-right corner kept): a per-centre scan's grids of 2^34
    # centres cannot be allocated, where 2^28 took seconds of paging before the limit
    ([[748382.109375, 1440629.64453125], [-103280.80078125, 5234.69140625],
      [482807.9140625, -209168.99609375]], (-81920, 262144), 131072),
    ([[785065.171875, 123306.77734375], [-7581.7890625, 731115.11328125],
      [-445811.48828125, -329830.62890625]], (0, 262144), 262144),
    ([[-184739.39453125, 1629235.2109375], [1473004.31640625, -326322.73828125],
      [1241497.6875, 636631.08203125]], (945204, 296296), 1),
    ([[1823073.64453125, 389113.578125], [-332594.62109375, 1642953.21875],
      [118340.34375, 552972.47265625]], (223956, 1319236), 1),
)  # fmt: skip


def _float64_tie(xy, first, size):
    """A case of :data:`FLOAT64_TIES` as a grid (label, vertices, x0, y0, size), its label
    saying where the deciding centre lies (computed: :func:`.block_arithmetic.float64_slip`)."""
    from .block_arithmetic import UNITS, float64_slip

    xy = np.array(xy, dtype=float)
    edge, t, key = float64_slip(xy, *first, size)
    x, y = (c / UNITS for c in (t["hi"] if key == "best" else t["lo"]))
    e = t[key]
    on = "exactly on" if e == 0 else f"{abs(e)}/65536 px² {'inside' if e > 0 else 'outside'}"
    kind = edge_kind((edge["B"], -edge["A"]))
    which = "its centre" if size == 1 else f"its {'best' if key == 'best' else 'worst'} centre"
    block = "one pixel" if size == 1 else f"a {size:,}-px block"
    label = (f"far out in float64: {block}, vertices with 1/256 fractions up to "
             f"{np.abs(xy).max():,.0f} px out, {which} ({num(x)}, {num(y)}) {on} a {kind} edge")  # fmt: skip
    return (label, xy, *_around(*first, size, (1, 1)), size)


_huge = cache(_huge_blocks)


def block_cases() -> list:
    """The hard and random grids (fixed, then drawn for this check), then the huge blocks
    and the far ties of 256 and 1024 px, last, so that a per-centre scan is told its other
    mistakes before it runs out of time."""
    return _seeded_cases() + copy.deepcopy(_huge())


block_cases.__module__ = _seeded_cases.__module__


def _edge_table(xy, x0, y0, size):
    """Per oriented edge: its name, top-left flag, and the corners maximising / minimising E."""
    setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
    v = setup.p / setup.unit
    rows, cols = _corners(x0, y0, size)
    e = edge_values_at(setup, rows, cols) / setup.unit**2  # in px²
    out = []
    for k in range(3):
        a, b = setup.perm[k], setup.perm[(k + 1) % 3]
        kmax, kmin = int(np.argmax(e[:, k])), int(np.argmin(e[:, k]))
        d = v[(k + 1) % 3] - v[k]
        kind = edge_kind(d)
        out.append({
            "name": f"v{a + 1}→v{b + 1}", "kind": kind, "owns": bool(setup.top_left[k]),
            "max": (cols[kmax] + 0.5, rows[kmax] + 0.5, float(e[kmax, k])),
            "min": (cols[kmin] + 0.5, rows[kmin] + 0.5, float(e[kmin, k])),
            "pass": setup.inside(k, edge_values_at(setup, rows, cols)[:, k]),
        })  # fmt: skip
    return out


def _corner(c) -> str:
    return f"{vec(c[:2])} (E = {num(c[2])})"


#: The verdicts from the most to the least generous.
_GENEROUS = {"accepted": 2, "partial": 1, "rejected": 0}


def _on_edge(edges, expected=None, got=None):
    """An edge exactly through one of the block's extreme centres, and that centre: the edge
    whose rule decides the verdict where one can tell (r214 item 6: at a vertex, on two edges,
    the first edge found included the centre, while the other excluded it and so rejected the
    block). An answer more generous than the right one is told an edge that excludes the
    centre, a stricter one an edge that includes it; the centre is the one that decides
    (the largest E for a rejection, else the smallest)."""
    found = [(e, key) for e in edges for key in ("max", "min") if e[key][2] == 0]
    if not found:
        return None, None
    if expected in _GENEROUS and got in _GENEROUS and expected != got:
        owns = _GENEROUS[got] < _GENEROUS[expected]  # stricter: an edge that includes it
        deciding = "max" if (expected if not owns else got) == "rejected" else "min"
        ranked = sorted(found, key=lambda f: (f[0]["owns"] != owns, f[1] != deciding))
        edge, key = ranked[0]
        return edge, edge[key][:2]
    edge, key = found[0]
    return edge, edge[key][:2]


def _by_verdicts(edges, expected, got, cause: bool = False) -> str:
    """The rule that decides this block, quoting its extreme centres. ``cause``: the words of
    the mistakes that test the wrong corner (r162 M1: the generic rule said "you tested the
    maximising one" and "Corners outside the triangle do not reject a block" to offsets that
    stop short of the block's last centre, which neither is)."""
    if expected == "rejected":
        edge = next(e for e in edges if not e["pass"].any())
        return (
            f": edge {edge['name']} excludes the block's four corner centres (and so every "
            f"centre between them): even the corner that maximises its E, "
            f"{_corner(edge['max'])}, fails; one such edge rejects the block"
        )
    if expected == "accepted":
        worst = min(edges, key=lambda e: e["min"][2])
        return (
            f": every edge includes the block's four corner centres; the lowest of the "
            "minimising corners is "
            f"{_corner(worst['min'])} for edge {worst['name']}, which passes"
        )
    failing = next((e for e in edges if not e["pass"].all()), None)
    if got == "accepted" and failing is not None:
        return (
            f": this corner, {_corner(failing['min'])}, is the one that minimises E for edge "
            f"{failing['name']}, and it fails"
            + (f"; you tested the maximising one, {_corner(failing['max'])}" if cause else "")
        )
    best = [f"{e['name']}: {_corner(e['max'])}" for e in edges]
    return (
        ": no edge excludes the block's four corner centres (each edge's maximising corner "
        "passes: " + "; ".join(best) + ")" + (_OUTSIDE if cause else "")
    )


_OUTSIDE = ". Corners outside the triangle do not reject a block: the test is per edge"


#: Fill colours of the blocks by the package's verdict: the picture's key below it (r149 E2:
#: grey, teal and orange here, white, greens and blues there, and no key of its own).
VERDICT_COLOURS = {"rejected": "#ffffff", "accepted": "#1b7837", "partial": "#2b7bba"}


def _block_key(ax, want, marked: bool, below: bool = False) -> None:
    """The case plot's own key: the package's verdicts present, the block that differs;
    ``below`` the axes where a note (no answer: an endless loop, an exception) is written
    across them (r162 D3: the note's box covered the key at the right)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    handles = [Patch(facecolor=VERDICT_COLOURS[k], alpha=0.35, edgecolor="#636363", label=f"package: {k}")  # fmt: skip
               for k in KINDS if (want == k).any()]  # fmt: skip
    if marked:
        handles.append(Line2D([], [], color="#d7301f", lw=2.5, label="first block that differs"))
    if below:  # under the tick labels and the x label: a fixed distance in points
        from matplotlib.transforms import ScaledTranslation

        under = ax.transAxes + ScaledTranslation(0, -48 / 72, ax.figure.dpi_scale_trans)
        ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                  bbox_transform=under, fontsize="small", frameon=False,
                  ncols=len(handles))  # fmt: skip
        return
    ax.legend(handles=handles, loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize="small",
              frameon=False)  # fmt: skip


#: The widest grid (px) a failing case's panel shows whole; a wider one is zoomed on the block
#: that differs (r198 C.1).
SMALL_GRID = 32


def draw_block_case(ax, case, got):
    """The snapped triangle over the grid's blocks, each tinted by the package's verdict, the
    first block that differs outlined (its four extreme centres once the hints are spent)."""
    from matplotlib.patches import Rectangle

    from .drawing import note_beside, plain_ticks

    xy, gx, gy, size = case[1]
    gx, gy = grid_of(gx, gy)
    want = np.broadcast_to(np.asarray(case[2]), gx.shape)
    artists, labelled = [], False
    for bx, by, kind in zip(gx.ravel(), gy.ravel(), want.ravel(), strict=True):
        patch = Rectangle((bx, by), size, size, facecolor=VERDICT_COLOURS[str(kind)], alpha=0.35,
                          edgecolor="#636363", linewidth=0.6)  # fmt: skip
        artists.append(ax.add_patch(patch))
    ring = np.vstack([snap(xy), snap(xy)[:1]])
    artists += ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1)
    _, (_, bx, by, _), e, g, wrong = first_block(case[1], case[2], case[2] if got is None else got)
    if got is not None and wrong:
        box = np.array([[bx, by], [bx + size, by], [bx + size, by + size], [bx, by + size], [bx, by]])  # fmt: skip
        artists += ax.plot(box[:, 0], box[:, 1], color="#d7301f", linewidth=2.5)
        # r73 08-1: the four decisive centres are the task's question: drawn only once two
        # different answers have failed, as the words say
        from .tries import hints_spent

        if hints_spent("classify_block"):
            ys, xs = _corners(bx, by, size)
            # r149 E2: each centre's smallest E over the edges beside it (a tie reads E = 0)
            setup = setup_edges(np.asarray(xy, dtype=float), SUBPIXEL_BITS)
            low = (edge_values_at(setup, ys, xs) / setup.unit**2).min(axis=1)
            for x, y, ev in zip(xs, ys, low, strict=True):  # outward, beside its centre
                right, down = x == xs.max() and size > 1, y == ys.max() and size > 1
                artists.append(ax.annotate(f"E = {num(float(ev))}", (x + 0.5, y + 0.5),
                                           xytext=(6 if right else -6, -8 if down else 8),
                                           textcoords="offset points", fontsize="x-small",
                                           ha="left" if right else "right",
                                           va="top" if down else "bottom",
                                           bbox={"boxstyle": "round,pad=0.1", "alpha": 0.8,
                                                 "facecolor": "white", "edgecolor": "none"}))  # fmt: skip
            artists += ax.plot(xs + 0.5, ys + 0.5, "o", color="#2b7bba", ms=4)
            labelled = True
    # r396 G3 (r446): the difference on a line of its own (one line was thrice the axes' width)
    yours = "" if got is None or not wrong else f"\nfirst differing block {e}, yours {g}"
    counts = ", ".join(f"{int((want == k).sum())} {k}" for k in KINDS if (want == k).any())
    ax.set_xlabel(f"{counts}{yours}")
    lo = np.minimum(ring.min(axis=0), [gx.min(), gy.min()]) - 1
    hi = np.maximum(ring.max(axis=0), [gx.max() + size, gy.max() + size]) + 1
    if got is not None and wrong and size <= 64:
        # r149 E2: zoomed on the block that differs (a tie ½ px from its side could not be
        # seen in the whole grid), with a margin of half a block; r198 C.1: on the whole grid
        # where it is small (the zoom cropped the blocks the title names, and their vertex)
        pad = max(3.0, size / 2)
        lo, hi = np.array([bx, by]) - pad, np.array([bx, by]) + size + pad
        whole_lo, whole_hi = np.array([gx.min(), gy.min()]), np.array([gx.max(), gy.max()]) + size
        if (whole_hi - whole_lo).max() <= SMALL_GRID:
            lo, hi = whole_lo - pad, whole_hi + pad
    if labelled:  # r214 item 8: room for the labels "E = …" beside the block, inside the axes
        extra = 0.2 * (hi[0] - lo[0])
        lo, hi = lo - [extra, 0.0], hi + [extra, 0.0]
    if got is None:  # r214 item 2: no answer: the report's note beside the panel, not over it
        note_beside(ax)
    _block_key(ax, want, got is not None and wrong, below=got is None)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(hi[1], lo[1])
    if size >= BLOCK_TICKS:
        _ticks_in_blocks(ax, size)
        ax.set_ylabel("y0 (blocks)")
    else:
        plain_ticks(ax)
        # r248 S4: the axes' quantity and unit
        ax.set_xlabel(f"x (px); {ax.get_xlabel()}")
        ax.set_ylabel("y (px, down)")
    ax.set_aspect("equal")
    return artists


#: The block size from which a panel's ticks count blocks (0, 1, 2 …), not pixels (r214 item 2:
#: "1000000" and "2000000", tilted, ran into each other under a 2¹⁹-px grid).
BLOCK_TICKS = 1024


def _ticks_in_blocks(ax, size: int) -> None:
    """Ticks on the blocks' sides, counted in blocks of ``size`` px, the unit said in the x
    label (a label such as "2·2¹⁹" at each tick was too wide for the panel)."""
    from matplotlib.ticker import FuncFormatter, MultipleLocator

    power = int(size).bit_length() - 1
    unit = f"2{superscript(power)}" if size == 1 << power else f"{size:,}"
    # r248: a far tie's view spans 9 blocks: every other one labelled past 6 (they ran together)
    span = max(abs(np.diff(ax.get_xlim()))[0], abs(np.diff(ax.get_ylim()))[0]) / size
    step = size * max(1, int(np.ceil(span / 6)))
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_locator(MultipleLocator(step))
        axis.set_major_formatter(FuncFormatter(lambda value, _: f"{value / size:g}"))
    ax.set_xlabel(f"x0, y0 in blocks of {unit} px; {ax.get_xlabel()}")


#: The register classify_block counts in (NumPy's int64; Python's ints have no limit).
INT_BITS = 64


@cache
def coordinate_range() -> tuple[float, float]:
    """The smallest and largest x or y (px) of the check's vertices and blocks."""
    lo, hi = np.inf, -np.inf
    for _, (xy, gx, gy, size), _ in block_cases():
        lo = min(lo, float(np.min(xy)), float(min(gx.min(), gy.min())))
        hi = max(hi, float(np.max(xy)), float(max(gx.max(), gy.max()) + size))
    return lo, hi


def integer_budget() -> str:
    """The sentence cell 1 of exercise 08 prints (cell 2 refers to it): lesson 10 §4's bit
    count for the check's cases in units of 1/256 px. r232 M1: the task counts in integers, as
    lesson 10 §4 counts on a GPU's grid (r248 C1: the package's walker keeps 512 units a pixel;
    the task asked for float64, whose exactness needed a reach, and a bias added to a large E₀
    rounded away, r232 C1): every coordinate that enters, vertex or pixel centre,
    lies within a range of L px, so two differ by less than 256·L ≤ 2^d units, and E needs
    2d + 2 bits with its sign."""
    lo, hi = coordinate_range()
    span = hi - lo
    d = int(np.ceil(np.log2(UNITS * span)))
    assert 2 * d + 2 <= INT_BITS, d  # the check's own cases: int64 holds every value
    return (
        f"8.1: the check's vertices and pixel centres lie within x, y = {lo:,.0f} … {hi:,.0f} px, "
        f"a range of L = {span:,.0f} px: in units of 1/{UNITS} px two coordinates differ by less "
        f"than {UNITS}·L < 2^{d}, so E needs 2·{d} + 2 = {2 * d + 2} bits (lesson 10 §4's count): "
        f"int{INT_BITS} holds every value exactly"
    )


def float64_limit() -> str:
    """The sentence cell 1 of exercise 08 prints beside lesson 10 §4's count (cell 2 quotes
    it, r248 F1): where float64 pixels stop being exact on the check's cases."""
    from . import block_arithmetic as ba  # (it reads the grid module, not this one)

    fraction = 2 * 8  # bits after the point of a product: 8 from each factor (1/256 grid)
    exact = ba.FLOAT64_BITS - fraction
    reach = max(abs(c) for c in coordinate_range())
    return (
        f"float64 pixels: a product of two differences on the 1/256 grid has {fraction} bits "
        f"after the point, so float64's {ba.FLOAT64_BITS} bits hold it exactly only below "
        f"2{superscript(exact)} px² (differences up to about {2 ** (exact / 2):,.0f} px); the check's "
        f"coordinates reach {reach:,.0f} px"
    )


def pixel_words(xy, row: int, col: int) -> str:
    """Why the triangle covers pixel (row, col) or not: its centre against each edge (r173 D1:
    the scene's caption gave the block's verdict only, not why its wrongly filled pixel is
    wrong, a centre exactly on a right edge)."""
    edges = _edge_table(xy, col, row, 1)
    centre = vec(edges[0]["max"][:2])
    failing = next((e for e in edges if not e["pass"].any()), None)
    if failing is None:
        return f"its centre {centre} passes every edge: the triangle covers it"
    if failing["max"][2] == 0:
        return (f"its centre {centre} lies exactly on edge {failing['name']}, and the top-left "
                "rule excludes it (which kind of edge is it, with y pointing down?): the "
                "triangle does not cover it")  # fmt: skip
    return (f"its centre {centre} lies outside edge {failing['name']} (E = "
            f"{num(failing['max'][2])} px²): the triangle does not cover it")  # fmt: skip
