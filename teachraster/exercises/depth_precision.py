"""Exercise ``depth_to_unorm(z, bits)``: the integer a ``bits``-bit unorm depth buffer stores.

Lesson 05b (Reed, *Depth Precision Visualized*; the GL 4.6 spec, §2.3.5 "Fixed-Point Data
Conversions"): a window depth z ∈ [0, 1] is stored as the integer round(z · (2^bits − 1)), so
that 0 and 1 are both exact. The expected answer is the package's
(:func:`teachraster.pipeline.depth.quantize`, whose read-back value times 2^bits − 1 is the
stored integer); where the exact product z · (2^bits − 1) lies within float64 rounding of a
half, either neighbour is accepted (GL leaves ties to the implementation). Explanations quote
the product and name the mistake its answer reproduces: truncation, 2^bits instead of
2^bits − 1, the value read back instead of the integer, float32 arithmetic.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache

import numpy as np

from ..pipeline.depth import quantize
from .cases import SEED
from .running import WrongAnswerType
from .scalars import num
from .scene_report import refuse_non_answers

#: The unorm depth formats of the package (GL_DEPTH_COMPONENT16 and 24).
BITS = (16, 24)
#: Ulps of z · (2^bits − 1) (in float64) within which a half counts as a tie.
TIE_ULPS = 4


def stored(z: float, bits: int) -> int:
    """The integer the package's ``unorm{bits}`` buffer stores for depth ``z``.

    >>> stored(0.25, 16), stored(1.0, 24)
    (16384, 16777215)
    """
    scale = 2**bits - 1
    return int(round(float(quantize(np.array([z]), f"unorm{bits}")[0]) * scale))


def accepted(z: float, bits: int) -> tuple[int, ...]:
    """The answers accepted for ``z``: the nearest integer, or both at a (near) tie."""
    exact = Fraction(z) * (2**bits - 1)  # z is a float64: this product is exact
    low = math.floor(exact)
    near_tie = abs(exact - low - Fraction(1, 2)) <= TIE_ULPS * math.ulp(float(exact))
    return (low, low + 1) if near_tie else (stored(z, bits),)


@cache  # the same cases on every check: built once
def depth_cases():
    """Hard cases (0 and 1, exact ties, k/(2^bits − 1) just below an integer), then random."""
    zs = []
    for bits in BITS:
        s = 2**bits - 1
        hard = [0.0, 1.0, 0.5, 0.25, 0.1, 0.75, 1e-9, 1 - 0.25 / s, np.nextafter(1.0, 0.0)]
        # the float just below k / s: its product z·s lands a hair below k, which truncation
        # (int()) turns into k − 1 (a depth a previous stage computed is rarely exact)
        below = [np.nextafter(k / s, 0.0) for k in (3, 1000, s - 7)]
        below = [z for z in below if z * s < round(z * s)]
        hard += below + [0.5 / s, 1.5 / s, 2.5 / s]
        zs += [(float(z), bits) for z in hard]
    rng = np.random.default_rng(SEED + 50)
    for bits in BITS:
        zs += [(float(z), bits) for z in rng.uniform(0, 1, 8)]
        zs += [(float(z), bits) for z in 1 - rng.uniform(0, 1e-3, 3)]  # far depths crowd at 1
    out = []
    for z, bits in zs:
        out.append((f"z = {z!r}, {bits} bits", (float(z), bits), stored(z, bits)))
    return out


def as_count(value) -> float:
    """The returned number (an int is expected; a float is judged by its value)."""
    refuse_non_answers(value, "an integer")
    arr = np.asarray(value)
    if arr.size != 1 or arr.dtype.kind not in "uif":
        raise WrongAnswerType(f"returned {value!r:.60}, not an integer")
    return float(arr.item())


def same_depth(got: float, expected: int, args) -> bool:
    return got in accepted(*args)


def explain_depth(args, expected, got) -> str:
    z, bits = args
    s = 2**bits - 1
    product = z * s
    shown = repr(product) if product != round(product) else str(int(product))
    head = f"in float64 z·(2^{bits} − 1) = {z!r}·{s} = {shown}"
    rule = f"the buffer stores the nearest integer, {expected}"
    f32 = float(np.rint(np.float32(z) * np.float32(s)))
    if got == f32 and got == int(product) and bits > 16:
        return (
            f"{head}; {rule}. Your {num(got)} is what truncation (int()) gives, and also what "
            "float32 arithmetic gives: round to the nearest integer, in float64"
        )
    if got == int(product) and got != expected:
        return (
            f"{head}, which int() truncates to {num(got)}; {rule}: rounding by truncation "
            "drops the fraction, round to the nearest instead"
        )
    if got == math.ceil(product) and got != expected:
        return f"{head}; {rule}, not the next integer up (you rounded up)"
    if got in (round(z * 2**bits), math.floor(z * 2**bits)):
        return (
            f"{head}; {rule}. Your {num(got)} multiplies by 2^{bits} = {2**bits}: the largest "
            f"stored integer, 2^{bits} − 1 = {s}, must hold z = 1 exactly, so scale by 2^{bits} − 1"
        )
    if abs(got - expected / s) <= 1e-9:
        return (
            f"{head}; {rule}. Your {num(got)} is the depth read back, {expected}/{s}: return "
            "the stored integer itself"
        )
    if got != round(got):
        return f"{head}; your {got!r} is not an integer: {rule}"
    if got == f32:
        gap = float(np.spacing(np.float32(product)))
        return (
            f"{head}; {rule}. Yours, {num(got)}, is what float32 arithmetic gives: float32 "
            f"numbers near {num(product)} are {num(gap)} apart. Compute in float64"
        )
    return f"{head}; {rule} (round(z·(2^{bits} − 1))); yours is {num(got)}"


def draw_depth(ax, case, got):
    """The product z·(2^bits − 1) on a number line, the stored integer and the student's."""
    (z, bits), expected = case[1], case[2]
    product = z * (2**bits - 1)
    artists = [ax.axvline(product, color="#888888", linestyle=":", label="z·(2^bits − 1)")]
    artists += ax.plot([expected], [0], "o", color="#2b7bba", ms=10, label="stored (expected)")
    if got is not None and np.isfinite(got):
        artists += ax.plot([got], [0], "x", color="#d7301f", ms=12, mew=2, label="yours")
    lo = math.floor(min(product, expected, product if got is None else got)) - 1
    hi = math.ceil(max(product, expected, product if got is None else got)) + 1
    ax.set_xlim(lo - 0.2, hi + 0.2)
    ax.set_yticks([])
    ax.set_xlabel(f"integers of the {bits}-bit buffer")
    ax.ticklabel_format(useOffset=False, style="plain", axis="x")
    artists.append(ax.legend(fontsize="x-small"))
    return artists
