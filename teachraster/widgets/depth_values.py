"""``DepthValuesExplorer``: where a depth buffer's representable values fall along z (05b).

Ritschel (*Interpolation and z-buffering*) warns that a "z-buffer can be inaccurate with few
bits"; where the inaccuracy lies depends on the mapping as much as on the bits. Four strips
show, along the view depth z (log scale), how many values unorm16, unorm24, float32 and
reverse-Z float32 can store in each pixel's range of z, with the near plane dragged along
the axis; a lens magnifies the z around the pointer linearly, where single values show.

Computed in the page (``static/explore_depth.js``); the stored values and their neighbours
are those of :func:`teachraster.pipeline.visibility.depth.quantize` of
:func:`~teachraster.pipeline.visibility.depth.window_depth` (and of ``reversed_depth`` in
float32), compared exactly by the tests.
"""

from __future__ import annotations

from ..core.validate import as_float
from .explorable import Explorable, esm_source


class DepthValuesExplorer(Explorable):
    """The representable depth values along z, with a draggable near plane.

    Parameters
    ----------
    near, far : float
        The clip planes (``0 < near <= far / 4``); the near plane is dragged from ``zmin``.
    z0 : float
        The distance the lens magnifies first.
    zmin : float
        The left end of the z axis.

    Attributes
    ----------
    near : float
        Where the page last left the near plane (set it to move the plane).

    Examples
    --------
    >>> ex = DepthValuesExplorer(near=0.1, far=1000.0)
    >>> ex.near = 1.0
    >>> ex.state["near"]
    1.0
    """

    _esm = esm_source("explore_depth")
    noun = "depth-values explorer"
    title = "Where the depth values are"

    def __init__(self, near: float = 0.1, far: float = 1000.0, *, z0: float = 100.0,
                 zmin: float = 0.01) -> None:  # fmt: skip
        near, far = as_float("near", near), as_float("far", far)
        z0, zmin = as_float("z0", z0), as_float("zmin", zmin)
        if not 0 < zmin <= near <= far / 4:
            raise ValueError(f"need 0 < zmin <= near <= far / 4, got zmin={zmin}, near={near}, "
                             f"far={far}")  # fmt: skip
        if not near <= z0 <= far:
            raise ValueError(f"z0 must lie between near and far, got {z0}")
        super().__init__()
        self.data = {"near": near, "far": far, "z0": z0, "zmin": zmin}
        self.state = {"near": near, "z0": z0, "zoom": 0}

    @property
    def near(self) -> float:
        """The near plane where the page last left it."""
        return float(self.state["near"])

    @near.setter
    def near(self, value: float) -> None:
        value = as_float("near", value)
        if not self.data["zmin"] <= value <= self.data["far"] / 4:
            raise ValueError(f"near must lie in [zmin, far / 4], got {value}")
        self.state = {**self.state, "near": value, "z0": max(self.state["z0"], value)}
