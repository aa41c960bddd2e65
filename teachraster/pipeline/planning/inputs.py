"""The argument checks of ``render`` and ``render_scene``, in one place.

:func:`check_render` turns what a caller passed into checked plain values (float64 arrays
of the right shapes, Python ints and bools, a set of forced effects) or raises a
ValueError/TypeError whose message names the offending argument, before anything the
size of the image is allocated. The image size is capped at ``max_pixels`` (2**28 unless
the caller raises it), so a typo such as ``width=100000`` fails at once with what it would
have cost instead of after minutes of allocation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.fill import CULL
from ...core.interpolation import MODES
from ...core.snapping import check_bits
from ...core.validate import (
    as_bool,
    as_finite,
    as_size,
    check_choice,
    check_pixels,
    check_shape,
    short_repr,
)
from ..visibility.depth import DEPTH_FORMATS
from .overrides import StageOverrides, check_overrides
from .render_plan import parse_force

#: Bytes per pixel of render's frame-sized buffers without attributes (triangle id, depth,
#: z-buffer, winner, fragment counts), plus 8 per attribute channel.
FRAME_BYTES = 40


@dataclass(frozen=True)
class RenderInputs:
    """Checked arguments of :func:`teachraster.pipeline.render_triangles.render`.

    ``clip`` is (N, 3, 4) float64, ``attrs`` (N, 3, k) float64 (k = 0 without attributes),
    ``forced`` the set of effect names ``force`` asked for; ``overrides`` the rules that
    replace the package's own (:mod:`.overrides`; None: none); the rest are plain Python values.
    """

    clip: np.ndarray
    attrs: np.ndarray
    width: int
    height: int
    depth_test: bool
    cull: str | None
    depth_format: str
    interpolation: str
    forced: frozenset[str]
    trace: bool
    subpixel_bits: int | None
    max_pixels: int
    overrides: StageOverrides | None = None


def check_force(force) -> frozenset[str]:
    """``force`` as a set of effect names: None, "all", one name, or a list, tuple or set of
    names. Anything else (a mapping, whose keys are no request; an array) is a TypeError.
    """
    if force is None or isinstance(force, str):
        return parse_force(force)
    names = list(force) if isinstance(force, list | tuple | set | frozenset) else None
    if names is None or not all(isinstance(name, str) for name in names):
        raise TypeError(
            "force must be None, 'all', an effect name or a list of effect names, got "
            f"{short_repr(force)}"
        )
    return parse_force(names)


def check_clip(clip) -> np.ndarray:
    """Clip-space triangles as (N, 3, 4) float64; ``[]`` is the empty scene.

    >>> check_clip([]).shape
    (0, 3, 4)
    """
    arr = as_finite("clip", clip, None)
    if arr.shape == (0,):  # an empty list: no triangles (np.zeros((0, 3, 4)) also works)
        return np.zeros((0, 3, 4))
    check_shape("clip", arr.shape, (None, 3, 4))
    return arr


def check_attrs(attrs, n: int) -> np.ndarray:
    """Per-vertex attributes (N, 3) or (N, 3, k) as (N, 3, k) float64; None gives k = 0."""
    if attrs is None:
        return np.zeros((n, 3, 0))
    arr = as_finite("attrs", attrs, None)
    if arr.ndim == 2:
        arr = arr[:, :, None]
    check_shape("attrs", arr.shape, (n, 3, None))
    return arr


def check_size(width, height, max_pixels, bytes_per_pixel: int = FRAME_BYTES):
    """``(width, height, max_pixels)`` as Python ints, the image no larger than allowed."""
    width, height = as_size("width", width), as_size("height", height)
    return width, height, check_pixels(width, height, max_pixels, bytes_per_pixel)


def check_render(
    clip, width, height, *, attrs, depth_test, cull, depth_format, interpolation, force,
    trace, subpixel_bits, max_pixels, overrides=None,
) -> RenderInputs:  # fmt: skip
    """Check every argument of ``render`` (same names and meanings) and return them clean.

    >>> args = check_render([], np.int16(4), 3, attrs=None, depth_test=True, cull=None,
    ...                     depth_format="float64", interpolation="perspective",
    ...                     force=None, trace=False, subpixel_bits=np.uint8(8), max_pixels=None)
    >>> args.width, type(args.subpixel_bits), args.clip.shape
    (4, <class 'int'>, (0, 3, 4))
    """
    width, height, max_pixels = check_size(width, height, max_pixels)
    depth_test = as_bool("depth_test", depth_test)
    trace = as_bool("trace", trace)
    check_choice("cull", cull, CULL)
    check_choice("depth_format", depth_format, DEPTH_FORMATS)
    check_choice("interpolation", interpolation, MODES)
    subpixel_bits = check_bits(subpixel_bits)
    forced = check_force(force)
    overrides = check_overrides(overrides)
    clip = check_clip(clip)
    attrs = check_attrs(attrs, len(clip))
    # Now that k is known, the frame's true cost (the size check above used k = 0).
    check_pixels(width, height, max_pixels, FRAME_BYTES + 8 * attrs.shape[2])
    return RenderInputs(
        clip, attrs, width, height, depth_test, cull, depth_format, interpolation, forced,
        trace, subpixel_bits, max_pixels, overrides,
    )  # fmt: skip
