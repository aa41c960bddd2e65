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

    assert CENTRE in _msaa(at_centre)
    assert CENTRE not in _msaa(_swapped)
    assert CENTRE not in _msaa(_shifted)
