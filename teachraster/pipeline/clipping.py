"""Homogeneous clipping against the near and far planes, before the divide by w.

A vertex behind the eye has w < 0; dividing by it would mirror the vertex through the
eye, and a vertex near w = 0 would be thrown towards infinity. So, as OpenGL does, each
triangle is clipped in clip space against ``-w <= z <= w`` (Sutherland-Hodgman), where
everything is still linear: a new vertex on an edge is ``v0 + t (v1 - v0)`` with
``t = d0 / (d0 - d1)`` for the signed distances d to the plane, and its attributes are
interpolated with the same t (attributes are linear in clip space, which is exactly why
perspective-correct interpolation later divides by w). x and y are not clipped: the
bounding box does that in screen space (a guard band).

For robustness with hand-made clip coordinates (not from a projection matrix) a third
plane ``w >= W_MIN`` keeps any vertex exactly on the eye plane (w = 0, z = 0, which
satisfies -w <= z <= w) away from the divide. And like a GPU's guard band, optional
planes ``|x|, |y| <= guard * w`` far outside the image keep window coordinates within the
range where the fixed-point edge functions are exact; they cut only invisible parts.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Smallest w a clipped vertex may have (see the module docstring).
W_MIN = 1e-300  # only a vertex exactly on (or numerically at) the eye plane is affected:
# any larger w is a legitimate vertex just in front of the eye, whose projection the guard
# band, not this plane, keeps in range

INSIDE, CLIPPED, DROPPED = 0, 1, 2

#: Default guard band of :func:`clip_triangles`, in NDC units: about a million image
#: widths, far beyond anything visible yet keeping every projected vertex finite.
DEFAULT_GUARD = 2.0**20


def planes(guard: float | None = None) -> np.ndarray:
    """Clip planes as rows (a, b, c, d): inside where a x + b y + c z + d w >= 0.

    Near ``z + w >= 0``, far ``w - z >= 0``, the eye plane ``w >= W_MIN`` (the offset is
    applied in :func:`distances`), then the four guard-band planes if ``guard`` is given.
    """
    rows = [[0, 0, 1, 1], [0, 0, -1, 1], [0, 0, 0, 1]]
    if guard is not None:
        rows += [[-1, 0, 0, guard], [1, 0, 0, guard], [0, -1, 0, guard], [0, 1, 0, guard]]
    return np.array(rows, dtype=np.float64)


def distances(v: np.ndarray, guard: float | None = None) -> np.ndarray:
    """(..., P) signed distances of clip-space points (..., 4) to each plane."""
    d = v @ planes(guard).T
    d[..., 2] -= W_MIN
    return d


def classify(clip: np.ndarray, guard: float | None = None) -> np.ndarray:
    """Per triangle: INSIDE (no plane cuts it), DROPPED (wholly outside one plane), CLIPPED.

    >>> classify(np.array([[[0, 0, 0, 1], [1, 0, 0, 1], [0, 1, 0, 1]],
    ...                    [[0, 0, -3, 1], [1, 0, -3, 1], [0, 1, -3, 1]],
    ...                    [[0, 0, -3, 1], [1, 0, 0, 1], [0, 1, 0, 1]]]))
    array([0, 2, 1], dtype=int8)
    """
    d = distances(clip, guard)  # (N, 3 vertices, P planes)
    inside = d >= 0
    status = np.full(len(clip), CLIPPED, dtype=np.int8)
    status[inside.all(axis=(1, 2))] = INSIDE
    status[(~inside).all(axis=1).any(axis=1)] = DROPPED
    return status


def _onto_plane(v: np.ndarray, k: int, guard: float | None) -> np.ndarray:
    """Put a new vertex exactly on clip plane k (its rounding error, ~1e-16, removed).

    Later planes and the divide by w then see it where it belongs: never a hair outside a
    plane it was cut at, and never at w <= 0 after the cut at the eye plane.
    """
    v = v.copy()
    if k == 0:  # near: z = -w
        v[2] = -v[3]
    elif k == 1:  # far: z = w
        v[2] = v[3]
    elif k == 2:  # eye: w = W_MIN
        v[3] = W_MIN
    else:  # guard band: x or y = +-guard * w
        axis, sign = (0, 0, 1, 1)[k - 3], (1, -1, 1, -1)[k - 3]
        v[axis] = sign * guard * v[3]
    return v


def _clip_against(poly: np.ndarray, attrs: np.ndarray, k: int, guard: float | None):
    """One Sutherland-Hodgman pass: ``poly`` (n, 4) and ``attrs`` (n, k) against plane ``k``.

    Returns the new polygon, its attributes and a bool mask of the vertices the pass created.
    """
    d = distances(poly, guard)[:, k]
    out_v, out_a, new = [], [], []
    n = len(poly)
    for i in range(n):
        j = (i + 1) % n
        if d[i] >= 0:
            out_v.append(poly[i])
            out_a.append(attrs[i])
            new.append(False)
        if (d[i] >= 0) != (d[j] >= 0):  # the edge crosses the plane: add the crossing
            # Step from the endpoint nearer the plane: t is then small and the new
            # vertex accurate (from the far end, 1 - t can round a vertex just off
            # the eye plane onto it), and an edge shared by two triangles is cut at
            # the same point whichever way round they traverse it.
            a, b = (i, j) if abs(d[i]) <= abs(d[j]) else (j, i)
            t = d[a] / (d[a] - d[b])
            out_v.append(_onto_plane(poly[a] + t * (poly[b] - poly[a]), k, guard))
            out_a.append(attrs[a] + t * (attrs[b] - attrs[a]))
            new.append(True)
    poly = np.array(out_v).reshape(-1, 4)
    return poly, np.array(out_a).reshape(len(poly), attrs.shape[1]), np.array(new, dtype=bool)


def clip_polygon(
    poly: np.ndarray, attrs: np.ndarray, guard: float | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Sutherland-Hodgman: clip one convex polygon (n, 4) and its attributes (n, k).

    Returns the clipped polygon and its attributes (possibly with 0 vertices).

    >>> tri = np.array([[0.0, 0, -3, 1], [0, 0, 0, 1], [1, 0, 0, 1]])
    >>> p, _ = clip_polygon(tri, np.zeros((3, 0)))
    >>> len(p), bool((p[:, 2] + p[:, 3] >= -1e-12).all())
    (4, True)
    """
    for k in range(len(planes(guard))):
        if len(poly) == 0:
            break
        poly, attrs, _ = _clip_against(poly, attrs, k, guard)
    return poly, attrs


