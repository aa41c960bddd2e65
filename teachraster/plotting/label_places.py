"""Where a label goes: clear of a triangle's edges, its vertex dots and the other labels, and
inside the Axes.

Review r216 03-5: at the sliders' ends the PlaneExplorer's vertex labels, pushed away from the
centroid and then moved in from the frame, covered their own vertex dot and the first pixels
of both edges (v1 at (0, 0)), or lay on one another (v3 at (0, 0) under v1). Here a label is
one of a few candidate boxes round its point, and the one chosen is the cheapest: a box
outside the frame, over another label or over a vertex dot costs most, one over an edge
less, one over the triangle's inside a little (it hides the pixels the label is about), and
the rest is a mild wish for the direction away from the triangle. Review r216 03-6: the same
costs place the values on the contour lines.

Everything is in display pixels (y up); a box is ``(x0, y0, x1, y1)``.
"""

from __future__ import annotations

import numpy as np

#: Directions tried round a vertex (every 15 degrees)
DIRECTIONS = 24

#: Rings of candidate boxes round a vertex: the nearest clear of its dot, then each this
#: many box heights farther (into a narrow corner of the triangle, past its edges)
RINGS = 4
RING_STEP = 0.6

#: What a candidate box pays, for: sticking out of the frame (per pixel), lying over another
#: label (and more per share of its own area) or over a vertex dot, touching an edge at all and then per
#: box width of edge, covering the triangle's inside (per share of its area, sampled),
#: turning from the preferred direction (1 - cos of the angle), each ring farther out, and
#: standing nearer another vertex than its own (it would name the wrong one); an edge label
#: by an end of its edge (:data:`END_SHARE`)
COST = {"out": 1000.0, "label": 100.0, "dot": 100.0, "touch": 20.0, "edge": 40.0,
        "inside": 10.0, "turn": 3.0, "ring": 1.0, "astray": 100.0, "crowd": 30.0,
        "end": 60.0}  # fmt: skip

#: An edge label whose foot on its edge lies farther than this share of the edge from the
#: middle pays COST["end"], in proportion to how much farther (all of it at an end)
END_SHARE = 0.3

#: An edge label clear of the dots by less than this share of a grid pixel still pays
#: COST["crowd"]: between two rows of centres it goes to the middle, not just off the dots
#: (review r302 02-FIG1: "E31" 2 px from row 7's centres read as lying on them)
CROWD_MARGIN = 0.1

#: Pixels an edge's line reaches beyond its centre line (half the classroom style's width and
#: a gap): a box nearer than this touches it
EDGE_REACH = 3.0

#: Above this a label would cover another label or a dot: a line's value is then left out
CLASH = 50.0


def boxes_around(centres: np.ndarray, half) -> np.ndarray:
    """(n, 4) boxes of half-size ``half`` = (half width, half height) round (n, 2) centres."""
    centres = np.asarray(centres, dtype=np.float64).reshape(-1, 2)
    hw, hh = half
    return np.column_stack([centres - (hw, hh), centres + (hw, hh)])


def overlap_share(boxes: np.ndarray, others: np.ndarray) -> np.ndarray:
    """For each of the (n, 4) ``boxes``: the area it shares with the (m, 4) ``others``, summed,
    as a share of its own area."""
    if len(others) == 0:
        return np.zeros(len(boxes))
    b, o = boxes[:, None, :], np.asarray(others, dtype=np.float64)[None, :, :]
    w = np.clip(np.minimum(b[..., 2], o[..., 2]) - np.maximum(b[..., 0], o[..., 0]), 0, None)
    h = np.clip(np.minimum(b[..., 3], o[..., 3]) - np.maximum(b[..., 1], o[..., 1]), 0, None)
    area = (boxes[:, 2] - boxes[:, 0]) * (boxes[:, 3] - boxes[:, 1])
    return (w * h).sum(axis=1) / np.maximum(area, 1e-12)


