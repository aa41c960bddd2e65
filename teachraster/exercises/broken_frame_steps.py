"""Exercise ``broken_frame_3_steps`` (lesson 11 with 05b): how many depth bits frame 3 needs.

Frame 3 of :mod:`.broken_frames` loses its pane to a tie in a 16-bit depth buffer: the pane is
drawn less than a step of the buffer nearer than the wall. Review r377 F4: the question before
this one (the wall's and the intended pane's whole numbers, and the steps between) was a
transcription, the unorm16 rule stated in words and one multiplication. This one needs lesson
05b's depth-precision reasoning: the fewest bits n of a unorm depth buffer (a depth d stored as
round(d · (2ⁿ − 1)), GL 4.6 §2.3.5, rounding half to even here) in which the pane, the same
distance in front of the wall as frame 3 draws it, wins the depth test at whatever depth the
two are drawn (r388 G5: "drawn where frame 3 draws it ... wherever the wall lies", read
literally, moved the wall alone): two depths more than a whole step 1/(2ⁿ − 1) apart are always
stored as different whole numbers, closer ones tie at some depths (exactly a step apart, two
halves can round to one even number: r388 G6), so n is the least with gap · (2ⁿ − 1) > 1. The
gap is read off the frame's trace (``frame.trace.window[k, :, 2]``, the depths the triangles
are drawn at, unrounded): the histories print depths as the 16-bit buffer stores them, the
pane's tied at the wall's.

The check hands the function the frame shown and frame 3 redrawn four times with another wall
and the pane another distance from it (:func:`.broken_frames.frame_3_gap`), so a number typed
in fails, and chosen so that each slip fails a case (r388 G1-G3): a gap whose log₂(1/gap) has a
fraction below ½ (rounded to the nearest bit), a gap just above 1/2²⁰ (a step of 1/2ⁿ for
1/(2ⁿ − 1)), a wall off the 16-bit grid (the pane's stored depth minus its drawn one for the
gap) whose depths, rounded to six decimals, are one. Each slip is named only where it gives
every answer (r388 G4: "this wall's depth only" named on one case, of depths rounded to six
decimals): also one bit too many, ln or log10 for log₂, one bit short, the intended pane's gap,
the frame shown's number typed in; the gap in 16-bit steps returned, a gap of 0 (the
histories' depths, tied, or six decimals) and a negative one (the pane's depth minus the
wall's) are explained failures.
"""

from __future__ import annotations

import math
import re

import numpy as np

from . import tries
from .answers import refuse_non_answers, short
from .broken_frames import broken_frame, frame_3_gap
from .diagnosis import constant_words
from .exercise import Exercise, Mistake
from .report import NOTHING_DRAWN_FOR
from .running import WrongAnswerType

#: The pixel whose history names the pane (any pixel of the pane: it lies parallel to the wall).
PIXEL = (13, 52)
#: What the answer is, as the notebook's question and every wrong answer's words say it.
WHAT = ("the fewest bits of a unorm depth buffer in which frame 3's pane, the same distance in "
        "front of the wall as frame 3 draws it, wins the depth test at whatever depth the two "
        "are drawn")  # fmt: skip
#: How far nearer than the wall (in depth) the redrawn frames draw the pane, with which of the
#: redrawn looks, and how far (in 16-bit steps) the wall lies off that look's grid point:
#: bit counts other than the frame shown's 20 (22, 19, 21), and walls where the fewest bits at
#: the wall's depth alone differ from case to case (17, 22, 17, 19: fixed looks), the answer
#: on one case only.
#: r388 G1-G3: 3e-6 (log₂(1/gap) = 18.35, a fraction below ½: rounded to the nearest, 18);
#: 1/(2²⁰ − 0.75), just above 1/2²⁰ (a step of 1/2ⁿ: 20; r395 N4: inside (2ⁿ − 1, 2ⁿ), not at
#: its midpoint, so "a half-step margin", log₂(1/gap + ½), fails without float noise); the wall 0.33 of a 16-bit step below
#: the grid (the pane's stored depth minus its drawn one: 18), where a six-decimal boundary
#: falls between the wall and the pane (rounded so, 1e-6 apart: 20, where a step of 1/2ⁿ
#: gives the answer, 22; both give 20 on the third redraw).
#: r395 N1: a wall at 0.2, far from the others' 0.65-0.7, so that the depth divided by the gap
#: (a float buffer's relative precision: 16) is not log₂(1/gap) (18).
GAPS = ((3e-7, 0, -0.33), (3e-6, 1, 0.0), (1 / (2**20 - 0.75), 2, 0.0), (5e-6, 1, -19661.0))
#: The most bits the question considers: float64's mantissa (53) and more say nothing new.
MOST = 53


