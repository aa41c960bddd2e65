"""``diagnosis._rounded_to`` names an answer rounded to N decimals or N significant digits.

It tests the answer's wrong numbers first and writes out the rest only when they fit (a whole
array written out for every N cost more than the rest of a check); the words must be those of
the plain test, number by number over the whole array, which this file keeps as a reference.
"""

from __future__ import annotations

import numpy as np

from teachraster.exercises import diagnosis


def _reference(expected, got) -> str | None:
    g, e = np.ravel(np.asarray(got, float)), np.ravel(np.asarray(expected, float))
    if np.array_equal(g, e):
        return None
    fit = [n for n in diagnosis.ROUNDINGS if np.allclose(g, np.round(e, n), rtol=1e-12, atol=1e-15)]
    if fit:
        return f"{fit[0]} decimals" if len(fit) == 1 else f"{fit[0]} to {fit[-1]} decimals"
    for n in range(3, 13):
        written = np.array([float(f"{x:.{n}g}") for x in e])
        if np.allclose(g, written, rtol=1e-12, atol=1e-300):
            return f"{n} significant digits"
    return None


def test_rounded_answers_are_named_as_the_whole_array_test_names_them():
    rng = np.random.default_rng(1)
    named = 0
    for _ in range(1000):
        e = rng.uniform(-1e3, 1e3, rng.integers(1, 9)) * 10.0 ** rng.integers(-6, 6)
        n, how = int(rng.integers(1, 14)), int(rng.integers(0, 4))
        if how == 0:  # every number to n significant digits
            g = np.array([float(f"{x:.{n}g}") for x in e])
        elif how == 1:  # to n decimals
            g = np.round(e, n)
        elif how == 2:  # one number rounded, the others exact
            g = e.copy()
            k = int(rng.integers(0, e.size))
            g[k] = float(f"{e[k]:.{n}g}")
        else:  # noise, rounded to nothing
            g = e * (1 + rng.normal(0, 1e-6, e.size))
        want = _reference(e, g)
        assert diagnosis._rounded_to(e, g) == want, (e, g)
        named += want is not None
    assert named > 300  # the cases do exercise both kinds of words
