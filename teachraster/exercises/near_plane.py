"""Exercise ``safe_near`` (lesson 05b): how far out must the near plane go?

Two surfaces ``gap`` apart at view distance z are told apart by a ``bits``-bit unorm depth
buffer when its resolution there, Δz = step / |d z_win / dz| (lesson 05b, §2; Ritschel,
*Interpolation and z-buffering*, depth aliasing), is at most ``gap``. With window depth
z_win = (f / (f − n)) (1 − n / z) and step = 1 / (2^bits − 1), the student solves for the
smallest near-plane distance n: the classic advice "push the near plane out", quantified.

Expected answers: the near plane at which :func:`teachraster.depth_resolution` (the
package's own) equals ``gap``, found by bisection on it, so no second formula decides. An
answer is checked against the criterion, not closeness to that number (r39 05-1, 05-2): it
passes when the buffer tells the two surfaces apart there, by the first-order resolution or
by whole steps (their window depths, :func:`teachraster.pipeline.visibility.depth.window_depth`,
one step apart, with the second surface at z − gap or at z + gap), and it is at most
:data:`SLACK` further out than the farthest of those smallest near planes.
"""

from __future__ import annotations

import copy
import math
from functools import cache

import numpy as np

from ..pipeline.visibility.depth import depth_resolution, window_depth
from .answers import as_number
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .package_answers import CHECKER_WORDS
from .running import WrongAnswerType
from .scalars import num
from .tolerance import close

#: (z, gap, far, bits) of the cases: near and far objects, thin and thick gaps, 4 to 24 bits.
SETTINGS = (
    (10.0, 0.01, 1000.0, 16), (100.0, 0.5, 1000.0, 16), (500.0, 1.0, 1000.0, 16),
    (2.0, 0.001, 100.0, 16), (50.0, 0.05, 100.0, 16), (100.0, 0.005, 1000.0, 24),
    (300.0, 0.005, 1000.0, 24), (1000.0, 0.1, 10000.0, 24), (30.0, 0.001, 50.0, 24),
    (5.0, 0.0001, 1000.0, 24), (20.0, 2.0, 25.0, 16), (900.0, 50.0, 1000.0, 16),
    # a thin gap near the far plane: the factor (f - n)/f moves n by 2 %, past SLACK
    (900.0, 0.5, 1000.0, 16),
    # r46 N2: "a buffer of a few bits" (lesson 05b): at 4 and 8 bits a step of 1/2^bits moves
    # n by 6.7 % and 0.4 %, past every reading that tells the surfaces apart; at 16 and 24
    # bits (1.5e-5) no tolerance could see it. The surfaces lie close to the far plane, where
    # so coarse a buffer still has a near plane between the eye and them.
    (45.0, 0.5, 50.0, 4), (9.5, 0.01, 10.0, 8), (99.0, 0.1, 100.0, 8),
)  # fmt: skip

#: How much further out than the smallest near plane an answer may be (a safe near plane,
#: found by bisection or rounded to a few digits, is right).
SLACK = 0.01


def as_lone_number(value):
    """One number, as :func:`.answers.as_number`, but not inside an array or brackets: the
    docs promise shapes must match (r414 F7: an array of shape (1,) passed 5.2b; r442 F1: a
    list of one too, and both in 5.1 to 5.3)."""
    if isinstance(value, np.ndarray) and value.ndim > 0:
        raise WrongAnswerType(
            f"returned an array of shape {value.shape} where one number is expected: return "
            "the number itself (float(...) of it)"
        )
    if isinstance(value, (tuple, list)) and len(value) == 1:
        raise WrongAnswerType(
            f"returned a {type(value).__name__} of one value where one number is expected: "
            "return the number itself, not inside brackets"
        )
    return as_number(value)


def resolution(z, near, far, bits) -> float:
    """The package's Δz at distance z (first order); for a buffer the package has no format
    for (4 or 8 bits), its 16-bit Δz scaled by the ratio of the steps (Δz is one step over
    the slope of z_win)."""
    if bits in (16, 24):
        return float(depth_resolution([z], near, far, f"unorm{bits}")[0])
    return float(depth_resolution([z], near, far, "unorm16")[0]) * (2**16 - 1) / (2**bits - 1)


