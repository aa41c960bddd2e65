"""Exercise ``decal_bias`` (lesson 05b, §5): the depth offset a decal on a tilted wall needs.

Lesson 05b §5 prints the APIs' polygon offset, o = units·r + factor·m (Direct3D 11's *Depth
Bias*: ``DepthBias * r + SlopeScaledDepthBias * MaxDepthSlope``; OpenGL 4.6 §14.6.5,
``glPolygonOffset(factor, units)``: ``m * factor + r * units``; Vulkan's
``vkCmdSetDepthBias(depthBiasConstantFactor, depthBiasClamp, depthBiasSlopeFactor)``), and shows
that ``glPolygonOffset(-1, -1)`` makes its decal win. It never works out *what* offset a given
decal needs, nor what too much of it hides. Here the student does, from the geometry: a wall
tilted by θ about the vertical axis at view distance z, whose window depth is affine in screen
x with slope m = f n tan θ · pixel / ((f − n) z) per pixel (1/z is affine in x/z on that
plane), a decal on it whose depth at a pixel may differ from the wall's by up to m either way,
both rounded to a ``bits``-bit unorm buffer, the strict test keeping the wall at a tie. That
error is a worst-case budget, the one a slope factor of 1 pays for (the decal's triangles set
up from their own vertices, off the wall's plane by up to a pixel's depth change), not lesson
05b §5's measurement: its decal shares the wall's plane and rasteriser, so the two depths come
out a rounding apart: this model with m replaced by the few steps that set-up errs by, not
m = 0, where one step would do (r316 C4, r325 C2).
The decal wins at every pixel iff |o| ≥ r + m; an opaque object ``clear`` in front of the wall
on the view axis, drawn before the decal (a tie keeps it), still hides the decal iff
|o| ≤ z_win(z) − z_win(z − clear) − m (r316 item 3: llvmpipe's r of two steps passes). When
that is less than r + m no offset does both, and the answer is NaN (:data:`TIGHT`: a solution
ignoring ``clear`` fails there; :data:`BAND`: room between r + m and r + 2m, where a test of
r + m against room alone fails). With reverse-Z (1 − z_win stored, greater wins) the sign
flips.

An answer is judged by that criterion, not closeness: any offset of the right sign between
the two bounds passes (float32's rounding, :data:`ROUNDING`, allowed at both ends). The expected
answer is the smallest, the package's :func:`teachraster.pipeline.depth.depth_bias` with
units and factor −1 (+1 under reverse-Z).
"""

from __future__ import annotations

import copy
import dataclasses
import math
import re
from functools import cache

import numpy as np

from ..pipeline.visibility.depth import depth_bias, window_depth
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .near_plane import HALF_STEP, XOR_UNBRACKETED, as_lone_number
from .package_answers import CHECKER_WORDS
from .reverse_z import gives_same_gap
from .scalars import num

#: (z, tilt in degrees, pixel, near, far, bits, reverse) of the fixed cases: a wall facing
#: the camera (m = 0: one step is the whole answer), tilts from 30° to 89° (the slope term
#: from a fraction of a step to thousands), 16 and 24 bits, reverse-Z. ``pixel`` is the
#: width one pixel spans at view distance 1 (2 tan(fov/2) / width: 60° over 1920 px).
SETTINGS = (
    (10.0, 60.0, 6.01e-4, 0.1, 1000.0, 24, False), (10.0, 0.0, 6.01e-4, 0.1, 1000.0, 24, False),
    (300.0, 80.0, 6.01e-4, 0.1, 1000.0, 24, False), (2.0, 85.0, 1e-3, 0.1, 100.0, 16, False),
    (100.0, 30.0, 1e-3, 1.0, 1000.0, 16, False), (1.0, 89.0, 6.01e-4, 0.1, 100.0, 24, False),
    (50.0, 45.0, 6.01e-4, 0.1, 1000.0, 24, True), (5.0, 70.0, 1e-3, 0.5, 200.0, 16, True),
)  # fmt: skip

