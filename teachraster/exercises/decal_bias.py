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
out a rounding apart, the case m → 0 of this model, where a step or a few suffice (r316 C4).
The decal wins at every pixel iff |o| ≥ r + m; an opaque object ``clear`` in front of the wall
on the view axis, drawn before the decal (a tie keeps it), still hides the decal iff
|o| ≤ z_win(z) − z_win(z − clear) − m (r316 item 3: llvmpipe's r of two steps passes). When
that is less than r + m no offset does both, and the answer is NaN (:data:`TIGHT`: a solution
ignoring ``clear`` fails there). With reverse-Z (1 − z_win stored, greater wins) the sign
flips.

An answer is judged by that criterion, not closeness: any offset of the right sign between
the two bounds passes (float32's rounding, :data:`ROUNDING`, allowed at both ends). The expected
answer is the smallest, the package's :func:`teachraster.pipeline.depth.depth_bias` with
units and factor −1 (+1 under reverse-Z).
"""

from __future__ import annotations

import copy
import math
import re
from functools import cache

import numpy as np

from ..pipeline.visibility.depth import depth_bias, window_depth
from .answers import as_number
from .cases import DRAWN, drawn_rng
from .exercise import Exercise, Mistake, PackageAnswer, variant_mistakes
from .near_plane import HALF_STEP
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
#: float32's relative rounding, allowed at both ends: a tilt held in float32 moves tan θ by
#: up to 3e-6 of itself at 88° (tan's relative slope there is 1/(sin θ cos θ) ≈ 29).
ROUNDING = 1e-5


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


def _case(setting, label=None, share=ROOM + 1):
    *head, reverse = setting
    clear = _clear(*head, share=share)
    args = (*head, reverse, clear)
    z, tilt, pixel, near, far, bits = head
    label = label or (f"z = {num(z)}, tilt {num(tilt)}°, pixel {num(pixel)}, near = {num(near)}, "
                      f"far = {num(far)}, {bits} bits{', reverse-Z' if reverse else ''}, "
                      f"clear {num(clear)}")  # fmt: skip
    return label, args, expected_offset(*args)


@cache
def _fixed_cases():
    return [_case(s) for s in SETTINGS] + [_case(s, share=TIGHT_SHARE) for s in TIGHT]


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
    """The offsets typical slips give (each one change), signed as the case needs."""
    r, m = step(bits), slope(z, tilt, pixel, near, far)
    sign = 1.0 if reverse else -1.0
    tight = impossible((z, tilt, pixel, near, far, bits, reverse, clear))
    return {
        "clear ignored": sign * (r + m) if tight else None,
        "z squared": sign * (r + m / z),
        "sign": -sign * (r + m),
        "reverse ignored": -(r + m),
        "no tie": sign * m,
        "no slope": sign * r,
        "in steps": sign * (1 + m / r),
        "view slope": sign * (r + pixel * z * math.tan(math.radians(tilt))),
        "degrees": sign * (r + m * math.tan(tilt) / math.tan(math.radians(tilt)))
        if 0 < tilt < 90
        else None,
        "per unit": sign * (r + m / pixel),
        "2^bits": sign * (1.0 / 2**bits + m),
        "half": sign * (r / 2 + m),
    }


def _m_said(m, r) -> str:
    """m as the words say it: the one form :data:`HINTS` hold back until the full words."""
    return f"m = {num(m)} ({num(m / r)} steps)"


MISTAKES = {
    "clear ignored": lambda a, e, g: (
        f": your offset ignores `clear`: the object only {num(a[7])} in front leaves room − m "
        "less than r + m, so no offset draws the decal over the wall and keeps the object in "
        "front: return NaN here (an offset this size puts the decal in front of the object)"
    ),
    "z squared": ": your slope is the wall's divided by z: dz_win/dz = f n/((f − n) z²) is "
    "per unit of view depth, and one pixel moves the wall's view depth by z · tan θ · pixel "
    "(1/z' = (1 − s tan θ)/z), so one z cancels",
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
    "no tie": ": you offset the decal by the pixel's depth span m alone. At the worst rounding "
    "both depths then store one value, and a tie keeps the wall (drawn first; the test is "
    "strict): one step r more makes the decal strictly nearer, |o| = r + m",
    "no slope": lambda a, e, g: (
        f": you left out the slope term: one step r covers a tie, the lesson's decal on the "
        f"wall's own plane (its depths a rounding apart), not this task's budget. Here the two "
        f"depths at a pixel can differ by one pixel's slope {_m_said(slope(*a[:5]), step(a[5]))}"
        ", so |o| = r + m"
    ),
    "in steps": ": that offset is counted in steps of the buffer (DepthBias's units), not in "
    "window depth: one step is r = 1/(2^bits − 1), and o = units·r + factor·m is a depth",
    "view slope": ": you took the slope of the view depth z per pixel (pixel·z·tan θ), not of "
    "the window depth the buffer stores: multiply by dz_win/dz = f n/((f − n) z²)",
    "degrees": ": the tilt is in degrees and the tangent takes radians: tan(np.radians(tilt))",
    "per unit": ": your slope is per unit of x/z, not per pixel: one pixel spans `pixel` of "
    "it, so MaxDepthSlope is that slope times pixel",
    "2^bits": lambda a, e, g: (
        f": you took r as 1/2^{a[5]}: the largest stored integer, 2^{a[5]} − 1, holds depth 1, "
        f"so one step is 1/(2^{a[5]} − 1), and yours falls short of a step by a hair: at the "
        "worst rounding the two depths tie"
    ),
    "half": f": {HALF_STEP}. Beyond the pixel's span m the decal needs a whole step r",
}


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
            f"{'positive' if reverse else 'negative'}; yours is {num(got, lo)}")  # fmt: skip
    if impossible(args):
        if np.isnan(got):
            return f"{head} (right: room − m < r + m, no offset does both)"
        return f"{head}: room − m < r + m, no offset does both, and the answer is NaN"
    if not np.isfinite(got) or got == 0 or (got > 0) != bool(reverse):
        return head
    if abs(got) < lo * (1 - ROUNDING):
        return (f"{head} (not enough: {num(abs(got) / r, lo / r)} steps, where the decal can "
                f"lie {num(m / r)} steps behind and must end a whole step nearer, "
                f"{num(lo / r, abs(got) / r)} steps)")  # fmt: skip
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
    (re.compile(r"m = \S+ \(\S+ steps\)"), "m (yours to work out)"),
    (re.compile(r"from \S+ \(r \+ m\) to \S+ \(room − m, where"), "from r + m to room − m (where"),
    (
        re.compile(r"\(not enough: \S+ steps, where the decal can lie [^)]*\)"),
        "(not enough: work out how far behind the wall the decal can lie)",
    ),
    (
        ". The decal's depth can lie up to m (one pixel's depth slope: the task's budget, not the "
        "lesson's on-plane rounding) behind the wall's and must round strictly nearer: |o| ≥ r + m",
        ". Work out the window depth's change per pixel on the tilted wall, and how far behind "
        "the wall the decal can then be",
    ),
)


def _zero(args, expected, got) -> bool:
    return bool(np.isfinite(got)) and got == 0


ZERO = Mistake("zero", ": no offset: the two depths tie or the wall wins", fits=_zero, symptom=True)


def draw_offset(ax, case, got):
    """|o| beyond the pixel's depth slope m, in steps of the buffer (linear: a missing tie step
    is one step, which a log axis of |o| hid beside thousands of steps of m): the accepted
    band, the smallest and yours (an arrow when it lies off the axis)."""
    _, args, expected = case
    lo, hi = bounds(*args)
    s, m = 1.0 / step(args[5]), slope(*args[:5])
    top = (hi - m) * s  # the most the object in front leaves, beyond m
    if impossible(args):  # the object leaves less than a step beyond m: nothing to accept
        artists = [ax.axvline(top, color="#2b7bba", label=f"the object: {num(top, 1.0)} "
                              "steps beyond m, short of 1: no offset fits (NaN)")]  # fmt: skip
    else:
        artists = [ax.axvspan(1.0, top, color="#d9ecd9", lw=0, zorder=0,
                              label=f"accepted: 1 to {num(top, 1.0)} steps beyond m")]  # fmt: skip
        artists.append(ax.axvline((abs(expected) - m) * s, color="#2b7bba",
                                  label="smallest (expected): one step beyond"))  # fmt: skip
    artists.append(ax.axvline(0.0, color="#888888", linestyle=":",
                              label=f"m = {num(m * s)} steps: the decal's depth at worst"))  # fmt: skip
    left, right = min(-1.0, 1.1 * top), max(2.0, 1.3 * top)  # a tight case's object: left of m
    if got is not None and np.isfinite(got) and got != 0:
        colour = "#7fbf7f" if same_offset(got, expected, args) else "#d7301f"
        x = (abs(got) - m) * s
        beyond = f"{x:.4g}" if abs(x) >= 1e-6 else "0"  # float64's residue of m − m is 0
        label = f"yours {got * s:.6g} steps" + (
            ": wrong sign" if (got > 0) != bool(args[6]) else f", {beyond} beyond m"
        )
        if -10 <= x <= 10 * right:
            right, left = max(right, 1.1 * x), min(left, 1.1 * x)
            artists.append(ax.axvline(x, color=colour, linestyle="--", label=label))
        else:  # off this axis: said at the side it lies on
            at, ha, arrow = (right, "right", "→") if x > 0 else (left, "left", "←")
            artists += ax.plot([], [], " ", label=label)
            artists.append(ax.text(at, 0.5, f"yours {arrow}", color=colour, ha=ha, va="center",
                                   transform=ax.get_xaxis_transform(), fontsize="small"))  # fmt: skip
    elif got is not None:
        artists += ax.plot([], [], " ", label=f"yours {num(got)}: not drawn")
    ax.set_xlim(left, right)
    ax.set_yticks([])
    ax.set_xlabel(f"|offset| − m, in steps of the {args[5]}-bit buffer (1/(2^{args[5]} − 1))")
    # under the axes, not beside them: its labels are long, and beside a notebook column's
    # figure they made it 1,040 px wide (the column holds 940)
    artists.append(ax.legend(fontsize="x-small", loc="upper center", bbox_to_anchor=(0.5, -0.3)))
    return artists


DECAL_BIAS = Exercise(
    "decal_bias", bias_cases, as_number, same_offset, explain_offset, _rule,
    variant_mistakes(_variants, MISTAKES, (ZERO,)), draw=draw_offset, match=gives_same_gap,
    float32=lambda args: expected_offset(*args),
    answers=(PackageAnswer(expected_offset, words=CHECKER_WORDS),),
    hints=HINTS,
)  # fmt: skip
