"""Review r374 (exercise 05): each variant the reader found misnamed or half-named is told its
own mistake, numbers print with consistent digits, 5.4's model answer uses `nearest` with its
own Δz, 5.3's zoom is a labelled panel, and the tasks say what the check assumes."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import reasoning_solutions as rs  # noqa: E402
from student_variants import KINDS, R374, WRONG  # noqa: E402

from teachraster import exercises as ex  # noqa: E402
from teachraster.exercises import decal_bias as db  # noqa: E402
from teachraster.exercises import depth_setup as ds  # noqa: E402
from teachraster.exercises import tries  # noqa: E402
from teachraster.exercises.diagnosis import Result  # noqa: E402
from teachraster.exercises.scalars import num  # noqa: E402

NOTEBOOK = Path(__file__).resolve().parent.parent / "notebooks/exercises/05_depth_precision.ipynb"
#: A float printed with all its digits (r374 F2: -1.0470271068459067e-05 beside 1.05e-05)
LONG = re.compile(r"\d\.\d{9,}")


def _cell(grade_id: str) -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    cell = next(c for c in cells if c["metadata"]["nbgrader"]["grade_id"] == grade_id)
    return "".join(cell["source"])


def _first(label: str):
    """The first failure of a variant of tests/student_variants.py, in a fresh kernel's state."""
    name, fn, words = WRONG[label]
    tries.forget_hints(name)
    report = ex.check(name, fn)
    assert not report.passed, str(report)
    return report, report.failures[0], words


@pytest.mark.parametrize("label", list(R374))
def test_each_variant_is_told_its_own_mistake_first(label):
    report, first, words = _first(label)
    assert words in first.explanation, first.explanation
    assert first.kind == KINDS[label], (first.kind, first.explanation)
    assert not LONG.search(first.explanation), first.explanation


def test_a_constant_nan_in_5_3_is_told_constant_with_the_cases_that_have_an_offset():
    """F1: ``return np.nan`` was told "check the r and m your test for NaN uses" and a `^` typo
    it does not hold; now it is constant, with how many cases have a working offset."""
    report, first, _ = _first("decal bias returning NaN always")
    cases = db.bias_cases()
    fits = sum(not db.impossible(args) for _, args, _ in cases)
    assert f"{fits} of the {len(cases)} cases have an offset that works" in first.explanation
    assert "0/0" not in first.explanation and "check the r and m" not in first.explanation
    # every case's NaN is what a complete solution with r typed 2^bits gives: said as a
    # condition, with the xor words
    assert "If your r is typed `1 / (2^bits - 1)`" in first.explanation
    # where an r from `^` leaves room for an offset (room far beyond 1/21), no `^` words
    roomy = (10.0, 60.0, 6.01e-4, 1.0, 100.0, 24, False, 9.0)
    assert not db._xor_gives(roomy)
    results = [Result(i, args, None, math.nan, False) for i, args in enumerate([roomy] * 3)]
    words = db.constant_nan(results)
    assert "NaN on every case" in words and "3 of the 3 cases" in words and "^" not in words


def test_a_constant_nan_elsewhere_keeps_its_words():
    """F1's fix is 5.3's own (NaN a legal answer): 5.1's constant NaN is still "a 0/0"."""
    tries.forget_hints("safe_near")
    report = ex.check("safe_near", lambda z, gap, far, bits: float("nan"))
    assert "a 0/0, or a NaN input passed on?" in report.failures[0].explanation


def test_5_3_room_in_view_units_and_slopes_are_told_apart():
    """F2/F3: `clear` in view units is named as such, not "ignores `clear`"; view depth's
    slope (code with `* pixel`) is named first, per unit only where pixel is never read."""
    _, first, _ = _first("decal bias with room taken as clear itself")
    assert "ignores `clear`" not in first.explanation
    assert "a view distance" in first.explanation
    _, first, _ = _first("decal bias from view depth's slope, own NaN test")
    assert first.explanation.count("you took the slope of the view depth") == 1
    assert "`* pixel` is missing" not in first.explanation
    _, first, _ = _first("decal bias per unit of x/z, own NaN test")
    assert "view depth" not in first.explanation


