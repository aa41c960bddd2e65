"""The lessons' numbers: each lesson is executed once and its variables are checked here.

The notebooks are written for a classroom, so they keep a visible check only where checking is
the point of the cell. The facts a lesson relies on (our loop fills what the package fills,
the formula gives the package's value, the figure shows what the text says) are asserted here,
on the variables the executed notebook leaves behind. ``lesson(name)``
(``tests/notebook_runs.py``) hands back every variable that pickles, as a namespace, from the
one execution of the notebook that every test of the run shares.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from notebook_runs import lesson  # noqa: F401 (other test modules import it from here)

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK_DIR = ROOT / "notebooks"

pytestmark = [pytest.mark.filterwarnings("ignore::DeprecationWarning"), pytest.mark.notebook]


# -- 01 span tables ------------------------------------------------------------------------------
def test_01_hand_written_span_loop_matches_the_package():
    ns = lesson("01_span_tables")
    span = ns.span
    assert list(span.order) == list(ns.order)
    assert np.array_equal(span.sorted_xy, ns.xy[ns.order])
    assert ns.u4 == 6.5 == span.u4
    # point 4 = (u4, v_mid) lies exactly on the long edge
    import teachraster as tr

    assert tr.edge_function(ns.xy[ns.order][0], ns.xy[ns.order][2], [ns.u4, ns.v_mid]) == 0
    assert span.flat_bottom[1, 1] == span.flat_bottom[2, 1] == ns.v_mid
    assert span.flat_top[0, 1] == span.flat_top[1, 1] == ns.v_mid
    assert np.array_equal(ns.cover, ns.fill.coverage)
    rows = [r for r in span.rows if r in ns.ends]  # the package also traces row v = v_bot
    assert set(span.rows) - set(rows) == {17}
    assert np.array_equal(span.x_left[: len(rows)], [ns.ends[i][0] for i in rows])
    assert np.array_equal(span.x_right[: len(rows)], [ns.ends[i][1] for i in rows])
    cover = ns.cover
    assert cover[5, 5] and not cover[5, 11]  # left end owned, right end not
    assert cover[9, 6] and not cover[9, 18]
    assert not cover[1].any() and not cover[17].any()


def test_01_flat_cases_follow_the_half_open_row_rule():
    ns = lesson("01_span_tables")
    for name, fill in ns.flat.items():
        assert np.array_equal(ns.ours_flat[name], fill.coverage), name
    top, bottom = ns.flat["flat-topped"], ns.flat["flat-bottomed"]
    assert top.trace.span.flat_bottom is None and top.coverage[2].sum() == 10
    assert bottom.trace.span.flat_top is None and not bottom.coverage[10].any()
    assert (
        not ns.flat["zero height"].coverage.any() and ns.flat["zero height"].trace.span.u4 is None
    )


# -- 02 half-planes ------------------------------------------------------------------------------
def test_02_bbox_edge_functions_and_bailout():
    import teachraster as tr

    ns = lesson("02_half_planes")
    box, rows, cols = ns.box, ns.rows, ns.cols
    assert (box.xmin, box.xmax, box.ymin, box.ymax) == (ns.u_min, ns.u_max, ns.v_min, ns.v_max)
    assert (box.col0, box.col1, box.row0, box.row1) == (
        cols.start,
        cols.stop,
        rows.start,
        rows.stop,
    )
    assert box.size == len(rows) * len(cols) == 169
    assert ns.cross_z == ns.cs148 == tr.edge_function(ns.v1, ns.v2, ns.p) > 0
    assert (ns.F != 0).all()
    assert np.array_equal((ns.F > 0).all(axis=-1), ns.fill.coverage)
    b = box
    assert np.array_equal(ns.trace.halfplane.edge_values, ns.F[b.row0 : b.row1, b.col0 : b.col1])
    assert np.array_equal(ns.runs, ns.by_hand)  # on the question's second triangle
    assert ns.with_bailout < ns.without


def test_02_winding_culling_and_the_top_left_rule():

    ns = lesson("02_half_planes")
    assert ns.front.front_facing and not ns.back.front_facing
    n = int(ns.fill.coverage.sum())
    assert ns.culled == {
        ("clockwise", None): n,
        ("clockwise", "back"): 0,
        ("clockwise", "front"): n,
        ("counter-clockwise", None): n,
        ("counter-clockwise", "back"): n,
        ("counter-clockwise", "front"): 0,
    }
    for name in ["top-left rule", "rule, unsnapped"]:
        assert np.array_equal(ns.counts[name], ns.square)
    naive = ns.counts["naive E >= 0"]
    assert naive.max() == 2 and (naive[ns.diagonal] == 2).all()
    assert not ns.row8["rule, above (its bottom edge)"].any()
    assert ns.row8["rule, below (its top edge)"].sum() == 12
    assert ns.row8["naive test, above"].sum() == ns.row8["naive test, below"].sum() == 13


# -- 03 barycentrics and plane equations --------------------------------------------------------
def test_03_three_views_of_one_plane():
    import teachraster as tr

    ns = lesson("03_barycentric_and_plane_equations")
    xy, p, f = ns.xy, ns.p, ns.f
    assert np.isclose(ns.lam_areas.sum(), 1.0) and np.allclose(ns.lam_areas @ xy, p)
    assert np.allclose(tr.barycentric(xy, p), ns.lam_areas) and np.allclose(ns.lam, ns.lam_areas)
    assert np.allclose(tr.barycentric(xy, xy), np.eye(3))
    lam_px = ns.lam_px
    assert np.allclose(lam_px, tr.barycentric(ns.fill.trace.snapped, ns.centres), atol=1e-15)
    assert ((lam_px >= 0) & (lam_px <= 1)).all()
    # the contour lines drawn are lines of constant λ1 inside the triangle
    assert np.nanmin(ns.lam1_fine) >= 0 and np.nanmax(ns.lam1_fine) <= 1
    plane = ns.plane
    assert np.allclose(-(plane.A * xy[:, 0] + plane.B * xy[:, 1] + plane.D) / plane.C, f)
    assert plane.C == tr.edge_function(*xy)
    assert np.isclose(plane(*p), ns.lam @ f)
    ys, xs = np.mgrid[0:14, 0:16] + 0.5
    assert np.allclose(ns.grid, plane(xs, ys), atol=1e-13)
    # Fatahalian's 3 x 3 system, and M recentred at v1, give the same gradient
    assert np.allclose(ns.system @ [ns.g_x, ns.g_y, ns.g_0], f)
    assert np.allclose(ns.g_recentred, [ns.g_x, ns.g_y]) and np.allclose(ns.M, ns.M_by_hand)
    assert np.allclose([ns.g_x, ns.g_y], [plane.dx, plane.dy])
    assert np.allclose(ns.planes.A, ns.abcd.dx) and np.allclose(ns.planes.B, ns.abcd.dy)
    assert np.allclose(ns.planes(*ns.centres.T), ns.fill.trace.pixel_barycentric @ ns.F)
    # review r143 03-11: the inverse of the vertex matrix (Olano and Greer) holds the λ planes
    # in its columns, M in its corner, and gives the attribute's plane; as printed
    assert np.abs(ns.inverse - ns.lam_planes).max() < 1e-12
    assert np.abs(ns.inverse[:2, 1:] - ns.M).max() < 1e-15
    assert np.allclose(ns.inverse @ f, [ns.g_x, ns.g_y, ns.g_0])
    assert np.allclose(ns.system @ ns.inverse, np.eye(3))


def test_03_r143_outside_the_triangle_one_weight_is_negative():
    """Review r143 03-10: f at every centre, covered or not; outside, one weight is negative,
    the weights still sum to 1 and f extrapolates past the vertex values (the printed numbers)."""
    ns = lesson("03_barycentric_and_plane_equations")
    covered, lam = ns.covered, ns.lam_all
    assert covered.sum() == 55 and (~covered).sum() == 169  # "55 of 224 centres covered"
    assert np.array_equal(lam.min(axis=-1) < 0, ~covered)  # outside <=> a negative weight
    assert np.allclose(lam.sum(axis=-1), 1.0)
    assert np.allclose(ns.f_all, ns.plane(ns.cx_all, ns.cy_all))  # the same plane
    assert round(ns.f_all.min(), 3) == 0.105 and round(ns.f_all.max(), 3) == 1.143
    assert ns.f_all.min() < ns.f.min() and ns.f_all.max() > ns.f.max()  # it extrapolates
    # helper pixels: uncovered, and in a 2 x 2 quad with a covered centre
    assert ns.helpers.sum() == 25 and not (ns.helpers & covered).any()
    for r, c in zip(*np.nonzero(ns.helpers)):
        assert covered[r // 2 * 2 : r // 2 * 2 + 2, c // 2 * 2 : c // 2 * 2 + 2].any()
    # the example printed: centre (2.5, 0.5), λ3 below 0 and λ1 above 1
    assert (ns.row, ns.col) == (0, 2) and ns.lam_all[0, 2, 2] < 0 < ns.lam_all[0, 2, 0] - 1


def test_03_stepping_and_recentring_numbers_match_the_text():
    ns = lesson("03_barycentric_and_plane_equations")
    err = ns.err
    assert err["stepped, float32"][-1] > 1e-3  # "a few hundredths off"
    assert err["stepped, float32"][-1] > 100 * np.spacing(np.float32(1000.0))
    assert 1e-13 < err["stepped, float64"].max() < 1e-9  # "about 1e-10"
    assert err["stepped, float64"].max() > 100 * err["direct, recentred (Fatahalian)"].max()
    assert max(ns.recentred) < 1e-13  # grid-aligned: differences exact, rounding level
    # review r78 03-2: "within a factor of about two of each other ... the level of one rounding"
    assert 1.5 < ns.direct_ratio < 2.5
    assert max(e.max() for e in ns.so_far.values()) <= np.spacing(1000.7)
    assert 1e-7 < ns.absolute[-1] < 1e-5  # "about 1e-6 at 1e6 px"
    assert ns.absolute[-1] > 1000 * ns.absolute[0]
    # review r57 03-3: the barycentrics a shader can read, by their API names
    import json

    nb = json.loads((ROOT / "notebooks" / "03_barycentric_and_plane_equations.ipynb").read_text())
    text = " ".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")
    for name in ("SV_Barycentrics", "gl_BaryCoordEXT", "gl_BaryCoordNoPerspEXT",
                 "VK_KHR_fragment_shader_barycentric"):  # fmt: skip
        assert name in text, name
    # review r78 03-4/03-6: the gradient printed as g_x, g_y (A, B are the other note's); the
    # cross-reference names lesson 06's heading as it reads
    code = " ".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code")
    assert "g.A" not in code and "g.g_x" in code
    six = (ROOT / "notebooks" / "06_what_accuracy_costs.ipynb").read_text()
    assert "*What a GPU pays*" in text and '"### What a GPU pays\\n"' in six
    # r209 03-3: "float64's gap near 10^13 is about 10^-3" (D's terms), "coordinates to about
    # 1e-10 px" at 1e6: printed
    assert ns.far_gap_at == 1e13 and 1e-3 <= ns.far_gap[1e13] < 2e-3
    assert 1e-10 <= ns.far_gap[1e6] < 2e-10


# -- 04 perspective-correct interpolation -------------------------------------------------------
def test_04_derivation_and_the_notes_barycentrics():
    ns = lesson("04_perspective_correct_interpolation")
    assert np.allclose(ns.t, ns.t_ray, atol=1e-15)
    assert np.allclose(ns.x / ns.z, ns.s)
    assert np.allclose(1 / ns.z, 1 / ns.z0 + ns.q * (1 / ns.z1 - 1 / ns.z0))  # Ek (19)
    assert not np.allclose(ns.z, ns.z0 + ns.q * (ns.z1 - ns.z0))
    assert ns.misprint > 0.1  # the notes' lines (17)-(18) with 1/z1 are wrong
    assert np.allclose(ns.u_persp, ns.u_true, atol=1e-12)
    assert np.abs(ns.u_affine - ns.u_true).max() > 0.1
    assert ns.residuals["u / w"] < 1e-12 and ns.residuals["1 / w"] < 1e-12
    assert ns.residuals["u"] > 1e-2 and ns.residuals["w"] > 1e-1
    # CS148's α_i are the world barycentrics of the hit point, and give Σλf/w ÷ Σλ/w
    assert np.allclose(ns.alpha, ns.alpha_ray, atol=1e-12)
    assert np.allclose(ns.u_alpha, ns.u_divide, atol=1e-15)
    assert np.allclose(ns.u_alpha, ns.u_true, atol=1e-12)


def test_04_toggle_heatmap_floor_and_tilt():
    ns = lesson("04_perspective_correct_interpolation")
    assert np.array_equal(ns.affine.coverage, ns.persp.coverage)
    assert np.allclose(*ns.same, equal_nan=True, atol=1e-15)
    assert 0.15 < np.nanmax(ns.diff) <= 3 - 2 * np.sqrt(2)
    assert 2 < ns.floor_w.max() / ns.floor_w.min() < 3  # the readable floor
    assert np.nanmax(ns.texels) > 10
    assert ns.far_w.max() > 35  # the original floor, for the moiré
    # r17: "towards the horizon one pixel row crosses more than one row of checks", printed
    assert (ns.crossed[:3] > 1).all() and ns.crossed[0] > 2


# -- 05a z-buffer ------------------------------------------------------------------------------
def test_05a_zbuffer_painter_plan_and_clipping():
    import teachraster as tr

    ns = lesson("05a_zbuffer")
    ids = ns.ids
    assert (ids["far first, then near"] == 1).all() and (ids["near first, then far"] == 0).all()
    assert (ids["equal depth (a tie)"] == 0).all() and (ids["no depth test"] == 1).all()
    for r in ns.results.values():
        assert (r["zbuf"].triangle_id == r["truth"]).all()
        assert (r["paint"].triangle_id != r["truth"]).sum() > 0
    assert min(ns.wrong_by_order["cyclic_overlap"].values()) > 0  # no order is right
    assert ns.orders_right == 0
    # the predicted answer: the best order gets one crossing wrong, "20 to 200 pixels"
    assert ns.best_order_wrong == min(ns.wrong_by_order["cyclic_overlap"].values())
    assert 20 <= ns.best_order_wrong <= 200
    assert min(ns.wrong_by_order["intersecting_triangles"].values()) > 0  # either order wrong
    frame = ns.frame
    assert np.array_equal(frame.depth.ravel()[ns.covered], ns.smallest[ns.covered])
    trace = frame.trace
    assert (trace.fragment_depth[ns.failed] >= ns.smallest[ns.pixel[ns.failed]]).all()
    assert trace.fragment_passed[trace.fragment_triangle == 0].all()
    assert np.array_equal(ns.failed_px, ns.painter_wrong) and ns.failed_px.any()
    # clipping, step by step: the near plane drops the vertex behind the eye, adds two on it
    near = ns.steps[0]
    assert near.plane.startswith("near") and near.new.sum() == 2 and len(near.polygon) == 4
    assert np.allclose(near.polygon[near.new, 2], -near.polygon[near.new, 3])
    assert not any(s.new.any() for s in ns.steps[1:])
    assert (ns.clipped[:, 3] > 0).all()
    assert ns.clip_tri_frame.coverage.any()
    from teachraster.pipeline.clipping import clip_polygon

    poly, attrs = clip_polygon(ns.clip_tri_clip, ns.clip_tri_u)
    assert np.allclose(poly, ns.clipped) and np.allclose(attrs, ns.clipped_u)
    assert (
        tr.render(ns.clip_tri_clip[None], 160, 120).coverage.sum()
        == ns.clip_tri_frame.coverage.sum()
    )


# -- 05b depth precision ------------------------------------------------------------------------
def test_05b_depth_mappings_resolution_and_fighting():
    import teachraster as tr

    ns = lesson("05b_depth_precision")
    assert ns.err_depth < 1e-12 and ns.err_z > 1e-3
    res = ns.res
    assert np.allclose(res[1:] / res[:-1], 100.0)
    # review r13 05b: the figure compares window and linear depth at the same 24 bits; they
    # meet at z = sqrt(n f) = 10, as the text says and the cell prints
    assert ns.z_meet == 10.0 and ns.meet[0] == pytest.approx(ns.meet[1], rel=1e-9)
    f, size = ns.fights, ns.size
    assert not f["float64"].any()
    assert not f["unorm16"][:2].any() and not f["float32"][:4].any()
    assert f["unorm16"][2] > 0 and f["float32"][2] == f["unorm24"][2] == 0
    assert f["float32"][5] > size[5] / 2 and f["unorm24"][5] > size[5] / 2
    for fmt, r in ns.predicted.items():  # section 2's prediction
        assert not f[fmt][r < ns.delta / 4].any()
        assert (f[fmt][r > 4 * ns.delta] > size[r > 4 * ns.delta] / 2).all()
    assert ns.levels["unorm16"] < ns.levels["unorm24"] <= ns.levels["float64"]
    assert tr.fights([2.0, 500.0], [2.5, 500.5], 0.1, 1000.0, "unorm16").tolist() == [False, True]


def test_05b_reverse_z_bias_and_explorer():
    ns = lesson("05b_depth_precision")
    # the per-pixel prediction reproduces the renders, and reverse-Z float32 removes the fight
    assert np.array_equal(ns.fights_window["float32"], ns.fights["float32"])
    assert not ns.fights_reversed["float32"].any()
    assert np.array_equal(ns.fights_reversed["unorm24"], ns.fights_window["unorm24"])
    assert ns.decal_shown["no bias"] < ns.decal_shown["depth bias"] == int(ns.decal_only.sum())


# -- 06 what accuracy costs ---------------------------------------------------------------------
def test_06_counts_errors_and_cracks():
    ns = lesson("06_what_accuracy_costs")
    row = {(r["group"], r["variant"]): r for r in ns.rows}
    assert row[("interpolation", "perspective")]["error"] < 1e-9
    assert row[("interpolation", "affine")]["error"] > 100
    sub = [row[("interpolation", f"subdivided N={n}")] for n in (2, 4, 8, 16, 32)]
    assert all(a["mean_abs_texels"] < b["mean_abs_texels"] for a, b in zip(sub, sub[1:]))
    assert all(a["cycles"] > b["cycles"] for a, b in zip(sub, sub[1:]))
    assert sub[3]["mean_abs_texels"] < 1.0  # Quake's N = 16: under a texel on average
    for ev in ["direct", "incremental"]:
        assert row[("edge functions", f"fixed8 {ev}")]["error"] == 0
        assert row[("edge functions", f"fixed4 {ev}")]["error"] > 0
        f32 = row[("edge functions", f"float32 {ev}")]
        assert f32["mesh_wrong_px_at_0"] < f32["mesh_wrong_px_at_1e6"]
    assert ns.cracks["top-left"]["gaps"] == ns.cracks["top-left"]["double_hits"] == 0
    assert ns.cracks["E >= 0"]["double_hits"] > 0 and ns.cracks["E > 0"]["gaps"] > 0
    assert all(r["error"] == 0 for r in ns.fill)
    assert row[("depth", "window unorm16")]["first_inverted_z"] == 20
    assert [r["variant"] for r in ns.fronts["interpolation"]][-1] == "perspective"


# -- 07 hard cases ------------------------------------------------------------------------------
def test_07_cases_fan_owners_and_catalogue():
    ns = lesson("07_hard_cases")
    ours, naive = ns.split_square
    assert ours.max() == 1 and naive.max() == 2
    owner = ns.fan_owner
    assert owner.max() == 15 and (owner >= -1).all()  # every pixel one owner, none twice
    assert ns.fan_naive[ns.hub] == 16 and owner[ns.hub] >= 0
    assert (ns.flat_top[0] != ns.flat_top[1]).any()
    assert ns.slivers[0].max() == 1 and ns.slivers[1].max() == 2
    assert ns.other_winding[0].any() and not ns.other_winding[1].any()
    at0, at1e6 = ns.far_coverage
    assert np.array_equal(at0, at1e6) and at1e6.any() and not ns.wrong32.any()
    assert ns.drift[1] > 1e6 * ns.drift[0]
    assert ns.sky.any() and not ns.sky_ours.any()
    assert ns.w_ratio_error > 0.5
    assert all(v == 0 for (fmt, _), v in ns.coplanar_wrong.items() if fmt == "float64")
    assert all(v > 0 for (fmt, _), v in ns.coplanar_wrong.items() if fmt == "unorm16")
    # review r72 07-1: §1's / square and the picker's \ square are both "shown", not "remaining"
    # review r244 M-1: the exactly coplanar case is shown in §5, with its cure
    assert (
        len(ns.shown) == 13 and {"d3d_split_square_other_diagonal", "coplanar_overlap"} <= ns.shown
    )
    # review r227 S-1: the lesson ends on the cases, not on the test table of every case (the
    # rest cell and introduce() check each case they print)
    assert not hasattr(ns, "failures") and len(ns.rest) > 10


# -- 00 tour ------------------------------------------------------------------------------------
def test_00_tour_numbers():
    ns = lesson("00_tour")
    assert ns.same and np.array_equal(ns.span.coverage, ns.halfplane.coverage)
    assert np.nanmax(ns.err) > 0.1
    assert ns.frame.image.shape == (240, 320, 3)
    # review r19 00-7: the cube's text says the faces turned away are filled too (culling
    # off) and the depth test keeps one fragment of the two each covered pixel gets
    assert ns.fragments == 2 * ns.covered and ns.covered == 8130
    # review r45 00-7: culling shown, not only named: half the fragments, the same picture
    assert 2 * ns.kept == ns.fragments and ns.same_picture
    assert {e.name for e in ns.frame.plan} >= {"clipping", "culling", "depth_test", "perspective"}
    # review r333 M2: the llvmpipe comparison shown, not only claimed (where GL is there)
    if ns.gl_ok:
        assert ns.gl_same == ns.gl_ids.size == 320 * 240


# -- 09 texture filtering --------------------------------------------------------------------------
def test_09_mipmaps_remove_the_moire():
    ns = lesson("09_texture_filtering")
    assert ns.rms["trilinear"] < 0.6 * ns.moire_error
    assert ns.rms["trilinear"] < ns.rms["bilinear"] < ns.rms["nearest"]
    assert ns.art.n_helpers > 0  # the quad figure shows helper pixels


def test_09_quad_differences_follow_the_exact_map():
    ns = lesson("09_texture_filtering")
    np.testing.assert_allclose(ns.quad_ddx, ns.exact_ddx, rtol=1e-9)
    # the quad in the cell below the figure has a helper at its upper right (review r195 09-12:
    # a whole quad's ddx was the plain difference by definition): ddx is the helper's
    # extrapolated value minus the upper-left pixel's, not what the image shows there
    r, c, qt, k = ns.qr, ns.qc, ns.qt, ns.pick
    assert qt.shaded[k, 0] and not qt.shaded[k, 1] and ns.quads.triangle_id[r, c] == ns.q_tri
    assert ns.quads.triangle_id[r, c + 1] != ns.q_tri  # the helper is not the triangle's pixel
    np.testing.assert_allclose(ns.quads.ddx[r, c], qt.values[k, 1] - qt.values[k, 0], atol=1e-12)
    shown = ns.quads.attrs[r, c + 1] - ns.quads.attrs[r, c]  # NaN, or the other triangle's
    assert not np.allclose(ns.quads.ddx[r, c], shown, atol=1e-6)


def test_09_an_srgb_textures_levels_average_light():
    import teachraster as tr

    ns = lesson("09_texture_filtering")
    # "averaging the encoded numbers darkens": black and white averaged as stored is 0.5,
    # about a fifth of white's light; averaged as light it is half of it, stored higher
    assert ns.of_numbers == 0.5 and float(tr.srgb_to_linear(ns.of_numbers)) < 0.25
    assert float(tr.srgb_to_linear(ns.of_light)) == pytest.approx(0.5) and ns.of_light > 0.7


def test_09_the_level_map_spans_magnified_and_minified_pixels():
    ns = lesson("09_texture_filtering")
    assert np.nanmin(ns.lam) < 0 < 5 < np.nanmax(ns.lam)
    assert len(ns.levels) == 8 and ns.levels[-1].shape[:2] == (1, 1)
    assert len(ns.band_rows) > 10  # the seams figure shows a real band


def test_09_anisotropy_wins_on_minified_pixels_and_costs_more():
    ns = lesson("09_texture_filtering")
    # review r61 09-6: the cap on the probes, 1 to 16: cap 1 is trilinear, 16 the default;
    # the error falls by less each time, the reads keep growing, 8 to 16 about a third more
    err = {cap: e for cap, (e, _, _) in ns.by_cap.items()}
    reads = {cap: r for cap, (_, r, _) in ns.by_cap.items()}
    assert err[1] == pytest.approx(ns.trilinear_error) and err[16] == pytest.approx(ns.aniso_error)
    caps = sorted(err)
    drops = [err[a] - err[b] for a, b in zip(caps, caps[1:])]
    assert all(d > 0 for d in drops) and drops == sorted(drops, reverse=True), err
    assert all(reads[a] < reads[b] for a, b in zip(caps, caps[1:])), reads
    assert 1.2 < reads[16] / reads[8] < 1.45 and drops[-1] < 0.005
    assert ns.aniso_error < ns.trilinear_error
    study = {r["filter"]: r for r in ns.study}
    minified = {f: r["error_minified"] for f, r in study.items()}
    reads = {f: r["texel_reads"] for f, r in study.items()}
    assert minified["anisotropic"] < minified["trilinear"] < minified["nearest"]
    assert reads["anisotropic"] > reads["trilinear"] > reads["nearest"]


def test_09_gpu_and_widget_agree_with_the_story():
    ns = lesson("09_texture_filtering")
    if ns.gl_agreement is not None:
        assert ns.gl_agreement >= 0.98
    # the widget is driven in tests/test_lessons_b.py (the lesson no longer drives it)


@pytest.mark.parametrize("path", sorted(NOTEBOOK_DIR.glob("*.ipynb")), ids=lambda p: p.stem)
def test_every_held_text_is_folded_so_its_source_does_not_answer_the_question(path):
    """A held cell (``q_x.hold()`` first) that displays a text shows its words after Check; its
    source must be folded too, or the words stand on screen under the question before it is
    answered (review r140: 04, 07; the same pattern then found in 02, 06, 09 and 10)."""
    import json
    import re

    for i, cell in enumerate(json.loads(path.read_text())["cells"]):
        text = "".join(cell["source"])
        if cell["cell_type"] != "code" or not re.match(r"(#[^\n]*\n)*q_\w+\.hold\(\)", text):
            continue
        if "Markdown(" in text or re.search(r"\b[A-Z_]+_TEXT = ", text):
            folded = cell["metadata"].get("jupyter", {}).get("source_hidden") is True
            assert folded and "hide-input" in cell["metadata"].get("tags", []), (path.name, i)


@pytest.mark.parametrize("path", sorted(NOTEBOOK_DIR.glob("*.ipynb")), ids=lambda p: p.stem)
def test_a_folded_cells_first_line_states_no_formula(path):
    """JupyterLab shows a folded cell's first line: lesson 03's held cell under q_weights read
    "q_weights.hold()  # p = λ1 v1 + λ2 v2 + λ3 v3 answers the drag by one substitution"
    (review r147, r143), the answer on screen before Check. A folded cell's first comment
    may set a premise ("x = 1.5", "N = 16") but states no formula (an = with an operator
    after it)."""
    import json
    import re

    for i, cell in enumerate(json.loads(path.read_text())["cells"]):
        if cell["cell_type"] != "code" or not cell["metadata"].get("jupyter", {}).get(
            "source_hidden"
        ):
            continue
        first = "".join(cell["source"]).split("\n", 1)[0]
        comment = first.split("#", 1)[1] if "#" in first else ""
        formula = re.search(r"=[^=,;:]*[+*/×÷]", comment)
        assert formula is None and "λ1 v1" not in first, (path.name, i, first)


def test_03_r155_homogeneous_rows_and_the_msaa_centre():
    """r155 F1: Olano and Greer's rows are the vertices before the divide, w_k (x_k, y_k, 1);
    w in the third column beside the screen x, y gives no f/w plane. C1: an uncovered centre is
    Direct3D's default evaluation point, GL leaves it open (lesson 08 §2). F2: beyond a vertex
    two weights are negative."""
    import json

    path = NOTEBOOK_DIR / "03_barycentric_and_plane_equations.ipynb"
    md = " ".join(
        " ".join("".join(c["source"]) for c in json.loads(path.read_text())["cells"]
                 if c["cell_type"] == "markdown").split()
    )  # fmt: skip
    assert "$w_k (x_k, y_k, 1)$" in md and "the third column holds each vertex's $w$" not in md
    assert "Direct3D's default" in md and "GL and Vulkan leave the location open" in md
    # r171: lesson 08 says so in its section 2; r258 C1: centroid sampling is its section 5
    assert "open: lesson 08, section 2; centroid sampling is its section 5)" in md
    eight = json.loads((NOTEBOOK_DIR / "08_antialiasing.ipynb").read_text())["cells"]
    heads = [line for c in eight for line in "".join(c["source"]).splitlines()
             if line.startswith("## ")]  # fmt: skip
    assert "## 2. Supersampling vs MSAA" in heads
    assert "## 5. Where MSAA evaluates attributes, and centroid sampling" in heads
    assert "two weights are negative" in md and "one weight negative" not in md


def _decade(value) -> int:
    """The nearest power of ten to the largest |value|, as lesson 03's ``about`` writes it."""
    return round(float(np.log10(np.abs(value).max())))


