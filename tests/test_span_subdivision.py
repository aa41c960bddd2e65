"""Lesson 06's one-span explorer: the closed form of subdivision's miss, checked against the
engine's subdivided interpolation, and the explorer's artists at its sliders' ends."""

from __future__ import annotations

import numpy as np
import pytest

import teachraster as tr
from teachraster.study import span_subdivision as ss


def engine_row(length: int, r: float, texels: float, n: int, mode: str = "subdivided"):
    """A triangle whose row 8 is covered from column 0 to ``length - 1``, 1/w and u/w affine
    in x only (w 1 at the first centre, r at the last; u 0 to ``texels``): the row's u."""
    xy = np.array([[0.0, -200.0], [0.0, 216.0], [length + 0.25, 8.5]])
    inv = 1 + (1 / r - 1) * (xy[:, 0] - 0.5) / (length - 1)
    u = texels / r * (xy[:, 0] - 0.5) / (length - 1) / inv
    fill = tr.rasterize(tr.Triangle(xy, w=1 / inv, attrs={"u": u}), length + 16, 20,
                        interpolation=mode, subdivision=n)  # fmt: skip
    cols = np.flatnonzero(fill.coverage[8])
    assert cols[0] == 0 and cols[-1] == length - 1
    return fill.attrs["u"][8, cols]


@pytest.mark.parametrize("length", [ss.SPAN_PIXELS, 64])
@pytest.mark.parametrize("n, r", [(4, 7.0), (16, 7.0), (16, 60.0), (64, 3.0), (2, 1.5)])
def test_the_span_model_is_the_engines_subdivided_interpolation(n, r, length):
    s = ss.subdivide_span(n, r, length=length, texels=256.0)
    assert np.allclose(engine_row(length, r, 256.0, n), s.pixel_u, atol=1e-9)
    exact = engine_row(length, r, 256.0, n, "perspective")
    assert np.allclose(exact, ss.true_u(np.arange(length), length, r, 256.0), atol=1e-9)
    # every pixel's miss within its piece's closed form, in texels and on screen
    piece = np.searchsorted(s.anchors, np.arange(length), side="right") - 1
    piece = np.minimum(piece, len(s.bound_texels) - 1)
    assert np.array_equal(piece, s.piece)
    assert np.all(np.abs(s.pixel_miss) <= s.bound_texels[piece] + 1e-9)
    assert np.all(np.abs(s.pixel_miss_px) <= s.bound_px[piece] + 1e-9)


def test_the_explorers_span_has_pieces_exactly_n_long():
    """r268 W1: 65 centres, 64 steps: every N of the slider divides the span evenly, and the
    cut when N halves falls steadily as r grows (64 centres left a short last piece)."""
    assert ss.SPAN_PIXELS == 65
    for n in (2, 4, 8, 16, 32, 64):
        assert set(np.diff(ss.anchors(ss.SPAN_PIXELS, n))) == {n}
    cuts = [ss.subdivide_span(16, r).worst_px / ss.subdivide_span(8, r).worst_px
            for r in 10 ** (np.arange(1, 17) / 8)]  # fmt: skip
    assert all(a > b for a, b in zip(cuts, cuts[1:])), cuts


def brute_force(n: int, r: float):
    """The span at pixel centres, from the formulas alone: the chord's u by interpolating the
    anchors' exact u; where the chord's u truly lies, by a fine search of the true u."""
    length, texels = ss.SPAN_PIXELS, float(ss.SPAN_TEXELS)
    x = np.arange(length)
    at = np.unique(np.r_[np.arange(0, length, n), length - 1])
    t = x / (length - 1)
    u = texels * (t / r) / ((1 - t) + t / r)
    chord = np.interp(x, at, u[at])
    fine = np.linspace(0, length - 1, 64 * 2000 + 1)
    tf = fine / (length - 1)
    uf = texels * (tf / r) / ((1 - tf) + tf / r)
    lies = np.interp(chord, uf, fine)  # u grows along the span: invert by interpolation
    return at, chord - u, lies - x


