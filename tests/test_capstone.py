"""The capstone (issue 30): the student's functions render the built-in scenes through the
pipeline's stage overrides; every scene passes with correct functions, and a wrong one is
explained at its first differing pixel by the stage where the pixel histories part."""

from __future__ import annotations

import numpy as np
import pytest
import reasoning_solutions as sol
import student_variants as sv

import teachraster as tr
from teachraster import edge_function
from teachraster import exercises as ex
from teachraster.exercises.capstone_render import SCENES


def _mine(scene, **changed):
    return {name: changed.get(name, sol.CAPSTONE[name]) for name in SCENES[scene].uses}


@pytest.mark.parametrize("scene", list(SCENES))
def test_every_scene_passes_with_correct_functions(scene):
    report = ex.capstone(scene, **_mine(scene))
    assert report.passed, str(report)
    assert "all 1728 pixels match" in str(report) and "cases pass" in str(report)


def _top_right(xy, p):  # covers centres on right edges instead of left ones
    return sol.covers(np.array(xy) * [-1, 1], np.array(p) * [-1, 1])


def _one_winding(xy, p):  # covers only triangles whose E(v1, v2, v3) > 0
    return bool(edge_function(*np.asarray(xy, float)) > 0 and sol.covers(xy, p))


def _texel_corners(tex, uv, wrap):  # bilinear at x = u·W (no −½)
    t = np.asarray(tex, float)
    h, w = t.shape[:2]
    x, y = uv[0] * w, uv[1] * h
    x0, y0 = int(np.floor(x)), int(np.floor(y))
    fx, fy = x - x0, y - y0
    at = lambda r, c: t[r % h, c % w]  # noqa: E731
    return (at(y0, x0) * (1 - fx) * (1 - fy) + at(y0, x0 + 1) * fx * (1 - fy)
            + at(y0 + 1, x0) * (1 - fx) * fy + at(y0 + 1, x0 + 1) * fx * fy)  # fmt: skip


def _straight_over(src, dst):  # GL's SRC_ALPHA over: premultiplies the glass a second time
    src, dst = np.asarray(src, float), np.asarray(dst, float)
    return src * src[3] + dst * (1 - src[3])


def _a_buffer_onto(depths, colours, background, order=None, step=sol.over_premultiplied):
    result = np.asarray(background, float)
    for k in np.argsort(-np.asarray(depths)) if order is None else order:
        result = np.asarray(step(colours[k], result))
    return result


def _drawing_order(depths, colours, background):  # what the GPU's blending gives
    return _a_buffer_onto(depths, colours, background, range(len(depths)))


def _nearest_first(depths, colours, background):  # sorted the wrong way round
    return _a_buffer_onto(depths, colours, background, np.argsort(depths))


def _under(depths, colours, background):  # correct: nearest first with the under step
    acc = np.zeros(4)
    for k in np.argsort(depths):
        acc = acc + (1 - acc[3]) * np.asarray(colours[k])
    return acc + (1 - acc[3]) * np.asarray(background)


def _own_alpha(depths, colours, background):  # r137 D12-1: each later one by its own 1 − α
    acc = np.zeros(4)
    for k in np.argsort(depths):
        acc = acc + np.asarray(colours[k]) * (1 if acc[3] == 0 else 1 - colours[k][3])
    return acc + (1 - acc[3]) * np.asarray(background) if acc[3] < 1 else acc


def _reset(depths, colours, background):  # r131 D12-3: the transmittance reset, not multiplied
    acc, t = np.zeros(4), 1.0
    for k in np.argsort(depths):
        acc, t = acc + t * np.asarray(colours[k]), 1 - colours[k][3]
    return acc + t * np.asarray(background)


def test_a_buffer_passes_nearest_first_with_under_too():
    """A correct resolve that goes the other way (exercise 9's under step) passes."""
    assert ex.capstone("glass_sorted", over=sol.over_premultiplied, a_buffer=_under).passed


def _nearest_level(pyramid, uv, lod, wrap):  # trilinear reading the nearest level only
    return sol.bilinear(pyramid[int(np.clip(np.round(lod), 0, len(pyramid) - 1))], uv, wrap)


