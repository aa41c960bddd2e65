"""The core: filling one screen-space triangle, step by step (numpy only).

One module per idea of the first four lessons, in the order the notes teach them:

- :mod:`.triangle`, :mod:`.snapping`, :mod:`.validate`: the input, on the sub-pixel grid;
- :mod:`.edges`, :mod:`.bbox`: edge functions, winding, the top-left rule, the bounding box
  (Ek, *Rasterization*, §1);
- :mod:`.span_tables`: sort by y, split at u4, fill raster lines (Jack, *Triangle
  rasterisation with span tables*);
- :mod:`.half_planes`: test every centre of the bounding box (Ek, *Rasterization*, §1.2);
- :mod:`.barycentrics`, :mod:`.plane_equations`, :mod:`.interpolation`: weights, planes and the
  setup matrix, affine vs perspective-correct values;
- :mod:`.sample_patterns`, :mod:`.multisample`: sample positions inside the pixel, coverage
  per sample and where a multisampled pixel's attributes are evaluated (antialiasing);
- :mod:`.lines`, :mod:`.line_rules`, :mod:`.line_trace`: line segments (the diamond-exit
  rule, Bresenham, DDA, wide lines as two triangles) and their steps;
- :mod:`.blend_factors`: GL's blend factors and equations, the sRGB curve;
- :mod:`.trace`: the recorded steps and their captions; :mod:`.fill`: ``rasterize`` itself.
"""

from .barycentrics import barycentric
from .bbox import BBox
from .blend_factors import blend_equation, linear_to_srgb, srgb_to_linear
from .edges import edge_function, is_top_left
from .fill import Fill, rasterize
from .half_planes import HalfPlaneTrace
from .interpolation import perspective_weights
from .line_trace import LineTrace
from .lines import rasterize_line
from .multisample import SampleTrace
from .plane_equations import (
    AttributePlane,
    PlaneEquation,
    attribute_plane,
    plane_equation,
    setup_matrix,
)
from .sample_patterns import sample_pattern
from .snapping import SUBPIXEL_BITS, snap
from .span_tables import SpanTrace, split_point
from .trace import FillTrace, Step
from .triangle import Triangle

__all__ = [
    "SUBPIXEL_BITS",
    "AttributePlane",
    "BBox",
    "Fill",
    "FillTrace",
    "HalfPlaneTrace",
    "LineTrace",
    "PlaneEquation",
    "SampleTrace",
    "SpanTrace",
    "Step",
    "Triangle",
    "attribute_plane",
    "barycentric",
    "blend_equation",
    "edge_function",
    "is_top_left",
    "linear_to_srgb",
    "perspective_weights",
    "plane_equation",
    "rasterize",
    "rasterize_line",
    "sample_pattern",
    "setup_matrix",
    "snap",
    "split_point",
    "srgb_to_linear",
]
