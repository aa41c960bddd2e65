"""Homogeneous clipping against the near and far planes, before the divide by w.

A vertex behind the eye has w < 0; dividing by it would mirror the vertex through the
eye, and a vertex near w = 0 would be thrown towards infinity. So, as OpenGL does, each
triangle is clipped in clip space against ``-w <= z <= w`` (Sutherland-Hodgman), where
everything is still linear: a new vertex on an edge is ``v0 + t (v1 - v0)`` with
``t = d0 / (d0 - d1)`` for the signed distances d to the plane, and its attributes are
interpolated with the same t (attributes are linear in clip space, which is exactly why
perspective-correct interpolation later divides by w). x and y are not clipped at the
image's edges: the bounding box does that in screen space. They are clipped only against a
guard band, as a GPU's are: the planes ``|x|, |y| <= guard * w`` far outside the image
(``render`` always passes them, sized by ``guard_band`` in ``rendering/stages.py``) keep
window coordinates within the range where the fixed-point edge functions are exact; they
cut only invisible parts.

Every plane passes through the origin of clip space, so clipping is *homogeneous*:
multiplying a vertex's (x, y, z, w) by any positive factor moves it along its own ray and
changes nothing on screen. There is no fixed margin such as ``w >= 1e-300``: a vertex a
hair in front of the eye is as good as any. After near, far and the guard band, the only
vertex that can still have w = 0 is the origin itself (0, 0, 0, 0), the apex of the view
cone, which projects onto the rest of its polygon; it is removed (the "eye plane").

All triangles that need it are clipped at once: a triangle cut by p planes becomes a
convex polygon of at most 3 + p corners (five against near and far), held in fixed-size
arrays with a vertex count per polygon, then fanned into triangles. Triangles with
coordinates near the float limits are first scaled by a power of two (exact, and invisible
after the divide by w), so no difference or product overflows.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ...core.validate import as_bool, as_finite, as_float

#: A clipped vertex always has w > W_MIN (= 0): the eye plane has no margin, which keeps
#: clipping invariant under scaling a vertex by a positive factor (see the module docstring).
W_MIN = 0.0

INSIDE, CLIPPED, DROPPED = 0, 1, 2

#: Default guard band of :func:`clip_triangles`, in NDC units: about a million image
#: widths, far beyond anything visible yet keeping every projected vertex finite.
DEFAULT_GUARD = 2.0**20

#: Triangles whose largest |coordinate| lies outside [2**-LIMIT_EXP, 2**LIMIT_EXP] are
#: rescaled by a power of two before clipping (products of two coordinates stay finite).
LIMIT_EXP = 480


def planes(guard: float | None = None) -> np.ndarray:
    """Clip planes as rows (a, b, c, d): inside where a x + b y + c z + d w >= 0.

    Near ``z + w >= 0``, far ``w - z >= 0``, then the four guard-band planes if ``guard``
    is given. (The eye plane, w > 0, is not a linear half-space test: see :func:`classify`.)
    """
    rows = [[0, 0, 1, 1], [0, 0, -1, 1]]
    if guard is not None:
        rows += [[-1, 0, 0, guard], [1, 0, 0, guard], [0, -1, 0, guard], [0, 1, 0, guard]]
    return np.array(rows, dtype=np.float64)


def distances(v: np.ndarray, guard: float | None = None) -> np.ndarray:
    """(..., P) signed distances of clip-space points (..., 4) to each plane."""
    return np.stack([_distance(v, k, guard) for k in range(len(planes(guard)))], axis=-1)


def _distance(v: np.ndarray, k: int, guard: float | None) -> np.ndarray:
    """(...,) signed distance to plane k, written out (no BLAS: the same rounding on every
    machine and batch size, so a shared edge is cut identically in every triangle)."""
    x, y, z, w = v[..., 0], v[..., 1], v[..., 2], v[..., 3]
    if k == 0:
        return z + w
    if k == 1:
        return w - z
    return guard * w + (-x, x, -y, y)[k - 2]


def _normalised(clip: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Triangles (N, 3, 4) scaled by 2**-e where their coordinates approach the float limits.

    Returns the scaled triangles and e (N,) (0 for the ordinary ones, left bit-identical).
    A common power of two per triangle is exact and keeps every ratio of its coordinates,
    so nothing the pipeline computes from it changes. The shift is the smallest that brings
    the largest |coordinate| within [2**-LIMIT_EXP, 2**LIMIT_EXP]: a vertex far smaller
    than the triangle's largest (a spread of scales beyond the float range between its
    vertices) keeps as many of its bits as it can.
    """
    peak = np.abs(clip).max(axis=(1, 2), initial=0.0)
    _, e = np.frexp(peak)
    e = np.where(e > LIMIT_EXP, e - LIMIT_EXP, np.where((e < -LIMIT_EXP) & (peak > 0),
                                                       e + LIMIT_EXP, 0))  # fmt: skip
    if not e.any():
        return clip, e
    scaled = np.ldexp(clip, -e[:, None, None])
    _check_spread(clip, scaled)
    return scaled, e


