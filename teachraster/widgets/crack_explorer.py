"""``CrackExplorer``: lesson 01's cracks and double draws, on random pairs of triangles.

Ek (*Triangles and Perspective Correct Interpolation*, §1.1) fills span by span between edge
crossings. Computed in floating point as he writes it, divide first, a crossing that should be
exactly a pixel centre can land a hair to either side (multiplied first, on snapped vertices,
it cannot: lesson 01, 4b), and so can a crossing stepped by Δu/Δv: the two triangles sharing
that edge then both draw the pixel, or neither does, or the wrong one does. The explorer fills
a random pair (vertices on pixel centres, sharing an edge) three ways (two panels side by side,
the third below with a key), the float crossing divided first + ceil, the float DDA
(x += Δu/Δv) and the integer edge functions,
marks the tie pixels each gives to the wrong triangle, the cracked and the doubly drawn ones,
rerolls, and keeps a running tally, which starts again whenever the way the edges are
evaluated changes (the toggle, the stored pair, the kernel), or the grid. (Measured: when both triangles evaluate the shared edge
alike, as lesson 01's loops do, rounding never cracks it or draws a pixel twice; it gives the
tie to the wrong triangle. Evaluated from opposite ends, it can crack, rarely: so rarely that
random pairs on a 16 x 16 grid hardly ever show it. A button loads a stored pair that does; a
larger grid (32 x 32 by default), where about two pairs in a thousand do, and "Roll until
one cracks", which rolls until one does, let students find their own: review r229 01-W2.)

Computed in the page (``static/raster_rules.js``, ``static/explore_cracks.js``); the tests
compare it with :mod:`teachraster.study.naive_spans` and :func:`teachraster.rasterize`.
"""

from __future__ import annotations

import operator

from ..core.validate import as_size
from .explorable import Explorable, esm_source

#: The default seed: its first pair shows the float DDA giving ties to the wrong triangle.
DEFAULT_SEED = 112
#: The side of the larger grid a button switches to: random pairs evaluated as listed crack
#: there about twice in a thousand (none in 3000 on 16 x 16; lesson 01 prints its rates).
LARGE_GRID = 32


class CrackExplorer(Explorable):
    """Random pairs of triangles sharing an edge, filled three ways in the page.

    Parameters
    ----------
    width, height : int
        The grid of each panel (at most 40 each: two panels share a notebook column). The
        stored pair that cracks needs 16 x 16 (the default); on a smaller grid it is not offered.
    large : int or None
        A button switches to a ``large`` x ``large`` grid (at most 40), where random pairs
        crack more often; None: no such button.
    seed : int
        Seed of the page's random pairs (the same seed draws the same pairs). The default,
        112, was found by searching seeds for a first pair of two triangles of fair size
        whose shared edge the float DDA gets wrong: it gives three of its ties to the wrong
        triangle (``tests/test_explorables_js.py`` checks it).

    Attributes
    ----------
    state : dict
        ``seed``, ``roll`` (how many rerolls since the first pair), ``asListed`` (edges
        evaluated from the end each triangle lists first), ``stored`` (the stored pair that
        cracks on show instead of the random one), ``large`` (the large grid on show) and
        ``tally`` (per fill: ``pairs``,
        ``faulty`` pairs with a crack or double draw, ``swappedPairs`` with a tie given to the
        wrong triangle, ``triangles``, ``wrongTriangles`` unlike the integer fill, ``cracks``,
        ``doubles`` and ``swapped`` in pixels), as of the page's last change.

    Examples
    --------
    >>> ex = CrackExplorer(seed=3)
    >>> ex.state["roll"], ex.data["width"]
    (0, 16)
    >>> ex.state["asListed"], ex.state["large"], ex.data["large"]
    (False, False, [32, 32])
    """

    _esm = esm_source("raster_rules", "explore_cracks")
    noun = "crack explorer"
    title = "Ties on a shared edge: stolen pixels, cracks and double draws"

    def __init__(self, width: int = 16, height: int = 16, *, seed: int = DEFAULT_SEED,
                 large: int | None = LARGE_GRID) -> None:  # fmt: skip
        width, height = as_size("width", width), as_size("height", height)
        if max(width, height) > 40:
            raise ValueError(f"width and height must be at most 40, got {width}x{height}")
        if large is not None:
            large = as_size("large", large)
            if large > 40:
                raise ValueError(f"large must be at most 40, got {large}")
        seed = operator.index(seed)
        if not 0 <= seed < 2**32:
            raise ValueError(f"seed must be in [0, 2**32), got {seed}")
        super().__init__()
        self.data = {"width": width, "height": height, "seed": seed,
                     "large": None if large is None else [large, large]}  # fmt: skip
        self.state = {"seed": seed, "roll": 0, "asListed": False, "stored": False,
                      "large": False}  # fmt: skip

    @property
    def tally(self) -> dict:
        """The page's running tally (empty until a page has shown the explorer)."""
        return dict(self.state.get("tally", {}))
