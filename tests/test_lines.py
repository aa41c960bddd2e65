"""Lines: the diamond-exit rule against an exact Fraction reference, Bresenham, DDA, wide lines,
attributes along the line, the trace and bad input."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import teachraster as tr
from teachraster.core.lines import wide_line_triangles

#: A concrete ε far below the 1/512 grid: on inputs with denominators 256 and coordinates
#: below 64, (ε, ε²) then decides every tie as the infinitesimal perturbation does.
EPS = Fraction(1, 2**80)


def _meets_open_diamond(a, b, centre) -> bool:
    """Does the closed segment a→b meet the open diamond |x-cx| + |y-cy| < 1/2? (Cyrus-Beck
    in x, y against the four open half-planes, in Fractions.)"""
    lo, hi = Fraction(0), Fraction(1)
    lo_strict = hi_strict = False
    dx, dy = b[0] - a[0], b[1] - a[1]
    for sx, sy in ((1, 1), (1, -1), (-1, 1), (-1, -1)):
        # sx (x - cx) + sy (y - cy) < 1/2 along a + t d
        c = Fraction(1, 2) - sx * (a[0] - centre[0]) - sy * (a[1] - centre[1])
        rate = sx * dx + sy * dy
        if rate == 0:
            if c <= 0:
                return False
        elif rate > 0:
            t = c / rate
            if t < hi or (t == hi and not hi_strict):
                hi, hi_strict = t, True
        else:
            t = c / rate
            if t > lo or (t == lo and not lo_strict):
                lo, lo_strict = t, True
    return lo < hi or (lo == hi and not lo_strict and not hi_strict)


def _inside_open_diamond(p, centre) -> bool:
    return abs(p[0] - centre[0]) + abs(p[1] - centre[1]) < Fraction(1, 2)


def reference_line(p0, p1, width, height) -> np.ndarray:
    """The GL rule in exact arithmetic: perturb both ends by -(ε, ε²), light the pixels whose
    diamond the segment meets unless it ends inside."""
    snap = [tuple(Fraction(round(v * 256), 256) for v in p) for p in (p0, p1)]
    a, b = ((x - EPS, y - EPS * EPS) for x, y in snap)
    a, b = tuple(a), tuple(b)
    out = np.zeros((height, width), bool)
    x_lo, x_hi = sorted((a[0], b[0]))
    y_lo, y_hi = sorted((a[1], b[1]))
    for i in range(max(0, int(y_lo) - 1), min(height, int(y_hi) + 2)):
        for j in range(max(0, int(x_lo) - 1), min(width, int(x_hi) + 2)):
            centre = (Fraction(2 * j + 1, 2), Fraction(2 * i + 1, 2))
            if _meets_open_diamond(a, b, centre) and not _inside_open_diamond(b, centre):
                out[i, j] = True
    return out


def _random_point(rng, size):
    kind = rng.integers(4)
    if kind == 0:  # anywhere on the 1/256 grid
        return rng.integers(0, size * 256, 2) / 256
    if kind == 1:  # a pixel centre
        return rng.integers(0, size, 2) + 0.5
    if kind == 2:  # a diamond corner (half-pixel on one axis)
        return rng.integers(0, 2 * size, 2) / 2
    return rng.integers(0, 4 * size, 2) / 4  # quarter pixels: boundary points


@pytest.mark.parametrize("seed", range(4))
def test_diamond_rule_matches_exact_reference(seed):
    rng = np.random.default_rng(seed)
    for _ in range(60):
        p0, p1 = _random_point(rng, 12), _random_point(rng, 12)
        got = tr.rasterize_line(p0, p1, 12, 12).coverage
        want = reference_line(p0, p1, 12, 12)
        assert (got == want).all(), (p0.tolist(), p1.tolist(), np.argwhere(got != want))


@pytest.mark.parametrize(
    ("p0", "p1", "lit", "unlit"),
    [
        # x-major, dy/dx > 0, line through (1.5, 1.0): the lower pixel (row 1)
        ((0.5, 0.5), (4.5, 2.5), (1, 1), (0, 1)),
        # x-major, dy/dx < 0, through (1.5, 2.0): the upper pixel (row 1, not row 2)
        ((0.5, 2.5), (4.5, 0.5), (1, 1), (2, 1)),
        # horizontal on the boundary y = 1.0: the upper row
        ((0.25, 1.0), (4.25, 1.0), (0, 2), (1, 2)),
        # y-major through (1.0, 1.5): the left pixel (col 0)
        ((0.5, 0.5), (1.5, 2.5), (1, 0), (1, 1)),
        # vertical on the boundary x = 1.0: the left column
        ((1.0, 0.25), (1.0, 4.25), (2, 0), (2, 1)),
    ],
)
def test_half_pixel_ties_follow_gl_perturbation(p0, p1, lit, unlit):
    cov = tr.rasterize_line(p0, p1, 6, 6).coverage
    assert cov[lit] and not cov[unlit]
    assert (cov == reference_line(p0, p1, 6, 6)).all()


def test_horizontal_vertical_45_degrees():
    cov = tr.rasterize_line((0.5, 2.5), (6.5, 2.5), 8, 5).coverage
    assert np.argwhere(cov).tolist() == [[2, j] for j in range(6)]
    cov = tr.rasterize_line((3.5, 0.5), (3.5, 4.5), 8, 5).coverage
    assert np.argwhere(cov).tolist() == [[i, 3] for i in range(4)]
    cov = tr.rasterize_line((0.5, 0.5), (4.5, 4.5), 5, 5).coverage
    assert np.argwhere(cov).tolist() == [[k, k] for k in range(4)]


def test_zero_length_lights_nothing():
    for rule in ("diamond", "bresenham", "dda"):
        assert not tr.rasterize_line((2.5, 2.5), (2.5, 2.5), 5, 5, rule=rule).coverage.any()
    assert not tr.rasterize_line((2.5, 2.5), (2.5, 2.5), 5, 5, line_width=3).coverage.any()


def test_closed_polyline_lights_each_vertex_once():
    pts = [(1.5, 1.5), (9.5, 2.5), (8.5, 8.5), (2.5, 7.5)]
    counts = np.zeros((10, 11), int)
    for a, b in zip(pts, pts[1:] + pts[:1]):
        counts += tr.rasterize_line(a, b, 11, 10).coverage
    for x, y in pts:
        assert counts[int(y), int(x)] == 1
    assert counts.max() == 1


def test_sharp_turn_outside_every_diamond_can_light_a_pixel_twice():
    """GL's rule is per segment: a vertex outside every diamond (a corner of four) with a
    sharp turn lets both segments light the pixel before the corner."""
    a, v, b = (0.5, 0.5), (4.0, 2.0), (0.5, 1.5)
    counts = sum(tr.rasterize_line(p, q, 6, 4).coverage.astype(int) for p, q in ((a, v), (v, b)))
    assert counts.max() == 2


def test_slopes_near_one():
    for slope in (1 - 1e-12, 1 + 1e-12, 1.0):
        p1 = (40.5, 0.5 + 40 * slope)
        got = tr.rasterize_line((0.5, 0.5), p1, 42, 42).coverage
        assert (got == reference_line((0.5, 0.5), p1, 42, 42)).all()


def test_very_long_line_is_exact_and_dda_drifts():
    n = 2**20
    p0, p1 = (0.5, 0.25), (n - 0.5, 3.25 + 1 / 256)
    exact = tr.rasterize_line(p0, p1, n, 4).coverage
    assert exact.sum(axis=0).tolist() == [1] * (n - 1) + [0]  # one pixel per column
    # the exact rule: the row is the one whose diamond the line exits at each column centre
    dda = tr.rasterize_line(p0, p1, n, 4, rule="dda").coverage
    assert (dda != exact).any(), "float32 stepping over 2**20 columns should drift"


def bresenham_loop(x0, y0, x1, y1):
    """The classic loop (first octant), written out: every pixel except the last."""
    dx, dy = x1 - x0, y1 - y0
    d, y, out = 2 * dy - dx, y0, []
    for x in range(x0, x1):
        out.append((y, x))
        if d > 0:
            y += 1
            d -= 2 * dx
        d += 2 * dy
    return out


def test_bresenham_is_the_classic_loop():
    rng = np.random.default_rng(3)
    for _ in range(40):
        x0, y0 = rng.integers(0, 5, 2)
        dx = rng.integers(1, 20)
        dy = rng.integers(0, dx + 1)
        x1, y1 = x0 + dx, y0 + dy
        fill = tr.rasterize_line((x0 + 0.5, y0 + 0.5), (x1 + 0.5, y1 + 0.5), 30, 30,
                                 rule="bresenham")  # fmt: skip
        assert sorted(map(tuple, np.argwhere(fill.coverage).tolist())) == sorted(
            bresenham_loop(int(x0), int(y0), int(x1), int(y1))
        )


def test_bresenham_and_diamond_differ_at_midpoint_ties():
    diamond = tr.rasterize_line((0.5, 0.5), (4.5, 2.5), 5, 3).coverage
    bres = tr.rasterize_line((0.5, 0.5), (4.5, 2.5), 5, 3, rule="bresenham").coverage
    assert diamond[1, 1] and bres[0, 1]


def test_wide_line_is_two_triangles_under_top_left_rule():
    p0, p1 = (1.3, 1.7), (12.2, 6.9)
    fill = tr.rasterize_line(p0, p1, 14, 10, line_width=3, trace=True)
    halves = fill.trace.wide
    assert not (halves[0] & halves[1]).any()
    assert ((halves[0] | halves[1]) == fill.coverage).all()
    tris = wide_line_triangles(p0, p1, 3)
    for tri, half in zip(tris, halves):
        assert (tr.rasterize(tr.Triangle(tri), 14, 10).coverage == half).all()
    assert fill.coverage.sum() > 2 * tr.rasterize_line(p0, p1, 14, 10).coverage.sum()


def test_attributes_perspective_correct_along_the_line():
    fill = tr.rasterize_line((0.5, 0.5), (8.5, 0.5), 10, 2, attrs={"u": [0.0, 1.0]}, w=[1, 4],
                             z=[0.2, 0.6])  # fmt: skip
    t = np.arange(8) / 8
    want = (t / 4) / ((1 - t) + t / 4)
    np.testing.assert_allclose(fill.attrs["u"][0, :8], want, rtol=1e-15)
    np.testing.assert_allclose(fill.depth[0, :8], 0.2 + 0.4 * t, rtol=1e-15)
    assert np.isnan(fill.attrs["u"][1]).all() and np.isnan(fill.attrs["u"][0, 8:]).all()
    affine = tr.rasterize_line((0.5, 0.5), (8.5, 0.5), 10, 2, attrs={"u": [0.0, 1.0]},
                               w=[1, 4], interpolation="affine")  # fmt: skip
    np.testing.assert_allclose(affine.attrs["u"][0, :8], t)


def test_attributes_stay_within_end_values():
    fill = tr.rasterize_line((0.2, 0.9), (7.7, 5.1), 9, 7, attrs={"c": [[0, 1], [1, -1]]},
                             w=[0.5, 9])  # fmt: skip
    c = fill.attrs["c"][fill.coverage]
    assert c.shape[1] == 2 and (c[:, 0] >= 0).all() and (c[:, 0] <= 1).all()


@pytest.mark.parametrize("rule", ["diamond", "bresenham", "dda"])
def test_trace_steps_and_captions(rule):
    fill = tr.rasterize_line((0.7, 1.2), (9.3, 5.6), 11, 7, rule=rule, trace=True)
    trace = fill.trace
    assert (trace.coverage_at(-1) == fill.coverage).all()
    assert not trace.coverage_at(1).any()
    assert trace.step(0).kind == "snap" and trace.step(1).kind == "axis"
    assert trace.step(2).kind == "column"
    total = np.zeros_like(fill.coverage)
    for k in range(len(trace)):
        assert isinstance(trace.caption(k), str) and trace.caption(k)
        assert not (total & trace.lit_at(k)).any()  # each pixel lit by one step only
        total |= trace.lit_at(k)
    assert (total == fill.coverage).all()
    if rule == "bresenham":
        assert "error term" in trace.caption(2)


def test_a_tie_is_only_marked_where_gl_perturbation_decides():
    """Review r63: a line through a diamond's corner and on into it entered both slabs at the
    same t, and that comparison (which bound to pick: the same t either way) was marked a tie:
    a horizontal line along a row of centres marked every pixel, and lesson 12a's task 2 (p1
    dragged to (9.5, 4.5)) two pixels the line crosses inside. Ties are now only where a
    comparison with GL's ε decides: the slope-½ line through the odd columns' pixel corners."""
    from teachraster.core.line_rules import diamond
    from teachraster.core.snapping import units_per_pixel

    unit = units_per_pixel(8)

    def ties(p0, p1):
        a, b = (tuple(int(round(v * unit)) for v in p) for p in (p0, p1))
        s = diamond(a, b, unit, 12, 10)
        return {(int(r), int(c)) for r, c, t in zip(s.rows, s.cols, s.tie, strict=True) if t}

    assert ties((0.5, 2.5), (10.5, 2.5)) == set()
    assert ties((0.5, 0.5), (9.5, 4.5)) == set()
    assert ties((0.5, 0.5), (4.5, 2.5)) == {(0, 1), (1, 1), (1, 3), (2, 3)}
    # review r71: an end point on a diamond's edge line extended tied lo with 1 (or hi with 0)
    # on diamonds the line never comes near, (1, 1), (2, 2), (1, 8), (2, 7) here; a tie only
    # counts where the other comparisons hold. The real ones stay: p0 on (0, 0)'s corner
    # (lit by -ε), p1 on (0, 8)'s corner (ends in it)
    assert ties((1.0, 0.5), (9, 0.5)) == {(0, 0), (0, 8)}
    # a line along the row boundary y = 1: rows 0 and 1 tie (ε lifts it into row 0), no more
    assert ties((0.5, 1.0), (8.5, 1.0)) == {(r, c) for r in (0, 1) for c in range(9)}
    # lesson 12a cell 6's line: its 4 won and 4 lost ties, as before
    assert ties((0.5, 0.5), (8.5, 4.5)) == {
        (1, 1), (2, 3), (3, 5), (4, 7), (0, 1), (1, 3), (2, 5), (3, 7)
    }  # fmt: skip


def test_y_major_trace_walks_rows():
    trace = tr.rasterize_line((1.5, 0.5), (3.5, 9.5), 6, 11, trace=True).trace
    assert trace.step(2).kind == "row" and trace.step(2).row is not None


def test_trace_is_off_by_default_and_never_changes_pixels():
    a = tr.rasterize_line((0.7, 1.2), (9.3, 5.6), 11, 7)
    b = tr.rasterize_line((0.7, 1.2), (9.3, 5.6), 11, 7, trace=True)
    assert a.trace is None and (a.coverage == b.coverage).all()


def test_bad_input_names_the_argument():
    with pytest.raises(ValueError, match="rule"):
        tr.rasterize_line((0, 0), (1, 1), 4, 4, rule="wu")
    with pytest.raises(ValueError, match="line_width"):
        tr.rasterize_line((0, 0), (1, 1), 4, 4, line_width=0.5)
    with pytest.raises(ValueError, match="line_width"):
        tr.rasterize_line((0, 0), (1, 1), 4, 4, line_width=2, rule="dda")
    with pytest.raises(ValueError, match="p1"):
        tr.rasterize_line((0, 0), (np.inf, 1), 4, 4)
    with pytest.raises(ValueError, match="p0"):
        tr.rasterize_line((3e6, 0), (1, 1), 4, 4)
    with pytest.raises(TypeError, match="width"):
        tr.rasterize_line((0, 0), (1, 1), 4.5, 4)
    with pytest.raises(ValueError, match="w"):
        tr.rasterize_line((0, 0), (1, 1), 4, 4, w=[1, 0])
    with pytest.raises(ValueError, match="attrs"):
        tr.rasterize_line((0, 0), (1, 1), 4, 4, attrs={"u": [1, 2, 3]})
    with pytest.raises(TypeError, match="trace"):
        tr.rasterize_line((0, 0), (1, 1), 4, 4, trace="yes")


# -- the line hard cases -------------------------------------------------------------------------
from teachraster.study import hardcases as hc  # noqa: E402


@pytest.mark.parametrize("name", hc.list_line_cases())
def test_line_case_meets_expectation(name):
    case = hc.get_line_case(name)
    result = case.run()
    case.check(result)
    assert case.why and case.expect and "\n" not in case.why + case.expect


@pytest.mark.parametrize("name", [n for n in hc.list_line_cases() if n != "line_very_long"])
def test_line_case_matches_exact_reference(name):
    case = hc.get_line_case(name)
    width, height = case.size
    for (p0, p1), fill in zip(case.segments, case.run().fills):
        assert (fill.coverage == reference_line(p0, p1, width, height)).all()


def test_line_case_registry():
    assert "closed_polyline" in hc.LINE_CASES
    with pytest.raises(ValueError, match="unknown line case"):
        hc.get_line_case("nope")
