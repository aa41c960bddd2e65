"""Exercise ``defect_case`` (exercise 3.1b, lesson 03; r488, issue 30): a case for each defect.

r455 T1: 3.1 ``barycentric`` is lesson 03 §1's formula written out. Exercise 3 now ships a
``barycentric`` with two defects (:func:`shipped_barycentric`, printed in a locked cell): its
zero-area test reads ``np.linalg.cond`` of the 3 × 3 matrix of the equations, and it divides by
``abs(E)``. The student repairs it (3.1, the check of ``barycentric``) and, for each defect
(:data:`DEFECTS`), returns ``(xy, p)``, a proper triangle on the 1/256-px grid and a point, on
which

- the shipped code with the *other* defect repaired is wrong (raises, or weights off by more
  than the check's 1e-6), so the defect is needed to break it, and
- the shipped code with this defect alone repaired is right (nothing else breaks it).

A "zero-area test" case must be at least 1 px² in area (:data:`LEAST_E`): the check's thin
far triangles, which the report of the shipped code quotes, are not one; nor is any triangle of
``barycentric``'s check. The expected weights are exact (fractions). The check
is two cases, a few solves each. The check watches every function of this module (r495 W2: a
search through :func:`verdict` passed): :func:`shipped_barycentric` lives in :mod:`.bary_shipped`,
so that the notebook's copy of it stays a tool.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from ..core.validate import as_finite
from .answers import refuse_non_answers, short
from .bary_shipped import (  # noqa: F401  (r495: its own module; re-exported)
    COND_LIMIT,
    DEFECTS,
    patched_barycentric,
    shipped_barycentric,
)
from .case_verdicts import CaseVerdicts
from .exercise import Exercise, PackageAnswer
from .package_answers import CHECKER_WORDS
from .running import WrongAnswerType
from .scalars import num, tri_words, vec

#: Every coordinate within this many px of the origin (the check's range; float64 holds every
#: product of two differences there exactly, so E is exact).
FAR = 1e5
#: A "zero-area test" case: |E(v1, v2, v3)| at least this (area 1 px²).
LEAST_E = 2
#: Weights this close to the exact ones count as right (``barycentric``'s check far out).
TOL = 1e-6


def _e(a, b, c):
    return float((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def cond(xy) -> float:
    """The condition number the shipped test reads."""
    return float(np.linalg.cond(np.vstack([np.asarray(xy, float).T, np.ones(3)])))


def exact_weights(xy, p) -> np.ndarray:
    """The weights in exact arithmetic (fractions), as float64."""
    v = [[Fraction(c) for c in q] for q in np.asarray(xy, float)]
    q = [Fraction(c) for c in np.asarray(p, float)]

    def e(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    area = e(v[0], v[1], v[2])
    l1, l2 = e(v[1], v[2], q) / area, e(v[2], v[0], q) / area
    return np.array([float(l1), float(l2), float(1 - l1 - l2)])


def outcome(case, repaired):
    """What :func:`patched_barycentric` gives on ``case``: weights, or the text of its error."""
    try:
        return patched_barycentric(*case, repaired)
    except ValueError as exc:
        return f"ValueError: {exc}"


def breaks(case, repaired) -> bool:
    """Is :func:`patched_barycentric` wrong on ``case`` (raises, or off by more than TOL)?"""
    got = outcome(case, repaired)
    return isinstance(got, str) or not np.allclose(got, exact_weights(*case), rtol=0, atol=TOL)


def as_case(value):
    """``(xy, p)`` read strictly: xy (3, 2) finite numbers, p 2."""
    refuse_non_answers(value, "a tuple (xy, p)")
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise WrongAnswerType(f"returned {short(value)}: expected a tuple (xy, p)")
    try:
        xy = as_finite("xy", value[0], (3, 2)).astype(float)
        p = as_finite("p", value[1], (2,)).astype(float)
    except (TypeError, ValueError) as exc:
        raise WrongAnswerType(f"returned {short(value)}: {exc}") from None
    return (xy, p)


def _vertices(xy) -> tuple:
    """The triangle's vertices in any order."""
    return tuple(sorted(map(tuple, np.asarray(xy, float).tolist())))


_CATALOGUE: dict = {}


