"""Review r426 (exercise 07): F1 an exception inside the student's own pixel_lod, trilinear or
bilinear is told per case, from what that case's call was given (one record, the last call's,
had been read for every case); F2 junk that filters the pyramid at a vertex's (u, v) never
unlocks 7.4's steps; F3 a λ per triangle is named and never counts as a try; F4 (u, v) halved
for the coarser level is named; P1 7.4 does not ask what 7.1's figure above it answers; FIG1 a
raising case's figure marks its pixel."""

from __future__ import annotations

import json
from pathlib import Path

import student_variants as sv

from teachraster import exercises as ex
from teachraster.exercises import pixel_level as pl
from teachraster.exercises import pixel_sampler as ps
from teachraster.exercises import tries
from teachraster.exercises.scalars import num, vec

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "07_texture_filtering.ipynb"


def _own_numbers(failure) -> tuple[str, str]:
    """This failure's case's own (u, v) and λ as the words print them."""
    case = next(c for c in ps.sample_cases() if c[0] == failure.case)
    pyramid, xy, w, uv, row, col, _ = case[1]
    lod = pl.expected_lod(xy, w, uv, ps.level_size(pyramid), row, col)
    return vec(ps.pixel_uv(xy, w, uv, row, col)), num(lod)


def test_each_raising_case_quotes_its_own_numbers():
    """F1: two cases raising in the student's bilinear at different (u, v) (and a case between
    them that does not raise), each told with its own (u, v); NaN λ cases with their own λ."""
    _, fn, _, _ = sv.R426_PIXEL[
        "pixel sample whose own bilinear forgets to clamp the indices for 'clamp' (raises)"
    ]
    raised = [f for f in ex.check("pixel_sample", fn).failures
              if f.got is None and f.case.startswith("floor")]  # fmt: skip
    assert len({_own_numbers(f)[0] for f in raised}) >= 2, [f.case for f in raised]
    for f in raised:
        uv, _ = _own_numbers(f)
        assert (
            f"inside your bilinear (which your trilinear calls), called with (u, v) = {uv};"
            in f.explanation
        ), (f.case, f.explanation)
    _, fn, _, _ = sv.R426_PIXEL["pixel sample with its own pixel_lod NaN on odd rows"]
    for f in ex.check("pixel_sample", fn).failures:
        if not f.case.startswith("floor"):
            continue  # a drawn case: drawn afresh by each check
        uv, _ = _own_numbers(f)
        assert f"called with (u, v) = {uv}, λ = nan: λ is not a number" in f.explanation, f.case


def test_a_raising_case_is_told_when_the_last_case_passes():
    """F1: the tip (λ above the pyramid) raises in the student's own unclamped trilinear and
    the last case passes: 7.3's words with the tip's own λ, never a bare IndexError; an own
    pixel_lod raising is named; a None from the student's bilinear is not blamed on a NaN λ."""
    fails = []
    for label in ("pixel sample whose own trilinear has no clamp (pyramid[lower + 1] past q)",
                  "pixel sample whose own pixel_lod raises at a helper outside the triangle",
                  "pixel sample with its own pixel_lod NaN on odd rows and its own bilinear "
                  "returning None"):  # fmt: skip
        report = ex.check("pixel_sample", sv.R426_PIXEL[label][1])
        assert len(report.failures) < len(ps.sample_cases()) or "None" in label
        fails.append(report.failures)
    tip = next(f for f in fails[0]
               if "the far tip" in f.case)  # fmt: skip
    uv, lod = _own_numbers(tip)
    assert (
        f"inside your trilinear, called with (u, v) = {uv}, λ = {lod}: at λ = {lod}, ⌊λ⌋ = 3 "
        "is already the last level"
    ) in tip.explanation, tip.explanation
    assert all(
        "it raised inside your pixel_lod" in f.explanation for f in fails[1] if f.got is None
    )
    even = next(f for f in fails[2]
                if "pixel (28, 14), 8×8 pyramid" in f.case)  # fmt: skip
    assert "on a None" in even.explanation and "λ = nan" not in even.explanation, even.explanation


