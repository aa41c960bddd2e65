"""Exercise ``line_pixels(p0, p1)`` of lesson 12a: the diamond-exit rule.

The expected pixels come from the core: :func:`teachraster.rasterize_line` (exact, with the
tie perturbation (x, y) − (ε, ε²) applied to teachraster's y-down window numbers: GL's
answer for every sloped line, Direct3D's for a horizontal line on a row boundary; lesson 12a
§1 and CONVENTIONS, Lines). The mistakes are the rule with a knob turned
(:func:`diamond_pixels`, here in floats with ε = 2⁻²⁰ and ε² = 2⁻⁴⁰, far above float64's
rounding of these coordinates and far below their 1/8 grid): the end pixel lit, or tested
before it was moved, the start pixel left dark, a closed diamond, no perturbation or one in
another direction, an ε too large, pairs given as (col, row), the end points read as (y, x),
the segment drawn from p1 to p0 (always, or where sorting the end points puts p1 first, as a
Bresenham loop does), Bresenham's walk, and a DDA that rounds the line at each column instead
of testing diamonds. The cases hold ties of every kind:
horizontal and vertical lines on pixel boundaries (both directions), 45° lines along diamond
edges, lines through diamond corners, and lines that pass a diamond corner so closely that an
ε of 1/100 moves them across it. A mistake is named only where it gives every failing answer
(r9: the end tested before moving was named "(−ε, −ε)" from one case it happened to share).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..core.lines import rasterize_line
from .answers import as_numbers, short
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Knobs, Mistake, PackageAnswer, Slip
from .running import WrongAnswerType

#: Lines live in a WINDOW × WINDOW image; end points on the 1/8 grid so ties happen.
WINDOW = 12
SEED = 20241126
#: The perturbation of the knobs' diamond rule.
EPS = 2.0**-20


def line_cases() -> list[tuple[str, tuple, set]]:
    """(label, (p0, p1), expected set of (row, col)) for the hard lines, then random ones."""
    named = [
        ("horizontal through centres", (1.5, 2.5), (8.5, 2.5)),
        ("vertical on a pixel boundary (x = 3)", (3.0, 0.25), (3.0, 7.25)),
        ("vertical on a pixel boundary, upwards", (5.0, 9.25), (5.0, 1.75)),
        ("horizontal on a pixel boundary (y = 3)", (0.25, 3.0), (7.25, 3.0)),
        ("horizontal on a pixel boundary, leftwards", (9.75, 6.0), (1.25, 6.0)),
        ("horizontal on a boundary from a centre column", (1.5, 8.0), (10.5, 8.0)),
        ("45° through centres", (0.5, 0.5), (7.5, 7.5)),
        ("45° along diamond edges (x + y = 7.5)", (0.5, 7.0), (7.0, 0.5)),
        ("45° along diamond edges, downwards", (2.0, 1.5), (8.0, 7.5)),
        ("x-major, a half-pixel tie (dy/dx > 0)", (0.5, 0.5), (8.5, 4.5)),
        ("x-major, a half-pixel tie (dy/dx < 0)", (0.5, 4.5), (8.5, 0.5)),
        ("y-major, a half-pixel tie", (0.5, 0.5), (4.5, 8.5)),
        # r18 D-4: on the 1/8 grid, as the task says every end point is (they were decimals)
        ("start inside its diamond, off centre", (1.75, 1.625), (9.25, 4.125)),
        ("end on a diamond corner", (1.25, 1.25), (6.5, 4.0)),
        ("running left and up", (10.375, 9.25), (1.625, 2.25)),
        ("zero length", (4.5, 4.5), (4.5, 4.5)),
        ("shorter than a pixel", (2.25, 2.375), (2.75, 2.625)),  # in one diamond
        # r9: an ε of 1/100 moves these across a diamond corner they pass within ε of (found
        # by a search over the 1/8 grid); the infinitesimal ε does not
        ("steep, past a corner by less than 1/100", (9.25, 6.25), (10.25, 2.625)),
        ("steep, past a corner, downwards", (1.375, 1.75), (3.25, 8.375)),
        ("x-major, past a corner by less than 1/100", (11.5, 2.625), (4.25, 7.625)),
        # r14 09-8: moved by −ε, p0 lies in the diamond of column −1, outside the image
        ("start on the image's left edge (x = 0), on a row's centre line", (0.0, 2.5), (5.0, 2.5)),
    ]
    rng, now = np.random.default_rng(SEED), drawn_rng()
    for k in range(24 + DRAWN):
        r = rng if k < 24 else now  # the last few drawn for this check (r11 09-B)
        # plain floats: a case prints as (8.125, 10.125), not np.float64(8.125) (r11 09-C)
        p0, p1 = (tuple(float(v) for v in r.integers(0, WINDOW * 8, 2) / 8) for _ in range(2))
        named.append((f"random line {k}" if k < 24 else f"line drawn for this check {k - 23}",
                      p0, p1))  # fmt: skip
    return [(label, (p0, p1), _expected_pixels(p0, p1)) for label, p0, p1 in named]


def _expected_pixels(p0, p1) -> frozenset[tuple[int, int]]:
    cov = rasterize_line(p0, p1, WINDOW, WINDOW).coverage
    return frozenset((int(r), int(c)) for r, c in np.argwhere(cov))


def as_pixels(value) -> frozenset[tuple[int, int]]:
    """The student's pixels as a set of (row, col); read as strictly as every answer."""
    if isinstance(value, (set, frozenset)):
        value = sorted(value, key=repr)
    if isinstance(value, (list, tuple)) and len(value) == 0:
        return frozenset()
    if isinstance(value, np.ndarray) and value.size == 0 and value.ndim <= 2:
        return frozenset()  # np.array([]) is an empty list of pairs too, shape (0,) (r8)
    arr = as_numbers(value, (-1, 2), "a list of (row, col) pairs")
    if not np.isfinite(arr).all() or (arr != np.round(arr)).any():
        raise WrongAnswerType(f"returned {short(value)}: pixel indices are whole numbers")
    pairs = [(int(r), int(c)) for r, c in arr]
    if len(set(pairs)) != len(pairs):
        raise WrongAnswerType("returned a pixel twice: a line lights each pixel at most once")
    return frozenset(pairs)


