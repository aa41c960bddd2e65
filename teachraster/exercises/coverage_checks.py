"""Check the coverage exercises, ``covers`` (one centre) and ``fill`` (a whole image).

As for the value exercises (:mod:`.value_checks`): every case runs within the budget and the
check stops at the first case past its limit; then each answer is compared with the core's
coverage and each failure explained (:mod:`.coverage`), within the budget too. ``fill`` may
return bools or 0/1 numbers (``np.zeros((h, w))`` filled with 1.0 is a correct answer); a
transposed image is recognised as such.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from . import coverage
from .answers import as_bool, as_coverage
from .cases import CoverageCase, catalogue_coverage, random_coverage
from .report import Failure, Report
from .running import SKIPPED, current, run_case, run_checker
from .value_checks import STOPS, all_not_implemented


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
                    out[t, i, j] = as_bool(fn(xy.copy(), p))
        return out

    return body


def _fill_body(fn, case: CoverageCase):
    def body():
        w, h = case.size
        return [as_coverage(fn(xy.copy(), w, h), h, w) for xy in case.triangles]

    return body


#: What a mirrored answer means, by exercise and mirror.
MIRRORED = {
    ("fill", "transposed"): (
        "your image is transposed: its [i, j] holds the pixel in row j and column i. An image "
        "is indexed [row, column] = [y, x]: np.zeros((height, width)) = {shape}, and out[i, j] "
        "is the pixel whose centre is (x, y) = (j + 0.5, i + 0.5)"
    ),
    ("covers", "transposed"): (
        "your coverage is the rule's mirrored across the diagonal: x and y are swapped "
        "somewhere. A point is (x, y) = (p[0], p[1]), x to the right, y down, and so is each "
        "vertex"
    ),
    ("fill", "upside down"): (
        "your image is upside down: row i holds the pixels whose centres have y = i + 0.5, with "
        "y pointing down (row 0 at the top), so do not flip the rows (height − 1 − i)"
    ),
}


def _mirrored(name: str, case, k: int, got: np.ndarray, expected: np.ndarray, how: str):
    text = MIRRORED[name, how].format(shape=expected.shape)
    label = case.label + (f", triangle {k}" if len(case.triangles) > 1 else "")
    shown = got if got.shape == expected.shape else got.T

    def draw(ax):
        from .drawing import draw_coverage

        return draw_coverage(ax, case, case.triangles[k], expected, shown, None, None)

    return Failure(label, text, expected, got, draw, how)


def _compare(name: str, case: CoverageCase, got: list, expected: np.ndarray) -> Failure | None:
    """The first wrong triangle of ``case`` explained, or None when all are right."""
    for k, g in enumerate(got):
        e = expected[k]
        flipped = g.shape != e.shape
        if not flipped and np.array_equal(g, e):
            continue
        if np.array_equal(g.T, e):
            return _mirrored(name, case, k, g, e, "transposed")
        if name == "fill" and not flipped and np.array_equal(g[::-1], e):
            return _mirrored(name, case, k, g, e, "upside down")
        fixed = np.array([x.T if x.shape != e.shape else x for x in got])
        failure = coverage.coverage_failure(case, k, fixed, expected)
        if flipped:
            text = (
                f"your image has shape {g.shape} = (width, height), transposed: an image is "
                f"(height, width) = {e.shape}. Even transposed back it is wrong: "
            )
            failure = replace(failure, explanation=text + failure.explanation, kind="transposed")
        return failure
    return None


def _check_coverage(name: str, fn, cases: list[CoverageCase], body) -> Report:
    ran = []
    for k, case in enumerate(cases):
        outcome = run_case(body(fn, case), case=f"{k + 1} of {len(cases)}")
        if outcome.error == SKIPPED:
            break
        ran.append((case, outcome))
        if outcome.kind in STOPS:
            break
    example = coverage.example_drawing(cases[0])
    if all_not_implemented(ran):
        return Report(name, [], len(cases), True, example)
    failures = []
    for case, outcome in ran:
        expected = np.array([coverage.expected_coverage(case, xy) for xy in case.triangles])
        if outcome.error is not None:
            draw = coverage.example_drawing(case, expected_only=True)
            failures.append(Failure(case.label, outcome.error, expected, None, draw, outcome.kind))
            continue
        fallback = Failure(case.label, "your coverage differs from the rule's", expected, None)
        failure = run_checker(
            lambda c=case, o=outcome, e=expected: _compare(name, c, o.value, e), fallback
        )
        if failure is not None:
            failures.append(failure)
    return Report(name, failures, len(cases), False, example, current().stopped, len(ran))


def check_covers(fn) -> Report:
    cases = catalogue_coverage() + random_coverage()
    return _check_coverage("covers", fn, cases, _covers_body)


def check_fill(fn) -> Report:
    # fill draws the image from the origin: cases far from it have no pixel to show
    cases = [c for c in catalogue_coverage() + random_coverage(far=False) if c.origin == (0, 0)]
    report = _check_coverage("fill", fn, cases, _fill_body)
    return replace(report, comparison=_lazy_comparison(fn, current().seconds))


def _lazy_comparison(fn, seconds: float):
    """The whole-picture comparison, computed on the first ``report.compare`` only."""
    done = []

    def comparison():
        from .compare import COMPARE_BUDGET, compare_fill

        if not done:
            done.append(compare_fill(fn, max(seconds, COMPARE_BUDGET)))
        return done[0]

    return comparison