#: Names of the clip planes, in the order of :func:`planes`.
PLANE_NAMES = ("near z >= -w", "far z <= w", "eye w > 0", "guard x >= -g w", "guard x <= g w",
               "guard y >= -g w", "guard y <= g w")  # fmt: skip


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
    list of ClipStep, one per plane (fewer if the polygon vanished).

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
        d = distances(poly, guard)[:, k]
        poly, attrs, new = _clip_against(poly, attrs, k, guard)
        steps.append(ClipStep(PLANE_NAMES[k], d, poly, attrs, new))
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
    polygons : tuple of (n, 4) arrays
        The clipped polygon of each CLIPPED input triangle, in input order (for the trace).
    """

    clip: np.ndarray
    attrs: np.ndarray
    parent: np.ndarray
    status: np.ndarray
    polygons: tuple[np.ndarray, ...]


def clip_triangles(
    clip: np.ndarray, attrs: np.ndarray, guard: float | None = DEFAULT_GUARD, force: bool = False
) -> ClipResult:
    """Clip triangles (N, 3, 4) with attributes (N, 3, k) against near, far and the guard band.

    Only triangles that a plane actually cuts go through the (per-polygon) clipper;
    ``force=True`` sends every triangle through it, for comparison. ``guard`` is the
    guard band in NDC units (``render`` sizes it to the image); ``None`` drops it, and then
    a vertex cut at the eye plane can project arbitrarily far.
    """
    status = classify(clip, guard)
    todo = np.flatnonzero(status != DROPPED) if force else np.flatnonzero(status == CLIPPED)
    pieces: dict[int, tuple[np.ndarray, np.ndarray]] = {}
    polygons = []
    for t in todo:
        poly, pattrs = clip_polygon(clip[t], attrs[t], guard)
        if status[t] == CLIPPED:
            polygons.append(poly)
        # A convex polygon becomes a fan of triangles around its first vertex, keeping
        # the winding (and so the facing) of the original triangle.
        fan = np.array([(0, i, i + 1) for i in range(1, len(poly) - 1)], dtype=np.int64)
        fan = fan.reshape(-1, 3)
        pieces[int(t)] = (poly[fan], pattrs[fan])
    out_clip, out_attrs, parent = [], [], []
    keep = status == INSIDE
    if not pieces:  # the common case: no triangle needed clipping
        idx = np.flatnonzero(keep)
        return ClipResult(clip[idx], attrs[idx], idx, status, tuple(polygons))
    for t in range(len(clip)):
        if int(t) in pieces:
            c, a = pieces[int(t)]
        elif keep[t]:
            c, a = clip[t : t + 1], attrs[t : t + 1]
        else:
            continue
        out_clip.append(c)
        out_attrs.append(a)
        parent.append(np.full(len(c), t))
    k = attrs.shape[2]
    return ClipResult(
        np.concatenate(out_clip) if out_clip else np.zeros((0, 3, 4)),
        np.concatenate(out_attrs) if out_attrs else np.zeros((0, 3, k)),
        np.concatenate(parent) if parent else np.zeros(0, dtype=np.int64),
        status,
        tuple(polygons),
    )
