"""Exercise ``reverse_z_worst`` (lesson 05b, §4): the coarsest depth of a range in float32
reverse-Z.

Review r381 F6 (r374 F9): 5.2's ``reverse_z_gap`` is lesson 05b's printed slope and one
``np.spacing``. Here the student uses it where the lesson gives no formula: the coarsest Δz
over every depth of a range [z_min, z_max], the gap the scene's surfaces need there. A unorm
buffer's Δz, step (f − n) z²/(f n), grows with z, so its worst depth is z_max; float32
reverse-Z's is a sawtooth: within a binade of d = (n/z − n/f)/(1 − n/f), [2^e, 2^(e+1)), the
step is fixed, 2^(e−23), and Δz = step / |dd/dz| grows like z²; where d falls below 2^e the
step halves. So the coarsest depth is z_max or the limit just nearer than a depth z_e where
the exact d = 2^e, whose Δz there is 2^(e−23) (1 − n/f) z_e²/n = 2^-23 z_e (1 − z_e/f) (d over its
slope is z (1 − z/f), largest at f/2). Evaluated at z_max alone it is up to 4 times too fine
on lesson 05b's planes (z from 100 to 900: the worst depth is 450.3, where d = 2^-13).

Expected answers: :func:`expected_worst`, the largest of z_max's Δz (its binade's step) and
each such edge's inside the range; :func:`brute_worst` (float32's step above d at 200,001
depths) lies within 2e-5 below it on every fixed case (tests). Δz is taken by the binade of
the *exact* d (r425 F1): d rounded to float32 still rounds up to 2^e a hair farther than z_e,
down to d = 2^e (1 − 2^-25) (:func:`rounded_edge`), where reverse_z_gap's Δz is 2^-24 (1 − z/f)
(relative) coarser: a search refined until it finds the jump lands there. An answer passes
from :data:`BELOW` under the limit to :data:`ABOVE` over it (float64's accuracy for the closed
form, with room: a uniform search falls short, a refined one lands on that rounded maximum,
3e-8 to 6e-8 over wherever z_e < f/2: r417 F1, r425 F1), or for an answer float32 holds
:data:`FLOAT32_STEPS` of its steps either way (its own rounding at each of a few operations,
wider than that difference: there the check cannot tell a search from the closed form).
"""

from __future__ import annotations

import copy
import dataclasses
import re
from functools import cache

import numpy as np

from ..pipeline.visibility.depth import depth_resolution, reversed_depth
from . import tries
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .near_plane import as_lone_number
from .package_answers import CHECKER_WORDS
from .report import NOTHING_DRAWN_FOR
from .reverse_z import MISTAKES as GAP_MISTAKES
from .reverse_z import gap_variants, gives_same_gap, reversed_depth_slope
from .running import WrongAnswerType
from .scalars import num

#: (z_min, z_max, near, far): lesson 05b's planes over most of the scene (the worst depth
#: 450.3, 4 times z_max's Δz; from z = 1, 416 times), short ranges whose last edge beats
#: z_max (1.2 to 1.9 times), a range past f/2 (its first edge is the worst: Δz falls there),
#: two whose worst is z_max itself (an edge 1.5 times finer inside the range, or none), and one
#: whose z_max stores d = 1/4 exactly (the coarsest is the binade's step above, from nearer depths).
SETTINGS = (
    (100.0, 900.0, 0.1, 1000.0), (200.0, 300.0, 0.1, 1000.0), (10.0, 30.0, 0.1, 1000.0),
    (2.0, 4.0, 1.0, 10.0), (500.0, 3000.0, 0.5, 1e4), (1.0, 999.0, 0.1, 1000.0),
    (600.0, 990.0, 0.1, 1000.0), (150.0, 290.0, 0.1, 1000.0), (120.0, 130.0, 0.1, 1000.0),
    (1.2, 1.6, 1.0, 2.0),
    # r414 F2: the worst crossing lies between any uniform grid's samples up to 10,001 (and a
    # geometric one's of 1,000), and the sample just nearer than it is > BELOW short; F4: at
    # the worst crossing of the last, d computed in float32 rounds to just under 2^-4
    (1.77, 24.7, 0.000138, 25.0), (406.0, 14200.0, 2.79, 15100.0), (258.0, 5340.0, 70.0, 5410.0),
    (300.0, 505.0, 40.8, 549.0),
    # r425 F2: z_min stores d = 1/4 exactly (z_min = 2.0 and d = 0.25 exactly in float64 too):
    # its own Δz, the binade above, is the coarsest; `z_min < z_e` skips it (39 % short)
    (2.0, 2.2, 1.0, 3.0),
)  # fmt: skip

#: How much coarser than a slip's Δz an answer may be and still be that slip (5.2's slips).
SLACK = 0.01
#: How much coarser than the coarsest Δz an answer may be (relative): float64's accuracy, with
#: room (r425 F1: at 1 %, a search refined onto the last depth whose float32 d rounds up to 2^e,
#: 2^-24 (1 − z_e/f) over, passed every case; at 1e-8 it fails wherever z_e < 0.83 f).
ABOVE = 1e-8
#: How much finer (relative). The answer is a closed form (a power of two times a few
#: products): float64 gives it to a few units of 2^-52, 1e-15. A search over sampled depths
#: falls short of the limit at a crossing z_e by about 2 δz/z_e, δz its spacing there (r417
#: F1: at 1e-4, 50,001 evenly spaced depths passed every case): at 1e-8 an even or geometric
#: search of 10^7 depths (numpy, about 0.1 s of CPU a case) fails most cases, and 4·10^7
#: already run past the check's 2 s of CPU a case (tests).
BELOW = 1e-8
#: A float32 answer holds the coarsest Δz only to its own rounding, 2^-24 relative per
#: operation: it may lie this many float32 steps under or over it (r425: the closed form computed
#: in float32 throughout, z_e's division, its square and the products each rounded, lay up to
#: 4.8 steps off over 20,000 drawn ranges, and 2.3 under on a fixed one; at 2 it failed a few
#: drawn cases in a hundred).
FLOAT32_STEPS = 8


def binade_step(d: float) -> float:
    """float32's step within d's binade [2^e, 2^(e+1)): 2^(e−23), the step above d.

    >>> binade_step(0.25) == 2.0**-25, binade_step(0.3) == 2.0**-25
    (True, True)
    """
    return float(2.0 ** (np.floor(np.log2(d)) - 23))


