"""Exercise ``depth_setup`` (lesson 05b, §2 and §4): which depth buffer, and which near plane.

Review r340 (M3, M5; r325 M2, M4): 5.1 (``safe_near``) and 5.2 (``reverse_z_gap``) are one
formula each and never meet. Here the student uses both to decide: a scene shows geometry
as close as ``nearest`` (the near plane may not lie beyond it), its far plane is ``far``, and
two surfaces ``gap`` apart at view distance ``z`` must not z-fight. A unorm24 buffer does it
when the smallest near plane that resolves the gap (5.1) is no farther than ``nearest``; else
float32 reverse-Z may (5.2), whose Δz = one float32 step at d over |dd/dz| lies between
2^-24 and 2^-23 of z (1 − z/f) whatever the near plane (d over its slope is z (1 − z/f)), so
pushing its near plane out buys nothing; else neither does. The scene needs a stencil
buffer, and unorm24 is preferred where it does the job by the formats' nominal sizes: its depth
and an 8-bit stencil share 32 bits a pixel (Direct3D's ``D24_UNORM_S8_UINT``), float32 depth
with a stencil is declared 64 (``D32_FLOAT_S8X24_UINT``). r351 item 1: that is the declared
size only (lesson 05b's table: OpenGL may store separate planes, Vulkan requires only one of
the two packed formats, AMD stores depth and stencil apart, Apple has no 24-bit depth); the
task says so.

The answer is (format, near, Δz): the choice, the near plane the student would use, and what
that set-up resolves at z there, the numbers that defend the choice. It is judged by criterion:
the right choice, any near plane in (0, nearest] at which the choice does the job (for
unorm24, from the smallest by any reading of 5.1's check up to ``nearest``), and Δz what the
chosen buffer resolves at z with *that* near plane (unorm24: one step over the slope, within
1 %; float32 reverse-Z: 5.2's accepted band; "neither": reverse-Z's, the better of the two,
which still falls short). The reference (:func:`expected_setup`) is the package's:
:func:`.near_plane.expected_near` and :func:`.reverse_z.expected_gap`. The cases lie clear of
the borders (the smallest unorm24 near plane at most 0.8 or at least 1.25 times ``nearest``,
or every near plane 5.1's check accepts beyond ``nearest``;
the gap at least 1.3 times reverse-Z's coarsest Δz, or below 0.7 of its finest), so every
reading of "resolves" agrees.
"""

from __future__ import annotations

import copy
import math
import re
from functools import cache

import numpy as np

from ..pipeline.visibility.depth import depth_resolution
from .answers import refuse_non_answers, short
from .cases import DRAWN, drawn_rng
from .diagnosis import near
from .exercise import Exercise, Mistake, PackageAnswer
from .near_plane import bounds as near_bounds
from .near_plane import expected_near, resolution
from .package_answers import CHECKER_WORDS
from .reverse_z import bounds as gap_bounds
from .reverse_z import expected_gap, readings
from .reverse_z import reversed_depth_slope as reverse_slope
from .running import WrongAnswerType
from .scalars import num

#: The formats as the answer names them: "reverse-z" is a float32 buffer with reverse-Z (the
#: explanations say "reverse-Z" alone: "float32" in them would read as blaming the arithmetic)
UNORM, REVERSE, NEITHER, FORWARD = "unorm24", "reverse-z", "neither", "float32"
#: What the answer is, as the task and every wrong answer's words say it.
WHAT = ('(format, near, dz): format "unorm24", "reverse-z" or "neither", the near '
        "plane you would use, and the smallest gap that set-up resolves at z there")  # fmt: skip
#: unorm24's Δz at the student's near plane: one step over the slope, this share either way.
SLACK = 0.01
#: A near plane this share beyond ``nearest`` is still ``nearest``: float32's rounding of it,
#: at most 6e-8 (r351: float32(0.1) = 0.1 + 1.5e-9 was told "0.1 lies beyond nearest = 0.1").
NEAR_ROUNDING = 1e-6

#: (z, gap, far, nearest) of the fixed cases: lesson 05b's planes (far 1000) with unorm24
#: enough with room (n 1/30 of nearest) or just (0.8), float32 reverse-Z needed (unorm24's
#: near plane 150 times nearest, or just 1.25), a first-person view (nearest 0.01, far 10⁴),
#: and neither (the gap below reverse-Z's finest Δz: at z = 900, and far out at z = 5e5); one
#: where 16 bits would do too (r374 F4: else 5.1 run with 16 bits answers as "reverse-Z
#: wherever unorm24 does" does, and the two could not be told apart).
SETTINGS = (
    (50.0, 0.01, 1000.0, 0.5), (100.0, 7.5e-4, 1000.0, 1.0), (500.0, 0.001, 1000.0, 0.1),
    (100.0, 6.0e-3, 1000.0, 0.125), (2000.0, 0.05, 1e4, 0.01), (900.0, 3.5e-6, 1000.0, 0.1),
    (10.0, 1.0e-4, 100.0, 1.0), (5e5, 0.01, 1e6, 0.02), (10.0, 0.05, 100.0, 1.0),
    # r458 G1: neither, with reverse-Z's Δz only 1.66 times the gap (d near the top of its
    # binade): "reverse-Z if its Δz is under twice the gap" passed every case before
    (185.0, 6.0e-6, 1000.0, 0.1),
    # r514 P1: reverse-Z with its Δz 0.76 times the gap (d just above a power of two), where
    # "reverse-Z if its Δz is under half the gap" passed every case; P2: 5.1's near plane 1.006
    # times nearest by every reading (gap/z 6e-6), where "unorm24 with 1 % slack" passed
    (168.0, 2.17e-5, 1000.0, 0.1), (100.0, 5.92e-4, 1000.0, 1.0),
)  # fmt: skip


