"""Issue 30's exercises: correct solutions written differently pass, each typical mistake is
named right in the first explanation (its kind and its words), and the broken frames' hints
are true and never give the answer away."""

from __future__ import annotations

import re

import numpy as np
import pytest
import reasoning_solutions as sol
from exercise_solutions import CORRECT
from student_variants import DIFFERENT, KINDS, WRONG, _hiz_with

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import broken_frames as bf
from teachraster.study.hardcases import naive_coverage


def _passes(name, fn):
    report = ex.check(name, fn)
    assert report.passed, str(report)


def _named(name, fn, kind, words):
    report = ex.check(name, fn)
    assert not report.passed
    first = report.failures[0]
    assert first.kind == kind, (kind, str(report))
    assert words in first.explanation, (words, first.explanation)
    return report


# -- robust_fill -----------------------------------------------------------------------------
def _fill(**kw):
    def fill(xy, width, height, origin=(0, 0)):
        v = np.asarray(xy, float) if kw.get("raw") else np.rint(np.asarray(xy, float) * 256) / 256
        return naive_coverage(v, width, height, origin=tuple(origin),
                              rule=kw.get("rule", "top_left"), dtype=kw.get("dtype", np.float64),
                              absolute=kw.get("absolute", False))  # fmt: skip

    return fill


# -- quad_derivatives ------------------------------------------------------------------------
def _quad(change):
    from teachraster import barycentric, perspective_weights

    def quad_derivatives(xy, w, f, row, col):
        def value(x, y):
            lam = barycentric(xy, [x, y])
            if change == "affine":
                return float(lam @ f)
            return float(perspective_weights(lam[None], w, extrapolate=change != "clamp")[0] @ f)

        r0, c0 = (row, col) if change == "unaligned" else (row - row % 2, col - col % 2)
        ul = value(c0 + 0.5, r0 + 0.5)
        dx, dy = value(c0 + 1.5, r0 + 0.5) - ul, value(c0 + 0.5, r0 + 1.5) - ul
        return (dx, -dy) if change == "up" else (dx, dy)

    return quad_derivatives


def step(bits):
    return 1 / (2**bits - 1)


def solve(s, z, gap, far):
    """The near plane where step (f - n) z² / (f n) = gap."""
    return s * far * z * z / (gap * far + s * z * z)


# Correct solutions written differently and typical mistakes (their words and kinds) are in
# student_variants.py (DIFFERENT, WRONG, KINDS), run by test_checker_corpus.py.


def test_every_issue_30_exercise_has_correct_variants_and_named_mistakes():
    issue_30 = set(ex.names()) - set(CORRECT)
    assert issue_30 == set(sol.CORRECT)
    wrong = {name for name, _, _ in WRONG.values()}
    different = {name for name, _ in DIFFERENT.values()}
    frames = {f"broken_frame_{n}" for n in range(1, 7)}
    assert issue_30 - frames <= wrong & different
    assert {label for label, (name, _, _) in WRONG.items() if name in issue_30} <= set(KINDS)


def test_perspective_weights_that_overflow_are_told_only_ratios_matter():
    report = ex.check("perspective_weights", lambda lam, w: (lam / w) / (lam / w).sum())
    assert {f.kind for f in report.failures} == {"overflow"}, str(report)
    assert "only the ratios" in report.failures[0].explanation


def test_safe_near_never_blames_float32_for_a_named_mistake():
    report = _named("safe_near", lambda z, g, f, b: solve(1 / 2**b, z, g, f), "2^bits", "step")
    assert all("float32's rounding" not in f.explanation for f in report.failures)


def test_robust_fill_names_the_absolute_form_and_fails_the_naive_fill_often():
    report = ex.check("robust_fill", _fill(rule="top_left", absolute=True, dtype=np.float32))
    assert "absolute form" in {f.kind for f in report.failures}, str(report)
    naive = ex.check("robust_fill", _fill(raw=True, rule="inclusive"))
    assert len(naive.failures) >= 5  # the naive fill fails the catalogue in many places


@pytest.mark.parametrize(
    ("tie", "kind"),
    [(lambda a, b: b[1] < a[1], "no top edges"),
     (lambda a, b: b[1] == a[1] and b[0] > a[0], "no left edges")],
)  # fmt: skip
def test_robust_fill_names_a_forgotten_tie_case_on_every_failure(tie, kind):
    """A fill that forgets half of the top-left rule only misses pixels: every failure names
    the forgotten half, never a reversed rule, E > 0 or the unsnapped orientation."""
    from student_variants import _fill_with

    report = ex.check("robust_fill", _fill_with(tie=tie))
    assert report.failures and {f.kind for f in report.failures} == {kind}, str(report)


