"""r206 (exercise 08_tiles, 8.2 ``hiz_rejects``): two wrong answers were told a mistake that is
not theirs (issue 30: never misdiagnose).

M1: the box rounded outward (floor and ceil swapped) was told "you evaluated the plane at the
tile's outer corners"; M2: the mean of the plane at the box's four extreme centres was told "you
took the plane's largest value at the corners". Both fitted every *failing* answer, the only
test a bool answer had (``partial_names=False``), and contradicted passing ones (8 and 2). The
words that say where the plane was evaluated, or which of its values was taken, are now said
only where the mistake gives every answer of the check (:data:`.hiz_tile.EXACT`), and the two
answers are named by their own words.
"""

from __future__ import annotations

import numpy as np
import pytest

# the fixtures of r149's tests: the full words; r162's: the first try's words
from test_exercises_r149 import full_words, tile_outer_corners  # noqa: F401
from test_exercises_r162 import first_words  # noqa: F401
from test_exercises_r198 import _hiz_variant

from teachraster import exercises as ex
from teachraster.exercises import hiz_tile

BOX_OUTWARD = _hiz_variant(
    ("np.ceil(min(x1, x2, x3) - 0.5)", "np.floor(min(x1, x2, x3) - 0.5)"),
    ("np.floor(max(x1, x2, x3) - 0.5)", "np.ceil(max(x1, x2, x3) - 0.5)"),
    ("np.ceil(min(y1, y2, y3) - 0.5)", "np.floor(min(y1, y2, y3) - 0.5)"),
    ("np.floor(max(y1, y2, y3) - 0.5)", "np.ceil(max(y1, y2, y3) - 0.5)"),
)
CORNER_MEAN = _hiz_variant(("max(corners.min(),", "max(corners.mean(),"))
FARTHEST = _hiz_variant(("max(corners.min(),", "max(corners.max(),"))

#: the false words each was told, and the kind it is named by now
MISNAMED = {
    "box rounded outward": (BOX_OUTWARD, "outer corners", "box outward", "rounded the box outward"),
    "the corners' mean": (CORNER_MEAN, "largest value", "corner mean", "the mean of the plane"),
}


@pytest.mark.parametrize("words", ["first_words", "full_words"])
@pytest.mark.parametrize("name", list(MISNAMED))
def test_m1_m2_are_not_told_anothers_mistake_and_are_named(name, words, request):
    request.getfixturevalue(words)
    fn, false_words, kind, own = MISNAMED[name]
    report = ex.check("hiz_rejects", fn, budget=120)
    assert report.failures
    for f in report.failures:
        assert false_words not in f.explanation, (f.case, f.explanation)
        assert f.kind == kind, (f.case, f.kind, f.explanation)
        assert own in f.explanation, f.explanation


def test_the_tightening_is_what_keeps_the_false_words_away():
    """Without the rule (the mistakes of :data:`.hiz_tile.EXACT` named on every failing answer
    alone) and without M1's own words, the box rounded outward would be told the outer
    corners again: it fits every failing answer of that mistake, and contradicts passing ones."""
    from teachraster.exercises.diagnosis import Result, _evaluate

    spec = hiz_tile.HIZ_REJECTS
    results = []
    for i, (_, args, expected) in enumerate(spec.cases()):
        got = BOX_OUTWARD(*[np.copy(a) if isinstance(a, np.ndarray) else a for a in args])
        results.append(Result(i, args, expected, got, spec.same(got, expected, args)))
    table = {m.kind: m for m in spec.all_mistakes()}
    fits = {f.mistake.kind: f for f in _evaluate(spec, list(table.values()), results)}
    outer = fits["tile outer corners"]
    assert len(outer.failing) == sum(not r.ok for r in results) and not outer.whole
    assert table["tile outer corners"].only_whole and table["plane farthest"].only_whole
    assert fits["box outward"].whole and fits["box outward"].failing


#: each answer whose words say where the plane was evaluated (or which value), as a student
#: writes it, and the kind it must still be named by
NAMED = {
    "the plane's farthest corner (the notebook's, max for min)": (FARTHEST, "plane farthest"),
    "lesson 10's bound at the tile's outer corners (r149 M3)": (
        tile_outer_corners,
        "tile outer corners",
    ),
}


@pytest.mark.parametrize("name", list(NAMED))
def test_the_real_mistakes_keep_their_words(name, full_words):  # noqa: F811
    fn, kind = NAMED[name]
    report = ex.check("hiz_rejects", fn, budget=120)
    assert report.failures
    assert {f.kind for f in report.failures} == {kind}, [f.kind for f in report.failures]


def _box_clipped_to_outer_corners(xyz, row0, col0, size, buffer):
    """The reader's w13: the plane at the box's own corners kept within the tile's outer
    corners, an empty box only where the box so kept is empty."""
    (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = np.asarray(xyz, dtype=float)
    xl, xh = max(col0, min(x1, x2, x3)), min(col0 + size, max(x1, x2, x3))
    yl, yh = max(row0, min(y1, y2, y3)), min(row0 + size, max(y1, y2, y3))
    if xl > xh or yl > yh:
        return True
    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
    a = ((z2 - z1) * (y3 - y1) - (z3 - z1) * (y2 - y1)) / area
    b = ((z3 - z1) * (x2 - x1) - (z2 - z1) * (x3 - x1)) / area
    corners = [z1 + a * (x - x1) + b * (y - y1) for x in (xl, xh) for y in (yl, yh)]
    return bool(max(min(corners), min(z1, z2, z3)) >= np.max(buffer))


def test_the_box_kept_within_the_outer_corners_is_named_so_not_the_vertex(full_words):  # noqa: F811
    """r206's w13 was told "the tile's outer corners" (it contradicted 3 passing answers): its
    own variant now gives every answer (its empty box is the box kept within the tile)."""
    report = ex.check("hiz_rejects", _box_clipped_to_outer_corners, budget=120)
    assert {f.kind for f in report.failures} == {"box in outer corners"}
    assert "corners kept within the tile's outer corners" in report.failures[0].explanation


@pytest.mark.parametrize("kind", hiz_tile.EXACT)
def test_each_exact_mistake_written_as_its_own_answer_is_named_by_its_words(kind):
    """Every mistake whose words need every answer is told where a student's answer is that
    mistake's on every case (the cases tell it apart from the mistakes before it)."""

    def answer(*args):
        return hiz_tile._variants(*args)[kind]

    report = ex.check("hiz_rejects", answer, budget=120)
    assert report.failures, kind
    assert {f.kind for f in report.failures} == {kind}, [f.kind for f in report.failures]


def test_correct_answer_still_passes():
    assert ex.check("hiz_rejects", _hiz_variant(), budget=120).passed
