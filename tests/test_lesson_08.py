"""Lesson 08 (antialiasing): what it shows, read from the one execution every notebook test
shares (``tests/notebook_runs.py``; it used to execute the lesson a second time here)."""

import numpy as np
import pytest
from notebook_runs import lesson

import teachraster as tr

pytestmark = pytest.mark.notebook


@pytest.fixture(scope="module")
def ns():
    return lesson("08_antialiasing")


def test_lesson_08_shows_what_it_says(ns):
    assert float(ns.area.sum()) == pytest.approx(
        abs(tr.Triangle(tr.snap(ns.xy)).signed_area), abs=1e-9
    )
    assert ns.sliver_1.coverage.sum() == 0 < ns.sliver_4.coverage.sum()  # vanishes, appears
    assert ns.shaded_ssaa > 2 * ns.shaded_msaa  # supersampling shades per sample
    assert 0.75 not in ns.levels["ordered grid"]
    assert ns.levels["rotated grid (standard)"] == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert (ns.count > 1).sum() == 0 and (ns.count == 1).sum() > 100  # watertight per sample
    assert ns.v_centre.min() < 0 or ns.v_centre.max() > 1  # extrapolated at the centres
    assert 0 <= ns.v_centroid.min() and ns.v_centroid.max() <= 1  # centroid stays inside
    assert ns.gif.stat().st_size > 1000
    plan = ns.frames[4].plan["multisampling"]
    assert 0 < plan.count < plan.total
    # cell 23: MSAA shades once per pixel and triangle; the plan printed under it agrees
    assert "shaded once per triangle and pixel" in plan.why and "shading per" not in plan.why
    # review r61 08-1: the printed counts are the GPU's story (every sample tested, the
    # uniform pixels compressed); review r136 08-8: the simulator's shortcut is not printed
    assert "a GPU tests every sample" in ns.gpu and not hasattr(ns, "ours")
    # review r129 08-1: the GPU's counts read from the frame's samples (one triangle in front
    # at all 4, or not); the plan (not printed) works per sample at every mixed pixel
    ids = ns.frames[4].sample_triangle_id
    one = (ids >= 0).all(-1) & (ids == ids[..., :1]).all(-1)
    assert ns.n_covered == plan.total == int((ids >= 0).any(-1).sum())
    assert ns.uniform == int(one.sum()) > ns.mixed == plan.total - ns.uniform > 0
    assert ns.partial == int(((ids >= 0).any(-1) & (ids < 0).any(-1)).sum()) < ns.mixed
    t = tr.render(tr.get_scene("cube"), None, 96, 72, samples=4, trace=True).trace
    worked = np.zeros(ids.shape[:2], bool)
    worked[t.fragment_row[t.fragment_sample >= 0], t.fragment_col[t.fragment_sample >= 0]] = True
    assert int(worked.sum()) == plan.count >= ns.mixed
    assert (worked | ~(ids >= 0).any(-1))[~one].all()  # every mixed pixel was worked per sample
    gpu = " ".join(ns.gpu.split())
    assert f"At {ns.uniform} of them one triangle is in front at all 4 samples" in gpu
    assert f"At the other {ns.mixed} the samples show two triangles" in gpu
    assert f"({ns.partial} of them are partly covered)" in gpu
    assert "can differ" not in gpu and "reached by two or more" not in gpu
    assert "might be in front in part of the pixel" in plan.why and "2+ triangles:" not in plan.why
    # §2: only partly covered pixels differ, by at most the samples' mean off the centre
    # times u's gradient; MSAA stores S colours and S depths per pixel
    assert ns.gap_full < 1e-12 and 0 < ns.gap_u
    u = tr.attribute_plane(tr.snap(ns.xy), [0.0, 1.0, 0.0])
    grad = float(np.hypot(u(1.0, 0.0) - u(0.0, 0.0), u(0.0, 1.0) - u(0.0, 0.0)))
    assert ns.gap_u <= ns.off_centre * grad + 1e-12
    assert ns.off_centre == pytest.approx(np.hypot(0.125, 0.375))  # one sample alone
    # cell 18: the covered samples outside the octagon's open inside lie on its own edges
    assert ns.extra.sum() >= 1 and ns.on_outer[ns.extra].all()
    # review r42 (r35 08-3): the 20 samples on the fan's spokes, printed, each covered once
    assert ns.on_spoke.sum() == 20 and (ns.count[ns.on_spoke] == 1).all()
    err = {f"{r['kind']}{r['samples']}": r["mean_error"] for r in ns.rows}
    assert err["standard16"] < err["standard4"] < err["standard1"]


def test_lesson_08_pattern_rows_figure(ns):
    # §7: the 8-sample rows are centred in strips of 1/8 (1/16 … 15/16), the 16-sample rows
    # start at the pixel's top edge (0, 1/16 … 15/16), as its text and the figure's titles say
    assert np.allclose(ns.pattern_rows[8], (2 * np.arange(8) + 1) / 16)
    assert np.allclose(ns.pattern_rows[16], np.arange(16) / 16)


def test_lesson_08_inspector_reads_sixteen_samples(ns):
    # the lesson's inspector, driven as a student would (the lesson no longer does it)
    from teachraster.widgets import PixelInspector

    inspector = PixelInspector(ns.tri, ns.W, ns.H, row=3, col=13)
    inspector.pattern.value = "16 standard"
    inspector.row.value, inspector.col.value = 3, 16
    assert "of 16 covered" in inspector.pixel.square.axes.get_title()
    assert inspector.table.value.count("<tr>") == 17  # every sample's edge values


def test_lesson_08_review_r26_wording_and_held_answers():
    """Review r26, 08: the centroid rule stated once (cell 19 read alone gave another rule);
    teachraster is no conformant implementation; the text saying how many levels the standard
    pattern gives is held with q_levels' figure, not a Markdown cell on screen before Check;
    the sliver question does not draw the samples whose coverage it asks about; why deferred
    renderers left MSAA for TAA."""
    import json
    from pathlib import Path

    cells = json.loads((Path(__file__).resolve().parents[1] / "notebooks" /
                        "08_antialiasing.ipynb").read_text())["cells"]  # fmt: skip
    md = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")
    code = ["".join(c["source"]) for c in cells if c["cell_type"] == "code"]
    flat = md.replace("\n", " ")
    # review r230 S3: Direct3D 11's functional spec fixes the rule (llvmpipe's); teachraster's
    # is one GL and Vulkan allow
    assert "conforming" not in flat and "differs in one case, which GL and Vulkan allow too" in flat
    assert "teachraster: the covered sample nearest the centre)" not in flat
    # review r240 S: Direct3D 11's rule is the one taught (§5 and the summary); teachraster's
    # variant, which keeps a covered centre, is one sentence and a row of the folded table
    words = " ".join(flat.split())
    assert words.count("the centre if every sample is covered, else the first covered") == 1
    assert "a partly covered pixel whose centre is covered keeps the centre" in words
    assert words.count("the centre when it is covered") == 1  # the table's teachraster row
    assert "levels (a **rotated grid**" not in flat  # (the summary, far below, says five)
    # review r245 S3: the held text names the property (n-rooks) and the rotated grid apart
    (held,) = [c for c in cells if "like n rooks on a chessboard" in "".join(c["source"])]
    assert "".join(held["source"]).startswith("q_levels.hold()")  # a code cell, held,
    assert held["metadata"]["jupyter"]["source_hidden"]  # its source collapsed as the question's
    sliver = next(c for c in code if "def draw_sliver" in c)
    # review r69 08-1: row 1's upper half (two sample rows) is left out of the picture and the
    # question, so the student finds which sample row lies inside the sliver
    assert "shown = ~((rows == 1) & (offsets4[s, 1] < 0.5))" in sliver
    # (r475 S7: the prompt shortened to what the figure does not show)
    assert "in the pixels' upper half (y from 1 to 1.5) are not drawn" in " ".join(sliver.split())
    assert "in row 1 the samples at y =" not in sliver
    # review r327 S2: the coordinate conventions are the axes' labels, not the question's text
    assert "(y grows downward, " not in sliver
    assert sliver.count('ax.set(xlabel=PIXEL_BORDERS, ylabel="y, down")') == 1
    assert "deferred shading" in flat and "G-buffer" in flat


def test_lesson_08_cells_name_no_review():
    """Review r29, 08-3: code comments cited "review r9", "review r26", which students cannot
    place; the cells say why, the review ids stay in the tests."""
    import json
    import re
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb"
    for k, cell in enumerate(json.loads(path.read_text())["cells"]):
        assert not re.search(r"\breviews? r\d", "".join(cell["source"])), k
    # review r29, 08-4: the line style of cell 29 no longer rebinds cell 1's `style`
    assert 'style = "s--"' not in path.read_text()


def test_lesson_08_centroid_prediction(ns):
    """Review r42 08-8: a prediction in §5, asked before the figure and the ranges that answer
    it (held), with its answer and explanation computed from the lesson's own triangle."""
    import json
    from pathlib import Path

    assert len(ns.covered) == 1 and ns.side == "above 1" and ns.v_at_centre > 1
    assert ns.v_at_centre == pytest.approx(ns.h_centre / ns.h_vertex, rel=1e-9)
    assert "answer=v_at_centre,\n    tolerance=0.1," in "".join(
        "".join(c["source"])
        for c in json.loads(
            (
                Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb"
            ).read_text()
        )["cells"]
    )
    cells = json.loads((Path(__file__).resolve().parents[1] / "notebooks" /
                        "08_antialiasing.ipynb").read_text())["cells"]  # fmt: skip
    sources = ["".join(c["source"]) for c in cells]
    (k,) = [i for i, s in enumerate(sources) if "q_centre = Predict(" in s]
    assert sources[k + 1].startswith("q_centre.hold()")
    assert not any("v at the pixel centres" in s for s in sources[:k])
    # review r61 08-5: nothing before the question says the centre value leaves [0, 1]
    assert not any("extrapolated" in s for s in sources[:k])


def test_lesson_08_review_r81_section_7_text_matches_its_chart(ns):
    """Review r81 08-1/2: cell 32 said the 16-sample pattern falls like 1/S on axis edges (its
    error times S doubles from 8 to 16), and cell 29 gave one S range for every series."""
    import json
    from pathlib import Path

    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    text = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")
    assert "8- and 16-sample patterns are" not in text
    assert "2-, 4- and 8-sample patterns" in text and "it does not continue the line" in text
    std = ns.standard_axis
    assert std[16] * 16 > 1.5 * std[8] * 8  # 16 does not fall like 1/S from 8
    # "S = 4 to 256; the standard patterns ... 2 to 16", as the chart draws them
    counts = {}
    for row in ns.edge_rows:
        counts.setdefault(row["kind"], []).append(row["samples"])
    assert all((min(v), max(v)) == (4, 256) for k, v in counts.items() if "standard" not in k)
    assert (min(counts["standard, axis edges"]), max(counts["standard, axis edges"])) == (2, 16)
    assert "$S$ = 4 to 256; the standard patterns" in text and "2 to 16)" in text


def test_lesson_08_review_r92_crawling_edge_and_vertex_names(ns):
    """Review r92 08-1/2/3: with one sample a few pixels switch per frame, never a row (the
    cell prints the counts); the 16-sample tail is dim, not pale; q_centre names the vertices
    v1, v2, v3 and the edge E12, as CONVENTIONS and the figure under it do."""
    import json
    from pathlib import Path

    assert 0 < max(ns.switched) < ns.W // 2 and min(ns.switched) >= 1
    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    sources = ["".join(c["source"]) for c in cells]
    crawl = " ".join(next(s for s in sources if s.startswith("### Crawling edges")).split())
    assert "whole row" not in crawl and "pale" not in crawl and "dim" in crawl
    (ask,) = [s for s in sources if "q_centre = Predict(" in s]
    assert "vertex 0" not in ask and "vertex 2" not in ask
    assert "the edge E12" in ask and "v3 lies" in ask
    assert not any("where it is written" in s for s in sources)  # review r92 08-7: "source"