def expected_near(z: float, gap: float, far: float, bits: int) -> float:
    """The near plane n with resolution(z, n) == gap: bisection on the package's Δz, which
    falls as n grows."""
    return _smallest(lambda n: resolution(z, n, far, bits) <= gap, z)


def steps_apart(z0: float, z1: float, near: float, far: float, bits: int) -> float:
    """How many steps of the buffer lie between the window depths of distances z0 and z1."""
    d = window_depth([z0, z1], near, far)
    return float(abs(d[1] - d[0])) * (2**bits - 1)


def bounds(z: float, gap: float, far: float, bits: int) -> tuple[float, float]:
    """(lowest, highest) near plane that passes: the smallest at which the surfaces are told
    apart by any reading (whole steps between z − gap and z is the most lenient), and
    :data:`SLACK` beyond the largest (whole steps between z and z + gap)."""
    back = _smallest(lambda n: steps_apart(z - gap, z, n, far, bits) >= 1, z)
    ahead = _smallest(lambda n: steps_apart(z, z + gap, n, far, bits) >= 1, z)
    first = expected_near(z, gap, far, bits)
    return min(back, first), max(ahead, first) * (1 + SLACK)


@cache
def _bounds(z, gap, far, bits) -> tuple[float, float]:
    return bounds(z, gap, far, bits)


def _smallest(told_apart, z: float) -> float:
    """The smallest n in (0, z) where ``told_apart(n)`` holds (it holds for every larger n)."""
    lo, hi = 1e-12 * z, z
    for _ in range(200):
        mid = (lo * hi) ** 0.5 if hi / lo > 4 else (lo + hi) / 2
        if told_apart(mid):
            hi = mid
        else:
            lo = mid
        if hi - lo <= 1e-15 * hi:
            break
    return hi


def near_cases() -> list[tuple[str, tuple, float]]:
    """The fixed cases (built once, then copied: see :func:`_near_cases`) and :data:`DRAWN`
    drawn for this check, so a table of the fixed cases' answers fails (r46 N1)."""
    out, now = copy.deepcopy(_near_cases()), drawn_rng()
    for k in range(DRAWN):
        z, gap, far, bits = _drawn_setting(now)
        label = (f"drawn for this check {k + 1}: z = {num(z)}, gap = {num(gap)}, "
                 f"far = {num(far)}, {bits} bits")  # fmt: skip
        out.append((label, (z, gap, far, bits), expected_near(z, gap, far, bits)))
    return out


def _drawn_setting(rng) -> tuple[float, float, float, int]:
    """(z, gap, far, bits), three significant digits, whose near plane lies between a
    thousandth and half of z: the far plane, z in front of it, then the gap that puts n
    there."""
    while True:
        bits = int(rng.choice([16, 24]))
        far = float(f"{10 ** rng.uniform(1, 4):.3g}")
        z = float(f"{far * rng.uniform(0.05, 0.95):.3g}")
        n = z * 10 ** rng.uniform(-3, np.log10(0.5))
        step = 1.0 / (2**bits - 1)
        gap = float(f"{step * z * z * (far - n) / (far * n):.3g}")
        if 0 < gap < z and 1e-3 * z < expected_near(z, gap, far, bits) < 0.5 * z:
            return z, gap, far, bits


@cache
def _near_cases() -> list[tuple[str, tuple, float]]:
    out = []
    for z, gap, far, bits in SETTINGS:
        n = expected_near(z, gap, far, bits)
        label = f"z = {num(z)}, gap = {num(gap)}, far = {num(far)}, {bits} bits"
        out.append((label, (z, gap, far, bits), n))
    return out


def same_near(got, expected, args=None) -> bool:
    """The surfaces are told apart at n = ``got`` and it is not needlessly far out (between
    :func:`bounds`, with float32's rounding at the low end); without the case's ``args``,
    within 1e-6 of ``expected``."""
    if args is None:
        return close(got, expected, 1e-6)
    if not np.isfinite(got):
        return False
    z, gap, far, bits = args
    lo, hi = _bounds(float(z), float(gap), float(far), int(bits))
    return lo * (1 - 1e-6) <= got <= hi


