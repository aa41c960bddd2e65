"""``PipelineMap``: lesson 00's map of the pipeline, with the tour triangle's data at each stage.

The logical order of OpenGL and Direct3D: vertex shader, primitive assembly, clipping (x and y
only beyond a guard band), the divide by w, the viewport, triangle set-up, rasterisation, the
fragment shader, the depth and stencil tests, blending. Early-z, which tests and writes depth before
shading, is drawn as a dashed conditional bypass, legal only when the shader neither discards,
writes depth nor writes memory (with discard a GPU may still test early and write late; lessons 05a, 10;
GL 4.6 §14.9, §15.2). Click a stage (in the style of the WebGL state diagram) to see the tour
triangle there: its clip coordinates, NDC, window coordinates, set-up, fragments, depth and
final pixels.

The data is the engine's (:func:`teachraster.render` with ``trace=True``,
:func:`teachraster.pipeline.geometry.viewport.to_window`, :func:`teachraster.core.edges.setup_edges`);
the page (``static/explore_pipeline.js``) only lays it out. The lessons in each box come from
the static figure's table (:data:`~teachraster.plotting.pipeline_overview.PIPELINE_STAGES`),
which has the same ten stages.
"""

from __future__ import annotations

import numpy as np

from ..core.edges import setup_edges
from ..core.fill import rasterize
from ..core.snapping import SUBPIXEL_BITS, units_per_pixel
from ..core.triangle import Triangle
from ..core.validate import as_finite, as_float, as_size
from ..pipeline.geometry.clipping import INSIDE, classify
from ..pipeline.geometry.viewport import to_window
from ..pipeline.rendering.render_triangles import render
from ..pipeline.rendering.stages import guard_band
from ..plotting.pipeline_overview import PIPELINE_STAGES, lesson_number
from ..plotting.style import VALUE_CMAP
from .explorable import Explorable, esm_source

#: The tour triangle of lesson 00 (window pixels, y down), its w and its attribute u.
TOUR_XY = ((2.2, 1.5), (13.7, 5.2), (5.1, 12.8))
TOUR_W = (1.0, 2.0, 4.0)
TOUR_U = (0.0, 1.0, 0.0)

#: The colour the map's colour target is cleared to (the blending stage's background).
CLEAR_COLOUR = 1.0


#: The map's stages by the static figure's (:data:`PIPELINE_STAGES`) names: every stage is
#: drawn in both, and the lessons are read from there, so the two pictures cannot disagree.
SHARED_STAGES = {
    "vertex": "vertex processing", "assembly": "primitive assembly", "clip": "clipping",
    "divide": "perspective divide", "viewport": "viewport", "setup": "triangle set-up",
    "rasterize": "rasterisation", "fragment": "fragment shading", "depth": "depth test",
    "blend": "blending",
}  # fmt: skip


def map_lessons() -> dict[str, tuple[str, ...]]:
    """The lessons (notebook stems) teaching each of the map's stages, by its key."""
    by_name = {stage.name: stage.lessons for stage in PIPELINE_STAGES}
    return {key: by_name[name] for key, name in SHARED_STAGES.items()}


def lessons_label(stems, width: int = 9) -> list[str]:
    """The lesson numbers of ``stems`` as a stage box prints them: a run of three or more
    consecutive whole numbers as a range, in lines of at most ``width`` characters (nine
    at 16 px are about 80 px: a 132-px box holds them with a wide margin on either side;
    twelve at 15 px filled a 104-px box from border to border, review r97 00-5).

    >>> lessons_label(["01_a", "02_b", "03_c", "04_d", "06_e", "07_f", "08_g", "10_h", "12_i"])
    ['01–04,', '06–08,', '10, 12']
    >>> lessons_label(["05a_zbuffer", "05b_depth_precision", "10_tiles"])
    ['05a, 05b,', '10']
    """
    import textwrap

    numbers, items = [lesson_number(stem) for stem in stems], []
    while numbers:
        run = 1  # how many numbers from here count up by one
        while (run < len(numbers) and numbers[run].isdigit() and numbers[0].isdigit()
               and int(numbers[run]) == int(numbers[0]) + run):  # fmt: skip
            run += 1
        items.append(f"{numbers[0]}–{numbers[run - 1]}" if run >= 3 else numbers[0])
        numbers = numbers[run if run >= 3 else 1 :]
    return textwrap.wrap(", ".join(items), width, break_on_hyphens=False)


def tour_clip(xy, w, width: int, height: int, near: float, far: float) -> np.ndarray:
    """(3, 4) clip coordinates a vertex shader with GL's perspective projection (``near``,
    ``far``; w = the depth along the viewing axis) would output for window positions ``xy`` at depths ``w``:
    the viewport inverted, x_ndc = 2x/W - 1, y_ndc = 1 - 2y/H, and GL's
    z_ndc = (f + n)/(f - n) - 2 f n / ((f - n) w)."""
    xy, w = np.asarray(xy, float), np.asarray(w, float)
    x_ndc = 2.0 * xy[:, 0] / width - 1.0
    y_ndc = 1.0 - 2.0 * xy[:, 1] / height
    z_ndc = (far + near) / (far - near) - 2.0 * far * near / ((far - near) * w)
    return np.stack([x_ndc * w, y_ndc * w, z_ndc * w, w], axis=-1)