def length_inside(boxes: np.ndarray, segments: np.ndarray) -> np.ndarray:
    """For each of the (n, 4) ``boxes``: the total length of the (m, 2, 2) ``segments`` inside
    it (Liang-Barsky clipping, all pairs at once).

    Examples
    --------
    >>> length_inside(np.array([[0.0, 0.0, 2.0, 2.0]]), np.array([[[-1.0, 1.0], [5.0, 1.0]]]))
    array([2.])
    """
    if len(segments) == 0:
        return np.zeros(len(boxes))
    p0 = np.asarray(segments, dtype=np.float64)[None, :, 0, :]  # (1, m, 2)
    d = np.asarray(segments, dtype=np.float64)[None, :, 1, :] - p0
    lo, hi = boxes[:, None, :2], boxes[:, None, 2:]  # (n, 1, 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1, t2 = (lo - p0) / d, (hi - p0) / d  # where each slab is entered and left
    within = (p0 >= lo) & (p0 <= hi)  # for a slab the segment runs along: inside it or not
    enter = np.where(d != 0, np.minimum(t1, t2), np.where(within, -np.inf, np.inf))
    leave = np.where(d != 0, np.maximum(t1, t2), np.where(within, np.inf, -np.inf))
    share = np.clip(np.minimum(leave.min(axis=-1), 1.0) - np.maximum(enter.max(axis=-1), 0.0), 0, 1)
    return (share * np.hypot(d[..., 0], d[..., 1])).sum(axis=1)


def clip_segment(a, b, box) -> tuple[float, float] | None:
    """The part of the segment from ``a`` to ``b`` inside ``box``, as the parameters (t0, t1)
    of its ends (0 at ``a``, 1 at ``b``); None where it misses the box.

    Examples
    --------
    >>> clip_segment(np.array([-1.0, 1.0]), np.array([3.0, 1.0]), (0.0, 0.0, 2.0, 2.0))
    (0.25, 0.75)
    """
    t0, t1 = 0.0, 1.0
    for k in range(2):
        d = float(b[k] - a[k])
        lo, hi = float(box[k] - a[k]), float(box[k + 2] - a[k])
        if d == 0:
            if not lo <= 0 <= hi:
                return None
            continue
        enter, leave = sorted((lo / d, hi / d))
        t0, t1 = max(t0, enter), min(t1, leave)
    return (t0, t1) if t0 <= t1 else None


def inside_share(boxes: np.ndarray, triangle: np.ndarray) -> np.ndarray:
    """For each of the (n, 4) ``boxes``: the share of its 3 × 3 sample points strictly inside
    ``triangle`` (3, 2), whichever way it winds (0 for three points on one line)."""
    u = np.array([0.1, 0.5, 0.9])
    gx = boxes[:, :1] + u * (boxes[:, 2:3] - boxes[:, :1])  # (n, 3)
    gy = boxes[:, 1:2] + u * (boxes[:, 3:4] - boxes[:, 1:2])
    px, py = np.repeat(gx, 3, axis=1), np.tile(gy, 3)  # (n, 9)
    sides = []
    for k in range(3):
        (ax_, ay), (bx, by) = triangle[k], triangle[(k + 1) % 3]
        sides.append((bx - ax_) * (py - ay) - (by - ay) * (px - ax_))
    s = np.stack(sides)
    inside = (s > 0).all(axis=0) | (s < 0).all(axis=0)
    return inside.mean(axis=1)


