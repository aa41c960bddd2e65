"""Review r315 (exercise 06): what the corpus (student_variants.R315) does not carry.

FIG1: the notebook's ``compare`` helper keeps the panels at their size under a long
explanation, the text clear of the colour bars; cells 2 and 8: the samples are not snapped,
and who promises a resolve in linear light.
"""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib
from exercise_solutions import _coverage_with

from teachraster import exercises as ex

matplotlib.use("Agg")
NB = Path(__file__).parents[1] / "notebooks" / "exercises" / "06_antialiasing.ipynb"


def _cell(k: int) -> str:
    return "".join(json.loads(NB.read_text())["cells"][k]["source"])


def test_compare_keeps_its_panels_under_a_long_explanation():
    import matplotlib.pyplot as plt

    # the reader's failing 6.1, a bottom-right tie rule: its pixel (5, 5) takes seven lines
    report = ex.check("coverage_fraction", _coverage_with(tie=lambda a, b: b[1] > a[1] or (b[1] == a[1] and b[0] < a[0])))  # fmt: skip
    row, col = 5, 5
    helpers = {}
    exec(_cell(1).replace("%matplotlib inline", ""), helpers)
    shown = []
    helpers["plt"].show = lambda: shown.append(plt.gcf())
    helpers["compare"](report, (row, col))
    fig = shown[0]
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    panels = [ax for ax in fig.get_axes() if ax.get_title()]
    assert min(ax.get_window_extent().height for ax in panels) / fig.dpi > 2.5  # not thumbnails
    words = next(t for sub in fig.subfigs for t in [sub._supxlabel] if t is not None)
    assert words.get_text().startswith(f"pixel ({row}, {col})")
    lowest = min(ax.get_tightbbox(renderer).y0 for ax in fig.get_axes())
    assert words.get_window_extent(renderer).y1 <= lowest + 1  # under the bars, not across
    plt.close(fig)


def test_cells_2_and_8_say_what_is_snapped_and_who_promises_the_resolve_in_light():
    assert "only the vertices are snapped" in _cell(2)
    text = _cell(8)
    for source in ("D3D11.3 §5.6.6", "`vkCmdResolveImage`", "GL 4.6 §18.3.1", '"sRGB resolve"'):
        assert source in text, source