def _check_spread(clip: np.ndarray, scaled: np.ndarray) -> None:
    """A ValueError naming ``clip`` where a shift made a normal vertex subnormal or zero.

    Only a triangle whose vertices differ in scale by more than about 2**1400 (the float
    range less the headroom the clipper's products need) can lose a vertex that way: it
    would silently turn into the eye point, so it is refused instead.
    """
    tiny = np.finfo(np.float64).tiny
    before, after = np.abs(clip).max(axis=-1), np.abs(scaled).max(axis=-1)
    lost = (before >= tiny) & (after < tiny)
    if lost.any():
        t, v = np.argwhere(lost)[0]
        raise ValueError(
            f"clip: the vertices of triangle {t} differ in scale by more than the float range "
            f"allows (vertex {v} would underflow); scale each vertex by a positive factor "
            "(which changes nothing on screen) so that they are closer"
        )


def _per_vertex(clip: np.ndarray) -> np.ndarray:
    """Every vertex scaled by its own power of two to a largest |coordinate| in [0.5, 1).

    Exact, and it keeps the sign of every plane distance (a positive factor on a vertex
    changes no side of a plane through the origin), so :func:`classify` decides the same for
    any spread of scales between a triangle's vertices.
    """
    peak = np.abs(clip).max(axis=-1)
    _, e = np.frexp(peak)
    return np.ldexp(clip, -e[..., None])


def classify(clip: np.ndarray, guard: float | None = None) -> np.ndarray:
    """Per triangle: INSIDE (no plane cuts it), DROPPED (wholly outside one plane), CLIPPED.

    A vertex is outside the eye plane when w <= 0 (near and far already reject w < 0, so
    this only catches w = 0; with the guard band, only the origin).

    >>> classify(np.array([[[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]],
    ...                    [[0, 0, -3, 1], [1, 0, -3, 1], [0, 1, -3, 1]],
    ...                    [[0, 0, -3, 1], [1, 0, 0, 1], [0, 1, 0, 1]]]))
    array([0, 2, 1], dtype=int8)
    """
    clip = _per_vertex(np.asarray(clip, dtype=np.float64).reshape(-1, 3, 4))
    inside = distances(clip, guard) >= 0  # (N, 3 vertices, P planes)
    inside = np.concatenate([inside, (clip[:, :, 3] > 0)[:, :, None]], axis=2)
    status = np.full(len(clip), CLIPPED, dtype=np.int8)
    status[inside.all(axis=(1, 2))] = INSIDE
    status[(~inside).all(axis=1).any(axis=1)] = DROPPED
    return status


