"""2×2 quads and screen-space derivatives: why GPUs shade pixels four at a time.

A texture filter needs the size of the pixel's footprint on the texture, that is the
derivatives ∂(u, v)/∂x and ∂(u, v)/∂y. A GPU has no formula for them: it shades pixels in
2×2 *quads* (aligned to even rows and columns) and takes differences between neighbours
(CONVENTIONS, "Quads, derivatives and level of detail"):

- *coarse* (the default, one pair per quad, as llvmpipe does): ``ddx`` = upper-right −
  upper-left, ``ddy`` = lower-left − upper-left (y down);
- *fine*: each pixel uses its own row for ``ddx`` and its own column for ``ddy``.

Quad pixels the triangle does not show (outside it, or hidden) are *helper pixels*: they are
evaluated on the triangle's own perspective-correct interpolation, **extrapolated and never
clamped** (:func:`extrapolate`), used only for the differences, never written. Each triangle
uses its own helpers, so a quad straddling two triangles is evaluated twice.

Beyond a triangle's horizon its interpolated 1/w is ≤ 0 and an extrapolated value means
nothing; a difference that would use such a helper is taken from the other row (or column)
of the quad instead, whose pixels all have 1/w > 0 (covered ones always do), and, if neither
has, from the exact derivative at the pixel's centre (:func:`exact_derivatives`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...core.interpolation import huge_exponents
from ..planning.render_plan import derivatives_effect

#: ``derivatives=`` choices; ``True`` means "coarse".
DERIVATIVE_MODES = ("coarse", "fine")
#: Lanes of a quad, in this order: (column offset, row offset).
LANES = ((0, 0), (1, 0), (0, 1), (1, 1))  # upper-left, upper-right, lower-left, lower-right


@dataclass(frozen=True)
class QuadTrace:
    """The quads ``render`` evaluated for derivatives: one row per (quad, triangle) pair.

    Attributes
    ----------
    row, col : (q,) int64
        The quad's upper-left pixel (both even).
    triangle : (q,) int64
        The input triangle whose interpolation the quad evaluated.
    shaded : (q, 4) bool
        Lanes (upper-left, upper-right, lower-left, lower-right) the triangle shows; the
        others are helper pixels.
    inv_w : (q, 4) float64
        The triangle's interpolated 1/w at each lane, relative to its nearest vertex
        (``min w / w``): ≤ 0 beyond its horizon. 1 for affine interpolation.
    values : (q, 4, k) float64
        The attributes at each lane, extrapolated at helpers, never clamped.
    fallback : (q,) bool
        Quads where a lane the differences prefer lies beyond the horizon (1/w ≤ 0), so some
        difference was taken elsewhere.
    """

    row: np.ndarray
    col: np.ndarray
    triangle: np.ndarray
    shaded: np.ndarray
    inv_w: np.ndarray
    values: np.ndarray
    fallback: np.ndarray

    @property
    def helpers(self) -> int:
        """How many helper pixels were evaluated."""
        return int((~self.shaded).sum())


@dataclass(frozen=True)
class AttributePlanes:
    """Per triangle, f/w and 1/w as affine functions of the window position (Ek, *Triangles
    and Perspective Correct Interpolation*, eq. 19), anchored at vertex 0 for precision.

    ``num(p) = num0 + (p - anchor) @ num_grad`` (M, k) is Σ λ_i f_i s_i and
    ``den(p) = den0 + (p - anchor) @ den_grad`` (M,) is Σ λ_i s_i, with s_i = min w / w_i
    (1 for affine interpolation): the attribute is ``num / den`` anywhere in the plane,
    inside the triangle or not, and ``den`` is 1/w relative to the nearest vertex.
    """

    anchor: np.ndarray
    num0: np.ndarray
    num_grad: np.ndarray
    den0: np.ndarray
    den_grad: np.ndarray


def attribute_planes(xy, w, attrs, perspective: bool) -> AttributePlanes:
    """:class:`AttributePlanes` of triangles ``xy`` (M, 3, 2), ``w`` (M, 3), ``attrs`` (M, 3, k).

    ``xy`` are the positions the rasteriser sets its weights up from
    (:attr:`teachraster.pipeline.batched_fill.Fragments.vertices`: the unsnapped window
    positions in ``render``), so helpers extrapolate exactly the covered pixels' functions.
    A zero-area triangle (it covers nothing) gets NaN planes.
    """
    xy = np.asarray(xy, dtype=np.float64)
    area = (xy[:, 1, 0] - xy[:, 0, 0]) * (xy[:, 2, 1] - xy[:, 0, 1]) - (
        xy[:, 1, 1] - xy[:, 0, 1]
    ) * (xy[:, 2, 0] - xy[:, 0, 0])
    area = np.where(area == 0, np.nan, area)
    # ∇λ_k = perpendicular of the opposite edge over twice the area.
    grad = np.empty((len(xy), 3, 2))
    for k in range(3):
        a, b = xy[:, (k + 1) % 3], xy[:, (k + 2) % 3]
        grad[:, k, 0] = -(b[:, 1] - a[:, 1]) / area
        grad[:, k, 1] = (b[:, 0] - a[:, 0]) / area
    s = w.min(axis=1, keepdims=True) / w if perspective else np.ones_like(w)
    sg = grad * s[:, :, None]  # (M, 3, 2): gradients of λ_i s_i
    return AttributePlanes(
        anchor=xy[:, 0],
        num0=attrs[:, 0] * s[:, 0:1],  # at vertex 0: λ = (1, 0, 0)
        num_grad=np.einsum("mia,mik->mak", sg, attrs),
        den0=s[:, 0],
        den_grad=sg.sum(axis=1),
    )


def extrapolate(planes: AttributePlanes, tri, x, y):
    """Attributes (n, k) and relative 1/w (n,) of triangles ``tri`` at points (x, y): no clamp.

    Unlike the clamped evaluation at covered centres (:mod:`teachraster.core.interpolation`),
    a helper pixel must keep its overshoot: it is what the difference measures. Beyond the
    triangle's horizon the returned 1/w is ≤ 0 and the value meaningless.

    >>> planes = attribute_planes(np.array([[[0.0, 0], [4, 0], [0, 4]]]), np.ones((1, 3)),
    ...                           np.array([[[0.0], [1.0], [0.0]]]), True)
    >>> extrapolate(planes, np.array([0]), np.array([6.0]), np.array([0.0]))   # outside
    (array([[1.5]]), array([1.]))
    """
    dx, dy = x - planes.anchor[tri, 0], y - planes.anchor[tri, 1]
    num = (
        planes.num0[tri]
        + dx[:, None] * planes.num_grad[tri, 0]
        + dy[:, None] * planes.num_grad[tri, 1]
    )
    den = planes.den0[tri] + dx * planes.den_grad[tri, 0] + dy * planes.den_grad[tri, 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        return num / den[:, None], den


def exact_derivatives(planes: AttributePlanes, tri, x, y):
    """The exact ∂f/∂x and ∂f/∂y (n, k) of the interpolated attribute at points (x, y).

    f = N / D with N and D affine: f' = (N' − f D') / D.
    """
    f, den = extrapolate(planes, tri, x, y)
    return tuple(
        (planes.num_grad[tri, a] - f * planes.den_grad[tri, a, None]) / den[:, None]
        for a in range(2)
    )


def lane_values(planes: AttributePlanes, tris, q_row, q_col, lanes=(0, 1, 2, 3)):
    """Attributes (one (n, k) array per lane in ``lanes``, None for the others) and relative
    1/w (4 arrays (n,)) at the lanes of quads whose upper-left pixel is (q_row, q_col), on
    triangles ``tris``; extrapolated, unclamped.

    The upper-left lane from the planes, the others one gradient step away (f/w and 1/w are
    affine, so this is exact up to rounding).
    """
    dx = q_col + 0.5 - planes.anchor[tris, 0]
    dy = q_row + 0.5 - planes.anchor[tris, 1]
    ngx, ngy = planes.num_grad[tris, 0], planes.num_grad[tris, 1]
    dgx, dgy = planes.den_grad[tris, 0], planes.den_grad[tris, 1]
    num = planes.num0[tris] + dx[:, None] * ngx + dy[:, None] * ngy
    den = planes.den0[tris] + dx * dgx + dy * dgy
    steps = ((0, 0), (1, 0), (0, 1), (1, 1))
    dens = [den + sx * dgx + sy * dgy if sx or sy else den for sx, sy in steps]
    vals = [None] * 4
    with np.errstate(divide="ignore", invalid="ignore"):
        for lane in lanes:
            sx, sy = steps[lane]
            n = num + (ngx if sx else 0.0) + (ngy if sy else 0.0)
            vals[lane] = n / dens[lane][:, None]
    return vals, dens


def quad_derivatives(rows, cols, tris, planes: AttributePlanes, mode: str, pairs):
    """Derivatives (v, k) at visible pixels ``rows``, ``cols`` of (post-clip) triangles ``tris``.

    ``pairs`` is :func:`quad_pairs` of these pixels: each (quad, triangle) pair is evaluated
    once, on its own triangle (so quads straddling two triangles get each triangle's helpers).
    Returns ``ddx``, ``ddy`` and (v,) bool: the pixels whose difference had to avoid a helper
    beyond the horizon.
    """
    q_row, q_col, q_tri, _, pixel_pair = pairs
    coarse = mode == "coarse"
    vals, dens = lane_values(planes, q_tri, q_row, q_col, (0, 1, 2) if coarse else (0, 1, 2, 3))
    ok = [d > 0 for d in dens]
    if coarse and ok[0].all() and ok[1].all() and ok[2].all():  # the usual case: no horizon
        return (vals[1] - vals[0])[pixel_pair], (vals[2] - vals[0])[pixel_pair], \
            np.zeros(len(rows), dtype=bool)  # fmt: skip
    if coarse:  # some quads must use their lower row or right column
        vals, _ = lane_values(planes, q_tri, q_row, q_col)
        own_row = own_col = np.zeros(len(rows), dtype=np.intp)
    else:
        own_row, own_col = rows % 2, cols % 2
    vals = [v[pixel_pair] for v in vals]  # per pixel from here on
    ok = [o[pixel_pair] for o in ok]
    ddx, moved_x, bad_x = _difference(vals, ok, own_row, ((0, 1), (2, 3)))
    ddy, moved_y, bad_y = _difference(vals, ok, own_col, ((0, 2), (1, 3)))
    stuck = np.flatnonzero(bad_x | bad_y)
    if len(stuck):  # no row (or column) of the quad is wholly in front of the horizon
        ex, ey = exact_derivatives(planes, tris[stuck], cols[stuck] + 0.5, rows[stuck] + 0.5)
        ddx[stuck] = np.where(bad_x[stuck, None], ex, ddx[stuck])
        ddy[stuck] = np.where(bad_y[stuck, None], ey, ddy[stuck])
    return ddx, ddy, moved_x | moved_y


def _difference(vals, ok, first, lanes):
    """Per pixel, the difference along its preferred row/column (``first``: 0 or 1) when both
    ends are in front of the horizon, else along the other one; and whether it moved, and
    whether neither was usable."""
    (a0, b0), (a1, b1) = lanes
    good0, good1 = ok[a0] & ok[b0], ok[a1] & ok[b1]
    mine = np.where(first == 0, good0, good1)
    theirs = np.where(first == 0, good1, good0)
    second = np.where(mine, first == 1, first == 0)
    out = np.where(second[:, None], vals[b1] - vals[a1], vals[b0] - vals[a0])
    return out, ~mine, ~(mine | theirs)


def quad_pairs(rows, cols, tris, width: int, height: int):
    """Every (quad, triangle) pair among pixels ``rows``, ``cols`` shown by ``tris``.

    Returns the pairs' quad upper-left rows and columns, triangles, (q, 4) shaded lanes (the
    other lanes of a pair are its helper pixels) and, per pixel, the index of its pair. A
    quad grid instead of a sort: each quad's four lanes are compared with each other.
    """
    qw = (width + 1) // 2
    quad = (rows // 2) * qw + cols // 2
    grid = np.full((((height + 1) // 2) * qw, 4), -1, dtype=np.int64)
    grid[quad, (rows % 2) * 2 + cols % 2] = tris
    occupied = np.flatnonzero((grid >= 0).any(axis=1))
    lanes = grid[occupied]
    starts = []  # a pair starts at its triangle's first lane in the quad
    for j in range(4):
        first = lanes[:, j] >= 0
        for i in range(j):
            first &= lanes[:, i] != lanes[:, j]
        starts.append(first)
    pos = np.concatenate([np.flatnonzero(f) for f in starts])  # into `occupied`
    start_lane = np.concatenate([np.full(int(f.sum()), j) for j, f in enumerate(starts)])
    tri = lanes[pos, start_lane]
    order = np.lexsort((tri, occupied[pos]))
    pos, start_lane, tri = pos[order], start_lane[order], tri[order]
    quad_id = occupied[pos]
    pair_at = np.full(grid.shape, -1, dtype=np.int64)  # pair index at each start lane
    pair_at[quad_id, start_lane] = np.arange(len(pos))
    # Each pixel's pair starts at the first lane of its quad holding its own triangle.
    first_lane = (grid[quad] == tris[:, None]).argmax(axis=1)
    pixel_pair = pair_at[quad, first_lane]
    shaded = grid[quad_id] == tri[:, None]
    return (quad_id // qw) * 2, (quad_id % qw) * 2, tri, shaded, pixel_pair


def shared_quad_pairs(rows, cols, tris, width: int, height: int):
    """:func:`quad_pairs` for pixels that may show several triangles (MSAA: a pixel shades
    once for every triangle that covers one of its samples).

    Each (pixel, triangle) pair is a lane of that triangle's quad; the same tuple as
    :func:`quad_pairs`, pairs sorted by quad then triangle.

    >>> rows, cols, tris = np.array([0, 0, 1]), np.array([0, 0, 1]), np.array([3, 5, 3])
    >>> q_row, q_col, q_tri, shaded, pixel_pair = shared_quad_pairs(rows, cols, tris, 4, 4)
    >>> q_tri.tolist(), shaded.astype(int).tolist(), pixel_pair.tolist()
    ([3, 5], [[1, 0, 0, 1], [1, 0, 0, 0]], [0, 1, 0])
    """
    qw = (width + 1) // 2
    quad = (rows // 2) * qw + cols // 2
    n_tri = int(tris.max()) + 1 if len(tris) else 1
    keys, pixel_pair = np.unique(quad * n_tri + tris, return_inverse=True)
    quad_id, tri = keys // n_tri, keys % n_tri
    shaded = np.zeros((len(keys), 4), dtype=bool)
    shaded[pixel_pair, (rows % 2) * 2 + cols % 2] = True
    return (quad_id // qw) * 2, (quad_id % qw) * 2, tri, shaded, pixel_pair.ravel()


def as_derivative_mode(derivatives) -> str | None:
    """``derivatives=`` as None (not asked), "coarse" or "fine"; ValueError naming it."""
    # One rule for flags (core.validate.as_bool): numpy's bools are bools too.
    if derivatives is None or (isinstance(derivatives, bool | np.bool_) and not derivatives):
        return None
    if isinstance(derivatives, bool | np.bool_):
        return "coarse"
    if isinstance(derivatives, str) and derivatives in DERIVATIVE_MODES:
        return derivatives
    raise ValueError(f"derivatives must be False, True, 'coarse' or 'fine'; got {derivatives!r}")


def derivatives_stage(frags, visible, clipped, size, mode, where, interpolation, forced, trace):
    """7. Quad derivatives of the attributes at the visible pixels that need them.

    ``mode`` None skips the stage unless "derivatives" is in ``forced`` (then "coarse");
    ``where`` (M,) bool, over triangles after clipping, limits it to the triangles that need
    derivatives (all when None, or when forced). Returns ``ddx``, ``ddy`` (v, k) with NaN at
    the pixels skipped (or None when the stage did not run), the :class:`QuadTrace` (when
    ``trace``) and the "derivatives" effect.
    """
    width, height = size
    force = "derivatives" in forced
    mode = mode or ("coarse" if force else None)
    n_visible = len(visible.pixels)
    if mode is None:
        return None, None, None, derivatives_effect(None, 0, n_visible, 0, 0, 0, False)
    w, attrs = clipped.clip[:, :, 3], clipped.attrs
    k = attrs.shape[2]
    scale = huge_exponents(attrs)  # (M, k): values near the float maximum, scaled exactly
    attrs = np.ldexp(attrs, -scale[:, None, :]) if scale.any() else attrs
    tris = frags.tri[visible.winner]
    need = np.ones(len(tris), dtype=bool) if where is None or force else where[tris]
    sel = np.flatnonzero(need)
    rows, cols = np.divmod(visible.pixels[sel], width)
    planes = attribute_planes(frags.vertices, w, attrs, interpolation == "perspective")
    pairs = quad_pairs(rows, cols, tris[sel], width, height)
    dx, dy, moved = quad_derivatives(rows, cols, tris[sel], planes, mode, pairs)
    if scale.any():  # back to the caller's scale: ±inf only where the true value overflows
        with np.errstate(over="ignore"):
            dx, dy = (np.ldexp(d, scale[tris[sel]]) for d in (dx, dy))
    if len(sel) == n_visible:
        ddx, ddy = dx, dy
    else:
        ddx = np.full((n_visible, k), np.nan)
        ddy = np.full((n_visible, k), np.nan)
        ddx[sel], ddy[sel] = dx, dy
    q_row, q_col, q_tri, shaded, _ = pairs
    quads = None
    if trace:
        vals, dens = lane_values(planes, q_tri, q_row, q_col)
        vals, inv_w = np.stack(vals, axis=1), np.stack(dens, axis=1)
        with np.errstate(over="ignore"):
            vals = np.ldexp(vals, scale[q_tri][:, None, :]) if scale.any() else vals
        ok = inv_w > 0
        if mode == "coarse":
            fallback = ~(ok[:, 0] & ok[:, 1] & ok[:, 2])
        else:
            fallback = ~ok.all(axis=1)
        quads = QuadTrace(q_row, q_col, clipped.parent[q_tri], shaded, inv_w, vals, fallback)
    n_helpers = int((~shaded).sum())
    effect = derivatives_effect(
        mode, len(sel), n_visible, len(q_row), n_helpers, int(moved.sum()), force
    )
    return ddx, ddy, quads, effect


def may_minify(clip, uv, width: int, height: int, texture_shape) -> np.ndarray:
    """(N,) bool: triangles whose texture could be minified (λ > 0) at some quad pixel.

    A cheap, conservative test that lets the plan skip derivatives for a magnified scene.
    With f = N / D (f/w and 1/w affine), ``∂f/∂x = (N_x D − N D_x) / D²``, whose numerator is
    affine too: over a region its length is at most its largest at the corners, and D² at
    least its smallest. The region is the triangle grown by one pixel each way (helper pixels
    lie there), so a triangle reported False has ρ ≤ 1 at every difference a quad takes.
    Triangles that reach the near plane or behind the eye are reported True.
    """
    clip = np.asarray(clip, dtype=np.float64)
    uv = np.asarray(uv, dtype=np.float64)
    th, tw = texture_shape[:2]
    w = clip[:, :, 3]
    out = np.ones(len(clip), dtype=bool)
    front = (w > 0).all(axis=1) & (np.abs(clip[:, :, 2]) <= w).all(axis=1)
    if not front.any():
        return out
    c, w, uv = clip[front], w[front], uv[front] * np.array([tw, th])  # in texels
    xy = np.stack([(c[..., 0] / w + 1) * width / 2, (1 - c[..., 1] / w) * height / 2], axis=-1)
    planes = attribute_planes(xy, w, uv, True)
    grow = np.array([[-1, -1], [-1, 1], [1, -1], [1, 1]], dtype=np.float64)
    corners = (xy[:, :, None, :] + grow).reshape(len(xy), 12, 2) - planes.anchor[:, None]
    num = planes.num0[:, None] + np.einsum("mpa,mak->mpk", corners, planes.num_grad)
    den = planes.den0[:, None] + np.einsum("mpa,ma->mp", corners, planes.den_grad)
    rho = np.zeros(len(xy))
    for a in range(2):
        numer = (
            planes.num_grad[:, a][:, None] * den[..., None]
            - num * planes.den_grad[:, None, a, None]
        )
        rho = np.maximum(rho, np.linalg.norm(numer, axis=-1).max(axis=1))
    d_min = den.min(axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        bound = np.where(d_min > 0, rho / d_min**2, np.inf)
    out[front] = ~(bound <= 1)
    return out
