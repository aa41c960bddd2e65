"""r494 (exercise 1): 1.2 ``box``'s new cases (a sliver covering no centre while its bounding
box holds some; bounds 1/256 px off a centre near the origin; bounds between −½ and ½) are
right by the package, cheap, and the mistakes they catch are named (the variants themselves run
in test_checker_corpus through student_variants.R494); the far cases' figure has no axis
offset over its label."""

from __future__ import annotations

import time

import numpy as np

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import centre_box as cb


def _case(start):
    return next(c for c in cb.box_cases() if c[0].startswith(start))


def _rectangle_box(xy, width, height):
    a = np.asarray(xy, dtype=float)
    (x0, y0), (x1, y1) = a.min(axis=0), a.max(axis=0)
    cov = np.zeros((height, width), dtype=bool)
    for t in ([[x0, y0], [x1, y0], [x0, y1]], [[x1, y0], [x1, y1], [x0, y1]]):
        cov |= tr.rasterize(tr.Triangle(np.array(t, dtype=float)), width, height).coverage
    rows, cols = np.flatnonzero(cov.any(axis=1)), np.flatnonzero(cov.any(axis=0))
    return int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1


def test_the_new_cases_are_the_packages_boxes():
    for start in ("a sliver covering no centre", "x_min and y_max 1/256 px", "x_min and y_min"):
        label, args, expected = _case(start)
        assert _rectangle_box(*args) == expected, label


def test_the_sliver_covers_nothing_while_its_box_holds_centres():
    _, (xy, w, h), expected = _case("a sliver covering no centre")
    assert not tr.rasterize(tr.Triangle(xy), w, h).coverage.any()
    r0, r1, c0, c1 = expected
    assert (r1 - r0) * (c1 - c0) == 18


def test_float32_is_exact_on_the_near_tolerance_case():
    """A tolerance, not float32, moves its bounds: float32 gives the right box there."""
    _, (xy, w, h), expected = _case("x_min and y_max 1/256 px")
    assert cb.centre_box(np.asarray(xy, np.float32).astype(float), w, h) == expected
    eps = cb._tolerance((xy, w, h), expected, (2, 5, 2, 7))
    assert eps == (-1, [1, 2])


def test_a_tolerance_is_not_called_float32_and_the_check_stays_fast():
    import math

    def box(xy, width, height):
        f = lambda v: math.ceil(v - 0.5 - 0.004)  # noqa: E731
        a = np.asarray(xy)
        c = lambda k, n: min(max(k, 0), n)  # noqa: E731
        lo, hi = a.min(0), a.max(0)
        return c(f(lo[1]), height), c(f(hi[1]), height), c(f(lo[0]), width), c(f(hi[0]), width)

    start = time.process_time()
    text = str(ex.check("box", box))
    assert time.process_time() - start < 1.0
    assert "float32" not in text, text
    assert text.count("a tolerance ε subtracted before rounding") == 3, text


def test_the_far_figure_has_no_axis_offset():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    cb.draw_box(ax, _case("100 000 px from the origin in x"), (1, 4, 100000, 100004))
    fig.canvas.draw()
    assert ax.xaxis.get_offset_text().get_text() == ""
    plt.close(fig)
