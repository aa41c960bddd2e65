"""Exercises of lesson 12: ``line_pixels`` (the diamond-exit rule), ``over`` and
``over_premultiplied`` (the blend equation), with explanations of the typical mistakes.

The expected answers come from the core: :func:`teachraster.rasterize_line` (exact, with GL's
tie perturbation) and :func:`teachraster.blend_equation` with the factor pairs of
``render(..., blend="over" | "premultiplied")``.
"""

from __future__ import annotations

import numpy as np

from ..core.blend_factors import BLEND_MODES, blend_equation
from ..core.lines import rasterize_line
from .answers import as_numbers, short
from .report import Report
from .running import WrongAnswerType
from .value_checks import ValueExercise, check_value_exercise

#: Lines live in a WINDOW × WINDOW image; end points on the 1/8 grid so ties happen.
WINDOW = 12
SEED = 20241126


# -- line_pixels ------------------------------------------------------------------------------
def line_cases() -> list[tuple[str, tuple, set]]:
    """(label, (p0, p1), expected set of (row, col)) for the catalogue and random lines."""
    named = [
        ("horizontal through centres", (1.5, 2.5), (8.5, 2.5)),
        ("vertical on a pixel boundary (x = 3)", (3.0, 0.25), (3.0, 7.25)),
        ("45° through centres", (0.5, 0.5), (7.5, 7.5)),
        ("x-major, a half-pixel tie (dy/dx > 0)", (0.5, 0.5), (8.5, 4.5)),
        ("x-major, a half-pixel tie (dy/dx < 0)", (0.5, 4.5), (8.5, 0.5)),
        ("y-major, a half-pixel tie", (0.5, 0.5), (4.5, 8.5)),
        ("start inside its diamond, off centre", (1.7, 1.6), (9.2, 4.1)),
        ("end on a diamond corner", (1.25, 1.25), (6.5, 4.0)),
        ("running left and up", (10.4, 9.3), (1.6, 2.2)),
        ("zero length", (4.5, 4.5), (4.5, 4.5)),
        ("shorter than a pixel", (2.2, 2.3), (2.9, 2.6)),
    ]
    rng = np.random.default_rng(SEED)
    for k in range(24):
        p0, p1 = (tuple(rng.integers(0, WINDOW * 8, 2) / 8) for _ in range(2))
        named.append((f"random line {k}", p0, p1))
    return [(label, (p0, p1), _expected_pixels(p0, p1)) for label, p0, p1 in named]


def _expected_pixels(p0, p1) -> set[tuple[int, int]]:
    cov = rasterize_line(p0, p1, WINDOW, WINDOW).coverage
    return {(int(r), int(c)) for r, c in np.argwhere(cov)}


def _pixel_set(value) -> set[tuple[int, int]]:
    """The student's pixels as a set of (row, col); read as strictly as every answer."""
    if isinstance(value, (set, frozenset)):
        value = sorted(value, key=repr)
    if isinstance(value, (list, tuple)) and len(value) == 0:
        return set()
    arr = as_numbers(value, (-1, 2), "a list of (row, col) pairs")
    if not np.isfinite(arr).all() or (arr != np.round(arr)).any():
        raise WrongAnswerType(f"returned {short(value)}: pixel indices are whole numbers")
    pairs = [(int(r), int(c)) for r, c in arr]
    if len(set(pairs)) != len(pairs):
        raise WrongAnswerType("returned a pixel twice: a line lights each pixel at most once")
    return set(pairs)


def _in_diamond(p, row, col) -> bool:
    return abs(p[0] - col - 0.5) + abs(p[1] - row - 0.5) <= 0.5


def explain_line(args, expected: set, got: set) -> str:
    """Why ``got`` is not the diamond rule's answer, about the first wrong pixel."""
    p0, p1 = args
    extra, missing = sorted(got - expected), sorted(expected - got)
    if extra:
        r, c = extra[0]
        if _in_diamond(p1, r, c):
            return (f"you lit (row {r}, col {c}), the pixel whose diamond p1 = {p1} lies in: the "
                    "segment ends there without exiting it, so GL leaves it to the next segment "
                    "(a polyline then lights each shared vertex once)")  # fmt: skip
        return (f"you lit (row {r}, col {c}): the segment {p0} → {p1} never exits its diamond "
                "|x - (col + ½)| + |y - (row + ½)| < ½ (a tie on its boundary is decided by "
                "moving the line by -(ε, ε²): inside only on the diamond's right half)")  # fmt: skip
    r, c = missing[0]
    if _in_diamond(p0, r, c):
        return (f"missing (row {r}, col {c}): p0 = {p0} lies in its diamond and the segment "
                "leaves it, so it is exited and lit, although p0 is not its centre")  # fmt: skip
    return (f"missing (row {r}, col {c}): the segment passes through its diamond and out again; "
            "at an exact half-pixel tie GL's perturbation (x, y) - (ε, ε²) picks the lower pixel "
            "for x-major lines with dy/dx > 0, the upper one for dy/dx < 0, the left one for "
            "y-major lines")  # fmt: skip


def check_line_pixels(fn) -> Report:
    """Run ``line_pixels(p0, p1)`` on every line case."""
    return check_value_exercise("line_pixels", fn, LINE_PIXELS)


def _draw_line(ax, case, got):
    return _line_drawing(case, got)(ax)