def _finest(z, far) -> tuple[float, float]:
    """(finest, coarsest) Δz of float32 reverse-Z at z, any near plane: 2^-24 and 2^-23 of
    z (1 − z/f), d over its slope."""
    span = z * (1 - z / far)
    return 2.0**-24 * span, 2.0**-23 * span


def choice(z, gap, far, nearest) -> str:
    """The buffer the scene needs: unorm24 if its smallest near plane is allowed, else float32
    reverse-Z if it resolves the gap, else neither."""
    if expected_near(z, gap, far, 24) <= nearest:
        return UNORM
    return REVERSE if expected_gap(z, nearest, far) <= gap else NEITHER


def expected_setup(z, gap, far, nearest) -> tuple[str, float, float]:
    """The package's answer: the chosen buffer at ``nearest`` with its Δz there (unorm24's,
    finer than the gap wherever 5.1's near plane lies short of ``nearest``: r374 F6, 5.1's
    own near plane has no margin; or float32 reverse-Z's, 5.2's, for "neither" too)."""
    chosen = choice(z, gap, far, nearest)
    if chosen == UNORM:
        return UNORM, nearest, resolution(z, nearest, far, 24)
    return chosen, nearest, expected_gap(z, nearest, far)


def clear_of_borders(z, gap, far, nearest) -> bool:
    """Every reading agrees on this case (see the module's docstring)."""
    ratio = expected_near(z, gap, far, 24) / nearest
    fine, coarse = _finest(z, far)
    # r514 P2: or every near plane 5.1's check accepts lies beyond nearest (by 0.2 %)
    unorm_clear = ratio <= 0.8 or ratio >= 1.25 or near_bounds(z, gap, far, 24)[0] > 1.002 * nearest
    return unorm_clear and (ratio <= 0.8 or gap >= 1.3 * coarse or gap <= 0.7 * fine)


def _label(z, gap, far, nearest) -> str:
    return f"z = {num(z)}, gap = {num(gap)}, far = {num(far)}, nearest = {num(nearest)}"


@cache
def _fixed():
    return [(_label(*s), s, expected_setup(*s)) for s in SETTINGS]


def setup_cases():
    """The fixed cases (built once, copied) and :data:`DRAWN` drawn for this check: one of
    each outcome in turn."""
    out, rng = copy.deepcopy(_fixed()), drawn_rng()
    for k in range(DRAWN):
        s = _drawn(rng, (UNORM, REVERSE, NEITHER)[k % 3])
        out.append((f"drawn for this check {k + 1}: {_label(*s)}", s, expected_setup(*s)))
    return out


def _drawn(rng, outcome) -> tuple[float, float, float, float]:
    """(z, gap, far, nearest), three significant digits, with ``outcome`` the answer."""
    while True:
        far = float(f"{10 ** rng.uniform(2, 5):.3g}")
        z = float(f"{far * rng.uniform(0.05, 0.9):.3g}")
        nearest = float(f"{z * 10 ** rng.uniform(-4, -1.5):.3g}")
        fine, coarse = _finest(z, far)
        if outcome == UNORM:
            gap = resolution(z, nearest * rng.uniform(0.05, 0.7), far, 24)
        elif outcome == REVERSE:
            top = resolution(z, 1.5 * nearest, far, 24)
            gap = coarse * 1.5 * (top / (1.5 * coarse)) ** rng.uniform(0, 1)
        else:
            gap = fine * rng.uniform(0.2, 0.6)
        s = (z, float(f"{gap:.3g}"), far, nearest)
        if clear_of_borders(*s) and choice(*s) == outcome:
            return s


def _echo(value) -> str:
    """The returned value as :func:`.answers.short` gives it, its floats with 6 significant
    digits (r381 F7: "(0.014900940040703407, 'unorm24', 0.01)")."""
    if type(value) not in (tuple, list) or not 0 < len(value) <= 6:
        return short(value)
    parts = [f"{float(v):.6g}" if isinstance(v, (float, np.floating)) else short(v) for v in value]
    inner = ", ".join(parts)
    return f"({inner})" if type(value) is tuple else f"[{inner}]"


