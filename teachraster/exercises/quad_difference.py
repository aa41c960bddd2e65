"""Exercise ``quad_derivatives`` (lesson 09): a pixel's derivatives from its 2×2 quad.

A GPU shades pixels in 2×2 quads aligned to even rows and columns, and takes a texture
coordinate's screen-space derivatives as differences between the quad's lanes. Coarse
derivatives (llvmpipe's, and ``render(..., derivatives=True)``'s) are one pair per quad:
ddx = f(upper right) − f(upper left), ddy = f(lower left) − f(upper left), y down. Lanes the
triangle does not cover are *helper* pixels: the value there is the triangle's perspective-
correct interpolation extrapolated (barycentrics outside [0, 1], never clamped), since the
difference across the edge is what the derivative needs.

Expected answers: the renderer's own quad lanes
(:func:`teachraster.pipeline.texturing.quad_derivatives.lane_values` of
:func:`~teachraster.pipeline.texturing.quad_derivatives.attribute_planes`).
"""

from __future__ import annotations

import textwrap

import numpy as np

from ..core.interpolation import perspective_weights
from ..pipeline.texturing.quad_derivatives import attribute_planes, lane_values
from .answers import as_numbers
from .cases import SEED, fixed_and_drawn
from .exercise import Exercise, PackageAnswer, variant_mistakes
from .scalars import num, vec
from .tolerance import all_close

#: Floor-like triangles: the far edge at w = 8 against 1 near, as on textured_floor.
FLOOR = (
    np.array([[2.0, 30.0], [30.0, 30.0], [14.0, 4.0]]),
    np.array([1.0, 1.0, 8.0]),
    np.array([0.0, 1.0, 0.5]),
)


def lanes(xy, w, f, row0: int, col0: int) -> np.ndarray:
    """The renderer's values at the quad's four lanes (upper left, upper right, lower left,
    lower right) whose upper-left pixel is (row0, col0); extrapolated, unclamped."""
    planes = attribute_planes(np.asarray(xy, float)[None], np.asarray(w, float)[None],
                              np.asarray(f, float)[None, :, None], True)  # fmt: skip
    vals, _ = lane_values(planes, np.array([0]), np.array([row0]), np.array([col0]))
    return np.array([v[0, 0] for v in vals])


def expected_pair(xy, w, f, row: int, col: int) -> np.ndarray:
    q = lanes(xy, w, f, row - row % 2, col - col % 2)
    return np.array([q[1] - q[0], q[2] - q[0]])