def _onto_plane(v: np.ndarray, k: int, guard: float | None) -> None:
    """Put new vertices (..., 4) exactly on clip plane k (their rounding error, ~1e-16, removed).

    Later planes and the divide by w then see them where they belong: never a hair outside
    a plane they were cut at.
    """
    if k == 0:  # near: z = -w
        v[..., 2] = -v[..., 3]
    elif k == 1:  # far: z = w
        v[..., 2] = v[..., 3]
    else:  # guard band: x or y = +-guard * w
        axis, sign = (0, 0, 1, 1)[k - 2], (1, -1, 1, -1)[k - 2]
        v[..., axis] = sign * guard * v[..., 3]


def _cut(poly, attrs, count, d, k, guard):
    """One Sutherland-Hodgman pass of polygons (n, cap, 4) against plane k: capacity + 1.

    Vertex i is kept when inside (d >= 0); where edge i -> i+1 crosses the plane the
    crossing follows it, so every polygon keeps its winding and starts where it did.
    Returns the polygons, their attributes, the corner counts and which corners are new.
    """
    n, cap = d.shape
    idx = np.arange(cap)
    valid = idx < count[:, None]
    nxt = np.where(idx + 1 < count[:, None], idx + 1, 0)
    d_next = np.take_along_axis(d, nxt, axis=1)
    keep = valid & (d >= 0)
    cross = valid & ((d >= 0) != (d_next >= 0))
    # Step from the endpoint nearer the plane: t is then small and the new vertex accurate,
    # and an edge shared by two triangles is cut at the same point whichever way round
    # they traverse it.
    swap = np.abs(d) > np.abs(d_next)
    p_next = np.take_along_axis(poly, nxt[:, :, None], axis=1)
    a_next = np.take_along_axis(attrs, nxt[:, :, None], axis=1)
    s3 = swap[:, :, None]
    pa, pb = np.where(s3, p_next, poly), np.where(s3, poly, p_next)
    fa, fb = np.where(s3, a_next, attrs), np.where(s3, attrs, a_next)
    da, db = np.where(swap, d_next, d), np.where(swap, d, d_next)
    t = np.divide(da, da - db, out=np.zeros_like(da), where=cross)[:, :, None]
    new_p = _crossing(pa, pb, da, db, t, cross)
    _onto_plane(new_p, k, guard)
    with np.errstate(over="ignore", invalid="ignore"):  # attributes near the float limit
        new_a = fa + t * (fb - fa)
    bad = ~np.isfinite(new_a)
    if bad.any():  # the difference overflowed: the convex form cannot
        alt = (1 - t) * fa + t * fb
        new_a[bad] = alt[bad]
    # Interleave (vertex i if kept, crossing i if any) and pack to the front of each row.
    cand_p = np.stack([poly, new_p], axis=2).reshape(n, 2 * cap, 4)
    cand_a = np.stack([attrs, new_a], axis=2).reshape(n, 2 * cap, attrs.shape[2])
    mask = np.stack([keep, cross], axis=2).reshape(n, 2 * cap)
    rows, slots = np.nonzero(mask)
    dest = (np.cumsum(mask, axis=1) - 1)[rows, slots]
    out_p = np.zeros((n, cap + 1, 4))
    out_a = np.zeros((n, cap + 1, attrs.shape[2]))
    out_p[rows, dest] = cand_p[rows, slots]
    out_a[rows, dest] = cand_a[rows, slots]
    new = np.zeros((n, cap + 1), dtype=bool)
    new[rows, dest] = slots % 2 == 1  # odd slots hold the crossings
    return out_p, out_a, mask.sum(axis=1), new