def _line_drawing(case, got):
    def draw(ax):
        from .drawing import STATE_COLOURS

        _, (p0, p1), expected = case
        state = np.zeros((WINDOW, WINDOW), int)
        for r, c in expected:
            state[r, c] = 1
        for r, c in (got or set()) ^ (expected if got is not None else set()):
            state[r, c] = 2 if (r, c) in expected else 3
        from matplotlib.colors import ListedColormap

        artists = [ax.imshow(state, cmap=ListedColormap(STATE_COLOURS), vmin=0, vmax=3,
                             extent=(0, WINDOW, WINDOW, 0), interpolation="nearest")]  # fmt: skip
        artists += ax.plot([p0[0], p1[0]], [p0[1], p1[1]], "k-o", ms=4)
        ax.set_aspect("equal")
        return artists

    return draw


# -- over and over_premultiplied ----------------------------------------------------------------
def blend_cases(mode: str) -> list[tuple[str, tuple, np.ndarray]]:
    """(label, (src, dst), expected) for ``mode`` "over" or "premultiplied"."""
    pairs = [
        ("opaque red over blue", [1, 0, 0, 1], [0, 0, 1, 1]),
        ("half red over blue", [1, 0, 0, 0.5], [0, 0, 1, 1]),
        ("half red over transparent black", [1, 0, 0, 0.5], [0, 0, 0, 0]),
        ("transparent over grey", [0.3, 0.6, 0.9, 0.0], [0.5, 0.5, 0.5, 1]),
        ("quarter green over half grey", [0, 1, 0, 0.25], [0.5, 0.5, 0.5, 0.5]),
    ]
    rng = np.random.default_rng(SEED + 1)
    for k in range(20):
        pairs.append((f"random colours {k}", *rng.uniform(0, 1, (2, 4)).round(3)))
    out = []
    for label, src, dst in pairs:
        src, dst = np.asarray(src, float), np.asarray(dst, float)
        if mode == "premultiplied":
            src = np.r_[src[:3] * src[3], src[3]]  # these cases hold premultiplied colours
            dst = np.r_[dst[:3] * dst[3], dst[3]]
        out.append((label, (src, dst), blend_equation(src, dst, *BLEND_MODES[mode])))
    return out


def _rgba(value) -> np.ndarray:
    return as_numbers(value, (4,), "an RGBA colour, shape (4,)")


def explain_blend(mode: str, args, expected, got) -> str:
    """Name the typical mistake behind a wrong blend, from the numbers."""
    src, dst = args
    a = src[3]
    dst_scaled = src * (a if mode == "over" else 1) + dst
    guesses = {
        "the destination alpha was used instead of the source alpha":
            src * dst[3] + dst * (1 - dst[3]),
        "the destination was not scaled by (1 - alpha)": dst_scaled,
    }  # fmt: skip
    if mode == "premultiplied":
        guesses["the colour was multiplied by alpha again (it is premultiplied already: the "
                "dark fringe)"] = np.r_[src[:3] * a, a] + dst * (1 - a)  # fmt: skip
    else:
        guesses["the source was not multiplied by its alpha (that is the premultiplied "
                "rule)"] = src + dst * (1 - a)  # fmt: skip
        guesses["alpha was composed as Porter-Duff's a + (1 - a)·b; GL's 'over' uses one "
                "factor pair, SRC_ALPHA, for all four channels (alpha a² + (1 - a)·b)"] = np.r_[
            src[:3] * a + dst[:3] * (1 - a), a + dst[3] * (1 - a)]  # fmt: skip
    for words, guess in guesses.items():
        if np.allclose(got, guess, atol=1e-9) and not np.allclose(guess, expected, atol=1e-9):
            return f"{words}: expected {np.round(expected, 4).tolist()}, got {np.round(got, 4).tolist()}"
    pair = " and ".join(BLEND_MODES[mode])
    return (f"expected src·{BLEND_MODES[mode][0]} + dst·{BLEND_MODES[mode][1]} "
            f"(glBlendFunc({pair})) = {np.round(expected, 4).tolist()}, "
            f"got {np.round(got, 4).tolist()}")  # fmt: skip


def _blend_exercise(mode: str) -> ValueExercise:
    return ValueExercise(
        lambda: blend_cases(mode),
        _rgba,
        lambda got, expected: bool(np.allclose(got, expected, rtol=1e-9, atol=1e-12)),
        lambda args, expected, got: explain_blend(mode, args, expected, got),
        lambda ax, case, got: _blend_drawing(case[2], got)(ax),
    )


def check_blend(name: str, mode: str, fn) -> Report:
    """Run ``fn(src, dst)`` on the blend cases of ``mode``."""
    return check_value_exercise(name, fn, _blend_exercise(mode))


def _blend_drawing(expected, got):
    def draw(ax):
        from .drawing import draw_values

        return draw_values(ax, ["R", "G", "B", "A"], expected, got)

    return draw


def check_over(fn) -> Report:
    return check_blend("over", "over", fn)


def check_over_premultiplied(fn) -> Report:
    return check_blend("over_premultiplied", "premultiplied", fn)


#: How ``line_pixels`` is checked: the pixels as a set, compared whole, explained by the rule.
LINE_PIXELS = ValueExercise(
    line_cases, _pixel_set, lambda got, expected: got == expected, explain_line, _draw_line
)

#: The three exercises, for the registry in :mod:`.checks`.
EXERCISES = {
    "line_pixels": check_line_pixels,
    "over": check_over,
    "over_premultiplied": check_over_premultiplied,
}