def outward(xy: np.ndarray) -> np.ndarray:
    """(3, 2) unit directions pointing away from the triangle at each vertex: the outer
    bisector of its angle; for three points on one line, square to it (all to one side,
    upwards); for three equal points, up."""
    xy = np.asarray(xy, dtype=np.float64)
    out = np.zeros((3, 2))
    for k in range(3):
        sides = [xy[(k + j) % 3] - xy[k] for j in (1, 2)]
        units = [s / n for s in sides if (n := float(np.hypot(*s))) > 1e-9]
        out[k] = -sum(units, np.zeros(2))
    (ax_, ay), (bx, by), (cx, cy) = xy
    flat = abs((bx - ax_) * (cy - ay) - (cx - ax_) * (by - ay))
    span = max(float(np.ptp(xy[:, 0])), float(np.ptp(xy[:, 1])), 1e-9)
    if flat < 1e-6 * span * span:  # on one line: the bisectors run along it
        far = xy[np.argmax(np.hypot(*(xy - xy[0]).T))] - xy[0]
        normal = np.array([-far[1], far[0]])
        if normal[1] < 0 or (normal[1] == 0 and normal[0] < 0):
            normal = -normal
        out[:] = normal if normal.any() else (0.0, 1.0)
    norms = np.hypot(out[:, 0], out[:, 1])[:, None]
    return np.where(norms > 1e-9, out / np.maximum(norms, 1e-12), (0.0, 1.0))


def _vertex_candidates(p: np.ndarray, half, dot: float) -> tuple[np.ndarray, np.ndarray]:
    """Centres of the boxes tried round the vertex ``p``: in each direction the nearest box
    clear of its dot (``dot``: the dot's radius and a gap), then :data:`RINGS` - 1 more, each
    :data:`RING_STEP` box heights farther. Returns the centres (RINGS DIRECTIONS, 2) and each
    one's ring (0 the nearest)."""
    hw, hh = half
    angle = np.linspace(0, 2 * np.pi, DIRECTIONS, endpoint=False)
    d = np.column_stack([np.cos(angle), np.sin(angle)])
    with np.errstate(divide="ignore"):
        r = np.minimum((hw + dot) / np.abs(d[:, 0]), (hh + dot) / np.abs(d[:, 1]))
    rings = np.arange(RINGS)
    centres = [p + (r + j * RING_STEP * 2 * hh)[:, None] * d for j in rings]
    return np.vstack(centres), np.repeat(rings, DIRECTIONS)


def _frame_excess(boxes: np.ndarray, frame) -> np.ndarray:
    """How far, in pixels, each box sticks out of ``frame`` (summed over its four sides)."""
    x0, y0, x1, y1 = frame
    return (np.clip(x0 - boxes[:, 0], 0, None) + np.clip(y0 - boxes[:, 1], 0, None)
            + np.clip(boxes[:, 2] - x1, 0, None) + np.clip(boxes[:, 3] - y1, 0, None))  # fmt: skip


def beside(boxes: np.ndarray, labels: np.ndarray) -> np.ndarray:
    """The cost of each box for lying over the (m, 4) ``labels``: one clash for any overlap
    at all, and more the more of it is covered."""
    share = overlap_share(boxes, labels)
    return COST["label"] * ((share > 0) + share)


def clutter(boxes, half, *, frame, triangle, dots) -> np.ndarray:
    """The cost of each box for what it covers besides labels: the frame's outside, vertex
    dots (the dots as small boxes), the triangle's edges and inside."""
    edges = np.stack([triangle, np.roll(triangle, -1, axis=0)], axis=1)
    on_edges = length_inside(boxes + (-EDGE_REACH, -EDGE_REACH, EDGE_REACH, EDGE_REACH), edges)
    return (COST["out"] * _frame_excess(boxes, frame)
            + COST["dot"] * (overlap_share(boxes, dots) > 0)
            + COST["touch"] * (on_edges > 0)
            + COST["edge"] * on_edges / (2 * half[0])
            + COST["inside"] * inside_share(boxes, triangle))  # fmt: skip