def _paragraphs(cells) -> list[str]:
    """The prose paragraphs of the Markdown cells (not tables, lists or display maths)."""
    found = []
    for cell in cells:
        if cell["cell_type"] != "markdown":
            continue
        for para in "".join(cell["source"]).split("\n\n"):
            if not para.lstrip().startswith(("|", "- ", "$$", "#")):
                found.append(" ".join(para.split()))
    return found


def test_03_r209_held_section_1_the_digits_lost_and_the_ranges_of_the_drift():
    """r209 03: 1, 2: every output of section 1 (the contour map labelled 0.6, 1.06 px from
    q_weights' answer, and the text on it) is held until Check, as its first paragraph says;
    3 (F): the digits go where D and A are built (terms of 10^13 cancel to D ~ 10^7), not in
    the last sum, whose terms are ~10^8; 6: 128 to 512 give back about a fifth; 7: the
    least-squares plane; 8: the area figure, a point outside with a negative weight; 9: the
    interpolation qualifiers and the provoking vertex; 10: no paragraph over 150 words."""
    import json
    import re

    import teachraster as tr

    ns = lesson("03_barycentric_and_plane_equations")
    path = NOTEBOOK_DIR / "03_barycentric_and_plane_equations.ipynb"
    cells = json.loads(path.read_text())["cells"]
    text = ["".join(c["source"]) for c in cells]
    one = next(i for i, t in enumerate(text) if t.startswith("## 1."))
    two = next(i for i, t in enumerate(text) if t.startswith("## 2."))
    # r216 03-3: "two paragraphs" were three; the outputs are no longer counted
    assert "This section's outputs (its text, numbers and figures) appear once" in " ".join(
        text[one].split()
    )
    codes = [t for c, t in zip(cells[one:two], text[one:two]) if c["cell_type"] == "code"]
    assert codes and all(t.startswith("q_weights.hold()") for t in codes)
    assert (
        sum("Markdown(" in t for t in codes) == 2 and sum("plt.subplots(" in t for t in codes) == 2
    )
    assert any("contour_levels = [0.2, 0.4, 0.6, 0.8]" in t for t in codes)  # the 0.6 label
    # 8: the areas of p and of a point beyond the edge v2v3, where λ1 alone is negative
    lam_out = tr.barycentric(ns.xy, ns.p_out)
    assert lam_out[0] < 0 < lam_out[1:].min() and np.isclose(lam_out.sum(), 1.0)
    assert any("def draw_areas" in t for t in codes)
    # 3: the magnitudes the explanation and the held text quote, as printed
    assert _decade(ns.d_terms) == 13 and _decade(ns.far_plane.D) == 7
    assert _decade(ns.far_D_error) == -4 and _decade(ns.far_A_error) == -10
    assert _decade(ns.worst_xy[0]) == 6 and _decade(ns.far_A_error * ns.worst_xy[0]) == -4
    assert _decade(ns.far_sum_parts["A x"]) == 8 and _decade(ns.absolute[-1]) == -6
    assert _decade(ns.far_gap[ns.far_gap_at]) == -3
    # the evaluation adds almost nothing: its error is D's and A x's
    inherited = ns.far_D_error + ns.far_A_error * ns.worst_xy[0]
    assert abs(ns.far_sum_error - inherited) < 1e-3 * abs(ns.far_sum_error)
    assert np.isclose(abs(ns.far_sum_error) / ns.far_plane.C, ns.absolute[-1], rtol=1e-6)
    assert not any("of that size" in t for t in text) and not any(
        "10<sup>12</sup>" in t for t in text
    )
    # 6: the power-of-two ranges of the float32 drift, as the held text says
    sums = {k: ns.rounded_by[ns.binade == k].sum() for k in range(5, 10)}  # 32 ... 512
    assert np.sign(sums[7]) == np.sign(sums[8]) == -np.sign(sums[9])  # 128-512: the other way
    assert 0.15 < -ns.back / sums[9] < 0.25 and np.isclose(ns.back, sums[7] + sums[8])
    assert all(abs(sums[k]) < abs(sums[7]) / 8 for k in (5, 6))  # below 128: far less
    held = next(t for t in text if t.startswith("q_drift.hold()") and "Markdown(" in t)
    held = " ".join(re.sub(r'"\s*"', "", held).split())
    assert "give about a fifth of it back" in held and "lower ranges" not in held
    # 7, 9, 10
    md = " ".join(" ".join(t.split()) for c, t in zip(cells, text) if c["cell_type"] == "markdown")
    code = " ".join(t for c, t in zip(cells, text) if c["cell_type"] == "code")
    assert "best plane" not in md + code and "least-squares plane" in md and "least-squares" in code
    for name in ("`flat`", "`nointerpolation`", "`noperspective`", "*provoking vertex*",
                 "§13.6 *Flatshading*", "`GL_LAST_VERTEX_CONVENTION`", "*leading vertex*",
                 "`VK_EXT_provoking_vertex`", "§4.5 *Interpolation Qualifiers*"):  # fmt: skip
        assert name in md, name
    longest = max(_paragraphs(cells), key=lambda p: len(p.split()))
    assert len(longest.split()) <= 150, longest[:80]