def test_robust_fill_names_a_reversed_rule_first_and_a_forgotten_one_only_where_it_misses():
    """A reversed tie rule gives every answer: it is named on every failure, the first
    included (r5: a reversed top rule was first called "no top edges"); a forgotten one only
    misses pixels, and is named only where pixels are missing only."""
    from student_variants import _fill_with, _owns_bottom_left, _owns_top_right, _owns_y_up_both

    forgotten = {"no top edges", "no left edges", "E > 0"}
    for tie, kind in ((_owns_bottom_left, "top edge reversed"),
                      (_owns_top_right, "left edge reversed"),
                      (_owns_y_up_both, "both reversed")):  # fmt: skip
        report = ex.check("robust_fill", _fill_with(tie=tie))
        assert {f.kind for f in report.failures} == {kind}, str(report)
    for tie in (
        lambda a, b: False,
        lambda a, b: b[1] < a[1],
        lambda a, b: b[1] == a[1] and b[0] > a[0],
    ):
        for f in ex.check("robust_fill", _fill_with(tie=tie)).failures:
            missing, extra = (int(n) for n in re.findall(r"(\d+) missing, (\d+) extra",
                                                         f.explanation)[-1])  # fmt: skip
            assert f.kind in forgotten and missing > 0 and extra == 0, f.explanation


def test_robust_fill_names_a_coarse_grid_never_float32_or_orientation():
    """Snapping to 1/16 px (4 sub-pixel bits) is a coarser grid, on every failure: never
    float32 (its vertices are float64) nor the unsnapped orientation (r5)."""
    from student_variants import _fill_with

    for grid in (16, 64, 2):
        report = ex.check("robust_fill", _fill_with(grid=grid))
        assert {f.kind for f in report.failures} == {"coarse snapping"}, str(report)
        assert "float32" not in str(report) and "unsnapped" not in str(report)


def test_the_naive_fills_report_shows_each_family_of_its_failures_first():
    """The naive fill (raw vertices, E >= 0, absolute float32) fails ties, snapping and
    precision at once: one failure of each family comes first, the far case says precision
    (r5: 48 failures of kind "value" hid the float32 and snapping ones)."""
    report = ex.check("robust_fill", _fill(raw=True, rule="inclusive", absolute=True,
                                           dtype=np.float32))  # fmt: skip
    shown = report.shown()
    kinds = [f.kind for f in shown]
    assert {"far from origin", "off the grid", "zero area"} <= set(kinds), kinds
    far = next(f for f in shown if f.kind == "far from origin")
    assert "precision" in far.explanation and "float32" in far.explanation


def test_robust_fill_blames_float32_only_where_its_spacing_and_the_answer_say_so():
    """The far-from-origin (precision) words need float32 coarser than 1/256 px (beyond
    2^16 px) and an answer a float32 evaluation gives (r6: said at 10013 px, where float32
    is 1/1024 px apart, to an E >= 0 fill, and to a transposed float64 fill)."""
    from student_variants import _fill_with

    def transposed(xy, width, height, origin=(0, 0)):  # built [col, row], origin read (x, y)
        return _fill_with()(xy, height, width, (origin[1], origin[0])).T

    naive = _fill_with(snap=False, dtype=np.float32, vertices=np.float32, tie=lambda a, b: True)
    report = ex.check("robust_fill", naive)
    near = [f for f in report.failures if f.case == "far_from_origin at 10000 px"]
    assert near and all(f.kind == "E >= 0" for f in near), str(report)
    report = ex.check("robust_fill", transposed)
    assert "far from origin" not in {f.kind for f in report.failures}, str(report)
    assert "float32" not in str(report) and "precision" not in str(report), str(report)


def test_robust_fill_task_keeps_the_goal_and_leaves_the_causes_to_the_checker():
    """Exercise 10's task names no fix: the catalogue's failures, explained, teach them."""
    import json
    from pathlib import Path

    path = Path(__file__).parents[1] / "notebooks/exercises/10_hard_cases.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    task = next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == "robust_fill_task")
    text = "".join(task["source"])
    for fix in ("np.rint", "1/256", "top-left rule", "winding", "snap"):
        assert fix not in text, fix


