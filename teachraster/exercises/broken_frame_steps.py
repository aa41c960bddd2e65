"""Exercise ``broken_frame_3_steps`` (lesson 11 with 05b): frame 3's tie, in the buffer's steps.

Frame 3 of :mod:`.broken_frames` loses its pane to a tie in a 16-bit depth buffer. Review r309
M3: its evidence, the intended pane's depth, is copied off a history and needs none of lesson
05b's reasoning. This task asks for it: the whole numbers the unorm16 buffer holds for the wall
and for the intended pane at a pixel of the pane, and how many steps apart they are, derived
from the depths the intended frame's history prints and the format its first line names (a
unorm depth d is stored as round(d · (2¹⁶ − 1)), GL 4.6 §2.3.5; lesson 05b). The frame pair is
the frame shown, then frame 3 redrawn with another wall (:data:`.broken_frames._REDRAWN`), so
numbers typed in fail. Typical mistakes named: steps of 1/2¹⁶ in place of 1/(2¹⁶ − 1), the
depths or their difference given for steps, a difference of the printed (rounded) depths
scaled but not rounded to a whole number of steps. (Truncation is no mistake here: the
depths stored are whole steps, k/65535, whose product with 65535 is k in float64 and in the
printed six decimals, for every look.)
"""

from __future__ import annotations

import numpy as np

from .answers import refuse_non_answers, short
from .broken_frames import _redrawn, broken_frame
from .exercise import Exercise, Mistake
from .running import WrongAnswerType

#: The steps of the 16-bit buffer: 2¹⁶ − 1, so that 0 and 1 are both exact.
STEPS = 2**16 - 1
#: The pixel the check reads, frame 3's solution's (any pixel of the pane holds the same
#: depths: the pane lies parallel to the wall).
PIXEL = (13, 52)
#: What the answer is, as the notebook's task and every wrong answer's words say it.
WHAT = ("(wall, pane, apart): the whole numbers the 16-bit buffer holds for the wall and for "
        "the intended pane at a pixel of the pane, and how many steps apart they are")  # fmt: skip


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
    """The frame shown and frame 3 redrawn with another wall (other depths, other steps)."""
    shown, redrawn = broken_frame(3), _redrawn(3)
    return [("the frame shown", (shown,), _stored(shown)),
            ("the frame redrawn", (redrawn,), _stored(redrawn))]  # fmt: skip


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


def _rule(args, expected, got) -> str:
    return (
        ": a unorm16 buffer holds the whole number round(d · (2¹⁶ − 1)) for a depth d "
        "(lesson 05b); the steps apart are the difference of the two whole numbers"
    )


def _copied(args, expected, got) -> bool:
    """The frame shown's numbers, given for the redrawn frame."""
    (b,) = args
    return b is not broken_frame(3) and tuple(got) == _stored(broken_frame(3))


MISTAKES = [
    Mistake("typed in", ": those are frame 3's numbers as shown; this is frame 3 redrawn with "
            "another wall, so read the depths off b.intended.history(row, col) inside your "
            "function", fits=lambda a, e, g: _copied(a, e, g)),
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
]  # fmt: skip


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
    reference=("teachraster.exercises.broken_frames",),
)  # fmt: skip