def _records(b, frame=None) -> tuple:
    """(the wall's record, the pane's) in ``frame``'s (the broken frame's) history of
    :data:`PIXEL`: the opaque fragment shown, and the glass."""
    frame = frame or b.frame
    records = frame.history(*PIXEL).records
    wall = next(r for r in records if r.outcome == "passed" and r.color[3] == 1)
    pane = next(r for r in records if r.outcome != "not_covered" and r is not wall
                and r.depth is not None and np.isfinite(r.depth))  # fmt: skip
    return wall, pane


def _drawn(b, frame=None) -> tuple[float, float]:
    """(the wall's depth, the pane's) as ``frame`` (the broken frame by default) draws them:
    the trace's window depth of the opaque fragment shown at :data:`PIXEL` and of the glass."""
    frame = frame or b.frame
    wall, pane = _records(b, frame)
    z = frame.trace.window[:, :, 2]
    return float(z[wall.piece].mean()), float(z[pane.piece].mean())


def _gap(b, frame=None) -> float:
    wall, pane = _drawn(b, frame)
    return wall - pane


def _bits(gap: float) -> int | None:
    """The least n with gap · (2ⁿ − 1) > 1: more than a whole step of an n-bit buffer (None
    for a gap of 0 or less)."""
    if not gap > 0:
        return None
    return next((n for n in range(1, MOST + 1) if gap * (2**n - 1) > 1), MOST + 1)


def _here(b) -> int | None:
    """The fewest bits at which the pane wins at this wall's depth alone (by where the wall
    lies on that buffer's grid): a mistake, not the question's answer."""
    wall, pane = _drawn(b)
    return next((n for n in range(1, MOST + 1)
                 if round(pane * (2**n - 1)) < round(wall * (2**n - 1))), None)  # fmt: skip


def _six(b) -> tuple[float, float]:
    """The wall's depth and the pane's rounded to the six decimals the histories print."""
    return tuple(round(d, 6) for d in _drawn(b))


def _stored_minus_drawn(b) -> float:
    """The pane's depth as the history prints it (stored) minus the depth it is drawn at."""
    return float(_records(b)[1].depth) - _drawn(b)[1]


def _cases():
    """The frame shown and frame 3 redrawn four times, the pane other distances from the
    wall (:data:`GAPS`)."""
    frames = [broken_frame(3), *(frame_3_gap(*g) for g in GAPS)]
    names = ("the frame shown", "the frame redrawn", "the frame redrawn again",
             "the frame redrawn a third time", "the frame redrawn a fourth time")  # fmt: skip
    return [(name, (b,), _bits(_gap(b))) for name, b in zip(names, frames, strict=True)]


def as_bits(value) -> int:
    """One whole number of bits, 1 or more (judged by its value: 20.0 is 20)."""
    refuse_non_answers(value, "one whole number, " + WHAT)
    if isinstance(value, bool | np.bool_):
        raise WrongAnswerType(f"returned {short(value)}, a bool: return {WHAT}, a whole number")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {short(value)}: return {WHAT}, one whole number") from None
    if np.isnan(x):
        raise WrongAnswerType(f"returned {short(value)}{NEGATIVE}")
    if not np.isfinite(x):
        raise WrongAnswerType(
            f"returned {short(value)}: a finite whole number, {WHAT} (as the histories print "
            "them, the pane's depth and the wall's are equal: the depths the triangles are "
            "drawn at are in frame.trace.window[k, :, 2])"
        )
    if not x.is_integer() or x < 1:
        raise WrongAnswerType(f"returned {short(value)}: bits come in whole numbers, 1 or more")
    return int(x)


