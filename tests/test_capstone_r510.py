"""r510 (exercise 12, the capstone, a verify-read after the redesigns of exercises 1, 3, 4, 6
and 7): 12.9's recipe with exercise 6.2's reference ``resolve_fragments`` gave NaN (0 × NaN)
and was told "a mean with NaN" (WF1); a ``trilinear`` of one's own built on 12.7's given
``bilinear`` recursed, told only "RecursionError" (WF2); the resolve check was called "the
resolve exercise's check", an exercise that no longer exists (MN1); a resolve with one colour
for many samples got the generic question (HN2, HN3); a texel_weights wrong only at λ near a
whole level (Q8) was told to restore 12.7's given cell. Each case well under a second."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from teachraster.exercises import capstone_render, capstone_reports
from teachraster.exercises.capstone_explain import check_words
from teachraster.exercises.capstone_samples import nan_weighed, resolve_slip
from teachraster.exercises.capstone_texels import at_pixel, each_other
from teachraster.exercises.texel_footprint import reference as texel_reference

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "12_capstone.ipynb"


def resolve_fragments(fragments, sample_fragment, background):
    """Exercise 6.2's reference solution, word for word."""
    fragments = np.asarray(fragments, dtype=float).reshape(-1, 3)
    ids = np.asarray(sample_fragment)
    total = np.zeros(3)
    for j, colour in enumerate(fragments):
        total += (ids == j).sum() * colour  # a fragment weighs by the samples it shows
    total += (ids < 0).sum() * np.asarray(background, dtype=float)
    return total / len(ids)


def _via_fragments(sample_colours, sample_ids, background):
    """WF1 (K3): 12.9's mapping, sample k pointing at fragment k or at -1."""
    ids = np.asarray(sample_ids)
    return resolve_fragments(
        sample_colours, np.where(ids >= 0, np.arange(len(ids)), -1), background
    )


def _right(sample_colours, sample_ids, background):
    covered = np.asarray(sample_ids)[:, None] >= 0
    return np.where(covered, sample_colours, np.asarray(background, float)).mean(axis=0)


def _first_colour(sample_colours, sample_ids, background):
    """HN3 (R3): the first covered sample's colour for every covered sample."""
    ids, cols = np.asarray(sample_ids), np.asarray(sample_colours, float)
    covered = ids >= 0
    n = covered.sum()
    return (n * cols[covered][0] + (len(ids) - n) * np.asarray(background, float)) / len(ids)


def _per_id(sample_colours, sample_ids, background):
    """HN2 (R2): one colour per triangle id (its first sample's), weighed by its samples."""
    ids, cols = np.asarray(sample_ids), np.asarray(sample_colours, float)
    total = np.zeros(3)
    for t in np.unique(ids):
        colour = np.asarray(background, float) if t < 0 else cols[np.flatnonzero(ids == t)[0]]
        total += (ids == t).sum() * colour
    return total / len(ids)


def test_nan_rows_weighed_by_zero_are_named():
    words = nan_weighed({"resolve": _via_fragments}, "resolve")
    assert "0 × NaN is NaN" in words, words
    for fine in (_right, _first_colour):
        assert nan_weighed({"resolve": fine}, "resolve") == ""
    assert nan_weighed({"covers": _via_fragments}, "covers") == ""


def _one_sample(sample_colours, sample_ids, background):
    """r449 W40 (its HN2): the colour of one covered sample, no mean."""
    ids = np.asarray(sample_ids)
    if not (ids >= 0).any():
        return np.asarray(background, float)
    return np.asarray(sample_colours[ids.argmax()], float)


def test_one_colour_for_many_samples_is_named():
    assert "the first covered sample" in resolve_slip({"resolve": _first_colour}, "resolve")
    assert "one colour per id" in resolve_slip({"resolve": _per_id}, "resolve")
    assert "one sample's colour (sample 3's) alone" in resolve_slip(
        {"resolve": _one_sample}, "resolve"
    )
    for other in (_right, _via_fragments):
        assert resolve_slip({"resolve": other}, "resolve") == ""


def bilinear(texture, uv, wrap):
    """12.7's given bilinear: trilinear on one level."""
    return trilinear([texture], uv, 0.0, wrap)


def trilinear(pyramid, uv, lod, wrap="repeat"):
    """WF2 (r481 K9): a right trilinear of exercise 7's old shape, built on bilinear."""
    lam = float(np.clip(lod, 0, len(pyramid) - 1))
    lo = int(lam)
    hi = min(lo + 1, len(pyramid) - 1)
    return (1 - (lam - lo)) * bilinear(pyramid[lo], uv, wrap) + (lam - lo) * bilinear(
        pyramid[hi], uv, wrap
    )


def test_filters_calling_each_other_are_named():
    words = each_other(trilinear, "trilinear")
    assert "each calls the other without end" in words and "keep 12.7's given" in words, words
    assert each_other(bilinear, "bilinear").startswith("; your bilinear calls trilinear")
    assert each_other(_right, "trilinear") == "" and each_other(trilinear, "resolve") == ""


def test_checks_without_an_exercise_are_called_by_their_call():
    for name in ("resolve", "bilinear", "trilinear"):
        said = check_words(name)
        assert "exercise's" not in said and f'ex.check("{name}", {name})' in said, said
    assert check_words("covers") == "the covers exercise's check"


def test_the_render_takes_own_report_from_its_home():
    assert capstone_render.own_report is capstone_reports.own_report


def _task(heading: str) -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    text = next("".join(c["source"]) for c in cells if "".join(c["source"]).startswith(heading))
    return " ".join(text.split())


def test_12_9_and_12_8_warn_of_the_traps():
    assert "0 × NaN is NaN" in _task("## 12.9")
    assert "call each other without end" in _task("## 12.8")


def _snapped(sizes, uv, lod, wrap):
    """Q8: λ snapped to a whole level within 0.05 of it (passes exercise 7.2's cases)."""
    lam = float(lod)
    if abs(lam - round(lam)) < 0.05:
        lam = float(round(lam))
    return texel_reference(sizes, uv, lam, wrap)


def test_texels_wrong_only_at_the_pixel_are_told_there_not_the_given_cell():
    sizes = [(8, 8), (4, 4), (2, 2), (1, 1)]
    said = at_pixel(_snapped, sizes, (0.463, 1.081), 2.045, "repeat")
    assert "passes exercise 7.2's check, but not at this pixel" in said, said
    assert "level 2 0.955, level 3 0.045" in said, said
    assert at_pixel(texel_reference, sizes, (0.463, 1.081), 2.045, "repeat") == ""
