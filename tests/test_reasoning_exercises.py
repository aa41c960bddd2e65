"""Issue 30's exercises: correct solutions written differently pass, each typical mistake is
named right in the first explanation (its kind and its words), and the broken frames' hints
are true and never give the answer away."""

from __future__ import annotations

import math

import numpy as np
import pytest
import reasoning_solutions as sol

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import broken_frames as bf
from teachraster.study.hardcases import naive_coverage


def _passes(name, fn):
    report = ex.check(name, fn)
    assert report.passed, str(report)


def _named(name, fn, kind, words):
    report = ex.check(name, fn)
    assert not report.passed
    first = report.failures[0]
    assert first.kind == kind, (kind, str(report))
    assert words in first.explanation, (words, first.explanation)
    return report


# -- span ---------------------------------------------------------------------------------------
def _span_by_testing(xy, row):
    """Another correct span: test every candidate centre with exact fractions."""
    from fractions import Fraction

    v = [(Fraction(float(x)), Fraction(float(y))) for x, y in xy]
    area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0])
    if area == 0:
        return (0, 0)
    if area < 0:
        v = [v[0], v[2], v[1]]
    y, cols = Fraction(2 * row + 1, 2), []
    lo = math.floor(min(float(x) for x, _ in xy)) - 1
    for col in range(lo, math.ceil(max(float(x) for x, _ in xy)) + 2):
        x, ok = Fraction(2 * col + 1, 2), True
        for (ax, ay), (bx, by) in zip(v, v[1:] + v[:1]):
            e = (bx - ax) * (y - ay) - (by - ay) * (x - ax)
            top_left = by < ay or (by == ay and bx > ax)
            ok &= e > 0 or (e == 0 and top_left)
        if ok:
            cols.append(col)
    return (cols[0], cols[-1] + 1) if cols else (5, 5)


def _span_variant(change):
    def span(xy, row):
        y = row + (0.0 if change == "top" else 0.5)
        xs = []
        for k in range(3):
            (ax, ay), (bx, by) = xy[k], xy[(k + 1) % 3]
            if ay != by and min(ay, by) <= y <= max(ay, by):
                xs.append(ax + (y - ay) * (bx - ax) / (by - ay))
        if not xs:
            return (0, 0)
        left, right = min(xs), max(xs)
        if change == "corners":
            return math.ceil(left), math.ceil(right)
        if change == "right":
            return math.ceil(left - 0.5), math.floor(right - 0.5) + 1
        return math.ceil(left - 0.5), math.ceil(right - 0.5)

    return span


# -- perspective_weights ---------------------------------------------------------------------


# -- depth_passes ----------------------------------------------------------------------------
def _depths(ties=False, mask=True, test_all=True, previous=False):
    def depth_passes(depths, writes):
        stored = last = math.inf
        out = []
        for d, w in zip(depths, writes):
            against = last if previous else stored
            ok = (d <= against) if ties else (d < against)
            ok = ok or (not test_all and not w)
            out.append(ok)
            if ok and (w or not mask):
                stored = d
            last = d
        return out

    return depth_passes


# -- safe_near -------------------------------------------------------------------------------


# -- robust_fill -----------------------------------------------------------------------------
def _fill(**kw):
    def fill(xy, width, height, origin=(0, 0)):
        v = np.asarray(xy, float) if kw.get("raw") else np.rint(np.asarray(xy, float) * 256) / 256
        return naive_coverage(v, width, height, origin=tuple(origin),
                              rule=kw.get("rule", "top_left"), dtype=kw.get("dtype", np.float64),
                              absolute=kw.get("absolute", False))  # fmt: skip

    return fill