def _quad_cases(rng, word) -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (xy, w, f, row, col), (ddx, ddy)): the floor's pixels at even and odd rows and
    columns, next to its edges (helper lanes), and seeded random triangles."""
    xy, w, f = FLOOR
    pixels = [(27, 3, "next to the left edge: helpers outside"),
              (28, 14, "inside, upper-left lane"), (29, 15, "inside, lower-right lane"),
              (5, 14, "at the far tip: helpers beyond the edges"),
              (20, 25, "next to the right edge"), (29, 29, "the near right corner")]  # fmt: skip
    out = [(f"floor, pixel ({r}, {c}): {why}", (xy, w, f, r, c)) for r, c, why in pixels]
    for k in range(10):
        txy = np.round(rng.uniform(0, 24, (3, 2)) * 256) / 256
        tw = np.exp(rng.uniform(0, np.log(10), 3))
        tf = np.round(rng.uniform(-2, 2, 3), 2)
        r, c = (int(v) for v in txy.mean(axis=0))
        out.append((f"{word} {k + 1}, pixel ({r}, {c})", (txy, tw, tf, r, c)))
    return [(label, args, expected_pair(*args)) for label, args in out]


quad_cases = fixed_and_drawn(_quad_cases, SEED + 70)  # r49: some drawn per check


def as_pair(value) -> np.ndarray:
    return as_numbers(value, (2,), "a pair (ddx, ddy)")


def same_pair(got: np.ndarray, expected: np.ndarray, args=None) -> bool:
    """Within 3e-5 of the lanes' size (about 250 float32 steps: a helper lane extrapolated
    past an edge magnifies float32 rounding): a difference of two lanes computed in float32 is
    off by their rounding, which scales with the lanes, not with the
    difference (a drawn case with lanes near 27 failed float32 by 2e-5 against 1e-6 of ddx)."""
    if not np.isfinite(got).all():
        return False
    size = 1.0
    if args is not None:
        xy, w, f, row, col = args
        size = max(1.0, float(np.max(np.abs(lanes(xy, w, f, row - row % 2, col - col % 2)))))
    return all_close(np.asarray(got) / size, np.asarray(expected) / size, 3e-5)


def value_at(xy, w, f, x, y, clamp=False, affine=False, times_w=False) -> float:
    """f at point (x, y): perspective-correct (or affine, or weighted λ·w for ``times_w``),
    extrapolated unless ``clamp``."""
    (x1, y1), (x2, y2), (x3, y3) = xy
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    lam = np.array([(x2 - x) * (y3 - y) - (y2 - y) * (x3 - x),
                    (x3 - x) * (y1 - y) - (y3 - y) * (x1 - x),
                    (x1 - x) * (y2 - y) - (y1 - y) * (x2 - x)]) / area  # fmt: skip
    if affine:
        return float(lam @ f)
    if times_w:  # r286: λ·w normalised, lesson 04's mistake (the divide by w turned around)
        mu = lam * w
        return float(mu @ f / mu.sum())
    mu = perspective_weights(lam[None], w, extrapolate=not clamp)[0]
    return float(mu @ f)


def _variants(xy, w, f, row, col) -> dict[str, np.ndarray]:
    r0, c0 = row - row % 2, col - col % 2

    def pair(r, c, centre=0.5, **kw):
        a = value_at(xy, w, f, c + centre, r + centre, **kw)
        return np.array([value_at(xy, w, f, c + 1 + centre, r + centre, **kw) - a,
                         value_at(xy, w, f, c + centre, r + 1 + centre, **kw) - a])  # fmt: skip

    right = pair(r0, c0)
    fine_x = value_at(xy, w, f, c0 + 1.5, row + 0.5) - value_at(xy, w, f, c0 + 0.5, row + 0.5)
    fine_y = value_at(xy, w, f, col + 0.5, r0 + 1.5) - value_at(xy, w, f, col + 0.5, r0 + 0.5)
    at = (col + 0.5, row + 0.5)
    eps = 1e-5  # a centred difference this small is the exact derivative to ~1e-10
    exact = [value_at(xy, w, f, at[0] + eps, at[1]) - value_at(xy, w, f, at[0] - eps, at[1]),
             value_at(xy, w, f, at[0], at[1] + eps) - value_at(xy, w, f, at[0], at[1] - eps)]  # fmt: skip
    lr = value_at(xy, w, f, c0 + 1.5, r0 + 1.5)
    own = value_at(xy, w, f, col + 0.5, row + 0.5)
    # r301: each pixel's quad partner (the other lane of its row, of its column) minus it
    partner = np.array([value_at(xy, w, f, (col ^ 1) + 0.5, row + 0.5) - own,
                        value_at(xy, w, f, col + 0.5, (row ^ 1) + 0.5) - own])  # fmt: skip
    return {
        "unaligned": pair(row, col),
        # r375 F9: one axis aligned to the quads, the other not, was told only the rule
        "column unaligned": pair(r0, col),
        "row unaligned": pair(row, c0),
        # r286 M3: the slips a reader found told only the rule
        "lower right": np.array(
            [
                lr - value_at(xy, w, f, c0 + 0.5, r0 + 1.5),
                lr - value_at(xy, w, f, c0 + 1.5, r0 + 0.5),
            ]
        ),  # fmt: skip
        "exact": np.array(exact) / (2 * eps),
        "odd quads": pair(row - (row + 1) % 2, col - (col + 1) % 2),
        "λ·w": pair(r0, c0, times_w=True),
        "clamped and y up": pair(r0, c0, clamp=True) * [1, -1],
        # r64 07 D3: the quad's number taken for its upper-left pixel; lanes at pixel corners
        "quad number": pair(row // 2, col // 2),
        "corners": pair(r0, c0, centre=0.0),
        "clamped": pair(r0, c0, clamp=True),
        "affine": pair(r0, c0, affine=True),
        "fine": np.array([fine_x, fine_y]),
        "y up": right * [1, -1],
        "swapped": right[::-1],
        "negated": -right,
        "row col swapped": pair(col - col % 2, row - row % 2),
        # the lanes' points as (y, x): each difference then runs along the other axis too
        "points (y, x)": pair(c0, r0)[::-1],
        # r301: one difference along the quad's other row or column was told only the rule
        "lower row": np.array([lr - value_at(xy, w, f, c0 + 0.5, r0 + 1.5), right[1]]),
        "right column": np.array([right[0], lr - value_at(xy, w, f, c0 + 1.5, r0 + 0.5)]),
        "partner minus own": partner,
        # r390 N3: (f(c0 + 2) − f(c0))/2, across the quad into the next, was told the method
        "two steps halved": np.array(
            [
                value_at(xy, w, f, c0 + 2.5, r0 + 0.5) - value_at(xy, w, f, c0 + 0.5, r0 + 0.5),
                value_at(xy, w, f, c0 + 0.5, r0 + 2.5) - value_at(xy, w, f, c0 + 0.5, r0 + 0.5),
            ]
        )
        / 2,  # fmt: skip
        "centred": np.array(
            [
                value_at(xy, w, f, col + 1.5, row + 0.5) - value_at(xy, w, f, col - 0.5, row + 0.5),
                value_at(xy, w, f, col + 0.5, row + 1.5) - value_at(xy, w, f, col + 0.5, row - 0.5),
            ]
        )
        / 2,  # fmt: skip
    }


MISTAKES = {
    "unaligned": "you took the quad whose upper-left pixel is this pixel: quads are aligned "
    "to even rows and columns, so pixel (row, col) belongs to the quad starting at "
    "(row − row mod 2, col − col mod 2)",
    "column unaligned": "you aligned the quad's row but not its column: quads start at even "
    "columns too, so pixel (row, col) belongs to the quad starting at (row − row mod 2, "
    "col − col mod 2)",
    "row unaligned": "you aligned the quad's column but not its row: quads start at even rows "
    "too, so pixel (row, col) belongs to the quad starting at (row − row mod 2, col − col mod 2)",
    "lower right": "you differenced against the quad's lower-right lane (f(lower right) "
    "minus its neighbours); coarse derivatives take the upper-left lane as the reference: ddx "
    "is its right neighbour minus it, ddy its lower neighbour minus it",
    "exact": "that is the exact derivative at the pixel's centre (a limit, or a tiny step): "
    "the GPU has only the values at its quad's four lanes, so ddx and ddy are differences of "
    "two lanes one whole pixel apart",
    "odd quads": "your quads start on odd rows and columns: quads are aligned to even rows "
    "and columns, so pixel (row, col) belongs to the quad starting at (row − row mod 2, "
    "col − col mod 2)",
    "λ·w": "you weighted the barycentrics by w (λ·w, normalised): perspective-correct "
    "interpolation divides by w, weights λ_i/w_i normalised (lesson 04)",
    "clamped and y up": "two slips: you clamped the interpolation at a helper pixel (a helper "
    "extrapolates the triangle's values, weights outside [0, 1] and all; "
    "`perspective_weights` clamps unless extrapolate=True); and your ddy has the wrong sign "
    "(y grows downwards: the lower lane minus the upper one)",
    "quad number": "you took pixel (row // 2, col // 2) for the quad's upper-left pixel: that "
    "is the quad's number; its upper-left pixel is at twice that, (row − row mod 2, "
    "col − col mod 2)",
    "corners": "you evaluated f at the pixels' corners (col, row); a lane's value is the one at "
    "its pixel's centre (col + ½, row + ½), where the pixel is shaded",
    "clamped": "you clamped the interpolation at a helper pixel (outside the triangle): a "
    "helper extrapolates the triangle's values, weights outside [0, 1] and all "
    "(`perspective_weights` clamps unless extrapolate=True)",
    "affine": "you interpolated affinely at the lanes: the values are perspective-correct "
    "(the divide by w), and so are their differences",
    "fine": "these are fine derivatives (each pixel's own row and column of the quad); "
    "coarse ones use the quad's upper row and left column for all four pixels",
    "y up": "your ddy has the wrong sign: y grows downwards, so ddy is the lower lane minus "
    "the upper one",
    "swapped": "you returned (ddy, ddx): ddx is the step right, along the row",
    "negated": "both your differences have the wrong sign: ddx is the right lane minus the "
    "left one, ddy the lower minus the upper",
    "row col swapped": "you took the pixel as (col, row): pixel (row, col) lies at x = col + ½, "
    "y = row + ½",
    "points (y, x)": "you passed each lane's centre as (row + ½, col + ½); a point is "
    "(x, y) = (col + ½, row + ½), x along the row",
    "centred": "you took a centred difference around the pixel, (f(x + 1) − f(x − 1))/2: the "
    "GPU differences the lanes of the pixel's 2×2 quad, right minus left, lower minus upper",
    "lower row": "your ddx is taken along the quad's lower row (lower right − lower left); "
    "coarse derivatives take ddx along its upper row, f(upper right) − f(upper left), for all "
    "four pixels",
    "right column": "your ddy is taken along the quad's right column (lower right − upper "
    "right); coarse derivatives take ddy along its left column, f(lower left) − f(upper left), "
    "for all four pixels",
    "partner minus own": lambda a, e, g: _partner_words(a[3], a[4]),
    "two steps halved": "you differenced two pixels two steps apart, (f(x + 2) − f(x))/2 and "
    "(f(y + 2) − f(y))/2, reaching into the next quad: a GPU has only its own quad's four "
    "lanes, so ddx and ddy are differences of two lanes one step apart (upper right − upper "
    "left, lower left − upper left), not halved",
}


def _partner_words(row: int, col: int) -> str:
    """Each pixel's quad partner minus the pixel itself, said for this pixel's row and column
    (r301: told only the rule): the sign turns on odd columns and rows."""
    flips = [f"on odd column {col} the partner lies to the left, so your ddx is left minus "
             "right" if col % 2 else "", f"on odd row {row} the partner lies above, so your "
             "ddy is upper minus lower" if row % 2 else ""]  # fmt: skip
    said = "; ".join(x for x in flips if x) or "here the pixel is the upper-left lane itself"
    return (
        f"you took each pixel's partner in the quad minus the pixel itself: {said}. A "
        "difference runs right minus left and lower minus upper, and coarse derivatives "
        "take the quad's upper row and left column for all four pixels"
    )


def explain_quad(args, expected, got) -> str:
    """The two pairs: which quad, which lanes and their values are what 7.4 asks to work out
    (r64 07 D3: every failure printed them and the formula); the rule says them once two
    different answers have failed."""
    return f"(ddx, ddy) = {vec(expected, got)}; yours is {vec(got, expected)}"


#: A named mistake's fix, as a question until two different answers have failed (r73 07-1).
NAMED_HINTS = (
    # r390 F8: the sign's fix came with the first, "a hint only", failure
    (
        "your ddy has the wrong sign: y grows downwards, so ddy is the lower lane minus the upper one",
        "your ddy has the wrong sign: which way does y grow on screen, and so which lane comes "
        "first in ddy?",
    ),
    (
        ", so pixel (row, col) belongs to the quad starting at (row − row mod 2, col − col mod 2)",
        ": which quad holds pixel (row, col), and which is its upper-left pixel?",
    ),
    (
        "; its upper-left pixel is at twice that, (row − row mod 2, col − col mod 2)",
        ", not a pixel: which pixel is that quad's upper-left one?",
    ),
)


#: 7.4's rule for an answer no mistake explains, and the question asked before it.
RULE = (
    ": pixel (row, col) belongs to the quad whose upper-left pixel is (row − row mod 2, "
    "col − col mod 2); ddx = f(upper right) − f(upper left), ddy = f(lower left) − "
    "f(upper left), each f at its lane's pixel centre, perspective-correct (and extrapolated "
    "at helper lanes)"
)
HINT = (
    ": which quad holds this pixel, which two of its lanes lie one step apart along x (and "
    "along y), and what must a lane outside the triangle hold for their difference to be the "
    "derivative inside? Work this case through by hand"
)


def _rule(args, expected, got) -> str:
    return RULE


def draw_quad(ax, case, got):
    """Close up on the pixel: the triangle's edges, the pixels around (covered grey, the
    others white), the pixel; the expected (ddx, ddy) and yours. Before any answer (``got``
    None) no pair is written. The pixel's quad with the value of f at each lane (helpers
    hatched) is the method 7.4 asks for: drawn once two different answers have failed, as the
    words say it (r64 07 D3)."""
    from matplotlib.patches import Patch, Rectangle

    from . import tries

    _, (xy, w, f, row, col), expected = case
    r0, c0 = row - row % 2, col - col % 2
    # the method once earned: the full words given, or this answer right (a passing check)
    passed = got is not None and same_pair(np.asarray(got), expected, case[1])
    method = got is not None and (tries.hints_spent("quad_derivatives") or passed)
    ring = np.vstack([xy, xy[:1]])
    artists = ax.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1.5)
    for y in range(r0 - 2, r0 + 4):
        for x in range(c0 - 2, c0 + 4):
            covered = inside(xy, x + 0.5, y + 0.5)
            artists.append(ax.add_patch(Rectangle((x, y), 1, 1, facecolor="#d2d2d2" if covered
                                                  else "white", edgecolor="#bbbbbb", lw=0.5)))  # fmt: skip
    if method:
        q = lanes(xy, w, f, r0, c0)
        for k, (dr, dc) in enumerate(((0, 0), (0, 1), (1, 0), (1, 1))):
            x, y = c0 + dc, r0 + dr
            covered = inside(xy, x + 0.5, y + 0.5)
            artists.append(ax.add_patch(Rectangle((x, y), 1, 1, facecolor="#c8c8c8" if covered
                                                  else "white", edgecolor="#2b7bba", lw=1.5,
                                                  hatch=None if covered else "//")))  # fmt: skip
            # staggered up and down, boxed: neighbours' labels ran together (r49)
            artists.append(ax.text(x + 0.5, y + (0.3 if dc == 0 else 0.7), f"{q[k]:.2g}",
                                   ha="center", va="center", fontsize="x-small", color="black",
                                   bbox={"facecolor": "white", "edgecolor": "none", "pad": 1}))  # fmt: skip
    artists.append(ax.add_patch(Rectangle((col, row), 1, 1, fill=False, edgecolor="#ff9f1c",
                                          lw=3)))  # fmt: skip
    if passed:  # r375 F2: 7.4's pixels, each outlined, and their quads
        for r, c in QUESTION_PIXELS:
            artists.append(ax.add_patch(Rectangle((c, r), 1, 1, fill=False, lw=1.5,
                                                  edgecolor="#ff9f1c", linestyle="--")))  # fmt: skip
            if (r - r % 2, c - c % 2) != (r0, c0):
                artists.append(ax.add_patch(Rectangle((c - c % 2, r - r % 2), 2, 2, fill=False,
                                                      edgecolor="#2b7bba", lw=1.5,
                                                      linestyle="--")))  # fmt: skip
    # a passing figure reaches 7.4's pixels' quads too, where they are near
    near = [(r - r % 2, c - c % 2) for r, c in QUESTION_PIXELS if passed
            and abs(r - r0) < 6 and abs(c - c0) < 6]  # fmt: skip
    ax.set_xlim(c0 - 1.5, max([c0 + 1.5] + [c for _, c in near]) + 2.2)
    room = 3.5 if passed else 0.0  # r390 N6: white rows below for the helper quad's inset
    ax.set_ylim(max([r0 + 1.5] + [r for r, _ in near]) + 2.2 + room, r0 - 1.5)
    if room:  # no row numbers beside the inset: it draws another quad
        ax.set_yticks([r for r in ax.get_yticks() if r <= r0 + 3])
    ax.set_aspect("equal")
    if got is not None:
        # beside the close-up, under the legend (r375: it covered the quad below the pixel's)
        artists.append(ax.text(1.04, 0.02, f"(ddx, ddy) = {vec(expected, got)}\nyours: "
                               f"{vec(got, expected)}", transform=ax.transAxes,
                               fontsize="x-small", va="bottom", ha="left",
                               bbox={"facecolor": "white", "edgecolor": "none"}))  # fmt: skip
    if passed:
        words = f"{quad_questions()}. {helper_question()}"
        ax.set_xlabel(textwrap.fill(words, 58), fontsize="x-small")
        artists += draw_helper_quad(ax)
    handles = [Patch(facecolor="#d2d2d2", edgecolor="#bbbbbb", label="covered"),
               Patch(facecolor="white", edgecolor="#ff9f1c", lw=3, label="the pixel")]  # fmt: skip
    if method:
        handles[1:1] = [Patch(facecolor="#c8c8c8", edgecolor="#2b7bba", label="its quad"),
                        Patch(facecolor="white", edgecolor="#2b7bba", hatch="//",
                              label="helper")]  # fmt: skip
    artists.append(ax.legend(handles=handles, fontsize="x-small", loc="upper left",
                             bbox_to_anchor=(1.02, 1)))  # fmt: skip
    return artists


#: 7.4's "answer first" pixels (r375 F2: a passing check never showed them); all covered
#: (r390 N1: (30, 16)'s quad lay wholly below the floor's edge, a quad a GPU never shades)
QUESTION_PIXELS = ((28, 14), (29, 15), (29, 16))


def quad_questions(pixels=QUESTION_PIXELS) -> str:
    """Which of ``pixels`` share a quad, and so one (ddx, ddy): 7.4's first question."""
    quads: dict[tuple[int, int], list] = {}
    for r, c in pixels:
        quads.setdefault((r - r % 2, c - c % 2), []).append(f"({r}, {c})")
    said = "; ".join(f"{' and '.join(p)} in the quad at ({q[0]}, {q[1]})"
                     for q, p in quads.items())  # fmt: skip
    return f"7.4 (dashed): {said}, one (ddx, ddy) each"


