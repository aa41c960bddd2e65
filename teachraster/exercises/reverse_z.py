"""Exercise ``reverse_z_gap`` (lesson 05b, §4): what a float32 reverse-Z buffer resolves.

Lesson 05b's central result: reverse-Z stores d = (n/z − n/f) / (1 − n/f) (1 at the near
plane, 0 at the far plane), and in a **float32** buffer the far depths land near 0, where a
float's steps are tiny, so the resolution grows about like z instead of z² (Lapidous and
Jiao 1999; Reed, *Depth Precision Visualized*). The student works out the smallest gap Δz at
view distance z that such a buffer resolves: §2's "one step over the slope", with the step a
float32's at the value stored, which nothing prints as a formula (the step is fixed within a
binade [2^e, 2^(e+1)), 2^(e−23), not 2^-23 of d).

Expected answers: :func:`teachraster.depth_resolution` (``float32``, ``mapping="reversed"``).
An answer is judged by the criterion, not closeness to that number: it passes when it is one
float32 step at the stored depth over |dd/dz| by either neighbour of the stored float (they
differ where d is a power of two: the float below is half as far as the float above), with
float32's rounding below and at most :data:`SLACK` above (a rounded-up gap is still resolved).
"""

from __future__ import annotations

import copy
from functools import cache

import numpy as np

from ..pipeline.visibility.depth import depth_resolution, reversed_depth, window_depth
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .near_plane import HALF_STEP, as_lone_number
from .package_answers import CHECKER_WORDS
from .scalars import num

#: (z, near, far) of the fixed cases: lesson 05b's planes (near 0.1, far 1000) from z = 1 to
#: z = 999 (d from 0.1 down to 1e-7), z close to the near plane (window depth below 1/2, so
#: float32's step there is not 1's), near/far = 1/10 (the far plane's factor 1 − n/f moves Δz
#: by 10 %), d exactly 1/4, a power of two, and d = 2.0e-8 (z = 5e5, far 1e6), below float32's step
#: at 1: d computed as 1 − z_win in float32 is 0 or 2^-24 there, never in d's binade (r340
#: M4: at z = 999 it landed on 2^-24, whose step below is d's own, and passed).
SETTINGS = (
    (300.0, 0.1, 1000.0), (1.0, 0.1, 1000.0), (10.0, 0.1, 1000.0), (500.0, 0.1, 1000.0),
    (999.0, 0.1, 1000.0), (0.15, 0.1, 1000.0), (2.0, 1.0, 10.0), (5.0, 1.0, 10.0),
    (1.6, 1.0, 2.0), (3000.0, 0.5, 1e5), (40.0, 0.01, 50.0), (5e5, 0.02, 1e6),
)  # fmt: skip

#: How much coarser than the finest reading an answer may be (a gap rounded up to a few
#: digits is still one the buffer resolves).
SLACK = 0.01
#: float32's relative rounding, below the finest reading (a student computing in float32).
ROUNDING = 1e-6


def reversed_depth_slope(z: float, near: float, far: float) -> float:
    """|dd/dz| of the reversed depth (window depth's slope: d = 1 − z_win)."""
    return near / ((1.0 - near / far) * z * z)


def _nearer_step(d: float, dtype=np.float32) -> float:
    """The gap from ``d`` (rounded to ``dtype``) to its nearer neighbour: below it at a power
    of two (the package's step, :func:`depth_resolution`)."""
    x = dtype(d)
    above = abs(float(np.spacing(x)))
    below = abs(float(x) - float(np.nextafter(x, dtype(-np.inf))))
    return min(above, below)


def readings(z: float, near: float, far: float) -> list[float]:
    """Δz by each reading of "one float32 step at the stored depth": the gap to the float
    above the stored d, to the float below it, and the step of d's own binade."""
    d = float(reversed_depth(z, near, far))
    x = np.float32(d)
    steps = [
        abs(float(np.spacing(x))),
        abs(float(x) - float(np.nextafter(x, np.float32(-np.inf)))),
        2.0 ** (np.floor(np.log2(d)) - 23),
    ]
    return [s / reversed_depth_slope(z, near, far) for s in steps]


