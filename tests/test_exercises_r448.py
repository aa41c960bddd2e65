"""r448 (exercise 04): what a verifying read found in depth_passes, clip_near and
clip_near_colour; the wrong variants themselves are in student_variants.py (R448)."""

from __future__ import annotations

import math

from teachraster import exercises as ex
from teachraster.exercises.zbuffer_pixel import depth_cases


def _first(report) -> str:
    return str(report).split("\n- ", 1)[1]


def test_depth_passes_gets_the_lists_the_task_promises():
    for _, (depths, writes), _ in depth_cases():
        assert type(depths) is list and type(writes) is list
        assert all(type(w) is bool for w in writes)


def test_a_depth_nearer_by_less_than_the_grid_is_asked():
    labels = [label for label, _, _ in depth_cases()]
    assert any("nearer by 0.01" in label for label in labels)
    assert any("nearer by 1e-7" in label for label in labels)


def test_glass_against_the_first_wall_is_not_called_a_shift():
    """M1: [True, True, True] against [True, True, False] was told "shifted by one"."""

    def glass_against_first_wall(depths, writes):
        stored, first, out = math.inf, math.inf, []
        for d, w in zip(depths, writes):
            ok = d < (stored if w else first)
            out.append(ok)
            if ok and w:
                stored = d
                first = d if first == math.inf else first
        return out

    report = ex.check("depth_passes", glass_against_first_wall)
    assert not report.passed
    said = str(report)
    assert "shifted" not in said and "still tested" not in said, said


def test_a_tolerance_in_the_clip_names_the_vertex_behind_the_eye():
    def clip(v):
        out = []
        for i in range(3):
            a, b = v[i], v[(i + 1) % 3]
            da, db = a[2] + a[3], b[2] + b[3]
            if da >= -1e-3:
                out.append(a)
            if (da >= -1e-3) != (db >= -1e-3):
                out.append(a + da / (da - db) * (b - a))
        return out

    report = ex.check("clip_near", clip)
    assert not report.passed
    assert "behind the eye (w < 0)" in _first(report)