def _variants(z, gap, far, bits) -> dict[str, float]:
    """The near plane typical slips give (each one formula change)."""
    step = 1.0 / (2**bits - 1)

    def solve(step, f):  # exact solution of step (f - n) z² / (f n) = gap
        return step * f * z * z / (gap * f + step * z * z)

    with np.errstate(all="ignore"):
        return {
            "2^bits": solve(1.0 / 2**bits, far),
            "1/bits": solve(1.0 / bits, far),  # r325: the bits, not the values they hold
            "ndc": solve(2 * step, far),
            "infinite far": step * z * z / gap,
            "linear": far - gap / step,
            "squared": solve(step, far) ** 0.5,
            "resolution": gap,
            "bits - 1": solve(1.0 / (2 ** (bits - 1) - 1), far),
            "z not squared": step * far * z / (gap * far + step * z),
            "z and gap swapped": step * far * gap * gap / (z * far + step * gap * gap),
            # r295 H-2..H-6: typical slips that were told only the symptom or the rule
            "xor": solve(1.0 / ((2 ^ bits) - 1), far),
            # r340: as students type it, 1/(2^bits - 1), which Python reads as 2 ^ (bits - 1)
            "xor, unbracketed": solve(1.0 / (2 ^ (bits - 1)), far),
            "sign slip": step * far * z * z / (gap * far - step * z * z),
            "negated": -solve(step, far),
            # r311 H-1: "rounding to nearest, so half a step is enough"
            "half": solve(step / 2, far),
            # r381 F5: int() of the right n (0 below 1: told only "0 < n < z" first)
            "int": float(math.trunc(solve(step, far))),
            **{f"{b} bits": solve(1.0 / (2**b - 1), far) for b in (16, 24) if b != bits},
            # r442 F3: the resolution asked at the nearer surface, z − gap (or the farther)
            "nearer surface": step * far * (z - gap) ** 2 / (gap * far + step * (z - gap) ** 2),
            "farther surface": step * far * (z + gap) ** 2 / (gap * far + step * (z + gap) ** 2),
        }


#: r311 H-1: the half-step model, named in 5.1 and 5.2 (:mod:`.reverse_z`) alike. Rounding
#: to nearest errs by at most half a step, but two depths half a step apart can still round to
#: one stored value (0.1 and 0.45 of a step both store 0): only a whole step apart always
#: stores two.
HALF_STEP = (
    "you took half a step (a stored value's rounding error, ±step/2) as enough. Two depths "
    "half a step apart can still round to one stored value (0.1 and 0.45 of a step both "
    "store 0); only depths a whole step apart always store different values"
)

#: r340: the `^` typo as students type it, named in 5.1 and 5.3 (:mod:`.decal_bias`) alike
XOR_UNBRACKETED = (
    "`^` is exclusive or in Python, not a power: `2^bits - 1` reads as 2 ^ (bits − 1), "
    "2 ^ 15 = 13 for 16 bits, 2 ^ 23 = 21 for 24; use 2**bits: the step is 1/(2**bits − 1)"
)