def _image_list(values: np.ndarray) -> list:
    """A (H, W) or (H, W, C) array as a row-major list, None where not finite."""
    flat = values.reshape(values.shape[0] * values.shape[1], -1)
    return [None if not np.isfinite(v).all() else (float(v[0]) if len(v) == 1 else v.tolist())
            for v in flat]  # fmt: skip


def tour_stages(xy=TOUR_XY, w=TOUR_W, u=TOUR_U, width: int = 16, height: int = 16,
                near: float = 0.5, far: float = 10.0) -> dict:  # fmt: skip
    """Everything the map shows, computed by the engine: per vertex clip coordinates, NDC,
    window coordinates and the clip tests; the set-up; per pixel the fragments, u, depth and
    the final colour (u through the lessons' colour map for values, the shader of this map)."""
    from matplotlib import colormaps

    clip = tour_clip(xy, w, width, height, near, far)
    attrs = np.asarray(u, float)[None, :, None]
    frame = render(clip[None], width, height, attrs=attrs, trace=True)
    window = to_window(clip, width, height)
    setup = setup_edges(window[:, :2], SUBPIXEL_BITS)
    given = np.array([setup.perm.tolist().index(k) for k in range(3)])
    edges_tl = [bool(setup.top_left[k]) for k in range(3)]
    fill = rasterize(Triangle(window[:, :2]), width, height, trace=True)
    box = fill.trace.bbox
    colour = colormaps[VALUE_CMAP](np.nan_to_num(frame.attrs[..., 0]))[..., :3]
    # the cleared colour target: white, the one clear colour no u stands out badly on (dark
    # grey hid the navy u = 0 fragments, mid grey the grey u = 0.5 ones; cividis runs from
    # navy through grey to yellow, and white is farthest from all of it)
    colour[~frame.coverage] = CLEAR_COLOUR
    # the guard band render clips this image with (not the clipper's default): the vertices
    # are tested against it (lessons 05a and 10 give its size; the map says only that it is
    # the simulator's own, review r241 S7)
    guard = guard_band(width, height, SUBPIXEL_BITS)
    return {
        "width": width, "height": height, "near": near, "far": far,
        "clip": clip.tolist(), "u": list(map(float, u)), "w": list(map(float, w)),
        "inside": [bool(s == INSIDE) for s in classify(clip[None], guard)],
        "guard": guard,
        "ndc": (clip[:, :3] / clip[:, 3:]).tolist(), "window": window.tolist(),
        "snapped": (setup.p[given] / units_per_pixel(SUBPIXEL_BITS)).tolist(),
        "area": float(setup.original_area2) / units_per_pixel(SUBPIXEL_BITS) ** 2 / 2,
        "front": bool(setup.original_area2 < 0), "culled": bool(frame.trace.culled[0]),
        "oriented": [int(k) for k in setup.perm], "topLeft": edges_tl,
        "bbox": [int(box.row0), int(box.row1), int(box.col0), int(box.col1)],
        "coverage": frame.coverage.ravel().astype(int).tolist(),
        "fragments": int(len(frame.trace.fragment_row)),
        "passed": int(frame.trace.fragment_passed.sum()),
        "attr": _image_list(frame.attrs), "depth": _image_list(frame.depth),
        "colour": np.round(colour * 255).astype(int).reshape(-1, 3).tolist(),
        "lessons": {key: lessons_label(stems) for key, stems in map_lessons().items()},
    }  # fmt: skip


class PipelineMap(Explorable):
    """The pipeline in GL/D3D order; click a stage for the tour triangle's data there.

    Parameters
    ----------
    xy, w, u : the triangle (window pixels), its clip-space w and its attribute per vertex
        (default: lesson 00's tour triangle).
    width, height : int
        The image (16 x 16 in the tour).
    near, far : float
        The perspective projection whose clip coordinates the map shows.

    Attributes
    ----------
    state : dict
        ``stage``: the stage on show (its key, e.g. ``"rasterize"``).

    Examples
    --------
    >>> m = PipelineMap()
    >>> m.data["fragments"], m.data["inside"]
    (59, [True])
    """

    _esm = esm_source("explore_pipeline")
    noun = "pipeline map"
    title = "The pipeline, stage by stage"

    def __init__(self, xy=TOUR_XY, w=TOUR_W, u=TOUR_U, width: int = 16, height: int = 16, *,
                 near: float = 0.5, far: float = 10.0, stage: str = "rasterize") -> None:  # fmt: skip
        xy, w, u = as_finite("xy", xy, (3, 2)), as_finite("w", w, (3,)), as_finite("u", u, (3,))
        if (w <= 0).any():
            raise ValueError(f"w must be > 0 at every vertex (in front of the eye), got {w}")
        near, far = as_float("near", near), as_float("far", far)
        if not 0 < near < far:
            raise ValueError(f"need 0 < near < far, got near={near}, far={far}")
        if ((w < near) | (w > far)).any():
            raise ValueError(f"w must lie between near and far, got {w.tolist()}")
        width, height = as_size("width", width), as_size("height", height)
        if width * height > 64 * 64:
            raise ValueError(f"the map shows every pixel: at most 64 x 64, got {width}x{height}")
        super().__init__()
        self.data = tour_stages(xy, w, u, width, height, near, far)
        self.state = {"stage": str(stage)}
