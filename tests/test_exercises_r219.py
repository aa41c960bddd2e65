"""r219 (exercise 07, 7.2 bilinear): four slips were told only the rule, each now a slip of the
one table (:data:`teachraster.exercises.texture_filtering.BILINEAR_KNOBS`) that the capstone
reads too (tests/test_capstone_r219.py): (a) x's fraction used along y and y's along x,
(b) u flipped (1 − u), u and v both flipped, (c) the wrap modes exchanged, (d) texel (row,
col) read as ``texture[col, row]`` with H and W right. Each student's function is the
notebook's own solution with the one slip made in it, as a student writes it."""

from __future__ import annotations

import json
from pathlib import Path

import exercise_solutions as es
import numpy as np
import pytest
import student_variants as sv

from teachraster import exercises as ex

NOTEBOOKS = Path(__file__).resolve().parents[1] / "notebooks/exercises"

#: (old, new) edits of the solution, each made once, and the words its first failure must hold
TOP = "top = (1 - fx) * tex[rows[0], cols[0]] + fx * tex[rows[0], cols[1]]"
BOTTOM = "bottom = (1 - fx) * tex[rows[1], cols[0]] + fx * tex[rows[1], cols[1]]"
COL_ROW = (
    (TOP, "top = (1 - fx) * tex[cols[0], rows[0]] + fx * tex[cols[1], rows[0]]"),
    (BOTTOM, "bottom = (1 - fx) * tex[cols[0], rows[1]] + fx * tex[cols[1], rows[1]]"),
)
U_FLIP = ("x, y = uv[0] * w - 0.5,", "x, y = (1 - uv[0]) * w - 0.5,")
V_FLIP = ("uv[1] * h - 0.5  #", "(1 - uv[1]) * h - 0.5  #")
SLIPS = {
    "fractions swapped": (
        [("fx, fy = x - x0, y - y0", "fx, fy = y - y0, x - x0")],
        ["the two fractions are exchanged"],
    ),
    "u flipped": ([U_FLIP], ["you flipped u (1 − u)"]),
    "v flipped": ([V_FLIP], ["you flipped v (1 − v)"]),
    "u flipped and v flipped": (
        [U_FLIP, V_FLIP],
        ["you flipped u (1 − u)", "you flipped v (1 − v)"],
    ),
    "wrap modes swapped": (
        [('if wrap == "repeat":', 'if wrap == "clamp":')],
        ["the wrap modes are exchanged", "you clamped", "you tiled"],
    ),
    "indexed [col, row]": (list(COL_ROW), ["as texture[col, row]"]),
}


#: The bilinear solution the capstone's 12.7 held before r497 (12.7 now takes exercise 7.2's
#: texel_weights and 7.3's given filters): the old bilinear check still runs (the capstone's
#: diagnosis), and these slips are made in it.
OLD_BILINEAR = '''
def bilinear(texture, uv, wrap):
    """The texture filtered bilinearly at uv = (u, v)."""
    tex = np.asarray(texture, dtype=float)
    h, w = tex.shape[:2]
    x, y = uv[0] * w - 0.5, uv[1] * h - 0.5  # texel centres on integers
    x0, y0 = np.floor(x), np.floor(y)
    fx, fy = x - x0, y - y0
    cols, rows = np.array([x0, x0 + 1], dtype=int), np.array([y0, y0 + 1], dtype=int)
    if wrap == "repeat":
        cols, rows = cols % w, rows % h
    else:
        cols, rows = np.clip(cols, 0, w - 1), np.clip(rows, 0, h - 1)
    top = (1 - fx) * tex[rows[0], cols[0]] + fx * tex[rows[0], cols[1]]
    bottom = (1 - fx) * tex[rows[1], cols[0]] + fx * tex[rows[1], cols[1]]
    return (1 - fy) * top + fy * bottom
'''


def solution_with(notebook: str, edits, name: str = "bilinear"):
    """Function ``name`` of ``notebook``'s solution cell ``<name>_solution`` (for bilinear, the
    old solution: the capstone's cell now holds texel_weights), each (old, new) edit made once."""
    cells = json.loads((NOTEBOOKS / notebook).read_text())["cells"]
    grade = f"{name}_solution"
    sources = ["".join(c["source"]) for c in cells
               if c["metadata"]["nbgrader"]["grade_id"] == grade]  # fmt: skip
    source = OLD_BILINEAR if name == "bilinear" else sources[0]
    for old, new in edits:
        assert source.count(old) == 1, old
        source = source.replace(old, new)
    ns = {"np": np}
    exec(source, ns)
    return ns[name]


def _slipped(kind: str):
    return solution_with("12_capstone.ipynb", SLIPS[kind][0])


@pytest.mark.parametrize("kind", list(SLIPS))
def test_each_slip_is_named_by_the_first_failure(kind):
    report = ex.check("bilinear", _slipped(kind))
    assert not report.passed
    first = report.failures[0]
    for words in SLIPS[kind][1]:
        assert words in first.explanation, first.explanation
    assert first.kind == kind, first.kind
    assert "in texel units x = u·W − ½" not in first.explanation  # not the rule alone


def test_the_wrap_modes_are_said_from_each_case_s_own_mode():
    report = ex.check("bilinear", _slipped("wrap modes swapped"))
    said = {f.case.rsplit("wrap=", 1)[1]: f.explanation for f in report.failures}
    assert "for wrap 'repeat' you clamped" in said["'repeat'"], said["'repeat'"]
    assert "for wrap 'clamp' you tiled" in said["'clamp'"], said["'clamp'"]


def test_texture_col_row_raises_on_a_wide_texture_and_is_named_on_a_square_one():
    """Where col ≥ H the student's own indexing raises, as the table's slip does (it says
    nothing there): the failures it answers are all named."""
    report = ex.check("bilinear", _slipped("indexed [col, row]"))
    kinds = {f.kind for f in report.failures}
    assert kinds <= {"indexed [col, row]", "raised"}, kinds
    assert "raised" in kinds


def test_a_texture_transposed_whole_is_still_told_rows_and_columns_swapped():
    """H and W read the other way round too (``w, h = tex.shape``): the transposed texture,
    not the [col, row] reading with H and W right."""
    whole = _slipped_with([("h, w = tex.shape[:2]", "w, h = tex.shape[:2]"), *COL_ROW])
    first = ex.check("bilinear", whole).failures[0]
    assert first.kind == "rows and columns swapped", (first.kind, first.explanation)


def _slipped_with(edits):
    return solution_with("12_capstone.ipynb", edits)


def test_always_clamp_is_still_told_always_clamp():
    first = ex.check("bilinear", _slipped_with([('if wrap == "repeat":', "if False:")]))
    assert first.failures[0].kind == "always clamp", first.failures[0].explanation


RIGHT = {
    "vectorised (the notebook's)": solution_with("12_capstone.ipynb", []),
    "loops": es.bilinear,
    "lerps with np.ix_": es.bilinear_lerp,
    "float32 texture": _slipped_with([("dtype=float)", "dtype=np.float32)")]),
    "float32 answer": sv.bilinear_float32,
}


@pytest.mark.parametrize("name", list(RIGHT))
def test_right_solutions_written_otherwise_pass(name):
    report = ex.check("bilinear", RIGHT[name])
    assert report.passed, str(report)