#: The object in front leaves the decal this many times the smallest offset (``clear`` is
#: rounded up to 3 digits from there): an offset twice the smallest hides the object.
ROOM = 1.5
#: Settings (as :data:`SETTINGS`) whose object in front leaves only this share of r + m: no
#: offset draws the decal over the wall and keeps the object in front, the answer is NaN, and a
#: solution that ignores ``clear`` fails (r316 M-2: otherwise the upper bound never binds).
TIGHT = (
    (10.0, 60.0, 6.01e-4, 0.1, 1000.0, 24, False), (5.0, 70.0, 1e-3, 0.5, 200.0, 16, True),
)  # fmt: skip
TIGHT_SHARE = 0.8
#: Settings whose object leaves room between r + m and r + 2m (m > r there, so this share of
#: r + m): room − m < r + m, NaN again, where a test of r + m against room alone (the decal's
#: own m toward the object forgotten) returns r + m and the decal shows through (r325 M1).
BAND = (
    (300.0, 80.0, 6.01e-4, 0.1, 1000.0, 24, False), (50.0, 45.0, 6.01e-4, 0.1, 1000.0, 24, True),
)  # fmt: skip
BAND_SHARE = 1.5
#: (setting, share) whose object leaves room − m just above r + m, clear/z about 0.07: an
#: offset fits, where a room taken behind the wall, z_win(z + clear) − z_win(z) (smaller by
#: about 2 clear/z), says NaN on both, and one to first order, f n/((f − n) z²) · clear
#: (smaller by about clear/z), on the first only: the two slips told apart (r340).
FIT = (
    ((1.0, 89.0, 6.01e-4, 0.1, 100.0, 24, False), 2.1),
    ((1.0, 89.0, 6.01e-4, 0.1, 100.0, 24, False), 2.25),
)
#: (setting, share or clear) on :data:`FIT`'s wall (clear/z about 0.064), r442: room − m 5 %
#: under r + m (NaN), where room to first order at the object's depth z − clear (over by about
#: clear/z) fits an offset; and 5e-4 over it (an offset), where room to first order at the
#: midpoint z − clear/2 (under by about (clear/2z)²) says NaN.
FIRST_ORDER = (
    ((1.0, 89.0, 6.01e-4, 0.1, 100.0, 24, False), 1.95, None),
    ((1.0, 89.0, 6.01e-4, 0.1, 100.0, 24, False), None, 0.064442),
)
#: float32's relative rounding, allowed at both ends: a tilt held in float32 moves tan θ by
#: up to 3e-6 of itself at 88° (tan's relative slope there is 1/(sin θ cos θ) ≈ 29).
ROUNDING = 1e-5
#: (setting, clear) whose room − m lies within a step of r + m with a step boundary between
#: the two depths (r381 F1): a room measured between the *rounded* window depths overshoots
#: the first (an offset where none fits: the decal shows through the object) and falls short
#: on the second (NaN where one fits). The task measures it between unrounded depths.
ROUNDED = (
    ((20.0, 65.0, 6.01e-4, 0.1, 1000.0, 16, False), 0.082),
    ((21.0, 55.0, 6.01e-4, 0.1, 1000.0, 16, True), 0.13),
)
#: (setting, clear), r514 P3: room − m 2 % under r + m (NaN), where the room rounded as one
#: difference to whole steps, round(room · (2^bits − 1)) r, lies 37 % over it (an offset:
#: the decal shows through the object), and each depth rounded (:data:`ROUNDED`) says NaN.
ROUNDED_DIFFERENCE = (((21.0, 55.0, 6.01e-4, 0.1, 1000.0, 16, True), 0.101),)
#: A setting with z² < n, where window depth changes faster than view depth (room > clear),
#: and no offset fits: a test against `clear` itself, a view distance, says NaN there, as it
#: should, where code with no test of the room returns r + m (r381 F2: the two told apart).
STEEP = ((0.2, 60.0, 6.01e-4, 0.1, 100.0, 16, False),)


def step(bits: int) -> float:
    """r: one step of a ``bits``-bit unorm buffer in window depth."""
    return 1.0 / (2**bits - 1)


def slope(z, tilt, pixel, near, far) -> float:
    """MaxDepthSlope: the window depth's change per pixel on the tilted wall (exact: the
    plane's 1/z is affine in x/z, so z_win is affine in screen x)."""
    return far * near * math.tan(math.radians(tilt)) * pixel / ((far - near) * z)


def _wall(z, near, far) -> float:
    return float(window_depth([z], near, far)[0])


def room(z, near, far, clear) -> float:
    """The window depth between the wall and the object ``clear`` in front of it."""
    return _wall(z, near, far) - _wall(z - clear, near, far)


def bounds(z, tilt, pixel, near, far, bits, reverse, clear) -> tuple[float, float]:
    """(smallest, largest) |o|: a step beyond the pixel's depth span, and what the object
    ``clear`` in front leaves (the decal at its nearest no nearer than the object: drawn
    before the decal, the object keeps a tie)."""
    r, m = step(bits), slope(z, tilt, pixel, near, far)
    return r + m, room(z, near, far, clear) - m


def impossible(args) -> bool:
    """No offset meets both conditions (beyond float32's rounding at both ends)."""
    lo, hi = bounds(*args)
    return lo * (1 - ROUNDING) > hi * (1 + ROUNDING)


def expected_offset(z, tilt, pixel, near, far, bits, reverse, clear) -> float:
    """The smallest offset, the package's: ``depth_bias`` with units and factor ∓1 (NaN when
    the object in front leaves too little for any)."""
    if impossible((z, tilt, pixel, near, far, bits, reverse, clear)):
        return math.nan
    sign = 1.0 if reverse else -1.0
    m = slope(z, tilt, pixel, near, far)
    wall = _wall(z, near, far)
    stored = 1.0 - wall if reverse else wall
    return float(depth_bias(stored, f"unorm{bits}", units=sign, slope=m, slope_factor=sign))


def _clear(z, tilt, pixel, near, far, bits, share=ROOM + 1) -> float:
    """The distance in front of the wall whose window depth is ``share`` times the smallest
    offset (:data:`ROOM` times it left beyond the decal at its farthest), rounded up to 3
    significant digits (None when the near plane is closer)."""
    need = step(bits) + slope(z, tilt, pixel, near, far)
    front = _wall(z, near, far) - share * need  # the object's window depth
    if front <= 0:
        return None
    z_front = near / (1 - front * (far - near) / far)  # window depth's inverse
    clear = z - z_front
    digits = 10 ** (math.floor(math.log10(clear)) - 2)
    return math.ceil(clear / digits) * digits


def _case(setting, label=None, share=ROOM + 1, clear=None):
    *head, reverse = setting
    clear = _clear(*head, share=share) if clear is None else clear
    args = (*head, reverse, clear)
    z, tilt, pixel, near, far, bits = head
    label = label or (f"z = {num(z)}, tilt {num(tilt)}°, pixel {num(pixel)}, near = {num(near)}, "
                      f"far = {num(far)}, {bits} bits{', reverse-Z' if reverse else ''}, "
                      f"clear {num(clear)}")  # fmt: skip
    return label, args, expected_offset(*args)