WRONG = [
    ("floor_bilinear", {"bilinear": sv.WRONG["bilinear as the floor texel"][1]},
     "texture filtering", "nearest filtering"),  # r6: named only as "blend the four texels"
    ("grid", {"covers": _top_right}, "coverage", "the top-left rule"),
    ("single_triangle", {"barycentric": lambda xy, p: np.roll(sol.barycentric(xy, p), 1)},
     "interpolation", "your barycentric returned"),
    ("textured_floor", {"perspective_weights": lambda lam, w: lam}, "interpolation",
     "your perspective_weights(λ, w) returned"),
    ("glass", {"over": _straight_over}, "blending", "your over(src, dst)"),
    ("floor_trilinear", {"trilinear": lambda p, uv, lod, w: sol.bilinear(p[0], uv, w)},
     "texture filtering", "your trilinear"),
    ("cube_msaa", {"resolve": lambda c, i, b: np.nanmean(c, axis=0)}, "resolve",
     "your resolve returned"),
    ("sphere", {"depth_passes": lambda d, w: [True] * len(d)}, "depth test", "depth_passes"),
    # each stage also names the mistake, as the function's own exercise names it
    ("single_triangle", {"barycentric": lambda xy, p: np.roll(sol.barycentric(xy, p), 1)},
     "interpolation", "the barycentric exercise's check names the mistake: the same numbers in "
     "another order"),
    ("textured_floor", {"perspective_weights": lambda lam, w: lam * w / (lam @ w)},
     "interpolation", "names the mistake: you multiplied λ by w"),
    ("glass", {"over": _straight_over}, "blending",
     "over's check (lesson 12b §4's premultiplied over: ex.check(\"over_premultiplied\", over) "
     "runs it) names the mistake: you multiplied the source colour by its alpha again"),
    # the A-buffer: each order mistake named in words, not only the numbers
    ("glass_sorted", {"a_buffer": _drawing_order}, "sorting",
     "the likely mistake: you composited in drawing order"),
    ("glass_sorted", {"a_buffer": _nearest_first}, "sorting",
     "the likely mistake: you laid each fragment over the result in order of increasing depth"),
    ("glass_sorted", {"a_buffer": lambda d, c, b: _a_buffer_onto(d, c, np.zeros(4))},
     "A-buffer resolve", "the likely mistake: you composited the fragments onto transparent "
     "black"),  # r84 12-3: not "sorting" (one fragment, or the background forgotten)
    # a_buffer calls the student's own over: a wrong over shows first, at the blending stage
    ("glass_sorted", {"over": _straight_over, "a_buffer": lambda d, c, b: _a_buffer_onto(
        d, c, b, step=_straight_over)}, "blending", "you multiplied the source colour by its alpha again"),
    ("grid", {"covers": _one_winding}, "coverage", "whose vertices run counter-clockwise"),
    ("floor_bilinear", {"bilinear": _texel_corners}, "texture filtering",
     "you sampled at texel corners"),
    ("floor_trilinear", {"trilinear": _nearest_level}, "texture filtering", "(the nearest)"),
    # the capstone's floor is tinted by ramps and tiled past [0, 1]: a transposed or clamping
    # filter no longer draws the package's frame
    ("floor_bilinear", {"bilinear": lambda t, uv, w: sol.bilinear(t, uv[::-1], w)},
     "texture filtering", "your bilinear(texture, uv, 'repeat') returned"),
    ("floor_bilinear", {"bilinear": lambda t, uv, w: sol.bilinear(t, uv, "clamp")},
     "texture filtering", "your bilinear(texture, uv, 'repeat') returned"),
    # the green copy of triangle 0 ties it bit for bit: a wrong tie rule shows it, and is named
    # no typical mistake fits: the function's own check still says what is wrong, in words
    ("single_triangle", {"barycentric": lambda xy, p: np.abs(sol.barycentric(xy, p)) + 0.1},
     "interpolation", "the barycentric exercise's check, on its own cases, says: at p="),
    ("floor_bilinear", {"bilinear": lambda t, uv, w: np.zeros(3)}, "texture filtering",
     "your function returns (0, 0, 0) on every case"),
    # r423 (fixex06b): named, not only "your answer holds NaN"
    ("cube_msaa", {"resolve": lambda c, i, b: np.asarray(c)[0]}, "resolve",
     "that is sample 0's colour as given"),
    # r137 D12-1: the two panes' alphas differ (0.6, 0.45), so the pane's own 1 − α fails
    ("glass_sorted", {"a_buffer": _own_alpha}, "sorting", "the A-buffer's resolve gives"),
    ("glass_sorted", {"a_buffer": _reset}, "sorting", "your alpha 1.18 is above 1"),
    ("glass_sorted", {"a_buffer": lambda d, c, b: np.ones(4)}, "A-buffer resolve",  # 1 fragment
     "your a_buffer returns (1, 1, 1, 1) whatever the fragments"),
    ("grid", {"covers": lambda xy, p: False}, "coverage", "your function never covers anything"),
    ("intersecting_triangles", {"depth_passes": sv.WRONG["passes with <="][1]}, "depth test",
     "use <, not <="),
    ("intersecting_triangles", {"depth_passes": sv.WRONG["against the previous fragment"][1]},
     "depth test", "the one just before it"),
    ("intersecting_triangles", {"depth_passes": lambda d, w: [True] * len(d)}, "depth test",
     "returned [True, True, True], the package's test passes [True, True, False] (strictly "
     "nearer than the depth last written): your function lets every fragment pass, always"),
]  # fmt: skip


