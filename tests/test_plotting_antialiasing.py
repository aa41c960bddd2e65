"""Antialiasing plots: artists on the axes, data equal to the fill's samples, in-place updates."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster import plotting as tp  # noqa: E402
from teachraster.study.antialiasing import pixel_area  # noqa: E402

XY = np.array([[0.6, 0.4], [9.3, 2.1], [2.2, 7.7]])


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def on_axes(result, ax):
    artists = list(result)
    assert artists and all(a.axes is ax for a in artists)
    return artists


def test_plot_samples_shows_every_sample_where_it_is():
    fill = tr.rasterize(tr.Triangle(XY), 10, 8, samples=4)
    fig, ax = plt.subplots()
    tp.plot_pixel_grid(ax, 10, 8)
    result = tp.plot_samples(ax, fill)
    on_axes(result, ax)
    covered = result.covered.get_offsets()
    assert len(covered) == fill.sample_coverage.sum()
    i, j, s = np.nonzero(fill.sample_coverage)
    want = np.column_stack([j + fill.samples[s, 0], i + fill.samples[s, 1]])
    np.testing.assert_array_equal(np.asarray(covered), want)
    x, _ = result.uncovered.get_data()
    assert len(x) == (~fill.sample_coverage).sum()
    # in place: another pattern and a frame with several triangles
    clip = np.array([[[-1, 1, 0, 1], [1, 1, 0, 1], [-1, -1, 0, 1]],
                     [[1, 1, 0.5, 1], [1, -1, 0.5, 1], [-1, -1, 0.5, 1]]], float)  # fmt: skip
    frame = tr.render(clip, 10, 8, samples=16)
    result.update(frame)
    assert len(result.covered.get_offsets()) == 10 * 8 * 16  # watertight: every sample
    assert len({tuple(c) for c in result.covered.get_facecolor()}) == 2  # two triangles
    with pytest.raises(ValueError, match="samples"):
        tp.plot_samples(ax, tr.rasterize(tr.Triangle(XY), 10, 8))


def test_fraction_and_error_images():
    fill = tr.rasterize(tr.Triangle(XY), 10, 8, samples=8)
    fig, (a, b) = plt.subplots(1, 2)
    frac = tp.plot_coverage_fraction(a, fill)
    on_axes(frac, a)
    area = pixel_area(XY, 10, 8)
    err = tp.plot_area_error(b, fill, area)
    on_axes(err, b)
    shown = np.asarray(err.image.get_array()).reshape(8, 10)
    want = fill.coverage_fraction - area
    keep = (fill.coverage_fraction > 0) | (area > 0)
    np.testing.assert_allclose(shown[keep], want[keep])
    assert f"max {np.abs(want[keep]).max():.3f}" in b.get_title()
    # maps to be compared share a colour range: the bound given, not their own maximum
    shared = tp.plot_area_error(a, fill, area, bound=0.9, colorbar=False)
    assert shared.image.get_clim() == (-0.9, 0.9)
    worst = np.abs(want[keep]).max()
    assert err.image.get_clim() == pytest.approx((-worst, worst))  # by default its own
    with pytest.raises(ValueError, match="bound"):
        tp.plot_area_error(a, fill, area, bound=0.0)


def test_pixel_inspector_plot_labels_samples_with_edge_values():
    fill = tr.rasterize(tr.Triangle(XY), 10, 8, samples=4, trace=True)
    fig, ax = plt.subplots()
    result = tp.plot_pixel_samples(ax, fill, 2, 6)
    on_axes(result, ax)
    assert len(result.dots) == 4 and len(result.labels) == 4
    e = fill.trace.samples.edge_values(2, 6)
    a, b = fill.trace.edges[0]
    assert f"E{a + 1}{b + 1}" in ax.get_title().split("\n")[-1]  # the names, in order
    assert result.labels[0].get_text().split("\n")[1].split()[0] == f"{e[0, 0]:+.3g}"
    assert "4 of 4" in ax.get_title()


def test_sampling_key_does_not_name_the_signal_twice_without_a_prefilter():
    """Review 08-09-r5 (08 item 8): at width 0 the key listed "signal" and "prefiltered"
    for one curve; it says what the line is at width 0. Review r101 08-D: a key that changed
    its text with the filter left a stale sliver in the page: one text at every width."""
    from teachraster.plotting.sampling import (
        plot_sampling,
        prefiltered_key,
        sample_signal,
        update_sampling,
    )

    fig, axes = plt.subplots(3, 1)
    art = plot_sampling(axes, sample_signal(32, 0.0))
    texts = lambda: [t.get_text() for t in axes[0].get_legend().get_texts()]  # noqa: E731
    assert texts()[1] == "prefiltered, width 0.00\n(none: the signal)"
    # review r119 08-C: at width 4 the key no longer says "the signal"; the first, longest
    # line keeps its length, so the key's box keeps its size (r101 08-D's stale sliver)
    update_sampling(art, sample_signal(32, 4.0))
    assert texts()[1] == "prefiltered, width 4.00\n(box: a local average)"
    assert "the signal" not in texts()[1]
    # review r129 08-7: the key names the shape, and the Gaussian's sigma (width = 2 sigma)
    update_sampling(art, sample_signal(32, 4.0, "gaussian"))
    assert texts()[1] == "prefiltered, width 4.00\n(Gaussian, σ = 2.00)"
    renderer = fig.canvas.get_renderer()
    for width, kernel in ((0.0, "box"), (4.0, "box"), (4.0, "gaussian")):
        first, second = (
            axes[0].text(0, 0, line, fontsize=12).get_window_extent(renderer).width
            for line in prefiltered_key(width, kernel).split("\n")
        )
        assert second <= first, (width, kernel)  # the first line stays the longest
    update_sampling(art, sample_signal(32, 0.5))
    assert texts()[1].split("\n")[0] == "prefiltered, width 0.50"
    plt.close(fig)