# -- quad_derivatives ------------------------------------------------------------------------
def _quad(change):
    from teachraster import barycentric, perspective_weights

    def quad_derivatives(xy, w, f, row, col):
        def value(x, y):
            lam = barycentric(xy, [x, y])
            if change == "affine":
                return float(lam @ f)
            return float(perspective_weights(lam[None], w, extrapolate=change != "clamp")[0] @ f)

        r0, c0 = (row, col) if change == "unaligned" else (row - row % 2, col - col % 2)
        ul = value(c0 + 0.5, r0 + 0.5)
        dx, dy = value(c0 + 1.5, r0 + 0.5) - ul, value(c0 + 0.5, r0 + 1.5) - ul
        return (dx, -dy) if change == "up" else (dx, dy)

    return quad_derivatives


# -- hiz_rejects -----------------------------------------------------------------------------
def _hiz(change):
    def hiz_rejects(xyz, row0, col0, size, buffer):
        xyz = np.asarray(xyz, float)
        if change == "vertex":
            return bool(xyz[:, 2].min() >= buffer.max())
        rows, cols = np.mgrid[row0 : row0 + size, col0 : col0 + size] + 0.5
        (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = xyz
        area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
        lam2 = ((x3 - x1) * (rows - y1) - (y3 - y1) * (cols - x1)) / -area
        lam3 = ((x2 - x1) * (rows - y1) - (y2 - y1) * (cols - x1)) / area
        plane = z1 + lam2 * (z2 - z1) + lam3 * (z3 - z1)  # every centre: brute force
        nearest = plane.min() if change == "no clamp" else max(plane.min(), xyz[:, 2].min())
        if change == "strict":
            return bool(nearest > buffer.max())
        if change == "tile min":
            return bool(nearest >= buffer.min())
        return bool(nearest >= buffer.max())

    return hiz_rejects


# -- front_to_back ---------------------------------------------------------------------------
def _layers(change):
    def front_to_back(layers):
        acc = np.zeros(4)
        for c in np.asarray(layers, float).reshape(-1, 4):
            t = 1 - acc[3]
            if change == "reversed":
                acc = c + acc * (1 - c[3])
            elif change == "sum":
                acc = acc + c
            elif change == "double":
                acc = np.r_[acc[:3] + t * c[3] * c[:3], acc[3] + t * c[3]]
            else:
                acc = acc + t * c
        return acc

    return front_to_back


def step(bits):
    return 1 / (2**bits - 1)


def solve(s, z, gap, far):
    """The near plane where step (f - n) z² / (f n) = gap."""
    return s * far * z * z / (gap * far + s * z * z)


# -- the tables: correct solutions written differently, typical mistakes --------------------
CORRECT = [
    ("span", sol.span),
    ("span", _span_by_testing),
    ("perspective_weights", sol.perspective_weights),
    ("perspective_weights", lambda lam, w: (q := lam * (w[0] / w)) / q.sum()),
    ("depth_passes", sol.depth_passes),
    ("depth_passes", lambda d, w: np.array(_depths()(d, w), dtype=int)),
    ("safe_near", sol.safe_near),
    ("safe_near", lambda z, gap, far, bits: 1 / (gap * (2**bits - 1) / z**2 + 1 / far)),
    ("robust_fill", sol.robust_fill),
    ("quad_derivatives", sol.quad_derivatives),
    ("quad_derivatives", _quad(None)),
    ("hiz_rejects", sol.hiz_rejects),
    ("hiz_rejects", _hiz(None)),
    ("front_to_back", sol.front_to_back),
    ("front_to_back", _layers(None)),
]

MISTAKES = [
    ("span", _span_variant("corners"), "corners", "x = col"),
    ("span", _span_variant("right"), "right inclusive", "right edge"),
    ("span", _span_variant("top"), "row top", "y = row"),
    ("perspective_weights", lambda lam, w: lam, "affine", "affine"),
    ("perspective_weights", lambda lam, w: lam * w / (lam @ w), "times w", "multiplied"),
    ("perspective_weights", lambda lam, w: lam / w, "unnormalised", "sum to 1"),
    ("depth_passes", _depths(ties=True), "ties", "use <, not <="),
    ("depth_passes", _depths(mask=False), "glass writes", "leaves the buffer"),
    ("depth_passes", _depths(test_all=False), "glass untested", "still tested"),
    ("depth_passes", _depths(previous=True), "previous", "just before"),
    ("depth_passes", lambda d, w: [True] * len(d), "all pass", "every fragment pass, always"),
    ("depth_passes", lambda d, w: [False] * len(d), "none pass", "no fragment pass, ever"),
    ("safe_near", lambda z, g, f, b: solve(1 / 2**b, z, g, f), "2^bits", "2^bits − 1"),
    ("safe_near", lambda z, g, f, b: solve(2 * step(b), z, g, f), "ndc", "NDC"),
    ("safe_near", lambda z, g, f, b: step(b) * z * z / g, "infinite far", "(f − n)/f"),
    ("robust_fill", _fill(raw=True), "no snapping", "snap them"),
    ("robust_fill", _fill(rule="inclusive"), "E >= 0", "covered twice"),
    ("quad_derivatives", _quad("unaligned"), "unaligned", "even rows"),
    ("quad_derivatives", _quad("affine"), "affine", "perspective-correct"),
    ("quad_derivatives", _quad("up"), "y up", "wrong sign"),
    ("hiz_rejects", _hiz("vertex"), "vertex", "nearest vertex"),
    ("hiz_rejects", _hiz("strict"), "strict", "use ≥"),
    ("hiz_rejects", _hiz("tile min"), "tile min", "farthest depth bounds"),
    ("front_to_back", _layers("reversed"), "reversed", "nearest"),
    ("front_to_back", _layers("sum"), "no transmittance", "transmittance"),
    ("front_to_back", _layers("double"), "double premultiplication", "premultiplied already"),
]


@pytest.mark.parametrize("name, fn", CORRECT, ids=[f"{n}-{k}" for k, (n, _) in enumerate(CORRECT)])
def test_correct_solutions_written_differently_pass(name, fn):
    _passes(name, fn)


@pytest.mark.parametrize("name, fn, kind, words", MISTAKES, ids=[m[2] for m in MISTAKES])
def test_each_typical_mistake_is_named_in_the_first_explanation(name, fn, kind, words):
    _named(name, fn, kind, words)


def test_perspective_weights_that_overflow_are_told_only_ratios_matter():
    report = ex.check("perspective_weights", lambda lam, w: (lam / w) / (lam / w).sum())
    assert {f.kind for f in report.failures} == {"overflow"}, str(report)
    assert "only the ratios" in report.failures[0].explanation


def test_safe_near_never_blames_float32_for_a_named_mistake():
    report = _named("safe_near", lambda z, g, f, b: solve(1 / 2**b, z, g, f), "2^bits", "step")
    assert all("float32's rounding" not in f.explanation for f in report.failures)


def test_robust_fill_names_the_absolute_form_and_fails_the_naive_fill_often():
    report = ex.check("robust_fill", _fill(rule="top_left", absolute=True, dtype=np.float32))
    assert "absolute form" in {f.kind for f in report.failures}, str(report)
    naive = ex.check("robust_fill", _fill(raw=True, rule="inclusive"))
    assert len(naive.failures) >= 5  # the naive fill fails the catalogue in many places


def test_quad_derivatives_clamped_at_helpers():
    report = ex.check("quad_derivatives", _quad("clamp"))
    assert report.failures and report.failures[0].kind == "clamped", str(report)


def test_hiz_rejects_without_the_vertex_clamp():
    report = ex.check("hiz_rejects", _hiz("no clamp"))
    assert "no clamp" in {f.kind for f in report.failures}, str(report)


# -- broken frames ---------------------------------------------------------------------------
ANSWERS = {1: "depth function", 2: "culled winding", 3: "z-fighting",
           4: "missing premultiplication", 5: "blend order", 6: "sliver"}  # fmt: skip


@pytest.mark.parametrize("number", list(ANSWERS))
def test_broken_frame_right_answer_passes_and_wrong_ones_get_true_hints(number):
    b = ex.broken_frame(number)
    assert b.cause == ANSWERS[number]
    row, col = (int(v) for v in np.argwhere(b.differs())[0])
    _passes(f"broken_frame_{number}", lambda: (ANSWERS[number].upper(), (row, col)))
    for cause in bf.CAUSES:
        if cause == b.cause:
            continue
        report = ex.check(f"broken_frame_{number}", lambda c=cause: (c, (row, col)))
        assert [f.kind for f in report.failures] == ["cause"], str(report)
        hint = report.failures[0].explanation
        assert b.cause not in hint and "does not explain" not in hint, (cause, hint)
    same = np.argwhere(~b.differs())[0]
    report = ex.check(f"broken_frame_{number}", lambda: (b.cause, tuple(same)))
    assert [f.kind for f in report.failures] == ["pixel"]


def test_broken_frames_one_and_two_look_alike_and_their_histories_differ():
    one, two = ex.broken_frame(1), ex.broken_frame(2)
    assert np.array_equal(bf._rgb(one.frame), bf._rgb(two.frame))
    assert not one.frame.trace.culled.any() and two.frame.trace.culled.any()


def test_broken_frame_answers_are_read_strictly():
    report = ex.check("broken_frame_1", lambda: ("the depth", (3, 4)))
    assert report.failures[0].kind == "type" and "not one of the causes" in str(report)
    report = ex.check("broken_frame_1", lambda: "depth function")
    assert report.failures[0].kind == "type"
    report = ex.check("broken_frame_1", lambda: ("depth function", (99, 4)))
    assert "outside" in str(report)


def test_the_frame_inspector_shows_the_broken_frames():
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector

    frames = {f"frame {b.number}": b.frame for b in bf.broken_frames()}
    w = FrameInspector(frames=frames, backend="image")
    try:
        assert list(w.scene.options) == list(frames) and w.frame is frames["frame 1"]
        assert w.samples.disabled and w.glass.disabled and not w.scene.disabled
        w.scene.value = "frame 2"
        w.click_at(30.5, 20.5)
        assert w.history.outcomes == frames["frame 2"].history(20, 30).outcomes
        assert "culled" in w.table.value
    finally:
        w.close()
    untraced = tr.render(tr.get_scene("cube").clip(4 / 3), 8, 6)
    with pytest.raises(ValueError, match="trace=True"):
        FrameInspector(frames={"a": untraced})
    with pytest.raises(TypeError, match="non-empty dict"):
        FrameInspector(frames={})


def test_broken_frame_numbers_are_checked():
    assert ex.broken_frame(np.int64(3)).number == 3
    with pytest.raises(TypeError, match="number must be an integer"):
        ex.broken_frame(True)
    with pytest.raises(ValueError, match="1 to 6"):
        ex.broken_frame(7)


WRONG = {name: fn for name, fn, _, _ in MISTAKES}
WRONG["broken_frame_1"] = lambda: ("z-fighting", (24, 28))
RIGHT = {name: fn for name, fn in CORRECT}
RIGHT["broken_frame_1"] = lambda: ("depth function", (24, 28))


@pytest.mark.parametrize("name", list(RIGHT))
def test_reports_draw_passing_failing_and_missing(name):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def stub(*args):
        raise NotImplementedError

    for fn in (RIGHT[name], WRONG[name], stub):
        report = ex.check(name, fn)
        if fn is stub:
            assert report.not_implemented and "not implemented yet" in str(report)
        fig, ax = plt.subplots(figsize=(3, 3))
        artists = report.plot(ax)
        assert artists and ax.get_title().startswith(name)
        fig.canvas.draw()
        plt.close(fig)