def diamond_pixels(p0, p1, *, eps=(-EPS, -EPS * EPS), end=False, order="row col",
                   closed=False, start=False, half=0.5, centre=0.5, inside=True):  # fmt: skip
    """The diamond-exit rule with knobs: the perturbation ``eps`` added to both end points;
    ``end=True`` also lights the pixel whose diamond holds p1, ``end="unmoved"`` tests that
    diamond with p1 before it was moved (``"unmoved closed"``: and its boundary counted in;
    ``"p1 never moved"``: p1 is not moved for the segment either); ``closed=True`` counts the
    diamond's boundary in;
    ``start=True`` leaves the diamond that holds (the moved) p0 dark; ``order="col row"``
    gives pairs the other way round; ``half`` is the diamond's radius and ``centre`` where it
    sits in its pixel (½: the centre); ``inside=False`` keeps pixels left of or above the
    image (column or row −1).

    The pixels of plain numbers are kept (:func:`_kept_diamonds`): a check asks each of its
    ~80 mistakes about every case, and the fixed cases again at every check.
    """
    knobs = (end, order, closed, start, half, centre, inside)
    ends = (*p0, *p1, *eps) if all(type(p) in (tuple, list) for p in (p0, p1, eps)) else ()
    if (len(ends) == 6 and all(type(v) in (float, int) for v in ends)
            and all(type(k) in (bool, str, float, int) for k in knobs)):  # fmt: skip
        return _kept_diamonds(*ends, *knobs)
    return _diamonds(p0, p1, eps, *knobs)


@lru_cache(maxsize=16384, typed=True)  # typed: end=True is not end=1
def _kept_diamonds(x0, y0, x1, y1, ex, ey, end, order, closed, start, half, centre, inside):
    """:func:`_diamonds` of plain numbers (the cases' end points are floats), kept: the
    pixels are a frozenset, and the same numbers give the same pixels."""
    return _diamonds((x0, y0), (x1, y1), (ex, ey), end, order, closed, start, half, centre,
                     inside)  # fmt: skip


def _diamonds(p0, p1, eps, end, order, closed, start, half, centre, inside):
    """:func:`diamond_pixels`, computed."""
    a, b = np.asarray(p0, float) + eps, np.asarray(p1, float) + eps
    if end == "p1 never moved":
        b = np.asarray(p1, float)
    lo, hi = np.floor(np.minimum(a, b)) - 1, np.floor(np.maximum(a, b)) + 2
    # no clip at the window's far side: a student's too-large diamond reaches past it
    first = np.maximum(lo, 0) if inside else lo
    cols, rows = np.meshgrid(np.arange(first[0], hi[0]), np.arange(first[1], hi[1]))
    cx, cy = cols.ravel() + centre, rows.ravel() + centre
    ok = _meets(a, b, cx, cy, closed, half)
    if end is not True:
        e = np.asarray(p1, float) if str(end).startswith("unmoved") else b
        far = np.abs(e[0] - cx) + np.abs(e[1] - cy)
        ok &= far > half if end == "unmoved closed" or closed == "all" else far >= half
    if start:
        ok &= np.abs(a[0] - cx) + np.abs(a[1] - cy) >= half
    pixels = zip(rows.ravel()[ok].astype(int), cols.ravel()[ok].astype(int))
    return frozenset((c, r) if order == "col row" else (r, c) for r, c in pixels)


def _meets(a, b, cx, cy, closed=False, half=0.5) -> np.ndarray:
    """Does the segment a -> b meet each diamond (open, or ``closed``) around (cx, cy)?"""
    d = b - a
    t_lo, t_hi = np.zeros(cx.shape), np.ones(cx.shape)
    lo_open, hi_open = np.zeros(cx.shape, bool), np.zeros(cx.shape, bool)
    ok = np.ones(cx.shape, bool)
    for sx, sy in ((1, 1), (1, -1), (-1, 1), (-1, -1)):  # sx(x − cx) + sy(y − cy) < ½
        c = half - sx * (a[0] - cx) - sy * (a[1] - cy)
        rate = sx * d[0] + sy * d[1]
        if rate == 0:
            ok &= c >= 0 if closed else c > 0
            continue
        t = c / rate
        if rate > 0:
            tighter = t <= t_hi
            t_hi, hi_open = np.where(tighter, t, t_hi), hi_open | tighter
        else:
            tighter = t >= t_lo
            t_lo, lo_open = np.where(tighter, t, t_lo), lo_open | tighter
    if closed:
        return ok & (t_lo <= t_hi)
    return ok & ((t_lo < t_hi) | ((t_lo == t_hi) & ~lo_open & ~hi_open))


def bresenham_pixels(p0, p1):
    """Bresenham's walk (lesson 12a §2), as the package draws it."""
    cov = rasterize_line(p0, p1, WINDOW, WINDOW, rule="bresenham").coverage
    return frozenset((int(r), int(c)) for r, c in np.argwhere(cov))


def hand_bresenham(p0, p1, end=False):
    """Bresenham's walk as a student writes it from the textbook: the end points floored to
    their pixels, one whole pixel per step, p1's pixel left dark unless ``end``."""
    (x0, y0), (x1, y1) = ((int(np.floor(x)), int(np.floor(y))) for x, y in (p0, p1))
    dx, dy = abs(x1 - x0), -abs(y1 - y0)
    sx, sy = (1 if x0 < x1 else -1), (1 if y0 < y1 else -1)
    err, out = dx + dy, set()
    while (x0, y0) != (x1, y1):
        out.add((y0, x0))
        e2 = 2 * err
        if e2 >= dy:
            err, x0 = err + dy, x0 + sx
        if e2 <= dx:
            err, y0 = err + dx, y0 + sy
    return frozenset(out | ({(y1, x1)} if end else set()))