def _crossing(pa, pb, da, db, t, cross):
    """Where edge a -> b crosses the plane: ``pa + da (pb - pa) / (da - db)``, nearer end a.

    Written with ``da`` applied last, not as ``pa + t (pb - pa)``: when the two endpoints'
    scales differ by more than the float range (w = 1e-250 at a, 1e121 at b) t itself
    underflows although the step ``t (pb - pa)`` is a perfectly ordinary number. Where the
    quotient overflows instead (a on the plane, b tiny), t's form is the accurate one.
    """
    with np.errstate(over="ignore", invalid="ignore", divide="ignore", under="ignore"):
        step = np.divide(pb - pa, (da - db)[:, :, None], out=np.zeros_like(pa),
                         where=cross[:, :, None])  # fmt: skip
        step *= da[:, :, None]
        new_p = pa + step
    bad = ~np.isfinite(new_p)
    if bad.any():
        new_p[bad] = (pa + t * (pb - pa))[bad]
    return new_p


def clip_polygons(poly, attrs, count, guard: float | None = None):
    """Clip convex polygons against near, far, the guard band and the eye, all at once.

    Parameters
    ----------
    poly : (n, cap, 4) float64
        Clip-space corners; row r uses its first ``count[r]`` entries.
    attrs : (n, cap, k) float64
        Their attributes.
    count : (n,) int
    guard : float or None
        Guard band in NDC units (None: no guard planes).

    Returns
    -------
    poly, attrs, count
        The clipped polygons (capacity grown by one per plane that cut anything), possibly
        with fewer than 3 corners (nothing left).
    """
    count = np.array(count, dtype=np.int64)  # a copy: updated in place below
    for k in range(len(planes(guard))):
        d = _distance(poly, k, guard)
        valid = np.arange(poly.shape[1]) < count[:, None]
        todo = np.flatnonzero((valid & (d < 0)).any(axis=1))
        if len(todo) == 0:
            continue
        cut_p, cut_a, cut_n, _ = _cut(poly[todo], attrs[todo], count[todo], d[todo], k, guard)
        poly = np.concatenate([poly, np.zeros((len(poly), 1, 4))], axis=1)
        attrs = np.concatenate([attrs, np.zeros((len(attrs), 1, attrs.shape[2]))], axis=1)
        poly[todo], attrs[todo], count[todo] = cut_p, cut_a, cut_n
    # The eye: drop corners with w <= 0 (after the planes above, only the origin, which
    # projects onto the rest of its polygon; without a guard band also directions at
    # infinity, which no image can show).
    valid = np.arange(poly.shape[1]) < count[:, None]
    live = valid & (poly[:, :, 3] > 0)
    if (live != valid).any():
        order = np.argsort(~live, axis=1, kind="stable")
        poly = np.take_along_axis(poly, order[:, :, None], axis=1)
        attrs = np.take_along_axis(attrs, order[:, :, None], axis=1)
        count = live.sum(axis=1)
    return poly, attrs, count


def _clip_against(poly: np.ndarray, attrs: np.ndarray, k: int, guard: float | None):
    """One Sutherland-Hodgman pass: ``poly`` (n, 4) and ``attrs`` (n, k) against plane ``k``.

    The renderer's own pass (:func:`_cut`) on a batch of one. Returns the new polygon, its
    attributes and a bool mask of the vertices the pass created.
    """
    d = _distance(poly, k, guard)
    p, a, n, new = _cut(poly[None], attrs[None], np.array([len(poly)]), d[None], k, guard)
    return p[0, : n[0]], a[0, : n[0]], new[0, : n[0]]


