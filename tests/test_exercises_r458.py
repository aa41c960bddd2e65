"""Review r458 (exercise 5, a verifying reader after r442): 5.4 took reverse-Z wherever its Δz
was under twice the gap (no case lay between; G1), and counted the package's
``depth_resolution`` for unorm24's Δz (G2)."""

from __future__ import annotations

import json
from pathlib import Path

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


# -- the redesign: 5.1 and 5.2 are rulers, with no point of their own ---------------------------

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks/exercises/05_depth_precision.ipynb"


def _cells():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    return {c["metadata"]["nbgrader"]["grade_id"]: c for c in cells}, cells


def test_the_rulers_are_written_in_5_2b_cell_and_graded_through_5_2b_and_5_4():
    """Readers found 5.1 and 5.2 one printed formula each (r425 F7, r442 F4): they earn no
    point; they are written above reverse_z_worst, and 5.4 calls both."""
    by_id, cells = _cells()
    graded = {g: c["metadata"]["nbgrader"]["points"] for g, c in by_id.items()
              if c["metadata"]["nbgrader"]["grade"]}  # fmt: skip
    assert graded == {"reverse_z_worst_check": 1, "decal_bias_check": 1, "depth_setup_check": 1}
    assert not {"safe_near_solution", "reverse_z_gap_solution"} & set(by_id)
    cell = "".join(by_id["reverse_z_worst_solution"]["source"])
    order = [cell.index(f"def {fn}(") for fn in ("safe_near", "reverse_z_gap", "reverse_z_worst")]
    assert order == sorted(order) and cell.count("### BEGIN SOLUTION") == 3, cell
    assert "safe_near(" in "".join(by_id["depth_setup_solution"]["source"])
    assert "reverse_z_gap(" in "".join(by_id["depth_setup_solution"]["source"])
    text = " ".join("".join(by_id["safe_near_task"]["source"]).split())
    assert "no point of their own" in text and "5.2b's cell" in text, text


def test_the_rulers_check_cell_runs_both_checks_ungraded_after_5_2b_check():
    by_id, cells = _cells()
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in cells]
    assert ids.index("rulers_check") == ids.index("reverse_z_worst_check") + 1
    meta = by_id["rulers_check"]["metadata"]["nbgrader"]
    assert meta == {"grade": False, "grade_id": "rulers_check", "locked": True,
                    "schema_version": 3, "solution": False, "task": False}  # fmt: skip
    source = "".join(by_id["rulers_check"]["source"])
    for fn in ("safe_near", "reverse_z_gap"):
        assert f'show(ex.check("{fn}", {fn}))' in source
    assert "assert_passed" not in source


def test_5_2b_sends_a_slip_of_the_ruler_to_the_rulers_check_cell():
    """5.2's slips carried into 5.2b point at the cell that checks 5.2 alone (5.2 has no check
    cell of its own)."""
    from student_variants import _r404_f64

    report = assert_first_named("reverse_z_worst", _r404_f64, "you took float64's step at d",
                                "5.2's slip")  # fmt: skip
    assert "the cell after this check runs 5.2's check (not graded)" in str(report), str(report)