@cache
def _fixed_cases():
    return ([_case(s) for s in SETTINGS] + [_case(s, share=TIGHT_SHARE) for s in TIGHT]
            + [_case(s, share=BAND_SHARE) for s in BAND]
            + [_case(s, share=share) for s, share in FIT]
            + [_case(s, clear=clear) for s, clear in ROUNDED]
            + [_case(s, share=TIGHT_SHARE) for s in STEEP]
            + [_case(s, share=share or ROOM + 1, clear=clear) for s, share, clear in FIRST_ORDER]
            + [_case(s, clear=clear) for s, clear in ROUNDED_DIFFERENCE])  # fmt: skip


def bias_cases():
    """The fixed cases (built once, copied) and :data:`DRAWN` drawn for this check."""
    out, rng = copy.deepcopy(_fixed_cases()), drawn_rng()
    fixed = len(out)
    while len(out) < fixed + DRAWN:
        far = float(f"{10 ** rng.uniform(2, 4):.3g}")
        near = float(f"{far * 10 ** rng.uniform(-5, -2):.3g}")
        z = float(f"{near * 10 ** rng.uniform(1, np.log10(0.5 * far / near)):.3g}")
        setting = (z, float(f"{rng.uniform(20, 88):.3g}"), 6.01e-4, near, far,
                   int(rng.choice([16, 24])), bool(rng.integers(2)))  # fmt: skip
        if _clear(*setting[:6]) is not None:
            label, args, expected = _case(setting)
            out.append((f"drawn for this check {len(out) - fixed + 1}: {label}", args,
                        expected))  # fmt: skip
    return out


def same_offset(got, expected, args=None) -> bool:
    """Right sign, and |o| between :func:`bounds` (NaN where no offset fits); without
    ``args``, within 1e-6 of it."""
    if args is None:
        return gives_same_gap(got, expected, None)
    if impossible(args):
        return bool(np.isnan(got))
    if not np.isfinite(got) or (got > 0) != bool(args[6]) or got == 0:
        return False
    lo, hi = bounds(*args)
    return lo * (1 - ROUNDING) <= abs(got) <= hi * (1 + ROUNDING)


def _variants(z, tilt, pixel, near, far, bits, reverse, clear) -> dict[str, float]:
    """The offsets typical slips give (each one change), signed as the case needs: NaN where
    no offset fits (the right test), and for a slip of r or m also by the student's own test,
    ``r' + m' > room − m'`` (``…, own test``: r325, a complete solution whose NaN fires on
    its own wrong m was told "a 0/0")."""
    r, m = step(bits), slope(z, tilt, pixel, near, far)
    sign = 1.0 if reverse else -1.0
    args = (z, tilt, pixel, near, far, bits, reverse, clear)
    tight = impossible(args)
    space = room(z, near, far, clear)

    def offset(o):  # the right test for NaN, the slip in the offset alone
        return math.nan if tight else sign * o

    def own(r_, m_):  # the slip's r' and m' in the test for NaN too
        return math.nan if r_ + m_ > space - m_ else sign * (r_ + m_)

    behind = _wall(z + clear, near, far) - _wall(z, near, far)
    first = far * near / ((far - near) * z * z) * clear  # lesson 05b §2's dz_win/dz · clear
    # r442: the same first order taken at the object's depth, or at the midpoint
    at_object = far * near / ((far - near) * (z - clear) ** 2) * clear
    at_mid = far * near / ((far - near) * (z - clear / 2) ** 2) * clear
    # slips of m, each in the offset alone and in the student's own test for NaN too (r340:
    # the own-test forms of z², view slope, the far plane's factor, cos and 1/tan were told
    # only the rule, or another slip's words)
    slopes = _slipped_slopes(m, z, tilt, pixel, near, far)
    slipped = {}
    for kind, m_ in slopes.items():
        slipped[kind] = None if m_ is None else offset(r + m_)
        slipped[f"{kind}, own test"] = None if m_ is None else own(r, m_)
    return {
        "clear ignored": sign * (r + m) if tight else None,
        # r381 F2: the room computed (`clear` read) but never tested: r + m on every case
        "no room test": sign * (r + m),
        # r374 F2: room taken as `clear` itself, a view distance (less than 2m + r only where
        # z² < n: :data:`STEEP`, which tells it from no test at all)
        "view units": math.nan if r + m > clear - m else sign * (r + m),
        # r381 F1: room measured between the depths rounded to the buffer (:data:`ROUNDED`)
        "rounded room": math.nan
        if r + m > _rounded(z, near, far, bits, clear) - m
        else sign * (r + m),
        # r514 P3: the room rounded to whole steps as one difference
        "rounded difference": math.nan
        if r + m > round(space * (2**bits - 1)) / (2**bits - 1) - m
        else sign * (r + m),
        "behind": math.nan if r + m > behind - m else sign * (r + m),
        "first order": math.nan if r + m > first - m else sign * (r + m),
        "first order at the object": math.nan if r + m > at_object - m else sign * (r + m),
        "first order at the midpoint": math.nan if r + m > at_mid - m else sign * (r + m),
        # a test for NaN twice as strict as it needs, a variant (not the NAN symptom alone):
        # r340's near-boundary case made a coincident slip of m outrank the symptom
        "r + 2m": math.nan if r + 2 * m > space - m else sign * (r + m),
        # the object's test without the decal's own m toward it: r + m > room
        "object without m": sign * (r + m) if tight and r + m <= space else None,
        "sign": math.nan if tight else -sign * (r + m),
        "reverse ignored": math.nan if tight else -(r + m),
        # r351: the mirror of "reverse ignored", positive with the less-wins test too
        "positive": math.nan if tight else r + m,
        "no tie": offset(m),
        "no slope": offset(r),
        "in steps": offset(1 + m / r),
        **slipped,
        "2^bits": offset(1.0 / 2**bits + m),
        "half": offset(r / 2 + m),
        # r340: 1/(2^bits - 1) typed, 1/(2 ^ (bits - 1)) run (in the test for NaN too, the
        # answer is NaN on every case: :data:`NAN_WORDS` names it)
        "xor": offset(1.0 / (2 ^ (bits - 1)) + m),
        # r442 F2: two steps for r (OpenGL's llvmpipe, Vulkan's bound 2 · 2^-bits), in the
        # test for NaN too (a larger offset still fits where it fits: the NaN tells it); and
        # the test rearranged with r counted twice, 2(r + m) > room
        "two steps": own(2.0 / 2**bits, m),
        "r twice in the test": math.nan if 2 * (r + m) > space else sign * (r + m),
        # r458 G4: the decal's stored depth returned for the offset (the wall's plus o, or
        # 1 − |o|): "yours is 1" was printed with the generic rule
        "a depth": offset(r + m) + ((1 - _wall(z, near, far)) if reverse else _wall(z, near, far)),
        "one minus": math.nan if tight else 1 - (r + m),
        # ... with the less-wins test only (reverse-Z's offset right)
        "one minus, less-wins": offset(r + m) if reverse else offset(r + m) + 1,
    }


