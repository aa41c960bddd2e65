"""Shared runners and checks of the hard cases: what a correct rasteriser must do, as code."""

from __future__ import annotations

import numpy as np

from ...core.fill import rasterize
from ...core.triangle import Triangle
from .case import Fills, Naive
from .naive import naive_counts


# -- shared runners and checks ---------------------------------------------------------------
def fill_all(inputs, method: str, **kwargs) -> Fills:
    width, height = inputs["size"]
    attrs = inputs.get("attrs")
    fills = []
    counts = np.zeros((height, width), dtype=np.int64)
    for k, xy in enumerate(inputs["triangles"]):
        tri = Triangle(
            xy,
            w=None if "w" not in inputs else inputs["w"][k],
            attrs={} if attrs is None else {"f": attrs[k]},
        )
        fill = rasterize(tri, width, height, method=method, trace=True, **kwargs)
        fills.append(fill)
        counts += fill.coverage
    return Fills(tuple(fills), counts)


def first_pixels(mask: np.ndarray, limit: int = 8) -> list:
    return np.argwhere(mask)[:limit].tolist()


def check_finite(result: Fills) -> None:
    """Attributes and barycentrics finite and sane inside coverage, NaN outside."""
    for k, fill in enumerate(result.fills):
        for name, values in fill.attrs.items():
            inside = values[fill.coverage]
            assert np.isfinite(inside).all(), f"triangle {k}: {name} not finite inside coverage"
            assert np.isnan(values[~fill.coverage]).all(), f"triangle {k}: {name} set outside"
        lam = fill.trace.pixel_barycentric
        assert np.isfinite(lam).all(), f"triangle {k}: barycentrics not finite"
        assert ((lam >= 0) & (lam <= 1)).all(), f"triangle {k}: barycentrics outside [0, 1]"
        assert np.allclose(lam.sum(axis=1), 1.0, rtol=0, atol=1e-12), f"triangle {k}: Σλ != 1"


def check_mask(inputs, result: Fills) -> None:
    """Counts equal the hand-derived ``expected`` mask of the case (0/1 per pixel)."""
    check_finite(result)
    want = inputs["expected"].astype(np.int64)
    got = result.counts
    bad = got != want
    assert not bad.any(), (
        f"coverage differs from the expected pixels at (row, col) {first_pixels(bad)}: "
        f"got counts {got[bad][:8].tolist()}, want {want[bad][:8].tolist()}"
    )


def check_nothing(inputs, result: Fills) -> None:
    for k, fill in enumerate(result.fills):
        assert not fill.coverage.any(), (
            f"triangle {k} has zero area after snapping but covers {first_pixels(fill.coverage)}"
        )
        for name, values in fill.attrs.items():
            assert np.isnan(values).all(), f"triangle {k}: {name} not NaN everywhere"


def check_watertight(inputs, result: Fills) -> None:
    """No pixel twice; every centre strictly inside the mesh's outline exactly once."""
    check_finite(result)
    twice = result.counts > 1
    assert not twice.any(), f"pixel centres covered twice: {first_pixels(twice)}"
    holes = inputs["interior"] & (result.counts != 1)
    assert not holes.any(), f"interior pixel centres not covered (cracks): {first_pixels(holes)}"


def naive_double_hits(inputs, ours: Fills, naive: Naive) -> str | None:
    """Centres drawn twice, and (E >= 0 draws right and bottom edges too) centres ours leaves to
    a neighbour: both kinds, and how many pixels differ in all (a pixel can be of both kinds).

    Naming the double hits only undersold the split square: 6 twice, but 16 pixels differ
    (review r6, 07-1).
    """
    twice = naive.counts > 1
    if not twice.any() or ours.counts.max() > 1:
        return None
    extra = (naive.counts > 0) & (ours.counts == 0)
    # "more than once": a fan's hub is drawn 16 times (review r145 07-2)
    line = f"naive covers {int(twice.sum())} pixel centre(s) more than once"
    if extra.any():
        line += f" and {int(extra.sum())} that ours leaves to a neighbour"
        both = int((twice & extra).sum())
        if both:  # so that the counts add up to the pixels that differ (review r145 07-18)
            line += f" ({both} of them in both)"
    return line + f": it differs from ours at {int((naive.counts != ours.counts).sum())} pixel(s)"


def naive_differs(inputs, ours: Fills, naive: Naive) -> str | None:
    diff = naive.counts != ours.counts
    if not diff.any():
        return None
    # pixels as the lessons write them, (1, 1), (1, 2) and (1, 3), not a Python list (r304 S-2)
    named = [f"({r}, {c})" for r, c in first_pixels(diff, 3)]
    shown = ", ".join(named[:-1]) + f" and {named[-1]}" if len(named) > 1 else named[0]
    return f"naive coverage differs at {int(diff.sum())} pixel(s), e.g. {shown} (row, column)"


def naive_mesh(rule: str, **kwargs):
    def run(inputs) -> Naive:
        width, height = inputs["size"]
        return Naive(counts=naive_counts(inputs["triangles"], width, height, rule=rule, **kwargs))

    return run


def triangles_array(*tris) -> np.ndarray:
    return np.array(tris, dtype=np.float64)


def pixel_mask(height, width, fn) -> np.ndarray:
    i, j = np.indices((height, width))
    return fn(i, j)


def strictly_inside(polygon, width: int, height: int) -> np.ndarray:
    """Pixel centres strictly inside a convex polygon given in order (exact: dyadic inputs)."""
    p = np.asarray(polygon, dtype=np.float64)
    ys, xs = np.mgrid[0:height, 0:width] + 0.5
    sides = []
    for k in range(len(p)):
        a, b = p[k], p[(k + 1) % len(p)]
        sides.append((b[0] - a[0]) * (ys - a[1]) - (b[1] - a[1]) * (xs - a[0]))
    sides = np.array(sides)
    return (sides > 0).all(axis=0) | (sides < 0).all(axis=0)
