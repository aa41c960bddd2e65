"""Review r131 (exercises 03, 08, 12 played as students in fresh processes): 8.2 passed a bound
that leaves out the centres on the triangle's bounding box (unsafe: a covered centre at a
vertex, D8-1), named three mistakes wrongly (an empty box kept, the box not cut to the tile,
the box cut in x only: D8-2, D8-3, D8-6); 03's text said the capstone accepts float32 within
its rounding only, while it accepts a float32 barycentric (D12-1); docs and 03 said exercise 3
imports or reuses exercise 1's edge function, which no cell holds (D3-1, D3-2); 08 cell 5 did
not say how to get the plane (D8-5).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from student_variants import DIFFERENT, WRONG
from test_exercises_r126 import _cell, _check

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import hiz_tile

ROOT = Path(__file__).parents[1]


def test_the_readers_vertex_on_a_centre_is_a_case_and_keeps_the_block():
    """D8-1: xyz (2.5, 0.5, 0.1), (7.5, 0.5, 0.5), (2.5, 6.5, 0.5) over tile (0, 0): the
    vertex's centre is covered (its depth 0.1 passes 0.2), so rejecting the block drops it."""
    labels = {label: (args, rejected) for label, args, rejected in hiz_tile.hiz_cases()}
    args, rejected = next(v for k, v in labels.items() if k.startswith("a vertex exactly on"))
    xyz = args[0]
    assert np.array_equal(xyz, [[2.5, 0.5, 0.1], [7.5, 0.5, 0.5], [2.5, 6.5, 0.5]])
    assert args[1:4] == (0, 0, 8) and np.all(args[4] == 0.2) and not rejected
    assert tr.rasterize(tr.Triangle(xyz[:, :2]), 8, 8).coverage[0, 2]
    sides = [k for k in labels if k.startswith("an edge exactly on a line of pixel centres")]
    assert len(sides) == 4 and not any(labels[k][1] for k in sides), sides


def test_the_border_left_out_fails_with_its_name_and_the_right_answers_pass():
    """D8-1: both border-dropping variants fail, each named on every failing case; the
    reference and an independent brute force still pass."""
    for label, words in (("Hi-Z without the box's border", "on the box's border"),
                         ("Hi-Z from ⌊xmin + ½⌋", "on the box's left or top border")):  # fmt: skip
        report = _check("hiz_rejects", WRONG[label][1])
        assert not report.passed and report.failures, label
        for failure in report.failures:
            assert words in failure.explanation, (label, failure.case, failure.explanation)
    for label in ("Hi-Z by brute force", "Hi-Z at the box's extreme centres"):
        assert _check("hiz_rejects", DIFFERENT[label][1]).passed, label
    handed_in = _check("hiz_rejects", lambda *a: hiz_tile.expected_reject(*a))
    assert not handed_in.passed and "not counted" in str(handed_in), str(handed_in)


def test_the_three_misnamed_mistakes_get_their_own_names_on_every_failure():
    """D8-2, D8-3, D8-6: each of the reader's variants is named on every failing case, and
    the box cut in one axis fails a case the box's own corners pass."""
    for label, kind in (("Hi-Z keeping an empty box", "empty kept"),
                        ("Hi-Z over the box not cut to the tile", "box uncut"),
                        ("Hi-Z with the box cut in x only", "box in x only"),
                        ("Hi-Z with the box cut in y only", "box in y only"),
                        ("Hi-Z at the box's own corners", "box corners")):  # fmt: skip
        report = _check("hiz_rejects", WRONG[label][1])
        assert report.failures, label
        assert {f.kind for f in report.failures} == {kind}, (label, str(report))
    corners = WRONG["Hi-Z at the box's own corners"][1]
    for label, args, rejected in hiz_tile.hiz_cases():
        if label.startswith("a triangle beyond the tile's"):
            assert corners(*args) == rejected, label
            assert WRONG["Hi-Z with the box cut in x only"][1](*args) != rejected or (
                WRONG["Hi-Z with the box cut in y only"][1](*args) != rejected
            ), label


def test_exercise_3_says_the_capstone_accepts_a_float32_barycentric():
    """D12-1: the capstone drops 3.1's float32 failures, also those beyond its rounding far
    from the origin: 03 says it accepts a float32 barycentric, and it does."""
    from test_capstone import _mine

    text = _cell("03_interpolation.ipynb", 2)
    assert "accepts a float32 `barycentric`" in text and "within float32's rounding)" not in text

    def barycentric32(xy, p):
        (x1, y1), (x2, y2), (x3, y3) = np.asarray(xy, dtype=np.float32)
        px, py = np.asarray(p, dtype=np.float32)
        det = (x1 - x3) * (y2 - y3) - (x2 - x3) * (y1 - y3)
        if det == 0:  # 3.1 since ex30b: a zero area has no weights
            raise ValueError("zero area")
        l1 = ((px - x3) * (y2 - y3) - (x2 - x3) * (py - y3)) / det
        l2 = ((x1 - x3) * (py - y3) - (px - x3) * (y1 - y3)) / det
        return np.array([l1, l2, np.float32(1) - l1 - l2])

    assert not _check("barycentric", barycentric32).passed
    cap = ex.capstone("single_triangle", **_mine("single_triangle", barycentric=barycentric32))
    assert cap.passed and cap.n_wrong == 0, str(cap)


def test_exercise_3_says_to_copy_the_edge_function_and_the_docs_agree():
    """D3-1, D3-2."""
    assert "copy your `edge_function` from exercise 1" in _cell("03_interpolation.ipynb", 2)
    docs = " ".join((ROOT / "docs/exercises.md").read_text().split())
    assert "exercises 3, 6 and 8" not in docs and "in exercises 6 and 8" in docs


def test_exercise_8_says_how_to_get_the_plane():
    """D8-5."""
    text = _cell("08_tiles.ipynb", 5)
    assert "z = z1 + a(x − x1) + b(y − y1)" in text and "Σ λi·zi" in text
