"""r505 (exercise 1): 1.2 ``box`` refuses an answer that changes ``xy`` in place (the given fill
calls ``covers`` on the same array after it), names an empty box for a thin triangle as such
(it fitted a tolerance ε, or ⌊x_max⌋), stays fast, draws an empty answer in its legend and
says what ``tr.rasterize`` computes; the variants themselves run in test_checker_corpus through
student_variants.R505."""

from __future__ import annotations

import math
import time

import numpy as np

from teachraster import exercises as ex
from teachraster.exercises import centre_box as cb


def _right(xy, width, height):
    a = np.asarray(xy, dtype=float)
    c = lambda v, n: min(max(math.ceil(v - 0.5), 0), n)  # noqa: E731
    (x0, y0), (x1, y1) = a.min(axis=0), a.max(axis=0)
    return c(y0, height), c(y1, height), c(x0, width), c(x1, width)


def test_a_box_changing_xy_in_place_fails_and_says_so():
    def box(xy, width, height):
        xy -= 0.5  # the caller's array: the given fill's covers would test another triangle
        return _right(xy + 0.5, width, height)

    report = ex.check("box", box)
    assert not report.passed
    assert "changed xy in place (v1 was (2.5, 1.5), now (2.0, 1.0))" in str(report), str(report)


def test_a_copy_changed_is_fine():
    def box(xy, width, height):
        xy = np.array(xy, dtype=float)
        xy.sort(axis=0)  # a copy of its own
        return _right(xy, width, height)

    assert ex.check("box", box).passed


def test_an_empty_box_for_a_thin_triangle_is_named_not_a_tolerance():
    def box(xy, width, height):
        a = np.asarray(xy, dtype=float)
        if abs(np.cross(a[1] - a[0], a[2] - a[0])) < 1:  # "zero area" with a tolerance
            return 0, 0, 0, 0
        return _right(xy, width, height)

    start = time.process_time()
    report = ex.check("box", box)
    assert time.process_time() - start < 1.0
    first = report.failures[0].explanation
    assert "your box is empty, yet this thin triangle covers 6 centre(s)" in first, first
    assert "its area is 0.122 px², small but not 0" in first, first
    assert "tolerance ε subtracted" not in first and "⌊x_max⌋" not in first, first


def test_the_tolerance_needs_the_very_empty_box():
    label, args, expected = next(c for c in cb.box_cases() if c[0].startswith("a vertical"))
    assert cb._tolerance(args, expected, (0, 0, 0, 0)) is None
    assert cb._tolerance(args, expected, (1, 7, 4, 4)) is not None  # ⌈v − ½ − 0.05⌉


def test_an_empty_answer_is_in_the_legend():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    case = next(c for c in cb.box_cases() if c[0].startswith("a vertical"))
    cb.draw_box(ax, case, (0, 0, 0, 0))
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "yours: (0, 0, 0, 0), empty" in labels, labels
    plt.close(fig)


def test_rasterize_is_not_said_to_compute_the_box():
    import teachraster as tr

    def box(xy, width, height):
        cov = tr.rasterize(tr.Triangle(np.asarray(xy, float)), width, height).coverage
        r, c = np.flatnonzero(cov.any(1)), np.flatnonzero(cov.any(0))
        return (0, 0, 0, 0) if not r.size else (r[0], r[-1] + 1, c[0], c[-1] + 1)

    text = str(ex.check("box", box))
    assert "the pixels the triangle covers, not the box" in text, text
    assert "computes this very answer" not in text, text