def edges(z_min: float, z_max: float, near: float, far: float) -> list[tuple[int, float]]:
    """(e, z_e) for each depth z_min ≤ z_e ≤ z_max where d = 2^e, farthest first (r414 F5:
    z_min on a crossing counts: the task takes the binade above a stored 2^e)."""
    span = 1 - near / far
    top = int(np.floor(np.log2(float(reversed_depth(z_min, near, far)))))
    low = int(np.ceil(np.log2(float(reversed_depth(z_max, near, far)))))
    out = []
    for e in range(low, top + 1):
        z_e = near / (2.0**e * span + near / far)
        if z_min * (1 - 1e-12) <= z_e <= z_max * (1 + 1e-12):
            out.append((e, min(max(z_e, z_min), z_max)))
    return out


def candidates(z_min, z_max, near, far, edge_step: int = -23) -> list[tuple[float, float]]:
    """(z, Δz) at z_max (its binade's step) and at each edge z_e (2^(e + ``edge_step``): the
    step above d = 2^e, or with ``edge_step`` = −24 the one below)."""
    slope = lambda z: reversed_depth_slope(z, near, far)  # noqa: E731
    d_max = float(reversed_depth(z_max, near, far))
    out = [(z_max, binade_step(d_max) / slope(z_max))]
    return out + [(z, 2.0 ** (e + edge_step) / slope(z)) for e, z in edges(z_min, z_max, near, far)]


def worst(z_min, z_max, near, far) -> tuple[float, float]:
    """(z, Δz) of the coarsest depth of the range (the limit just nearer than z at an edge)."""
    return max(candidates(z_min, z_max, near, far), key=lambda c: c[1])


def expected_worst(z_min: float, z_max: float, near: float, far: float) -> float:
    """The coarsest Δz of float32 reverse-Z over [z_min, z_max]."""
    return worst(z_min, z_max, near, far)[1]


def brute_worst(z_min, z_max, near, far, count: int = 200_001) -> float:
    """The largest step-above over the slope at ``count`` depths (a check of
    :func:`expected_worst`, never its source)."""
    z = np.linspace(z_min, z_max, count)
    d = reversed_depth(z, near, far).astype(np.float32)
    return float((np.abs(np.spacing(d)).astype(float) / reversed_depth_slope(z, near, far)).max())


def _label(z_min, z_max, near, far) -> str:
    """Short: the figure's title holds it on one line (r404 F4: it wrapped at "far =")."""
    return f"z {num(z_min)} to {num(z_max)}, near {num(near)}, far {num(far)}"


@cache
def _fixed():
    return [(_label(*s), s, expected_worst(*s)) for s in SETTINGS]


def worst_cases():
    """The fixed cases (built once, copied) and :data:`DRAWN` drawn for this check, each with
    its worst depth inside the range, at least 10 % coarser than z_max's."""
    out, rng = copy.deepcopy(_fixed()), drawn_rng()
    for k in range(DRAWN):
        s = _drawn(rng)
        out.append((f"drawn for this check {k + 1}: {_label(*s)}", s, expected_worst(*s)))
    return out


def _drawn(rng) -> tuple[float, float, float, float]:
    """(z_min, z_max, near, far), three significant digits."""
    while True:
        far = float(f"{10 ** rng.uniform(1, 5):.3g}")
        near = float(f"{far * 10 ** rng.uniform(-6, -2):.3g}")
        z_max = float(f"{far * rng.uniform(0.1, 0.95):.3g}")
        z_min = float(f"{z_max * rng.uniform(0.05, 0.8):.3g}")
        s = (z_min, z_max, near, far)
        if z_min > 2 * near and worst(*s)[1] > 1.1 * candidates(*s)[0][1]:
            return s


def as_gap(value):
    """One number, as :func:`.near_plane.as_lone_number` (r414 F7: an array of shape (1,)
    passed, where the docs promise shapes must match; r442 F1: a list of one), and several
    numbers named as such."""
    if (
        isinstance(value, (tuple, list))
        and len(value) != 1
        and all(
            isinstance(v, (int, float, np.floating, np.integer)) and not isinstance(v, bool)
            for v in value
        )
    ):  # r417 F8: (900.0, 7.366170393652282e-06) was echoed with 17 digits
        raise WrongAnswerType(
            f"returned ({', '.join(num(v) for v in value)}), {len(value)} values where one "
            "number is expected: return the Δz alone"
        )
    return as_lone_number(value)


def _float32_held(got) -> bool:
    """A float32 answer, or one made float (``float(step / slope)`` with a float32 step
    divides in float32, and is right)."""
    with np.errstate(over="ignore"):  # a huge answer: no float32 holds it
        held = got is not None and np.isfinite(got) and float(np.float32(got)) == float(got)
    return bool(getattr(got, "dtype", None) == np.float32 or held)


def lowest(expected, got=None) -> float:
    """The smallest answer accepted: :data:`BELOW` under the coarsest Δz, or for an answer
    float32 holds (:func:`_float32_held`) :data:`FLOAT32_STEPS` of float32's steps there (its
    rounding, no more)."""
    low = expected * (1 - BELOW)
    if _float32_held(got):
        low = min(low, expected - FLOAT32_STEPS * float(np.spacing(np.float32(expected))))
    return low


def highest(expected, got=None) -> float:
    """The largest answer accepted: :data:`ABOVE` over the coarsest Δz, or for an answer
    float32 holds :data:`FLOAT32_STEPS` of float32's steps over it."""
    high = expected * (1 + ABOVE)
    if _float32_held(got):
        high = max(high, expected + FLOAT32_STEPS * float(np.spacing(np.float32(expected))))
    return high


def same_worst(got, expected, args=None) -> bool:
    """From :func:`lowest` to :func:`highest`."""
    if not np.isfinite(got):
        return False
    # as float64 (an np.float32 compared with a Python float is compared in float32)
    return lowest(expected, got) <= float(got) <= highest(expected, got)


def rounded_edge(z_min, z_max, near, far) -> tuple[float, float] | None:
    """(z_b, Δz) at the farthest depth whose d, rounded to float32, is still the worst
    crossing's 2^e: d = 2^e (1 − 2^-25) (a tie rounds to the even 2^e), where reverse_z_gap
    gives the largest Δz of the range (r425 F1); None where the worst is z_max."""
    z_w = worst(z_min, z_max, near, far)[0]
    if z_w == z_max:
        return None
    e = int(np.round(np.log2(float(reversed_depth(z_w, near, far)))))
    span = 1 - near / far
    z_b = min(near / (2.0**e * (1 - 2.0**-25) * span + near / far), z_max)
    return z_b, 2.0 ** (e - 23) / reversed_depth_slope(z_b, near, far)


