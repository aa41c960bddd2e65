"""Blending plots (lesson 12b): colour buffers side by side, their difference, every sample's
colour at its position."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.plotting.blending import (  # noqa: E402
    plot_colour_difference,
    plot_composites,
    plot_sample_colours,
)


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def test_composites_show_each_buffer_as_displayed():
    a, b = np.zeros((4, 6, 4)), np.ones((4, 6, 4))
    a[..., 0], a[..., 3] = 0.5, 0.25  # stored alpha 0.25: displayed opaque all the same
    fig, axes = plt.subplots(1, 2)
    drawn = plot_composites(axes, [a, b], ["a", "b"])
    assert [ax.get_title() for ax in axes] == ["a", "b"]
    shown = drawn[0].image.get_array()
    assert shown.shape == (4, 6, 4) and np.allclose(shown[..., 0], 0.5)
    assert np.allclose(shown[..., 3], 1)
    with pytest.raises(ValueError, match="2 Axes for 1 images"):
        plot_composites(axes, [a], ["a", "b"])


def test_composites_draw_a_fragment_with_its_alpha_over_a_checkerboard():
    """Lesson 12b §1: the source swatch (a fragment's colour, which no window displays) is
    drawn with its alpha over the checkerboard; the buffers beside it as displayed."""
    src, dst = np.zeros((8, 8, 4)), np.zeros((8, 8, 4))
    src[..., 0], src[..., 3] = 1.0, 0.5
    dst[..., 2], dst[..., 3] = 1.0, 1.0
    fig, axes = plt.subplots(1, 2)
    drawn = plot_composites(axes, [src, dst], ["src", "dst"], views=["alpha", "displayed"])
    assert drawn[0].checker.get_visible() and not drawn[1].checker.get_visible()
    assert np.allclose(drawn[0].image.get_array()[..., 3], 0.5)
    board = drawn[0].checker.get_array()
    assert len(np.unique(board)) == 2  # both squares of the checkerboard show
    with pytest.raises(ValueError, match="1 views"):
        plot_composites(axes, [src, dst], ["src", "dst"], views=["alpha"])


def test_colour_difference_is_the_largest_channel_difference():
    a, b = np.zeros((3, 5, 3)), np.zeros((3, 5, 3))
    b[1, 2] = [0.1, 0.4, 0.2]
    fig, ax = plt.subplots()
    drawn = plot_colour_difference(ax, a, b)
    assert drawn.maximum == pytest.approx(0.4)
    data = drawn.image.get_array()
    assert data[1, 2] == pytest.approx(0.4) and data.sum() == pytest.approx(0.4)
    assert drawn.colorbar.get_ticks().tolist() == pytest.approx([0, 0.4])
    with pytest.raises(ValueError, match="one shape"):
        plot_colour_difference(ax, a, b[:2])


def test_sample_colours_put_each_sample_where_it_lies_in_its_colour():
    tri = np.array([[[-1, -1, 0, 1], [0.9, -0.7, 0, 1], [-0.6, 0.95, 0, 1]]])
    frame = tr.render(tri, 6, 5, attrs=np.array([[[0.9, 0.4, 0.1, 0.5]] * 3]), blend="over",
                      samples=4, clear_color=(0, 0, 1, 1))  # fmt: skip
    fig, ax = plt.subplots()
    drawn = plot_sample_colours(ax, frame.sample_color, frame.samples, pixel=(2, 3))
    xy = drawn.dots.get_offsets()
    assert len(xy) == 5 * 6 * 4
    # dot (row, col, sample) in row-major order: at (col + ox, row + oy)
    k = (2 * 6 + 3) * 4 + 1
    assert np.allclose(xy[k], [3 + frame.samples[1, 0], 2 + frame.samples[1, 1]])
    colours = drawn.dots.get_facecolors()[:, :3]
    assert np.allclose(colours, frame.sample_color.reshape(-1, 4)[:, :3])
    assert drawn.outline.get_xy() == (3, 2)
    with pytest.raises(ValueError, match="offsets must be"):
        plot_sample_colours(ax, frame.sample_color, frame.samples[:2])