def test_quad_derivatives_clamped_at_helpers():
    report = ex.check("quad_derivatives", _quad("clamp"))
    assert report.failures and report.failures[0].kind == "clamped", str(report)


def test_hiz_rejects_without_the_vertex_clamp():
    report = ex.check("hiz_rejects", _hiz_with(clamp=False))
    assert "no clamp" in {f.kind for f in report.failures}, str(report)


# -- broken frames ---------------------------------------------------------------------------
ANSWERS = {1: "depth function", 2: "culled winding", 3: "z-fighting",
           4: "missing premultiplication", 5: "blend order", 6: "sliver"}  # fmt: skip
STAGE = {1: "depth test", 2: "culling", 3: "depth test", 4: "blending", 5: "blending",
         6: "coverage"}  # fmt: skip
PAIRS = [(1, 2), (3, 4), (5, 6)]


def _showing(number):
    """The first pixel the check accepts for frame ``number``."""
    return next((int(r), int(c)) for r, c in np.argwhere(bf._differs(number))
                if bf._shows(number, r, c))  # fmt: skip


def _strings(value, depth=0, seen=None):
    """Every text reachable from ``value``'s public attributes, dict values and items (the
    render settings' strings too): what a student can read off the object without a
    history."""
    seen = set() if seen is None else seen
    if id(value) in seen or depth > 6 or isinstance(value, np.ndarray | int | float):
        return
    seen.add(id(value))
    if isinstance(value, str):
        yield value
        return
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _strings(k, depth + 1, seen)
            yield from _strings(v, depth + 1, seen)
        return
    if isinstance(value, tuple | list | frozenset | set):
        for v in value:
            yield from _strings(v, depth + 1, seen)
        return
    yield repr(value) if type(value).__repr__ is not object.__repr__ else ""
    for name in dir(value):
        if name.startswith("_") or name in ("cache",):
            continue
        try:
            attr = getattr(value, name)
        except Exception:
            continue
        if not callable(attr):
            yield from _strings(attr, depth + 1, seen)


@pytest.mark.parametrize("number", list(ANSWERS))
def test_broken_frame_objects_students_get_do_not_carry_the_answer(number):
    """Adversarial: the frame, the intended frame and the symptom only; no public attribute,
    repr or __dict__ value (down to the render settings) names the cause or the words of its
    gloss; and the frame was rendered with exactly the settings of the intended one (the
    mistake is in what is drawn), so comparing settings tells nothing."""
    b = ex.broken_frame(number)
    public = {a for a in dir(b) if not a.startswith("_")}
    assert public == {"number", "symptom", "frame", "intended"}, public
    texts = " ".join([repr(b), str(b), *map(repr, vars(b).values()), *_strings(b)]).lower()
    cause = ANSWERS[number]
    for telling in {cause, cause.replace("-", " "), cause.replace(" ", "_")}:
        assert telling not in texts, telling
    for word in ("front", "unorm16", "float64", "straight", "fight", "order", "thin"):
        assert word not in b.symptom.lower()

    def settings(frame):
        i, blend = frame.trace.debug.inputs, frame.trace.debug.blend
        return (i.width, i.height, i.depth_test, i.cull, i.depth_format, i.interpolation,
                i.subpixel_bits, frame.samples is None, blend.mode, blend.color_format,
                tuple(blend.clear_color))  # fmt: skip

    assert settings(b.frame) == settings(b.intended)
    assert str(b.frame.plan) == str(b.intended.plan) == bf.WITHHELD
    with pytest.raises(KeyError, match="withheld"):
        b.frame.plan["culling"]


def test_broken_frame_plans_are_the_same_text_within_each_pair_and_the_evidence_is_private():
    """r7: frame 2's plan said "cull='back' asked: 6 back-facing triangle(s) removed" beside
    frame 1's "not asked", and ``ex.broken_frames.parts_at`` returned the answer's stage."""
    for a, b in PAIRS:
        one, two = ex.broken_frame(a), ex.broken_frame(b)
        assert str(one.frame.plan) == str(two.frame.plan)
        assert str(one.intended.plan) == str(two.intended.plan)
    for name in ("parts_at", "SIGNATURES", "hint"):
        assert not hasattr(bf, name), name
        assert not hasattr(ex, name), name
    assert not any(n in bf.__dict__ for n in dir(ex) if n in ("parts_at", "SIGNATURES"))


