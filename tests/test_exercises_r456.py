"""r456 (exercise 04): what a verifying read found in depth_passes, clip_near and
clip_near_colour beyond r448; the wrong and different variants are in student_variants.py
(R456)."""

from __future__ import annotations

import numpy as np

from teachraster import exercises as ex
from teachraster.exercises.depth_clipping import clip_cases
from teachraster.exercises.zbuffer_pixel import depth_cases


def _depth_float32(depths, writes):
    stored, out = np.float32(np.inf), []
    for d, w in zip(np.asarray(depths, np.float32), writes):
        out.append(bool(d < stored))
        if d < stored and w:
            stored = d
    return out


def _clip_float32(v):
    v = np.asarray(v, np.float32)
    out = []
    for i in range(3):
        a, b = v[i], v[(i + 1) % 3]
        da, db = a[2] + a[3], b[2] + b[3]
        if da >= 0:
            out.append(a)
        if da * db < 0:  # d_a·d_b of the case near the eye is 2^-127: no underflow
            out.append(a + abs(da) / (abs(da) + abs(db)) * (b - a))
    return np.array(out, np.float32).reshape(-1, 4)


def test_the_new_cases_hold_apart_in_float32():
    """The margins' and tolerances' cases are exact in float32: a float32 answer passes."""
    assert ex.check("depth_passes", _depth_float32).passed
    assert ex.check("clip_near", _clip_float32).passed
    labels = [label for label, _, _ in depth_cases()]
    assert any("one float32 step" in label for label in labels)
    for label, (v,), _ in clip_cases():
        if "behind the near plane, close to the eye" in label or "float32 step" in label:
            held = v.astype(np.float32)
            assert (held.astype(float) == v).all(), label
            assert ((held[:, 2] + held[:, 3]).astype(float) == v[:, 2] + v[:, 3]).all(), label


def _check(name, source):
    space = {"np": np}
    exec(source, space)  # noqa: S102 - the test's own source
    return ex.check(name, space[name])


def test_the_packages_depth_test_and_distances_are_not_counted():
    report = _check(
        "depth_passes",
        """
from teachraster.pipeline.visibility.zbuffer import passes_depth_test
def depth_passes(depths, writes):
    stored, out = np.inf, []
    for d, w in zip(depths, writes):
        ok = bool(passes_depth_test(d, stored))
        out.append(ok)
        if ok and w:
            stored = d
    return out
""",
    )
    assert not report.passed and "not counted" in str(report)
    report = _check(
        "clip_near",
        """
from teachraster.pipeline.geometry.clipping import distances
def clip_near(v):
    v = np.asarray(v, float)
    d = distances(v)[:, 0]
    out = []
    for i in range(3):
        j = (i + 1) % 3
        if d[i] >= 0:
            out.append(v[i])
        if (d[i] >= 0) != (d[j] >= 0):
            out.append(v[i] + d[i] / (d[i] - d[j]) * (v[j] - v[i]))
    return np.array(out).reshape(-1, 4)
""",
    )
    assert not report.passed and "not counted" in str(report)


def test_depths_near_the_near_plane_are_drawn_on_their_own_scale():
    """The 1e-20 case's bars were invisible on the 0-1 axis, and no offset text stands above
    the axis: the scale is in the label."""
    import matplotlib.pyplot as plt

    def margin(depths, writes):
        stored, out = np.inf, []
        for d, w in zip(depths, writes):
            ok = d < stored - 1e-9
            out.append(ok)
            if ok and w:
                stored = d
        return out

    report = ex.check("depth_passes", margin)
    assert "1e-20" in report.failures[0].case
    fig, ax = plt.subplots()
    report.plot(ax)
    fig.canvas.draw()
    assert ax.get_ylim()[1] < 1e-19
    assert "× 1e-20" in ax.get_ylabel() and not ax.yaxis.get_offset_text().get_text()
    plt.close(fig)
