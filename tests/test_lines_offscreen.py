"""Lines whose end points lie far off screen, tiny or huge: the rules against exact references.

Issue 28: a segment whose major-axis range misses the image lights nothing (it raised a raw
unpacking error), a subnormal w gives finite attributes by the triangles' 1/w rule, an
unsnapped line from beyond ~1e16 px is clipped (it came out empty) and a too-wide line
names ``line_width``, never the internal ``xy``.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from test_lines import bresenham_loop, reference_line

import teachraster as tr
from teachraster.core.lines import wide_line_triangles

SIZES = [(7, 5), (5, 7), (6, 6)]  # x-major and y-major images, both kinds of lines in each


def _far_point(size):
    """Coordinates up to two image sizes off screen on either side, on the 1/4 grid (ties)
    or the 1/256 grid (anywhere)."""
    lo, hi = -2 * size, 3 * size
    quarter = st.integers(4 * lo, 4 * hi).map(lambda v: v / 4)
    fine = st.integers(256 * lo, 256 * hi).map(lambda v: v / 256)
    return st.one_of(quarter, fine)


@st.composite
def far_segments(draw):
    """(p0, p1, width, height): random segments, or horizontal, vertical and diagonal ones,
    in either direction, with both ends (or one) far off screen."""
    width, height = draw(st.sampled_from(SIZES))
    x, y = _far_point(width), _far_point(height)
    p0 = (draw(x), draw(y))
    kind = draw(st.sampled_from(["any", "horizontal", "vertical", "diagonal", "antidiagonal"]))
    if kind == "any":
        p1 = (draw(x), draw(y))
    else:
        length = draw(st.integers(-4 * 3 * max(width, height), 4 * 3 * max(width, height))) / 4
        dx, dy = {"horizontal": (1, 0), "vertical": (0, 1), "diagonal": (1, 1),
                  "antidiagonal": (1, -1)}[kind]  # fmt: skip
        p1 = (p0[0] + dx * length, p0[1] + dy * length)
    return p0, p1, width, height


@settings(max_examples=80)
@given(far_segments(), st.booleans())
def test_far_off_screen_diamond_matches_exact_reference(segment, trace):
    p0, p1, width, height = segment
    fill = tr.rasterize_line(p0, p1, width, height, trace=trace)
    assert (fill.coverage == reference_line(p0, p1, width, height)).all()
    if trace:  # the trace of a line that walks nothing still reads
        assert (fill.trace.coverage_at(-1) == fill.coverage).all()
        assert all(fill.trace.caption(k) for k in range(len(fill.trace)))


def test_major_range_missing_the_image_is_empty():
    # x-major, columns 9.. only, in a 7-wide image: the case that raised "not enough values"
    for p0, p1 in [((33.06, 41.02), (12.4, 19.77)), ((-20.5, 2.5), (-9.5, 3.5)),
                   ((2.5, -30.5), (3.5, -12.5)), ((3.0, 20.0), (4.0, 9.0))]:  # fmt: skip
        for p, q in ((p0, p1), (p1, p0)):
            fill = tr.rasterize_line(p, q, 7, 5, trace=True)
            assert not fill.coverage.any()
            assert "nothing to walk" in fill.trace.caption(1)


def _bresenham_reference(p0, p1, width, height):
    """The classic loop in its first octant, mapped to the line's octant, clipped to the image."""
    x0, y0, x1, y1 = (int(np.floor(v)) for v in (*p0, *p1))
    dx, dy = x1 - x0, y1 - y0
    x_major = abs(p1[0] - p0[0]) >= abs(p1[1] - p0[1])
    dm, dn = (abs(dx), abs(dy)) if x_major else (abs(dy), abs(dx))
    out = np.zeros((height, width), bool)
    for minor, major in bresenham_loop(0, 0, dm, dn):
        ox, oy = (major, minor) if x_major else (minor, major)
        col, row = x0 + ox * (1 if dx >= 0 else -1), y0 + oy * (1 if dy >= 0 else -1)
        if 0 <= row < height and 0 <= col < width:
            out[row, col] = True
    return out


@settings(max_examples=60)
@given(far_segments())
def test_far_off_screen_bresenham_is_the_classic_loop_clipped(segment):
    p0, p1, width, height = segment
    p0, p1 = tuple(np.floor(p0) + 0.5), tuple(np.floor(p1) + 0.5)  # pixel centres: no ties
    got = tr.rasterize_line(p0, p1, width, height, rule="bresenham").coverage
    assert (got == _bresenham_reference(p0, p1, width, height)).all()


