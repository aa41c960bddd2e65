"""Review r381 F6 (r374 F9): exercise 5.2b, ``reverse_z_worst``, the coarsest Δz of float32
reverse-Z over a range of depths, which lesson 05b's printed formula at z_max does not give."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import reasoning_solutions as sol

from teachraster import depth_resolution
from teachraster import exercises as ex
from teachraster.exercises import reverse_z_worst as rzw
from teachraster.exercises import tries

NOTEBOOK = Path(__file__).resolve().parent.parent / "notebooks/exercises/05_depth_precision.ipynb"


@pytest.mark.parametrize("setting", rzw.SETTINGS)
def test_the_reference_is_the_largest_step_over_the_slope_at_every_depth(setting):
    """The edges and z_max give what 200,001 depths' float32 steps over the slope give."""
    expected, brute = rzw.expected_worst(*setting), rzw.brute_worst(*setting)
    assert brute <= expected * (1 + 1e-9) and brute >= expected * (1 - 2e-5), (expected, brute)


def test_unorm_resolves_worst_at_z_max_and_reverse_z_inside_the_range():
    """The claim the task makes: unorm's Δz grows with z at every near plane; reverse-Z's worst
    on lesson 05b's planes from 100 to 900 is at 450.3 (d = 2^-13), 4 times z_max's."""
    for near, far in ((0.1, 1000.0), (1.0, 10.0), (0.01, 1e4)):
        z = np.linspace(2 * near, far, 10_001)
        for fmt in ("unorm16", "unorm24"):
            assert np.all(np.diff(depth_resolution(z, near, far, fmt)) > 0)
    z_w, dz = rzw.worst(100.0, 900.0, 0.1, 1000.0)
    assert (
        abs(z_w - 450.333) < 1e-3 and np.float32(rzw.reversed_depth(z_w, 0.1, 1000.0)) == 2.0**-13
    )
    assert 3.9 < dz / rzw.candidates(100.0, 900.0, 0.1, 1000.0)[0][1] < 4.1


def test_the_printed_formula_at_z_max_fails_and_is_told_where_the_worst_is():
    """r404 F1: first a question (no depth, no binade, no method), the place once two
    different answers have failed."""
    tries.forget_hints("reverse_z_worst")
    at_max = lambda a, b, n, f: sol.reverse_z_gap(b, n, f)  # noqa: E731
    report = ex.check("reverse_z_worst", at_max)
    assert len(report.failures) >= len(rzw.SETTINGS) - 2, str(report)
    first = report.failures[0].explanation
    # r425 F3: hedged (float64's step at the crossings gives the same answer)
    assert "that is z_max's own Δz on every case: you evaluated the gap at z_max only" in first
    assert "does float32 reverse-Z?" in first and "(4.01 times too fine)" in first, first
    for told in ("450.3", "2^-13", "2^-36", "compare z_max with"):
        assert told not in str(report), told
    ex.check("reverse_z_worst", lambda a, b, n, f: sol.reverse_z_gap(a, n, f))
    first = ex.check("reverse_z_worst", at_max).failures[0].explanation
    assert "worst step is at z = 450.333, where d falls to 2^-13" in first, first
    tries.forget_hints("reverse_z_worst")


def test_the_figure_draws_the_curve_only_once_told():
    """r404 F1: after a wrong answer with hints left, z_max's Δz and yours only."""
    import matplotlib.pyplot as plt

    case = rzw.worst_cases()[0]
    tries.forget_hints("reverse_z_worst")
    labels = {}
    for key, got in (("wrong", 7.37e-6), ("right", case[2])):
        fig, ax = plt.subplots()
        rzw.draw_worst(ax, case, got)
        labels[key] = " ".join(t.get_text() for t in ax.get_legend().get_texts())
        assert ax.yaxis.get_offset_text().get_text() == "", key
        plt.close(fig)
    assert "coarsest" not in labels["wrong"] and "z_max's own" in labels["wrong"]
    assert "coarsest 2.95e-05 at z = 450.333" in labels["right"], labels


def test_drawn_cases_have_their_worst_inside_the_range():
    for _, args, expected in rzw.worst_cases()[len(rzw.SETTINGS) :]:
        assert expected > 1.1 * rzw.candidates(*args)[0][1]