def classic_bresenham(p0, p1):
    """Bresenham's loop as most courses print it (r14 09-6): ``err = dx − dy``, a step in x
    when ``e2 > −dy``, in y when ``e2 < dx`` (strict: at a tie it stays where Zingl's form of
    :func:`hand_bresenham` steps), the end points floored, both end pixels lit."""
    (x0, y0), (x1, y1) = ((int(np.floor(x)), int(np.floor(y))) for x, y in (p0, p1))
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx, sy = (1 if x0 < x1 else -1), (1 if y0 < y1 else -1)
    err, out = dx - dy, {(y0, x0)}
    while (x0, y0) != (x1, y1):
        e2 = 2 * err
        if e2 > -dy:
            err, x0 = err - dy, x0 + sx
        if e2 < dx:
            err, y0 = err + dx, y0 + sy
        out.add((y0, x0))
    return frozenset(out)


def sampled_dda(p0, p1):
    """A DDA as a textbook samples it (r14 09-6): n = max(|dx|, |dy|) (whole) evenly spaced
    points from p0, p1 not among them, each lighting the pixel it lies in."""
    (x0, y0), (x1, y1) = p0, p1
    n = int(max(abs(x1 - x0), abs(y1 - y0)))
    return frozenset(
        (int(np.floor(y0 + (y1 - y0) * k / n)), int(np.floor(x0 + (x1 - x0) * k / n)))
        for k in range(n)
    )


def rounded_dda(p0, p1, centred=False):
    """A DDA that rounds (r289 S1): n = max(|dx|, |dy|) steps between the end points' pixels
    (``centred``: the end points less ½, which puts the pixel centres on whole numbers, n
    counted between them rounded), each point x0 + k·dx/n rounded to the nearest whole pixel,
    p1's step left out."""
    if centred:
        x0, y0, x1, y1 = (float(v) - 0.5 for v in (*p0, *p1))
        n = max(abs(round(x1) - round(x0)), abs(round(y1) - round(y0)))
    else:
        x0, y0, x1, y1 = (int(np.floor(v)) for v in (*p0, *p1))
        n = max(abs(x1 - x0), abs(y1 - y0))
    steps = ((round(x0 + (x1 - x0) * k / n), round(y0 + (y1 - y0) * k / n)) for k in range(n))
    return frozenset((y, x) for x, y in steps if 0 <= x < WINDOW and 0 <= y < WINDOW)


def _unmoved_range(p0, p1):
    """The rule's pixels inside the box of the pixels the unmoved end points lie in."""
    (c0, c1), (r0, r1) = (sorted((int(np.floor(p0[k])), int(np.floor(p1[k])))) for k in (0, 1))
    return frozenset((r, c) for r, c in diamond_pixels(p0, p1) if r0 <= r <= r1 and c0 <= c <= c1)


def _unmoved_range_words(p0, p1) -> str:
    """What a search over the unmoved end points' pixels misses, for this line (r12 09-2: the
    words said a diamond reaches past its pixel's square, which it does not, and gave a
    vertical line's example for a horizontal one). An end point on a pixel boundary, x = k or
    y = k, moves by −ε (−ε²) into column (row) k − 1, and lit pixels may lie there."""
    (c0, _), (r0, _) = (sorted((int(np.floor(p0[k])), int(np.floor(p1[k])))) for k in (0, 1))
    missed = sorted(diamond_pixels(p0, p1) - _unmoved_range(p0, p1))
    moves = []
    for axis, k, by, what in ((0, c0, "−ε", "column"), (1, r0, "−ε²", "row")):
        if any(m[1 - axis] < k for m in missed):
            on = f"{'xy'[axis]} = {k}"
            ends = f"both end points, on {on}, move" if p0[axis] == p1[axis] else (
                f"the end point on {on} moves")  # fmt: skip
            moves.append(f"{ends} by {by} into {what} {k - 1}")
    lit = ", ".join(f"({r}, {c})" for r, c in missed[:4]) + (" …" if len(missed) > 4 else "")
    return (
        "you searched only the pixels the unmoved end points' box covers, but the rule moves "
        f"the end points first: {' and '.join(moves) or 'an end point moves'}, outside that "
        f"box, and the moved segment lights pixels (row, col) {lit} there. Search the box of the moved end "
        "points' pixels"
    )


def dda_pixels(p0, p1):
    """One pixel per major-axis centre, the line rounded there (no diamond)."""
    (x0, y0), (x1, y1) = p0, p1
    dx, dy = x1 - x0, y1 - y0
    out = set()
    if abs(dx) >= abs(dy) and dx:
        for j in range(int(min(x0, x1)), int(max(x0, x1)) + 1):
            x = j + 0.5
            if min(x0, x1) <= x < max(x0, x1):
                out.add((int(np.floor(y0 + (x - x0) * dy / dx)), j))
    elif dy:
        for i in range(int(min(y0, y1)), int(max(y0, y1)) + 1):
            y = i + 0.5
            if min(y0, y1) <= y < max(y0, y1):
                out.add((i, int(np.floor(x0 + (y - y0) * dx / dy))))
    return frozenset(p for p in out if 0 <= p[0] < WINDOW and 0 <= p[1] < WINDOW)


#: Said after the cause (r289 S3: ~430 characters of it opened every tie explanation; r326 S4:
#: it still followed the cause at that length), and attributed as lesson 12a §1 does: the
#: −(ε, ε²) in y-down numbers is Vulkan's rule (S8).
_TIE = (
    "at a tie the rule moves both end points by (−ε, −ε²), ε vanishingly small: x left, y up "
    "the image, so a line on x = k lights column k − 1 and one on y = k row k − 1, the upper "
    "row, as Vulkan's rule does (GL's window has y up and lights the lower row, row k: lesson "
    "12a §1)"
)
#: How :data:`_TIE` reads after the first line that says it in full (r23 D-6).
_TIE_AGAIN = "at a tie the rule moves both end points by (−ε, −ε²), as said above"