def _rounded(z, near, far, bits, clear) -> float:
    """The room between the wall's and the object's window depths each rounded to the buffer."""
    scale = 2**bits - 1
    return (round(_wall(z, near, far) * scale) - round(_wall(z - clear, near, far) * scale)) / scale


def _slipped_slopes(m, z, tilt, pixel, near, far) -> dict[str, float | None]:
    """m as each typical slip of it gives it (None where the slip says nothing: a trigonometric
    slip at 0° or 90°)."""
    rad = math.radians(tilt)
    inside = 0 < tilt < 90
    return {
        # r351: "the decal can be m either way, so 2m": first, as its own test's NaN on the
        # tight cases is also what per unit's gives, and that was said once hints were spent
        "doubled": 2 * m,
        "z squared": m / z,
        "view slope": pixel * z * math.tan(rad),
        "infinite far": m * (far - near) / far,
        "degrees": m * math.tan(tilt) / math.tan(rad) if inside else None,
        "per unit": m / pixel,
        "sine": m * math.sin(rad) / math.tan(rad) if inside else None,
        "cosine": m * math.cos(rad) / math.tan(rad) if inside else None,
        "cotangent": m / math.tan(rad) ** 2 if inside else None,
        # r442 F3: half a pixel's slope ("from the pixel's centre to its edge")
        "halved": m / 2,
        # r458 G3: an extra 1/cos θ (the wall's length per pixel along its tilt), 2m at 60°,
        # where "r + 2m" was said
        "secant": m / math.cos(rad) if inside else None,
    }


def _steps(x, *others) -> str:
    """``x`` steps, as :func:`num` prints it, "1 step" for one (r381 F7: "1 steps")."""
    said = num(x, *others)
    return f"{said} step" if said == "1" else f"{said} steps"


def _m_said(m, r) -> str:
    """m as the words say it: the one form :data:`HINTS` hold back until the full words."""
    return f"m = {num(m)} ({_steps(m / r)})"


_DEGREES = ": the tilt is in degrees and the tangent takes radians: tan(np.radians(tilt))"
_PER_UNIT = (": your slope is per unit of x/z, not per pixel (the `* pixel` is missing): one "
             "pixel spans `pixel` of x/z, so MaxDepthSlope is that slope times pixel")  # fmt: skip
_SINE = (": you took sin θ where the slope needs tan θ: a point seen at s = x/z on the wall "
         "tilted by θ lies at 1/z' = (1 − s tan θ)/z, so the depth changes per pixel with tan θ")  # fmt: skip

_Z_SQUARED = (": your slope is the wall's divided by z: dz_win/dz = f n/((f − n) z²) is "
              "per unit of view depth, and one pixel moves the wall's view depth by "
              "z · tan θ · pixel (1/z' = (1 − s tan θ)/z), so one z cancels")  # fmt: skip
_VIEW = (": you took the slope of the view depth z per pixel (pixel·z·tan θ), not of the "
         "window depth the buffer stores: multiply by dz_win/dz = f n/((f − n) z²)")  # fmt: skip
_FAR = (": your slope lacks the far plane's factor f/(f − n): z_win = f/(f − n) · (1 − n/z), "
        "so dz_win/dz = f n/((f − n) z²); n/z² alone is the slope for a far plane at infinity")  # fmt: skip
_COSINE = (": you took cos θ where the slope needs tan θ: a point seen at s = x/z on the wall "
           "tilted by θ lies at 1/z' = (1 − s tan θ)/z, so the depth changes per pixel with "
           "tan θ (0 for a wall facing the camera, without bound as it turns edge-on)")  # fmt: skip
_COTANGENT = (": you took 1/tan θ where the slope needs tan θ: a wall facing the camera "
              "(θ = 0) has no slope, and the slope grows without bound as it turns edge-on; "
              "a point seen at s = x/z on the wall lies at 1/z' = (1 − s tan θ)/z")  # fmt: skip