def _variants(z_min, z_max, near, far) -> dict[str, float]:
    """The Δz typical readings give (each one change)."""
    cands = candidates(z_min, z_max, near, far)
    below = candidates(z_min, z_max, near, far, edge_step=-24)
    slope = lambda z: reversed_depth_slope(z, near, far)  # noqa: E731
    d_min = float(reversed_depth(z_min, near, far))
    at_min = binade_step(d_min) / slope(z_min)
    # the finest: just farther than an edge (its step below) or at z_min
    finest = min([at_min] + [dz for _, dz in below[1:]])
    peak = min(max(far / 2, z_min), z_max)
    out = {}
    # r425 F2: a crossing on z_min skipped (`z_min < z_e`): the answer itself where z_min is
    # none, so it fits (and is whole) only where a crossing on z_min was the coarsest
    out["z_min's crossing skipped"] = max(dz for z, dz in cands if z != z_min or z == z_max)
    return out | {
        # r417 F3: the right candidates, the finest of them taken (before z_max's: the same
        # answer wherever z_max's is the finest)
        "finest candidate": min(dz for _, dz in cands),
        # r442 F3: the candidates averaged
        "mean of candidates": float(np.mean([dz for _, dz in cands])),
        "z_max only": cands[0][1],
        "twice z_max's": 2 * cands[0][1],
        "z_min only": at_min,
        "both ends": max(cands[0][1], at_min),
        "last edge": max(dz for _, dz in cands[:2]),
        "edges only": max((dz for _, dz in cands[1:]), default=0.0),
        "step below at edges": max(dz for _, dz in below),
        "twice the step at edges": max(
            dz * (1 if z == z_max and k == 0 else 2) for k, (z, dz) in enumerate(cands)
        ),
        "bound 2^-23": 2.0**-23 * peak * (1 - peak / far),
        # r425 F4: the parabola's peak f/2 whether in the range or not (after the clamped one:
        # where f/2 lies in the range they are the same answer)
        "bound 2^-23 unclamped": 2.0**-23 * far / 4,
        "bound 2^-24": 2.0**-24 * peak * (1 - peak / far),
        "bound at z_max": 2.0**-23 * z_max * (1 - z_max / far),
        "finest": finest,
        "worst z": worst(z_min, z_max, near, far)[0],
        # r417 F3, F5: z not squared at the crossings; z_min's step taken at z_max
        "crossings, z not squared": max([cands[0][1]] + [dz / z for z, dz in cands[1:]]),
        "z_min's step at z_max": binade_step(d_min) / slope(z_max),
        # r514 M1: the right crossings and steps over the slope n/z² (1 − n/f left out of the
        # slope alone): f/(f − n) times the coarsest, told "a margin added?"
        "slope without 1 - n/f": expected_worst(z_min, z_max, near, far) / (1 - near / far),
    }


def _crossing_slips(z_min, z_max, near, far) -> dict[str, float]:
    """r425 F3, F4: crossings of the wrong d. Without 1 − n/f (in d and in its slope: d' =
    n/z − n/f crosses 2^e at n/(2^e + n/f)), or at n/2^e (where n/z is a power of two, the
    slope n/z²), or (r442) at n/(2^e (1 − n/f)), the n/f term left out and the slope right;
    z_max's own Δz as reverse_z_gap gives it, as the student's code keeps it."""
    at_max = float(np.spacing(np.float32(reversed_depth(z_max, near, far)))) / (
        reversed_depth_slope(z_max, near, far)
    )
    out = {}
    for kind, cross, step_max in (
        (
            "1 - n/f dropped",
            lambda e: near / (2.0**e + near / far),
            float(np.spacing(np.float32(near / z_max - near / far))) * z_max**2 / near,
        ),
        ("crossings at n/2^e", lambda e: near / 2.0**e, at_max),
        # r442 F3: the crossing solved without the n/f term, the slope kept
        ("crossings without n/f", lambda e: near / (2.0**e * (1 - near / far)), at_max),
    ):
        # the slope n/z² where 1 − n/f is dropped (the first two), n/((1 − n/f) z²) kept
        keep = (1 - near / far) if kind == "crossings without n/f" else 1.0
        dzs = [step_max] + [2.0 ** (e - 23) * keep * cross(e) ** 2 / near for e in range(-150, 2)
                            if z_min <= cross(e) <= z_max]  # fmt: skip
        out[kind] = max(dzs)
    return out


#: Where the words say where the worst depth is, or how to find it (r404 F1: said in full at
#: once, they answered the task's prediction); said as a question until two answers failed.
WHERE = (". For float32 reverse-Z the worst step is at z = ", " inside the range")
WHERE_HINT = (". A unorm buffer resolves worst at z_max; does float32 reverse-Z? Look at how the "
              "step of d changes over the range: ask your reverse_z_gap at a few depths")  # fmt: skip


def _z_max_words(args, expected, got) -> str:
    """The transcribed formula at z_max (r381 F6): where the worst step really is (staged)."""
    z_w, dz = worst(*args)
    e = int(np.round(np.log2(float(reversed_depth(z_w, *args[2:])))))
    # r425 F3: or the crossings came out finer (float64's step there): hedged, the value alone
    return (f": that is z_max's own Δz on every case: you evaluated the gap at z_max only, or "
            "the depths you compared it with came out finer (float64's np.spacing at a crossing, "
            f"2^29 times finer than float32's step?){WHERE[0]}"
            f"{num(z_w)}, where d falls to 2^{e}: just nearer, d's binade has the step "
            f"2^{e - 23}, and Δz = {num(dz, got)} there. A unorm buffer's Δz grows with z, so "
            "its worst is z_max; float32's step halves wherever d falls below a power of two, "
            f"so compare z_max with each depth where that happens{WHERE[1]}")  # fmt: skip


_LATER = (", at z_max or just nearer than a depth where d falls below a power of two",
          ", but where? Look at how float32's step of d changes over the range")  # fmt: skip
_BETWEEN = ("Between them d crosses powers of two, and just nearer than each crossing the step "
            "is twice the step beyond it: one of those depths can be coarser than either end",
            "Is nothing between them coarser? Look at how float32's step of d changes between "
            "them")  # fmt: skip


def _dropped_words(args, expected, got) -> str:
    z_w = worst(*args)[0]
    where = (
        ""
        if z_w == args[1]
        else (
            f" (the coarsest crossing lies at z = {num(z_w)}, where d = "
            f"2^{int(np.round(np.log2(float(reversed_depth(z_w, *args[2:])))))})"
        )
    )
    return (": you dropped the factor 1 − n/f from d and from its slope: d = (n/z − n/f)/(1 − n/f)"
            " crosses 2^e at z = n/(2^e (1 − n/f) + n/f), not n/(2^e + n/f)" + where
            + ", and |dd/dz| = n/((1 − n/f) z²): keep the (1 − n/f) in both")  # fmt: skip