def _unsigned(xy, p):  # barycentrics from unsigned areas: right inside, wrong outside
    return np.abs(sol.barycentric(xy, p))


_LE, _PREVIOUS = sv.WRONG["passes with <="][1], sv.WRONG["against the previous fragment"][1]
_LEFT_ONLY = sv.WRONG["covers forgetting top edges"][1]
_MASKLESS = sv.WRONG["glass writes depth"][1]

#: Wrong functions a scene's own pixels cannot see (every centre inside, glass that writes no
#: depth, a sphere with no tie): each must still fail, on its own exercise's cases or in the
#: capstone scene that sees it (r5: all of these passed).
BLIND = [
    ("glass", {"depth_passes": lambda d, w: [True] * len(d)},
     "depth_passes exercise's own cases", "lets every fragment pass"),
    ("glass", {"depth_passes": _LE}, "depth_passes exercise's own cases", "use <, not <="),
    ("single_triangle", {"barycentric": _unsigned}, "barycentric exercise's own cases",
     "signed"),
    ("textured_floor", {"barycentric": _unsigned}, "barycentric exercise's own cases", "signed"),
    ("sphere", {"barycentric": _unsigned}, "barycentric exercise's own cases", "signed"),
    ("sphere", {"covers": sv.WRONG["covers with E >= 0"][1]}, "the grid scene", "E ≥ 0"),
    ("sphere", {"covers": sv.WRONG["covers with E > 0"][1]}, "the grid scene", "E > 0"),
    ("sphere", {"depth_passes": _LE}, "the intersecting_triangles scene", "use <, not <="),
    ("sphere", {"depth_passes": _PREVIOUS}, "the intersecting_triangles scene",
     "the one just before it"),
    # r6: ties on left edges only (no grid centre lies on a horizontal edge), and a depth
    # write where writes[k] is False (every fragment of these scenes writes): both passed
    ("grid", {"covers": _LEFT_ONLY}, "covers exercise's own cases", "on left edges"),
    ("sphere", {"covers": _LEFT_ONLY}, "covers exercise's own cases", "on left edges"),
    ("intersecting_triangles", {"depth_passes": _MASKLESS}, "depth_passes exercise's own cases",
     "leaves the buffer"),
    ("sphere", {"depth_passes": _MASKLESS}, "depth_passes exercise's own cases",
     "leaves the buffer"),
]  # fmt: skip


@pytest.mark.parametrize("scene, changed, where, words", BLIND,
                         ids=[f"{b[0]}-{b[3][:12]}" for b in BLIND])  # fmt: skip