def test_broken_frames_come_in_look_alike_pairs_told_apart_only_by_their_histories():
    """Each pair: one symptom, the same picture and the same intended picture pixel for pixel,
    two causes (among them the look-alikes the brief names: depth function / culled winding,
    z-fighting / missing premultiplication, blend order / sliver); their histories part from
    the intended ones at different stages."""
    for a, b in PAIRS:
        one, two = ex.broken_frame(a), ex.broken_frame(b)
        assert one.symptom == two.symptom
        assert np.array_equal(bf._rgb(one.frame), bf._rgb(two.frame))
        assert np.array_equal(bf._rgb(one.intended), bf._rgb(two.intended))
        assert bf._answer(a) != bf._answer(b)
        assert not np.array_equal(bf._rgb(one.frame), bf._rgb(one.intended))
        stages = {bf._parts_at(n, *_showing(n)) for n in (a, b)}
        assert stages == {STAGE[a], STAGE[b]}
    assert not ex.broken_frame(1).frame.trace.culled.any()
    assert ex.broken_frame(2).frame.trace.culled.any()


def test_broken_frame_causes_are_listed_alphabetically_never_in_the_frames_order():
    """r8: cell 1 printed the causes in the frames' order (causes 1-6 = frames 1-6), an
    answer key. The public list and the notebook's print are alphabetical, and the causes
    that occur do not come in the frames' order."""
    import json
    from pathlib import Path

    assert list(bf.CAUSES) == sorted(bf.CAUSES)
    shown = [c for c in bf.CAUSES if c in ANSWERS.values()]
    assert shown != [ANSWERS[n] for n in sorted(ANSWERS)]
    nb = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/exercises/11_broken_frames.ipynb").read_text())  # fmt: skip
    setup = "".join(nb["cells"][1]["source"])
    assert "sorted(ex.CAUSES.items())" in setup
    with pytest.raises(Exception) as info:  # a misspelt cause lists them, in the same order
        bf.as_diagnosis(("no such cause", (1, 1), "coverage"))
    listed = [c for c in bf.CAUSES if c in str(info.value)]
    assert str(info.value).index(listed[0]) < str(info.value).index(listed[-1])
    assert listed == sorted(listed)


def test_broken_frame_6_accepts_only_pixels_the_sliver_crosses():
    """r8: 36 of the 96 accepted pixels (the solution's own (23, 40) among them) lay in the
    sliver's bounding box only. Each accepted pixel's box holds a point of the sliver (found by
    sampling its edges densely, not by the check's own test), and (23, 40) is refused."""
    frame = ex.broken_frame(6).frame
    xy = frame.trace.window[int(np.argmin(bf._altitudes(frame))), :, :2]
    t = np.linspace(0, 1, 200_001)[:, None]  # along its three edges: it is 0.1 px thick
    points = np.concatenate([a + t * (b - a) for a, b in zip(xy, np.roll(xy, -1, axis=0))])
    crossed = {(int(y), int(x)) for x, y in points}
    accepted = {(int(r), int(c)) for r, c in np.argwhere(bf._differs(6)) if bf._shows(6, r, c)}
    assert accepted and accepted <= crossed, sorted(accepted - crossed)
    assert (22, 40) in accepted and (23, 40) not in accepted


def test_broken_frame_texts_do_not_pair_a_task_with_its_cause():
    """The symptoms say what is seen, never the mechanism, and frame 1's task text shares no
    telling word with the cause list (r5: "mapping" in both gave frame 1 away)."""
    import json
    from pathlib import Path

    nb = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/exercises/11_broken_frames.ipynb").read_text())  # fmt: skip
    tasks = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]).lower()
             for c in nb["cells"] if c["metadata"].get("nbgrader", {}).get("grade_id", "")
             .endswith("_task")}  # fmt: skip
    for word in (r"mapping", r"reversed", r"1 − d", r"\bless\b"):
        assert not re.search(word, tasks["frame_1_task"]), word
        assert not re.search(word, bf.CAUSES["depth function"].lower()), word
    for n, cause in ANSWERS.items():
        assert cause not in tasks[f"frame_{n}_task"]
    symptoms = " ".join(ex.broken_frame(n).symptom.lower() for n in ANSWERS)
    for telling in ("depth write", "dotted", "gap", "too bright", "wrong faces", "hidden",
                    "behind", "in front", "vanish", "thin", "stripe", "glow", "dash"):  # fmt: skip
        assert telling not in symptoms, telling
    for key, gloss in bf.CAUSES.items():  # a cause, never the symptom it leaves
        for telling in ("vanish", "shows only", "stripe", "dark", "bright", "missing"):
            assert telling not in gloss, (key, gloss)