MISTAKES = {
    # r425 F2: first (z_max's own or another crossing's gives the same number there)
    "z_min's crossing skipped": lambda a, e, g: (
        f": z_min = {num(a[0])} lies on a crossing: d there is exactly 2^"
        f"{int(np.round(np.log2(float(reversed_depth(a[0], *a[2:])))))}, and yours is what the "
        "range gives without it. z_min stores d = 2^e exactly: its own Δz, the step of the "
        "binade above, 2^(e−23), over the slope, counts (z_min ≤ z_e, not z_min < z_e)"
    ),
}
#: r425 F3, F4: the crossings of the wrong d, said where an answer is that very number (1e-9:
#: with n/f ≪ 1 it lies within 1e-5 of the right one, where a search could fall by chance).
CROSSING_WORDS = {
    "1 - n/f dropped": _dropped_words,
    "crossings without n/f": ": you put d's crossings at z = n/(2^e (1 − n/f)), leaving out "
    "the n/f that d = (n/z − n/f)/(1 − n/f) subtracts: d is 2^e at z = n/(2^e (1 − n/f) + "
    "n/f), a little nearer",
    "crossings at n/2^e": ": you put d's crossings at z = n/2^e, where n/z is a power of two, "
    "and took the slope n/z²: that holds for an infinite far plane only. With this far plane d "
    "= (n/z − n/f)/(1 − n/f) is 2^e at z = n/(2^e (1 − n/f) + n/f), and |dd/dz| = n/((1 − n/f) "
    "z²)",
}
MISTAKES |= {
    "finest candidate": ": you compared the right depths, z_max and the limit just nearer "
    "than each depth where d crosses a power of two, but returned the finest of them: the "
    "task asks the coarsest, the gap surfaces need to be told apart at every depth of the range",
    "mean of candidates": ": you averaged the right candidates, z_max and the limit just "
    "nearer than each depth where d crosses a power of two: the task asks the coarsest of "
    "them, the gap surfaces need to be told apart at every depth of the range",
    "z_max only": _z_max_words,
    "twice z_max's": ": that is twice z_max's own Δz: doubling the gap at z_max guesses at "
    "the range. Where in the range can a coarser Δz than z_max's lie, and how much coarser?",
    "z_min only": ": you evaluated the gap at z_min only, the nearest depth: Δz grows with z "
    f"within each binade of d, so the coarsest lies farther{_LATER[0]}",
    "both ends": f": you compared the two ends of the range only. {_BETWEEN[0]}",
    "last edge": ": you compared z_max with the last depth before it where d crosses a power "
    "of two only. Every crossing inside the range is a candidate: their Δz, 2^-23 z (1 − z/f), "
    "is largest near f/2, not always nearest to z_max",
    "edges only": ": you compared the depths where d crosses a power of two only, and left "
    "z_max out: past the last crossing Δz keeps growing like z², so z_max can be the coarsest",
    "step below at edges": ": at each depth where d is exactly a power of two 2^e you took "
    "the step below it, 2^(e−24), the one towards farther depths (the stored 2^e's nearer "
    "neighbour, or np.spacing of d rounded down first). Just nearer than that depth d lies in the binade "
    "above, whose step is 2^(e−23): the coarsest Δz is that limit",
    "twice the step at edges": ": at each depth where d is exactly a power of two 2^e you "
    "took the step 2^(e−22), twice the binade's: d's binade [2^e, 2^(e+1)) steps by 2^(e−23), "
    "as np.spacing of 2^e says",
    "bound 2^-23": ": you took the bound 2^-23 z (1 − z/f) (d over its slope) at its largest "
    "in the range: it is reached only where d is a power of two, so the true worst is the "
    "largest over those depths and z_max, not over every z",
    "bound 2^-23 unclamped": ": you took the bound 2^-23 z (1 − z/f) at its peak over every "
    "z, z = f/2 (2^-23 f/4), not over this range's depths; and the bound is reached only where d is a "
    "power of two: the coarsest is the largest over those depths in the range and z_max",
    "bound 2^-24": ": you took 2^-24 z (1 − z/f), the finest bound of reverse-Z's Δz, "
    "not the coarsest over the range: just nearer than each depth where d is a power of two "
    "2^e the step is 2^(e−23), twice that",
    "bound at z_max": ": you took the bound 2^-23 z (1 − z/f) (d over its slope) at z_max: it "
    "is reached only where d is a power of two, and z_max's d need not be one. Which depths "
    "of the range are the candidates?",
    "finest": ": you returned the finest Δz of the range; the task asks the coarsest, the gap "
    "surfaces need to be told apart at every depth of it",
    "worst z": lambda a, e, g: (
        f": that is the depth where Δz is coarsest, {num(worst(*a)[0])}: return Δz itself there"
    ),
    "crossings, z not squared": ": at the depths where d crosses a power of two you took "
    "the step times z, not z²: d's slope |dd/dz| is n/((1 − n/f) z²), so Δz = step / slope "
    "= step (1 − n/f) z²/n",
    "slope without 1 - n/f": ": yours is f/(f − n) times the coarsest: your slope of d is "
    "n/z², the slope of n/z alone. With this far plane d = (n/z − n/f)/(1 − n/f) changes by "
    "|dd/dz| = n/((1 − n/f) z²), so Δz = step (1 − n/f) z²/n: keep the (1 − n/f)",
    "z_min's step at z_max": lambda a, e, g: (
        ": you took the step of d at z_min (its binade's, 2^"
        f"{int(np.floor(np.log2(float(reversed_depth(a[0], *a[2:]))))) - 23}) and divided it by "
        "the slope at z_max: each depth's Δz is the step of its own d over the slope there, "
        "and d at z_max lies binades below d at z_min, where the step is smaller"
    ),
}


def _edge_rounded_below(args, expected, got) -> bool:
    """The worst edge's Δz by the step below (d rounded to just under 2^e there), ±1 %, and
    only where that is what the case's answer would then be (r404 F2: z_max's own Δz, coarser
    than it on 200 to 300, was told "your d came out just under")."""
    z_w = worst(*args)[0]
    if not np.isfinite(got) or z_w == args[1]:
        return False
    below = [dz for z, dz in candidates(*args, edge_step=-24) if z == z_w][0]
    rest = [dz for z, dz in candidates(*args) if z != z_w]
    # r414 F4: or no other candidate's (d rounded under in float32 at every crossing)
    other = any(abs(got - dz) <= 1e-3 * dz for dz in rest)
    if below < max(rest):  # then exactly (2 × z_max's Δz, 0.3 % off, is no such d)
        return bool(not other and abs(got - below) <= 1e-6 * below)
    return bool(abs(got - below) <= 0.01 * below)