def test_lesson_08_review_r101_intersection_line_and_held_texts(ns):
    """Review r101 08-A: cell 26 said the upright pair meets along "a pixel boundary (x = 0)";
    world x = 0 lies at window x = 23.5 here, on the centres of column 23, as the text now
    says (and the cell prints). 08-E: §7's random curve is a fresh draw per pixel, not the
    cost of the random pattern's uneven rows."""
    import json
    from pathlib import Path

    assert ns.line_x == 23.5 and ns.line_x % 1 == 0.5  # a column of centres, no boundary
    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    text = " ".join(" ".join("".join(c["source"]) for c in cells).split())
    assert f"at window x = {ns.line_x:g} here" in text and "pixel boundary (x = 0)" not in text
    assert "through the centres of one pixel column" in text
    assert "what that costs" not in text and "what uneven ones cost" not in text


def test_lesson_08_review_r105_prediction_resolve_pixel_and_centred_pattern(ns):
    """Review r105 08-4: §7's "guess which falls fastest" is a Predict, its answer the steepest
    fitted slope, the chart held until Check. 08-1: the 16-sample pattern centred (+1/32 px) is
    printed and beats the grid, as the text quotes. r101/r105 top change 2: one pixel resolved
    as numbers and as light, its numbers printed. 08-3, 08-6: the error maps' outline, and
    Direct3D's reference rasterizer in the centroid table."""
    import json
    from pathlib import Path

    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    sources = ["".join(c["source"]) for c in cells]
    text = " ".join(" ".join(s for c, s in zip(cells, sources)
                             if c["cell_type"] == "markdown").split())  # fmt: skip
    # the prediction: asked before the chart, answered by the fitted slopes the chart prints
    (k,) = [i for i, s in enumerate(sources) if "q_fastest = Predict(" in s]
    assert cells[k]["metadata"]["jupyter"]["source_hidden"]
    # review r147 #9: the answer is a number now, the jittered exponent the chart fits
    # review r171 9: ± 0.05, which tells the answer from the grid's slope and from −0.5, −1
    assert "answer=round(jittered_k, 2)" in sources[k] and "tolerance=0.05" in sources[k]
    assert sources[k + 1].startswith("q_fastest.hold()") and "ax.loglog" in sources[k + 1]
    assert "guess which falls fastest" not in text
    assert "grid" == min(ns.fitted, key=ns.fitted.get)
    for kind, k_fit in ns.fitted.items():
        assert k_fit == pytest.approx(ns.edge_slopes[kind])
    # the centred 16-sample pattern: below the grid, which is below the pattern as it is
    e16, centred = ns.err16, ns.err16_centred
    assert centred < e16["grid"] < e16["standard"] and ns.err4["standard"] < ns.err4["grid"]
    assert f"mean error of {centred:.3f} on these triangles" in text
    assert f"below the grid's {e16['grid']:.3f}" in text and "$1/32$ px" in text
    # "its rows and columns start at the pixel's edge": 0, 1/16, ... 15/16 both ways
    for axis in (0, 1):
        assert np.allclose(np.sort(tr.sample_pattern(16)[:, axis]), np.arange(16) / 16)
    # one pixel of the resolve: 2 of 4 samples on a face; the numbers' mean is the image's
    er, ec = ns.er, ns.ec
    assert int(ns.on_face[er, ec].sum()) == 2
    np.testing.assert_allclose(ns.px_numbers, ns.frame4.image[er, ec])
    np.testing.assert_allclose(ns.px_numbers, ns.px_samples.mean(axis=0))
    assert (ns.px_light >= ns.px_numbers - 1e-12).all() and (ns.px_light > ns.px_numbers).any()
    dark = int(np.argmin(ns.px_samples[ns.on_face[er, ec]][0]))  # the face's darkest channel
    assert ns.px_samples[ns.on_face[er, ec]][0][dark] == 0
    # review r230 C1: the numbers tr.render averages here are sRGB codes
    quoted = f"{ns.px_numbers[dark]:.3f} as codes and {ns.px_light[dark]:.3f} as light"
    assert quoted == "0.500 as codes and 0.735 as light" and quoted in text
    # the error maps outline their triangle; Direct3D's reference rasterizer is quoted
    (maps,) = [s for s in sources if "art = plot_area_error(" in s]
    assert "np.vstack([xy2, xy2[:1]])" in maps
    assert "the first covered sample is chosen, starting from the pixel center" in text


def test_lesson_08_review_r108_fixed_draws_fastest_reasoned_and_figures(ns):
    """Review r108 08-2: §7's second chart measures one fixed draw of the jittered and random
    patterns (the same offsets in every pixel), its first chart a fresh draw per edge; cells 16
    and 37 say so. 08-4: q_fastest gives what to reason with (the crossed cells, coin tosses,
    §3's edge passing samples one at a time). 08-3: the intersection magnified, the line of equal
    depth between the samples each triangle won. 08-5/6/7: the quarter labels at the pixel
    centre, the fading tail, the 16-sample pattern's two samples on the border printed."""
    import json
    from pathlib import Path

    from notebook_runs import executed, streams

    from teachraster.study.antialiasing import sample_error_study

    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    sources = ["".join(c["source"]) for c in cells]
    flat = " ".join(" ".join(sources).split())
    # the second chart's jittered and random: tr.sample_pattern(S, kind), one draw (seed 0)
    for kind in ("jittered", "random"):
        (fixed,) = sample_error_study(size=32, repeat=1, counts=(), kinds=(),
                                      patterns={kind: tr.sample_pattern(4, kind)})  # fmt: skip
        (study,) = [r for r in ns.rows if r["kind"] == kind and r["samples"] == 4]
        assert fixed["mean_error"] == study["mean_error"]
    assert "a fresh draw of samples for each pixel" not in flat
    # review r194 9: said where §7's second chart is, not in §3's held text
    assert "not the fresh draw per edge of §7's first chart" in flat
    assert "are each **one fixed draw** (`tr.sample_pattern(S, kind)`, seed 0)" in flat
    # q_fastest: the reasoning's means are in the question, the answer in neither
    (ask,) = [s for s in sources if "q_fastest = Predict(" in s]
    asked = " ".join(ask.split("answer=")[0].split()).replace('" "', "")
    assert "the edge crosses at most 2√S − 1 of the S cells" in asked
    # review r194 6: the explanation counts the crossed cells as the stem does
    told = " ".join(ask.split("explain=")[1].split()).replace('" "', "")
    assert "of the order of √S (at most 2√S − 1)" in told and "the about √S" not in told
    # review r136 08-1 kept random's S^-1/2 out of the stem, as it gave "slowest" away; r147
    # #9 asks jittered's exponent, a number, and gives random's rate to scale it
    assert "coin tosses" not in asked and "S<sup>−1/2</sup> (the central limit" in asked
    assert "what is k for <b>jittered</b> samples?" in asked
    assert "S^−3/4" not in asked and "S<sup>−3/4" not in asked and "Mitchell" not in asked
    # review r119 08-A: the facts are neutral, no adjective grades the options; the answer is
    # the order of all three (fastest first), which the fitted slopes give
    for graded in ("no chance", "left to chance", "fastest</b>", "only in the cells"):
        assert graded not in asked, graded
    assert ["grid", "jittered", "random"] == sorted(ns.fitted, key=ns.fitted.get)
    # 08-B: exponents in widget HTML are typeset (<sup>), not typed as S^−1/2
    assert "S^−" not in ask and "S^k" not in ask and "S<sup>−1/2</sup>" in ask
    # 08-D: the two S^-1/2 curves, random and the grid on axis edges, coincide: captioned
    assert round(ns.edge_slopes["random"], 1) == round(ns.edge_slopes["grid, axis edges"], 1)
    at = {r["kind"]: r["mean_error"] for r in ns.edge_rows if r["samples"] == 256}
    assert abs(at["random"] / at["grid, axis edges"] - 1) < 0.25
    # review r129 08-5: in the chart they run side by side, both readable (no hiding)
    assert "at large $S$ they run side by side" in flat and "one hiding the other" not in flat
    # the magnified intersection: the dashed line (equal depth) parts the samples each won
    a, b, c = ns.dz
    ids = ns.pierced[4].sample_triangle_id
    for r, col in zip(ns.s_rows, ns.s_cols):
        for (ox, oy), k in zip(ns.pierced[4].samples, ids[r, col]):
            assert (a * (col + ox) + b * (r + oy) + c < 0) == (k == 0)  # red nearer: red
    assert np.allclose(a * ns.meet_x + b * ns.meet_y + c, 0)
    assert "The right-hand panels magnify the dashed window" in flat  # r202: one row per S
    # 08-5: no sample of the 4-sample pattern near the pixel centre, where the label is now
    assert np.hypot(*(tr.sample_pattern(4) - 0.5).T).min() > 0.35
    assert any("ax.text(c + 0.5, r + 0.5," in s for s in sources)
    # 08-6: the tail's pixels fade; 08-7: the border samples, printed and named in the text
    crawl = " ".join(next(s for s in sources if s.startswith("### Crawling edges")).split())
    assert "barely lighter" not in crawl and "fade towards the tip" in crawl
    assert ns.on_border == [(12, (0.0, 0.5)), (15, (0.0625, 0.0))]
    printed = streams(executed("08_antialiasing").notebook())
    assert "sample 12 at (0.0, 0.5), sample 15 at (0.0625, 0.0)" in printed
    assert "two of the 16 samples lie on the pixel's edges" in flat


def test_lesson_08_review_r127_fastest_held_diagonals_and_why_the_grid_beats_jittered(ns):
    """Review r127 08-2: the theory under q_fastest's chart (the whole order) is held until
    Check, in a code cell with its source collapsed, not a Markdown cell on screen before it.
    08-3: diagonals of the grid meet several samples at once too, not only rows or columns.
    08-4: why the grid beats jittered, with what the study shows: its slope between successive
    S steepens and stays steeper than jittered's, its error is below jittered's at every S."""
    import json
    from pathlib import Path

    from notebook_runs import executed, streams

    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    sources = ["".join(c["source"]) for c in cells]
    (k,) = [i for i, s in enumerate(sources) if "q_fastest = Predict(" in s]
    held = cells[k + 2]
    assert held["cell_type"] == "code" and sources[k + 2].startswith("q_fastest.hold()")
    assert held["metadata"]["jupyter"]["source_hidden"] and "hide-input" in held["metadata"]["tags"]
    # no Markdown cell from the question to the held theory says the rates
    for c, s in zip(cells[: k + 3], sources):
        if c["cell_type"] == "markdown":
            assert "Mitchell" not in s and "a little faster" not in s and "S^{-3/4}" not in s
    flat = " ".join(sources[k].split()).replace('" "', "")
    assert "only an edge along its rows or columns" not in flat
    assert "parallel to the grid's rows or columns meets √S" not in flat
    # review r129 08-4: any simple slope meets several grid points at once, not only rows,
    # columns and diagonals; the count along a slope of 1/2 is computed, not typed (since r147
    # #9 asks jittered's exponent, the grid is in the explanation, not in the stem)
    assert "{on_a_line['slope 1/2']} along a slope of ½" in flat
    assert "an edge along a diagonal or another simple slope meets several at" in flat
    assert ns.on_a_line == {"row": 16, "diagonal": 16, "slope 1/2": 8, "slope 1/3": 6}
    # the study: the grid's slope between successive S steepens, each steeper than jittered's
    grid, jit = ns.step_slopes["grid"], ns.step_slopes["jittered"]
    assert (np.diff(grid) < 0).all() and (grid < jit).all() and (grid > -1).all()
    assert all(abs(j + 0.75) < 0.05 for j in jit)
    assert (ns.edge_errors["grid"] < ns.edge_errors["jittered"]).all()
    # the held text quotes what the cells print
    text = " ".join(ns.FASTEST_TEXT.split())
    fitted = f"{ns.edge_slopes['grid']:.2f} for the grid against {ns.edge_slopes['jittered']:.2f}"
    assert fitted == "-0.80 for the grid against -0.74"
    assert fitted.replace("-", "−") in text  # review r129 08-9: a typographic minus
    steps = {
        kind: ", ".join(f"{v:.2f}".replace("-", "−") for v in ns.step_slopes[kind])
        for kind in ("grid", "jittered")
    }
    assert (
        f"the grid's slope goes {steps['grid']} while jittered's stays near −3/4 ({steps['jittered']})"
        in text
    )
    printed = streams(executed("08_antialiasing").notebook())
    assert f"grid: {steps['grid']}" in printed and f"jittered: {steps['jittered']}" in printed
    assert "fitted slopes k of error ∝ S^k:\n  grid: −0.80\n" in printed


