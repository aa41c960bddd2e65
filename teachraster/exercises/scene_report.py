"""Reports of exercises 05–08: the cases as every exercise checks them, plus a whole picture.

:func:`check_cases` runs a student's function on ``(label, args, expected)`` cases as the
first exercises do (each case under the time limit of :func:`.running.run_case`), with one
difference: ``same(got, expected, args)`` sees the case's arguments too, so that an answer
may be accepted for a reason that depends on them (either neighbour at an exact rounding
tie). The :class:`SceneReport` it returns is a :class:`.Report` that can also draw the
student's function plugged into a small scene beside the package's
(:meth:`SceneReport.compare`, drawn by :mod:`.compare_scenes`).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from .report import Failure, Report
from .running import WrongAnswerType, run_case

#: What a forgotten ``return`` gives, in the words of every exercise's checker.
RETURNED_NONE = "returned None (a missing `return`?)"


def refuse_non_answers(value, what: str) -> None:
    """Raise :class:`.running.WrongAnswerType` for None, text and containers of names.

    numpy would read the text "0.5" as a number; a student's function that returns text has
    a bug worth naming, not an answer.
    """
    if value is None:
        raise WrongAnswerType(RETURNED_NONE)
    if isinstance(value, str | bytes | np.bytes_):
        raise WrongAnswerType(f"returned the text {value!r:.40}, not {what}")
    if isinstance(value, dict | set):
        raise WrongAnswerType(f"returned a {type(value).__name__}, not {what}")


def failure(case, explanation, expected, got, draw=None, kind="") -> Failure:
    """A :class:`.Failure`, with its kind where the report sorts failures by kind."""
    if kind and "kind" in getattr(Failure, "__dataclass_fields__", {}):
        return Failure(case, explanation, expected, got, draw, kind=kind)
    return Failure(case, explanation, expected, got, draw)


@dataclass(frozen=True)
class SceneReport(Report):
    """A :class:`.Report` with a scene: ``report.compare(axes)`` shows a whole picture.

    ``scene`` is a :class:`teachraster.exercises.compare_scenes.Scene` (or None): it runs
    the student's function over a small scene only when a comparison is drawn or asked for.
    """

    scene: object | None = field(default=None, repr=False, compare=False)

    def compare(self, axes=None, pixel=None):
        """Draw the student's picture, the package's, and their differences, side by side.

        Parameters
        ----------
        axes : three matplotlib Axes, one Axes (split in three) or None (a new figure)
        pixel : (row, col) or "first", optional
            Mark this pixel (or the first that differs) in every panel and write the
            explanation of its value under the middle panel (:meth:`explain_pixel`). With
            an interactive backend a click on a pixel does the same.

        Returns
        -------
        list of matplotlib artists
        """
        if self.scene is None:
            raise ValueError(f"{self.exercise} has no picture to compare")
        from .compare_scenes import draw_comparison

        return draw_comparison(self.scene, axes, pixel)

    def explain_pixel(self, row: int, col: int) -> str:
        """Why pixel (``row``, ``col``) of the student's picture differs (or does not)."""
        if self.scene is None:
            raise ValueError(f"{self.exercise} has no picture to compare")
        return self.scene.explain(row, col)

    def differing_pixels(self) -> np.ndarray:
        """(n, 2) rows and columns where the student's picture differs from the package's."""
        if self.scene is None:
            raise ValueError(f"{self.exercise} has no picture to compare")
        return np.argwhere(self.scene.differs())


def check_cases(
    name: str, fn: Callable, cases, convert, same, explain, draw, scene=None, budget=None
):
    """Run ``fn(*args)`` on ``cases`` of (label, args, expected) and explain each failure.

    ``convert`` turns the returned value into the answer's type (or raises
    :class:`.running.WrongAnswerType`); ``same(got, expected, args)`` accepts it;
    ``explain(args, expected, got)`` says why it is wrong; ``draw(ax, case, got)`` draws a
    case. ``scene(fn)`` builds the whole-picture comparison. Each case runs under
    :func:`.running.run_case`'s time limit; ``budget`` (seconds, optional) also caps all cases
    together, the cases left when it is spent failing as "not run". ``NotImplementedError`` on
    every case makes the report "not implemented yet"; on some cases only, those fail.
    """
    failures, unimplemented = [], 0
    built = None if scene is None else scene(fn)
    start = time.perf_counter()
    for label, args, expected in cases:
        left = None if budget is None else budget - (time.perf_counter() - start)
        if left is not None and left <= 0:
            text = f"not run: the {budget:g} s the check may take were spent on the cases before"
            failures.append(failure(label, text, expected, None, kind="budget"))
            continue
        copies = tuple(_copy(a) for a in args)
        outcome = run_case(lambda copies=copies: convert(fn(*copies)), left)
        if outcome.not_implemented:
            unimplemented += 1
            text = outcome.error or "your function raised NotImplementedError on this case"
            failures.append(failure(label, text, expected, None, kind="not implemented"))
        elif outcome.error:
            kind = getattr(outcome, "kind", "") or _kind(outcome.error)
            failures.append(failure(label, outcome.error, expected, None, kind=kind))
        elif not same(outcome.value, expected, args):
            text = explain(args, expected, outcome.value)
            drawing = _drawer(draw, (label, args, expected), outcome.value)
            failures.append(failure(label, text, expected, outcome.value, drawing))
    if unimplemented == len(cases):
        return SceneReport(
            exercise=name, failures=[], n_cases=len(cases), not_implemented=True,
            example=_drawer(draw, cases[0], None), scene=built,
        )  # fmt: skip
    example = _drawer(draw, cases[0], cases[0][2])
    return SceneReport(
        exercise=name, failures=failures, n_cases=len(cases), example=example, scene=built
    )


def _kind(error: str) -> str:
    """The kind of a failed run, from its words (where the runner does not say it)."""
    if RETURNED_NONE in error:
        return "none"
    if error.startswith("your function returned"):
        return "type"
    return "timeout" if "stopped" in error else "raised"


def _copy(value):
    """A fresh copy of an argument (a student may write into it), lists of arrays included."""
    if isinstance(value, np.ndarray):
        return value.copy()
    if isinstance(value, list):
        return type(value)(_copy(v) for v in value)  # a Pyramid stays a Pyramid
    return value


def _drawer(draw, case, got):
    def drawing(ax):
        return draw(ax, case, got)

    return drawing
