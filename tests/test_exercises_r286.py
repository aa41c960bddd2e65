"""r286 (exercise 07, texture filtering): ±inf passed ``bilinear`` and ``trilinear``, and twelve
mistakes were told only the rule.

C1: ``tolerance.all_close`` scaled its tolerance by max(1, |got|, |expected|), inf where the
answer is, so inf ≤ 1e-6·inf held. Every exercise whose answer is numbers now refuses +inf,
-inf, inf in one entry and NaN, and says so ("your answer holds +inf at [2] …").
"""

from __future__ import annotations

import numpy as np
import pytest

from teachraster import exercises as ex
from teachraster.exercises import diagnosis, tolerance, tries
from teachraster.exercises.checks import exercise
from teachraster.exercises.diagnosis import Result


def test_all_close_refuses_inf_and_keeps_equal_non_finite():
    assert not tolerance.all_close([np.inf], [0.5], 1e-6)
    assert not tolerance.all_close([-np.inf, 0.5], [0.5, 0.5], 1e-6)
    assert not tolerance.all_close([np.inf], [-np.inf])
    assert not tolerance.all_close([np.nan], [0.5])
    assert tolerance.all_close([np.inf, np.nan, 1.0], [np.inf, np.nan, 1.0 + 1e-12])


def _numeric(expected) -> bool:
    """Is ``expected`` a float or an array of floats (not bools, ints, sets or words)?"""
    if isinstance(expected, (bool, np.bool_, int, np.integer)):
        return False
    try:
        a = np.asarray(expected)
    except Exception:  # noqa: BLE001
        return False
    return a.dtype.kind == "f" and a.size > 0 and bool(np.isfinite(a).all())


POISONS = {
    "+inf": lambda a: a + np.inf,
    "-inf": lambda a: a - np.inf,
    "inf in one entry": lambda a: np.where(
        np.arange(a.size).reshape(a.shape) == a.size - 1, np.inf, a
    ),
    "NaN": lambda a: a * np.nan,
}
WORDS = {
    "+inf": "holds +inf",
    "-inf": "holds -inf",
    "inf in one entry": "holds +inf",
    "NaN": "holds NaN",
}
NUMERIC = [n for n in ex.names() if not n.startswith("broken_frame")]


@pytest.mark.parametrize("poison", list(POISONS))
@pytest.mark.parametrize("name", NUMERIC)
def test_every_numeric_check_refuses_inf_and_nan_by_name(name, poison):
    spec = exercise(name)
    cases = spec.cases()
    k = next((k for k, (_, _, e) in enumerate(cases) if _numeric(e)), None)
    if k is None:
        pytest.skip(f"{name}: no case whose answer is floats")
    _, args, expected = cases[k]
    bad = POISONS[poison](np.array(expected, dtype=float))
    if poison == "inf in one entry" and np.ndim(expected):
        assert np.isfinite(bad).sum() == bad.size - 1
    got = spec.convert(bad) if np.ndim(expected) else float(bad)
    assert not spec.same(got, expected, args), (name, poison, got)
    results = [Result(j, a, e, got if j == k else e, j != k) for j, (_, a, e) in enumerate(cases)]
    kind, words = diagnosis.diagnose(spec, results)[k]
    if poison == "NaN" and kind != "nan":  # a mistake that gives NaN, named by its cause
        assert kind not in ("value", ""), (name, kind, words)
        return
    assert kind == "nan" and WORDS[poison] in words, (name, poison, kind, words)
    if np.ndim(expected) and poison == "inf in one entry":
        at = [int(i) for i in np.unravel_index(bad.size - 1, bad.shape)]
        assert f"at {at}" in words, words


# -- M3, M4, S12: the twelve half-named slips, each named by its cause on the first failure --
def _bil(texture, uv, wrap, rows=None):
    """A right bilinear (GL's LINEAR); ``rows`` "clamp": the rows clamped whatever the wrap."""
    t = np.asarray(texture, dtype=float)
    h, w = t.shape[:2]
    x, y = uv[0] * w - 0.5, uv[1] * h - 0.5
    x0, y0 = int(np.floor(x)), int(np.floor(y))
    fx, fy = x - x0, y - y0

    def ix(i, n, mode):
        return i % n if mode == "repeat" else min(max(i, 0), n - 1)

    c0, c1 = ix(x0, w, wrap), ix(x0 + 1, w, wrap)
    r0, r1 = ix(y0, h, rows or wrap), ix(y0 + 1, h, rows or wrap)
    top = t[r0, c0] * (1 - fx) + t[r0, c1] * fx
    return top * (1 - fy) + (t[r1, c0] * (1 - fx) + t[r1, c1] * fx) * fy


def _reversed_channels(texture, uv, wrap):
    v = _bil(texture, uv, wrap)
    return v[::-1] if np.ndim(v) else v