def _float_example(args, axes) -> str:
    """ ": 6.0 − 1e-16 == 6.0 in float64, whose spacing just below 6 is 8.9e-16", for a
    coordinate of the case's own end points on ``axes`` (0: x, 1: y), one on a pixel
    boundary first (where the ties are): a move below half that spacing vanishes (r23 D-6:
    the words quoted 3.0 on lines at x = 5 and y = 6). Empty when every such coordinate is 0."""
    values = [float(p[k]) for k in axes for p in args if float(p[k]) != 0]
    if not values:
        return ""
    v = min(values, key=lambda x: (x != round(x), abs(x)))  # a boundary first, then the nearest
    tiny = next(10.0**k for k in range(-1, -330, -1) if v - 10.0**k == v)
    gap = v - float(np.nextafter(v, -np.inf))
    return f": {v!r} − {tiny:.0e} == {v!r} in float64, whose spacing just below it is {gap:.2g}"


def _lost(what: str, axes):
    """Words for a perturbation that an answer may have lost to rounding: ``what`` it shows,
    and the case's own coordinate that a float move vanishes beside (r8: 1e-18 was told
    "left y as it is", and the student had not)."""

    def words(args, expected, got) -> str:
        return (f"{what} (or yours was lost in floating point{_float_example(args, axes)}; "
                "compute with Fraction, as the task says, and convert each coordinate: a "
                f"float minus a Fraction is a float again, so write Fraction(x) − ε); {_TIE}")  # fmt: skip

    return words


#: (x move, y move) -> what the student did, in words. Each wrong pair names the coordinate
#: that is off and by how much, never a mistake the answer cannot show (r8: (−ε, −ε) was
#: called "you swapped the two").
_MOVES = {
    (0.0, 0.0): ("no perturbation", _lost("you did not move the end points at all", (0, 1))),
    (-EPS, 0.0): ("no ε² in y", _lost("you did not move y", (1,))),
    (-EPS, EPS * EPS): ("+ε² in y", "you moved y by +ε² (down the image; the rule moves it up, "
                        "by −ε²)"),
    (-EPS, -EPS): ("ε in y", "you moved y by −ε, as much as x: y moves by ε², far "
                   "less than x's ε, so that y decides only the ties x leaves"),
    (-EPS, EPS): ("+ε in y", "you moved y by +ε: y moves by −ε² (up, and far less "
                  "than x)"),
    (EPS, -EPS * EPS): ("+ε in x", "you moved x by +ε (to the right; the rule moves "
                        "it left)"),
    (EPS, 0.0): ("+ε in x, y not moved", "you moved x by +ε (right; the rule moves it left) and "
                 "did not move y"),
    (EPS, EPS * EPS): ("+ε in x, +ε² in y", "you moved both the other way: x by +ε and y by "
                       "+ε² (the rule moves them left and up)"),
    # r483 H2: y moved by ε/2 breaks no tie on a line of slope ½ (the move runs along it)
    (-EPS, -EPS / 2): ("ε in y", "you moved y by −ε/2, a multiple of x's ε: y moves by ε², "
                       "far less than any multiple of ε, so that y decides only the ties x "
                       "leaves (a move along a line of slope ½ breaks no tie on it)"),
    (0.0, -EPS * EPS): ("x not moved", "you did not move x"),
    (0.0, -EPS): ("only y moved", "you did not move x, and moved y by −ε"),
    # r326: what reading the end points as (y, x) and returning (col, row) pairs gives (the
    # image transposed twice, the tie moves once): the likelier cause, said first
    (-EPS * EPS, -EPS): ("ε in y, ε² in x", "you read the end points as (y, x) and returned "
                         "(col, row) pairs, or gave each coordinate the other's move: either "
                         "way you moved x by −ε² and y by −ε. p0 and p1 are (x, y), and the larger move "
                         "belongs to x (−ε), the tinier one to y (−ε²)"),
}  # fmt: skip


def _end_lit(a, e, g):
    return (f"you lit the pixel whose diamond p1 = {a[1]} lies in: the segment ends there "
            "without exiting it, so the rule leaves it to the next segment (a polyline then "
            "lights each shared vertex once)")  # fmt: skip


def _end_unmoved(a, e, g):
    # r18 D-6: "as for the rest of the segment" told a student who never moved p1 that they
    # had; moving p1 for the end test alone is enough, so the words say only that
    return (f"you tested which diamond p1 = {a[1]} lies in with p1 unmoved: the rule moves "
            "p1 by (−ε, −ε²) for that test too, as it moves p0 (on a tie the moved p1 lies in "
            "another diamond, or in none)")  # fmt: skip


def _p1_never_moved(a, e, g):
    # the fixed cases cannot tell this from the slip above; a random segment ending on a
    # diamond's corner can (test_p1_never_moved_is_not_told_it_was_moved_for_the_segment)
    return (f"you tested which diamond p1 = {a[1]} lies in with p1 unmoved, and ended the "
            "segment at the unmoved p1 too: the rule moves p1 by (−ε, −ε²), as it moves p0, "
            "for the segment and for that test")  # fmt: skip


def _end_unmoved_closed(a, e, g):
    return (f"you tested which diamond p1 = {a[1]} lies in with p1 unmoved, and counted the "
            "diamond's boundary in (≤ ½): the rule moves p1 by (−ε, −ε²) for that test too, "
            "as it moves p0, and its diamonds are open (< ½)")  # fmt: skip


def _start_diamond_dark(a, e, g):
    return (f"you left the diamond p0 = {a[0]} lies in dark: the segment starts inside it and "
            "leaves it, so its pixel is lit (only p1's own diamond stays dark)")  # fmt: skip