def _call(fn, args):
    """``fn``'s answer read by :func:`as_bits`; the gap counted in 16-bit steps (the number of
    the question 11.3b asked before r377) told as such (r388 G7)."""
    value = fn(*args)
    try:
        return as_bits(value)
    except WrongAnswerType:
        (b,) = args
        if _close(value, _gap(b) * 65535):
            raise WrongAnswerType(
                f"returned {short(value)}: that is the gap counted in steps of the 16-bit buffer "
                "(gap · 65535); the question asks for a number of bits, the fewest with which "
                "the pane wins at whatever depth the two are drawn"
            ) from None
        raise


def _close(value, x: float) -> bool:
    try:
        return math.isclose(float(value), x, rel_tol=1e-6)
    except (TypeError, ValueError, OverflowError):
        return False


def _same(got, expected, args=None) -> bool:
    return got == expected


def _explain(args, expected, got) -> str:
    (b,) = args
    what = "frame 3" if b is broken_frame(3) else "frame 3 redrawn"
    return f"{what}: yours is {got} bits"


#: The reasoning, said once two answers have failed (until then, :data:`HINTS`' words).
RULE = (": two depths more than a whole step 1/(2ⁿ − 1) apart are always stored as different "
        "whole numbers; closer ones tie wherever no rounding boundary falls between them (and "
        "exactly a step apart, two halves may round to one even number), so n is the least "
        "with gap · (2ⁿ − 1) > 1")  # fmt: skip


def _answer_for(n: int) -> str:
    """The gaps for which ``n`` bits is the answer: more than 1/(2ⁿ − 1), up to 1/(2ⁿ⁻¹ − 1)."""
    lo = f"{n} bits would be the answer for a gap above {1 / (2**n - 1):.4g}"
    return lo if n == 1 else f"{lo} up to {1 / (2 ** (n - 1) - 1):.4g}"


def _rule(args, expected, got) -> str:
    (b,) = args
    return (f"{RULE} (lesson 05b), the gap being the wall's depth minus the pane's, as the "
            "trace holds them (frame.trace.window[k, :, 2], unrounded); "
            f"{_answer_for(got)}; this pane's gap is {_gap(b):.4g}")  # fmt: skip


#: What the frame shown's number, typed in, is told.
TYPED = (": that is frame 3's number as shown; this is frame 3 redrawn with another wall and "
         "its pane another distance from it, so read the depths inside your function, off "
         "b.frame.trace.window[k, :, 2]")  # fmt: skip
#: The intended pane's gap, which the intended frames draw alike (1e-3: 10 bits in every
#: case, so a constant answer), told as the slip it is.
INTENDED = (": that is the intended pane's gap (the intended frame draws it farther from the "
            "wall); the question asks for frame 3's pane, where the broken frame draws it: "
            "b.frame.trace.window[k, :, 2]")  # fmt: skip
#: The fewest bits at this wall's depth alone (:func:`_here`), told as the slip it is.
HERE = (": at this wall's depth the pane already wins with that many bits, by where the wall "
        "lies on that buffer's grid (a rounding boundary falls between the two depths); the "
        "question asks from how many bits on it wins at whatever depth the two are drawn, the "
        "same distance apart")  # fmt: skip
#: A negative gap (the pane's depth minus the wall's), said of a NaN returned or raised.
NEGATIVE = (": a NaN, the logarithm of a negative number? The pane is drawn nearer than the "
            "wall, so the gap is the wall's depth minus the pane's; the pane's minus the "
            "wall's is negative")  # fmt: skip


