"""Review r475 of lesson 08: S1 (the intersection's example pixel no longer turns on a
near-tie: test_lesson_08_r382 checks its choice and its printed line), S3 (cell 34 names the
standards table where it is), S4 (q_centre's figure in the questions' x, y ticks, its E12 line
visible over the outline), S6 (cell 56, shown before q_fastest is checked, says where the chart
it reads is), M1 (well-spaced sample sets named beside the discrepancy bound)."""

import json
from pathlib import Path

import numpy as np
import pytest
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.notebook


def _sources():
    cells = json.loads((ROOT / "notebooks" / "08_antialiasing.ipynb").read_text())["cells"]
    return cells, ["".join(c["source"]) for c in cells]


@pytest.fixture(scope="module")
def ns():
    return lesson("08_antialiasing")


def test_s1_the_example_pixel_has_no_near_tie(ns):
    gaps = {k: min(abs(np.array(g))) for k, g in ns.depth_gaps.items()}
    assert (ns.sr, ns.sc) == max(gaps, key=gaps.get) and gaps[ns.sr, ns.sc] >= 1.5e-4
    assert min(gaps.values()) < 5e-5  # the split pixels hold near-ties: the choice matters


def test_s3_s6_references_say_where_the_table_and_the_chart_are():
    cells, sources = _sources()
    (resolve,) = [s for s in sources if s.startswith("## 6. The resolve, on a scene")]
    words = " ".join(resolve.split())
    assert "(which APIs promise it: the standards table below)" in words
    assert "the table under *MSAA in today's practice*" not in words
    (k,) = [i for i, s in enumerate(sources) if s.startswith("### The lesson's rules, standard")]
    assert k > sources.index(resolve)  # the table is below it
    (axis,) = [s for s in sources if s.startswith("On axis-aligned edges the standard 2-")]
    words = " ".join(axis.split())
    assert 'fall like $1/S$ (the chart under the question, once checked: "standard, axis edges")' in words  # fmt: skip
    (q,) = [i for i, s in enumerate(sources) if "q_fastest = Predict(" in s]
    assert sources.index(axis) > q and sources[q + 1].startswith("q_fastest.hold()")


def test_s4_q_centre_figure_in_coordinates_with_a_visible_e12(ns):
    _, sources = _sources()
    (ask,) = [s for s in sources if "q_centre = Predict(" in s]
    figure = ask[ask.index("# the question's picture") : ask.index("q_centre = Predict(")]
    assert "plot_pixel_grid(ax, W, 4, ticks=False)" in figure
    assert "screen_ticks(ax, W, 4, most=11)" in figure
    assert 'ax.set(xlabel=PIXEL_BORDERS, ylabel="y, down")' in figure  # as q_sliver, q_levels
    assert "ax.xaxis.tick_top()" in figure
    # the E12 line is drawn over the triangle's outline (zorder 4 > the outline's 2), in black
    line = figure[figure.index("ax.plot([0, W]") : figure.index("ax.add_patch")]
    assert 'color="black"' in line and "zorder=4" in line
    assert "the line of E12: v = 0 along it" in line


def test_m1_well_spaced_sets_named_beside_the_bound(ns):
    held = " ".join(ns.FASTEST_TEXT.split())
    bound = held.index("are not the worst edge the bound speaks of.")
    rest = held[bound:]
    assert "blue-noise (Poisson-disk) sets" in rest and "Halton and Sobol" in rest
    assert "*Physically Based Rendering*, 4th ed., ch. 8" in rest


def test_s7_taa_cases_one_line_each():
    """S7: cell 51 packed 11 numbers in one paragraph; the four histories are now a list, each
    with its own numbers (test_lesson_08 checks the numbers against cell 49's table)."""
    _, sources = _sources()
    (taa,) = [s for s in sources if s.startswith("Held still, 16 jittered frames average")]
    cases = [line for line in taa.splitlines() if line.startswith("- ")]
    starts = ("Not reprojected,", "Reprojected,", "Clamped,", "Clamped but not reprojected,")
    assert len(cases) == 4 and all(c[2:].startswith(s) for c, s in zip(cases, starts))