def catalogue() -> dict:
    """``barycentric``'s fixed cases (not the drawn ones): vertices -> label."""
    if not _CATALOGUE:
        from .interpolation import OFF_CENTRE, THIN_FAR, proper_triangles

        fixed = [(label, xy) for label, xy in proper_triangles()]
        fixed += [(label, xy) for label, xy, _ in (*OFF_CENTRE, *THIN_FAR)]
        for label, xy in fixed:
            _CATALOGUE.setdefault(_vertices(xy), label)
    return _CATALOGUE


def _off_grid(case) -> str | None:
    xy, p = case
    for what, v in (*((f"v{k + 1}", xy[k]) for k in range(3)), ("p", p)):
        if np.abs(v).max() > FAR:
            return (f"{what} = {vec(v)} has a coordinate outside −{FAR:,.0f} to {FAR:,.0f} px "
                    "(the task's range)")  # fmt: skip
        if np.any(np.round(v * 256) / 256 != v):
            return (
                f"{what} = {vec(v)} is off the 1/256-px grid (every coordinate a multiple of 1/256)"
            )
    return None


def _weights_words(case, repaired) -> str:
    got = outcome(case, repaired)
    if isinstance(got, str):  # r495 S1: not "raises ValueError: zero area: p = ... off the grid"
        return "raises ValueError (its zero-area test refuses the triangle)"
    return f"returns {vec(got, exact_weights(*case))}"


def _verdict_of(defect: str, case) -> tuple[str, str] | None:
    """(kind, words) of what is wrong with ``case`` as a case for ``defect``; None if it is one."""
    xy, p = case
    other = next(d for d in DEFECTS if d != defect)
    words = _off_grid(case)
    if words:
        return "out of range", words
    area = _e(*xy)
    if area == 0:
        return "zero area", ("your triangle has zero area (E(v1, v2, v3) = 0 exactly: its "
                             "vertices lie on one line), and refusing it is right: the task asks "
                             "for a proper triangle that the shipped code gets wrong")  # fmt: skip
    label = catalogue().get(_vertices(xy))
    if label is not None:
        return "catalogue", (f"your triangle is the case '{label}' of barycentric's check: "
                             "find one of your own")  # fmt: skip
    if defect == "zero-area test" and abs(area) < LEAST_E:
        return "thin", (f"your triangle's area is {num(abs(area) / 2)} px², below the task's 1 "
                        "px² (E(v1, v2, v3) = " f"{area!r}): find a triangle at least a pixel "
                        "large that the shipped test refuses")  # fmt: skip
    if _needed_words(other, defect, case) is None and (
        other != "zero-area test" or abs(area) >= LEAST_E
    ):
        return "the other defect's", (f"this is a case for the other defect, '{other}', not "
                                      f"for '{defect}': each defect has a case of its own")  # fmt: skip
    return _needed_words(defect, other, case)


def _needed_words(defect: str, other: str, case) -> tuple[str, str] | None:
    xy, p = case
    exact = vec(exact_weights(*case))
    if not breaks(case, (other,)):
        if defect == "zero-area test":
            return "passes the test", (
                f"the shipped test lets this triangle through (its condition number is "
                f"{cond(xy):.2g}, not above 1e8), and with the area repaired the shipped code "
                f"returns the right weights {exact}: what makes that number larger?"
            )
        if _e(*xy) < 0:  # abs flips λ1 and λ2: harmless only where they are (about) 0
            return "at v3", _at_v3_words(case)
        return "area right", (f"with the zero-area test repaired, the shipped code returns the "
                              f"right weights {exact} here: E(v1, v2, v3) = {_e(*xy)!r}, and "
                              "abs(E) = E, so dividing by abs(E) changes nothing on this "
                              "triangle")  # fmt: skip
    if breaks(case, (defect,)):
        if defect == "zero-area test":
            return "also needs", (f"the other defect breaks it too: with the zero-area test "
                                  f"repaired alone, the shipped code still {_weights_words(case, (defect,))} "
                                  f"where the weights are {exact}; a case for the zero-area test "
                                  "must be right once that test alone is repaired")  # fmt: skip
        return "also needs", (f"the other defect breaks it too: the shipped zero-area test refuses this triangle (its "
                              f"condition number is {cond(xy):.2g}, above 1e8): with the area "
                              f"repaired alone the shipped code {_weights_words(case, (defect,))}; "
                              "a case for the area must pass that test")  # fmt: skip
    return None