def _nearest_point(xy, x, y) -> tuple[float, float]:
    """The triangle's point nearest (x, y): (x, y) itself inside, else the nearest point of
    its edges."""
    if inside(xy, x, y):
        return x, y
    best, p = None, np.array([x, y], dtype=float)
    for k in range(3):
        a, b = np.asarray(xy[k], float), np.asarray(xy[(k + 1) % 3], float)
        s = float(np.clip((p - a) @ (b - a) / ((b - a) @ (b - a)), 0.0, 1.0))
        q = a + s * (b - a)
        if best is None or np.hypot(*(q - p)) < np.hypot(*(best - p)):
            best = q
    return float(best[0]), float(best[1])


def helper_quad(xy=FLOOR[0], w=FLOOR[1], f=FLOOR[2]):
    """The first quad (by rows, then columns) whose left column is covered and right column
    not: (row0, col0, f upper left, f upper right extrapolated, f at the triangle's point
    nearest the upper right lane), or None."""
    size = int(np.ceil(np.max(xy))) + 2
    for r0 in range(0, size, 2):
        for c0 in range(0, size, 2):
            covered = [inside(xy, c0 + dc + 0.5, r0 + dr + 0.5) for dr in (0, 1) for dc in (0, 1)]
            if covered == [True, False, True, False]:
                left = value_at(xy, w, f, c0 + 0.5, r0 + 0.5)
                right = value_at(xy, w, f, c0 + 1.5, r0 + 0.5)
                near = value_at(xy, w, f, *_nearest_point(xy, c0 + 1.5, r0 + 0.5))
                return r0, c0, left, right, near
    return None


