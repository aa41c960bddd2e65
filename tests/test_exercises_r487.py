"""r487 (r453 T1, issue 30): exercise 1.2 is ``box(xy, width, height)``, the rows and columns
whose centres a triangle with xy's bounding box can cover, clamped; ``fill`` is given as the
loop over it. The expected boxes are exact (fractions) and cross-checked here against the
package: the bounding rectangle, filled as two triangles by ``tr.rasterize`` (watertight under
the top-left rule), covers exactly the box's centres."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import teachraster as tr
from teachraster import exercises as ex
from teachraster.exercises import centre_box as cb

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks" / "exercises" / "01_coverage.ipynb"


def _rectangle_box(xy, width, height):
    """The package's answer: the box of the centres its fill of the bounding rectangle (two
    triangles) covers, or None where it covers none."""
    a = np.asarray(xy, dtype=float)
    (x0, y0), (x1, y1) = a.min(axis=0), a.max(axis=0)
    cov = np.zeros((height, width), dtype=bool)
    for t in ([[x0, y0], [x1, y0], [x0, y1]], [[x1, y0], [x1, y1], [x0, y1]]):
        cov |= tr.rasterize(tr.Triangle(np.array(t, dtype=float)), width, height).coverage
    rows, cols = np.flatnonzero(cov.any(axis=1)), np.flatnonzero(cov.any(axis=0))
    if not rows.size:
        return None
    return int(rows[0]), int(rows[-1]) + 1, int(cols[0]), int(cols[-1]) + 1


def _small(args):
    return args[1] * args[2] <= 10**4


def test_every_fixed_and_drawn_case_equals_the_packages_rectangle():
    for label, args, expected in cb.box_cases():
        if not _small(args):
            continue
        got = _rectangle_box(*args)
        if got is None:
            assert cb.is_empty(expected), label
        else:
            assert got == expected, (label, got, expected)


def test_random_boxes_equal_the_packages_rectangle_and_hold_its_coverage():
    rng = np.random.default_rng(487)
    for _ in range(60):
        w, h = (int(v) for v in rng.integers(4, 16, 2))
        xy = rng.integers(-3 * 256, 19 * 256, (3, 2)) / 256
        xy = np.where(rng.random((3, 2)) < 0.5, np.floor(xy) + 0.5, xy)
        box = cb.centre_box(xy, w, h)
        got = _rectangle_box(xy, w, h)
        assert cb.is_empty(box) if got is None else got == box, (xy, w, h, got, box)
        cov = tr.rasterize(tr.Triangle(xy), w, h).coverage
        r0, r1, c0, c1 = box
        inside = np.zeros_like(cov)
        inside[r0:r1, c0:c1] = True
        assert not (cov & ~inside).any(), (xy, w, h)


def test_the_far_cases_hold_centres_float32_moves():
    far = [(a, e) for _, a, e in cb.box_cases() if not _small(a)]
    assert len(far) == 2
    for args, expected in far:
        assert cb.centre_box(np.asarray(args[0], np.float32).astype(float), *args[1:]) != expected


def test_the_teacher_solution_and_reasoning_solution_pass_fast():
    import reasoning_solutions as sol

    start = time.process_time()
    report = ex.check("box", sol.box)
    assert report.passed, str(report)
    assert time.process_time() - start < 1.0


def test_lesson_02s_box_fails_named_and_the_rule_kept_back_on_the_first_try():
    from student_variants import _r487_lesson02

    code = (
        f"import sys; sys.path.insert(0, {str(ROOT)!r}); "
        f"sys.path.insert(0, {str(ROOT / 'tests')!r})\n"
        "from teachraster import exercises as ex\n"
        "from student_variants import _r487_lesson02\n"
        "print(ex.check('box', _r487_lesson02).failures[0].explanation)\n"
    )
    first = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           check=True).stdout  # fmt: skip
    assert "as lesson 02 §1's closed box does" in first, first
    assert "can the top-left rule ever cover a centre there?" in first, first
    assert "never covers" not in first, first
    start = time.process_time()
    assert not ex.check("box", _r487_lesson02).passed
    assert time.process_time() - start < 1.0


def test_fill_as_given_passes_with_the_solutions():
    import reasoning_solutions as sol
    from exercise_solutions import covers

    def fill(xy, width, height):
        out = np.zeros((height, width), dtype=bool)
        i0, i1, j0, j1 = sol.box(xy, width, height)
        for i in range(i0, i1):
            for j in range(j0, j1):
                out[i, j] = covers(xy, (j + 0.5, i + 0.5))
        return out

    assert ex.check("fill", fill).passed


def _cells():
    return json.loads(NOTEBOOK.read_text())["cells"]


def test_the_notebook_grades_box_and_gives_fill():
    cells = _cells()
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in cells]
    assert "box_solution" in ids and "box_check" in ids and "fill_solution" not in ids
    given = "".join(cells[ids.index("fill_given")]["source"])
    assert "box(xy, width, height)" in given and 'ex.check("fill", fill)' in given
    assert "assert_passed" not in given  # ungraded: a wrong covers does not stop the notebook
    task = " ".join("".join(cells[ids.index("task_1_2")]["source"]).split())
    for asked in ("which edges or vertices", "Which sides does your box", "wholly outside"):
        assert asked in task
    assert not re.search(r"ceil|⌈|floor|⌊|- 0\.5|− ½", task), task


def test_no_lesson_prints_the_half_open_box():
    """Lesson 01 prints ⌈v − ½⌉ for span ends (2.1's rounding); no lesson writes the box's end
    as ⌈max − ½⌉: lesson 02 §1 prints the closed box, which fails."""
    pattern = re.compile(r"ceil\(\s*[uxvy]_?max\s*-\s*0\.5|⌈\s*[uxvy]_?max\s*[−-]\s*(0\.5|½)")
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        text = "".join("".join(c["source"]) for c in json.loads(path.read_text())["cells"])
        assert not pattern.search(text), path.name


@pytest.mark.parametrize(
    "value, words",
    [((1.0, 5.0, 2.0, 6.0), "floats"), ((1, 5, 2), "3 values"), ((True, 1, 2, 3), "bools")],
)
def test_answers_of_the_wrong_type_are_told(value, words):
    with pytest.raises(TypeError, match=words):
        cb.as_box(value)
