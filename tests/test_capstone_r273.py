"""r273 (exercise 12, the capstone, a fresh read): the MSAA scene names a covers mistake as the
grid does, the "as at the pixel's centre" guess only where it holds (item 1); a tie on an edge
of a triangle wound the other way is named as the conventions name it (item 2); the causes
behind four symptoms (item 3); how points cascade (item 4)."""

from __future__ import annotations

import numpy as np
import pytest
import reasoning_solutions as sol
from test_capstone_r222 import _one_winding

from teachraster import exercises as ex

CENTRE = "as at the pixel's centre"


def _msaa(covers) -> str:
    report = ex.capstone("cube_msaa", covers=covers, resolve=sol.resolve)
    assert not report.passed
    return str(report)


def _swapped(xy, p):
    return sol.covers(xy, np.array([p[1], p[0]], dtype=float))


def _shifted(xy, p):
    return sol.covers(xy, np.asarray(p, dtype=float) + 0.5)


# -- 1: the MSAA scene's covers diagnosis, in the grid's order ---------------------------------
@pytest.mark.parametrize("covers, words", [
    (lambda xy, p: False, "never covers anything"),
    (_one_winding, "counter-clockwise on screen"),
])  # fmt: skip
def test_the_msaa_scene_names_a_covers_mistake_as_the_grid_does(covers, words):
    """r273 12-1: `return False` and one winding were told "answers as at the pixel's centre"
    (their wrong answer equalled the centre's at the sample shown)."""
    said = _msaa(covers)
    assert CENTRE not in said
    assert words in said
    assert words in str(ex.capstone("grid", covers=covers))


def test_the_centre_guess_needs_every_differing_sample_to_match_the_centre():
    def at_centre(xy, p):
        return sol.covers(xy, (np.floor(p[0]) + 0.5, np.floor(p[1]) + 0.5))

    # r453 WP1: exercise 1's check now asks covers off the centres and names this itself
    said = _msaa(at_centre)
    assert CENTRE in said or "you tested the centre of p's pixel" in said, said
    assert CENTRE not in _msaa(_swapped)
    assert CENTRE not in _msaa(_shifted)


# -- 2: a tie on an edge of a counter-clockwise triangle, named as the conventions name it --
def _edge_kind_by_conventions(a, b) -> str:
    """CONVENTIONS' top-left test for the edge walked a→b (y down, interior on the right of
    the walk for E > 0): top when horizontal with b.x > a.x, left when b.y < a.y."""
    if a[1] == b[1]:
        return "top" if b[0] > a[0] else "bottom"
    return "left" if b[1] < a[1] else "right"


def test_a_tie_of_a_counter_clockwise_triangle_names_the_edge_as_walked():
    """r273 12-2: triangle 127 of the grid (E(v1, v2, v3) = −6.75) was said to lie on edge
    v1→v2; walked v1→v2 the conventions' formula says left (covered), the rule says right."""
    import re

    from teachraster.exercises import coverage

    xy = np.array([(31.79296875, 10.20703125), (34.390625, 7.609375), (31.79296875, 7.609375)])
    assert coverage.area2(xy) < 0
    words, _, _ = coverage.explain_pixel(xy, np.array([33.5, 8.5]), False)
    assert "edge v2→v1 (E21: this triangle runs the other way), a right edge" in words, words
    a, b = (int(v) - 1 for v in re.search(r"edge v(\d)→v(\d)", words).groups())
    assert _edge_kind_by_conventions(xy[a], xy[b]) == "right"
    # a clockwise triangle keeps v1→v2
    words, _, _ = coverage.explain_pixel(xy[[0, 2, 1]], np.array([33.5, 8.5]), False)
    assert "edge v3→v1, a right edge" in words, words


def test_the_grid_hint_names_the_edge_the_rule_walks():
    from student_variants import WRONG
    from test_capstone import _mine

    from teachraster.exercises import tries

    tries.forget_hints("covers")
    try:
        first = str(ex.capstone("grid", **_mine("grid", covers=WRONG["covers with E >= 0"][1])))
    finally:
        tries.spend_hints(["covers"])
    assert "edge v2→v1 (E21: this triangle runs the other way): the top-left rule" in first


