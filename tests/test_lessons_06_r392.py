"""Lesson 06, review r392: each test fails on the lesson before the fix.

M1: §2 (edge functions) had no picture; its claim that float32 at 10⁶ px *is* 4-bit sub-pixel
fixed point rested on one printed line. A figure now draws float32's spacing against the
distance from the origin beside the 1/256 and 1/16 px grids, and the mesh's pixels that
float32 gets wrong at 10⁶ px over fixed4's (the same 69 pixels, 138 triangle decisions).
S1: about 100 printed lines sat in cells 3, 20, 28, 33 and 41; the NVIDIA rates are printed
once (grouped by share), and the lines the text does not quote are folded in ``<details>``.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from notebook_runs import executed, lesson, printed_and_folded

from teachraster.study import bench

ROOT = Path(__file__).resolve().parent.parent
NAME = "06_what_accuracy_costs"
NOTEBOOK = ROOT / "notebooks" / f"{NAME}.ipynb"


def _stream_lines(cell) -> int:
    return sum(o.get("text", "").count("\n") for o in cell.outputs if o.output_type == "stream")


def test_mesh_wrong_pixels_sum_to_the_study_columns():
    size = bench.sizes(quick=True)["mesh"]
    far = bench.mesh_wrong_pixels(size, 1_000_000, "float32")
    fixed4 = bench.mesh_wrong_pixels(size, 0, "fixed4")
    # the study's own columns (bench_edges): 138 at 1e6 for float32, 138 everywhere for fixed4
    assert int(far.sum()) == int(fixed4.sum()) == 138
    assert np.array_equal(far > 0, fixed4 > 0) and int((far > 0).sum()) == 69
    assert int(bench.mesh_wrong_pixels(size, 0, "float32").sum()) == 0
    assert int(bench.mesh_wrong_pixels(size, 1_000_000, "float32", against="fixed4").sum()) == 0


def test_edge_precision_plots_return_their_artists(plt):
    from teachraster.plotting.edge_precision import plot_float32_spacing, plot_mesh_differences

    fig, (a, b) = plt.subplots(1, 2)
    drawn = plot_float32_spacing(a, {"@1e6": 1_000_000})
    assert len(drawn["grids"]) == 4 and len(drawn["marks"]) == 2
    assert "@1e6: 1/16 px" in [t.get_text() for t in a.texts]
    wrong = np.zeros((8, 8), int)
    wrong[2, 3] = 2
    tris = np.array([[[0, 0], [8, 0], [0, 8]]], float)
    got = plot_mesh_differences(b, tris, 8, wrong, wrong, labels=("a", "b"))
    assert got["wrong"].get_offsets().tolist() == [[3.5, 2.5]] and got["also"] is not None
    plt.close(fig)


@pytest.mark.notebook
def test_m1_section_2_draws_float32_far_out():
    ns = lesson(NAME)
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    ids = [c["id"] for c in cells]
    at = ids.index("c07edgefig")
    assert ids[at - 1] == "c07" and ids[at + 1] == "c08"  # beside §2's table, before its text
    source = "".join(cells[at]["source"])
    assert "plot_float32_spacing(" in source and "plot_mesh_differences(" in source
    assert source.split("\n", 1)[0].startswith("# float32 far out")
    run = executed(NAME).notebook().cells
    (shown,) = [c for c in run if c.get("id") == "c07edgefig"]
    assert any("image/png" in o.get("data", {}) for o in shown.outputs)
    assert ns.fig_edges.get_size_inches()[0] * ns.fig_edges.dpi <= 900
    assert ns.f32_vs_f4 == {0: 138, 100_000: 128, 1_000_000: 0} and ns.far_pixels == 69
    edge = " ".join(ns.EDGE_TEXT.split())
    assert "the figure's staircase reaches the 4-bit line there" in edge
    assert "(its right panel: the same 69)" in edge
    printed = printed_and_folded(executed(NAME).notebook())
    assert "@1e6's 138 are 69 pixels, each\n  on an edge, decided wrongly by both" in printed


@pytest.mark.notebook
def test_s1_printed_lines_cut_the_rest_folded():
    run = {c.get("id"): c for c in executed(NAME).notebook().cells}
    limits = {
        "c02prices": 16,
        "c03": 12,
        "c07": 9,
        "c07edgefig": 5,
        "c11": 9,
        "c13": 7,
        "c15front": 12,
    }
    for cid, most in limits.items():
        assert _stream_lines(run[cid]) <= most, (cid, _stream_lines(run[cid]))
    for cid in ("c03", "c11", "c13", "c15front"):
        pages = ["".join(o.get("data", {}).get("text/html", "")) for o in run[cid].outputs]
        assert any(p.startswith("<details><summary>") for p in pages), cid
    printed = printed_and_folded(executed(NAME).notebook())
    # the NVIDIA generations once, grouped; the fronts and the rest one click away
    assert printed.count("Maxwell") == 1 and "results per clock" not in printed
    assert "divide =   8: front affine -> N=32" in printed  # folded, unescaped
    assert "error of the direct variants" not in printed  # the table and the figure show it
