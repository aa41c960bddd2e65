"""``report.compare``: the student's fill of a small scene beside the package's, and the
pixels where they differ, each explained on demand."""

from __future__ import annotations

import time

import numpy as np
import pytest
from exercise_solutions import CORRECT, _fill_from, both_own, one_winding

from teachraster import exercises as ex
from teachraster.exercises.compare import COMPARE_BUDGET, compare_fill, pixel_explanation


@pytest.fixture
def plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    yield plt
    plt.close("all")


def texts(artists) -> str:
    return "\n".join(a.get_text() for a in artists if hasattr(a, "get_text"))


def test_a_correct_fill_matches_on_every_pixel(plt):
    c = compare_fill(CORRECT["fill"], 120)  # exact Fractions: slow on a loaded machine
    want, got = c.counts
    assert c.error is None and np.array_equal(want, got) and len(c.differing()) == 0
    assert want.max() == 1 and want.sum() > 50  # watertight: every centre once
    fig, axes = plt.subplots(1, 3)
    artists = ex.check("fill", CORRECT["fill"], budget=120).compare(axes)
    assert axes[2].get_title() == "differences: 0 pixel(s)"
    assert "matches the package's on every pixel" in texts(artists)
    fig.canvas.draw()


@pytest.mark.parametrize(
    "covers, sign, words",
    [(one_winding, -1, "handle both windings"), (both_own, +1, "covered twice")],
)
def test_differing_pixels_are_marked_and_explained(plt, covers, sign, words):
    fill = _fill_from(covers, 0.5)
    c = compare_fill(fill, 120)
    want, got = c.counts
    diff = got - want
    assert (diff != 0).any() and (np.sign(diff[diff != 0]) == sign).all()
    i, j = c.differing()[0]
    text = pixel_explanation(c, int(i), int(j))
    assert words in text and f"centre ({j + 0.5}, {i + 0.5})" in text
    fig, ax = plt.subplots(figsize=(10, 4))
    report = ex.check("fill", fill, budget=60)
    artists = report.compare(ax, pixel=(int(i), int(j)))
    assert text.split(":")[0] in texts(artists)
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
    assert "pixel (row 17, column 3)" in texts(axes[0].texts)


def test_a_broken_fill_gets_panels_that_say_so_within_the_budget(plt):
    def loops(xy, width, height):
        while True:
            try:
                while True:
                    pass
            except BaseException:
                pass

    start = time.perf_counter()
    c = compare_fill(loops)
    assert time.perf_counter() - start < COMPARE_BUDGET + 2
    assert c.got is None and "did not return within 1 s on case triangle 0" in c.error
    fig, ax = plt.subplots()
    artists = ex.check("fill", lambda xy, w, h: None, budget=1).compare(ax)
    assert "returned None" in texts(artists)
    fig.canvas.draw()


def test_compare_is_for_pictures_and_checks_its_arguments(plt):
    fig, ax = plt.subplots()
    with pytest.raises(ValueError, match="fill does"):
        ex.check("depth_test", CORRECT["depth_test"]).compare(ax)
    report = ex.check("fill", CORRECT["fill"], budget=120)
    with pytest.raises(TypeError, match="pixel"):
        report.compare(ax, pixel=(1.5, 2))
    with pytest.raises(ValueError, match="three"):
        report.compare([ax, ax])
    assert "outside" in pixel_explanation(compare_fill(CORRECT["fill"], 120), 99, 0)
    with pytest.raises(ValueError, match="fill does"):
        ex.check("depth_test", CORRECT["depth_test"]).explain_pixel(0, 0)


def test_the_differing_pixels_and_their_explanations_without_a_figure(plt):
    report = ex.check("fill", _fill_from(one_winding, 0.5), budget=60)
    wrong = report.differing_pixels()
    assert len(wrong)
    i, j = (int(v) for v in wrong[0])
    assert "handle both windings" in report.explain_pixel(i, j)
    artists = report.compare(pixel="first")  # a new figure
    assert f"pixel (row {i}, column {j})" in texts(artists)
