"""``names()`` and ``check(name, fn, budget=10.0)``: run an exercise's cases, build its report."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from . import lines_blending, near_clip, reasoning_tasks, scalars
from .answers import MAX_VERTICES, as_bool, as_number, as_numbers, short
from .coverage_checks import check_covers, check_fill
from .report import Report
from .running import SKIPPED, WrongAnswerType, check_seconds
from .running import budget as time_budget
from .tolerance import all_close, close, same_polygon
from .value_checks import ValueExercise, check_value_exercise


def _vector3(value) -> np.ndarray:
    return as_numbers(value, (3,), "3 weights, shape (3,)")


def _polygon(value) -> np.ndarray:
    sized = isinstance(value, (list, tuple)) or (isinstance(value, np.ndarray) and value.ndim)
    if sized and len(value) > MAX_VERTICES:  # before any conversion: a huge answer costs nothing
        raise WrongAnswerType(
            f"returned {short(value)}: a triangle clipped by one plane has at most 4 vertices"
        )
    if sized and np.size(value) == 0:
        return np.zeros((0, 4))
    return as_numbers(value, (-1, 4), "an (n, 4) array of vertices (x, y, z, w)")


# -- drawings of the value exercises (matplotlib is imported only inside .drawing) ------------
def _draw_edge(ax, case, got):
    from .drawing import draw_values

    return draw_values(ax, ["E(a, b, p)"], [case[2]], None if got is None else [got])


def _draw_split(ax, case, got):
    from .drawing import draw_split

    return draw_split(ax, case[1][0], case[2], got)


def _draw_bary(ax, case, got):
    from .drawing import draw_values

    return draw_values(ax, ["λ1", "λ2", "λ3"], case[2], got)


def _draw_persp(ax, case, got):
    from .drawing import draw_bars

    lam, w, f = case[1]
    labels = ["perspective-\ncorrect", "affine Σλf"]
    values = [case[2], float(lam @ f)]
    if got is not None:
        labels.append("yours")
        values.append(got)
    wrong = [False, False, got is not None and not close(got, case[2])]
    return draw_bars(ax, labels, values, wrong[: len(values)])


def _draw_depth(ax, case, got):
    from .drawing import draw_bars

    a, b = case[1]
    passes = "passes" if case[2] else "fails"
    artists = draw_bars(ax, ["incoming", "stored"], [a, b], [False, False])
    yours = "" if got is None else f", yours {'passes' if got else 'fails'}"
    artists.append(ax.set_xlabel(f"depth (smaller is nearer): it {passes}{yours}"))
    return artists


def _draw_clip(ax, case, got):
    from .drawing import draw_clip

    return draw_clip(ax, case[1][0], case[2], got)


#: How each value exercise is checked (every exercise but covers and fill).
VALUE_EXERCISES = {
    "edge_function": ValueExercise(
        scalars.edge_function_cases,
        as_number,
        close,
        scalars.explain_edge_function,
        _draw_edge,
        scalars.edge_function_pattern,
    ),
    "split_point": ValueExercise(
        scalars.split_point_cases, as_number, close, scalars.explain_split_point, _draw_split
    ),
    "barycentric": ValueExercise(
        scalars.barycentric_cases,
        _vector3,
        all_close,
        scalars.explain_barycentric,
        _draw_bary,
        scalars.barycentric_pattern,
    ),
    "perspective": ValueExercise(
        scalars.perspective_cases, as_number, close, scalars.explain_perspective, _draw_persp
    ),
    "depth_test": ValueExercise(
        scalars.depth_test_cases,
        as_bool,
        lambda a, b: a == b,
        scalars.explain_depth_test,
        _draw_depth,
    ),
    "clip_near": ValueExercise(
        near_clip.clip_cases, _polygon, same_polygon, near_clip.explain_clip, _draw_clip
    ),
}


def check_values(name: str, fn) -> Report:
    """Check one of the value exercises (every exercise but covers and fill)."""
    return check_value_exercise(name, fn, VALUE_EXERCISES[name])


from . import later  # noqa: E402  (exercises 05–08: their own modules, registered below)

#: The exercises in course order, and what checks each.
EXERCISES: dict[str, Callable] = {
    "edge_function": lambda fn: check_values("edge_function", fn),
    "covers": check_covers,
    "fill": check_fill,
    "split_point": lambda fn: check_values("split_point", fn),
    "barycentric": lambda fn: check_values("barycentric", fn),
    "perspective": lambda fn: check_values("perspective", fn),
    "depth_test": lambda fn: check_values("depth_test", fn),
    "clip_near": lambda fn: check_values("clip_near", fn),
    **later.EXERCISES,  # 05–08: depth precision, antialiasing, texture filtering, tiles
    **lines_blending.EXERCISES,  # lesson 12: line_pixels, over, over_premultiplied
    **reasoning_tasks.EXERCISES,  # issue 30: reasoning tasks, lessons 07-12, broken frames
}


def names() -> list[str]:
    """The exercises, in course order.

    >>> names()[:3]
    ['edge_function', 'covers', 'fill']
    """
    return list(EXERCISES)


def check(name: str, fn: Callable, *, budget: float = 10.0) -> Report:
    """Run exercise ``name``'s cases on the student's ``fn`` and explain every failure.

    Never raises and never hangs because of ``fn``: its exceptions (``SystemExit`` included)
    become failures; ``NotImplementedError`` on every case marks the report "not implemented
    yet"; the whole check, comparison and explanations included, takes about ``budget``
    seconds at most, a case at most a fifth of it, and the check stops at the first case that
    runs past its limit (an endless loop is reported after 2 s of the default 10).
    """
    if not isinstance(name, str) or name not in EXERCISES:
        raise ValueError(f"name must be one of {names()}, got {name!r}")
    if not callable(fn):
        raise TypeError(f"fn must be a function, got {type(fn).__name__}")
    seconds = check_seconds(budget)
    with time_budget(seconds) as b:
        report = EXERCISES[name](fn)
    if b.stopped is not None and report.stopped is None:  # an exercise that does not say
        kept = [f for f in report.failures if f.explanation != SKIPPED]
        n_run = report.n_cases - (len(report.failures) - len(kept))
        report = replace(report, failures=kept, stopped=b.stopped, n_run=n_run)
    return report