LINE_KNOBS = Knobs(diamond_pixels, {
    "end": [Slip("end pixel lit", _end_lit, True),
            Slip("end tested before moving", _end_unmoved, "unmoved"),
            # r11 09-F: with the boundary counted in as well, the rule was restated
            Slip("end tested before moving, closed", _end_unmoved_closed, "unmoved closed"),
            Slip("end tested before moving, p1 never moved", _p1_never_moved, "p1 never moved")],
    "order": [Slip("(col, row) order", "your pairs are (col, row): return (row, col), the row "
                   "first, as an image is indexed [row, col]", "col row")],
    "closed": [Slip("closed diamond", "your diamond includes its boundary (|dx| + |dy| ≤ ½); "
                    "it is open (< ½): a segment that only touches a corner or runs along an "
                    "edge does not meet it, and such ties go to the segment moved by "
                    "(−ε, −ε²)", True),
              # r289 S1: the boundary counted in everywhere, p1's diamond too (with no ε, the
              # reader's closed diamond got the rule restated)
              Slip("closed diamond", "your diamonds include their boundary (|dx| + |dy| ≤ ½), "
                   "p1's too; they are open (< ½): a segment that only touches a corner or runs "
                   "along an edge does not meet one, and such ties go to the segment moved by "
                   "(−ε, −ε²)", "all")],
    "start": [Slip("start diamond dark", _start_diamond_dark, True)],
    # last: in a combination the other slip's cause comes first, the tie words last (r289 S3)
    "eps": [Slip(kind, words if callable(words) else f"{words}; {_TIE}", move)
            for move, (kind, words) in _MOVES.items()],
})  # fmt: skip

#: ε too large (r9: 1/100 passed every case): each gives its own answer, named by its value.
LARGE_EPS = {"1/10": 0.1, "1/16": 1 / 16, "1/20": 0.05, "1/32": 1 / 32, "1/50": 0.02,
             "1/64": 1 / 64, "1/100": 0.01, "1/128": 1 / 128, "1/256": 1 / 256,
             "1/1000": 1e-3}  # fmt: skip


def _large_eps_words(args, expected, got) -> str:
    """Every ε of the table that gives the student's pixels on this case (r14 09-4: ε = 1/64
    was told "those an ε of 1/50 gives", the table's first that fits)."""
    p0, p1 = args
    fits = [n for n, e in LARGE_EPS.items() if diamond_pixels(p0, p1, eps=(-e, -e * e)) == got]
    which = fits[0] if len(fits) == 1 else ", ".join(fits[:-1]) + f" or {fits[-1]}"
    return (f"your ε is not small enough: your pixels are those an ε of {which} (and ε² in "
            "y) gives, where the moved segment crosses a diamond corner it only passes near "
            "and another pixel lights; the rule's ε is smaller than any gap the inputs can "
            "make, so take one far below the 1/8 grid's (2⁻⁸⁰, with Fraction)")  # fmt: skip


def _large_eps(name: str, eps: float) -> Mistake:
    return Mistake(
        "ε not small enough",
        _large_eps_words,
        gives=lambda p0, p1: diamond_pixels(p0, p1, eps=(-eps, -eps * eps)),
    )


def _pixel_of(p) -> tuple[int, int]:
    """(row, col) of the pixel whose square holds the point p = (x, y)."""
    return int(np.floor(p[1])), int(np.floor(p[0]))


def _p1_square_dark(moved: bool):
    """``gives`` (r445 H2): every pixel whose diamond the segment meets, p1's own diamond's
    too, less the pixel whose square holds p1 (``moved``: p1 moved by (−ε, −ε²) first)."""

    def gives(p0, p1):
        end = (p1[0] - EPS, p1[1] - EPS * EPS) if moved else p1
        return diamond_pixels(p0, p1, end=True) - {_pixel_of(end)}

    return gives


def _p1_square_words(args, expected, got) -> str:
    """Which square's pixel was left dark, and where p1 lies: in whose diamond, or in none."""
    p0, p1 = args
    moved = got == _p1_square_dark(True)(p0, p1) and got != _p1_square_dark(False)(p0, p1)
    r, c = _pixel_of((p1[0] - EPS, p1[1] - EPS * EPS) if moved else p1)
    inside = sorted(diamond_pixels(p0, p1, end=True) - diamond_pixels(p0, p1))
    where = (f"the moved p1 lies in the diamond of (row {inside[0][0]}, col {inside[0][1]}), "
             "the one pixel the rule leaves dark" if inside else
             "the moved p1 lies in no diamond (near a corner of its square), so the rule leaves "
             "no pixel dark here")  # fmt: skip
    which = "the moved p1" if moved else f"p1 = {p1}"
    return (f"you left dark the pixel whose square holds {which}, (row {r}, col {c}), instead "
            f"of the one whose diamond holds it: {where}")  # fmt: skip


def _squares(p0, p1, closed=True) -> frozenset[tuple[int, int]]:
    """The pixels inside the image whose square the segment p0 → p1 meets (``closed``: its
    boundary counted in; else its inside, crossed over some length)."""
    (x0, y0), (x1, y1) = p0, p1
    out = set()
    for r in range(WINDOW):
        for c in range(WINDOW):
            lo, hi = 0.0, 1.0
            for a, d, edge in ((x0, x1 - x0, c), (y0, y1 - y0, r)):
                if d == 0:
                    inside = edge <= a <= edge + 1 if closed else edge < a < edge + 1
                    lo, hi = (lo, hi) if inside else (1.0, 0.0)
                    continue
                t1, t2 = sorted(((edge - a) / d, (edge + 1 - a) / d))
                lo, hi = max(lo, t1), min(hi, t2)
            if lo <= hi if closed else lo < hi:
                out.add((r, c))
    return frozenset(out)


def _by_squares(args, expected, got) -> bool:
    """r445 H3/H4: a pixel lit that the rule leaves dark, and every pixel lit on the
    segment's path of (closed) pixel squares: a walk over squares (supercover, or the squares
    the segment leaves). Named only where it fits every failing answer, after the rule's own
    slips, which light pixels on that path too."""
    p0, p1 = args
    ends = {_pixel_of(p1), _pixel_of((p1[0] - EPS, p1[1] - EPS * EPS))}
    # every square crossed inside lit (p1's aside), none off the path (a circle or a diamond
    # of another size lights fewer)
    path = _squares(p0, p1, closed=False) - ends <= got <= _squares(p0, p1)
    return (
        got != expected and path and bool(got - expected or (expected - got <= ends))
    )  # only p1's square left dark where no other pixel tells


