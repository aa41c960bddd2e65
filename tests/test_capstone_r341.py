"""r341 (exercise 12, the capstone, a fresh read) X-1: a right trilinear that passes its wrap on
to a bilinear that ignores it was told "wrap not passed on" (12.8); whether trilinear reads its
``wrap`` tells the two causes of every level tiled apart, in the capstone as in exercise 7 (the
corpus carries both: tests/student_variants.py)."""

from __future__ import annotations

import pytest
import student_variants as sv
from test_capstone import _mine

from teachraster import exercises as ex
from teachraster.exercises.package_answers import parameters_read


@pytest.mark.parametrize("trilinear, said, unsaid", [
    (sv.trilinear_on_a_tiling_bilinear, "the bilinear it calls tiles whatever", "pass trilinear's"),
    (sv.trilinear_wrap_not_passed, "pass trilinear's `wrap` on", "the bilinear it calls"),
])  # fmt: skip
def test_the_capstone_blames_the_piece_that_tiles(trilinear, said, unsaid):
    report = ex.capstone("floor_trilinear", **_mine("floor_trilinear", trilinear=trilinear))
    assert not report.passed
    words = str(report)
    assert said in words and unsaid not in words, words


def test_a_parameter_is_read_in_a_nested_function_or_a_star_argument():
    def nested(pyramid, uv, lod, wrap="repeat"):
        return lambda: (pyramid, wrap)

    def starred(*args, **kwargs):
        return kwargs

    assert parameters_read(nested) == {"pyramid", "wrap"}
    assert parameters_read(starred) == {"kwargs"}
    assert parameters_read(print) == frozenset()  # no Python code: nothing known


@pytest.mark.parametrize("cell_start, lesson, sections", [
    ("## 12.1", "02_half_planes", ["§14.6.1", "§3.4.2.1", "*Basic Polygon Rasterization*"]),
    ("## 12.4", "05a_zbuffer", ["§17.3.4", "§17.9", "VkPipelineDepthStencilStateCreateInfo"]),
])  # fmt: skip
def test_the_two_graded_tie_rules_have_a_table_citing_the_lessons_sections(
    cell_start, lesson, sections
):
    """r341 M: no GL/D3D/Vulkan line for the two tie rules the capstone grades; each task now
    has one, citing the sections its lesson's full table cites."""
    import json
    from pathlib import Path

    root = Path(__file__).resolve().parents[1] / "notebooks"

    def markdown(name):
        cells = json.loads((root / f"{name}.ipynb").read_text())["cells"]
        return ["".join(c["source"]) for c in cells if c["cell_type"] == "markdown"]

    task = next(t for t in markdown("exercises/12_capstone") if t.startswith(cell_start))
    table = task[task.index("| ") :]
    taught = "\n".join(markdown(lesson))
    for section in sections:
        assert section in table and section in taught, section


def test_a_warning_is_told_by_its_category():
    """r371 C1: numpy's DeprecationWarning (np.cross on 2-vectors, in a correct covers) was
    told "numpy telling of an operation that overflowed or divided by zero"."""
    import warnings

    import numpy as np

    def covers_cross(xy, p):
        v1, v2, v3 = (np.asarray(v, dtype=float) for v in xy)
        p = np.asarray(p, dtype=float)
        warnings.warn("2D cross products are deprecated", DeprecationWarning, stacklevel=1)
        e = [np.cross(b - a, p - a) for a, b in ((v1, v2), (v2, v3), (v3, v1))]
        return all(x >= 0 for x in e) or all(x <= 0 for x in e)

    report = ex.check("covers", covers_cross)
    said = report.printed or ""
    assert "will change or go away in a later version" in said and "overflowed" not in said, said

    def overflowing(xy, p):
        with np.errstate(over="warn"):
            np.float32(3e38) * np.float32(10)
        return False

    said = ex.check("covers", overflowing).printed or ""
    assert "overflowed, divided by zero or had no valid answer" in said, said
