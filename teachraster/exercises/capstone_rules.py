"""The student's functions as the pipeline's stage rules, their answers read as the exercises
read them.

Each function the capstone takes is wrapped once: the wrapper notes which function is running
(so that an exception, a wrong type or the time limit is reported with its name) and reads
its answer with the converter its exercise uses (``None`` is a missing ``return``, text is not
a number, ...), then hands the pipeline plain values
(:class:`teachraster.pipeline.planning.overrides.StageOverrides`).
"""

from __future__ import annotations

import copy
import weakref
from dataclasses import dataclass, field

import numpy as np

from ..pipeline.planning.overrides import StageOverrides
from .answers import as_bool, as_numbers
from .front_to_back import as_rgba
from .perspective_weighting import as_weights
from .running import WrongAnswerType, one_call
from .value_checks import float_type
from .zbuffer_pixel import as_passes


def _colour(value) -> np.ndarray:
    return as_numbers(value, (3,), "a colour of 3 channels, shape (3,)")


def _weights(value) -> np.ndarray:
    return as_numbers(value, (3,), "3 weights, shape (3,)")


#: The functions the capstone takes: the stage rule each replaces (None: none, it runs after
#: the pipeline), how its answer is read.
FUNCTIONS = {
    "covers": ("coverage", as_bool),
    "barycentric": ("weights", _weights),
    "perspective_weights": ("perspective", as_weights),
    "depth_passes": ("depth", as_passes),
    "over": ("blend", as_rgba),
    "bilinear": ("bilinear", _colour),
    "trilinear": ("trilinear", _colour),
    "resolve": ("resolve", _colour),
    "a_buffer": (None, as_rgba),  # the A-buffer's resolve of one pixel, after the pipeline
}


@dataclass
class Tracker:
    """Which of the student's functions ran last (the one to blame when something fails)."""

    name: str = ""
    #: (function, "are float32") when some answer of a function was float32 (or float16).
    precision: tuple[str, str] | None = None
    #: Each function's first call: (its arguments, copied, and its answer as read), asked
    #: again after the render to tell a function that keeps state between calls (r449).
    first: dict = field(default_factory=dict)


def wrapped(name: str, fn, tracker: Tracker):
    """``fn`` as a stage rule: tracked, its answer read by the exercise's converter."""
    convert = FUNCTIONS[name][1]

    def rule(*args):
        tracker.name = name
        raw = one_call(fn, *args)  # r163 12-8: a loop stops at the call's limit, not the scene's
        if tracker.precision is None and (low := float_type(raw)) is not None:
            tracker.precision = (name, f"are {low}")
        value = convert(raw)
        if name not in tracker.first:
            tracker.first[name] = (copy.deepcopy(args), value)
        if name == "depth_passes" and len(value) != len(args[0]):
            raise WrongAnswerType(
                f"returned {len(value)} value(s) for {len(args[0])} fragment(s): one "
                "True/False per fragment"
            )
        return value

    return rule


def rules(functions: dict, tracker: Tracker) -> StageOverrides:
    """The stage overrides that plug ``functions`` (name: function) into the pipeline (those
    that run after it, such as ``a_buffer``, are called by the capstone itself)."""
    return StageOverrides(**{FUNCTIONS[name][0]: wrapped(name, fn, tracker)
                             for name, fn in functions.items()
                             if FUNCTIONS[name][0] is not None})  # fmt: skip


#: The functions found to keep state (r449), with their two answers: a later scene, whose
#: first call already meets the state an earlier one left, says so too.
KEPT_STATE: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def kept_state(functions: dict, tracker: Tracker) -> tuple[str, object, object] | None:
    """(name, first answer, answer now) of a function of ``functions`` whose first call of the
    render, made again with the same arguments, answers otherwise (r449: a depth buffer kept
    in a global between pixels was told "no fragment passes, ever"), or one found so in an
    earlier scene (:data:`KEPT_STATE`), or None. The caller runs it within the checker's
    limits (a call that raises or loops here tells nothing)."""
    for name, (args, before) in tracker.first.items():
        fn = functions[name]
        try:
            if fn in KEPT_STATE:
                return (name, *KEPT_STATE[fn])
            again = FUNCTIONS[name][1](fn(*copy.deepcopy(args)))
        except Exception:  # noqa: BLE001 - a student's bug is reported elsewhere, not raised
            continue
        if not np.array_equal(np.asarray(again), np.asarray(before), equal_nan=True):
            try:
                KEPT_STATE[fn] = (before, again)
            except TypeError:  # not weakly referable: this scene says it alone
                pass
            return name, before, again
    return None
