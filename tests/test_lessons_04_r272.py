"""Lesson 04, review r272: each test fails on the lesson before the fix.

C1/F1/FIG3: with the summary's Try-it (w = [1, 1, 8], the floor at 64 x 48) the words of
section 5 and of *Far away* follow what the cells print, and the far-floor figure stays inside
the image; the one-row-of-checks rule names the camera's direction.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK = ROOT / "notebooks" / "04_perspective_correct_interpolation.ipynb"


def _cells() -> dict:
    return {c["id"]: "".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]}


def _flat(cell_id: str) -> str:
    return " ".join(_cells()[cell_id].split())


class _Held:
    def hold(self):
        pass


def _run(sources, capsys, ns=None) -> tuple[dict, str]:
    """Run cell sources in one namespace (figures not shown); what they printed."""
    ns = {"display": lambda *a, **k: None, "q_affine": _Held(), "q_diagonal": _Held()} | (ns or {})
    capsys.readouterr()
    for source in sources:
        exec(source.replace("%matplotlib inline", "").replace("plt.show()", ""), ns)
    return ns, capsys.readouterr().out


def _section_5(capsys, w_text=None):
    cells = _cells()
    made = cells["c04-surfaces"].split("surfaces = ")[0]
    if w_text:
        made = made.replace("w = np.array([1.0, 2.0, 4.0])", f"w = np.array({w_text})")
    return _run([cells["c01"], made, cells["c05"], cells["c09"].split("player = ")[0],
                 cells["c12"], cells["q-worst"]], capsys)  # fmt: skip


@pytest.mark.notebook
@pytest.mark.parametrize("w_text", [None, "[1.0, 1.0, 8.0]"])
def test_c1_section_5_says_what_its_cell_prints_for_f(capsys, w_text):
    """Cell 20 said an attribute 1 at v3 is not exact on the line of depth w2; with the Try-it
    that line is edge v1v2, where it is exact. Now the cell prints the verdict."""
    ns, printed = _section_5(capsys, w_text)
    text = _flat("c11")
    assert "and 0 at the other two is not (the last lines" not in text
    assert "the last lines of the cell say which, for the current $w$" in text
    exact = ns["iso_gap"] < 1e-9
    assert exact == (w_text is not None)  # Try-it: v2 -> v1, f = 0 at both ends
    verdict = "exact on it too: its ends agree" if exact else "not exact on it: its ends disagree"
    assert f"so f is {verdict}" in printed
    assert f"largest |Δf| on it {ns['iso_gap']:.3f}" in printed
    summary = _flat("c20")
    assert "(section 5, with section 2's depths: the line of depth $w_2$ is exact" in summary
    plt.close("all")


def _floor(capsys, size="320, 240"):
    cells = _cells()
    made = cells["c14"].replace("FW, FH = 320, 240", f"FW, FH = {size}")
    assert made != cells["c14"] or size == "320, 240"
    return _run([cells["c01"], made, cells["c16"], cells["c27fig"]], capsys)


@pytest.mark.notebook
@pytest.mark.parametrize("size", ["320, 240", "64, 48"])
def test_c1_fig3_far_floor_words_follow_the_printed_rows(capsys, size):
    """Cell 33 typed "(0 → 3, 4 → 6)", false at 64 x 48 (6, 10, 11, ...); the figure kept 32
    rows below the far edge on a 48-row image and its labels ran out of the axes."""
    ns, printed = _floor(capsys, size)
    text = _flat("c15")
    assert "(0 → 3, 4 → 6)" not in text and "a few rows below" not in text
    assert "the cell prints the skips" in text
    rows = ns["check_rows"]
    steps = np.diff(rows)
    skips = [f"{a} -> {b}" for a, b, d in zip(rows, rows[1:], steps) if d > 1]
    assert skips and steps[0] > 1  # "near the far edge the lookup skips"
    assert f"skips of more than one check row: {', '.join(skips)}" in printed
    start = int(re.search(r"from pixel row (\d) of the eight on", printed).group(1))
    assert steps[start - 1 :].max() <= 1 and steps[start - 2] > 1
    crossed = [float(x) for x in re.search(r"crosses.*?: (.*)", printed).group(1).split(", ")]
    assert crossed[0] > 1  # item 1: more than one row of checks per pixel row
    assert np.all(np.diff(ns["run_px"]) > 0)  # item 4: the runs grow steadily
    assert 0 < ns["far_row"] - ns["horizon_y"] < 6  # "a little below the true horizon"
    # FIG3: the window inside the image, the labels inside the axes
    fig, ax = ns["fig"], ns["ax"]
    bottom, top = ax.get_ylim()
    assert bottom <= ns["FH"] and top >= ns["horizon_y"] - ns["FH"] / 40
    fig.canvas.draw()
    box = ax.get_window_extent()
    for label in ax.texts:
        inner = label.get_window_extent()
        assert box.x0 <= inner.x0 and inner.x1 <= box.x1, label.get_text()
    plt.close("all")


@pytest.mark.notebook
def test_f1_one_row_of_checks_needs_the_camera_along_them(capsys):
    """Cell 33 claimed one row of checks per pixel row "whichever way the camera turns"."""
    text = _flat("c15")
    assert "whichever way the camera turns or looks down: each row samples" not in text
    assert "because this camera also looks straight along the checks" in text
    ns, printed = _floor(capsys)
    assert ns["v_spread"] < 1e-12
    assert f"largest spread of v along a pixel row: ≈ 0 ({ns['v_spread']:.0e}" in printed
    plt.close("all")


def test_m1_one_standards_table_for_the_rule():
    """There was no GL/D3D/Vulkan/llvmpipe/teachraster table for the rule (M1)."""
    cells = _cells()
    ids = list(cells)
    assert ids.index("c04-apis") == ids.index("c04") + 1
    table = cells["c04-apis"]
    head = "| | OpenGL 4.6 (GLSL 4.60) | Direct3D 11 | Vulkan | llvmpipe | teachraster |"
    assert head in table
    # the same columns as lesson 03's tables of its rules (two since r380 FIG1: the
    # standards, then llvmpipe and teachraster)
    three = json.loads((ROOT / "notebooks/03_barycentric_and_plane_equations.ipynb").read_text())
    rules = next("".join(c["source"]) for c in three["cells"] if c.get("id") == "c03-rules-table")
    heads = [line for line in rules.splitlines() if line.startswith("| rule |")]
    columns = [column.rstrip(" |") for line in heads for column in line.split(" | ")[1:]]
    assert columns == [column.rstrip(" |") for column in head.split(" | ")[1:]]
    rows = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    assert [r.split(" | ")[0] for r in rows[1:]] == [
        "| perspective-correct attribute (the default)", "| affine attribute",
        "| window depth", "| where the divide is made", "| what a shader can read",
    ]  # fmt: skip
    assert all(r.count(" | ") == 5 for r in rows)  # six columns each
    for cite in ("eq. (14.9) of §14.6.1 *Basic Polygon Rasterization*", "eq. (14.10)",
                 "`D3D_INTERPOLATION_LINEAR_NOPERSPECTIVE`", "HLSL *Interpolation Modifiers*",
                 "*Interpolation Decorations*", "`lp_bld_interp.c`", "`LP_INTERP_PERSPECTIVE`",
                 "`lp_build_rcp`", "`gl_FragCoord.w`", "`gl_BaryCoordEXT`",
                 "`gl_BaryCoordNoPerspEXT`", "`SV_Barycentrics`",
                 "`VK_KHR_fragment_shader_barycentric`", "`tr.perspective_weights`",
                 "`fill.trace.pixel_barycentric`",
                 # r312 M2: Direct3D 11's own sections (D3D11.3 functional specification)
                 "D3D11.3 §16.4 *Rasterizer / Pixel Shader Attribute Interpolation Modes*",
                 "§16.3 *Pixel Shader Inputs*", "§16.3.1 *Pixel Shader Input Z Requirements*",
                 "`SV_Position`'s $w$"):  # fmt: skip
        assert cite in table, cite
    assert "affine in screen space, as GL's" not in table
    # the prose no longer lists the keywords the table gives
    assert "Direct3D's `noperspective` interpolation modifier" not in cells["c04"]


def test_m1_the_table_names_what_the_package_has():
    import teachraster as tr

    lam = np.array([[0.5, 0.5, 0.0]])
    mu = tr.perspective_weights(lam, np.array([1.0, 3.0, 1.0]))
    assert np.allclose(mu, [[0.75, 0.25, 0.0]])  # (λ_i / w_i) / Σ λ_j / w_j
    fill = tr.rasterize(tr.Triangle([[1, 1], [9, 2], [3, 8]], w=[1, 2, 4]), 10, 10, trace=True)
    assert fill.trace.pixel_barycentric.shape[1] == 3


@pytest.mark.notebook
@pytest.mark.parametrize("w_text", [None, "[1.0, 1.0, 8.0]"])
def test_m2_click_the_pixel_with_the_largest_error(capsys, w_text):
    """Sections 2-5 had no prediction answered on a figure (M2): now q_worst asks about the
    pixels of largest |Δu| before the heatmap, which it holds with the text under it. r342 P1:
    "which centres reach the edges' peak" was answered by the 3-D view's "largest over the
    whole triangle"; now it asks for the one pixel of largest |Δu| again (r312 P1's worry,
    0.163 against 0.160, met by the dotted lines of constant w along which |Δu| is affine)."""
    cells = _cells()
    ids = list(cells)
    assert ids.index("q-worst") == ids.index("c12") + 1 == ids.index("ab224988") - 1
    for held in ("ab224988", "c12-peak-md", "c12-held-errors", "c12-spans"):
        assert cells[held].startswith("q_worst.hold()"), held
    assert "PredictPixels," in cells["c01"]
    ns, _ = _section_5(capsys, w_text)
    diff, worst, q = ns["diff"], ns["worst"], ns["q_worst"]
    assert worst == tuple(int(k) for k in np.unravel_index(np.nanargmax(diff), diff.shape))
    assert worst == ((4, 10) if w_text is None else (12, 6))  # the reviewer's, and r250's
    assert np.argwhere(q.answer).tolist() == [list(worst)] and q.data["one"]
    q.given = [list(worst)]
    assert q.correct
    for lure in ns["lured"]:  # the centres nearest a diamond
        q.given = [list(lure)]
        assert not q.correct
    # the dotted lines are lines of constant w: 1/w is the same at both their ends
    lines = ns["constant_w_lines"]()
    assert len(lines) >= 5
    for a, b in lines:
        lam = ns["tr"].barycentric(ns["xy"], np.array([a, b]))
        assert np.ptp(lam @ (1 / ns["w"])) < 1e-12
    explain = q.explain
    assert f"Pixel (row {worst[0]}, col {worst[1]}): |Δu| = {diff[worst]:.3f}" in explain
    if w_text is None:
        assert ns["lured"] == [(4, 9), (10, 8)] and f"{diff[worst]:.3f}" == "0.163"
        assert "(row 4, col 9), (row 10, col 8), lie deeper inside: only 0.160, 0.143." in explain
    else:
        assert ns["lured"] == [] and "It is the pixel centre nearest a diamond." in explain
    assert "<b>Click the pixel whose centre has the largest |Δu|</b>" in q.question
    assert "one=True" in cells["q-worst"] and "none=" not in cells["q-worst"]
    # nothing before the question gives the answer away
    before = " ".join(cells[k] for k in ids[: ids.index("q-worst")])
    assert f"row {worst[0]}, col {worst[1]}" not in before
    assert "falls off quickly inward" not in " ".join(before.split())
    # r335 P1: no cell before it prints the affine errors at the pixel centres (0.163)
    for printed in ("u_affine - u_true", "lam @ u_vertex - u_alpha", "np.nanmax(diff)"):
        assert printed not in before, printed
    plt.close("all")


def test_fig4_the_explorer_says_when_the_segment_lies_on_the_screen():
    """At z1/z0 = 1 the lesson's segment (z0 = 1) lies on the screen line: one line where the
    key promises two, and nothing said so (FIG4). Now the line under the sliders says it."""
    from teachraster.plotting.projection import Segment
    from teachraster.widgets import ProjectionExplorer

    explorer = ProjectionExplorer(Segment(-1.0, 1.0, 2.0, 4.0), q=0.75)
    try:
        assert "lies <i>on</i> the screen" not in explorer.info.value
        explorer.ratio.value = 1.0
        line = explorer.info.value
        assert "t = q everywhere" in line and "0.000" in line
        assert "both ends at depth 1: the segment lies <i>on</i> the screen" in line
        explorer.ratio.value = 2.0
        assert "lies <i>on</i> the screen" not in explorer.info.value
    finally:
        plt.close("all")


@pytest.mark.notebook
def test_r335_p1_nothing_seen_before_q_worst_prints_the_centres_largest():
    """r335 P1: sections 2-4 printed the affine error's largest over the pixel centres (0.163,
    below the edges' 0.172), which answered q_worst; now those lines, and the spans table's
    affine row under it, are held until it is checked. r342 P1: nor is the pixel named."""
    from test_predictions_r147 import seen_before_check

    seen = seen_before_check(
        "04_perspective_correct_interpolation", "q_worst = PredictPixels(", "q_worst"
    )
    assert "0.163" not in seen and "0.160" not in seen
    assert "row 4, col 10" not in seen and "(4, 10)" not in seen
