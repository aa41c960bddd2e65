"""Review r433 (exercise 7.4): F1 a None from the student's own helper is named (a pixel_lod
without ``return`` was told "λ = nan", a trilinear without one blamed on pixel_sample); F3
λ/w not renormalised, λ·w and (u, v) in texels are named; F2 junk mixing a vertex's (u, v)
with the pixel's row and col never counts as a try, while real attempts still do."""

from __future__ import annotations

import student_variants as sv

from teachraster import exercises as ex
from teachraster.exercises import pixel_sampler as ps
from teachraster.exercises import tries


def _first(label: str):
    _, fn, words, kind = sv.R433_PIXEL[label]
    return ex.check("pixel_sample", fn).failures[0], words, kind


def test_a_none_from_the_students_own_helper_is_named():
    """F1: λ = None is no "λ = nan"; a None from their trilinear names their trilinear."""
    for label in ("pixel sample whose own pixel_lod has no return",
                  "pixel sample whose own trilinear has no return where t ≠ 0"):  # fmt: skip
        first, words, kind = _first(label)
        assert words in first.explanation and first.kind == kind, first.explanation
        assert "nan" not in first.explanation, first.explanation
    first, _, _ = _first("pixel sample whose own trilinear has no return where t ≠ 0")
    assert "7.3's check fails on it" in first.explanation, first.explanation


def test_the_perspective_and_texel_slips_are_named():
    """F3: each slip named, never the generic hint."""
    for label in ("pixel sample with λ/w weights not renormalised",
                  "pixel sample with λ·w weights", "pixel sample with (u, v) in texels"):  # fmt: skip
        first, words, kind = _first(label)
        assert words in first.explanation and first.kind == kind, first.explanation
        assert "at which point" not in first.explanation, first.explanation


def test_junk_mixing_row_and_col_never_unlocks_the_steps():
    """F2: the three junk answers in a row, each told the one-quad move; none counts."""
    tries.forget_hints("pixel_sample")
    for label in sv.R433_JUNK:
        said = str(ex.check("pixel_sample", sv.R433_PIXEL[label][1]))
        assert ps.RULE not in said, said
        assert "moved together by one quad (2 pixels right and down" in said, said
    assert not tries.hints_spent("pixel_sample")
    tries.forget_hints()


def test_real_attempts_still_count_and_unlock_the_steps():
    """F2: two real but unnamed attempts (the pixel above's (u, v), the vertices' mean (u, v)
    with the own λ) pass the one-quad move and count: the second gets the steps."""
    bodies = (
        "trilinear(pyramid, perspective_weights(barycentric(xy, [[col + 0.5, row - 0.5]]), w)[0]"
        " @ np.asarray(uv, float), pixel_lod(xy, w, uv, np.shape(pyramid[0])[:2], row, col), wrap)",
        "trilinear(pyramid, np.mean(np.asarray(uv, float), 0), "
        "pixel_lod(xy, w, uv, np.shape(pyramid[0])[:2], row, col), wrap)",
    )
    tries.forget_hints("pixel_sample")
    said = ""
    for body in bodies:
        fn = sv._r426("pixel_sample",
                      f"def pixel_sample(pyramid, xy, w, uv, row, col, wrap):\n    return {body}\n")  # fmt: skip
        said = str(ex.check("pixel_sample", fn))
        assert "moved together by one quad" not in said, said
    assert ps.RULE in said, said
    tries.forget_hints()