def _verdict(number, answer):
    """The first explanation of ``answer``, with the session's try count cleared (it is the
    one thing that may change between two wrong answers)."""
    bf._TRIES.clear()
    report = ex.check(f"broken_frame_{number}", lambda: answer)
    assert not report.passed, answer
    assert [f.kind for f in report.failures] == ["not right"], str(report)
    return report.failures[0].explanation


@pytest.mark.parametrize("number", list(ANSWERS))
def test_broken_frame_right_answer_passes_and_every_wrong_one_gets_one_verdict(number):
    """r7: 38 blind calls solved all six, the right stage being the one whose message
    changed. Now every wrong combination of cause, pixel and stage (the right pixel, a pixel
    the mistake left alone, the pixel as (x, y), a changed pixel whose history lacks the
    cause) gets the identical words, which name no part."""
    assert bf._answer(number) == ANSWERS[number]
    row, col = _showing(number)
    assert bf._parts_at(number, row, col) == STAGE[number]
    _passes(f"broken_frame_{number}",
            lambda: (ANSWERS[number].upper(), (row, col), STAGE[number].upper()))  # fmt: skip
    pixels = [(row, col), tuple(int(v) for v in np.argwhere(~bf._differs(number))[0])]
    if col < bf.H:
        pixels.append((col, row))
    lacking = [(int(r), int(c)) for r, c in np.argwhere(bf._differs(number))
               if not bf._shows(number, r, c)]  # fmt: skip
    pixels += lacking[:1]
    said = set()
    for cause in bf.CAUSES:
        for pixel in pixels:
            for stage in bf.STAGES:
                if (cause, pixel, stage) == (ANSWERS[number], (row, col), STAGE[number]):
                    continue
                said.add(_verdict(number, (cause, pixel, stage)))
    assert len(said) == 1, said
    (words,) = said
    assert "1 try of frame" in words and "same corners on screen" in words, words
    for telling in (*bf.STAGES, *bf.CAUSES, f"({row}, {col})", "changed, but", "the same in"):
        assert telling not in words, (telling, words)


def test_broken_frame_tries_are_counted_per_frame():
    bf._TRIES.clear()
    for _ in range(3):
        ex.check("broken_frame_3", lambda: ("sliver", (1, 1), "coverage"))
    said = ex.check("broken_frame_3", lambda: ("sliver", (1, 1), "coverage"))
    assert "4 tries of frame 3 recorded" in said.failures[0].explanation, str(said)
    assert bf._TRIES == {3: 4}


def test_broken_frame_5_stage_compares_triangles_by_their_corners_not_their_records():
    """r7: at (20, 31) of frame 5 the first records differ ('not_covered' beside 'passed':
    the strip is drawn first, so triangle 0 is another triangle in each frame), yet the
    histories first differ at 'blending', matching each triangle by its corners on screen;
    the verdict says so, and no longer "from the first record"."""
    b = ex.broken_frame(5)
    first = [h.records[0].outcome for h in (b.frame.history(20, 31), b.intended.history(20, 31))]
    assert first == ["not_covered", "passed"]
    assert bf._parts_at(5, 20, 31) == "blending"
    words = _verdict(5, ("blend order", (20, 31), "coverage"))
    assert "first record" not in words and "whatever its number" in words, words
    _passes("broken_frame_5", lambda: ("blend order", (20, 31), "blending"))


