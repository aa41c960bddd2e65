"""Review r417 (exercise 5, a fresh reader): 5.2b ``reverse_z_worst`` graded to 1e-8, so that
no sampled search within the check's CPU limit passes (F1); causes named only where they give
every answer (F2, F3, F5); bounds printed with the digits that tell them apart (F4)."""

from __future__ import annotations

import numpy as np
import pytest
import reasoning_solutions as sol
from student_variants import R417

from teachraster import exercises as ex
from teachraster.exercises import reverse_z_worst as rzw
from teachraster.exercises import tries


def _dense(count, space=np.linspace):
    def reverse_z_worst(z_min, z_max, near, far):
        z = space(z_min, z_max, count)
        d = ((near / z - near / far) / (1 - near / far)).astype(np.float32)
        return float((np.spacing(d).astype(float) * (1 - near / far) * z * z / near).max())

    return reverse_z_worst


@pytest.mark.parametrize("space", [np.linspace, np.geomspace])
def test_ten_million_sampled_depths_fail_most_fixed_cases(space):
    """F1: at 1e-4, 50,001 evenly spaced depths passed every case; at 1e-8, 10^7 (about 0.1 s
    of CPU a case, vectorised) fail most of the fixed cases whose worst is a crossing."""
    search = _dense(10_000_001, space)
    crossing = [s for s in rzw.SETTINGS if rzw.worst(*s)[0] != s[1]]
    failed = [s for s in crossing if not rzw.same_worst(search(*s), rzw.expected_worst(*s))]
    assert len(failed) >= len(crossing) // 2, (len(failed), len(crossing))


def test_the_band_is_float64s_or_float32s_own_rounding():
    """F1: right answers in float64 lie within 1e-15; one float32 holds within two steps."""
    for s in rzw.SETTINGS:
        e = rzw.expected_worst(*s)
        assert rzw.same_worst(sol.reverse_z_worst(*s), e), s
        assert rzw.same_worst(np.float32(e), e) and rzw.same_worst(float(np.float32(e)), e), s
        assert not rzw.same_worst(e * (1 - 3e-8), e), s
        below = e - (rzw.FLOAT32_STEPS + 1) * float(np.spacing(np.float32(e)))
        assert not rzw.same_worst(np.float32(below), e), s


def test_the_bounds_print_apart_from_the_answer_and_the_coarsest():
    """F4: "accepts 2.95e-05 to …; yours is 2.95e-05", a bound printed above the coarsest."""
    for s in rzw.SETTINGS:
        e = rzw.expected_worst(*s)
        for got in (e * (1 - 2e-8), e * (1 - 1e-4), e * 0.9):
            words = rzw.explain_worst(s, e, got)
            lo = words.split("the check accepts ")[1].split(" to ")[0]
            yours = words.split("yours is ")[1].split(" ")[0]
            coarsest = words.split("the coarsest Δz is ")[1].split(" ")[0]
            assert len({lo, yours, coarsest}) == 3, words
            assert float(lo) < float(coarsest) and float(yours) < float(coarsest), words


@pytest.mark.parametrize("label", sorted(R417))
def test_each_r417_variant_is_named_by_its_cause(label):
    """F1, F2, F3, F5: every failure named, the first by the words the report asked for."""
    name, fn, words, kind = R417[label]
    tries.forget_hints(name)
    report = ex.check(name, fn)
    assert not report.passed, label
    first = report.failures[0]
    assert words in first.explanation and first.kind == kind, (label, first.kind, first.explanation)
    tries.forget_hints(name)


def test_z_max_only_is_said_only_where_it_gives_every_answer():
    """F3: the finest candidate, z_max's own on case 1, was told "you evaluated the gap at
    z_max only"; z_max's own on every case still is."""
    tries.forget_hints("reverse_z_worst")
    at_max = ex.check("reverse_z_worst", lambda a, b, n, f: sol.reverse_z_gap(b, n, f))
    assert all(f.kind == "z_max only" for f in at_max.failures), str(at_max)
    _, fn, _, _ = R417["reverse-Z worst, the finest of the right candidates"]
    report = ex.check("reverse_z_worst", fn)
    assert "z_max only" not in str(report), str(report)
    tries.forget_hints("reverse_z_worst")


def test_a_pair_is_printed_short():
    """F8: (900.0, 7.366170393652282e-06) echoed with 17 digits."""
    report = ex.check("reverse_z_worst", lambda a, b, n, f: (b, sol.reverse_z_gap(b, n, f)))
    assert "returned (900, 7.37e-06), 2 values" in report.failures[0].explanation, str(report)


def test_a_slip_tied_with_another_names_both():
    """F8: a constant 2^-23 (1 − n/f) z_max²/n was float32's step above 1 on case 1, float16's
    on case 2 (the same number there): both are said where both give it."""
    s = (200.0, 300.0, 0.1, 1000.0)
    got = 2.0**-23 * (1 - 0.1 / 1000) * 300.0**2 / 0.1
    kinds = [k for k, _ in rzw.gap_slips(s, got, rzw.expected_worst(*s))]
    assert {"float16", "step above 1"} <= set(kinds), kinds
    words = rzw._gap_slip_words(s, rzw.expected_worst(*s), got)
    assert "float16" in words and "just above depth 1" in words, words