def place_vertex_labels(xy, half, dot: float, frame) -> np.ndarray:
    """Centres (3, 2) for the labels of the triangle ``xy`` (3, 2)'s vertices, each a box of
    half-size ``half`` clear of its vertex's dot (radius and gap ``dot``), inside ``frame``
    where it fits, off the edges, the other dots and the other labels, away from the
    triangle where it can. Two passes: each label placed, then each again beside the others.

    Examples
    --------
    >>> xy = np.array([[0.0, 0.0], [100.0, 0.0], [0.0, 80.0]])
    >>> c = place_vertex_labels(xy, (10.0, 8.0), 4.0, (0.0, 0.0, 200.0, 200.0))
    >>> bool(c[0, 0] > 0 and c[0, 1] > 0)  # at the frame's corner: moved in, off the edges
    True
    """
    xy = np.asarray(xy, dtype=np.float64)
    options = [_vertex_options(xy, k, half, dot, frame) for k in range(3)]
    centres: dict = {}
    for _ in range(2):
        for k, (cand, boxes, cost) in enumerate(options):
            others = boxes_around([c for j, c in centres.items() if j != k], half)
            centres[k] = cand[int(np.argmin(cost + beside(boxes, others)))]
    return np.array([centres[k] for k in range(3)])


def _vertex_options(xy, k: int, half, dot: float, frame) -> tuple:
    """The candidate centres round vertex ``k`` of ``xy``, their boxes and what each costs
    (the other labels aside)."""
    cand, ring = _vertex_candidates(xy[k], half, dot)
    boxes = boxes_around(cand, half)
    own = np.linalg.norm(cand - xy[k], axis=1)
    turn = 1 - ((cand - xy[k]) @ outward(xy)[k]) / own
    others = np.delete(xy, k, axis=0)
    astray = np.linalg.norm(cand[:, None, :] - others[None], axis=-1).min(axis=1) < own
    dots = boxes_around(others, (dot / 2, dot / 2))
    cost = (clutter(boxes, half, frame=frame, triangle=xy, dots=dots)
            + COST["turn"] * turn + COST["ring"] * ring + COST["astray"] * astray)  # fmt: skip
    return cand, boxes, cost


def place_on_line(segment, half, *, frame, triangle, labels, dots, samples: int = 41):
    """The centre for a label of half-size ``half`` on the line through ``segment`` (2, 2),
    inside ``frame``, clear of ``labels`` (m, 4) and ``dots`` (k, 4), off the triangle's edges
    and, where it can, its inside; near the triangle rather than far from it. None where every
    place on the line within the frame would cover a label or a dot."""
    a, b = np.asarray(segment, dtype=np.float64)
    hw, hh = half
    inner = (frame[0] + hw, frame[1] + hh, frame[2] - hw, frame[3] - hh)
    if inner[0] >= inner[2] or inner[1] >= inner[3]:
        return None
    span = clip_segment(a, b, inner)
    if span is None:
        return None
    cand = a + np.linspace(*span, samples)[:, None] * (b - a)
    boxes = boxes_around(cand, half)
    centre = triangle.mean(axis=0)
    reach = max(np.hypot(frame[2] - frame[0], frame[3] - frame[1]), 1e-9)
    cost = clutter(boxes, half, frame=frame, triangle=triangle, dots=dots) + beside(boxes, labels)
    cost = cost + 2 * COST["inside"] * inside_share(boxes, triangle)  # the pixels shown
    cost = cost + COST["turn"] * np.hypot(*(cand - centre).T) / reach
    best = int(np.argmin(cost))
    return None if cost[best] >= CLASH else cand[best]


#: How far from its edge's midpoint an edge label may go (pixels of the grid, each way)
EDGE_LABEL_REACH = 3.0


