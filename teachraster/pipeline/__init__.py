"""The scene pipeline: from clip-space triangles to a depth-tested, interpolated frame.

One sub-package per stage, in pipeline order, so that the stage a lesson teaches is one
folder (lowest first: a sub-package imports only from those before it, which
``tests/test_layout.py`` checks):

- :mod:`.geometry`: cameras, meshes, OBJ files, homogeneous clipping, the viewport (05a);
- :mod:`.rasterization`: every triangle's span fill at once, per-sample coverage (01-02, 08);
- :mod:`.visibility`: depth formats and precision, the z-buffer, Hi-Z (05a, 05b, 10);
- :mod:`.planning`: the render plan (which effects a scene needs, and why) and checked inputs;
- :mod:`.texturing`: texels, mipmaps, filters, quad derivatives (09);
- :mod:`.antialiasing`: the multisampled render (08);
- :mod:`.rendering`: the stage functions, ``render`` of triangles and of scenes, the built-in
  scenes, the painter's algorithm (05a);
- :mod:`.debugging`: a traced frame's pixel history and debug views, behind
  ``frame.history(row, col)`` and ``frame.overlay(kind)`` (11).

Every module keeps its old flat path as well (``teachraster.pipeline.texture`` is
``teachraster.pipeline.texturing.texture``), so code written before the grouping still imports.
"""

from .geometry.camera import Camera, look_at, orthographic, perspective
from .geometry.clipping import clip_triangles
from .geometry.mesh import Mesh, rotate, scale, translate
from .geometry.obj import ObjError, read_obj
from .geometry.viewport import to_window
from .planning.render_plan import Effect, Plan
from .rasterization.batched_fill import Fragments, rasterize_batch
from .rendering.painters_algorithm import painter
from .rendering.render_scenes import SceneFrame, render, render_scene
from .rendering.render_triangles import Frame, RenderTrace
from .rendering.scenes import SCENES, Scene, get_scene
from .texturing.mip_pyramid import mipmap
from .texturing.texture import TEXTURE_FILTERS, checkerboard, sample, texel_error
from .texturing.texture_filters import mip_level
from .visibility.depth import (
    DEPTH_FORMATS,
    depth_resolution,
    fights,
    linear_depth,
    quantize,
    seed_depth,
    window_depth,
)

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


def _keep_flat_paths() -> None:
    """Register every stage module under its old flat name too (``pipeline.<module>``)."""
    import importlib
    import pkgutil
    import sys

    for group in pkgutil.iter_modules(__path__):
        if not group.ispkg:
            continue
        package = importlib.import_module(f"{__name__}.{group.name}")
        for info in pkgutil.iter_modules(package.__path__):
            module = importlib.import_module(f"{package.__name__}.{info.name}")
            sys.modules.setdefault(f"{__name__}.{info.name}", module)
            if not hasattr(sys.modules[__name__], info.name):
                setattr(sys.modules[__name__], info.name, module)


_keep_flat_paths()