def as_setup(value) -> tuple[str, float, float]:
    """(format, near, dz): the format's words read loosely (case, spaces, "reverse z"), the
    numbers strictly (finite)."""
    refuse_non_answers(value, "three values " + WHAT)
    try:
        fmt, near, dz = value
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {_echo(value)}: return {WHAT}") from None
    if not isinstance(fmt, (str, np.str_)):
        raise WrongAnswerType(f"returned {_echo(value)}: its first value is the format, {WHAT}")
    words = " ".join(re.sub(r"[-_]", " ", str(fmt).lower()).split())
    read = {"unorm24": UNORM, "unorm 24": UNORM, "d24": UNORM, "float32 reverse z": REVERSE,
            "reverse z": REVERSE, "float32": FORWARD, "neither": NEITHER}.get(words)  # fmt: skip
    if read is None:
        raise WrongAnswerType(f'returned the format {short(fmt)}: say "unorm24", '
                              '"reverse-z" or "neither"')  # fmt: skip
    numbers = []
    for v in (near, dz):
        if isinstance(v, (bool, str, bytes, np.bool_)) or not np.ndim(v) == 0:
            raise WrongAnswerType(f"returned {_echo(value)}: near and dz are numbers, {WHAT}")
        numbers.append(float(v))
    if not all(math.isfinite(v) for v in numbers):
        raise WrongAnswerType(f"returned {_echo(value)}: near and dz are finite numbers, {WHAT}")
    return read, numbers[0], numbers[1]


def _resolves(fmt, z, n, far) -> tuple[float, float]:
    """(lowest, highest) Δz the answer may quote for ``fmt`` at near plane ``n``."""
    if fmt == UNORM:
        dz = resolution(z, n, far, 24)
        return dz * (1 - SLACK), dz * (1 + SLACK)
    return gap_bounds(z, n, far)


def _reverse_finest(z, n, far) -> float:
    """reverse-Z's finest Δz at z by a float32 neighbour of the stored d (not d's binade,
    which for a subnormal d, at n ≈ 1e-45 z, is far finer than any float32 step)."""
    return min(readings(z, n, far)[:2])


def _near_ok(args, fmt, n) -> bool:
    """n in (0, nearest], where the choice does the job: unorm24 from 5.1's smallest on,
    reverse-Z where its Δz (any reading) is within the gap (r351: at n = 1e-45 z, d rounds to
    float32 0 and Δz was 700 against a gap of 0.001, and passed)."""
    z, gap, far, nearest = args
    if not 0 < n <= nearest * (1 + NEAR_ROUNDING):
        return False
    if fmt == REVERSE:
        return n < z and _reverse_finest(z, n, far) <= gap
    return fmt != UNORM or n >= near_bounds(z, gap, far, 24)[0] * (1 - 1e-6)


def _dz_ok(args, fmt, n, dz) -> bool:
    z, _, far, _ = args
    if not 0 < n < z:
        return False
    lo, hi = _resolves(fmt, z, n, far)
    return lo <= dz <= hi


def same_setup(got, expected, args=None) -> bool:
    """The right format, a near plane in (0, nearest] that does the job, and the Δz of that
    set-up there; without ``args``, equal to ``expected`` within 1e-6."""
    fmt, n, dz = got
    if args is None:
        return fmt == expected[0] and all(
            abs(a - b) <= 1e-6 * abs(b) for a, b in zip((n, dz), expected[1:], strict=True)
        )
    return fmt == expected[0] and _near_ok(args, fmt, n) and _dz_ok(args, fmt, n, dz)


def _closed_near(z, gap, far) -> float:
    """5.1's closed form for unorm24, n = step f z² / (gap f + step z²), beyond z where no near
    plane short of z does it (:func:`.near_plane.expected_near` stops at z)."""
    step = 1 / (2**24 - 1)
    return step * far * z * z / (gap * far + step * z * z)


def explain_setup(args, expected, got) -> str:
    """The scene, what each buffer resolves, the right choice and the student's."""
    z, gap, far, nearest = args
    n_u = expected_near(z, gap, far, 24)
    fmt, n, dz = got
    # yours with the digits that tell it from the bound it is judged by (r351 item 3)
    bound = n_u if fmt == UNORM and n <= nearest else nearest
    # where only a near plane at z would do, "n ≥ 900" at z = 900 read as a usable one
    # told from yours only where the check could tell them apart (r374 F2: 5.1's n printed
    # with 16 digits beside yours with 4, where yours lay beyond `nearest` anyway)
    apart = fmt == UNORM and n <= nearest and abs(n - n_u) > 1e-6 * n_u
    need = f"n ≥ {num(n_u, n if apart else None)}" if n_u < 0.99 * z else (
        f"a near plane beyond z (5.1's formula gives {num(_closed_near(z, gap, far))}: none "
        "short of z does it)")  # fmt: skip
    return (f"at z = {num(z)} with far = {num(far)}, surfaces {num(gap)} apart and nothing "
            f"nearer than {num(nearest, n)}: unorm24 needs {need} (Δz at n = "
            f"{num(nearest)}: {num(resolution(z, nearest, far, 24))}), reverse-Z "
            f"resolves Δz = {num(expected_gap(z, nearest, far))} at n = {num(nearest)}, so the "
            f'answer is "{expected[0]}"; yours is ("{fmt}", {num(n, bound)}, {num(dz)})')  # fmt: skip


