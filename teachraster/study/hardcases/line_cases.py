"""Line cases: the inputs that make the diamond-exit rule earn its keep.

Kept in their own registry, :data:`LINE_CASES`, beside the triangle catalogue: a line case
runs :func:`teachraster.rasterize_line` on one or more segments (a polyline's segments in
order) and checks the summed coverage ``counts`` against what the GL rule must give.

>>> case = get_line_case("closed_polyline")
>>> result = case.run()
>>> case.check(result)
>>> int(result.counts.max())          # each shared vertex lit once
1
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from ...core.fill import Fill
from ...core.lines import rasterize_line


@dataclass(frozen=True)
class LineResult:
    """One fill per segment and how many segments lit each pixel."""

    fills: tuple[Fill, ...]
    counts: np.ndarray


@dataclass(frozen=True, eq=False)
class LineCase:
    """A named line case: ``segments`` (n, 2, 2) window px, ``size`` (width, height)."""

    name: str
    why: str
    expect: str
    segments: np.ndarray
    size: tuple[int, int]
    checker: Callable[[LineResult], None] = field(repr=False)
    rule: str = "diamond"

    def run(self, rule: str | None = None, trace: bool = False) -> LineResult:
        """Rasterise every segment (``rule`` default the case's) and count the hits; with
        ``trace`` each fill keeps its steps (for the player)."""
        width, height = self.size
        fills = tuple(
            rasterize_line(p0, p1, width, height, rule=rule or self.rule, trace=trace)
            for p0, p1 in self.segments
        )
        counts = sum((f.coverage.astype(np.int64) for f in fills), np.zeros((height, width), int))
        return LineResult(fills, counts)

    def check(self, result: LineResult) -> None:
        """Raise ``AssertionError`` unless ``result`` meets ``expect``."""
        self.checker(result)


LINE_CASES: dict[str, LineCase] = {}


def _add(name, why, expect, segments, size, checker) -> None:
    segs = np.asarray(segments, dtype=np.float64)
    segs.flags.writeable = False
    LINE_CASES[name] = LineCase(name, why, expect, segs, size, checker)


def get_line_case(name: str) -> LineCase:
    """The line case called ``name``; ``ValueError`` lists the names when there is none."""
    if name not in LINE_CASES:
        raise ValueError(f"unknown line case {name!r}; choose from {', '.join(LINE_CASES)}")
    return LINE_CASES[name]


def list_line_cases() -> list[str]:
    """Names of the line cases, in catalogue order."""
    return list(LINE_CASES)


def _pixels(result) -> list[tuple[int, int]]:
    return [tuple(map(int, rc)) for rc in np.argwhere(result.counts)]


def _expect_pixels(pixels):
    def check(result):
        got = _pixels(result)
        assert got == sorted(pixels), f"lit {got}, expected {sorted(pixels)}"

    return check


def _polyline(points, closed):
    pts = list(points) + ([points[0]] if closed else [])
    return [(a, b) for a, b in zip(pts[:-1], pts[1:])]


def _each_vertex_once(points):
    def check(result):
        for x, y in points:
            n = result.counts[int(y), int(x)]
            assert n == 1, f"vertex ({x}, {y}) lit {n} times"
        assert result.counts.max() == 1, "a pixel lit twice"

    return check


def _lit_twice_before_the_corner(result):
    assert (result.counts == 2).sum() >= 1, "the sharp turn should light a pixel twice"


def _one_per_column(result):
    cols = result.counts.sum(axis=0)
    assert (cols[:-1] == 1).all() and cols[-1] == 0, "one pixel per column, none at the end"


def _matches_exact_45(result):
    lit = _pixels(result)
    assert lit == [(k, k) for k in range(len(lit))], lit


_add(
    "line_horizontal",
    "a horizontal line through pixel centres: one row, the end pixel left out",
    "row 2, columns 1..6 lit once each; column 7 (p1's diamond) dark",
    [((1.5, 2.5), (7.5, 2.5))],
    (9, 5),
    _expect_pixels([(2, j) for j in range(1, 7)]),
)
_add(
    "line_vertical",
    "a vertical line exactly on the boundary x = 3 between two columns",
    "column 2 (the left one: GL's ε moves the line left), rows 0..3",
    [((3.0, 0.25), (3.0, 4.25))],
    (6, 6),
    _expect_pixels([(i, 2) for i in range(4)]),
)
_add(
    "line_45_degrees",
    "a 45° line through pixel centres: every diamond corner is a tie",
    "the diagonal pixels (k, k), k = 0..6, each once",
    [((0.5, 0.5), (7.5, 7.5))],
    (8, 8),
    _matches_exact_45,
)
_add(
    "line_endpoints_on_diamond_corners",
    "end points exactly on diamond corners (half pixels)",
    "GL's perturbation decides: the start pixel (row 0, col 0) lit, the last one not",
    [((0.5, 0.0), (6.5, 3.0))],
    (8, 4),
    _expect_pixels([(0, 0), (0, 1), (1, 2), (1, 3), (2, 4), (2, 5)]),
)
_add(
    "line_zero_length",
    "a zero-length line: its start's diamond is its end's",
    "nothing lit (GL: the end point's diamond is never exited)",
    [((2.5, 2.5), (2.5, 2.5))],
    (5, 5),
    _expect_pixels([]),
)
_add(
    "line_very_long",
    "a line 2**20 px long, slope 3/2**20: float stepping drifts, exact does not",
    "one pixel per column, none at the end; DDA differs (lesson 12a)",
    [((0.5, 0.25), (2**20 - 0.5, 3.25 + 1 / 256))],
    (2**20, 4),
    _one_per_column,
)
_add(
    "line_slope_one_plus",
    "slope 1 + 1e-12: snapping makes it exactly 45°",
    "the same pixels as the 45° line",
    [((0.5, 0.5), (40.5, 40.5 + 40e-12))],
    (42, 42),
    _matches_exact_45,
)
_add("line_slope_one_minus", "slope 1 - 1e-12: snapping makes it exactly 45°",
     "the same pixels as the 45° line", [((0.5, 0.5), (40.5, 40.5 - 40e-12))], (42, 42),
     _matches_exact_45)  # fmt: skip
_CLOSED = [(1.5, 1.5), (9.5, 2.5), (8.5, 8.5), (2.5, 7.5)]
_add(
    "closed_polyline",
    "a closed polyline: every vertex is the end of one segment, start of next",
    "each vertex pixel lit exactly once, no pixel twice",
    _polyline(_CLOSED, True),
    (11, 10),
    _each_vertex_once(_CLOSED),
)
_add("sharp_turn_off_diamond", "a sharp turn at a vertex on a diamond corner (outside all diamonds)",
     "the pixel before the corner is lit by both segments (GL and llvmpipe alike)",
     _polyline([(0.5, 0.5), (4.0, 2.0), (0.5, 1.5)], False), (6, 4),
     _lit_twice_before_the_corner)  # fmt: skip