def helper_question(xy=FLOOR[0], w=FLOOR[1], f=FLOOR[2]) -> str:
    """7.4's helper question answered on the floor, at :func:`helper_quad` (drawn in the pass
    figure's inset, r390 N6): ddx with the helper's value taken at the triangle's nearest
    point, against the extrapolated one, and why the first is wrong."""
    found = helper_quad(xy, w, f)
    if found is None:
        return ""
    r0, c0, left, right, near = found
    less = abs(near - left) < abs(right - left)
    why = (", so ddx measures less than one pixel's step of f and λ comes out too small"
           if less else "")  # fmt: skip
    return (
        f"Helpers at the nearest point (inset, the quad at ({r0}, {c0}), right column "
        f"outside): ddx {num(near - left)}, not {num(right - left)}: the nearest point "
        f"lies on the edge, short of the helper's centre{why}"
    )


def draw_helper_quad(ax, xy=FLOOR[0], w=FLOOR[1], f=FLOOR[2]) -> list:
    """An inset beside ``ax``: :func:`helper_quad`'s quad, the triangle's edge through it, each
    lane's extrapolated value and, at the helper, the nearest point's (r390 N6)."""
    from matplotlib.patches import Rectangle

    found = helper_quad(xy, w, f)
    if found is None:
        return []
    r0, c0, *_ = found
    inset = ax.inset_axes([0.02, 0.02, 0.5, 0.38])  # in the white rows below the view
    ring = np.vstack([xy, xy[:1]])
    inset.plot(ring[:, 0], ring[:, 1], color="black", linewidth=1.2)
    for dr in (0, 1):
        for dc in (0, 1):
            x, y = c0 + dc, r0 + dr
            covered = inside(xy, x + 0.5, y + 0.5)
            inset.add_patch(Rectangle((x, y), 1, 1, facecolor="#c8c8c8" if covered else "white",
                                      edgecolor="#2b7bba", lw=1.2,
                                      hatch=None if covered else "//"))  # fmt: skip
            inset.text(x + 0.5, y + 0.5, f"{value_at(xy, w, f, x + 0.5, y + 0.5):.3f}", ha="center",
                       va="center", fontsize="xx-small",
                       bbox={"facecolor": "white", "edgecolor": "none", "pad": 0.5})  # fmt: skip
    nx, ny = _nearest_point(xy, c0 + 1.5, r0 + 0.5)
    inset.plot([nx], [ny], "x", color="#d62728", markersize=5)
    inset.set_title(f"helper quad ({r0}, {c0}); × nearest: {value_at(xy, w, f, nx, ny):.3f}",
                    fontsize="xx-small", color="#d62728", loc="left")  # fmt: skip
    inset.set_xlim(c0 - 0.2, c0 + 2.2)
    inset.set_ylim(r0 + 2.2, r0 - 0.2)
    inset.set_aspect("equal")
    inset.set_xticks([])
    inset.set_yticks([])
    return [inset]


def inside(xy, x, y) -> bool:
    """Is point (x, y) inside triangle ``xy`` or on its edges (either winding)?"""
    e = [(xy[(k + 1) % 3, 0] - xy[k, 0]) * (y - xy[k, 1])
         - (xy[(k + 1) % 3, 1] - xy[k, 1]) * (x - xy[k, 0]) for k in range(3)]  # fmt: skip
    return all(v >= 0 for v in e) or all(v <= 0 for v in e)


QUAD_DERIVATIVES = Exercise(
    "quad_derivatives", quad_cases, as_pair, same_pair, explain_quad, _rule,
    variant_mistakes(_variants, MISTAKES), answers=(PackageAnswer(lane_values),),
    draw=draw_quad, hints=((RULE, HINT), *NAMED_HINTS), inputs_drawn=True,
    example=2,  # r375 F2: pixel (29, 15), 7.4's question (pixel (27, 3) was drawn)
    once=((RULE, ": as said for the first failing case"),),
)  # fmt: skip
