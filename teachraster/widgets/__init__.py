"""Jupyter widgets (ipywidgets 8) for stepping through fills and comparing interpolations.

``import teachraster.widgets`` imports matplotlib and ipywidgets (the ``lab`` extra); the core
never does. Every widget builds on the in-place views of :mod:`teachraster.plotting`, shows
itself when it is the last expression of a cell (or ``display(w.widget)``), and can be driven
from code by setting ``.value`` on its controls, so its logic is tested without a browser.

Widgets
-------
- :class:`FillPlayer` -- Play/Pause, step slider, first/previous/next/last and the caption of
  the current step, all in the page (:class:`FramesWidget`: the steps are drawn once and
  sent as frames); method toggle (span tables / half-planes / tiles), interpolation toggle
  (affine / perspective-correct, when the triangle has attributes) and samples in the kernel;
  a FillView (and an InterpolationView when the triangle has attributes).
- :class:`TriangleEditor` -- drag a vertex in the figure (in the page: :class:`DragFigure`;
  or under ipympl), move it and change its w with sliders; the fill, the split at u4 and the
  affine-vs-perspective error heatmap follow.
- :class:`TileExplorer` -- the block hierarchy of a tiled fill, level by level or block by
  block in a traversal order, with block sizes and traversal as menus and the counters.
- :class:`HiZTileExplorer` -- one scene's Hi-Z replay, drawing order × tile size as menus:
  the stored depths, the fragments rejected, killed and shaded, the rejections drawn.
- :class:`TexturedPlaneViewer` -- a checkerboard square tilted away from the camera, affine vs
  perspective-correct texture coordinates side by side, with the error in texels; a tilt
  slider.
- :class:`PixelInspector` -- choose a pixel and a sample pattern: every sample of the image,
  and the pixel magnified with the triangle owning each sample and its edge values.
- :class:`FilterExplorer` -- a checkerboard square tilting to the horizon with a filter
  chooser: the filtered image, the mip level per pixel and the error against the true
  footprint average (lesson 09).
- :class:`LiveSlider` -- a slider in the page whose values reach the kernel coalesced (the
  explorers' tilt, near-plane and vertex sliders): the kernel renders the latest value,
  never a queue; where the page has the picture of a position drawn ahead
  (:mod:`teachraster.widgets.ahead`: every position, drawn while the kernel idles), it shows
  it by itself and the kernel hears of the release only.
- :class:`Predict` -- "predict, then see": a question that takes the student's answer (a
  choice or a number) before it reveals the answer, the explanation and its figure; headless
  runs show the answer at once.
- :class:`ProjectionExplorer` (lesson 04: eye, screen and segment, a slider along the screen)
  and :class:`ZBufferStepper` (lesson 05a: the z-buffer triangle by triangle).
- :class:`FrameInspector` -- a built-in scene with a view chooser (the image or an overlay:
  overdraw, depth complexity, quad overshading, ...); click a pixel for its history (lesson 11).
- :class:`PlaneExplorer` (lesson 03), :class:`DepthPrecisionExplorer` (lesson 05b: bits, near
  plane, reverse-Z) and :class:`CasePicker` (lesson 07: any hard case, ours beside naive).
- :class:`LinePlayer` and :class:`BlendingExplorer` (lessons 12a, 12b): a line step by step under the
  diamond rule, Bresenham or DDA; transparent triangles reordered, their blend state and
  alpha chosen, sRGB.

Offline pages
-------------
``teachraster html`` shows every widget class of this package through
:func:`teachraster.widgets.offline.offline_page`: a slider over the pictures a slider
explorer draws ahead, or over the positions of the control a class names in
``_offline_sweep_`` (players step, explorers slide), else a snapshot of its widget tree with
its picture; a class that knows better implements ``_offline_page_()``.

Explorables computed in the page
--------------------------------
These carry their rules to the page (:mod:`teachraster.widgets.explorable`: plain JavaScript,
each rule cross-checked against the engine by the tests), so they drag at the screen's frame
rate with no kernel in the loop and stay live in ``teachraster html`` pages:
:class:`PipelineMap` (00), :class:`CrackExplorer` (01), :class:`EdgeFunctionExplorer` (02),
:class:`AttributeSurfaces` and :class:`EyeRayExplorer` (03/04), :class:`DepthValuesExplorer`
(05b), :class:`FootprintExplorer` (09), :class:`DiamondExplorer` (12); and the predictions
answered on a figure, :class:`PredictPixels`, :class:`PredictPoint`, :class:`PredictOrder`,
and :class:`PredictChoice`, a multiple choice whose Check the page enables at the pick
(:mod:`teachraster.widgets.predict_figure`).

Figures
-------
``backend="auto"`` (the default) puts an interactive ipympl canvas in the widget under
``%matplotlib widget``, and otherwise a PNG image (``ipywidgets.Image``) redrawn at each
update, which works with the inline backend, in a browser and headless (nbclient). Force one
with ``backend="ipympl"`` or ``backend="image"``.

Example
-------
>>> import teachraster as tr
>>> from teachraster.widgets import FillPlayer
>>> player = FillPlayer(tr.Triangle([[1, 1], [14, 4], [5, 14]]), 16, 16, backend="image")
>>> player.next.click()
>>> player.slider.value
1
>>> player.close()
"""

from .attribute_surfaces import AttributeSurfaces, EyeRayExplorer
from .blending import BlendingExplorer
from .case_picker import CasePicker
from .crack_explorer import CrackExplorer
from .depth_explorer import DepthPrecisionExplorer
from .depth_values import DepthValuesExplorer
from .display import BACKENDS, FigureDisplay, resolve_backend
from .dragging import DragFigure
from .edge_explorer import EdgeFunctionExplorer
from .editor import TriangleEditor
from .filter_explorer import FilterExplorer
from .footprint_explorer import FootprintExplorer
from .frame_inspector import FrameInspector
from .frames import FramesWidget
from .hiz_tiles import HiZTileExplorer
from .inspector import PixelInspector
from .line_diamonds import DiamondExplorer
from .line_player import LinePlayer
from .live_slider import LiveSlider
from .pipeline_map import PipelineMap
from .plane_explorer import PlaneExplorer
from .player import FillPlayer
from .predict import Predict
from .predict_figure import PredictChoice, PredictOrder, PredictPixels, PredictPoint
from .projection_explorer import ProjectionExplorer
from .textured import TexturedPlaneViewer
from .tiles import TileExplorer
from .zbuffer_stepper import ZBufferStepper

__all__ = [
    "FrameInspector",
    "AttributeSurfaces",
    "BACKENDS",
    "BlendingExplorer",
    "CasePicker",
    "CrackExplorer",
    "DepthPrecisionExplorer",
    "DepthValuesExplorer",
    "DiamondExplorer",
    "DragFigure",
    "EdgeFunctionExplorer",
    "EyeRayExplorer",
    "FigureDisplay",
    "FilterExplorer",
    "FootprintExplorer",
    "FramesWidget",
    "HiZTileExplorer",
    "FillPlayer",
    "LinePlayer",
    "LiveSlider",
    "PipelineMap",
    "PixelInspector",
    "PlaneExplorer",
    "Predict",
    "PredictChoice",
    "PredictOrder",
    "PredictPixels",
    "PredictPoint",
    "ProjectionExplorer",
    "TexturedPlaneViewer",
    "TileExplorer",
    "TriangleEditor",
    "ZBufferStepper",
    "resolve_backend",
]
