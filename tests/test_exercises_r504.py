"""r504 (exercise 12, the capstone, a verify-read after r487–r502): a texel_weights returning
``{}`` is told through exercise 7.2's check, not only bilinear's shape (HN1); exercise 6.2's
``resolve_fragments`` pasted with ``sample_ids`` read as rows of ``sample_colours`` is named,
not left a raw IndexError (RAW1), and 12.9 says what a sample id is. Each case well under a
second."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from teachraster import exercises as ex
from teachraster.exercises.capstone_samples import ids_as_rows

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "12_capstone.ipynb"


def _empty(sizes, uv, lod, wrap):
    """HN1 (S3): a placeholder left in."""
    return {}


def trilinear(pyramid, uv, lod, wrap="repeat"):
    """12.7's given cell (exercise 7.3's), on ``_empty``."""
    sizes = [np.shape(level)[:2] for level in pyramid]
    texels = texel_weights(sizes, uv, lod, wrap)
    return sum(
        weight * np.asarray(pyramid[k], dtype=float)[row, col]
        for (k, row, col), weight in texels.items()
    )


def bilinear(texture, uv, wrap):
    """12.7's given cell."""
    return trilinear([texture], uv, 0.0, wrap)


texel_weights = _empty


def _pasted(sample_colours, sample_ids, background):
    """RAW1 (R01): 6.2's resolve_fragments with the ids taken for fragment rows."""
    rows, bg = np.asarray(sample_colours, float), np.asarray(background, float)
    return np.mean([rows[i] if i >= 0 else bg for i in sample_ids], axis=0)


def _right(sample_colours, sample_ids, background):
    covered = np.asarray(sample_ids)[:, None] >= 0
    return np.where(covered, sample_colours, np.asarray(background, float)).mean(axis=0)


def test_an_empty_texel_weights_is_told_through_exercise_7_2s_check():
    words = str(ex.capstone("floor_bilinear", bilinear=bilinear))
    assert "exercise 7.2's check fails your texel_weights" in words, words
    assert "returns {} on every case" in words, words


def test_ids_read_as_rows_are_named():
    words = ids_as_rows({"resolve": _pasted}, "resolve")
    assert "not a row of sample_colours" in words and "np.arange(S)" in words, words
    assert ids_as_rows({"resolve": _right}, "resolve") == ""
    assert ids_as_rows({"covers": _pasted}, "covers") == ""


def test_12_9_says_what_a_sample_id_is():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    text = next("".join(c["source"]) for c in cells if "".join(c["source"]).startswith("## 12.9"))
    flat = " ".join(text.split())
    assert "the id of the triangle that covers it" in flat
    assert "not a row of `sample_colours`" in flat


def _clipped_rows(sample_colours, sample_ids, background):
    """RAW1 (R06): ids read as rows, clipped so that it never raises (it shows NaN)."""
    rows, bg = np.asarray(sample_colours, float), np.asarray(background, float)
    return np.mean([rows[min(i, len(rows) - 1)] if i >= 0 else bg for i in sample_ids], axis=0)


def test_ids_read_as_rows_without_raising_are_named_too():
    assert "not a row of sample_colours" in ids_as_rows({"resolve": _clipped_rows}, "resolve")