#: The words of each slip of m (:func:`_slipped_slopes`), said alike with the student's own
#: test for NaN
_DOUBLED = (": your m is twice one pixel's depth slope. The decal's depth lies within m of "
            "the wall's either way, but each bound needs only one side: from m behind it must "
            "end a step in front, |o| ≥ r + m, and from m in front it must stay behind the "
            "object, |o| ≤ room − m")  # fmt: skip
_HALVED = (": your m is half one pixel's depth slope (from the pixel's centre to its edge?). "
           "MaxDepthSlope is the change of depth from one pixel to the next, and the decal's "
           "depth may lie that whole m behind the wall's: |o| ≥ r + m")  # fmt: skip
_SECANT = (": your m has an extra 1/cos θ (tan θ/cos θ): a point seen at s = x/z on the wall "
           "tilted by θ lies at 1/z' = (1 − s tan θ)/z, so the depth changes per pixel with "
           "tan θ alone; the wall's length along its tilt does not enter")  # fmt: skip
_SLOPE_WORDS = {
    "doubled": _DOUBLED, "halved": _HALVED, "secant": _SECANT,
    "z squared": _Z_SQUARED, "infinite far": _FAR, "degrees": _DEGREES, "per unit": _PER_UNIT,
    "view slope": _VIEW, "sine": _SINE, "cosine": _COSINE, "cotangent": _COTANGENT,
}  # fmt: skip
#: Both slips make m thousands of times too large, and with it their own test for NaN says
#: NaN on every case with an offset, so their answers are alike: told apart by whether the code
#: reads ``pixel`` (r374 F3: view depth's slope was told "the `* pixel` is missing" first, of
#: code that has it; :data:`_READS`). So are code that never reads ``clear`` and code that
#: reads it but never tests the room (r381 F2: r + m on every case); a test against ``clear``
#: itself, a view distance, differs from both on :data:`STEEP`.
_OWN_WORDS = {}
_READS = {"per unit, own test": {"unread": "pixel"}, "view slope, own test": {"reads": "pixel"},
          "clear ignored": {"unread": "clear"}, "no room test": {"reads": "clear"}}  # fmt: skip

