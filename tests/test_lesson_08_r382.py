"""Review r382 of lesson 08: C1 (u a frequency and an attribute, in lesson 00's table too), M1
(depth evaluated at each sample, with the printed depths of one pixel), FIG1 (q_levels' strip
cropped, the inside shaded), FIG2 (the whole floor beside its strips), S1 (the
SamplingExplorer fits one 1366 × 900 screen), S2 (a lecture path), S3 (q_centre drawn)."""

import json
from pathlib import Path

import numpy as np
import pytest
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.notebook


def _cells(name):
    cells = json.loads((ROOT / "notebooks" / f"{name}.ipynb").read_text())["cells"]
    return cells, ["".join(c["source"]) for c in cells]


@pytest.fixture(scope="module")
def ns():
    return lesson("08_antialiasing")


def test_c1_u_is_said_both_ways_in_lesson_00_and_08():
    _, tour = _cells("00_tour")
    (row,) = [line for s in tour for line in s.splitlines() if line.startswith("| $u$ |")]
    assert "in lesson 08 both: in §1 a frequency, later attributes again" in row
    assert row.endswith("| 00, 03, 04, 05a, 06, 08, 09 |")
    _, sources = _cells("08_antialiasing")
    words = " ".join(" ".join(sources).split())
    assert (
        "frequency $u$ (cycles per sample spacing; later sections use $u$, $v$ for attributes)"
        in (words)
    )
    assert 'attrs={"u": [0.0, 1.0, 0.0], "v": [0.0, 0.0, 1.0]}' in words  # §2's attributes


def test_m1_depth_per_sample_said_sourced_and_printed(ns):
    from notebook_runs import executed, streams

    cells, sources = _cells("08_antialiasing")
    (text,) = [s for s in sources if s.startswith("### Intersections: the depth test per sample")]
    words = " ".join(text.split())
    assert ("attributes are evaluated once per pixel (§2, §5), depth at each sample's own "
            "position, tested there (GL 4.6 §14.3.1, §17.3; D3D11.3 §3.5)") in words  # fmt: skip
    assert "(`gl_FragDepth`, `SV_Depth`)" in words and "unless it runs per sample" in words
    (table,) = [s for s in sources if s.startswith("### The lesson's rules, standard by standard")]
    (row,) = [r for r in table.splitlines() if r.startswith("| depth under MSAA (§6)")]
    assert "`gl_FragDepth`" in row and "`SV_Depth`" in row and "§17.3" in row
    # the printed pixel: its samples' signs are the depth test's verdicts, its centre's one
    # sign would give the whole pixel to one triangle, against the samples' split
    gap = np.array(ns.depth_gap)
    ids = ns.pierced[4].sample_triangle_id[ns.sr, ns.sc]
    assert ns.split[ns.sr, ns.sc] and ((gap[1:] < 0) == (ids == 0)).all()
    assert (gap[1:] < 0).any() and (gap[1:] > 0).any()
    # r475 S1: the pixel whose smallest |gap| (centre and samples) is the largest; it was the
    # most one-sided centre, (17, 25), where blue won a sample by +0.00001, a printed near-tie
    assert min(abs(gap)) == max(min(abs(np.array(g))) for g in ns.depth_gaps.values())
    assert min(abs(gap)) >= 1.5e-4, gap  # every sign readable at 5 decimals
    printed = streams(executed("08_antialiasing").notebook())
    said = (f"at its samples {', '.join(f'{d:+.5f}' for d in gap[1:])}: red won "
            f"{int((ids == 0).sum())} of 4;")  # fmt: skip
    assert said in " ".join(printed.split())
    winner = "red" if gap[0] < 0 else "blue"
    assert f"one depth for the pixel would give all 4 to {winner}" in " ".join(printed.split())


def test_fig1_levels_question_cropped_with_the_inside_shaded(ns):
    # rows 1-4 asked: every pixel at ¼ or ¾ lies in rows 2-3, none in rows 0 and 5 left out
    assert ns.QUESTION_ROWS == slice(1, 5) and ns.odd_standard.sum() == 8
    assert ns.odd_standard[ns.QUESTION_ROWS].sum() == 8 and not ns.odd_standard[[0, 5]].any()
    _, sources = _cells("08_antialiasing")
    (ask,) = [s for s in sources if "q_levels = PredictPixels(" in s]
    assert 'ax.fill([*ends[:, 0], 0], [*ends[:, 1], 9], color="#56B4E9"' in ask
    assert "answer=odd_standard[QUESTION_ROWS]," in ask
    assert '"inside the triangle"' in ask and "labels=[str(k + up) for k in range(5)]" in ask


def test_fig2_floor_strips_beside_the_whole_floor(ns):
    _, sources = _cells("08_antialiasing")
    (code,) = [s for s in sources if s.startswith("# the figure: the floor's far rows")]
    assert '"1 sample, whole"' in code and '"reference, whole"' in code
    assert "floor_crop.stop - floor_crop.start" in code


def test_s1_sampling_explorer_fits_a_1366_by_900_screen():
    from teachraster.widgets.sampling_explorer import SamplingExplorer

    ex = SamplingExplorer(rate=32, width=0.0, backend="image")
    try:
        # the sliders and the info line stood about 215 px above the figure (review r382)
        assert ex.fig.get_size_inches()[1] * ex.fig.dpi + 215 <= 780
    finally:
        ex.close()


def test_s2_lecture_path_and_s3_q_centre_drawn():
    cells, sources = _cells("08_antialiasing")
    assert "**Lecture path** (one session): §1 to §5, §6 up to the intersections" in sources[0]
    (ask,) = [s for s in sources if "q_centre = Predict(" in s]
    figure = ask[ask.index("# the question's picture") : ask.index("q_centre = Predict(")]
    assert "plt.show()" in figure and "the line of E12: v = 0 along it" in figure
    assert "attrs" not in figure and "v_at_centre" not in figure  # no value given away
