"""Review r425 (exercise 5, a fresh reader): 5.2b graded to 1e-8 either way, since a search
refined onto the jump of float32's rounded d lands over the limit (F1); z_min on a crossing
graded (F2); 5.2b, 5.2 and 5.4 slips named (F3, F4, F5); 5.3's rule staged (F6)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
import reasoning_solutions as sol
from student_variants import DIFFERENT, R425
from variant_checks import assert_first_named, assert_passes

from teachraster import exercises as ex
from teachraster.exercises import decal_bias as db
from teachraster.exercises import reverse_z_worst as rzw
from teachraster.exercises import tries

NOTEBOOK = Path(__file__).parents[1] / "notebooks" / "exercises" / "05_depth_precision.ipynb"


def _task_text() -> str:
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    ids = [c["metadata"]["nbgrader"]["grade_id"] for c in cells]
    return "".join(cells[ids.index("reverse_z_worst_task")]["source"])


def test_the_rounded_maximum_lies_where_the_task_says():
    """F1: reverse_z_gap's largest lies at d = 2^e (1 − 2^-25), 2^-24 (1 − z_e/f) over the
    limit: 3e-8 to 6e-8 wherever the coarsest crossing is nearer than f/2, over ABOVE on every
    fixed case whose crossing is nearer than 0.83 f (the task's words)."""
    text = " ".join(_task_text().split())
    assert "up to 6·10^-8 (relative) more" in text and "3·10^-8 to 6·10^-8 over it" in text
    assert "wherever the coarsest depth lies nearer than f/2" in text
    for s in rzw.SETTINGS:
        edge = rzw.rounded_edge(*s)
        if edge is None:
            continue
        z_w, e = rzw.worst(*s)[0], rzw.expected_worst(*s)
        over = edge[1] / e - 1
        assert over == pytest.approx(2.0**-24 * (1 - z_w / s[3]), rel=1e-3), s
        assert over <= 6e-8 and (z_w > s[3] / 2 or over >= 2.9e-8), (s, over)
        if z_w < 0.83 * s[3]:
            assert not rzw.same_worst(edge[1], e), s
        # reverse_z_gap (float32's d) a hair nearer gives it (at z_b, d is float32's tie, and
        # float64's rounding of d decides), and a hair farther the step halves
        assert sol.reverse_z_gap(edge[0] * (1 - 1e-12), *s[2:]) == pytest.approx(edge[1], rel=1e-9)
        assert sol.reverse_z_gap(edge[0] * (1 + 1e-9), *s[2:]) < e, s


def test_the_task_makes_no_false_claim_about_searches():
    """F1: "no search the check's time limit allows comes within 10^-8" was false."""
    text = " ".join(_task_text().split())
    assert "no search" not in text and "comes within" not in text
    assert "the *exact* d" in text and "the task leaves that rounding out" in text


def test_z_min_on_a_crossing_is_a_fixed_case():
    """F2: no case put z_min on a crossing, so `z_min < z_e` passed."""
    assert (2.0, 2.2, 1.0, 3.0) in rzw.SETTINGS
    assert rzw.worst(2.0, 2.2, 1.0, 3.0)[0] == 2.0


@pytest.mark.parametrize("label", sorted(R425))
def test_each_r425_variant_is_named_by_its_cause(label):
    """F1–F5: every r425 wrong variant fails, its first failure named by its cause."""
    assert_first_named(*R425[label])


@pytest.mark.parametrize("label", sorted(k for k in DIFFERENT if "(r425" in k))
def test_each_r425_right_variant_passes(label):
    assert_passes(*DIFFERENT[label])


def test_float32_answers_pass_either_side_by_their_rounding():
    """F1: the band over the limit is 1e-8 for float64, float32's two steps for float32."""
    for s in rzw.SETTINGS:
        e = rzw.expected_worst(*s)
        up = np.float32(e + 1.5 * float(np.spacing(np.float32(e))))
        assert rzw.same_worst(up, e) and not rzw.same_worst(e * (1 + 3e-8), e), s
        assert rzw.same_worst(e * (1 + 5e-9), e), s


def _decal_first(fn) -> str:
    return ex.check("decal_bias", fn).failures[0].explanation


def test_5_3_holds_back_the_rule_until_two_answers_failed():
    """F6: the first failure gave [r + m, room − m], room's value and the NaN test."""
    tries.forget_hints("decal_bias")
    first = _decal_first(lambda z, t, p, n, f, b, rev, c: -1 / (2**b - 1))
    assert "room − m" not in first and "room =" not in first and "NaN when" not in first, first
    assert "big enough to win against the wall" in first, first
    _decal_first(lambda z, t, p, n, f, b, rev, c: -2 / (2**b - 1))
    full = _decal_first(lambda z, t, p, n, f, b, rev, c: -3 / (2**b - 1))
    assert "(room − m, where room =" in full and "NaN when room − m < r + m" in full, full
    tries.forget_hints("decal_bias")


def test_5_3s_figure_calls_no_negative_number_absolute():
    """F8: "yours -1 steps, as |o|"."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    tries.forget_hints("decal_bias")
    case = db.bias_cases()[0]
    fig, ax = plt.subplots()
    db.draw_offset(ax, case, -1 / (2 ** case[1][5] - 1))
    labels = ax.get_legend_handles_labels()[1]
    plt.close(fig)
    assert any(lab.startswith("|yours| = 1 steps") for lab in labels), labels
    assert not any("room =" in lab for lab in labels), labels


def test_the_closed_form_in_float32_throughout_passes_every_drawn_range():
    """r425 C4: at two float32 steps it failed a few drawn ranges in a hundred (4.8 steps off)."""
    from student_variants import _r425_all_float32

    rng = np.random.default_rng(425)
    for _ in range(3000):
        s = rzw._drawn(rng)
        assert rzw.same_worst(_r425_all_float32(*s), rzw.expected_worst(*s)), s
    for s in rzw.SETTINGS:
        assert rzw.same_worst(_r425_all_float32(*s), rzw.expected_worst(*s)), s
