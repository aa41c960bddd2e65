"""Lessons 06-10: every number their text quotes or implies, checked against what they compute.

The markdown of these lessons refers to the numbers its cells print ("the cell above prints …")
instead of typing them; where the text still makes a claim about a number (a slope "between −1
and −½", "tens of texels", "more than 32 bits"), it is checked here on the variables the
executed lesson leaves behind (``tests/notebook_runs.py``'s ``lesson()``: one execution per
test run, shared with every other test that reads the lesson). The widgets that the lessons no
longer drive in front of the class are driven here.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from notebook_runs import lesson

ROOT = Path(__file__).resolve().parent.parent


pytestmark = [pytest.mark.filterwarnings("ignore::DeprecationWarning"), pytest.mark.notebook]


# -- 06 what accuracy costs ---------------------------------------------------------------------
def test_06_quake_mean_versus_max_and_the_cost_model():
    ns = lesson("06_what_accuracy_costs")
    n16 = ns.subdivided[16]
    assert n16["mean_abs_texels"] < 1.0  # "under a texel on average"
    assert 10 <= n16["error"] < 100  # "tens of texels at the worst pixels"
    # "the printed exponents start near 2 and fall as N grows" (spans end before their N-th pixel)
    ex = ns.exponents
    assert ex[0] > 1.9 and all(a > b for a, b in zip(ex, ex[1:])) and ex[-1] < 1.75, ex
    # "tens of texels ... a pixel or more (a few pixels) on screen at the worst pixels"
    k = int(np.argmax(ns.err_tex))
    assert ns.err_tex[k] == pytest.approx(n16["error"]) and 1 <= ns.err_px[k] < 10
    assert 1 <= ns.err_px.max() < 10 and ns.err_px.mean() < 1
    # the cycle model puts every subdivided variant at a fraction of the exact divide's cost
    assert all(r < 0.6 for r in ns.model_ratio.values()) and ns.model_ratio[16] < 0.15
    # "about half the bytes differ, each by one level"
    assert 0.4 < ns.differ < 0.6 and int(np.abs(ns.truncated - ns.rounded).max()) == 1
    cyc = ns.cyc
    assert cyc["perspective"] > 10 * cyc["affine"]  # "tens of times what affine does"
    assert cyc["affine"] < cyc["subdivided N=16"] < cyc["perspective"] / 5  # "buys most of it back"
    rows = {(r["group"], r["variant"]): r for r in ns.rows}
    assert rows[("interpolation", "affine")]["error"] >= 100  # "off by hundreds of texels"


def test_06_edge_bits_and_depth_claims():
    ns = lesson("06_what_accuracy_costs")
    rows = {(r["group"], r["variant"]): r for r in ns.rows}
    assert list(ns.needed.values()) == [37] * 3  # "the 37 the mesh needs"
    assert rows[("edge functions", "fixed8 direct")]["bits"] == 63
    assert rows[("edge functions", "float32 direct")]["bits"] == 24
    # linear unorm16: one step is more than the gap, at every distance
    assert ns.linear_step16 > 0.01 and round(ns.linear_step16, 4) == 0.0153
    for fmt in ("float64", "float32", "unorm24", "unorm16"):
        assert rows[("depth", f"linear {fmt}")]["slanted_wrong"] > 0  # wrong at any bits
    assert rows[("depth", "window float64")]["error"] == 0
    from teachraster.study import bench

    depth_rows = [r for r in ns.rows if r["group"] == "depth"]
    front = [r["variant"] for r in bench.pareto_front(depth_rows, x="bits")]
    assert not any(v.startswith("linear") for v in front)
    # "window float32 and window unorm24 get exactly the same pixels wrong": the same step near 1
    assert (
        rows[("depth", "window float32")]["facing_wrong"]
        == rows[("depth", "window unorm24")]["facing_wrong"]
    )
    assert ns.spacing32 == pytest.approx(ns.step24, rel=1e-6)
    stored_front = [r["variant"] for r in bench.pareto_front(depth_rows, x="stored_bits")]
    assert "window unorm24" in stored_front and "window float32" not in stored_front
    assert {r["variant"].split()[1]: r["stored_bits"] for r in depth_rows} == {
        "float64": 64,
        "float32": 32,
        "unorm24": 24,
        "unorm16": 16,
    }
    # the two naive tie rules fail on the same shared-edge centres, none on the outline
    assert ns.cracks["E >= 0"]["double_hits"] == ns.cracks["E > 0"]["gaps"] > 0
    # "float32 keeps 24 bits, fewer than a position at 1e6 px on the 1/256 px grid needs"
    assert ns.position_bits == 28 > 24 and ns.float32_step == 1 / 16
    assert np.isclose(ns.floor_w.max() / ns.floor_w.min(), 100)  # "w grows a hundredfold"
    # "the counts differ by a factor of twenty or more"
    assert all(r >= 20 for r in ns.fill_ratio.values()), ns.fill_ratio


def test_06_divide_cost_slider_reprices_the_front():
    from teachraster.widgets.divide_cost import DivideCostExplorer, priced

    ns = lesson("06_what_accuracy_costs")
    ex = DivideCostExplorer(ns.interp_rows, backend="image")
    try:
        assert ex.front[0] == "affine" and ex.front[-1] == "perspective"
        cheap = {r["variant"]: r["cycles"] for r in priced(ns.interp_rows, 1.0)}
        ex.divide.value = 1.0
        assert "subdivided N=2" not in ex.front  # as dear as perspective-correct, and worse
        assert cheap["perspective"] / cheap["affine"] < 10 < ns.cyc["perspective"]
        assert "6×" in ex.info.value
        cheap_text = ex.info.value
        ex.divide.value = 128.0  # the slider's top: the headline moves with the price
        assert ex.info.value != cheap_text and "N=16 costs <b>7%</b>" in ex.info.value
        assert "N=16 costs <b>27%</b>" in cheap_text
        ex.error.value = "mean error"
        assert ex.front[-1] == "perspective"
    finally:
        ex.close()


# -- 07 hard cases ---------------------------------------------------------------------------
def test_07_the_catalogue_still_passes():
    ns = lesson("07_hard_cases")
    assert not ns.failures and ns.fan_naive.max() == 16
    assert not ns.wrong32.any()  # the predicted "nothing at all" at 1e6 px in float32


def test_07_predictions_and_the_numbers_the_text_quotes():
    ns = lesson("07_hard_cases")
    # the split square's diagonal runs through the centres (1, 1) .. (6, 6): 6 drawn twice
    assert ns.twice == 6 == int((ns.split_square[1] > 1).sum())
    # float32's gap near 1e12 dwarfs every value of E inside the triangle (its doubled area)
    assert ns.spacing == 2.0**16 and ns.doubled_area < ns.spacing / 100
    # the sliver below the shared edge owns the row, alone
    assert ns.owners == [ns.below]
    # float32 and unorm24 lose about the same pixels at the shallow slope (same step in [0.5, 1))
    f32, u24 = ns.coplanar_wrong[("float32", 1e-06)], ns.coplanar_wrong[("unorm24", 1e-06)]
    assert f32 > 0 and u24 > 0 and abs(f32 - u24) <= 0.25 * max(f32, u24)
    assert float(np.spacing(np.float32(ns.near_depth))) == pytest.approx(1 / (2**24 - 1), rel=1e-6)


def test_07_your_turn_naive_differs_and_the_top_left_rule_fixes_it():
    from teachraster.study import hardcases

    ns = lesson("07_hard_cases")
    assert set(ns.my_wrong) == set(hardcases.list_cases("mesh"))
    assert all(v > 0 for v in ns.my_wrong.values())  # E >= 0 differs on every mesh case

    # ... and the change the text asks for (the top-left rule) brings every count to 0
    def top_left_coverage(xy, width, height):
        xy = np.asarray(xy, dtype=float)
        a, b, c = xy
        if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0:
            xy = xy[[0, 2, 1]]
        x, y = np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)
        inside = np.ones((height, width), dtype=bool)
        for p, q in zip(xy, np.roll(xy, -1, axis=0)):
            e = (q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0])
            top_left = q[1] < p[1] or (q[1] == p[1] and q[0] > p[0])
            inside &= (e > 0) | ((e == 0) & top_left)
        return inside

    for name in hardcases.list_cases("mesh"):
        case = hardcases.get_case(name)
        w, h = case.inputs["size"]
        mine = sum(top_left_coverage(t, w, h).astype(int) for t in case.triangles)
        assert np.array_equal(mine, case.run().counts), name


def test_07_case_picker_driven_by_the_test():
    from teachraster.widgets.case_picker import CasePicker

    picker = CasePicker("fan_spokes_through_centres", backend="image")
    try:
        picker.case.value, picker.method.value = "d3d_split_square", "span"
        assert picker.passed and picker.difference
    finally:
        picker.close()


# -- 08 antialiasing -----------------------------------------------------------------------------
def test_08_error_exponents_follow_mitchell_and_the_text():
    ns = lesson("08_antialiasing")
    slopes = ns.slopes
    # the triangle study: "between the two lines of the theory, -1/2 and -3/4 or a little beyond"
    assert all(-0.85 < k < -0.5 for k in slopes.values()), slopes
    assert max(slopes, key=slopes.get) == "random"  # nearest to -1/2
    for kind in ("standard", "grid", "jittered"):
        assert ns.err16[kind] > 2 * ns.err1 / 16  # not 1/S
    # one edge per pixel: jittered S^-3/4 (Mitchell 1996), random and axis-edge grid S^-1/2,
    # the grid over all angles "a little faster than S^-3/4"
    e = ns.edge_slopes
    assert abs(e["jittered"] + 0.75) < 0.08 and abs(e["random"] + 0.5) < 0.05, e
    assert abs(e["grid, axis edges"] + 0.5) < 0.05 and e["grid"] < -0.75, e
    # "the standard 4-, 8- and 16-sample patterns" put every sample on its own row and column
    import teachraster as tr

    for n in (4, 8, 16):
        p = tr.sample_pattern(n)
        assert len(set(p[:, 0].tolist())) == len(set(p[:, 1].tolist())) == n
    # "on these triangles the ordered grid has the smallest mean error at S = 16"
    assert ns.best16 == "grid" == min(ns.err16, key=ns.err16.get)


def test_08_predictions_are_answered_by_what_the_lesson_computes():
    ns = lesson("08_antialiasing")
    # the sliver: no centre, and the 4-sample pattern draws pixels 0 to 15 at a quarter each
    assert int(ns.sliver_1.coverage.sum()) == 0
    assert int(ns.sliver_4.coverage.sum()) == 16  # the Predict's answer
    assert np.flatnonzero(ns.sliver_4.coverage[1]).tolist() == list(range(16))
    assert set(ns.sliver_4.coverage_fraction[ns.sliver_4.coverage].tolist()) == {0.25}
    # a horizontal edge through the ordered grid: three values (0, 1/2, 1)
    assert ns.grid_values == 3  # the Predict's answer
    # the near-horizontal edge of the figure: the grid shows 1/4 once, not 3/4 ("luck")
    assert ns.levels["ordered grid"] == [0.0, 0.25, 0.5, 1.0]


def test_08_levels_fan_hub_centroid_and_resolve():
    ns = lesson("08_antialiasing")
    assert ns.levels["rotated grid (standard)"] == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert 0.75 not in ns.levels["ordered grid"]
    assert ns.hub_count == 1 and int((ns.count > 1).sum()) == 0
    assert np.allclose(ns.centre, [10, 6] + ns.pattern16[0])
    v_c, v_s = ns.at_centre.attrs["v"][ns.pr, ns.pc], ns.at_centroid.attrs["v"][ns.pr, ns.pc]
    assert not 0 <= v_c <= 1 and 0 <= v_s <= 1  # extrapolated at the centre, inside at the sample
    assert not ns.at_centre.coverage_fraction[ns.pr, ns.pc] == 1.0
    assert ns.at_centre.sample_coverage[ns.pr, ns.pc, ns.nearest]
    assert (ns.crop[0].stop - ns.crop[0].start) >= 20  # the crop shows the cube large


def test_08_sampling_explorer_and_inspector():
    import teachraster as tr
    from teachraster.widgets import PixelInspector
    from teachraster.widgets.sampling_explorer import SamplingExplorer

    ex = SamplingExplorer(rate=32, width=0.0, backend="image")
    try:
        none = ex.result.rms_error
        ex.width.value = 1.0
        box = ex.result.rms_error
        assert box < none and ex.result.nyquist == 16
        ex.rate.value = 64
        assert ex.result.alias_from > 0.5
    finally:
        ex.close()
    inspector = PixelInspector(tr.Triangle([[1.3, 1.6], [18.7, 4.2], [6.1, 12.8]]), 20, 14,
                               row=2, col=12, backend="image")  # fmt: skip
    try:
        inspector.pattern.value = "16 standard"
        assert "of 16 covered" in inspector.pixel.square.axes.get_title()
        # 16 samples: each labelled by its number only, the edge values need 4 or fewer
        assert [t.get_text() for t in inspector.pixel.labels] == [str(s) for s in range(16)]
    finally:
        inspector.close()


# -- 11 and 12: predictions -------------------------------------------------------------------------
@pytest.mark.parametrize("name", ["11_debugging_a_frame", "12_lines_and_blending"])
def test_11_12_predictions_hide_their_answer_and_some_are_answered_on_a_figure(name):
    """A prediction's cell holds its answer: collapsed in the saved notebook (and tagged
    hide-input for the html page); at least one question is answered by acting on a figure."""
    import json
    import re

    cells = json.loads((ROOT / "notebooks" / f"{name}.ipynb").read_text())["cells"]
    asked = [c for c in cells if c["cell_type"] == "code"
             and re.search(r"\bPredict\w*\(", "".join(c["source"]))]  # fmt: skip
    assert len(asked) >= 3
    for cell in asked:
        meta = cell["metadata"]
        assert meta["jupyter"]["source_hidden"] is True and "hide-input" in meta["tags"]
    on_figure = [c for c in asked if re.search(r"\bPredict(Pixels|Point|Order)\(",
                                               "".join(c["source"]))]  # fmt: skip
    assert on_figure, name


# -- 11 debugging a frame ------------------------------------------------------------------------
def test_11_replay_and_the_sliver_between_centres():
    ns = lesson("11_debugging_a_frame")
    assert ns.replay_matches  # "replaying the records that passed rebuilds the pixel exactly"
    covered_1, covered_4 = ns.covered[1], ns.covered[4]
    assert 0 < covered_1 < covered_4  # a few centres where it crosses a row; more samples more


def test_11_helper_share_counts_every_lane_launched():
    ns = lesson("11_debugging_a_frame")
    # "Small triangles waste most of their quads' lanes on helpers": the sphere's median
    # triangle is a few pixels, the floor's two triangles are huge and waste few lanes.
    assert ns.share["uv_sphere"] > 0.5 > 0.2 > ns.share["textured_floor"]
    # the same share from the overlay's per-quad fractions, weighted by the lanes launched
    t = ns.floor.trace
    passed = t.fragment_passed
    quad = (t.fragment_row[passed] // 2) * ((ns.W + 1) // 2) + t.fragment_col[passed] // 2
    useful = np.bincount(quad, minlength=((ns.W + 1) // 2) * ((ns.H + 1) // 2))
    frac = ns.floor.overlay("quad_overshading")[::2, ::2].ravel()
    with np.errstate(invalid="ignore", divide="ignore"):
        launched = np.where(frac < 1, useful / (1 - frac), 0)
    assert np.isclose(1 - useful.sum() / launched.sum(), ns.share["textured_floor"])


# -- 09 texture filtering -----------------------------------------------------------------------
def test_09_bilinear_footprint_seams_and_the_sampling_picture():
    ns = lesson("09_texture_filtering")
    assert ns.whole  # the quad the text differences is covered by one triangle
    assert ns.bilinear_gap < 1e-12
    near, far = ns.picked["near"], ns.picked["far"]
    assert near[0] > far[0]
    # "near the viewer smaller than a texel and about twice as long as wide; towards the horizon
    # many texels long and thin"
    from teachraster.plotting.footprint import footprint

    fps = {}
    for name, (r, c) in ns.picked.items():
        fps[name] = footprint(ns.frame.attrs[r, c], ns.frame.ddx[r, c], ns.frame.ddy[r, c],
                              ns.levels[0].shape)  # fmt: skip
    axes = {k: sorted([np.hypot(*fp.axis_x), np.hypot(*fp.axis_y)]) for k, fp in fps.items()}
    assert axes["near"][1] < 1 and 1.5 < axes["near"][1] / axes["near"][0] < 2.5
    assert axes["far"][1] > 5 and axes["far"][1] / axes["far"][0] > 5
    read = ns.level_read
    steps = read["linear_mipmap_nearest"][ns.rows_shown, ns.W // 2]
    steps = steps[np.isfinite(steps)]
    assert np.array_equal(steps, np.round(steps)) and len(set(steps.tolist())) >= 3
    smooth = read["trilinear"][ns.rows_shown, ns.W // 2]
    assert (np.abs(smooth - np.round(smooth)) > 0.1).any()  # blended between levels
    assert len(ns.seam_rows) >= 3
    sampled = ns.sampled
    assert sampled[(1.0, "box")].rms_error < sampled[(0.0, "box")].rms_error
    assert sampled[(2.0, "gaussian")].rms_error < sampled[(0.0, "box")].rms_error


def test_09_quads_closed_form_and_predictions():
    ns = lesson("09_texture_filtering")
    # the title counts distinct quads, the plan (triangle, quad) shadings: one quad twice
    assert ns.art.n_quads == 20 and ns.shadings == 21
    assert f"{ns.shadings} 2x2 quad(s)" in str(ns.quads.plan["derivatives"])
    # the closed form (N_x - f D_x) / D is the derivative at the step's middle
    np.testing.assert_allclose(ns.closed_form, ns.exact_derivative, rtol=1e-5)
    # rho = 3: lambda = 1.585, GL's nearest level 2 (not floor(lambda) = 1)
    assert ns.level_q == 2 and abs(ns.lam_q - np.log2(3)) < 1e-12
    assert ns.top > 0  # the figures start at the floor, not in the sky


def test_09_summary_claim_more_reads_do_not_always_buy_accuracy():
    ns = lesson("09_texture_filtering")
    b, nmn = ns.b, ns.nmn
    assert b["texel_reads"] > nmn["texel_reads"]
    assert b["error_minified"] > nmn["error_minified"]
    assert ns.aniso_error < ns.trilinear_error


def test_09_filter_explorer_driven_by_the_test():
    from teachraster.widgets import FilterExplorer

    explorer = FilterExplorer(tilt=80, filter="trilinear", backend="image")
    try:
        errors = {}
        for f in ["nearest", "trilinear", "anisotropic"]:
            explorer.filter.value = f
            errors[f] = explorer.rms
            read = explorer.levels_read[np.isfinite(explorer.levels_read)]
            if f == "nearest":  # no mipmaps: the level panel shows level 0 everywhere
                assert read.size and (read == 0).all()
            else:
                assert read.max() > 2  # the tilted square's far end reads small levels
        assert errors["trilinear"] < errors["nearest"] and errors["anisotropic"] < errors["nearest"]
    finally:
        explorer.close()


# -- 10 tiles and hierarchical z ----------------------------------------------------------------
def test_10_numbers_the_text_relies_on():
    from teachraster.core import fixed_point

    ns = lesson("10_tiles_and_hierarchical_z")
    assert np.isclose(ns.values.max(), ns.corner_max) and np.isclose(ns.values.min(), ns.corner_min)
    assert all(ns.same.values())
    assert ns.per_pixel[0] > 10 * ns.per_pixel[-1]
    assert 30 <= ns.tests[2] <= 100  # the predicted "about 50"
    budget = ns.narrow.budget
    assert not budget.fits and f"{budget.needed} bits needed" in "\n".join(budget.lines())
    assert budget.needed > 32  # "more than 32"
    assert ns.narrow.wrong.any() and not ns.small_ok.wrong.any()
    assert ns.jumps["serpentine"] == 0
    assert ns.tile_changes["tiled"] == ns.tile_changes["morton"] == 3  # "3 is the least"
    assert min(ns.tile_changes.values()) == 3
    assert 2**30 / 512 < fixed_point.max_extent(8, 64)  # the guard band fits int64
    assert ns.front_first["hiz_rejected"] > 0 and ns.front_first["shaded"] == 96 * 64
    assert ns.gpu["hiz_rejected"] == 0  # back to front (the last order drawn): "none"
    assert ns.sphere["hiz_rejected"] > 0


def test_10_tile_explorer_driven_by_the_test():
    import teachraster as tr
    from teachraster.widgets import TileExplorer

    ns = lesson("10_tiles_and_hierarchical_z")
    explorer = TileExplorer(tr.Triangle(ns.xy), 64, 64, block_sizes=(16, 4, 1), backend="image")
    try:
        explorer.level.value = 1
        first = explorer.caption_text
        explorer.block.value = 3
        assert first and explorer.caption_text and explorer.caption_text != first
    finally:
        explorer.close()
