"""teachraster: an instrumented triangle rasteriser for teaching how GPUs fill triangles.

The core (this package minus plotting and widgets) depends on numpy only.

>>> import teachraster as tr
>>> fill = tr.rasterize(tr.Triangle([[0, 0], [3, 0], [0, 3]]), 3, 3, method="span")
>>> int(fill.coverage.sum())   # centres with x + y < 3; the hypotenuse is not top-left
3
"""

from .barycentric import barycentric
from .batch import Fragments, rasterize_batch
from .bbox import BBox
from .camera import Camera, look_at, orthographic, perspective
from .clipping import clip_triangles
from .depth import (
    DEPTH_FORMATS,
    depth_resolution,
    fights,
    linear_depth,
    quantize,
    seed_depth,
    window_depth,
)
from .edges import edge_function, is_top_left
from .half_planes import HalfPlaneTrace
from .interpolation import perspective_weights
from .mesh import Mesh, rotate, scale, translate
from .obj import ObjError, read_obj
from .plan import Effect, Plan
from .plane_equation import (
    AttributePlane,
    PlaneEquation,
    attribute_plane,
    plane_equation,
    setup_matrix,
)
from .rasterize import Fill, rasterize
from .render import Frame, RenderTrace
from .scene_render import SceneFrame, render, render_scene
from .scenes import SCENES, Scene, get_scene
from .snapping import SUBPIXEL_BITS, snap
from .span_tables import SpanTrace, split_point
from .texture import checkerboard, sample, texel_error
from .trace import FillTrace, Step
from .triangle import Triangle
from .viewport import to_window

__version__ = "0.1.0"

__all__ = [
    "DEPTH_FORMATS",
    "SCENES",
    "SUBPIXEL_BITS",
    "AttributePlane",
    "BBox",
    "Camera",
    "Effect",
    "Fill",
    "FillTrace",
    "Fragments",
    "Frame",
    "HalfPlaneTrace",
    "Mesh",
    "ObjError",
    "Plan",
    "PlaneEquation",
    "RenderTrace",
    "Scene",
    "SceneFrame",
    "SpanTrace",
    "Step",
    "Triangle",
    "attribute_plane",
    "barycentric",
    "checkerboard",
    "clip_triangles",
    "depth_resolution",
    "edge_function",
    "fights",
    "get_scene",
    "is_top_left",
    "linear_depth",
    "look_at",
    "orthographic",
    "perspective",
    "perspective_weights",
    "plane_equation",
    "quantize",
    "rasterize",
    "rasterize_batch",
    "read_obj",
    "render",
    "render_scene",
    "rotate",
    "sample",
    "scale",
    "seed_depth",
    "setup_matrix",
    "snap",
    "split_point",
    "texel_error",
    "to_window",
    "translate",
    "window_depth",
]
