"""Exercise ``broken_frame_3_steps`` (lesson 11 with 05b): frame 3's tie, in the buffer's steps.

Frame 3 of :mod:`.broken_frames` loses its pane to a tie in a 16-bit depth buffer. Review r309
M3: its evidence, the intended pane's depth, is copied off a history and needs none of lesson
05b's reasoning. This task asks for it: the whole number the unorm16 buffer stores the wall's
depth as, the one the intended pane's depth is compared as (the glass writes no depth, r318
C1), and how many steps apart they are, derived from the depths the intended frame's history
prints and the format its first line names (a unorm depth d is stored as round(d · (2¹⁶ − 1)),
GL 4.6 §2.3.5; lesson 05b; said as a hint until two answers failed, r318 M1). The frame pair
is the frame shown, then frame 3 redrawn twice with another wall and its intended pane
another distance from the wall (:func:`.broken_frames.frame_3_apart`: r318, 66 steps in
every look, so 66 typed in passed). Typical mistakes named: steps of 1/2¹⁶ in place of
1/(2¹⁶ − 1), the pane read off the broken frame's history (tied: the wall's number; r377 F3),
the depths or their difference given for steps, a difference of the printed
(rounded) depths scaled but not rounded to a whole number of steps, the printed depths scaled
and rounded up or down, the frame shown's steps apart typed in. (Rounding up or down the
depths themselves is no mistake here and cannot be told apart: the renderer compares each
fragment's depth as the buffer would store it, rounded to the nearest step, np.rint in
:func:`~teachraster.pipeline.visibility.depth.quantize`, so every depth a history holds is a
whole step k/65535, whose product with 65535 is k in float64.)
"""

from __future__ import annotations

import math

import numpy as np

from .answers import refuse_non_answers, short
from .broken_frames import broken_frame, frame_3_apart
from .diagnosis import constant_words
from .exercise import Exercise, Mistake
from .running import WrongAnswerType

#: The steps of the 16-bit buffer: 2¹⁶ − 1, so that 0 and 1 are both exact.
STEPS = 2**16 - 1
#: The pixel the check reads, frame 3's solution's (any pixel of the pane holds the same
#: depths: the pane lies parallel to the wall).
PIXEL = (13, 52)
#: What the answer is, as the notebook's task and every wrong answer's words say it.
WHAT = ("(wall, pane, apart): the whole number the 16-bit buffer stores the wall's depth as, "
        "the one the intended pane's depth is compared as, at a pixel of the pane, and how "
        "many steps apart they are")  # fmt: skip
#: How far (in steps) the redrawn frames' intended panes lie nearer than the wall: not 66 (the
#: frame shown's), and not whole steps (the pane's depth is compared as the nearest step).
APART = (41.3, 97.4)


def _depths(b) -> tuple[float, float]:
    """(the wall's depth, the pane's) in the intended frame's history of :data:`PIXEL`: the
    opaque fragment, and the glass one."""
    records = b.intended.history(*PIXEL).records
    wall = next(r.depth for r in records if r.outcome == "passed" and r.color[3] == 1)
    pane = next(r.depth for r in records if r.outcome == "passed" and r.color[3] < 1)
    return float(wall), float(pane)


def _stored(b, scale: float = STEPS, rounding=round) -> tuple[float, float, float]:
    """(wall, pane, apart) with each depth scaled by ``scale`` and rounded by ``rounding``:
    the answer (the defaults) and the mistakes that change the scale or the rounding."""
    wall, pane = (float(rounding(d * scale)) for d in _depths(b))
    return wall, pane, wall - pane


def _printed(b) -> tuple[float, float]:
    """The two depths as the history prints them (six decimals)."""
    return tuple(round(d, 6) for d in _depths(b))


def _cases():
    """The frame shown and frame 3 redrawn twice, with another wall and its intended pane
    another distance from the wall (other depths, other steps apart)."""
    frames = [broken_frame(3), *(frame_3_apart(steps) for steps in APART)]
    names = ("the frame shown", "the frame redrawn", "the frame redrawn again")
    return [(name, (b,), _stored(b)) for name, b in zip(names, frames, strict=True)]