def test_03_r216_snapping_is_for_coverage_and_the_digits_of_d():
    """r216 03: 1 (C): GPUs snap for exact edge functions (coverage, lesson 06 §3); r226 F1:
    Direct3D sets the attributes up from the snapped positions (D3D11.3 §3.2.4), llvmpipe and
    tr.render from the unsnapped ones; 2: 16 digits of 10^13 is 10^-3 per term (half the
    gap), and D's printed 2e-4 is what their partial cancellation leaves; 4: window depth is
    itself an f/w; 7: a minus sign, not a hyphen."""
    import json

    ns = lesson("03_barycentric_and_plane_equations")
    path = NOTEBOOK_DIR / "03_barycentric_and_plane_equations.ipynb"
    cells = json.loads(path.read_text())["cells"]
    md = " ".join(
        " ".join("".join(c["source"]).split()) for c in cells if c["cell_type"] == "markdown"
    )
    assert "That is why GPUs snap" not in md and "as they are on a snapped grid" not in md
    assert "decides **coverage** there" in md and "lesson 06 §3" in md
    # r226 F1: no "GPUs set up from the unsnapped positions"; llvmpipe's choice, named as its
    assert "The attributes are set up in floating point from the *unsnapped*" not in md
    assert (
        "**llvmpipe**, and with it `tr.render`, sets up the attributes from the *unsnapped*" in md
    )
    assert "exact (this experiment's quarter-pixel grid)" in md
    # 2: per term up to half the gap near 10^13 (10^-3); D off by the printed 2.0e-04
    assert _decade(ns.far_gap[ns.far_gap_at] / 2) == -3
    # printed() writes it to one digit, as "2·10⁻⁴"
    assert f"{abs(ns.far_D_error):.1e}" == "2.0e-04" and f"{abs(ns.far_D_error):.0e}" == "2e-04"
    assert abs(ns.far_D_error) < ns.far_gap[ns.far_gap_at] / 2  # less than one term's rounding
    code = " ".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    # r380 S3: told once, in the text under the figure (q_far's explanation points to it)
    assert code.count("{printed(far_D_error)}") == 1 and "keeps about 16 digits, so D" not in code
    # 4: the summary's "only f/w and 1/w" and section 3's window depth agree
    assert md.count("$z_\\text{ndc} = z_\\text{clip}/w$ is itself an $f/w$") == 2
    # 7
    assert ns.far_sum < 0 and ns.far_sum_text == f"−{abs(ns.far_sum):.0f}"