def _constant(value) -> str:
    """The frame shown's number typed in fails every redrawn frame, and the intended pane's
    gap is the same in every case (the fewest bits at the wall's depth is said only where it
    is the number on two cases or more: r388 G4): each said as its slip, other constants as
    every check says them."""
    b = broken_frame(3)
    try:
        x = float(value)
    except (TypeError, ValueError):
        return constant_words(value)
    if x == _bits(_gap(b)):
        return TYPED.removeprefix(": ")
    if x == _bits(_gap(b, b.intended)):
        return INTENDED.removeprefix(": ")
    if sum(x == _here(a) for _, (a,), _ in _cases()) >= 2:
        return HERE.removeprefix(": ")
    if (
        math.isfinite(x)
        and x == int(x)
        and x <= 1000
        and x >= TIED + max(e for _, _, e in _cases())
    ):
        return _tied_words(int(x))
    return constant_words(value)


#: How many bits beyond every case's answer a constant is read as a gap of 0 with an ε added
#: (r395 N2: 40, from the histories' tied depths and 1e-12, was told "a placeholder").
TIED = 8


def _tied_words(n: int) -> str:
    """A huge constant: the answer for a gap of about 0, the histories' tied depths plus ε."""
    return (
        f"{_answer_for(n)}: a gap of about 0, the histories' depths tied with a tiny ε added? The "
        "histories print depths as the 16-bit buffer stores them, the pane's tied at the "
        "wall's: the depths the triangles are drawn at are in frame.trace.window[k, :, 2]"
    )


def _raised(args, error: str) -> str:
    """A gap of 0 divided by (the histories' depths: the pane's stored tied at the wall's; or
    the depths rounded to six decimals), and a negative gap's NaN."""
    (b,) = args
    if "NaN" in error or "invalid value" in error:
        return f" ({NEGATIVE.removeprefix(': ')})"
    if not any(w in error for w in ("ZeroDivisionError", "divide by zero", "infinity")):
        return ""
    wall, pane = _six(b)
    if wall == pane:
        return (f" (a gap of 0? rounded to six decimals the wall's depth and the pane's are "
                f"both {wall:.6f}: the six decimals are for the evidence of 11.1 to 11.9; "
                "read these depths unrounded, off frame.trace.window[k, :, 2])")  # fmt: skip
    return (" (a gap of 0? the histories print depths as the 16-bit buffer stores them, the "
            "pane's tied at the wall's: the depths the triangles are drawn at are in "
            "frame.trace.window[k, :, 2])")  # fmt: skip


def _of_gap(b, f):
    """``f(gap)`` of the drawn gap (None where it is undefined: a mistake says nothing)."""
    gap = _gap(b)
    return f(gap) if gap > 0 else None


def _six_words(args, expected, got) -> str:
    (b,) = args
    (wall, pane), (w6, p6) = _drawn(b), _six(b)
    return (f": {got} bits is the answer for a gap of {w6 - p6:.4g}, the depths' difference "
            f"rounded to six decimals ({w6:.6f} − {p6:.6f}); the trace's depths, {wall:.10f} "
            f"and {pane:.10f}, are {wall - pane:.4g} apart: the six decimals are for the "
            "evidence of 11.1 to 11.9; read these depths unrounded")  # fmt: skip


def _stored_words(args, expected, got) -> str:
    (b,) = args
    wall, pane = _records(b)
    drawn = _drawn(b)[0]
    return (f": {got} bits is the answer for {_stored_minus_drawn(b):.4g}, the pane's stored "
            "depth (as the history prints it) minus its drawn one: that is how far the 16-bit "
            "buffer rounds the pane, which is the gap only where the wall lies on that "
            f"buffer's grid; this wall does not (drawn at {drawn:.10f}, stored as "
            f"{wall.depth:.10f}): the gap is the wall's drawn depth minus the pane's")  # fmt: skip


def _nearest_words(args, expected, got) -> str:
    """Rounded to the nearest bit, said only where log₂(1/gap)'s fraction is below ½ (r395 N3:
    elsewhere nearest and up agree, and the slip is the step of 1/2ⁿ)."""
    (b,) = args
    gap = _gap(b)
    log = math.log2(1 / gap)
    if not log % 1 < 0.5:
        return _power_words(args, expected, got)
    return (f": log₂ rounded to the nearest bit? Here log₂(1/gap) is {log:.8f}, "
            f"whose fraction is below ½; with {got} bits the gap is "
            f"{gap * (2**got - 1):.8f} of a step, less than a whole one, and the two depths "
            "tie wherever no rounding boundary falls between them: round up")  # fmt: skip