def test_a_wrong_function_the_scene_cannot_see_fails_where_it_shows(scene, changed, where, words):
    report = ex.capstone(scene, **_mine(scene, **changed))
    assert not report.passed, str(report)
    last = report.failures[-1].explanation
    assert where in last and words in last, str(report)
    if report.n_wrong == 0:  # r49: the headline must not read like a pass
        assert ": fails, though all" in str(report).splitlines()[0], str(report)


@pytest.mark.parametrize("scene, changed, stage, words", WRONG,
                         ids=[f"{w[0]}-{w[3][:12]}" for w in WRONG])  # fmt: skip
def test_a_wrong_function_is_found_at_its_stage(scene, changed, stage, words):
    report = ex.capstone(scene, **_mine(scene, **changed))
    assert not report.passed and report.n_wrong > 0
    first = report.failures[0]
    assert first.kind == stage and words in first.explanation, str(report)
    assert report.differing_pixels().shape == (report.n_wrong, 2)


def _float32(fn):  # the student's function computing in float32 (imread's type)
    def in_float32(*args):
        args = [np.asarray(a, np.float32) if isinstance(a, np.ndarray) and a.dtype.kind == "f"
                else a for a in args]  # fmt: skip
        return np.asarray(fn(*args), dtype=np.float32)

    return in_float32


FLOAT32 = [
    ("single_triangle", "barycentric"),
    ("textured_floor", "perspective_weights"),
    ("floor_bilinear", "bilinear"),
    ("cube_msaa", "resolve"),
    ("glass", "over"),
    ("glass_sorted", "a_buffer"),
]


@pytest.mark.parametrize("scene, name", FLOAT32)
def test_a_float32_function_passes_and_is_named(scene, name):
    """float32 within its rounding is right in the capstone too (not failed, and said)."""
    report = ex.capstone(scene, **_mine(scene, **{name: _float32(sol.CAPSTONE[name])}))
    assert report.passed, str(report)
    assert f"your {name} answers are float32" in str(report), str(report)
    assert "float32" not in str(ex.capstone(scene, **_mine(scene)))


def test_unfinished_raising_and_wrong_types_name_the_function():
    def stub(*args):
        raise NotImplementedError()

    report = ex.capstone("sphere", **_mine("sphere", perspective_weights=stub))
    assert report.not_implemented and "perspective_weights raises" in str(report)
    report = ex.capstone("grid", covers=lambda xy, p: None)
    assert report.failures[0].kind == "none" and "your covers returned None" in str(report)
    report = ex.capstone("grid", covers=lambda xy, p: 1 / 0)
    assert "your covers raised ZeroDivisionError" in str(report)
    report = ex.capstone("intersecting_triangles", depth_passes=lambda d, w: [True])
    assert "one True/False per fragment" in str(report)


def test_bad_calls_are_errors_naming_the_argument():
    with pytest.raises(ValueError, match="scene must be one of"):
        ex.capstone("teapot", covers=sol.covers)
    with pytest.raises(TypeError, match="missing"):
        ex.capstone("grid")
    with pytest.raises(TypeError, match="covers must be a function"):
        ex.capstone("grid", covers=3)


def test_compare_draws_three_panels_with_the_first_pixel_marked():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.capstone("grid", covers=_top_right)
    fig, axes = plt.subplots(1, 3)
    artists = report.compare(axes)
    assert artists and "differ" in axes[2].get_title()
    assert axes[2].get_xlabel().startswith("pixel (")
    plt.close(fig)
    ties = ex.capstone("intersecting_triangles", depth_passes=sv.WRONG["passes with <="][1])
    fig, axes = plt.subplots(1, 3)
    assert ties.compare(axes) and "differ" in axes[2].get_title()  # the tie scene draws too
    plt.close(fig)

    def unfinished(xy, p):
        raise NotImplementedError

    for stub in (ex.capstone("grid", covers=lambda xy, p: None),
                 ex.capstone("single_triangle", barycentric=unfinished)):  # fmt: skip
        fig, axes = plt.subplots(1, 3)
        stub.compare(axes)
        assert axes[2].get_title() == "nothing to compare yet", axes[2].get_title()  # r6
        plt.close(fig)