def _by_squares_words(args, expected, got) -> str:
    if not got - expected:  # p1's square alone left dark on this case
        return "you walked the pixel squares along the segment; " + _p1_square_words(
            args, expected, got
        )
    return ("you walked the pixel squares along the segment (your pixels are the squares it "
            "reaches); the rule tests the diamond inside each square, |x − (col + ½)| + "
            "|y − (row + ½)| < ½, so a segment that only clips a square's corner or runs along "
            "its edge lights nothing there")  # fmt: skip


def _short_search(args, expected, got) -> bool:
    """r445 H5: only pixels missing, all in the image's last row or last column."""
    missing = expected - got
    return (bool(missing) and got <= expected
            and (all(r == WINDOW - 1 for r, _ in missing)
                 or all(c == WINDOW - 1 for _, c in missing)))  # fmt: skip


def _short_search_words(args, expected, got) -> str:
    missing = sorted(expected - got)
    axis = "row" if all(r == WINDOW - 1 for r, _ in missing) else "column"
    return (f"every pixel you left dark lies in {axis} {WINDOW - 1}, the image's last: your "
            f"search stops before it (range({WINDOW}) runs from 0 to {WINDOW - 1})")  # fmt: skip


def _start_dark(p0, p1):
    start = (int(np.floor(p0[1])), int(np.floor(p0[0])))
    return diamond_pixels(p0, p1) - {start}


def _drawn_sorted(key):
    """``gives``: the rule on the segment drawn from the end point that ``key`` puts first
    (a Bresenham loop's swap, r326 M2): p1 → p0 where ``key(p1, p0) < key(p0, p1)``."""
    return lambda p0, p1: diamond_pixels(p1, p0) if key(p1, p0) < key(p0, p1) else (
        diamond_pixels(p0, p1))  # fmt: skip


def _sorted_words(order: str):
    """Words for :func:`_drawn_sorted`: the direction the rule follows, and which end's pixel
    it leaves dark, by the case's numbers."""

    def words(args, expected, got) -> str:
        lit = ", ".join(f"(row {r}, col {c})" for r, c in sorted(got - expected))
        dark = ", ".join(f"(row {r}, col {c})" for r, c in sorted(expected - got))
        return (f"you drew this segment from p1 to p0 (you put the end points in order {order}, "
                "as a Bresenham loop does): the rule depends on the direction; it runs from p0 "
                "to p1 and leaves only p1's own diamond dark" +
                (f"; you lit p1's pixel {lit}" if lit else "") +
                (f"; you left p0's pixel {dark} dark" if dark else ""))  # fmt: skip

    return words


def _major(p, q):
    """Sort key of a Bresenham loop: the coordinate that changes more from p to q (x on a
    tie), then the other."""
    x_major = abs(q[0] - p[0]) >= abs(q[1] - p[1])
    return (p[0], p[1]) if x_major else (p[1], p[0])


#: r326 M2: end points put in order before drawing reverse about half the segments, and got
#: the rule restated (the "reversed" mistake reverses all of them, and fits no other).
SORTED_ENDS = {
    "left to right": lambda p, q: (p[0], p[1]),
    "left to right (by x alone)": lambda p, q: p[0],
    "top to bottom": lambda p, q: (p[1], p[0]),
    "top to bottom (by y alone)": lambda p, q: p[1],
    "along the axis that changes more": _major,
}


def _transposed_words(args, expected, got) -> str:
    """r326 M1: the end points read as (row, col), the pairs then right by that reading."""
    (x0, y0), _ = args
    return (f"you read the end points as (y, x): p0 and p1 are (x, y), x along the columns and "
            f"y down the rows, so p0 = ({x0}, {y0}) lies in column {int(np.floor(x0))}, row "
            f"{int(np.floor(y0))}; your pixels are those of the segment mirrored across the "
            "diagonal")  # fmt: skip


_BRESENHAM = ("you walked the line with Bresenham's error term (lesson 12a §2): it takes the "
              "end points to the pixels they lie in and steps one whole pixel at a time; the "
              "diamond-exit rule tests the diamonds the segment itself passes through and "
              "leaves")  # fmt: skip


def _slabs_apart(p0, p1) -> frozenset:
    """r483 H1: the pixels whose u slab and v slab the moved segment each meets, at any t
    (not at a shared one), p1's diamond dark."""
    ax, ay, bx, by = p0[0] - EPS, p0[1] - EPS * EPS, p1[0] - EPS, p1[1] - EPS * EPS
    # r513 R1: one pixel beyond the image too (a search past its edge lights some there)
    cy, cx = np.mgrid[-1 : WINDOW + 1, -1 : WINDOW + 1] + 0.5
    ok = np.ones(cx.shape, bool)
    for s in (1, -1):
        u0, u1 = (ax - cx) + s * (ay - cy), (bx - cx) + s * (by - cy)
        d = u1 - u0
        if not d.any():
            ok &= np.abs(u0) < 0.5
            continue
        t1, t2 = (-0.5 - u0) / d, (0.5 - u0) / d
        ok &= np.maximum(np.minimum(t1, t2), 0) < np.minimum(np.maximum(t1, t2), 1)
    ok &= np.abs(bx - cx) + np.abs(by - cy) >= 0.5
    return frozenset((int(r) - 1, int(c) - 1) for r, c in zip(*np.nonzero(ok)))


def _slabs_apart_fits(args, expected, got) -> bool:
    """Every pixel the rule lights, and extra ones only where both slabs are met apart (a
    search over all the image or around the segment lights some of those)."""
    return expected < got <= _slabs_apart(*args)


