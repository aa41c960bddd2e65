"""Lesson 08 (antialiasing): what it shows, read from the one execution every notebook test
shares (``tests/notebook_runs.py``; it used to execute the lesson a second time here)."""

import pytest
from notebook_runs import lesson

import teachraster as tr

pytestmark = pytest.mark.notebook


@pytest.fixture(scope="module")
def ns():
    return lesson("08_antialiasing")


def test_lesson_08_shows_what_it_says(ns):
    assert float(ns.area.sum()) == pytest.approx(
        abs(tr.Triangle(tr.snap(ns.xy)).signed_area), abs=1e-9
    )
    assert ns.sliver_1.coverage.sum() == 0 < ns.sliver_4.coverage.sum()  # vanishes, appears
    assert ns.shaded_ssaa > 2 * ns.shaded_msaa  # supersampling shades per sample
    assert 0.75 not in ns.levels["ordered grid"]
    assert ns.levels["rotated grid (standard)"] == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert (ns.count > 1).sum() == 0 and (ns.count == 1).sum() > 100  # watertight per sample
    assert ns.v_centre.min() < 0 or ns.v_centre.max() > 1  # extrapolated at the centres
    assert 0 <= ns.v_centroid.min() and ns.v_centroid.max() <= 1  # centroid stays inside
    assert ns.gif.stat().st_size > 1000
    plan = ns.frames[4].plan["multisampling"]
    assert 0 < plan.count < plan.total
    err = {f"{r['kind']}{r['samples']}": r["mean_error"] for r in ns.rows}
    assert err["standard16"] < err["standard4"] < err["standard1"]


def test_lesson_08_inspector_reads_sixteen_samples(ns):
    # the lesson's inspector, driven as a student would (the lesson no longer does it)
    from teachraster.widgets import PixelInspector

    inspector = PixelInspector(ns.tri, ns.W, ns.H, row=3, col=13)
    inspector.pattern.value = "16 standard"
    inspector.row.value, inspector.col.value = 3, 16
    assert "of 16 covered" in inspector.pixel.square.axes.get_title()
