"""``DiamondExplorer``: lesson 12a's diamond-exit rule, with the diamonds drawn and ties found.

The GL specification (4.6, §14.5.1) and Direct3D light a pixel when the segment meets the
open diamond around its centre and goes on out of it, and leave out the diamond the segment
ends in. The LinePlayer's captions talk about those diamonds; here they are drawn, every
pixel's, with the ones the walk looked at outlined, the lit ones filled and the end's dashed.
The end points are dragged, and snap onto pixel centres, diamond corners and pixel corners,
where the perturbation by -(ε, ε²) decides the ties (marked "tie"): with y down, as Vulkan's
Bresenham rule; the caption says where GL, which applies it with y up, decides otherwise.

Computed in the page (``static/raster_rules.js``, ``static/explore_lines.js``) with the
engine's exact rule (:mod:`teachraster.core.line_rules`); the tests compare every decision.
"""

from __future__ import annotations

from ..core.snapping import SUBPIXEL_BITS
from ..core.validate import as_finite, as_size
from .explorable import Explorable, esm_source


class DiamondExplorer(Explorable):
    """A one-pixel line over the grid with every diamond, its ends dragged onto ties.

    Parameters
    ----------
    p0, p1 : (2,) array-like
        The end points in pixels.
    width, height : int
        The grid (at most 40 x 30).

    Attributes
    ----------
    state : dict
        ``p0``, ``p1`` and ``step`` (the step on show, -1 for all), as of the page's last
        change.

    Examples
    --------
    >>> ex = DiamondExplorer((0.5, 0.5), (9.5, 4.5), 11, 6)
    >>> ex.state["p1"]
    [9.5, 4.5]
    """

    _esm = esm_source("raster_rules", "explore_lines")
    noun = "diamond explorer"
    title = "Which pixels a line lights: the diamonds"

    def __init__(self, p0=(1.5, 1.5), p1=(10.4, 4.6), width: int = 12, height: int = 7) -> None:
        width, height = as_size("width", width), as_size("height", height)
        if width > 40 or height > 30:
            raise ValueError(f"width and height must be at most 40 and 30, got {width}x{height}")
        p0 = as_finite("p0", p0, (2,)).tolist()
        p1 = as_finite("p1", p1, (2,)).tolist()
        super().__init__()
        self.data = {"width": width, "height": height, "bits": SUBPIXEL_BITS, "p0": p0,
                     "p1": p1}  # fmt: skip
        self.state = {"p0": p0, "p1": p1, "step": -1}
