"""teachraster: an instrumented triangle rasteriser for teaching how GPUs fill triangles.

The core (this package minus plotting and widgets) depends on numpy only.

>>> import teachraster as tr
>>> fill = tr.rasterize(tr.Triangle([[0, 0], [3, 0], [0, 3]]), 3, 3, method="span")
>>> int(fill.coverage.sum())   # centres with x + y < 3; the hypotenuse is not top-left
3
"""

# The public API is the core's and the pipeline's names: each package lists its own once, in
# its __all__ (teachraster/core/__init__.py, teachraster/pipeline/__init__.py).
from . import core, pipeline
from .core import *  # noqa: F403
from .pipeline import *  # noqa: F403

__version__ = "0.1.0"

__all__ = [*core.__all__, *pipeline.__all__]