def place_edge_labels(mids, half, *, edges, to_display, frame, triangle, dots,
                      labels=None) -> np.ndarray:  # fmt: skip
    """Centres (display pixels, (3, 2)) for the labels of a triangle's three edges on a pixel
    grid, each a box of half-size ``half`` (display pixels) within :data:`EDGE_LABEL_REACH`
    grid pixels of its edge's midpoint ``mids`` (3, 2, grid coordinates), clear of the
    ``dots`` (n, 4 boxes: the pixel centres and the vertex dots), the edges and the other
    labels, outside the triangle (display, (3, 2)) where it can, and nearer its own edge than
    the others (it names that one). The candidates sit on the grid's row boundaries (whole
    y), where a box less than a pixel high covers no centre (review r291 02-3: "E31" hid row
    8's centres), then between them. ``edges`` (3, 2) are the vertex indices (into
    ``triangle``) of each label's edge, in the order of ``mids``: the test order of a fill
    differs from v1→v2→v3 when the triangle winds the other way (review r299 02-3: after the
    flip "E21" and "E13" were drawn at each other's edge). ``labels`` (m, 4 boxes, display):
    other labels (the vertex names) kept clear of as the edge labels keep clear of each other
    (review r354 FIG1: "E21" over "v1").

    Examples
    --------
    >>> tri = np.array([[1.0, 1.0], [9.0, 1.0], [1.0, 9.0]])
    >>> mids = (tri + np.roll(tri, -1, axis=0)) / 2
    >>> u, v = np.meshgrid(np.arange(10) + 0.5, np.arange(10) + 0.5)
    >>> dots = boxes_around(np.column_stack([u.ravel(), v.ravel()]), (0.1, 0.1))
    >>> c = place_edge_labels(mids, (0.4, 0.3), edges=[[0, 1], [1, 2], [2, 0]],
    ...                       to_display=lambda p: np.asarray(p, float),
    ...                       frame=(0, 0, 10, 10), triangle=tri, dots=dots)
    >>> bool((overlap_share(boxes_around(c, (0.4, 0.3)), dots) == 0).all())
    True
    """
    mids = np.asarray(mids, dtype=np.float64)
    steps = np.arange(-EDGE_LABEL_REACH, EDGE_LABEL_REACH + 1e-9, 0.25)
    segments = np.asarray(triangle, dtype=np.float64)[np.asarray(edges, dtype=int)]  # (3, 2, 2)
    grid_px = float(np.hypot(*(to_display([1.0, 0.0]) - to_display([0.0, 0.0])))) or 1.0
    placed: list = []
    named = np.zeros((0, 4)) if labels is None else np.asarray(labels, dtype=np.float64)
    for k, mid in enumerate(mids):
        dx, dy = np.meshgrid(steps, steps)
        cand = np.column_stack([mid[0] + dx.ravel(), mid[1] + dy.ravel()])
        cand = np.vstack([cand, np.column_stack([cand[:, 0], np.round(cand[:, 1])])])
        shown = np.asarray(to_display(cand), dtype=np.float64)
        boxes = boxes_around(shown, half)
        gap = np.stack([_to_segment(shown, a, b) for a, b in segments])  # (3, n), mids' order
        astray = gap[k] > np.delete(gap, k, axis=0).min(axis=0)
        # beside an end of its edge rather than its middle: by a vertex it names the vertex
        # more than the edge ("E21" right of "v1", review r354 FIG1)
        a, b = segments[k]
        along = ((shown - a) @ (b - a)) / max(float((b - a) @ (b - a)), 1e-12)
        beyond = np.clip(np.abs(along - 0.5) - END_SHARE, 0, None) / (0.5 - END_SHARE + 1e-9)
        far = np.hypot(*(cand - mid).T)
        crowded = overlap_share(boxes + CROWD_MARGIN * grid_px * np.array([-1, -1, 1, 1]), dots)
        cost = (clutter(boxes, half, frame=frame, triangle=triangle, dots=dots)
                + COST["crowd"] * (crowded > 0)
                + beside(boxes, np.vstack([boxes_around(placed, half), named]))
                + COST["astray"] * astray + COST["end"] * beyond
                + 2 * COST["inside"] * inside_share(boxes, triangle)
                + COST["ring"] * far + COST["ring"] * gap[k] / grid_px)  # fmt: skip
        placed.append(shown[int(np.argmin(cost))])
    return np.array(placed)


def _to_segment(points: np.ndarray, a, b) -> np.ndarray:
    """Distance of each of the (n, 2) ``points`` from the segment a-b."""
    d = np.asarray(b, dtype=np.float64) - a
    t = np.clip(((points - a) @ d) / max(float(d @ d), 1e-12), 0.0, 1.0)
    return np.hypot(*(points - (a + t[:, None] * d)).T)
