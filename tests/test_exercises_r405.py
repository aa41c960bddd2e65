"""Review r405 (exercise 07, after the 7.1 / 7.4 redesign): 7.4 has RGB cases (F1), blames a
wrong 7.1 or 7.3 of the student's own where that is the cause (F2), and names the cheap
slips of both tasks from their numbers (F3). The reader's variants are in
student_variants.R405_PIXEL (run by test_checker_corpus.py)."""

from __future__ import annotations

import student_variants as sv

from teachraster import exercises as ex
from teachraster.exercises import pixel_sampler as ps


def test_the_sampler_has_an_rgb_texture_and_its_checklist_asks_the_wrap_mode():
    rgb = [e for label, _, e in ps.sample_cases() if "RGB" in label]
    assert len(rgb) == 2 and all(e.shape == (3,) for e in rgb)
    assert "with which wrap mode?" in ps.HINT


def test_a_wrong_pixel_lod_is_blamed_and_its_compensation_is_not_advised():
    """F2: the reader's X2 was told to pass the size as (W, H), which made 7.4 pass with 7.1
    still wrong; now the student's own pixel_lod is named, with its λ and 7.1's."""
    _, fn, _, _ = sv.R405_PIXEL["pixel sample, right, with a pixel_lod whose W and H are swapped"]
    report = ex.check("pixel_sample", fn)
    assert all(f.kind == "your pixel_lod (7.1)" for f in report.failures), str(report)
    assert "(W, H)" not in str(report)
