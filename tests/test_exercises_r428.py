"""r428 (exercise 1): near ties beside long edges tell a step off the centre, a relative
tolerance on the edge function's products, one on the area and an absolute one apart."""

import numpy as np

from teachraster.exercises import coverage as cov
from teachraster.exercises import sample_steps as st
from teachraster.exercises.coverage_checks import _expected, fill_cases, long_near_ties


def _wrong(images):
    case = long_near_ties()
    return tuple(int((im != e).sum()) for im, e in zip(images, _expected(case)))


def test_each_slip_gets_a_different_set_of_the_long_near_ties_wrong():
    case = long_near_ties()
    tris = case.triangles
    isclose = _wrong([st.image(case, xy, rel=1e-9) for xy in tris])
    step = _wrong([st.image(case, xy, (1e-7, 0.0)) for xy in tris])
    area = _wrong([st.image(case, xy, rel=1e-9, area=abs(cov.area2(xy))) for xy in tris])
    assert isclose == (0, 1, 1, 1, 0)  # diagonal, shallow, sliver
    assert step == (1, 1, 0, 1, 0)  # steep, diagonal, sliver
    assert area == (1, 1, 1, 0, 1)  # all but the sliver
    # no step along any direction, of any size, gives isclose's set
    for delta in st.STEPS:
        for sx, sy in st.DIRECTIONS:
            assert _wrong([st.image(case, xy, (sx * delta, sy * delta)) for xy in tris]) != isclose


def test_the_steep_and_the_short_near_ties_are_exact_in_float32():
    case = long_near_ties()
    f = np.float32
    for xy in case.triangles[[0, 4]]:
        v = xy.astype(f)
        rows, cols = np.indices(case.size[::-1])
        px, py = (cols + f(0.5)).astype(f), (rows + f(0.5)).astype(f)
        s = np.sign(cov.area2(xy))
        for k in range(3):
            a, b = v[k], v[(k + 1) % 3]
            e32 = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
            a, b = xy[k], xy[(k + 1) % 3]
            exact = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
            assert np.array_equal(np.sign(e32), np.sign(exact)), s


def test_fill_has_the_long_near_ties_too():
    assert any(label.startswith("long near ties") for label, _, _ in fill_cases())