def test_junk_at_a_vertex_uv_and_a_per_triangle_lod_never_unlock_the_steps():
    """F2, F3: the pyramid filtered at the mean of the vertices' (u, v) with λ = 0, then level
    0 at vertex 0's (u, v) (7.4); a λ per triangle twice, then ptp junk (7.1): none counts."""
    samples = [sv._r426("pixel_sample", "def pixel_sample(pyramid, xy, w, uv, row, col, wrap):\n"
                        f"    return {body}\n")
               for body in ("trilinear(pyramid, np.mean(np.asarray(uv, float), 0), 0, wrap)",
                            "bilinear(pyramid[0], np.asarray(uv, float)[0], wrap)")]  # fmt: skip
    lods = [
        sv.R426_PIXEL[f"pixel lod with one λ per triangle, {how}"][1]
        for how in ("texel area over pixel area", "the longest edge in texels over pixels")
    ]
    lods.append(sv._r426("pixel_lod", "def pixel_lod(xy, w, uv, size, row, col):\n    return "
                         "float(np.log2(max(size) * np.ptp(np.asarray(uv, float)))) - 2\n"))  # fmt: skip
    for name, rule, fns in (("pixel_sample", ps.RULE, samples), ("pixel_lod", pl.RULE, lods)):
        tries.forget_hints(name)
        for fn in fns:
            said = str(ex.check(name, fn))
            assert rule not in said and "at which point" not in said.split("(u, v) taken")[-1]
        assert not tries.hints_spent(name), name
        tries.forget_hints(name)
    said = str(ex.check("pixel_sample", samples[1]))
    assert "another quad of this triangle, the filtered value is" in said, said
    assert "yours is 0.373 at both: does your value depend on the pixel" in said, said
    tries.forget_hints()


def test_7_4_asks_only_what_7_1s_figure_does_not_answer():
    """P1: 7.1's passing figure draws (27, 3)'s quad and the helpers that give its λ: 7.4 no
    longer asks which pixels give it, only where the texture is read."""
    cells = {c["metadata"]["nbgrader"]["grade_id"]: "".join(c["source"]).replace("\n", " ")
             for c in json.loads(NOTEBOOK.read_text())["cells"]}  # fmt: skip
    task = cells["pixel_sample_task"]
    assert "which pixels' values give its λ" not in task
    assert "7.1's figure above shows which of them give its λ" in task
    assert "at which point is the texture read for (27, 3), and why there?" in task


def test_a_raising_cases_figure_marks_its_pixel(plt):
    """FIG1: the floor drawn for a case with no answer marks that case's pixel too."""
    fn = sv.R426_PIXEL[
        "pixel sample whose own bilinear forgets to clamp the indices for 'clamp' (raises)"
    ][1]
    report = ex.check("pixel_sample", fn)
    first = report.failures[0]
    assert first.got is None and "pixel (9, 15)" in first.case
    fig, ax = plt.subplots()
    report.plot(ax)
    assert "(9, 15)" in {t.get_text() for t in ax.texts}


def test_no_record_of_one_function_is_read_for_another():
    """F1: the records are per case and per function: a passing function checked after a
    raising one is not told the other's exception words."""
    fn = sv.R426_PIXEL["pixel sample with its own pixel_lod NaN on odd rows"][1]
    assert not ex.check("pixel_sample", fn).passed
    assert ex.check("pixel_sample", sv._r426("pixel_sample", "")).passed
    assert ps._RUNNING["raised in"] == {}


def test_7_1s_fail_figure_says_why_its_quad_is_not_drawn(plt):
    """FIG2: before the hints are spent a failing 7.1 figure draws no quad, and says why."""
    tries.forget_hints("pixel_lod")
    fig, ax = plt.subplots()
    ex.check("pixel_lod", sv._lod405(EXTRAP="False")).plot(ax)
    tries.forget_hints("pixel_lod")
    assert "its quad not drawn: which it is, is question (1)" in ax.get_xlabel()