def clip_polygon(
    poly: np.ndarray, attrs: np.ndarray, guard: float | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Sutherland-Hodgman on one convex polygon (n, 4) and its attributes (n, k).

    Returns the clipped polygon and its attributes (possibly with 0 vertices).

    >>> tri = np.array([[0.0, 0, -3, 1], [0, 0, 0, 1], [1, 0, 0, 1]])
    >>> p, _ = clip_polygon(tri, np.zeros((3, 0)))
    >>> len(p), bool((p[:, 2] + p[:, 3] >= -1e-12).all())
    (4, True)
    """
    poly = np.asarray(poly, dtype=np.float64)
    attrs = np.asarray(attrs, dtype=np.float64).reshape(len(poly), -1)
    p, a, n = clip_polygons(poly[None], attrs[None], np.array([len(poly)]), guard)
    return p[0, : n[0]], a[0, : n[0]]


#: Names of the clip planes, in the order of :func:`planes`.
#: The eye comes last: it only removes the origin, which the planes before it leave alone.
# in the order of planes(): row 2 is -x + g w >= 0, that is x <= g w (the names had the two
# sides of each pair swapped)
PLANE_NAMES = ("near z >= -w", "far z <= w", "guard x <= g w", "guard x >= -g w",
               "guard y <= g w", "guard y >= -g w", "eye w > 0")  # fmt: skip


@dataclass(frozen=True)
class ClipStep:
    """The polygon after one clip plane (a record of :func:`clip_polygon_steps`).

    Attributes
    ----------
    plane : str
        Which plane, e.g. ``"near z >= -w"``.
    distances : (n,) float64
        Signed distance of each vertex of the polygon *before* this plane (>= 0 inside).
    polygon : (m, 4) float64
        The clip-space polygon after this plane.
    attrs : (m, k) float64
        Its attributes (new vertices: interpolated with the same t as the position).
    new : (m,) bool
        Which vertices this plane created (on the plane itself).
    """

    plane: str
    distances: np.ndarray
    polygon: np.ndarray
    attrs: np.ndarray
    new: np.ndarray


def clip_polygon_steps(poly, attrs=None, guard: float | None = None) -> list[ClipStep]:
    """:func:`clip_polygon` one plane at a time, for teaching: the polygon after each plane.

    The same passes as :func:`clip_polygon` (so the last step's polygon is its result), each
    recorded with the distances it tested, the vertices it kept and the ones it created.

    Parameters
    ----------
    poly : (n, 4) array-like
        Clip-space polygon (a triangle: n = 3).
    attrs : (n, k) array-like, optional
        Vertex attributes (default: none).
    guard : float, optional
        Guard band in NDC units (default: no guard-band planes).

    Returns
    -------
    list of ClipStep, one per plane in the order of ``PLANE_NAMES`` (near, far, the guard band
    if given, then the eye, whose "distance" is w and which keeps w > 0); fewer if the
    polygon vanished.

    Examples
    --------
    >>> tri = [[0.0, 0, -3, 1], [0, 0, 0, 1], [1, 0, 0, 1]]   # vertex 0 in front of near
    >>> steps = clip_polygon_steps(tri, [[0.0], [1.0], [2.0]])
    >>> steps[0].plane, len(steps[0].polygon), steps[0].new.tolist()
    ('near z >= -w', 4, [True, False, False, True])
    >>> steps[0].attrs[steps[0].new].ravel().round(4).tolist()   # a third of the way back
    [0.6667, 1.3333]
    """
    poly = np.asarray(poly, dtype=np.float64).reshape(-1, 4)
    attrs = np.zeros((len(poly), 0)) if attrs is None else np.asarray(attrs, dtype=np.float64)
    attrs = attrs.reshape(len(poly), -1)
    steps = []
    for k in range(len(planes(guard))):
        if len(poly) == 0:
            break
        d = _distance(poly, k, guard)
        poly, attrs, new = _clip_against(poly, attrs, k, guard)
        steps.append(ClipStep(PLANE_NAMES[k], d, poly, attrs, new))
    if len(poly):  # the eye, last: keeps w > 0 (drops only the origin, see the module doc)
        live = poly[:, 3] > 0
        steps.append(
            ClipStep(
                PLANE_NAMES[-1], poly[:, 3], poly[live], attrs[live], np.zeros(live.sum(), bool)
            )
        )
    return steps


@dataclass(frozen=True)
class ClipResult:
    """Triangles after clipping, ready for the viewport transform.

    Attributes
    ----------
    clip : (M, 3, 4) float64
        Output triangles (unchanged ones first keep their order with clipped pieces in
        place: output order follows input order).
    attrs : (M, 3, k) float64
    parent : (M,) int
        Input triangle each output triangle came from.
    status : (N,) int8
        Per input triangle: 0 inside, 1 clipped, 2 dropped.
    cut, cut_count : (c, cap, 4) float64 and (c,) int
        The clipped polygon of each CLIPPED input triangle, in input order, as fixed-size
        rows and corner counts; ``polygons`` gives them as a tuple of (n, 4) arrays.
    """

    clip: np.ndarray
    attrs: np.ndarray
    parent: np.ndarray
    status: np.ndarray
    cut: np.ndarray
    cut_count: np.ndarray

    @cached_property
    def polygons(self) -> tuple[np.ndarray, ...]:
        """The clipped polygon of each CLIPPED input triangle, in input order (the trace)."""
        return tuple(p[:n] for p, n in zip(self.cut, self.cut_count.tolist()))


def _fan(poly, attrs, count):
    """Fan convex polygons into triangles (0, i, i + 1): (T, 3, 4), (T, 3, k), owner (T,).

    Around the first corner, keeping the winding (and so the facing) of the original.
    """
    pieces = np.maximum(count - 2, 0)
    owner = np.repeat(np.arange(len(count)), pieces)
    i = np.arange(pieces.sum()) - np.repeat(np.cumsum(pieces) - pieces, pieces) + 1
    corners = np.stack([np.zeros_like(i), i, i + 1], axis=1)
    return poly[owner[:, None], corners], attrs[owner[:, None], corners], owner


def _checked(clip, attrs, guard, force):
    """The arguments of :func:`clip_triangles`, validated (errors name the argument)."""
    clip = as_finite("clip", clip, (None, 3, 4))
    attrs = as_finite("attrs", attrs, (len(clip), 3, None))
    if guard is not None:
        guard = as_float("guard", guard)
        if not guard >= 1.0:
            raise ValueError(f"guard must be >= 1 (NDC units beyond the image), got {guard!r}")
    return clip, attrs, guard, as_bool("force", force)


def clip_triangles(
    clip: np.ndarray, attrs: np.ndarray, guard: float | None = DEFAULT_GUARD, force: bool = False
) -> ClipResult:
    """Clip triangles (N, 3, 4) with attributes (N, 3, k) against near, far and the guard band.

    Only triangles that a plane actually cuts go through the clipper; ``force=True`` sends
    every triangle through it, for comparison. ``guard`` is the guard band in NDC units
    (``render`` sizes it to the image); ``None`` drops it, and then a vertex cut near the
    eye plane can project arbitrarily far.
    """
    clip, attrs, guard, force = _checked(clip, attrs, guard, force)
    scaled, e = _normalised(clip)
    status = classify(scaled, guard)
    todo = np.flatnonzero(status != DROPPED) if force else np.flatnonzero(status == CLIPPED)
    keep = status == INSIDE
    if len(todo) == 0:  # the common case: no triangle needed clipping
        idx = np.flatnonzero(keep)
        return ClipResult(clip[idx], attrs[idx], idx, status, np.zeros((0, 3, 4)), idx[:0])
    poly, pattrs, count = clip_polygons(scaled[todo], attrs[todo], np.full(len(todo), 3), guard)
    poly = np.ldexp(poly, e[todo][:, None, None])  # back to the caller's scale
    is_cut = status[todo] == CLIPPED
    tris, tattrs, owner = _fan(poly, pattrs, count)
    # Output in input order: unclipped triangles as they are, pieces in their parent's place.
    through = np.zeros(len(clip), dtype=bool)
    through[todo] = True
    plain = np.flatnonzero(keep & ~through)
    parent = np.concatenate([plain, todo[owner]])
    order = np.argsort(parent, kind="stable")
    return ClipResult(
        np.concatenate([clip[plain], tris])[order],
        np.concatenate([attrs[plain], tattrs])[order],
        parent[order],
        status,
        poly[is_cut],
        count[is_cut],
    )
