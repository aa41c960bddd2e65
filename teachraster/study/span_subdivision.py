"""Subdivision on one span: exact divides every N pixels, affine chords between (lesson 06).

One span of ``length`` pixels, its depth w growing from 1 at its first pixel centre to ``r``
at its last, its texture coordinate u from 0 to ``texels``. Perspective-correct
interpolation (CONVENTIONS, *Interpolation*; the *Triangle Rasterisation* notes) makes
u/w and 1/w affine along the span, so at a fraction t of the way

    1/w(t) = (1 - t) + t/r,        u(t) = texels · (t/r) / ((1 - t) + t/r).

Subdivided interpolation (Quake's) computes u exactly at the *anchors*, every N-th pixel of
the span from its first and at its last (as ``tr.rasterize(..., interpolation="subdivided")``
does), and joins them by straight chords. On one piece whose ends' depths differ by a factor
ρ (the later over the earlier), at a fraction τ of the way along it the true u has gone the
share s(τ) = τ / (ρ - (ρ - 1)τ) of the piece's change Δu and the chord τ of it. Their gap
τ - s(τ) is largest where ρ - (ρ - 1)τ = √ρ, at τ* = √ρ/(√ρ + 1), and is

    (√ρ - 1)² / (ρ - 1) = (√ρ - 1)/(√ρ + 1)    of Δu         (the worst miss in texels).

Read the other way (where on screen does the texel the chord shows belong?), the same share
of the piece's length in pixels: the worst miss *on screen* is (√ρ - 1)²/(ρ - 1) · N pixels.
Near ρ = 1 the share is about (ρ - 1)/4, and ρ - 1 grows like the piece's length: the miss on
screen grows like N², the square law lesson 06 measures on its floor.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: The span the explorer draws: its length in pixels and the texels u crosses along it. 65
#: pixel centres are 64 steps, so that every N of the sliders (2 ... 64) divides the span into
#: pieces of exactly N pixels' steps (64 centres left the last piece one step short).
SPAN_PIXELS, SPAN_TEXELS = 65, 256


def miss_share(rho) -> np.ndarray:
    """(√ρ - 1)²/(ρ - 1): the worst miss of an affine chord, as a share of the piece's change
    of u (and of its length on screen), for a depth ratio ρ ≥ 1 across the piece (1/ρ for ρ < 1:
    the share is the same read from the other end). 0 at ρ = 1, approaching 1 as ρ grows.

    >>> [round(float(v), 4) for v in miss_share([1.0, 2.0, 4.0, 100.0])]
    [0.0, 0.1716, 0.3333, 0.8182]
    """
    rho = np.asarray(rho, dtype=float)
    rho = np.maximum(rho, 1.0 / rho)
    root = np.sqrt(rho)
    return (root - 1.0) / (root + 1.0)  # = (√ρ - 1)²/(ρ - 1), finite at ρ = 1


def anchors(length: int, n: int) -> np.ndarray:
    """The pixels of a ``length``-pixel span where subdivision by ``n`` divides exactly: every
    n-th from the first, and the last (``tr.rasterize``'s subdivided interpolation).

    >>> anchors(10, 4).tolist(), anchors(9, 4).tolist(), anchors(1, 4).tolist()
    ([0, 4, 8, 9], [0, 4, 8], [0])
    """
    if length < 1 or n < 1:
        raise ValueError(f"length and n must be at least 1, got {length}, {n}")
    return np.unique(np.r_[np.arange(0, length, n), length - 1])


def true_u(x, length: int, r: float, texels: float):
    """u (texels) at pixel position ``x`` (0 the first pixel centre, ``length - 1`` the last),
    perspective-correct: u/w and 1/w affine in x."""
    t = np.asarray(x, dtype=float) / max(length - 1, 1)
    return texels * (t / r) / ((1.0 - t) + t / r)


def where_u(u, length: int, r: float, texels: float):
    """The pixel position whose true u is ``u``: :func:`true_u` inverted (a share a = u/texels
    of the way in u lies at t = a / (a + (1 - a)/r) of the span).

    >>> round(float(where_u(true_u(20.0, 65, 7.0, 256.0), 65, 7.0, 256.0)), 9)
    20.0
    """
    a = np.asarray(u, dtype=float) / texels
    return a / (a + (1.0 - a) / r) * max(length - 1, 1)


def depth_w(x, length: int, r: float):
    """w at pixel position ``x``: its reciprocal affine in x, 1 at the first pixel, r at the last."""
    t = np.asarray(x, dtype=float) / max(length - 1, 1)
    return 1.0 / ((1.0 - t) + t / r)


@dataclass(frozen=True)
class SpanSubdivision:
    """One span subdivided: what :func:`subdivide_span` computed (see the module)."""

    length: int
    n: int
    r: float
    texels: float
    anchors: np.ndarray  # pixel positions of the exact divides
    anchor_u: np.ndarray  # u there (texels)
    pixel_u: np.ndarray  # the chords' u at every pixel centre
    pixel_miss: np.ndarray  # chord minus true u at every pixel centre (texels)
    pixel_miss_px: np.ndarray  # where the chord's u truly lies, minus the centre (pixels)
    piece: np.ndarray  # the piece each pixel centre lies on (an anchor: the piece it starts)
    rho: np.ndarray  # each piece's depth ratio, later over earlier
    bound_texels: np.ndarray  # each piece's worst miss between its anchors (texels)
    bound_px: np.ndarray  # and on screen (pixels)
    worst: int  # the piece whose pixel centre shows a texel farthest from where it belongs
    worst_x: int  # the centre on that piece where the miss in texels is largest

    @property
    def worst_texels(self) -> float:
        """The largest miss in texels at a pixel centre of the worst piece."""
        return float(abs(self.pixel_miss[self.worst_x]))

    @property
    def worst_px(self) -> float:
        """The largest miss on screen at a pixel centre (on the worst piece, by its choice)."""
        return float(np.abs(self.pixel_miss_px).max())

    @property
    def worst_px_x(self) -> int:
        """The pixel centre of :attr:`worst_px` (on the worst piece)."""
        return int(np.argmax(np.abs(self.pixel_miss_px)))


def subdivide_span(n: int, r: float, length: int = SPAN_PIXELS,
                   texels: float = SPAN_TEXELS) -> SpanSubdivision:  # fmt: skip
    """The span subdivided by ``n`` at depth ratio ``r`` (the last pixel's w over the
    first's, ≥ 1): the anchors, the chords and their misses at every pixel centre (in texels
    and on screen), and each piece's worst miss by the closed form (between anchors, where no
    pixel centre need lie: the centres' own misses are at most that).

    >>> s = subdivide_span(64, 4.0, length=65, texels=100.0)   # one piece: the whole span
    >>> [round(float(b[0]), 4) for b in (s.bound_texels, s.bound_px)]  # a third of Δu, of 64 px
    [33.3333, 21.3333]
    >>> s.worst_x, round(s.worst_texels, 4), round(s.worst_px, 4)   # τ = 2/3 lies near 43
    (43, 33.3292, 21.3307)
    """
    n, length = int(n), int(length)
    r, texels = float(r), float(texels)
    if not (1.0 <= r < np.inf):
        raise ValueError(f"r must be a finite depth ratio of at least 1, got {r}")
    at = anchors(length, n)
    u_at = true_u(at, length, r, texels)
    x = np.arange(length)
    chords = np.interp(x, at, u_at) if len(at) > 1 else u_at[:1].repeat(length)
    w_at = depth_w(at, length, r)
    rho = w_at[1:] / w_at[:-1] if len(at) > 1 else np.ones(1)
    share = miss_share(rho)
    change = np.diff(u_at) if len(at) > 1 else np.zeros(1)
    pieces = np.diff(at) if len(at) > 1 else np.zeros(1)
    bound_texels, bound_px = share * change, share * pieces
    miss = chords - true_u(x, length, r, texels)
    miss_px = where_u(chords, length, r, texels) - x
    piece = np.minimum(np.searchsorted(at, x, side="right") - 1, len(rho) - 1)
    # the piece and both numbers the explorer's caption gives: from the same centres
    worst = int(piece[np.argmax(np.abs(miss_px))])
    on = np.flatnonzero(piece == worst)
    worst_x = int(on[np.argmax(np.abs(miss[on]))])
    return SpanSubdivision(length, n, r, texels, at, u_at, chords, miss, miss_px, piece, rho,
                           bound_texels, bound_px, worst, worst_x)  # fmt: skip
