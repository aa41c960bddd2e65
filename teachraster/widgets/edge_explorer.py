"""``EdgeFunctionExplorer``: lesson 02's edge functions, live in the page.

Ek (*Triangles and Perspective Correct Interpolation*, §1.2) decides coverage with three edge
functions; Giesen (*Optimizing the basic rasterizer*) applies the top-left rule as an integer
bias per edge. Here a student drags the vertices of two triangles sharing an edge over the
pixel grid and sees, at every centre, the signs of E12, E23 and E31, each edge's half-plane,
each edge's kind (top, left, right, bottom) with its bias, and which triangle owns the centres
exactly on the shared edge; "3-D" shows each E as a tilted plane cutting z = 0 along its edge.

Everything is computed in the page (``static/raster_rules.js`` and ``static/explore_edges.js``)
with the engine's rules: snapping to 1/256 px, exact integer edge functions, the top-left
rule. ``tests/test_explorables_js.py`` compares them with :mod:`teachraster.core.edges` and
:func:`teachraster.rasterize`.
"""

from __future__ import annotations

import numpy as np

from ..core.snapping import SUBPIXEL_BITS
from ..core.validate import as_finite, as_size
from ..plotting.style import COLORS
from .explorable import Explorable, esm_source

#: The default vertices v1, v2, v3 (triangle A) and v4 (B = v3 v2 v4): the shared edge v2-v3
#: runs through pixel centres, so the top-left rule has ties to decide.
DEFAULT_VERTICES = ((2.5, 1.5), (13.5, 5.5), (5.5, 13.5), (14.5, 12.5))

#: Largest grid side: the page's edge functions stay exact doubles (see raster_rules.js).
MAX_SIDE = 128


class EdgeFunctionExplorer(Explorable):
    """Two triangles sharing an edge, dragged over the pixel grid, computed in the page.

    Parameters
    ----------
    vertices : (4, 2) array-like
        v1, v2, v3 (triangle A) and v4 (triangle B = v3, v2, v4), in pixels.
    width, height : int
        The pixel grid (at most 128 each).

    Attributes
    ----------
    vertices : (4, 2) ndarray
        Where the vertices are (as of the last release in the page; set it to move them).
    state : dict
        ``vertices``, ``chosen`` ("A" or "B": whose signs are shown), ``planes`` (the 3-D view
        on), ``snap`` (the drag's grid in px, 0 for none).

    Examples
    --------
    >>> ex = EdgeFunctionExplorer()
    >>> ex.vertices[1].tolist()
    [13.5, 5.5]
    >>> ex.vertices = [[1, 1], [9, 2], [3, 8], [10, 9]]
    >>> ex.state["vertices"][3]
    [10.0, 9.0]
    """

    _esm = esm_source("raster_rules", "view3d", "explore_edges")
    noun = "edge-function explorer"
    title = "Edge functions, live"

    def __init__(self, vertices=DEFAULT_VERTICES, width: int = 16, height: int = 14) -> None:
        width, height = as_size("width", width), as_size("height", height)
        if max(width, height) > MAX_SIDE:
            raise ValueError(f"width and height must be at most {MAX_SIDE}, got {width}x{height}")
        super().__init__()
        self.data = {"width": width, "height": height, "bits": SUBPIXEL_BITS,
                     "colors": dict(COLORS), "vertices": _checked(vertices)}  # fmt: skip
        self.state = {"vertices": _checked(vertices), "chosen": "A", "planes": False,
                      "snap": 0.25}  # fmt: skip

    @property
    def vertices(self) -> np.ndarray:
        """(4, 2) float64: v1, v2, v3, v4 where the page last left them."""
        return np.array(self.state["vertices"], dtype=np.float64)

    @vertices.setter
    def vertices(self, value) -> None:
        self.state = {**self.state, "vertices": _checked(value)}


def _checked(vertices) -> list:
    """Four finite vertices as a JSON-ready list of [x, y] floats."""
    return as_finite("vertices", vertices, (4, 2)).tolist()