def bounds(z: float, near: float, far: float) -> tuple[float, float]:
    """(lowest, highest) Δz that passes."""
    r = readings(z, near, far)
    return min(r) * (1 - ROUNDING), max(r) * (1 + SLACK)


@cache
def _bounds(z, near, far) -> tuple[float, float]:
    return bounds(z, near, far)


def expected_gap(z: float, near: float, far: float) -> float:
    """The package's Δz of a float32 reverse-Z buffer at z."""
    return float(depth_resolution([z], near, far, "float32", mapping="reversed")[0])


def gap_cases() -> list[tuple[str, tuple, float]]:
    """The fixed cases (built once, copied) and :data:`DRAWN` drawn for this check, so a
    table of the fixed cases' answers fails."""
    out, rng = copy.deepcopy(_gap_cases()), drawn_rng()
    for k in range(DRAWN):
        z, near, far = _drawn_setting(rng)
        label = (f"drawn for this check {k + 1}: z = {num(z)}, near = {num(near)}, "
                 f"far = {num(far)}")  # fmt: skip
        out.append((label, (z, near, far), expected_gap(z, near, far)))
    return out


def _drawn_setting(rng) -> tuple[float, float, float]:
    """(z, near, far), three significant digits: far from 10 to 10⁵, near a thousandth to a
    millionth of it (or a tenth), z between twice the near plane and 0.95 of the far."""
    far = float(f"{10 ** rng.uniform(1, 5):.3g}")
    near = float(f"{far * 10 ** rng.choice([rng.uniform(-6, -3), -1.0]):.3g}")
    z = float(f"{near * 10 ** rng.uniform(np.log10(2), np.log10(0.95 * far / near)):.3g}")
    return z, near, far


@cache
def _gap_cases() -> list[tuple[str, tuple, float]]:
    return [(f"z = {num(z)}, near = {num(near)}, far = {num(far)}", (z, near, far),
             expected_gap(z, near, far)) for z, near, far in SETTINGS]  # fmt: skip


def same_gap(got, expected, args=None) -> bool:
    """One float32 step at the stored depth over the slope, by any reading (:func:`bounds`);
    without the case's ``args``, within 1e-6 of ``expected``."""
    if args is None:
        return bool(abs(got - expected) <= 1e-6 * abs(expected))
    if not np.isfinite(got):
        return False
    lo, hi = _bounds(*(float(a) for a in args))
    return lo <= got <= hi


def one_minus_window(z, near, far, all_float32: bool = True) -> float:
    """d as 1 − z_win in float32: z_win rounded to float32 (computed in float32 as students
    write it, f/(f − n) · (1 − n/z), or in float64 and then rounded), then subtracted from 1
    (exact there), so d is a whole multiple of 2^-24 wherever z_win ≥ 1/2."""
    if all_float32:
        z, near, far = np.float32(z), np.float32(near), np.float32(far)
        win = far / (far - near) * (np.float32(1) - near / z)
    else:
        win = np.float32(window_depth(z, near, far))
    return float(np.float32(1) - np.float32(win))