def _rule(args, expected, got) -> str:
    return ('. Take unorm24 if its smallest near plane (5.1) is at most `nearest`; else '
            'reverse-Z if its Δz at z (5.2) is at most the gap; else "neither". The '
            "near plane lies in (0, nearest], and Δz is what your buffer resolves at z with it")  # fmt: skip


# -- the typical mistakes: each a description of the answer (any near plane, any digits) --


def _fits(want_fmt, expected_fmts, test=None):
    def fits(args, expected, got):
        if got[0] != want_fmt or expected[0] not in expected_fmts:
            return False
        return True if test is None else bool(test(args, got))

    return fits


def _beyond(args, got) -> bool:
    return got[1] > args[3] * (1 + NEAR_ROUNDING)


def _yours_beyond(args, got) -> str:
    """The words "your near plane n lies beyond `nearest` = m", with the digits that tell them
    apart (r351: "0.1 lies beyond nearest = 0.1")."""
    n, nearest = got[1], args[3]
    return f"your near plane {num(n, nearest)} lies beyond `nearest` = {num(nearest, n)}"


def _words_beyond(args, expected, got) -> str:
    z, gap, far, nearest = args
    return (f": {_yours_beyond(args, got)}: it clips "
            f"geometry the scene shows. With n ≤ {num(nearest)} unorm24 resolves at best Δz = "
            f"{num(resolution(z, nearest, far, 24))} at z, more than the gap: compare 5.1's near "
            "plane with `nearest` before you choose unorm24")  # fmt: skip


def _words_too_coarse(args, expected, got) -> str:
    z, gap, far, nearest = args
    return (f": at your near plane {num(got[1])} unorm24 resolves Δz = "
            f"{num(resolution(z, got[1], far, 24))} at z, more than the gap {num(gap)}: the two "
            f"surfaces z-fight. It needs n ≥ {num(expected_near(z, gap, far, 24))}, beyond "
            f"`nearest` = {num(nearest)}")  # fmt: skip


def _words_unorm_does(args, expected, got) -> str:
    z, gap, far, nearest = args
    return (f": unorm24 does it here, with any near plane from "
            f"{num(expected_near(z, gap, far, 24))} to {num(nearest)} (5.1), and is preferred: "
            "with the stencil the scene needs, its format is nominally 32 bits a pixel, "
            "reverse-Z's 64: 5.1's near plane within `nearest` decides it, before reverse-Z is "
            "asked")  # fmt: skip


def _words_reverse_does(args, expected, got) -> str:
    z, gap, far, nearest = args
    return (f": reverse-Z resolves Δz = {num(expected_gap(z, nearest, far))} at z "
            f"with n = {num(nearest)}, within the gap {num(gap)}: it does the job where unorm24 "
            "cannot")  # fmt: skip


def _words_reverse_short(args, expected, got) -> str:
    z, gap, far, nearest = args
    fine, _ = _finest(z, far)
    return (f": reverse-Z resolves Δz = {num(expected_gap(z, got[1], far))} at z with "
            f"your n = {num(got[1])}, more than the gap {num(gap)}, and no near plane helps: "
            f"its Δz is one step of the stored float at d over |dd/dz|, 2^-24 to 2^-23 of z (1 − z/f) "
            f"(here ≥ {num(fine)}) whatever n is. Say \"neither\"")  # fmt: skip


def _quoted_other(args, got) -> bool:
    """Δz quoted of the other buffer at the student's near plane."""
    z, _, far, _ = args
    if not 0 < got[1] < z:
        return False
    other = REVERSE if got[0] == UNORM else UNORM
    lo, hi = _resolves(other, z, got[1], far)
    return lo <= got[2] <= hi


def _gap_quoted(args, got) -> bool:
    """The gap returned as Δz where the set-up resolves another."""
    return abs(got[2] - args[1]) <= 1e-9 * args[1]


