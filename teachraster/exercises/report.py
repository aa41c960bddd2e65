"""What :func:`teachraster.exercises.check` returns: which cases failed, and why."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

#: Failures spelled out by ``print(report)`` (all of them are in ``report.failures``).
SHOWN = 3


@dataclass(frozen=True)
class Failure:
    """One failing case.

    Attributes
    ----------
    case : str
        Which case (catalogue name or random case and its numbers).
    explanation : str
        Why the answer is wrong, in terms of the rules, quoting the case's numbers.
    expected, got
        The reference answer and the student's (None when the function gave no answer).
    kind : str
        The kind of mistake, in a few words ("raised", "timeout", "none", "type", "exit",
        "not implemented", or a mistake the explanation names): the summary shows one failure
        of each kind before the rest, so that one mistake cannot hide another.
    """

    case: str
    explanation: str
    expected: Any
    got: Any
    draw: Callable | None = field(default=None, repr=False, compare=False)
    kind: str = ""


#: Headlines of failures without an answer to draw, by kind (the plot's title says it).
HEADLINES = {
    "raised": "your function raised an exception",
    "not implemented": "your function raised NotImplementedError",
    "timeout": "your function did not return in time",
    "budget": "the check ran out of time",
    "exit": "your function called exit()",
    "none": "your function returned None",
    "type": "your function returned the wrong type",
}


@dataclass(frozen=True)
class Report:
    """The result of checking one exercise.

    Attributes
    ----------
    exercise : str
        Its name.
    passed : bool
        True when every case ran and passed.
    failures : list of Failure
        The failing cases, in case order (catalogue first).
    n_cases : int
        How many cases the exercise has.
    not_implemented : bool
        Every case raised ``NotImplementedError`` (the student has not written it yet).
    stopped : str or None
        Why the check stopped before its last case (a case ran past its time limit), if it did.
    n_run : int or None
        How many cases ran (``n_cases`` unless the check stopped).
    """

    exercise: str
    failures: list[Failure]
    n_cases: int
    not_implemented: bool = False
    example: Callable | None = field(default=None, repr=False, compare=False)
    stopped: str | None = None
    n_run: int | None = None
    comparison: Callable | None = field(default=None, repr=False, compare=False)

    @property
    def passed(self) -> bool:
        return not self.failures and not self.not_implemented and self.stopped is None

    def shown(self) -> list[Failure]:
        """The failures the summary spells out: one of each kind first, then the others."""
        first, rest, kinds = [], [], set()
        for f in self.failures:
            (rest if f.kind in kinds else first).append(f)
            kinds.add(f.kind)
        n = max(SHOWN, len(first))
        picked = {id(f) for f in (first + rest)[:n]}
        return [f for f in self.failures if id(f) in picked]  # in case order

    def __str__(self) -> str:
        if self.not_implemented:
            return (
                f"{self.exercise}: not implemented yet (it, or a function it calls, raises "
                "NotImplementedError: replace `raise NotImplementedError()` with your code, "
                "then run this cell again)"
            )
        if self.passed:
            return f"{self.exercise}: all {self.n_cases} cases pass"
        head = f"{self.exercise}: {len(self.failures)} of {self.n_cases} cases fail"
        if self.stopped is not None:
            n_run = self.n_cases if self.n_run is None else self.n_run
            head += f"; the check stopped after case {n_run} of {self.n_cases}"
        lines = [head]
        shown = self.shown()
        for f in shown:
            lines.append(f"- {f.case}: {f.explanation}")
        if len(self.failures) > len(shown):
            lines.append(f"  ... and {len(self.failures) - len(shown)} more (see report.failures)")
        if self.stopped is not None and not self.failures:
            lines.append(f"- {self.stopped}")
        return "\n".join(lines)

    def assert_passed(self) -> None:
        """Do nothing when the report passed; else raise ``AssertionError`` with its summary.

        This is what an nbgrader test cell calls: a failing exercise scores 0 and the
        feedback carries the checker's explanation.
        """
        if not self.passed:
            raise AssertionError(str(self))

    def _repr_pretty_(self, p, cycle) -> None:  # IPython shows the summary, not the fields
        p.text(str(self))

    def title(self) -> str:
        """The title of :meth:`plot`'s figure: "passes" only when the report passed."""
        if self.passed:
            return f"{self.exercise}: all {self.n_cases} cases pass"
        if self.not_implemented:
            return f"{self.exercise}: not implemented yet"
        if not self.failures:
            return f"{self.exercise}: {HEADLINES['budget']}"
        f = self.failures[0]
        case = f.case if len(f.case) <= 40 else f.case[:37] + "..."
        if f.got is None and f.kind in HEADLINES:
            return f"{self.exercise}: {HEADLINES[f.kind]} ({case})"
        return f"{self.exercise} fails: {case}"

    def plot(self, ax):
        """Draw the first failing case (or, when all pass, a passing one) on ``ax``.

        Coverage exercises show the pixels: correct ones grey, *missing* ones (the rule
        covers them, the function did not) and *extra* ones (the reverse) marked, with the
        edge that decides the first wrong pixel drawn thick. A function that raised, ran out
        of time or returned None or the wrong type gets the case's expected answer with a
        note saying so; the title says "pass" only when the report passed. Returns the
        artists.
        """
        f = self.failures[0] if self.failures else None
        drawing = f.draw if f is not None else self.example
        if drawing is not None:
            artists = list(drawing(ax))
        else:
            artists = []
            ax.set_axis_off()
        note = None
        if f is not None and (f.got is None or drawing is None):
            note = f.explanation
        elif f is None and not self.passed and not self.not_implemented:
            note = self.stopped or str(self)
        if note is not None:
            artists.append(_note(ax, note))
        artists.append(ax.set_title(self.title(), fontsize="small"))
        return artists

    def compare(self, ax=None, pixel=None):
        """The student's whole picture beside the package's, and where they differ.

        Renders a small scene (a fan of 16 triangles whose shared edges run through pixel
        centres, wound both ways) with the student's function and with the package; ``ax``
        is one Axes (split into three panels), three Axes, or None (a new figure). The third
        panel marks each pixel whose coverage count differs, with the difference.
        ``pixel=(row, col)`` (default, or "first": the first differing pixel), or a click on
        any panel, shows the explanation for that pixel. Exercises with a picture only
        (``fill``); returns the artists.
        """
        if ax is None:
            import matplotlib.pyplot as plt

            ax = plt.subplots(1, 3, figsize=(9, 3.6))[1]
        pixel = None if pixel is None or pixel == "first" else _pixel(pixel)
        from .compare import draw_comparison

        return draw_comparison(_three_panels(ax), self._comparison(), pixel)

    def explain_pixel(self, row: int, col: int) -> str:
        """Why pixel (``row``, ``col``) of the student's picture differs (or does not)."""
        from .compare import pixel_explanation

        return pixel_explanation(self._comparison(), *_pixel((row, col)))

    def differing_pixels(self):
        """(n, 2) rows and columns where the student's picture differs from the package's."""
        return self._comparison().differing()

    def _comparison(self):
        if self.comparison is None:
            raise ValueError(
                f"report.compare draws a whole picture: {self.exercise} makes none (fill does)"
            )
        return self.comparison()


def _pixel(pixel) -> tuple[int, int]:
    import operator

    try:
        i, j = pixel
        return operator.index(i), operator.index(j)
    except (TypeError, ValueError):
        raise TypeError(f"pixel must be a pair of ints (row, column), got {pixel!r}") from None


def _three_panels(ax) -> list:
    """Three Axes: the ones given, or three panels inset in one Axes."""
    if hasattr(ax, "inset_axes"):
        ax.set_axis_off()
        return [ax.inset_axes([k / 3 + 0.01, 0.2, 0.29, 0.75]) for k in range(3)]
    axes = list(ax.ravel() if hasattr(ax, "ravel") else ax)
    if len(axes) != 3:
        raise ValueError(f"ax must be one Axes or three, got {len(axes)}")
    return axes


def _note(ax, text: str, width: int = 60):
    """A boxed note across the axes (what happened, where no answer can be drawn)."""
    import textwrap

    lines = textwrap.wrap(text, width)[:6]
    return ax.text(
        0.5,
        0.5,
        "\n".join(lines),
        transform=ax.transAxes,
        ha="center",
        va="center",
        fontsize="x-small",
        bbox={"boxstyle": "round", "facecolor": "#fff4f2", "edgecolor": "#d7301f"},
    )
