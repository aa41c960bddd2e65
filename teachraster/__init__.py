"""teachraster: an instrumented triangle rasteriser for teaching how GPUs fill triangles.

The core (this package minus plotting and widgets) depends on numpy only.

>>> import teachraster as tr
>>> fill = tr.rasterize(tr.Triangle([[0, 0], [3, 0], [0, 3]]), 3, 3, method="span")
>>> int(fill.coverage.sum())   # centres with x + y < 3; the hypotenuse is not top-left
3
"""

from .barycentric import barycentric
from .bbox import BBox
from .edges import edge_function, is_top_left
from .half_planes import HalfPlaneTrace
from .interpolation import perspective_weights
from .plane_equation import (
    AttributePlane,
    PlaneEquation,
    attribute_plane,
    plane_equation,
    setup_matrix,
)
from .rasterize import Fill, rasterize
from .snapping import SUBPIXEL_BITS, snap
from .span_tables import SpanTrace, split_point
from .trace import FillTrace, Step
from .triangle import Triangle

__version__ = "0.1.0"

__all__ = [
    "SUBPIXEL_BITS",
    "AttributePlane",
    "BBox",
    "Fill",
    "FillTrace",
    "HalfPlaneTrace",
    "PlaneEquation",
    "SpanTrace",
    "Step",
    "Triangle",
    "attribute_plane",
    "barycentric",
    "edge_function",
    "is_top_left",
    "perspective_weights",
    "plane_equation",
    "rasterize",
    "setup_matrix",
    "snap",
    "split_point",
]
