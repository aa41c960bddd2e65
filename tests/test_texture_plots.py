"""Lesson 09's figures and widget: quads and helpers, the LOD map, the pyramid, filters side
by side, and the FilterExplorer driven from code."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import teachraster as tr  # noqa: E402
from teachraster.pipeline.texture_filters import nearest_level  # noqa: E402
from teachraster.plotting import (  # noqa: E402
    plot_filters,
    plot_lod,
    plot_pixel_grid,
    plot_pyramid,
    plot_quads,
)

CLIP = np.array(
    [
        [[-0.9, -0.8, 0, 1], [0.7, -0.9, 0, 2], [-0.2, 0.8, 0, 1]],
        [[0.7, -0.9, 0, 2], [0.9, 0.7, 0, 1], [-0.2, 0.8, 0, 1]],
    ]
)
UV = np.array([[[0, 0], [1, 0], [0, 1]], [[1, 0], [1, 1], [0, 1]]], float)


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def test_plot_quads_draws_every_pair_and_helper():
    frame = tr.render(CLIP, 12, 10, attrs=UV, derivatives=True, trace=True)
    fig, ax = plt.subplots()
    plot_pixel_grid(ax, 12, 10)
    art = plot_quads(ax, frame)
    q = frame.trace.quads
    assert art.n_helpers == q.helpers == len(art.helpers.get_paths())
    assert len(art.shaded.get_paths()) == frame.coverage.sum()
    assert art.n_quads == len(set(zip(q.row.tolist(), q.col.tolist())))
    assert len(art) == 4
    with pytest.raises(ValueError, match="trace=True"):
        plot_quads(ax, tr.render(CLIP, 12, 10, attrs=UV, derivatives=True))


def test_plot_lod_one_colour_per_level_and_update():
    lam = np.array([[np.nan, -2.0, 0.4, 0.6], [1.4, 1.6, 3.0, 9.0]])
    fig, ax = plt.subplots()
    art = plot_lod(ax, lam, 4)
    shown = np.asarray(art.image.get_array()).reshape(lam.shape)
    want = nearest_level(np.nan_to_num(lam), 3).astype(float)
    np.testing.assert_array_equal(shown[1:], want[1:])
    assert np.ma.is_masked(art.image.get_array()[0]) or np.isnan(shown[0, 0])
    assert art.levels == 4 and len(art.colorbar.get_ticks()) == 4
    art.update(lam + 1)
    np.testing.assert_array_equal(
        np.asarray(art.image.get_array()).reshape(lam.shape)[1], nearest_level(lam[1] + 1, 3)
    )


def test_plot_pyramid_shows_every_level():
    levels = tr.mipmap(tr.checkerboard(4, 32))
    fig, ax = plt.subplots()
    art = plot_pyramid(ax, levels)
    assert len(art.images) == len(levels) == 6
    assert art.labels[0].get_text() == "0: 32×32"
    # review r336 S3: the levels too small for a label (4 and 5 here) drawn again, enlarged,
    # each with its size, in the panel's corner beside them
    texts = [t.get_text() for t in art.labels]
    assert "4–5, drawn 4× larger:" in texts and {"4: 2×2", "5: 1×1"} <= set(texts)
    (x0, x1, y1, y0), (_, a1, _, _) = art.enlarged[0].get_extent(), art.images[4].get_extent()
    assert len(art.enlarged) == 2 and x1 - x0 == y1 - y0 == 4 * 2 and x0 > a1


def test_plot_filters_reports_rms_against_truth():
    rng = np.random.default_rng(1)
    truth = rng.uniform(0, 1, (6, 8, 3))
    imgs = {"a": truth + 0.1, "b": truth.copy()}
    fig, axes = plt.subplots(2, 2)
    art = plot_filters(axes, imgs, truth)
    assert art.rms["a"] == pytest.approx(0.1) and art.rms["b"] == 0
    assert len(art.images) == len(art.errors) == 2 and art.colorbar is not None


def test_filter_explorer_controls_move_the_figures():
    from teachraster.widgets import FilterExplorer

    ex = FilterExplorer(64, 48, tilt=84.0, filter="nearest", samples=8, backend="image")
    draws = ex.display.draws
    errors = {}
    for f in ("nearest", "bilinear", "trilinear", "anisotropic"):
        ex.filter.value = f
        errors[f] = ex.rms
        assert f in ex.info.value
    assert ex.display.draws == draws + 3
    # mipmaps remove the moiré (the truth itself is a 64-point estimate: compare coarsely)
    assert errors["trilinear"] < 0.5 * min(errors["nearest"], errors["bilinear"])
    assert errors["anisotropic"] < 0.5 * min(errors["nearest"], errors["bilinear"])
    lam_far = np.nanmax(ex.lod)
    ex.tilt.value = 10.0  # nearly facing the camera: hardly minified
    assert np.nanmax(ex.lod) < lam_far
    ex.close()


def test_plot_levels_read_colours_the_engines_levels_and_blends():
    """One level's colour where one level is read, the two levels' colours mixed by the
    engine's weight where two are blended, transparent where nothing is read."""
    from matplotlib.colors import to_rgba

    from teachraster.pipeline.texture_filters import LevelsRead
    from teachraster.plotting import plot_levels_read
    from teachraster.plotting.texture_plots import LEVEL_COLORS

    nan = np.nan
    read = LevelsRead(
        first=np.array([[nan, 0.0, 2.0]]),
        second=np.array([[nan, 0.0, 3.0]]),
        weight=np.array([[nan, 0.0, 0.25]]),
        probes=np.ones((1, 3), dtype=int),
        lod=np.array([[nan, 0.0, 2.25]]),
    )
    fig, ax = plt.subplots()
    art = plot_levels_read(ax, read, 5)
    shown = np.asarray(art.image.get_array()).reshape(1, 3, 4)
    assert shown[0, 0, 3] == 0  # nothing read: transparent
    np.testing.assert_allclose(shown[0, 1], to_rgba(LEVEL_COLORS[0]))
    want = 0.75 * np.array(to_rgba(LEVEL_COLORS[2])) + 0.25 * np.array(to_rgba(LEVEL_COLORS[3]))
    np.testing.assert_allclose(shown[0, 2], want)
    assert art.levels == 5 and len(art.colorbar.get_ticks()) == 5
    plt.close(fig)


