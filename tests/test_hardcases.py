"""The hard-case catalogue (``teachraster.study.hardcases``): every case, every fill method.

Each case is run with each fill method it applies to and checked against its ``expect``;
screen-space cases are also checked against the exact reference rasteriser of ``conftest``
(written from CONVENTIONS alone), and the two fill methods must agree pixel for pixel. Every
naive variant must really differ from ours, so that lesson 07 shows a real difference.
"""

import warnings

import numpy as np
import pytest
from conftest import explain, reference_coverage

import teachraster as tr
from teachraster.study import hardcases as hc

RUNS = [(name, method) for name, case in hc.CASES.items() for method in case.methods]
SCREEN = [name for name, case in hc.CASES.items() if case.triangles is not None]
NAIVE = [name for name, case in hc.CASES.items() if case.has_naive]

# What issue 5 asks the catalogue to hold, as the case names that cover it.
REQUIRED = {
    "the Direct3D split square": ["d3d_split_square", "d3d_split_square_other_diagonal"],
    "fans with spokes through pixel centres": ["fan_spokes_through_centres"],
    "all six vertex orders": ["six_vertex_orders"],
    "flat, near-flat, collinear, coincident": [
        "flat_top", "flat_bottom", "near_flat", "collinear", "coincident_vertices",
    ],
    "sub-pixel triangles": ["subpixel_triangles"],
    "slivers": ["sliver_pair", "diagonal_sliver"],
    "far from the origin": ["far_from_origin"],
    "translation invariance": ["translation_invariance"],
    "snapping flips winding or degenerates": ["snap_flips_winding", "snap_degenerate"],
    "incremental stepping drift": ["stepping_drift"],
    "behind the eye, w = 0, w = 1e-9": [
        "behind_camera", "eye_plane_vertex", "hair_in_front_of_eye",
    ],
    "perspective denominators near zero": ["perspective_w_ratio_1e6", "perspective_w_scale"],
    "coplanar and nearly coplanar depth": ["coplanar_overlap", "nearly_coplanar_overlap"],
}  # fmt: skip


@pytest.fixture(scope="module")
def results():
    """Each (case, method) run once, shared by the tests below; warnings are recorded."""
    cache = {}

    def get(name, method):
        if (name, method) not in cache:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                result = hc.get_case(name).run(method)
            cache[name, method] = (result, [str(w.message) for w in caught])
        return cache[name, method]

    return get


@pytest.mark.parametrize(("name", "method"), RUNS)
def test_case_meets_expectation(results, name, method):
    result, caught = results(name, method)
    hc.get_case(name).check(result)
    assert not caught, f"{name} ({method}): the core warned: {caught}"


@pytest.mark.parametrize("name", SCREEN)
def test_screen_cases_match_exact_reference(results, name):
    case = hc.get_case(name)
    for method in case.methods:
        fills = results(name, method)[0].fills
        assert len(fills) == len(case.triangles)
        for xy, fill in zip(case.triangles, fills):
            height, width = fill.coverage.shape
            want = reference_coverage(xy, width, height)
            assert (fill.coverage == want).all(), f"{method}: " + explain(xy, fill.coverage, want)


@pytest.mark.parametrize("name", [n for n in hc.CASES if len(hc.CASES[n].methods) > 1])
def test_methods_agree(results, name):
    """Half-planes and span tables cover the same pixels and interpolate the same values."""
    a, b = (results(name, m)[0] for m in hc.get_case(name).methods)
    if isinstance(a, hc.Fills):
        for k, (fa, fb) in enumerate(zip(a.fills, b.fills)):
            assert (fa.coverage == fb.coverage).all(), f"triangle {k}: coverage differs"
            for key in fa.attrs:
                np.testing.assert_array_equal(fa.attrs[key], fb.attrs[key])
    elif isinstance(a, hc.Rendered):
        assert (a.coverage == b.coverage).all()
    elif isinstance(a, hc.FarResult):
        for o in a.coverage:
            assert (a.coverage[o] == b.coverage[o]).all(), f"offset {o}: coverage differs"


@pytest.mark.parametrize("name", list(hc.CASES))
def test_case_is_documented(name):
    case = hc.get_case(name)
    assert case.name == name
    for field in ("why", "expect"):
        text = getattr(case, field)
        assert isinstance(text, str) and text.strip(), f"{name}: empty {field}"
        assert "\n" not in text, f"{name}: {field} must be one line"
    assert len(case.why) <= 120, f"{name}: why is not a short line ({len(case.why)} chars)"
    assert case.kind in {"triangle", "triangles", "mesh", "clip", "precision", "depth"}
    if case.has_naive:
        assert case.naive_does.strip() and "\n" not in case.naive_does
    assert case.methods and case.methods[0] in {"halfplane", "span", "batch"}