def test_broken_frame_1_and_6_causes_say_what_their_frames_show():
    """Frame 1 tests LESS on reversed depths (its history shows the smaller depth kept, the
    farther surface of the intended mapping). Frame 6's strip is thinner than a pixel and
    covers no centre, though its history reaches many pixels."""
    one = ex.broken_frame(1)
    row, col = _showing(1)
    rec = [
        r for r in one.frame.history(row, col).records if r.outcome in ("passed", "failed_depth")
    ]
    kept = [r for r in rec if r.shown][0]
    assert all(kept.depth < r.depth for r in rec if r.outcome == "failed_depth")
    meant = {r.triangle: r.depth for r in one.intended.history(row, col).records
             if r.outcome in ("passed", "failed_depth")}  # fmt: skip
    assert meant[kept.triangle] == max(meant.values())  # the farther surface, as meant
    assert "farther surface" in bf.CAUSES["depth function"]
    six = ex.broken_frame(6)
    assert bf._thinnest(six.frame) < 0.2 and bf._thinnest(six.intended) > 1
    assert not (six.frame.triangle_id == 2).any()
    # r7 11-6: the intended frame is the strip modelled 2 px thick, not the sliver drawn
    # with more samples: the cause names the geometry, never "with one sample per pixel"
    assert "modelled thinner" in bf.CAUSES["sliver"]
    assert "drawn with one sample per pixel" not in bf.CAUSES["sliver"]
    assert six.frame.samples is None and six.intended.samples is None


def test_broken_frames_3_to_6_draw_their_glass_without_depth_writes():
    """The glass writes no depth (lesson 11 §6): in frame 5 the wall drawn after it passes,
    nothing is rejected, and the order alone hides the strip; in frame 4 the pane's colour
    is its straight one, in the intended frame that times its alpha."""
    b = ex.broken_frame(5)
    records = [r for r in b.frame.history(23, 41).records if r.outcome != "not_covered"]
    glass = [r for r in records if r.color and r.color[3] < 1]
    assert glass and not any(r.depth_write for r in glass)
    assert all(r.outcome == "passed" for r in records)
    four = ex.broken_frame(4)
    pane = [r.color for r in four.frame.history(24, 20).records if r.color and r.color[3] < 1]
    meant = [r.color for r in four.intended.history(24, 20).records
             if r.color and r.color[3] < 1]  # fmt: skip
    pane, meant = pane[0], meant[0]
    assert np.allclose(np.array(meant[:3]), np.array(pane[:3]) * pane[3])


def test_broken_frame_answers_are_read_strictly():
    report = ex.check("broken_frame_1", lambda: ("the depth", (3, 4), "culling"))
    assert report.failures[0].kind == "type" and "not one of the causes" in str(report)
    report = ex.check("broken_frame_1", lambda: "depth function")
    assert report.failures[0].kind == "type" and "only the cause" in str(report)
    report = ex.check("broken_frame_1", lambda: ("depth function", (24, 28)))
    assert report.failures[0].kind == "type" and "without the stage" in str(report)
    report = ex.check("broken_frame_1", lambda: ("depth function", (24, 28), "raster"))
    assert "not one of the stages" in str(report)
    report = ex.check("broken_frame_1", lambda: ("depth function", (99, 4), "culling"))
    assert "outside" in str(report)
    report = ex.check("broken_frame_1", lambda: ("depth function", (24.7, 31.2), "culling"))
    assert report.failures[0].kind == "type" and "row 24.7 is not an integer" in str(report)
    report = ex.check("broken_frame_1", lambda: ("depth function", (24, True), "culling"))
    assert report.failures[0].kind == "type" and "col is a bool" in str(report)
    _passes("broken_frame_1", lambda: ("depth function", (np.int64(24), 28), "depth test"))


def test_the_frame_inspector_shows_the_broken_frames():
    pytest.importorskip("ipywidgets")
    from teachraster.widgets import FrameInspector

    frames = ex.frames_to_inspect()
    assert list(frames)[:4] == ["frame 1", "intended 1", "frame 2", "intended 2"]
    assert frames["intended 5"] is ex.broken_frame(5).intended and len(frames) == 12
    w = FrameInspector(frames=frames, backend="image")
    try:
        assert list(w.scene.options) == list(frames) and w.frame is frames["frame 1"]
        assert w.samples.disabled and w.glass.disabled and not w.scene.disabled
        w.scene.value = "frame 2"
        w.click_at(30.5, 20.5)
        assert w.history.outcomes == frames["frame 2"].history(20, 30).outcomes
        assert "culled" in w.table.value
        w.scene.value = "intended 2"
        w.click_at(30.5, 20.5)
        assert w.history.outcomes == frames["intended 2"].history(20, 30).outcomes
    finally:
        w.close()
    untraced = tr.render(tr.get_scene("cube").clip(4 / 3), 8, 6)
    with pytest.raises(ValueError, match="trace=True"):
        FrameInspector(frames={"a": untraced})
    with pytest.raises(TypeError, match="non-empty dict"):
        FrameInspector(frames={})


