"""r357 (exercise 04 read again): the clip figures left v3, the vertex behind the camera, off
the panel, and the note of a function that returned None covered the panel's y label; cell 5
had no table of the APIs' near planes. The misnamed and half-named slips are corpus cases
(``student_variants.R357``).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from teachraster.exercises.depth_clipping import clip_with
from teachraster.exercises.drawing import draw_clip

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "04_depth_and_clipping.ipynb"


def test_cell_5_has_the_near_plane_of_each_api_one_line_each():
    text = "".join(json.loads(NOTEBOOK.read_text())["cells"][5]["source"])
    rows = [line for line in text.splitlines() if line.startswith("| ")]
    assert [r.split("|")[1].strip() for r in rows[1:]] == [
        "OpenGL 4.6", "Direct3D 11", "Vulkan", "llvmpipe (Mesa)", "teachraster"]  # fmt: skip
    assert "`GL_DEPTH_CLAMP`" in text and "`depthClampEnable`" in text
    assert "`DepthClipEnable = FALSE`" in text and "guard band" in rows[0]


def test_v3_is_marked_at_the_panels_edge_and_the_note_keeps_off_the_y_label():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.exercises.report import _free_span

    v = np.array([[-1.0, -1, 1.804, 2], [1, -1, 1.804, 2], [0, -1, -2.204, -2]])
    for got in (clip_with(v), None):
        fig, ax = plt.subplots(figsize=(7, 4))
        artists = draw_clip(ax, v, clip_with(v), got)
        said = [a.get_text() for a in artists if hasattr(a, "get_text")]
        assert any(t.startswith("v3 off the panel:\nz + w = -4.204") for t in said), said
        if got is None:  # the note's strip ends left of the panel's tick labels and y label
            fig.canvas.draw()
            panel = next(p for p in ax.child_axes if p.get_ylabel())
            label = panel.yaxis.label.get_window_extent().transformed(ax.transAxes.inverted())
            assert _free_span(ax)[1] < label.x0, (_free_span(ax), label.x0)
        plt.close(fig)


def test_4_3s_discs_sit_on_their_vertices_when_the_answer_is_none():
    """r364 FIG1: with no answer, 4.3 drew the expected colours on draw_clip's blank strip (the
    first inset), so every disc lay off its vertex, some outside the panel."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.exercises import clip_colour
    from teachraster.exercises.drawing import clip_panels

    case = clip_colour.colour_cases()[0]
    polygon = np.asarray(case[1][2], float)  # r489: 4.3 is handed the polygon
    fig, ax = plt.subplots(figsize=(7, 4))
    clip_colour._draw(ax, case, None)
    (panel,) = clip_panels(ax)  # the x panel alone
    (discs,) = panel.collections
    np.testing.assert_allclose(
        discs.get_offsets(), np.column_stack([polygon[:, 0], polygon[:, 2] + polygon[:, 3]])
    )
    strip = [a for a in ax.child_axes if a not in clip_panels(ax)]
    assert len(strip) == 1 and not strip[0].collections
    plt.close(fig)