@pytest.mark.parametrize("n", [2, 64, 16])
@pytest.mark.parametrize("r", [1.0, 100.0, 10.0])
def test_the_caption_reports_pixel_centres_from_one_piece(n, r):
    """r268 W2: the caption's texels and px are the misses at the pixel centres of one piece
    (the one whose centre is farthest off on screen), checked by brute force at both ends of
    both sliders; its bound is that piece's closed form."""
    from teachraster.widgets.span_explorer import SpanSubdivisionExplorer

    at, miss, miss_px = brute_force(n, r)
    piece = np.minimum(np.searchsorted(at, np.arange(len(miss)), side="right") - 1, len(at) - 2)
    worst = int(piece[np.argmax(np.abs(miss_px))])
    on = piece == worst
    texels, px = np.abs(miss[on]).max(), np.abs(miss_px).max()
    assert abs(miss_px[on]).max() == px
    ex = SpanSubdivisionExplorer(n, r, backend="image")
    s, caption = ex.result, ex.info.value
    assert s.worst == worst and abs(s.worst_texels - texels) < 1e-9
    assert abs(s.worst_px - px) < 1e-3
    a, b = int(at[worst]), int(at[worst + 1])
    if texels == 0:  # r515 S3: nothing misses, no piece named
        assert "no piece misses" in caption and "worst piece" not in caption
        ex.close()
        return
    assert f"pixels {a}–{b}" in caption and f"of its {b - a} px" in caption
    assert f"<b>{texels:.3g} texels</b>" in caption and f"<b>{px:.3g} px</b>" in caption
    assert f"Δu = {s.anchor_u[worst + 1] - s.anchor_u[worst]:.3g} texels" in caption
    ex.close()


def test_the_closed_form_is_the_largest_gap_of_a_chord():
    """(√ρ − 1)²/(ρ − 1), in texels and in pixels, against a fine search on one piece."""
    tau = np.linspace(0, 1, 200_001)
    for rho in (1.01, 2.0, 3.51, 100.0):
        s = tau / (rho - (rho - 1) * tau)  # the true share of Δu at τ
        back = rho * tau / (1 + (rho - 1) * tau)  # where the chord's value truly lies
        share = float(ss.miss_share(rho))
        assert abs((tau - s).max() - share) < 1e-8
        assert abs((back - tau).max() - share) < 1e-8
        assert abs(share - (np.sqrt(rho) - 1) ** 2 / (rho - 1)) < 1e-12
    # lesson 04's r = 2: 3 − 2√2; near 1 the square law's (ρ − 1)/4
    assert abs(float(ss.miss_share(2.0)) - (3 - 2 * np.sqrt(2))) < 1e-12
    assert abs(float(ss.miss_share(1.001)) / 0.001 - 0.25) < 1e-3


def test_on_screen_the_miss_follows_the_square_law_only_where_w_changes_little():
    cut = {r: ss.subdivide_span(16, r).worst_px / ss.subdivide_span(8, r).worst_px
           for r in (1.2, 100.0)}  # fmt: skip
    assert 3.8 < cut[1.2] <= 4.0 and 2.0 < cut[100.0] < 3.0


def test_the_explorer_moves_its_artists_and_stays_finite_at_every_slider_end():
    from teachraster.widgets.span_explorer import SpanSubdivisionExplorer

    ex = SpanSubdivisionExplorer(16, 4.0, backend="image")
    lo_n, hi_n = 2.0 ** np.array(ex.n.min), 2.0 ** np.array(ex.n.max)
    assert (lo_n, hi_n) == (2.0, 64.0) and (10**ex.r.min, 10**ex.r.max) == (1.0, 100.0)
    for n, r in [(2, 1.0), (2, 100.0), (64, 1.0), (64, 100.0), (8, 10.0)]:
        ex.n.value, ex.r.value = float(n), float(r)
        s = ex.result
        assert (s.n, s.r) == (n, r)
        art = ex.art
        assert np.array_equal(art.anchors.get_xdata(), s.anchors)
        assert np.allclose(art.chords.get_ydata()[:: ss_fine()], s.pixel_u)
        for line in (art.true, art.chords, art.miss, art.pixel_miss, art.anchors):
            assert np.isfinite(np.asarray(line.get_ydata(), float)).all()
        assert np.isfinite(s.worst_texels) and np.isfinite(s.worst_px)
        assert f"{s.worst_texels:.3g} texels" in art.worst_text.get_text()
        assert "nan" not in ex.info.value.lower()
        ex._blit.draw()
    ex.close()