EDGE_BELOW = Mistake(
    "edge rounded below",
    lambda a, e, g: (
        f": at z = {num(worst(*a)[0])}, where d is 2^"
        f"{int(np.round(np.log2(float(reversed_depth(worst(*a)[0], *a[2:])))))}, the coarsest "
        "depth of this range, your step there was the one below, half the binade's: d came out "
        "just under that power of two (rounded there, or the depth taken a hair too far), or "
        "you took 2^(e−24) (2^-24 z (1 − z/f)) there. "
        "The coarsest Δz is the limit from nearer depths: take the binade's own step there, "
        "2^(e−23) for d = 2^e, rather than np.spacing of a d computed at that depth"
    ),
    fits=_edge_rounded_below,
)

# r417 F3: said only where it gives every answer (the finest candidate, or z not squared,
# gave z_max's own on one case and was told "you evaluated the gap at z_max only"): each of
# these gives z_max's own Δz on most cases, so any of them fits most answers that are
ONLY_WHOLE = ("finest candidate", "z_max only", "crossings, z not squared")

# r404 F3: a sampled minimum is the finest within a few samples' reach, not to 1e-6
FINEST_SAMPLED = Mistake(
    "finest, sampled", MISTAKES["finest"],
    fits=lambda a, e, g: bool(np.isfinite(g)) and abs(g / _variants(*a)["finest"] - 1) <= 0.01,
)  # fmt: skip

Z_MAX_HERE = Mistake(
    "z_max's own here",
    ": that is z_max's own Δz: on this case a depth inside the range, where d crosses a power "
    "of two, is coarser. Did you leave that crossing out (or skip it), return another of the "
    "candidates than the largest, or did d there come out just under the power of two "
    "(np.spacing then gives the step below, half the binade's)?",
    fits=lambda a, e, g: bool(np.isfinite(g)) and worst(*a)[0] != a[1]
    and abs(g - candidates(*a)[0][1]) <= 1e-3 * abs(g),
)  # fmt: skip


def _other_crossing(args, expected, got) -> tuple[float, int] | None:
    """(z, e) of a crossing inside the range, not the worst, whose limit Δz ``got`` is (±1e-6);
    None: none (r414: a worst crossing skipped, or its d rounded under in float32, left the
    next one's Δz, which was told "a search over sampled depths")."""
    if not np.isfinite(got):
        return None
    z_w = worst(*args)[0]
    for (z, dz), (e, _) in zip(candidates(*args)[1:], edges(*args)):
        if z != z_w and abs(got - dz) <= 1e-6 * dz:
            return z, e
    return None


OTHER_CROSSING = Mistake(
    "another crossing's",
    lambda a, e, g: (
        f": that is the Δz just nearer than z = {num(_other_crossing(a, e, g)[0])}, where d "
        f"falls to 2^{_other_crossing(a, e, g)[1]}: a crossing of this range, but not its "
        "coarsest; another depth where d crosses a power of two is coarser. Did your loop skip "
        "it, or did d there come out just under the power of two (np.spacing then gives the "
        "step below, half the binade's)?"
    ),
    fits=lambda a, e, g: _other_crossing(a, e, g) is not None,
)


def _outside_crossing(args, expected, got) -> tuple[float, int] | None:
    """(z, e) of a depth outside the range where d = 2^e whose limit Δz ``got`` is (±1e-6);
    None: none (r417 F5: crossings kept without the z_min ≤ z ≤ z_max test were told only
    the rule)."""
    z_min, z_max, near, far = args
    if not np.isfinite(got) or got <= 0:
        return None
    span = 1 - near / far
    top = int(np.floor(np.log2(float(reversed_depth(z_min, near, far)))))
    low = int(np.ceil(np.log2(float(reversed_depth(z_max, near, far)))))
    for e in range(low - 40, top + 41):
        z = near / (2.0**e * span + near / far)
        dz = 2.0 ** (e - 23) / reversed_depth_slope(z, near, far)
        if not z_min <= z <= z_max and abs(got - dz) <= 1e-6 * dz:
            return z, e
    return None


def _outside_words(args, expected, got) -> str:
    z, e = _outside_crossing(args, expected, got)
    return (f": your Δz is the limit just nearer than z = {num(z)}, where d falls to 2^{e}: "
            f"outside this range, {num(args[0])} to {num(args[1])}. Only the depths where d "
            "crosses a power of two inside the range (z_min ≤ z ≤ z_max) are candidates, "
            "beside z_max itself")  # fmt: skip


OUTSIDE = Mistake("crossing outside the range", _outside_words,
                  fits=lambda a, e, g: _outside_crossing(a, e, g) is not None)  # fmt: skip


def _too_fine(args, expected, got) -> bool:
    """A search over depths that missed the edge: finer than the coarsest, coarser than z_max,
    and the depth whose limit Δz that is (Δz grows like z² in the worst depth's binade) lies
    within 5 % of the range nearer than the worst depth, as a search of 20 or more samples
    stops (r404 F2: half the coarsest was told "a search that stopped short")."""
    at_max = candidates(*args)[0][1]
    # r417: closer than 1e-6 a search and a number rounded on the way look alike (HAIR_SHORT)
    if not (np.isfinite(got) and at_max < got < min(lowest(expected, got), expected * (1 - 1e-6))):
        return False
    if _other_crossing(args, expected, got) is not None:
        return False  # another crossing's limit exactly: a skipped crossing, not a search
    z_w = worst(*args)[0]
    z_s = z_w * np.sqrt(got / expected)
    return bool(z_s > args[0] and z_w - z_s <= 0.05 * (args[1] - args[0]))


def _search_words(args, expected, got) -> str:
    """r414 F2: where the coarsest step lies, and the depth the student's samples reached;
    r417 F1: how far short, against what the check allows."""
    z_w = worst(*args)[0]
    e = int(np.round(np.log2(float(reversed_depth(z_w, *args[2:])))))
    z_s = z_w * np.sqrt(got / expected)
    return (f": your Δz lies between z_max's and the coarsest, {_short(1 - got / expected)} "
            "short of it: a search over sampled depths? The coarsest step lies just nearer "
            f"than z = {num(z_w)}, where d falls to 2^{e}; your samples stopped at about z = "
            f"{num(z_s, z_w)} in that binade (Δz grows like z² there; with no samples, that "
            "is where the depth you took lay, a hair nearer than the crossing). A search falls short "
            "by about twice its spacing over z, and the check allows "
            f"{_short(BELOW)}; one refined until it finds the jump lands a hair over it (the "
            "stored d rounds up to the power of two a little farther), which fails too. Δz jumps there (the step halves), so the coarsest is the limit just nearer "
            "than it: compute it at each such depth rather than sample")  # fmt: skip


