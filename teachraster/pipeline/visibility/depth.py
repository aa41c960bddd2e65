"""Depth mappings and depth-buffer precision: why distant surfaces z-fight (Ritschel, *Interpolation and z-buffering*).

Ritschel's (*Interpolation and z-buffering*) z-buffer keeps, per pixel, the depth of the nearest fragment so far and warns that a
"z-buffer can be inaccurate with few bits" ("aliasing on depth", z-buffer tearing). Which depth
is stored matters as much as how many bits store it:

- **view distance** ``z`` (> 0 in front of the eye) is what the seed's pseudo-code compares, but
  it is *not* affine in screen space (Ritschel, *Interpolation and z-buffering*: interpolate 1/z, not z), so GPUs do not store it;
- the CS148 rasterisation notes' ``z' = n + f - f n / z`` (*Overlapping Triangles* and *Depth*;
  :func:`seed_depth`) is affine in ``1/z`` and therefore affine in screen space, maps
  ``near -> near`` and ``far -> far`` and keeps the depth order;
- the **window depth** of OpenGL, :func:`window_depth`, is the same hyperbola rescaled to
  [0, 1]: ``(z' - n) / (f - n) = (f / (f - n)) (1 - n / z)``. This is what CONVENTIONS' ``z_win``
  holds and what a real depth buffer stores;
- :func:`linear_depth` ``(z - n) / (f - n)`` is the comparison case with even resolution;
- :func:`reversed_depth` ``1 - window_depth``, computed without that subtraction, is
  **reverse-Z**: near -> 1, far -> 0, the larger value wins the depth test. In ``float32`` it
  puts the dense floats near 0 where the hyperbola is flat (far away), which nearly evens out
  the resolution.

:func:`depth_bias` is Direct3D's / OpenGL's polygon offset (``DepthBias`` and
``SlopeScaledDepthBias``, ``glPolygonOffset(factor, units)``): a per-triangle offset added to
the window depth, negative on a decal lying on a wall so that it wins the "less" test (or
positive on the wall); :func:`max_depth_slope` gives the
slope term and :func:`offset_clip_depth` applies a window-depth offset to clip-space triangles.

Because the hyperbola flattens out with distance, one step of a 16- or 24-bit buffer spans a
width in ``z`` that grows like ``z**2`` (:func:`depth_resolution`): two surfaces a fixed
distance apart are told apart near the camera and collapse to the same stored value far away,
where they z-fight (:func:`fights`).

>>> near, far = 0.1, 1000.0
>>> fights([2.0, 500.0], [2.5, 500.5], near, far, "unorm16")
array([False,  True])
"""

from __future__ import annotations

import numpy as np

from ...core.validate import as_float, as_real, check_choice

DEPTH_FORMATS = ("float64", "float32", "unorm24", "unorm16")
MAPPINGS = ("perspective", "linear", "reversed")

_UNORM_BITS = {"unorm24": 24, "unorm16": 16}


def quantize(depth, fmt: str) -> np.ndarray:
    """The value a depth buffer of format ``fmt`` stores for ``depth``, as float64.

    Parameters
    ----------
    depth : array-like
        Window depths, normally in [0, 1]; NaN (no fragment) stays NaN.
    fmt : {"float64", "float32", "unorm24", "unorm16"}
        ``float32`` rounds to the nearest float32 (``GL_DEPTH_COMPONENT32F``). ``unormB`` stores
        the integer ``round(d (2**B - 1))`` (round half to even) and reads back that integer
        divided by ``2**B - 1`` (``GL_DEPTH_COMPONENT24`` / ``16``); a unorm buffer cannot
        hold anything outside [0, 1], so depth is clamped to [0, 1] first, as GL does for
        fixed-point depth buffers. ``float64`` returns a copy unchanged.

    Returns
    -------
    float64 ndarray, same shape as ``depth``
        Always a new array, 0-d for a scalar (the caller may write into it).

    Examples
    --------
    >>> quantize([0.25, 1.0, np.nan], "unorm16")       # 0.25 * 65535 = 16383.75 -> 16384
    array([0.250004, 1.      ,      nan])
    >>> quantize([0.1], "float32") - 0.1
    array([1.49...e-09])
    """
    check_choice("fmt (the depth_format)", fmt, DEPTH_FORMATS)
    if isinstance(depth, np.ndarray) and depth.dtype == np.float64:
        d = depth  # the z-buffer's own arrays: no check, no copy (runs per fragment batch)
    else:
        d = as_real("depth", depth)
    if fmt == "float64":
        return d.copy() if d is depth else d
    if fmt == "float32":
        return d.astype(np.float32).astype(np.float64)
    scale = float(2 ** _UNORM_BITS[fmt] - 1)
    # In place on one fresh array: this runs once per fragment batch in the z-buffer, so avoid
    # temporaries. rint rounds half to even; NaN passes through clip and rint unchanged.
    out = np.empty(d.shape)
    np.clip(d, 0.0, 1.0, out=out)
    out *= scale
    np.rint(out, out=out)
    out /= scale
    return out