def test_the_time_limit_is_the_classes_and_prints_are_kept_aside(monkeypatch, capsys):
    """An endless covers stops within the budget (raised by the lecturer's variable); a
    debug print per pixel is kept aside, not sent line by line."""
    from endless_loops import forever

    from teachraster.exercises.running import BUDGET_VARIABLE

    report = ex.capstone("grid", covers=forever, budget=0.2)
    assert report.failures[0].kind == "timeout" and "0.2 s" in str(report), str(report)
    # r40 12-6: the pipeline calls covers once per pixel by design; no hint that it should not
    assert "a Python call per pixel?" not in str(report) and "once per pixel" in str(report)
    monkeypatch.setenv(BUDGET_VARIABLE, "0.4")
    report = ex.capstone("grid", covers=forever, budget=0.2)
    assert "0.4 s" in str(report), str(report)
    monkeypatch.delenv(BUDGET_VARIABLE)
    capsys.readouterr()

    def chatty(xy, p):
        print("pixel", p)
        return sol.covers(xy, p)

    report = ex.capstone("grid", covers=chatty)
    assert report.passed and report.printed is not None and "printed" in str(report)
    assert capsys.readouterr().out.count("\n") < 100


def _over_rgb_only(src, dst):  # blends RGB, leaves the destination's alpha as it was
    out = sol.CAPSTONE["over"](src, dst)
    out = np.array(out, dtype=float)
    out[3] = np.asarray(dst, dtype=float)[3]
    return out


@pytest.mark.parametrize("scene", ["glass", "glass_sorted"])
def test_an_over_that_leaves_alpha_alone_fails_the_glass_on_its_own_cases(scene):
    """The glass's background is opaque (alpha 1 whatever over does to alpha): the over
    exercise's own cases see the alpha the scene cannot."""
    report = ex.capstone(scene, **_mine(scene, over=_over_rgb_only))
    assert not report.passed and report.n_wrong == 0, str(report)
    assert "your over fails over's own cases (lesson 12b §4" in report.failures[-1].explanation


def test_capstone_headings_are_numbered_in_order_and_the_sphere_claims_what_it_sees():
    """12.1 to 12.10 without a gap; the sphere (no centre on an edge, no equal depths) says
    where its ties are checked instead (the grid and the green copy), and a `<=` depth test
    fails it there."""
    import inspect
    import json
    import re
    from pathlib import Path

    path = Path(__file__).parents[1] / "notebooks/exercises/12_capstone.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    text = ["".join(c["source"]) for c in cells if c["cell_type"] == "markdown"]
    numbers = [int(n) for t in text for n in re.findall(r"^## 12\.(\d+)", t, re.M)]
    assert numbers == list(range(1, len(numbers) + 1)), numbers
    sphere = next(t for t in text if "All of it at once" in t)
    # the CPU limit is said where students read it (r5: 30 s of CPU, 88 s of wall time, unsaid)
    setup = "".join(cells[1]["source"])
    assert "ex.CAPSTONE_BUDGET" in setup and "a second or so;" not in text[0]
    assert inspect.signature(ex.capstone).parameters["budget"].default == ex.CAPSTONE_BUDGET
    le = sv.WRONG["passes with <="][1]
    assert not ex.capstone("sphere", **_mine("sphere", depth_passes=le)).passed
    assert "When one of them is wrong" not in sphere and "12.1" in sphere and "12.4" in sphere


