"""Frame debugging: a traced frame's pixel history and its debug views (lesson 11).

- :mod:`.frame_history`: ``frame.history(row, col)``, every triangle on the way to a pixel in
  submission order with the first test that stopped it, replayable bit for bit;
- :mod:`.overlays`: ``frame.overlay(kind)``, overdraw, depth complexity, quad overshading,
  triangle size, Hi-Z and NaN views of the whole frame; ``helper_share(frame)``, the helper
  lanes over all lanes launched, ``quad_triangles(frame, row, col)``, who shaded a quad, and
  ``visible_triangle_sizes(frame)``, one size per triangle shown.

This stage reads frames, so it sits above :mod:`..rendering`; the two ``Frame`` methods find
it through :data:`~teachraster.pipeline.rendering.render_triangles.FRAME_DEBUGGERS`, where it
registers itself here (importing ``teachraster`` imports every stage).
"""

from ..rendering.render_triangles import FRAME_DEBUGGERS
from .frame_history import OUTCOMES, HistoryRecord, PixelHistory, pixel_history
from .overlays import (
    KINDS,
    covered_pieces,
    helper_share,
    overlay,
    passed_per_triangle,
    quad_triangles,
    visible_triangle_sizes,
)

FRAME_DEBUGGERS.update(history=pixel_history, overlay=overlay)

__all__ = [
    "KINDS",
    "OUTCOMES",
    "HistoryRecord",
    "PixelHistory",
    "covered_pieces",
    "helper_share",
    "overlay",
    "passed_per_triangle",
    "pixel_history",
    "quad_triangles",
    "visible_triangle_sizes",
]
