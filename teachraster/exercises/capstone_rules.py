"""The student's functions as the pipeline's stage rules, their answers read as the exercises
read them.

Each function the capstone takes is wrapped once: the wrapper notes which function is running
(so that an exception, a wrong type or the time limit is reported with its name) and reads
its answer with the converter its exercise uses (``None`` is a missing ``return``, text is not
a number, ...), then hands the pipeline plain values
(:class:`teachraster.pipeline.planning.overrides.StageOverrides`).
"""

from __future__ import annotations

from dataclasses import dataclass

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


def wrapped(name: str, fn, tracker: Tracker):
    """``fn`` as a stage rule: tracked, its answer read by the exercise's converter."""
    convert = FUNCTIONS[name][1]

    def rule(*args):
        tracker.name = name
        raw = one_call(fn, *args)  # r163 12-8: a loop stops at the call's limit, not the scene's
        if tracker.precision is None and (low := float_type(raw)) is not None:
            tracker.precision = (name, f"are {low}")
        value = convert(raw)
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
