"""Review r472 of lesson 01: C1 the summary's prestep sentence says what cell 22 prints (a
vertex's height matters, not its leaving the centres); S2 section 5 in four parts (5, 5b, 5c,
5d); S3 the misfill count announced once; S4 no review id in the student's code. S1 (every
printed line fits 80 characters) is tests/test_lessons_b.py::test_every_printed_line_fits_a_column.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LESSON = ROOT / "notebooks" / "01_span_tables.ipynb"


def _cells() -> list[dict]:
    return json.loads(LESSON.read_text())["cells"]


def _source(cell_id: str) -> str:
    return " ".join("".join(next(c for c in _cells() if c.get("id") == cell_id)["source"]).split())


def test_c1_the_summary_names_the_vertex_height_the_prestep_output_shows():
    summary = _source("c17")
    assert "as soon as a vertex leaves the centres" not in summary
    assert "as soon as a vertex leaves the height of a row of centres" in summary
    # cell 22 moves v2 sideways off every centre (u = 18.3) and prints 0 changed at v = 9.5
    assert "for v2_v in np.round(np.arange(9.5, 10.55, 0.1), 1):" in _source("c5-prestep")
    assert "moved_v2 = tr.snap(np.array([xy[0], [18.3, v2_v], xy[2]]))" in _source("c5-prestep")


def test_s2_section_5_in_four_parts_in_order():
    heads = [
        line
        for c in _cells()
        if c["cell_type"] == "markdown"
        for line in "".join(c["source"]).splitlines()
        if re.match(r"#{2,3} 5", line)
    ]
    assert [h.split(".")[0] for h in heads] == ["## 5", "### 5b", "### 5c", "### 5d"], heads
    assert _source("20841a15").startswith("### 5b. Where stepping loses a tie")
    assert "### 5c. Span tables against half-planes" in _source("dda_end")
    assert _source("c24b-gouraud-text").startswith("### 5d. Colours along the spans")


def test_s3_the_count_is_announced_once():
    assert "How often does that do harm?" not in _source("20841a15")
    assert "no order of operations helps" in _source("20841a15")  # r251's check kept
    told = _source("dda_walk_text")
    assert "How often does that do harm on whole triangles?" in told
    assert "with their vertices on pixel centres, where ties are common" in told


def test_s4_no_review_id_in_the_code():
    code = "".join("".join(c["source"]) for c in _cells() if c["cell_type"] == "code")
    assert not re.search(r"\br\d{3} [A-Z]+\d", code), re.findall(r"\br\d{3} [A-Z]+\d", code)


@pytest.mark.notebook
def test_s1_the_reflowed_lines_keep_their_numbers():
    """The lines cut to 80 characters still print the numbers the text quotes."""
    from notebook_runs import executed, streams

    printed = streams(executed("01_span_tables").notebook())
    for line in (
        "  45395 crossings, 7655 of them ties;",
        "  each from both ends, wrong decisions: divide first 7, multiply first 0",
        "  our loop differs from the package on 0 of 300 random triangles",
        "  0.80 px higher: 7 pixels differ, in rows [10, 11, 12, 13, 14, 15, 16]",
        "  4 7.5  * 7.500000000000001  +8.9e-16    +1.5e-05  1920 +    0/1536 carry",
        "  by the float crossing 2 (0.1%), by the float DDA 4 (0.2%);",
        "  = 59.1 triangles expected to misfill",
    ):
        assert line in printed.splitlines(), line
    assert max(len(line) for line in printed.splitlines()) <= 80


@pytest.mark.parametrize("size", [(9.12, 6.48), (7.2, 5.8), (9.0, 7.0)])  # as test_setup_marks
def test_fig1_the_players_middle_tag_is_beside_v2(size):
    """r472 FIG1: moved off the edge into v2 (r452 FIG2), "middle" went to (13.3, 10.8), six
    columns from v2 at (18.5, 9.5), where it read as naming the flat-top part; the places
    above the vertex label, moved sideways into the Axes, now come first when clear."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    import teachraster as tr
    from teachraster.plotting import use_style
    from teachraster.plotting.setup_marks import ROLES
    from teachraster.widgets import FillPlayer

    with plt.style.context("default"):
        use_style("classroom")
        player = FillPlayer(tr.Triangle([[8.5, 17.5], [18.5, 9.5], [4.5, 1.5]]), 20, 20,
                            method="span", backend="image")  # fmt: skip
        try:
            view = player.view
            view.fig.set_size_inches(*size)
            split = next(k for k in range(len(view.trace)) if view.trace.step(k).kind == "split")
            view.show_step(split, draw=False)
            view.setup_marks.update(view.trace, view.triangle.labels)
            view.fig.canvas.draw()
            renderer = view.fig.canvas.get_renderer()
            ax = view.fig.axes[0]
            centres = {}
            for role, tag in zip(ROLES, view.setup_marks.roles):
                box = tag.get_window_extent(renderer)
                centres[role] = ax.transData.inverted().transform(
                    ((box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2)
                )
        finally:
            player.close()
            plt.close("all")
    near = {role: float(np.hypot(*(centres[role] - v))) for role, v in
            (("top", (4.5, 1.5)), ("middle", (18.5, 9.5)), ("bottom", (8.5, 17.5)))}  # fmt: skip
    assert near["middle"] < 5.0, (size, near)
    assert near["middle"] < near["top"] + 1.5 and near["middle"] < near["bottom"] + 1.5, near
