"""Review r458 (exercise 5, a verifying reader after r442): 5.4 took reverse-Z wherever its Δz
was under twice the gap (no case lay between; G1), and counted the package's
``depth_resolution`` for unorm24's Δz (G2)."""

from __future__ import annotations

import pytest
import reasoning_solutions as rs
from student_variants import R458
from variant_checks import assert_first_named

from teachraster import depth_resolution
from teachraster import exercises as ex


@pytest.mark.parametrize("label", sorted(R458))
def test_each_r458_variant_is_named_by_its_cause(label):
    assert_first_named(*R458[label])


def test_the_package_resolution_in_depth_setup_is_not_counted():
    """G2: unorm24's Δz from the package passed 5.4 unflagged."""

    def depth_setup(z, gap, far, nearest):
        dz = float(depth_resolution([z], nearest, far, "unorm24")[0])
        if dz <= gap:
            return "unorm24", nearest, dz
        dz = rs.reverse_z_gap(z, nearest, far)
        return ("reverse-z" if dz <= gap else "neither"), nearest, dz

    report = ex.check("depth_setup", depth_setup)
    assert not report.passed and "not counted" in str(report), str(report)
    assert "depth_resolution" in str(report), str(report)
    assert ex.check("depth_setup", rs.depth_setup).passed