def test_03_r226_direct3d_sets_up_from_snapped_positions_in_float32():
    """r226 03: F1: the Direct3D 11.3 functional specification, quoted as it reads, sets up the
    attribute interpolators from the snapped positions, in float32; its case measured: float32
    within a 16 384-px target, where the absolute form misses by more than 1 and the recentred
    one stays within a few steps. C2: the sum printed is A x + B y + D (near -619), not its
    negation."""
    import json
    import re

    ns = lesson("03_barycentric_and_plane_equations")
    path = NOTEBOOK_DIR / "03_barycentric_and_plane_equations.ipynb"
    cells = json.loads(path.read_text())["cells"]
    md = " ".join(
        " ".join("".join(c["source"]).split()) for c in cells if c["cell_type"] == "markdown"
    )
    # the specification's words (microsoft/DirectX-Specs, d3d/archive/D3D11_3_FunctionalSpec.htm)
    quote = (
        "Post-clipped vertex positions in the rasterizer are snapped to fixed point, to uniformly "
        "distribute precision across the RenderTarget area. Many rasterizer operations, including "
        "face culling as one example, occur on fixed point snapped positions, while other "
        "operations, such as attribute interpolator setup, use positions that have been "
        "converted back to floating point from the fixed point snapped positions."
    )
    assert quote in md.replace("> ", "") and "§3.2.4 *Fixed Point Integers*" in md
    assert "§15.16.2" in md and "16.8 fixed point, §15.16 *Rasterizer Precision*" in md
    # float32: §15.16.2 sends the interpolators to §3.1's rules, whose overview (§3.1.1, not
    # the 16- and 64-bit formats of §3.1) puts every computation under IEEE 754 single
    # precision (review r320 S7); §5.9.1.2's words on its interpolators beside it
    assert '"follow the Floating Point Rules (3.1)" (§15.16.2), under which' in md
    assert '32-bit single precision floating point behavior" (§3.1.1;' in md
    assert '"single precision floating point texture coordinates (and the associated' in md
    assert "read literally" in md.lower() and "`subPixelPrecisionBits`" in md
    # the float32 table: Direct3D's largest render target, offsets on its 1/256-px grid
    assert ns.side == 16_384 and ns.offsets32[-1] == ns.side - 16
    on_grid = [(ns.local + off) * 256 for off in ns.offsets32]
    assert all(np.array_equal(units, np.round(units)) for units in on_grid)
    assert 1.0 < ns.absolute32[-1] < 2.0 and 0.05 < ns.absolute32[-2] < 0.2
    assert max(ns.recentred32) < 4 * ns.float32_gap  # "within 3.1 float32 steps" (r330 C1)
    assert round(max(ns.recentred32) / ns.float32_gap) == 3
    code = " ".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    assert "dtype=np.float32" in code and "Evaluating $Ax + By + D$ then adds" in code
    assert "Evaluating $-(Ax + By + D)$ then adds" not in code
    assert ns.far_sum < 0  # the sum printed, and quoted as −619, is A x + B y + D itself
    held = next(
        "".join(c["source"]) for c in cells if "Evaluating $Ax + By + D$" in "".join(c["source"])
    )
    assert "negated and divided by $C$" in re.sub(r'"\s*f?"', "", held)