MISTAKES = {
    "2^bits": "you took the buffer's step as 1/2^bits; a unorm buffer's largest value is "
    "2^bits − 1, which stores depth 1, so the step is 1/(2^bits − 1)",
    "1/bits": "you took the buffer's step as 1/bits: `bits` bits hold 2^bits values, 0 to "
    "2^bits − 1, evenly over depth 0 to 1, so one step is 1/(2^bits − 1)",
    # r295 M-1: half the gap gives the very same n (2·step/gap = step/(gap/2))
    "ndc": "you took a step of 2/(2^bits − 1), as if the buffer stored NDC depth in [−1, 1], "
    "or you halved the gap (half a step of margin on each side?): either gives this n. The "
    "buffer stores window depth in [0, 1], one step is 1/(2^bits − 1), and the surfaces are "
    "the whole gap apart",
    "infinite far": "you dropped the factor (f − n)/f: your n is right only for a far plane "
    "at infinity; solve step (f − n) z² / (f n) ≤ gap for n exactly",
    "linear": "you used linear depth, (z − n)/(f − n), whose resolution is the same "
    "everywhere: the buffer stores window depth, which is affine in 1/z",
    "squared": "your n is the square root of the answer: Δz grows like z² / n, so n grows like z²",
    "resolution": "you returned the gap; return the near-plane distance n",
    "bits - 1": "you used one bit fewer than the buffer has (2^(bits − 1) − 1 steps): the "
    "step is 1/(2^bits − 1)",
    "z not squared": "you used z where the resolution grows with z²: Δz ≈ step · z² / n "
    "(for f ≫ n), so n grows like z², not like z",
    "z and gap swapped": "you swapped z and gap: z is the distance of the surfaces, gap "
    "their separation (the arguments are safe_near(z, gap, far, bits))",
    "xor": "`^` is exclusive or in Python (2 ^ 16 = 18, 2 ^ 24 = 26), not a power: the power "
    "is 2**bits, so the step is 1/(2**bits − 1)",
    "xor, unbracketed": XOR_UNBRACKETED,
    "sign slip": "a sign slipped as you solved for n: gathering the terms in n gives "
    "gap·f + step·z² beside n, a plus, where yours has gap·f − step·z²",
    "negated": "your n has the right size and the wrong sign: a near plane lies in front of "
    "the eye, n > 0",
    "half": HALF_STEP,
    "int": lambda a, e, g: (
        f"int() truncates your n toward 0, {num(e, g)} to {num(g)}: that lies nearer than the "
        "smallest near plane (0 is no near plane at all), where the two surfaces' window depths "
        "are less than a step apart. Keep every digit, or round up"
    ),
    "nearer surface": lambda a, e, g: (
        f"you took the resolution at z − gap = {num(a[0] - a[1])}, where Δz is finer than at "
        f"z = {num(a[0])}: surfaces {num(a[1])} apart there, at z − gap and z, then lie less "
        "than a whole step apart. Take the resolution at z itself (or the window depths of "
        "z − gap and z a whole step apart)"
    ),
    "farther surface": lambda a, e, g: (
        f"you took the resolution at z + gap = {num(a[0] + a[1])}, farther than the surfaces: "
        "Δz grows with z, so your near plane lies further out than needed. Take it at z itself "
        "(or the window depths of z and z + gap a whole step apart)"
    ),
    **{
        f"{b} bits": f"your n is the one for a {b}-bit buffer, whatever `bits` is: the step is "
        "1/(2^bits − 1) with the case's own bits"
        for b in (16, 24)
    },
}


def explain_near(args, expected, got) -> str:
    """The case, the smallest near plane and yours, with the resolution yours gives."""
    z, gap, far, bits = args
    lo, hi = _bounds(float(z), float(gap), float(far), int(bits))
    head = (f"at z = {num(z)} with far = {num(far)} and {bits} bits, surfaces {num(gap)} apart "
            f"need n ≥ {_num(expected, got, lo)} (to first order; {_num(lo, got, expected)} "
            f"with their window depths a whole step apart); yours is {num(got, expected)}")  # fmt: skip
    if not np.isfinite(got) or not 0 < got < z:
        return head
    yours = resolution(z, got, far, bits)
    if got < lo:
        steps = steps_apart(z - gap, z, got, far, bits)
        # r295 R-2: 0.9995 of a step was printed "1 of a step" beside "too coarse"
        verdict = (f"too coarse: the two surfaces' window depths lie {num(steps, 1.0)} of a "
                   "step apart, so both can round to one stored value and z-fight")  # fmt: skip
    elif got > hi:
        # r84 05-1: "any near plane from lo to hi tells them apart" read as if yours did not
        # r351 item 2: Δz falls with n at every depth: a farther near plane costs no precision,
        # it clips the geometry between the two planes (5.4's words)
        verdict = (f"farther than needed: yours tells them apart too, but lies further out than "
                   f"the smallest near plane that does, and clips any geometry between the two; "
                   f"the check accepts {_num(lo, got, hi)} to {_num(hi, got, lo)}, the smallest by any "
                   "reading of whole steps up to 1 % further out")  # fmt: skip
    else:
        verdict = "right"
    return f"{head}, where the buffer resolves Δz = {num(yours)} ({verdict})"


