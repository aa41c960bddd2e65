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
        The reference answer and the student's.
    """

    case: str
    explanation: str
    expected: Any
    got: Any
    draw: Callable | None = field(default=None, repr=False, compare=False)


@dataclass(frozen=True)
class Report:
    """The result of checking one exercise.

    Attributes
    ----------
    exercise : str
        Its name.
    passed : bool
        True when every case passed.
    failures : list of Failure
        The failing cases, catalogue first.
    n_cases : int
        How many cases ran.
    not_implemented : bool
        The function raised ``NotImplementedError`` (the student has not written it yet).
    """

    exercise: str
    failures: list[Failure]
    n_cases: int
    not_implemented: bool = False
    example: Callable | None = field(default=None, repr=False, compare=False)

    @property
    def passed(self) -> bool:
        return not self.failures and not self.not_implemented

    def __str__(self) -> str:
        if self.not_implemented:
            return (
                f"{self.exercise}: not implemented yet (it, or a function it calls, raises "
                "NotImplementedError: replace `raise NotImplementedError()` with your code, "
                "then run this cell again)"
            )
        if self.passed:
            return f"{self.exercise}: all {self.n_cases} cases pass"
        lines = [f"{self.exercise}: {len(self.failures)} of {self.n_cases} cases fail"]
        for f in self.failures[:SHOWN]:
            lines.append(f"- {f.case}: {f.explanation}")
        if len(self.failures) > SHOWN:
            lines.append(f"  ... and {len(self.failures) - SHOWN} more (see report.failures)")
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

    def plot(self, ax):
        """Draw the first failing case (or, when all pass, a passing one) on ``ax``.

        Coverage exercises show the pixels: correct ones grey, *missing* ones (the rule
        covers them, the function did not) and *extra* ones (the reverse) marked, with the
        edge that decides the first wrong pixel drawn thick. Returns the artists.
        """
        if self.failures and self.failures[0].draw is not None:
            artists = self.failures[0].draw(ax)
            case = self.failures[0].case
            case = case if len(case) <= 48 else case[:45] + "..."
            ax.set_title(f"{self.exercise}: {case}", fontsize="small")
        elif self.example is not None:
            artists = self.example(ax)
            state = "not implemented yet" if self.not_implemented else "passes"
            ax.set_title(f"{self.exercise}: {state}", fontsize="small")
        else:
            artists = [ax.text(0.5, 0.5, str(self), ha="center", va="center", wrap=True)]
            ax.set_axis_off()
        return artists