def test_03_r226_shared_edge_why_triangles_and_the_shaders_derivatives():
    """r226 03: M1: two triangles sharing an edge agree along it (C0) and the slope jumps
    across it; M2: three points fix a plane, four do not (CS148), so a quad's shading depends
    on its diagonal; M3: for an affine attribute ddx, ddy are (g_x, g_y), for a perspective-
    correct one they vary; S3: the helper pixels read f inside the vertex range; C1: the loop
    the note means is shown; S1: where the gradients are measured; S2: three decimals."""
    import json

    ns = lesson("03_barycentric_and_plane_equations")
    path = NOTEBOOK_DIR / "03_barycentric_and_plane_equations.ipynb"
    cells = json.loads(path.read_text())["cells"]
    md = " ".join(
        " ".join("".join(c["source"]).split()) for c in cells if c["cell_type"] == "markdown"
    )
    # M1: C0 along the shared edge, the slope along it equal, across it not
    assert ns.seam < 1e-15
    (along_1, along_2), (across_1, across_2) = ns.slopes
    assert abs(along_1 - along_2) < 1e-15 and abs(across_1 - across_2) > 0.1
    assert np.sign(across_1) != np.sign(across_2)  # the crease: f falls, then rises
    assert "the slope of $f$ jumps" in md and "Mach bands" in md
    # M2: the fourth value off the plane; the two splits of the quad disagree
    assert abs(ns.pair_planes[0](*ns.v4) - ns.f4) > 0.5
    assert abs(ns.pair_planes[0](*ns.cross) - ns.other_split(*ns.cross)) > 0.5
    assert "This isn't true for 4 points\" (the CS148 notes, *Why Triangles?*)" in md
    # M3: the shader's derivatives
    assert ns.ddx_error < 1e-15 and ns.ddy_error < 1e-15
    assert ns.ddx_u.max() > 2 * ns.ddx_u.min() > 0
    assert "a one-pixel difference *is* the gradient" in md
    # S3: the helper pixels read f among the vertex values; f leaves them farther out
    assert not (ns.beyond & ns.helpers).any() and ns.beyond.sum() == 60
    # C1: the loop shown, with x stepped in the inner loop and the row start named once
    loop = md.split("```c")[1].split("```")[0]
    assert "x++" in loop and "y++) { Colour tempColour = initialCol;" in loop
    assert "initialColour" not in loop and "xmin" not in loop and "The loop below" not in md
    # S1: the gradient measured from p, g_0 at the origin
    assert (
        "measured at the origin and one pixel away" not in md
        and "(the cell above's `gradient`)" in md
    )
    # S2: the area figure's weights to three decimals, which sum to 1
    import teachraster as tr

    assert round(sum(round(float(w), 3) for w in tr.barycentric(ns.xy, ns.p_out)), 3) == 1.0
    assert "{weight:.3f}" in "".join(
        next(c["source"] for c in cells if c.get("id") == "c02a-areas")
    )
    # S4: the qualifiers' table after the caveat (section 3), not in section 2's stepping
    text = ["".join(c["source"]) for c in cells]
    table = next(i for i, t in enumerate(text) if "| `noperspective` | `noperspective` |" in t)
    caveat = next(i for i, t in enumerate(text) if "### Caveat: a plane over the screen" in t)
    four = next(i for i, t in enumerate(text) if t.startswith("## 4."))
    assert caveat < table < four