MISTAKES = {
    "clear ignored": lambda a, e, g: (
        f": your offset ignores `clear`: the object only {num(a[7])} in front leaves room − m "
        "less than r + m, so no offset draws the decal over the wall and keeps the object in "
        "front: return NaN here (an offset this size puts the decal in front of the object)"
    ),
    "no room test": lambda a, e, g: (
        ": you return r + m on every case: no test of the room the object leaves. Here it "
        f"leaves z_win(z) − z_win(z − clear) = {num(room(a[0], a[3], a[4], a[7]))} of window "
        "depth, less than r + 2m: return NaN when r + m > room − m"
    ),
    "view units": lambda a, e, g: (
        f": your test for NaN compares with `clear` itself ({num(a[7])}), a view distance. The "
        "room the object leaves is a window depth, as the offset is: z_win(z) − z_win(z − "
        f"clear) = {num(room(a[0], a[3], a[4], a[7]))}, less than r + 2m here"
    ),
    "rounded room": lambda a, e, g: (
        ": your room is measured between rounded depths, "
        f"{num(_rounded(a[0], a[3], a[4], a[5], a[7]))} here where the unrounded window depths "
        f"leave {num(room(a[0], a[3], a[4], a[7]))}. Rounding to nearest keeps order: a decal "
        "whose unrounded depth is no nearer than the object's rounds to no nearer a value, and "
        "a tie keeps the object. So compare the unrounded depths (the rounding is what r pays "
        "for)"
    ),
    "rounded difference": lambda a, e, g: (
        ": your room is rounded to whole steps, "
        f"{num(round(room(a[0], a[3], a[4], a[7]) * (2 ** a[5] - 1)) / (2 ** a[5] - 1))} here, "
        f"where the unrounded window depths leave {num(room(a[0], a[3], a[4], a[7]))}. The "
        "task measures the room between unrounded window depths (the rounding is what r pays "
        "for): compare them as they are"
    ),
    "behind": ": you placed the object behind the wall (z + clear): it is in front, at "
    "z − clear, so room = z_win(z) − z_win(z − clear)",
    "first order": ": you took room to first order, f n/((f − n) z²) · clear, which falls short "
    "of it by about a factor 1 − clear/z: the object's window depth is exact, so room = "
    "z_win(z) − z_win(z − clear)",
    "first order at the object": ": you took room to first order at the object's depth, f n/"
    "((f − n)(z − clear)²) · clear, which overshoots it by about clear/z (the slope of z_win is "
    "steeper there than over the span): the object's window depth is exact, so room = "
    "z_win(z) − z_win(z − clear)",
    "first order at the midpoint": ": you took room to first order at the midpoint, f n/((f − "
    "n)(z − clear/2)²) · clear, which falls short of it by about (clear/2)²/(z − clear/2)²: "
    "close, but the test of r + m against room − m needs it exactly, room = z_win(z) − "
    "z_win(z − clear)",
    "r + 2m": ": NaN means “no offset works” here, and this case has one: r + m ≤ room − m. "
    "Your test for NaN asks for r + 2m: the decal at its nearest lies m in front of the wall, "
    "|o| + m from it, so |o| = r + m fits while room − m ≥ r + m",
    "object without m": ": your test for NaN compares r + m with room alone: at its nearest "
    "the decal lies m in front of the wall, so it stays behind the object only if "
    "|o| ≤ room − m, and no offset fits unless r + m ≤ room − m (room ≥ r + 2m). Here room "
    "lies between r + m and r + 2m: return NaN (an offset of r + m shows the decal through "
    "the object)",
    "sign": lambda a, e, g: (
        ": wrong sign for reverse-Z: the buffer stores 1 − z_win and the test keeps the "
        "greater value, so the decal moves nearer with a positive offset (glPolygonOffset(1, 1))"
        if a[6]
        else ": wrong sign: the depth test keeps the smaller depth, so the decal moves nearer "
        "with a negative offset (glPolygonOffset(−1, −1)); a positive one pushes it behind "
        "the wall (with reverse-Z, greater is nearer and the sign flips)"
    ),
    "reverse ignored": ": your offset is negative under reverse-Z too: reverse-Z stores "
    "1 − z_win and the test keeps the greater value, so there the decal moves nearer with a "
    "positive offset (glPolygonOffset(1, 1))",
    "positive": ": your offset is positive with the forward test, which keeps the smaller "
    "depth: smaller is nearer, so the decal moves nearer with a negative offset "
    "(glPolygonOffset(−1, −1)); a positive one pushes it behind the wall. Only under reverse-Z "
    "(greater wins) is the offset positive",
    "no tie": ": you offset the decal by the pixel's depth span m alone. At the worst rounding "
    "both depths then store one value, and a tie keeps the wall (drawn first; the test is "
    "strict): one step r more makes the decal strictly nearer, |o| = r + m",
    "no slope": lambda a, e, g: (
        f": you left out the slope term: one step r covers a tie of two equal depths (the lesson's "
        f"decal, on the wall's own plane, needed a few for its rounding), not this task's budget. Here the two "
        f"depths at a pixel can differ by one pixel's slope {_m_said(slope(*a[:5]), step(a[5]))}"
        ", so |o| = r + m"
    ),
    "in steps": ": that offset is counted in steps of the buffer (DepthBias's units), not in "
    "window depth: one step is r = 1/(2^bits − 1), and o = units·r + factor·m is a depth",
    **{
        k: _OWN_WORDS.get(k, w)
        for kind, w in _SLOPE_WORDS.items()
        for k in (kind, f"{kind}, own test")
    },
    "2^bits": lambda a, e, g: (
        f": you took r as 1/2^{a[5]}: the largest stored integer, 2^{a[5]} − 1, holds depth 1, "
        f"so one step is 1/(2^{a[5]} − 1), and yours falls short of a step by a hair: at the "
        "worst rounding the two depths tie"
    ),
    "half": f": {HALF_STEP}. Beyond the pixel's span m the decal needs a whole step r",
    "xor": f": {XOR_UNBRACKETED}",
    "two steps": lambda a, e, g: (
        f": your test for NaN fires here, but one offset does both: r + m ≤ room − m with r = "
        f"1/(2^{a[5]} − 1). Yours takes r as two steps, 2/2^{a[5]} (OpenGL's llvmpipe, or "
        "Vulkan's bound): this task takes Direct3D's r, one step, 1/(2^bits − 1)"
    ),
    "a depth": lambda a, e, g: _depth_words(a, g),
    "one minus": lambda a, e, g: _depth_words(a, g),
    "one minus, less-wins": lambda a, e, g: _depth_words(a, g),
    "r twice in the test": ": your test for NaN fires here, but one offset does both: r + m ≤ "
    "room − m, that is r + 2m ≤ room. Yours asks 2(r + m) ≤ room: it counts r twice (the decal "
    "at its nearest lies m in front of the wall, o + m from it; r is in o once)",
}


def _depth_words(args, got) -> str:
    """r458 G4: a depth near the wall's (or near 1) returned for the offset."""
    return (f": yours, {got:.9g}, is a depth near the wall's stored "
            f"{(1 - _wall(*args[:1], *args[3:5])) if args[6] else _wall(*args[:1], *args[3:5]):.9g}"
            " (or near 1), not an offset: return o itself, the small number the API adds to "
            "the decal's depths, a step and a pixel's slope")  # fmt: skip


def explain_offset(args, expected, got) -> str:
    """The case's wall depth, slope and both bounds, and the student's offset."""
    z, tilt, pixel, near, far, bits, reverse, clear = args
    lo, hi = bounds(*args)
    r, m = step(bits), slope(*args[:5])
    wall = _wall(z, near, far)
    head = (f"the wall stores {'1 − z_win' if reverse else 'z_win'} ≈ "
            f"{1 - wall if reverse else wall:.7g}; its depth slope is {_m_said(m, r)} per "
            f"pixel, r = 1/(2^{bits} − 1); the decal needs |o| from {num(lo, hi)} (r + m) to "
            f"{num(hi, lo)} (room − m, where room = {num(room(z, near, far, clear))}: the object "
            f"{num(clear)} in front, drawn before the decal, must still hide it), "
            f"{'positive' if reverse else 'negative'}; yours is "
            # told from the signed bound: against |o| a positive r + m printed 17 digits (r351),
            # and alone where the answer is NaN (r374 F2: r + m, told from itself, printed 17)
            f"{num(got, None if impossible(args) else lo if reverse else -lo)}")  # fmt: skip
    if impossible(args):
        if np.isnan(got):
            return f"{head} (right: room − m < r + m, no offset does both)"
        return f"{head}: room − m < r + m, no offset does both, and the answer is NaN"
    if not np.isfinite(got) or got == 0 or (got > 0) != bool(reverse):
        return head
    if abs(got) < lo * (1 - ROUNDING):
        return (f"{head} (not enough: {_steps(abs(got) / r, lo / r)}, where the decal can "
                f"lie {_steps(m / r)} behind and must end a whole step nearer, "
                f"{_steps(lo / r, abs(got) / r)})")  # fmt: skip
    if abs(got) > hi * (1 + ROUNDING):
        return (f"{head} (too much: the decal at its nearest, |o| + m in front of the wall, is "
                f"now strictly nearer than the object {num(clear)} in front and shows "
                "through it)")  # fmt: skip
    return f"{head} (right)"