def _short(share: float) -> str:
    """A relative shortfall in words: 3e-08 (a power of ten written out: 1e-08)."""
    return f"{share:.1g}" if share >= 1e-4 else f"{share:.1e}".replace(".0e", "e")


def _hair_short(args, expected, got) -> bool:
    """Under the band by less than 1e-5, and no search's shortfall (r417 F1: at 1e-8, inputs
    rounded to float32 on the way, 3e-8 short, were told the rule's "where can it lie?")."""
    return bool(np.isfinite(got) and 0 < 1 - got / expected <= 1e-5
                and got < lowest(expected, got) and not _too_fine(args, expected, got))  # fmt: skip


def _hair_words(args, expected, got) -> str:
    z_w = worst(*args)[0]
    where = "at z_max itself"
    if z_w != args[1]:
        e = int(np.round(np.log2(float(reversed_depth(z_w, *args[2:])))))
        where = f"just nearer than z = {num(z_w)}, where d falls to 2^{e}"
    return (f": yours is {_short(1 - got / expected)} short of the coarsest ({where}), where "
            f"the check allows {_short(BELOW)}: the closed form, a power of two times a few "
            "products, comes out within 1e-15 in float64. A search over sampled depths (it "
            "falls short by about twice its spacing over z), a depth taken a hair off, or a "
            "number rounded on the way "
            "(an input or a depth kept in fewer bits than float64's)?")  # fmt: skip


def _over(args, expected, got) -> bool:
    """Over the band by less than 2 % (beyond it :data:`RATIO` says the factor)."""
    return bool(np.isfinite(got) and highest(expected, got) < got <= expected * 1.02)


def _at_rounded_edge(args, expected, got) -> bool:
    """Between the limit and reverse_z_gap's largest at :func:`rounded_edge` (a hair over it):
    a search refined onto the jump of float32's rounded d (r425 F1)."""
    edge = rounded_edge(*args)
    return edge is not None and got <= edge[1] * (1 + 1e-9)


def _over_words(args, expected, got) -> str:
    share = _short(got / expected - 1)
    if not _at_rounded_edge(args, expected, got):
        # r442 F2: a depth held in float32 on the way lands a few of its roundings over
        over = got / expected - 1
        why = ("A number rounded on the way (a depth or an input kept in float32, whose "
               "rounding, 6e-8 of it, moves Δz by up to twice that through z²), or a margin "
               "added?" if over <= 1e-6 else
               "A number rounded on the way (an input or a depth kept in fewer bits than "
               "float64's), or a margin added?" if over <= 1e-5 else
               "Did you round it up, or add a margin?")  # fmt: skip
        return (f": yours is {share} over the coarsest, where the check allows {_short(ABOVE)}: "
                "a gap rounded up is still resolved, but the task asks the coarsest Δz itself, "
                f"a closed form float64 gives to about 1e-15. {why}")  # fmt: skip
    z_w, (z_b, dz_b) = worst(*args)[0], rounded_edge(*args)
    e = int(np.round(np.log2(float(reversed_depth(z_w, *args[2:])))))
    return (f": yours is {share} over the coarsest, where the check allows {_short(ABOVE)}: "
            f"it lies between the limit just nearer than z = {num(z_w, z_b)}, where the exact d "
            f"falls to 2^{e}, and {num(dz_b, expected)}, the Δz reverse_z_gap gives at z = "
            f"{num(z_b, z_w)}: down to there the stored d, rounded to the buffer's format, "
            f"still rounds up to 2^{e} (the binade above keeps its step while the slope "
            "falls). A search refined until "
            "it finds the jump lands there. The task takes Δz by the binade of the exact d, "
            "whose largest is that limit: compute it at each such depth, and sample only to "
            "explore")  # fmt: skip


CROSSING_SLIPS = tuple(
    Mistake(kind, words, fits=lambda a, e, g, kind=kind: bool(
        np.isfinite(g) and abs(g / _crossing_slips(*a)[kind] - 1) <= 1e-9))
    for kind, words in CROSSING_WORDS.items()
)  # fmt: skip


def _searched_over(args, expected, got) -> bool:
    """Over the band, onto the jump of float32's rounded d: a refined search (r425 F1)."""
    return _over(args, expected, got) and _at_rounded_edge(args, expected, got)


def _margin_words(args, expected, got) -> str:
    return (f": yours is the coarsest times {got / expected:.9g}, {_short(got / expected - 1)} "
            "over it on every failing case, where the check allows "
            f"{_short(ABOVE)}: a margin added? A gap rounded up is still resolved, but the task "
            "asks the coarsest Δz itself, a closed form float64 gives to about 1e-15")  # fmt: skip


# r514 (r458 w_X6): one factor a hair over 1 on every failing case, a margin (its first case
# was told the rule alone: OVER, a symptom, lost to the rule there); float32's rounding on the
# way lands a different share over on each case, so it does not fit
MARGIN = Mistake("margin", _margin_words, parameter=lambda a, e, g: g / e - 1,
                 fits=lambda a, e, g: None if same_worst(g, e, a)
                 else _over(a, e, g) and not _at_rounded_edge(a, e, g))  # fmt: skip

# r425 F1: over the band by a margin (a search that found the jump is SEARCH's)
OVER = Mistake("over the coarsest", _over_words, symptom=True,
               fits=lambda a, e, g: _over(a, e, g) and not _at_rounded_edge(a, e, g))  # fmt: skip


def _search_case_words(args, expected, got) -> str:
    if _searched_over(args, expected, got):
        return _over_words(args, expected, got)
    return (_search_words if _too_fine(args, expected, got) else _hair_words)(args, expected, got)


# one kind (r417): a search short by less than 1e-6 gets the second words, by more the first;
# r425 F1: one refined onto the jump of float32's rounding lands over (a uniform one on some
# cases too), its own words
SEARCH = Mistake(
    "search missed the edge",
    _search_case_words,
    fits=lambda a, e, g: _too_fine(a, e, g) or _hair_short(a, e, g) or _searched_over(a, e, g),
    symptom=True,
)

#: r458: 5.2 is a ruler with no check cell of its own; the locked cell after 5.2b's checks it
RULER_CHECK = (". Check your reverse_z_gap alone first: the cell after this check runs 5.2's check "
               "(not graded)")  # fmt: skip

#: 5.2's slips that 5.2b can carry over (r404 F3): each changes Δz by far more than the band.
GAP_SLIPS = ("float64", "window depth", "float16", "step above 1", "step in depth",
             "times slope", "z not squared", "spacing of z", "infinite far",
             "infinite far, slope", "infinite far, depth", "near and far swapped")  # fmt: skip