LINE_MISTAKES = [
    LINE_KNOBS,
    *(_large_eps(name, eps) for name, eps in LARGE_EPS.items()),
    Mistake(
        "reversed",
        # r24 D-4: "and the −(ε, ε²) perturbation is not symmetric" was false: both end
        # points move alike; only which end's diamond stays dark depends on the direction
        "you drew the segment from p1 to p0: its direction matters, the rule leaves p1's own "
        "diamond dark (not p0's); both end points move by the same −(ε, ε²), so reversing "
        "the segment changes only which end's diamond stays dark",
        gives=lambda p0, p1: diamond_pixels(p1, p0),
    ),
    *(
        Mistake("end points sorted", _sorted_words(order), gives=_drawn_sorted(key))
        for order, key in SORTED_ENDS.items()
    ),
    Mistake(
        "end points read as (y, x)",
        _transposed_words,
        gives=lambda p0, p1: diamond_pixels((p0[1], p0[0]), (p1[1], p1[0])),
    ),
    Mistake(
        "start pixel dark",
        "you left the pixel p0 lies in dark: the segment starts inside its diamond and exits "
        "it, so it is lit (only p1's own diamond stays dark)",
        gives=_start_dark,
    ),
    Mistake(
        "Bresenham",
        _BRESENHAM,
        gives=bresenham_pixels,
    ),
    # r11 09-F: a textbook Bresenham (end points floored), with p1's pixel dark or lit
    *(
        Mistake("Bresenham", _BRESENHAM, gives=lambda p0, p1, e=e: hand_bresenham(p0, p1, e))
        for e in (False, True)
    ),
    Mistake("Bresenham", _BRESENHAM, gives=classic_bresenham),  # r14 09-6: e2 > −dy, e2 < dx
    Mistake(
        "DDA",
        "you sampled the segment at n = max(|dx|, |dy|) evenly spaced points from p0 and lit "
        "the pixel each lies in (a DDA, lesson 12a §3): that lights the pixels the samples "
        "fall in, wherever in the pixel; the rule lights the pixels whose diamond "
        "|x − (col + ½)| + |y − (row + ½)| < ½ the segment passes through and leaves",
        gives=sampled_dda,
    ),
    # r289 S1: rounding DDAs, from the end points' pixels and from their centres
    *(
        Mistake(
            "DDA",
            "you stepped a DDA from pixel to pixel, rounding x0 + k·dx/n to the nearest whole "
            "pixel at each of n = max(|dx|, |dy|) steps (lesson 12a §3): that lights the pixel "
            "nearest each sample; the rule lights the pixels whose diamond the segment itself "
            "passes through and leaves",
            gives=lambda p0, p1, c=c: rounded_dda(p0, p1, c),
        )
        for c in (False, True)
    ),
    Mistake(
        "search range from the unmoved ends",
        lambda a, e, g: _unmoved_range_words(*a),
        gives=_unmoved_range,
    ),
    Mistake(
        "diamond radius",
        "your diamond is too large: it is the points within ½ of the pixel's centre, measured "
        "as |dx| + |dy| (its corners are the midpoints of the pixel's sides), not within 1",
        gives=lambda p0, p1: diamond_pixels(p0, p1, half=1.0),
    ),
    Mistake(
        "diamond at the corner",
        "your diamonds sit on the pixels' corners: pixel (row, col) owns the diamond around "
        "its centre (col + ½, row + ½)",
        gives=lambda p0, p1: diamond_pixels(p0, p1, centre=0.0),
    ),
    Mistake(  # r11 09-F: the same, searched over the window only (as a loop over range(12))
        "diamond at the corner",
        "your diamonds sit on the pixels' corners (centres at whole numbers): pixel (row, "
        "col) owns the diamond around its centre (col + ½, row + ½)",
        gives=lambda p0, p1: frozenset(
            (r, c) for r, c in diamond_pixels(p0, p1, centre=0.0) if r < WINDOW and c < WINDOW
        ),  # fmt: skip
    ),
    Mistake(  # r14 09-8
        "outside the image",
        lambda a, e, g: (
            f"you lit {', '.join(f'(row {r}, col {c})' for r, c in sorted(g - e))}, outside the "
            f"{WINDOW} × {WINDOW} image: moved by (−ε, −ε²), the segment passes through the "
            "diamond of a pixel in column −1 (or row −1), which reaches to x = 0 (y = 0). "
            f"Return only the pixels inside the image (0 ≤ row, col < {WINDOW})"
        ),
        gives=lambda p0, p1: diamond_pixels(p0, p1, inside=False),
    ),
    Mistake(  # r483 H1: hint 2's slabs clipped one by one, their t intervals not shared
        "slabs apart",
        "you tested the two slabs of the diamond apart: the segment is within ½ of the centre's "
        "u = x + y for some t and within ½ of its v = x − y for some t, but the diamond needs "
        "both at the same t: intersect the two open intervals of t with [0, 1]",
        fits=_slabs_apart_fits,
        only_whole=True,
    ),
    *(
        Mistake("p1's square dark", _p1_square_words, gives=_p1_square_dark(m))
        for m in (False, True)
    ),
    Mistake("search stops short", _short_search_words, fits=_short_search, only_whole=True),
    Mistake(
        "p0's pixel only",
        "you returned only the pixel p0 lies in: the rule lights every pixel whose diamond the "
        "segment passes through and leaves, all along it",
        gives=lambda p0, p1: frozenset({(int(np.floor(p0[1])), int(np.floor(p0[0])))}),
    ),
    Mistake(
        "DDA",
        "you rounded the line at each column (or row) centre, a DDA; the rule lights the "
        "pixels whose diamond |x − (col + ½)| + |y − (row + ½)| < ½ the segment exits",
        gives=dda_pixels,
    ),
    Mistake(  # r513 M2: a zero-length special case was told "you walked the pixel squares"
        "zero length lit",
        "a segment of zero length (p0 = p1) never leaves the diamond p1 lies in, so the rule "
        "lights nothing: it needs no special case (the next segment of a polyline lights that "
        "pixel)",
        gives=lambda p0, p1: (
            frozenset({_pixel_of(p0)}) if tuple(p0) == tuple(p1) else _expected_pixels(p0, p1)
        ),
    ),
    # last: the rule's slips and the walks above light pixels on the squares' path too
    Mistake("pixel squares", _by_squares_words, fits=_by_squares, only_whole=True),
]