def test_another_pixel_is_explained_and_the_overdraw_is_shown_where_only_it_differs():
    """r5: report.explain_pixel raised on every capstone report, and the grid's E >= 0 drew
    two identical frames beside a red diagonal (only the overdraw differs there)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.capstone("grid", covers=sv.WRONG["covers with E >= 0"][1])
    row, col = (int(v) for v in report.differing_pixels()[-1])
    said = report.explain_pixel(row, col)
    assert said.startswith(f"pixel ({row}, {col}), coverage:") and "E ≥ 0" in said, said
    assert report.explain_pixel(0, 0) == "pixel (0, 0) matches the package's"
    with pytest.raises(ValueError, match="row, col"):
        report.explain_pixel(99, 0)
    fig, axes = plt.subplots(1, 3)
    report.compare(axes)
    assert "overdraw" in axes[0].get_title() and "overdraw" in axes[1].get_title()
    yours, ours = (ax.get_images()[0].get_array() for ax in axes[:2])
    assert not np.array_equal(yours[row, col], ours[row, col])
    plt.close(fig)
    fig, axes = plt.subplots(1, 3)
    ex.capstone("grid", covers=_top_right).compare(axes)  # the frames differ: the frames
    assert "overdraw" not in axes[0].get_title()
    plt.close(fig)


def test_numbers_in_capstone_sentences_are_this_pixels_or_said_to_be_the_exercises():
    """A mistake named through the exercise's own case says so (r5: exercise 1's E = -135 and
    "triangle 1" read as the grid's triangle 113's), and float noise prints short."""
    from teachraster.exercises.scalars import vec

    report = ex.capstone("grid", covers=_one_winding)
    assert "names the mistake: in its own case" in report.failures[0].explanation, str(report)
    assert vec([0.737, 0.522, 0.9199999999999999], [0.735, 0.521, 0.92]) == "(0.737, 0.522, 0.92)"
    assert vec([0.735, 0.521, 0.92], [0.737, 0.522, 0.9199999999999999]) == "(0.735, 0.521, 0.92)"
    assert vec([0.8], [0.8000000000000002]) != vec([0.8000000000000002], [0.8])  # apart


#: r40 12-1: one-line wrappers of the package's own functions passed these scenes, though
#: ``ex.check`` refuses the very same lambdas ("not counted").
WRAPPERS = [
    ("single_triangle", {"barycentric": lambda xy, p: tr.barycentric(xy, [p])[0]},
     "barycentric"),
    ("floor_bilinear", {"bilinear": lambda t, uv, w: tr.sample(t, uv, "bilinear", w)}, "sample"),
    ("floor_trilinear", {"trilinear": lambda p, uv, lod, wrap="repeat":
                         tr.sample(p, uv, "trilinear", wrap, lod=lod)}, "sample"),
    ("sphere", {"bilinear": lambda t, uv, w: tr.sample(t, uv, "bilinear", w)}, "sample"),
]  # fmt: skip


@pytest.mark.parametrize("scene, changed, called", WRAPPERS, ids=[w[0] for w in WRAPPERS])
def test_a_wrapper_of_the_packages_answer_draws_the_frame_but_does_not_count(
    scene, changed, called
):
    report = ex.capstone(scene, **_mine(scene, **changed))
    name = next(iter(changed))
    assert not report.passed and not report.failures and report.n_wrong == 0, str(report)
    text = str(report)
    assert "pixels match the package's, but not counted" in text, text
    assert f"your {name} calls teachraster's {called}" in text, text
    # r174 12-9: the assertion names the scene, the printed report says why (not counted)
    with pytest.raises(AssertionError, match="does not pass: the report printed above"):
        report.assert_passed()


def test_a_bilinear_that_swaps_u_and_v_fails_the_sphere():
    """r40 12-2: the sphere's untinted checkerboard is its own transpose, so a u/v swap drew
    it right; tinted like the floor, it shows."""
    swapped = lambda t, uv, w: sol.CAPSTONE["bilinear"](t, (uv[1], uv[0]), w)  # noqa: E731
    report = ex.capstone("sphere", **_mine("sphere", bilinear=swapped))
    assert not report.passed and report.n_wrong > 0, str(report)
    assert report.failures[0].kind == "texture filtering", str(report)


def test_the_glass_in_drawing_order_marks_what_the_a_buffer_repairs():
    """r40 12-3: with right functions the glass scene's third panel was empty; the section's
    point, the pixels the A-buffer resolves otherwise, is marked there."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.exercises.capstone_render import contrast_pixels

    report = ex.capstone("glass", **_mine("glass"))
    repaired = contrast_pixels("glass")
    assert report.passed and len(repaired) > 0
    fig, axes = plt.subplots(1, 3)
    report.compare(axes)
    assert f"blue: {len(repaired)}" in axes[2].get_title()
    plt.close(fig)


