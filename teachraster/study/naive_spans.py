"""Span tables without an exact tie rule: the two fills lesson 01 writes by hand (numpy only).

Ek (*Triangles and Perspective Correct Interpolation*, §1.1) fills a triangle raster line by
raster line between the crossings of its edges. Written in floating point, the fill is only as
right as those crossings:

- :func:`naive_span_fill` computes each crossing with the u4 formula as Ek writes it, divide
  first, and fills the centres ``ceil(x_left - 0.5) <= j < ceil(x_right - 0.5)`` (the
  top-left rule, if the crossing were exact; multiplied first, ``a_u + (v - a_v)(b_u - a_u) /
  (b_v - a_v)`` on snapped vertices, it is: lesson 01, 4b);
- ``stepped=True`` walks each edge by ``Δu/Δv`` per raster line (a float DDA), so rounding
  accumulates.

A crossing that should be exactly ``j + 0.5`` can come out a hair to either side. When the
two triangles sharing that edge evaluate it alike (as lesson 01's loops do: both from its
upper end), they agree on the hair: the tie pixel is drawn once, but by the wrong one of the
two. When they evaluate it differently, both may draw it or neither. :func:`shared_edge_faults`
counts those against the engine's integer edge functions. The page-side crack explorer (``teachraster.widgets.CrackExplorer``) runs the same fills in
JavaScript; the tests compare the two exactly.
"""

from __future__ import annotations

import numpy as np

from ..core.edges import edge_function
from ..core.fill import rasterize
from ..core.snapping import SUBPIXEL_BITS, to_units, units_per_pixel
from ..core.triangle import Triangle
from ..core.validate import as_finite, as_size


def _crossing(a, b, v):
    """u where the raster line at height v meets the edge a-b (the u4 formula, v_mid -> v),
    divide first: the quotient rounds before the multiply, so a tie can be lost."""
    return (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) + a[0]


def _rows(top, bot, height: int) -> list[int]:
    """The raster lines a span fill visits: v_top <= i + 0.5 < v_bot (top-left rule)."""
    return [i for i in range(height) if top[1] <= i + 0.5 < bot[1]]


def naive_span_fill(xy, width: int, height: int, *, stepped: bool = False,
                    as_listed: bool = False) -> np.ndarray:  # fmt: skip
    """(height, width) bool: lesson 01's float span fill (``stepped``: its float DDA).

    Parameters
    ----------
    xy : (3, 2) array-like
        Vertices in pixels (not snapped).
    width, height : int
    stepped : bool
        Walk each edge by ``Δu/Δv`` per raster line instead of computing each crossing.
    as_listed : bool
        Evaluate each edge from the end the triangle lists first (v1 → v2 → v3 → v1)
        instead of from its upper end: two triangles sharing an edge then evaluate it from
        opposite ends, and round differently.

    Examples
    --------
    >>> int(naive_span_fill([[8.5, 17.5], [4.5, 1.5], [18.5, 9.5]], 20, 20).sum())  # lesson 01
    96
    """
    v = as_finite("xy", xy, (3, 2))
    width, height = as_size("width", width), as_size("height", height)
    t, m, b = np.lexsort((v[:, 0], v[:, 1]))  # by v, then by u
    top, mid, bot = v[t], v[m], v[b]

    def edge(i, j):  # the two ends of an edge, in the order they are evaluated from
        return (v[j], v[i]) if as_listed and (j + 1) % 3 == i else (v[i], v[j])

    cover = np.zeros((height, width), dtype=bool)
    rows = _rows(top, bot, height)
    if not rows:
        return cover
    long_is_left = _crossing(top, bot, mid[1]) < mid[0]
    long = edge(t, b)
    x_long, step_long = _walker(*long, rows[0] + 0.5)
    upper = None
    for i in rows:
        y = i + 0.5
        short = edge(t, m) if y < mid[1] else edge(m, b)
        if stepped:
            if upper is not (y < mid[1]):  # start (or switch to) the short edge of this part
                upper = y < mid[1]
                x_short, step_short = _walker(*short, y)
        else:
            x_long, x_short = _crossing(*long, y), _crossing(*short, y)
        x_left, x_right = (x_long, x_short) if long_is_left else (x_short, x_long)
        first, stop = int(np.ceil(x_left - 0.5)), int(np.ceil(x_right - 0.5))
        cover[i, max(first, 0) : max(min(stop, width), 0)] = True
        if stepped:
            x_long, x_short = x_long + step_long, x_short + step_short
    return cover