def explain_line(args, expected, got) -> str:
    """The first wrong pixel, what the rule says of it."""
    p0, p1 = args
    extra, missing = sorted(got - expected), sorted(expected - got)
    if extra:
        r, c = extra[0]
        return (f"for the segment {p0} → {p1} you lit (row {r}, col {c}), which the rule leaves "
                f"dark ({len(extra)} extra, {len(missing)} missing)")  # fmt: skip
    r, c = missing[0]
    return (f"for the segment {p0} → {p1} the rule lights (row {r}, col {c}), which you left "
            f"dark ({len(missing)} missing)")  # fmt: skip


#: One way to the answer, said by the rule only once two different answers of the student's
#: have failed (r84 09-1: the notebook's box spelled it out before any try; ``hints``).
ALGORITHM = (
    " (one way: in the turned coordinates u = x + y, v = x − y a diamond is an open square, so "
    "each of its two conditions holds on an open interval of t along p(t) = p0 + t·(p1 − p0); "
    "the segment meets the diamond where both intervals and the closed [0, 1] share a point, "
    "and leaves it unless p1 lies inside; move both end points first and compute with "
    "`Fraction`, so that every tie is exact)"
)


def _line_rule(args, expected, got) -> str:
    p0, p1 = args
    return (
        ": a pixel is lit when the segment passes through its diamond |x − (col + ½)| + "
        "|y − (row + ½)| < ½ and leaves it (p1's own diamond stays dark)" + ALGORITHM + "; " + _TIE
    )


def draw_line(ax, case, got):
    """The segment over the pixels and the diamonds around it: the rule's lit pixels beside
    yours, in a key (r9: no key, no diamonds, p0 and p1 alike); before any answer (``got``
    None), the segment alone, so that the figure never shows the answer first."""
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    from .drawing import STATE_COLOURS

    _, (p0, p1), expected = case
    state = np.zeros((WINDOW, WINDOW), int)
    for r, c in expected if got is not None else ():
        state[r, c] = 1
    for r, c in (got or set()) ^ (expected if got is not None else set()):
        if 0 <= r < WINDOW and 0 <= c < WINDOW:
            state[r, c] = 2 if (r, c) in expected else 3
    artists = [ax.imshow(state, cmap=ListedColormap(STATE_COLOURS), vmin=0, vmax=3,
                         extent=(0, WINDOW, WINDOW, 0), interpolation="nearest")]  # fmt: skip
    (x0, x1), (y0, y1) = (sorted((p0[k], p1[k])) for k in (0, 1))
    near = [(j, i) for i in range(max(int(y0) - 1, 0), min(int(y1) + 2, WINDOW))
            for j in range(max(int(x0) - 1, 0), min(int(x1) + 2, WINDOW))]  # fmt: skip
    far = [(j, i) for i in range(WINDOW) for j in range(WINDOW) if (j, i) not in near]
    # r25 D-6: diamonds near the segment only left the rest of the 12 × 12 axes looking as if
    # the grid stopped there: every pixel's diamond, those the segment can meet stronger
    for cells, style in ((far, dict(lw=0.5, alpha=0.55)), (near, dict(lw=0.8))):
        diamonds = [[(j + 0.5, i), (j + 1, i + 0.5), (j + 0.5, i + 1), (j, i + 0.5)]
                    for j, i in cells]  # fmt: skip
        artists.append(ax.add_collection(PolyCollection(diamonds, facecolor="none",
                                                        edgecolor="#E69F00", **style)))  # fmt: skip
    artists += ax.plot([p0[0], p1[0]], [p0[1], p1[1]], "k-", lw=1.5)
    artists += ax.plot(*p0, "o", color="k", ms=6)
    artists += ax.plot(*p1, "o", mfc="white", mec="k", ms=7)
    ax.set_aspect("equal")
    # r18 D-9: the task's trap is (row, col) against (x, y): say which axis is which
    artists.append(ax.set_xlabel("x = col", fontsize="x-small"))
    artists.append(ax.set_ylabel("y = row (pointing down)", fontsize="x-small"))
    handles = [Line2D([], [], marker="o", color="k", ls="", label="p0"),
               Line2D([], [], marker="o", mfc="white", mec="k", ls="", label="p1"),
               Patch(facecolor="none", edgecolor="#E69F00", label="diamonds")]  # fmt: skip
    if got is not None:
        shown = [k for k in (1, 2, 3) if k == 1 or (state == k).any()]
        names = {1: "lit by both", 2: "missing (rule: lit)", 3: "extra (rule: dark)"}
        handles += [Patch(color=STATE_COLOURS[k], label=names[k]) for k in shown]
    # outside the axes, to the right: the key never hides a pixel
    artists.append(ax.legend(handles=handles, fontsize="x-small", loc="upper left",
                             bbox_to_anchor=(1.02, 1)))  # fmt: skip
    return artists


LINE_PIXELS = Exercise(
    "line_pixels", line_cases, as_pixels, lambda g, e, a: g == e, explain_line, _line_rule,
    LINE_MISTAKES, constant=lambda v: (
        # r14 09-5: ``return []`` was told "returns set()", a set the student never wrote
        f"your function returns {short(set(v)) if len(v) else 'no pixels'} for every line, "
        "whatever its end points: a placeholder left in?"),
    answers=(PackageAnswer(rasterize_line, modules=("teachraster.core.line_rules",)),),
    draw=draw_line, partial_names=False, once=((_TIE, _TIE_AGAIN), (ALGORITHM, "")),
    hints=((ALGORITHM, ""),),
    inputs_drawn=True, example=7,  # 45° along diamond edges: ties, drawn over the diamonds
)  # fmt: skip