def gap_variants(z, near, far) -> dict[str, float]:
    """The Δz typical slips give (each one change), 5.2's and, at the coarsest depth, 5.2b's
    (:mod:`.reverse_z_worst`: r404 F3, the student's own 5.2 slip carried over)."""
    d = float(reversed_depth(z, near, far))
    slope = reversed_depth_slope(z, near, far)
    step = _nearer_step(d)
    win = float(window_depth(z, near, far))
    # r340 M4: the step above d computed as 1 − z_win in float32 (0 → float32's least step)
    rounded = {k: float(np.spacing(np.float32(one_minus_window(z, near, far, k)))) / slope
               for k in (True, False)}  # fmt: skip
    return {
        "1 - z_win in float32": rounded[True],
        "1 - z_win in float32, z_win in float64": rounded[False],
        "window depth": _nearer_step(win) / slope,
        "step above 1": 2.0**-23 / slope,
        "float64": _nearer_step(d, np.float64) / slope,
        # r311 H-3/H-4: the format's precision (float16), and the planes swapped in d's
        # formula (which gives window depth, with a negative slope)
        "float16": _nearer_step(d, np.float16) / slope,
        "near and far swapped": -_nearer_step(win) / slope,
        "relative step": d * 2.0**-23 / slope,
        "relative step, half": d * 2.0**-24 / slope,
        "half": step / (2 * slope),
        "gl ndc": _nearer_step(2 * d - 1) / 2 / slope,
        # r381 F4: np.spacing of the signed NDC depth (negative below d = 1/2), over its
        # slope 2|dd/dz| or over d's
        "gl ndc, signed": float(np.spacing(np.float32(2 * d - 1))) / 2 / slope,
        "gl ndc, signed, d's slope": float(np.spacing(np.float32(2 * d - 1))) / slope,
        # r381 F4: float32's step at the view depth z, not at the stored d
        "spacing of z": float(np.spacing(np.float32(z))),
        "infinite far": _nearer_step(near / z) * z * z / near,
        "infinite far, slope": step * z * z / near,
        # r325: d = n/z stored, the finite far plane's slope kept
        "infinite far, depth": _nearer_step(near / z) / slope,
        "step in depth": step,
        "times slope": step * slope,
        "z not squared": step * z * (1 - near / far) / near,
        # r374 F5: the slope's 1 − n/f on the wrong side of the fraction, or taken twice
        "1 - n/f twice": step * (1 - near / far) / slope,
        "1 - n/f inverted": step / slope / (1 - near / far) ** 2,
        # r425 F4: f where the slope has n (step (1 − n/f) z²/f)
        "far for near in the slope": step * near / far / slope,
        # r442 F3: the step measured from the exact d to its float32 neighbour (above, or
        # below), not between two stored values; the slope as a secant over one unit of z;
        # the slope as d/z (true of d = n/z alone)
        "from the exact d": (float(np.nextafter(np.float32(d), np.float32(np.inf))) - d) / slope,
        "from the exact d, below": (d - float(np.nextafter(np.float32(d), np.float32(0)))) / slope,
        "secant over one unit": _nearer_step(d) / (d - float(reversed_depth(z + 1.0, near, far))),
        "slope d/z": _nearer_step(d) * z / d,
        # r442: the binade above d's (ceil for floor): twice the step but at a power of two
        "ceil for floor": 2.0 ** (np.ceil(np.log2(d)) - 23) / slope,
    }


_RELATIVE = ("you took a fixed share of d as float32's step (its relative precision, "
             "2^-23 or 2^-24 of d): within a binade [2^e, 2^(e+1)) every step is the same, "
             "2^(e−23), which is 2^-23 · d only where d is a power of two")  # fmt: skip
_INFINITE = (
    "you dropped the far plane: d = n/z and |dd/dz| = n/z² hold for f = ∞ only; "
    "with this far plane d = (n/z − n/f)/(1 − n/f) and |dd/dz| = n/((1 − n/f) z²)"
)


#: r442 F3: a distance from the exact d, which the buffer never holds
_FROM_EXACT = (
    "you measured the step from the exact d to a float32 neighbour: the buffer holds d "
    "rounded to float32, and its step is the distance between two stored values, np.spacing "
    "of np.float32(d) (or to the neighbour below)"
)


def _signed_ndc_words(args, expected, got) -> str:
    """np.spacing of 2d − 1 (r381 F4: its negative step was told "a gap is a positive
    distance" alone)."""
    ndc = 2 * float(reversed_depth(*args)) - 1
    glclip = ("OpenGL's default NDC, 2d − 1 in [−1, 1], is reverse-Z without glClipControl(..., "
              "GL_ZERO_TO_ONE), where float32 near −1 has steps of 2^-24 only (lesson 05b, §4). "
              "The buffer here stores d itself, in [0, 1]")  # fmt: skip
    if ndc < 0:
        return ("your step is negative where the value you took the spacing of is negative: "
                f"np.spacing of a negative float32 is negative, and 2d − 1 = {ndc:.4g} here. "
                f"Did d go through [−1, 1] NDC? {glclip}")  # fmt: skip
    return f"you took the step at 2d − 1 = {ndc:.4g}: {glclip}"