def _rule(args, expected, got) -> str:
    return (". The decal's depth can lie up to m (one pixel's depth slope: the task's budget, "
            "not the lesson's on-plane rounding) behind the wall's and must round strictly "
            "nearer: |o| ≥ r + m, negative (positive for reverse-Z), and at most room − m, "
            "so that the object in front still hides it (NaN when room − m < r + m)")  # fmt: skip


#: What the words hold back until the full words (:func:`.tries.staged`, r316 item 5): m, the
#: quantity the task derives, and the bounds and step counts that give it away.
HINTS = (
    (re.compile(r"m = \S+ \(\S+ steps?\)"), "m (yours to work out)"),
    # r425 F6: the two-sided rule, room's value and the NaN test held back with m: until two
    # answers have failed the words say only which condition fails
    (
        re.compile(
            r"the decal needs \|o\| from \S+ \(r \+ m\) to \S+ \(room − m, where room = "
            r"\S+: the object (\S+) in front, drawn before the decal, must still hide it\)"
        ),
        r"the decal needs an offset (big enough to win against the wall, small enough that the "
        r"object \1 in front, drawn before the decal, still hides it)",
    ),
    (
        re.compile(r"\(not enough: \S+ steps?, where the decal can lie [^)]*\)"),
        "(not enough: work out how far behind the wall the decal can lie)",
    ),
    (
        re.compile(
            r"\(too much: the decal at its nearest, \|o\| \+ m in front of the wall, is now "
            r"strictly nearer than the object (\S+) in front and shows through it\)"
        ),
        r"(too much: the decal shows through the object \1 in front)",
    ),
    ("room − m < r + m, no offset does both", "no offset does both here"),
    (
        ". The decal's depth can lie up to m (one pixel's depth slope: the task's budget, not the "
        "lesson's on-plane rounding) behind the wall's and must round strictly nearer: |o| ≥ r + m",
        ". Work out the window depth's change per pixel on the tilted wall, and how far behind "
        "the wall the decal can then be",
    ),
    (
        ", and at most room − m, so that the object in front still hides it (NaN when room − m "
        "< r + m)",
        ". Then how much is too much, with the object in front, and when does no offset do both?",
    ),
)


def _zero(args, expected, got) -> bool:
    return bool(np.isfinite(got)) and got == 0


ZERO = Mistake("zero", ": no offset: the two depths tie or the wall wins", fits=_zero, symptom=True)


def _nan_with_room(args, expected, got) -> bool | None:
    return (not impossible(args)) if bool(np.isnan(got)) else None


#: r340: a NaN the table does not name, said without "a 0/0": NaN is a legal answer here (a
#: `^` typo in r gives NaN on every case: :func:`constant_nan` names it, r374 F1)
NAN_WORDS = (
    "your answer holds NaN, “no offset works”, and this case has one (r + m ≤ room − m): check "
    "the r and m your test for NaN uses"
)


def _xor_gives(args) -> bool:
    """Does a complete solution with r typed as ``1 / (2^bits - 1)`` (run as 2 ^ (bits − 1),
    in its test for NaN too) return NaN on this case?"""
    z, tilt, pixel, near, far, bits, reverse, clear = args
    r, m = 1.0 / (2 ^ (bits - 1)), slope(z, tilt, pixel, near, far)
    return r + m > room(z, near, far, clear) - m


def constant_nan(results) -> str:
    """NaN on every case (r374 F1: a constant NaN was told a `^` typo it did not hold): how
    many cases have an offset that works, and the `^` words only where r computed with `^`
    gives NaN on every case too."""
    fits = sum(not impossible(r.args) for r in results)
    words = (f"your function returns NaN on every case, whatever its arguments, and {fits} of "
             f"the {len(results)} cases have an offset that works (r + m ≤ room − m): a "
             "placeholder left in, or a test for NaN that fires on every case")  # fmt: skip
    if all(_xor_gives(r.args) for r in results):
        words += (". If your r is typed `1 / (2^bits - 1)`: that NaN is what it gives, since "
                  f"{XOR_UNBRACKETED}")  # fmt: skip
    return words


#: r325: NaN is a legal answer here ("no offset works"), so an unnamed NaN is not "a 0/0"
NAN = Mistake(
    "nan", ": your answer holds NaN. NaN means “no offset works” here, and this case has one: "
    "r + m ≤ room − m. "
    "Your test for NaN fires where it should not: check the r and m it uses", fits=_nan_with_room,
    symptom=True,
)  # fmt: skip


def gives_same_offset(got, answer, args) -> bool:
    """A mistake gives the student's answer: NaN for NaN (no offset fits), else as
    :func:`.reverse_z.gives_same_gap`."""
    if answer is not None and np.isnan(answer) and np.isnan(got):
        return True
    return gives_same_gap(got, answer, args)


