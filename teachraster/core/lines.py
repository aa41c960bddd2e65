"""``rasterize_line``: which pixels a line segment lights, and its attributes along it.

One-pixel lines follow the diamond-exit rule of the GL specification (§14.5.1) and Direct3D
(:mod:`.line_rules`, exact with GL's tie perturbation); Bresenham's midpoint loop and the DDA
are there to compare. Wide lines are what llvmpipe and most hardware draw: the rectangle of
``line_width`` around the segment, split into two triangles filled under the one top-left
rule of :mod:`.edges` (so the two halves never share a pixel). End points are snapped like
triangle vertices (:mod:`.snapping`).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .fill import Fill, rasterize
from .interpolation import interpolate
from .line_clip import clip_to_box
from .line_rules import RULE_FUNCTIONS, RULES, empty_steps, major_axis
from .line_trace import LineTrace
from .snapping import (
    FLOAT_LIMIT,
    SUBPIXEL_BITS,
    UNIT_LIMIT,
    check_bits,
    snap,
    to_units,
    units_per_pixel,
)
from .triangle import Triangle
from .validate import as_bool, as_finite, as_float, as_size, check_choice, check_pixels

#: Largest |coordinate| of a line end point in internal units (2**20 px with 8 bits): the
#: exact diamond test multiplies two differences of u = x + y, each below 2**31.
LINE_UNIT_LIMIT = 2**29

INTERPOLATIONS = ("perspective", "affine")


def rasterize_line(
    p0,
    p1,
    width: int,
    height: int,
    *,
    rule: str = "diamond",
    line_width: float = 1,
    trace: bool = False,
    subpixel_bits: int | None = SUBPIXEL_BITS,
    w=None,
    z=None,
    attrs: Mapping | None = None,
    interpolation: str = "perspective",
    max_pixels: int | None = None,
) -> Fill:
    """Light the pixels of the segment p0 → p1 in a ``height`` × ``width`` image.

    Parameters
    ----------
    p0, p1 : (2,) array-like
        End points in window pixels (x right, y down; CONVENTIONS).
    width, height : int
        Image size in pixels.
    rule : {"diamond", "bresenham", "dda"}
        The diamond-exit rule (GL, Vulkan's Bresenham mode; p1's own diamond is left out so
        that a polyline lights each shared vertex once), Bresenham's integer midpoint loop
        between the end pixels, or the float32 DDA; the last two also leave out p1's pixel.
    line_width : float
        1 (one-pixel lines, the rule above) or more: the rectangle of that width around the
        segment, as two triangles under the top-left rule (``rule`` must be "diamond").
    trace : bool
        Record every step (:class:`~teachraster.core.line_trace.LineTrace`).
    subpixel_bits : int or None
        End points are snapped to ``1 / 2**subpixel_bits`` px (8), as triangle vertices are,
        and must then lie within ±2**20 px (8 bits; wide lines 2**21; a ValueError names
        p0 or p1). None keeps raw floats: the segment is first clipped exactly to a box just
        around the image (GL clips lines too), so ends as far as the float maximum work.
    w : (2,) array-like, optional
        Clip-space w of each end (> 0, subnormal included), for perspective-correct
        attributes; default 1.
    z : (2,) array-like, optional
        Window depth of each end (affine along the line).
    attrs : mapping of str to (2,) or (2, k) array-like, optional
        Attributes at the ends, interpolated at each lit pixel centre's projection onto
        the segment (the GL rule), perspective-correct unless ``interpolation="affine"``.

    Returns
    -------
    Fill
        ``coverage`` (height, width) bool, ``attrs`` (NaN where not lit), ``depth``,
        ``trace``.

    Examples
    --------
    >>> import teachraster as tr
    >>> tr.rasterize_line((0.5, 0.5), (4.5, 2.5), 5, 3).coverage.astype(int)
    array([[1, 0, 0, 0, 0],
           [0, 1, 1, 0, 0],
           [0, 0, 0, 1, 0]])

    Column 1 is a tie (the line crosses x = 1.5 at y = 1.0, the corner of two diamonds): GL's
    perturbation gives it to the lower pixel; column 4 holds p1, left to the next segment.
    """
    width, height = as_size("width", width), as_size("height", height)
    check_pixels(width, height, max_pixels, 8)
    check_choice("rule", rule, RULES)
    check_choice("interpolation", interpolation, INTERPOLATIONS)
    line_width = _check_width(line_width, rule)
    trace, subpixel_bits = as_bool("trace", trace), check_bits(subpixel_bits)
    ends = np.stack([as_finite("p0", p0, (2,)), as_finite("p1", p1, (2,))])
    w, z, attrs = _check_vertex_data(w, z, attrs)
    snapped = snap(ends, subpixel_bits)
    if line_width > 1:
        coverage, line_trace = _wide(snapped, line_width, width, height, subpixel_bits)
    else:
        coverage, line_trace = _thin(snapped, rule, width, height, subpixel_bits, trace)
    values, depth = _interpolate(snapped, coverage, w, z, attrs, interpolation)
    return Fill(coverage=coverage, attrs=values, depth=depth, trace=line_trace if trace else None)


def _thin(snapped, rule, width, height, subpixel_bits, keep_missed):
    """Coverage and trace of a one-pixel line: the rule walks the (clipped) end points."""
    units = _line_units(snapped, subpixel_bits, width, height)
    if units is None:  # an unsnapped line that misses the image and its margin
        steps = empty_steps(major_axis(snapped[1] - snapped[0]))
    else:
        unit = units_per_pixel(subpixel_bits)
        steps = RULE_FUNCTIONS[rule](units[0], units[1], unit, width, height, keep_missed)
    coverage = np.zeros((height, width), bool)
    coverage[steps.rows[steps.lit], steps.cols[steps.lit]] = True
    size = (width, height)
    return coverage, LineTrace(rule, _pair(snapped[0]), _pair(snapped[1]), size, steps)


def _pair(p) -> tuple[float, float]:
    return float(p[0]), float(p[1])


def _check_width(line_width, rule) -> float:
    line_width = as_float("line_width", line_width)
    if line_width < 1:
        raise ValueError(f"line_width must be >= 1, got {line_width:g}")
    if line_width > 1 and rule != "diamond":
        raise ValueError(
            f"line_width > 1 draws the rectangle as two triangles; rule must be 'diamond', "
            f"got line_width={line_width:g} with rule={rule!r}"
        )
    return line_width


def _check_vertex_data(w, z, attrs):
    w = np.ones(2) if w is None else as_finite("w", w, (2,))
    if (w <= 0).any():
        raise ValueError(f"w must be > 0 at both ends, got {w.tolist()}")
    z = None if z is None else as_finite("z", z, (2,))
    if attrs is None:
        attrs = {}
    if not isinstance(attrs, Mapping):
        raise TypeError(f"attrs must be a mapping of name to (2,) or (2, k), got {type(attrs)}")
    checked = {}
    for name, value in attrs.items():
        value = as_finite(f"attrs[{name!r}]", value, None)
        if value.ndim not in (1, 2) or value.shape[0] != 2:
            raise ValueError(f"attrs[{name!r}] must have shape (2,) or (2, k), got {value.shape}")
        checked[name] = value
    return w, z, checked


#: Margin (px) of the box an unsnapped one-pixel line is clipped to: the clipped ends' own
#: diamonds then lie outside the image, so clipping changes no pixel of the image.
CLIP_MARGIN = 2.0


def _line_units(snapped: np.ndarray, subpixel_bits, width: int, height: int):
    """End points in internal units for the rule, or None when there is nothing to walk.

    Snapped ends are refused (naming p0 or p1) beyond the exact range; unsnapped ones are
    clipped exactly to a box around the image (:mod:`.line_clip`), where doubles still
    resolve a pixel's fraction.
    """
    if subpixel_bits is None:
        clipped = clip_to_box(snapped, width, height, CLIP_MARGIN)
        return None if clipped is None else [tuple(float(v) for v in u) for u in clipped]
    _check_ends(snapped, LINE_UNIT_LIMIT / units_per_pixel(subpixel_bits), subpixel_bits)
    return [tuple(int(v) for v in u) for u in to_units(snapped, subpixel_bits)]


def _check_ends(snapped: np.ndarray, limit: float, subpixel_bits) -> None:
    """Raise, naming p0 or p1, when an end lies ``limit`` px or more from the origin."""
    for k, name in enumerate(("p0", "p1")):
        if np.abs(snapped[k]).max() >= limit:
            raise ValueError(
                f"{name}: line end points beyond ±{limit:g} px cannot be rasterised "
                f"exactly with {subpixel_bits} sub-pixel bits; clip the line first"
            )


def _check_rectangle(tris: np.ndarray, line_width: float, subpixel_bits) -> None:
    """Raise, naming line_width, p0 and p1, when the wide line's rectangle leaves the range
    the triangle fill handles (its corners go through the same snap as any triangle's)."""
    limit = FLOAT_LIMIT if subpixel_bits is None else UNIT_LIMIT / units_per_pixel(subpixel_bits)
    reach = float(np.abs(snap(tris.reshape(-1, 2), subpixel_bits)).max(initial=0.0))
    if not reach < limit:
        raise ValueError(
            f"line_width: a line {line_width:g} px wide around p0 → p1 reaches {reach:g} px "
            f"from the origin, beyond the ±{limit:g} px its two triangles can be filled in "
            f"with subpixel_bits={subpixel_bits}; draw it narrower or clip p0, p1 first"
        )


def wide_line_triangles(p0, p1, line_width: float, shape: str = "rectangle") -> np.ndarray:
    """(2, 3, 2): a wide line as two triangles sharing the diagonal p0 + n → p1 - n.

    ``shape="rectangle"`` (CONVENTIONS, what ``rasterize_line`` fills): n is the half-width
    normal of the segment. ``shape="gl"``: GL's aliased wide line (GL 4.6 §14.5.2.2 *Wide Lines*), the
    parallelogram offset by half the width along the *minor* axis only (n = (0, w/2) for an
    x-major line), which is what llvmpipe fills. Empty for a zero-length line.
    """
    check_choice("shape", shape, ("rectangle", "gl"))
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    d = p1 - p0
    length = float(np.hypot(*d))
    if length == 0:
        return np.zeros((0, 3, 2))
    if shape == "gl":
        n = (
            np.array([0.0, line_width / 2])
            if abs(d[0]) >= abs(d[1])
            else np.array([line_width / 2, 0.0])
        )
    else:
        n = np.array([-d[1], d[0]]) * (line_width / 2 / length)
    c = [p0 + n, p1 + n, p1 - n, p0 - n]
    return np.array([[c[0], c[1], c[2]], [c[0], c[2], c[3]]])


def _wide(snapped, line_width, width, height, subpixel_bits):
    """Coverage and trace of a wide line: the rectangle as two triangles, top-left rule.

    Snapped ends are checked like a one-pixel line's against the triangle range; an
    unsnapped segment is first clipped to a box that still holds every part of the
    rectangle over the image (a margin of half the width and more).
    """
    segment = snapped
    if subpixel_bits is None:
        segment = clip_to_box(snapped, width, height, line_width / 2 + CLIP_MARGIN)
    else:
        _check_ends(snapped, UNIT_LIMIT / units_per_pixel(subpixel_bits), subpixel_bits)
    tris = np.zeros((0, 3, 2)) if segment is None else wide_line_triangles(*segment, line_width)
    _check_rectangle(tris, line_width, subpixel_bits)
    halves = [
        rasterize(Triangle(t), width, height, subpixel_bits=subpixel_bits).coverage for t in tris
    ]
    while len(halves) < 2:
        halves.append(np.zeros((height, width), bool))
    coverage = halves[0] | halves[1]
    return coverage, LineTrace("diamond", _pair(snapped[0]), _pair(snapped[1]),
                               (width, height), None, (halves[0], halves[1]))  # fmt: skip


def line_parameter(p0, p1, rows, cols) -> np.ndarray:
    """t of each pixel centre's projection onto p0 → p1, clamped to [0, 1] (GL's t, clamped
    so that a lit pixel always gets a convex combination of the end values).

    t is a ratio, so both of its vectors are first scaled by one power of two (exact) that
    brings the direction's largest component into [0.5, 1): no product overflows however
    far apart the ends lie (up to the float maximum).

    >>> line_parameter((0.5, 0.5), (4.5, 0.5), np.array([0, 0]), np.array([2, 9]))
    array([0.5, 1. ])
    """
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    with np.errstate(over="ignore"):
        d = p1 - p0
    halve = not np.isfinite(d).all()  # ends of opposite signs near the float maximum
    if halve:
        d = p1 / 2 - p0 / 2
    peak = np.abs(d).max()
    if peak == 0:
        return np.zeros(len(rows))
    shift = -int(np.frexp(peak)[1]) - halve
    d = np.ldexp(d, -int(np.frexp(peak)[1]))
    qx, qy = np.ldexp(cols + 0.5 - p0[0], shift), np.ldexp(rows + 0.5 - p0[1], shift)
    t = (qx * d[0] + qy * d[1]) / float(d @ d)
    return np.clip(t, 0.0, 1.0)


def _interpolate(snapped, coverage, w, z, attrs, interpolation):
    """Attributes and depth at the lit centres, by the triangles' own rule
    (:func:`~teachraster.core.interpolation.interpolate`): the line is the degenerate
    triangle (p0, p1, p1) with barycentrics (1 - t, t, 0), so the ratios of w, not 1/w
    itself, weigh the ends (finite for a subnormal w) and the values stay in their range.
    """
    rows, cols = np.nonzero(coverage)
    t = line_parameter(snapped[0], snapped[1], rows, cols)
    lam = np.stack([1 - t, t, np.zeros_like(t)], axis=1)
    w3 = np.array([w[0], w[1], w[1]])
    values = {}
    for name, value in attrs.items():
        image = np.full(coverage.shape + value.shape[1:], np.nan)
        image[rows, cols] = interpolate(lam, _three(value), w3, interpolation)
        values[name] = image
    depth = None
    if z is not None:  # window depth is affine in screen space
        depth = np.full(coverage.shape, np.nan)
        depth[rows, cols] = interpolate(lam, _three(z), w3, "affine")
    return values, depth


def _three(value: np.ndarray) -> np.ndarray:
    """End values (2, ...) as the degenerate triangle's (p0, p1, p1)."""
    return np.concatenate([value, value[1:]])
