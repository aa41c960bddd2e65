"""r148 (exercise 12, the capstone, a fresh read): each defect, as a class, with a test that
fails on the code before the fix."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import reasoning_solutions as sol

import teachraster.core.barycentrics as core_barycentrics
import teachraster.exercises.capstone_glass as capstone_glass
import teachraster.pipeline.texturing.texel_fetch as texel_fetch
from teachraster import edge_function, linear_to_srgb, srgb_to_linear
from teachraster import exercises as ex
from teachraster.core.edges import is_top_left, setup_edges
from teachraster.exercises.capstone_render import SCENES, _frame
from teachraster.exercises.checks import check

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/12_capstone.ipynb"


def _mine(scene, **changed):
    return {name: changed.get(name, sol.CAPSTONE[name]) for name in SCENES[scene].uses}


def _winding(sign):
    """A covers that accepts only triangles whose E(v1, v2, v3) has ``sign``."""

    def covers(xy, p):
        if np.sign(edge_function(*np.asarray(xy, float))) != sign:
            return False
        return sol.covers(xy, p)

    return covers


# -- D12-1: the grid holds both windings, as its title says ------------------------------------


def test_the_grid_holds_both_windings_and_covers_every_centre_once():
    frame = _frame(SCENES["grid"])
    windows = frame.trace.window[:, :, :2]
    signs = {int(np.sign(edge_function(*w))) for w in windows}
    assert signs == {-1, 1}
    assert "both windings" in SCENES["grid"].words
    assert np.max(frame.overlay("overdraw")) == 1


@pytest.mark.parametrize("sign", [-1, 1])
def test_a_covers_of_one_winding_fails_the_grid_on_its_own_pixels(sign):
    report = ex.capstone("grid", covers=_winding(sign))
    assert not report.passed
    assert report.n_wrong > 0, str(report)  # seen by the scene, not only by the fallback
    assert "no edge through one of its centres is horizontal" not in str(report)


def test_a_blind_spot_reason_is_not_given_to_an_exception():
    def raises_on_flat_ties(xy, p):  # no centre of the grid lies on a horizontal edge
        xy = np.asarray(xy, float)
        if any(xy[k, 1] == xy[k - 1, 1] == p[1] for k in range(3)):
            raise IndexError("boom")
        return sol.covers(xy, p)

    report = ex.capstone("grid", covers=raises_on_flat_ties)
    assert not report.passed and "raised IndexError" in str(report)
    assert "horizontal" not in str(report)


# -- D12-2: rounded weights are not a number added to E ------------------------------------------


def test_rounded_weights_are_told_rounded_not_an_added_area_constant():
    report = ex.capstone(
        "single_triangle", barycentric=lambda xy, p: np.round(sol.barycentric(xy, p), 5)
    )
    text = str(report)
    assert not report.passed
    assert "added a small number" not in text
    assert "rounded to 5 decimals" in text


def test_a_weight_error_of_no_common_scale_is_not_told_an_added_constant():
    def skewed(xy, p):
        return np.asarray(sol.barycentric(xy, p)) * (1 + np.array([3e-6, -3e-6, 1e-6]))

    text = str(ex.capstone("single_triangle", barycentric=skewed))
    assert "added a small number" not in text
    # r164 B4: exercise 3.1 no longer names an ε fitted case by case, so the capstone's
    # "not by one common factor" (said against that ε) has nothing to answer: the rule
    assert "constant factor" not in text
    assert "the weights rebuild p" in text or "λ_i = E of the edge opposite" in text, text


def test_the_barycentric_exercise_tells_rounding_not_an_added_constant():
    report = check("barycentric", lambda xy, p: np.round(sol.barycentric(xy, p), 5))
    assert not report.passed
    assert report.failures[0].kind == "rounded"
    assert "added a small number" not in str(report)


def test_a_real_added_constant_is_still_named():
    def guarded(xy, p):
        a, b, c = np.asarray(xy, float)
        p = np.asarray(p, float)
        area = edge_function(a, b, c) + 1e-4
        return (
            np.array([edge_function(b, c, p), edge_function(c, a, p), edge_function(a, b, p)])
            / area
        )

    assert check("barycentric", guarded).failures[0].kind == "epsilon added to the area"


def test_a_right_float32_barycentric_is_still_told_float32():
    def f32(xy, p):
        return np.asarray(sol.barycentric(np.asarray(xy, np.float32), np.asarray(p, np.float32)),
                          np.float32)  # fmt: skip

    report = ex.capstone("single_triangle", barycentric=f32)
    assert report.passed and "float32" in str(report)


# -- D12-3: a resolve averaging sRGB values is named -------------------------------------------


def _srgb_resolve(codes: bool):
    def resolve(colours, ids, background):
        colours, background = np.asarray(colours, float), np.asarray(background, float)
        shares = [linear_to_srgb(colours[k] if i >= 0 else background) for k, i in enumerate(ids)]
        if codes:
            return srgb_to_linear(np.mean(np.round(np.array(shares) * 255), axis=0) / 255)
        return srgb_to_linear(np.mean(shares, axis=0))

    return resolve


@pytest.mark.parametrize("codes", [False, True])
def test_a_resolve_averaging_srgb_is_told_so(codes):
    report = ex.capstone("cube_msaa", **_mine("cube_msaa", resolve=_srgb_resolve(codes)))
    text = str(report)
    assert not report.passed
    assert "averaged in sRGB instead of linear light" in text
    assert "where no triangle covered the sample" not in text


# -- D12-4: a_buffer on stacks of three and four fragments -------------------------------------


def _previous_alpha(depths, colours, background):  # each fragment by the previous one's α
    acc, prev = np.zeros(4), 0.0
    for k in np.argsort(depths):
        c = np.asarray(colours[k], float)
        acc, prev = acc + (1 - prev) * c, c[3]
    return acc + (1 - acc[3]) * np.asarray(background, float)


def test_an_a_buffer_weighting_by_the_previous_alpha_fails_and_is_named():
    report = ex.capstone("glass_sorted", over=sol.over_premultiplied, a_buffer=_previous_alpha)
    assert not report.passed
    assert "just in front of it" in str(report)


def test_the_a_buffer_stacks_hold_three_and_four_fragments_and_a_right_one_passes():
    assert {len(d) for d, _ in capstone_glass.OWN_STACKS} >= {3, 4}
    for (
        depths,
        colours,
    ) in capstone_glass.OWN_STACKS:  # the package's resolve is right on them: the reference
        out = capstone_glass.package_resolve(np.array(depths), np.array(colours), np.ones(4))
        assert 0 <= out[3] <= 1 + 1e-12
    assert ex.capstone("glass_sorted", **_mine("glass_sorted")).passed


# -- D12-5: the package's internals are not the student's work ---------------------------------


def _bilinear_from_corner(texture, uv, wrap):
    t = np.asarray(texture, float)
    h, w = t.shape[:2]
    x0, y0, fx, fy = texel_fetch.bilinear_corner(np.array([float(uv[0])]),
                                                 np.array([float(uv[1])]), h, w)  # fmt: skip
    x0, y0, fx, fy = int(x0[0]), int(y0[0]), float(fx[0]), float(fy[0])
    at = lambda r, c: t[r % h, c % w]  # noqa: E731
    return (at(y0, x0) * (1 - fx) * (1 - fy) + at(y0, x0 + 1) * fx * (1 - fy)
            + at(y0 + 1, x0) * (1 - fx) * fy + at(y0 + 1, x0 + 1) * fx * fy)  # fmt: skip


def _bilinear_blended(texture, uv, wrap):
    t = np.asarray(texture, float)
    h, w = t.shape[:2]
    x, y = uv[0] * w - 0.5, uv[1] * h - 0.5
    x0, y0 = int(np.floor(x)), int(np.floor(y))
    at = lambda r, c: t[r % h, c % w]  # noqa: E731
    return texel_fetch._bilinear_blend(at(y0, x0), at(y0, x0 + 1), at(y0 + 1, x0),
                                       at(y0 + 1, x0 + 1), x - x0, y - y0)  # fmt: skip


@pytest.mark.parametrize("fn, name", [(_bilinear_from_corner, "bilinear_corner"),
                                      (_bilinear_blended, "_bilinear_blend")])  # fmt: skip
def test_bilinear_from_the_texel_fetch_helpers_is_not_counted(fn, name):
    report = ex.capstone("floor_bilinear", bilinear=fn)
    assert not report.passed
    assert f"calls teachraster's {name}" in str(report)


def test_barycentric_from_the_core_module_and_covers_from_its_tie_rule_are_not_counted():
    def from_edges(xy, p):  # the core's own weights from edge values of the student's
        s = setup_edges(np.asarray(xy, float), None)
        e = [edge_function(s.p[k], s.p[(k + 1) % 3], np.asarray(p, float)) for k in range(3)]
        return core_barycentrics.barycentric_from_edges(s, np.array([e]))[0]

    report = check("barycentric", from_edges)
    assert not report.passed and "barycentric_from_edges" in str(report)

    def tie_by_package(xy, p):
        is_top_left(np.asarray(xy[0], float), np.asarray(xy[1], float))
        return sol.covers(xy, p)

    report = check("covers", tie_by_package)
    assert not report.passed and "is_top_left" in str(report)


# -- D12-6: covers at the sample positions of the MSAA scene -----------------------------------


def test_the_msaa_scene_asks_covers_at_its_sample_positions():
    assert "covers" in SCENES["cube_msaa"].uses

    def at_centre(xy, p):
        return sol.covers(xy, (np.floor(p[0]) + 0.5, np.floor(p[1]) + 0.5))

    report = ex.capstone("cube_msaa", covers=at_centre, resolve=sol.resolve)
    assert not report.passed
    assert "sample coverage" in str(report)
    # r453 WP1: exercise 1's own check now asks covers off the centres and names this itself
    said = str(report)
    assert "as at the pixel's centre" in said or "you tested the centre of p's pixel" in said
    assert ex.capstone("cube_msaa", covers=sol.covers, resolve=sol.resolve).passed


def test_the_notebook_hands_covers_to_the_msaa_scene():
    cells = ["".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]]
    assert any('ex.capstone("cube_msaa", covers=covers, resolve=resolve)' in c for c in cells)


# -- D12-7: the tolerance's words, one paragraph per stage, Run All, the figure's key ----------


def test_one_mistake_is_explained_once_per_scene():
    report = ex.capstone("single_triangle",
                         barycentric=lambda xy, p: np.roll(sol.barycentric(xy, p), 1))  # fmt: skip
    text = str(report)
    assert text.count("the package's weights are") == 1
    assert "too (report.explain_pixel" in text


def test_the_tolerance_is_not_called_float32s_rounding():
    import teachraster.exercises.capstone_render as render

    source = Path(render.__file__).read_text()
    assert "How close a compared value must be: float32's rounding" not in source
    assert "17 half-ulps" in source


def test_the_intro_tells_to_run_the_scenes_one_at_a_time():
    intro = "".join(json.loads(NOTEBOOK.read_text())["cells"][0]["source"])
    assert "Run All" in intro and "one at a time" in intro


def test_the_difference_panel_has_a_key_and_a_larger_outline(plt):
    report = ex.capstone("grid", covers=_winding(-1))
    fig, axes = plt.subplots(1, 3)
    report.compare(axes)
    assert "red: differs, grey: matches" in axes[2].get_xlabel()
    widths = [max(line.get_xdata()) - min(line.get_xdata()) for line in axes[2].get_lines()]
    assert max(widths) >= 5