def _tri(pyramid, uv, lod, wrap="repeat", *, top=None, level=None, size0=False, tiled=False):
    """A right trilinear; ``top``: the highest λ kept (q − 1), ``level``: "round" picks one
    level with Python's round() of the weight; ``size0``: level 0's W, H for every level."""
    q = len(pyramid) - 1
    lam = min(max(lod, 0.0), q if top is None else top)
    lo = int(np.floor(lam))
    up, t = min(lo + 1, q), lam - lo

    def b(d):
        lv = np.asarray(pyramid[d], dtype=float)
        if not size0:
            return _bil(lv, uv, wrap)
        (h0, w0), (h, w) = np.shape(pyramid[0])[:2], lv.shape[:2]
        return _bil(lv, (uv[0] * w0 / w, uv[1] * h0 / h), "repeat" if tiled else wrap)

    if level == "round":
        return b(up if round(t) else lo)
    return (1 - t) * b(lo) + t * b(up)


def _weights(lam, w, *, times_w=False, clamp=False):
    lam = np.asarray(lam, dtype=float)
    if clamp:
        lam = np.clip(lam, 0.0, None)
    mu = lam * w if times_w else lam / w
    return mu / mu.sum()


def _value(xy, w, f, x, y, **kw):
    (x1, y1), (x2, y2), (x3, y3) = np.asarray(xy, dtype=float)
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    lam = np.array([(x2 - x) * (y3 - y) - (y2 - y) * (x3 - x),
                    (x3 - x) * (y1 - y) - (y3 - y) * (x1 - x),
                    (x1 - x) * (y2 - y) - (y1 - y) * (x2 - x)]) / area  # fmt: skip
    return float(_weights(lam, np.asarray(w, dtype=float), **kw) @ np.asarray(f, dtype=float))


def _quad(how):
    def quad_derivatives(xy, w, f, row, col):
        kw = {"times_w": how == "λ·w", "clamp": how == "clamped and y up"}

        def at(c, r):
            return _value(xy, w, f, c + 0.5, r + 0.5, **kw)

        if how == "exact":
            e = 1e-6
            x, y = col + 0.5, row + 0.5
            return ((_value(xy, w, f, x + e, y) - _value(xy, w, f, x - e, y)) / (2 * e),
                    (_value(xy, w, f, x, y + e) - _value(xy, w, f, x, y - e)) / (2 * e))  # fmt: skip
        odd = how == "odd quads"
        r0, c0 = row - (row + odd) % 2, col - (col + odd) % 2
        if how == "lower right":
            lr = at(c0 + 1, r0 + 1)
            return lr - at(c0, r0 + 1), lr - at(c0 + 1, r0)
        ul = at(c0, r0)
        sign = -1 if how == "clamped and y up" else 1
        return at(c0 + 1, r0) - ul, sign * (at(c0, r0 + 1) - ul)

    return quad_derivatives


def _mip_vectors(ddx, ddy, size):
    h, w = size
    return float(np.log2(np.hypot((ddx[0] + ddy[0]) * w, (ddx[1] + ddy[1]) * h)))


SLIPS = [
    ("mip_level", _mip_vectors, "ddx + ddy as vectors", "added ddx and ddy as vectors"),
    ("bilinear", _reversed_channels, "channel order", "another channel order (BGR"),
    ("bilinear", lambda t, uv, w: _bil(t, uv, w, rows="clamp"), "repeat on columns only",
     "tiled the columns (u) but clamped the rows (v)"),
    ("bilinear", lambda t, uv, w: np.asarray(t, float).mean(axis=(0, 1)), "texture's mean",
     "the mean of the whole texture"),
    ("trilinear", lambda p, uv, lod, wrap="repeat": _tri(p, uv, lod, wrap, level="round"),
     "round() for the nearest level", "rounds halves to even"),
    ("trilinear", lambda p, uv, lod, wrap="repeat": _tri(p, uv, lod, wrap, size0=True),
     "uv scaled per level", "every level with level 0's W and H"),
    # the reader's: level 0's size, and every level tiled ("%" for the indices)
    ("trilinear",
     lambda p, uv, lod, wrap="repeat": _tri(p, uv, lod, wrap, size0=True, tiled=True),
     "level 0's size for every level", "with level 0's W and H"),
    ("trilinear", lambda p, uv, lod, wrap="repeat": _tri(p, uv, lod, wrap, top=len(p) - 2),
     "λ clamped to [0, q − 1]", "you clamped λ to [0, q − 1]"),
    ("quad_derivatives", _quad("lower right"), "lower right", "the quad's lower-right lane"),
    ("quad_derivatives", _quad("exact"), "exact", "the exact derivative"),
    ("quad_derivatives", _quad("odd quads"), "odd quads", "start on odd rows and columns"),
    ("quad_derivatives", _quad("λ·w"), "λ·w", "weighted the barycentrics by w"),
    ("quad_derivatives", _quad("clamped and y up"), "clamped and y up",
     "clamps unless extrapolate=True); and your ddy has the wrong sign"),
]  # fmt: skip


@pytest.mark.parametrize("words", ["first try", "full words"])
@pytest.mark.parametrize(
    ("name", "fn", "kind", "phrase"), SLIPS, ids=[f"{s[0]} {s[2]}" for s in SLIPS]
)
def test_each_slip_is_named_by_its_cause_on_the_first_failure(name, fn, kind, phrase, words):
    tries.forget_hints(name)
    if words == "full words":
        tries.spend_hints([name])
    try:
        report = ex.check(name, fn)
    finally:
        tries.forget_hints(name)
    assert not report.passed, str(report)
    first = report.failures[0]
    assert first.kind == kind, (first.kind, first.explanation)
    if words == "full words":
        assert phrase in first.explanation, first.explanation
