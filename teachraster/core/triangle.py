"""The input of the core rasteriser: one screen-space triangle and its vertex data."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from .validate import as_finite


@dataclass(frozen=True)
class Triangle:
    """One triangle in screen space, ready to be filled.

    Parameters
    ----------
    xy : (3, 2) array-like
        Vertex positions in pixels: x to the right, y down (see CONVENTIONS).
    w : (3,) array-like, optional
        Clip-space w of each vertex (> 0); for a perspective camera this is the
        view-space depth. Default: all 1, i.e. no perspective.
    z : (3,) array-like, optional
        Window depth of each vertex, in [0, 1] (smaller is nearer).
    attrs : mapping of str to (3,) or (3, k) array-like, optional
        Per-vertex attributes to interpolate (colours, texture coordinates, ...).

    Examples
    --------
    >>> tri = Triangle([[1, 1], [5, 1], [1, 4]], attrs={"u": [0, 1, 0]})
    >>> tri.signed_area       # clockwise on screen: back-facing (see CONVENTIONS)
    6.0
    """

    xy: np.ndarray
    w: np.ndarray | None = None
    z: np.ndarray | None = None
    attrs: Mapping[str, np.ndarray] = field(default_factory=dict)

    def __post_init__(self) -> None:
        xy = as_finite("xy", self.xy, (3, 2))
        w = np.ones(3) if self.w is None else as_finite("w", self.w, (3,))
        if (w <= 0).any():
            raise ValueError(
                f"w must be > 0 for every vertex, got {w.tolist()}: a vertex with w <= 0 "
                "is on or behind the eye; clip the triangle against the near plane first "
                "(the scene pipeline, tr.render, does this in clip space)"
            )
        z = None if self.z is None else as_finite("z", self.z, (3,))
        if z is not None and ((z < 0) | (z > 1)).any():
            raise ValueError(f"z is window depth and must lie in [0, 1], got {z.tolist()}")
        attrs = {} if self.attrs is None else self.attrs
        if not isinstance(attrs, Mapping):
            raise TypeError(f"attrs must be a mapping of name to values, got {type(attrs)}")
        clean = {}
        for name, values in attrs.items():
            if not isinstance(name, str):
                raise TypeError(f"attrs: names must be strings, got {name!r}")
            arr = as_finite(f"attrs[{name!r}]", values, None)
            if arr.ndim not in (1, 2) or arr.shape[0] != 3:
                raise ValueError(
                    f"attrs[{name!r}] must have shape (3,) or (3, k): one value per vertex, "
                    f"got {arr.shape}"
                )
            clean[name] = arr
        for arr in (xy, w, *([z] if z is not None else []), *clean.values()):
            arr.flags.writeable = False
        object.__setattr__(self, "xy", xy)
        object.__setattr__(self, "w", w)
        object.__setattr__(self, "z", z)
        object.__setattr__(self, "attrs", clean)

    @property
    def signed_area(self) -> float:
        """Signed area in px², positive when the vertices run clockwise on screen.

        Computed relative to v1 (y-down numbers), ``E(v1, v2, v3) / 2``. Front-facing
        triangles (counter-clockwise on screen) have a negative value.
        """
        (ax, ay), (bx, by), (cx, cy) = self.xy
        return float(((bx - ax) * (cy - ay) - (by - ay) * (cx - ax)) / 2)

    @property
    def front_facing(self) -> bool:
        """True when the vertices run counter-clockwise as seen on screen."""
        return self.signed_area < 0