def window_depth(z_view, near: float, far: float) -> np.ndarray:
    """OpenGL window depth in [0, 1] of points at view distance ``z_view`` (near -> 0, far -> 1).

    The perspective projection (``glFrustum`` / ``gluPerspective``) gives NDC depth
    ``(f + n)/(f - n) - 2 f n / ((f - n) z)``; the viewport's ``z/2 + 1/2`` (CONVENTIONS) turns
    that into ``(f / (f - n)) (1 - n / z)``.

    Parameters
    ----------
    z_view : array-like
        Distance in front of the eye along the view axis (> 0; NaN passes through). Points
        nearer than ``near`` give negative depth and points beyond ``far`` depth above 1: the
        near and far clip planes remove them.
    near, far : float
        Clip-plane distances, 0 < near < far.

    Returns
    -------
    float64 ndarray

    Examples
    --------
    >>> window_depth([0.5, 1.0, 2.0], 0.5, 2.0)
    array([0.    , 0.6667, 1.    ])
    """
    near, far = _planes(near, far, positive=True)
    z = _distances("z_view", z_view, positive=True)
    # Written as (1 - n/z) / (1 - n/f): mathematically f (z - n) / (z (f - n)), but in floating
    # point every step is monotonic in z, so depth order is never reversed by rounding, and
    # z = near gives exactly 0 and z = far exactly 1 (same expression above and below the bar).
    # A distance far inside the near plane (a subnormal z) sends near / z to inf: the limit, -inf
    # window depth, is the right answer (clipped away, or clamped by a unorm buffer), not an error.
    with np.errstate(over="ignore"):
        return (1.0 - near / z) / (1.0 - near / far)


def seed_depth(z, near: float, far: float) -> np.ndarray:
    """The CS148 notes' ``z' = n + f - f n / z``: the perspective depth in view-distance units.

    The formula is the CS148 rasterisation notes' (*Overlapping Triangles*: "the screen space
    projection computes z' = n + f - (fn/z)"; *Depth*: its inverse per vertex). ``z'`` is
    affine in ``1/z``, so it may be interpolated affinely in screen space (Ritschel,
    *Interpolation and z-buffering*, eq. 12: what is affine on the screen is ``1/z``), unlike
    ``z`` itself; it maps near to near and far to far and preserves order.

    Parameters
    ----------
    z : array-like
        View distances (> 0).
    near, far : float
        0 < near < far.

    Examples
    --------
    >>> seed_depth([1.0, 2.0, 4.0], 1.0, 4.0)      # 5 - 4/z
    array([1., 3., 4.])
    """
    near, far = _planes(near, far, positive=True)
    z = _distances("z", z, positive=True)
    # n + (f - n) * window_depth equals n + f - fn/z exactly in real numbers; in floating point
    # it inherits window_depth's monotonicity and gives exactly n at z = n (and f at z = f up
    # to one rounding of n + (f - n)), where the literal formula drifts by a few ulps.
    return near + (far - near) * window_depth(z, near, far)


def reversed_depth(z_view, near: float, far: float) -> np.ndarray:
    """Reverse-Z window depth in [0, 1]: near -> 1, far -> 0, **larger is nearer**.

    Mathematically ``1 - window_depth(z)``, i.e. ``(n / z - n / f) / (1 - n / f)``, but
    computed in that second form: ``1 - d`` would round away exactly the precision reverse-Z
    is for. With a ``float32`` buffer (``GL_DEPTH_COMPONENT32F`` with ``glClipControl(...,
    GL_ZERO_TO_ONE)`` and ``glDepthFunc(GL_GREATER)``; Direct3D with ``D3D11_COMPARISON_GREATER``),
    far-away depths land near 0, where floats are densest, and the resolution in ``z`` is
    nearly proportional to ``z`` instead of ``z**2``.

    Parameters
    ----------
    z_view : array-like
        View distances (> 0).
    near, far : float
        0 < near < far.

    Examples
    --------
    >>> reversed_depth([0.5, 1.0, 2.0], 0.5, 2.0)
    array([1.    , 0.3333, 0.    ])
    """
    near, far = _planes(near, far, positive=True)
    z = _distances("z_view", z_view, positive=True)
    with np.errstate(over="ignore"):  # as in window_depth: a subnormal z gives +inf, the limit
        return (near / z - near / far) / (1.0 - near / far)