def as_steps(value) -> tuple[float, float, float]:
    """(wall, pane, apart), three finite numbers (judged by their values: 39321.0 is 39321)."""
    refuse_non_answers(value, "three numbers " + WHAT)
    try:
        numbers = [float(v) for v in value]
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {short(value)}: return {WHAT}") from None
    if isinstance(value, str) or len(numbers) != 3 or any(isinstance(v, bool) for v in value):
        raise WrongAnswerType(f"returned {short(value)}: return three numbers, {WHAT}")
    if not all(np.isfinite(numbers)):
        raise WrongAnswerType(f"returned {short(value)}: three finite numbers, {WHAT}")
    return tuple(numbers)


def _same(got, expected, args=None) -> bool:
    return tuple(got) == tuple(expected)


def _explain(args, expected, got) -> str:
    (b,) = args
    wall, pane = _printed(b)
    what = "frame 3" if b is broken_frame(3) else "frame 3 redrawn"
    yours = tuple(int(v) if float(v).is_integer() else round(v, 6) for v in got)
    return (
        f"{what} at {PIXEL}, where the intended frame's history prints the wall at "
        f"{wall:.6f} and the pane at {pane:.6f}: yours is {yours}"
    )


#: The rule, said once two answers have failed (r318 M1: the question gave it, and the task
#: was a transcription); until then, :data:`HINTS`' words.
RULE = ": a unorm16 buffer stores a depth d as the whole number round(d · (2¹⁶ − 1))"


def _rule(args, expected, got) -> str:
    return f"{RULE} (lesson 05b); the steps apart are the difference of the two whole numbers"


def _copied(args, expected, got) -> bool:
    """The frame shown's numbers, given for the redrawn frame."""
    (b,) = args
    return b is not broken_frame(3) and tuple(got) == _stored(broken_frame(3))


def _apart_copied(args, expected, got) -> bool:
    """The frame shown's steps apart, given for a redrawn frame whose pane lies elsewhere."""
    (b,) = args
    shown = _stored(broken_frame(3))[2]
    return b is not broken_frame(3) and got[2] == shown != expected[2]


def _printed_rounded(b, rounding) -> tuple[float, float]:
    """The printed (six-decimal) depths times 65535, rounded by ``rounding``."""
    return tuple(float(rounding(d * STEPS)) for d in _printed(b))


def _rounded_off(args, expected, got) -> bool:
    """The printed depths scaled, then rounded up or down (not to the nearest step)."""
    (b,) = args
    return tuple(got[:2]) != tuple(expected[:2]) and any(
        tuple(got[:2]) == _printed_rounded(b, f) for f in (math.ceil, math.floor)
    )


#: What the frame shown's numbers, typed in, are told.
TYPED = (": those are frame 3's numbers as shown; this is frame 3 redrawn with another wall "
         "and its pane another distance from it, so read the depths off "
         "b.intended.history(row, col) inside your function")  # fmt: skip


def _constant(value) -> str:
    """The frame shown's numbers typed in fail both redrawn frames, a constant answer: said as
    the typed-in mistake (r318: three cases now), other constants as every check says them."""
    try:
        typed = tuple(float(v) for v in value) == _stored(broken_frame(3))
    except (TypeError, ValueError):
        typed = False
    return TYPED.removeprefix(": ") if typed else constant_words(value)


def _tied(args, expected, got) -> bool:
    """The pane read off the broken frame's own history, where it fails on a tie at the
    wall's depth: its whole number is the wall's (r377 F3: told the unorm16 rule)."""
    return got[1] == expected[0] != expected[1]


def _tied_words(args, expected, got) -> str:
    (b,) = args
    return (
        f": your pane, {got[1]:g}, is the wall's number: that is frame 3's pane as drawn, "
        f"tied with the wall (read off the broken frame's history, b.frame.history{PIXEL}, "
        "where it fails on a tie at the wall's depth); the question asks for the intended "
        f"pane, the depth the intended frame's history prints ({_printed(b)[1]:.6f}), in "
        "the buffer's steps"
    )