@settings(max_examples=60)
@given(far_segments())
def test_far_off_screen_dda_stays_on_the_line(segment):
    """Over a few steps float32 cannot drift: each lit pixel holds the line's exact minor
    coordinate at its centre, and every column (row) it walks inside the image is lit."""
    p0, p1, width, height = segment
    fill = tr.rasterize_line(p0, p1, width, height, rule="dda", trace=True)
    steps = fill.trace.steps
    d = np.subtract(p1, p0)
    if not steps.x_major:
        d = d[::-1]
    for row, col in np.argwhere(fill.coverage):
        major, minor = (col, row) if steps.x_major else (row, col)
        start = (p0[0], p0[1]) if steps.x_major else (p0[1], p0[0])
        exact = start[1] + (major + 0.5 - start[0]) * d[1] / d[0]
        assert minor - 1e-4 <= exact < minor + 1 + 1e-4
    assert fill.coverage.sum() == len(steps.rows)


@settings(max_examples=60)
@given(far_segments(), st.sampled_from([2.0, 3.5, 9.0]))
def test_far_off_screen_wide_line_is_its_two_triangles(segment, line_width):
    p0, p1, width, height = segment
    fill = tr.rasterize_line(p0, p1, width, height, line_width=line_width)
    want = np.zeros((height, width), bool)
    for tri in wide_line_triangles(p0, p1, line_width):
        want |= tr.rasterize(tr.Triangle(tri), width, height).coverage
    assert (fill.coverage == want).all()


# -- tiny w -----------------------------------------------------------------------------------
def _exact_perspective(t, f, w):
    """((1 - t) f0/w0 + t f1/w1) / ((1 - t)/w0 + t/w1) in Fractions, rounded once."""
    t = Fraction(float(t))
    w0, w1 = Fraction(float(w[0])), Fraction(float(w[1]))
    num = (1 - t) * Fraction(float(f[0])) / w0 + t * Fraction(float(f[1])) / w1
    return float(num / ((1 - t) / w0 + t / w1))


@pytest.mark.parametrize(
    "w", [(1e-310, 1.0), (1.0, 1e-310), (1e-310, 3e-320), (5e-324, 1e300), (1e-300, 1e300)]
)
def test_subnormal_w_gives_finite_attributes_by_the_triangle_rule(w):
    p0, p1 = (0.5, 0.5), (10.5, 3.5)
    fill = tr.rasterize_line(p0, p1, 12, 5, w=w, attrs={"c": [2.0, -1.0]}, z=[0.25, 0.75])
    lit = fill.coverage
    values = fill.attrs["c"][lit]
    assert np.isfinite(values).all() and (values <= 2.0).all() and (values >= -1.0).all()
    rows, cols = np.nonzero(lit)
    t = tr.core.lines.line_parameter(p0, p1, rows, cols)
    want = [_exact_perspective(tk, (2.0, -1.0), w) for tk in t]
    np.testing.assert_allclose(values, want, rtol=1e-14, atol=1e-15)
    np.testing.assert_allclose(fill.depth[lit], 0.25 + 0.5 * t, rtol=1e-15)


def test_line_and_triangle_share_the_perspective_rule():
    """A triangle with the same w at a vertex gives the same value along that edge."""
    w = (1e-310, 1.0)
    line = tr.rasterize_line((0.5, 0.5), (8.5, 0.5), 10, 3, w=w, attrs={"u": [0.0, 1.0]})
    tri = tr.rasterize(tr.Triangle([(0.5, 0.5), (8.5, 0.5), (0.5, 2.5)], w=[w[0], w[1], 1.0],
                                   attrs={"u": [0.0, 1.0, 0.0]}), 10, 3)  # fmt: skip
    both = line.coverage[0] & tri.coverage[0]
    assert both.sum() >= 7
    np.testing.assert_array_equal(line.attrs["u"][0, both], tri.attrs["u"][0, both])


# -- unsnapped ends far away ------------------------------------------------------------------
#: Far below any gap the exact decisions see for these ends (their denominators are small).
EPS = Fraction(1, 2**400)


def _reference_unsnapped(p0, p1, width, height, shift=(0, 0)):
    """The diamond-exit rule on the float end points as they are (no snap), in Fractions,
    the segment moved by ``shift``."""
    from test_lines import _inside_open_diamond, _meets_open_diamond

    sx, sy = Fraction(shift[0]), Fraction(shift[1])
    a = (Fraction(float(p0[0])) + sx - EPS, Fraction(float(p0[1])) + sy - EPS * EPS)
    b = (Fraction(float(p1[0])) + sx - EPS, Fraction(float(p1[1])) + sy - EPS * EPS)
    out = np.zeros((height, width), bool)
    for i in range(height):
        for j in range(width):
            centre = (Fraction(2 * j + 1, 2), Fraction(2 * i + 1, 2))
            out[i, j] = _meets_open_diamond(a, b, centre) and not _inside_open_diamond(b, centre)
    return out


#: Unsnapped lines are decided in doubles: a pixel the line passes within ~1e-16 px of a
#: diamond's corner may go either way. The comparison keeps to pixels whose answer stays
#: the same when the segment moves by this much in any diagonal direction.
NEAR = Fraction(1, 2**30)