def test_broken_frame_numbers_are_checked():
    assert ex.broken_frame(np.int64(3)).number == 3
    with pytest.raises(TypeError, match="number must be an int"):
        ex.broken_frame(True)
    with pytest.raises(TypeError, match="number must be an int"):
        ex.broken_frame(3.0)
    with pytest.raises(ValueError, match="1 to 6"):
        ex.broken_frame(7)


RIGHT = dict(sol.CORRECT)
FIRST_WRONG = {}
for _name, _fn, _ in WRONG.values():
    FIRST_WRONG.setdefault(_name, _fn)
for _n in range(1, 7):  # a cause that is not the frame's
    FIRST_WRONG.setdefault(
        f"broken_frame_{_n}",
        lambda n=_n: ("sliver" if n != 6 else "z-fighting", (24, 28), "coverage"),
    )


@pytest.mark.parametrize("name", list(RIGHT))
def test_reports_draw_passing_failing_and_missing(name):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    def stub(*args):
        raise NotImplementedError

    for fn in (RIGHT[name], FIRST_WRONG[name], stub):
        report = ex.check(name, fn)
        if fn is stub:
            assert report.not_implemented and "not implemented yet" in str(report)
        fig, ax = plt.subplots(figsize=(3, 3))
        artists = report.plot(ax)
        assert artists and ax.get_title().startswith(name)
        fig.canvas.draw()
        plt.close(fig)


def test_an_unnormalised_barycentric_is_told_that_its_own_weights_sum_wrong():
    """r5: "the weights are (0.4, 0.2, 0.4), which sum to 25" (it is the student's λ)."""
    report = ex.check("barycentric", lambda xy, p: sol_areas(xy, p))
    first = report.failures[0].explanation
    assert "which sum to" not in first and "; yours sum to" in first, first


def sol_areas(xy, p):
    """λ not divided by E(v1, v2, v3)."""
    v1, v2, v3 = np.asarray(xy, float)
    return np.array([tr.edge_function(v2, v3, p), tr.edge_function(v3, v1, p),
                     tr.edge_function(v1, v2, p)])  # fmt: skip