def _depths(z_min, z_max, near, far) -> list[float]:
    """The ends, and a hair nearer than each depth where d or n/z (an infinite far plane's
    depth) is a power of two: where a slip's Δz is largest, as the right one's is."""
    out = [z_min, z_max] + [z * (1 - 1e-6) for _, z in edges(z_min, z_max, near, far)]
    low, top = int(np.floor(np.log2(near / z_max))), int(np.ceil(np.log2(near / z_min)))
    return out + [near / 2.0**e * (1 - 1e-6) for e in range(low, top + 1)
                  if z_min < near / 2.0**e * (1 - 1e-6) <= z_max]  # fmt: skip


#: How far under a slip's largest Δz an answer may fall and still be that slip: a search over
#: 2,001 or more samples of it falls this short at most (δz ≤ 2.41 z_e/2000, as for the answer).
SLIP_BELOW = 0.005


def gap_slips(args, got, expected=None) -> list[tuple[str, float]]:
    """Every (5.2's slip, what it gives) :func:`gap_slip` could name, nearest first: those
    giving the same number are each a cause (r417 F8: float16's step at d and float32's
    above 1 give the same Δz at z = 300 with near 0.1, far 1000)."""
    if not np.isfinite(got) or got == 0:
        return []

    # r425 F4: a negative slip's band was empty (near and far swapped), so sorted
    def near_to(x, dz):
        ends = (dz * (1 - SLIP_BELOW), dz * (1 + SLACK))
        return min(ends) <= x <= max(ends)

    found = {}
    for z in _depths(*args):
        for kind, dz in gap_variants(z, *args[2:]).items():
            if kind in GAP_SLIPS and np.isfinite(dz):
                found[kind] = max(found.get(kind, -np.inf), dz) if dz > 0 else min(
                    found.get(kind, np.inf), dz)  # fmt: skip
    # r425 F4: the slip at z_max alone (float64's step at z_max only: not the range's largest)
    at_max = {k: dz for k, dz in gap_variants(args[1], *args[2:]).items()
              if k in GAP_SLIPS and np.isfinite(dz)}  # fmt: skip
    near = [(round(abs(got / dz - 1), 3), GAP_SLIPS.index(kind), kind, dz)
            for table in (found, at_max) for kind, dz in table.items() if dz != 0]  # fmt: skip
    near = [n for n in near if near_to(got, n[3])]
    if expected is not None:
        near = [n for n in near if not near_to(n[3], expected)]
    out = []
    for n in sorted(near):
        if n[2] not in [k for k, _ in out]:  # a kind once, at its nearest
            out.append(n[2:])
    return out


def gap_slip(args, got, expected=None) -> tuple[str, float] | None:
    """(5.2's slip, what it gives) whose largest Δz over the range's depths is ``got`` within
    :data:`SLIP_BELOW` under and :data:`SLACK` over it, the nearest such (the first of
    :data:`GAP_SLIPS` among equals); None: none. A slip whose Δz lies that close to
    ``expected`` is never one (r414 F1: with n/f ≪ 1 "infinite far" gives the answer itself,
    and at 2 % every sampled search 1 % short was told "you dropped the far plane")."""
    slips = gap_slips(args, got, expected)
    return slips[0] if slips else None


def _gap_slip_words(args, expected, got) -> str:
    kind, dz = gap_slip(args, got, expected)
    words = GAP_MISTAKES[kind]
    same = [k for k, v in gap_slips(args, got, expected)[1:] if v == dz]
    if same:  # r417 F8: each slip that gives this very number, not the first alone
        return (
            f": yours, {num(got)}, is what {len(same) + 1} of 5.2's slips give at this range's "
            f"coarsest depths ({num(dz)}): {words}; or (the same number here) "
            + "; or ".join(GAP_MISTAKES[k] for k in same)
            + RULER_CHECK
        )
    return (
        f": yours, {num(got)}, is what one of 5.2's slips gives at this range's coarsest "
        f"depths ({num(dz)}): {words}" + RULER_CHECK
    )


# ``gives`` says nothing (None), but marks a cause the checker computes (5.2's own slips, run
# at the range's depths), so its words may name float64 or float16 (diagnosis's rule for them)
GAP_SLIP = Mistake("5.2's slip", _gap_slip_words, gives=lambda *a: None,
                   fits=lambda a, e, g: gap_slip(a, g, e) is not None)  # fmt: skip


def _ratio_words(args, expected, got) -> str:
    c = got / expected
    why = {0.5: " (exactly half: the step below d, 2^(e−24), where the binade's step is "
                "2^(e−23)? Or half of your reverse_z_gap?)",
           2.0: " (exactly twice: two steps, or a step twice the binade's, 2^(e−22) where d "
                "is in [2^e, 2^(e+1))?)"}  # fmt: skip
    said = next((w for k, w in why.items() if abs(c - k) <= 1e-3 * k), "")
    return f": your answer is {_times(c)} × the coarsest on every case{said}"


def _off_by_a_factor(args, expected, got) -> bool | None:
    """A factor ≠ 1 beyond a search's shortfall (2 %); None (nothing said) on a passing case,
    so a case whose answer is right does not hide a factor on every failing one (r414 F6)."""
    if same_worst(got, expected):
        return None
    return bool(np.isfinite(got) and got > 0 and abs(got / expected - 1) > 0.02)


RATIO = Mistake("constant ratio", _ratio_words, fits=_off_by_a_factor,
                parameter=lambda a, e, g: g / e, only_whole=True)  # fmt: skip


def _nan_without_crossing(args, expected, got) -> bool | None:
    """NaN on a range no crossing lies in (r442 F3: an answer started as NaN and set only by
    a crossing); None (no say) on a number."""
    if got is None or not np.isnan(got):
        return None
    return not edges(*args)


NAN_NO_CROSSING = Mistake(
    "NaN without a crossing",
    lambda a, e, g: (
        f": no depth from {num(a[0])} to {num(a[1])} has d at a power of two (d stays in one "
        "binade over the range), and yours is NaN here: did your answer start as NaN (or "
        "unset) and wait for a crossing to set it? Without one the coarsest is z_max's own Δz"
    ),
    fits=_nan_without_crossing,
)

RANGE = Mistake("range", ": a gap is a positive distance",
                fits=lambda a, e, g: bool(np.isfinite(g)) and g <= 0, symptom=True)  # fmt: skip


