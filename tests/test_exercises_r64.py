"""Review r64 (exercises 01, 04, 08 played as students): what the first failing try may say,
the cost rule of 8.1, the stub's pictures, 8.2's words.

The named mistakes themselves are in ``student_variants.py`` (run by test_checker_corpus); the
constants in test_checker_constants.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from exercise_solutions import CORRECT
from graded_cells import graded_cell
from reasoning_solutions import CORRECT as REASONING
from student_variants import classify_every_centre, classify_pixel_corners

from teachraster import exercises as ex
from teachraster.exercises import tries

ROOT = Path(__file__).resolve().parents[1]


def _first_try(name, fn):
    """The report of a student's first failing check of task ``name`` in a fresh kernel."""
    tries.forget_hints(name)
    try:
        return ex.check(name, fn, budget=60)
    finally:
        tries.forget_hints(name)


def _words(report) -> str:
    return " ".join(f.explanation for f in report.failures)


def test_the_first_try_at_classify_block_does_not_print_the_extreme_centres():
    """r64 08-3: "(extreme centres x = 8.5, 11.5; y = 12.5, 15.5)" headed every failure, the
    constant's too: the answer to "which few points decide an edge"."""
    first = _first_try("classify_block", lambda *a: "partial")
    assert "extreme centres x =" not in _words(first)
    assert "maximising corner" not in _words(first) and "minimising" not in _words(first)
    assert "a hint only" in (first.tries or "")
    # after two different failing answers the full words come
    tries.forget_hints("classify_block")
    ex.check("classify_block", lambda *a: "partial", budget=60)
    later = ex.check("classify_block", lambda *a: "rejected", budget=60)
    tries.forget_hints("classify_block")
    assert "extreme centres x =" in _words(later)


def test_the_first_try_at_hiz_rejects_does_not_say_where_the_depth_is_nearest():
    first = _first_try("hiz_rejects", lambda *a: False)
    assert "extreme centres" not in _words(first) and "nearest at (" not in _words(first)


@pytest.mark.parametrize("name", ["covers", "fill"])
def test_the_first_try_at_coverage_does_not_name_the_kind_of_each_edge(name):
    """r46 E3, r64: "lies exactly on edge v1→v2, a top edge" named what the task asks to work
    out (which directed edges are top or left, with y down)."""
    from student_variants import WRONG

    fn = WRONG["covers with E >= 0" if name == "covers" else "fill with centres at (j, i)"][1]
    words = _words(_first_try(name, fn))
    assert "lies exactly on edge" in words
    for kind in ("top", "left", "right", "bottom"):
        assert f"a {kind} edge:" not in words and f"({kind})" not in words


def test_the_first_try_at_clip_near_gives_no_crossing_t_nor_point():
    """r64 04: the staged hint dropped the formula but still said "at t = 0.475 … at (…)"."""

    def from_the_other_end(v):
        from exercise_solutions import clip_against

        return clip_against(v, t=lambda a, b: (b[2] + b[3]) / ((b[2] + b[3]) - (a[2] + a[3])))

    words = _words(_first_try("clip_near", from_the_other_end))
    assert "crosses the near plane where" in words
    assert "crosses the near plane at t =" not in words and "d_a/(d_a − d_b)" not in words


def test_a_block_scan_of_every_centre_runs_out_of_time_on_the_huge_blocks_only():
    """r64 08-1: testing all size² centres passed every case, though the task asks for a few
    edge tests per edge; the 2^19-px blocks (last) stop it, their label says why, and every
    case before them passes."""
    report = ex.check("classify_block", classify_every_centre)
    assert not report.passed and report.stopped is not None
    (failure,) = report.failures
    assert failure.kind == "timeout" and "2^19" in failure.case
    assert "scan of their" in failure.case and "does not finish" in failure.case
    assert ex.check("classify_block", CORRECT["classify_block"]).passed


def test_the_pixels_top_left_corners_are_named_not_two_corners():
    """r64 08-2: (x0, y0) … (x0 + size − 1, …) was told "you tested only 2 of the 4"."""
    report = ex.check("classify_block", classify_pixel_corners)
    assert {f.kind for f in report.failures} == {"pixel corners"}, str(report)
    assert "½ px right and down" in report.failures[0].explanation