# -- 3: the cause behind each symptom ---------------------------------------------------------
def _mine(scene, **changed):
    from teachraster.exercises.capstone_render import SCENES

    return {name: changed.get(name, sol.CAPSTONE[name]) for name in SCENES[scene].uses}


@pytest.mark.parametrize("scene", ["grid", "cube_msaa"])
@pytest.mark.parametrize("covers, words", [
    (_shifted, "you tested p + (0.5, 0.5), not p"),
    (_swapped, "you tested the point (p[1], p[0])"),
])  # fmt: skip
def test_a_covers_that_tests_another_point_is_named(scene, covers, words):
    """r273 12-3: p moved by half a pixel (sample offsets measured from the centre, issue
    30's class) and p's x and y swapped were told only the tie they broke."""
    said = str(ex.capstone(scene, **_mine(scene, covers=covers)))
    assert words in said, said
    assert CENTRE not in said


def test_the_covers_check_names_the_point_mistakes():
    for covers, kind in ((_shifted, "tested past p"), (_swapped, "p swapped")):
        report = ex.check("covers", covers)
        assert not report.passed
        assert report.failures[0].kind == kind, report.failures[0].kind


def _farther_from_infinity(depths, writes):
    stored, out = np.inf, []
    for d, write in zip(depths, writes):
        passes = d > stored
        out.append(passes)
        if passes and write:
            stored = d
    return out


def test_greater_against_infinity_is_not_told_a_buffer_at_0_as_fact():
    said = str(ex.capstone("intersecting_triangles",
                           **_mine("intersecting_triangles", depth_passes=_farther_from_infinity)))  # fmt: skip
    own = str(ex.check("depth_passes", _farther_from_infinity))
    for text in (said, own):
        assert "(>) against a buffer started at +∞" in text, text
        assert "you started the buffer at 0" not in text


def _reversed_a_buffer(depths, colours, background):
    result = np.asarray(background, dtype=float)
    for k in range(len(depths) - 1, -1, -1):
        result = np.asarray(sol.over_premultiplied(colours[k], result))
    return result


def test_an_a_buffer_in_reverse_drawing_order_is_named():
    said = str(ex.capstone("glass_sorted", **_mine("glass_sorted", a_buffer=_reversed_a_buffer)))
    assert "you composited in reverse drawing order" in said, said
    assert "you composited in drawing order" not in said


# -- 4: points cascade, as cell 0 says ------------------------------------------------------
def _swapped_bilinear(texture, uv, wrap):
    return sol.bilinear(texture, np.asarray(uv, dtype=float)[::-1], wrap)


def _trilinear_on(bilinear):
    def trilinear(pyramid, uv, lod, wrap="repeat"):
        q = len(pyramid) - 1
        lam = min(max(lod, 0.0), q)
        d = int(np.floor(lam))
        a = bilinear(pyramid[d], uv, wrap)
        b = bilinear(pyramid[min(d + 1, q)], uv, wrap)
        return (1 - (lam - d)) * a + (lam - d) * b

    return trilinear


def test_cell_0_says_how_one_bilinear_mistake_cascades():
    """r273 12-6: a correct trilinear on a wrong bilinear scores 0; cell 0 and the folded cell
    say so, with the scenes this test fails."""
    import json

    from test_capstone_r174 import NOTEBOOK

    cells = json.loads(NOTEBOOK.read_text())["cells"]
    assert "One mistake can cost several points" in "".join(cells[0]["source"])
    fold = " ".join("".join(cells[2]["source"]).split())
    assert "Points cascade" in fold
    # r497: 12.7 gives exercise 7.3's filters, built on the student's texel_weights
    assert "a `texel_weights` with u and v swapped fails 12.7, 12.8 and 12.10" in fold
    mine = dict(bilinear=_swapped_bilinear, trilinear=_trilinear_on(_swapped_bilinear))
    for scene in ("floor_bilinear", "floor_trilinear", "sphere"):
        assert not ex.capstone(scene, **_mine(scene, **mine)).passed, scene
    right = _trilinear_on(sol.bilinear)
    assert ex.capstone("floor_trilinear", trilinear=right).passed