def test_lesson_08_review_r129_held_chart_source_reconstruction_and_even_steps(ns):
    """Review r129 08-8: q_fastest's held chart cell has its source collapsed and no comment or
    label in it states a rate (the reference line's label is named in the question's own
    collapsed cell). 08-2: step 3 names both reconstructions, the display's box and the
    explorer's tent. 08-3: even rows make the quarter steps come at equal intervals of the
    edge's travel; the random pattern's intervals are printed from its rows."""
    import json
    from pathlib import Path

    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    sources = ["".join(c["source"]) for c in cells]
    (k,) = [i for i, s in enumerate(sources) if "q_fastest = Predict(" in s]
    chart = cells[k + 1]
    assert sources[k + 1].startswith("q_fastest.hold()") and "ax.loglog" in sources[k + 1]
    assert (
        chart["metadata"]["jupyter"]["source_hidden"] and "hide-input" in chart["metadata"]["tags"]
    )
    for told in ("steepens", "Mitchell", "S^{-3/4}", "jittered curve", '"jittered"]'):
        assert told not in sources[k + 1], told
    assert "(the grid)" not in sources[k]
    # review r133 08-H: the reference line's rate and Mitchell's name are in neither collapsed
    # source before Check (the exponent comes from the package, the legend names no rate)
    for told in ("Mitchell", "3/4", "-0.75", "REFERENCE"):
        assert told not in sources[k] and told not in sources[k + 1], told
    assert "STRATIFIED_ERROR_EXPONENT" in sources[k + 1]
    assert 'label="theory line (explained below)"' in sources[k + 1]
    text = " ".join(" ".join(sources).split())
    assert "the display shows each value over its pixel." not in text
    assert "A display shows each value over its pixel (a **box**)" in text
    assert (
        "(a **tent**, as bilinear filtering does)" in text
        and "a Gaussian's width is $2\\sigma$" in text
    )
    assert "coverage moves in equal steps" not in text and "its steps are equal" not in text
    assert "its steps come at equal intervals of the edge's travel" in text
    assert "coverage steps by ¼ at equal " in text
    assert np.allclose(ns.steps_apart["rotated grid (standard)"], 0.25)
    apart = ", ".join(f"{d:.2f}" for d in ns.steps_apart["random"])
    assert apart == "0.15, 0.35, 0.22"
    assert np.allclose(np.diff(ns.pattern_rows4["random"]), ns.steps_apart["random"])


def test_lesson_08_review_r133_shading_ratio_msaa_inside_robust_fastest_and_lesson_09(ns):
    """Review r133 08-A: supersampling costs up to S times the shading, the ratio quoted from the
    printed one. 08-B: inside a triangle MSAA leaves texture detail to texture filtering and
    shading aliasing as it is. 08-C: lesson 09 does not claim to name aliasing first. 08-H:
    q_fastest asks what holds on any run (the slowest, far from the other two; the lowest at
    S = 256), not the order of the grid and jittered, whose fitted slopes are close."""
    import json
    from pathlib import Path

    from notebook_runs import executed, streams

    root = Path(__file__).resolve().parents[1]
    cells = json.loads((root / "notebooks" / "08_antialiasing.ipynb").read_text())["cells"]
    text = " ".join(" ".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")
                    .split())  # fmt: skip
    ratio = ns.shaded_ssaa / ns.shaded_msaa
    assert 1 < ratio < 4 and ns.shading_ratio == ratio
    printed = streams(executed("08_antialiasing").notebook())
    assert f"supersampling / MSAA: {ratio:.1f}× the shading work" in printed
    # review r194 9: the ratio quoted without "(the cell below prints ...)"
    assert f"fewer at the edges: {ratio:.1f}× for this triangle" in text
    assert "the cell below prints" not in text
    assert "up to $S$ times the shading work ($S$ times at every fully covered pixel" in text
    assert "$S$ times the shading work;" not in text and "($S\\times$ the shading)" not in text
    assert "(up to $S\\times$ the shading, §2)" in text
    assert "texture detail inside the triangle is not antialiased" not in text
    assert "texture detail is left to texture filtering (lesson 09)" in text
    assert "(a sharp highlight, an alpha-tested cut-out) stays" in text
    # lesson 09 meets aliasing in textures; lesson 08 §1 named it
    assert "one effect, **aliasing**" in text
    nine = json.loads((root / "notebooks" / "09_texture_filtering.ipynb").read_text())["cells"]
    opening = " ".join("".join(nine[0]["source"]).split())
    assert "This lesson names that effect" not in opening
    assert "Lesson 08 named that effect for edges, **aliasing**; this lesson meets it" in opening
    # q_fastest (r147 #9: jittered's exponent; ± 0.05 since r171): random's slope, given in the stem, is
    # well beyond the tolerance; the grid ends well below jittered
    grid, jit, rnd = (ns.fitted[k] for k in ("grid", "jittered", "random"))
    assert rnd - jit > 0.2 and grid < jit and ns.jittered_k == jit
    assert ns.at_256["grid"] < 0.7 * ns.at_256["jittered"]
    assert ns.at_256["jittered"] == ns.edge_errors["jittered"][-1]
    assert ns.STRATIFIED_ERROR_EXPONENT == -0.75


def test_lesson_08_review_r136_plan_gpu_only_blends_titles_and_decimals(ns):
    """Review r136 08: the resolve's text and print explain the GPU, one sentence points to
    the simulator's plan (08-8); the magnified intersection's blended pixels without dots are
    explained, and are pixels an edge runs through (08-5); the figure title names row and
    column (08-6); q_centre's division checks at its printed decimals (cosmetic); the plan of
    cell 0 lists the eight sections (08-9); CSAA's 2-bit index is the cited book's (08-11)."""
    import json
    import re
    from pathlib import Path

    from notebook_runs import executed, streams

    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    sources = ["".join(c["source"]) for c in cells]
    flat = " ".join(" ".join(sources).split())
    printed = streams(executed("08_antialiasing").notebook())
    # 08-8: no simulator plan printed or explained; the GPU's counts stay
    assert "teachraster's plan" not in printed and "shortcut to the same picture" not in flat
    # review r183 13: the simulator's plan, named and never shown, is no longer pointed to
    md = " ".join("".join(c["source"]) for c in cells if c["cell_type"] == "markdown")
    assert "frame.plan" not in md
    assert f"At {ns.uniform} of them one triangle is in front at all 4 samples" in " ".join(
        printed.split()
    )
    # 08-5: every blended pixel of the magnified window without dots has an edge through it
    ids = ns.pierced[4].sample_triangle_id
    unmarked = 0
    for r in range(*ns.zoom_y):
        for c in range(*ns.zoom_x):
            if (ids[r, c] == 0).any() and (ids[r, c] == 1).any() and not ns.split[r, c]:
                assert not ns.inside_both[r, c], (r, c)
                unmarked += 1
    assert unmarked > 0
    assert "A blended pixel there without dots is not counted: an edge of one of the" in flat
    # 08-6: the magnified pixel's title names row and column
    assert f"pixel (row {ns.pr}, col {ns.pc}): centre v" in printed
    # q_centre: the heights at 4 decimals divide to the printed quotient
    num, den = round(ns.h_centre, 4), round(ns.h_vertex, 4)
    assert f"{num / den:.3f}" == f"{ns.h_centre / ns.h_vertex:.3f}"
    assert 'f"so v = {h_centre:.4f} / {h_vertex:.4f} =' in flat
    # 08-9: one item of the plan a numbered section
    sections = [n for s in sources for n in re.findall(r"^## (\d)\. ", s, flags=re.M)]
    plan = re.findall(r"^(\d)\. ", sources[0], flags=re.M)
    assert plan == [str(k) for k in range(1, len(sections) + 1)] and len(sections) == 8
    # 08-11: the bit count only where the source gives it
    assert "(2 bits for 4 colours)" not in flat
    assert "in NVIDIA's 16× CSAA a 2-bit index into the 4 colours" in flat


