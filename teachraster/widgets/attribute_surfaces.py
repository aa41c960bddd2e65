"""``AttributeSurfaces`` and ``EyeRayExplorer``: lessons 03/04's attribute, in 3-D and along a ray.

Ek (*Triangles and Perspective Correct Interpolation*, §2, eq. 19) shows that under
perspective f/w and 1/w are affine in screen space while f is not. ``AttributeSurfaces``
draws them over the screen triangle as a rotatable 3-D picture: a plane for a flat triangle;
for a perspective one f/w and 1/w as two planes, the perspective-correct f as their ratio (a
curved sheet) and the affine plane that misses it. ``EyeRayExplorer`` is Ek's Figures 6-7
(the eye, the screen z = 1, a segment) with draggable segment ends, a depth-ratio slider and
t(q) drawn live, the largest gap q - t marked: 3 - 2√2 for a depth ratio of 2.

Computed in the page (``static/explore_attributes.js``, ``static/explore_projection.js``);
the values are those of :func:`teachraster.barycentric` and
:func:`teachraster.core.interpolation.perspective_weights` (and of
:class:`teachraster.plotting.projection.Segment`), compared by the tests.
"""

from __future__ import annotations

import numpy as np

from ..core.validate import as_finite, as_float, as_size
from .explorable import Explorable, esm_source


class AttributeSurfaces(Explorable):
    """f, f/w, 1/w and the affine plane over a screen triangle, turned with the pointer.

    Parameters
    ----------
    xy : (3, 2) array-like
        The screen triangle in pixels.
    w : (3,) array-like
        Clip-space w of each vertex (> 0); the page's slider moves v3's (1 to 8).
    f : (3,) array-like
        The attribute at each vertex, in [0, 1].
    width, height : int
        The screen under the triangle.
    show : iterable of str, optional
        The sheets switched on at the start, of ``SHEETS``: "correct" (the
        perspective-correct f), "affine", "fw" (f/w) and "inv" (1/w). Default: the page's
        own, the two f sheets (lesson 03 switches f/w and 1/w on later; lesson 04 opens on
        f, f/w and 1/w, its claim being that two of them are planes, and leaves the affine
        plane for the student to switch on).

    Examples
    --------
    >>> ex = AttributeSurfaces(w=[1, 1, 4])
    >>> ex.state["w"]
    [1.0, 1.0, 4.0]
    >>> AttributeSurfaces(show=["correct", "fw"]).state["show"]["inv"]
    False
    """

    #: The sheets' names, as the page's buttons and ``state["show"]`` know them
    SHEETS = ("correct", "affine", "fw", "inv")

    _esm = esm_source("raster_rules", "view3d", "explore_attributes")
    noun = "3-D attribute view"
    title = "The attribute over the triangle, in 3-D"

    def __init__(self, xy=((2.0, 2.0), (14.0, 4.0), (5.0, 14.0)), w=(1.0, 1.0, 4.0),
                 f=(0.0, 1.0, 0.0), width: int = 16, height: int = 16,
                 show=None) -> None:  # fmt: skip
        xy = as_finite("xy", xy, (3, 2))
        w, f = as_finite("w", w, (3,)), as_finite("f", f, (3,))
        if (w <= 0).any():
            raise ValueError(f"w must be > 0 at every vertex, got {w.tolist()}")
        if ((f < 0) | (f > 1)).any():
            raise ValueError(f"f must lie in [0, 1] (the picture's height), got {f.tolist()}")
        width, height = as_size("width", width), as_size("height", height)
        super().__init__()
        self.data = {"xy": xy.tolist(), "w": w.tolist(), "f": f.tolist(), "width": width,
                     "height": height}  # fmt: skip
        state = {"w": w.tolist()}
        if show is not None:
            show = [show] if isinstance(show, str) else list(show)
            unknown = [name for name in show if name not in self.SHEETS]
            if unknown:
                raise ValueError(f"show: unknown sheets {unknown}, expected some of {self.SHEETS}")
            state["show"] = {name: name in show for name in self.SHEETS}
        # one assignment: a traitlets Dict syncs to the page only when it is assigned, never
        # when changed in place (the page then opened on its own default sheets)
        self.state = state


class EyeRayExplorer(Explorable):
    """Ek's eye-screen-segment picture with draggable ends, a depth ratio and t(q) live.

    Parameters
    ----------
    ends : ((x0, z0), (x1, z1))
        The segment's ends, in front of the eye (0.3 <= z <= 4.4, |x| <= 3.4: the picture).
    q : float
        The screen parameter shown first.

    Examples
    --------
    >>> ex = EyeRayExplorer()
    >>> ex.state["ends"]
    [[-1.0, 1.5], [2.0, 3.0]]
    """

    _esm = esm_source("explore_projection")
    noun = "eye-ray explorer"
    title = "Equal steps on the screen, unequal steps in the world"

    def __init__(self, ends=((-1.0, 1.5), (2.0, 3.0)), q: float = 0.5) -> None:
        ends = as_finite("ends", ends, (2, 2))
        if not ((ends[:, 1] >= 0.3) & (ends[:, 1] <= 4.4) & (np.abs(ends[:, 0]) <= 3.4)).all():
            raise ValueError(
                "ends must lie in the picture: 0.3 <= z <= 4.4 (in front of the eye) "
                f"and |x| <= 3.4, got {ends.tolist()}"
            )
        q = as_float("q", q)
        if not 0.0 <= q <= 1.0:
            raise ValueError(f"q must lie in [0, 1], got {q}")
        super().__init__()
        self.data = {"ends": ends.tolist(), "q": q}
        self.state = {"ends": ends.tolist(), "q": q}
