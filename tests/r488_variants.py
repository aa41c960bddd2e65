"""Exercise 3.1b ``defect_case`` (r488): three students' answers, correct and wrong.

Each wrong answer carries the kind its first failure must have; tests/test_exercises_r488.py
runs them, and the report r488 lists their first explanations (each run in a fresh process).
"""

from __future__ import annotations

import numpy as np

D = 20000.0
#: Student A's cases: a 2-px triangle (E = 4 > 0) D px out; a clockwise one (E = -16) at 0.
FAR_CCW = ([[D, D], [D + 2, D], [D, D + 2]], (D + 0.5, D + 0.5))
FAR_CW = ([[D, D], [D, D + 2], [D + 2, D]], (D + 0.5, D + 0.5))
NEAR_CW = ([[0.0, 0.0], [0.0, 4.0], [4.0, 0.0]], (1.0, 1.0))
NEAR_CCW = ([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]], (1.0, 1.0))


def pair(zero, area):
    """``defect_case`` returning ``zero`` for the zero-area test and ``area`` for the area."""
    return lambda defect: zero if defect == "zero-area test" else area


def _searcher(defect):
    """Student B: moves a 3-px triangle out until the shipped test refuses it (E > 0)."""
    from teachraster.exercises.bary_repair import cond  # noqa: F401  (not used: own test below)

    def refused(xy):
        v = np.asarray(xy, float)
        return np.linalg.cond(np.vstack([v.T, np.ones(3)])) > 1e8

    if defect == "area":
        return [[10, 10], [10, 13], [13, 10]], (11.5, 11)
    d = 1.0
    while not refused([[d, d], [d + 3, d], [d, d + 3]]):
        d *= 2
    return [[d, d], [d + 3, d], [d, d + 3]], (d + 1, d + 1)


def _searcher_own_cond(defect):
    """Student B': the same search with a condition number computed from the SVD."""
    if defect == "area":
        return np.array([[5.5, 2.25], [1.5, 9.75], [12.5, 7.0]]), np.array([6.5, 6.5])
    d = 64.0
    while True:
        v = np.array([[d, -d], [d + 4, -d], [d, -d + 1]])
        s = np.linalg.svd(np.vstack([v.T, np.ones(3)]), compute_uv=False)
        if s[0] / s[-1] > 1e8:
            return v, np.array([d + 1, -d + 0.25])
        d *= 1.5
        d = np.round(d * 256) / 256


def _tuple_lists(defect):
    """Student C: plain tuples, the far one on negative coordinates, p outside."""
    if defect == "zero-area test":
        return ((-30000, -30000), (-29998, -30000), (-30000, -29998)), (-29990, -29990)
    return ((0, 0), (0, 6), (6, 0)), (-3, 2)


def _int_arrays(defect):
    """Student C': numpy int arrays; the area case's p on an edge."""
    if defect == "zero-area test":
        return np.array([[50000, 60000], [50005, 60000], [50000, 60001]]), np.array([50001, 60000])
    return np.array([[0, 0], [0, 8], [8, 0]]), np.array([4, 4])


#: label -> defect_case; every one must pass.
CORRECT = {
    "A: 2 px at 20 000 px; clockwise 4 px at 0": pair(FAR_CCW, NEAR_CW),
    "A: p = v3 of a far clockwise one (with the area repaired it is refused; alone, right at v3)":
        pair(([[D, D], [D, D + 2], [D + 2, D]], (D + 2, D)), NEAR_CW),
    "A: p at v1 of the clockwise one": pair(FAR_CCW, (NEAR_CW[0], (0.0, 0.0))),
    "B: a search doubling the distance": _searcher,
    "B: a search by the SVD, 1.5x steps on the grid": _searcher_own_cond,
    "C: tuples, negative coordinates, p outside": _tuple_lists,
    "C: int arrays, p on an edge": _int_arrays,
    "C: a check's shape (flat_top) moved 20 000 px out, and one at 0 for the area":
        pair(([[20000, 20000], [20006, 20000], [20000, 20006]], (20001, 20001)),
             ([[0, 0], [0, 6], [6, 0]], (-3, 2))),
    "C: a 10-px triangle at 100 000 px (E = 100)":
        pair(([[99990, 99990], [100000, 99990], [99990, 100000]], (99991, 99991)), NEAR_CW),
    "C: 1/256-px grid vertices, p off the centre":
        pair(([[12345.5, 23456.25], [12347.75, 23456.25], [12345.5, 23457.5]],
              (12346.0078125, 23456.5)),
             ([[1.00390625, 1.5], [2.5, 9.25], [8.75, 2.0]], (3.375, 3.125))),
}  # fmt: skip

_ORIGIN_THIN = ([[D, D], [D + 200, D], [D, D + 1 / 256]], (D + 0.5, D))


def _stub_raises(defect):
    raise NotImplementedError()


