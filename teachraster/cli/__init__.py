"""``teachraster ...``: export fills, comparisons, scenes and hard cases for slides.

Every export is a still PNG or an animation (GIF through Pillow, MP4 through ffmpeg), chosen
by the suffix of ``-o``. Exports use the projector-ready ``classroom`` style unless
``--style default`` is given. Subcommands::

    teachraster fill --xy "2.2,1.5 13.7,5.2 5.1,12.8" --method halfplane -o fill.gif
    teachraster fill --xy "2.2,1.5 13.7,5.2 5.1,12.8" --step 5 -o step5.png
    teachraster compare --xy "1,1 15,3 4,14" --w "1,4,2" --attr u=0,1,0 -o error.png
    teachraster compare --xy "1,1 15,3 4,14" --attr u=0,1,0 --sweep-w 1:8 -o sweep.gif
    teachraster scene textured_floor --compare -o floor.png
    teachraster case d3d_split_square -o split.png
    teachraster list

The same runs as ``python -m teachraster ...``. Animations are driven by the plotting
layer's in-place updates (:meth:`FillView.show_step`, :meth:`InterpolationView.update`): each
frame changes the data of the artists drawn once, then the writer grabs the canvas.

The core stays numpy-only: matplotlib is imported inside the functions that draw, so
importing this module (or ``teachraster``) does not load it.

>>> build_parser().parse_args(["fill", "--xy", "0,0 4,0 0,4", "-o", "f.png"]).size
(16, 16)
>>> parse_xy("2.2,1.5 13.7,5.2 5.1,12.8").tolist()
[[2.2, 1.5], [13.7, 5.2], [5.1, 12.8]]
"""

from .arguments import (
    ANIMATED,
    ANIMATION_DPI,
    PNG_DPI,
    STILL,
    parse_attr,
    parse_range,
    parse_size,
    parse_w,
    parse_xy,
)
from .export import Progress, ffmpeg_available
from .parser import build_parser
from .run import main

__all__ = [
    "ANIMATED",
    "ANIMATION_DPI",
    "PNG_DPI",
    "STILL",
    "Progress",
    "build_parser",
    "ffmpeg_available",
    "main",
    "parse_attr",
    "parse_range",
    "parse_size",
    "parse_w",
    "parse_xy",
]