_SIGNED_NDC = _signed_ndc_words


def _one_minus_window_words(args, expected, got) -> str:
    z, near, far = args
    d = float(reversed_depth(z, near, far))
    rounded = {one_minus_window(z, near, far, k) for k in (True, False)}
    said = " or ".join(f"{v:.4g}" for v in sorted(rounded))
    return (": you computed d as 1 − z_win in float32. Near 1, float32's step is 2^-24 "
            f"≈ 6e-8, so z_win is rounded to it before the subtraction and d comes out {said} "
            f"where it is {d:.4g}: another binade, another step. That cancellation is what "
            "reverse-Z must avoid (lesson 05b, §4: never as 1 − d from an already rounded d); "
            "a pipeline that writes float32(1 − z_win) resolves no better than window depth. "
            "Compute d = (n/z − n/f)/(1 − n/f) itself")  # fmt: skip


MISTAKES = {
    "1 - z_win in float32": _one_minus_window_words,
    "1 - z_win in float32, z_win in float64": _one_minus_window_words,
    # r295 M-1's lesson: one answer, several readings, all named. Window depth's float32 step
    # is 2^-24 wherever z_win ≥ 1/2, so 2^-24 (the step below 1) and unorm24's 1/(2^24 − 1)
    # give this very answer there, and the right one elsewhere (there d ≥ 1/2)
    "window depth": "that is the Δz of ordinary window depth z_win, not reversed (or, the "
    "same answer, float32's step taken at depth 1, 2^-24, or unorm24's step): far depths lie "
    "near 1 there, where float32's step is 2^-24. Reverse-Z stores d = 1 − z_win, which lies "
    "near 0 for far surfaces, where float32's steps are tiny (near and far swapped in d give "
    "this very z_win: d = (n/z − n/f)/(1 − n/f) with n and f exchanged is f/(f − n) · (1 − n/z))",
    "step above 1": "you took float32's step just above depth 1, 2^-23: the buffer stores d, "
    "near 0 for far surfaces, and float32's step is the one at d",
    "float64": "you took float64's step at d (np.spacing of a float64): the buffer is "
    "float32, whose steps are 2^29 times coarser",
    "float16": "you took float16's step at d (np.float16, 10 bits of fraction): the buffer is "
    "float32, 23 bits of fraction, whose steps are 2^13 = 8192 times finer",
    "near and far swapped": "you swapped n and f in d = (n/z − n/f)/(1 − n/f): with them "
    "swapped it gives ordinary window depth z_win (far depths near 1, where float32's step is "
    "2^-24) and a negative slope, so yours is minus window depth's Δz. Reverse-Z keeps the "
    "planes and flips the depth: d = 1 − z_win",
    "relative step": _RELATIVE,
    "relative step, half": _RELATIVE,
    # two readings give this very answer: half a step, and NDC's slope
    "half": f"yours is half of it: {HALF_STEP}. Or you took the slope of an NDC depth 2d − 1 "
    "in [−1, 1], twice d's: the buffer stores d in [0, 1]. Or you took 2^(e−24) for 24 bits "
    "of precision: they count the hidden leading 1, the stored fraction has 23, so d "
    "in [2^e, 2^(e+1)) steps by 2^(e−23)",
    "ceil for floor": "you took the step of the binade above d's, 2^(⌈log2 d⌉ − 23): d in "
    "[2^e, 2^(e+1)) has e = ⌊log2 d⌋ and steps by 2^(e−23) (np.spacing of d as stored)",
    "gl ndc": "you sent d through OpenGL's default NDC, 2d − 1 in [−1, 1], where float32 "
    "near −1 has steps of 2^-24 only: that is reverse-Z without glClipControl(..., "
    "GL_ZERO_TO_ONE) (lesson 05b, §4). The buffer here stores d itself, in [0, 1]",
    "gl ndc, signed": _SIGNED_NDC,
    "gl ndc, signed, d's slope": _SIGNED_NDC,
    "spacing of z": "you took float32's step at z, the view depth: the buffer stores d, not z. "
    "Δz is one float32 step at the stored d = (n/z − n/f)/(1 − n/f), divided by how fast d "
    "changes with z, |dd/dz| = n/((1 − n/f) z²)",
    "infinite far": _INFINITE,
    "infinite far, slope": _INFINITE,
    "infinite far, depth": "you stored d = n/z, reverse-Z for a far plane at infinity, and "
    "kept this far plane's slope: with this far plane d = (n/z − n/f)/(1 − n/f), and "
    "the buffer's step is the one at that d",
    "step in depth": "you returned the step in stored depth; Δz is a distance in view "
    "depth: that step divided by |dd/dz|",
    "times slope": "you multiplied the step by |dd/dz|; divide it: Δz = step / |dd/dz|",
    "z not squared": "you used z where the slope falls like 1/z²: |dd/dz| = n/((1 − n/f) z²)",
    "1 - n/f twice": "your Δz has the factor 1 − n/f twice: d = (n/z − n/f)/(1 − n/f), so "
    "|dd/dz| = n/((1 − n/f) z²) and Δz = step · (1 − n/f) z²/n, with 1 − n/f once",
    "1 - n/f inverted": "your slope has 1 − n/f on the wrong side: d = (n/z − n/f)/(1 − n/f) "
    "divides by it, so |dd/dz| = n/((1 − n/f) z²) and Δz = step · (1 − n/f) z²/n",
    "from the exact d": _FROM_EXACT,
    "from the exact d, below": _FROM_EXACT,
    "secant over one unit": "your slope is a difference of d over one unit of z, d(z) − "
    "d(z + 1): d's slope falls like 1/z², so that difference is the slope at z times z/(z + 1), "
    "short by 1/(z + 1) of it (most near the eye). Take the derivative, |dd/dz| = "
    "n/((1 − n/f) z²)",
    "slope d/z": "you took d's slope as d/z: that holds for d = n/z alone (a far plane at "
    "infinity). With this far plane d = (n/z − n/f)/(1 − n/f), and |dd/dz| = n/((1 − n/f) z²)",
    "far for near in the slope": "you divided by f where d's slope has n: d = (n/z − n/f)/(1 − "
    "n/f) changes by |dd/dz| = n/((1 − n/f) z²), so Δz = step · (1 − n/f) z²/n, f/n "
    "times yours",
}