def test_03_r258_true_colours_rules_table_and_what_the_shader_receives():
    """r258 03: FIG1: the plane beyond the triangle keeps its true colours (no veil), coverage
    drawn as a staircase; M1: the rules table, GL / D3D / Vulkan / llvmpipe / teachraster with
    sections; M2: two weights, two multiply-adds per component, and the shorter blended normal."""
    import json

    from notebook_runs import executed, streams

    ns = lesson("03_barycentric_and_plane_equations")
    path = NOTEBOOK_DIR / "03_barycentric_and_plane_equations.ipynb"
    cells = json.loads(path.read_text())["cells"]
    text = ["".join(c["source"]) for c in cells]
    md = " ".join(" ".join(t.split()) for c, t in zip(cells, text) if c["cell_type"] == "markdown")
    printed = streams(executed("03_barycentric_and_plane_equations").notebook())
    # FIG1: no white veil or hatch over the uncovered pixels; the staircase borders the 55
    fig = next(t for t in text if "the plane beyond the triangle" in t)
    assert "facecolor=(1, 1, 1" not in fig and 'hatch="//"' not in fig
    assert "pale and hatched" not in md and "each in its true colour" in md
    edges = {tuple(map(tuple, s)) for s in ns.steps}
    assert len(edges) == len(ns.steps) > 0  # each border side drawn once
    # M1: one row per rule, one column per standard, with sections; r380 FIG1: in two
    # tables, the standards and the two implementations, so that each fits a laptop's column
    table = next(t for t in text if t.startswith("### The rules of this lesson, standard by"))
    headers = [line for line in table.splitlines() if line.startswith("| rule |")]
    assert headers == ["| rule | OpenGL 4.6 (GLSL 4.60) | Direct3D 11 | Vulkan |",
                       "| rule | llvmpipe | teachraster |"]  # fmt: skip
    rows = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    assert [line.count(" | ") for line in rows] == [3] * 5 + [2] * 5
    for cite in ("§14.6.1", "§3.2.4, §3.4.1, §15.16.2", "§13.6 *Flatshading*", "`VK_EXT_provoking_vertex`",
                 "§4.5 *Interpolation Qualifiers*", "*Interpolation Decorations*",
                 "`subPixelPrecisionBits`", "*leading vertex*"):  # fmt: skip
        assert cite in table, cite
    # M2: two weights, two multiply-adds a component: 256 for 32 float4 attributes
    assert ns.shader_gap < 1e-15 and ns.components == 128
    assert np.isclose(ns.lam_i + ns.lam_j + tr_lambda1(ns), 1.0)
    assert "128 components, 256 multiply-adds a pixel" in printed
    assert "`v_interp_p1_f32`" in md and "`BaryCoordNoPerspAMD`" in md
    # r277 F1: (I, J) are in the hardware's vertex order (v1 first is our assumption), and the
    # two instructions are GCN to RDNA 2's
    assert "the hardware's own vertex order" in md and "from GCN to RDNA 2" in md
    # the blended unit normals are shorter than 1: Phong shading renormalises
    assert 0.85 < ns.lengths.min() < ns.lengths.max() < 1.0
    assert f"{ns.lengths.min():.3f} to {ns.lengths.max():.3f}" in printed
    # no printed line wider than 80 columns
    assert max(len(line) for line in printed.splitlines()) <= 80