def _walker(a, b, v):
    """Where raster line v meets edge a-b, and the step to the next line: Δu/Δv."""
    step = (b[0] - a[0]) / (b[1] - a[1])
    return a[0] + (v - a[1]) * step, step


#: The three fills of the crack explorer, by name.
FILLS = ("crossing", "dda", "integer")


def fill_by(name: str, xy, width: int, height: int, as_listed: bool = False) -> np.ndarray:
    """Coverage of ``xy`` by one of :data:`FILLS` (``integer``: the engine's fill)."""
    if name == "integer":
        return rasterize(Triangle(xy), width, height).coverage
    if name not in FILLS:
        raise ValueError(f"name must be one of {FILLS}, got {name!r}")
    return naive_span_fill(xy, width, height, stepped=name == "dda", as_listed=as_listed)


def shared_edge_faults(first, second, width: int, height: int, name: str,
                       as_listed: bool = False) -> dict:  # fmt: skip
    """Cracks and double draws of two triangles that share their first two vertices' edge.

    ``first`` and ``second`` are (3, 2) vertex lists whose edge from vertex 0 to vertex 1 (in
    either direction) is shared; ``as_listed`` as in :func:`naive_span_fill`. A *double* is a pixel both fill; a *crack* a pixel whose
    centre lies exactly on the shared edge's line, inside the pair (the engine gives it to
    one of them), but that neither fills. ``wrong`` counts the pixels where each differs from the
    engine.

    Returns
    -------
    dict
        ``cracks``, ``doubles`` (int arrays of (row, col)), ``wrong`` (two ints).
    """
    a = fill_by(name, first, width, height, as_listed)
    b = fill_by(name, second, width, height, as_listed)
    exact_a = fill_by("integer", first, width, height)
    exact_b = fill_by("integer", second, width, height)
    # on the edge exactly: integer edge functions on the snapped grid (pixel centres are
    # integers in its units)
    p, q = to_units(np.asarray(first, dtype=np.float64)[:2], SUBPIXEL_BITS)
    unit = units_per_pixel(SUBPIXEL_BITS)
    cols, rows = np.meshgrid(np.arange(width) * unit + unit // 2,
                             np.arange(height) * unit + unit // 2)  # fmt: skip
    on_edge = (q[0] - p[0]) * (rows - p[1]) - (q[1] - p[1]) * (cols - p[0]) == 0
    doubles = a & b
    cracks = on_edge & (exact_a | exact_b) & ~a & ~b
    swapped = on_edge & (a ^ b) & (a != exact_a)  # drawn once, by the other triangle
    wrong = [int((a != exact_a).sum()), int((b != exact_b).sum())]
    return {
        "cracks": np.argwhere(cracks),
        "doubles": np.argwhere(doubles),
        "swapped": np.argwhere(swapped),
        "wrong": wrong,
    }


def random_shared_pairs(rng: np.random.Generator, n: int, width: int, height: int) -> list:
    """``n`` random pairs of triangles sharing an edge, drawn as the crack explorer draws them.

    Four pixel centres p, q, r, s (p != q), redrawn until r and s lie strictly on either side
    of the line p-q; the pair is ``(p, q, r), (q, p, s)`` with r on the side where
    ``edge_function(p, q, r) > 0``, so the second triangle lists the shared edge the other way.

    Parameters
    ----------
    rng : numpy.random.Generator
        The random stream (the page's stream differs: only the distribution is the same).
    n, width, height : int
        How many pairs, and the grid the centres lie on.

    Returns
    -------
    list of tuple of numpy.ndarray
        ``n`` pairs of (3, 2) vertex arrays, for :func:`shared_edge_faults`.
    """
    n, width, height = int(n), as_size("width", width), as_size("height", height)
    if n < 0:
        raise ValueError(f"n must be >= 0, got {n}")
    pairs = []
    while len(pairs) < n:
        p, q, r, s = rng.integers(0, (width, height), (4, 2)) + 0.5
        if (p == q).all():
            continue
        side = np.sign([edge_function(p, q, r), edge_function(p, q, s)])
        if side[0] * side[1] < 0:  # strictly on either side of p-q
            r, s = (r, s) if side[0] > 0 else (s, r)
            pairs.append((np.array([p, q, r]), np.array([q, p, s])))
    return pairs
