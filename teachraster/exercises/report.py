"""What :func:`teachraster.exercises.check` returns: which cases failed, and why."""

from __future__ import annotations

import weakref
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
    "memory": "your function ran out of memory",
}


class CheckFailed(AssertionError):
    """A failing check's ``AssertionError``, shown by IPython (JupyterLab, nbconvert) as its
    one line: a traceback printed :meth:`Report.assert_passed`'s source and docstring and the
    report a second time (r173 D5). Named ``AssertionError``, as the kernel reports it (the
    grader and *Run All*'s ``raises-exception`` tag read that name)."""

    def _render_traceback_(self) -> list[str]:
        return [f"AssertionError: {self}"]


CheckFailed.__name__ = CheckFailed.__qualname__ = "AssertionError"


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
    package : str or None
        Why the answer does not count although it may be right: the function calls the
        package's own answer (``tr.mip_level`` in ``mip_level``).
    printed : str or None
        How much the function printed during the check (the output is kept aside).
    precision : str or None
        A note that the answers were computed in float32 (or float16) and pass within its
        rounding: named, not failed.
    scene : Scene or None
        The student's function in a whole picture beside the package's (:meth:`compare`).
    tries : str or None
        A note that the task has failed more checks in this kernel than a diagnosis needs,
        and that further checks wait (:mod:`.tries`, exercise 11).
    """

    exercise: str
    failures: list[Failure]
    n_cases: int
    not_implemented: bool = False
    example: Callable | None = field(default=None, repr=False, compare=False)
    stopped: str | None = None
    n_run: int | None = None
    package: str | None = None
    printed: str | None = None
    precision: str | None = None
    scene: object | None = field(default=None, repr=False, compare=False)
    tries: str | None = None

    @property
    def passed(self) -> bool:
        return (
            not self.failures
            and not self.not_implemented
            and self.stopped is None
            and self.package is None
        )

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
            note = "" if self.precision is None else f" ({self.precision})"
            return self._with_printed(f"{self.exercise}: all {self.n_cases} cases pass{note}")
        if self.package is not None and not self.failures and self.stopped is None:
            text = (
                f"{self.exercise}: all {self.n_cases} cases pass, but not counted: {self.package}"
            )
            return self._with_printed(text)
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
        if self.package is not None:
            lines.append(f"- not counted: {self.package}")
        if self.tries is not None:
            lines.append(f"- {self.tries}")
        return self._with_printed("\n".join(lines))

    def _with_printed(self, text: str) -> str:
        return text if self.printed is None else f"{text}\n({self.printed})"

    def assert_passed(self) -> None:
        """Do nothing when the report passed; else raise ``AssertionError`` with its first line.

        This is what an nbgrader test cell calls: a failing exercise scores 0, and the
        feedback carries the checker's explanation, printed by the cell above the error.
        """
        if not self.passed:
            # r173 D5 (r149 E5, r162 D6): the report is printed above the error already; the
            # error says its first line only, as one line, not this method's source
            head = str(self).splitlines()[0]
            if self.package is not None and "not counted" not in head:
                head += "; and not counted (it uses the package's own answer)"
            raise CheckFailed(f"{head} (the report above says why)")

    def _repr_pretty_(self, p, cycle) -> None:  # IPython shows the summary, not the fields
        p.text(str(self))

    def title(self) -> str:
        """The title of :meth:`plot`'s figure: "passes" only when the report passed."""
        if self.passed:
            return f"{self.exercise}: all {self.n_cases} cases pass"
        if self.not_implemented:
            return f"{self.exercise}: not implemented yet"
        if self.package is not None and not self.failures and self.stopped is None:
            return f"{self.exercise}: the package's own function (not counted)"
        if not self.failures:
            return f"{self.exercise}: {HEADLINES['budget']}"
        f = self.failures[0]
        if f.got is None and f.kind in HEADLINES:
            return _wrapped(f"{self.exercise}: {HEADLINES[f.kind]} ({f.case})")
        return _wrapped(f"{self.exercise} fails: {f.case}")

    def plot(self, ax):
        """Draw the first failing case (or, when all pass, a passing one) on ``ax``.

        Coverage exercises show the pixels: correct ones grey, *missing* ones (the rule
        covers them, the function did not) and *extra* ones (the reverse) marked, with the
        edge that decides the first wrong pixel drawn thick. A function that raised, ran out
        of time or returned None or the wrong type gets the case's expected answer with a
        note saying so; the title says "pass" only when the report passed. The untouched
        stub gets no drawing, only :data:`NOTHING_DRAWN_YET` (a case's picture holds its
        answer, which the student has not yet worked out). Returns the artists.
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
            note = self.stopped or self.package or str(self)
        elif self.not_implemented and drawing is None:
            note = NOTHING_DRAWN_FOR.get(self.exercise, NOTHING_DRAWN_YET)
        if note is not None:
            artists.append(_note(ax, note))
        artists.append(ax.set_title(self.title(), fontsize="small"))
        return artists

    def compare(self, axes=None, pixel=None):
        """The student's function in a whole picture, beside the package's, and where they differ.

        Draws three panels on ``axes`` (three Axes, one Axes split in three, or None: a new
        figure): yours, the package's and the differing pixels; ``pixel=(row, col)`` or
        ``"first"`` (the first differing pixel) is marked in every panel and explained below
        them; with an interactive backend a click explains the clicked pixel. The picture runs
        the student's function once, within the time a case may take, and not at all when the
        check stopped on a time limit. Exercises with a picture only; returns the artists.
        """
        picture = self._picture()
        picture.check_failed = not self.passed
        return picture.draw(axes, pixel)

    def explain_pixel(self, row: int, col: int) -> str:
        """Why pixel (``row``, ``col``) of the student's picture differs (or does not)."""
        return self._picture().explain(row, col)

    def differing_pixels(self):
        """(n, 2) rows and columns where the student's picture differs from the package's."""
        return self._picture().differing()

    def _picture(self):
        if self.scene is None:
            raise ValueError(f"report.compare draws a whole picture: {self.exercise} makes none")
        return self.scene


