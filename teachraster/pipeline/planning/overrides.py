"""Stage overrides: per-element rules that replace the package's own in one render.

A course's capstone renders the built-in scenes with the student's own functions (the
exercises' ``covers``, ``barycentric``, ``perspective_weights``, ``depth_passes``, ``over``,
``bilinear``, ``trilinear``, ``resolve``) beside the package's render of the same scenes.
Each rule is a plain Python function of the scalar or small-array arguments the exercises
use; the pipeline reads :class:`StageOverrides` in one place per stage and, where a rule is
given, calls it element by element instead of its own vectorised code:

- ``coverage(xy, p)`` -> bool: the fill, at every pixel centre ``p`` (2,) of each
  triangle's bounding box, ``xy`` (3, 2) its snapped window x, y;
- ``weights(xy, p)`` -> (3,) barycentrics: interpolation, at every visible fragment's centre,
  ``xy`` the window positions the weights are set up from;
- ``perspective(lam, w)`` -> (3,) weights of the vertex values: interpolation, from those
  barycentrics and the vertices' clip-space w (3,);
- ``depth(depths, writes)`` -> (n,) bools: the z-buffer of one pixel, whose n fragments
  (drawing order) have these depths and depth masks; which of them pass;
- ``blend(src, dst)`` -> (4,) RGBA: the colour buffer, every fragment blended;
- ``bilinear(texture, uv, wrap)`` and ``trilinear(pyramid, uv, lod, wrap)`` -> (C,):
  ``render_scene``'s texturing with ``texture_filter`` "bilinear" or "trilinear";
- ``resolve(colours, ids, background)`` -> (3,): ``render_scene``'s MSAA resolve of one
  covered pixel, from its S samples' colours (S, 3) and triangle ids (S,).

Nothing else changes: clipping, culling, snapping, depth values, Hi-Z's decisions where no
rule it depends on is replaced, the trace and the pixel history all read the same stage
outputs, so ``frame.history(row, col)`` of an overridden render tells the overridden
story. Without overrides (``overrides=None``, the default) nothing here runs: the package's
rules stay the single source of truth of every reference render. Rules of one-sample stages
(coverage, weights, perspective, depth) need ``samples=1``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields

#: The rules a render may replace, in pipeline order.
RULES = (
    "coverage", "weights", "perspective", "depth", "blend", "bilinear", "trilinear", "resolve",
)  # fmt: skip
#: The rules of the one-sample stages (multisampling has its own per-sample coverage).
SINGLE_SAMPLE_RULES = ("coverage", "weights", "perspective", "depth")


@dataclass(frozen=True)
class StageOverrides:
    """The rules that replace the package's own in one render (see the module docstring);
    each a callable or None (the package's rule)."""

    coverage: Callable | None = None
    weights: Callable | None = None
    perspective: Callable | None = None
    depth: Callable | None = None
    blend: Callable | None = None
    bilinear: Callable | None = None
    trilinear: Callable | None = None
    resolve: Callable | None = None

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if value is not None and not callable(value):
                raise TypeError(
                    f"overrides: {f.name} must be a function or None, got {type(value).__name__}"
                )

    @property
    def given(self) -> tuple[str, ...]:
        """The names of the rules replaced, in pipeline order."""
        return tuple(name for name in RULES if getattr(self, name) is not None)


def check_overrides(overrides) -> StageOverrides | None:
    """``overrides`` as a :class:`StageOverrides` (None when nothing is replaced).

    Accepts None, a :class:`StageOverrides` or a mapping of rule names to functions.

    >>> check_overrides({"depth": lambda depths, writes: [True] * len(depths)}).given
    ('depth',)
    >>> check_overrides({"coverage": None}) is None
    True
    >>> check_overrides({"cover": print})
    Traceback (most recent call last):
    ...
    ValueError: overrides: unknown rule 'cover'; the rules are coverage, weights, perspective, depth, blend, bilinear, trilinear, resolve
    """
    if overrides is None:
        return None
    if isinstance(overrides, Mapping):
        unknown = [k for k in overrides if k not in RULES]
        if unknown:
            raise ValueError(
                f"overrides: unknown rule {unknown[0]!r}; the rules are {', '.join(RULES)}"
            )
        overrides = StageOverrides(**overrides)
    if not isinstance(overrides, StageOverrides):
        raise TypeError(
            "overrides must be None, a StageOverrides or a dict of rule names to functions, "
            f"got {type(overrides).__name__}"
        )
    return overrides if overrides.given else None


def rule(overrides: StageOverrides | None, name: str) -> Callable | None:
    """The replacing rule ``name`` of ``overrides``, or None (the package's own)."""
    return None if overrides is None else getattr(overrides, name)