def explain_gap(args, expected, got) -> str:
    """The case, the stored depth, the smallest gap and the student's, with a verdict."""
    z, near, far = args
    lo, hi = _bounds(float(z), float(near), float(far))
    d = float(reversed_depth(z, near, far))
    head = (f"at z = {num(z)} with near = {num(near)} and far = {num(far)}, reverse-Z stores "
            f"d = {d:.4g}, where the buffer resolves Δz = {num(expected, got)}; yours is "
            f"{num(got, expected)}")  # fmt: skip
    if not np.isfinite(got) or got <= 0:
        return head
    # the band, as safe_near's words give it (at a power of two it is 2 wide: either neighbour)
    band = f"the check accepts {_num(lo, hi)} to {_num(hi, lo)}"
    if got < lo:
        return (f"{head} ({num(expected / got, 1.0)} times too fine: surfaces that close can "
                f"store one value; {band})")  # fmt: skip
    if got > hi:
        return f"{head} ({num(got / expected, 1.0)} times too coarse; {band})"
    return f"{head} (right)"


def _rule(args, expected, got) -> str:
    return (". Δz is one float32 step at the stored d (fixed within each binade "
            "[2^e, 2^(e+1)): 2^(e−23)) divided by |dd/dz| = n/((1 − n/f) z²)")  # fmt: skip