def _power_words(args, expected, got) -> str:
    """A step of 1/2ⁿ, or (the same answers on every case: r399 F3) a count of steps between
    2ⁿ − 1 and 2ⁿ, such as a half-step margin (gap · (2ⁿ − ½) ≥ 1)."""
    (b,) = args
    gap = _gap(b)
    return (f": a step of 1/2ⁿ? (Or a count of steps between 2ⁿ − 1 and 2ⁿ, such as a half-step "
            f"margin, 2ⁿ − ½?) An n-bit unorm buffer stores 0 to 1 in 2ⁿ − 1 steps, each "
            f"1/(2ⁿ − 1) (lesson 05b): with {got} bits the gap is {gap * 2**got:.8f} of 1/2^{got} "
            f"but {gap * (2**got - 1):.8f} of a step, not more than a whole one, so the two "
            "depths still tie at some depths")  # fmt: skip


def _relative_words(args, expected, got) -> str:
    (b,) = args
    wall, gap = _drawn(b)[0], _gap(b)
    return (f": the depth divided by the gap (a float buffer's relative precision, lesson 05b's "
            f"reverse-Z)? Here log₂(wall/gap) is {math.log2(wall / gap):.4f}, the wall drawn at "
            f"{wall:.4f}; unorm steps are the same size, 1/(2ⁿ − 1), at every depth, so the "
            f"depth does not enter: with {got} bits the gap is {gap * (2**got - 1):.8f} of a "
            "step")  # fmt: skip


def _more_words(args, expected, got) -> str:
    (b,) = args
    fewer = got - 1
    return (f": one bit too many: with {fewer} bits the gap is already "
            f"{_gap(b) * (2**fewer - 1):.3g} steps, more than a whole one, so the pane wins "
            "at whatever depth the two are drawn")  # fmt: skip


def _log_words(name: str):
    def words(args, expected, got) -> str:
        (b,) = args
        return (f": {name} in place of log₂? Bits count powers of 2: with {got} bits a unorm "
                f"buffer has 2^{got} − 1 = {2**got - 1} steps, and the gap is "
                f"{_gap(b) * (2**got - 1):.3g} of one")  # fmt: skip

    return words


#: The closed form a bit short gives, said in the full words only (r399 F5: on the first
#: failure it gave the answer, log₂(1 + 1/gap) rounded up, away; :data:`HINTS`).
STEP_SHORT_FORM = " (log₂(1 + 1/gap) rounded down?)"

MISTAKES = [
    # r388 G4: each named only where it gives every answer (a gives, run on every case, the
    # passing ones too): "this wall's depth only", per case, named a six-decimal gap's 20
    Mistake("this wall's depth only", HERE, gives=_here),
    Mistake("depths rounded to six decimals", _six_words,
            gives=lambda b: _bits(_six(b)[0] - _six(b)[1])),
    Mistake("stored minus drawn", _stored_words, gives=lambda b: _bits(_stored_minus_drawn(b))),
    Mistake("the depth divided by the gap", _relative_words,
            gives=lambda b: _of_gap(b, lambda g: math.ceil(math.log2(_drawn(b)[0] / g)))),
    Mistake("rounded to the nearest bit", _nearest_words,
            gives=lambda b: _of_gap(b, lambda g: round(math.log2(1 / g)))),
    Mistake("a step of 1/2ⁿ", _power_words,
            gives=lambda b: _of_gap(b, lambda g: math.ceil(math.log2(1 / g)))),
    Mistake("one bit too many", _more_words, gives=lambda b: _of_gap(b, lambda g: _bits(g) + 1)),
    Mistake("ln for log₂", _log_words("ln"),
            gives=lambda b: _of_gap(b, lambda g: math.ceil(math.log(1 + 1 / g)))),
    Mistake("log10 for log₂", _log_words("log10"),
            gives=lambda b: _of_gap(b, lambda g: math.ceil(math.log10(1 + 1 / g)))),
    # half a step's n and log₂(1 + 1/gap) rounded down are one bit short alike
    Mistake("a step short", lambda a, e, g: f": with {g} bits the gap is half a step or "
            f"more, short of a whole one{STEP_SHORT_FORM}; two depths less than a step apart "
            "are still stored alike wherever both round to the same whole number: round up, "
            "to more than a whole step", fits=lambda a, e, g: g == e - 1),
    Mistake("the intended pane", INTENDED, gives=lambda b: _bits(_gap(b, b.intended))),
]  # fmt: skip

