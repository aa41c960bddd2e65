"""Plots and in-place-updating views of teachraster fills and renders (matplotlib).

``import teachraster`` never imports matplotlib; ``import teachraster.plotting`` does.

Conventions
-----------
Every ``plot_*`` function takes a matplotlib ``Axes`` first, draws on it and returns the
artists it created: a small dataclass that iterates like a list (``list(result)``) and names
them as fields. Pixel (row i, col j) is the square [j, j+1] × [i, i+1] in data coordinates,
**y down** (``ax.set_ylim(height, 0)``), with its centre (the sample point) at
(j + 0.5, i + 0.5), as in CONVENTIONS. NaN (not covered) is drawn transparent. Colours are
fixed per role (:data:`COLORS`, Okabe–Ito, colour-blind safe); sizes follow ``rcParams``, so
``use_style("classroom")`` makes every figure projector-ready.

Geometry of one fill (``fill = tr.rasterize(tri, W, H, trace=True)``)
-------------------------------------------------------------------
- :func:`plot_pixel_grid` -- pixel boundaries; sets up pixel axes (y down, ticks on centres).
- :func:`plot_pixel_centres` -- the sample points, filled where covered.
- :func:`plot_coverage` -- covered pixels of a Fill, Frame, trace or bool array.
- :func:`plot_triangle` -- edges with direction arrows, vertex labels v1, v2, v3, edge names.
- :func:`plot_bbox` -- the bounding box and the pixels whose centres it holds.
- :func:`plot_split` -- span tables: the split line at u4 with its value, the two flat parts.
- :func:`plot_raster_line` -- span tables: the raster line of a step and its span.
- :func:`plot_current_pixel` -- half-planes: the pixel a step tests.
- :func:`plot_edge_values` -- edge function E_k (values or signs) at every pixel centre.
- :func:`plot_bailout` -- which edge test rejected each pixel, and how many tests ran.
- :func:`plot_visit_order` -- the order in which the fill reaches the pixels.

Tiles (``fill = tr.rasterize(tri, W, H, method="tiled", trace=True)``)
-------------------------------------------------------------------
- :func:`plot_blocks` -- the classified blocks coloured by kind, a level or up to a step.
- :func:`plot_hierarchy` -- one panel per block size.
- :func:`plot_block_counters` -- llvmpipe-style counters as a table.
- :func:`plot_traversal` -- scanline, serpentine, tiled and Morton visiting orders.
- :func:`plot_block_path` -- the walk through one level's blocks in a traversal order.
- :func:`plot_block_values` -- one edge's values over a block, its extreme corners marked.
- :func:`plot_llvmpipe_bins` -- llvmpipe's binning pass: what it does with each 64×64 tile.
- :func:`plot_early_z` -- per pixel, fragments Hi-Z rejected, early-z killed, or shaded
  (``tr.render(..., trace=True)``).

Per-pixel values
----------------
- :func:`plot_barycentric` -- λ1, λ2, λ3 as RGB, or one weight as a value map.
- :func:`plot_attribute` -- an interpolated attribute (affine or perspective-correct).
- :func:`plot_error_heatmap` -- |a − b| with a colour bar; its maximum marked and in the title.
- :func:`plot_profile` -- two images' values along one row or column, as two curves.
- :func:`plot_depth` -- the depth buffer (window depth, dark = nearer).
- :func:`plot_image` -- a colour image such as a texture-mapped SceneFrame.
- :func:`plot_plan` / :func:`format_plan` -- a render plan as a text table.

Antialiasing (multisampled fills and frames, :mod:`.antialiasing`)
------------------------------------------------------------------
- :func:`plot_samples` -- every sample at its position, filled where covered.
- :func:`plot_pixel_samples` -- one pixel magnified: samples, owners, edge values.
- :func:`plot_coverage_fraction` -- the fraction of samples covered per pixel.
- :func:`plot_area_error` -- coverage fraction minus the exact area, signed.

Texture filtering (lesson 09)
-----------------------------
- :func:`plot_quads` -- 2×2 quads and helper pixels of ``render(..., derivatives=True, trace=True)``.
- :func:`plot_lod` -- the level-of-detail map, one colour per mip level.
- :func:`plot_levels_read` -- the level(s) a filter reads per pixel, blends mixed by weight.
- :func:`plot_pyramid` -- a mip pyramid, level 0 and the smaller levels beside it.
- :func:`plot_filters` -- filtered renders side by side with their error against the truth.

Frame debugging (``frame = tr.render(..., trace=True)``, :mod:`.frame_debug`)
--------------------------------------------------------------------------
- :func:`plot_overlay` -- ``frame.overlay(kind)``: overdraw, depth complexity, quad
  overshading, triangle size, Hi-Z, NaN, with a colour bar in numbers.
- :func:`plot_history` -- one pixel's history: a tile per fragment at its depth, coloured
  by outcome, the depth buffer before and after.

Views (draw once, then update in place; for widgets and animations)
-------------------------------------------------------------------
- :class:`FillView` -- step through a fill: ``show_step(k)``, ``set_fill(new_fill)``;
  ``redraw()`` renders a step by blitting (:class:`~.blitting.LayeredBlit`).
- :class:`InterpolationView` -- affine | perspective-correct | error heatmap, ``update(fill)``.
- :class:`ComparisonView` -- any two images and their error heatmap, ``update(a, b)``.

Style
-----
- :func:`use_style` -- ``"classroom"`` (large fonts, thick lines) or ``"default"``; also a
  context manager.
- :data:`COLORS`, :data:`OKABE_ITO` -- the colour of each role and the palette.
"""

