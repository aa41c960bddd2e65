"""Review r415 (exercise 07, 7.1 and 7.4): M1 λ − 1 and level 1's size give the same numbers,
and both are named; F2 the reader's half-named variants are named from their numbers (other
lanes of the quad, which GL and Direct3D allow; λ·w; the size divided; the quad index; the
quad's centre; λ clamped to q − 1; ⌈λ⌉ and λ + ½; a wrong 7.2 bilinear; an RGB level's full
shape as the size). The variants are student_variants.R415_PIXEL."""

from __future__ import annotations

import pytest
import student_variants as sv

from teachraster import exercises as ex
from teachraster.exercises import tries


@pytest.mark.parametrize("label", list(sv.R415_PIXEL))
def test_the_readers_variants_are_named(label):
    name, fn, words, kind = sv.R415_PIXEL[label]
    tries.spend_hints([name])
    first = ex.check(name, fn).failures[0]
    tries.forget_hints(name)
    assert first.kind == kind and words in first.explanation, (first.kind, first.explanation)


def test_the_full_shape_of_an_rgb_level_as_the_size_is_explained():
    fn = sv._ps405(SIZE="np.shape(pyramid[0])")
    said = [f.explanation for f in ex.check("pixel_sample", fn).failures]
    assert any("np.shape(level 0) is (8, 8, 3)" in s and "shape[:2]" in s for s in said), said


def test_answers_that_ignore_the_inputs_do_not_unlock_the_steps():
    """F1: ``return row * 0.1`` then ``return col * 0.1`` (and 7.4's twins) brought the whole
    recipe; an answer that ignores the triangle's (u, v) (7.1) or the pyramid (7.4) is told so,
    and no such try counts towards the full words."""
    from teachraster.exercises import pixel_level as pl
    from teachraster.exercises import pixel_sampler as ps

    tasks = {"pixel_lod": (pl.RULE, "your λ is still", lambda *a: a[4] * 0.1, lambda *a: a[5] * 0.1),
             "pixel_sample": (ps.RULE, "1 brighter your value is still",
                              lambda *a: a[4] * 0.01, lambda *a: a[5] * 0.01, lambda *a: 0.3 + a[4])}  # fmt: skip
    for name, (rule, words, *junk) in tasks.items():
        tries.forget_hints(name)
        for fn in junk:
            said = str(ex.check(name, fn))
            assert rule not in said and words in said, said
        assert not tries.hints_spent(name)
        tries.forget_hints(name)
