"""One small example of every widget class of :mod:`teachraster.widgets`, for tests that must
cover them all (``tests/test_offline_widgets.py``): a class without an example here fails
that test, so a new widget cannot be forgotten."""

from __future__ import annotations

import teachraster as tr

TRI = [[1.2, 1.5], [13.7, 4.2], [5.1, 12.8]]


def _rows():
    """Interpolation rows as lesson 06's study makes them (counts and errors), made up."""
    out = []
    for name, d, m, a, err in [("affine", 0, 6, 6, 3.0), ("subdivided N=16", 0.2, 9, 9, 0.6),
                               ("subdivided N=2", 1, 12, 12, 0.1), ("perspective", 2, 12, 10, 0.0)]:  # fmt: skip
        out.append({"variant": name, "group": "interpolation", "divides": d, "multiplies": m,
                    "additions": a, "error": err * 2, "mean_abs_texels": err,
                    "cycles": 1.0})  # fmt: skip
    return out


def _hiz_frames():
    """Two full-screen triangles at two depths, drawn in both orders (traced)."""
    import numpy as np

    tri = np.array([[[-1, -1, z, 1], [3, -1, z, 1], [-1, 3, z, 1]] for z in (0.0, 0.5)])
    return {"near first": tr.render(tri, 16, 16, trace=True),
            "far first": tr.render(tri[::-1], 16, 16, trace=True)}  # fmt: skip


def examples():
    """name -> a function making that widget (image backend, small sizes)."""
    from teachraster import widgets as w
    from teachraster.widgets.divide_cost import DivideCostExplorer
    from teachraster.widgets.sampling_explorer import SamplingExplorer
    from teachraster.widgets.span_explorer import SpanSubdivisionExplorer

    tri = tr.Triangle(TRI, attrs={"u": [0.0, 1.0, 0.5]})
    return {
        "FillPlayer": lambda: w.FillPlayer(tr.Triangle(TRI), 8, 8, backend="image"),
        "TriangleEditor": lambda: w.TriangleEditor(tri, 16, 14, backend="image"),
        "TileExplorer": lambda: w.TileExplorer(
            tr.Triangle(TRI), 16, 16, block_sizes=(8, 2), backend="image"
        ),  # fmt: skip
        "TexturedPlaneViewer": lambda: w.TexturedPlaneViewer(48, 36, backend="image"),
        "PixelInspector": lambda: w.PixelInspector(tr.Triangle(TRI), 8, 8, backend="image"),
        "FilterExplorer": lambda: w.FilterExplorer(48, 36, backend="image"),
        "Predict": lambda: w.Predict("How many?", ["one", "two"], "two", explain="Two."),
        "ProjectionExplorer": lambda: w.ProjectionExplorer(backend="image"),
        "ZBufferStepper": lambda: w.ZBufferStepper(
            tr.render(tr.get_scene("cube"), None, 24, 18, trace=True), backend="image"
        ),
        "FrameInspector": lambda: w.FrameInspector(
            "intersecting_triangles", 24, 18, backend="image"
        ),  # fmt: skip
        "PlaneExplorer": lambda: w.PlaneExplorer(backend="image"),
        "DepthPrecisionExplorer": lambda: w.DepthPrecisionExplorer(backend="image"),
        "CasePicker": lambda: w.CasePicker(backend="image"),
        "LinePlayer": lambda: w.LinePlayer((0.5, 0.5), (9.5, 4.5), 11, 6, backend="image"),
        "BlendingExplorer": lambda: w.BlendingExplorer(size=(16, 16), backend="image"),
        "HiZTileExplorer": lambda: w.HiZTileExplorer(_hiz_frames(), (4, 8), backend="image"),
        "SamplingExplorer": lambda: SamplingExplorer(backend="image"),
        "DivideCostExplorer": lambda: DivideCostExplorer(_rows(), backend="image"),
        "SpanSubdivisionExplorer": lambda: SpanSubdivisionExplorer(backend="image"),
        # computed in the page (teachraster.widgets.explorable): live in an offline page
        "PipelineMap": lambda: w.PipelineMap(),
        "CrackExplorer": lambda: w.CrackExplorer(8, 8),
        "EdgeFunctionExplorer": lambda: w.EdgeFunctionExplorer(),
        "AttributeSurfaces": lambda: w.AttributeSurfaces(),
        "EyeRayExplorer": lambda: w.EyeRayExplorer(),
        "DepthValuesExplorer": lambda: w.DepthValuesExplorer(),
        "FootprintExplorer": lambda: w.FootprintExplorer(24, 18),
        "DiamondExplorer": lambda: w.DiamondExplorer((1.5, 1.5), (6.4, 3.6), 8, 5),
        "PredictPixels": lambda: w.PredictPixels(
            "Which pixels?", answer=tr.rasterize(tr.Triangle(TRI), 8, 8).coverage
        ),
        "PredictPoint": lambda: w.PredictPoint(
            "Where?", answer=(1.0, 2.0), draw=None, xlim=(0, 4), ylim=(0, 4)
        ),
        "PredictOrder": lambda: w.PredictOrder("Nearest first?", ["a", "b"], answer=["b", "a"]),
        "PredictChoice": lambda: w.PredictChoice("How far?", ["near", "far"], answer="far"),
    }