@settings(max_examples=15)
@given(
    st.floats(1e16, 1e300),
    st.floats(0.1, 1e6),
    st.floats(0, 2 * np.pi),
    st.tuples(st.floats(0.0, 6.0), st.floats(0.0, 4.0)),
)
@example(far=1e16, near=1.0, angle=0.0, through=(2.0, 1.0))  # on the border of rows 0 and 1
def test_unsnapped_line_from_far_away_is_clipped_exactly(far, near, angle, through):
    """Ends beyond 1e16 px (where a double cannot hold half a pixel) still light the pixels
    the exact rule lights on those very floats: the line is clipped, not lost."""
    direction = np.array([np.cos(angle), np.sin(angle)])
    p0 = np.asarray(through) - far * direction
    p1 = np.asarray(through) + near * direction
    for a, b in ((p0, p1), (p1, p0)):
        got = tr.rasterize_line(a, b, 6, 4, subpixel_bits=None).coverage
        want = _reference_unsnapped(a, b, 6, 4)
        decided = np.ones_like(want)
        for shift in ((NEAR, NEAR), (NEAR, -NEAR), (-NEAR, NEAR), (-NEAR, -NEAR)):
            decided &= _reference_unsnapped(a, b, 6, 4, shift) == want
        assert (got == want)[decided].all()
        # the comparison is never vacuous: a line lying on a pixel border (y = 1.0 at angle 0)
        # leaves the two rows beside it undecided, and a 6x4 image still has 12 decided pixels
        assert decided.sum() >= 12


@pytest.mark.parametrize("far", [1e16, 1e17, 1e200, 1.7e308])
def test_unsnapped_axis_lines_from_far_away_light_their_row_and_column(far):
    row = tr.rasterize_line((-far, 2.5), (far, 2.5), 8, 6, subpixel_bits=None).coverage
    assert np.argwhere(row).tolist() == [[2, j] for j in range(8)]
    col = tr.rasterize_line((3.5, far), (3.5, -far), 8, 6, subpixel_bits=None).coverage
    assert np.argwhere(col).tolist() == [[i, 3] for i in range(6)]
    diag = tr.rasterize_line((-far, -far), (far, far), 6, 6, subpixel_bits=None).coverage
    assert (diag == tr.rasterize_line((-9, -9), (9, 9), 6, 6, subpixel_bits=None).coverage).all()
    wide = tr.rasterize_line((-far, 2.5), (far, 2.5), 8, 6, subpixel_bits=None, line_width=3)
    assert wide.coverage[1:4].all() and not wide.coverage[[0, 4, 5]].any()
    lit = tr.rasterize_line((-far, 2.5), (far, 2.5), 8, 6, subpixel_bits=None,
                            attrs={"u": [0.0, 1.0]}).attrs["u"][2]  # fmt: skip
    np.testing.assert_allclose(lit, 0.5, atol=1e-12)  # the middle of a huge segment


# -- errors name the argument ----------------------------------------------------------------
@pytest.mark.parametrize("bits", [8, 4, 0, None])
@pytest.mark.parametrize(
    ("p0", "p1", "line_width", "name"),
    [
        ((0.5, 0.5), (10.5, 3.5), 1e300, "line_width"),
        ((0.5, 0.5), (10.5, 3.5), 1.5e308, "line_width"),
        ((0.5, 0.5), (1e12, 3.5), 3, "p1"),
        ((-3e15, 0.5), (1.5, 3.5), 3, "p0"),
    ],
)
def test_huge_wide_line_names_its_argument(p0, p1, line_width, name, bits):
    if bits is None and name != "line_width":  # unsnapped ends are clipped instead
        fill = tr.rasterize_line(p0, p1, 12, 5, line_width=line_width, subpixel_bits=None)
        assert fill.coverage.any()
        return
    with pytest.raises(ValueError, match=f"^{name}") as info:
        tr.rasterize_line(p0, p1, 12, 5, line_width=line_width, subpixel_bits=bits)
    assert "xy" not in str(info.value)


@pytest.mark.filterwarnings("error::RuntimeWarning")  # no overflow on the way either
@settings(max_examples=60)
@given(
    st.floats(-1e30, 1e30), st.floats(-1e30, 1e30), st.floats(1.0, 1e30),
    st.sampled_from([8, 2, None]),
)  # fmt: skip
def test_any_line_lights_or_refuses_naming_an_argument(x, y, line_width, bits):
    try:
        tr.rasterize_line((x, y), (4.0, 3.0), 9, 7, line_width=line_width, subpixel_bits=bits)
    except ValueError as error:
        assert str(error).split(":")[0] in ("p0", "p1", "line_width")


@pytest.mark.filterwarnings("error::RuntimeWarning")
def test_an_unsnapped_triangle_far_left_of_the_image_fills_nothing_quietly():
    """What a wide line's rectangle hands the fill: bounds beyond int64 once in pixels."""
    tri = tr.Triangle([[-1e28, 0.0], [-1e28, 5.0], [-2e28, 3.0]])
    assert not tr.rasterize(tri, 8, 8, subpixel_bits=None).coverage.any()