def linear_depth(z, near: float, far: float) -> np.ndarray:
    """``(z - near) / (far - near)``: depth linear in view distance, the even-resolution baseline.

    Parameters
    ----------
    z : array-like
        View distances.
    near, far : float
        near < far (near may be 0 or negative: this is also an orthographic camera's depth).

    Examples
    --------
    >>> linear_depth([1.0, 2.5, 4.0], 1.0, 4.0)
    array([0. , 0.5, 1. ])
    """
    near, far = _planes(near, far, positive=False)
    z = _distances("z", z, positive=False)
    return (z - near) / (far - near)


def depth_resolution(z, near: float, far: float, fmt: str, mapping: str = "perspective"):
    """Smallest change in view distance at ``z`` that changes the stored depth (to first order).

    One step of the buffer, ``step(d)``, divided by how fast the mapped depth ``d(z)`` moves:
    ``step / |d'(z)|``. Surfaces closer together than this tend to store the same value and
    z-fight (Ritschel's *Interpolation and z-buffering* depth aliasing).

    - ``perspective`` (:func:`window_depth`): ``d' = f n / ((f - n) z**2)``, so with a fixed step
      the resolution grows like ``z**2``;
    - ``linear`` (:func:`linear_depth`): ``d' = 1 / (f - n)``, the same everywhere;
    - ``reversed`` (:func:`reversed_depth`): the same slope as ``perspective``, but the stored
      values of far points are near 0, where a float's step is small.

    The step is ``1 / (2**B - 1)`` for ``unormB`` and, for ``float32`` / ``float64``, the gap
    from the stored value to its nearer neighbouring float (below it at a power of two, so
    ``2**-24`` for float32 at the far plane's depth 1, like unorm24), so floats resolve more
    finely near depth 0 than near 1.

    Parameters
    ----------
    z : array-like
        View distances (> 0 for the perspective mapping).
    near, far : float
        Clip planes.
    fmt : {"float64", "float32", "unorm24", "unorm16"}
        Depth buffer format.
    mapping : {"perspective", "linear", "reversed"}
        Which depth is stored.

    Returns
    -------
    float64 ndarray
        Distance in the units of ``z``.

    Examples
    --------
    >>> depth_resolution([2.0, 500.0], 0.1, 1000.0, "unorm16")
    array([6.1e-04, 3.81e+01])
    >>> depth_resolution([2.0, 500.0], 0.1, 1000.0, "unorm16", mapping="linear")
    array([0.0153, 0.0153])
    >>> depth_resolution([500.0], 0.1, 1000.0, "float32", mapping="reversed") < 1e-3
    array([ True])
    """
    map_depth, positive = _mapping(mapping)
    near, far = _planes(near, far, positive=positive)
    z = _distances("z", z, positive=positive)
    check_choice("fmt (the depth_format)", fmt, DEPTH_FORMATS)
    # past z ~ 1e154, z**2 overflows: the slope's limit is 0 and the resolution's +inf (the
    # fuzzer drew 1.4e154), returned without a raw numpy warning
    with np.errstate(over="ignore", divide="ignore"):
        if mapping in ("perspective", "reversed"):
            slope = near / ((1.0 - near / far) * z * z)  # = f n / ((f - n) z**2), as window_depth
        else:
            slope = np.full_like(z, 1.0 / (far - near))
        return _step(map_depth(z, near, far), fmt, nearer=True) / slope


