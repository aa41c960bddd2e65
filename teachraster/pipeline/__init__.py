"""The scene pipeline: from clip-space triangles to a depth-tested, interpolated frame.

Lesson 05 in code, one module per stage or ingredient:

- :mod:`.camera`, :mod:`.mesh`, :mod:`.obj`, :mod:`.scenes`, :mod:`.texture`: what is drawn;
- :mod:`.texel_fetch`, :mod:`.mip_pyramid`, :mod:`.texture_filters`: texels, mipmaps, filters;
- :mod:`.clipping`: homogeneous near/far clipping (Sutherland-Hodgman, before the divide);
- :mod:`.viewport`: clip space to window coordinates;
- :mod:`.batched_fill`: every triangle's span fill at once (identical to ``rasterize``);
- :mod:`.depth`: depth mappings and storage precision (Ritschel, *Interpolation and
  z-buffering*);
- :mod:`.zbuffer`: the depth test resolved for all fragments at once;
- :mod:`.render_plan`: which effects a scene needs, and the words that say why;
- :mod:`.stages`: the stage functions (clip, viewport, cull, fill, depth, interpolate), each
  returning its data and its plan effect;
- :mod:`.render_triangles`: ``render`` of clip-space triangles, the stages in a row;
- :mod:`.render_scenes`: ``render`` of a :class:`Scene` through a camera, shaded;
- :mod:`.painters_algorithm`: the painter's algorithm, for comparison with the z-buffer.
"""

from .batched_fill import Fragments, rasterize_batch
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
from .mesh import Mesh, rotate, scale, translate
from .mip_pyramid import mipmap
from .obj import ObjError, read_obj
from .painters_algorithm import painter
from .render_plan import Effect, Plan
from .render_scenes import SceneFrame, render, render_scene
from .render_triangles import Frame, RenderTrace
from .scenes import SCENES, Scene, get_scene
from .texture import TEXTURE_FILTERS, checkerboard, sample, texel_error
from .texture_filters import mip_level
from .viewport import to_window

__all__ = [
    "DEPTH_FORMATS",
    "SCENES",
    "TEXTURE_FILTERS",
    "Camera",
    "Effect",
    "Fragments",
    "Frame",
    "Mesh",
    "ObjError",
    "Plan",
    "RenderTrace",
    "Scene",
    "SceneFrame",
    "checkerboard",
    "clip_triangles",
    "depth_resolution",
    "fights",
    "get_scene",
    "linear_depth",
    "look_at",
    "mip_level",
    "mipmap",
    "orthographic",
    "painter",
    "perspective",
    "quantize",
    "rasterize_batch",
    "read_obj",
    "render",
    "render_scene",
    "rotate",
    "sample",
    "scale",
    "seed_depth",
    "texel_error",
    "to_window",
    "translate",
    "window_depth",
]