def test_5_4_names_a_flipped_comparison_and_16_bits_not_compare_first():
    """F4: both students compared; they are told their own slip, with 5.1's numbers."""
    for label in ("depth set-up with the comparison flipped", "depth set-up with 5.1 for 16 bits"):
        report, first, _ = _first(label)
        assert "5.1's near plane within `nearest` decides it" not in first.explanation
        assert all(f.kind == KINDS[label] for f in report.failures), str(report)
    # a student who always prefers reverse-Z is not told either: its own cause (r417 F2: it
    # was "16 bits" where both give the same tuples)
    tries.forget_hints("depth_setup")
    report = ex.check("depth_setup", WRONG["depth set-up preferring reverse-Z"][1])
    assert {f.kind for f in report.failures} == {"reverse-Z preferred"}, str(report)
    assert "16 bits" not in str(report), str(report)


def test_5_4_numbers_print_alike_and_no_near_plane_at_z_is_claimed():
    """F2 (Y-U) and F10: 5.1's n beside yours with the same digits; at z = 900 the words say
    no near plane short of z does it, with the formula's n beyond z."""
    z, gap, far, nearest = 2000.0, 0.05, 1e4, 0.01
    n = rs.safe_near(z, gap, far, 24)
    text = ds.explain_setup((z, gap, far, nearest), ds.expected_setup(z, gap, far, nearest),
                            ("unorm24", n, gap))  # fmt: skip
    assert not LONG.search(text), text
    args = (900.0, 3.5e-06, 1000.0, 0.1)
    text = ds.explain_setup(args, ds.expected_setup(*args), ("neither", 0.1, 1e-5))
    closed = rs.safe_near(900.0, 3.5e-06, 1000.0, 24)
    assert closed > 900 and f"5.1's formula gives {num(closed)}: none short of z" in text
    assert "a near plane at z itself" not in text


def test_5_4_model_answer_uses_nearest_with_its_own_dz():
    """F6: the teacher's answer is unorm24 at `nearest` with what it resolves there, not 5.1's
    zero-margin n with the gap handed back; the package's reference agrees."""
    source = _cell("depth_setup_solution")
    assert 'return "unorm24", nearest,' in source and 'return "unorm24", n, gap' not in source
    assert "margin" in source
    for _, args, expected in ds.setup_cases():
        got = rs.depth_setup(*args)
        assert ds.same_setup(got, expected, args)
        if expected[0] == "unorm24":
            assert got[1] == args[3] == expected[1]
            assert got[2] == pytest.approx(expected[2], rel=1e-9) and got[2] < args[1]
    assert ex.check("depth_setup", rs.depth_setup).passed


def test_5_3_zoom_is_its_own_labelled_panel_at_classroom_size():
    """F7: the linear zoom sits under the log strip, says it is a zoom, and its ticks are no
    smaller than "small"."""
    tries.forget_hints("decal_bias")
    case = db.bias_cases()[0]
    fig, ax = plt.subplots(figsize=(4.8, 4))
    db.draw_offset(ax, case, case[2])  # passing: m and the zoom drawn
    (panel,) = ax.child_axes
    assert "zoom" in panel.get_xlabel() and "linear" in panel.get_xlabel()
    strip, box = ax.get_window_extent(), panel.get_window_extent()
    assert box.y1 < strip.y0  # under the strip, not inside its log axis
    sizes = [t.get_fontsize() for t in panel.get_xticklabels()]
    assert (
        min(sizes)
        >= matplotlib.font_manager.font_scalings["small"] * plt.rcParams["font.size"] - 1e-9
    )
    plt.close(fig)


def test_the_tasks_say_what_the_checks_assume():
    """F7/F8/F9: 5.3's cell ends without a blank line and says the decal's pixel is on the
    view axis and room is measured between unrounded depths; 5.1 says the package's
    depth_resolution is not counted (and the check does not count it)."""
    text = _cell("decal_bias_task")
    assert not text.endswith("\n") and text == text.rstrip()
    assert "decal's pixel on the view axis" in text and "unrounded window depths" in text
    assert "`depth_resolution` is not counted" in _cell("safe_near_task")
    import teachraster as tr

    def safe_near(z, gap, far, bits):
        lo, hi = 1e-9, z
        for _ in range(100):
            mid = (lo + hi) / 2
            dz = float(tr.depth_resolution([z], mid, far, "unorm16")[0])
            if dz * (2**16 - 1) / (2**bits - 1) <= gap:
                hi = mid
            else:
                lo = mid
        return hi

    report = ex.check("safe_near", safe_near)
    assert not report.passed and "depth_resolution" in (report.package or "")
    assert rs.safe_near(10.0, 0.01, 1000.0, 24) > 0 and np.isfinite(rs.safe_near(1, 1, 10, 16))