def test_the_notebook_explains_a_pixel_that_differs_not_a_fixed_one():
    """r49: cell 12's example pointed at a sky pixel, which matched for every floor mistake."""
    import json
    from pathlib import Path

    path = Path(__file__).parents[1] / "notebooks/exercises/12_capstone.ipynb"
    nb = json.loads(path.read_text())
    code = ["".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "code"]
    calls = [c for c in code if "report.explain_pixel(" in c]
    assert calls and all("differing_pixels()" in c for c in calls), calls


def test_a_replay_of_the_package_answers_fails_its_own_drawn_cases():
    """r49: a spy recorded tr.barycentric's answers on a first run; replayed, they passed the
    scene. The exercise's own check, with cases drawn afresh, must refuse them."""
    import teachraster as tr

    record = {}

    def spy(xy, p):
        answer = tr.barycentric(xy, p)
        record[repr((np.asarray(xy).tolist(), np.asarray(p).tolist()))] = answer
        return answer

    ex.capstone("single_triangle", **_mine("single_triangle", barycentric=spy))

    def replay(xy, p):
        key = repr((np.asarray(xy).tolist(), np.asarray(p).tolist()))
        return record.get(key, [1 / 3, 1 / 3, 1 / 3])

    report = ex.capstone("single_triangle", **_mine("single_triangle", barycentric=replay))
    assert report.n_wrong == 0 and not report.passed, str(report)
    assert "barycentric exercise's own cases" in str(report), str(report)


def test_two_covers_mistakes_name_the_one_the_inside_pixel_shows():
    """r49: no winding swap and E > 0 at a pixel strictly inside was blamed on the tie rule
    alone; the winding mistake explains the pixel and must be named."""

    def covers(xy, p):
        return all(edge_function(xy[i], xy[(i + 1) % 3], p) > 0 for i in range(3))

    first = ex.capstone("grid", **_mine("grid", covers=covers)).failures[0].explanation
    assert "strictly inside" in first and "counter-clockwise" in first, first


def test_glass_sorted_says_when_a_buffer_never_called_the_over_passed():
    """r49: a straight-alpha over passed beside an a_buffer that composites with another over
    was said to be hidden by "the opaque background"; the scene never ran it."""

    def over(dst, src):  # straight alpha: the source multiplied by its alpha again
        s, d = np.asarray(src, float), np.asarray(dst, float)
        return s * s[3] + d * (1 - s[3])

    report = ex.capstone("glass_sorted", **_mine("glass_sorted", over=over))
    assert not report.passed
    assert "never calls the over you passed" in str(report), str(report)
    assert "opaque background" not in str(report), str(report)


def test_no_pixel_differs_is_never_said_of_a_scene_not_rendered():
    """r84 12-1: cell 12 printed "no pixel differs" for textured_floor with the stubs as
    shipped (and after an exception or a time-out): the scene was never rendered."""
    import json
    from pathlib import Path

    from endless_loops import forever

    def stub(*args):
        raise NotImplementedError()

    mine = {"barycentric": sol.CAPSTONE["barycentric"], "perspective_weights": stub}
    raised = {"barycentric": lambda xy, p: 1 / 0, "perspective_weights": stub}
    for report in (ex.capstone("textured_floor", **mine),
                   ex.capstone("textured_floor", **raised),
                   ex.capstone("grid", covers=forever, budget=0.2)):  # fmt: skip
        assert len(report.differing_pixels()) == 0
        words = report.no_difference()
        assert "no pixel differs" not in words and "was not rendered" in words, words
        assert report.explain_pixel(0, 0) == words
    assert "perspective_weights raises NotImplementedError" in ex.capstone(
        "textured_floor", **mine).no_difference()  # fmt: skip
    assert "ZeroDivisionError" in ex.capstone("textured_floor", **raised).no_difference()
    right = ex.capstone("single_triangle", **_mine("single_triangle"))
    assert right.no_difference().startswith("no pixel differs: all 1728 pixels match")
    path = Path(__file__).parents[1] / "notebooks/exercises/12_capstone.ipynb"
    code = ["".join(c["source"]) for c in json.loads(path.read_text())["cells"]]
    assert not [c for c in code if '"no pixel differs"' in c]
    assert [c for c in code if "report.no_difference()" in c]