def _dz_words(what):
    def words(args, expected, got):
        z, gap, far, nearest = args
        fmt, n = got[0], got[1]
        said_what = what(got) if callable(what) else what
        shown = REVERSE if fmt == NEITHER else fmt
        lo, hi = _resolves(shown, z, n, far) if 0 < n < z else (math.nan, math.nan)
        # told apart (r374: "0.022 to 0.022"); unorm24's own Δz, then the window accepted (r425
        # F5: its lower end, 0.000295, was printed as its Δz beside 0.000298)
        said = f"{num(lo, hi)} to {num(hi, lo)}"
        if fmt == UNORM:
            dz = resolution(z, n, far, 24)
            said = f"{num(dz, lo)} (the check accepts {said}, {SLACK * 100:g} % either way)"
        return (f": {said_what}. With your near plane {num(n)}, {shown} resolves Δz = {said} at z"
                + ("; for \"neither\" give reverse-Z's numbers, the better of the two"
                   if fmt == NEITHER else ""))  # fmt: skip

    return words


def _dz_wrong(args, expected, got) -> bool:
    return (
        got[0] == expected[0]
        and _near_ok(args, got[0], got[1])
        and not _dz_ok(args, got[0], got[1], got[2])
    )


def _gap_words(got) -> str:
    """The gap quoted as Δz: for unorm24 it is also unorm24's Δz at 5.1's own near plane, where
    it equals the gap by construction (r381 F3: that slip was told "you gave the gap back")."""
    if got[0] == UNORM:
        return ("your Δz is the gap itself: that is unorm24's Δz at 5.1's own near plane (there "
                "it equals the gap, by 5.1's construction), not at the near plane you return; "
                "quote what your set-up resolves at yours")  # fmt: skip
    return ("you gave the gap back as Δz; quote what your set-up resolves, the number that shows "
            "it does the job")  # fmt: skip


def _swapped_near(args, expected, got) -> bool:
    """(format, Δz, near): the answer passes with its two numbers swapped (r381 F3)."""
    return got[1] != got[2] and same_setup((got[0], got[2], got[1]), expected, args)


def _reverse_dz_as(reading):
    """A reverse-Z or "neither" answer whose Δz is ``reading(z, n, far)`` within 1 %, not what
    reverse-Z resolves there (r351's half-named: each was told only the wrong choice or the
    symptom)."""

    def fits(args, expected, got):
        z, _, far, _ = args
        fmt, n, dz = got
        if fmt not in (REVERSE, NEITHER) or expected[0] == UNORM or not 0 < n < z:
            return False
        lo, hi = _resolves(REVERSE, z, n, far)
        with np.errstate(all="ignore"):
            said = [v for v in reading(z, n, far) if math.isfinite(v) and v > 0]
        return not lo <= dz <= hi and any(abs(dz - v) <= 0.01 * v for v in said)

    return fits


def _coarse(args, got) -> bool:
    """Is the Δz of the answer 2^-23 of z (1 − z/f), the coarser of :func:`_finest`'s two?"""
    fine, coarse = _finest(args[0], args[2])
    return abs(got[2] - coarse) < abs(got[2] - fine)


def _step_at_one(z, n, far):
    """Δz with float32's step at depth 1, np.spacing(np.float32(1)) = 2^-23, for the one at d
    (2^-24, the step below 1, is unorm24's Δz within 1 %: "the other buffer's")."""
    return [2.0**-23 / reverse_slope(z, n, far)]


def _swapped(z, n, far):
    """5.2's Δz called as reverse_z_gap(near, z, far)."""
    try:
        return list(gap_bounds(n, z, far)) + [expected_gap(n, z, far)]
    except (ValueError, ZeroDivisionError, FloatingPointError):
        return []


def _far_near_swapped(args, expected, got) -> bool:
    """r458 G4: Δz from reverse_z_gap(z, far, near), near and far swapped: d lies near 1 and
    its slope is negative, so Δz comes out negative (or, with abs, far too coarse); it was told
    only "not what your set-up resolves"."""
    z, _, far, _ = args
    fmt, n, dz = got
    if fmt not in (REVERSE, NEITHER) or expected[0] == UNORM or not 0 < n < z:
        return False
    with np.errstate(all="ignore"):
        k = 1 - far / n
        swapped = float(np.spacing(np.float32((far / z - far / n) / k))) * k * z * z / far
    # negative only: its size is about unorm24's Δz (float32's step near 1 is 2^-24), which
    # a positive one quotes ("the other buffer's")
    return math.isfinite(swapped) and dz < 0 and abs(dz - swapped) <= 0.01 * abs(swapped)


def _reverse_too_close(args, expected, got) -> bool:
    """reverse-Z's near plane so close that d falls to float32's subnormals (or 0): its Δz
    is no longer a fixed share of z (1 − z/f) and exceeds the gap (r351: n = 1e-45 z)."""
    z, gap, far, nearest = args
    n = got[1]
    if not (got[0] == expected[0] == REVERSE and 0 < n < z and not _beyond(args, got)):
        return False
    return _reverse_finest(z, n, far) > gap


