"""``names()`` and ``check(name, fn)``: run an exercise's cases and build its report."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from . import coverage, lines_blending, near_clip, scalars
from .cases import CoverageCase, catalogue_coverage, random_coverage
from .report import Failure, Report
from .running import WrongAnswerType, run_case
from .tolerance import all_close, close, same_polygon


def _as_bool(value) -> bool:
    arr = np.asarray(value)
    if arr.size != 1 or arr.dtype.kind not in "bui":
        raise WrongAnswerType(f"returned {value!r:.60}, not a bool")
    return bool(arr.item())


def _window(case: CoverageCase, xy: np.ndarray):
    """Rows and columns of the window worth testing: the triangle's box and one more pixel."""
    w, h = case.size
    lo = np.floor(xy.min(axis=0) - case.origin).astype(int) - 1
    hi = np.ceil(xy.max(axis=0) - case.origin).astype(int) + 1
    return range(max(lo[1], 0), min(hi[1], h)), range(max(lo[0], 0), min(hi[0], w))


def _covers_body(fn, case: CoverageCase):
    def body():
        w, h = case.size
        out = np.zeros((len(case.triangles), h, w), dtype=bool)
        x0, y0 = case.origin
        for t, xy in enumerate(case.triangles):
            rows, cols = _window(case, xy)
            for i in rows:
                for j in cols:
                    p = np.array([x0 + j + 0.5, y0 + i + 0.5])
                    out[t, i, j] = _as_bool(fn(xy.copy(), p))
        return out

    return body


def _fill_body(fn, case: CoverageCase):
    def body():
        w, h = case.size
        out = []
        for xy in case.triangles:
            got = np.asarray(fn(xy.copy(), w, h))
            if got.shape != (h, w) or got.dtype.kind not in "bui":
                raise WrongAnswerType(
                    f"returned a {got.dtype} array of shape {got.shape}; expected a bool array "
                    f"of shape (height, width) = {(h, w)}"
                )
            out.append(got.astype(bool))
        return np.array(out)

    return body


def _check_coverage(name: str, fn, cases: list[CoverageCase], body) -> Report:
    failures = []
    for case in cases:
        expected = np.array([coverage.expected_coverage(case, xy) for xy in case.triangles])
        outcome = run_case(body(fn, case))
        if outcome.not_implemented:
            return Report(name, [], len(cases), True, coverage.example_drawing(cases[0]))
        if outcome.error:
            failures.append(Failure(case.label, outcome.error, expected, None))
            continue
        for k in range(len(case.triangles)):
            if not np.array_equal(outcome.value[k], expected[k]):
                failures.append(coverage.coverage_failure(case, k, outcome.value, expected))
                break  # one failure per case keeps the report readable
    return Report(name, failures, len(cases), False, coverage.example_drawing(cases[0]))


def check_covers(fn) -> Report:
    cases = catalogue_coverage() + random_coverage()
    return _check_coverage("covers", fn, cases, _covers_body)


def check_fill(fn) -> Report:
    # fill draws the image from the origin: cases far from it have no pixel to show
    cases = [c for c in catalogue_coverage() + random_coverage(far=False) if c.origin == (0, 0)]
    return _check_coverage("fill", fn, cases, _fill_body)


def _check_values(name, fn, cases, convert, same, explain, draw) -> Report:
    """Run ``fn(*args)`` on ``cases`` of (label, args, expected) and compare with ``same``."""
    failures = []
    for label, args, expected in cases:
        copies = tuple(np.array(a, copy=True) if isinstance(a, np.ndarray) else a for a in args)
        outcome = run_case(lambda copies=copies: convert(fn(*copies)))
        if outcome.not_implemented:
            return Report(name, [], len(cases), True, _drawer(draw, cases[0], None))
        if outcome.error:
            failures.append(Failure(label, outcome.error, expected, None))
        elif not same(outcome.value, expected):
            text = explain(args, expected, outcome.value)
            case = (label, args, expected)
            failures.append(
                Failure(label, text, expected, outcome.value, _drawer(draw, case, outcome.value))
            )
    return Report(name, failures, len(cases), False, _drawer(draw, cases[0], cases[0][2]))


def _drawer(draw, case, got):
    def drawing(ax):
        return draw(ax, case, got)

    return drawing


def _numbers(value) -> np.ndarray:
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise WrongAnswerType(f"returned {value!r:.60}, not numbers") from None


def _float(value) -> float:
    arr = _numbers(value)
    if arr.size != 1:
        raise WrongAnswerType(f"returned {value!r:.60}, not one number")
    return float(arr.item())


def _vector3(value) -> np.ndarray:
    arr = _numbers(value)
    if arr.shape != (3,):
        raise WrongAnswerType(f"returned {value!r:.60}; expected 3 weights, shape (3,)")
    return arr


def _polygon(value) -> np.ndarray:
    arr = _numbers(value)
    if arr.size == 0:
        return np.zeros((0, 4))
    if arr.ndim != 2 or arr.shape[1] != 4:
        raise WrongAnswerType(f"returned {value!r:.60}; expected an (n, 4) array of vertices")
    return arr


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


def check_values(name: str, fn) -> Report:
    """Check one of the value exercises (every exercise but covers and fill)."""
    spec = {
        "edge_function": (
            scalars.edge_function_cases,
            _float,
            close,
            scalars.explain_edge_function,
            _draw_edge,
        ),
        "split_point": (
            scalars.split_point_cases,
            _float,
            close,
            scalars.explain_split_point,
            _draw_split,
        ),
        "barycentric": (
            scalars.barycentric_cases,
            _vector3,
            all_close,
            scalars.explain_barycentric,
            _draw_bary,
        ),
        "perspective": (
            scalars.perspective_cases,
            _float,
            close,
            scalars.explain_perspective,
            _draw_persp,
        ),
        "depth_test": (
            scalars.depth_test_cases,
            _as_bool,
            lambda a, b: a == b,
            scalars.explain_depth_test,
            _draw_depth,
        ),
        "clip_near": (
            near_clip.clip_cases,
            _polygon,
            same_polygon,
            near_clip.explain_clip,
            _draw_clip,
        ),
    }
    cases, convert, same, explain, draw = spec[name]
    return _check_values(name, fn, cases(), convert, same, explain, draw)


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
}


def names() -> list[str]:
    """The exercises, in course order.

    >>> names()[:3]
    ['edge_function', 'covers', 'fill']
    """
    return list(EXERCISES)


def check(name: str, fn: Callable) -> Report:
    """Run exercise ``name``'s cases on the student's ``fn`` and explain every failure.

    Never raises because of ``fn``: its exceptions become failures, ``NotImplementedError``
    marks the report "not implemented yet", and each case has a time limit.
    """
    if name not in EXERCISES:
        raise ValueError(f"name must be one of {names()}, got {name!r}")
    if not callable(fn):
        raise TypeError(f"fn must be a function, got {type(fn).__name__}")
    return EXERCISES[name](fn)