# matplotlib itself comes with the style (as before: ``import teachraster.plotting`` imports
# matplotlib, never pyplot); every other name is imported from its module on first use (PEP 562),
# so a kernel that needs only ``use_style`` (the exercise notebooks) does not import the
# plotting modules it never calls (measured: see the commit that made this lazy).
from .style import COLORS, OKABE_ITO, STYLES, use_style

#: Each public name that is not the style's, and the module of this package that defines it.
_LAZY = {
    "PixelSampleArtists": "antialiasing",
    "SampleArtists": "antialiasing",
    "plot_area_error": "antialiasing",
    "plot_coverage_fraction": "antialiasing",
    "plot_pixel_samples": "antialiasing",
    "plot_samples": "antialiasing",
    "HistoryArtists": "frame_debug",
    "OverlayArtists": "frame_debug",
    "plot_history": "frame_debug",
    "plot_overlay": "frame_debug",
    "HeatmapArtists": "images",
    "ImageArtists": "images",
    "PlanArtists": "images",
    "ProfileArtists": "images",
    "abs_error": "images",
    "attribute_image": "images",
    "format_plan": "images",
    "plot_attribute": "images",
    "plot_barycentric": "images",
    "plot_depth": "images",
    "plot_error_heatmap": "images",
    "plot_image": "images",
    "plot_plan": "images",
    "plot_profile": "images",
    "BailoutArtists": "plots",
    "BBoxArtists": "plots",
    "CentreArtists": "plots",
    "CoverageArtists": "plots",
    "EdgeValueArtists": "plots",
    "GridArtists": "plots",
    "PixelArtists": "plots",
    "RasterLineArtists": "plots",
    "SplitArtists": "plots",
    "TriangleArtists": "plots",
    "VisitArtists": "plots",
    "bailout": "plots",
    "edge_images": "plots",
    "plot_bailout": "plots",
    "plot_bbox": "plots",
    "plot_coverage": "plots",
    "plot_current_pixel": "plots",
    "plot_edge_values": "plots",
    "plot_pixel_centres": "plots",
    "plot_pixel_grid": "plots",
    "plot_raster_line": "plots",
    "plot_split": "plots",
    "plot_triangle": "plots",
    "plot_visit_order": "plots",
    "visit_order": "plots",
    "FilterArtists": "texture_plots",
    "LevelsReadArtists": "texture_plots",
    "LodArtists": "texture_plots",
    "PyramidArtists": "texture_plots",
    "QuadArtists": "texture_plots",
    "plot_filters": "texture_plots",
    "plot_levels_read": "texture_plots",
    "plot_lod": "texture_plots",
    "plot_pyramid": "texture_plots",
    "plot_quads": "texture_plots",
    "BLOCK_COLORS": "tiles",
    "BlockArtists": "tiles",
    "BlockPathArtists": "tiles",
    "BlockValueArtists": "tiles",
    "CounterArtists": "tiles",
    "EarlyZArtists": "tiles",
    "TraversalArtists": "tiles",
    "block_mask": "tiles",
    "decided_mask": "tiles",
    "early_z_counts": "tiles",
    "plot_block_counters": "tiles",
    "plot_block_path": "tiles",
    "plot_block_values": "tiles",
    "plot_blocks": "tiles",
    "plot_early_z": "tiles",
    "plot_early_z_panels": "tiles",
    "plot_hierarchy": "tiles",
    "plot_llvmpipe_bins": "tiles",
    "plot_traversal": "tiles",
    "plot_walk_path": "tiles",
    "zoom_on_block": "tiles",
    "ComparisonView": "views",
    "FillView": "views",
    "InterpolationView": "views",
}


def __getattr__(name: str):
    import importlib
    import importlib.util

    module = _LAZY.get(name)
    if module is None:
        # a submodule, an attribute once the eager imports had loaded it (``tp.plots``)
        if not name.startswith("_") and importlib.util.find_spec(f"{__name__}.{name}"):
            return importlib.import_module(f".{name}", __name__)
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(f".{module}", __name__), name)
    globals()[name] = value  # the next lookup is an ordinary one
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY))


#: The style's names, then every name of :data:`_LAZY` (one list of the lazy names, not two).
__all__ = ["COLORS", "OKABE_ITO", "STYLES", "use_style", *_LAZY]