def fights(z_a, z_b, near: float, far: float, fmt: str, mapping: str = "perspective"):
    """Predict z-fighting: True where two different distances store equal (or swapped) depths.

    When two surfaces at ``z_a != z_b`` store the same depth, the depth test (strictly smaller
    wins, CONVENTIONS) cannot tell which is in front, and rounding of the interpolated depth
    across the triangles decides pixel by pixel: the stripes of Ritschel's *Interpolation and z-buffering* "z-buffer tearing".
    Equal distances are a tie, not a precision effect, and give False; so does NaN.

    Parameters
    ----------
    z_a, z_b : array-like
        View distances of the two surfaces at the same pixels (broadcast together).
    near, far, fmt, mapping
        As for :func:`depth_resolution`.

    Returns
    -------
    bool ndarray

    Examples
    --------
    >>> fights([100.0, 100.0], [100.5, 100.5], 0.1, 1000.0, "unorm24")
    array([False, False])
    >>> fights([100.0], [100.5], 0.1, 1000.0, "unorm16")
    array([ True])
    """
    map_depth, positive = _mapping(mapping)
    near, far = _planes(near, far, positive=positive)
    a = _distances("z_a", z_a, positive=positive)
    b = _distances("z_b", z_b, positive=positive)
    try:
        a, b = np.broadcast_arrays(a, b)
    except ValueError:
        raise ValueError(
            f"z_a and z_b must broadcast together, got {a.shape} and {b.shape}"
        ) from None
    check_choice("fmt (the depth_format)", fmt, DEPTH_FORMATS)
    qa = quantize(map_depth(a, near, far), fmt)
    qb = quantize(map_depth(b, near, far), fmt)
    real = ~(np.isnan(a) | np.isnan(b)) & (a != b)
    # Every mapping and quantisation is monotonic, so an inversion should never happen; it is
    # checked anyway, because a swapped order would be as visible as a tie. Reverse-Z stores
    # the nearer surface as the larger value.
    order = -1.0 if mapping == "reversed" else 1.0
    wrong = (qa == qb) | (np.sign(order * (qa - qb)) != np.sign(a - b))
    return real & wrong