def draw_offset(ax, case, got):
    """|o| in steps of the buffer on a strip (symlog: one step beside thousands of m, where a
    linear axis put 0, 1 and yours on the left spine, r325 FIG1): the object's room, the
    accepted band and the smallest, m, and yours. Until the hints are spent and while yours
    fails, m and the bounds (which give it) are held back as the words hold them (r325 C1)."""
    from . import tries

    _, args, expected = case
    lo, hi = bounds(*args)
    r, m = step(args[5]), slope(*args[:5])
    space = room(args[0], args[3], args[4], args[7])
    ok = got is not None and bool(np.isfinite(got)) and same_offset(got, expected, args)
    full = tries.hints_spent("decal_bias") or ok
    # r425 F6: room's value held back with m, as the words hold it
    said = f": room = {num(space / r)} steps" if full else " in front"
    artists = [ax.axvline(space / r, color="#555555", label=f"the object{said}")]
    xs = [0.0, space / r]
    if not full:
        artists += ax.plot([], [], " ", label="accepted: enough to win against the wall (m yours "
                           "to work out), not so much that the decal shows through the object")  # fmt: skip
    elif impossible(args):
        artists.append(ax.axvline(hi / r, color="#2b7bba", linestyle="-.", label=f"room − m = "
                                  f"{num(hi / r, lo / r)} steps < r + m: no offset fits (NaN)"))  # fmt: skip
        xs.append(hi / r)
    else:
        artists.append(ax.axvspan(lo / r, hi / r, color="#d9ecd9", lw=0, zorder=0,
                                  label=f"accepted: {num(lo / r, hi / r)} to {num(hi / r, lo / r)}"
                                  " steps (r + m to room − m)"))  # fmt: skip
        artists.append(ax.axvline(lo / r, color="#2b7bba", label="smallest (expected): r + m"))
    if full:
        artists.append(ax.axvline(m / r, color="#888888", linestyle=":",
                                  label=f"m = {num(m / r)} steps: the decal's depth at worst"))  # fmt: skip
        xs += [lo / r, m / r]
    if got is not None and np.isfinite(got) and got != 0:
        x = abs(got) / r
        wrong_sign = (got > 0) != bool(args[6])
        # r425 F8: "yours -1 steps, as |o|" called a negative number an absolute value
        label = f"|yours| = {num(abs(got) / r)} steps" + (" (wrong sign)" if wrong_sign else "")
        artists.append(ax.axvline(x, color="#7fbf7f" if ok else "#d7301f", linestyle="--",
                                  lw=2, label=label))  # fmt: skip
        xs.append(x)
    elif got is not None:
        artists += ax.plot([], [], " ", label=f"yours {num(got)}: not drawn")
    zoom = full and lo / r >= ZOOM_FROM
    if zoom:
        artists.append(_zoom(ax, r, m, lo, hi, got, ok))
    ax.set_xscale("symlog", linthresh=1.0)
    ax.set_xlim(0.0, 2.0 * max(xs + [2.0]))
    ax.set_yticks([])
    ax.set_box_aspect(0.3)  # a number line, not a box (r325 FIG1)
    ax.set_xlabel(f"|offset| in steps of the {args[5]}-bit buffer")
    # under the axes, not beside them: its labels are long, and beside a notebook column's
    # figure they made it 1,040 px wide (the column holds 940)
    # below the zoom's panel where there is one (:func:`_zoom`)
    artists.append(ax.legend(fontsize="x-small", loc="upper center",
                             bbox_to_anchor=(0.5, -2.15 if zoom else -0.8)))  # fmt: skip
    return artists


#: From this many steps on, m, r + m and an answer a step apart share a pixel on the symlog
#: strip (r351 item 6): a second panel under the strip draws them on a linear scale.
ZOOM_FROM = 20.0


def _zoom(ax, r, m, lo, hi, got, ok):
    """A panel under the strip, on a linear scale around m and r + m (one step apart), with the
    accepted band and yours when it lies there (r374 F7: an inset in the strip's empty left
    part read as part of the log axis, its ticks at xx-small)."""
    panel = ax.inset_axes([0.0, -1.45, 1.0, 0.55])
    x0, x1 = m / r - 1, lo / r + 1.5
    panel.axvspan(lo / r, hi / r, color="#d9ecd9", lw=0, zorder=0)
    panel.axvline(m / r, color="#888888", linestyle=":")
    panel.axvline(lo / r, color="#2b7bba")
    if got is not None and np.isfinite(got) and x0 <= abs(got) / r <= x1:
        panel.axvline(abs(got) / r, color="#7fbf7f" if ok else "#d7301f", linestyle="--", lw=2)
    panel.set_xlim(x0, x1)
    panel.set_xticks([m / r, lo / r], ["m", "r + m"], fontsize="small")
    panel.set_yticks([])
    panel.set_xlabel("zoom on m and r + m: linear, 1 step apart", fontsize="small")
    return panel


def _mistakes() -> list[Mistake]:
    """The table, each slip of m that :data:`_READS` names told apart by what the code reads."""
    table = variant_mistakes(_variants, MISTAKES, (ZERO, NAN))
    return [dataclasses.replace(m, **_READS.get(m.kind, {})) for m in table]


DECAL_BIAS = Exercise(
    "decal_bias", bias_cases, as_lone_number, same_offset, explain_offset, _rule,
    _mistakes(), draw=draw_offset, match=gives_same_offset,
    float32=lambda args: expected_offset(*args),
    answers=(PackageAnswer(expected_offset, words=CHECKER_WORDS),),
    hints=HINTS,
    nan_words=NAN_WORDS,
    constant_nan=constant_nan,
)  # fmt: skip