def tr_lambda1(ns) -> float:
    """λ1 at the lesson's point p, the weight a GPU does not send."""
    import teachraster as tr

    return float(tr.barycentric(ns.xy, ns.p)[0])


def test_03_r320_every_table_cell_cites_and_the_sheet_is_a_prediction():
    """r320 03: M1: each cell of the standards table names its section or source: Direct3D's
    leading vertex (D3D11.3 §8.14) and its pixel centre (§3.5.5), the llvmpipe cells (a Mesa
    file or the course's own measurement), Vulkan's single-sample centre; M2: where the curved
    sheet rises above the affine plane is asked (q_sheet, a PredictPixels) before the view and
    the text that say it, which are held; S1: section 1's formula cell shown, its plots folded;
    S3, S4: superscripts and minus signs."""
    import json
    import re

    from notebook_runs import executed, streams

    import teachraster as tr

    ns = lesson("03_barycentric_and_plane_equations")
    path = NOTEBOOK_DIR / "03_barycentric_and_plane_equations.ipynb"
    cells = json.loads(path.read_text())["cells"]
    text = ["".join(c["source"]) for c in cells]
    by_id = {c["id"]: t for c, t in zip(cells, text)}
    table = by_id["c03-rules-table"]
    lines = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    standards = [line.split(" | ")[1:] for line in lines[1:5]]  # r380 FIG1: two tables
    llvmpipe = [line.split(" | ")[1] for line in lines[6:]]
    for cell in [c for row in standards for c in row] + llvmpipe:  # each cites
        assert re.search(r"§\d|\*[A-Z][^*]+\*|`[\w.]+\.c`|`tests/", cell), cell
    for cite in ("§8.14 *Leading Vertex*", "§3.5.5", "`lp_state_setup.c`", "`lp_bld_interp.c`",
                 "`test_attributes_follow_the_unsnapped_vertices`", '"the center of the fragment area"',
                 "the GL–Direct3D difference cannot be shown here"):  # fmt: skip
        assert cite in table, cite
    assert "dcl_input" not in table and "anywhere within the fragment" not in table
    # M2: the answer is the package's, on v2's side of the line from v3 to e (affine f = f3)
    assert ns.w_far == 8.0 and ns.above_affine.sum() == 32 and ns.below_affine.sum() == 23
    assert ns.sheet_covered.sum() == 55 and np.isclose(ns.e_along, 3 / 7)
    lam = tr.barycentric(ns.xy, np.column_stack([np.nonzero(ns.sheet_covered)[1] + 0.5,
                                                 np.nonzero(ns.sheet_covered)[0] + 0.5]))  # fmt: skip
    edge_value = (lam[:, 0] * ns.f[0] + lam[:, 1] * ns.f[1]) / (lam[:, 0] + lam[:, 1])
    assert np.array_equal(edge_value > ns.f[2], ns.above_affine[ns.sheet_covered])
    ids = [c["id"] for c in cells]
    ask = ids.index("q-sheet")
    # its explanation's numbers: the counts, and where the rise is largest (x, y of the centre)
    assert 'explain=f"{above_affine.sum()} of the {sheet_covered.sum()} covered pixels' in (
        " ".join(text[ask].split())
    )
    assert (ns.rise_at[1] + 0.5, ns.rise_at[0] + 0.5) == (6.5, 10.5)
    assert ids[ask + 1 : ask + 3] == ["c18c-surfaces", "c18c-surfaces-held"]
    assert all(text[k].startswith("q_sheet.hold()") for k in (ask + 1, ask + 2))
    assert "PredictPixels(" in text[ask] and "answer=above_affine" in text[ask]
    before = " ".join(text[:ask])
    assert "sags" not in before and "bulges" not in before and "sags *below*" in text[ask + 2]
    printed = streams(executed("03_barycentric_and_plane_equations").notebook())
    assert "f above the affine plane at 32, below at 23" in printed
    assert f"largest rise {np.nanmax(ns.sheet_gap):.3f}" in printed
    # S1: the formula cell shown, the plotting cells folded; p's formula still held and folded
    assert not cells[ids.index("c03")]["metadata"].get("jupyter")
    for cid in ("c02a-areas", "c06", "c78ad05a", "c09b-shared-edge", "c03-point-held"):
        assert cells[ids.index(cid)]["metadata"]["jupyter"]["source_hidden"] is True, cid
    # S3, S4
    assert "<sup>" not in by_id["recentre_predict"].split("explain=")[0]
    assert "direct, −(Ax + By + D)/C" in printed and "absolute −(Ax+By+D)/C" in printed
    assert "attribute values −2.9 to 7.3" in printed