def gives_same_gap(got, answer, args) -> bool:
    """A mistake gives the student's answer: within 1e-6 relative (Δz is often 1e-8 or
    less, where the default's absolute tolerance near zero would take any tiny number)."""
    if answer is None or not np.isfinite(answer) or not np.isfinite(got):
        return answer is not None and got == answer
    return abs(got - answer) <= 1e-6 * max(abs(got), abs(answer))


def _num(x: float, other: float) -> str:
    """``x`` with at least 3 significant digits, more where needed to tell it from ``other``."""
    return max(num(x, other), f"{x:.3g}", key=len)


def _margin(args, expected, got) -> float | None:
    """r442: yours over the coarsest reading by more than :data:`SLACK` (up to 20 %), as a
    factor; None where it is not."""
    if not np.isfinite(got):
        return None
    c = got / max(readings(*(float(a) for a in args)))
    return c if 1 + SLACK < c <= 1.2 else None


MARGIN = Mistake(
    "margin",
    lambda a, e, g: (
        f": yours is {_margin(a, e, g):.4g} times one step above the stored d over the slope, "
        f"{num(max(readings(*a)), g)}: the check accepts up to 1 % over it (a gap rounded "
        "up a little). A margin, or a factor slipped in?"
    ),
    fits=lambda a, e, g: _margin(a, e, g) is not None,
    parameter=_margin,
    symptom=True,
)


def _not_positive(args, expected, got) -> bool:
    return bool(np.isfinite(got)) and got <= 0


RANGE = Mistake("range", ": a gap is a positive distance", fits=_not_positive, symptom=True)


def _binade_depths(z, near, far) -> tuple[float, float]:
    """The depths, nearer and farther, between which the stored d stays in z's binade
    [2^e, 2^(e+1)) (within the near and far planes)."""
    k = 1 - near / far
    e = np.floor(np.log2((near / z - near / far) / k))
    z_near = near / (2.0 ** (e + 1) * k + near / far)
    z_far = near / (2.0**e * k + near / far)
    return max(z_near, near * 1.01), min(z_far, far * 0.999)


def draw_gap(ax, case, got):
    """Δz against z (log y) over the binade of d the case's z lies in, float32 reverse-Z and
    window depth, the accepted range at the case's z, the expected gap and yours (r417 F7:
    over z/4 to 4 z, the sawtooth's teeth answered 5.2b's prediction a cell early)."""
    _, (z, near, far), expected = case
    lo_z, hi_z = _binade_depths(float(z), float(near), float(far))
    zs = np.linspace(lo_z, hi_z, 400)[1:-1]
    artists = ax.semilogy(zs, depth_resolution(zs, near, far, "float32", mapping="reversed"),
                          color="black", label="float32, reverse-Z")  # fmt: skip
    artists += ax.semilogy(zs, depth_resolution(zs, near, far, "float32"), color="#888888",
                           linestyle=":", label="float32, window depth")  # fmt: skip
    first, last = _bounds(float(z), float(near), float(far))
    # the band is 1 % tall, a sliver on decades of Δz: the inset below shows it on a linear
    # scale (r311 FIG-1)
    artists += ax.plot([z, z], [first, last], color="#7fbf7f", lw=8, solid_capstyle="butt",
                       label=f"accepted {_num(first, last)} to {_num(last, first)}",
                       zorder=1)  # fmt: skip
    artists += ax.plot([z], [expected], "o", color="#2b7bba", ms=8,
                       label=f"Δz (expected) {num(expected, got)}")  # fmt: skip
    if got is not None and np.isfinite(got) and got > 0:
        colour = "#7fbf7f" if same_gap(got, expected, (z, near, far)) else "#d7301f"
        artists += ax.plot([z], [got], "x", color=colour, ms=12, mew=2.5,
                           label=f"your Δz {num(got, expected)}")  # fmt: skip
        ax.set_ylim(min(ax.get_ylim()[0], got / 3), max(ax.get_ylim()[1], got * 3))
    elif got is not None:
        why = "not a number" if np.isnan(got) else "not a positive distance"
        artists += ax.plot([], [], " ", label=f"your Δz {num(got)}: not drawn, {why}")
    ax.set_xlim(lo_z, hi_z)
    artists += _zoom(ax, (z, near, far), (first, last), expected, got)
    from matplotlib.ticker import MaxNLocator

    ax.xaxis.set_major_locator(MaxNLocator(5))
    ax.set_xlabel(f"view depth z over one binade of d (near {num(near)}, far {num(far)})",
                  fontsize="small")  # fmt: skip
    ax.set_ylabel("smallest resolved gap Δz")
    # beside the axes: inside, it lay on the window-depth curve (which rises to the top left
    # or right, whichever the case)
    artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    return artists