def test_the_a_buffers_order_is_said_only_after_two_wrong_frames():
    """r84 12-2: every failing pixel of glass_sorted said "(farthest first, each nearer
    fragment laid over what lies behind it)" and "sort by depth and start from the farthest":
    12.5's one reasoning step, given by the first wrong run. A hint first, the order after a
    second different wrong frame (as ex.check's hints)."""
    from teachraster.exercises import tries

    def drawing_order(depths, colours, background):
        return _a_buffer_onto(depths, colours, background, order=range(len(depths)))

    def nearest_first(depths, colours, background):
        return _a_buffer_onto(depths, colours, background, order=np.argsort(depths))

    tries.forget_hints("a_buffer")
    try:
        first = str(ex.capstone("glass_sorted", **_mine("glass_sorted", a_buffer=drawing_order)))
        assert "drawing order" in first, first
        for words in ("farthest first", "start from the farthest", "sort by depth"):
            assert words not in first, (words, first)
        again = str(ex.capstone("glass_sorted", **_mine("glass_sorted", a_buffer=drawing_order)))
        assert "farthest first" not in again  # the same wrong frame again: still a hint
        second = str(ex.capstone("glass_sorted", **_mine("glass_sorted", a_buffer=nearest_first)))
        assert "farthest first" in second, second
    finally:
        tries.spend_hints(["a_buffer"])


def test_the_floors_uv_cross_the_borders_on_screen_as_12_7_says():
    """r137 D12-2: 12.7 says the floor's vertices carry (u, v) from −¼ to 1¼ and that on
    screen u crosses 0 and 1 and v crosses 1 (not that v runs from −¼ on screen)."""
    from teachraster.exercises.capstone_scenes import UV_SCALE, UV_SHIFT

    assert (UV_SHIFT, UV_SHIFT + UV_SCALE) == (-0.25, 1.25)
    asked = []

    def probe(texture, uv, wrap):
        asked.append(np.asarray(uv, float))
        return sol.bilinear(texture, uv, wrap)

    assert ex.capstone("floor_bilinear", bilinear=probe).passed
    uv = np.array(asked[: 48 * 20])  # the frame's pixels (the exercise's own cases follow)
    assert uv[:, 0].min() < 0 and uv[:, 0].max() > 1
    assert uv[:, 1].min() > 0 and uv[:, 1].max() > 1
    text = _cell("12.7")
    assert "vertices carry (u, v) from −¼ to 1¼" in text and "u crosses 0 and 1" in text


def _cell(heading: str) -> str:
    """The markdown cell of 12_capstone.ipynb under ``## heading``, its whitespace folded."""
    import json
    from pathlib import Path

    path = Path(__file__).parents[1] / "notebooks/exercises/12_capstone.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    text = ["".join(c["source"]) for c in cells if c["cell_type"] == "markdown"]
    cell = next(t for t in text if t.startswith(f"## {heading} "))
    return " ".join(cell.split())  # the words, whatever the line breaks


def test_the_glass_panes_alphas_are_the_scenes_and_said():
    """r137 D12-1: two different alphas, said in 12.4 and 12.5 as the scene draws them."""
    from teachraster.exercises.capstone_render import GLASS_ALPHA

    assert GLASS_ALPHA == (0.6, 0.45)
    assert "alphas 0.6 and 0.45" in _cell("12.4")
    assert "the red one at alpha 0.6, the blue one at 0.45" in _cell("12.5")
    # r137 D12-3: 12.2 says float32 answers pass exercise 3's own cases here too
    assert "within float32's rounding are accepted" in _cell("12.2")
