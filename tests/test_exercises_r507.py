"""r507: exercise 4 read again after r496. 4.3's check no longer hangs on lesson 04's weights
solved by least squares on the screen (LAPACK's SVD never returns on a matrix holding inf, the
w = 0 case: numpy's lstsq, svd and pinv refuse it while the student's function runs); two cases
leave two sets of equations open at once, so a fallback from one to the other fails; a vertex
0.0008 behind the near plane fails a kept-vertex look-up with a loose tolerance; NaN or one
grey at every vertex of a triangle some sets leave open lists them all; positions as colours,
colours over w times w and float16 weights are named; 4.1's answers in reverse order are
named. Every variant is in tests/student_variants.py (R507, R507_DIFFERENT), replayed by
test_checker_corpus; here only what the corpus does not show (cost: one check, about 0.5 s,
in a subprocess that cannot hang the suite)."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest
from student_variants import R507, R507_DIFFERENT

from teachraster.exercises import clip_colour as cc
from teachraster.exercises.finite_linalg import HANGING, InfiniteMatrix, refusing_inf


def test_the_guard_refuses_inf_and_gives_numpy_back():
    a = np.array([[np.inf, 1.0, 1.0], [1.0, 1.0, 1.0], [1.0, 2.0, 3.0]])
    with refusing_inf():
        for name in HANGING:
            with pytest.raises(InfiniteMatrix):
                getattr(np.linalg, name)(*((a, np.ones(3)) if name == "lstsq" else (a,)))
        ok = np.linalg.lstsq(np.eye(3), np.ones(3), rcond=None)[0]  # finite: numpy's own
        assert np.allclose(ok, 1.0)
    assert all(getattr(np.linalg, n).__module__.startswith("numpy") for n in HANGING)
    assert issubclass(InfiniteMatrix, np.linalg.LinAlgError)


def test_lstsq_on_the_screen_ends_and_names_w_0():
    """T1: the check ran 12 minutes before it was killed; it must end in seconds."""
    code = textwrap.dedent(
        """
        import numpy as np
        from student_variants import R507
        from teachraster import exercises as ex
        name, fn, _, _ = R507["clipped colours: lesson 04 weights by lstsq on x/w, y/w, z/w (r507 T1)"]
        report = ex.check(name, fn)
        print(next(f.explanation for f in report.failures if "inf" in f.explanation))
        """
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=60,
        env={**__import__("os").environ, "PYTHONPATH": ":".join(sys.path)},
    )  # fmt: skip
    assert out.returncode == 0, out.stderr[-2000:]
    assert "your matrix holds inf: on the screen v1 = (0.5, 1, -1, 0) has w = 0" in out.stdout


def test_two_open_sets_on_one_triangle_and_a_near_new_vertex_are_cases():
    labels = [label for label, _, _ in cc.colour_cases()]
    for start in ("every y = 0 and v3 = v1 + v2", "x + y = 1 and z = w − 2 at every vertex",
                  "a vertex 0.0008 behind the near plane"):  # fmt: skip
        assert any(label.startswith(start) for label in labels), start
    v = np.array([[1.0, 0, -2, 1], [-0.5, 0, 1, 1], [0.5, 0, -1, 2]])
    open_sets = cc._open_subsets(v)
    assert ((0, 1), True) in open_sets and ((0, 1, 2, 3), False) in open_sets
    v = np.array([[-1.0, 2, -3, -1], [1, 0, 0, 2], [2, -1, 2, 4]])
    open_sets = cc._open_subsets(v)
    assert ((0, 1), True) in open_sets and ((2, 3), True) in open_sets


def test_r507_variants_are_in_the_corpus_with_kinds():
    assert len(R507) == 13 and len(R507_DIFFERENT) == 10
    kinds = {kind for _, _, _, kind in R507.values()}
    assert {"kept by a loose tolerance", "NaN where some equations are open", "one grey for all",
            "answers reversed", "colour from the screen"} <= kinds  # fmt: skip