def _words_reverse_too_close(args, expected, got) -> str:
    z, gap, far, nearest = args
    n = got[1]
    d = (n / z - n / far) / (1 - n / far)
    return (f": at your near plane {num(n)} reverse-Z stores d = {d:.3g} for z, "
            # "float32" would read as blaming the student's arithmetic (see FORWARD's note)
            f"{'stored as 0' if np.float32(d) == 0 else 'stored below 2^-126, as a subnormal'}, "
            "where the buffer's steps no longer shrink with d: it resolves Δz = "
            f"{num(_reverse_finest(z, n, far))} at z, more than the gap {num(gap)}. Your choice is "
            "right; its near plane does not do the job")  # fmt: skip


def _words_unorm_too_close(args, expected, got) -> str:
    """Each number with the digits that tell it from the one it is compared with (r351 item 3:
    a near plane just short of 5.1's printed alike)."""
    z, gap, far, _ = args
    n, need = got[1], expected_near(z, gap, far, 24)
    dz = num(resolution(z, n, far, 24), gap) if 0 < n < z else "—"
    return (f": at your near plane {num(n, need)} unorm24 resolves Δz = {dz}, more than the "
            f"gap {num(gap)}: it needs n ≥ {num(need, n)} (5.1)")  # fmt: skip


def _choice_by(n_of):
    """The answer, format only (numbers :func:`match_setup` leaves open), of a student whose
    unorm24 test compares ``n_of(z, gap, far, nearest)`` with ``nearest`` (True: unorm24)."""

    def gives(z, gap, far, nearest):
        if n_of(z, gap, far, nearest):
            return UNORM, None, None
        return (REVERSE if expected_gap(z, nearest, far) <= gap else NEITHER), None, None

    return gives


def _words_flipped(args, expected, got) -> str:
    z, gap, far, nearest = args
    n_u = expected_near(z, gap, far, 24)
    where = "beyond" if n_u > nearest else "within"
    return (f": your comparison of 5.1's near plane with `nearest` is flipped: here 5.1's n = "
            f"{num(n_u, nearest)} lies {where} `nearest` = {num(nearest, n_u)}, and you chose "
            f'"{got[0]}". On every case you choose unorm24 where its near plane lies beyond '
            "`nearest`, and reverse-Z (or \"neither\") where it does not")  # fmt: skip


def _words_16(args, expected, got) -> str:
    z, gap, far, nearest = args
    n16, n24 = expected_near(z, gap, far, 16), expected_near(z, gap, far, 24)
    return (f": your choices follow 5.1's near plane for 16 bits, n = {num(n16, n24)} here "
            f"(`nearest` = {num(nearest)}): this scene's unorm24 has 24 bits, and 5.1 gives "
            f"n = {num(n24, n16)} for them")  # fmt: skip


def _unorm32(args, expected, got) -> bool:
    """r514 H (ds_Y1): unorm24 taken as 32 bits, its declared size with the stencil: its Δz
    one 32-bit step over the slope (1 %; a choice by 1 % slack was named so by the choice)."""
    z, gap, far, nearest = args
    if got[0] != UNORM or not 0 < got[1] < z:
        return False
    return abs(got[2] / resolution(z, got[1], far, 32) - 1) <= SLACK


def _words_32(args, expected, got) -> str:
    z, gap, far, nearest = args
    return (": you took unorm24 as 32 bits, D24_UNORM_S8_UINT's declared size: 24 of them "
            "hold depth, 8 the stencil, so one step is 1/(2^24 − 1). At your near plane "
            f"{num(got[1])} unorm24 resolves Δz = {num(resolution(z, got[1], far, 24))} at z, "
            f"and it needs n ≥ {num(expected_near(z, gap, far, 24))} (5.1 with 24 bits)")  # fmt: skip


def _unorm_no_far(args, expected, got) -> bool:
    """r514 H (ds_Y8): unorm24's Δz as step z²/n, the factor (f − n)/f dropped (0.1 %)."""
    z, gap, far, nearest = args
    if not got[0] == expected[0] == UNORM or not 0 < got[1] < z:
        return False
    return any(abs(got[2] / (z * z / (k * got[1])) - 1) <= 1e-3 for k in (2**24, 2**24 - 1))


def _reverse_first(z, gap, far, nearest):
    """The format (numbers left open) of a student who takes reverse-Z wherever it resolves
    the gap, and unorm24 only where it does not (r417 F2)."""
    if expected_gap(z, nearest, far) <= gap:
        return REVERSE, None, None
    return (UNORM if expected_near(z, gap, far, 24) <= nearest else NEITHER), None, None


def _words_reverse_first(args, expected, got) -> str:
    z, gap, far, nearest = args
    return (f": you chose reverse-Z where it resolves the gap, but unorm24 does it here too, "
            f"with any near plane from {num(expected_near(z, gap, far, 24))} (5.1) to "
            f"`nearest` = {num(nearest)}. Of two set-ups that both keep the surfaces apart the "
            "task takes the smaller format: with the stencil, unorm24's is nominally 32 bits a "
            "pixel, reverse-Z's 64. Ask 5.1's near plane first; reverse-Z only where it lies "
            "beyond `nearest`")  # fmt: skip


