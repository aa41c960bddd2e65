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


@pytest.mark.parametrize("n, r", [(4, 7.0), (16, 7.0), (16, 60.0), (64, 3.0), (2, 1.5)])
def test_the_span_model_is_the_engines_subdivided_interpolation(n, r):
    s = ss.subdivide_span(n, r, length=64, texels=256.0)
    assert np.allclose(engine_row(64, r, 256.0, n), s.pixel_u, atol=1e-9)
    exact = engine_row(64, r, 256.0, n, "perspective")
    assert np.allclose(exact, ss.true_u(np.arange(64), 64, r, 256.0), atol=1e-9)
    # every pixel's miss within its piece's closed form, the worst close to it
    piece = np.searchsorted(s.anchors, np.arange(64), side="right") - 1
    piece = np.minimum(piece, len(s.bound_texels) - 1)
    assert np.all(np.abs(s.pixel_miss) <= s.bound_texels[piece] + 1e-9)
    assert np.abs(s.pixel_miss).max() >= 0.9 * s.worst_texels


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
    assert 3.7 < cut[1.2] <= 4.0 and 2.0 < cut[100.0] < 3.0


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
