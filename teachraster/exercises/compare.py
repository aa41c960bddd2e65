"""Whole pictures side by side: the student's ``fill`` on a small scene beside the package's.

The scene is the catalogue's ``fan_spokes_through_centres``: 16 triangles around one vertex,
their shared edges running through pixel centres, so that the top-left rule decides many
pixels and a watertight fill covers every centre inside the fan exactly once; every other
triangle is wound the other way. Each panel
shows how many triangles cover each pixel; the third marks the pixels where the student's
count differs from the package's (+1: covered once too often, −1: a hole). A ``pixel=(i, j)``
argument, or a click on any panel, shows the explanation for that pixel: which triangle should
(or should not) cover it and why, by the rules (:func:`.coverage.explain_pixel`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .answers import as_coverage
from .cases import CoverageCase, catalogue_coverage
from .coverage import diagnose, edge_name, expected_coverage, explain_pixel, point
from .running import budget, run_case

#: The scene compared (a catalogue case).
SCENE = "fan_spokes_through_centres"
#: Seconds the student's fill may take on the whole scene (at least: the check's budget, if more).
COMPARE_BUDGET = 5.0


@dataclass(frozen=True)
class Comparison:
    """The scene's coverage by the package (``expected``) and by the student (``got``).

    ``expected`` and ``got`` are (n, h, w) bool arrays, one image per triangle; ``got`` is
    None when the student's function gave no image (``error`` says why).
    """

    case: CoverageCase
    expected: np.ndarray
    got: np.ndarray | None
    error: str | None

    @property
    def counts(self) -> tuple[np.ndarray, np.ndarray | None]:
        """How many triangles cover each pixel: the package's, the student's."""
        got = None if self.got is None else self.got.sum(axis=0)
        return self.expected.sum(axis=0), got

    def differing(self) -> np.ndarray:
        """(k, 2) rows and columns of the pixels whose count differs, in raster order."""
        want, got = self.counts
        return np.zeros((0, 2), int) if got is None else np.argwhere(want != got)


def scene() -> CoverageCase:
    """The fan, every other triangle turned the other way round (a fill handles both windings,
    and the coverage does not change)."""
    fan = next(c for c in catalogue_coverage() if c.label == SCENE)
    triangles = fan.triangles.copy()
    triangles[1::2] = triangles[1::2][:, [0, 2, 1]]
    label = f"{SCENE}, every other triangle wound the other way"
    return replace(fan, label=label, triangles=triangles)


def compare_fill(fn, seconds: float = COMPARE_BUDGET) -> Comparison:
    """Run the student's ``fill`` on every triangle of the scene, within ``seconds``."""
    case = scene()
    w, h = case.size
    expected = np.array([expected_coverage(case, xy) for xy in case.triangles])

    got = []
    with budget(seconds):
        for k, xy in enumerate(case.triangles):  # a triangle is a case: a loop stops early
            outcome = run_case(
                lambda xy=xy: as_coverage(fn(xy.copy(), w, h), h, w),
                case=f"triangle {k} of the scene",
            )
            if outcome.error is not None:
                return Comparison(case, expected, None, outcome.error)
            got.append(outcome.value if outcome.value.shape == (h, w) else outcome.value.T)
    return Comparison(case, expected, np.array(got), None)


def pixel_explanation(c: Comparison, i: int, j: int) -> str:
    """Why pixel (row i, column j) of the scene is covered as it is, and what yours did."""
    h, w = c.expected.shape[1:]
    if not (0 <= i < h and 0 <= j < w):
        return f"pixel (row {i}, column {j}) is outside the {w} × {h} image"
    centre = np.array([j + 0.5, i + 0.5])
    want = np.flatnonzero(c.expected[:, i, j])
    head = f"pixel (row {i}, column {j}), centre {point(centre)}: "
    if c.got is None:
        return head + f"covered by triangle(s) {list(want)}; yours gave no image ({c.error})"
    got = np.flatnonzero(c.got[:, i, j])
    wrong = np.flatnonzero(c.expected[:, i, j] != c.got[:, i, j])
    if not len(wrong):
        which = f"triangle {want[0]}" if len(want) else "no triangle"
        return head + f"covered by {which}, in yours as in the package's"
    k = int(wrong[0])
    xy = c.case.triangles[k]
    text, edge, _ = explain_pixel(xy, centre, bool(c.expected[k, i, j]))
    _, mistake = diagnose(c.case, xy, c.got[k], c.expected[k])  # the mistake of the triangle
    where = f" (edge {edge_name(edge)})" if edge is not None else ""
    return (
        head + f"the rule covers it {len(want)} time(s), yours {len(got)}. Triangle {k}"
        f"{where}: {text}" + (f". On this triangle {mistake}" if mistake else "")
    )


def draw_comparison(axes, c: Comparison, pixel=None) -> list:
    """Three panels: the package's counts, the student's, the differences; and the
    explanation of ``pixel`` (default: the first differing pixel). Returns the artists."""
    from .drawing import draw_counts, draw_differences

    want, got = c.counts
    artists = draw_counts(axes[0], c.case, want, "the package's fill")
    if got is None:
        artists += draw_counts(axes[1], c.case, np.zeros_like(want), "yours: no image")
        artists.append(
            axes[1].text(
                0.5,
                0.5,
                c.error[:80],
                transform=axes[1].transAxes,
                ha="center",
                va="center",
                fontsize="x-small",
                wrap=True,
            )
        )
    else:
        artists += draw_counts(axes[1], c.case, got, "your fill")
    diff = np.zeros_like(want) if got is None else got - want
    artists += draw_differences(axes[2], c.case, diff)
    wrong = c.differing()
    if pixel is None and len(wrong):
        pixel = tuple(int(v) for v in wrong[0])
    note = _explanation_text(axes[0], c, pixel)
    artists.append(note)
    figure = axes[0].figure

    def on_click(event):  # a click on any panel explains that pixel, in place
        if event.inaxes in axes and event.xdata is not None:
            note.set_text(_wrapped(c, int(np.floor(event.ydata)), int(np.floor(event.xdata))))
            figure.canvas.draw_idle()

    figure.canvas.mpl_connect("button_press_event", on_click)
    return artists


def _wrapped(c: Comparison, i: int, j: int, width: int = 90) -> str:
    import textwrap

    return "\n".join(textwrap.wrap(pixel_explanation(c, i, j), width)[:8])


def _explanation_text(ax, c: Comparison, pixel):
    if pixel is None:
        text = "your fill matches the package's on every pixel (click a pixel to explain it)"
    else:
        text = _wrapped(c, *pixel)
    return ax.text(
        0.0, -0.08, text, transform=ax.transAxes, ha="left", va="top", fontsize="x-small"
    )
