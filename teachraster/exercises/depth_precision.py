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
from .answers import as_number
from .cases import SEED
from .exercise import Exercise, Mistake, PackageAnswer
from .scalars import num

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
    return float(as_number(value))


def same_depth(got: float, expected: int, args) -> bool:
    return got in accepted(*args)


def explain_depth(args, expected, got) -> str:
    z, bits = args
    s = 2**bits - 1
    product = z * s
    shown = repr(product) if product != round(product) else str(int(product))
    return (
        f"in float64 z·(2^{bits} − 1) = {z!r}·{s} = {shown}; the buffer stores the nearest "
        f"integer, {expected}; yours is {num(got, expected)}"
    )


def _float32_words(args, expected, got) -> str:
    z, bits = args
    product = z * (2**bits - 1)
    gap = float(np.spacing(np.float32(product)))
    return (
        f": that is what float32 arithmetic gives: float32 numbers near {num(product)} are "
        f"{num(gap)} apart. Compute in float64"
    )


def _scaled(scale, rounding=round):
    def gives(z, bits):
        value = z * scale(bits)
        return float(rounding(value)) if np.isfinite(value) else None

    return gives


DEPTH_MISTAKES = [
    Mistake("truncation", ": int() truncates (it drops the fraction); round to the nearest "
            "integer instead", gives=_scaled(lambda b: 2**b - 1, math.trunc)),
    Mistake("rounded up", ": you rounded up; the buffer stores the nearest integer",
            gives=_scaled(lambda b: 2**b - 1, math.ceil)),
    Mistake("2^bits", lambda a, e, g: f": you multiplied by 2^{a[1]} = {2**a[1]}: the largest "
            f"stored integer, 2^{a[1]} − 1 = {2**a[1] - 1}, must hold z = 1 exactly, so scale "
            f"by 2^{a[1]} − 1", gives=_scaled(lambda b: 2**b)),
    Mistake("2^bits", lambda a, e, g: f": you multiplied by 2^{a[1]} = {2**a[1]} and "
            f"truncated: scale by 2^{a[1]} − 1 = {2**a[1] - 1} and round to the nearest",
            gives=_scaled(lambda b: 2**b, math.floor)),
    Mistake("xor", lambda a, e, g: f": `^` is exclusive or in Python: 2 ^ {a[1]} = {2 ^ a[1]}; "
            f"the power is 2**{a[1]}, so the scale is 2**{a[1]} − 1",
            gives=_scaled(lambda b: (2 ^ b) - 1)),
    Mistake("2·bits", lambda a, e, g: f": that scales by 2·{a[1]} − 1 = {2 * a[1] - 1}; the "
            f"scale is 2**{a[1]} − 1 = {2**a[1] - 1}", gives=_scaled(lambda b: 2 * b - 1)),
    Mistake("read back", lambda a, e, g: f": that is the depth read back, {e}/{2**a[1] - 1}: "
            "return the stored integer itself", gives=lambda z, b: stored(z, b) / (2**b - 1)),
    Mistake("float32", _float32_words,
            gives=lambda z, b: float(np.rint(np.float32(z) * np.float32(2**b - 1)))),
    Mistake("float32", lambda a, e, g: ": that is what truncation gives, computed in float32: "
            "round to the nearest integer, in float64",
            gives=lambda z, b: float(np.trunc(np.float32(z) * np.float32(2**b - 1)))),
    Mistake("not an integer", lambda a, e, g: f": {g!r} is not an integer; the buffer stores "
            "whole numbers", fits=lambda a, e, g: g != round(g), symptom=True),
]  # fmt: skip


def _rule(args, expected, got) -> str:
    z, bits = args
    return f": round(z·(2^{bits} − 1))"


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


def exercise(scene) -> Exercise:
    return Exercise(
        "depth_to_unorm", depth_cases, as_count, same_depth, explain_depth, _rule,
        DEPTH_MISTAKES, float32=lambda args: 0.0, answers=(PackageAnswer(quantize),),
        draw=draw_depth, scene=scene,
    )  # fmt: skip
