"""r310 (exercise 04 read again): cell 2 said glass "is seen" where the check's own case covers
it with a wall drawn later; cell 0 pointed at an eye-plane case lesson 07 does not have; cell 5
did not say a repeated vertex is accepted; the clip figure's y panel was one vertical line for
the floor triangle (y = −1 everywhere) and a small polygon sat in a corner of axes scaled to
the whole triangle. The half-named slips are corpus cases (``student_variants.R310``).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from teachraster.exercises.depth_clipping import clip_with
from teachraster.exercises.drawing import draw_clip

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "04_depth_and_clipping.ipynb"


def _cell(k: int) -> str:
    return "".join(json.loads(NOTEBOOK.read_text())["cells"][k]["source"])


def test_the_text_says_glass_passes_and_why_it_is_drawn_last():
    assert "is seen when" not in _cell(2) and "glass **passes**" in _cell(2)
    assert "after all the opaque\ngeometry" in _cell(2)
    assert "a vertex behind the camera, which lesson 07 comes back to" in _cell(0)
    assert "the first\none repeated at the end, is accepted" in _cell(5)


def test_the_clip_figure_drops_a_flat_y_panel_and_zooms_on_the_polygon(plt):
    floor = np.array([[-1.0, -1, 1.8, 2], [1, -1, 1.8, 2], [0, -1, -2.2, -2]])
    fig, ax = plt.subplots()
    draw_clip(ax, floor, clip_with(floor), clip_with(floor))
    assert [a.get_xlabel() for a in ax.child_axes] == ["x (clip space)"]
    legend = ax.child_axes[0].get_legend()
    assert any("no y panel" in t.get_text() for t in legend.get_texts())
    # two vertices behind: a small polygon near the plane, zoomed on (plane in view)
    v = np.array([[0.0, 0, 0.2, 0.3], [4, 0, -4, -3], [-4, 4, -4, -3]])
    kept = clip_with(v)
    fig, ax = plt.subplots()
    draw_clip(ax, v, kept, kept)
    x_panel = ax.child_axes[0]
    lo, hi = x_panel.get_ylim()
    assert lo < 0 < hi and hi - lo < 0.5 * np.ptp(v[:, 2] + v[:, 3])
    lo, hi = x_panel.get_xlim()
    assert hi - lo < 0.5 * np.ptp(v[:, 0])
