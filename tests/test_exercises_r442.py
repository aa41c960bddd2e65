"""Review r442 (exercise 5, a verifying reader): 5.3's test for NaN with r doubled or counted
twice, and m halved, named (F2, F3); 5.2's step from the exact d and its secant and d/z slopes
(F3); 5.1's resolution at z ± gap (F3); 5.2b's one-element list refused (F1), a depth held in
float32 told from a margin, 2^-24 at the crossings, crossings without n/f, candidates averaged
or picked by depth, NaN on a range without a crossing (F2, F3). Second round: 5.3's room to
first order at the object or the midpoint passed (two fixed cases now tell them), 5.2's
2^(e−24), ceil for floor and a margin, 5.1's bisection low end, 5.2b's depth a hair nearer
told as a search only."""

from __future__ import annotations

import numpy as np
import pytest
from student_variants import DIFFERENT, R442, R442_MORE
from variant_checks import assert_first_named, assert_passes

from teachraster import exercises as ex
from teachraster.exercises import near_plane as npl
from teachraster.exercises import reverse_z_worst as rzw


@pytest.mark.parametrize("label", sorted(R442) + sorted(R442_MORE))
def test_each_r442_variant_is_named_by_its_cause(label):
    """Every r442 wrong variant fails, its first failure named by its cause (R442_MORE: the
    second round, room to first order at the object or midpoint among them, which passed)."""
    assert_first_named(*{**R442, **R442_MORE}[label])


@pytest.mark.parametrize("label", sorted(k for k in DIFFERENT if "(r442" in k))
def test_each_r442_right_variant_passes(label):
    assert_passes(*DIFFERENT[label])


def test_a_list_of_one_is_refused_as_an_array_of_one_is():
    """F1: [Δz] passed where np.array([Δz]) was refused."""
    for value in ([1e-5], (1e-5,)):
        with pytest.raises(Exception, match="one number is expected"):
            rzw.as_gap(value)
    assert rzw.as_gap(1e-5) == 1e-5


@pytest.mark.parametrize("name", ["safe_near", "reverse_z_gap", "decal_bias"])
def test_5_1_to_5_3_refuse_one_number_in_brackets(name):
    """F1's class: 5.1 to 5.3 took [x] and np.array([x]) for x (5.2b alone refused the array)."""
    import reasoning_solutions as sol

    right = getattr(sol, name)
    for wrap in (lambda v: [v], lambda v: np.array([v])):
        report = ex.check(name, lambda *a, wrap=wrap: wrap(right(*a)))
        assert not report.passed, name
        assert "where one number is expected" in report.failures[0].explanation, str(report)
    with pytest.raises(Exception, match="not inside brackets"):
        npl.as_lone_number((0.5,))


def test_the_step_below_at_the_worst_crossing_names_2_to_the_e_minus_24():
    """F2 (w_N5): 2^-24 z (1 − z/f) at the crossings, z_min's own Δz beside, was told "your d
    came out just under" with no d computed: the words now give 2^(e−24) as a reading too."""
    args = (100.0, 900.0, 0.1, 1000.0)
    z_w = rzw.worst(*args)[0]
    got = 2.0**-24 * z_w * (1 - z_w / args[3])
    assert rzw.EDGE_BELOW.fits(args, rzw.expected_worst(*args), got)
    words = rzw.EDGE_BELOW.say(args, rzw.expected_worst(*args), got)
    assert "or you took 2^(e−24) (2^-24 z (1 − z/f)) there" in words