def test_the_fill_plot_leaves_the_titles_corner_free():
    """r5: the check plot's title ran into the y tick "0" at the top edge."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("robust_fill", _fill(raw=True, rule="inclusive"))
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    assert min(ax.get_yticks()) > min(ax.get_ylim()), ax.get_yticks()
    plt.close(fig)


def test_broken_frame_cause_alone_reads_plainly():
    """A cause without its evidence is told to add it (r6: "return the value itself, not a
    string")."""
    said = ex.check("broken_frame_1", lambda: "depth function").failures[0].explanation
    assert "only the cause" in said and "(cause, (row, col), stage)" in said, said
    assert "not a string" not in said, said


# -- over_premultiplied (9.2): derived from the straight rule ---------------------------------
def test_over_premultiplied_is_derived_and_a_wrong_answer_never_gets_the_factors():
    """Exercise 9.2 gives Porter and Duff's straight rule only; the derivation's slips are
    named (the straight rule copied onto premultiplied colours, the result divided back to
    straight, a side multiplied by its alpha again, the weights swapped), and no explanation
    hands over the answer's factors (before: 'glBlendFunc(ONE, ONE_MINUS_SRC_ALPHA)' and
    'src + dst·(1 − α)' after any wrong answer made it transcription again)."""
    import json
    from pathlib import Path

    from student_variants import KINDS, WRONG

    labels = [k for k, (name, _, _) in WRONG.items() if name == "over_premultiplied"]
    assert {KINDS[k] for k in labels if k in KINDS} >= {
        "straight rule on premultiplied", "returned straight", "destination premultiplied twice",
        "weights swapped"}  # fmt: skip
    tries = [WRONG[k][1] for k in labels] + [lambda s, d: np.asarray(s) * 0.5 + d[3]]
    for fn in tries:
        report = ex.check("over_premultiplied", fn)
        assert not report.passed
        for f in report.failures:
            for answer in ("ONE_MINUS_SRC_ALPHA", "src + dst", "glBlendFunc(ONE"):
                assert answer not in f.explanation, f.explanation
    last = ex.check("over_premultiplied", tries[-1]).failures[0].explanation
    assert "your 9.2a with src and dst written as c = α·C" in last, last
    nb = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/exercises/09_lines_and_blending.ipynb").read_text())  # fmt: skip
    task = next("".join(c["source"]) for c in nb["cells"]
                if c["metadata"]["nbgrader"]["grade_id"] == "over_premultiplied_task")  # fmt: skip
    # r8: the task gives the coverage argument, not the straight form's formula to transcribe
    assert "straight" in task and "1 − α_s" in task and "divided by α" in task
    for answer in ("ONE_MINUS_SRC_ALPHA", "src + dst", "c_s + c_d", "GL_ONE", "α_d·(1 − α_s)",
                   "α_s + α_d"):  # fmt: skip
        assert answer not in task, answer


def test_exercise_9_2_credits_the_straight_form_rightly_and_asks_what_lesson_12_does_not_print():
    """r7 09-1: "Porter and Duff ... give over for straight colours" was wrong (they work
    premultiplied); 09-2: lesson 12 §9 prints the premultiplied rule, so 9.2 first asks for
    straight inputs returned premultiplied, which it does not print."""
    import json
    from pathlib import Path

    nb = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/exercises/09_lines_and_blending.ipynb").read_text())  # fmt: skip
    text = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]) for c in nb["cells"]}
    task = text["over_premultiplied_task"]
    assert "Porter and Duff" in task and "give *over* for **straight**" not in task
    assert "over_to_premultiplied(src, dst)" in task and "lesson 12, §9" not in task
    assert "over_to_premultiplied_check" in text and "over_premultiplied_step" in text
    said = str(ex.check("over_premultiplied", lambda s, d: np.asarray(s) * 0.5 + d[3]))
    assert "your 9.2a with src and dst" in said and "Porter and Duff's rule" not in said, said
    lesson = json.loads(Path(__file__).parents[1].joinpath(
        "notebooks/12_lines_and_blending.ipynb").read_text())  # fmt: skip
    printed = " ".join("".join(c["source"]) for c in lesson["cells"])
    # the Summary names the exercise's functions (r8); no cell defines or computes it
    assert "def over_to_premultiplied" not in printed and "over_to_premultiplied(" not in printed
    from teachraster.exercises.blending import from_straight

    src, dst = [0.2, 0.4, 0.6, 0.5], [1.0, 0.5, 0.0, 0.5]
    assert np.allclose(from_straight(src, dst), [0.35, 0.325, 0.3, 0.75])  # 0.6·0.5 + 0·0.5·0.5
    _passes("over_to_premultiplied", sol.over_to_premultiplied)
    said = str(ex.check("over_to_premultiplied", from_straight))
    assert "not counted" in said or "package" in said, said
    _named("over_to_premultiplied", lambda s, d: np.asarray(s) + np.asarray(d) * (1 - s[3]),
           "inputs not premultiplied", "as if they were premultiplied")  # fmt: skip
    _named("over_to_premultiplied",
           lambda s, d: np.r_[np.asarray(s[:3]) * s[3] + np.asarray(d[:3]) * (1 - s[3]),
                              s[3] + d[3] * (1 - s[3])],
           "destination alpha ignored", "α_d·(1 − α_s)")  # fmt: skip


def test_the_fill_legend_lists_only_the_states_drawn():
    """r6 10-3: the legend listed "missing (the rule covers it)" where no pixel was missing."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("robust_fill", _fill(rule="inclusive"))  # E >= 0: extra pixels only
    assert not report.passed
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    plt.close(fig)
    assert "covered" in labels and any(t.startswith("extra") for t in labels), labels
    assert not any(t.startswith("missing") for t in labels), labels


def test_broken_frame_figure_marks_the_pixel_on_both_pictures_under_a_short_title():
    """r7 11-10: the pixel was marked on the broken frame only, and the title was cut."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    report = ex.check("broken_frame_5", lambda: ("blend order", (20, 31), "coverage"))
    fig, ax = plt.subplots(figsize=(7, 4))
    report.plot(ax)
    xs = sorted(min(line.get_xdata()) for line in ax.lines)
    assert xs == [31, 31 + bf.W + 12], xs
    assert ax.get_title() == "broken_frame_5 fails: the diagnosis", ax.get_title()
    plt.close(fig)