def explain_worst(args, expected, got) -> str:
    """The case, its coarsest Δz, the band the check accepts, and the student's."""
    lo, hi = lowest(expected, got), highest(expected, got)
    # r417 F4: each bound with the digits that tell it from the answer and from the coarsest
    head = (f"for z from {num(args[0])} to {num(args[1])} (near {num(args[2])}, far "
            f"{num(args[3])}) the coarsest Δz is {_apart(expected, got, lo, hi)} (the check "
            f"accepts {_apart(lo, got, expected, hi)} to {_apart(hi, got, expected, lo)}); "
            f"yours is {_apart(got, expected, lo)}")  # fmt: skip
    if not np.isfinite(got) or got <= 0 or same_worst(got, expected):
        return head
    # r404 F3: the ratio always, as 5.2's words give it (r417: a share where it is near 1)
    if abs(got / expected - 1) < 1e-4:
        return f"{head} ({_short(abs(got / expected - 1))} {'over' if got > hi else 'under'} it)"
    if got > hi:
        return f"{head} ({_times(got / expected)} times too coarse)"
    return f"{head} ({_times(expected / got)} times too fine)"


def _apart(x, *others) -> str:
    """``x`` with the digits that tell it from each of ``others`` (:func:`.scalars.num` tells
    it from one)."""
    texts = [num(x)] + [num(x, o) for o in others if o is not None and np.isfinite(o)]
    return max(texts, key=len)


def _times(r: float) -> str:
    """A ratio in 3 significant digits, a power of ten written out (no 17-digit echo)."""
    if r < 1.01:  # r414: "1 times too fine" for a search 0.05 % short
        return f"{r:.5g}"
    if r < 1000:
        return f"{r:.3g}"
    k = int(np.floor(np.log10(r)))
    return f"{r / 10**k:.2g} × 10^{k}"


def _rule(args, expected, got) -> str:
    return (". Within a binade of d the step is fixed and Δz grows like z²; it halves where "
            "d falls below a power of two: compare z_max with the limit just nearer than "
            "each such depth in the range")  # fmt: skip


def _unit(top: float) -> tuple[float, str]:
    """A power of ten to draw Δz in, and its name for the axis (r404 F4: no offset text)."""
    k = int(np.floor(np.log2(top) / np.log2(10))) if top > 0 and np.isfinite(top) else 0
    return 10.0**k, ("" if k == 0 else f" (× 1e{k})")


def draw_worst(ax, case, got):
    """Yours (a dashed line) and z_max's Δz (a dot); the sawtooth over the range, the coarsest
    depth and the band accepted only once the words give where it lies (the hints spent) or
    the answer passes (r404 F1: drawn after any wrong answer, they were the answer)."""
    _, (z_min, z_max, near, far), expected = case
    ok = got is not None and bool(np.isfinite(got)) and same_worst(got, expected)
    told = tries.hints_spent("reverse_z_worst") or ok
    drawn = got is not None and bool(np.isfinite(got)) and got > 0
    at_max = candidates(z_min, z_max, near, far)[0][1]
    top = max([at_max] + ([expected] if told else []) + ([got] if drawn else []))
    unit, named = _unit(top)
    artists = ax.plot([z_max], [at_max / unit], "s", color="#555555", ms=7, zorder=4,
                      label=f"z_max's own Δz {num(at_max, expected)}")  # fmt: skip
    if told:
        zs = np.linspace(z_min, z_max, 2000)
        dz = depth_resolution(zs, near, far, "float32", mapping="reversed")
        artists += ax.plot(zs, dz / unit, color="black", lw=1, label="float32 reverse-Z Δz")
        z_w = worst(z_min, z_max, near, far)[0]
        artists += ax.plot([z_w], [expected / unit], "o", color="#2b7bba", ms=8,
                           label=f"coarsest {num(expected, got)} at z = {num(z_w)}")  # fmt: skip
        lo, hi = lowest(expected, got), highest(expected, got)
        # r425: 1e-8 either way, thinner than a line: said, since it cannot be seen
        width = _short(max(1 - lo / expected, hi / expected - 1))
        artists.append(ax.axhspan(lo / unit, hi / unit, color="#d9ecd9", lw=0, zorder=0,
                                  label=f"accepted: {width} either way (thinner than a line)"))  # fmt: skip
    if drawn:
        colour = "#7fbf7f" if ok else "#d7301f"
        artists.append(ax.axhline(got / unit, color=colour, linestyle="--",
                                  label=f"yours {num(got, expected)}"))  # fmt: skip
    elif got is not None:
        artists += ax.plot([], [], " ", label=f"yours {num(got)}: not drawn")
    ax.set_ylim(0, top * 1.3 / unit)
    ax.set_xlim(z_min - 0.02 * (z_max - z_min), z_max + 0.02 * (z_max - z_min))
    ax.set_xlabel(f"view depth z (near {num(near)}, far {num(far)})")
    ax.set_ylabel(f"resolved gap Δz{named}", fontsize="small")
    # below the axes: inside, it hid the curve's teeth (r404 F4: beside them, it was as wide)
    artists.append(ax.legend(fontsize="x-small", loc="upper center", ncol=2,
                             bbox_to_anchor=(0.5, -0.2), frameon=False))  # fmt: skip
    return artists


REVERSE_Z_WORST = Exercise(
    "reverse_z_worst", worst_cases, as_gap, same_worst, explain_worst, _rule,
    [dataclasses.replace(m, only_whole=True) if m.kind in ONLY_WHOLE else m
     for m in variant_mistakes(_variants, MISTAKES, (*CROSSING_SLIPS, EDGE_BELOW, Z_MAX_HERE, OTHER_CROSSING, OUTSIDE,
     GAP_SLIP, FINEST_SAMPLED, RATIO, MARGIN, SEARCH, OVER, NAN_NO_CROSSING, RANGE))], draw=draw_worst,
    match=gives_same_gap, float32=lambda args: expected_worst(*args), float32_floor=0.0,
    answers=(
        PackageAnswer(expected_worst, words=CHECKER_WORDS),
        PackageAnswer(depth_resolution, what="float32 reverse-Z's Δz, which your reverse_z_gap "
                      "computes", when=lambda a: a.get("fmt") == "float32"
                      and a.get("mapping") == "reversed"),
    ), reference=("teachraster.exercises.reverse_z",), hints=(
        # the method, held back until two different answers have failed (r39's rule; r404
        # F1: where the worst depth is, too, and where it can lie)
        ("compare z_max with the limit just nearer than each such depth in the range",
         "where in the range can the coarsest lie?"),
        (re.compile(re.escape(WHERE[0]) + ".*?" + re.escape(WHERE[1])), WHERE_HINT),
        _LATER, _BETWEEN,
    ), slow=" (a Python call per sampled depth?)",
)  # fmt: skip

# r404 F1: the stub's note says what this figure draws (the answer only once told)
NOTHING_DRAWN_FOR[REVERSE_Z_WORST.name] = (
    "Nothing drawn yet: once your function returns answers, the check draws its first failing "
    "case (or, when all pass, one of the cases): your Δz and z_max's own; Δz over the range and "
    "its coarsest depth once two different answers have failed, or yours passes"
)