def _num(x: float, *others: float) -> str:
    """``x`` with the digits that tell it from each of ``others`` (r295 R-1: bounds 0.00275
    and 0.00339 were both printed "0.003", told only from the student's 8)."""
    return max((num(x, o) for o in others), key=len)


def _rule(args, expected, got) -> str:
    return (
        ". The step of a bits-bit unorm buffer is 1/(2^bits − 1) in window depth; solve "
        "step · (f − n) z² / (f n) ≤ gap for n"
    )


def _out_of_range(args, expected, got) -> bool:
    """Finite and outside (0, z): NaN and ±inf are told as such (r295 H-1: NaN was told
    only "0 < n < z")."""
    z = args[0]
    return bool(np.isfinite(got)) and not 0 < got < z


def _rounds_apart(args, expected, got) -> bool:
    """r311 H-2: too close, yet at n = ``got`` the two depths round to different integers (a
    scan for "the rounded integers differ" stops at such a lucky n)."""
    z, gap, far, bits = args
    if not (np.isfinite(got) and 0 < got < z):
        return False
    scale = 2**bits - 1
    stored = np.rint(window_depth([z - gap, z, z + gap], got, far) * scale)
    return bool(got < _bounds(float(z), float(gap), float(far), int(bits))[0]) and (
        stored[0] != stored[1] or stored[1] != stored[2]
    )


ROUNDS_APART = Mistake(
    "rounded integers",
    ". At your n the two depths do round to different integers, but only by luck: a step "
    "boundary happens to fall between them, though they lie less than a step apart. Move z or "
    "n a little and both round to one value; the buffer tells surfaces apart wherever they "
    "lie only when their window depths are a whole step apart",
    fits=_rounds_apart,
)


def _rounded_to(x: float, got: float) -> int | None:
    """The significant digits (1 to 6) to which ``x`` rounded down or to nearest gives
    ``got``, or None."""
    if not (np.isfinite(got) and 0 < got < x):
        return None
    for k in range(1, 7):
        unit = 10.0 ** (np.floor(np.log10(x)) - k + 1)
        for r in (np.floor(x / unit) * unit, np.round(x / unit) * unit):
            if abs(r - got) <= 1e-9 * x:
                return k
    return None


def _rounded_down(args, expected, got) -> bool:
    """r340/r351: the smallest near plane rounded down to a few digits (0.15 for 0.153), which
    falls short; it was told "only by luck"."""
    z, gap, far, bits = args
    lo = _bounds(float(z), float(gap), float(far), int(bits))[0]
    return (
        bool(np.isfinite(got)) and got < lo * (1 - 1e-6) and _rounded_to(expected, got) is not None
    )


ROUNDED_DOWN = Mistake(
    "rounded down",
    lambda a, e, g: (
        f": your n is the smallest near plane, {num(e, g)}, rounded down to "
        f"{_rounded_to(e, g)} significant digit{'s' if _rounded_to(e, g) > 1 else ''}: that lies "
        "nearer than the smallest, where the two surfaces' window depths are less than a step "
        "apart. Round up, or keep every digit"
    ),
    fits=_rounded_down,
)


def _just_under(args, expected, got) -> float | None:
    """r442: under the smallest accepted near plane by at most 1 %, and no rounding of it (a
    bisection that returned its bracket's low end was told only "by luck"); the share, or
    None."""
    z, gap, far, bits = args
    lo = _bounds(float(z), float(gap), float(far), int(bits))[0]
    if not np.isfinite(got) or not 0 < got < lo * (1 - 1e-6) or _rounded_down(args, expected, got):
        return None
    share = 1 - got / lo
    return share if share <= 0.01 else None


JUST_UNDER = Mistake(
    "just under",
    lambda a, e, g: (
        f": yours lies {_just_under(a, e, g):.1g} (relative) nearer than the smallest near plane "
        "that tells the surfaces apart: a bisection that returned its bracket's low end (the "
        "side where they are not yet told apart), a scan that stopped where the two depths' "
        "rounded integers first differ (less than a step apart they can, by luck), or a "
        "formula a little off? Return the end where they are told apart, or solve "
        "step (f − n) z²/(f n) = gap for n exactly"
    ),
    fits=lambda a, e, g: _just_under(a, e, g) is not None,
)

