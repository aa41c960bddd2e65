"""Exercise ``broken_frame_3_steps`` (lesson 11 with 05b): how many depth bits frame 3 needs.

Frame 3 of :mod:`.broken_frames` loses its pane to a tie in a 16-bit depth buffer: the pane is
drawn less than a step of the buffer nearer than the wall. Review r377 F4: the question before
this one (the wall's and the intended pane's whole numbers, and the steps between) was a
transcription, the unorm16 rule stated in words and one multiplication. This one needs lesson
05b's depth-precision reasoning: the fewest bits n of a unorm depth buffer (a depth d stored as
round(d · (2ⁿ − 1)), GL 4.6 §2.3.5) in which the pane, drawn where frame 3 draws it, wins the
depth test wherever the wall lies: two depths a whole step 1/(2ⁿ − 1) apart or more are always
stored as different whole numbers, and closer ones tie at some depths, so n is the least with
gap · (2ⁿ − 1) ≥ 1, that is ⌈log₂(1 + 1/gap)⌉. The gap is read off the frame's trace
(``frame.trace.window[k, :, 2]``, the depths the triangles are drawn at): the histories print
depths as the 16-bit buffer stores them, the pane's tied at the wall's.

The check hands the function the frame shown and frame 3 redrawn twice with another wall and
the pane another distance from it (:func:`.broken_frames.frame_3_gap`), so a number typed in
fails. Typical mistakes named: the fewest bits at this wall's depth only (where the wall lies on
the grid may part them sooner), one bit short (half a step for a whole one, or log₂ rounded
down), the intended pane's gap (the same in every case), the frame shown's
number typed in, and a gap of 0 divided by (the histories' depths, tied).
"""

from __future__ import annotations

import numpy as np

from .answers import refuse_non_answers, short
from .broken_frames import broken_frame, frame_3_gap
from .diagnosis import constant_words
from .exercise import Exercise, Mistake
from .running import WrongAnswerType

#: The pixel whose history names the pane (any pixel of the pane: it lies parallel to the wall).
PIXEL = (13, 52)
#: What the answer is, as the notebook's question and every wrong answer's words say it.
WHAT = ("the fewest bits of a unorm depth buffer in which frame 3's pane, drawn where frame 3 "
        "draws it, wins the depth test wherever the wall lies")  # fmt: skip
#: How far nearer than the wall (in depth) the redrawn frames draw the pane, and with which
#: of the redrawn looks: not the frame shown's 1e-6, bit counts other than its 20 (22 and 18),
#: and walls where the fewest bits at the wall's depth alone differ from case to case (17, 20,
#: 17: a fixed look, so that this slip is named as such, never as a constant answer).
GAPS = ((3e-7, 0), (5e-6, 1))
#: The most bits the question considers: float64's mantissa (53) and more say nothing new.
MOST = 53


def _drawn(b, frame=None) -> tuple[float, float]:
    """(the wall's depth, the pane's) as ``frame`` (the broken frame by default) draws them:
    the trace's window depth of the opaque fragment shown at :data:`PIXEL` and of the glass."""
    frame = frame or b.frame
    records = frame.history(*PIXEL).records
    wall = next(r for r in records if r.outcome == "passed" and r.color[3] == 1)
    pane = next(r for r in records if r.outcome != "not_covered" and r is not wall
                and r.depth is not None and np.isfinite(r.depth))  # fmt: skip
    z = frame.trace.window[:, :, 2]
    return float(z[wall.piece].mean()), float(z[pane.piece].mean())


def _gap(b, frame=None) -> float:
    wall, pane = _drawn(b, frame)
    return wall - pane


def _bits(gap: float) -> int:
    """The least n with gap · (2ⁿ − 1) ≥ 1: a whole step of an n-bit buffer."""
    return next((n for n in range(1, MOST + 1) if gap * (2**n - 1) >= 1), MOST + 1)


def _here(b) -> int | None:
    """The fewest bits at which the pane wins at this wall's depth alone (by where the wall
    lies on that buffer's grid): a mistake, not the question's answer."""
    wall, pane = _drawn(b)
    return next((n for n in range(1, MOST + 1)
                 if round(pane * (2**n - 1)) < round(wall * (2**n - 1))), None)  # fmt: skip


def _cases():
    """The frame shown and frame 3 redrawn twice, the pane other distances from the wall."""
    frames = [broken_frame(3), *(frame_3_gap(gap, look) for gap, look in GAPS)]
    names = ("the frame shown", "the frame redrawn", "the frame redrawn again")
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
    if not np.isfinite(x):
        raise WrongAnswerType(
            f"returned {short(value)}: a finite whole number, {WHAT} (as the histories print "
            "them, the pane's depth and the wall's are equal: the depths the triangles are "
            "drawn at are in frame.trace.window[k, :, 2])"
        )
    if not x.is_integer() or x < 1:
        raise WrongAnswerType(f"returned {short(value)}: bits come in whole numbers, 1 or more")
    return int(x)