@pytest.mark.parametrize("filter", list(tr.TEXTURE_FILTERS))
def test_filter_explorer_level_panel_shows_what_each_filter_reads(filter):
    """The "mip level(s) read" panel shows the engine's levels for the filter on show (not
    GL's nearest level of λ for every filter): level 0 without mipmaps, one level per pixel
    for the nearest-mip filters, ⌊λ⌋ blended with ⌊λ⌋ + 1 for the linear-mip ones, and for
    anisotropic its probes' finer levels."""
    from teachraster.pipeline.texture_filters import levels_read
    from teachraster.plotting.texture_plots import levels_read_image
    from teachraster.widgets import FilterExplorer

    ex = FilterExplorer(64, 48, tilt=89.0, filter=filter, samples=2, backend="image")
    try:
        f = ex.frame
        want = levels_read(filter, f.ddx, f.ddy, ex.texture.shape)
        shown = np.asarray(ex.panels["lod"].image.get_array()).reshape(48, 64, 4)
        np.testing.assert_array_equal(shown, levels_read_image(want, ex.n_levels))
        r, ok = ex.levels_read, np.isfinite(ex.levels_read.first)
        nearest = nearest_level(np.nan_to_num(ex.lod), ex.n_levels - 1)[ok]
        if filter in ("nearest", "bilinear"):
            assert (r.first[ok] == 0).all() and (r.weight[ok] == 0).all()
        elif filter.endswith("mipmap_nearest"):
            assert (r.first[ok] == nearest).all() and (r.weight[ok] == 0).all()
        elif filter != "anisotropic":
            assert (r.first[ok] == np.floor(ex.lod[ok])).all() and (r.weight[ok] > 0).mean() > 0.9
            assert (r.first[ok] != nearest).any()  # GL's nearest level is not what is read
        else:
            assert r.probes[ok].max() > 1 and (r.first[ok] < np.floor(ex.lod[ok])).any()
            assert (r.lod[ok] <= ex.lod[ok] + 1e-12).all()
    finally:
        ex.close()


def test_filter_explorer_error_panel_is_as_large_as_the_image_and_its_maximum_off_it():
    """Lesson 09 asks students to read the error panel: it is as large as the level panel
    beside it, under the filtered image (review r42 09-3: the image on top, three figure
    pixels per image pixel), its colour bar's numbers as large as axis labels, and its maximum
    is written below the picture, not over its pixels."""
    import matplotlib as mpl

    from teachraster.widgets import FilterExplorer
    from teachraster.widgets.common import style_context

    ex = FilterExplorer(64, 48, tilt=60.0, filter="nearest_mipmap_nearest", samples=2,
                        backend="image", style="classroom")  # fmt: skip
    try:
        ex.fig.canvas.draw()
        renderer = ex.fig.canvas.get_renderer()
        image, _, lod, error_box = (round(ax.get_window_extent().width) for ax in ex.axes)
        # review r246 09 FIG2: every panel at the image's scale, a pixel at one place in each
        assert lod == error_box == image, (image, lod, error_box)
        error = ex.panels["error"]
        picture = ex.axes[3].get_window_extent()
        note = error.note.get_window_extent(renderer)
        assert error.note.get_visible() and error.note.get_text().startswith("max ")
        assert note.y1 < picture.y0 and note.x1 <= ex.fig.bbox.x1  # below the picture
        # r233 FIG1: the colour bars stand beside their panels, the note under the bar's foot
        assert error.colorbar.ax.get_window_extent().y0 > note.y1
        with style_context("classroom"):  # the size of the style's axis labels
            labels = mpl.rcParams["axes.labelsize"]
            size = mpl.font_manager.FontProperties(size=labels).get_size_in_points()
        assert size > 16
        for bar in (error.colorbar, ex.panels["lod"].colorbar):
            assert all(t.get_fontsize() >= size for t in bar.ax.get_yticklabels())
    finally:
        ex.close()
