"""Every triangle's coverage at once: the batched span fill and per-sample coverage.

The scene-sized versions of :func:`teachraster.rasterize` (lessons 01-02, 08): the same
top-left rule from :mod:`teachraster.core`, for thousands of triangles in one pass.
"""
