"""r446: exercise 08's verifying read. A zero-area test with a tolerance passed every case (no
triangle of tiny but nonzero area covered a centre); six slips were told only the rule: T = −R
(r396 G1), vertices and centres in different units or the vertices on a coarser grid (r396
G2), x0 and y0 read as block indices, a block accepted by one edge, the first centre's ½ in
one axis only; and in 8.2 the box's columns ⌈xmin⌉ … ⌊xmax⌋ and both gradient signs flipped.
Each is named now in its first explanation (``student_variants.R446``). The corpus's
per-centre scan no longer pages gigabytes on a 16,384-px block (now 131,072 px, the same
deciding centre), and a mistake that misses one failing answer is no longer evaluated on the
rest where only whole fits are named.
"""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import R446

from teachraster import exercises as ex
from teachraster.exercises.block_arithmetic import float64_slip
from teachraster.exercises.tile_blocks import FLOAT64_TIES, block_cases, expected_block


@pytest.mark.parametrize("label", list(R446))
def test_each_slip_is_named_first(label):
    name, fn, words, kind = R446[label]
    report = ex.check(name, fn)
    assert not report.passed
    first = report.failures[0]
    assert words in first.explanation, first.explanation
    assert first.kind == kind, (first.kind, first.explanation)
    assert "float32" not in first.explanation


def test_the_smallest_area_covers_a_centre():
    """2·area = 1 unit² of 1/256 px, the vertex (0.5, 0.5) on a top and a left edge: covered."""
    case = next(c for c in block_cases() if c[0].startswith("the smallest area"))
    _, (xy, gx, gy, size), want = case
    assert size == 1 and want.ravel()[0] == "accepted" and set(want.ravel()[1:]) == {"rejected"}


def test_the_far_float64_block_keeps_its_deciding_centre():
    """The 131,072-px block's best centre is the 16,384-px block's it replaced."""
    xy, first, size = FLOAT64_TIES[2]
    assert size == 2**17 and first == (-81920, 262144)
    edge, t, key = float64_slip(np.array(xy), *first, size)
    assert key == "best" and (t["hi"][0] / 256, t["hi"][1] / 256) == (49151.5, 262144.5)
    assert expected_block(np.array(xy), *first, size) == "rejected"