def match_setup(got, value, args=None) -> bool:
    """Does the student's answer equal what a mistake gives? Numbers the mistake leaves open
    (None: a choice alone, :func:`_choice_by`) match any."""
    if got is None or value is None:
        return got is None and value is None
    return all(v is None or near(g, v) for g, v in zip(got, value, strict=True))


MISTAKES = [
    # r381 F3: (format, dz, near) was told "at your near plane 0.000298 unorm24 resolves …"
    Mistake("near and dz swapped", lambda a, e, g: (
        f": your near plane and Δz look swapped: return (format, near, dz). Your second value "
        f"{num(g[1])} is the Δz, your third, {num(g[2])}, the near plane"),
        fits=_swapped_near),
    # r374 F4: each told "Compare 5.1's near plane with `nearest` first", which they did
    Mistake("comparison flipped", _words_flipped, gives=_choice_by(
        lambda z, gap, far, nearest: expected_near(z, gap, far, 24) > nearest)),
    # r417 F2: reverse-Z whenever it works was told "16 bits" (the same tuples on the cases
    # where unorm24 does it with room): the task's size rule ignored, named before
    Mistake("reverse-Z preferred", _words_reverse_first, gives=_reverse_first),
    Mistake("32 bits", _words_32, fits=_unorm32),
    Mistake("16 bits", _words_16, gives=_choice_by(
        lambda z, gap, far, nearest: expected_near(z, gap, far, 16) <= nearest)),
    Mistake("float32 forward", ": float32 without reverse-Z stores z_win, near 1 for far "
            "surfaces, where float32's step is 2^-24, no finer than unorm24's 1/(2^24 − 1): it "
            "buys nothing there. Reverse-Z stores d = 1 − z_win, near 0 for far surfaces, where "
            "float32's steps are tiny (lesson 05b, §4)",
            fits=lambda a, e, g: g[0] == FORWARD),
    Mistake("reverse-Z step at 1", lambda a, e, g: (
        f": your Δz {num(g[2])} is float32's step at depth 1 over the slope: reverse-Z stores "
        f"d ≈ {(g[1] / a[0] - g[1] / a[2]) / (1 - g[1] / a[2]):.3g} for z, where float32's "
        "step is far finer (np.spacing(np.float32(d)), 5.2): with it, reverse-Z resolves Δz = "
        f"{num(expected_gap(a[0], g[1], a[2]))}"), fits=_reverse_dz_as(_step_at_one)),
    Mistake("reverse_z_gap swapped", lambda a, e, g: (
        f": your Δz {num(g[2])} is reverse_z_gap(near, z, far), its first two arguments "
        "swapped: call reverse_z_gap(z, near, far), which gives "
        f"{num(expected_gap(a[0], g[1], a[2]))} at your near plane"),
        fits=_reverse_dz_as(_swapped)),
    Mistake("reverse_z_gap near and far swapped", lambda a, e, g: (
        f": your Δz {num(g[2])} is reverse_z_gap(z, far, near), near and far swapped (d then "
        "lies near 1, and its slope is negative): call reverse_z_gap(z, near, far), which gives "
        f"{num(expected_gap(a[0], g[1], a[2]))} at your near plane"),
        fits=_far_near_swapped),
    # r374 F5: the bound the words quote, taken for Δz, was told only "not what it resolves"
    Mistake("reverse-Z coarse bound", lambda a, e, g: (
        f": your Δz {num(g[2])} is a bound, {'2^-23' if _coarse(a, g) else '2^-24'} of "
        "z (1 − z/f), which holds whatever the near plane: the step at the stored d itself over "
        "|dd/dz| (5.2) lies between 2^-24 and 2^-23 of it, and with it "
        f"reverse-Z resolves Δz = {num(expected_gap(a[0], g[1], a[2]))} at your near plane"),
        fits=_reverse_dz_as(lambda z, n, far: list(_finest(z, far)))),
    Mistake("beyond nearest", _words_beyond, fits=_fits(UNORM, (REVERSE, NEITHER), _beyond)),
    Mistake("unorm24 too coarse", _words_too_coarse, fits=_fits(UNORM, (REVERSE, NEITHER))),
    Mistake("unorm24 preferred", _words_unorm_does, fits=_fits(REVERSE, (UNORM,))),
    Mistake("neither, unorm24 does", _words_unorm_does, fits=_fits(NEITHER, (UNORM,))),
    Mistake("neither, reverse-Z does", _words_reverse_does, fits=_fits(NEITHER, (REVERSE,))),
    Mistake("reverse-Z too coarse", _words_reverse_short, fits=_fits(REVERSE, (NEITHER,))),
    Mistake("reverse-Z near beyond nearest", lambda a, e, g: (
        f": {_yours_beyond(a, g)}: it clips geometry "
        "the scene shows, and buys reverse-Z nothing (its Δz hardly depends on n)"),
        fits=lambda a, e, g: g[0] == e[0] != UNORM and _beyond(a, g)),
    Mistake("unorm24 near beyond nearest", lambda a, e, g: (
        f": {_yours_beyond(a, g)}: it clips geometry the scene shows. unorm24 is right, at "
        f"any near plane from {num(expected_near(*a[:3], 24))} (5.1) to `nearest` itself"),
        fits=lambda a, e, g: g[0] == e[0] == UNORM and _beyond(a, g)),
    Mistake("reverse-Z near too close", _words_reverse_too_close, fits=_reverse_too_close),
    Mistake("unorm24 near too close", _words_unorm_too_close,
        fits=lambda a, e, g: g[0] == e[0] == UNORM and 0 < g[1] <= a[3]
        and not _near_ok(a, UNORM, g[1])),
    Mistake("unorm24 Δz without the far plane", lambda a, e, g: (
        f": your Δz {num(g[2])} is step · z²/n, the far plane's factor (f − n)/f left out "
        "(right for an infinite far plane only): unorm24 resolves step (f − n) z²/(f n), "
        f"{num(resolution(a[0], g[1], a[2], 24), g[2])} at your near plane here"),
        fits=_unorm_no_far),
    Mistake("dz of the other buffer", _dz_words("that Δz is the other buffer's"),
            fits=lambda a, e, g: _dz_wrong(a, e, g) and _quoted_other(a, g)),
    Mistake("dz is the gap", _dz_words(_gap_words),
            fits=lambda a, e, g: _dz_wrong(a, e, g) and _gap_quoted(a, g)),
    Mistake("dz", _dz_words("your Δz is not what your set-up resolves there"), fits=_dz_wrong,
            symptom=True),
]  # fmt: skip