#: The reports :func:`~.checks.check` returned, by id, while they live (a dead report's entry
#: goes with it, so a reused id never matches): a report built by hand is not among them.
_ISSUED: weakref.WeakValueDictionary = weakref.WeakValueDictionary()


def issue(report: Report) -> Report:
    """Record ``report`` as one the checker made, and return it."""
    _ISSUED[id(report)] = report
    return report


def issued(report) -> bool:
    """Did the checker make ``report`` (:func:`issue`)? What is told only after a pass reads
    only such reports (r18-10: exercise 11's frame note was printed for any object with
    ``passed=True``). A cosmetic gate, not a lock: the package's source is readable."""
    return _ISSUED.get(id(report)) is report


def _wrapped(title: str, width: int = 60, lines: int = 3) -> str:
    """A title on at most ``lines`` lines of ``width`` (r64 01-3: "random 30: counter-clockwise
    on scree..." was cut at 40 characters, before the words that said what the case is)."""
    import re
    import textwrap

    # r84 03-4: a point's coordinates stay on one line ("p=(6.5,⏎6.5)" was cut in two)
    whole = re.sub(r"\([^()]{0,24}\)", lambda m: m.group(0).replace(" ", "\u00a0"), title)
    text = "\n".join(textwrap.wrap(whole, width, max_lines=lines, placeholder=" ..."))
    return text.replace("\u00a0", " ")


#: The stub's figure (issue 30, r46: every stub figure showed one case's expected answer).
NOTHING_DRAWN_YET = (
    "Nothing drawn yet: once your function returns answers, the check draws its first "
    "failing case (or, when all pass, one of the cases) with the rule's answer beside yours"
)


#: The stub's note for an exercise whose figure never draws the rule's answer (r395 N6: 11.3b
#: draws only yours), by exercise name; each such exercise puts its own words here.
NOTHING_DRAWN_FOR: dict[str, str] = {}


def _note(ax, text: str, width: int = 60):
    """A boxed note (what happened, where no answer can be drawn) across the part of the axes
    that no inset covers (r164: 3.1's note lay under the triangle inset on the right, half
    of it unreadable), wrapped to that part's width."""
    import textwrap

    from .drawing import NOTE_BESIDE

    if getattr(ax, NOTE_BESIDE, False):  # beside the axes, right, where the drawing asks it
        return ax.text(1.06, 0.5, "\n".join(textwrap.wrap(text, 34)[:12]), transform=ax.transAxes,
                       ha="left", va="center", fontsize="x-small",
                       bbox={"boxstyle": "round", "facecolor": "#fff4f2", "edgecolor": "#d7301f"})  # fmt: skip
    left, right = _free_span(ax)
    share = right - left
    lines = textwrap.wrap(text, max(16, int(width * share)))[: 6 if share > 0.9 else 16]
    return ax.text(
        (left + right) / 2,
        0.5,
        "\n".join(lines),
        transform=ax.transAxes,
        ha="center",
        va="center",
        fontsize="x-small",
        bbox={"boxstyle": "round", "facecolor": "#fff4f2", "edgecolor": "#d7301f"},
    )


def _free_span(ax) -> tuple[float, float]:
    """(left, right), in axes coordinates, of the widest strip of ``ax`` that none of its
    insets (:meth:`~matplotlib.axes.Axes.inset_axes` within it) covers, with a margin."""
    covered = []
    for inset in getattr(ax, "child_axes", ()):
        locator = inset.get_axes_locator()
        if locator is None:
            continue
        # the inset's box (figure fractions) in ``ax``'s own coordinates
        box = locator(inset, None).transformed(inset.figure.transSubfigure - ax.transAxes)
        x0, x1 = box.x0, box.x1
        if x0 < 1 and x1 > 0:  # inside the axes (hiz_tile's lies outside, at x < 0)
            covered.append((max(0.0, x0), min(1.0, x1)))
    if not covered:
        return 0.0, 1.0
    edges = sorted({0.0, 1.0, *(c for span in covered for c in span)})
    gaps = [(a, b) for a, b in zip(edges, edges[1:])
            if not any(lo < (a + b) / 2 < hi for lo, hi in covered)]  # fmt: skip
    a, b = max(gaps, key=lambda g: g[1] - g[0], default=(0.0, 1.0))
    return a + 0.02, b - 0.02