def _at_v3_words(case) -> str:
    """Why a clockwise triangle's case for the area is not one: p is v3, or so near it that
    the sign slip on λ1 and λ2 stays within :data:`TOL` (r495 M1, M2: "abs(E) = E" was said
    of E < 0, "at p = v3" of a p 1/256 px from it)."""
    xy, p = case
    exact = exact_weights(*case)
    if np.array_equal(p, xy[2]):
        return (f"at p = v3 the shipped code's λ1 and λ2 are 0 and its λ3 = 1 − 0 − 0 is right "
                f"whatever it divides by: its weights {vec(exact)} are right here; move p")  # fmt: skip
    off = float(np.abs(patched_barycentric(*case, ("zero-area test",)) - exact).max())
    return (f"E(v1, v2, v3) = {_e(*xy)!r} < 0, so abs flips the signs of λ1 and λ2, but p lies "
            f"{num(float(np.hypot(*(p - xy[2]))))} px from v3 on this triangle, where λ1 and λ2 "
            f"are only {num(abs(exact[0]))} and {num(abs(exact[1]))}: the shipped weights are "
            f"off by {off:.2g}, within the check's {TOL:g}; move p further from v3")  # fmt: skip


#: :func:`_verdict_of`, remembered for the check's few answers (one place: case_verdicts).
verdict = CaseVerdicts(_verdict_of, key=lambda case: (case[0].tobytes(), case[1].tobytes()))


#: The kinds of a wrong case, most specific first.
KINDS = ("out of range", "zero area", "catalogue", "thin", "the other defect's",
         "passes the test", "at v3",
         "area right", "also needs")  # fmt: skip


def cases() -> list[tuple[str, tuple, str]]:
    """One case per defect; the expected answer is the defect's name (any case of it is right)."""
    return [(f"the defect '{d}'", (d,), d) for d in DEFECTS]


def _explain(args, expected, got) -> str:
    xy, p = got
    return (f"defect_case('{args[0]}'): {tri_words(xy)}, p = {vec(p)}; the shipped code "
            f"{_weights_words(got, ())}")  # fmt: skip


def _rule(args, expected, got) -> str:
    return ""


def _compose(head: str, words: str) -> str:
    return f"{head}: {words}" if words else head


def draw_case(ax, case, got):
    """The student's triangle and point, and the shipped code's weights on them."""
    if isinstance(got, str) or got is None:
        ax.set_axis_off()
        return [ax.text(0.5, 0.5, "a case for each defect:\nsee the printed report",
                        ha="center", va="center", transform=ax.transAxes)]  # fmt: skip
    xy, p = got
    ring = np.vstack([xy, xy[:1]])
    artists = ax.plot(ring[:, 0], ring[:, 1], "-o", color="C0", label="your triangle")
    artists += ax.plot(*p, "x", color="C3", label=f"p; shipped: {_weights_words(got, ())}"[:70])
    for k, v in enumerate(xy):
        artists.append(ax.annotate(f"v{k + 1}", v, textcoords="offset points", xytext=(4, 4)))
    ax.set_aspect("equal", adjustable="datalim")
    ax.invert_yaxis()
    ax.set_xlabel("x (px)")
    ax.set_ylabel("y (px, down)")
    ax.margins(0.45)  # room for the legend beside the triangle
    ax.ticklabel_format(useOffset=False)  # 20 000 px out: whole coordinates, no "+2e4"
    ax.legend(loc="best", fontsize="small", framealpha=0.8)
    return artists


DEFECT_CASE = Exercise(
    "defect_case", cases, as_case, verdict.same, _explain, _rule,
    verdict.mistakes(KINDS), draw=draw_case, compose=_compose,
    reference=("teachraster.exercises.interpolation",),
    # r495 W2: a search through the checker's judge (``verdict``, ``breaks``) passed uncounted:
    # the window that watches the checker's modules opens for an exercise with answers
    answers=(PackageAnswer(verdict, words=CHECKER_WORDS),
             # r506: patched_barycentric lives beside the shipped code (3.1's check reads it)
             PackageAnswer(patched_barycentric, words=CHECKER_WORDS)),
)  # fmt: skip
