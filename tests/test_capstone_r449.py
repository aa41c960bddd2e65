"""r449 (exercise 12, the capstone, a verify-read): a covers mistake its own check finds on
its cases (MN1, MN2: "every pixel you get wrong has a vertex of its triangle at its centre")
is not repeated at a scene point it cannot change: a point strictly inside or outside its
triangle, or on an edge at no vertex."""

from __future__ import annotations

import numpy as np
import pytest
import reasoning_solutions as sol

from teachraster import exercises as ex
from teachraster.exercises.capstone_samples import point_place

VERTEX_WORDS = "has a vertex of its triangle at its centre"
NOT_HERE = "where that cannot change the answer"


def _resnapped(xy, p):
    """MN1: the vertices snapped again, to a 1/16-px grid."""
    return sol.covers(np.round(np.asarray(xy, dtype=float) * 16) / 16, p)


def _nudged(xy, p):
    """MN2: p moved by 1/512 px on both axes."""
    return sol.covers(xy, np.asarray(p, dtype=float) + 1 / 512)


@pytest.mark.parametrize("scene, covers, place", [
    ("grid", _resnapped, "strictly outside an edge"),
    ("cube_msaa", _nudged, "strictly inside its triangle"),
])  # fmt: skip
def test_the_vertex_diagnosis_is_not_said_of_a_point_that_is_no_vertex(scene, covers, place):
    functions = {"covers": covers}
    if scene == "cube_msaa":
        functions["resolve"] = sol.resolve
    report = ex.capstone(scene, **functions)
    assert not report.passed
    first = report.failures[0].explanation
    assert VERTEX_WORDS not in first, first
    assert NOT_HERE in first and place in first, first


def test_point_place():
    xy = np.array([[1.5, 1.5], [6.5, 1.5], [1.5, 6.5]])
    assert point_place(xy, (1.5, 1.5)) == "vertex"
    assert point_place(xy, (3.5, 1.5)) == "edge"
    assert point_place(xy, (2.5, 2.5)) == "inside"
    assert point_place(xy[::-1], (2.5, 2.5)) == "inside"  # the other winding
    assert point_place(xy, (5.5, 5.5)) == "outside"
    assert point_place(xy, (8.5, 1.5)) == "outside"  # on an edge's line, past its end
    assert point_place(np.array([[0, 0], [1, 1], [2, 2]]), (0.5, 0.5)) == "edge"  # zero area


def _depth_kept_between_pixels():
    """A depth buffer kept outside the function: never reset between pixels."""
    stored = [np.inf]

    def depth_passes(depths, writes):
        passed = []
        for depth, write in zip(depths, writes):
            passed.append(bool(depth < stored[0]))
            if depth < stored[0] and write:
                stored[0] = depth
        return passed

    return depth_passes


def test_a_function_that_keeps_state_between_calls_is_named_in_every_scene():
    """r449: told "no fragment passes, ever (False for every fragment ...)", a constant it
    is not: it passed the first pixel's fragment, and the state left fails the rest."""
    depth_passes = _depth_kept_between_pixels()
    first = ex.capstone("intersecting_triangles", depth_passes=depth_passes)
    later = ex.capstone("glass", depth_passes=depth_passes, over=sol.over)
    for report in (first, later):
        assert not report.passed
        said = report.failures[0].explanation
        assert said.startswith("your depth_passes keeps state from one call to the next"), said
    assert ex.capstone("intersecting_triangles", depth_passes=sol.depth_passes).passed