def ss_fine() -> int:
    from teachraster.plotting.span_subdivision import FINE_PER_PIXEL

    return FINE_PER_PIXEL


def test_the_explorer_refuses_what_its_sliders_cannot_show():
    from teachraster.widgets.span_explorer import SpanSubdivisionExplorer

    for n, r in [(3, 4.0), (128, 4.0), (16, 0.5), (16, 1000.0)]:
        with pytest.raises(ValueError):
            SpanSubdivisionExplorer(n, r, backend="image")


def test_at_r_1_the_caption_says_no_miss_and_the_label_clears_the_ticks():
    """Review r283 FIG2: at r = 1 the closed form is 0/0: the caption says its limit, no miss,
    instead of "= 0.000"; the worst miss sits at pixel 0, so its label goes right of it,
    inside the axes, not over the y-axis ticks."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.plotting.span_subdivision import plot_span
    from teachraster.study import span_subdivision as spans
    from teachraster.widgets.span_explorer import SpanSubdivisionExplorer

    ex = SpanSubdivisionExplorer(2, 1.0, backend="image")
    assert "(ρ = 1: u is affine)" in ex.info.value and "= 0.000" not in ex.info.value
    ex.close()
    # r515 S3: with nothing missing there is no worst piece or pixel to name
    ex = SpanSubdivisionExplorer(8, 1.0, backend="image")
    assert "no piece misses (ρ = 1: u is affine)" in ex.info.value
    assert "worst piece" not in ex.info.value and "pixel 0" not in ex.info.value
    ex.close()
    for r, side in ((1.0, "left"), (10.0, "right")):
        fig, (ax_u, ax_miss) = plt.subplots(2, 1)
        art = plot_span(ax_u, ax_miss, spans.subdivide_span(16, r))
        assert art.worst_text.get_horizontalalignment() == side, r
        plt.close(fig)


def test_misses_below_the_floor_are_drawn_in_a_marked_band_not_on_0_01():
    """Review r378 FIG1: at N = 2, r = 10 the misses of pixels 0-17 are under 0.01 texel and
    were drawn on the 0.01 line, reading as 0.01. Now they lie in a grey band under the floor,
    its tick "< 0.01", and the key says so; misses from 0.01 up are drawn at their value."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from teachraster.plotting import span_subdivision as ps

    s = ss.subdivide_span(2, 10.0)
    small = np.abs(s.pixel_miss) < ps.MISS_FLOOR
    assert small[:13].all() and small[13:].sum() < len(small) - 13
    fig, (ax_u, ax_miss) = plt.subplots(2, 1)
    art = ps.plot_span(ax_u, ax_miss, s)
    drawn = np.asarray(art.pixel_miss.get_ydata(), float)
    bottom, top = ax_miss.get_ylim()
    assert bottom < ps.MISS_BELOW < ps.MISS_FLOOR and top == ps.MISS_TOP
    assert np.all(drawn[small] == ps.MISS_BELOW)
    assert np.allclose(drawn[~small], np.abs(s.pixel_miss[~small]))
    labels = {t.get_text(): t.get_position()[1] for t in ax_miss.get_yticklabels()}
    assert labels["< 0.01"] == ps.MISS_BELOW and labels["0.01"] == ps.MISS_FLOOR
    key = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "below 0.01 texel: drawn in the grey band" in key
    bounds = np.asarray(art.bounds.get_ydata(), float)
    assert np.nanmin(bounds) == ps.MISS_BELOW  # the closed form's dashes too
    plt.close(fig)
    # the widget's caption says it
    from teachraster.widgets.span_explorer import SpanSubdivisionExplorer

    ex = SpanSubdivisionExplorer(2, 10.0, backend="image")
    try:
        assert "drawn in the grey band at the bottom, marked < 0.01" in ex.widget.children[0].value
    finally:
        ex.close()
