"""The trace of one line: its steps, as plain arrays, with captions written on demand.

Steps: 0 ``snap`` (the end points on the sub-pixel grid), 1 ``axis`` (the major axis and the
range walked), then one ``column`` (x-major) or ``row`` (y-major) step per major-axis pixel
the rule visited, in the order it walked them (for Bresenham and DDA, from p0 towards p1).
Wide lines have two work steps, one per triangle of the rectangle. Presentation code asks
the trace (``step``, ``caption``, ``coverage_at``, ``lit_at``) rather than re-deriving it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .line_rules import ENDS_INSIDE, LIT, LineSteps, gl_decides_otherwise
from .trace import Step
from .validate import as_int

SETUP = ("snap", "axis")

_WHY = {
    "diamond": {
        LIT: "the segment meets its diamond and goes on out of it: lit",
        ENDS_INSIDE: "the segment ends inside its diamond: left to the next segment",
    },
    "bresenham": {LIT: "lit"},
    "dda": {LIT: "lit"},
}


def _at_centre_words(x_major: bool, major: int, value: float) -> str:
    """Where the diamond rule reads the line in a column (row): on its centre line
    x = j + ½ (y = i + ½), not at a pixel centre; the value there may be a row (column)
    boundary, the very tie being decided ("line at the centre: y = 1" read as the line
    passing through a pixel centre)."""
    where, axis, other = ("column", "x", "y") if x_major else ("row", "y", "x")
    return (f"at {axis} = {major + 0.5:g}, the {where}'s centre, the line is at "
            f"{other} = {value:.6g}")  # fmt: skip


@dataclass(frozen=True)
class LineTrace:
    """Every step of one line (see the module docstring).

    ``p0``, ``p1`` the snapped end points (px); ``rule`` as asked; ``size`` (width, height);
    ``steps`` the rule's :class:`~teachraster.core.line_rules.LineSteps` (None for a wide
    line); ``wide`` the coverage of each of the two triangles of a wide line, else None.
    """

    rule: str
    p0: tuple[float, float]
    p1: tuple[float, float]
    size: tuple[int, int]
    steps: LineSteps | None
    wide: tuple[np.ndarray, np.ndarray] | None = None

    @property
    def n_work(self) -> int:
        """Number of work steps (visited columns or rows; 2 for a wide line)."""
        return 2 if self.steps is None else len(self.steps.major)

    def __len__(self) -> int:
        return len(SETUP) + self.n_work

    def index(self, k: int) -> int:
        """Step ``k`` as a non-negative index (negative counts from the end)."""
        k = as_int("k", k)
        n = len(self)
        if not -n <= k < n:
            raise ValueError(f"k must be in [{-n}, {n}), got {k}")
        return k % n

    def step(self, k: int) -> Step:
        """Step ``k`` as a :class:`~teachraster.core.trace.Step` (kind, caption, pixel)."""
        k = self.index(k)
        if k < len(SETUP):
            return Step(index=k, kind=SETUP[k], caption=self.caption(k))
        work = k - len(SETUP)
        if self.steps is None:
            return Step(index=k, kind="triangle", caption=self.caption(k), work=work)
        major = int(self.steps.major[work])
        row, col = (None, major) if self.steps.x_major else (major, None)
        kind = "column" if self.steps.x_major else "row"
        return Step(index=k, kind=kind, caption=self.caption(k), row=row, col=col, work=work)

    def caption(self, k: int) -> str:
        """Step ``k`` in words."""
        k = self.index(k)
        if k == 0:
            return (f"snap: p0 = ({self.p0[0]:g}, {self.p0[1]:g}), "
                    f"p1 = ({self.p1[0]:g}, {self.p1[1]:g}) on the sub-pixel grid")  # fmt: skip
        if k == 1:
            return self._axis_caption()
        if self.steps is None:
            half = ("first", "second")[k - len(SETUP)]
            n = int(self.wide[k - len(SETUP)].sum())
            return f"wide line, {half} triangle of the rectangle: {n} centres (top-left rule)"
        return self._work_caption(k - len(SETUP))

    def _axis_caption(self) -> str:
        if self.steps is None:
            return "wide line: the rectangle around the segment, split into two triangles"
        axis = "x" if self.steps.x_major else "y"
        name = "columns" if self.steps.x_major else "rows"
        if len(self.steps.major) == 0:
            return f"{axis}-major, nothing to walk"
        lo, hi = int(self.steps.major.min()), int(self.steps.major.max())
        return f"{axis}-major: walk {name} {lo}..{hi}, one step each"

    def _work_caption(self, work: int) -> str:
        s = self.steps
        where = "column" if s.x_major else "row"
        head = f"{where} {int(s.major[work])}"
        value = float(s.value[work])
        if self.rule == "bresenham":
            # the loop stops before p1's pixel: after the last column there is no next one
            then = f"{'step' if value > 0 else 'stay'} next"
            if work == len(s.major) - 1:
                then = f"last {where}: p1's pixel is left to the next segment"
            head += f", error term D = {value:g} ({then})"
        elif self.rule == "dda":
            head += f", float32 sum: {'y' if s.x_major else 'x'} = {value:.6g}"
        else:
            head += ": " + _at_centre_words(s.x_major, int(s.major[work]), value)
        mine = (s.step == work) & (s.state != 0)
        parts = [
            f"pixel (row {r}, col {c}): {_WHY[self.rule][int(st)]}"
            for r, c, st in zip(s.rows[mine], s.cols[mine], s.state[mine], strict=True)
        ]
        if s.tie is not None and s.tie[mine].any():  # the segment touches a diamond's boundary
            parts.append(self._tie_words())
        return head + ("; " + "; ".join(parts) if parts else "; no pixel lit")

    def _tie_words(self) -> str:
        """Which rule decided a tie: the ``-(ε, ε²)`` shift with y down (Vulkan's), and what GL,
        shifting with y up, does there (review r160 12a-1: GL was named for both)."""
        words = ("a tie, decided by moving the end points by −(ε, ε²) with y down (Vulkan's "
                 "Bresenham rule)")  # fmt: skip
        if gl_decides_otherwise(self.p0, self.p1):
            return words + ("; GL moves them with y up and lights the pixel below instead (the "
                            "line lies on a row boundary)")  # fmt: skip
        return words + "; GL, moving them with y up, decides it the same way"

    def coverage_at(self, k: int) -> np.ndarray:
        """(height, width) bool: the pixels lit once steps 0..k have run (none in set-up)."""
        k = self.index(k)
        width, height = self.size
        out = np.zeros((height, width), bool)
        work = k - len(SETUP)
        if work < 0:
            return out
        if self.steps is None:  # wide lines: one coverage image per step
            for done in self.wide[: work + 1]:
                out |= done
            return out
        mine = (self.steps.step <= work) & (self.steps.state == LIT)
        out[self.steps.rows[mine], self.steps.cols[mine]] = True
        return out

    def lit_at(self, k: int) -> np.ndarray:
        """(height, width) bool: the pixels step ``k`` itself lit, what it added to
        :meth:`coverage_at` (each pixel is decided in one step only: its column or row, or
        one triangle of a wide line, which the top-left rule keeps apart)."""
        k = self.index(k)
        now = self.coverage_at(k)
        return now & ~self.coverage_at(k - 1) if k > 0 else now

    def midpoint(self, k: int) -> tuple[tuple[float, float], tuple[float, float]] | None:
        """Bresenham's test at step ``k``: the midpoint between the next column's (row's) two
        candidate pixels and the point where the line between the end pixels' centres crosses
        that column (row), both (x, y) in px; None for other rules and the set-up steps.

        The error term is that gap scaled: ``D = 2·dmajor·(line − midpoint)`` along the
        minor axis (in the direction the minor axis steps), so the crossing is read off D.
        """
        k = self.index(k)
        work = k - len(SETUP)
        if self.rule != "bresenham" or self.steps is None or work < 0:
            return None
        s = self.steps
        axis = 0 if s.x_major else 1
        p = [int(np.floor(self.p0[0])), int(np.floor(self.p0[1]))]
        q = [int(np.floor(self.p1[0])), int(np.floor(self.p1[1]))]
        d_major, d_minor = q[axis] - p[axis], q[1 - axis] - p[1 - axis]
        if d_major == 0:
            return None
        sign_major, sign_minor = np.sign(d_major), (1 if d_minor >= 0 else -1)
        nxt = int(s.major[work]) + sign_major  # the column (row) the error term decides
        done = (nxt - p[axis]) * sign_major  # major steps from p0's pixel
        line = p[1 - axis] + 0.5 + d_minor * done / abs(d_major)
        mid = line - sign_minor * float(s.value[work]) / (2 * abs(d_major))
        major = nxt + 0.5

        def xy(minor):
            return (float(major), float(minor)) if s.x_major else (float(minor), float(major))

        return xy(mid), xy(line)

    def ends_inside(self) -> tuple[np.ndarray, np.ndarray]:
        """(rows, cols) of the pixels whose diamond the line ends in (diamond rule)."""
        if self.steps is None:
            return np.zeros(0, np.int64), np.zeros(0, np.int64)
        mine = self.steps.state == ENDS_INSIDE
        return self.steps.rows[mine], self.steps.cols[mine]

    def near(self) -> np.ndarray:
        """(m,) bool: the candidates worth drawing, those the line comes near.

        The walk tests a window of candidates in each column (row), most of them far from
        the line. Kept: those lit, ended in or decided by a tie, and the missed ones whose
        pixel the segment passes through inside that column (a diamond the line misses
        although it crosses the pixel). The diamond explorer draws the same ones
        (``nearCandidates`` in ``widgets/static/explore_lines.js``; reviews r83, r88, r262).
        """
        s = self.steps
        if s is None:
            return np.zeros(0, bool)
        ax, ot = (0, 1) if s.x_major else (1, 0)
        a, b = np.asarray(self.p0, float), np.asarray(self.p1, float)
        major = s.major[s.step]  # each candidate's column (row)
        # the part of the segment inside that column, and its extent along the minor axis
        lo = np.maximum(major, min(a[ax], b[ax]))
        hi = np.minimum(major + 1, max(a[ax], b[ax]))
        span = b[ax] - a[ax]

        def at(u):
            return a[ot] + (u - a[ax]) * (b[ot] - a[ot]) / span if span else np.full_like(u, a[ot])

        m0, m1 = np.minimum(at(lo), at(hi)), np.maximum(at(lo), at(hi))
        minor = s.rows if s.x_major else s.cols
        crossed = np.where(m0 == m1, (minor <= m0) & (m0 < minor + 1),
                           (minor < m1) & (m0 < minor + 1))  # fmt: skip
        tie = s.tie if s.tie is not None else np.zeros_like(crossed)
        return (s.state != 0) | tie | crossed