def max_depth_slope(window) -> np.ndarray:
    """Direct3D's ``MaxDepthSlope`` of each triangle: ``max(|dz/dx|, |dz/dy|)`` in window space.

    Parameters
    ----------
    window : (N, 3, 3) or (3, 3) array-like
        Window-space vertices (x, y in pixels, z the window depth), e.g. from
        :func:`teachraster.pipeline.viewport.to_window`.

    Returns
    -------
    (N,) float64 ndarray (0-d for one triangle); NaN for a zero-area triangle.

    Examples
    --------
    >>> float(max_depth_slope([[0, 0, 0.5], [10, 0, 0.6], [0, 10, 0.5]]))   # 0.01 per pixel in x
    0.01
    """
    v = np.asarray(window, dtype=np.float64)
    if v.shape[-2:] != (3, 3):
        raise ValueError(f"window must have shape (N, 3, 3) or (3, 3), got {v.shape}")
    e1, e2 = v[..., 1, :] - v[..., 0, :], v[..., 2, :] - v[..., 0, :]
    # The plane z = z0 + gx (x - x0) + gy (y - y0) through the three vertices (lesson 03's M).
    det = e1[..., 0] * e2[..., 1] - e2[..., 0] * e1[..., 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        gx = (e2[..., 1] * e1[..., 2] - e1[..., 1] * e2[..., 2]) / det
        gy = (e1[..., 0] * e2[..., 2] - e2[..., 0] * e1[..., 2]) / det
    out = np.maximum(np.abs(gx), np.abs(gy))
    return np.where(det == 0, np.nan, out)


def depth_bias(depth, fmt: str, *, units: float = 0.0, slope: float = 0.0,
               slope_factor: float = 0.0) -> np.ndarray:  # fmt: skip
    """Polygon offset ``o = units * r + slope_factor * slope``, **added** to the window depth.

    The sign is the APIs': OpenGL 4.6 §14.6.5 (*Depth Offset*) adds
    ``o = m * factor + r * units`` (``glPolygonOffset(factor, units)``) to each fragment's
    depth before the depth test, and Direct3D 11 adds
    ``DepthBias * r + SlopeScaledDepthBias * MaxDepthSlope``; both factors may be negative.
    ``r`` is the smallest difference the depth buffer resolves at ``depth``: one step of the
    format (``1 / (2**B - 1)`` for unorm, the float spacing at ``depth`` for floats; Direct3D
    takes the exponent of the triangle's largest depth, which is the same step). With the
    default "less" test (smaller is nearer) a decal drawn on a wall therefore gets **negative**
    factors, ``glPolygonOffset(-1, -1)``: ``units <= -1`` stores it at least one step nearer, so
    it wins instead of z-fighting (positive factors on the wall do the same; with reverse-Z,
    where larger is nearer, the signs flip). The slope term keeps that true across a steep
    triangle, whose interpolated depths differ by more than one step from pixel to pixel.

    Parameters
    ----------
    depth : array-like
        Stored depth(s) where the offset applies (its step sets ``r``).
    fmt : {"float64", "float32", "unorm24", "unorm16"}
    units, slope_factor : float
        The constant and slope-scaled factors (GL's ``units`` and ``factor``), signed; 0 by
        default, as in GL.
    slope : float or array-like
        :func:`max_depth_slope` of the triangle (depth per pixel, >= 0).

    Returns
    -------
    float64 ndarray: the offset ``o``, to add to the window depth
    (:func:`offset_clip_depth`); negative for negative factors.

    Examples
    --------
    >>> float(depth_bias(0.5, "unorm16", units=-1.0) * 65535)   # a decal: one step nearer
    -1.0
    >>> float(depth_bias(0.5, "float32", units=2.0)) == 2 * float(np.spacing(np.float32(0.5)))
    True
    """
    check_choice("fmt (the depth_format)", fmt, DEPTH_FORMATS)
    d = _distances("depth", depth, positive=False)
    return np.asarray(float(units) * _step(d, fmt) + float(slope_factor) * np.asarray(slope, float))


def offset_clip_depth(clip, offset) -> np.ndarray:
    """Clip-space triangles whose window depth is moved by ``offset`` (per triangle or one).

    Window depth is ``z / (2 w) + 1/2`` (CONVENTIONS), so adding ``2 * offset * w`` to clip
    z moves the window depth of every point of the triangle by exactly ``offset`` and changes
    nothing else: ``x``, ``y`` and ``w`` (hence coverage and interpolation) are untouched. Pass
    ``depth_bias(...)`` as it is, the APIs' polygon offset added to the depth: negative units
    pull a decal nearer (smaller is nearer).

    Parameters
    ----------
    clip : (N, 3, 4) array-like
        Clip-space triangles.
    offset : float or (N,) array-like
        Window-depth offset of each triangle.

    Examples
    --------
    >>> out = offset_clip_depth([[[0, 0, 0.0, 2], [1, 0, 0.0, 2], [0, 1, 0.0, 2]]], -0.25)
    >>> out[0, :, 2] / out[0, :, 3] / 2 + 0.5          # window depth 0.5 -> 0.25
    array([0.25, 0.25, 0.25])
    """
    c = np.array(clip, dtype=np.float64)
    if c.ndim != 3 or c.shape[1:] != (3, 4):
        raise ValueError(f"clip must have shape (N, 3, 4), got {c.shape}")
    off = np.broadcast_to(np.asarray(offset, dtype=np.float64), (c.shape[0],))
    c[..., 2] += 2.0 * off[:, None] * c[..., 3]
    return c


# -- helpers ----------------------------------------------------------------------------------
def _step(d: np.ndarray, fmt: str, *, nearer: bool = False) -> np.ndarray:
    """One step of the stored depth at ``d``: the gap between neighbouring storable values.

    For floats, the gap up to the next float (the ``2**(e - 23)`` of glPolygonOffset's ``r``),
    or with ``nearer`` the gap to the nearer neighbour, below ``d`` at a power of two.
    """
    if fmt in _UNORM_BITS:
        return np.full_like(d, 1.0 / (2 ** _UNORM_BITS[fmt] - 1))
    dtype = np.float32 if fmt == "float32" else np.float64
    x = d.astype(dtype)
    # np.spacing is signed (negative below 0); the step size is its magnitude.
    above = np.abs(np.spacing(x))
    if nearer:
        # At d = 1 (the far plane) the float above lies outside the depth range [0, 1]: a
        # surface just in front of the far plane rounds to 1 - 2**-24, not to 1 + 2**-23.
        above = np.minimum(above, np.abs(x - np.nextafter(x, dtype(-np.inf))))
    return above.astype(np.float64)


def _mapping(mapping: str):
    """The depth function for ``mapping`` and whether it needs z > 0."""
    if mapping == "perspective":
        return window_depth, True
    if mapping == "linear":
        return linear_depth, False
    if mapping == "reversed":
        return reversed_depth, True
    raise ValueError(f"mapping must be one of {MAPPINGS}, got {mapping!r}")


def _planes(near, far, *, positive: bool) -> tuple[float, float]:
    """Validated ``near`` and ``far`` as floats; errors name the argument."""
    out = []
    for name, value in (("near", near), ("far", far)):
        out.append(as_float(name, value))
    n, f = out
    if positive and n <= 0:
        raise ValueError(
            f"near must be > 0 for a perspective depth (1/z blows up at the eye), got {n}"
        )
    if f <= n:
        raise ValueError(f"far must be > near, got near={n}, far={f}")
    return n, f


def _distances(name: str, z, *, positive: bool) -> np.ndarray:
    """``z`` as a float64 array; with ``positive``, every non-NaN value must be > 0."""
    arr = as_real(name, z)
    if positive and (arr <= 0).any():
        raise ValueError(
            f"{name} must be > 0 (in front of the eye); a point at or behind the eye has no "
            f"perspective depth -- clip against the near plane first. Got min {np.nanmin(arr)}"
        )
    return arr