def draw_setup(ax, case, got):
    """Δz at z against the near plane (log-log) for unorm24 and float32 reverse-Z, the gap,
    ``nearest`` (beyond it, shaded: not allowed), and the student's (near, Δz)."""
    _, (z, gap, far, nearest), expected = case
    lo, hi = nearest / 1000, nearest * 100
    if got is not None and isinstance(got, tuple) and 0 < got[1] < z:  # yours in view
        lo, hi = min(lo, got[1] / 3), max(hi, got[1] * 3)
    hi = min(hi, z * 0.9)
    ns = np.geomspace(lo, hi, 200)
    artists = ax.loglog(ns, [resolution(z, n, far, 24) for n in ns], color="black",
                        label="unorm24")  # fmt: skip
    artists += ax.loglog(ns, [expected_gap(z, n, far) for n in ns], color="#2b7bba",
                         label="reverse-Z (float32)")  # fmt: skip
    artists.append(ax.axhline(gap, color="#888888", linestyle=":", label=f"gap {num(gap)}"))
    artists.append(ax.axvspan(nearest, hi, color="#eeeeee", lw=0, zorder=0,
                              label=f"beyond nearest = {num(nearest)}: clips the scene"))  # fmt: skip
    if got is not None and isinstance(got, tuple) and lo <= got[1] <= hi and got[2] > 0:
        ok = same_setup(got, expected, (z, gap, far, nearest))
        artists += ax.plot([got[1]], [got[2]], "x", color="#7fbf7f" if ok else "#d7301f",
                           ms=11, mew=2.5, label=f'yours: "{got[0]}", n {num(got[1])}, '
                           f"Δz {num(got[2])}")  # fmt: skip
    elif got is not None and isinstance(got, tuple):
        artists += ax.plot([], [], " ", label=f'yours: "{got[0]}", n {num(got[1])}: off this plot')
    ax.set_xlim(lo, hi)
    ax.set_xlabel(f"near plane n (z = {num(z)}, far = {num(far)})")
    # short: the long label reached the failure's two-line title (r351 item 7)
    ax.set_ylabel("Δz resolved at z")
    # under the axes, as 5.3's: beside them, "yours" made the figure wider than a notebook column
    artists.append(ax.legend(fontsize="x-small", loc="upper center", bbox_to_anchor=(0.5, -0.2)))
    return artists


#: The verdict, held back until two different answers have failed (:mod:`.tries`): the numbers
#: before it are the evidence, and comparing them is the task.
HINTS = ((re.compile(r', so the answer is "[^"]+"'), ""),)

DEPTH_SETUP = Exercise(
    "depth_setup", setup_cases, as_setup, same_setup, explain_setup, _rule, MISTAKES,
    draw=draw_setup, answers=(
        PackageAnswer(expected_setup, words=CHECKER_WORDS),
        # r458 G2: unorm24's Δz from the package passed unflagged (5.1 and 5.2 flag it)
        PackageAnswer(depth_resolution, what="a buffer's Δz, what your own safe_near and "
                      "reverse_z_gap are there to work out"),
    ), example=2,
    match=match_setup,
    reference=("teachraster.exercises.near_plane", "teachraster.exercises.reverse_z"), hints=HINTS,
)  # fmt: skip