def _same(got, expected, args=None) -> bool:
    return got == expected


def _explain(args, expected, got) -> str:
    (b,) = args
    what = "frame 3" if b is broken_frame(3) else "frame 3 redrawn"
    return f"{what}: yours is {got} bits"


#: The reasoning, said once two answers have failed (until then, :data:`HINTS`' words).
RULE = (": two depths a whole step 1/(2ⁿ − 1) apart or more are always stored as different "
        "whole numbers; closer ones tie wherever a rounding boundary does not fall between "
        "them, so n is the least with gap · (2ⁿ − 1) ≥ 1")  # fmt: skip


def _rule(args, expected, got) -> str:
    return (f"{RULE} (lesson 05b), the gap being the wall's depth minus the pane's, as the "
            "trace holds them (frame.trace.window[k, :, 2])")  # fmt: skip


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
        "question asks from how many bits on it wins wherever the wall lies, which takes a "
        "whole step between them")  # fmt: skip


def _constant(value) -> str:
    """The frame shown's number typed in fails both redrawn frames, and the intended pane's
    gap is the same in every case (the fewest bits at the wall's depth may be too, the looks
    drawn being random): each said as its slip, other constants as every check says them."""
    b = broken_frame(3)
    try:
        x = float(value)
    except (TypeError, ValueError):
        return constant_words(value)
    for slip, words in ((_bits(_gap(b)), TYPED), (_bits(_gap(b, b.intended)), INTENDED),
                        (_here(b), HERE)):  # fmt: skip
        if x == slip:
            return words.removeprefix(": ")
    return constant_words(value)


def _raised(args, error: str) -> str:
    """A gap of 0 (the histories' depths: the pane's stored tied at the wall's) divided by."""
    if "ZeroDivisionError" not in error and "divide by zero" not in error:
        return ""
    return (" (a gap of 0? the histories print depths as the 16-bit buffer stores them, the "
            "pane's tied at the wall's: the depths the triangles are drawn at are in "
            "frame.trace.window[k, :, 2])")  # fmt: skip


MISTAKES = [
    # the frame shown's number typed in is the same in every case: said by _constant (a
    # per-case test named a computed answer that happened to equal it)
    Mistake("this wall's depth only", HERE, fits=lambda a, e, g: g == _here(a[0]) != e),
    # half a step's n and log₂(1 + 1/gap) rounded down are one bit short alike
    Mistake("a step short", lambda a, e, g: f": with {g} bits the gap is half a step or "
            "more, short of a whole one (log₂(1 + 1/gap) rounded down?); two depths less than "
            "a step apart are still stored alike wherever both round to the same whole number: "
            "round up, to a whole step", fits=lambda a, e, g: g == e - 1),
    Mistake("the intended pane", INTENDED, gives=lambda b: _bits(_gap(b, b.intended))),
]  # fmt: skip

#: The reasoning, said as a hint until two different answers have failed.
HINTS = ((RULE, ": how far apart must two depths be for an n-bit buffer to store them as "
          "different whole numbers whatever they are?"),)  # fmt: skip


def _draw(ax, case, got):
    """The gap in steps of the student's n-bit buffer, gap · (2ⁿ − 1) (a cross, its value
    written), against the whole step (dashed): never the curve over n, whose crossing would
    be the answer."""
    (b,) = case[1]
    artists = [ax.axhline(1.0, color="#888888", linestyle="--")]
    artists.append(ax.annotate("a whole step", (0.01, 1.0), xycoords=("axes fraction", "data"),
                               va="bottom", fontsize="x-small"))  # fmt: skip
    if isinstance(got, int) and 1 <= got <= MOST:
        steps = _gap(b) * (2.0**got - 1)
        artists += ax.plot([got], [steps], "x", color="#d7301f", ms=11, mew=2)
        artists.append(ax.annotate(f"{got} bits: the gap is {steps:.3g} steps", (got, steps),
                                   xytext=(8, 0), textcoords="offset points", va="center",
                                   fontsize="x-small"))  # fmt: skip
        ax.set_xlim(got - 8, got + 8)
    ax.set_yscale("log")
    ax.set_ylim(1e-3, 1e3)
    ax.set_xlabel("bits n of the depth buffer; ×: yours", fontsize="small")
    ax.set_ylabel("gap · (2ⁿ − 1)", fontsize="small")
    return artists


#: The exercise, for the registry.
BROKEN_FRAME_3_STEPS = Exercise(
    "broken_frame_3_steps", _cases, as_bits, _same, _explain, _rule, MISTAKES, draw=_draw,
    reference=("teachraster.exercises.broken_frames",), hints=HINTS, constant=_constant,
    raised_words=_raised,
)  # fmt: skip
