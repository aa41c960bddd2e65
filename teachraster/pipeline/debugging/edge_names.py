"""The names a pixel history gives the edges of a triangle after clipping.

The rasteriser tests the edges of the triangles *after* clipping (pieces), but a student
reads the triangle as given: v1, v2, v3 in the order given and its edges E12, E23, E31 in
walking order (E13, E32, E21 for a triangle walked the other way round, CONVENTIONS). A
clipped triangle is a convex polygon fanned into pieces around its first corner
(:mod:`teachraster.pipeline.geometry.clipping`), so an edge of a piece is one of three
things:

- part of an edge of the input triangle: named as that edge, E12, E23 or E31;
- an edge the clipper made along a clip plane (near, far, the guard band): beyond it, that
  part of the triangle was clipped away;
- a *seam*, the diagonal between two pieces of the same clipped polygon: beyond it, the
  neighbouring piece takes over (the triangle still covers the point).

Which one is decided exactly, by clipping the triangles again with their vertices'
barycentric coordinates as attributes (the clipper's own code, so the very same polygons):
a new corner on the input edge opposite vk gets λk = 0 *exactly* (it is interpolated
between two corners that both have λk = 0), and a corner the clipper made lies exactly on
its plane (the clipper puts it there). An edge with both ends on an input edge is that
edge; else, with both ends on one plane, a clip edge (also a diagonal of a polygon whose
pieces beyond it have zero area: a vertex exactly on the plane); else a seam. A corner is
named by what it lies on: "v2", or "E23∩near" for the near plane's crossing of E23.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..geometry.clipping import CLIPPED, clip_triangles, distances
from ..rendering.stages import guard_band

#: Short names of the clip planes, in the clipper's order (near, far, then the guard band's
#: right, left, top and bottom planes: x <= g w, x >= -g w, y <= g w, y >= -g w, the rows of
#: ``planes()``; NDC y points up).
PLANES = ("near", "far", "guard right", "guard left", "guard top", "guard bottom")

#: What kind of edge refused a point (``PieceEdges.kind``).
INPUT_EDGE, CLIP_EDGE, SEAM = 0, 1, 2


@dataclass(frozen=True)
class PieceEdges:
    """What each edge of each piece (triangle after clipping) is, for the pixel history.

    Per piece and tested edge k (the edge set-up's order, :class:`~teachraster.core.edges.
    EdgeSetup`): ``kind`` (M, 3) INPUT_EDGE, CLIP_EDGE or SEAM, ``across`` (M, 3) the piece
    on the other side of a seam (-1 otherwise); :meth:`name` says it in words.
    """

    kind: np.ndarray  # (M, 3) int8
    across: np.ndarray  # (M, 3) int64
    label: np.ndarray  # (M, 3) per tested edge: input edge 0..2, 3 + plane, -1 seam
    ends: np.ndarray  # (M, 3, 2) the piece's corners at the two ends of each tested edge
    backwards: np.ndarray  # (M,) bool: the input triangle is walked the other way round
    turned: np.ndarray  # (M,) bool: snapping turned the piece over (it runs the other way)
    corners: dict  # piece -> ((3, 3) λ, (3, P) on plane) of its corners (clipped only)

    def name(self, piece: int, k: int) -> str:
        """The name of tested edge ``k`` of ``piece``: "E12", "near", "seam v1–E23∩near"."""
        lab, back = int(self.label[piece, k]), bool(self.backwards[piece])
        if lab >= 3:
            return PLANES[lab - 3] if lab - 3 < len(PLANES) else "clip edge"
        if lab >= 0:
            return input_edge_name(lab, back)
        lam, on_plane = self.corners[piece]
        a, b = (_corner_name(lam[c], on_plane[c], back) for c in self.ends[piece, k])
        return f"seam {a}–{b}"


def piece_edges(dbg, setup) -> PieceEdges:
    """The :class:`PieceEdges` of a traced frame (computed once, kept in ``dbg.cache``).

    ``setup`` is the edge set-up of the pieces (snapped, as the renderer tests them): its
    ``perm`` says which way round each piece is tested.
    """
    if "edge_names" not in dbg.cache:
        dbg.cache["edge_names"] = _piece_edges(dbg, setup)
    return dbg.cache["edge_names"]


def _piece_edges(dbg, setup) -> PieceEdges:
    clipped = dbg.clipped
    m = len(clipped.parent)
    label, across, corners = _polygon_edges(dbg)
    # The way round each input triangle is walked: that of its pieces (zero-area pieces,
    # which have none, do not vote).
    area = np.asarray(setup.original_area2, dtype=np.float64).reshape(m)
    vote = np.bincount(clipped.parent, weights=np.sign(area), minlength=len(clipped.status))
    backwards = vote[clipped.parent] < 0
    turned = (area != 0) & ((area < 0) != backwards)  # a thin piece snapping turned over
    perm = np.asarray(setup.perm).reshape(m, 3)
    rows = np.arange(m)
    tested = np.empty((m, 3), dtype=np.int64)
    over = np.empty((m, 3), dtype=np.int64)
    ends = np.empty((m, 3, 2), dtype=np.int64)
    for k in range(3):
        a, b = perm[:, k], perm[:, (k + 1) % 3]
        edge = np.where(b == (a + 1) % 3, a, b)  # the polygon edge (corner e -> e+1) tested
        tested[:, k], over[:, k] = label[rows, edge], across[rows, edge]
        ends[:, k] = np.stack([a, b], axis=1)
    kind = np.where(tested >= 3, CLIP_EDGE, np.where(tested < 0, SEAM, INPUT_EDGE))
    return PieceEdges(kind.astype(np.int8), over, tested, ends, backwards, turned, corners)


def input_edge_name(i: int, backwards: bool = False) -> str:
    """The name of the input edge from v(i+1) to v(i+2), in walking order.

    >>> input_edge_name(0), input_edge_name(2), input_edge_name(0, backwards=True)
    ('E12', 'E31', 'E21')
    """
    a, b = i + 1, (i + 1) % 3 + 1
    return f"E{b}{a}" if backwards else f"E{a}{b}"


def _polygon_edges(dbg):
    """Per piece: the label of its polygon edges e (corner e -> e+1), (M, 3): input edge
    i = 0..2 (v(i+1) -> v(i+2)), 3 + plane, or -1 for a seam; the piece across each seam
    (M, 3); and, for the pieces of clipped triangles, their corners' λ and planes."""
    clipped = dbg.clipped
    m = len(clipped.parent)
    label = np.tile(np.arange(3), (m, 1))
    across = np.full((m, 3), -1, dtype=np.int64)
    cut = np.flatnonzero(clipped.status == CLIPPED)
    if len(cut) == 0:
        return label, across, {}
    a = dbg.inputs
    guard = guard_band(a.width, a.height, a.subpixel_bits)
    eye = np.broadcast_to(np.eye(3), (len(cut), 3, 3))
    again = clip_triangles(a.clip[cut], eye, guard=guard)  # the same polygons, λ as attrs
    pieces = np.flatnonzero(np.isin(clipped.parent, cut))
    lam = again.attrs  # (P, 3 corners, 3): λ of each corner
    on_plane = distances(clipped.clip[pieces], guard) == 0  # (P, 3 corners, planes)
    first = np.searchsorted(clipped.parent, clipped.parent[pieces])  # the parent's piece 0
    j = pieces - first
    n = np.bincount(clipped.parent, minlength=len(clipped.status))[clipped.parent[pieces]]
    for e in range(3):
        u, v = lam[:, e], lam[:, (e + 1) % 3]
        on_edge = (u == 0) & (v == 0)  # (P, 3): both ends have λc = 0: the edge opposite vc
        plane = on_plane[:, e] & on_plane[:, (e + 1) % 3]
        lab = np.full(len(pieces), 3 + len(PLANES))
        lab = np.where(((e == 0) & (j > 0)) | ((e == 2) & (j < n - 1)), -1, lab)  # fan
        # a diagonal along a plane (the pieces beyond it have zero area) bounds the polygon
        lab = np.where(plane.any(axis=1), 3 + np.argmax(plane, axis=1), lab)
        lab = np.where(on_edge.any(axis=1), (np.argmax(on_edge, axis=1) + 1) % 3, lab)
        label[pieces, e] = lab
        across[pieces, e] = np.where(lab == -1, pieces + (-1 if e == 0 else 1), -1)
    return label, across, {int(p): (lam[i], on_plane[i]) for i, p in enumerate(pieces)}


def _corner_name(lam, on_plane, backwards: bool) -> str:
    """ "v2" for an input vertex, else what the corner lies on: "E23∩near"."""
    if np.count_nonzero(lam) == 1:
        return f"v{int(np.flatnonzero(lam)[0]) + 1}"
    parts = [input_edge_name((int(c) + 1) % 3, backwards) for c in np.flatnonzero(lam == 0)]
    parts += [PLANES[k] for k in np.flatnonzero(on_plane)]
    return "∩".join(parts) if parts else "inside"