@pytest.mark.parametrize("name", NAIVE)
def test_naive_really_differs(results, name):
    """Where the catalogue says a naive implementation goes wrong, it really does."""
    case = hc.get_case(name)
    ours = results(name, case.methods[0])[0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # naive code is allowed to divide by zero
        naive = case.naive()
    difference = case.naive_difference(ours, naive)
    assert difference, f"{name}: naive variant ({case.naive_does!r}) shows no difference"


def test_split_square_summary_names_both_kinds_of_difference():
    """Review r6, 07-1: the line said "6 twice" while the naive picture differs at 16 pixels,
    6 on the diagonal and 11 on the right and bottom sides that belong to the neighbours."""
    case = hc.get_case("d3d_split_square")
    ours, naive = case.run(), case.naive()
    twice = int((naive.counts > 1).sum())
    extra = int(((naive.counts > 0) & (ours.counts == 0)).sum())
    differ = int((naive.counts != ours.counts).sum())
    assert (twice, extra, differ) == (6, 11, 16)  # the corner (6, 6) is of both kinds
    line = case.naive_difference(ours, naive)
    assert f"{twice} pixel centre(s) more than once" in line and f"{extra} that ours leaves" in line
    # review r145 07-18: the corner in both sets is said, so that 6 + 11 - 1 = 16 adds up
    both = int(((naive.counts > 1) & (ours.counts == 0)).sum())
    assert both == 1 and f"({both} of them in both)" in line and twice + extra - both == differ
    assert line.endswith(f"differs from ours at {differ} pixel(s)")


def test_naive_lines_write_pixels_and_shifts_as_the_lessons_do():
    """Review r304 S-2: the naive lines printed Python lists ([[1, 1], [1, 2], [1, 3]])."""
    for name, said in (("flat_top", "e.g. (1, 1), (1, 2) and (1, 3) (row, column)"),
                       ("translation_invariance", "shifts (1, 0), (0, 3), (10, 3) and (31, 5) px")):  # fmt: skip
        case = hc.get_case(name)
        line = case.naive_difference(case.run(), case.naive())
        assert said in line and "[" not in line, line


def test_registry():
    assert hc.list_cases() == list(hc.CASES)
    assert hc.list_cases("clip") == ["behind_camera", "eye_plane_vertex", "hair_in_front_of_eye"]
    with pytest.raises(ValueError, match="unknown hard case"):
        hc.get_case("no such case")
    with pytest.raises(ValueError, match="method"):
        hc.get_case("flat_top").run("scanline")
    with pytest.raises(ValueError, match="no naive"):
        hc.get_case("coplanar_overlap").naive()
    for topic, names in REQUIRED.items():
        missing = [n for n in names if n not in hc.CASES]
        assert not missing, f"{topic}: missing {missing}"


def test_inputs_are_read_only():
    case = hc.get_case("d3d_split_square")
    with pytest.raises(TypeError):
        case.inputs["size"] = (1, 1)
    with pytest.raises(ValueError):
        case.triangles[0, 0, 0] = 99.0


def test_naive_coverage_matches_core_on_easy_input():
    """The naive helpers agree with the core where no tie or precision issue arises."""
    xy = np.array([[1.3, 1.2], [14.7, 3.1], [5.2, 13.6]])
    core = tr.rasterize(tr.Triangle(xy), 16, 16, subpixel_bits=None).coverage
    for rule in ("inclusive", "strict", "top_left"):
        assert (hc.naive_coverage(xy, 16, 16, rule=rule) == core).all(), rule


def test_fill_window_matches_rasterize():
    """The far-from-origin runner is ``rasterize`` restricted to a window."""
    xy = np.array([[20.5, 18.5], [33.25, 21.5], [24.75, 29.5]])
    f = np.array([0.1, 7.3, -2.9])
    full = tr.rasterize(tr.Triangle(xy, attrs={"f": f}), 40, 40)
    for method in ("halfplane", "span"):
        cov, values = hc.fill_window(xy, f, 16, 16, 16, method)
        assert (cov == full.coverage[16:32, 16:32]).all()
        np.testing.assert_array_equal(values, full.attrs["f"][16:32, 16:32])


def test_depth_cases_show_fighting_as_bits_drop(results):
    """The lesson's table: wrong pixels per format for the nearly coplanar pair."""
    result = results("nearly_coplanar_overlap", "batch")[0]
    for tilt in hc.get_case("nearly_coplanar_overlap").inputs["tilts"]:
        counts = [result.wrong[(fmt, tilt)] for fmt in hc.DEPTH_ORDER]
        assert counts[0] == 0 and counts[-1] > 0, (tilt, counts)


@pytest.mark.parametrize("name", ["collinear", "coincident_vertices"])
def test_zero_area_naive_fills_the_whole_line_as_it_says(name):
    """Review r3 07-1: the naive fill of a zero-area triangle has no bounding box, so it lights
    centres on the line beyond the vertices; the case's text says so (not "the 7 centres")."""
    case = hc.get_case(name)
    lit = np.argwhere(case.naive().counts > 0)[:, ::-1] + 0.5  # (x, y) of the lit centres
    xy = np.unique(np.asarray(case.triangles)[0], axis=0)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    beyond = ((lit < lo) | (lit > hi)).any(axis=1)
    assert beyond.any() and "beyond" in case.naive_does and "no bounding box" in case.naive_does


def test_near_flat_why_puts_point_4_below_v1():
    """Review r98 07-1: "the split point u4 is 1/256 px below v1" read u4, a horizontal
    coordinate, as a height (lesson 01 prints u4 beside v1's u). Point 4 = (u4, v_mid) is the
    point below v1: here the long edge v1-v3 is vertical, so u4 is v1's u exactly."""
    import teachraster as tr

    case = hc.get_case("near_flat")
    v1 = case.triangles[0][0]
    span = tr.rasterize(tr.Triangle(case.triangles[0]), 10, 10, method="span", trace=True)
    span = span.trace.span
    v_mid = span.sorted_xy[1][1]
    assert span.u4 == v1[0] and v_mid - v1[1] == 1 / 256  # point 4: straight below v1
    assert "point 4 = (u4, v_mid), lies 1/256 px below v1" in case.why
    assert "u4 is" not in case.why


def test_drift_along_row_and_perspective_errors():
    """Review r145 07-9, 07-13: lesson 07 plots stepping drift along a row and prints the
    perspective case's error against the exact value; both come from the catalogue."""
    row = hc.drift_along_row(0)
    cols, f32 = row["columns"], row["float32 stepping"]
    assert set(row) == {"columns", "covered", "float32 stepping", "float64 stepping",
                        "ours (direct)"}  # fmt: skip
    # review r150 07-1: the stepper walks all 4096 centres of row 0, as lesson 03's q_drift
    # does; the triangle covers the first 3840, where ours is defined
    assert len(cols) == 4096 and row["covered"].sum() == 3840 and row["covered"][:3840].all()
    assert np.isnan(row["ours (direct)"][3840:]).all()
    assert abs(f32).max() == abs(f32[-1]) and abs(f32[-1]) > 10 * abs(f32[: len(f32) // 8]).max()
    assert round(abs(f32[-1]), 4) == 0.0398  # lesson 03's end error over the same row
    assert abs(f32).max() == hc.get_case("stepping_drift").naive().values["stepped32"]
    # review r150 07-2: the signed error wanders (through zero twice after it passes 1e-4)
    crossings = np.flatnonzero(np.diff(np.sign(f32)) != 0) + 1
    assert [c for c in crossings if abs(f32[:c]).max() > 1e-4] == [615, 2464]
    assert abs(row["float64 stepping"]).max() < 1e-9
    assert np.nanmax(abs(row["ours (direct)"])) < 1e-12
    case = hc.get_case("stepping_drift")
    assert "over the 4096 pixels of row 0" in case.naive_difference(case.run(), case.naive())
    assert "4096-pixel rows" not in case.why and "lesson 03" in case.why
    case = hc.get_case("perspective_w_ratio_1e6")
    errors = hc.perspective_errors(case.inputs, case.run())
    assert len(errors) == len(case.inputs["ws"]) and max(errors) <= 1e-9


def test_translation_invariance_why_says_the_true_thing():
    """Review r150 07-4: 0.3 + 10 == 10.3 in float64; what differs is 10.3 - 10 != 0.3."""
    why = hc.get_case("translation_invariance").why
    assert 0.3 + 10 == 10.3 and 10.3 - 10 != 0.3
    assert f"10.3 - 10 gives {10.3 - 10!r}, not 0.3" in why
    assert "is not exactly 10.3" not in why