#: label -> (defect_case, kind of its first failure).
WRONG = {
    "A: swapped (the far one for the area)": (pair(NEAR_CW, FAR_CCW), "the other defect's"),
    "A: the far one, clockwise, for the zero-area test": (pair(FAR_CW, NEAR_CW), "also needs"),
    "A: the far clockwise one for both": (pair(FAR_CW, FAR_CW), "also needs"),
    "A: the check's first failing case (its six_vertex_orders) for the area": (
        pair(FAR_CCW, ([[1.5, 1.5], [4.5, 13.5], [13.5, 4.5]], (6.5, 6.5))), "catalogue"),
    "A: a near counter-clockwise one for the zero-area test": (pair(NEAR_CCW, NEAR_CW),
                                                                 "passes the test"),
    "A: only 1 000 px out": (pair(([[1000, 1000], [1002, 1000], [1000, 1002]], (1000.5, 1000.5)),
                                  NEAR_CW), "passes the test"),
    "A: a 100-px triangle 10 000 px out": (pair(([[1e4, 1e4], [1e4 + 100, 1e4], [1e4, 1e4 + 100]],
                                                  (1e4 + 1, 1e4 + 1)), NEAR_CW), "passes the test"),
    "A: a counter-clockwise one for the area": (pair(FAR_CCW, NEAR_CCW), "area right"),
    "A: the clockwise one at p = v3": (pair(FAR_CCW, (NEAR_CW[0], (4.0, 0.0))), "at v3"),
    "A: a far clockwise one for the area": (pair(FAR_CCW, FAR_CW), "also needs"),
    "A: the same far counter-clockwise one for both": (pair(FAR_CCW, FAR_CCW),
                                                        "the other defect's"),
    "B: a thin far sliver of its own (0.39 px²)": (pair(_ORIGIN_THIN, NEAR_CW), "thin"),
    "B: 0.5 px² at 100 000 px": (pair(([[1e5 - 1, 1e5 - 1], [1e5, 1e5 - 1], [1e5 - 1, 1e5]],
                                        (1e5 - 0.75, 1e5 - 0.75)), NEAR_CW), "thin"),
    "B: the check's far_from_origin triangle": (
        pair(([[100001, 100001], [100013.75, 100004], [100005.25, 100012]], (100006.5, 100005.5)),
             NEAR_CW), "out of range"),
    "B: the check's far triangle at 10 000 px": (
        pair(([[10001, 10001], [10013.75, 10004], [10005.25, 10012]], (10006.5, 10005.5)),
             NEAR_CW), "catalogue"),
    "B: the check's random 25, 30 000 px out, from its report": (
        pair(([[30003.86328125, 30010.015625], [30000.84765625, 30005.19140625],
               [30002.65625, 30007.25390625]], (30002.5, 30007.5)), NEAR_CW), "catalogue"),
    "B: three collinear far vertices": (pair(([[D, D], [D + 2, D + 2], [D + 4, D + 4]],
                                             (D + 1, D + 1)), NEAR_CW), "zero area"),
    "B: two equal vertices for the area": (pair(FAR_CCW, ([[0, 0], [0, 0], [4, 0]], (1, 0))),
                                           "zero area"),
    "B: 200 000 px out": (pair(([[2e5, 2e5], [2e5 + 2, 2e5], [2e5, 2e5 + 2]], (2e5, 2e5)),
                                NEAR_CW), "out of range"),
    "B: vertices off the grid (0.1 px)": (pair(FAR_CCW, ([[0.1, 0], [0, 4], [4, 0]], (1, 1))),
                                          "out of range"),
    "B: p off the grid (1/3 px)": (pair(FAR_CCW, (NEAR_CW[0], (1 / 3, 1.0))), "out of range"),
    "B: p a million px out": (pair(FAR_CCW, (NEAR_CW[0], (1e6, 1.0))), "out of range"),
    "C: the defect names misspelt (always the area case)": (
        lambda defect: FAR_CCW if defect == "zero area test" else NEAR_CW, "the other defect's"),
    "C: a lesson-07 style clockwise triangle for the zero-area test": (
        pair(([[1.5, 1.5], [4.5, 13.5], [13.5, 4.5]], (6.5, 6.5)), NEAR_CW), "catalogue"),
    "C: p = v3 of a counter-clockwise one": (pair(FAR_CCW, (NEAR_CCW[0], (0.0, 4.0))),
                                            "area right"),
    "C: a far clockwise one at p = v3 for the area": (
        pair(FAR_CCW, ([[D, D], [D, D + 2], [D + 2, D]], (D + 2, D))), "the other defect's"),
    "C: a 2-px one 5 000 px out": (pair(([[5000, 5000], [5002, 5000], [5000, 5002]],
                                         (5000.5, 5000.5)), NEAR_CW), "passes the test"),
    "C: swapped and a near one": (pair(NEAR_CW, NEAR_CCW), "the other defect's"),
}  # fmt: skip

#: label -> (defect_case, words its first explanation holds).
STUBS = {
    "raise NotImplementedError()": (_stub_raises, "not implemented yet"),
    "return None": (lambda defect: None, "returned None"),
    "the same point-triangle for both": (lambda defect: ([[0, 0], [0, 0], [0, 0]], (0, 0)),
                                         "zero area"),
}  # fmt: skip