def test_the_stub_scene_shows_no_package_picture(plt):
    """r64 08-6 (and 06, 07): the stub's scene row drew the package's picture (8.1's verdict
    map) beside an empty "yours" and an all-red difference panel."""
    from teachraster.exercises.scenes import STUB_PANELS

    def stub(*args):
        raise NotImplementedError

    for name in ("classify_block", "coverage_fraction", "mip_level"):
        report = ex.check(name, stub)
        fig, axes = plt.subplots(1, 3)
        report.compare(axes, pixel="first")
        for ax, (title, _) in zip(axes, STUB_PANELS):
            if title == "the package's" and name != "classify_block":  # 06, 07: the inputs
                assert ax.get_title().startswith("the scene's input"), ax.get_title()
                continue
            assert not ax.images and ax.get_title() == title
            assert len(ax.texts) == 1
        plt.close(fig)


def _cell(path: str, grade_id: str) -> str:
    return graded_cell(ROOT / path, grade_id)


def test_hiz_task_says_which_bound_is_asked_truthfully():
    """r64 08-4: "the check asks for the tightest safe answer" was false (the plane over the
    covered centres is tighter); the check asks for the box's bound (r126 N8-1), and a
    tighter per-pixel bound is named, not passed."""
    text = _cell("notebooks/exercises/08_tiles.ipynb", "hiz_rejects_task")
    assert "tightest" not in text and "lies outside its bounding box" in text
    assert "with no coverage test" in text  # r162: the highest bound of those facts alone
    from student_variants import hiz_covered_centres

    assert not ex.check("hiz_rejects", hiz_covered_centres).passed
    assert ex.check("hiz_rejects", REASONING["hiz_rejects"]).passed


def test_clip_near_in_float32_passes_as_the_task_says():
    """r64 04-4: a float32 clipper (every GPU's) failed 24 of 30 cases at 4e-8; it passes
    within 1e-6, as colours do, and cell 5 says so."""
    from student_variants import clip_float32

    report = ex.check("clip_near", clip_float32)
    assert report.passed and "float32" in str(report)
    text = _cell("notebooks/exercises/04_depth_and_clipping.ipynb", "task_4_2")
    assert "float32" in text


def test_a_far_case_figure_has_its_whole_title_and_plain_ticks(plt):
    """r64 01-3: "+1e5" offsets over ticks 0…12, and a title cut at 40 characters."""
    from student_variants import WRONG

    report = ex.check("covers", WRONG["covers in float32"][1])
    fig, ax = plt.subplots()
    report.plot(ax)
    title = ax.get_title().replace("\n", " ")
    assert "100000 px from the origin" in title, title
    fig.canvas.draw()
    assert ax.xaxis.get_offset_text().get_text() == ""
    assert ax.yaxis.get_offset_text().get_text() == ""
    assert all(t.get_text().startswith("1000") for t in ax.get_xticklabels() if t.get_text())


def test_the_docs_task_table_does_not_give_8_2s_method_away():
    """r85 08 (fixexr7): docs/exercises.md's table said "the depth plane's minimum at the
    extreme centres, bounded by the nearest vertex (the larger of the two bounds …)", the
    method the notebook gives only as a hint behind <details>."""
    docs = (ROOT / "docs/exercises.md").read_text(encoding="utf-8")
    row = next(line for line in docs.splitlines() if line.startswith("| 8.2 `hiz_rejects"))
    for method in ("extreme centres", "nearest vertex", "larger of the two", "minimum"):
        assert method not in row, (method, row)
    text = _cell("notebooks/exercises/08_tiles.ipynb", "hiz_rejects_task")
    hint = text[text.index("<details>") :]
    # r126 N8-1: the task states the bound (the box cut); which centres and where, the hint
    # (r149: the hint asks it as questions now, without naming the extreme centres)
    assert "extreme centres" not in text[: len(text) - len(hint)]
