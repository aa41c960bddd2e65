"""``report.compare`` for ``fill``: the student's fill of a fan of 16 triangles beside the
package's, the pixels where the counts differ, each explained on demand (the same pictures as
exercises 05–08: one :class:`~teachraster.exercises.scenes.Scene` for all)."""

from __future__ import annotations

import time

import numpy as np
import pytest
from endless_loops import forever
from exercise_solutions import CORRECT, _fill_from, both_own, one_winding

from teachraster import exercises as ex
from teachraster.exercises.picture_scenes import fill_scene


def texts(fig) -> str:
    return "\n".join(t.get_text() for t in fig.findobj(lambda a: hasattr(a, "get_text")))


def test_a_correct_fill_matches_on_every_pixel(plt):
    scene = fill_scene(CORRECT["fill"])
    scene.seconds = 120  # exact Fractions: slow on a loaded machine
    assert scene.error is None and len(scene.differing()) == 0
    assert scene.reference.max() == 1 and scene.reference.sum() > 50  # watertight: once each
    fig, axes = plt.subplots(1, 3)
    report = ex.check("fill", CORRECT["fill"], budget=120)
    report.compare(axes)
    assert axes[2].get_title() == "no pixel differs"
    fig.canvas.draw()


@pytest.mark.parametrize(
    "covers, count, words",
    [(one_winding, 0, "your function left it uncovered"), (both_own, 2, "covered it")],
)
def test_differing_pixels_are_marked_and_explained(plt, covers, count, words):
    fill = _fill_from(covers, 0.5)
    report = ex.check("fill", fill, budget=60)
    wrong = report.differing_pixels()
    assert len(wrong)
    i, j = (int(v) for v in wrong[0])
    text = report.explain_pixel(i, j)
    assert words in text and f"centre ({j + 0.5}, {i + 0.5})" in text
    assert f"yours {count}" in text
    fig, ax = plt.subplots(figsize=(10, 4))
    report.compare(ax, pixel=(i, j))
    assert text.split(":")[0] in texts(fig).replace("\n", " ")
    fig.canvas.draw()


def test_a_click_explains_that_pixel_in_place(plt):
    from matplotlib.backend_bases import MouseEvent

    fig, axes = plt.subplots(1, 3)
    report = ex.check("fill", _fill_from(one_winding, 0.5), budget=60)
    report.compare(axes)
    fig.canvas.draw()
    x, y = axes[1].transData.transform((3.5, 17.5))  # column 3, row 17: outside the fan
    event = MouseEvent("button_press_event", fig.canvas, x, y, button=1)
    fig.canvas.callbacks.process("button_press_event", event)
    assert "pixel (17, 3)" in fig.get_supxlabel()


def test_a_broken_fill_gets_panels_that_say_so_within_its_time(plt):
    start = time.perf_counter()
    report = ex.check("fill", forever, budget=1)
    fig, axes = plt.subplots(1, 3)
    report.compare(axes)
    assert time.perf_counter() - start < 1 + 2
    assert "not run" in axes[0].texts[0].get_text()
    report = ex.check("fill", lambda xy, w, h: None, budget=1)
    fig, axes = plt.subplots(1, 3)
    report.compare(axes)
    assert "returned None" in axes[0].texts[0].get_text()
    fig.canvas.draw()


def test_compare_is_for_pictures_and_checks_its_arguments(plt):
    fig, ax = plt.subplots()
    with pytest.raises(ValueError, match="makes none"):
        ex.check("depth_test", CORRECT["depth_test"]).compare(ax)
    report = ex.check("fill", CORRECT["fill"], budget=120)
    with pytest.raises(TypeError, match="pixel"):
        report.compare(ax, pixel=(1.5, 2))
    with pytest.raises(ValueError, match="three"):
        report.compare([ax, ax])
    with pytest.raises(ValueError, match="must lie in"):
        report.explain_pixel(99, 0)
    with pytest.raises(ValueError, match="makes none"):
        ex.check("depth_test", CORRECT["depth_test"]).explain_pixel(0, 0)


def test_the_differing_pixels_and_their_explanations_without_a_figure(plt):
    report = ex.check("fill", _fill_from(one_winding, 0.5), budget=60)
    wrong = report.differing_pixels()
    assert len(wrong) and np.shape(wrong)[1] == 2
    i, j = (int(v) for v in wrong[0])
    assert "the rule covers it 1 time(s), yours 0" in report.explain_pixel(i, j)
    report.compare(pixel="first")  # a new figure
    assert f"pixel ({i}, {j})" in plt.gcf().get_supxlabel()