MISTAKES = [
    Mistake("typed in", TYPED, fits=lambda a, e, g: _copied(a, e, g)),
    Mistake("the broken frame's tied pane", _tied_words, fits=_tied),
    Mistake("apart typed in", lambda a, e, g: f": {g[2]:g} steps apart is frame 3's as "
            "shown; this frame's intended pane is drawn another distance from the wall: count "
            "the steps from the depths its history prints", fits=_apart_copied),
    Mistake("2^16 steps", ": you scaled by 2¹⁶ = 65536; a unorm16 buffer has 2¹⁶ − 1 = 65535 "
            "steps from 0 to 1 (so that 1 is stored exactly): round(d · 65535)",
            gives=lambda b: _stored(b, 2**16)),
    Mistake("depths for steps", ": those are the depths themselves; the buffer holds whole "
            "steps of 1/65535: round(d · 65535), and their difference counts the steps",
            fits=lambda a, e, g: _near(g, (*_depths(a[0]), e[2] / STEPS))),
    Mistake("depth difference for steps", lambda a, e, g: f": {g[2]:.6f} is the difference "
            "of the depths, not of the steps: subtract the two whole numbers",
            fits=lambda a, e, g: g[:2] == e[:2] and abs(g[2] - (e[2] / STEPS)) < 2e-6),
    Mistake("steps not whole", lambda a, e, g: f": {g[2]:.4f} is the printed depths' "
            "difference scaled, not a whole number of steps: the depths are printed rounded "
            "to six decimals; subtract the two whole numbers the buffer holds",
            fits=lambda a, e, g: g[:2] == e[:2] and not float(g[2]).is_integer()
            and abs(g[2] - e[2]) < 0.5),
    Mistake("rounded up or down", ": the printed depths are rounded to six decimals, so "
            "d · 65535 lies a little off the whole step; rounding it up or down (ceil, "
            "floor, int) can miss that step: the buffer rounds to the nearest step",
            fits=_rounded_off),
]  # fmt: skip

#: The rule's formula, said as a hint until two different answers have failed (r318 M1).
HINTS = ((RULE, ": a unorm16 buffer stores a depth as a whole number of steps from 0 to 1 "
          "(how many steps, and how is d turned into one?)"),
         ("round(d · 65535)", "a whole number of steps"),)  # fmt: skip


def _near(got, values) -> bool:
    """Is each number of ``got`` within the history's printed rounding (2e-6) of ``values``?"""
    return all(abs(g - v) < 2e-6 for g, v in zip(got, values, strict=True))


def _draw(ax, case, got):
    """The printed depths times 65535 on the buffer's steps (dotted: what is rounded), and the
    student's wall and pane (crosses), never the answer itself."""
    (b,) = case[1]
    products = [d * STEPS for d in _printed(b)]
    artists = []
    for x, name, side in zip(products, ("wall", "pane"), ("right", "left"), strict=True):
        artists.append(ax.axvline(x, color="#888888", linestyle=":"))
        gap = 1 if side == "left" else -1  # the words beside the line, inside the axes
        artists.append(ax.annotate(f"{name}: d · 65535", (x + gap, 0.6), ha=side,
                                   fontsize="x-small"))  # fmt: skip
    if isinstance(got, tuple) and len(got) == 3:
        artists += ax.plot(list(got[:2]), [0, 0], "x", color="#d7301f", ms=11, mew=2)
    ax.set_xlim(products[1] - 10, products[0] + 10)
    ax.set_ylim(-1, 1)
    ax.set_yticks([])
    ax.ticklabel_format(useOffset=False, style="plain", axis="x")
    ax.set_xlabel("steps of the 16-bit depth buffer (1/65535 each); ×: yours", fontsize="small")
    return artists


#: The exercise, for the registry.
BROKEN_FRAME_3_STEPS = Exercise(
    "broken_frame_3_steps", _cases, as_steps, _same, _explain, _rule, MISTAKES, draw=_draw,
    reference=("teachraster.exercises.broken_frames",), hints=HINTS, constant=_constant,
)  # fmt: skip