def test_lesson_08_review_r171_gif_plane_legend_maps_rms_and_missing_items(ns):
    """Review r171: 3, the GIF for slides lies in exports/ beside the notebook, its path
    printed; F2, lesson 03's plane in lesson 03's form, and lesson 03 points to §2, where the
    lesson says GL leaves the location open; 4, the legend's markers in the winners' colours;
    5, the 16-sample map on its own range, its worst pixels printed with what runs through
    them; 7, the explorer's RMS split into blur and leak, the text quoting the table's order;
    11, 12, 14, 17, 18: the exercise linked, exact coverage and the A-buffer, programmable
    sample positions, supersampling's mean of all S samples, the top-left rule's line."""
    import json
    from pathlib import Path

    from notebook_runs import executed, streams

    root = Path(__file__).resolve().parents[1]
    cells = json.loads((root / "notebooks" / "08_antialiasing.ipynb").read_text())["cells"]
    sources = ["".join(c["source"]) for c in cells]
    text = " ".join(" ".join(s for c, s in zip(cells, sources)
                             if c["cell_type"] == "markdown").split())  # fmt: skip
    printed = streams(executed("08_antialiasing").notebook())
    # 3: beside the notebook, the path printed
    assert ns.gif.parent.name == "exports" and ns.gif.is_absolute()
    lines = printed.splitlines()
    (at,) = [k for k, line in enumerate(lines) if line.startswith("the GIF, for slides")]
    assert lines[at + 1].endswith("/exports/08_crawling_edges.gif")
    assert "mkdtemp" not in " ".join(sources) and "`exports/` beside the notebook" in text
    # F2: the plane as lesson 03 writes it; lesson 03's pointer to §2
    assert "f_a + g_x(x - a_x)" not in text and "(lesson 03's $f = g_x x + g_y y + g_0$)" in text
    three = json.loads((root / "notebooks" / "03_barycentric_and_plane_equations.ipynb")
                       .read_text())["cells"]  # fmt: skip
    md3 = " ".join(" ".join("".join(c["source"]) for c in three).split())
    assert "$f = g_x x + g_y y + g_0$" in md3 or "g_x x + g_y y + g_0" in md3
    assert "lesson 08, section 2" in md3 and "lesson 08, section 5" not in md3
    section2 = text.split("## 2. Supersampling vs MSAA")[1].split("## 3.")[0]
    assert "GL and Vulkan leave it open" in section2  # review r254 S1
    # 4: no grey marker in the intersection's legend
    (fig29,) = [s for s in sources if "equal depth: where the triangles meet" in s]
    assert 'mfc="0.5"' not in fig29 and "a sample red won" in fig29 and "a sample blue won" in fig29
    # 5: the 16-sample map on its own range; its worst pixel is the corner v2 here
    assert ns.max_gap[16] < 0.25 * ns.max_gap[1]
    assert "16 samples, the five largest errors:" in printed
    r, c = np.unravel_index(ns.worst_16[0], ns.err_16.shape)
    assert f"pixel (row {r}, col {c}): {ns.err_16[r, c]:+.3f}, corner v2" in printed
    assert abs(ns.err_16[r, c]) == pytest.approx(ns.max_gap[16])
    # 7: the table's numbers are the widget's own; the Gaussian leaks less, blurs more, loses
    # (review r183 C1: three parts, the tent's reconstruction error apart from the blur)
    from teachraster.plotting.sampling import sample_signal

    def parts(r):  # the lesson's split, redone: blur, tent, both left of the band; leak; all
        left = r.x < r.alias_from

        def rms(a):
            return float(np.sqrt(np.mean(a**2)))

        return (rms((r.filtered - r.ideal)[left]), rms((r.reconstructed - r.filtered)[left]),
                rms((r.reconstructed - r.ideal)[left]), rms((r.reconstructed - r.ideal)[~left]),
                r.rms_error)  # fmt: skip

    box, gauss = (parts(sample_signal(32, 1.0, k)) for k in ("box", "gaussian"))
    assert gauss[3] < box[3] and gauss[0] > box[0] and gauss[4] > box[4]
    widths = (8, 16, 7, 14, 7)
    row = "  gaussian   1.0" + "".join(f"{v:{w}.3f}" for v, w in zip(gauss, widths))
    assert row in printed, row
    assert "leaks far less but blurs more, and here the blur costs more than the leak" in text
    # 13: the spectra drawn are the explorer's filters: a cosine of frequency u (cycles per
    # spacing) filtered by the widget's own prefilter keeps the share the curves give
    from teachraster.plotting.sampling import FINE, prefilter

    x = (np.arange(FINE) + 0.5) / FINE
    middle = slice(FINE // 4, 3 * FINE // 4)  # away from the mirrored ends
    for kind in ("box", "gaussian"):
        for u in (0.25, 0.75, 1.43):
            wave = np.cos(2 * np.pi * 32 * u * x)
            out = prefilter(wave, 1 / 32, 1.0, kind)
            share = abs(out[middle] @ wave[middle]) / (wave[middle] @ wave[middle])
            drawn = abs(np.sinc(u)) if kind == "box" else np.exp(-2 * (np.pi * u / 2) ** 2)
            assert share == pytest.approx(drawn, abs=0.015), (kind, u)
    said = "a wave at u = 0.75, above the limit: sampled, it is read as u = 0.25:\n  box keeps"
    assert f"{said} 0.30, Gaussian 0.06" in printed
    assert "box's side lobe: keeps up to 0.22 of a wave at u = 1.43" in printed
    assert "Sampling then **folds** every frequency above the limit" in text
    # 11, 12, 14, 17, 18
    assert "[exercises/06_antialiasing.ipynb](exercises/06_antialiasing.ipynb)" in text
    assert (root / "notebooks" / "exercises" / "06_antialiasing.ipynb").exists()
    assert "**A-buffer**" in text and "SIGGRAPH 1984" in text and "FreeType" in text
    assert "`VK_EXT_sample_locations`" in text and "`SetSamplePositions`" in text
    assert "the pixel shows the mean of all $S$ samples (the uncovered ones hold the" in text
    assert "$a \\to b$ is top or left when $b_y < a_y$, or $b_y = a_y$ and $b_x > a_x$" in text
    assert "Sutherland" not in text and "(a narrower angle of the other directions)" not in text
    # 15, 16: the held text on q_levels hedged once; the summary explains the GPU, not the
    # simulator (§6 keeps its one pointer to the plan)
    assert "can still show an extra value" not in " ".join(sources)
    summary = text.split("## Summary")[1]
    assert "shortcut of the simulator" not in summary and "a saving of bandwidth." in summary


def test_lesson_08_review_r183_three_faults_abuffer_centroid_and_sliver_none(ns):
    """Review r183: C1, the explorer's table called the tent's own error "blur" (0.119 with no
    filter); the three faults are named and printed apart. F2, the A-buffer's mask was already
    fixed-size: MSAA fixes the storage (S colours and depths, no fragment list). c26, the
    Direct3D row is the lesson's reading; centroid derivatives are less accurate (GLSL 4.60
    §4.5). 8, "no pixel" is an answer to the sliver question. 11, 12: the prose of §2, §5 and
    §6 cut, no development history in the code."""
    import json
    from pathlib import Path

    import matplotlib.pyplot as plt
    from notebook_runs import executed, streams

    from teachraster.plotting.common import screen_ticks
    from teachraster.plotting.sampling import sample_signal
    from teachraster.widgets import PredictPixels

    root = Path(__file__).resolve().parents[1]
    cells = json.loads((root / "notebooks" / "08_antialiasing.ipynb").read_text())["cells"]
    sources = ["".join(c["source"]) for c in cells]
    md = [s for c, s in zip(cells, sources) if c["cell_type"] == "markdown"]
    text = " ".join(" ".join(md).split())
    printed = streams(executed("08_antialiasing").notebook())
    # C1: no filter, no blur; the 0.119 the text quotes is the tent's error, printed as such
    none = sample_signal(32, 0.0, "box")
    left = none.x < none.alias_from
    tent = float(np.sqrt(np.mean((none.reconstructed - none.ideal)[left] ** 2)))
    assert np.array_equal(none.filtered, none.signal) and f"{tent:.3f}" == "0.119"
    assert "  none       0.0   0.000           0.119  0.119" in printed
    assert "With no filter there is no blur: that row's 0.119 left of the band is the tent's own error" in text  # fmt: skip
    assert "the tent's **reconstruction error**" in text and "the **leak**" in text
    assert "It adds up two faults" not in text
    assert "left of the band" in printed and "reconstruction" in printed
    # F2: the storage is what MSAA fixed, not the mask
    assert "made fixed-size" not in text and "a fixed 4 × 8 bit mask" in text
    assert ("MSAA keeps the mask but stores a fixed $S$ colours and $S$ depths per pixel "
            "instead of the list") in text  # fmt: skip
    # c26: the Direct3D reading is the lesson's; llvmpipe's rule the other reading
    # review r230 S3: the reading is no longer the lesson's; D3D11.3 settles it
    assert "The Direct3D row is this lesson's reading" not in text
    assert 'The Direct3D 10 page means "fully covered" by "covered"' in text
    assert "as Direct3D's reference rasterizer moves outward" not in text
    assert '"derivatives of centroid-sampled inputs may be less accurate" (GLSL 4.60 §4.5)' in text
    # 8: the sliver question, built as the lesson builds it, takes "no pixel" as an answer
    (ask,) = [s for s in sources if "q_sliver = PredictPixels(" in s]
    assert "none=" in ask and "or tick <i>no pixel</i>" in ask
    from teachraster.study.antialiasing import pixel_area

    scope = {"tr": __import__("teachraster"), "np": np, "plt": plt, "PredictPixels": PredictPixels,
             "screen_ticks": screen_ticks, "pixel_area": pixel_area}  # fmt: skip
    exec(ask, scope)
    q = scope["q_sliver"]
    assert "noneLabel" in q.data and q.given is None
    q.check()
    assert not q.revealed  # nothing given: Check waits
    q.given = []  # "no pixel", what 1 sample draws
    q.check()
    assert q.revealed and q.correct is False
    assert (
        "You marked 0 pixels: 0 right, 0 too many, 8 missed. The answer: 8 pixels drawn."
        in q.verdict()
    )
    plt.close("all")
    # 11: the prose cut by about a quarter (words: §2 was 366, §6's opening 254; §5's prose
    # round the centroid table 165, the Direct3D reading and the derivatives now within it)
    # (review r240: the words on screen, outside the folds read after the lecture)
    section2 = next(s for s in md if s.startswith("## 2. Supersampling vs MSAA"))
    section6 = next(s for s in md if s.startswith("## 6. The resolve, on a scene"))
    assert len(_unfolded(section2).split()) <= 300 and len(_unfolded(section6).split()) <= 200
    centroid = next(s for s in md if "| teachraster |" in s)
    assert len(_unfolded(centroid).split()) <= 175
    # 12: the code's comments say why, not how the figure came to be
    code = " ".join(" ".join(s.split()) for c, s in zip(cells, sources) if c["cell_type"] == "code")
    for history in (
        "a blank margin was left",
        "the star hid",
        "read as white",
        "it stood on screen",
    ):
        assert history not in code, history


#: Vulkan's table *Standard Sample Locations* (chapter *Rasterization*, *Multisampling*),
#: sample i in row i: the positions the lesson says Vulkan, Direct3D and teachraster share.
VULKAN_STANDARD_LOCATIONS = {
    2: [(0.75, 0.75), (0.25, 0.25)],
    4: [(0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)],
    8: [(0.5625, 0.3125), (0.4375, 0.6875), (0.8125, 0.5625), (0.3125, 0.1875),
        (0.1875, 0.8125), (0.0625, 0.4375), (0.6875, 0.9375), (0.9375, 0.0625)],
    16: [(0.5625, 0.5625), (0.4375, 0.3125), (0.3125, 0.625), (0.75, 0.4375),
         (0.1875, 0.375), (0.625, 0.8125), (0.8125, 0.6875), (0.6875, 0.1875),
         (0.375, 0.875), (0.5, 0.0625), (0.25, 0.125), (0.125, 0.75),
         (0.0, 0.5), (0.9375, 0.25), (0.875, 0.9375), (0.0625, 0.0)],
}  # fmt: skip


def _unfolded(markdown: str) -> str:
    """A Markdown cell without its folds (``<details>``, read after the lecture)."""
    import re

    return re.sub(r"<details>.*?</details>", "", markdown, flags=re.S)


def _lesson_text():
    import json
    from pathlib import Path

    cells = json.loads(
        (Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb").read_text()
    )["cells"]
    sources = ["".join(c["source"]) for c in cells]
    md = " ".join(" ".join(s for c, s in zip(cells, sources) if c["cell_type"] == "markdown")
                  .split())  # fmt: skip
    return cells, sources, md


def test_lesson_08_review_r230_resolve_averages_what_it_stores(ns):
    """Review r230 C1: lesson 12b's table says teachraster's resolve averages linear values,
    lesson 08 said it averages numbers, the wrong ones. Both hold: tr.render averages what it
    stores, codes in §6's cube, light in an sRGB8 target; the cell renders the cube into one.
    M4: what each API promises for an sRGB resolve, with its section. S4: none promises the
    box. M2: HDR colour resolved before tone mapping."""
    import json
    from pathlib import Path

    from notebook_runs import executed, streams

    _, sources, md = _lesson_text()
    printed = streams(executed("08_antialiasing").notebook())
    assert "`tr.render` resolves by averaging the numbers it stores, whatever they stand for" in md
    assert "The cube's colours are **sRGB codes**" in md and "what `tr.render` does" not in md
    er, ec = ns.er, ns.ec
    np.testing.assert_allclose(ns.target_codes[er, ec], ns.px_light, atol=1e-12)
    assert np.abs(ns.target_codes - ns.light_mean).max() < 1e-12  # every pixel, light's mean
    quoted = "(" + ", ".join(f"{v:.3f}" for v in ns.px_light) + ")"
    assert f"srgb8 frame.color (light), mean encoded: {quoted}, unrounded" in printed
    assert "codes averaged (tr.render here)" in printed
    # lesson 12b's table row, which the lesson now agrees with (12b is not edited)
    root = Path(__file__).resolve().parents[1]
    twelve = json.loads((root / "notebooks" / "12b_blending.ipynb").read_text())["cells"]
    table = " ".join("".join(c["source"]) for c in twelve)
    assert "| teachraster | yes: `frame.color` is the mean of the samples' linear values" in table
    assert "lesson 12b's table says of it" in md
    # review r269 C1: the GPU's target stores codes (GL 4.6 §17.3.7); the simulator keeps light
    assert "it stores linear values" not in md
    assert "A GPU's 8-bit sRGB target stores **codes**" in md
    # review r327 C2: GL promises the decode for blending (§17.3.6.1 Blend Equation, per sample
    # by §17.3.10), not for the resolve: the main text says so, as its fold and the table do
    assert "blends or resolves" not in md and "§17.3.6–17.3.7" not in md
    assert ("blending decodes each sample to light and re-encodes it (GL 4.6 §17.3.6.1, §17.3.7, "
            "with `GL_FRAMEBUFFER_SRGB`). The resolve averages light where Direct3D 11 promises "
            "it; Vulkan recommends it, GL does not say (fold below)") in md  # fmt: skip
    assert "| not promised (§18.3.1); blending decodes and encodes (§17.3.6.1, §17.3.7) |" in md
    # M4: the three APIs, each with its section
    assert '"Multisample resolve is performed in linear space" (D3D11.3 §5.6.6)' in md
    assert "*should* decode the samples before averaging and *must*" in md
    assert "`VK_KHR_maintenance10`" in md and "can improve perceptual aliasing" in md
    assert "falls against it is not said (GL 4.6 §18.3.1)" in md
    # S4, and review r240 F: two APIs promise the box mean, GL's blit and vkCmdResolveImage
    # leave the filter open (test_lesson_08_review_r240_resolve_promised_and_stored)
    assert "but no API promises it" not in md
    # M2: the numbers the text quotes are the cell's
    res = ns.hdr_resolves
    assert f"{ns.hdr_samples.mean():.3f}" == "10.025" and "its mean is 10.025" in md
    assert f"{res['box mean, then tone-mapped']:.3f}" == "0.909" and "that is 0.909" in md
    assert f"{20 / 21:.3f}" == "0.952" and "the lamp's own 0.952" in md  # Reinhard's x/(1+x)
    for name in ("each sample tone-mapped, then the mean", "weighted mean, then tone-mapped"):
        assert f"{res[name]:.3f}" == "0.500", name
    assert "Karis, *Tone mapping*" in md and "the jaggies are back" in md


def test_lesson_08_review_r230_msaa_leaves_the_floor_aliased(ns):
    """Review r230 M1: what MSAA leaves aliased is shown, not only stated: lesson 09's floor,
    1 sample, MSAA, supersampling and a 256-sample reference; inside the floor MSAA is the
    1-sample image, supersampling less than half its error, trilinear filtering in between."""
    from notebook_runs import executed, streams

    e = ns.floor_errors
    assert ns.same_inside and e["4× MSAA"] == e["1 sample"]
    assert e["4× supersampling"] < 0.5 * e["4× MSAA"]
    trilinear = float(
        np.abs(ns.trilinear - ns.floor_reference).mean(axis=2)[ns.floor_inside].mean()
    )
    assert e["4× supersampling"] < trilinear < e["4× MSAA"]
    assert ns.floor_inside.sum() > 500
    printed = streams(executed("08_antialiasing").notebook())
    assert "MSAA and 1 sample, the same colour at every one of them: True" in printed
    _, sources, md = _lesson_text()
    assert "Inside the floor MSAA changes nothing" in md
    assert any("tr.render(floor, None, W_floor, H_floor, samples=4)" in s for s in sources)


def test_lesson_08_review_r230_sample_shading_positions_and_discrepancy(ns):
    """Review r230 F1: GL_SAMPLE_SHADING alone shades once per pixel; per-sample shading
    needs glMinSampleShading(1.0), or gl_SampleID / a sample input. M3: which positions are
    portable, Vulkan's table being teachraster's. M5: a source for "no pattern reaches 1/S".
    S1: the question names no figure it hides. S9: the exercise numbering."""
    cells, sources, md = _lesson_text()
    assert "(`GL_SAMPLE_SHADING`): the shader runs per covered sample" not in md
    assert "`glEnable(GL_SAMPLE_SHADING)` *and* `glMinSampleShading(1.0)`" in md
    assert "max(⌈0 × S⌉, 1) = 1 run per pixel (GL 4.6 §14.3.1.1 *Sample Shading*" in md
    assert "`gl_SampleID`" in md and "`SV_SampleIndex`" in md and "D3D11.3 §23.6" in md
    # M3: Vulkan's standard locations are teachraster's patterns
    for n, table in VULKAN_STANDARD_LOCATIONS.items():
        np.testing.assert_array_equal(tr.sample_pattern(n), np.array(table))
    assert "`VkPhysicalDeviceLimits::standardSampleLocations`" in md
    assert "`D3D11_STANDARD_MULTISAMPLE_PATTERN` (D3D11.3 §19.2.4" in md
    assert "`glGetMultisamplefv(GL_SAMPLE_POSITION, i, …)`" in md and "(GL 4.6 §14.3.1)" in md
    # M5: the theorem and its sources, held with the chart (its S^-3/4 would answer q_fastest);
    # the chart's steepest mean slope is far from -1
    held = " ".join(ns.FASTEST_TEXT.split())
    assert "Discrepancy theory proves it" in held and "Alexander" in held
    assert "Matoušek, *Geometric Discrepancy*, 1999" in held and "Discrepancy theory" not in md
    # review r245 P1: no unheld Markdown after q_fastest rules out its answers (the theorem
    # stays in the held text above)
    assert "(the theorem under the chart says none can)" not in md
    assert "no pattern can reach $1/S$ at every angle" not in md
    assert min(ns.edge_slopes[k] for k in ("grid", "jittered", "random")) > -0.9
    # review r327 C1: the last sentence says what the legend prints: the random-angle curves
    # stay short of -1, the standard patterns on axis-aligned edges reach it
    any_angle = [ns.edge_slopes[k] for k in ns.ANY_ANGLE.values()]
    axis = ns.edge_slopes["standard, axis edges (S = 2-8)"]
    assert min(any_angle) == ns.edge_slopes[ns.ANY_ANGLE[ns.steepest]] > -0.9
    assert f"{axis:.2f}" in ("-0.99", "-1.00", "-1.01") and "none of them reaches" not in held
    steepest, axis = (f"{k:.2f}".replace("-", "−") for k in (min(any_angle), axis))
    assert (f"At random angles none reaches a slope of −1 (the steepest, {ns.steepest}, "
            f"{steepest}); only the n-rooks standard patterns on axis-aligned edges do ({axis}, "
            "$S$ = 2 to 8)") in held  # fmt: skip
    # S1
    (ask,) = [s for s in sources if "q_levels = PredictPixels(" in s]
    assert "The figure below" not in ask and "Check draws the three patterns' strips" in ask
    # S9
    assert "**Exercise 6** (the exercises are numbered on their own; 6 goes with this lesson)" in md


def test_lesson_08_review_r230_centroid_slopes_and_worst_pixels(ns):
    """Review r230 S2: the standard patterns number their samples outward from the centre, so
    teachraster's and llvmpipe's centroids differ only where the centre is covered; a random
    pattern differs elsewhere too. S3: Direct3D 11.3 fixes the rule, the D3D10 page's context
    quoted. S5: one range of S for every fitted slope. S6: what the worst pixels share, and
    E23's gap, printed. FIG1: no dots on the 1-sample magnified panel."""
    from notebook_runs import executed, streams

    cells, sources, md = _lesson_text()
    # review r240 S: no lesson cell compares the simulator's centroid with llvmpipe's; the
    # facts the text states are checked here
    assert not hasattr(ns, "centre_out") and not any("rules_part" in s for s in sources)
    for n in (2, 4, 8, 16):  # "the standard patterns number their samples outward"
        distance = np.hypot(*(tr.sample_pattern(n) - 0.5).T)
        assert (np.diff(distance) >= 0).all(), n
    for pattern in (4, 8, 16):  # so Direct3D 11's rule and ours part only at a covered centre
        centre, differ = _centroid_rules_differ(ns.thin, ns.W, 4, pattern)
        assert not (differ & ~centre).any() and differ[centre].all() and centre.any(), pattern
    centre, differ = _centroid_rules_differ(ns.thin, ns.W, 4, tr.sample_pattern(16, "random"))
    assert (differ & ~centre).any()  # "on a random pattern ... also part"
    assert "On a random pattern" in md and "also part where the centre is not covered" in md
    assert '"(assuming the pixel is not fully covered)"' in md
    assert "D3D11.3 functional spec §3.5.5, *Centroid Sampling of Attributes*" in md
    assert "in increasing order of sample index" in md
    # S5: every slope over S = 1, 4, 16
    assert ns.FIT_COUNTS == (1, 4, 16)
    for kind, k in ns.slopes.items():
        r = [x for x in ns.rows if x["kind"] == kind and x["samples"] in ns.FIT_COUNTS]
        assert len(r) == 3
        fit = np.polyfit(np.log([x["samples"] for x in r]), np.log([x["mean_error"] for x in r]), 1)
        assert k == pytest.approx(fit[0])
    assert "Each slope is fitted over $S$ = 1, 4 and 16" in md
    printed = streams(executed("08_antialiasing").notebook())
    assert "fitted slopes k of error ∝ S^k, over S = 1, 4, 16:" in printed
    # S6: the numbers the text quotes
    gaps = (ns.e23_gap, float(np.median(ns.all_gaps)), float(ns.all_gaps.max()))
    assert [f"{g:.2f}" for g in gaps] == ["0.23", "0.16", "0.24"]
    assert "a gap of 0.23 px, near the widest of any direction (0.24 px" in md
    assert "the median\ndirection's" not in md and "direction's widest gap is 0.16 px" in md
    assert "along the axes 0.0625 px" in printed  # the rows of the 16-sample pattern
    assert "Three of the five lie on the edge E23" in md
    # FIG1: the 1-sample panel draws no dots; the legend says whose dots they are
    (fig,) = [s for s in sources if "equal depth: where the triangles meet" in s]
    assert "if fr.sample_triangle_id is not None else ()" in fig
    assert "4 samples, a counted pixel" in fig


def _centroid_rules_differ(triangle, width, height, pattern):
    """At the partly covered pixels: is the centre covered, and do Direct3D 11's centroid
    (the centre if every sample is covered, else the first covered sample; llvmpipe's) and
    teachraster's ``centroid=True`` take points with different values of ``v``?"""
    fill = tr.rasterize(triangle, width, height, samples=pattern)
    ours = tr.rasterize(triangle, width, height, samples=pattern, centroid=True).attrs["v"]
    cov = fill.sample_coverage
    r, c = np.nonzero(cov.any(axis=-1) & ~cov.all(axis=-1))
    first = np.argmax(cov[r, c], axis=-1)
    plane = tr.attribute_plane(tr.snap(triangle.xy), triangle.attrs["v"])
    theirs = plane(c + fill.samples[first, 0], r + fill.samples[first, 1])
    centre = tr.rasterize(triangle, width, height).coverage[r, c]
    return centre, np.abs(theirs - ours[r, c]) > 1e-9


def test_lesson_08_review_r240_resolve_promised_and_stored(ns):
    """Review r240 F (and C against 12b): two APIs promise the box resolve, Direct3D on its
    standard patterns and Vulkan's render-pass AVERAGE; GL's blit and vkCmdResolveImage leave
    it open, as lesson 12b's table says. S: the sRGB8 resolve as a GPU stores it, code 188."""
    import json
    from pathlib import Path

    from notebook_runs import executed, streams

    from teachraster.pipeline.blending.colour_blending import store_colour

    _, _, md = _lesson_text()
    assert (
        '"is defined as a simple average of the samples within each pixel" (D3D11.3 §19.2.4' in md
    )
    assert "Vulkan, in a render pass: `VK_RESOLVE_MODE_AVERAGE_BIT`, the default," in md
    assert 'gives "the average of the sample values", at implementation-defined precision' in md
    assert ("GL's `glBlitFramebuffer` and Vulkan's `vkCmdResolveImage` leave the filter to the "
            "implementation (GL 4.6 §18.3.1") in md  # fmt: skip
    root = Path(__file__).resolve().parents[1]
    twelve = json.loads((root / "notebooks" / "12b_blending.ipynb").read_text())["cells"]
    table = " ".join(" ".join("".join(c["source"]) for c in twelve).split())
    assert '"a simple average of the samples within each pixel"' in table
    assert '`VK_RESOLVE_MODE_AVERAGE_BIT`, the default where no mode is specified: "the average of the sample values"' in table  # fmt: skip
    assert "| Vulkan, `vkCmdResolveImage` |" in table and "implementation-dependent" in table
    # the sRGB8 target: the unrounded mean, and the code a GPU stores (the package's rule)
    er, ec = ns.er, ns.ec
    light = np.append(ns.srgb_target.color[er, ec, :3], 1.0)
    stored = tr.linear_to_srgb(store_colour(light, "srgb8")[:3]) * 255
    np.testing.assert_allclose(stored, ns.stored_codes[er, ec], atol=1e-9)
    assert ns.stored_codes[er, ec].tolist() == [188, 214, 201]
    printed = streams(executed("08_antialiasing").notebook())
    assert "the 8-bit target holds codes (188, 214, 201) = (0.737, 0.839, 0.788)" in printed
    assert (
        f"{ns.stored_codes[er, ec][0] / 255:.3f}" == "0.737" and f"{ns.px_light[0]:.3f}" == "0.735"
    )
    assert (
        "stores the nearest code, 188 (0.737)" in md and "keeps the resolved mean unrounded" in md
    )


def test_lesson_08_review_r240_patterns_taa_highlight_and_prose(ns):
    """Review r240 M: D3D11.3 §19.2.4's reasons for the standard patterns (the worst edge, the
    16-division grid) tied to §7's 16-sample rows; TAA shown (jittered frames averaging to 16
    samples, the history, reprojection); a highlight under MSAA and per-sample shading. S: the
    floor's supersampling is an ordered grid; ¼ or ¾; the summary's positions; prose cut."""
    import re

    from notebook_runs import executed, streams

    cells, sources, md = _lesson_text()
    printed = streams(executed("08_antialiasing").notebook())
    # §19.2.4, quoted as the specification words it
    discrepancy = "the error between analytic coverage and sample based coverage"
    assert f'"halfplane discrepancy – {discrepancy}", this section\'s error' in md
    assert '"the worst case (L-inf) error over all halfplanes (single worst edge)" proved' in md
    assert '"not that useful alone" (D3D11.3 §19.2.4)' in md
    assert '"a sub-pixel grid limited to 16 horizontal and vertical divisions"' in md
    assert '"it is undesirable for a sample pattern to have multiple samples line up' in md
    sixteen = tr.sample_pattern(16)
    assert (sixteen * 16 == np.round(sixteen * 16)).all()  # on the 1/16 grid, every row taken
    assert sorted(sixteen[:, 1].tolist()) == [k / 16 for k in range(16)]
    assert "Hardware patterns are chosen for the worst case" not in md
    # TAA: 16 jittered frames average to the 16-sample image exactly; the history errs far
    # less than one sample; moving, reprojection beats no reprojection beats one sample
    assert np.abs(ns.averaged_16 - ns.still_16[0]).max() == 0 and ns.ALPHA == 0.1
    assert "largest difference 0" in printed and "history (α = 0.1) after 32 frames" in printed
    crossed = (ns.still_16[0] > 0) & (ns.still_16[0] < 1)  # the pixels the edges cross

    def err(image):
        return float(np.abs(image - ns.still_16[0])[crossed].mean())

    assert err(ns.taa_still[-1]) < 0.25 * err(ns.centre_only)
    assert f"history (α = 0.1) after 32 frames: {err(ns.taa_still[-1]):.3f}" in printed
    e = ns.crawl_errors
    assert (e["history, reprojected"] < e["history, not reprojected"]
            < e["1 sample at the centre"])  # fmt: skip
    assert '"formally defined as temporally-amortized supersampling" (Yang, Liu and Salvi' in md
    assert "(Karis, *High Quality Temporal Supersampling*, SIGGRAPH 2014)" in md
    assert "behind the motion (above it, middle left)" in md  # review r245 M1: six panels now
    # the highlight: MSAA is the 1-sample image; per-sample shading far nearer the reference
    assert ns.band_same and "4× MSAA and 1 sample, the same image: True" in printed
    b = ns.band_errors
    assert b["4× per-sample shading"] < 0.5 * b["4× MSAA"]
    assert f"the band, {ns.band_width:.2f} px wide at half its peak" in printed
    assert "its `discard` keeps or drops all the pixel's samples together" in md
    # S: the floor's supersampling is not per_sample=True, and says so
    assert "`tr.render` has no per-sample mode" in md and "on an ordered grid" in md
    # S: a crossing between a row's two samples gives ¼ or ¾
    (ask,) = [s for s in sources if "q_levels = PredictPixels(" in s]
    assert "no quarter value" not in ask and "a quarter value there" not in ask
    # review r269 P1: the question asks the pixels at ¼ or ¾ under the standard pattern
    assert "Click the pixels of rows 2 and 3 that show ¼ or ¾" in ask
    assert ns.odd_standard.sum() == 8 and ns.odd_grid.sum() == 1
    assert [f"{x:.1f}" for _, x in ns.std_crossed] == ["1.3", "5.4", "9.6", "13.8", "17.9"]
    explain = " ".join(ns.levels_explain.split())
    assert "8 pixels: row 2, pixels 0, 6, 7, 8; row 3, pixels 14, 15, 16, 17." in explain
    assert "here 1 pixel(s) show ¼ or ¾ (4 levels against the standard pattern's 5)" in explain
    # review r327 S1: a pixel that holds a pass goes with its own sample's side of the pass
    assert "a pixel that holds a pass goes with the side its own sample on that row lies on" in (
        explain
    )
    pattern = ns.standard4
    for y, x in ns.std_crossed:
        r, j = int(y), int(x)
        (s,) = np.flatnonzero(np.isclose(pattern[:, 1], y - r))
        assert ns.edge_standard.sample_coverage[r, j, s] == (j + pattern[s, 0] < x)
    # S: the summary keeps the conditions under which the positions are fixed
    summary = md.split("## Summary")[1]
    assert "fix the standard positions" not in summary
    assert (
        "`standardSampleLocations`" in summary and "`D3D11_STANDARD_MULTISAMPLE_PATTERN`" in summary
    )
    # S: the prose on screen under 4,000 words (it was 4,738); the rest in folds. Review r269
    # M1's standards table is reference, not prose: its rows are not counted (prose 3,948 -> 3,867)
    markdown = ["".join(c["source"]) for c in cells if c["cell_type"] == "markdown"]
    prose = [
        "\n".join(r for r in _unfolded(m).splitlines() if not r.startswith("|")) for m in markdown
    ]
    on_screen = sum(len(p.split()) for p in prose)
    assert on_screen < 4000, on_screen
    folds = [m for m in markdown if "<details>" in m]
    assert len(folds) >= 5 and all(
        "<summary><b>More, for reading after the lecture:</b>" in m for m in folds
    )
    assert all(m.count("<details>") == m.count("</details>") for m in markdown)
    assert not re.search(r"</details>\S", " ".join(markdown))


def test_lesson_08_review_r245_srgb_introduced_and_the_cube_in_light(ns):
    """Review r245 C1: lessons 09 and 12b say §6 introduces sRGB; it used the codes without the
    curve, pointing back to 12b. §6 gives the IEC 61966-2-1 curve (the package's constants), a
    cell writes both directions out and prints the two numbers the text quotes, and a plot.
    S4: §6's headline cube is the sRGB8 target (light averaged), codes averaged the mistake."""
    import inspect
    import json
    from pathlib import Path

    from notebook_runs import executed, streams

    from teachraster.core import blend_factors

    cells, sources, md = _lesson_text()
    printed = streams(executed("08_antialiasing").notebook())
    assert "(IEC 61966-2-1) spends more codes on dark values" in md
    assert "equal steps of light (lesson 12b §6)" not in md  # no pointer back to 12b
    # the formula's constants are the package's, both ways
    curve = inspect.getsource(blend_factors.srgb_to_linear) + inspect.getsource(
        blend_factors.linear_to_srgb
    )
    for constant in ("12.92", "0.04045", "0.055", "1.055", "2.4", "0.0031308"):
        assert constant in curve, constant
    assert "L = \\frac{c}{12.92} \\quad (c \\le 0.04045)" in md
    assert "L = \\left(\\frac{c + 0.055}{1.055}\\right)^{2.4} \\quad (c > 0.04045)" in md
    # the worked numbers: printed by the cell, quoted by the text
    told = (f"{float(tr.srgb_to_linear(0.5)):.3f}", f"{float(tr.linear_to_srgb(0.5)):.3f}")
    assert told == ("0.214", "0.735")
    assert "code 0.5 is light 0.214; light 0.5 is code 0.735" in printed
    assert "code 0.5 is light 0.214, light 0.5 is code 0.735" in md
    assert "the same as tr.srgb_to_linear and tr.linear_to_srgb: True" in printed
    (k,) = [i for i, s in enumerate(sources) if s.startswith("### One pixel of the resolve")]
    assert "def encode(light):" in sources[k + 1] and "plt.show()" in sources[k + 1]
    assert "def decode(c):" in sources[k + 1] and "1 / 2.4" in sources[k + 1]
    # lessons 09 and 12b point here, to the heading that now introduces the encoding
    root = Path(__file__).resolve().parents[1]
    for name, pointer in (("09_texture_filtering", "(lesson 08, §6, *One pixel of the resolve*)"),
                          ("12b_blending", "(lesson 08 §6 introduces the encoding)")):  # fmt: skip
        other = json.loads((root / "notebooks" / f"{name}.ipynb").read_text())["cells"]
        assert pointer in " ".join(" ".join("".join(c["source"]) for c in other).split())
    # S4: the panels of §6 are the sRGB8 target; the pixel's codes-averaged mean the mistake
    (panels,) = [s for s in sources if "srgb8 = {s: tr.render(scene.clip(96 / 72)" in s]
    assert "plot_image(ax, tr.linear_to_srgb(fr.color[..., :3])[crop])" in panels
    assert "srgb_target = srgb8[4]" in " ".join(sources)
    np.testing.assert_array_equal(ns.srgb_target.color, ns.srgb8[4].color)
    assert "in an 8-bit sRGB target (whose resolve averages light: next section)" in md
    assert "Given codes, it averages codes: the mistake" in md
    (figure,) = [s for s in sources if '"cube codes"' in s]
    assert "(the mistake)" in figure and "4 samples, light averaged" in figure


def test_lesson_08_review_r245_caption_summary_and_reading_order(ns):
    """Review r245 C2: the inspector shades covered fractions at every count (grey up to 4
    samples); S2: both panels in coordinates, said once. P1: no unheld Markdown after
    q_fastest states the rates or rules out −1. S1: §7's chart is read right under it, the
    maps introduced before them. S3: n-rooks named, the rotated grid the 4-sample pattern.
    S5: extrapolated only where the centre is outside."""
    cells, sources, md = _lesson_text()
    caption = " ".join(next(s for s in sources if s.startswith("## 8. Inspect a pixel")).split())
    assert "(above 4 samples, each pixel shaded by its covered fraction instead)" not in caption
    assert "each pixel shaded by its covered fraction (grey; above 4 samples in colour" in caption
    assert "Both panels are in screen coordinates: pixel (row i, col j) spans x from j to j + 1" in caption  # fmt: skip
    # P1: after the question, every Markdown cell (the summary included) leaves the rates alone
    (k,) = [i for i, s in enumerate(sources) if "q_fastest = Predict(" in s]
    after = " ".join(" ".join(s.split()) for c, s in zip(cells[k:], sources[k:])
                     if c["cell_type"] == "markdown")  # fmt: skip
    for told in ("S^{-3/4}", "S^{-1/2}", "none can", "at every angle", "No pattern"):
        assert told not in after, told
    summary = md.split("## Summary")[1]
    assert "How fast the error falls with $S$ depends on where the samples lie (§7)" in summary
    # S1: the chart's text right under the chart; the maps' introduction right before them
    ids = [c["id"] for c in cells]
    assert ids.index("c23b") == ids.index("c08caa52") + 1
    assert ids.index("f90c4152") == ids.index("010d8f32") + 1
    assert sources[ids.index("010d8f32")].startswith("Back to one triangle: its signed error")
    # S3: one sample per row and column is n-rooks, true of every standard pattern; the
    # rotated grid is the 4-sample one, a square turned by atan(1/2)
    assert ns.rooks == [2, 4, 8, 16] and ns.turned == pytest.approx(np.degrees(np.arctan(0.5)))
    assert "The **rotated grid** puts every sample on its own row and column" not in md
    assert "The standard patterns are **n-rooks** (a sample on each row and column)" in summary
    assert "the 4-sample **rotated grid** also spaces its rows evenly" in summary
    assert "each **n-rooks** (one sample on every row and column)" in md
    # S5
    assert "At the pixel centre attributes are **extrapolated**" not in md
    assert "Where the pixel centre lies outside the triangle, MSAA **extrapolates**" in summary
    # the prose did not grow: r245 counted 4,990 Markdown words; r254 added M2's sentence (an
    # edge's spectrum) and S1's Vulkan quotation (55 words, the on-screen count fell by 77)
    # r269 added the standards table (reference, not prose: not counted) and M3's sentences,
    # and cut as many words elsewhere
    total = sum(len(s.split()) for c, s in zip(cells, sources)
                if c["cell_type"] == "markdown" and not s.startswith("### The lesson's rules"))  # fmt: skip
    assert total <= 5045, total


def test_lesson_08_review_r245_taa_clamp_quads_and_standard_at_any_angle(ns):
    """Review r245 M1: the TAA study clamps its history to the new frame's neighbourhood and
    prints the same error with the ghost pixels; Halton jitter, the Catmull-Rom fetch and
    disocclusion named, with their sources. M2: the shader's runs on the cube, per pixel and
    triangle and in 2 × 2 quads, counted. M3: the standard patterns at any angle on §7's
    theory chart."""
    from notebook_runs import executed, streams

    from teachraster.study.antialiasing import temporal_history

    cells, sources, md = _lesson_text()
    printed = streams(executed("08_antialiasing").notebook())
    e, g = ns.crawl_errors, ns.ghosts
    np.testing.assert_allclose(ns.crawl_taa["reprojected, clamped"],
                               temporal_history(ns.crawl, ns.ALPHA, motion=(0.0, 1 / 16),
                                                clamp=True))  # fmt: skip
    for moved in ("not reprojected", "reprojected"):
        assert g[f"history, {moved}, clamped"] < 0.5 * g[f"history, {moved}"]  # fewer ghosts
        assert e[f"history, {moved}, clamped"] > e[f"history, {moved}"]  # the tail wiped
    assert g["1 sample at the centre"] == 0
    before, after = g["history, reprojected"], g["history, reprojected, clamped"]
    assert f"the ghost pixels fall from {before} to {after}" in md
    worse = f"from {e['history, reprojected']:.3f} to {e['history, reprojected, clamped']:.3f}"
    assert worse == "from 0.142 to 0.182" and f"the mean error rises {worse}" in md
    name = "history, reprojected, clamped"
    split = ns.ghost_split[name]
    assert (f"  {name:34s} {e[name]:.3f} {g[name]:6d} {split['behind']:6d} "
            f"{split['ahead']:5d}") in printed  # fmt: skip
    # a ghost pixel: empty at 16 samples, above 1/16 in the history, summed over frames 16-31
    history = ns.crawl_taa["reprojected"][16:]
    assert before == int(((ns.crawl_16[16:] == 0) & (history > 1 / 16)).sum())
    assert "Halton (2, 3)" in md and "bicubic (Catmull-Rom) fetch" in md
    assert "(a **disocclusion**, found by comparing depths)" in md
    assert "(Karis, *High Quality Temporal Supersampling*, SIGGRAPH 2014)" in md
    # M2: the shader's runs at 4 samples, recounted from the samples by another route
    ids = ns.frames[4].sample_triangle_id
    pairs, lanes = 0, 0
    for t in range(int(ids.max()) + 1):
        shown = (ids == t).any(axis=-1)
        pairs += int(shown.sum())
        h, w = shown.shape
        quads = np.pad(shown, ((0, h % 2), (0, w % 2))).reshape((h + 1) // 2, 2, (w + 1) // 2, 2)
        lanes += 4 * int(quads.any(axis=(1, 3)).sum())
    assert (pairs, lanes) == (ns.pairs4, ns.lanes4) == (866, 1100)
    assert ns.n_covered < ns.pairs4 < ns.lanes4 and ns.lanes1 < ns.lanes4
    runs = " ".join(printed.split())
    assert (f"The shader runs at {pairs:,} (pixel, triangle) pairs, not {ns.n_covered:,}" in runs
            and f"{lanes:,} lanes, helpers included ({ns.lanes1:,} with 1 sample)" in runs)  # fmt: skip
    assert "in whole 2 × 2 quads (lesson 09 §2)" in md
    # M3: the standard patterns at any angle, fitted over S = 2-16, beside the axis edges
    any_angle = ns.edge_slopes["standard, any angle (S = 2-16)"]
    assert -0.8 < any_angle < ns.edge_slopes["standard, axis edges (S = 2-8)"] + 0.5
    assert any_angle > ns.edge_slopes["standard, axis edges (S = 2-8)"]
    assert "the standard patterns, at random angles and on axis-aligned edges, 2 to 16)" in md


def test_lesson_08_review_r254_taa_ghosts_split_behind_and_ahead(ns):
    """Review r254 C1: "reprojected, it follows" stood beside 306 -> 289 ghost pixels, 149 of
    them above the triangle and 140 below: the count mixed the trail (behind the motion) with
    the blur of the bilinear fetch (both sides). The study now counts each side, the lesson
    prints both, and the text says what they show."""
    from notebook_runs import executed, streams

    from teachraster.study.antialiasing import ghost_sides

    _, _, md = _lesson_text()
    printed = " ".join(streams(executed("08_antialiasing").notebook()).split())
    split = ns.ghost_split
    assert split == {name: ghost_sides(h[16:], ns.crawl_16[16:], (0.0, 1 / 16))
                     for name, h in ns.shown_crawl.items()}  # fmt: skip
    assert all(s["beside"] == 0 for s in split.values())
    kept, moved = split["history, not reprojected"], split["history, reprojected"]
    clamped = split["history, reprojected, clamped"]
    assert kept["ahead"] == 0 < kept["behind"]  # a trail: behind only
    assert abs(moved["behind"] - moved["ahead"]) < 0.1 * moved["behind"]  # a blur: both sides
    assert (kept["behind"], moved["behind"], moved["ahead"]) == (306, 149, 140)
    assert (clamped["behind"], clamped["ahead"]) == (71, 26)
    assert "behind the motion (above the triangle) and ahead of it (below)" in printed
    assert f"all {kept['behind']} ghost pixels lie behind the motion" in md
    assert (f"Reprojected, {moved['behind']} lie behind and {moved['ahead']} ahead: not a trail "
            "but a blur on both sides of the edges") in md  # fmt: skip
    assert (f"from {ns.ghosts['history, reprojected']} to "
            f"{ns.ghosts['history, reprojected, clamped']} ({clamped['behind']} behind, "
            f"{clamped['ahead']} ahead)") in md  # fmt: skip
    assert "Reprojected, it follows" not in md


def test_lesson_08_review_r254_labels_inside_their_frames():
    """Review r254 FIG1: the sRGB curve's label "code 0.735: light 0.500" ran over the right
    spine at c = 1; it now starts at the L axis, on its dotted line. FIG2: "centre: v = +1.16
    (extrapolated)" crossed the pixel's border and the frame; it now sits under the ✕ on two
    lines, centred, inside the pixel."""
    _, sources, _ = _lesson_text()
    (curve,) = [s for s in sources if "def decode(c):" in s]
    assert '(float(encode(0.5)), 0.5, "axis", (8, 5))' in curve
    assert '(c if at == "point" else 0.0, light)' in curve
    (centre,) = [s for s in sources if "q_centre.hold()" in s and "ax.annotate" in s]
    assert '(extrapolated)", (pc + 0.5, pr + 0.5)' in centre and ":+.2f}\\n(extrapolated)" in centre
    assert "xytext=(0, -20)" in centre and 'ha="center", va="top"' in centre


def test_lesson_08_review_r254_sliver_against_the_exact_area(ns):
    """Review r254 M1: the sliver's reveal compared 4× MSAA with nothing; the pixels it draws
    at ¼ are covered 0.085 to 0.028 (3 to 9 times too bright), printed beside the fractions.
    S3: the explanation says the tail (pixels 8 to 10) is still lost."""
    from notebook_runs import executed, streams

    from teachraster.study.antialiasing import pixel_area

    printed = streams(executed("08_antialiasing").notebook())
    area = pixel_area(ns.sliver.xy, ns.W_strip, 3)[1]
    np.testing.assert_array_equal(ns.sliver_area, area)
    assert ns.sliver_drawn.tolist() == list(range(8)) and ns.sliver_lost.tolist() == [8, 9, 10]
    assert (ns.sliver_4.coverage_fraction[1][ns.sliver_drawn] == 0.25).all()
    assert "  α   " + " ".join(f"{v:5.3f}" for v in area) in printed
    assert "0.085 0.077" in printed and "0.028 0.020 0.012 0.004" in printed
    explain = " ".join(ns.sliver_explain.split())
    assert ("each at ¼, where the sliver covers only 0.085 to 0.028 of the pixel: 3 to 9 times "
            "too bright") in explain  # fmt: skip
    assert "Pixels 8 to 10 (areas 0.020 to 0.004) are still lost" in explain
    assert "each at a quarter of full coverage" not in explain


def test_lesson_08_review_r254_edge_spectrum_vulkan_and_the_levels_strip(ns):
    """Review r254 M2: an edge's spectrum is unbounded, so samples never remove its aliasing
    (cited). S1: Vulkan leaves MSAA's evaluation point open too, in its own words. S2: the
    q_levels triangle's far vertex lies outside the strip on the same snapped line, so rows 2-3
    hold the question's edge only."""
    _, sources, md = _lesson_text()
    assert ("An edge is a step, whose spectrum falls only like $1/u$: no sampling rate is above "
            "all of it, so more samples reduce an edge's aliasing but never remove it (Pharr, "
            "Jakob and Humphreys, *Physically Based Rendering*, 4th ed., §8.1") in md  # fmt: skip
    assert "in Direct3D, llvmpipe and teachraster; GL and Vulkan leave it open" in md
    # Vulkan's current wording (1.3.221 on; lesson 03's table), Direct3D's functional spec
    assert "anywhere within the fragment" not in md and "dcl_input" not in md
    assert (
        'Vulkan: "an implementation-defined position within the fragment area" '
        '(*Interpolation Decorations*; one sample: "the center of the fragment area")'
    ) in md
    assert ('Direct3D: "pixel-frequency interpolation-modes such as linear evaluate at the pixel '
            'center" (D3D11.3 §3.5.5)') in md  # fmt: skip
    assert 'with one sample per pixel "the center of the fragment area"' in md  # the table
    # S2: the same line as through (20, 3.5), once snapped; no other edge in rows 2-3
    a, b = tr.snap(np.array([ns.edge_from, ns.edge_to]))
    old = tr.snap(np.array([[0.0, 2.3], [20.0, 3.5]]))
    assert (b[1] - a[1]) / (b[0] - a[0]) == (old[1, 1] - old[0, 1]) / (old[1, 0] - old[0, 0])
    assert ns.edge_to[0] > ns.W
    fill = tr.rasterize(tr.Triangle([ns.edge_from, ns.edge_to, [0.0, 8.0]]), ns.W, 6)
    assert fill.coverage[4:].all()  # rows 4-5: the inside, no second edge in the strip
    assert ns.edge_levels == [0.0, 0.25, 0.5, 1.0] and len(ns.standard_levels) == 5
    row3 = ns.edge_grid.coverage_fraction[3]
    assert row3[-4:].tolist() == [0.5] * 4  # no 0 at the right end from a second edge
    assert "the only edge in rows 2 and 3" in next(
        s for s in sources if "q_levels = PredictPixels(" in s
    )
    assert [round(x, 2) for _, x in ns.crossed] == [7.5, 15.83]


def test_lesson_08_review_r337_fig1_samples_graze_the_levels_edge(ns):
    """Review r337 FIG-1: q_levels' circles lie down to 0.0025 px from the drawn edge, under a
    screen pixel. No edge fixes it: each sample row it crosses in the strip holds a sample every
    pixel, so one lies within slope / 2 of it, and rows 2-3 hold a slope of 0.1 at most (a
    search of edges in rows 2-3 of strips 8 to 20 pixels wide that keep the standard pattern's 5
    levels and the grid's fewer found none clearing 0.05 px). So the question gives the nearest
    distance and sends the student to the passes."""
    x = np.arange(ns.W)[:, None] + ns.standard4[:, 0]
    y = np.add.outer((2, 3), ns.standard4[:, 1])[:, None]
    (dx, dy), (x0, y0) = ns.edge_to - ns.edge_from, ns.edge_from
    distance = np.abs(dx * (y - y0) - dy * (x - x0)) / np.hypot(dx, dy)
    assert ns.graze == pytest.approx(distance.min()) and ns.slope / 2 < 0.05
    assert (distance < 2 * ns.graze).sum() >= 2  # "some"
    (ask,) = [s for s in _lesson_text()[1] if "q_levels = PredictPixels(" in s]
    assert "pattern's samples, some within {graze:.4f} px of the edge: find where it passes" in ask
    assert "share of its samples" not in ask  # the words it replaced


def test_lesson_08_review_r269_rules_table_and_llvmpipe(ns):
    """Review r269 M1: one GL / Direct3D / Vulkan / llvmpipe / teachraster table for the
    lesson's five rules, with sections, consistent with lesson 12b's sRGB table. M2: a cell
    compares llvmpipe with teachraster (positions, per-sample coverage, the resolve,
    centroid), or says that there is no OpenGL. M3: MLAA/SMAA and temporal upscaling named.
    S1: the standard pattern, not the grid, is off-centre at 16. S2: memory against bandwidth."""
    from notebook_runs import executed, streams

    _, sources, md = _lesson_text()
    (table,) = [s for s in sources if s.startswith("### The lesson's rules, standard by standard")]
    rows = [r for r in table.splitlines() if r.startswith("| ")]
    assert (
        rows[0]
        == "| rule | OpenGL 4.6 (GLSL 4.60) | Direct3D 11 | Vulkan | llvmpipe | teachraster |"
    )
    assert [r.split(" | ")[0] for r in rows[1:]] == [
        "| where MSAA evaluates an attribute (§2)", "| sample positions (§3)",
        "| the tie rule, per sample (§4)", "| depth under MSAA (§6)", "| resolve filter (§6)",
        "| sRGB resolve (§6)",
        "| sample-rate shading (here)"]  # fmt: skip
    for section in ("GLSL §4.5", "§14.3.1)", "§18.3.1", "§14.3.1.1", "§19.2.4", "§5.6.6", "§23.6"):
        assert section in table, section
    assert "`ResolveSubresource`" in table and "`sampleShadingEnable`" in table
    assert "| not promised (§18.3.1);" in table and "| in linear light (§5.6.6) |" in table
    printed = streams(executed("08_antialiasing").notebook())
    if "no OpenGL here:" in printed:
        return
    assert all(ns.gl_same.values()) and ns.resolve_gap == 0
    assert "sample positions = tr.sample_pattern(4): True" in printed
    assert "§4's fan: 396 covered samples, the same ones: True" in printed
    part, apart, centres = ns.centroid_apart
    assert 0 < apart < part and centres
    assert f"centroid: {part} partly covered pixels, {apart} with another value;" in printed
    # M3, S1, S2
    assert "(MLAA, SMAA)" in md and "(TAAU, DLSS, FSR, XeSS)" in md
    assert "At 16 the standard pattern rounds one way" in md
    assert "memory grows like $S$, bandwidth up to $S$" in " ".join(md.split()) or (
        "memory grows like $S$, bandwidth up to" in md
    )


def test_lesson_08_review_r287_tie_row_clamp_alone_centroid_reason_and_minus(ns):
    """Review r287 M1: the standards table has a row for the tie rule per sample, and the
    llvmpipe cell measures it on a fan whose spokes pass through 4-sample positions (§4's fan
    has none there). S1: the row "not reprojected, clamped" is discussed: as few ghosts behind
    as with reprojection, none ahead, yet the worst error. S4: a reason for teachraster's
    centroid rule. S2: the explorer's shape chooser is greyed out at filter width 0. S3: the
    verdict and the inspector's edge values use the minus sign."""
    from notebook_runs import executed, streams

    from teachraster.plotting.antialiasing import edge_value_text
    from teachraster.widgets.predict import Predict
    from teachraster.widgets.sampling_explorer import SamplingExplorer

    _, sources, md = _lesson_text()
    words = " ".join(md.split())
    (table,) = [s for s in sources if s.startswith("### The lesson's rules, standard by standard")]
    (row,) = [r for r in table.splitlines() if r.startswith("| the tie rule, per sample (§4)")]
    for told in ("§14.6.6 *Polygon Multisample Rasterization*", "§14.6.1's", "§3.4.2.1",
                 "*Basic Polygon Rasterization*", "`tr.is_top_left`", "no rule named"):  # fmt: skip
        assert told in row, told
    assert table.count("\n| ") == 8 and "Seven rules of §2–§4 and §6" in table
    printed = streams(executed("08_antialiasing").notebook())
    if "no OpenGL here:" not in printed:
        assert ns.gl_same["§4's fan, 4-sample hub"] and ns.ties == 20
        # review r327 S4: the line names its fan
        assert (
            f"    ties in the 4-sample-hub fan (on a spoke two triangles share): {ns.ties}"
            in printed
        )
    # S1: the numbers the sentence quotes, printed in cell 49's table
    e, split = ns.crawl_errors, ns.ghost_split
    alone, both = split["history, not reprojected, clamped"], split["history, reprojected, clamped"]
    assert alone["ahead"] == 0 and abs(alone["behind"] - both["behind"]) <= 2
    worst = e["history, not reprojected, clamped"]
    assert worst == max(v for k, v in e.items() if k.startswith("history"))
    assert (f"the trail falls as far ({alone['behind']}, all behind) and nothing blurs ahead, "
            f"yet of the histories it errs most ({worst:.3f}): the clamp hides a missing "
            "reprojection") in words  # fmt: skip
    # S4
    assert ("keeps the centre, where MSAA's own value already lies inside the triangle") in words
    # S2
    explorer = SamplingExplorer(backend="image")
    try:
        assert explorer.kernel.disabled
        explorer.width.value = 1.0
        assert not explorer.kernel.disabled
    finally:
        explorer.close()
    # S3
    assert edge_value_text(-4.86) == "−4.86" and edge_value_text(4.86) == "+4.86"
    q = Predict("exponent?", answer=-0.74, tolerance=0.05, headless=False)
    try:
        q.control.value = "-0.6"
        q.check.click()
        said = q.feedback.value
        assert "<b>−0.6</b>; the answer is <b>−0.74 (± 0.05)</b>" in said and "-0." not in said
    finally:
        q.close()


def test_lesson_08_review_r313_ghosts_outlined_circles_floor_rms_and_maintenance10(ns):
    """Review r313. FIG1: the TAA panels outline each history's ghost pixels by side (half of
    them too faint to see in colour), the text says so. FIG2: q_levels' circles as large as
    q_sliver's. FIG3: the floor figure shows only the rows where 1 sample departs from the
    reference. S1: the discrepancy paragraph tells mean |error| from RMS. S2: the Vulkan sRGB
    row names VK_KHR_maintenance10."""
    import json
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "notebooks" / "08_antialiasing.ipynb"
    cells = {c["id"]: "".join(c["source"]) for c in json.loads(path.read_text())["cells"]}
    assert "ghost_masks(image[None], crawl_16[last][None], MOTION)" in cells["30cda8d6"]
    words = " ".join(cells["836112a2"].split())
    # r475 S7: the four histories one line each
    assert "Moving (ghosts outlined): - Not reprojected, the history trails" in words
    assert '"o", ms=8,' in cells["7dcf3ede"] and "ms=5" not in cells["7dcf3ede"]
    far = ns.floor_crop
    floor_rows = np.flatnonzero(ns.on_floor.any(axis=(1, 2, 3)))
    assert far.stop - far.start <= 0.6 * len(floor_rows)  # 10 of 19 rows
    departs = np.abs(ns.floor_images["1 sample"] - ns.floor_reference).mean(axis=(1, 2))
    assert (departs[far] > 0.01).any() and (departs[far.stop :] <= 0.01).all()
    held = " ".join(ns.FASTEST_TEXT.split())
    assert "These are means of |error|; Mitchell's statement is about the variance" in held
    assert "so its RMS error falls like jittered's, $S^{-3/4}$" in held
    row = next(line for line in cells["6ff4236c"].splitlines() if line.startswith("| sRGB"))
    assert "`VK_KHR_maintenance10` reports which and may let the application require" in row