def _zoom(ax, args, band, expected, got) -> list:
    """An inset below the legend, beside the axes (inside, it lay on the sawtooth): Δz on a
    linear scale around the expected one, the accepted band, the expected gap and yours (or
    an arrow to it, when it lies off this scale)."""
    first, last = band
    z = args[0]
    inset = ax.inset_axes([1.06, 0.08, 0.62, 0.22])
    left, right = first - 0.5 * (last - first), last + 0.5 * (last - first)
    artists = [inset.axvspan(first, last, color="#7fbf7f", lw=0)]
    # r417 F8: the expected Δz is the band's left edge: a line there, not a dot half outside
    # the green, and an accepted answer's × in a darker green than the band
    artists.append(inset.axvline(expected, color="#2b7bba", lw=1.5))
    if got is not None and np.isfinite(got) and got > 0:
        ok = same_gap(got, expected, args)
        colour = "#1b7837" if ok else "#d7301f"
        if left <= got <= right:
            artists += inset.plot([got], [0.5], "x", color=colour, ms=9, mew=2)
        else:  # off this scale: an arrow at the side it lies on
            x, ha, arrow = (right, "right", "→") if got > right else (left, "left", "←")
            artists.append(inset.text(x, 0.5, f"yours {arrow}", color=colour, ha=ha,
                                      va="center", fontsize="x-small",
                                      bbox={"fc": "white", "ec": "none", "pad": 1}))  # fmt: skip
    inset.set_xlim(left, right)
    inset.set_ylim(0, 1)
    inset.set_yticks([])
    inset.set_xticks([first, last])
    inset.set_xticklabels([_num(first, last), _num(last, first)], fontsize="x-small")
    # from the inset's left edge rightwards: centred, it ran over the main axes (r325 FIG2)
    inset.set_title(f"accepted Δz at z = {num(z)}, zoomed", fontsize="x-small", pad=3, loc="left")
    return artists + [inset]


REVERSE_Z_GAP = Exercise(
    "reverse_z_gap", gap_cases, as_lone_number, same_gap, explain_gap, _rule,
    variant_mistakes(gap_variants, MISTAKES, (MARGIN, RANGE)), draw=draw_gap, match=gives_same_gap,
    # r414 F3: a pass draws z = 5 at near 1, far 10: at lesson 05b's planes (the first case)
    # its sawtooth over z 75 to 1000 answered 5.2b's prediction, a cell before 5.2b asks it
    example=7,
    # float32's rounding is relative to Δz itself (1e-8 and less), not to 1 (r325 C3: floored
    # at 1, a slope slip 11 % off and 6× errors were called float32's rounding)
    float32=lambda args: expected_gap(*args), float32_floor=0.0,
    answers=(
        PackageAnswer(expected_gap, words=CHECKER_WORDS),
        PackageAnswer(depth_resolution, what="float32 reverse-Z's Δz, this very answer",
                      when=lambda a: a.get("fmt") == "float32" and a.get("mapping") == "reversed"),
    ), hints=(
        (". Δz is one float32 step at the stored d (fixed within each binade [2^e, 2^(e+1)): "
         "2^(e−23)) divided by |dd/dz| = n/((1 − n/f) z²)",
         ". Find the float32 step at the value the buffer stores, and how fast that value "
         "changes with z"),
    ),
)  # fmt: skip