#: The reasoning (with the gaps the student's number answers), said as a hint until two
#: different answers have failed.
HINTS = (
    # r395 N5: the hint a sentence of its own, the gap's words the next one
    (f"{RULE} (lesson 05b), the gap being", ": how far apart must two depths be for an n-bit "
     "buffer to store them as different whole numbers whatever they are (lesson 05b)? The gap "
     "is"),
    (re.compile(r"; \d+ bits would be the answer for a gap above \S+( up to \S+)?; this pane's "
                r"gap is \S+$"), ""),
    # r399 F5: a bit short, the closed form waits for the full words
    (STEP_SHORT_FORM, ""),
)  # fmt: skip


def _draw(ax, case, got):
    """The gap in steps of the student's n-bit buffer, gap · (2ⁿ − 1) (a cross, its value
    written), and the whole step (dashed) once the words give the rule (the hints spent) or
    the answer passed (r388 G8): never the curve over n, whose crossing would be the answer.
    Until then the axis is "the gap in steps", its formula unnamed (r399 F5)."""
    (b,) = case[1]
    artists = []
    told = tries.hints_spent("broken_frame_3_steps") or got == case[2]
    if told:
        artists.append(ax.axhline(1.0, color="#888888", linestyle="--"))
        artists.append(ax.annotate("a whole step", (0.01, 1.0), va="bottom", fontsize="x-small",
                                   xycoords=("axes fraction", "data")))  # fmt: skip
    ax.set_yscale("log")
    ax.set_ylim(0.1, 10)
    if isinstance(got, int) and 1 <= got <= MOST:
        steps = _gap(b) * (2.0**got - 1)
        artists += ax.plot([got], [steps], "x", color="#d7301f", ms=11, mew=2)
        below = steps < 1  # the words on the side away from the dashed line (r388 G8)
        artists.append(ax.annotate(f"{got} bits: the gap is {steps:.3g} steps", (got, steps),
                                   xytext=(8, -12 if below else 12), textcoords="offset points",
                                   va="top" if below else "bottom", fontsize="x-small"))  # fmt: skip
        ax.set_xlim(got - 8, got + 8)
        ax.set_ylim(min(0.1, steps / 3), max(10, steps * 3))
    ax.set_xlabel("bits n of the depth buffer; ×: yours", fontsize="small")
    # r399 F5: the criterion's form only once the words give it
    ax.set_ylabel(
        "gap · (2ⁿ − 1)" if told else "the gap in steps of\nan n-bit buffer", fontsize="small"
    )
    return artists


#: The exercise, for the registry.
BROKEN_FRAME_3_STEPS = Exercise(
    "broken_frame_3_steps", _cases, as_bits, _same, _explain, _rule, MISTAKES, draw=_draw,
    reference=("teachraster.exercises.broken_frames",), hints=HINTS, constant=_constant,
    raised_words=_raised, call=_call,
)  # fmt: skip

# r395 N6: the stub's note says what this figure draws (never the answer: r388 G8)
NOTHING_DRAWN_FOR[BROKEN_FRAME_3_STEPS.name] = (
    "Nothing drawn yet: once your function returns answers, the check draws its first failing "
    "case (or, when all pass, one of the cases): your number of bits and the gap in steps of "
    "that buffer, never the rule's answer"
)