RANGE = Mistake("range", ": a near plane lies between the eye and the surfaces, 0 < n < z",
                fits=_out_of_range, symptom=True)  # fmt: skip


def draw_near(ax, case, got):
    """Δz at the case's distance against the near plane (log-log), the gap, the expected
    near plane and yours."""
    _, (z, gap, far, bits), expected = case
    shown = got is not None and np.isfinite(got) and 0 < got < z
    lo, hi = expected / 30, min(expected * 30, z * 0.999)
    if shown and abs(got - expected) < 0.1 * expected:  # r84 05-3: 3 % apart drew one line
        lo, hi = 0.8 * min(got, expected), min(1.2 * max(got, expected), z * 0.999)
    ns = np.geomspace(lo, hi, 200)
    dz = np.array([resolution(z, n, far, bits) for n in ns])
    artists = ax.loglog(ns, dz, color="black", label=f"Δz at z = {num(z)}")
    artists.append(ax.axhline(gap, color="#888888", linestyle=":", label=f"gap {num(gap)}"))
    artists.append(ax.axvline(expected, color="#2b7bba",
                              label=f"smallest n (expected) {num(expected, got)}"))  # fmt: skip
    # r295 S-1: the band the check accepts, which "farther than needed" speaks of
    first, last = _bounds(float(z), float(gap), float(far), int(bits))
    artists.append(
        ax.axvspan(
            first,
            last,
            color="#d9ecd9",
            lw=0,
            zorder=0,
            label=f"accepted {_num(first, last)} to {_num(last, first)}",
        )
    )
    if shown:
        colour = "#7fbf7f" if same_near(got, expected, (z, gap, far, bits)) else "#d7301f"
        artists.append(ax.axvline(got, color=colour, linestyle="--",
                                  label=f"your n {num(got, expected)}"))  # fmt: skip
    elif got is not None:  # r295 FIG-2: a NaN or out-of-range answer was not in the figure
        why = "not a number" if np.isnan(got) else f"outside 0 < n < {num(z)}"
        artists += ax.plot([], [], " ", label=f"your n {num(got)}: not drawn, {why}")
    ax.set_xlim(lo, hi)
    if hi / lo < 10:  # r295 FIG-1: within a decade every minor tick was labelled, overlapping
        from matplotlib.ticker import FuncFormatter, MaxNLocator, NullLocator

        ax.xaxis.set_major_locator(MaxNLocator(4))
        ax.xaxis.set_minor_locator(NullLocator())
        ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:.3g}"))
    ax.set_xlabel("near plane n")
    ax.set_ylabel("depth resolution Δz")
    # r311 FIG-2: beside the axes, as 5.2's: inside, it covered the expected line and the band
    artists.append(ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1)))
    return artists


SAFE_NEAR = Exercise(
    "safe_near", near_cases, as_lone_number, same_near, explain_near, _rule,
    variant_mistakes(_variants, MISTAKES, (ROUNDED_DOWN, JUST_UNDER, ROUNDS_APART, RANGE)),
    draw=draw_near,
    # r126 (fixex10's note): no answer was listed, so expected_near, handed in, passed
    answers=(
        PackageAnswer(expected_near, words=CHECKER_WORDS),
        # r374 F9: a search over n of the package's unorm resolution passed with no algebra
        PackageAnswer(depth_resolution, when=lambda a: str(a.get("fmt", "")).startswith("unorm"),
                      what="a unorm buffer's Δz, the very quantity this task asks you to derive "
                      "and solve for n"),
    ), hints=(
        # r39 05-3: the first wrong try printed the inequality the task asks to derive
        ("; solve step (f − n) z² / (f n) ≤ gap for n exactly", "; keep it and solve for n "
         "exactly"),
        (": Δz ≈ step · z² / n (for f ≫ n), so n grows like z², not like z", ""),
        ("; solve step · (f − n) z² / (f n) ≤ gap for n", "; differentiate z_win with respect "
         "to z, and find the n where one step divided by that slope at z is gap"),
        # r381 F5: the sign slip's words gave the solved formula's denominator at once
        ("gathering the terms in n gives gap·f + step·z² beside n, a plus, where yours has "
         "gap·f − step·z²", "gather the terms in n again, and check the sign of each"),
    ),
)  # fmt: skip