def test_the_task_states_the_band_its_check_allows():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in cells]
    # r417 F7: the prediction, a place to write it (the function's cell, which the student
    # edits: every other cell is locked), then the task and its rule
    text = "".join(cells[ids.index("reverse_z_worst_task")]["source"])
    asked = text.split("\n---\n")[0]
    assert "predict" in asked and "power of two" not in asked, asked
    stub = "".join(cells[ids.index("reverse_z_worst_solution")]["source"])
    assert stub.startswith("# Your prediction (not graded)"), stub
    # r417 F1, r425 F1: 10^-8 either way (a uniform search falls short, a refined one lands on
    # float32's rounded maximum, over it); no claim that no search comes that close
    assert rzw.BELOW == rzw.ABOVE, (rzw.BELOW, rzw.ABOVE)
    assert f"within 10^{int(np.log10(rzw.BELOW))} (relative) of the coarsest Δz either" in text
    assert "seldom" not in text and "no search" not in text and "% above" not in text, text
    assert rzw.FLOAT32_STEPS == 8 and "eight of\nfloat32's steps either way" in text, text
    # r458: 5.2 is a ruler written in 5.2b's cell, above reverse_z_worst (its task before 5.2b's)
    assert ids.index("reverse_z_gap_task") < ids.index("reverse_z_worst_task")
    assert stub.index("def reverse_z_gap(") < stub.index("def reverse_z_worst(")
    assert "predict" in text and text.index("predict") < text.index("Write `reverse_z_worst")


def test_z_min_on_a_crossing_counts_with_the_binade_above():
    """r414 F5: d(2) = 1/4 exactly for near 1, far 3: z_min's own Δz, 2^-25 (1 − n/f) z_min²/n,
    is the coarsest, as the task's rule (the step above a stored 2^e) and 200,001 depths say."""
    setting = (2.0, 2.2, 1.0, 3.0)
    assert rzw.reversed_depth(2.0, 1.0, 3.0) == 0.25
    expected = rzw.expected_worst(*setting)
    assert expected == 2.0**-25 * (1 - 1 / 3) * 4.0 == sol.reverse_z_gap(2.0, 1.0, 3.0)
    assert rzw.worst(*setting)[0] == 2.0
    assert expected * (1 - 2e-5) <= rzw.brute_worst(*setting) <= expected * (1 + 1e-9)


@pytest.mark.parametrize("count", [1001, 2001, 10001])
def test_an_evenly_spaced_search_fails_a_fixed_case(count):
    """r414 F2: 1,001 (and up to 10,001) evenly spaced depths passed every case at 0.5 %."""
    short = [
        s
        for s in rzw.SETTINGS
        for z in [np.linspace(s[0], s[1], count)]
        if max(sol.reverse_z_gap(x, *s[2:]) for x in z) < rzw.expected_worst(*s) * (1 - rzw.BELOW)
    ]
    assert len(short) >= 3, short


def test_a_search_just_short_is_no_slip_of_5_2():
    """r414 F1: "infinite far" gives the answer itself where n/f ≪ 1: a search 1 % short was
    told "you dropped the far plane", with the answer printed as the slip's value."""
    setting = (100.0, 900.0, 0.1, 1000.0)
    expected = rzw.expected_worst(*setting)
    for got in (expected * 0.99, expected * 0.995, expected * 0.9999):
        assert rzw.gap_slip(setting, got, expected) is None, got


def test_d_in_float32_at_the_worst_crossing_fails_a_fixed_case():
    """r414 F4: on (300, 505, 40.8, 549) d computed in float32 at the worst crossing rounds to
    just under 2^-4 (np.spacing: the step below), on every run, not on 1 draw in 15."""
    s = (300.0, 505.0, 40.8, 549.0)
    assert s in rzw.SETTINGS
    z_w = rzw.worst(*s)[0]
    f = np.float32
    d = (f(s[2]) / f(z_w) - f(s[2]) / f(s[3])) / (f(1) - f(s[2]) / f(s[3]))
    assert d < 2.0**-4 and np.float32(rzw.reversed_depth(z_w, *s[2:])) == 2.0**-4


def test_5_2s_passing_figure_is_not_at_5_2bs_planes():
    """r414 F3: a passing 5.2 drew its first case, z = 300 at near 0.1, far 1000: the sawtooth
    over z 75 to 1000 answered 5.2b's prediction (lesson 05b's planes) a cell early."""
    from teachraster.exercises.reverse_z import REVERSE_Z_GAP, gap_cases

    _, (_, near, far), _ = gap_cases()[REVERSE_Z_GAP.example]
    assert (near, far) != (0.1, 1000.0)


def test_the_teachers_solution_takes_z_min_on_a_crossing():
    """r414 F5: the solution follows the task's rule at z_min too."""
    assert sol.reverse_z_worst(2.0, 2.2, 1.0, 3.0) == rzw.expected_worst(2.0, 2.2, 1.0, 3.0)
